#!/bin/sh
# polysurf_scenes: quadrics, cubics, quartics and polys bounded the ways POV-Ray's scenes bound
# them pass `circe check`, each with a line of triangles and the distance reached: a quartic torus
# bounded_by a sphere, a cubic clipped_by a box under a rotation the clip shares, two infinite
# quadric cylinders intersected (each bounds the other's open axis), a paraboloid subtracted from
# a box, a quadric cylinder cut by two planes, a quartic that bounds itself (x^4 + y^4 + z^4 = 1,
# no bound given); `sturm` accepted. Then the unbounded ones (nothing bounds them along some axis:
# a quadric cylinder alone, one cut by a plane across it, a plane quadric in a union, a quartic
# clipped by a half-space): each is polygonised inside the scene's box with a
# warning at its use; and a cylinder along x between `plane { x, 3 }` and `plane { x, -3 inverse }`
# is bounded (an inverted axis plane bounds its other side), without a warning.
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
cat >"$tmp/u.pov" <<'POV'
camera { location <0, 0, -20> look_at 0 }
light_source { <10, 20, -20> color rgb 1 }
quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -1 translate 5 * x }
intersection {
	quadric { <0, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
	plane { y, 0.5 }
}
union {
	sphere { 0, 1 }
	quadric { <0, 0, 0>, <0, 0, 0>, <0, 1, 0>, 0 translate -3 * y }
}
quartic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
           1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, -1>
	clipped_by { plane { z, 1 } }
}
intersection {
	quadric { <0, 1, 1>, <0, 0, 0>, <0, 0, 0>, -1 }
	plane { x, 3 }
	plane { x, -3 inverse }
	translate 4 * y
}
POV
"$CIRCE" check "$tmp/u.pov" >"$tmp/out" 2>"$tmp/err"
rc=$?
[ $rc -eq 0 ] || { echo "FAIL unbounded: check exit $rc"; cat "$tmp/err"; fail=1; }
for at in 3:1 5:2 10:2 12:1; do
	grep -q "^$tmp/u.pov:$at: warning: an unbounded [a-z]*: circe polygonises it inside the scene's box" "$tmp/err" ||
		{ echo "FAIL no unbounded warning at $at"; fail=1; }
done
grep -q "^$tmp/u.pov:17:2: warning: an unbounded" "$tmp/err" &&
	{ echo "FAIL the cylinder between two axis planes (one inverted) is bounded"; fail=1; }
for at in 3:1 5:2 10:2 12:1 17:2; do
	grep -Eq "^  [a-z]+ at $tmp/u.pov:$at: [1-9][0-9]* triangles, within [0-9.e-]+ units of the surface" "$tmp/out" ||
		{ echo "FAIL no tessellation line for $at"; fail=1; }
done
[ $fail -eq 0 ] || { cat "$tmp/out" "$tmp/err"; }
exit $fail
