#!/bin/sh
# camera_pov.sh [OUTDIR]: every camera projection side by side with POV-Ray 3.7. One scene of
# self-lit spheres (POV-Ray: ambient 1 diffuse 0 with ambient_light 0... 1; circe: emission) of
# distinct greys around the camera, so a mirrored, shifted or stretched framing shows; each
# camera rendered 160x120 by both. Per camera: the correlation of linear luminance (POV-Ray's
# sRGB PNG linearised, circe's too), the IoU of the sphere masks (luminance > 0.05) and the
# offset of the masks' centroids in pixels; a contact sheet OUTDIR/sheet.png (POV-Ray left,
# circe right). Skips (exit 77) without povray or convert.
#   CIRCE (default build/circe), POVINC (default /usr/share/povray-3.7/include)
set -u
out=${1:-bench/out/camera_pov}
circe=${CIRCE:-build/circe}
inc=${POVINC:-/usr/share/povray-3.7/include}
command -v povray >/dev/null && command -v convert >/dev/null || { echo "SKIP: no povray or convert"; exit 77; }
mkdir -p "$out" || exit 1
W=${W:-160} H=${H:-120}
L='location <0.3, 0.4, -5> look_at <0, 0, 0>'
# name|camera body (the same text for both renderers)
cams="persp_default|$L
persp_angle_right|$L angle 60 right x*image_width/image_height
persp_mirror|$L right -x*4/3
persp_direction|location <0.3, 0.4, -5> direction <0, 0, 1.5>
persp_sky|$L sky <0.4, 1, 0>
persp_transform|location <0, 0, -5> look_at <0, 0, 0> rotate <10, 20, 0> translate <0.5, 0, 0>
ortho_default|orthographic $L
ortho_right_up|orthographic $L right 6*x up 4.5*y
ortho_angle|orthographic $L angle 40
ortho_scaled|orthographic $L right 6*x up 4.5*y scale 0.8
fisheye|fisheye $L angle 180
fisheye_square|fisheye $L angle 120 right x up y
ultra_wide_angle|ultra_wide_angle $L angle 150
panoramic|panoramic $L
cylinder_1|cylinder 1 $L angle 150
cylinder_2|cylinder 2 $L angle 120
cylinder_3|cylinder 3 $L angle 150
cylinder_4|cylinder 4 $L angle 120
spherical|spherical $L
spherical_angle|spherical $L angle 200, 120
focal_blur|$L aperture 0.4 focal_point <0, 0, 0> blur_samples 100"
spheres='<0, 0, 0>, 1, 1
<2.2, 0.8, 0.5>, 0.6, 0.6
<-1.8, -0.9, 1>, 0.5, 0.35
<0, 1.6, -1>, 0.35, 0.8
<5, 0, -5>, 1, 0.5
<-5, 1, -6>, 1, 0.7
<0, 0, -11>, 1.5, 0.9
<0, 5, -5>, 1, 0.4'
# write_scene BODY pov|circe: the spheres under camera { BODY }, each glowing its grey: in POV-Ray's
# words (ambient 1, diffuse 0, under ambient_light 1) or in circe's (an emission).
write_scene() {
	[ "$2" = pov ] && echo "global_settings { ambient_light 1 assumed_gamma 1 }"
	echo "camera { $1 }"
	echo "background { color rgb 0 }"
	echo "$spheres" | while IFS= read -r s; do
		g=${s##*, }; c=${s%, *}
		if [ "$2" = pov ]; then
			echo "sphere { $c pigment { rgb $g } finish { ambient 1 diffuse 0 } }"
		else
			echo "sphere { $c material { emission rgb $g } }"
		fi
	done
}
sheet=""
echo "camera                 r       IoU    centroid_offset_px"
echo "$cams" | while IFS='|' read -r name body; do
	pov="$out/$name.pov" cir="$out/$name.circe.pov"
	write_scene "$body" pov >"$pov"
	write_scene "$body" circe >"$cir"
	povray +W$W +H$H -D +A0.1 +I"$pov" +O"$out/$name.pov.png" +L"$inc" >/dev/null 2>&1 ||
		{ echo "$name: povray failed"; continue; }
	"$circe" render "$cir" -W $W -H $H --spp 64 --seed 1 --quiet -o "$out/$name.exr" --png "$out/$name.circe.png" ||
		{ echo "$name: circe failed"; continue; }
	convert "$out/$name.pov.png" -colorspace gray -depth 8 "$out/$name.a.pgm"
	convert "$out/$name.circe.png" -colorspace gray -depth 8 "$out/$name.b.pgm"
	python3 - "$name" "$out/$name.a.pgm" "$out/$name.b.pgm" <<'PY'
import sys
def load(p):
    d = open(p, 'rb').read()
    head, pos = [], 0
    while len(head) < 4:  # P5 W H MAX, comment lines skipped
        end = d.index(b'\n', pos)
        line = d[pos:end].split(b'#')[0].split()
        head += line
        pos = end + 1
    w, h = int(head[1]), int(head[2])
    px = d[pos:]
    lin = lambda v: (v / 255.0) / 12.92 if v <= 10 else ((v / 255.0 + 0.055) / 1.055) ** 2.4
    t = [lin(v) for v in range(256)]
    return w, h, [t[v] for v in px[:w * h]]
w, h, a = load(sys.argv[2]); _, _, b = load(sys.argv[3])
n = len(a); ma = sum(a) / n; mb = sum(b) / n
cov = sum((x - ma) * (y - mb) for x, y in zip(a, b))
va = sum((x - ma) ** 2 for x in a); vb = sum((y - mb) ** 2 for y in b)
r = cov / (va * vb) ** 0.5 if va > 0 and vb > 0 else float('nan')
A = [x > 0.05 for x in a]; B = [y > 0.05 for y in b]
inter = sum(1 for x, y in zip(A, B) if x and y); union = sum(1 for x, y in zip(A, B) if x or y)
def cen(M):
    s = sum(M) or 1
    return (sum(i % w for i, m in enumerate(M) if m) / s, sum(i // w for i, m in enumerate(M) if m) / s)
ca, cb = cen(A), cen(B)
off = ((ca[0] - cb[0]) ** 2 + (ca[1] - cb[1]) ** 2) ** 0.5
print("%-20s %7.4f %7.4f %8.2f" % (sys.argv[1], r, inter / union if union else float('nan'), off))
PY
done
ls "$out"/*.pov.png >/dev/null 2>&1 || exit 1
for f in "$out"/*.pov.png; do
	n=${f%.pov.png}
	convert "$f" "$n.circe.png" +append -bordercolor gray40 -border 1 "$n.pair.png"
done
montage_list=$(ls "$out"/*.pair.png)
# shellcheck disable=SC2086
convert $montage_list -append "$out/sheet.png" && echo "sheet: $out/sheet.png"
