/* stats.h - statistics shared by the test programs: the regularised incomplete gamma function
 * behind every chi-square p-value. */
#ifndef CIRCE_TESTS_STATS_H
#define CIRCE_TESTS_STATS_H

#include <math.h>

/* Regularised upper incomplete gamma Q(a, x) (Numerical Recipes 6.2: series below a + 1,
 * Lentz's continued fraction above). */
static inline double stats_gamma_q(double a, double x)
{
	if (x <= 0.0)
		return 1.0;
	double gln = lgamma(a);
	if (x < a + 1.0) {
		double ap = a, sum = 1.0 / a, del = sum;
		for (int n = 0; n < 10000; n++) {
			ap += 1.0;
			del *= x / ap;
			sum += del;
			if (fabs(del) < fabs(sum) * 1e-15)
				break;
		}
		return 1.0 - sum * exp(-x + a * log(x) - gln);
	}
	double b = x + 1.0 - a, c = 1.0 / 1e-300, d = 1.0 / b, h = d;
	for (int i = 1; i < 10000; i++) {
		double an = -i * (i - a);
		b += 2.0;
		d = an * d + b;
		if (fabs(d) < 1e-300)
			d = 1e-300;
		c = b + an / c;
		if (fabs(c) < 1e-300)
			c = 1e-300;
		d = 1.0 / d;
		double del = d * c;
		h *= del;
		if (fabs(del - 1.0) < 1e-15)
			break;
	}
	return exp(-x + a * log(x) - gln) * h;
}

#endif
