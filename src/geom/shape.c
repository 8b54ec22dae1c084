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

