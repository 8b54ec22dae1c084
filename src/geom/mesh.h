/* mesh.h - the triangle mesh every object of circe becomes, and the ways to make one: plain arrays
 * (mesh/mesh2), files through Assimp (import.c), primitives (prim.c) and subdivision (subdiv.h).
 * A mesh owns its arrays (allocated with mem_alloc, released by mesh_free). Optional attributes
 * are NULL when absent. Indices are 32-bit, three per triangle, counter-clockwise seen from the
 * side the geometric normal (v1 - v0) x (v2 - v0) points to. */
#ifndef CIRCE_GEOM_MESH_H
#define CIRCE_GEOM_MESH_H

#include "base/diag.h"
#include "base/vec.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* A tangent-space frame's tangent: the direction of increasing u, and the handedness sign of the
 * bitangent (b = sign * cross(n, t)), as glTF and MikkTSpace store it. */
typedef struct mesh_tangent {
	vec3 t;
	float sign;
} mesh_tangent;

typedef struct mesh {
	uint32_t num_vertices, num_triangles;
	vec3 *positions;        /* num_vertices */
	vec3 *normals;          /* shading normals, unit length, or NULL */
	vec2 *uvs;              /* or NULL */
	mesh_tangent *tangents; /* or NULL */
	uint32_t *indices;      /* 3 * num_triangles, each < num_vertices */
} mesh;

/* Allocates the arrays of a mesh of nv vertices and nt triangles; the optional attributes are
 * allocated when their flag is set. Contents are uninitialised. False (and an empty mesh) when
 * memory runs out or a count overflows. */
bool mesh_alloc(mesh *m, size_t nv, size_t nt, bool normals, bool uvs, bool tangents);
void mesh_free(mesh *m);
/* A deep copy of src into dst (its own arrays); false when memory runs out (dst left empty). */
bool mesh_copy(mesh *dst, const mesh *src);
/* Bytes held by the mesh's arrays. */
size_t mesh_bytes(const mesh *m);
/* Whether every index is below num_vertices (the invariant of a mesh; asserted where one is used). */
bool mesh_indices_valid(const mesh *m);

/* The POV-Ray mesh2 / mesh data: positions with per-corner index triples for positions and,
 * optionally, normals and UVs (normal_indices / uv_indices may be NULL: then the position indices
 * are used). Corners with distinct (position, normal, uv) become distinct vertices. An index out of
 * range is reported at loc ("face N: ...") and returns false. */
typedef struct mesh_arrays {
	const vec3 *positions;
	size_t num_positions;
	const vec3 *normals; /* or NULL */
	size_t num_normals;
	const vec2 *uvs; /* or NULL */
	size_t num_uvs;
	const uint32_t *face_indices; /* 3 per face */
	const uint32_t *normal_indices, *uv_indices;
	size_t num_faces;
} mesh_arrays;
bool mesh_from_arrays(const mesh_arrays *a, mesh *out, diag *d, diag_loc loc);

/* Reads a mesh file through Assimp (OBJ, PLY, glTF/GLB, STL, ...): all meshes of the file,
 * flattened through their node transforms, polygons triangulated, points and lines dropped.
 * Keeps the file's normals, first UV channel and tangents where it has them. Errors name the file
 * and give Assimp's reason. */
bool mesh_import(const char *path, mesh *out, diag *d);

/* The largest magnitude a mesh file's coordinate may have (after its node transforms): far beyond
 * any model, and small enough that squares and cross products of edges stay finite in float. */
#define MESH_MAX_COORD 1e15f

/* Removes every triangle whose three corner positions (compared as floats, -0 equal to +0, in any
 * order: either winding) are those of an earlier triangle, keeping the first, in order. Returns
 * how many were removed, or SIZE_MAX when memory runs out (m unchanged). Vertices are kept: a
 * duplicate's corners are at the kept triangle's positions, so the bounds do not change. */
size_t mesh_remove_duplicate_triangles(mesh *m);

/* Fills m->tangents from positions, normals and UVs (per-vertex accumulation of the per-triangle
 * tangent of Lengyel 2001, Gram-Schmidt against the normal). Needed when a normal map is used and
 * the file has none. False when the mesh lacks normals or UVs, or memory runs out. Triangles with
 * a degenerate UV mapping get an arbitrary tangent orthogonal to the normal. */
bool mesh_generate_tangents(mesh *m);

/* Applies an affine transform to positions, normals and tangents (normals by the inverse
 * transpose, renormalised). Used to flatten an instance into world space. A transform with a
 * negative determinant flips the winding so geometric normals keep facing outward. */
void mesh_transform(mesh *m, const xform *t);

/* Axis-aligned bounds of the positions; false for an empty mesh. */
bool mesh_bounds(const mesh *m, vec3 *lo, vec3 *hi);

#endif
