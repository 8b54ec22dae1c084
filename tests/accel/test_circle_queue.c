/* test_circle_queue: the circle traversal's bounded queue under stress. This program compiles its
 * own BVH (src/accel/bvh.c, Makefile.am) with a queue of eight nodes before it goes depth first
 * (BVH_CIRCLE_FIFO), trees limited to depth 16 (BVH_MAX_DEPTH: the queue's room for a descent is
 * then 120 nodes, and the build splits at the median near the limit) and leaf batches of one
 * (BVH_CIRCLE_LEAF_BATCH). Circles on the head, radii up to half its size, must still equal
 * brute force exactly, having gone depth first many times (under AddressSanitizer, the queue's
 * bounds are checked too). */
#include "accel/bvh_internal.h"
#include "check.h"
#include "brute.h"

long bvh_circle_queue_lifo;

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
	return check_done("test_circle_queue");
}
