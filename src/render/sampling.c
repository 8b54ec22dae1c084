/* sampling.c - the warps and distributions of sampling.h. Cumulative sums are kept in double so a
 * large environment map's CDF stays monotone; searches are binary. */
#include "render/sampling.h"

#include "base/mem.h"

#include <assert.h>
#include <string.h>

vec2 render_concentric_disk(vec2 u)
{
	float ox = 2.0f * u.x - 1.0f, oy = 2.0f * u.y - 1.0f;
	if (ox == 0.0f && oy == 0.0f)
		return v2(0.0f, 0.0f);
	float r, theta;
	if (fabsf(ox) > fabsf(oy)) {
		r = ox;
		theta = 0.25f * RENDER_PI * (oy / ox);
	} else {
		r = oy;
		theta = 0.5f * RENDER_PI - 0.25f * RENDER_PI * (ox / oy);
	}
	return v2(r * cosf(theta), r * sinf(theta));
}

vec3 render_cosine_hemisphere(vec2 u)
{
	vec2 d = render_concentric_disk(u);
	float z = sqrtf(fmaxf(0.0f, 1.0f - d.x * d.x - d.y * d.y));
	return v3(d.x, d.y, z);
}

vec3 render_uniform_sphere(vec2 u)
{
	float z = 1.0f - 2.0f * u.x;
	float r = sqrtf(fmaxf(0.0f, 1.0f - z * z));
	float phi = 2.0f * RENDER_PI * u.y;
	return v3(r * cosf(phi), r * sinf(phi), z);
}

/* 1 - cos of the half angle, from its sin^2. */
static float cone_one_minus_cos(float sin2_max)
{
	return sin2_max / (1.0f + sqrtf(fmaxf(0.0f, 1.0f - sin2_max)));
}

vec3 render_uniform_cone(vec2 u, float sin2_max)
{
	float w = u.x * cone_one_minus_cos(sin2_max); /* 1 - cos theta */
	float r = sqrtf(fmaxf(0.0f, w * (2.0f - w)));
	float phi = 2.0f * RENDER_PI * u.y;
	return v3(r * cosf(phi), r * sinf(phi), 1.0f - w);
}

float render_uniform_cone_pdf(float sin2_max)
{
	return 1.0f / (2.0f * RENDER_PI * cone_one_minus_cos(sin2_max));
}

vec2 render_uniform_triangle(vec2 u)
{
	float b0, b1;
	if (u.y > u.x) {
		b0 = 0.5f * u.x;
		b1 = u.y - b0;
	} else {
		b1 = 0.5f * u.y;
		b0 = u.x - b1;
	}
	return v2(b0, b1);
}

bool render_distrib1d_init(render_distrib1d *d, const float *func, size_t n)
{
	memset(d, 0, sizeof *d);
	if (n == 0)
		return false;
	d->func = mem_alloc(n, sizeof *d->func);
	d->cdf = mem_alloc(n + 1, sizeof *d->cdf);
	if (!d->func || !d->cdf) {
		render_distrib1d_free(d);
		return false;
	}
	d->n = n;
	d->cdf[0] = 0.0;
	for (size_t i = 0; i < n; i++) {
		float f = func[i];
		d->func[i] = (isfinite(f) && f > 0.0f) ? f : 0.0f;
		d->cdf[i + 1] = d->cdf[i] + (double)d->func[i] / (double)n;
	}
	d->integral = d->cdf[n];
	for (size_t i = 1; i <= n; i++)
		d->cdf[i] = d->integral > 0.0 ? d->cdf[i] / d->integral : (double)i / (double)n;
	d->cdf[n] = 1.0;
	return true;
}

void render_distrib1d_free(render_distrib1d *d)
{
	mem_free(d->func);
	mem_free(d->cdf);
	memset(d, 0, sizeof *d);
}

/* The cell i with cdf[i] <= u < cdf[i+1], skipping empty cells. */
static size_t find_cell(const render_distrib1d *d, double u)
{
	assert(d->n > 0); /* render_distrib1d_init refuses n = 0 */
	size_t lo = 0, hi = d->n; /* invariant: cdf[lo] <= u, answer in [lo, hi) */
	while (hi - lo > 1) {
		size_t mid = lo + (hi - lo) / 2;
		if (d->cdf[mid] <= u)
			lo = mid;
		else
			hi = mid;
	}
	assert(lo < d->n);
	return lo;
}

static float cell_density(const render_distrib1d *d, size_t i)
{
	return d->integral > 0.0 ? (float)(d->func[i] / d->integral) : 1.0f;
}

float render_distrib1d_sample(const render_distrib1d *d, float u, float *pdf, size_t *cell)
{
	size_t i = find_cell(d, u);
	double width = d->cdf[i + 1] - d->cdf[i];
	double du = width > 0.0 ? ((double)u - d->cdf[i]) / width : 0.5;
	double x = ((double)i + du) / (double)d->n;
	float xf = (float)x;
	if (xf >= 1.0f) /* rounding to float must not leave [0,1) */
		xf = nextafterf(1.0f, 0.0f);
	if (pdf)
		*pdf = cell_density(d, i);
	if (cell)
		*cell = i;
	return xf;
}

size_t render_distrib1d_sample_discrete(const render_distrib1d *d, float u, float *prob)
{
	size_t i = find_cell(d, u);
	if (prob)
		*prob = (float)(d->cdf[i + 1] - d->cdf[i]);
	return i;
}

float render_distrib1d_discrete_prob(const render_distrib1d *d, size_t i)
{
	return i < d->n ? (float)(d->cdf[i + 1] - d->cdf[i]) : 0.0f;
}

bool render_distrib2d_init(render_distrib2d *d, const float *func, size_t nu, size_t nv)
{
	memset(d, 0, sizeof *d);
	d->rows = mem_calloc(nv, sizeof *d->rows);
	float *row_integrals = mem_alloc(nv, sizeof *row_integrals);
	bool ok = d->rows && row_integrals && nu > 0 && nv > 0;
	if (ok) {
		d->nu = nu;
		d->nv = nv;
		for (size_t v = 0; v < nv && ok; v++) {
			ok = render_distrib1d_init(&d->rows[v], func + v * nu, nu);
			row_integrals[v] = ok ? (float)d->rows[v].integral : 0.0f;
		}
		ok = ok && render_distrib1d_init(&d->marginal, row_integrals, nv);
	}
	mem_free(row_integrals);
	if (!ok)
		render_distrib2d_free(d);
	return ok;
}

void render_distrib2d_free(render_distrib2d *d)
{
	if (d->rows)
		for (size_t v = 0; v < d->nv; v++)
			render_distrib1d_free(&d->rows[v]);
	mem_free(d->rows);
	render_distrib1d_free(&d->marginal);
	memset(d, 0, sizeof *d);
}

vec2 render_distrib2d_sample(const render_distrib2d *d, vec2 u, float *pdf)
{
	float pv, pu;
	size_t row;
	float y = render_distrib1d_sample(&d->marginal, u.y, &pv, &row);
	assert(row < d->nv);
	float x = render_distrib1d_sample(&d->rows[row], u.x, &pu, NULL);
	*pdf = pv * pu;
	return v2(x, y);
}

float render_distrib2d_pdf(const render_distrib2d *d, vec2 uv)
{
	size_t iu = (size_t)fminf(fmaxf(uv.x * (float)d->nu, 0.0f), (float)(d->nu - 1));
	size_t iv = (size_t)fminf(fmaxf(uv.y * (float)d->nv, 0.0f), (float)(d->nv - 1));
	return cell_density(&d->marginal, iv) * cell_density(&d->rows[iv], iu);
}
