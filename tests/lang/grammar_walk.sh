#!/bin/sh
# grammar_walk: every rule of grammar/scene.ebnf is named in a `// rule:` comment of
# tests/good/grammar_walk.pov, and that scene parses (its IR is compared by tests/lang/good_scenes.sh).
set -u
: "${CIRCE:?}" "${srcdir:?}"
ebnf="$srcdir/grammar/scene.ebnf"
walk="$srcdir/tests/good/grammar_walk.pov"
rules=$(sed -n 's/^\([a-z_][a-z0-9_]*\) *::=.*/\1/p' "$ebnf")
[ -n "$rules" ] || { echo "FAIL: no rules found in $ebnf"; exit 1; }
covered=$(sed -n 's|^// rule: ||p' "$walk" | tr ',' '\n' | tr -d ' ')
fail=0 n=0
for r in $rules; do
	n=$((n + 1))
	echo "$covered" | grep -qx "$r" || { echo "FAIL: rule '$r' has no example in grammar_walk.pov"; fail=1; }
done
for c in $covered; do
	echo "$rules" | grep -qx "$c" || { echo "FAIL: grammar_walk.pov names '$c', which scene.ebnf lacks"; fail=1; }
done
"$CIRCE" check --dump "$walk" >/dev/null || { echo "FAIL: grammar_walk.pov does not parse"; fail=1; }
echo "grammar rules: $n"
exit $fail
