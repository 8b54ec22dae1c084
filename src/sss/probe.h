/* probe.h - how the SSS comparators (disk.h, walk.h) see the geometry: one callback that traces a
 * world-space ray against ONE object (the SSS volume) and returns its closest hit, so these
 * modules and their tests need no renderer. probe.c gives the callback for a BVH built in world
 * space over a mesh (flattened objects, tests); an instanced object needs its own callback that
 * moves the ray into object space and the hit back. */
#ifndef CIRCE_SSS_PROBE_H
#define CIRCE_SSS_PROBE_H

#include "accel/bvh.h"
#include "base/vec.h"
#include "geom/mesh.h"

#include <stdbool.h>
#include <stdint.h>

/* One hit of a ray on the object, in world space. */
typedef struct sss_probe_hit {
	float t;      /* along the ray, in units of |dir| */
	vec3 p;	      /* position */
	vec3 ng;      /* unit geometric normal (v1 - v0) x (v2 - v0): outward on a well-wound mesh */
	uint32_t prim; /* triangle */
	float u, v;    /* barycentrics of the triangle's second and third vertex */
	float scale;   /* the triangle's scale for ray offsets (accel/offset.h); 0: unknown */
} sss_probe_hit;

/* The closest hit of ray on the object with t in [ray->tmin, ray->tmax]: true and *hit filled, or
 * false for a miss. Must be thread-safe for concurrent calls with the same ctx. */
typedef bool (*sss_probe_fn)(const void *ctx, const bvh_ray *ray, sss_probe_hit *hit);

/* A lower bound on the distance from p to the object's surface, or cap (> 0) when it is at
 * least cap away (accel's bvh_nearest, tlas_nearest_set): the ball of that radius about p holds
 * no surface, so a walk's ray that stays inside it cannot hit one (walk.c skips the cast). 0 is
 * always a valid answer. Thread-safe like sss_probe_fn. */
typedef float (*sss_probe_nearest_fn)(const void *ctx, vec3 p, float cap);

typedef struct sss_probe {
	sss_probe_fn closest;
	const void *ctx;
	sss_probe_nearest_fn nearest; /* NULL: not known (the walk casts every step) */
} sss_probe;

/* A mesh in world space and its BVH (bvh_build over the same positions and indices). */
typedef struct sss_probe_mesh {
	const bvh *bvh;
	const mesh *mesh;
} sss_probe_mesh;

/* The probe of an sss_probe_mesh (ctx points to it and must outlive the probe), with the nearest
 * surface by bvh_nearest. */
sss_probe sss_probe_of_mesh(const sss_probe_mesh *pm);

/* Every hit along the ray with t in [tmin, tmax], ascending, by repeated closest-hit queries:
 * after a hit at t the next query starts at t + SSS_PROBE_GAP (tmax - tmin), so a hit reported by
 * both triangles of a shared edge counts once. Writes at most max_hits and returns the number
 * written; *more (may be NULL) is set when hits were left beyond max_hits. */
int sss_probe_all(const sss_probe *pr, const bvh_ray *ray, sss_probe_hit *hits, int max_hits, bool *more);

/* The relative gap between successive hits of sss_probe_all: two surfaces closer than this
 * fraction of the segment count as one (the same hit on two triangles of an edge differs by a
 * few ulps of t). */
#define SSS_PROBE_GAP 1e-6f

#endif
