// noise_threshold must be > 0.
global_settings { noise_threshold -0.05 }
