// An image_map pigment is mapped by the uv coordinates: circe cannot move it.
#declare P = pigment { image_map { png "albedo.png" } }
sphere { 0, 1 pigment { P scale 2 } }
