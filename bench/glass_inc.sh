#!/bin/sh
# glass_inc.sh [CIRCE] [OUTDIR]: bench/glass_inc.pov (glass.inc's T_Glass1, Col_Glass_Ruby with
# F_Glass5 and I_Glass1, Col_Glass_Winebottle with F_Glass9 and I_Glass_Fade_Exp2) rendered by
# POV-Ray 3.7 with the real glass.inc and by circe with a copy of glass.inc and glass_old.inc whose
# finish items circe's glass branch lacks (ambient, reflection, conserve_energy, brilliance, phong)
# are removed; with NOSPEC=1 specular and roughness go too (circe's specular is a glossy lobe that
# reflects the whole scene, POV-Ray's a highlight of the lights only) and circe's lights are
# scaled by pi (POV-Ray's diffuse has no 1 / pi). Prints the normalised cross-correlation of the
# luminance images (sRGB linearised by ImageMagick); writes OUTDIR/side.png (circe left).
# Skips (exit 77) without povray or ImageMagick.
set -u
here=$(cd "$(dirname "$0")" && pwd)
circe=${1:-$here/../build/circe}
out=${2:-${TMPDIR:-/tmp}/glass_inc}
inc=/usr/share/povray-3.7/include
for t in povray convert compare python3; do
	command -v $t >/dev/null 2>&1 || { echo "glass_inc: no $t, skipped"; exit 77; }
done
mkdir -p "$out/inc" || exit 1
for f in glass glass_old; do
	python3 - "$inc/$f.inc" "$out/inc/$f.inc" "${NOSPEC:-0}" <<'PY' || exit 1
import re, sys
s = open(sys.argv[1]).read()
s = re.sub(r'reflection\s*\{[^}]*\}', '', s)
words = 'ambient|reflection|conserve_energy|brilliance|phong_size|phong'
if sys.argv[3] == '1':
    words += '|specular|roughness'
s = re.sub(r'\n\s*(' + words + r')\b[^\n]*', '', s)
open(sys.argv[2], 'w').write(s)
PY
done
scene=$out/scene.pov
if [ "${NOSPEC:-0}" = 1 ]; then
	sed 's/color rgb 1 }/color rgb 3.14159 }/; s/color rgb 0.5 }/color rgb 1.5708 }/' "$here/glass_inc.pov" >"$scene"
else
	cp "$here/glass_inc.pov" "$scene"
fi
"$circe" render "$scene" -I "$out/inc" -I $inc --png "$out/circe.png" -o "$out/circe.exr" -W 160 -H 120 \
	--spp ${SPP:-256} --quiet 2>"$out/circe.log" || { cat "$out/circe.log"; exit 1; }
povray +W160 +H120 -D +I"$here/glass_inc.pov" +O"$out/povray.png" +L$inc >"$out/povray.log" 2>&1 ||
	{ cat "$out/povray.log"; exit 1; }
for f in circe povray; do convert "$out/$f.png" -colorspace RGB -colorspace Gray "$out/$f.gray.png"; done
ncc=$(compare -metric NCC "$out/circe.gray.png" "$out/povray.gray.png" null: 2>&1)
convert "$out/circe.png" "$out/povray.png" +append "$out/side.png"
echo "glass.inc: ncc $ncc (NOSPEC=${NOSPEC:-0}); side by side: $out/side.png"
