/* test_robust: rays from inside closed tessellated meshes never escape through shared edges or
 * vertices, and rays spawned from hits at coordinates 1e-8 to 1e8 never hit their own triangle. */
#include "check.h"
#include "brute.h"
#include "accel/offset.h"
#include "geom/prim.h"
#include "geom/subdiv.h"

#include <stdio.h>
#include <stdlib.h>

/* Rays from points near the centre towards the mesh's vertices, edge points and random
 * directions: every one must hit. */
static void check_closed(const char *name, const mesh *m, float inner_radius, long count, uint64_t seed)
{
	bvh *b = bvh_build(m->positions, m->num_vertices, m->indices, m->num_triangles);
	CHECK(b != NULL, "bvh of %s", name);
	if (!b)
		return;
	rng g;
	rng_seed(&g, seed, 3);
	long escaped = 0;
	for (long i = 0; i < count; i++) {
		vec3 o = v3_scale(test_unit_vector(&g), inner_radius * rng_float(&g));
		uint32_t f = rng_below(&g, m->num_triangles);
		int c = (int)rng_below(&g, 3);
		vec3 target;
		switch (i % 3) {
		case 0: /* a vertex exactly */
			target = test_tri_vertex(m, f, c);
			break;
		case 1: /* a point of an edge */
			target = v3_lerp(test_tri_vertex(m, f, c), test_tri_vertex(m, f, (c + 1) % 3), rng_float(&g));
			break;
		default:
			target = v3_add(o, test_unit_vector(&g));
		}
		bvh_ray r = {o, v3_sub(target, o), 0.0f, INFINITY};
		bvh_hit h;
		if (!bvh_intersect(b, &r, &h) && escaped++ < 5)
			CHECK(0, "%s: ray %ld from (%g %g %g) towards (%.9g %.9g %.9g) escaped", name, i, o.x, o.y, o.z,
			      target.x, target.y, target.z);
	}
	CHECK(escaped == 0, "%s: %ld of %ld rays escaped", name, escaped, count);
	printf("%s: %ld rays from inside, %ld escaped\n", name, count, escaped);
	bvh_free(b);
}

static void check_watertight(long count)
{
	diag d;
	diag_init(&d, stderr);
	/* A subdivided cube (shared vertices through Bfr), a Loop octahedron, a UV sphere. */
	vec3 cube[8];
	for (int i = 0; i < 8; i++)
		cube[i] = v3(i & 1 ? 1.0f : -1.0f, i & 2 ? 1.0f : -1.0f, i & 4 ? 1.0f : -1.0f);
	uint32_t sizes[6] = {4, 4, 4, 4, 4, 4};
	uint32_t quads[24] = {0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5};
	subd_cage cc = {.positions = cube, .num_vertices = 8, .face_sizes = sizes, .num_faces = 6, .face_indices = quads};
	subd_options o = {.level = 5};
	mesh m;
	if (subd_tessellate(&cc, &o, &m, &d, diag_noloc())) {
		check_closed("subdivided cube", &m, 0.3f, count / 3, 1);
		mesh_free(&m);
	}
	vec3 oct[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
	uint32_t ts[8] = {3, 3, 3, 3, 3, 3, 3, 3};
	uint32_t tri[24] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
	subd_cage lc = {.positions = oct, .num_vertices = 6, .face_sizes = ts, .num_faces = 8, .face_indices = tri,
			.scheme = SUBD_LOOP};
	if (subd_tessellate(&lc, &o, &m, &d, diag_noloc())) {
		check_closed("loop octahedron", &m, 0.2f, count / 3, 2);
		mesh_free(&m);
	}
	if (prim_sphere(v3(0, 0, 0), 1.0f, 200, &m)) {
		check_closed("sphere", &m, 0.5f, count - 2 * (count / 3), 3);
		mesh_free(&m);
	}
	CHECK(d.errors == 0, "tessellation errors");
	diag_free(&d);
}

/* The bunny scaled to coordinates of magnitude `scale` (and moved by `shift` scales): rays hit
 * it, and rays spawned from the hit points on either side, offset as the renderer does
 * (bvh_offset_scaled), never hit the same triangle; and the offset is the same fraction of the
 * triangle's scale at every scale (Waechter & Binder's point-sized one, printed beside it, is
 * not). */
static void check_spawn(const mesh *unit, double scale, double shift, long count, uint64_t seed)
{
	mesh m = *unit;
	m.positions = malloc(unit->num_vertices * sizeof(vec3));
	for (uint32_t v = 0; v < unit->num_vertices; v++) {
		vec3 p = unit->positions[v];
		m.positions[v] = v3((float)(p.x * scale + shift * scale), (float)(p.y * scale + shift * scale),
				    (float)(p.z * scale - shift * scale));
	}
	bvh *b = bvh_build(m.positions, m.num_vertices, m.indices, m.num_triangles);
	vec3 lo, hi;
	mesh_bounds(&m, &lo, &hi);
	rng g;
	rng_seed(&g, seed, 4);
	long self = 0, hits = 0;
	double rel = 0.0, wb_rel = 0.0;
	for (long i = 0; i < count && b; i++) {
		bvh_ray r = test_random_ray(&m, lo, hi, &g);
		bvh_hit h;
		if (!bvh_intersect(b, &r, &h))
			continue;
		hits++;
		vec3 ng;
		float sc;
		vec3 p = test_hit_point(&m, &h, &ng, &sc);
		if (v3_dot(ng, r.dir) > 0.0f)
			ng = v3_neg(ng);
		for (int side = 0; side < 2; side++) {
			vec3 n = side ? v3_neg(ng) : ng;
			vec3 d = test_unit_vector(&g);
			if (v3_dot(d, n) < 0.0f)
				d = v3_neg(d);
			vec3 o = bvh_offset_scaled(p, n, sc);
			rel = fmax(rel, v3_length(v3_sub(o, p)) / sc);
			wb_rel = fmax(wb_rel, v3_length(v3_sub(bvh_offset_origin(p, n), p)) / sc);
			bvh_ray s = {o, d, 0.0f, INFINITY};
			bvh_hit h2;
			if (bvh_intersect(b, &s, &h2) && h2.prim == h.prim && self++ < 5)
				CHECK(0, "scale %g: the ray spawned from triangle %u (side %d) hit it again at t %g", scale, h.prim,
				      side, h2.t);
		}
	}
	CHECK(self == 0 && hits > count / 4, "scale %g shift %g: %ld self-hits among %ld hits", scale, shift, self, hits);
	printf("scale %g shift %g: offset at most %.3g of the triangle's scale (Waechter & Binder: %.3g)\n", scale,
	       shift, rel, wb_rel);
	CHECK(rel <= 1.01 * BVH_OFFSET_REL && rel > 0.5 * BVH_OFFSET_REL, "scale %g: offset %.3g of the scale, expected %.3g",
	      scale, rel, (double)BVH_OFFSET_REL);
	bvh_free(b);
	free(m.positions);
}

int main(void)
{
	test_simd_from_env();
	check_watertight(test_count(1000000));
	diag d;
	diag_init(&d, stderr);
	mesh bunny;
	if (test_unit_bunny(&bunny, &d)) {
		for (int e = -8; e <= 8; e += 2) {
			check_spawn(&bunny, pow(10.0, e), 0.0, test_count(20000), 100 + e);
			check_spawn(&bunny, pow(10.0, e), 3.0, test_count(20000), 200 + e);
		}
		mesh_free(&bunny);
	} else {
		CHECK(0, "cannot read the bunny");
	}
	diag_free(&d);
	return check_done("test_robust");
}
