#!/bin/sh
# pov_lights.sh [CIRCE] [OUTDIR]: tests/scenes/pov_lights.pov (POV-Ray's lights without circe's
# intensity) rendered by circe and by POV-Ray 3.7 at 160x120, side by side. Prints each image's
# mean linear value (POV-Ray's sRGB PNG and circe's sRGB preview both linearised by ImageMagick),
# their ratio (1 by design: circe scales a POV-Ray light by pi, src/build/build_light.c, so that
# its Lambert albedo / pi shows POV-Ray's pigment * diffuse * C), and the normalised
# cross-correlation of the two luminance images. The scene sets ambient_light 0 (POV-Ray's
# implicit ambient 0.1 is what circe's global illumination replaces). Writes OUTDIR/side.png
# (circe on the left, POV-Ray on the right). Skips (exit 77) without povray or ImageMagick.
set -u
here=$(cd "$(dirname "$0")" && pwd)
circe=${1:-$here/../build/circe}
out=${2:-${TMPDIR:-/tmp}/pov_lights}
inc=/usr/share/povray-3.7/include
for t in povray convert compare; do
	command -v $t >/dev/null 2>&1 || { echo "pov_lights: no $t, skipped"; exit 77; }
done
mkdir -p "$out" || exit 1
scene=$here/../tests/scenes/pov_lights.pov
"$circe" render "$scene" -o "$out/circe.exr" --png "$out/circe.png" -W 160 -H 120 --spp 256 --quiet 2>/dev/null || exit 1
povray +W160 +H120 -D +I"$scene" +O"$out/povray.png" +L$inc >"$out/povray.log" 2>&1 || { cat "$out/povray.log"; exit 1; }
mean() { convert "$1" -colorspace RGB -format '%[fx:mean]' info:; }
c=$(mean "$out/circe.png") p=$(mean "$out/povray.png")
for f in circe povray; do convert "$out/$f.png" -colorspace RGB -colorspace Gray "$out/$f.gray.png"; done
ncc=$(compare -metric NCC "$out/circe.gray.png" "$out/povray.gray.png" null: 2>&1)
convert "$out/circe.png" "$out/povray.png" +append "$out/side.png"
awk -v c="$c" -v p="$p" -v r="$ncc" 'BEGIN { printf "mean linear: circe %.4f  povray %.4f  ratio %.4f  ncc %.4f\n", c, p, c / p, r }'
echo "side by side: $out/side.png"
