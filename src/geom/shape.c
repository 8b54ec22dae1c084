/* shape.c - what POV-Ray's shapes (shape.h) share: the growing mesh, bounds, the dispatch to
 * each tessellator and the IR dump. */
#include "geom/shape.h"

#include "base/mem.h"

#include <math.h>
#include <string.h>

void sb_init(shape_builder *b) { memset(b, 0, sizeof *b); }

void sb_free(shape_builder *b)
{
	mem_free(b->pos), mem_free(b->nrm), mem_free(b->uv), mem_free(b->idx);
	sb_init(b);
}

/* Grows the builder's arrays to hold one more vertex (triangle); false when it cannot. */
static bool grow_v(shape_builder *b)
{
	if (b->nv < b->cap_v)
		return true;
	uint32_t cap = b->cap_v ? 2 * b->cap_v : 256;
	if (cap < b->cap_v || cap > 3u * SHAPE_MAX_TRIANGLES) {
		b->failed = true;
		return false;
	}
	vec3 *p = mem_realloc(b->pos, cap, sizeof *p);
	if (p)
		b->pos = p;
	vec3 *n = p ? mem_realloc(b->nrm, cap, sizeof *n) : NULL;
	if (n)
		b->nrm = n;
	vec2 *u = n ? mem_realloc(b->uv, cap, sizeof *u) : NULL;
	if (!u) {
		b->failed = true;
		return false;
	}
	b->uv = u;
	b->cap_v = cap;
	return true;
}

uint32_t sb_vertex(shape_builder *b, dvec3 p, dvec3 n, double u, double v)
{
	if (b->failed || !grow_v(b))
		return 0;
	b->pos[b->nv] = d3_to_v3(p);
	double l = d3_length(n);
	b->nrm[b->nv] = l > 0 ? d3_to_v3(d3_scale(n, 1.0 / l)) : v3(0, 1, 0);
	b->uv[b->nv] = v2((float)u, (float)v);
	return b->nv++;
}

void sb_tri(shape_builder *b, uint32_t a, uint32_t c1, uint32_t c2, dvec3 want)
{
	if (b->failed)
		return;
	if (b->nt >= SHAPE_MAX_TRIANGLES) {
		b->failed = true;
		return;
	}
	if (b->nt == b->cap_t) {
		uint32_t cap = b->cap_t ? 2 * b->cap_t : 256;
		uint32_t *i = mem_realloc(b->idx, 3 * (size_t)cap, sizeof *i);
		if (!i) {
			b->failed = true;
			return;
		}
		b->idx = i, b->cap_t = cap;
	}
	dvec3 pa = v3_to_d3(b->pos[a]), pb = v3_to_d3(b->pos[c1]), pc = v3_to_d3(b->pos[c2]);
	dvec3 g = d3_cross(d3_sub(pb, pa), d3_sub(pc, pa));
	if (d3_dot(g, want) < 0) {
		uint32_t t = c1;
		c1 = c2, c2 = t;
	}
	uint32_t *o = &b->idx[3 * (size_t)b->nt++];
	o[0] = a, o[1] = c1, o[2] = c2;
}

void sb_compact(shape_builder *b)
{
	if (b->failed || !b->nv)
		return;
	uint32_t *map = mem_alloc(b->nv, sizeof *map);
	if (!map) {
		b->failed = true;
		return;
	}
	for (uint32_t i = 0; i < b->nv; i++)
		map[i] = UINT32_MAX;
	for (size_t k = 0; k < 3 * (size_t)b->nt; k++)
		map[b->idx[k]] = 0;
	uint32_t nv = 0;
	for (uint32_t i = 0; i < b->nv; i++)
		if (map[i] == 0) {
			b->pos[nv] = b->pos[i], b->nrm[nv] = b->nrm[i], b->uv[nv] = b->uv[i];
			map[i] = nv++;
		}
	for (size_t k = 0; k < 3 * (size_t)b->nt; k++)
		b->idx[k] = map[b->idx[k]];
	b->nv = nv;
	mem_free(map);
}

bool sb_finish(shape_builder *b, mesh *out, bool uvs, const char *what, diag *d, diag_loc loc)
{
	if (b->nt >= SHAPE_MAX_TRIANGLES) {
		diag_error(d, loc, "the %s would make more than %u triangles (the limit of one shape)", what,
			   SHAPE_MAX_TRIANGLES);
		sb_free(b);
		return false;
	}
	if (b->failed || !mesh_alloc(out, b->nv, b->nt, true, uvs, false)) {
		diag_error(d, loc, "out of memory while tessellating the %s", what);
		sb_free(b);
		return false;
	}
	memcpy(out->positions, b->pos, b->nv * sizeof *b->pos);
	memcpy(out->normals, b->nrm, b->nv * sizeof *b->nrm);
	if (uvs)
		memcpy(out->uvs, b->uv, b->nv * sizeof *b->uv);
	memcpy(out->indices, b->idx, 3 * (size_t)b->nt * sizeof *b->idx);
	sb_free(b);
	return true;
}

uint32_t shape_cubic_steps(const double A[2], const double B[2], double tol)
{
	/* P''(t) = 6 A t + 2 B is linear: its largest length is at t = 0 or 1. */
	double m0 = hypot(2 * B[0], 2 * B[1]), m1 = hypot(6 * A[0] + 2 * B[0], 6 * A[1] + 2 * B[1]);
	double m = fmax(m0, m1);
	double n = m > 0 ? ceil(sqrt(m / (8.0 * tol))) : 1.0;
	return n < 1 ? 1 : n > 4096 ? 4096 : (uint32_t)n;
}

void shape_bounds(const shape_desc *s, dvec3 *lo, dvec3 *hi)
{
	*lo = d3(INFINITY, INFINITY, INFINITY), *hi = d3(-INFINITY, -INFINITY, -INFINITY);
	switch (s->kind) {
	case SHAPE2_LATHE:
	case SHAPE2_SOR: /* the control points bound the curve closely enough to size the accuracy */
		for (uint32_t i = 0; i < s->n_pts; i++) {
			double r = fabs(s->pts[2 * i]), y = s->pts[2 * i + 1];
			*lo = d3(fmin(lo->x, -r), fmin(lo->y, y), fmin(lo->z, -r));
			*hi = d3(fmax(hi->x, r), fmax(hi->y, y), fmax(hi->z, r));
		}
		break;
	case SHAPE2_PRISM: {
		/* a conic sweep scales the outline by the height: its extremes are at h1 or h2 */
		double k = s->conic ? fmax(fabs(s->h1), fabs(s->h2)) : 1.0;
		for (uint32_t i = 0; i < s->n_pts; i++) {
			double x = s->pts[2 * i] * k, z = s->pts[2 * i + 1] * k;
			double xl = s->conic ? -fabs(x) : x, zl = s->conic ? -fabs(z) : z;
			*lo = d3(fmin(lo->x, xl), s->h1, fmin(lo->z, zl));
			*hi = d3(fmax(hi->x, fabs(x) * s->conic + x * !s->conic), s->h2,
				 fmax(hi->z, fabs(z) * s->conic + z * !s->conic));
		}
		break;
	}
	case SHAPE2_SPHERE_SWEEP:
		for (uint32_t i = 0; i < s->n_pts; i++) {
			const double *q = &s->pts[4 * i];
			double r = fabs(q[3]);
			*lo = d3(fmin(lo->x, q[0] - r), fmin(lo->y, q[1] - r), fmin(lo->z, q[2] - r));
			*hi = d3(fmax(hi->x, q[0] + r), fmax(hi->y, q[1] + r), fmax(hi->z, q[2] + r));
		}
		break;
	case SHAPE2_BLOB:
		for (uint32_t i = 0; i < s->n_comps; i++) {
			const shape_blob_comp *c = &s->comps[i];
			if (c->strength <= 0)
				continue;
			for (int e = 0; e < (c->cylinder ? 2 : 1); e++) {
				dvec3 p = e ? c->b : c->a;
				double r = c->radius;
				if (c->has_xf) { /* the corners of the component's box, transformed */
					for (int k = 0; k < 8; k++) {
						dvec3 q = d3(p.x + (k & 1 ? r : -r), p.y + (k & 2 ? r : -r), p.z + (k & 4 ? r : -r));
						q = xform_point(&c->xf, q);
						*lo = d3(fmin(lo->x, q.x), fmin(lo->y, q.y), fmin(lo->z, q.z));
						*hi = d3(fmax(hi->x, q.x), fmax(hi->y, q.y), fmax(hi->z, q.z));
					}
					continue;
				}
				*lo = d3(fmin(lo->x, p.x - r), fmin(lo->y, p.y - r), fmin(lo->z, p.z - r));
				*hi = d3(fmax(hi->x, p.x + r), fmax(hi->y, p.y + r), fmax(hi->z, p.z + r));
			}
		}
		break;
	case SHAPE2_BICUBIC: /* a Bezier patch lies in the hull of its control points */
		for (uint32_t i = 0; i < 16; i++) {
			const double *q = &s->pts[3 * i];
			*lo = d3(fmin(lo->x, q[0]), fmin(lo->y, q[1]), fmin(lo->z, q[2]));
			*hi = d3(fmax(hi->x, q[0]), fmax(hi->y, q[1]), fmax(hi->z, q[2]));
		}
		break;
	case SHAPE2_ISOSURFACE: /* its container */
	case SHAPE2_PARAMETRIC:
		if (s->contained_sphere) {
			dvec3 r = d3(s->sphere_r, s->sphere_r, s->sphere_r);
			*lo = d3_sub(s->box_lo, r), *hi = d3_add(s->box_lo, r);
		} else {
			*lo = s->box_lo, *hi = s->box_hi;
		}
		break;
	case SHAPE2_JULIA: {
		double ev, r = shape_julia_radius(s, &ev);
		*lo = d3(-r, -r, -r), *hi = d3(r, r, r);
		break;
	}
	case SHAPE2_TEXT: {
		size_t n = s->text ? strlen(s->text) : 0;
		double w = (double)n * (1.0 + fabs(s->offset.x));
		*lo = d3(0, -0.3 + fmin(0, (double)n * s->offset.y), fmin(0, s->depth));
		*hi = d3(fmax(w, 0.1), 1.0 + fmax(0, (double)n * s->offset.y), fmax(s->depth, 0) + fabs((double)n * s->offset.z));
		break;
	}
	}
	if (!(lo->x <= hi->x))
		*lo = *hi = d3(0, 0, 0);
}

bool shape_tessellate(const shape_desc *s, const shape_accuracy *acc, mesh *out, double *tol_out, diag *d,
		      diag_loc loc)
{
	*tol_out = acc->tol;
	switch (s->kind) {
	case SHAPE2_LATHE: return shape_lathe(s, acc, out, d, loc);
	case SHAPE2_SOR: return shape_sor(s, acc, out, d, loc);
	case SHAPE2_PRISM: return shape_prism(s, acc, out, d, loc);
	case SHAPE2_SPHERE_SWEEP: return shape_sphere_sweep(s, acc, out, d, loc);
	case SHAPE2_BLOB: return shape_blob(s, acc, out, tol_out, d, loc);
	case SHAPE2_TEXT: return shape_text(s, acc, out, d, loc);
	case SHAPE2_BICUBIC: return shape_bicubic(s, acc, out, d, loc);
	case SHAPE2_ISOSURFACE: return shape_isosurface(s, acc, out, tol_out, d, loc);
	case SHAPE2_PARAMETRIC: return shape_parametric(s, acc, out, tol_out, d, loc);
	case SHAPE2_JULIA: return shape_julia(s, acc, out, tol_out, d, loc);
	}
	return false;
}

