// noise_threshold: global_settings' adaptive sampling threshold (circe's, as render --noise-threshold);
// the dump shows it only when set.
#version 3.7;
global_settings { max_trace_level 6 noise_threshold 0.04 }
camera { location <0, 1, -4> look_at <0, 0.5, 0> }
light_source { <2, 4, -3> color rgb 1 }
sphere { <0, 0.5, 0>, 0.5 }
