// uv_mapping on an object (POV-Ray's UV_MAPPING flag, benchmark.pov's `object { MSH uv_mapping texture
// { ... } }`): the object's textures at the surface's <u, v, 0>, written before or after them; the
// declared texture itself unchanged.
#declare T = texture { pigment { checker color rgb 1 color rgb 0 scale 0.1 } }
sphere { 0, 1 uv_mapping texture { T } }
sphere { x, 1 texture { T } uv_mapping }
sphere { 2*x, 1 texture { T } }
union { sphere { 3*x, 1 } sphere { 4*x, 1 texture { pigment { bozo } } } texture { T } uv_mapping }
