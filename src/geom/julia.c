/* julia.c - POV-Ray's julia_fractal as a mesh: its inside set (core/shape/fractal.cpp,
 * core/math/quaternion.cpp, hypercomplex.cpp: q <- f(q) + c from the point on the 4-D slice,
 * inside while |q|^2 stays within the exit value for max_iteration steps) sampled on a grid of
 * POV-Ray's bounding cube (then again, finer, in the bound of what that grid found) and
 * polygonised by field.c, each vertex found on its grid edge by
 * bisection of the inside test; normals the mesh's own (area-weighted face normals), since the
 * inside test has no gradient. The set's detail finer than a grid cell is not resolved: the cell
 * is the accuracy reported. */
#include "geom/shape.h"

#include "base/mem.h"

#include <math.h>
#include <string.h>

/* The most grid points a fractal may sample. */
#define JULIA_MAX_GRID_POINTS (1u << 21)


static bool julia_inside(const shape_desc *s, double ev, dvec3 p)
{
	double x = p.x, y = p.y, z = p.z;
	double w = (s->slice_dist - s->slice[0] * x - s->slice[1] * y - s->slice[2] * z) / s->slice[3];
	const double *c = s->julia;
	for (int i = 1; i <= s->max_iteration; i++) {
		if (s->algebra == 0) { /* quaternion */
			double d = y * y + z * z + w * w, x2 = x * x;
			if (d + x2 > ev)
				return false;
			if (s->jfunc == 0) { /* q^2 */
				double x2r = 2 * x;
				y = x2r * y + c[1], z = x2r * z + c[2], w = x2r * w + c[3];
				x = x2 - d + c[0];
			} else { /* q^3 */
				double t = 3 * x2 - d;
				x = x * (x2 - 3 * d) + c[0];
				y = y * t + c[1], z = z * t + c[2], w = w * t + c[3];
			}
		} else { /* hypercomplex: commutative, x' = xa - yb - zc + wd ... (POV-Ray's sqr) */
			if (x * x + y * y + z * z + w * w > ev)
				return false;
			double a = x, b = y, cc = z, dd = w;
			if (s->jfunc == 1) { /* q^2 first, then times q */
				a = x * x - y * y - z * z + w * w, b = 2 * (x * y - z * w), cc = 2 * (x * z - w * y),
				dd = 2 * (x * w + y * z);
			}
			double nx = x * a - y * b - z * cc + w * dd, ny = x * b + y * a - z * dd - w * cc;
			double nz = x * cc + z * a - y * dd - w * b, nw = x * dd + w * a + y * cc + z * b;
			x = nx + c[0], y = ny + c[1], z = nz + c[2], w = nw + c[3];
		}
	}
	return true;
}

typedef struct jctx {
	const shape_desc *s;
	double ev;
} jctx;

static double julia_eval(const void *ctx, dvec3 p, dvec3 *g)
{
	const jctx *c = ctx;
	if (g)
		*g = d3(0, 0, 0);
	return julia_inside(c->s, c->ev, p) ? 1.0 : -1.0;
}

bool shape_julia(const shape_desc *s, const shape_accuracy *acc, mesh *out, double *tol_out, diag *d, diag_loc loc)
{
	jctx c = {.s = s};
	double r = shape_julia_radius(s, &c.ev);
	dvec3 lo = d3(-r, -r, -r), hi = d3(r, r, r);
	/* a fractal has no curvature to size its cells by: cells of twice the tolerance, as many as
	 * the grid allows */
	double h = 2 * acc->tol;
	shape_field F = {.eval = julia_eval, .ctx = &c, .on_edges = true, .shift = 0.6180339887};
	shape_builder b;
	double want = h;
	h = shape_field_fit_step(d3_sub(hi, lo), want, JULIA_MAX_GRID_POINTS);
	if (!shape_field_polygonise(&F, lo, hi, h, "julia_fractal", &b, d, loc))
		return false;
	if (!b.failed && b.nv && h > want) {
		/* the set is often much smaller than POV-Ray's bounding cube (hypercomplex: 4): once more
		 * inside the bound of what the coarse grid found, two cells around it */
		vec3 l3 = b.pos[0], h3 = b.pos[0];
		for (uint32_t i = 1; i < b.nv; i++)
			l3 = v3_min(l3, b.pos[i]), h3 = v3_max(h3, b.pos[i]);
		dvec3 pad = d3(2 * h, 2 * h, 2 * h);
		dvec3 lo2 = d3_sub(v3_to_d3(l3), pad), hi2 = d3_add(v3_to_d3(h3), pad);
		double h2 = shape_field_fit_step(d3_sub(hi2, lo2), want, JULIA_MAX_GRID_POINTS);
		if (h2 < 0.8 * h) {
			sb_free(&b);
			h = h2;
			if (!shape_field_polygonise(&F, lo2, hi2, h, "julia_fractal", &b, d, loc))
				return false;
		}
	}
	if (!b.failed) { /* the normals: area-weighted face normals at each vertex */
		dvec3 *n = mem_calloc(b.nv ? b.nv : 1, sizeof *n);
		if (!n)
			b.failed = true;
		for (uint32_t t = 0; t < b.nt && n; t++) {
			const uint32_t *i = &b.idx[3 * (size_t)t];
			dvec3 p0 = v3_to_d3(b.pos[i[0]]), p1 = v3_to_d3(b.pos[i[1]]), p2 = v3_to_d3(b.pos[i[2]]);
			dvec3 fn = d3_cross(d3_sub(p1, p0), d3_sub(p2, p0));
			for (int k = 0; k < 3; k++)
				n[i[k]] = d3_add(n[i[k]], fn);
		}
		for (uint32_t v = 0; v < b.nv && n; v++) {
			double l = d3_length(n[v]);
			b.nrm[v] = l > 0 ? d3_to_v3(d3_scale(n[v], 1 / l)) : v3(0, 1, 0);
		}
		mem_free(n);
	}
	*tol_out = fmax(acc->tol, h); /* the set's detail within a cell is not resolved */
	return sb_finish(&b, out, false, "julia_fractal", d, loc);
}
