#!/bin/sh
# color_range.sh: colours outside the range of their physical use — legal in POV-Ray, whose
# sombrero sample paints with rgb <-0.5, ...> — are clamped with one warning at the colour: a
# reflectance (pigment, diffuse) into [0, 1], a radiance (emission, background) into [0, inf).
# The render drops no sample as non-finite (before: 55289 of the 55296 below) and is
# the very image of the scene written with the clamped colours. Float (EXR) textures and
# environments may hold any number: their texels are clamped the same way (a NaN or an infinity
# to 0), with one warning naming how many (before: samples dropped for each bad texel seen).
. "$top_srcdir/tests/lib.sh"
enter_workdir
cat >neg.pov <<'EOS'
camera { location <0, 0.5, -4> look_at <0, 0, 0> angle 50 }
light_source { <-3, 5, -4> color rgb 30 }
background { color rgb <0.2, -0.1, 0.3> }
sphere { 0, 1 texture { pigment { color rgb <-0.5, 0.5, 0.5> } } }
#declare I = 0;
#while (I < 3)
  sphere { <-1.5 + 1.5 * I, -1.2, 1>, 0.3 material { diffuse { color rgb <1.5, 0.4, -2> } } }
  #declare I = I + 1;
#end
box { <-2, 1.2, 1>, <2, 1.4, 1.2> material { emission rgb <4, -1, 2> } }
EOS
sed 's/<0.2, -0.1, 0.3>/<0.2, 0, 0.3>/; s/<-0.5, 0.5, 0.5>/<0, 0.5, 0.5>/; s/<1.5, 0.4, -2>/<1, 0.4, 0>/; s/<4, -1, 2>/<4, 0, 2>/' \
	neg.pov >clamped.pov
expect_status 0 "$CIRCE" render neg.pov -o neg.exr -W 48 -H 36 --spp 32 --seed 4
grep -q ' 0 non-finite samples dropped' err || fail "samples dropped as non-finite: $(cat err)"
for w in \
	'neg.pov:3:14: warning: background colour <0.2, -0.1, 0.3> is outside [0, inf), the range of a radiance: clamped to <0.2, 0, 0.3>' \
	'neg.pov:4:35: warning: pigment colour <-0.5, 0.5, 0.5> is outside [0, 1], the range of a reflectance: clamped to <0, 0.5, 0.5>' \
	'neg.pov:7:64: warning: diffuse colour <1.5, 0.4, -2> is outside [0, 1], the range of a reflectance: clamped to <1, 0.4, 0>' \
	'neg.pov:10:55: warning: emission <4, -1, 2> is outside [0, inf), the range of a radiance: clamped to <4, 0, 2>'; do
	grep -qxF "$w" err || fail "missing warning '$w' in: $(cat err)"
done
# Once per colour: the loop passes the diffuse colour three times.
n=$(grep -c 'warning:' err)
[ "$n" = 4 ] || fail "$n warnings, want 4 (one per colour): $(cat err)"
expect_status 0 "$CIRCE" render clamped.pov -o clamped.exr -W 48 -H 36 --spp 32 --seed 4 --quiet
grep -q 'warning' err && fail "warnings for colours in range: $(cat err)"
expect_status 0 "$CIRCE" compare neg.exr clamped.exr --fail 0
# An albedo texture and an environment with a negative, a NaN, an infinite and (albedo) a > 1 texel.
MKEXR="$top_builddir/tests/io/mkexr"
"$MKEXR" tex.exr 8 8 --const 0.5 --set 1,1,R,-3 --set 2,2,G,nan --set 3,3,B,inf --set 4,4,R,5 || exit 99
"$MKEXR" env.exr 16 8 --const 0.5 --set 1,1,R,-3 --set 2,2,G,nan --set 3,3,B,inf || exit 99
cat >tex.pov <<'EOS'
camera { location <0, 0.5, -4> look_at <0, 0, 0> angle 50 }
light_source { <-3, 5, -4> color rgb 30 }
sky_sphere { image "env.exr" }
sphere { <-0.6, 0, 0>, 0.5 texture { pigment { image_map { exr "tex.exr" } } } }
sphere { <0.6, 0, 0>, 0.5 material { wax { image "tex.exr" radius 2 } } }
EOS
expect_status 0 "$CIRCE" render tex.pov -o tex.exr -W 48 -H 36 --spp 32 --seed 4
grep -q ' 0 non-finite samples dropped' err || fail "samples dropped as non-finite: $(cat err)"
for w in \
	"tex.pov:3:1: warning: 3 texels of the environment are outside [0, inf), the range of a radiance (negative, NaN or infinite): clamped, a non-finite one to 0" \
	"tex.pov:4:48: warning: 4 texels of 'tex.exr' are outside [0, 1], the range of a reflectance: clamped, a non-finite one to 0" \
	"tex.pov:5:27: warning: 4 texels of 'tex.exr' are outside [0, 1], the range of a reflectance: clamped, a non-finite one to 0"; do
	grep -qxF "$w" err || fail "missing warning '$w' in: $(cat err)"
done
pass
