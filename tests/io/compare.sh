#!/bin/sh
# compare.sh: `circe compare` gives 0 for identical images, finds one changed pixel with its value
# and position, lets --fail/--fail-percent decide the exit status, counts NaN, writes --diff,
# restricts itself to --channels, and reports size mismatches, unreadable files and bad options
# clearly.
. "$top_srcdir/tests/lib.sh"
MKEXR="$top_builddir/tests/io/mkexr"
cd "$(mktemp -d)" || exit 99
trap 'rm -rf "$PWD"' EXIT

"$MKEXR" a.exr 16 8 && cp a.exr b.exr || fail "mkexr"
expect_status 0 "$CIRCE" compare a.exr b.exr
grep -qx 'rmse: 0' out || fail "identical images: rmse not 0: $(cat out)"
grep -qx 'max_abs: 0 at 0,0 channel A' out || fail "identical images: $(cat out)"
grep -qx 'result: PASS' out || fail "identical images do not pass"

# One pixel changed: G at (5,3) from 3/8 to 0.875 (an error of exactly 0.5).
"$MKEXR" c.exr 16 8 --set 5,3,G,0.875 || fail "mkexr"
expect_status 1 "$CIRCE" compare c.exr a.exr
grep -qx 'max_abs: 0.5 at 5,3 channel G' out || fail "changed pixel not found: $(cat out)"
grep -q '^over_threshold: 0.78125% (1 pixels with error > 1e-06; allowed 0%)$' out || fail "over: $(cat out)"
grep -qx 'result: FAIL' out || fail "changed pixel does not fail"
expect_status 0 "$CIRCE" compare c.exr a.exr --fail 0.6
expect_status 0 "$CIRCE" compare c.exr a.exr --fail 0.1 --fail-percent 1
expect_status 1 "$CIRCE" compare c.exr a.exr --fail 0.1 --fail-percent 0.5
# rmse over 16*8*4 values with one error of 0.5
grep -qx 'rmse: 0.0220970869' out || fail "rmse: $(cat out)"

# --channels restricts every figure to the channels named (each must be in both images).
expect_status 0 "$CIRCE" compare c.exr a.exr --channels R,B
grep -qx 'channels: 2' out || fail "--channels R,B: $(cat out)"
grep -qx 'rmse: 0' out || fail "--channels R,B sees the G error: $(cat out)"
expect_status 1 "$CIRCE" compare c.exr a.exr --channels G
grep -qx 'rmse: 0.0441941738' out || fail "--channels G: rmse over 16*8 values: $(cat out)"
# mean: c.exr's G plane is a.exr's (mean 0.4375) plus 0.5 at one pixel of 128.
grep -qx 'mean: a 0.44140625 b 0.4375' out || fail "--channels G: means: $(cat out)"
expect_status 1 "$CIRCE" compare c.exr a.exr --channels R,G,G
grep -qx 'channels: 2' out || fail "--channels R,G,G counts G twice: $(cat out)"
expect_status 1 "$CIRCE" compare c.exr a.exr --channels R,Z
grep -q "^a.exr: error: no channel 'Z' (asked by --channels)$" err || fail "unknown channel: $(cat err)"
expect_status 2 "$CIRCE" compare c.exr a.exr --channels R,,G
grep -q "channels needs a list" err || fail "bad --channels list: $(cat err)"
expect_status 2 "$CIRCE" compare c.exr a.exr --channels ''

# --diff writes |A - B|, found again against a black image.
expect_status 1 "$CIRCE" compare c.exr a.exr --diff d.exr
"$MKEXR" zero.exr 16 8 --const 0 || fail "mkexr"
expect_status 1 "$CIRCE" compare d.exr zero.exr
grep -qx 'max_abs: 0.5 at 5,3 channel G' out || fail "diff image: $(cat out)"

# NaN and Inf in A are counted and always fail.
"$MKEXR" n.exr 16 8 --set 1,1,R,nan --set 2,2,B,inf || fail "mkexr"
expect_status 1 "$CIRCE" compare n.exr a.exr --fail 10
grep -qx 'nonfinite_a: nan 1 inf 1' out || fail "non-finite counts: $(cat out)"

# Errors.
"$MKEXR" small.exr 8 8 || fail "mkexr"
expect_status 1 "$CIRCE" compare small.exr a.exr
grep -q "small.exr: error: size 8x8 .* differs from a.exr: 16x8" err || fail "size mismatch message: $(cat err)"
expect_status 1 "$CIRCE" compare missing.exr a.exr
grep -q "^missing.exr: error: cannot read EXR" err || fail "missing file message: $(cat err)"
expect_status 2 "$CIRCE" compare a.exr b.exr --fail abc
grep -q "fail needs a number" err || fail "bad option message: $(cat err)"
expect_status 2 "$CIRCE" compare a.exr
expect_status 2 "$CIRCE" compare a.exr b.exr --fail-percent 101
pass
