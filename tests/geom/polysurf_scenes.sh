#!/bin/sh
# polysurf_scenes: quadrics, cubics, quartics and polys bounded the ways POV-Ray's scenes bound
# them pass `circe check`, each with a line of triangles and the distance reached: a quartic torus
# bounded_by a sphere, a cubic clipped_by a box under a rotation the clip shares, two infinite
# quadric cylinders intersected (each bounds the other's open axis), a paraboloid subtracted from
# a box, a quadric cylinder cut by two planes, a quartic that bounds itself (x^4 + y^4 + z^4 = 1,
# no bound given); `sturm` accepted. (The unbounded ones are in
# tests/bad: quadric_plane_union, quadric_open_axis, poly_clip_halfspace, poly_use.)
set -u
: "${CIRCE:?}"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/circe-polysurf.XXXXXX") || exit 99
trap 'rm -rf "$tmp"' EXIT
cat >"$tmp/s.pov" <<'POV'
camera { location <0, 2, -30> look_at 0 }
light_source { <10, 20, -20> color rgb 1 }
quartic { < 1, 0, 0, 0, 2, 0, 0, 2, 0, -104, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
            1, 0, 0, 2, 0, 56, 0, 0, 0, 0, 1, 0, -104, 0, 784 >
	sturm
	bounded_by { sphere { 0, 10 } }
	translate -12 * x
}
cubic { < 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, -1, 0 >
	clipped_by { box { -2, 2 } }
	rotate <30, 40, 10>
	translate 6 * x
}
intersection {
	quadric { <0, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
	quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
	rotate <-30, 0, 30>
}
difference {
	box { <-2, -2, -2>, <2, 2, 2> }
	quadric { <1, 0, 1>, <0, 0, 0>, <0, -1, 0>, 0 }
	translate <0, -6, 0>
}
intersection {
	quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
	plane { y, 1 }
	plane { -y, 1 }
	translate <0, 6, 0>
}
quartic { < 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
            1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, -1 >
	translate <6, 6, 0>
}
POV
"$CIRCE" check "$tmp/s.pov" >"$tmp/out" 2>"$tmp/err"
rc=$?
fail=0
[ $rc -eq 0 ] || { echo "FAIL check exit $rc"; cat "$tmp/err"; fail=1; }
for at in "quartic at $tmp/s.pov:3:1" "cubic at $tmp/s.pov:9:1" "quadric at $tmp/s.pov:15:2" \
	"quadric at $tmp/s.pov:16:2" "quadric at $tmp/s.pov:21:2" "quadric at $tmp/s.pov:25:2" \
	"quartic at $tmp/s.pov:30:1"; do
	grep -Eq "^  $at: [1-9][0-9]* triangles, within [0-9.e-]+ units of the surface" "$tmp/out" ||
		{ echo "FAIL no tessellation line for $at"; fail=1; }
done
[ $fail -eq 0 ] || cat "$tmp/out"
exit $fail
