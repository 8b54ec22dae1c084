#!/bin/sh
# bench/sampler.sh [CIRCE] [OUTDIR]: issue 20's samplers and variance breakdown on the head set-up
# (bench/cycles/head.pov). (1) The NMSE of --sampler random and --sampler sobol at equal samples
# per pixel, against a REF_SPP reference rendered with the random sampler: NMSE = rmse^2 / mean^2
# over R, G, B (`circe compare`) less the reference's own NMSE, which is measured (half the NMSE
# between two references of different seeds), not estimated; beside it circe's own estimate
# (its closing 'noise' line) and the estimate's ratio to the measurement, and circe's render
# seconds. (2) The variance breakdown: each --part (camera, coat, sss, direct, indirect) and the
# whole image at PART_SPP, for each sampler, with two seeds: a part's NMSE is half the MSE
# between its two seeds over the whole image's mean^2 (no reference needed: the seeds are
# independent), so the parts' NMSEs are shares of the whole's (they need not sum to it: the
# parts of one path are correlated, the coat and the BSSRDF branch exclude each other).
# Environment: W, H (160x120), THREADS (2), REF_SPP (512), SPPS ("16 32 64 128"), PART_SPP (32).
# Run from the source folder, circe in build/.
set -u
here=$(cd "$(dirname "$0")" && pwd)
circe=${1:-$here/../build/circe}
out=${2:-${TMPDIR:-/tmp}/sampler}
W=${W:-160} H=${H:-120} THREADS=${THREADS:-2} REF_SPP=${REF_SPP:-512} SPPS=${SPPS:-16 32 64 128}
PART_SPP=${PART_SPP:-32}
scene=$here/cycles/head.pov
[ -x "$circe" ] || { echo "sampler.sh: no circe at $circe" >&2; exit 2; }
mkdir -p "$out" || exit 1

# render OUT ARGS...: renders; prints "render_seconds estimated_nmse".
render() {
	o=$1
	shift
	"$circe" render "$scene" -W "$W" -H "$H" --threads "$THREADS" -o "$o" "$@" 2>"$o.log" ||
		{ cat "$o.log" >&2; return 1; }
	t=$(sed -n 's/^circe: time: .*render \([0-9.]*\) s$/\1/p' "$o.log")
	e=$(sed -n 's/^circe: noise: estimated NMSE \([^ ]*\) .*/\1/p' "$o.log")
	echo "$t $e"
}
# mse A B: "rmse^2 mean(B)" over R, G, B.
mse() {
	"$circe" compare "$1" "$2" --channels R,G,B 2>/dev/null |
		awk '/^rmse:/ { r = $2 } /^mean:/ { m = $5 } END { printf "%.6e %.6e\n", r * r, m }'
}

render "$out/ref_a.exr" --sampler random --spp "$REF_SPP" --seed 1000 >/dev/null || exit 1
render "$out/ref_b.exr" --sampler random --spp "$REF_SPP" --seed 1001 >/dev/null || exit 1
set -- $(mse "$out/ref_a.exr" "$out/ref_b.exr")
ref_nmse=$(echo "$1 $2" | awk '{ printf "%.4e", $1 / ($2 * $2) / 2 }')
echo "scene: bench/cycles/head.pov, ${W}x$H, $THREADS threads; reference: random, $REF_SPP spp, its own NMSE $ref_nmse"
echo
echo "| sampler | spp | NMSE | random / sobol | circe's estimate | estimate / NMSE | render s |"
echo "|---|---|---|---|---|---|---|"
for spp in $SPPS; do
	for smp in random sobol; do
		set -- $(render "$out/$smp.$spp.exr" --sampler $smp --spp "$spp" --seed 1)
		t=$1 est=$2
		set -- $(mse "$out/$smp.$spp.exr" "$out/ref_a.exr")
		n=$(echo "$1 $2 $ref_nmse" | awk '{ printf "%.3e", $1 / ($2 * $2) - $3 }')
		[ $smp = random ] && n_random=$n
		ratio=$(echo "$n_random $n" | awk '{ printf "%.2f", $1 / $2 }')
		echo "$est $n $t" | awk -v s=$smp -v p="$spp" -v r="$ratio" \
			'{ printf "| %s | %s | %s | %s | %.3e | %.2f | %s |\n", s, p, $2, (s == "sobol" ? r "x" : "-"), $1, $1 / $2, $3 }'
	done
done
echo
echo "Variance breakdown at $PART_SPP spp (NMSE of each part over the whole image's mean^2, from two seeds):"
echo
echo "| sampler | part | mean / whole's | NMSE | share of the whole's NMSE |"
echo "|---|---|---|---|---|"
for smp in random sobol; do
	for part in all camera coat sss direct indirect; do
		for seed in 1 2; do
			render "$out/p.$smp.$part.$seed.exr" --sampler $smp --part $part --spp "$PART_SPP" --seed $seed \
				>/dev/null || exit 1
		done
		set -- $(mse "$out/p.$smp.$part.1.exr" "$out/p.$smp.$part.2.exr")
		if [ $part = all ]; then
			whole_mse=$1 whole_mean=$2
		fi
		echo "$1 $2 $whole_mse $whole_mean" | awk -v s=$smp -v p=$part \
			'{ printf "| %s | %s | %.3f | %.3e | %.1f %% |\n", s, p, $2 / $4, $1 / 2 / ($4 * $4), 100 * $1 / $3 }'
	done
done
