#!/bin/sh
# bench/cycles/parts.sh [CIRCE] [OUTDIR]: where circe's remaining variance comes from on the
# Cycles comparison's scenes (bench/cycles/SCENE.pov): the whole image and each --part (camera,
# coat, sss, direct, indirect) at PART_SPP with the default (Sobol) sampler, two seeds each; a
# part's NMSE is half the MSE between its two seeds over the whole image's mean^2 (as
# bench/sampler.sh's breakdown), its share that NMSE over the whole image's. Shares need not sum
# to 100 %: the parts of one path are correlated. Environment: W, H (160x120), THREADS (2),
# PART_SPP (32), SCENES ("head textured lights"), SAMPLER (sobol), SSS (circle: the method),
# PARTS ("all camera coat sss direct indirect"). Run from the source folder.
set -u
here=$(cd "$(dirname "$0")" && pwd)
circe=${1:-$here/../../build/circe}
out=${2:-${TMPDIR:-/tmp}/cycles_parts}
W=${W:-160} H=${H:-120} THREADS=${THREADS:-2} PART_SPP=${PART_SPP:-32}
SCENES=${SCENES:-head textured lights} SAMPLER=${SAMPLER:-sobol} SSS=${SSS:-circle}
PARTS=${PARTS:-all camera coat sss direct indirect}
[ -x "$circe" ] || { echo "cycles/parts.sh: no circe at $circe" >&2; exit 2; }
mkdir -p "$out" || exit 1
# mse A B: "rmse^2 mean(B)" over R, G, B.
mse() {
	"$circe" compare "$1" "$2" --channels R,G,B 2>/dev/null |
		awk '/^rmse:/ { r = $2 } /^mean:/ { m = $5 } END { printf "%.6e %.6e\n", r * r, m }'
}
echo "${W}x$H, $THREADS threads, $PART_SPP spp, sampler $SAMPLER, sss $SSS, load $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| scene | part | mean / whole's | NMSE | share of the whole's NMSE |"
echo "|---|---|---|---|---|"
for sc in $SCENES; do
	for part in $PARTS; do
		for seed in 1 2; do
			o=$out/$sc.$part.$seed.exr
			"$circe" render "$here/$sc.pov" -W "$W" -H "$H" --threads "$THREADS" --sampler "$SAMPLER" --sss "$SSS" \
				--part $part --spp "$PART_SPP" --seed $seed -o "$o" 2>"$o.log" || { cat "$o.log" >&2; exit 1; }
		done
		set -- $(mse "$out/$sc.$part.1.exr" "$out/$sc.$part.2.exr")
		[ $part = all ] && whole_mse=$1 whole_mean=$2
		echo "$1 $2 $whole_mse $whole_mean" | awk -v sc=$sc -v p=$part \
			'{ printf "| %s | %s | %.3f | %.3e | %.1f %% |\n", sc, p, $2 / $4, $1 / 2 / ($4 * $4), 100 * $1 / $3 }'
	done
done
