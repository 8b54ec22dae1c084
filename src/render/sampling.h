/* sampling.h - warps from the unit square to the domains the renderer samples (hemisphere, sphere,
 * cone, disk, triangle), piecewise-constant 1D/2D distributions (the environment map's importance
 * sampling, light selection by power) and the power heuristic of multiple importance sampling.
 * Every warp states its pdf in the measure of its domain; inputs u are uniform in [0,1). */
#ifndef CIRCE_RENDER_SAMPLING_H
#define CIRCE_RENDER_SAMPLING_H

#include "base/vec.h"

#include <stdbool.h>
#include <stddef.h>

#define RENDER_PI     3.14159265358979323846f
#define RENDER_INV_PI 0.31830988618379067154f

/* Shirley & Chiu 1997 concentric map to the unit disk; pdf 1/pi per unit area. */
vec2 render_concentric_disk(vec2 u);
/* Cosine-weighted direction about +z (Malley's method); pdf cos(theta)/pi per steradian. */
vec3 render_cosine_hemisphere(vec2 u);
static inline float render_cosine_hemisphere_pdf(float cos_theta)
{
	return cos_theta > 0.0f ? cos_theta * RENDER_INV_PI : 0.0f;
}
/* Uniform direction on the unit sphere; pdf 1/(4 pi). */
vec3 render_uniform_sphere(vec2 u);
#define RENDER_UNIFORM_SPHERE_PDF (0.25f * RENDER_INV_PI)
/* Uniform direction in the cone about +z whose half angle has sin^2 = sin2_max (in (0, 1]; the
 * cone is at most a hemisphere); pdf 1/(2 pi (1 - cos_max)). Given by sin^2 because a small cone
 * (a distant sphere light) has cos_max within a few float ulps of 1: 1 - cos is computed as
 * sin^2 / (1 + cos) and the sampled sin theta from 1 - cos theta, both without cancellation. */
vec3 render_uniform_cone(vec2 u, float sin2_max);
float render_uniform_cone_pdf(float sin2_max);
/* Uniform point on a triangle as barycentrics (b0, b1), b2 = 1 - b0 - b1 (Heitz 2019, "A
 * Low-Distortion Map Between Triangle and Square"); pdf 1/area. */
vec2 render_uniform_triangle(vec2 u);

/* Power heuristic with beta = 2 (Veach 1997, eq. 9.13) for one sample of each strategy. */
static inline float render_power_heuristic(float pdf_a, float pdf_b)
{
	float a = pdf_a * pdf_a, b = pdf_b * pdf_b;
	return a > 0.0f ? a / (a + b) : 0.0f;
}

/* A piecewise-constant density on [0,1) over n equal cells, proportional to func (>= 0).
 * When every value is zero the distribution is uniform (integral reports 0). Owns its arrays. */
typedef struct render_distrib1d {
	float *func; /* n values (copied, negatives/non-finite clamped to 0) */
	double *cdf; /* n + 1 values, cdf[0] = 0, cdf[n] = 1 */
	size_t n;
	double integral; /* sum of func / n */
} render_distrib1d;

/* False when memory runs out (d is then empty and safe to free). */
bool render_distrib1d_init(render_distrib1d *d, const float *func, size_t n);
void render_distrib1d_free(render_distrib1d *d);
/* Samples a continuous x in [0,1); *pdf is the density at x, *cell the cell of x. */
float render_distrib1d_sample(const render_distrib1d *d, float u, float *pdf, size_t *cell);
/* Samples a cell with probability func[i] / sum; *prob receives that probability. */
size_t render_distrib1d_sample_discrete(const render_distrib1d *d, float u, float *prob);
/* The probability of cell i under sample_discrete. */
float render_distrib1d_discrete_prob(const render_distrib1d *d, size_t i);

/* A piecewise-constant density on [0,1)^2 over nu x nv cells, func row-major (v rows of nu):
 * a marginal over rows times a conditional within each row (Pharr et al., PBRT 3rd ed. 13.6.7). */
typedef struct render_distrib2d {
	render_distrib1d *rows; /* nv conditionals */
	render_distrib1d marginal;
	size_t nu, nv;
} render_distrib2d;

bool render_distrib2d_init(render_distrib2d *d, const float *func, size_t nu, size_t nv);
void render_distrib2d_free(render_distrib2d *d);
/* A point in [0,1)^2 and its density per unit (u,v) area. */
vec2 render_distrib2d_sample(const render_distrib2d *d, vec2 u, float *pdf);
float render_distrib2d_pdf(const render_distrib2d *d, vec2 uv);

#endif
