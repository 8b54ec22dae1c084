/* scheduler.c - the pass loop, the worker pool and the progress reports (scheduler.h). The calling
 * thread only coordinates: it starts a pass by bumping `generation` under the mutex, waits for
 * `active` to reach zero (waking up to refresh progress), then commits or discards the pass. */
#include "render/scheduler.h"

#include "base/mem.h"
#include "render/adaptive.h"

#include <assert.h>
#include <pthread.h>
#include <time.h>
#include <unistd.h>

/* How often the coordinating thread wakes to refresh progress and look at the interrupt flag. */
#define RENDER_PROGRESS_PERIOD_S 0.25
/* The most samples per pixel a render may reach (the sample index is 32-bit). */
#define RENDER_MAX_SPP 0x7fffffffu

typedef struct pool {
	const render_job *job;
	film *film;
	int tile, tiles_x, tiles_y, tile_count;
	uint32_t s0, s1; /* the pass's sample range, written under mu before the generation bump */

	pthread_mutex_t mu;
	pthread_cond_t start, done;
	unsigned generation;
	bool quit;
	int active; /* workers still in the current pass */

	_Atomic int next_tile;
	_Atomic int tiles_done;
	_Atomic uint64_t samples_done; /* pixel samples of the current pass, for progress */
	_Atomic uint64_t dropped;      /* samples dropped in the current pass */
	_Atomic uint64_t sss_searches, sss_nohit, sss_overflow, sss_walks, sss_walk_dropped,
		sss_walk_steps, sss_walk_skipped, sss_walk_queries; /* of the current pass */
} pool;

static double now_s(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int render_default_threads(void)
{
	long n = sysconf(_SC_NPROCESSORS_ONLN);
	return n > 0 ? (int)n : 1;
}

static bool interrupted(const render_job *job)
{
	return job->interrupt && atomic_load(job->interrupt) != 0;
}

/* Renders samples [s0, s1) of one pixel (x, y) from px into px. */
static void render_pixel(pool *p, int x, int y, film_pixel *px, uint64_t counts[9])
{
	const render_job *job = p->job;
	for (uint32_t s = p->s0; s < p->s1; s++) {
		render_sampler g = render_sampler_make(job->sampler, job->seed, (uint32_t)x, (uint32_t)y, s);
		vec2 pu = render_sampler_2d(&g, RENDER_DIM_PIXEL);
		vec2 lu = render_sampler_2d(&g, RENDER_DIM_LENS);
		render_ray ray;
		render_sample smp = {0}; /* no ray (outside a fisheye's circle): black */
		if (cam_sample(job->camera, x, y, pu, lu, &ray))
			smp = render_path(job->scene, &job->settings, ray, &g);
		counts[1] += smp.sss_searches;
		counts[2] += smp.sss_nohit;
		counts[3] += smp.sss_overflow;
		counts[4] += smp.sss_walks;
		counts[5] += smp.sss_walk_dropped;
		counts[6] += smp.sss_walk_steps;
		counts[7] += smp.sss_walk_skipped;
		counts[8] += smp.sss_walk_queries;
		if (!film_pixel_add(px, &smp, job->scene->light_sign != NULL)) {
			render_sample zero = {0};
			film_pixel_add(px, &zero, false);
			counts[0]++;
		}
	}
}

/* Renders one tile's pixels for samples [s0, s1) into film->work (the pixels adaptive sampling
 * stopped are copied as they are); false when interrupted. */
static bool render_tile(pool *p, int tile)
{
	assert(tile >= 0 && tile < p->tile_count);
	film *f = p->film;
	int tx = tile % p->tiles_x, ty = tile / p->tiles_x;
	int xa = f->ax0 + tx * p->tile, ya = f->ay0 + ty * p->tile;
	int xb = xa + p->tile < f->ax1 ? xa + p->tile : f->ax1,
	    yb = ya + p->tile < f->ay1 ? ya + p->tile : f->ay1;
	uint64_t counts[9] = {0}; /* dropped, SSS searches, no-hits, overflows, walks, walks dropped, walk
				   * interactions, skipped casts, nearest queries */
	for (int y = ya; y < yb; y++) {
		if (interrupted(p->job))
			return false;
		uint64_t taken = 0;
		for (int x = xa; x < xb; x++) {
			film_pixel px = *film_at(f->acc, f, x, y);
			if (!px.stopped) {
				assert(px.n == p->s0);
				px.nets = p->job->sampler == RENDER_SAMPLER_SOBOL;
				render_pixel(p, x, y, &px, counts);
				taken += p->s1 - p->s0;
			}
			*film_at(f->work, f, x, y) = px;
		}
		atomic_fetch_add(&p->samples_done, taken);
	}
	atomic_fetch_add(&p->dropped, counts[0]);
	atomic_fetch_add(&p->sss_searches, counts[1]);
	atomic_fetch_add(&p->sss_nohit, counts[2]);
	atomic_fetch_add(&p->sss_overflow, counts[3]);
	atomic_fetch_add(&p->sss_walks, counts[4]);
	atomic_fetch_add(&p->sss_walk_dropped, counts[5]);
	atomic_fetch_add(&p->sss_walk_steps, counts[6]);
	atomic_fetch_add(&p->sss_walk_skipped, counts[7]);
	atomic_fetch_add(&p->sss_walk_queries, counts[8]);
	return true;
}

static void *worker(void *arg)
{
	pool *p = arg;
	unsigned seen = 0;
	for (;;) {
		pthread_mutex_lock(&p->mu);
		while (p->generation == seen && !p->quit)
			pthread_cond_wait(&p->start, &p->mu);
		bool quit = p->quit;
		seen = p->generation;
		pthread_mutex_unlock(&p->mu);
		if (quit)
			return NULL;
		for (;;) {
			if (interrupted(p->job))
				break;
			int t = atomic_fetch_add(&p->next_tile, 1);
			if (t >= p->tile_count || !render_tile(p, t))
				break;
			atomic_fetch_add(&p->tiles_done, 1);
		}
		pthread_mutex_lock(&p->mu);
		if (--p->active == 0)
			pthread_cond_signal(&p->done);
		pthread_mutex_unlock(&p->mu);
	}
}

/* One report to the job's progress callback; fraction in [0,1]. */
static void report_progress(const render_job *job, double fraction, double rate, double elapsed, bool done)
{
	render_progress p = {.fraction = fraction, .rate = rate, .elapsed = elapsed, .done = done};
	job->progress(job->progress_user, &p);
}

/* Samples per pixel of the next pass: double the last, capped by the target, by RENDER_PASS_MAX_S,
 * by the time budget left at the measured rate (pixel samples per second) and, with adaptive
 * sampling, by the next check (a pass ends on each, whatever the timing). */
static uint32_t next_pass_size(const render_job *job, uint32_t done, uint32_t last, double rate_px,
			       double left_s)
{
	uint64_t want = last ? 2u * (uint64_t)last : 1u;
	if (rate_px > 0.0) {
		double limit = RENDER_PASS_MAX_S;
		if (job->time_budget_s > 0.0 && left_s < limit)
			limit = left_s;
		double fit = rate_px * limit;
		if (fit < (double)want)
			want = fit < 1.0 ? 1u : (uint64_t)fit;
	}
	uint64_t cap = job->spp ? job->spp : RENDER_MAX_SPP;
	if (job->adaptive.threshold > 0.0) {
		uint32_t check = adaptive_next_check(&job->adaptive, done);
		cap = check < cap ? check : cap;
	}
	if (done + want > cap)
		want = cap - done;
	return (uint32_t)want;
}

/* Starts up to `threads` workers on p, their ids in tid; returns how many started. */
static int pool_start(pool *p, pthread_t *tid, int threads)
{
	pthread_mutex_init(&p->mu, NULL);
	pthread_cond_init(&p->start, NULL);
	pthread_cond_init(&p->done, NULL);
	int started = 0;
	while (started < threads && pthread_create(&tid[started], NULL, worker, p) == 0)
		started++;
	return started;
}

/* Tells the `started` workers to quit, joins them and destroys p's mutex and conditions. */
static void pool_stop(pool *p, pthread_t *tid, int started)
{
	pthread_mutex_lock(&p->mu);
	p->quit = true;
	pthread_cond_broadcast(&p->start);
	pthread_mutex_unlock(&p->mu);
	for (int i = 0; i < started; i++)
		pthread_join(tid[i], NULL);
	pthread_mutex_destroy(&p->mu);
	pthread_cond_destroy(&p->start);
	pthread_cond_destroy(&p->done);
}

/* Waits (holding p->mu) for the workers to finish the pass, reporting progress every
 * RENDER_PROGRESS_PERIOD_S. npix: the sampled rectangle's pixel count; t0: when the render started. */
static void wait_pass(pool *p, double t0, double npix)
{
	const render_job *job = p->job;
	const film *f = p->film;
	while (p->active > 0) {
		struct timespec ts;
		clock_gettime(CLOCK_REALTIME, &ts);
		long ns = ts.tv_nsec + (long)(RENDER_PROGRESS_PERIOD_S * 1e9);
		ts.tv_sec += ns / 1000000000L;
		ts.tv_nsec = ns % 1000000000L;
		pthread_cond_timedwait(&p->done, &p->mu, &ts);
		if (job->progress && p->active > 0) {
			double el = now_s() - t0;
			/* Counts stopped pixels as sampled: with adaptive sampling, an upper bound. */
			double done_px = (double)f->spp * npix + (double)atomic_load(&p->samples_done);
			double frac = job->spp ? done_px / ((double)job->spp * npix) : 0.0;
			if (job->time_budget_s > 0.0 && el / job->time_budget_s > frac)
				frac = el / job->time_budget_s;
			report_progress(job, frac > 1.0 ? 1.0 : frac, el > 0 ? done_px / el : 0.0, el, false);
		}
	}
}

/* Runs samples [film->spp, film->spp + n) of every tile on the `workers` started; true when
 * every tile completed (false: interrupted, the film's work buffer is to be discarded). */
static bool run_pass(pool *p, int workers, uint32_t n, double t0, double npix)
{
	assert(workers > 0 && n > 0);
	pthread_mutex_lock(&p->mu);
	p->s0 = p->film->spp;
	p->s1 = p->film->spp + n;
	atomic_store(&p->next_tile, 0);
	atomic_store(&p->tiles_done, 0);
	atomic_store(&p->samples_done, 0);
	atomic_store(&p->dropped, 0);
	atomic_store(&p->sss_searches, 0);
	atomic_store(&p->sss_nohit, 0);
	atomic_store(&p->sss_overflow, 0);
	atomic_store(&p->sss_walks, 0);
	atomic_store(&p->sss_walk_dropped, 0);
	atomic_store(&p->sss_walk_steps, 0);
	atomic_store(&p->sss_walk_skipped, 0);
	atomic_store(&p->sss_walk_queries, 0);
	p->active = workers;
	p->generation++;
	pthread_cond_broadcast(&p->start);
	wait_pass(p, t0, npix);
	pthread_mutex_unlock(&p->mu);
	assert(atomic_load(&p->tiles_done) <= p->tile_count);
	return atomic_load(&p->tiles_done) == p->tile_count;
}

/* Commits the completed pass to the film and adds its counts to the render's; runs adaptive
 * sampling's check when the pass ended on one. Returns how many pixels still take samples. */
static size_t commit_pass(pool *p, render_stats *total, size_t active)
{
	const adaptive_params *ad = &p->job->adaptive;
	film_commit(p->film, p->s1);
	total->samples += atomic_load(&p->samples_done);
	p->film->dropped += atomic_load(&p->dropped);
	total->sss_searches += atomic_load(&p->sss_searches);
	total->sss_nohit += atomic_load(&p->sss_nohit);
	total->sss_overflow += atomic_load(&p->sss_overflow);
	total->sss_walks += atomic_load(&p->sss_walks);
	total->sss_walk_dropped += atomic_load(&p->sss_walk_dropped);
	total->sss_walk_steps += atomic_load(&p->sss_walk_steps);
	total->sss_walk_skipped += atomic_load(&p->sss_walk_skipped);
	total->sss_walk_queries += atomic_load(&p->sss_walk_queries);
	total->passes++;
	if (ad->threshold > 0.0 && adaptive_is_check(ad, p->film->spp))
		active = adaptive_check(p->film, ad, p->film->spp);
	return active;
}

/* Whether the render has reached its target: the samples, the time budget or RENDER_MAX_SPP. */
static bool target_reached(const render_job *job, const film *f, double elapsed)
{
	return (job->spp && f->spp >= job->spp) || (job->time_budget_s > 0.0 && elapsed >= job->time_budget_s) ||
	       f->spp >= RENDER_MAX_SPP;
}

render_status render_run(const render_job *job, film *f, render_stats *stats)
{
	if (!job->scene || !job->camera || (job->spp == 0 && !(job->time_budget_s > 0.0)) ||
	    job->camera->width != f->width || job->camera->height != f->height ||
	    job->settings.max_trace_level < 1 || job->adaptive.threshold < 0.0 ||
	    (job->adaptive.threshold > 0.0 && !adaptive_film_ok(f)))
		return RENDER_ERROR;
	double t0 = now_s();
	int threads = job->threads > 0 ? job->threads : render_default_threads();
	pool p = {.job = job, .film = f, .tile = job->tile_size > 0 ? job->tile_size : RENDER_DEFAULT_TILE};
	p.tiles_x = (film_sampled_width(f) + p.tile - 1) / p.tile;
	p.tiles_y = (f->ay1 - f->ay0 + p.tile - 1) / p.tile;
	p.tile_count = p.tiles_x * p.tiles_y;
	pthread_t *tid = mem_alloc((size_t)threads, sizeof *tid);
	if (!tid)
		return RENDER_ERROR;
	int started = pool_start(&p, tid, threads);

	render_status status = started > 0 ? RENDER_DONE : RENDER_ERROR;
	double npix = (double)film_sampled_width(f) * (f->ay1 - f->ay0);
	double rate_px = 0.0, last_checkpoint = t0;
	uint32_t last = 0;
	render_stats total = {0};
	size_t active = 1; /* pixels still sampled; a continued film's stopped ones are skipped */
	while (status == RENDER_DONE) {
		double elapsed = now_s() - t0;
		if (target_reached(job, f, elapsed))
			break;
		if (active == 0) { /* adaptive sampling stopped every pixel: they are final */
			if (job->spp)
				f->spp = job->spp;
			break;
		}
		if (interrupted(job)) {
			status = RENDER_INTERRUPTED;
			break;
		}
		uint32_t n = next_pass_size(job, f->spp, last, rate_px, job->time_budget_s - elapsed);
		double pass_start = now_s();
		if (!run_pass(&p, started, n, t0, npix)) { /* interrupted: discard the pass */
			status = RENDER_INTERRUPTED;
			break;
		}
		active = commit_pass(&p, &total, active);
		last = n;
		double pass_s = now_s() - pass_start;
		if (pass_s > 0.0)
			rate_px = (double)n / pass_s;
		if (job->checkpoint && job->checkpoint_interval_s > 0.0 &&
		    now_s() - last_checkpoint >= job->checkpoint_interval_s) {
			job->checkpoint(job->checkpoint_user, f);
			last_checkpoint = now_s();
		}
	}
	pool_stop(&p, tid, started);
	mem_free(tid);

	double seconds = now_s() - t0;
	if (job->progress)
		report_progress(job, job->spp ? (double)f->spp / job->spp : 1.0,
				seconds > 0 ? (double)total.samples / seconds : 0.0, seconds, true);
	if (stats) {
		*stats = total;
		stats->spp = f->spp;
		stats->dropped = f->dropped;
		stats->seconds = seconds;
		stats->samples_per_s = seconds > 0.0 ? (double)total.samples / seconds : 0.0;
		stats->threads = started;
	}
	return status;
}
