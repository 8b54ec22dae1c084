// A GLB whose JSON chunk claims 2 GB in a 528-byte file: Assimp allocated 2.1 GB before failing.
camera { location <0, 0, -4> look_at <0, 0, 0> }
mesh { file "chunk_length.glb" }
