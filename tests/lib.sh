# lib.sh: helpers for circe's shell tests (sourced). Exit codes follow automake: 0 pass, 1 fail,
# 77 skip, 99 hard error.
fail() { echo "FAIL: $*" >&2; exit 1; }
skip() { echo "SKIP: $*"; exit 77; }
pass() { echo "PASS"; exit 0; }
# expect_status N CMD...: runs CMD with stdout in ./out and stderr in ./err; fails unless it exits N.
expect_status() {
	want=$1; shift
	"$@" >out 2>err
	got=$?
	[ "$got" = "$want" ] || fail "'$*' exited $got, expected $want; stdout: $(cat out); stderr: $(cat err)"
}
# seed_noise A.exr B.exr: the RMSE of A against B (two renders that differ only in the seed).
seed_noise() {
	expect_status 1 "$CIRCE" compare "$1" "$2"
	sed -n 's/^rmse: //p' out
}
# expect_same_within_noise NAME A.exr B.exr NOISE DIVISOR: fails unless the RMSE of A against B
# is under NOISE / DIVISOR (the same image up to rounding, when NOISE is the seed-to-seed RMSE).
expect_same_within_noise() {
	"$CIRCE" compare "$2" "$3" >out 2>&1
	rmse=$(sed -n 's/^rmse: //p' out)
	awk -v a="$rmse" -v b="$4" -v k="$5" 'BEGIN { exit !(a < b / k) }' ||
		fail "$1: rmse $rmse against $3, noise between seeds $4: $(cat out)"
	echo "$1: rmse $rmse against $3; between seeds $4"
}
# enter_workdir: makes a temporary folder, removed when the test exits, and works in it ($work).
enter_workdir() {
	work=$(mktemp -d) || exit 99
	trap 'rm -rf "$work"' EXIT
	cd "$work" || exit 99
}
