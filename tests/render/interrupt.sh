#!/bin/sh
# interrupt.sh: SIGINT mid-render finishes nothing new, writes a valid EXR of the samples completed
# so far with their count in the header, exits 130, and leaves no temporary file; SIGTERM too.
. "$top_srcdir/tests/lib.sh"
scene="$top_srcdir/tests/farm/farm.pov"
enter_workdir
"$CIRCE" render "$scene" -o probe.exr -W 8 -H 8 --spp 1 --quiet >log 2>&1 ||
	{ grep -q "which this build lacks" log && skip "circe render is not in this build yet"; fail "render: $(cat log)"; }
rm -f probe.exr
for sig in INT TERM; do
	"$CIRCE" render "$scene" -o out.exr -W 160 -H 120 --spp 1000000 --threads 2 --checkpoint 1000 >log 2>&1 &
	pid=$!
	sleep 3
	kill -"$sig" $pid
	wait $pid
	status=$?
	[ $status = 130 ] || fail "SIG$sig: exit status $status, expected 130: $(cat log)"
	[ -f out.exr ] || fail "SIG$sig: no image written"
	expect_status 0 "$CIRCE" compare out.exr out.exr
	"$EXRHEADER" out.exr >h 2>&1 || true
	if [ -n "$EXRHEADER" ]; then
		spp=$(sed -n 's/^circe.spp (type int): //p' h)
		[ -n "$spp" ] && [ "$spp" -ge 1 ] && [ "$spp" -lt 1000000 ] || fail "SIG$sig: circe.spp '$spp': $(cat h)"
		grep -q '^circe.interrupted (type int): 1' h || fail "SIG$sig: not marked interrupted: $(cat h)"
	fi
	[ "$(ls -A | grep -v -e '^out.exr$' -e '^log$' -e '^out$' -e '^err$' -e '^h$')" = "" ] ||
		fail "SIG$sig: files left behind: $(ls -A)"
	rm -f out.exr
done
pass
