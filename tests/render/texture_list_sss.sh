#!/bin/sh
# texture_list_sss.sh: a closed mesh2 with a texture_list is placed as one mesh a texture (its
# pieces); where the textures are subsurface materials the pieces are one SSS volume, the whole
# closed mesh (build_csg.c piece_groups, build_sss.c pieces_closure). A cube whose faces take two
# textures of the same wax renders bit for bit as the cube with one texture, by circle tracing
# (circles and probes see every piece: as separate volumes a seam shows where the pieces meet) and
# by the volume walk (refused before: each piece alone is open) on all but a few pixels: the walk's
# runs inside a free ball (walk.c walk_run_ball) end at a limit from the ball's radius, whose last
# bits can differ where the nearest point lies on an edge the two pieces share (a tie answered by
# the other piece's triangle), so a path or two take other random numbers; 2 % of the pixels are
# allowed to differ (2 of 1,200 do), separate open volumes would differ everywhere near the seam.
# A wax piece beside a diffuse one
# is an open SSS volume: the volume method still refuses it.
. "$top_srcdir/tests/lib.sh"
enter_workdir
V='vertex_vectors { 8, <-1,-1,-1>, <1,-1,-1>, <1,1,-1>, <-1,1,-1>, <-1,-1,1>, <1,-1,1>, <1,1,1>, <-1,1,1> }'
# the faces outward; those of x < 0 and the -z face's left triangle take texture 0, the rest 1
F0='<0,2,1>, 0, <0,3,2>, 0, <4,5,6>, 1, <4,6,7>, 1, <0,4,7>, 0, <0,7,3>, 0'
F1='<1,2,6>, 1, <1,6,5>, 1, <3,7,6>, 1, <3,6,2>, 1, <0,1,5>, 1, <0,5,4>, 0'
F='<0,2,1>, <0,3,2>, <4,5,6>, <4,6,7>, <0,4,7>, <0,7,3>, <1,2,6>, <1,6,5>, <3,7,6>, <3,6,2>, <0,1,5>, <0,5,4>'
head='camera { location <1.2, 1.6, -3.4> look_at 0 angle 45 }
light_source { <-2, 4, -3> color 1.5 }
plane { y, -1 pigment { rgb 0.5 } }'
for m in circle volume; do
	W="#declare Wax = material { wax { radius <6, 4, 3> method $m } }"
	printf '%s\n%s\nmesh2 { %s texture_list { 2, texture { Wax }, texture { Wax } } face_indices { 12, %s, %s } }\n' \
		"$head" "$W" "$V" "$F0" "$F1" >two_$m.pov
	printf '%s\n%s\nmesh2 { %s face_indices { 12, %s } texture { Wax } }\n' "$head" "$W" "$V" "$F" >one_$m.pov
	for f in two one; do
		expect_status 0 "$CIRCE" render ${f}_$m.pov -o ${f}_$m.exr -W 40 -H 30 --spp 16 --seed 5 --quiet
	done
	if [ $m = circle ]; then
		expect_status 0 "$CIRCE" compare two_$m.exr one_$m.exr
	else
		expect_status 0 "$CIRCE" compare two_$m.exr one_$m.exr --fail-percent 2
	fi
done
W='#declare Wax = material { wax { radius <6, 4, 3> method volume } }'
printf '%s\n%s\nmesh2 { %s texture_list { 2, texture { Wax }, texture { pigment { rgb 0.5 } } } face_indices { 12, %s, %s } }\n' \
	"$head" "$W" "$V" "$F0" "$F1" >mixed.pov
expect_status 3 "$CIRCE" check mixed.pov
grep -q 'the volume SSS method needs a closed object' err || fail "the open wax piece was not refused: $(cat err)"
pass
