#!/bin/sh
# bench/tiles.sh [SCENE] [N...]: the overhead of rendering a frame as N tiles (a farm's job array)
# against one whole render: total CPU seconds of the N processes and where the difference goes
# (scene parse, build = tessellation + BVHs, render). One thread per process, as a farm task of
# one CPU. Prints a markdown table. Run from the build folder (it uses ./circe).
set -eu
scene=${1:-../scenes/default.pov}
if [ $# -gt 0 ]; then shift; fi
counts=${*:-"4 16"}
opts="-W 320 -H 240 --spp 16 --threads 1"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# cpu_and_phases CMD...: runs circe, prints "cpu parse build render" (seconds).
run() {
	/usr/bin/time -f '%U %S' -o "$work/t" ./circe render "$@" 2>"$work/log" >/dev/null
	cpu=$(awk '{print $1 + $2}' "$work/t")
	sed -n 's/^circe: time: parse \([0-9.]*\) s, build \([0-9.]*\) s.*render \([0-9.]*\) s$/\1 \2 \3/p' "$work/log" |
		awk -v c="$cpu" '{print c, $1, $2, $3}'
}
echo "| render | processes | CPU s | parse s | build s | render s | CPU vs whole |"
echo "|---|---|---|---|---|---|---|"
# shellcheck disable=SC2086
set -- $(run "$scene" -o "$work/whole.exr" $opts)
whole_cpu=$1
printf '| whole | 1 | %.2f | %.3f | %.3f | %.2f | 1.00 |\n' "$1" "$2" "$3" "$4"
for n in $counts; do
	tot_cpu=0 tot_p=0 tot_b=0 tot_r=0
	i=0
	while [ "$i" -lt "$n" ]; do
		# shellcheck disable=SC2086
		set -- $(run "$scene" -o "$work/t$i.exr" --tile "$i/$n" $opts)
		tot_cpu=$(echo "$tot_cpu $1" | awk '{print $1 + $2}')
		tot_p=$(echo "$tot_p $2" | awk '{print $1 + $2}')
		tot_b=$(echo "$tot_b $3" | awk '{print $1 + $2}')
		tot_r=$(echo "$tot_r $4" | awk '{print $1 + $2}')
		i=$((i + 1))
	done
	ratio=$(echo "$tot_cpu $whole_cpu" | awk '{printf "%.2f", $1 / $2}')
	printf '| %d tiles | %d | %.2f | %.3f | %.3f | %.2f | %s |\n' "$n" "$n" "$tot_cpu" "$tot_p" "$tot_b" "$tot_r" "$ratio"
done
