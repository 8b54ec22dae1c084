/* film.h - the pixel accumulators of a render: beauty and the AOVs (albedo, normal, depth,
 * variance) in double, for the region [x0,x1) x [y0,y1) of a width x height image (the whole image
 * when no region is given). Pixel coordinates are always the whole image's, so a region's pixels
 * are bit-identical to the same pixels of a whole render.
 * Two buffers: `acc` holds the committed state, every pixel with exactly `spp` samples; a pass
 * writes `acc + its samples` into `work`, and committing swaps them, so an interrupted pass is
 * discarded without touching `acc`. Each pixel's samples are added one by one in sample order
 * whatever the passes were, which makes the sums independent of threads, tiles and pass sizes.
 * Memory: 2 x 104 bytes per pixel. Reading (film_read) is only safe between passes. */
#ifndef CIRCE_RENDER_FILM_H
#define CIRCE_RENDER_FILM_H

#include "render/integrator.h"

#include <stdbool.h>
#include <stdint.h>

typedef struct film_pixel {
	double sum[3], sum_sq[3]; /* radiance and its square, per channel */
	double albedo[3], normal[3], depth;
} film_pixel;

typedef struct film {
	int width, height;	/* the whole image */
	int x0, y0, x1, y1;	/* the region rendered, half-open */
	film_pixel *acc, *work; /* (x1 - x0) * (y1 - y0) pixels, row-major from (x0, y0) */
	uint32_t spp;		/* samples in every pixel of acc */
	uint64_t dropped;	/* non-finite or negative samples dropped (counted as zero) */
} film;

/* The channels film_read produces. */
typedef enum film_channel {
	FILM_BEAUTY,  /* RGB mean radiance */
	FILM_ALBEDO,  /* RGB mean first-hit albedo */
	FILM_NORMAL,  /* XYZ mean first-hit normal (world space, not renormalised) */
	FILM_DEPTH,   /* 1 value: mean first-hit distance, 0 where nothing was hit */
	FILM_VARIANCE /* RGB variance of the mean: sample variance / spp (0 below 2 samples) */
} film_channel;

/* Whole image when x0 = y0 = x1 = y1 = 0. False for a region outside the image, an empty one,
 * or when memory runs out. */
bool film_init(film *f, int width, int height, int x0, int y0, int x1, int y1);
void film_free(film *f);
static inline int film_region_width(const film *f)
{
	return f->x1 - f->x0;
}
static inline int film_region_height(const film *f)
{
	return f->y1 - f->y0;
}
/* 3 for RGB/XYZ channels, 1 for depth. */
int film_channel_components(film_channel ch);
/* Fills out (region width * height * components floats, row-major from (x0, y0)) from acc. */
void film_read(const film *f, film_channel ch, float *out);
/* Adds one sample to a pixel accumulator; returns false (and adds a zero sample) when the
 * radiance is non-finite or negative, or an AOV non-finite. */
bool film_pixel_add(film_pixel *p, const render_sample *s);
/* Commits a finished pass: work becomes acc and now holds spp samples per pixel. */
void film_commit(film *f, uint32_t spp);

#endif
