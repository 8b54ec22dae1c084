// A cage file that is a folder.
subdivision_surface { file "a_folder" level 2 }
