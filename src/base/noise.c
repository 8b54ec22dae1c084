/* noise.c - Perlin's improved noise (the lattice under POV-Ray's noise patterns and f_noise3d),
 * moved here from render/pattern.c so the scene language's functions share it. */
#include "base/noise.h"

#include <math.h>

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

