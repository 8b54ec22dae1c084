/* build_sss.c - what subsurface scattering adds to the build: each SSS material's BSSRDF, the
 * closed-volume check of the volume method, and the SSS groups of instances. */
#include "build/build_impl.h"

#include "base/mem.h"
#include "scene/pattern.h"
#include "sss/medium.h"
#include "sss/profile.h"
#include "sss/walk.h"

#include <math.h>
#include <string.h>

bool is_sss(const scene_material *m)
{
	return m && (m->kind == MAT_SKIN || m->kind == MAT_WAX || m->kind == MAT_MARBLE || m->pov_sss);
}

sss_method sss_method_of(const scene_material *m, const world_options *opt)
{
	sss_method s = opt->sss_method != SSS_METHOD_DEFAULT ? opt->sss_method : m->sss.method;
	return s == SSS_METHOD_DEFAULT ? SSS_METHOD_CIRCLE : s;
}

/* The points a patterned pigment's mean is taken over: a Halton set in [-POV_SSS_MEAN_HALF,
 * POV_SSS_MEAN_HALF]^3 of the pattern's object space: patterns of POV-Ray's scales (1, or a few
 * units as subsurface.pov's checker of 4) repeat many times within it; deterministic. */
#define POV_SSS_MEAN_POINTS 1024
#define POV_SSS_MEAN_HALF 10.0

static double halton(uint32_t i, uint32_t base)
{
	double f = 1.0, r = 0.0;
	for (; i; i /= base) {
		f /= base;
		r += f * (double)(i % base);
	}
	return r;
}

/* The diffuse reflectance a POV-Ray subsurface texture's medium is derived at: pigment * Kd,
 * the pigment's mean over POV_SSS_MEAN_POINTS points when it is a pattern (the entry points'
 * own pigment then scales each weight by pigment / mean: integrator.c's colour blurring). */
static vec3 pov_sss_reflectance(const world *w, const world_material *wm, const scene_material *sm)
{
	vec3 c = sm->color;
	if (wm->has_pattern) {
		dvec3 sum = d3(0, 0, 0);
		for (uint32_t i = 1; i <= POV_SSS_MEAN_POINTS; i++) {
			dvec3 q = d3_scale(d3(2 * halton(i, 2) - 1, 2 * halton(i, 3) - 1, 2 * halton(i, 5) - 1),
					   POV_SSS_MEAN_HALF);
			float o[5];
			pattern_eval(&w->patterns, wm->pattern, q, 0.0, o);
			vec3 rgb = v3(o[0], o[1], o[2]);
			scene_color_clamp(&rgb, SCENE_COLOR_REFLECTANCE);
			sum = d3_add(sum, v3_to_d3(rgb));
		}
		c = d3v(d3_scale(sum, 1.0 / POV_SSS_MEAN_POINTS));
	}
	scene_color_clamp(&c, SCENE_COLOR_REFLECTANCE);
	return v3_scale(c, fminf(sm->diffuse, 1.0f));
}

/* POV-Ray's subsurface texture as circe's artist form (doc/language.md "POV-Ray's subsurface"):
 * the albedo is POV-Ray's diffuse reflectance rd, the radius the l_d of POV-Ray's own medium for
 * rd and the translucency (sss_pov_translucency_radius_mm). */
static sss_medium_spec pov_sss_spec(const scene_material *sm, vec3 rd)
{
	const float rdc[3] = {rd.x, rd.y, rd.z};
	const vec3 t = sm->finish.translucency_mm;
	const float tc[3] = {t.x, t.y, t.z};
	float ld[3];
	for (int c = 0; c < 3; c++)
		ld[c] = (float)sss_pov_translucency_radius_mm(rdc[c], tc[c], sm->sss.ior);
	return (sss_medium_spec){.form = SSS_FORM_ARTIST, .has = SSS_HAS_ALBEDO | SSS_HAS_RADIUS, .albedo = rd,
				 .radius_mm = v3(ld[0], ld[1], ld[2])};
}

/* Both forms of an SSS material's medium, from what the scene wrote: the one derivation
 * (sss/medium.h), at build time. A POV-Ray subsurface texture's is pov_sss_spec's, whose
 * reflectance the build kept in the material's render_sss (k its index). */
static sss_medium medium_of(const world *w, size_t k, const scene_material *m)
{
	sss_medium md;
	sss_medium_spec spec = m->sss.medium;
	if (m->pov_sss)
		spec = pov_sss_spec(m, w->sss[k].albedo);
	sss_medium_derive(&spec, m->sss.ior, &md);
	return md;
}

/* The BSSRDF of an SSS material: the medium derived from what the scene wrote, its profile from
 * the artist form (the albedo the coat shows and a texture scales), the method (the command
 * line's over the material's), and f_t's normalisation. */
bool build_sss(world *w, size_t k, const scene *sc, const world_options *opt, const scene_material *sm,
		      diag *d)
{
	const scene_sss *ss = &sm->sss;
	render_sss *r = &w->sss[k];
	if (sm->pov_sss)
		r->albedo = pov_sss_reflectance(w, &w->materials[k], sm);
	sss_medium md = medium_of(w, k, sm);
	if (!sss_profile_from_artist(&r->profile, ss->profile, md.albedo, md.ld_mm, ss->ior)) {
		diag_error(d, sm->loc, "the subsurface medium is out of range (albedo %g %g %g, radius %g %g %g mm, ior %g)",
			   md.albedo[0], md.albedo[1], md.albedo[2], md.ld_mm[0], md.ld_mm[1], md.ld_mm[2], (double)ss->ior);
		return false;
	}
	r->method = sss_method_of(sm, opt);
	r->units_per_mm = (float)(1.0 / sc->global.mm_per_unit);
	/* The walk's medium from the physical form of the same derivation: the coefficients the
	 * profile's albedo comes from, so volume against the profiles measures the diffusion
	 * models' error and nothing else. */
	const double *ss_mm = md.sigma_s_per_mm, *sa_mm = md.sigma_a_per_mm;
	bool walks = r->method == SSS_METHOD_VOLUME || r->method == SSS_METHOD_AUTO;
	if (walks &&
	    !sss_walk_medium_from_reduced(&r->medium, ss_mm, sa_mm, ss->anisotropy, ss->ior, sc->global.mm_per_unit)) {
		diag_error(d, sm->loc, "the subsurface medium is out of range for the %s method (sigma_s' %g %g %g, "
				       "sigma_a %g %g %g per mm, anisotropy %g, ior %g)",
			   sss_method_name(r->method), ss_mm[0], ss_mm[1], ss_mm[2], sa_mm[0], sa_mm[1], sa_mm[2], (double)ss->anisotropy,
			   (double)ss->ior);
		return false;
	}
	r->ior = ss->ior;
	/* auto's length: the largest channel's diffuse mean free path, in scene units (the walk is
	 * taken where the object is a few of them thick; check_volumes turns it off on open objects) */
	double ld = fmax(md.ld_mm[0], fmax(md.ld_mm[1], md.ld_mm[2]));
	r->auto_ld = (float)(ld * r->units_per_mm);
	r->auto_walk = r->method == SSS_METHOD_AUTO && !r->auto_open; /* check_volumes ran first */
	if (r->method == SSS_METHOD_AUTO && !sss_auto_slab_make(&r->auto_slab, ss_mm, sa_mm, ss->ior))
		r->auto_walk = false; /* no extinction: sss_walk_medium_from_reduced refused it above */
	/* the profile's tail (sss/medium.h): where the object is thinner than that, the walk whatever
	 * the light; never beyond the thickness ray's reach */
	double reach_mm = SSS_AUTO_CIRCLE_ABOVE * ld;
	r->auto_tail_walk = (float)(fmin(reach_mm, sss_auto_tail_thickness(&r->profile, SSS_AUTO_TAIL_WALK)) * r->units_per_mm);
	r->auto_tail_circle =
		(float)(fmin(reach_mm, sss_auto_tail_thickness(&r->profile, SSS_AUTO_TAIL_CIRCLE)) * r->units_per_mm);
	/* f_t's c (DESIGN.md): integral of (1 - F(mu)) mu dmu over the outside hemisphere, times 2,
	 * is 1 - 2 FM1(eta) with FM1 of light arriving from outside (sss_fresnel_moment1's eta =
	 * n_inside / n_outside); DESIGN.md writes FM1(1/eta) in pbrt's opposite convention. */
	r->entry_norm = (float)(1.0 / (1.0 - 2.0 * sss_fresnel_moment1(ss->ior)));
	r->albedo = v3((float)md.albedo[0], (float)md.albedo[1], (float)md.albedo[2]);
	if (sm->pov_sss) { /* POV-Ray's brightness: the weight's tex / albedo becomes tex * gain / albedo
			    * (k 2 on open objects until build_pov_probe measures it) */
		r->pov_k = r->pov_open ? 2.0f : 1.0f;
		r->albedo = v3((float)(md.albedo[0] / sss_pov_gain(md.albedo[0], ss->ior, r->pov_k)),
			       (float)(md.albedo[1] / sss_pov_gain(md.albedo[1], ss->ior, r->pov_k)),
			       (float)(md.albedo[2] / sss_pov_gain(md.albedo[2], ss->ior, r->pov_k)));
	}
	/* A POV-Ray subsurface texture's weight is always its entry's b->diffuse / albedo: its
	 * pigment there, and the finish's scale that keeps the lobes and the BSSRDF within 1. */
	r->textured = ss->albedo_image != NULL || ss->pigment != NULL || sm->pigment != NULL || sm->pov_sss;
	w->sss_of[k] = r;
	w->has_sss = true;
	return true;
}

/* A walk's length grows like the square of the object's size in transport mean free paths
 * (diffusion), capped by absorption at about sigma_t'/sigma_a interactions. When the smaller of
 * the two exceeds the walk's step bound most long walks will be dropped (dark, counted): say so
 * before the render rather than after. High albedos given in the artist form are the usual cause
 * (albedo 1 needs sigma_a = 0, so the inversion makes sigma_s' very large). */
static void warn_dense_medium(const world *w, const world_inst *in, const scene *sc, const scene_object *o,
			      diag *d)
{
	sss_medium md = medium_of(w, (size_t)in->material, o->material);
	double size_mm = v3_length(v3_sub(in->hi, in->lo)) * sc->global.mm_per_unit, worst = 0.0;
	const double *s_s = md.sigma_s_per_mm, *s_a = md.sigma_a_per_mm;
	for (int c = 0; c < 3; c++) {
		double st = s_s[c] + s_a[c], tau = st * size_mm;
		double steps = fmin(tau * tau, s_a[c] > 0.0 ? st / s_a[c] : INFINITY);
		worst = fmax(worst, steps);
	}
	if (worst > SSS_WALK_MAX_STEPS)
		diag_warning(d, o->loc,
			     "the volume method's walks in this object need about %.3g interactions (its medium is "
			     "dense for its size and hardly absorbs); walks stop at %d, and those are dropped and "
			     "counted",
			     worst, SSS_WALK_MAX_STEPS);
}

/* The closure of the SSS pieces of instance i's mesh (mesh2's texture_list, world_inst.n_pieces,
 * those of its SSS volume: piece_groups) taken together, one mesh of their triangles. */
static sss_mesh_closure pieces_closure(const world *w, size_t i, uint64_t *open_edges)
{
	const world_inst *in = &w->insts[i];
	size_t nv = 0, nt = 0;
	for (size_t j = in->piece0; j < in->piece0 + in->n_pieces; j++)
		if (w->sss_group[j] == w->sss_group[i])
			nv += w->insts[j].g->m.num_vertices, nt += w->insts[j].g->m.num_triangles;
	if (nv > UINT32_MAX || nt > UINT32_MAX / 3)
		return SSS_MESH_NO_MEMORY;
	mesh all = {.num_vertices = (uint32_t)nv, .num_triangles = (uint32_t)nt};
	all.positions = mem_alloc(nv ? nv : 1, sizeof *all.positions);
	all.indices = mem_alloc(nt ? nt : 1, 3 * sizeof *all.indices);
	sss_mesh_closure c = SSS_MESH_NO_MEMORY;
	if (all.positions && all.indices) {
		uint32_t v0 = 0, t0 = 0;
		for (size_t j = in->piece0; j < in->piece0 + in->n_pieces; j++) {
			const mesh *m = &w->insts[j].g->m;
			if (w->sss_group[j] != w->sss_group[i])
				continue;
			memcpy(all.positions + v0, m->positions, m->num_vertices * sizeof *m->positions);
			for (size_t k = 0; k < 3 * (size_t)m->num_triangles; k++)
				all.indices[3 * (size_t)t0 + k] = m->indices[k] + v0;
			v0 += m->num_vertices, t0 += m->num_triangles;
		}
		c = sss_walk_mesh_closure(&all, open_edges);
	}
	mem_free(all.positions), mem_free(all.indices);
	return c;
}

/* Whether instance i's mesh is closed (sss_walk_mesh_closure), cached per mesh in closed[] (0
 * unknown, 1 closed, -1 open): 1, 0, or -1 out of memory. A piece of a mesh placed in pieces
 * that is one SSS volume with the others is closed when they are together (pieces_closure).
 * *open_edges (when not NULL) says how many edges are open where this call checked them. */
static int mesh_closed(const world *w, size_t i, int8_t *closed, uint64_t *open_edges)
{
	size_t gi = (size_t)(w->insts[i].g - w->geoms);
	if (open_edges)
		*open_edges = 0;
	if (!closed[gi]) {
		uint64_t open = 0;
		const world_inst *in = &w->insts[i];
		bool pieces = in->n_pieces && w->sss_group[i] >= 0 && (size_t)w->sss_group[i] >= in->piece0 &&
			      (size_t)w->sss_group[i] < in->piece0 + in->n_pieces;
		sss_mesh_closure c = pieces ? pieces_closure(w, i, &open) : sss_walk_mesh_closure(&in->g->m, &open);
		if (c == SSS_MESH_NO_MEMORY)
			return -1;
		closed[gi] = c == SSS_MESH_CLOSED ? 1 : -1;
		if (open_edges)
			*open_edges = open;
	}
	return closed[gi] > 0;
}

/* Whether a CSG item (a node >= 0, an instance -1 - i) is a bounded solid, as POV-Ray's subsurface
 * probe rays from inside it find: every one meets its surface (1), or some leave it unmet (0: a
 * plane, an open mesh, an inverse, a clipped solid); -1 out of memory. An intersection is bounded
 * when one operand is, a union or merge when all are, a difference when its base is. */
static int pov_bounded(const world *w, int32_t item, int8_t *closed)
{
	if (item < 0) {
		const world_inst *in = &w->insts[-1 - item];
		if (in->hidden || in->csg_inverse || in->inside_kind == WORLD_INSIDE_PLANE)
			return 0;
		return mesh_closed(w, (size_t)(-1 - item), closed, NULL);
	}
	const world_csg_node *n = &w->csg_nodes[item];
	if (n->inverse)
		return 0;
	bool any = false, all = true;
	for (uint32_t k = n->first; k < n->first + n->count; k++) {
		const world_csg_kid *kid = &w->csg_kids[k];
		if (kid->item < 0 && w->insts[-1 - kid->item].hidden)
			return 0; /* clipped_by: the cut leaves a hole */
		if (n->op == SCENE_CSG_DIFFERENCE && kid->operand != 0)
			continue;
		int b = pov_bounded(w, kid->item, closed);
		if (b < 0)
			return -1;
		any = any || b, all = all && b;
	}
	return n->op == SCENE_CSG_INTERSECTION ? any : all;
}

/* POV-Ray's subsurface brightness depends on whether its objects are bounded (sss_pov_gain's k):
 * render_sss.pov_open of every POV-Ray subsurface texture on an unbounded object, the whole CSG
 * solid's when it is in one. A texture on both kinds takes the open one's, and says so. */
static bool mark_pov_open(world *w, const scene *sc, int8_t *closed, diag *d)
{
	uint8_t *seen = mem_calloc(w->n_materials, 1); /* per material: 1 an object seen, 2 mixed said */
	if (!seen) {
		diag_error(d, diag_noloc(), "out of memory");
		return false;
	}
	bool ok = true;
	for (size_t i = 0; i < w->n_insts && ok; i++) {
		const scene_object *o = scene_object_at(sc, w->insts[i].object);
		if (!is_sss(o->material) || !o->material->pov_sss || w->insts[i].hidden)
			continue;
		int32_t item = -1 - (int32_t)i;
		for (int32_t p = w->insts[i].csg_parent; p >= 0; p = w->csg_nodes[p].parent)
			item = p;
		int b = pov_bounded(w, item, closed);
		if (b < 0) {
			diag_error(d, o->loc, "out of memory while checking that the object is closed");
			ok = false;
			break;
		}
		size_t k = (size_t)w->insts[i].material;
		render_sss *r = &w->sss[k]; /* built after this check */
		if ((seen[k] & 1) && r->pov_open != !b && !(seen[k] & 2)) {
			diag_warning(d, o->loc, "this subsurface texture is on both open and closed objects: POV-Ray "
						"shows it about twice as bright on the open ones, circe on all of them; give "
						"each kind its own texture (said once per texture)");
			seen[k] |= 2;
		}
		r->pov_open = r->pov_open || !b;
		seen[k] |= 1;
	}
	mem_free(seen);
	return ok;
}

/* POV-Ray's probe factor, measured as POV-Ray's probe rays meet the scene (pov_probe_factors):
 * POV_PROBE_GRID^2 camera rays over the image, and at each exit point they find on an open
 * object of a POV-Ray subsurface texture POV_PROBE_DIRS rays, uniform over the sphere, from the
 * base point POV-Ray takes (its average free path 1/sigma_t' behind the surface, on the side away
 * from the eye: trace.cpp ComputeDiffuseSampleBase). Deterministic (Halton directions). */
#define POV_PROBE_GRID 32
#define POV_PROBE_DIRS 64

/* The base point's depth below the surface, in scene units: POV-Ray's 1/sigma_t' of the
 * luminance-weighted coefficients (its greyscale of sigma_a plus that of sigma_s'), sigma_s' =
 * 1/T, sigma_t' = sigma_s' / alpha' (ComputeSubsurfaceScattering). */
static double pov_probe_depth(const render_sss *r, const scene_material *sm, double mm_per_unit)
{
	const vec3 t = sm->finish.translucency_mm;
	const double tc[3] = {t.x, t.y, t.z}, wl[3] = {0.2126, 0.7152, 0.0722};
	double st = 0.0;
	for (int c = 0; c < 3; c++)
		st += wl[c] / (tc[c] * fmax(sss_pov_alpha_prime(r->profile.ch[c].albedo, sm->sss.ior), 1e-9));
	return 1.0 / (st * mm_per_unit);
}

/* POV-Ray's diffuse estimate averages over its probe rays that meet any surface (trace.cpp
 * ComputeSubsurfaceScattering: trueNumSamples), each weighted for the whole sphere, so where a
 * fraction P of them meets something its estimate is 1/P times the dipole's integral: k = 1/P,
 * 2 under a plane with nothing below it, less where the rays that leave an open object's back
 * meet other objects (a disc standing on a floor). The factor of each POV-Ray subsurface texture
 * on open objects is P's mean over its exit points the camera sees (1/P held to [1, 4]), and its
 * weights' albedo is set from it (render_sss.albedo, sss_pov_gain); a texture the camera does not
 * see keeps k = 2. Run once the world can be traced. */
bool build_pov_probe(world *w, const scene *sc, diag *d)
{
	bool any = false;
	for (size_t k = 0; k < w->n_materials; k++)
		any = any || (w->sss_of[k] && w->sss[k].pov_open);
	if (!any)
		return true;
	size_t n_obj = scene_n_objects(sc);
	int8_t *closed = mem_calloc(w->n_geoms ? w->n_geoms : 1, 1);
	int8_t *open_obj = mem_calloc(n_obj ? n_obj : 1, 1); /* per scene object: 1 open, -1 bounded */
	double *hits = mem_calloc(w->n_materials, sizeof *hits), *rays = mem_calloc(w->n_materials, sizeof *rays);
	bool ok = closed && open_obj && hits && rays;
	for (size_t i = 0; ok && i < w->n_insts; i++) {
		const world_inst *in = &w->insts[i];
		if (in->hidden || !w->sss_of[in->material] || !w->sss[in->material].pov_open || in->object >= n_obj)
			continue;
		int32_t item = -1 - (int32_t)i;
		for (int32_t p = in->csg_parent; p >= 0; p = w->csg_nodes[p].parent)
			item = p;
		int b = pov_bounded(w, item, closed);
		ok = b >= 0;
		open_obj[in->object] = b ? -1 : 1;
	}
	if (!ok) {
		diag_error(d, diag_noloc(), "out of memory");
		goto done;
	}
	const render_scene *rs = &w->rs;
	const cam *c = &w->camera;
	uint32_t seq = 0;
	for (int gy = 0; gy < POV_PROBE_GRID; gy++)
		for (int gx = 0; gx < POV_PROBE_GRID; gx++) {
			/* the same image points at every resolution: pixel and offset of (gx + 1/2) / grid */
			double fx = (gx + 0.5) * c->width / POV_PROBE_GRID, fy = (gy + 0.5) * c->height / POV_PROBE_GRID;
			int px = (int)fx, py = (int)fy;
			render_ray ray;
			render_hit hit = {0};
			if (!cam_sample(c, px, py, v2((float)(fx - px), (float)(fy - py)), v2(0.5f, 0.5f), &ray) ||
			    !rs->intersect(rs->user, &ray, 0.0f, c->max_distance > 0.0f ? c->max_distance : INFINITY, &hit) || hit.material < 0 ||
			    hit.object >= n_obj || open_obj[hit.object] != 1)
				continue;
			size_t k = (size_t)hit.material;
			const scene_material *sm = scene_object_at(sc, hit.object)->material;
			if (!w->sss_of[k] || !sm || !sm->pov_sss)
				continue;
			double depth = pov_probe_depth(&w->sss[k], sm, sc->global.mm_per_unit);
			/* behind the surface: the side away from the eye */
			vec3 n = v3_dot(hit.ng, ray.d) > 0.0f ? hit.ng : v3_neg(hit.ng);
			vec3 base = v3_add(hit.p, v3_scale(n, (float)depth));
			for (int j = 0; j < POV_PROBE_DIRS; j++, seq++) {
				double z = 1.0 - 2.0 * halton(seq + 1, 2), phi = 2.0 * M_PI * halton(seq + 1, 3);
				double s = sqrt(fmax(0.0, 1.0 - z * z));
				render_ray probe = {base, v3((float)(s * cos(phi)), (float)(s * sin(phi)), (float)z)};
				render_hit ph = {0};
				hits[k] += rs->intersect(rs->user, &probe, (float)(1e-3 * depth), INFINITY, &ph);
				rays[k] += 1.0;
			}
		}
	for (size_t k = 0; k < w->n_materials; k++) {
		if (!(rays[k] > 0.0))
			continue;
		render_sss *r = &w->sss[k];
		double f = fmin(fmax(rays[k] / fmax(hits[k], 1.0), 1.0), 4.0);
		r->pov_k = (float)f;
		double a[3];
		for (int ch = 0; ch < 3; ch++) {
			double rd = r->profile.ch[ch].albedo;
			a[ch] = rd / sss_pov_gain(rd, r->ior, f);
		}
		r->albedo = v3((float)a[0], (float)a[1], (float)a[2]);
	}
done:
	mem_free(closed), mem_free(open_obj), mem_free(hits), mem_free(rays);
	return ok;
}

/* The volume method walks inside the object: an SSS object rendered by it must bound a volume
 * (sss_walk_mesh_closure), else light would leave through the holes. Checked once per mesh; a
 * POV-Ray subsurface texture's objects too, under every method (mark_pov_open). */
bool check_volumes(world *w, const scene *sc, const world_options *opt, diag *d)
{
	bool ok = true;
	int8_t *closed = mem_calloc(w->n_geoms ? w->n_geoms : 1, 1); /* 0 unknown, 1 closed, -1 open */
	if (!closed) {
		diag_error(d, diag_noloc(), "out of memory");
		return false;
	}
	if (!mark_pov_open(w, sc, closed, d)) {
		mem_free(closed);
		return false;
	}
	for (size_t i = 0; i < w->n_insts; i++) {
		const scene_object *o = scene_object_at(sc, w->insts[i].object);
		sss_method method = is_sss(o->material) ? sss_method_of(o->material, opt) : SSS_METHOD_DEFAULT;
		if (method != SSS_METHOD_VOLUME && method != SSS_METHOD_AUTO)
			continue;
		const world_geom *g = w->insts[i].g;
		size_t gi = (size_t)(g - w->geoms);
		uint64_t open_edges = 0;
		if (mesh_closed(w, i, closed, &open_edges) < 0) {
			diag_error(d, o->loc, "out of memory while checking that the object is closed");
			ok = false;
			break;
		}
		if (closed[gi] < 0 && method == SSS_METHOD_AUTO) {
			/* auto walks only where the object is thin; an open one holds no volume to walk
			 * in, so its material keeps to circle tracing (said once per material) */
			render_sss *r = &w->sss[w->insts[i].material]; /* built after this check */
			if (!r->auto_open)
				diag_warning(d, o->loc, "the auto SSS method walks only in closed objects, and this one %s: "
							"its material uses circle tracing everywhere",
					     o->geom->kind == SHAPE_PLANE ? "is a plane" : "is open");
			r->auto_open = true;
		} else if (closed[gi] < 0) {
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
		} else if (method == SSS_METHOD_VOLUME) {
			warn_dense_medium(w, &w->insts[i], sc, o, d);
		}
	}
	mem_free(closed);
	return ok;
}

/* The SSS volume of each instance: alone (-1), or the first instance of its material's group.
 * The one record of membership: the top level's set of each instance is sss_set's, and both SSS
 * queries (circles, nearest hits) find a group's members through it. */
void build_groups(world *w, const scene *sc)
{
	for (size_t i = 0; i < w->n_insts; i++) {
		const scene_material *m = scene_object_at(sc, w->insts[i].object)->material;
		w->sss_group[i] = -1;
		for (size_t j = 0; is_sss(m) && m->sss.group && j <= i; j++) {
			const scene_material *mj = scene_object_at(sc, w->insts[j].object)->material;
			if (is_sss(mj) && mj->sss.group && !strcmp(mj->sss.group, m->sss.group)) {
				w->sss_group[i] = (int)j;
				break;
			}
		}
	}
}

const char *world_sss_method(const world *w)
{
	const char *name = "none";
	for (size_t i = 0; i < w->n_materials; i++) {
		if (!w->sss_of[i])
			continue;
		const char *m = sss_method_name(w->sss_of[i]->method);
		if (strcmp(name, "none") && strcmp(name, m))
			return "mixed";
		name = m;
	}
	return name;
}
