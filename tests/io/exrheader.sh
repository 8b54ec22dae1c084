#!/bin/sh
# exrheader.sh: OpenEXR's own exrheader lists the AOV channels and the attributes circe writes,
# and the data/display windows of a tile.
. "$top_srcdir/tests/lib.sh"
[ -n "$EXRHEADER" ] && [ -x "$EXRHEADER" ] || skip "exrheader not found (install the Debian package openexr)"
cd "$(mktemp -d)" || exit 99
trap 'rm -rf "$PWD"' EXIT
"$top_builddir/tests/io/mkexr" a.exr 12 6 --aov || fail "mkexr"
"$EXRHEADER" a.exr >h 2>&1 || fail "exrheader failed: $(cat h)"
for ch in A B G R Z albedo.R; do
	grep -q "^ *$ch, 32-bit floating-point" h || fail "channel $ch missing: $(cat h)"
done
grep -q 'software (type string): "circe mkexr"' h || fail "software attribute: $(cat h)"
grep -q 'spp (type int): 16' h || fail "spp attribute: $(cat h)"
grep -q 'compression (type compression): zip' h || fail "compression: $(cat h)"
pass
