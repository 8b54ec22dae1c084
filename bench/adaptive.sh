#!/bin/sh
# bench/adaptive.sh [CIRCE] [OUTDIR]: issue 20's adaptive sampling measured: the time to reach
# NMSE TARGET (5e-3) with fixed samples per pixel and with --noise-threshold, on each scene of
# SCENES, against a REF_SPP-sample reference of another seed. Each run's NMSE = rmse^2 / mean^2
# over R, G, B (`circe compare`) minus the reference's own estimated NMSE (its noise adds to the
# measured one: the two are independent); its time is the CPU seconds of the whole process (user
# + sys: the machine is shared, wall time is printed beside). The time to TARGET is interpolated
# log-log between the two runs of a series that bracket it ('~' marks one extrapolated from the
# series' last two). Fixed and adaptive runs alternate, REPEATS times with a new seed each; the
# ratio fixed / adaptive is taken per repeat. Also printed: circe's own estimate of each run's
# NMSE (its closing 'noise' line) beside the measured one.
# Environment: W, H (160x120), THREADS (2), REF_SPP (2048), SPPS ("32 64 128 256 512"),
# THRESHOLDS ("0.2 0.1 0.06 0.04 0.025"), MAX_SPP (2048), REPEATS (2), TARGET (5e-3),
# SCENES ("scenes/default.pov bench/cycles/head.pov"). Run from the source folder, circe in build/.
set -u
here=$(cd "$(dirname "$0")" && pwd)
top=$here/..
circe=${1:-$top/build/circe}
out=${2:-${TMPDIR:-/tmp}/adaptive}
W=${W:-160} H=${H:-120} THREADS=${THREADS:-2} REF_SPP=${REF_SPP:-2048} MAX_SPP=${MAX_SPP:-2048}
SPPS=${SPPS:-32 64 128 256 512} THRESHOLDS=${THRESHOLDS:-0.2 0.1 0.06 0.04 0.025}
REPEATS=${REPEATS:-2} TARGET=${TARGET:-5e-3}
SCENES=${SCENES:-scenes/default.pov bench/cycles/head.pov}
[ -x "$circe" ] || { echo "adaptive.sh: no circe at $circe" >&2; exit 2; }
mkdir -p "$out" || exit 1

# run OUT ARGS...: renders; prints "cpu_s wall_s est_nmse mean_spp" (mean_spp: the max for fixed runs).
run() {
	o=$1
	shift
	/usr/bin/time -f '%U %S %e' -o "$o.time" "$circe" render "$scene" -W "$W" -H "$H" --threads "$THREADS" \
		-o "$o" "$@" 2>"$o.log" || { cat "$o.log" >&2; return 1; }
	est=$(sed -n 's/^circe: noise: estimated NMSE \([^ ]*\) .*/\1/p' "$o.log")
	spp=$(sed -n 's/^circe: adaptive: .*: \([0-9.]*\) samples per pixel on average.*/\1/p' "$o.log")
	[ -n "$spp" ] || spp=$(sed -n 's/^circe: [^:]*: \([0-9]*\) samples per pixel in.*/\1/p' "$o.log")
	awk -v e="$est" -v s="$spp" '{ printf "%.2f %.2f %s %s\n", $1 + $2, $3, e, s }' "$o.time"
}
# nmse TEST: rmse^2 / mean^2 against the reference, less the reference's own estimate.
nmse() {
	"$circe" compare "$1" "$ref" --channels R,G,B 2>/dev/null |
		awk -v r0="$ref_est" '/^rmse:/ { r = $2 } /^mean:/ { m = $5 } END { printf "%.4e\n", r * r / (m * m) - r0 }'
}
# to_target: reads "cpu nmse" lines of one series; prints the CPU seconds at TARGET.
to_target() {
	sort -g | awk -v t="$TARGET" '
		{ c[n] = log($1); e[n] = log($2); n++ }
		END {
			lt = log(t)
			for (i = 1; i < n; i++)
				if (e[i - 1] >= lt && e[i] <= lt) { k = i; break }
			mark = ""
			if (!k) { k = n - 1; mark = "~" }
			s = (c[k] - c[k - 1]) / (e[k] - e[k - 1])
			printf "%s%.2f\n", mark, exp(c[k] + s * (lt - e[k]))
		}'
}

rows=$out/rows.txt
: >"$rows"
for scene in $SCENES; do
	name=$(basename "$scene" .pov)
	ref=$out/$name.ref.exr
	run "$ref" --spp "$REF_SPP" --seed 1000 >"$out/$name.ref.txt" || exit 1
	ref_est=$(awk '{ print $3 }' "$out/$name.ref.txt")
	echo "$name: reference $REF_SPP spp: $(cat "$out/$name.ref.txt") (cpu s, wall s, its estimated NMSE, spp)"
	rep=1
	while [ "$rep" -le "$REPEATS" ]; do
		set -- $THRESHOLDS
		for s in $SPPS; do
			r=$(run "$out/$name.f$s.exr" --spp "$s" --seed "$rep") || exit 1
			echo "$name $rep fixed $s $r $(nmse "$out/$name.f$s.exr")" >>"$rows"
			if [ $# -gt 0 ]; then
				r=$(run "$out/$name.a$1.exr" --spp "$MAX_SPP" --noise-threshold "$1" --seed "$rep") || exit 1
				echo "$name $rep adaptive $1 $r $(nmse "$out/$name.a$1.exr")" >>"$rows"
				shift
			fi
		done
		for t in "$@"; do
			r=$(run "$out/$name.a$t.exr" --spp "$MAX_SPP" --noise-threshold "$t" --seed "$rep") || exit 1
			echo "$name $rep adaptive $t $r $(nmse "$out/$name.a$t.exr")" >>"$rows"
		done
		rep=$((rep + 1))
	done
done
echo
echo "scene repeat kind param cpu_s wall_s est_nmse mean_spp nmse"
cat "$rows"
echo
echo "time (CPU s) to NMSE $TARGET at ${W}x$H, $THREADS threads:"
printf '%-10s %-6s %-10s %-10s %s\n' scene repeat fixed adaptive ratio
for scene in $SCENES; do
	name=$(basename "$scene" .pov)
	rep=1
	while [ "$rep" -le "$REPEATS" ]; do
		tf=$(awk -v n="$name" -v r="$rep" '$1 == n && $2 == r && $3 == "fixed" && $9 > 0 { print $5, $9 }' "$rows" | to_target)
		ta=$(awk -v n="$name" -v r="$rep" '$1 == n && $2 == r && $3 == "adaptive" && $9 > 0 { print $5, $9 }' "$rows" | to_target)
		ratio=$(echo "$tf $ta" | tr -d '~' | awk '{ printf "%.2f", $1 / $2 }')
		printf '%-10s %-6s %-10s %-10s %s\n' "$name" "$rep" "$tf" "$ta" "$ratio"
		rep=$((rep + 1))
	done
done
