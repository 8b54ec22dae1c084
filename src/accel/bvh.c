/* bvh.c - binned-SAH build of a binary BVH and its ray and circle traversals.
 * Nodes are 32 bytes; children are stored as a pair (first, first + 1). Leaves point into an
 * array of triangle copies (three vertices and the id, 40 bytes) in leaf order. */
#include "accel/bvh.h"

#include "base/mem.h"

#include <string.h>

/* SAH: the cost of one node visit relative to one triangle test. */
#define SAH_TRAVERSAL_COST 1.0f
#define SAH_BINS 16
/* Slack of the slab test's far distance: 1 + 2 gamma(3) of Ize 2013 ("Robust BVH Ray
 * Traversal") covers the rounding of the box distances; we take ten times that, because the
 * triangle test's t carries rounding too and a box must never cull a hit the brute force finds. */
#define BVH_SLAB_SLACK (1.0f + 20.0f * 0x1p-24f * 3.0f)
/* Relative slack of the circle/box test, against float rounding of box and circle data. */
#define BVH_CIRCLE_SLACK 1e-5f

typedef struct bvh_tri {
	vec3 v0, v1, v2;
	uint32_t id;
} bvh_tri;

struct bvh {
	bvh_node *nodes;
	uint32_t num_nodes;
	bvh_tri *tris;
	uint32_t num_tris;
};

/* A primitive reference during the build: its box, and its index in the input. */
typedef struct build_ref {
	vec3 lo;
	uint32_t id;
	vec3 hi;
	uint32_t pad;
} build_ref;

typedef struct build_task {
	uint32_t node, begin, end, depth;
} build_task;

static float half_area(vec3 lo, vec3 hi)
{
	vec3 e = v3_sub(hi, lo);
	return e.x * e.y + e.y * e.z + e.z * e.x;
}

static int bin_of(float c, float cmin, float scale)
{
	int b = (int)((c - cmin) * scale);
	return b < 0 ? 0 : b >= SAH_BINS ? SAH_BINS - 1 : b;
}

static void make_leaf(bvh_node *nd, uint32_t begin, uint32_t count)
{
	nd->first = begin;
	nd->count = count;
}

/* Chooses the best binned-SAH split of refs[b, e) with centroid (doubled: lo + hi) bounds
 * [clo, chi]. Returns false when no split beats a leaf (or none exists); else sets axis and the
 * first bin of the right side. */
static bool find_split(const build_ref *refs, uint32_t b, uint32_t e, vec3 clo, vec3 chi, float node_area,
		       int *axis, int *split_bin, float *scale_out)
{
	uint32_t count = e - b;
	float best = (float)count; /* the leaf's cost */
	bool found = false;
	bool leaf_ok = count <= BVH_MAX_LEAF;
	if (!leaf_ok)
		best = INFINITY;
	for (int ax = 0; ax < 3; ax++) {
		float cmin = v3_get(clo, ax), ext = v3_get(chi, ax) - cmin;
		if (!(ext > 0.0f))
			continue;
		float scale = (float)SAH_BINS * (1.0f - 1e-6f) / ext;
		uint32_t cnt[SAH_BINS] = {0};
		vec3 blo[SAH_BINS], bhi[SAH_BINS];
		for (int i = 0; i < SAH_BINS; i++)
			blo[i] = v3s(INFINITY), bhi[i] = v3s(-INFINITY);
		for (uint32_t i = b; i < e; i++) {
			const build_ref *r = &refs[i];
			int k = bin_of(v3_get(r->lo, ax) + v3_get(r->hi, ax), cmin, scale);
			cnt[k]++;
			blo[k] = v3_min(blo[k], r->lo);
			bhi[k] = v3_max(bhi[k], r->hi);
		}
		/* Sweep from the right, then from the left. */
		float right_cost[SAH_BINS];
		vec3 lo = v3s(INFINITY), hi = v3s(-INFINITY);
		uint32_t n = 0;
		for (int i = SAH_BINS - 1; i > 0; i--) {
			lo = v3_min(lo, blo[i]), hi = v3_max(hi, bhi[i]), n += cnt[i];
			right_cost[i] = n ? half_area(lo, hi) * (float)n : 0.0f;
		}
		lo = v3s(INFINITY), hi = v3s(-INFINITY), n = 0;
		for (int i = 0; i < SAH_BINS - 1; i++) {
			lo = v3_min(lo, blo[i]), hi = v3_max(hi, bhi[i]), n += cnt[i];
			if (n == 0 || n == count)
				continue;
			float cost = SAH_TRAVERSAL_COST +
				     (half_area(lo, hi) * (float)n + right_cost[i + 1]) / node_area;
			if (cost < best) {
				best = cost, *axis = ax, *split_bin = i + 1, *scale_out = scale;
				found = true;
			}
		}
	}
	return found;
}

bool bvh_build_nodes(const vec3 *lo, const vec3 *hi, uint32_t n, bvh_node **nodes_out,
		     uint32_t *num_nodes, uint32_t *perm)
{
	*nodes_out = NULL, *num_nodes = 0;
	if (n == 0)
		return true;
	build_ref *refs = mem_alloc(n, sizeof *refs);
	bvh_node *nodes = mem_alloc(2 * (size_t)n - 1, sizeof *nodes);
	if (!refs || !nodes) {
		mem_free(refs), mem_free(nodes);
		return false;
	}
	for (uint32_t i = 0; i < n; i++)
		refs[i] = (build_ref){lo[i], i, hi[i], 0};
	uint32_t used = 1;
	build_task stack[BVH_MAX_DEPTH + 2];
	int sp = 0;
	stack[sp++] = (build_task){0, 0, n, 0};
	while (sp > 0) {
		build_task tk = stack[--sp];
		bvh_node *nd = &nodes[tk.node];
		vec3 blo = v3s(INFINITY), bhi = v3s(-INFINITY), clo = blo, chi = bhi;
		for (uint32_t i = tk.begin; i < tk.end; i++) {
			blo = v3_min(blo, refs[i].lo), bhi = v3_max(bhi, refs[i].hi);
			vec3 c = v3_add(refs[i].lo, refs[i].hi);
			clo = v3_min(clo, c), chi = v3_max(chi, c);
		}
		nd->lo[0] = blo.x, nd->lo[1] = blo.y, nd->lo[2] = blo.z;
		nd->hi[0] = bhi.x, nd->hi[1] = bhi.y, nd->hi[2] = bhi.z;
		uint32_t count = tk.end - tk.begin;
		if (count == 1 || tk.depth >= BVH_MAX_DEPTH - 1) {
			make_leaf(nd, tk.begin, count);
			continue;
		}
		int axis = 0, split_bin = 0;
		float scale = 0.0f;
		uint32_t mid;
		if (find_split(refs, tk.begin, tk.end, clo, chi, half_area(blo, bhi), &axis, &split_bin,
			       &scale)) {
			float cmin = v3_get(clo, axis);
			uint32_t i = tk.begin, j = tk.end;
			while (i < j) {
				const build_ref *r = &refs[i];
				if (bin_of(v3_get(r->lo, axis) + v3_get(r->hi, axis), cmin, scale) < split_bin) {
					i++;
				} else {
					build_ref tmp = refs[i];
					refs[i] = refs[--j];
					refs[j] = tmp;
				}
			}
			mid = i;
		} else if (count <= BVH_MAX_LEAF) {
			make_leaf(nd, tk.begin, count);
			continue;
		} else {
			/* All centroids coincide (or no split helps): halve by position in the array. */
			mid = tk.begin + count / 2;
		}
		uint32_t left = used;
		used += 2;
		nd->first = left;
		nd->count = BVH_INNER | (uint32_t)axis;
		stack[sp++] = (build_task){left + 1, mid, tk.end, tk.depth + 1};
		stack[sp++] = (build_task){left, tk.begin, mid, tk.depth + 1};
	}
	for (uint32_t i = 0; i < n; i++)
		perm[i] = refs[i].id;
	mem_free(refs);
	bvh_node *shrunk = mem_realloc(nodes, used, sizeof *nodes);
	*nodes_out = shrunk ? shrunk : nodes;
	*num_nodes = used;
	return true;
}

bvh *bvh_build(const vec3 *positions, uint32_t num_vertices, const uint32_t *indices,
	       uint32_t num_triangles)
{
	for (size_t i = 0; i < 3 * (size_t)num_triangles; i++)
		if (indices[i] >= num_vertices)
			return NULL;
	bvh *b = mem_calloc(1, sizeof *b);
	uint32_t *keep = mem_alloc(num_triangles, sizeof *keep);
	vec3 *lo = mem_alloc(num_triangles, sizeof *lo), *hi = mem_alloc(num_triangles, sizeof *hi);
	uint32_t *perm = mem_alloc(num_triangles, sizeof *perm);
	bool ok = b && keep && lo && hi && perm;
	uint32_t n = 0;
	if (ok) {
		for (uint32_t f = 0; f < num_triangles; f++) {
			const uint32_t *ix = indices + 3 * f;
			vec3 a = positions[ix[0]], c = positions[ix[1]], d = positions[ix[2]];
			if (tri_is_degenerate(a, c, d))
				continue;
			keep[n] = f;
			lo[n] = v3_min(a, v3_min(c, d));
			hi[n] = v3_max(a, v3_max(c, d));
			n++;
		}
		ok = bvh_build_nodes(lo, hi, n, &b->nodes, &b->num_nodes, perm);
	}
	if (ok && n > 0) {
		b->tris = mem_alloc(n, sizeof *b->tris);
		ok = b->tris != NULL;
	}
	if (ok) {
		for (uint32_t i = 0; i < n; i++) {
			uint32_t f = keep[perm[i]];
			const uint32_t *ix = indices + 3 * f;
			b->tris[i] = (bvh_tri){positions[ix[0]], positions[ix[1]], positions[ix[2]], f};
		}
		b->num_tris = n;
	}
	mem_free(keep), mem_free(lo), mem_free(hi), mem_free(perm);
	if (!ok) {
		bvh_free(b);
		return NULL;
	}
	return b;
}

void bvh_free(bvh *b)
{
	if (!b)
		return;
	mem_free(b->nodes);
	mem_free(b->tris);
	mem_free(b);
}

bool bvh_bounds(const bvh *b, vec3 *lo, vec3 *hi)
{
	if (b->num_nodes == 0)
		return false;
	const bvh_node *r = &b->nodes[0];
	*lo = v3(r->lo[0], r->lo[1], r->lo[2]);
	*hi = v3(r->hi[0], r->hi[1], r->hi[2]);
	return true;
}

size_t bvh_bytes(const bvh *b)
{
	return sizeof *b + (size_t)b->num_nodes * sizeof(bvh_node) + (size_t)b->num_tris * sizeof(bvh_tri);
}

uint32_t bvh_num_nodes(const bvh *b) { return b->num_nodes; }

/* Max and min that ignore a NaN in x (0 * inf, a ray in a slab's plane): the slab then does not
 * constrain, which is conservative. maxss/minss compile from this form. */
static inline float max_nan(float x, float m) { return x > m ? x : m; }
static inline float min_nan(float x, float m) { return x < m ? x : m; }

bool bvh_node_hit(const bvh_node *nd, const tri_ray *r, float tlimit, float *tnear)
{
	float x0 = (nd->lo[0] - r->org.x) * r->inv_dir.x, x1 = (nd->hi[0] - r->org.x) * r->inv_dir.x;
	float y0 = (nd->lo[1] - r->org.y) * r->inv_dir.y, y1 = (nd->hi[1] - r->org.y) * r->inv_dir.y;
	float z0 = (nd->lo[2] - r->org.z) * r->inv_dir.z, z1 = (nd->hi[2] - r->org.z) * r->inv_dir.z;
	bool sx = r->inv_dir.x < 0.0f, sy = r->inv_dir.y < 0.0f, sz = r->inv_dir.z < 0.0f;
	float tn = r->tmin, tf = tlimit;
	tn = max_nan(sx ? x1 : x0, tn), tf = min_nan(sx ? x0 : x1, tf);
	tn = max_nan(sy ? y1 : y0, tn), tf = min_nan(sy ? y0 : y1, tf);
	tn = max_nan(sz ? z1 : z0, tn), tf = min_nan(sz ? z0 : z1, tf);
	*tnear = tn;
	return tn <= tf * BVH_SLAB_SLACK;
}

typedef struct stack_entry {
	uint32_t node;
	float tnear;
} stack_entry;

bool bvh_intersect_prepared(const bvh *b, const tri_ray *r, float *tlimit, bvh_hit *hit)
{
	if (b->num_nodes == 0)
		return false;
	float tn0, tn1;
	if (!bvh_node_hit(&b->nodes[0], r, *tlimit, &tn0))
		return false;
	stack_entry stack[BVH_MAX_DEPTH + 2];
	int sp = 0;
	uint32_t ni = 0;
	bool found = false;
	uint32_t best_id = UINT32_MAX;
	for (;;) {
		const bvh_node *nd = &b->nodes[ni];
		if (nd->count & BVH_INNER) {
			uint32_t c0 = nd->first, c1 = c0 + 1;
			bool h0 = bvh_node_hit(&b->nodes[c0], r, *tlimit, &tn0);
			bool h1 = bvh_node_hit(&b->nodes[c1], r, *tlimit, &tn1);
			if (h0 && h1) {
				if (tn1 < tn0) {
					uint32_t tc = c0;
					c0 = c1, c1 = tc;
					float tt = tn0;
					tn0 = tn1, tn1 = tt;
				}
				stack[sp++] = (stack_entry){c1, tn1};
				ni = c0;
				continue;
			}
			if (h0) {
				ni = c0;
				continue;
			}
			if (h1) {
				ni = c1;
				continue;
			}
		} else {
			const bvh_tri *tr = &b->tris[nd->first];
			for (uint32_t i = 0; i < nd->count; i++, tr++) {
				float t, u, v;
				if (tri_intersect(r, tr->v0, tr->v1, tr->v2, *tlimit, &t, &u, &v) &&
				    (t < *tlimit || tr->id < best_id)) {
					*tlimit = t;
					best_id = tr->id;
					hit->t = t, hit->u = u, hit->v = v, hit->prim = tr->id;
					found = true;
				}
			}
		}
		/* Pop the next entry that can still hold a hit no farther than the best. */
		for (;;) {
			if (sp == 0)
				return found;
			stack_entry e = stack[--sp];
			if (e.tnear <= *tlimit * BVH_SLAB_SLACK) {
				ni = e.node;
				break;
			}
		}
	}
}

bool bvh_occluded_prepared(const bvh *b, const tri_ray *r)
{
	if (b->num_nodes == 0)
		return false;
	float tn;
	if (!bvh_node_hit(&b->nodes[0], r, r->tmax, &tn))
		return false;
	uint32_t stack[BVH_MAX_DEPTH + 2];
	int sp = 0;
	uint32_t ni = 0;
	for (;;) {
		const bvh_node *nd = &b->nodes[ni];
		if (nd->count & BVH_INNER) {
			uint32_t c0 = nd->first, c1 = c0 + 1;
			bool h0 = bvh_node_hit(&b->nodes[c0], r, r->tmax, &tn);
			bool h1 = bvh_node_hit(&b->nodes[c1], r, r->tmax, &tn);
			if (h0 && h1) {
				stack[sp++] = c1;
				ni = c0;
				continue;
			}
			if (h0 || h1) {
				ni = h0 ? c0 : c1;
				continue;
			}
		} else {
			const bvh_tri *tr = &b->tris[nd->first];
			for (uint32_t i = 0; i < nd->count; i++, tr++) {
				float t, u, v;
				if (tri_intersect(r, tr->v0, tr->v1, tr->v2, r->tmax, &t, &u, &v))
					return true;
			}
		}
		if (sp == 0)
			return false;
		ni = stack[--sp];
	}
}

bool bvh_intersect(const bvh *b, const bvh_ray *ray, bvh_hit *hit)
{
	tri_ray r;
	if (!tri_ray_prepare(&r, ray->org, ray->dir, ray->tmin, ray->tmax))
		return false;
	float tlimit = ray->tmax;
	hit->inst = 0;
	return bvh_intersect_prepared(b, &r, &tlimit, hit);
}

bool bvh_occluded(const bvh *b, const bvh_ray *ray)
{
	tri_ray r;
	if (!tri_ray_prepare(&r, ray->org, ray->dir, ray->tmin, ray->tmax))
		return false;
	return bvh_occluded_prepared(b, &r);
}

/* A circle prepared for box tests: its plane normal m = t x n and the slack. */
typedef struct circle_prep {
	vec3 c, t, m;
	float r, slack;
	bool full;
} circle_prep;

static bool circle_prepare(const tri_circle *q, circle_prep *p)
{
	if (!v3_is_finite(q->centre) || !v3_is_finite(q->t) || !v3_is_finite(q->n) || !isfinite(q->radius) ||
	    q->radius < 0.0f)
		return false;
	p->c = q->centre, p->t = q->t, p->m = v3_cross(q->t, q->n), p->r = q->radius, p->full = q->full;
	p->slack = BVH_CIRCLE_SLACK * (q->radius + v3_max_comp(v3_abs(q->centre)));
	return true;
}

static bool box_circle(const circle_prep *p, vec3 lo, vec3 hi)
{
	vec3 e = v3_scale(v3_sub(hi, lo), 0.5f);
	vec3 rel = v3_sub(v3_scale(v3_add(lo, hi), 0.5f), p->c);
	float slack = p->slack + BVH_CIRCLE_SLACK * (v3_max_comp(v3_abs(lo)) + v3_max_comp(v3_abs(hi)));
	/* The box meets the plane: its projection on m holds the centre's. */
	if (fabsf(v3_dot(p->m, rel)) > v3_dot(v3_abs(p->m), e) + slack)
		return false;
	/* For a half circle, the box reaches the side cos theta >= 0. */
	if (!p->full && v3_dot(p->t, rel) + v3_dot(v3_abs(p->t), e) < -slack)
		return false;
	/* The box meets the sphere of radius r: nearest point inside, farthest outside. */
	vec3 a = v3_abs(rel);
	vec3 dn = v3_max(v3_sub(a, e), v3s(0.0f)), df = v3_add(a, e);
	float rmax = p->r + slack, rmin = p->r - slack;
	if (v3_length2(dn) > rmax * rmax)
		return false;
	if (rmin > 0.0f && v3_length2(df) < rmin * rmin)
		return false;
	return true;
}

bool bvh_box_circle(vec3 lo, vec3 hi, const tri_circle *q)
{
	circle_prep p;
	return circle_prepare(q, &p) && box_circle(&p, lo, hi);
}

static bool node_circle(const circle_prep *p, const bvh_node *nd)
{
	return box_circle(p, v3(nd->lo[0], nd->lo[1], nd->lo[2]), v3(nd->hi[0], nd->hi[1], nd->hi[2]));
}

uint32_t bvh_circle(const bvh *b, const tri_circle *q, tri_circle_hit *hits, uint32_t max_hits)
{
	circle_prep p;
	if (b->num_nodes == 0 || !circle_prepare(q, &p) || !node_circle(&p, &b->nodes[0]))
		return 0;
	uint32_t stack[BVH_MAX_DEPTH + 2];
	int sp = 0;
	uint32_t ni = 0, total = 0;
	for (;;) {
		const bvh_node *nd = &b->nodes[ni];
		if (nd->count & BVH_INNER) {
			uint32_t c0 = nd->first, c1 = c0 + 1;
			bool h0 = node_circle(&p, &b->nodes[c0]), h1 = node_circle(&p, &b->nodes[c1]);
			if (h0 && h1) {
				stack[sp++] = c1;
				ni = c0;
				continue;
			}
			if (h0 || h1) {
				ni = h0 ? c0 : c1;
				continue;
			}
		} else {
			const bvh_tri *tr = &b->tris[nd->first];
			for (uint32_t i = 0; i < nd->count; i++, tr++) {
				tri_circle_hit h[2];
				int nh = tri_circle_intersect(q, tr->v0, tr->v1, tr->v2, h);
				for (int k = 0; k < nh; k++, total++) {
					if (total < max_hits) {
						hits[total] = h[k];
						hits[total].prim = tr->id;
					}
				}
			}
		}
		if (sp == 0)
			return total;
		ni = stack[--sp];
	}
}

vec3 bvh_offset_origin(vec3 p, vec3 n)
{
	/* Waechter & Binder 2019, listing 6-1: below 1/32 a fixed float offset, above it an offset of
	 * 256 * n ulps in the integer representation. */
	const float origin = 1.0f / 32.0f, float_scale = 1.0f / 65536.0f, int_scale = 256.0f;
	float pc[3] = {p.x, p.y, p.z}, nc[3] = {n.x, n.y, n.z}, out[3];
	for (int i = 0; i < 3; i++) {
		int32_t of = (int32_t)(int_scale * nc[i]);
		int32_t bits;
		memcpy(&bits, &pc[i], sizeof bits);
		bits += pc[i] < 0.0f ? -of : of;
		float pi;
		memcpy(&pi, &bits, sizeof pi);
		out[i] = fabsf(pc[i]) < origin ? pc[i] + float_scale * nc[i] : pi;
	}
	return v3(out[0], out[1], out[2]);
}
