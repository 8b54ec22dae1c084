/* bvh.h - the bounding volume hierarchy of one triangle mesh, traced by rays (closest hit, any hit)
 * and by circles (every hit: circle tracing, DESIGN.md). Built once with binned SAH (Wald 2007,
 * "On fast Construction of SAH-based Bounding Volume Hierarchies"), then read-only: any number of
 * threads may trace one bvh at once. The bvh keeps its own copy of the triangles' vertices, so the
 * mesh may change or go after the build; triangle ids are the mesh's triangle indices.
 * Degenerate triangles (zero area, non-finite vertices) are left out and never hit. */
#ifndef CIRCE_ACCEL_BVH_H
#define CIRCE_ACCEL_BVH_H

#include "accel/tri.h"
#include "base/vec.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef struct bvh bvh;

/* A ray: points org + t dir for t in the closed interval [tmin, tmax]. dir need not be unit;
 * t is in units of |dir|. */
typedef struct bvh_ray {
	vec3 org, dir;
	float tmin, tmax;
} bvh_ray;

/* The closest hit: t, barycentrics (u, v) of the triangle's second and third vertex, triangle
 * id, and for the top level (tlas.h) the instance. */
typedef struct bvh_hit {
	float t, u, v;
	uint32_t prim, inst;
} bvh_hit;

/* Builds over the triangles indices[3i..3i+2] of positions. NULL when memory runs out, an index
 * is out of range (num_vertices bounds them) or there are 2^27 triangles or more. An empty mesh
 * gives a valid bvh that hits nothing. */
bvh *bvh_build(const vec3 *positions, uint32_t num_vertices, const uint32_t *indices,
	       uint32_t num_triangles);
void bvh_free(bvh *b);

/* Closest hit with t in [ray.tmin, ray.tmax]; ties in t go to the lower triangle id, so the result
 * is the one a loop over all triangles with tri_intersect gives. False for a miss and for a ray
 * that tri_ray_prepare rejects (NaN or Inf components, zero direction). */
bool bvh_intersect(const bvh *b, const bvh_ray *ray, bvh_hit *hit);
/* Any hit with t in [tmin, tmax]. */
bool bvh_occluded(const bvh *b, const bvh_ray *ray);

/* Every hit of the circle q (tri.h) on the mesh, in no particular order; prim set, inst 0.
 * Writes at most max_hits to hits and returns the total count (which may be larger: call again
 * with a larger buffer to get them all). A circle with a non-finite or negative radius, or
 * non-finite axes, has no hits. */
uint32_t bvh_circle(const bvh *b, const tri_circle *q, tri_circle_hit *hits, uint32_t max_hits);

/* Traversal on a prepared ray, for the top level: updates *hit when a hit is closer than
 * *tlimit, then lowers *tlimit to it. */
bool bvh_intersect_prepared(const bvh *b, const tri_ray *r, float *tlimit, bvh_hit *hit);
bool bvh_occluded_prepared(const bvh *b, const tri_ray *r);

/* Bounds of the triangles that can be hit; false when there are none. */
bool bvh_bounds(const bvh *b, vec3 *lo, vec3 *hi);
/* Bytes held by the bvh (nodes and triangle copies), and its counts, for statistics. */
size_t bvh_bytes(const bvh *b);
uint32_t bvh_num_nodes(const bvh *b);
/* Children a node (4 or 8): 8 where the build found a CPU with AVX2, whose kernels then trace it;
 * 4, traced with SSE2, elsewhere or when the environment variable CIRCE_SIMD is "sse2" at the
 * build. Both give the same hits, bit for bit. */
uint32_t bvh_width(const bvh *b);

/* The origin of a ray leaving a surface at p with geometric normal n (pointing to the side the ray
 * goes to), moved off the surface so the ray cannot hit the triangle it left: Waechter & Binder
 * 2019, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems ch. 6, listing
 * 6-1. It sizes the offset by p's coordinates, with a fixed 1/65536 below 1/32, which is far too
 * large for small scenes and too small for a point in the middle of a large triangle: rays from a
 * known triangle use bvh_offset_scaled (offset.h), this is its fallback for an unknown one. */
vec3 bvh_offset_origin(vec3 p, vec3 n);

/* The node-level tree of any set of boxes (used for triangles and for instances): binned SAH over
 * the boxes' centroids, pricing a leaf by its count rounded up to whole leaf_blocks (the
 * primitives its test takes at once; a power of two). perm receives the order of the boxes in the leaves.
 * Internal to accel. */
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
