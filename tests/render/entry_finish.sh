#!/bin/sh
# entry_finish.sh: every entry of a patterned texture is lit with its own finish, as POV-Ray's
# ComputeOneTextureColour lights each entry before it blends them (doc/language.md "Patterned
# textures"): a checker of S and S renders as S itself, bit for bit; an average of a matte M and
# a glowing, polished S renders with the mean of M's and S's renders (within 3 %), and so does a
# checker of the two (within 5 %: half of the sphere each); a gradient blending S into S as S
# (within 1 %). With the first entry's finish over the blended pigments (circe before), the
# average was 0.85 of that mean (S lit with M's finish).
. "$top_srcdir/tests/lib.sh"
enter_workdir
scene() {
	cat >"$1.pov" <<EOS
global_settings { assumed_gamma 1 ambient_light 1 }
camera { location <0, 0, -4> look_at 0 angle 35 }
light_source { <-4, 5, -6> color rgb 1 }
#declare M = texture { pigment { rgb <0.8, 0.2, 0.15> } finish { diffuse 0.8 ambient 0 } }
#declare S = texture { pigment { rgb <0.2, 0.3, 0.9> } finish { diffuse 0.1 ambient 0.9 phong 1 phong_size 20 } }
sphere { 0, 1 texture { $2 } }
EOS
	expect_status 0 "$CIRCE" render "$1.pov" -o "$1.exr" -W 48 -H 48 --spp 64 --quiet
}
scene plain "S"
scene checker "checker texture { S } texture { S } scale 0.3"
expect_status 0 "$CIRCE" compare checker.exr plain.exr --fail 1e-6
scene m "M"
scene s "S"
scene avg "average texture_map { [1 M] [1 S] }"
scene mix "checker texture { M } texture { S } scale 0.25"
mean() { "$CIRCE" compare "$1" "$1" | sed -n 's/^mean: a \([^ ]*\) .*/\1/p'; }
mm=$(mean m.exr) ms=$(mean s.exr) mv=$(mean avg.exr) mx=$(mean mix.exr)
awk -v a="$mm" -v b="$ms" -v v="$mv" 'BEGIN { m = (a + b) / 2; exit !(v > 0.97 * m && v < 1.03 * m) }' ||
	fail "average of M and S: mean $mv, the mean of M's ($mm) and S's ($ms) is not within 3 %"
awk -v a="$mm" -v b="$ms" -v v="$mx" 'BEGIN { m = (a + b) / 2; exit !(v > 0.95 * m && v < 1.05 * m) }' ||
	fail "checker of M and S: mean $mx, the mean of M's ($mm) and S's ($ms) is not within 5 %"
scene grad "gradient x texture_map { [0 S] [1 S] } scale 2 translate -x"
mg=$(mean grad.exr)
awk -v a="$ms" -v g="$mg" 'BEGIN { exit !(g > 0.99 * a && g < 1.01 * a) }' ||
	fail "a gradient of S into S: mean $mg, S's $ms"
echo "means: M $mm, S $ms, average $mv, checker $mx, gradient of S into S $mg"
pass
