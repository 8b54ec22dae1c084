/* rng.h - PCG32 (O'Neill 2014, "PCG: A Family of Simple Fast Space-Efficient Statistically Good
 * Algorithms for Random Number Generation", the pcg32 XSH-RR variant) and the hash that gives every
 * sample its own stream. The stream of a sample depends only on (seed, pixel x, pixel y, sample
 * index), which is what makes images bit-identical for any thread count or tiling (DESIGN.md). */
#ifndef CIRCE_BASE_RNG_H
#define CIRCE_BASE_RNG_H

#include <assert.h>
#include <stdint.h>

typedef struct rng {
	uint64_t state;
	uint64_t inc; /* always odd */
} rng;

#define RNG_PCG_MULT 6364136223846793005ULL

static inline uint32_t rng_u32(rng *g);

/* Seeds a generator on stream `stream` (any value; made odd internally). */
static inline void rng_seed(rng *g, uint64_t seed, uint64_t stream)
{
	g->state = 0;
	g->inc = (stream << 1) | 1u;
	rng_u32(g);
	g->state += seed;
	rng_u32(g);
}

static inline uint32_t rng_u32(rng *g)
{
	uint64_t old = g->state;
	g->state = old * RNG_PCG_MULT + g->inc;
	uint32_t xorshifted = (uint32_t)(((old >> 18) ^ old) >> 27);
	uint32_t rot = (uint32_t)(old >> 59);
	return (xorshifted >> rot) | (xorshifted << ((32 - rot) & 31));
}

/* Uniform in [0, 1): 24 random bits, so the result is exactly representable and never 1. */
static inline float rng_float(rng *g) { return (float)(rng_u32(g) >> 8) * 0x1p-24f; }

/* Uniform in [0, 1) with 53 random bits. */
static inline double rng_double(rng *g)
{
	uint64_t hi = rng_u32(g) >> 5, lo = rng_u32(g) >> 6;
	return (double)(hi * 67108864u + lo) * 0x1p-53;
}

/* Uniform integer in [0, n), n > 0, without modulo bias (Lemire 2019). */
static inline uint32_t rng_below(rng *g, uint32_t n)
{
	assert(n > 0);
	uint64_t m = (uint64_t)rng_u32(g) * n;
	uint32_t l = (uint32_t)m;
	if (l < n) {
		uint32_t t = (uint32_t)(-n) % n;
		while (l < t) {
			m = (uint64_t)rng_u32(g) * n;
			l = (uint32_t)m;
		}
	}
	return (uint32_t)(m >> 32);
}

/* A 64-bit finaliser (Stafford's "Mix13" variant of the MurmurHash3 fmix64): a bijection whose
 * every output bit depends on every input bit. */
static inline uint64_t rng_mix64(uint64_t z)
{
	z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
	z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
	return z ^ (z >> 31);
}

/* The generator of one sample: its state and stream are hashes of (seed, x, y, sample). Each
 * input passes through the mixer in turn, so neighbouring pixels and sample indices land on
 * unrelated states and streams. */
static inline rng rng_for_sample(uint64_t seed, uint32_t px, uint32_t py, uint32_t sample)
{
	uint64_t h = rng_mix64(seed ^ 0x9e3779b97f4a7c15ULL);
	h = rng_mix64(h ^ (((uint64_t)px << 32) | py));
	h = rng_mix64(h ^ sample);
	rng g;
	rng_seed(&g, h, rng_mix64(h ^ 0xd1b54a32d192ed03ULL));
	return g;
}

#endif
