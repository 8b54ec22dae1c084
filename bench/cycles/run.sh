#!/bin/sh
# bench/cycles/run.sh [CIRCE] [OUTDIR]: issue 20's noise-per-sample comparison of circe's circle
# tracing with Blender Cycles' Christensen-Burley (and random walk), on bench/cycles/head.pov and
# its twin bench/cycles/scene.py. Each renderer renders its own reference (REF_SPP samples), then
# each of SPPS with another seed; the error is NMSE = MSE / mean^2 over R, G, B against its own
# reference (`circe compare`), the time is the render's: circe's parse + build + render (its own
# report), Cycles' scene sync + BVH + render (Blender's start-up, about a second, left out and
# printed apart). Efficiency = 1 / (NMSE x seconds); the last column is circe's over Cycles'
# Burley at the same spp. Exit 77 without blender. Run from the source folder, circe in build/.
# Environment: W, H (320x240), THREADS (2), REF_SPP (2048), SPPS ("16 32 64 128"),
# CIRCE_METHODS ("circle disk"), CYCLES_METHODS ("BURLEY RANDOM_WALK").
set -u
here=$(cd "$(dirname "$0")" && pwd)
circe=${1:-$here/../../build/circe}
out=${2:-${TMPDIR:-/tmp}/cycles}
W=${W:-320} H=${H:-240} THREADS=${THREADS:-2} REF_SPP=${REF_SPP:-2048}
SPPS=${SPPS:-16 32 64 128}
CIRCE_METHODS=${CIRCE_METHODS:-circle disk} CYCLES_METHODS=${CYCLES_METHODS:-BURLEY RANDOM_WALK}
command -v blender >/dev/null 2>&1 || { echo "cycles/run.sh: no blender, skipped"; exit 77; }
[ -x "$circe" ] || { echo "cycles/run.sh: no circe at $circe" >&2; exit 2; }
mkdir -p "$out" || exit 1
obj=$here/../../scenes/assets/lee_perry_smith_head/LeePerrySmith.obj

# circe_render METHOD SPP SEED OUT: prints the seconds circe reports (parse + build + render).
circe_render() {
	"$circe" render "$here/head.pov" -W "$W" -H "$H" --threads "$THREADS" --sss "$1" --spp "$2" \
		--seed "$3" -o "$4" 2>"$4.log" || { cat "$4.log" >&2; return 1; }
	sed -n 's/^circe: time: parse \([0-9.]*\) s, build \([0-9.]*\) s.*render \([0-9.]*\) s$/\1 \2 \3/p' "$4.log" |
		awk '{ printf "%.3f\n", $1 + $2 + $3 }'
}
# cycles_render METHOD SPP SEED OUT: prints Cycles' seconds; Blender's total wall time to OUT.wall.
cycles_render() {
	t0=$(date +%s.%N)
	blender -b --factory-startup --python "$here/scene.py" -- "$obj" "$4" "$2" "$3" "$1" "$W" "$H" \
		"$THREADS" >"$4.log" 2>&1 || { tail -20 "$4.log" >&2; return 1; }
	t1=$(date +%s.%N)
	echo "$t0 $t1" | awk '{ printf "%.3f\n", $2 - $1 }' >"$4.wall"
	sed -n 's/^cycles-render-seconds //p' "$4.log"
}
# nmse TEST REF: MSE / mean(REF)^2 over R, G, B.
nmse() {
	"$circe" compare "$1" "$2" --channels R,G,B 2>/dev/null |
		awk '/^rmse:/ { r = $2 } /^mean:/ { m = $5 } END { printf "%.4e\n", r * r / (m * m) }'
}

# series circe|cycles METHOD: its reference, then one row per spp of SPPS into $rows.
series() {
	"${1}_render" "$2" "$REF_SPP" 1000 "$out/${1}_$2.ref.exr" >/dev/null || return 1
	for s in $SPPS; do
		t=$("${1}_render" "$2" "$s" 1 "$out/${1}_$2.$s.exr") || return 1
		echo "$1:$2 $s $(nmse "$out/${1}_$2.$s.exr" "$out/${1}_$2.ref.exr") $t" >>"$rows"
	done
}

rows=$out/rows.txt
: >"$rows"
for m in $CIRCE_METHODS; do series circe "$m" || exit 1; done
for m in $CYCLES_METHODS; do series cycles "$m" || exit 1; done
echo "scene: bench/cycles/head.pov, ${W}x$H, $THREADS threads, references at $REF_SPP spp"
echo
echo "| renderer:method | spp | NMSE | seconds | 1/(NMSE x s) | vs Cycles Burley |"
echo "|---|---|---|---|---|---|"
awk '{ e = 1 / ($3 * $4); eff[$1 " " $2] = e; row[NR] = $0; effn[NR] = e }
	END { for (i = 1; i <= NR; i++) { split(row[i], f, " ")
		b = eff["cycles:BURLEY " f[2]]
		printf "| %s | %s | %s | %s | %.1f | %s |\n", f[1], f[2], f[3], f[4], effn[i], b ? sprintf("%.2fx", effn[i] / b) : "-" } }' "$rows"
echo
for f in "$out"/cycles_*.exr.wall; do
	[ -f "$f" ] || continue
	n=${f%.exr.wall}
	echo "Blender's wall time for ${n##*/}: $(cat "$f") s, of which Cycles' render $(sed -n 's/^cycles-render-seconds //p' "$n.exr.log") s"
	break
done
