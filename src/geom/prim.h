/* prim.h - the analytic primitives of the scene language as triangle meshes: sphere, box, and the
 * infinite plane cut to a box or to the view of an eye. Each fills a mesh (mesh.h) with positions,
 * outward unit normals and UVs, in the primitive's own space (transforms belong to the instance). */
#ifndef CIRCE_GEOM_PRIM_H
#define CIRCE_GEOM_PRIM_H

#include "geom/mesh.h"

/* Longitude/latitude sphere: `segments` around (>= 3) and segments / 2 from pole to pole, the
 * poles shared by their fans so the mesh is closed. UV: u = longitude / 2 pi, v = latitude. */
bool prim_sphere(vec3 centre, float radius, uint32_t segments, mesh *out);
/* The segment count giving a chordal error at most max_error (scene units) on the radius. */
uint32_t prim_sphere_segments(float radius, float max_error);

/* Sphere tessellation levels, shared by every sphere of a scene through instancing: level k has
 * PRIM_SPHERE_MIN_SEGMENTS << k segments around, up to the cap PRIM_SPHERE_LEVELS - 1. The
 * coarsest keeps a sphere within 1 % of its radius wherever it is seen (shadows, reflections, SSS);
 * the finest is today's detail for a sphere that fills the screen (65,024 triangles). */
#define PRIM_SPHERE_MIN_SEGMENTS 32u
#define PRIM_SPHERE_LEVELS 5u
uint32_t prim_sphere_level_segments(uint32_t level);
/* A bound on how far prim_sphere's surface lies inside the sphere of radius 1, for `segments`:
 * the largest depth of a triangle's plane below the sphere, over the latitude bands. */
double prim_sphere_rel_error(uint32_t segments);

/* The box between two opposite corners (any order): 6 faces of 2 triangles with flat normals,
 * 24 vertices. A box flat along one axis (POV-Ray renders it: its slab test meets the plane) is
 * the one rectangle, facing +axis: 2 triangles, 4 vertices (flat along more: a rectangle of no
 * area, never hit). */
bool prim_box(vec3 corner1, vec3 corner2, mesh *out);

/* The plane { normal, offset } (points p with dot(p, normal) = offset * |normal|, as POV-Ray),
 * clipped to the box [lo, hi] grown by 1 % of its size on each side: a convex polygon of 3 to 6 vertices, fanned. False
 * when the plane misses the box (an empty mesh is returned) or the normal is zero. */
bool prim_plane(vec3 normal, float offset, vec3 lo, vec3 hi, mesh *out);

/* The plane { normal, offset } as seen from eye: square rings around the eye's foot on the plane,
 * each twice the size of the one inside, out to where the plane is seen within horizon_rad of its
 * horizon (h / tan(horizon_rad) from the foot, h the eye's height above it). Triangles grow with
 * their distance from the eye, so their float error is that of geometry around them, and the rings
 * share their corners (no T-junctions). UVs are planar, from the foot of the origin, so they do
 * not move with the eye. False when the normal is zero or the rings would exceed
 * PRIM_PLANE_MAX_RINGS. */
#define PRIM_PLANE_MAX_RINGS 40
bool prim_plane_view(vec3 normal, float offset, vec3 eye, float horizon_rad, mesh *out);

#endif
