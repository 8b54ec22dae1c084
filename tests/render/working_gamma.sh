#!/bin/sh
# working_gamma.sh: POV-Ray's assumed_gamma (doc/language.md, "assumed_gamma"; scene/gamma.c).
# POV-Ray computes in its working space of gamma G with the colours as written and writes the
# light r^G: a background of 0.5 under assumed_gamma 2.2 is written as 0.5^2.2 = 0.21764, and
# under 1 as 0.5. An image is decoded to light and re-encoded into the working space: an EXR of
# constant 0.3 on a glowing square (ambient 1, diffuse 0) that fills the frame is written as 0.3
# under any G; a plain colour of 0.3 on it as 0.3^G. The PNG preview gets the same curve.
. "$top_srcdir/tests/lib.sh"
enter_workdir
MKEXR="$top_builddir/tests/io/mkexr"
# scene NAME GAMMA BODY: NAME.exr, 8x8, 4 spp (nothing here is noisy: no light, glow and sky only)
scene() {
	cat >"$1.pov" <<EOS
global_settings { assumed_gamma $2 }
camera { orthographic location <0, 0, -3> look_at <0, 0, 0> right x up y }
$3
EOS
	expect_status 0 "$CIRCE" render "$1.pov" -o "$1.exr" --png "$1.png" -W 8 -H 8 --spp 4 --quiet
}
# near NAME VALUE: NAME.exr is VALUE everywhere within 1e-5 (relative).
near() {
	"$MKEXR" "ref_$1.exr" 8 8 --const "$2" --alpha 1 || exit 99
	"$CIRCE" compare "$1.exr" "ref_$1.exr" --fail 1e-5 >cmp.txt 2>&1 || fail "$1: not $2: $(cat cmp.txt)"
}
"$MKEXR" c03.exr 4 4 --const 0.3 --alpha 1 || exit 99
square="box { <-1, -1, 0>, <1, 1, 0.1> finish { ambient 1 diffuse 0 } "
scene bg22 2.2 "background { color rgb 0.5 }"
near bg22 0.2176376
scene bg1 1.0 "background { color rgb 0.5 }"
near bg1 0.5
scene img22 2.2 "$square pigment { image_map { exr \"c03.exr\" } } }"
near img22 0.3
scene plain22 2.2 "$square pigment { color rgb 0.3 } }"
near plain22 0.0707403
# the preview: the same bytes as a G = 1 scene whose background is 0.5^2.2
scene bgref 1.0 "background { color rgb 0.2176376 }"
cmp -s bg22.png bgref.png || fail "bg22.png differs from bgref.png"
pass
