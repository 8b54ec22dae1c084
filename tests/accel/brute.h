/* brute.h - test helpers of accel: loading the test assets, random rays and circles on a mesh,
 * and the brute-force references (every triangle through tri.h) that the BVH must equal. */
#ifndef CIRCE_TESTS_ACCEL_BRUTE_H
#define CIRCE_TESTS_ACCEL_BRUTE_H

#include "accel/bvh.h"
#include "base/rng.h"
#include "geom/mesh.h"

#include <stdio.h>

#include <stdlib.h>
#include <string.h>

/* $top_srcdir/rel, or ./rel when top_srcdir is unset. */
static inline const char *test_path(const char *rel)
{
	static char buf[4096];
	const char *top = getenv("top_srcdir");
	snprintf(buf, sizeof buf, "%s/%s", top ? top : ".", rel);
	return buf;
}

/* The BVH path of the test's builds, from the environment as circe's main reads it: CIRCE_SIMD=sse2
 * forces 4-wide SSE2 nodes on a CPU with AVX2 (tests/accel/sse2.sh runs every accel test so). */
static inline void test_simd_from_env(void)
{
	const char *s = getenv("CIRCE_SIMD");
	bvh_set_simd(s && strcmp(s, "sse2") == 0 ? BVH_SIMD_SSE2 : BVH_SIMD_AUTO);
}

/* CIRCE_TEST_SCALE divides the counts of the long tests; under AddressSanitizer (ten times
 * slower) it defaults to 20. */
static inline long test_count(long n)
{
	const char *s = getenv("CIRCE_TEST_SCALE");
#ifdef __SANITIZE_ADDRESS__
	long div = s ? atol(s) : 20;
#else
	long div = s ? atol(s) : 1;
#endif
	return div > 1 ? (n / div > 0 ? n / div : 1) : n;
}

/* The bunny of scenes/assets, centred on the origin and scaled to about unit size. */
static inline bool test_unit_bunny(mesh *bunny, diag *d)
{
	if (!mesh_import(test_path("scenes/assets/bunny/bunny_npm.obj"), bunny, d))
		return false;
	vec3 lo, hi;
	mesh_bounds(bunny, &lo, &hi);
	vec3 mid = v3_scale(v3_add(lo, hi), 0.5f);
	float ext = v3_max_comp(v3_sub(hi, lo));
	for (uint32_t v = 0; v < bunny->num_vertices; v++)
		bunny->positions[v] = v3_scale(v3_sub(bunny->positions[v], mid), 1.0f / ext);
	return true;
}

static inline vec3 test_tri_vertex(const mesh *m, uint32_t f, int c)
{
	return m->positions[m->indices[3 * f + c]];
}

/* A uniformly random point of triangle f. */
/* The point of hit h on m from its barycentrics (exactly on the triangle), and in *ng the
 * triangle's unit geometric normal by its winding; *scale (may be NULL) the triangle's largest
 * |coordinate| (accel/offset.h's scale). */
static inline vec3 test_hit_point(const mesh *m, const bvh_hit *h, vec3 *ng, float *scale)
{
	vec3 v0 = test_tri_vertex(m, h->prim, 0), v1 = test_tri_vertex(m, h->prim, 1), v2 = test_tri_vertex(m, h->prim, 2);
	*ng = v3_normalize(v3_cross(v3_sub(v1, v0), v3_sub(v2, v0)));
	if (scale) {
		vec3 a = v3_max(v3_max(v3_abs(v0), v3_abs(v1)), v3_abs(v2));
		*scale = fmaxf(a.x, fmaxf(a.y, a.z));
	}
	return v3_add(v3_add(v3_scale(v0, 1.0f - h->u - h->v), v3_scale(v1, h->u)), v3_scale(v2, h->v));
}

static inline vec3 test_point_on(const mesh *m, uint32_t f, rng *g)
{
	float a = rng_float(g), b = rng_float(g);
	if (a + b > 1.0f)
		a = 1.0f - a, b = 1.0f - b;
	vec3 v0 = test_tri_vertex(m, f, 0), v1 = test_tri_vertex(m, f, 1), v2 = test_tri_vertex(m, f, 2);
	return v3_add(v0, v3_add(v3_scale(v3_sub(v1, v0), a), v3_scale(v3_sub(v2, v0), b)));
}

static inline vec3 test_unit_vector(rng *g)
{
	float z = 1.0f - 2.0f * rng_float(g), phi = 6.2831853f * rng_float(g);
	float s = sqrtf(fmaxf(0.0f, 1.0f - z * z));
	return v3(s * cosf(phi), s * sinf(phi), z);
}

/* The triangles of a mesh as the brute-force references read them: three vertices each, and
 * whether tri_is_degenerate skips it (computed once, not per query). */
typedef struct brute {
	uint32_t n;
	vec3 *v;     /* 3 per triangle */
	bool *skip;
} brute;

static inline brute brute_make(const mesh *m)
{
	brute b = {m->num_triangles, malloc(3 * (size_t)m->num_triangles * sizeof(vec3) + 1),
		   malloc((size_t)m->num_triangles + 1)};
	for (uint32_t f = 0; f < m->num_triangles; f++) {
		for (int c = 0; c < 3; c++)
			b.v[3 * f + c] = test_tri_vertex(m, f, c);
		b.skip[f] = tri_is_degenerate(b.v[3 * f], b.v[3 * f + 1], b.v[3 * f + 2]);
	}
	return b;
}

static inline void brute_free(brute *b) { free(b->v), free(b->skip); }

/* Closest hit over every triangle, ties to the lower id, as bvh_intersect promises. */
static inline bool brute_intersect(const brute *m, const bvh_ray *ray, bvh_hit *hit)
{
	tri_ray r;
	if (!tri_ray_prepare(&r, ray->org, ray->dir, ray->tmin, ray->tmax))
		return false;
	float best = ray->tmax;
	bool found = false;
	const vec3 *v = m->v;
	for (uint32_t f = 0; f < m->n; f++, v += 3) {
		float t, a, b;
		if (!m->skip[f] && tri_intersect(&r, v[0], v[1], v[2], best, &t, &a, &b) && (t < best || !found)) {
			best = t, found = true;
			*hit = (bvh_hit){t, a, b, f, 0};
		}
	}
	return found;
}

static inline uint32_t brute_circle(const brute *m, const tri_circle *q, tri_circle_hit *hits, uint32_t max)
{
	uint32_t n = 0;
	if (!v3_is_finite(q->centre) || !isfinite(q->radius) || q->radius < 0.0f)
		return 0;
	const vec3 *v = m->v;
	for (uint32_t f = 0; f < m->n; f++, v += 3) {
		if (m->skip[f])
			continue;
		tri_circle_hit h[2];
		int k = tri_circle_intersect(q, v[0], v[1], v[2], h);
		for (int i = 0; i < k; i++, n++)
			if (n < max)
				hits[n] = h[i], hits[n].prim = f;
	}
	return n;
}


/* A random circle on the surface: centre on a random triangle, n its normal, t random in the
 * tangent plane, radius log-uniform in [1e-3, 0.5] of the extent; half or full. */
static inline tri_circle test_random_circle(const mesh *m, float extent, rng *g)
{
	uint32_t f = rng_below(g, m->num_triangles);
	vec3 v0 = test_tri_vertex(m, f, 0), v1 = test_tri_vertex(m, f, 1), v2 = test_tri_vertex(m, f, 2);
	vec3 n = v3_normalize(v3_cross(v3_sub(v1, v0), v3_sub(v2, v0)));
	if (!(v3_length2(n) > 0.5f))
		n = v3(0, 0, 1);
	vec3 b1, b2;
	v3_basis(n, &b1, &b2);
	float phi = 6.2831853f * rng_float(g);
	tri_circle q;
	q.centre = test_point_on(m, f, g);
	q.t = v3_normalize(v3_add(v3_scale(b1, cosf(phi)), v3_scale(b2, sinf(phi))));
	q.n = n;
	q.radius = extent * 1e-3f * powf(500.0f, rng_float(g));
	q.full = rng_float(g) < 0.5f;
	return q;
}

/* A random ray: from a random point of the enlarged bounds, towards a random surface point (half
 * of them) or in a random direction. */
static inline bvh_ray test_random_ray(const mesh *m, vec3 lo, vec3 hi, rng *g)
{
	vec3 ext = v3_sub(hi, lo);
	vec3 o = v3(lo.x - 0.5f * ext.x + 2.0f * ext.x * rng_float(g), lo.y - 0.5f * ext.y + 2.0f * ext.y * rng_float(g),
		    lo.z - 0.5f * ext.z + 2.0f * ext.z * rng_float(g));
	vec3 d = rng_float(g) < 0.5f ? v3_sub(test_point_on(m, rng_below(g, m->num_triangles), g), o)
				    : test_unit_vector(g);
	return (bvh_ray){o, d, 0.0f, INFINITY};
}

/* The comparisons of the tests (need check.h included first). */
#define MAX_HITS 4096

/* The distance from p to segment a b, in double. */
static inline double brute_segment_distance(dvec3 p, dvec3 a, dvec3 b)
{
	dvec3 ab = d3_sub(b, a), ap = d3_sub(p, a);
	double l2 = d3_dot(ab, ab), t = l2 > 0.0 ? d3_dot(ap, ab) / l2 : 0.0;
	t = t < 0.0 ? 0.0 : t > 1.0 ? 1.0 : t;
	return d3_length(d3_sub(ap, d3_scale(ab, t)));
}

/* The distance from p to the nearest triangle that the BVH keeps, in double, another way than
 * bvh_nearest's (Voronoi regions): the foot of the perpendicular on the plane when its
 * barycentrics are all >= 0, else the nearest of the three edges. */
static inline double brute_nearest(const brute *m, vec3 p)
{
	double best = INFINITY;
	dvec3 pd = v3_to_d3(p);
	for (uint32_t f = 0; f < m->n; f++) {
		if (m->skip[f])
			continue;
		dvec3 a = v3_to_d3(m->v[3 * f]), b = v3_to_d3(m->v[3 * f + 1]), c = v3_to_d3(m->v[3 * f + 2]);
		dvec3 n = d3_cross(d3_sub(b, a), d3_sub(c, a));
		double nn = d3_dot(n, n), d = INFINITY;
		if (nn > 0.0) {
			double h = d3_dot(d3_sub(pd, a), n) / nn;
			dvec3 q = d3_sub(pd, d3_scale(n, h)); /* the foot on the plane */
			double wa = d3_dot(d3_cross(d3_sub(b, q), d3_sub(c, q)), n);
			double wb = d3_dot(d3_cross(d3_sub(c, q), d3_sub(a, q)), n);
			double wc = d3_dot(d3_cross(d3_sub(a, q), d3_sub(b, q)), n);
			if (wa >= 0.0 && wb >= 0.0 && wc >= 0.0)
				d = fabs(h) * sqrt(nn);
		}
		if (!(d < INFINITY)) {
			d = brute_segment_distance(pd, a, b);
			d = fmin(d, brute_segment_distance(pd, b, c));
			d = fmin(d, brute_segment_distance(pd, c, a));
		}
		best = fmin(best, d);
	}
	return best;
}

/* bvh_nearest against brute_nearest at random points: the enlarged bounds (far and inside), and
 * points of the surface moved along a random direction by 1e-6 to 1e-1 of the extent (near). The
 * BVH's must be a lower bound (within the absolute 1e-12 of the extent that rounding may take)
 * and tight (within 1e-5); with a cap, the cap wherever the brute force's distance is beyond it. */
static inline void check_nearest(const char *name, const mesh *m, const brute *bf, const bvh *b, long count,
				 uint64_t seed)
{
	vec3 lo, hi;
	mesh_bounds(m, &lo, &hi);
	vec3 ext = v3_sub(hi, lo);
	double extent = v3_length(ext);
	rng g;
	rng_seed(&g, seed, 3);
	long bad = 0, capped = 0, near = 0;
	for (long i = 0; i < count; i++) {
		vec3 p;
		if (i % 2 == 0) {
			p = v3(lo.x - 0.5f * ext.x + 2.0f * ext.x * rng_float(&g), lo.y - 0.5f * ext.y + 2.0f * ext.y * rng_float(&g),
			       lo.z - 0.5f * ext.z + 2.0f * ext.z * rng_float(&g));
		} else {
			vec3 s = test_point_on(m, rng_below(&g, m->num_triangles), &g);
			p = v3_madd(s, test_unit_vector(&g), (float)(extent * 1e-6 * pow(1e5, rng_double(&g))));
			near++;
		}
		double want = brute_nearest(bf, p);
		float got = bvh_nearest(b, p, INFINITY);
		float cap = (float)(extent * 0.2 * rng_double(&g));
		float got_cap = bvh_nearest(b, p, cap);
		bool ok = got <= want + 1e-12 * extent && got >= want * (1.0 - 1e-5) - 1e-12 * extent;
		if (want >= cap)
			ok = ok && got_cap == cap, capped++;
		else
			ok = ok && got_cap == got;
		if (!ok && bad++ < 5)
			CHECK(0, "%s point %ld (%.9g %.9g %.9g): bvh %.17g (cap %.9g: %.17g), brute %.17g", name, i, p.x, p.y,
			      p.z, got, cap, got_cap, want);
	}
	CHECK(bad == 0, "%s: %ld of %ld nearest distances differ", name, bad, count);
	CHECK(capped > count / 20 && capped < count - count / 20, "%s: %ld of %ld capped", name, capped, count);
	CHECK(bvh_nearest(b, v3(NAN, 0, 0), 1.0f) == 1.0f && bvh_nearest(b, lo, 0.0f) == 0.0f &&
		      bvh_nearest(b, lo, -1.0f) == 0.0f,
	      "%s: nearest's edge cases", name);
	printf("%s: %ld nearest points (%ld near the surface, %ld capped), %ld differ\n", name, count, near, capped, bad);
}

static inline void check_rays(const char *name, const mesh *m, const brute *bf, const bvh *b, long count, uint64_t seed)
{
	vec3 lo, hi;
	mesh_bounds(m, &lo, &hi);
	rng g;
	rng_seed(&g, seed, 1);
	long hits = 0, bad = 0;
	for (long i = 0; i < count; i++) {
		bvh_ray ray = test_random_ray(m, lo, hi, &g);
		if (i % 4 == 3)
			ray.tmax = v3_length(v3_sub(hi, lo)) * rng_float(&g) / v3_length(ray.dir);
		bvh_hit hb = {0}, hr = {0};
		bool fb = bvh_intersect(b, &ray, &hb), fr = brute_intersect(bf, &ray, &hr);
		bool occ = bvh_occluded(b, &ray);
		hits += fr;
		if (fb != fr || occ != fr || (fr && (hb.t != hr.t || hb.u != hr.u || hb.v != hr.v || hb.prim != hr.prim))) {
			if (bad++ < 5)
				CHECK(0, "%s ray %ld: bvh %d (t %.9g prim %u) occluded %d, brute %d (t %.9g prim %u)", name, i,
				      fb, hb.t, hb.prim, occ, fr, hr.t, hr.prim);
		}
	}
	CHECK(bad == 0, "%s: %ld of %ld rays differ", name, bad, count);
	CHECK(hits > count / 5, "%s: %ld of %ld rays hit", name, hits, count);
	printf("%s: %ld rays, %ld hits, %ld differ\n", name, count, hits, bad);
}

/* min_hits: the fewest hits the circles must make in all (a closed mesh: about one per circle). */
static inline void check_circles(const char *name, const mesh *m, const brute *bf, const bvh *b, long count,
				 long min_hits, uint64_t seed)
{
	vec3 lo, hi;
	mesh_bounds(m, &lo, &hi);
	float extent = v3_length(v3_sub(hi, lo));
	static tri_circle_hit hb[MAX_HITS], hr[MAX_HITS];
	rng g;
	rng_seed(&g, seed, 2);
	long total = 0, bad = 0;
	for (long i = 0; i < count; i++) {
		tri_circle q = test_random_circle(m, extent, &g);
		uint32_t nb = bvh_circle(b, &q, hb, MAX_HITS), nr = brute_circle(bf, &q, hr, MAX_HITS);
		total += nr;
		bool same = nb == nr && nb <= MAX_HITS;
		if (same) {
			qsort(hb, nb, sizeof *hb, tri_circle_hit_cmp);
			qsort(hr, nr, sizeof *hr, tri_circle_hit_cmp);
			same = memcmp(hb, hr, nb * sizeof *hb) == 0;
		}
		if (!same && bad++ < 5)
			CHECK(0, "%s circle %ld (r %g, %s): bvh %u hits, brute %u", name, i, q.radius,
			      q.full ? "full" : "half", nb, nr);
	}
	CHECK(bad == 0, "%s: %ld of %ld circles differ", name, bad, count);
	CHECK(total >= min_hits, "%s: %ld hits for %ld circles", name, total, count);
	printf("%s: %ld circles, %ld hits, %ld differ\n", name, count, total, bad);
}

static inline void check_mesh_file(const char *rel, long rays, long circles)
{
	mesh m;
	diag d;
	diag_init(&d, stderr);
	const char *path = test_path(rel);
	if (!mesh_import(path, &m, &d)) {
		CHECK(0, "cannot read %s", path);
		diag_free(&d);
		return;
	}
	bvh *b = bvh_build(m.positions, m.num_vertices, m.indices, m.num_triangles);
	CHECK(b != NULL, "bvh of %s", rel);
	if (b) {
		brute bf = brute_make(&m);
		check_rays(rel, &m, &bf, b, rays, 11);
		check_circles(rel, &m, &bf, b, circles, circles, 12);
		check_nearest(rel, &m, &bf, b, circles / 50, 13);
		brute_free(&bf);
		bvh_free(b);
	}
	mesh_free(&m);
	diag_free(&d);
}

#endif
