/* walk.c - the volumetric random walk (README.md, "The volume random walk") and the closed-mesh
 * check. */
#include "sss/walk.h"

#include "accel/offset.h"
#include "base/mem.h"
#include "sss/profile.h"
#include "sss/walk_exp.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>

#define WALK_PI 3.14159265358979323846

/* Below this |g| the phase function is sampled as isotropic: the inverse CDF's 1/g loses all
 * digits as g -> 0. */
#define WALK_G_ISOTROPIC 1e-4

/* No collision happens within WALK_SKIN times the hit's scale (the larger of its largest
 * coordinate and its triangle's: the hit's t carries the error of the triangle's vertices; about
 * 8 float ulps), measured along the normal: a collision point rounded onto or across the surface
 * would start the next ray outside (on a 400 mm box the point's own scale let walks land 5e-6
 * outside its face, lost). The skin only transmits (weight e^{-sigma_t d_skin}, sampled consistently): a bias of
 * the order sigma_t * 1e-6 * |coordinates|, negligible. */
#define WALK_SKIN 1e-6
/* A walk's ray reaches this much (of the same scale) past the free path: the skin ahead of a
 * boundary hit at up to 1/8 of grazing still sees it (the skin is WALK_SKIN / cos). */
#define WALK_REACH (8.0 * WALK_SKIN)
#define WALK_WHOLE_EVERY 64

/* fmax and fmin with their NaN rules (the number when one is NaN), inline: at -O2 without
 * -ffinite-math-only the compiler calls libm's for them, a call per use in the walk's loop
 * (issue 21's profile of the wax bunny under auto: 1.7 % of the render in __fmax). */
static inline double walk_max(double a, double b) { return a > b || b != b ? a : b; }
static inline double walk_min(double a, double b) { return a < b || b != b ? a : b; }
/* The same for numbers known not to be NaN (the walk's distances, cosines and scales): plain
 * comparisons, one maxsd or minsd each (issue 21: the NaN rule's extra compare and branch made
 * walk_max 6 % of a marble walk's instructions). A NaN a gives b, as fmax. */
static inline double walk_maxn(double a, double b) { return a > b ? a : b; }
static inline double walk_minn(double a, double b) { return a < b ? a : b; }


bool sss_walk_medium_from_reduced(sss_walk_medium *m, const double sigma_s_prime_per_mm[3],
				  const double sigma_a_per_mm[3], double g, double eta, double mm_per_unit)
{
	if (!(fabs(g) < 1.0) || !(eta > 0.0) || !isfinite(eta) || !(mm_per_unit > 0.0) || !isfinite(mm_per_unit))
		return false;
	for (int c = 0; c < 3; c++)
		if (!(sigma_s_prime_per_mm[c] >= 0.0) || !isfinite(sigma_s_prime_per_mm[c]) ||
		    !(sigma_a_per_mm[c] >= 0.0) || !isfinite(sigma_a_per_mm[c]))
			return false;
	for (int c = 0; c < 3; c++) {
		m->sigma_s[c] = sigma_s_prime_per_mm[c] / (1.0 - g) * mm_per_unit;
		m->sigma_a[c] = sigma_a_per_mm[c] * mm_per_unit;
	}
	m->g = g;
	m->classic = false;
	m->eta = eta;
	return true;
}

/* The unit direction at cosine mu from the unit axis n, azimuth 2 pi u, in n's basis b1, b2
 * (v3_basis; the guide's axis is fixed for a walk, so its basis is made once). The azimuth's
 * cosine and sine in float (one sincosf; issue 21: double sincos was 8 % of a marble walk): the
 * direction is a float vector, so the double's digits were rounded away anyway. */
static vec3 walk_dir_in(vec3 n, vec3 b1, vec3 b2, double mu, double u)
{
	float s = (float)sqrt(walk_maxn(0.0, 1.0 - mu * mu)), phi = (float)(2.0 * WALK_PI * u);
	float c_phi = cosf(phi), s_phi = sinf(phi);
	return v3_normalize(v3_add(v3_scale(n, (float)mu), v3_add(v3_scale(b1, s * c_phi), v3_scale(b2, s * s_phi))));
}

vec3 sss_walk_sample_hg(vec3 w, double g, double u1, double u2)
{
	double mu;
	if (fabs(g) < WALK_G_ISOTROPIC) {
		mu = 1.0 - 2.0 * u1;
	} else {
		double s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u1);
		mu = (1.0 + g * g - s * s) / (2.0 * g);
	}
	mu = walk_max(-1.0, walk_min(1.0, mu));
	vec3 b1, b2;
	v3_basis(w, &b1, &b2);
	return walk_dir_in(w, b1, b2, mu, u2);
}

/* Uniform in [0, 1) from one step of the generator (32 bits). */
static inline double walk_u32(rng *g) { return (double)rng_u32(g) * 0x1p-32; }

/* The probabilities of the hero channels: proportional to an estimate of what each channel
 * returns, the albedo of a semi-infinite medium of single-scattering albedo a,
 * (1 - s)/(1 + s) with s = sqrt(1 - a) (the two-stream / diffusion form; within 35 % of
 * Chandrasekhar's at a = 0.3-0.99, which is all a choice of channel needs), with a floor of a
 * tenth of the largest so that no channel's weight can grow beyond 10 / (its albedo). Fixed
 * for the whole walk, as path-level spectral MIS requires. */
static void walk_hero_probs(const sss_walk_medium *m, const double sigma_t[3], double q[3])
{
	double top = 0.0;
	for (int c = 0; c < 3; c++) {
		double a = sigma_t[c] > 0.0 ? m->sigma_s[c] / sigma_t[c] : 0.0, s = sqrt(walk_max(0.0, 1.0 - a));
		q[c] = (1.0 - s) / (1.0 + s);
		top = walk_max(top, q[c]);
	}
	if (!(top > 0.0))
		top = q[0] = q[1] = q[2] = 1.0; /* nothing scatters: any channel */
	double sum = 0.0;
	for (int c = 0; c < 3; c++)
		sum += q[c] = walk_max(q[c], 0.1 * top);
	for (int c = 0; c < 3; c++)
		q[c] /= sum;
}

/* The hero channel of a walk from u in [0, 1) (a channel without extinction never collides: its
 * free paths end at the boundary, which serves every channel's estimate). */
static int walk_hero(const double q[3], double u)
{
	return u < q[0] ? 0 : u < q[0] + q[1] || q[2] == 0.0 ? 1 : 2;
}

/* The weights of the walk so far: f_k over the mixture of the channels' path densities
 * (relative to the hero's), channel c chosen with probability q_c: the balance heuristic. */
static void walk_beta(const double q[3], const double f[3], const double ratio[3], double beta[3])
{
	double mix = q[0] * ratio[0] + q[1] * ratio[1] + q[2] * ratio[2];
	double inv = mix > 0.0 && isfinite(mix) ? 1.0 / mix : 0.0; /* one division, not three */
	for (int k = 0; k < 3; k++)
		beta[k] = f[k] * inv;
}

/* The normal of the side of the surface that direction w goes to. */
static vec3 walk_side(vec3 ng, vec3 w)
{
	return v3_dot(ng, w) >= 0.0f ? ng : v3_neg(ng);
}

/* The k-th try in a row to start inside again from the boundary point p (n_in pointing into the
 * medium; scale the triangle's, accel/offset.h): the ray offset, doubled k - 1 times. */
static vec3 walk_step_in(vec3 p, vec3 n_in, float scale, int k)
{
	vec3 o = bvh_offset_scaled(p, n_in, scale);
	return k <= 1 ? o : v3_madd(p, v3_sub(o, p), ldexpf(1.0f, k - 1 < 30 ? k - 1 : 30));
}

/* ---- guided sampling (Meng, Hanika & Dachsbacher 2016) ------------------------------------------ */

double sss_walk_dwivedi_nu(double alpha)
{
	/* d'Eon & Krivanek 2020, "A Zero-Variance-Based Sampling Scheme for Monte Carlo Subsurface
	 * Scattering", eq. 67: the fit nu0 = 1/sqrt(1 - alpha^k(alpha)) to the root of
	 * 1 = alpha nu0/2 ln((nu0 + 1)/(nu0 - 1)), Dwivedi's diffusion length in mean free paths
	 * (the same fit Cycles' subsurface_random_walk.h uses). */
	if (!(alpha > 0.0))
		return 1.0;
	if (!(alpha < 1.0))
		return INFINITY;
	double k = 2.44294 - 0.0215813 * alpha + 0.578637 / alpha;
	double q = -expm1(k * log(alpha)); /* 1 - alpha^k, without cancellation near alpha = 1 */
	return q > 0.0 ? 1.0 / sqrt(q) : INFINITY;
}

/* The guided direction density over the cosine mu with the guiding axis, Meng et al. 2016 eq. 9:
 * p(mu) = 1 / ((nu - mu) ln((nu + 1)/(nu - 1))) on [-1, 1] (times 1/(2 pi) per steradian);
 * walk_scatter evaluates it at mu and -mu with one division. */

/* Its inverse CDF, Meng et al. 2016 eq. 10: mu = nu - (nu + 1) ((nu - 1)/(nu + 1))^u. */
static double dwivedi_sample_mu(double nu, double log_nu, double u)
{
	return walk_maxn(-1.0, walk_minn(1.0, nu - (nu + 1.0) * sss_walk_exp(-u * log_nu)));
}

/* The Henyey-Greenstein density per steradian of the cosine mu between the old and new
 * directions. */
static double hg_pdf(double g, double mu)
{
	if (fabs(g) < WALK_G_ISOTROPIC)
		return 1.0 / (4.0 * WALK_PI);
	double d = 1.0 + g * g - 2.0 * g * mu;
	return (1.0 - g * g) / (4.0 * WALK_PI * d * sqrt(d));
}


/* The guide of one walk (README.md, "Guided sampling"): the axis n (outward at the entry), the
 * diffusion length nu in mean free paths of the reference channel (sigma_ref: the channel of
 * the highest single-scattering albedo, as Cycles: too low a nu would over-guide the others),
 * the probability `frac` of a guided step, and the far side found by the first segment. */
typedef struct walk_guide {
	bool on;
	vec3 x, n;	   /* the entry point; the outward normal there */
	vec3 b1, b2;	   /* n's basis (v3_basis), for the guided directions */
	double nu, log_nu; /* nu, ln((nu + 1)/(nu - 1)) */
	double inv_nu;	   /* 1 / nu */
	double frac;	   /* probability of the guided strategy at a scattering event */
	double sigma_ref;  /* extinction of the reference channel, per scene unit */
	double far;	   /* thickness below the entry along -n found by the first segment; 0: none */
} walk_guide;

/* Whether the walk is guided, and with what: off for a classic medium, an index-matched
 * nothing (no scattering), no absorption at all (nu infinite: the guided densities become the
 * classic ones) or nearly none (nu > WALK_NU_MAX). */
#define WALK_NU_MAX 1e4
#define WALK_NU_MIN (1.0 + 1e-6)
/* Above this nu (albedo about 0.98) the classic strategy's share falls as WALK_FRAC_NU / (2 nu). */
#define WALK_FRAC_NU 4.0
static walk_guide walk_guide_make(const sss_walk_medium *m, const double sigma_t[3], vec3 x, vec3 n)
{
	walk_guide gd = {0};
	double a_max = -1.0;
	int ref = 0;
	for (int c = 0; c < 3; c++) {
		double a = sigma_t[c] > 0.0 ? m->sigma_s[c] / sigma_t[c] : 0.0;
		if (a > a_max)
			a_max = a, ref = c;
	}
	if (m->classic || !(a_max > 0.0))
		return gd;
	double nu = walk_max(WALK_NU_MIN, sss_walk_dwivedi_nu(a_max));
	if (!(nu < WALK_NU_MAX))
		return gd;
	gd.on = true;
	gd.x = x, gd.n = n;
	v3_basis(n, &gd.b1, &gd.b2);
	gd.nu = nu;
	gd.log_nu = log((nu + 1.0) / (nu - 1.0));
	gd.inv_nu = 1.0 / nu;
	/* Cycles' compromise for anisotropic media: 1 - max(1/2, |g|^(1/8)); 1/2 when isotropic.
	 * The classic share of 1/2 shrinks by the factor WALK_FRAC_NU / nu beyond nu =
	 * WALK_FRAC_NU (issue 21): at a high albedo the guided densities approach the classic ones (nu / (nu - mu) and
	 * a stretch 1 - mu / nu), so the mixture's weights stay near 1 with little of the classic
	 * strategy, and each step's pull to the surface, weak there, is not halved. */
	gd.frac = 1.0 - walk_max(0.5 * walk_min(1.0, WALK_FRAC_NU / nu), pow(fabs(m->g), 0.125));
	gd.sigma_ref = sigma_t[ref];
	return gd;
}

/* The probability of guiding away from the entry, towards the far side (d'Eon & Krivanek's
 * recorded presentation, as in Cycles): a logistic in the depth x of the point below the entry's
 * tangent plane, 1/2 half-way to the far side, with the decay length nu mean free paths of the
 * reference channel (Dwivedi's solution decays as e^{-z sigma_t / nu}). */
static double walk_backward_frac(const walk_guide *gd, vec3 p)
{
	if (!(gd->far > 0.0))
		return 0.0;
	double x = walk_maxn(0.0, walk_minn(gd->far, -(double)v3_dot(v3_sub(p, gd->x), gd->n)));
	double e = (gd->far - 2.0 * x) * gd->sigma_ref * gd->inv_nu;
	return e > 700.0 ? 0.0 : 1.0 / (1.0 + sss_walk_exp(e));
}

/* One scattering event's sampling record: the direction's density factors (guided over
 * phase) and the stretch of the guided free-path densities, as Cycles keeps them. */
typedef struct walk_dir {
	bool scattered;		 /* the direction came from a scattering event (else: entry, reflection) */
	double f_fwd, f_bwd;	 /* p_guided(w) / p_phase(w), forward and backward */
	double s_fwd, s_bwd;	 /* the guided extinction is sigma_t times these */
	double bwd;		 /* probability of the backward guide */
} walk_dir;

/* At a scattering event: pick the strategy (classic: the phase function; guided: Dwivedi's
 * directions about n, forward or backward), sample the new direction and record the densities
 * every strategy would have given it. Returns the stretch of the strategy taken. */
static vec3 walk_scatter(const sss_walk_medium *m, const walk_guide *gd, vec3 p, vec3 w, rng *g, walk_dir *wd,
			 double *stretch)
{
	*stretch = 1.0;
	wd->scattered = true;
	if (!gd->on) {
		wd->f_fwd = wd->f_bwd = 0.0, wd->s_fwd = wd->s_bwd = 1.0, wd->bwd = 0.0;
		double u1 = rng_double(g), u2 = walk_u32(g);
		return sss_walk_sample_hg(w, m->g, u1, u2);
	}
	wd->bwd = walk_backward_frac(gd, p);
	/* the choices and the azimuth from one 32-bit draw each (their probabilities exact to
	 * 2^-32, the azimuth finer than the float direction it makes), the cosine from 53 bits:
	 * 5 steps of the generator, not 8 (issue 21) */
	double u_strategy = walk_u32(g), u_side = walk_u32(g), u1 = rng_double(g), u2 = walk_u32(g);
	bool guided = u_strategy < gd->frac, backward = u_side < wd->bwd;
	vec3 nw;
	double mu;
	if (guided) {
		mu = dwivedi_sample_mu(gd->nu, gd->log_nu, u1);
		if (backward)
			mu = -mu; /* the backward guide is the forward one mirrored through the tangent plane */
		nw = walk_dir_in(gd->n, gd->b1, gd->b2, mu, u2);
	} else {
		nw = sss_walk_sample_hg(w, m->g, u1, u2);
	}
	mu = walk_maxn(-1.0, walk_minn(1.0, (double)v3_dot(nw, gd->n)));
	double ph = hg_pdf(m->g, walk_maxn(-1.0, walk_minn(1.0, (double)v3_dot(w, nw))));
	/* p(mu) / (2 pi ph) forward and backward: 1 / ((nu -+ mu) ln(..) 2 pi ph), one division */
	double a = gd->nu - mu, b = gd->nu + mu, inv = 1.0 / (a * b * gd->log_nu * 2.0 * WALK_PI * ph);
	wd->f_fwd = b * inv;
	wd->f_bwd = a * inv;
	wd->s_fwd = 1.0 - mu * gd->inv_nu;
	wd->s_bwd = 1.0 + mu * gd->inv_nu;
	if (guided)
		*stretch = backward ? wd->s_bwd : wd->s_fwd;
	return nw;
}

/* The density of the free path that ended at distance t (collision: the density
 * s sigma e^{-s sigma t}; boundary at d = t: the probability e^{-s sigma d} of passing it) of
 * a channel of extinction sigma under every strategy, relative to the phase function's density
 * of the direction: (1 - frac) classic + frac (mix of forward and backward guided). e is
 * e^{-sigma t}, computed once for the throughput too; the stretched exponentials are e times
 * e^{+-mu sigma t / nu} (s = 1 -+ mu/nu), one more exp. */
static double walk_path_pdf(const walk_guide *gd, const walk_dir *wd, double sigma, double t, double e,
			    bool collision)
{
	double classic = collision ? sigma * e : e;
	if (!gd->on || !wd->scattered)
		return classic;
	double x = sss_walk_exp(sigma * t * (1.0 - wd->s_fwd)); /* (1 - s_fwd) = mu/nu: e^{mu sigma t/nu} */
	double ef = e * x, guided = wd->f_fwd * (collision ? wd->s_fwd * sigma * ef : ef);
	if (wd->bwd > 0.0) {
		double eb = x > 0.0 ? e / x : 0.0;
		double bwd = collision ? wd->s_bwd * sigma * eb : eb;
		guided = (1.0 - wd->bwd) * guided + wd->bwd * wd->f_bwd * bwd;
	}
	return (1.0 - gd->frac) * classic + gd->frac * guided;
}

/* ---- skipping casts (README.md, "Skipping casts") ----------------------------------------------- */

/* Below this many mean free paths (mfp_ball in sss_walk) a ball saves (about (r / mfp)^2 / 2 steps
 * of a diffusing walk) less than its query costs: the next query waits, twice as long each time
 * in a row, up to WALK_BALL_WAIT steps. */
#ifndef WALK_BALL_MIN
#define WALK_BALL_MIN 3.0
#endif
/* No query while a surface point known to the walk (below) is nearer than this many mean free
 * paths: it bounds the ball's radius, and a ball bounded so is seldom worth its query (issue
 * 21, fifth pass, instructions per sample pass against 3: head_front's auto -3.2 %, the wax
 * bunny's -1.8 % and its volume -2.3 %, the marble slab's volume -0.6 %; 8 and 12 were no
 * better on the bunny, 12 worse on the slab). */
#ifndef WALK_BALL_KNOWN
#define WALK_BALL_KNOWN 6.0
#endif
/* Nor before this many steps: most short walks (skin: 12 interactions on the bench's head) end
 * before a ball would pay (issue 21, fifth pass, against none: head_front's auto -0.6 %, the
 * bunny's auto and volume -0.1 %, the marble slab's volume 0.0 %; 4 and 8 gained less). */
#ifndef WALK_BALL_FIRST
#define WALK_BALL_FIRST 16
#endif
#ifndef WALK_BALL_WAIT
#define WALK_BALL_WAIT 16
#endif
/* The query looks no farther than this many mean free paths (a larger ball would outlast the
 * walk; a nearer cap prunes more of the tree). */
#ifndef WALK_BALL_CAP
#define WALK_BALL_CAP 64.0
#endif

/* A ball free of the object's surface: centre c, radius r (0: none), and the queries' back-off;
 * and two points known to lie on the surface (the entry, the last boundary the walk's casts hit):
 * the distance to either bounds the nearest surface's from above, so a query whose answer could
 * not reach WALK_BALL_MIN is known to fail without asking it (issue 21, fifth pass: on skin and
 * in a wax bunny's ears most queries were such, each costing some eight casts). */
typedef struct walk_ball {
	vec3 c;
	double r;
	int wait, backoff;
	vec3 on[2];
} walk_ball;

static double walk_dist2(vec3 a, vec3 b)
{
	vec3 d = v3_sub(a, b);
	return (double)d.x * d.x + (double)d.y * d.y + (double)d.z * d.z;
}

static bool walk_skip = true;
void sss_walk_set_skip(bool on) { walk_skip = on; }

/* Whether the ball about p of radius `need` is free of surface: inside the ball known, or in a
 * new one asked of the probe at p when a query is due. mfp: the walk's length unit for balls,
 * the mean free path of its channel of the highest albedo (mfp_ball in sss_walk). */
static bool walk_ball_holds(walk_ball *b, const sss_probe *pr, vec3 p, double need, double mfp,
			    sss_walk_result *res)
{
	if (b->r > 0.0) {
		vec3 d = v3_sub(p, b->c);
		double s2 = (double)d.x * d.x + (double)d.y * d.y + (double)d.z * d.z, room = b->r - need;
		if (room > 0.0 && s2 < room * room) { /* |p - c| + need < r, without a square root */
			res->skipped++;
			return true;
		}
	}
	if (!pr->nearest || !walk_skip || res->steps < WALK_BALL_FIRST)
		return false;
	if (b->wait > 0) {
		b->wait--;
		return false;
	}
	/* a known surface point nearer than WALK_BALL_KNOWN mean free paths: the ball would be no
	 * larger (the point is a float, off the surface by an ulp or so of its coordinates: the 1e-3
	 * margin), so the query is not asked and stays due. Either way only the cost changes: a
	 * query's answer decides which casts are made, never what they would find. */
	double least = WALK_BALL_KNOWN * mfp * (1.0 - 1e-3), least2 = least * least;
	double known2 = walk_minn(walk_dist2(p, b->on[0]), walk_dist2(p, b->on[1]));
	if (known2 < least2)
		return false;
	/* nor can the answer exceed the known distance (less the points' rounding, WALK_SKIN of the
	 * coordinates' magnitude): a nearer cap prunes more of the tree */
	double mag = walk_maxn(fabs(p.x), walk_maxn(fabs(p.y), fabs(p.z)));
	float cap = (float)walk_minn(WALK_BALL_CAP * mfp, sqrt(known2) - WALK_SKIN * mag);
	if (!(cap > 0.0f))
		return false;
	res->queries++;
	b->c = p;
	b->r = (double)pr->nearest(pr->ctx, p, cap);
	if (!(b->r >= WALK_BALL_MIN * mfp)) {
		b->wait = b->backoff;
		b->backoff = b->backoff < WALK_BALL_WAIT ? 2 * b->backoff : WALK_BALL_WAIT;
	} else {
		b->backoff = 1;
	}
	if (need < b->r) {
		res->skipped++;
		return true;
	}
	return false;
}

/* ---- runs inside a free ball (README.md, "Runs inside a ball") ------------------------------------ */

/* A run starts at a collision at least this many mean free paths (mfp_ball) inside the known
 * ball: nearer its surface it would end within a step or two, and its setup (six exponentials)
 * would cost more than the steps it makes cheaper. */
#ifndef WALK_RUN_MIN
#define WALK_RUN_MIN 2.0
#endif
/* A run makes at most this many collisions before handing back to the walk's loop (Russian
 * roulette and the step bound are the loop's): it bounds the exponents of its weights, about
 * this many mean free paths' worth, far inside a double's range. */
#define WALK_RUN_MAX 128

static bool walk_run = true;
void sss_walk_set_run(bool on) { walk_run = on; }

/* A Henyey-Greenstein direction about w (53 bits for the cosine, 32 for the azimuth) or, when
 * isotropic, Marsaglia's (1972): a point (a, b) uniform in the unit disc by rejection from the
 * square (32-bit draws, 4/pi tries on average), s = a^2 + b^2, the direction
 * (2a sqrt(1 - s), 2b sqrt(1 - s), 1 - 2s), uniform on the sphere; no trigonometry, no basis. */
static vec3 walk_run_dir(double g_hg, vec3 w, rng *g)
{
	if (fabs(g_hg) >= WALK_G_ISOTROPIC) {
		double u1 = rng_double(g), u2 = walk_u32(g);
		return sss_walk_sample_hg(w, g_hg, u1, u2);
	}
	for (;;) {
		float a = (float)(2.0 * walk_u32(g) - 1.0), b = (float)(2.0 * walk_u32(g) - 1.0), s = a * a + b * b;
		if (s < 1.0f && s > 0.0f) {
			float r = 2.0f * sqrtf(1.0f - s);
			return v3(a * r, b * r, 1.0f - 2.0f * s);
		}
	}
}

/* The radius about the ball's centre within which a run's collisions stay (0: none): the ball
 * less the skin ahead of a surface (WALK_REACH of the larger of the coordinates' magnitude and
 * the largest triangle's scale met, whose rounding the nearest distance carries, as the skipped
 * casts' test) and a relative 1e-6 of the radius for the float points' rounding. Every point of
 * a segment between two points within it is within it (the ball is convex). */
static double walk_run_limit(const walk_ball *b, double last_scale)
{
	double mag = walk_maxn(last_scale, walk_maxn(fabs(b->c.x), walk_maxn(fabs(b->c.y), fabs(b->c.z))));
	return walk_maxn(0.0, b->r * (1.0 - 1e-6) - 2.0 * WALK_REACH * mag);
}

/* The run's state handed back to the walk: the point and direction after its last collision, and
 * the free path already drawn along that direction that would leave the ball. */
typedef struct walk_run_end {
	vec3 p, w;
	double t;
} walk_run_end;

/* From a collision at p, free of surface within the ball b: the classic walk of the hero channel
 * (directions from the phase function, free paths of the hero's extinction; no guide, no cast,
 * no weights per step) until a free path would end beyond lim (walk_run_limit; p is within it),
 * the step bound is
 * reached or WALK_RUN_MAX collisions are made; then the channels' weights take the whole run at
 * once: n collisions and a length L multiply f_k by (sigma_s,k / sigma_t,h)^n e^{-(sigma_t,k -
 * sigma_t,h) L} and ratio_k by (sigma_t,k / sigma_t,h)^n e^{-(sigma_t,k - sigma_t,h) L}, exactly
 * the products the loop's classic steps would make (walk_path_pdf with no guide: sigma e^{-sigma
 * t} a collision), and an unbiased walk, the strategy being a function of the state (the mixture
 * of the loop's one-sample MIS may depend on the point; inside the ball it is the classic one).
 * log_s, log_t: ln(sigma_s,k / sigma_t,h), ln(sigma_t,k / sigma_t,h) (unused where sigma_s,k
 * or sigma_t,k is 0: that channel's f or ratio becomes 0). */
static walk_run_end walk_run_ball(const sss_walk_medium *m, const walk_ball *b, double lim, const double sigma_t[3],
				  int hero, const double log_s[3], const double log_t[3], vec3 p, vec3 w, rng *g,
				  sss_walk_result *res, int max_steps, double f[3], double ratio[3])
{
	double sh = sigma_t[hero], inv_sh = 1.0 / sh, len = 0.0, lim2 = lim * lim;
	int n = 0;
	walk_run_end e;
	for (;;) {
		w = walk_run_dir(m->g, w, g);
		double t = -log(1.0 - rng_double(g)) * inv_sh;
		vec3 q = v3_madd(p, w, (float)t);
		if (!(walk_dist2(q, b->c) < lim2) || n >= WALK_RUN_MAX || res->steps >= max_steps) {
			e.p = p, e.w = w, e.t = t;
			break;
		}
		p = q, len += t, n++;
		res->steps++, res->skipped++;
	}
	res->runs++;
	if (n == 0)
		return e; /* no collision, no length: the weights stand */
	for (int k = 0; k < 3; k++) {
		double dl = -(sigma_t[k] - sh) * len;
		f[k] = m->sigma_s[k] > 0.0 ? f[k] * sss_walk_exp(walk_minn(700.0, n * log_s[k] + dl)) : 0.0;
		ratio[k] = sigma_t[k] > 0.0 ? ratio[k] * sss_walk_exp(walk_minn(700.0, n * log_t[k] + dl)) : 0.0;
	}
	return e;
}

/* One of the few functions over 100 lines left whole (issue 16): the walk is one loop whose
 * steps (the boundary hit, the free flight with its channel pdfs, the exit test, the reentry
 * after a step that lands outside, the scattering) read and write the same variables of its
 * state (origin, direction, beta, the sampling record, outward, stuck, steps, the result);
 * split, each step would take them all by pointer and the loop would read worse, not better. */
sss_walk_result sss_walk(const sss_walk_medium *m, const sss_probe *pr, vec3 x, vec3 ng, float x_scale, vec3 w,
			 rng *g, int max_steps)
{
	sss_walk_result res = {0};
	res.weight = v3s(0.0f);
	if (!v3_is_finite(x) || !v3_is_finite(ng) || !v3_is_finite(w) || v3_length2(w) == 0.0f || max_steps < 1) {
		res.status = SSS_WALK_BAD_INPUT;
		return res;
	}
	double sigma_t[3], beta[3] = {1.0, 1.0, 1.0};
	for (int c = 0; c < 3; c++)
		sigma_t[c] = m->sigma_s[c] + m->sigma_a[c];
	w = v3_normalize(w);
	vec3 org = bvh_offset_scaled(x, walk_side(ng, w), x_scale);
	/* the mesh's orientation, from the entry: +1 when ng points out of the medium */
	float outward = v3_dot(w, ng) <= 0.0f ? 1.0f : -1.0f;
	walk_guide gd = walk_guide_make(m, sigma_t, x, v3_neg(walk_side(ng, w)));
	walk_dir wd = {0}; /* the entry direction: no scattering event chose it */
	/* spectral MIS over the whole walk (hero channel; Wilkie et al. 2014, pbrt-v4's volumes):
	 * the free paths of one channel, chosen with probability q_c for the whole walk; f: each
	 * channel's path throughput over the hero's path density; ratio: each channel's path
	 * density over the hero's. The weight of channel k is f_k / sum_c q_c ratio_c. */
	double f[3] = {1.0, 1.0, 1.0}, ratio[3] = {1.0, 1.0, 1.0}, q[3];
	walk_hero_probs(m, sigma_t, q);
	int hero = walk_hero(q, rng_double(g));
	double stretch = 1.0;
	int stuck = 0;		  /* reentries in a row */
	double last_scale = x_scale; /* the largest triangle scale met: the skin's scale ahead */
	walk_ball ball = {.c = org, .r = 0.0, .wait = 0, .backoff = 1, .on = {x, x}};
	/* The balls' and runs' length unit: the mean free path of the channel of the highest
	 * single-scattering albedo, whichever the hero. A run changes the sampling, and spectral
	 * MIS weighs each channel by the density its own walk would have given the path: every
	 * choice of strategy must be a function of the path alone, the same for every hero, so the
	 * queries (which make the balls) and the runs' start must not depend on the hero's
	 * extinction (issue 21, sixth pass). */
	double mfp_ball = 0.0, a_top = -1.0;
	for (int c = 0; c < 3; c++) {
		double a = sigma_t[c] > 0.0 ? m->sigma_s[c] / sigma_t[c] : -1.0;
		if (a > a_top)
			a_top = a, mfp_ball = 1.0 / sigma_t[c];
	}
	double pending = -1.0;		  /* a free path a run drew, for the next flight; < 0: none */
	double log_s[3], log_t[3];	  /* for runs: ln(sigma_s,k / sigma_t,h), ln(sigma_t,k / sigma_t,h) */
	bool logs = false;
	for (res.steps = 0; res.steps < max_steps;) {
		/* the hero's free path (stretched when the direction was guided); the densities of
		 * every channel and strategy for the path so far are kept relative to the hero's */
		double st = sigma_t[hero] * stretch;
		/* -ln(1 - u): u has 53 bits, so 1 - u is exact and log's argument is log1p's (libm's
		 * log is the cheaper of the two: issue 21); a run inside a ball hands over the free
		 * path it drew (classic: stretch 1) */
		double t = pending >= 0.0 ? pending : st > 0.0 ? -log(1.0 - rng_double(g)) / st : INFINITY;
		pending = -1.0;
		/* The ray only needs to reach past the free path: a boundary beyond it is not met
		 * (issue 21: a cast bounded by t visits the BVH's nodes along a segment a few mean
		 * free paths long, not the whole chord to the far side; measured in
		 * bench/sss/README.md). WALK_REACH of the coordinates' magnitude past t keeps the
		 * skin below for boundaries within it. Every WALK_WHOLE_EVERY-th cast is whole,
		 * the first among them (the guide wants the far side below the entry): a walk that
		 * left through a crack of an open mesh ends LOST within that many steps instead of
		 * wandering in the void. */
		float reach = INFINITY;
		bool bounded = res.steps % WALK_WHOLE_EVERY != 0 && t < INFINITY, hit = false;
		double skin = 0.0;
		if (bounded) {
			skin = WALK_REACH * walk_maxn(last_scale, walk_maxn(fabs(org.x), walk_maxn(fabs(org.y), fabs(org.z))));
			reach = (float)(t + skin);
		}
		sss_probe_hit h;
		/* Inside a ball known to be free of surface the bounded cast can only miss (README.md,
		 * "Skipping casts"): its answer is known without it. The skin's margin again, and a
		 * relative 1e-6, cover the cast's rounding and the float ray's. */
		if (!bounded || !walk_ball_holds(&ball, pr, org, (double)reach * (1.0 + 1e-6) + skin, mfp_ball,
						 &res)) {
			bvh_ray ray = {org, w, 0.0f, reach};
			hit = pr->closest(pr->ctx, &ray, &h);
		}
		if (!hit && !(reach < INFINITY)) {
			res.status = SSS_WALK_LOST;
			return res;
		}
		if (!hit) /* nothing within reach: the free path ends inside, a collision */
			h.t = INFINITY, h.scale = 0.0f, h.p = org, h.ng = v3(0.0f, 0.0f, 1.0f);
		else
			last_scale = walk_maxn(last_scale, (double)h.scale), ball.on[1] = h.p;
		if (gd.on && res.steps == 0) { /* the far side below the entry (Cycles' opposite interface) */
			gd.far = walk_max(0.0, -(double)v3_dot(v3_sub(h.p, gd.x), gd.n));
			/* (the guided fraction faded with this thickness until issue 21's second pass,
			 * 1 - e^{-far sigma_ref / (4 nu)}: with the backward guide and the higher
			 * fraction of bright media the fade cost efficiency in every layer walkbench
			 * measures, 3 and 30 mm of skin, wax and marble; src/sss/README.md) */
		}
		double scale = walk_maxn(h.scale, walk_maxn(fabs(h.p.x), walk_maxn(fabs(h.p.y), fabs(h.p.z))));
		double cos_n = walk_maxn(1e-6, fabs((double)v3_dot(w, h.ng)));
		double d = walk_maxn(0.0, h.t - WALK_SKIN * scale / cos_n); /* w is unit */
		res.steps++;
		bool collision = t < d;
		double len = collision ? t : d, p[3], e[3];
		for (int k = 0; k < 3; k++) {
			e[k] = sss_walk_exp(-sigma_t[k] * len);
			p[k] = walk_path_pdf(&gd, &wd, sigma_t[k], len, e[k], collision);
		}
		if (!(p[hero] > 0.0) || !isfinite(p[hero])) {
			res.status = SSS_WALK_ABSORBED; /* the density underflowed: nothing is carried */
			return res;
		}
		double big = 0.0;
		double inv_hero = 1.0 / p[hero];
		for (int k = 0; k < 3; k++) {
			f[k] *= (collision ? m->sigma_s[k] : 1.0) * e[k] * inv_hero;
			ratio[k] *= p[k] * inv_hero;
			big = walk_maxn(big, walk_maxn(f[k], ratio[k]));
		}
		if (big > 1e100) /* the weights are f over the mixture of ratios: rescale both alike */
			for (int k = 0; k < 3; k++)
				f[k] *= 1e-100, ratio[k] *= 1e-100;
		walk_beta(q, f, ratio, beta);
		if (!(walk_max(beta[0], walk_max(beta[1], beta[2])) > 0.0)) {
			res.status = SSS_WALK_ABSORBED; /* nothing scatters (a pure absorber), or all underflowed */
			return res;
		}
		if (collision) {
			org = v3_madd(org, w, (float)t);
			/* a run's start lies within its limit, WALK_RUN_MIN mean free paths inside the ball */
			double lim = ball.r > 0.0 ? walk_run_limit(&ball, last_scale) : 0.0;
			double room = walk_minn(lim, ball.r - WALK_RUN_MIN * mfp_ball);
			if (walk_run && room > 0.0 && walk_dist2(org, ball.c) < room * room) {
				if (!logs) {
					for (int k = 0; k < 3; k++) {
						log_s[k] = m->sigma_s[k] > 0.0 ? log(m->sigma_s[k] / sigma_t[hero]) : 0.0;
						log_t[k] = sigma_t[k] > 0.0 ? log(sigma_t[k] / sigma_t[hero]) : 0.0;
					}
					logs = true;
				}
				walk_run_end e = walk_run_ball(m, &ball, lim, sigma_t, hero, log_s, log_t, org, w, g, &res,
							       max_steps, f, ratio);
				org = e.p, w = e.w, pending = e.t;
				wd.scattered = false, stretch = 1.0; /* the next free path is classic */
				double top = 0.0;
				for (int k = 0; k < 3; k++)
					top = walk_maxn(top, walk_maxn(f[k], ratio[k]));
				if (top > 1e100)
					for (int k = 0; k < 3; k++)
						f[k] *= 1e-100, ratio[k] *= 1e-100;
				walk_beta(q, f, ratio, beta);
				if (!(walk_max(beta[0], walk_max(beta[1], beta[2])) > 0.0)) {
					res.status = SSS_WALK_ABSORBED;
					return res;
				}
			} else {
				w = walk_scatter(m, &gd, org, w, g, &wd, &stretch);
			}
		} else {
			wd.scattered = false, stretch = 1.0; /* the next direction is the boundary's */
			vec3 n_out = walk_side(h.ng, w); /* points out of the medium along w */
			if (outward * v3_dot(w, h.ng) < 0.0f) {
				/* the surface seen from outside: a collision point rounded across the
				 * boundary (closer to it than a float resolves), or a ray leaving a large
				 * triangle from behind that the triangle test still reports at t ~ 0 (its
				 * error grows with the triangle's size, not with |p|). Step back in, each
				 * time in a row twice as far. */
				org = walk_step_in(h.p, n_out, h.scale, ++stuck);
				res.reentries++;
				continue;
			}
			stuck = 0;
			double cos_i = walk_min(1.0, (double)v3_dot(w, n_out));
			double eta = 1.0 / m->eta; /* from the medium (eta) to outside (1) */
			if (rng_double(g) < sss_fresnel_dielectric(cos_i, eta)) {
				w = v3_normalize(v3_madd(w, n_out, (float)(-2.0 * cos_i)));
				org = bvh_offset_scaled(h.p, v3_neg(n_out), h.scale);
				res.reflections++;
			} else {
				/* Snell: the tangential part scales by n_i/n_t = m->eta */
				double sin2_t = m->eta * m->eta * (1.0 - cos_i * cos_i);
				double cos_t = sqrt(walk_max(0.0, 1.0 - sin2_t));
				vec3 wt = v3_madd(v3_scale(w, (float)m->eta), n_out, (float)(cos_t - m->eta * cos_i));
				res.status = SSS_WALK_EXITED;
				res.p = h.p, res.ng = h.ng, res.dir = v3_normalize(wt);
				res.prim = h.prim, res.u = h.u, res.v = h.v;
				res.weight = v3((float)beta[0], (float)beta[1], (float)beta[2]);
				if (!v3_is_finite(res.weight) || !v3_is_finite(res.dir)) {
					res.weight = v3s(0.0f);
					res.status = SSS_WALK_LOST;
				}
				return res;
			}
		}
		if (res.steps >= SSS_WALK_RR_START) {
			double survive = walk_min(1.0, walk_max(beta[0], walk_max(beta[1], beta[2])));
			if (survive < 1.0) { /* (1: no draw, it would pass, and no rescaling) */
				if (!(rng_double(g) < survive)) {
					res.status = SSS_WALK_ABSORBED;
					return res;
				}
				double inv = 1.0 / survive;
				for (int k = 0; k < 3; k++)
					beta[k] *= inv, f[k] *= inv;
			}
		}
	}
	res.status = SSS_WALK_STEP_LIMIT;
	return res;
}

/* ---- closed meshes ---------------------------------------------------------------------------- */

/* A vertex under welding: its position and index, sorted by position (no context for qsort). */
typedef struct weld_vertex {
	vec3 p;
	uint32_t index;
} weld_vertex;

static int weld_cmp(const void *a, const void *b)
{
	vec3 p = ((const weld_vertex *)a)->p, q = ((const weld_vertex *)b)->p;
	if (p.x != q.x)
		return p.x < q.x ? -1 : 1;
	if (p.y != q.y)
		return p.y < q.y ? -1 : 1;
	if (p.z != q.z)
		return p.z < q.z ? -1 : 1;
	return 0;
}

static int edge_cmp(const void *a, const void *b)
{
	uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
	return x < y ? -1 : x > y;
}

sss_mesh_closure sss_walk_mesh_closure(const mesh *m, uint64_t *open_edges)
{
	if (open_edges)
		*open_edges = 0;
	if (m->num_triangles == 0)
		return SSS_MESH_OPEN;
	uint32_t nv = m->num_vertices;
	weld_vertex *order = mem_alloc(nv, sizeof *order);
	uint32_t *canon = mem_alloc(nv, sizeof *canon);
	uint64_t *edges = mem_alloc(m->num_triangles, 3 * sizeof *edges);
	if (!order || !canon || !edges) {
		mem_free(order), mem_free(canon), mem_free(edges);
		return SSS_MESH_NO_MEMORY;
	}
	for (uint32_t i = 0; i < nv; i++)
		order[i] = (weld_vertex){m->positions[i], i};
	qsort(order, nv, sizeof *order, weld_cmp);
	for (uint32_t i = 0; i < nv; i++)
		canon[order[i].index] = i > 0 && weld_cmp(&order[i - 1], &order[i]) == 0 ? canon[order[i - 1].index]
										    : order[i].index;
	size_t ne = 0;
	for (uint32_t t = 0; t < m->num_triangles; t++) {
		uint32_t v[3];
		for (int k = 0; k < 3; k++)
			v[k] = canon[m->indices[3 * (size_t)t + k]];
		if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0])
			continue; /* collapsed by welding: no area, no edges */
		for (int k = 0; k < 3; k++) {
			uint32_t a = v[k], b = v[(k + 1) % 3];
			edges[ne++] = a < b ? (uint64_t)a << 32 | b : (uint64_t)b << 32 | a;
		}
	}
	qsort(edges, ne, sizeof *edges, edge_cmp);
	uint64_t open = 0;
	for (size_t i = 0; i < ne;) {
		size_t j = i;
		while (j < ne && edges[j] == edges[i])
			j++;
		open += j - i != 2;
		i = j;
	}
	mem_free(order), mem_free(canon), mem_free(edges);
	if (open_edges)
		*open_edges = open;
	return open == 0 && ne > 0 ? SSS_MESH_CLOSED : SSS_MESH_OPEN;
}
