/* noise.h - Perlin's improved noise ("Improving Noise", SIGGRAPH 2002): the one lattice noise of
 * circe, under the noise patterns (scene/pattern.c) and the language's f_noise3d (lang/func.c). */
#ifndef CIRCE_BASE_NOISE_H
#define CIRCE_BASE_NOISE_H

#include "base/vec.h"

/* Perlin's improved noise at p, in about [-1, 1]; coordinates are clamped to +-1e9 first. */
double noise_perlin(dvec3 p);
/* Perlin's permutation table at i & 255. */
int noise_perm(int i);

#endif
