/* world.c - the integrator's callbacks over a built world (build/): intersect, occluded,
 * circle, sss_closest and shade, and the hit record they fill. */
#include "render/world.h"

#include "render/bsdf_pov.h"

#include "accel/offset.h"
#include "render/shading.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

/* How many float ulps of its triangle's scale a hit position may be off (the interpolation of
 * three rounded vertices and a transform): the tolerance of a pattern's cell boundaries. */
#define PATTERN_HIT_ULPS 16.0
/* The entries of a patterned texture with layered entries one hit blends at most: an average's
 * every one (another pattern blends two). */
#define WORLD_MAP_PICKS PATTERN_MAX_ENTRIES

static vec3 d3v(dvec3 v) { return d3_to_v3(v); }

/* A normal and a vector of instance `in`'s object space in world space. */
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
	if (in->csg_flip) /* the instance bounds its CSG solid from outside (world_csg.c) */
		ng = v3_neg(ng), ns = v3_neg(ns);
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
	int material = in->material;
	if (in->part_material && in->g->tri_part && in->g->tri_part[prim] <= in->n_parts)
		material = in->part_material[in->g->tri_part[prim]]; /* a blob component's texture */
	*hit = (render_hit){.p = p, .ng = ng, .ns = ns, .uv = uv, .material = material, .light = in->light,
			    .object = inst, .prim = prim, .bary = v2(u, v), .scale = scale};
}

/* render_scene.intersect: the nearest hit on any instance, through the top-level BVH. */
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
uint32_t sss_set(const world *w, size_t i)
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
	uint32_t kept = 0;
	for (uint32_t i = 0; i < n; i++) {
		vec3 ns;
		tri_circle_hit h = hits[i];
		h.inst = w->top_inst[h.inst];
		/* A CSG solid's circle hits are those on its boundary, as its rays' (world_csg.c). */
		if (w->insts[h.inst].csg_filtered && !world_csg_keep(w, h.inst, h.pos))
			continue;
		hit_normals(&w->insts[h.inst], h.prim, h.u, h.v, &h.ng, &ns);
		hits[kept++] = h;
	}
	return kept;
}

static void world_circle_surface(void *user, const tri_circle_hit *h, render_hit *hit)
{
	fill_hit(user, h->inst, h->prim, h->u, h->v, hit);
	hit->p = h->pos;
}

/* No SSS ray steps over more hits of a CSG operand off its solid's boundary than this. */
#define RENDER_CSG_SKIPS 4096

/* The nearest hit of a ray on the SSS volume of `at`: its instance alone (the ray moved into its
 * object space: t is kept, the direction not being renormalised), or the members of its group,
 * found by the top level through the group's set (sss_set), as world_circle finds them. */
static bool world_sss_closest(void *user, const render_hit *at, const render_ray *ray, float tmin, float tmax,
			      render_hit *hit)
{
	const world *w = user;
	if (!w->top || at->object >= w->n_insts)
		return false;
	bvh_ray r = {ray->o, ray->d, tmin, tmax};
	bvh_hit best;
	uint32_t inst;
	if (w->sss_group[at->object] >= 0) {
		if (!tlas_intersect_set(w->top, &r, sss_set(w, at->object), &best))
			return false;
		inst = w->top_inst[best.inst];
	} else {
		const world_inst *in = &w->insts[at->object];
		if (!in->g->b)
			return false;
		if (!in->identity) {
			r.org = d3v(xform_inv_point(&in->xf, v3_to_d3(ray->o)));
			r.dir = d3v(xform_inv_vector(&in->xf, v3_to_d3(ray->d)));
		}
		for (int k = 0;; k++) { /* a CSG operand: the next hit on the solid's boundary */
			if (k == RENDER_CSG_SKIPS || !bvh_intersect(in->g->b, &r, &best))
				return false;
			if (!in->csg_filtered)
				break;
			bvh_hit keyed = best;
			if (world_csg_filter((void *)w, (uint32_t)at->object, &r, &keyed))
				break;
			r.tmin = nextafterf(best.t, INFINITY);
		}
		inst = at->object;
	}
	fill_hit(w, inst, best.prim, best.u, best.v, hit);
	hit->t = best.t;
	return true;
}

/* render_scene.sss_nearest: the distance from p to the SSS volume of `at` (its group's
 * instances through the top level, or its own mesh), a lower bound, capped. A CSG operand's
 * boundary is a part of its mesh, so the mesh's distance bounds it too. */
static float world_sss_nearest(void *user, const render_hit *at, vec3 p, float cap)
{
	const world *w = user;
	if (!w->top || at->object >= w->n_insts)
		return 0.0f;
	if (w->sss_group[at->object] >= 0)
		return tlas_nearest_set(w->top, p, sss_set(w, at->object), cap);
	const world_inst *in = &w->insts[at->object];
	if (!in->g->b)
		return cap;
	if (in->identity)
		return bvh_nearest(in->g->b, p, cap);
	double sc;
	if (!xform_is_similarity(&in->xf, &sc) || !(sc > 0.0))
		return 0.0f; /* no ball: the walk casts */
	const double slack = 1.0 - 1e-5; /* the transform's rounding */
	vec3 q = d3v(xform_inv_point(&in->xf, v3_to_d3(p)));
	float d = bvh_nearest(in->g->b, q, (float)((double)cap / (sc * slack)));
	return (float)fmin((double)cap, d * sc * slack);
}

/* render_scene.occluded: any hit on an instance that casts shadows (not no_shadow). */
static bool world_occluded(void *user, const render_ray *ray, float tmin, float tmax)
{
	const world *w = user;
	bvh_ray r = {ray->o, ray->d, tmin, tmax};
	return w->shadow && tlas_occluded(w->shadow, &r);
}

/* No shadow ray steps over more no_shadow surfaces than this (then it finds nothing). */
#define RENDER_SHADOW_SKIPS 64

/* render_scene.shadow_closest: the nearest hit of world_intersect on an instance that casts
 * shadows (no_shadow ones are stepped over, along the same ray). */
static bool world_shadow_closest(void *user, const render_ray *ray, float tmin, float tmax, render_hit *hit)
{
	const world *w = user;
	for (int k = 0; k < RENDER_SHADOW_SKIPS; k++) {
		if (!world_intersect(user, ray, tmin, tmax, hit))
			return false;
		if (hit->object >= w->n_insts || !w->insts[hit->object].no_shadow)
			return true;
		tmin = nextafterf(hit->t, INFINITY);
	}
	return false;
}

/* render_scene.light_reach: POV-Ray's light_group (the object's group, or one around it, is the
 * light's; a global light lights a grouped object only under its outermost group's
 * global_lights) and projected_through (the light's objects met along the shadow ray before
 * *tmax: *tmax becomes the distance to the first). Lights past the scene's light_sources (the
 * sky, emissive objects) are global. */
static bool world_light_reach(void *user, uint32_t object, size_t light, const render_ray *ray, float *tmax)
{
	const world *w = user;
	if (light >= w->n_reach)
		return true;
	const world_reach *r = &w->reach[light];
	uint32_t g = object < w->n_insts ? w->insts[object].light_group : 0;
	if (r->group) {
		while (g && g != r->group)
			g = w->group_parent[g - 1];
		if (!g)
			return false;
	} else if (g) {
		while (w->group_parent[g - 1])
			g = w->group_parent[g - 1];
		if (!w->group_global[g - 1])
			return false;
	}
	if (r->through && ray) {
		const render_scene *ts = &r->through->rs;
		render_hit h;
		memset(&h, 0, sizeof h);
		if (!ts->intersect(ts->user, ray, 0.0f, *tmax, &h))
			return false;
		*tmax = h.t;
	}
	return true;
}

/* The five channels of pattern node `node` at the hit, in its object's space (the scene's
 * placement undone, whatever the instance's mesh transform) or at <u, v, 0> with uv_mapping; ns
 * the normal slope sees. */
static void pattern_at_hit(const world *w, const render_hit *hit, uint32_t node, bool uv, vec3 ns, float c[5])
{
	const world_inst *in = &w->insts[hit->object];
	dvec3 p = uv ? d3(hit->uv.x, hit->uv.y, 0.0) : xform_inv_point(&in->pattern_xf, v3_to_d3(hit->p));
	/* The hit is a float position: rounding of a few ulps of the triangle's scale, through the
	 * object's inverse placement. uv coordinates are floats of their own size (at most ~1). */
	double tol = uv ? PATTERN_HIT_ULPS * FLT_EPSILON
			: PATTERN_HIT_ULPS * FLT_EPSILON * fmax(hit->scale, 1e-30) * pattern_inv_gain(&in->pattern_xf);
	pattern_surface sf = {v3_to_d3(ns), v3_to_d3(hit->p)}; /* slope's: the world normal, perturbed */
	pattern_eval_at(&w->patterns, node, p, &sf, tol, c);
}

/* A POV-Ray pigment at the hit: the diffuse colour, clamped to a reflectance. A texture whose
 * pattern carries filter or transmit (bsdf_clear.patterned) takes the point's: its transparent
 * part lets pigment * filter + transmit through and its diffuse is scaled by the opacity
 * 1 - filter - transmit, as a plain colour's (build_material.c build_clear). */
static void shade_pattern(const world *w, const world_material *wm, const render_hit *hit, vec3 ns,
			  bsdf_params *params)
{
	float c[5];
	pattern_at_hit(w, hit, wm->pattern, wm->pattern_uv, ns, c);
	vec3 rgb = v3(c[0], c[1], c[2]);
	scene_color_clamp(&rgb, SCENE_COLOR_REFLECTANCE);
	if (params->kind == BSDF_POV && params->clear.patterned) {
		float f = fminf(fmaxf(c[3], 0.0f), 1.0f), t = fminf(fmaxf(c[4], 0.0f), 1.0f);
		params->clear.tint = v3_min(v3_add(v3_scale(rgb, f), v3s(t)), v3s(1.0f));
		params->clear.reflect *= fminf(1.0f, f + t);
		params->pov.diffuse = wm->opaque_diffuse * fmaxf(0.0f, 1.0f - f - t);
		params->pov.glow = v3_scale(params->pov.glow, fmaxf(0.0f, 1.0f - f - t)); /* as the diffuse */
	}
	if (params->kind == BSDF_POV) /* the finish's lobes follow the pigment (its diffuse included) */
		bsdf_pov_set_pigment(params, rgb);
	else
		params->diffuse = v3_scale(rgb, wm->pattern_kd); /* a finish's diffuse scales its pigment */
}

/* A POV-Ray normal { } (node `node`) at the hit: the shading normal taken into the object's space
 * (the transpose of its placement), perturbed there by the pattern, and brought back. */
static void shade_normal(const world *w, uint32_t node, bool uv, const render_hit *hit, vec3 *ns)
{
	const world_inst *in = &w->insts[hit->object];
	dvec3 p = uv ? d3(hit->uv.x, hit->uv.y, 0.0) : xform_inv_point(&in->pattern_xf, v3_to_d3(hit->p));
	dvec3 n = pattern_normal_through(&in->pattern_xf, v3_to_d3(*ns), true);
	pattern_surface sf = {v3_to_d3(*ns), v3_to_d3(hit->p)};
	pattern_perturb_at(&w->patterns, node, p, &sf, &n);
	vec3 out = v3_normalize(d3v(pattern_normal_through(&in->pattern_xf, n, false)));
	if (v3_is_finite(out) && v3_length2(out) > 0.5f)
		*ns = out;
}

/* The factor on a channel's layer weights that keeps their sum s and what passes t at most 1. */
static float layers_cap(float s, float t)
{
	return s + t > 1.0f && s > 0.0f ? fmaxf(0.0f, 1.0f - t) / s : 1.0f;
}

/* A layered texture at the hit, as POV-Ray 3.7 lights one (trace.cpp ComputeLightedTexture): from
 * the top layer down, each layer is lit with its own pigment, finish and normal, its diffuse
 * and ambient scaled by its opacity 1 - filter - transmit, and all of it by W, what the layers
 * above let through (the product of their pigment * filter + transmit); the light that passes
 * every layer is the surface's transparent part (bsdf_clear). The BSDF is the sum of the layers'
 * W-weighted lobes. Where no layer has its own normal, their Lambert terms (W_i Kd_i opacity_i
 * C_i, one normal) add into one lobe evaluated exactly (bsdf_params.pov_layer_diffuse), save a
 * layer whose diffuse is no plain Lambert (brilliance, subsurface); the rest of the layers' lobes
 * (highlights, reflection, and every lobe where the layers' normals differ) is estimated: shade
 * picks one layer by hit->u_layer, with probability proportional to the luminance of its weighted
 * albedo bound less the diffuse already summed, and returns those lobes times W over that
 * probability (bsdf_params.pov_weight): their expectation is the sum. The emission (ambient) is
 * the sum itself.
 * Where the sum of the layers' albedos and the transparent part could pass 1 in a channel (upper
 * layers' highlights over the light they let through), the layers' weights are scaled so that
 * it is 1 (doc/language.md "Layered textures"). */
/* What shade_layers gathers over the layers of one stack or of several (a patterned texture's
 * entries, each with its weight): the reservoir's pick, the sums, what passes. */
typedef struct layer_sum {
	vec3 emit, sum, mixed, passed; /* passed: what passes each stack, times its weight, added */
	float clear;		       /* the stacks' filter + transmit products, times their weights */
	float total, pick_a;
	double u;
	bsdf_params pick;
	vec3 pick_w, pick_n;
} layer_sum;

/* One stack of layers (bottom first) into *acc at weight s: from the top down, each layer lit with
 * its own finish over params, at the hit (q NULL) or at the point *q of its pattern (q_tol its
 * tolerance: a patterned texture's entry), its normal its own (when it has one) or raw. */
static void stack_layers(const world *w, const world_layer *layers, uint32_t n_layers, bool mix, float s,
			 const render_hit *hit, const bsdf_params *params, vec3 raw, const dvec3 *q, double q_tol,
			 layer_sum *acc)
{
	vec3 through = v3s(s);
	float clear = s;
	pattern_surface sf = {v3_to_d3(raw), v3_to_d3(hit->p)};
	for (uint32_t i = n_layers; i-- > 0;) {
		const world_layer *l = &layers[i];
		vec3 n = raw;
		if (l->has_normal)
			shade_normal(w, l->normal, l->normal_uv, hit, &n);
		float c[5];
		if (l->has_pattern && q)
			pattern_eval_at(&w->patterns, l->pattern, *q, &sf, q_tol, c);
		else if (l->has_pattern)
			pattern_at_hit(w, hit, l->pattern, l->pattern_uv, n, c);
		else
			memcpy(c, l->color, sizeof c);
		vec3 rgb = v3(c[0], c[1], c[2]);
		scene_color_clamp(&rgb, SCENE_COLOR_REFLECTANCE);
		float f = fminf(fmaxf(c[3], 0.0f), 1.0f), t = fminf(fmaxf(c[4], 0.0f), 1.0f);
		float opacity = fmaxf(0.0f, 1.0f - f - t);
		bsdf_params b = *params;
		b.pov = l->finish;
		b.pov.diffuse *= opacity;
		bsdf_pov_set_pigment(&b, rgb);
		acc->emit = v3_add(acc->emit, v3_mul(through, v3_scale(b.emit, opacity)));
		if (mix && b.pov.diffuse > 0.0f && b.pov.brilliance_less_1 == 0.0f && b.pov.sss_diffuse <= 0.0f) {
			vec3 d = v3_mul(through, b.diffuse);
			acc->mixed = v3_add(acc->mixed, d);
			acc->sum = v3_add(acc->sum, d);
			b.pov.diffuse = 0.0f; /* after bsdf_pov_set_pigment: pov_scale counts it */
			b.diffuse = v3s(0.0f);
		}
		vec3 wa = v3_mul(through, bsdf_pov_albedo_bound(&b));
		acc->sum = v3_add(acc->sum, wa);
		float a = v3_luminance(wa);
		if (a > 0.0f) { /* a one-number weighted reservoir: u rescaled at each choice */
			acc->total += a;
			double p = a / acc->total;
			if (acc->u < p) {
				acc->pick = b, acc->pick_w = through, acc->pick_n = n, acc->pick_a = a;
				acc->u = acc->u / p;
			} else {
				acc->u = (acc->u - p) / (1.0 - p);
			}
			acc->u = fmin(fmax(acc->u, 0.0), 1.0 - DBL_EPSILON);
		}
		through = v3_mul(through, v3_min(v3_add(v3_scale(rgb, f), v3s(t)), v3s(1.0f)));
		clear *= fminf(1.0f, f + t);
		if (!(v3_max_comp(through) > 0.0f))
			break; /* the layers below are hidden */
	}
	acc->passed = v3_add(acc->passed, through);
	acc->clear += clear;
}

/* The BSDF of what *acc gathered: the picked layer's lobes at their weight, the layers' diffuse,
 * the glow, the transparent part (shade_layers). */
static void layers_done(const layer_sum *acc, bsdf_params *params, vec3 *ns)
{
	/* The energy bound: sum + through <= 1 in every channel */
	vec3 through = acc->passed, sum = acc->sum;
	float k = fminf(layers_cap(sum.x, through.x), fminf(layers_cap(sum.y, through.y), layers_cap(sum.z, through.z)));
	if (acc->pick_a > 0.0f) {
		*params = acc->pick;
		params->pov_weight = v3_scale(acc->pick_w, k * acc->total / acc->pick_a);
	} else { /* no layer reflects anything: the top one's lobes at weight 0 */
		params->pov_weight = v3s(0.0f);
	}
	params->pov_layer_diffuse = v3_scale(acc->mixed, k);
	params->emit = acc->emit;
	*ns = acc->pick_n;
	if (params->clear.patterned) {
		params->clear.tint = v3_min(through, v3s(1.0f));
		params->clear.reflect *= fminf(1.0f, acc->clear);
	}
}

static void shade_layers(const world *w, const world_material *wm, const render_hit *hit, bsdf_params *params,
			 vec3 *ns)
{
	layer_sum acc = {.emit = v3s(0.0f), .sum = v3s(0.0f), .mixed = v3s(0.0f), .passed = v3s(0.0f),
			 .u = hit->u_layer, .pick = *params, .pick_w = v3s(0.0f), .pick_n = *ns};
	stack_layers(w, wm->layers, wm->n_layers, wm->layers_mix, 1.0f, hit, params, *ns, NULL, 0.0, &acc);
	layers_done(&acc, params, ns);
}

/* A patterned texture with layered entries (world_material.map): the entries its pattern picks at
 * the hit (pattern_pick: one, or two blended, or average's), each stack of layers lit as a layered
 * texture's at the point its entry is evaluated, at the entry's weight, into one sum (POV-Ray's
 * ComputeOneTextureColour: the entries' lit colours blended by the map's weights). Every layer
 * sees the material's normal (the pattern's normal_map of the entries'), so their Lambert terms
 * add into one lobe. */
static void shade_map(const world *w, const world_material *wm, const render_hit *hit, bsdf_params *params, vec3 *ns)
{
	const world_inst *in = &w->insts[hit->object];
	dvec3 p = wm->pattern_uv ? d3(hit->uv.x, hit->uv.y, 0.0) : xform_inv_point(&in->pattern_xf, v3_to_d3(hit->p));
	double tol = wm->pattern_uv ? PATTERN_HIT_ULPS * FLT_EPSILON
				    : PATTERN_HIT_ULPS * FLT_EPSILON * fmax(hit->scale, 1e-30) * pattern_inv_gain(&in->pattern_xf);
	pattern_surface sf = {v3_to_d3(*ns), v3_to_d3(hit->p)};
	uint32_t entry[WORLD_MAP_PICKS];
	double weight[WORLD_MAP_PICKS], q_tol;
	dvec3 q;
	uint32_t n = pattern_pick(&w->patterns, wm->pattern, p, &sf, tol, WORLD_MAP_PICKS, entry, weight, &q, &q_tol);
	layer_sum acc = {.emit = v3s(0.0f), .sum = v3s(0.0f), .mixed = v3s(0.0f), .passed = v3s(0.0f),
			 .u = hit->u_layer, .pick = *params, .pick_w = v3s(0.0f), .pick_n = *ns};
	for (uint32_t i = 0; i < n; i++)
		if (entry[i] < wm->n_map && weight[i] > 0.0)
			stack_layers(w, wm->map[entry[i]].layers, wm->map[entry[i]].n, true, (float)weight[i], hit, params,
				     *ns, &q, q_tol, &acc);
	layers_done(&acc, params, ns);
}

/* render_scene.shade: the material's albedo texture (clamped to a reflectance) and its normal map
 * (through the mesh's tangents, which the build made for it) at the hit. */
static void world_shade(void *user, const render_hit *hit, bsdf_params *params, vec3 *ns)
{
	const world *w = user;
	if (hit->material < 0 || hit->object >= w->n_insts)
		return;
	const world_material *wm = &w->materials[hit->material];
	/* The normal first: a slope pigment sees the perturbed normal, as POV-Ray's (trace.cpp's
	 * ComputeLightedTexture perturbs a layer's normal before its pigment). */
	if (wm->n_layers) {
		shade_layers(w, wm, hit, params, ns);
		return;
	}
	if (wm->n_map) { /* the pattern's normal first, then the entries' layers see it */
		if (wm->has_normal)
			shade_normal(w, wm->normal, wm->normal_uv, hit, ns);
		shade_map(w, wm, hit, params, ns);
		return;
	}
	if (wm->has_normal)
		shade_normal(w, wm->normal, wm->normal_uv, hit, ns);
	if (wm->has_pattern)
		shade_pattern(w, wm, hit, *ns, params);
	if (wm->albedo) {
		float c[4];
		image_bilinear(wm->albedo, hit->uv.x, hit->uv.y, c);
		params->diffuse = v3(c[0], c[1], c[2]);
		/* A float (EXR) texture may hold any number: a reflectance is in [0, 1] (check warns). */
		scene_color_clamp(&params->diffuse, SCENE_COLOR_REFLECTANCE);
		if (params->kind == BSDF_POV) /* the texel is the finish's pigment */
			bsdf_pov_set_pigment(params, params->diffuse);
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

/* render_scene.density: the product of medium m's density patterns at world point p, in the
 * space of the container `object` (as its pigment's), each channel clamped to the bound the
 * majorant was made from. */
static vec3 world_density(void *user, uint32_t object, const render_medium *m, vec3 p)
{
	const world *w = user;
	if (object >= w->n_insts && object != UINT32_MAX)
		return v3s(0.0f);
	/* UINT32_MAX: the atmosphere's, in world space */
	dvec3 q = object == UINT32_MAX ? v3_to_d3(p) : xform_inv_point(&w->insts[object].pattern_xf, v3_to_d3(p));
	double tol = PATTERN_HIT_ULPS * FLT_EPSILON * fmax(d3_length(q), 1.0);
	vec3 r = v3s(1.0f);
	for (uint32_t i = 0; i < m->n_density; i++) {
		float c[5];
		pattern_eval(&w->patterns, m->density[i], q, tol, c);
		r = v3_mul(r, v3(c[0], c[1], c[2]));
	}
	return v3_min(v3_max(r, v3s(0.0f)), m->density_max);
}

/* render_scene.hollow: whether instance `object` is hollow. */
static bool world_hollow(void *user, uint32_t object)
{
	const world *w = user;
	return object < w->n_insts && w->insts[object].hollow;
}

/* The integrator's view of w: world.c's callbacks with w as their user, and the build's tables.
 * Shadow rays walk through surfaces only when some material is transparent: elsewhere an
 * occluded shadow ray costs no closest-hit query. */
void world_bind(world *w)
{
	bool clear = false;
	for (size_t i = 0; i < w->n_materials; i++)
		clear |= w->bsdfs[i].clear.kind != BSDF_CLEAR_NONE;
	w->rs = (render_scene){.user = w, .intersect = world_intersect, .occluded = world_occluded,
			       .shadow_closest = clear ? world_shadow_closest : NULL,
			       .shade = world_shade, .materials = w->bsdfs, .material_count = w->n_materials,
			       .lights = &w->lights, .sss = w->has_sss ? w->sss_of : NULL, .circle = world_circle,
			       .circle_surface = world_circle_surface,
			       .sss_closest = world_sss_closest, .sss_nearest = world_sss_nearest, .fogs = w->fogs, .fog_count = w->n_fogs,
			       .media = w->has_media ? w->media_of : NULL, .density = world_density,
			       .hollow = world_hollow, .light_reach = w->reach ? world_light_reach : NULL,
			       .light_sign = w->light_sign, .n_light_sign = w->n_light_sign,
			       .atmosphere = w->has_atmosphere ? &w->atmosphere : NULL};
}
