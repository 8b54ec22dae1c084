/* check.h - the assertions of circe's unit test programs. A failed check prints where and the
 * values involved, and the program goes on to report every failure; check_done() gives the exit
 * status the automake harness reads (0 pass, 1 fail). */
#ifndef CIRCE_TESTS_CHECK_H
#define CIRCE_TESTS_CHECK_H

#include <math.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/wait.h>
#include <unistd.h>

static int check_count, check_failed;

#define CHECK(cond, ...)                                                                   \
	do {                                                                               \
		check_count++;                                                             \
		if (!(cond)) {                                                             \
			check_failed++;                                                    \
			fprintf(stderr, "%s:%d: check failed: %s: ", __FILE__, __LINE__, #cond); \
			fprintf(stderr, __VA_ARGS__);                                      \
			fputc('\n', stderr);                                               \
		}                                                                          \
	} while (0)

/* |a - b| <= tol, printing both values on failure. */
#define CHECK_NEAR(a, b, tol)                                                              \
	do {                                                                               \
		double check_a_ = (double)(a), check_b_ = (double)(b);                     \
		CHECK(fabs(check_a_ - check_b_) <= (tol), "%s = %.17g, %s = %.17g, tol %g", #a, \
		      check_a_, #b, check_b_, (double)(tol));                              \
	} while (0)

/* A path inside dir, in one of four rotating buffers (so a call can take several). */
static inline const char *check_path(const char *dir, const char *name)
{
	static char buf[4][256];
	static int k;
	k = (k + 1) % 4;
	snprintf(buf[k], sizeof buf[k], "%s/%s", dir, name);
	return buf[k];
}

/* Whether fn(arg) ends its process with SIGABRT (a failed assert()): it runs in a child whose
 * stderr goes to /dev/null. The checks of circe's invariants use it (README.md, "Assertions"). */
static inline bool check_aborts(void (*fn)(void *), void *arg)
{
	fflush(NULL);
	pid_t pid = fork();
	if (pid < 0)
		return false;
	if (pid == 0) {
		if (!freopen("/dev/null", "w", stderr))
			_exit(2);
		fn(arg);
		_exit(0);
	}
	int status;
	if (waitpid(pid, &status, 0) != pid)
		return false;
	return WIFSIGNALED(status) && WTERMSIG(status) == SIGABRT;
}

static inline int check_done(const char *name)
{
	printf("%s: %d checks, %d failed\n", name, check_count, check_failed);
	return check_failed ? 1 : 0;
}

#endif
