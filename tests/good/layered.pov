// POV-Ray's layered textures: a #declare of texture { } texture { } (stones2.inc's form), a
// declared layered texture used and layered on again, and layers written on an object.
#declare Blue_Bozo = texture { pigment { color rgb <0.2, 0.3, 0.8> } }
  texture { pigment { bozo color_map { [0.5 rgbt <1, 1, 1, 1>] [0.5 rgb <1, 0.9, 0.2>] } } finish { phong 0.5 } }
#declare After = 1; // a directive right after the layers runs after them
sphere { 0, 1 texture { Blue_Bozo } }
sphere { x, 1 texture { Blue_Bozo } texture { pigment { rgbt <1, 0, 0, 0.5> } } }
sphere { -x, 1 texture { pigment { checker } } texture { pigment { rgbf <0, 1, 0, 0.5> } } }
