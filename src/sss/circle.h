/* circle.h - the estimator mathematics of circle tracing (Legros & Corvazier 2016; DESIGN.md,
 * "Circle sampling"), independent of any BVH: the circle of a sampled radius, the exact area
 * density of a hit on it, the leak filter, and the choice of one hit among all hits of a circle.
 * Thread-safe: pure functions of their arguments; nothing allocates. */
#ifndef CIRCE_SSS_CIRCLE_H
#define CIRCE_SSS_CIRCLE_H

#include "accel/tri.h"
#include "base/vec.h"

#include <stdbool.h>

typedef enum sss_circle_kind {
	SSS_CIRCLE_HALF, /* theta in [-pi/2, pi/2], phi in [0, 2 pi): a plane is hit exactly once */
	SSS_CIRCLE_FULL, /* theta in [0, 2 pi), phi in [0, pi) */
} sss_circle_kind;

typedef enum sss_circle_weight {
	SSS_CIRCLE_EXACT, /* the exact density of DESIGN.md */
	SSS_CIRCLE_TALK, /* the talk's 1/sqrt(1 - (n_i.d)^2): |n_i.e_theta| replaced by sqrt(1 - (n_i.d)^2) */
} sss_circle_weight;

/* The floor of |n_i . e_theta| in the density: the remedy for grazing hits, a clamp (README.md,
 * "Grazing hits", has the measurements that chose it: 0.34 % low on the worst scene measured).
 * It bounds every hit's weight by ratio_c / (2 pi p_phi SSS_CIRCLE_GRAZING_MIN). */
#define SSS_CIRCLE_GRAZING_MIN 0.02f

/* Hits of one circle whose angles differ by at most this (radians, either way round) are one point
 * of the surface, counted once (README.md, "Coincident surfaces"): duplicated triangles, or two
 * objects of one SSS volume in the same place, each report the same point. A few float ulps of
 * an angle near 2 pi (4.8e-7), far below any distance between distinct surfaces that matters:
 * two hits that close are r * 2e-6 apart. */
#define SSS_CIRCLE_SAME_THETA 2e-6f

/* The most hits sss_circle_choose weighs in one call: it keeps their weights on the stack (16
 * bytes each). Twice the renderer's RENDER_SSS_MAX_HITS (64), the hits it keeps of one circle. */
#define SSS_CIRCLE_MAX_HITS 128

/* Probabilities of the three circle families (axes n, b1, b2) under mis_axes: King et al. 2013's
 * probe-axis probabilities. */
#define SSS_CIRCLE_MIS_Q_NORMAL 0.5f

typedef struct sss_circle_opts {
	sss_circle_kind kind;
	sss_circle_weight weight;
	/* One-sample MIS over three families of circles, whose planes contain n, b1 or b2
	 * (probabilities 0.5, 0.25, 0.25), balance heuristic. Off by default (README.md). */
	bool mis_axes;
	float grazing_min; /* floor of |n_i . e| in every density, in [0, 1); 0 is the pure density */
} sss_circle_opts;

/* Half circles, exact weight, no MIS, the grazing floor SSS_CIRCLE_GRAZING_MIN. */
sss_circle_opts sss_circle_default_opts(void);

/* One circle: c(theta) = q.centre + q.radius (cos(theta) q.t + sin(theta) q.n), the query the
 * BVH traces (accel/tri.h) with what the estimator adds to it. */
typedef struct sss_circle {
	tri_circle q;		    /* centre x (the exit point), radius r > 0 (the sampled profile radius,
				     * scene units), the plane's t and axis q.n: the exit's normal unless
				     * mis_axes chose b1 or b2; q.full for full circles */
	vec3 n, b1, b2;		    /* the exit's geometric normal and its basis (v3_basis) */
	float theta_min, theta_max; /* the arc to trace */
	float p_phi;		    /* density of phi: 1/(2 pi) half, 1/pi full */
	int family;		    /* 0 (axis n), 1 (b1), 2 (b2) */
} sss_circle;

/* A hit of the circle on the surface is the BVH's tri_circle_hit: the estimator reads its
 * position pos, its unit geometric normal ng (either orientation) and its angle theta. */

/* The circle at exit point x with unit normal n, of radius r, with phi = 2 pi u_phi (half) or
 * pi u_phi (full); u_family (in [0, 1)) picks the family when o->mis_axes, else is ignored. */
sss_circle sss_circle_make(vec3 x, vec3 n, float r, float u_family, float u_phi, const sss_circle_opts *o);
vec3 sss_circle_point(const sss_circle *c, float theta);
/* The unit tangent e_theta = -sin(theta) t + cos(theta) axis. */
vec3 sss_circle_tangent(const sss_circle *c, float theta);

/* The area density p_A of a hit (per unit area, in the units of 1 / (radius^2)), given the pdf
 * of r (pdf_r = sss_profile_pdf(r)): p(r) p_phi |n_i . e_theta| / (r sqrt(1 - (n . d)^2)) for
 * the exact weight, summed over the families with their probabilities under mis_axes. Zero at
 * an exactly grazing hit when grazing_min is 0; +Inf for a hit on the axis (theta = +-pi/2). */
float sss_circle_pdf_area(const sss_circle *c, float pdf_r, const tri_circle_hit *h,
			  const sss_circle_opts *o);

/* The leak filter of DESIGN.md: mix(1, max(0, n . n_i), max(0, n . d)), d = (x_i - x)/|x_i - x|. */
float sss_circle_leak(vec3 n, vec3 n_i, vec3 d);

/* R(r) f_t / p_A of one hit, per channel, from ratio = sss_profile_ratio(r) (2 pi r R / p(r)):
 * computed as ratio f_t / (2 pi H) with H = r p_A / p(r), so r and p(r) never divide. Zero for a
 * hit on the circle's axis. Finite for every input when grazing_min > 0, and then each channel is
 * at most ratio_c / (2 pi p_phi grazing_min) (ratio_c / grazing_min for half circles). */
vec3 sss_circle_hit_weight(const sss_circle *c, vec3 ratio, const tri_circle_hit *h,
			   const sss_circle_opts *o);

/* True when hits[i] is at the point of an earlier hit (hits[0] to hits[i - 1]): their angles within
 * SSS_CIRCLE_SAME_THETA. Such a hit is not counted by sss_circle_choose. */
bool sss_circle_repeats(const tri_circle_hit *hits, int i);

/* Resampling among the k hits of one circle: picks hit i with probability
 * P_i = lum(w_i) / sum_j lum(w_j), w_i = sss_circle_hit_weight, using u in [0, 1), where hits that
 * repeat an earlier one's point (sss_circle_repeats) weigh 0: each point of the surface counts
 * once, however many coincident triangles report it (the first in the array stands for them, its
 * normal used). Returns i, with
 * *weight = w_i / P_i (the estimator's factor: multiply by the light arriving at hit i) and
 * *prob = P_i; each channel of *weight is at most k times the bound of sss_circle_hit_weight.
 * Returns -1 with *weight = 0 and *prob = 0 when k is 0 or every weight is 0 (the caller counts
 * the no-hit case). k is at most SSS_CIRCLE_MAX_HITS (asserted); each weight is computed once. */
int sss_circle_choose(const sss_circle *c, vec3 ratio, const tri_circle_hit *hits, int k, float u,
		      const sss_circle_opts *o, vec3 *weight, float *prob);

#endif
