/* world.c - IR to meshes, BVHs, instances, BSDFs, textures, lights and camera; the integrator's
 * callbacks over them. */
#include "render/world.h"

#include "accel/offset.h"
#include "base/mem.h"
#include "geom/cage.h"
#include "geom/prim.h"
#include "geom/subdiv.h"
#include "render/assets.h"
#include "render/shading.h"
#include "sss/profile.h"
#include "sss/walk.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The grey of an object without a material: mid-grey diffuse. */
#define WORLD_DEFAULT_GREY 0.5f

/* The bytes a texture may take: what the allocator's limit leaves (main sets it to --max-memory,
 * or the machine's memory), 0 when there is no limit. */
static size_t texture_room(void)
{
	size_t limit = mem_limit(), live = mem_live_bytes();
	return !limit ? 0 : limit > live ? limit - live : 1;
}

/* The image at path (the language resolved it against the scene's folders), loaded once per
 * world; NULL after reporting an error at loc. One that would not fit in texture_room() is
 * refused from its header's size, before it is decoded. */
static const image *world_image(world *w, diag_loc loc, const char *path, image_encoding enc, diag *d)
{
	size_t max_bytes = texture_room();
	char *full = mem_strdup(path);
	if (!full) {
		diag_error(d, loc, "out of memory");
		return NULL;
	}
	for (size_t i = 0; i < w->n_images; i++)
		if (!strcmp(w->image_paths[i], full)) {
			mem_free(full);
			return w->images[i];
		}
	image **imgs = mem_realloc(w->images, w->n_images + 1, sizeof *imgs);
	char **paths = imgs ? mem_realloc(w->image_paths, w->n_images + 1, sizeof *paths) : NULL;
	image *img = paths ? mem_calloc(1, sizeof *img) : NULL;
	if (imgs)
		w->images = imgs;
	if (paths)
		w->image_paths = paths;
	if (!img) {
		mem_free(full);
		diag_error(d, loc, "out of memory");
		return NULL;
	}
	if (!image_load_limited(full, enc, max_bytes, img, d)) {
		diag_note(d, loc, "the image was named here");
		mem_free(img);
		mem_free(full);
		return NULL;
	}
	w->images[w->n_images] = img;
	w->image_paths[w->n_images++] = full;
	return img;
}

/* The number of img's texels outside the range of `use` (a float EXR may hold any number); with
 * rgb non-NULL, every texel's RGB clamped into it (scene_color_clamp) is written there. */
static size_t clamp_texels(const image *img, scene_color_use use, float *rgb)
{
	size_t n = (size_t)img->width * (size_t)img->height, clamped = 0;
	for (size_t i = 0; i < n; i++) {
		vec3 texel = v3(img->rgba[i * 4], img->rgba[i * 4 + 1], img->rgba[i * 4 + 2]);
		clamped += scene_color_clamp(&texel, use);
		if (rgb)
			rgb[i * 3] = texel.x, rgb[i * 3 + 1] = texel.y, rgb[i * 3 + 2] = texel.z;
	}
	return clamped;
}

/* An albedo texture's texels outside [0, 1]: the shade hook clamps each lookup, and this says so
 * once, at the material. */
static void warn_reflectance_image(const image *img, diag_loc loc, const char *path, diag *d)
{
	size_t clamped = clamp_texels(img, SCENE_COLOR_REFLECTANCE, NULL);
	if (clamped)
		diag_warning(d, loc, "%zu texels of '%s' are outside [0, 1], the range of a reflectance: clamped, a "
				     "non-finite one to 0",
			     clamped, path);
}

static vec3 d3v(dvec3 v) { return d3_to_v3(v); }

/* The scene's camera as the tessellation sees it: eye, view and vertical field of view at the
 * image's size (the default camera when the scene has none, as build_camera does). */
static subd_camera scene_view(const scene *sc, const world_options *opt)
{
	const scene_camera *c = &sc->camera;
	cam_params dc = cam_params_default();
	dvec3 from = sc->has_camera ? c->location : dc.location;
	dvec3 to = sc->has_camera ? c->look_at : dc.look_at;
	double angle_deg = sc->has_camera ? c->angle_deg : dc.angle_deg;
	double aspect = (double)opt->width / (double)opt->height;
	double half_h = tan(angle_deg * M_PI / 360.0) / aspect;
	/* The view in double: a difference of positions far from the origin would cancel in float. */
	return (subd_camera){.position = d3v(from), .look = d3v(d3_sub(to, from)), .up = sc->has_camera ? d3v(c->sky) : dc.sky,
			     .fov_y_deg = (float)(2.0 * atan(half_h) * 180.0 / M_PI),
			     .image_height = (uint32_t)opt->height};
}

/* Pixels per unit of size at unit distance, at the centre of the view. */
static double view_focal_px(const subd_camera *v)
{
	return 0.5 * v->image_height / tan(v->fov_y_deg * M_PI / 360.0);
}

/* The subdivision options of a cage: uniform level, or adaptive through the scene's camera. */
static subd_options subdiv_options(const scene *sc, const scene_subdiv *sd, const world_options *opt,
				   subd_camera *camera)
{
	subd_options so = {.level = sd->level, .max_bytes = opt->max_memory};
	if (sd->level <= 0 && sd->max_edge_px > 0) {
		*camera = scene_view(sc, opt);
		so.camera = camera;
		so.max_edge_px = (float)sd->max_edge_px;
	}
	return so;
}

/* The creases and corners of a cage: a file's tags first, then the scene's, so that where both
 * name an edge the scene's sharpness holds (subd_tessellate keeps the later one). The scene's
 * indices are the file's own vertex numbers, mapped through its welding; each is checked against
 * the cage (a file cage is only known here) and reported at the scene's place. */
static bool subdiv_tags(const scene_subdiv *sd, const cage_data *file, subd_cage *cage, diag *d)
{
	uint32_t fc = file ? file->num_creases : 0, fk = file ? file->num_corners : 0;
	size_t nc = (size_t)fc + sd->n_creases, nk = (size_t)fk + sd->n_corners;
	uint32_t *crease_v = mem_alloc(2 * nc, sizeof *crease_v), *corner_v = mem_alloc(nk, sizeof *corner_v);
	float *crease_s = mem_alloc(nc, sizeof *crease_s), *corner_s = mem_alloc(nk, sizeof *corner_s);
	if (!crease_v || !crease_s || !corner_v || !corner_s) {
		mem_free(crease_v), mem_free(crease_s), mem_free(corner_v), mem_free(corner_s);
		diag_error(d, sd->file ? sd->file_loc : diag_noloc(), "out of memory");
		return false;
	}
	if (file) {
		memcpy(crease_v, file->crease_vertices, 2 * (size_t)fc * sizeof *crease_v);
		memcpy(crease_s, file->crease_sharpness, fc * sizeof *crease_s);
		memcpy(corner_v, file->corner_vertices, fk * sizeof *corner_v);
		memcpy(corner_s, file->corner_sharpness, fk * sizeof *corner_s);
	}
	int errors = 0;
	for (uint32_t i = 0; i < sd->n_creases; i++) {
		const scene_crease *c = &sd->creases[i];
		uint32_t a = c->a, b = c->b;
		if (file && (a >= file->num_file_vertices || b >= file->num_file_vertices)) {
			diag_error(d, c->loc, "crease %u: vertex %u is out of range (the cage file '%s' has %u vertices)", i,
				   a >= file->num_file_vertices ? a : b, sd->file, file->num_file_vertices);
			errors++;
			continue;
		}
		if (file) {
			a = file->weld[a], b = file->weld[b];
			if (!cage_has_edge(file, a, b)) {
				diag_error(d, c->loc, "crease %u: <%u, %u> is not an edge of the cage in '%s'", i, c->a, c->b,
					   sd->file);
				errors++;
				continue;
			}
		}
		crease_v[2 * (fc + i)] = a, crease_v[2 * (fc + i) + 1] = b;
		crease_s[fc + i] = c->sharpness;
	}
	for (uint32_t i = 0; i < sd->n_corners; i++) {
		const scene_corner *c = &sd->corners[i];
		uint32_t v = c->vertex;
		if (file && v >= file->num_file_vertices) {
			diag_error(d, c->loc, "corner %u: vertex %u is out of range (the cage file '%s' has %u vertices)", i,
				   v, sd->file, file->num_file_vertices);
			errors++;
			continue;
		}
		corner_v[fk + i] = file ? file->weld[v] : v;
		corner_s[fk + i] = c->sharpness;
	}
	if (errors) {
		mem_free(crease_v), mem_free(crease_s), mem_free(corner_v), mem_free(corner_s);
		return false;
	}
	cage->crease_vertices = crease_v, cage->crease_sharpness = crease_s, cage->num_creases = (uint32_t)nc;
	cage->corner_vertices = corner_v, cage->corner_sharpness = corner_s, cage->num_corners = (uint32_t)nk;
	return true;
}

static bool build_subdiv(world *w, const scene *sc, const scene_geom *g, const world_options *opt, mesh *m,
			 diag *d)
{
	const scene_subdiv *sd = &g->u.subdiv;
	cage_data file;
	subd_cage cage;
	if (sd->file) {
		if (!cage_load(sd->file, &file, d, sd->file_loc))
			return false;
		w->stats.cage_file_faces += file.num_faces;
		cage = cage_view(&file);
		cage.source = sd->file;
	} else {
		cage = (subd_cage){
			.positions = sd->vertices, .num_vertices = sd->n_vertices,
			.face_sizes = sd->face_sizes, .num_faces = sd->n_faces, .face_indices = sd->face_verts,
			.uvs = sd->n_uv_faces ? sd->uvs : NULL, .num_uvs = sd->n_uvs,
			.uv_indices = sd->n_uv_faces ? sd->uv_face_verts : NULL,
		};
	}
	cage.scheme = sd->scheme == SCENE_SUBD_LOOP ? SUBD_LOOP : SUBD_CATMULL_CLARK;
	/* The scene's boundary rule when written, else the file's tag, else the language's default. */
	cage.boundary = sd->file && !sd->boundary_given && file.has_boundary ? file.boundary
		      : sd->boundary == SCENE_SUBD_EDGE_AND_CORNER ? SUBD_BOUNDARY_EDGE_AND_CORNER
								   : SUBD_BOUNDARY_EDGE_ONLY;
	bool ok = subdiv_tags(sd, sd->file ? &file : NULL, &cage, d);
	if (ok) {
		subd_camera camera;
		subd_options so = subdiv_options(sc, sd, opt, &camera);
		ok = subd_tessellate(&cage, &so, m, d, sd->file ? sd->file_loc : g->loc);
		mem_free((void *)cage.crease_vertices), mem_free((void *)cage.crease_sharpness);
		mem_free((void *)cage.corner_vertices), mem_free((void *)cage.corner_sharpness);
	}
	if (sd->file)
		cage_free(&file);
	return ok;
}

/* Tessellates one geometry record (spheres and planes wait for their objects' transforms). */
static bool build_geom(world *w, const scene *sc, const scene_geom *g, const world_options *opt, diag *d)
{
	mesh *m = &w->geoms[g->id].m;
	switch (g->kind) {
	case SHAPE_SPHERE: /* an instance of a unit sphere, chosen per object (sphere_instance) */
		return true;
	case SHAPE_BOX:
		if (!prim_box(d3v(g->u.box.corner1), d3v(g->u.box.corner2), m))
			break;
		return true;
	case SHAPE_PLANE:
		return true;
	case SHAPE_MESH: {
		const scene_mesh *sm = &g->u.mesh;
		mesh_arrays a = {sm->positions, sm->n_positions, sm->normals, sm->n_normals, sm->uvs, sm->n_uvs,
				 sm->faces, sm->normal_idx, sm->uv_idx, sm->n_faces};
		return mesh_from_arrays(&a, m, d, g->loc);
	}
	case SHAPE_MESH_FILE: {
		bool ok = mesh_import(g->u.file.path, m, d);
		if (!ok)
			diag_note(d, g->loc, "the mesh file was named here");
		return ok;
	}
	case SHAPE_SUBDIV:
		w->stats.subdiv_surfaces++;
		return build_subdiv(w, sc, g, opt, m, d);
	}
	diag_error(d, g->loc, "out of memory while tessellating");
	return false;
}

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

static bool is_sss(const scene_material *m)
{
	return m && (m->kind == MAT_SKIN || m->kind == MAT_WAX || m->kind == MAT_MARBLE);
}

static scene_sss_method sss_method_of(const scene_material *m, const world_options *opt)
{
	return opt->sss_method != SSS_METHOD_DEFAULT ? opt->sss_method : m->sss.method;
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

/* The BSSRDF of an SSS material: its profile from the artist form (the albedo the coat shows and
 * a texture scales), the method (the command line's over the material's), and f_t's normalisation. */
static bool build_sss(world *w, size_t k, const scene *sc, const world_options *opt, const scene_material *sm,
		      diag *d)
{
	static const sss_profile_kind kinds[] = {[PROFILE_GAUSSIAN] = SSS_PROFILE_GAUSSIAN,
						 [PROFILE_SUM_OF_GAUSSIANS] = SSS_PROFILE_SUM_OF_GAUSSIANS,
						 [PROFILE_BURLEY] = SSS_PROFILE_BURLEY,
						 [PROFILE_DIPOLE] = SSS_PROFILE_DIPOLE};
	const scene_sss *ss = &sm->sss;
	render_sss *r = &w->sss[k];
	double albedo[3] = {ss->albedo.x, ss->albedo.y, ss->albedo.z};
	double ld_mm[3] = {ss->radius_mm.x, ss->radius_mm.y, ss->radius_mm.z};
	if (!sss_profile_from_artist(&r->profile, kinds[ss->profile], albedo, ld_mm, ss->ior)) {
		diag_error(d, sm->loc, "the subsurface medium is out of range (albedo %g %g %g, radius %g %g %g mm, ior %g)",
			   albedo[0], albedo[1], albedo[2], ld_mm[0], ld_mm[1], ld_mm[2], (double)ss->ior);
		return false;
	}
	scene_sss_method m = sss_method_of(sm, opt);
	r->method = m == SSS_METHOD_FULLCIRCLE ? RENDER_SSS_FULLCIRCLE
		    : m == SSS_METHOD_DISK     ? RENDER_SSS_DISK
		    : m == SSS_METHOD_VOLUME   ? RENDER_SSS_VOLUME
					       : RENDER_SSS_CIRCLE;
	r->units_per_mm = (float)(1.0 / sc->global.mm_per_unit);
	/* The walk's medium from the physical form the scene derived from the artist one: the same
	 * coefficients the dipole's albedo comes from, so volume against the profiles measures the
	 * diffusion models' error and nothing else. */
	double ss_mm[3] = {ss->sigma_s_per_mm.x, ss->sigma_s_per_mm.y, ss->sigma_s_per_mm.z};
	double sa_mm[3] = {ss->sigma_a_per_mm.x, ss->sigma_a_per_mm.y, ss->sigma_a_per_mm.z};
	if (r->method == RENDER_SSS_VOLUME &&
	    !sss_walk_medium_from_reduced(&r->medium, ss_mm, sa_mm, ss->anisotropy, ss->ior, sc->global.mm_per_unit)) {
		diag_error(d, sm->loc, "the subsurface medium is out of range for the volume method (sigma_s' %g %g %g, "
				       "sigma_a %g %g %g per mm, anisotropy %g, ior %g)",
			   ss_mm[0], ss_mm[1], ss_mm[2], sa_mm[0], sa_mm[1], sa_mm[2], (double)ss->anisotropy,
			   (double)ss->ior);
		return false;
	}
	r->ior = ss->ior;
	/* f_t's c (DESIGN.md): integral of (1 - F(mu)) mu dmu over the outside hemisphere, times 2,
	 * is 1 - 2 FM1(eta) with FM1 of light arriving from outside (sss_fresnel_moment1's eta =
	 * n_inside / n_outside); DESIGN.md writes FM1(1/eta) in pbrt's opposite convention. */
	r->entry_norm = (float)(1.0 / (1.0 - 2.0 * sss_fresnel_moment1(ss->ior)));
	r->albedo = ss->albedo;
	r->textured = ss->albedo_image != NULL;
	w->sss_of[k] = r;
	w->has_sss = true;
	return true;
}

/* BSDF parameters and textures of a scene material. */
static bool build_material(world *w, size_t k, const scene *sc, const world_options *opt,
			   const scene_material *sm, diag *d)
{
	world_material *wm = &w->materials[k];
	switch (sm->kind) {
	case MAT_DIFFUSE:
		w->bsdfs[k] = bsdf_diffuse(sm->color);
		break;
	case MAT_TEXTURE:
		w->bsdfs[k] = bsdf_pov_finish(sm->color, sm->diffuse, sm->specular, sm->roughness);
		break;
	case MAT_EMISSION:
		w->bsdfs[k] = bsdf_diffuse(v3s(0.0f));
		break;
	case MAT_SKIN:
	case MAT_WAX:
	case MAT_MARBLE:
		/* The coat's reflection; its diffuse interior is replaced by the BSSRDF in the
		 * integrator, but keeps the albedo for the AOV and the choice of lobe. */
		w->bsdfs[k] = bsdf_coat(sm->sss.albedo, sm->sss.ior, sm->sss.roughness);
		if (!build_sss(w, k, sc, opt, sm, d))
			return false;
		break;
	default:
		w->bsdfs[k] = bsdf_diffuse(v3s(WORLD_DEFAULT_GREY));
		break;
	}
	bool sss = sm->kind == MAT_SKIN || sm->kind == MAT_WAX || sm->kind == MAT_MARBLE;
	const char *albedo = sss ? sm->sss.albedo_image : sm->image;
	if (albedo && !(wm->albedo = world_image(w, sm->loc, albedo, IMAGE_SRGB, d)))
		return false;
	if (albedo)
		warn_reflectance_image(wm->albedo, sm->loc, albedo, d);
	if (sss && sm->sss.normal_map) {
		if (!(wm->normal_map =
			  world_image(w, sm->loc, sm->sss.normal_map, IMAGE_RAW, d)))
			return false;
		wm->normal_strength = sm->sss.normal_strength;
	}
	return true;
}

/* ---- the integrator's callbacks ---------------------------------------------------------- */

static vec3 xf_normal(const world_inst *in, vec3 n)
{
	return in->identity ? n : d3v(xform_normal(&in->xf, v3_to_d3(n)));
}

static vec3 xf_vector(const world_inst *in, vec3 v)
{
	return in->identity ? v : d3v(xform_vector(&in->xf, v3_to_d3(v)));
}

/* The world-space normals of instance `in` at triangle prim, barycentrics (u, v) of its second
 * and third vertex: the geometric one *ng turned into the hemisphere of the shading one *ns. */
static void hit_normals(const world_inst *in, uint32_t prim, float u, float v, vec3 *ng_out, vec3 *ns_out)
{
	const mesh *m = &in->g->m;
	const uint32_t *ix = m->indices + 3 * (size_t)prim;
	float b0 = 1.0f - u - v;
	vec3 p0 = m->positions[ix[0]], p1 = m->positions[ix[1]], p2 = m->positions[ix[2]];
	vec3 ng = v3_normalize(xf_normal(in, v3_cross(v3_sub(p1, p0), v3_sub(p2, p0))));
	vec3 ns = ng;
	if (m->normals) {
		vec3 n = v3_add(v3_add(v3_scale(m->normals[ix[0]], b0), v3_scale(m->normals[ix[1]], u)),
				v3_scale(m->normals[ix[2]], v));
		n = v3_normalize(xf_normal(in, n));
		if (v3_is_finite(n) && v3_length2(n) > 0.5f)
			ns = n;
		if (v3_dot(ns, ng) < 0.0f)
			ng = v3_neg(ng); /* render_hit wants both normals in one hemisphere */
	}
	*ng_out = ng, *ns_out = ns;
}

/* The surface of instance `inst` at triangle prim, barycentrics (u, v) of its second and third
 * vertex: world position, normals (both in one hemisphere), uv. */
static void fill_hit(const world *w, uint32_t inst, uint32_t prim, float u, float v, render_hit *hit)
{
	const world_inst *in = &w->insts[inst];
	const mesh *m = &in->g->m;
	const uint32_t *ix = m->indices + 3 * (size_t)prim;
	float b0 = 1.0f - u - v;
	vec3 p0 = m->positions[ix[0]], p1 = m->positions[ix[1]], p2 = m->positions[ix[2]];
	vec3 ng, ns;
	hit_normals(in, prim, u, v, &ng, &ns);
	vec2 uv = v2(0.0f, 0.0f);
	if (m->uvs)
		uv = v2(b0 * m->uvs[ix[0]].x + u * m->uvs[ix[1]].x + v * m->uvs[ix[2]].x,
			b0 * m->uvs[ix[0]].y + u * m->uvs[ix[1]].y + v * m->uvs[ix[2]].y);
	/* The position from the triangle: its error is that of the vertices, which the ray offset
	 * covers; o + t d would carry the error of the whole ray. */
	vec3 p = v3_add(v3_add(v3_scale(p0, b0), v3_scale(p1, u)), v3_scale(p2, v));
	float scale = bvh_triangle_scale(p0, p1, p2);
	if (!in->identity) {
		p = d3v(xform_point(&in->xf, v3_to_d3(p)));
		scale = in->xf_gain * scale + in->xf_shift; /* a bound of the world vertices' scale */
	}
	*hit = (render_hit){.p = p, .ng = ng, .ns = ns, .uv = uv, .material = in->material, .light = in->light,
			    .object = inst, .prim = prim, .bary = v2(u, v), .scale = scale};
}

static bool world_intersect(void *user, const render_ray *ray, float tmin, float tmax, render_hit *hit)
{
	const world *w = user;
	bvh_ray r = {ray->o, ray->d, tmin, tmax};
	bvh_hit best;
	if (!w->top || !tlas_intersect(w->top, &r, &best))
		return false;
	fill_hit(w, w->top_inst[best.inst], best.prim, best.u, best.v, hit);
	hit->t = best.t;
	return true;
}

/* The top level's set of an instance: its SSS volume, i.e. the first member of its group, or
 * itself (a group's first member is an instance of the group, so the two never collide). */
static uint32_t sss_set(const world *w, size_t i)
{
	return w->sss_group[i] >= 0 ? (uint32_t)w->sss_group[i] : (uint32_t)i;
}

/* Every hit of the circle on the SSS volume of `at`: its instance alone, or every member of its
 * group (the top level's set of the group: other objects cost no traversal and take no room), in
 * the top level's canonical order. The position is the circle's exact one; the normal is the
 * one fill_hit gives (the weights must see the normal the chosen hit is shaded with). */
static uint32_t world_circle(void *user, const render_hit *at, const tri_circle *q, tri_circle_hit *hits, uint32_t max,
			     bool *more)
{
	const world *w = user;
	if (!w->top || at->object >= w->n_insts || w->inst_top[at->object] == UINT32_MAX)
		return 0;
	uint32_t total = w->sss_group[at->object] < 0 ? tlas_circle(w->top, q, w->inst_top[at->object], hits, max)
						      : tlas_circle_set(w->top, q, sss_set(w, at->object), hits, max);
	uint32_t n = total < max ? total : max;
	*more = total > n; /* beyond the buffer: known only by count */
	for (uint32_t i = 0; i < n; i++) {
		vec3 ns;
		hits[i].inst = w->top_inst[hits[i].inst];
		hit_normals(&w->insts[hits[i].inst], hits[i].prim, hits[i].u, hits[i].v, &hits[i].ng, &ns);
	}
	return n;
}

static void world_circle_surface(void *user, const tri_circle_hit *h, render_hit *hit)
{
	fill_hit(user, h->inst, h->prim, h->u, h->v, hit);
	hit->p = h->pos;
}

/* The nearest hit of a ray on the SSS volume of `at`: its instance, or each member of its group
 * in turn (the ray moved into each one's object space: t is kept, the direction not being
 * renormalised), the members found through the group's list. */
static bool world_sss_closest(void *user, const render_hit *at, const render_ray *ray, float tmin, float tmax,
			      render_hit *hit)
{
	const world *w = user;
	if (at->object >= w->n_insts)
		return false;
	int group = w->sss_group[at->object];
	bvh_hit best;
	uint32_t best_inst = UINT32_MAX;
	for (size_t i = group < 0 ? at->object : (size_t)group; i < w->n_insts;
	     i = group < 0 ? w->n_insts : w->sss_next[i]) {
		const world_inst *in = &w->insts[i];
		if (!in->g->b)
			continue;
		bvh_ray r = {ray->o, ray->d, tmin, tmax};
		if (!in->identity) {
			r.org = d3v(xform_inv_point(&in->xf, v3_to_d3(ray->o)));
			r.dir = d3v(xform_inv_vector(&in->xf, v3_to_d3(ray->d)));
		}
		bvh_hit h;
		if (bvh_intersect(in->g->b, &r, &h)) {
			best = h, best_inst = (uint32_t)i;
			tmax = h.t;
		}
	}
	if (best_inst == UINT32_MAX)
		return false;
	fill_hit(w, best_inst, best.prim, best.u, best.v, hit);
	hit->t = best.t;
	return true;
}

static bool world_occluded(void *user, const render_ray *ray, float tmin, float tmax)
{
	const world *w = user;
	bvh_ray r = {ray->o, ray->d, tmin, tmax};
	return w->shadow && tlas_occluded(w->shadow, &r);
}

static void world_shade(void *user, const render_hit *hit, bsdf_params *params, vec3 *ns)
{
	const world *w = user;
	if (hit->material < 0 || hit->object >= w->n_insts)
		return;
	const world_material *wm = &w->materials[hit->material];
	if (wm->albedo) {
		float c[4];
		image_bilinear(wm->albedo, hit->uv.x, hit->uv.y, c);
		params->diffuse = v3(c[0], c[1], c[2]);
		/* A float (EXR) texture may hold any number: a reflectance is in [0, 1] (check warns). */
		scene_color_clamp(&params->diffuse, SCENE_COLOR_REFLECTANCE);
	}
	const world_inst *in = &w->insts[hit->object];
	const mesh *m = &in->g->m;
	if (wm->normal_map && m->tangents) {
		const uint32_t *ix = m->indices + 3 * (size_t)hit->prim;
		float b0 = 1.0f - hit->bary.x - hit->bary.y;
		vec3 t = v3_add(v3_add(v3_scale(m->tangents[ix[0]].t, b0), v3_scale(m->tangents[ix[1]].t, hit->bary.x)),
				v3_scale(m->tangents[ix[2]].t, hit->bary.y));
		float c[4];
		image_bilinear(wm->normal_map, hit->uv.x, hit->uv.y, c);
		*ns = render_normal_map(*ns, xf_vector(in, t), m->tangents[ix[0]].sign, v3(c[0], c[1], c[2]),
					wm->normal_strength);
	}
}

/* ---- building ---------------------------------------------------------------------------- */


/* An SSS object under a non-uniform transform gets its own copy of the triangles in world space
 * (DESIGN.md): circles stay circles only under similarities, and circle tracing runs in an
 * instance's own space. Its geometry record is the one at index `slot` (past the scene's). */
static bool flatten_instance(world *w, world_inst *in, size_t slot, diag *d, diag_loc loc)
{
	world_geom *copy = &w->geoms[slot];
	if (!mesh_copy(&copy->m, &in->g->m)) {
		diag_error(d, loc, "out of memory while flattening an SSS object into world space");
		return false;
	}
	mesh_transform(&copy->m, &in->xf);
	in->g = copy;
	in->xf = xform_identity();
	in->identity = true;
	w->stats.flattened++;
	return true;
}


/* A walk's length grows like the square of the object's size in transport mean free paths
 * (diffusion), capped by absorption at about sigma_t'/sigma_a interactions. When the smaller of
 * the two exceeds the walk's step bound most long walks will be dropped (dark, counted): say so
 * before the render rather than after. High albedos given in the artist form are the usual cause
 * (albedo 1 needs sigma_a = 0, so the inversion makes sigma_s' very large). */
static void warn_dense_medium(const world_inst *in, const scene *sc, const scene_object *o, diag *d)
{
	const scene_sss *ss = &o->material->sss;
	double size_mm = v3_length(v3_sub(in->hi, in->lo)) * sc->global.mm_per_unit, worst = 0.0;
	const float *s_s = &ss->sigma_s_per_mm.x, *s_a = &ss->sigma_a_per_mm.x;
	for (int c = 0; c < 3; c++) {
		double st = (double)s_s[c] + s_a[c], tau = st * size_mm;
		double steps = fmin(tau * tau, s_a[c] > 0.0f ? st / s_a[c] : INFINITY);
		worst = fmax(worst, steps);
	}
	if (worst > SSS_WALK_MAX_STEPS)
		diag_warning(d, o->loc,
			     "the volume method's walks in this object need about %.3g interactions (its medium is "
			     "dense for its size and hardly absorbs); walks stop at %d, and those are dropped and "
			     "counted",
			     worst, SSS_WALK_MAX_STEPS);
}

/* The volume method walks inside the object: an SSS object rendered by it must bound a volume
 * (sss_walk_mesh_closure), else light would leave through the holes. Checked once per mesh. */
static bool check_volumes(const world *w, const scene *sc, const world_options *opt, diag *d)
{
	bool ok = true;
	int8_t *closed = mem_calloc(w->n_geoms ? w->n_geoms : 1, 1); /* 0 unknown, 1 closed, -1 open */
	if (!closed) {
		diag_error(d, diag_noloc(), "out of memory");
		return false;
	}
	for (size_t i = 0; i < w->n_insts; i++) {
		const scene_object *o = scene_object_at(sc, i);
		if (!is_sss(o->material) || sss_method_of(o->material, opt) != SSS_METHOD_VOLUME)
			continue;
		const world_geom *g = w->insts[i].g;
		size_t gi = (size_t)(g - w->geoms);
		uint64_t open_edges = 0;
		if (!closed[gi]) {
			sss_mesh_closure c = sss_walk_mesh_closure(&g->m, &open_edges);
			if (c == SSS_MESH_NO_MEMORY) {
				diag_error(d, o->loc, "out of memory while checking that the object is closed");
				ok = false;
				break;
			}
			closed[gi] = c == SSS_MESH_CLOSED ? 1 : -1;
		}
		if (closed[gi] < 0) {
			if (o->geom->kind == SHAPE_PLANE)
				diag_error(d, o->loc, "the volume SSS method needs a closed object, and a plane bounds "
						      "no volume");
			else
				diag_error(d, o->loc, "the volume SSS method needs a closed object: this one has %llu "
						      "edge(s) not shared by exactly two triangles",
					   (unsigned long long)open_edges);
			if (opt->sss_method == SSS_METHOD_VOLUME)
				diag_note(d, diag_noloc(), "--sss volume applies to every SSS material; render this "
							   "scene with circle, fullcircle or disk");
			else
				diag_note(d, o->material->loc, "its material is here; give it method circle, fullcircle "
							      "or disk for an open surface");
			ok = false;
		} else {
			warn_dense_medium(&w->insts[i], sc, o, d);
		}
	}
	mem_free(closed);
	return ok;
}

/* The SSS volume of each instance: alone (-1), or the first instance of its material's group;
 * and each group's members as a list in instance order (sss_next). */
static void build_groups(world *w, const scene *sc)
{
	for (size_t i = 0; i < w->n_insts; i++) {
		const scene_material *m = scene_object_at(sc, i)->material;
		w->sss_group[i] = -1;
		w->sss_next[i] = UINT32_MAX;
		for (size_t j = 0; is_sss(m) && m->sss.group && j <= i; j++) {
			const scene_material *mj = scene_object_at(sc, j)->material;
			if (is_sss(mj) && mj->sss.group && !strcmp(mj->sss.group, m->sss.group)) {
				w->sss_group[i] = (int)j;
				break;
			}
		}
	}
	/* Each member links to the next: walk back from the end, keeping each group's last seen. */
	for (size_t i = w->n_insts; i-- > 0;) {
		if (w->sss_group[i] < 0)
			continue;
		size_t head = (size_t)w->sss_group[i];
		if (i != head) {
			w->sss_next[i] = w->sss_next[head];
			w->sss_next[head] = (uint32_t)i;
		}
	}
}

/* The largest length an axis of the object takes under t: a sphere's radius in the world (exact
 * under a similarity; under a non-uniform scale, that of the longest axis). */
static double axis_scale(const xform *t)
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

/* The tessellation level of a sphere (world.h): the coarsest whose silhouette, radius_px on screen,
 * stays within WORLD_SPHERE_MAX_ERROR_PX and whose edges, 2 pi radius_px / segments, within
 * WORLD_SPHERE_MAX_EDGE_PX; the finest when none is, or the camera is at or inside the sphere. The
 * silhouette of a sphere of radius r seen from distance dist has angular radius asin(r / dist),
 * so radius_px = focal_px r / sqrt(dist^2 - r^2) on the axis (cos_axis 1); a surface error e r
 * moves it by e radius_px. */
static uint32_t sphere_level(const double rel_err[PRIM_SPHERE_LEVELS], double focal_px, double dist, double r,
			     double cos_axis)
{
	double c = fmax(fmin(cos_axis, 1.0), WORLD_SPHERE_MIN_COS);
	double radius_px = dist > r ? focal_px * r / sqrt((dist - r) * (dist + r)) / (c * c) : INFINITY;
	uint32_t k = 0;
	while (k + 1 < PRIM_SPHERE_LEVELS &&
	       !(rel_err[k] * radius_px <= WORLD_SPHERE_MAX_ERROR_PX &&
		 2.0 * M_PI * radius_px <= WORLD_SPHERE_MAX_EDGE_PX * prim_sphere_level_segments(k)))
		k++;
	return k;
}

/* Makes the sphere object `in` an instance of the unit sphere at the level its size on screen
 * asks for: its transform gains the sphere's centre and radius. The unit spheres are made once
 * each, when first used. */
static bool sphere_instance(world *w, const scene_geom *g, const subd_camera *view, const double rel_err[],
			    world_inst *in, diag *d, diag_loc loc)
{
	xform place;
	double r = g->u.sphere.radius;
	if (!xform_scale(d3(r, r, r), &place)) {
		diag_error(d, loc, "the sphere's radius %g is too small", r);
		return false;
	}
	place = xform_then(xform_then(place, xform_translate(g->u.sphere.center)), in->xf);
	dvec3 to_centre = d3_sub(xform_point(&in->xf, g->u.sphere.center), v3_to_d3(view->position));
	double dist = d3_length(to_centre);
	double cos_axis = dist > 0.0 ? d3_dot(to_centre, d3_normalize(v3_to_d3(view->look))) / dist : 1.0;
	uint32_t level = sphere_level(rel_err, view_focal_px(view), dist, r * axis_scale(&in->xf), cos_axis);
	world_geom *unit = &w->geoms[w->unit_spheres + level];
	if (!unit->m.num_triangles && !prim_sphere(v3s(0.0f), 1.0f, prim_sphere_level_segments(level), &unit->m)) {
		diag_error(d, loc, "out of memory while tessellating");
		return false;
	}
	in->g = unit;
	in->xf = place;
	return true;
}

static bool build_instances(world *w, const scene *sc, const world_options *opt, diag *d)
{
	subd_camera view = scene_view(sc, opt);
	double rel_err[PRIM_SPHERE_LEVELS];
	for (uint32_t k = 0; k < PRIM_SPHERE_LEVELS; k++)
		rel_err[k] = prim_sphere_rel_error(prim_sphere_level_segments(k));
	size_t n = scene_n_objects(sc);
	w->insts = mem_calloc(n ? n : 1, sizeof *w->insts);
	w->sss_group = mem_calloc(n ? n : 1, sizeof *w->sss_group);
	w->sss_next = mem_calloc(n ? n : 1, sizeof *w->sss_next);
	if (!w->insts || !w->sss_group || !w->sss_next) {
		diag_error(d, diag_noloc(), "out of memory");
		return false;
	}
	for (size_t i = 0; i < n; i++) {
		const scene_object *o = scene_object_at(sc, i);
		world_inst *in = &w->insts[w->n_insts++];
		in->g = &w->geoms[o->geom->id];
		in->xf = o->transform;
		if (o->geom->kind == SHAPE_SPHERE && !sphere_instance(w, o->geom, &view, rel_err, in, d, o->loc))
			return false;
		in->identity = is_identity(&in->xf);
		set_xf_bound(in);
		in->no_shadow = o->no_shadow;
		in->light = -1;
		/* Without a material: the default grey, the last entry. */
		in->material = o->material ? (int)o->material->id : (int)w->n_materials - 1;
		if (is_sss(o->material) && o->geom->kind != SHAPE_PLANE && !xform_is_similarity(&in->xf, NULL) &&
		    !flatten_instance(w, in, sc->n_geoms + i, d, o->loc))
			return false;
	}
	build_groups(w, sc);
	return true;
}

/* Bounds of everything but planes, and the camera (for the lights). Each plane object gets its
 * own mesh, reaching from the camera to its horizon (prim_plane_view): what it shows depends on
 * the camera alone, not on the other objects. */
static bool build_planes(world *w, const scene *sc, const world_options *opt, diag *d)
{
	vec3 lo = v3s(FLT_MAX), hi = v3s(-FLT_MAX);
	for (size_t i = 0; i < w->n_insts; i++) {
		world_inst *in = &w->insts[i];
		const scene_object *o = scene_object_at(sc, i);
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
		const scene_object *o = scene_object_at(sc, i);
		world_inst *in = &w->insts[i];
		if (o->geom->kind != SHAPE_PLANE)
			continue;
		world_geom *own = &w->geoms[sc->n_geoms + i];
		vec3 at = d3v(xform_inv_point(&in->xf, eye));
		if (!prim_plane_view(d3v(o->geom->u.plane.normal), (float)o->geom->u.plane.offset, at,
				     WORLD_PLANE_HORIZON_RAD, &own->m)) {
			diag_error(d, o->geom->loc, d3_length(o->geom->u.plane.normal) == 0.0 ? "the plane's normal is zero"
											      : "out of memory while tessellating");
			return false;
		}
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
static bool build_top(world *w, diag *d)
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
		if (!in->g->b)
			continue;
		w->inst_top[i] = na;
		w->top_inst[na] = (uint32_t)i;
		all[na++] = (tlas_instance){in->g->b, in->xf, sss_set(w, i)};
		if (!in->no_shadow)
			casters[nc++] = (tlas_instance){in->g->b, in->xf, 0};
	}
	if (ok && na)
		ok = (w->top = tlas_build(all, na)) != NULL;
	if (ok && nc)
		ok = (w->shadow = tlas_build(casters, nc)) != NULL;
	mem_free(all), mem_free(casters);
	if (!ok)
		diag_error(d, diag_noloc(), "out of memory while building the top-level BVH");
	else
		w->stats.geometry_bytes += (w->top ? tlas_bytes(w->top) : 0) + (w->shadow ? tlas_bytes(w->shadow) : 0);
	return ok;
}

/* Adds an emissive instance as a mesh light over its world-space triangles. */
static bool add_mesh_light(world *w, world_inst *in, vec3 radiance, diag *d, diag_loc loc)
{
	const mesh *m = &in->g->m;
	vec3 *v = mem_alloc((size_t)m->num_triangles * 3, sizeof *v);
	if (!v) {
		diag_error(d, loc, "out of memory");
		return false;
	}
	for (size_t t = 0; t < (size_t)m->num_triangles * 3; t++) {
		vec3 p = m->positions[m->indices[t]];
		v[t] = in->identity ? p : d3v(xform_point(&in->xf, v3_to_d3(p)));
	}
	light l;
	bool ok = light_mesh_init(&l, v, m->num_triangles, radiance);
	mem_free(v);
	if (!ok)
		return true; /* zero area: it emits nothing */
	in->light = (int)w->lights.count;
	if (!light_set_add(&w->lights, &l)) {
		light_free(&l);
		diag_error(d, loc, "out of memory");
		return false;
	}
	return true;
}

static bool build_lights(world *w, const scene *sc, diag *d)
{
	light_set_init(&w->lights);
	for (size_t i = 0; i < scene_n_lights(sc); i++) {
		const scene_light *sl = scene_light_at(sc, i);
		vec3 c = v3_scale(sl->color, (float)sl->intensity);
		vec3 pos = d3v(sl->position), at = d3v(sl->point_at);
		light l;
		switch (sl->kind) {
		case SCENE_LIGHT_POINT:
			l = light_point(pos, c);
			break;
		case SCENE_LIGHT_SPHERE:
			l = light_sphere(pos, (float)sl->radius, c);
			break;
		case SCENE_LIGHT_SPOT:
			l = light_spot(pos, at, c, (float)sl->cone_deg, (float)sl->falloff_deg);
			break;
		default:
			l = light_parallel(pos, at, c);
			break;
		}
		if (!light_set_add(&w->lights, &l)) {
			diag_error(d, sl->loc, "out of memory");
			return false;
		}
	}
	if (sc->has_background) {
		light l = light_background(sc->background);
		if (!light_set_add(&w->lights, &l))
			return false;
	}
	if (sc->has_sky_sphere) {
		const scene_sky_sphere *sky = &sc->sky_sphere;
		const image *img = world_image(w, sky->loc, sky->image, IMAGE_SRGB, d);
		if (!img)
			return false;
		size_t n = (size_t)img->width * (size_t)img->height;
		w->env_rgb = mem_alloc(n, 3 * sizeof(float));
		if (!w->env_rgb) {
			diag_error(d, sky->loc, "out of memory");
			return false;
		}
		size_t clamped = clamp_texels(img, SCENE_COLOR_RADIANCE, w->env_rgb);
		if (clamped)
			diag_warning(d, sky->loc, "%zu texels of the environment are outside [0, inf), the range of a "
						  "radiance (negative, NaN or infinite): clamped, a non-finite one to 0",
				     clamped);
		xform rot = xform_rotate(sky->rotate_deg);
		light l;
		if (!light_envmap_init(&l, w->env_rgb, img->width, img->height, (float)sky->intensity, &rot) ||
		    !light_set_add(&w->lights, &l)) {
			diag_error(d, sky->loc, "out of memory");
			return false;
		}
	}
	for (size_t i = 0; i < w->n_insts; i++) {
		const scene_object *o = scene_object_at(sc, i);
		if (o->material && v3_max_comp(o->material->emission) > 0.0f &&
		    !add_mesh_light(w, &w->insts[i], o->material->emission, d, o->loc))
			return false;
	}
	/* The scene's own radius, however small: a floor in absolute units would weigh infinite and
	 * parallel lights against the others differently at different scales. */
	if (!light_set_finish(&w->lights, w->radius)) {
		diag_error(d, diag_noloc(), "out of memory");
		return false;
	}
	return true;
}

static bool build_camera(world *w, const scene *sc, const world_options *opt, diag *d)
{
	cam_params cp = cam_params_default();
	diag_loc loc = diag_noloc();
	if (sc->has_camera) {
		const scene_camera *c = &sc->camera;
		loc = c->loc;
		cp.location = c->location;
		cp.look_at = c->look_at;
		cp.sky = d3v(c->sky);
		cp.angle_deg = (float)c->angle_deg;
		/* POV-Ray's default right <1.33,0,0> is its 4:3 default image; circe fits the image
		 * instead, unless the scene sets another right. */
		bool default_right = c->right.x == 1.33 && c->right.y == 0.0 && c->right.z == 0.0;
		cp.right = default_right ? v3s(0.0f) : d3v(c->right);
		cp.up = d3v(c->up);
		cp.aperture = (float)c->aperture;
		cp.focal_point = c->has_focal_point ? c->focal_point : cp.look_at;
	}
	if (!cam_init(&w->camera, &cp, opt->width, opt->height)) {
		diag_error(d, loc, "the camera is degenerate (look_at at the location, sky along the view, or angle out of range)");
		return false;
	}
	return true;
}

bool world_build(world *w, const scene *sc, const world_options *opt, diag *d)
{
	memset(w, 0, sizeof *w);
	if (!assets_open(sc, d)) /* every named file, at its string, before any work */
		return false;
	light_set_init(&w->lights);
	world_options o = *opt;
	if (!o.max_memory)
		o.max_memory = SUBD_DEFAULT_MAX_BYTES;
	/* Room for the scene's geometry, a private mesh per object (used only when flattened, or for a
	 * plane), and the unit spheres. */
	w->unit_spheres = sc->n_geoms + scene_n_objects(sc);
	w->n_geoms = w->unit_spheres + PRIM_SPHERE_LEVELS;
	w->geoms = mem_calloc(w->n_geoms ? w->n_geoms : 1, sizeof *w->geoms);
	w->n_materials = sc->n_materials + 1;
	w->bsdfs = mem_calloc(w->n_materials, sizeof *w->bsdfs);
	w->materials = mem_calloc(w->n_materials, sizeof *w->materials);
	w->sss = mem_calloc(w->n_materials, sizeof *w->sss);
	w->sss_of = mem_calloc(w->n_materials, sizeof *w->sss_of);
	if (!w->geoms || !w->bsdfs || !w->materials || !w->sss || !w->sss_of) {
		diag_error(d, diag_noloc(), "out of memory");
		world_free(w);
		return false;
	}
	bool ok = true;
	for (const scene_geom *g = sc->geoms; g && ok; g = g->next)
		ok = build_geom(w, sc, g, &o, d);
	ok = ok && build_instances(w, sc, &o, d) && build_planes(w, sc, &o, d) && check_volumes(w, sc, &o, d);
	/* Normal maps need tangents; meshes without them get generated ones. */
	for (const scene_material *m = sc->materials; ok && m; m = m->next)
		ok = o.geometry_only || build_material(w, m->id, sc, &o, m, d);
	if (ok)
		w->bsdfs[w->n_materials - 1] = bsdf_diffuse(v3s(WORLD_DEFAULT_GREY));
	for (size_t i = 0; ok && !o.geometry_only && i < w->n_insts; i++) {
		world_inst *in = &w->insts[i];
		mesh *m = (mesh *)&in->g->m;
		if (w->materials[in->material].normal_map && !m->tangents && m->normals && m->uvs)
			ok = mesh_generate_tangents(m);
		if (!ok)
			diag_error(d, diag_noloc(), "out of memory while generating tangents");
	}
	for (size_t i = 0; i < w->n_geoms; i++) {
		world_geom *g = &w->geoms[i];
		w->stats.triangles += g->m.num_triangles;
		w->stats.geometry_bytes += mesh_bytes(&g->m);
		if (!ok || o.geometry_only || !g->m.num_triangles)
			continue;
		g->b = bvh_build(g->m.positions, g->m.num_vertices, g->m.indices, g->m.num_triangles);
		if (!g->b) {
			diag_error(d, diag_noloc(), "out of memory while building the BVH");
			ok = false;
		} else {
			w->stats.geometry_bytes += bvh_bytes(g->b);
		}
	}
	for (size_t i = 0; i < w->n_insts; i++)
		w->stats.instanced_triangles += w->insts[i].g->m.num_triangles;
	ok = ok && (o.geometry_only || build_top(w, d));
	ok = ok && (o.geometry_only || (build_lights(w, sc, d) && build_camera(w, sc, &o, d)));
	if (!ok) {
		world_free(w);
		return false;
	}
	w->rs = (render_scene){.user = w, .intersect = world_intersect, .occluded = world_occluded,
			       .shade = world_shade, .materials = w->bsdfs, .material_count = w->n_materials,
			       .lights = &w->lights, .sss = w->has_sss ? w->sss_of : NULL, .circle = world_circle,
			       .circle_surface = world_circle_surface,
			       .sss_closest = world_sss_closest};
	return true;
}

void world_free(world *w)
{
	for (size_t i = 0; w->geoms && i < w->n_geoms; i++) {
		mesh_free(&w->geoms[i].m);
		bvh_free(w->geoms[i].b);
	}
	for (size_t i = 0; i < w->n_images; i++) {
		image_free(w->images[i]);
		mem_free(w->images[i]);
		mem_free(w->image_paths[i]);
	}
	light_set_free(&w->lights);
	tlas_free(w->top), tlas_free(w->shadow);
	mem_free(w->top_inst), mem_free(w->inst_top), mem_free(w->sss_group), mem_free(w->sss_next);
	mem_free(w->sss), mem_free(w->sss_of);
	mem_free(w->geoms), mem_free(w->insts), mem_free(w->bsdfs), mem_free(w->materials);
	mem_free(w->images), mem_free(w->image_paths), mem_free(w->env_rgb);
	memset(w, 0, sizeof *w);
}
