/* mean3.h - the running mean and standard error of an RGB Monte Carlo estimate, shared by the
 * sss comparator tests (test_disk, test_walk). */
#ifndef CIRCE_TESTS_SSS_MEAN3_H
#define CIRCE_TESTS_SSS_MEAN3_H

#include <math.h>

typedef struct test_mean3 {
	double s[3], s2[3];
	long n;
} test_mean3;

static inline void test_mean3_add(test_mean3 *m, const double v[3])
{
	m->n++;
	for (int c = 0; c < 3; c++)
		m->s[c] += v[c], m->s2[c] += v[c] * v[c];
}
static inline double test_mean3_mean(const test_mean3 *m, int c) { return m->s[c] / m->n; }
static inline double test_mean3_se(const test_mean3 *m, int c)
{
	double mean = test_mean3_mean(m, c);
	return sqrt(fmax(0.0, m->s2[c] / m->n - mean * mean) / (m->n - 1));
}

#endif
