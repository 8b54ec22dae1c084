/* atomic.c - temporary file, fsync, rename; or, for a device or a FIFO, a copy into it. */
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

/* What atomic_open does with the path it is given. */
typedef enum target_kind {
	TARGET_FILE,     /* absent, or a regular file (through a link: resolved names it) */
	TARGET_IN_PLACE, /* a character device or a FIFO */
	TARGET_REFUSED   /* why says what it is */
} target_kind;

static target_kind classify(const char *path, char **resolved, const char **why)
{
	*resolved = NULL;
	struct stat lst, st;
	if (lstat(path, &lst) != 0)
		return TARGET_FILE; /* absent, or unreachable: creating the temporary says why */
	if (stat(path, &st) != 0) {
		*why = errno == ENOENT ? "is a symbolic link to a missing file; it is not replaced"
				       : "is a symbolic link that cannot be followed; it is not replaced";
		return TARGET_REFUSED;
	}
	if (S_ISREG(st.st_mode)) {
		if (S_ISLNK(lst.st_mode)) {
			char *r = realpath(path, NULL);
			*resolved = r ? mem_strdup(r) : NULL;
			free(r);
			if (!*resolved) {
				*why = "is a symbolic link whose target cannot be resolved";
				return TARGET_REFUSED;
			}
		}
		return TARGET_FILE;
	}
	if (S_ISCHR(st.st_mode) || S_ISFIFO(st.st_mode))
		return TARGET_IN_PLACE;
	*why = S_ISDIR(st.st_mode) ? "is a directory"
				   : "is not a regular file, a character device or a FIFO; it is not replaced";
	return TARGET_REFUSED;
}

/* The folder for an in-place target's temporary: $TMPDIR, else /tmp (a device's folder is often
 * not writable, and the temporary never gets a name there). */
static char *in_place_temp_beside(void)
{
	const char *t = getenv("TMPDIR");
	if (!t || !*t)
		t = "/tmp";
	size_t n = strlen(t) + sizeof "/circe-output";
	char *p = mem_alloc(n, 1);
	if (p)
		snprintf(p, n, "%s/circe-output", t);
	return p;
}

/* Opens f->fd, readable too (an in-place commit copies from it), in the folder of beside. */
static bool open_temp(atomic_file *f, const char *beside)
{
	char *dir = dir_of(beside);
	if (!dir) {
		errno = ENOMEM;
		return false;
	}
#ifdef O_TMPFILE
	f->fd = open(dir, O_TMPFILE | O_RDWR | O_CLOEXEC, 0666 & ~0022);
#endif
	if (f->fd < 0) {
		/* No O_TMPFILE here: a named temporary, removed on abort. */
		f->tmp_path = tmp_name_for(beside);
		if (f->tmp_path)
			f->fd = mkstemps(f->tmp_path, 4);
		if (f->fd >= 0)
			fchmod(f->fd, 0644);
	}
	int err = errno;
	mem_free(dir);
	errno = err;
	return f->fd >= 0;
}

bool atomic_open(atomic_file *f, const char *final_path, diag *d)
{
	f->fd = -1;
	f->tmp_path = NULL;
	const char *why = NULL;
	char *resolved;
	target_kind kind = classify(final_path, &resolved, &why);
	if (kind == TARGET_REFUSED) {
		diag_file_error(d, final_path, "cannot write the output: it %s", why);
		return false;
	}
	f->in_place = kind == TARGET_IN_PLACE;
	f->final_path = resolved ? resolved : mem_strdup(final_path);
	char *beside = f->in_place ? in_place_temp_beside() : NULL;
	if (!f->final_path || (f->in_place && !beside)) {
		mem_free(beside);
		mem_free(f->final_path);
		diag_file_error(d, final_path, "out of memory");
		return false;
	}
	bool ok = open_temp(f, beside ? beside : f->final_path);
	int err = errno;
	mem_free(beside);
	if (!ok) {
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

/* Writes all n bytes of buf to fd; false with *err set (ENOSPC from /dev/full). */
static bool write_all(int fd, const char *buf, size_t n, int *err)
{
	while (n > 0) {
		ssize_t w = write(fd, buf, n);
		if (w < 0 && errno == EINTR)
			continue;
		if (w <= 0) {
			*err = w < 0 ? errno : EIO;
			return false;
		}
		buf += w, n -= (size_t)w;
	}
	return true;
}

enum { COPY_CHUNK_BYTES = 16 * 1024 }; /* on the stack of whichever thread writes */

/* The complete temporary, copied from its start into the device or FIFO final_path. */
static bool copy_in_place(atomic_file *f, int *err)
{
	int out = open(f->final_path, O_WRONLY | O_CLOEXEC);
	if (out < 0) {
		*err = errno;
		return false;
	}
	char buf[COPY_CHUNK_BYTES];
	off_t at = 0;
	bool ok = true;
	for (;;) {
		ssize_t n = pread(f->fd, buf, sizeof buf, at);
		if (n < 0 && errno == EINTR)
			continue;
		if (n < 0)
			*err = errno, ok = false;
		if (n <= 0 || !(ok = write_all(out, buf, (size_t)n, err)))
			break;
		at += n;
	}
	if (close(out) != 0 && ok) {
		*err = errno;
		ok = false;
	}
	return ok;
}

/* fsyncs the temporary and gives it the final name. */
static bool publish(atomic_file *f, int *err)
{
	if (fsync(f->fd) != 0) {
		*err = errno;
		return false;
	}
	if (!f->tmp_path)
		return link_unnamed(f, err);
	if (rename(f->tmp_path, f->final_path) != 0) {
		*err = errno;
		return false;
	}
	mem_free(f->tmp_path);
	f->tmp_path = NULL;
	return true;
}

bool atomic_commit(atomic_file *f, diag *d)
{
	int err = 0;
	bool ok = f->in_place ? copy_in_place(f, &err) : publish(f, &err);
	if (close(f->fd) != 0 && ok) {
		err = errno;
		ok = false;
	}
	f->fd = -1;
	if (ok && !f->in_place)
		sync_dir(f->final_path);
	else if (!ok)
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

/* path made absolute against the working folder, "." and ".." folded and repeated '/' dropped,
 * without following links (heap; NULL when memory runs out). */
static char *lexical_absolute(const char *path)
{
	char cwd[PATH_MAX] = "";
	if (path[0] != '/' && !getcwd(cwd, sizeof cwd))
		cwd[0] = '\0';
	size_t n = strlen(cwd) + strlen(path) + 3;
	char *out = mem_alloc(n, 1);
	if (!out)
		return NULL;
	char *in = mem_alloc(n, 1);
	if (!in) {
		mem_free(out);
		return NULL;
	}
	snprintf(in, n, "%s/%s", cwd, path);
	size_t len = 0;
	for (char *seg = in; *seg;) {
		size_t k = strcspn(seg, "/");
		if (k == 2 && seg[0] == '.' && seg[1] == '.') {
			while (len > 0 && out[--len] != '/')
				;
		} else if (k > 0 && !(k == 1 && seg[0] == '.')) {
			out[len++] = '/';
			memcpy(out + len, seg, k);
			len += k;
		}
		seg += k + (seg[k] == '/');
	}
	if (len == 0)
		out[len++] = '/';
	out[len] = '\0';
	mem_free(in);
	return out;
}

enum { LINK_HOPS_MAX = 40 }; /* Linux's own limit on links followed in one lookup */

/* Where a chain of symbolic links that ends at a missing file points (heap; path itself when it
 * is no link). A dangling link is a name for the file its target will be. */
static char *follow_links(const char *path)
{
	char *cur = mem_strdup(path);
	for (int hop = 0; cur && hop < LINK_HOPS_MAX; hop++) {
		char target[PATH_MAX];
		ssize_t n = readlink(cur, target, sizeof target - 1);
		if (n < 0)
			break;
		target[n] = '\0';
		char *dir = target[0] == '/' ? mem_strdup("") : dir_of(cur);
		size_t len = (dir ? strlen(dir) : 0) + (size_t)n + 2;
		char *next = dir ? mem_alloc(len, 1) : NULL;
		if (next)
			snprintf(next, len, "%s%s%s", dir, target[0] == '/' ? "" : "/", target);
		mem_free(dir);
		mem_free(cur);
		cur = next;
	}
	return cur;
}

/* The absolute path of the file path names (through symbolic links, even dangling ones) with
 * its folder resolved by realpath when that folder exists. */
static char *normal_path(const char *path)
{
	char *linked = follow_links(path);
	char *lex = linked ? lexical_absolute(linked) : NULL;
	mem_free(linked);
	if (!lex)
		return NULL;
	char *slash = strrchr(lex, '/');
	if (slash == lex || !slash[1])
		return lex;
	*slash = '\0';
	char *dir = realpath(lex, NULL);
	*slash = '/';
	if (!dir)
		return lex;
	size_t n = strlen(dir) + strlen(slash) + 1;
	char *out = mem_alloc(n, 1);
	if (out)
		snprintf(out, n, "%s%s", strcmp(dir, "/") ? dir : "", slash);
	free(dir);
	mem_free(lex);
	return out;
}

bool atomic_same_output(const char *a, const char *b)
{
	struct stat sa, sb;
	if (stat(a, &sa) == 0 && stat(b, &sb) == 0)
		return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino && !S_ISCHR(sa.st_mode);
	char *na = normal_path(a), *nb = normal_path(b);
	bool same = na && nb ? !strcmp(na, nb) : !strcmp(a, b);
	mem_free(na);
	mem_free(nb);
	return same;
}
