#!/bin/sh
# auto.sh - `--sss auto` against the others (issue 21): for each scene, volume's reference (the
# truth every profile approximates) renders for REF seconds on two threads; then circle, disk,
# auto and volume each render for the same T seconds on one thread (`circe render --time`), and
# each image is measured against the reference: mean brightness over the reference's (signed
# model bias of the whole image) and RMSE over R, G, B (bias plus noise: the total error a user
# sees at equal time). Also each method's render time per sample relative to circle's, and the
# fraction of auto's entry searches that walked. Writes the table (markdown) to stdout and, with
# --images, side-by-side PNGs (circle | auto | volume at equal time) into bench/sss/plots/.
# With OLD=path/to/circe, an older binary's auto joins as "auto, before" (a rule's before and after
# in one run).
# Usage, from build/: sh ../bench/sss/auto.sh [--time T] [--ref-time REF] [--size WxH]
#                     [--scenes "finger sheet ..."] [--methods "circle auto ..."] [--images] [--work DIR]
# Defaults: T 4 s, REF 20 s, 64x48, all scenes: about five minutes.
set -u
here=$(cd "$(dirname "$0")" && pwd)
circe=${CIRCE:-./circe}
t=4 ref_t=20 size=64x48 images=0 work=bench-sss/auto
scenes="finger sheet head head_front lips slab sphere bunny"
methods="circle disk auto volume"
old=${OLD:-}
while [ $# -gt 0 ]; do
	case $1 in
	--time) t=$2; shift ;;
	--ref-time) ref_t=$2; shift ;;
	--size) size=$2; shift ;;
	--scenes) scenes=$2; shift ;;
	--methods) methods=$2; shift ;;
	--images) images=1 ;;
	--work) work=$2; shift ;;
	-h | --help) sed -n '2,15p' "$0"; exit 0 ;;
	*) echo "auto.sh: unknown option '$1'" >&2; exit 2 ;;
	esac
	shift
done
W=${size%x*} H=${size#*x}
mkdir -p "$work" || exit 1
field() { sed -n "$2" "$1" | tail -1; }
metrics() {
	"$circe" compare "$1" "$2" --channels R,G,B --fail 1e30 2>/dev/null |
		awk '/^rmse:/ { r = $2 } /^mean:/ { a = $3; b = $5 } END { print r, a, b }'
}
echo "Run of $(date -u '+%Y-%m-%d %H:%M UTC'), git $(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo '?'):"
echo "${W}x$H, each method ${t} s on 1 thread, volume's reference ${ref_t} s on 2 threads; load average $(cut -d' ' -f1-3 /proc/loadavg)."
echo
echo "| scene | method | spp | s / spp vs circle | walks | mean vs volume | RMSE vs volume | RMSE / circle's |"
echo "|---|---|---|---|---|---|---|---|"
for s in $scenes; do
	pov="$here/scenes/$s.pov"
	[ -f "$pov" ] || { echo "auto.sh: no scene $pov" >&2; continue; }
	ref="$work/$s.ref.exr"
	"$circe" render "$pov" -o "$ref" -W "$W" -H "$H" --time "$ref_t" --seed 900005 --threads 2 --sss volume \
		>"$work/$s.ref.log" 2>&1 || { echo "auto.sh: $s: reference failed" >&2; continue; }
	c_sps= c_rmse=
	for m in $methods ${old:+auto-old}; do
		log="$work/$s.$m.log" bin=$circe sss=$m
		[ "$m" = auto-old ] && bin=$old sss=auto
		"$bin" render "$pov" -o "$work/$s.$m.exr" -W "$W" -H "$H" --time "$t" --seed 1 --threads 1 --sss "$sss" \
			>"$log" 2>&1 || { echo "auto.sh: $s $m failed" >&2; continue; }
		spp=$(field "$log" 's/.*: \([0-9]*\) samples per pixel in .*/\1/p')
		sec=$(field "$log" 's/.*, render \([0-9.e+-]*\) s$/\1/p')
		walks=$(field "$log" 's/.*volume walks (\([0-9.e+-]*\) of the searches).*/\1/p')
		set -- $(metrics "$work/$s.$m.exr" "$ref")
		sps=$(awk -v a="$sec" -v n="$spp" 'BEGIN { printf "%.6g", a / n }')
		[ "$m" = circle ] && c_sps=$sps c_rmse=$1
		awk -v s="$s" -v m="$m" -v n="$spp" -v sps="$sps" -v cs="$c_sps" -v w="${walks:-0}" -v r="$1" -v a="$2" \
			-v b="$3" -v cr="$c_rmse" 'BEGIN {
			printf "| %s | %s | %d | %.2f | %.2f | %+.1f %% | %.4g | %s |\n", s, (m == "auto" ? "**auto**" : m == "auto-old" ? "auto, before" : m), n,
				sps / cs, w, 100 * (a / b - 1), r, (m == "circle" ? "1" : sprintf("%.2f", r / cr)) }'
	done
done
[ "$images" = 1 ] || exit 0
# circle | auto | volume at equal time, larger, for the README
for s in finger head; do
	for m in circle auto volume; do
		"$circe" render "$here/scenes/$s.pov" -o "$work/$s.$m.big.exr" --png "$work/$s.$m.big.png" -W 192 -H 144 \
			--time "$((t * 2))" --seed 2 --threads 2 --sss "$m" >/dev/null 2>&1
	done
	convert "$work/$s.circle.big.png" "$work/$s.auto.big.png" "$work/$s.volume.big.png" +append \
		"$here/plots/auto_$s.png" && echo "auto.sh: $here/plots/auto_$s.png" >&2
done
