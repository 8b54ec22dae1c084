/* bvh_internal.h - what accel's own files share behind bvh.h's verbs: the binary node tree that
 * bvh.c collapses into wide nodes and tlas.c traces as it is, its build and box tests, the
 * traversal on a prepared ray that the top level calls per instance, and the counts that tests
 * read. Included by accel's own .c files and by the tests of these internals only; the rest of the
 * program sees bvh.h. */
#ifndef CIRCE_ACCEL_BVH_INTERNAL_H
#define CIRCE_ACCEL_BVH_INTERNAL_H

#include "accel/bvh.h"

/* Traversal on a prepared ray, for the top level: updates *hit when a hit is closer than
 * *tlimit, then lowers *tlimit to it. */
bool bvh_intersect_prepared(const bvh *b, const tri_ray *r, float *tlimit, bvh_hit *hit);
bool bvh_occluded_prepared(const bvh *b, const tri_ray *r);

/* The bvh's node count, for statistics. */
uint32_t bvh_num_nodes(const bvh *b);
/* Children a node (4 or 8): 8 where the build found a CPU with AVX2, whose kernels then trace it;
 * 4, traced with SSE2, elsewhere or when bvh_set_simd chose BVH_SIMD_SSE2 before the build. Both
 * give the same hits, bit for bit. */
uint32_t bvh_width(const bvh *b);

/* A node of the binary tree: its box, and a leaf's primitives or an inner node's children. */
typedef struct bvh_node {
	float lo[3];
	uint32_t first; /* leaf: first primitive in perm order; inner: index of the second child */
	float hi[3];
	uint32_t count; /* leaf: number of primitives (> 0); inner: BVH_INNER | split axis */
} bvh_node;
#define BVH_INNER 0x80000000u
/* Max primitives in a leaf (SAH decides below it). */
#define BVH_MAX_LEAF 8
/* Max depth of a tree: traversal stacks hold this many entries. (A test, test_circle_queue,
 * compiles its own BVH with a smaller one.) */
#ifndef BVH_MAX_DEPTH
#define BVH_MAX_DEPTH 62
#endif
/* The node-level tree of any set of boxes (used for triangles and for instances): binned SAH over
 * the boxes' centroids, pricing a leaf by its count rounded up to a whole number of leaf_block
 * (the primitives its test takes at once; a power of two). perm receives the order of the boxes
 * in the leaves. Every leaf holds 1 to BVH_MAX_LEAF boxes, no node is deeper than
 * BVH_MAX_DEPTH - 1 (both asserted), and n boxes make at most 2n - 1 nodes. */
bool bvh_build_nodes(const vec3 *lo, const vec3 *hi, uint32_t n, uint32_t leaf_block, bvh_node **nodes,
		     uint32_t *num_nodes, uint32_t *perm);
static inline vec3 bvh_node_lo(const bvh_node *nd) { return v3(nd->lo[0], nd->lo[1], nd->lo[2]); }
static inline vec3 bvh_node_hi(const bvh_node *nd) { return v3(nd->hi[0], nd->hi[1], nd->hi[2]); }
/* One step down an unordered traversal from an inner node whose children c0, c0 + 1 were tested
 * (h0, h1): go to the first child hit and push the other if both were. False when neither was
 * (the caller pops). */
static inline bool bvh_descend(bool h0, bool h1, uint32_t c0, uint32_t *stack, int *sp, uint32_t *ni)
{
	if (h0 && h1)
		stack[(*sp)++] = c0 + 1;
	if (!(h0 || h1))
		return false;
	*ni = h0 ? c0 : c0 + 1;
	return true;
}
/* Slab test of a ray against a node, conservative against rounding: true when the box may hold
 * a hit with t in [r->tmin, tlimit]; *tnear receives the entry distance. */
bool bvh_node_hit(const bvh_node *nd, const tri_ray *r, float tlimit, float *tnear);
/* Conservative circle/box test: the box meets the circle's own bounds, its plane and the
 * spherical shell of its radius (and, for a half circle, the half space cos theta >= 0). */
bool bvh_box_circle(vec3 lo, vec3 hi, const tri_circle *q);

#endif
