/* disk.c - the disk comparator (King et al. 2013): probe axes, the MIS density of a hit, the
 * weights of every hit of a probe, and the choice of one. */
#include "sss/disk.h"

#include "sss/circle.h"

#include <assert.h>
#include <math.h>

#define DISK_PI 3.14159265358979323846

sss_disk_frame sss_disk_frame_make(vec3 x, vec3 n)
{
	sss_disk_frame f;
	f.x = x;
	f.axis[0] = n;
	v3_basis(n, &f.axis[1], &f.axis[2]);
	f.p[0] = SSS_DISK_P_NORMAL, f.p[1] = f.p[2] = SSS_DISK_P_TANGENT;
	return f;
}

sss_disk_probe sss_disk_probe_axis(const sss_profile *p, double mm_per_unit, const sss_disk_frame *f, int axis,
				   double r_mm, double u_phi)
{
	sss_disk_probe q;
	q.axis = axis;
	q.r_mm = r_mm;
	double r_max = sss_profile_r_max(p) / mm_per_unit, r = q.r_mm / mm_per_unit;
	double half = sqrt(fmax(0.0, r_max * r_max - r * r)), phi = 2.0 * DISK_PI * u_phi;
	vec3 a = f->axis[q.axis], e1 = f->axis[(q.axis + 1) % 3], e2 = f->axis[(q.axis + 2) % 3];
	/* the disk point x + r (cos phi e1 + sin phi e2), then up the axis to the sphere */
	vec3 c = v3_add(f->x, v3_add(v3_scale(e1, (float)(r * cos(phi))), v3_scale(e2, (float)(r * sin(phi)))));
	q.org = v3_madd(c, a, (float)half);
	q.dir = v3_neg(a);
	q.tmax = (float)(2.0 * half);
	return q;
}

sss_disk_probe sss_disk_probe_make(const sss_profile *p, double mm_per_unit, const sss_disk_frame *f,
				   const double u[3])
{
	/* u[0] picks the axis by f->p; what is left of it, rescaled, is phi (as Cycles'
	 * subsurface_disk reuses its disk_u): a stratified set of (u[0], u[2]) stays stratified in
	 * (phi, r) on each axis. */
	assert(f->p[0] > 0.0 && f->p[1] > 0.0 && f->p[2] > 0.0);
	int axis = u[0] < f->p[0] ? 0 : u[0] < f->p[0] + f->p[1] ? 1 : 2;
	double lo = axis == 0 ? 0.0 : axis == 1 ? f->p[0] : f->p[0] + f->p[1];
	double phi = fmin(fmax((u[0] - lo) / f->p[axis], 0.0), 1.0);
	return sss_disk_probe_axis(p, mm_per_unit, f, axis, sss_profile_sample(p, u[1], u[2]), phi);
}

void sss_disk_axis_pdfs(const sss_profile *p, double mm_per_unit, const sss_disk_frame *f, vec3 y, vec3 n_y,
			double pdf_mm2[3])
{
	dvec3 d = d3_scale(d3_sub(v3_to_d3(y), v3_to_d3(f->x)), mm_per_unit), ny = v3_to_d3(n_y);
	double r_max = sss_profile_r_max(p), dd = d3_dot(d, d);
	for (int a = 0; a < 3; a++) {
		if (!(dd < r_max * r_max)) { /* outside the sphere that bounds every probe */
			pdf_mm2[a] = 0.0;
			continue;
		}
		dvec3 ax = v3_to_d3(f->axis[a]);
		double along = d3_dot(d, ax), cos_y = fabs(d3_dot(ny, ax));
		double r_a = sqrt(fmax(0.0, dd - along * along)); /* the distance across the axis */
		if (!(r_a < r_max) || cos_y == 0.0)
			pdf_mm2[a] = 0.0;
		else if (r_a == 0.0)
			pdf_mm2[a] = INFINITY;
		else
			pdf_mm2[a] = sss_profile_pdf(p, r_a) / (2.0 * DISK_PI * r_a) * cos_y;
	}
}

double sss_disk_pdf_area(const sss_profile *p, double mm_per_unit, const sss_disk_frame *f, vec3 y, vec3 n_y)
{
	double pdf[3];
	sss_disk_axis_pdfs(p, mm_per_unit, f, y, n_y, pdf);
	return f->p[0] * pdf[0] + f->p[1] * pdf[1] + f->p[2] * pdf[2];
}

int sss_disk_gather(const sss_profile *p, double mm_per_unit, const sss_disk_frame *f, const sss_disk_probe *q,
		    const sss_probe *pr, sss_disk_hit *hits, int max_hits, bool *more)
{
	if (more)
		*more = false;
	if (!(q->tmax > 0.0f) || max_hits <= 0)
		return 0;
	sss_probe_hit ph[SSS_DISK_MAX_HITS];
	bvh_ray ray = {q->org, q->dir, 0.0f, q->tmax};
	int cap = max_hits < SSS_DISK_MAX_HITS ? max_hits : SSS_DISK_MAX_HITS;
	int k = sss_probe_all(pr, &ray, ph, cap, more);
	for (int i = 0; i < k; i++) {
		sss_disk_hit *h = &hits[i];
		h->p = ph[i].p, h->ng = ph[i].ng, h->prim = ph[i].prim, h->u = ph[i].u, h->v = ph[i].v;
		vec3 d = v3_sub(h->p, f->x);
		double dist = v3_length(d), pdf = sss_disk_pdf_area(p, mm_per_unit, f, h->p, h->ng);
		vec3 R = sss_profile_eval(p, dist * mm_per_unit);
		float leak = sss_circle_leak(f->axis[0], h->ng, dist > 0.0 ? v3_scale(d, (float)(1.0 / dist)) : v3s(0.0f));
		h->weight = v3s(0.0f);
		if (pdf > 0.0 && isfinite(pdf)) {
			vec3 w = v3_scale(R, (float)(leak / pdf));
			if (v3_is_finite(w))
				h->weight = w;
		}
	}
	return k;
}

int sss_disk_choose(const sss_disk_hit *hits, int k, float u, vec3 *weight, float *prob)
{
	*weight = v3s(0.0f);
	*prob = 0.0f;
	double total = 0.0;
	for (int i = 0; i < k; i++)
		total += fmax(0.0, v3_luminance(hits[i].weight));
	if (!(total > 0.0) || !isfinite(total))
		return -1;
	double x = u * total;
	int pick = -1;
	for (int i = 0; i < k; i++) {
		double l = v3_luminance(hits[i].weight);
		if (l <= 0.0)
			continue;
		pick = i; /* the last positive hit when rounding leaves x over */
		if (x < l)
			break;
		x -= l;
	}
	assert(pick >= 0); /* total > 0: some hit has a positive weight */
	*prob = (float)(v3_luminance(hits[pick].weight) / total);
	*weight = v3_scale(hits[pick].weight, 1.0f / *prob);
	return pick;
}
