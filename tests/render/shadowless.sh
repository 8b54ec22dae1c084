#!/bin/sh
# shadowless.sh: a POV-Ray shadowless light is its fill light (trace.cpp gives a FILL_LIGHT_SOURCE
# no highlights): it lights the diffuse, with its brilliance, but makes no specular or phong. A
# white sphere of diffuse 0 with phong 0.8 and specular 0.6 under a light behind the camera shows
# its highlights at the centre (POV-Ray 1.4, clipped to 1 in its PNG; circe 1.31, its energy cap);
# under the same light made shadowless the centre is black (povray 3.7: 0 there; circe drew both
# highlights before). With diffuse 0.6 the shadowless light's centre is the diffuse alone, Kd cos^b
# = 0.6 at normal incidence (povray 3.7: 0.6).
. "$top_srcdir/tests/lib.sh"
enter_workdir
MKEXR="$top_builddir/tests/io/mkexr"
scene() {
	cat >"$1.pov" <<EOS
global_settings { assumed_gamma 1 ambient_light 0 }
camera { location <0, 0, -4> look_at 0 angle 30 }
light_source { <0, 0, -10> color rgb 1 $2 }
sphere { 0, 1 pigment { rgb 1 } finish { diffuse $3 brilliance 2 phong 0.8 phong_size 20 specular 0.6 roughness 0.05 } }
EOS
	expect_status 0 "$CIRCE" render "$1.pov" -o "$1.exr" -W 32 -H 32 --spp 16 --quiet --region 15,15,17,17
}
"$MKEXR" high.exr 32 32 --const 1.2 --alpha 1 --window 15,15,17,17 || exit 99
"$MKEXR" zero.exr 32 32 --const 0 --alpha 1 --window 15,15,17,17 || exit 99
"$MKEXR" diff.exr 32 32 --const 0.6 --alpha 1 --window 15,15,17,17 || exit 99
scene lit "" 0
"$CIRCE" compare lit.exr high.exr --fail 0.25 --channels R,G,B >cmp.txt 2>&1 ||
	fail "an ordinary light: no highlight of 0.95 to 1.45 at the centre: $(cat cmp.txt)"
scene fill shadowless 0
"$CIRCE" compare fill.exr zero.exr --fail 0.001 --channels R,G,B >cmp.txt 2>&1 ||
	fail "a shadowless light makes a highlight: $(cat cmp.txt)"
scene filld shadowless 0.6
"$CIRCE" compare filld.exr diff.exr --fail 0.02 --channels R,G,B >cmp.txt 2>&1 ||
	fail "a shadowless light's diffuse is not 0.6 at the centre: $(cat cmp.txt)"
pass
