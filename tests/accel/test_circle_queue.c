/* test_circle_queue: the circle traversal's bounded queue under stress. This program compiles its
 * own BVH (src/accel/bvh.c, Makefile.am) with a queue of eight nodes before it goes depth first
 * (BVH_CIRCLE_FIFO), trees limited to depth 16 (BVH_MAX_DEPTH: the queue's room for a descent is
 * then 120 nodes, and the build splits at the median near the limit) and leaf batches of one
 * (BVH_CIRCLE_LEAF_BATCH). Circles on the head, radii up to half its size, must still equal
 * brute force exactly, having gone depth first many times (under AddressSanitizer, the queue's
 * bounds are checked too). A row of triangles at x = 2^k, which binned SAH peels off one a level,
 * reaches the depth limit: the build keeps within it (asserted in bvh.c) and rays agree with
 * brute force. */
#include "accel/bvh_internal.h"
#include "check.h"
#include "brute.h"

long bvh_circle_queue_lifo;

/* Triangles of unit size in the planes x = 2^k, k = 0 .. n - 1 (binning peels off about four a
 * level: 100 reach depth 16 well before the last). */
static void check_deep_tree(int n)
{
	mesh m;
	CHECK(mesh_alloc(&m, 3 * (size_t)n, (size_t)n, false, false, false), "mesh of %d triangles", n);
	for (int k = 0; k < n; k++) {
		float x = ldexpf(1.0f, k);
		m.positions[3 * k] = v3(x, 0, 0), m.positions[3 * k + 1] = v3(x, 1, 0), m.positions[3 * k + 2] = v3(x, 0, 1);
		for (int c = 0; c < 3; c++)
			m.indices[3 * k + c] = (uint32_t)(3 * k + c);
	}
	bvh *b = bvh_build(m.positions, m.num_vertices, m.indices, m.num_triangles);
	CHECK(b != NULL, "bvh of %d triangles at x = 2^k", n);
	if (b) {
		brute bf = brute_make(&m);
		check_rays("triangles at x = 2^k", &m, &bf, b, test_count(20000), 5);
		/* Along +x from the origin every plane is crossed: the nearest is x = 1. */
		bvh_ray r = {v3(0, 0.25f, 0.25f), v3(1, 0, 0), 0.0f, INFINITY};
		bvh_hit h;
		CHECK(bvh_intersect(b, &r, &h) && h.prim == 0 && fabsf(h.t - 1.0f) < 1e-6f, "ray along the row: prim %u t %g",
		      h.prim, h.t);
		brute_free(&bf);
		bvh_free(b);
	}
	mesh_free(&m);
}

int main(void)
{
	test_simd_from_env();
	mesh m;
	diag d;
	diag_init(&d, stderr);
	const char *rel = "scenes/assets/lee_perry_smith_head/LeePerrySmith.obj";
	if (!mesh_import(test_path(rel), &m, &d)) {
		CHECK(0, "cannot read %s", rel);
		diag_free(&d);
		return check_done("test_circle_queue");
	}
	bvh *b = bvh_build(m.positions, m.num_vertices, m.indices, m.num_triangles);
	CHECK(b != NULL, "bvh of %s", rel);
	if (b) {
		brute bf = brute_make(&m);
		long circles = test_count(20000);
		check_circles(rel, &m, &bf, b, circles, circles, 21);
		printf("test_circle_queue: depth first %ld times (width %u)\n", bvh_circle_queue_lifo, bvh_width(b));
		CHECK(bvh_circle_queue_lifo > circles, "the queue went depth first %ld times", bvh_circle_queue_lifo);
		brute_free(&bf);
		bvh_free(b);
	}
	mesh_free(&m);
	diag_free(&d);
	check_deep_tree(100);
	return check_done("test_circle_queue");
}
