/* medium.h - the one owner of an SSS material's physics: the measured presets, the names of the
 * SSS methods and profiles, and the single derivation of a medium's two forms (physical:
 * reduced scattering sigma_s' and absorption sigma_a in mm^-1; artist: diffuse albedo A and
 * diffuse mean free path l_d in mm) from what a scene wrote. The scene IR keeps what was written
 * (an sss_medium_spec); the build calls sss_medium_derive. Pure functions, no allocation. */
#ifndef CIRCE_SSS_MEDIUM_H
#define CIRCE_SSS_MEDIUM_H

#include "base/vec.h"
#include "sss/profile.h"

#include <stdbool.h>

/* ---- the names ---------------------------------------------------------------------------------- */

/* How a subsurface material finds its entry point (src/sss: circle.*, disk.*, walk.*). */
typedef enum sss_method {
	SSS_METHOD_DEFAULT,    /* a material's: whatever the command line says (circle without --sss) */
	SSS_METHOD_CIRCLE,     /* half circles (Legros & Corvazier 2016) */
	SSS_METHOD_FULLCIRCLE, /* full circles */
	SSS_METHOD_DISK,       /* King et al. 2013 probe segments */
	SSS_METHOD_VOLUME,     /* random walk in the medium: the reference the profiles approximate */
	SSS_METHOD_AUTO,       /* per exit point: circle where the object is thick, the walk where thin */
} sss_method;
/* The number of methods, default included (a #define: switches over them stay complete). */
#define SSS_METHODS 6

/* "default", "circle", "fullcircle", "disk", "volume", "auto"; "?" out of range. */
const char *sss_method_name(sss_method m);
/* The method of that name (the table of sss_method_name); false when none is. */
bool sss_method_from_name(const char *name, sss_method *m);

/* "gaussian", "sum_of_gaussians", "burley", "dipole" (the scene language's words); "?" out of range. */
const char *sss_profile_name(sss_profile_kind k);
bool sss_profile_from_name(const char *name, sss_profile_kind *k);

/* ---- auto: the choice between circle tracing and the walk ------------------------------------------ */

/* The rule of `auto` (src/sss/README.md, "auto"): at an exit point whose object is `m` diffuse
 * mean free paths thick below it (the thickness along the inward normal over the largest channel's
 * l_d), the walk is taken with probability 1 up to SSS_AUTO_WALK_BELOW, 0 from SSS_AUTO_CIRCLE_ABOVE
 * on, and in between 1 - smoothstep of log m across the band (continuous with a continuous slope:
 * no seam where the choice changes). m = +Inf (nothing below: an open surface) gives 0; NaN or
 * m <= 0 gives 1. */
#define SSS_AUTO_WALK_BELOW 5.0
#define SSS_AUTO_CIRCLE_ABOVE 10.0
double sss_auto_walk_prob(double m);

/* The light factor of `auto` (src/sss/README.md, "auto"): f is the share of the light leaving an
 * exit point that the profile misses, estimated from the unshadowed irradiance of the far side
 * (where the thickness ray leaves the object) and of the exit point's own side,
 * f = E_far T / (E_near R + E_far T) with the diffusion slab's T and R below. The walk's probability is multiplied by 0 for
 * f <= SSS_AUTO_LIGHT_CIRCLE, 1 for f >= SSS_AUTO_LIGHT_WALK, and smoothstep of log f across the
 * band between (continuous with a continuous slope); NaN gives 1, the safe side. */
#define SSS_AUTO_LIGHT_CIRCLE 0.01
#define SSS_AUTO_LIGHT_WALK 0.1
/* The far side's cosine is wrapped, (cos + w) / (1 + w) clamped at 0: light entering near the far
 * point but past its terminator diffuses to it (the sides of a back-lit finger). */
#ifndef SSS_AUTO_LIGHT_WRAP
#define SSS_AUTO_LIGHT_WRAP 0.5f
#endif
double sss_auto_light_prob(double f);
/* The profile's tail (issue 21, src/sss/README.md "auto"): where the object below the exit is
 * thinner than the distance within which the profile lays down all but a few per cent of its
 * light, the profile's half space is not there whatever the light (the bench's lips, skin lit from
 * the front, 2 to 3 l_d of red thick: circle -15 % against the walk). The walk is taken with
 * probability at least sss_auto_thin_prob: 1 up to the thickness where the largest channel's tail
 * 1 - CDF(L) is SSS_AUTO_TAIL_WALK, 0 from where it is SSS_AUTO_TAIL_CIRCLE on, and 1 - smoothstep
 * of log L between (continuous with a continuous slope). */
#define SSS_AUTO_TAIL_WALK 0.05
#define SSS_AUTO_TAIL_CIRCLE 0.02
/* The smallest thickness L (mm) at which every channel of albedo > 0 has 1 - CDF(L) <= tail
 * (0 < tail < 1; 0 when no channel has an albedo). */
double sss_auto_tail_thickness(const sss_profile *p, double tail);
/* From the thickness L and the two thicknesses above (any one unit; l_walk <= l_circle): NaN or
 * L <= l_walk gives 1, L >= l_circle (or l_circle <= 0) gives 0. */
double sss_auto_thin_prob(double L, double l_walk, double l_circle);
/* What a slab of the medium sends out of each side (src/sss/README.md, "auto": the diffusion
 * slab), per channel: the 1D diffusion solution between the extrapolated boundaries (zero
 * fluence at z_b = 2 A D outside each face, D = 1/(3 sigma_t'), A = (1 + F_dr)/(1 - F_dr) from the
 * exact FM1) of a source at z_0 = 1/sigma_t' below the lit face: of what scatters there, the
 * far face's share is sinh(sigma_tr s)/sinh(sigma_tr d) (transmission, T) and the lit face's
 * sinh(sigma_tr (d - s))/sinh(sigma_tr d) (reflection, R), s = z_0 + z_b, d = L + 2 z_b. Lengths in
 * mm. The parameters of one material: */
typedef struct sss_auto_slab {
	double sigma_tr[3]; /* per mm; 0: no absorption (the linear limit s/d) */
	double src[3];	    /* s - L-independent part: z_0 + z_b, mm */
	double ext[3];	    /* 2 z_b, mm */
} sss_auto_slab;
/* From the physical form (sigma_s', sigma_a per mm) and the boundary's eta; false when a channel
 * has no extinction. */
bool sss_auto_slab_make(sss_auto_slab *s, const double sigma_s_prime_per_mm[3], const double sigma_a_per_mm[3],
			double eta);
/* T and R of channel c for a slab L mm thick (L >= 0; +Inf: T = 0). */
void sss_auto_slab_tr(const sss_auto_slab *s, int c, double L_mm, double *t, double *r);
/* f from the two irradiances (any common unit, >= 0) and the thickness in mm: the largest over
 * the channels of E_far T_c / (E_near R_c + E_far T_c) (the channel that carries the most light
 * through: the safe side); 0 when the far side is unlit. */
double sss_auto_light_share(const sss_auto_slab *s, double e_near, double e_far, double L_mm);

/* ---- the presets ---------------------------------------------------------------------------------- */

/* Jensen et al. 2001 measured coefficients (their Figure 5), with the eta their Rd column implies. */
typedef struct sss_preset {
	const char *name;
	float sigma_s_per_mm[3], sigma_a_per_mm[3];
	float eta;
} sss_preset;
extern const sss_preset sss_presets[];
extern const int sss_n_presets;
/* NULL when the name is not a preset's. */
const sss_preset *sss_preset_find(const char *name);

/* ---- a medium as written, and its derivation ------------------------------------------------------ */

/* Which form the scene wrote; the other is derived. */
typedef enum sss_form { SSS_FORM_DEFAULT, SSS_FORM_PHYSICAL, SSS_FORM_ARTIST } sss_form;

/* Which parameters of an sss_medium_spec hold a value (written, or the block's default). */
enum { SSS_HAS_SIGMA_S = 1, SSS_HAS_SIGMA_A = 2, SSS_HAS_ALBEDO = 4, SSS_HAS_RADIUS = 8 };

/* A medium as the scene wrote it: a preset (the physical base), the parameters that hold a value
 * (`has`), and the form they were written in. */
typedef struct sss_medium_spec {
	const char *preset; /* a name sss_preset_find knows, or NULL */
	sss_form form;	    /* DEFAULT: nothing written, the base (preset, or albedo and radius) alone */
	unsigned has;	    /* SSS_HAS_*: the others are derived */
	vec3 sigma_s_per_mm, sigma_a_per_mm; /* reduced scattering sigma_s', absorption sigma_a */
	vec3 albedo;			     /* diffuse (multiple-scattering) reflectance A, in [0, 1] */
	vec3 radius_mm;			     /* diffuse mean free path l_d = 1 / sigma_tr, > 0 */
} sss_medium_spec;

/* Both forms, per channel. */
typedef struct sss_medium {
	double sigma_s_per_mm[3], sigma_a_per_mm[3];
	double albedo[3], ld_mm[3];
} sss_medium;

/* Physical -> artist, one channel: A = sss_dipole_albedo(sigma_s'/sigma_t', eta) (exact FM1) and
 * l_d = 1/sqrt(3 sigma_a sigma_t') (Jensen et al. 2001, section 2.4; +Inf when sigma_a = 0). */
void sss_medium_to_artist(double sigma_s, double sigma_a, double eta, double *albedo, double *ld_mm);
/* Artist -> physical, one channel: alpha' = sss_dipole_alpha_prime(A, eta), held at or below the
 * profiles' SSS_ALPHA_PRIME_MAX as sss_channel_from_artist holds it, then sigma_t' =
 * 1/(l_d sqrt(3 (1 - alpha'))) (Jensen & Buhler 2002, section 4). ld_mm > 0. */
void sss_medium_to_physical(double albedo, double ld_mm, double eta, double *sigma_s, double *sigma_a);

/* The medium of a spec, boundary index eta: the base's two forms (the preset's coefficients and
 * their artist form, or without a preset the spec's albedo and radius and their physical form);
 * then the written form, each parameter the spec's where it has one and the base's where not; then
 * the other form derived from it. The preset, when there is one, must be known (asserted). */
void sss_medium_derive(const sss_medium_spec *s, double eta, sss_medium *out);

/* ---- POV-Ray's subsurface { translucency } ------------------------------------------------------ */

/* POV-Ray 3.7's own approximation of the diffuse Fresnel reflectance F_dr (core/lighting/
 * subsurface.h FresnelDiffuseReflectance, which replaces JMLH01's polynomial): for eta >= 1
 * ((1 - 1/eta) + 3 (1 - 1/eta)^4.5) / 4, below 1 eta^2 - eta^2.25. 0 at eta = 1. */
double sss_pov_fresnel_diffuse(double eta);
/* The reduced albedo alpha' POV-Ray gives a diffuse reflectance R_d in [0, 1] (subsurface.cpp
 * PrecomputedReducedAlbedo, which tabulates it at 100 steps): the inverse of JMLH01's R_d(alpha')
 * (sss_dipole_albedo's formula) with A_F = (1 + F)/(1 - F), F = sss_pov_fresnel_diffuse(eta);
 * here by bisection to 1e-15, held at SSS_ALPHA_PRIME_MAX. */
double sss_pov_alpha_prime(double rd, double eta);
/* The diffuse mean free path l_d = 1/sigma_tr (mm) of POV-Ray's medium for a translucency T (mm)
 * and the diffuse reflectance rd = pigment * finish diffuse, boundary eta (trace.cpp
 * ComputeSubsurfaceScattering: sigma_s' = 1/T, sigma_t' = sigma_s'/alpha', sigma_a = sigma_t' -
 * sigma_s', sigma_tr = sqrt(3 sigma_a sigma_t')), in closed form T alpha' / sqrt(3 (1 - alpha')).
 * An rd of 0 gives l_d 0, which no profile takes: l_d is held at SSS_POV_MIN_RADIUS_FRACTION T
 * (such a channel reflects nothing, so its radius is never seen). T > 0. */
double sss_pov_translucency_radius_mm(double rd, double translucency_mm, double eta);
#define SSS_POV_MIN_RADIUS_FRACTION 1e-9
/* POV-Ray's brightness of a subsurface surface over circe's BSSRDF of the same medium, one
 * channel of diffuse reflectance rd = pigment * diffuse (doc/language.md "POV-Ray's subsurface",
 * "Brightness"): the factor that makes a flat surface lit and seen along its normal show what
 * POV-Ray 3.7 shows there. POV-Ray's light there is Ft(0)^2 (k rd + alpha'/24) (trace.cpp
 * ComputeSubsurfaceScattering: its diffuse term's estimate, k times the dipole's R_d, and its
 * single scattering, alpha'/24 with s ~ exp(-sigma_t s), sigma_tc = 2 sigma_t and p = 1/4 in
 * its units), circe's Ft(0)^2 rd / (1 - 2 FM1(eta)) (f_t's normalisation), so the factor is
 * (1 - 2 FM1(eta)) (k + alpha'(rd)/(24 rd)), alpha' sss_pov_alpha_prime's. k is 1 over the
 * fraction of POV-Ray's probe rays that meet a surface, as its estimate divides by those only:
 * 1 on a closed object, 2 under a plane (half of them find nothing). rd is held at >=
 * SSS_POV_GAIN_MIN_RD (the ratio's limit at 0 is finite). eta > 0. */
double sss_pov_gain(double rd, double eta, double k);
#define SSS_POV_GAIN_MIN_RD 1e-6

#endif
