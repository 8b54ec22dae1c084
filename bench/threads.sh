#!/bin/sh
# bench/threads.sh [SCENE] [THREADS...]: samples per second of one scene at each thread count,
# side by side in one run, and the scaling against one thread. Prints a markdown table. Run from
# the build folder (it uses ./circe). The image is the same for every count (determinism).
set -eu
scene=${1:-../scenes/default.pov}
if [ $# -gt 0 ]; then shift; fi
counts=${*:-"1 2"}
opts="-W 320 -H 240 --spp 32"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| threads | render s | samples/s | scaling |"
echo "|---|---|---|---|"
base=""
for t in $counts; do
	./circe render "$scene" -o "$work/t$t.exr" $opts --threads "$t" 2>"$work/log" >/dev/null
	set -- $(sed -n 's/^circe: .* samples per pixel in \([0-9.]*\) s (\([0-9.e+]*\) samples\/s.*/\1 \2/p' "$work/log")
	[ -n "$base" ] || base=$2
	printf '| %d | %.2f | %.3g | %.2f |\n' "$t" "$1" "$2" "$(echo "$2 $base" | awk '{print $1 / $2}')"
done
