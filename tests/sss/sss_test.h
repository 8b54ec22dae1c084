/* sss_test.h - numerical helpers shared by the sss test programs: quadrature, the chi-square
 * p-value, and the sample-count scale (CIRCE_TEST_SCALE). */
#ifndef CIRCE_TESTS_SSS_TEST_H
#define CIRCE_TESTS_SSS_TEST_H

#include "stats.h"

#include <math.h>
#include <stdlib.h>

#define PI 3.14159265358979323846

/* Sample counts are multiplied by CIRCE_TEST_SCALE (clamped to [0.01, 100]); its default is 1,
 * or 0.25 in a sanitizer build (GCC's and Clang's address sanitizer macros). */
#if defined(__SANITIZE_ADDRESS__)
#define SSS_TEST_DEFAULT_SCALE 0.25
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define SSS_TEST_DEFAULT_SCALE 0.25
#endif
#endif
#ifndef SSS_TEST_DEFAULT_SCALE
#define SSS_TEST_DEFAULT_SCALE 1.0
#endif

static inline long test_scaled(long n)
{
	const char *s = getenv("CIRCE_TEST_SCALE");
	double k = s ? atof(s) : SSS_TEST_DEFAULT_SCALE;
	if (!(k >= 0.01))
		k = 0.01;
	if (k > 100.0)
		k = 100.0;
	return (long)(n * k);
}

/* Integral of f over [a, b] by Simpson's rule on panels that double in length from a
 * (the first of length (b - a) 2^-40): resolves features near a at every scale. */
static inline double integrate_log(double (*f)(double, const void *), const void *ctx, double a, double b)
{
	double s = 0.0, lo = a, len = (b - a) * 0x1p-40;
	while (lo < b) {
		double hi = fmin(b, lo + len), h = (hi - lo) / 64.0;
		double part = f(lo, ctx) + f(hi, ctx);
		for (int i = 1; i < 64; i++)
			part += (i % 2 ? 4.0 : 2.0) * f(lo + i * h, ctx);
		s += part * h / 3.0;
		lo = hi;
		len = hi - a;
	}
	return s;
}

/* Gauss-Legendre nodes and weights of order n on [-1, 1], by Newton's method on P_n. */
static inline void gauss_legendre(int n, double *x, double *w)
{
	for (int i = 0; i < n; i++) {
		double z = cos(PI * (i + 0.75) / (n + 0.5)), dp = 1.0;
		for (int it = 0; it < 100; it++) {
			double p0 = 1.0, p1 = z;
			for (int k = 2; k <= n; k++) {
				double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
				p0 = p1, p1 = p2;
			}
			dp = n * (z * p1 - p0) / (z * z - 1.0);
			double dz = p1 / dp;
			z -= dz;
			if (fabs(dz) < 1e-15)
				break;
		}
		x[i] = z;
		w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
	}
}


/* P(chi-square with dof degrees of freedom >= x). */
static inline double chi2_pvalue(double x, int dof)
{
	return stats_gamma_q(0.5 * dof, 0.5 * x);
}

/* The per-test level that keeps the family-wise level at alpha over m tests (Sidak). */
static inline double sidak(double alpha, int m)
{
	return 1.0 - pow(1.0 - alpha, 1.0 / m);
}

#endif
