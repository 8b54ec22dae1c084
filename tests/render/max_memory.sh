#!/bin/sh
# max_memory.sh: spheres share their tessellation (10^4 small spheres cost a few unit spheres and
# their instances), and --max-memory bounds what circe allocates: check estimates a render's
# memory and fails over the limit, a render refuses what would pass it before allocating, and
# both say which limit it was (exit 3 while parsing or building the scene, 1 for the film), with
# no output left behind.
. "$top_srcdir/tests/lib.sh"
enter_workdir
cat >many.pov <<'EOS'
camera { location <0, 0, -30> look_at <0, 0, 0> }
light_source { <10, 20, -30> color rgb 1500 }
#declare I = 0;
#while (I < 10000)
  sphere { <mod(I, 100) * 0.2 - 10, floor(I / 100) * 0.2 - 10, 0>, 0.08 }
  #declare I = I + 1;
#end
EOS
expect_status 0 "$CIRCE" check many.pov --max-memory 200M
tri=$(sed -n 's/.*triangles after tessellation: \([0-9]*\) unique.*/\1/p' out)
mib=$(sed -n 's/.*estimated render memory at 640x480: \([0-9.]*\) MiB.*/\1/p' out)
[ -n "$tri" ] && [ "$tri" -le 20000 ] || fail "10^4 spheres: $tri unique triangles: $(cat out)"
awk -v m="$mib" 'BEGIN { exit !(m != "" && m < 100) }' || fail "10^4 spheres: estimated $mib MiB: $(cat out)"
# The estimate (the film's 61 MiB at 640x480 included) is over 40M: check fails.
expect_status 3 "$CIRCE" check many.pov --max-memory 40M
grep -q "over the memory limit of 40.0 MiB (--max-memory)" err || fail "check's message: $(cat err)"
# The render builds the scene within 40M, and the film would pass it.
expect_status 1 "$CIRCE" render many.pov -o a.exr --max-memory 40M
grep -q "out of memory for a 640x480 film" err && grep -q "memory limit of 40.0 MiB (--max-memory)" err ||
	fail "render's message: $(cat err)"
# Too small for the scene itself: a scene error, where it was found.
expect_status 3 "$CIRCE" render many.pov -o a.exr --max-memory 4M
grep -q "error: out of memory" err && grep -q "memory limit of 4.0 MiB (--max-memory)" err ||
	fail "render's message at 4M: $(cat err)"
expect_status 3 "$CIRCE" check many.pov --max-memory 4M
grep -q "memory limit of 4.0 MiB (--max-memory)" err || fail "check's message at 4M: $(cat err)"
[ -e a.exr ] && fail "a refused render left a.exr"
expect_status 2 "$CIRCE" check many.pov --max-memory 2T
# A cube subdivided 8 times (786,432 triangles, about 66 MiB) under --max-memory 50M: refused
# by its estimate, before tessellating, in check as in render.
cat >cube.pov <<'EOS'
subdivision_surface {
  vertex_vectors { 8, <-0.5,-0.5,0.5>, <0.5,-0.5,0.5>, <-0.5,0.5,0.5>, <0.5,0.5,0.5>,
                      <-0.5,0.5,-0.5>, <0.5,0.5,-0.5>, <-0.5,-0.5,-0.5>, <0.5,-0.5,-0.5> }
  faces { 6, <0,1,3,2>, <2,3,5,4>, <4,5,7,6>, <6,7,1,0>, <1,7,5,3>, <6,0,2,4> }
  level 8
}
EOS
for cmd in check render; do
	expect_status 3 "$CIRCE" $cmd cube.pov --max-memory 50M
	grep -q "cube.pov:1:1: error: .*over the limit of 50.0 MiB" err || fail "$cmd cube.pov: $(cat err)"
done
[ -e cube.exr ] && fail "a refused render left cube.exr"
pass
