// looks_like holds an object.
light_source { 0 color rgb 1 looks_like { rgb 1 } }
