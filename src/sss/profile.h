/* profile.h - radial diffusion profiles R(r) of the BSSRDF (DESIGN.md, "Subsurface scattering"):
 * gaussian, sum_of_gaussians, burley, dipole. Each channel's profile integrates to its albedo A,
 * is sampled exactly in r with pdf p(r) proportional to 2 pi r R(r), and is truncated at r_max.
 * Formulas, sources and the parameter links are in src/sss/README.md. All functions are pure
 * (thread-safe) and allocate nothing; the structs are plain data. */
#ifndef CIRCE_SSS_PROFILE_H
#define CIRCE_SSS_PROFILE_H

#include "base/vec.h"

#include <stdbool.h>

typedef enum sss_profile_kind {
	SSS_PROFILE_GAUSSIAN,
	SSS_PROFILE_SUM_OF_GAUSSIANS,
	SSS_PROFILE_BURLEY,
	SSS_PROFILE_DIPOLE,
} sss_profile_kind;
/* The number of kinds (a #define, not an enumerator: switches over the kinds stay complete). */
#define SSS_PROFILE_KINDS 4

/* The tail left out by truncation: the untruncated CDF reaches 1 - SSS_PROFILE_TAIL at r_max.
 * Both R and p are renormalised over [0, r_max] (divided by 1 - SSS_PROFILE_TAIL), so the
 * truncated profile still integrates to A and sampling, pdf and R agree exactly. */
#define SSS_PROFILE_TAIL 1e-3

/* Entries of the dipole's CDF table: half-octave steps in r below r_max. */
#define SSS_DIPOLE_TABLE 48

/* The artist form's largest alpha': A = 1 with a finite l_d = 1/sigma_tr would need sigma_a = 0
 * and sigma_t' infinite; alpha' stays this close to 1 instead (R_d then falls short of 1 by
 * about 1e-5). */
#define SSS_ALPHA_PRIME_MAX (1.0 - 1e-12)

/* Components of a Gaussian mixture (d'Eon & Luebke's skin fit has six). */
#define SSS_PROFILE_MAX_GAUSSIANS 6

/* One colour channel of a profile. Plain data: copy it freely; no allocation anywhere. */
typedef struct sss_channel {
	sss_profile_kind kind;
	double albedo;	 /* A in [0, 1]: integral of R(r) 2 pi r dr */
	double r_max_mm; /* truncation radius, > 0 */
	double norm;	 /* untruncated CDF at r_max = 1 - SSS_PROFILE_TAIL (renormalisation) */
	union {
		struct { /* gaussian, sum_of_gaussians: sum_i w_i e^{-r^2/(2 v_i)} / (2 pi v_i) */
			int n;
			double v_mm2[SSS_PROFILE_MAX_GAUSSIANS];
			double w[SSS_PROFILE_MAX_GAUSSIANS]; /* sum to 1 */
		} gauss;
		struct { /* burley: (e^{-r/d} + e^{-r/(3d)}) / (8 pi d r) */
			double d_mm;
		} burley;
		struct {		    /* dipole (Jensen et al. 2001, eq. 4), in units of mm */
			double alpha_prime; /* reduced single-scattering albedo sigma_s'/sigma_t' */
			double sigma_tr;    /* effective transport coefficient, per mm */
			double z_r, z_v;    /* real and virtual source depths, mm */
			/* untruncated CDF at r_max 2^{-k/2}, k = SSS_DIPOLE_TABLE - 1 - i: the sampler's
			 * starting bracket, refined by Newton's method on the exact CDF */
			double table_cdf[SSS_DIPOLE_TABLE];
		} dipole;
	};
} sss_channel;

/* An RGB profile: three channels and the probabilities of choosing each for sampling r
 * (proportional to the channel albedos, uniform when all are zero). The pdf of r is the mixture
 * sum_c q_c p_c(r): one-sample MIS over channels with the balance heuristic. */
typedef struct sss_profile {
	sss_channel ch[3];
	double q[3];
} sss_profile;

/* ---- the medium -> profile links (README.md: "Parameters") ----------------------------------- */

/* Unpolarised Fresnel reflectance of a smooth dielectric boundary for incidence cosine mu >= 0
 * and relative index eta (transmitted over incident side); 1 under total internal reflection. */
double sss_fresnel_dielectric(double mu, double eta);
/* First Fresnel moment FM1(eta) = integral_0^1 F(mu) mu dmu of the exact unpolarised dielectric
 * Fresnel reflectance, eta = n_transmitted / n_incident (> 0). Light inside a medium of index
 * eta hitting its boundary sees FM1(1/eta); its diffuse reflectance is F_dr = 2 FM1(1/eta). */
double sss_fresnel_moment1(double eta);

/* Jensen et al. 2001 total diffuse reflectance of the dipole (their eq. 5 integrated, section
 * 2.4): R_d = alpha'/2 (1 + e^{-4/3 A_F sqrt(3(1 - alpha'))}) e^{-sqrt(3(1 - alpha'))}, with
 * A_F = (1 + F_dr)/(1 - F_dr). Monotone in alpha' in [0, 1]; 0 at 0 and 1 at 1. */
double sss_dipole_albedo(double alpha_prime, double eta);
/* The inverse of sss_dipole_albedo in alpha' (bisection to 1e-15), for albedo in [0, 1]. */
double sss_dipole_alpha_prime(double albedo, double eta);
/* The same inverse for a given boundary term A_F = (1 + F_dr)/(1 - F_dr) (>= 1) instead of eta's
 * exact one: POV-Ray's translucency (medium.h) takes its own F_dr. */
double sss_dipole_alpha_prime_af(double albedo, double a_f);

/* Builds one channel from the physical form: reduced scattering and absorption coefficients in
 * mm^-1 and the relative index of refraction eta of the boundary. The multiple-scattering
 * albedo is A = sss_dipole_albedo(sigma_s'/sigma_t', eta) and the diffuse mean free path is
 * l_d = 1/sigma_tr = 1/sqrt(3 sigma_a sigma_t') (mm). `channel` (0 r, 1 g, 2 b) picks d'Eon &
 * Luebke's weights for sum_of_gaussians. Returns false (and leaves *out untouched) on negative
 * or non-finite coefficients, sigma_t' = 0, eta <= 0, or sigma_a = 0 for any kind but the
 * dipole (l_d would be infinite). */
bool sss_channel_from_physical(sss_channel *out, sss_profile_kind kind, int channel,
			       double sigma_s_prime_per_mm, double sigma_a_per_mm, double eta);
/* Builds one channel from the artist form: multiple-scattering albedo A in [0, 1] and "radius"
 * ld_mm, the diffuse mean free path l_d = 1/sigma_tr in mm (> 0): Jensen & Buhler 2002's
 * convention, the scene's radius_mm. The medium is sigma_t' = 1/(l_d sqrt(3 (1 - alpha'))) with
 * alpha' inverting sss_dipole_albedo (held below 1 at A = 1). Returns false on out-of-range input. */
bool sss_channel_from_artist(sss_channel *out, sss_profile_kind kind, int channel, double albedo,
			     double ld_mm, double eta);

/* Builds the RGB profile from three channels (fills q). */
sss_profile sss_profile_make(const sss_channel ch[3]);
/* The RGB profile from per-channel physical or artist parameters (the channel functions above,
 * channel c from element c); false when any channel is refused. */
bool sss_profile_from_physical(sss_profile *out, sss_profile_kind kind, const double sigma_s_prime_per_mm[3],
			       const double sigma_a_per_mm[3], double eta);
bool sss_profile_from_artist(sss_profile *out, sss_profile_kind kind, const double albedo[3],
			     const double ld_mm[3], double eta);

/* ---- one channel ------------------------------------------------------------------------------ */

/* R(r) in mm^-2, truncated and renormalised: 0 beyond r_max; the paper's formula otherwise.
 * burley and dipole grow like 1/r at r = 0 (burley is +Inf there). */
double sss_channel_eval(const sss_channel *c, double r_mm);
/* Pdf of r in mm^-1 on [0, r_max], = 2 pi r R(r) / A (defined for A = 0 as the limit shape). */
double sss_channel_pdf(const sss_channel *c, double r_mm);
/* Integral of the pdf from 0 to r; 1 from r_max on. */
double sss_channel_cdf(const sss_channel *c, double r_mm);
/* Exact sample of r in (0, r_max] from u in [0, 1). */
double sss_channel_sample(const sss_channel *c, double u);

/* ---- RGB, one-sample MIS over channels -------------------------------------------------------- */

/* Samples r: u_channel picks the channel by q, u_r the radius in it. */
double sss_profile_sample(const sss_profile *p, double u_channel, double u_r);
/* The mixture pdf sum_c q_c p_c(r), in mm^-1. */
double sss_profile_pdf(const sss_profile *p, double r_mm);
/* R(r) per channel, mm^-2. */
vec3 sss_profile_eval(const sss_profile *p, double r_mm);
/* 2 pi r R_c(r) / pdf(r) per channel: the profile's Monte Carlo weight for a sample r of the
 * mixture (= A_c p_c(r) / sum_k q_k p_k(r)), finite for every sampled r, bounded by sum_c A_c
 * (the q are proportional to A). Zero where the pdf is zero. */
vec3 sss_profile_ratio(const sss_profile *p, double r_mm);
/* The largest channel truncation radius: no sample lies beyond it. */
double sss_profile_r_max(const sss_profile *p);

#endif
