#!/bin/sh
# texture_limit.sh: a texture's size is checked from its header before it is decoded. PNG, JPEG
# and EXR headers claiming 30000 x 30000 pixels (13733 MiB as float RGBA; a few hundred bytes
# each, made by mkbigimage) are refused at once under --max-memory 512M, and 60000 x 60000 (54932
# MiB) under the default limit, the machine's memory (24 GiB); a texture takes what the limit
# leaves after what is already allocated. They used to be allocated and decoded (13.5 GB, 16 GB for the JPEG, still loading after
# 60 s; the test runs under a 4 GB address-space limit where the build allows, so the old
# behaviour fails fast). A progressive JPEG's coefficient buffer counts too. A JPEG cut in half
# loads with a warning (libjpeg fills the rest with grey), as does one within the limit whose data
# stops early.
. "$top_srcdir/tests/lib.sh"
enter_workdir
# A 4 GB address-space limit, unless the build cannot run under one (ASan reserves terabytes).
if (ulimit -v 4000000 && "$top_builddir/tests/io/mkbigimage" . 16 16) >/dev/null 2>&1; then
	ulimit -v 4000000
fi
scene() { # scene NAME IMAGE
	cat >"$1.pov" <<EOS
camera { location <0, 0, -4> look_at <0, 0, 0> }
light_source { <-3, 5, -4> color rgb 1 intensity 20 }
sphere { <0, 0, 0>, 1 material { diffuse { image "$2" } } }
EOS
}
render() { "$CIRCE" render "$1.pov" -o "$1.exr" -W 8 -H 8 --spp 1 --quiet "$@"; }
"$top_builddir/tests/io/mkbigimage" . || fail "mkbigimage"
for f in big.png big.jpg big.exr; do
	scene t "$f"
	for limit in "--max-memory 512M" ""; do
		size=30000 mib=13733
		if [ -z "$limit" ]; then
			size=60000 mib=54932
			"$top_builddir/tests/io/mkbigimage" . $size $size || fail "mkbigimage $size"
		fi
		start=$(date +%s)
		expect_status 3 "$CIRCE" render t.pov -o t.exr -W 8 -H 8 --spp 1 --quiet $limit
		grep -q "^$f: error: a ${size}x$size image takes $mib MiB as float RGBA, more than the [0-9]* MiB left under the memory limit" err ||
			fail "$f ${limit:-default limit}: not refused from its header: $(cat err)"
		[ -z "$limit" ] || grep -q "more than the 5[01][0-9] MiB left" err || fail "$f: the room left under 512M: $(cat err)"
		[ $(($(date +%s) - start)) -le 5 ] || fail "$f: the refusal took more than 5 s"
		[ ! -e t.exr ] || fail "$f: an image was written"
	done
	"$top_builddir/tests/io/mkbigimage" . || fail "mkbigimage"
done

# Within the limit (2000 x 2000: 61 MiB) but cut short: loaded, grey where data is missing, a warning.
"$top_builddir/tests/io/mkbigimage" . 2000 2000 || fail "mkbigimage 2000"
scene small big.jpg
expect_status 0 "$CIRCE" render small.pov -o small.exr -W 8 -H 8 --spp 1 --quiet --max-memory 512M
grep -q "^big.jpg: warning: the JPEG data is corrupt or cut short" err || fail "no warning for the cut JPEG: $(cat err)"

# A progressive JPEG is decoded through a whole-image buffer of coefficients too: 6000 x 6000 takes
# 549 MiB as floats and 206 MiB of coefficients, refused under 600M, loaded (cut short) under 1G.
"$top_builddir/tests/io/mkbigimage" . 6000 6000 progressive || fail "mkbigimage progressive"
expect_status 3 "$CIRCE" render small.pov -o small.exr -W 8 -H 8 --spp 1 --quiet --max-memory 600M
grep -q "^big.jpg: error: a progressive 6000x6000 JPEG needs its coefficients in memory too, more than the [56][0-9][0-9] MiB left under the memory limit" err ||
	fail "progressive JPEG over the limit: $(cat err)"
expect_status 0 "$CIRCE" render small.pov -o small.exr -W 8 -H 8 --spp 1 --quiet --max-memory 1G

# A real JPEG cut in half.
src="$top_srcdir/scenes/assets/lee_perry_smith_head/Map-COL.jpg"
head -c $(($(wc -c <"$src") / 2)) "$src" >half.jpg
scene half half.jpg
expect_status 0 "$CIRCE" render half.pov -o half.exr -W 8 -H 8 --spp 1 --quiet
grep -q "^half.jpg: warning: the JPEG data is corrupt or cut short (.* the first: Premature end of JPEG file)" err ||
	fail "no warning for the JPEG cut in half: $(cat err)"
pass
