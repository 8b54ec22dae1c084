#!/bin/sh
# plane.sh: a plane renders on its own (POV-Ray's first scene: a plane and a light) with the
# shading a diffuse plane under a point light has in closed form (a physical light with intensity,
# and POV-Ray's without: no falloff, or its fade; shadowless through an occluder), and what it shows does not
# depend on the other objects of the scene: a small object far behind the camera leaves its
# pixels as they were (the plane reaches out to its horizon from the camera, not to the bounds of
# the rest of the scene).
. "$top_srcdir/tests/lib.sh"
enter_workdir
MKEXR="$top_builddir/tests/io/mkexr"
cat >alone.pov <<'EOS'
camera { location <0, 1, -2> look_at <0, 0, 0> }
light_source { <0, 4, 0> color rgb 1 intensity 16 }
plane { y, 0 material { diffuse { color rgb 1 } } }
EOS
# The centre pixels see the plane about the origin, 4 below the light: radiance
# albedo / pi * I / d^2 = 1 / pi (within 1 %: the pixels lie within 0.05 of the origin).
expect_status 0 "$CIRCE" render alone.pov -o alone.exr -W 32 -H 24 --spp 16 --quiet --region 15,11,17,13
"$MKEXR" ref.exr 32 24 --const 0.31831 --alpha 1 --window 15,11,17,13 || exit 99
expect_status 0 "$CIRCE" compare alone.exr ref.exr --fail 0.0032 --channels R,G,B
# POV-Ray's light without intensity, ten times as far: no falloff, and POV-Ray's brightness (its
# colour scaled by pi, build_light.c): radiance albedo * C = 1, as POV-Ray shows pigment * C; and
# one faded at its fade_distance, where POV-Ray's 2 / (1 + 1^3) is 1.
sed 's|light_source {.*|light_source { <0, 40, 0> color rgb 1 }|' alone.pov >pov.pov
sed 's|light_source {.*|light_source { <0, 8, 0> color rgb 1 fade_distance 8 fade_power 3 }|' alone.pov >fade.pov
# A shadowless light through a black sphere above the centre: the plane lit as without it.
sed 's|light_source {.*|light_source { <0, 40, 0> color rgb 1 shadowless }\nsphere { <0, 3, 0>, 0.5 material { diffuse { color rgb 0 } } }|' alone.pov >shadowless.pov
"$MKEXR" ref1.exr 32 24 --const 1 --alpha 1 --window 15,11,17,13 || exit 99
for f in pov fade shadowless; do
	expect_status 0 "$CIRCE" render $f.pov -o $f.exr -W 32 -H 24 --spp 16 --quiet --region 15,11,17,13
	expect_status 0 "$CIRCE" compare $f.exr ref1.exr --fail 0.01 --channels R,G,B
done
expect_status 0 "$CIRCE" check alone.pov
grep -q "triangles after tessellation: 0 unique" out && fail "check counts no triangles for the plane: $(cat out)"
# The whole frame, alone and with a small sphere 40 units behind the camera.
sed 's|^plane|sphere { <3, 0.5, -40>, 0.5 }\nplane|' alone.pov >far.pov
expect_status 0 "$CIRCE" render alone.pov -o a.exr -W 64 -H 48 --spp 16 --quiet
expect_status 0 "$CIRCE" render alone.pov -o a2.exr -W 64 -H 48 --spp 16 --quiet --seed 7
expect_status 0 "$CIRCE" render far.pov -o f.exr -W 64 -H 48 --spp 16 --quiet
noise=$(seed_noise a.exr a2.exr)
expect_same_within_noise "far object" f.exr a.exr "$noise" 1
expect_status 0 "$CIRCE" compare f.exr a.exr --fail 0.01 --channels R,G,B
pass
