#!/bin/sh
# walk_skip.sh: the volume walk's skipped casts (src/sss/README.md, "Skipping casts") change no
# image: a wax bunny (an imported mesh under a similarity transform) and a wax sphere rendered
# with --sss volume, the skip on (the default) and off (CIRCE_WALK_SKIP=off), same seed: the two
# images' RMSE under 1/20 of the RMSE between two seeds, and their means equal within 1/20 of the
# seed-to-seed difference of the means; most interactions skip their cast. Those two renders keep
# the runs inside a ball off (CIRCE_WALK_RUN=off: a run samples its steps otherwise, so the image
# differs by noise); with them on (the default) the image's mean agrees with theirs within 3
# standard errors and its RMSE against them is seed noise (under 1.5 times it), and 1
# and 2 threads and four regions merged give the same image, bit for bit.
. "$top_srcdir/tests/lib.sh"
enter_workdir
cat >w.pov <<EOS
global_settings { mm_per_unit 3 }
camera { location <0, 5, -22> look_at <0, 4.6, 0> angle 40 }
light_source { <-16, 12, 10> color rgb 1 intensity 1500 }
light_source { <4, 8, -20> color rgb 1 intensity 80 }
background { color rgb 0 }
mesh { file "$top_srcdir/scenes/assets/bunny/bunny_npm.obj" material { wax {} } scale 0.8 rotate <0, 20, 0> translate <-2, 0.5, 0> }
sphere { <4, 3, 0>, 2 material { wax {} } }
EOS
opts="-W 32 -H 24 --spp 4 --sss volume"
expect_status 0 env CIRCE_WALK_RUN=off "$CIRCE" render w.pov -o noruns.exr $opts --seed 3 --threads 1
grep 'without a ray cast' err >skip.txt || fail "no skipped casts reported: $(cat err)"
frac=$(sed -n 's/.*walks: \([0-9.e-]*\) of the interactions without.*/\1/p' skip.txt)
awk -v f="$frac" 'BEGIN { exit !(f > 0.3) }' || fail "only $frac of the interactions skipped their cast"
expect_status 0 env CIRCE_WALK_SKIP=off "$CIRCE" render w.pov -o off.exr $opts --seed 3 --threads 1
grep -q 'without a ray cast' err && fail "CIRCE_WALK_SKIP=off still skipped: $(cat err)"
expect_status 0 env CIRCE_WALK_RUN=off "$CIRCE" render w.pov -o seed.exr $opts --seed 4 --threads 1
noise=$(seed_noise seed.exr off.exr)
expect_same_within_noise "skip on against off" noruns.exr off.exr "$noise" 20
mean_of() { "$CIRCE" compare "$1" "$2" --fail 1e30 2>/dev/null | awk '/^mean:/ { print $3, $5 }'; }
set -- $(mean_of noruns.exr off.exr) $(mean_of seed.exr off.exr)
awk -v a="$1" -v b="$2" -v s="$3" 'BEGIN { d = a - b; n = s - b; if (d < 0) d = -d; if (n < 0) n = -n
	exit !(d <= n / 20 + 1e-12) }' || fail "means: skip on $1, off $2; another seed $3"
echo "means: skip on $1, off $2, another seed $3; $frac of the interactions without a cast"
# the runs inside a ball: another sampling of the same walk, so the same image up to noise
expect_status 0 "$CIRCE" render w.pov -o on.exr $opts --seed 3 --threads 1
set -- $(mean_of on.exr off.exr) $(mean_of seed.exr off.exr)
# the mean's standard error from the per-pixel noise (the seed-to-seed RMSE over sqrt(2 N),
# N = 32 x 24 pixels): within 3 of it (0.005 here, 2 % of the mean; a bias like circle's on thin wax,
# -7.6 %, fails)
awk -v a="$1" -v b="$2" -v e="$noise" 'BEGIN { d = a - b; if (d < 0) d = -d
	exit !(d <= 3 * e / sqrt(2 * 768)) }' || fail "means: runs $1, no runs $2; noise between seeds $noise"
expect_same_within_noise "runs against none" on.exr off.exr "$noise" 0.67
echo "means: runs $1, none $2, another seed $3"
expect_status 0 "$CIRCE" render w.pov -o on2.exr $opts --seed 3 --threads 2
expect_status 0 "$CIRCE" compare on2.exr on.exr --fail 0
grep -q '^max_abs: 0 at' out || fail "skip on: 1 and 2 threads differ: $(cat out)"
for r in 0,0,16,12 16,0,32,12 0,12,16,24 16,12,32,24; do
	expect_status 0 "$CIRCE" render w.pov -o "q$r.exr" $opts --seed 3 --threads 2 --quiet --region $r
done
expect_status 0 "$CIRCE" merge -o quarters.exr q*.exr
expect_status 0 "$CIRCE" compare quarters.exr on.exr --fail 0
grep -q '^max_abs: 0 at' out || fail "skip on: regions assembled differ from the whole: $(cat out)"
pass
