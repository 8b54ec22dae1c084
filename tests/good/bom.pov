// bom: a scene that starts with a UTF-8 byte order mark; strings and comments may hold UTF-8: été.
sphere { 0, 1 material { diffuse { image "téxture.png" } } }
