#!/bin/sh
# plane_alone.sh: a scene of a plane, the camera and two lights (a parallel one and a point one)
# — its extent is one point, the camera. The plane must still reach past the view (it was cut to
# a floor of 1e-2 units around the camera and the image was black), and the light selection must
# give the parallel light its weight (a scene radius of 0 gave it none): light adds, so the mean
# of the image with both lights is the sum of the means with each alone, within 2 %.
. "$top_srcdir/tests/lib.sh"
enter_workdir
head='camera { location <0, 1, -4> look_at <0, 0, 0> angle 50 }
plane { y, 0 }'
sun='light_source { <-3, 5, -4> color rgb 3 parallel point_at 0 }'
lamp='light_source { <3, 2, -4> color rgb 3 }'
printf '%s\n%s\n%s\n' "$head" "$sun" "$lamp" >both.pov
printf '%s\n%s\n' "$head" "$sun" >sun.pov
printf '%s\n%s\n' "$head" "$lamp" >lamp.pov
for f in both sun lamp; do
	expect_status 0 "$CIRCE" render $f.pov -o $f.exr -W 32 -H 24 --spp 64 --seed 5 --quiet
done
# The RGB mean of an image: compare's "mean: a A b B" line.
mean() {
	"$CIRCE" compare "$1" both.exr --channels R,G,B >out 2>&1
	sed -n 's/^mean: a \([^ ]*\) b .*/\1/p' out
}
b=$(mean both.exr) s=$(mean sun.exr) l=$(mean lamp.exr)
echo "means: both $b, sun $s, lamp $l"
awk -v b="$b" -v s="$s" -v l="$l" 'BEGIN { exit !(l > 0.003 && s > 0.1 && (b - s - l) ^ 2 < (0.02 * b) ^ 2) }' ||
	fail "the plane alone: mean with both lights $b, sun alone $s, lamp alone $l"
pass
