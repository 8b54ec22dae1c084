// looks_like in a declared light: circe places the object where the light is placed (not yet).
#declare L = light_source { 0 color rgb 1 looks_like { sphere { 0, 1 } } }
