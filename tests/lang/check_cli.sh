#!/bin/sh
# check_cli: `circe check` exit codes and summary: 0 ok, 1 unreadable file, 2 bad command line, 3 scene error.
set -u
: "${CIRCE:?}" "${srcdir:?}"
tmp=$(mktemp -d "${TMPDIR:-/tmp}/circe-cli.XXXXXX") || exit 99
trap 'rm -rf "$tmp"' EXIT
fail=0
expect() { # expect STATUS DESCRIPTION -- command...
	want=$1 what=$2
	shift 3
	"$@" >"$tmp/out" 2>"$tmp/err"
	got=$?
	if [ "$got" -ne "$want" ]; then
		echo "FAIL $what: exit $got, expected $want"
		cat "$tmp/out" "$tmp/err"
		fail=1
	fi
}
good="$srcdir/tests/good"
expect 0 "good scene" -- "$CIRCE" check -I "$good/inc" "$good/include_path.pov"
grep -q "objects:    5" "$tmp/out" || { echo "FAIL summary lacks the object count"; cat "$tmp/out"; fail=1; }
grep -Eq "triangles after tessellation: [1-9][0-9]* unique" "$tmp/out" ||
	{ echo "FAIL summary lacks the tessellated triangle count"; cat "$tmp/out"; fail=1; }
printf 'mesh { file "missing.obj" }\n' >"$tmp/nofile.pov"
expect 3 "missing mesh file is a scene error" -- "$CIRCE" check "$tmp/nofile.pov"
grep -q "nofile.pov:1:13: error: mesh file '$tmp/missing.obj': cannot open it: No such file or directory" "$tmp/err" ||
	{ echo "FAIL missing mesh file message:"; cat "$tmp/err"; fail=1; }
expect 1 "missing file" -- "$CIRCE" check "$tmp/none.pov"
grep -qx "$tmp/none.pov: error: cannot open: No such file or directory" "$tmp/err" ||
	{ echo "FAIL missing-file message:"; cat "$tmp/err"; fail=1; }
mkdir "$tmp/folder"
expect 1 "a folder as the scene" -- "$CIRCE" check "$tmp/folder"
grep -qx "$tmp/folder: error: cannot open: Is a directory" "$tmp/err" ||
	{ echo "FAIL folder-as-scene message:"; cat "$tmp/err"; fail=1; }
expect 1 "render of a folder" -- "$CIRCE" render "$tmp/folder" -o "$tmp/folder.exr"
grep -qx "$tmp/folder: error: cannot open: Is a directory" "$tmp/err" && [ ! -e "$tmp/folder.exr" ] ||
	{ echo "FAIL render of a folder:"; cat "$tmp/err"; fail=1; }
# Every file the scene names is opened by check; render says the same thing (tests/bad holds
# the cases and their expected diagnostics) and writes nothing.
for name in image_missing image_directory image_not_an_image sky_sphere_image_missing normal_map_directory \
	mesh_file_missing mesh_file_directory subdiv_file_missing subdiv_file_directory include_directory; do
	expect 3 "render $name" -- sh -c 'cd "$1/tests/bad" && "$2" render "$3.pov" -W 4 -H 4 --spp 1 -o "$4/x.exr"' \
		sh "$srcdir" "$CIRCE" "$name" "$tmp"
	grep -E '^[^ :]+:([0-9]+:[0-9]+:)? (error|note): ' "$tmp/err" | cmp -s - "$srcdir/tests/bad/$name.err" ||
		{ echo "FAIL render $name: diagnostics differ from check's:"; cat "$tmp/err"; fail=1; }
	[ ! -e "$tmp/x.exr" ] || { echo "FAIL render $name wrote an image"; fail=1; }
done
expect 2 "no scene" -- "$CIRCE" check
expect 2 "two scenes" -- "$CIRCE" check a.pov b.pov
expect 2 "bad clock" -- "$CIRCE" check --clock abc "$good/basic.pov"
expect 2 "unknown option" -- "$CIRCE" check --frobnicate "$good/basic.pov"
expect 3 "scene error" -- "$CIRCE" check "$srcdir/tests/bad/sphere_negative_radius.pov"
expect 3 "include without -I" -- "$CIRCE" check "$good/include_path.pov"
printf 'sphere { 0, clock }\n' >"$tmp/clock.pov"
expect 3 "clock 0 makes radius 0" -- "$CIRCE" check "$tmp/clock.pov"
expect 0 "--clock sets clock" -- "$CIRCE" check --clock 0.5 "$tmp/clock.pov"
expect 0 "--dump" -- "$CIRCE" check --dump --clock 0.5 "$tmp/clock.pov"
grep -q "radius 0.5" "$tmp/out" || { echo "FAIL dump lacks the clocked radius"; fail=1; }
# --frame N: an animation's frame, as POV-Ray's Initial_Frame of a scene's .ini gives it (the
# portfolio scenes index arrays by frame_number - 1): frame_number and its range are N, clock_on 1.
printf '#declare A = array[2] { 3, 5 }\nsphere { <frame_number, initial_frame, clock_on>, A[frame_number - 1] }\n' >"$tmp/frame.pov"
expect 3 "frame_number 0 without --frame" -- "$CIRCE" check "$tmp/frame.pov"
grep -q "frame.pov:2:53: error: array index -1 out of range 0..1 of 'A'" "$tmp/err" ||
	{ echo "FAIL frame_number without --frame:"; cat "$tmp/err"; fail=1; }
expect 0 "--frame sets frame_number" -- "$CIRCE" check --dump --frame 2 "$tmp/frame.pov"
grep -q "center <2, 2, 1> radius 5" "$tmp/out" || { echo "FAIL --frame 2:"; cat "$tmp/out"; fail=1; }
expect 2 "bad frame" -- "$CIRCE" check --frame -1 "$good/basic.pov"
grep -qx "circe: error: --frame needs a frame number >= 0, not '-1'" "$tmp/err" ||
	{ echo "FAIL bad --frame message:"; cat "$tmp/err"; fail=1; }
# #debug, #warning and #undef's warning go to stderr exactly so; check still succeeds.
expect 0 "#debug and #warning" -- sh -c 'cd "$1" && "$2" check messages.pov' sh "$good" "$CIRCE"
cmp -s "$tmp/err" "$good/messages.stderr" ||
	{ echo "FAIL #debug/#warning output differs (expected, then got):"; cat "$good/messages.stderr" "$tmp/err"; fail=1; }
# Uses of names declared deprecated warn exactly so (POV-Ray 3.7's rules); check still succeeds.
expect 0 "#declare deprecated" -- sh -c 'cd "$1" && "$2" check deprecated.pov' sh "$good" "$CIRCE"
cmp -s "$tmp/err" "$good/deprecated.stderr" ||
	{ echo "FAIL deprecation warnings differ (expected, then got):"; cat "$good/deprecated.stderr" "$tmp/err"; fail=1; }
# Data files: #read's warnings exactly so; #write writes as povray 3.7.0 does (floats %g, vectors
# <a,b,...> and a blank, strings as they are), under check as under render; a file outside the
# scene's folder is refused unless an -I folder holds it, and #read searches the -I folders.
expect 0 "#fopen/#read" -- sh -c 'cd "$1" && "$2" check datafile.pov' sh "$good" "$CIRCE"
cmp -s "$tmp/err" "$good/datafile.stderr" ||
	{ echo "FAIL #read warnings differ (expected, then got):"; cat "$good/datafile.stderr" "$tmp/err"; fail=1; }
mkdir "$tmp/scene" "$tmp/lib"
cat >"$tmp/scene/write.pov" <<'EOF2'
#fopen F "out.txt" write
#write (F, 1.23456789, ",", <1, 2.5, 3>, ",", "\"str\"", ",\n", -1e10, ", ", <1, 2>, "\n")
#fclose F
#fopen F "out.txt" append
#write (F 7 "\n") // POV-Ray's commas are optional (its portfolio's html_gen.inc: #write(HTMLFile Header1))
#fclose F
#fopen G "out.txt" read
#read (G, A, B, C, D, E, H)
#if (A != 1.23457 | H != 7 | defined(G)) #error "out.txt was not read back" #end
sphere { B, A }
EOF2
expect 0 "#write" -- sh -c 'cd "$1" && "$2" check write.pov' sh "$tmp/scene" "$CIRCE"
printf '1.23457,<1,2.5,3> ,"str",\n-1e+10, <1,2> \n7\n' | cmp -s - "$tmp/scene/out.txt" ||
	{ echo "FAIL #write output:"; cat "$tmp/scene/out.txt"; fail=1; }
printf '2\n' >"$tmp/lib/radius.txt"
printf '#fopen F "../lib/radius.txt" read\n#read (F, R)\nsphere { 0, R }\n' >"$tmp/scene/up.pov"
expect 3 "a data file outside the scene's folder" -- "$CIRCE" check "$tmp/scene/up.pov"
grep -q "is outside the scene's folder and the -I folders" "$tmp/err" || { echo "FAIL outside message:"; cat "$tmp/err"; fail=1; }
expect 0 "a data file in an -I folder" -- "$CIRCE" check -I "$tmp/lib" "$tmp/scene/up.pov"
printf '#fopen F "radius.txt" read\n#read (F, R)\nsphere { 0, R }\n' >"$tmp/scene/search.pov"
expect 0 "#fopen read searches the -I folders" -- "$CIRCE" check -I "$tmp/lib" "$tmp/scene/search.pov"
# global_settings items circe does on its own: one warning each, exactly so, and the IR is that
# of the scene without them (the lines between its "ignored" markers).
expect 0 "ignored global_settings" -- sh -c 'cd "$1" && "$2" check --dump ignored_settings.pov' sh "$good" "$CIRCE"
cmp -s "$tmp/err" "$good/ignored_settings.stderr" ||
	{ echo "FAIL ignored settings' warnings differ (expected, then got):"; cat "$good/ignored_settings.stderr" "$tmp/err"; fail=1; }
# radiosity's settings are ignored but its presence is recorded (POV-Ray's sky lights under it):
# the IR says so in one line, the only difference.
grep -qx 'global radiosity' "$tmp/out" || { echo "FAIL the IR does not record radiosity"; fail=1; }
sed 's/@[^ ]*//g; /^global radiosity$/d' "$tmp/out" >"$tmp/ignored.ir"
sed '/ignored: begin/,/ignored: end/d' "$good/ignored_settings.pov" >"$tmp/plain.pov"
expect 0 "global_settings without the ignored items" -- "$CIRCE" check --dump "$tmp/plain.pov"
sed 's/@[^ ]*//g' "$tmp/out" | cmp -s - "$tmp/ignored.ir" ||
	{ echo "FAIL the ignored settings change the IR:"; sed 's/@[^ ]*//g' "$tmp/out" | diff - "$tmp/ignored.ir"; fail=1; }
# A light's POV-Ray items that do nothing warn at their keyword, as POV-Ray does: fade_distance
# without fade_power (its default 0 fades nothing), orient without area_light.
printf 'light_source { <0, 5, 0> color rgb 1 fade_distance 5 }\nlight_source { 0 color rgb 1 orient }\n' >"$tmp/lightwarn.pov"
expect 0 "light items that do nothing" -- "$CIRCE" check "$tmp/lightwarn.pov"
grep -q "lightwarn.pov:1:38: warning: the light does not fade: POV-Ray fades only with both fade_distance and fade_power > 0" "$tmp/err" &&
	grep -q "lightwarn.pov:2:30: warning: 'orient' only affects area_light" "$tmp/err" ||
	{ echo "FAIL light warnings:"; cat "$tmp/err"; fail=1; }
# #error stops with exit 3 and its message at the directive.
printf 'sphere { 0, 1 }\n#error "stop"\n' >"$tmp/error.pov"
expect 3 "#error" -- "$CIRCE" check "$tmp/error.pov"
grep -qx "$tmp/error.pov:2:1: error: parse halted by #error: stop" "$tmp/err" ||
	{ echo "FAIL #error message:"; cat "$tmp/err"; fail=1; }
# render gives the scene its image size and frame (main.c fills lang_options).
cat >"$tmp/values.pov" <<'EOF2'
#if (image_width != 6 | image_height != 4 | frame_number != 3 | !clock_on | clock != 0.5)
  #error "wrong values"
#end
sphere { 0, 1 }
EOF2
expect 0 "render's image_width, image_height, frame_number, clock_on" -- \
	"$CIRCE" render "$tmp/values.pov" -W 6 -H 4 --spp 1 --frame 3 --clock 0.5 -o "$tmp/values.exr" --quiet
printf 'sphere { 0, 1 scale <1, 2, 1> material { skin {} } }\nsphere { 0, 1 scale 2 material { wax {} } }\n' >"$tmp/nu.pov"
expect 0 "non-uniform SSS" -- "$CIRCE" check "$tmp/nu.pov"
grep -q "SSS objects under a non-uniform scale: 1 " "$tmp/out" || { echo "FAIL non-uniform SSS not reported"; fail=1; }

# A subdivision cage from a file: its faces and its tessellation are counted (the cube: 6 quads,
# 6 * 2 * 4^3 triangles at level 3).
printf 'subdivision_surface { file "%s" level 3 }\n' \
	"$srcdir/scenes/assets/opensubdiv_shapes/catmark_cube_creases1.obj" >"$tmp/cage.pov"
expect 0 "cage file" -- "$CIRCE" check "$tmp/cage.pov"
grep -q "subdivision cage faces: 6$" "$tmp/out" && grep -q "triangles after tessellation: 768 unique" "$tmp/out" ||
	{ echo "FAIL cage file summary:"; cat "$tmp/out" "$tmp/err"; fail=1; }

# A large file is mapped and its pages dropped behind the lexer: a validation error found after
# the parse must still quote its line from the start of the file.
{
	printf 'subdivision_surface {\n  vertex_vectors { 3, <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }\n'
	printf '  faces { 2, <0, 1, 2>, <0, 2> }\n}\n'
	awk 'BEGIN { for (i = 0; i < 160000; i++) print "// 0123456789012345678901234567890123456789012345678901234567" }'
	printf 'sphere { 0, 1 }\n'
} >"$tmp/big.pov"
expect 3 "large mapped file" -- "$CIRCE" check "$tmp/big.pov"
head -2 "$tmp/err" >"$tmp/got"
printf '%s\n' "$tmp/big.pov:3:25: error: face 1 has 2 vertices; a face needs at least 3" \
	"  faces { 2, <0, 1, 2>, <0, 2> }" | cmp -s - "$tmp/got" ||
	{ echo "FAIL large mapped file: quoted line"; cat "$tmp/err"; fail=1; }
exit $fail
