// global_settings' subsurface takes samples and radiosity only.
global_settings { subsurface { samples 10, 10 ior 1.5 } }
