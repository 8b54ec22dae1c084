#!/bin/sh
# interrupt.sh: SIGINT mid-render finishes nothing new, writes a valid EXR of the samples completed
# so far with their count in the header, exits 130, and leaves no temporary file; SIGTERM too.
# Interrupted before the first pass is done (in start-up, during the first pass, by two signals at
# once): circe exits 130 itself, says so, and writes nothing: an older image stays as it was.
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

# Before the first pass: the good older image must survive. The first pass at this size takes
# seconds (one thread); each signal comes well before it ends.
"$CIRCE" render "$scene" -o old.exr -W 8 -H 8 --spp 1 --quiet >log 2>&1 || fail "render: $(cat log)"
cp old.exr keep.exr
# A scene whose parse takes a second or two: a signal at 0.1 s comes while it is read.
printf '%s\n' '#declare J = 0;' '#while (J < 30)' '#declare I = 0;' '#while (I < 100000)' \
	'#declare I = I + 1;' '#end' '#declare J = J + 1;' '#end' 'sphere { 0, 1 }' >slow.pov
for when in start-up first-pass twice; do
	s=$scene
	[ $when = start-up ] && s=slow.pov
	"$CIRCE" render "$s" -o old.exr --png old.png -W 1500 -H 1500 --spp 4 --threads 1 --quiet >log 2>&1 &
	pid=$!
	case $when in
	start-up) sleep 0.1; kill -INT $pid ;;
	first-pass) sleep 0.5; kill -INT $pid ;;
	twice) sleep 0.3; kill -INT $pid; kill -INT $pid ;;
	esac
	wait $pid
	status=$?
	# 130 is also what the shell reports for a death by SIGINT: the message tells them apart.
	[ $status = 130 ] && grep -q "^circe: interrupted before any pass was done: nothing written" log ||
		fail "SIGINT ($when): exit status $status, expected 130 with a message: $(cat log)"
	cmp -s old.exr keep.exr || fail "SIGINT ($when): the older image was replaced"
	[ ! -e old.png ] || fail "SIGINT ($when): a PNG was written"
	[ "$(ls -A | grep '\.tmp$')" = "" ] || fail "SIGINT ($when): files left behind: $(ls -A)"
done
pass
