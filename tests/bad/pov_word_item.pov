// A POV-Ray keyword where circe expects an object item: named, never "expected ...".
sphere { 0, 1 pigment { rgb 1 } cutaway_textures }
