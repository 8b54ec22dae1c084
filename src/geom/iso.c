/* iso.c - POV-Ray's isosurface as a mesh: inside where f(x, y, z) < threshold and inside the
 * container (POV-Ray's contained_by box or sphere), so the field field.c polygonises is
 * min(threshold - f, the signed distance into the container), positive inside: where the container
 * cuts the surface the mesh is closed by the container's face, unless `open`, where the triangles
 * on the container are dropped (POV-Ray's `open` shows no container surface). The function is a
 * black box: its gradient is taken by forward differences, the vertices are found on their grid
 * edges by regula falsi (no Newton step can leave the cell, whatever the function does), and the
 * distance the triangles reach is measured (|F| / |grad F| at their centres) and reported. The grid
 * is filled by field.c's octree: max_gradient (times ISO_GRADIENT_SAFETY) bounds how fast the
 * function changes, so blocks far from the surface are not sampled point by point. */
#include "geom/shape.h"

#include "base/mem.h"

#include <math.h>
#include <string.h>

/* The most grid points an isosurface may sample: each is a call of an interpreted function. */
#define ISO_MAX_GRID_POINTS (1u << 21)
/* The grid's octree trusts POV-Ray's max_gradient (default 1.1) with this margin: a block is left
 * unevaluated only where the function, changing at twice max_gradient, could not reach its
 * threshold within a cell of the block. */
#define ISO_GRADIENT_SAFETY 2.0

typedef struct iso_ctx {
	const shape_desc *s;
	double eps; /* the forward differences' step */
	bool failed; /* the function could not be evaluated somewhere */
	dvec3 failed_at;
	double max_grad; /* the largest |grad f| met at the vertices */
} iso_ctx;

/* threshold - f(p): positive inside; NaN where f cannot be evaluated or is not finite. */
static double iso_f(iso_ctx *c, dvec3 p)
{
	double xyz[3] = {p.x, p.y, p.z}, v;
	if (!c->s->fn(c->s->fn_ctx, xyz, &v)) {
		if (!c->failed)
			c->failed = true, c->failed_at = p;
		return NAN;
	}
	return isfinite(v) ? c->s->threshold - v : NAN;
}

/* The signed distance into the container: positive inside. */
static double container(const shape_desc *s, dvec3 p, dvec3 *g)
{
	if (s->contained_sphere) {
		dvec3 r = d3_sub(p, s->box_lo);
		double l = d3_length(r);
		if (g)
			*g = l > 0 ? d3_scale(r, -1 / l) : d3(0, -1, 0);
		return s->sphere_r - l;
	}
	double best = INFINITY;
	dvec3 bg = d3(0, 0, 0);
	const double lo[3] = {s->box_lo.x, s->box_lo.y, s->box_lo.z}, hi[3] = {s->box_hi.x, s->box_hi.y, s->box_hi.z};
	const double q[3] = {p.x, p.y, p.z};
	for (int a = 0; a < 3; a++) {
		double dl = q[a] - lo[a], dh = hi[a] - q[a];
		if (dl < best)
			best = dl, bg = d3(a == 0, a == 1, a == 2);
		if (dh < best)
			best = dh, bg = d3(-(a == 0), -(a == 1), -(a == 2));
	}
	if (g)
		*g = bg;
	return best;
}

/* The gradient of threshold - f at p, where it is fv, by forward differences (step 1e-3 of a cell:
 * first order is plenty for normals and distances, in three more calls of the function where
 * central ones took six). */
static void iso_grad(iso_ctx *c, dvec3 p, double fv, dvec3 *g)
{
	double e = c->eps, d[3];
	for (int a = 0; a < 3; a++) {
		dvec3 u = d3(a == 0 ? e : 0, a == 1 ? e : 0, a == 2 ? e : 0);
		d[a] = (iso_f(c, d3_add(p, u)) - fv) / e;
	}
	*g = d3(d[0], d[1], d[2]);
	if (!isfinite(d3_length(*g)))
		*g = d3(0, 0, 0);
}

/* threshold - f at p and its gradient (iso_grad). */
static double iso_eval_fn(iso_ctx *c, dvec3 p, dvec3 *g)
{
	double fv = iso_f(c, p);
	iso_grad(c, p, fv, g);
	return fv;
}

static double iso_eval(const void *ctx, dvec3 p, dvec3 *g)
{
	iso_ctx *c = (iso_ctx *)ctx; /* the failure flag and the gradient statistic are written */
	double cv = container(c->s, p, g);
	double fv = iso_f(c, p);
	if (isnan(fv))
		return g ? cv : -fabs(cv) - 1; /* outside where f fails; the container's gradient */
	if (cv < fv)
		return cv;
	if (g) {
		iso_grad(c, p, fv, g); /* f at p is a pure function's value: not called again */
		c->max_grad = fmax(c->max_grad, d3_length(*g));
	}
	return fv;
}

/* ---- the cache of grids (shape.h's shape_cache) ---- */

typedef struct iso_pass {
	shape_desc s; /* a copy: the caller's may be gone; its fn_ctx lives as long as the cache */
	double h;
	shape_builder b; /* the pass's mesh (after drop_cut); uv unused */
	double got, max_grad;
} iso_pass;

struct shape_cache {
	iso_pass *e;
	size_t n, cap;
	size_t bytes, max_bytes;
	size_t hits;
};

shape_cache *shape_cache_new(size_t max_bytes)
{
	shape_cache *c = mem_calloc(1, sizeof *c);
	if (c)
		c->max_bytes = max_bytes;
	return c;
}

void shape_cache_free(shape_cache *c)
{
	if (!c)
		return;
	for (size_t i = 0; i < c->n; i++)
		mem_free(c->e[i].b.pos), mem_free(c->e[i].b.nrm), mem_free(c->e[i].b.idx);
	mem_free(c->e);
	mem_free(c);
}

size_t shape_cache_hits(const shape_cache *c) { return c ? c->hits : 0; }
size_t shape_cache_kept(const shape_cache *c) { return c ? c->n : 0; }

static bool same_bits(const void *a, const void *b, size_t n) { return memcmp(a, b, n) == 0; }

/* Whether a and b are one isosurface for the polygoniser: everything a pass reads (the function,
 * threshold, container, open, max_gradient, region), doubles compared bit for bit. */
static bool iso_same(const shape_desc *a, const shape_desc *b)
{
	if (a->fn != b->fn || a->fn_same != b->fn_same || !a->fn_same)
		return false;
	if (a->fn_ctx != b->fn_ctx && !a->fn_same(a->fn_ctx, b->fn_ctx))
		return false;
	return same_bits(&a->threshold, &b->threshold, sizeof a->threshold) && a->contained_sphere == b->contained_sphere &&
	       same_bits(&a->box_lo, &b->box_lo, sizeof a->box_lo) && same_bits(&a->box_hi, &b->box_hi, sizeof a->box_hi) &&
	       same_bits(&a->sphere_r, &b->sphere_r, sizeof a->sphere_r) && a->open == b->open &&
	       same_bits(&a->max_gradient, &b->max_gradient, sizeof a->max_gradient) && a->has_region == b->has_region &&
	       (!a->has_region || (same_bits(&a->region_lo, &b->region_lo, sizeof a->region_lo) &&
				   same_bits(&a->region_hi, &b->region_hi, sizeof a->region_hi)));
}

static bool copy_builder(shape_builder *to, const shape_builder *from)
{
	sb_init(to);
	uint32_t nv = from->nv ? from->nv : 1, nt = from->nt ? from->nt : 1;
	to->pos = mem_alloc(nv, sizeof *to->pos), to->nrm = mem_alloc(nv, sizeof *to->nrm);
	to->uv = mem_calloc(nv, sizeof *to->uv), to->idx = mem_alloc(3 * (size_t)nt, sizeof *to->idx);
	if (!to->pos || !to->nrm || !to->uv || !to->idx) {
		sb_free(to);
		return false;
	}
	memcpy(to->pos, from->pos, from->nv * sizeof *to->pos);
	memcpy(to->nrm, from->nrm, from->nv * sizeof *to->nrm);
	memcpy(to->idx, from->idx, 3 * (size_t)from->nt * sizeof *to->idx);
	to->nv = to->cap_v = from->nv, to->nt = to->cap_t = from->nt;
	return true;
}

/* The pass of s at step h from the cache into b (initialised here), its distance and largest
 * gradient; false when it is not there (or memory runs out: then it is made again). */
static bool cache_take(shape_cache *c, const shape_desc *s, double h, shape_builder *b, double *got, double *max_grad)
{
	for (size_t i = 0; c && i < c->n; i++) {
		const iso_pass *e = &c->e[i];
		if (!same_bits(&e->h, &h, sizeof h) || !iso_same(&e->s, s))
			continue;
		if (!copy_builder(b, &e->b))
			return false;
		*got = e->got, *max_grad = e->max_grad;
		c->hits++;
		return true;
	}
	return false;
}

/* Keeps a copy of the pass (b, got, max_grad) of s at step h, when s may be cached and there is room. */
static void cache_keep(shape_cache *c, const shape_desc *s, double h, const shape_builder *b, double got, double max_grad)
{
	size_t bytes = (size_t)b->nv * (sizeof *b->pos + sizeof *b->nrm) + 3 * (size_t)b->nt * sizeof *b->idx;
	if (!c || !s->fn_same || b->failed || bytes > c->max_bytes - c->bytes)
		return;
	if (c->n == c->cap) {
		size_t cap = c->cap ? 2 * c->cap : 8;
		iso_pass *e = mem_realloc(c->e, cap, sizeof *e);
		if (!e)
			return;
		c->e = e, c->cap = cap;
	}
	iso_pass *e = &c->e[c->n];
	if (!copy_builder(&e->b, b))
		return;
	mem_free(e->b.uv), e->b.uv = NULL;
	e->s = *s, e->h = h, e->got = got, e->max_grad = max_grad;
	c->n++, c->bytes += bytes;
}

/* The rungs of the ladder of grid steps within an octave: 2^(k/8) / 2, k = 0 .. 7. */
static const double ISO_RUNGS[8] = {0.5, 0.5 * 1.0905077326652577, 0.5 * 1.1892071150027210, 0.5 * 1.2968395546510096,
				    0.5 * 1.4142135623730951, 0.5 * 1.5422108254079407, 0.5 * 1.6817928305074290,
				    0.5 * 1.8340080864093424};

/* A step h taken down to the ladder 2^(k/8), k an integer: at most 9 % finer than h (its
 * triangles no farther from the surface), and the same step for isosurfaces of one function whose
 * tolerances differ a little (isocacti's 750 rocks, each at its distance from the camera), so
 * that they share one grid through the cache. Exact: frexp and ldexp only change the exponent. */
static double ladder_step(double h)
{
	int e;
	double m = frexp(h, &e); /* [0.5, 1) */
	int k = 7;
	while (k > 0 && ISO_RUNGS[k] > m)
		k--;
	return ldexp(ISO_RUNGS[k], e);
}

/* The container's bound. */
static void iso_bounds(const shape_desc *s, dvec3 *lo, dvec3 *hi)
{
	if (s->contained_sphere) {
		dvec3 r = d3(s->sphere_r, s->sphere_r, s->sphere_r);
		*lo = d3_sub(s->box_lo, r), *hi = d3_add(s->box_lo, r);
	} else {
		*lo = s->box_lo, *hi = s->box_hi;
	}
}

/* Drops the triangles whose three corners lie on the container where it cuts (open), and the
 * vertices no triangle uses then. Returns the largest distance, to first order, of the open rim's
 * vertices (those left on the container) from the function's surface: the rim follows the grid. */
static double drop_cut(iso_ctx *c, shape_builder *b, double h)
{
	uint32_t *map = mem_alloc(b->nv ? b->nv : 1, sizeof *map);
	if (!map) {
		b->failed = true;
		return 0;
	}
	for (uint32_t i = 0; i < b->nv; i++) {
		dvec3 p = v3_to_d3(b->pos[i]);
		double cv = container(c->s, p, NULL), fv = iso_f(c, p);
		map[i] = fabs(cv) < 1e-3 * h && !(fv < cv - 1e-9); /* 1: on the cut */
	}
	uint32_t n = 0;
	for (uint32_t t = 0; t < b->nt; t++) {
		const uint32_t *i = &b->idx[3 * (size_t)t];
		if (map[i[0]] == 1 && map[i[1]] == 1 && map[i[2]] == 1)
			continue;
		memmove(&b->idx[3 * (size_t)n++], i, 3 * sizeof *i);
	}
	b->nt = n;
	mem_free(map);
	sb_compact(b);
	double rim = 0;
	for (uint32_t i = 0; i < b->nv; i++) {
		dvec3 p = v3_to_d3(b->pos[i]), g;
		double cv = container(c->s, p, NULL), fv = iso_eval_fn(c, p, &g), gl = d3_length(g);
		if (fabs(cv) < 1e-3 * h && gl > 0 && isfinite(fv / gl))
			rim = fmax(rim, fabs(fv) / gl);
	}
	return rim;
}

bool shape_isosurface_named(const shape_desc *s, const shape_accuracy *acc, const char *what, mesh *out, double *tol_out,
			    diag *d, diag_loc loc)
{
	dvec3 lo, hi;
	iso_bounds(s, &lo, &hi);
	dvec3 ext = d3_sub(hi, lo);
	double size = fmax(ext.x, fmax(ext.y, ext.z));
	if (!(size > 0)) {
		diag_error(d, loc, "the %s's container is empty", what);
		return false;
	}
	/* The blob's rule with a curvature radius of an eighth of the container: a step h gives
	 * triangles h^2 / (8 r_c) off a surface curved at r_c; then again (once, or max_passes - 1
	 * times) at the step the measured distance asks for, when it was missed and the grid allows it. */
	double rc = size / 8, h = fmin(sqrt(8 * acc->tol * rc), rc / 3);
	if (h > 0 && isfinite(h))
		h = ladder_step(h);
	iso_ctx c = {.s = s, .eps = 0};
	/* the workers' contexts (acc->threads), each written by its worker alone, merged into c */
	int workers = acc->threads > 1 ? acc->threads : 1;
	iso_ctx *wc = workers > 1 ? mem_alloc((size_t)workers, sizeof *wc) : NULL;
	const void **wp = wc ? mem_alloc((size_t)workers, sizeof *wp) : NULL;
	if (!wp)
		workers = 1;
	for (int k = 0; k < workers && wp; k++)
		wp[k] = &wc[k];
	/* the golden ratio's fraction of a cell: the box's faces fall between grid points (a grid
	 * point on the zero set would make degenerate triangles there) */
	/* The field, min(threshold - f, the container's distance), changes at most as fast as f or 1. */
	shape_field F = {.eval = iso_eval, .ctx = &c, .on_edges = true, .shift = 0.6180339887,
			 .has_region = s->has_region, .region_lo = s->region_lo, .region_hi = s->region_hi,
			 .lipschitz = s->max_gradient > 0 ? ISO_GRADIENT_SAFETY * fmax(s->max_gradient, 1.0) : 0.0,
			 .workers = workers, .worker_ctx = wp};
	shape_builder b;
	double got = 0;
	int passes = s->max_passes > 0 ? s->max_passes : 2;
	for (int pass = 0; pass < passes; pass++) {
		h = shape_field_fit_step(ext, h, ISO_MAX_GRID_POINTS);
		c.eps = 1e-3 * h;
		/* the pass's own largest gradient (the cache keeps it), then the passes' together */
		double grad_before = c.max_grad;
		c.max_grad = 0;
		if (!cache_take(acc->cache, s, h, &b, &got, &c.max_grad)) {
			for (int k = 0; k < workers && wc; k++)
				wc[k] = c;
			if (!shape_field_polygonise(&F, lo, hi, h, what, &b, d, loc)) {
				mem_free(wc), mem_free(wp);
				return false;
			}
			bool failed = c.failed;
			for (int k = 0; k < workers && wc; k++)
				failed |= wc[k].failed;
			if (failed && workers > 1) { /* again on one thread: the first point where it fails */
				sb_free(&b);
				F.workers = 1;
				if (!shape_field_polygonise(&F, lo, hi, h, what, &b, d, loc)) {
					mem_free(wc), mem_free(wp);
					return false;
				}
			}
			if (c.failed) {
				sb_free(&b);
				mem_free(wc), mem_free(wp);
				diag_error(d, loc, "the isosurface's function '%s' cannot be evaluated by circe at <%g, %g, %g>",
					   s->fn_name ? s->fn_name : "function", c.failed_at.x, c.failed_at.y, c.failed_at.z);
				return false;
			}
			double rim = 0;
			if (s->open && !b.failed)
				rim = drop_cut(&c, &b, h);
			got = b.failed ? 0 : fmax(rim, shape_field_error(&F, &b));
			/* the largest gradient the workers met (a maximum: the same whoever met it) */
			for (int k = 0; k < workers && wc; k++)
				c.max_grad = fmax(c.max_grad, wc[k].max_grad);
			cache_keep(acc->cache, s, h, &b, got, c.max_grad);
		}
		c.max_grad = fmax(grad_before, c.max_grad);
		if (b.failed || got <= 1.5 * acc->tol || pass == passes - 1)
			break;
		double h2 = fmax(h * sqrt(acc->tol / got), 0.5 * h);
		h2 = ladder_step(h2);
		if (shape_field_fit_step(ext, h2, ISO_MAX_GRID_POINTS) >= h)
			break; /* the grid cannot be finer */
		sb_free(&b);
		h = h2;
	}
	if (s->max_gradient > 0 && c.max_grad > 1.1 * s->max_gradient)
		diag_warning(d, loc,
			     "the isosurface's function has a gradient of %g, more than its max_gradient %g (POV-Ray "
			     "would miss parts of the surface; circe trusts twice max_gradient where it skips empty space)",
			     c.max_grad, s->max_gradient);
	mem_free(wc), mem_free(wp);
	*tol_out = fmax(acc->tol, got);
	return sb_finish(&b, out, false, what, d, loc);
}

bool shape_isosurface(const shape_desc *s, const shape_accuracy *acc, mesh *out, double *tol_out, diag *d, diag_loc loc)
{
	return shape_isosurface_named(s, acc, "isosurface", out, tol_out, d, loc);
}
