#!/bin/sh
# mesh_uv.sh: a mesh's triangles with uv_vectors (POV-Ray's Parse_Mesh) carry their uvs to a
# uv_mapping pigment: a quad of two such triangles renders bit for bit as the mesh2 of the same
# positions and uvs, and differs from the same mesh without uv_vectors (all its uvs 0: one colour).
. "$top_srcdir/tests/lib.sh"
enter_workdir
head='camera { location <0.5, 0.5, -2> look_at <0.5, 0.5, 0> angle 40 }
light_source { <0, 0, -5> color 1 }'
pig='pigment { uv_mapping checker rgb 1 rgb 0 scale 0.25 }'
printf '%s\nmesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> uv_vectors <0,0>, <1,0>, <0,1> }
triangle { <1,0,0>, <1,1,0>, <0,1,0> uv_vectors <1,0>, <1,1>, <0,1> } %s }\n' "$head" "$pig" >tri.pov
printf '%s\nmesh2 { vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0>, <1,1,0> }
uv_vectors { 4, <0,0>, <1,0>, <0,1>, <1,1> } face_indices { 2, <0,1,2>, <1,3,2> } %s }\n' "$head" "$pig" >m2.pov
printf '%s\nmesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> } triangle { <1,0,0>, <1,1,0>, <0,1,0> } %s }\n' \
	"$head" "$pig" >none.pov
for f in tri m2 none; do
	expect_status 0 "$CIRCE" render $f.pov -o $f.exr -W 32 -H 32 --spp 4 --seed 1 --quiet
done
expect_status 0 "$CIRCE" compare tri.exr m2.exr
"$CIRCE" compare tri.exr none.exr >out 2>&1 && fail "uv_vectors changed nothing: $(cat out)"
grep -q '^result: FAIL' out || fail "compare: $(cat out)"
pass
