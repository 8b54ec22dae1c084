#!/bin/sh
# good_scenes: every tests/good/*.pov parses (`circe check --dump`, -I tests/good/inc) to exactly the IR
# in its .dump golden file (and, where a NAME.stderr is, writes exactly that to stderr: #debug
# output, warnings), and a NAME_literal.pov twin to NAME's IR but for the locations.
# CIRCE_UPDATE_GOLDEN=1 rewrites the goldens (a developer's act: it writes into the source tree,
# so never in make check).
set -u
: "${CIRCE:?set CIRCE to the circe binary}" "${srcdir:?set srcdir to the source tree}"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/circe-good.XXXXXX") || exit 99
trap 'rm -rf "$tmp"' EXIT
cd "$srcdir/tests/good" || exit 99
n=0 fail=0
for pov in *.pov; do
	name=${pov%.pov}
	n=$((n + 1))
	if ! "$CIRCE" check --dump -I inc "$pov" >"$tmp/got" 2>"$tmp/err"; then
		echo "FAIL $pov: circe check failed"
		cat "$tmp/err"
		fail=$((fail + 1))
		continue
	fi
	if [ -e "$name.stderr" ] && [ "${CIRCE_UPDATE_GOLDEN:-0}" != 1 ] && ! cmp -s "$tmp/err" "$name.stderr"; then
		echo "FAIL $pov: its #debug output and warnings differ from $name.stderr (expected, then got):"
		diff "$name.stderr" "$tmp/err" | head -40
		fail=$((fail + 1))
	fi
	if [ "${CIRCE_UPDATE_GOLDEN:-0}" = 1 ]; then
		cp "$tmp/got" "$name.dump"
	elif ! cmp -s "$tmp/got" "$name.dump"; then
		echo "FAIL $pov: IR differs from $name.dump (expected, then got):"
		diff "$name.dump" "$tmp/got" | head -40
		fail=$((fail + 1))
	fi
done
# A NAME_literal.pov twin writes NAME.pov's declared values as literals: the same IR but for the
# source locations.
for lit in *_literal.pov; do
	[ -e "$lit" ] || continue
	name=${lit%_literal.pov}
	sed 's/@[^ ]*//g' "$name.dump" >"$tmp/declared"
	sed 's/@[^ ]*//g' "${lit%.pov}.dump" >"$tmp/literal"
	if ! cmp -s "$tmp/declared" "$tmp/literal"; then
		echo "FAIL $lit: its IR differs from $name.pov's beyond the source locations:"
		diff "$tmp/declared" "$tmp/literal" | head -20
		fail=$((fail + 1))
	fi
done
echo "good scenes: $n checked, $fail failed"
[ $n -gt 0 ] && [ $fail -eq 0 ]
