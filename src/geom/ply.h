/* ply.h - a structural check of PLY files before Assimp reads them. Assimp 5 loops forever on a
 * header without end_header and aborts (an assertion in its triangulation) on a file whose data
 * ends before the elements its header declares: a truncated download would hang or crash circe.
 * This walks the header and every element of the body (ASCII tokens, or binary sizes with list
 * counts decoded in the file's byte order) without building anything, so such files become errors
 * with a reason. It checks structure only: values and indices are Assimp's and mesh.c's to judge. */
#ifndef CIRCE_GEOM_PLY_H
#define CIRCE_GEOM_PLY_H

#include <stdbool.h>
#include <stddef.h>

/* The longest header accepted; past it without end_header the file is refused. */
#define PLY_MAX_HEADER (1u << 20)
/* The longest list (a polygon's vertex count, say) accepted in a file. */
#define PLY_MAX_LIST 65535

/* True when data (len bytes, the whole file) is not a PLY file at all (it does not start with the
 * line "ply" or "PLY", Assimp's two magics) or is a structurally complete one; false with the
 * reason in why (len why_len) otherwise. */
bool ply_check(const char *data, size_t len, char *why, size_t why_len);

#endif
