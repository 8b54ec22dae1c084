/* fog.h - POV-Ray's fog along a ray (POV-Ray 3.7 trace.cpp ComputeFog, ComputeConstantFogDepth,
 * ComputeGroundFogDepth): a segment of length t keeps att = exp(-tau / distance) of the light
 * behind it and gains (1 - att) * colour; tau = t for a constant fog, the integral of the ground
 * fog's density along the segment otherwise. Several fogs multiply their att and add their
 * colours, as POV-Ray's loop does. */
#ifndef CIRCE_RENDER_FOG_H
#define CIRCE_RENDER_FOG_H

#include "base/vec.h"

#include <stdbool.h>
#include <stddef.h>

/* The most fogs a scene renders (the build warns beyond). */
#define RENDER_MAX_FOGS 8

typedef struct render_fog {
	bool ground;	/* POV-Ray's fog_type 2 */
	float distance; /* > 0: the length over which the fog keeps 1 / e */
	vec3 color;
	float offset, alt; /* ground: height (along up) below which the density is 1; its scale */
	vec3 up;	   /* ground: unit */
} render_fog;

/* The optical depth of f over the segment o + s d, s in [0, t] (t may be INFINITY; d unit):
 * t for a constant fog; for a ground fog the integral of its density, 1 at heights h <= 0 and
 * 1 / (1 + h^2) above, h = (y - offset) / alt (alt 0: 1 below offset, 0 above). */
double render_fog_depth(const render_fog *f, vec3 o, vec3 d, double t);

/* What the fogs do to a segment: the light from beyond is multiplied by *att and *add is
 * added to it. */
void render_fog_segment(const render_fog *fogs, size_t n, vec3 o, vec3 d, float t, vec3 *att, vec3 *add);

#endif
