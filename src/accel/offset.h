/* offset.h - where a ray leaving a surface starts, for any scale of scene. bvh_offset_origin
 * (Waechter & Binder 2019) sizes its offset by the hit point's own coordinates, with a fixed
 * 1/65536 below 1/32: right for scenes of unit size, but the error of a hit (the position from
 * barycentrics, and the triangle test's t for the next ray) grows with the magnitude of the
 * triangle's VERTICES, not of the point. A ray leaving a 400-unit face near its middle from behind
 * was reported back on it at t ~ 0 (0.6 % of rays), and a scene scaled by 1e-3 had offsets of
 * 2.5 % of its objects' size (the volume walk rendered 2 % darker). Here the offset is a fixed
 * number of ulps of the triangle's scale, so it follows the scene from 1e-8 to 1e8. */
#ifndef CIRCE_ACCEL_OFFSET_H
#define CIRCE_ACCEL_OFFSET_H

#include "base/vec.h"

#include <math.h>

/* The origin of a ray leaving a surface at p with geometric normal n (pointing to the side the ray
 * goes to), moved off the surface so the ray cannot hit the triangle it left: Waechter & Binder
 * 2019, "A Fast and Robust Method for Avoiding Self-Intersection", Ray Tracing Gems ch. 6, listing
 * 6-1. It sizes the offset by p's coordinates, with a fixed 1/65536 below 1/32, which is far too
 * large for small scenes and too small for a point in the middle of a large triangle: rays from a
 * known triangle use bvh_offset_scaled, this is its fallback for an unknown one (bvh.c). */
vec3 bvh_offset_origin(vec3 p, vec3 n);

/* The offset relative to the scale: 2^-15, 256 ulps of a float of that magnitude (W&B's int_scale). */
#define BVH_OFFSET_REL 3.0517578125e-5f

/* The largest absolute coordinate of a triangle's vertices: the scale of its hit's error. */
static inline float bvh_triangle_scale(vec3 a, vec3 b, vec3 c)
{
	vec3 m = v3_max(v3_max(v3_abs(a), v3_abs(b)), v3_abs(c));
	return fmaxf(m.x, fmaxf(m.y, m.z));
}

/* p moved along n (unit, towards the side the ray goes to) by BVH_OFFSET_REL of scale; falls back
 * to bvh_offset_origin when the scale is unknown (0) or not finite. Since |p| <= scale for a point
 * of the triangle, the step is at least 128 ulps of every coordinate of p. */
static inline vec3 bvh_offset_scaled(vec3 p, vec3 n, float scale)
{
	if (!(scale > 0.0f) || !isfinite(scale))
		return bvh_offset_origin(p, n);
	return v3_madd(p, n, scale * BVH_OFFSET_REL);
}

#endif
