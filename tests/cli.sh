#!/bin/sh
# cli.sh: the command line — --help and --version, exit status 2 with a clear message for every
# kind of bad option, and no output file when the command line is wrong; two outputs naming one
# file are a command-line error.
. "$top_srcdir/tests/lib.sh"
cd "$(mktemp -d)" || exit 99
trap 'rm -rf "$PWD"' EXIT
expect_status 0 "$CIRCE" --version
grep -Eq '^circe [0-9]+\.[0-9]+\.[0-9]+$' out || fail "version: $(cat out)"
expect_status 0 "$CIRCE" --help
grep -q '^usage: circe render SCENE' out || fail "help: $(cat out)"
expect_status 2 "$CIRCE"
grep -q 'no subcommand given' err || fail "$(cat err)"
expect_status 2 "$CIRCE" paint x.pov
grep -qx "circe: error: unknown subcommand 'paint'" err || fail "$(cat err)"
# Each bad render option: its message, exit 2.
bad() {
	msg=$1; shift
	expect_status 2 "$CIRCE" render "$@"
	grep -qF "circe: error: $msg" err || fail "'$*': expected '$msg', got: $(cat err)"
}
bad "'render' needs a scene"
bad "'render' takes one scene" a.pov b.pov
bad "--spp needs a sample count from 1 to 2^30, not '0'" a.pov --spp 0
bad "--spp needs a sample count from 1 to 2^30, not '12x'" a.pov --spp 12x
bad "--time needs a number of seconds > 0, not '-1'" a.pov --time -1
bad "--spp and --time exclude each other" a.pov --spp 4 --time 10
bad "-W needs a width from 1 to 65536, not '0'" a.pov -W 0
bad "-H needs a height from 1 to 65536, not 'big'" a.pov -H big
bad "--threads needs a count from 1 to 1024, not '0'" a.pov --threads 0
bad "--sss must be circle, fullcircle, disk, volume or auto, not 'dipole'" a.pov --sss dipole
bad "--circle-weight must be exact or talk, not 'approx'" a.pov --circle-weight approx
bad "--sampler must be sobol or random, not 'halton'" a.pov --sampler halton
bad "--part must be all, camera, coat, sss, direct or indirect, not 'sky'" a.pov --part sky
bad "--seed needs an integer >= 0, not '-3'" a.pov --seed -3
bad "--region needs X0,Y0,X1,Y1 with 0 <= X0 < X1 and 0 <= Y0 < Y1, not '1,2,3'" a.pov --region 1,2,3
bad "--region needs X0,Y0,X1,Y1 with 0 <= X0 < X1 and 0 <= Y0 < Y1, not '5,0,5,10'" a.pov --region 5,0,5,10
bad "--region lies outside the -W x -H image" a.pov -W 10 -H 10 --region 0,0,11,10
bad "--aov takes a list of albedo, normal, depth, variance, error, samples, not 'albedo,foo'" a.pov --aov albedo,foo
bad "--tile needs I/N with 0 <= I < N, not '3/3'" a.pov --tile 3/3
bad "--noise-threshold needs a relative error > 0 such as 0.05, not '-0.1'" a.pov --noise-threshold -0.1
bad "--noise-threshold needs a relative error > 0 such as 0.05, not '0'" a.pov --noise-threshold 0
bad "--noise-threshold needs a relative error > 0 such as 0.05, not 'low'" a.pov --noise-threshold low
bad "--noise-threshold needs a relative error > 0 such as 0.05, not 'nan'" a.pov --noise-threshold nan
bad "--min-spp needs a sample count from 1 to 2^30, not '0'" a.pov --noise-threshold 0.1 --min-spp 0
bad "--region and --tile exclude each other" a.pov --tile 0/2 --region 0,0,1,1
bad "--clock needs a number, not 'noon'" a.pov --clock noon
bad "--frame needs a frame number >= 0, not '-1'" a.pov --frame -1
bad "--checkpoint needs a number of seconds > 0, not '0'" a.pov --checkpoint 0
bad "--max-memory needs a size such as 512M or 2G, not '2T'" a.pov --max-memory 2T
bad "bad option for 'render'" a.pov --bogus
[ -z "$(ls)" ] || [ "$(ls)" = "err
out" ] || fail "files left behind: $(ls)"
# Two outputs naming one file (another spelling, a link, a folder's alias, after --frame): exit 2
# before anything is read or written.
same() {
	expect_status 2 "$CIRCE" render -W 4 -H 4 --spp 1 --quiet "$@"
	grep -q "^circe: error: -o '.*' and --png '.*' name the same file" err || fail "'$*': $(cat err)"
}
printf 'sphere { 0, 1 }\n' >s.pov
same s.pov -o same.exr --png same.exr
same s.pov -o same.exr --png ./same.exr
same s.pov -o same.exr --png no_such_dir/../same.exr
same s.pov -o "$PWD/same.exr" --png same.exr
same s.pov -o x.exr --png 'x.####.exr' --frame 7
ln -s same.exr link.exr
same s.pov -o same.exr --png link.exr
mkdir sub && ln -s sub alias
same s.pov -o sub/a.exr --png alias/a.exr
[ ! -e same.exr ] && [ -z "$(ls sub)" ] || fail "an output was written: $(ls -R)"
expect_status 0 "$CIRCE" render s.pov -W 4 -H 4 --spp 1 --quiet -o same.exr
same s.pov -o link.exr --png same.exr
expect_status 0 "$CIRCE" render s.pov -W 4 -H 4 --spp 1 --quiet -o same.exr --png other.exr --frame 3
pass
