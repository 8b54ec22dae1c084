// A PLY file cut short after its vertices: its header declares a face that is not there.
camera { location <0, 0, -4> look_at <0, 0, 0> }
mesh { file "truncated.ply" }
