#!/bin/sh
# pov_side.sh [CIRCE] [OUTDIR] [SCENE.pov ...]: POV-Ray scenes rendered by circe and by POV-Ray 3.7
# at 160x120, side by side (issue 18's measure). Without SCENEs: bench/pov/*.pov (one per finish
# feature and fog), tests/scenes/pov_finish.pov (the finishes' golden scene) and the POV-Ray sample scenes listed in POV_SIDE_SAMPLES (paths, or paths
# ending POV-Ray's examples; default: the two that pass `circe check` and render something,
# advanced/sombrero.pov and lights/parallel_lights.pov; bench/pov_survey.sh lists what passes). Each scene renders from its own folder (-I at POV-Ray's include
# folder and the scene's folder). Prints per scene: both mean linear values (POV-Ray's sRGB PNG and
# circe's sRGB preview linearised by ImageMagick), their ratio, and r, the correlation of the
# two luminance images (ImageMagick's normalised cross-correlation: the Pearson correlation of
# the mean-subtracted images, so a uniform scale of either does not change it). Writes
# OUTDIR/NAME.side.png (circe left, POV-Ray right) and OUTDIR/sheet.png, a contact sheet of every
# pair. A scene either renderer refuses is listed with its reason. Exit 77 without povray or
# ImageMagick. Environment: POV_SIDE_SPP (circe's samples per pixel, default 256),
# POV_INCLUDE (default /usr/share/povray-3.7/include), POV_SIDE_TIMEOUT (seconds each renderer may
# take per scene, through coreutils' timeout; default none).
set -u
here=$(cd "$(dirname "$0")" && pwd)
circe=${1:-$here/../build/circe}
out=${2:-${TMPDIR:-/tmp}/pov_side}
[ $# -ge 2 ] && shift 2 || shift $#
inc=${POV_INCLUDE:-/usr/share/povray-3.7/include}
spp=${POV_SIDE_SPP:-256}
limit=${POV_SIDE_TIMEOUT:-}
to=""
[ -n "$limit" ] && to="timeout $limit"
for t in povray convert compare montage; do
	command -v $t >/dev/null 2>&1 || { echo "pov_side: no $t, skipped"; exit 77; }
done
case $circe in /*) ;; *) circe=$(pwd)/$circe ;; esac
mkdir -p "$out" || exit 1
out=$(cd "$out" && pwd)
if [ $# -eq 0 ]; then
	set -- "$here"/pov/*.pov "$here"/../tests/scenes/pov_finish.pov
	for s in ${POV_SIDE_SAMPLES-advanced/sombrero.pov lights/parallel_lights.pov}; do
		[ -f "$s" ] || s=$(dpkg -L povray-examples 2>/dev/null | grep "/$s\$" | head -n 1)
		[ -n "$s" ] && set -- "$@" "$s"
	done
fi
mean() { convert "$1" -colorspace RGB -format '%[fx:mean]' info:; }
printf '| scene | circe mean | POV-Ray mean | ratio | r |\n|---|---|---|---|---|\n'
pairs=""
for s in "$@"; do
	name=$(basename "$s" .pov)
	dir=$(cd "$(dirname "$s")" && pwd)
	c="$out/$name.circe.png" p="$out/$name.povray.png"
	if ! (cd "$dir" && $to "$circe" render -I "$inc" -I "$dir" "$dir/$name.pov" -o "$out/$name.exr" --png "$c" \
		-W 160 -H 120 --spp "$spp" --quiet) 2>"$out/$name.circe.log"; then
		msg=$(grep -m1 error "$out/$name.circe.log" | cut -c1-80)
		printf '| %s | circe refuses: %s | | | |\n' "$name" "${msg:-no message (over POV_SIDE_TIMEOUT?)}"
		continue
	fi
	if ! (cd "$dir" && $to povray +W160 +H120 -D -V +I"$dir/$name.pov" +O"$p" +L"$inc" +L"$dir") >"$out/$name.povray.log" 2>&1; then
		printf '| %s | | POV-Ray fails (%s.povray.log) | | |\n' "$name" "$name"
		continue
	fi
	for f in "$c" "$p"; do convert "$f" -colorspace RGB -colorspace Gray "$f.gray.png"; done
	r=$(compare -metric NCC "$c.gray.png" "$p.gray.png" null: 2>&1)
	mc=$(mean "$c") mp=$(mean "$p")
	awk -v n="$name" -v c="$mc" -v p="$mp" -v r="$r" \
		'BEGIN { printf "| %s | %.4f | %.4f | %.3f | %.3f |\n", n, c, p, (p > 0 ? c / p : 0), r }'
	convert "$c" "$p" +append "$out/$name.side.png"
	pairs="$pairs $out/$name.side.png"
done
if [ -n "$pairs" ]; then
	# shellcheck disable=SC2086 # a list of paths without blanks (OUTDIR's)
	montage -label '%t' $pairs -tile 3x -geometry +4+4 -pointsize 11 "$out/sheet.png"
	echo "contact sheet (circe left, POV-Ray right): $out/sheet.png"
fi
