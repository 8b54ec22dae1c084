#!/bin/sh
# bench/spheres.sh [COUNT...]: memory and time of scenes of many spheres (issue 15: a grid of N
# balls, as molecules and particle scenes hold), each rendered at 640x480 with 4 samples per pixel
# under --max-memory 2G. Prints a markdown table: peak resident memory (getrusage, through
# /usr/bin/time -v), parse, build and render seconds, and the unique and instanced triangles.
# Run from the build folder (it uses ./circe; CIRCE=... for another binary). The scene is written
# with a #while loop, so the parse time is the language's.
set -eu
circe=${CIRCE:-./circe}
counts=${*:-"1000 10000 100000"}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
echo "| spheres | peak RSS MiB | parse s | build s | render s | unique triangles | instanced triangles |"
echo "|---|---|---|---|---|---|---|"
for n in $counts; do
	k=$(awk -v n="$n" 'BEGIN { k = int(n ^ (1 / 3)); while (k * k * k < n) k++; print k }')
	cat >"$work/s.pov" <<EOS
camera { location <$k * 1.8, $k * 1.6, -$k * 1.5> look_at <$k / 2, $k / 2, $k / 2> angle 50 }
light_source { <-$k, $k * 3, -$k * 2> color rgb 1 intensity $((k * k * 20)) }
background { color rgb 0.2 }
#declare K = $k;
#declare I = 0;
#while (I < $n)
  sphere { <mod(I, K), mod(floor(I / K), K), floor(I / (K * K))>, 0.3
           material { diffuse { color rgb <0.8, 0.5, 0.3> } } }
  #declare I = I + 1;
#end
EOS
	/usr/bin/time -v "$circe" render "$work/s.pov" -o "$work/s.exr" -W 640 -H 480 --spp 4 --max-memory 2G \
		>/dev/null 2>"$work/log" || { cat "$work/log" >&2; exit 1; }
	rss=$(sed -n 's/.*Maximum resident set size (kbytes): //p' "$work/log")
	set -- $(sed -n 's/^circe: time: parse \([0-9.]*\) s, build \([0-9.]*\) s .* render \([0-9.]*\) s$/\1 \2 \3/p' \
		"$work/log")
	"$circe" check "$work/s.pov" >"$work/check"
	tri=$(sed -n 's/.*tessellation: \([0-9]*\) unique, \([0-9]*\) with instances.*/\1 | \2/p' "$work/check")
	printf '| %d | %.0f | %s | %s | %s | %s |\n' "$n" "$(echo "$rss" | awk '{print $1 / 1024}')" "$1" "$2" "$3" "$tri"
done
