/* scheduler.h - progressive, multi-threaded rendering into a film.
 * A render is a sequence of passes; pass k adds samples [s0, s1) to every pixel of the region.
 * The first pass has 1 sample per pixel; each next pass doubles, capped so that a pass should take
 * at most RENDER_PASS_MAX_S seconds (and no more than the time budget left), so checkpoints and
 * the time budget are honoured within about one pass. Within a pass, tiles of tile_size^2 pixels
 * are taken from an atomic counter by `threads` worker threads. Because each pixel's samples are
 * summed one by one in sample order, each from its sampler (seed, x, y, s; sampler.h), the image is
 * bit-identical for any thread count, tile size, region and pass schedule.
 *
 * Adaptive sampling (job.adaptive, adaptive.h): passes also end on each of its checks, which run
 * between passes on the committed film; a pixel it stops keeps its samples and takes no more, and
 * when it has stopped every pixel the render ends (the film's spp set to the target, the pixels
 * final). Its decisions depend on sample counts and the pixels' own samples only, so the image is
 * bit-identical for any thread count, tiling, region and pass schedule here too.
 * Stopping: after the pass that reaches `spp`, or after the first pass that ends at or past
 * `time_budget_s` (the budget is a target: the last pass is sized to end near it), or on interrupt.
 * Interrupt: when *interrupt becomes non-zero the workers start nothing new (they leave even the
 * tile in hand), the pass in progress is discarded unless it already completed, and render_run
 * returns RENDER_INTERRUPTED with the film holding the last committed pass: every pixel has the
 * same film->spp samples. The flag may be set from a signal handler (atomic_store on a lock-free
 * _Atomic int is async-signal-safe):
 *     static _Atomic int stop;  static void on_signal(int sig) { (void)sig; atomic_store(&stop, 1); }
 * Checkpoints: every checkpoint_interval_s seconds (checked between passes) the callback is called
 * on the calling thread with the consistent film; it may read it (film_read) and write a file.
 * Progress: when a callback is given, it is called on the calling thread about 4 times a second
 * during a pass, and once more when the render ends (done: true); render/ prints nothing itself
 * (circe's main.c draws the terminal's progress line). Threads share only atomics and
 * mutex-protected state; the scene's callbacks must be thread-safe. */
#ifndef CIRCE_RENDER_SCHEDULER_H
#define CIRCE_RENDER_SCHEDULER_H

#include "render/adaptive.h"
#include "render/camera.h"
#include "render/film.h"
#include "render/integrator.h"

#include <stdatomic.h>
#include <stdbool.h>
#include <stdint.h>

#define RENDER_PASS_MAX_S   2.0
#define RENDER_DEFAULT_TILE 16

/* What a progress callback is told. */
typedef struct render_progress {
	double fraction; /* of the samples (or of the time budget) done, in [0, 1] */
	double rate;	 /* pixel samples per second since the render started */
	double elapsed;	 /* seconds since the render started */
	bool done;	 /* the last call: the render has ended */
} render_progress;

typedef struct render_job {
	const render_scene *scene;
	const cam *camera;
	render_settings settings;
	uint64_t seed;
	render_sampler_kind sampler;  /* Sobol (the default, 0) or random (sampler.h) */
	uint32_t spp;		      /* target samples per pixel; 0: none (then a time budget is needed) */
	double time_budget_s;	      /* 0: none */
	int threads;		      /* 0: all online cores */
	int tile_size;		      /* 0: RENDER_DEFAULT_TILE */
	double checkpoint_interval_s; /* 0: no checkpoints */
	void (*checkpoint)(void *user, const film *f); /* may be NULL */
	void *checkpoint_user;
	void (*progress)(void *user, const render_progress *p); /* may be NULL */
	void *progress_user;
	_Atomic int *interrupt; /* may be NULL */
	adaptive_params adaptive; /* threshold 0: off; else the film needs an apron (adaptive.h) */
} render_job;

typedef enum render_status { RENDER_DONE, RENDER_INTERRUPTED, RENDER_ERROR } render_status;

typedef struct render_stats {
	uint32_t spp;	      /* samples per pixel completed (= film->spp) */
	uint64_t samples;     /* pixel samples taken by the committed passes, the apron's included */
	uint64_t dropped;     /* non-finite samples dropped (= film->dropped); should be 0 */
	uint64_t sss_searches; /* SSS entry searches (circles, probes, walks) of the committed passes */
	uint64_t sss_nohit;    /* of them, those that found no entry (their paths end: the no-hit rate) */
	uint64_t sss_overflow; /* of them, those with more hits than kept */
	uint64_t sss_walks;    /* of them, volume walks (every search of volume, auto's walks) */
	uint64_t sss_walk_dropped; /* of the walks, those that reached their step bound (dark, counted) */
	uint64_t sss_walk_steps;   /* the walks' interactions */
	uint64_t sss_walk_skipped; /* of them, those whose ray cast was skipped (a ball free of surface) */
	uint64_t sss_walk_queries; /* the walks' nearest-surface queries */
	double seconds;	      /* wall time of render_run */
	double samples_per_s; /* pixel samples committed per second */
	int passes;	      /* committed passes */
	int threads;
} render_stats;

/* Renders job into f (from film_init). A film that already holds spp samples of the same job
 * (an interrupted or time-limited render) is continued from sample spp on, and ends bit-identical
 * to an uninterrupted render. Returns RENDER_ERROR (with f untouched) for an invalid job (no spp and no time
 * budget, no scene or camera, a camera whose size differs from the film's) or when threads cannot be started.
 * stats may be NULL. */
render_status render_run(const render_job *job, film *f, render_stats *stats);
/* Number of online cores (at least 1). */
int render_default_threads(void);

#endif
