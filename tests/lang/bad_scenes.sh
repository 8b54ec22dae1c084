#!/bin/sh
# bad_scenes: every tests/bad/*.pov must make `circe check` exit 3 (never crash) with exactly the
# diagnostics of its .err sidecar: the header lines `file:line:col: error|note: message` (and
# `file: error: message` for a file that has no line to quote).
# With CIRCE_VALGRIND=1 (and $VALGRIND from configure) each case also runs under valgrind.
set -u
: "${CIRCE:?set CIRCE to the circe binary}" "${srcdir:?set srcdir to the source tree}"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/circe-bad.XXXXXX") || exit 99
trap 'rm -rf "$tmp"' EXIT
use_vg=0
if [ "${CIRCE_VALGRIND:-0}" = 1 ]; then
	[ -n "${VALGRIND:-}" ] || { echo "SKIP: CIRCE_VALGRIND=1 but valgrind was not found"; exit 77; }
	use_vg=1
fi
cd "$srcdir/tests/bad" || exit 99
n=0 fail=0
for pov in *.pov; do
	name=${pov%.pov}
	n=$((n + 1))
	if [ $use_vg = 1 ]; then
		$VALGRIND -q --error-exitcode=99 --leak-check=full --errors-for-leak-kinds=definite,indirect \
			"$CIRCE" check "$pov" >"$tmp/out" 2>"$tmp/err"
	else
		"$CIRCE" check "$pov" >"$tmp/out" 2>"$tmp/err"
	fi
	rc=$?
	grep -E '^[^ :]+:([0-9]+:[0-9]+:)? (error|note): |^circe: (error|note): ' "$tmp/err" >"$tmp/got"
	if [ $rc -ne 3 ]; then
		echo "FAIL $pov: exit status $rc, expected 3"
		head -20 "$tmp/err"
		fail=$((fail + 1))
	elif ! cmp -s "$tmp/got" "$name.err"; then
		echo "FAIL $pov: diagnostics differ (expected, then got):"
		diff "$name.err" "$tmp/got"
		fail=$((fail + 1))
	fi
done
echo "bad scenes: $n checked, $fail failed$([ $use_vg = 1 ] && echo ' (under valgrind)')"
[ $n -ge 60 ] || { echo "FAIL: only $n bad scenes (at least 60 expected)"; exit 1; }
[ $fail -eq 0 ]
