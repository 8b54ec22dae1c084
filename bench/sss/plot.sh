#!/bin/sh
# plot.sh - log-log plots of the SSS benchmark with gnuplot: RMSE against render time per scene and
# method, against the method's own reference (noise) and against volume's (noise + model bias).
# usage: plot.sh RESULTS.csv OUTDIR "SCENES" "METHODS" DATADIR
# Writes OUTDIR/SCENE.png (both references) and OUTDIR/headline.png (every scene, own reference).
# Without gnuplot (or $GNUPLOT) it says so and exits 0: plots are optional.
set -u
csv=$1 outdir=$2 scenes=$3 methods=$4 data=$5
gp=${GNUPLOT:-gnuplot}
if ! command -v "$gp" >/dev/null 2>&1; then
	echo "plot.sh: no gnuplot ('apt-get install gnuplot-nox'): plots skipped" >&2
	exit 0
fi
mkdir -p "$outdir" "$data" || exit 1
# One data file per scene, method and reference kind: "seconds rmse spp".
for s in $scenes; do
	for m in $methods; do
		for kind in self volume; do
			awk -F, -v s="$s" -v m="$m" -v k="$kind" \
				'$1 == s && $3 == m && $12 == k && $5 != "NA" && $7 != "NA" && $7 + 0 > 0 { print $5, $7, $4 }' \
				"$csv" >"$data/$s.$m.$kind.dat"
		done
	done
done
# plot_cmd SCENE KIND: the gnuplot `plot` command of one panel (every method with data).
plot_cmd() {
	cmd=""
	for m in $methods; do
		f="$data/$1.$m.$2.dat"
		# Against volume's reference, volume's own series is the one to show.
		[ "$2" = volume ] && [ "$m" = volume ] && f="$data/$1.$m.self.dat"
		[ -s "$f" ] || continue
		case $m in
		circle) st="lw 2.5 lc rgb '#d62728' pt 7" ;;
		fullcircle) st="lw 1.5 lc rgb '#ff7f0e' pt 5" ;;
		talk) st="lw 1.5 lc rgb '#9467bd' pt 9 dt 2" ;;
		disk) st="lw 2.5 lc rgb '#1f77b4' pt 13" ;;
		*) st="lw 1.5 lc rgb '#2ca02c' pt 11" ;;
		esac
		cmd="$cmd${cmd:+, }'$f' using 1:2 with linespoints $st ps 0.8 title '$m'"
	done
	[ -n "$cmd" ] && echo "plot $cmd" ||
		echo "set label 1 'no data' at graph 0.45, 0.5; plot [1:10] 1 notitle lc rgb 'white'; unset label 1"
}
common="set logscale xy; set format x '10^{%L}'; set format y '10^{%L}'; set grid xtics ytics mxtics mytics lc rgb '#dddddd';
set xlabel 'render time, 1 thread (s)'; set key top right font ',9'"
script="$data/plots.gp"
{
	echo "set terminal pngcairo size 1200,720 font 'sans,10'"
	echo "set output '$outdir/headline.png'"
	echo "$common"
	n=$(echo $scenes | wc -w)
	cols=3
	[ "$n" -lt 3 ] && cols=$n
	rows=$(((n + cols - 1) / cols))
	echo "set multiplot layout $rows,$cols title 'SSS methods: RMSE against each method''s own high-count reference, by render time (log-log; lower is better)' font ',12'"
	for s in $scenes; do
		echo "set title '$s'; set ylabel 'RMSE'"
		plot_cmd "$s" self
	done
	echo "unset multiplot"
	# Per scene: the volume panel only where some method was measured against volume.
	for s in $scenes; do
		if cat "$data/$s".*.volume.dat 2>/dev/null | grep -q .; then
			echo "set terminal pngcairo size 1000,420 font 'sans,10'"
			echo "set output '$outdir/$s.png'"
			echo "set multiplot layout 1,2 title '$s' font ',12'"
		else
			echo "set terminal pngcairo size 560,420 font 'sans,10'"
			echo "set output '$outdir/$s.png'"
			echo "set multiplot layout 1,1 title '$s' font ',12'"
		fi
		echo "set title 'noise: against the same method at a high count'; set ylabel 'RMSE'"
		plot_cmd "$s" self
		if cat "$data/$s".*.volume.dat 2>/dev/null | grep -q .; then
			echo "set title 'noise + model bias: against volume at a high count'"
			plot_cmd "$s" volume
		fi
		echo "unset multiplot"
	done
} >"$script"
"$gp" "$script" || { echo "plot.sh: gnuplot failed on $script" >&2; exit 1; }
