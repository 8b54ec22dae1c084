/* atomic.c - temporary file, fsync, rename. */
#include "io/atomic.h"

#include "base/mem.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

/* The directory part of path ("." when none), heap-allocated. */
static char *dir_of(const char *path)
{
	const char *slash = strrchr(path, '/');
	if (!slash)
		return mem_strdup(".");
	if (slash == path)
		return mem_strdup("/");
	size_t n = (size_t)(slash - path);
	char *d = mem_alloc(n + 1, 1);
	if (d) {
		memcpy(d, path, n);
		d[n] = '\0';
	}
	return d;
}

/* A temporary name beside path: DIR/.BASE.XXXXXX.tmp (the X's for mkstemps). */
static char *tmp_name_for(const char *path)
{
	const char *slash = strrchr(path, '/');
	const char *base = slash ? slash + 1 : path;
	size_t dirlen = slash ? (size_t)(slash - path) + 1 : 0;
	size_t n = dirlen + strlen(base) + 16;
	char *t = mem_alloc(n, 1);
	if (t)
		snprintf(t, n, "%.*s.%s.XXXXXX.tmp", (int)dirlen, path, base);
	return t;
}

bool atomic_open(atomic_file *f, const char *final_path, diag *d)
{
	f->fd = -1;
	f->tmp_path = NULL;
	f->final_path = mem_strdup(final_path);
	char *dir = dir_of(final_path);
	if (!f->final_path || !dir) {
		mem_free(dir);
		mem_free(f->final_path);
		diag_file_error(d, final_path, "out of memory");
		return false;
	}
#ifdef O_TMPFILE
	f->fd = open(dir, O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666 & ~0022);
#endif
	if (f->fd < 0) {
		/* No O_TMPFILE here: a named temporary, removed on abort. */
		f->tmp_path = tmp_name_for(final_path);
		if (f->tmp_path)
			f->fd = mkstemps(f->tmp_path, 4);
		if (f->fd >= 0)
			fchmod(f->fd, 0644);
	}
	int err = errno;
	mem_free(dir);
	if (f->fd < 0) {
		diag_file_error(d, final_path, "cannot create the output: %s", strerror(err));
		mem_free(f->tmp_path);
		mem_free(f->final_path);
		f->tmp_path = f->final_path = NULL;
		return false;
	}
	return true;
}

static void sync_dir(const char *path)
{
	char *dir = dir_of(path);
	if (!dir)
		return;
	int dfd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
	if (dfd >= 0) {
		fsync(dfd);
		close(dfd);
	}
	mem_free(dir);
}

/* Gives the unnamed temporary a name: the final one when free, else a temporary to rename. */
static bool link_unnamed(atomic_file *f, int *err)
{
	char proc[64];
	snprintf(proc, sizeof proc, "/proc/self/fd/%d", f->fd);
	if (linkat(AT_FDCWD, proc, AT_FDCWD, f->final_path, AT_SYMLINK_FOLLOW) == 0)
		return true;
	if (errno != EEXIST) {
		*err = errno;
		return false;
	}
	for (int attempt = 0; attempt < 100; attempt++) {
		char *t = tmp_name_for(f->final_path);
		if (!t) {
			*err = ENOMEM;
			return false;
		}
		/* Fill the X's ourselves: linkat has no mkstemp. */
		char *x = strstr(t, ".XXXXXX.tmp") + 1;
		unsigned v = (unsigned)getpid() * 2654435761u + (unsigned)attempt * 40503u;
		for (int i = 0; i < 6; i++, v /= 36)
			x[i] = "abcdefghijklmnopqrstuvwxyz0123456789"[v % 36];
		if (linkat(AT_FDCWD, proc, AT_FDCWD, t, AT_SYMLINK_FOLLOW) == 0) {
			f->tmp_path = t;
			if (rename(t, f->final_path) == 0) {
				mem_free(t);
				f->tmp_path = NULL;
				return true;
			}
			*err = errno;
			return false; /* atomic_abort removes the named temporary */
		}
		mem_free(t);
		if (errno != EEXIST) {
			*err = errno;
			return false;
		}
	}
	*err = EEXIST;
	return false;
}

bool atomic_commit(atomic_file *f, diag *d)
{
	int err = 0;
	bool ok = fsync(f->fd) == 0;
	if (!ok)
		err = errno;
	if (ok && !f->tmp_path)
		ok = link_unnamed(f, &err);
	else if (ok && rename(f->tmp_path, f->final_path) != 0) {
		err = errno;
		ok = false;
	}
	if (ok) {
		mem_free(f->tmp_path);
		f->tmp_path = NULL;
	}
	if (close(f->fd) != 0 && ok) {
		err = errno;
		ok = false;
	}
	f->fd = -1;
	if (ok)
		sync_dir(f->final_path);
	else
		diag_file_error(d, f->final_path, "cannot write the output: %s", strerror(err));
	atomic_abort(f);
	return ok;
}

void atomic_abort(atomic_file *f)
{
	if (f->fd >= 0)
		close(f->fd);
	f->fd = -1;
	if (f->tmp_path)
		unlink(f->tmp_path);
	mem_free(f->tmp_path);
	mem_free(f->final_path);
	f->tmp_path = f->final_path = NULL;
}
