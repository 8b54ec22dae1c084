/* test_trig: trig_atan2 against libm's atan2 at the signed zeros, on the axes and diagonals, at
 * the edges of its sixteenths, at extreme magnitudes and ratios, and at 10^6 random points of every
 * quadrant: within 1e-15 radians, the same sign, and (for circle tracing's float angles) the same
 * float everywhere the test looks. */
#include "base/rng.h"
#include "base/trig.h"
#include "check.h"

static long compared, float_differs;
static double worst;

static void compare(double y, double x)
{
	double want = atan2(y, x), got = trig_atan2(y, x);
	double err = fabs(got - want);
	compared++;
	if (err > worst)
		worst = err;
	CHECK(err <= 1e-15, "atan2(%.17g, %.17g) = %.17g, trig_atan2 %.17g", y, x, want, got);
	CHECK(signbit(got) == signbit(want), "atan2(%.17g, %.17g) = %.17g, trig_atan2 %.17g", y, x, want, got);
	float_differs += (float)got != (float)want;
}

int main(void)
{
	/* Signed zeros, axes and diagonals, in every quadrant. */
	const double s[] = {0.0, -0.0, 1.0, -1.0, 0x1p-1074, -0x1p-1074, 1e300, -1e300};
	for (int i = 0; i < 8; i++)
		for (int j = 0; j < 8; j++)
			compare(s[i], s[j]);
	/* Each sixteenth's edges and midpoints (t = (k +- 1/2) / 16 and k / 16), a hair either side,
	 * swapped and signed. */
	for (int k = 0; k <= 32; k++) {
		double t = k / 32.0;
		for (int d = -2; d <= 2; d++) {
			double tt = nextafter(t, d < 0 ? 0.0 : 2.0);
			double v[2] = {t, d == 0 ? t : tt};
			for (int q = 0; q < 4; q++) {
				double sx = q & 1 ? -1.0 : 1.0, sy = q & 2 ? -1.0 : 1.0;
				compare(sy * v[d & 1], sx * 1.0);
				compare(sy * 1.0, sx * v[d & 1]);
			}
		}
	}
	/* Extreme ratios and magnitudes. */
	const double m[] = {0x1p-1074, 1e-300, 1e-200, 1e-30, 1e-8, 0.5, 1.0, 3.0, 1e8, 1e30, 1e200, 1e300, 0x1.fffffffffffffp1023};
	for (int i = 0; i < 13; i++)
		for (int j = 0; j < 13; j++)
			for (int q = 0; q < 4; q++)
				compare(q & 2 ? -m[i] : m[i], q & 1 ? -m[j] : m[j]);
	/* Random points: uniform angles at log-uniform radii, and uniform coordinates. */
	rng g;
	rng_seed(&g, 7u, 11u);
	for (long i = 0; i < 500000; i++) {
		double phi = (2.0 * rng_float(&g) - 1.0) * M_PI, r = pow(10.0, 40.0 * rng_float(&g) - 20.0);
		compare(r * sin(phi), r * cos(phi));
		compare(2.0 * rng_float(&g) - 1.0, 2.0 * rng_float(&g) - 1.0);
	}
	printf("test_trig: %ld points, largest difference from atan2 %.3g rad, float differs at %ld\n", compared,
	       worst, float_differs);
	CHECK(float_differs == 0, "%ld of %ld points round to another float than atan2's", float_differs, compared);
	return check_done("test_trig");
}
