#!/bin/sh
# slurm.sh: the farm scripts on a real SLURM. Starts a private single-node SLURM (own config, ports
# and state under the build tree), submits a 4-tile job array and the merge job with afterok,
# waits with a timeout, checks the merged EXR is bit-identical to a single-process render, and
# stops only the daemons it started. Skips (77) without root or slurm-wlm and munge.
. "$top_srcdir/tests/lib.sh"
[ "$(id -u)" = 0 ] || skip "needs root to run slurmd"
for p in munged slurmctld slurmd sbatch squeue sinfo; do
	command -v $p >/dev/null 2>&1 || skip "$p not found (install the Debian packages slurm-wlm and munge)"
done
scene="$top_srcdir/tests/farm/farm.pov"
work=$(mktemp -d "$top_builddir/tests/slurm.XXXXXX") || exit 99
. "$top_srcdir/tests/farm/slurm-cluster.sh"
trap 'slurm_stop; rm -rf "$work"' EXIT
cd "$work" || exit 99
opts="-W 48 -H 36 --spp 4 --seed 5"
# shellcheck disable=SC2086
"$CIRCE" render "$scene" -o whole.exr --threads 1 --quiet $opts >log 2>&1 ||
	{ grep -q "which this build lacks" log && skip "circe render is not in this build yet"; fail "whole render: $(cat log)"; }
slurm_start "$work/cluster" || fail "SLURM did not start: $(tail -n 20 "$work"/cluster/log/* 2>/dev/null)"
export CIRCE
# shellcheck disable=SC2086
sh "$top_srcdir/farm/slurm/submit-tiles.sh" "$scene" "$work/full.exr" 4 $opts >submit.log 2>&1 ||
	fail "submit: $(cat submit.log)"
# Wait for both jobs to leave the queue (120 s at most).
for _ in $(seq 240); do
	[ -z "$(squeue -h 2>/dev/null)" ] && break
	sleep 0.5
done
[ -z "$(squeue -h)" ] || fail "jobs still queued after 120 s: $(squeue)"
[ -f full.exr ] || fail "no merged image; logs: $(cat ./*.log)"
expect_status 0 "$CIRCE" compare full.exr whole.exr --fail 0
grep -q '^max_abs: 0 at' out || fail "merged differs from the single render: $(cat out)"
pass
