/* bsdf.c - Lambert, GGX (visible-normal sampling) and the mixtures of bsdf.h. A mixture picks one
 * lobe with probability proportional to its estimated reflectance and reports the pdf of the whole
 * mixture, so eval/pdf/sample agree for MIS. */
#include "render/bsdf.h"

#include "render/bsdf_pov.h"

#include "render/sampling.h"
#include "sss/profile.h"

static float clamp_alpha(float a)
{
	return fminf(fmaxf(isfinite(a) ? a : 1.0f, BSDF_MIN_ALPHA), 1.0f);
}

bsdf_params bsdf_diffuse(vec3 albedo)
{
	return (bsdf_params){.kind = BSDF_DIFFUSE, .diffuse = albedo, .alpha = 1.0f, .ior = 1.0f};
}

bsdf_params bsdf_pov_finish(vec3 pigment, float kd, float ks, float roughness)
{
	/* Walter et al. 2007, sec. 5.2: Blinn-Phong exponent n ~ 2 / alpha^2 - 2. */
	float n = 1.0f / fmaxf(roughness, 1e-6f);
	return (bsdf_params){.kind = BSDF_PLASTIC,
			     .diffuse = v3_scale(pigment, kd),
			     .specular = v3s(ks),
			     .alpha = clamp_alpha(sqrtf(2.0f / (n + 2.0f))),
			     .ior = 1.0f};
}

bsdf_params bsdf_coat(vec3 albedo, float ior, float roughness)
{
	return (bsdf_params){
	    .kind = BSDF_COAT, .diffuse = albedo, .alpha = clamp_alpha(roughness), .ior = ior};
}

/* One Fresnel formula for circe: the SSS module's, in double. */
float bsdf_fresnel_dielectric(float cos_i, float eta)
{
	return (float)sss_fresnel_dielectric(fmin(fmax(cos_i, 0.0), 1.0), eta);
}

/* Trowbridge-Reitz / GGX: D(h) = alpha^2 / (pi ((alpha^2 - 1) cos^2 + 1)^2) (Walter et al. 2007, eq. 33). */
float bsdf_ggx_d(vec3 h, float alpha)
{
	if (h.z <= 0.0f)
		return 0.0f;
	float a2 = alpha * alpha;
	float t = (a2 - 1.0f) * h.z * h.z + 1.0f;
	return a2 / (RENDER_PI * t * t);
}

/* Smith's Lambda for GGX (Heitz 2014, eq. 72). */
static float ggx_lambda(vec3 w, float alpha)
{
	float c2 = w.z * w.z;
	if (c2 <= 0.0f)
		return 0.0f;
	float tan2 = fmaxf(0.0f, 1.0f - c2) / c2;
	return 0.5f * (-1.0f + sqrtf(1.0f + alpha * alpha * tan2));
}

/* Heitz 2018, listing 1: sample a normal visible from wo (z > 0). */
vec3 bsdf_ggx_sample_vndf(vec3 wo, float alpha, vec2 u)
{
	vec3 vh = v3_normalize(v3(alpha * wo.x, alpha * wo.y, wo.z));
	float lensq = vh.x * vh.x + vh.y * vh.y;
	vec3 t1 = lensq > 0.0f ? v3_scale(v3(-vh.y, vh.x, 0.0f), 1.0f / sqrtf(lensq)) : v3(1, 0, 0);
	vec3 t2 = v3_cross(vh, t1);
	float r = sqrtf(u.x), phi = 2.0f * RENDER_PI * u.y;
	float p1 = r * cosf(phi), p2 = r * sinf(phi);
	float s = 0.5f * (1.0f + vh.z);
	p2 = (1.0f - s) * sqrtf(fmaxf(0.0f, 1.0f - p1 * p1)) + s * p2;
	vec3 nh = v3_add(v3_add(v3_scale(t1, p1), v3_scale(t2, p2)),
			 v3_scale(vh, sqrtf(fmaxf(0.0f, 1.0f - p1 * p1 - p2 * p2))));
	return v3_normalize(v3(alpha * nh.x, alpha * nh.y, fmaxf(1e-7f, nh.z)));
}

/* GGX reflection without Fresnel: D G2 / (4 cos_o cos_i); *h receives the half vector. */
static float ggx_reflect(vec3 wo, vec3 wi, float alpha, vec3 *h)
{
	*h = v3_normalize(v3_add(wo, wi));
	float g2 = 1.0f / (1.0f + ggx_lambda(wo, alpha) + ggx_lambda(wi, alpha));
	return bsdf_ggx_d(*h, alpha) * g2 / (4.0f * wo.z * wi.z);
}

/* Density of wi under visible-normal sampling: G1(wo) D(h) / (4 cos_o) (Heitz 2018, eq. 17 with
 * the reflection Jacobian 1 / (4 wo.h)). */
static float ggx_pdf(vec3 wo, vec3 wi, float alpha)
{
	vec3 h = v3_normalize(v3_add(wo, wi));
	if (v3_dot(wo, h) <= 0.0f)
		return 0.0f;
	float g1 = 1.0f / (1.0f + ggx_lambda(wo, alpha));
	return g1 * bsdf_ggx_d(h, alpha) / (4.0f * wo.z);
}

/* The probability of choosing the specular lobe of a mixture. */
static float spec_prob(const bsdf_params *b, vec3 wo)
{
	float ws, wd;
	if (b->kind == BSDF_PLASTIC) {
		ws = v3_luminance(b->specular);
		wd = v3_luminance(b->diffuse);
	} else if (b->kind == BSDF_COAT) {
		ws = bsdf_fresnel_dielectric(wo.z, b->ior);
		wd = (1.0f - ws) * v3_luminance(b->diffuse);
	} else {
		return 0.0f;
	}
	return ws + wd > 0.0f ? ws / (ws + wd) : 0.5f;
}

vec3 bsdf_eval(const bsdf_params *b, vec3 wo, vec3 wi)
{
	if (wo.z <= 0.0f || wi.z <= 0.0f)
		return v3s(0.0f);
	if (b->kind == BSDF_POV)
		return bsdf_pov_eval(b, wo, wi);
	vec3 h;
	switch (b->kind) {
	case BSDF_DIFFUSE:
		return v3_scale(b->diffuse, RENDER_INV_PI);
	case BSDF_PLASTIC: {
		float s = ggx_reflect(wo, wi, b->alpha, &h);
		return v3_madd(v3_scale(b->diffuse, RENDER_INV_PI), b->specular, s);
	}
	case BSDF_COAT: {
		float s = ggx_reflect(wo, wi, b->alpha, &h) * bsdf_fresnel_dielectric(v3_dot(wi, h), b->ior);
		float t = (1.0f - bsdf_fresnel_dielectric(wo.z, b->ior)) *
			  (1.0f - bsdf_fresnel_dielectric(wi.z, b->ior));
		return v3_add(v3_scale(b->diffuse, t * RENDER_INV_PI), v3s(s));
	}
	case BSDF_SSS_ENTRY:
		return v3_scale(b->diffuse, (1.0f - bsdf_fresnel_dielectric(wi.z, b->ior)) * RENDER_INV_PI);
	case BSDF_POV: /* bsdf_pov_eval, above */
		break;
	}
	return v3s(0.0f);
}

float bsdf_pdf(const bsdf_params *b, vec3 wo, vec3 wi)
{
	if (wo.z <= 0.0f || wi.z <= 0.0f)
		return 0.0f;
	if (b->kind == BSDF_POV)
		return bsdf_pov_pdf(b, wo, wi);
	float ps = spec_prob(b, wo);
	float pd = render_cosine_hemisphere_pdf(wi.z);
	return ps > 0.0f ? ps * ggx_pdf(wo, wi, b->alpha) + (1.0f - ps) * pd : pd;
}

vec3 bsdf_highlights(const bsdf_params *b, vec3 wo, vec3 wi)
{
	return b->kind == BSDF_POV ? bsdf_pov_highlights(b, wo, wi) : v3s(0.0f);
}

vec3 bsdf_shine(const bsdf_params *b, vec3 wo, vec3 wi)
{
	return b->kind == BSDF_POV ? bsdf_pov_shine(b, wo, wi) : v3s(0.0f);
}

vec3 bsdf_eval_delta_light(const bsdf_params *b, vec3 wo, vec3 wi)
{
	return b->kind == BSDF_POV ? bsdf_pov_eval_delta_light(b, wo, wi) : bsdf_eval(b, wo, wi);
}

bool bsdf_sample(const bsdf_params *b, vec3 wo, float u_lobe, vec2 u, vec3 *wi, vec3 *f, float *pdf)
{
	if (wo.z <= 0.0f)
		return false;
	if (b->kind == BSDF_POV) {
		if (!bsdf_pov_sample(b, wo, u_lobe, u, wi))
			return false;
	} else if (u_lobe < spec_prob(b, wo)) {
		vec3 h = bsdf_ggx_sample_vndf(wo, b->alpha, u);
		*wi = v3_sub(v3_scale(h, 2.0f * v3_dot(wo, h)), wo);
	} else {
		*wi = render_cosine_hemisphere(u);
	}
	if (wi->z <= 0.0f)
		return false;
	*pdf = bsdf_pdf(b, wo, *wi);
	*f = b->kind == BSDF_POV ? bsdf_pov_eval_paths(b, wo, *wi) : bsdf_eval(b, wo, *wi);
	return *pdf > 0.0f && isfinite(*pdf);
}

vec3 bsdf_albedo(const bsdf_params *b)
{
	vec3 a = b->kind == BSDF_PLASTIC ? v3_add(b->diffuse, b->specular) : b->diffuse;
	if (b->kind == BSDF_POV) /* the diffuse reflectance; the highlights are no albedo */
		a = v3_add(v3_mul(v3_scale(b->pigment, b->pov.diffuse * b->pov_scale), b->pov_weight),
			   b->pov_layer_diffuse);
	return v3_min(a, v3s(1.0f));
}

/* GGX reflection without Fresnel and its visible-normal density, for the lobes of bsdf_pov.c. */
float bsdf_ggx_reflection(vec3 wo, vec3 wi, float alpha)
{
	vec3 h;
	return ggx_reflect(wo, wi, alpha, &h);
}

float bsdf_ggx_pdf(vec3 wo, vec3 wi, float alpha)
{
	return ggx_pdf(wo, wi, alpha);
}

/* ---- the transparent part ------------------------------------------------------------------ */

bool bsdf_dielectric_sample(vec3 wo, float eta, float reflect, vec3 tint, float u, vec3 *wi, vec3 *weight,
			    bool *refracted)
{
	float cos_o = fminf(fmaxf(wo.z, 0.0f), 1.0f);
	float f = bsdf_fresnel_dielectric(cos_o, eta); /* 1 under total internal reflection */
	float wr = reflect * f, wt = (1.0f - f) * v3_luminance(tint);
	if (!(wr + wt > 0.0f))
		return false;
	float pr = wr / (wr + wt);
	if (u < pr) {
		*wi = v3(-wo.x, -wo.y, wo.z);
		*weight = v3s(wr / pr);
		*refracted = false;
		return true;
	}
	/* Snell: sin_t = sin_o / eta, wi = -wo / eta + n (cos_o / eta - cos_t), n = +z; in double,
	 * where 1 - sin_t^2 is a cancellation at grazing angles. */
	double cos2_t = 1.0 - (1.0 - (double)cos_o * cos_o) / ((double)eta * eta);
	if (!(cos2_t > 0.0))
		return false; /* only when f rounded below 1: no transmission exists */
	*wi = v3_normalize(v3(-wo.x / eta, -wo.y / eta, -(float)sqrt(cos2_t)));
	*weight = v3_scale(tint, (1.0f - f) / (1.0f - pr));
	*refracted = true;
	return true;
}

float bsdf_clear_weight(const bsdf_params *b, vec3 wo, bool entering)
{
	const bsdf_clear *c = &b->clear;
	switch (c->kind) {
	case BSDF_CLEAR_THIN:
		return v3_luminance(c->tint);
	case BSDF_CLEAR_DIELECTRIC: {
		float f = bsdf_fresnel_dielectric(wo.z, entering ? c->ior : 1.0f / c->ior);
		return c->reflect * f + (1.0f - f) * v3_luminance(c->tint);
	}
	case BSDF_CLEAR_NONE:
		break;
	}
	return 0.0f;
}

bool bsdf_clear_sample(const bsdf_params *b, vec3 wo, bool entering, float u, vec3 *wi, vec3 *weight,
		       bool *refracted)
{
	const bsdf_clear *c = &b->clear;
	if (c->kind == BSDF_CLEAR_THIN) {
		*wi = v3_neg(wo);
		*weight = c->tint;
		*refracted = true;
		return v3_max_comp(c->tint) > 0.0f;
	}
	if (c->kind != BSDF_CLEAR_DIELECTRIC)
		return false;
	return bsdf_dielectric_sample(wo, entering ? c->ior : 1.0f / c->ior, c->reflect, c->tint, u, wi, weight,
				      refracted);
}

vec3 bsdf_clear_shadow(const bsdf_params *b, float cos)
{
	const bsdf_clear *c = &b->clear;
	if (c->kind == BSDF_CLEAR_NONE)
		return v3s(0.0f);
	if (c->kind == BSDF_CLEAR_THIN)
		return c->tint;
	return v3_scale(c->tint, 1.0f - bsdf_fresnel_dielectric(fabsf(cos), c->ior));
}

static float fade_channel(const bsdf_fade *f, float kept, float d)
{
	if (f->power >= 1000.0f)
		return expf(-(1.0f - kept) * d / f->distance);
	return kept + (1.0f - kept) / (1.0f + powf(d / f->distance, f->power));
}

vec3 bsdf_fade_apply(const bsdf_fade *f, float d)
{
	if (!(f->distance > 0.0f) || !(f->power > 0.0f) || !(d > 0.0f))
		return v3s(1.0f);
	return v3(fade_channel(f, f->color.x, d), fade_channel(f, f->color.y, d), fade_channel(f, f->color.z, d));
}
