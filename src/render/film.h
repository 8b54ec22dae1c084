/* film.h - the pixel accumulators of a render: beauty and the AOVs (albedo, normal, depth,
 * variance) in double, for the region [x0,x1) x [y0,y1) of a width x height image (the whole image
 * when no region is given). Pixel coordinates are always the whole image's, so a region's pixels
 * are bit-identical to the same pixels of a whole render.
 * Two buffers: `acc` holds the committed state, every pixel with `spp` samples (fewer where
 * adaptive sampling stopped it: its own count `n`); a pass writes `acc + its samples` into `work`,
 * and committing swaps them, so an interrupted pass is discarded without touching `acc`. Each
 * pixel's samples are added one by one in sample order whatever the passes were, which makes the
 * sums independent of threads, tiles and pass sizes.
 * The sampled rectangle [ax0,ax1) x [ay0,ay1) is the region, or with an apron (film_init_apron,
 * for adaptive sampling's neighbour rule, adaptive.h) the region and a ring of that many pixels
 * around it, clipped to the image; acc and work cover it, row-major from (ax0, ay0); film_read
 * reads the region only.
 * Memory: 2 x 120 bytes per sampled pixel. Reading (film_read) is only safe between passes. */
#ifndef CIRCE_RENDER_FILM_H
#define CIRCE_RENDER_FILM_H

#include "render/integrator.h"

#include <stdbool.h>
#include <stdint.h>

typedef struct film_pixel {
	double sum[3]; /* radiance, per channel */
	union {	       /* by the pixel's estimator (nets): */
		double sum_sq[3]; /* 0: the radiance squared */
		double sum_q[3];  /* 1: the radiance of the first q samples, q the largest power of two < n */
	};
	double albedo[3], normal[3], depth;
	uint32_t n;	   /* samples added (= the film's spp unless adaptive sampling stopped the pixel) */
	uint32_t latch;	   /* adaptive: the check (sample count) at which its own error fell below the
			    * threshold; 0: not yet */
	uint32_t stopped;  /* adaptive: 1 once the pixel takes no more samples */
	uint32_t nets;	   /* 1: the samples' prefixes of 2^k are nets (the Sobol sampler): the error is
			    * estimated from the prefixes (film_pixel_variance); 0: independent samples */
} film_pixel;

typedef struct film {
	int width, height;	/* the whole image */
	int x0, y0, x1, y1;	/* the region rendered, half-open */
	int ax0, ay0, ax1, ay1; /* the sampled rectangle: the region and its apron */
	film_pixel *acc, *work; /* (ax1 - ax0) * (ay1 - ay0) pixels, row-major from (ax0, ay0) */
	uint32_t spp;		/* samples in every pixel of acc that adaptive sampling did not stop */
	uint64_t dropped;	/* non-finite or negative samples dropped (counted as zero) */
} film;

/* The channels film_read produces. */
typedef enum film_channel {
	FILM_BEAUTY,  /* RGB mean radiance */
	FILM_ALBEDO,  /* RGB mean first-hit albedo */
	FILM_NORMAL,  /* XYZ mean first-hit normal (world space, not renormalised) */
	FILM_DEPTH,   /* 1 value: mean first-hit distance, 0 where nothing was hit */
	FILM_VARIANCE, /* RGB variance of the mean: sample variance / n (0 below 2 samples) */
	FILM_ERROR,    /* 1 value: the estimated relative error adaptive sampling tests (adaptive.h) */
	FILM_SAMPLES   /* 1 value: the pixel's sample count n */
} film_channel;

/* Whole image when x0 = y0 = x1 = y1 = 0. False for a region outside the image, an empty one,
 * or when memory runs out. */
bool film_init(film *f, int width, int height, int x0, int y0, int x1, int y1);
/* film_init with an apron of `apron` pixels (>= 0) around the region, clipped to the image. */
bool film_init_apron(film *f, int width, int height, int x0, int y0, int x1, int y1, int apron);
void film_free(film *f);
static inline int film_region_width(const film *f)
{
	return f->x1 - f->x0;
}
static inline int film_region_height(const film *f)
{
	return f->y1 - f->y0;
}
static inline int film_sampled_width(const film *f)
{
	return f->ax1 - f->ax0;
}
/* The accumulator of image pixel (x, y), which must lie in the sampled rectangle. */
static inline film_pixel *film_at(film_pixel *buf, const film *f, int x, int y)
{
	return &buf[(size_t)(y - f->ay0) * (size_t)film_sampled_width(f) + (size_t)(x - f->ax0)];
}
static inline bool film_in_region(const film *f, int x, int y)
{
	return x >= f->x0 && x < f->x1 && y >= f->y0 && y < f->y1;
}
/* 3 for RGB/XYZ channels, 1 for depth, error and samples. */
int film_channel_components(film_channel ch);
/* Fills out (region width * height * components floats, row-major from (x0, y0)) from acc. */
void film_read(const film *f, film_channel ch, float *out);
/* Adds one sample to a pixel accumulator (and counts it in n); returns false, adding nothing, when
 * the radiance is non-finite or negative (unless signed_radiance: the scene's negative lights,
 * render_scene.light_sign), or an AOV non-finite (the caller then adds a zero sample). The beauty's
 * read-out is the mean clamped at 0. */
bool film_pixel_add(film_pixel *p, const render_sample *s, bool signed_radiance);
/* The variance of the pixel's mean in channel k (0..2); 0 below 2 samples. Independent samples
 * (nets 0): the sample variance / n. A sampler whose first 2^k samples are a net for every k
 * (nets 1: sampler.h's Sobol): its mean converges faster than the sample variance says (it
 * overestimates the error 4 to 6 times at 16 to 64 samples, bench/README.md), and the variance
 * of the mean I_n is estimated instead from the mean A_q of the first q samples, q the largest
 * power of two below n: (I_n - A_q)^2 q / (n - q), unbiased for independent samples (I_n - A_q
 * = (n - q) / n (B - A_q), B the mean of the others) and, for a sequence of nets, a comparison
 * of two well-stratified sets of about the same size, as Cycles compares the image with its half
 * of the samples (kernel/film/adaptive_sampling.h). One difference per channel: noisy per pixel,
 * unbiased over many. */
double film_pixel_variance(const film_pixel *p, int k);
/* The pixel's estimated relative error: the standard error of its mean (the RMS over R, G, B of
 * sqrt(film_pixel_variance)) over its brightness L (the mean of R, G, B), where below L = 1 the
 * divisor is sqrt(L) instead, as Cycles' adaptive sampling normalises it (kernel/film/
 * adaptive_sampling.h: dark pixels are judged as they look after a display's gamma, not by their
 * relative error, which would spend most samples on the darkest). 0 for a pixel of no variance,
 * +inf below 2 samples. */
double film_pixel_error(const film_pixel *p);
/* Commits a finished pass: work becomes acc and now holds spp samples per pixel. */
void film_commit(film *f, uint32_t spp);

#endif
