// An OBJ vertex at z = 1e38: finite, but its squares overflow in every intersection test.
camera { location <0, 0, -4> look_at <0, 0, 0> }
mesh { file "huge_vertex.obj" }
