#!/bin/sh
# determinism.sh: the same scene and seed give bit-identical EXRs for 1 and 2 threads, and four
# --region quarters assembled equal the whole image bit-exactly; another seed gives another image.
# Both samplers (Sobol, the default, and random).
# Every SSS method (auto included, and its regions) is deterministic across thread counts too, and the BVH's SSE2 path (4-wide, as on
# a CPU without AVX2: CIRCE_SIMD=sse2) renders the same pixels as the dispatched one (8-wide with
# AVX2 where the CPU has it): the trees differ, their hits do not.
. "$top_srcdir/tests/lib.sh"
scene="$top_srcdir/tests/farm/farm.pov"
enter_workdir
opts="-W 40 -H 30 --spp 8 --seed 3 --quiet --aov albedo,normal,depth,variance"
# shellcheck disable=SC2086
"$CIRCE" render "$scene" -o t1.exr --threads 1 $opts >log 2>&1 ||
	{ grep -q "which this build lacks" log && skip "circe render is not in this build yet"; fail "render: $(cat log)"; }
# shellcheck disable=SC2086
expect_status 0 "$CIRCE" render "$scene" -o t2.exr --threads 2 $opts
expect_status 0 "$CIRCE" compare t2.exr t1.exr --fail 0
grep -q '^max_abs: 0 at' out || fail "1 and 2 threads differ: $(cat out)"
grep -qx 'channels: 14' out || fail "expected RGBA + 10 AOV channels: $(cat out)"
for r in 0,0,20,15 20,0,40,15 0,15,20,30 20,15,40,30; do
	# shellcheck disable=SC2086
	expect_status 0 "$CIRCE" render "$scene" -o "q$r.exr" --threads 2 --region $r $opts
done
expect_status 0 "$CIRCE" merge -o quarters.exr q*.exr
expect_status 0 "$CIRCE" compare quarters.exr t1.exr --fail 0
grep -q '^max_abs: 0 at' out || fail "regions assembled differ from the whole: $(cat out)"
# shellcheck disable=SC2086
expect_status 0 "$CIRCE" render "$scene" -o s4.exr $opts --seed 4
expect_status 1 "$CIRCE" compare s4.exr t1.exr --fail 0
# The random sampler (--sampler random) is as deterministic, and another image than Sobol's.
for t in 1 2; do
	# shellcheck disable=SC2086
	expect_status 0 "$CIRCE" render "$scene" -o "r$t.exr" --threads $t --sampler random $opts
done
expect_status 0 "$CIRCE" compare r2.exr r1.exr --fail 0
grep -q '^max_abs: 0 at' out || fail "--sampler random: 1 and 2 threads differ: $(cat out)"
expect_status 1 "$CIRCE" compare r1.exr t1.exr --fail 0
# Tiles of different samplers are not one render.
# shellcheck disable=SC2086
expect_status 0 "$CIRCE" render "$scene" -o qr.exr --threads 2 --region 0,0,20,15 --sampler random $opts
expect_status 1 "$CIRCE" merge -o mixed.exr qr.exr "q20,0,40,15.exr" "q0,15,20,30.exr" "q20,15,40,30.exr"
grep -q 'circe.sampler is' err || fail "merge took tiles of two samplers: $(cat err)"
cat >sss.pov <<'EOS'
camera { location <0, 1.2, -4> look_at <0, 0.5, 0> angle 50 }
sky_sphere { pigment { color rgb <0.6, 0.7, 0.8> } intensity 1 }
light_source { <-3, 5, -4> color rgb 2 parallel point_at <0, 0, 0> }
sphere { <0, 0.6, 0>, 0.6 material { wax { } } }
box { <0.7, 0, -0.3>, <1.3, 0.6, 0.3> material { skin { } } }
EOS
for m in circle fullcircle disk volume auto; do
	for t in 1 2; do
		expect_status 0 "$CIRCE" render sss.pov -o "$m$t.exr" --threads $t --sss $m -W 24 -H 18 --spp 4 --quiet
	done
	expect_status 0 "$CIRCE" compare "${m}2.exr" "${m}1.exr" --fail 0
	grep -q '^max_abs: 0 at' out || fail "--sss $m: 1 and 2 threads differ: $(cat out)"
	expect_status 0 env CIRCE_SIMD=sse2 "$CIRCE" render sss.pov -o "${m}sse2.exr" --sss $m -W 24 -H 18 --spp 4 --quiet
	expect_status 0 "$CIRCE" compare "${m}sse2.exr" "${m}1.exr" --fail 0
	grep -q '^max_abs: 0 at' out || fail "--sss $m: the SSE2 and the dispatched BVH differ: $(cat out)"
done
# auto's choice between circle and walk (wax sphere 12 mm across: in its band; the skin box 6 mm:
# walks) comes from the sample's own generator: regions assembled equal the whole image too.
for r in 0,0,12,9 12,0,24,9 0,9,12,18 12,9,24,18; do
	expect_status 0 "$CIRCE" render sss.pov -o "auto_q$r.exr" --threads 2 --sss auto -W 24 -H 18 --spp 4 --quiet --region $r
done
expect_status 0 "$CIRCE" merge -o auto_quarters.exr auto_q*.exr
expect_status 0 "$CIRCE" compare auto_quarters.exr auto1.exr --fail 0
grep -q '^max_abs: 0 at' out || fail "--sss auto: regions assembled differ from the whole: $(cat out)"
# Media: delta and ratio tracking draw from the sample's own generator, whatever the threads.
for t in 1 2; do
	expect_status 0 "$CIRCE" render "$top_srcdir/tests/scenes/media.pov" -o "media$t.exr" --threads $t -W 32 -H 24 \
		--spp 4 --quiet
done
expect_status 0 "$CIRCE" compare media2.exr media1.exr --fail 0
grep -q '^max_abs: 0 at' out || fail "media: 1 and 2 threads differ: $(cat out)"
expect_status 0 env CIRCE_SIMD=sse2 "$CIRCE" render "$scene" -o sse2.exr $opts
expect_status 0 "$CIRCE" compare sse2.exr t1.exr --fail 0
grep -q '^max_abs: 0 at' out || fail "the SSE2 and the dispatched BVH differ: $(cat out)"
pass
