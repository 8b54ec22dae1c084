// A height field of a function (POV-Ray's function image): a float function, sampled at
// <i / (W - 1), j / (H - 1), 0> (the dump's sum: 64 x 48 points of 0.5 + 0.4 x y, mean 0.6), and a
// pigment's (its grey), with smooth and water_level.
height_field { function 64, 48 { 0.5 + 0.4 * x * y } smooth }
height_field { function 20, 20 { pigment { gradient x } } water_level 0.2 translate 2 * x }
