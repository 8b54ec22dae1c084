/* tlas.h - the top level: a BVH over instances, each a mesh BVH (bvh.h) placed by an affine
 * transform. Instances share their bvh, so memory grows with unique geometry, not with copies
 * (about 100 bytes per instance). Read-only after the build; the bvhs must outlive the tlas. */
#ifndef CIRCE_ACCEL_TLAS_H
#define CIRCE_ACCEL_TLAS_H

#include "accel/bvh.h"

typedef struct tlas tlas;

/* set: a tag tlas_circle_set and tlas_intersect_set select instances by (for the renderer, the
 * SSS volume the instance belongs to); 0 when unused. */
/* filtered: the instance's ray hits go through the tlas's filter (tlas_set_filter), which may
 * reject them; key is what the filter is given for the instance. */
typedef struct tlas_instance {
	const bvh *geom;
	xform to_world;
	uint32_t set;
	bool filtered;
	uint32_t key;
} tlas_instance;

/* A hit filter: true keeps the hit (hit->t, u, v, prim: in instance space, t in units of the world
 * ray's |dir|) of the ray on the filtered instance whose key is `key`. A rejected hit is stepped
 * over: the traversal looks for the instance's next hit along the ray (closest and any hit alike).
 * It must be a pure function of its arguments (rays are traced by many threads at once). */
typedef bool (*tlas_filter)(void *user, uint32_t key, const bvh_ray *ray, const bvh_hit *hit);

/* Restricts tlas_circle to no instance in particular. */
#define TLAS_ALL_INSTANCES UINT32_MAX

/* NULL when memory runs out. Instances whose bvh is empty are kept (and never hit). */
tlas *tlas_build(const tlas_instance *instances, uint32_t count);
void tlas_free(tlas *t);
/* The filter of the filtered instances (none until set: their hits are all kept). Set it before
 * any ray is traced. */
void tlas_set_filter(tlas *t, tlas_filter fn, void *user);
size_t tlas_bytes(const tlas *t);

/* Closest hit over all instances, in world space: hit->inst is the instance's index, hit->prim
 * the triangle id in its mesh, t in units of the world ray's |dir|. Rays with NaN or Inf
 * components are rejected. */
bool tlas_intersect(const tlas *t, const bvh_ray *ray, bvh_hit *hit);
bool tlas_occluded(const tlas *t, const bvh_ray *ray);
/* tlas_intersect over the instances whose set is `set` alone (the others are transparent). */
bool tlas_intersect_set(const tlas *t, const bvh_ray *ray, uint32_t set, bvh_hit *hit);

/* bvh_nearest over the instances whose set is `set`, in world space: a lower bound on the
 * distance from p to their nearest triangle, or cap when none is nearer. An instance under a
 * similarity transform scales its object-space distance by the scale (less a relative 1e-5 for
 * the float transform); one under any other transform, a distance to its world box only. */
float tlas_nearest_set(const tlas *t, vec3 p, uint32_t set, float cap);

/* Every hit of the world-space circle q on instance `only` (or on all, TLAS_ALL_INSTANCES), with
 * positions and normals in world space and inst set. A circle is traced in an instance's own
 * space, which keeps it a circle only under a similarity transform (DESIGN.md): instances with a
 * non-uniform scale or shear are skipped - the scene build flattens SSS objects that have one.
 * The hits come in the canonical order (tri_circle_hits_sort: by instance index, triangle,
 * angle), whatever the trees. Returns the total count; at most max_hits are written. */
uint32_t tlas_circle(const tlas *t, const tri_circle *q, uint32_t only, tri_circle_hit *hits, uint32_t max_hits);

/* tlas_circle over the instances whose set is `set`, found through the tree: the others cost
 * neither traversal nor room in hits. */
uint32_t tlas_circle_set(const tlas *t, const tri_circle *q, uint32_t set, tri_circle_hit *hits, uint32_t max_hits);

/* True when circles can be traced on instance i (its transform is a similarity). */
bool tlas_circle_ok(const tlas *t, uint32_t i);

#endif
