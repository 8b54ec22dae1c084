/* test_sampling: the warps and piecewise-constant distributions draw from the densities they state
 * (chi-square), those densities integrate to one, and the power heuristic has its textbook values. */
#include "chi2.h"
#include "render/sampling.h"

static bool s_cosine(void *ctx, rng *g, vec3 *d)
{
	(void)ctx;
	*d = render_cosine_hemisphere(v2(rng_float(g), rng_float(g)));
	return true;
}
static double p_cosine(void *ctx, vec3 d)
{
	(void)ctx;
	return render_cosine_hemisphere_pdf(d.z);
}
static bool s_sphere(void *ctx, rng *g, vec3 *d)
{
	(void)ctx;
	*d = render_uniform_sphere(v2(rng_float(g), rng_float(g)));
	return true;
}
static double p_sphere(void *ctx, vec3 d)
{
	(void)ctx;
	(void)d;
	return RENDER_UNIFORM_SPHERE_PDF;
}
static bool s_cone(void *ctx, rng *g, vec3 *d)
{
	float c = *(float *)ctx;
	*d = render_uniform_cone(v2(rng_float(g), rng_float(g)), 1.0f - c * c);
	return true;
}
static double p_cone(void *ctx, vec3 d)
{
	float c = *(float *)ctx;
	return d.z >= c ? render_uniform_cone_pdf(1.0f - c * c) : 0.0;
}

static void test_disk_and_triangle(long n)
{
	enum { NR = 10, NA = 20, NB = 10 };
	double obs[NR * NA] = {0}, ex[NR * NA];
	rng g;
	rng_seed(&g, 11, 3);
	for (long i = 0; i < n; i++) {
		vec2 p = render_concentric_disk(v2(rng_float(&g), rng_float(&g)));
		double r2 = p.x * p.x + p.y * p.y, a = atan2(p.y, p.x) + M_PI;
		CHECK(r2 <= 1.0 + 1e-6, "disk point outside the disk: r^2 = %g", r2);
		int ir = (int)(r2 * NR), ia = (int)(a / (2 * M_PI) * NA);
		ir = ir >= NR ? NR - 1 : ir;
		ia = ia >= NA ? NA - 1 : ia;
		obs[ir * NA + ia] += 1;
	}
	for (int i = 0; i < NR * NA; i++)
		ex[i] = (double)n / (NR * NA); /* uniform area: equal bins of r^2 and angle */
	chi2_counts("concentric disk", obs, ex, NR * NA);

	/* Uniform on a triangle: b0 has density 2 (1 - b0), b1 / (1 - b0) is uniform given b0. */
	double tobs[NB * NB] = {0}, tex[NB * NB];
	for (long i = 0; i < n; i++) {
		vec2 b = render_uniform_triangle(v2(rng_float(&g), rng_float(&g)));
		CHECK(b.x >= 0 && b.y >= 0 && b.x + b.y <= 1.0f + 1e-6f, "barycentrics (%g %g) outside", b.x,
		      b.y);
		int i0 = (int)(b.x * NB), i1 = (int)(b.y / (1.0 - b.x) * NB);
		i0 = i0 >= NB ? NB - 1 : i0;
		i1 = i1 >= NB ? NB - 1 : i1 < 0 ? 0 : i1;
		tobs[i0 * NB + i1] += 1;
	}
	for (int i0 = 0; i0 < NB; i0++)
		for (int i1 = 0; i1 < NB; i1++) {
			double lo = (double)i0 / NB, hi = (double)(i0 + 1) / NB;
			tex[i0 * NB + i1] = n * ((1 - lo) * (1 - lo) - (1 - hi) * (1 - hi)) / NB;
		}
	chi2_counts("uniform triangle", tobs, tex, NB * NB);
}

static void test_distributions(long n)
{
	const float f[8] = {1, 0, 3, 0.5f, 0, 0, 2, 7};
	render_distrib1d d;
	CHECK(render_distrib1d_init(&d, f, 8), "distrib1d init");
	CHECK_NEAR(d.integral, 13.5 / 8, 1e-6);
	double obs[8] = {0}, ex[8], pdf_int = 0;
	rng g;
	rng_seed(&g, 5, 9);
	for (long i = 0; i < n; i++) {
		float pdf;
		size_t cell;
		float x = render_distrib1d_sample(&d, rng_float(&g), &pdf, &cell);
		CHECK(x >= 0.0f && x < 1.0f && (size_t)(x * 8) == cell, "x %g in cell %zu", x, cell);
		CHECK(fabsf(pdf - f[cell] / (float)d.integral) < 1e-5f, "pdf %g vs %g", pdf,
		      f[cell] / d.integral);
		obs[cell] += 1;
	}
	for (int i = 0; i < 8; i++) {
		ex[i] = n * f[i] / 13.5;
		pdf_int += f[i] / d.integral / 8;
		CHECK_NEAR(render_distrib1d_discrete_prob(&d, (size_t)i), f[i] / 13.5, 1e-6);
	}
	CHECK_NEAR(pdf_int, 1.0, 1e-6);
	chi2_counts("distrib1d", obs, ex, 8);
	render_distrib1d_free(&d);

	/* 2D: a 6 x 4 table; cells drawn in proportion to their value, pdf per unit area. */
	float t[24];
	double sum = 0;
	for (int i = 0; i < 24; i++)
		sum += t[i] = (float)((i * 7) % 5);
	render_distrib2d d2;
	CHECK(render_distrib2d_init(&d2, t, 6, 4), "distrib2d init");
	double o2[24] = {0}, e2[24], integral = 0;
	for (long i = 0; i < n; i++) {
		float pdf;
		vec2 uv = render_distrib2d_sample(&d2, v2(rng_float(&g), rng_float(&g)), &pdf);
		int c = (int)(uv.y * 4) * 6 + (int)(uv.x * 6);
		CHECK(fabsf(pdf - render_distrib2d_pdf(&d2, uv)) < 1e-4f * pdf, "pdf %g vs %g at (%g %g)",
		      pdf, render_distrib2d_pdf(&d2, uv), uv.x, uv.y);
		o2[c] += 1;
	}
	for (int i = 0; i < 24; i++) {
		e2[i] = n * t[i] / sum;
		integral += render_distrib2d_pdf(&d2, v2((i % 6 + 0.5f) / 6, (i / 6 + 0.5f) / 4)) / 24;
	}
	CHECK_NEAR(integral, 1.0, 1e-5);
	chi2_counts("distrib2d", o2, e2, 24);
	render_distrib2d_free(&d2);

	/* All zero: uniform. */
	const float z[4] = {0, 0, 0, 0};
	CHECK(render_distrib1d_init(&d, z, 4), "zero distrib init");
	float pdf;
	render_distrib1d_sample(&d, 0.6f, &pdf, NULL);
	CHECK_NEAR(pdf, 1.0, 1e-6);
	render_distrib1d_free(&d);
}

/* The cells at the ends of a 1D distribution: u = 0 and the largest float below 1 land in the
 * first and last cell with weight (find_cell asserts its answer is a cell), empty cells are skipped. */
static void test_distrib1d_edges(void)
{
	const float below_one = nextafterf(1.0f, 0.0f);
	float one[1] = {2.0f}, four[4] = {1, 1, 1, 1}, middle[4] = {0, 1, 0, 0};
	render_distrib1d d;
	size_t cell;
	float pdf;
	CHECK(render_distrib1d_init(&d, one, 1), "one cell");
	float x = render_distrib1d_sample(&d, below_one, &pdf, &cell);
	CHECK(cell == 0 && x < 1.0f && pdf == 1.0f, "one cell: cell %zu, x %.9g, pdf %g", cell, x, pdf);
	render_distrib1d_free(&d);
	CHECK(render_distrib1d_init(&d, four, 4), "four cells");
	render_distrib1d_sample(&d, 0.0f, NULL, &cell);
	CHECK(cell == 0, "u = 0: cell %zu", cell);
	x = render_distrib1d_sample(&d, below_one, NULL, &cell);
	CHECK(cell == 3 && x < 1.0f, "u below 1: cell %zu, x %.9g", cell, x);
	render_distrib1d_free(&d);
	CHECK(render_distrib1d_init(&d, middle, 4), "one cell of four with weight");
	float ends[2] = {0.0f, below_one};
	for (int k = 0; k < 2; k++) {
		float prob;
		size_t i = render_distrib1d_sample_discrete(&d, ends[k], &prob);
		CHECK(i == 1 && prob == 1.0f, "u = %.9g: cell %zu (prob %g), expected the one with weight", ends[k], i,
		      prob);
	}
	render_distrib1d_free(&d);
}

int main(void)
{
	long n = test_samples(1000000);
	vec3 z = v3(0, 0, 1);
	chi2_sphere("cosine hemisphere", s_cosine, p_cosine, NULL, z, -1.0, 16, 32, 8, n, 1);
	chi2_sphere("uniform sphere", s_sphere, p_sphere, NULL, z, -1.0, 16, 32, 4, n, 2);
	float cmax = 0.8f;
	chi2_sphere("uniform cone", s_cone, p_cone, &cmax, z, cmax, 10, 32, 4, n, 3);
	test_disk_and_triangle(n);
	test_distributions(n);
	test_distrib1d_edges();

	CHECK_NEAR(render_power_heuristic(1.0f, 1.0f), 0.5, 1e-7);
	CHECK_NEAR(render_power_heuristic(3.0f, 1.0f), 0.9, 1e-7);
	CHECK_NEAR(render_power_heuristic(0.0f, 0.0f), 0.0, 0);
	return check_done("test_sampling");
}
