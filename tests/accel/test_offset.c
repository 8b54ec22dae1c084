/* test_offset: the ray offset of accel/offset.h lets a ray leaving a large face from behind get
 * away, where the triangle test reports it back at t ~ 0 under Waechter & Binder's point-sized
 * offset (counted here). Scale invariance from 1e-8 to 1e8 is test_robust's check_spawn. */
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

int main(void)
{
	test_simd_from_env();
	long n = test_count(100000);
	long old = behind_face(200.0f, false, n), now = behind_face(200.0f, true, n);
	printf("leaving a 400-unit face from behind: %ld of %ld rays back on it with the point's offset, %ld with "
	       "the triangle's\n", old, n, now);
	CHECK(now == 0, "%ld rays came back to the face they left", now);
	return check_done("test_offset");
}
