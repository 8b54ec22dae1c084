/* integrator.h - the unidirectional path tracer and the narrow scene interface it traces through.
 * The integrator knows nothing of the scene language, meshes or BVHs: a scene is a render_scene,
 * two callbacks (nearest hit, any hit) plus the material table and the light set. The lead's glue
 * backs intersect/occluded with bvh_intersect/bvh_occluded and fills render_hit from the triangle;
 * tests back them with analytic spheres and planes.
 *
 * Light transport: next-event estimation to one light chosen by power (light_set_pick) plus a BSDF
 * sample that continues the path; the two are combined by the power heuristic (Veach 1997, 9.2).
 * RENDER_LIGHT_ONLY and RENDER_BSDF_ONLY keep one strategy at full weight, for tests (BSDF-only
 * cannot see delta lights). Russian roulette starts after RENDER_RR_DEPTH scattering events, with
 * survival probability min(1, max component of the path throughput). max_trace_level is the most
 * scattering events of a path (POV-Ray's meaning: 1 is direct light only); emission reached after
 * the last event still counts. All randomness comes from the rng given per sample. */
#ifndef CIRCE_RENDER_INTEGRATOR_H
#define CIRCE_RENDER_INTEGRATOR_H

#include "base/rng.h"
#include "base/vec.h"
#include "render/bsdf.h"
#include "render/camera.h"
#include "render/light.h"

#include <stdbool.h>
#include <stdint.h>

/* What intersect reports about the nearest surface. */
typedef struct render_hit {
	float t;	       /* distance along the (unit) ray direction */
	vec3 p;		       /* world position */
	vec3 ng;	       /* unit geometric normal, either orientation */
	vec3 ns;	       /* unit shading normal (interpolated/normal-mapped), same hemisphere as ng */
	vec2 uv;	       /* texture coordinates */
	int material;	       /* index into render_scene.materials; -1: a black, non-reflecting surface */
	int light;	       /* index into render_scene.lights->lights of the emissive mesh (LIGHT_MESH)
				  this surface belongs to, or -1 */
	uint32_t object, prim; /* the scene's own ids, passed back to shade() for texture lookups */
} render_hit;

typedef struct render_scene {
	void *user; /* handed to every callback */
	/* Nearest hit with t in (tmin, tmax); fills *hit. Must be thread-safe (called concurrently). */
	bool (*intersect)(void *user, const render_ray *ray, float tmin, float tmax, render_hit *hit);
	/* Any hit with t in (tmin, tmax): the shadow test. Surfaces marked no_shadow should be skipped. */
	bool (*occluded)(void *user, const render_ray *ray, float tmin, float tmax);
	/* Optional (NULL: materials are used as they are): applies textures and normal maps at the
	 * hit, starting from *params = materials[hit->material] and *ns = hit->ns. Thread-safe. */
	void (*shade)(void *user, const render_hit *hit, bsdf_params *params, vec3 *ns);
	const bsdf_params *materials;
	size_t material_count;
	const light_set *lights; /* finished (light_set_finish); sphere lights are traced here */
} render_scene;

typedef enum render_mode { RENDER_MIS, RENDER_LIGHT_ONLY, RENDER_BSDF_ONLY } render_mode;

#define RENDER_RR_DEPTH		       3
#define RENDER_DEFAULT_MAX_TRACE_LEVEL 5 /* POV-Ray's default */

typedef struct render_settings {
	int max_trace_level; /* >= 1 */
	render_mode mode;
} render_settings;

/* One camera sample: radiance and the AOVs of the first surface hit (zero where the ray escapes). */
typedef struct render_sample {
	vec3 radiance;
	vec3 albedo; /* bsdf_albedo of the first hit */
	vec3 normal; /* world shading normal of the first hit, facing the camera */
	float depth; /* distance from the camera to the first hit, 0 when none */
} render_sample;

/* Traces one path from the camera ray; g supplies every random number. May return non-finite
 * radiance when the scene does (the film drops such samples). */
render_sample render_path(const render_scene *scene, const render_settings *settings, render_ray ray, rng *g);

#endif
