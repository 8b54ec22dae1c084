/* polysurf.c - POV-Ray's quadric, cubic, quartic and poly inside a box (polysurf.h): the
 * polynomial is the isosurface function f (inside where f < 0, POV-Ray's convention: Poly::Inside
 * takes a value below its tolerance as inside, Quadric::Inside a value <= 0) of a box container,
 * so the accuracy rule, the triangle limit and the measured distance are iso.c's. The grid's box
 * is the caller's grown by SHAPE_POLY_MARGIN of its size on every side: where the surface meets
 * the grid's box, marching tetrahedra cut the crease by about a cell (a cell is at most a 24th of
 * the box, iso.c's r_c / 3 with r_c an eighth), so that crease, and the box's faces, lie outside
 * the caller's box, where the CSG that bounds the surface drops them; the distance is measured
 * inside the caller's box only. */
#include "geom/polysurf.h"

#include "geom/shape.h"

#include <math.h>
#include <string.h>

uint32_t shape_poly_terms(int order)
{
	return (uint32_t)((order + 1) * (order + 2) * (order + 3) / 6);
}

double shape_poly_eval(int order, const double *c, dvec3 p)
{
	double x[SHAPE_POLY_MAX_ORDER + 1], y[SHAPE_POLY_MAX_ORDER + 1], z[SHAPE_POLY_MAX_ORDER + 1];
	x[0] = y[0] = z[0] = 1.0;
	for (int i = 1; i <= order; i++)
		x[i] = x[i - 1] * p.x, y[i] = y[i - 1] * p.y, z[i] = z[i - 1] * p.z;
	double r = 0.0;
	uint32_t t = 0;
	for (int i = order; i >= 0; i--)
		for (int j = order - i; j >= 0; j--)
			for (int k = order - i - j; k >= 0; k--, t++)
				if (c[t] != 0.0)
					r += c[t] * x[i] * y[j] * z[k];
	return r;
}

/* P at p and its gradient. */
static double poly_grad(int order, const double *c, dvec3 p, dvec3 *g)
{
	double x[SHAPE_POLY_MAX_ORDER + 1], y[SHAPE_POLY_MAX_ORDER + 1], z[SHAPE_POLY_MAX_ORDER + 1];
	x[0] = y[0] = z[0] = 1.0;
	for (int i = 1; i <= order; i++)
		x[i] = x[i - 1] * p.x, y[i] = y[i - 1] * p.y, z[i] = z[i - 1] * p.z;
	double r = 0.0, gx = 0.0, gy = 0.0, gz = 0.0;
	uint32_t t = 0;
	for (int i = order; i >= 0; i--)
		for (int j = order - i; j >= 0; j--)
			for (int k = order - i - j; k >= 0; k--, t++) {
				double ct = c[t];
				if (ct == 0.0)
					continue;
				r += ct * x[i] * y[j] * z[k];
				if (i)
					gx += ct * i * x[i - 1] * y[j] * z[k];
				if (j)
					gy += ct * j * x[i] * y[j - 1] * z[k];
				if (k)
					gz += ct * k * x[i] * y[j] * z[k - 1];
			}
	*g = d3(gx, gy, gz);
	return r;
}

void shape_quadric_poly(const double q[10], double c[10])
{
	/* order 2's terms: x^2 xy xz x y^2 yz y z^2 z 1 */
	const double v[10] = {q[0], q[3], q[4], q[6], q[1], q[5], q[7], q[2], q[8], q[9]};
	memcpy(c, v, sizeof v);
}

bool shape_poly_ball(int order, const double *c, double *radius)
{
	if (order < 2 || order % 2)
		return false;
	/* C_k: the sum of |c| over the terms of degree k (each at most rho^k on the sphere of radius rho);
	 * L: the top form's gradient on the unit sphere is at most order * C_order */
	double ck[SHAPE_POLY_MAX_ORDER + 1] = {0};
	uint32_t t = 0;
	for (int i = order; i >= 0; i--)
		for (int j = order - i; j >= 0; j--)
			for (int k = order - i - j; k >= 0; k--, t++)
				ck[i + j + k] += fabs(c[t]);
	if (!(ck[order] > 0))
		return false;
	/* The top form's least value on the unit sphere: sampled at N Fibonacci directions, less its
	 * Lipschitz bound times twice the lattice's spacing (every point of the sphere is nearer a
	 * direction than that), so a positive m is a true lower bound. */
	enum { N = 200000 };
	const double golden = M_PI * (3.0 - sqrt(5.0)), delta = 2.0 * sqrt(4.0 * M_PI / N);
	double lo = INFINITY;
	for (int q = 0; q < N; q++) {
		double z = 1.0 - (2.0 * q + 1.0) / N, r = sqrt(fmax(0.0, 1.0 - z * z)), ph = golden * q;
		dvec3 u = d3(r * cos(ph), r * sin(ph), z);
		double x[SHAPE_POLY_MAX_ORDER + 1], y[SHAPE_POLY_MAX_ORDER + 1], w[SHAPE_POLY_MAX_ORDER + 1], h = 0.0;
		x[0] = y[0] = w[0] = 1.0;
		for (int i = 1; i <= order; i++)
			x[i] = x[i - 1] * u.x, y[i] = y[i - 1] * u.y, w[i] = w[i - 1] * u.z;
		t = 0;
		for (int i = order; i >= 0; i--)
			for (int j = order - i; j >= 0; j--)
				for (int k = order - i - j; k >= 0; k--, t++)
					if (i + j + k == order && c[t] != 0.0)
						h += c[t] * x[i] * y[j] * w[k];
		lo = fmin(lo, h);
	}
		double m = lo - order * ck[order] * delta;
	if (!(m > 0))
		return false;
	/* P >= m rho^n - sum_{k<n} C_k rho^k on the sphere of radius rho: positive past the one
	 * positive root of the right side (one sign change), found by doubling and bisection. */
	double hi = 1.0;
	for (int it = 0; it < 200; it++) {
		double f = m * pow(hi, order);
		for (int k = 0; k < order; k++)
			f -= ck[k] * pow(hi, k);
		if (f > 0)
			break;
		hi *= 2;
	}
	double a = 0.0;
	for (int it = 0; it < 100; it++) {
		double mid = 0.5 * (a + hi), f = m * pow(mid, order);
		for (int k = 0; k < order; k++)
			f -= ck[k] * pow(mid, k);
		if (f > 0)
			hi = mid;
		else
			a = mid;
	}
	*radius = hi;
	return isfinite(hi);
}

typedef struct poly_ctx {
	int order;
	const double *c;
} poly_ctx;

/* P / |grad P|: the distance to the surface to first order, so that the field iso.c takes the
 * minimum of with the distance into the box compares lengths with lengths (P itself may be
 * thousands where the box's distance is one: the minimum would then pick the box inside the solid,
 * and the measured distance would be the box's). Where the gradient vanishes (a cone's apex, a
 * double surface) P alone. */
static bool poly_fn(const void *ctx, const double xyz[3], double *out)
{
	const poly_ctx *pc = ctx;
	dvec3 g;
	double v = poly_grad(pc->order, pc->c, d3(xyz[0], xyz[1], xyz[2]), &g), gl = d3_length(g);
	*out = gl > 0.0 && isfinite(v / gl) ? v / gl : v;
	return true;
}

bool shape_poly_surface(int order, const double *c, dvec3 lo, dvec3 hi, double max_error, mesh *out, double *err,
			const char *what, diag *d, diag_loc loc)
{
	memset(out, 0, sizeof *out);
	poly_ctx pc = {order, c};
	dvec3 ext = d3_sub(hi, lo);
	double m = SHAPE_POLY_MARGIN * fmax(ext.x, fmax(ext.y, ext.z));
	shape_desc s = {.kind = SHAPE2_ISOSURFACE, .fn = poly_fn, .fn_ctx = &pc, .fn_name = what, .threshold = 0.0,
			.box_lo = d3_sub(lo, d3(m, m, m)), .box_hi = d3_add(hi, d3(m, m, m)),
			.has_region = true, .region_lo = lo, .region_hi = hi, .max_passes = 3};
	shape_accuracy acc = {.tol = max_error, .segments = 3};
	return shape_isosurface_named(&s, &acc, what, out, err, d, loc);
}
