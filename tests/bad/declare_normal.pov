// POV-Ray's normal perturbations are outside circe: declaring one says so at its keyword.
#declare N = normal { bumps 0.5 }
