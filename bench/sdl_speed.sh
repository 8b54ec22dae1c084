#!/bin/sh
# bench/sdl_speed.sh [CIRCE] [ROUNDS]: how fast circe interprets POV-Ray's SDL beside POV-Ray 3.7
# (issue 17). Two scenes: `macro` includes colors.inc and strings.inc and runs a 10^5-iteration
# #while that calls a macro (with a #local) at each turn; `function` includes functions.inc,
# math.inc and transforms.inc and runs a 10^5-iteration #while calling a user function (which calls
# another and an internal one) at each turn. circe's parse time (`circe render`'s "time: parse")
# and POV-Ray's ("Parse Time" of its statistics) are printed side by side, ROUNDS times
# alternately (default 3), with both #debug results (they must agree). textures.inc is not in
# them: it needs the appearance issue. Exit 77 without povray or povray-includes.
# Run from the build folder (default ./circe).
set -u
circe=${1:-./circe}
rounds=${2:-3}
inc=${POV_INCLUDE:-/usr/share/povray-3.7/include}
command -v povray >/dev/null 2>&1 && [ -f "$inc/colors.inc" ] ||
	{ echo "sdl_speed: skipped: needs povray and povray-includes" >&2; exit 77; }
work=$(mktemp -d "${TMPDIR:-/tmp}/sdl-speed.XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT
cat >"$work/speed.pov" <<'EOF'
#include "colors.inc"
#include "strings.inc"
#macro Step(A, I)
	#local B = A + sin(I * 0.001) * 0.5;
	B
#end
#declare S = 0;
#declare I = 0;
#while (I < 100000)
	#declare S = Step(S, I);
	#declare I = I + 1;
#end
#debug concat("S = ", str(S, 0, 3), "\n")
sphere { 0, 1 pigment { White } }
EOF
cat >"$work/function.pov" <<'EOF'
#include "functions.inc"
#include "math.inc"
#include "transforms.inc"
#declare Bump = function(a, b) { sin(a * 0.001) * 0.5 + b * 1e-6 }
#declare Field = function { f_sphere(x, y, z, 1) + Bump(x, y) * max(abs(z), 0.25) + f_sqr(y) }
#declare S = 0;
#declare I = 0;
#while (I < 100000)
	#declare S = S + Field(I * 1e-5, 0.5, I * 2e-5);
	#declare I = I + 1;
#end
#debug concat("S = ", str(S, 0, 3), "\n")
sphere { 0, 1 }
EOF
echo "| case | round | circe parse (s) | POV-Ray parse (s) | POV-Ray / circe | circe #debug | POV-Ray #debug |"
echo "|---|---|---|---|---|---|---|"
for case in speed function; do
for r in $(seq "$rounds"); do
	"$circe" render "$work/$case.pov" -I "$inc" -W 8 -H 6 --spp 1 --threads 1 -o "$work/c.exr" >"$work/c.out" 2>&1
	c=$(sed -n 's/.*time: parse \([0-9.]*\) s.*/\1/p' "$work/c.out")
	cd_=$(sed -n 's/^S = //p' "$work/c.out")
	(cd "$work" && povray +W8 +H6 -D +L"$inc" +I"$case".pov +Op.png >"$work/p.out" 2>&1)
	p=$(sed -n 's/.*Parse Time:.*(\([0-9.]*\) seconds).*/\1/p' "$work/p.out")
	pd=$(sed -n 's/^S = //p' "$work/p.out")
	awk -v k="$([ "$case" = speed ] && echo macro || echo function)" -v r="$r" -v c="$c" -v p="$p" -v cd="$cd_" -v pd="$pd" \
		'BEGIN { printf "| %s | %d | %.3f | %.3f | %.1f | %s | %s |\n", k, r, c, p, (c > 0 ? p / c : 0), cd, pd }'
done
done
