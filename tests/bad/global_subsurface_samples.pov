// samples takes two counts of at least 1.
global_settings { subsurface { samples 0, 10 } }
