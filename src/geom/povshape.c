/* povshape.c - tessellation of cone, torus, disc, polygon, superellipsoid, height field and the
 * quadric ellipsoid (povshape.h). Parametric shapes lay out a (columns + 1) x (rows + 1) vertex grid,
 * the seam duplicated for UVs; closedness is that of positions. */
#include "geom/povshape.h"
#include "geom/polysurf.h"

#include "base/mem.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

uint32_t shape_circle_segments(double radius, const shape_accuracy *a)
{
	double n = SHAPE_MIN_SEGMENTS;
	if (radius > 0.0 && a->max_error > 0.0 && a->max_error < radius)
		n = fmax(n, ceil(M_PI / acos(1.0 - a->max_error / radius)));
	if (radius > 0.0 && a->max_edge > 0.0)
		n = fmax(n, ceil(2.0 * M_PI * radius / a->max_edge));
	return n > SHAPE_MAX_SEGMENTS ? SHAPE_MAX_SEGMENTS : (uint32_t)n;
}

double shape_circle_error(double radius, uint32_t n) { return radius * (1.0 - cos(M_PI / n)); }

/* Refuses, at loc, a mesh over the shape's triangle limit (before anything is allocated). */
static bool within_limit(size_t triangles, const shape_accuracy *a, const char *what, diag *d, diag_loc loc)
{
	if (triangles <= a->max_triangles)
		return true;
	diag_error(d, loc, "the %s would need %zu triangles, over the limit of %u a shape may make", what, triangles,
		   a->max_triangles);
	return false;
}

static bool alloc_mesh(mesh *out, size_t nv, size_t nt, bool normals, diag *d, diag_loc loc)
{
	if (mesh_alloc(out, nv, nt, normals, true, false))
		return true;
	diag_error(d, loc, "out of memory while tessellating");
	return false;
}

/* An orthonormal frame (e1, e2) with e1 x e2 = n, n unit. */
static void frame(dvec3 n, dvec3 *e1, dvec3 *e2)
{
	dvec3 t = fabs(n.x) < 0.9 ? d3(1, 0, 0) : d3(0, 1, 0);
	*e1 = d3_normalize(d3_cross(t, n));
	*e2 = d3_cross(n, *e1);
}

static vec3 v3d(dvec3 v) { return d3_to_v3(v); }

/* Fills vertex v. */
static void put(mesh *m, uint32_t v, dvec3 p, dvec3 n, double u, double w)
{
	m->positions[v] = v3d(p);
	if (m->normals)
		m->normals[v] = v3d(n);
	m->uvs[v] = v2((float)u, (float)w);
}

static uint32_t *tri(uint32_t *ix, uint32_t a, uint32_t b, uint32_t c)
{
	ix[0] = a, ix[1] = b, ix[2] = c;
	return ix + 3;
}

/* ---- cone and cylinder --------------------------------------------------------------------- */

/* An end disc of radius r at c facing n (about the axis frame e1, e2): a fan whose rim vertices
 * start at first (nseg + 1 of them, the last the seam). Returns the next free vertex. */
static uint32_t cone_cap(mesh *m, uint32_t v, uint32_t **ix, dvec3 c, double r, dvec3 e1, dvec3 e2, dvec3 n,
			 bool facing_axis, uint32_t nseg)
{
	uint32_t centre = v++;
	put(m, centre, c, n, 0.5, 0.5);
	for (uint32_t j = 0; j <= nseg; j++) {
		double ph = 2.0 * M_PI * (j % nseg) / nseg, cs = cos(ph), sn = sin(ph);
		put(m, v + j, d3_add(c, d3_add(d3_scale(e1, r * cs), d3_scale(e2, r * sn))), n, 0.5 + 0.5 * cs,
		    0.5 + 0.5 * sn);
	}
	for (uint32_t j = 0; j < nseg; j++)
		*ix = facing_axis ? tri(*ix, centre, v + j, v + j + 1) : tri(*ix, centre, v + j + 1, v + j);
	return v + nseg + 1;
}

bool shape_cone(dvec3 base, double rb, dvec3 cap, double rc, bool open, const shape_accuracy *a, mesh *out,
		double *err, diag *d, diag_loc loc)
{
	memset(out, 0, sizeof *out);
	dvec3 axis = d3_sub(cap, base);
	double len = d3_length(axis);
	if (!(len > 0.0) || !(rb >= 0.0) || !(rc >= 0.0) || !(rb > 0.0 || rc > 0.0)) {
		diag_error(d, loc, "a cone needs distinct end points and radii >= 0, not both 0");
		return false;
	}
	axis = d3_scale(axis, 1.0 / len);
	uint32_t nseg = shape_circle_segments(fmax(rb, rc), a);
	bool cap_b = !open && rb > 0.0, cap_c = !open && rc > 0.0;
	size_t side_tris = (size_t)nseg * ((rb > 0.0) + (rc > 0.0));
	size_t nt = side_tris + (size_t)nseg * (cap_b + cap_c);
	size_t nv = 2 * ((size_t)nseg + 1) + (size_t)(cap_b + cap_c) * (nseg + 2);
	if (!within_limit(nt, a, "cone", d, loc) || !alloc_mesh(out, nv, nt, true, d, loc))
		return false;
	dvec3 e1, e2;
	frame(axis, &e1, &e2);
	uint32_t *ix = out->indices, row = nseg + 1;
	for (uint32_t j = 0; j <= nseg; j++) {
		/* Segment j's apex vertex takes the normal at the middle of the segment: a point has none. */
		double ph = 2.0 * M_PI * (j % nseg) / nseg, phm = 2.0 * M_PI * (j + 0.5) / nseg;
		dvec3 radial = d3_add(d3_scale(e1, cos(ph)), d3_scale(e2, sin(ph)));
		dvec3 mid = d3_add(d3_scale(e1, cos(phm)), d3_scale(e2, sin(phm)));
		/* The side's normal: tangent along the axis is axis len + (rc - rb) radial. */
		dvec3 n = d3_normalize(d3_add(d3_scale(radial, len), d3_scale(axis, rb - rc)));
		dvec3 nm = d3_normalize(d3_add(d3_scale(mid, len), d3_scale(axis, rb - rc)));
		put(out, j, d3_add(base, d3_scale(radial, rb)), rb > 0.0 ? n : nm, (double)j / nseg, 0.0);
		put(out, row + j, d3_add(cap, d3_scale(radial, rc)), rc > 0.0 ? n : nm, (double)j / nseg, 1.0);
	}
	for (uint32_t j = 0; j < nseg; j++) {
		if (rb > 0.0)
			ix = tri(ix, j, j + 1, row + j + 1);
		if (rc > 0.0)
			ix = tri(ix, j, row + j + 1, row + j);
	}
	uint32_t v = 2 * row;
	if (cap_b)
		v = cone_cap(out, v, &ix, base, rb, e1, e2, d3_scale(axis, -1.0), false, nseg);
	if (cap_c)
		v = cone_cap(out, v, &ix, cap, rc, e1, e2, axis, true, nseg);
	*err = shape_circle_error(fmax(rb, rc), nseg);
	return true;
}

/* ---- torus ----------------------------------------------------------------------------------- */

/* Triangles of a (cols x rows) grid of quads over vertices (cols + 1) per row, vertex (i, k) at
 * k (cols + 1) + i, for grids whose d/di x d/dk points outward; a quad whose row k is a pole
 * (pole_lo: row 0, pole_hi: row `rows`) loses its triangle of zero area. */
static uint32_t *grid_tris(uint32_t *ix, uint32_t cols, uint32_t rows, bool pole_lo, bool pole_hi)
{
	for (uint32_t k = 0; k < rows; k++)
		for (uint32_t i = 0; i < cols; i++) {
			uint32_t a = k * (cols + 1) + i, b = a + 1, c = a + cols + 1, e = c + 1;
			if (!(pole_lo && k == 0))
				ix = tri(ix, a, b, e);
			if (!(pole_hi && k + 1 == rows))
				ix = tri(ix, a, e, c);
		}
	return ix;
}

bool shape_torus(double major, double minor, const shape_accuracy *a, mesh *out, double *err, diag *d,
		 diag_loc loc)
{
	memset(out, 0, sizeof *out);
	if (!(minor > 0.0) || !(major >= minor)) {
		diag_error(d, loc, "a torus needs radii 0 < minor <= major");
		return false;
	}
	/* Half the error to each circle: a quad's triangles lie within the sum of their sagittas. */
	shape_accuracy half = *a;
	half.max_error = 0.5 * a->max_error;
	uint32_t n = shape_circle_segments(major + minor, &half), m = shape_circle_segments(minor, &half);
	size_t nt = 2 * (size_t)n * m, nv = ((size_t)n + 1) * (m + 1);
	if (!within_limit(nt, a, "torus", d, loc) || !alloc_mesh(out, nv, nt, true, d, loc))
		return false;
	for (uint32_t k = 0; k <= m; k++) {
		double th = -M_PI + 2.0 * M_PI * (k % m) / m;
		for (uint32_t i = 0; i <= n; i++) {
			/* Columns run with POV-Ray's u, so that phi = atan2(z, x) decreases along them. */
			double ph = M_PI - 2.0 * M_PI * (i % n) / n, rho = major + minor * cos(th);
			dvec3 nrm = d3(cos(th) * cos(ph), sin(th), cos(th) * sin(ph));
			put(out, k * (n + 1) + i, d3(rho * cos(ph), minor * sin(th), rho * sin(ph)), nrm, (double)i / n,
			    (double)k / m);
		}
	}
	grid_tris(out->indices, n, m, false, false);
	*err = shape_circle_error(major + minor, n) + shape_circle_error(minor, m);
	return true;
}

/* ---- disc ------------------------------------------------------------------------------------ */

bool shape_disc(dvec3 centre, dvec3 normal, double radius, double hole, const shape_accuracy *a, mesh *out,
		double *err, diag *d, diag_loc loc)
{
	memset(out, 0, sizeof *out);
	double nl = d3_length(normal);
	if (!(nl > 0.0) || !(radius > 0.0) || !(hole >= 0.0) || !(hole < radius)) {
		diag_error(d, loc, "a disc needs a normal, a radius > 0 and a hole in [0, radius)");
		return false;
	}
	dvec3 n = d3_scale(normal, 1.0 / nl), e1, e2;
	frame(n, &e1, &e2);
	uint32_t nseg = shape_circle_segments(radius, a);
	bool ring = hole > 0.0;
	size_t nt = (size_t)nseg * (ring ? 2 : 1), nv = 2 * ((size_t)nseg + 1);
	if (!within_limit(nt, a, "disc", d, loc) || !alloc_mesh(out, nv, nt, true, d, loc))
		return false;
	/* Inner row (the hole's rim, or the centre repeated) then the outer rim. */
	for (uint32_t j = 0; j <= nseg; j++) {
		double ph = 2.0 * M_PI * (j % nseg) / nseg, cs = cos(ph), sn = sin(ph);
		dvec3 radial = d3_add(d3_scale(e1, cs), d3_scale(e2, sn));
		double f = hole / radius;
		put(out, j, d3_add(centre, d3_scale(radial, hole)), n, 0.5 + 0.5 * f * cs, 0.5 + 0.5 * f * sn);
		put(out, nseg + 1 + j, d3_add(centre, d3_scale(radial, radius)), n, 0.5 + 0.5 * cs, 0.5 + 0.5 * sn);
	}
	uint32_t *ix = out->indices, o = nseg + 1;
	for (uint32_t j = 0; j < nseg; j++) {
		ix = tri(ix, j, o + j, o + j + 1);
		if (ring)
			ix = tri(ix, j, o + j + 1, j + 1);
	}
	*err = shape_circle_error(radius, nseg);
	return true;
}

/* ---- superellipsoid ------------------------------------------------------------------------- */

/* |x|^e with x in [-1, 1], the sign kept (Barr's signed power); cosines of multiples of pi / 2
 * within rounding of 0 are 0, so poles and axes are exact. */
static double spow(double x, double e)
{
	if (fabs(x) < 1e-15)
		return e > 0.0 ? 0.0 : copysign(INFINITY, x);
	return copysign(pow(fabs(x), e), x);
}

/* POV-Ray's Superellipsoid::evaluate_g: (x^p + y^p)^(1/p) for x, y >= 0, without overflow. */
static double p_norm(double x, double y, double p)
{
	if (x > y)
		return x * pow(1.0 + pow(y / x, p), 1.0 / p);
	if (y > 0.0)
		return y * pow(1.0 + pow(x / y, p), 1.0 / p);
	return 0.0;
}

double shape_superellipsoid_norm(double e, double n, dvec3 p)
{
	return p_norm(p_norm(fabs(p.x), fabs(p.y), 2.0 / e), fabs(p.z), 2.0 / n);
}

/* The normal direction at (lon u, lat v): the gradient, C_v^(2-n) C_u^(2-e), C_v^(2-n) S_u^(2-e),
 * S_v^(2-n) in signed powers. Where a power of 0 is infinite (an exponent over 2 makes a cusp
 * there), the direction from the centre: a cusp's outward bisector. */
static dvec3 super_normal(double e, double n, double cu, double su, double cv, double sv, dvec3 p)
{
	dvec3 r = d3(spow(cv, 2.0 - n) * spow(cu, 2.0 - e), spow(cv, 2.0 - n) * spow(su, 2.0 - e), spow(sv, 2.0 - n));
	double l = d3_length(r);
	if (!(l > 0.0) || !isfinite(l))
		r = p, l = d3_length(p);
	return d3_scale(r, 1.0 / l);
}

/* cos and sin of k pi / (2 q), exact at multiples of pi / 2. */
static void quarter_cs(uint32_t k, uint32_t q, double *c, double *s)
{
	if (k % q == 0) {
		static const double cs[4] = {1, 0, -1, 0}, sn[4] = {0, 1, 0, -1};
		*c = cs[(k / q) % 4], *s = sn[(k / q) % 4];
		return;
	}
	double a = M_PI * k / (2.0 * q);
	*c = cos(a), *s = sin(a);
}

/* The superellipsoid's grid of cols x rows (cols a multiple of 4, rows even). */
static void super_grid(double e, double n, uint32_t cols, uint32_t rows, mesh *m)
{
	for (uint32_t k = 0; k <= rows; k++) {
		double c, s, cv, sv; /* latitude -pi/2 + k pi / rows: cos = sin(k pi / rows), sin = -cos(...) */
		quarter_cs(k, rows / 2, &c, &s);
		cv = s, sv = -c;
		for (uint32_t i = 0; i <= cols; i++) {
			double cu, su; /* longitude -pi + 2 pi i / cols */
			quarter_cs(i % cols, cols / 4, &cu, &su);
			cu = -cu, su = -su;
			/* + 0.0 makes -0 +0: the pole's vertices are then one point, bit for bit. */
			dvec3 p = d3(spow(cv, n) * spow(cu, e) + 0.0, spow(cv, n) * spow(su, e) + 0.0, spow(sv, n) + 0.0);
			put(m, k * (cols + 1) + i, p, super_normal(e, n, cu, su, cv, sv, p), (double)i / cols, (double)k / rows);
		}
	}
}

/* The largest radial distance from the surface of the triangles' centroids and edge midpoints. */
static double super_error(double e, double n, const mesh *m)
{
	double worst = 0.0;
	static const double w[4][3] = {{1 / 3.0, 1 / 3.0, 1 / 3.0}, {0.5, 0.5, 0}, {0, 0.5, 0.5}, {0.5, 0, 0.5}};
	for (uint32_t t = 0; t < m->num_triangles; t++) {
		dvec3 c[3];
		for (int k = 0; k < 3; k++)
			c[k] = v3_to_d3(m->positions[m->indices[3 * t + k]]);
		for (int s = 0; s < 4; s++) {
			dvec3 p = d3_add(d3_add(d3_scale(c[0], w[s][0]), d3_scale(c[1], w[s][1])), d3_scale(c[2], w[s][2]));
			double nrm = shape_superellipsoid_norm(e, n, p);
			if (nrm > 0.0)
				worst = fmax(worst, d3_length(p) * fabs(1.0 - 1.0 / nrm));
		}
	}
	return worst;
}

bool shape_superellipsoid(double e, double n, const shape_accuracy *a, mesh *out, double *err, diag *d,
			  diag_loc loc)
{
	memset(out, 0, sizeof *out);
	if (!(e > 0.0) || !(n > 0.0) || !isfinite(e) || !isfinite(n)) {
		diag_error(d, loc, "a superellipsoid needs exponents > 0");
		return false;
	}
	/* From the segments a sphere of radius 1 (its equator) needs, a multiple of 4 (the axes on the
	 * grid), doubled while the measured error is over the bound. */
	uint32_t start = (shape_circle_segments(1.0, a) + 3) / 4 * 4;
	for (uint32_t cols = start;; cols *= 2) {
		uint32_t rows = cols / 2;
		size_t nt = 2 * (size_t)cols * (rows - 1), nv = ((size_t)cols + 1) * (rows + 1);
		if (!within_limit(nt, a, "superellipsoid", d, loc) || !alloc_mesh(out, nv, nt, true, d, loc))
			return false;
		super_grid(e, n, cols, rows, out);
		grid_tris(out->indices, cols, rows, true, true);
		*err = super_error(e, n, out);
		if (*err <= a->max_error || cols >= SHAPE_MAX_SEGMENTS || 4 * nt > a->max_triangles)
			return true;
		mesh_free(out);
	}
}

/* ---- polygon --------------------------------------------------------------------------------- */

typedef struct edge2 {
	double x0, y0, x1, y1; /* y0 < y1 */
} edge2;

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return x < y ? -1 : x > y;
}

static double edge_x(const edge2 *e, double y)
{
	if (y <= e->y0)
		return e->x0;
	if (y >= e->y1)
		return e->x1;
	return e->x0 + (e->x1 - e->x0) * (y - e->y0) / (e->y1 - e->y0);
}

/* The y where edges a and b cross strictly inside both, or NAN. */
static double crossing_y(const edge2 *a, const edge2 *b)
{
	double dax = a->x1 - a->x0, day = a->y1 - a->y0, dbx = b->x1 - b->x0, dby = b->y1 - b->y0;
	double den = dax * dby - day * dbx;
	if (den == 0.0)
		return NAN;
	double ex = b->x0 - a->x0, ey = b->y0 - a->y0;
	double s = (ex * dby - ey * dbx) / den, t = (ex * day - ey * dax) / den;
	return s > 0.0 && s < 1.0 && t > 0.0 && t < 1.0 ? a->y0 + s * day : NAN;
}

typedef struct slab_x {
	double lo, hi, mid;
} slab_x;

static int cmp_slab_x(const void *a, const void *b)
{
	return cmp_double(&((const slab_x *)a)->mid, &((const slab_x *)b)->mid);
}

/* The even-odd fill of the edges as trapezoids between consecutive ys: counts the triangles, and
 * writes them (2-D, counter-clockwise, 6 doubles each) when out is not NULL. */
static size_t fill_slabs(const edge2 *e, size_t ne, const double *ys, size_t nys, slab_x *xs, double *out)
{
	size_t count = 0;
	for (size_t s = 0; s + 1 < nys; s++) {
		double ya = ys[s], yb = ys[s + 1], ym = 0.5 * (ya + yb);
		size_t na = 0;
		for (size_t i = 0; i < ne; i++)
			if (e[i].y0 <= ya && e[i].y1 >= yb)
				xs[na++] = (slab_x){edge_x(&e[i], ya), edge_x(&e[i], yb), edge_x(&e[i], ym)};
		qsort(xs, na, sizeof *xs, cmp_slab_x);
		for (size_t k = 0; k + 1 < na; k += 2) {
			const slab_x *l = &xs[k], *r = &xs[k + 1];
			const double q[2][6] = {{l->lo, ya, r->lo, ya, r->hi, yb}, {l->lo, ya, r->hi, yb, l->hi, yb}};
			for (int t = 0; t < 2; t++) {
				if (t == 0 ? !(r->lo > l->lo) : !(r->hi > l->hi))
					continue;
				if (out)
					memcpy(out + 6 * count, q[t], sizeof q[t]);
				count++;
			}
		}
	}
	return count;
}

/* The polygon's edges in its plane (frame e1, e2 about origin o), subpolygons as POV-Ray's; edges
 * of zero length and horizontal ones (they bound no trapezoid) are left out. */
static size_t polygon_edges(const dvec3 *p, uint32_t n, dvec3 o, dvec3 e1, dvec3 e2, edge2 *out)
{
	size_t ne = 0;
	uint32_t start = 0;
	for (uint32_t j = 1; j < n; j++) {
		dvec3 a = d3_sub(p[j - 1], o), b = d3_sub(p[j], o);
		double ax = d3_dot(a, e1), ay = d3_dot(a, e2), bx = d3_dot(b, e1), by = d3_dot(b, e2);
		if (ay != by)
			out[ne++] = ay < by ? (edge2){ax, ay, bx, by} : (edge2){bx, by, ax, ay};
		if (p[j].x == p[start].x && p[j].y == p[start].y && p[j].z == p[start].z && j > start)
			start = ++j;
	}
	return ne;
}

/* Newell's normal of the polygon's outline (every consecutive pair, as the subpolygons chain). */
static dvec3 newell(const dvec3 *p, uint32_t n)
{
	dvec3 s = d3(0, 0, 0);
	uint32_t start = 0;
	for (uint32_t j = 1; j < n; j++) {
		dvec3 a = p[j - 1], b = p[j];
		s = d3_add(s, d3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y)));
		if (p[j].x == p[start].x && p[j].y == p[start].y && p[j].z == p[start].z && j > start)
			start = ++j;
	}
	return s;
}

/* The polygon's plane: its unit normal and the largest extent of its points; false when the
 * points are collinear or off one plane (warned at loc: POV-Ray ignores such a polygon). */
static bool polygon_plane(const dvec3 *p, uint32_t n, dvec3 *normal, diag *d, diag_loc loc)
{
	dvec3 lo = p[0], hi = p[0];
	for (uint32_t i = 1; i < n; i++)
		lo = d3(fmin(lo.x, p[i].x), fmin(lo.y, p[i].y), fmin(lo.z, p[i].z)),
		hi = d3(fmax(hi.x, p[i].x), fmax(hi.y, p[i].y), fmax(hi.z, p[i].z));
	double size = d3_length(d3_sub(hi, lo));
	dvec3 nn = newell(p, n);
	double len = d3_length(nn);
	/* Relative to the square of the size: Newell's sum is twice an area. */
	if (!(len > 1e-12 * size * size) || !isfinite(len)) {
		diag_warning(d, loc, "the polygon's points are collinear: it is ignored, as POV-Ray does");
		return false;
	}
	*normal = d3_scale(nn, 1.0 / len);
	for (uint32_t i = 1; i < n; i++)
		if (fabs(d3_dot(*normal, d3_sub(p[i], p[0]))) > 1e-6 * size) {
			diag_warning(d, loc, "the polygon's point %u is off the plane of the others: it is ignored, as POV-Ray does",
				     i + 1);
			return false;
		}
	return true;
}

/* The ys between which the edges neither cross nor end, sorted, each once: every end point and
 * every crossing (pair by pair). False when memory runs out. */
static bool polygon_ys(const edge2 *e, size_t ne, vecbuf *ys)
{
	for (size_t i = 0; i < ne; i++) {
		if (!vecbuf_push(ys, &e[i].y0) || !vecbuf_push(ys, &e[i].y1))
			return false;
		for (size_t j = i + 1; j < ne; j++) {
			double y = crossing_y(&e[i], &e[j]);
			if (!isnan(y) && !vecbuf_push(ys, &y))
				return false;
		}
	}
	double *v = ys->data;
	qsort(v, ys->len, sizeof *v, cmp_double);
	size_t u = 0;
	for (size_t i = 0; i < ys->len; i++)
		if (!u || v[i] != v[u - 1])
			v[u++] = v[i];
	ys->len = u;
	return true;
}

bool shape_polygon(const dvec3 *p, uint32_t n, const shape_accuracy *a, mesh *out, diag *d, diag_loc loc)
{
	memset(out, 0, sizeof *out);
	if (n < 3 || n > SHAPE_POLYGON_MAX_POINTS) {
		diag_error(d, loc, "a polygon needs 3 to %u points, found %u", SHAPE_POLYGON_MAX_POINTS, n);
		return false;
	}
	dvec3 nrm, e1, e2;
	if (!polygon_plane(p, n, &nrm, d, loc))
		return true; /* ignored: an empty mesh */
	frame(nrm, &e1, &e2);
	edge2 *e = mem_alloc(n, sizeof *e);
	slab_x *xs = mem_alloc(n, sizeof *xs);
	double *tris = NULL;
	vecbuf yb;
	vecbuf_init(&yb, sizeof(double));
	bool ok = e && xs;
	size_t ne = ok ? polygon_edges(p, n, p[0], e1, e2, e) : 0;
	bool oom = !ok || !polygon_ys(e, ne, &yb);
	ok = ok && !oom;
	const double *ys = yb.data;
	size_t nys = yb.len;
	size_t nt = ok ? fill_slabs(e, ne, ys, nys, xs, NULL) : 0;
	ok = ok && within_limit(nt, a, "polygon", d, loc);
	if (ok && nt) {
		ok = (tris = mem_alloc(6 * nt, sizeof *tris)) && alloc_mesh(out, 3 * nt, nt, true, d, loc);
		if (ok) {
			fill_slabs(e, ne, ys, nys, xs, tris);
			for (size_t t = 0; t < 3 * nt; t++) {
				double x = tris[2 * t], y = tris[2 * t + 1];
				put(out, (uint32_t)t, d3_add(p[0], d3_add(d3_scale(e1, x), d3_scale(e2, y))), nrm, x, y);
				out->indices[t] = (uint32_t)t;
			}
		}
	}
	if (oom || (nt && !tris))
		diag_error(d, loc, "out of memory while tessellating");
	mem_free(e), mem_free(xs), mem_free(tris);
	vecbuf_free(&yb);
	return ok;
}

/* ---- height field ------------------------------------------------------------------------------ */

/* Vertex (x, z) of the field's grid. */
static dvec3 hf_point(const float *h, uint32_t w, uint32_t hh, uint32_t x, uint32_t z)
{
	return d3((double)x / (w - 1), h[(size_t)z * w + x], (double)z / (hh - 1));
}

/* POV-Ray's smooth_height_field: the sum of the cross products toward the four neighbours. */
static dvec3 hf_normal(const float *h, uint32_t w, uint32_t hh, uint32_t x, uint32_t z)
{
	static const int nb[4][4] = {{1, 0, 0, 1}, {0, 1, -1, 0}, {-1, 0, 0, -1}, {0, -1, 1, 0}};
	dvec3 c = hf_point(h, w, hh, x, z), s = d3(0, 0, 0);
	for (int k = 0; k < 4; k++) {
		long ax = (long)x + nb[k][0], az = (long)z + nb[k][1], bx = (long)x + nb[k][2], bz = (long)z + nb[k][3];
		if (ax < 0 || az < 0 || bx < 0 || bz < 0 || ax >= w || bx >= w || az >= hh || bz >= hh)
			continue;
		dvec3 pa = d3_sub(hf_point(h, w, hh, (uint32_t)ax, (uint32_t)az), c);
		dvec3 pb = d3_sub(hf_point(h, w, hh, (uint32_t)bx, (uint32_t)bz), c);
		s = d3_add(s, d3_normalize(d3_cross(pb, pa)));
	}
	return d3_normalize(s);
}

/* One triangle clipped to y >= water: 0, 1 or 2 triangles (written when m is not NULL, from
 * vertex *v on, unshared; otherwise only counted). Corners wholly above keep grid vertices. */
static size_t hf_clip(const dvec3 q[3], const dvec3 nq[3], const uint32_t gi[3], double water, mesh *m,
		      uint32_t *v, uint32_t **ix)
{
	int above = (q[0].y >= water) + (q[1].y >= water) + (q[2].y >= water);
	if (above == 0)
		return 0;
	if (above == 3) {
		if (m)
			*ix = tri(*ix, gi[0], gi[1], gi[2]);
		return 1;
	}
	dvec3 poly[4], pn[4];
	int np = 0;
	for (int i = 0; i < 3; i++) {
		const dvec3 a = q[i], b = q[(i + 1) % 3];
		if (a.y >= water)
			pn[np] = nq[i], poly[np++] = a;
		if ((a.y >= water) != (b.y >= water)) {
			double t = (water - a.y) / (b.y - a.y);
			pn[np] = d3_normalize(d3_add(d3_scale(nq[i], 1 - t), d3_scale(nq[(i + 1) % 3], t)));
			poly[np++] = d3_add(a, d3_scale(d3_sub(b, a), t));
			poly[np - 1].y = water;
		}
	}
	if (m) {
		for (int i = 0; i < np; i++)
			put(m, *v + (uint32_t)i, poly[i], pn[i], poly[i].x, poly[i].z);
		for (int i = 1; i + 1 < np; i++)
			*ix = tri(*ix, *v, *v + (uint32_t)i, *v + (uint32_t)i + 1);
		*v += (uint32_t)np;
	}
	return (size_t)np - 2;
}

/* Every cell's two triangles (POV-Ray's split), clipped at the water: counts them and the extra
 * vertices (*extra), and writes them when m is not NULL. */
static size_t hf_cells(const float *h, uint32_t w, uint32_t hh, double water, const vec3 *normals, mesh *m,
		       size_t *extra)
{
	size_t nt = 0, nv = 0;
	uint32_t v = w * hh, *ix = m ? m->indices : NULL;
	for (uint32_t z = 0; z + 1 < hh; z++)
		for (uint32_t x = 0; x + 1 < w; x++) {
			/* (x, z), (x, z + 1), (x + 1, z) and (x + 1, z + 1), (x + 1, z), (x, z + 1): upward. */
			const uint32_t c[2][3][2] = {{{x, z}, {x, z + 1}, {x + 1, z}}, {{x + 1, z + 1}, {x + 1, z}, {x, z + 1}}};
			for (int t = 0; t < 2; t++) {
				dvec3 q[3], nq[3];
				uint32_t gi[3];
				for (int k = 0; k < 3; k++) {
					q[k] = hf_point(h, w, hh, c[t][k][0], c[t][k][1]);
					gi[k] = c[t][k][1] * w + c[t][k][0];
					nq[k] = normals ? v3_to_d3(normals[gi[k]]) : d3(0, 1, 0);
				}
				int above = (q[0].y >= water) + (q[1].y >= water) + (q[2].y >= water);
				nv += above == 1 ? 3 : above == 2 ? 4 : 0;
				nt += hf_clip(q, nq, gi, water, m, &v, &ix);
			}
		}
	*extra = nv;
	return nt;
}

bool shape_height_field(const float *heights, uint32_t w, uint32_t h, bool smooth, double water_level,
			const shape_accuracy *a, mesh *out, diag *d, diag_loc loc)
{
	memset(out, 0, sizeof *out);
	if (w < 2 || h < 2) {
		diag_error(d, loc, "a height field needs an image of at least 2 x 2 pixels, found %u x %u", w, h);
		return false;
	}
	size_t full = 2 * (size_t)(w - 1) * (h - 1);
	if (!within_limit(full, a, "height field", d, loc))
		return false;
	size_t extra;
	size_t nt = hf_cells(heights, w, h, water_level, NULL, NULL, &extra);
	/* Smooth normals are always kept for the grid (the clipped corners interpolate them); a flat
	 * field's are the triangles' own, so it has none. */
	if (!alloc_mesh(out, (size_t)w * h + extra, nt, true, d, loc))
		return false;
	for (uint32_t z = 0; z < h; z++)
		for (uint32_t x = 0; x < w; x++)
			put(out, z * w + x, hf_point(heights, w, h, x, z), smooth ? hf_normal(heights, w, h, x, z) : d3(0, 1, 0),
			    (double)x / (w - 1), (double)z / (h - 1));
	hf_cells(heights, w, h, water_level, out->normals, out, &extra);
	if (!smooth) {
		mem_free(out->normals);
		out->normals = NULL;
	}
	return true;
}

/* ---- quadric ------------------------------------------------------------------------------------ */


/* The ellipsoid of a quadric: its kind and, for an ellipsoid, centre c, semi-axes and their
 * directions (the columns of v). */
static shape_quadric_kind quadric_ellipsoid(const double q[10], dvec3 *c, double axis[3], double v[3][3])
{
	double a[3][3] = {{q[0], q[3] / 2, q[4] / 2}, {q[3] / 2, q[1], q[5] / 2}, {q[4] / 2, q[5] / 2, q[2]}};
	double l[3], g[3] = {q[6], q[7], q[8]};
	shape_sym3_eigen(a, l, v);
	double lmax = fmax(fabs(l[0]), fmax(fabs(l[1]), fabs(l[2])));
	/* Definite: every eigenvalue of one sign, none negligible (which would make an axis infinite). */
	double sign = l[0] > 0 ? 1.0 : -1.0;
	bool definite = lmax > 0.0 && isfinite(lmax);
	for (int i = 0; i < 3; i++)
		definite = definite && sign * l[i] > 1e-12 * lmax;
	/* Negative definite: the solid (POV-Ray's inside, where the quadric is below 0) is the
	 * outside of the ellipsoid, unbounded: polygonised inside its bounds as a poly is. */
	if (!definite || sign < 0.0)
		return SHAPE_QUADRIC_UNBOUNDED;
	/* Centre -Q^-1 g / 2 in the eigenbasis; then (p - c)^T Q (p - c) = k. */
	double cl[3], k = -q[9];
	for (int i = 0; i < 3; i++) {
		double gl = v[0][i] * g[0] + v[1][i] * g[1] + v[2][i] * g[2];
		cl[i] = -gl / (2.0 * l[i]);
		k += l[i] * cl[i] * cl[i];
	}
	if (!(sign * k > 0.0) || !isfinite(k))
		return SHAPE_QUADRIC_EMPTY;
	*c = d3(0, 0, 0);
	for (int i = 0; i < 3; i++) {
		axis[i] = sqrt(k / l[i]);
		*c = d3_add(*c, d3_scale(d3(v[0][i], v[1][i], v[2][i]), cl[i]));
	}
	return SHAPE_QUADRIC_ELLIPSOID;
}

shape_quadric_kind shape_quadric_bound(const double q[10], dvec3 *centre, double *radius)
{
	double axis[3], v[3][3];
	shape_quadric_kind k = quadric_ellipsoid(q, centre, axis, v);
	*radius = k == SHAPE_QUADRIC_ELLIPSOID ? fmax(axis[0], fmax(axis[1], axis[2])) : 0.0;
	return k;
}


bool shape_quadric(const double q[10], const shape_accuracy *acc, mesh *out, double *err, shape_quadric_kind *kind,
		   diag *d, diag_loc loc)
{
	memset(out, 0, sizeof *out);
	double axis[3], v[3][3];
	dvec3 c;
	if ((*kind = quadric_ellipsoid(q, &c, axis, v)) != SHAPE_QUADRIC_ELLIPSOID)
		return true;
	double amax = fmax(axis[0], fmax(axis[1], axis[2]));
	uint32_t seg = shape_circle_segments(amax, acc);
	if (!within_limit(2 * (size_t)seg * (seg / 2 - 1), acc, "quadric", d, loc))
		return false;
	if (!prim_sphere(v3s(0.0f), 1.0f, seg, out)) {
		diag_error(d, loc, "out of memory while tessellating");
		return false;
	}
	for (uint32_t i = 0; i < out->num_vertices; i++) {
		dvec3 s = v3_to_d3(out->positions[i]), p = c, n = d3(0, 0, 0);
		for (int j = 0; j < 3; j++) {
			dvec3 col = d3(v[0][j], v[1][j], v[2][j]);
			double sj = j == 0 ? s.x : j == 1 ? s.y : s.z;
			p = d3_add(p, d3_scale(col, axis[j] * sj));
			n = d3_add(n, d3_scale(col, sj / axis[j])); /* the gradient Q (p - c), up to a factor */
		}
		out->positions[i] = v3d(p);
		out->normals[i] = v3d(d3_normalize(n));
	}
	/* An eigenbasis of negative determinant mirrors the sphere: restore the winding. */
	double det = v[0][0] * (v[1][1] * v[2][2] - v[1][2] * v[2][1]) - v[0][1] * (v[1][0] * v[2][2] - v[1][2] * v[2][0]) +
		     v[0][2] * (v[1][0] * v[2][1] - v[1][1] * v[2][0]);
	if (det < 0.0)
		for (uint32_t t = 0; t < out->num_triangles; t++) {
			uint32_t s = out->indices[3 * t + 1];
			out->indices[3 * t + 1] = out->indices[3 * t + 2], out->indices[3 * t + 2] = s;
		}
	*err = prim_sphere_rel_error(seg) * amax;
	return true;
}
