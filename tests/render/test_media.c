/* test_media: POV-Ray's media as render/media.h tracks them - Beer-Lambert through a homogeneous
 * slab (exact) and by ratio and delta tracking (a medium flagged heterogeneous whose density is
 * constant, so the majorant exceeds the extinction and null collisions happen), the emission of
 * an absorbing box against its closed form, a heterogeneous density's transmittance and emission
 * against a numerical integration along the ray, the scattering probability of the tracker
 * against its integral, and each phase function: normalised, and sampled as it says (chi-square,
 * Henyey-Greenstein at several eccentricities and POV-Ray's Mie and Rayleigh shapes). */
#include "check.h"
#include "render/chi2.h"
#include "render/media.h"

#include <math.h>

/* A density along x: 0.5 + 0.4 sin(3 x) (within [0.1, 0.9]; its bound says 1). */
static vec3 wavy(const void *ctx, const render_medium *m, vec3 p)
{
	(void)ctx, (void)m;
	return v3s(0.5f + 0.4f * sinf(3.0f * p.x));
}

/* The constant density 0.5 with a bound of 1: twice the majorant the medium needs. */
static vec3 half(const void *ctx, const render_medium *m, vec3 p)
{
	(void)ctx, (void)m, (void)p;
	return v3s(0.5f);
}

static render_media one_medium(vec3 sa, vec3 ss, vec3 e, bool dense)
{
	render_media md = {.n = 1};
	md.m[0] = (render_medium){.absorption = sa, .scattering = ss, .emission = e, .extinction = 1.0f,
				  .phase = RENDER_PHASE_ISOTROPIC, .density_max = v3s(1.0f), .n_density = dense ? 1 : 0};
	render_media_finish(&md);
	return md;
}

/* Mean and standard error of n estimates, channel x. */
typedef struct est {
	double sum, sum2;
	long n;
} est;
static void est_add(est *e, double x) { e->sum += x, e->sum2 += x * x, e->n++; }
static double est_mean(const est *e) { return e->sum / e->n; }
static double est_err(const est *e)
{
	double m = est_mean(e);
	return sqrt(fmax(0.0, e->sum2 / e->n - m * m) / e->n);
}

#define CHECK_EST(e, want, what)                                                                          \
	CHECK(fabs(est_mean(&(e)) - (want)) < 4.5 * est_err(&(e)) + 1e-4, "%s: %g +- %g, want %g", what,  \
	      est_mean(&(e)), est_err(&(e)), (double)(want))

static void beer_lambert(void)
{
	vec3 sa = v3(0.2f, 0.5f, 1.0f);
	render_media hom = one_medium(sa, v3s(0.0f), v3s(0.0f), false);
	vec3 o = v3(0, 0, 0), d = v3(1, 0, 0);
	rng g;
	rng_seed(&g, 1, 1);
	vec3 t = render_media_transmittance(&hom, NULL, NULL, o, d, 2.0f, &g);
	CHECK_NEAR(t.x, expf(-0.4f), 1e-6);
	CHECK_NEAR(t.z, expf(-2.0f), 1e-6);
	/* The tracker's closed form for a medium that does not scatter. */
	vec3 beta = v3s(1.0f), rad = v3s(0.0f);
	render_media_coef c;
	float ts;
	CHECK(!render_media_track(&hom, NULL, NULL, o, d, 2.0f, &g, &beta, &rad, &c, &ts), "absorber scatters");
	CHECK_NEAR(beta.y, expf(-1.0f), 1e-6);
	/* Ratio tracking and weighted delta tracking: density 0.5 under a majorant of 1 * sigma. */
	render_media het = one_medium(sa, v3s(0.0f), v3s(0.0f), true);
	est tr = {0}, tb = {0};
	long n = test_samples(200000);
	for (long i = 0; i < n; i++) {
		est_add(&tr, render_media_transmittance(&het, half, NULL, o, d, 2.0f, &g).z);
		beta = v3s(1.0f);
		render_media_track(&het, half, NULL, o, d, 2.0f, &g, &beta, &rad, &c, &ts);
		est_add(&tb, beta.z);
	}
	CHECK_EST(tr, exp(-1.0), "ratio tracking through a slab");
	CHECK_EST(tb, exp(-1.0), "delta tracking through a slab");
}

static void emission_box(void)
{
	/* An absorbing, emitting box: L = e (1 - exp(-sigma d)) / sigma per channel. */
	vec3 sa = v3(0.5f, 1.0f, 0.0f), e = v3(2.0f, 1.0f, 0.5f);
	float len = 1.5f;
	render_media hom = one_medium(sa, v3s(0.0f), e, false);
	rng g;
	rng_seed(&g, 2, 1);
	vec3 beta = v3s(1.0f), rad = v3s(0.0f);
	render_media_coef c;
	float ts;
	render_media_track(&hom, NULL, NULL, v3s(0), v3(0, 0, 1), len, &g, &beta, &rad, &c, &ts);
	CHECK_NEAR(rad.x, 2.0 * (1.0 - exp(-0.75)) / 0.5, 1e-5);
	CHECK_NEAR(rad.y, 1.0 * (1.0 - exp(-1.5)) / 1.0, 1e-5);
	CHECK_NEAR(rad.z, 0.5 * len, 1e-5); /* no absorption: e times the length */
	/* The same box, heterogeneous with the constant density 0.5: the collision estimator. */
	render_media het = one_medium(sa, v3s(0.0f), e, true);
	est ex = {0}, ez = {0};
	long n = test_samples(200000);
	for (long i = 0; i < n; i++) {
		beta = v3s(1.0f), rad = v3s(0.0f);
		render_media_track(&het, half, NULL, v3s(0), v3(0, 0, 1), len, &g, &beta, &rad, &c, &ts);
		est_add(&ex, rad.x), est_add(&ez, rad.z);
	}
	CHECK_EST(ex, 1.0 * (1.0 - exp(-0.25 * len)) / 0.25, "emission, absorbing, by collisions");
	CHECK_EST(ez, 0.25 * len, "emission alone, by collisions");
}

static void heterogeneous(void)
{
	/* Along x from 0.2 over 3 units: tau(s) = sigma * integral of the density; the emission
	 * integral of e d(s) exp(-tau(s)), both by the midpoint rule. */
	const double sigma = 1.2, eg = 0.8, len = 3.0, x0 = 0.2;
	const int m = 100000;
	double tau = 0.0, emit = 0.0;
	for (int i = 0; i < m; i++) {
		double x = x0 + (i + 0.5) * len / m, dens = 0.5 + 0.4 * sin(3.0 * x);
		double tau_mid = tau + 0.5 * sigma * dens * len / m;
		emit += eg * dens * exp(-tau_mid) * len / m;
		tau += sigma * dens * len / m;
	}
	render_media md = one_medium(v3s((float)sigma), v3s(0.0f), v3s((float)eg), true);
	rng g;
	rng_seed(&g, 3, 1);
	est tr = {0}, em = {0};
	long n = test_samples(200000);
	vec3 o = v3((float)x0, 0, 0), d = v3(1, 0, 0);
	for (long i = 0; i < n; i++) {
		est_add(&tr, render_media_transmittance(&md, wavy, NULL, o, d, (float)len, &g).x);
		vec3 beta = v3s(1.0f), rad = v3s(0.0f);
		render_media_coef c;
		float ts;
		render_media_track(&md, wavy, NULL, o, d, (float)len, &g, &beta, &rad, &c, &ts);
		est_add(&em, rad.x);
	}
	CHECK_EST(tr, exp(-tau), "heterogeneous transmittance");
	CHECK_EST(em, emit, "heterogeneous emission");
}

static void scatter_probability(void)
{
	/* Scattering weight sigma_s beta at the event integrates to sigma_s / sigma_t (1 - T),
	 * the passing weight to T; through null collisions (density 0.5 under a bound of 1). */
	vec3 sa = v3s(0.3f), ss = v3(0.5f, 1.0f, 2.0f);
	float len = 1.0f;
	render_media md = one_medium(sa, ss, v3s(0.0f), true);
	rng g;
	rng_seed(&g, 4, 1);
	est sc[3] = {{0}}, pass = {0};
	long n = test_samples(400000);
	for (long i = 0; i < n; i++) {
		vec3 beta = v3s(1.0f), rad = v3s(0.0f);
		render_media_coef c;
		float ts;
		bool s = render_media_track(&md, half, NULL, v3s(0), v3(0, 1, 0), len, &g, &beta, &rad, &c, &ts);
		vec3 w = s ? v3_mul(beta, c.sigma_s) : v3s(0.0f);
		est_add(&sc[0], w.x), est_add(&sc[1], w.y), est_add(&sc[2], w.z);
		est_add(&pass, s ? 0.0 : beta.z);
	}
	double st[3] = {0.5 * 0.8, 0.5 * 1.3, 0.5 * 2.3}, s_s[3] = {0.25, 0.5, 1.0};
	for (int k = 0; k < 3; k++)
		CHECK_EST(sc[k], s_s[k] / st[k] * (1.0 - exp(-st[k] * len)), "scattering weight");
	CHECK_EST(pass, exp(-st[2] * len), "passing weight");
}

typedef struct phase_ctx {
	render_media md;
	render_media_coef c;
	vec3 d_in;
} phase_ctx;

static bool phase_sample(void *ctx, rng *g, vec3 *dir)
{
	phase_ctx *p = ctx;
	vec3 f;
	float pdf;
	float u0 = rng_float(g);
	vec2 u = v2(rng_float(g), rng_float(g));
	return render_media_phase_sample(&p->md, &p->c, p->d_in, u0, u, dir, &f, &pdf);
}

static double phase_pdf(void *ctx, vec3 dir)
{
	phase_ctx *p = ctx;
	float pdf;
	render_media_phase_eval(&p->md, &p->c, p->d_in, dir, &pdf);
	return pdf;
}

static void phases(void)
{
	/* Each normalised over the sphere (midpoint rule in mu). */
	render_phase kinds[] = {RENDER_PHASE_ISOTROPIC, RENDER_PHASE_MIE_HAZY, RENDER_PHASE_MIE_MURKY,
				RENDER_PHASE_RAYLEIGH, RENDER_PHASE_HG};
	for (int k = 0; k < 5; k++) {
		double s = 0.0;
		const int m = 200000;
		for (int i = 0; i < m; i++)
			s += render_phase_pdf(kinds[k], 0.6f, (float)(-1.0 + (i + 0.5) * 2.0 / m)) * 2.0 / m;
		CHECK_NEAR(2.0 * M_PI * s, 1.0, 1e-4);
	}
	/* POV-Ray's HG (media.cpp): forward scattering for eccentricity > 0 along the path. */
	CHECK(render_phase_pdf(RENDER_PHASE_HG, 0.5f, 1.0f) > render_phase_pdf(RENDER_PHASE_HG, 0.5f, -1.0f),
	      "HG g > 0 scatters forward");
	struct {
		render_phase k;
		float g;
		const char *name;
	} cases[] = {{RENDER_PHASE_HG, 0.7f, "HG g 0.7"},	     {RENDER_PHASE_HG, -0.4f, "HG g -0.4"},
		     {RENDER_PHASE_HG, 0.0f, "HG g 0"},		     {RENDER_PHASE_MIE_HAZY, 0, "Mie hazy"},
		     {RENDER_PHASE_MIE_MURKY, 0, "Mie murky"},	     {RENDER_PHASE_RAYLEIGH, 0, "Rayleigh"}};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		phase_ctx p = {.md = {.n = 1}, .d_in = v3_normalize(v3(0.3f, -0.2f, 1.0f))};
		p.md.m[0] = (render_medium){.scattering = v3s(1.0f), .extinction = 1.0f, .phase = cases[i].k, .g = cases[i].g};
		render_media_finish(&p.md);
		render_media_coef_at(&p.md, NULL, NULL, v3s(0), &p.c);
		/* about -d_in: a rounded mu of -1 then clamps into the last bin, not below zmin */
		chi2_sphere(cases[i].name, phase_sample, phase_pdf, &p, v3_neg(p.d_in), -1.0, 48, 6, 24,
			    test_samples(200000), 40 + i);
	}
	/* Two media mixed: the mixture's density is the sigma_s-weighted sum. */
	phase_ctx p = {.md = {.n = 2}, .d_in = v3(0, 0, 1)};
	p.md.m[0] = (render_medium){.scattering = v3s(1.0f), .extinction = 1.0f, .phase = RENDER_PHASE_HG, .g = 0.8f};
	p.md.m[1] = (render_medium){.scattering = v3s(3.0f), .extinction = 1.0f, .phase = RENDER_PHASE_RAYLEIGH};
	render_media_finish(&p.md);
	render_media_coef_at(&p.md, NULL, NULL, v3s(0), &p.c);
	chi2_sphere("HG + Rayleigh", phase_sample, phase_pdf, &p, v3_neg(p.d_in), -1.0, 48, 6, 24, test_samples(200000),
		    50);
}

int main(void)
{
	beer_lambert();
	emission_box();
	heterogeneous();
	scatter_probability();
	phases();
	return check_done("test_media");
}
