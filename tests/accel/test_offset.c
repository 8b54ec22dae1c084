/* test_offset: the ray offset of accel/offset.h. Rays spawned from hits on either side of a
 * triangle never hit it again, from coordinates of 1e-8 to 1e8, with an offset that is the same
 * fraction of the triangle's scale at every scale (Waechter & Binder's fixed 1/65536 near the
 * origin is not: it is measured here for comparison); and a ray leaving a large face from behind,
 * which the triangle test reports back at t ~ 0 under the point-sized offset, gets away. */
#include "check.h"
#include "brute.h"
#include "accel/offset.h"
#include "geom/prim.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Rays leave the middle of a box face of half-size `half` from behind (into the box), in
 * directions spread over the hemisphere; returns how many come back to the face at t < 1. */
static long behind_face(float half, bool scaled, long count)
{
	mesh m;
	if (!prim_box(v3(-half, -half, 0), v3(half, half, 2 * half), &m))
		return -1;
	bvh *b = bvh_build(m.positions, m.num_vertices, m.indices, m.num_triangles);
	long back = 0;
	rng g;
	rng_seed(&g, 5, 1);
	for (long i = 0; i < count && b; i++) {
		vec3 p = v3(6 * rng_float(&g) - 3, 6 * rng_float(&g) - 3, 0);
		vec3 d = test_unit_vector(&g);
		if (d.z < 0.0f)
			d.z = -d.z;
		vec3 in = v3(0, 0, 1);
		vec3 o = scaled ? bvh_offset_scaled(p, in, half) : bvh_offset_origin(p, in);
		bvh_ray r = {o, d, 0.0f, INFINITY};
		bvh_hit h;
		if (bvh_intersect(b, &r, &h) && h.t < 1.0f)
			back++;
	}
	bvh_free(b);
	mesh_free(&m);
	return back;
}

/* The bunny scaled to coordinates of magnitude `scale`: spawned rays on both sides of every hit
 * never hit their triangle; returns the largest offset over the triangle's scale. */
static double check_spawn(const mesh *unit, double scale, long count, uint64_t seed, double *wb_rel)
{
	mesh m = *unit;
	m.positions = malloc(unit->num_vertices * sizeof(vec3));
	for (uint32_t v = 0; v < unit->num_vertices; v++)
		m.positions[v] = v3_scale(unit->positions[v], (float)scale);
	bvh *b = bvh_build(m.positions, m.num_vertices, m.indices, m.num_triangles);
	vec3 lo, hi;
	mesh_bounds(&m, &lo, &hi);
	rng g;
	rng_seed(&g, seed, 4);
	long self = 0, hits = 0;
	double rel = 0.0;
	*wb_rel = 0.0;
	for (long i = 0; i < count && b; i++) {
		bvh_ray r = test_random_ray(&m, lo, hi, &g);
		bvh_hit h;
		if (!bvh_intersect(b, &r, &h))
			continue;
		hits++;
		vec3 v0 = test_tri_vertex(&m, h.prim, 0), v1 = test_tri_vertex(&m, h.prim, 1), v2 = test_tri_vertex(&m, h.prim, 2);
		vec3 p = v3_add(v3_add(v3_scale(v0, 1.0f - h.u - h.v), v3_scale(v1, h.u)), v3_scale(v2, h.v));
		vec3 ng = v3_normalize(v3_cross(v3_sub(v1, v0), v3_sub(v2, v0)));
		float s = bvh_triangle_scale(v0, v1, v2);
		for (int side = 0; side < 2; side++) {
			vec3 n = side ? v3_neg(ng) : ng;
			vec3 d = test_unit_vector(&g);
			if (v3_dot(d, n) < 0.0f)
				d = v3_neg(d);
			vec3 o = bvh_offset_scaled(p, n, s);
			rel = fmax(rel, v3_length(v3_sub(o, p)) / s);
			*wb_rel = fmax(*wb_rel, v3_length(v3_sub(bvh_offset_origin(p, n), p)) / s);
			bvh_ray sr = {o, d, 0.0f, INFINITY};
			bvh_hit h2;
			if (bvh_intersect(b, &sr, &h2) && h2.prim == h.prim)
				self++;
		}
	}
	CHECK(self == 0 && hits > count / 4, "scale %g: %ld self-hits among %ld hits", scale, self, hits);
	bvh_free(b);
	free(m.positions);
	return rel;
}

int main(void)
{
	long n = test_count(100000);
	long old = behind_face(200.0f, false, n), now = behind_face(200.0f, true, n);
	printf("leaving a 400-unit face from behind: %ld of %ld rays back on it with the point's offset, %ld with "
	       "the triangle's\n", old, n, now);
	CHECK(now == 0, "%ld rays came back to the face they left", now);

	diag d;
	diag_init(&d, stderr);
	mesh bunny;
	if (mesh_import(test_path("scenes/assets/bunny/bunny_npm.obj"), &bunny, &d)) {
		vec3 lo, hi;
		mesh_bounds(&bunny, &lo, &hi);
		vec3 mid = v3_scale(v3_add(lo, hi), 0.5f);
		float ext = v3_max_comp(v3_sub(hi, lo));
		for (uint32_t v = 0; v < bunny.num_vertices; v++)
			bunny.positions[v] = v3_scale(v3_sub(bunny.positions[v], mid), 1.0f / ext);
		for (int e = -8; e <= 8; e += 2) {
			double wb, rel = check_spawn(&bunny, pow(10.0, e), test_count(20000), 300 + e, &wb);
			printf("scale 1e%+d: offset at most %.3g of the triangle's scale (Waechter & Binder: %.3g)\n", e, rel,
			       wb);
			CHECK(rel <= 1.01 * BVH_OFFSET_REL && rel > 0.5 * BVH_OFFSET_REL,
			      "scale 1e%d: offset %.3g of the scale, expected %.3g", e, rel, (double)BVH_OFFSET_REL);
		}
		mesh_free(&bunny);
	} else {
		CHECK(0, "cannot read the bunny");
	}
	diag_free(&d);
	return check_done("test_offset");
}
