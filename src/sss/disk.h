/* disk.h - the disk comparator of `--sss disk` (DESIGN.md, "The two comparators"): King, Kulla,
 * Conty & Fajardo 2013, "BSSRDF Importance Sampling" (SIGGRAPH talk). At the exit point x with
 * frame (n, t, b) a probe axis is chosen (n, t, b with probabilities 0.9, 0.05, 0.05), a radius r
 * from the profile (one-sample MIS over channels) and an angle phi on the disk perpendicular to
 * the axis; the segment along the axis through that disk point, inside the sphere of radius r_max,
 * is traced and EVERY hit on the object is kept, weighted by MIS over the three axes. The density
 * and its derivation: src/sss/README.md, "The disk comparator". Thread-safe; nothing allocates. */
#ifndef CIRCE_SSS_DISK_H
#define CIRCE_SSS_DISK_H

#include "base/vec.h"
#include "sss/probe.h"
#include "sss/profile.h"

#include <stdbool.h>
#include <stdint.h>

/* Probabilities of the probe axes n, t, b. King et al. 2013 (and Cycles' subsurface_disk) use
 * 0.5, 0.25, 0.25; measured (src/sss/README.md, "The disk comparator"; bench/README.md), 0.9,
 * 0.05, 0.05 has the lower variance on the head (NMSE 5x lower) and on test_disk's spheres and
 * cylinders down to a radius of a quarter of r_max: the normal's probes find most of the light,
 * and a tangent's probes, which mostly miss, are needed only where the surface turns. */
#define SSS_DISK_P_NORMAL 0.9
#define SSS_DISK_P_TANGENT 0.05

/* Hits kept per probe; a probe with more is rare (a thin, folded object) and reported. */
#define SSS_DISK_MAX_HITS 16

/* The frame at the exit point: x, the unit normal n (outward) and the tangents t, b of v3_basis. */
typedef struct sss_disk_frame {
	vec3 x, axis[3]; /* axis[0] = n, axis[1] = t, axis[2] = b */
	double p[3];	 /* the axes' probabilities P_a, each > 0, summing to 1 (sss_disk_frame_make:
			  * SSS_DISK_P_NORMAL, SSS_DISK_P_TANGENT, SSS_DISK_P_TANGENT) */
} sss_disk_frame;

sss_disk_frame sss_disk_frame_make(vec3 x, vec3 n);

/* One probe: the segment org + s dir, s in [0, tmax] (scene units, dir unit), along axis `axis`
 * (0 n, 1 t, 2 b) at distance r_mm (mm) from x. tmax is 0 when r_mm >= r_max (nothing to trace). */
typedef struct sss_disk_probe {
	vec3 org, dir;
	float tmax;
	int axis;
	double r_mm;
} sss_disk_probe;

/* The probe from three uniform numbers in [0, 1): u[0] the axis (by f->p) and, rescaled within
 * the axis's share, phi; u[1] the channel, u[2] the radius. (u[0], u[2]) is best one 2-D
 * stratified point. mm_per_unit (> 0) converts the profile's mm to scene units. */
sss_disk_probe sss_disk_probe_make(const sss_profile *p, double mm_per_unit, const sss_disk_frame *f,
				   const double u[3]);

/* The probe along axis `axis` (0 n, 1 t, 2 b) at the radius r_mm (mm, sampled from the profile's
 * mixture pdf: sss_profile_sample or sss_profile_sample1) and the angle 2 pi u_phi. */
sss_disk_probe sss_disk_probe_axis(const sss_profile *p, double mm_per_unit, const sss_disk_frame *f, int axis,
				   double r_mm, double u_phi);

/* The area density, per mm^2, with which the probe along axis a reaches the surface point y of
 * unit normal n_y: pdf(r_a) / (2 pi r_a) |n_y . a|, r_a the distance (mm) from x to y across the
 * axis, pdf the profile's mixture pdf; zero beyond r_max, +Inf at r_a = 0 (when n_y . a != 0).
 * pdf_mm2[a] for a = n, t, b. */
void sss_disk_axis_pdfs(const sss_profile *p, double mm_per_unit, const sss_disk_frame *f, vec3 y, vec3 n_y,
			double pdf_mm2[3]);
/* The density of the whole sampler (one-sample MIS over axes, balance heuristic):
 * sum_a P_a pdf_a(y), per mm^2, P_a = f->p[a]. */
double sss_disk_pdf_area(const sss_profile *p, double mm_per_unit, const sss_disk_frame *f, vec3 y, vec3 n_y);

/* One hit of a probe with its weight. */
typedef struct sss_disk_hit {
	vec3 p, ng;	/* position and unit geometric normal (outward on a well-wound mesh) */
	uint32_t prim;	/* triangle and barycentrics, for textures at the entry point */
	float u, v;
	vec3 weight;	/* R(|p - x|) f_t / sss_disk_pdf_area, per channel, dimensionless; f_t the
			 * leak filter of DESIGN.md (sss_circle_leak); 0 on the probe's axis line */
} sss_disk_hit;

/* Traces the probe through pr and weighs every hit; returns the number of hits written (at most
 * max_hits); *more (may be NULL) is set when the probe had more hits than max_hits (those are
 * lost: count them). The sum of the weights (times the light at each hit) is the estimator. */
int sss_disk_gather(const sss_profile *p, double mm_per_unit, const sss_disk_frame *f, const sss_disk_probe *q,
		    const sss_probe *pr, sss_disk_hit *hits, int max_hits, bool *more);

/* Resampling among the k hits (as sss_circle_choose): picks hit i with probability
 * P_i = lum(w_i) / sum_j lum(w_j) using u in [0, 1), returns i with *weight = w_i / P_i and
 * *prob = P_i; -1 with zeros when k is 0 or every weight is 0 (the caller counts it). */
int sss_disk_choose(const sss_disk_hit *hits, int k, float u, vec3 *weight, float *prob);

#endif
