#!/bin/sh
# bench/pov_survey.sh [CIRCE]: POV-Ray 3.7's sample scenes (Debian's povray-examples) through
# `circe check`, each from its own folder with -I at POV-Ray's include folder and the scene's
# folder, under a time limit (an animation at the first frame and clock of the .ini of its name). The first error of each scene is classified by its message and a
# markdown table printed: how many pass, what stops the rest. A crash (a signal) or a timeout is a
# defect of circe and is listed loudly at the end (and the exit status is 1), as is any sanitizer
# report when CIRCE is a build of --enable-sanitizers.
# Exit 77 when povray-examples is not installed. Run from the build folder (default ./circe).
# Environment: POV_INCLUDE (default /usr/share/povray-3.7/include), SURVEY_TIMEOUT (seconds per
# scene, default 10), SURVEY_TOP (rows of first stops, default 25), SURVEY_LOG (a file that
# receives each failing scene with its first error message).
set -u
circe=${1:-${CIRCE:-./circe}}
inc=${POV_INCLUDE:-/usr/share/povray-3.7/include}
limit=${SURVEY_TIMEOUT:-10}
top=${SURVEY_TOP:-25}
case $circe in /*) ;; *) circe=$(pwd)/$circe ;; esac
[ -x "$circe" ] || { echo "pov_survey: no circe at $circe" >&2; exit 2; }
scenes=$(dpkg -L povray-examples 2>/dev/null | grep '\.pov$' | sort)
if [ -z "$scenes" ] || [ ! -d "$inc" ]; then
	echo "pov_survey: skipped: povray-examples (and povray-includes at $inc) not installed" >&2
	exit 77
fi
work=$(mktemp -d "${TMPDIR:-/tmp}/pov-survey.XXXXXX") || exit 99
trap 'rm -rf "$work"' EXIT
# The scenes run in a copy of the examples' folder: some write files beside them (#fopen ...
# write: the portfolio's HTML pages), which must not touch the installed package.
root=$(printf '%s\n' "$scenes" | sed -n 's|^\(.*/examples\)/.*|\1|p' | head -n 1)
[ -n "$root" ] && cp -R "$root" "$work/examples" || { echo "pov_survey: cannot copy the examples" >&2; exit 99; }
: >"$work/stops"
: >"$work/defects"
total=0 pass=0
for s in $scenes; do
	total=$((total + 1))
	copy=$work/examples/${s#"$root"/}
	dir=$(dirname "$copy")
	# An animation's .ini of the scene's name (the portfolio's, animations/): its first frame and
	# clock, as POV-Ray renders it with that .ini (frame_number 0 indexes the portfolio's arrays at -1).
	anim=
	ini=${s%.pov}.ini
	if [ -f "$ini" ]; then
		f=$(tr -d '\r' <"$ini" | sed -n -E 's/^[[:space:]]*[Ii]nitial_[Ff]rame[[:space:]]*=[[:space:]]*([0-9]+)[[:space:]]*(;.*)?$/\1/p' | tail -n 1)
		c=$(tr -d '\r' <"$ini" | sed -n -E 's/^[[:space:]]*[Ii]nitial_[Cc]lock[[:space:]]*=[[:space:]]*(-?[0-9.]+)[[:space:]]*(;.*)?$/\1/p' | tail -n 1)
		[ -z "$f" ] || anim="--frame $f"
		[ -z "$c" ] || anim="$anim --clock $c"
	fi
	# shellcheck disable=SC2086 # $anim is options, split on purpose
	(cd "$dir" && exec timeout -k 2 "$limit" "$circe" check $anim -I "$inc" -I "$dir" "$copy") >/dev/null 2>"$work/err.copy"
	rc=$?
	sed "s|$work/examples|$root|g" "$work/err.copy" >"$work/err"
	# A circe built with --enable-sanitizers: any report is a defect, whatever the exit status.
	if grep -q -E 'ERROR: (Address|Leak)Sanitizer|runtime error: ' "$work/err"; then
		echo "DEFECT sanitizer report: $s" >>"$work/defects"
		echo "sanitizer report (defect)" >>"$work/stops"
		continue
	fi
	if [ "$rc" -eq 0 ]; then
		pass=$((pass + 1))
		continue
	fi
	if [ "$rc" -eq 124 ] || [ "$rc" -eq 137 ]; then
		echo "DEFECT timeout (over ${limit} s): $s" >>"$work/defects"
		echo "timeout (defect)" >>"$work/stops"
		continue
	fi
	if [ "$rc" -gt 128 ]; then
		echo "DEFECT crash (signal $((rc - 128))): $s" >>"$work/defects"
		echo "crash (defect)" >>"$work/stops"
		continue
	fi
	if [ "$rc" -ne 3 ] && [ "$rc" -ne 1 ]; then
		echo "DEFECT exit status $rc: $s" >>"$work/defects"
	fi
	# The first diagnostic header of an error; its message, grouped: the word of "not
	# supported", the name of an undeclared identifier, the shape of an "expected" message.
	msg=$(grep -m1 -E '^[^ ]*: error: |: error: ' "$work/err" | sed 's/^.*: error: //')
	[ -n "$msg" ] || msg="exit $rc without an error message (defect)"
	[ -z "${SURVEY_LOG:-}" ] || printf '%s: %s\n' "$s" "$msg" >>"$SURVEY_LOG"
	printf '%s\n' "$msg" | sed -E \
		-e "s/^('[^']*') is not supported by circe.*/not supported: \1/" -e t \
		-e "s/^undeclared identifier ('[^']*').*/undeclared identifier \1/" -e t \
		-e "s/^cannot find (include|font) file .*/a file not in povray-examples (include, font or image)/" -e t \
		-e "s/^image file .*: cannot open it: No such file or directory$/a file not in povray-examples (include, font or image)/" -e t \
		-e "s/identifier '[^']*'/identifier 'NAME'/g" \
		-e "s/string \"[^\"]*\"/string \"...\"/g" \
		-e "s/'-?[0-9][0-9.e+-]*'/'NUMBER'/g" \
		-e "s/line [0-9]+/line N/g" \
		-e "s/-?[0-9]+(\.[0-9]+)?(e[+-]?[0-9]+)?/N/g" >>"$work/stops"
done
fail=$((total - pass))
echo "| scenes | pass | stop at an error |"
echo "|---|---|---|"
echo "| $total | $pass | $fail |"
echo
echo "| first stop (top $top) | scenes |"
echo "|---|---|"
sort "$work/stops" | uniq -c | sort -k1,1nr -k2 | head -n "$top" |
	sed -E 's/^ *([0-9]+) (.*)$/| \2 | \1 |/; s/\|([^|]*)\| *([0-9]+) \|$/|\1| \2 |/'
kinds=$(sort -u "$work/stops" | wc -l)
[ "$kinds" -le "$top" ] || echo "| ($((kinds - top)) other kinds) | $(sort "$work/stops" | uniq -c | sort -k1,1nr | tail -n +$((top + 1)) | awk '{ n += $1 } END { print n }') |"
if [ -s "$work/defects" ]; then
	echo
	echo "**DEFECTS of circe (crash, timeout or unexpected exit status):**"
	sed 's/^/- /' "$work/defects"
	sed 's/^/pov_survey: /' "$work/defects" >&2
	exit 1
fi
exit 0
