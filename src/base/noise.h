/* noise.h - POV-Ray 3.7's lattice noise, under the noise patterns (scene/pattern.c) and the
 * language's f_noise3d (lang/func.c), and Perlin's improved noise ("Improving Noise", 2002). */
#ifndef CIRCE_BASE_NOISE_H
#define CIRCE_BASE_NOISE_H

#include "base/vec.h"

/* Perlin's improved noise at p, in about [-1, 1]; coordinates are clamped to +-1e9 first. */
double noise_perlin(dvec3 p);
/* Perlin's permutation table at i & 255. */
int noise_perm(int i);

/* POV-Ray 3.7's noise (noise_generator 2, its default) at p, in [0, 1]: the value of its bozo,
 * f_noise3d and so on, the same numbers as POV-Ray's own (noise.c says how). */
double noise_pov(dvec3 p);
/* POV-Ray 3.7's vector noise (DNoise) at p: each component a lattice sum, about [-0.5, 0.5]. */
dvec3 noise_pov_vector(dvec3 p);
/* POV-Ray's Hash3d of a lattice cell: its permutation over x, y, z (each mod 4096), in 0..4095. */
int noise_pov_hash3(int x, int y, int z);
/* POV-Ray's gPatternRands at i (0 <= i < 4098; 0 elsewhere): MT19937's i-th output over 2^32. */
double noise_pov_rand(int i);

#endif
