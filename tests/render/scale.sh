#!/bin/sh
# scale.sh: a scene scaled by 1e-3 and by 1e3 (camera included) renders the same image as at
# scale 1 with the same seed — ray offsets follow float precision, not a fixed epsilon. "The same"
# within float rounding: paths that diverge by rounding make a difference far below the noise, so
# the RMSE against scale 1 must be under a quarter of the RMSE between two seeds.
. "$top_srcdir/tests/lib.sh"
enter_workdir
for s in 1 0.001 1000; do
	cat >s$s.pov <<EOS
camera { location <0, 1.2, -4> * $s look_at <0, 0.5, 0> * $s angle 50 }
background { color rgb <0.6, 0.7, 0.8> }
union {
  sphere { <0, 0.6, 0>, 0.6 material { diffuse { color rgb <0.8, 0.3, 0.2> } } }
  box { <0.7, 0, -0.3>, <1.3, 0.6, 0.3> material { diffuse { color rgb 0.7 } } }
  box { <-3, -0.1, -3>, <3, 0, 3> material { diffuse { color rgb 0.6 } } }
  scale $s
}
EOS
	expect_status 0 "$CIRCE" render s$s.pov -o s$s.exr -W 48 -H 36 --spp 64 --seed 9 --quiet
done
expect_status 0 "$CIRCE" render s1.pov -o seed.exr -W 48 -H 36 --spp 64 --seed 10 --quiet
noise=$(seed_noise seed.exr s1.exr)
for s in 0.001 1000; do
	expect_same_within_noise "scale $s" s$s.exr s1.exr "$noise" 4
done
pass
