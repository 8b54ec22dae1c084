/* noise.c - the lattice noises: POV-Ray 3.7's own (under the noise patterns, f_noise3d and the
 * noise-based internal functions: noise_pov, noise_pov_vector) and Perlin's improved noise
 * (noise_perlin, which circe's patterns took before they took POV-Ray's). */
#include "base/noise.h"

#include <math.h>
#include <pthread.h>
#include <stdint.h>

/* Coordinates beyond this are clamped before the noise's lattice arithmetic (POV-Ray clamps
 * warped points at 1e17, warp.cpp's COORDINATE_LIMIT; the lattice index must fit an int). */
#define NOISE_COORD_LIMIT 1.0e9
/* Perlin's permutation, "Improving Noise" (SIGGRAPH 2002) and its reference implementation
 * (mrl.cs.nyu.edu/~perlin/noise/): a published table. */
static const unsigned char perm[256] = {
	151, 160, 137, 91,  90,	 15,  131, 13,	201, 95,  96,  53,  194, 233, 7,   225, 140, 36,  103, 30,	69,  142,
	8,   99,  37,  240, 21,	 10,  23,  190, 6,   148, 247, 120, 234, 75,  0,   26,	197, 62,  94,  252, 219, 203,
	117, 35,  11,  32,  57,	 177, 33,  88,	237, 149, 56,  87,  174, 20,  125, 136, 171, 168, 68,  175, 74,	 165,
	71,  134, 139, 48,  27,	 166, 77,  146, 158, 231, 83,  111, 229, 122, 60,  211, 133, 230, 220, 105, 92,	 41,
	55,  46,  245, 40,  244, 102, 143, 54,	65,  25,  63,  161, 1,	 216, 80,  73,	209, 76,  132, 187, 208, 89,
	18,  169, 200, 196, 135, 130, 116, 188, 159, 86,  164, 100, 109, 198, 173, 186, 3,   64,	52,  217, 226, 250,
	124, 123, 5,   202, 38,	 147, 118, 126, 255, 82,  85,  212, 207, 206, 59,  227, 47,  16,	58,  17,  182, 189,
	28,  42,  223, 183, 170, 213, 119, 248, 152, 2,	 44,  154, 163, 70,  221, 153, 101, 155, 167, 43,  172, 9,
	129, 22,  39,  253, 19,	 98,  108, 110, 79,  113, 224, 232, 178, 185, 112, 104, 218, 246, 97,  228, 251, 34,
	242, 193, 238, 210, 144, 12,  191, 179, 162, 241, 81,  51,  145, 235, 249, 14,	239, 107, 49,  192, 214, 31,
	181, 199, 106, 157, 184, 84,  204, 176, 115, 121, 50,  45,  127, 4,   150, 254, 138, 236, 205, 93,	222, 114,
	67,  29,  24,  72,  243, 141, 128, 195, 78,  66,  215, 61,  156, 180};

int noise_perm(int i) { return perm[i & 255]; }

static double fade(double t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }
static double lerp(double t, double a, double b) { return a + t * (b - a); }

/* The gradient of hash h dotted with (x, y, z): Perlin 2002's twelve edge directions. */
static double grad(int h, double x, double y, double z)
{
	h &= 15;
	double u = h < 8 ? x : y, v = h < 4 ? y : (h == 12 || h == 14) ? x : z;
	return ((h & 1) ? -u : u) + ((h & 2) ? -v : v);
}

static double clamp_coord(double x)
{
	if (!(x == x))
		return 0.0;
	return x > NOISE_COORD_LIMIT ? NOISE_COORD_LIMIT : x < -NOISE_COORD_LIMIT ? -NOISE_COORD_LIMIT : x;
}

double noise_perlin(dvec3 p)
{
	double x = clamp_coord(p.x), y = clamp_coord(p.y), z = clamp_coord(p.z);
	double fx = floor(x), fy = floor(y), fz = floor(z);
	int X = (int)((long long)fx & 255), Y = (int)((long long)fy & 255), Z = (int)((long long)fz & 255);
	x -= fx, y -= fy, z -= fz;
	double u = fade(x), v = fade(y), w = fade(z);
	int A = perm[X] + Y, AA = perm[A & 255] + Z, AB = perm[(A + 1) & 255] + Z;
	int B = perm[(X + 1) & 255] + Y, BA = perm[B & 255] + Z, BB = perm[(B + 1) & 255] + Z;
#define P(i) perm[(i) & 255]
	return lerp(w,
		    lerp(v, lerp(u, grad(P(AA), x, y, z), grad(P(BA), x - 1, y, z)),
			 lerp(u, grad(P(AB), x, y - 1, z), grad(P(BB), x - 1, y - 1, z))),
		    lerp(v, lerp(u, grad(P(AA + 1), x, y, z - 1), grad(P(BA + 1), x - 1, y, z - 1)),
			 lerp(u, grad(P(AB + 1), x, y - 1, z - 1), grad(P(BB + 1), x - 1, y - 1, z - 1))));
#undef P
}

/* ---- POV-Ray 3.7's own lattice noise (noise_generator 2, its default) ----
 * The noise patterns of a POV-Ray scene are POV-Ray's only if the noise is its own: with another
 * lattice noise a bozo shows other blobs of the same size (bench/pov_cover.sh measured r 0.0 to
 * 0.3 for the noise patterns beside POV-Ray). The facts below are POV-Ray 3.7's (source/core/
 * material/noise.cpp and portablenoise.cpp, read to learn them; this is circe's own code): its
 * table of 267 random numbers (RTable, the constants as published); a permutation of 0..4095
 * made by swapping entry i (from 4095 down) with entry (s >> 16 & 0x7FFF) mod 4096 of the linear
 * congruential sequence s <- 1812433253 s + 12345 from 0 (InitTextureTable); the lattice cell of
 * a point, its corners hashed through the permutation and each corner's four table numbers
 * k..k+3 (k the hash's low byte) making a linear function 0.5 R[k] + R[k+1] dx + R[k+2] dy +
 * R[k+3] dz of the offset from the corner, blended by the cubic s-curve 3t^2 - 2t^3 (INCRSUM);
 * generator 2 brings the sum into [0, 1] as (sum + 1.05242) 0.48985582, clamped. The vector
 * noise (DNoise) takes the same blend of three such functions, from k, k + 4 and k + 8. */
static const double pov_rtable[267] = {
	-1, 0.604974, -0.937102, 0.414115, 0.576226, -0.0161593, 0.432334, 0.103685, 0.590539, 0.0286412,
	0.46981, -0.84622, -0.0734112, -0.304097, -0.40206, -0.210132, -0.919127, 0.652033, -0.83151,
	-0.183948, -0.671107, 0.852476, 0.043595, -0.404532, 0.75494, -0.335653, 0.618433, 0.605707,
	0.708583, -0.477195, 0.899474, 0.490623, 0.221729, -0.400381, -0.853727, -0.932586, 0.659113,
	0.961303, 0.325948, -0.750851, 0.842466, 0.734401, -0.649866, 0.394491, -0.466056, -0.434073,
	0.109026, 0.0847028, -0.738857, 0.241505, 0.16228, -0.71426, -0.883665, -0.150408, -0.90396,
	-0.686549, -0.785214, 0.488548, 0.0246433, 0.142473, -0.602136, 0.375845, -0.00779736, 0.498955,
	-0.268147, 0.856382, -0.386007, -0.596094, -0.867735, -0.570977, -0.914366, 0.28896, 0.672206,
	-0.233783, 0.94815, 0.895262, 0.343252, -0.173388, -0.767971, -0.314748, 0.824308, -0.342092,
	0.721431, -0.24004, -0.63653, 0.553277, 0.376272, 0.158984, -0.452659, 0.396323, -0.420676,
	-0.454154, 0.122179, 0.295857, 0.0664225, -0.202075, -0.724788, 0.453513, 0.224567, -0.908812,
	0.176349, -0.320516, -0.697139, 0.742702, -0.900786, 0.471489, -0.133532, 0.119127, -0.889769,
	-0.23183, -0.669673, -0.046891, -0.803433, -0.966735, 0.475578, -0.652644, 0.0112459, -0.730007,
	0.128283, 0.145647, -0.619318, 0.272023, 0.392966, 0.646418, -0.0207675, -0.315908, 0.480797,
	0.535668, -0.250172, -0.83093, -0.653773, -0.443809, 0.119982, -0.897642, 0.89453, 0.165789,
	0.633875, -0.886839, 0.930877, -0.537194, 0.587732, 0.722011, -0.209461, -0.0424659, -0.814267,
	-0.919432, 0.280262, -0.66302, -0.558099, -0.537469, -0.598779, 0.929656, -0.170794, -0.537163,
	0.312581, 0.959442, 0.722652, 0.499931, 0.175616, -0.534874, -0.685115, 0.444999, 0.17171, 0.108202,
	-0.768704, -0.463828, 0.254231, 0.546014, 0.869474, 0.875212, -0.944427, 0.130724, -0.110185,
	0.312184, -0.33138, -0.629206, 0.0606546, 0.722866, -0.0979477, 0.821561, 0.0931258, -0.972808,
	0.0318151, -0.867033, -0.387228, 0.280995, -0.218189, -0.539178, -0.427359, -0.602075, 0.311971,
	0.277974, 0.773159, 0.592493, -0.0331884, -0.630854, -0.269947, 0.339132, 0.581079, 0.209461,
	-0.317433, -0.284993, 0.181323, 0.341634, 0.804959, -0.229572, -0.758907, -0.336721, 0.605463,
	-0.991272, -0.0188754, -0.300191, 0.368307, -0.176135, -0.3832, -0.749569, 0.62356, -0.573938,
	0.278309, -0.971313, 0.839994, -0.830686, 0.439078, 0.66128, 0.694514, 0.0565042, 0.54342,
	-0.438804, -0.0228428, -0.687068, 0.857267, 0.301991, -0.494255, -0.941039, 0.775509, 0.410575,
	-0.362081, -0.671534, -0.348379, 0.932433, 0.886442, 0.868681, -0.225666, -0.062211, -0.0976425,
	-0.641444, -0.848112, 0.724697, 0.473503, 0.998749, 0.174701, 0.559625, -0.029099, -0.337392,
	-0.958129, -0.659785, 0.236042, -0.246937, 0.659449, -0.027512, 0.821897, -0.226215, 0.0181735,
	0.500481, -0.420127, -0.427878, 0.566186,
};

static unsigned short pov_hash[8192];
static pthread_once_t pov_hash_once = PTHREAD_ONCE_INIT;

static void pov_hash_init(void)
{
	uint32_t s = 0;
	for (int i = 0; i < 4096; i++)
		pov_hash[i] = (unsigned short)i;
	for (int i = 4095; i >= 0; i--) {
		s = s * 1812433253u + 12345u;
		int j = (int)((s >> 16) & 0x7FFF) % 4096;
		unsigned short t = pov_hash[i];
		pov_hash[i] = pov_hash[j], pov_hash[j] = t;
	}
	for (int i = 0; i < 4096; i++)
		pov_hash[4096 + i] = pov_hash[i];
}

/* The lattice cell of one coordinate: its index into the permutation (POV-Ray offsets the cell
 * by 10000 and wraps at 4096) and the offset within it. */
static int pov_cell(double x, double *frac)
{
	double f = floor(x);
	*frac = x - f;
	return (int)(((long long)f + 10000) & 0xFFF);
}

static double scurve(double t) { return t * t * (3.0 - 2.0 * t); }

/* The corners' blend at p, corner c = cx + 2 cy + 4 cz: its table index k[c] (the low byte of
 * the hash of the corner's three cells), its weight w[c] (the s-curves' product, x by y then by
 * z) and the offset of p from it, (dx[cx], dy[cy], dz[cz]). The hash's first two levels are
 * shared by the corners that share them (14 lookups, not 24; the same indices). */
typedef struct {
	int k[8];
	double w[8];
	double dx[2], dy[2], dz[2];
} pov_blend;

static void pov_blend_at(dvec3 p, pov_blend *b)
{
	pthread_once(&pov_hash_once, pov_hash_init);
	double fx, fy, fz;
	int ix = pov_cell(clamp_coord(p.x), &fx), iy = pov_cell(clamp_coord(p.y), &fy), iz = pov_cell(clamp_coord(p.z), &fz);
	double sx = scurve(fx), sy = scurve(fy), sz = scurve(fz);
	const double wx[2] = {1.0 - sx, sx}, wy[2] = {1.0 - sy, sy}, wz[2] = {1.0 - sz, sz};
	b->dx[0] = fx, b->dx[1] = fx - 1, b->dy[0] = fy, b->dy[1] = fy - 1, b->dz[0] = fz, b->dz[1] = fz - 1;
#pragma GCC unroll 2
	for (int cx = 0; cx < 2; cx++) {
		int hx = pov_hash[ix + cx];
#pragma GCC unroll 2
		for (int cy = 0; cy < 2; cy++) {
			int hxy = pov_hash[hx ^ (iy + cy)];
			double wxy = wx[cx] * wy[cy];
#pragma GCC unroll 2
			for (int cz = 0; cz < 2; cz++) {
				int c = cx + 2 * cy + 4 * cz;
				b->k[c] = pov_hash[hxy ^ (iz + cz)] & 0xFF;
				b->w[c] = wxy * wz[cz];
			}
		}
	}
}

/* POV-Ray's linear function of corner table index k at the offset (x, y, z) from the corner. */
static double pov_linear(int k, double x, double y, double z)
{
	return 0.5 * pov_rtable[k] + pov_rtable[k + 1] * x + pov_rtable[k + 2] * y + pov_rtable[k + 3] * z;
}

double noise_pov(dvec3 p)
{
	pov_blend b;
	pov_blend_at(p, &b);
	double sum = 0.0;
#pragma GCC unroll 8
	for (int c = 0; c < 8; c++)
		sum += b.w[c] * pov_linear(b.k[c], b.dx[c & 1], b.dy[c >> 1 & 1], b.dz[c >> 2]);
	sum = (sum + 1.05242) * 0.48985582;
	return sum < 0.0 ? 0.0 : sum > 1.0 ? 1.0 : sum;
}

dvec3 noise_pov_vector(dvec3 p)
{
	pov_blend b;
	pov_blend_at(p, &b);
	dvec3 r = d3(0.0, 0.0, 0.0);
	for (int c = 0; c < 8; c++) {
		double x = b.dx[c & 1], y = b.dy[c >> 1 & 1], z = b.dz[c >> 2];
		r.x += b.w[c] * pov_linear(b.k[c], x, y, z);
		r.y += b.w[c] * pov_linear(b.k[c] + 4, x, y, z);
		r.z += b.w[c] * pov_linear(b.k[c] + 8, x, y, z);
	}
	return r;
}

/* ---- POV-Ray 3.7's random numbers of cells and crackle ----
 * pattern.cpp's gPatternRands: the first outputs of the Mersenne Twister MT19937 (Matsumoto and
 * Nishimura 1998) from its standard seed 5489, each over 2^32 (boost's uniform_real in [0, 1)
 * from one 32-bit draw), indexed by Hash3d: the permutation above applied to the cell's three
 * coordinates in turn, each taken mod 4096. Indices reach 4095 + 2. */
#define POV_RANDS 4098
static double pov_rands[POV_RANDS];
static pthread_once_t pov_rands_once = PTHREAD_ONCE_INIT;

static void pov_rands_init(void)
{
	uint32_t mt[624];
	mt[0] = 5489u;
	for (int i = 1; i < 624; i++)
		mt[i] = 1812433253u * (mt[i - 1] ^ (mt[i - 1] >> 30)) + (uint32_t)i;
	int next = 624;
	for (int n = 0; n < POV_RANDS; n++) {
		if (next == 624) { /* the twist: a new block of 624 */
			for (int i = 0; i < 624; i++) {
				uint32_t y = (mt[i] & 0x80000000u) | (mt[(i + 1) % 624] & 0x7fffffffu);
				mt[i] = mt[(i + 397) % 624] ^ (y >> 1) ^ ((y & 1u) ? 0x9908b0dfu : 0u);
			}
			next = 0;
		}
		uint32_t y = mt[next++];
		y ^= y >> 11;
		y ^= (y << 7) & 0x9d2c5680u;
		y ^= (y << 15) & 0xefc60000u;
		y ^= y >> 18;
		pov_rands[n] = (double)y / 4294967296.0;
	}
}

int noise_pov_hash3(int x, int y, int z)
{
	pthread_once(&pov_hash_once, pov_hash_init);
	return pov_hash[pov_hash[pov_hash[x & 0xFFF] ^ (y & 0xFFF)] ^ (z & 0xFFF)];
}

double noise_pov_rand(int i)
{
	pthread_once(&pov_rands_once, pov_rands_init);
	return i >= 0 && i < POV_RANDS ? pov_rands[i] : 0.0;
}
