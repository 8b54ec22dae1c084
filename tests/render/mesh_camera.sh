#!/bin/sh
# mesh_camera.sh: POV-Ray's mesh_camera distribution types 1 and 3 through the whole render, the
# scenes of glow alone (ambient 1, no light: flat colours, so only the rays count).
# 1. Type 3 on a flat quad whose uv cover [0,1]^2 is the orthographic camera of the same screen:
#    pixel point (x, y) is uv (x / w, 1 - y / h), the point of the quad there, the quad's normal
#    (the same image within 1e-3 but at a few edge samples; a mirrored orthographic camera, the
#    control, differs).
# 2. Type 1 summing two meshes (the upper and lower rows of a grid of a face per pixel) is type
#    0 with the whole grid as one mesh: the same rays, the same image.
# 3. Type 1 with 2 rays per pixel from one list of 1.5 * width * height faces, the first
#    width * height facing a red wall, the rest a blue one: ray 1 of pixel i is face
#    w * h + i, so the upper half of the pixels average red and blue, the lower half have one
#    ray (red): means R 0.75, B 0.25 (POV-Ray 3.7's code, which never shoots ray 1, would give
#    R 1, B 0).
# 4. max_distance: below.
. "$top_srcdir/tests/lib.sh"
enter_workdir
world='background { rgb <0.1, 0.2, 0.4> }
plane { z, 4 pigment { checker rgb 0.9, rgb 0.1 scale 0.5 } finish { ambient 1 diffuse 0 } }
sphere { <-0.8, 0.3, 1>, 0.6 pigment { rgb <0.9, 0.2, 0.1> } finish { ambient 1 diffuse 0 } }
box { <0.6, -1.2, 0>, <1.7, -0.2, 1> rotate z * 20 pigment { rgb <0.1, 0.8, 0.2> } finish { ambient 1 diffuse 0 } }'
# POV-Ray's face normal cross(P3 - P1, P2 - P1) of these two is +z, toward the world.
quad='mesh {
  triangle { <-2, -1.5, 0>, <-2, 1.5, 0>, <2, 1.5, 0> uv_vectors <0, 0>, <0, 1>, <1, 1> }
  triangle { <-2, -1.5, 0>, <2, 1.5, 0>, <2, -1.5, 0> uv_vectors <0, 0>, <1, 1>, <1, 0> }
  translate <0, 0, -5>
}'
printf 'camera { mesh_camera { 1 3 %s } location <0, 0, 0> }\n%s\n' "$quad" "$world" >uv.pov
printf 'camera { orthographic location <0, 0, -5> look_at <0, 0, 0> right 4 * x up 3 * y }\n%s\n' "$world" >ortho.pov
printf 'camera { orthographic location <0, 0, -5> look_at <0, 0, 0> right -4 * x up 3 * y }\n%s\n' "$world" >mirror.pov
for f in uv ortho mirror; do
	expect_status 0 "$CIRCE" render $f.pov -o $f.exr -W 40 -H 30 --spp 16 --seed 3 --quiet
done
"$CIRCE" compare uv.exr ortho.exr --fail 1e-3 --fail-percent 2 >out 2>&1 ||
	fail "type 3 on a flat quad is not the orthographic camera: $(cat out)"
echo "type 3 against orthographic: $(tr '\n' ' ' <out)"
if "$CIRCE" compare mirror.exr ortho.exr --fail 1e-3 --fail-percent 2 >out 2>&1; then
	fail "the control: a mirrored orthographic camera passes the same comparison: $(cat out)"
fi

# A grid of a face per pixel of a W x H image, rows J0 to J1 - 1 (pixel i is face i), centroids at
# the pixel centres of the orthographic screen above, normals +z (or -z with Back).
grid='#declare W = 16; #declare H = 12; #declare E = 0.05;
#macro Rows(J0, J1, Back)
  mesh {
    #local J = J0;
    #while (J < J1)
      #local I = 0;
      #while (I < W)
        #local C = <-2 + 4 * (I + 0.5) / W, 1.5 - 3 * (J + 0.5) / H, -5>;
        #if (Back)
          triangle { C + <-E, -E, 0>, C + <2 * E, -E, 0>, C + <-E, 2 * E, 0> }
        #else
          triangle { C + <-E, -E, 0>, C + <-E, 2 * E, 0>, C + <2 * E, -E, 0> }
        #end
        #local I = I + 1;
      #end
      #local J = J + 1;
    #end
  }
#end'
printf '%s\n#declare Up = Rows(0, 5, false)\n#declare Down = Rows(5, H, false)\ncamera { mesh_camera { 1 1 mesh { Up } mesh { Down } } }\n%s\n' \
	"$grid" "$world" >summed.pov
printf '%s\n#declare All = Rows(0, H, false)\ncamera { mesh_camera { 1 0 mesh { All } } }\n%s\n' "$grid" "$world" >whole.pov
for f in summed whole; do
	expect_status 0 "$CIRCE" render $f.pov -o $f.exr -W 16 -H 12 --spp 4 --seed 3 --quiet
done
"$CIRCE" compare summed.exr whole.exr --fail 1e-6 --fail-percent 0 >out 2>&1 ||
	fail "type 1 of two meshes is not type 0 of their faces in one: $(cat out)"

# Type 1, 2 rays: faces 0 to W*H - 1 face +z (a red wall at z 4), the next W*H / 2 face -z (a blue
# wall at z -9).
printf '%s\n%s\n%s\n%s\n%s\n' "$grid" '#declare Front = Rows(0, H, false) #declare Back = Rows(0, H / 2, true)' \
	'camera { mesh_camera { 2 1 mesh { Front } mesh { Back } } }' \
	'plane { z, 4 pigment { rgb <1, 0, 0> } finish { ambient 1 diffuse 0 } }' \
	'plane { z, -9 pigment { rgb <0, 0, 1> } finish { ambient 1 diffuse 0 } }' >two.pov
expect_status 0 "$CIRCE" render two.pov -o two.exr -W 16 -H 12 --spp 64 --seed 3 --quiet
mean() {
	"$CIRCE" compare two.exr two.exr --channels "$1" >out 2>&1
	sed -n 's/^mean: a \([^ ]*\) b .*/\1/p' out
}
r=$(mean R) g=$(mean G) b=$(mean B)
echo "type 1, 2 rays: means R $r G $g B $b (want 0.75 0 0.25)"
awk -v r="$r" -v g="$g" -v b="$b" 'BEGIN { exit !(r != "" && (r - 0.75) ^ 2 < 1e-4 && g ^ 2 < 1e-8 && (b - 0.25) ^ 2 < 1e-4) }' ||
	fail "type 1 with 2 rays per pixel: means R $r G $g B $b, want 0.75 0 0.25"

# 4. max_distance (POV-Ray's TraceRay maxDepth on the camera ray): the type 3 quad's rays at 7
#    from z = -5 meet the sphere and the box (at distances 5 and more) but not the plane at
#    distance 9, which the background replaces: the orthographic camera of the world without the
#    plane (within 1e-3 but at a few edge samples); the control, the same camera without
#    max_distance, differs from it.
noplane=$(printf '%s\n' "$world" | grep -v '^plane')
printf 'camera { mesh_camera { 1 3 7 %s } location <0, 0, 0> }\n%s\n' "$quad" "$world" >far.pov
printf 'camera { orthographic location <0, 0, -5> look_at <0, 0, 0> right 4 * x up 3 * y }\n%s\n' "$noplane" >near.pov
for f in far near; do
	expect_status 0 "$CIRCE" render $f.pov -o $f.exr -W 40 -H 30 --spp 16 --seed 3 --quiet
done
"$CIRCE" compare far.exr near.exr --fail 1e-3 --fail-percent 2 >out 2>&1 ||
	fail "max_distance 7 does not hide the plane at 9: $(cat out)"
if "$CIRCE" compare uv.exr near.exr --fail 1e-3 --fail-percent 2 >out 2>&1; then
	fail "the control: the camera without max_distance matches the world without the plane: $(cat out)"
fi
pass
