#!/bin/sh
# adaptive.sh: --noise-threshold through the command line. The same scene, seed and threshold give
# bit-identical EXRs (beauty, the error and samples AOVs) for 1 and 2 threads, for four --region
# quarters merged and for --tile I/N merged; the pixels' counts spread between the minimum and
# --spp; render reports the estimated noise beside its time, for adaptive and fixed renders; a
# --checkpoint is written during an adaptive render; --time with a threshold ends; the scene's
# global_settings noise_threshold is the option's default.
. "$top_srcdir/tests/lib.sh"
scene="$top_srcdir/tests/farm/farm.pov"
enter_workdir
opts="-W 40 -H 30 --spp 56 --noise-threshold 0.03 --min-spp 8 --seed 5 --aov error,samples,variance"
# shellcheck disable=SC2086
"$CIRCE" render "$scene" -o t1.exr --threads 1 $opts >log 2>&1 ||
	{ grep -q "which this build lacks" log && skip "circe render is not in this build yet"; fail "render: $(cat log)"; }
grep -Eq '^circe: noise: estimated NMSE [0-9.e+-]+ \(relative RMS error [0-9.e+-]+ %\), mean pixel error [0-9.e+-]+, in [0-9.]+ s$' log ||
	fail "no noise line: $(cat log)"
grep -Eq '^circe: adaptive: threshold 0.03: [0-9.]+ samples per pixel on average \(8 to 56\)$' log ||
	fail "the counts do not spread from 8 to 56: $(cat log)"
# shellcheck disable=SC2086
expect_status 0 "$CIRCE" render "$scene" -o t2.exr --threads 2 $opts
expect_status 0 "$CIRCE" compare t2.exr t1.exr --fail 0
grep -q '^max_abs: 0 at' out || fail "1 and 2 threads differ: $(cat out)"
grep -qx 'channels: 9' out || fail "expected RGBA, variance, error and samples: $(cat out)"
expect_status 0 "$CIRCE" compare t1.exr t1.exr --channels samples
mean=$(sed -n 's/^mean: a \([0-9.]*\) .*/\1/p' out)
awk -v m="$mean" 'BEGIN { exit !(m > 8 && m < 56) }' || fail "mean samples per pixel $mean"
for r in 0,0,13,15 13,0,40,15 0,15,13,30 13,15,40,30; do
	# shellcheck disable=SC2086
	expect_status 0 "$CIRCE" render "$scene" -o "q$r.exr" --threads 2 --region $r $opts
done
expect_status 0 "$CIRCE" merge -o quarters.exr q*.exr
expect_status 0 "$CIRCE" compare quarters.exr t1.exr --fail 0
grep -q '^max_abs: 0 at' out || fail "regions assembled differ from the whole: $(cat out)"
tiles=""
for i in 0 1 2 3 4; do
	# shellcheck disable=SC2086
	expect_status 0 "$CIRCE" render "$scene" --tile $i/5 -o "tile$i.exr" --threads 1 $opts
	tiles="$tiles tile$i.exr"
done
# shellcheck disable=SC2086
expect_status 0 "$CIRCE" merge -o merged.exr $tiles
expect_status 0 "$CIRCE" compare merged.exr t1.exr --fail 0
grep -q '^max_abs: 0 at' out || fail "5 tiles merged differ from the whole: $(cat out)"
# The scene's global_settings noise_threshold is the same as the option; the option wins over it.
printf 'global_settings { noise_threshold 0.03 }\n#include "farm.pov"\n' >sdl.pov
sdl="-W 40 -H 30 --spp 56 --min-spp 8 --seed 5 --aov error,samples,variance -I $top_srcdir/tests/farm"
# shellcheck disable=SC2086
expect_status 0 "$CIRCE" render sdl.pov -o sdl.exr $sdl
expect_status 0 "$CIRCE" compare sdl.exr t1.exr --fail 0
grep -q '^max_abs: 0 at' out || fail "global_settings noise_threshold differs from --noise-threshold: $(cat out)"
# shellcheck disable=SC2086
expect_status 0 "$CIRCE" render sdl.pov -o sdl2.exr $sdl --noise-threshold 0.2
grep -q '^circe: adaptive: threshold 0.2:' err || fail "--noise-threshold does not override the scene's: $(cat err)"
# Tiles of another threshold are another render: merge refuses them.
# shellcheck disable=SC2086
expect_status 0 "$CIRCE" render "$scene" --tile 0/5 -o other0.exr $opts --noise-threshold 0.2
# shellcheck disable=SC2086
expect_status 1 "$CIRCE" merge -o bad.exr other0.exr tile1.exr tile2.exr tile3.exr tile4.exr
grep -q 'circe.noise_threshold is' err || fail "merge of two thresholds: $(cat err)"
# A fixed-sample render reports its noise too, and without the adaptive line.
expect_status 0 "$CIRCE" render "$scene" -o fixed.exr -W 40 -H 30 --spp 8
grep -q '^circe: noise: estimated NMSE' err || fail "fixed render: no noise line: $(cat err)"
! grep -q '^circe: adaptive:' err || fail "fixed render: an adaptive line: $(cat err)"
# A checkpoint of an adaptive render, then --time with a threshold.
"$CIRCE" render "$scene" -o ck.exr -W 160 -H 120 --spp 1000000 --noise-threshold 0.001 --threads 2 --checkpoint 1 --quiet >log 2>&1 &
pid=$!
for _ in $(seq 40); do
	sleep 0.25
	[ -f ck.exr ] && break
done
kill -INT $pid
wait $pid
[ -f ck.exr ] || fail "no checkpoint after 10 s: $(cat log)"
expect_status 0 "$CIRCE" compare ck.exr ck.exr
expect_status 0 "$CIRCE" render "$scene" -o timed.exr -W 32 -H 24 --time 1 --noise-threshold 0.05 --quiet
pass
