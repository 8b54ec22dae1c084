/* test_bsdf: each BSDF samples the density its pdf states (chi-square over the sphere), the pdf
 * integrates to the probability of a successful sample, eval is reciprocal and never creates
 * energy, and the Fresnel and POV-Ray roughness mappings have their documented values. */
#include "chi2.h"
#include "render/bsdf.h"
#include "render/bsdf_pov.h"
#include "render/sampling.h"

typedef struct bctx {
	bsdf_params b;
	vec3 wo;
} bctx;

static bool s_bsdf(void *ctx, rng *g, vec3 *d)
{
	bctx *c = ctx;
	vec3 f;
	float pdf;
	float ul = rng_float(g);
	vec2 u = v2(rng_float(g), rng_float(g));
	if (!bsdf_sample(&c->b, c->wo, ul, u, d, &f, &pdf))
		return false;
	/* The sample's own pdf and value agree with pdf() and eval() (less the highlights of light
	 * sources, which paths never carry). */
	float p2 = bsdf_pdf(&c->b, c->wo, *d);
	vec3 f2 = v3_sub(bsdf_eval(&c->b, c->wo, *d), bsdf_highlights(&c->b, c->wo, *d));
	CHECK(fabsf(pdf - p2) <= 1e-4f * p2 && fabsf(f.x - f2.x) <= 1e-4f * f2.x + 1e-7f,
	      "sample pdf %g vs %g, f %g vs %g", pdf, p2, f.x, f2.x);
	return true;
}

static double p_bsdf(void *ctx, vec3 d)
{
	bctx *c = ctx;
	return bsdf_pdf(&c->b, c->wo, d);
}

static vec3 dir_at(float theta_deg)
{
	float t = theta_deg * RENDER_PI / 180.0f;
	return v3(sinf(t), 0.0f, cosf(t));
}

/* Integral of f cos over the hemisphere (the directional albedo) by stratified quadrature. */
static double albedo_of(const bsdf_params *b, vec3 wo)
{
	const int nz = 400, np = 200;
	double s = 0.0;
	for (int i = 0; i < nz; i++)
		for (int j = 0; j < np; j++) {
			double z = (i + 0.5) / nz, phi = 2 * M_PI * (j + 0.5) / np, r = sqrt(1 - z * z);
			vec3 wi = v3((float)(r * cos(phi)), (float)(r * sin(phi)), (float)z);
			s += bsdf_eval(b, wo, wi).x * z;
		}
	return s * 2 * M_PI / ((double)nz * np);
}

/* The directional albedo by importance sampling: mean of f cos / pdf over n samples (for lobes
 * too sharp for quadrature: the mirror). */
static double albedo_sampled(const bsdf_params *b, vec3 wo, long n, uint64_t seed)
{
	rng g;
	rng_seed(&g, seed, 3);
	double s = 0.0;
	for (long i = 0; i < n; i++) {
		vec3 wi, f;
		float pdf;
		float ul = rng_float(&g);
		vec2 u = v2(rng_float(&g), rng_float(&g));
		if (bsdf_sample(b, wo, ul, u, &wi, &f, &pdf))
			s += f.x * wi.z / pdf;
	}
	return s / (double)n;
}

static bsdf_pov_finish_spec pov_spec(float kd, float ks, float rough, float kp, float psize)
{
	return (bsdf_pov_finish_spec){.diffuse = kd, .specular = ks, .roughness = rough, .phong = kp,
				      .phong_size = psize, .refl_falloff = 1.0f};
}

/* BSDF_POV: each lobe mixture samples its pdf, POV-Ray's brightness at the highlight's peak, the
 * reflection's weight against POV-Ray's formula, and no finish reflecting more than comes in. */
static void test_pov_finish(long n)
{
	vec3 z = v3(0, 0, 1);
	bsdf_pov_finish_spec f = pov_spec(0.6f, 0.8f, 0.05f, 0.0f, 40.0f);
	bctx c = {bsdf_pov(&f, v3(0.7f, 0.4f, 0.2f)), dir_at(30)};
	chi2_sphere("pov diffuse + specular, 30 deg", s_bsdf, p_bsdf, &c, z, -1.0, 16, 32, 12, n, 21);
	f = pov_spec(0.5f, 0.0f, 0.05f, 1.0f, 10.0f);
	f.metallic = 1.0f;
	c.b = bsdf_pov(&f, v3(0.9f, 0.7f, 0.2f));
	c.wo = dir_at(60);
	chi2_sphere("pov diffuse + metallic phong 10, 60 deg", s_bsdf, p_bsdf, &c, z, -1.0, 16, 32, 12, n, 22);
	f = pov_spec(0.3f, 0.5f, 0.2f, 0.6f, 4.0f);
	c.b = bsdf_pov(&f, v3s(0.5f));
	c.wo = dir_at(75);
	chi2_sphere("pov specular + phong, 75 deg", s_bsdf, p_bsdf, &c, z, -1.0, 16, 32, 12, n, 24);

	/* The highlights are POV-Ray's formulas under a light scaled by pi: at normal incidence the
	 * peak is Ks (POV-Ray's Ks (N.H)^n with N.H = 1), and with wi 40 degrees off the normal the
	 * half vector is 20 degrees off, Ks cos(20)^20 = 0.2882 Ks (roughness 0.05: n = 20). */
	f = pov_spec(0.0f, 0.7f, 0.05f, 0.0f, 40.0f);
	bsdf_params pk = bsdf_pov(&f, v3s(1));
	CHECK_NEAR(bsdf_eval(&pk, z, z).x * M_PI, 0.7, 1e-5);
	CHECK_NEAR(bsdf_eval(&pk, z, dir_at(40)).x * M_PI * cos(40 * M_PI / 180), 0.7 * pow(cos(20 * M_PI / 180), 20), 1e-5);
	CHECK(bsdf_pdf(&pk, z, z) == 0.0f, "a highlight is never sampled");
	/* Phong: Kp (R.L)^p, R the mirror of the eye: wo 30 degrees one side, wi 20 the other is 10
	 * degrees off R; p 40. */
	f = pov_spec(0.0f, 0.0f, 0.05f, 0.9f, 40.0f);
	pk = bsdf_pov(&f, v3s(1));
	CHECK_NEAR(bsdf_eval(&pk, z, z).x * M_PI, 0.9, 1e-5);
	vec3 wo30 = dir_at(30);
	wo30.x = -wo30.x;
	CHECK_NEAR(bsdf_eval(&pk, wo30, dir_at(20)).x * M_PI * cos(20 * M_PI / 180), 0.9 * pow(cos(10 * M_PI / 180), 40), 1e-5);
	/* Their albedos at normal incidence (the energy bound), against quadrature of eval. */
	CHECK_NEAR(bsdf_pov_specular_albedo(20.0f), 8.0 * (1 - pow(2, -11)) / 22.0, 1e-6);
	CHECK_NEAR(bsdf_pov_phong_albedo(10.0f), 2.0 / 11.0, 1e-6);
	CHECK_NEAR(bsdf_pov_specular_albedo(0.5f), 1.0, 1e-6); /* capped */
	f = pov_spec(0.0f, 0.5f, 0.1f, 0.0f, 40.0f);
	pk = bsdf_pov(&f, v3s(1));
	CHECK_NEAR(albedo_of(&pk, z), 0.5 * bsdf_pov_specular_albedo(10.0f), 2e-3);
	f = pov_spec(0.0f, 0.0f, 0.05f, 0.5f, 10.0f);
	pk = bsdf_pov(&f, v3s(1));
	CHECK_NEAR(albedo_of(&pk, z), 0.5 * bsdf_pov_phong_albedo(10.0f), 2e-3);
	/* Metallic: POV-Ray's empirical Fresnel is 0 at normal incidence, 1 at grazing. */
	CHECK_NEAR(bsdf_pov_metallic_fresnel(1.0f), 0.0, 1e-4);
	CHECK_NEAR(bsdf_pov_metallic_fresnel(0.0f), 1.0, 1e-6);

	/* Reflection { 0.1, 0.6 falloff 2 }: the mirror reflects min + (max - min) (1 - c)^2. */
	f = pov_spec(0.0f, 0.0f, 0.05f, 0.0f, 40.0f);
	f.refl_min = v3s(0.1f), f.refl_max = v3s(0.6f), f.refl_falloff = 2.0f;
	bsdf_params m = bsdf_pov(&f, v3s(1));
	for (float th = 0; th < 80; th += 25) {
		double cth = cos(th * M_PI / 180), want = 0.1 + 0.5 * pow(1 - cth, 2);
		double got = albedo_sampled(&m, dir_at(th), 20000, 31);
		CHECK(fabs(got - want) < 0.01 * want, "reflection at %g deg: %g, POV-Ray's %g", th, got, want);
	}
	/* Fresnel reflection of ior 1.5 between 0 and 1: the dielectric's 0.04 at normal incidence. */
	f.refl_min = v3s(0.0f), f.refl_max = v3s(1.0f), f.refl_ior = 1.5f;
	m = bsdf_pov(&f, v3s(1));
	CHECK_NEAR(albedo_sampled(&m, z, 20000, 32), 0.04, 0.002);

	/* Energy: the brightest finishes reflect at most what comes in (quadrature for the glossy
	 * lobes, sampling with the mirror), and a white matte one reflects it all. */
	f = pov_spec(1.0f, 1.0f, 0.02f, 1.0f, 5.0f);
	bsdf_params hot = bsdf_pov(&f, v3s(1));
	f.refl_min = f.refl_max = v3s(1.0f);
	bsdf_params mirror = bsdf_pov(&f, v3s(1));
	f = pov_spec(1.0f, 0.0f, 0.05f, 0.0f, 40.0f);
	bsdf_params matte = bsdf_pov(&f, v3s(1));
	for (float th = 0; th < 90; th += 22.5f) {
		double a1 = albedo_of(&hot, dir_at(th)), a2 = albedo_sampled(&mirror, dir_at(th), 20000, 33);
		CHECK(a1 <= 1.0 + 1e-3 && a1 > 0.5, "pov finish albedo at %g deg: %g", th, a1);
		CHECK(a2 <= 1.0 + 0.01, "pov finish with a mirror, albedo at %g deg: %g", th, a2);
		CHECK_NEAR(albedo_of(&matte, dir_at(th)), 1.0, 1e-3);
	}
	/* Ambient and emission glow pigment * glow; a textured pigment changes them together. */
	f.glow = v3(0.2f, 0.2f, 0.4f);
	bsdf_params glow = bsdf_pov(&f, v3(1.0f, 0.5f, 0.5f));
	CHECK_NEAR(glow.emit.z, 0.2, 1e-6);
	bsdf_pov_set_pigment(&glow, v3(0.5f, 0.5f, 1.0f));
	CHECK_NEAR(glow.emit.z, 0.4, 1e-6);
	CHECK_NEAR(glow.diffuse.x, 0.5, 1e-6);
	/* A delta light shows in the diffuse lobe and the highlights, never in the near-mirror
	 * reflection (POV-Ray's reflection rays see no light source): at the mirror direction the
	 * reflection alone is thousands of times the rest, and the delta light's value is the rest. */
	f = pov_spec(0.5f, 0.4f, 0.05f, 0.0f, 40.0f);
	f.refl_min = f.refl_max = v3s(0.5f);
	bsdf_params dm = bsdf_pov(&f, v3(0.8f, 0.6f, 0.4f));
	vec3 wo35 = dir_at(35), wm = dir_at(35);
	wm.x = -wm.x;
	vec3 full = bsdf_eval(&dm, wo35, wm), dl = bsdf_eval_delta_light(&dm, wo35, wm);
	double rest = 0.8 * 0.5 * dm.pov_scale / M_PI + bsdf_highlights(&dm, wo35, wm).x;
	CHECK(full.x > 1000 * rest, "the mirror direction: %g against the rest %g", full.x, rest);
	CHECK_NEAR(dl.x, rest, 1e-6 * rest);
	/* bsdf_shine, what a POV-Ray shadowless (fill) light does not show: the specular and phong of
	 * the highlights, not brilliance's part. With specular and phong the finish's highlights less
	 * its shine are those of the same finish without them (its brilliance's cos^b term alone). */
	f = pov_spec(0.6f, 0.5f, 0.05f, 0.7f, 20.0f);
	f.brilliance_less_1 = 2.0f;
	bsdf_params sh = bsdf_pov(&f, v3(0.8f, 0.6f, 0.4f));
	f.specular = f.phong = 0.0f;
	bsdf_params dull = bsdf_pov(&f, v3(0.8f, 0.6f, 0.4f));
	for (double th = 0; th < 80; th += 15) {
		vec3 wi = dir_at(th), wo = dir_at(th * 0.5 + 10);
		wo.x = -wo.x;
		vec3 rest = v3_sub(bsdf_highlights(&sh, wo, wi), bsdf_shine(&sh, wo, wi)), want = bsdf_highlights(&dull, wo, wi);
		double s0 = (double)sh.pov_scale / dull.pov_scale; /* both capped by their own energy */
		CHECK(fabs(rest.y - want.y * s0) <= 1e-5 * fabs(want.y) + 1e-7 && bsdf_shine(&sh, wo, wi).y > 0,
		      "shine at %g deg: the rest %g, brilliance's part %g", th, rest.y, want.y * s0);
	}
	CHECK(v3_max_comp(bsdf_shine(&dull, z, z)) == 0.0f, "no specular, no phong: no shine");
	/* Reciprocity of what paths carry (metallic tint and reflection weigh at wi.h); POV-Ray's
	 * highlights are not reciprocal and light sources alone show in them. */
	f = pov_spec(0.4f, 0.5f, 0.1f, 0.5f, 8.0f);
	f.metallic = 0.7f, f.refl_min = v3s(0.1f), f.refl_max = v3s(0.5f);
	bsdf_params rc = bsdf_pov(&f, v3(0.8f, 0.5f, 0.2f));
	vec3 a = v3_normalize(v3(0.3f, -0.2f, 0.8f)), b = v3_normalize(v3(-0.5f, 0.1f, 0.4f));
	CHECK_NEAR(bsdf_pov_eval_paths(&rc, a, b).y, bsdf_pov_eval_paths(&rc, b, a).y, 1e-6);
	/* A POV-Ray subsurface texture (sss_diffuse): no Lambert lobe (the highlight alone remains),
	 * and b->diffuse, the BSSRDF's albedo, scaled with the lobes so that BSSRDF + highlight +
	 * reflection stay within 1 (white pigment, Kd 1, specular 0.6, reflection 0.3). */
	f = pov_spec(0.0f, 0.6f, 0.1f, 0.0f, 40.0f);
	f.refl_min = f.refl_max = v3s(0.3f);
	bsdf_params hl = bsdf_pov(&f, v3s(1.0f));
	f.sss_diffuse = 1.0f;
	bsdf_params ss = bsdf_pov(&f, v3s(1.0f));
	float hlw = 0.6f * bsdf_pov_specular_albedo(10.0f);
	CHECK_NEAR(ss.diffuse.x, 1.0 / (1.0 + hlw + 0.3), 1e-6);
	CHECK_NEAR(ss.pov_scale, 1.0 / (1.0 + hlw + 0.3), 1e-6);
	for (double th = 5; th < 85; th += 20) {
		vec3 wi = dir_at(th + 3), wo = dir_at(th);
		wo.x = -wo.x;
		double want = bsdf_eval(&hl, wo, wi).x * ss.pov_scale / hl.pov_scale;
		CHECK(fabs(bsdf_eval(&ss, wo, wi).x - want) <= 1e-5 * want + 1e-9, "sss texture's lobes at %g deg: %g, want %g",
		      th, bsdf_eval(&ss, wo, wi).x, want);
	}
	/* brilliance 4 (Kd 0.3 = 0.75 * 2 / (4 + 1), as build_material.c gives POV-Ray's diffuse
	 * 0.75): light sources see POV-Ray's 0.75 cos^4 pigment (the BSDF times cos pi under the
	 * scaled light), paths carry the Lambert lobe of the same energy, and the whole, light
	 * sources' view included, reflects 0.3 pigment: what POV-Ray's cos^4 reflects. */
	f = pov_spec(0.3f, 0.0f, 0.05f, 0.0f, 40.0f);
	f.brilliance_less_1 = 3.0f;
	bsdf_params br = bsdf_pov(&f, v3(0.8f, 0.6f, 0.4f));
	for (double th = 0; th < 90; th += 15) {
		vec3 wi = dir_at(th), wo = dir_at(20);
		wo.x = -wo.x;
		double c = cos(th * M_PI / 180), want = 0.75 * pow(c, 4) * 0.8;
		CHECK_NEAR(bsdf_eval_delta_light(&br, wo, wi).x * c * M_PI, want, 1e-5);
		CHECK_NEAR(bsdf_eval(&br, wo, wi).x * c * M_PI, want, 1e-5);
		CHECK_NEAR(bsdf_pov_eval_paths(&br, wo, wi).x * M_PI, 0.3 * 0.8, 1e-6);
	}
	CHECK_NEAR(albedo_of(&br, dir_at(30)), 0.3 * 0.8, 1e-3);
}

int main(void)
{
	long n = test_samples(1000000);
	vec3 z = v3(0, 0, 1);
	bctx c = {bsdf_diffuse(v3(0.8f, 0.5f, 0.2f)), dir_at(40)};
	chi2_sphere("bsdf diffuse", s_bsdf, p_bsdf, &c, z, -1.0, 16, 32, 8, n, 10);
	c.b = bsdf_pov_finish(v3(0.6f, 0.6f, 0.6f), 0.5f, 0.6f, 0.1f);
	c.wo = dir_at(30);
	chi2_sphere("bsdf plastic, alpha 0.41, 30 deg", s_bsdf, p_bsdf, &c, z, -1.0, 16, 32, 12, n, 11);
	c.b.alpha = 0.6f;
	c.wo = dir_at(75);
	chi2_sphere("bsdf plastic, alpha 0.6, 75 deg", s_bsdf, p_bsdf, &c, z, -1.0, 16, 32, 12, n, 12);
	c.b = bsdf_coat(v3(0.9f, 0.6f, 0.5f), 1.4f, 0.35f);
	c.wo = dir_at(20);
	chi2_sphere("bsdf coat, alpha 0.35, 20 deg", s_bsdf, p_bsdf, &c, z, -1.0, 16, 32, 12, n, 13);
	c.wo = dir_at(80);
	chi2_sphere("bsdf coat, alpha 0.35, 80 deg", s_bsdf, p_bsdf, &c, z, -1.0, 16, 32, 12, n, 14);

	/* Fresnel: ((n - 1) / (n + 1))^2 at normal incidence, 1 at grazing. */
	CHECK_NEAR(bsdf_fresnel_dielectric(1.0f, 1.5f), 0.04, 1e-6);
	CHECK_NEAR(bsdf_fresnel_dielectric(0.0f, 1.5f), 1.0, 1e-6);
	/* POV-Ray roughness 0.05: Blinn exponent 20, alpha sqrt(2 / 22). */
	CHECK_NEAR(bsdf_pov_finish(v3s(1), 0.6f, 0.4f, 0.05f).alpha, sqrt(2.0 / 22.0), 1e-6);

	/* GGX D integrates to one over projected area: int D(h) cos dh = 1. */
	double dsum = 0;
	for (int i = 0; i < 2000; i++) {
		double zz = (i + 0.5) / 2000;
		dsum += bsdf_ggx_d(v3((float)sqrt(1 - zz * zz), 0, (float)zz), 0.3f) * zz;
	}
	CHECK_NEAR(dsum * 2 * M_PI / 2000, 1.0, 2e-3);

	/* Energy: a white Lambertian reflects everything; GGX alone and the coat never exceed one. */
	bsdf_params white = bsdf_diffuse(v3s(1));
	CHECK_NEAR(albedo_of(&white, dir_at(50)), 1.0, 1e-3);
	for (float th = 0; th < 90; th += 22.5f) {
		bsdf_params spec = bsdf_pov_finish(v3s(0), 0.0f, 1.0f, 0.02f);
		bsdf_params coat = bsdf_coat(v3s(1), 1.4f, 0.3f);
		double a1 = albedo_of(&spec, dir_at(th)), a2 = albedo_of(&coat, dir_at(th));
		CHECK(a1 <= 1.0 && a1 > 0.5, "GGX albedo at %g deg: %g", th, a1);
		CHECK(a2 <= 1.0 && a2 > 0.7, "coat albedo at %g deg: %g", th, a2);
	}

	test_pov_finish(n);

	/* Reciprocity and the lower hemisphere. */
	bsdf_params coat = bsdf_coat(v3(0.7f, 0.5f, 0.3f), 1.33f, 0.2f);
	vec3 a = v3_normalize(v3(0.3f, -0.2f, 0.8f)), b = v3_normalize(v3(-0.5f, 0.1f, 0.4f));
	CHECK_NEAR(bsdf_eval(&coat, a, b).y, bsdf_eval(&coat, b, a).y, 1e-6);
	CHECK(bsdf_eval(&coat, a, v3(0, 0.6f, -0.8f)).x == 0.0f, "light through the surface");
	return check_done("test_bsdf");
}
