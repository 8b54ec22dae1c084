/* scene.h - the scene IR: plain C structs that the language fills and the geometry and renderer
 * read. No text syntax lives here. Every item keeps the diag_loc of the text that made it, so later
 * stages (tessellation, BVH build) can report errors at the right place. A scene owns all of its
 * memory (an arena plus a few large heap arrays); scene_free releases everything. */
#ifndef CIRCE_SCENE_SCENE_H
#define CIRCE_SCENE_SCENE_H

#include "base/diag.h"
#include "base/mem.h"
#include "base/vec.h"
#include "scene/material.h"

#include <stdbool.h>
#include <stdint.h>

/* The camera's projections, in render/camera.h's cam_type order (build_camera casts). */
typedef enum scene_cam_type {
	SCENE_CAM_PERSPECTIVE, SCENE_CAM_ORTHOGRAPHIC, SCENE_CAM_FISHEYE, SCENE_CAM_ULTRA_WIDE_ANGLE,
	SCENE_CAM_PANORAMIC, SCENE_CAM_CYLINDER_1, SCENE_CAM_CYLINDER_2, SCENE_CAM_CYLINDER_3,
	SCENE_CAM_CYLINDER_4, SCENE_CAM_SPHERICAL, SCENE_CAM_OMNIMAX, SCENE_CAM_MESH,
} scene_cam_type;

/* One face of a mesh_camera's mesh in world space (render/camera.h's cam_mesh_face, the same
 * layout): its centroid, the mesh transform's linear part of its unit normal, the transformed
 * unit normal. */
typedef struct scene_cam_face {
	vec3 centroid, offset, dir;
} scene_cam_face;
/* The face of triangle p1 p2 p3 under the mesh's object-to-world t, as POV-Ray's mesh camera
 * takes it: the centroid, the unit normal cross(p3 - p1, p2 - p1) (Mesh::Compute_Mesh_Triangle).
 * False for a degenerate triangle (POV-Ray drops it: not a face). */
bool scene_cam_face_make(dvec3 p1, dvec3 p2, dvec3 p3, const xform *t, scene_cam_face *out);
/* One face of a distribution 3 mesh_camera's mesh (render/camera.h's cam_uv_face, the same
 * layout): its corners in world space, at each corner the mesh transform's linear part of the
 * corner's unit normal (the offset along it) and the transformed normal (the direction, not
 * renormalised: a ray interpolates the three), and the corners' uv. */
typedef struct scene_cam_uv_face {
	vec3 p[3], offset[3], dir[3];
	vec2 uv[3];
} scene_cam_uv_face;
/* The face of triangle p[0..2] with uv[0..2] under t, as POV-Ray's distribution 3 takes it: with
 * n NULL (flat) each corner's normal is the face's, cross(p3 - p1, p2 - p1) normalised; else the
 * corners' own n[0..2] (unit; POV-Ray's smooth, for a triangle whose normals differ). False for a
 * degenerate triangle (not a face) and for one of no area in uv (no pixel maps onto it: POV-Ray's
 * barycentrics would be 0 / 0 there). */
bool scene_cam_uv_face_make(const dvec3 p[3], const dvec3 *n, const vec2 uv[3], const xform *t,
			    scene_cam_uv_face *out);
/* The uv index of n faces: a grid of *grid x *grid cells over [0,1]^2, cell (i, j) (i along u, j
 * along v) listing from list[start[j * grid + i]] to list[start[j * grid + i + 1]] the faces
 * whose uv bounds meet it, in face order (the first face holding a point is the first of its
 * cell's that does). In arena a; false when out of memory. */
bool scene_cam_uv_index(arena *a, const scene_cam_uv_face *f, uint32_t n, uint32_t *grid,
			const uint32_t **start, const uint32_t **list);
/* The cell (0 to grid - 1) of coordinate x in [0, 1] on that grid (x below 0 in cell 0, 1 and above
 * in the last), the index's and the lookup's one rule. */
static inline uint32_t scene_cam_uv_cell(double x, uint32_t grid)
{
	double c = x * (double)grid;
	return !(c >= 0.0) ? 0u : c >= (double)(grid - 1) ? grid - 1 : (uint32_t)c;
}

typedef struct scene_camera {
	diag_loc loc;
	dvec3 location, look_at, sky, right, up;
	double angle_deg; /* horizontal field of view */
	double aperture; /* thin lens when > 0 */
	dvec3 focal_point;
	bool has_focal_point;
	int type; /* render/camera.h's cam_type (0 perspective) */
	dvec3 direction; /* POV-Ray's direction; <0,0,1> by default */
	bool has_look_at, has_angle, has_direction, has_right, has_up;
	double v_angle_deg; /* spherical's vertical angle */
	bool has_xform; /* translate/rotate/scale/matrix on the camera, applied last */
	xform xf;
	/* POV-Ray's camera normal { }: a normal pattern perturbing each camera ray's direction, at
	 * the image point <x0, y0, 0> (x0, y0 in [-0.5, 0.5]); NULL: none */
	const struct scene_pigment *normal;
	diag_loc normal_loc;
	/* SCENE_CAM_MESH, POV-Ray's mesh_camera (distributions 0 to 2): the non-degenerate faces of
	 * its first mesh_count meshes (0: one a ray per pixel; 1 and 2: all), mesh k's from mesh_first[k] to
	 * mesh_first[k + 1], in the scene's arena; location z offsets each ray's origin along its
	 * face normal, a direction z < 0 reverses the rays */
	const scene_cam_face *mesh_faces;
	const uint32_t *mesh_first;
	uint32_t mesh_n, mesh_count;
	int mesh_distribution; /* 0; 1: the meshes' faces summed, ray k of pixel i from face
				  k * width * height + i; 2: mesh k the k-th vertical strip of the
				  image; 3: the first mesh's uv, uv_faces */
	uint32_t mesh_rays;    /* rays per pixel (distribution 1 uses it; 0 and 2 count meshes) */
	/* distribution 3: the first mesh's non-degenerate faces of an area in uv, in order, and
	 * their uv index (scene_cam_uv_index); smooth: POV-Ray's smooth (the normals interpolate) */
	const scene_cam_uv_face *uv_faces;
	uint32_t uv_n, uv_grid;
	const uint32_t *uv_start, *uv_list;
	bool mesh_smooth;
	/* POV-Ray's max_distance (Camera::Max_Ray_Distance): the camera ray's first hit is sought
	 * only this far from its origin, beyond it the ray misses; 0: no limit */
	double mesh_max_distance;
} scene_camera;

typedef enum scene_light_kind {
	SCENE_LIGHT_POINT,
	SCENE_LIGHT_SPHERE,
	SCENE_LIGHT_SPOT,
	SCENE_LIGHT_PARALLEL,
	SCENE_LIGHT_CYLINDER
} scene_light_kind;

/* A light_source. Its distance law (grammar/README.md, "Lights"): with `intensity`, circe's
 * physical 1 / d^2; without, POV-Ray's: none, or POV-Ray's fade when fade_distance and
 * fade_power are both > 0. A sphere light is always physical; parallel and cylinder lights never
 * fall off as 1 / d^2. */
typedef struct scene_light {
	diag_loc loc;
	scene_light_kind kind;
	dvec3 position;
	vec3 color;
	double intensity; /* multiplies color; default 1 */
	bool has_intensity; /* `intensity` given: the inverse square */
	double radius; /* sphere lights: scene units */
	dvec3 point_at; /* spot, parallel and cylinder lights */
	double cone_deg, falloff_deg; /* spot lights: POV-Ray's radius and falloff, degrees */
	double cyl_radius, cyl_falloff; /* cylinder lights: POV-Ray's radius and falloff, scene units */
	double tightness; /* spot and cylinder lights; 0 = none */
	double fade_distance, fade_power; /* POV-Ray's fade; 0 = none */
	bool shadowless;
	bool no_media; /* media_interaction off: the light scatters in no medium */
	/* POV-Ray's area_light: axes (full edges, from -1/2 to +1/2 about the position), the sample
	 * counts (kept for the dump; circe samples the area continuously) and the modifiers. */
	bool area;
	dvec3 axis1, axis2;
	int area_n1, area_n2;
	bool circular, orient, jitter;
	/* POV-Ray's looks_like: the objects that show the light (placed at its position when given,
	 * moved by its later transforms, no_shadow), added to the scene's objects where the light is
	 * placed; in the scene's arena. */
	const struct scene_object *looks;
	uint32_t n_looks;
	/* The light_sources written in the looks_like object (POV-Ray's Post_Process walks the
	 * light's children, so they light the scene): moved with it, placed after it where it is
	 * placed; in the scene's arena. */
	const struct scene_light *looks_lights;
	uint32_t n_looks_lights;
	/* POV-Ray's light_group: the group (1-based index of scene.light_groups) whose objects alone
	 * the light lights; 0: a global light. */
	uint32_t group;
	/* POV-Ray's projected_through: the light reaches a point only through these objects (its
	 * shadow ray must meet them, and only what lies before them shadows); in the scene's arena,
	 * never placed in the scene, moved by the light's later transforms. */
	const struct scene_object *projected;
	uint32_t n_projected;
} scene_light;

/* POV-Ray's light_group: its objects are lit by its lights (scene_light.group) and those of the
 * groups around it (parent, 1-based; 0: none); by the global lights only with global_lights on
 * (the outermost group's word, as POV-Ray's flag set on every child). */
typedef struct scene_light_group {
	diag_loc loc;
	uint32_t parent;
	bool global_lights;
} scene_light_group;

typedef enum scene_shape_kind {
	SHAPE_SPHERE,
	SHAPE_BOX,
	SHAPE_PLANE,
	SHAPE_MESH, /* triangles from mesh{triangle...}, mesh2, or a generated list */
	SHAPE_MESH_FILE, /* mesh { file "x.obj" }: loaded by the importer */
	SHAPE_SUBDIV, /* subdivision_surface */
	SHAPE_POV, /* lathe, sor, prism, sphere_sweep, blob, text, bicubic_patch: geom/shape.h's description */
	/* POV-Ray's shapes tessellated at the build (src/geom/povshape.h; scene_shapes.c names them) */
	SHAPE_CONE, /* cone and cylinder */
	SHAPE_TORUS,
	SHAPE_DISC,
	SHAPE_POLYGON,
	SHAPE_SUPERELLIPSOID,
	SHAPE_HEIGHT_FIELD,
	SHAPE_QUADRIC,
	SHAPE_POLY /* poly, cubic, quartic */
} scene_shape_kind;

/* POV-Ray's cone { <base>, rb, <cap>, rc [open] } and cylinder { <base>, <cap>, r [open] }. */
typedef struct scene_cone {
	dvec3 base, cap;
	double base_radius, cap_radius;
	bool open, cylinder; /* cylinder: written as one, for names and the dump */
} scene_cone;

/* polygon { N, <p>... }: the points as written (2-D ones promoted to z = 0), subpolygons closed
 * by repeating their first point as POV-Ray's Parse_Polygon finds them; owned by the arena. */
typedef struct scene_polygon {
	dvec3 *points;
	uint32_t n;
} scene_polygon;

/* height_field { png|exr "file" [smooth] [water_level w] }. */
typedef struct scene_height_field {
	const char *path; /* resolved like scene_geom's file path; NULL for a function's field */
	diag_loc path_loc;
	/* `function W, H { ... }`: the heights POV-Ray's function image holds (Make_Pattern_Image: the
	 * function at <i / (W - 1), j / (H - 1), 0>, 16-bit grey), row z = 0 first as an image's
	 * bottom row (owned by the scene's arena) */
	const float *heights;
	uint32_t fn_w, fn_h;
	bool smooth;
	double water_level; /* in the field's own height, 0 .. 1 */
} scene_height_field;

/* quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }: A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y +
 * I z + J = 0 (POV-Ray's Quadric). poly { order, <c...> } (cubic: order 3, quartic: 4) keeps its
 * (order+1)(order+2)(order+3)/6 coefficients in POV-Ray's order; owned by the arena. */
typedef struct scene_quadric {
	dvec3 square, mixed, linear;
	double constant;
} scene_quadric;

typedef struct scene_poly {
	int order;
	const char *keyword; /* "poly", "cubic" or "quartic", for messages */
	double *coeffs;
	uint32_t n;
} scene_poly;

/* A triangle mesh. Faces index positions; normal_idx/uv_idx (when non-NULL) index normals/uvs
 * with the same layout (three per face). Arrays are heap-owned by the scene. */
typedef struct scene_mesh {
	vec3 *positions;
	uint32_t n_positions;
	vec3 *normals;
	uint32_t n_normals;
	vec2 *uvs;
	uint32_t n_uvs;
	uint32_t *faces; /* 3 * n_faces */
	uint32_t *normal_idx; /* 3 * n_faces or NULL */
	uint32_t *uv_idx; /* 3 * n_faces or NULL */
	uint32_t n_faces;
} scene_mesh;

typedef enum scene_subd_scheme { SCENE_SUBD_CATMULL_CLARK, SCENE_SUBD_LOOP } scene_subd_scheme;
typedef enum scene_subd_boundary { SCENE_SUBD_EDGE_ONLY, SCENE_SUBD_EDGE_AND_CORNER } scene_subd_boundary;

typedef struct scene_crease {
	uint32_t a, b;
	float sharpness;
	diag_loc loc;
} scene_crease;

typedef struct scene_corner {
	uint32_t vertex;
	float sharpness;
	diag_loc loc;
} scene_corner;

/* A subdivision cage: either a file or inline vertices and faces of any size >= 3. */
typedef struct scene_subdiv {
	const char *file; /* NULL for an inline cage; resolved like scene_geom's file path */
	diag_loc file_loc; /* where 'file' was written: a cage file's errors are reported there */
	vec3 *vertices;
	uint32_t n_vertices;
	uint32_t *face_sizes; /* n_faces entries */
	uint32_t *face_verts; /* sum of face_sizes entries */
	diag_loc *face_locs; /* where each face was written, for errors */
	uint32_t n_faces, n_face_verts;
	vec2 *uvs;
	uint32_t n_uvs;
	uint32_t *uv_face_sizes, *uv_face_verts; /* same face count as the cage when given */
	uint32_t n_uv_faces, n_uv_face_verts;
	scene_crease *creases;
	uint32_t n_creases;
	scene_corner *corners;
	uint32_t n_corners;
	scene_subd_scheme scheme;
	scene_subd_boundary boundary;
	bool boundary_given; /* written in the scene: it overrides a cage file's boundary tag */
	int level; /* uniform level when > 0 */
	double max_edge_px; /* adaptive: longest tessellated edge on screen, pixels (when level == 0) */
} scene_subdiv;

/* Geometry, shared between every object that instances it (object { Name } points here). */
typedef struct scene_geom {
	diag_loc loc;
	scene_shape_kind kind;
	uint32_t id; /* 0, 1, ... in creation order */
	union {
		struct {
			dvec3 center;
			double radius;
		} sphere;
		struct {
			dvec3 corner1, corner2;
		} box;
		struct {
			dvec3 normal;
			double offset;
		} plane;
		scene_mesh mesh;
		struct {
			const char *path; /* resolved against the folder of the file that names it */
		} file;
		scene_subdiv subdiv;
		const struct shape_desc *pov; /* SHAPE_POV: in the scene's arena */
		scene_cone cone;
		struct {
			double major, minor;
		} torus;
		struct {
			dvec3 center, normal;
			double radius, hole; /* hole 0: none */
		} disc;
		scene_polygon polygon;
		struct {
			double e, n; /* POV-Ray's <e, n>: east-west and north-south exponents */
		} superellipsoid;
		scene_height_field height_field;
		scene_quadric quadric;
		scene_poly poly;
	} u;
	struct scene_geom *next; /* the scene's list of all geometry */
} scene_geom;

/* CSG (POV-Ray's intersection, difference, merge; a union only where it must be a node: an
 * operand of several objects, or an inverted union). Every object stays an object of its own (its
 * geometry made triangles as anywhere); the objects of one CSG solid carry their path from the
 * solid's root, and the build classifies their hits by the solid's boolean (build/README.md). */
typedef enum scene_csg_op {
	SCENE_CSG_UNION, /* every operand's surface is kept (POV-Ray's union) */
	SCENE_CSG_INTERSECTION,
	SCENE_CSG_DIFFERENCE, /* the first operand less the others */
	SCENE_CSG_MERGE, /* the union without the surfaces inside another operand */
} scene_csg_op;

/* One step of an object's path: the CSG node it is in (an id unique to each placed copy of the
 * block: object { Name } copies take new ids), which of its operands holds the object, the node's
 * operator and whether the node is inverted (inverse). */
typedef struct scene_csg_step {
	uint32_t id;
	uint32_t operand;
	scene_csg_op op;
	bool inverse;
	diag_loc loc; /* the block's keyword */
} scene_csg_step;

/* One placed object: a geometry, its object-to-world transform and its material. Unions are
 * flattened into their members, each with the composed transform. */
typedef struct scene_object {
	diag_loc loc;
	const scene_geom *geom;
	xform transform;
	const scene_material *material; /* NULL: the default grey diffuse */
	/* With texture_placed: object space to its texture's space, the transforms written before
	 * the texture (which POV-Ray does not apply to it); else the identity (a texture given
	 * before every transform moves with the object). */
	xform texture_from_object;
	bool texture_placed;
	bool no_shadow;
	bool instance; /* made by object { Name } */
	uint8_t pov_flags; /* SCENE_OBJ_*: POV-Ray's object flags circe records but does not render yet */
	/* CSG: the path from the solid's root (csg[0]) to the innermost node holding the object,
	 * csg_depth steps (0: not in a CSG solid); in the scene's arena, never shared between objects. */
	const scene_csg_step *csg;
	uint32_t csg_depth;
	bool inverse; /* the object's own inverse: its inside is the outside of its surface */
	bool clip_only; /* a clipped_by object: its inside clips, its surface is never seen */
	uint32_t light_group; /* the innermost light_group holding it (1-based), 0: none */
	/* A blob's component textures (geom/shape.h's shape_blob_comp.part): part k's material at
	 * part_mat[k - 1] (in the arena); part 0 is the object's material. n_parts 0: none. */
	const struct scene_material *const *part_mat;
	uint32_t n_parts;
	/* mesh2's texture_list: the mesh placed as one object a texture (pieces of them, this one
	 * piece, the others the objects just before and after it in the same order), each piece an
	 * open surface of the one solid: its inside is the parity of all the pieces' crossings.
	 * pieces 0: a whole object. */
	uint32_t piece, pieces;
} scene_object;

/* POV-Ray 3.7's object flags (Parse_Object_Mods): hollow matters only for media; the others hide
 * an object from some rays or light its back, which the renderer does not do yet. */
enum {
	SCENE_OBJ_HOLLOW = 1, /* hollow [on] */
	SCENE_OBJ_HOLLOW_SET = 2, /* hollow was said (on or off): a union's hollow leaves it */
	SCENE_OBJ_NO_IMAGE = 4,
	SCENE_OBJ_NO_REFLECTION = 8,
	SCENE_OBJ_NO_RADIOSITY = 16,
	SCENE_OBJ_DOUBLE_ILLUMINATE = 32,
};

typedef struct scene_global {
	double mm_per_unit; /* default 10 */
	int max_trace_level; /* default 5 */
	double assumed_gamma; /* default 1 */
	bool assumed_gamma_set; /* written: POV-Ray's explicit gamma mode (else its #version decides) */
	double working_gamma; /* POV-Ray's working gamma G (scene/gamma.c): images read as colour are
			       * raised to 1/G, the image written as r^G; 1 for circe's scenes */
	double noise_threshold; /* adaptive sampling's (render --noise-threshold); 0: off, the default */
	vec3 ambient_light; /* default 1: scales every explicit finish ambient (scene/finish.h) */
	/* global_settings { subsurface { samples D, S  radiosity B } }: POV-Ray's switch for its
	 * finishes' subsurface (without it they render without); samples and radiosity are recorded
	 * only: circe is progressive and lights entry points by global illumination. */
	bool subsurface;
	int subsurface_samples[2]; /* POV-Ray's defaults 50, 50 */
	bool subsurface_radiosity;
	/* global_settings { radiosity {...} }: its settings are ignored (circe always computes global
	 * illumination), its presence is POV-Ray's switch: POV-Ray's background and sky_sphere light
	 * the scene only under it, and finishes' ambient gives way to it (doc/language.md "Finishes").
	 * radiosity_legacy: it came under a #version below 3.7, where POV-Ray keeps the ambient. */
	bool radiosity, radiosity_legacy;
} scene_global;

/* Pigment layers of a sky_sphere (POV-Ray's are unlimited; circe's sky is baked from these). */
enum { SCENE_SKY_MAX_PIGMENTS = 8 };

typedef struct scene_sky_sphere {
	diag_loc loc;
	const char *image;
	double intensity;
	bool has_intensity; /* circe's `intensity` was given: the sky lights the scene always */
	dvec3 rotate_deg;
	/* Or POV-Ray pigments, bottom first, evaluated at the unit direction (the build bakes them
	 * into a lat-long image): each layer's filter and transmit show the ones below. */
	const struct scene_pigment *pigments[SCENE_SKY_MAX_PIGMENTS];
	int n_pigments;
} scene_sky_sphere;

/* A file the scene names, as resolved (see scene_geom's file path), and the place of its string:
 * the build opens every one first, so that `check` and `render` report a missing one alike. */
typedef enum scene_asset_kind { SCENE_ASSET_IMAGE, SCENE_ASSET_MESH, SCENE_ASSET_CAGE, SCENE_ASSET_FONT } scene_asset_kind;

typedef struct scene_asset {
	scene_asset_kind kind;
	const char *path; /* owned by the scene's arena */
	diag_loc loc;
} scene_asset;

typedef struct scene {
	arena arena; /* owns strings, materials, small records */
	scene_global global;
	bool has_camera;
	scene_camera camera;
	vecbuf lights; /* scene_light */
	vecbuf light_groups; /* scene_light_group; a light's or an object's group g is element g - 1 */
	bool has_background;
	vec3 background;
	diag_loc background_loc;
	/* The background is circe's environment light (a one-colour sky_sphere with `intensity`), which
	 * lights every surface; POV-Ray's `background` or sky_sphere without it lights diffuse and
	 * glossy surfaces only under global_settings' radiosity (scene_sky_lights). */
	bool background_circe;
	bool has_sky_sphere;
	scene_sky_sphere sky_sphere;
	scene_fog *fogs; /* every fog, newest first (they combine in any order) */
	/* POV-Ray's atmospheric media (a `media` statement outside an interior): a part record whose
	 * media fill the space outside every object (and inside hollow ones); NULL: none. */
	const struct scene_material *atmosphere;
	vecbuf objects; /* scene_object */
	scene_geom *geoms; /* every geometry record, newest first */
	uint32_t n_geoms;
	scene_material *materials; /* every material record, newest first */
	uint32_t n_materials;
	vecbuf assets; /* scene_asset, in the order the text names them */
	vecbuf clamped_colors; /* diag_loc of each colour clamped so far (scene_color_finalise) */
	uint32_t csg_ids; /* the last id given to a CSG node (scene_csg_step) */
	uint64_t source_hash; /* of every file the language read for it, includes too (lang.h) */
} scene;

scene *scene_new(void);
void scene_free(scene *s);

/* New records owned by s; NULL when memory runs out. */
scene_geom *scene_new_geom(scene *s, scene_shape_kind kind, diag_loc loc);
scene_material *scene_new_material(scene *s, diag_loc loc);
/* Appends a named file to s->assets; false when memory runs out. */
bool scene_add_asset(scene *s, scene_asset_kind kind, const char *path, diag_loc loc);

static inline size_t scene_n_objects(const scene *s) { return s->objects.len; }
static inline const scene_object *scene_object_at(const scene *s, size_t i)
{
	return &VECBUF_AT(&s->objects, scene_object, i);
}
static inline size_t scene_n_lights(const scene *s) { return s->lights.len; }
static inline const scene_light *scene_light_at(const scene *s, size_t i)
{
	return &VECBUF_AT(&s->lights, scene_light, i);
}

/* Whether the scene's environment is circe's own (a sky_sphere `image`, or one with `intensity`):
 * then it lights every surface, as under POV-Ray's radiosity. */
static inline bool scene_env_circe(const scene *s)
{
	return (s->has_sky_sphere && (s->sky_sphere.image || s->sky_sphere.has_intensity)) ||
	       (s->has_background && s->background_circe);
}
/* Whether the background and the sky_sphere light surfaces, or are only seen (by camera rays and
 * their mirror reflections and refractions): POV-Ray's sky lights only under radiosity. */
static inline bool scene_background_lights(const scene *s)
{
	return s->background_circe || s->global.radiosity;
}
static inline bool scene_sky_sphere_lights(const scene *s)
{
	return s->sky_sphere.image || s->sky_sphere.has_intensity || s->global.radiosity;
}
/* Whether POV-Ray finishes glow by their ambient: POV-Ray 3.7 adds it only without radiosity (or
 * under radiosity in a scene of #version below 3.7; trace.cpp). The implicit 0.1 (no `ambient`
 * written) stands for the light POV-Ray does not compute: it glows only where neither radiosity
 * nor circe's own environment computes that light. */
static inline bool scene_ambient_glows(const scene *s, bool explicit_ambient)
{
	bool radiosity = s->global.radiosity && !s->global.radiosity_legacy;
	return !radiosity && (explicit_ambient || !scene_env_circe(s));
}

/* A colour written at loc becomes a physical quantity of the given use: clamps it into its range
 * (scene_color_clamp) and, when that changed it, warns at loc naming `what` ("diffuse colour"),
 * the value written and the value kept — once per place in the text, however often the parser
 * passes it (a loop, a macro). False only when memory runs out (reported to d). */
bool scene_color_finalise(scene *s, diag *d, diag_loc loc, const char *what, scene_color_use use, vec3 *c);

/* POV-Ray 3.7's working gamma for a scene (parser/parse.cpp, the end of Parse_Frame): the
 * assumed_gamma written, else for a scene whose #version ends below 3.7 its legacy mode (no
 * gamma handling: the numbers go to the display as they are, a gamma of about 2.2), else 1. */
#define SCENE_LEGACY_GAMMA 2.2
double scene_working_gamma(const scene_global *g, double version);

/* POV-Ray's subsurface switch, once the whole scene is read: each texture whose finish has
 * subsurface { } becomes a pov_sss texture (its interior's ior, or 1 as POV-Ray's atmosphere,
 * warned about; the dipole, POV-Ray's profile) when global_settings has subsurface { }, and
 * renders without it (warned about once) when not, as in POV-Ray 3.7. */
void scene_resolve_pov_sss(scene *s, diag *d);

/* Checks what the parser cannot check alone (index ranges, creases, camera, materials) and
 * reports every problem through d. Returns the number of errors found. */
int scene_validate(const scene *s, diag *d);

/* Counts for `circe check`. */
typedef struct scene_stats {
	size_t objects, instances, geoms, lights;
	size_t materials_by_kind[MAT_KIND_COUNT];
	size_t mesh_triangles; /* explicit triangles only; tessellation comes later */
	size_t subdiv_faces;
	size_t sss_nonuniform; /* SSS objects under a non-uniform transform: flattened at build */
	size_t memory_bytes; /* estimated IR memory */
} scene_stats;
void scene_stats_get(const scene *s, scene_stats *st);

/* The keyword of a shape kind ("sphere", "cylinder", ...; a cone written as a cylinder says so). */
const char *scene_shape_name(const scene_geom *g);
/* The dump of a shape of scene_shapes.c's kinds (SHAPE_CONE and after): its fields, a newline. */
void scene_dump_shape(FILE *o, const scene_geom *g);

/* Writes a stable text dump of the IR (for golden tests and debugging). */
void scene_dump(const scene *s, FILE *out);

#endif
