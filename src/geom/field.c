/* field.c - the polygoniser blob and isosurface share: a scalar field (positive inside) sampled
 * on a grid, its zero set polygonised by marching tetrahedra (six tetrahedra a cube, split along
 * its main diagonal, so neighbouring cubes agree and the surface is closed), each vertex shared by
 * the edge it lies on; the vertices then moved onto the zero set (Newton steps along the gradient,
 * at most half a cell, or kept on their edge and found there by regula falsi), normals -gradient.
 * The triangles are counted from the grid before any is made and refused past the limit. With
 * workers (shape_field.workers) the grid's values, the vertices' places, the normals and the
 * distance are computed on threads, each value by the point it belongs to alone; the topology
 * (which edges have vertices, their numbers, the triangles) is made in order on the caller's, so
 * the mesh is the same for any count. */
#include "geom/shape.h"

#include "base/mem.h"
#include "base/par.h"

#include <math.h>
#include <string.h>

/* Newton steps onto the zero set, each at most a fraction of a cell. */
#define FIELD_NEWTON_STEPS 4
/* Regula falsi (Illinois) steps along an edge, at most, and the bracket (a fraction of the edge)
 * at which they stop. */
#define FIELD_EDGE_STEPS 12
#define FIELD_EDGE_TOL 1e-6
/* Indices a worker takes at a time (vertices, triangles), and the triangles the march keeps
 * waiting for their vertices' places before it places them (on the workers) and adds them. */
#define FIELD_CHUNK 512
#define FIELD_PENDING 65536

typedef struct grid {
	dvec3 lo;
	double h;
	uint32_t nx, ny, nz; /* points along each axis */
	float *f; /* the field at each point */
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

/* F for each of its workers: copies of F calling eval with worker_ctx[w] (*n of them; one, F
 * itself, when F has no workers or memory runs out). Freed by field_workers_free. */
static shape_field *field_workers(const shape_field *F, int *n)
{
	*n = 1;
	if (F->workers > 1 && F->worker_ctx) {
		shape_field *w = mem_alloc((size_t)F->workers, sizeof *w);
		if (w) {
			for (int k = 0; k < F->workers; k++)
				w[k] = *F, w[k].ctx = F->worker_ctx[k], w[k].workers = 1;
			*n = F->workers;
			return w;
		}
	}
	return (shape_field *)F;
}

static void field_workers_free(const shape_field *F, shape_field *w)
{
	if (w != F)
		mem_free(w);
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

/* A triangle made before its vertices are placed: sb_tri's arguments. */
typedef struct pend_tri {
	uint32_t v[3];
	dvec3 want;
} pend_tri;

typedef struct mt {
	const shape_field *F;
	shape_field *Fw; /* the workers' (field_workers) */
	int workers;
	grid *G;
	shape_builder *b;
	/* the vertices of the edges from the points of planes k and k + 1 (the layer of cubes being
	 * marched): plane[0] and plane[1], 7 edges a point (edge_vertex's ranks), UINT32_MAX where
	 * none was made yet */
	uint32_t *plane[2];
	uint32_t k;
	const uint8_t *crossed; /* the cubes with points inside and outside (count_crossed) */
	bool failed;
	/* vertices v0 .. b->nv - 1 wait for their places: ends[2 (v - v0)], ends[2 (v - v0) + 1] the
	 * grid points of their edge; pend the triangles waiting for them */
	uint32_t v0;
	size_t *ends, cap_ends;
	pend_tri *pend;
	size_t n_pend, cap_pend;
} mt;

/* The zero of the field on the segment pa (value fa > 0 or < 0) to pb (fb of the other sign):
 * the Illinois variant of regula falsi, kept inside the segment. */
static dvec3 edge_root(const shape_field *F, dvec3 pa, double fa, dvec3 pb, double fb)
{
	double ta = 0, tb = 1;
	int side = 0;
	dvec3 ab = d3_sub(pb, pa);
	double t = fa / (fa - fb);
	for (int it = 0; it < FIELD_EDGE_STEPS; it++) {
		t = (ta * fb - tb * fa) / (fb - fa);
		if (!(t > ta && t < tb))
			t = 0.5 * (ta + tb);
		double ft = F->eval(F->ctx, d3_add(pa, d3_scale(ab, t)), NULL);
		if (ft == 0 || !isfinite(ft) || tb - ta < FIELD_EDGE_TOL)
			break;
		if ((ft > 0) == (fa > 0)) {
			ta = t, fa = ft;
			if (side == -1)
				fb *= 0.5;
			side = -1;
		} else {
			tb = t, fb = ft;
			if (side == 1)
				fa *= 0.5;
			side = 1;
		}
	}
	return d3_add(pa, d3_scale(ab, t));
}

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
	/* the lower point lies in plane k or k + 1 of the layer of cubes marched */
	uint32_t *slot = &t->plane[a / sz - t->k][(a % sz) * 7 + rank];
	if (*slot != UINT32_MAX)
		return *slot;
	/* placed later, with the others waiting (place_pending) */
	size_t w = t->b->nv - t->v0;
	if (2 * w + 2 > t->cap_ends) {
		size_t cap = t->cap_ends ? 2 * t->cap_ends : 2 * FIELD_PENDING;
		size_t *e = mem_realloc(t->ends, cap, sizeof *e);
		if (!e) {
			t->failed = true;
			return 0;
		}
		t->ends = e, t->cap_ends = cap;
	}
	uint32_t v = sb_vertex(t->b, gpos(t->G, a), d3(0, 1, 0), 0, 0);
	if (t->b->failed) {
		t->failed = true;
		return 0;
	}
	t->ends[2 * w] = a, t->ends[2 * w + 1] = b;
	*slot = v;
	return v;
}

/* The places of waiting vertices [begin, end) (after v0): on their edge, where the field is 0. */
static void place_vertices(void *ctx, size_t begin, size_t end, int worker)
{
	mt *t = ctx;
	const shape_field *F = &t->Fw[worker];
	for (size_t w = begin; w < end; w++) {
		size_t a = t->ends[2 * w], b = t->ends[2 * w + 1];
		double fa = t->G->f[a], fb = t->G->f[b];
		dvec3 pa = gpos(t->G, a), pb = gpos(t->G, b), p;
		if (F->on_edges)
			p = edge_root(F, pa, fa, pb, fb);
		else
			p = d3_add(pa, d3_scale(d3_sub(pb, pa), fa / (fa - fb)));
		t->b->pos[t->v0 + w] = d3_to_v3(p);
	}
}

/* Places the waiting vertices (on the workers), then adds the waiting triangles in their order
 * (sb_tri orients each by its vertices' places). */
static void place_pending(mt *t)
{
	if (!t->failed && t->b->nv > t->v0)
		par_for(t->workers, t->b->nv - t->v0, FIELD_CHUNK, place_vertices, t);
	for (size_t i = 0; i < t->n_pend && !t->failed; i++)
		sb_tri(t->b, t->pend[i].v[0], t->pend[i].v[1], t->pend[i].v[2], t->pend[i].want);
	t->v0 = t->b->nv, t->n_pend = 0;
}

/* Triangle a c1 c2 facing want, added once its vertices are placed. */
static void pending_tri(mt *t, uint32_t a, uint32_t c1, uint32_t c2, dvec3 want)
{
	if (t->failed)
		return;
	if (t->n_pend == t->cap_pend) {
		size_t cap = t->cap_pend ? 2 * t->cap_pend : 1024;
		pend_tri *p = mem_realloc(t->pend, cap, sizeof *p);
		if (!p) {
			t->failed = true;
			return;
		}
		t->pend = p, t->cap_pend = cap;
	}
	t->pend[t->n_pend++] = (pend_tri){{a, c1, c2}, want};
}

/* One tetrahedron of grid points: its piece of the zero set (inside: field above 0). */
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
		pending_tri(t, e[0], e[1], e[2], want);
		return;
	}
	uint32_t e00 = edge_vertex(t, v[in[0]], v[out[0]]), e01 = edge_vertex(t, v[in[0]], v[out[1]]);
	uint32_t e11 = edge_vertex(t, v[in[1]], v[out[1]]), e10 = edge_vertex(t, v[in[1]], v[out[0]]);
	pending_tri(t, e00, e01, e11, want);
	pending_tri(t, e00, e11, e10, want);
}

/* Each cube of the grid as six tetrahedra about its diagonal from corner 0 to corner 7. */
static void march(mt *t)
{
	static const int tets[6][4] = {{0, 1, 3, 7}, {0, 3, 2, 7}, {0, 2, 6, 7}, {0, 6, 4, 7}, {0, 4, 5, 7}, {0, 5, 1, 7}};
	const grid *G = t->G;
	size_t plane = (size_t)7 * G->nx * G->ny;
	memset(t->plane[0], 0xff, plane * sizeof *t->plane[0]);
	memset(t->plane[1], 0xff, plane * sizeof *t->plane[1]);
	for (uint32_t k = 0; k + 1 < G->nz && !t->failed; k++) {
		if (k > 0) { /* plane k + 1 of the last layer is this one's plane k */
			uint32_t *p = t->plane[0];
			t->plane[0] = t->plane[1], t->plane[1] = p;
			memset(p, 0xff, plane * sizeof *p);
		}
		t->k = k;
		for (uint32_t j = 0; j + 1 < G->ny; j++)
			for (uint32_t i = 0; i + 1 < G->nx; i++) {
				if (!t->crossed[gidx(G, i, j, k)])
					continue;
				size_t c[8];
				for (int q = 0; q < 8; q++)
					c[q] = gidx(G, i + (q & 1), j + (q >> 1 & 1), k + (q >> 2 & 1));
				for (int q = 0; q < 6; q++) {
					size_t v[4] = {c[tets[q][0]], c[tets[q][1]], c[tets[q][2]], c[tets[q][3]]};
					tetra(t, v);
				}
				if (t->n_pend >= FIELD_PENDING)
					place_pending(t);
			}
	}
	place_pending(t);
}

/* Moves every vertex onto the zero set (Newton along the gradient, at most half a cell in all;
 * not for a field whose vertices were found on their edges) and gives it the surface's normal,
 * -gradient. */
typedef struct project_job {
	const shape_field *Fw;
	shape_builder *b;
	double h;
} project_job;

static void project_vertices(void *ctx, size_t begin, size_t end, int worker)
{
	const project_job *J = ctx;
	const shape_field *F = &J->Fw[worker];
	shape_builder *b = J->b;
	double h = J->h;
	for (size_t i = begin; i < end; i++) {
		dvec3 p0 = v3_to_d3(b->pos[i]), p = p0, g;
		for (int it = 0; it < (F->on_edges ? 0 : FIELD_NEWTON_STEPS); it++) {
			double f = F->eval(F->ctx, p, &g), g2 = d3_dot(g, g);
			if (!(g2 > 0))
				break;
			p = d3_sub(p, d3_scale(g, f / g2));
		}
		dvec3 mv = d3_sub(p, p0);
		double l = d3_length(mv);
		if (l > 0.5 * h)
			p = d3_add(p0, d3_scale(mv, 0.5 * h / l));
		F->eval(F->ctx, p, &g);
		b->pos[i] = d3_to_v3(p);
		dvec3 n = d3_scale(g, -1);
		double nl = d3_length(n);
		b->nrm[i] = nl > 0 && isfinite(nl) ? d3_to_v3(d3_scale(n, 1 / nl)) : v3(0, 1, 0);
	}
}

static void project(const shape_field *Fw, int workers, shape_builder *b, double h)
{
	project_job J = {Fw, b, h};
	par_for(workers, b->nv, FIELD_CHUNK, project_vertices, &J);
}

/* The first-order distance |F| / |grad F| at p, or 0 where it cannot be told. */
static double field_dist(const shape_field *F, dvec3 p)
{
	dvec3 g;
	double f = F->eval(F->ctx, p, &g), gl = d3_length(g);
	return gl > 0 && isfinite(f / gl) ? fabs(f) / gl : 0.0;
}

/* The first-order distance of the triangle p0 p1 p2: |F| at its centre and edge midpoints over
 * |grad F| at its centre (one gradient a triangle: an isosurface's costs six calls of its function). */
static double tri_points_dist(const shape_field *F, dvec3 p0, dvec3 p1, dvec3 p2)
{
	dvec3 c = d3_scale(d3_add(d3_add(p0, p1), p2), 1.0 / 3), g;
	double f = F->eval(F->ctx, c, &g), gl = d3_length(g);
	if (!(gl > 0) || !isfinite(f / gl))
		return 0.0;
	double m = fabs(f);
	m = fmax(m, fabs(F->eval(F->ctx, d3_scale(d3_add(p0, p1), 0.5), NULL)));
	m = fmax(m, fabs(F->eval(F->ctx, d3_scale(d3_add(p1, p2), 0.5), NULL)));
	m = fmax(m, fabs(F->eval(F->ctx, d3_scale(d3_add(p2, p0), 0.5), NULL)));
	return isfinite(m / gl) ? m / gl : 0.0;
}

typedef struct error_job {
	const shape_field *Fw;
	const shape_builder *b;
	double *max; /* each worker's largest distance */
} error_job;

static void error_tris(void *ctx, size_t begin, size_t end, int worker)
{
	const error_job *J = ctx;
	const shape_field *F = &J->Fw[worker];
	const shape_builder *b = J->b;
	double w = J->max[worker];
	for (size_t t = begin; t < end; t++) {
		const uint32_t *i = &b->idx[3 * t];
		dvec3 p0 = v3_to_d3(b->pos[i[0]]), p1 = v3_to_d3(b->pos[i[1]]), p2 = v3_to_d3(b->pos[i[2]]);
		dvec3 c = d3_scale(d3_add(d3_add(p0, p1), p2), 1.0 / 3);
		if (F->has_region && (c.x < F->region_lo.x || c.y < F->region_lo.y || c.z < F->region_lo.z ||
				      c.x > F->region_hi.x || c.y > F->region_hi.y || c.z > F->region_hi.z))
			continue;
		w = fmax(w, tri_points_dist(F, p0, p1, p2));
	}
	J->max[worker] = w;
}

double shape_field_error(const shape_field *F, const shape_builder *b)
{
	/* The centre and the edges' midpoints of each triangle: marching tetrahedra make slivers,
	 * whose largest distance is at the midpoint of the long edge, not at the centre. The largest
	 * over the workers' largest: a maximum, whatever triangles each measured. */
	int n;
	shape_field *Fw = field_workers(F, &n);
	double one = 0, *max = n > 1 ? mem_calloc((size_t)n, sizeof *max) : &one;
	if (!max)
		n = 1, max = &one;
	error_job J = {Fw, b, max};
	par_for(n, b->nt, FIELD_CHUNK, error_tris, &J);
	double w = 0;
	for (int k = 0; k < n; k++)
		w = fmax(w, max[k]);
	if (max != &one)
		mem_free(max);
	field_workers_free(F, Fw);
	return w;
}

/* ---- refinement where the distance is missed ---------------------------------------------- */

/* The first-order distance of triangle t of b (its centre and edge midpoints). */
static double tri_dist(const shape_field *F, const shape_builder *b, uint32_t t)
{
	const uint32_t *i = &b->idx[3 * (size_t)t];
	return tri_points_dist(F, v3_to_d3(b->pos[i[0]]), v3_to_d3(b->pos[i[1]]), v3_to_d3(b->pos[i[2]]));
}

/* The slot of edge key k in m (open addressing; m->key[slot] == k when it was there). */
static size_t emap_slot(const edge_map *m, uint64_t k)
{
	size_t h = (size_t)(k * 0x9E3779B97F4A7C15ull) & (m->cap - 1);
	while (m->key[h] != UINT64_MAX && m->key[h] != k)
		h = (h + 1) & (m->cap - 1);
	return h;
}

static uint64_t ekey(uint32_t a, uint32_t b) { return a < b ? (uint64_t)a << 32 | b : (uint64_t)b << 32 | a; }

/* The point of the zero set near the midpoint of a b: Newton steps along the gradient, in all at
 * most half the edge's length; the midpoint itself where they do not come nearer. */
static dvec3 mid_on_surface(const shape_field *F, dvec3 a, dvec3 b, dvec3 *n)
{
	dvec3 m = d3_scale(d3_add(a, b), 0.5), p = m, g;
	double lim = 0.5 * d3_length(d3_sub(b, a)), f0 = field_dist(F, m);
	for (int it = 0; it < FIELD_NEWTON_STEPS + 2; it++) {
		double f = F->eval(F->ctx, p, &g), g2 = d3_dot(g, g);
		if (!(g2 > 0) || !isfinite(f))
			break;
		p = d3_sub(p, d3_scale(g, f / g2));
	}
	dvec3 mv = d3_sub(p, m);
	double l = d3_length(mv);
	if (!(l <= lim))
		p = d3_add(m, d3_scale(mv, lim / l));
	if (!(field_dist(F, p) <= f0))
		p = m;
	F->eval(F->ctx, p, &g);
	*n = d3_scale(g, -1);
	return p;
}

double shape_field_refine(const shape_field *F, shape_builder *b, double tol, int rounds, uint32_t *rounds_made)
{
	uint32_t done = 0;
	/* dirty: made or changed by the last round (at first every triangle); only those are
	 * measured, the others keep their distance */
	uint8_t *dirty = mem_alloc(b->nt ? b->nt : 1, 1);
	float *dist = mem_alloc(b->nt ? b->nt : 1, sizeof *dist);
	if (!dirty || !dist) {
		mem_free(dirty), mem_free(dist);
		b->failed = true;
		return 0;
	}
	memset(dirty, 1, b->nt ? b->nt : 1);
	for (int r = 0; r < rounds && !b->failed; r++) {
		/* the edges of every triangle that misses tol, each split at its point on the surface */
		edge_map m = {0};
		uint32_t nt = b->nt, bad = 0;
		uint8_t *miss = mem_calloc(nt ? nt : 1, 1);
		if (!miss) {
			b->failed = true;
			break;
		}
		for (uint32_t t = 0; t < nt; t++) {
			if (dirty[t])
				dist[t] = (float)tri_dist(F, b, t), dirty[t] = 0;
			bad += miss[t] = dist[t] > tol;
		}
		if (!bad) {
			mem_free(miss);
			break;
		}
		bool ok = true;
		for (uint32_t t = 0; ok && t < nt; t++)
			for (int k = 0; ok && miss[t] && k < 3; k++) {
				if (2 * (m.n + 1) > m.cap && !map_grow(&m)) {
					ok = false;
					break;
				}
				uint32_t a = b->idx[3 * (size_t)t + k], c = b->idx[3 * (size_t)t + (k + 1) % 3];
				size_t h = emap_slot(&m, ekey(a, c));
				if (m.key[h] == UINT64_MAX)
					m.key[h] = ekey(a, c), m.val[h] = UINT32_MAX, m.n++;
			}
		/* every triangle with k split edges becomes k + 1: counted against the limit first */
		size_t add = 0;
		for (uint32_t t = 0; ok && t < nt; t++)
			for (int k = 0; k < 3; k++) {
				uint32_t a = b->idx[3 * (size_t)t + k], c = b->idx[3 * (size_t)t + (k + 1) % 3];
				add += m.key[emap_slot(&m, ekey(a, c))] != UINT64_MAX;
			}
		if (!ok || (size_t)nt + add >= SHAPE_MAX_TRIANGLES) {
			mem_free(miss), mem_free(m.key), mem_free(m.val);
			if (!ok)
				b->failed = true;
			break; /* the limit: keep the mesh as it is, its distance measured */
		}
		uint32_t *idx = mem_alloc(3 * ((size_t)nt + add), sizeof *idx);
		uint8_t *nd = mem_alloc((size_t)nt + add, 1);
		float *ndist = mem_alloc((size_t)nt + add, sizeof *ndist);
		if (!idx || !nd || !ndist) {
			mem_free(miss), mem_free(m.key), mem_free(m.val), mem_free(idx), mem_free(nd), mem_free(ndist);
			b->failed = true;
			break;
		}
		for (size_t h = 0; h < m.cap; h++)
			if (m.key[h] != UINT64_MAX) {
				uint32_t a = (uint32_t)(m.key[h] >> 32), c = (uint32_t)m.key[h];
				dvec3 n, p = mid_on_surface(F, v3_to_d3(b->pos[a]), v3_to_d3(b->pos[c]), &n);
				m.val[h] = sb_vertex(b, p, n, 0, 0);
			}
		size_t o = 0;
		for (uint32_t t = 0; t < nt && !b->failed; t++) {
			uint32_t v[3], mid[3];
			int nm = 0, first = -1;
			for (int k = 0; k < 3; k++)
				v[k] = b->idx[3 * (size_t)t + k];
			for (int k = 0; k < 3; k++) {
				size_t h = emap_slot(&m, ekey(v[k], v[(k + 1) % 3]));
				mid[k] = m.key[h] != UINT64_MAX ? m.val[h] : UINT32_MAX;
				nm += mid[k] != UINT32_MAX;
			}
#define TRI(x, y, z) (nd[o / 3] = nm > 0, ndist[o / 3] = dist[t], idx[o++] = (x), idx[o++] = (y), idx[o++] = (z))
			if (nm == 0) {
				TRI(v[0], v[1], v[2]);
			} else if (nm == 3) {
				TRI(v[0], mid[0], mid[2]), TRI(mid[0], v[1], mid[1]), TRI(mid[2], mid[1], v[2]);
				TRI(mid[0], mid[1], mid[2]);
			} else if (nm == 1) { /* the split edge k: v[k] mid v[k+2], mid v[k+1] v[k+2] */
				for (int k = 0; k < 3; k++)
					if (mid[k] != UINT32_MAX)
						first = k;
				uint32_t a = v[first], c = v[(first + 1) % 3], e = v[(first + 2) % 3];
				TRI(a, mid[first], e), TRI(mid[first], c, e);
			} else { /* two: the unsplit edge k; the quad left split along its shorter diagonal */
				for (int k = 0; k < 3; k++)
					if (mid[k] == UINT32_MAX)
						first = k;
				/* rotate so the unsplit edge is v2 v0: split edges v0 v1 (m0) and v1 v2 (m1) */
				int k0 = (first + 1) % 3;
				uint32_t a = v[k0], c = v[(k0 + 1) % 3], e = v[(k0 + 2) % 3];
				uint32_t m0 = mid[k0], m1 = mid[(k0 + 1) % 3];
				TRI(m0, c, m1);
				double d1 = d3_length(d3_sub(v3_to_d3(b->pos[a]), v3_to_d3(b->pos[m1])));
				double d2 = d3_length(d3_sub(v3_to_d3(b->pos[m0]), v3_to_d3(b->pos[e])));
				if (d1 <= d2)
					TRI(a, m0, m1), TRI(a, m1, e);
				else
					TRI(a, m0, e), TRI(m0, m1, e);
			}
#undef TRI
		}
		mem_free(miss), mem_free(m.key), mem_free(m.val);
		if (b->failed) {
			mem_free(idx), mem_free(nd), mem_free(ndist);
			break;
		}
		mem_free(b->idx), mem_free(dirty), mem_free(dist);
		b->idx = idx, b->nt = (uint32_t)(o / 3), b->cap_t = b->nt;
		dirty = nd, dist = ndist;
		done++;
	}
	double w = 0;
	for (uint32_t t = 0; t < b->nt && !b->failed; t++)
		w = fmax(w, dirty[t] ? tri_dist(F, b, t) : dist[t]);
	mem_free(dirty), mem_free(dist);
	if (rounds_made)
		*rounds_made = done;
	return w;
}

/* The octree's blocks, cells a side, at the top. */
#define FIELD_BLOCK 32

/* One grid point's value (NaN: outside). */
static float field_point(const shape_field *F, const grid *G, size_t id)
{
	double v = F->eval(F->ctx, gpos(G, id), NULL);
	return isnan(v) ? -1.0f : (float)v;
}

/* Whether point (i, j, k) of the top-level block whose first point is o was set before: by the
 * block itself (done), or on the block's low faces, which the blocks before it along each axis
 * set (a top-level block sets all its points, and the blocks are filled k, then j, then i, the
 * lower first). So a top-level block writes only points no other writes, and reads only those:
 * the blocks may be filled at once, each as it would be filled after the ones before it. */
static bool point_done(const uint8_t *done, size_t id, uint32_t i, uint32_t j, uint32_t k, const uint32_t o[3])
{
	return (i == o[0] && i > 0) || (j == o[1] && j > 0) || (k == o[2] && k > 0) || done[id];
}

/* The block of n cells a side from point (i0, j0, k0) (cut at the grid's end) within the
 * top-level block at o: its points not yet set (point_done) take the value at the block's centre
 * when F's Lipschitz bound keeps the surface more than a cell's diagonal from all of them, else
 * its eight halves are filled, down to blocks of two cells, whose points are evaluated. */
static void fill_block(const shape_field *F, grid *G, uint8_t *done, uint32_t i0, uint32_t j0, uint32_t k0,
		       uint32_t n, const uint32_t o[3])
{
	uint32_t i1 = i0 + n < G->nx - 1 ? i0 + n : G->nx - 1, j1 = j0 + n < G->ny - 1 ? j0 + n : G->ny - 1,
		 k1 = k0 + n < G->nz - 1 ? k0 + n : G->nz - 1;
	if (n > 2) {
		double h = G->h, di = i1 - i0, dj = j1 - j0, dk = k1 - k0;
		dvec3 c = d3(G->lo.x + h * (i0 + i1) / 2, G->lo.y + h * (j0 + j1) / 2, G->lo.z + h * (k0 + k1) / 2);
		double r = 0.5 * h * sqrt(di * di + dj * dj + dk * dk), v = F->eval(F->ctx, c, NULL);
		if (isfinite(v) && fabs(v) > F->lipschitz * (r + h * sqrt(3.0))) {
			for (uint32_t k = k0; k <= k1; k++)
				for (uint32_t j = j0; j <= j1; j++)
					for (uint32_t i = i0; i <= i1; i++) {
						size_t id = gidx(G, i, j, k);
						if (!point_done(done, id, i, j, k, o))
							G->f[id] = (float)v, done[id] = 1;
					}
			return;
		}
		uint32_t m = n / 2;
		for (uint32_t q = 0; q < 8; q++) {
			uint32_t a = i0 + (q & 1) * m, b = j0 + (q >> 1 & 1) * m, e = k0 + (q >> 2 & 1) * m;
			if (a < i1 && b < j1 && e < k1)
				fill_block(F, G, done, a, b, e, m, o);
		}
		return;
	}
	for (uint32_t k = k0; k <= k1; k++)
		for (uint32_t j = j0; j <= j1; j++)
			for (uint32_t i = i0; i <= i1; i++) {
				size_t id = gidx(G, i, j, k);
				if (!point_done(done, id, i, j, k, o))
					G->f[id] = field_point(F, G, id), done[id] = 1;
			}
}

typedef struct fill_job {
	const shape_field *Fw;
	grid *G;
	uint8_t *done;
	uint32_t bx, by; /* top-level blocks along x and y */
} fill_job;

/* Top-level blocks [begin, end) in the order k, j, i. */
static void fill_blocks(void *ctx, size_t begin, size_t end, int worker)
{
	const fill_job *J = ctx;
	for (size_t q = begin; q < end; q++) {
		uint32_t o[3] = {(uint32_t)(q % J->bx) * FIELD_BLOCK, (uint32_t)(q / J->bx % J->by) * FIELD_BLOCK,
				 (uint32_t)(q / J->bx / J->by) * FIELD_BLOCK};
		fill_block(&J->Fw[worker], J->G, J->done, o[0], o[1], o[2], FIELD_BLOCK, o);
	}
}

typedef struct points_job {
	const shape_field *Fw;
	grid *G;
} points_job;

static void fill_points(void *ctx, size_t begin, size_t end, int worker)
{
	const points_job *J = ctx;
	for (size_t i = begin; i < end; i++)
		J->G->f[i] = field_point(&J->Fw[worker], J->G, i);
}

/* The grid's values: F's fill, its octree (lipschitz), or every point, on F's workers Fw. False:
 * out of memory. */
static bool fill_grid(const shape_field *F, const shape_field *Fw, int workers, grid *G)
{
	size_t np = (size_t)G->nx * G->ny * G->nz;
	if (F->fill) {
		F->fill(F->ctx, G->lo, G->h, G->nx, G->ny, G->nz, G->f);
		return true;
	}
	if (!(F->lipschitz > 0)) {
		points_job J = {Fw, G};
		par_for(workers, np, 4 * FIELD_CHUNK, fill_points, &J);
		return true;
	}
	uint8_t *done = mem_calloc(np, 1);
	if (!done)
		return false;
	uint32_t bx = (G->nx - 2) / FIELD_BLOCK + 1, by = (G->ny - 2) / FIELD_BLOCK + 1, bz = (G->nz - 2) / FIELD_BLOCK + 1;
	fill_job J = {Fw, G, done, bx, by};
	par_for(workers, (size_t)bx * by * bz, 1, fill_blocks, &J);
	mem_free(done);
	return true;
}

typedef struct crossed_job {
	const grid *G;
	size_t *counts; /* each worker's */
	uint8_t *crossed; /* 1 for each crossed cube (indexed as its lowest point), for the march */
} crossed_job;

/* The cubes of layers [begin, end) with points inside and outside, added to the worker's count. */
static void count_crossed(void *ctx, size_t begin, size_t end, int worker)
{
	const crossed_job *J = ctx;
	const grid *G = J->G;
	size_t n = 0;
	for (uint32_t k = (uint32_t)begin; k < end; k++)
		for (uint32_t j = 0; j + 1 < G->ny; j++)
			for (uint32_t i = 0; i + 1 < G->nx; i++) {
				bool in = false, outp = false;
				for (int q = 0; q < 8; q++) {
					bool inside = G->f[gidx(G, i + (q & 1), j + (q >> 1 & 1), k + (q >> 2 & 1))] > 0;
					in |= inside, outp |= !inside;
				}
				n += in && outp;
				J->crossed[gidx(G, i, j, k)] = in && outp;
			}
	J->counts[worker] += n;
}

double shape_field_fit_step(dvec3 ext, double h, size_t max_points)
{
	while ((ext.x / h + 3) * (ext.y / h + 3) * (ext.z / h + 3) > (double)max_points)
		h *= 1.05;
	return h;
}

bool shape_field_polygonise(const shape_field *F, dvec3 lo, dvec3 hi, double h, const char *what, shape_builder *b,
			    diag *d, diag_loc loc)
{
	dvec3 ext = d3_sub(hi, lo);
	double sh = (F->shift > 0 && F->shift <= 1 ? F->shift : 1) * h;
	grid G = {.lo = d3_sub(lo, d3(sh, sh, sh)), .h = h};
	G.nx = (uint32_t)ceil(ext.x / h) + 3, G.ny = (uint32_t)ceil(ext.y / h) + 3, G.nz = (uint32_t)ceil(ext.z / h) + 3;
	size_t np = (size_t)G.nx * G.ny * G.nz;
	G.f = mem_alloc(np, sizeof *G.f);
	if (!G.f) {
		diag_error(d, loc, "out of memory while tessellating the %s (a grid of %ux%ux%u)", what, G.nx, G.ny, G.nz);
		return false;
	}
	int workers;
	shape_field *Fw = field_workers(F, &workers);
	if (!fill_grid(F, Fw, workers, &G)) {
		field_workers_free(F, Fw);
		mem_free(G.f);
		diag_error(d, loc, "out of memory while tessellating the %s (a grid of %ux%ux%u)", what, G.nx, G.ny, G.nz);
		return false;
	}
	/* The triangles to come, counted before any is made: about six a crossed cube (measured). */
	size_t one = 0, *counts = workers > 1 ? mem_calloc((size_t)workers, sizeof *counts) : &one;
	uint8_t *cubes = mem_alloc(np, 1);
	if (!cubes) {
		if (counts != &one)
			mem_free(counts);
		field_workers_free(F, Fw);
		mem_free(G.f);
		diag_error(d, loc, "out of memory while tessellating the %s (a grid of %ux%ux%u)", what, G.nx, G.ny, G.nz);
		return false;
	}
	crossed_job C = {&G, counts ? counts : &one, cubes};
	par_for(counts ? workers : 1, G.nz - 1, 1, count_crossed, &C);
	size_t crossed = 0;
	for (int w = 0; w < (counts ? workers : 1); w++)
		crossed += C.counts[w];
	if (counts != &one)
		mem_free(counts);
	if (crossed * 6 > SHAPE_MAX_TRIANGLES) {
		mem_free(cubes);
		field_workers_free(F, Fw);
		mem_free(G.f);
		diag_error(d, loc, "the %s would make about %zu triangles (the limit of one shape is %u)", what, crossed * 6,
			   SHAPE_MAX_TRIANGLES);
		return false;
	}
	sb_init(b);
	mt t = {.F = F, .Fw = Fw, .workers = workers, .G = &G, .b = b, .crossed = cubes};
	size_t plane = (size_t)7 * G.nx * G.ny;
	t.plane[0] = mem_alloc(plane, sizeof *t.plane[0]), t.plane[1] = mem_alloc(plane, sizeof *t.plane[1]);
	if (t.plane[0] && t.plane[1])
		march(&t);
	else
		t.failed = true;
	mem_free(G.f), mem_free(cubes), mem_free(t.plane[0]), mem_free(t.plane[1]), mem_free(t.ends), mem_free(t.pend);
	if (t.failed)
		b->failed = true;
	if (!b->failed)
		project(Fw, workers, b, h);
	field_workers_free(F, Fw);
	return true;
}
