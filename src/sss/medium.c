/* medium.c - the SSS presets, the names of methods and profiles, and the one derivation of a
 * medium's physical and artist forms. Sources: H. W. Jensen, S. R. Marschner, M. Levoy,
 * P. Hanrahan, "A Practical Model for Subsurface Light Transport", SIGGRAPH 2001 (JMLH01);
 * H. W. Jensen, J. Buhler, "A Rapid Hierarchical Rendering Technique for Translucent Materials",
 * SIGGRAPH 2002 (JB02). The dipole's albedo and its inverse are profile.c's (exact FM1). */
#include "sss/medium.h"

#include <assert.h>
#include <math.h>
#include <string.h>

static const char *const method_names[SSS_METHODS] = {"default", "circle", "fullcircle", "disk", "volume", "auto"};
static const char *const profile_names[SSS_PROFILE_KINDS] = {"gaussian", "sum_of_gaussians", "burley", "dipole"};

/* The index of name in names[0, n), or -1. */
static int name_index(const char *const *names, int n, const char *name)
{
	for (int i = 0; i < n; i++)
		if (!strcmp(name, names[i]))
			return i;
	return -1;
}

const char *sss_method_name(sss_method m)
{
	return (unsigned)m < SSS_METHODS ? method_names[m] : "?";
}

bool sss_method_from_name(const char *name, sss_method *m)
{
	int i = name_index(method_names, SSS_METHODS, name);
	if (i >= 0)
		*m = (sss_method)i;
	return i >= 0;
}

double sss_auto_walk_prob(double m)
{
	if (!(m > SSS_AUTO_WALK_BELOW)) /* NaN too: an unknown thickness walks, the safe side */
		return 1.0;
	if (!(m < SSS_AUTO_CIRCLE_ABOVE))
		return 0.0;
	double x = log(m / SSS_AUTO_WALK_BELOW) / log(SSS_AUTO_CIRCLE_ABOVE / SSS_AUTO_WALK_BELOW);
	return 1.0 - x * x * (3.0 - 2.0 * x);
}

double sss_auto_light_prob(double f)
{
	if (!(f < SSS_AUTO_LIGHT_WALK)) /* NaN too */
		return 1.0;
	if (!(f > SSS_AUTO_LIGHT_CIRCLE))
		return 0.0;
	double x = log(f / SSS_AUTO_LIGHT_CIRCLE) / log(SSS_AUTO_LIGHT_WALK / SSS_AUTO_LIGHT_CIRCLE);
	return x * x * (3.0 - 2.0 * x);
}

bool sss_auto_slab_make(sss_auto_slab *s, const double sigma_s_prime_per_mm[3], const double sigma_a_per_mm[3],
			double eta)
{
	/* the boundary term A = (1 + F_dr)/(1 - F_dr), F_dr = 2 FM1(1/eta) (profile.h) */
	double fdr = 2.0 * sss_fresnel_moment1(1.0 / eta), a_f = (1.0 + fdr) / (1.0 - fdr);
	for (int c = 0; c < 3; c++) {
		double sa = fmax(0.0, sigma_a_per_mm[c]), st = fmax(0.0, sigma_s_prime_per_mm[c]) + sa;
		if (!(st > 0.0) || !isfinite(st))
			return false;
		double d = 1.0 / (3.0 * st), zb = 2.0 * a_f * d;
		s->sigma_tr[c] = sqrt(sa / d);
		s->src[c] = 1.0 / st + zb;
		s->ext[c] = 2.0 * zb;
	}
	return true;
}

void sss_auto_slab_tr(const sss_auto_slab *s, int c, double L_mm, double *t, double *r)
{
	double L = fmax(0.0, L_mm), src = fmin(s->src[c], L + s->ext[c]), d = L + s->ext[c];
	double k = s->sigma_tr[c];
	if (!(L < INFINITY)) {
		*t = 0.0, *r = k > 0.0 ? exp(-k * src) : 1.0;
		return;
	}
	if (!(k * d > 1e-6)) { /* (nearly) no absorption: the linear limit */
		*t = src / d, *r = (d - src) / d;
		return;
	}
	/* sinh(a)/sinh(b) = e^{a-b} (1 - e^{-2a})/(1 - e^{-2b}): no overflow at any thickness */
	double den = -expm1(-2.0 * k * d);
	*t = exp(k * (src - d)) * -expm1(-2.0 * k * src) / den;
	*r = exp(-k * src) * -expm1(-2.0 * k * (d - src)) / den;
}

double sss_auto_light_share(const sss_auto_slab *s, double e_near, double e_far, double L_mm)
{
	double far = e_far > 0.0 ? e_far : 0.0, near = e_near > 0.0 ? e_near : 0.0; /* NaN or <= 0: unlit */
	if (!(far > 0.0) || !(L_mm < INFINITY))
		return 0.0; /* an unlit far side, or T = 0 in every channel */
	if (!(near > 0.0))
		return 1.0; /* all of the light is the far side's */
	/* f_c = far T / (near R + far T) = 1 / (1 + (near / far) (R / T)): only the ratio R / T of
	 * each channel, e^{k (d - 2 s)} (1 - e^{-2 k (d - s)}) / (1 - e^{-2 k s}) by
	 * sss_auto_slab_tr's formula, two exponentials where T and R take five (issue 21: the light
	 * share was 4.5 % of the wax sphere's render under auto, where nothing walks). */
	double L = fmax(0.0, L_mm), ratio = near / far, f = 0.0;
	for (int c = 0; c < 3; c++) {
		double k = s->sigma_tr[c], d = L + s->ext[c], src = fmin(s->src[c], d), rt;
		if (!(k * d > 1e-6))
			rt = src > 0.0 ? (d - src) / src : INFINITY; /* the linear limit */
		else
			rt = src > 0.0 ? exp(k * (d - 2.0 * src)) * -expm1(-2.0 * k * (d - src)) / -expm1(-2.0 * k * src)
				       : INFINITY;
		double fc = 1.0 / (1.0 + ratio * rt); /* rt = +Inf: 0 */
		if (fc > f)
			f = fc;
	}
	return f;
}

/* The largest tail 1 - CDF(L) over the channels that carry light. */
static double tail_at(const sss_profile *p, double L)
{
	double t = 0.0;
	for (int c = 0; c < 3; c++)
		if (p->ch[c].albedo > 0.0)
			t = fmax(t, 1.0 - sss_channel_cdf(&p->ch[c], L));
	return t;
}

double sss_auto_tail_thickness(const sss_profile *p, double tail)
{
	/* the tail falls with L and is 0 from the largest r_max on: bisection to a double's resolution */
	double lo = 0.0, hi = sss_profile_r_max(p);
	if (!(tail_at(p, 0.0) > tail))
		return 0.0;
	for (int i = 0; i < 200 && hi - lo > 1e-12 * hi; i++) {
		double mid = 0.5 * (lo + hi);
		if (tail_at(p, mid) > tail)
			lo = mid;
		else
			hi = mid;
	}
	return hi;
}

double sss_auto_thin_prob(double L, double l_walk, double l_circle)
{
	if (!(l_circle > 0.0) || L >= l_circle)
		return 0.0;
	if (!(L > l_walk)) /* NaN too */
		return 1.0;
	double x = log(L / l_walk) / log(l_circle / l_walk);
	return 1.0 - x * x * (3.0 - 2.0 * x);
}

const char *sss_profile_name(sss_profile_kind k)
{
	return (unsigned)k < SSS_PROFILE_KINDS ? profile_names[k] : "?";
}

bool sss_profile_from_name(const char *name, sss_profile_kind *k)
{
	int i = name_index(profile_names, SSS_PROFILE_KINDS, name);
	if (i >= 0)
		*k = (sss_profile_kind)i;
	return i >= 0;
}

/* JMLH01, Figure 5: sigma_s' and sigma_a in mm^-1 for R, G, B, with the eta their Rd column implies. */
const sss_preset sss_presets[] = {
	{"apple", {2.29f, 2.39f, 1.97f}, {0.0030f, 0.0034f, 0.046f}, 1.3f},
	{"chicken1", {0.15f, 0.21f, 0.38f}, {0.015f, 0.077f, 0.19f}, 1.3f},
	{"chicken2", {0.19f, 0.25f, 0.32f}, {0.018f, 0.088f, 0.20f}, 1.3f},
	{"cream", {7.38f, 5.47f, 3.15f}, {0.0002f, 0.0028f, 0.0163f}, 1.3f},
	{"ketchup", {0.18f, 0.07f, 0.03f}, {0.061f, 0.97f, 1.45f}, 1.3f},
	/* marble: the Rd column of Figure 5 is reproduced with eta 1.5 (1.3 gives 0.83/0.83/0.80). */
	{"marble", {2.19f, 2.62f, 3.00f}, {0.0021f, 0.0041f, 0.0071f}, 1.5f},
	{"potato", {0.68f, 0.70f, 0.55f}, {0.0024f, 0.0090f, 0.12f}, 1.3f},
	{"skimmilk", {0.70f, 1.22f, 1.90f}, {0.0014f, 0.0025f, 0.0142f}, 1.3f},
	{"skin1", {0.74f, 0.88f, 1.01f}, {0.032f, 0.17f, 0.48f}, 1.3f},
	{"skin2", {1.09f, 1.59f, 1.79f}, {0.013f, 0.070f, 0.145f}, 1.3f},
	{"wholemilk", {2.55f, 3.21f, 3.77f}, {0.0011f, 0.0024f, 0.014f}, 1.3f},
};
const int sss_n_presets = (int)(sizeof sss_presets / sizeof sss_presets[0]);

const sss_preset *sss_preset_find(const char *name)
{
	for (int i = 0; i < sss_n_presets; i++)
		if (!strcmp(sss_presets[i].name, name))
			return &sss_presets[i];
	return NULL;
}

void sss_medium_to_artist(double sigma_s, double sigma_a, double eta, double *albedo, double *ld_mm)
{
	double sigma_t = sigma_s + sigma_a; /* reduced extinction sigma_t' */
	*albedo = sss_dipole_albedo(sigma_t > 0.0 ? fmin(1.0, sigma_s / sigma_t) : 0.0, eta);
	/* JMLH01: sigma_tr = sqrt(3 sigma_a sigma_t'); JB02 calls l_d = 1/sigma_tr the diffuse mean
	 * free path and uses it as the artist's "scattering distance". */
	double sigma_tr = sqrt(3.0 * sigma_a * sigma_t);
	*ld_mm = sigma_tr > 0.0 ? 1.0 / sigma_tr : INFINITY;
}

void sss_medium_to_physical(double albedo, double ld_mm, double eta, double *sigma_s, double *sigma_a)
{
	/* JB02 section 4: alpha' with R_d(alpha') = A, then sigma_t' = sigma_tr / sqrt(3 (1 - alpha')). */
	double alpha_prime = fmin(sss_dipole_alpha_prime(albedo, eta), SSS_ALPHA_PRIME_MAX);
	double sigma_t = 1.0 / (ld_mm * sqrt(3.0 * (1.0 - alpha_prime)));
	*sigma_s = alpha_prime * sigma_t;
	*sigma_a = sigma_t - *sigma_s;
}

/* Channel c of a vec3. */
static double channel(vec3 v, int c)
{
	return c == 0 ? v.x : c == 1 ? v.y : v.z;
}

/* The base of one channel: the preset's coefficients and their artist form, or the spec's albedo
 * and radius (the block's defaults) and their physical form. */
static void base_channel(const sss_medium_spec *s, const sss_preset *pr, int c, double eta, double phys[2],
			 double art[2])
{
	if (pr) {
		phys[0] = pr->sigma_s_per_mm[c], phys[1] = pr->sigma_a_per_mm[c];
		sss_medium_to_artist(phys[0], phys[1], eta, &art[0], &art[1]);
	} else {
		art[0] = channel(s->albedo, c), art[1] = channel(s->radius_mm, c);
		sss_medium_to_physical(art[0], art[1], eta, &phys[0], &phys[1]);
	}
}

void sss_medium_derive(const sss_medium_spec *s, double eta, sss_medium *out)
{
	const sss_preset *pr = s->preset ? sss_preset_find(s->preset) : NULL;
	assert(!s->preset || pr);
	/* Without a preset the base is the artist form, which the spec must then hold. */
	assert(pr || (s->has & (SSS_HAS_ALBEDO | SSS_HAS_RADIUS)) == (SSS_HAS_ALBEDO | SSS_HAS_RADIUS));
	for (int c = 0; c < 3; c++) {
		double phys[2], art[2];
		base_channel(s, pr, c, eta, phys, art);
		if (s->form == SSS_FORM_PHYSICAL) {
			if (s->has & SSS_HAS_SIGMA_S)
				phys[0] = channel(s->sigma_s_per_mm, c);
			if (s->has & SSS_HAS_SIGMA_A)
				phys[1] = channel(s->sigma_a_per_mm, c);
			sss_medium_to_artist(phys[0], phys[1], eta, &art[0], &art[1]);
		} else if (s->form == SSS_FORM_ARTIST) {
			if (s->has & SSS_HAS_ALBEDO)
				art[0] = channel(s->albedo, c);
			if (s->has & SSS_HAS_RADIUS)
				art[1] = channel(s->radius_mm, c);
			sss_medium_to_physical(art[0], art[1], eta, &phys[0], &phys[1]);
		}
		out->sigma_s_per_mm[c] = phys[0], out->sigma_a_per_mm[c] = phys[1];
		out->albedo[c] = art[0], out->ld_mm[c] = art[1];
	}
}

/* ---- POV-Ray's subsurface { translucency } (doc/language.md "POV-Ray's subsurface") ------------ */

double sss_pov_fresnel_diffuse(double eta)
{
	if (eta < 1.0)
		return eta * eta - pow(eta, 2.25);
	double k = 1.0 - 1.0 / eta;
	return (k + 3.0 * pow(k, 4.5)) / 4.0;
}

double sss_pov_alpha_prime(double rd, double eta)
{
	double f = sss_pov_fresnel_diffuse(eta);
	double a = sss_dipole_alpha_prime_af(fmin(fmax(rd, 0.0), 1.0), (1.0 + f) / (1.0 - f));
	return fmin(a, SSS_ALPHA_PRIME_MAX);
}

double sss_pov_translucency_radius_mm(double rd, double translucency_mm, double eta)
{
	/* sigma_s' = 1/T, sigma_t' = 1/(T alpha'), sigma_a = (1 - alpha')/(T alpha'), so
	 * 1/sigma_tr = 1/sqrt(3 sigma_a sigma_t') = T alpha' / sqrt(3 (1 - alpha')). */
	double a = sss_pov_alpha_prime(rd, eta);
	double ld = translucency_mm * a / sqrt(3.0 * (1.0 - a));
	return fmax(ld, SSS_POV_MIN_RADIUS_FRACTION * translucency_mm);
}

double sss_pov_gain(double rd, double eta, double k)
{
	double r = fmin(fmax(rd, SSS_POV_GAIN_MIN_RD), 1.0);
	double single = sss_pov_alpha_prime(r, eta) / (24.0 * r); /* POV-Ray's single scattering over R_d */
	return (1.0 - 2.0 * sss_fresnel_moment1(eta)) * (k + single);
}
