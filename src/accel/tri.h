/* tri.h - the exact primitive tests of circe's BVH, shared by the traversal and by the brute-force
 * references of the tests, so both give bit-identical answers: the watertight ray/triangle test
 * (Woop, Benthin & Wald 2013, "Watertight Ray/Triangle Intersection", JCGT 2(1)) and the
 * circle/triangle test of circle tracing (DESIGN.md, "Circle sampling"). */
#ifndef CIRCE_ACCEL_TRI_H
#define CIRCE_ACCEL_TRI_H

#include "base/trig.h"
#include "base/vec.h"

#include <math.h>
#include <stdbool.h>
#ifdef __SSE2__
#include <emmintrin.h>
#endif
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* A ray ready for the watertight test: origin, direction, the closed interval [tmin, tmax], and
 * the shear of Woop et al. (section 3): kz the dominant axis of dir, kx and ky the others in an
 * order that keeps the winding, s = (dx/dz, dy/dz, 1/dz). */
typedef struct tri_ray {
	vec3 org, dir, inv_dir;
	float tmin, tmax;
	int kx, ky, kz;
	float sx, sy, sz;
} tri_ray;

/* False, leaving *r unusable, when a component of org or dir is NaN or infinite, dir is zero,
 * tmin is not finite or negative, tmax is NaN or tmax < tmin. */
static inline bool tri_ray_prepare(tri_ray *r, vec3 org, vec3 dir, float tmin, float tmax)
{
	if (!v3_is_finite(org) || !v3_is_finite(dir) || !isfinite(tmin) || tmin < 0.0f ||
	    isnan(tmax) || tmax < tmin || (dir.x == 0.0f && dir.y == 0.0f && dir.z == 0.0f))
		return false;
	r->org = org, r->dir = dir, r->tmin = tmin, r->tmax = tmax;
	/* The axes without branches (for incoherent rays each is a coin toss): kz the largest |d| (x
	 * only when larger than both, then y when larger than z, else z), kx and ky the next two in
	 * turn, swapped when d[kz] < 0. */
	vec3 a = v3_abs(dir);
	int xy = a.x > a.y;
	float axy = xy ? a.x : a.y;
	int kz = axy > a.z ? 1 - xy : 2;
	static const int next_axis[3] = {1, 2, 0};
	int kx = next_axis[kz], ky = next_axis[kx];
	float dz = v3_get(dir, kz);
	int swap = -(int)(dz < 0.0f);
	int dk = (kx ^ ky) & swap;
	kx ^= dk, ky ^= dk;
	r->kx = kx, r->ky = ky, r->kz = kz;
#ifdef __SSE2__
	/* The six quotients as two vector divisions (each lane rounds as the scalar division does):
	 * the set-up is a good part of a ray that misses after a node or two. */
	float q[4], s[4];
	_mm_storeu_ps(q, _mm_div_ps(_mm_set1_ps(1.0f), _mm_setr_ps(dir.x, dir.y, dir.z, 1.0f)));
	_mm_storeu_ps(s, _mm_div_ps(_mm_setr_ps(v3_get(dir, kx), v3_get(dir, ky), 1.0f, 1.0f), _mm_set1_ps(dz)));
	r->inv_dir = v3(q[0], q[1], q[2]);
	r->sx = s[0], r->sy = s[1], r->sz = s[2];
#else
	r->inv_dir = v3(1.0f / dir.x, 1.0f / dir.y, 1.0f / dir.z);
	r->sx = v3_get(dir, kx) / dz, r->sy = v3_get(dir, ky) / dz, r->sz = 1.0f / dz;
#endif
	return true;
}

/* True when the triangle cannot be hit: a vertex is not finite or its area is zero in float.
 * Such triangles are left out of the BVH, and the brute-force references skip them too. */
static inline bool tri_is_degenerate(vec3 v0, vec3 v1, vec3 v2)
{
	if (!v3_is_finite(v0) || !v3_is_finite(v1) || !v3_is_finite(v2))
		return true;
	vec3 c = v3_cross(v3_sub(v1, v0), v3_sub(v2, v0));
	return !(v3_length2(c) > 0.0f) || !v3_is_finite(c);
}

/* Woop, Benthin & Wald 2013, figure 10. Hits with t in [r->tmin, tlimit] and returns t and the
 * barycentrics (u, v) of v1 and v2 (the point is (1-u-v) v0 + u v1 + v v2). Both sides hit. Edges
 * and vertices shared by two triangles are hit by at least one of them. */
static inline bool tri_intersect(const tri_ray *r, vec3 v0, vec3 v1, vec3 v2, float tlimit, float *t,
				 float *u, float *v)
{
	/* Vertices relative to the origin, indexed by the ray's axis permutation (loads, not
	 * branches: kx, ky, kz vary from ray to ray). */
	float A[3] = {v0.x - r->org.x, v0.y - r->org.y, v0.z - r->org.z};
	float B[3] = {v1.x - r->org.x, v1.y - r->org.y, v1.z - r->org.z};
	float C[3] = {v2.x - r->org.x, v2.y - r->org.y, v2.z - r->org.z};
	float Az = A[r->kz], Bz = B[r->kz], Cz = C[r->kz];
	float Ax = A[r->kx] - r->sx * Az, Ay = A[r->ky] - r->sy * Az;
	float Bx = B[r->kx] - r->sx * Bz, By = B[r->ky] - r->sy * Bz;
	float Cx = C[r->kx] - r->sx * Cz, Cy = C[r->ky] - r->sy * Cz;
	float U = Cx * By - Cy * Bx, V = Ax * Cy - Ay * Cx, W = Bx * Ay - By * Ax;
	if (U == 0.0f || V == 0.0f || W == 0.0f) {
		/* On an edge in float: decide in double so both neighbours agree (section 3.3). */
		U = (float)((double)Cx * By - (double)Cy * Bx);
		V = (float)((double)Ax * Cy - (double)Ay * Cx);
		W = (float)((double)Bx * Ay - (double)By * Ax);
	}
	if ((U < 0.0f || V < 0.0f || W < 0.0f) && (U > 0.0f || V > 0.0f || W > 0.0f))
		return false;
	float det = U + V + W;
	if (det == 0.0f)
		return false;
	float T = U * (r->sz * Az) + V * (r->sz * Bz) + W * (r->sz * Cz);
	float tt = T / det;
	if (!(tt >= r->tmin && tt <= tlimit))
		return false;
	*t = tt, *u = V / det, *v = W / det;
	return true;
}

/* A circle of circle tracing: c(theta) = centre + radius (cos theta t + sin theta n), t and n unit
 * and orthogonal. A half circle keeps theta in [-pi/2, pi/2]; a full one theta in [0, 2 pi). */
typedef struct tri_circle {
	vec3 centre, t, n;
	float radius;
	bool full;
} tri_circle;

typedef struct tri_circle_hit {
	vec3 pos;    /* on the triangle and on the circle */
	float theta; /* circle angle of pos */
	float u, v;  /* barycentrics of v1 and v2 */
	vec3 ng;     /* unit geometric normal, (v1 - v0) x (v2 - v0) normalised */
	uint32_t prim, inst;
} tri_circle_hit;

/* The canonical order of circle hits (a qsort comparator): by instance, triangle, then angle.
 * A traversal reports hits in an order that depends on every box test on the way, not only on the
 * hits; the circle queries (bvh_circle, tlas_circle) sort them before they return, so a choice
 * among hits (and the image) does not change when the tree is built or traversed differently.
 * Instance and triangle first, not the angle: it is the order the goldens were rendered in (a
 * resampling's cumulative sum walks the hits in this order), and two hits of one triangle and
 * one instance have distinct angles, so the order is total on the hits of one circle. */
static inline int tri_circle_hit_cmp(const void *a, const void *b)
{
	const tri_circle_hit *x = a, *y = b;
	if (x->inst != y->inst)
		return x->inst < y->inst ? -1 : 1;
	if (x->prim != y->prim)
		return x->prim < y->prim ? -1 : 1;
	return x->theta < y->theta ? -1 : x->theta > y->theta ? 1 : 0;
}

/* Up to this many hits are sorted by insertion, inline: a circle has a few hits (bench/rays.sh's
 * bunny circles: 1.0 on average), where qsort's calls through a pointer cost 2 % of a circle
 * query; more go to qsort. */
#define TRI_CIRCLE_SORT_INSERTION 16

/* Puts hits[0, n) in the canonical order (tri_circle_hit_cmp: total on one circle's hits, so
 * both sorts give the same order). */
static inline void tri_circle_hits_sort(tri_circle_hit *hits, uint32_t n)
{
	if (n > TRI_CIRCLE_SORT_INSERTION) {
		qsort(hits, n, sizeof *hits, tri_circle_hit_cmp);
		return;
	}
	for (uint32_t i = 1; i < n; i++) {
		tri_circle_hit h = hits[i];
		uint32_t j = i;
		for (; j > 0 && tri_circle_hit_cmp(&hits[j - 1], &h) > 0; j--)
			hits[j] = hits[j - 1];
		hits[j] = h;
	}
}

/* The relative margin of the circle/triangle float pre-tests (tri_circle_intersect's and the BVH's
 * leaf test's): it bounds the float error of m . (v - c) against the double test's
 * M . (P - C): with t and n unit, m's components are off by at most 2.4e-7, v - c by 6e-8 of
 * |v| + |c| a coordinate, the products and sums by 1.8e-7 of their magnitudes, under 5e-7 of
 * the sum over axes of |v| + |c| in all; the margin, 3e-6 of the triangle's and the centre's
 * twelve magnitudes, is six times that. So only triangles the double test would also reject
 * are skipped. (1e-5 before: 1.64 triangles a circle on the head reached the exact test instead of
 * 1.41, for 1.24 hits.) */
#define TRI_CIRCLE_MARGIN 3e-6f

/* A circle in double, as the exact test uses it: centre, axes and the plane normal M = T x N. The
 * BVH prepares it once a circle (tri_circle_exact_prepared); the values are those the exact test
 * would compute itself, so the hits are the same bits either way. */
typedef struct tri_circle_d {
	dvec3 C, T, N, M;
	double r;
	bool full;
} tri_circle_d;

static inline void tri_circle_d_prepare(const tri_circle *c, tri_circle_d *cd)
{
	cd->C = v3_to_d3(c->centre), cd->T = v3_to_d3(c->t), cd->N = v3_to_d3(c->n);
	cd->M = d3_cross(cd->T, cd->N);
	cd->r = c->radius, cd->full = c->full;
}

/* Inlined into the BVH's leaf loop even though it is long: called out of line, its spills and
 * reloads of the prepared circle cost 50 instructions a test. */
#define TRI_ALWAYS_INLINE static inline __attribute__((always_inline))

/* Exact circle/triangle test, in double: the triangle is clipped to the circle's plane, giving a
 * segment, and the segment is solved against the circle. Writes up to two hits to out and returns
 * their number. A triangle lying in the circle's plane gives none: the circle would run inside it,
 * where the hit density |n_i . e_theta| is zero (DESIGN.md). Degenerate triangles give none. */
TRI_ALWAYS_INLINE int tri_circle_exact_prepared(const tri_circle_d *c, vec3 v0, vec3 v1, vec3 v2,
						tri_circle_hit out[2]);

/* The exact test in two halves, for callers that overlap several triangles' tests (the BVH: each
 * half is a long chain of dependent operations, two divisions and a square root, then a division
 * and atan2's two): tri_circle_segment_solve clips the triangle to the plane and solves the segment's
 * circle equation, returning the number of roots (0: no hit); tri_circle_segment_hits keeps the
 * roots on the segment and on the circle's side and writes their hits. */
typedef struct tri_circle_segment {
	dvec3 S0, D, ng;		 /* the segment S0 + s D, s in [0, 1], and the triangle's normal */
	double su0, sv0, su1, sv1, s[2]; /* the ends' barycentrics, the roots */
} tri_circle_segment;
TRI_ALWAYS_INLINE int tri_circle_segment_solve(const tri_circle_d *c, vec3 v0, vec3 v1, vec3 v2,
					       tri_circle_segment *g);
TRI_ALWAYS_INLINE int tri_circle_segment_hits(const tri_circle_d *c, const tri_circle_segment *g, int nr,
					      tri_circle_hit out[2]);

static inline int tri_circle_exact(const tri_circle *c, vec3 v0, vec3 v1, vec3 v2, tri_circle_hit out[2])
{
	tri_circle_d cd;
	tri_circle_d_prepare(c, &cd);
	return tri_circle_exact_prepared(&cd, v0, v1, v2, out);
}

static inline int tri_circle_intersect(const tri_circle *c, vec3 v0, vec3 v1, vec3 v2,
				       tri_circle_hit out[2])
{
	/* A float pre-test: a triangle whose vertices lie clearly on one side of the circle's plane
	 * cannot meet it (the margin: TRI_CIRCLE_MARGIN). */
	vec3 mf = v3_cross(c->t, c->n);
	float d0 = v3_dot(mf, v3_sub(v0, c->centre)), d1 = v3_dot(mf, v3_sub(v1, c->centre)),
	      d2 = v3_dot(mf, v3_sub(v2, c->centre));
	vec3 mag = v3_add(v3_add(v3_abs(v0), v3_abs(v1)), v3_add(v3_abs(v2), v3_abs(c->centre)));
	float margin = TRI_CIRCLE_MARGIN * (mag.x + mag.y + mag.z);
	if ((d0 > margin && d1 > margin && d2 > margin) || (d0 < -margin && d1 < -margin && d2 < -margin))
		return 0;
	return tri_circle_exact(c, v0, v1, v2, out);
}

/* Where edge (i, j) of a triangle, its ends Pi and Pj at plane distances di and dj of opposite
 * signs and with barycentrics (ui, vi) and (uj, vj) of v1 and v2, crosses the plane: the point,
 * and its barycentrics. */
static inline dvec3 tri_edge_crossing(dvec3 Pi, dvec3 Pj, double di, double dj, double ui, double vi,
				      double uj, double vj, double *su, double *sv)
{
	double s = di / (di - dj);
	*su = ui + s * (uj - ui), *sv = vi + s * (vj - vi);
	return d3_add(Pi, d3_scale(d3_sub(Pj, Pi), s));
}

TRI_ALWAYS_INLINE int tri_circle_segment_solve(const tri_circle_d *c, vec3 v0, vec3 v1, vec3 v2,
					       tri_circle_segment *g)
{
	dvec3 C = c->C, M = c->M;
	dvec3 P0 = v3_to_d3(v0), P1 = v3_to_d3(v1), P2 = v3_to_d3(v2);
	double d0 = d3_dot(M, d3_sub(P0, C)), d1 = d3_dot(M, d3_sub(P1, C)), d2 = d3_dot(M, d3_sub(P2, C));
	/* Vertices above (bit i of above) and below the plane: none when all are on one side or
	 * all on the plane. */
	int above = (d0 > 0.0) | (d1 > 0.0) << 1 | (d2 > 0.0) << 2;
	int below = (d0 < 0.0) | (d1 < 0.0) << 1 | (d2 < 0.0) << 2;
	if (above == 7 || below == 7 || (above | below) == 0)
		return 0;
	dvec3 ng = d3_cross(d3_sub(P1, P0), d3_sub(P2, P0));
	if (!(d3_dot(ng, ng) > 0.0))
		return 0;
	/* The segment [S0, S1]: vertices on the plane and crossings of edges (i, i + 1) whose ends
	 * lie on opposite sides, in the order of i, each with its barycentrics (of v1, v2). */
	dvec3 S0, S1;
	double su0, sv0, su1, sv1;
	const dvec3 P[3] = {P0, P1, P2};
	const double d[3] = {d0, d1, d2}, bu[3] = {0, 1, 0}, bv[3] = {0, 0, 1};
	if ((above | below) == 7) {
		/* No vertex on the plane (the usual case): two edges cross. S0 is edge 0's crossing
		 * when it crosses, else edge 1's; S1 edge 2's when it crosses, else edge 1's: indices
		 * without a branch (which edges cross is a coin toss). */
		int c0 = (d0 < 0.0) != (d1 < 0.0), c2 = (d2 < 0.0) != (d0 < 0.0);
		int i0 = 1 - c0, j0 = 2 - c0, i1 = 1 + c2, j1 = 2 - 2 * c2;
		S0 =
		    tri_edge_crossing(P[i0], P[j0], d[i0], d[j0], bu[i0], bv[i0], bu[j0], bv[j0], &su0, &sv0);
		S1 =
		    tri_edge_crossing(P[i1], P[j1], d[i1], d[j1], bu[i1], bv[i1], bu[j1], bv[j1], &su1, &sv1);
	} else {
		dvec3 S[3];
		double su[3], sv[3];
		int ns = 0;
		for (int i = 0; i < 3; i++) {
			int j = i == 2 ? 0 : i + 1;
			if (d[i] == 0.0) {
				S[ns] = P[i], su[ns] = i == 1, sv[ns] = i == 2, ns++;
			} else if ((d[i] < 0.0 && d[j] > 0.0) || (d[i] > 0.0 && d[j] < 0.0)) {
				S[ns] = tri_edge_crossing(P[i], P[j], d[i], d[j], bu[i], bv[i], bu[j], bv[j],
							  &su[ns], &sv[ns]);
				ns++;
			}
		}
		if (ns != 2)
			return 0;
		S0 = S[0], S1 = S[1], su0 = su[0], sv0 = sv[0], su1 = su[1], sv1 = sv[1];
	}
	/* |S0 + s D - C|^2 = r^2 for s in [0, 1]. */
	dvec3 D = d3_sub(S1, S0), E = d3_sub(S0, C);
	double a = d3_dot(D, D), b = d3_dot(D, E), r = c->r;
	double cc = d3_dot(E, E) - r * r;
	if (!(a > 0.0))
		return 0;
	double disc = b * b - a * cc;
	if (disc < 0.0)
		return 0;
	double sq = sqrt(disc);
	/* Stable roots: q = -(b + sign(b) sq), s = q / a and cc / q. sq takes b's sign (+ for b >= 0,
	 * so also for -0) by its sign bit: no branch on b, whose sign is a coin toss (b - sq is
	 * b + -sq exactly). */
	uint64_t bits;
	memcpy(&bits, &sq, sizeof bits);
	bits ^= (uint64_t)!(b >= 0.0) << 63;
	double signed_sq;
	memcpy(&signed_sq, &bits, sizeof signed_sq);
	double q = -(b + signed_sq);
	g->S0 = S0, g->D = D, g->ng = ng;
	g->su0 = su0, g->sv0 = sv0, g->su1 = su1, g->sv1 = sv1;
	if (q == 0.0) {
		g->s[0] = 0.0; /* b == 0 and disc == 0: the segment touches at S0 */
		return 1;
	}
	g->s[0] = q / a, g->s[1] = cc / q;
	return disc > 0.0 ? 2 : 1;
}

TRI_ALWAYS_INLINE int tri_circle_segment_hits(const tri_circle_d *c, const tri_circle_segment *g, int nr,
					      tri_circle_hit out[2])
{
	dvec3 C = c->C, T = c->T, N = c->N, S0 = g->S0, D = g->D;
	double su0 = g->su0, sv0 = g->sv0, su1 = g->su1, sv1 = g->sv1;
	int nh = 0;
	vec3 ngu = v3s(0.0f);
	for (int k = 0; k < nr; k++) {
		double s = g->s[k];
		if (!(s >= 0.0 && s <= 1.0))
			continue;
		dvec3 x = d3_add(S0, d3_scale(D, s));
		dvec3 rel = d3_sub(x, C);
		double ct = d3_dot(rel, T), st = d3_dot(rel, N);
		if (!c->full && ct < 0.0)
			continue;
		double theta = trig_atan2(st, ct);
		if (c->full && theta < 0.0)
			theta += 2.0 * M_PI;
		if (nh == 0)
			ngu = d3_to_v3(d3_normalize(g->ng)); /* only for hits */
		tri_circle_hit *h = &out[nh++];
		h->pos = d3_to_v3(x);
		h->theta = (float)theta;
		h->u = (float)(su0 + s * (su1 - su0));
		h->v = (float)(sv0 + s * (sv1 - sv0));
		h->ng = ngu;
		h->prim = h->inst = 0;
	}
	return nh;
}

TRI_ALWAYS_INLINE int tri_circle_exact_prepared(const tri_circle_d *c, vec3 v0, vec3 v1, vec3 v2,
						tri_circle_hit out[2])
{
	tri_circle_segment g;
	int nr = tri_circle_segment_solve(c, v0, v1, v2, &g);
	return nr ? tri_circle_segment_hits(c, &g, nr, out) : 0;
}

#endif
