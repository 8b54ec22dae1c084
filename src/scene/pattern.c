/* pattern.c - POV-Ray 3.7's patterns, waves, warps and colour maps, and the noise under them.
 * Each pattern cites the function of POV-Ray's source (source/core/material/pattern.cpp,
 * github.com/POV-Ray/povray) whose definition it implements; the code is written from those
 * definitions, not copied. */
#include "scene/pattern.h"

#include "base/noise.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define TWO_PI 6.283185307179586
/* POV-Ray's EPSILON (source/core/configcore.h): the block patterns' floor() nudge, so a point
 * exactly on an integer plane falls on the same side as POV-Ray puts it. */
#define POV_EPSILON 1.0e-10
/* warp.cpp's COORDINATE_LIMIT: warped points are clamped there. */
#define POV_COORDINATE_LIMIT 1.0e17
/* POV-Ray's default number of waves of ripples and waves (global_settings number_of_waves). */
#define POV_NUMBER_OF_WAVES 10

int pattern_perm(int i) { return noise_perm(i); }

static double clamp01(double v) { return v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v; }

/* POV-Ray 3.7's own noise (base/noise.c: its table, permutation and blend, noise_generator 2),
 * so that bozo, granite, agate and the rest show POV-Ray's blobs, not others of their size. */
double pattern_noise(dvec3 p) { return noise_pov(p); }

/* POV-Ray's DNoise: the vector noise bumps, dents and the turbulence warp move by. */
dvec3 pattern_dnoise(dvec3 p) { return noise_pov_vector(p); }

/* POV-Ray 3.7's generator-2 branches of Turbulence, granite and wrinkles take 2 noise - 0.5 (or
 * |1 - 2 noise|): its range-corrected noise has about half generator 1's spread. */
static double noise2(dvec3 p) { return 2.0 * pattern_noise(p) - 0.5; }

/* texture.cpp's Turbulence (generator 2): clamp(2 noise(p) - 0.5, 0, 1) + sum over octaves 2..n
 * of omega^(i-1) (2 noise(lambda^(i-1) p) - 0.5). */
double pattern_turbulence(dvec3 p, const pattern_turb *t)
{
	double value = clamp01(noise2(p)), l = t->lambda, o = t->omega;
	for (int i = 2; i <= t->octaves; i++) {
		value += o * noise2(d3_scale(p, l));
		l *= t->lambda, o *= t->omega;
	}
	return value;
}

/* noise.cpp's DTurbulence: the same sum of vector noise. */
dvec3 pattern_dturbulence(dvec3 p, const pattern_turb *t)
{
	dvec3 r = pattern_dnoise(p);
	double l = t->lambda, o = t->omega;
	for (int i = 2; i <= t->octaves; i++) {
		r = d3_add(r, d3_scale(pattern_dnoise(d3_scale(p, l)), o));
		l *= t->lambda, o *= t->omega;
	}
	return r;
}

/* texture.cpp's cycloidal: sin(2 pi v). */
static double cycloidal(double v) { return sin(v * TWO_PI); }

/* texture.cpp's Triangle_Wave: 0 at integers, 1 at halves. */
static double triangle_wave(double v)
{
	double off = v - floor(v);
	return off >= 0.5 ? 2.0 * (1.0 - off) : 2.0 * off;
}

/* ContinuousPattern::Evaluate: frequency and phase (mod a hair over 1, as POV-Ray does: a ramp
 * reaches 1 at the top), then the wave's shape. */
double pattern_wave_apply(pattern_wave w, double v, double frequency, double phase, double exponent)
{
	if (frequency != 0.0)
		v = fmod(v * frequency + phase, 1.00001);
	if (v < 0.0)
		v -= floor(v);
	switch (w) {
	case WAVE_RAMP: return v;
	case WAVE_SINE: return (1.0 + cycloidal(v)) * 0.5;
	case WAVE_TRIANGLE: return triangle_wave(v);
	case WAVE_SCALLOP: return fabs(cycloidal(v * 0.5));
	case WAVE_CUBIC: return v * v * (3.0 - 2.0 * v);
	case WAVE_POLY: return pow(v, exponent);
	}
	return v;
}

static int cell_of(double v) { return (int)floor(fmax(-2.0e9, fmin(2.0e9, v))); }

/* crackle's feature point of a unit cube (pattern.cpp's IntPickInCube): the cube's corner plus
 * three of gPatternRands from the cube's Hash3d on, so the cells are POV-Ray's own. */
dvec3 pattern_crackle_point(int x, int y, int z)
{
	int h = noise_pov_hash3(x, y, z);
	return d3(x + noise_pov_rand(h), y + noise_pov_rand(h + 1), z + noise_pov_rand(h + 2));
}

/* |a|^m for crackle's metric, without pow where m is 1, 1.5, 2 or 3. */
static inline double metric_pow(double a, double m)
{
	a = fabs(a);
	if (m == 2.0)
		return a * a;
	if (m == 1.0)
		return a;
	if (m == 3.0)
		return a * a * a;
	if (m == 1.5)
		return a * sqrt(a);
	return pow(a, m);
}

/* A distance under crackle's metric m before its root: |d|^2 summed for 2, |d| for 1, |d|^m; a
 * sum known to be at least `above` (the third nearest so far) stops there: it is not among them. */
static double metric_sum(dvec3 d, double m, double above)
{
	if (m == 2.0)
		return d.x * d.x + d.y * d.y + d.z * d.z;
	if (m == 1.0)
		return fabs(d.x) + fabs(d.y) + fabs(d.z);
	double s = metric_pow(d.x, m);
	if (s >= above)
		return s;
	s += metric_pow(d.y, m);
	if (s >= above)
		return s;
	return s + metric_pow(d.z, m);
}

/* POV-Ray 3.7's CracklePattern::EvaluateRaw: one feature point per unit cube; the three nearest
 * of the 81 cubes that can hold them (p's cube, its 26 neighbours, and the cubes two away along
 * one axis from the 9 of each face: POV-Ray's gaCrackleCubeTable), their distances under the
 * metric, each with the offset added in the metric's power, combined by the form and clamped to
 * [0, 1]; solid: the noise at the nearest point (one value per cell). */
static double crackle(dvec3 p, const pattern_node *n)
{
	int cx = cell_of(p.x), cy = cell_of(p.y), cz = cell_of(p.z);
	double m = n->crackle_metric, d[3] = {1e300, 1e300, 1e300};
	dvec3 nearest = d3(0, 0, 0);
	/* The 27 nearest cubes first, then the 54 beyond; a cube whose gap to p along one axis is at
	 * least the third distance so far (under the metric's root, reach) cannot hold one of the
	 * three nearest points and is skipped unhashed (its point lies inside it). The three nearest
	 * are those of every order but for exact ties. */
	double reach = INFINITY;
	for (int pass = 0; pass < 2; pass++)
		for (int i = -2; i <= 2; i++)
			for (int j = -2; j <= 2; j++)
				for (int k = -2; k <= 2; k++) {
					int twos = (abs(i) == 2) + (abs(j) == 2) + (abs(k) == 2);
					if (twos > 1 || (twos > 0) != (pass > 0))
						continue;
					double gi = i > 0 ? cx + i - p.x : i < 0 ? p.x - (cx + i + 1) : 0.0;
					double gj = j > 0 ? cy + j - p.y : j < 0 ? p.y - (cy + j + 1) : 0.0;
					double gk = k > 0 ? cz + k - p.z : k < 0 ? p.z - (cz + k + 1) : 0.0;
					if (gi >= reach || gj >= reach || gk >= reach)
						continue;
					dvec3 f = pattern_crackle_point(cx + i, cy + j, cz + k);
					double s = metric_sum(d3_sub(f, p), m, d[2]);
					if (s >= d[2])
						continue;
					if (s < d[0])
						d[2] = d[1], d[1] = d[0], d[0] = s, nearest = f;
					else if (s < d[1])
						d[2] = d[1], d[1] = s;
					else
						d[2] = s;
					if (d[2] < 1e300)
						reach = m == 2.0 ? sqrt(d[2]) : m == 1.0 ? d[2] : pow(d[2], 1.0 / m);
				}
	if (n->solid) /* POV-Ray: Noise(nucleus), so the cells' values cluster as its noise does */
		return pattern_noise(nearest);
	double o = n->crackle_offset, add = m == 2.0 ? o * o : m == 1.0 ? o : pow(o, m);
	double r[3];
	for (int c = 0; c < 3; c++) {
		double v = o != 0.0 ? d[c] + add : d[c];
		r[c] = m == 2.0 ? sqrt(v) : m == 1.0 ? v : pow(v, 1.0 / m);
	}
	dvec3 f = n->crackle_form;
	return clamp01(f.x * r[0] + f.y * r[1] + f.z * r[2]);
}

/* POV-Ray 3.7's FractalPattern::ExteriorColour and InteriorColour: what a point that escapes
 * after `iters` iterations at z = a + bi, or one that never does (mindist2: the least |z|^2 on
 * its orbit), is worth, by the pattern's types and factors. */
static double fractal_exterior(const pattern_node *n, int iters, double a, double b)
{
	double f = n->exterior_factor;
	switch (n->fractal_exterior) {
	case 0: return f;
	case 1: return (double)iters / n->fractal_iterations;
	case 2: return a * f;
	case 3: return b * f;
	case 4: return a * a * f;
	case 5: return b * b * f;
	case 6: return sqrt(a * a + b * b) * f;
	case 7: return f >= 1.0 ? (double)(iters % (unsigned)f) / f : 0.0; /* the parser keeps f >= 1 */
	case 8: return f > 0.0 ? (double)(iters % (unsigned)(1.0 + f)) / f : 0.0;
	default: return 0.0;
	}
}

static double fractal_interior(const pattern_node *n, double a, double b, double mindist2)
{
	double f = n->interior_factor;
	switch (n->fractal_interior) {
	case 0: return f;
	case 1: return sqrt(mindist2) * f;
	case 2: return a * f;
	case 3: return b * f;
	case 4: return a * a * f;
	case 5: return b * b * f;
	case 6: return a * a + b * b * f; /* POV-Ray's own precedence, kept */
	default: return 0.0;
	}
}

/* (a + bi)^e for e > 4, as POV-Ray 3.7's mandelx_pattern and juliax_pattern: the binomial sums
 * with pow, the signs of i^k (k & 2: negative). */
static void fractal_power(double *a, double *b, int e)
{
	double x = *a, y = *b, re = pow(x, e), im = 0.0, c = 1.0; /* c: the binomial coefficient (e k) */
	for (int k = 1; k <= e; k++) {
		c = c * (e - k + 1) / k;
		double t = (k & 2 ? -c : c) * pow(x, e - k) * pow(y, k);
		if (k & 1)
			im += t;
		else
			re += t;
	}
	*a = re, *b = im;
}

/* Mandel2Pattern and JuliaPattern::EvaluateRaw: z <- z^2 + c from z = c = <x, y> (mandel) or from
 * z = <x, y> with the pattern's c (julia), until |z|^2 > 4 or the iterations limit; exponent 3
 * and 4 as POV-Ray's mandel3/4 and julia3/4 patterns, above 4 as mandelx and juliax. */
static double fractal(const pattern_node *n, dvec3 p)
{
	double a = p.x, b = p.y, cr = p.x, ci = p.y;
	if (n->kind == PATTERN_JULIA)
		cr = n->julia_c[0], ci = n->julia_c[1];
	double a2 = a * a, b2 = b * b, mindist2 = a2 + b2;
	int e = n->fractal_exponent;
	for (int it = 0; it < n->fractal_iterations; it++) {
		if (e == 3) {
			b = 3.0 * a2 * b - b2 * b + ci;
			a = a2 * a - 3.0 * a * b2 + cr;
		} else if (e == 4) {
			b = 4.0 * (a2 * a * b - a * b2 * b) + ci;
			a = a2 * a2 - 6.0 * a2 * b2 + b2 * b2 + cr;
		} else if (e > 4) {
			fractal_power(&a, &b, e);
			a += cr, b += ci;
		} else {
			b = 2.0 * a * b + ci;
			a = a2 - b2 + cr;
		}
		a2 = a * a, b2 = b * b;
		double d2 = a2 + b2;
		mindist2 = fmin(mindist2, d2);
		if (d2 > 4.0)
			return fractal_exterior(n, it, a, b);
	}
	return fractal_interior(n, a, b, mindist2);
}

/* Complex numbers for the magnet fractals. */
typedef struct cplx {
	double re, im;
} cplx;
static cplx c_add(cplx a, cplx b) { return (cplx){a.re + b.re, a.im + b.im}; }
static cplx c_mul(cplx a, cplx b) { return (cplx){a.re * b.re - a.im * b.im, a.re * b.im + a.im * b.re}; }
static cplx c_scale(cplx a, double s) { return (cplx){a.re * s, a.im * s}; }
static cplx c_div(cplx a, cplx b)
{
	double d = b.re * b.re + b.im * b.im;
	return (cplx){(a.re * b.re + a.im * b.im) / d, (a.im * b.re - a.re * b.im) / d};
}

/* POV-Ray 3.7's Magnet1M/1J/2M/2JPattern::EvaluateRaw: type 1 iterates
 * z <- ((z^2 + c - 1) / (2z + c - 2))^2, type 2 z <- ((z^3 + 3(c - 1)z + (c - 1)(c - 2)) /
 * (3z^2 + 3(c - 2)z + (c - 1)(c - 2) + 1))^2; mandel's form starts at z = 0 with c the point (the
 * least |z|^2 starting at 10000), julia's at z = the point with c given; a point escapes when
 * |z|^2 > 10000 or z comes within 0.01 of 1. */
static double magnet(const pattern_node *n, dvec3 p)
{
	cplx z = {0, 0}, c = {p.x, p.y};
	double mindist2 = 10000.0;
	if (n->magnet_julia) {
		z = c, c = (cplx){n->julia_c[0], n->julia_c[1]};
		mindist2 = z.re * z.re + z.im * z.im;
	}
	cplx c1 = {c.re - 1.0, c.im}, c2 = {c.re - 2.0, c.im}, c12 = c_mul(c1, c2);
	for (int it = 0; it < n->fractal_iterations; it++) {
		cplx num, den;
		if (n->magnet_type == 2) {
			cplx z2 = c_mul(z, z);
			num = c_add(c_add(c_mul(z2, z), c_scale(c_mul(c1, z), 3.0)), c12);
			den = c_add(c_add(c_scale(z2, 3.0), c_scale(c_mul(c2, z), 3.0)), (cplx){c12.re + 1.0, c12.im});
		} else {
			num = c_add(c_mul(z, z), c1);
			den = c_add(c_scale(z, 2.0), c2);
		}
		cplx q = c_div(num, den);
		z = c_mul(q, q);
		double d2 = z.re * z.re + z.im * z.im;
		mindist2 = fmin(mindist2, d2);
		if (d2 > 10000.0 || (z.re - 1.0) * (z.re - 1.0) + z.im * z.im < 1e-4)
			return fractal_exterior(n, it, z.re, z.im);
	}
	return fractal_interior(n, z.re, z.im, mindist2);
}

/* The i-th wave source of ripples and waves: POV-Ray's vector noise at <i, 0, 0>, normalised, and
 * its frequency from POV-Ray's own generator (noise.cpp's Initialize_Waves, its seed and
 * constants). */
static dvec3 wave_source(int i) { return d3_normalize(pattern_dnoise(d3((double)i, 0.0, 0.0))); }

/* The next wave's frequency from Initialize_Waves' generator (state *next, seeded -560851967). */
static double wave_frequency(uint32_t *next)
{
	*next = *next * 1812433253u + 12345u;
	return (double)((int32_t)*next >> 16 & 0x7FFF) * 0.000030518509476 + 0.01;
}

static double wave_sum(dvec3 p, const pattern_node *n, bool waves)
{
	uint32_t next = (uint32_t)-560851967;
	double scalar = 0.0;
	for (int i = 0; i < POV_NUMBER_OF_WAVES; i++) {
		double f = wave_frequency(&next);
		double len = d3_length(d3_sub(p, wave_source(i)));
		if (len == 0.0)
			len = 1.0;
		if (waves)
			scalar += cycloidal(len * n->frequency * f + n->phase) / f;
		else
			scalar += cycloidal(len * n->frequency + n->phase);
	}
	scalar /= POV_NUMBER_OF_WAVES;
	return waves ? 0.2 * (2.5 + scalar) : 0.5 * (1.0 + scalar);
}

/* The angle about the z axis of Spiral1Pattern/Spiral2Pattern, in [0, 2 pi). */
static double spiral_phi(double x, double y, double rad)
{
	if (rad == 0.0)
		return 0.0;
	double s = fmax(-1.0, fmin(1.0, y / rad));
	return x < 0.0 ? 1.5 * M_PI - asin(s) : 0.5 * M_PI + asin(s);
}

/* CLIP_DENSITY of pattern.cpp: 1 - r inside the unit range, 1 below it, 0 above. */
static double clip_density(double r) { return r < 0.0 ? 1.0 : r > 1.0 ? 0.0 : 1.0 - r; }

/* QuiltedPattern's quilt_cubic (INV_SQRT_3_4 = 1/sqrt(3/4)). */
static double quilt_cubic(double t, double p1, double p2)
{
	double it = 1.0 - t;
	return (t * t * t + 3.0 * t * it * it * p1 + 3.0 * t * t * it * p2) * 1.1547005383792517;
}

/* POV-Ray's fractional part as (int) truncation does it, then folded into [0, 1). */
static double frac_trunc(double v)
{
	double f = v - trunc(v);
	return f < 0.0 ? f + 1.0 : f;
}

/* BrickPattern::Evaluate: 0 in the mortar, 1 in a brick; rows alternate by half a brick. */
static double brick(dvec3 p, dvec3 size, double mortar, double eps)
{
	double fudge = eps + mortar;
	double x = p.x + fudge, y = p.y + fudge, z = p.z + fudge;
	if (frac_trunc(y / size.y) <= mortar / size.y)
		return 0.0;
	double row = frac_trunc(y / size.y * 0.5);
	double mw = mortar / size.x, md = mortar / size.z;
	if (row <= 0.5 ? frac_trunc(x / size.x) <= mw : frac_trunc(x / size.x + 0.5) <= mw)
		return 0.0;
	if (row > 0.5 ? frac_trunc(z / size.z) <= md : frac_trunc(z / size.z + 0.5) <= md)
		return 0.0;
	return 1.0;
}

/* HexagonPattern::Evaluate: the x-z plane tiled by hexagons of side 1 in three colours; the
 * lattice is cut in cells of 0.5 by sqrt(3)/2, and the two slanted ones split on a diagonal. */
static double hexagon(dvec3 p)
{
	static const int straight[2][6] = {{0, 1, 1, 2, 2, 0}, {2, 2, 0, 0, 1, 1}};
	static const int below[6] = {0, 2, 1, 0, 2, 1}, above[6] = {2, 1, 0, 2, 1, 0};
	double x = fabs(p.x), z = p.z < 0.0 ? 5.196152424 - fabs(p.z) : p.z;
	double xs = x / 0.5, zs = z / 0.866025404;
	xs -= floor(xs / 6.0) * 6.0;
	zs -= floor(zs / 6.0) * 6.0;
	int xm = (int)floor(xs) % 6, zm = (int)floor(zs) % 6;
	if (xm < 0 || zm < 0 || xm > 5 || zm > 5)
		return 0.0;
	if (xm == 0 || xm == 5)
		return straight[0][zm];
	if (xm == 2 || xm == 3)
		return straight[1][zm];
	double xl = xs - xm, zl = zs - zm;
	if ((xm + zm) % 2 == 1)
		xl = 1.0 - xl;
	if (xl == 0.0)
		xl = 0.0001;
	return zl / xl < 1.0 ? below[zm] : above[zm];
}

/* Raw values of the noise-family patterns (NoisePattern, DentsPattern, WrinklesPattern,
 * GranitePattern, AgatePattern's turbulence). */
static double raw_noisy(const pattern_node *n, dvec3 p)
{
	switch (n->kind) {
	case PATTERN_DENTS: {
		double v = pattern_noise(p);
		return v * v * v;
	}
	case PATTERN_WRINKLES: { /* pattern.cpp wrinkles_pattern (generator 2): ten octaves of
				  clamp(2 noise - 0.5, 0, 1), lambda 2, omega 0.5, halved */
		double v = clamp01(noise2(p)), l = 2.0, o = 0.5;
		for (int i = 1; i < 10; i++, l *= 2.0, o *= 0.5)
			v += o * clamp01(noise2(d3_scale(p, l)));
		return v / 2.0;
	}
	case PATTERN_GRANITE: { /* pattern.cpp granite_pattern (generator 2): six octaves of
				 min(|1 - 2 noise|, 0.5) at 4 p */
		double v = 0.0, freq = 1.0;
		for (int i = 0; i < 6; i++, freq *= 2.0)
			v += fmin(fabs(1.0 - 2.0 * pattern_noise(d3_scale(p, 4.0 * freq))), 0.5) / freq;
		return v;
	}
	case PATTERN_AGATE: {
		double turb = n->agate_turb * pattern_turbulence(p, &n->turb);
		double v = 0.5 * (cycloidal(1.3 * turb + 1.1 * p.z) + 1.0);
		return v < 0.0 ? 0.0 : pow(fmin(1.0, v), 0.77);
	}
	default: /* bozo, spotted, bumps */
		return pattern_noise(p);
	}
}

/* The classic turbulence a pattern handles itself (marble, spiral): Turbulence[X] times the
 * scalar turbulence, 0 without one. */
static double own_turb(const pattern_node *n, dvec3 p)
{
	return n->turb.amount.x != 0.0 ? n->turb.amount.x * pattern_turbulence(p, &n->turb) : 0.0;
}

/* WoodPattern: the distance from the z axis, its x and y wobbled by the vector turbulence. */
static double wood(const pattern_node *n, dvec3 p)
{
	double x = p.x, y = p.y;
	if (n->turb.amount.x != 0.0 || n->turb.amount.y != 0.0) {
		dvec3 t = pattern_dturbulence(p, &n->turb);
		x += cycloidal((p.x + t.x) * n->turb.amount.x);
		y += cycloidal((p.y + t.y) * n->turb.amount.y);
	}
	return sqrt(x * x + y * y);
}

static double raw_shapes(const pattern_node *n, dvec3 p, double eps)
{
	switch (n->kind) {
	case PATTERN_GRADIENT: {
		double r = d3_dot(p, n->vector);
		return r > 1.0 ? fmod(r, 1.0) : r;
	}
	case PATTERN_RADIAL:
		return fabs(p.x) < 0.001 && fabs(p.z) < 0.001 ? 0.25 : 0.25 + (atan2(p.x, p.z) + M_PI) / TWO_PI;
	case PATTERN_ONION: return fmod(d3_length(p), 1.0);
	case PATTERN_LEOPARD: {
		double s = (sin(p.x) + sin(p.y) + sin(p.z)) / 3.0;
		return s * s;
	}
	case PATTERN_MARBLE: return p.x + own_turb(n, p);
	case PATTERN_WOOD: return wood(n, p);
	case PATTERN_CELLS: /* CellsPattern: gPatternRands at the cell's Hash3d */
		return fmin(noise_pov_rand(noise_pov_hash3(cell_of(p.x + eps), cell_of(p.y + eps), cell_of(p.z + eps))), 1.0);
	case PATTERN_CRACKLE: return crackle(p, n);
	case PATTERN_MANDEL:
	case PATTERN_JULIA: return fractal(n, p);
	case PATTERN_MAGNET: return magnet(n, p);
	case PATTERN_SPIRAL1:
	case PATTERN_SPIRAL2: {
		double rad = sqrt(p.x * p.x + p.y * p.y);
		double v = p.z + rad + n->arms * spiral_phi(p.x, p.y, rad) / TWO_PI + own_turb(n, p);
		return n->kind == PATTERN_SPIRAL1 ? v : triangle_wave(rad) + triangle_wave(v);
	}
	case PATTERN_QUILTED: {
		dvec3 v = d3(p.x - floor(p.x) - 0.5, p.y - floor(p.y) - 0.5, p.z - floor(p.z) - 0.5);
		v = d3_scale(v, quilt_cubic(d3_length(v), n->control0, n->control1));
		return (fabs(v.x) + fabs(v.y) + fabs(v.z)) / 3.0;
	}
	case PATTERN_PLANAR: return clip_density(fabs(p.y));
	case PATTERN_BOXED: return clip_density(fmax(fabs(p.x), fmax(fabs(p.y), fabs(p.z))));
	case PATTERN_CYLINDRICAL: return clip_density(sqrt(p.x * p.x + p.z * p.z));
	case PATTERN_SPHERICAL: return clip_density(d3_length(p));
	case PATTERN_RIPPLES: return wave_sum(p, n, false);
	case PATTERN_WAVES: return wave_sum(p, n, true);
	default: return 0.0;
	}
}

/* ImagePattern through imageutil.cpp's map_pos: planar on the unit square of x-y, spherical
 * (u the longitude from +x towards +z... as POV-Ray's acos form, v the latitude), cylindrical
 * (u the angle about y, v = y), torus (5: u the angle about y, v the angle about the ring of
 * radius 1, from its inside); map types 3, 4, 6 and 7 are planar, as map_pos's default; repeated
 * unless once. The texel (bilinear with interpolate, else
 * the nearest) into c; false outside the image (once, or the mapping's poles). */
static bool image_texel(const pattern_node *n, dvec3 p, float c[4])
{
	double u = p.x, v = p.y;
	bool inside = true;
	if (n->map_type == 5) { /* torus_image_map: about the y axis, major radius 1 (POV-Ray's Gradient.x) */
		double len = sqrt(p.x * p.x + p.z * p.z);
		if (len == 0.0)
			return false;
		double theta = acos(fmax(-1.0, fmin(1.0, p.x / len)));
		if (p.z < 0.0)
			theta = TWO_PI - theta;
		double rx = len - 1.0, r = sqrt(rx * rx + p.y * p.y);
		if (r == 0.0)
			return false;
		double phi = acos(fmax(-1.0, fmin(1.0, -rx / r)));
		if (p.y > 0.0)
			phi = TWO_PI - phi;
		u = theta / TWO_PI, v = phi / TWO_PI;
	} else if (n->map_type == 1 || n->map_type == 2) {
		double len = d3_length(p);
		double x = len > 0.0 ? p.x / len : 0.0, y = len > 0.0 ? p.y / len : 0.0, z = len > 0.0 ? p.z / len : 0.0;
		double r = sqrt(x * x + z * z), theta = 0.0;
		if (r > 0.0) {
			theta = acos(fmax(-1.0, fmin(1.0, x / r)));
			if (z < 0.0)
				theta = TWO_PI - theta;
		}
		u = theta / TWO_PI;
		v = n->map_type == 1 ? 0.5 + asin(fmax(-1.0, fmin(1.0, y))) / M_PI : p.y;
		inside = len > 0.0 && (n->map_type == 1 || r > 0.0);
	}
	if (n->once && (u < 0.0 || u >= 1.0 || v < 0.0 || v >= 1.0))
		inside = false;
	if (!inside || !n->img)
		return false;
	if (n->interpolate) {
		image_bilinear(n->img, (float)(u - floor(u)), (float)(v - floor(v)), c);
	} else { /* the nearest texel */
		int w = n->img->width, h = n->img->height;
		int ix = (int)fmin(w - 1, floor((u - floor(u)) * w)), iy = (int)fmin(h - 1, floor((1.0 - (v - floor(v))) * h));
		for (int i = 0; i < 4; i++)
			c[i] = n->img->rgba[((size_t)iy * w + ix) * 4 + i];
	}
	return true;
}

/* imageutil.cpp's image_pattern: the image's grey (0.297 r + 0.589 g + 0.114 b) at the mapped
 * texel, or with use_alpha its transparency (1 - alpha; an image without alpha: its red, as
 * POV-Ray), clamped to [0, 1]; 0 outside the image. The image is read as stored (POV-Ray reads it
 * without gamma correction). */
static double image_pattern(const pattern_node *n, dvec3 p)
{
	float c[4];
	if (!image_texel(n, p, c))
		return 0.0;
	double v = n->use_alpha ? (n->img_alpha ? 1.0 - c[3] : c[0]) : 0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2];
	return clamp01(v);
}

/* ---- POV-Ray 3.7's tilings (pattern.cpp's tiling_*): each folds the x-z plane into one tile
 * by its symmetries and gives 0 at the tile's centre rising to 1 at its edge; a tiling of k kinds
 * of tile puts kind i in [i/k, (i+1)/k]. Written from POV-Ray's constructions: ---------------- */

#define TILE_S3 1.7320508075688772935 /* sqrt 3 */
#define TILE_H3 0.86602540378443864676 /* sqrt 3 / 2 */

/* v modulo m into [0, m). */
static double mod_floor(double v, double m) { return v - m * floor(v / m); }

/* Squares of side 1 on the integer grid: the larger of the two axes' distances from the centre. */
static double tiling_square(dvec3 p)
{
	double x = fabs(p.x), z = fabs(p.z);
	x = 2.0 * fabs(x - floor(x) - 0.5), z = 2.0 * fabs(z - floor(z) - 0.5);
	return fmax(x, z);
}

/* Hexagons of side 1: the 3 x sqrt 3 cell folded by its mirrors to the triangle between a
 * hexagon's centre and an edge, where the two distances to the edges are linear. */
static double tiling_hexagon(dvec3 p)
{
	double x = mod_floor(p.x + 0.5, 3.0), z = mod_floor(p.z, TILE_S3);
	if (z > TILE_H3)
		z = TILE_S3 - z;
	if (x > 1.5)
		x -= 1.5, z = TILE_H3 - z;
	if (TILE_S3 * x + z < TILE_H3)
		x = 0.5 - x, z = TILE_H3 - z;
	if (x > 1.0)
		x = 2.0 - x;
	double d = fmax(1.0 - z / TILE_H3, 1.0 - (TILE_S3 * x + z - TILE_H3) / TILE_S3);
	return clamp01(d);
}

/* Equilateral triangles of side 1, two kinds (pointing up and down: 0 and 1/2). */
static double tiling_triangle(dvec3 p)
{
	double x = p.x - floor(p.x), z = mod_floor(p.z, TILE_S3);
	int kind = 0;
	if (z > TILE_H3)
		z = TILE_S3 - z, kind ^= 1;
	if (x > 0.5)
		x = 1.0 - x;
	if (x == 0.0) /* POV-Ray's own branch on the cell's edge: a mirror, no change of kind */
		z = TILE_H3 - z, x = 0.5;
	else if (z / x > TILE_S3)
		z = TILE_H3 - z, x = 0.5 - x, kind ^= 1;
	double d = fmax(1.0 - z * 2.0 * TILE_S3, 1.0 - (TILE_S3 * x - z) * TILE_S3);
	return kind / 2.0 + 0.5 * d;
}

/* The lozenge fold shared by tilings 4 and 5: (x, z) in a half cell to the distance to the
 * lozenge's edges. */
static double lozenge_fold(double x, double z)
{
	if (2.0 * z > TILE_H3)
		z = TILE_H3 - z, x = 1.5 - x;
	if (x > 0.75)
		x -= 1.0;
	if (x != 0.0 && z / x > TILE_S3)
		z = TILE_H3 - z, x = 0.5 - x;
	return fmax(1.0 - z * 4.0 * TILE_S3 / 3.0, 1.0 - fabs(TILE_S3 * x - z) * TILE_S3 * 2.0 / 3.0);
}

/* Lozenges (rhombi of 60 degrees), one kind. */
static double tiling_lozenge(dvec3 p)
{
	double x = p.x - floor(p.x), z = mod_floor(p.z, TILE_S3);
	if (z > TILE_H3)
		z -= TILE_H3, x += 0.5;
	return lozenge_fold(x, z);
}

/* Rhombi in three orientations (kinds 0, 1/3, 2/3): the cube pattern seen from a corner. */
static double tiling_rhombus(dvec3 p)
{
	double x = mod_floor(p.x + 0.5, 3.0), z = mod_floor(p.z, TILE_S3);
	int kind = 0;
	if (z > TILE_H3)
		z = TILE_S3 - z, kind = 2 - kind;
	if (x > 1.5)
		x -= 1.5, z = TILE_H3 - z, kind = 2 - kind;
	if (x < 0.5)
		x = 1.0 - x, kind = 2 - kind;
	x -= 0.5;
	if (x == 0.0 || z / x > TILE_S3) { /* the upright rhombus turned by 60 degrees onto the others */
		double rx = x / 2.0 + z * TILE_H3, rz = z / 2.0 - x * TILE_H3;
		x = rx, z = rz, kind = 1;
	}
	return clamp01(lozenge_fold(x, z) / 3.0 + kind / 3.0);
}

/* Rectangles of 2 x 1 in a basket weave of 4 x 4, two kinds (along x: 1/2 and up; along z: 0):
 * each unit square of the cell is moved to its rectangle's frame. */
static double tiling_rectangle(dvec3 p)
{
	double x = mod_floor(p.x, 4.0), z = mod_floor(p.z, 4.0);
	/* per unit square (x + 4 z): its shift in x and z, and whether its rectangle lies along x */
	static const signed char shift[16][3] = {
		{0, 1, 1}, {2, 0, 0}, {2, 0, 0}, {3, 0, 1}, {0, 1, 1}, {1, 2, 1}, {3, 1, 0}, {3, 1, 0},
		{0, 2, 0}, {1, 2, 1}, {2, 3, 1}, {4, 2, 0}, {1, 3, 0}, {1, 3, 0}, {2, 3, 1}, {3, 4, 1}};
	int cell = (int)x + 4 * (int)z;
	cell = cell < 0 ? 0 : cell > 15 ? 15 : cell;
	x -= shift[cell][0], z -= shift[cell][1];
	bool along_x = shift[cell][2];
	double dx, dz;
	if (along_x)
		dx = 2.0 * fabs(x - 0.5), dz = 2.0 * (fmax(fabs(z), 0.5) - 0.5);
	else
		dx = 2.0 * (fmax(fabs(x), 0.5) - 0.5), dz = 2.0 * fabs(z - 0.5);
	return fabs(fmax(dx, dz) / 2.0 + (along_x ? 0.5 : 0.0));
}

#define TILE_R2 1.4142135623730950488 /* sqrt 2 */
#define TILE_H2 0.70710678118654752440 /* sqrt 2 / 2 */

/* Octagons and squares (7): a cell of 1 + sqrt 2 folded onto its eighth; the square (kind 0, up
 * to 1/2) where |x| + |z| < sqrt 2 / 2 about the cell's corner, the octagon (above 1/2) else. */
static double tiling_octa_square(dvec3 p)
{
	const double cell = TILE_R2 + 1.0, mid = TILE_H2 + 0.5;
	double x = fabs(mod_floor(p.x, cell) - mid), z = fabs(mod_floor(p.z, cell) - mid);
	if (z > x) {
		double t = x;
		x = z, z = t;
	}
	if (x + z < TILE_H2)
		return (x + z) / TILE_R2;
	return fmax(0.500000000001, fmax(1.0 - z, (TILE_R2 + TILE_H2 - (x + z)) / TILE_R2)); /* POV-Ray's floor */
}

/* Squares and triangles in rows (8): a square row of height 1 and a triangle row of height
 * sqrt 3 / 2, shifted by half a square; squares one kind (2/3 up), triangles two (0 and 1/3). */
static double tiling_square_triangle(dvec3 p)
{
	double x = p.x - floor(p.x), z = mod_floor(p.z, 2.0 + TILE_S3);
	int kind = 0;
	if (z > TILE_H3 + 1.0)
		z -= TILE_H3 + 1.0, x += x > 0.5 ? -0.5 : 0.5;
	if (x > 0.5)
		x = 1.0 - x;
	z -= 1.0;
	if (z > 0.0) { /* a triangle */
		if (x == 0.0)
			z = TILE_H3 - z, x = 0.5, kind ^= 1;
		else if (z / x > TILE_S3)
			z = TILE_H3 - z, x = 0.5 - x, kind ^= 1;
		return (kind + fmax(1.0 - 2.0 * z * TILE_S3, 1.0 - (TILE_S3 * x - z) * TILE_S3)) / 3.0;
	}
	if (z < -0.5) /* a square */
		z = -1.0 - z;
	if (x > 0.5)
		x = 1.0 - x;
	double d1 = fmin(2.0 + 2.0 * TILE_S3 * fabs(x), 3.0), d2 = fmin(2.0 + 2.0 * TILE_S3 * fabs(z), 3.0);
	return (5.0000001 - fmin(d1, d2)) / 3.0; /* POV-Ray's constant */
}

/* Hexagons and triangles (9, the trihexagonal tiling): triangles two kinds (0, 1/3), hexagons
 * above 2/3. */
static double tiling_hexa_triangle(dvec3 p)
{
	double x = mod_floor(p.x + 0.5, 2.0), z = mod_floor(p.z, 2.0 * TILE_S3);
	int kind = 0;
	if (z > TILE_S3)
		z -= TILE_S3, x += x < 1.0 ? 1.0 : -1.0;
	if (z > TILE_H3)
		z = TILE_S3 - z, kind ^= 1;
	if (x > 1.0)
		x = 2.0 - x;
	if (TILE_S3 * x + z < TILE_H3) /* a triangle */
		return (kind + fmax(1.0 - z * 2.0 * TILE_S3, 1.0 + (TILE_S3 * x + z - TILE_H3) * TILE_S3)) / 3.0;
	double d = 5.0 - fmin(2.0 + 2.0 * z * TILE_S3, 2.0 + 2.0 * (TILE_S3 * x + z - TILE_H3) * TILE_H3);
	return fmax(d, 2.0000001) / 3.0; /* POV-Ray's floor */
}

/* Squares in rows offset by half a square (10). */
static double tiling_square_offset(dvec3 p)
{
	double z = mod_floor(p.z, 2.0), x = p.x;
	if (z > 1.0)
		x += 0.5, z -= 1.0;
	x -= floor(x);
	return fmax(2.0 * fabs(x - 0.5), 2.0 * fabs(z - 0.5));
}

/* The pinwheel of a square and four 2 x 1 rectangles in a 3 x 3 cell, shared by tilings 11 and
 * 12: the unit square (ix, iz) of the cell moved to its tile's frame; the square is kind 0, the
 * rectangles along z kind 1, along x kind 2. */
static double pinwheel(double x, double z)
{
	int kind = 2;
	switch ((int)x + 3 * (int)z) {
	case 0:
	case 3: z -= 1.0; break;
	case 1:
	case 2: x -= 2.0, kind = 1; break;
	case 4: x -= 1.0, z -= 1.0, kind = 0; break;
	case 5:
	case 8: x -= 2.0, z -= 2.0; break;
	case 6:
	case 7: x -= 1.0, z -= 2.0, kind = 1; break;
	default: break; /* the cell's far edge (tiling 12's |x| = 3): as POV-Ray, unmoved */
	}
	double dx = kind == 1 ? 2.0 * (fmax(fabs(x), 0.5) - 0.5) : 2.0 * fabs(x - 0.5);
	double dz = kind == 2 ? 2.0 * (fmax(fabs(z), 0.5) - 0.5) : 2.0 * fabs(z - 0.5);
	return (fmax(dx, dz) + kind) / 3.0;
}

/* A square ringed by four rectangles turning one way (11), or both ways (12: a 6 x 6 cell folded
 * in four about its centre). */
static double tiling_square_rectangle(dvec3 p) { return pinwheel(mod_floor(p.x, 3.0), mod_floor(p.z, 3.0)); }

static double tiling_rectangle_square(dvec3 p)
{
	return pinwheel(fabs(mod_floor(p.x, 6.0) - 3.0), fabs(mod_floor(p.z, 6.0) - 3.0));
}

/* Squares cut by their diagonals into an inner square and four triangles, on a grid turned by
 * 45 degrees (13: three kinds; 14: the four triangles each a kind of its own, five in all): the
 * cell of 4 / sqrt 2 folded about its centre. */
static double tiling_square_internal(dvec3 p, bool five)
{
	double x = mod_floor(p.x * TILE_R2, 4.0) - 2.0, z = mod_floor(p.z * TILE_R2, 4.0) - 2.0;
	int mir_x = x < 0.0 ? 1 : 0, mir_z = z < 0.0 ? 2 : 3;
	x = fabs(x), z = fabs(z);
	double d;
	int base;
	switch ((int)x + 2 * (int)z) {
	case 0: /* the inner square */
		d = fmax(2.0 * fmax(x - 0.5, 0.0), 2.0 * fmax(z - 0.5, 0.0));
		return five ? (4.000001 + d) / 5.0 : d / 3.0; /* POV-Ray's constant */
	case 1:
		d = fabs(1.5 - x) * 2.0;
		if (z > 0.5)
			d = fmax(d, 1.0 - TILE_R2 * fabs(x - z));
		base = five ? mir_x : 2;
		break;
	case 2:
		d = fabs(1.5 - z) * 2.0;
		if (x > 0.5)
			d = fmax(d, 1.0 - TILE_R2 * fabs(x - z));
		base = five ? mir_z : 1;
		break;
	case 3:
		if (x > z)
			d = fmax(fabs(1.5 - x) * 2.0, 1.0 - TILE_R2 * fabs(z - x)), base = five ? mir_x : 2;
		else
			d = fmax(fabs(1.5 - z) * 2.0, 1.0 - TILE_R2 * fabs(x - z)), base = five ? mir_z : 1;
		break;
	default: return 0.0; /* the cell's far edge: POV-Ray's 0 */
	}
	return (base + d) / (five ? 5.0 : 3.0);
}

/* Squares of side 1 and 2 (15) in a 5 x 5 cell: each unit square moved to its square's frame. */
static double tiling_square_double(dvec3 p)
{
	/* per unit square (x + 5 z): its shift in x and z, and whether it is a small square */
	static const signed char shift[25][3] = {
		{0, 0, 1}, {2, 0, 0}, {2, 0, 0}, {4, 1, 0}, {4, 1, 0}, {1, 2, 0}, {1, 2, 0}, {2, 1, 1}, {4, 1, 0},
		{4, 1, 0}, {1, 2, 0}, {1, 2, 0}, {3, 3, 0}, {3, 3, 0}, {4, 2, 1}, {0, 4, 0}, {1, 3, 1}, {3, 3, 0},
		{3, 3, 0}, {5, 4, 0}, {0, 4, 0}, {2, 5, 0}, {2, 5, 0}, {3, 4, 1}, {5, 4, 0}};
	double x = mod_floor(p.x, 5.0), z = mod_floor(p.z, 5.0);
	int cell = (int)x + 5 * (int)z;
	cell = cell < 0 ? 0 : cell > 24 ? 24 : cell;
	x -= shift[cell][0], z -= shift[cell][1];
	if (shift[cell][2])
		return fabs(fmax(2.0 * fabs(x - 0.5), 2.0 * fabs(z - 0.5)) / 2.0);
	double dx = 2.0 * (fmax(fabs(x), 0.5) - 0.5), dz = 2.0 * (fmax(fabs(z), 0.5) - 0.5);
	return fabs(fmax(dx, dz) / 2.0 + 0.50000001); /* POV-Ray's constant */
}

/* Hexagons, squares and triangles (16, the rhombitrihexagonal tiling: three kinds; 17: each
 * square and triangle of its own orientation, six kinds). The cell of (3 + sqrt 3) x 2 (1 + sqrt 3)
 * is folded to a quarter about a hexagon's centre; the part below the hexagon's edge turned by
 * 60 degrees onto the square and the triangle beside it. */
static double tiling_hexa_square_triangle(dvec3 p, bool six)
{
	const double half = TILE_H3 + 1.5, ring = TILE_S3 + 1.0;
	double x = mod_floor(p.x + 0.5, 3.0 + TILE_S3), z = mod_floor(p.z, 2.0 * ring);
	int mir_x = 0, mir_z = 0, rota = 0;
	if (x > half)
		x -= half, z += z < ring ? TILE_H3 + 0.5 : -(TILE_H3 + 0.5);
	if (z > ring)
		z -= ring;
	if (z > 0.5 + TILE_H3)
		z = ring - z, mir_z ^= 1;
	if (x > 1.0 + TILE_H3)
		x = TILE_S3 + 2.0 - x, mir_x ^= 1;
	if (TILE_S3 * x + z < TILE_H3 + 2.0 && x < 0.5 + TILE_H3) { /* turn the lower part by 60 degrees */
		double rz = z - (0.5 + TILE_H3), rx = x - (1.0 + TILE_H3);
		x = rx / 2.0 - rz * TILE_H3 + 1.0 + TILE_H3;
		z = rz / 2.0 + rx * TILE_H3 + 0.5 + TILE_H3;
		rota ^= 1;
		if (z < 0.0)
			z = -z;
		if (x > 1.0 + TILE_H3)
			x = TILE_S3 + 2.0 - x, mir_x ^= 1, mir_z ^= 1;
	}
	if (!(TILE_S3 * x + z < TILE_H3 + 2.0) && !(z < 0.5)) { /* the hexagon */
		double hz = fabs(z - 0.5), hx = fabs(x - TILE_H3);
		double d = fmin(2.0 * hz * TILE_S3, (TILE_S3 * hx + hz) * TILE_S3 - 1.5);
		return six ? fmax(6.0 - d, 5.000001) / 6.0 : fmax(3.0 - d, 2.0000001) / 3.0; /* POV-Ray's floors */
	}
	if (!(z < 0.5))
		return 0.0;
	if (x > TILE_H3 + 0.5) { /* a square */
		double sx = x - (TILE_H3 + 0.5), sz = z - 0.5;
		double d = fmax(fmax(1.0 + sz * 2.0 * TILE_S3, 0.0), fmax(1.0 - sx * 2.0 * TILE_S3, 0.0));
		return six ? (d + rota * (1.000001 + ((mir_x + mir_z) % 2))) / 6.0 : d / 3.0;
	}
	double tx = fabs(x - (TILE_H3 + 0.5)); /* a triangle */
	double d = fmax(2.0 - tx * 2.0 * TILE_S3, (TILE_S3 * z + tx) * TILE_S3 + 0.5);
	return six ? (((rota + mir_x) % 2 ? 2.0 : 3.0) + d) / 6.0 : d / 3.0;
}

/* Pairs of 2 x 1 rectangles (18) in a 4 x 4 cell, two kinds (along x: 1/2 and up; along z: 0). */
static double tiling_rectangle_pair(dvec3 p)
{
	static const signed char shift[16][3] = {
		{0, 1, 1}, {1, 1, 1}, {3, 0, 0}, {3, 0, 0}, {0, 1, 1}, {1, 1, 1}, {3, 1, 0}, {3, 1, 0},
		{1, 2, 0}, {1, 2, 0}, {2, 3, 1}, {3, 3, 1}, {1, 3, 0}, {1, 3, 0}, {2, 3, 1}, {3, 3, 1}};
	double x = mod_floor(p.x, 4.0), z = mod_floor(p.z, 4.0);
	int cell = (int)x + 4 * (int)z;
	cell = cell < 0 ? 0 : cell > 15 ? 15 : cell;
	x -= shift[cell][0], z -= shift[cell][1];
	bool along_x = shift[cell][2];
	double dx, dz;
	if (along_x)
		dx = 2.0 * fabs(x - 0.5), dz = 2.0 * (fmax(fabs(z), 0.5) - 0.5);
	else
		dx = 2.0 * (fmax(fabs(x), 0.5) - 0.5), dz = 2.0 * fabs(z - 0.5);
	return fabs((fmax(dx, dz) + (along_x ? 1.0 : 0.0)) / 2.0);
}

/* The triangle fold of tilings 19 and 20: (x, z) in a cell of triangles to POV-Ray's triangle
 * value with kind `kind` (0 or 1) carried in. */
static double triangle_fold(double x, double z, int kind)
{
	x -= floor(x), z = mod_floor(z, TILE_S3);
	if (z > TILE_H3)
		z = TILE_S3 - z, kind ^= 1;
	if (x > 0.5)
		x = 1.0 - x;
	if (x == 0.0)
		z = TILE_H3 - z, x = 0.5, kind ^= 1;
	else if (z / x > TILE_S3)
		z = TILE_H3 - z, x = 0.5 - x, kind ^= 1;
	return (kind + fmax(1.0 - z * 2.0 * TILE_S3, 1.0 - (TILE_S3 * x - z) * TILE_S3)) / 3.0;
}

/* Hexagons among triangles, the rows shifted to the right (19) or to the left (20), the snub
 * hexagonal tiling's two hands: triangles two kinds (0, 1/3), hexagons above 2/3. */
static double tiling_hexa_tri(dvec3 p, bool right)
{
	double x = p.x, z = p.z;
	int rows = (int)fmax(-2.0e9, fmin(2.0e9, z / TILE_H3)) / 3; /* POV-Ray's integer steps, truncated to 0 */
	if (z < 0.0)
		rows -= 1;
	x += right ? rows / 2.0 : -rows / 2.0;
	z = mod_floor(z, 3.0 * TILE_H3);
	x = mod_floor(x + 7.0, 7.0);
	if (right) {
		if (x > 4.5 && z > TILE_S3)
			x -= 4.5, z -= TILE_H3;
		if (x > 5.0 && z < TILE_H3)
			x -= 5.0, z += TILE_S3;
		if (x > 2.5 && z < TILE_S3)
			x -= 2.5, z += TILE_H3;
	} else {
		if (x > 2.0 && z < TILE_H3)
			x -= 2.0, z += TILE_S3;
		if (x > 4.5 && z < TILE_S3)
			x -= 4.5, z += TILE_H3;
		if (x > 2.5 && z > TILE_S3)
			x -= 2.5, z -= TILE_H3;
	}
	int kind = 0, row = (int)(z / TILE_H3);
	if (row == 2)
		row = 1, z = 2.0 * TILE_S3 - z, kind ^= 1;
	if (!row || x > 2.0 || z + TILE_S3 * x < TILE_S3 || TILE_S3 * x - z > TILE_S3)
		return triangle_fold(x, z, kind);
	z -= TILE_H3; /* the hexagon */
	if (x > 1.0)
		x = 2.0 - x;
	double d = 5.0 - fmin(2.0 + 2.0 * z * TILE_S3, 2.0 + 2.0 * (TILE_S3 * x + z - TILE_H3) * TILE_H3);
	return fmax(d, 2.000001) / 3.0; /* POV-Ray's floor */
}

/* Squares and triangles (21, the snub square tiling): a (1 + sqrt 3)^2 cell folded to a quarter
 * and turned onto one square's corner; four kinds of triangle (0 to 4/6), two of square (4/6 up). */
static double tiling_square_tri(dvec3 p)
{
	const double cell = 1.0 + TILE_S3, half = 0.5 + TILE_H3;
	double x = mod_floor(p.x, cell), z = mod_floor(p.z, cell);
	int delta = 0, gamma = 0, beta = 0;
	if (z > half)
		z = cell - z, delta ^= 1;
	if (x > half)
		x = cell - x, delta ^= 1, beta = 1;
	int xflop = 2.0 * x + (TILE_S3 - 1.0) * 2.0 * z / (TILE_S3 + 1.0) > TILE_S3;
	int zflop = 2.0 * z * TILE_S3 + (TILE_S3 - 3.0) * 2.0 * x / (TILE_S3 + 1.0) > TILE_S3;
	double t;
	switch (xflop + 2 * zflop) {
	case 0: gamma = 2 * beta; break;
	case 1: /* turned clockwise */
		gamma = beta ? 1 + 2 * delta : 3 - 2 * delta;
		t = x, x = z, z = half - t;
		break;
	case 2: /* turned the other way */
		gamma = beta ? 3 - 2 * delta : 1 + 2 * delta;
		t = z, z = x, x = half - t;
		break;
	default: /* mirrored through the corner */
		gamma = beta ? 0 : 2;
		x = half - x, z = half - z;
		break;
	}
	if (x == 0.0)
		z = 0.0;
	double s = z * 2.0 * TILE_S3 - TILE_S3 + x * 2.0;
	if (s < 0.0) /* a triangle */
		return (gamma + 1.0 - fmin(-1.5 / TILE_S3 * s, 2.0 * x * TILE_S3)) / 6.0;
	s = fmin(s * 1.5 / TILE_S3, 1.0); /* a square */
	if (delta)
		return fmin(fmax((6.0 - s) / 6.0, 5.000001 / 6.0), 1.0); /* POV-Ray's constants */
	return fmax(fmin((5.0 - s) / 6.0, 5.0 / 6.0), 4.000001 / 6.0);
}

/* Dodecagons and triangles (22, the truncated hexagonal tiling): the cell folded to a twelfth
 * of a dodecagon, a point beyond its slanted edge turned by 120 degrees; triangles two kinds (up
 * to 1/3, 1/3 to 2/3), dodecagons above 2/3. */
static double tiling_dodeca_tri(dvec3 p)
{
	const double wing = 1.0 + TILE_H3;
	double x = mod_floor(p.x, 2.0 + TILE_S3), z = mod_floor(p.z, 3.0 + 2.0 * TILE_S3);
	int toggle = 0;
	if (z > TILE_S3 + 1.5)
		z -= TILE_S3 + 1.5, x += (x < wing ? 1.0 : -1.0) * wing;
	if (x > wing)
		x = 2.0 + TILE_S3 - x;
	if (z > wing)
		z = 2.0 + TILE_S3 - z, toggle ^= 1;
	double d2 = x - TILE_H3 - 0.5 + z * TILE_S3;
	if (d2 < 0.0) {
		double tx = x, tz = z;
		x = (1.0 + TILE_S3) / 4.0 + 0.5 * tx - TILE_H3 * tz;
		z = (3.0 + TILE_S3) / 4.0 - TILE_H3 * tx - 0.5 * tz;
		d2 = -d2;
	}
	double d3 = (z - TILE_H3 - 0.5 + x * TILE_S3) * TILE_S3;
	if (d3 < 0.0)
		return (fmax(d3, -1.0) + 1.0 + toggle) / 3.0;
	double r = fmin(fmin(fmin(z * 3.0, d2 * TILE_S3), d3), fmin(x * 3.0, 1.0));
	return (3.0000001 - r) / 3.0; /* POV-Ray's constant */
}

/* Dodecagons, hexagons and squares (23, the truncated trihexagonal tiling: three kinds; 24: the
 * squares of its two orientations apart, five kinds): the cell folded to a twelfth of a
 * dodecagon and its neighbours. */
static double tiling_dodeca_hex(dvec3 p, bool five)
{
	const double wing = 1.5 + TILE_H3;
	double x = mod_floor(p.x, 3.0 + TILE_S3), z = mod_floor(p.z, 3.0 + 3.0 * TILE_S3);
	int mir_x = 0, mir_z = 0;
	if (z > 1.5 * TILE_S3 + 1.5)
		z -= 1.5 * TILE_S3 + 1.5, x += (x < wing ? 1.0 : -1.0) * wing;
	if (x > wing)
		x = 3.0 + TILE_S3 - x, mir_x ^= 1;
	if (z > 1.0 + TILE_S3)
		z = 2.0 + 2.0 * TILE_S3 - z, mir_z ^= 1;
	if (x - TILE_H3 - 1.5 + z * TILE_S3 < 0.0) {
		double tx = x, tz = z;
		x = (3.0 + TILE_S3) / 4.0 + 0.5 * tx - TILE_H3 * tz;
		z = (3.0 + 3.0 * TILE_S3) / 4.0 - TILE_H3 * tx - 0.5 * tz;
	}
	double d2 = x - TILE_H3 - 2.5 + z * TILE_S3, d1 = z * 2.0 - TILE_S3;
	double d3 = z - 1.5 * TILE_S3 - 0.5 + x * TILE_S3, d4 = (x - 0.5) * 2.0, r;
	if (d2 >= 0.0 && d1 >= 0.0 && d3 >= 0.0 && d4 >= 0.0) { /* the dodecagon */
		r = (five ? 5.000001 : 3.000001) - fmin(fmin(d1, d2), fmin(d3, fmin(d4, 1.0))); /* POV-Ray's */
	} else {
		double d5 = 2.0 * z - 2.0 * TILE_S3 - 1.0;
		if (d5 >= 0.0) {
			r = 2.0 - fmin(d5, -d4);
		} else {
			double d6 = TILE_S3 * x - z - TILE_H3 + 0.5, d7 = d6 - 2.0;
			switch ((d6 >= 0.0 ? 0 : 1) + (d7 >= 0.0 ? 2 : 0)) {
			case 1: r = 1.0 - fmin(fmin(-d6, -d3), fmin(-d5, 1.0)); break; /* the left hexagon */
			case 2: r = 1.0 - fmin(fmin(d7, -d1), 1.0); break;		 /* the bottom hexagon */
			default: /* a slanted square */
				r = (five ? (mir_z + mir_x) % 2 + 3.0 : 2.0) - fmin(fmin(d6, -d2), -d7);
				break;
			}
		}
	}
	return r / (five ? 5.0 : 3.0);
}

/* ---- the Penrose tilings P2 (26, kites and darts) and P3 (27, rhombi): the plane folded by the
 * decagon's symmetry, scaled down by phi^2 per step to the seed triangle, then subdivided back as
 * the half-kite and half-dart Robinson triangles deflate, POV-Ray's tiling_penrose. The distance
 * factors 5.55 and 4.46 are POV-Ray's own (its source calls them empirical). */

#define PEN_PHI 1.6180339887498948482
#define PEN_INVPHI 0.61803398874989484820
#define PEN_SQRPHI 2.6180339887498948482
#define PEN_INVSQRPHI 0.38196601125010515180
#define PEN_SIN18 0.30901699437494742410
#define PEN_SIN36 0.58778525229247312917
#define PEN_SIN54 0.80901699437494742410
#define PEN_SIN72 0.95105651629515357212
#define PEN_TAN72 3.0776835371752534026
#define PEN_TAN36 0.72654252800536088590
#define PEN_COS18 PEN_SIN72
#define PEN_COS36 PEN_SIN54
#define PEN_COS72 PEN_SIN18
#define PEN_SIN108 PEN_SIN72
#define PEN_COS108 (-PEN_SIN18)
#define PEN_SIN144 PEN_SIN36
#define PEN_COS144 (-PEN_SIN54)
#define PEN_TAN108 (-PEN_TAN72)
#define PEN_TAN144 (-PEN_TAN36)
#define PEN_EPS 1e-6 /* POV-Ray's TILING_EPSILON */

static double max3(double a, double b, double c) { return fmax(a, fmax(b, c)); }

static double penrose_halfdart(double x, double z, int depth, bool rhombs);

static double penrose_halfkite(double x, double z, int depth, bool rhombs)
{
	z = fabs(z);
	if (depth > 0) {
		if (z < (x - PEN_INVPHI) * PEN_TAN144)
			return penrose_halfdart(x * PEN_PHI, z * PEN_PHI, depth - 1, rhombs);
		x -= PEN_COS36, z -= PEN_SIN36;
		double rx = x * PEN_COS108 - z * PEN_SIN108, rz = z * PEN_COS108 + x * PEN_SIN108;
		return penrose_halfkite(rx * PEN_PHI, rz * PEN_PHI, depth - 1, rhombs);
	}
	if (rhombs) {
		if (z < (x - PEN_INVPHI) * PEN_TAN72) {
			double d1 = fabs(PEN_SIN72 * (x - PEN_INVPHI) - PEN_COS72 * z) * 5.55;
			double d2 = fabs(PEN_SIN108 * (x - 1.0) - PEN_COS108 * z) * 5.55;
			return max3(1.0 - d1 / 2.0, 1.0 - d2 / 2.0, 0.5 + PEN_EPS);
		}
		double d1 = fabs(z) * 5.55, d2 = fabs(PEN_SIN72 * (x - PEN_INVPHI) - PEN_COS72 * z) * 5.55;
		return fmin(max3(0.5 - d1 / 2.0, 0.5 - d2 / 2.0, 0.0), 0.5 - PEN_EPS);
	}
	double d1 = fabs(PEN_SIN36 * x - PEN_COS36 * z) * 4.46, d2 = fabs(PEN_SIN108 * (x - 1.0) - PEN_COS108 * z) * 4.46;
	return fmin(max3(0.5 - d1 / 2.0, 0.5 - d2 / 2.0, 0.0), 0.5 - PEN_EPS);
}

static double penrose_halfdart(double x, double z, int depth, bool rhombs)
{
	z = fabs(z);
	if (depth > 0) {
		if (z < (x - PEN_INVPHI) * PEN_TAN108) {
			double rx = x * PEN_COS36 + z * PEN_SIN36, rz = z * PEN_COS36 - x * PEN_SIN36;
			return penrose_halfkite(rx * PEN_PHI, rz * PEN_PHI, depth - 1, rhombs);
		}
		x -= 1.0;
		double rx = x * PEN_COS144 + z * PEN_SIN144, rz = z * PEN_COS144 - x * PEN_SIN144;
		return penrose_halfdart(rx * PEN_PHI, rz * PEN_PHI, depth - 1, rhombs);
	}
	if (rhombs) {
		double d1 = fabs(PEN_SIN36 * x - PEN_COS36 * z) * 5.55, d2 = fabs(PEN_SIN144 * (x - 1.0) - PEN_COS144 * z) * 5.55;
		return fmin(max3(0.5 - d1 / 2.0, 0.5 - d2 / 2.0, 0.0), 0.5 - PEN_EPS);
	}
	double d1 = fabs(z) * 4.46, d2 = fabs(PEN_SIN144 * (x - 1.0) - PEN_COS144 * z) * 4.46;
	return max3(1.0 - d1 / 2.0, 1.0 - d2 / 2.0, 0.5 + PEN_EPS);
}

/* The decagon's fold and the depth of subdivision the point's distance needs (POV-Ray's
 * tiling_penrose with its centre flag off: five darts at the centre, or five wide rhombi). */
static double tiling_penrose(dvec3 p, bool rhombs)
{
	double x = p.x, z = p.z, r = sqrt(x * x + z * z);
	if (r <= 1e-10) /* POV-Ray's EPSILON */
		return 1.0;
	z = fabs(z);
	if (x < r * PEN_COS36) {
		double rs = x < r * PEN_COS108 ? PEN_SIN144 : PEN_SIN72, rc = x < r * PEN_COS108 ? PEN_COS144 : PEN_COS72;
		double rx = x * rc + z * rs, rz = z * rc - x * rs;
		x = rx, z = fabs(rz);
	}
	if (rhombs)
		x *= PEN_INVPHI, z *= PEN_INVPHI;
	double dist = fabs(PEN_SIN108 * x - PEN_COS108 * z) / PEN_COS18;
	double steps = ceil(log(dist) / log(PEN_SQRPHI));
	int depth = steps > 0.0 ? (int)fmin(steps, 1000.0) : 0; /* bounded: a point 10^400 away never comes */
	x *= pow(PEN_INVSQRPHI, depth), z *= pow(PEN_INVSQRPHI, depth);
	if (depth % 2) {
		double rx = x * PEN_COS36 + z * PEN_SIN36, rz = z * PEN_COS36 - x * PEN_SIN36;
		x = rx, z = fabs(rz);
	}
	return penrose_halfkite(x, z, 2 * depth, rhombs);
}

/* Penrose's P1 tiling (25: pentagons of three kinds, stars, boats and diamonds, 0 to 1 in sixths),
 * POV-Ray's tiling_penrose1 with a pentagon at the centre: the plane folded by the pentagon's
 * symmetry, scaled down by phi^4 per step, then subdivided back through the six tiles'
 * deflations. The distance factor 5.55 / phi is POV-Ray's. */
#define PEN_TAN18 0.32491969623290632616
#define PEN_TAN54 1.3763819204711735382
#define PEN_SIN162 PEN_SIN18
#define PEN_COS162 (-PEN_SIN72)
#define PEN_TAN162 (-PEN_TAN18)
#define PEN_TAN126 (-PEN_TAN54)
#define P1_SCALE (5.55 * PEN_INVPHI)

/* The pentagon's tenfold fold of (x, z) about the origin (r its distance). */
static void p1_fold(double *x, double *z, double r)
{
	*z = fabs(*z);
	if (*x < r * PEN_COS36) {
		double rs = *x < r * PEN_COS108 ? PEN_SIN144 : PEN_SIN72, rc = *x < r * PEN_COS108 ? PEN_COS144 : PEN_COS72;
		double rx = *x * rc + *z * rs, rz = *z * rc - *x * rs;
		*x = rx, *z = fabs(rz);
	}
}

static double p1_pentagon_dist(double x) { return fabs(x - 0.5 / PEN_TAN36) * P1_SCALE; }

/* A tile's leaf value: kind k of six (k/6 up to (k+1)/6) from the distance d to its edge. */
static double p1_leaf(int k, double d)
{
	return fmin(fmax((k + 1.0) / 6.0 - d / 6.0, k ? k / 6.0 + PEN_EPS : 0.0), (k + 1.0) / 6.0 - PEN_EPS);
}

static double p1_pentagon2(double x, double z, int depth, bool inside_quad);
static double p1_pentagon3(double x, double z, int depth, bool inside_wedge);
static double p1_star(double x, double z, int depth);
static double p1_boat(double x, double z, int depth, bool inside_wedge);
static double p1_diamond(double x, double z, int depth, bool side_a);

static double p1_pentagon1(double x, double z, int depth)
{
	z = fabs(z);
	p1_fold(&x, &z, sqrt(x * x + z * z));
	if (depth <= 0)
		return p1_leaf(0, p1_pentagon_dist(x));
	if (z < (x - 0.5 / PEN_TAN36) * PEN_TAN54 + 0.5)
		return p1_pentagon2((x - 0.5 / PEN_TAN36 - PEN_INVPHI * 0.5 * PEN_COS72 / PEN_SIN36) * PEN_PHI, z * PEN_PHI,
				    depth - 1, false);
	double rx = x * PEN_COS36 + z * PEN_SIN36, rz = z * PEN_COS36 - x * PEN_SIN36;
	return p1_star(rx * PEN_PHI, rz * PEN_PHI, depth - 1);
}

static double p1_pentagon2(double x, double z, int depth, bool inside_quad)
{
	z = fabs(z);
	if (depth <= 0) {
		p1_fold(&x, &z, sqrt(x * x + z * z));
		return p1_leaf(1, p1_pentagon_dist(x));
	}
	if (inside_quad) {
		if (z < (x - PEN_INVSQRPHI * 0.5 / PEN_SIN36) * PEN_TAN54)
			return p1_pentagon1((x - 0.5 / PEN_SIN36) * PEN_PHI, z * PEN_PHI, depth - 1);
		if (z < (x - PEN_INVSQRPHI * 0.5 / PEN_SIN36) * PEN_TAN162)
			return p1_diamond(-x * PEN_PHI, z * PEN_PHI, depth - 1, true);
		double rx = x * PEN_COS108 - z * PEN_SIN108 + PEN_INVPHI * 0.5 / PEN_SIN36, rz = z * PEN_COS108 + x * PEN_SIN108;
		return p1_pentagon2(rx * PEN_PHI, rz * PEN_PHI, depth - 1, true);
	}
	if (z < (x + 0.5 / PEN_SIN36) * PEN_TAN18)
		return p1_diamond((x + 0.5 / PEN_SIN36 - PEN_INVSQRPHI * 0.5 / PEN_SIN36) * PEN_PHI, z * PEN_PHI, depth - 1, false);
	double rx = -(x * PEN_COS36 + z * PEN_SIN36) - PEN_COS72 * 0.5 / PEN_SIN36;
	double rz = (z * PEN_COS36 - x * PEN_SIN36) - PEN_SIN72 * 0.5 / PEN_SIN36;
	return p1_pentagon3(rx * PEN_PHI, rz * PEN_PHI, depth - 1, false);
}

static double p1_pentagon3(double x, double z, int depth, bool inside_wedge)
{
	z = fabs(z);
	if (depth <= 0) {
		p1_fold(&x, &z, sqrt(x * x + z * z));
		return p1_leaf(2, p1_pentagon_dist(x));
	}
	if (inside_wedge && x > PEN_INVSQRPHI * 0.5 * PEN_COS72 / PEN_SIN36)
		return p1_pentagon2(-(x - PEN_INVSQRPHI * 0.5 * PEN_COS72 / PEN_SIN36 - PEN_INVPHI * 0.5 / PEN_TAN36) * PEN_PHI,
				    z * PEN_PHI, depth - 1, true);
	if (!inside_wedge && x < 0.5 * PEN_COS108 / PEN_SIN36) {
		double rx = x * PEN_COS144 + z * PEN_SIN144 - 0.5 / PEN_SIN36, rz = z * PEN_COS144 - x * PEN_SIN144;
		return p1_pentagon2(rx * PEN_PHI, rz * PEN_PHI, depth - 1, false);
	}
	if (!inside_wedge && z > (x - PEN_INVSQRPHI * 0.5 / PEN_SIN36) * PEN_TAN126) {
		double rx = -(x * PEN_COS36 - z * PEN_SIN36) - PEN_COS72 * 0.5 / PEN_SIN36;
		double rz = (z * PEN_COS36 + x * PEN_SIN36) - PEN_SIN72 * 0.5 / PEN_SIN36;
		return p1_pentagon3(rx * PEN_PHI, rz * PEN_PHI, depth - 1, false);
	}
	return p1_boat(x * PEN_PHI, z * PEN_PHI, depth - 1, inside_wedge);
}

static double p1_star(double x, double z, int depth)
{
	z = fabs(z);
	if (depth <= 0)
		return p1_leaf(3, fabs(PEN_SIN162 * (x - PEN_PHI * 0.5 / PEN_SIN36) - PEN_COS162 * z) * P1_SCALE);
	if (x < PEN_INVPHI * 0.5 / PEN_TAN36)
		return p1_pentagon1(x * PEN_PHI, z * PEN_PHI, depth - 1);
	return p1_pentagon3(-(x - PEN_INVPHI / PEN_TAN36) * PEN_PHI, z * PEN_PHI, depth - 1, true);
}

static double p1_boat(double x, double z, int depth, bool inside_wedge)
{
	z = fabs(z);
	if (depth <= 0) {
		double d1 = fabs(x - PEN_INVPHI * 0.5 * PEN_COS72 / PEN_SIN36) * P1_SCALE;
		x = -x;
		p1_fold(&x, &z, sqrt(x * x + z * z));
		double d2 = fabs(PEN_SIN162 * (x - PEN_PHI * 0.5 / PEN_SIN36) - PEN_COS162 * z) * P1_SCALE;
		return fmin(max3(5.0 / 6.0 - d1 / 6.0, 5.0 / 6.0 - d2 / 6.0, 4.0 / 6.0 + PEN_EPS), 5.0 / 6.0 - PEN_EPS);
	}
	if (inside_wedge && x > PEN_PHI * 0.5 * PEN_COS108 / PEN_SIN36)
		return p1_pentagon1(-x * PEN_PHI, z * PEN_PHI, depth - 1);
	double rx = x, rz = z;
	if (!inside_wedge)
		rx = x * PEN_COS72 - z * PEN_SIN72, rz = z * PEN_COS72 + x * PEN_SIN72;
	return p1_pentagon3((rx + 0.5 / PEN_SIN36) * PEN_PHI, rz * PEN_PHI, depth - 1, true);
}

static double p1_diamond(double x, double z, int depth, bool side_a)
{
	z = fabs(z);
	if (depth <= 0)
		return p1_leaf(5, fabs(PEN_SIN18 * (x + PEN_INVPHI * 0.5 / PEN_SIN36) - PEN_COS18 * z) * P1_SCALE);
	return side_a ? p1_pentagon1(x * PEN_PHI, z * PEN_PHI, depth - 1) : p1_pentagon3(x * PEN_PHI, z * PEN_PHI, depth - 1, true);
}

static double tiling_penrose1(dvec3 p)
{
	double x = p.x, z = p.z, r = sqrt(x * x + z * z);
	if (r <= 1e-10) /* POV-Ray's EPSILON */
		return 1.0;
	p1_fold(&x, &z, r);
	double steps = ceil(log(x * 2.0 * PEN_TAN36) / log(PEN_SQRPHI * PEN_SQRPHI));
	int depth = steps > 0.0 ? (int)fmin(steps, 500.0) : 0;
	double shrink = pow(PEN_INVSQRPHI * PEN_INVSQRPHI, depth);
	return p1_pentagon1(x * shrink, z * shrink, 4 * depth);
}

/* TilingPattern::EvaluateRaw's choice: POV-Ray's 27; 0 and its numbers past 27 are squares. */
static double tiling(int number, dvec3 p)
{
	switch (number) {
	case 7: return tiling_octa_square(p);
	case 8: return tiling_square_triangle(p);
	case 9: return tiling_hexa_triangle(p);
	case 10: return tiling_square_offset(p);
	case 11: return tiling_square_rectangle(p);
	case 12: return tiling_rectangle_square(p);
	case 13: return tiling_square_internal(p, false);
	case 14: return tiling_square_internal(p, true);
	case 15: return tiling_square_double(p);
	case 16: return tiling_hexa_square_triangle(p, false);
	case 17: return tiling_hexa_square_triangle(p, true);
	case 18: return tiling_rectangle_pair(p);
	case 19: return tiling_hexa_tri(p, true);
	case 20: return tiling_hexa_tri(p, false);
	case 21: return tiling_square_tri(p);
	case 22: return tiling_dodeca_tri(p);
	case 23: return tiling_dodeca_hex(p, false);
	case 24: return tiling_dodeca_hex(p, true);
	case 25: return tiling_penrose1(p);
	case 26: return tiling_penrose(p, false);
	case 27: return tiling_penrose(p, true);
	case 2: return tiling_hexagon(p);
	case 3: return tiling_triangle(p);
	case 4: return tiling_lozenge(p);
	case 5: return tiling_rhombus(p);
	case 6: return tiling_rectangle(p);
	default: return tiling_square(p);
	}
}

/* imageutil.cpp's material_map: the entry the image names at the mapped point: a palette image's
 * index (the nearest texel), another image's red times 255; past the entries' count n it wraps
 * (mod n), n itself being the last entry (POV-Ray's list walk); outside a once image, or no
 * image, the first. */
static double material_map(const pattern_node *n, dvec3 p)
{
	float c[4];
	pattern_node near = *n;
	near.interpolate = near.interpolate && !(n->img && n->img->indexed); /* an index is not blended */
	if (!image_texel(&near, p, c))
		return 0.0;
	double v = n->img->indexed ? c[0] : c[0] * 255.0;
	long k = v > 0.0 && v < 1e9 ? (long)v : 0, count = n->n_entries;
	if (count > 0 && k > count)
		k %= count;
	if (count > 0 && k >= count)
		k = count - 1;
	return (double)k;
}

/* POV-Ray 3.7.0's slope_pattern (pattern.cpp; SlopePattern::EvaluateRaw of later versions): the
 * angle between the surface's normal and the direction (or the direction to the point_at
 * point), asin(cos) mapped to [0, 1] (0 facing away, 0.5 across, 1 along), through the low and
 * width given; with an altitude, blended by the two weights with the point's projection on the
 * altitude's direction (through its low and width); wrapped into [0, 1) (1 itself just below).
 * The normal is the surface's in world space, not moved by the pattern's transforms (POV-Ray's
 * PNormal); the altitude sees the pattern's point. No surface (a function, a medium, a sky): 0. */
static double slope(const pattern_node *n, dvec3 p, const pattern_surface *sf)
{
	if (!sf)
		return 0.0;
	double v1;
	if (n->slope_point_at) {
		dvec3 d = d3_sub(n->slope_dir, sf->point);
		double len = d3_length(d);
		v1 = len > 0.0 ? d3_dot(sf->normal, d) / len : 0.0;
	} else {
		v1 = d3_dot(sf->normal, n->slope_dir);
	}
	v1 = v1 > 1.0 ? 1.0 : v1 < -1.0 ? -1.0 : v1;
	v1 = (asin(v1) / M_PI * 2.0 + 1.0) * 0.5;
	if (n->slope_width != 0.0)
		v1 = (v1 - n->slope_lo) / n->slope_width;
	if (n->altit_len == 0.0) {
		if (v1 == 1.0)
			return v1 - POV_EPSILON;
		return v1 < 0.0 ? 1.0 + fmod(v1, 1.0) : fmod(v1, 1.0);
	}
	double v2 = d3_dot(p, n->altit_dir);
	if (n->altit_width != 0.0)
		v2 = (v2 - n->altit_lo) / n->altit_width;
	double v = n->slope_len * v1 + n->altit_len * v2;
	if (v - 1.0 < POV_EPSILON && v >= 1.0)
		return v - POV_EPSILON;
	return v < 0.0 ? 1.0 + fmod(v, 1.0) : fmod(v, 1.0);
}

/* density_pattern's tricubic step (POV-Ray 3.7's intp3): Catmull-Rom between fb and fc. */
static double intp3(double t, double fa, double fb, double fc, double fd)
{
	double b = (fc - fa) * 0.5, d = (fd - fb) * 0.5;
	double e = 2.0 * (fb - fc) + b + d, f = -3.0 * (fb - fc) - 2.0 * b - d;
	return ((e * t + f) * t + b) * t + fb;
}

static uint32_t wrap_index(long long i, uint32_t n) { return (uint32_t)(((i % n) + n) % n); }

/* POV-Ray 3.7's density_pattern (pattern.cpp): the voxels fill the unit cube, 0 outside it;
 * interpolate 0 the voxel the point is in, 1 trilinear between it and its upper neighbours
 * (wrapping at the far faces), 2 tricubic (Catmull-Rom over 4 x 4 x 4 voxels, wrapping; POV-Ray
 * wraps an index -1 through an unsigned modulo, which it means as the last voxel: circe takes
 * the last voxel). Never below 0. */
static double density_file(const pattern_node *n, dvec3 p)
{
	const uint32_t sx = n->vox_n[0], sy = n->vox_n[1], sz = n->vox_n[2];
	if (!n->voxels || !sx || !sy || !sz || !(p.x >= 0.0 && p.x < 1.0 && p.y >= 0.0 && p.y < 1.0 && p.z >= 0.0 && p.z < 1.0))
		return 0.0;
#define VOX(x, y, z) ((double)n->voxels[((size_t)(z) * sy + (y)) * sx + (x)])
	double xx = p.x * sx, yy = p.y * sy, zz = p.z * sz, d;
	uint32_t x1 = (uint32_t)xx, y1 = (uint32_t)yy, z1 = (uint32_t)zz;
	x1 = x1 < sx ? x1 : sx - 1, y1 = y1 < sy ? y1 : sy - 1, z1 = z1 < sz ? z1 : sz - 1;
	switch (n->vox_interp % 10) {
	case 0: d = VOX(x1, y1, z1); break;
	case 1: {
		uint32_t x2 = (x1 + 1) % sx, y2 = (y1 + 1) % sy, z2 = (z1 + 1) % sz;
		xx -= floor(xx), yy -= floor(yy), zz -= floor(zz);
		double xi = 1.0 - xx, yi = 1.0 - yy;
		d = ((VOX(x1, y1, z1) * xi + VOX(x2, y1, z1) * xx) * yi + (VOX(x1, y2, z1) * xi + VOX(x2, y2, z1) * xx) * yy) *
			    (1.0 - zz) +
		    ((VOX(x1, y1, z2) * xi + VOX(x2, y1, z2) * xx) * yi + (VOX(x1, y2, z2) * xi + VOX(x2, y2, z2) * xx) * yy) * zz;
		break;
	}
	default: {
		xx -= floor(xx), yy -= floor(yy), zz -= floor(zz);
		uint32_t k[4];
		for (int i = 0; i < 4; i++)
			k[i] = wrap_index((long long)z1 + i - 1, sz);
		double in_y[4];
		for (int i = 0; i < 4; i++) {
			uint32_t ii = wrap_index((long long)x1 + i - 1, sx);
			double in_z[4];
			for (int j = 0; j < 4; j++) {
				uint32_t jj = wrap_index((long long)y1 + j - 1, sy);
				in_z[j] = intp3(zz, VOX(ii, jj, k[0]), VOX(ii, jj, k[1]), VOX(ii, jj, k[2]), VOX(ii, jj, k[3]));
			}
			in_y[i] = intp3(yy, in_z[0], in_z[1], in_z[2], in_z[3]);
		}
		d = intp3(xx, in_y[0], in_y[1], in_y[2], in_y[3]);
		break;
	}
	}
#undef VOX
	return d < 0.0 ? 0.0 : d;
}

/* pattern_raw with eps for POV-Ray's EPSILON: the nudge that puts a point on a cell's boundary on
 * the side POV-Ray puts it, grown to the point's own uncertainty (pattern_eval's tol). */
static void eval_depth(const pattern_prog *pg, uint32_t node, dvec3 p, const pattern_surface *sf, double eps, int depth,
		       float out[5]);

static double raw_eps(const pattern_prog *pg, const pattern_node *n, dvec3 p, const pattern_surface *sf, double eps)
{
	switch (n->kind) {
	case PATTERN_CHECKER: /* CheckerPattern::Evaluate */
		return (long long)(floor(p.x + eps) + floor(p.y + eps) + floor(p.z + eps)) & 1
			       ? 1.0
			       : 0.0;
	case PATTERN_HEXAGON: return hexagon(p);
	case PATTERN_BRICK: return brick(p, n->vector, n->mortar, eps);
	case PATTERN_BOZO:
	case PATTERN_SPOTTED:
	case PATTERN_BUMPS:
	case PATTERN_DENTS:
	case PATTERN_WRINKLES:
	case PATTERN_GRANITE:
	case PATTERN_AGATE: return raw_noisy(n, p);
	case PATTERN_FUNCTION: { /* FunctionPattern::EvaluateRaw: the function's value, mod 1 above 1 */
		double xyz[3] = {p.x, p.y, p.z}, v = 0.0;
		if (!n->fn.eval || !n->fn.eval(n->fn.ctx, xyz, &v) || !isfinite(v))
			return 0.0;
		return v > 1.0 ? fmod(v, 1.0) : v;
	}
	case PATTERN_SLOPE: return slope(n, p, sf);
	case PATTERN_DENSITY_FILE: return density_file(n, p);
	case PATTERN_IMAGE_PATTERN: return image_pattern(n, p);
	case PATTERN_TILING: return tiling(n->tiling, p);
	case PATTERN_MATERIAL_MAP: return material_map(n, p);
	case PATTERN_OBJECT: { /* ObjectPattern::Evaluate: Inside_Object, 1 inside */
		double xyz[3] = {p.x, p.y, p.z}, v = 0.0;
		return n->fn.eval && n->fn.eval(n->fn.ctx, xyz, &v) && v > 0.5 ? 1.0 : 0.0;
	}
	case PATTERN_PIGMENT_PATTERN: { /* PigmentPattern: its pigment's greyscale */
		float c[5];
		if (!pg || n->child < 0)
			return 0.0;
		eval_depth(pg, (uint32_t)n->child, p, sf, eps, 0, c);
		return 0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2];
	}
	default: return raw_shapes(n, p, eps);
	}
}

double pattern_raw(const pattern_node *n, dvec3 p) { return raw_eps(NULL, n, p, NULL, POV_EPSILON); }

static bool is_block(pattern_kind k)
{
	return k == PATTERN_CHECKER || k == PATTERN_HEXAGON || k == PATTERN_BRICK || k == PATTERN_MATERIAL_MAP ||
	       k == PATTERN_OBJECT;
}

/* The mapping warps' last step (warp.cpp): the mapped <x, y, z> turned to the orientation o
 * (the identity for <0, 0, 1>). */
static dvec3 orient_mapped(dvec3 o, double x, double y, double z)
{
	if (o.x == 0.0 && o.y == 0.0 && o.z == 1.0)
		return d3(x, y, z);
	return d3(o.x * z + o.y * x + o.z * x, o.x * y - o.y * z + o.z * y, -o.x * x + o.y * y + o.z * z);
}

/* The angle of <x, z> from the x axis, in [0, 2 pi) (warp.cpp's acos form). */
static double xz_angle(double x, double z, double len)
{
	if (z == 0.0)
		return x > 0.0 ? 0.0 : M_PI;
	double t = acos(fmax(-1.0, fmin(1.0, x / len)));
	return z < 0.0 ? TWO_PI - t : t;
}

/* POV-Ray's distance exponent: the mapped u (and v) scaled by len^e (e 0: not at all). */
static double dist_scale(double len, double e) { return e == 1.0 ? len : e != 0.0 ? pow(len, e) : 1.0; }

dvec3 pattern_warp_point(const pattern_warp *w, dvec3 p)
{
	switch (w->kind) {
	case WARP_TRANSFORM: return xform_inv_point(&w->xf, p);
	case WARP_TURBULENCE: return d3_add(p, d3_mul(pattern_dturbulence(p, &w->turb), w->turb.amount));
	case WARP_REPEAT: { /* RepeatWarp::WarpPoint */
		double *c = w->axis == 0 ? &p.x : w->axis == 1 ? &p.y : &p.z;
		double blk = floor(*c / w->width);
		*c -= blk * w->width;
		if ((long long)blk & 1) {
			p = d3_mul(p, w->flip);
			double f = w->axis == 0 ? w->flip.x : w->axis == 1 ? w->flip.y : w->flip.z;
			if (f < 0.0)
				*c += w->width;
		}
		return d3_add(p, d3_scale(w->offset, blk));
	}
	case WARP_BLACK_HOLE: { /* BlackHoleWarp::WarpPoint, type 0 */
		dvec3 c = w->center;
		bool rep = w->repeat.x > 0.0 || w->repeat.y > 0.0 || w->repeat.z > 0.0;
		int bx = w->repeat.x > 0.0 ? cell_of(p.x / w->repeat.x) : 0, by = w->repeat.y > 0.0 ? cell_of(p.y / w->repeat.y) : 0,
		    bz = w->repeat.z > 0.0 ? cell_of(p.z / w->repeat.z) : 0;
		if (rep && (w->uncertainty.x != 0.0 || w->uncertainty.y != 0.0 || w->uncertainty.z != 0.0)) {
			/* POV-Ray's "turbulence" of a black hole: each block's centre moved by a random
			 * fraction in [0, 1) of the vector per axis, WarpRands at the block's Hash3d and the two
			 * after it (warp.cpp; WarpRands is the same sequence as gPatternRands) */
			int h = noise_pov_hash3(bx, by, bz);
			c.x += noise_pov_rand(h) * w->uncertainty.x;
			c.y += noise_pov_rand(h + 1) * w->uncertainty.y;
			c.z += noise_pov_rand(h + 2) * w->uncertainty.z;
		}
		if (w->repeat.x > 0.0)
			c.x += w->repeat.x * bx;
		if (w->repeat.y > 0.0)
			c.y += w->repeat.y * by;
		if (w->repeat.z > 0.0)
			c.z += w->repeat.z * bz;
		dvec3 d = d3_sub(p, c);
		double len = d3_length(d);
		if (len >= w->radius)
			return p;
		double s = fmin(1.0, pow((w->radius - len) / w->radius, w->falloff) * w->strength);
		return d3_add(p, d3_scale(d, w->inverse ? -s : s));
	}
	case WARP_PLANAR: /* PlanarWarp::WarpPoint: z is the offset */
		return orient_mapped(w->orientation, p.x, p.y, w->plane_offset);
	case WARP_CYLINDRICAL: { /* CylindricalWarp::WarpPoint: u the angle about y over 2 pi, v y, z the radius */
		double len = sqrt(p.x * p.x + p.z * p.z);
		if (len == 0.0)
			return p;
		double th = xz_angle(p.x, p.z, len) / (TWO_PI) * dist_scale(len, w->dist_exp);
		return orient_mapped(w->orientation, th, p.y, len);
	}
	case WARP_SPHERICAL: { /* SphericalWarp::WarpPoint: u longitude, v latitude, z the distance */
		double dist = d3_length(p);
		if (dist == 0.0)
			return p;
		double x = p.x / dist, y = p.y / dist, z = p.z / dist;
		double phi = 0.5 + asin(fmax(-1.0, fmin(1.0, y))) / M_PI, len = sqrt(x * x + z * z);
		double th = len == 0.0 ? 0.0 : xz_angle(x, z, len) / (TWO_PI);
		double f = dist_scale(dist, w->dist_exp);
		return orient_mapped(w->orientation, th * f, phi * f, dist);
	}
	case WARP_TOROIDAL: { /* ToroidalWarp::WarpPoint: u about y, v about the tube, z the tube's radius */
		double len = sqrt(p.x * p.x + p.z * p.z);
		if (len == 0.0)
			return p;
		double th = -xz_angle(p.x, p.z, len);
		double x = len - w->major_radius, r = sqrt(x * x + p.y * p.y);
		double phi = r > 0.0 ? acos(fmax(-1.0, fmin(1.0, -x / r))) : 0.0;
		if (p.y > 0.0)
			phi = TWO_PI - phi;
		double f = dist_scale(r, w->dist_exp);
		return orient_mapped(w->orientation, th / (-TWO_PI) * f, phi / (TWO_PI) * f, r);
	}
	case WARP_CUBIC: { /* CubicWarp::WarpPoint: the six faces onto a cross-shaped net in [0, 1]^2 */
		double x = p.x, y = p.y, z = p.z, ax = fabs(x), ay = fabs(y), az = fabs(z);
		if (x >= 0 && x >= ay && x >= az)
			return d3(0.75 - 0.25 * (z / x + 1.0) / 2.0, 1.0 / 3.0 + (1.0 / 3.0) * (y / x + 1.0) / 2.0, x);
		if (y >= 0 && y >= ax && y >= az)
			return d3(0.25 + 0.25 * (x / y + 1.0) / 2.0, 1.0 - (1.0 / 3.0) * (z / y + 1.0) / 2.0, y);
		if (z >= 0 && z >= ax && z >= ay)
			return d3(0.25 + 0.25 * (x / z + 1.0) / 2.0, 1.0 / 3.0 + (1.0 / 3.0) * (y / z + 1.0) / 2.0, z);
		if (x < 0 && x <= -ay && x <= -az)
			return d3(0.25 * (z / -x + 1.0) / 2.0, 1.0 / 3.0 + (1.0 / 3.0) * (y / -x + 1.0) / 2.0, -x);
		if (y < 0 && y <= -ax && y <= -az)
			return d3(0.25 + 0.25 * (x / -y + 1.0) / 2.0, (1.0 / 3.0) * (z / -y + 1.0) / 2.0, -y);
		return d3(1.0 - 0.25 * (x / -z + 1.0) / 2.0, 1.0 / 3.0 + (1.0 / 3.0) * (y / -z + 1.0) / 2.0, -z);
	}
	}
	return p;
}

/* Warp_EPoint's last step: each coordinate within POV-Ray's COORDINATE_LIMIT (warp.cpp), and a
 * NaN made 0, so no pattern meets an infinity or a NaN. */
static double limit_coord(double v)
{
	if (!(v == v))
		return 0.0;
	return v > POV_COORDINATE_LIMIT ? POV_COORDINATE_LIMIT : v < -POV_COORDINATE_LIMIT ? -POV_COORDINATE_LIMIT : v;
}

static dvec3 limit_point(dvec3 p) { return d3(limit_coord(p.x), limit_coord(p.y), limit_coord(p.z)); }

double pattern_inv_gain(const xform *t)
{
	double g = 0.0;
	for (int r = 0; r < 3; r++)
		g = fmax(g, fabs(t->inv[r][0]) + fabs(t->inv[r][1]) + fabs(t->inv[r][2]));
	return g;
}

/* p through n's warps; *eps (a length) follows it through the transforms. */
static dvec3 warped(const pattern_prog *pg, const pattern_node *n, dvec3 p, double *eps)
{
	p = limit_point(p);
	for (uint32_t i = 0; i < n->n_warps; i++) {
		const pattern_warp *w = &pg->warps[n->warp0 + i];
		p = pattern_warp_point(w, p);
		if (w->kind == WARP_TRANSFORM)
			*eps *= pattern_inv_gain(&w->xf);
	}
	/* Classic turbulence acts in the pattern's own space, after its transforms (POV-Ray keeps
	 * it first in the warp list, which is applied last to first). */
	if (!n->turb_in_pattern && (n->turb.amount.x != 0.0 || n->turb.amount.y != 0.0 || n->turb.amount.z != 0.0))
		p = d3_add(p, d3_mul(pattern_dturbulence(p, &n->turb), n->turb.amount));
	return limit_point(p);
}

double pattern_value(const pattern_prog *pg, const pattern_node *n, dvec3 p)
{
	double eps = POV_EPSILON;
	dvec3 q = warped(pg, n, p, &eps);
	double raw = raw_eps(pg, n, q, NULL, eps);
	if (is_block(n->kind) || n->kind == PATTERN_PLAIN || n->kind == PATTERN_IMAGE)
		return raw;
	return pattern_wave_apply(n->wave, raw, n->frequency, n->phase, n->exponent);
}

static void finite5(float c[5])
{
	for (int i = 0; i < 5; i++)
		if (!isfinite(c[i]))
			c[i] = 0.0f;
}


/* An entry's colour at p: its own, or its pigment's. */
static void entry_color(const pattern_prog *pg, const pattern_entry *e, dvec3 p, const pattern_surface *sf, double eps,
			int depth, float out[5])
{
	if (e->node >= 0 && depth < PATTERN_MAX_DEPTH) {
		eval_depth(pg, (uint32_t)e->node, p, sf, eps, depth + 1, out);
		return;
	}
	for (int i = 0; i < 5; i++)
		out[i] = e->node >= 0 ? 0.0f : e->color[i];
}

static void map_lookup(const pattern_prog *pg, const pattern_node *n, double v, dvec3 p, const pattern_surface *sf,
		       double eps, int depth,
		       float out[5])
{
	const pattern_entry *e = pg->entries + n->entry0;
	uint32_t k = n->n_entries;
	if (k == 0) {
		for (int i = 0; i < 5; i++)
			out[i] = 0.0f;
		return;
	}
	if (k == 1 || v <= e[0].value) {
		entry_color(pg, &e[0], p, sf, eps, depth, out);
		return;
	}
	if (v >= e[k - 1].value) {
		entry_color(pg, &e[k - 1], p, sf, eps, depth, out);
		return;
	}
	uint32_t j = 1;
	while (j < k - 1 && e[j].value <= v) /* the first entry above v: e[j-1].value <= v < e[j].value */
		j++;
	double span = e[j].value - e[j - 1].value;
	double t = span > 0.0 ? (v - e[j - 1].value) / span : 1.0;
	float a[5], b[5];
	entry_color(pg, &e[j - 1], p, sf, eps, depth, a);
	entry_color(pg, &e[j], p, sf, eps, depth, b);
	for (int i = 0; i < 5; i++)
		out[i] = (float)((1.0 - t) * a[i] + t * b[i]);
}

/* An image_map's colour at p (image_texel maps it): clear outside the image. An image with an
 * alpha channel transmits 1 - alpha (POV-Ray's GetRGBFTValue), `filter all F` and `transmit all T`
 * add to each texel's filter and transmit (POV-Ray 3.7's AllTransmitLegacyMode: a scene of
 * #version below 3.8 adds them whatever the alpha). A palette image's `filter I, F` and
 * `transmit I, F` give the texels of index I their filter and transmit (the nearest texel's
 * index: POV-Ray blends interpolated texels' values, circe takes the nearest's). */
static void image_color(const pattern_node *n, dvec3 p, float out[5])
{
	float c[4];
	if (!image_texel(n, p, c)) {
		out[0] = out[1] = out[2] = out[3] = 0.0f, out[4] = 1.0f;
		return;
	}
	out[0] = c[0], out[1] = c[1], out[2] = c[2];
	float clear = n->img_alpha ? fminf(fmaxf(1.0f - c[3], 0.0f), 1.0f) : 0.0f;
	out[3] = n->filter_all, out[4] = n->transmit_all + clear;
	if (n->img_index) {
		pattern_node near = *n;
		near.img = n->img_index, near.interpolate = false;
		float ix[4];
		if (image_texel(&near, p, ix) && ix[0] >= 0.0f && ix[0] < 256.0f) {
			int i = (int)ix[0];
			if (n->pal_filter && !isnan(n->pal_filter[i]))
				out[3] = n->pal_filter[i];
			if (n->pal_transmit && !isnan(n->pal_transmit[i]))
				out[4] = n->pal_transmit[i];
		}
	}
}

void pattern_map_lookup(const pattern_prog *pg, const pattern_node *n, double v, dvec3 p, int depth, float out[5])
{
	map_lookup(pg, n, v, p, NULL, POV_EPSILON, depth, out);
}

/* A layered texture's pigment (POV-Ray's texture { } texture { }, bottom first): each upper layer
 * shows its own colour where it is opaque, 1 - filter - transmit, and lets the layers below
 * through by transmit, tinted by its colour by filter (trace.cpp's layering of textures, on
 * pigments alone). What the whole lets through is the layers' product. */
static void layers(const pattern_prog *pg, const pattern_node *n, dvec3 p, const pattern_surface *sf, double eps,
		   int depth, float out[5])
{
	for (int i = 0; i < 5; i++)
		out[i] = 0.0f;
	for (uint32_t j = 0; j < n->n_entries; j++) {
		float c[5];
		entry_color(pg, &pg->entries[n->entry0 + j], p, sf, eps, depth, c);
		if (j == 0) {
			memcpy(out, c, sizeof c);
			continue;
		}
		float f = c[3], t = c[4], opaque = fmaxf(0.0f, 1.0f - f - t);
		for (int i = 0; i < 3; i++)
			out[i] = c[i] * opaque + out[i] * (t + f * c[i]);
		out[3] *= f + t, out[4] *= f + t;
	}
}

/* POV-Ray's average (pigment.cpp ColourBlendMap/PigmentBlendMap::ComputeAverage): the entries'
 * colours at p, each weighted by its value, divided by the weights' sum (the parser makes it > 0). */
static void average(const pattern_prog *pg, const pattern_node *n, dvec3 p, const pattern_surface *sf, double eps,
		    int depth, float out[5])
{
	double sum[5] = {0}, total = 0.0;
	for (uint32_t j = 0; j < n->n_entries; j++) {
		const pattern_entry *e = &pg->entries[n->entry0 + j];
		float c[5];
		entry_color(pg, e, p, sf, eps, depth, c);
		for (int i = 0; i < 5; i++)
			sum[i] += e->value * c[i];
		total += e->value;
	}
	for (int i = 0; i < 5; i++)
		out[i] = total != 0.0 ? (float)(sum[i] / total) : 0.0f;
}

static void eval_depth(const pattern_prog *pg, uint32_t node, dvec3 p, const pattern_surface *sf, double eps, int depth,
		       float out[5])
{
	const pattern_node *n = &pg->nodes[node];
	if (n->kind == PATTERN_PLAIN) {
		for (int i = 0; i < 5; i++)
			out[i] = n->color[i];
		return;
	}
	if (n->kind == PATTERN_LAYERS) {
		layers(pg, n, p, sf, eps, depth, out);
		finite5(out);
		return;
	}
	dvec3 q = warped(pg, n, p, &eps);
	if (n->kind == PATTERN_IMAGE) {
		image_color(n, q, out);
	} else if (n->kind == PATTERN_AVERAGE) {
		average(pg, n, q, sf, eps, depth, out);
	} else if (is_block(n->kind)) {
		uint32_t i = (uint32_t)raw_eps(pg, n, q, sf, eps);
		if (i < n->n_entries)
			entry_color(pg, &pg->entries[n->entry0 + i], q, sf, eps, depth, out);
		else
			out[0] = out[1] = out[2] = out[3] = out[4] = 0.0f;
	} else {
		double v = pattern_wave_apply(n->wave, raw_eps(pg, n, q, sf, eps), n->frequency, n->phase, n->exponent);
		map_lookup(pg, n, v, q, sf, eps, depth, out);
	}
	finite5(out);
}

void pattern_eval_at(const pattern_prog *pg, uint32_t node, dvec3 p, const pattern_surface *sf, double tol,
		     float out[5])
{
	eval_depth(pg, node, p, sf, tol > POV_EPSILON ? tol : POV_EPSILON, 0, out);
}

void pattern_eval(const pattern_prog *pg, uint32_t node, dvec3 p, double tol, float out[5])
{
	pattern_eval_at(pg, node, p, NULL, tol, out);
}

pattern_node pattern_node_default(pattern_kind kind)
{
	pattern_node n = {.kind = kind, .frequency = 1.0, .exponent = 1.0, .vector = d3(0, 1, 0), .arms = 1,
			  .bump_amount = 0.5, .accuracy = 0.02, .child = -1,
			  .crackle_form = d3(-1, 1, 0), .crackle_metric = 2.0,
			  .fractal_iterations = 1, .fractal_exponent = 2, .fractal_exterior = 1, .exterior_factor = 1.0, .interior_factor = 1.0,
			  .control0 = 1.0, .control1 = 1.0, .agate_turb = 1.0,
			  .turb = {.octaves = 6, .omega = 0.5, .lambda = 2.0}};
	n.wave = kind == PATTERN_MARBLE || kind == PATTERN_WOOD || kind == PATTERN_SPIRAL1 || kind == PATTERN_SPIRAL2
			 ? WAVE_TRIANGLE
			 : WAVE_RAMP;
	n.turb_in_pattern = kind == PATTERN_MARBLE || kind == PATTERN_WOOD || kind == PATTERN_SPIRAL1 ||
			    kind == PATTERN_SPIRAL2;
	if (kind == PATTERN_QUILTED)
		n.frequency = 0.0; /* QuiltedPattern's constructor */
	if (kind == PATTERN_BRICK)
		n.vector = d3(8.0, 3.0, 4.5), n.mortar = 0.5 - 2.0 * POV_EPSILON;
	return n;
}

/* pattern.cpp's gaDefaultBlendMapEntries_*: the colours a pattern shows without a map. */
int pattern_default_map(pattern_kind kind, pattern_entry out[6])
{
	static const double agate[6][4] = {{0.0, 1, 1, 1},	  {0.5, 0.95, 0.75, 0.5}, {0.5, 0.9, 0.7, 0.5},
					   {0.6, 0.9, 0.7, 0.4},  {0.6, 1.0, 0.7, 0.4},	  {1.0, 0.6, 0.3, 0.0}};
	static const double bozo[6][4] = {{0.4, 1, 1, 1}, {0.4, 0, 1, 0}, {0.6, 0, 1, 0},
					  {0.6, 0, 0, 1}, {0.8, 0, 0, 1}, {0.8, 1, 0, 0}};
	static const double brick[2][4] = {{0.0, 0.5, 0.5, 0.5}, {1.0, 0.6, 0.15, 0.15}};
	static const double checker[2][4] = {{0.0, 0, 0, 1}, {1.0, 0, 1, 0}};
	static const double hexagon[3][4] = {{0.0, 0, 0, 1}, {1.0, 0, 1, 0}, {2.0, 1, 0, 0}};
	static const double marble[3][4] = {{0.0, 0.9, 0.8, 0.8}, {0.9, 0.9, 0.08, 0.08}, {0.9, 0, 0, 0}};
	static const double radial[4][4] = {{0.0, 0, 1, 1}, {0.333, 1, 1, 0}, {0.666, 1, 0, 1}, {1.0, 0, 1, 1}};
	static const double wood[2][4] = {{0.6, 0.666, 0.312, 0.2}, {0.6, 0.4, 0.1333, 0.066}};
	static const double gray[2][4] = {{0.0, 0, 0, 0}, {1.0, 1, 1, 1}};
	/* POV-Ray's gaDefaultBlendMapEntries_Mandel */
	static const double mandel[5][4] = {{0.001, 0, 0, 0}, {0.001, 0, 1, 1}, {0.012, 1, 1, 0}, {0.015, 1, 0, 1},
					    {0.1, 0, 1, 1}};
	const double(*t)[4] = gray;
	int n = 2;
	switch (kind) {
	case PATTERN_AGATE: t = agate, n = 6; break;
	case PATTERN_BOZO: t = bozo, n = 6; break;
	case PATTERN_BRICK: t = brick, n = 2; break;
	case PATTERN_CHECKER: t = checker, n = 2; break;
	case PATTERN_HEXAGON: t = hexagon, n = 3; break;
	case PATTERN_MARBLE: t = marble, n = 3; break;
	case PATTERN_RADIAL: t = radial, n = 4; break;
	case PATTERN_WOOD: t = wood, n = 2; break;
	case PATTERN_MANDEL: t = mandel, n = 5; break;
	default: break;
	}
	for (int i = 0; i < n; i++)
		out[i] = (pattern_entry){.value = t[i][0],
					 .color = {(float)t[i][1], (float)t[i][2], (float)t[i][3], 0.0f, 0.0f},
					 .node = -1};
	return n;
}

/* ---- normals ------------------------------------------------------------------------------ */

/* The sum over POV-Ray's wave sources of normal.cpp's ripples (waves: with each source's
 * frequency): each pushes the normal along p - source by the wave's sine. */
static dvec3 wave_normal(const pattern_node *n, dvec3 p, bool waves)
{
	uint32_t next = (uint32_t)-560851967;
	dvec3 d = d3(0, 0, 0);
	for (int i = 0; i < POV_NUMBER_OF_WAVES; i++) {
		double f = wave_frequency(&next);
		dvec3 q = d3_sub(p, wave_source(i));
		double len = d3_length(q);
		if (len == 0.0)
			len = 1.0;
		double s = waves ? cycloidal(len * n->frequency * f + n->phase) * n->bump_amount / f
				 : cycloidal(len * n->frequency + n->phase) * n->bump_amount;
		d = d3_add(d, d3_scale(q, s / (len * POV_NUMBER_OF_WAVES)));
	}
	return d;
}

/* normal.cpp's wrinkles: ten octaves of |vector noise| / 2^i. */
static dvec3 wrinkles_normal(dvec3 p)
{
	dvec3 r = d3(0, 0, 0);
	double scale = 1.0;
	for (int i = 0; i < 10; i++, scale *= 2.0) {
		dvec3 v = pattern_dnoise(d3_scale(p, scale));
		r = d3_add(r, d3(fabs(v.x) / scale, fabs(v.y) / scale, fabs(v.z) / scale));
	}
	return r;
}

/* Perturb_Normal's slope of any pattern: its value at the four corners of a tetrahedron of size
 * accuracy around p, times -5 amount (POV-Ray's "fudge factor") scaled to the step. */
/* POV-Ray 3.7's Do_Slope_Map (normal.cpp): a value to a height through the slope_map's entries
 * <height, slope>, by its Hermite_Cubic between the two entries about it (t their map weight),
 * the end entries' heights beyond them. */
static double slope_lookup(const pattern_prog *pg, const pattern_node *n, double v)
{
	const pattern_entry *e = pg->entries + n->entry0;
	uint32_t k = n->n_entries;
	if (k == 0)
		return v;
	if (k == 1 || v <= e[0].value)
		return e[0].color[0];
	if (v >= e[k - 1].value)
		return e[k - 1].color[0];
	uint32_t j = 1;
	while (j < k - 1 && e[j].value <= v)
		j++;
	double span = e[j].value - e[j - 1].value;
	if (!(span > 0.0))
		return e[j].color[0];
	double t = (v - e[j - 1].value) / span, h1 = e[j - 1].color[0], s1 = e[j - 1].color[1];
	double h2 = e[j].color[0], s2 = e[j].color[1];
	return t * t * t * (s1 + s2 + 2.0 * (h1 - h2)) - t * t * (2.0 * s1 + s2 + 3.0 * (h1 - h2)) + t * s1 + h1;
}

static dvec3 slope_normal(const pattern_prog *pg, const pattern_node *n, dvec3 q, const pattern_surface *sf, double eps)
{
	static const double pyramid[4][3] = {{0.942809041, -0.333333333, 0.0},
					     {-0.471404521, -0.333333333, 0.816496581},
					     {-0.471404521, -0.333333333, -0.816496581},
					     {0.0, 1.0, 0.0}};
	double delta = n->accuracy > 0 ? n->accuracy : 0.02;
	double amount = n->bump_amount * -5.0 * 0.02 / delta;
	dvec3 d = d3(0, 0, 0);
	for (int i = 0; i < 4; i++) {
		dvec3 v = d3(pyramid[i][0], pyramid[i][1], pyramid[i][2]);
		dvec3 at = d3_add(q, d3_scale(v, delta));
		double value = raw_eps(pg, n, at, sf, eps);
		if (!is_block(n->kind))
			value = pattern_wave_apply(n->wave, value, n->frequency, n->phase, n->exponent);
		if (n->slope_map)
			value = slope_lookup(pg, n, value);
		d = d3_add(d, d3_scale(v, value * amount));
	}
	return d;
}

dvec3 pattern_normal_through(const xform *t, dvec3 n, bool into)
{
	const double(*m)[4] = into ? t->m : t->inv; /* M^T n into, M^-T n out */
	return d3(m[0][0] * n.x + m[1][0] * n.y + m[2][0] * n.z, m[0][1] * n.x + m[1][1] * n.y + m[2][1] * n.z,
		  m[0][2] * n.x + m[1][2] * n.y + m[2][2] * n.z);
}

/* POV-Ray's greyscale (0.297 r + 0.589 g + 0.114 b) of texel (x, y) (row 0 the top), wrapped. */
static double texel_grey(const image *img, int x, int y)
{
	x = ((x % img->width) + img->width) % img->width, y = ((y % img->height) + img->height) % img->height;
	const float *c = img->rgba + ((size_t)y * (size_t)img->width + (size_t)x) * 4;
	return 0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2];
}

/* imageutil.cpp's bump_map: the image's grey at the mapped texel and at its two lower
 * neighbours (left and right) make a small triangle of heights times amount; its normal,
 * expressed in a frame of the surface normal and the world's y axis, is the new normal. */
static dvec3 bump_map_normal(const pattern_node *n, dvec3 q, dvec3 nrm)
{
	double u = q.x, v = q.y;
	if (!n->img || (n->once && (u < 0.0 || u >= 1.0 || v < 0.0 || v >= 1.0)))
		return nrm;
	int w = n->img->width, h = n->img->height;
	int x = (int)floor((u - floor(u)) * w), y = (int)floor((1.0 - (v - floor(v))) * h);
	double a = n->bump_amount;
	dvec3 p1 = d3(0, a * texel_grey(n->img, x, y), 0), p2 = d3(-1, a * texel_grey(n->img, x - 1, y + 1), 1);
	dvec3 p3 = d3(1, a * texel_grey(n->img, x + 1, y + 1), 1);
	dvec3 bump = d3_normalize(d3_cross(d3_sub(p3, p2), d3_sub(p1, p2)));
	dvec3 yp = nrm, xp = d3_cross(nrm, d3(0, 1, 0));
	double len = d3_length(xp);
	if (len < 1e-10) {
		yp = d3(0, nrm.y >= 0 ? 1 : -1, 0), xp = d3(1, 0, 0);
		len = 1.0;
	}
	xp = d3_scale(xp, 1.0 / len);
	dvec3 zp = d3_normalize(d3_cross(xp, yp));
	return d3_sub(d3_add(d3_scale(xp, bump.x), d3_scale(yp, bump.y)), d3_scale(zp, bump.z));
}

static void perturb_depth(const pattern_prog *pg, uint32_t node, dvec3 p, const pattern_surface *sf, int depth,
			  dvec3 *nrm);

/* POV-Ray 3.7's facets (normal.cpp): the point (coords) or the unit normal, scaled by 1 / size,
 * finds the nearest of the cells' feature points (crackle's, of the 81 cubes about it) under the
 * metric (2: squared distance; 1: POV-Ray's dx + dy + dz, signed as it writes it; else the sum of
 * |d|^metric). Without coords that point is the new normal (so the normal is quantised into
 * facets); with coords F the normal is pushed by F times the vector noise at that point, less
 * its part along the normal. */
static dvec3 facets_normal(const pattern_node *n, dvec3 q, dvec3 v)
{
	double len = d3_length(v);
	if (!(len > 0.0))
		return v;
	v = d3_scale(v, 1.0 / len);
	double scale = n->facets_size < 1e-6 ? 1e6 : 1.0 / n->facets_size, m = n->crackle_metric;
	dvec3 t = d3_scale(n->facets_coords != 0.0 ? q : v, scale);
	int cx = cell_of(t.x), cy = cell_of(t.y), cz = cell_of(t.z);
	double best = INFINITY;
	dvec3 nearest = t;
	for (int i = -2; i <= 2; i++)
		for (int j = -2; j <= 2; j++)
			for (int k = -2; k <= 2; k++) {
				if ((abs(i) == 2) + (abs(j) == 2) + (abs(k) == 2) > 1)
					continue;
				dvec3 f = pattern_crackle_point(cx + i, cy + j, cz + k), d = d3_sub(f, t);
				double s = m == 2.0 ? d3_dot(d, d) : m == 1.0 ? d.x + d.y + d.z : metric_sum(d, m, INFINITY);
				if (s < best)
					best = s, nearest = f;
			}
	if (n->facets_coords == 0.0)
		return nearest;
	dvec3 pert = pattern_dnoise(nearest);
	pert = d3_sub(pert, d3_scale(v, d3_dot(pert, v)));
	return d3_add(v, d3_scale(pert, n->facets_coords));
}

/* A normal's normal_map (normal.cpp Perturb_Normal): the entries are normals, each perturbing v at
 * q in turn. average: their results weighted by the entries' values over the weights' sum
 * (NormalBlendMap::ComputeAverage); another pattern: the two entries around its value, blended
 * by the map's weights, then normalised, as POV-Ray's. */
static dvec3 normal_map(const pattern_prog *pg, const pattern_node *n, dvec3 q, const pattern_surface *sf, double eps,
			int depth, dvec3 v)
{
	const pattern_entry *e = pg->entries + n->entry0;
	uint32_t k = n->n_entries;
	if (n->kind == PATTERN_AVERAGE) {
		dvec3 sum = d3(0, 0, 0);
		double total = 0.0;
		for (uint32_t j = 0; j < k; j++) {
			dvec3 vj = v;
			if (e[j].node >= 0)
				perturb_depth(pg, (uint32_t)e[j].node, q, sf, depth + 1, &vj);
			sum = d3_add(sum, d3_scale(vj, e[j].value));
			total += e[j].value;
		}
		return total != 0.0 ? d3_scale(sum, 1.0 / total) : v;
	}
	double raw = raw_eps(pg, n, q, sf, eps);
	double val = is_block(n->kind) ? raw : pattern_wave_apply(n->wave, raw, n->frequency, n->phase, n->exponent);
	uint32_t lo = 0, hi = 0;
	double t = 0.0;
	if (k > 1 && val >= e[k - 1].value) {
		lo = hi = k - 1;
	} else if (k > 1 && val > e[0].value) {
		hi = 1;
		while (hi < k - 1 && e[hi].value <= val)
			hi++;
		lo = hi - 1;
		double span = e[hi].value - e[lo].value;
		t = span > 0.0 ? (val - e[lo].value) / span : 1.0;
	}
	dvec3 a = v, b = v;
	if (e[hi].node >= 0) /* an entry the build filled with a colour (a block list's default) is flat */
		perturb_depth(pg, (uint32_t)e[hi].node, q, sf, depth + 1, &b);
	if (lo != hi) {
		if (e[lo].node >= 0)
			perturb_depth(pg, (uint32_t)e[lo].node, q, sf, depth + 1, &a);
		b = d3_add(d3_scale(a, 1.0 - t), d3_scale(b, t));
	}
	double len = d3_length(b);
	return len > 0.0 ? d3_scale(b, 1.0 / len) : v;
}

void pattern_perturb_at(const pattern_prog *pg, uint32_t node, dvec3 p, const pattern_surface *sf, dvec3 *nrm)
{
	perturb_depth(pg, node, p, sf, 0, nrm);
}

void pattern_perturb(const pattern_prog *pg, uint32_t node, dvec3 p, dvec3 *nrm)
{
	pattern_perturb_at(pg, node, p, NULL, nrm);
}

static void perturb_depth(const pattern_prog *pg, uint32_t node, dvec3 p, const pattern_surface *sf, int depth,
			  dvec3 *nrm)
{
	const pattern_node *n = &pg->nodes[node];
	if (depth > PATTERN_MAX_DEPTH)
		return;
	dvec3 v = *nrm;
	for (uint32_t i = 0; i < n->n_warps; i++)
		if (pg->warps[n->warp0 + i].kind == WARP_TRANSFORM)
			v = pattern_normal_through(&pg->warps[n->warp0 + i].xf, v, true);
	/* POV-Ray's Warp_Normal (warps.cpp, without no_bump_scale): the normal is unit in the
	 * pattern's space when the perturbation is added, so a scaled pattern or object keeps the
	 * bumps' angle; UnWarp_Normal makes the result unit again. */
	v = d3_normalize(v);
	double eps = POV_EPSILON;
	dvec3 q = warped(pg, n, p, &eps);
	bool has_map = n->n_entries > 0 && pg->entries[n->entry0].node >= 0; /* a normal_map's entries */
	if (has_map) {
		v = normal_map(pg, n, q, sf, eps, depth, v);
	} else {
		switch (n->kind) {
		case PATTERN_BUMPS: v = d3_add(v, d3_scale(pattern_dnoise(q), n->bump_amount)); break;
		case PATTERN_DENTS: {
			double k = pattern_noise(q);
			v = d3_add(v, d3_scale(pattern_dnoise(q), k * k * k * n->bump_amount));
			break;
		}
		case PATTERN_WRINKLES: v = d3_add(v, d3_scale(wrinkles_normal(q), n->bump_amount)); break;
		case PATTERN_RIPPLES: v = d3_add(v, wave_normal(n, q, false)); break;
		case PATTERN_WAVES: v = d3_add(v, wave_normal(n, q, true)); break;
		case PATTERN_IMAGE: v = bump_map_normal(n, q, d3_normalize(v)); break;
		case PATTERN_FACETS: v = facets_normal(n, q, v); break;
		case PATTERN_PLAIN: break;
		default: v = d3_add(v, slope_normal(pg, n, q, sf, eps)); break;
		}
	}
	for (uint32_t i = n->n_warps; i-- > 0;)
		if (pg->warps[n->warp0 + i].kind == WARP_TRANSFORM)
			v = pattern_normal_through(&pg->warps[n->warp0 + i].xf, v, false);
	v = d3_normalize(v);
	if (isfinite(v.x) && isfinite(v.y) && isfinite(v.z))
		*nrm = v;
}

uint32_t pattern_pick(const pattern_prog *pg, uint32_t node, dvec3 p, const pattern_surface *sf, double tol,
		      uint32_t max, uint32_t *entry, double *weight, dvec3 *q, double *q_tol)
{
	const pattern_node *n = &pg->nodes[node];
	double eps = tol > POV_EPSILON ? tol : POV_EPSILON;
	if (n->kind == PATTERN_PLAIN || n->kind == PATTERN_LAYERS || n->kind == PATTERN_IMAGE || !n->n_entries ||
	    max < 1)
		return 0;
	*q = warped(pg, n, p, &eps);
	*q_tol = eps;
	uint32_t k = n->n_entries;
	const pattern_entry *e = pg->entries + n->entry0;
	if (n->kind == PATTERN_AVERAGE) { /* average(): every entry by its value over their sum */
		double total = 0.0;
		for (uint32_t j = 0; j < k; j++)
			total += e[j].value;
		uint32_t m = 0;
		for (uint32_t j = 0; j < k && m < max; j++)
			if (total != 0.0 && e[j].value != 0.0)
				entry[m] = j, weight[m++] = e[j].value / total;
		return m;
	}
	if (is_block(n->kind)) { /* eval_depth's block lookup: an index past the list is none */
		uint32_t i = (uint32_t)raw_eps(pg, n, *q, sf, eps);
		if (i >= k)
			return 0;
		entry[0] = i, weight[0] = 1.0;
		return 1;
	}
	double v = pattern_wave_apply(n->wave, raw_eps(pg, n, *q, sf, eps), n->frequency, n->phase, n->exponent);
	/* map_lookup's search: clamped at the ends, the two entries around v blended linearly */
	if (k == 1 || v <= e[0].value || v >= e[k - 1].value) {
		entry[0] = k == 1 || v <= e[0].value ? 0 : k - 1, weight[0] = 1.0;
		return 1;
	}
	uint32_t j = 1;
	while (j < k - 1 && e[j].value <= v)
		j++;
	double span = e[j].value - e[j - 1].value;
	double t = span > 0.0 ? (v - e[j - 1].value) / span : 1.0;
	entry[0] = j - 1, weight[0] = 1.0 - t;
	if (max < 2 || t <= 0.0) {
		weight[0] = 1.0;
		return 1;
	}
	if (t >= 1.0) {
		entry[0] = j, weight[0] = 1.0;
		return 1;
	}
	entry[1] = j, weight[1] = t;
	return 2;
}
