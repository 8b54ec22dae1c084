/* test_tlas: instancing - rays and circles through the top level agree with each instance traced
 * on its own (and with a flattened copy), and memory grows with unique geometry only. */
#include "accel/tlas.h"
#include "check.h"
#include "brute.h"
#include "geom/prim.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

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

/* True when hits[0, n) are in the canonical order (tri_circle_hit_cmp never decreases). */
static bool in_order(const tri_circle_hit *hits, uint32_t n)
{
	for (uint32_t i = 1; i < n; i++)
		if (tri_circle_hit_cmp(&hits[i - 1], &hits[i]) > 0)
			return false;
	return true;
}

/* The circle queries return their hits in the canonical order whatever the trees: the mesh m's
 * hits come out the same, bit for bit and in the same order, from a bvh of m and from a bvh of m
 * with far triangles appended (ids of m's unchanged, the tree a different one), and likewise
 * through two top levels over the same instances with far ones appended to the second. */
static void check_canonical_order(const mesh *m)
{
	uint32_t nv = m->num_vertices, nt = m->num_triangles;
	vec3 *pos = malloc(2 * (size_t)nv * sizeof *pos);
	uint32_t *ix = malloc(6 * (size_t)nt * sizeof *ix);
	for (uint32_t v = 0; v < nv; v++)
		pos[v] = m->positions[v], pos[nv + v] = v3_add(v3_scale(m->positions[v], 0.5f), v3(7.0f, 0.0f, 0.0f));
	for (uint32_t k = 0; k < 3 * nt; k++)
		ix[k] = m->indices[k], ix[3 * nt + k] = nv + m->indices[k];
	bvh *a = bvh_build(m->positions, nv, m->indices, nt), *b = bvh_build(pos, 2 * nv, ix, 2 * nt);
	tlas_instance in[8];
	for (int i = 0; i < 8; i++) /* instances 0-3 overlap the unit box; 4-7 lie far away */
		in[i] = (tlas_instance){i < 4 ? a : b, xform_translate(d3(i < 4 ? 0.1 * i : 30.0 + 5.0 * i, 0.0, 0.0)),
					(uint32_t)i % 2};
	tlas *t4 = tlas_build(in, 4), *t8 = tlas_build(in, 8);
	static tri_circle_hit ha[256], hb[256];
	vec3 lo, hi;
	mesh_bounds(m, &lo, &hi);
	rng g;
	rng_seed(&g, 5, 5);
	long bad = 0, multi = 0;
	for (int k = 0; k < 2000; k++) {
		tri_circle q = test_random_circle(m, v3_length(v3_sub(hi, lo)), &g);
		uint32_t na = bvh_circle(a, &q, ha, 256), nb = bvh_circle(b, &q, hb, 256);
		bool ok = na == nb && na <= 256 && in_order(ha, na) && memcmp(ha, hb, na * sizeof *ha) == 0;
		uint32_t sa = tlas_circle_set(t4, &q, 0, ha, 256), sb = tlas_circle_set(t8, &q, 0, hb, 256);
		ok = ok && sa == sb && sa <= 256 && in_order(ha, sa) && memcmp(ha, hb, sa * sizeof *ha) == 0;
		uint32_t aa = tlas_circle(t4, &q, TLAS_ALL_INSTANCES, ha, 256);
		ok = ok && aa <= 256 && in_order(ha, aa);
		multi += na > 1;
		if (!ok && bad++ < 5)
			CHECK(0, "circle %d: %u and %u hits on the two bvhs, %u and %u on the two top levels' set", k, na,
			      nb, sa, sb);
	}
	CHECK(bad == 0 && multi > 100, "canonical order: %ld circles differ (%ld with several hits)", bad, multi);
	tlas_free(t4), tlas_free(t8);
	bvh_free(a), bvh_free(b);
	free(pos), free(ix);
}

/* tlas_nearest_set against the instances flattened into world space (bvh_nearest on each copy):
 * a lower bound always; equal within the float transforms' rounding where every instance is a
 * similarity (a non-uniform scale gives its box's distance, still a lower bound). */
static void check_nearest_set(const tlas_instance *in, int n, const mesh *const meshes[2], bvh *const geoms[2], rng *g)
{
	bvh **flat = malloc((size_t)n * sizeof *flat);
	for (int i = 0; i < n; i++) {
		const mesh *src = meshes[in[i].geom == geoms[0] ? 0 : 1];
		mesh w = *src;
		w.positions = malloc(w.num_vertices * sizeof(vec3));
		for (uint32_t v = 0; v < w.num_vertices; v++)
			w.positions[v] = d3_to_v3(xform_point(&in[i].to_world, v3_to_d3(src->positions[v])));
		flat[i] = bvh_build(w.positions, w.num_vertices, w.indices, w.num_triangles);
		free(w.positions);
	}
	tlas *t = tlas_build(in, (uint32_t)n);
	long count = test_count(3000), bad = 0, tight = 0, uniform_sets = 0;
	for (long k = 0; k < count; k++) {
		vec3 p = v3(50.0f * rng_float(g) - 25.0f, 50.0f * rng_float(g) - 25.0f, 50.0f * rng_float(g) - 25.0f);
		uint32_t set = (uint32_t)(k % 3);
		float cap = k % 2 ? INFINITY : 10.0f * rng_float(g);
		float want = cap;
		bool all_similar = true;
		for (int i = 0; i < n; i++)
			if (in[i].set == set) {
				want = fminf(want, bvh_nearest(flat[i], p, cap));
				double sc;
				all_similar = all_similar && xform_is_similarity(&in[i].to_world, &sc);
			}
		float got = tlas_nearest_set(t, p, set, cap);
		bool ok = got <= want * (1.0f + 1e-5f) + 1e-5f && got <= cap;
		if (all_similar) {
			uniform_sets++;
			ok = ok && got >= want * (1.0f - 1e-4f) - 1e-5f;
		}
		tight += got >= want * 0.999f;
		if (!ok && bad++ < 5)
			CHECK(0, "nearest %ld (set %u, cap %g): tlas %.9g, flattened %.9g", k, set, cap, got, want);
	}
	CHECK(bad == 0 && tight > count / 2, "nearest: %ld of %ld differ (%ld tight, %ld similar sets)",
	      bad, count, tight, uniform_sets);
	CHECK(tlas_nearest_set(t, v3(NAN, 0, 0), 0, 2.0f) == 2.0f && tlas_nearest_set(t, v3(0, 0, 0), 0, 0.0f) == 0.0f,
	      "nearest's edge cases");
	printf("tlas nearest: %ld points, %ld tight, %ld differ\n", count, tight, bad);
	tlas_free(t);
	for (int i = 0; i < n; i++)
		bvh_free(flat[i]);
	free(flat);
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
	long count = test_count(20000), bad = 0, hits = 0, set_bad = 0, set_hits = 0;
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
		/* The nearest hit of one set's instances (set k % 3): the others are transparent. */
		uint32_t set = (uint32_t)(k % 3);
		bvh_hit hs, bs = {INFINITY, 0, 0, 0, UINT32_MAX};
		for (uint32_t i = set; i < NUM_INST; i += 3) {
			bvh_ray lr = {d3_to_v3(xform_inv_point(&in[i].to_world, v3_to_d3(r.org))),
				      d3_to_v3(xform_inv_vector(&in[i].to_world, v3_to_d3(r.dir))), 0.0f, bs.t};
			bvh_hit h;
			if (bvh_intersect(in[i].geom, &lr, &h) && h.t < bs.t)
				bs = h, bs.inst = i;
		}
		bool fs = tlas_intersect_set(t, &r, set, &hs), fbs = bs.inst != UINT32_MAX;
		set_hits += fs;
		if ((fs != fbs || (fs && (fabsf(hs.t - bs.t) > 6e-4f || hs.inst % 3 != set))) && set_bad++ < 5)
			CHECK(0, "ray %ld, set %u: tlas %d (t %g inst %u), alone %d (t %g inst %u)", k, set, fs, hs.t, hs.inst,
			      fbs, bs.t, bs.inst);
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
	CHECK(set_bad == 0 && set_hits > count / 30, "rays on one set: %ld differ, %ld hits of %ld", set_bad, set_hits,
	      count);
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
	check_canonical_order(&bunny);
	check_nearest_set(in, 40, meshes, geoms, &g);
	static tlas_instance similar[40]; /* the same without the non-uniform ones */
	int ns = 0;
	for (int i = 0; i < 40; i++)
		if (i % 10 != 9)
			similar[ns++] = in[i];
	check_nearest_set(similar, ns, meshes, geoms, &g);
	tlas_free(t);
	bvh_free(geoms[0]), bvh_free(geoms[1]);
	mesh_free(&bunny), mesh_free(&sphere);
	diag_free(&d);
	return check_done("test_tlas");
}
