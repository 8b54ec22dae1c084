/* integrator.h - the unidirectional path tracer and the narrow scene interface it traces through.
 * The integrator knows nothing of the scene language, meshes or BVHs: a scene is a render_scene,
 * five callbacks (intersect: the nearest hit; occluded: any hit; shade: textures and normal maps
 * at a hit; circle and sss_closest: the SSS queries on the volume of a hit) plus the material
 * table, the SSS table and the light set. render/world.c backs them with the built world's BVHs
 * and fills render_hit from the triangle; tests back them with analytic spheres and planes.
 *
 * Light transport: next-event estimation to one light chosen by power (light_set_pick) plus a BSDF
 * sample that continues the path; the two are combined by the power heuristic (Veach 1997, 9.2).
 * RENDER_LIGHT_ONLY and RENDER_BSDF_ONLY keep one strategy at full weight, for tests (BSDF-only
 * cannot see delta lights). Russian roulette starts after RENDER_RR_DEPTH scattering events, with
 * survival probability min(1, max component of the path throughput). max_trace_level is the most
 * scattering events of a path (POV-Ray's meaning: 1 is direct light only); emission reached after
 * the last event still counts. All randomness comes from the sample's sampler (sampler.h), each
 * purpose at a vertex its own dimension.
 *
 * Subsurface scattering (DESIGN.md, "Subsurface scattering"): at a material with a render_sss the
 * coat's specular reflection stays a BSDF lobe; the light it transmits, 1 - F(w_o), goes through
 * the BSSRDF instead of the coat's diffuse interior. One of the two continues the path, chosen by
 * their estimated weights. The BSSRDF samples an entry point x_i (render_sss.method picks how: the
 * dispatch is in integrator.c) and the path goes on from x_i through the entry lobe
 * (1 - F(w_i)) / (c pi) with the shading normal and textures evaluated at x_i; the whole exit-entry
 * step counts as one scattering event. */
#ifndef CIRCE_RENDER_INTEGRATOR_H
#define CIRCE_RENDER_INTEGRATOR_H

#include "accel/tri.h"
#include "base/rng.h"
#include "base/vec.h"
#include "render/bsdf.h"
#include "render/camera.h"
#include "render/fog.h"
#include "render/light.h"
#include "render/media.h"
#include "render/sampler.h"
#include "sss/circle.h"
#include "sss/medium.h"
#include "sss/profile.h"
#include "sss/walk.h"

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
	vec2 bary;     /* barycentrics of the triangle's second and third vertex, for shade() */
	float scale;   /* largest |coordinate| of the triangle's world vertices: rays leaving p start
			  bvh_offset_scaled(p, n, scale) (accel/offset.h); 0: unknown */
	float u_layer; /* in [0, 1): where the material is layered (bsdf_params.layered), the number
			  by which shade() picks a layer; drawn by the integrator, 0 elsewhere */
} render_hit;

/* The BSSRDF of one material (plain data, built once per material). */
typedef struct render_sss {
	sss_method method;   /* never SSS_METHOD_DEFAULT: the build chose */
	sss_profile profile; /* radii in mm, channel albedos A = the material's albedo */
	float units_per_mm;  /* scene units per mm (1 / mm_per_unit): a profile radius to the scene */
	float ior;	     /* of the boundary; the coat's */
	float entry_norm;    /* 1/c of f_t: makes the entry lobe (1 - F(w_i)) cos / (c pi) integrate to 1 */
	sss_walk_medium medium; /* volume and auto: the medium's coefficients per scene unit */
	float auto_ld;	     /* the largest channel's diffuse mean free path l_d, in scene units */
	sss_auto_slab auto_slab; /* auto's light factor: the diffusion slab of the medium (sss/medium.h) */
	float auto_tail_walk, auto_tail_circle; /* auto's profile tail: the thicknesses, scene units, where
						 * the profile's tail is SSS_AUTO_TAIL_WALK and _CIRCLE */
	bool auto_walk;	     /* auto may walk: every object of the material is closed */
	bool auto_open;	     /* the build's: an object of this material under auto is open */
	bool pov_open;	     /* the build's: an object of this POV-Ray subsurface texture is open */
	float pov_k;	     /* its POV-Ray probe factor (sss_pov_gain's k): 1 closed, about 2 open */
	vec3 albedo;	     /* the profile's A: an albedo texture at x_i scales the weight by tex / A;
			      * a POV-Ray subsurface texture's is A / sss_pov_gain (its brightness) */
	bool textured;	     /* the albedo comes from a texture (shade() sets it at x_i) */
} render_sss;

/* The most circle hits kept per circle; a circle with more keeps the first ones, and is counted
 * (render_sample.sss_overflow, printed at the end of a render). */
#define RENDER_SSS_MAX_HITS 64

typedef struct render_scene {
	void *user; /* handed to every callback */
	/* Nearest hit with t in (tmin, tmax); fills *hit (which arrives zeroed: fields left unset stay 0).
	 * Must be thread-safe (called concurrently). */
	bool (*intersect)(void *user, const render_ray *ray, float tmin, float tmax, render_hit *hit);
	/* Any hit with t in (tmin, tmax): the shadow test. Surfaces marked no_shadow should be skipped. */
	bool (*occluded)(void *user, const render_ray *ray, float tmin, float tmax);
	/* Optional (NULL: every surface a shadow ray meets is opaque): the nearest hit with t in
	 * (tmin, tmax) on the surfaces occluded sees, filled like intersect's; shadow rays walk
	 * through transparent ones with it (doc/language.md "Transparency and interiors"). */
	bool (*shadow_closest)(void *user, const render_ray *ray, float tmin, float tmax, render_hit *hit);
	/* Optional (NULL: materials are used as they are): applies textures and normal maps at the
	 * hit, starting from *params = materials[hit->material] and *ns = hit->ns. Thread-safe. */
	void (*shade)(void *user, const render_hit *hit, bsdf_params *params, vec3 *ns);
	const bsdf_params *materials;
	size_t material_count;
	const light_set *lights; /* finished (light_set_finish); sphere lights are traced here */
	/* Indexed like materials: the BSSRDF of a subsurface material (NULL for the others), or NULL
	 * for the whole table when no material is subsurface. */
	const render_sss *const *sss;
	/* Every hit of the world-space circle q on the SSS volume of the surface `at` (its object or
	 * its SSS group), in the canonical order (tri_circle_hits_sort, whatever the trees): its
	 * world position pos on the circle, its angle theta, the geometric normal ng as intersect
	 * fills render_hit's (in the shading normal's hemisphere), inst the object, prim and
	 * barycentrics. Returns how many were written (at most max); *more tells whether there were
	 * others. Needed when sss is not NULL. Thread-safe. */
	uint32_t (*circle)(void *user, const render_hit *at, const tri_circle *q, tri_circle_hit *hits,
			   uint32_t max, bool *more);
	/* The full surface at a hit that circle returned, filled like intersect's (t is 0, p the
	 * circle's position): asked for the chosen hit only. Needed with circle. Thread-safe. */
	void (*circle_surface)(void *user, const tri_circle_hit *h, render_hit *hit);
	/* The nearest hit with t in [tmin, tmax] of a ray on the SSS volume of the surface `at`
	 * alone (other objects are transparent to it), filled like intersect's: the disk's probes
	 * and the volume's walk. Needed when a material uses disk or volume. Thread-safe. */
	bool (*sss_closest)(void *user, const render_hit *at, const render_ray *ray, float tmin, float tmax,
			    render_hit *hit);
	/* A lower bound on the distance from p to the SSS volume of `at` (what sss_closest traces),
	 * or cap when it is at least cap away (tlas_nearest_set, bvh_nearest): the volume walk skips
	 * the casts inside that ball (src/sss/README.md, "Skipping casts"). NULL: the walk casts
	 * every step. Thread-safe. */
	float (*sss_nearest)(void *user, const render_hit *at, vec3 p, float cap);
	/* POV-Ray's fogs (fog.h), applied along camera rays and the mirror-like continuations of
	 * them (a BSDF sample of density >= RENDER_FOG_MIRROR_PDF: POV-Ray's reflection and
	 * refraction rays). Not along diffuse or glossy path rays: a fog is no light of the scene
	 * (escaping, they would see its colour as a sky lighting everything, which POV-Ray without
	 * diffuse interreflection never shows), nor shadow rays (as POV-Ray's lights without
	 * media_attenuation). */
	const render_fog *fogs;
	size_t fog_count;
	/* POV-Ray's media (media.h), indexed like materials: the media of a material's interior
	 * (NULL for a material without), or NULL for the whole table when no material has any. A
	 * path inside a container (entered by refraction through its surface) is tracked through
	 * them, and shadow rays take their transmittance. */
	const render_media *const *media;
	/* The density of medium m at world point p in the container `object` (its patterns live in
	 * the object's space), each channel in [0, m->density_max]. Needed when a medium has a
	 * density pattern. Thread-safe. */
	vec3 (*density)(void *user, uint32_t object, const render_medium *m, vec3 p);
	/* Whether the object is hollow (POV-Ray's flag): the media of a container around it go on
	 * inside it; a non-hollow object inside a container holds none of its media. NULL: none is.
	 * Thread-safe. */
	bool (*hollow)(void *user, uint32_t object);
	/* Optional (NULL: every light lights every surface, its shadow ray running to the light):
	 * POV-Ray's light_group and projected_through (doc/language.md, "Lights"). Whether light
	 * `light` (an index of lights) lights object `object` (a hit's; UINT32_MAX: a medium's point,
	 * lit by the global lights) along the shadow ray `ray` that would reach it at *tmax: false
	 * when the light's group leaves the object out, or the light's projected_through objects are
	 * not met before *tmax; else *tmax becomes the distance to the first of them (only what lies
	 * before shadows). ray NULL: the group alone. Thread-safe. */
	bool (*light_reach)(void *user, uint32_t object, size_t light, const render_ray *ray, float *tmax);
	/* Optional (NULL: every light adds light): per light of the first n_light_sign, the sign of
	 * each channel of its colour, +1 or -1: POV-Ray's negative light takes light away. Its light
	 * holds the colour's magnitude (light selection weighs that); next-event estimation applies
	 * the sign. With it a sample's radiance may be negative (the film keeps it: a pixel's mean is
	 * clamped at 0 when read, as POV-Ray's colour at the end). */
	const vec3 *light_sign;
	size_t n_light_sign;
	/* Optional (NULL: none): POV-Ray's atmospheric media, which fill the space outside every
	 * object and inside hollow ones: every path starts in them (the bottom of its nest of
	 * interiors, under any container it enters), shadow rays take their transmittance; a path
	 * that escapes the scene crosses none of them. density is asked with object UINT32_MAX (world
	 * space). */
	const render_media *atmosphere;
} render_scene;

typedef enum render_mode { RENDER_MIS, RENDER_LIGHT_ONLY, RENDER_BSDF_ONLY } render_mode;

/* The parts of the light a path gathers, by the scattering events before it (the variance
 * breakdown of issue 20: `circe render --part`): seen from the camera with none (emitters, the
 * background, ambient and fog on the camera's ray); after one, by the kind of that event: the
 * coat of a subsurface material (its specular reflection), its BSSRDF (the exit-entry step), any
 * other surface or a medium; after two or more. The five partition the image: every path makes
 * the same random decisions whatever the part (only what it adds is masked), so the parts of one
 * seed sum to the whole image sample by sample. */
typedef enum render_part {
	RENDER_PART_ALL = 0,
	RENDER_PART_CAMERA,
	RENDER_PART_COAT,
	RENDER_PART_SSS,
	RENDER_PART_DIRECT,
	RENDER_PART_INDIRECT,
	RENDER_PART_COUNT
} render_part;
/* Parses all, camera, coat, sss, direct or indirect; false for anything else. */
bool render_part_from_name(const char *name, render_part *part);
const char *render_part_name(render_part part);

#define RENDER_RR_DEPTH		       3
/* A BSDF sample at least this dense (per steradian) continues a mirror's view: its lobe is
 * narrower than 1 / 100 sr (GGX alpha < ~0.06), as POV-Ray's reflection rays. */
#define RENDER_FOG_MIRROR_PDF 100.0f
/* A BSDF sample at least this dense continues a mirror's view of POV-Ray's sky (light.h's
 * seen_only): above any Lambert lobe's (1 / pi) and a rough GGX's (alpha above ~0.3); the tails of
 * POV-Ray's reflection lobe (GGX alpha 0.001) fall below it for under 1 % of its samples (below
 * RENDER_FOG_MIRROR_PDF for 2.6 %: a mirror would darken so much). */
#define RENDER_SKY_MIRROR_PDF 1.0f
#define RENDER_DEFAULT_MAX_TRACE_LEVEL 5 /* POV-Ray's default */

typedef struct render_settings {
	int max_trace_level; /* >= 1 */
	render_mode mode;
	sss_circle_weight circle_weight; /* exact (default, 0) or the talk's, for comparison */
	/* false (default): shadow rays pass through dielectrics tinted (POV-Ray's shadows; paths
	 * refracted after a diffuse bounce then see no emitter, the shadow ray stood for them);
	 * true: dielectrics block shadow rays and only paths find the light through them (caustics,
	 * unbiased, noisy). Thin transparent surfaces pass shadow rays in both (exact). */
	bool opaque_glass_shadows;
	render_part part; /* RENDER_PART_ALL (default): everything */
	/* The camera ray's first hit is sought only this far (cam.max_distance, POV-Ray's mesh_camera
	 * max_distance): beyond it the ray misses; later rays are not limited. 0 (default): none. */
	float camera_tmax;
} render_settings;

/* One camera sample: radiance and the AOVs of the first surface hit (zero where the ray escapes). */
typedef struct render_sample {
	vec3 radiance;
	vec3 albedo; /* bsdf_albedo of the first hit */
	vec3 normal; /* world shading normal of the first hit, facing the camera */
	float depth; /* distance from the camera to the first hit, 0 when none */
	uint32_t sss_searches; /* entry-point searches of this path: circles, disk probes or walks */
	uint32_t sss_nohit;    /* of them, those that found no entry point (no hit; a walk lost or at
				* its step bound): the path ends there */
	uint32_t sss_overflow; /* searches with more hits than kept (the first ones are used) */
	uint32_t sss_walks;    /* searches that were volume walks (volume; auto where it walked) */
	uint32_t sss_walk_dropped; /* of them, walks that reached SSS_WALK_MAX_STEPS: dropped (weight 0,
				    * also in sss_nohit), biased low, so counted and printed */
	uint32_t sss_walk_steps;   /* the interactions of those walks: their cost */
	uint32_t sss_walk_skipped; /* of them, those whose ray cast a ball free of surface answered */
	uint32_t sss_walk_queries; /* the walks' nearest-surface queries (sss_nearest) */
} render_sample;

/* Traces one path from the camera ray; g supplies every random number (its camera dimensions
 * are the caller's: RENDER_DIM_PIXEL and RENDER_DIM_LENS). May return non-finite radiance when
 * the scene does (the film drops such samples). */
render_sample render_path(const render_scene *scene, const render_settings *settings, render_ray ray,
			  render_sampler *g);

#endif
