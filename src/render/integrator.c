/* integrator.c - path tracing with NEE and MIS, and the BSSRDF step of subsurface materials
 * (integrator.h). The shading frame's +z is the
 * shading normal turned to the side of the outgoing direction; a direction on the far side of the
 * geometric normal is rejected so shading normals cannot leak light through a surface. */
#include "render/integrator.h"

#include "render/bsdf_pov.h"

#include "accel/bvh.h"
#include "accel/offset.h"
#include "sss/disk.h"
#include "sss/probe.h"

#include <assert.h>
#include <string.h>

static const char *const part_names[RENDER_PART_COUNT] = {"all", "camera", "coat", "sss", "direct", "indirect"};

bool render_part_from_name(const char *name, render_part *part)
{
	for (int k = 0; k < RENDER_PART_COUNT; k++)
		if (!strcmp(name, part_names[k])) {
			*part = (render_part)k;
			return true;
		}
	return false;
}

const char *render_part_name(render_part part)
{
	return part >= 0 && part < RENDER_PART_COUNT ? part_names[part] : "all";
}

/* A path passes at most this many thin transparent surfaces without counting them as bounces. */
#define RENDER_MAX_PASSES 64

/* Shadow rays stop this fraction short of the light so they do not hit the emitter itself. */
#define RENDER_SHADOW_EPS 1e-3f

/* The least probability of the subsurface branch at a subsurface material whose coat transmits
 * anything: the branch is chosen by the albedo at the exit, but an albedo texture at the entry
 * point may be brighter, and every contribution must keep a chance. */
#define RENDER_SSS_MIN_PROB 0.1f

/* The sampler's dimensions of a path vertex (sampler.h), counted from the vertex's block
 * (render_sampler_vertex, once per loop of render_path): each purpose keeps its label, so it is
 * the same dimension in every sample of a pixel whichever others a path skipped. A next-event
 * estimation takes three from its base: the light's pick (unused: the pick takes the point's
 * first coordinate, light_set_pick_at), the point on it (2-D), the stream of its shadow ray's
 * media. */
enum {
	DIM_NEE = 0,	    /* at the surface or the medium's scattering point: 0-2 */
	DIM_SSS_BRANCH = 3, /* coat or BSSRDF */
	DIM_SSS_SEARCH = 4, /* the entry search's numbers: 4-8 */
	DIM_SSS_NEE = 9,    /* at the entry point: 9-11 */
	DIM_DELTA = 12,	    /* a delta lobe or the opaque ones */
	DIM_CLEAR = 13,	    /* which delta lobe */
	DIM_BSDF_LOBE = 14, /* the BSDF's (or phase function's) lobe */
	DIM_BSDF_DIR = 15,  /* its direction (2-D) */
	DIM_RR = 16,	    /* Russian roulette */
	DIM_MEDIA = 17,	    /* the stream of the media's tracking along the segment before the vertex */
	DIM_LAYER = 18,	    /* a layered texture's layer (render_hit.u_layer) */
	DIM_COUNT = 19
};
_Static_assert(DIM_COUNT <= RENDER_VERTEX_DIMS, "a vertex's dimensions fit its block");

typedef struct frame {
	vec3 t, b, n;
} frame;

static vec3 to_local(const frame *f, vec3 v)
{
	return v3(v3_dot(v, f->t), v3_dot(v, f->b), v3_dot(v, f->n));
}
static vec3 to_world(const frame *f, vec3 v)
{
	return v3_add(v3_add(v3_scale(f->t, v.x), v3_scale(f->b, v.y)), v3_scale(f->n, v.z));
}

/* Spawned rays leave from the hit moved off its surface just enough for float error: a fixed
 * number of ulps of the triangle's scale (accel/offset.h), valid from 1e-8 to 1e8 in coordinates,
 * so scenes behave the same at any scale. The scene's hit positions must be computed from the
 * triangle (barycentrics), not as o + t d, for the offset to cover their error. */
static vec3 offset_origin(vec3 p, float scale, vec3 n_out) { return bvh_offset_scaled(p, n_out, scale); }

/* Nearest surface closer than tmax: the scene's or a sphere light's. *sphere_light receives the
 * sphere light's index when that is nearer, else -1. */
static bool trace(const render_scene *s, const render_ray *ray, float tmax, render_hit *hit, int *sphere_light)
{
	bool found = s->intersect(s->user, ray, 0.0f, tmax, hit);
	*sphere_light = -1;
	const light_set *ls = s->lights;
	for (size_t i = 0; ls && i < ls->count; i++) {
		const light *l = &ls->lights[i];
		float t;
		if (l->kind == LIGHT_SPHERE &&
		    light_sphere_hit(l, ray, 0.0f, found ? hit->t : tmax, &t)) {
			found = true;
			*sphere_light = (int)i;
			hit->t = t;
			hit->p = v3_madd(ray->o, ray->d, t);
			hit->ng = hit->ns = v3_normalize(v3_sub(hit->p, l->pos));
			hit->material = -1;
			hit->light = (int)i;
		}
	}
	return found;
}

/* MIS weight of an emitter reached by a BSDF sample of density bsdf_pdf. */
static float emitter_weight(const render_settings *set, int bounce, bool prev_delta, float bsdf_pdf,
			    float light_pdf)
{
	if (bounce == 0 || prev_delta || set->mode == RENDER_BSDF_ONLY)
		return 1.0f;
	if (set->mode == RENDER_LIGHT_ONLY)
		return 0.0f;
	return render_power_heuristic(bsdf_pdf, light_pdf);
}

/* A shadow ray crosses at most this many transparent surfaces; beyond, it counts as blocked. */
#define RENDER_SHADOW_MAX_CROSSINGS 16

/* Whether a shadow ray passes the transparent surface of material b (settings decide for glass). */
static bool shadow_passes(const render_settings *set, const bsdf_params *b)
{
	return b->clear.kind == BSDF_CLEAR_THIN || (b->clear.kind == BSDF_CLEAR_DIELECTRIC && !set->opaque_glass_shadows);
}

/* The medium a ray travels in: the container's media and its object (for the density's space). */
typedef struct media_ctx {
	const render_scene *s;
	uint32_t object;
} media_ctx;

static vec3 media_density(const void *ctx, const render_medium *m, vec3 p)
{
	const media_ctx *c = ctx;
	return c->s->density ? c->s->density(c->s->user, c->object, m, p) : v3s(1.0f);
}

/* The nest's material for the atmosphere (render_scene.atmosphere), at its bottom, object
 * UINT32_MAX: no surface crossed leaves it. */
#define RENDER_NEST_ATMOSPHERE (-2)

static const render_media *media_of(const render_scene *s, int material)
{
	if (material == RENDER_NEST_ATMOSPHERE)
		return s->atmosphere;
	return material >= 0 && s->media && (size_t)material < s->material_count ? s->media[material] : NULL;
}

/* Whether the scene has media: an interior's or the atmosphere's. */
static inline bool any_media(const render_scene *s) { return s->media || s->atmosphere; }

/* The interiors a ray is in, innermost last: entered by refraction into a dielectric, left by
 * refraction out of the same object. Deeper nests keep their outer RENDER_MAX_NEST - 1 and the
 * innermost. */
#define RENDER_MAX_NEST 4
typedef struct nest {
	int n;
	int mat[RENDER_MAX_NEST];
	uint32_t obj[RENDER_MAX_NEST];
} nest;

static void nest_cross(nest *st, int mat, uint32_t obj, bool entering)
{
	if (entering) {
		int i = st->n < RENDER_MAX_NEST ? st->n++ : RENDER_MAX_NEST - 1;
		st->mat[i] = mat, st->obj[i] = obj;
		return;
	}
	for (int i = st->n - 1; i >= 0; i--)
		if (st->obj[i] == obj) {
			for (int k = i; k + 1 < st->n; k++)
				st->mat[k] = st->mat[k + 1], st->obj[k] = st->obj[k + 1];
			st->n--;
			return;
		}
}

static int nest_top(const nest *st) { return st->n ? st->mat[st->n - 1] : -1; }

/* The media a ray in the nest travels through: the innermost interior's, or, through hollow
 * objects without media, those of the container around them (POV-Ray's hollow); *obj the
 * container. NULL: none. */
static const render_media *nest_media(const render_scene *s, const nest *st, uint32_t *obj)
{
	for (int i = st->n - 1; i >= 0; i--) {
		const render_media *md = media_of(s, st->mat[i]);
		if (md) {
			*obj = st->obj[i];
			return md;
		}
		if (!s->hollow || !s->hollow(s->user, st->obj[i]))
			return NULL;
	}
	return NULL;
}

/* The transmittance of the media of the nest over o + t d, t in [t0, t1]. */
static vec3 media_segment(const render_scene *s, const nest *st, vec3 o, vec3 d, float t0, float t1, rng *g)
{
	media_ctx mc = {s, 0};
	const render_media *md = any_media(s) ? nest_media(s, st, &mc.object) : NULL;
	if (!md || !(t1 > t0) || (md == s->atmosphere && !isfinite(t1))) /* the atmosphere ends with the scene */
		return v3s(1.0f);
	return render_media_transmittance(md, media_density, &mc, v3_madd(o, d, t0), d, t1 - t0, g);
}

/* What reaches p from the light at tmax along the shadow ray: 1 when nothing is in between, 0
 * behind an opaque surface, the product of bsdf_clear_shadow at each transparent surface crossed
 * (and the fade and the media of a dielectric's interior between its entry and its exit)
 * otherwise. The ray starts inside the interior of material `inside` (object inside_obj), -1:
 * outside every interior. */
static vec3 shadow_transmittance(const render_scene *s, const render_settings *set, render_ray ray, float tmax,
				 const nest *from, render_sampler *smp, uint32_t dim)
{
	rng local, *g = any_media(s) ? render_sampler_stream(smp, dim, &local) : NULL; /* only media draw */
	const vec3 o0 = ray.o;
	nest st = *from;
	if (!s->occluded(s->user, &ray, 0.0f, tmax))
		return media_segment(s, &st, o0, ray.d, 0.0f, tmax, g);
	vec3 tr = v3s(1.0f);
	int inside = nest_top(&st);
	float t_in = 0.0f, t_done = 0.0f;
	for (int k = 0; s->shadow_closest && k < RENDER_SHADOW_MAX_CROSSINGS; k++) {
		render_hit h = {0};
		if (!s->shadow_closest(s->user, &ray, 0.0f, tmax - t_done, &h))
			return v3_mul(tr, media_segment(s, &st, o0, ray.d, t_done, tmax, g));
		if (h.material < 0 || (size_t)h.material >= s->material_count)
			return v3s(0.0f);
		const bsdf_params *b = &s->materials[h.material];
		bsdf_params at;
		if (b->clear.patterned && s->shade) { /* the pattern's transparency at this point */
			vec3 ns = h.ns;
			at = *b;
			s->shade(s->user, &h, &at, &ns);
			b = &at;
		}
		if (!shadow_passes(set, b) || (s->sss && s->sss[h.material]))
			return v3s(0.0f);
		float c = v3_dot(ray.d, h.ng);
		tr = v3_mul(tr, bsdf_clear_shadow(b, c));
		tr = v3_mul(tr, media_segment(s, &st, o0, ray.d, t_done, t_done + h.t, g));
		t_done += h.t;
		if (b->clear.kind == BSDF_CLEAR_DIELECTRIC && c < 0.0f) {
			inside = h.material, t_in = t_done;
		} else if (b->clear.kind == BSDF_CLEAR_DIELECTRIC && inside == h.material) {
			tr = v3_mul(tr, bsdf_fade_apply(&b->clear.fade, t_done - t_in));
			inside = -1;
		}
		if (b->clear.kind == BSDF_CLEAR_DIELECTRIC)
			nest_cross(&st, h.material, h.object, c < 0.0f);
		if (!(v3_max_comp(tr) > 0.0f))
			return v3s(0.0f);
		ray.o = offset_origin(h.p, h.scale, c > 0.0f ? h.ng : v3_neg(h.ng));
	}
	return v3s(0.0f);
}

/* Next-event estimation from hit point p: one light picked by its importance at p, one sample of it. lobe_prob:
 * the probability that the path's own sample uses b (the rest goes to delta lobes), for MIS. */
/* Whether the light choice at a vertex of BSDF b weighs the cosine at the receiver: not for the
 * coat's reflection alone (a glossy lobe's highlight from a light low over the horizon does not
 * fade with the cosine). */
static bool pick_by_cosine(const bsdf_params *b)
{
	return !(b->kind == BSDF_COAT && !(v3_max_comp(b->diffuse) > 0.0f));
}

/* Whether light li, dist away, lights object `object` along the shadow ray (render_scene.light_reach):
 * the shadow ray's *tmax shortened to its projected_through object. The object is looked for up
 * to the light itself (dist), not *tmax: at a distance, the shadow ray's margin is wider than an
 * object about the light. */
static bool light_reaches(const render_scene *s, uint32_t object, size_t li, const render_ray *shadow, float dist,
			  float *tmax)
{
	if (!s->light_reach)
		return true;
	float t = dist;
	if (!s->light_reach(s->user, object, li, shadow, &t))
		return false;
	if (t < dist)
		*tmax = fminf(*tmax, t * (1.0f - RENDER_SHADOW_EPS));
	return true;
}

static vec3 sample_direct(const render_scene *s, const render_settings *set, const bsdf_params *b,
			  const frame *f, vec3 ng_out, vec3 p, float p_scale, vec3 wo_local, float lobe_prob, const nest *in,
			  uint32_t object, render_sampler *g, uint32_t dim)
{
	const light_set *ls = s->lights;
	if (!ls || ls->count == 0)
		return v3s(0.0f);
	/* The light by its importance at p, its point from the same 2-D point: x picks, what is
	 * left of it is the point's first coordinate (light_set_pick_at). */
	float pick;
	vec2 u = render_sampler_2d(g, dim + 1);
	size_t li = light_set_pick_at(ls, p, ng_out, pick_by_cosine(b), u.x, &pick, &u.x);
	light_sample ls_out;
	if (!(pick > 0.0f) || ls->lights[li].seen_only || !light_sample_from(&ls->lights[li], p, ng_out, u, &ls_out))
		return v3s(0.0f);
	if (v3_dot(ls_out.wi, ng_out) <= 0.0f)
		return v3s(0.0f);
	vec3 wi_local = to_local(f, ls_out.wi);
	vec3 fval = ls_out.delta ? bsdf_eval_delta_light(b, wo_local, wi_local) : bsdf_eval(b, wo_local, wi_local);
	/* POV-Ray's shadowless light is its fill light: diffuse only, no specular or phong (trace.cpp) */
	vec3 shine = v3s(0.0f);
	if (ls_out.shadowless) {
		shine = bsdf_shine(b, wo_local, wi_local);
		fval = v3_max(v3_sub(fval, shine), v3s(0.0f));
	}
	if (v3_max_comp(fval) <= 0.0f)
		return v3s(0.0f);
	render_ray shadow = {offset_origin(p, p_scale, ng_out), ls_out.wi};
	float tmax = isfinite(ls_out.dist) ? ls_out.dist * (1.0f - RENDER_SHADOW_EPS) : INFINITY;
	if (!light_reaches(s, object, li, &shadow, ls_out.dist, &tmax))
		return v3s(0.0f);
	vec3 vis = ls_out.shadowless ? v3s(1.0f) : shadow_transmittance(s, set, shadow, tmax, in, g, dim + 2);
	if (!(v3_max_comp(vis) > 0.0f))
		return v3s(0.0f);
	float light_pdf = pick * ls_out.pdf;
	float w = (ls_out.delta || set->mode == RENDER_LIGHT_ONLY)
		      ? 1.0f
		      : render_power_heuristic(light_pdf, lobe_prob * bsdf_pdf(b, wo_local, wi_local));
	if (w < 1.0f) { /* highlights only light sources show in: no BSDF sample shares them */
		vec3 hl = v3_sub(bsdf_highlights(b, wo_local, wi_local), shine);
		/* at least 0: a brilliance's part of hl is signed (bsdf_pov.h), under a light MIS shares */
		fval = v3_max(v3_add(v3_scale(v3_max(v3_sub(fval, hl), v3s(0.0f)), w), hl), v3s(0.0f));
		w = 1.0f;
	}
	vec3 c = v3_scale(v3_mul(v3_mul(fval, ls_out.li), vis), w * fabsf(wi_local.z) / light_pdf);
	return s->light_sign && li < s->n_light_sign ? v3_mul(c, s->light_sign[li]) : c;
}

/* Next-event estimation at a scattering point x of a medium (coefficients c, reached along
 * d_in): one light picked by its importance at x, the media's phase functions towards it, the shadow ray
 * starting inside the container. A light marked no_media lights no medium. */
static vec3 sample_direct_medium(const render_scene *s, const render_settings *set, const render_media *md,
				 const render_media_coef *c, vec3 d_in, vec3 x, const nest *in, render_sampler *g,
				 uint32_t dim)
{
	const light_set *ls = s->lights;
	if (!ls || ls->count == 0 || set->mode == RENDER_BSDF_ONLY)
		return v3s(0.0f);
	float pick;
	vec2 u = render_sampler_2d(g, dim + 1);
	size_t li = light_set_pick_at(ls, x, v3s(0.0f), true, u.x, &pick, &u.x);
	light_sample ls_out;
	if (!(pick > 0.0f) || ls->lights[li].no_media || ls->lights[li].seen_only || !light_sample_from(&ls->lights[li], x, v3s(0.0f), u, &ls_out))
		return v3s(0.0f);
	float phase_pdf;
	vec3 fval = render_media_phase_eval(md, c, d_in, ls_out.wi, &phase_pdf);
	if (!(v3_max_comp(fval) > 0.0f))
		return v3s(0.0f);
	render_ray shadow = {x, ls_out.wi};
	float tmax = isfinite(ls_out.dist) ? ls_out.dist * (1.0f - RENDER_SHADOW_EPS) : INFINITY;
	if (!light_reaches(s, UINT32_MAX, li, &shadow, ls_out.dist, &tmax))
		return v3s(0.0f);
	vec3 vis = ls_out.shadowless ? v3s(1.0f) : shadow_transmittance(s, set, shadow, tmax, in, g, dim + 2);
	if (!(v3_max_comp(vis) > 0.0f))
		return v3s(0.0f);
	float light_pdf = pick * ls_out.pdf;
	float w = (ls_out.delta || set->mode == RENDER_LIGHT_ONLY) ? 1.0f : render_power_heuristic(light_pdf, phase_pdf);
	vec3 r = v3_scale(v3_mul(v3_mul(fval, ls_out.li), vis), w / light_pdf);
	return s->light_sign && li < s->n_light_sign ? v3_mul(r, s->light_sign[li]) : r;
}

/* ---- subsurface scattering ----------------------------------------------------------------- */

/* An entry point found by a method: the surface there (normals facing out of the medium) and the
 * weight R(r) f_leak / (p_A P) of the BSSRDF's spatial part (DESIGN.md). */
typedef struct sss_entry {
	render_hit hit;
	vec3 weight;
} sss_entry;

/* The scene's normals keep the mesh's orientation: `side` turns them as the exit's was turned to
 * the outside (the viewer's side), so the leak filter sees outward normals everywhere. */
static void turn_hit(render_hit *h, float side)
{
	h->ng = v3_scale(h->ng, side);
	h->ns = v3_scale(h->ns, side);
}

/* Circle tracing (Legros & Corvazier 2016; src/sss/README.md "Plugging in"): r from the profile,
 * the circle of that radius about the exit x in a plane through its normal n_out, every hit on
 * the same SSS volume, one chosen by resampling proportional to its full weight. */
_Static_assert(RENDER_SSS_MAX_HITS <= SSS_CIRCLE_MAX_HITS, "sss_circle_choose weighs every hit kept");

static bool circle_entry(const render_scene *s, const render_settings *set, const render_sss *m,
			 const render_hit *exit, vec3 n_out, render_sampler *g, sss_entry *e, render_sample *out)
{
	sss_circle_opts o = sss_circle_default_opts();
	o.kind = m->method == SSS_METHOD_FULLCIRCLE ? SSS_CIRCLE_FULL : SSS_CIRCLE_HALF;
	o.weight = set->circle_weight;
	/* The radius and the circle's angle as one 2-D point: stratified together. (The random
	 * sampler draws y first: u_r keeps the stream's order of before.) */
	float u_channel = render_sampler_1d(g, DIM_SSS_SEARCH);
	vec2 u_rphi = render_sampler_2d(g, DIM_SSS_SEARCH + 1);
	float u_r = u_rphi.y, u_phi = u_rphi.x;
	float u_pick = render_sampler_1d(g, DIM_SSS_SEARCH + 2);
	double r_mm = sss_profile_sample(&m->profile, u_channel, u_r);
	sss_circle c = sss_circle_make(exit->p, n_out, (float)(r_mm * m->units_per_mm), 0.0f, u_phi, &o);
	tri_circle_hit hits[RENDER_SSS_MAX_HITS];
	bool more = false;
	uint32_t k = c.q.radius > 0.0f ? s->circle(s->user, exit, &c.q, hits, RENDER_SSS_MAX_HITS, &more) : 0;
	assert(k <= RENDER_SSS_MAX_HITS);
	if (more)
		out->sss_overflow++;
	float side = v3_dot(exit->ng, n_out) >= 0.0f ? 1.0f : -1.0f;
	for (uint32_t i = 0; i < k; i++)
		hits[i].ng = v3_scale(hits[i].ng, side); /* turn_hit's turn */
	vec3 w;
	float prob;
	int i = sss_circle_choose(&c, sss_profile_ratio(&m->profile, r_mm), hits, (int)k, u_pick, &o, &w, &prob);
	if (i < 0 || !v3_is_finite(w)) {
		out->sss_nohit++;
		return false;
	}
	assert((uint32_t)i < k);
	s->circle_surface(s->user, &hits[i], &e->hit); /* the full record of the chosen hit only */
	turn_hit(&e->hit, side);
	e->weight = w;
	return true;
}

/* The comparators see the SSS volume through src/sss's probe: the scene's sss_closest, with the
 * surface of every hit kept in order (slot min(n, cap - 1): a walk needs only the last one, its
 * exit) so the chosen hit can be shaded like any other. */
typedef struct probe_ctx {
	const render_scene *s;
	const render_hit *at; /* the exit point: its SSS volume is the one traced */
	float side;	      /* turn_hit's */
	render_hit *log;
	int cap, *n;
} probe_ctx;

static bool probe_closest(const void *ctx, const bvh_ray *ray, sss_probe_hit *h)
{
	const probe_ctx *c = ctx;
	render_hit rh = {0};
	render_ray r = {ray->org, ray->dir};
	if (!c->s->sss_closest(c->s->user, c->at, &r, ray->tmin, ray->tmax, &rh))
		return false;
	turn_hit(&rh, c->side);
	*h = (sss_probe_hit){.t = rh.t, .p = rh.p, .ng = rh.ng, .prim = rh.prim, .u = rh.bary.x, .v = rh.bary.y,
			     .scale = rh.scale};
	c->log[*c->n < c->cap ? *c->n : c->cap - 1] = rh;
	++*c->n;
	return true;
}

/* The walk's nearest surface (sss_probe_nearest_fn): the scene's, 0 (no ball) without it. */
static float probe_nearest(const void *ctx, vec3 p, float cap)
{
	const probe_ctx *c = ctx;
	return c->s->sss_nearest ? c->s->sss_nearest(c->s->user, c->at, p, cap) : 0.0f;
}

/* The disk comparator (King et al. 2013; src/sss/README.md "The disk comparator"): a probe
 * segment along n, t or b through the sphere of r_max, every hit on the same volume weighed by
 * MIS over the axes, one chosen by resampling as circle_entry does. */
static bool disk_entry(const render_scene *s, const render_sss *m, const render_hit *exit, vec3 n_out,
		       render_sampler *g, sss_entry *e, render_sample *out)
{
	/* The axis with phi, and the radius, as one 2-D point (sss_disk_probe_make): stratified
	 * together on each axis. */
	vec2 u_ar = render_sampler_2d(g, DIM_SSS_SEARCH + 1);
	double u[3] = {u_ar.x, render_sampler_1d_double(g, DIM_SSS_SEARCH), u_ar.y};
	float u_pick = render_sampler_1d(g, DIM_SSS_SEARCH + 2);
	double mm_per_unit = 1.0 / m->units_per_mm;
	sss_disk_frame f = sss_disk_frame_make(exit->p, n_out);
	sss_disk_probe q = sss_disk_probe_make(&m->profile, mm_per_unit, &f, u);
	render_hit log[SSS_DISK_MAX_HITS + 1];
	int n = 0;
	probe_ctx ctx = {s, exit, v3_dot(exit->ng, n_out) >= 0.0f ? 1.0f : -1.0f, log, SSS_DISK_MAX_HITS + 1, &n};
	sss_probe pr = {probe_closest, &ctx, NULL};
	sss_disk_hit hits[SSS_DISK_MAX_HITS];
	bool more;
	int k = sss_disk_gather(&m->profile, mm_per_unit, &f, &q, &pr, hits, SSS_DISK_MAX_HITS, &more);
	assert(k >= 0 && k <= SSS_DISK_MAX_HITS);
	if (more)
		out->sss_overflow++;
	vec3 w;
	float prob;
	int i = sss_disk_choose(hits, k, u_pick, &w, &prob);
	if (i < 0 || !v3_is_finite(w)) {
		out->sss_nohit++;
		return false;
	}
	assert(i < k && i < n); /* the chosen hit was logged: log[i] is its surface */
	e->hit = log[i];
	e->weight = w;
	return true;
}

/* The direction of wo (unit, on n's side) refracted into a medium of relative index ior through
 * the unit normal n; false under total internal reflection. */
static bool refract_in(vec3 wo, vec3 n, float ior, vec3 *wt)
{
	float cos_i = v3_dot(wo, n), inv = 1.0f / ior;
	float sin2_t = inv * inv * fmaxf(0.0f, 1.0f - cos_i * cos_i);
	if (!(sin2_t < 1.0f))
		return false;
	float cos_t = sqrtf(1.0f - sin2_t);
	*wt = v3_normalize(v3_add(v3_scale(wo, -inv), v3_scale(n, inv * cos_i - cos_t)));
	return true;
}

/* The volumetric reference: the light the coat transmits at x refracts into the medium (Snell,
 * through the shading normal when that keeps it inside) and random-walks to where it leaves
 * (sss_walk: scattering, absorption, Fresnel reflection at every boundary hit from inside). The
 * position and weight of the exit are the walk's; the direction it leaves in is not followed:
 * the path goes on through the same entry lobe (1 - F(w_i)) cos / (c pi) as the BSSRDF methods,
 * the angular form every diffusion profile assumes, so light sampling works at the exit (a
 * smooth boundary's one refracted direction never finds a point light) and the comparison with
 * the profiles measures their spatial and total albedo error, not an angular one. */
static bool volume_entry(const render_scene *s, const render_sss *m, const render_hit *exit, vec3 n_shade,
			 vec3 n_out, vec3 wo, render_sampler *smp, sss_entry *e, render_sample *out)
{
	rng local, *g = render_sampler_stream(smp, DIM_SSS_SEARCH, &local);
	vec3 w_in;
	if (!refract_in(wo, n_shade, m->ior, &w_in) || v3_dot(w_in, n_out) >= 0.0f)
		if (!refract_in(wo, n_out, m->ior, &w_in))
			return false;
	render_hit last;
	int n = 0;
	probe_ctx ctx = {s, exit, 1.0f, &last, 1, &n};
	sss_probe pr = {probe_closest, &ctx, s->sss_nearest ? probe_nearest : NULL};
	sss_walk_result r = sss_walk(&m->medium, &pr, exit->p, exit->ng, exit->scale, w_in, g, SSS_WALK_MAX_STEPS);
	out->sss_walks++;
	out->sss_walk_dropped += r.status == SSS_WALK_STEP_LIMIT;
	out->sss_walk_steps += (uint32_t)r.steps;
	out->sss_walk_skipped += (uint32_t)r.skipped;
	out->sss_walk_queries += (uint32_t)r.queries;
	if (r.status == SSS_WALK_ABSORBED)
		return false; /* an outcome of the walk, not a failure */
	if (r.status != SSS_WALK_EXITED || n == 0 || last.prim != r.prim || !v3_is_finite(r.weight)) {
		out->sss_nohit++; /* lost, at the step bound, or bad input */
		return false;
	}
	if (v3_dot(last.ng, r.dir) < 0.0f)
		turn_hit(&last, -1.0f);
	e->hit = last;
	e->weight = r.weight;
	return true;
}

/* auto's light estimate (src/sss/README.md, "auto"): the unshadowed irradiance at p on the side
 * its unit normal n faces, in luminance: each light's one sample at the fixed u = (1/2, 1/2)
 * (a delta light's own value; an area's or a sphere's centre-ish point), weighed by the cosine
 * wrapped by `wrap` ((cos + wrap) / (1 + wrap), clamped at 0) over its density, and an infinite
 * light as pi times its radiance along n. Deterministic and continuous in p and n; no random
 * number, no ray. */
static double auto_irradiance(const render_scene *s, vec3 p, vec3 n, float wrap)
{
	double e = 0.0;
	if (!s->lights)
		return 0.0;
	for (size_t i = 0; i < s->lights->count; i++) {
		const light *l = &s->lights->lights[i];
		if (l->seen_only)
			continue;
		if (light_is_infinite(l)) {
			e += RENDER_PI * (double)v3_luminance(light_radiance_dir(l, n));
			continue;
		}
		light_sample ls;
		if (!light_sample_from(l, p, n, v2(0.5f, 0.5f), &ls) || !(ls.pdf > 0.0f))
			continue;
		float c = (v3_dot(n, ls.wi) + wrap) / (1.0f + wrap);
		if (c > 0.0f)
			e += (double)v3_luminance(ls.li) * c / ls.pdf;
	}
	return e;
}

/* auto (src/sss/README.md, "auto"): the thickness of the object below the exit, by one ray along
 * the inward geometric normal on the SSS volume alone, in diffuse mean free paths l_d, sets the
 * geometric probability of the walk (sss_auto_walk_prob: 1 below 5 l_d, 0 from 10 l_d on, smooth
 * between); where it is not 0, the share of the exit's light that comes from the far side where
 * the ray left (sss_auto_light_share of the two sides' unshadowed irradiance) multiplies it by
 * sss_auto_light_prob (0 below 1 %, 1 from 10 %): the walk only where light reaches the far side.
 * Where the object is thinner than the profile's own reach (sss_auto_thin_prob: its tail from 5 %
 * to 2 %), the walk whatever the light, the larger of the two probabilities.
 * Circle tracing otherwise. The ray stops at the band's far end: beyond it the answer is circle.
 * The choice draws its own sampler dimension, and only where the probability is strictly between
 * 0 and 1, so a thick object (or a thin one lit from the front only) renders exactly as under
 * circle, a thin one lit through exactly as under volume. */
static bool auto_entry(const render_scene *s, const render_settings *set, const render_sss *m,
		       const render_hit *exit, vec3 n_shade, vec3 n_out, vec3 wo, render_sampler *g, sss_entry *e,
		       render_sample *out)
{
	float p_walk = 0.0f;
	/* the choice's number: the search's fifth, which neither circle (its first three) nor the walk
	 * (a stream keyed by the first) draws; drawn once at most */
	float u = 0.0f;
	bool drawn = false;
	if (m->auto_walk) {
		float reach = (float)SSS_AUTO_CIRCLE_ABOVE * m->auto_ld;
		double thick = INFINITY; /* nothing below within reach: thick */
		render_ray probe = {bvh_offset_scaled(exit->p, v3_neg(n_out), exit->scale), v3_neg(n_out)};
		render_hit far = {0};
		bool hit = false;
		if (!(reach < INFINITY)) {
			thick = 0.0; /* no absorption at all (l_d infinite): every object is thin */
		} else if ((hit = s->sss_closest(s->user, exit, &probe, 0.0f, reach, &far))) {
			thick = far.t;
		}
		double mfp = m->auto_ld > 0.0f ? thick / m->auto_ld : 0.0;
		double p = sss_auto_walk_prob(mfp);
		/* thinner than the profile's own reach: the walk, lit from either side (the larger of
		 * the two probabilities: continuous where both are) */
		double thin = hit ? sss_auto_thin_prob(thick, m->auto_tail_walk, m->auto_tail_circle) : 0.0;
		if (p > 0.0 && hit) {
			/* The light factor (in [0, 1]) only lowers p, and the floor is taken after it:
			 * where the floor is at least p, or the choice's number is at or past p, the
			 * light cannot change the choice and is not estimated (issue 21, fifth pass: the
			 * two irradiances and the share were 40 % of auto's price on the wax sphere,
			 * where nothing walks). The same choices as estimating it always: a Sobol value
			 * depends only on its dimension, so it is drawn early here; the random sampler's
			 * next number depends on what was drawn before, so it keeps the order. */
			if (!(thin < p)) {
				p = thin; /* max(p * light, thin) = thin */
			} else {
				if (render_sampler_keyed(g) && (float)p < 1.0f)
					u = render_sampler_1d(g, DIM_SSS_SEARCH + 4), drawn = true;
				if (drawn && !(u < (float)p)) {
					p = thin; /* u >= p >= max(p * light, thin): circle, as thin decides */
				} else {
					vec3 n_far = v3_dot(far.ng, probe.d) >= 0.0f ? far.ng : v3_neg(far.ng); /* out of the far side */
					double e_far = auto_irradiance(s, far.p, n_far, SSS_AUTO_LIGHT_WRAP);
					double e_near = e_far > 0.0 ? auto_irradiance(s, exit->p, n_out, 0.0f) : 0.0;
					p *= sss_auto_light_prob(
						sss_auto_light_share(&m->auto_slab, e_near, e_far, thick / m->units_per_mm));
				}
			}
		}
		if (hit && p < 1.0)
			p = fmax(p, thin);
		p_walk = (float)p;
	}
	bool walk = p_walk >= 1.0f;
	if (!walk && p_walk > 0.0f) {
		if (!drawn)
			u = render_sampler_1d(g, DIM_SSS_SEARCH + 4);
		walk = u < p_walk;
	}
	if (walk)
		return volume_entry(s, m, exit, n_shade, n_out, wo, g, e, out);
	return circle_entry(s, set, m, exit, n_out, g, e, out);
}

/* The one place where a method is chosen. False when no entry point was found: the path ends
 * there (each method counts its failures in out->sss_nohit; an absorbed walk is not one). */
static bool sss_find_entry(const render_scene *s, const render_settings *set, const render_sss *m,
			   const render_hit *exit, vec3 n_shade, vec3 n_out, vec3 wo, render_sampler *g, sss_entry *e,
			   render_sample *out)
{
	out->sss_searches++;
	switch (m->method) {
	case SSS_METHOD_CIRCLE:
	case SSS_METHOD_FULLCIRCLE:
		return circle_entry(s, set, m, exit, n_out, g, e, out);
	case SSS_METHOD_DISK:
		return disk_entry(s, m, exit, n_out, g, e, out);
	case SSS_METHOD_VOLUME:
		return volume_entry(s, m, exit, n_shade, n_out, wo, g, e, out);
	case SSS_METHOD_AUTO:
		return auto_entry(s, set, m, exit, n_shade, n_out, wo, g, e, out);
	case SSS_METHOD_DEFAULT: /* never: the build chose the method */
		break;
	}
	assert(!"an SSS material without a method");
	return false;
}

static float ratio_or_zero(float a, float b) { return b > 0.0f ? a / b : 0.0f; }

/* Probability of taking the subsurface branch at an SSS material: the coat's transmitted weight
 * (1 - F) A against its reflected F, with a floor while anything is transmitted. */
static float sss_branch_prob(float fresnel, vec3 albedo)
{
	float ws = fresnel, wd = (1.0f - fresnel) * v3_luminance(albedo);
	float p = ws + wd > 0.0f ? wd / (ws + wd) : 0.5f;
	return fresnel < 1.0f ? fmaxf(p, RENDER_SSS_MIN_PROB) : 0.0f;
}

/* What a path carries from one scattering event to the next. */
typedef struct path {
	vec3 radiance, beta; /* gathered so far; throughput */
	float prev_pdf;	     /* of the BSDF sample that left prev_p */
	bool prev_delta;     /* that sample was a delta lobe (or is the camera's ray) */
	vec3 prev_p, prev_n; /* the vertex that sample left, its ng_out */
	uint32_t prev_object; /* its object (UINT32_MAX: a medium's point, or the camera) */
	bool prev_cosine;    /* its light choice weighed the cosine (pick_by_cosine) */
	bool fog_view;	     /* the camera's ray or a mirror's continuation of it: fogged (fog.h) */
	bool sky_view;	     /* the same, by RENDER_SKY_MIRROR_PDF: sees a light that is only seen
			      * (light.h's seen_only) */
	bool passed;	     /* thin transparent surfaces were passed since prev_p (same direction) */
	bool stood_for;	     /* refracted through glass since the last non-delta vertex, whose
			      * shadow rays passed that glass: emitters found now were counted there */
	bool scattered;	     /* a non-delta vertex was met */
	int medium;	     /* the material whose interior the path is in (nest's innermost), -1: none */
	nest in;	     /* the interiors the path is in */
	int bounce;	     /* render_path's: the scattering events before the current ray */
	render_part first;   /* the kind of the first event (coat, sss, direct); camera: none yet */
} path;

/* Whether light after `events` scattering events, the first of kind `kind` (when events is 1),
 * belongs to the settings' part. */
static inline bool in_part(const render_settings *set, int events, render_part kind)
{
	if (set->part == RENDER_PART_ALL)
		return true;
	render_part p = events == 0 ? RENDER_PART_CAMERA : events == 1 ? kind : RENDER_PART_INDIRECT;
	return p == set->part;
}

/* Adds light c (already weighed by the throughput) that arrives after the path's events. */
static inline void gather(const render_settings *set, path *pa, vec3 c)
{
	if (in_part(set, pa->bounce, pa->first))
		pa->radiance = v3_add(pa->radiance, c);
}

/* The first scattering event's kind is kind, unless one was met already. */
static inline void first_event(path *pa, render_part kind)
{
	if (pa->first == RENDER_PART_CAMERA)
		pa->first = kind;
}

/* A surface the path scatters at: its BSDF, the shading frame, where rays leave from. */
typedef struct vertex {
	bsdf_params b;
	float lobe_prob; /* the probability of sampling b's lobes (1 - that of its delta lobes) */
	frame f;
	vec3 ng_out;   /* geometric normal on the side of wo */
	vec3 p;	       /* rays leave from p, offset by p_scale (offset_origin) */
	float p_scale;
	vec3 wo_local; /* the outgoing direction in f */
	uint32_t object; /* the hit's (render_scene.light_reach) */
} vertex;

/* A path that escapes the scene sees every infinite light, weighed against the BSDF sample; one
 * that is only seen (POV-Ray's sky without radiosity) only by the camera's ray and its mirror
 * continuations, in full (next-event estimation never takes it). */
static inline void add_escaped(const render_scene *s, const render_settings *set, int bounce, vec3 d, path *pa)
{
	const light_set *ls = s->lights;
	for (size_t k = 0; ls && k < ls->infinite_count; k++) {
		const light *l = &ls->lights[ls->infinite[k]];
		if (l->seen_only) {
			if (pa->sky_view)
				gather(set, pa, v3_mul(pa->beta, light_radiance_dir(l, d)));
			continue;
		}
		float lp = light_set_prob_at(ls, ls->infinite[k], pa->prev_p, pa->prev_n, pa->prev_cosine) * light_pdf(l, pa->prev_p, pa->prev_n, d, INFINITY, v3s(0));
		float w = pa->stood_for ? 0.0f : emitter_weight(set, bounce, pa->prev_delta, pa->prev_pdf, lp);
		gather(set, pa, v3_scale(v3_mul(pa->beta, light_radiance_dir(l, d)), w));
	}
}

/* The emission of the light the surface hit belongs to (an emissive mesh or a sphere light). */
static inline void add_emitted(const render_scene *s, const render_settings *set, int bounce, vec3 d,
			       const render_hit *hit, path *pa)
{
	const light_set *ls = s->lights;
	if (hit->light < 0 || !ls || (size_t)hit->light >= ls->count)
		return;
	/* a light's group holds for the BSDF's sample as for next-event estimation (a sphere light) */
	float t_reach = INFINITY;
	if (bounce > 0 && !pa->prev_delta && s->light_reach &&
	    !s->light_reach(s->user, pa->prev_object, (size_t)hit->light, NULL, &t_reach))
		return;
	const light *l = &ls->lights[hit->light];
	float dist = pa->passed ? v3_length(v3_sub(hit->p, pa->prev_p)) : hit->t;
	float lp = light_set_prob_at(ls, (size_t)hit->light, pa->prev_p, pa->prev_n, pa->prev_cosine) * light_pdf(l, pa->prev_p, pa->prev_n, d, dist, hit->ng);
	float w = pa->stood_for ? 0.0f : emitter_weight(set, bounce, pa->prev_delta, pa->prev_pdf, lp);
	gather(set, pa, v3_scale(v3_mul(pa->beta, l->color), w));
}

/* The vertex at a surface hit from direction -wo: the material shaded there, the frame about the
 * shading normal turned to wo's side. */
static inline void make_vertex(const render_scene *s, const render_hit *hit, vec3 wo, vertex *v)
{
	v->b = s->materials[hit->material];
	vec3 ns = hit->ns;
	if (s->shade)
		s->shade(s->user, hit, &v->b, &ns);
	v->ng_out = v3_dot(hit->ng, wo) >= 0.0f ? hit->ng : v3_neg(hit->ng);
	/* The shading normal turns to wo's side with the surface's own (interpolated) normal, as
	 * POV-Ray flips its perturbed normal by the raw one: a normal { } tilted past the geometric
	 * horizon stays tilted, not mirrored into a normal facing the light. */
	v->f.n = v3_dot(hit->ns, v->ng_out) >= 0.0f ? ns : v3_neg(ns);
	/* A shading normal turned away from the viewer (strong normal maps, coarse meshes) would
	 * leave wo below the BSDF's horizon: it is bent to just above wo's horizon, the nearest
	 * normal that shades (continuous as the normal crosses it, and dark towards a light along
	 * wo, as POV-Ray's cos of a normal facing away); along -wo itself the true normal. */
	float nw = v3_dot(v->f.n, wo);
	if (nw <= 0.0f) {
		vec3 bent = v3_add(v->f.n, v3_scale(wo, 1e-3f - nw));
		v->f.n = v3_length2(bent) > 1e-6f ? v3_normalize(bent) : v->ng_out;
	}
	v3_basis(v->f.n, &v->f.t, &v->f.b);
	v->wo_local = to_local(&v->f, wo);
	v->p = hit->p;
	v->p_scale = hit->scale;
	v->lobe_prob = 1.0f;
	v->object = hit->object;
}

/* Next-event estimation at v through the BSDF b (v's own, or a part of it), an event of kind
 * `kind` (for --part; computed whatever the part, so the random decisions stay the same). */
static inline void add_direct(const render_scene *s, const render_settings *set, const bsdf_params *b,
			      const vertex *v, render_sampler *g, uint32_t dim, render_part kind, path *pa)
{
	if (set->mode == RENDER_BSDF_ONLY)
		return;
	vec3 c = v3_mul(pa->beta, sample_direct(s, set, b, &v->f, v->ng_out, v->p, v->p_scale, v->wo_local,
						 v->lobe_prob, &pa->in, v->object, g, dim));
	if (in_part(set, pa->bounce + 1, pa->bounce == 0 ? kind : pa->first))
		pa->radiance = v3_add(pa->radiance, c);
}

/* The BSSRDF branch taken: the path moves to the entry point e found for the exit `hit` and
 * leaves it through the entry lobe, outside the medium. fr is the coat's Fresnel at the exit,
 * p_sss the branch's probability. */
static inline void enter_at(const render_scene *s, const render_settings *set, const render_sss *sm,
			    const sss_entry *e, float fr, float p_sss, vertex *v, render_sampler *g, path *pa)
{
	bsdf_params at = s->materials[e->hit.material];
	vec3 ns_i = e->hit.ns;
	if (s->shade)
		s->shade(s->user, &e->hit, &at, &ns_i);
	vec3 w = v3_scale(e->weight, (1.0f - fr) / p_sss);
	/* Diffuse colour blurring: the albedo texture at x_i, not at x. */
	if (sm->textured)
		w = v3_mul(w, v3(ratio_or_zero(at.diffuse.x, sm->albedo.x), ratio_or_zero(at.diffuse.y, sm->albedo.y),
				 ratio_or_zero(at.diffuse.z, sm->albedo.z)));
	pa->beta = v3_mul(pa->beta, w);
	v->p = e->hit.p;
	v->p_scale = e->hit.scale;
	v->object = e->hit.object;
	v->ng_out = e->hit.ng;
	v->f.n = v3_dot(ns_i, v->ng_out) > 0.0f ? ns_i : v->ng_out;
	v3_basis(v->f.n, &v->f.t, &v->f.b);
	v->wo_local = v3(0.0f, 0.0f, 1.0f);
	v->b = (bsdf_params){.kind = BSDF_SSS_ENTRY, .diffuse = v3s(sm->entry_norm), .alpha = 1.0f, .ior = sm->ior};
	add_direct(s, set, &v->b, v, g, DIM_SSS_NEE, RENDER_PART_SSS, pa);
}

/* Scattering at a subsurface material: the coat's reflection is a lobe of its own (light sampled
 * here, and v keeps only it), its transmission the BSSRDF (v moves to the entry point). False
 * when the BSSRDF found no entry: the path ends. */
static inline bool sss_scatter(const render_scene *s, const render_settings *set, const render_sss *sm,
			       const render_hit *hit, vec3 wo, vertex *v, render_sampler *g, path *pa, render_sample *out)
{
	float fr = bsdf_fresnel_dielectric(v->wo_local.z, sm->ior);
	float p_sss = sss_branch_prob(fr, v->b.diffuse);
	bsdf_params spec = v->b;
	spec.diffuse = v3s(0.0f);
	add_direct(s, set, &spec, v, g, DIM_NEE, RENDER_PART_COAT, pa);
	if (!(render_sampler_1d(g, DIM_SSS_BRANCH) < p_sss)) {
		first_event(pa, RENDER_PART_COAT);
		v->b = spec;
		pa->beta = v3_scale(pa->beta, 1.0f / (1.0f - p_sss));
		return true;
	}
	first_event(pa, RENDER_PART_SSS);
	sss_entry e;
	if (!sss_find_entry(s, set, sm, hit, v->f.n, v->ng_out, wo, g, &e, out))
		return false;
	enter_at(s, set, sm, &e, fr, p_sss, v, g, pa);
	return true;
}

/* Russian roulette past RENDER_RR_DEPTH; false when the path ends. */
static inline bool roulette(int bounce, render_sampler *g, path *pa)
{
	if (bounce + 1 >= RENDER_RR_DEPTH) {
		float q = fminf(1.0f, v3_max_comp(pa->beta));
		if (!(render_sampler_1d(g, DIM_RR) < q))
			return false;
		pa->beta = v3_scale(pa->beta, 1.0f / q);
	}
	return true;
}

/* The BSDF sample that continues the path from v, and Russian roulette; false when the path ends.
 * *ray becomes the next ray. */
static inline bool continue_path(const vertex *v, int bounce, render_sampler *g, path *pa, render_ray *ray)
{
	float u_lobe = render_sampler_1d(g, DIM_BSDF_LOBE);
	vec2 u = render_sampler_2d(g, DIM_BSDF_DIR);
	vec3 wi_local, fval;
	float pdf;
	if (!bsdf_sample(&v->b, v->wo_local, u_lobe, u, &wi_local, &fval, &pdf))
		return false;
	vec3 wi = to_world(&v->f, wi_local);
	if (v3_dot(wi, v->ng_out) <= 0.0f)
		return false;
	pdf *= v->lobe_prob;
	pa->beta = v3_mul(pa->beta, v3_scale(fval, fabsf(wi_local.z) / pdf));
	pa->prev_pdf = pdf;
	pa->prev_delta = false;
	pa->passed = pa->stood_for = false;
	pa->scattered = true;
	pa->prev_p = v->p, pa->prev_n = v->ng_out, pa->prev_cosine = pick_by_cosine(&v->b);
	pa->prev_object = v->object;
	if (!roulette(bounce, g, pa))
		return false;
	*ray = (render_ray){offset_origin(v->p, v->p_scale, v->ng_out), v3_normalize(wi)};
	return true;
}

/* The fogs between the ray's origin and t: what lies beyond is dimmed, the fog's colour added. */
static inline void through_fog(const render_scene *s, const render_settings *set, const render_ray *ray, float t,
			       path *pa)
{
	vec3 att, add;
	render_fog_segment(s->fogs, s->fog_count, ray->o, ray->d, t, &att, &add);
	gather(set, pa, v3_mul(pa->beta, add));
	pa->beta = v3_mul(pa->beta, att);
}

/* The probability of the delta lobes of v's transparent part against its opaque lobes, by their
 * weights (0 at an opaque surface or where nothing passes, 1 where the opaque part reflects
 * nothing). A POV-Ray finish's opaque weight counts its highlights and reflection with its
 * diffuse (bsdf_pov_albedo_bound): a clear layer's or glass's phong alone is no "nothing". */
static inline float delta_prob(const vertex *v, bool entering)
{
	if (v->b.clear.kind == BSDF_CLEAR_NONE)
		return 0.0f;
	float wd = bsdf_clear_weight(&v->b, v->wo_local, entering);
	float wo = v3_luminance(v->b.kind == BSDF_POV ? bsdf_pov_albedo_bound(&v->b) : bsdf_albedo(&v->b));
	if (!(wd > 0.0f))
		return 0.0f;
	return wo > 0.0f ? wd / (wd + wo) : 1.0f;
}

/* The path goes on from v by a delta lobe of its transparent part (chosen with probability
 * p_delta): reflected, refracted into or out of the interior, or straight through a thin surface,
 * which is no scattering event (the emitter MIS stays with the vertex before it). False when the
 * path ends; *ray becomes the next ray. */
static inline bool continue_clear(const render_settings *set, const render_hit *hit, const vertex *v, bool entering,
				  float p_delta, int bounce, render_sampler *g, path *pa, render_ray *ray)
{
	vec3 wi_local, w;
	bool refracted;
	if (!bsdf_clear_sample(&v->b, v->wo_local, entering, render_sampler_1d(g, DIM_CLEAR), &wi_local, &w,
			       &refracted))
		return false;
	bool thin = v->b.clear.kind == BSDF_CLEAR_THIN;
	vec3 wi = thin ? ray->d : v3_normalize(to_world(&v->f, wi_local));
	vec3 side = refracted ? v3_neg(v->ng_out) : v->ng_out;
	if (v3_dot(wi, side) <= 0.0f)
		return false; /* the shading normal sent it to the wrong side of the surface */
	pa->beta = v3_mul(pa->beta, v3_scale(w, 1.0f / p_delta));
	if (thin) {
		pa->passed = true;
	} else {
		pa->prev_delta = true;
		pa->passed = false;
		if (refracted) {
			nest_cross(&pa->in, hit->material, hit->object, entering);
			pa->medium = nest_top(&pa->in);
			pa->stood_for |= pa->scattered && !set->opaque_glass_shadows;
		}
	}
	if (!roulette(bounce, g, pa))
		return false;
	*ray = (render_ray){offset_origin(v->p, v->p_scale, side), wi};
	return true;
}

/* The segment of *ray up to seg inside the media md: the emission on the way, and a scattering
 * event there (light sampled through the phase functions, the path continued by a phase
 * sample: *ray becomes the next ray). 1: the path scattered and goes on; 0: it reached the
 * surface at seg; -1: it ends. */
static int through_media(const render_scene *s, const render_settings *set, const render_media *md, uint32_t obj,
			 float seg, int bounce, render_sampler *g, path *pa, render_ray *ray)
{
	media_ctx mc = {s, obj};
	render_media_coef c;
	float ts;
	rng local;
	/* The media's emission on the way: straight into the radiance, or apart for a part. */
	vec3 emitted = v3s(0.0f), *acc = set->part == RENDER_PART_ALL ? &pa->radiance : &emitted;
	bool scattered = render_media_track(md, media_density, &mc, ray->o, ray->d, seg,
					    render_sampler_stream(g, DIM_MEDIA, &local), &pa->beta, acc, &c, &ts);
	gather(set, pa, emitted);
	if (!scattered)
		return v3_max_comp(pa->beta) > 0.0f ? 0 : -1;
	if (bounce >= set->max_trace_level)
		return -1;
	vec3 x = v3_madd(ray->o, ray->d, ts);
	vec3 direct = v3_mul(pa->beta, sample_direct_medium(s, set, md, &c, ray->d, x, &pa->in, g, DIM_NEE));
	if (in_part(set, bounce + 1, bounce == 0 ? RENDER_PART_DIRECT : pa->first))
		pa->radiance = v3_add(pa->radiance, direct);
	first_event(pa, RENDER_PART_DIRECT);
	float u_pick = render_sampler_1d(g, DIM_BSDF_LOBE);
	vec2 u = render_sampler_2d(g, DIM_BSDF_DIR);
	vec3 wi, fval;
	float pdf;
	if (!render_media_phase_sample(md, &c, ray->d, u_pick, u, &wi, &fval, &pdf))
		return -1;
	pa->beta = v3_mul(pa->beta, v3_scale(fval, 1.0f / pdf));
	pa->prev_pdf = pdf;
	pa->prev_delta = false;
	pa->passed = pa->stood_for = false;
	pa->scattered = true;
	pa->prev_p = x, pa->prev_n = v3s(0.0f), pa->prev_cosine = true;
	pa->prev_object = UINT32_MAX;
	pa->fog_view = pa->sky_view = false;
	if (!roulette(bounce, g, pa))
		return -1;
	*ray = (render_ray){x, wi};
	return 1;
}

render_sample render_path(const render_scene *s, const render_settings *set, render_ray ray, render_sampler *g)
{
	assert(set->max_trace_level >= 1);
	render_sample out = {0};
	/* prev_delta: the camera's ray, whatever it sees directly counts fully. */
	path pa = {.radiance = v3s(0.0f), .beta = v3s(1.0f), .prev_delta = true, .prev_p = ray.o, .prev_n = v3s(0.0f), .prev_cosine = true, .prev_object = UINT32_MAX,
		   .fog_view = true, .sky_view = true, .medium = -1, .first = RENDER_PART_CAMERA};
	if (s->atmosphere) /* the camera is in the atmosphere */
		pa.in = (nest){.n = 1, .mat = {RENDER_NEST_ATMOSPHERE}, .obj = {UINT32_MAX}};
	/* bounce counts scattering events; passes the thin surfaces passed, which are none. */
	/* vtx counts the loops (the sampler's blocks): bounce does not count thin surfaces. */
	for (int bounce = 0, passes = 0, vtx = 0;; bounce++, vtx++) {
		render_sampler_vertex(g, (uint32_t)vtx);
		pa.bounce = bounce;
		render_hit hit = {0}; /* fields a scene leaves unset stay 0 (scale: unknown) */
		int sphere_light;
		/* the camera's ray alone may be limited (POV-Ray's TraceRay maxDepth, the first call) */
		float tmax = vtx == 0 && set->camera_tmax > 0.0f ? set->camera_tmax : INFINITY;
		bool hit_any = trace(s, &ray, tmax, &hit, &sphere_light);
		if (s->fog_count && pa.fog_view) /* a limited miss: the fog that deep, as POV-Ray's */
			through_fog(s, set, &ray, hit_any ? hit.t : tmax, &pa);
		uint32_t md_obj = 0;
		const render_media *md = any_media(s) && pa.in.n ? nest_media(s, &pa.in, &md_obj) : NULL;
		if (md) {
			/* a limited miss: the media that deep too (POV-Ray's ComputeMedia to that depth) */
			float seg = hit_any ? hit.t : isfinite(tmax) ? tmax : 0.0f;
			int r = through_media(s, set, md, md_obj, seg, bounce, g, &pa, &ray);
			if (r < 0)
				break;
			if (r > 0)
				continue;
		}
		if (!hit_any) /* a leak out of interiors that are not closed */
			pa.in.n = 0, pa.medium = -1;
		if (!hit_any) {
			add_escaped(s, set, bounce, ray.d, &pa);
			break;
		}
		if (pa.medium >= 0)
			pa.beta = v3_mul(pa.beta, bsdf_fade_apply(&s->materials[pa.medium].clear.fade, hit.t));
		add_emitted(s, set, bounce, ray.d, &hit, &pa);
		if (bounce == 0 && passes == 0) {
			out.depth = hit.t;
			out.normal = v3_dot(hit.ns, ray.d) > 0.0f ? v3_neg(hit.ns) : hit.ns;
		}
		bool at_cap = bounce >= set->max_trace_level; /* then only thin surfaces are passed */
		if (sphere_light >= 0 || hit.material < 0 || (size_t)hit.material >= s->material_count ||
		    (at_cap && s->materials[hit.material].clear.kind != BSDF_CLEAR_THIN))
			break;
		vec3 wo = v3_neg(ray.d);
		vertex v;
		if (s->materials[hit.material].layered) /* drawn only there: the random sampler's stream */
			hit.u_layer = render_sampler_1d(g, DIM_LAYER);
		make_vertex(s, &hit, wo, &v);
		/* A POV-Ray finish's ambient and emission: seen by every ray, never sampled as a light. */
		gather(set, &pa, v3_mul(pa.beta, v.b.emit));
		if (bounce == 0 && passes == 0)
			out.albedo = bsdf_albedo(&v.b);
		const render_sss *sm = s->sss ? s->sss[hit.material] : NULL;
		bool entering = v3_dot(hit.ng, wo) >= 0.0f; /* normals point out of objects */
		float p_delta = sm ? 0.0f : delta_prob(&v, entering);
		v.lobe_prob = 1.0f - p_delta;
		if (sm) {
			if (!sss_scatter(s, set, sm, &hit, wo, &v, g, &pa, &out))
				break;
		} else if (v.lobe_prob > 0.0f && !at_cap) {
			/* POV-Ray's highlights are seen by next-event estimation alone, whatever lobe the
			 * path goes on by: delta_prob counts them in the opaque part's weight, so a clear
			 * glass (no diffuse) or a checker's Clear squares with specular or phong keep
			 * lobe_prob > 0, and their highlights, unscaled by the opacity as POV-Ray's (the
			 * light's sample is weighted by MIS against lobe_prob times the BSDF's pdf) */
			add_direct(s, set, &v.b, &v, g, DIM_NEE, RENDER_PART_DIRECT, &pa);
		}
		if (!sm)
			first_event(&pa, RENDER_PART_DIRECT);
		bool delta = p_delta > 0.0f && render_sampler_1d(g, DIM_DELTA) < p_delta;
		if (at_cap && !delta)
			break;
		if (delta) { /* a delta continuation keeps the camera ray's fog, as a mirror's does */
			if (!continue_clear(set, &hit, &v, entering, p_delta, bounce, g, &pa, &ray))
				break;
			if (v.b.clear.kind == BSDF_CLEAR_THIN && ++passes < RENDER_MAX_PASSES)
				bounce--;
		} else if (!continue_path(&v, bounce, g, &pa, &ray)) {
			break;
		} else {
			pa.fog_view = pa.fog_view && pa.prev_pdf >= RENDER_FOG_MIRROR_PDF;
			pa.sky_view = pa.sky_view && pa.prev_pdf >= RENDER_SKY_MIRROR_PDF;
		}
	}
	out.radiance = pa.radiance;
	return out;
}
