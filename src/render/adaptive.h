/* adaptive.h - adaptive sampling: pixels whose estimated error is below a threshold stop taking
 * samples, after Cycles' scheme (integrator.cpp, kernel/film/adaptive_sampling.h): no pixel stops
 * before min_spp samples, the error is checked every ADAPTIVE_STEP samples after, and a pixel keeps
 * going while any of its 3x3 neighbours is not yet converged.
 * Determinism: the check points are sample counts fixed by the parameters (the scheduler ends a
 * pass at each), never by time. A pixel's own convergence is latched at the first check where its
 * error (film_pixel_error, on its own samples) is below the threshold; until then it samples
 * whatever its neighbours do, so its latch depends on its own sample stream only. A pixel stops
 * at the first check where it and all its neighbours (inside the image) are latched: a function
 * of the 3x3 pixels' streams alone, so threads, tiles, passes and regions cannot change it, given
 * the region's film has a one-pixel apron (ADAPTIVE_APRON) sampled until its own latch. Unlike
 * Cycles a latched pixel is not re-tested (Cycles may un-converge it): that re-test would make a
 * pixel's state depend on how long its neighbours kept it going, a chain that crosses tiles. */
#ifndef CIRCE_RENDER_ADAPTIVE_H
#define CIRCE_RENDER_ADAPTIVE_H

#include "render/film.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Samples between checks after the first (Cycles' adaptive_step). */
#define ADAPTIVE_STEP 16
/* The apron a region's film needs (film_init_apron): the neighbour rule reaches one pixel. */
#define ADAPTIVE_APRON 1

typedef struct adaptive_params {
	double threshold; /* the relative error below which a pixel may stop; 0: adaptive sampling off */
	uint32_t min_spp; /* the first check; 0: adaptive_auto_min_spp(threshold) */
} adaptive_params;

/* Cycles' automatic minimum, max(4, ceil(16 / T^0.3)) (Integrator::get_adaptive_sampling: 0.1 ->
 * 32, 0.01 -> 64, 0.001 -> 128 samples), for threshold T > 0. */
uint32_t adaptive_auto_min_spp(double threshold);
/* The first check of a (its min_spp, or the automatic one). */
uint32_t adaptive_first_check(const adaptive_params *a);
/* Whether a check falls at `count` samples: the first check, then every ADAPTIVE_STEP. */
bool adaptive_is_check(const adaptive_params *a, uint32_t count);
/* The smallest check after `count` samples. */
uint32_t adaptive_next_check(const adaptive_params *a, uint32_t count);
/* Whether f's sampled rectangle holds every image neighbour of its region (the apron is there). */
bool adaptive_film_ok(const film *f);
/* The check at `count` samples on f->acc (every active pixel holds `count` samples): latches the
 * pixels whose error fell below the threshold and stops those the rule stops. Returns how many
 * pixels of the sampled rectangle still take samples. Not thread-safe: between passes only. */
size_t adaptive_check(film *f, const adaptive_params *a, uint32_t count);

/* What a render's film says of its own noise, over the region. */
typedef struct adaptive_summary {
	double nmse;	   /* estimated MSE / mean^2: the variances of the pixels' means over the mean */
	double mean_error; /* mean of film_pixel_error over pixels with >= 2 samples */
	double mean_spp;   /* mean samples per pixel */
	uint32_t min_spp, max_spp;
} adaptive_summary;
void adaptive_summarise(const film *f, adaptive_summary *out);

#endif
