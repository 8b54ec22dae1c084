/* chi2.h - chi-square goodness-of-fit tests for the render tests: a sampler's histogram against
 * the integral of its claimed density over the same bins (after Jakob's Mitsuba tests), with bins
 * of low expectation pooled, and a Sidak-corrected significance so the whole suite's chance of a
 * false alarm stays at CHI2_SUITE_ALPHA. Sample counts scale with the environment variable
 * CIRCE_TEST_SCALE (default 1: 10^6 samples per test, about a second in all, sanitizers included;
 * smaller scales weaken the statistical tests and the integrator's may then fail by chance). */
#ifndef CIRCE_TESTS_RENDER_CHI2_H
#define CIRCE_TESTS_RENDER_CHI2_H

#include "base/mem.h"
#include "base/rng.h"
#include "base/vec.h"
#include "check.h"
#include "stats.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>

#define CHI2_SUITE_ALPHA 0.01
/* The number of chi-square tests in tests/render (test_sampling, test_bsdf, test_light, test_sobol). */
#define CHI2_SUITE_TESTS 27
/* A pooled bin must expect at least this many samples for the chi-square approximation. */
#define CHI2_MIN_EXPECTED 5.0

static inline double test_scale(void)
{
	const char *s = getenv("CIRCE_TEST_SCALE");
	return s && atof(s) > 0.0 ? atof(s) : 1.0;
}

static inline long test_samples(long n)
{
	long m = (long)(n * test_scale());
	return m < 1000 ? 1000 : m;
}


static inline double chi2_alpha(void)
{
	return 1.0 - pow(1.0 - CHI2_SUITE_ALPHA, 1.0 / CHI2_SUITE_TESTS);
}

static int chi2_cmp_expected(const void *a, const void *b)
{
	const double *x = a, *y = b;
	return (x[1] > y[1]) - (x[1] < y[1]);
}

/* Pearson's test of observed counts against expected counts (same total up to integration error):
 * pools the smallest bins until each expects CHI2_MIN_EXPECTED, CHECKs the p-value against the
 * Sidak-corrected alpha, and fails outright when a bin expecting nothing got samples. */
static inline double chi2_counts(const char *name, const double *obs, const double *expct, int n)
{
	double *pair = mem_alloc((size_t)n, 2 * sizeof(double));
	for (int i = 0; i < n; i++) {
		pair[2 * i] = obs[i];
		pair[2 * i + 1] = expct[i];
		CHECK(!(expct[i] <= 0.0 && obs[i] > 0.0), "%s: bin %d expects %g but has %g samples", name, i,
		      expct[i], obs[i]);
	}
	qsort(pair, (size_t)n, 2 * sizeof(double), chi2_cmp_expected);
	double stat = 0.0, po = 0.0, pe = 0.0;
	int bins = 0;
	for (int i = 0; i < n; i++) {
		po += pair[2 * i];
		pe += pair[2 * i + 1];
		if (pe >= CHI2_MIN_EXPECTED) {
			stat += (po - pe) * (po - pe) / pe;
			bins++;
			po = pe = 0.0;
		}
	}
	if (pe > 0.0 || po > 0.0) { /* the remainder joins the statistic as one more (small) bin */
		stat += pe > 0.0 ? (po - pe) * (po - pe) / fmax(pe, CHI2_MIN_EXPECTED) : po;
		bins++;
	}
	mem_free(pair);
	double p = bins > 1 ? stats_gamma_q(0.5 * (bins - 1), 0.5 * stat) : 1.0;
	CHECK(p > chi2_alpha(), "%s: chi2 = %g over %d bins, p = %g below alpha %g", name, stat, bins, p,
	      chi2_alpha());
	printf("  %-40s chi2 %10.2f  dof %4d  p %.4f\n", name, stat, bins - 1, p);
	return p;
}

/* A direction sampler and its density. sample returns false for a failed sample. */
typedef bool (*chi2_sample_fn)(void *ctx, rng *g, vec3 *dir);
typedef double (*chi2_pdf_fn)(void *ctx, vec3 dir);

/* Direction in the frame with +z = axis from (z, phi). */
static inline vec3 chi2_dir(vec3 axis, double z, double phi)
{
	vec3 b1, b2;
	v3_basis(axis, &b1, &b2);
	double r = sqrt(fmax(0.0, 1.0 - z * z));
	return v3_normalize(
	    v3_add(v3_add(v3_scale(b1, (float)(r * cos(phi))), v3_scale(b2, (float)(r * sin(phi)))),
		   v3_scale(axis, (float)z)));
}

/* Chi-square test on the sphere: nz bins of z = cos(angle to axis) over [zmin, 1] times nphi bins
 * of azimuth and one bin for [-1, zmin) (when zmin > -1), over the successful samples. Expected counts
 * integrate pdf by the midpoint rule on sub x sub cells per bin (solid angle dz dphi). Also CHECKs
 * that the density integrates over the sphere to the fraction of samples that succeeded. */
static inline void chi2_sphere(const char *name, chi2_sample_fn sample, chi2_pdf_fn pdf, void *ctx, vec3 axis,
			       double zmin, int nz, int nphi, int sub, long n, uint64_t seed)
{
	int nb = nz * nphi + 2;
	double *obs = mem_calloc((size_t)nb, sizeof *obs), *ex = mem_calloc((size_t)nb, sizeof *ex);
	vec3 b1, b2;
	v3_basis(axis, &b1, &b2);
	rng g;
	rng_seed(&g, seed, 7);
	long ok = 0;
	for (long i = 0; i < n; i++) {
		vec3 d;
		if (!sample(ctx, &g, &d)) {
			obs[nb - 1] += 1;
			continue;
		}
		ok++;
		double z = v3_dot(d, axis), phi = atan2(v3_dot(d, b2), v3_dot(d, b1));
		if (phi < 0)
			phi += 2 * M_PI;
		if (z < zmin) {
			obs[nb - 2] += 1;
			continue;
		}
		int iz = (int)((z - zmin) / (1.0 - zmin) * nz), ip = (int)(phi / (2 * M_PI) * nphi);
		iz = iz < 0 ? 0 : iz >= nz ? nz - 1 : iz;
		ip = ip < 0 ? 0 : ip >= nphi ? nphi - 1 : ip;
		obs[iz * nphi + ip] += 1;
	}
	double total = 0.0;
	double dz = (1.0 - zmin) / nz, dp = 2 * M_PI / nphi;
	for (int iz = 0; iz < nz; iz++)
		for (int ip = 0; ip < nphi; ip++) {
			double s = 0.0;
			for (int a = 0; a < sub; a++)
				for (int b = 0; b < sub; b++) {
					double z = zmin + dz * (iz + (a + 0.5) / sub);
					double phi = dp * (ip + (b + 0.5) / sub);
					s += pdf(ctx, chi2_dir(axis, z, phi));
				}
			s *= dz * dp / (sub * sub);
			ex[iz * nphi + ip] = s * n;
			total += s;
		}
	if (zmin > -1.0) {
		int oz = nz * sub, op = nphi * sub;
		double ddz = (zmin + 1.0) / oz, ddp = 2 * M_PI / op, s = 0.0;
		for (int a = 0; a < oz; a++)
			for (int b = 0; b < op; b++)
				s += pdf(ctx, chi2_dir(axis, -1.0 + ddz * (a + 0.5), ddp * (b + 0.5)));
		s *= ddz * ddp;
		ex[nb - 2] = s * n;
		total += s;
	}
	/* The histogram of the successful samples against the density conditioned on success; the
	 * failure mass is checked through the integral instead. */
	for (int i = 0; i < nb - 1; i++)
		ex[i] *= total > 0.0 ? (double)ok / ((double)n * total) : 0.0;
	double frac = (double)ok / (double)n;
	double tol = 2e-3 + 5.0 * sqrt(fmax(frac * (1.0 - frac), 1e-6) / (double)n);
	CHECK(fabs(total - frac) <= tol,
	      "%s: pdf integrates to %.5f but %.5f of the samples succeeded (tol %g)", name, total, frac,
	      tol);
	chi2_counts(name, obs, ex, nb - 1);
	mem_free(obs);
	mem_free(ex);
}

#endif
