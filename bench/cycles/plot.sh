#!/bin/sh
# bench/cycles/plot.sh ROWS PNG: NMSE against CPU seconds from bench/cycles/run.sh's rows.txt,
# one panel per scene, log-log, with gnuplot (a benchmark tool only: exit 77 without it).
set -u
rows=$1 png=$2
command -v gnuplot >/dev/null 2>&1 || { echo "cycles/plot.sh: no gnuplot, skipped"; exit 77; }
tmp=$(mktemp -d) || exit 1
trap 'rm -rf "$tmp"' EXIT
# One file per scene and series: "cpu nmse spp".
awk -v d="$tmp" '$2 !~ /^ref:/ { f = d "/" $1 "." $2; gsub(/[:@]/, "_", f); print $5, $4, $3 >> f }' "$rows"
scenes=$(awk '{ print $1 }' "$rows" | uniq | tr '\n' ' ')
n=$(echo $scenes | wc -w)
{
	echo "set terminal pngcairo noenhanced size $((420 * n)),420 font ',10'"
	echo "set output '$png'"
	echo "set multiplot layout 1,$n"
	echo "set logscale xy; set grid; set key top right font ',8'; set yrange [3e-4:3e-1]; set xrange [0.3:10]; set xlabel 'CPU seconds'; set ylabel 'NMSE'"
	echo "set format y '%.0e'"
	for sc in $scenes; do
		echo "set title '$sc'"
		p="plot"
		# series, colour, title
		for e in "circe_circle_sobol #9400d3 circe_circle_sobol" "cycles_BURLEY #009e73 cycles_Burley" \
			"circe_circle_random #56b4e9 circe_circle_random" "circe_disk_sobol #e69f00 circe_disk_sobol"; do
			set -- $e
			f=$tmp/$sc.$1
			[ -f "$f" ] || continue
			echo "$p '$f' using 1:2 with linespoints lw 2 lc rgb '$2' title '$3' \\"
			p=","
			for g in "$f"_time*; do
				[ -f "$g" ] || continue
				echo ", '$g' using 1:2 with points pt 7 ps 1.5 lc rgb '$2' title '$3, equal time' \\"
			done
		done
		echo
	done
	echo "unset multiplot"
} >"$tmp/plot.gp"
gnuplot "$tmp/plot.gp"
