/* adaptive.c - the check points, the latch-and-neighbours rule and the noise summary (adaptive.h). */
#include "render/adaptive.h"

#include <assert.h>
#include <math.h>

uint32_t adaptive_auto_min_spp(double threshold)
{
	assert(threshold > 0.0);
	double m = ceil(16.0 / pow(threshold, 0.3));
	return m < 4.0 ? 4u : m > 1e9 ? 1000000000u : (uint32_t)m;
}

uint32_t adaptive_first_check(const adaptive_params *a)
{
	return a->min_spp ? a->min_spp : adaptive_auto_min_spp(a->threshold);
}

bool adaptive_is_check(const adaptive_params *a, uint32_t count)
{
	uint32_t first = adaptive_first_check(a);
	return count >= first && (count - first) % ADAPTIVE_STEP == 0;
}

uint32_t adaptive_next_check(const adaptive_params *a, uint32_t count)
{
	uint32_t first = adaptive_first_check(a);
	if (count < first)
		return first;
	uint64_t next = first + ((uint64_t)(count - first) / ADAPTIVE_STEP + 1) * ADAPTIVE_STEP;
	return next > UINT32_MAX ? UINT32_MAX : (uint32_t)next;
}

bool adaptive_film_ok(const film *f)
{
	int a = ADAPTIVE_APRON;
	return f->ax0 <= (f->x0 - a > 0 ? f->x0 - a : 0) && f->ay0 <= (f->y0 - a > 0 ? f->y0 - a : 0) &&
	       f->ax1 >= (f->x1 + a < f->width ? f->x1 + a : f->width) &&
	       f->ay1 >= (f->y1 + a < f->height ? f->y1 + a : f->height);
}

/* Whether pixel (x, y) and its neighbours inside the image (all in the sampled rectangle) are
 * latched. */
static bool neighbourhood_latched(const film *f, int x, int y)
{
	for (int dy = -1; dy <= 1; dy++)
		for (int dx = -1; dx <= 1; dx++) {
			int qx = x + dx, qy = y + dy;
			if (qx < 0 || qy < 0 || qx >= f->width || qy >= f->height)
				continue;
			assert(qx >= f->ax0 && qx < f->ax1 && qy >= f->ay0 && qy < f->ay1);
			if (!film_at(f->acc, f, qx, qy)->latch)
				return false;
		}
	return true;
}

size_t adaptive_check(film *f, const adaptive_params *a, uint32_t count)
{
	assert(a->threshold > 0.0 && adaptive_film_ok(f));
	/* First every latch, then the rule reads them: no pixel sees a half-done check. */
	for (int y = f->ay0; y < f->ay1; y++)
		for (int x = f->ax0; x < f->ax1; x++) {
			film_pixel *p = film_at(f->acc, f, x, y);
			if (p->stopped || p->latch)
				continue;
			assert(p->n == count); /* not latched: it sampled every pass */
			if (film_pixel_error(p) < a->threshold)
				p->latch = count;
		}
	size_t active = 0;
	for (int y = f->ay0; y < f->ay1; y++)
		for (int x = f->ax0; x < f->ax1; x++) {
			film_pixel *p = film_at(f->acc, f, x, y);
			if (!p->stopped)
				/* The apron only lends its latches: it samples until its own. */
				p->stopped =
				    film_in_region(f, x, y) ? neighbourhood_latched(f, x, y) : p->latch != 0;
			active += !p->stopped;
		}
	return active;
}

void adaptive_summarise(const film *f, adaptive_summary *out)
{
	double var = 0.0, sum = 0.0, err = 0.0, spp = 0.0;
	size_t n_err = 0, npix = (size_t)film_region_width(f) * (size_t)film_region_height(f);
	uint32_t lo = UINT32_MAX, hi = 0;
	for (int y = f->y0; y < f->y1; y++)
		for (int x = f->x0; x < f->x1; x++) {
			const film_pixel *p = film_at(f->acc, f, x, y);
			for (int k = 0; k < 3 && p->n; k++)
				sum += p->sum[k] / p->n;
			for (int k = 0; k < 3; k++)
				var += film_pixel_variance(p, k);
			double pe = film_pixel_error(p);
			if (isfinite(pe))
				err += pe, n_err++;
			spp += p->n;
			lo = p->n < lo ? p->n : lo;
			hi = p->n > hi ? p->n : hi;
		}
	double mean = sum / (3.0 * (double)npix), mse = var / (3.0 * (double)npix);
	*out = (adaptive_summary){.nmse = mean > 0.0 ? mse / (mean * mean) : 0.0,
				  .mean_error = n_err ? err / (double)n_err : 0.0,
				  .mean_spp = spp / (double)npix,
				  .min_spp = lo,
				  .max_spp = hi};
}
