/* test_atomic: a writer killed midway leaves the previous file intact and no temporary behind;
 * a completed write replaces the old file whole. */
#include "base/diag.h"
#include "check.h"
#include "io/exr.h"

#include <dirent.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

static char dir[] = "/tmp/circe-test-atomic-XXXXXX";
static char out[300];

static bool write_image(int w, int h, float value)
{
	float *px = malloc(sizeof(float) * (size_t)w * h);
	/* A pattern that compresses slowly, so the writer is killed while compressing or writing. */
	for (size_t i = 0; i < (size_t)w * h; i++)
		px[i] = value + (float)((i * 2654435761u) % 1000003u) * 1e-3f;
	exrfile_channel ch[3] = {{"R", px, 1, (size_t)w}, {"G", px, 1, (size_t)w}, {"B", px, 1, (size_t)w}};
	exrfile_write_desc desc = {{0, 0, w, h}, {0, 0, w, h}, 3, ch, 0, NULL};
	diag d;
	diag_init(&d, stderr);
	bool ok = exrfile_write(out, &desc, &d);
	diag_free(&d);
	free(px);
	return ok;
}

static int count_entries(void)
{
	DIR *dp = opendir(dir);
	int n = 0;
	struct dirent *e;
	while ((e = readdir(dp)))
		if (strcmp(e->d_name, ".") && strcmp(e->d_name, ".."))
			n++;
	closedir(dp);
	return n;
}

int main(void)
{
	if (!mkdtemp(dir))
		return 99;
	snprintf(out, sizeof out, "%s/out.exr", dir);
	CHECK(write_image(16, 16, 7.0f), "first write");
	int killed_midway = 0, finished = 0;
	for (int round = 0; round < 6; round++) {
		pid_t pid = fork();
		if (pid == 0)
			_exit(write_image(1536, 1536, 100.0f) ? 0 : 1);
		struct timespec ts = {0, (long)(30 + round * 60) * 1000000L};
		nanosleep(&ts, NULL);
		kill(pid, round % 2 ? SIGKILL : SIGTERM);
		int status;
		waitpid(pid, &status, 0);
		bool was_killed = WIFSIGNALED(status);
		killed_midway += was_killed;
		finished += !was_killed;
		/* Whatever happened, out.exr reads back whole: the old 16x16 or a complete new image. */
		diag d;
		diag_init(&d, stderr);
		exrfile_image img;
		bool ok = exrfile_read(out, &img, &d);
		CHECK(ok, "round %d: out.exr readable after the writer %s", round,
		      was_killed ? "was killed" : "finished");
		if (ok) {
			bool old = img.width == 16 && exrfile_find_channel(&img, "R")[0] == 7.0f;
			bool fresh = img.width == 1536 && exrfile_find_channel(&img, "R")[0] == 100.0f;
			CHECK(old || (fresh && !was_killed) || fresh, "round %d: image is %dx%d", round, img.width,
			      img.height);
			CHECK(!(was_killed && !old && !fresh), "round %d: killed writer left a mixed file", round);
			exrfile_free(&img);
		}
		diag_free(&d);
		CHECK(count_entries() == 1, "round %d: %d entries in the directory (temporaries left?)", round,
		      count_entries());
		/* Put the old file back for the next round. */
		if (!was_killed)
			CHECK(write_image(16, 16, 7.0f), "restore");
	}
	CHECK(killed_midway >= 3, "only %d of 6 writers were killed midway (machine too fast?)", killed_midway);
	unlink(out);
	rmdir(dir);
	printf("killed midway %d, finished %d\n", killed_midway, finished);
	return check_done("test_atomic");
}
