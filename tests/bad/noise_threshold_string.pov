// noise_threshold takes a number.
global_settings { noise_threshold "low" }
