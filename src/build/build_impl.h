/* build_impl.h - what the build's files share, for src/build/ only: the stages world_build
 * (build.c) calls in order, and the helpers more than one of them uses. */
#ifndef CIRCE_BUILD_BUILD_IMPL_H
#define CIRCE_BUILD_BUILD_IMPL_H

#include "build/build.h"
#include "geom/prim.h"
#include "geom/subdiv.h"
#include "render/world.h"
#include "scene/pigment.h"

/* The grey of an object without a material: mid-grey diffuse. */
#define WORLD_DEFAULT_GREY 0.5f

static inline vec3 d3v(dvec3 v) { return d3_to_v3(v); }

/* build_camera.c */
subd_camera scene_view(const scene *sc, const world_options *opt);
double view_focal_px(const subd_camera *v);
bool build_camera(world *w, const scene *sc, const world_options *opt, diag *d);

/* build_geom.c */
bool build_geom(world *w, const scene *sc, const scene_geom *g, const world_options *opt, diag *d);

/* build_shape.c */
bool build_pov_shape(world *w, const scene *sc, const scene_geom *g, const world_options *opt, diag *d);
/* Appends one tessellated shape's record to w->stats.shapes (for `circe check`). */
bool note_shape(world *w, const world_shape_stat *st, diag *d);

/* build_inst.c */
/* The sphere level (world.h) for a silhouette radius_px pixels on screen. */
uint32_t sphere_level(const double rel_err[PRIM_SPHERE_LEVELS], double radius_px);
/* Pixels per scene unit on screen at an object whose world-space bounding sphere is (centre, r),
 * off the view's axis as a sphere's level counts it; INFINITY with the camera inside. */
double view_px_per_unit(const subd_camera *view, dvec3 centre, double r);
double axis_scale(const xform *t);
bool build_instances(world *w, const scene *sc, const world_options *opt, diag *d);
bool build_planes(world *w, const scene *sc, const world_options *opt, diag *d);
bool build_top(world *w, diag *d);
/* build_csg.c: the CSG solids' trees and their instances' classification facts, after the groups. */
bool build_csg(world *w, const scene *sc, diag *d);

/* build_shapes.c: POV-Ray's shapes each object uses, tessellated once per geometry record at the
 * accuracy its most demanding object asks for on screen. */
bool build_shapes(world *w, const scene *sc, const subd_camera *view, diag *d);

/* build_material.c */
const image *world_image(world *w, diag_loc loc, const char *path, image_encoding enc, diag *d);
size_t clamp_texels(const image *img, scene_color_use use, float *rgb);
/* Warns once at loc when an albedo image holds texels outside [0, 1] (the lookups clamp them). */
void warn_reflectance_image(const image *img, diag_loc loc, const char *path, diag *d);
/* build_pattern.c: pg compiled into w->patterns; *node receives its root. False after reporting. */
bool build_pattern(world *w, const scene_pigment *pg, uint32_t *node, diag *d);
/* The size of the lat-long image a patterned sky_sphere is baked into: 0.35 degrees a texel. */
#define WORLD_SKY_WIDTH 1024
#define WORLD_SKY_HEIGHT 512
/* build_pattern.c: sky's pigment layers baked into w->env_rgb (WORLD_SKY_WIDTH x HEIGHT, RGB). */
bool build_sky_pigments(world *w, const scene_sky_sphere *sky, diag *d);
bool build_material(world *w, size_t k, const scene *sc, const world_options *opt, const scene_material *sm,
		    diag *d);

/* build_sss.c */
bool is_sss(const scene_material *m);
sss_method sss_method_of(const scene_material *m, const world_options *opt);
bool build_sss(world *w, size_t k, const scene *sc, const world_options *opt, const scene_material *sm, diag *d);
bool check_volumes(world *w, const scene *sc, const world_options *opt, diag *d);
void build_groups(world *w, const scene *sc);
/* POV-Ray's subsurface probe factor on open objects, once the world can be traced. */
bool build_pov_probe(world *w, const scene *sc, diag *d);

/* build_light.c */
bool build_lights(world *w, const scene *sc, diag *d);
/* build_material.c: POV-Ray's atmospheric media (world.atmosphere). */
bool build_atmosphere(world *w, const scene *sc, diag *d);
/* build_trace.c: the scene of objs[0..n) alone, their records copied; NULL out of memory. */
scene *build_object_scene(const scene *parent, const scene_object *objs, size_t n);
/* build_light.c: POV-Ray's light_group and projected_through (world.reach). */
bool build_reach(world *w, const scene *sc, const world_options *opt, diag *d);

#endif
