#!/bin/sh
# bench/circles.sh [-r ROUNDS] [-c LO,HI] MESH BASE=RAYBENCH NAME=RAYBENCH...: circle throughput of
# several raybench binaries (a baseline first), run alternately for ROUNDS rounds (default 9) on
# the same 2*10^5 half circles of MESH (`--circles`, radii log-uniform in LO..HI of the diagonal,
# default 0.001,0.1), each the best of five repeats. Prints, per binary, the median Mcircles/s and
# the median over rounds of its ratio to the baseline in the same round: on a noisy machine the
# per-round ratio is steadier than a ratio of medians. Run from the build folder (bench/raygen
# makes the small ray file raybench needs).
set -eu
rounds=9
radii=0.001,0.1
while [ $# -gt 0 ]; do
	case $1 in
	-r) rounds=$2; shift 2 ;;
	-c) radii=$2; shift 2 ;;
	*) break ;;
	esac
done
[ $# -ge 2 ] || { echo "usage: bench/circles.sh [-r ROUNDS] [-c LO,HI] MESH BASE=RAYBENCH [NAME=RAYBENCH...]" >&2; exit 2; }
mesh=$1
shift
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
bench/raygen "$mesh" incoherent 1000 "$work/rays.bin" >/dev/null
for round in $(seq "$rounds"); do
	for v in "$@"; do
		name=${v%%=*} bin=${v#*=}
		mc=$("$bin" "$mesh" "$work/rays.bin" --repeat 5 --circles 200000 --circle-radius "$radii" |
			tr ' ' '\n' | awk 'prev == "mcircles" { print } { prev = $0 }')
		echo "$round $name $mc"
	done
done >"$work/runs"
# Ratio to the baseline of the same round (the baseline is each round's first line), then medians.
awk 'NR == FNR { if (!($1 in base)) base[$1] = $3; next } { print $2, $3, $3 / base[$1] }' "$work/runs" "$work/runs" \
	>"$work/ratios"
median() { sort -g | awk '{ a[NR] = $1 } END { print (NR % 2) ? a[(NR + 1) / 2] : (a[NR / 2] + a[NR / 2 + 1]) / 2 }'; }
echo "| version | Mcircles/s (median) | ratio to ${1%%=*} (median of rounds) | ratios, round by round |"
echo "|---|---|---|---|"
for v in "$@"; do
	name=${v%%=*}
	mc=$(awk -v n="$name" '$1 == n { print $2 }' "$work/ratios" | median)
	ratio=$(awk -v n="$name" '$1 == n { print $3 }' "$work/ratios" | median)
	all=$(awk -v n="$name" '$1 == n { printf "%.2f ", $3 }' "$work/ratios")
	printf '| %s | %.3f | %.3f | %s|\n' "$name" "$mc" "$ratio" "$all"
done
