/* test_walk: the volume random walk against closed forms: Chandrasekhar's albedo of a semi-infinite
 * isotropic medium (grey and RGB, spectral MIS), energy conservation without absorption (box and
 * sphere, Fresnel boundary), Beer-Lambert through a pure absorber; the step bound and lost walks are
 * reported; the closed-mesh check on closed and open meshes; auto's diffusion slab (sss/medium.h)
 * against the walk's transmission and reflection of sheets of skin, wax and marble. */
#include "accel/bvh.h"
#include "base/rng.h"
#include "check.h"
#include "geom/prim.h"
#include "sss/medium.h"
#include "sss/profile.h"
#include "sss/walk.h"
#include "sss/walk_exp.h"
#include "mean3.h"
#include "sss_test.h"

#include <stdio.h>
#include <string.h>

/* ---- geometry through the probe interface ----------------------------------------------------- */

typedef struct object {
	mesh m;
	bvh *b;
	sss_probe_mesh pm;
	sss_probe pr;
} object;

static void object_init(object *o)
{
	o->b = bvh_build(o->m.positions, o->m.num_vertices, o->m.indices, o->m.num_triangles);
	CHECK(o->b != NULL, "bvh_build failed");
	o->pm = (sss_probe_mesh){o->b, &o->m};
	o->pr = sss_probe_of_mesh(&o->pm);
}

static void object_box(object *o, vec3 lo, vec3 hi)
{
	CHECK(prim_box(lo, hi, &o->m), "prim_box failed");
	object_init(o);
}

static void object_free(object *o)
{
	bvh_free(o->b);
	mesh_free(&o->m);
}

/* ---- statistics ------------------------------------------------------------------------------ */

typedef struct stat3 {
	test_mean3 m;
	long count[SSS_WALK_BAD_INPUT + 1];
	long steps, reentries, runs;
} stat3;

static void stat_add(stat3 *st, const sss_walk_result *r, bool counts)
{
	st->count[r->status]++;
	st->steps += r->steps;
	st->reentries += r->reentries;
	st->runs += r->runs;
	double w[3] = {counts ? r->weight.x : 0.0, counts ? r->weight.y : 0.0, counts ? r->weight.z : 0.0};
	test_mean3_add(&st->m, w);
}

/* ---- Chandrasekhar's H-function of isotropic scattering -------------------------------------- */

#define H_NODES 256
static double h_x[H_NODES], h_w[H_NODES], h_val[H_NODES];

/* H on Gauss-Legendre nodes of [0, 1], iterating 1/H(mu) = sqrt(1 - a) + a/2 integral_0^1
 * mu' H(mu') / (mu + mu') dmu' (Chandrasekhar 1960, Radiative Transfer, eq. V.(32)'s alternative
 * form, which converges for every albedo a); returns H(mu) by the same quadrature. */
static double h_function(double a, double mu)
{
	double x[H_NODES], w[H_NODES];
	gauss_legendre(H_NODES, x, w);
	for (int i = 0; i < H_NODES; i++)
		h_x[i] = 0.5 * (x[i] + 1.0), h_w[i] = 0.5 * w[i], h_val[i] = 1.0;
	for (int it = 0; it < 2000; it++) {
		double next[H_NODES], change = 0.0;
		for (int i = 0; i < H_NODES; i++) {
			double s = 0.0;
			for (int j = 0; j < H_NODES; j++)
				s += h_w[j] * h_x[j] * h_val[j] / (h_x[i] + h_x[j]);
			next[i] = 1.0 / (sqrt(1.0 - a) + 0.5 * a * s);
			change = fmax(change, fabs(next[i] - h_val[i]));
		}
		memcpy(h_val, next, sizeof next);
		if (change < 1e-13)
			break;
	}
	double s = 0.0;
	for (int j = 0; j < H_NODES; j++)
		s += h_w[j] * h_x[j] * h_val[j] / (mu + h_x[j]);
	return 1.0 / (sqrt(1.0 - a) + 0.5 * a * s);
}

/* The plane albedo of a semi-infinite isotropic medium of single-scattering albedo a lit at
 * cos(incidence) mu: 1 - H(mu) sqrt(1 - a) (Chandrasekhar 1960, eq. IV.(42)-(43)). */
static double plane_albedo(double a, double mu)
{
	return 1.0 - h_function(a, mu) * sqrt(1.0 - a);
}

/* ---- the checks ------------------------------------------------------------------------------ */

static void check_basics(void)
{
	/* Fresnel: normal incidence ((eta - 1)/(eta + 1))^2, total internal reflection, eta = 1 */
	CHECK_NEAR(sss_fresnel_dielectric(1.0, 1.5), 0.04, 1e-12);
	CHECK_NEAR(sss_fresnel_dielectric(0.3, 1.0 / 1.5), 1.0, 0.0);
	CHECK_NEAR(sss_fresnel_dielectric(0.3, 1.0), 0.0, 1e-15);

	/* the reduced form: sigma_s = sigma_s' / (1 - g), per scene unit */
	double ss[3] = {1.0, 2.0, 0.5}, sa[3] = {0.1, 0.0, 0.3};
	sss_walk_medium m;
	CHECK(sss_walk_medium_from_reduced(&m, ss, sa, 0.5, 1.4, 10.0), "refused");
	CHECK_NEAR(m.sigma_s[0], 20.0, 1e-12);
	CHECK_NEAR(m.sigma_s[2], 10.0, 1e-12);
	CHECK_NEAR(m.sigma_a[2], 3.0, 1e-12);
	CHECK(!sss_walk_medium_from_reduced(&m, ss, sa, 1.0, 1.4, 10.0), "g = 1 accepted");
	CHECK(!sss_walk_medium_from_reduced(&m, ss, sa, 0.5, 0.0, 10.0), "eta = 0 accepted");
	sa[1] = -1.0;
	CHECK(!sss_walk_medium_from_reduced(&m, ss, sa, 0.5, 1.4, 10.0), "negative sigma_a accepted");
	sa[1] = NAN;
	CHECK(!sss_walk_medium_from_reduced(&m, ss, sa, 0.5, 1.4, 10.0), "NaN sigma_a accepted");

	/* Henyey-Greenstein: the mean cosine is g, the second moment (1 + 2 g^2)/3 */
	const double gs[] = {0.0, 0.5, -0.3, 0.9, 0.99};
	rng r;
	rng_seed(&r, 7, 1);
	long n = test_scaled(200000);
	/* and the azimuth (float sine and cosine since issue 21) uniform: about w, along two
	 * perpendicular axes e1, e2, <x^2> = <y^2> = (1 - <mu^2>)/2, <x> = <y> = <x y> = 0 */
	for (size_t k = 0; k < sizeof gs / sizeof gs[0]; k++) {
		vec3 w = v3_normalize(v3(0.3f, -0.5f, 0.8f)), e1, e2;
		v3_basis(w, &e1, &e2);
		double s = 0.0, s2 = 0.0, s4 = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, syy = 0.0, sxy = 0.0;
		for (long i = 0; i < n; i++) {
			double u1 = rng_double(&r), u2 = rng_double(&r);
			vec3 d = sss_walk_sample_hg(w, gs[k], u1, u2);
			double mu = v3_dot(d, w), x = v3_dot(d, e1), y = v3_dot(d, e2);
			CHECK(fabsf(v3_length(d) - 1.0f) < 1e-5f, "|d| = %g", v3_length(d));
			s += mu, s2 += mu * mu, s4 += mu * mu * mu * mu;
			sx += x, sy += y, sxx += x * x, syy += y * y, sxy += x * y;
		}
		/* each of x, y, x y has a variance at most 1 (|x|, |y| <= 1): 4 SE is 4 / sqrt(n) */
		double tol = 4.0 / sqrt((double)n), half = (1.0 - s2 / n) / 2.0;
		CHECK(fabs(sx / n) < tol && fabs(sy / n) < tol && fabs(sxy / n) < tol,
		      "g %g: azimuth <x> %g <y> %g <xy> %g (tolerance %g)", gs[k], sx / n, sy / n, sxy / n, tol);
		CHECK(fabs(sxx / n - half) < tol && fabs(syy / n - half) < tol, "g %g: <x^2> %g <y^2> %g, want %g",
		      gs[k], sxx / n, syy / n, half);
		double mean = s / n, se = sqrt((s2 / n - mean * mean) / n);
		double m2 = s2 / n, se2 = sqrt((s4 / n - m2 * m2) / n), want2 = (1.0 + 2.0 * gs[k] * gs[k]) / 3.0;
		CHECK(fabs(mean - gs[k]) <= 3.0 * se + 1e-12, "g %g: mean cosine %g +- %g", gs[k], mean, se);
		CHECK(fabs(m2 - want2) <= 3.0 * se2 + 1e-12, "g %g: <mu^2> %g +- %g, want %g", gs[k], m2, se2, want2);
	}
}

/* The walk's exponential (walk_exp.h) against libm's: its relative error bound over its range,
 * exact at 0, libm's own outside the range and for NaN. */
static void check_exp(void)
{
	double worst = 0.0, worst_x = 0.0;
	long n = 0;
	for (double x = -707.99; x < 708.0; x += 0.000713, n++) {
		double a = sss_walk_exp(x), b = exp(x), e = fabs(a - b) / b;
		if (!(e <= worst))
			worst = e, worst_x = x;
	}
	/* near 0 too, where the walk's arguments mostly are (short free paths) */
	for (double x = -1e-3; x < 1e-3; x += 1.37e-9, n++) {
		double a = sss_walk_exp(x), b = exp(x), e = fabs(a - b) / b;
		if (!(e <= worst))
			worst = e, worst_x = x;
	}
	printf("walk_exp: relative error at most %.3g (at x = %.6g) over %ld points; the bound %.3g\n", worst,
	       worst_x, n, SSS_WALK_EXP_REL_ERR);
	CHECK(worst <= SSS_WALK_EXP_REL_ERR, "walk_exp: relative error %g at x = %.17g", worst, worst_x);
	CHECK(sss_walk_exp(0.0) == 1.0, "walk_exp(0) = %.17g", sss_walk_exp(0.0));
	CHECK(sss_walk_exp(-800.0) == 0.0 && isinf(sss_walk_exp(800.0)) && isnan(sss_walk_exp(NAN)) &&
		      sss_walk_exp(-INFINITY) == 0.0,
	      "walk_exp outside its range: %g %g %g", sss_walk_exp(-800.0), sss_walk_exp(800.0), sss_walk_exp(NAN));
}

static void check_closure(void)
{
	object o;
	uint64_t open;
	CHECK(prim_box(v3(-1, -1, -1), v3(1, 2, 3), &o.m), "prim_box");
	CHECK(sss_walk_mesh_closure(&o.m, &open) == SSS_MESH_CLOSED && open == 0, "box: open edges %llu",
	      (unsigned long long)open);
	o.m.num_triangles--; /* a box without its last triangle has a hole of three edges */
	CHECK(sss_walk_mesh_closure(&o.m, &open) == SSS_MESH_OPEN && open == 3, "box - 1: open edges %llu",
	      (unsigned long long)open);
	mesh_free(&o.m);

	CHECK(prim_sphere(v3(0, 0, 0), 1.0f, 24, &o.m), "prim_sphere");
	CHECK(sss_walk_mesh_closure(&o.m, &open) == SSS_MESH_CLOSED && open == 0, "sphere: open edges %llu",
	      (unsigned long long)open);
	mesh_free(&o.m);

	CHECK(prim_plane(v3(0, 0, 1), 0.0f, v3(-1, -1, -1), v3(1, 1, 1), &o.m), "prim_plane");
	CHECK(sss_walk_mesh_closure(&o.m, &open) == SSS_MESH_OPEN && open > 0, "plane: open edges %llu",
	      (unsigned long long)open);
	mesh_free(&o.m);

	mesh empty = {0};
	CHECK(sss_walk_mesh_closure(&empty, &open) == SSS_MESH_OPEN, "empty mesh called closed");
}

/* The albedo of a large box (200 mean free paths of the thinnest channel on each side) lit at
 * normal incidence in the middle of its top face: light leaving through the top. */
/* The means of the last check_semi_infinite_at, per channel, and its runs a walk (check_runs). */
static double last_mean[3], last_runs;

static void check_semi_infinite_at(const char *name, const double albedo[3], const double sigma_t[3], double mu,
				   bool classic, double *se_out, double *steps_out)
{
	double lmax = 200.0 / fmin(sigma_t[0], fmin(sigma_t[1], sigma_t[2]));
	object o;
	object_box(&o, v3((float)-lmax, (float)-lmax, (float)-lmax), v3((float)lmax, (float)lmax, 0.0f));
	sss_walk_medium m = {{0}, {0}, 0.0, 1.0, classic};
	for (int c = 0; c < 3; c++)
		m.sigma_s[c] = albedo[c] * sigma_t[c], m.sigma_a[c] = (1.0 - albedo[c]) * sigma_t[c];
	rng r;
	rng_seed(&r, 11, 2);
	stat3 st = {0};
	long n = test_scaled(200000);
	vec3 w_in = v3((float)sqrt(1.0 - mu * mu), 0.0f, (float)-mu);
	for (long i = 0; i < n; i++) {
		sss_walk_result res = sss_walk(&m, &o.pr, v3(0, 0, 0), v3(0, 0, 1), 0.0f, w_in, &r, SSS_WALK_MAX_STEPS);
		bool top = res.status == SSS_WALK_EXITED && res.p.z == 0.0f;
		if (top)
			CHECK(res.dir.z > 0.0f && fabsf(v3_length(res.dir) - 1.0f) < 1e-5f, "i %ld steps %d p %g %g %g ng %g %g %g exit dir %g %g %g", i, res.steps, res.p.x, res.p.y, res.p.z, res.ng.x, res.ng.y, res.ng.z,
			      res.dir.x, res.dir.y, res.dir.z);
		stat_add(&st, &res, top);
	}
	for (int c = 0; c < 3; c++) {
		double want = plane_albedo(albedo[c], mu), got = test_mean3_mean(&st.m, c), se = test_mean3_se(&st.m, c);
		printf("semi-infinite %s%s, cos %.2f, ch %d: albedo %.3f: walk %.5f +- %.5f, Chandrasekhar %.5f (%+.2f SE)\n",
		       name, classic ? " (classic)" : "", mu, c, albedo[c], got, se, want, (got - want) / se);
		CHECK(fabs(got - want) <= 3.0 * se, "%s ch %d: %g +- %g, want %g", name, c, got, se, want);
		if (se_out)
			se_out[c] = se;
		last_mean[c] = got;
	}
	last_runs = (double)st.runs / st.m.n;
	if (steps_out)
		*steps_out = (double)st.steps / st.m.n;
	printf("  %ld walks, %.1f interactions each, %.2f runs inside a ball, lost %ld, step limit %ld, re-entries %ld\n",
	       st.m.n, (double)st.steps / st.m.n, (double)st.runs / st.m.n, st.count[SSS_WALK_LOST],
	       st.count[SSS_WALK_STEP_LIMIT], st.reentries);
	CHECK(st.count[SSS_WALK_LOST] == 0 && st.count[SSS_WALK_STEP_LIMIT] == 0, "lost %ld, step limit %ld",
	      st.count[SSS_WALK_LOST], st.count[SSS_WALK_STEP_LIMIT]);
	object_free(&o);
}

static void check_semi_infinite(const char *name, const double albedo[3], const double sigma_t[3])
{
	check_semi_infinite_at(name, albedo, sigma_t, 1.0, false, NULL, NULL);
}

/* Runs inside a ball (README.md, "Runs inside a ball"): deep in a free ball the walk's steps are a
 * run of classic steps of the hero, the channels' weights taking the whole run at once (the
 * hero's (sigma_s,k / sigma_t,h)^n and e^{-(sigma_t,k - sigma_t,h) L} per channel). A bright RGB
 * medium of three extinctions and albedos, each channel against Chandrasekhar (3 SE, in
 * check_semi_infinite_at) with the runs on and off: on, the walks make runs (one every two walks at least
 * on average), off none; the two agree per channel within 3 SE of their difference. A run that
 * forgot the channels' extinctions (e^{-(sigma_t,k - sigma_t,h) L}) fails both, by 30 SE and more
 * (measured, and the slab checks of check_auto_slab with it). */
static void check_runs(void)
{
	const double albedo[3] = {0.999, 0.99, 0.95}, sigma_t[3] = {1.0, 2.0, 0.5};
	double se_on[3], se_off[3], on[3];
	check_semi_infinite_at("rgb bright (runs)", albedo, sigma_t, 1.0, false, se_on, NULL);
	double runs_on = last_runs;
	memcpy(on, last_mean, sizeof on);
	sss_walk_set_run(false);
	check_semi_infinite_at("rgb bright (no runs)", albedo, sigma_t, 1.0, false, se_off, NULL);
	sss_walk_set_run(true);
	CHECK(runs_on >= 0.5 && last_runs == 0.0, "runs a walk: %g on, %g off", runs_on, last_runs);
	for (int c = 0; c < 3; c++) {
		double se = sqrt(se_on[c] * se_on[c] + se_off[c] * se_off[c]);
		printf("runs ch %d: on %.5f, off %.5f (%+.2f SE); variance on / off %.2f\n", c, on[c], last_mean[c],
		       (on[c] - last_mean[c]) / se, se_on[c] * se_on[c] / (se_off[c] * se_off[c]));
		CHECK(fabs(on[c] - last_mean[c]) <= 3.0 * se, "ch %d: runs %g, none %g, SE %g", c, on[c], last_mean[c], se);
	}
}

/* Guided and classic walks against Chandrasekhar at high albedos and oblique incidence; the
 * guided walk must be at least as good per interaction (printed: SE^2 x interactions, the cost
 * of a given noise in ray casts). */
static void check_guided_vs_classic(void)
{
	/* 0.999: marble's and wax's albedos, where the classic share of the mixture falls below 1/2
	 * (issue 21, WALK_FRAC_NU) */
	const double albedos[] = {0.95, 0.99, 0.3, 0.999}, mus[] = {1.0, 0.5, 1.0, 1.0}, ones[3] = {1, 1, 1};
	for (int i = 0; i < 4; i++) {
		double a[3] = {albedos[i], albedos[i], albedos[i]}, se_g[3], se_c[3], n_g, n_c;
		char name[64];
		snprintf(name, sizeof name, "grey %g", albedos[i]);
		check_semi_infinite_at(name, a, ones, mus[i], false, se_g, &n_g);
		check_semi_infinite_at(name, a, ones, mus[i], true, se_c, &n_c);
		double cost_g = se_g[0] * se_g[0] * n_g, cost_c = se_c[0] * se_c[0] * n_c;
		printf("  albedo %g cos %.2f: variance x interactions, classic / guided = %.2f\n", albedos[i], mus[i],
		       cost_c / cost_g);
		CHECK(cost_g < 1.1 * cost_c, "albedo %g: guided costs %g, classic %g", albedos[i], cost_g, cost_c);
	}
}

/* A slab of optical thickness 2 lit obliquely (the far side is near: the backward guide is in
 * use): guided and classic walks agree on the light leaving through the top (reflection) and
 * through the bottom (transmission); the classic walk is the analog estimator, unbiased. */
static void check_thin_slab(void)
{
	object o;
	object_box(&o, v3(-400, -400, -2), v3(400, 400, 0));
	rng r;
	rng_seed(&r, 23, 6);
	long n = test_scaled(100000);
	test_mean3 top[2] = {{0}}, bottom[2] = {{0}};
	double steps[2] = {0, 0};
	for (int classic = 0; classic < 2; classic++) {
		sss_walk_medium m = {{0.9, 0.7, 0.99}, {0.1, 0.3, 0.01}, 0.2, 1.3, classic};
		for (long i = 0; i < n; i++) {
			sss_walk_result res = sss_walk(&m, &o.pr, v3(0, 0, 0), v3(0, 0, 1), 0.0f, v3(0.6f, 0, -0.8f), &r,
						       SSS_WALK_MAX_STEPS);
			bool ex = res.status == SSS_WALK_EXITED;
			double w[3] = {res.weight.x, res.weight.y, res.weight.z}, z[3] = {0, 0, 0};
			test_mean3_add(&top[classic], ex && res.p.z == 0.0f ? w : z);
			test_mean3_add(&bottom[classic], ex && res.p.z == -2.0f ? w : z);
			steps[classic] += res.steps;
		}
	}
	for (int side = 0; side < 2; side++)
		for (int c = 0; c < 3; c++) {
			test_mean3 *gm = side ? &bottom[0] : &top[0], *cm = side ? &bottom[1] : &top[1];
			double a = test_mean3_mean(gm, c), b = test_mean3_mean(cm, c);
			double sa = test_mean3_se(gm, c), sb = test_mean3_se(cm, c), se = sqrt(sa * sa + sb * sb);
			printf("slab tau 2, %s ch %d: guided %.5f +- %.5f, classic %.5f +- %.5f (%+.2f SE)\n",
			       side ? "transmitted" : "reflected", c, a, sa, b, sb, (a - b) / se);
			CHECK(fabs(a - b) <= 3.5 * se, "%s ch %d: guided %g classic %g +- %g", side ? "bottom" : "top", c, a,
			      b, se);
		}
	printf("  interactions per walk: guided %.2f, classic %.2f\n", steps[0] / n, steps[1] / n);
	object_free(&o);
}

/* Dwivedi's nu0 by the fit against the root of 1 = alpha nu/2 ln((nu + 1)/(nu - 1)). */
static void check_dwivedi_nu(void)
{
	const double alphas[] = {0.2, 0.5, 0.8, 0.95, 0.99, 0.999};
	for (size_t i = 0; i < sizeof alphas / sizeof alphas[0]; i++) {
		double a = alphas[i], lo = 1.0 + 1e-15, hi = 1e6;
		for (int it = 0; it < 200; it++) { /* f(nu) = alpha nu/2 ln(...) - 1 decreases in nu */
			double mid = 0.5 * (lo + hi);
			if (0.5 * a * mid * log((mid + 1.0) / (mid - 1.0)) > 1.0)
				lo = mid;
			else
				hi = mid;
		}
		double fit = sss_walk_dwivedi_nu(a), exact = 0.5 * (lo + hi);
		printf("Dwivedi nu0(%.3f): fit %.5f, root %.5f\n", a, fit, exact);
		CHECK(fabs(fit / exact - 1.0) < 0.01, "nu0(%g): fit %g, root %g", a, fit, exact);
	}
	CHECK(sss_walk_dwivedi_nu(0.0) == 1.0 && isinf(sss_walk_dwivedi_nu(1.0)), "nu0 at 0 and 1");
}

/* Without absorption every walk leaves: grey, each weight is exactly 1; RGB, 1 in expectation. */
static void check_energy(const char *name, object *o, vec3 entry, vec3 ng, const double sigma_s[3], double g,
			 double eta)
{
	sss_walk_medium m = {{sigma_s[0], sigma_s[1], sigma_s[2]}, {0, 0, 0}, g, eta};
	bool grey = sigma_s[0] == sigma_s[1] && sigma_s[1] == sigma_s[2];
	rng r;
	rng_seed(&r, 13, 3);
	stat3 st = {0};
	long n = test_scaled(50000), refl = 0;
	for (long i = 0; i < n; i++) {
		/* refracted from a cosine-distributed incident direction */
		double u1 = rng_double(&r), u2 = rng_double(&r), st_ = sqrt(u1) / eta, ct = sqrt(1.0 - st_ * st_);
		vec3 b1, b2;
		v3_basis(ng, &b1, &b2);
		vec3 w = v3_add(v3_scale(ng, (float)-ct), v3_add(v3_scale(b1, (float)(st_ * cos(2 * PI * u2))),
								    v3_scale(b2, (float)(st_ * sin(2 * PI * u2)))));
		sss_walk_result res = sss_walk(&m, &o->pr, entry, ng, 0.0f, w, &r, SSS_WALK_MAX_STEPS);
		if (grey && res.status == SSS_WALK_EXITED)
			CHECK(fabsf(res.weight.x - 1.0f) < 1e-4f, "%s: grey weight %g", name, res.weight.x);
		refl += res.reflections;
		stat_add(&st, &res, true);
	}
	for (int c = 0; c < 3; c++) {
		double got = test_mean3_mean(&st.m, c), se = test_mean3_se(&st.m, c);
		printf("energy %s ch %d: %.5f +- %.5f\n", name, c, got, se);
		CHECK(fabs(got - 1.0) <= 3.0 * se + 1e-6, "%s ch %d: %g +- %g, want 1", name, c, got, se);
	}
	printf("  %ld walks, %.1f interactions, %.2f internal reflections each; lost %ld, step limit %ld\n", st.m.n,
	       (double)st.steps / st.m.n, (double)refl / st.m.n, st.count[SSS_WALK_LOST], st.count[SSS_WALK_STEP_LIMIT]);
	CHECK(st.count[SSS_WALK_EXITED] == st.m.n, "%s: %ld of %ld exited (lost %ld, limit %ld)", name,
	      st.count[SSS_WALK_EXITED], st.m.n, st.count[SSS_WALK_LOST], st.count[SSS_WALK_STEP_LIMIT]);
}

/* A pure absorber transmits e^{-sigma_a L / cos} along a straight line through a slab. */
static void check_beer_lambert(void)
{
	const double thick = 1.5, sa[3] = {0.2, 0.7, 1.5}, cos_i = 0.6;
	object o;
	object_box(&o, v3(-50, -50, (float)-thick), v3(50, 50, 0));
	sss_walk_medium m = {{0, 0, 0}, {sa[0], sa[1], sa[2]}, 0.0, 1.0};
	vec3 w = v3((float)sqrt(1.0 - cos_i * cos_i), 0.0f, (float)-cos_i);
	rng r;
	rng_seed(&r, 17, 4);
	stat3 st = {0};
	long n = test_scaled(100000);
	for (long i = 0; i < n; i++) {
		sss_walk_result res = sss_walk(&m, &o.pr, v3(0, 0, 0), v3(0, 0, 1), 0.0f, w, &r, SSS_WALK_MAX_STEPS);
		bool bottom = res.status == SSS_WALK_EXITED && res.p.z == (float)-thick;
		if (res.status == SSS_WALK_EXITED)
			CHECK(bottom && v3_length(v3_sub(res.dir, w)) < 1e-5f, "exit at z %g, dir %g %g %g", res.p.z,
			      res.dir.x, res.dir.y, res.dir.z);
		stat_add(&st, &res, bottom);
	}
	for (int c = 0; c < 3; c++) {
		double want = exp(-sa[c] * thick / cos_i), got = test_mean3_mean(&st.m, c), se = test_mean3_se(&st.m, c);
		printf("Beer-Lambert ch %d: %.5f +- %.5f, exp(-sigma_a L / cos) %.5f\n", c, got, se, want);
		CHECK(fabs(got - want) <= 3.0 * se, "ch %d: %g +- %g, want %g", c, got, se, want);
	}
	object_free(&o);
}

/* The bound on steps and the lost walks are statuses, counted by the caller. */
static void check_failures(void)
{
	object o;
	object_box(&o, v3(-5, -5, -5), v3(5, 5, 5));
	sss_walk_medium m = {{10, 10, 10}, {0, 0, 0}, 0.0, 1.4};
	rng r;
	rng_seed(&r, 19, 5);
	long limit = 0;
	for (int i = 0; i < 1000; i++) {
		sss_walk_result res = sss_walk(&m, &o.pr, v3(0, 0, 5), v3(0, 0, 1), 0.0f, v3(0, 0, -1), &r, 5);
		CHECK(res.steps <= 5 && (res.status == SSS_WALK_EXITED || res.status == SSS_WALK_STEP_LIMIT),
		      "steps %d, status %d", res.steps, res.status);
		if (res.status == SSS_WALK_STEP_LIMIT) {
			limit++;
			CHECK(res.steps == 5 && res.weight.x == 0.0f, "step limit with %d steps, weight %g", res.steps,
			      res.weight.x);
		}
	}
	printf("step bound 5 in a 100 mean-free-path box: %ld of 1000 walks reported STEP_LIMIT\n", limit);
	CHECK(limit > 500, "only %ld walks reached the bound", limit);
	sss_walk_result res = sss_walk(&m, &o.pr, v3(0, 0, 5), v3(0, 0, 1), 0.0f, v3(NAN, 0, -1), &r, 5);
	CHECK(res.status == SSS_WALK_BAD_INPUT && res.weight.x == 0.0f, "NaN direction: status %d", res.status);
	res = sss_walk(&m, &o.pr, v3(0, 0, 5), v3(0, 0, 1), 0.0f, v3(0, 0, -1), &r, 0);
	CHECK(res.status == SSS_WALK_BAD_INPUT, "max_steps 0: status %d", res.status);
	object_free(&o);

	/* an open mesh: the walk below a plane finds no surface and says so */
	CHECK(prim_plane(v3(0, 0, 1), 0.0f, v3(-1, -1, -1), v3(1, 1, 1), &o.m), "prim_plane");
	object_init(&o);
	long lost = 0;
	for (int i = 0; i < 100; i++) {
		res = sss_walk(&m, &o.pr, v3(0, 0, 0), v3(0, 0, 1), 0.0f, v3(0, 0, -1), &r, SSS_WALK_MAX_STEPS);
		lost += res.status == SSS_WALK_LOST;
		CHECK(res.status == SSS_WALK_LOST || res.status == SSS_WALK_EXITED, "open mesh: status %d", res.status);
		CHECK(v3_is_finite(res.weight), "non-finite weight");
	}
	CHECK(lost > 50, "open mesh: only %ld of 100 walks lost", lost);
	object_free(&o);

	/* albedo 0 and 1 exactly, eta 1 and 3, extreme coefficients: finite weights */
	object_box(&o, v3(-1, -1, -1), v3(1, 1, 1));
	const double coef[] = {0.0, 1e-6, 1.0, 1e4};
	for (int a = 0; a < 4; a++)
		for (int b = 0; b < 4; b++)
			for (int e = 0; e < 2; e++) {
				sss_walk_medium mm = {{coef[a], coef[b], 0}, {coef[b], 0, coef[a]}, 0.3, e ? 3.0 : 1.0};
				for (int i = 0; i < 20; i++) {
					res = sss_walk(&mm, &o.pr, v3(0, 0, 1), v3(0, 0, 1), 0.0f, v3(0.6f, 0, -0.8f), &r,
						       SSS_WALK_MAX_STEPS);
					CHECK(v3_is_finite(res.weight) && v3_min_comp(res.weight) >= 0.0f,
					      "coef %g %g eta %d: weight %g %g %g", coef[a], coef[b], e, res.weight.x,
					      res.weight.y, res.weight.z);
				}
			}
	object_free(&o);
}

/* auto's light factor weighs the far side's light by the diffusion slab's T / R (sss/medium.h):
 * a sheet L mm thick of skin1, the wax block's default and marble, entered at normal incidence
 * through the medium's own boundary (the walk's Fresnel), its light leaving through the far face
 * (T) and the lit one (R). The slab's T / R of the channel auto uses (the largest, red in all
 * three) must be within a factor 1.6 of the walk's; e^{-L/l_d}, the rule before, is printed beside
 * (wax's is 8 to 12 times the walk's). */
static void check_auto_slab(void)
{
	const char *names[] = {"skin1", "wax", "marble"};
	const double etas[] = {1.4, 1.45, 1.5}, Ls[] = {3.0, 6.0};
	for (int i = 0; i < 3; i++) {
		sss_medium_spec spec = {0};
		if (i == 1) {
			spec.albedo = v3(0.95f, 0.78f, 0.45f), spec.radius_mm = v3(2.0f, 1.2f, 0.6f);
			spec.has = SSS_HAS_ALBEDO | SSS_HAS_RADIUS;
		} else {
			spec.preset = names[i];
		}
		sss_medium md;
		sss_medium_derive(&spec, etas[i], &md);
		sss_auto_slab sl;
		sss_walk_medium m;
		CHECK(sss_auto_slab_make(&sl, md.sigma_s_per_mm, md.sigma_a_per_mm, etas[i]) &&
			      sss_walk_medium_from_reduced(&m, md.sigma_s_per_mm, md.sigma_a_per_mm, 0.0, etas[i], 1.0),
		      "%s: the slab and the walk's medium", names[i]);
		for (int j = 0; j < 2; j++) {
			double L = Ls[j];
			object o;
			object_box(&o, v3(-200.0f, -200.0f, (float)-L), v3(200.0f, 200.0f, 0.0f));
			rng r;
			rng_seed(&r, 21, (uint64_t)(2 * i + j));
			test_mean3 t = {0}, rf = {0};
			/* not fewer than 40000 in a sanitizer build either: the wax's 6 mm transmission
			 * (0.005) needs them to stand 5 standard errors above 0 */
			long n = test_scaled(40000) < 40000 ? 40000 : test_scaled(40000);
			for (long k = 0; k < n; k++) {
				sss_walk_result res = sss_walk(&m, &o.pr, v3(0, 0, 0), v3(0, 0, 1), 0.0f, v3(0, 0, -1), &r,
							       SSS_WALK_MAX_STEPS);
				bool out = res.status == SSS_WALK_EXITED;
				bool top = out && res.p.z == 0.0f, bottom = out && res.p.z == (float)-L;
				double wt[3] = {bottom ? res.weight.x : 0.0, bottom ? res.weight.y : 0.0, bottom ? res.weight.z : 0.0};
				double wr[3] = {top ? res.weight.x : 0.0, top ? res.weight.y : 0.0, top ? res.weight.z : 0.0};
				test_mean3_add(&t, wt);
				test_mean3_add(&rf, wr);
			}
			double tm, rm;
			sss_auto_slab_tr(&sl, 0, L, &tm, &rm);
			double wt = test_mean3_mean(&t, 0), wr = test_mean3_mean(&rf, 0);
			double ratio = (tm / rm) / (wt / wr), old = exp(-L / md.ld_mm[0]) / (wt / wr);
			printf("auto slab %s %.0f mm (red): walk T %.4f +- %.4f, R %.4f; slab T %.4f, R %.4f; T/R slab / walk "
			       "%.2f, e^-m / walk %.2f\n",
			       names[i], L, wt, test_mean3_se(&t, 0), wr, tm, rm, ratio, old);
			CHECK(wt > 5.0 * test_mean3_se(&t, 0), "%s %g mm: the walk's transmission is not resolved", names[i], L);
			CHECK(ratio > 1.0 / 1.6 && ratio < 1.6, "%s %g mm: the slab's T/R is %.2f of the walk's", names[i], L,
			      ratio);
			object_free(&o);
		}
	}
}

/* A unit vector from the index i (deterministic, spread over the sphere). */
static vec3 test_unit_vector_of(long i)
{
	double z = 1.0 - 2.0 * fmod(0.6180339887 * (double)i, 1.0), phi = 2.0 * PI * fmod(0.7548776662 * (double)i, 1.0);
	double s = sqrt(fmax(0.0, 1.0 - z * z));
	return v3((float)(s * cos(phi)), (float)(s * sin(phi)), (float)z);
}

/* A probe whose nearest surface lies: always the cap (no surface anywhere), for check_skip. */
static float liar_nearest(const void *ctx, vec3 p, float cap)
{
	(void)ctx, (void)p;
	return cap;
}

static bool same_walk(const sss_walk_result *a, const sss_walk_result *b)
{
	return a->status == b->status && a->steps == b->steps && a->reflections == b->reflections &&
	       a->reentries == b->reentries && memcmp(&a->p, &b->p, sizeof a->p) == 0 &&
	       memcmp(&a->weight, &b->weight, sizeof a->weight) == 0 && a->prim == b->prim;
}

/* Skipping casts inside a ball free of surface (README.md, "Skipping casts") changes no walk: a
 * dense, bright medium (hundreds of interactions a walk, most of them far from the surface) in
 * o walks the same with the nearest-surface query and without it, the same random numbers giving
 * the same exits, weights and steps bit for bit, while most casts are skipped; sss_walk_set_skip
 * (false) asks no query. A probe that claims there is no surface near makes the walks differ: the
 * comparison can fail. */
static void check_skip(const char *name, object *o, vec3 entry, vec3 ng)
{
	sss_walk_medium m = {{200, 150, 100}, {0.2, 0.5, 1.0}, 0.3, false, 1.3};
	sss_probe plain = o->pr, liar = o->pr;
	plain.nearest = NULL, liar.nearest = liar_nearest;
	long n = test_scaled(2000), differ = 0, lied = 0, steps = 0, skipped = 0, queries = 0, off_queries = 0, exited = 0;
	for (long i = 0; i < n; i++) {
		rng r0, r1, r2, r3;
		rng_seed(&r0, 77, (uint64_t)i), rng_seed(&r1, 77, (uint64_t)i), rng_seed(&r2, 77, (uint64_t)i);
		rng_seed(&r3, 77, (uint64_t)i);
		vec3 w = v3_normalize(v3_add(v3_neg(ng), v3_scale(test_unit_vector_of(i), 0.5f)));
		sss_walk_set_run(false); /* a run samples its steps otherwise: the same walks, bit for bit, without */
		sss_walk_result a = sss_walk(&m, &o->pr, entry, ng, 0.0f, w, &r0, SSS_WALK_MAX_STEPS);
		sss_walk_result b = sss_walk(&m, &plain, entry, ng, 0.0f, w, &r1, SSS_WALK_MAX_STEPS);
		sss_walk_result c = sss_walk(&m, &liar, entry, ng, 0.0f, w, &r2, SSS_WALK_MAX_STEPS);
		sss_walk_set_skip(false);
		sss_walk_result d = sss_walk(&m, &o->pr, entry, ng, 0.0f, w, &r3, SSS_WALK_MAX_STEPS);
		sss_walk_set_skip(true);
		sss_walk_set_run(true);
		differ += !same_walk(&a, &b) || !same_walk(&d, &b);
		lied += !same_walk(&c, &b);
		steps += a.steps, skipped += a.skipped, queries += a.queries, off_queries += d.queries + b.queries;
		exited += a.status == SSS_WALK_EXITED;
		CHECK(b.skipped == 0 && d.skipped == 0, "%s walk %ld: skipped casts without the query", name, i);
	}
	printf("skip %s: %ld walks, %.1f interactions, %.3f of them without a cast, %.2f queries a walk; %ld differ, "
	       "%ld with a lying probe\n",
	       name, n, (double)steps / n, (double)skipped / steps, (double)queries / n, differ, lied);
	CHECK(differ == 0, "%s: %ld of %ld walks differ with the skip", name, differ, n);
	CHECK(skipped > steps / 2 && off_queries == 0 && exited > n / 4, "%s: %ld of %ld casts skipped, %ld exited", name,
	      skipped, steps, exited);
	CHECK(lied > n / 10, "%s: a lying probe changed only %ld of %ld walks", name, lied, n);
}

int main(void)
{
	check_basics();
	check_exp();
	check_closure();

	const double grey[3] = {0.8, 0.8, 0.8}, ones[3] = {1, 1, 1};
	check_semi_infinite("grey 0.8", grey, ones);
	const double rgb_albedo[3] = {0.99, 0.8, 0.3}, rgb_sigma[3] = {1.0, 2.0, 0.5};
	check_semi_infinite("rgb", rgb_albedo, rgb_sigma);
	check_dwivedi_nu();
	check_guided_vs_classic();
	check_runs();
	check_thin_slab();
	check_auto_slab();

	object box, sphere;
	object_box(&box, v3(-1, -1, -1), v3(1, 1, 1));
	const double s_grey[3] = {3, 3, 3}, s_rgb[3] = {1, 3, 6};
	check_energy("box grey g 0.7 eta 1.4", &box, v3(0.2f, -0.3f, 1.0f), v3(0, 0, 1), s_grey, 0.7, 1.4);
	check_energy("box rgb g 0 eta 1.4", &box, v3(0.2f, -0.3f, 1.0f), v3(0, 0, 1), s_rgb, 0.0, 1.4);
	check_skip("box", &box, v3(0.2f, -0.3f, 1.0f), v3(0, 0, 1));
	object_free(&box);
	CHECK(prim_sphere(v3(0, 0, 0), 1.0f, 48, &sphere.m), "prim_sphere");
	object_init(&sphere);
	/* the entry at a vertex-free point of the tessellated sphere: the first triangle's centroid */
	const uint32_t *ix = sphere.m.indices + 3 * 100;
	vec3 a = sphere.m.positions[ix[0]], b = sphere.m.positions[ix[1]], c = sphere.m.positions[ix[2]];
	vec3 centroid = v3_scale(v3_add(a, v3_add(b, c)), 1.0f / 3.0f);
	vec3 n = v3_normalize(v3_cross(v3_sub(b, a), v3_sub(c, a)));
	if (v3_dot(n, centroid) < 0.0f)
		n = v3_neg(n);
	check_energy("sphere rgb g -0.3 eta 1.3", &sphere, centroid, n, s_rgb, -0.3, 1.3);
	check_skip("sphere", &sphere, centroid, n);
	object_free(&sphere);

	check_beer_lambert();
	check_failures();
	return check_done("test_walk");
}
