// a mesh_camera needs a mesh (POV-Ray's Parse_Mesh_Camera: "mesh or mesh2 expected")
camera { mesh_camera { 1 0 } location <0, 0, -0.01> }
sphere { <0, 0, 5>, 1 }
