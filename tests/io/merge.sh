#!/bin/sh
# merge.sh: `circe merge` assembles tiles bit-exactly into the whole frame, and refuses tiles from
# different renders, frames or channel sets, overlapping tiles and missing coverage (naming the
# missing rectangles).
. "$top_srcdir/tests/lib.sh"
MKEXR="$top_builddir/tests/io/mkexr"
cd "$(mktemp -d)" || exit 99
trap 'rm -rf "$PWD"' EXIT
same="--attr circe.scene_hash=abc --iattr circe.seed=1 --iattr circe.spp=8 --attr circe.sss=circle"
"$MKEXR" whole.exr 40 30 --aov $same || fail "mkexr"
# Four 20x15 quarters.
q=0
for r in 0,0,20,15 20,0,40,15 0,15,20,30 20,15,40,30; do
	"$MKEXR" t$q.exr 40 30 --aov --window $r $same --attr circe.tile=$q/4 || fail "mkexr"
	q=$((q + 1))
done
expect_status 0 "$CIRCE" merge -o m.exr t2.exr t0.exr t3.exr t1.exr
expect_status 0 "$CIRCE" compare m.exr whole.exr --fail 0
grep -qx 'max_abs: 0 at 0,0 channel A' out || fail "merged differs: $(cat out)"
cmp -s m.exr whole.exr || true # headers may differ (software); pixels are compared above

# Refusals, each with its message; none leaves an output file.
rm -f m.exr
"$MKEXR" seed.exr 40 30 --aov --window 0,0,20,15 --attr circe.scene_hash=abc --iattr circe.seed=2 \
	--iattr circe.spp=8 --attr circe.sss=circle || fail "mkexr"
expect_status 1 "$CIRCE" merge -o m.exr t0.exr t1.exr t2.exr seed.exr
grep -q '^seed.exr: error: circe.seed is 2 but t0.exr has 1: the tiles come from different renders$' err ||
	fail "seed: $(cat err)"
"$MKEXR" scene.exr 40 30 --aov --window 20,15,40,30 --attr circe.scene_hash=xyz --iattr circe.seed=1 \
	--iattr circe.spp=8 --attr circe.sss=circle || fail "mkexr"
expect_status 1 "$CIRCE" merge -o m.exr t0.exr scene.exr
grep -q 'circe.scene_hash is "xyz" but t0.exr has "abc"' err || fail "scene: $(cat err)"
"$MKEXR" spp.exr 40 30 --aov --window 20,15,40,30 --attr circe.scene_hash=abc --iattr circe.seed=1 \
	--iattr circe.spp=16 --attr circe.sss=circle || fail "mkexr"
expect_status 1 "$CIRCE" merge -o m.exr t0.exr spp.exr
grep -q 'circe.spp is 16 but t0.exr has 8' err || fail "spp: $(cat err)"
"$MKEXR" size.exr 40 31 --aov --window 20,15,40,30 $same || fail "mkexr"
expect_status 1 "$CIRCE" merge -o m.exr t0.exr size.exr
grep -q '^size.exr: error: frame 40x31 differs from t0.exr.s 40x30$' err || fail "size: $(cat err)"
"$MKEXR" chans.exr 40 30 --window 20,15,40,30 $same || fail "mkexr"
expect_status 1 "$CIRCE" merge -o m.exr t0.exr chans.exr
grep -q "^chans.exr: error: its channels differ from t0.exr's$" err || fail "channels: $(cat err)"
"$MKEXR" over.exr 40 30 --aov --window 10,10,30,20 $same || fail "mkexr"
expect_status 1 "$CIRCE" merge -o m.exr t0.exr t1.exr t2.exr t3.exr over.exr
grep -q '^over.exr: error: overlaps t0.exr at pixels x 10..19, y 10..14: each pixel must come from one tile$' err ||
	fail "overlap: $(cat err)"
expect_status 1 "$CIRCE" merge -o m.exr t0.exr t3.exr
grep -q '^merge: error: no tile covers pixels x 20..39, y 0..14 (20x15)$' err || fail "coverage 1: $(cat err)"
grep -q '^merge: error: no tile covers pixels x 0..19, y 15..29 (20x15)$' err || fail "coverage 2: $(cat err)"
expect_status 1 "$CIRCE" merge -o m.exr t0.exr missing.exr
grep -q '^missing.exr: error: cannot read EXR' err || fail "missing: $(cat err)"
[ ! -e m.exr ] || fail "a refused merge wrote m.exr"
expect_status 2 "$CIRCE" merge t0.exr
expect_status 2 "$CIRCE" merge -o m.exr
pass
