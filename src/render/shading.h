/* shading.h - helpers for the scene's shade() hook (integrator.h): tangent-space normal mapping.
 * Texture lookup itself lives with the images (io); this is only the frame arithmetic. */
#ifndef CIRCE_RENDER_SHADING_H
#define CIRCE_RENDER_SHADING_H

#include "base/vec.h"

/* The shading normal from a tangent-space normal-map texel rgb in [0,1]^3 (the MikkTSpace
 * convention of glTF and most tools: rgb * 2 - 1 gives (x, y, z) along the tangent, the bitangent
 * bitangent_sign * (n x tangent), and n). strength scales the x and y deviations (1: as
 * painted, 0: the map has no effect). n must be unit; the tangent need not be orthogonal to n (it
 * is orthogonalised) nor unit: only its direction counts, whatever its length (1e-30 or 1e30). Returns a unit vector in n's hemisphere; n itself when the input is
 * degenerate (zero tangent, texel pointing below the surface). */
vec3 render_normal_map(vec3 n, vec3 tangent, float bitangent_sign, vec3 rgb, float strength);

#endif
