#!/bin/sh
# negative_light.sh: POV-Ray's negative light (doc/language.md, "Negative lights") takes light
# away: a plane under a light of rgb 1 and a negative one of rgb -0.5 beside it at the same place
# renders as under rgb 0.5 alone (means within 2 %, direct light); a stronger negative light
# leaves the pixels at 0 (the mean clamped, as POV-Ray's colour), finite; a negative channel
# takes away that channel alone (the red of rgb <1, 1, 1> and <-0.5, 0, 0>: red half, green whole).
. "$top_srcdir/tests/lib.sh"
enter_workdir
head='camera { location <0, 3, -4> look_at <0, 0, 0> angle 50 }
plane { y, 0 pigment { rgb 0.8 } }'
L() { printf 'light_source { <1, 4, -2> color rgb %s }\n' "$1"; }
printf '%s\n%s%s\n' "$head" "$(L 1)" "$(L -0.5)" >pair.pov
printf '%s\n%s\n' "$head" "$(L 0.5)" >half.pov
printf '%s\n%s%s\n' "$head" "$(L 1)" "$(L -2)" >dark.pov
printf '%s\n%s%s\n' "$head" "$(L 1)" "$(L '<-0.5, 0, 0>')" >red.pov
printf '%s\n%s\n' "$head" "$(L '<0.5, 1, 1>')" >redhalf.pov
for f in pair half dark red redhalf; do
	expect_status 0 "$CIRCE" render $f.pov -o $f.exr -W 32 -H 24 --spp 64 --seed 4 --quiet --part direct
done
mean() { # $1 image, $2 channel
	"$CIRCE" compare "$1" "$1" --channels "$2" >out 2>&1
	sed -n 's/^mean: a \([^ ]*\) b .*/\1/p' out
}
near() { # $1 $2 images, $3 channel: means within 2 %, lit
	a=$(mean "$1" "$3") b=$(mean "$2" "$3")
	echo "means ($3): $1 $a, $2 $b"
	awk -v a="$a" -v b="$b" 'BEGIN { exit !(b > 0.05 && (a - b) ^ 2 < (0.02 * b) ^ 2) }' || fail "$1 ($a) is not $2 ($b) in $3"
}
near pair.exr half.exr R,G,B
near red.exr redhalf.exr R
near red.exr redhalf.exr G
d=$(mean dark.exr R,G,B)
"$CIRCE" compare dark.exr dark.exr >out 2>&1
grep -q '^nonfinite_a: nan 0 inf 0' out || fail "non-finite pixels: $(cat out)"
[ "$d" = 0 ] || fail "under a stronger negative light the mean is $d, not 0"
pass
