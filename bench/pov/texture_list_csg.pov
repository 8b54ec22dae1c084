// texture_list_csg.pov (bench/pov_side.sh): a mesh2 of two textures (a tetrahedron, red and
// green faces: circe places it as one mesh a texture) minus a sphere. The cavity is cut in both
// pieces and nothing of the sphere shows outside the tetrahedron: the operand's inside is the
// whole mesh's. POV-Ray needs the inside_vector for the mesh to have an inside.
global_settings { assumed_gamma 1 }
camera { location <0.5, 2.5, -5> look_at <0, 0, 0> angle 45 }
light_source { <-4, 8, -6> color rgb 1 }
plane { y, -1.3 pigment { color rgb 0.7 } finish { ambient 0 } }
difference {
  mesh2 {
    vertex_vectors { 4, <-1.2, -1, -1>, <1.3, -1.1, -0.8>, <0, 1.3, -0.6>, <0.1, -0.2, 1.4> }
    texture_list { 2, texture { pigment { rgb <0.9, 0.2, 0.1> } finish { ambient 0 } }
                      texture { pigment { rgb <0.2, 0.8, 0.2> } finish { ambient 0 } } }
    face_indices { 4, <0, 2, 1>, 0, <0, 1, 3>, 0, <1, 2, 3>, 1, <0, 3, 2>, 1 }
    inside_vector <0, 0, 1>
  }
  sphere { <0.3, 0.1, -0.6>, 0.6 pigment { rgb <0.9, 0.9, 0.3> } finish { ambient 0 } }
  rotate 25*y
}
