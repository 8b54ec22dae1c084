/* cage.h - subdivision control cages read from files, polygons kept as they are (no
 * triangulation), for `subdivision_surface { file "cage.obj" }`.
 * OBJ goes through circe's own reader (cage.c): Assimp's OBJ loader drops OpenSubdiv's `t` tag
 * lines (creases, corners, holes, boundary rule) and renumbers vertices per face corner, so the
 * vertex indices the tags and the scene's creases name would be lost. Other formats (PLY, glTF,
 * ...) go through Assimp's C API without aiProcess_Triangulate (import.c).
 * Either way the cage is welded: vertices at exactly the same position become one (files
 * duplicate them at UV seams; a cage that does not share them tears apart), and face-varying UVs
 * are renumbered by (welded vertex, exact UV value). */
#ifndef CIRCE_GEOM_CAGE_H
#define CIRCE_GEOM_CAGE_H

#include "base/diag.h"
#include "base/mem.h"
#include "geom/subdiv.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* A cage read from a file; owns its arrays (cage_free). Vertex indices are of the welded cage,
 * except that `weld` maps the file's own vertex numbers (zero-based: OBJ's `v` order, Assimp's
 * vertex order over the file's meshes) to them: the numbers tags and scenes write. */
typedef struct cage_data {
	vec3 *positions;
	uint32_t num_vertices;	    /* after welding */
	uint32_t num_file_vertices; /* before: the range of weld */
	uint32_t *weld;		    /* file vertex -> welded vertex */
	uint32_t *face_sizes;
	uint32_t num_faces;
	uint32_t *face_indices; /* sum of face_sizes */
	vec2 *uvs;		/* NULL: no UVs (some face corner had none) */
	uint32_t num_uvs;
	uint32_t *uv_indices; /* layout of face_indices */
	/* From the file's tags (OBJ only), in welded vertex numbers. */
	uint32_t *crease_vertices; /* 2 per crease */
	float *crease_sharpness;
	uint32_t num_creases;
	uint32_t *corner_vertices;
	float *corner_sharpness;
	uint32_t num_corners;
	uint32_t *hole_faces;
	uint32_t num_holes;
	bool has_boundary; /* the file names a boundary rule (`t interpolateboundary`) */
	subd_boundary boundary;
	uint64_t *edges; /* sorted keys of the welded cage's edges (cage_has_edge) */
	size_t num_edges;
} cage_data;

/* Reads the cage at path (OBJ by its suffix, any other format through Assimp), welds it and
 * checks it: at least one face, every face of 3 or more distinct vertices, indices in range, tags
 * on edges and vertices that exist. Errors and warnings (an ignored tag) are reported at loc, the
 * place in the scene that named the file, as "cage file 'PATH': ..." with the file's line when
 * there is one. False (and an empty cage) on error. */
bool cage_load(const char *path, cage_data *out, diag *d, diag_loc loc);
void cage_free(cage_data *c);

/* True when the welded vertices a and b are joined by an edge of some face. */
bool cage_has_edge(const cage_data *c, uint32_t a, uint32_t b);

/* The subd_cage view of c (its arrays, not copies), with the file's tags; scheme and boundary are
 * left to the caller. */
subd_cage cage_view(const cage_data *c);

/* ---- for the importers (cage.c, import.c) ------------------------------------------------- */

/* The file's polygons before welding: positions in file order, faces, and optional per-corner
 * UVs. Filled by a reader, then cage_build welds them into a cage_data. */
typedef struct cage_raw {
	vecbuf positions;  /* vec3 */
	vecbuf uvs;	   /* vec2 */
	vecbuf face_sizes; /* uint32_t */
	vecbuf face_lines; /* uint32_t: the file's line of each face (0: none) */
	vecbuf indices;	   /* uint32_t, into positions */
	vecbuf uv_indices; /* uint32_t, into uvs; empty when a corner had none */
	bool uv_missing;   /* some corner had no UV */
} cage_raw;

/* Assimp's formats into raw polygons (import.c). False after setting *why (static text or buf). */
bool cage_import_assimp(const char *path, cage_raw *raw, char *buf, size_t len, const char **why);

#endif
