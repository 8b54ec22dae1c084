/* profile.c - the four radial profiles: untruncated formulas from their papers, the truncation
 * that renormalises them over [0, r_max], exact sampling of r, and the links from the medium's
 * coefficients to each profile's parameters (README.md has the derivations). */
#include "sss/profile.h"

#include <assert.h>
#include <float.h>
#include <math.h>

#define PI 3.14159265358979323846

/* Smallest u used by the samplers: r = 0 exactly would make burley's R infinite; the shift is
 * far below the 2^-53 resolution of the random numbers, so it changes no distribution. */
#define SSS_U_MIN 0x1p-64
/* Iterations of bisection: enough to reach the last bit of a double on any bracket. */
#define SSS_BISECT_STEPS 200
/* Relative bracket width at which a bisection stops: a few ulps of a double. */
#define SSS_BISECT_REL 1e-15
/* Relative Newton step below which the dipole's CDF inversion stops (see invert_cdf0). */
#define SSS_NEWTON_DONE 1e-9
/* Intervals of the Simpson rule for the Fresnel moment; the integrand is smooth on each piece
 * (split at the critical angle), so the error is below 1e-9. */
#define SSS_FM1_INTERVALS 512

/* d'Eon & Luebke 2007, GPU Gems 3 ch. 14, Table 14-1: the six-Gaussian fit of a three-layer
 * skin profile. Variances in mm^2, then the weights of red, green and blue (each column sums
 * to 1). G(v, r) = e^{-r^2/(2v)} / (2 pi v). */
static const double sog_skin_v_mm2[6] = {0.0064, 0.0484, 0.187, 0.567, 1.99, 7.41};
static const double sog_skin_w[3][6] = {
    {0.233, 0.100, 0.118, 0.113, 0.358, 0.078},
    {0.455, 0.336, 0.198, 0.007, 0.004, 0.0},
    {0.649, 0.344, 0.0, 0.007, 0.0, 0.0},
};

/* ---- Fresnel and the dipole's albedo ---------------------------------------------------------- */

/* Unpolarised dielectric Fresnel reflectance for cos(incidence) mu, eta = n_t / n_i. */
double sss_fresnel_dielectric(double mu, double eta)
{
	double sin2_t = (1.0 - mu * mu) / (eta * eta);
	if (sin2_t >= 1.0)
		return 1.0;
	double mu_t = sqrt(1.0 - sin2_t);
	double rs = (mu - eta * mu_t) / (mu + eta * mu_t);
	double rp = (eta * mu - mu_t) / (eta * mu + mu_t);
	return 0.5 * (rs * rs + rp * rp);
}

/* Simpson's rule over x in [0, 1] of k^2 F(mu) x with mu = sqrt(mu_c^2 + k^2 x^2). With k = 1 and
 * mu_c = 0 this is FM1 itself; with k = eta < 1 and mu_c = cos(critical angle), x is the cosine
 * on the transmitted side and this is the part of FM1 above mu_c, in the variable that makes it
 * smooth (1 - mu^2 = eta^2 (1 - x^2), so mu dmu = eta^2 x dx). */
static double fm1_simpson(double mu_c, double k, double eta)
{
	double h = 1.0 / SSS_FM1_INTERVALS, s = 0.0;
	for (int i = 0; i <= SSS_FM1_INTERVALS; i++) {
		double x = h * i, mu = sqrt(mu_c * mu_c + k * k * x * x);
		double w = (i == 0 || i == SSS_FM1_INTERVALS) ? 1.0 : (i % 2 ? 4.0 : 2.0);
		s += w * sss_fresnel_dielectric(fmin(mu, 1.0), eta) * x;
	}
	return k * k * s * h / 3.0;
}

double sss_fresnel_moment1(double eta)
{
	if (eta >= 1.0)
		return fm1_simpson(0.0, 1.0, eta);
	/* Total internal reflection below mu_c: F = 1 there exactly. */
	double mu_c = sqrt(1.0 - eta * eta);
	return 0.5 * mu_c * mu_c + fm1_simpson(mu_c, eta, eta);
}

/* A_F of Jensen et al. 2001 (eq. 3's boundary condition): (1 + F_dr) / (1 - F_dr), F_dr the
 * internal diffuse reflectance 2 FM1(1/eta). */
static double dipole_boundary_a(double eta)
{
	double f_dr = 2.0 * sss_fresnel_moment1(1.0 / eta);
	return (1.0 + f_dr) / (1.0 - f_dr);
}

/* R_d of Jensen et al. 2001 (section 2.4) for a given A_F. */
static double dipole_albedo_a(double alpha_prime, double a_f)
{
	double s = sqrt(3.0 * (1.0 - alpha_prime));
	return 0.5 * alpha_prime * (1.0 + exp(-4.0 / 3.0 * a_f * s)) * exp(-s);
}

double sss_dipole_albedo(double alpha_prime, double eta)
{
	return dipole_albedo_a(alpha_prime, dipole_boundary_a(eta));
}

double sss_dipole_alpha_prime(double albedo, double eta)
{
	return sss_dipole_alpha_prime_af(albedo, dipole_boundary_a(eta));
}

double sss_dipole_alpha_prime_af(double albedo, double a_f)
{
	double lo = 0.0, hi = 1.0;
	if (!(albedo > 0.0))
		return 0.0;
	if (albedo >= 1.0)
		return 1.0;
	for (int i = 0; i < SSS_BISECT_STEPS && hi - lo > SSS_BISECT_REL; i++) {
		double mid = 0.5 * (lo + hi);
		if (dipole_albedo_a(mid, a_f) < albedo)
			lo = mid;
		else
			hi = mid;
	}
	return 0.5 * (lo + hi);
}

/* ---- the untruncated shapes: pdf p0, tail 1 - CDF0, CDF0 ------------------------------------- */

/* The dipole's normalisation T: its untruncated albedo is alpha' T. */
static double dipole_t(const sss_channel *c)
{
	return 0.5 * (exp(-c->dipole.sigma_tr * c->dipole.z_r) + exp(-c->dipole.sigma_tr * c->dipole.z_v));
}

/* z (1 + sigma d) e^{-sigma d} / d^3 with d = sqrt(r^2 + z^2): one source of Jensen's eq. 4. */
static double dipole_source(double r, double z, double sigma)
{
	double d = sqrt(r * r + z * z);
	return z * (1.0 + sigma * d) * exp(-sigma * d) / (d * d * d);
}

/* e^{-sigma z} - (z/d) e^{-sigma d}: one source's integral of 2 pi r R / (alpha'/2) over
 * [0, r] (d/du of -e^{-sigma u}/u is (1 + sigma u) e^{-sigma u}/u^2), written without
 * cancellation for small r. */
static double dipole_source_cdf(double r, double z, double sigma)
{
	double d = sqrt(r * r + z * z), dz = r * r / (d + z);
	return -exp(-sigma * z) * expm1(-log1p(dz / z) - sigma * dz);
}

static double pdf0(const sss_channel *c, double r)
{
	switch (c->kind) {
	case SSS_PROFILE_GAUSSIAN:
	case SSS_PROFILE_SUM_OF_GAUSSIANS: {
		double p = 0.0;
		for (int i = 0; i < c->gauss.n; i++)
			p += c->gauss.w[i] * r / c->gauss.v_mm2[i] * exp(-r * r / (2.0 * c->gauss.v_mm2[i]));
		return p;
	}
	case SSS_PROFILE_BURLEY: {
		double d = c->burley.d_mm;
		return (exp(-r / d) + exp(-r / (3.0 * d))) / (4.0 * d);
	}
	case SSS_PROFILE_DIPOLE: {
		double s = c->dipole.sigma_tr;
		return 0.5 * r * (dipole_source(r, c->dipole.z_r, s) + dipole_source(r, c->dipole.z_v, s)) /
		       dipole_t(c);
	}
	}
	return 0.0;
}

/* The untruncated CDF0(r) and its complement 1 - CDF0(r), each computed without cancellation
 * (the complement directly, so the truncation radius is accurate). */
static void cdf_tail0(const sss_channel *c, double r, double *cdf, double *tail)
{
	double f = 0.0, t = 0.0;
	switch (c->kind) {
	case SSS_PROFILE_GAUSSIAN:
	case SSS_PROFILE_SUM_OF_GAUSSIANS:
		for (int i = 0; i < c->gauss.n; i++) {
			double x = -r * r / (2.0 * c->gauss.v_mm2[i]);
			f -= c->gauss.w[i] * expm1(x);
			t += c->gauss.w[i] * exp(x);
		}
		break;
	case SSS_PROFILE_BURLEY: {
		double d = c->burley.d_mm;
		f = -0.25 * expm1(-r / d) - 0.75 * expm1(-r / (3.0 * d));
		t = 0.25 * exp(-r / d) + 0.75 * exp(-r / (3.0 * d));
		break;
	}
	case SSS_PROFILE_DIPOLE: {
		double s = c->dipole.sigma_tr, zr = c->dipole.z_r, zv = c->dipole.z_v, k = 0.5 / dipole_t(c);
		double dr = sqrt(r * r + zr * zr), dv = sqrt(r * r + zv * zv);
		f = k * (dipole_source_cdf(r, zr, s) + dipole_source_cdf(r, zv, s));
		t = k * (zr * exp(-s * dr) / dr + zv * exp(-s * dv) / dv);
		break;
	}
	}
	*cdf = f;
	*tail = t;
}

static double cdf0(const sss_channel *c, double r)
{
	double f, t;
	cdf_tail0(c, r, &f, &t);
	return f;
}

static double tail0(const sss_channel *c, double r)
{
	double f, t;
	cdf_tail0(c, r, &f, &t);
	return t;
}

/* Any length of the profile's scale, to start the search for r_max. */
static double length_scale(const sss_channel *c)
{
	switch (c->kind) {
	case SSS_PROFILE_GAUSSIAN:
	case SSS_PROFILE_SUM_OF_GAUSSIANS:
		return sqrt(c->gauss.v_mm2[0]);
	case SSS_PROFILE_BURLEY:
		return c->burley.d_mm;
	case SSS_PROFILE_DIPOLE:
		return c->dipole.z_r;
	}
	return 1.0;
}

/* The radius of entry i of the dipole's CDF table: r_max 2^{-(SSS_DIPOLE_TABLE - 1 - i)/2}. */
static double dipole_table_r(const sss_channel *c, int i)
{
	return c->r_max_mm * exp2(-0.5 * (SSS_DIPOLE_TABLE - 1 - i));
}

/* The r where tail0 falls to SSS_PROFILE_TAIL (tail0 decreases from 1 to 0), and the
 * renormalisation CDF0(r_max). */
static void set_truncation(sss_channel *c)
{
	double lo = 0.0, hi = length_scale(c);
	while (tail0(c, hi) > SSS_PROFILE_TAIL)
		lo = hi, hi *= 2.0;
	for (int i = 0; i < SSS_BISECT_STEPS && hi - lo > SSS_BISECT_REL * hi; i++) {
		double mid = 0.5 * (lo + hi);
		if (tail0(c, mid) > SSS_PROFILE_TAIL)
			lo = mid;
		else
			hi = mid;
	}
	c->r_max_mm = hi;
	c->norm = cdf0(c, hi);
	assert(c->r_max_mm > 0.0 && c->norm > 0.0); /* sss_channel's: r_max > 0, the renormalisation */
	if (c->kind == SSS_PROFILE_DIPOLE)
		for (int i = 0; i < SSS_DIPOLE_TABLE; i++)
			c->dipole.table_cdf[i] = cdf0(c, dipole_table_r(c, i));
}

/* ---- building channels ------------------------------------------------------------------------ */

/* Christensen & Burley 2015, section 5, eq. 8: the fit for the diffuse mean free path,
 * d = l_d / s(A). */
static double burley_s(double albedo)
{
	double x = albedo - 0.33;
	return 3.5 + 100.0 * x * x * x * x;
}

/* The gaussian kinds have no physical derivation: their variances are scaled so that the mean
 * exit distance E[r] equals burley's for the same (A, l_d), E[r] = d/4 + 3 (3d)/4 = 2.5 d. A
 * Gaussian of variance v has E[r] = sqrt(pi v / 2) (the Rayleigh mean). */
static void gauss_fit_mean(sss_channel *c, double mean_mm)
{
	double m = 0.0;
	for (int i = 0; i < c->gauss.n; i++)
		m += c->gauss.w[i] * sqrt(PI * c->gauss.v_mm2[i] / 2.0);
	double k2 = (mean_mm / m) * (mean_mm / m);
	for (int i = 0; i < c->gauss.n; i++)
		c->gauss.v_mm2[i] *= k2;
}

/* The channel from the medium: (A, l_d) for burley and the gaussians, (alpha', sigma_t', eta)
 * for the dipole. */
static void channel_build(sss_channel *c, sss_profile_kind kind, int channel, double albedo, double ld_mm,
			  double alpha_prime, double sigma_t_per_mm, double eta)
{
	c->kind = kind;
	c->albedo = albedo;
	double d_mm = ld_mm / burley_s(albedo);
	switch (kind) {
	case SSS_PROFILE_GAUSSIAN:
		c->gauss.n = 1;
		c->gauss.w[0] = 1.0;
		c->gauss.v_mm2[0] = 1.0;
		gauss_fit_mean(c, 2.5 * d_mm);
		break;
	case SSS_PROFILE_SUM_OF_GAUSSIANS:
		c->gauss.n = 0;
		for (int i = 0; i < 6; i++) {
			if (sog_skin_w[channel][i] > 0.0) {
				c->gauss.w[c->gauss.n] = sog_skin_w[channel][i];
				c->gauss.v_mm2[c->gauss.n++] = sog_skin_v_mm2[i];
			}
		}
		gauss_fit_mean(c, 2.5 * d_mm);
		break;
	case SSS_PROFILE_BURLEY:
		c->burley.d_mm = d_mm;
		break;
	case SSS_PROFILE_DIPOLE: {
		/* Jensen et al. 2001, section 2.3: sigma_tr = sqrt(3 sigma_a sigma_t'), z_r = 1/sigma_t',
		 * z_v = z_r (1 + 4/3 A_F), with sigma_a = (1 - alpha') sigma_t'. */
		double a_f = dipole_boundary_a(eta);
		c->dipole.alpha_prime = alpha_prime;
		c->dipole.sigma_tr = sqrt(3.0 * (1.0 - alpha_prime)) * sigma_t_per_mm;
		c->dipole.z_r = 1.0 / sigma_t_per_mm;
		c->dipole.z_v = c->dipole.z_r * (1.0 + 4.0 / 3.0 * a_f);
		c->albedo = alpha_prime * dipole_t(c);
		break;
	}
	}
	set_truncation(c);
}

static bool finite_nonneg(double x)
{
	return isfinite(x) && x >= 0.0;
}
static bool finite_pos(double x)
{
	return isfinite(x) && x > 0.0;
}

bool sss_channel_from_physical(sss_channel *out, sss_profile_kind kind, int channel,
			       double sigma_s_prime_per_mm, double sigma_a_per_mm, double eta)
{
	if (!finite_nonneg(sigma_s_prime_per_mm) || !finite_nonneg(sigma_a_per_mm) || !finite_pos(eta) ||
	    channel < 0 || channel > 2)
		return false;
	double sigma_t = sigma_s_prime_per_mm + sigma_a_per_mm;
	double ld_mm = 1.0 / sqrt(3.0 * sigma_a_per_mm * sigma_t);
	if (!finite_pos(sigma_t) || !finite_pos(1.0 / sigma_t) ||
	    (kind != SSS_PROFILE_DIPOLE && !finite_pos(ld_mm)))
		return false;
	double alpha_prime = fmin(1.0, sigma_s_prime_per_mm / sigma_t);
	double albedo = sss_dipole_albedo(alpha_prime, eta);
	channel_build(out, kind, channel, albedo, ld_mm, alpha_prime, sigma_t, eta);
	return true;
}

bool sss_channel_from_artist(sss_channel *out, sss_profile_kind kind, int channel, double albedo,
			     double ld_mm, double eta)
{
	if (!(albedo >= 0.0 && albedo <= 1.0) || !finite_pos(ld_mm) || !finite_pos(eta) || channel < 0 ||
	    channel > 2)
		return false;
	/* JB02 section 4: alpha' from R_d(alpha') = A, then sigma_t' = sigma_tr / sqrt(3 (1 - alpha')). */
	double alpha_prime = fmin(sss_dipole_alpha_prime(albedo, eta), SSS_ALPHA_PRIME_MAX);
	double sigma_t = 1.0 / (ld_mm * sqrt(3.0 * (1.0 - alpha_prime)));
	channel_build(out, kind, channel, albedo, ld_mm, alpha_prime, sigma_t, eta);
	return true;
}

/* ---- one channel: truncated and renormalised ---------------------------------------------------- */

double sss_channel_eval(const sss_channel *c, double r)
{
	if (r > c->r_max_mm || r < 0.0)
		return 0.0;
	double a = c->albedo, R;
	switch (c->kind) {
	case SSS_PROFILE_GAUSSIAN:
	case SSS_PROFILE_SUM_OF_GAUSSIANS:
		R = 0.0;
		for (int i = 0; i < c->gauss.n; i++) {
			double v = c->gauss.v_mm2[i];
			R += c->gauss.w[i] * exp(-r * r / (2.0 * v)) / (2.0 * PI * v);
		}
		R *= a;
		break;
	case SSS_PROFILE_BURLEY: { /* Christensen & Burley 2015, eq. 2 with s = 1/d */
		double d = c->burley.d_mm;
		R = a * (exp(-r / d) + exp(-r / (3.0 * d))) / (8.0 * PI * d * r);
		break;
	}
	case SSS_PROFILE_DIPOLE: { /* Jensen et al. 2001, eq. 4 */
		double s = c->dipole.sigma_tr;
		R = c->dipole.alpha_prime / (4.0 * PI) *
		    (dipole_source(r, c->dipole.z_r, s) + dipole_source(r, c->dipole.z_v, s));
		break;
	}
	default:
		R = 0.0;
	}
	return R / c->norm;
}

double sss_channel_pdf(const sss_channel *c, double r)
{
	if (r > c->r_max_mm || r < 0.0)
		return 0.0;
	return pdf0(c, r) / c->norm;
}

double sss_channel_cdf(const sss_channel *c, double r)
{
	if (r <= 0.0)
		return 0.0;
	if (r >= c->r_max_mm)
		return 1.0;
	return fmin(1.0, cdf0(c, r) / c->norm);
}

/* Picks a component of a mixture of n truncated components: weights w_i, each with mass m_i
 * inside [0, r_max]; returns i and rescales *u to a uniform number within that component. */
static int pick_component(const double *w, const double *m, int n, double *u)
{
	double total = 0.0;
	for (int i = 0; i < n; i++)
		total += w[i] * m[i];
	double x = *u * total;
	for (int i = 0; i < n; i++) {
		double wi = w[i] * m[i];
		if ((x < wi || i == n - 1) && wi > 0.0) {
			*u = fmin(fmax(x / wi, 0.0), 1.0);
			return i;
		}
		x -= wi;
	}
	return n - 1;
}

/* Solves cdf0(r) = target on [0, r_max] (the dipole's) by Newton's method kept inside a
 * bisection bracket, starting from the bracket of the CDF table. */
static double invert_cdf0(const sss_channel *c, double target)
{
	/* The bracket from the table (binary search), the start by linear interpolation in it. */
	const double *t = c->dipole.table_cdf;
	int a = 0, b = SSS_DIPOLE_TABLE - 1;
	if (target <= t[0]) {
		b = 0;
	} else {
		while (b - a > 1) {
			int m = (a + b) / 2;
			if (t[m] < target)
				a = m;
			else
				b = m;
		}
	}
	double lo = b == 0 ? 0.0 : dipole_table_r(c, a), hi = dipole_table_r(c, b);
	double flo = b == 0 ? 0.0 : t[a], fhi = t[b];
	double r = fhi > flo ? lo + (hi - lo) * (target - flo) / (fhi - flo) : 0.5 * (lo + hi);
	if (!(r > lo && r < hi))
		r = 0.5 * (lo + hi);
	for (int i = 0; i < SSS_BISECT_STEPS; i++) {
		double f = cdf0(c, r) - target;
		if (f == 0.0)
			return r;
		if (f < 0.0)
			lo = r;
		else
			hi = r;
		double p = pdf0(c, r);
		double next = p > 0.0 ? r - f / p : 0.5 * (lo + hi);
		if (!(next >= lo && next <= hi))
			next = 0.5 * (lo + hi);
		/* Newton converges quadratically: after a step below 1e-9 r the error of `next` is
		 * of order (1e-9)^2 r, below the double's resolution. */
		if (fabs(next - r) <= SSS_NEWTON_DONE * r || hi - lo <= SSS_BISECT_REL * hi)
			return next;
		r = next;
	}
	return r;
}

double sss_channel_sample(const sss_channel *c, double u)
{
	u = fmin(fmax(u, SSS_U_MIN), 1.0);
	double r = 0.0, rm = c->r_max_mm;
	switch (c->kind) {
	case SSS_PROFILE_GAUSSIAN:
	case SSS_PROFILE_SUM_OF_GAUSSIANS: {
		/* Each component is a Rayleigh law: the Box-Muller radius, truncated at r_max. */
		double m[SSS_PROFILE_MAX_GAUSSIANS];
		for (int i = 0; i < c->gauss.n; i++)
			m[i] = -expm1(-rm * rm / (2.0 * c->gauss.v_mm2[i]));
		int i = pick_component(c->gauss.w, m, c->gauss.n, &u);
		u = fmax(u, SSS_U_MIN);
		r = sqrt(-2.0 * c->gauss.v_mm2[i] * log1p(-u * m[i]));
		break;
	}
	case SSS_PROFILE_BURLEY: {
		/* 2 pi r R / A = 1/4 Exp(1/d) + 3/4 Exp(1/(3d)): pick an exponential, invert it. */
		const double w[2] = {0.25, 0.75};
		double rate[2] = {1.0 / c->burley.d_mm, 1.0 / (3.0 * c->burley.d_mm)};
		double m[2] = {-expm1(-rm * rate[0]), -expm1(-rm * rate[1])};
		int i = pick_component(w, m, 2, &u);
		u = fmax(u, SSS_U_MIN);
		r = -log1p(-u * m[i]) / rate[i];
		break;
	}
	case SSS_PROFILE_DIPOLE:
		r = invert_cdf0(c, u * c->norm);
		break;
	}
	return fmin(fmax(r, DBL_MIN), rm);
}

/* ---- RGB -------------------------------------------------------------------------------------- */

sss_profile sss_profile_make(const sss_channel ch[3])
{
	sss_profile p;
	double sum = 0.0;
	for (int c = 0; c < 3; c++)
		p.ch[c] = ch[c], sum += ch[c].albedo;
	for (int c = 0; c < 3; c++)
		p.q[c] = sum > 0.0 ? ch[c].albedo / sum : 1.0 / 3.0;
	return p;
}

/* The two forms' channel builders share one signature: (out, kind, channel, x, y, eta). */
typedef bool (*channel_builder)(sss_channel *, sss_profile_kind, int, double, double, double);

static bool profile_build(sss_profile *out, sss_profile_kind kind, channel_builder build, const double x[3],
			  const double y[3], double eta)
{
	sss_channel ch[3];
	for (int c = 0; c < 3; c++)
		if (!build(&ch[c], kind, c, x[c], y[c], eta))
			return false;
	*out = sss_profile_make(ch);
	return true;
}

bool sss_profile_from_physical(sss_profile *out, sss_profile_kind kind, const double sigma_s_prime_per_mm[3],
			       const double sigma_a_per_mm[3], double eta)
{
	return profile_build(out, kind, sss_channel_from_physical, sigma_s_prime_per_mm, sigma_a_per_mm, eta);
}

bool sss_profile_from_artist(sss_profile *out, sss_profile_kind kind, const double albedo[3],
			     const double ld_mm[3], double eta)
{
	return profile_build(out, kind, sss_channel_from_artist, albedo, ld_mm, eta);
}

double sss_profile_sample(const sss_profile *p, double u_channel, double u_r)
{
	/* sss_profile_make's q sum to 1, so the loop below ends */
	assert(p->q[0] > 0.0 || p->q[1] > 0.0 || p->q[2] > 0.0);
	int c = u_channel < p->q[0] ? 0 : u_channel < p->q[0] + p->q[1] ? 1 : 2;
	while (p->q[c] <= 0.0) /* rounding at the top of u_channel: never a channel of q = 0 */
		c = (c + 2) % 3;
	return sss_channel_sample(&p->ch[c], u_r);
}

double sss_profile_pdf(const sss_profile *p, double r)
{
	double s = 0.0;
	for (int c = 0; c < 3; c++)
		if (p->q[c] > 0.0)
			s += p->q[c] * sss_channel_pdf(&p->ch[c], r);
	return s;
}

vec3 sss_profile_eval(const sss_profile *p, double r)
{
	return v3((float)sss_channel_eval(&p->ch[0], r), (float)sss_channel_eval(&p->ch[1], r),
		  (float)sss_channel_eval(&p->ch[2], r));
}

vec3 sss_profile_ratio(const sss_profile *p, double r)
{
	double pc[3], pdf = 0.0, w[3];
	for (int c = 0; c < 3; c++) {
		pc[c] = sss_channel_pdf(&p->ch[c], r);
		pdf += p->q[c] * pc[c];
	}
	for (int c = 0; c < 3; c++)
		w[c] = pdf > 0.0 ? p->ch[c].albedo * pc[c] / pdf : 0.0;
	return v3((float)w[0], (float)w[1], (float)w[2]);
}

double sss_profile_r_max(const sss_profile *p)
{
	return fmax(p->ch[0].r_max_mm, fmax(p->ch[1].r_max_mm, p->ch[2].r_max_mm));
}
