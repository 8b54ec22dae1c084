/* test_glass: the transparent part of circe's surfaces (bsdf.h's bsdf_clear) — the dielectric's
 * Fresnel against Hecht's formula, its lobes' probabilities and energy (reflect + transmit = 1),
 * Snell's law, total internal reflection without NaN, reciprocity of F; POV-Ray's fade formula;
 * and through the integrator: a glass slab of ior 1.5 transmits (1 - F) / (1 + F), a glass slab
 * in a white furnace stays 1, shadow rays through a slab keep (1 - F)^2, and a thin transmitting
 * sheet over a floor renders alike by light sampling, BSDF sampling and MIS. */
#include "check.h"
#include "render/bsdf.h"
#include "render/camera.h"
#include "render/integrator.h"
#include "scenes.h"

/* Hecht, Optics, eq. 4.34 and 4.40 (amplitude coefficients), from the angles themselves. */
static double hecht_fresnel(double theta_i, double n1, double n2)
{
	double s = n1 / n2 * sin(theta_i);
	if (s >= 1.0)
		return 1.0;
	double theta_t = asin(s), ci = cos(theta_i), ct = cos(theta_t);
	double rs = (n1 * ci - n2 * ct) / (n1 * ci + n2 * ct);
	double rp = (n2 * ci - n1 * ct) / (n2 * ci + n1 * ct);
	return 0.5 * (rs * rs + rp * rp);
}

static void test_fresnel(void)
{
	const double n = 1.5;
	for (int i = 0; i <= 90; i++) {
		double th = i * M_PI / 180.0;
		float c = (float)cos(th);
		CHECK_NEAR(bsdf_fresnel_dielectric(c, (float)n), hecht_fresnel(th, 1.0, n), 2e-6);
		CHECK_NEAR(bsdf_fresnel_dielectric(c, (float)(1.0 / n)), hecht_fresnel(th, n, 1.0), 2e-6);
		/* Reciprocity of F: the refracted pair reflects alike from either side. */
		double tt = asin(sin(th) / n);
		CHECK_NEAR(bsdf_fresnel_dielectric(c, (float)n), bsdf_fresnel_dielectric((float)cos(tt), (float)(1 / n)), 2e-5);
	}
	CHECK_NEAR(bsdf_fresnel_dielectric(1.0f, 1.5f), 0.04, 1e-7); /* ((n - 1) / (n + 1))^2 */
}

/* Over many u: the reflected fraction is the lobe's probability, every weight is what the lobe
 * promises, the mean weight is reflect F + (1 - F) tint, the refraction obeys Snell. */
static void lobe_at(float cos_o, float eta, float reflect, vec3 tint)
{
	float sin_o = sqrtf(fmaxf(0.0f, 1.0f - cos_o * cos_o));
	vec3 wo = v3(sin_o * 0.6f, sin_o * 0.8f, cos_o);
	double f = bsdf_fresnel_dielectric(cos_o, eta);
	double wr = reflect * f, wt = (1 - f) * v3_luminance(tint);
	const int n = 20000;
	int refl = 0, ok = 0;
	double mean = 0;
	for (int i = 0; i < n; i++) {
		vec3 wi, w;
		bool refracted;
		float u = (i + 0.5f) / n;
		if (!bsdf_dielectric_sample(wo, eta, reflect, tint, u, &wi, &w, &refracted))
			continue;
		ok++;
		CHECK(v3_is_finite(wi) && v3_is_finite(w), "NaN at cos %g eta %g", cos_o, eta);
		CHECK_NEAR(v3_length(wi), 1.0, 1e-5);
		mean += w.y;
		if (!refracted) {
			refl++;
			CHECK(wi.z == wo.z && wi.x == -wo.x, "mirror direction at cos %g", cos_o);
			continue;
		}
		CHECK(wi.z < 0, "refraction goes below at cos %g eta %g: %g", cos_o, eta, wi.z);
		float sin_t = sqrtf(wi.x * wi.x + wi.y * wi.y);
		CHECK_NEAR(sin_t * eta, sin_o, 2e-5); /* Snell */
		CHECK(wi.x * wo.x <= 0 && wi.y * wo.y <= 0, "refraction keeps the plane of incidence");
	}
	if (wr + wt <= 0) {
		CHECK(ok == 0, "nothing to carry, yet %d samples", ok);
		return;
	}
	CHECK(ok == n, "cos %g eta %g: %d of %d samples failed", cos_o, eta, n - ok, n);
	CHECK_NEAR((double)refl / n, wr / (wr + wt), 2.0 / n);
	CHECK_NEAR(mean / n, reflect * f + (1 - f) * tint.y, 1e-3);
}

static void test_lobe(void)
{
	const float cosines[] = {1.0f, 0.9f, 0.5f, 0.2f, 0.05f, 1e-4f, 0.0f};
	for (size_t i = 0; i < sizeof cosines / sizeof cosines[0]; i++) {
		lobe_at(cosines[i], 1.5f, 1.0f, v3s(1.0f)); /* energy: weights 1, R + T = 1 */
		lobe_at(cosines[i], 1.0f / 1.5f, 1.0f, v3s(1.0f)); /* leaving: TIR below 48.2 deg */
		lobe_at(cosines[i], 1.5f, 0.9f, v3(0.9f, 0.36f, 0.36f));
		lobe_at(cosines[i], 1.0f, 1.0f, v3s(0.5f)); /* ior 1: no reflection, straight on */
		lobe_at(cosines[i], 1.5f, 0.0f, v3s(0.0f)); /* nothing through, nothing reflected */
	}
	/* Under total internal reflection everything reflects with weight 1 (reflect 1). */
	vec3 wi, w;
	bool refracted;
	float c = 0.5f, s = sqrtf(1 - c * c); /* 60 deg inside glass, critical 41.8 */
	CHECK(bsdf_dielectric_sample(v3(s, 0, c), 1 / 1.5f, 1.0f, v3s(1), 0.999f, &wi, &w, &refracted) && !refracted &&
		  w.x == 1.0f,
	      "TIR: refracted %d weight %g", refracted, w.x);
	/* Energy of the whole lobe is a probability: weight summed over choices <= 1 for tint <= 1. */
	bsdf_params b = bsdf_pov_finish(v3s(1), 0, 0, 0.05f);
	b.clear = (bsdf_clear){.kind = BSDF_CLEAR_DIELECTRIC, .tint = v3s(1), .reflect = 1, .ior = 1.5f};
	CHECK_NEAR(bsdf_clear_weight(&b, v3(0, 0, 1), true), 1.0, 1e-6);
	CHECK_NEAR(bsdf_clear_weight(&b, v3(s, 0, c), false), 1.0, 1e-6);
	CHECK_NEAR(bsdf_clear_shadow(&b, -0.3f).x, 1 - hecht_fresnel(acos(0.3), 1, 1.5), 2e-6);
	b.clear.kind = BSDF_CLEAR_THIN;
	b.clear.tint = v3(0.2f, 0.5f, 1.0f);
	CHECK(bsdf_clear_sample(&b, v3(s, 0, c), true, 0.3f, &wi, &w, &refracted) && refracted && wi.x == -s &&
		  wi.z == -c && w.y == 0.5f,
	      "thin: straight through with the tint");
}

/* POV-Ray's fade (core/render/trace.cpp, ComputeLightedTexture), written from its formula. */
static void test_fade(void)
{
	bsdf_fade sq = {.distance = 1.0f, .power = 2.0f, .color = v3(0, 0.5f, 1)};
	for (int i = 0; i <= 20; i++) {
		double d = 0.25 * i;
		vec3 t = bsdf_fade_apply(&sq, (float)d);
		double att = 1 + pow(d / 1.0, 2);
		CHECK_NEAR(t.x, 0 + (1 - 0) / att, 1e-6);
		CHECK_NEAR(t.y, 0.5 + 0.5 / att, 1e-6);
		CHECK_NEAR(t.z, 1.0, 1e-6);
	}
	CHECK_NEAR(bsdf_fade_apply(&sq, 1.0f).x, 0.5, 1e-6); /* half at fade_distance */
	/* fade_power 1 (glass.inc has none, POV-Ray's docs' linear-ish case): color + (1 - color) /
	 * (1 + d / distance), here at distance 2 with glass.inc's default fade_color 0. */
	bsdf_fade lin = {.distance = 2.0f, .power = 1.0f, .color = v3(0, 0.25f, 0)};
	const double ds[] = {0.1, 0.5, 1.0, 2.0, 3.7, 10.0};
	for (size_t i = 0; i < sizeof ds / sizeof ds[0]; i++) {
		vec3 t = bsdf_fade_apply(&lin, (float)ds[i]);
		double att = 1 + ds[i] / 2.0;
		CHECK_NEAR(t.x, 1 / att, 1e-6);
		CHECK_NEAR(t.y, 0.25 + 0.75 / att, 1e-6);
	}
	/* glass.inc's I_Glass1 (fade_distance 1, fade_power 2, fade_color 0) through the ruby ball's
	 * diameter 2: 1 / (1 + 4) = 0.2 of the light, in every channel (the ruby's red is the
	 * pigment's filter, applied at each surface, not the fade's). */
	bsdf_fade g1 = {.distance = 1.0f, .power = 2.0f};
	CHECK_NEAR(bsdf_fade_apply(&g1, 2.0f).x, 0.2, 1e-6);
	CHECK_NEAR(bsdf_fade_apply(&g1, 2.0f).z, 0.2, 1e-6);
	/* glass.inc's I_Glass_Fade_Exp2 (fade_distance 1, fade_power 1001): exp(-d). */
	bsdf_fade g3 = {.distance = 1.0f, .power = 1001.0f};
	for (size_t i = 0; i < sizeof ds / sizeof ds[0]; i++)
		CHECK_NEAR(bsdf_fade_apply(&g3, (float)ds[i]).y, exp(-ds[i]), 1e-6);
	bsdf_fade ex = {.distance = 0.5f, .power = 1001.0f, .color = v3(0.2f, 0, 0)};
	CHECK_NEAR(bsdf_fade_apply(&ex, 0.5f).y, exp(-1.0), 1e-6);
	CHECK_NEAR(bsdf_fade_apply(&ex, 2.0f).x, exp(-0.8 * 4), 1e-6);
	/* Beer-Lambert: exponential fade multiplies over pieces of the path. */
	CHECK_NEAR(bsdf_fade_apply(&ex, 0.3f).x * bsdf_fade_apply(&ex, 0.9f).x, bsdf_fade_apply(&ex, 1.2f).x, 1e-6);
	bsdf_fade none = {.distance = 0.0f, .power = 2.0f};
	CHECK(bsdf_fade_apply(&none, 3.0f).x == 1.0f, "fade_distance 0: no fade");
	none = (bsdf_fade){.distance = 1.0f, .power = 0.0f};
	CHECK(bsdf_fade_apply(&none, 3.0f).x == 1.0f, "fade_power 0: no fade");
}

static cam make_cam(vec3 loc, vec3 at, float angle, int w, int h)
{
	cam c;
	CHECK(ts_camera(loc, at, angle, w, h, &c), "camera");
	return c;
}

/* The mean luminance over n paths through the centre of c, and its standard error. */
static double render_mean(const ts_scene *s, const cam *c, render_settings set, int n, double *se)
{
	double sum = 0, sum2 = 0;
	for (int k = 0; k < n; k++) {
		render_sampler g = render_sampler_make(RENDER_SAMPLER_SOBOL, 5, 0, 0, (uint32_t)k);
		vec2 pu = render_sampler_2d(&g, RENDER_DIM_PIXEL);
		render_sample smp = render_path(&s->rs, &set, cam_ray(c, 0, 0, pu, v2(0, 0)), &g);
		double l = v3_luminance(smp.radiance);
		CHECK(isfinite(l), "a NaN or Inf sample");
		sum += l, sum2 += l * l;
	}
	double m = sum / n;
	*se = sqrt(fmax(0, sum2 / n - m * m) / n);
	return m;
}

/* A glass slab 0 < y < 1 (planes with outward normals), clear (tint 1, reflect 1). */
static void add_slab(ts_scene *s, int material)
{
	s->pl[s->npl++] = (ts_plane){v3(0, 1, 0), 1.0f, material};
	s->pl[s->npl++] = (ts_plane){v3(0, -1, 0), 0.0f, material};
	s->mat[material] = bsdf_pov_finish(v3s(1), 0, 0, 0.05f);
	s->mat[material].clear = (bsdf_clear){.kind = BSDF_CLEAR_DIELECTRIC, .tint = v3s(1), .reflect = 1, .ior = 1.5f};
}

/* Seen from above at theta through the slab, an emitter of radiance 1 below it shows the slab's
 * transmittance with every inter-reflection: (1 - F)^2 sum F^2k = (1 - F) / (1 + F). */
static void test_slab_transmits(void)
{
	for (int a = 0; a < 3; a++) {
		double th = (double[]){0.01, 45.0, 70.0}[a] * M_PI / 180;
		ts_scene s;
		ts_init(&s);
		add_slab(&s, 0);
		vec3 q[4] = {v3(-1e3f, -1, -1e3f), v3(1e3f, -1, -1e3f), v3(1e3f, -1, 1e3f), v3(-1e3f, -1, 1e3f)};
		s.tri[s.ntri++] = (ts_tri){{q[0], q[2], q[1]}, -1, 0};
		s.tri[s.ntri++] = (ts_tri){{q[0], q[3], q[2]}, -1, 0};
		vec3 v[6] = {q[0], q[2], q[1], q[0], q[3], q[2]};
		light mesh;
		CHECK(light_mesh_init(&mesh, v, 2, v3s(1)), "emitter");
		light_set_add(&s.lights, &mesh);
		light_set_finish(&s.lights, 2e3f);
		vec3 eye = v3((float)(-3 * sin(th)), (float)(1 + 3 * cos(th)), 0);
		cam c = make_cam(eye, v3(0, 1, 0), 0.01f, 1, 1);
		double se, m = render_mean(&s, &c, (render_settings){.max_trace_level = 100, .mode = RENDER_MIS}, 40000, &se);
		double f = hecht_fresnel(th, 1, 1.5), want = (1 - f) / (1 + f);
		printf("  slab at %2.0f deg: T = %.4f +- %.4f, want (1 - F) / (1 + F) = %.4f\n", th * 180 / M_PI, m, se, want);
		CHECK(fabs(m - want) <= 4 * se + 1e-3, "slab at %g deg: %g, want %g (se %g)", th * 180 / M_PI, m, want, se);
		light_set_free(&s.lights);
	}
}

/* Glass in a white furnace: every path ends in the sky with weight 1 (R + T = 1, no loss). */
static void test_slab_furnace(void)
{
	ts_scene s;
	ts_init(&s);
	add_slab(&s, 0);
	s.sph[s.nsph++] = (ts_sphere){v3(0, 3, 0), 0.8f, 0}; /* and a glass ball above it */
	light bg = light_background(v3s(1));
	light_set_add(&s.lights, &bg);
	light_set_finish(&s.lights, 10.0f);
	cam c = make_cam(v3(-2, 4, -3), v3(0, 2, 0), 30, 1, 1);
	double se, m = render_mean(&s, &c, (render_settings){.max_trace_level = 200, .mode = RENDER_MIS}, 4000, &se);
	printf("  glass furnace: %.5f +- %.5f\n", m, se);
	CHECK(fabs(m - 1.0) <= 2e-3, "glass in the furnace: %g", m);
	light_set_free(&s.lights);
}

/* A white floor under the slab, a point light above: the shadow ray keeps tint (1 - F(theta))
 * at each crossing (the default), nothing with opaque_glass_shadows. */
static void test_shadow_through_slab(void)
{
	ts_scene s;
	ts_init(&s);
	s.rs.shadow_closest = ts_intersect;
	add_slab(&s, 0);
	s.pl[s.npl++] = (ts_plane){v3(0, 1, 0), -1.0f, 1};
	s.mat[1] = bsdf_diffuse(v3s(1));
	light pt = light_point(v3(2, 3, 0), v3s(10));
	light_set_add(&s.lights, &pt);
	light_set_finish(&s.lights, 10.0f);
	/* The floor point (0, -1, 0), seen from between the slab and the floor. */
	cam c = make_cam(v3(0, -0.5f, -1), v3(0, -1, 0), 0.01f, 1, 1);
	double se, m = render_mean(&s, &c, (render_settings){.max_trace_level = 1, .mode = RENDER_MIS}, 16, &se);
	double d2 = 4 + 16, cos_l = 4 / sqrt(d2), f = hecht_fresnel(acos(cos_l), 1, 1.5);
	double want = (1 / M_PI) * 10 * cos_l / d2 * (1 - f) * (1 - f);
	CHECK_NEAR(m, want, 1e-3 * want);
	m = render_mean(&s, &c, (render_settings){.max_trace_level = 1, .mode = RENDER_MIS, .opaque_glass_shadows = true},
			16, &se);
	CHECK(m == 0.0, "opaque glass shadows: %g", m);
	light_set_free(&s.lights);
}

/* A thin sheet (tint 0.5, half opaque) over a floor, under a sphere light: the pass-through is
 * no scattering event, so light sampling, BSDF sampling and MIS agree. */
static void test_thin_mis(void)
{
	double m[3], se[3];
	const render_mode modes[3] = {RENDER_LIGHT_ONLY, RENDER_BSDF_ONLY, RENDER_MIS};
	for (int k = 0; k < 3; k++) {
		ts_scene s;
		ts_init(&s);
		s.rs.shadow_closest = ts_intersect;
		s.pl[s.npl++] = (ts_plane){v3(0, 1, 0), 0.0f, 0};
		s.mat[0] = bsdf_diffuse(v3s(0.8f));
		s.pl[s.npl++] = (ts_plane){v3(0, 1, 0), 1.0f, 1};
		s.mat[1] = bsdf_diffuse(v3s(0.25f));
		s.mat[1].clear = (bsdf_clear){.kind = BSDF_CLEAR_THIN, .tint = v3s(0.5f)};
		light sl = light_sphere(v3(0.5f, 3, 0), 0.7f, v3s(4));
		light_set_add(&s.lights, &sl);
		light_set_finish(&s.lights, 10.0f);
		cam c = make_cam(v3(0, 0.5f, -1), v3(0, 0, 0), 0.01f, 1, 1);
		m[k] = render_mean(&s, &c, (render_settings){.max_trace_level = 3, .mode = modes[k]}, 200000, &se[k]);
		light_set_free(&s.lights);
	}
	printf("  thin sheet: light %.5f +- %.5f, BSDF %.5f +- %.5f, MIS %.5f +- %.5f\n", m[0], se[0], m[1], se[1], m[2],
	       se[2]);
	for (int k = 0; k < 2; k++)
		CHECK(fabs(m[k] - m[2]) <= 4 * sqrt(se[k] * se[k] + se[2] * se[2]), "strategy %d: %g vs MIS %g", k, m[k],
		      m[2]);
}

int main(void)
{
	test_fresnel();
	test_lobe();
	test_fade();
	test_slab_transmits();
	test_slab_furnace();
	test_shadow_through_slab();
	test_thin_mis();
	return check_done("test_glass");
}
