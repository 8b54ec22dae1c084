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
