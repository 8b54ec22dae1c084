/* media.h - POV-Ray's participating media (interior { media { ... } }) as a physical medium:
 * absorption, emission and scattering coefficients per scene unit, each scaled by a density (a
 * product of patterns, 1 when none), summed over the media of one interior. A path inside a
 * container is tracked by delta tracking against a majorant (Woodcock 1965; the weighted form of
 * Galtier et al. 2013 / Novák et al. 2018, "Monte Carlo methods for volumetric light transport
 * simulation", sec. 5): at each tentative collision the emission is collected, then a real
 * scattering or a null collision is chosen and the throughput weighted so the estimate stays
 * unbiased for any majorant >= the extinction. Shadow rays take the transmittance by ratio
 * tracking (exactly exp(-sigma_t d) in a homogeneous medium). A medium that does not scatter
 * and is homogeneous is integrated in closed form. Phase functions are POV-Ray's five types
 * (core/material/media.cpp), each normalised to a density over the sphere and sampled exactly. */
#ifndef CIRCE_RENDER_MEDIA_H
#define CIRCE_RENDER_MEDIA_H

#include "base/rng.h"
#include "base/vec.h"

#include <stdbool.h>
#include <stdint.h>

/* Media of one interior, densities of one media (POV-Ray has no limit; the parser states these). */
#define RENDER_MEDIA_MAX 8
#define RENDER_MEDIUM_MAX_DENSITIES 8

/* POV-Ray's scattering types, by their numbers. */
typedef enum render_phase {
	RENDER_PHASE_ISOTROPIC = 1,
	RENDER_PHASE_MIE_HAZY = 2,
	RENDER_PHASE_MIE_MURKY = 3,
	RENDER_PHASE_RAYLEIGH = 4,
	RENDER_PHASE_HG = 5
} render_phase;

typedef struct render_medium {
	vec3 absorption, emission, scattering; /* per scene unit at density 1; emission: radiance per unit */
	float extinction;		       /* POV-Ray's: sigma_t = absorption + extinction * scattering */
	render_phase phase;
	float g; /* RENDER_PHASE_HG's eccentricity, in (-1, 1) */
	uint32_t density[RENDER_MEDIUM_MAX_DENSITIES]; /* pattern nodes whose colours multiply */
	uint32_t n_density;			       /* 0: density 1 everywhere */
	vec3 density_max; /* a bound of the density product (the scene's density callback clamps to it) */
} render_medium;

typedef struct render_media {
	render_medium m[RENDER_MEDIA_MAX];
	uint32_t n;
	float majorant;	   /* >= every channel of sigma_t anywhere in the container (render_media_finish) */
	bool homogeneous;  /* no medium has a density pattern */
	bool scatters, emits;
} render_media;

/* The density of medium m at world point p, each channel in [0, m->density_max]. */
typedef vec3 (*render_density_fn)(const void *ctx, const render_medium *m, vec3 p);

/* The coefficients at one point. */
typedef struct render_media_coef {
	vec3 sigma_t, emission, sigma_s;
	vec3 sigma_s_of[RENDER_MEDIA_MAX]; /* each medium's part of sigma_s */
} render_media_coef;

/* Sets majorant, homogeneous, scatters and emits from md's media. */
void render_media_finish(render_media *md);

/* The coefficients at p (density from f, unused when md is homogeneous). */
void render_media_coef_at(const render_media *md, render_density_fn f, const void *ctx, vec3 p, render_media_coef *c);

/* The phase function of kind k as a density per steradian of mu, the cosine between the
 * direction light travelled in and the one it leaves in (1: straight on, POV-Ray's alpha). */
float render_phase_pdf(render_phase k, float g, float mu);
/* A mu drawn from render_phase_pdf exactly (u in [0, 1)). */
float render_phase_sample_mu(render_phase k, float g, float u);

/* The emission gathered per unit length when the extinction is below this rate: an emitting
 * medium of little extinction is still sampled about RENDER_MEDIA_EMIT_STEPS times per segment. */
#define RENDER_MEDIA_EMIT_STEPS 8.0f
/* No segment is tracked through more tentative collisions than this (then its weight is 0). */
#define RENDER_MEDIA_MAX_STEPS 100000

/* Tracks a path through md along o + t d (d unit), t in [0, tmax] (finite): adds the emission
 * on the way, times *beta, to *radiance, and weights *beta. True when the path scatters at
 * *t_out (then *c holds the coefficients there and *beta already carries 1 / (majorant P_s):
 * render_media_phase_eval's value completes the weight). False when it reaches tmax (or its
 * weight became 0). */
bool render_media_track(const render_media *md, render_density_fn f, const void *ctx, vec3 o, vec3 d, float tmax,
			rng *g, vec3 *beta, vec3 *radiance, render_media_coef *c, float *t_out);

/* The transmittance of md over o + t d, t in [0, tmax]: exact when homogeneous, ratio tracking
 * (unbiased) otherwise. */
vec3 render_media_transmittance(const render_media *md, render_density_fn f, const void *ctx, vec3 o, vec3 d,
				float tmax, rng *g);

/* At a scattering point with coefficients c, a path that arrived along d_in: the scattering
 * sum_i sigma_s_i p_i(mu) towards wi (unit) and the density *pdf of render_media_phase_sample. */
vec3 render_media_phase_eval(const render_media *md, const render_media_coef *c, vec3 d_in, vec3 wi, float *pdf);
/* A direction drawn from the mixture of the media's phase functions (each chosen by its
 * share of sigma_s), its scattering value and density as render_media_phase_eval's. False when
 * nothing scatters there. */
bool render_media_phase_sample(const render_media *md, const render_media_coef *c, vec3 d_in, float u_pick, vec2 u,
			       vec3 *wi, vec3 *fval, float *pdf);

#endif
