/* walk_exp.h - the volume walk's exponential (issue 21): e^x inline, for the free paths'
 * transmittances and densities (six a step for three channels and two strategies). libm's exp
 * and its wrapper were 15 % of a marble slab's render under `--sss volume`. Relative error
 * below SSS_WALK_EXP_REL_ERR over (-708, 708) (test_walk measures it against libm); outside
 * that range, and for NaN, libm's own. Deterministic: plain products and
 * sums (no fused multiply-add under -ffp-contract=off), the same bits on every machine. */
#ifndef CIRCE_SSS_WALK_EXP_H
#define CIRCE_SSS_WALK_EXP_H

#include <math.h>
#include <stdint.h>
#include <string.h>

/* The bound test_walk checks (measured there: at most 2.6e-15 over 2 million points, at large
 * |x| where n ln2_lo rounds; the polynomial's truncation, r^6 / 720 at |r| = ln 2 / 64, is
 * 2.2e-15). */
#define SSS_WALK_EXP_REL_ERR 4e-15

/* e^x. x = (32 m + j) ln 2 / 32 + r with n = 32 m + j = round(32 x / ln 2), j in [0, 32), so
 * |r| <= ln 2 / 64 (ln 2 in two parts, fdlibm's: n ln2_hi / 32 is exact for |n| < 2^21);
 * e^x = 2^m 2^(j/32) e^r, 2^(j/32) from the table (correctly rounded: 50-digit decimal
 * arithmetic), e^r by its Taylor series to r^5 (Estrin's scheme), 2^m into the exponent bits. */
static inline double sss_walk_exp(double x)
{
	static const double two_j32[32] = {
		0x1.0000000000000p+0, 0x1.059b0d3158574p+0, 0x1.0b5586cf9890fp+0, 0x1.11301d0125b51p+0,
		0x1.172b83c7d517bp+0, 0x1.1d4873168b9aap+0, 0x1.2387a6e756238p+0, 0x1.29e9df51fdee1p+0,
		0x1.306fe0a31b715p+0, 0x1.371a7373aa9cbp+0, 0x1.3dea64c123422p+0, 0x1.44e086061892dp+0,
		0x1.4bfdad5362a27p+0, 0x1.5342b569d4f82p+0, 0x1.5ab07dd485429p+0, 0x1.6247eb03a5585p+0,
		0x1.6a09e667f3bcdp+0, 0x1.71f75e8ec5f74p+0, 0x1.7a11473eb0187p+0, 0x1.82589994cce13p+0,
		0x1.8ace5422aa0dbp+0, 0x1.93737b0cdc5e5p+0, 0x1.9c49182a3f090p+0, 0x1.a5503b23e255dp+0,
		0x1.ae89f995ad3adp+0, 0x1.b7f76f2fb5e47p+0, 0x1.c199bdd85529cp+0, 0x1.cb720dcef9069p+0,
		0x1.d5818dcfba487p+0, 0x1.dfc97337b9b5fp+0, 0x1.ea4afa2a490dap+0, 0x1.f50765b6e4540p+0,
	};
	if (!(x > -708.0 && x < 708.0))
		return exp(x);
	const double ln2_hi = 6.93147180369123816490e-01 / 32, ln2_lo = 1.90821492927058770002e-10 / 32;
	const double shift = 6755399441055744.0; /* 1.5 * 2^52: adding it rounds to an integer */
	double nd = x * 46.166241308446828 + shift; /* 32 / ln 2 */
	nd -= shift;
	double r = (x - nd * ln2_hi) - nd * ln2_lo;
	int64_t n = (int64_t)nd, j = n & 31, m = (n - j) / 32; /* m = floor(n / 32), exactly */
	double r2 = r * r;
	double p = (1.0 + r) + r2 * ((0.5 + r * (1.0 / 6)) + r2 * (1.0 / 24 + r * (1.0 / 120)));
	uint64_t bits;
	memcpy(&bits, &two_j32[j], sizeof bits);
	bits += (uint64_t)m << 52; /* times 2^m: m >= -1022 here, 2^(j/32) 2^m stays normal */
	double scale;
	memcpy(&scale, &bits, sizeof scale);
	return p * scale;
}

#endif
