/* test_circle: circle hits on a plane, a sphere and a cylinder land on the analytic intersections;
 * the float pre-test of the circle/triangle test never loses a hit; the exact test gives the hits of
 * its reference form bit for bit. */
#include "check.h"
#include "brute.h"
#include "geom/prim.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

/* |a - b| modulo 2 pi. */
static double angle_diff(double a, double b)
{
	double d = fmod(fabs(a - b), 2 * PI);
	return fmin(d, 2 * PI - d);
}

static tri_circle circle_at(vec3 c, vec3 n, double phi, float r, bool full)
{
	vec3 b1, b2;
	v3_basis(n, &b1, &b2);
	vec3 t = v3_normalize(v3_add(v3_scale(b1, (float)cos(phi)), v3_scale(b2, (float)sin(phi))));
	return (tri_circle){c, t, n, r, full};
}

/* The plane y = 0 (a big quad): a half circle centred on it hits once, at theta 0, at distance r;
 * a full circle twice (0 and pi); a tilted circle above it where c_y + r sin(...) = 0. */
static void check_plane(long count)
{
	vec3 p[4] = {{-100, 0, -100}, {100, 0, -100}, {100, 0, 100}, {-100, 0, 100}};
	uint32_t ix[6] = {0, 2, 1, 0, 3, 2};
	bvh *b = bvh_build(p, 4, ix, 2);
	rng g;
	rng_seed(&g, 1, 1);
	long bad = 0;
	for (long i = 0; i < count; i++) {
		vec3 c = v3(20.0f * rng_float(&g) - 10.0f, 0.0f, 20.0f * rng_float(&g) - 10.0f);
		float r = 0.01f + 5.0f * rng_float(&g);
		bool full = i % 2;
		tri_circle q = circle_at(c, v3(0, 1, 0), 2 * PI * rng_float(&g), r, full);
		tri_circle_hit h[8];
		uint32_t n = bvh_circle(b, &q, h, 8);
		/* A hit exactly on the quad's diagonal counts for both triangles: merge equal thetas. */
		uint32_t distinct = 0;
		for (uint32_t k = 0; k < n; k++) {
			bool dup = false;
			for (uint32_t j = 0; j < k; j++)
				dup |= fabsf(h[j].theta - h[k].theta) < 1e-6f;
			distinct += !dup;
			vec3 want = v3_madd(c, q.t, cosf(h[k].theta) * r);
			float err = v3_length(v3_sub(h[k].pos, want));
			bool ok = err <= 2e-6f * (r + 15.0f) && fabsf(h[k].pos.y) <= 1e-6f &&
				  (fabsf(h[k].theta) <= 1e-6f || fabsf(h[k].theta - (float)PI) <= 1e-6f) &&
				  fabsf(fabsf(h[k].ng.y) - 1.0f) <= 1e-6f;
			if (!ok && bad++ < 5)
				CHECK(0, "plane circle %ld: hit theta %g at distance %g from the analytic point", i, h[k].theta, err);
		}
		if (distinct != (full ? 2u : 1u) && bad++ < 5)
			CHECK(0, "plane circle %ld (%s): %u hits", i, full ? "full" : "half", distinct);
	}
	/* Tilted circles above the plane: centre at height hgt, normal tilted by alpha from y in the
	 * (t, y) plane: sin(theta) cos(alpha) ... solve c_y + r (cos theta t_y + sin theta n_y) = 0. */
	for (long i = 0; i < count; i++) {
		float hgt = 0.5f * rng_float(&g), r = 1.0f + rng_float(&g), alpha = 1.2f * (rng_float(&g) - 0.5f);
		vec3 c = v3(0, hgt, 0);
		vec3 n = v3(sinf(alpha), cosf(alpha), 0), t = v3(cosf(alpha), -sinf(alpha), 0);
		tri_circle q = {c, t, n, r, true};
		tri_circle_hit h[8];
		uint32_t k = bvh_circle(b, &q, h, 8);
		/* hgt + r (cos th t_y + sin th n_y) = 0 with t_y = -sin a, n_y = cos a:
		 * hgt + r sin(th - a) = 0, so th = a + asin(-hgt / r) or a + pi - asin(-hgt / r). */
		double s = asin(-(double)hgt / r);
		double want[2] = {fmod(alpha + s + 2 * PI, 2 * PI), fmod(alpha + PI - s + 2 * PI, 2 * PI)};
		int matched = 0;
		for (uint32_t j = 0; j < k; j++)
			for (int w = 0; w < 2; w++)
				matched += fabs(h[j].theta - want[w]) < 2e-6 && fabsf(h[j].pos.y) < 1e-6f;
		if ((k != 2 || matched != 2) && bad++ < 5)
			CHECK(0, "tilted circle %ld: %u hits, %d match (%g %g)", i, k, matched, want[0], want[1]);
	}
	CHECK(bad == 0, "plane: %ld bad circles", bad);
	bvh_free(b);
}

/* A finely tessellated unit sphere: a circle at a surface point x with n the normal meets the
 * great circle at angle a = 2 asin(r / 2) from x, at theta = atan2(cos a - 1, sin a) (and, for
 * a full circle, pi - that). */
static void check_sphere(long count)
{
	mesh m;
	const uint32_t seg = 1024;
	CHECK(prim_sphere(v3(0, 0, 0), 1.0f, seg, &m), "sphere");
	bvh *b = bvh_build(m.positions, m.num_vertices, m.indices, m.num_triangles);
	/* Chordal error of the tessellation (rings are seg / 2 apart in latitude, so both directions
	 * count) bounds how far a hit can be from the true sphere. */
	double chord = 2.0 * (1.0 - cos(2.0 * PI / seg)) + 1e-6;
	rng g;
	rng_seed(&g, 2, 2);
	long bad = 0;
	for (long i = 0; i < count; i++) {
		vec3 n = test_unit_vector(&g);
		if (fabsf(n.y) > 0.9f)
			continue; /* near the poles the fans are thin; the rest suffices */
		vec3 x = n;
		float r = 0.05f + 1.5f * rng_float(&g);
		bool full = i % 2;
		tri_circle q = circle_at(x, n, 2 * PI * rng_float(&g), r, full);
		tri_circle_hit h[16];
		uint32_t k = bvh_circle(b, &q, h, 16);
		double a = 2.0 * asin(r / 2.0), th = atan2(cos(a) - 1.0, sin(a));
		double want[2] = {th, PI - th};
		for (uint32_t j = 0; j < k && j < 16; j++) {
			float rad = v3_length(h[j].pos);
			double dt = fmin(angle_diff(h[j].theta, want[0]), angle_diff(h[j].theta, want[1]));
			float dist = v3_length(v3_sub(h[j].pos, x));
			bool ok = fabs(rad - 1.0) <= chord && fabs(dist - r) <= 1e-5 && dt <= 4 * chord / r + 1e-5;
			if (!ok && bad++ < 5)
				CHECK(0, "sphere circle %ld: |p| %g, |p - x| %g vs r %g, theta %g vs %g / %g", i, rad, dist, r,
				      h[j].theta, want[0], want[1]);
		}
		if ((k < 1 || (full && k < 2)) && bad++ < 5)
			CHECK(0, "sphere circle %ld: %u hits", i, k);
	}
	CHECK(bad == 0, "sphere: %ld bad circles", bad);
	bvh_free(b);
	mesh_free(&m);
}

/* A cylinder x^2 + z^2 = 1, |y| <= 4, of 2048 segments: a circle at x = (1, 0, 0) with n = x and
 * t in the tangent plane hits it where |c(theta)|_xz = 1, found here by bisection in double. */
static void check_cylinder(long count)
{
	const uint32_t seg = 2048;
	vec3 *p = malloc(2 * seg * sizeof *p);
	uint32_t *ix = malloc(6 * seg * sizeof *ix);
	for (uint32_t i = 0; i < seg; i++) {
		double a = 2 * PI * i / seg;
		p[2 * i] = v3((float)cos(a), -4.0f, (float)sin(a));
		p[2 * i + 1] = v3((float)cos(a), 4.0f, (float)sin(a));
		uint32_t j = (i + 1) % seg;
		uint32_t *t = ix + 6 * i;
		t[0] = 2 * i, t[1] = 2 * i + 1, t[2] = 2 * j, t[3] = 2 * j, t[4] = 2 * i + 1, t[5] = 2 * j + 1;
	}
	bvh *b = bvh_build(p, 2 * seg, ix, 2 * seg);
	double chord = 1.0 - cos(PI / seg) + 1e-6;
	rng g;
	rng_seed(&g, 3, 3);
	long bad = 0;
	for (long i = 0; i < count; i++) {
		vec3 x = v3(1, 0, 0), n = v3(1, 0, 0);
		double phi = 2 * PI * rng_float(&g);
		vec3 t = v3(0, (float)cos(phi), (float)sin(phi));
		float r = 0.05f + 1.5f * rng_float(&g);
		tri_circle q = {x, t, n, r, false};
		tri_circle_hit h[16];
		uint32_t k = bvh_circle(b, &q, h, 16);
		/* f(theta) = |c(theta)|_xz^2 - 1 changes sign once on (0, pi/2] and once on [-pi/2, 0). */
		double want[2];
		for (int side = 0; side < 2; side++) {
			double lo = side ? -PI / 2 : 1e-9, hi = side ? -1e-9 : PI / 2;
			for (int it = 0; it < 200; it++) {
				double mid = 0.5 * (lo + hi);
				double cx = 1.0 + r * sin(mid) * 1.0, cz = r * cos(mid) * t.z;
				double cxl = 1.0 + r * sin(lo), czl = r * cos(lo) * t.z;
				double fm = cx * cx + cz * cz - 1.0, fl = cxl * cxl + czl * czl - 1.0;
				if ((fm < 0) == (fl < 0))
					lo = mid;
				else
					hi = mid;
			}
			want[side] = 0.5 * (lo + hi);
		}
		for (uint32_t j = 0; j < k && j < 16; j++) {
			double rad = sqrt((double)h[j].pos.x * h[j].pos.x + (double)h[j].pos.z * h[j].pos.z);
			double dt = fmin(angle_diff(h[j].theta, want[0]), angle_diff(h[j].theta, want[1]));
			bool ok = fabs(rad - 1.0) <= chord && dt <= 8 * chord / r + 1e-5 &&
				  fabs(v3_length(v3_sub(h[j].pos, x)) - r) <= 1e-5;
			if (!ok && bad++ < 5)
				CHECK(0, "cylinder circle %ld: rho %.9g theta %g want %g / %g", i, rad, h[j].theta, want[0], want[1]);
		}
		if (k < 1 && bad++ < 5)
			CHECK(0, "cylinder circle %ld: no hit", i);
	}
	CHECK(bad == 0, "cylinder: %ld bad circles", bad);
	bvh_free(b);
	free(p), free(ix);
}

/* tri_circle_intersect's float pre-test (and so the BVH's leaf test, which uses the same margin)
 * skips only triangles its exact part gives no hit for: triangles crossing the circle with their
 * vertices within 1e-9 to 1e-6 (relative to the coordinates) of the circle's plane, at coordinates
 * from 1e-8 to 1e8, get the same hits from tri_circle_intersect as from tri_circle_exact. (With a
 * margin of 1e-9 instead of 3e-6, 0.2 % of them lose their hit; the margin's derivation, tri.h,
 * covers the worst case, which random triangles do not reach.) */
static void check_pretest(long count)
{
	rng g;
	rng_seed(&g, 3, 4);
	long with_hits = 0, differ = 0;
	for (long i = 0; i < count; i++) {
		float scale = powf(10.0f, 16.0f * rng_float(&g) - 8.0f);
		vec3 c = v3_scale(test_unit_vector(&g), scale * rng_float(&g));
		tri_circle q = circle_at(c, test_unit_vector(&g), 2 * PI * rng_float(&g),
					 scale * powf(10.0f, -2.0f * rng_float(&g)), i % 2 == 0);
		vec3 m = v3_normalize(v3_cross(q.t, q.n));
		float th = (float)PI * (rng_float(&g) - 0.5f);
		vec3 on = v3_add(q.centre, v3_scale(v3_add(v3_scale(q.t, cosf(th)), v3_scale(q.n, sinf(th))), q.radius));
		/* In-plane corners about the circle point, a tenth of r out, lifted off the plane by
		 * tiny amounts of both signs. */
		vec3 v[3];
		for (int k = 0; k < 3; k++) {
			float a = 2.0943951f * (float)k + rng_float(&g);
			vec3 inplane = v3_add(v3_scale(q.t, cosf(a)), v3_scale(q.n, sinf(a)));
			float lift = (rng_float(&g) - 0.5f) * powf(10.0f, -9.0f + 3.0f * rng_float(&g)) * scale;
			v[k] = v3_add(v3_add(on, v3_scale(inplane, 0.1f * q.radius)), v3_scale(m, lift));
		}
		tri_circle_hit a[2], b[2];
		memset(a, 0, sizeof a), memset(b, 0, sizeof b);
		int na = tri_circle_intersect(&q, v[0], v[1], v[2], a), nb = tri_circle_exact(&q, v[0], v[1], v[2], b);
		with_hits += nb > 0;
		if ((na != nb || memcmp(a, b, sizeof a) != 0) && differ++ < 5)
			CHECK(0, "triangle %ld (scale %g): %d hits with the pre-test, %d without", i, scale, na, nb);
	}
	printf("pre-test: %ld triangles, %ld with hits, %ld differ\n", count, with_hits, differ);
	CHECK(differ == 0, "%ld of %ld triangles lose hits to the pre-test", differ, count);
	CHECK(with_hits > count / 4, "only %ld of %ld triangles hit", with_hits, count);
}

/* The exact circle/triangle test as first written (main before 2026-12-04's circle20f): edges in
 * order, their crossings from arrays, the roots in a loop, every value in double. tri.h's
 * tri_circle_exact is arranged for speed (a circle prepared once, the crossing edges chosen by
 * index, no copies); it must return the same hits bit for bit, since images depend on them. */
static int reference_exact(const tri_circle *c, vec3 v0, vec3 v1, vec3 v2, tri_circle_hit out[2])
{
	dvec3 C = v3_to_d3(c->centre), T = v3_to_d3(c->t), N = v3_to_d3(c->n), M = d3_cross(T, N);
	dvec3 P[3] = {v3_to_d3(v0), v3_to_d3(v1), v3_to_d3(v2)};
	double d[3];
	for (int i = 0; i < 3; i++)
		d[i] = d3_dot(M, d3_sub(P[i], C));
	bool all_above = d[0] > 0.0 && d[1] > 0.0 && d[2] > 0.0,
	     all_below = d[0] < 0.0 && d[1] < 0.0 && d[2] < 0.0;
	if (all_above || all_below || (d[0] == 0.0 && d[1] == 0.0 && d[2] == 0.0))
		return 0;
	dvec3 ng = d3_cross(d3_sub(P[1], P[0]), d3_sub(P[2], P[0]));
	if (!(d3_dot(ng, ng) > 0.0))
		return 0;
	static const double bu[3] = {0, 1, 0}, bv[3] = {0, 0, 1};
	dvec3 S[3];
	double su[3], sv[3];
	int ns = 0;
	for (int i = 0; i < 3; i++) {
		int j = (i + 1) % 3;
		if (d[i] == 0.0) {
			S[ns] = P[i], su[ns] = bu[i], sv[ns] = bv[i], ns++;
		} else if ((d[i] < 0.0 && d[j] > 0.0) || (d[i] > 0.0 && d[j] < 0.0)) {
			double s = d[i] / (d[i] - d[j]);
			S[ns] = d3_add(P[i], d3_scale(d3_sub(P[j], P[i]), s));
			su[ns] = bu[i] + s * (bu[j] - bu[i]), sv[ns] = bv[i] + s * (bv[j] - bv[i]);
			ns++;
		}
	}
	if (ns != 2)
		return 0;
	dvec3 D = d3_sub(S[1], S[0]), E = d3_sub(S[0], C);
	double a = d3_dot(D, D), b = d3_dot(D, E), r = c->radius, cc = d3_dot(E, E) - r * r;
	if (!(a > 0.0))
		return 0;
	double disc = b * b - a * cc;
	if (disc < 0.0)
		return 0;
	double sq = sqrt(disc), q = b >= 0.0 ? -(b + sq) : -(b - sq), roots[2];
	int nr = 0;
	if (q != 0.0) {
		roots[nr++] = q / a;
		if (disc > 0.0)
			roots[nr++] = cc / q;
	} else {
		roots[nr++] = 0.0;
	}
	int nh = 0;
	for (int k = 0; k < nr; k++) {
		double s = roots[k];
		if (!(s >= 0.0 && s <= 1.0))
			continue;
		dvec3 x = d3_add(S[0], d3_scale(D, s)), rel = d3_sub(x, C);
		double ct = d3_dot(rel, T), st = d3_dot(rel, N);
		if (!c->full && ct < 0.0)
			continue;
		double theta = trig_atan2(st, ct);
		if (c->full && theta < 0.0)
			theta += 2.0 * PI;
		out[nh++] = (tri_circle_hit){d3_to_v3(x),
					     (float)theta,
					     (float)(su[0] + s * (su[1] - su[0])),
					     (float)(sv[0] + s * (sv[1] - sv[0])),
					     d3_to_v3(d3_normalize(ng)),
					     0,
					     0};
	}
	return nh;
}

/* tri_circle_exact against reference_exact on triangles about circle points, small and large, and
 * about the centre, larger than the circle (crossing it twice), and on axis-aligned circles with vertices
 * exactly on the plane (the segment then ends at a vertex, or the triangle touches the plane at one). */
static void check_exact_reference(long count)
{
	rng g;
	rng_seed(&g, 5, 6);
	long with_hits = 0, on_plane = 0, two = 0, differ = 0;
	for (long i = 0; i < count; i++) {
		bool aligned = i % 4 == 3;
		vec3 n = aligned ? v3(0.0f, 1.0f, 0.0f) : test_unit_vector(&g);
		vec3 c = v3_scale(test_unit_vector(&g), 10.0f * rng_float(&g));
		float r = powf(10.0f, 2.0f * rng_float(&g) - 1.0f);
		tri_circle q = aligned ? (tri_circle){c, v3(1.0f, 0.0f, 0.0f), n, r, i % 8 == 3}
				       : circle_at(c, n, 2 * PI * rng_float(&g), r, i % 2 == 0 || i % 8 == 1);
		float th = 2.0f * (float)PI * rng_float(&g),
		      size = r * powf(10.0f, 2.0f * rng_float(&g) - 1.5f);
		vec3 on = v3_add(c, v3_scale(v3_add(v3_scale(q.t, cosf(th)), v3_scale(q.n, sinf(th))), r));
		if (i % 4 == 1) /* about the centre and larger than the circle: chords, two hits */
			on = c, size = r * (2.0f + 2.0f * rng_float(&g));
		vec3 v[3];
		for (int k = 0; k < 3; k++) {
			v[k] = v3_add(
			    on, v3_scale(test_unit_vector(&g), i % 4 == 1 ? size : size * rng_float(&g)));
			/* On an axis-aligned circle's plane z = c.z, exactly: M = t x n is (0, 0, 1). */
			if (aligned && rng_below(&g, 3) == 0)
				v[k].z = c.z, on_plane++;
		}
		tri_circle_hit a[2], b[2];
		memset(a, 0, sizeof a), memset(b, 0, sizeof b);
		int na = tri_circle_exact(&q, v[0], v[1], v[2], a),
		    nb = reference_exact(&q, v[0], v[1], v[2], b);
		with_hits += nb > 0, two += nb == 2;
		if ((na != nb || memcmp(a, b, sizeof a) != 0) && differ++ < 5)
			CHECK(0, "triangle %ld: %d hits, the reference %d (theta %.9g / %.9g)", i, na, nb,
			      a[0].theta, b[0].theta);
	}
	printf(
	    "exact test against the reference: %ld triangles, %ld with hits, %ld with two, %ld vertices on "
	    "the plane, %ld differ\n",
	    count, with_hits, two, on_plane, differ);
	CHECK(differ == 0, "%ld of %ld triangles differ from the reference", differ, count);
	CHECK(with_hits > count / 5 && two > count / 100 && on_plane > count / 10,
	      "too few cases: %ld with hits, %ld with two, %ld on the plane", with_hits, two, on_plane);
}

int main(void)
{
	test_simd_from_env();
	check_exact_reference(test_count(200000));
	check_pretest(test_count(200000));
	check_plane(test_count(20000));
	check_sphere(test_count(5000));
	check_cylinder(test_count(5000));
	return check_done("test_circle");
}
