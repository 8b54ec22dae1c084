/* bounds.c - what the shapes' bounds need of their descriptions alone, with no mesh: the box of
 * the shapes of shape.h (shape_bounds), the julia_fractal's sphere, a quadric's box and the
 * symmetric eigen decomposition it is read from. The language's min_extent and max_extent use
 * these (src/lang/extent.c) as the build does, so they stand apart from the tessellators. */
#include "geom/polysurf.h"
#include "geom/shape.h"

#include <math.h>
#include <string.h>

/* POV-Ray's Fractal_Tolerance (fractal.h) */
#define SHAPE_JULIA_TOLERANCE 1e-7

double shape_julia_radius(const shape_desc *s, double *exit_value)
{
	if (s->algebra == 0) {
		double r = 1 + sqrt(s->julia[0] * s->julia[0] + s->julia[1] * s->julia[1] + s->julia[2] * s->julia[2] +
				    s->julia[3] * s->julia[3]) + SHAPE_JULIA_TOLERANCE;
		r = fmin(r, 2.0);
		*exit_value = r * r + SHAPE_JULIA_TOLERANCE;
		return r;
	}
	*exit_value = 16;
	return 4;
}

void shape_bounds(const shape_desc *s, dvec3 *lo, dvec3 *hi)
{
	*lo = d3(INFINITY, INFINITY, INFINITY), *hi = d3(-INFINITY, -INFINITY, -INFINITY);
	switch (s->kind) {
	case SHAPE2_LATHE:
	case SHAPE2_SOR: /* the control points bound the curve closely enough to size the accuracy */
		for (uint32_t i = 0; i < s->n_pts; i++) {
			double r = fabs(s->pts[2 * i]), y = s->pts[2 * i + 1];
			*lo = d3(fmin(lo->x, -r), fmin(lo->y, y), fmin(lo->z, -r));
			*hi = d3(fmax(hi->x, r), fmax(hi->y, y), fmax(hi->z, r));
		}
		break;
	case SHAPE2_PRISM: {
		/* a conic sweep scales the outline by the height: its extremes are at h1 or h2 */
		double k = s->conic ? fmax(fabs(s->h1), fabs(s->h2)) : 1.0;
		for (uint32_t i = 0; i < s->n_pts; i++) {
			double x = s->pts[2 * i] * k, z = s->pts[2 * i + 1] * k;
			double xl = s->conic ? -fabs(x) : x, zl = s->conic ? -fabs(z) : z;
			*lo = d3(fmin(lo->x, xl), s->h1, fmin(lo->z, zl));
			*hi = d3(fmax(hi->x, fabs(x) * s->conic + x * !s->conic), s->h2,
				 fmax(hi->z, fabs(z) * s->conic + z * !s->conic));
		}
		break;
	}
	case SHAPE2_SPHERE_SWEEP:
		for (uint32_t i = 0; i < s->n_pts; i++) {
			const double *q = &s->pts[4 * i];
			double r = fabs(q[3]);
			*lo = d3(fmin(lo->x, q[0] - r), fmin(lo->y, q[1] - r), fmin(lo->z, q[2] - r));
			*hi = d3(fmax(hi->x, q[0] + r), fmax(hi->y, q[1] + r), fmax(hi->z, q[2] + r));
		}
		break;
	case SHAPE2_BLOB:
		for (uint32_t i = 0; i < s->n_comps; i++) {
			const shape_blob_comp *c = &s->comps[i];
			if (c->strength <= 0)
				continue;
			for (int e = 0; e < (c->cylinder ? 2 : 1); e++) {
				dvec3 p = e ? c->b : c->a;
				double r = c->radius;
				if (c->has_xf) { /* the corners of the component's box, transformed */
					for (int k = 0; k < 8; k++) {
						dvec3 q = d3(p.x + (k & 1 ? r : -r), p.y + (k & 2 ? r : -r), p.z + (k & 4 ? r : -r));
						q = xform_point(&c->xf, q);
						*lo = d3(fmin(lo->x, q.x), fmin(lo->y, q.y), fmin(lo->z, q.z));
						*hi = d3(fmax(hi->x, q.x), fmax(hi->y, q.y), fmax(hi->z, q.z));
					}
					continue;
				}
				*lo = d3(fmin(lo->x, p.x - r), fmin(lo->y, p.y - r), fmin(lo->z, p.z - r));
				*hi = d3(fmax(hi->x, p.x + r), fmax(hi->y, p.y + r), fmax(hi->z, p.z + r));
			}
		}
		break;
	case SHAPE2_BICUBIC: /* a Bezier patch lies in the hull of its control points */
		for (uint32_t i = 0; i < 16; i++) {
			const double *q = &s->pts[3 * i];
			*lo = d3(fmin(lo->x, q[0]), fmin(lo->y, q[1]), fmin(lo->z, q[2]));
			*hi = d3(fmax(hi->x, q[0]), fmax(hi->y, q[1]), fmax(hi->z, q[2]));
		}
		break;
	case SHAPE2_ISOSURFACE: /* its container */
	case SHAPE2_PARAMETRIC:
		if (s->contained_sphere) {
			dvec3 r = d3(s->sphere_r, s->sphere_r, s->sphere_r);
			*lo = d3_sub(s->box_lo, r), *hi = d3_add(s->box_lo, r);
		} else {
			*lo = s->box_lo, *hi = s->box_hi;
		}
		break;
	case SHAPE2_JULIA: {
		double ev, r = shape_julia_radius(s, &ev);
		*lo = d3(-r, -r, -r), *hi = d3(r, r, r);
		break;
	}
	case SHAPE2_TEXT: {
		size_t n = s->text ? strlen(s->text) : 0;
		double w = (double)n * (1.0 + fabs(s->offset.x));
		*lo = d3(0, -0.3 + fmin(0, (double)n * s->offset.y), fmin(0, s->depth));
		*hi = d3(fmax(w, 0.1), 1.0 + fmax(0, (double)n * s->offset.y), fmax(s->depth, 0) + fabs((double)n * s->offset.z));
		break;
	}
	}
	if (!(lo->x <= hi->x))
		*lo = *hi = d3(0, 0, 0);
}

void shape_sym3_eigen(double a[3][3], double l[3], double v[3][3])
{
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			v[i][j] = i == j;
	for (int sweep = 0; sweep < 50; sweep++) {
		double off = fabs(a[0][1]) + fabs(a[0][2]) + fabs(a[1][2]);
		if (off == 0.0)
			break;
		for (int p = 0; p < 2; p++)
			for (int q = p + 1; q < 3; q++) {
				if (a[p][q] == 0.0)
					continue;
				double th = 0.5 * (a[q][q] - a[p][p]) / a[p][q];
				double t = copysign(1.0, th) / (fabs(th) + sqrt(th * th + 1.0)), c = 1.0 / sqrt(t * t + 1.0), s = t * c;
				for (int k = 0; k < 3; k++) { /* a = J^T a J */
					double akp = a[k][p], akq = a[k][q];
					a[k][p] = c * akp - s * akq, a[k][q] = s * akp + c * akq;
				}
				for (int k = 0; k < 3; k++) {
					double apk = a[p][k], aqk = a[q][k];
					a[p][k] = c * apk - s * aqk, a[q][k] = s * apk + c * aqk;
				}
				for (int k = 0; k < 3; k++) {
					double vkp = v[k][p], vkq = v[k][q];
					v[k][p] = c * vkp - s * vkq, v[k][q] = s * vkp + c * vkq;
				}
			}
	}
	for (int i = 0; i < 3; i++)
		l[i] = a[i][i];
}

bool shape_quadric_box(const double q[10], dvec3 *lo, dvec3 *hi)
{
	double a[3][3] = {{q[0], q[3] / 2, q[4] / 2}, {q[3] / 2, q[1], q[5] / 2}, {q[4] / 2, q[5] / 2, q[2]}};
	double l[3], v[3][3], g[3] = {q[6], q[7], q[8]};
	shape_sym3_eigen(a, l, v);
	double lmax = fmax(fabs(l[0]), fmax(fabs(l[1]), fabs(l[2]))), glen = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
	*lo = d3(-INFINITY, -INFINITY, -INFINITY), *hi = d3(INFINITY, INFINITY, INFINITY);
	if (!(lmax > 0.0) || !isfinite(lmax))
		return true; /* linear: a half-space (or all or nothing) */
	/* The solid P <= 0 is bounded along some axis only where the quadratic part is positive
	 * semi-definite (an elliptic cylinder, an ellipsoid); a negative eigenvalue (a cone, a
	 * hyperboloid, the outside of a cylinder) or a linear term along a null direction (a paraboloid)
	 * leaves every axis unbounded. */
	bool null[3];
	double cl[3], k = -q[9];
	for (int i = 0; i < 3; i++) {
		double gl = v[0][i] * g[0] + v[1][i] * g[1] + v[2][i] * g[2];
		null[i] = fabs(l[i]) <= 1e-12 * lmax;
		if (!null[i] && l[i] < 0.0)
			return true;
		if (null[i] && fabs(gl) > 1e-12 * (glen + fabs(q[9]) + lmax))
			return true;
		cl[i] = null[i] ? 0.0 : -gl / (2.0 * l[i]);
		k += null[i] ? 0.0 : l[i] * cl[i] * cl[i];
	}
	if (k < 0.0)
		return false; /* (x - c)^T Q (x - c) <= k < 0: no points */
	double c[3] = {0, 0, 0};
	for (int i = 0; i < 3; i++)
		for (int r = 0; r < 3; r++)
			c[r] += v[r][i] * cl[i];
	double plo[3] = {-INFINITY, -INFINITY, -INFINITY}, phi[3] = {INFINITY, INFINITY, INFINITY};
	for (int r = 0; r < 3; r++) { /* along axis r: c_r +- sqrt(k sum_i v_ri^2 / l_i), if no null direction has a part along it */
		double s = 0.0;
		bool bounded = true;
		for (int i = 0; i < 3; i++) {
			if (null[i])
				bounded = bounded && fabs(v[r][i]) <= 1e-9;
			else
				s += v[r][i] * v[r][i] / l[i];
		}
		if (bounded)
			plo[r] = c[r] - sqrt(k * s), phi[r] = c[r] + sqrt(k * s);
	}
	*lo = d3(plo[0], plo[1], plo[2]), *hi = d3(phi[0], phi[1], phi[2]);
	return true;
}
