/* atomic.h - files that appear whole or not at all. Output is written to an unnamed temporary in
 * the target's directory (O_TMPFILE; a named `.NAME.XXXXXX.tmp` where the filesystem lacks it),
 * synced, then given the final name in one step: a crash or Ctrl-C never leaves a truncated file
 * under the final name, and an existing file is replaced only by a complete one.
 * Only a regular file is ever replaced. A symbolic link to one is followed: its target is replaced
 * atomically and the link stays. A character device or a FIFO (/dev/null, /dev/full, a pipe) is
 * written in place once the temporary (then in $TMPDIR or /tmp) is complete; anything else that
 * exists (a folder, a socket, a block device, a dangling link) is refused with a message. */
#ifndef CIRCE_IO_ATOMIC_H
#define CIRCE_IO_ATOMIC_H

#include "base/diag.h"

#include <stdbool.h>

typedef struct atomic_file {
	int fd;           /* write here (pwrite or write): always a seekable temporary */
	char *final_path; /* owned: the path given, or the regular file a symbolic link names */
	char *tmp_path;   /* owned; NULL for an unnamed temporary */
	bool in_place;    /* final_path is a character device or a FIFO: commit copies into it */
} atomic_file;

/* Opens a temporary for final_path; false (reported to d) when the directory is not writable or
 * final_path exists and is something that is never written (see above). */
bool atomic_open(atomic_file *f, const char *final_path, diag *d);
/* fsyncs, names the file final_path (replacing any old one), fsyncs the directory, closes; for an
 * in-place target, copies the temporary into it instead. A write error (ENOSPC) is reported. */
bool atomic_commit(atomic_file *f, diag *d);
/* Discards the temporary; the old file under final_path (if any) is untouched. */
void atomic_abort(atomic_file *f);

/* True when writing a and then b would land in one file, so that b overwrites a: the same
 * device and inode when both exist, else the same absolute path once the existing folders in it
 * are resolved (symbolic links, "." and ".."). Two names of one character device (/dev/null) are
 * not the same output: each write goes through whole. */
bool atomic_same_output(const char *a, const char *b);

#endif
