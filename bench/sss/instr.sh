#!/bin/sh
# instr.sh - auto's cost against circle's without the machine's load (issue 21): instructions per
# sample pass under valgrind's cachegrind (--cache-sim=no), the count at SPP minus the count at
# 1 spp over SPP - 1, so parsing, the build and the EXR write drop out. Deterministic: the load of
# a shared machine does not move it; not CPU time (an exp and a cache miss count alike), but the
# same code paths. With OLD=path/to/circe an older binary's auto joins as "auto-before".
# Usage, from build/: sh ../bench/sss/instr.sh [--spp N] [--size WxH] [--scenes "slab sphere ..."]
#                     [--methods "circle auto"]
# Defaults: 5 spp, 32x24, the scenes of auto.sh; needs valgrind. The first method is the
# yardstick of the ratio column.
set -u
here=$(cd "$(dirname "$0")" && pwd)
circe=${CIRCE:-./circe}
old=${OLD:-}
spp=5 size=32x24 scenes="slab sphere bunny head_front head lips finger sheet" methods="circle auto"
while [ $# -gt 0 ]; do
	case $1 in
	--spp) spp=$2; shift ;;
	--size) size=$2; shift ;;
	--scenes) scenes=$2; shift ;;
	--methods) methods=$2; shift ;;
	-h | --help) sed -n '2,10p' "$0"; exit 0 ;;
	*) echo "instr.sh: unknown option '$1'" >&2; exit 2 ;;
	esac
	shift
done
command -v valgrind >/dev/null || { echo "instr.sh: valgrind is not installed" >&2; exit 1; }
W=${size%x*} H=${size#*x}
out=$(mktemp -d) || exit 1
trap 'rm -rf "$out"' EXIT
ir() { # binary scene spp method
	valgrind --tool=cachegrind --cache-sim=no --cachegrind-out-file=/dev/null "$1" render "$here/scenes/$2.pov" \
		-o "$out/x.exr" -W "$W" -H "$H" --spp "$3" --seed 1 --threads 1 --sss "$4" 2>&1 |
		sed -n 's/.*I *refs: *//p' | tr -d ,
}
echo "| scene | method | instructions per sample pass (${W}x$H) | / ${methods%% *} |"
echo "|---|---|---|---|"
for s in $scenes; do
	base=
	for m in $methods ${old:+auto-before}; do
		bin=$circe sss=$m
		[ "$m" = auto-before ] && bin=$old sss=auto
		a=$(ir "$bin" "$s" "$spp" "$sss") b=$(ir "$bin" "$s" 1 "$sss")
		[ -n "$a" ] && [ -n "$b" ] || { echo "instr.sh: $s $m failed" >&2; continue; }
		x=$(awk -v a="$a" -v b="$b" -v n="$spp" 'BEGIN { printf "%.0f", (a - b) / (n - 1) }')
		[ -z "$base" ] && base=$x
		awk -v s="$s" -v m="$m" -v x="$x" -v c="$base" 'BEGIN { printf "| %s | %s | %.4g | %.3f |\n", s, m, x, x / c }'
	done
done
