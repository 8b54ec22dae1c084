/* test_sobol: the Owen-scrambled Sobol sampler (render/sampler.h). The first 2^m points of Sobol's
 * dimensions 0 and 1, plain and scrambled, and of every 2-D request of the sampler, are
 * (0,m,2)-nets: each elementary interval of area 2^-m (every shape 2^-a x 2^-(m-a)) holds exactly
 * one point, and so does each later aligned block of 2^m; each 1-D request is stratified the same
 * way; the scramble is nested (points sharing their first k bits still share them and no others);
 * two padded dimensions are uncorrelated (chi-square on a 2-D grid, over a pixel's samples and
 * over pixels); values are determined by (seed, pixel, dimension, index) and change with each. */
#include "chi2.h"
#include "render/sampler.h"

#include <string.h>

#define MAX_M 12

/* Whether n = 2^m points (x[i], y[i]) (32-bit fixed point) put exactly one point in each
 * elementary interval of every shape; reports the first failure under name. */
static bool is_net(const char *name, const uint32_t *x, const uint32_t *y, int m)
{
	uint32_t n = 1u << m;
	unsigned char *seen = mem_calloc(n, 1);
	bool ok = true;
	for (int a = 0; a <= m && ok; a++) {
		int b = m - a;
		memset(seen, 0, n);
		for (uint32_t i = 0; i < n; i++) {
			uint32_t cx = a ? x[i] >> (32 - a) : 0, cy = b ? y[i] >> (32 - b) : 0;
			uint32_t cell = (cx << b) | cy;
			if (seen[cell]++) {
				CHECK(false, "%s: 2^%d points, intervals 2^-%d x 2^-%d: cell (%u, %u) holds two (point %u)", name,
				      m, a, b, cx, cy, i);
				ok = false;
				break;
			}
		}
	}
	mem_free(seen);
	return ok;
}

/* Whether n = 2^m values put one in each interval of 2^-m. */
static bool is_stratified(const char *name, const uint32_t *x, int m)
{
	uint32_t n = 1u << m;
	unsigned char *seen = mem_calloc(n, 1);
	bool ok = true;
	for (uint32_t i = 0; i < n && ok; i++) {
		uint32_t c = m ? x[i] >> (32 - m) : 0;
		if (seen[c]++) {
			CHECK(false, "%s: 2^%d values, interval %u holds two", name, m, c);
			ok = false;
		}
	}
	mem_free(seen);
	return ok;
}

static uint32_t bits24(float f) { return (uint32_t)(f * 0x1p24f) << 8; }

/* Sobol's dimensions 0 and 1 without scrambling: every block [b 2^m, (b+1) 2^m) is a net. */
static void test_plain_nets(void)
{
	static uint32_t x[1u << MAX_M], y[1u << MAX_M];
	CHECK(render_sobol(0, 0) == 0 && render_sobol(0, 1) == 0, "the first point is the origin");
	CHECK(render_sobol(1, 0) == 0x80000000u && render_sobol(1, 1) == 0x80000000u, "the second is (1/2, 1/2)");
	/* Known points of dimension 1 (Pascal's matrix): index 2 -> 3/4 ... */
	CHECK(render_sobol(2, 1) == 0xc0000000u && render_sobol(3, 1) == 0x40000000u,
	      "dimension 1 at 2, 3: %08x %08x", render_sobol(2, 1), render_sobol(3, 1));
	const uint32_t blocks[] = {0, 1, 5, 1000};
	for (int m = 0; m <= MAX_M; m++)
		for (size_t k = 0; k < sizeof blocks / sizeof blocks[0]; k++) {
			uint32_t n = 1u << m, b = blocks[k];
			for (uint32_t i = 0; i < n; i++)
				x[i] = render_sobol(b * n + i, 0), y[i] = render_sobol(b * n + i, 1);
			char name[64];
			snprintf(name, sizeof name, "plain Sobol, block %u", b);
			is_net(name, x, y, m);
		}
}

/* The scramble is nested: two values sharing their first k bits share them after, and their bit k
 * (the first that differs) still differs. */
static void test_scramble_nested(void)
{
	rng g;
	rng_seed(&g, 21, 1);
	int bad = 0;
	for (int t = 0; t < 100000; t++) {
		uint32_t seed = rng_u32(&g), a = rng_u32(&g);
		int k = (int)rng_below(&g, 32);
		uint32_t bit = 0x80000000u >> k, hi = k ? ~0u << (32 - k) : 0u;
		uint32_t b = (a & hi) | (~a & bit) | (rng_u32(&g) & (bit - 1u)); /* first difference: bit k */
		uint32_t sa = render_owen_scramble(a, seed), sb = render_owen_scramble(b, seed);
		uint32_t d = sa ^ sb;
		int first = d ? __builtin_clz(d) : 32;
		bad += first != k;
	}
	CHECK(bad == 0, "%d of 100000 pairs lost or gained common leading bits in the scramble", bad);
}

/* The sampler's 2-D requests over a pixel's first 2^m samples: nets, for several keys and
 * dimensions (the camera's and a few vertex blocks'), through the public float interface too. */
static void test_scrambled_nets(void)
{
	static uint32_t x[1u << MAX_M], y[1u << MAX_M], fx[1u << 10], fy[1u << 10];
	const uint64_t seeds[] = {0, 1, 77, 0xdeadbeef};
	for (size_t si = 0; si < sizeof seeds / sizeof seeds[0]; si++)
		for (uint32_t dim = 0; dim < 40; dim += 3) {
			uint32_t px = (uint32_t)(13 * si + dim), py = (uint32_t)(7 * dim);
			uint64_t key = render_sampler_key(seeds[si], px, py);
			for (int m = 0; m <= MAX_M; m++) {
				uint32_t n = 1u << m;
				for (uint32_t i = 0; i < n; i++) {
					uint32_t b[2];
					render_sampler_bits(key, dim, i, b);
					x[i] = b[0], y[i] = b[1];
				}
				char name[80];
				snprintf(name, sizeof name, "scrambled, seed %llu, dimension %u",
					 (unsigned long long)seeds[si], dim);
				is_net(name, x, y, m);
				is_stratified(name, x, m);
				/* A later block of 2^m samples too. */
				for (uint32_t i = 0; i < n; i++) {
					uint32_t b[2];
					render_sampler_bits(key, dim, 3 * n + i, b);
					x[i] = b[0], y[i] = b[1];
				}
				is_net(name, x, y, m);
			}
			/* The same through render_sampler_2d and _1d at a vertex block, floats (24 bits). */
			for (int m = 0; m <= 10; m++) {
				uint32_t n = 1u << m;
				for (uint32_t i = 0; i < n; i++) {
					render_sampler s = render_sampler_make(RENDER_SAMPLER_SOBOL, seeds[si], px, py, i);
					render_sampler_vertex(&s, dim % 5);
					vec2 u = render_sampler_2d(&s, dim % 7);
					CHECK(u.x >= 0.0f && u.x < 1.0f && u.y >= 0.0f && u.y < 1.0f, "point outside [0,1)^2");
					fx[i] = bits24(u.x), fy[i] = bits24(u.y);
				}
				is_net("render_sampler_2d", fx, fy, m);
				for (uint32_t i = 0; i < n; i++) {
					render_sampler s = render_sampler_make(RENDER_SAMPLER_SOBOL, seeds[si], px, py, i);
					render_sampler_vertex(&s, dim % 5);
					fx[i] = bits24(render_sampler_1d(&s, dim % 11));
					double d = render_sampler_1d_double(&s, dim % 13);
					CHECK(d >= 0.0 && d < 1.0, "double %g outside [0,1)", d);
					fy[i] = (uint32_t)(d * 0x1p32);
				}
				is_stratified("render_sampler_1d", fx, m);
				is_stratified("render_sampler_1d_double", fy, m);
			}
		}
}

/* Two padded dimensions are independent: the 2-D histogram of (dimension a, dimension b) is
 * uniform, over one pixel's samples and over many pixels' first sample. */
static void chi2_pair(const char *name, uint64_t seed, uint32_t da, uint32_t db, bool over_pixels, bool two_d)
{
	enum { G = 16, N = 1 << 14 };
	double obs[G * G] = {0}, ex[G * G];
	for (uint32_t i = 0; i < N; i++) {
		render_sampler s = over_pixels ? render_sampler_make(RENDER_SAMPLER_SOBOL, seed, i % 128, i / 128, 0)
					       : render_sampler_make(RENDER_SAMPLER_SOBOL, seed, 3, 4, i);
		float a = two_d ? render_sampler_2d(&s, da).x : render_sampler_1d(&s, da);
		float b = two_d ? render_sampler_2d(&s, db).y : render_sampler_1d(&s, db);
		obs[(int)(a * G) * G + (int)(b * G)] += 1;
	}
	for (int k = 0; k < G * G; k++)
		ex[k] = (double)N / (G * G);
	chi2_counts(name, obs, ex, G * G);
}

static void test_determinism(void)
{
	render_sampler a = render_sampler_make(RENDER_SAMPLER_SOBOL, 5, 10, 20, 30);
	render_sampler b = render_sampler_make(RENDER_SAMPLER_SOBOL, 5, 10, 20, 30);
	render_sampler_vertex(&a, 3), render_sampler_vertex(&b, 3);
	/* Any order of requests: a value is a function of its dimension. */
	float a1 = render_sampler_1d(&a, 4);
	vec2 a2 = render_sampler_2d(&a, 9);
	vec2 b2 = render_sampler_2d(&b, 9);
	float b1 = render_sampler_1d(&b, 4);
	CHECK(a1 == b1 && a2.x == b2.x && a2.y == b2.y, "the same key gave different values");
	/* Each of seed, pixel, dimension and index changes the values. */
	int same = 0;
	for (uint32_t k = 1; k <= 1000; k++) {
		uint32_t base[2], v[2];
		uint64_t key = render_sampler_key(5, 10, 20);
		render_sampler_bits(key, 7, 30, base);
		render_sampler_bits(render_sampler_key(5 + k, 10, 20), 7, 30, v);
		same += v[0] == base[0];
		render_sampler_bits(render_sampler_key(5, 10 + k, 20), 7, 30, v);
		same += v[0] == base[0];
		render_sampler_bits(render_sampler_key(5, 10, 20 + k), 7, 30, v);
		same += v[0] == base[0];
		render_sampler_bits(key, 7 + k, 30, v);
		same += v[0] == base[0];
		render_sampler_bits(key, 7, 30 + k, v);
		same += v[0] == base[0];
	}
	CHECK(same == 0, "%d of 5000 changed keys gave the same value", same);
	/* The random sampler is its stream's numbers, y before x. */
	rng g;
	rng_seed(&g, 3, 9);
	render_sampler r = render_sampler_of_rng(g);
	float u0 = rng_float(&g), u1 = rng_float(&g), u2 = rng_float(&g);
	float r0 = render_sampler_1d(&r, 100);
	vec2 r12 = render_sampler_2d(&r, 0);
	CHECK(r0 == u0 && r12.y == u1 && r12.x == u2, "the random sampler is not its stream");
	render_sampler_kind kind;
	CHECK(render_sampler_from_name("sobol", &kind) && kind == RENDER_SAMPLER_SOBOL, "sobol");
	CHECK(render_sampler_from_name("random", &kind) && kind == RENDER_SAMPLER_RANDOM, "random");
	CHECK(!render_sampler_from_name("halton", &kind), "halton is no sampler");
}

int main(void)
{
	test_plain_nets();
	test_scramble_nested();
	test_scrambled_nets();
	test_determinism();
	/* Within a block, across blocks (vertices), 1-D and 2-D, over samples and over pixels. */
	chi2_pair("padded 1-D dimensions 2 and 3 over samples", 1, 2, 3, false, false);
	chi2_pair("padded 1-D dimensions 0 and 40 over samples", 2, 0, 40, false, false);
	chi2_pair("padded 2-D dimensions 5 (x) and 6 (y) over samples", 3, 5, 6, false, true);
	chi2_pair("padded 1-D dimensions 2 and 3 over pixels", 4, 2, 3, true, false);
	return check_done("test_sobol");
}
