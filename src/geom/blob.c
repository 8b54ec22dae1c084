/* blob.c - POV-Ray's blob as a mesh: its field (core/shape/blob.cpp: each component adds
 * s (1 - d^2 / r^2)^2 inside its radius; a cylinder measures d from its axis, with hemispheres at
 * its ends) sampled on a grid, the threshold's iso-surface polygonised by marching tetrahedra (six
 * tetrahedra a cube, split along its main diagonal, so neighbouring cubes agree and the surface is
 * closed), each vertex shared by the edge it lies on, then moved onto the iso-surface by Newton
 * steps along the field's gradient. */
#include "geom/shape.h"

#include "base/mem.h"

#include <math.h>
#include <string.h>

/* The most grid points a blob may sample (floats: 64 MiB); past it the grid is coarsened. */
#define BLOB_MAX_GRID_POINTS (1u << 24)
/* Newton steps onto the iso-surface, each at most a fraction of a cell. */
#define BLOB_NEWTON_STEPS 4

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

static double field_grad(const shape_desc *s, dvec3 p, dvec3 *g)
{
	*g = d3(0, 0, 0);
	double f = 0;
	for (uint32_t i = 0; i < s->n_comps; i++)
		f += comp_field(&s->comps[i], p, g);
	return f;
}

typedef struct grid {
	dvec3 lo;
	double h;
	uint32_t nx, ny, nz; /* points along each axis */
	float *f; /* field - threshold at each point */
} grid;

static size_t gidx(const grid *G, uint32_t i, uint32_t j, uint32_t k)
{
	return ((size_t)k * G->ny + j) * G->nx + i;
}

static dvec3 gpos(const grid *G, size_t id)
{
	uint32_t i = (uint32_t)(id % G->nx), j = (uint32_t)(id / G->nx % G->ny), k = (uint32_t)(id / G->nx / G->ny);
	return d3(G->lo.x + i * G->h, G->lo.y + j * G->h, G->lo.z + k * G->h);
}

/* Adds each component's field to the grid points inside its bounding box. */
static void splat(const shape_desc *s, grid *G)
{
	for (uint32_t c = 0; c < s->n_comps; c++) {
		shape_desc one = *s;
		shape_blob_comp pos = s->comps[c];
		pos.strength = 1; /* shape_bounds skips negative components: bound this one too */
		one.comps = &pos, one.n_comps = 1;
		dvec3 lo, hi;
		shape_bounds(&one, &lo, &hi);
		pos.strength = s->comps[c].strength;
		int i0 = (int)floor((lo.x - G->lo.x) / G->h), i1 = (int)ceil((hi.x - G->lo.x) / G->h);
		int j0 = (int)floor((lo.y - G->lo.y) / G->h), j1 = (int)ceil((hi.y - G->lo.y) / G->h);
		int k0 = (int)floor((lo.z - G->lo.z) / G->h), k1 = (int)ceil((hi.z - G->lo.z) / G->h);
		i0 = i0 < 0 ? 0 : i0, j0 = j0 < 0 ? 0 : j0, k0 = k0 < 0 ? 0 : k0;
		i1 = i1 >= (int)G->nx ? (int)G->nx - 1 : i1, j1 = j1 >= (int)G->ny ? (int)G->ny - 1 : j1;
		k1 = k1 >= (int)G->nz ? (int)G->nz - 1 : k1;
		for (int k = k0; k <= k1; k++)
			for (int j = j0; j <= j1; j++)
				for (int i = i0; i <= i1; i++) {
					dvec3 p = d3(G->lo.x + i * G->h, G->lo.y + j * G->h, G->lo.z + k * G->h);
					G->f[gidx(G, (uint32_t)i, (uint32_t)j, (uint32_t)k)] += (float)comp_field(&pos, p, NULL);
				}
	}
}

/* Edge vertices, shared: an open-addressing table from the edge's two grid points to a vertex. */
typedef struct edge_map {
	uint64_t *key;
	uint32_t *val;
	size_t cap, n;
} edge_map;

static bool map_grow(edge_map *m)
{
	size_t cap = m->cap ? 2 * m->cap : 1 << 16;
	uint64_t *k = mem_alloc(cap, sizeof *k);
	uint32_t *v = mem_alloc(cap, sizeof *v);
	if (!k || !v) {
		mem_free(k), mem_free(v);
		return false;
	}
	memset(k, 0xff, cap * sizeof *k);
	for (size_t i = 0; i < m->cap; i++)
		if (m->key[i] != UINT64_MAX) {
			size_t h = (size_t)(m->key[i] * 0x9E3779B97F4A7C15ull) & (cap - 1);
			while (k[h] != UINT64_MAX)
				h = (h + 1) & (cap - 1);
			k[h] = m->key[i], v[h] = m->val[i];
		}
	mem_free(m->key), mem_free(m->val);
	m->key = k, m->val = v, m->cap = cap;
	return true;
}

typedef struct mt {
	const shape_desc *s;
	grid *G;
	shape_builder *b;
	edge_map map;
	bool failed;
} mt;

/* The vertex on the edge between grid points a and b (field values of opposite signs). */
static uint32_t edge_vertex(mt *t, size_t a, size_t b)
{
	if (a > b) {
		size_t x = a;
		a = b, b = x;
	}
	/* The tetrahedra's edges go from a point to one of 7 neighbours (+x, +y, +z and their sums):
	 * the key is the lower point and the neighbour's rank. */
	size_t off = b - a, sx = 1, sy = t->G->nx, sz = (size_t)t->G->nx * t->G->ny;
	size_t offs[7] = {sx, sy, sz, sx + sy, sx + sz, sy + sz, sx + sy + sz};
	uint64_t rank = 0;
	while (rank < 7 && offs[rank] != off)
		rank++;
	uint64_t key = (uint64_t)a * 8 + rank;
	if (2 * (t->map.n + 1) > t->map.cap && !map_grow(&t->map)) {
		t->failed = true;
		return 0;
	}
	size_t h = (size_t)(key * 0x9E3779B97F4A7C15ull) & (t->map.cap - 1);
	while (t->map.key[h] != UINT64_MAX) {
		if (t->map.key[h] == key)
			return t->map.val[h];
		h = (h + 1) & (t->map.cap - 1);
	}
	double fa = t->G->f[a], fb = t->G->f[b];
	double u = fa / (fa - fb);
	dvec3 pa = gpos(t->G, a), pb = gpos(t->G, b);
	dvec3 p = d3_add(pa, d3_scale(d3_sub(pb, pa), u));
	uint32_t v = sb_vertex(t->b, p, d3(0, 1, 0), 0, 0);
	t->map.key[h] = key, t->map.val[h] = v, t->map.n++;
	return v;
}

/* One tetrahedron of grid points: its piece of the iso-surface (inside: field above threshold). */
static void tetra(mt *t, const size_t v[4])
{
	int in[4], nin = 0, out[4], nout = 0;
	for (int i = 0; i < 4; i++) {
		if (t->G->f[v[i]] > 0)
			in[nin++] = i;
		else
			out[nout++] = i;
	}
	if (nin == 0 || nout == 0)
		return;
	dvec3 ci = d3(0, 0, 0), co = d3(0, 0, 0);
	for (int i = 0; i < nin; i++)
		ci = d3_add(ci, d3_scale(gpos(t->G, v[in[i]]), 1.0 / nin));
	for (int i = 0; i < nout; i++)
		co = d3_add(co, d3_scale(gpos(t->G, v[out[i]]), 1.0 / nout));
	dvec3 want = d3_sub(co, ci); /* outward: from inside points to outside ones */
	if (nin == 1 || nout == 1) {
		int lone = nin == 1 ? in[0] : out[0];
		const int *others = nin == 1 ? out : in;
		uint32_t e[3];
		for (int i = 0; i < 3; i++)
			e[i] = edge_vertex(t, v[lone], v[others[i]]);
		sb_tri(t->b, e[0], e[1], e[2], want);
		return;
	}
	uint32_t e00 = edge_vertex(t, v[in[0]], v[out[0]]), e01 = edge_vertex(t, v[in[0]], v[out[1]]);
	uint32_t e11 = edge_vertex(t, v[in[1]], v[out[1]]), e10 = edge_vertex(t, v[in[1]], v[out[0]]);
	sb_tri(t->b, e00, e01, e11, want);
	sb_tri(t->b, e00, e11, e10, want);
}

/* Each cube of the grid as six tetrahedra about its diagonal from corner 0 to corner 7. */
static void march(mt *t)
{
	static const int tets[6][4] = {{0, 1, 3, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 6, 4, 7}, {0, 4, 5, 7}, {0, 5, 1, 7}};
	const grid *G = t->G;
	for (uint32_t k = 0; k + 1 < G->nz && !t->failed; k++)
		for (uint32_t j = 0; j + 1 < G->ny; j++)
			for (uint32_t i = 0; i + 1 < G->nx; i++) {
				size_t c[8];
				bool any_in = false, any_out = false;
				for (int q = 0; q < 8; q++) {
					c[q] = gidx(G, i + (q & 1), j + (q >> 1 & 1), k + (q >> 2 & 1));
					if (G->f[c[q]] > 0)
						any_in = true;
					else
						any_out = true;
				}
				if (!any_in || !any_out)
					continue;
				for (int q = 0; q < 6; q++) {
					size_t v[4] = {c[tets[q][0]], c[tets[q][1]], c[tets[q][2]], c[tets[q][3]]};
					tetra(t, v);
				}
			}
}

/* Moves every vertex onto the iso-surface (Newton along the gradient, at most half a cell in all)
 * and gives it the surface's normal, -gradient. */
static void project(const shape_desc *s, shape_builder *b, double h)
{
	for (uint32_t i = 0; i < b->nv; i++) {
		dvec3 p0 = v3_to_d3(b->pos[i]), p = p0, g;
		for (int it = 0; it < BLOB_NEWTON_STEPS; it++) {
			double f = field_grad(s, p, &g) - s->threshold, g2 = d3_dot(g, g);
			if (!(g2 > 0))
				break;
			p = d3_sub(p, d3_scale(g, f / g2));
		}
		dvec3 mv = d3_sub(p, p0);
		double l = d3_length(mv);
		if (l > 0.5 * h)
			p = d3_add(p0, d3_scale(mv, 0.5 * h / l));
		field_grad(s, p, &g);
		b->pos[i] = d3_to_v3(p);
		dvec3 n = d3_scale(g, -1);
		double nl = d3_length(n);
		b->nrm[i] = nl > 0 ? d3_to_v3(d3_scale(n, 1 / nl)) : v3(0, 1, 0);
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

/* The largest distance of the triangles' centres from the iso-surface, to first order
 * (|F - threshold| / |grad F|): what the mesh reached, reported as its tolerance. */
static double measured_tol(const shape_desc *s, const shape_builder *b)
{
	double w = 0;
	for (uint32_t t = 0; t < b->nt; t++) {
		const uint32_t *i = &b->idx[3 * t];
		dvec3 c = d3_scale(v3_to_d3(v3_add(v3_add(b->pos[i[0]], b->pos[i[1]]), b->pos[i[2]])), 1.0 / 3), g;
		double f = field_grad(s, c, &g) - s->threshold, gl = d3_length(g);
		if (gl > 0)
			w = fmax(w, fabs(f) / gl);
	}
	return w;
}

/* One polygonisation at grid step h into b; false (reported) past the limits. */
static bool blob_at(const shape_desc *s, dvec3 lo, dvec3 hi, double h, shape_builder *b, diag *d, diag_loc loc)
{
	dvec3 ext = d3_sub(hi, lo);
	grid G = {.lo = d3_sub(lo, d3(h, h, h)), .h = h};
	G.nx = (uint32_t)ceil(ext.x / h) + 3, G.ny = (uint32_t)ceil(ext.y / h) + 3, G.nz = (uint32_t)ceil(ext.z / h) + 3;
	size_t np = (size_t)G.nx * G.ny * G.nz;
	G.f = mem_alloc(np, sizeof *G.f);
	if (!G.f) {
		diag_error(d, loc, "out of memory while tessellating the blob (a grid of %ux%ux%u)", G.nx, G.ny, G.nz);
		return false;
	}
	for (size_t i = 0; i < np; i++)
		G.f[i] = (float)-s->threshold;
	splat(s, &G);
	/* The triangles to come, counted before any is made: about six a crossed cube (measured). */
	size_t crossed = 0;
	for (uint32_t k = 0; k + 1 < G.nz; k++)
		for (uint32_t j = 0; j + 1 < G.ny; j++)
			for (uint32_t i = 0; i + 1 < G.nx; i++) {
				bool in = false, outp = false;
				for (int q = 0; q < 8; q++) {
					bool inside = G.f[gidx(&G, i + (q & 1), j + (q >> 1 & 1), k + (q >> 2 & 1))] > 0;
					in |= inside, outp |= !inside;
				}
				crossed += in && outp;
			}
	if (crossed * 6 > SHAPE_MAX_TRIANGLES) {
		mem_free(G.f);
		diag_error(d, loc, "the blob would make about %zu triangles (the limit of one shape is %u)", crossed * 6,
			   SHAPE_MAX_TRIANGLES);
		return false;
	}
	sb_init(b);
	mt t = {.s = s, .G = &G, .b = b};
	march(&t);
	mem_free(G.f), mem_free(t.map.key), mem_free(t.map.val);
	if (t.failed)
		b->failed = true;
	if (!b->failed)
		project(s, b, h);
	return true;
}

/* The grid step the grid's size allows: h grown until the grid has at most BLOB_MAX_GRID_POINTS. */
static double fit_step(dvec3 ext, double h)
{
	while ((ext.x / h + 3) * (ext.y / h + 3) * (ext.z / h + 3) > BLOB_MAX_GRID_POINTS)
		h *= 1.05;
	return h;
}

bool shape_blob(const shape_desc *s, const shape_accuracy *acc, mesh *out, double *tol_out, diag *d, diag_loc loc)
{
	dvec3 lo, hi;
	shape_bounds(s, &lo, &hi);
	double rc, h0 = blob_step(s, acc->tol, &rc);
	dvec3 ext = d3_sub(hi, lo);
	double h = fit_step(ext, h0);
	shape_builder b;
	if (!blob_at(s, lo, hi, h, &b, d, loc))
		return false;
	/* Sharp creases (where negative components cut) stand further off than the curvature rule
	 * says: the distance reached is measured and reported, not assumed. */
	double got = b.failed ? 0 : measured_tol(s, &b);
	*tol_out = fmax(acc->tol, got);
	return sb_finish(&b, out, false, "blob", d, loc);
}
