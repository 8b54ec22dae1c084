#!/bin/sh
# outputs.sh: -o and --png replace only regular files. A character device or a FIFO is written in
# place (a write error such as ENOSPC is exit 1 with its message); a symbolic link to a regular
# file keeps the link and replaces its target; a folder or a dangling link is refused, untouched.
. "$top_srcdir/tests/lib.sh"
enter_workdir
printf 'camera { location <0, 0, -4> look_at 0 }\nlight_source { <2, 3, -4> color 1 }\nsphere { 0, 1 }\n' >s.pov
r() { "$CIRCE" render s.pov -W 8 -H 8 --quiet "$@"; }
expect_status 0 r --spp 2 -o direct.exr

# Devices of our own first (as root): an unfixed circe would replace these, not /dev's.
if mknod full c 1 7 2>/dev/null && mknod null c 1 3 2>/dev/null; then
	for opt in -o --png; do
		expect_status 1 r --spp 1 $opt full
		grep -qx "full: error: cannot write the output: No space left on device" err || fail "$opt full: $(cat err)"
		[ -c full ] || fail "$opt full: the device was replaced: $(ls -l full)"
	done
	expect_status 0 r --spp 1 -o null --png null
	[ -c null ] || fail "-o null: the device was replaced: $(ls -l null)"
elif [ -w /dev ]; then
	skip "cannot make device nodes, and /dev is writable: /dev/full is not risked"
fi
expect_status 1 r --spp 1 -o /dev/full
grep -qx "/dev/full: error: cannot write the output: No space left on device" err || fail "/dev/full: $(cat err)"
[ -c /dev/full ] || fail "/dev/full is no longer a character device"
expect_status 0 r --spp 1 -o /dev/null
[ -c /dev/null ] || fail "/dev/null is no longer a character device"

# A FIFO: the reader gets the whole EXR, the FIFO stays.
mkfifo pipe
cat pipe >from_pipe.exr &
reader=$!
expect_status 0 r --spp 2 -o pipe
[ -p pipe ] || { kill $reader; fail "the FIFO was replaced: $(ls -l pipe)"; }
wait $reader
expect_status 0 "$CIRCE" compare from_pipe.exr direct.exr

# A symbolic link to a regular file: the link stays, its target gets the new image.
expect_status 0 r --spp 1 -o real.exr --png real.png
ln -s real.exr link.exr
ln -s real.png link.png
expect_status 0 r --spp 2 -o link.exr --png link.png
[ -L link.exr ] && [ "$(readlink link.exr)" = real.exr ] || fail "link.exr was replaced: $(ls -l link.exr)"
[ -L link.png ] && [ "$(readlink link.png)" = real.png ] || fail "link.png was replaced: $(ls -l link.png)"
expect_status 0 "$CIRCE" compare real.exr direct.exr

# Refused, untouched: a dangling link, a folder.
ln -s nowhere.exr dangling.exr
expect_status 1 r --spp 1 -o dangling.exr
grep -q "dangling.exr: error: cannot write the output: it is a symbolic link to a missing file" err ||
	fail "dangling link: $(cat err)"
[ -L dangling.exr ] && [ ! -e nowhere.exr ] || fail "dangling link touched: $(ls -l)"
mkdir folder
expect_status 1 r --spp 1 -o folder
grep -qx "folder: error: cannot write the output: it is a directory" err || fail "folder: $(cat err)"
[ -d folder ] || fail "folder replaced"
[ "$(ls -A | grep '\.tmp$')" = "" ] || fail "temporaries left behind: $(ls -A)"
pass
