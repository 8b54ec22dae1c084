/* film.c - accumulation and read-out (film.h). */
#include "render/film.h"

#include "base/mem.h"

#include <assert.h>
#include <string.h>

bool film_init(film *f, int width, int height, int x0, int y0, int x1, int y1)
{
	memset(f, 0, sizeof *f);
	if (x0 == 0 && y0 == 0 && x1 == 0 && y1 == 0) {
		x1 = width;
		y1 = height;
	}
	if (width <= 0 || height <= 0 || x0 < 0 || y0 < 0 || x1 > width || y1 > height || x0 >= x1 ||
	    y0 >= y1)
		return false;
	size_t n = (size_t)(x1 - x0) * (size_t)(y1 - y0);
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
	return ch == FILM_DEPTH ? 1 : 3;
}

bool film_pixel_add(film_pixel *p, const render_sample *s)
{
	vec3 c = s->radiance;
	bool ok = v3_is_finite(c) && c.x >= 0.0f && c.y >= 0.0f && c.z >= 0.0f && v3_is_finite(s->albedo) &&
		  v3_is_finite(s->normal) && isfinite(s->depth);
	if (!ok)
		return false;
	const float rgb[3] = {c.x, c.y, c.z}, alb[3] = {s->albedo.x, s->albedo.y, s->albedo.z},
		    nrm[3] = {s->normal.x, s->normal.y, s->normal.z};
	for (int k = 0; k < 3; k++) {
		p->sum[k] += rgb[k];
		p->sum_sq[k] += (double)rgb[k] * rgb[k];
		p->albedo[k] += alb[k];
		p->normal[k] += nrm[k];
	}
	p->depth += s->depth;
	return true;
}

void film_commit(film *f, uint32_t spp)
{
	assert(spp > f->spp); /* a pass adds samples */
	film_pixel *t = f->acc;
	f->acc = f->work;
	f->work = t;
	f->spp = spp;
}

void film_read(const film *f, film_channel ch, float *out)
{
	size_t n = (size_t)film_region_width(f) * (size_t)film_region_height(f);
	double inv = f->spp ? 1.0 / f->spp : 0.0, ns = f->spp;
	for (size_t i = 0; i < n; i++) {
		const film_pixel *p = &f->acc[i];
		for (int k = 0; k < 3; k++) {
			switch (ch) {
			case FILM_BEAUTY:
				out[3 * i + k] = (float)(p->sum[k] * inv);
				break;
			case FILM_ALBEDO:
				out[3 * i + k] = (float)(p->albedo[k] * inv);
				break;
			case FILM_NORMAL:
				out[3 * i + k] = (float)(p->normal[k] * inv);
				break;
			case FILM_VARIANCE: {
				double var = 0.0;
				if (f->spp > 1) {
					double mean = p->sum[k] * inv;
					var = fmax(0.0, (p->sum_sq[k] - ns * mean * mean) / (ns - 1.0)) / ns;
				}
				out[3 * i + k] = (float)var;
				break;
			}
			case FILM_DEPTH:
				if (k == 0)
					out[i] = (float)(p->depth * inv);
				break;
			}
		}
	}
}
