/* integrator.c - path tracing with NEE and MIS (integrator.h). The shading frame's +z is the
 * shading normal turned to the side of the outgoing direction; a direction on the far side of the
 * geometric normal is rejected so shading normals cannot leak light through a surface. */
#include "render/integrator.h"

/* Ray origins are pushed off the surface by this times (1 + largest |coordinate|): float
 * positions carry that much relative error after intersection. */
#define RENDER_RAY_EPS 1e-4f
/* Shadow rays stop this fraction short of the light so they do not hit the emitter itself. */
#define RENDER_SHADOW_EPS 1e-3f

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

static vec3 offset_origin(vec3 p, vec3 n_out)
{
	float scale = 1.0f + v3_max_comp(v3_abs(p));
	return v3_madd(p, n_out, RENDER_RAY_EPS * scale);
}

/* Nearest surface: the scene's or a sphere light's. *light_hit receives the sphere light's index
 * when that is nearer, else -1. */
static bool trace(const render_scene *s, const render_ray *ray, render_hit *hit, int *sphere_light)
{
	bool found = s->intersect(s->user, ray, 0.0f, INFINITY, hit);
	*sphere_light = -1;
	const light_set *ls = s->lights;
	for (size_t i = 0; ls && i < ls->count; i++) {
		const light *l = &ls->lights[i];
		float t;
		if (l->kind == LIGHT_SPHERE &&
		    light_sphere_hit(l, ray, 0.0f, found ? hit->t : INFINITY, &t)) {
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

/* Next-event estimation from hit point p: one light picked by power, one sample of it. */
static vec3 sample_direct(const render_scene *s, const render_settings *set, const bsdf_params *b,
			  const frame *f, vec3 ng_out, vec3 p, vec3 wo_local, rng *g)
{
	const light_set *ls = s->lights;
	if (!ls || ls->count == 0)
		return v3s(0.0f);
	float pick;
	size_t li = light_set_pick(ls, rng_float(g), &pick);
	vec2 u = v2(rng_float(g), rng_float(g));
	light_sample ls_out;
	if (!(pick > 0.0f) || !light_sample_from(&ls->lights[li], p, u, &ls_out))
		return v3s(0.0f);
	if (v3_dot(ls_out.wi, ng_out) <= 0.0f)
		return v3s(0.0f);
	vec3 wi_local = to_local(f, ls_out.wi);
	vec3 fval = bsdf_eval(b, wo_local, wi_local);
	if (v3_max_comp(fval) <= 0.0f)
		return v3s(0.0f);
	render_ray shadow = {offset_origin(p, ng_out), ls_out.wi};
	float tmax = isfinite(ls_out.dist) ? ls_out.dist * (1.0f - RENDER_SHADOW_EPS) : INFINITY;
	if (s->occluded(s->user, &shadow, 0.0f, tmax))
		return v3s(0.0f);
	float light_pdf = pick * ls_out.pdf;
	float w = (ls_out.delta || set->mode == RENDER_LIGHT_ONLY)
		      ? 1.0f
		      : render_power_heuristic(light_pdf, bsdf_pdf(b, wo_local, wi_local));
	return v3_scale(v3_mul(fval, ls_out.li), w * fabsf(wi_local.z) / light_pdf);
}

render_sample render_path(const render_scene *s, const render_settings *set, render_ray ray, rng *g)
{
	render_sample out = {0};
	vec3 radiance = v3s(0.0f), beta = v3s(1.0f);
	float prev_pdf = 0.0f;
	bool prev_delta = true; /* the camera: whatever it sees directly counts fully */
	vec3 prev_p = ray.o;
	const light_set *ls = s->lights;
	for (int bounce = 0;; bounce++) {
		render_hit hit;
		int sphere_light;
		if (!trace(s, &ray, &hit, &sphere_light)) {
			for (size_t k = 0; ls && k < ls->infinite_count; k++) {
				const light *l = &ls->lights[ls->infinite[k]];
				float lp = light_set_prob(ls, ls->infinite[k]) *
					   light_pdf(l, prev_p, ray.d, INFINITY, v3s(0));
				float w = emitter_weight(set, bounce, prev_delta, prev_pdf, lp);
				radiance =
				    v3_add(radiance, v3_scale(v3_mul(beta, light_radiance_dir(l, ray.d)), w));
			}
			break;
		}
		if (hit.light >= 0 && ls && (size_t)hit.light < ls->count) {
			const light *l = &ls->lights[hit.light];
			float lp = light_set_prob(ls, (size_t)hit.light) *
				   light_pdf(l, prev_p, ray.d, hit.t, hit.ng);
			float w = emitter_weight(set, bounce, prev_delta, prev_pdf, lp);
			radiance = v3_add(radiance, v3_scale(v3_mul(beta, l->color), w));
		}
		if (bounce == 0) {
			out.depth = hit.t;
			out.normal = v3_dot(hit.ns, ray.d) > 0.0f ? v3_neg(hit.ns) : hit.ns;
		}
		if (sphere_light >= 0 || hit.material < 0 || (size_t)hit.material >= s->material_count ||
		    bounce >= set->max_trace_level)
			break;

		bsdf_params b = s->materials[hit.material];
		vec3 ns = hit.ns;
		if (s->shade)
			s->shade(s->user, &hit, &b, &ns);
		if (bounce == 0)
			out.albedo = bsdf_albedo(&b);
		vec3 wo = v3_neg(ray.d);
		vec3 ng_out = v3_dot(hit.ng, wo) >= 0.0f ? hit.ng : v3_neg(hit.ng);
		frame f;
		f.n = v3_dot(ns, ng_out) >= 0.0f ? ns : v3_neg(ns);
		/* A shading normal turned away from the viewer (strong normal maps, coarse meshes)
		 * would leave wo below the BSDF's horizon: shade with the true normal instead. */
		if (v3_dot(f.n, wo) <= 0.0f)
			f.n = ng_out;
		v3_basis(f.n, &f.t, &f.b);
		vec3 wo_local = to_local(&f, wo);

		if (set->mode != RENDER_BSDF_ONLY)
			radiance =
			    v3_add(radiance,
				   v3_mul(beta, sample_direct(s, set, &b, &f, ng_out, hit.p, wo_local, g)));

		float u_lobe = rng_float(g);
		vec2 u = v2(rng_float(g), rng_float(g));
		vec3 wi_local, fval;
		float pdf;
		if (!bsdf_sample(&b, wo_local, u_lobe, u, &wi_local, &fval, &pdf))
			break;
		vec3 wi = to_world(&f, wi_local);
		if (v3_dot(wi, ng_out) <= 0.0f)
			break;
		beta = v3_mul(beta, v3_scale(fval, fabsf(wi_local.z) / pdf));
		prev_pdf = pdf;
		prev_delta = false;
		prev_p = hit.p;
		if (bounce + 1 >= RENDER_RR_DEPTH) {
			float q = fminf(1.0f, v3_max_comp(beta));
			if (!(rng_float(g) < q))
				break;
			beta = v3_scale(beta, 1.0f / q);
		}
		ray = (render_ray){offset_origin(hit.p, ng_out), v3_normalize(wi)};
	}
	out.radiance = radiance;
	return out;
}
