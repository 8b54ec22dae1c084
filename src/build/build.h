/* build.h - the build stage: the scene IR (scene/scene.h) made a world ready to render, its
 * geometry tessellated into meshes with their BVHs, its objects placed as instances, its
 * materials as BSDF parameters with their textures, its lights and its camera (README.md). */
#ifndef CIRCE_BUILD_BUILD_H
#define CIRCE_BUILD_BUILD_H

#include "base/diag.h"
#include "render/camera.h"
#include "render/integrator.h"
#include "scene/pigment.h"
#include "scene/scene.h"

#include <stdbool.h>
#include <stddef.h>

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

struct world_tracer;

typedef struct world_options {
	int width, height;    /* the image, for the camera and adaptive tessellation */
	size_t max_memory;    /* tessellation and per-texture limit in bytes (0: 1 GiB) */
	bool geometry_only;   /* `circe check`: tessellate and count, no textures, lights or BVHs */
	sss_method sss_method; /* --sss: overrides every material's; SSS_METHOD_DEFAULT: their own */
	/* trace()'s worlds (NULL: none): a POV-Ray shape (an isosurface, a lathe, ...) that one of
	 * them tessellated at the accuracy this build asks of it is copied from there, not made again
	 * (world_tracer_mesh): the surface rendered is the one traced, bit for bit. */
	const struct world_tracer *reuse;
	/* isosurface grids made by other builds, looked up and kept (geom/shape.h shape_cache; NULL:
	 * the build keeps its own while it runs, WORLD_SHAPE_CACHE_BYTES at most): the same
	 * isosurface at the same grid step is made once, bit for bit the same mesh. */
	struct shape_cache *shape_cache;
	/* threads isosurfaces are tessellated on (geom/shape.h shape_accuracy.threads) and the
	 * meshes' BVHs built on (0: every core, base/par.h's par_default_workers): the same meshes
	 * and BVHs for any count */
	int threads;
} world_options;

/* The most bytes of isosurface grids a build keeps for its own isosurfaces (world_options). */
#define WORLD_SHAPE_CACHE_BYTES ((size_t)256 << 20)

/* One tessellated shape of POV-Ray's (cylinder, torus, lathe, blob, ...) for `circe check`: its
 * keyword, place, triangles, the distance from its surface the mesh keeps to (0: exact, a polygon
 * or height field), in its own units, and the sphere level its size on screen asked for (-1 where
 * the accuracy was chosen otherwise). */
typedef struct world_shape_stat {
	const char *name;
	diag_loc loc;
	size_t triangles;
	double max_error;
	int level;
} world_shape_stat;

typedef struct world_stats {
	size_t triangles;       /* of the unique meshes */
	size_t instanced_triangles; /* counting each instance */
	size_t geometry_bytes;  /* meshes and BVHs */
	size_t subdiv_surfaces;
	size_t cage_file_faces; /* faces of the cages read from files (the IR counts inline ones) */
	size_t flattened;       /* SSS instances under a non-uniform transform, copied into world space */
	size_t instances;       /* one per scene object */
	size_t instance_bytes;  /* the world's records of them (not the top-level BVHs) */
	const world_shape_stat *shapes; /* in the scene's order of geometry; owned by the world */
	size_t n_shapes;
	size_t csg_nodes;       /* nodes of the CSG solids (build_csg.c), unions made for operands too */
	size_t csg_solids;      /* CSG solids (their roots) */
	size_t csg_clips;       /* clipped_by objects (never traced) */
	size_t reused_shapes;   /* shapes copied from trace()'s worlds (world_options.reuse) */
	size_t cached_shapes;   /* isosurfaces with a grid taken from the shape cache (world_options.shape_cache) */
} world_stats;


/* A scene made ready to render, read-only once built: any number of render threads share it.
 * Opaque but to the build and render/world.c (render/world.h lays it out). */
typedef struct world world;

/* Builds the world of sc; errors (a file that cannot be read, tessellation over the memory limit,
 * a degenerate camera) are reported to d at the scene's location, and give NULL. */
world *world_build(const scene *sc, const world_options *opt, diag *d);
/* Frees w and all it holds; NULL is nothing. */
void world_free(world *w);

/* The integrator's view of w (integrator.h) and its camera, valid while w lives. */
const render_scene *world_scene(const world *w);
const cam *world_camera(const world *w);
/* The build's counts. */
void world_stats_get(const world *w, world_stats *out);
/* The SSS method of w's materials, as the output's header records it: "circle", "fullcircle",
 * "disk" or "volume" (--sss, else the materials' one), "mixed" when they differ, "none" without
 * SSS materials. */
const char *world_sss_method(const world *w);

/* POV-Ray's trace(object, start, direction [, normal]) at parse time (build_trace.c): an object's
 * records (the objects of one object value, CSG paths and all) made a world of their own under the
 * parent scene's camera, so tessellated as the render will tessellate them, and kept for later
 * traces of the same key (WORLD_TRACER_SLOTS objects at once, the oldest built again when
 * needed). */
enum { WORLD_TRACER_SLOTS = 4 };
typedef struct world_tracer world_tracer;
/* The tessellation a trace sees is that of an image of this size (circe's default), whatever the
 * render's: the values a scene computes with trace do not change with the image's size. */
enum { WORLD_TRACE_WIDTH = 640, WORLD_TRACE_HEIGHT = 480 };
/* max_memory: the tessellation limit, as world_options' (0: its default). NULL when memory runs out. */
world_tracer *world_tracer_new(size_t max_memory);
/* The threads t's worlds tessellate isosurfaces on (world_options.threads; 0, the default: every core). */
void world_tracer_set_threads(world_tracer *t, int threads);
void world_tracer_free(world_tracer *t);
/* The nearest hit past the start of the ray from org along dir on objs[0..n) (parent: the scene
 * they belong to, as parsed so far; key: a name for the object that stays its own while t lives,
 * NULL for none): 1 with *hit and the unit normal *normal there (outward of the solid), 0 for none
 * (both zero vectors, as POV-Ray's), -1 after reporting at loc (a zero direction, an object that
 * cannot be built). */
int world_trace(world_tracer *t, const scene *parent, const scene_object *objs, size_t n, const void *key, dvec3 org,
		dvec3 dir, dvec3 *hit, dvec3 *normal, diag *d, diag_loc loc);
/* POV-Ray's object pattern and inside(object, point): the inside of objs[0..n) (their union; CSG
 * by its trees, a mesh by the parity of its crossings) as a function of a world-space point, 1
 * inside and 0 outside, valid while t lives (the scene's patterns call it during the render:
 * free t after the render), thread-safe. False after reporting at loc. */
bool world_inside_fn(world_tracer *t, const scene *parent, const scene_object *objs, size_t n, const void *key,
		     scene_fn *out, diag *d, diag_loc loc);
/* The cache of isosurface grids t's worlds keep (WORLD_SHAPE_CACHE_BYTES at most), for the
 * render's world_options.shape_cache; valid while t lives; NULL for a NULL t. */
struct shape_cache *world_tracer_shapes(const world_tracer *t);
/* How many worlds t has built (each object once while it stays kept). */
size_t world_tracer_builds(const world_tracer *t);
/* The mesh of POV-Ray shape `shape` (a geom/shape.h shape_desc) tessellated at accuracy tol and
 * segments (geom/shape.h shape_accuracy) in one of t's kept worlds, copied into *out with the
 * error bound it met in *err; false when no kept world made that one (or memory runs out: the
 * caller then tessellates it itself). */
bool world_tracer_mesh(const world_tracer *t, const void *shape, double tol, uint32_t segments, mesh *out,
		       double *err);

#endif
