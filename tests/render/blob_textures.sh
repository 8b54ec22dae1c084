#!/bin/sh
# blob_textures.sh: a blob's component textures (doc/language.md, "blob"): each triangle takes the
# texture of the component whose field is strongest at its centre. Seen end on, the red
# component's cap renders bit for bit as the whole blob red, the blue one's as the whole blob
# blue (orthographic views that see only the caps); seen from the side it is neither.
. "$top_srcdir/tests/lib.sh"
enter_workdir
blob() { # $1 the red component's texture, $2 the blue one's, $3 the blob's
	printf 'blob { threshold 0.6 sphere { 0, 1, 1 } sphere { 1.2*x, 1, 1 %s } sphere { -1.2*x, 1, 1 %s } %s }\n' \
		"$1" "$2" "$3"
}
red='pigment { rgb <1, 0.1, 0.1> }'
blue='texture { pigment { rgb <0.1, 0.1, 1> } }'
light='light_source { <0, 5, -5> color 1 } light_source { <5, 0, 0> color 1 } light_source { <-5, 0, 0> color 1 }'
for v in px nx side; do
	case $v in
	px) cam='camera { orthographic location <5, 0, 0> look_at 0 right z*0.6 up y*0.6 }' ;;
	nx) cam='camera { orthographic location <-5, 0, 0> look_at 0 right z*0.6 up y*0.6 }' ;;
	side) cam='camera { location <0, 0, -6> look_at 0 angle 50 }' ;;
	esac
	printf '%s\n%s\n%s\n' "$cam" "$light" "$(blob "$red" "$blue" 'pigment { rgb 1 }')" >parts_$v.pov
	printf '%s\n%s\n%s\n' "$cam" "$light" "$(blob '' '' "$red")" >red_$v.pov
	printf '%s\n%s\n%s\n' "$cam" "$light" "$(blob '' '' "$blue")" >blue_$v.pov
	for f in parts red blue; do
		expect_status 0 "$CIRCE" render ${f}_$v.pov -o ${f}_$v.exr -W 24 -H 24 --spp 4 --seed 1 --quiet
	done
done
expect_status 0 "$CIRCE" compare parts_px.exr red_px.exr
expect_status 0 "$CIRCE" compare parts_nx.exr blue_nx.exr
"$CIRCE" compare parts_side.exr red_side.exr >out 2>&1 && fail "from the side the blob is all red"
"$CIRCE" compare parts_side.exr blue_side.exr >out 2>&1 && fail "from the side the blob is all blue"
pass
