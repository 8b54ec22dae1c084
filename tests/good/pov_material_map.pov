// POV-Ray's material_map: an image's palette indices (another image's red times 255) pick the
// textures; the texture's transforms move the image and the textures alike.
sphere { 0, 1 texture { material_map { png "tiny.png" map_type 0 once texture { pigment { rgb 1 } }
  texture { pigment { rgb <1, 0, 0> } normal { bumps 0.3 } } texture { pigment { checker } } } scale 2 translate -1 } }
