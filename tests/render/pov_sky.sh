#!/bin/sh
# pov_sky.sh: POV-Ray's sky lights only under radiosity (doc/language.md, "The sky and radiosity").
# A white sphere (pigment 1, diffuse 1, ambient 0) fills the centre of the frame under a white sky
# and no light: under POV-Ray's `background` it renders 0 (the sky lights no diffuse surface);
# under `global_settings { radiosity {} }`, or circe's own sky (`intensity`), it is the furnace,
# 1.0; a mirror (reflection 1, diffuse 0) shows POV-Ray's sky, 1.0, with or without radiosity;
# and the implicit ambient 0.1 glows 0.1 * pigment * ambient_light without radiosity (0.05 at
# ambient_light 0.5) but not under circe's sky. A sky_sphere's image_map (map_type 1, a uniform
# EXR of 0.5) is what the mirror shows: 0.5.
. "$top_srcdir/tests/lib.sh"
enter_workdir
MKEXR="$top_builddir/tests/io/mkexr"
# scene NAME SETTINGS SKY FINISH: NAME.exr, the 12x12 centre pixels (all on the sphere).
scene() {
	cat >"$1.pov" <<EOS
global_settings { $2 }
camera { location <0, 0, -3> look_at <0, 0, 0> angle 40 }
$3
sphere { <0, 0, 0>, 1 texture { pigment { color rgb 1 } finish { $4 } } }
EOS
	expect_status 0 "$CIRCE" render "$1.pov" -o "$1.exr" -W 32 -H 32 --spp 256 --quiet --region 10,10,22,22
}
# near NAME VALUE TOLERANCE: NAME.exr's centre is VALUE within the tolerance (relative).
near() {
	"$MKEXR" "ref$2.exr" 32 32 --const "$2" --alpha 1 --window 10,10,22,22 || exit 99
	"$CIRCE" compare "$1.exr" "ref$2.exr" --fail "$3" >cmp.txt 2>&1 || fail "$1: not $2 within $3: $(cat cmp.txt)"
}
sky="background { color rgb 1 }"
scene dark "max_trace_level 5" "$sky" "ambient 0 diffuse 1"
"$MKEXR" zero.exr 32 32 --const 0 --alpha 1 --window 10,10,22,22 || exit 99
expect_status 0 "$CIRCE" compare dark.exr zero.exr --fail 1e-6
scene lit "radiosity { count 50 }" "$sky" "ambient 0 diffuse 1"
near lit 1 0.01
scene circe "max_trace_level 5" "sky_sphere { pigment { color rgb 1 } intensity 1 }" "ambient 0 diffuse 1"
near circe 1 0.01
scene mirror "max_trace_level 5" "$sky" "ambient 0 diffuse 0 reflection 1"
near mirror 1 0.01
scene mirror_r "radiosity { }" "$sky" "ambient 0 diffuse 0 reflection 1"
near mirror_r 1 0.01
scene glow "ambient_light 0.5" "$sky" "diffuse 1"
near glow 0.05 0.001
scene glow_r "ambient_light 0.5 radiosity { }" "" "diffuse 1 ambient 1"
expect_status 0 "$CIRCE" compare glow_r.exr zero.exr --fail 1e-6
scene glow_c "ambient_light 0.5" "sky_sphere { pigment { color rgb 0 } intensity 1 }" "diffuse 1"
expect_status 0 "$CIRCE" compare glow_c.exr zero.exr --fail 1e-6
"$MKEXR" sky.exr 16 8 --const 0.5 --alpha 1 || exit 99
scene mirror_img "max_trace_level 5" "sky_sphere { pigment { image_map { exr \"sky.exr\" map_type 1 } } }" "ambient 0 diffuse 0 reflection 1"
near mirror_img 0.5 0.01
pass
