/* test_disk: the disk comparator (King et al. 2013) is unbiased: on a plane its mean is the albedo
 * (with variance, unlike circles); on a sphere and a cylinder it matches quadrature within 3
 * standard errors, each probe axis alone too; the MIS density is the sum of the axes'; the choice
 * among hits keeps the mean; weights do not depend on the scene's unit; the probe picks its axis
 * with the frame's probabilities and a uniform phi on it. */
#include "accel/bvh.h"
#include "base/rng.h"
#include "check.h"
#include "geom/prim.h"
#include "sss/disk.h"
#include "mean3.h"
#include "sss_test.h"

#include <stdio.h>
#include <string.h>

/* ---- analytic surfaces through the probe interface ------------------------------------------- */

/* A sphere (cylinder = false) of radius R about c, or an infinite cylinder about the y axis
 * through c; normals point away from the centre or axis. */
typedef struct quadric {
	dvec3 c;
	double R;
	bool cylinder;
} quadric;

static bool quadric_closest(const void *ctx, const bvh_ray *ray, sss_probe_hit *hit)
{
	const quadric *q = ctx;
	dvec3 o = d3_sub(v3_to_d3(ray->org), q->c), d = v3_to_d3(ray->dir);
	if (q->cylinder)
		o.y = 0.0, d.y = 0.0;
	double a = d3_dot(d, d), b = d3_dot(o, d), cc = d3_dot(o, o) - q->R * q->R, disc = b * b - a * cc;
	if (a == 0.0 || disc < 0.0)
		return false;
	double s = sqrt(disc), roots[2] = {(-b - s) / a, (-b + s) / a};
	for (int i = 0; i < 2; i++) {
		double t = roots[i];
		if (t < ray->tmin || t > ray->tmax)
			continue;
		dvec3 p = d3_add(v3_to_d3(ray->org), d3_scale(v3_to_d3(ray->dir), t)), n = d3_sub(p, q->c);
		if (q->cylinder)
			n.y = 0.0;
		hit->t = (float)t;
		hit->p = d3_to_v3(p);
		hit->ng = d3_to_v3(d3_normalize(n));
		hit->prim = 0, hit->u = hit->v = 0.0f;
		return true;
	}
	return false;
}

/* ---- integrands and quadrature --------------------------------------------------------------- */

static double g_smooth(vec3 y)
{
	return 1.0 + 0.5 * y.x + 0.3 * y.y * y.y;
}

#define GL_N 400
static double gl_x[GL_N], gl_w[GL_N];

/* integral over the surface of R_c(|y - x|) f_t g(y) dA, with x at (0, 0, R) on the sphere or
 * (R, 0, 0) on the cylinder; f_t = 1 on these convex surfaces (the leak filter's n . d <= 0). */
static double quadrature(const sss_profile *p, int c, const quadric *q)
{
	double r_max = sss_profile_r_max(p), R = q->R, sum = 0.0;
	if (!q->cylinder) {
		double th_max = r_max >= 2.0 * R ? PI : 2.0 * asin(r_max / (2.0 * R));
		for (int i = 0; i < GL_N; i++) {
			double th = th_max * gl_x[i], wt = th_max * gl_w[i];
			double dist = 2.0 * R * sin(0.5 * th);
			double Rv = v3_get(sss_profile_eval(p, dist), c);
			for (int j = 0; j < 256; j++) {
				double ph = 2.0 * PI * j / 256;
				vec3 y = v3((float)(R * sin(th) * cos(ph)), (float)(R * sin(th) * sin(ph)), (float)(R * cos(th)));
				sum += wt * (2.0 * PI / 256) * R * R * sin(th) * Rv * g_smooth(y);
			}
		}
		return sum;
	}
	double al_max = r_max >= 2.0 * R ? PI : acos(1.0 - r_max * r_max / (2.0 * R * R));
	for (int i = 0; i < GL_N; i++) {
		double al = al_max * gl_x[i], wa = al_max * gl_w[i];
		double chord2 = 2.0 * R * R * (1.0 - cos(al)), h_max = sqrt(fmax(0.0, r_max * r_max - chord2));
		for (int j = 0; j < GL_N; j++) {
			double h = h_max * gl_x[j], wh = h_max * gl_w[j];
			double Rv = v3_get(sss_profile_eval(p, sqrt(chord2 + h * h)), c);
			vec3 y = v3((float)(R * cos(al)), (float)h, (float)(R * sin(al)));
			sum += 4.0 * wa * wh * R * Rv * g_smooth(y); /* symmetric in alpha and h */
		}
	}
	return sum;
}

static sss_profile profile(sss_profile_kind kind, const double albedo[3], const double ld_mm[3])
{
	sss_profile p;
	CHECK(sss_profile_from_artist(&p, kind, albedo, ld_mm, 1.3), "profile not built");
	return p;
}

/* ---- the estimator --------------------------------------------------------------------------- */

typedef struct estimate {
	test_mean3 m;
	long no_hit, more;
} estimate;

/* Mean of sum over hits of w_i g(y_i) (force_axis < 0: the MIS sampler; else that axis alone,
 * weighted by its own density), or with choose, the resampled single hit. */
static estimate run(const sss_profile *p, double mm_per_unit, const sss_disk_frame *f, const sss_probe *pr,
		    long n, int force_axis, bool choose, uint64_t seed)
{
	rng r;
	rng_seed(&r, seed, 9);
	estimate e = {0};
	sss_disk_hit hits[SSS_DISK_MAX_HITS];
	for (long i = 0; i < n; i++) {
		double u[3] = {rng_double(&r), rng_double(&r), rng_double(&r)};
		sss_disk_probe q = force_axis >= 0 ? sss_disk_probe_axis(p, mm_per_unit, f, force_axis,
									 sss_profile_sample(p, u[1], u[2]), u[0])
						   : sss_disk_probe_make(p, mm_per_unit, f, u);
		bool more;
		int k = sss_disk_gather(p, mm_per_unit, f, &q, pr, hits, SSS_DISK_MAX_HITS, &more);
		e.no_hit += k == 0;
		e.more += more;
		double v[3] = {0, 0, 0};
		if (choose) {
			vec3 w;
			float prob;
			int pick = sss_disk_choose(hits, k, rng_float(&r), &w, &prob);
			if (pick >= 0)
				for (int c = 0; c < 3; c++)
					v[c] = v3_get(w, c) * g_smooth(hits[pick].p);
		} else {
			for (int j = 0; j < k; j++) {
				vec3 w = hits[j].weight;
				if (force_axis >= 0) {
					double pdf[3];
					sss_disk_axis_pdfs(p, mm_per_unit, f, hits[j].p, hits[j].ng, pdf);
					vec3 d = v3_sub(hits[j].p, f->x);
					vec3 R = sss_profile_eval(p, v3_length(d) * mm_per_unit);
					w = pdf[force_axis] > 0.0 && isfinite(pdf[force_axis])
						    ? v3_scale(R, (float)(1.0 / pdf[force_axis]))
						    : v3s(0.0f);
				}
				for (int c = 0; c < 3; c++)
					v[c] += v3_get(w, c) * g_smooth(hits[j].p);
			}
		}
		test_mean3_add(&e.m, v);
	}
	return e;
}

static void compare(const char *name, const estimate *e, const double want[3], int channels)
{
	for (int c = 0; c < channels; c++) {
		double got = test_mean3_mean(&e->m, c), se = test_mean3_se(&e->m, c);
		printf("%-34s ch %d: quadrature %.6f, disk %.6f +- %.6f (%+.2f SE), no-hit %.3f\n", name, c, want[c], got,
		       se, (got - want[c]) / se, (double)e->no_hit / e->m.n);
		CHECK(fabs(got - want[c]) <= 3.0 * se, "%s ch %d: %g +- %g, want %g", name, c, got, se, want[c]);
	}
	CHECK(e->more == 0, "%s: %ld probes with more than %d hits", name, e->more, SSS_DISK_MAX_HITS);
}

/* ---- the tests ------------------------------------------------------------------------------- */

/* The probe's axis and phi from u[0] (sss_disk_probe_make): each axis with its probability and a
 * uniform phi on it (chi-square over 3 x 16 bins), for the default probabilities and others; a
 * stratified u[0] gives each axis its exact share. */
static void check_probe_choice(void)
{
	const double grey[3] = {0.8, 0.8, 0.8}, ld[3] = {2.0, 2.0, 2.0};
	sss_profile p = profile(SSS_PROFILE_GAUSSIAN, grey, ld);
	const double ps[2][3] = {{SSS_DISK_P_NORMAL, SSS_DISK_P_TANGENT, SSS_DISK_P_TANGENT}, {0.3, 0.5, 0.2}};
	long n = test_scaled(200000);
	for (int k = 0; k < 2; k++) {
		sss_disk_frame f = sss_disk_frame_make(v3(0.2f, 0.1f, -0.3f), v3_normalize(v3(0.3f, 1.0f, 0.2f)));
		if (k == 1)
			memcpy(f.p, ps[1], sizeof f.p);
		CHECK(f.p[0] == ps[k][0] && f.p[1] == ps[k][1] && f.p[2] == ps[k][2], "frame's probabilities");
		enum { PHI_BINS = 16 };
		double obs[3 * PHI_BINS] = {0}, want[3 * PHI_BINS];
		long strat[3] = {0};
		rng r;
		rng_seed(&r, 71 + k, 3);
		for (long i = 0; i < n; i++) {
			double u[3] = {rng_double(&r), rng_double(&r), rng_double(&r)};
			sss_disk_probe q = sss_disk_probe_make(&p, 1.0, &f, u);
			/* phi from the probe's point on its disk */
			vec3 d = v3_sub(q.org, f.x), e1 = f.axis[(q.axis + 1) % 3], e2 = f.axis[(q.axis + 2) % 3];
			double phi = atan2(v3_dot(d, e2), v3_dot(d, e1));
			if (phi < 0.0)
				phi += 2.0 * 3.14159265358979323846;
			int b = (int)(phi / (2.0 * 3.14159265358979323846) * PHI_BINS);
			obs[q.axis * PHI_BINS + (b < PHI_BINS ? b : PHI_BINS - 1)] += 1.0;
			u[0] = (i + 0.5) / n;
			strat[sss_disk_probe_make(&p, 1.0, &f, u).axis]++;
		}
		for (int a = 0; a < 3; a++) {
			for (int b = 0; b < PHI_BINS; b++)
				want[a * PHI_BINS + b] = n * f.p[a] / PHI_BINS;
			CHECK(fabs(strat[a] - n * f.p[a]) <= 1.0, "probabilities %d: axis %d stratified %ld of %ld, want %g",
			      k, a, strat[a], n, n * f.p[a]);
		}
		double chi = 0.0;
		for (int i = 0; i < 3 * PHI_BINS; i++)
			chi += (obs[i] - want[i]) * (obs[i] - want[i]) / want[i];
		double pv = chi2_pvalue(chi, 3 * PHI_BINS - 1);
		printf("probe axis and phi, P = %.2f %.2f %.2f: chi-square %.1f (%d dof), p %.3f\n", f.p[0], f.p[1], f.p[2],
		       chi, 3 * PHI_BINS - 1, pv);
		CHECK(pv > 1e-3, "probabilities %d: axis and phi chi-square %g, p %g", k, chi, pv);
	}
}

/* A plane (a mesh and its BVH through the probe): the mean is A, with variance. g = 1 there. */
static void check_plane(void)
{
	mesh m;
	CHECK(prim_plane(v3(0, 0, 1), 0.0f, v3(-50, -50, -1), v3(50, 50, 1), &m), "prim_plane");
	bvh *b = bvh_build(m.positions, m.num_vertices, m.indices, m.num_triangles);
	sss_probe_mesh pm = {b, &m};
	sss_probe pr = sss_probe_of_mesh(&pm);
	const double grey[3] = {0.8, 0.8, 0.8}, ld[3] = {2.2853675, 2.2853675, 2.2853675};
	const double rgb[3] = {0.9, 0.6, 0.3}, ld_rgb[3] = {3.0, 1.5, 0.8};
	sss_profile profs[2] = {profile(SSS_PROFILE_GAUSSIAN, grey, ld), profile(SSS_PROFILE_BURLEY, rgb, ld_rgb)};
	const char *names[2] = {"plane gaussian grey", "plane burley rgb"};
	sss_disk_frame f = sss_disk_frame_make(v3(0.3f, -0.2f, 0.0f), v3(0, 0, 1));
	long n = test_scaled(200000);
	for (int k = 0; k < 2; k++) {
		estimate e = {0};
		rng r;
		rng_seed(&r, 3 + k, 1);
		sss_disk_hit hits[SSS_DISK_MAX_HITS];
		for (long i = 0; i < n; i++) {
			double u[3] = {rng_double(&r), rng_double(&r), rng_double(&r)};
			sss_disk_probe q = sss_disk_probe_make(&profs[k], 1.0, &f, u);
			int h = sss_disk_gather(&profs[k], 1.0, &f, &q, &pr, hits, SSS_DISK_MAX_HITS, NULL);
			e.no_hit += h == 0;
			double v[3] = {0, 0, 0};
			for (int j = 0; j < h; j++)
				for (int c = 0; c < 3; c++)
					v[c] += v3_get(hits[j].weight, c);
			test_mean3_add(&e.m, v);
		}
		const double *A = k == 0 ? grey : rgb;
		for (int c = 0; c < 3; c++) {
			double got = test_mean3_mean(&e.m, c), se = test_mean3_se(&e.m, c), sd = se * sqrt((double)e.m.n);
			printf("%-34s ch %d: A %.3f, disk %.6f +- %.6f (%+.2f SE), sample sd %.3f, no-hit %.3f\n", names[k], c,
			       A[c], got, se, (got - A[c]) / se, sd, (double)e.no_hit / e.m.n);
			CHECK(fabs(got - A[c]) <= 3.0 * se, "%s ch %d: %g +- %g, want %g", names[k], c, got, se, A[c]);
			CHECK(sd > 0.1 * A[c], "%s: no variance (sd %g): the disk is not exact on a plane", names[k], sd);
		}
	}
	bvh_free(b);
	mesh_free(&m);
}

/* The MIS density is the sum of the axes' densities; the balance weights sum to 1; zero beyond
 * r_max; the weights do not depend on the scene's unit. */
static void check_density(void)
{
	const double a[3] = {0.7, 0.5, 0.2}, ld[3] = {1.0, 0.6, 0.3};
	sss_profile p = profile(SSS_PROFILE_DIPOLE, a, ld);
	double r_max = sss_profile_r_max(&p);
	rng r;
	rng_seed(&r, 5, 2);
	for (int i = 0; i < 1000; i++) {
		vec3 n = v3_normalize(v3(rng_float(&r) - 0.5f, rng_float(&r) - 0.5f, rng_float(&r) - 0.5f));
		vec3 ny = v3_normalize(v3(rng_float(&r) - 0.5f, rng_float(&r) - 0.5f, rng_float(&r) - 0.5f));
		vec3 x = v3(rng_float(&r), rng_float(&r), rng_float(&r));
		vec3 y = v3_add(x, v3_scale(v3(rng_float(&r) - 0.5f, rng_float(&r) - 0.5f, rng_float(&r) - 0.5f),
					    (float)(1.5 * r_max)));
		sss_disk_frame f = sss_disk_frame_make(x, n);
		double pdf[3], total = sss_disk_pdf_area(&p, 1.0, &f, y, ny), wsum = 0.0;
		sss_disk_axis_pdfs(&p, 1.0, &f, y, ny, pdf);
		const double P[3] = {SSS_DISK_P_NORMAL, SSS_DISK_P_TANGENT, SSS_DISK_P_TANGENT};
		for (int k = 0; k < 3; k++)
			wsum += total > 0.0 ? P[k] * pdf[k] / total : 0.0;
		if (total > 0.0)
			CHECK_NEAR(wsum, 1.0, 1e-12);
		if (v3_length(v3_sub(y, x)) > r_max * 1.0001)
			CHECK(total == 0.0, "density %g beyond r_max", total);

		/* the same configuration in a unit 1000 times smaller: density per mm^2 unchanged */
		sss_disk_frame f2 = sss_disk_frame_make(v3_scale(x, 1000.0f), n);
		double total2 = sss_disk_pdf_area(&p, 1e-3, &f2, v3_scale(y, 1000.0f), ny);
		CHECK(fabs(total2 - total) <= 1e-3 * total, "scaled density %g, unscaled %g", total2, total);
	}
	/* a probe beyond r_max has nothing to trace */
	sss_disk_frame f = sss_disk_frame_make(v3(0, 0, 0), v3(0, 0, 1));
	sss_disk_hit hits[4];
	sss_disk_probe q = {v3(0, 0, 1), v3(0, 0, -1), 0.0f, 0, r_max};
	quadric s = {d3(0, 0, 0), 1.0, false};
	sss_probe pr = {quadric_closest, &s, NULL};
	CHECK(sss_disk_gather(&p, 1.0, &f, &q, &pr, hits, 4, NULL) == 0, "hits on an empty probe");
	vec3 w;
	float prob;
	CHECK(sss_disk_choose(hits, 0, 0.5f, &w, &prob) == -1 && w.x == 0.0f && prob == 0.0f, "choice among none");
}

static void check_curved(void)
{
	const double grey[3] = {0.8, 0.8, 0.8}, ld[3] = {2.2853675, 2.2853675, 2.2853675};
	const double rgb[3] = {0.9, 0.6, 0.3}, ld_rgb[3] = {3.0, 1.5, 0.8};
	sss_profile gp = profile(SSS_PROFILE_GAUSSIAN, grey, ld), bp = profile(SSS_PROFILE_BURLEY, rgb, ld_rgb);
	quadric sphere = {d3(0, 0, 0), 1.0, false}, cyl = {d3(0, 0, 0), 1.0, true}, thin = {d3(0, 0, 0), 0.5, true};
	sss_probe ps = {quadric_closest, &sphere}, pc = {quadric_closest, &cyl}, pt = {quadric_closest, &thin};
	sss_disk_frame fs = sss_disk_frame_make(v3(0, 0, 1), v3(0, 0, 1));
	sss_disk_frame fc = sss_disk_frame_make(v3(1, 0, 0), v3(1, 0, 0));
	sss_disk_frame ft = sss_disk_frame_make(v3(0.5f, 0, 0), v3(1, 0, 0));
	long n = test_scaled(250000);

	double want[3];
	want[0] = quadrature(&gp, 0, &sphere);
	estimate e = run(&gp, 1.0, &fs, &ps, n, -1, false, 21);
	compare("sphere R 1 gaussian, MIS", &e, want, 1);
	for (int a = 0; a < 3; a++) {
		char name[64];
		snprintf(name, sizeof name, "sphere R 1 gaussian, axis %c only", "ntb"[a]);
		e = run(&gp, 1.0, &fs, &ps, n / 2, a, false, 22 + a);
		compare(name, &e, want, 1);
	}
	e = run(&gp, 1.0, &fs, &ps, n, -1, true, 25);
	compare("sphere R 1 gaussian, one hit chosen", &e, want, 1);

	want[0] = quadrature(&gp, 0, &cyl);
	e = run(&gp, 1.0, &fc, &pc, n, -1, false, 31);
	compare("cylinder R 1 gaussian, MIS", &e, want, 1);
	for (int a = 0; a < 3; a++) {
		char name[64];
		if (fabsf(fc.axis[a].y) > 0.99f)
			continue; /* along the cylinder: never hits, and its density is zero everywhere */
		snprintf(name, sizeof name, "cylinder R 1 gaussian, axis %c only", "ntb"[a]);
		e = run(&gp, 1.0, &fc, &pc, n / 2, a, false, 32 + a);
		compare(name, &e, want, 1);
	}
	want[0] = quadrature(&gp, 0, &thin);
	e = run(&gp, 1.0, &ft, &pt, n, -1, false, 41);
	compare("cylinder R 0.5 gaussian, MIS", &e, want, 1);

	for (int c = 0; c < 3; c++)
		want[c] = quadrature(&bp, c, &sphere);
	e = run(&bp, 1.0, &fs, &ps, n, -1, false, 51);
	compare("sphere R 1 burley rgb, MIS", &e, want, 3);
}

int main(void)
{
	gauss_legendre(GL_N, gl_x, gl_w);
	for (int i = 0; i < GL_N; i++) /* nodes and weights on [0, 1] */
		gl_x[i] = 0.5 * (gl_x[i] + 1.0), gl_w[i] *= 0.5;
	check_density();
	check_probe_choice();
	check_plane();
	check_curved();
	return check_done("test_disk");
}
