/* subdiv.h - subdivision surfaces tessellated on their limit surface, through OpenSubdiv 3.5's Bfr
 * API (subdiv.cpp, the only C++ file of circe, is the shim behind these C functions).
 * The result is a triangle mesh whose vertices lie on the limit surface with limit normals; points
 * along a cage edge shared by two faces are evaluated once and shared, so the mesh is watertight.
 * Two modes: a uniform level (each face edge split into 2^level segments), or screen-adaptive
 * (each cage edge split so no segment is longer than max_edge_px pixels through the camera). */
#ifndef CIRCE_GEOM_SUBDIV_H
#define CIRCE_GEOM_SUBDIV_H

#include "base/diag.h"
#include "geom/mesh.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef enum subd_scheme { SUBD_CATMULL_CLARK, SUBD_LOOP } subd_scheme;
typedef enum subd_boundary { SUBD_BOUNDARY_EDGE_ONLY, SUBD_BOUNDARY_EDGE_AND_CORNER } subd_boundary;

/* The control cage. Faces are listed by size (face_sizes) with their vertex indices one after the
 * other (face_indices, zero-based, counter-clockwise seen from outside). Creases are pairs of
 * vertices that must be an edge of the cage, with a sharpness (0 smooth .. 10 and above
 * infinitely sharp). Corners are vertices with a sharpness. When an edge or a corner vertex is
 * listed twice, the later sharpness holds. Holes are faces left out of the surface (they still shape their neighbours).
 * UVs are face-varying: uv_indices has the layout of face_indices and points into uvs (NULL: no
 * UVs). source names the file the cage came from in errors (NULL: an inline cage). */
typedef struct subd_cage {
	const vec3 *positions;
	uint32_t num_vertices;
	const uint32_t *face_sizes;
	uint32_t num_faces;
	const uint32_t *face_indices;
	const uint32_t *crease_vertices; /* 2 per crease */
	const float *crease_sharpness;
	uint32_t num_creases;
	const uint32_t *corner_vertices;
	const float *corner_sharpness;
	uint32_t num_corners;
	const uint32_t *hole_faces;
	uint32_t num_holes;
	const vec2 *uvs;
	uint32_t num_uvs;
	const uint32_t *uv_indices;
	subd_scheme scheme;
	subd_boundary boundary;
	const char *source;
} subd_cage;

/* The pinhole camera the adaptive mode measures edges through, in the cage's space: position,
 * look direction and up (unit or not), vertical field of view in degrees (a focal length f with a
 * sensor height h gives 2 atan(h / 2f)), and the image height in pixels. */
typedef struct subd_camera {
	vec3 position, look, up;
	float fov_y_deg;
	uint32_t image_height;
} subd_camera;

/* camera NULL or max_edge_px <= 0: uniform mode with `level` (0 to SUBD_MAX_LEVEL).
 * Otherwise adaptive with max_edge_px, each edge's rate capped at max_rate (0: SUBD_MAX_RATE).
 * max_bytes bounds the estimated memory of the result and its BVH (0: SUBD_DEFAULT_MAX_BYTES). */
typedef struct subd_options {
	int level;
	float max_edge_px;
	const subd_camera *camera;
	int max_rate;
	size_t max_bytes;
} subd_options;

/* OpenSubdiv stores the level in 4 bits; circe refuses what it would wrap. */
#define SUBD_MAX_LEVEL 15
#define SUBD_MAX_RATE 4096
#define SUBD_DEFAULT_MAX_BYTES ((size_t)1 << 30)
/* Estimated bytes per output triangle: indices (12), a vertex with position, normal and UV (32,
 * one per triangle at most), and the BVH's triangle copy and nodes (about 56). */
#define SUBD_BYTES_PER_TRIANGLE 100u

/* Tessellates the cage into out (positions, normals, and uvs when the cage has them). Errors -
 * invalid topology, indices out of range, a crease that is not an edge, a level out of range, an
 * estimate over the memory limit, OpenSubdiv's own errors - are reported at loc and return false
 * with out empty. Thread-safe apart from OpenSubdiv's global error callbacks, installed once. */
bool subd_tessellate(const subd_cage *cage, const subd_options *opt, mesh *out, diag *d, diag_loc loc);

/* The number of triangles subd_tessellate would produce (an upper estimate), or 0 on invalid
 * input; *bytes receives the memory estimate. Cheap: no OpenSubdiv call. */
uint64_t subd_estimate(const subd_cage *cage, const subd_options *opt, uint64_t *bytes);

#ifdef __cplusplus
}
#endif

#endif
