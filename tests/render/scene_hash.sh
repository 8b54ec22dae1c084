#!/bin/sh
# shellcheck disable=SC2086 # $opts is a word list by design
# scene_hash.sh: the scene hash in a render's header (circe.scene_hash, which `circe merge`
# checks) covers every file the language read: tiles of one scene merge, and a tile rendered
# after an included file changed is refused as another scene's.
. "$top_srcdir/tests/lib.sh"
enter_workdir
printf 'camera { location <0, 0, -4> look_at 0 }\nlight_source { <2, 4, -3> color rgb 1 }\n#include "part.inc"\n' >scene.pov
printf 'sphere { 0, 1 }\n' >part.inc
opts="-W 16 -H 12 --spp 1 --quiet"
expect_status 0 "$CIRCE" render scene.pov -o t1.exr --tile 0/2 $opts
expect_status 0 "$CIRCE" render scene.pov -o t2.exr --tile 1/2 $opts
expect_status 0 "$CIRCE" merge -o whole.exr t1.exr t2.exr
# The same scene file, another include: another scene.
printf 'sphere { 0, 1.5 }\n' >part.inc
expect_status 0 "$CIRCE" render scene.pov -o t2b.exr --tile 1/2 $opts
expect_status 1 "$CIRCE" merge -o other.exr t1.exr t2b.exr
grep -q 'circe.scene_hash is "[0-9a-f]\{16\}" but t1.exr has "[0-9a-f]\{16\}"' err ||
	fail "a changed include is not another scene: $(cat err)"
[ ! -e other.exr ] || fail "a refused merge left other.exr"
pass
