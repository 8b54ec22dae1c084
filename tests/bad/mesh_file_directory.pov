// A mesh file that is a folder.
mesh { file "a_folder" }
