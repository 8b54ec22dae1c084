#!/bin/sh
# trace_reuse.sh: a POV-Ray shape that trace() tessellated for its world (build_trace.c) is
# copied into the render's world when the render asks the same accuracy of it (world_options.
# reuse), not tessellated again (isocacti's 2.5 M-triangle ground was made twice). The render with
# the trace is bit for bit the render without it; an object placed nearer the camera than the one
# traced asks a finer mesh and is tessellated anew; check says how many shapes were copied.
. "$top_srcdir/tests/lib.sh"
enter_workdir
scene() { # $1 name, $2 the trace statement (or nothing), $3 the object's placement
	cat >"$1.pov" <<EOS
#include "functions.inc"
global_settings { assumed_gamma 1 }
camera { location <0, 1, -5> look_at 0 angle 40 }
light_source { <-5, 8, -6> color rgb 1 }
#declare Rock = isosurface {
  function { f_r(x, y, z) - 1 + f_noise3d(2 * x, 2 * y, 2 * z) * 0.4 }
  threshold 0 max_gradient 3 contained_by { sphere { 0, 1.5 } }
  pigment { rgb <0.8, 0.6, 0.4> } finish { specular 0.3 } }
$2
object { Rock $3 }
EOS
}
INC="-I /usr/share/povray-3.7/include"
[ -f /usr/share/povray-3.7/include/functions.inc ] || INC=""
scene traced '#declare Pt = trace(Rock, <0, 5, 0>, -y);
#if (Pt.y < 0.3) #error "trace missed the rock" #end' ''
scene plain '' ''
scene near '#declare Pt = trace(Rock, <0, 5, 0>, -y);' 'translate <0, 0, -2>'
[ -n "$INC" ] || skip "no POV-Ray include folder (functions.inc)"
for s in traced plain near; do
	expect_status 0 "$CIRCE" check "$s.pov" $INC
	cp out "$s.check"
done
grep -q "shapes copied from trace()'s worlds: 1 " traced.check || fail "the traced isosurface was not copied: $(cat traced.check)"
grep -q "copied from trace" plain.check && fail "no trace, yet a shape copied: $(cat plain.check)"
grep -q "copied from trace" near.check && fail "placed nearer than traced (a finer mesh asked), yet copied: $(cat near.check)"
t1=$(grep "isosurface at" traced.check | sed 's/ at [^:]*:/ at /') t2=$(grep "isosurface at" plain.check | sed 's/ at [^:]*:/ at /')
[ -n "$t1" ] && [ "$t1" = "$t2" ] || fail "the copied mesh is not the one made: '$t1' against '$t2'"
# At trace's own image size (640 x 480, build.h WORLD_TRACE_WIDTH), where the render asks the
# accuracy the trace's world made; a window over the rock.
for s in traced plain; do
	expect_status 0 "$CIRCE" render "$s.pov" $INC -o "$s.exr" -W 640 -H 480 --region 280,180,360,260 --spp 2
	cp err "$s.render"
done
grep -q "1 shapes copied from trace" traced.render || fail "the render did not copy the traced rock: $(cat traced.render)"
grep -q "copied from trace" plain.render && fail "the render without a trace copied a shape: $(cat plain.render)"
expect_status 0 "$CIRCE" compare traced.exr plain.exr --fail 0
pass
