/* bsdf_pov.c - POV-Ray's finish as four lobes (diffuse, specular, phong, reflection) that add,
 * scaled together when they could reflect more than comes in. Paths sample the diffuse and
 * reflection lobes (one picked with probability proportional to its weight at wo, the pdf that of
 * the mixture); the highlights are POV-Ray's own formulas, seen by next-event estimation only. */
#include "render/bsdf_pov.h"

#include "render/sampling.h"

enum { LOBE_DIFFUSE, LOBE_REFLECTION, LOBE_COUNT };

float bsdf_pov_specular_albedo(float n)
{
	/* Ks (N.H)^n / (pi cos_i) times cos_i over the hemisphere at normal incidence (H halves the
	 * angle of wi): 8 (1 - 2^(-(n + 2) / 2)) / (n + 2) per unit Ks; less towards grazing. */
	n = fmaxf(n, 0.0f);
	return fminf(8.0f * (1.0f - powf(2.0f, -0.5f * (n + 2.0f))) / (n + 2.0f), 1.0f);
}

float bsdf_pov_phong_albedo(float p)
{
	/* Kp (R.L)^p / (pi cos_i) times cos_i over the hemisphere about R: at most 2 / (p + 1). */
	return fminf(2.0f / (fmaxf(p, 0.0f) + 1.0f), 1.0f);
}

float bsdf_pov_metallic_fresnel(float c)
{
	/* POV-Ray 3.7 trace.cpp ComputeMetallic [DB 9/94]: x = angle / (pi / 2). */
	float x = acosf(fminf(fmaxf(c, 0.0f), 1.0f)) / (0.5f * RENDER_PI);
	float d = x - 1.12f;
	float f = 0.014567225f / (d * d) - 0.011612903f;
	return fminf(fmaxf(f, 0.0f), 1.0f);
}

/* The tint of a highlight or reflection of metallic amount m over pigment P at cos c. */
static vec3 metallic_tint(float m, vec3 pigment, float c)
{
	if (m <= 0.0f)
		return v3s(1.0f);
	float k = m * (1.0f - bsdf_pov_metallic_fresnel(c));
	return v3_add(v3s(1.0f), v3_scale(v3_sub(pigment, v3s(1.0f)), k));
}

/* POV-Ray's reflectivity at cos c (trace.cpp ComputeReflectivity, ComputeFresnel). */
static vec3 reflectivity(const bsdf_pov_finish_spec *f, vec3 pigment, float c)
{
	float t;
	if (f->refl_ior > 0.0f)
		t = bsdf_fresnel_dielectric(c, f->refl_ior);
	else
		t = powf(fmaxf(1.0f - c, 0.0f), f->refl_falloff);
	vec3 r = v3_lerp(f->refl_min, f->refl_max, t);
	return v3_mul(r, metallic_tint(f->refl_metallic, pigment, c));
}

static bool has_reflection(const bsdf_pov_finish_spec *f)
{
	return v3_max_comp(f->refl_min) > 0.0f || v3_max_comp(f->refl_max) > 0.0f;
}

static float spec_n(const bsdf_pov_finish_spec *f) { return 1.0f / fmaxf(f->roughness, 1e-6f); }

/* The largest the lobes over b->pigment can reflect in each channel, before pov_scale (every
 * tint is at most 1): the diffuse term (the Lambert lobe's Kd, or a subsurface texture's: its
 * BSSRDF's albedo, scaled with the lobes so that the whole still reflects at most 1), the
 * highlights' albedos, the reflection's largest. */
static vec3 lobes_bound(const bsdf_params *b)
{
	const bsdf_pov_finish_spec *f = &b->pov;
	float hl = f->specular * bsdf_pov_specular_albedo(spec_n(f)) + f->phong * bsdf_pov_phong_albedo(f->phong_size);
	float kd = f->sss_diffuse > 0.0f ? f->sss_diffuse : f->diffuse;
	vec3 sum = v3_add(v3_scale(b->pigment, kd), v3s(hl));
	return v3_add(sum, v3_max(f->refl_min, f->refl_max));
}

vec3 bsdf_pov_albedo_bound(const bsdf_params *b)
{
	return v3_add(v3_mul(v3_scale(lobes_bound(b), b->pov_scale), b->pov_weight), b->pov_layer_diffuse);
}

static bool has_layer_diffuse(const bsdf_params *b) { return v3_max_comp(b->pov_layer_diffuse) > 0.0f; }

void bsdf_pov_set_pigment(bsdf_params *b, vec3 pigment)
{
	const bsdf_pov_finish_spec *f = &b->pov;
	b->pigment = v3_min(v3_max(pigment, v3s(0.0f)), v3s(1.0f));
	float kd = f->sss_diffuse > 0.0f ? f->sss_diffuse : f->diffuse;
	float m = v3_max_comp(lobes_bound(b));
	b->pov_scale = m > 1.0f ? 1.0f / m : 1.0f;
	b->diffuse = v3_scale(b->pigment, kd * b->pov_scale);
	b->emit = v3_mul(f->glow, b->pigment);
}

bsdf_params bsdf_pov(const bsdf_pov_finish_spec *f, vec3 pigment)
{
	bsdf_params b = {.kind = BSDF_POV, .alpha = 1.0f, .ior = 1.0f, .pov = *f, .pov_weight = v3s(1.0f)};
	bsdf_pov_set_pigment(&b, pigment);
	return b;
}

/* The lobes' weights (luminance) at wo, normalised: the probabilities of choosing each. */
static void lobe_probs(const bsdf_params *b, vec3 wo, float p[LOBE_COUNT])
{
	const bsdf_pov_finish_spec *f = &b->pov;
	/* A subsurface texture's b->diffuse is the BSSRDF's albedo: it has no Lambert lobe. */
	p[LOBE_DIFFUSE] = f->sss_diffuse > 0.0f ? 0.0f : v3_luminance(b->diffuse);
	p[LOBE_REFLECTION] = has_reflection(f) ? v3_luminance(reflectivity(f, b->pigment, wo.z)) : 0.0f;
	if (has_layer_diffuse(b)) { /* the picked layer's lobes at their weight beside the layers' diffuse */
		vec3 w = v3_scale(b->pov_weight, b->pov_scale);
		p[LOBE_DIFFUSE] = v3_luminance(v3_mul(v3_scale(b->pigment, f->sss_diffuse > 0.0f ? 0.0f : f->diffuse), w));
		p[LOBE_DIFFUSE] += v3_luminance(b->pov_layer_diffuse);
		p[LOBE_REFLECTION] = has_reflection(f) ? v3_luminance(v3_mul(reflectivity(f, b->pigment, wo.z), w)) : 0.0f;
	}
	float sum = 0.0f;
	for (int k = 0; k < LOBE_COUNT; k++)
		sum += p[k] = fmaxf(p[k], 0.0f);
	for (int k = 0; k < LOBE_COUNT; k++)
		p[k] = sum > 0.0f ? p[k] / sum : 0.0f; /* nothing paths carry: the path ends */
}

vec3 bsdf_pov_eval_paths(const bsdf_params *b, vec3 wo, vec3 wi)
{
	if (wo.z <= 0.0f || wi.z <= 0.0f)
		return v3s(0.0f);
	const bsdf_pov_finish_spec *f = &b->pov;
	vec3 h = v3_normalize(v3_add(wo, wi));
	float c = fminf(fmaxf(v3_dot(wi, h), 0.0f), 1.0f);
	vec3 r = v3_scale(b->pigment, f->diffuse * RENDER_INV_PI);
	if (has_reflection(f))
		r = v3_madd(r, reflectivity(f, b->pigment, c), bsdf_ggx_reflection(wo, wi, BSDF_POV_MIRROR_ALPHA));
	r = v3_mul(v3_scale(r, b->pov_scale), b->pov_weight);
	return has_layer_diffuse(b) ? v3_madd(r, b->pov_layer_diffuse, RENDER_INV_PI) : r;
}

/* The highlights of light sources; with shine false only the brilliance's part (bsdf_pov_shine). */
static vec3 highlights(const bsdf_params *b, vec3 wo, vec3 wi, bool shine)
{
	const bsdf_pov_finish_spec *f = &b->pov;
	bool bright = f->brilliance_less_1 != 0.0f && f->diffuse > 0.0f && f->sss_diffuse <= 0.0f;
	if (wo.z <= 0.0f || wi.z <= 0.0f || ((!shine || (f->specular <= 0.0f && f->phong <= 0.0f)) && !bright))
		return v3s(0.0f);
	vec3 r = v3s(0.0f);
	if (bright) { /* POV-Ray's Kd' cos^b beside the Lambert lobe's Kd cos (bsdf_pov.h) */
		float bm1 = f->brilliance_less_1, full = f->diffuse * 0.5f * (bm1 + 2.0f);
		float d = (full * powf(wi.z, bm1) - f->diffuse) * wi.z; /* the cosine POV-Ray's term has */
		r = v3_madd(r, b->pigment, d);
	}
	if (shine && f->specular > 0.0f) { /* trace.cpp ComputeSpecularColour: Ks (N.H)^(1/roughness) */
		vec3 h = v3_normalize(v3_add(wo, wi));
		if (h.z > 0.0f)
			r = v3_madd(r, metallic_tint(f->metallic, b->pigment, fminf(fmaxf(v3_dot(wi, h), 0.0f), 1.0f)),
				    f->specular * powf(h.z, spec_n(f)));
	}
	if (shine && f->phong > 0.0f) { /* ComputePhongColour: Kp (R.L)^phong_size, R the mirror of the eye */
		float rl = 2.0f * wo.z * wi.z - v3_dot(wo, wi);
		if (rl > 0.0f)
			r = v3_madd(r, metallic_tint(f->metallic, b->pigment, wi.z), f->phong * powf(rl, f->phong_size));
	}
	/* POV-Ray adds this to the colour without the cosine its diffuse has; under a light scaled by
	 * pi (build_light.c) the BSDF that gives it is this / (pi cos_i). */
	return v3_mul(v3_scale(r, b->pov_scale * RENDER_INV_PI / wi.z), b->pov_weight);
}

vec3 bsdf_pov_highlights(const bsdf_params *b, vec3 wo, vec3 wi) { return highlights(b, wo, wi, true); }

vec3 bsdf_pov_shine(const bsdf_params *b, vec3 wo, vec3 wi)
{
	return v3_sub(highlights(b, wo, wi, true), highlights(b, wo, wi, false));
}

vec3 bsdf_pov_eval(const bsdf_params *b, vec3 wo, vec3 wi)
{
	return v3_add(bsdf_pov_eval_paths(b, wo, wi), bsdf_pov_highlights(b, wo, wi));
}

vec3 bsdf_pov_eval_delta_light(const bsdf_params *b, vec3 wo, vec3 wi)
{
	if (wo.z <= 0.0f || wi.z <= 0.0f)
		return v3s(0.0f);
	vec3 r = v3_mul(v3_scale(b->pigment, b->pov.diffuse * RENDER_INV_PI * b->pov_scale), b->pov_weight);
	if (has_layer_diffuse(b))
		r = v3_madd(r, b->pov_layer_diffuse, RENDER_INV_PI);
	return v3_add(r, bsdf_pov_highlights(b, wo, wi));
}

float bsdf_pov_pdf(const bsdf_params *b, vec3 wo, vec3 wi)
{
	if (wo.z <= 0.0f || wi.z <= 0.0f)
		return 0.0f;
	float p[LOBE_COUNT];
	lobe_probs(b, wo, p);
	float pdf = p[LOBE_DIFFUSE] * render_cosine_hemisphere_pdf(wi.z);
	if (p[LOBE_REFLECTION] > 0.0f)
		pdf += p[LOBE_REFLECTION] * bsdf_ggx_pdf(wo, wi, BSDF_POV_MIRROR_ALPHA);
	return pdf;
}

bool bsdf_pov_sample(const bsdf_params *b, vec3 wo, float u_lobe, vec2 u, vec3 *wi)
{
	float p[LOBE_COUNT];
	lobe_probs(b, wo, p);
	int k = -1;
	float acc = 0.0f;
	for (int j = 0; j < LOBE_COUNT; j++) /* the last lobe of non-zero weight catches rounding */
		if (p[j] > 0.0f && (k < 0 || u_lobe >= acc)) {
			k = j;
			acc += p[j];
		}
	if (k < 0)
		return false;
	if (k == LOBE_DIFFUSE) {
		*wi = render_cosine_hemisphere(u);
		return true;
	}
	vec3 h = bsdf_ggx_sample_vndf(wo, BSDF_POV_MIRROR_ALPHA, u);
	*wi = v3_sub(v3_scale(h, 2.0f * v3_dot(wo, h)), wo);
	return true;
}
