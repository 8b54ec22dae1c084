#!/bin/sh
# run.sh - the SSS speed/accuracy trade-off benchmark (issue 6): renders each scene of
# bench/sss/scenes with each SSS method at doubling sample counts, one thread, and measures the
# error against two references (the same method at a high count: sampling efficiency; volume at a
# high count: the model's bias). Writes results.csv, bias.csv, plots/*.png (gnuplot) and the tables
# between the markers of README.md. See bench/sss/README.md; `make bench-sss` runs it.
set -u

usage() {
	cat <<'EOF'
usage: bench/sss/run.sh [--quick] [--size WxH] [--max-spp N] [--ref-spp N] [--volume-ref-time S]
                        [--volume-ref-spp N] [--volume-max-spp N] [--scenes "slab sphere ..."]
                        [--methods "circle disk ..."] [--ref-threads N] [--work DIR] [--out DIR]
                        [--circe PATH]
  --quick             smoke test: 48x36, 1 to 8 spp, references at 128 spp (volume: 4 s, series
                      to 2 spp), results in WORK/quick
  --size WxH          image size (default 96x72)
  --max-spp N         the series renders 1, 2, 4, ... N samples per pixel (default 64)
  --ref-spp N         samples of each method's own reference (default 1024)
  --volume-ref-time S the volume reference, the model-bias yardstick, renders for S seconds
                      (`circe render --time`; default 60): a walk costs 10 to 100 times a circle
  --volume-ref-spp N  or this many samples instead (then --volume-ref-time is ignored)
  --volume-max-spp N  cap of the volume method's series (default 8)
  --scenes LIST      among: slab sphere bunny head lips finger sheet (default: all)
  --methods LIST     among: circle fullcircle talk disk volume auto (default: all)
  --ref-threads N    threads for the references (default 2; the series always run on 1 thread)
  --work DIR         renders, logs and the reference cache (default ./bench-sss)
  --out DIR          where results.csv, bias.csv, plots/ and README.md go
                     (default: the folder of this script; WORK/quick with --quick)
  --circe PATH       the circe binary (default $CIRCE, else ./circe)
Environment: CIRCE (the binary), GNUPLOT (default gnuplot; plots are skipped when missing).
EOF
}

here=$(cd "$(dirname "$0")" && pwd)
circe=${CIRCE:-./circe}
quick=0
size=96x72
max_spp=64
ref_spp=1024
vol_ref_spp=
vol_ref_time=60
vol_max_spp=8
scenes="slab sphere bunny head lips finger sheet"
methods="circle fullcircle talk disk volume auto"
ref_threads=2
work=bench-sss
out=
args="$*"
while [ $# -gt 0 ]; do
	case $1 in
	--quick) quick=1 ;;
	--size) size=$2; shift ;;
	--max-spp) max_spp=$2; shift ;;
	--ref-spp) ref_spp=$2; shift ;;
	--volume-ref-spp) vol_ref_spp=$2; shift ;;
	--volume-ref-time) vol_ref_time=$2; shift ;;
	--volume-max-spp) vol_max_spp=$2; shift ;;
	--scenes) scenes=$2; shift ;;
	--methods) methods=$2; shift ;;
	--ref-threads) ref_threads=$2; shift ;;
	--work) work=$2; shift ;;
	--out) out=$2; shift ;;
	--circe) circe=$2; shift ;;
	-h | --help) usage; exit 0 ;;
	*) echo "run.sh: unknown option '$1'" >&2; usage >&2; exit 2 ;;
	esac
	shift
done
if [ "$quick" = 1 ]; then
	size=48x36 max_spp=8 ref_spp=128 vol_ref_time=4 vol_max_spp=2
	out=${out:-$work/quick}
fi
out=${out:-$here}
[ -n "$vol_ref_spp" ] && vol_ref_time=0
W=${size%x*}
H=${size#*x}
for n in "$W" "$H" "$max_spp" "$ref_spp" "${vol_ref_spp:-1}" "$vol_ref_time" "$vol_max_spp" "$ref_threads"; do
	case $n in '' | *[!0-9]*) echo "run.sh: '$n' is not a positive whole number" >&2; exit 2 ;; esac
done
for s in $scenes; do
	[ -f "$here/scenes/$s.pov" ] || { echo "run.sh: no scene $here/scenes/$s.pov" >&2; exit 2; }
done
for m in $methods; do
	case $m in circle | fullcircle | talk | disk | volume | auto) ;;
	*) echo "run.sh: unknown method '$m'" >&2; exit 2 ;;
	esac
done
command -v "$circe" >/dev/null 2>&1 || [ -x "$circe" ] || { echo "run.sh: no circe at '$circe' (set CIRCE or --circe)" >&2; exit 2; }
mkdir -p "$work/renders" "$work/refs" "$work/logs" "$out" || exit 1
work=$(cd "$work" && pwd)
out=$(cd "$out" && pwd)
circe_sum=$(cksum <"$(command -v "$circe" || echo "$circe")" | cut -d' ' -f1)
now() { date +%s.%N; }
run_start=$(now)
# Seeds: each method's reference has a seed of its own, never a series render's (1 to max-spp),
# so a reference shares no samples with the renders measured against it nor with another method's
# reference (their difference is then bias plus independent noise, as bias.csv assumes).
ref_seed() {
	case $1 in circle) echo 900001 ;; fullcircle) echo 900002 ;; talk) echo 900003 ;;
	disk) echo 900004 ;; auto) echo 900006 ;; *) echo 900005 ;; esac
}
log() { printf '%s\n' "$*" >&2; }

# sss_options METHOD: circe's options for a method of the benchmark.
sss_options() {
	case $1 in
	talk) echo "--sss circle --circle-weight talk" ;;
	*) echo "--sss $1" ;;
	esac
}

# render SCENE METHOD SPP SEED THREADS EXR LOG: renders (SPP "tS": for S seconds); sets r_rc,
# r_seconds (circe's own render-phase clock), r_wall (the whole process: parse, build, render,
# write), r_spp (samples per pixel done), r_nohit, r_dropped.
render() {
	case $3 in t*) budget="--time ${3#t}" ;; *) budget="--spp $3" ;; esac
	t0=$(now)
	# shellcheck disable=SC2046,SC2086
	"$circe" render "$here/scenes/$1.pov" -o "$6" -W "$W" -H "$H" $budget --seed "$4" \
		--threads "$5" $(sss_options "$2") >"$7" 2>&1
	r_rc=$?
	t1=$(now)
	r_wall=$(awk -v a="$t0" -v b="$t1" 'BEGIN { printf "%.4f", b - a }')
	r_seconds=$(sed -n 's/.*, render \([0-9.e+-]*\) s$/\1/p' "$7" | tail -1)
	r_nohit=$(sed -n 's/.*no-hit rate \([0-9.e+-]*\)[):].*/\1/p' "$7" | tail -1)
	r_dropped=$(sed -n 's/.*; \([0-9]*\) non-finite samples dropped$/\1/p' "$7" | tail -1)
	r_spp=$(sed -n 's/.*: \([0-9]*\) samples per pixel in .*/\1/p' "$7" | tail -1)
	[ -n "$r_seconds" ] || r_seconds=NA
	[ -n "$r_nohit" ] || r_nohit=NA
	[ -n "$r_dropped" ] || r_dropped=NA
}

# stand_in LOG: true when circe rendered a method with another one standing in for it.
stand_in() { grep -q "not in this build yet" "$1"; }

# metrics A.exr B.exr: prints "rmse relmse mean_a mean_b" of A against B over R, G, B (alpha left
# out), NA for what compare did not print.
metrics() {
	"$circe" compare "$1" "$2" --channels R,G,B --fail 1e30 2>/dev/null |
		awk '/^rmse:/ { r = $2 } /^relmse:/ { q = $2 } /^mean:/ { a = $3; b = $5 }
		     END { print (r == "" ? "NA" : r), (q == "" ? "NA" : q), (a == "" ? "NA" : a), (b == "" ? "NA" : b) }'
}

# reference SCENE METHOD SPP: makes (or finds in the cache) the reference EXR, prints its path;
# its samples per pixel go beside it in REF.spp (SPP "tS" renders for S seconds).
# The cache key holds the scene text, the image size, samples, seed, method and circe's checksum.
reference() {
	key=$(cat "$here/scenes/$1.pov" | cksum | cut -d' ' -f1)
	seed=$(ref_seed "$2")
	ref="$work/refs/$1.$2.${W}x$H.$3spp.s$seed.$key.$circe_sum.exr"
	rlog="$work/logs/ref.$1.$2.log"
	if [ -f "$ref" ]; then
		log "  reference $1 $2 $3 spp: cached"
	else
		log "  reference $1 $2 $3 spp ($ref_threads threads) ..."
		render "$1" "$2" "$3" "$seed" "$ref_threads" "$ref.tmp.exr" "$rlog"
		if [ "$r_rc" != 0 ]; then
			log "  reference $1 $2 failed (exit $r_rc): $(grep -m1 error "$rlog")"
			rm -f "$ref.tmp.exr"
			return 1
		fi
		mv "$ref.tmp.exr" "$ref"
		echo "$r_spp" >"$ref.spp"
		log "    $r_spp spp, ${r_seconds} s"
	fi
	echo "$ref"
}

# ---- methods this circe does not have: one tiny render each, looking for circe's stand-in note
skipped=""
for m in $methods; do
	case $m in disk | volume | auto) ;; *) continue ;; esac
	set -- $scenes
	render "$1" "$m" 1 1 1 "$work/renders/probe.$m.exr" "$work/logs/probe.$m.log"
	if stand_in "$work/logs/probe.$m.log"; then
		log "run.sh: $m: circe renders it with circle as a stand-in (not in this build): skipped"
		methods=$(echo " $methods " | sed "s/ $m / /; s/^ *//; s/ *$//")
		skipped="$skipped $m(stand-in)"
	fi
done

# ---- references ---------------------------------------------------------------------------
csv="$out/results.csv"
bias="$out/bias.csv"
: >"$work/refs.list"
for s in $scenes; do
	for m in $methods; do
		n=$ref_spp
		if [ "$m" = volume ]; then
			if [ "$vol_ref_time" -gt 0 ]; then n=t$vol_ref_time; else n=$vol_ref_spp; fi
		fi
		if ref=$(reference "$s" "$m" "$n"); then
			echo "$s $m $ref" >>"$work/refs.list"
		else
			skipped="$skipped $s/$m(failed)"
		fi
	done
done
ref_of() { awk -v s="$1" -v m="$2" '$1 == s && $2 == m { print $3 }' "$work/refs.list"; }
ref_spp_of() { r=$(ref_of "$1" "$2"); [ -n "$r" ] && cat "$r.spp" 2>/dev/null || echo NA; }
material_of() { sed -n 's/.*\(skin\|wax\|marble\) *{.*/\1/p' "$here/scenes/$1.pov" | head -1; }

# ---- the series, one thread; methods interleaved at each count so load drifts hit all alike --
echo "scene,material,method,spp,seconds,wall_seconds,rmse,relmse,efficiency,nohit_rate,dropped,reference" >"$csv"
spp=1
while [ "$spp" -le "$max_spp" ]; do
	log "series: $spp spp"
	for s in $scenes; do
		mat=$(material_of "$s")
		vref=$(ref_of "$s" volume)
		for m in $methods; do
			[ "$m" = volume ] && [ "$spp" -gt "$vol_max_spp" ] && continue
			self=$(ref_of "$s" "$m")
			[ -n "$self" ] || continue
			exr="$work/renders/$s.$m.$spp.exr"
			render "$s" "$m" "$spp" "$spp" 1 "$exr" "$work/logs/$s.$m.$spp.log"
			if [ "$r_rc" != 0 ]; then
				log "  $s $m $spp spp failed (exit $r_rc)"
				continue
			fi
			for kind in self volume; do
				if [ "$kind" = self ]; then r=$self; else r=$vref; fi
				[ -n "$r" ] || continue
				[ "$kind" = volume ] && [ "$m" = volume ] && continue
				set -- $(metrics "$exr" "$r")
				eff=$(awk -v e="$1" -v t="$r_seconds" 'BEGIN { if (e + 0 > 0 && t + 0 > 0) printf "%.6g", 1 / (e * e * t); else print "NA" }')
				echo "$s,$mat,$m,$spp,$r_seconds,$r_wall,$1,$2,$eff,$r_nohit,$r_dropped,$kind" >>"$csv"
			done
		done
	done
	spp=$((spp * 2))
done

# ---- model bias: each method's reference against volume's; and against circle's, which every
# BSSRDF method must match up to noise (the same model), except the talk's biased weight
echo "scene,material,method,against,rmse,relmse,noise_rmse,bias_rmse,mean_ratio" >"$bias"
for s in $scenes; do
	mat=$(material_of "$s")
	for m in $methods; do
		self=$(ref_of "$s" "$m")
		for against in volume circle; do
			[ "$m" = "$against" ] && continue
			[ "$against" = circle ] && [ "$m" = volume ] && continue
			r=$(ref_of "$s" "$against")
			[ -n "$self" ] && [ -n "$r" ] || continue
			set -- $(metrics "$self" "$r")
			# The references' own noise: each method's variance per sample, the mean of MSE x spp
			# over its series (counts >= 2), divided by its reference's count; the two references
			# are independent, so their variances add. bias_rmse = sqrt(rmse^2 - noise^2): the part
			# of the difference that noise does not explain (0 when none). mean_ratio: the mean
			# of the method's image over the other's, a signed bias of the whole image.
			awk -F, -v s="$s" -v m="$m" -v a="$against" -v n1="$(ref_spp_of "$s" "$m")" -v n2="$(ref_spp_of "$s" "$against")" \
				-v r="$1" -v q="$2" -v ma="$3" -v mb="$4" -v out="$s,$mat,$m,$against" '
				$1 == s && $12 == "self" && ($3 == m || $3 == a) && $4 >= 2 && $7 != "NA" {
					v[$3] += $7 * $7 * $4; c[$3]++ }
				END { t = n = 0
				      for (k in v) { n++; t += v[k] / c[k] / (k == m ? n1 : n2) }
				      mr = (ma != "NA" && mb + 0 > 0) ? sprintf("%.6g", ma / mb) : "NA"
				      if (n < 2 || r == "NA" || n1 == "NA" || n2 == "NA") { print out "," r "," q ",NA,NA," mr; exit }
				      b = r * r - t
				      printf "%s,%s,%s,%.6g,%.6g,%s\n", out, r, q, sqrt(t), (b > 0 ? sqrt(b) : 0), mr }' "$csv" >>"$bias"
		done
	done
done

run_end=$(now)
run_s=$(awk -v a="$run_start" -v b="$run_end" 'BEGIN { printf "%.0f", b - a }')
log "run.sh: done in $run_s s; skipped:${skipped:- nothing}"

# ---- plots ---------------------------------------------------------------------------------
"$here/plot.sh" "$csv" "$out/plots" "$scenes" "$methods" "$work/plotdata" || log "run.sh: plots failed"

# ---- the tables of README.md ----------------------------------------------------------------
readme="$out/README.md"
[ -f "$readme" ] || cp "$here/README.md" "$readme" 2>/dev/null || :
if [ "$vol_ref_time" -gt 0 ]; then
	vol_ref_desc="$vol_ref_time s each: $(for s in $scenes; do printf '%s %s, ' "$s" "$(ref_spp_of "$s" volume)"; done | sed 's/, $//') spp"
else
	vol_ref_desc="$vol_ref_spp spp"
fi
cpu=$(sed -n 's/^model name[[:space:]]*: //p' /proc/cpuinfo 2>/dev/null | head -1)
{
	echo "Run of $(date -u '+%Y-%m-%d %H:%M UTC'): \`bench/sss/run.sh $args\` ($(basename "$circe") $("$circe" --version 2>/dev/null | head -1 | sed 's/^circe //'),"
	echo "git $(git -C "$here" rev-parse --short HEAD 2>/dev/null || echo '?')), ${W}x$H, series 1 to $max_spp spp (volume: to $vol_max_spp) on 1 thread,"
	echo "references at $ref_spp spp (volume: $vol_ref_desc) on $ref_threads threads; $(nproc 2>/dev/null || echo '?') cores ($cpu),"
	echo "load average at the end $(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null); the whole run took $run_s s.${skipped:+ Skipped:$skipped.}"
	echo
	awk -F, -f "$here/report.awk" "$csv" "$bias"
} >"$work/tables.md"
if grep -q '<!-- sss-results:begin -->' "$readme" 2>/dev/null; then
	awk -v tables="$work/tables.md" '
		/<!-- sss-results:begin -->/ { print; while ((getline l < tables) > 0) print l; skip = 1; next }
		/<!-- sss-results:end -->/ { skip = 0 }
		!skip' "$readme" >"$readme.tmp" && mv "$readme.tmp" "$readme"
	log "run.sh: tables written into $readme"
else
	log "run.sh: no markers in $readme; tables in $work/tables.md"
fi
log "run.sh: $csv, $bias, $out/plots/"
