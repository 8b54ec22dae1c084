// mesh_include: a mesh whose triangles come from an include file, as POV-Ray's samples do.
mesh {
  #include "tris.inc"
  smooth_triangle { <0, 0, 1>, <0, 0, -1>, <1, 0, 1>, <0, 0, -1>, <0, 1, 1>, <0, 0, -1> }
  translate x
}
#declare M = mesh { #include "tris.inc" }
object { M }
object { M translate z }
