/* bsdf_pov.c - POV-Ray's finish as four lobes (diffuse, specular, phong, reflection) that add,
 * scaled together when they could reflect more than comes in. The mixture picks one lobe with
 * probability proportional to its weight at wo and reports the pdf of the whole mixture. */
#include "render/bsdf_pov.h"

#include "render/sampling.h"

enum { LOBE_DIFFUSE, LOBE_SPECULAR, LOBE_PHONG, LOBE_REFLECTION, LOBE_COUNT };

float bsdf_pov_blinn_alpha(float n)
{
	/* Walter et al. 2007, sec. 5.2: Blinn-Phong exponent n ~ 2 / alpha^2 - 2. */
	float a = sqrtf(2.0f / (fmaxf(n, 0.0f) + 2.0f));
	return fminf(fmaxf(a, BSDF_MIN_ALPHA), 1.0f);
}

float bsdf_pov_blinn_weight(float n)
{
	/* GGX's peak D(n) / (4 cos_o cos_i) = 1 / (4 pi alpha^2) at normal incidence against POV-Ray's
	 * (N.H)^n / pi there (per unit Ks, the light scaled by pi): weight 4 alpha^2, at most 1. */
	float a = bsdf_pov_blinn_alpha(n);
	return fminf(4.0f * a * a, 1.0f);
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
static float phong_n(const bsdf_pov_finish_spec *f) { return 4.0f * f->phong_size; }

void bsdf_pov_set_pigment(bsdf_params *b, vec3 pigment)
{
	const bsdf_pov_finish_spec *f = &b->pov;
	b->pigment = v3_min(v3_max(pigment, v3s(0.0f)), v3s(1.0f));
	/* The largest the lobes can reflect in any channel: every tint is at most 1. */
	float hl = f->specular * bsdf_pov_blinn_weight(spec_n(f)) + f->phong * bsdf_pov_blinn_weight(phong_n(f));
	/* The diffuse term: the Lambert lobe's Kd, or a subsurface texture's (its BSSRDF's albedo,
	 * scaled with the lobes so that the whole still reflects at most 1). */
	float kd = f->sss_diffuse > 0.0f ? f->sss_diffuse : f->diffuse;
	vec3 sum = v3_add(v3_scale(b->pigment, kd), v3s(hl));
	sum = v3_add(sum, v3_max(f->refl_min, f->refl_max));
	float m = v3_max_comp(sum);
	b->pov_scale = m > 1.0f ? 1.0f / m : 1.0f;
	b->diffuse = v3_scale(b->pigment, kd * b->pov_scale);
	b->emit = v3_mul(f->glow, b->pigment);
}

bsdf_params bsdf_pov(const bsdf_pov_finish_spec *f, vec3 pigment)
{
	bsdf_params b = {.kind = BSDF_POV, .alpha = 1.0f, .ior = 1.0f, .pov = *f};
	bsdf_pov_set_pigment(&b, pigment);
	return b;
}

/* The lobes' weights (luminance) at wo, normalised: the probabilities of choosing each. */
static void lobe_probs(const bsdf_params *b, vec3 wo, float p[LOBE_COUNT])
{
	const bsdf_pov_finish_spec *f = &b->pov;
	/* A subsurface texture's b->diffuse is the BSSRDF's albedo: it has no Lambert lobe. */
	p[LOBE_DIFFUSE] = f->sss_diffuse > 0.0f ? 0.0f : v3_luminance(b->diffuse);
	p[LOBE_SPECULAR] = f->specular * bsdf_pov_blinn_weight(spec_n(f)) *
			   v3_luminance(metallic_tint(f->metallic, b->pigment, wo.z));
	p[LOBE_PHONG] = f->phong * bsdf_pov_blinn_weight(phong_n(f)) *
			v3_luminance(metallic_tint(f->metallic, b->pigment, wo.z));
	p[LOBE_REFLECTION] = has_reflection(f) ? v3_luminance(reflectivity(f, b->pigment, wo.z)) : 0.0f;
	float sum = 0.0f;
	for (int k = 0; k < LOBE_COUNT; k++)
		sum += p[k] = fmaxf(p[k], 0.0f);
	for (int k = 0; k < LOBE_COUNT; k++)
		p[k] = sum > 0.0f ? p[k] / sum : (k == LOBE_DIFFUSE);
}

vec3 bsdf_pov_eval(const bsdf_params *b, vec3 wo, vec3 wi)
{
	if (wo.z <= 0.0f || wi.z <= 0.0f)
		return v3s(0.0f);
	const bsdf_pov_finish_spec *f = &b->pov;
	vec3 h = v3_normalize(v3_add(wo, wi));
	float c = fminf(fmaxf(v3_dot(wi, h), 0.0f), 1.0f);
	vec3 r = v3_scale(b->pigment, f->diffuse * RENDER_INV_PI);
	vec3 tint = metallic_tint(f->metallic, b->pigment, c);
	if (f->specular > 0.0f) {
		float n = spec_n(f);
		float g = f->specular * bsdf_pov_blinn_weight(n) * bsdf_ggx_reflection(wo, wi, bsdf_pov_blinn_alpha(n));
		r = v3_madd(r, tint, g);
	}
	if (f->phong > 0.0f) {
		float n = phong_n(f);
		float g = f->phong * bsdf_pov_blinn_weight(n) * bsdf_ggx_reflection(wo, wi, bsdf_pov_blinn_alpha(n));
		r = v3_madd(r, tint, g);
	}
	if (has_reflection(f))
		r = v3_madd(r, reflectivity(f, b->pigment, c), bsdf_ggx_reflection(wo, wi, BSDF_POV_MIRROR_ALPHA));
	return v3_scale(r, b->pov_scale);
}

float bsdf_pov_pdf(const bsdf_params *b, vec3 wo, vec3 wi)
{
	if (wo.z <= 0.0f || wi.z <= 0.0f)
		return 0.0f;
	float p[LOBE_COUNT];
	lobe_probs(b, wo, p);
	const bsdf_pov_finish_spec *f = &b->pov;
	float pdf = p[LOBE_DIFFUSE] * render_cosine_hemisphere_pdf(wi.z);
	if (p[LOBE_SPECULAR] > 0.0f)
		pdf += p[LOBE_SPECULAR] * bsdf_ggx_pdf(wo, wi, bsdf_pov_blinn_alpha(spec_n(f)));
	if (p[LOBE_PHONG] > 0.0f)
		pdf += p[LOBE_PHONG] * bsdf_ggx_pdf(wo, wi, bsdf_pov_blinn_alpha(phong_n(f)));
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
	const bsdf_pov_finish_spec *f = &b->pov;
	float alpha = k == LOBE_SPECULAR ? bsdf_pov_blinn_alpha(spec_n(f))
		      : k == LOBE_PHONG  ? bsdf_pov_blinn_alpha(phong_n(f))
					 : BSDF_POV_MIRROR_ALPHA;
	vec3 h = bsdf_ggx_sample_vndf(wo, alpha, u);
	*wi = v3_sub(v3_scale(h, 2.0f * v3_dot(wo, h)), wo);
	return true;
}
