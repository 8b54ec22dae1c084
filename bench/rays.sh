#!/bin/sh
# bench/rays.sh [-r ROUNDS] [-n RAYS] [-c LO,HI] NAME=RAYBENCH [NAME=RAYBENCH...]: issue 4's table. Runs each
# raybench binary (e.g. main's and a branch's) on the head and the bunny, primary and incoherent
# rays, with --embree and --circles, alternately for ROUNDS rounds (default 3), and prints a
# markdown table of the medians of the rounds: build, closest hit, any hit against Embree in the
# same process (ratios > 1: faster than Embree), bytes per triangle and the cost of a circle in
# closest-hit rays (-c: circle radii log-uniform in LO..HI of the diagonal, raybench's
# --circle-radius; 0.0003,0.03 resembles the default scene's skin on the head). Compares against
# Embree when configure found libembree-dev; without it the Embree columns read n/a (then
# bench/rayab.sh compares against another revision in one process). Run from the build folder;
# meshes from ../shared/assets (CIRCE_ASSETS overrides), ray files made once with bench/raygen.
set -eu
rounds=3
nrays=1000000
radii=0.001,0.1
while [ $# -gt 0 ]; do
	case $1 in
	-r) rounds=$2; shift 2 ;;
	-n) nrays=$2; shift 2 ;;
	-c) radii=$2; shift 2 ;;
	*) break ;;
	esac
done
[ $# -gt 0 ] || { echo "usage: bench/rays.sh [-r ROUNDS] [-n RAYS] [-c LO,HI] NAME=RAYBENCH..." >&2; exit 2; }
assets=${CIRCE_ASSETS:-$(dirname "$0")/../../shared/assets}
[ -d "$assets" ] || assets=../../shared/assets
head=$assets/lee_perry_smith_head/LeePerrySmith.obj
bunny=$assets/bunny/bunny_npm.obj
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for mesh in head bunny; do
	eval "path=\$$mesh"
	for kind in primary incoherent; do
		bench/raygen "$path" $kind "$nrays" "$work/$mesh-$kind.bin" >/dev/null
	done
done
# raybench --embree exists only when configure found Embree.
embree=--embree
first=${1#*=}
"$first" "$head" "$work/head-primary.bin" --repeat 1 --embree >/dev/null 2>&1 || embree=
[ -n "$embree" ] || echo "raybench was built without Embree: its columns read n/a" >&2
# One line per run: version mesh kind then raybench's key value pairs.
for round in $(seq "$rounds"); do
	for mesh in head bunny; do
		eval "path=\$$mesh"
		for kind in primary incoherent; do
			for v in "$@"; do
				name=${v%%=*} bin=${v#*=}
				out=$("$bin" "$path" "$work/$mesh-$kind.bin" --repeat 3 $embree --circles 100000 --circle-radius "$radii")
				echo "$name $mesh $kind $out" >>"$work/runs"
			done
		done
	done
done
awk -v versions="$*" '
function median(list,    n, a, i, j, t) {
	n = split(list, a, " ")
	for (i = 2; i <= n; i++)
		for (j = i; j > 1 && a[j - 1] + 0 > a[j] + 0; j--) { t = a[j]; a[j] = a[j - 1]; a[j - 1] = t }
	return n % 2 ? a[(n + 1) / 2] : (a[n / 2] + a[n / 2 + 1]) / 2
}
{
	key = $1 SUBSEP $2 SUBSEP $3
	for (i = 4; i < NF; i += 2)
		val[key, $i] = val[key, $i] " " $(i + 1)
}
function or_na(list, fmt) { return list == "" ? "n/a" : sprintf(fmt, median(list)) }
END {
	nv = split(versions, vs, " ")
	print "| mesh | rays | version | build ratio | closest Mrays/s (Embree) | closest ratio | any ratio | B/tri | circle = N rays | hits agree |"
	print "|---|---|---|---|---|---|---|---|---|---|"
	split("head bunny", meshes, " "); split("primary incoherent", kinds, " ")
	for (m = 1; m <= 2; m++) for (k = 1; k <= 2; k++) for (v = 1; v <= nv; v++) {
		name = vs[v]; sub(/=.*/, "", name)
		key = name SUBSEP meshes[m] SUBSEP kinds[k]
		printf "| %s | %s | %s | %s | %.2f (%s) | %s | %s | %.1f | %.2f | %s |\n", meshes[m], kinds[k], name,
			or_na(val[key, "ratio_build"], "%.2f"), median(val[key, "mrays_closest"]),
			or_na(val[key, "embree_mrays_closest"], "%.2f"), or_na(val[key, "ratio_closest"], "%.2f"),
			or_na(val[key, "ratio_any"], "%.2f"), median(val[key, "bytes_per_tri"]),
			median(val[key, "circle_cost_in_rays"]), or_na(val[key, "hits_agree"], "%s")
	}
}' "$work/runs"
