#!/bin/sh
# light_group.sh: POV-Ray's light_group (doc/language.md, "Lights"), direct light only (--part
# direct), two views: the plane alone (P) and the sphere filling the frame (S). L1 is in a group
# with the sphere, L2 is global. Without global_lights the plane is lit as by L2 alone and the
# sphere as by L1 alone (means within 2 %: the same expectation, other noise); with global_lights
# on the sphere is lit as by both, bit for bit; a group of every light and object renders bit for
# bit the scene without it. Two copies of a declared light_group (a light beside a sphere) render
# bit for bit as the two groups written out, and not as one group of both lights and spheres (the
# right copy's light, between the spheres, would light the left sphere's right side).
. "$top_srcdir/tests/lib.sh"
enter_workdir
camP='location <3, 2, -3> look_at <3, 0, 0> angle 40'
camS='location <0, 1, -2.2> look_at <0, 1, 0> angle 30'
L1='light_source { <-3, 5, -4> color rgb 2 }'
L2='light_source { <4, 6, -2> color rgb <1, 0.8, 0.6> }'
A='sphere { <0, 1, 0>, 1 pigment { rgb 0.8 } }'
P='plane { y, 0 pigment { rgb 0.7 } }'
for v in P S; do
	eval cam=\$cam$v
	printf 'camera { %s }\nlight_group { %s %s } %s %s\n' "$cam" "$L1" "$A" "$P" "$L2" >g$v.pov
	printf 'camera { %s }\nlight_group { %s %s global_lights on } %s %s\n' "$cam" "$L1" "$A" "$P" "$L2" >on$v.pov
	printf 'camera { %s }\n%s %s %s\n' "$cam" "$L1" "$A" "$P" >l1$v.pov
	printf 'camera { %s }\n%s %s %s\n' "$cam" "$L2" "$A" "$P" >l2$v.pov
	printf 'camera { %s }\n%s %s %s %s\n' "$cam" "$L1" "$L2" "$A" "$P" >all$v.pov
	printf 'camera { %s }\nlight_group { %s %s %s %s }\n' "$cam" "$L1" "$L2" "$A" "$P" >one$v.pov
	for f in g on l1 l2 all one; do
		expect_status 0 "$CIRCE" render $f$v.pov -o $f$v.exr -W 32 -H 24 --spp 64 --seed 3 --quiet --part direct
	done
done
mean() {
	"$CIRCE" compare "$1" "$1" --channels R,G,B >out 2>&1
	sed -n 's/^mean: a \([^ ]*\) b .*/\1/p' out
}
near() { # $1 $2: means within 2 %, both lit
	a=$(mean "$1") b=$(mean "$2")
	echo "means: $1 $a, $2 $b"
	awk -v a="$a" -v b="$b" 'BEGIN { exit !(a > 0.05 && (a - b) ^ 2 < (0.02 * b) ^ 2) }' || fail "$1 ($a) is not $2 ($b)"
}
near gP.exr l2P.exr
near gS.exr l1S.exr
a=$(mean gP.exr) b=$(mean allP.exr)
awk -v a="$a" -v b="$b" 'BEGIN { exit !(a < 0.8 * b) }' || fail "the group's light lights the plane outside it ($a, both lights $b)"
expect_status 0 "$CIRCE" compare onS.exr allS.exr
expect_status 0 "$CIRCE" compare oneS.exr allS.exr
expect_status 0 "$CIRCE" compare oneP.exr allP.exr
cam='location <0, 3, -6> look_at <0, 0.6, 0> angle 50'
L='light_source { <-1.5, 0.6, 0> color rgb <1.2, 0.3, 0.2> }'
B='sphere { <0, 0.6, 0>, 0.6 pigment { rgb 0.9 } }'
W='light_source { <0, 6, -3> color rgb 0.8 }'
printf 'camera { %s }\n#declare G = light_group { %s %s }\nobject { G translate -x * 1.5 } object { G translate x * 1.5 } %s %s\n' \
	"$cam" "$L" "$B" "$P" "$W" >decl.pov
printf 'camera { %s }\nlight_group { %s %s translate -x * 1.5 } light_group { %s %s translate x * 1.5 } %s %s\n' \
	"$cam" "$L" "$B" "$L" "$B" "$P" "$W" >two.pov
printf 'camera { %s }\nlight_group { %s %s %s %s } %s %s\n' "$cam" \
	'light_source { <-3, 0.6, 0> color rgb <1.2, 0.3, 0.2> }' 'light_source { <0, 0.6, 0> color rgb <1.2, 0.3, 0.2> }' \
	'sphere { <-1.5, 0.6, 0>, 0.6 pigment { rgb 0.9 } }' 'sphere { <1.5, 0.6, 0>, 0.6 pigment { rgb 0.9 } }' \
	"$P" "$W" >shared.pov
for f in decl two shared; do
	expect_status 0 "$CIRCE" render $f.pov -o $f.exr -W 32 -H 24 --spp 64 --seed 3 --quiet --part direct
done
expect_status 0 "$CIRCE" compare decl.exr two.exr
expect_status 1 "$CIRCE" compare decl.exr shared.exr
pass
