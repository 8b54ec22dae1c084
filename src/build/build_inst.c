/* build_inst.c - the scene's objects as instances: transforms, spheres at their level of detail,
 * SSS objects flattened under non-uniform transforms, planes out to their horizon, and the
 * top-level BVHs over them. */
#include "build/build_impl.h"

#include "base/mem.h"
#include "geom/prim.h"

#include <float.h>
#include <math.h>
#include <string.h>

/* World-space bounds of an object-space box under t. */
static void xform_bounds(const xform *t, vec3 lo, vec3 hi, vec3 *wlo, vec3 *whi)
{
	*wlo = v3s(FLT_MAX), *whi = v3s(-FLT_MAX);
	for (int k = 0; k < 8; k++) {
		dvec3 c = d3(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z);
		vec3 p = d3v(xform_point(t, c));
		*wlo = v3_min(*wlo, p), *whi = v3_max(*whi, p);
	}
}

static bool is_identity(const xform *t)
{
	xform id = xform_identity();
	return !memcmp(t->m, id.m, sizeof id.m);
}

/* xf_gain and xf_shift of an instance: the largest row sum of |M| and the largest |t|, so that
 * every coordinate of xf(v) is at most gain max|v| + shift. */
static void set_xf_bound(world_inst *in)
{
	double gain = 0.0, shift = 0.0;
	for (int r = 0; r < 3; r++) {
		gain = fmax(gain, fabs(in->xf.m[r][0]) + fabs(in->xf.m[r][1]) + fabs(in->xf.m[r][2]));
		shift = fmax(shift, fabs(in->xf.m[r][3]));
	}
	in->xf_gain = (float)gain, in->xf_shift = (float)shift;
}

/* Whether an object of material m shows a normal map, which needs its mesh's tangents (the shade
 * callback of render/world.c reads them); check loads no textures, so needs none. */
static bool wants_tangents(const scene_material *m, const world_options *opt)
{
	return !opt->geometry_only && is_sss(m) && m->sss.normal_map;
}

/* Makes g's tangents, for a normal-mapped object: unless the mesh has its own (a file's) or lacks
 * the normals and UVs they are made from. */
static bool make_tangents(world_geom *g, diag *d)
{
	if (g->m.tangents || !g->m.normals || !g->m.uvs)
		return true;
	if (!mesh_generate_tangents(&g->m)) {
		diag_error(d, diag_noloc(), "out of memory while generating tangents");
		return false;
	}
	g->tangents_made = true;
	return true;
}

/* An SSS object under a non-uniform transform gets its own copy of the triangles in world space
 * (DESIGN.md): circles stay circles only under similarities, and circle tracing runs in an
 * instance's own space. Its geometry record is the one at index `slot` (past the scene's). */
static bool flatten_instance(world *w, world_inst *in, size_t slot, bool tangents, diag *d, diag_loc loc)
{
	world_geom *copy = &w->geoms[slot];
	if (!mesh_copy(&copy->m, &in->g->m)) {
		diag_error(d, loc, "out of memory while flattening an SSS object into world space");
		return false;
	}
	mesh_transform(&copy->m, &in->xf);
	if (in->g->tangents_made) { /* made for the shared mesh's users: the copy makes its own */
		mem_free(copy->m.tangents);
		copy->m.tangents = NULL;
	}
	in->g = copy;
	in->xf = xform_identity();
	in->identity = true;
	w->stats.flattened++;
	return !tangents || make_tangents(copy, d);
}

/* The largest length an axis of the object takes under t: a sphere's radius in the world (exact
 * under a similarity; under a non-uniform scale, that of the longest axis). */
double axis_scale(const xform *t)
{
	double s = 0.0;
	for (int c = 0; c < 3; c++)
		s = fmax(s, sqrt(t->m[0][c] * t->m[0][c] + t->m[1][c] * t->m[1][c] + t->m[2][c] * t->m[2][c]));
	return s;
}

/* Off the view's axis, at angle a, the image of a small sphere stretches by 1 / cos^2 a along the
 * radius (the image plane's x = f tan a); this is the smallest cos a counted, 60 degrees, past the
 * corners of any usual view (a sphere out of sight is sized as at this angle). */
#define WORLD_SPHERE_MIN_COS 0.5

/* The silhouette of a sphere of radius r seen from distance dist has angular radius asin(r / dist),
 * so its radius on screen is focal_px r / sqrt(dist^2 - r^2) on the axis (cos_axis 1): per unit of
 * r, the pixels a unit of length takes there. */
double view_px_per_unit(const subd_camera *view, dvec3 centre, double r)
{
	dvec3 to_centre = d3_sub(centre, v3_to_d3(view->position));
	double dist = d3_length(to_centre);
	double cos_axis = dist > 0.0 ? d3_dot(to_centre, d3_normalize(v3_to_d3(view->look))) / dist : 1.0;
	double c = fmax(fmin(cos_axis, 1.0), WORLD_SPHERE_MIN_COS);
	return dist > r ? view_focal_px(view) / sqrt((dist - r) * (dist + r)) / (c * c) : INFINITY;
}

/* The tessellation level of a sphere (world.h): the coarsest whose silhouette, radius_px on screen,
 * stays within WORLD_SPHERE_MAX_ERROR_PX and whose edges, 2 pi radius_px / segments, within
 * WORLD_SPHERE_MAX_EDGE_PX; the finest when none is, or the camera is at or inside the sphere. A
 * surface error e r moves the silhouette by e radius_px. */
uint32_t sphere_level(const double rel_err[PRIM_SPHERE_LEVELS], double radius_px)
{
	uint32_t k = 0;
	while (k + 1 < PRIM_SPHERE_LEVELS &&
	       !(rel_err[k] * radius_px <= WORLD_SPHERE_MAX_ERROR_PX &&
		 2.0 * M_PI * radius_px <= WORLD_SPHERE_MAX_EDGE_PX * prim_sphere_level_segments(k)))
		k++;
	return k;
}

/* The world placement of o's texture space (texture -> world): the object's transform after the
 * inverse of its texture_from_object. */
static xform pattern_space(const scene_object *o)
{
	if (!o->texture_placed)
		return o->transform;
	xform inv;
	memcpy(inv.m, o->texture_from_object.inv, sizeof inv.m);
	memcpy(inv.inv, o->texture_from_object.m, sizeof inv.inv);
	return xform_then(inv, o->transform);
}

/* Makes the sphere object `in` an instance of the unit sphere at the level its size on screen
 * asks for: its transform gains the sphere's centre and radius. The unit spheres are made once
 * each, when first used. Returns that unit sphere, NULL after reporting an error. */
static world_geom *sphere_instance(world *w, const scene_geom *g, const subd_camera *view, const double rel_err[],
				   world_inst *in, diag *d, diag_loc loc)
{
	xform place;
	double r = g->u.sphere.radius;
	if (!xform_scale(d3(r, r, r), &place)) {
		diag_error(d, loc, "the sphere's radius %g is too small", r);
		return NULL;
	}
	place = xform_then(xform_then(place, xform_translate(g->u.sphere.center)), in->xf);
	double rw = r * axis_scale(&in->xf);
	uint32_t level = sphere_level(rel_err, rw * view_px_per_unit(view, xform_point(&in->xf, g->u.sphere.center), rw));
	world_geom *unit = &w->geoms[w->unit_spheres + level];
	if (!unit->m.num_triangles && !prim_sphere(v3s(0.0f), 1.0f, prim_sphere_level_segments(level), &unit->m)) {
		diag_error(d, loc, "out of memory while tessellating");
		return NULL;
	}
	in->g = unit;
	in->xf = place;
	return unit;
}

bool build_instances(world *w, const scene *sc, const world_options *opt, diag *d)
{
	subd_camera view = scene_view(sc, opt);
	if (!build_shapes(w, sc, &view, d))
		return false;
	double rel_err[PRIM_SPHERE_LEVELS];
	for (uint32_t k = 0; k < PRIM_SPHERE_LEVELS; k++)
		rel_err[k] = prim_sphere_rel_error(prim_sphere_level_segments(k));
	size_t n = scene_n_objects(sc);
	w->insts = mem_calloc(n ? n : 1, sizeof *w->insts);
	w->sss_group = mem_calloc(n ? n : 1, sizeof *w->sss_group);
	if (!w->insts || !w->sss_group) {
		diag_error(d, diag_noloc(), "out of memory");
		return false;
	}
	for (size_t i = 0; i < n; i++) {
		const scene_object *o = scene_object_at(sc, i);
		world_inst *in = &w->insts[w->n_insts++];
		world_geom *g = &w->geoms[o->geom->id];
		in->object = (uint32_t)i;
		in->g = g;
		in->xf = o->transform;
		in->pattern_xf = pattern_space(o);
		if (o->geom->kind == SHAPE_SPHERE && !(g = sphere_instance(w, o->geom, &view, rel_err, in, d, o->loc)))
			return false;
		in->identity = is_identity(&in->xf);
		set_xf_bound(in);
		in->no_shadow = o->no_shadow;
		in->hollow = (o->pov_flags & SCENE_OBJ_HOLLOW) != 0;
		in->light_group = o->light_group;
		in->light = -1;
		/* Without a material: the default grey, the last entry. */
		in->material = o->material ? (int)o->material->id : (int)w->n_materials - 1;
		if (o->n_parts) { /* a blob's component textures (world_inst.part_material) */
			if (!(in->part_material = mem_alloc(o->n_parts + 1u, sizeof *in->part_material))) {
				diag_error(d, o->loc, "out of memory");
				return false;
			}
			in->part_material[0] = in->material;
			for (uint32_t k = 0; k < o->n_parts; k++)
				in->part_material[k + 1] = (int)o->part_mat[k]->id;
			in->n_parts = o->n_parts;
		}
		/* A plane's mesh is made later (build_planes), with its tangents. */
		bool tangents = wants_tangents(o->material, opt) && o->geom->kind != SHAPE_PLANE;
		if (is_sss(o->material) && o->geom->kind != SHAPE_PLANE && !xform_is_similarity(&in->xf, NULL)) {
			if (!flatten_instance(w, in, sc->n_geoms + i, tangents, d, o->loc))
				return false;
		} else if (tangents && !make_tangents(g, d)) {
			return false;
		}
	}
	build_groups(w, sc);
	return build_csg(w, sc, d);
}

/* Bounds of everything but planes, and the camera (for the lights). Each plane object gets its
 * own mesh, reaching from the camera to its horizon (prim_plane_view): what it shows depends on
 * the camera alone, not on the other objects. */
bool build_planes(world *w, const scene *sc, const world_options *opt, diag *d)
{
	vec3 lo = v3s(FLT_MAX), hi = v3s(-FLT_MAX);
	for (size_t i = 0; i < w->n_insts; i++) {
		world_inst *in = &w->insts[i];
		const scene_object *o = scene_object_at(sc, in->object);
		if (o->geom->kind == SHAPE_PLANE || !mesh_bounds(&in->g->m, &in->lo, &in->hi))
			continue;
		xform_bounds(&in->xf, in->lo, in->hi, &in->lo, &in->hi);
		lo = v3_min(lo, in->lo), hi = v3_max(hi, in->hi);
	}
	if (sc->has_camera) {
		vec3 c = d3v(sc->camera.location);
		lo = v3_min(lo, c), hi = v3_max(hi, c);
	}
	if (lo.x > hi.x)
		lo = v3s(-1.0f), hi = v3s(1.0f);
	/* The extent in the scene's own units, however small (a floor of 1e-3 units made the lights'
	 * radius in a scene of 1e-6 a thousand times its size); a scene that is one point (the camera
	 * alone) takes the size of its coordinates, or 1 at the origin. */
	vec3 centre = v3_scale(v3_add(lo, hi), 0.5f);
	float size = v3_max_comp(v3_sub(hi, lo));
	if (!(size > 0.0f))
		size = v3_max_comp(v3_abs(centre)) > 0.0f ? v3_max_comp(v3_abs(centre)) : 1.0f;
	dvec3 eye = v3_to_d3(scene_view(sc, opt).position);
	for (size_t i = 0; i < w->n_insts; i++) {
		world_inst *in = &w->insts[i];
		const scene_object *o = scene_object_at(sc, in->object);
		if (o->geom->kind != SHAPE_PLANE)
			continue;
		world_geom *own = &w->geoms[sc->n_geoms + in->object];
		vec3 at = d3v(xform_inv_point(&in->xf, eye));
		if (!prim_plane_view(d3v(o->geom->u.plane.normal), (float)o->geom->u.plane.offset, at,
				     WORLD_PLANE_HORIZON_RAD, &own->m)) {
			diag_error(d, o->geom->loc, d3_length(o->geom->u.plane.normal) == 0.0 ? "the plane's normal is zero"
											      : "out of memory while tessellating");
			return false;
		}
		if (wants_tangents(o->material, opt) && !make_tangents(own, d))
			return false;
		in->g = own;
		if (mesh_bounds(&in->g->m, &in->lo, &in->hi))
			xform_bounds(&in->xf, in->lo, in->hi, &in->lo, &in->hi);
	}
	w->lo = lo, w->hi = hi;
	/* The lights' scene radius: a scene that is one point (planes and the camera) takes the
	 * planes' size, so a parallel light keeps its weight against the others. */
	w->radius = 0.5f * v3_length(v3_sub(hi, lo));
	if (!(w->radius > 0.0f))
		w->radius = 0.5f * size;
	return true;
}

/* The top-level BVHs: one over every instance with triangles, one over those casting shadows. */
bool build_top(world *w, diag *d)
{
	tlas_instance *all = mem_alloc(w->n_insts ? w->n_insts : 1, sizeof *all);
	tlas_instance *casters = mem_alloc(w->n_insts ? w->n_insts : 1, sizeof *casters);
	w->top_inst = mem_alloc(w->n_insts ? w->n_insts : 1, sizeof *w->top_inst);
	w->inst_top = mem_alloc(w->n_insts ? w->n_insts : 1, sizeof *w->inst_top);
	bool ok = all && casters && w->top_inst && w->inst_top;
	uint32_t na = 0, nc = 0;
	for (size_t i = 0; ok && i < w->n_insts; i++) {
		const world_inst *in = &w->insts[i];
		w->inst_top[i] = UINT32_MAX;
		if (!in->g->b || in->hidden) /* a clipped_by object is never seen */
			continue;
		w->inst_top[i] = na;
		w->top_inst[na] = (uint32_t)i;
		all[na++] = (tlas_instance){in->g->b, in->xf, sss_set(w, i), in->csg_filtered, (uint32_t)i};
		if (!in->no_shadow)
			casters[nc++] = (tlas_instance){in->g->b, in->xf, 0, in->csg_filtered, (uint32_t)i};
	}
	if (ok && na)
		ok = (w->top = tlas_build(all, na)) != NULL;
	if (ok && nc)
		ok = (w->shadow = tlas_build(casters, nc)) != NULL;
	if (ok && w->n_csg_nodes) { /* the CSG solids' boundaries: render/world_csg.c */
		if (w->top)
			tlas_set_filter(w->top, world_csg_filter, w);
		if (w->shadow)
			tlas_set_filter(w->shadow, world_csg_filter, w);
	}
	mem_free(all), mem_free(casters);
	if (!ok)
		diag_error(d, diag_noloc(), "out of memory while building the top-level BVH");
	else
		w->stats.geometry_bytes += (w->top ? tlas_bytes(w->top) : 0) + (w->shadow ? tlas_bytes(w->shadow) : 0);
	return ok;
}
