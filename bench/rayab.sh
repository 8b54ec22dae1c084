#!/bin/sh
# bench/rayab.sh [-r REPEAT] [-n RAYS] [-k CIRCLES] [-c LO,HI] BASE: this tree's BVH (src/accel, as
# built into libcirce.a) against the one of git revision BASE, in one process (bench/rayab.c), on
# the head and the bunny, primary and incoherent rays (bench/raygen, RAYS each, default 200000),
# and CIRCLES half circles (default 30000, radii log-uniform in LO..HI of the diagonal, default
# 0.001,0.1; 0.0003,0.03 resembles the renderer's skin). Each of REPEAT repeats (default 9) times
# both versions, the one going first alternating; prints a markdown table of the medians of the
# per-repeat ratios (base time / new time: > 1 is faster) and checks that both give the same hits
# bit for bit. For a machine without Embree (raybench --embree), and for a change's own effect
# without the run-to-run noise of separate processes. Run from the build folder; meshes from
# ../shared/assets (CIRCE_ASSETS overrides).
set -eu
repeat=9
nrays=200000
ncircles=30000
radii=0.001,0.1
while [ $# -gt 0 ]; do
	case $1 in
	-r) repeat=$2; shift 2 ;;
	-n) nrays=$2; shift 2 ;;
	-k) ncircles=$2; shift 2 ;;
	-c) radii=$2; shift 2 ;;
	*) break ;;
	esac
done
[ $# -eq 1 ] || { echo "usage: bench/rayab.sh [-r REPEAT] [-n RAYS] [-k CIRCLES] [-c LO,HI] BASE" >&2; exit 2; }
base=$1
top=$(sed -n 's/^top_srcdir = //p' Makefile)
assets=${CIRCE_ASSETS:-$top/../shared/assets}
[ -d "$assets" ] || assets=../../shared/assets
head=$assets/lee_perry_smith_head/LeePerrySmith.obj
bunny=$assets/bunny/bunny_npm.obj
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
make -s libcirce.a bench/obj.o bench/raygen
# The build's compiler, flags and libraries.
eval "$(make -s -f Makefile -f - rayab-vars <<'MK'
rayab-vars:
	@echo "cc='$(CC)'"; echo "cflags='$(DEFS) $(AM_CPPFLAGS) $(CPPFLAGS) $(AM_CFLAGS) $(CFLAGS)'"; echo "libs='$(CIRCE_LIBS) $(LIBS)'"
MK
)"
# The base revision's accel/, its bvh.c compiled against its own headers, its symbols renamed.
mkdir -p "$work/base/src/accel"
for f in $(git -C "$top" ls-tree --name-only "$base" src/accel/); do
	git -C "$top" show "$base:$f" >"$work/base/$f"
done
# shellcheck disable=SC2086
$cc -I"$work/base/src" $cflags -c -o "$work/base_bvh.o" "$work/base/src/accel/bvh.c"
nm -g --defined-only "$work/base_bvh.o" | awk '{ print $3, "base_" $3 }' >"$work/syms"
objcopy --redefine-syms="$work/syms" "$work/base_bvh.o"
# shellcheck disable=SC2086
$cc $cflags -I"$top/bench" -c -o "$work/rayab.o" "$top/bench/rayab.c"
# shellcheck disable=SC2086
$cc $cflags -o "$work/rayab" "$work/rayab.o" bench/obj.o "$work/base_bvh.o" $libs
echo "| mesh | rays | closest Mrays/s base (new) | closest ratio | any ratio | circles ratio | build ratio | circle = N rays base (new) | B/tri base (new) | same hits |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for mesh in head bunny; do
	eval "path=\$$mesh"
	for kind in primary incoherent; do
		bench/raygen "$path" $kind "$nrays" "$work/rays.bin" >/dev/null
		"$work/rayab" "$path" "$work/rays.bin" "$repeat" "$ncircles" "$radii" >"$work/out" || true
		awk -v mesh=$mesh -v kind=$kind '{
			for (i = 1; i < NF; i += 2) v[$i] = $(i + 1)
			same = v["closest_differ"] + v["any_differ"] + v["circles_differ"] == 0 ? "yes" : \
				"NO (" v["closest_differ"] " " v["any_differ"] " " v["circles_differ"] ")"
			printf "| %s | %s | %.2f (%.2f) | %.3f | %.3f | %.3f | %.3f | %.2f (%.2f) | %.1f (%.1f) | %s |\n", mesh, kind,
				v["base_mrays_closest"], v["mrays_closest"], v["ratio_closest"], v["ratio_any"], v["ratio_circles"],
				v["ratio_build"], v["base_circle_cost_in_rays"], v["circle_cost_in_rays"], v["base_bytes_per_tri"],
				v["bytes_per_tri"], same
		}' "$work/out"
	done
done
