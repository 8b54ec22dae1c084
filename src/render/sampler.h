/* sampler.h - where a camera sample's random numbers come from: Owen-scrambled Sobol points
 * (the default) or independent PCG32 numbers (rng.h, the renderer's first sampler).
 *
 * Sobol (RENDER_SAMPLER_SOBOL): every request names a dimension (a label: the integrator's
 * RENDER_DIM_* offsets within the block of the path's current vertex, render_sampler_vertex), and
 * the request is answered by the first one or two dimensions of the Sobol sequence at a shuffled
 * index, Owen-scrambled. The dimension's seeds are a hash of (the pixel's key, the dimension): a
 * padded sampler (as pbrt-v4's PaddedSobolSampler and Cycles' Sobol-Burley), so each 1-D request
 * is stratified over a pixel's samples, each 2-D request's points are a (0,2)-sequence, and two
 * requests are independently scrambled and shuffled, hence uncorrelated with each other.
 *   - Sobol's dimension 0 is the van der Corput sequence (the bit reverse of the index), dimension
 *     1 the one of the primitive polynomial x + 1 with m_1 = 1, the first entry of Joe & Kuo's
 *     table (S. Joe and F. Y. Kuo 2008, "Constructing Sobol sequences with better two-dimensional
 *     projections", SIAM J. Sci. Comput. 30(5); new-joe-kuo-6.21201, d = 2): its generator is
 *     Pascal's triangle mod 2. Together they are a (0,2)-sequence in base 2.
 *   - The scramble is Burley's hash-based nested uniform scramble (B. Burley 2020, "Practical
 *     Hash-based Owen Scrambling", JCGT 9(4), sections 3-4): the bits reversed, a Laine-Karras
 *     style permutation (S. Laine and T. Karras 2011, "Stratified sampling for stochastic
 *     transparency") in which every bit is flipped by a function of the bits below it only, the
 *     bits reversed back. Each output bit depends on itself and the bits above it, so it is an
 *     Owen scramble: every elementary interval maps to one of the same size, and nets stay nets.
 *   - The index is shuffled by the same scramble (Burley 2020, section 4) with its own seed per
 *     dimension: it maps every aligned block of 2^m indices onto an aligned block of 2^m, and an
 *     aligned block of 2^m Sobol points is a (0,m,2)-net, so the first 2^m samples of a pixel are
 *     one for every m whatever the total. Nothing depends on the sample count: passes, time
 *     budgets and adaptive sampling may end a pixel anywhere.
 * A value depends only on (seed, pixel, dimension, sample index): images stay bit-identical for any
 * thread count, tiling, region and pass schedule.
 *
 * Unbounded consumers (media tracking, random walks) take an rng seeded from one dimension
 * (render_sampler_stream), as pbrt-v4 seeds its RNGs from a sampler value: the dimensions after
 * them stay aligned across samples.
 *
 * Random (RENDER_SAMPLER_RANDOM): every request takes the next numbers of one PCG32 stream per
 * sample (rng_for_sample), whatever its dimension; a 2-D request draws y before x, the order the
 * renderer drew them in before this sampler (GCC evaluates v2's arguments right to left), so it
 * renders the images of before bit for bit. */
#ifndef CIRCE_RENDER_SAMPLER_H
#define CIRCE_RENDER_SAMPLER_H

#include "base/rng.h"
#include "base/vec.h"

#include <stdbool.h>
#include <stdint.h>

typedef enum render_sampler_kind { RENDER_SAMPLER_SOBOL = 0, RENDER_SAMPLER_RANDOM } render_sampler_kind;

/* The camera's dimensions; a path's vertex k has RENDER_VERTEX_DIMS after them
 * (render_sampler_vertex), numbered by the integrator. */
enum { RENDER_DIM_PIXEL = 0, RENDER_DIM_LENS = 1, RENDER_CAMERA_DIMS = 2 };
#define RENDER_VERTEX_DIMS 32u

typedef struct render_sampler {
	render_sampler_kind kind;
	uint64_t key;	/* Sobol: the hash of (seed, pixel) */
	uint32_t index; /* the sample number */
	uint32_t base;	/* Sobol: the first dimension of the current block */
	rng g;		/* random: the sample's stream */
} render_sampler;

/* The sampler of sample `sample` of pixel (px, py). */
render_sampler render_sampler_make(render_sampler_kind kind, uint64_t seed, uint32_t px, uint32_t py,
				   uint32_t sample);
/* A random sampler drawing from g (tests and benchmarks that hold their own stream). */
static inline render_sampler render_sampler_of_rng(rng g)
{
	return (render_sampler){.kind = RENDER_SAMPLER_RANDOM, .g = g};
}
/* Whether a value depends only on its dimension (Sobol), not on what was drawn before (random):
 * a keyed sampler's number may be drawn early, or drawn and not used, without changing any other. */
static inline bool render_sampler_keyed(const render_sampler *s) { return s->kind != RENDER_SAMPLER_RANDOM; }
/* Parses "sobol" or "random"; false for anything else. */
bool render_sampler_from_name(const char *name, render_sampler_kind *kind);
const char *render_sampler_name(render_sampler_kind kind);

/* Dimensions dim of the following requests are counted from the block of vertex k. */
static inline void render_sampler_vertex(render_sampler *s, uint32_t k)
{
	s->base = RENDER_CAMERA_DIMS + k * RENDER_VERTEX_DIMS;
}

/* A number in [0, 1) (24 bits), a point in [0, 1)^2, a double in [0, 1) (53 bits: the Sobol
 * value's 32 and 21 hashed below them). */
float render_sampler_1d(render_sampler *s, uint32_t dim);
vec2 render_sampler_2d(render_sampler *s, uint32_t dim);
double render_sampler_1d_double(render_sampler *s, uint32_t dim);
/* An rng for a consumer of unbounded count: random: the sample's own stream; Sobol: *local,
 * seeded from dimension dim and the index. */
rng *render_sampler_stream(render_sampler *s, uint32_t dim, rng *local);

/* The pieces, for the tests. */
uint32_t render_sobol(uint32_t index, int dim); /* dim 0 or 1, the 32 bits of the point */
uint32_t render_owen_scramble(uint32_t x, uint32_t seed);
/* The 32-bit Sobol values of a request: dimension `dim` (absolute) of the sampler of key `key`
 * at sample `index`; out[0] and out[1] its two components. */
void render_sampler_bits(uint64_t key, uint32_t dim, uint32_t index, uint32_t out[2]);
/* The key of (seed, pixel) (render_sampler.key). */
uint64_t render_sampler_key(uint64_t seed, uint32_t px, uint32_t py);

#endif
