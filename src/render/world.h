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
#include "geom/mesh.h"
#include "io/image.h"
#include "render/camera.h"
#include "render/integrator.h"
#include "render/light.h"
#include "scene/scene.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Spheres are instances of one unit sphere per tessellation level (prim.h), the level the coarsest
 * whose silhouette stays within WORLD_SPHERE_MAX_ERROR_PX of the true one and whose edges (along
 * the equator) are at most WORLD_SPHERE_MAX_EDGE_PX long on screen, from the sphere's size and
 * distance to the camera. Shading normals are the sphere's own, so the outline shows the facets
 * first; but facets wider than a pixel also show in the shading, where the interpolated normals
 * depart from them (tests/render/furnace.sh sees it), hence the edge bound, as subdivision's
 * max_edge. */
#define WORLD_SPHERE_MAX_ERROR_PX 0.1
#define WORLD_SPHERE_MAX_EDGE_PX 1.0
/* A plane reaches out from the camera until it is seen within this angle of its horizon (a
 * pixel of a 4K image 60 degrees wide is 2.7e-4 rad), whatever else the scene holds. */
#define WORLD_PLANE_HORIZON_RAD 1e-4f

typedef struct world_options {
	int width, height;    /* the image, for the camera and adaptive tessellation */
	size_t max_memory;    /* tessellation and per-texture limit in bytes (0: 1 GiB) */
	bool geometry_only;   /* `circe check`: tessellate and count, no textures, lights or BVHs */
	scene_sss_method sss_method; /* --sss: overrides every material's; SSS_METHOD_DEFAULT: their own */
} world_options;

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

typedef struct world_stats {
	size_t triangles;       /* of the unique meshes */
	size_t instanced_triangles; /* counting each instance */
	size_t geometry_bytes;  /* meshes and BVHs */
	size_t subdiv_surfaces;
	size_t cage_file_faces; /* faces of the cages read from files (the IR counts inline ones) */
	size_t flattened;       /* SSS instances under a non-uniform transform, copied into world space */
} world_stats;

typedef struct world {
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
	int *sss_group;         /* insts index -> its SSS volume: -1 alone, else the first member's index */
	uint32_t *sss_next;     /* insts index -> the next member of its SSS group (UINT32_MAX: none) */
	world_stats stats;
	render_scene rs;        /* the integrator's view of this world */
} world;

/* Builds w from the scene; errors (a file that cannot be read, tessellation over the memory limit,
 * a degenerate camera) are reported to d at the scene's location. On failure w is left empty. */
bool world_build(world *w, const scene *sc, const world_options *opt, diag *d);
void world_free(world *w);

#endif
