// sky_colour: a sky_sphere of one colour pigment is circe's background (a constant environment
// light), replacing a background given before or after it, as POV-Ray's sky_sphere hides the
// background; intensity multiplies it. A light's colour may be a float (grey) after the comma.
#declare Sky = pigment { rgb <0.2, 0.3, 0.4> }
background { rgb 1 }
sky_sphere { pigment { Sky } intensity 2 }
background { rgb <1, 0, 0> }
light_source { <0, 9, 0>, 0.5 }
light_source { <0, 9, 0>, <1, 0.5, 0> intensity 2 }
#declare Grey = 0.25;
light_source { <0, 9, 0>, Grey }
sphere { 0, 1 }
