#!/bin/sh
# clear_highlight.sh: POV-Ray's highlights on a surface with no opaque lobe. A clear sphere
# (rgbt 1, diffuse 0, no interior: a thin surface) with phong 0.4 phong_size 20 under a light
# behind the camera shows its phong highlight on the front and the back surface, as POV-Ray
# (povray 3.7 renders the centre pixel 0.745 linear, circe 0.716 at 64 spp): circe's next-event
# estimation, the highlights' only way in, used to be skipped where the path could only go on by
# the clear lobe, and the sphere was black. The same with a Clear square of a checker.
. "$top_srcdir/tests/lib.sh"
enter_workdir
MKEXR="$top_builddir/tests/io/mkexr"
scene() {
	cat >"$1.pov" <<EOS
global_settings { assumed_gamma 1 ambient_light 0 }
camera { location <0, 0, -4> look_at 0 angle 30 }
light_source { <0, 0, -10> color rgb 1 }
sphere { 0, 1 pigment { $2 } finish { diffuse 0 phong 0.4 phong_size 20 } }
EOS
	expect_status 0 "$CIRCE" render "$1.pov" -o "$1.exr" -W 32 -H 32 --spp 64 --quiet --region 15,15,17,17
}
# The 2 x 2 centre pixels are 0.6 to 0.8 (POV-Ray 0.745 at the centre): within 0.35 of 0.5 each.
"$MKEXR" half.exr 32 32 --const 0.5 --alpha 1 --window 15,15,17,17 || exit 99
for s in "rgbt 1" "checker rgbt 1, rgbt 1" "checker rgbf 1, rgb 0 scale 100"; do
	scene clear "$s"
	"$CIRCE" compare clear.exr half.exr --fail 0.35 --channels R,G,B >cmp.txt 2>&1 ||
		fail "pigment { $s }: no highlight of 0.5 to 0.85 at the centre: $(cat cmp.txt)"
done
pass
