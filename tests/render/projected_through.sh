#!/bin/sh
# projected_through.sh: POV-Ray's projected_through (doc/language.md, "projected_through"), direct
# light only (--part direct) on a plane seen at a low angle (the box below is out of view, its shadow in it). Through a sphere around the light (every
# shadow ray meets it) the image is the light's without it, bit for bit; a box between that sphere
# and the light then casts no shadow (only what lies before the projected object shadows: the
# image is again the same), while without projected_through it shadows. Through a small sphere
# below the light only a disc of the plane is lit: the mean falls below half, and stays above 0.
. "$top_srcdir/tests/lib.sh"
enter_workdir
head='camera { location <0, 0.5, -6> look_at <0, 0, 0> angle 40 }
plane { y, 0 pigment { rgb 0.8 } }'
box='box { <-0.3, 2.5, -0.3>, <0.3, 2.6, 0.3> }'
light() { printf 'light_source { <0, 3, 0> color rgb 2 %s }\n' "$1"; }
big='projected_through { sphere { <0, 3, 0>, 1 } }'
small='projected_through { sphere { <0, 2, 0>, 0.3 } }'
printf '%s\n%s\n' "$head" "$(light '')" >free.pov
printf '%s\n%s\n' "$head" "$(light "$big")" >big.pov
printf '%s\n%s\n%s\n' "$head" "$(light "$big")" "$box" >bigbox.pov
printf '%s\n%s\n%s\n' "$head" "$(light '')" "$box" >freebox.pov
printf '%s\n%s\n' "$head" "$(light "$small")" >small.pov
for f in free big bigbox freebox small; do
	expect_status 0 "$CIRCE" render $f.pov -o $f.exr -W 32 -H 32 --spp 16 --seed 2 --quiet --part direct
done
expect_status 0 "$CIRCE" compare big.exr free.exr
expect_status 0 "$CIRCE" compare bigbox.exr free.exr
"$CIRCE" compare freebox.exr free.exr >out 2>&1 && fail "the box casts no shadow without projected_through: $(cat out)"
mean() {
	"$CIRCE" compare "$1" "$1" --channels R,G,B >out 2>&1
	sed -n 's/^mean: a \([^ ]*\) b .*/\1/p' out
}
a=$(mean small.exr) b=$(mean free.exr)
echo "means: through the small sphere $a, free $b"
awk -v a="$a" -v b="$b" 'BEGIN { exit !(a > 0.01 * b && a < 0.5 * b) }' || fail "through a small sphere: mean $a, free $b"
pass
