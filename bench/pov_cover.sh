#!/bin/sh
# pov_cover.sh [CIRCE] [OUTDIR] [SCENE.pov ...]: issue 18's coverage set beside POV-Ray 3.7, through
# bench/pov_side.sh (160x120, circe at POV_SIDE_SPP samples, default 64; POV_SIDE_TIMEOUT seconds
# a renderer, default 90: nrm_crackle takes 40 s under load): without SCENEs, bench/pov/cover/*.pov (every pattern on a cube seen
# along its diagonal, every light kind on one stage, glass.inc's glasses and clear dielectrics)
# and bench/pov/*.pov (the finishes, metals, fog, normals and POV-Ray's subsurface syntax). Prints
# pov_side's table with a verdict per scene: ok where r >= POV_COVER_MIN (default 0.9), LOW
# below, and a last line counting them; OUTDIR/sheet.png is the contact sheet (circe left,
# POV-Ray right). Exit 77 without povray or ImageMagick (as pov_side), 1 if a scene is LOW or
# failed, else 0.
set -u
here=$(cd "$(dirname "$0")" && pwd)
circe=${1:-$here/../build/circe}
out=${2:-${TMPDIR:-/tmp}/pov_cover}
[ $# -ge 2 ] && shift 2 || shift $#
[ $# -eq 0 ] && set -- "$here"/pov/cover/*.pov "$here"/pov/*.pov
min=${POV_COVER_MIN:-0.9}
table=$(POV_SIDE_SPP=${POV_SIDE_SPP:-64} POV_SIDE_TIMEOUT=${POV_SIDE_TIMEOUT:-90} sh "$here/pov_side.sh" "$circe" "$out" "$@")
status=$?
[ $status = 77 ] && { echo "$table"; exit 77; }
echo "$table" | awk -F'|' -v min="$min" '
	/^\| scene / { print $0 " verdict |"; next }
	/^\|---/ { print $0 "---|"; next }
	/^\| / {
		r = $6 + 0
		if ($6 ~ /[0-9]/ && r >= min) { v = "ok"; ok++ } else { v = "LOW"; low++ }
		print $0 " " v " |"
		next
	}
	{ print }
	END { printf "%d ok, %d LOW or failed (r >= %s)\n", ok, low, min; exit low > 0 }'
