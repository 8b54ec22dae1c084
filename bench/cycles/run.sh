#!/bin/sh
# bench/cycles/run.sh [CIRCE] [OUTDIR]: issue 20's comparison of circe's circle tracing with Blender
# Cycles' Christensen-Burley on bench/cycles/SCENE.pov and its twin bench/cycles/scene.py (SCENE
# head, textured, lights). Per scene each renderer renders its own reference (REF_SPP samples,
# seed 1000), then at each of SPPS (seed 1) circe with the Sobol sampler (its default), Cycles
# Burley and circe with --sampler random, interleaved so that the machine's load falls on all of
# them alike. Then the equal-time rows: circe at the samples that fit into Cycles' CPU seconds at
# the largest of SPPS (its CPU seconds per sample measured in the same run), both samplers. Where
# the scene is one of DISK_SCENES, circe's disk method too (its own reference, DISK_REF_SPP).
# NMSE = MSE / mean^2 over R, G, B against the renderer's own reference (`circe compare`). Time is
# CPU seconds (user + sys, every thread): circe's whole process (parse, build, render), Cycles'
# process during bpy.ops.render.render (sync, BVH, images, render; Blender's start-up left out);
# the wall seconds beside it. CPU time because the machine is shared: wall time is the load's.
# Efficiency = 1 / (NMSE x CPU s); the last column is a row's over Cycles Burley's at the same spp
# (equal-time rows: over Cycles' at the spp whose seconds they were given).
# Writes OUTDIR/rows.txt (scene label spp nmse cpu wall mean), the table on stdout, and
# OUTDIR/*.png of the references (side by side: OUTDIR/SCENE.sides.png, circe left).
# Exit 77 without blender. Run from the source folder, circe in build/.
# Environment: W, H (160x120), THREADS (2), REF_SPP (2048), SPPS ("32 64 128"),
# SCENES ("head textured lights"), DISK_SCENES ("head"), DISK_REF_SPP (1024), DISK_SPPS ("32 128"),
# BEFORE (another circe, e.g. a build of an older commit: its Sobol circle rows at each of SPPS
# and its disk rows, labelled circe-before:..., against this circe's references, which estimate
# the same image: a before/after in one run).
set -u
here=$(cd "$(dirname "$0")" && pwd)
circe=${1:-$here/../../build/circe}
out=${2:-${TMPDIR:-/tmp}/cycles}
W=${W:-160} H=${H:-120} THREADS=${THREADS:-2} REF_SPP=${REF_SPP:-2048}
SPPS=${SPPS:-32 64 128} SCENES=${SCENES:-head textured lights}
DISK_SCENES=${DISK_SCENES-head} DISK_REF_SPP=${DISK_REF_SPP:-1024} DISK_SPPS=${DISK_SPPS:-32 128}
BEFORE=${BEFORE:-}
command -v blender >/dev/null 2>&1 || { echo "cycles/run.sh: no blender, skipped"; exit 77; }
[ -x "$circe" ] || { echo "cycles/run.sh: no circe at $circe" >&2; exit 2; }
mkdir -p "$out" || exit 1
obj=$here/../../scenes/assets/lee_perry_smith_head/LeePerrySmith.obj

# circe_render SCENE SSS SAMPLER SPP SEED OUT: prints "cpu wall" (whole process); $bin instead of
# $circe when set.
circe_render() {
	/usr/bin/time -f "%U %S %e" -o "$6.time" "${bin:-$circe}" render "$here/$1.pov" -W "$W" -H "$H" \
		--threads "$THREADS" --sss "$2" --sampler "$3" --spp "$4" --seed "$5" -o "$6" 2>"$6.log" ||
		{ cat "$6.log" >&2; return 1; }
	tail -1 "$6.time" | awk '{ printf "%.3f %.3f\n", $1 + $2, $3 }'
}
# cycles_render SCENE METHOD SPP SEED OUT: prints "cpu wall" of Cycles' render.
cycles_render() {
	blender -b --factory-startup --python "$here/scene.py" -- "$obj" "$5" "$3" "$4" "$2" "$W" "$H" \
		"$THREADS" "$1" >"$5.log" 2>&1 || { tail -20 "$5.log" >&2; return 1; }
	c=$(sed -n 's/^cycles-render-cpu //p' "$5.log") w=$(sed -n 's/^cycles-render-seconds //p' "$5.log")
	echo "$c $w"
}
# nmse TEST REF: "NMSE mean(REF)", NMSE = MSE / mean(REF)^2 over R, G, B.
nmse() {
	"$circe" compare "$1" "$2" --channels R,G,B 2>/dev/null |
		awk '/^rmse:/ { r = $2 } /^mean:/ { m = $5 } END { printf "%.4e %.5f\n", r * r / (m * m), m }'
}
# row SCENE LABEL SPP IMAGE REF CPU WALL: one line of rows.txt.
row() {
	set -- "$1" "$2" "$3" "$6" "$7" $(nmse "$4" "$5")
	echo "$1 $2 $3 $6 $4 $5 $7" >>"$rows"
}

rows=$out/rows.txt
: >"$rows"
for sc in $SCENES; do
	o=$out/$sc
	set -- $(circe_render "$sc" circle sobol "$REF_SPP" 1000 "$o.circe.ref.exr") || exit 1
	echo "$sc ref:circe $REF_SPP 0 $1 $2 $(nmse "$o.circe.ref.exr" "$o.circe.ref.exr" | cut -d' ' -f2)" >>"$rows"
	set -- $(cycles_render "$sc" BURLEY "$REF_SPP" 1000 "$o.cycles.ref.exr") || exit 1
	echo "$sc ref:cycles $REF_SPP 0 $1 $2 $(nmse "$o.cycles.ref.exr" "$o.cycles.ref.exr" | cut -d' ' -f2)" >>"$rows"
	last=
	for s in $SPPS; do
		set -- $(circe_render "$sc" circle sobol "$s" 1 "$o.sobol.$s.exr") || exit 1
		row "$sc" circe:circle:sobol "$s" "$o.sobol.$s.exr" "$o.circe.ref.exr" "$1" "$2"
		if [ -n "$BEFORE" ]; then
			set -- $(bin=$BEFORE circe_render "$sc" circle sobol "$s" 1 "$o.before.$s.exr") || exit 1
			row "$sc" circe-before:circle:sobol "$s" "$o.before.$s.exr" "$o.circe.ref.exr" "$1" "$2"
		fi
		set -- $(cycles_render "$sc" BURLEY "$s" 1 "$o.burley.$s.exr") || exit 1
		row "$sc" cycles:BURLEY "$s" "$o.burley.$s.exr" "$o.cycles.ref.exr" "$1" "$2"
		set -- $(circe_render "$sc" circle random "$s" 1 "$o.random.$s.exr") || exit 1
		row "$sc" circe:circle:random "$s" "$o.random.$s.exr" "$o.circe.ref.exr" "$1" "$2"
		last=$s
	done
	# Equal time: the samples that fit into Cycles' CPU seconds at $last, from each sampler's
	# CPU seconds per sample at $last (its start-up, parse and build, counted in).
	for smp in sobol random; do
		n=$(awk -v sc="$sc" -v s="$last" -v smp="$smp" '
			$1 == sc && $3 == s && $2 == "cycles:BURLEY" { t = $5 }
			$1 == sc && $3 == s && $2 == "circe:circle:" smp { c = $5 }
			END { n = int(s * t / c + 0.5); print n < 1 ? 1 : n }' "$rows")
		set -- $(circe_render "$sc" circle "$smp" "$n" 2 "$o.$smp.time$last.exr") || exit 1
		row "$sc" "circe:circle:$smp@time$last" "$n" "$o.$smp.time$last.exr" "$o.circe.ref.exr" "$1" "$2"
	done
	case " $DISK_SCENES " in
	*" $sc "*)
		set -- $(circe_render "$sc" disk sobol "$DISK_REF_SPP" 1000 "$o.disk.ref.exr") || exit 1
		for s in $DISK_SPPS; do
			set -- $(circe_render "$sc" disk sobol "$s" 1 "$o.disk.$s.exr") || exit 1
			row "$sc" circe:disk:sobol "$s" "$o.disk.$s.exr" "$o.disk.ref.exr" "$1" "$2"
			[ -n "$BEFORE" ] || continue
			set -- $(bin=$BEFORE circe_render "$sc" disk sobol "$s" 1 "$o.disk.before.$s.exr") || exit 1
			row "$sc" circe-before:disk:sobol "$s" "$o.disk.before.$s.exr" "$o.disk.ref.exr" "$1" "$2"
		done
		;;
	esac
	for r in circe cycles; do convert "$o.$r.ref.exr" "$o.$r.ref.png" 2>/dev/null; done
	convert "$o.circe.ref.png" "$o.cycles.ref.png" +append "$o.sides.png" 2>/dev/null
done

echo "${W}x$H, $THREADS threads, references at $REF_SPP spp (disk: $DISK_REF_SPP), load $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| scene | renderer:method:sampler | spp | NMSE | CPU s | wall s | 1/(NMSE x CPU s) | vs Cycles Burley |"
echo "|---|---|---|---|---|---|---|---|"
awk 'NR == FNR { if ($2 == "cycles:BURLEY") b[$1 " " $3] = 1 / ($4 * $5); next }
	$2 ~ /^ref:/ { printf "| %s | %s (reference, mean %s) | %s | - | %s | %s | - | - |\n", $1, substr($2, 5), $7, $3, $5, $6; next }
	{ e = 1 / ($4 * $5); key = $1 " " $3
	  n = split($2, f, "@time"); ref = n > 1 ? $1 " " f[2] : key
	  printf "| %s | %s | %s | %s | %s | %s | %.1f | %s |\n", $1, $2, $3, $4, $5, $6, e,
		(ref in b) ? sprintf("%.2fx", e / b[ref]) : "-" }' "$rows" "$rows"
