// A corner tag that announces two numbers and gives one.
subdivision_surface { file "subdiv_file_tag_malformed.obj" }
