/* tlas.c - the BVH over instances: rays and circles are moved into each instance's space and
 * traced through its mesh BVH. */
#include "accel/tlas.h"
#include "accel/bvh_internal.h"

#include "base/mem.h"

#include <assert.h>
#include <math.h>

/* An instance as traced: world-to-object and object-to-world in float, 3x4 row-major. */
typedef struct inst {
	const bvh *geom;
	float w2o[12], o2w[12];
	float scale; /* of a similarity transform, 0 otherwise */
	uint32_t set;
	bool filtered;
	uint32_t key;
} inst;

/* No ray steps over more rejected hits of one instance than this (then the instance is missed). */
#define TLAS_MAX_REJECTED 4096

struct tlas {
	bvh_node *nodes;
	uint32_t num_nodes;
	uint32_t *order; /* instance index of each leaf slot */
	inst *insts;
	uint32_t count;
	tlas_filter filter;
	void *filter_user;
};

static vec3 mul_point(const float m[12], vec3 p)
{
	return v3(m[0] * p.x + m[1] * p.y + m[2] * p.z + m[3], m[4] * p.x + m[5] * p.y + m[6] * p.z + m[7],
		  m[8] * p.x + m[9] * p.y + m[10] * p.z + m[11]);
}

static vec3 mul_vector(const float m[12], vec3 v)
{
	return v3(m[0] * v.x + m[1] * v.y + m[2] * v.z, m[4] * v.x + m[5] * v.y + m[6] * v.z,
		  m[8] * v.x + m[9] * v.y + m[10] * v.z);
}

tlas *tlas_build(const tlas_instance *instances, uint32_t count)
{
	tlas *t = mem_calloc(1, sizeof *t);
	vec3 *lo = mem_alloc(count, sizeof *lo), *hi = mem_alloc(count, sizeof *hi);
	bool ok = t && lo && hi;
	if (ok) {
		t->insts = mem_alloc(count, sizeof *t->insts);
		t->order = mem_alloc(count, sizeof *t->order);
		ok = t->insts && t->order;
	}
	for (uint32_t i = 0; ok && i < count; i++) {
		inst *in = &t->insts[i];
		const xform *x = &instances[i].to_world;
		in->geom = instances[i].geom;
		in->set = instances[i].set;
		in->filtered = instances[i].filtered;
		in->key = instances[i].key;
		for (int r = 0; r < 3; r++)
			for (int c = 0; c < 4; c++)
				in->o2w[4 * r + c] = (float)x->m[r][c], in->w2o[4 * r + c] = (float)x->inv[r][c];
		double s;
		in->scale = xform_is_similarity(x, &s) ? (float)s : 0.0f;
		vec3 blo, bhi;
		if (!bvh_bounds(in->geom, &blo, &bhi)) {
			/* Nothing to hit: an empty box far from everything is never entered. */
			lo[i] = v3s(INFINITY), hi[i] = v3s(-INFINITY);
			continue;
		}
		lo[i] = v3s(INFINITY), hi[i] = v3s(-INFINITY);
		for (int k = 0; k < 8; k++) {
			dvec3 p = d3(k & 1 ? bhi.x : blo.x, k & 2 ? bhi.y : blo.y, k & 4 ? bhi.z : blo.z);
			vec3 w = d3_to_v3(xform_point(x, p));
			lo[i] = v3_min(lo[i], w), hi[i] = v3_max(hi[i], w);
		}
		/* Rounding of the float transform: grow the box by a few ulps of its size. */
		vec3 pad = v3_scale(v3_add(v3_abs(lo[i]), v3_abs(hi[i])), 1e-6f);
		lo[i] = v3_sub(lo[i], pad), hi[i] = v3_add(hi[i], pad);
	}
	if (ok)
		ok = bvh_build_nodes(lo, hi, count, 1, &t->nodes, &t->num_nodes, t->order);
	mem_free(lo), mem_free(hi);
	if (!ok) {
		tlas_free(t);
		return NULL;
	}
	for (uint32_t i = 0; i < count; i++)
		assert(t->order[i] < count); /* trace reads insts[order[...]] without a check */
	t->count = count;
	return t;
}

void tlas_free(tlas *t)
{
	if (!t)
		return;
	mem_free(t->nodes), mem_free(t->order), mem_free(t->insts), mem_free(t);
}

size_t tlas_bytes(const tlas *t)
{
	return sizeof *t + (size_t)t->num_nodes * sizeof(bvh_node) + (size_t)t->count * (sizeof(inst) + sizeof(uint32_t));
}

void tlas_set_filter(tlas *t, tlas_filter fn, void *user)
{
	t->filter = fn;
	t->filter_user = user;
}

/* The closest hit of the world ray on filtered instance `in` (object-space ray prepared from
 * org, dir) that the filter keeps, in [tmin, *tlimit]: rejected hits are stepped over. */
static bool filtered_hit(const tlas *t, const inst *in, const bvh_ray *ray, vec3 org, vec3 dir, float *tlimit,
			 bvh_hit *hit)
{
	float tmin = ray->tmin;
	for (int k = 0; k < TLAS_MAX_REJECTED; k++) {
		tri_ray r;
		float lim = *tlimit;
		bvh_hit h;
		if (!tri_ray_prepare(&r, org, dir, tmin, lim) || !bvh_intersect_prepared(in->geom, &r, &lim, &h))
			return false;
		h.inst = 0;
		if (t->filter(t->filter_user, in->key, ray, &h)) {
			*tlimit = lim;
			*hit = h;
			return true;
		}
		tmin = nextafterf(h.t, INFINITY);
		if (!(tmin <= *tlimit))
			return false;
	}
	return false;
}

bool tlas_circle_ok(const tlas *t, uint32_t i) { return i < t->count && t->insts[i].scale > 0.0f; }

/* Visits the leaves of the top level whose boxes the ray reaches; for each instance (every one,
 * or those whose set is *set) calls the mesh traversal with the ray in object space. any: stop at
 * the first hit. */
static bool trace(const tlas *t, const bvh_ray *ray, bvh_hit *hit, bool any, const uint32_t *set)
{
	tri_ray wr;
	if (t->num_nodes == 0 || !tri_ray_prepare(&wr, ray->org, ray->dir, ray->tmin, ray->tmax))
		return false;
	float tlimit = ray->tmax, tn;
	if (!bvh_node_hit(&t->nodes[0], &wr, tlimit, &tn))
		return false;
	uint32_t stack[BVH_MAX_DEPTH + 2];
	int sp = 0;
	uint32_t ni = 0;
	bool found = false;
	for (;;) {
		const bvh_node *nd = &t->nodes[ni];
		if (nd->count & BVH_INNER) {
			uint32_t c0 = nd->first, c1 = c0 + 1;
			bool h0 = bvh_node_hit(&t->nodes[c0], &wr, tlimit, &tn);
			bool h1 = bvh_node_hit(&t->nodes[c1], &wr, tlimit, &tn);
			/* No assert on sp here, in the rays' hot loop: one push a level, and
			 * bvh_build_nodes asserts the depth. */
			if (bvh_descend(h0, h1, c0, stack, &sp, &ni))
				continue;
		} else {
			for (uint32_t k = 0; k < nd->count; k++) {
				uint32_t id = t->order[nd->first + k];
				const inst *in = &t->insts[id];
				if (set && in->set != *set)
					continue;
				vec3 org = mul_point(in->w2o, ray->org), dir = mul_vector(in->w2o, ray->dir);
				if (in->filtered && t->filter) {
					bvh_hit h;
					if (!filtered_hit(t, in, ray, org, dir, &tlimit, &h))
						continue;
					if (any)
						return true;
					*hit = h;
					hit->inst = id;
					found = true;
					continue;
				}
				tri_ray r;
				if (!tri_ray_prepare(&r, org, dir, ray->tmin, tlimit))
					continue;
				if (any) {
					if (bvh_occluded_prepared(in->geom, &r))
						return true;
				} else if (bvh_intersect_prepared(in->geom, &r, &tlimit, hit)) {
					hit->inst = id;
					found = true;
				}
			}
		}
		if (sp == 0)
			return found;
		ni = stack[--sp];
	}
}

bool tlas_intersect(const tlas *t, const bvh_ray *ray, bvh_hit *hit) { return trace(t, ray, hit, false, NULL); }

bool tlas_intersect_set(const tlas *t, const bvh_ray *ray, uint32_t set, bvh_hit *hit)
{
	return trace(t, ray, hit, false, &set);
}

bool tlas_occluded(const tlas *t, const bvh_ray *ray)
{
	bvh_hit unused;
	return trace(t, ray, &unused, true, NULL);
}

/* The circle in instance space, traced there, hits moved back to world space. */
static uint32_t circle_instance(const tlas *t, uint32_t id, const tri_circle *q, tri_circle_hit *hits, uint32_t room)
{
	const inst *in = &t->insts[id];
	if (in->scale <= 0.0f)
		return 0;
	tri_circle oq = {mul_point(in->w2o, q->centre), v3_normalize(mul_vector(in->w2o, q->t)),
			 v3_normalize(mul_vector(in->w2o, q->n)), q->radius / in->scale, q->full};
	uint32_t n = bvh_circle(in->geom, &oq, hits, room);
	for (uint32_t k = 0; k < n && k < room; k++) {
		hits[k].pos = mul_point(in->o2w, hits[k].pos);
		/* A similarity maps normals like vectors (up to scale). */
		hits[k].ng = v3_normalize(mul_vector(in->o2w, hits[k].ng));
		hits[k].inst = id;
	}
	return n;
}

/* The circle through the tree, on every instance (all) or on those of one set, in the
 * traversal's order. */
static uint32_t circle_tree(const tlas *t, const tri_circle *q, bool all, uint32_t set, tri_circle_hit *hits,
			    uint32_t max_hits)
{
	if (t->num_nodes == 0 || !bvh_box_circle(bvh_node_lo(&t->nodes[0]), bvh_node_hi(&t->nodes[0]), q))
		return 0;
	uint32_t stack[BVH_MAX_DEPTH + 2];
	int sp = 0;
	uint32_t ni = 0, total = 0;
	for (;;) {
		const bvh_node *nd = &t->nodes[ni];
		if (nd->count & BVH_INNER) {
			uint32_t c0 = nd->first, c1 = c0 + 1;
			const bvh_node *a = &t->nodes[c0], *b = &t->nodes[c1];
			bool h0 = bvh_box_circle(bvh_node_lo(a), bvh_node_hi(a), q);
			bool h1 = bvh_box_circle(bvh_node_lo(b), bvh_node_hi(b), q);
			assert(sp < BVH_MAX_DEPTH + 2); /* one push a level: bvh_build_nodes bounds the depth */
			if (bvh_descend(h0, h1, c0, stack, &sp, &ni))
				continue;
		} else {
			for (uint32_t k = 0; k < nd->count; k++) {
				uint32_t id = t->order[nd->first + k];
				assert(id < t->count);
				if (!all && t->insts[id].set != set)
					continue;
				uint32_t room = total < max_hits ? max_hits - total : 0;
				total += circle_instance(t, id, q, hits + (room ? total : 0), room);
			}
		}
		if (sp == 0)
			return total;
		ni = stack[--sp];
	}
}

/* The hits of several instances, each already in bvh_circle's order, put in the canonical one. */
static uint32_t sorted(tri_circle_hit *hits, uint32_t total, uint32_t max_hits)
{
	tri_circle_hits_sort(hits, total < max_hits ? total : max_hits);
	return total;
}

uint32_t tlas_circle(const tlas *t, const tri_circle *q, uint32_t only, tri_circle_hit *hits, uint32_t max_hits)
{
	if (only != TLAS_ALL_INSTANCES) /* one instance: bvh_circle's order is the canonical one */
		return only < t->count ? circle_instance(t, only, q, hits, max_hits) : 0;
	return sorted(hits, circle_tree(t, q, true, 0, hits, max_hits), max_hits);
}

uint32_t tlas_circle_set(const tlas *t, const tri_circle *q, uint32_t set, tri_circle_hit *hits, uint32_t max_hits)
{
	return sorted(hits, circle_tree(t, q, false, set, hits, max_hits), max_hits);
}

/* The squared distance from p to a node's box (0 inside). */
static double node_d2(const bvh_node *nd, vec3 p)
{
	double d2 = 0.0;
	float c[3] = {p.x, p.y, p.z};
	for (int k = 0; k < 3; k++) {
		double d = c[k] < nd->lo[k] ? (double)nd->lo[k] - c[k] : c[k] > nd->hi[k] ? (double)c[k] - nd->hi[k] : 0.0;
		d2 += d * d;
	}
	return d2;
}

/* An instance's part of tlas_nearest_set: the world distance's lower bound, capped. */
static float nearest_instance(const inst *in, const bvh_node *leaf, vec3 p, float cap)
{
	if (!(in->scale > 0.0f)) /* not a similarity: the world box's distance, a lower bound */
		return (float)fmin((double)cap, sqrt(node_d2(leaf, p)) * (1.0 - 1e-5));
	/* the float transforms are exact to a few ulps; 1e-5 of the distance is far more */
	const double slack = 1.0 - 1e-5;
	float d = bvh_nearest(in->geom, mul_point(in->w2o, p), (float)((double)cap / (in->scale * slack)));
	return (float)fmin((double)cap, d * in->scale * slack);
}

float tlas_nearest_set(const tlas *t, vec3 p, uint32_t set, float cap)
{
	if (!(cap > 0.0f))
		return 0.0f;
	if (t->num_nodes == 0 || !v3_is_finite(p))
		return cap;
	float best = cap;
	uint32_t stack[BVH_MAX_DEPTH + 2];
	int sp = 0;
	uint32_t ni = 0;
	for (;;) {
		const bvh_node *nd = &t->nodes[ni];
		double b2 = (double)best * best;
		if (nd->count & BVH_INNER) {
			uint32_t c0 = nd->first, c1 = c0 + 1;
			double d0 = node_d2(&t->nodes[c0], p), d1 = node_d2(&t->nodes[c1], p);
			bool h0 = d0 < b2, h1 = d1 < b2;
			if (h0 && h1 && d1 < d0) /* the nearer first */
				c0 = c1, c1 = nd->first, h0 = h1 = true;
			if (h0 && h1) {
				assert(sp < BVH_MAX_DEPTH + 2);
				stack[sp++] = c1;
				ni = c0;
				continue;
			}
			if (h0 || h1) {
				ni = h0 ? c0 : c1;
				continue;
			}
		} else {
			for (uint32_t k = 0; k < nd->count; k++) {
				const inst *in = &t->insts[t->order[nd->first + k]];
				if (in->set != set)
					continue;
				float d = nearest_instance(in, nd, p, best);
				if (d < best)
					best = d;
			}
		}
		if (sp == 0)
			return best;
		ni = stack[--sp];
	}
}
