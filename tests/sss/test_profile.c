/* test_profile: every profile integrates to its albedo, its pdf to 1 and its CDF to the pdf's
 * integral, truncation holds the stated tail, sampling passes chi-square, and the medium links
 * (Fresnel moment, Jensen's R_d, physical <-> artist) agree with their sources. */
#include "base/rng.h"
#include "check.h"
#include "sss/profile.h"
#include "sss_test.h"

#include <stdio.h>
#include <string.h>

/* Chi-square tests in this program, for the Sidak correction of the family level 0.01. */
#define CHI2_TESTS 16
#define CHI2_BINS  100

static const char *kind_name[] = {"gaussian", "sum_of_gaussians", "burley", "dipole"};

/* 2 pi r R(r); burley's R is infinite at r = 0 but 2 pi r R has a finite limit there. */
static double f_R(double r, const void *c)
{
	r = fmax(r, 1e-300);
	return 2.0 * PI * r * sss_channel_eval(c, r);
}
static double f_pdf(double r, const void *c)
{
	return sss_channel_pdf(c, r);
}
static double f_mix_pdf(double r, const void *p)
{
	return sss_profile_pdf(p, r);
}

/* The same channel without truncation: the paper's formula on [0, inf). */
static sss_channel untruncated(const sss_channel *c)
{
	sss_channel u = *c;
	u.r_max_mm = 1e9 * c->r_max_mm;
	u.norm = 1.0;
	return u;
}

/* Integrals of one channel: R to A, pdf to 1, the CDF to the pdf's integral, the tail. */
static void check_normalisation(const sss_channel *c, const char *what)
{
	double rm = c->r_max_mm;
	double a = integrate_log(f_R, c, 0.0, rm);
	CHECK(fabs(a - c->albedo) <= 1e-6, "%s: integral of R 2 pi r dr = %.9f, albedo %.9f", what, a,
	      c->albedo);
	double one = integrate_log(f_pdf, c, 0.0, rm);
	CHECK(fabs(one - 1.0) <= 1e-6, "%s: integral of pdf = %.9f", what, one);
	for (int k = 1; k < 10; k++) {
		double r = rm * k * k / 100.0;
		double cdf = sss_channel_cdf(c, r), q = integrate_log(f_pdf, c, 0.0, r);
		CHECK(fabs(cdf - q) <= 1e-7, "%s: CDF(%g) = %.9f, integral of pdf %.9f", what, r, cdf, q);
	}
	/* The paper's formula integrates to A over [0, inf), and holds 1 - tail of it below r_max. */
	sss_channel u = untruncated(c);
	double all = integrate_log(f_R, &u, 0.0, u.r_max_mm), below = integrate_log(f_R, &u, 0.0, rm);
	double tail_ok = c->albedo > 0.0 ? fabs(below / all - (1.0 - SSS_PROFILE_TAIL)) : 0.0;
	CHECK(fabs(all - c->albedo) <= 2e-6, "%s: untruncated integral %.9f, albedo %.9f", what, all,
	      c->albedo);
	CHECK(tail_ok <= 1e-6, "%s: untruncated mass below r_max %.9f of %.9f (want 1 - %g)", what, below,
	      all, SSS_PROFILE_TAIL);
	CHECK(fabs(c->norm - (1.0 - SSS_PROFILE_TAIL)) <= 1e-9, "%s: norm %.12f", what, c->norm);
}

/* The single-component samplers (gaussian, dipole) invert the CDF: CDF(sample(u)) = u to the
 * resolution of a double (the mixtures pick a component first, so this does not hold for them). */
static void check_inversion(const sss_channel *c, const char *what)
{
	if (c->kind != SSS_PROFILE_GAUSSIAN && c->kind != SSS_PROFILE_DIPOLE)
		return;
	double worst = 0.0, at = 0.0;
	for (int i = 1; i < 1000; i++) {
		double u = i / 1000.0, e = fabs(sss_channel_cdf(c, sss_channel_sample(c, u)) - u);
		if (e > worst)
			worst = e, at = u;
	}
	CHECK(worst <= 1e-12, "%s: |CDF(sample(u)) - u| = %g at u = %g", what, worst, at);
}

/* Bin edges at the CDF's quantiles k/CHI2_BINS, found by bisection on cdf (independent of the
 * samplers' own inversion). */
static void quantile_edges(double (*cdf)(const void *, double), const void *ctx, double r_max, double *edge)
{
	edge[0] = 0.0;
	edge[CHI2_BINS] = r_max;
	for (int k = 1; k < CHI2_BINS; k++) {
		double lo = 0.0, hi = r_max, t = (double)k / CHI2_BINS;
		for (int i = 0; i < 100; i++) {
			double mid = 0.5 * (lo + hi);
			if (cdf(ctx, mid) < t)
				lo = mid;
			else
				hi = mid;
		}
		edge[k] = 0.5 * (lo + hi);
	}
}

static int bin_of(const double *edge, double r)
{
	int lo = 0, hi = CHI2_BINS;
	while (hi - lo > 1) {
		int mid = (lo + hi) / 2;
		if (r < edge[mid])
			hi = mid;
		else
			lo = mid;
	}
	return lo;
}

typedef double (*sampler_fn)(const void *ctx, rng *g);

/* Pearson's chi-square of n samples against the CDF, with equiprobable bins; expected counts
 * from CDF differences at the edges actually found. */
static void check_chi2(sampler_fn sample, double (*cdf)(const void *, double), const void *ctx, double r_max,
		       const char *what, uint64_t seed)
{
	double edge[CHI2_BINS + 1];
	long count[CHI2_BINS] = {0}, n = test_scaled(1000000), bad = 0;
	quantile_edges(cdf, ctx, r_max, edge);
	rng g;
	rng_seed(&g, seed, 17);
	for (long i = 0; i < n; i++) {
		double r = sample(ctx, &g);
		if (!(r > 0.0 && r <= r_max)) {
			bad++;
			continue;
		}
		count[bin_of(edge, r)]++;
	}
	CHECK(bad == 0, "%s: %ld samples outside (0, r_max = %g]", what, bad, r_max);
	double chi2 = 0.0;
	for (int k = 0; k < CHI2_BINS; k++) {
		double e = n * (cdf(ctx, edge[k + 1]) - cdf(ctx, edge[k]));
		chi2 += (count[k] - e) * (count[k] - e) / e;
	}
	double p = chi2_pvalue(chi2, CHI2_BINS - 1), level = sidak(0.01, CHI2_TESTS);
	CHECK(p > level, "%s: chi-square %.1f over %d dof, p = %.3g < %.3g (%ld samples)", what, chi2,
	      CHI2_BINS - 1, p, level, n);
	printf("  %-44s chi2 %7.1f  p %.3f\n", what, chi2, p);
}

static double ch_sample(const void *c, rng *g)
{
	return sss_channel_sample(c, rng_double(g));
}
static double ch_cdf(const void *c, double r)
{
	return sss_channel_cdf(c, r);
}
static double mix_sample(const void *p, rng *g)
{
	double uc = rng_double(g);
	return sss_profile_sample(p, uc, rng_double(g));
}
static double mix_cdf(const void *p, double r)
{
	const sss_profile *pr = p;
	double s = 0.0;
	for (int c = 0; c < 3; c++)
		s += pr->q[c] * sss_channel_cdf(&pr->ch[c], r);
	return s;
}

/* Jensen et al. 2001's polynomial for the internal diffuse Fresnel reflectance (section 2.3,
 * after Egan & Hilgeman): an approximation of 2 FM1(1/eta). */
static double jensen_fdr(double eta)
{
	return -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
}

/* Brute-force first Fresnel moment: midpoint rule, 10^6 intervals. */
static double fm1_reference(double eta)
{
	const int n = 1000000;
	double s = 0.0;
	for (int i = 0; i < n; i++) {
		double mu = (i + 0.5) / n, sin2 = (1.0 - mu * mu) / (eta * eta), f = 1.0;
		if (sin2 < 1.0) {
			double mt = sqrt(1.0 - sin2);
			double rs = (mu - eta * mt) / (mu + eta * mt), rp = (eta * mu - mt) / (eta * mu + mt);
			f = 0.5 * (rs * rs + rp * rp);
		}
		s += f * mu;
	}
	return s / n;
}

static void check_medium_links(void)
{
	CHECK_NEAR(sss_fresnel_moment1(1.0), 0.0, 1e-15);
	const double etas[] = {1.0 / 1.5, 1.0 / 1.3, 1.2, 1.3, 1.5, 2.0};
	for (int i = 0; i < 6; i++) {
		double got = sss_fresnel_moment1(etas[i]), ref = fm1_reference(etas[i]);
		CHECK(fabs(got - ref) <= 2e-7, "FM1(%g) = %.9f, brute force %.9f", etas[i], got, ref);
	}
	for (double eta = 1.1; eta < 1.61; eta += 0.1) {
		double f_dr = 2.0 * sss_fresnel_moment1(1.0 / eta);
		CHECK(fabs(f_dr - jensen_fdr(eta)) <= 0.01, "F_dr(%g) = %.4f, Jensen's polynomial %.4f", eta,
		      f_dr, jensen_fdr(eta));
	}
	/* Jensen et al. 2001's R_d for skin1 (their measured sigma_s', sigma_a, eta 1.3), written
	 * here with their polynomial F_dr: ours uses the exact Fresnel moment, so they differ a little. */
	const double ss[3] = {0.74, 0.88, 1.01}, sa[3] = {0.032, 0.17, 0.48};
	for (int c = 0; c < 3; c++) {
		double ap = ss[c] / (ss[c] + sa[c]), s = sqrt(3.0 * (1.0 - ap));
		double f = jensen_fdr(1.3), a_f = (1.0 + f) / (1.0 - f);
		double rd = 0.5 * ap * (1.0 + exp(-4.0 / 3.0 * a_f * s)) * exp(-s);
		double a = sss_dipole_albedo(ap, 1.3);
		CHECK(fabs(a - rd) <= 2e-3, "skin1 channel %d: R_d %.4f, with Jensen's F_dr %.4f", c, a, rd);
	}
	CHECK_NEAR(sss_dipole_albedo(0.0, 1.4), 0.0, 0.0);
	CHECK_NEAR(sss_dipole_albedo(1.0, 1.4), 1.0, 1e-15);
	for (double a = 0.0; a <= 1.0; a += 0.125) {
		double ap = sss_dipole_alpha_prime(a, 1.4);
		CHECK(fabs(sss_dipole_albedo(ap, 1.4) - a) <= 1e-10, "R_d(alpha'(%g)) = %.12f", a,
		      sss_dipole_albedo(ap, 1.4));
	}
	/* Physical and artist forms meet: (sigma_s', sigma_a) and (R_d, l_d = 1/sigma_tr) build the
	 * same channel for every kind. */
	for (int k = 0; k < 4; k++) {
		sss_channel p, a;
		CHECK(sss_channel_from_physical(&p, k, 1, 0.88, 0.17, 1.3), "physical %s", kind_name[k]);
		double alb = sss_dipole_albedo(0.88 / 1.05, 1.3), ld = 1.0 / sqrt(3.0 * 0.17 * 1.05);
		CHECK(sss_channel_from_artist(&a, k, 1, alb, ld, 1.3), "artist %s", kind_name[k]);
		CHECK(fabs(p.r_max_mm - a.r_max_mm) <= 1e-8 * p.r_max_mm && fabs(p.albedo - a.albedo) <= 1e-9,
		      "%s: physical r_max %.12g A %.12g, artist r_max %.12g A %.12g", kind_name[k],
		      p.r_max_mm, p.albedo, a.r_max_mm, a.albedo);
	}
	/* Bad input is refused. */
	sss_channel c;
	CHECK(!sss_channel_from_physical(&c, SSS_PROFILE_BURLEY, 0, 0.0, 0.0, 1.3), "sigma_t = 0 accepted");
	CHECK(!sss_channel_from_physical(&c, SSS_PROFILE_BURLEY, 0, -1.0, 0.5, 1.3),
	      "negative sigma accepted");
	CHECK(!sss_channel_from_physical(&c, SSS_PROFILE_BURLEY, 0, NAN, 0.5, 1.3), "NaN sigma accepted");
	CHECK(!sss_channel_from_physical(&c, SSS_PROFILE_BURLEY, 0, 1.0, 0.0, 1.3),
	      "sigma_a = 0 (l_d infinite) accepted");
	CHECK(sss_channel_from_physical(&c, SSS_PROFILE_DIPOLE, 0, 1.0, 0.0, 1.3) &&
		  fabs(c.albedo - 1.0) < 1e-12,
	      "dipole without absorption: albedo %.15f", c.albedo);
	CHECK(!sss_channel_from_artist(&c, SSS_PROFILE_BURLEY, 0, 1.5, 1.0, 1.3), "albedo 1.5 accepted");
	CHECK(!sss_channel_from_artist(&c, SSS_PROFILE_BURLEY, 0, 0.5, 0.0, 1.3), "radius 0 accepted");
	CHECK(!sss_channel_from_artist(&c, SSS_PROFILE_BURLEY, 0, 0.5, 1.0, 0.0), "eta 0 accepted");
	CHECK(!sss_channel_from_artist(&c, SSS_PROFILE_BURLEY, 3, 0.5, 1.0, 1.3), "channel 3 accepted");
}

/* No NaN, no Inf, samples in (0, r_max], at the edges of the parameter space. */
static void check_extremes(void)
{
	const double albedo[] = {0.0, 1.0, 0.5}, ld[] = {1e-9, 1e6, 1.0}, eta[] = {1.0, 1.4, 3.0};
	rng g;
	rng_seed(&g, 5, 5);
	for (int k = 0; k < 4; k++)
		for (int ia = 0; ia < 3; ia++)
			for (int im = 0; im < 3; im++)
				for (int ie = 0; ie < 3; ie++) {
					sss_channel c;
					bool ok =
					    sss_channel_from_artist(&c, k, 0, albedo[ia], ld[im], eta[ie]);
					CHECK(ok && isfinite(c.r_max_mm) && c.r_max_mm > 0.0 &&
						  isfinite(c.albedo),
					      "%s A %g l_d %g eta %g: built %d r_max %g A %g", kind_name[k],
					      albedo[ia], ld[im], eta[ie], ok, c.r_max_mm, c.albedo);
					if (!ok)
						continue;
					int bad = 0;
					for (int i = 0; i < 200; i++) {
						double u = i == 0   ? 0.0
							   : i == 1 ? 1.0 - 0x1p-53
								    : rng_double(&g);
						double r = sss_channel_sample(&c, u);
						double R = sss_channel_eval(&c, r),
						       p = sss_channel_pdf(&c, r);
						if (!(r > 0.0 && r <= c.r_max_mm) || !isfinite(R) ||
						    !isfinite(p) || !(p > 0.0))
							bad++;
					}
					CHECK(bad == 0, "%s A %g l_d %g eta %g: %d bad samples", kind_name[k],
					      albedo[ia], ld[im], eta[ie], bad);
				}
}

int main(void)
{
	check_medium_links();
	check_extremes();

	/* Channels to test: skin1 (physical) green, a wax-like artist channel, both albedo ends. */
	struct {
		bool physical;
		int channel;
		double a, b; /* sigma_s', sigma_a or albedo, l_d */
		double eta;
	} cfg[] = {
	    {true, 1, 0.88, 0.17, 1.3},
	    {false, 0, 0.95, 2.0, 1.45},
	    {false, 2, 1.0, 0.6, 1.0},
	};
	int chi = 0;
	for (int k = 0; k < 4; k++)
		for (int i = 0; i < 3; i++) {
			sss_channel c;
			bool ok = cfg[i].physical ? sss_channel_from_physical(&c, k, cfg[i].channel, cfg[i].a,
									      cfg[i].b, cfg[i].eta)
						  : sss_channel_from_artist(&c, k, cfg[i].channel, cfg[i].a,
									    cfg[i].b, cfg[i].eta);
			char what[96];
			snprintf(what, sizeof what, "%s %s (%g, %g, eta %g)", kind_name[k],
				 cfg[i].physical ? "physical" : "artist", cfg[i].a, cfg[i].b, cfg[i].eta);
			CHECK(ok, "%s: not built", what);
			if (!ok)
				continue;
			check_normalisation(&c, what);
			check_inversion(&c, what);
			check_chi2(ch_sample, ch_cdf, &c, c.r_max_mm, what, 100 + chi++);
		}

	/* RGB profiles with different radii per channel: one-sample MIS over channels. */
	const double ss[3] = {0.74, 0.88, 1.01}, sa[3] = {0.032, 0.17, 0.48};
	const double wax_a[3] = {0.95, 0.78, 0.45}, wax_l[3] = {2.0, 1.2, 0.6};
	for (int k = 0; k < 4; k++) {
		sss_profile p;
		bool ok = k % 2 ? sss_profile_from_physical(&p, k, ss, sa, 1.3)
				: sss_profile_from_artist(&p, k, wax_a, wax_l, 1.45);
		CHECK(ok, "rgb %s not built", kind_name[k]);
		if (!ok)
			continue;
		char what[96];
		snprintf(what, sizeof what, "rgb %s (%s)", kind_name[k], k % 2 ? "skin1" : "wax");
		/* Piecewise between the channels' truncation radii, where the mixture pdf jumps. */
		double rm = sss_profile_r_max(&p), one = 0.0,
		       cut[4] = {0.0, p.ch[0].r_max_mm, p.ch[1].r_max_mm, p.ch[2].r_max_mm};
		for (int i = 1; i < 4; i++)
			for (int j = i; j > 1 && cut[j] < cut[j - 1]; j--) {
				double t = cut[j];
				cut[j] = cut[j - 1], cut[j - 1] = t;
			}
		for (int i = 0; i < 3; i++)
			one += cut[i + 1] > cut[i] ? integrate_log(f_mix_pdf, &p, cut[i], cut[i + 1]) : 0.0;
		CHECK(fabs(one - 1.0) <= 1e-6, "%s: mixture pdf integrates to %.9f", what, one);
		double sum_a = p.ch[0].albedo + p.ch[1].albedo + p.ch[2].albedo;
		for (int i = 1; i < 200; i++) {
			double r = rm * i / 200.0, pdf = sss_profile_pdf(&p, r);
			vec3 ratio = sss_profile_ratio(&p, r), R = sss_profile_eval(&p, r);
			for (int c = 0; c < 3; c++) {
				double w = v3_get(ratio, c), expect = 2.0 * PI * r * v3_get(R, c) / pdf;
				CHECK(w <= sum_a * (1.0 + 1e-6) &&
					  (pdf == 0.0 || fabs(w - expect) <= 1e-5 * (1.0 + expect)),
				      "%s r %g channel %d: ratio %g, 2 pi r R / pdf %g, bound %g", what, r, c,
				      w, expect, sum_a);
			}
		}
		check_chi2(mix_sample, mix_cdf, &p, rm, what, 100 + chi++);
	}
	CHECK(chi == CHI2_TESTS, "%d chi-square tests, the Sidak correction assumes %d", chi, CHI2_TESTS);
	return check_done("test_profile");
}
