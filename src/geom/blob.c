/* blob.c - POV-Ray's blob as a mesh: its field (core/shape/blob.cpp: each component adds
 * s (1 - d^2 / r^2)^2 inside its radius; a cylinder measures d from its axis, with hemispheres at
 * its ends) less the threshold, polygonised by field.c (marching tetrahedra on a grid the
 * components are splatted into, vertices moved onto the iso-surface by Newton steps), then refined
 * where it is still farther than the tolerance (field.c's shape_field_refine). */
#include "geom/shape.h"

#include "base/mem.h"

#include <math.h>
#include <string.h>

/* The most grid points a blob may sample (floats: 64 MiB); past it the grid is coarsened. */
#define BLOB_MAX_GRID_POINTS (1u << 24)
/* Rounds of refinement where the grid misses the tolerance: each halves the edges there, about a
 * quarter of the distance, so six take a crease thousands of times the tolerance off within it. */
#define BLOB_REFINE_ROUNDS 6

/* The field of component c at p, and its gradient when g is not NULL (added to *g). */
static double comp_field(const shape_blob_comp *c, dvec3 p, dvec3 *g)
{
	dvec3 q = c->has_xf ? xform_inv_point(&c->xf, p) : p;
	double r2 = c->radius * c->radius;
	dvec3 rel = d3_sub(q, c->a);
	if (c->cylinder) {
		dvec3 ax = d3_sub(c->b, c->a);
		double len = d3_length(ax);
		dvec3 u = d3_scale(ax, 1.0 / len);
		double z = d3_dot(rel, u);
		if (z > len)
			rel = d3_sub(q, c->b);
		else if (z >= 0)
			rel = d3_sub(rel, d3_scale(u, z));
	}
	double d2 = d3_dot(rel, rel);
	if (d2 >= r2)
		return 0;
	double w = 1 - d2 / r2;
	if (g) {
		dvec3 gq = d3_scale(rel, -4 * c->strength * w / r2);
		*g = d3_add(*g, c->has_xf ? xform_normal(&c->xf, gq) : gq);
	}
	return c->strength * w * w;
}

double shape_blob_field(const shape_desc *s, dvec3 p)
{
	double f = 0;
	for (uint32_t i = 0; i < s->n_comps; i++)
		f += comp_field(&s->comps[i], p, NULL);
	return f;
}

uint32_t shape_blob_part_at(const shape_desc *s, dvec3 p)
{
	double best = 0;
	uint32_t part = 0;
	for (uint32_t i = 0; i < s->n_comps; i++) {
		double f = fabs(comp_field(&s->comps[i], p, NULL));
		if (f > best)
			best = f, part = s->comps[i].part;
	}
	return part;
}

static double field_grad(const shape_desc *s, dvec3 p, dvec3 *g)
{
	*g = d3(0, 0, 0);
	double f = 0;
	for (uint32_t i = 0; i < s->n_comps; i++)
		f += comp_field(&s->comps[i], p, g);
	return f;
}

/* Adds each component's field to the grid points inside its bounding box. */
static void splat(const void *ctx, dvec3 glo, double h, uint32_t nx, uint32_t ny, uint32_t nz, float *f)
{
	const shape_desc *s = ctx;
	for (size_t i = 0; i < (size_t)nx * ny * nz; i++)
		f[i] = (float)-s->threshold;
	for (uint32_t c = 0; c < s->n_comps; c++) {
		shape_desc one = *s;
		shape_blob_comp pos = s->comps[c];
		pos.strength = 1; /* shape_bounds skips negative components: bound this one too */
		one.comps = &pos, one.n_comps = 1;
		dvec3 lo, hi;
		shape_bounds(&one, &lo, &hi);
		pos.strength = s->comps[c].strength;
		int i0 = (int)floor((lo.x - glo.x) / h), i1 = (int)ceil((hi.x - glo.x) / h);
		int j0 = (int)floor((lo.y - glo.y) / h), j1 = (int)ceil((hi.y - glo.y) / h);
		int k0 = (int)floor((lo.z - glo.z) / h), k1 = (int)ceil((hi.z - glo.z) / h);
		i0 = i0 < 0 ? 0 : i0, j0 = j0 < 0 ? 0 : j0, k0 = k0 < 0 ? 0 : k0;
		i1 = i1 >= (int)nx ? (int)nx - 1 : i1, j1 = j1 >= (int)ny ? (int)ny - 1 : j1;
		k1 = k1 >= (int)nz ? (int)nz - 1 : k1;
		for (int k = k0; k <= k1; k++)
			for (int j = j0; j <= j1; j++)
				for (int i = i0; i <= i1; i++) {
					dvec3 p = d3(glo.x + i * h, glo.y + j * h, glo.z + k * h);
					f[((size_t)k * ny + (size_t)j) * nx + (size_t)i] += (float)comp_field(&pos, p, NULL);
				}
	}
}

/* The grid's step: triangles of edge h on a surface curved at radius r_c stand h^2 / (8 r_c) off
 * it (Newton puts their corners on it); a cell at most r_c / 3 keeps thin parts. */
static double blob_step(const shape_desc *s, double tol, double *rc_out)
{
	double rc = INFINITY;
	for (uint32_t i = 0; i < s->n_comps; i++)
		if (s->comps[i].strength > 0) {
			double r = s->comps[i].radius;
			if (s->comps[i].has_xf) { /* the smallest scale of its transform */
				double m = INFINITY;
				for (int a = 0; a < 3; a++) {
					dvec3 e = d3(a == 0, a == 1, a == 2);
					m = fmin(m, d3_length(xform_vector(&s->comps[i].xf, e)));
				}
				r *= m;
			}
			rc = fmin(rc, r);
		}
	*rc_out = rc;
	return fmin(sqrt(8 * tol * rc), rc / 3);
}

/* The blob's field less its threshold, and its gradient: field.c's view of it. */
static double blob_eval(const void *ctx, dvec3 p, dvec3 *g)
{
	const shape_desc *s = ctx;
	dvec3 gg;
	double f = field_grad(s, p, &gg) - s->threshold;
	if (g)
		*g = gg;
	return f;
}

bool shape_blob(const shape_desc *s, const shape_accuracy *acc, mesh *out, double *tol_out, diag *d, diag_loc loc)
{
	dvec3 lo, hi;
	shape_bounds(s, &lo, &hi);
	double rc, h0 = blob_step(s, acc->tol, &rc);
	dvec3 ext = d3_sub(hi, lo);
	double h = shape_field_fit_step(ext, h0, BLOB_MAX_GRID_POINTS);
	shape_field F = {.eval = blob_eval, .fill = splat, .ctx = s};
	shape_builder b;
	if (!shape_field_polygonise(&F, lo, hi, h, "blob", &b, d, loc))
		return false;
	/* Sharp creases (where negative components cut: the candle's rim) stand further off than the
	 * curvature rule says: the triangles that miss are split there, their new corners put on the
	 * surface, until all are within the tolerance; the distance reached is measured and
	 * reported, not assumed. */
	double got = b.failed ? 0 : shape_field_refine(&F, &b, acc->tol, BLOB_REFINE_ROUNDS, NULL);
	*tol_out = fmax(acc->tol, got);
	return sb_finish(&b, out, false, "blob", d, loc);
}
