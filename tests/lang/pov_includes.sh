#!/bin/sh
# pov_includes: POV-Ray 3.7's colors.inc (each colour it declares printed), strings.inc, arrays.inc,
# consts.inc and rand.inc parse and their macros work: tests/lang/pov_includes_scene.pov's #debug output
# is exactly pov_includes_scene.stderr (povray 3.7.0 printed the same); so are functions.inc's,
# math.inc's and transforms.inc's functions (pov_functions_scene) and every closed-form internal
# function of functions.inc at points taking each branch (pov_internals_scene); the appearance
# includes each render a minimal scene (below). Skips (77) without
# povray-includes; POV_INCLUDE names another include folder.
set -u
: "${CIRCE:?set CIRCE to the circe binary}" "${srcdir:?set srcdir to the source tree}"
inc=${POV_INCLUDE:-/usr/share/povray-3.7/include}
[ -f "$inc/colors.inc" ] || { echo "pov_includes: skipped: no colors.inc in $inc"; exit 77; }
tmp=$(mktemp -d "${TMPDIR:-/tmp}/circe-povinc.XXXXXX") || exit 99
trap 'rm -rf "$tmp"' EXIT
"$CIRCE" check -I "$inc" "$srcdir/tests/lang/pov_includes_scene.pov" >"$tmp/out" 2>"$tmp/err" ||
	{ echo "FAIL: pov_includes_scene.pov does not parse"; cat "$tmp/err"; exit 1; }
cmp -s "$tmp/err" "$srcdir/tests/lang/pov_includes_scene.stderr" ||
	{ echo "FAIL: output differs (expected, then got):"; diff "$srcdir/tests/lang/pov_includes_scene.stderr" "$tmp/err" | head -40; exit 1; }
echo "pov_includes: $(grep -c ' color rgbft ' "$tmp/err") colours of colors.inc, the macros of strings.inc and arrays.inc"
"$CIRCE" check -I "$inc" "$srcdir/tests/lang/pov_functions_scene.pov" >"$tmp/out" 2>"$tmp/err" ||
	{ echo "FAIL: pov_functions_scene.pov does not parse"; cat "$tmp/err"; exit 1; }
cmp -s "$tmp/err" "$srcdir/tests/lang/pov_functions_scene.stderr" ||
	{ echo "FAIL: functions output differs (expected, then got):"; diff "$srcdir/tests/lang/pov_functions_scene.stderr" "$tmp/err" | head -40; exit 1; }
echo "pov_includes: functions.inc, math.inc and transforms.inc functions as povray 3.7.0 computes them"
"$CIRCE" check -I "$inc" "$srcdir/tests/lang/pov_internals_scene.pov" >"$tmp/out" 2>"$tmp/err" ||
	{ echo "FAIL: pov_internals_scene.pov does not parse"; cat "$tmp/err"; exit 1; }
cmp -s "$tmp/err" "$srcdir/tests/lang/pov_internals_scene.stderr" ||
	{ echo "FAIL: internal functions differ from povray 3.7.0's (expected, then got):"; diff "$srcdir/tests/lang/pov_internals_scene.stderr" "$tmp/err" | head -40; exit 1; }
echo "pov_includes: $(wc -l <"$tmp/err") values of functions.inc's internal functions as povray 3.7.0 computes them"
# The standard appearance includes, each in a minimal scene (bench/pov/cover/inc_*.pov: textures.inc,
# finish.inc, golds.inc, woods.inc, stones.inc with stones1.inc and stones2.inc, skies.inc; glass.inc's
# glass_inc.pov, bench/pov/metals.pov; beside POV-Ray in bench/pov_cover.sh at r 0.95 to 0.99):
# each parses, builds and renders a small image.
n=0
for s in "$srcdir"/bench/pov/cover/inc_*.pov "$srcdir/bench/pov/cover/glass_inc.pov" "$srcdir/bench/pov/metals.pov"; do
	"$CIRCE" render -I "$inc" -I "$srcdir/bench/pov/cover" "$s" -o "$tmp/inc.exr" -W 16 -H 12 --spp 2 --quiet \
		>"$tmp/out" 2>"$tmp/err" || { echo "FAIL: $s does not render"; cat "$tmp/err"; exit 1; }
	n=$((n + 1))
done
[ $n -eq 8 ] || { echo "FAIL: expected 8 include scenes, found $n"; exit 1; }
echo "pov_includes: $n scenes of textures.inc, finish.inc, metals.inc, golds.inc, glass.inc, woods.inc, stones.inc and skies.inc render"
