#!/bin/sh
# layered_map.sh: a layered texture as an entry of a patterned texture is lit per layer, each
# layer with its own finish, as at the top level (POV-Ray's ComputeOneTextureColour lights each
# entry by ComputeLightedTexture): a checker of T and T renders as T itself, bit for bit; an
# average of a glazed layered texture A (red under a clear layer with phong) and a matte B renders
# with the mean of A's and B's renders, and a gradient blending A into A as A itself (within 1 %) (the entries blended after lighting, each with its own
# finish; the old composite pigment under A's top finish alone was 13 % darker).
. "$top_srcdir/tests/lib.sh"
enter_workdir
scene() {
	cat >"$1.pov" <<EOS
global_settings { assumed_gamma 1 ambient_light 0 }
camera { location <0, 0, -4> look_at 0 angle 35 }
light_source { <-4, 5, -6> color rgb 1 }
#declare A =
  texture { pigment { rgb <0.8, 0.2, 0.15> } finish { diffuse 0.7 } }
  texture { pigment { rgbt <1, 1, 1, 0.85> } finish { phong 0.9 phong_size 40 diffuse 0.3 } }
#declare B = texture { pigment { rgb <0.9, 0.85, 0.3> } finish { diffuse 0.8 } }
sphere { 0, 1 texture { $2 } }
EOS
	expect_status 0 "$CIRCE" render "$1.pov" -o "$1.exr" -W 48 -H 48 --spp 64 --quiet
}
scene plain "A"
scene checker "checker texture { A } texture { A } scale 0.3"
expect_status 0 "$CIRCE" compare checker.exr plain.exr --fail 1e-6
scene a "A"
scene b "B"
scene avg "average texture_map { [1 A] [1 B] }"
mean() { "$CIRCE" compare "$1" "$1" | sed -n 's/^mean: a \([^ ]*\) .*/\1/p'; }
ma=$(mean a.exr) mb=$(mean b.exr) mv=$(mean avg.exr)
awk -v a="$ma" -v b="$mb" -v v="$mv" 'BEGIN { m = (a + b) / 2; exit !(v > 0.97 * m && v < 1.03 * m) }' ||
	fail "average of A and B: mean $mv, the mean of A's ($ma) and B's ($mb) is not within 3 %"
scene grad "gradient x texture_map { [0 A] [1 A] } scale 2 translate -x"
mg=$(mean grad.exr)
awk -v a="$ma" -v g="$mg" 'BEGIN { exit !(g > 0.99 * a && g < 1.01 * a) }' ||
	fail "a gradient of A into A: mean $mg, A's $ma"
echo "means: A $ma, B $mb, average $mv, gradient of A into A $mg"
pass
