#!/bin/sh
# frames.sh: animation as POV-Ray does it — `clock` set by --clock moves the scene, --frame N puts
# the zero-padded frame number in place of the #### of the output name (or before the extension),
# and the EXR header records the clock.
. "$top_srcdir/tests/lib.sh"
scene="$top_srcdir/tests/farm/anim.pov"
enter_workdir
opts="-W 32 -H 24 --spp 4 --quiet"
# shellcheck disable=SC2086
expect_status 0 "$CIRCE" render "$scene" --clock 0 --frame 3 -o 'anim.####.exr' $opts
[ -f anim.0003.exr ] || fail "no anim.0003.exr: $(ls)"
# shellcheck disable=SC2086
expect_status 0 "$CIRCE" render "$scene" --clock 1 --frame 12 -o 'anim.##.exr' $opts
[ -f anim.12.exr ] || fail "no anim.12.exr: $(ls)"
# shellcheck disable=SC2086
expect_status 0 "$CIRCE" render "$scene" --clock 0 --frame 7 -o plain.exr $opts
[ -f plain.0007.exr ] || fail "no plain.0007.exr: $(ls)"
# clock moved the sphere: the two ends differ; the same clock gives the same image.
expect_status 1 "$CIRCE" compare anim.12.exr anim.0003.exr --fail 0.1
expect_status 0 "$CIRCE" compare plain.0007.exr anim.0003.exr --fail 0
if [ -n "$EXRHEADER" ]; then
	"$EXRHEADER" anim.12.exr | grep -q '^circe.clock (type double): 1$' || fail "clock attribute: $("$EXRHEADER" anim.12.exr)"
fi
pass
