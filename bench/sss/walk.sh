#!/bin/sh
# walk.sh - the volume walk before and after (issue 21): renders bench/sss scenes with --sss volume
# by two circe binaries (OLD, NEW) at the same samples on one thread, measures each image's RMSE
# against a reference (NEW at REF samples on two threads, its own seed) and prints the efficiency
# ratio (MSE x seconds of OLD over that of NEW: above 1, NEW reaches a given noise that much
# faster). Usage: OLD=/path/to/old/circe sh bench/sss/walk.sh [SPP] [REF_SPP] [SIZE] [SCENES]
# from build/ (NEW defaults to ./circe). Short: a minute or two for the defaults.
set -u
here=$(cd "$(dirname "$0")" && pwd)
old=${OLD:?set OLD to the circe binary to compare against}
new=${NEW:-./circe}
spp=${1:-8}
ref_spp=${2:-128}
size=${3:-64x48}
scenes=${4:-"slab sphere finger"}
W=${size%x*} H=${size#*x}
work=${WORK:-bench-sss/walk}
mkdir -p "$work"
secs() { sed -n 's/.*, render \([0-9.e+-]*\) s$/\1/p' "$1" | tail -1; }
echo "| scene | spp | old s | new s | old RMSE | new RMSE | old mean | new mean | ref mean | efficiency new / old |"
echo "|---|---|---|---|---|---|---|---|---|---|"
for s in $scenes; do
	ref="$work/$s.ref.exr"
	"$new" render "$here/scenes/$s.pov" -o "$ref" -W "$W" -H "$H" --spp "$ref_spp" --seed 900005 --threads 2 \
		--sss volume >"$work/$s.ref.log" 2>&1 || { echo "reference $s failed" >&2; continue; }
	for b in old new; do
		if [ $b = old ]; then bin=$old; else bin=$new; fi
		"$bin" render "$here/scenes/$s.pov" -o "$work/$s.$b.exr" -W "$W" -H "$H" --spp "$spp" --seed 1 \
			--threads 1 --sss volume >"$work/$s.$b.log" 2>&1
		eval "t_$b=\$(secs \"$work/$s.$b.log\")"
		set -- $("$new" compare "$work/$s.$b.exr" "$ref" --channels R,G,B --fail 1e30 2>/dev/null |
			awk '/^rmse:/ { r = $2 } /^mean:/ { a = $3; b = $5 } END { print r, a, b }')
		eval "r_$b=$1 m_$b=$2 mref=$3"
	done
	awk -v s="$s" -v n="$spp" -v to="$t_old" -v tn="$t_new" -v ro="$r_old" -v rn="$r_new" -v mo="$m_old" \
		-v mn="$m_new" -v mr="$mref" 'BEGIN { printf "| %s | %d | %.2f | %.2f | %.4g | %.4g | %.4g | %.4g | %.4g | **%.2f** |\n",
		s, n, to, tn, ro, rn, mo, mn, mr, (ro * ro * to) / (rn * rn * tn) }'
done
