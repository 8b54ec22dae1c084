#!/bin/sh
# atmosphere.sh: POV-Ray's atmospheric media (a media statement outside an interior; doc/language.md
# "Atmospheric media"), against their closed forms. An orthographic camera 5 units from a wall:
# through absorption 0.2 a glowing wall shows exp(-1) of itself; emission 0.1 before a black wall
# adds 0.5; a diffuse wall lit by a point light at the camera (direct light) loses exp(-2) (the
# camera ray and the shadow ray, 5 units each); a ray that escapes to the background crosses no
# atmosphere (bit for bit the image without it). Means within 1 %.
. "$top_srcdir/tests/lib.sh"
enter_workdir
cam='camera { orthographic location <0, 0, -5> look_at <0, 0, 0> right x*2 up y*2 }'
wall() { printf 'box { <-10, -10, 0>, <10, 10, 1> pigment { rgb %s } finish { %s } }\n' "$1" "$2"; }
printf '%s\n%s\n' "$cam" "$(wall 1 'ambient 1 diffuse 0')" >glow.pov
printf '%s\n%s\nmedia { absorption 0.2 }\n' "$cam" "$(wall 1 'ambient 1 diffuse 0')" >absorb.pov
printf '%s\n%s\nmedia { emission 0.1 }\n' "$cam" "$(wall 0 'ambient 0 diffuse 0')" >emit.pov
lamp='light_source { <0, 0, -5> color 1 }'
near='camera { orthographic location <0, 0, -5> look_at <0, 0, 0> right x*0.2 up y*0.2 }' # shadow rays of 5 units
printf '%s\n%s\n%s\n' "$near" "$(wall 1 'ambient 0')" "$lamp" >lit.pov
printf '%s\n%s\n%s\nmedia { absorption 0.2 }\n' "$near" "$(wall 1 'ambient 0')" "$lamp" >litabs.pov
printf 'camera { location <0, 0, -5> look_at <0, 0, 0> }\nbackground { rgb 1 }\n' >sky.pov
printf 'camera { location <0, 0, -5> look_at <0, 0, 0> }\nbackground { rgb 1 }\nmedia { absorption 0.2 }\n' >skyabs.pov
for f in glow absorb emit sky skyabs; do
	expect_status 0 "$CIRCE" render $f.pov -o $f.exr -W 16 -H 16 --spp 16 --seed 1 --quiet
done
for f in lit litabs; do
	expect_status 0 "$CIRCE" render $f.pov -o $f.exr -W 16 -H 16 --spp 16 --seed 1 --quiet --part direct
done
mean() {
	"$CIRCE" compare "$1" "$1" --channels R,G,B >out 2>&1
	sed -n 's/^mean: a \([^ ]*\) b .*/\1/p' out
}
within() { # $1 what, $2 got, $3 expected
	echo "$1: $2, expected $3"
	awk -v a="$2" -v b="$3" 'BEGIN { exit !(b > 0 && (a - b) ^ 2 < (0.01 * b) ^ 2) }' || fail "$1: $2, expected $3"
}
g=$(mean glow.exr) a=$(mean absorb.exr) e=$(mean emit.exr) l=$(mean lit.exr) la=$(mean litabs.exr)
within "absorbed glow" "$a" "$(awk -v g="$g" 'BEGIN { print g * exp(-1) }')"
within "emission" "$e" 0.5
within "absorbed lamp" "$la" "$(awk -v l="$l" 'BEGIN { print l * exp(-2) }')"
expect_status 0 "$CIRCE" compare skyabs.exr sky.exr
pass
