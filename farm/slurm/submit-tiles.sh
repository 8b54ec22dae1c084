#!/bin/sh
# submit-tiles.sh SCENE OUT.exr N [circe render options...]: renders SCENE as N tiles on the farm
# (one job-array task each) and merges them into OUT.exr when all have succeeded. Prints the two
# job ids. Set CIRCE to the circe binary if it is not on the nodes' PATH; sbatch options such as
# --partition go in SBATCH_PARTITION etc. (sbatch's own environment variables).
set -eu
[ $# -ge 3 ] || { echo "usage: submit-tiles.sh SCENE OUT.exr N [circe render options...]" >&2; exit 2; }
scene=$1 out=$2 n=$3
shift 3
here=$(cd "$(dirname "$0")" && pwd)
prefix=${out%.exr}
array=$(sbatch --parsable --array=0-$((n - 1)) --output="$prefix.tile-%a.log" \
	"$here/circe-tile.sbatch" "$scene" "$prefix" "$n" "$@")
array=${array%%;*}
merge=$(sbatch --parsable --dependency=afterok:"$array" --output="$prefix.merge.log" \
	"$here/circe-merge.sbatch" "$out" "$prefix" "$n")
merge=${merge%%;*}
echo "tiles: job $array (array 0-$((n - 1))), merge: job $merge"
echo "a failed tile I is resubmitted alone with:"
echo "  sbatch --array=I $here/circe-tile.sbatch $scene $prefix $n $*"
echo "  sbatch $here/circe-merge.sbatch $out $prefix $n"
