#!/bin/sh
# furnace.sh: the white furnace through the whole pipeline (language, tessellation, BVH, path
# tracer, EXR): a diffuse sphere of albedo 1 inside a constant white background renders 1.0 in
# every pixel within 0.3 %, and albedo 0.5 renders 0.5 on the sphere (a convex object sees only the
# background, so its radiance is its albedo). The background is sampled by cosine about the
# normal, so one sample here has a standard deviation of only about 0.007 (0.23 when it was
# sampled over the whole sphere; what is left comes from shading normals that differ from the
# facets'): over 1024 samples, 0.3 % is more than ten standard deviations of a pixel.
. "$top_srcdir/tests/lib.sh"
enter_workdir
MKEXR="$top_builddir/tests/io/mkexr"
for a in 1 0.5; do
	cat >f.pov <<EOS
camera { location <0, 0, -3> look_at <0, 0, 0> angle 40 }
sky_sphere { pigment { color rgb 1 } intensity 1 }
sphere { <0, 0, 0>, 1 material { diffuse { color rgb $a } } }
EOS
	# The centre 12x12 pixels lie on the sphere; albedo 1 is also checked over the whole image.
	expect_status 0 "$CIRCE" render f.pov -o f.exr -W 32 -H 32 --spp 1024 --quiet --region 10,10,22,22
	"$MKEXR" ref.exr 32 32 --const "$a" --alpha 1 --window 10,10,22,22 || exit 99
	expect_status 0 "$CIRCE" compare f.exr ref.exr --fail 0.003
done
# POV-Ray's finish (BSDF_POV) under POV-Ray's background, which lights under radiosity (where the
# finish's implicit ambient 0.1 is off, as in POV-Ray; doc/language.md): a white pigment of diffuse 1 reflects everything (1.0 within 0.3 %),
# and one that asks for more than everything (diffuse 1, phong 1, specular 1, reflection 0.5) is
# scaled to reflect at most that (bsdf_pov.h): between 0.9 and 1.003 (GGX's masking loses a little).
cat >p.pov <<'EOS'
global_settings { radiosity { } }
camera { location <0, 0, -3> look_at <0, 0, 0> angle 40 }
background { color rgb 1 }
sphere { <0, 0, 0>, 1 texture { pigment { color rgb 1 } finish { diffuse 1 } } }
EOS
expect_status 0 "$CIRCE" render p.pov -o p.exr -W 32 -H 32 --spp 1024 --quiet --region 10,10,22,22
"$MKEXR" ref.exr 32 32 --const 1 --alpha 1 --window 10,10,22,22 || exit 99
expect_status 0 "$CIRCE" compare p.exr ref.exr --fail 0.003
sed -i 's|finish { diffuse 1 }|finish { diffuse 1 phong 1 specular 1 reflection 0.5 }|' p.pov
expect_status 0 "$CIRCE" render p.pov -o h.exr -W 32 -H 32 --spp 1024 --quiet --region 10,10,22,22
"$CIRCE" compare h.exr ref.exr >cmp.txt 2>&1
awk '/^mean:/ { m = $3 } END { exit !(m > 0.9 && m < 1.003) }' cmp.txt || fail "the brightest POV-Ray finish reflects $(grep mean: cmp.txt)"
# A layered texture (render/world.c shade_layers): a half-filtering white layer of diffuse 1 over
# a white one reflects 0.5 + 0.5 * 1 = 1 (within 0.3 %: both layers' picks carry weight 1); a clear
# layer with highlights over it asks for more and is capped at 1 (between 0.9 and 1.003).
cat >l.pov <<'EOS'
global_settings { radiosity { } }
camera { location <0, 0, -3> look_at <0, 0, 0> angle 40 }
background { color rgb 1 }
sphere { <0, 0, 0>, 1 texture { pigment { color rgb 1 } finish { diffuse 1 } }
  texture { pigment { color rgbf <1, 1, 1, 0.5> } finish { diffuse 1 } } }
EOS
expect_status 0 "$CIRCE" render l.pov -o l.exr -W 32 -H 32 --spp 1024 --quiet --region 10,10,22,22
expect_status 0 "$CIRCE" compare l.exr ref.exr --fail 0.003
sed -i 's|rgbf <1, 1, 1, 0.5> } finish { diffuse 1 }|rgbf 1 } finish { diffuse 1 phong 1 specular 1 reflection 0.5 }|' l.pov
expect_status 0 "$CIRCE" render l.pov -o lh.exr -W 32 -H 32 --spp 1024 --quiet --region 10,10,22,22
"$CIRCE" compare lh.exr ref.exr >cmp.txt 2>&1
awk '/^mean:/ { m = $3 } END { exit !(m > 0.9 && m < 1.003) }' cmp.txt || fail "the brightest layered texture reflects $(grep mean: cmp.txt)"
# The whole frame of albedo 1, silhouette included, at fewer samples: within 1 %.
sed -i 's/rgb 0.5/rgb 1/' f.pov
expect_status 0 "$CIRCE" render f.pov -o w.exr -W 32 -H 32 --spp 512 --quiet
"$MKEXR" one.exr 32 32 --const 1 || exit 99
expect_status 0 "$CIRCE" compare w.exr one.exr --fail 0.01
pass
