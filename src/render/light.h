/* light.h - circe's light sources and the set the integrator samples from.
 *   LIGHT_POINT     POV-Ray light_source { V color C }: irradiance C cos times its distance law
 *                   (light_falloff): 1 / d^2 for circe's `intensity` (C is then an intensity,
 *                   W/sr per unit colour), none (POV-Ray's default: C cos at any distance) or
 *                   POV-Ray's fade_distance/fade_power. Delta: only light sampling finds it.
 *                   With an area (light_set_area) it is POV-Ray's area_light made continuous: the
 *                   point is drawn uniformly over a parallelogram or an ellipse about pos at each
 *                   sample, each point a point light of the whole colour (POV-Ray's n1 x n2 array
 *                   with the colour shared among its points, in the limit of many points), so the
 *                   sample stays delta-like: li already holds the estimate, pdf 1, no MIS.
 *   LIGHT_SPOT      a point light times POV-Ray's spot factor: cos^tightness, times 1 inside
 *                   `radius`, 0 outside `falloff` (half-angles in degrees about point_at), a
 *                   smoothstep of cos between (POV-Ray 3.7 Attenuate_Light).
 *   LIGHT_PARALLEL  POV-Ray `parallel`: irradiance C from the fixed direction location->point_at.
 *   LIGHT_CYLINDER  POV-Ray `cylinder`: a parallel beam along location->point_at, lighting only
 *                   points ahead of location within `falloff` of the axis: (1 - r/falloff)^tightness,
 *                   times a smoothstep beyond `radius` (POV-Ray 3.7 Attenuate_Light). Its shadow
 *                   rays end at the plane through location.
 *   LIGHT_SPHERE    POV-Ray `radius R` > 0: a sphere of radius R with uniform radiance
 *                   Le = C / (pi R^2), so from afar it equals the point light of the same colour.
 *                   Sampled by the cone of directions it subtends (uniform in solid angle). The
 *                   integrator intersects it itself (it is not in the BVH) and it casts no shadow.
 *   LIGHT_MESH      an emissive triangle mesh (`emission C`): radiance C from both faces; a
 *                   triangle chosen by area, a uniform point on it, pdf converted to solid angle.
 *   LIGHT_BACKGROUND  `background { color C }`: radiance C from every direction, uniform sphere
 *                   sampling.
 *   LIGHT_ENVMAP    `sky_sphere { image }`: a lat-long float RGB image, sampled by a 2D
 *                   piecewise-constant distribution of luminance * sin(theta).
 * Lat-long convention (in the map's own frame, before `rotate`): row 0 is +y (up), the last row
 * -y; column u in [0,1) is the longitude phi = 2 pi (u - 0.5) measured from +z towards +x, so the
 * image centre lies straight ahead of POV-Ray's default camera and +x (right) is at u = 0.75.
 * Radiance is looked up at the nearest pixel (matching the sampling density exactly).
 * Light selection: in a set of at most LIGHT_SET_LOCAL_MAX lights each light is chosen at the
 * shading point with probability proportional to light_importance there (an estimate of its
 * unshadowed contribution, 0 only where it cannot reach the point's side: lights below the
 * horizon are never picked); in a larger set through a light tree (light_set_pick_at); with
 * more than LIGHT_SET_LOCAL_MAX lights outside the tree, or where no light reaches, with
 * probability proportional to its power estimate (luminance of its flux; infinite and parallel lights count
 * over a disk or sphere of the scene's bounding radius, as PBRT does; a light without the
 * inverse square as what it gives at that radius, a POV-Ray spot as its point light) — see
 * light_power. Lights are read-only once the set is finished, so any number of threads may
 * sample them. */
#ifndef CIRCE_RENDER_LIGHT_H
#define CIRCE_RENDER_LIGHT_H

#include "base/vec.h"
#include "render/camera.h"
#include "render/sampling.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

typedef enum light_kind {
	LIGHT_POINT,
	LIGHT_SPOT,
	LIGHT_PARALLEL,
	LIGHT_CYLINDER,
	LIGHT_SPHERE,
	LIGHT_MESH,
	LIGHT_BACKGROUND,
	LIGHT_ENVMAP
} light_kind;

/* How a point, spot or area light's irradiance falls with the distance d to it. */
typedef enum light_falloff {
	LIGHT_FALLOFF_INVERSE_SQUARE, /* circe's `intensity`: 1 / d^2, physical */
	LIGHT_FALLOFF_NONE,	      /* POV-Ray's light without fade: constant */
	LIGHT_FALLOFF_FADE	      /* POV-Ray's fade: light_fade(d, fade_distance, fade_power) */
} light_falloff;

/* The shape a point or spot light's position is spread over (POV-Ray's area_light). */
typedef enum light_area { LIGHT_AREA_NONE, LIGHT_AREA_PARALLELOGRAM, LIGHT_AREA_ELLIPSE } light_area;

typedef struct light {
	light_kind kind;
	vec3 color;		 /* intensity (point, spot), irradiance (parallel), radiance (the others) */
	vec3 pos;		 /* point, spot, sphere centre */
	vec3 dir;		 /* spot axis, or the direction parallel light travels (unit) */
	float radius;		 /* sphere */
	float cos_hot, cos_fall; /* spot: cosines of radius and falloff */
	float tightness;	 /* spot, cylinder: POV-Ray's exponent; 0 = none */
	float cyl_radius, cyl_falloff; /* cylinder: full and zero beam radii, scene units */
	light_falloff falloff;	 /* point, spot (the inverse square by default), parallel, cylinder */
	float fade_distance, fade_power; /* LIGHT_FALLOFF_FADE */
	bool shadowless;	 /* POV-Ray's `shadowless`: its samples skip the shadow ray */
	bool no_media;		 /* POV-Ray's `media_interaction off`: lights no medium (its scattering) */
	/* An infinite light that lights nothing: POV-Ray's background or sky_sphere without radiosity,
	 * seen only by camera rays and their mirror reflections and refractions (integrator.c). Its
	 * selection weight is 0: next-event estimation never takes it. */
	bool seen_only;
	light_area area_shape;	 /* point, spot */
	bool area_orient;	 /* the area turned to face each receiver, both axes |axis1| long */
	vec3 axis1, axis2;	 /* the area's full edge vectors (an ellipse's diameters) */
	/* LIGHT_MESH: world-space triangles, three vertices each (owned). */
	vec3 *tri;
	size_t tri_count;
	float area;
	render_distrib1d tri_select;
	/* LIGHT_ENVMAP: the caller's image, kept alive by the caller until the light is freed. */
	const float *image; /* width * height RGB triples, row 0 = top (+y) */
	int width, height;
	render_distrib2d env_dist;
	float rot[3][3]; /* world = rot * map frame (an orthonormal matrix) */
	/* Set by light_set_finish for light_importance: the luminance the estimate scales (the
	 * colour's; a sphere's times pi R^2, a mesh's times its area, an environment's times its
	 * mean over the sphere) and the sphere about the light that bounds where it emits from
	 * (centre, radius; 0 for a point). */
	float imp_lum;
	vec3 imp_c;
	float imp_r;
	float *imp_env; /* LIGHT_ENVMAP: its irradiance at LIGHT_IMP_NU x LIGHT_IMP_NV normals (owned) */
} light;

/* The grid of normals (lat-long, in the map's frame) at which an environment's irradiance is
 * tabulated for light_importance. */
#define LIGHT_IMP_NU 16
#define LIGHT_IMP_NV 8

/* One light sample seen from point p: unit direction wi towards the light, the distance to the
 * emitting point (INFINITY for lights at infinity), the incident radiance (for delta lights the
 * irradiance-producing value, already divided by d^2), and the solid-angle pdf (1 for delta). */
typedef struct light_sample {
	vec3 wi;
	float dist;
	vec3 li;
	float pdf;
	bool delta;
	bool shadowless; /* no shadow ray: the light's `shadowless` */
} light_sample;

light light_point(vec3 pos, vec3 intensity);
light light_spot(vec3 pos, vec3 point_at, vec3 intensity, float radius_deg, float falloff_deg);
light light_parallel(vec3 from, vec3 point_at, vec3 irradiance);
/* POV-Ray's cylinder light: beam radii in scene units, falloff >= radius > = 0. */
light light_cylinder(vec3 from, vec3 point_at, vec3 irradiance, float radius, float falloff, float tightness);
/* Spreads a point or spot light over the parallelogram pos + s axis1 + t axis2, s, t in
 * [-1/2, 1/2] (or the ellipse inscribed in it), turned to face each receiver when orient. */
void light_set_area(light *l, vec3 axis1, vec3 axis2, bool ellipse, bool orient);
/* POV-Ray 3.7's fade (Attenuate_Light): 2 / (1 + (d / fade_distance)^fade_power), or 1 when
 * fade_power <= 0 or fade_distance <= 0 (POV-Ray fades only when both are given). */
float light_fade(float d, float fade_distance, float fade_power);
/* Sphere light with POV-Ray's light colour C: radiance C / (pi radius^2). */
light light_sphere(vec3 center, float radius, vec3 color);
light light_background(vec3 radiance);
/* Emissive mesh from tri_count world-space triangles given as 3 * tri_count vertices (copied).
 * False when memory runs out or the total area is zero. */
bool light_mesh_init(light *l, const vec3 *verts, size_t tri_count, vec3 radiance);
/* Lat-long environment: rgb holds width * height RGB floats (not copied), scaled by `scale`,
 * rotated by rot (world = rot * map; xform's linear part, e.g. xform_rotate). False when memory
 * runs out or the size is zero. */
bool light_envmap_init(light *l, const float *rgb, int width, int height, float scale, const xform *rot);
void light_free(light *l);

/* True for point, spot (area ones too), parallel and cylinder lights: no surface to hit, no MIS. */
static inline bool light_is_delta(const light *l)
{
	return l->kind == LIGHT_POINT || l->kind == LIGHT_SPOT || l->kind == LIGHT_PARALLEL ||
	       l->kind == LIGHT_CYLINDER;
}
static inline bool light_is_infinite(const light *l)
{
	return l->kind == LIGHT_BACKGROUND || l->kind == LIGHT_ENVMAP;
}

/* Samples the light from p, a point of a surface whose unit normal n faces the side that receives
 * light (or the zero vector for none). False when it contributes nothing there (p inside a sphere
 * light, outside a spot cone, a grazing mesh point). n is used by the background only: with a
 * normal its directions are cosine-weighted about it, and none lies below it; without, uniform over
 * the sphere. */
bool light_sample_from(const light *l, vec3 p, vec3 n, vec2 u, light_sample *out);
/* Solid-angle density that light_sample_from(p, n_p) picks direction wi hitting the light at
 * distance dist where its geometric normal is n (dist and n are used by meshes only, n_p by the
 * background). 0 for delta lights. */
float light_pdf(const light *l, vec3 p, vec3 n_p, vec3 wi, float dist, vec3 n);
/* Radiance arriving along a ray with direction d that escapes to an infinite light. */
vec3 light_radiance_dir(const light *l, vec3 d);
/* Ray-sphere test for a sphere light: the nearest t in (tmin, tmax), or false. */
bool light_sphere_hit(const light *l, const render_ray *ray, float tmin, float tmax, float *t);
/* Luminance of the light's flux (the selection weight); scene_radius bounds the scene, in its own
 * units with no floor: every weight then scales alike (as s^2 when the scene and its lights are
 * scaled by s), so the choice among lights does not depend on the scene's scale. */
float light_power(const light *l, float scene_radius);
/* An estimate of the light's unshadowed contribution at p, integral L_i max(0, n . w) dw over
 * directions w (n the zero vector: integral L_i dw, a medium's point), in luminance: the light's
 * distance law times the largest cosine over the sphere that bounds it (imp_c, imp_r), so it is 0
 * only where no point of the light lies above p's horizon. The environment and background count
 * as their irradiance at the normal nearest n of a grid (an environment's tabulated, a uniform
 * background's pi L, scaled by LIGHT_IMP_BACKGROUND) or 4 pi times their mean radiance without a
 * normal. With cosine false (a glossy lobe's choice) the cosine bound only tests the horizon:
 * 1 above it, 0 below. Needs light_set_finish's imp_* fields. */
float light_importance(const light *l, vec3 p, vec3 n, bool cosine);
/* Map-frame direction to lat-long (u, v) in [0,1)^2 and back (exposed for tests). */
vec2 light_env_uv(vec3 local_dir);
vec3 light_env_dir(vec2 uv);

/* A node of the light tree (sets of more than LIGHT_SET_LOCAL_MAX lights): the sphere that bounds
 * its lights' bounding spheres and the sum of their imp_lum; a leaf (light >= 0) holds one light,
 * an inner node its two children. */
typedef struct light_node {
	vec3 c;
	float r, lum;
	int32_t light, child[2];
} light_node;

/* All the scene's lights with the selection distribution. */
typedef struct light_set {
	light *lights;
	size_t count, cap;
	render_distrib1d select;
	size_t *infinite; /* indices of the background and environment lights */
	size_t infinite_count;
	/* The light tree (only when count > LIGHT_SET_LOCAL_MAX): the lights with the inverse square
	 * (point, spot, sphere, mesh) in nodes[0] and below; the others (parallel, cylinder, no
	 * falloff or POV-Ray's fade, background, environment) weighed one by one beside it. */
	light_node *nodes;
	size_t node_count;
	size_t *loose; /* the lights outside the tree */
	size_t loose_count;
	uint64_t *trail; /* per light in the tree: its path from the root, bit k = the child taken at
			  * depth k, and the depth in the top 6 bits */
} light_set;

void light_set_init(light_set *s);
/* Appends a copy of l (the set takes over what l owns); NULL when memory runs out. */
light *light_set_add(light_set *s, const light *l);
/* Builds the selection distribution; call once after the last add. False on memory exhaustion. */
bool light_set_finish(light_set *s, float scene_radius);
void light_set_free(light_set *s);
/* Picks a light with probability proportional to its power: its index and that probability. */
size_t light_set_pick(const light_set *s, float u, float *prob);
float light_set_prob(const light_set *s, size_t i);

/* A uniform background's importance is this share of its irradiance pi L: its light sample has
 * the density of a diffuse surface's own (cosine) sample, which MIS weighs against it, so it
 * adds little; the other lights gain its share (bench/README.md, "Several lights"). */
#define LIGHT_IMP_BACKGROUND 0.05f
/* Sets of at most this many lights choose by light_importance at the shading point. */
#define LIGHT_SET_LOCAL_MAX 16
/* Picks a light for the shading point p (normal n facing the receiving side, or zero): with
 * probability proportional to light_importance(p, n) in a set of at most LIGHT_SET_LOCAL_MAX
 * lights; in a larger set through the light tree (each loose light and the tree's root weighed by
 * their importance, then at each node one child by its importance, the node's lights' summed
 * imp_lum over the squared distance to its bounding sphere times the cosine bound over it, as
 * pbrt-v4's BVHLightSampler without its emission cones; Conty Estevez & Kulla 2018, "Importance
 * Sampling of Many Lights with Adaptive Tree Splitting"); by power where no weight is positive.
 * cosine: light_importance's. Its index, *prob that probability (0 when no light can be picked:
 * the tree's descent can end at a node whose children both weigh 0), and *u_rest what is left of u within the light's share, rescaled to
 * [0, 1): uniform given the light, for the light's own sample (so a stratified u stays
 * stratified among the samples of each light). */
size_t light_set_pick_at(const light_set *s, vec3 p, vec3 n, bool cosine, float u, float *prob, float *u_rest);
/* The probability that light_set_pick_at(p, n, cosine) picks light i (bit for bit the same). */
float light_set_prob_at(const light_set *s, size_t i, vec3 p, vec3 n, bool cosine);

#endif
