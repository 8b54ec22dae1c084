#!/bin/sh
# cli_help.sh: `circe SUBCOMMAND --help` prints the usage and then the subcommand's options from
# the table they are parsed by (main.c), so every option of the usage's synopsis is listed with
# a line of help, and --help and -h exit 0 for each subcommand.
. "$top_srcdir/tests/lib.sh"
cd "$(mktemp -d)" || exit 99
trap 'rm -rf "$PWD"' EXIT
for sub in render check compare merge; do
	for h in --help -h; do
		expect_status 0 "$CIRCE" $sub $h
		head -n 1 out | grep -q '^usage: circe render SCENE' || fail "$sub $h: no usage: $(head -n 1 out)"
		grep -qx "$sub options:" out || fail "$sub $h: no '$sub options:' list"
	done
	# The options of the subcommand's synopsis lines, each listed with a help text.
	opts=$(sed -n '/^$/q;p' out | awk -v s="circe $sub " 'index($0, s) { on = 1 } on && index($0, "circe ") && !index($0, s) { on = 0 } on' |
		grep -oE -- '(--[a-z-]+|-[A-Za-z])( |\]|$)' | sed 's/[] ]$//' | sort -u)
	[ -n "$opts" ] || fail "$sub: no options found in the usage"
	for o in $opts; do
		sed -n "/^$sub options:/,\$p" out | grep -Eq -- "^  (-[A-Za-z], )?$o( [^ ]+)? +[a-z]" ||
			fail "$sub --help does not list $o"
	done
	echo "$sub: $(echo $opts | wc -w) options of the usage listed"
done
echo PASS
