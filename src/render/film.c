/* film.c - accumulation and read-out (film.h). */
#include "render/film.h"

#include "base/mem.h"

#include <assert.h>
#include <math.h>
#include <string.h>

bool film_init(film *f, int width, int height, int x0, int y0, int x1, int y1)
{
	return film_init_apron(f, width, height, x0, y0, x1, y1, 0);
}

bool film_init_apron(film *f, int width, int height, int x0, int y0, int x1, int y1, int apron)
{
	memset(f, 0, sizeof *f);
	if (x0 == 0 && y0 == 0 && x1 == 0 && y1 == 0) {
		x1 = width;
		y1 = height;
	}
	if (width <= 0 || height <= 0 || x0 < 0 || y0 < 0 || x1 > width || y1 > height || x0 >= x1 ||
	    y0 >= y1 || apron < 0)
		return false;
	f->ax0 = x0 - apron > 0 ? x0 - apron : 0;
	f->ay0 = y0 - apron > 0 ? y0 - apron : 0;
	f->ax1 = x1 + apron < width ? x1 + apron : width;
	f->ay1 = y1 + apron < height ? y1 + apron : height;
	size_t n = (size_t)(f->ax1 - f->ax0) * (size_t)(f->ay1 - f->ay0);
	f->acc = mem_calloc(n, sizeof *f->acc);
	f->work = mem_calloc(n, sizeof *f->work);
	if (!f->acc || !f->work) {
		film_free(f);
		return false;
	}
	f->width = width;
	f->height = height;
	f->x0 = x0;
	f->y0 = y0;
	f->x1 = x1;
	f->y1 = y1;
	return true;
}

void film_free(film *f)
{
	mem_free(f->acc);
	mem_free(f->work);
	memset(f, 0, sizeof *f);
}

int film_channel_components(film_channel ch)
{
	return ch == FILM_DEPTH || ch == FILM_ERROR || ch == FILM_SAMPLES ? 1 : 3;
}

bool film_pixel_add(film_pixel *p, const render_sample *s, bool signed_radiance)
{
	vec3 c = s->radiance;
	bool ok = v3_is_finite(c) && (signed_radiance || (c.x >= 0.0f && c.y >= 0.0f && c.z >= 0.0f)) &&
		  v3_is_finite(s->albedo) && v3_is_finite(s->normal) && isfinite(s->depth);
	if (!ok)
		return false;
	const float rgb[3] = {c.x, c.y, c.z}, alb[3] = {s->albedo.x, s->albedo.y, s->albedo.z},
		    nrm[3] = {s->normal.x, s->normal.y, s->normal.z};
	bool pow2 = p->n && !(p->n & (p->n - 1u)); /* the first n samples are the prefix q from now on */
	for (int k = 0; k < 3; k++) {
		if (!p->nets)
			p->sum_sq[k] += (double)rgb[k] * rgb[k];
		else if (pow2)
			p->sum_q[k] = p->sum[k];
		p->sum[k] += rgb[k];
		p->albedo[k] += alb[k];
		p->normal[k] += nrm[k];
	}
	p->depth += s->depth;
	p->n++;
	return true;
}

double film_pixel_variance(const film_pixel *p, int k)
{
	if (p->n < 2)
		return 0.0;
	double ns = p->n, mean = p->sum[k] * (1.0 / ns); /* as the mean is read: the same rounding */
	if (p->nets) {
		uint32_t q = 1u << (31 - __builtin_clz(p->n - 1u)); /* the largest power of two < n */
		double d = mean - p->sum_q[k] / (double)q;
		return d * d * (double)q / (ns - (double)q);
	}
	return fmax(0.0, (p->sum_sq[k] - ns * mean * mean) / (ns - 1.0)) / ns;
}

double film_pixel_error(const film_pixel *p)
{
	if (p->n < 2)
		return INFINITY;
	double var = (film_pixel_variance(p, 0) + film_pixel_variance(p, 1) + film_pixel_variance(p, 2)) / 3.0;
	if (!(var > 0.0))
		return 0.0;
	double lum = fabs(p->sum[0] + p->sum[1] + p->sum[2]) / (3.0 * p->n); /* signed: negative lights */
	return sqrt(var) / (lum >= 1.0 ? lum : sqrt(lum));
}

void film_commit(film *f, uint32_t spp)
{
	assert(spp > f->spp); /* a pass adds samples */
	film_pixel *t = f->acc;
	f->acc = f->work;
	f->work = t;
	f->spp = spp;
}

/* One value of a pixel's channel ch, component k. */
static float channel_value(const film_pixel *p, film_channel ch, int k)
{
	double inv = p->n ? 1.0 / p->n : 0.0;
	switch (ch) {
	case FILM_BEAUTY: /* at least 0: a negative light's samples (render_scene.light_sign) may sum below */
		return (float)fmax(0.0, p->sum[k] * inv);
	case FILM_ALBEDO:
		return (float)(p->albedo[k] * inv);
	case FILM_NORMAL:
		return (float)(p->normal[k] * inv);
	case FILM_VARIANCE:
		return (float)film_pixel_variance(p, k);
	case FILM_DEPTH:
		return (float)(p->depth * inv);
	case FILM_ERROR: {
		/* Below 2 samples nothing is known: written as a large finite value, no Inf in a file. */
		double e = film_pixel_error(p);
		return isfinite(e) && e < 1e30 ? (float)e : 1e30f;
	}
	case FILM_SAMPLES:
		return (float)p->n;
	}
	return 0.0f;
}

void film_read(const film *f, film_channel ch, float *out)
{
	int comps = film_channel_components(ch), rw = film_region_width(f);
	for (int y = f->y0; y < f->y1; y++)
		for (int x = f->x0; x < f->x1; x++) {
			const film_pixel *p = film_at(f->acc, f, x, y);
			size_t i = (size_t)(y - f->y0) * (size_t)rw + (size_t)(x - f->x0);
			for (int k = 0; k < comps; k++)
				out[(size_t)comps * i + (size_t)k] = channel_value(p, ch, k);
		}
}
