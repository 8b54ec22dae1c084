/* media.c - coefficients, phase functions, delta and ratio tracking of POV-Ray's media (media.h). */
#include "render/media.h"

#include <math.h>

#define INV_4PI 0.0795774715f

/* Below this |g| Henyey-Greenstein is sampled as isotropic (its inversion divides by g). */
#define PHASE_HG_ISOTROPIC_G 1e-3f

static float sum3(vec3 v) { return v.x + v.y + v.z; }

static vec3 sigma_t_of(const render_medium *m)
{
	return v3_add(m->absorption, v3_scale(m->scattering, m->extinction));
}

void render_media_finish(render_media *md)
{
	vec3 maj = v3s(0.0f);
	md->homogeneous = true, md->scatters = md->emits = false;
	for (uint32_t i = 0; i < md->n; i++) {
		const render_medium *m = &md->m[i];
		vec3 dmax = m->n_density ? m->density_max : v3s(1.0f);
		maj = v3_add(maj, v3_mul(dmax, sigma_t_of(m)));
		md->homogeneous &= m->n_density == 0;
		md->scatters |= v3_max_comp(v3_mul(dmax, m->scattering)) > 0.0f;
		md->emits |= v3_max_comp(v3_mul(dmax, m->emission)) > 0.0f;
	}
	md->majorant = v3_max_comp(maj);
}

void render_media_coef_at(const render_media *md, render_density_fn f, const void *ctx, vec3 p, render_media_coef *c)
{
	c->sigma_t = c->emission = c->sigma_s = v3s(0.0f);
	for (uint32_t i = 0; i < md->n; i++) {
		const render_medium *m = &md->m[i];
		vec3 d = m->n_density && f ? f(ctx, m, p) : v3s(1.0f);
		c->sigma_s_of[i] = v3_mul(d, m->scattering);
		c->sigma_s = v3_add(c->sigma_s, c->sigma_s_of[i]);
		c->sigma_t = v3_add(c->sigma_t, v3_mul(d, sigma_t_of(m)));
		c->emission = v3_add(c->emission, v3_mul(d, m->emission));
	}
}

/* POV-Ray's Mie shapes 1 + b ((1 + mu) / 2)^n (media.cpp; after Nishita et al. 1987): b, n. */
static void mie_shape(render_phase k, float *b, float *n)
{
	*b = k == RENDER_PHASE_MIE_HAZY ? 9.0f : 50.0f;
	*n = k == RENDER_PHASE_MIE_HAZY ? 8.0f : 32.0f;
}

float render_phase_pdf(render_phase k, float g, float mu)
{
	switch (k) {
	case RENDER_PHASE_MIE_HAZY:
	case RENDER_PHASE_MIE_MURKY: {
		/* integral over the sphere: 4 pi (1 + b / (n + 1)) */
		float b, n;
		mie_shape(k, &b, &n);
		return (1.0f + b * powf(0.5f * (1.0f + mu), n)) * INV_4PI / (1.0f + b / (n + 1.0f));
	}
	case RENDER_PHASE_RAYLEIGH:
		return 3.0f / (16.0f * (float)M_PI) * (1.0f + mu * mu);
	case RENDER_PHASE_HG: {
		float d = 1.0f + g * g - 2.0f * g * mu;
		return INV_4PI * (1.0f - g * g) / (d * sqrtf(d));
	}
	case RENDER_PHASE_ISOTROPIC:
	default:
		return INV_4PI;
	}
}

float render_phase_sample_mu(render_phase k, float g, float u)
{
	switch (k) {
	case RENDER_PHASE_MIE_HAZY:
	case RENDER_PHASE_MIE_MURKY: {
		/* A mixture: uniform in x = (1 + mu) / 2 with weight 1, density (n + 1) x^n with
		 * weight b / (n + 1); u is reused inside the branch it chose. */
		float b, n;
		mie_shape(k, &b, &n);
		float p_uni = 1.0f / (1.0f + b / (n + 1.0f));
		if (u < p_uni)
			return fminf(1.0f, 2.0f * (u / p_uni) - 1.0f);
		float v = fminf(1.0f, (u - p_uni) / (1.0f - p_uni));
		return 2.0f * powf(v, 1.0f / (n + 1.0f)) - 1.0f;
	}
	case RENDER_PHASE_RAYLEIGH: {
		/* 3/4 uniform in mu, 1/4 of density 3/2 mu^2 (its CDF (mu^3 + 1) / 2). */
		if (u < 0.75f)
			return fminf(1.0f, 2.0f * (u / 0.75f) - 1.0f);
		return cbrtf(fminf(1.0f, 2.0f * ((u - 0.75f) / 0.25f) - 1.0f));
	}
	case RENDER_PHASE_HG:
		if (fabsf(g) >= PHASE_HG_ISOTROPIC_G) {
			/* The inverse of the CDF of (1 - g^2) / (2 (1 + g^2 - 2 g mu)^(3/2)). */
			float s = (1.0f - g * g) / (1.0f + g - 2.0f * g * u);
			return fmaxf(-1.0f, fminf(1.0f, (1.0f + g * g - s * s) / (2.0f * g)));
		}
		return 1.0f - 2.0f * u;
	case RENDER_PHASE_ISOTROPIC:
	default:
		return 1.0f - 2.0f * u;
	}
}

vec3 render_media_phase_eval(const render_media *md, const render_media_coef *c, vec3 d_in, vec3 wi, float *pdf)
{
	float mu = v3_dot(d_in, wi), total = sum3(c->sigma_s);
	vec3 f = v3s(0.0f);
	*pdf = 0.0f;
	if (!(total > 0.0f))
		return f;
	for (uint32_t i = 0; i < md->n; i++) {
		float p = render_phase_pdf(md->m[i].phase, md->m[i].g, mu);
		f = v3_add(f, v3_scale(c->sigma_s_of[i], p));
		*pdf += sum3(c->sigma_s_of[i]) / total * p;
	}
	return f;
}

bool render_media_phase_sample(const render_media *md, const render_media_coef *c, vec3 d_in, float u_pick, vec2 u,
			       vec3 *wi, vec3 *fval, float *pdf)
{
	float total = sum3(c->sigma_s), acc = 0.0f;
	if (!(total > 0.0f))
		return false;
	uint32_t k = 0;
	for (uint32_t i = 0; i < md->n; i++) {
		acc += sum3(c->sigma_s_of[i]) / total;
		k = i;
		if (u_pick < acc && sum3(c->sigma_s_of[i]) > 0.0f)
			break;
	}
	float mu = render_phase_sample_mu(md->m[k].phase, md->m[k].g, u.x);
	float s = sqrtf(fmaxf(0.0f, 1.0f - mu * mu)), phi = 2.0f * (float)M_PI * u.y;
	vec3 t, b;
	v3_basis(d_in, &t, &b);
	*wi = v3_normalize(v3_add(v3_scale(d_in, mu), v3_add(v3_scale(t, s * cosf(phi)), v3_scale(b, s * sinf(phi)))));
	*fval = render_media_phase_eval(md, c, d_in, *wi, pdf);
	return *pdf > 0.0f && v3_is_finite(*wi);
}

static float exp_sample(rng *g, float rate) { return -logf(1.0f - rng_float(g)) / rate; }

/* exp(-sigma t) per channel; 1 where sigma is 0 (also for an infinite t). */
static float exp_neg(float sigma, float t) { return sigma > 0.0f ? expf(-sigma * t) : 1.0f; }
static vec3 transmit(vec3 sigma, float t) { return v3(exp_neg(sigma.x, t), exp_neg(sigma.y, t), exp_neg(sigma.z, t)); }

/* The integral of exp(-s t) e over t in [0, len], per channel: e (1 - exp(-s len)) / s. */
static float emitted(float e, float s, float len)
{
	return s * len > 1e-4f ? e * (1.0f - expf(-s * len)) / s : e * len * (1.0f - 0.5f * s * len);
}

bool render_media_track(const render_media *md, render_density_fn f, const void *ctx, vec3 o, vec3 d, float tmax,
			rng *g, vec3 *beta, vec3 *radiance, render_media_coef *c, float *t_out)
{
	if (!(tmax > 0.0f) || !isfinite(tmax))
		return false;
	if (md->homogeneous && !md->scatters) { /* closed form: Beer-Lambert and its emission */
		render_media_coef_at(md, f, ctx, o, c);
		vec3 e = v3(emitted(c->emission.x, c->sigma_t.x, tmax), emitted(c->emission.y, c->sigma_t.y, tmax),
			    emitted(c->emission.z, c->sigma_t.z, tmax));
		*radiance = v3_add(*radiance, v3_mul(*beta, e));
		*beta = v3_mul(*beta, transmit(c->sigma_t, tmax));
		return false;
	}
	float rate = md->majorant;
	if (md->emits)
		rate = fmaxf(rate, RENDER_MEDIA_EMIT_STEPS / tmax);
	if (!(rate > 0.0f))
		return false;
	float t = 0.0f;
	for (int k = 0; k < RENDER_MEDIA_MAX_STEPS; k++) {
		t += exp_sample(g, rate);
		if (!(t < tmax))
			return false;
		render_media_coef_at(md, f, ctx, v3_madd(o, d, t), c);
		if (md->emits)
			*radiance = v3_add(*radiance, v3_mul(*beta, v3_scale(c->emission, 1.0f / rate)));
		vec3 sn = v3_max(v3_sub(v3s(rate), c->sigma_t), v3s(0.0f));
		float ws = sum3(v3_mul(*beta, c->sigma_s)), wn = sum3(v3_mul(*beta, sn));
		float ps = ws + wn > 0.0f ? ws / (ws + wn) : 0.0f;
		if (ps > 0.0f && rng_float(g) < ps) {
			*beta = v3_scale(*beta, 1.0f / (rate * ps));
			*t_out = t;
			return true;
		}
		if (!(ps < 1.0f)) {
			*beta = v3s(0.0f);
			return false;
		}
		*beta = v3_mul(*beta, v3_scale(sn, 1.0f / (rate * (1.0f - ps))));
		if (!(v3_max_comp(*beta) > 0.0f))
			return false;
	}
	*beta = v3s(0.0f);
	return false;
}

vec3 render_media_transmittance(const render_media *md, render_density_fn f, const void *ctx, vec3 o, vec3 d,
				float tmax, rng *g)
{
	if (!(tmax > 0.0f))
		return v3s(1.0f);
	if (md->homogeneous) {
		render_media_coef c;
		render_media_coef_at(md, f, ctx, o, &c);
		return transmit(c.sigma_t, tmax);
	}
	float rate = md->majorant;
	if (!(rate > 0.0f))
		return v3s(1.0f);
	if (!isfinite(tmax))
		return v3s(0.0f);
	vec3 tr = v3s(1.0f);
	float t = 0.0f;
	for (int k = 0; k < RENDER_MEDIA_MAX_STEPS; k++) {
		t += exp_sample(g, rate);
		if (!(t < tmax))
			return tr;
		render_media_coef c;
		render_media_coef_at(md, f, ctx, v3_madd(o, d, t), &c);
		tr = v3_mul(tr, v3_max(v3_sub(v3s(1.0f), v3_scale(c.sigma_t, 1.0f / rate)), v3s(0.0f)));
		if (!(v3_max_comp(tr) > 0.0f))
			return v3s(0.0f);
	}
	return v3s(0.0f);
}
