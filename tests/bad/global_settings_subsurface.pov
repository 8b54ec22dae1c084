// subsurface {...} of global_settings is not one that circe drops: it is the appearance issue's.
global_settings { subsurface { samples 50, 10 } }
