/* par.c - par_for: the caller and workers - 1 threads take chunks from one atomic counter. */
#include "base/par.h"

#include <pthread.h>
#include <stdatomic.h>
#include <unistd.h>

/* The most threads one loop starts (the render's --threads limit). */
#define PAR_MAX_WORKERS 1024

typedef struct par_job {
	par_body body;
	void *ctx;
	size_t n, chunk;
	atomic_size_t next; /* the next chunk to take */
} par_job;

typedef struct par_arg {
	par_job *job;
	int worker;
} par_arg;

int par_default_workers(void)
{
	long n = sysconf(_SC_NPROCESSORS_ONLN);
	return n > 0 ? (n > PAR_MAX_WORKERS ? PAR_MAX_WORKERS : (int)n) : 1;
}

static void run_chunks(par_job *j, int worker)
{
	for (;;) {
		size_t c = atomic_fetch_add(&j->next, 1);
		if (c >= (j->n + j->chunk - 1) / j->chunk)
			return;
		size_t b = c * j->chunk, e = b + j->chunk < j->n ? b + j->chunk : j->n;
		j->body(j->ctx, b, e, worker);
	}
}

static void *par_thread(void *p)
{
	par_arg *a = p;
	run_chunks(a->job, a->worker);
	return NULL;
}

void par_for(int workers, size_t n, size_t chunk, par_body body, void *ctx)
{
	if (!n)
		return;
	if (!chunk)
		chunk = 1;
	size_t chunks = (n + chunk - 1) / chunk;
	if (workers > PAR_MAX_WORKERS)
		workers = PAR_MAX_WORKERS;
	if ((size_t)workers > chunks)
		workers = (int)chunks;
	if (workers <= 1) {
		body(ctx, 0, n, 0);
		return;
	}
	par_job job = {.body = body, .ctx = ctx, .n = n, .chunk = chunk};
	atomic_init(&job.next, 0);
	pthread_t tid[PAR_MAX_WORKERS];
	par_arg arg[PAR_MAX_WORKERS];
	int started = 0;
	for (int w = 1; w < workers; w++) {
		arg[started] = (par_arg){&job, w};
		if (pthread_create(&tid[started], NULL, par_thread, &arg[started]) != 0)
			break;
		started++;
	}
	run_chunks(&job, 0);
	for (int i = 0; i < started; i++)
		pthread_join(tid[i], NULL);
}
