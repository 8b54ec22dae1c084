#!/bin/sh
# submit-frames.sh SCENE 'OUT.####.exr' FIRST LAST [circe render options...]: renders frames
# FIRST..LAST of an animation, one job-array task each; the frame number replaces #### in the
# output name and clock runs from 0 to 1 over the range.
set -eu
[ $# -ge 4 ] || { echo "usage: submit-frames.sh SCENE 'OUT.####.exr' FIRST LAST [options...]" >&2; exit 2; }
scene=$1 pattern=$2 first=$3 last=$4
shift 4
here=$(cd "$(dirname "$0")" && pwd)
job=$(sbatch --parsable --array="$first-$last" --output="${pattern%.exr}.%a.log" \
	"$here/circe-frame.sbatch" "$scene" "$pattern" "$first" "$last" "$@")
echo "frames: job ${job%%;*} (array $first-$last)"
echo "a failed frame F is resubmitted alone with:"
echo "  sbatch --array=F $here/circe-frame.sbatch $scene '$pattern' $first $last $*"
