/* sampler.c - the padded Owen-scrambled Sobol sampler and the random one (sampler.h). */
#include "render/sampler.h"

#include <string.h>

static inline uint32_t reverse_bits(uint32_t x)
{
	x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
	x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
	x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
	return __builtin_bswap32(x);
}

/* Burley 2020's Laine-Karras style permutation (his listing with the constants he found): the
 * addition and every x * even flip bit k by a function of bits < k only. */
static inline uint32_t lk_permute(uint32_t x, uint32_t seed)
{
	x += seed;
	x ^= x * 0x6c50b47cu;
	x ^= x * 0xb82f1e52u;
	x ^= x * 0xc7afe638u;
	x ^= x * 0x8d22f6e6u;
	return x;
}

uint32_t render_owen_scramble(uint32_t x, uint32_t seed) { return reverse_bits(lk_permute(reverse_bits(x), seed)); }

/* Dimension 1: column k of the generator is V_k = m_{k+1} 2^(31-k) with m_1 = 1 and, for x + 1,
 * m_k = 2 m_{k-1} xor m_{k-1} (Bratley & Fox 1988's recurrence), i.e. V_{k+1} = V_k xor V_k >> 1. */
static inline uint32_t sobol1(uint32_t i)
{
	uint32_t x = 0;
	for (uint32_t v = 0x80000000u; i; i >>= 1, v ^= v >> 1)
		if (i & 1u)
			x ^= v;
	return x;
}

uint32_t render_sobol(uint32_t index, int dim) { return dim == 0 ? reverse_bits(index) : sobol1(index); }

uint64_t render_sampler_key(uint64_t seed, uint32_t px, uint32_t py)
{
	uint64_t h = rng_mix64(seed ^ 0x5851f42d4c957f2dULL);
	return rng_mix64(h ^ (((uint64_t)px << 32) | py));
}

/* The seeds of dimension dim: 64 hashed bits (the key is a hash already: one mix of it and the
 * dimension times an odd constant, distinct for every dimension, is enough). */
static inline uint64_t dim_hash(uint64_t key, uint32_t dim)
{
	return rng_mix64(key ^ ((uint64_t)(dim + 1u) * 0x9e3779b97f4a7c15ULL));
}

/* A third 32-bit seed from h (the second component's scramble): h's bits multiplied up. */
static inline uint32_t seed_y(uint64_t h) { return (uint32_t)((h * 0xd1b54a32d192ed03ULL) >> 32) ^ (uint32_t)h; }

/* The shuffled index of dimension hash h: its own scramble of the sample number. */
static inline uint32_t shuffled(uint64_t h, uint32_t index) { return render_owen_scramble(index, (uint32_t)h); }

/* The scrambled 32-bit value of Sobol dimension 0 at shuffled index j: owen(reverse(j)) is
 * reverse(lk(j)). */
static inline uint32_t value0(uint64_t h, uint32_t j) { return reverse_bits(lk_permute(j, (uint32_t)(h >> 32))); }
static inline uint32_t value1(uint64_t h, uint32_t j) { return render_owen_scramble(sobol1(j), seed_y(h)); }

void render_sampler_bits(uint64_t key, uint32_t dim, uint32_t index, uint32_t out[2])
{
	uint64_t h = dim_hash(key, dim);
	uint32_t j = shuffled(h, index);
	out[0] = value0(h, j);
	out[1] = value1(h, j);
}

static inline float to_float(uint32_t x) { return (float)(x >> 8) * 0x1p-24f; }

render_sampler render_sampler_make(render_sampler_kind kind, uint64_t seed, uint32_t px, uint32_t py,
				   uint32_t sample)
{
	render_sampler s = {.kind = kind, .index = sample, .base = 0};
	if (kind == RENDER_SAMPLER_RANDOM)
		s.g = rng_for_sample(seed, px, py, sample);
	else
		s.key = render_sampler_key(seed, px, py);
	return s;
}

bool render_sampler_from_name(const char *name, render_sampler_kind *kind)
{
	if (!strcmp(name, "sobol"))
		*kind = RENDER_SAMPLER_SOBOL;
	else if (!strcmp(name, "random"))
		*kind = RENDER_SAMPLER_RANDOM;
	else
		return false;
	return true;
}

const char *render_sampler_name(render_sampler_kind kind) { return kind == RENDER_SAMPLER_RANDOM ? "random" : "sobol"; }

float render_sampler_1d(render_sampler *s, uint32_t dim)
{
	if (s->kind == RENDER_SAMPLER_RANDOM)
		return rng_float(&s->g);
	uint64_t h = dim_hash(s->key, s->base + dim);
	return to_float(value0(h, shuffled(h, s->index)));
}

vec2 render_sampler_2d(render_sampler *s, uint32_t dim)
{
	if (s->kind == RENDER_SAMPLER_RANDOM) {
		float y = rng_float(&s->g);
		float x = rng_float(&s->g);
		return v2(x, y);
	}
	uint32_t b[2];
	render_sampler_bits(s->key, s->base + dim, s->index, b);
	return v2(to_float(b[0]), to_float(b[1]));
}

double render_sampler_1d_double(render_sampler *s, uint32_t dim)
{
	if (s->kind == RENDER_SAMPLER_RANDOM)
		return rng_double(&s->g);
	uint64_t h = dim_hash(s->key, s->base + dim);
	uint64_t hi = value0(h, shuffled(h, s->index));
	uint64_t lo = rng_mix64(h ^ s->index) >> 43; /* 21 bits below the stratified 32 */
	return (double)((hi << 21) | lo) * 0x1p-53;
}

rng *render_sampler_stream(render_sampler *s, uint32_t dim, rng *local)
{
	if (s->kind == RENDER_SAMPLER_RANDOM)
		return &s->g;
	uint64_t h = rng_mix64(dim_hash(s->key, s->base + dim) ^ s->index);
	rng_seed(local, h, rng_mix64(h ^ 0xd1b54a32d192ed03ULL));
	return local;
}
