// An SSS normal map that names a folder.
sphere { 0, 1 material { skin { normal_map "a_folder" } } }
