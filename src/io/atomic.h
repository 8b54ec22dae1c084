/* atomic.h - files that appear whole or not at all. Output is written to an unnamed temporary in
 * the target's directory (O_TMPFILE; a named `.NAME.XXXXXX.tmp` where the filesystem lacks it),
 * synced, then given the final name in one step: a crash or Ctrl-C never leaves a truncated file
 * under the final name, and an existing file is replaced only by a complete one. */
#ifndef CIRCE_IO_ATOMIC_H
#define CIRCE_IO_ATOMIC_H

#include "base/diag.h"

#include <stdbool.h>

typedef struct atomic_file {
	int fd;           /* write here (pwrite or write) */
	char *final_path; /* owned */
	char *tmp_path;   /* owned; NULL for an unnamed temporary */
} atomic_file;

/* Opens a temporary beside final_path; false (reported to d) when the directory is not writable. */
bool atomic_open(atomic_file *f, const char *final_path, diag *d);
/* fsyncs, names the file final_path (replacing any old one), fsyncs the directory, closes. */
bool atomic_commit(atomic_file *f, diag *d);
/* Discards the temporary; the old file under final_path (if any) is untouched. */
void atomic_abort(atomic_file *f);

#endif
