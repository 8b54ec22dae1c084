/* test_medium: the one derivation of an SSS medium (sss/medium.h) - the presets, each form from
 * the other against values computed independently (JMLH01's Figure 5, the polynomial F_dr the
 * scene used before, l_d by hand), the round trips, what a spec's base and written parameters
 * give, the name tables of methods and profiles read both ways, and POV-Ray's subsurface brightness
 * (sss_pov_gain) against values by hand and POV-Ray's estimator rebuilt by quadrature. */
#include "check.h"
#include "sss/medium.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* JMLH01 section 2.4's polynomial fit of the diffuse Fresnel reflectance (after Egan &
 * Hilgeman), and the dipole's R_d with it: the derivation the parser made before, an
 * independent value the exact FM1 must stay close to. */
static double rd_polynomial(double alpha_p, double eta)
{
	double fdr = -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
	double A = (1.0 + fdr) / (1.0 - fdr), s = sqrt(3.0 * (1.0 - alpha_p));
	return 0.5 * alpha_p * (1.0 + exp(-4.0 / 3.0 * A * s)) * exp(-s);
}

static void check_presets(void)
{
	static const char *const names[] = {"skin1", "skin2", "marble", "wholemilk", "skimmilk", "cream",
					    "ketchup", "apple", "potato", "chicken1", "chicken2"};
	for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
		CHECK(sss_preset_find(names[i]) != NULL, "preset %s missing", names[i]);
	CHECK(sss_preset_find("skin3") == NULL, "unknown preset found");
	CHECK(sss_n_presets == 11, "%d presets", sss_n_presets);
	const sss_preset *skin1 = sss_preset_find("skin1");
	CHECK_NEAR(skin1->sigma_s_per_mm[0], 0.74, 1e-6);
	CHECK_NEAR(skin1->sigma_a_per_mm[2], 0.48, 1e-6);
}

/* Physical -> artist against known values. */
static void check_to_artist(void)
{
	/* JMLH01, Figure 5 lists the diffuse reflectance Rd the coefficients give with the preset's
	 * eta: the derivation must reproduce it to about the table's two digits. */
	struct { const char *name; double rd[3]; } rd[] = {
		{"marble", {0.83, 0.79, 0.75}}, {"skin1", {0.44, 0.22, 0.13}}, {"ketchup", {0.16, 0.01, 0.00}},
		{"potato", {0.77, 0.62, 0.21}}, {"wholemilk", {0.91, 0.88, 0.76}}, {"apple", {0.85, 0.84, 0.53}}};
	for (size_t i = 0; i < sizeof rd / sizeof rd[0]; i++) {
		const sss_preset *p = sss_preset_find(rd[i].name);
		for (int c = 0; c < 3; c++) {
			double a, l;
			sss_medium_to_artist(p->sigma_s_per_mm[c], p->sigma_a_per_mm[c], p->eta, &a, &l);
			CHECK(a > rd[i].rd[c] - 0.04 && a < rd[i].rd[c] + 0.04, "%s channel %d: Rd %.4f, paper %.2f",
			      rd[i].name, c, a, rd[i].rd[c]);
		}
	}
	/* The exact FM1 against the polynomial F_dr: within 0.5 % of each other on every preset
	 * and the block iors (the polynomial's own error). */
	static const double etas[] = {1.3, 1.4, 1.45, 1.5};
	double worst = 0.0;
	for (int i = 0; i < sss_n_presets; i++)
		for (int e = 0; e < 4; e++)
			for (int c = 0; c < 3; c++) {
				const sss_preset *p = &sss_presets[i];
				double a, l, s = p->sigma_s_per_mm[c], k = p->sigma_a_per_mm[c];
				sss_medium_to_artist(s, k, etas[e], &a, &l);
				double poly = rd_polynomial(s / (s + k), etas[e]);
				worst = fmax(worst, fabs(a - poly) / poly);
			}
	printf("test_medium: exact FM1 and the polynomial F_dr: R_d differ by at most %.3g (relative)\n", worst);
	CHECK(worst < 5e-3 && worst > 0.0, "exact FM1 and the polynomial F_dr differ by %.3g (relative)", worst);
	/* l_d = 1/sqrt(3 sigma_a sigma_t'): skin1's red, 1/sqrt(3 * 0.032 * 0.772) = 3.6732944 mm. */
	double a, l;
	sss_medium_to_artist(0.74, 0.032, 1.4, &a, &l);
	CHECK_NEAR(l, 3.6732944, 1e-6);
	sss_medium_to_artist(1.0, 0.0, 1.4, &a, &l);
	CHECK(isinf(l) && a > 0.99, "no absorption: l_d infinite (%g), A near 1 (%g)", l, a);
}

static void check_round_trips(void)
{
	for (int i = 0; i < sss_n_presets; i++)
		for (int c = 0; c < 3; c++) {
			const sss_preset *p = &sss_presets[i];
			double a, r, s2, a2;
			sss_medium_to_artist(p->sigma_s_per_mm[c], p->sigma_a_per_mm[c], 1.4, &a, &r);
			sss_medium_to_physical(a, r, 1.4, &s2, &a2);
			CHECK(fabs(s2 - p->sigma_s_per_mm[c]) < 1e-9 * (1 + p->sigma_s_per_mm[c]) &&
				      fabs(a2 - p->sigma_a_per_mm[c]) < 1e-9 * (1 + p->sigma_a_per_mm[c]),
			      "%s channel %d: sigma_s %g -> %.12g, sigma_a %g -> %.12g", p->name, c, p->sigma_s_per_mm[c], s2,
			      p->sigma_a_per_mm[c], a2);
		}
	for (double alb = 0.05; alb < 0.9; alb += 0.1)
		for (double rad = 0.1; rad < 20; rad *= 3) {
			double s, a, alb2, rad2;
			sss_medium_to_physical(alb, rad, 1.3, &s, &a);
			sss_medium_to_artist(s, a, 1.3, &alb2, &rad2);
			CHECK_NEAR(alb2, alb, 1e-9);
			CHECK_NEAR(rad2, rad, 1e-9 * rad);
		}
}

/* What sss_medium_derive makes of a spec: the base, the written form over it, the other derived. */
static void check_derive(void)
{
	const sss_preset *skin1 = sss_preset_find("skin1");
	sss_medium m;
	double a, l, s, k;
	/* A preset alone: its coefficients exactly, their artist form. */
	sss_medium_spec sp = {.preset = "skin1"};
	sss_medium_derive(&sp, 1.4, &m);
	sss_medium_to_artist(skin1->sigma_s_per_mm[1], skin1->sigma_a_per_mm[1], 1.4, &a, &l);
	CHECK(m.sigma_s_per_mm[1] == skin1->sigma_s_per_mm[1] && m.sigma_a_per_mm[1] == skin1->sigma_a_per_mm[1] &&
		  m.albedo[1] == a && m.ld_mm[1] == l,
	      "preset alone: sigma_s %g sigma_a %g albedo %g l_d %g", m.sigma_s_per_mm[1], m.sigma_a_per_mm[1],
	      m.albedo[1], m.ld_mm[1]);
	/* An artist colour over a preset (skin { color 0.5 }): the preset's radius, the colour. */
	sp = (sss_medium_spec){.preset = "skin1", .form = SSS_FORM_ARTIST, .has = SSS_HAS_ALBEDO, .albedo = v3s(0.5f)};
	sss_medium_derive(&sp, 1.4, &m);
	sss_medium_to_artist(skin1->sigma_s_per_mm[0], skin1->sigma_a_per_mm[0], 1.4, &a, &l);
	sss_medium_to_physical(0.5, l, 1.4, &s, &k);
	CHECK(m.albedo[0] == 0.5 && m.ld_mm[0] == l && m.sigma_s_per_mm[0] == s && m.sigma_a_per_mm[0] == k,
	      "colour over a preset: albedo %g l_d %g (want %g), sigma_s %g sigma_a %g", m.albedo[0], m.ld_mm[0], l,
	      m.sigma_s_per_mm[0], m.sigma_a_per_mm[0]);
	/* Artist defaults with one physical coefficient written (wax { sigma_s 1 }): sigma_a from
	 * the defaults' physical form. */
	sp = (sss_medium_spec){.form = SSS_FORM_PHYSICAL, .has = SSS_HAS_SIGMA_S | SSS_HAS_ALBEDO | SSS_HAS_RADIUS,
			       .sigma_s_per_mm = v3s(1.0f), .albedo = v3(0.95f, 0.78f, 0.45f), .radius_mm = v3(2, 1.2f, 0.6f)};
	sss_medium_derive(&sp, 1.45, &m);
	sss_medium_to_physical(0.45f, 0.6f, 1.45, &s, &k);
	sss_medium_to_artist(1.0, k, 1.45, &a, &l);
	CHECK(m.sigma_s_per_mm[2] == 1.0 && m.sigma_a_per_mm[2] == k && m.albedo[2] == a && m.ld_mm[2] == l,
	      "sigma_s over artist defaults: sigma_a %g (want %g), albedo %g (want %g)", m.sigma_a_per_mm[2], k,
	      m.albedo[2], a);
	/* A preset written after nothing else of its form, then a coefficient over it. */
	sp = (sss_medium_spec){.preset = "apple", .form = SSS_FORM_PHYSICAL, .has = SSS_HAS_SIGMA_A,
			       .sigma_a_per_mm = v3s(0.5f)};
	sss_medium_derive(&sp, 1.3, &m);
	CHECK(m.sigma_s_per_mm[0] == sss_preset_find("apple")->sigma_s_per_mm[0] && m.sigma_a_per_mm[0] == 0.5,
	      "sigma_a over a preset: sigma_s %g sigma_a %g", m.sigma_s_per_mm[0], m.sigma_a_per_mm[0]);
}

/* Each name table read both ways. */
static void check_names(void)
{
	for (int i = 0; i < SSS_METHODS; i++) {
		sss_method m = SSS_METHOD_VOLUME;
		CHECK(sss_method_from_name(sss_method_name((sss_method)i), &m) && m == (sss_method)i,
		      "method %d: '%s' reads back as %d", i, sss_method_name((sss_method)i), (int)m);
	}
	for (int i = 0; i < SSS_PROFILE_KINDS; i++) {
		sss_profile_kind k = SSS_PROFILE_DIPOLE;
		CHECK(sss_profile_from_name(sss_profile_name((sss_profile_kind)i), &k) && k == (sss_profile_kind)i,
		      "profile %d: '%s' reads back as %d", i, sss_profile_name((sss_profile_kind)i), (int)k);
	}
	sss_method m;
	sss_profile_kind k;
	CHECK(!sss_method_from_name("circles", &m) && !sss_profile_from_name("Burley", &k), "unknown names refused");
	CHECK(!strcmp(sss_method_name(SSS_METHOD_FULLCIRCLE), "fullcircle") &&
		  !strcmp(sss_profile_name(SSS_PROFILE_SUM_OF_GAUSSIANS), "sum_of_gaussians") &&
		  !strcmp(sss_method_name(SSS_METHOD_AUTO), "auto") &&
		  !strcmp(sss_method_name((sss_method)SSS_METHODS), "?"),
	      "the names of the scene language");
}

/* POV-Ray's translucency (medium.h): its F_dr approximation by hand at a few iors, and l_d for
 * hand-derived cases (an independent Python bisection of the same R_d with POV-Ray's A_F, then
 * T alpha' / sqrt(3 (1 - alpha')) and, as a cross-check, 1/sqrt(3 sigma_a sigma_t') from
 * sigma_s' = 1/T); the artist -> physical inversion with POV-Ray's own F_dr gives back sigma_s' =
 * 1/T. */
static void check_pov_translucency(void)
{
	CHECK_NEAR(sss_pov_fresnel_diffuse(1.0), 0.0, 1e-15);
	/* ((1 - 1/1.5) + 3 (1/3)^4.5) / 4 = (0.333333 + 3 * 0.0071277) / 4 */
	CHECK_NEAR(sss_pov_fresnel_diffuse(1.5), 0.08867916915916321, 1e-12);
	CHECK_NEAR(sss_pov_fresnel_diffuse(1.45), 0.08146200874334836, 1e-12);
	CHECK_NEAR(sss_pov_fresnel_diffuse(0.8), 0.03472537023796751, 1e-12); /* 0.64 - 0.8^2.25 */
	struct { double rd, t_mm, eta, alpha_p, ld_mm; } c[] = {
		{0.5, 1.0, 1.5, 0.9509911282904941, 2.480153073223057},
		{0.48, 2.5, 1.45, 0.9446513337273659, 5.795585848145875},	/* subsurface.pov's candle, red */
		{0.006, 0.5, 1.45, 0.060037604588687274, 0.017876294201699196}, /* and its blue */
		{0.9, 0.4562, 1.5, 0.9988546047894247, 7.773547349912382},
		{0.3, 1.0, 1.0, 0.8452371414148621, 1.2404651677009542},
	};
	for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
		double a = sss_pov_alpha_prime(c[i].rd, c[i].eta);
		double ld = sss_pov_translucency_radius_mm(c[i].rd, c[i].t_mm, c[i].eta);
		CHECK(fabs(a - c[i].alpha_p) < 1e-12, "case %zu: alpha' %.15g, by hand %.15g", i, a, c[i].alpha_p);
		CHECK(fabs(ld / c[i].ld_mm - 1.0) < 1e-9, "case %zu: l_d %.15g mm, by hand %.15g", i, ld, c[i].ld_mm);
		double st = 1.0 / (c[i].t_mm * a), sa = st - 1.0 / c[i].t_mm;
		CHECK_NEAR(ld, 1.0 / sqrt(3.0 * sa * st), 1e-12 * ld);
	}
	/* The bounds: rd 0 keeps a positive radius, rd 1 a finite one; l_d grows with rd and with T. */
	double l0 = sss_pov_translucency_radius_mm(0.0, 2.0, 1.5), l1 = sss_pov_translucency_radius_mm(1.0, 2.0, 1.5);
	CHECK(l0 > 0.0 && l0 <= 2.0 * SSS_POV_MIN_RADIUS_FRACTION * 1.0000001, "rd 0: l_d %g", l0);
	CHECK(isfinite(l1) && l1 > 1.0, "rd 1: l_d %g", l1);
	double prev = 0.0;
	for (int k = 1; k <= 99; k++) {
		double l = sss_pov_translucency_radius_mm(k / 100.0, 1.0, 1.3);
		CHECK(l > prev, "l_d not increasing at rd %d/100: %g after %g", k, l, prev);
		prev = l;
	}
	CHECK_NEAR(sss_pov_translucency_radius_mm(0.4, 3.0, 1.3), 3.0 * sss_pov_translucency_radius_mm(0.4, 1.0, 1.3),
		   1e-12);
}

/* Jensen et al. 2001's dipole profile R_d(r) (their eq. 4, per unit area) with POV-Ray's boundary
 * term A = (1 + F)/(1 - F), F = POV-Ray's F_dr: reduced albedo a, sigma_t' st (per mm), r in mm. */
static double dipole_r(double r, double a, double st, double eta)
{
	double f = sss_pov_fresnel_diffuse(eta), A = (1.0 + f) / (1.0 - f);
	double sa = st * (1.0 - a), str = sqrt(3.0 * sa * st);
	double zr = 1.0 / st, zv = zr * (1.0 + 4.0 / 3.0 * A);
	double dr = sqrt(r * r + zr * zr), dv = sqrt(r * r + zv * zv);
	return a / (4.0 * M_PI) *
	       (zr * (str * dr + 1.0) * exp(-str * dr) / (dr * dr * dr) + zv * (str * dv + 1.0) * exp(-str * dv) / (dv * dv * dv));
}

/* POV-Ray's brightness over circe's (sss_pov_gain): against values computed independently (a
 * Python script: POV-Ray's F_dr, JMLH01's R_d inverted by bisection, FM1 by a midpoint rule of
 * 200000 steps, then (1 - 2 FM1) (k + alpha'/(24 rd))), and its two parts rebuilt here from what
 * POV-Ray 3.7's trace.cpp does (read, not copied): ComputeSubsurfaceScattering's diffuse estimate
 * on a half-space, its probe rays from a base point 1/sigma_t' deep, uniform over the sphere,
 * each weighted by 4 pi d^2 / cos, averaged over the rays that hit (the upward half), is twice the
 * dipole's R_d; its single scattering at normal light and view, s = -ln(eps) / sigma_t, is
 * alpha'/24 (sigma_s F p / sigma_tc e^{-2 sigma_t s}, sigma_tc = 2 sigma_t, p = 1/4, F = 1). */
static void check_pov_gain(void)
{
	struct { double rd, eta, closed, open; } c[] = {
		{0.5, 1.5, 0.9801979659, 1.8884200066},
		{0.1, 1.45, 1.1255424728, 2.0411755137},
		{0.9, 1.3, 0.9822819550, 1.9211501298},
		{0.0, 1.5, 1.3105167368, 2.2187387775}, /* held at rd 1e-6 */
		{0.3, 1.0, 1.1173940474, 2.1173940474},
	};
	for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
		double g0 = sss_pov_gain(c[i].rd, c[i].eta, 1.0), g1 = sss_pov_gain(c[i].rd, c[i].eta, 2.0);
		CHECK(fabs(g0 / c[i].closed - 1.0) < 1e-8 && fabs(g1 / c[i].open - 1.0) < 1e-8,
		      "case %zu: gain closed %.10g open %.10g, by hand %.10g %.10g", i, g0, g1, c[i].closed, c[i].open);
	}
	CHECK(sss_pov_gain(-1.0, 1.5, 1.0) == sss_pov_gain(0.0, 1.5, 1.0) && isfinite(sss_pov_gain(0.0, 1.5, 2.0)),
	      "rd <= 0 is held");
	/* The two parts from POV-Ray's estimator, for rd 0.5 at eta 1.5, T = 1 mm. */
	const double rd = 0.5, eta = 1.5, a = sss_pov_alpha_prime(rd, eta), st = 1.0 / a, z0 = 1.0 / st;
	const int n = 200000;
	double mean_hit = 0.0, single = 0.0;
	for (int i = 0; i < n; i++) {
		double mu = (i + 0.5) / n; /* over the hits, mu = cos is uniform in (0, 1] */
		double d = z0 / mu, r = d * sqrt(1.0 - mu * mu);
		mean_hit += dipole_r(r, a, st, eta) * 4.0 * M_PI * d * d / mu / n;
		double eps = (i + 0.5) / n, s = -log(eps) / st;
		single += (a * st) * 0.25 / (2.0 * st) * exp(-2.0 * st * s) / n;
	}
	printf("POV-Ray's estimator on a half-space: mean over hits %.6f = %.6f R_d; single %.6f = alpha'/%.4f\n",
	       mean_hit, mean_hit / rd, single, a / single);
	CHECK(fabs(mean_hit / (2.0 * rd) - 1.0) < 1e-3, "half-space: %.6g, expected 2 R_d = %.6g", mean_hit, 2.0 * rd);
	CHECK(fabs(single * 24.0 / a - 1.0) < 1e-6, "single scattering %.9g, expected alpha'/24 = %.9g", single, a / 24.0);
	/* POV-Ray's Ft(0)^2 (k rd + single) over circe's Ft(0)^2 rd / (1 - 2 FM1) */
	double c_norm = 1.0 - 2.0 * sss_fresnel_moment1(eta);
	CHECK_NEAR(sss_pov_gain(rd, eta, 2.0), (mean_hit + single) / rd * c_norm, 1e-3);
	CHECK_NEAR(sss_pov_gain(rd, eta, 1.0), (mean_hit / 2.0 + single) / rd * c_norm, 1e-3);
}

/* auto's probability of the walk: 1 up to SSS_AUTO_WALK_BELOW l_d, 0 from SSS_AUTO_CIRCLE_ABOVE
 * on, continuous (no seam) and monotone between, with slope 0 at both ends; the extremes are
 * finite. */
static void check_auto_rule(void)
{
	const double lo = SSS_AUTO_WALK_BELOW, hi = SSS_AUTO_CIRCLE_ABOVE;
	CHECK(sss_auto_walk_prob(0.0) == 1.0 && sss_auto_walk_prob(lo) == 1.0 && sss_auto_walk_prob(-1.0) == 1.0,
	      "thin walks");
	CHECK(sss_auto_walk_prob(NAN) == 1.0 && sss_auto_walk_prob(hi) == 0.0 && sss_auto_walk_prob(INFINITY) == 0.0 &&
		  sss_auto_walk_prob(1e300) == 0.0,
	      "thick is circle; NaN walks");
	CHECK_NEAR(sss_auto_walk_prob(sqrt(lo * hi)), 0.5, 1e-12); /* the geometric middle of the band */
	const double step = 1e-4;
	double prev = 1.0, worst_step = 0.0;
	for (double m = 0.5 * lo; m < 1.5 * hi; m += step) {
		double p = sss_auto_walk_prob(m);
		CHECK(p <= prev && p >= 0.0 && p <= 1.0, "m %g: p %g after %g", m, p, prev);
		worst_step = fmax(worst_step, prev - p);
		prev = p;
	}
	/* the largest change over one step: the slope of 1 - smoothstep(ln(m/lo)/ln(hi/lo)) is at most
	 * 1.5 / (m ln(hi/lo)), largest at the low end */
	double slope = 1.5 / (lo * log(hi / lo));
	CHECK(worst_step < 1.01 * slope * step, "a jump of %g in the walk probability (slope bound %g)", worst_step,
	      slope * step);
	CHECK(1.0 - sss_auto_walk_prob(lo * 1.0001) < 1e-6 && sss_auto_walk_prob(hi / 1.0001) < 1e-6,
	      "slope 0 at the ends of the band");
}

/* auto's light factor: 0 up to a far-side share of SSS_AUTO_LIGHT_CIRCLE, 1 from SSS_AUTO_LIGHT_WALK,
 * continuous and monotone between with slope 0 at both ends; the share itself, E_far T / (E_near R +
 * E_far T) of the largest channel, 0 when the far side is unlit; the diffusion slab's T and R against
 * their sinh forms, monotone in the thickness, bounded, and without overflow. */
static void check_auto_light(void)
{
	const double lo = SSS_AUTO_LIGHT_CIRCLE, hi = SSS_AUTO_LIGHT_WALK;
	CHECK(sss_auto_light_prob(0.0) == 0.0 && sss_auto_light_prob(lo) == 0.0 && sss_auto_light_prob(-1.0) == 0.0,
	      "no far light: circle");
	CHECK(sss_auto_light_prob(hi) == 1.0 && sss_auto_light_prob(1.0) == 1.0 && sss_auto_light_prob(NAN) == 1.0,
	      "far light: the walk; NaN walks");
	CHECK_NEAR(sss_auto_light_prob(sqrt(lo * hi)), 0.5, 1e-12);
	const double step = 1e-6;
	double prev = 0.0, worst_step = 0.0;
	for (double f = 0.5 * lo; f < 1.5 * hi; f += step) {
		double p = sss_auto_light_prob(f);
		CHECK(p >= prev && p >= 0.0 && p <= 1.0, "f %g: p %g after %g", f, p, prev);
		worst_step = fmax(worst_step, p - prev);
		prev = p;
	}
	/* smoothstep(ln(f/lo)/ln(hi/lo)) has slope at most 1.5 / (f ln(hi/lo)), largest at f = lo */
	double slope = 1.5 / (lo * log(hi / lo));
	CHECK(worst_step < 1.01 * slope * step, "a jump of %g in the light factor (slope bound %g)", worst_step,
	      slope * step);
	CHECK(sss_auto_light_prob(lo * 1.0001) < 1e-6 && 1.0 - sss_auto_light_prob(hi / 1.0001) < 1e-6,
	      "slope 0 at the ends of the band");
	/* the diffusion slab of skin1 (eta 1.4) */
	const sss_preset *sk = sss_preset_find("skin1");
	double ss[3], sa[3];
	for (int c = 0; c < 3; c++)
		ss[c] = sk->sigma_s_per_mm[c], sa[c] = sk->sigma_a_per_mm[c];
	sss_auto_slab sl;
	CHECK(sss_auto_slab_make(&sl, ss, sa, 1.4), "the slab of skin1");
	CHECK(sss_auto_light_share(&sl, 1.0, 0.0, 2.0) == 0.0 && sss_auto_light_share(&sl, 0.0, 0.0, 0.0) == 0.0 &&
		  sss_auto_light_share(&sl, 1.0, NAN, 1.0) == 0.0,
	      "an unlit far side has no share");
	CHECK(sss_auto_light_share(&sl, 0.0, 3.0, 5.0) == 1.0, "an unlit near side: all the light is the far side's");
	/* T and R against sinh(sigma_tr s)/sinh(sigma_tr d) and sinh(sigma_tr (d - s))/sinh(sigma_tr d) written
	 * out from the coefficients (JMLH01's D, z_b = 2 A D with A = (1 + F_dr)/(1 - F_dr)) */
	double fdr = 2.0 * sss_fresnel_moment1(1.0 / 1.4), af = (1.0 + fdr) / (1.0 - fdr);
	double f_max = 0.0;
	for (int c = 0; c < 3; c++) {
		double st = ss[c] + sa[c], D = 1.0 / (3.0 * st), zb = 2.0 * af * D, k = sqrt(3.0 * sa[c] * st);
		double L = 4.0, src = 1.0 / st + zb, d = L + 2.0 * zb, t, r;
		sss_auto_slab_tr(&sl, c, L, &t, &r);
		CHECK_NEAR(t, sinh(k * src) / sinh(k * d), 1e-12);
		CHECK_NEAR(r, sinh(k * (d - src)) / sinh(k * d), 1e-12);
		f_max = fmax(f_max, 40.0 * t / (1.0 * r + 40.0 * t));
		/* less through and more back as the slab thickens; never more than the source */
		double t2, r2, t0, r0, ti, ri;
		sss_auto_slab_tr(&sl, c, 2.0 * L, &t2, &r2);
		sss_auto_slab_tr(&sl, c, 0.0, &t0, &r0);
		sss_auto_slab_tr(&sl, c, INFINITY, &ti, &ri);
		CHECK(t2 < t && r2 > r && t + r <= 1.0 && t0 + r0 <= 1.0 && t0 > t, "channel %d: T %g %g, R %g %g", c, t, t2, r,
		      r2);
		CHECK(ti == 0.0 && fabs(ri - exp(-k * src)) < 1e-12 && r2 < ri, "channel %d: the half space", c);
		sss_auto_slab_tr(&sl, c, 1e6, &t2, &r2); /* no overflow at any thickness */
		CHECK(t2 == 0.0 && isfinite(r2), "channel %d: a slab 1 km thick: T %g R %g", c, t2, r2);
	}
	CHECK_NEAR(sss_auto_light_share(&sl, 1.0, 40.0, 4.0), f_max, 1e-15); /* the largest channel's */
	CHECK(sss_auto_light_share(&sl, 2.0, 5.0, -1.0) == sss_auto_light_share(&sl, 2.0, 5.0, 0.0),
	      "L < 0 counts as 0");
	/* the share from R/T alone (issue 21's cheaper form) against far T / (near R + far T) from
	 * sss_auto_slab_tr, over thicknesses from 0 to 1 m and light ratios from 1e-4 to 1e4 */
	double worst = 0.0;
	for (double L = 0.0; L < 1000.0; L = L * 1.5 + 0.01)
		for (double q = 1e-4; q < 1e4; q *= 3.0) {
			double want = 0.0;
			for (int c = 0; c < 3; c++) {
				double tc, rc;
				sss_auto_slab_tr(&sl, c, L, &tc, &rc);
				want = fmax(want, q * tc / (rc + q * tc));
			}
			worst = fmax(worst, fabs(sss_auto_light_share(&sl, 1.0, q, L) - want));
		}
	CHECK(worst < 1e-13, "the share by R/T agrees with T and R: largest difference %g", worst);
	CHECK(sss_auto_light_share(&sl, 1.0, 5.0, INFINITY) == 0.0 && sss_auto_light_share(&sl, 0.0, 5.0, INFINITY) == 0.0,
	      "a half space lets nothing through, lit or not");
	/* no absorption: everything leaves, T + R = 1, linear in L */
	const double none[3] = {0.0, 0.0, 0.0};
	CHECK(sss_auto_slab_make(&sl, ss, none, 1.4), "the slab without absorption");
	double t, r;
	sss_auto_slab_tr(&sl, 0, 3.0, &t, &r);
	CHECK_NEAR(t + r, 1.0, 1e-12);
	CHECK(!sss_auto_slab_make(&sl, none, none, 1.4), "no extinction: no slab");
}

/* auto's profile tail (issue 21): the thickness where the largest channel's tail 1 - CDF(L) is
 * given, by bisection, for every profile kind on skin1 (the channels' tails checked either side
 * of it), ordered (a smaller tail is further), 0 when even L = 0 is below it; and the floor
 * sss_auto_thin_prob, 1 up to the first thickness, 0 from the second, monotone and continuous
 * (the same slope bound as the geometric rule's) between, with NaN walking. */
static void check_auto_tail(void)
{
	const sss_preset *sk = sss_preset_find("skin1");
	double ss[3], sa[3];
	for (int c = 0; c < 3; c++)
		ss[c] = sk->sigma_s_per_mm[c], sa[c] = sk->sigma_a_per_mm[c];
	const sss_profile_kind kinds[4] = {SSS_PROFILE_GAUSSIAN, SSS_PROFILE_SUM_OF_GAUSSIANS, SSS_PROFILE_BURLEY,
					   SSS_PROFILE_DIPOLE};
	for (int k = 0; k < 4; k++) {
		sss_profile p;
		CHECK(sss_profile_from_physical(&p, kinds[k], ss, sa, 1.4), "skin1's %s profile", sss_profile_name(kinds[k]));
		double l5 = sss_auto_tail_thickness(&p, SSS_AUTO_TAIL_WALK), l2 = sss_auto_tail_thickness(&p, SSS_AUTO_TAIL_CIRCLE);
		double t_at = 0.0, t_below = 0.0;
		for (int c = 0; c < 3; c++) {
			t_at = fmax(t_at, 1.0 - sss_channel_cdf(&p.ch[c], l2));
			t_below = fmax(t_below, 1.0 - sss_channel_cdf(&p.ch[c], l2 * (1.0 - 1e-9)));
		}
		printf("skin1 %s: the profile's tail is 5 %% at %.3f mm, 2 %% at %.3f mm\n", sss_profile_name(kinds[k]), l5, l2);
		CHECK(l5 > 0.0 && l5 < l2 && l2 <= sss_profile_r_max(&p), "%s: tail thicknesses %g, %g", sss_profile_name(kinds[k]),
		      l5, l2);
		CHECK(t_at <= SSS_AUTO_TAIL_CIRCLE && t_below > SSS_AUTO_TAIL_CIRCLE * (1.0 - 1e-6),
		      "%s: the tail %g at %g mm, %g just below", sss_profile_name(kinds[k]), t_at, l2, t_below);
		CHECK(sss_auto_tail_thickness(&p, 0.999999) == 0.0 || sss_auto_tail_thickness(&p, 0.999999) < l5,
		      "%s: a tail of nearly all", sss_profile_name(kinds[k]));
	}
	const double a = 2.0, b = 5.0;
	CHECK(sss_auto_thin_prob(0.0, a, b) == 1.0 && sss_auto_thin_prob(a, a, b) == 1.0 && sss_auto_thin_prob(NAN, a, b) == 1.0,
	      "thinner than the tail walks");
	CHECK(sss_auto_thin_prob(b, a, b) == 0.0 && sss_auto_thin_prob(INFINITY, a, b) == 0.0 &&
		  sss_auto_thin_prob(1.0, 0.0, 0.0) == 0.0,
	      "thicker, or no tail: no floor");
	CHECK_NEAR(sss_auto_thin_prob(sqrt(a * b), a, b), 0.5, 1e-12);
	double prev = 1.0, worst = 0.0, step = 1e-4;
	for (double L = 0.5 * a; L < 1.5 * b; L += step) {
		double q = sss_auto_thin_prob(L, a, b);
		CHECK(q <= prev && q >= 0.0 && q <= 1.0, "L %g: %g after %g", L, q, prev);
		worst = fmax(worst, prev - q), prev = q;
	}
	CHECK(worst < 1.01 * 1.5 / (a * log(b / a)) * step, "a jump of %g in the floor", worst);
}

int main(void)
{
	check_presets();
	check_to_artist();
	check_round_trips();
	check_derive();
	check_names();
	check_pov_translucency();
	check_pov_gain();
	check_auto_rule();
	check_auto_light();
	check_auto_tail();
	return check_done("test_medium");
}
