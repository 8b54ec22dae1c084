#!/bin/sh
# bench/shapes.sh [CIRCE]: the tessellation of POV-Ray's lathe, sor, prism, sphere_sweep, blob,
# text, bicubic_patch and isosurface (issue 19) at the default accuracy: each alone in a scene, seen from 6 units filling
# about half of `circe check`'s 640x480 view, through `circe check` (which tessellates as a render
# would and builds no BVH). Prints a markdown table: triangles, the tolerance chosen, and the
# wall time of the whole check (parse + tessellation), best of 3. Run from the build folder.
set -u
circe=${1:-${CIRCE:-./circe}}
inc=${POV_INCLUDE:-/usr/share/povray-3.7/include}
work=$(mktemp -d "${TMPDIR:-/tmp}/shapes-bench.XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT
cam='camera { location <0, 1, -6> look_at <0, 1, 0> angle 40 }'
cat >"$work/lathe.pov" <<POV
$cam
lathe { cubic_spline 7, <0, -0.5>, <0, 0>, <0.9, 0.1>, <0.5, 1>, <0.7, 2>, <0, 2.2>, <0, 2.5> }
POV
cat >"$work/sor.pov" <<POV
$cam
sor { 6, <0, 0>, <0.6, 0>, <0.8, 0.6>, <0.3, 1.2>, <0.5, 1.8>, <0.5, 2> }
POV
cat >"$work/prism.pov" <<POV
$cam
prism { cubic_spline 0, 2, 8, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1> }
POV
cat >"$work/sphere_sweep.pov" <<POV
$cam
sphere_sweep { b_spline 6, <-2, 1, 0>, 0.15, <-1, 1.6, 0>, 0.2, <0, 1, 0>, 0.25, <1, 1.6, 0>, 0.2,
	<2, 1, 0>, 0.15, <3, 1.6, 0>, 0.1 }
POV
cat >"$work/blob.pov" <<POV
$cam
blob { threshold 0.5
	cylinder { <0, 0, 0>, <0, 2, 0>, 1, 1 } sphere { <0, 2.5, 0>, 0.8, -2 } sphere { <0, -0.52, 0>, 0.8, -2 }
	sphere { <0, 2, -0.5>, 0.1, -0.2 } cylinder { <0, 1.88, -0.52>, <0, 1.5, -0.52>, 0.05, 0.2 }
	sphere { <0, 1.5, -0.55>, 0.07, 0.2 } }
POV
cat >"$work/text.pov" <<POV
$cam
text { ttf "timrom.ttf" "circe" 0.3, 0 translate <-1.2, 0.5, 0> }
POV
cat >"$work/bicubic_patch.pov" <<POV
$cam
bicubic_patch { type 1 <-2, 0, -2>, <-1, 1, -2>, <1, -1, -2>, <2, 0, -2>, <-2, 1, -1>, <-1, 3, -1>,
	<1, 2, -1>, <2, 0, -1>, <-2, 0, 1>, <-1, -1, 1>, <1, 2, 1>, <2, 1, 1>, <-2, 0, 2>, <-1, 1, 2>,
	<1, 0, 2>, <2, 0, 2> }
POV
cat >"$work/isosurface.pov" <<POV
$cam
isosurface { function { sqrt(pow(sqrt(x * x + z * z) - 0.7, 2) + y * y) - 0.25 }
	contained_by { box { <-1, -0.5, -1>, <1, 0.5, 1> } } rotate -60 * x translate y }
POV
cat >"$work/isosurface_cut.pov" <<POV
$cam
isosurface { function { y - sin(x * 4 * pi) * 0.1 } max_gradient 1.7
	contained_by { box { <-1, -1, -1>, <1, 1, 1> } } translate y }
POV
cat >"$work/parametric.pov" <<POV
$cam
parametric { function { (1 + 0.4 * cos(v)) * cos(u) } function { 0.4 * sin(v) }
	function { (1 + 0.4 * cos(v)) * sin(u) } <0, 0>, <2 * pi, 2 * pi> contained_by { box { -2, 2 } }
	rotate -60 * x translate y }
POV
cat >"$work/julia_fractal.pov" <<POV
$cam
julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 translate y }
POV
echo "| shape | triangles | tolerance (units) | check time (s, best of 3) |"
echo "|---|---:|---:|---:|"
for s in lathe sor prism sphere_sweep blob text bicubic_patch isosurface isosurface_cut parametric julia_fractal; do
	best=""
	for run in 1 2 3; do
		t0=$(date +%s.%N)
		"$circe" check -I "$inc" "$work/$s.pov" >"$work/out" 2>&1 || { echo "| $s | failed | | |"; cat "$work/out" >&2; continue 2; }
		t1=$(date +%s.%N)
		t=$(echo "$t1 - $t0" | bc)
		if [ -z "$best" ] || [ "$(echo "$t < $best" | bc)" = 1 ]; then best=$t; fi
	done
	line=$(grep "^  ${s%_cut} at " "$work/out")
	tris=$(echo "$line" | sed 's/.*: \([0-9]*\) triangles.*/\1/')
	tol=$(echo "$line" | sed 's/.*within \([^ ]*\) units.*/\1/')
	printf '| %s | %s | %s | %.3f |\n' "$s" "$tris" "$tol" "$best"
done
