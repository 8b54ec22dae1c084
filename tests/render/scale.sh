#!/bin/sh
# scale.sh: a scene scaled by 1e-8 to 1e8 (camera and lights included) renders the
# same image as at scale 1 with the same seed — ray offsets follow float precision, not a fixed
# epsilon, and nothing weighs lengths against an absolute unit. Lights scale as physics says: a
# point or spot light's intensity and a sphere light's colour by s^2 (irradiance I / d^2), while
# radiance (background, emission) and a parallel light's irradiance stay; POV-Ray's lights
# without intensity (no falloff, or a fade whose fade_distance scales, an area light's axes too)
# keep their colour. "The same" within float
# rounding: paths that diverge by rounding make a difference far below the noise, so the RMSE
# against scale 1 must be under a quarter of the RMSE between two seeds, and no pixel may be off
# by more than 0.05. (Before, at scale 1e-6: the light selection's scene radius had a floor of
# 1e-3 units, so the background was picked 1e5 times too often — fireflies up to 117, 59 % of the
# pixels off by more than 0.01; the plane reached 1e-2, a thousand times the scene, and its hits
# carried that much rounding; below 1e-6 the camera was "degenerate".) SSS materials:
# tests/render/sss_scale.sh.
. "$top_srcdir/tests/lib.sh"
enter_workdir
scales="1 1e-8 1e-6 0.001 1000 1e6 1e8"
for s in $scales; do
	cat >s$s.pov <<EOS
camera { location <0, 1.2, -4> * $s look_at <0, 0.5, 0> * $s angle 50 }
sky_sphere { pigment { color rgb <0.3, 0.35, 0.4> } intensity 1 }
light_source { <-3, 5, -4> * $s color rgb 1 intensity 30 * $s * $s }
light_source { <3, 4, -2> * $s color rgb 20 * $s * $s radius 0.3 * $s }
light_source { <1, 5, -3> * $s color rgb 1 intensity 20 * $s * $s spotlight point_at <0, 0, 0> * $s radius 15 falloff 25 }
light_source { <2, 6, -5> * $s color rgb 0.3 }
light_source { <-2, 3, -1> * $s color rgb 0.5 fade_distance 3 * $s fade_power 2 }
light_source { <0, 6, -2> * $s color rgb 0.4 area_light <2, 0, 0> * $s, <0, 0, 2> * $s, 4, 4 jitter }
union {
  sphere { <0, 0.6, 0>, 0.6 material { diffuse { color rgb <0.8, 0.3, 0.2> } } }
  box { <0.7, 0, -0.3>, <1.3, 0.6, 0.3> material { diffuse { color rgb 0.7 } } }
  box { <-1.4, 0, 0.4>, <-1.0, 0.2, 0.8> material { emission rgb <2, 1.5, 1> } }
  plane { y, 0 material { diffuse { color rgb 0.6 } } }
  scale $s
}
EOS
	expect_status 0 "$CIRCE" render s$s.pov -o s$s.exr -W 48 -H 36 --spp 64 --seed 9 --quiet
done
expect_status 0 "$CIRCE" render s1.pov -o seed.exr -W 48 -H 36 --spp 64 --seed 10 --quiet
noise=$(seed_noise seed.exr s1.exr)
for s in $scales; do
	[ "$s" = 1 ] && continue
	expect_same_within_noise "scale $s" s$s.exr s1.exr "$noise" 4
	expect_status 0 "$CIRCE" compare s$s.exr s1.exr --fail 0.05
done
pass
