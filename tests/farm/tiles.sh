#!/bin/sh
# tiles.sh: a frame rendered as 2, 4 and 7 tiles, with 1 and 2 threads per tile, then merged, is
# bit-identical to the frame rendered whole in one process.
. "$top_srcdir/tests/lib.sh"
scene="$top_srcdir/tests/farm/farm.pov"
enter_workdir
opts="-W 48 -H 36 --spp 4 --seed 11 --quiet"
# shellcheck disable=SC2086
"$CIRCE" render "$scene" -o whole.exr --threads 2 $opts >log 2>&1 ||
	{ grep -q "which this build lacks" log && skip "circe render is not in this build yet"; fail "whole render: $(cat log)"; }
for n in 2 4 7; do
	for t in 1 2; do
		tiles=""
		i=0
		while [ $i -lt $n ]; do
			# shellcheck disable=SC2086
			expect_status 0 "$CIRCE" render "$scene" --tile $i/$n -o tile-$i.exr --threads $t $opts
			tiles="$tiles tile-$i.exr"
			i=$((i + 1))
		done
		# shellcheck disable=SC2086
		expect_status 0 "$CIRCE" merge -o merged.exr $tiles
		expect_status 0 "$CIRCE" compare merged.exr whole.exr --fail 0
		grep -qx 'max_abs: 0 at 0,0 channel A' out || grep -q '^max_abs: 0 at' out ||
			fail "$n tiles, $t threads: merged differs from whole: $(cat out)"
		rm -f tile-*.exr merged.exr
	done
done
pass
