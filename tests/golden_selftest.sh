#!/bin/sh
# golden_selftest.sh: the golden driver on EXRs this test writes itself — a match passes and
# cleans up, a difference over the threshold fails and keeps the image and its diff, a missing
# golden image or a failed render is a hard error.
. "$top_srcdir/tests/lib.sh"
work=$(mktemp -d) || exit 99
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/scenes" "$work/golden" "$work/build"
cat >"$work/scenes/pat.pov" <<'EOS'
// render: 16 8
// compare: --fail 0.01 --fail-percent 0
EOS
# The fake renderer: "SCENE -o OUT W H" -> mkexr OUT W H, plus $FAKE_EXTRA.
cat >"$work/fake" <<EOS
#!/bin/sh
[ "\$2" = -o ] || exit 2
exec "$top_builddir/tests/io/mkexr" "\$3" "\$4" "\$5" \$FAKE_EXTRA
EOS
chmod +x "$work/fake"
export GOLDEN_RENDER="$work/fake"
run() { top_builddir="$work/build" sh "$top_srcdir/tests/golden.sh" "$work/scenes/pat.pov" >"$work/log" 2>&1; }

run; [ $? = 99 ] || fail "missing golden is not a hard error: $(cat "$work/log")"
grep -q "no golden image" "$work/log" || fail "message: $(cat "$work/log")"
GOLDEN_UPDATE=1 run || fail "update-golden: $(cat "$work/log")"
[ -f "$work/golden/pat.exr" ] || fail "golden not written"
run || fail "identical render fails: $(cat "$work/log")"
[ ! -e "$work/build/tests/out/pat.exr" ] || fail "passing test left its image"
FAKE_EXTRA="--set 3,3,R,0.19" run || fail "difference under the threshold fails: $(cat "$work/log")"
FAKE_EXTRA="--set 3,3,R,0.9" run; [ $? = 1 ] || fail "difference over the threshold passes: $(cat "$work/log")"
[ -f "$work/build/tests/out/pat.exr" ] && [ -f "$work/build/tests/out/pat.diff.exr" ] || fail "failing test kept no images"
grep -q "max_abs: 0.7.* at 3,3 channel R" "$work/log" || fail "report: $(cat "$work/log")"
FAKE_EXTRA="--bogus" GOLDEN_RENDER=false run; [ $? = 99 ] || fail "failed render is not a hard error"
pass
