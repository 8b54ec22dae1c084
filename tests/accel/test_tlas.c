/* test_tlas: instancing - rays and circles through the top level agree with each instance traced
 * on its own (and with a flattened copy), and memory grows with unique geometry only. */
#include "accel/tlas.h"
#include "check.h"
#include "brute.h"
#include "geom/prim.h"

#include <stdio.h>
#include <stdlib.h>

#define NUM_INST 300

static xform random_similarity(rng *g, bool uniform)
{
	xform r = xform_rotate(d3(360.0 * rng_float(g), 360.0 * rng_float(g), 360.0 * rng_float(g)));
	double s = 0.3 + 2.0 * rng_float(g);
	xform sc;
	xform_scale(uniform ? d3(s, s, s) : d3(s, 0.5 * s, 1.5 * s), &sc);
	xform t = xform_translate(d3(40.0 * rng_float(g) - 20.0, 40.0 * rng_float(g) - 20.0, 40.0 * rng_float(g) - 20.0));
	return xform_then(xform_then(sc, r), t);
}

int main(void)
{
	test_simd_from_env();
	diag d;
	diag_init(&d, stderr);
	mesh bunny, sphere;
	if (!mesh_import(test_path("scenes/assets/bunny/bunny_npm.obj"), &bunny, &d) ||
	    !prim_sphere(v3(0, 0, 0), 1.0f, 48, &sphere)) {
		CHECK(0, "inputs");
		return check_done("test_tlas");
	}
	/* The bunny to about unit size. */
	vec3 lo, hi;
	mesh_bounds(&bunny, &lo, &hi);
	xform norm = xform_then(xform_translate(d3_scale(v3_to_d3(v3_add(lo, hi)), -0.5)), xform_identity());
	xform sc;
	xform_scale(d3(1.0 / v3_max_comp(v3_sub(hi, lo)), 1.0 / v3_max_comp(v3_sub(hi, lo)), 1.0 / v3_max_comp(v3_sub(hi, lo))), &sc);
	norm = xform_then(norm, sc);
	mesh_transform(&bunny, &norm);
	bvh *geoms[2] = {bvh_build(bunny.positions, bunny.num_vertices, bunny.indices, bunny.num_triangles),
			 bvh_build(sphere.positions, sphere.num_vertices, sphere.indices, sphere.num_triangles)};
	const mesh *meshes[2] = {&bunny, &sphere};
	static tlas_instance in[NUM_INST];
	rng g;
	rng_seed(&g, 9, 9);
	for (int i = 0; i < NUM_INST; i++)
		in[i] = (tlas_instance){geoms[i % 2], random_similarity(&g, i % 10 != 9), (uint32_t)i % 3};
	tlas *t = tlas_build(in, NUM_INST);
	CHECK(t != NULL, "tlas");
	size_t unique = bvh_bytes(geoms[0]) + bvh_bytes(geoms[1]);
	CHECK(tlas_bytes(t) < unique / 2, "the top level (%zu bytes) is small beside the geometry (%zu)", tlas_bytes(t), unique);
	printf("tlas: %d instances, %zu bytes top level, %zu bytes unique geometry (copies would take %zu)\n", NUM_INST,
	       tlas_bytes(t), unique, unique * NUM_INST / 2);

	/* Rays: the top level against every instance traced alone (the same float transform is not
	 * available here, so t is compared with a tolerance). */
	long count = test_count(20000), bad = 0, hits = 0;
	for (long k = 0; k < count; k++) {
		vec3 o = v3(60.0f * rng_float(&g) - 30.0f, 60.0f * rng_float(&g) - 30.0f, 60.0f * rng_float(&g) - 30.0f);
		bvh_ray r = {o, test_unit_vector(&g), 0.0f, INFINITY};
		bvh_hit ht, hb = {INFINITY, 0, 0, 0, UINT32_MAX};
		bool ft = tlas_intersect(t, &r, &ht);
		for (uint32_t i = 0; i < NUM_INST; i++) {
			bvh_ray lr = {d3_to_v3(xform_inv_point(&in[i].to_world, v3_to_d3(r.org))),
				      d3_to_v3(xform_inv_vector(&in[i].to_world, v3_to_d3(r.dir))), 0.0f, hb.t};
			bvh_hit h;
			if (bvh_intersect(in[i].geom, &lr, &h) && h.t < hb.t)
				hb = h, hb.inst = i;
		}
		bool fb = hb.inst != UINT32_MAX;
		hits += fb;
		/* The float transforms differ in rounding: t agrees to 1e-5 of the scene's size (60);
		 * the triangle may then differ at shared edges and vertices. */
		const float tol = 6e-4f;
		bool ok = ft == fb && (!ft || fabsf(ht.t - hb.t) <= tol);
		ok = ok && tlas_occluded(t, &r) == fb;
		if (!ok && bad++ < 5)
			CHECK(0, "ray %ld: tlas %d (t %g inst %u prim %u), alone %d (t %g inst %u prim %u)", k, ft, ht.t, ht.inst,
			      ht.prim, fb, hb.t, hb.inst, hb.prim);
	}
	CHECK(bad == 0 && hits > count / 10, "rays: %ld differ, %ld hits of %ld", bad, hits, count);
	bvh_ray nan_ray = {{NAN, 0, 0}, {0, 0, 1}, 0, INFINITY};
	bvh_hit h;
	CHECK(!tlas_intersect(t, &nan_ray, &h) && !tlas_occluded(t, &nan_ray), "NaN rays are refused");

	/* Circles on one instance: the same hits as on a flattened world-space copy of it. */
	static tri_circle_hit ha[4096], hw[4096];
	long cbad = 0, ctotal = 0;
	for (uint32_t i = 0; i < NUM_INST; i += 7) {
		CHECK(tlas_circle_ok(t, i) == (i % 10 != 9), "instance %u: circles %s", i, i % 10 != 9 ? "allowed" : "refused");
		if (!tlas_circle_ok(t, i))
			continue;
		mesh w = *meshes[i % 2];
		w.positions = malloc(w.num_vertices * sizeof(vec3));
		for (uint32_t v = 0; v < w.num_vertices; v++)
			w.positions[v] = d3_to_v3(xform_point(&in[i].to_world, v3_to_d3(meshes[i % 2]->positions[v])));
		bvh *wb = bvh_build(w.positions, w.num_vertices, w.indices, w.num_triangles);
		vec3 wlo, whi;
		mesh_bounds(&w, &wlo, &whi);
		for (int k = 0; k < 50; k++) {
			tri_circle q = test_random_circle(&w, v3_length(v3_sub(whi, wlo)), &g);
			uint32_t na = tlas_circle(t, &q, i, ha, 4096), nw = bvh_circle(wb, &q, hw, 4096);
			ctotal += nw;
			/* Match as sets: theta may wrap (0 and 2 pi) between the two. */
			bool ok = na == nw;
			float scale = v3_max_comp(v3_sub(whi, wlo));
			for (uint32_t j = 0; ok && j < na; j++) {
				bool found = false;
				for (uint32_t m = 0; m < nw && !found; m++)
					found = ha[j].prim == hw[m].prim && ha[j].inst == i &&
						v3_length(v3_sub(ha[j].pos, hw[m].pos)) <= 1e-4f * scale && v3_dot(ha[j].ng, hw[m].ng) > 0.999f;
				ok = found;
			}
			if (!ok && cbad++ < 5)
				CHECK(0, "instance %u circle %d: %u hits through the tlas, %u on the flattened copy", i, k, na, nw);
			uint32_t nall = tlas_circle(t, &q, TLAS_ALL_INSTANCES, ha, 4096);
			CHECK(nall >= na, "all instances give at least the hits of one (%u, %u)", nall, na);
			/* A set's hits are exactly the hits of all instances that are in the set. */
			uint32_t set = i % 3, nset = tlas_circle_set(t, &q, set, hw, 4096), nin = 0;
			for (uint32_t j = 0; j < nall && j < 4096; j++)
				nin += ha[j].inst % 3 == set;
			bool same = nset == nin;
			for (uint32_t j = 0; same && j < nset; j++) {
				bool found = false;
				for (uint32_t m = 0; m < nall && !found; m++)
					found = ha[m].inst == hw[j].inst && ha[m].prim == hw[j].prim && ha[m].theta == hw[j].theta;
				same = found && hw[j].inst % 3 == set;
			}
			CHECK(same, "instance %u circle %d: set %u gives %u hits, all instances %u in the set", i, k, set,
			      nset, nin);
		}
		bvh_free(wb);
		free(w.positions);
	}
	CHECK(cbad == 0 && ctotal > 0, "circles: %ld differ (%ld hits)", cbad, ctotal);
	tlas_free(t);
	bvh_free(geoms[0]), bvh_free(geoms[1]);
	mesh_free(&bunny), mesh_free(&sphere);
	diag_free(&d);
	return check_done("test_tlas");
}
