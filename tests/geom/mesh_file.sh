#!/bin/sh
# mesh_file.sh: what `mesh { file }` does with suspect files, and subsurface scattering on
# coincident surfaces.
# - Exact duplicate triangles are removed at import with a warning giving the count: a cube whose
#   12 triangles are each written 1, 10 and 1000 times renders the same image in skin (circle
#   tracing counted every copy: 1000 copies were many times as bright).
# - Coincident surfaces that import cannot see (two objects of one SSS group in the same place)
#   count once in the circle estimator: the pair renders the image of one, within noise.
# - A truncated OBJ (its last line cut) imports with a warning; NaN or huge vertices are refused.
. "$top_srcdir/tests/lib.sh"
enter_workdir
# cube.obj with every face written $1 times (two triangles per side).
cube() {
	awk -v n="$1" 'BEGIN {
		for (i = 0; i < 8; i++) printf "v %d %d %d\n", i % 2, int(i / 2) % 2, int(i / 4)
		split("1 3 4 2 5 6 8 7 1 2 6 5 3 7 8 4 1 5 7 3 2 4 8 6", q, " ")
		for (c = 0; c < n; c++)
			for (f = 0; f < 6; f++) {
				a = q[4*f+1]; b = q[4*f+2]; d = q[4*f+3]; e = q[4*f+4]
				printf "f %d %d %d\nf %d %d %d\n", a, b, d, a, d, e
			}
	}'
}
scene() { # scene NAME OBJECTS: a skin scene holding OBJECTS, traced by circles
	cat >"$1.pov" <<EOS
global_settings { mm_per_unit 2 }
camera { location <2.2, 2.5, -3> look_at <0.5, 0.5, 0.5> angle 40 }
light_source { <-3, 5, -4> color rgb 1 intensity 40 }
sky_sphere { pigment { color rgb 0.1 } intensity 1 }
$2
EOS
}
for n in 1 10 1000; do
	cube $n >cube$n.obj
	scene dup$n "mesh { file \"cube$n.obj\" material { skin { method circle } } }"
	expect_status 0 "$CIRCE" render dup$n.pov -o dup$n.exr -W 32 -H 24 --spp 16 --seed 3 --quiet
	case $n in
	1) ! grep -q warning err || fail "one copy: a warning: $(cat err)" ;;
	*) want="cube$n.obj: warning: $((12 * n - 12)) of its $((12 * n)) triangles duplicate an earlier one"
	   grep -q "^$want" err || fail "$n copies: no warning '$want': $(cat err)" ;;
	esac
done
expect_status 0 "$CIRCE" render dup1.pov -o seed.exr -W 32 -H 24 --spp 16 --seed 4 --quiet
noise=$(seed_noise seed.exr dup1.exr)
for n in 10 1000; do
	expect_same_within_noise "$n copies" dup$n.exr dup1.exr "$noise" 4
done

# Two objects of one group in the same place against one of them.
obj='mesh { file "cube1.obj" material { skin { method circle group "g" } } }'
scene one "$obj"
scene two "$obj
$obj"
for s in one two; do
	expect_status 0 "$CIRCE" render $s.pov -o $s.exr -W 32 -H 24 --spp 64 --seed 5 --quiet
done
expect_status 0 "$CIRCE" render one.pov -o one6.exr -W 32 -H 24 --spp 64 --seed 6 --quiet
noise=$(seed_noise one6.exr one.exr)
expect_same_within_noise "two coincident objects" two.exr one.exr "$noise" 1.5

# A truncated OBJ: the warning, and what is there is rendered.
cube 1 | head -c 150 >cut.obj
scene cut 'mesh { file "cut.obj" }'
expect_status 0 "$CIRCE" check cut.pov
grep -q "^cut.obj: warning: the file's last line has no line end: a truncated file?" err ||
	fail "no truncation warning: $(cat err)"

# Vertices that are NaN, infinite or 1e38: refused (exit 3), with the count.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nv nan 0 0\nv 0 inf 0\nv 0 0 1e38\nf 1 2 3\nf 4 5 6\n' >bad.obj
scene bad 'mesh { file "bad.obj" }'
expect_status 3 "$CIRCE" check bad.pov
grep -q "^bad.obj: error: vertex coordinates must be finite and at most 1e+15 in magnitude.*: 3 of 6 vertices are not" err ||
	fail "no error for NaN, inf and 1e38: $(cat err)"
pass
