/* test_polysurf: POV-Ray's polynomial surfaces inside a box (src/geom/polysurf.h) against their
 * analytic surfaces: POV-Ray's term order (a torus and a sphere written as a quartic and a quadric),
 * random points on the triangles that are not the box's faces within the stated (and the reported)
 * distance, closed (every welded edge in two triangles), outward (the divergence theorem's volume
 * against the solid's, shading normals along the geometric ones), and a paraboloid's cut by its
 * box; shape_quadric_box against a brute-force grid and its unbounded kinds; shape_poly_ball. (The triangle limit
 * is field.c's, tested with the isosurface in test_shapes2.) */
#include "check.h"
#include "base/rng.h"
#include "geom/polysurf.h"
#include "shapes.h"

#include <string.h>

static diag D;

static double volume(const mesh *m, long *disagree)
{
	double vol = 0.0;
	*disagree = 0;
	for (uint32_t t = 0; t < m->num_triangles; t++) {
		const uint32_t *ix = m->indices + 3 * t;
		dvec3 a = v3_to_d3(m->positions[ix[0]]), b = v3_to_d3(m->positions[ix[1]]), c = v3_to_d3(m->positions[ix[2]]);
		dvec3 ng = d3_cross(d3_sub(b, a), d3_sub(c, a));
		vol += d3_dot(a, d3_cross(b, c)) / 6.0;
		int against = 0;
		for (int k = 0; k < 3; k++)
			against += d3_dot(ng, v3_to_d3(m->normals[ix[k]])) < 0.0;
		*disagree += against == 3 && d3_length(ng) > 0;
	}
	return vol;
}

/* Whether triangle t lies on the box's face (all three corners on one face plane). */
static bool on_box(const mesh *m, uint32_t t, dvec3 lo, dvec3 hi)
{
	double l[3] = {lo.x, lo.y, lo.z}, h[3] = {hi.x, hi.y, hi.z}, e = 1e-5 * (hi.x - lo.x);
	for (int a = 0; a < 3; a++) {
		int nl = 0, nh = 0;
		for (int k = 0; k < 3; k++) {
			vec3 p = m->positions[m->indices[3 * t + k]];
			double x = a == 0 ? p.x : a == 1 ? p.y : p.z;
			nl += fabs(x - l[a]) < e, nh += fabs(x - h[a]) < e;
		}
		if (nl == 3 || nh == 3)
			return true;
	}
	return false;
}

/* The box the mesh is closed by: the one given grown by SHAPE_POLY_MARGIN. */
static void grown(dvec3 *lo, dvec3 *hi)
{
	dvec3 e = d3_sub(*hi, *lo);
	double m = SHAPE_POLY_MARGIN * fmax(e.x, fmax(e.y, e.z));
	*lo = d3_sub(*lo, d3(m, m, m)), *hi = d3_add(*hi, d3(m, m, m));
}

static bool in_box(dvec3 p, dvec3 lo, dvec3 hi)
{
	return p.x >= lo.x && p.y >= lo.y && p.z >= lo.z && p.x <= hi.x && p.y <= hi.y && p.z <= hi.z;
}

/* The largest dist over 8 random points of every triangle, those inside [lo, hi] (the box
 * given: the crease at the grown box is outside it, where the CSG cuts it away). */
static double worst(const mesh *m, double (*dist)(dvec3), dvec3 lo, dvec3 hi)
{
	rng r;
	rng_seed(&r, 11, 3);
	double w = 0.0;
	for (uint32_t t = 0; t < m->num_triangles; t++)
		for (int k = 0; k < 8; k++) {
			dvec3 p = sample_tri(m, t, &r);
			if (in_box(p, lo, hi))
				w = fmax(w, dist(p));
		}
	return w;
}

/* POV-Ray's torus sample (objects/quartic/torus.pov): major sqrt(40), minor sqrt(12) about y. */
static const double R2 = 40.0, r2 = 12.0;
static double torus_dist(dvec3 p)
{
	return fabs(hypot(hypot(p.x, p.z) - sqrt(R2), p.y) - sqrt(r2));
}
static double sphere_dist(dvec3 p) { return fabs(d3_length(d3_sub(p, d3(0.5, 0, 0))) - 2.0); }
/* z = x^2 + y^2 (inside above it: x^2 + y^2 - z < 0) */
static double para_dist_only(dvec3 p)
{
	/* the distance to the parabola in the (rho, z) plane: the nearest point (s, s^2) solves
	 * 2 s^3 + (1 - 2 z) s - rho = 0; Newton from rho */
	double rho = hypot(p.x, p.y), s = rho;
	for (int i = 0; i < 60; i++) {
		double f = 2 * s * s * s + (1 - 2 * p.z) * s - rho, g = 6 * s * s + 1 - 2 * p.z;
		if (fabs(g) < 1e-12)
			break;
		s -= f / g;
	}
	return hypot(rho - s, p.z - s * s);
}
static double para_dist(dvec3 p) { return para_dist_only(p); }

static void test_terms(void)
{
	CHECK(shape_poly_terms(2) == 10 && shape_poly_terms(3) == 20 && shape_poly_terms(4) == 35, "term counts");
	double c[35] = {0};
	c[6] = 1.0; /* order 4's term 6: x^2 y (i = 2, j = 1, k = 0) */
	CHECK_NEAR(shape_poly_eval(4, c, d3(2, 3, 5)), 12.0, 1e-12);
	memset(c, 0, sizeof c);
	c[28] = 1.0; /* y z (i = 0, j = 1, k = 1) */
	CHECK_NEAR(shape_poly_eval(4, c, d3(2, 3, 5)), 15.0, 1e-12);
	/* the quadric's A..J: 1 x^2 + 2 y^2 + 3 z^2 + 4 xy + 5 xz + 6 yz + 7 x + 8 y + 9 z + 10 */
	double q[10] = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, pc[10];
	shape_quadric_poly(q, pc);
	dvec3 p = d3(0.3, -1.1, 2.0);
	double want = p.x * p.x + 2 * p.y * p.y + 3 * p.z * p.z + 4 * p.x * p.y + 5 * p.x * p.z + 6 * p.y * p.z +
		      7 * p.x + 8 * p.y + 9 * p.z + 10;
	CHECK_NEAR(shape_poly_eval(2, pc, p), want, 1e-12);
}

static void check_closed(const mesh *m, double want_vol, double vol_tol, const char *what)
{
	long dis;
	double vol = volume(m, &dis);
	CHECK(open_edges(m) == 0, "%s closed: %ld open edges", what, open_edges(m));
	CHECK(fabs(vol - want_vol) <= vol_tol * want_vol, "%s outward: volume %g, the solid's %g", what, vol, want_vol);
	CHECK(dis == 0, "%s: %ld triangles face against their normals", what, dis);
}

static void test_torus(void)
{
	/* torus.pov's coefficients: (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2) */
	const double c[35] = {1, 0, 0, 0, 2, 0, 0, 2, 0, -104, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
			      1, 0, 0, 2, 0, 56, 0, 0, 0, 0, 1, 0, -104, 0, 784};
	dvec3 lo = d3(-10, -10, -10), hi = d3(10, 10, 10);
	const double tols[] = {0.05, 0.01};
	for (int i = 0; i < 2; i++) {
		mesh m;
		double err = 0;
		CHECK(shape_poly_surface(4, c, lo, hi, tols[i], &m, &err, "quartic", &D, diag_noloc()), "torus quartic");
		double w = worst(&m, torus_dist, lo, hi);
		fprintf(stderr, "torus %g: %u triangles, reported %g, measured %g\n", tols[i], m.num_triangles, err, w);
		CHECK(err <= 1.5 * tols[i], "torus reached %g, asked %g", err, tols[i]);
		/* the reported distance is measured to first order at four points a triangle: within 10 % */
		CHECK(w <= 1.1 * fmax(err, tols[i]), "torus within %g (reported %g): %g", tols[i], err, w);
		check_closed(&m, 2 * M_PI * M_PI * sqrt(R2) * r2, 0.01, "torus");
		mesh_free(&m);
	}
}

static void test_sphere_and_cut(void)
{
	/* a sphere of radius 2 about (0.5, 0, 0) as a quadric: x^2 + y^2 + z^2 - x - 3.75 */
	double q[10] = {1, 1, 1, 0, 0, 0, -1, 0, 0, -3.75}, c[10];
	shape_quadric_poly(q, c);
	dvec3 lo = d3(-2, -2.5, -3), hi = d3(3, 2.5, 2.5);
	mesh m;
	double err;
	CHECK(shape_poly_surface(2, c, lo, hi, 0.005, &m, &err, "quadric", &D, diag_noloc()), "sphere quadric");
	double w = worst(&m, sphere_dist, lo, hi);
	CHECK(w <= 1.1 * fmax(err, 0.005), "sphere within %g (reported %g): %g", 0.005, err, w);
	check_closed(&m, 4.0 / 3 * M_PI * 8, 0.01, "sphere");
	mesh_free(&m);

	/* a paraboloid cut by its box: the solid above z = x^2 + y^2 up to z = 1 is closed by the cut */
	double pq[10] = {1, 1, 0, 0, 0, 0, 0, 0, -1, 0};
	shape_quadric_poly(pq, c);
	lo = d3(-1.5, -1.5, -0.5), hi = d3(1.5, 1.5, 1);
	CHECK(shape_poly_surface(2, c, lo, hi, 0.002, &m, &err, "quadric", &D, diag_noloc()), "paraboloid");
	w = worst(&m, para_dist, lo, hi);
	CHECK(w <= 1.1 * fmax(err, 0.002), "paraboloid within %g (reported %g): %g", 0.002, err, w);
	grown(&lo, &hi); /* closed at the grown box: z up to 1.3 */
	check_closed(&m, M_PI * hi.z * hi.z / 2, 0.01, "cut paraboloid"); /* the volume pi h^2 / 2 */
	bool cap = false;
	for (uint32_t t = 0; t < m.num_triangles; t++)
		cap |= on_box(&m, t, lo, hi);
	CHECK(cap, "the paraboloid's cut is closed by the grown box's face");
	mesh_free(&m);
}

/* shape_quadric_box: an elliptic cylinder bounds the axes across it, an ellipsoid all three,
 * a paraboloid, a cone and the outside of a sphere none; a quadric without points is empty. */
static void test_quadric_box(void)
{
	dvec3 lo, hi;
	const double cyl_x[10] = {0, 4, 1, 0, 0, 0, 0, 0, 0, -4}; /* 4 y^2 + z^2 <= 4: |y| <= 1, |z| <= 2 */
	CHECK(shape_quadric_box(cyl_x, &lo, &hi), "cylinder has points");
	CHECK(isinf(lo.x) && isinf(hi.x), "cylinder open along x: %g %g", lo.x, hi.x);
	CHECK_NEAR(lo.y, -1, 1e-12);
	CHECK_NEAR(hi.y, 1, 1e-12);
	CHECK_NEAR(lo.z, -2, 1e-12);
	CHECK_NEAR(hi.z, 2, 1e-12);
	/* a rotated ellipsoid (x + y)^2 / 2 + (x - y)^2 + z^2 <= 1, centred at (1, 0, 0) after its linear terms */
	const double ell[10] = {1.5, 1.5, 1, -1, 0, 0, -3, 1, 0, 0.5};
	CHECK(shape_quadric_box(ell, &lo, &hi), "ellipsoid has points");
	/* brute force: the extremes of P <= 0 on a fine grid lie inside the box and near its faces */
	double ext[6] = {INFINITY, INFINITY, INFINITY, -INFINITY, -INFINITY, -INFINITY};
	for (int i = 0; i <= 120; i++)
		for (int j = 0; j <= 120; j++)
			for (int k = 0; k <= 120; k++) {
				dvec3 p = d3(-3 + 6.0 * i / 120, -3 + 6.0 * j / 120, -3 + 6.0 * k / 120);
				double c[10];
				shape_quadric_poly(ell, c);
				if (shape_poly_eval(2, c, p) <= 0) {
					ext[0] = fmin(ext[0], p.x), ext[1] = fmin(ext[1], p.y), ext[2] = fmin(ext[2], p.z);
					ext[3] = fmax(ext[3], p.x), ext[4] = fmax(ext[4], p.y), ext[5] = fmax(ext[5], p.z);
				}
			}
	const double box[6] = {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z};
	for (int a = 0; a < 6; a++)
		CHECK(fabs(box[a] - ext[a]) <= 0.06 && (a < 3 ? box[a] <= ext[a] : box[a] >= ext[a]),
		      "ellipsoid box side %d: %g, the grid's extreme %g", a, box[a], ext[a]);
	const double para[10] = {1, 1, 0, 0, 0, 0, 0, 0, -1, 0}, cone[10] = {1, -1, 1, 0, 0, 0, 0, 0, 0, 0};
	const double outside[10] = {-1, -1, -1, 0, 0, 0, 0, 0, 0, 1}, none[10] = {1, 1, 1, 0, 0, 0, 0, 0, 0, 1};
	CHECK(shape_quadric_box(para, &lo, &hi) && isinf(lo.x) && isinf(hi.y) && isinf(hi.z), "paraboloid unbounded");
	CHECK(shape_quadric_box(cone, &lo, &hi) && isinf(lo.x) && isinf(lo.y) && isinf(lo.z), "cone unbounded");
	CHECK(shape_quadric_box(outside, &lo, &hi) && isinf(lo.x) && isinf(hi.z), "a sphere's outside unbounded");
	CHECK(!shape_quadric_box(none, &lo, &hi), "x^2 + y^2 + z^2 + 1 <= 0 is empty");
}

/* shape_poly_ball: a ball holding the solid where the top form is positive on every direction */
static void test_poly_ball(void)
{
	double bicube[35] = {0}, r;
	bicube[0] = bicube[20] = bicube[30] = 1, bicube[34] = -1000; /* x^4 + y^4 + z^4 - 1000 (bicube.pov) */
	CHECK(shape_poly_ball(4, bicube, &r), "bicube bounds itself");
	double reach = pow(1000, 0.25) * pow(3, 0.25); /* the farthest point, along a diagonal: 3 x^4 = 1000 */
	CHECK(r >= reach && r <= 2 * reach, "bicube's ball %g holds its farthest point %g, not much more", r, reach);
	const double torus[35] = {1, 0, 0, 0, 2, 0, 0, 2, 0, -104, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
				  1, 0, 0, 2, 0, 56, 0, 0, 0, 0, 1, 0, -104, 0, 784};
	CHECK(shape_poly_ball(4, torus, &r) && r >= sqrt(R2) + sqrt(r2), "torus ball %g holds R + r", r);
	const double piriform[35] = {4, 0, 0, -4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
				     0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1, 0, 0};
	CHECK(!shape_poly_ball(4, piriform, &r), "piriform's top form 4 x^4 vanishes on x = 0: not shown bounded");
	double cubic[20] = {0};
	cubic[0] = 1, cubic[19] = -1;
	CHECK(!shape_poly_ball(3, cubic, &r), "an odd order is never bounded this way");
}

int main(void)
{
	diag_init(&D, stderr);
	test_terms();
	test_quadric_box();
	test_poly_ball();
	test_torus();
	test_sphere_and_cut();
	diag_free(&D);
	return check_done("test_polysurf");
}
