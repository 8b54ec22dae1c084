#!/bin/sh
# golden.sh SCENE.pov: the golden-image driver. Renders the scene with the options on its
# `// render:` line, compares the result with tests/golden/NAME.exr through `circe compare` with
# the thresholds on its `// compare:` line, and keeps the image and the difference image under
# tests/out/ on failure. Exit: 0 pass, 1 fail, 99 hard error (no golden image, render failed).
#   GOLDEN_RENDER   command used instead of "$CIRCE render" (the driver's own self-test)
#   GOLDEN_UPDATE=1 write the rendered image as the new golden (make update-golden)
scene=$1
[ -f "$scene" ] || { echo "golden.sh: error: no scene '$scene'" >&2; exit 99; }
name=$(basename "$scene" .pov)
scenedir=$(cd "$(dirname "$scene")" && pwd)
golden="$scenedir/../golden/$name.exr"
outdir="${top_builddir:-.}/tests/out"
mkdir -p "$outdir" || exit 99
out="$outdir/$name.exr"
diff="$outdir/$name.diff.exr"
render_opts=$(sed -n 's|^// render:||p' "$scene" | head -n 1)
compare_opts=$(sed -n 's|^// compare:||p' "$scene" | head -n 1)
[ -n "$compare_opts" ] || { echo "golden.sh: error: $scene has no '// compare:' line" >&2; exit 99; }
rm -f "$out" "$diff"
# shellcheck disable=SC2086 # the option lines are word lists by design
if [ -n "$GOLDEN_RENDER" ]; then
	$GOLDEN_RENDER "$scene" -o "$out" $render_opts
else
	"$CIRCE" render "$scene" -o "$out" --quiet $render_opts
fi
status=$?
[ $status = 0 ] && [ -f "$out" ] || { echo "golden.sh: error: rendering $scene failed (exit $status)" >&2; exit 99; }
if [ "$GOLDEN_UPDATE" = 1 ]; then
	cp "$out" "$golden" && echo "golden.sh: updated $golden" && exit 0
	exit 99
fi
[ -f "$golden" ] || { echo "golden.sh: error: no golden image $golden (run 'make update-golden' and review it)" >&2; exit 99; }
# shellcheck disable=SC2086
"$CIRCE" compare "$out" "$golden" --diff "$diff" $compare_opts
status=$?
case $status in
0) rm -f "$out" "$diff"; exit 0 ;;
1) echo "golden.sh: $name differs from its golden image; kept $out and $diff" >&2; exit 1 ;;
*) exit 99 ;;
esac
