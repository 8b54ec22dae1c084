#!/bin/sh
# checkpoint.sh: with --checkpoint 1 a long render writes its image so far under the final name
# while it runs (atomically: always a whole EXR), with the samples done so far in the header; a
# --time budget stops the render after about that long.
. "$top_srcdir/tests/lib.sh"
scene="$top_srcdir/tests/farm/farm.pov"
work=$(mktemp -d) || exit 99
trap 'kill $pid 2>/dev/null; rm -rf "$work"' EXIT
cd "$work" || exit 99
"$CIRCE" render "$scene" -o out.exr -W 160 -H 120 --spp 1000000 --threads 2 --checkpoint 1 --quiet >log 2>&1 &
pid=$!
seen=0
for _ in $(seq 40); do
	sleep 0.25
	if [ -f out.exr ]; then
		seen=1
		break
	fi
done
[ $seen = 1 ] || fail "no checkpoint after 10 s: $(cat log)"
expect_status 0 "$CIRCE" compare out.exr out.exr
kill -INT $pid
wait $pid
status=$?
[ $status = 130 ] || fail "exit status $status after SIGINT, expected 130"
# A time budget: 2 s of rendering ends well before 20 s, with a whole image.
start=$(date +%s)
expect_status 0 "$CIRCE" render "$scene" -o timed.exr -W 64 -H 48 --time 2 --quiet
[ $(( $(date +%s) - start )) -lt 20 ] || fail "--time 2 took $(( $(date +%s) - start )) s"
expect_status 0 "$CIRCE" compare timed.exr timed.exr
pass
