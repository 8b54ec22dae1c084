// #default takes texture, pigment and finish; POV-Ray's normal perturbations are outside circe.
#default { normal { bumps 0.5 } }
