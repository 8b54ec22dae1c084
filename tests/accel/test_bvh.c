/* test_bvh: ray and circle traversal of the BVH equal brute force over every triangle, exactly. */
#include "accel/bvh_internal.h"
#include "check.h"
#include "brute.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Rays with NaN or Inf components are refused before traversal; so are circles. */
static void check_bad_input(void)
{
	vec3 p[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
	uint32_t ix[3] = {0, 1, 2};
	bvh *b = bvh_build(p, 3, ix, 1);
	bvh_hit h;
	float bad[] = {NAN, INFINITY, -INFINITY};
	for (int i = 0; i < 3; i++) {
		bvh_ray r = {{0.2f, 0.2f, 1}, {0, 0, -1}, 0, INFINITY};
		CHECK(bvh_intersect(b, &r, &h), "the good ray hits");
		bvh_ray r1 = r, r2 = r, r3 = r;
		r1.org.x = bad[i], r2.dir.y = bad[i], r3.tmin = bad[i];
		CHECK(!bvh_intersect(b, &r1, &h) && !bvh_occluded(b, &r1), "origin %g refused", bad[i]);
		CHECK(!bvh_intersect(b, &r2, &h) && !bvh_occluded(b, &r2), "direction %g refused", bad[i]);
		CHECK(!bvh_intersect(b, &r3, &h), "tmin %g refused", bad[i]);
		tri_circle q = {{0.2f, 0.2f, 0}, {1, 0, 0}, {0, 0, 1}, bad[i], false};
		tri_circle_hit ch[4];
		CHECK(bvh_circle(b, &q, ch, 4) == 0, "radius %g gives no hits", bad[i]);
	}
	bvh_ray zero = {{0.2f, 0.2f, 1}, {0, 0, 0}, 0, INFINITY};
	CHECK(!bvh_intersect(b, &zero, &h), "zero direction refused");
	uint32_t oob[3] = {0, 1, 3};
	CHECK(bvh_build(p, 3, oob, 1) == NULL, "index out of range refused");
	bvh_free(b);
	bvh *e = bvh_build(p, 3, ix, 0);
	bvh_ray r = {{0.2f, 0.2f, 1}, {0, 0, -1}, 0, INFINITY};
	CHECK(e && !bvh_intersect(e, &r, &h) && !bvh_occluded(e, &r), "an empty bvh hits nothing");
	bvh_free(e);
}

/* Degenerate (collinear, zero-area, NaN) and duplicated triangles never crash and never hit; of
 * duplicates, the lower id wins. */
static void check_degenerate(void)
{
	enum { N = 4000 };
	vec3 *p = malloc(3 * N * sizeof *p);
	uint32_t *ix = malloc(3 * N * sizeof *ix);
	rng g;
	rng_seed(&g, 5, 5);
	for (uint32_t f = 0; f < N; f++) {
		vec3 a = v3(rng_float(&g), rng_float(&g), rng_float(&g)), b = v3(rng_float(&g), rng_float(&g), rng_float(&g));
		switch (f % 5) {
		case 0: /* a point */
			p[3 * f] = p[3 * f + 1] = p[3 * f + 2] = a;
			break;
		case 1: /* collinear along an axis, and two equal vertices */
			p[3 * f] = a, p[3 * f + 1] = v3(b.x, a.y, a.z), p[3 * f + 2] = v3(rng_float(&g), a.y, a.z);
			if (f % 2)
				p[3 * f + 2] = b, p[3 * f + 1] = b;
			break;
		case 2: /* NaN vertex */
			p[3 * f] = a, p[3 * f + 1] = b, p[3 * f + 2] = v3(NAN, 0, 0);
			break;
		case 3: /* a proper triangle */
			p[3 * f] = a, p[3 * f + 1] = b, p[3 * f + 2] = v3(rng_float(&g), rng_float(&g), rng_float(&g));
			break;
		case 4: /* the previous one again */
			p[3 * f] = p[3 * f - 3], p[3 * f + 1] = p[3 * f - 2], p[3 * f + 2] = p[3 * f - 1];
			break;
		}
		ix[3 * f] = 3 * f, ix[3 * f + 1] = 3 * f + 1, ix[3 * f + 2] = 3 * f + 2;
	}
	mesh m = {.num_vertices = 3 * N, .num_triangles = N, .positions = p, .indices = ix};
	bvh *b = bvh_build(p, 3 * N, ix, N);
	brute bf = brute_make(&m);
	CHECK(b != NULL, "bvh over degenerate triangles");
	long bad = 0, hits = 0;
	for (int i = 0; i < 20000 && b; i++) {
		bvh_ray r = test_random_ray(&m, v3s(0), v3s(1), &g);
		bvh_hit hb = {0}, hr = {0};
		bool fb = bvh_intersect(b, &r, &hb), fr = brute_intersect(&bf, &r, &hr);
		hits += fb;
		if (fb != fr || (fb && (hb.prim != hr.prim || hb.t != hr.t)) || (fb && hb.prim % 5 != 3)) {
			if (bad++ < 5)
				CHECK(0, "ray %d: bvh %d prim %u t %g, brute %d prim %u t %g", i, fb, hb.prim, hb.t, fr,
				      hr.prim, hr.t);
		}
		tri_circle q = test_random_circle(&m, 1.0f, &g);
		static tri_circle_hit ch[MAX_HITS];
		uint32_t nc = bvh_circle(b, &q, ch, MAX_HITS);
		for (uint32_t k = 0; k < nc && k < MAX_HITS; k++)
			if (ch[k].prim % 5 != 3 && ch[k].prim % 5 != 4 && bad++ < 5)
				CHECK(0, "circle %d hits degenerate triangle %u", i, ch[k].prim);
	}
	CHECK(bad == 0 && hits > 0, "%ld bad answers among degenerate triangles (%ld hits)", bad, hits);
	bvh_free(b);
	brute_free(&bf);
	free(p), free(ix);
}

/* Meshes of a few triangles: a root that is a leaf, 4-wide nodes with empty slots, leaves of every
 * size, and few-binned splits. */
static void check_small_meshes(void)
{
	static const uint32_t sizes[] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 12, 16, 17, 31, 64, 257};
	rng g;
	rng_seed(&g, 9, 9);
	for (size_t s = 0; s < sizeof sizes / sizeof *sizes; s++) {
		uint32_t n = sizes[s];
		vec3 *p = malloc(3 * n * sizeof *p);
		uint32_t *ix = malloc(3 * n * sizeof *ix);
		for (uint32_t i = 0; i < 3 * n; i++) {
			vec3 c = v3(rng_float(&g), rng_float(&g), rng_float(&g));
			p[i] = i % 3 ? v3_add(p[i - i % 3], v3_scale(v3_sub(c, v3s(0.5f)), 0.4f)) : c;
			ix[i] = i;
		}
		mesh m = {.num_vertices = 3 * n, .num_triangles = n, .positions = p, .indices = ix};
		bvh *b = bvh_build(p, 3 * n, ix, n);
		CHECK(b != NULL, "bvh of %u triangles", n);
		if (b) {
			char name[32];
			snprintf(name, sizeof name, "%u triangles", n);
			brute bf = brute_make(&m);
			check_rays(name, &m, &bf, b, 2000, 21 + s);
			check_circles(name, &m, &bf, b, 2000, 500, 22 + s); /* a soup: some circles miss */
			brute_free(&bf);
		}
		bvh_free(b);
		free(p), free(ix);
	}
}

/* Rays aimed exactly at vertices and edge midpoints, where U, V or W of the watertight test is
 * zero in float and the double-precision decision runs (in the four-wide leaf test, those lanes
 * fall back to tri_intersect). */
static void check_edge_rays(const char *rel)
{
	mesh m;
	diag d;
	diag_init(&d, stderr);
	if (!mesh_import(test_path(rel), &m, &d)) {
		CHECK(0, "cannot read %s", rel);
		diag_free(&d);
		return;
	}
	bvh *b = bvh_build(m.positions, m.num_vertices, m.indices, m.num_triangles);
	brute bf = brute_make(&m);
	vec3 lo, hi;
	mesh_bounds(&m, &lo, &hi);
	rng g;
	rng_seed(&g, 31, 31);
	long bad = 0, hits = 0, n = test_count(20000);
	for (long i = 0; i < n && b; i++) {
		uint32_t f = rng_below(&g, m.num_triangles);
		vec3 v0 = test_tri_vertex(&m, f, 0), v1 = test_tri_vertex(&m, f, 1);
		vec3 target = i % 2 ? v0 : v3_scale(v3_add(v0, v1), 0.5f);
		bvh_ray r = test_random_ray(&m, lo, hi, &g);
		r.dir = v3_sub(target, r.org);
		bvh_hit hb = {0}, hr = {0};
		bool fb = bvh_intersect(b, &r, &hb), fr = brute_intersect(&bf, &r, &hr), occ = bvh_occluded(b, &r);
		hits += fr;
		if ((fb != fr || occ != fr || (fr && (hb.t != hr.t || hb.u != hr.u || hb.v != hr.v || hb.prim != hr.prim))) &&
		    bad++ < 5)
			CHECK(0, "%s edge ray %ld: bvh %d (t %.9g prim %u) occluded %d, brute %d (t %.9g prim %u)", rel, i, fb,
			      hb.t, hb.prim, occ, fr, hr.t, hr.prim);
	}
	CHECK(b && bad == 0 && hits > n / 2, "%s: %ld of %ld edge rays differ (%ld hits)", rel, bad, n, hits);
	printf("%s: %ld rays at vertices and edges, %ld hits, %ld differ\n", rel, n, hits, bad);
	brute_free(&bf);
	bvh_free(b);
	mesh_free(&m);
	diag_free(&d);
}

/* The node width follows the dispatch: 4 (SSE2) when CIRCE_SIMD is "sse2" (tests/accel/sse2.sh runs
 * every accel test so; test_simd_from_env passes it to bvh_set_simd), else 8 where the CPU has
 * AVX2. bvh_set_simd(BVH_SIMD_SSE2) gives 4 on any CPU, and a tree keeps its width after the
 * setting changes. */
static void check_width(void)
{
	vec3 p[3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
	uint32_t ix[3] = {0, 1, 2};
	bvh *b = bvh_build(p, 3, ix, 1);
	const char *simd = getenv("CIRCE_SIMD");
	uint32_t want = 4;
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
	if (!(simd && strcmp(simd, "sse2") == 0) && __builtin_cpu_supports("avx2"))
		want = 8;
#endif
	printf("CIRCE_SIMD=%s: nodes of %u children\n", simd ? simd : "(unset)", b ? bvh_width(b) : 0);
	CHECK(b && bvh_width(b) == want, "node width %u, expected %u", b ? bvh_width(b) : 0, want);
	bvh_set_simd(BVH_SIMD_SSE2);
	bvh *b4 = bvh_build(p, 3, ix, 1);
	test_simd_from_env();
	CHECK(b4 && bvh_width(b4) == 4, "node width %u under BVH_SIMD_SSE2, expected 4", b4 ? bvh_width(b4) : 0);
	CHECK(b && bvh_width(b) == want, "node width %u after the setting changed, expected %u",
	      b ? bvh_width(b) : 0, want);
	bvh_free(b4);
	bvh_free(b);
}

/* bvh_box_circle is conservative: a box holding a point of the arc (sampled at 4096 angles) always
 * passes, over 4000 random circles (half and full, radii from 1e-3 to 10, centres up to 100 from the
 * origin) and boxes around them. And it culls: boxes wholly off the plane, inside the sphere,
 * outside it or (half circles) behind the centre fail. */
static void check_box_circle(void)
{
	rng g;
	rng_seed(&g, 5, 9);
	long holding = 0, missed = 0, culled = 0, cull_cases = 0, circles = test_count(4000);
	for (int i = 0; i < circles; i++) {
		tri_circle q;
		q.centre = v3_scale(v3_sub(v3(rng_float(&g), rng_float(&g), rng_float(&g)), v3s(0.5f)), 200.0f * rng_float(&g));
		q.n = test_unit_vector(&g);
		vec3 b1, b2;
		v3_basis(q.n, &b1, &b2);
		float phi = 6.2831853f * rng_float(&g);
		q.t = v3_normalize(v3_add(v3_scale(b1, cosf(phi)), v3_scale(b2, sinf(phi))));
		q.radius = 1e-3f * powf(1e4f, rng_float(&g));
		q.full = i % 2 == 0;
		vec3 m = v3_normalize(v3_cross(q.t, q.n));
		float r = q.radius;
		/* Random boxes near the arc, from a hundredth of r to twice r across. */
		for (int j = 0; j < 8; j++) {
			float th0 = q.full ? 6.2831853f * rng_float(&g) : 3.1415927f * (rng_float(&g) - 0.5f);
			vec3 on = v3_add(q.centre, v3_scale(v3_add(v3_scale(q.t, cosf(th0)), v3_scale(q.n, sinf(th0))), r));
			vec3 at = v3_add(on, v3_scale(v3_sub(v3(rng_float(&g), rng_float(&g), rng_float(&g)), v3s(0.5f)), r));
			vec3 half = v3_scale(v3(rng_float(&g), rng_float(&g), rng_float(&g)), r * powf(100.0f, rng_float(&g)) / 100.0f);
			vec3 lo = v3_sub(at, half), hi = v3_add(at, half);
			bool holds = false;
			for (int k = 0; k < 4096 && !holds; k++) {
				float th = q.full ? 6.2831853f * k / 4096.0f : 3.1415927f * (k / 4095.0f - 0.5f);
				vec3 p = v3_add(q.centre, v3_scale(v3_add(v3_scale(q.t, cosf(th)), v3_scale(q.n, sinf(th))), r));
				holds = p.x > lo.x && p.x < hi.x && p.y > lo.y && p.y < hi.y && p.z > lo.z && p.z < hi.z;
			}
			holding += holds;
			if (holds && !bvh_box_circle(lo, hi, &q) && missed++ < 5)
				CHECK(0, "circle %d box %d holds a point of the arc and fails the test", i, j);
		}
		/* Boxes the test must cull, a tenth of r across: 0.3 r off the plane; at the centre;
		 * 1.5 r out in the plane; for a half circle, 0.5 r behind the centre along t. Only
		 * where r is over 1e-3 of the centre's coordinates: the test's slack against rounding,
		 * 1e-5 of the magnitudes, must stay under a twentieth of r. */
		vec3 ac = v3_abs(q.centre);
		if (!(r > 1e-3f * fmaxf(ac.x, fmaxf(ac.y, ac.z))))
			continue;
		vec3 e = v3s(0.05f * r);
		vec3 cases[4] = {v3_add(v3_add(q.centre, v3_scale(q.t, 0.7f * r)), v3_scale(m, 0.3f * r)), q.centre,
				 v3_add(q.centre, v3_scale(q.n, 1.5f * r)), v3_sub(q.centre, v3_scale(q.t, 0.5f * r))};
		for (int k = 0; k < (q.full ? 3 : 4); k++) {
			cull_cases++;
			culled += !bvh_box_circle(v3_sub(cases[k], e), v3_add(cases[k], e), &q);
		}
	}
	printf("box_circle: %ld boxes hold a point of an arc, %ld fail the test; %ld of %ld boxes culled\n", holding,
	       missed, culled, cull_cases);
	CHECK(holding > circles / 2, "only %ld boxes hold a point of an arc", holding);
	CHECK(missed == 0, "%ld boxes holding a point of the arc fail", missed);
	CHECK(culled == cull_cases, "%ld of %ld boxes off the circle pass", cull_cases - culled, cull_cases);
}

int main(void)
{
	test_simd_from_env();
	check_width();
	check_box_circle();
	check_bad_input();
	check_degenerate();
	check_small_meshes();
	check_edge_rays("scenes/assets/bunny/bunny_npm.obj");
	check_mesh_file("scenes/assets/bunny/bunny_npm.obj", test_count(100000), test_count(100000));
	return check_done("test_bvh");
}
