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

/* The SIMD path of the builds that follow. BVH_SIMD_AUTO, the default: 8-wide nodes traced with
 * AVX2 where the CPU has it, else 4-wide nodes traced with SSE2 (the x86-64 baseline);
 * BVH_SIMD_SSE2: the 4-wide path on any CPU (main.c chooses it when the environment variable
 * CIRCE_SIMD is "sse2"). Both give the same hits, bit for bit. Set it before other threads build:
 * a bvh keeps the width it was built with, so bvhs of both paths may be traced side by side. */
typedef enum bvh_simd { BVH_SIMD_AUTO, BVH_SIMD_SSE2 } bvh_simd;
void bvh_set_simd(bvh_simd simd);

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

/* Every hit of the circle q (tri.h) on the mesh, in the canonical order (tri_circle_hits_sort:
 * the same for any tree built over the mesh); prim set, inst 0. Writes at most max_hits to hits
 * and returns the total count (which may be larger: call again with a larger buffer to get them
 * all; which hits are kept when there are more is the traversal's choice). A circle with a non-finite or negative radius, or
 * non-finite axes, has no hits. */
uint32_t bvh_circle(const bvh *b, const tri_circle *q, tri_circle_hit *hits, uint32_t max_hits);

/* The distance from p to the nearest triangle of the mesh, or cap when none is nearer than cap
 * (cap > 0; 0 for cap <= 0; cap for an empty bvh or a non-finite p): a lower bound for callers
 * that need a ball free of surface (the volume walk skips the casts inside it, src/sss). The
 * exact point-triangle distance at the leaves (in double), boxes nearer than the best so far
 * visited nearest first; the result is rounded down by a relative 2^-20 and stays below the
 * true distance but for an absolute error of about 1e-15 of the triangles' sizes, which a
 * caller's own margin must cover. Degenerate triangles, never hit, are not counted either. */
float bvh_nearest(const bvh *b, vec3 p, float cap);

/* Bounds of the triangles that can be hit; false when there are none. */
bool bvh_bounds(const bvh *b, vec3 *lo, vec3 *hi);
/* Bytes held by the bvh (nodes and triangle copies), for statistics. */
size_t bvh_bytes(const bvh *b);

#endif
