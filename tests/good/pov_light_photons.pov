// pov_light_photons: a light_source's photons block (POV-Ray's photon flags of a light:
// balcony.pov, glassthing.pov) is read and ignored with one warning, as an object's is.
light_source { <0, 5, 0> rgb 1 photons { reflection on refraction on } }
light_source { <0, 5, 1> rgb 1 photons { refraction off } }
