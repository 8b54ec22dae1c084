// A mesh_camera max_distance below POV-Ray's EPSILON (1e-10) is no limit, as in POV-Ray
// (TraceRay: maxDepth >= EPSILON): the dump has no max_distance; a negative one too, with a
// warning (the first camera, replaced by the second, as POV-Ray uses the last).
camera { mesh_camera { 1 0 (-2) mesh { triangle { <0, 0, 0>, <0, 1, 0>, <1, 0, 0> } } } }
camera { mesh_camera { 1 0 1e-12 mesh { triangle { <0, 0, 0>, <0, 1, 0>, <1, 0, 0> } } } }
sphere { <0, 0, 5>, 1 }
