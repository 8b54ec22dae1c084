/* world.h - a scene made ready to render: the IR's geometry tessellated into meshes (one per
 * geometry record, shared by every object that instances it), a BVH per mesh, the objects as
 * instances with their transforms, the materials as BSDF parameters with their textures, the
 * lights, and the camera. It backs the integrator's render_scene (integrator.h): its callbacks
 * trace the instances and apply textures and normal maps at a hit. Read-only once built, so any
 * number of render threads share one world. */
#ifndef CIRCE_RENDER_WORLD_H
#define CIRCE_RENDER_WORLD_H

#include "accel/bvh.h"
#include "accel/tlas.h"
#include "base/diag.h"
#include "build/build.h"
#include "geom/mesh.h"
#include "io/image.h"
#include "render/camera.h"
#include "render/integrator.h"
#include "render/light.h"
#include "scene/scene.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* One geometry record made triangles: its mesh and BVH (object space). */
typedef struct world_geom {
	mesh m;
	bvh *b;
	vec3 lo, hi; /* object-space bounds */
} world_geom;

/* One placed object. */
typedef struct world_inst {
	const world_geom *g;
	xform xf;
	bool identity;  /* xf is the identity: no ray transform needed */
	float xf_gain, xf_shift; /* |xf(v)|max <= gain |v|max + shift (row sums of |M|, |t|max): a
				  * triangle's world scale from its object one without transforming it */
	bool no_shadow;
	int material;   /* index into world.materials */
	int light;      /* index of its mesh light in world.lights, or -1 */
	vec3 lo, hi;    /* world-space bounds */
} world_inst;

/* What a material adds to its BSDF parameters at a hit. */
typedef struct world_material {
	const image *albedo; /* NULL: the constant colour of the BSDF */
	const image *normal_map;
	float normal_strength;
} world_material;


struct world {
	world_geom *geoms;      /* indexed by scene_geom.id; then one private mesh per object (a flattened
				 * instance, a plane); then the unit spheres of each level (prim.h) */
	size_t n_geoms;
	size_t unit_spheres;    /* geoms index of the unit sphere of level 0 */
	world_inst *insts;
	size_t n_insts;
	tlas *top;              /* every instance with triangles */
	uint32_t *top_inst;     /* top's instance index -> insts index */
	tlas *shadow;           /* the instances that cast shadows (not no_shadow) */
	bsdf_params *bsdfs;     /* indexed like materials; the last is the default grey */
	world_material *materials;
	size_t n_materials;
	image **images;         /* every texture loaded, once per path (stable addresses) */
	char **image_paths;
	size_t n_images;
	float *env_rgb;         /* the sky_sphere's pixels, RGB, kept for its light */
	light_set lights;
	cam camera;
	vec3 lo, hi;            /* world bounds of the objects */
	float radius;           /* of the bounding sphere, for the lights */
	bool has_sss;           /* some material scatters below its surface */
	render_sss *sss;        /* indexed like materials; meaningful where sss_of is not NULL */
	const render_sss **sss_of; /* the integrator's table: NULL for materials without SSS */
	uint32_t *inst_top;     /* insts index -> top's instance index (UINT32_MAX: not in top) */
	int *sss_group;         /* insts index -> its SSS volume: -1 alone, else the first member's index;
				 * the one record of membership (the top level's sets are sss_set's) */
	world_stats stats;
	render_scene rs;        /* the integrator's view of this world */
};

/* render/world.c: the top level's set of instance i (its SSS volume), which the build gives it. */
uint32_t sss_set(const world *w, size_t i);
/* render/world.c: w->rs, the integrator's view of the built w through world.c's callbacks. */
void world_bind(world *w);

#endif
