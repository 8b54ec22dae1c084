// pov_values: POV-Ray's predefined values: true/yes/on are 1, false/no/off are 0; pi, tau;
// version is 3.7 until #version sets it; clock_on is 0 and frame_number 0 outside an animation;
// image_width x image_height are circe's default image under `circe check`; the predefined
// names are ordinary globals a scene may #declare again.
sphere { <true, yes, on>, 1 + false + no + off }
sphere { <pi, tau, version>, 1 }
#version 3.6;
sphere { <version, clock_on, frame_number>, 1 }
box { <clock_delta, initial_clock, final_clock>, <image_width, image_height, initial_frame + final_frame + 1> }
#declare image_width = 2;
sphere { 0, image_width }
