/* test_rng: PCG32 matches its reference output, per-sample streams are reproducible and
 * statistically independent of their neighbours, and the bounded draws are unbiased. */
#include "base/rng.h"
#include "check.h"

#include <stdlib.h>

/* Pearson correlation of n paired values. */
static double correlation(const double *a, const double *b, int n)
{
	double ma = 0, mb = 0;
	for (int i = 0; i < n; i++)
		ma += a[i], mb += b[i];
	ma /= n, mb /= n;
	double sab = 0, saa = 0, sbb = 0;
	for (int i = 0; i < n; i++) {
		sab += (a[i] - ma) * (b[i] - mb);
		saa += (a[i] - ma) * (a[i] - ma);
		sbb += (b[i] - mb) * (b[i] - mb);
	}
	return sab / sqrt(saa * sbb);
}

static void below_zero(void *g) { (void)rng_below(g, 0); }

int main(void)
{
	/* The reference pcg32 demo (pcg32-global-demo) seeded with (42, 54) prints these first six. */
	rng g;
	rng_seed(&g, 42u, 54u);
	const uint32_t expect[6] = {0xa15c02b7, 0x7b47f409, 0xba1d3330, 0x83d2f293, 0xbfa4784b, 0xcbed606e};
	for (int i = 0; i < 6; i++) {
		uint32_t v = rng_u32(&g);
		CHECK(v == expect[i], "draw %d: 0x%08x, expected 0x%08x", i, v, expect[i]);
	}

	/* Same inputs, same numbers; any input changed, different numbers. */
	rng a = rng_for_sample(7, 10, 20, 3), b = rng_for_sample(7, 10, 20, 3);
	for (int i = 0; i < 100; i++)
		CHECK(rng_u32(&a) == rng_u32(&b), "reproducible at draw %d", i);
	rng vary[4] = {rng_for_sample(8, 10, 20, 3), rng_for_sample(7, 11, 20, 3),
		       rng_for_sample(7, 10, 21, 3), rng_for_sample(7, 10, 20, 4)};
	rng base = rng_for_sample(7, 10, 20, 3);
	uint32_t b0 = rng_u32(&base);
	for (int k = 0; k < 4; k++)
		CHECK(rng_u32(&vary[k]) != b0, "input %d changes the stream", k);

	/* Neighbouring pixels and sample indices: the first draws of 100000 pairs are uncorrelated
	 * (|r| < 5/sqrt(n), five standard errors), and each marginal is uniform (chi-square, 64 bins). */
	enum { N = 100000, BINS = 64 };
	double *u0 = malloc(sizeof(double) * N), *ux = malloc(sizeof(double) * N),
	       *us = malloc(sizeof(double) * N), *u2 = malloc(sizeof(double) * N);
	int hist[BINS] = {0};
	for (int i = 0; i < N; i++) {
		uint32_t px = (uint32_t)(i % 317), py = (uint32_t)(i / 317), s = (uint32_t)(i % 5);
		rng r0 = rng_for_sample(1, px, py, s), rx = rng_for_sample(1, px + 1, py, s),
		    rs = rng_for_sample(1, px, py, s + 1);
		u0[i] = rng_double(&r0);
		u2[i] = rng_double(&r0);
		ux[i] = rng_double(&rx);
		us[i] = rng_double(&rs);
		hist[(int)(u0[i] * BINS)]++;
	}
	double bound = 5.0 / sqrt((double)N);
	double c1 = correlation(u0, ux, N), c2 = correlation(u0, us, N), c3 = correlation(u0, u2, N);
	CHECK(fabs(c1) < bound, "neighbour pixel correlation %g", c1);
	CHECK(fabs(c2) < bound, "neighbour sample correlation %g", c2);
	CHECK(fabs(c3) < bound, "successive draw correlation %g", c3);
	double chi2 = 0, e = (double)N / BINS;
	for (int k = 0; k < BINS; k++)
		chi2 += (hist[k] - e) * (hist[k] - e) / e;
	/* 63 degrees of freedom: the 0.999 quantile is 103.4. */
	CHECK(chi2 < 103.4, "uniformity chi-square %g over 63 dof", chi2);

	/* rng_below never reaches n and covers every value; rng_float stays in [0, 1). */
	int seen[7] = {0};
	for (int i = 0; i < 7000; i++) {
		uint32_t v = rng_below(&g, 7);
		CHECK(v < 7, "below(7) gave %u", v);
		if (v < 7)
			seen[v]++;
		float f = rng_float(&g);
		CHECK(f >= 0.0f && f < 1.0f, "float %g", f);
	}
	for (int k = 0; k < 7; k++)
		CHECK(seen[k] > 850 && seen[k] < 1150, "value %d seen %d times of 7000", k, seen[k]);
	/* The boundary of rng_below: n = 1 has the one value 0; n = 0 has none, an assert refuses it. */
	for (int i = 0; i < 100; i++)
		CHECK(rng_below(&g, 1) == 0, "below(1) gave a value other than 0");
#ifndef NDEBUG
	CHECK(check_aborts(below_zero, &g), "rng_below(g, 0) did not stop at its assert");
#endif
	free(u0), free(ux), free(us), free(u2);
	return check_done("test_rng");
}
