/* prim.h - the analytic primitives of the scene language as triangle meshes: sphere, box, and the
 * infinite plane cut to the scene's bounds. Each fills a mesh (mesh.h) with positions, outward
 * unit normals and UVs, in the primitive's own space (transforms belong to the instance). */
#ifndef CIRCE_GEOM_PRIM_H
#define CIRCE_GEOM_PRIM_H

#include "geom/mesh.h"

/* Longitude/latitude sphere: `segments` around (>= 3) and segments / 2 from pole to pole, the
 * poles shared by their fans so the mesh is closed. UV: u = longitude / 2 pi, v = latitude. */
bool prim_sphere(vec3 centre, float radius, uint32_t segments, mesh *out);
/* The segment count giving a chordal error at most max_error (scene units) on the radius. */
uint32_t prim_sphere_segments(float radius, float max_error);

/* The box between two opposite corners (any order): 6 faces of 2 triangles with flat normals,
 * 24 vertices. Degenerate (a zero extent) boxes are still written and simply never hit. */
bool prim_box(vec3 corner1, vec3 corner2, mesh *out);

/* The plane { normal, offset } (points p with dot(p, normal) = offset * |normal|, as POV-Ray),
 * clipped to the box [lo, hi] grown by 1 %: a convex polygon of 3 to 6 vertices, fanned. False
 * when the plane misses the box (an empty mesh is returned) or the normal is zero. */
bool prim_plane(vec3 normal, float offset, vec3 lo, vec3 hi, mesh *out);

#endif
