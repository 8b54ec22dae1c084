#!/bin/sh
# sss_scale.sh: a scene with subsurface scattering scaled by 1e-8 to 1e8, with mm_per_unit
# scaled inversely (the same physical size in mm), renders the same image as at scale 1 with the
# same seed: profile radii follow the scene through mm_per_unit, circles and ray offsets follow
# float precision. This is what scale invariance means for SSS: every scattering length of a
# material (radius, sigma_s, sigma_a) is in millimetres, never in scene units, so scaling the
# geometry alone makes the object physically smaller and rightly more translucent; scaling it with
# mm_per_unit keeps the object and the image. "The same" within rounding: the RMSE against scale 1 must be under 1/20 of the
# RMSE between two seeds, for circle, disk and volume. Also checks that the no-hit rate is printed.
. "$top_srcdir/tests/lib.sh"
enter_workdir
for s in 1 1e-8 1e-6 0.001 1000 1e6 1e8; do
	cat >s$s.pov <<EOS
global_settings { mm_per_unit 10 / $s }
camera { location <0, 1.2, -4> * $s look_at <0, 0.5, 0> * $s angle 50 }
sky_sphere { pigment { color rgb <0.6, 0.7, 0.8> } intensity 1 }
light_source { <-3, 5, -4> color rgb 2 parallel point_at <0, 0, 0> }
union {
  sphere { <0, 0.6, 0>, 0.6 material { wax { radius <20, 12, 6> } } }
  box { <0.7, 0, -0.3>, <1.3, 0.6, 0.3> material { skin { } } }
  box { <-3, -0.1, -3>, <3, 0, 3> material { marble { } } }
  scale $s
}
EOS
done
# Every method: circle, the disk's probes and the volume's walk all follow mm_per_unit.
for m in circle disk volume; do
	for s in 1 1e-8 1e-6 0.001 1000 1e6 1e8; do
		expect_status 0 "$CIRCE" render s$s.pov -o $m$s.exr -W 40 -H 30 --spp 16 --seed 9 --threads 1 --sss $m
	done
	grep -q 'no-hit rate' err || fail "no no-hit rate printed: $(cat err)"
	expect_status 0 "$CIRCE" render s1.pov -o seed.exr -W 40 -H 30 --spp 16 --seed 10 --quiet --sss $m
	noise=$(seed_noise seed.exr $m"1.exr")
	for s in 1e-8 1e-6 0.001 1000 1e6 1e8; do
		expect_same_within_noise "$m, scale $s" $m$s.exr $m"1.exr" "$noise" 20
	done
done
pass
