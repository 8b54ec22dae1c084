/* test_povshape: POV-Ray's shapes as meshes (src/geom/povshape.h) against their analytic
 * surfaces: random points on the triangles within the stated distance, vertices on the surface,
 * closed where the shape is closed (every welded edge in two triangles), outward normals (and the
 * divergence theorem's volume), the even-odd polygon against brute force, the height field's
 * heights and water cut, the triangle limit and the refusals. */
#include "check.h"
#include "geom/povshape.h"
#include "base/rng.h"
#include "shapes.h"

#include <string.h>

static diag D;

/* The largest distance(p) over `per` random points of every triangle. */
static double max_distance(const mesh *m, double (*dist)(dvec3, const double *), const double *prm, int per)
{
	rng r;
	rng_seed(&r, 7, 1);
	double worst = 0.0;
	for (uint32_t t = 0; t < m->num_triangles; t++)
		for (int k = 0; k < per; k++)
			worst = fmax(worst, dist(sample_tri(m, t, &r), prm));
	return worst;
}

/* The enclosed volume by the divergence theorem (positive when the triangles face outward), and
 * how many triangles' geometric normals disagree with their shading normals. */
static double volume(const mesh *m, long *disagree)
{
	double vol = 0.0;
	*disagree = 0;
	for (uint32_t t = 0; t < m->num_triangles; t++) {
		const uint32_t *ix = m->indices + 3 * t;
		dvec3 a = v3_to_d3(m->positions[ix[0]]), b = v3_to_d3(m->positions[ix[1]]), c = v3_to_d3(m->positions[ix[2]]);
		dvec3 ng = d3_cross(d3_sub(b, a), d3_sub(c, a));
		vol += d3_dot(a, d3_cross(b, c)) / 6.0;
		for (int k = 0; k < 3 && m->normals; k++)
			*disagree += d3_dot(ng, v3_to_d3(m->normals[ix[k]])) <= 0.0;
	}
	return vol;
}

static shape_accuracy acc(double err)
{
	return (shape_accuracy){.max_error = err, .max_edge = 0.0, .max_triangles = SHAPE_MAX_TRIANGLES};
}

/* ---- cone and cylinder: the distance in the meridian plane to the outline's three segments ---- */

static double seg_dist(double px, double py, double ax, double ay, double bx, double by)
{
	double dx = bx - ax, dy = by - ay, t = ((px - ax) * dx + (py - ay) * dy) / (dx * dx + dy * dy);
	t = fmin(fmax(t, 0.0), 1.0);
	return hypot(px - ax - t * dx, py - ay - t * dy);
}

/* prm: base y 0, cap y = prm[0], radii prm[1], prm[2]; the axis is y. */
static double cone_dist(dvec3 p, const double *prm)
{
	double h = prm[0], rb = prm[1], rc = prm[2], rho = hypot(p.x, p.z);
	double d = seg_dist(p.y, rho, 0, rb, h, rc);
	if (prm[3] == 0.0) /* capped */
		d = fmin(d, fmin(seg_dist(p.y, rho, 0, 0, 0, rb), seg_dist(p.y, rho, h, 0, h, rc)));
	return d;
}

static void test_cone(double rb, double rc, bool open, double tol)
{
	mesh m;
	double err, prm[4] = {2.0, rb, rc, open};
	shape_accuracy a = acc(tol);
	CHECK(shape_cone(d3(0, 0, 0), rb, d3(0, 2, 0), rc, open, &a, &m, &err, &D, diag_noloc()), "cone %g %g", rb, rc);
	CHECK(err <= tol, "cone's stated error %g over the asked %g", err, tol);
	double worst = max_distance(&m, cone_dist, prm, 8);
	CHECK(worst <= err * (1 + 1e-6) + 1e-7, "cone %g %g: a point %g from the surface, stated %g", rb, rc, worst, err);
	long bad, open_e = open_edges(&m);
	double vol = volume(&m, &bad);
	CHECK(bad == 0, "cone %g %g: %ld normals disagree with their triangles", rb, rc, bad);
	if (!open) {
		CHECK(open_e == 0, "capped cone %g %g has %ld open edges", rb, rc, open_e);
		double exact = M_PI * 2.0 / 3.0 * (rb * rb + rb * rc + rc * rc);
		CHECK(vol > 0 && fabs(vol - exact) < 4 * err / fmax(rb, rc) * exact + 1e-6, "cone volume %g, exact %g", vol,
		      exact);
	} else {
		uint32_t n = shape_circle_segments(fmax(rb, rc), &a);
		CHECK(open_e == (long)n * ((rb > 0) + (rc > 0)), "open cone: %ld open edges, expected the rims' %u", open_e,
		      n * ((rb > 0) + (rc > 0)));
	}
	mesh_free(&m);
}

/* ---- torus --------------------------------------------------------------------------------- */

static double torus_dist(dvec3 p, const double *prm)
{
	return fabs(hypot(hypot(p.x, p.z) - prm[0], p.y) - prm[1]);
}

static void test_torus(void)
{
	mesh m;
	double err, prm[2] = {1.0, 0.3};
	shape_accuracy a = acc(1e-3);
	CHECK(shape_torus(1.0, 0.3, &a, &m, &err, &D, diag_noloc()), "torus");
	CHECK(err <= 1e-3, "torus error %g", err);
	double worst = max_distance(&m, torus_dist, prm, 8);
	CHECK(worst <= err, "torus: a point %g from the surface, stated %g", worst, err);
	CHECK(open_edges(&m) == 0, "torus has %ld open edges", open_edges(&m));
	long bad;
	double vol = volume(&m, &bad), exact = 2 * M_PI * M_PI * 1.0 * 0.09;
	CHECK(bad == 0 && fabs(vol - exact) < 0.01 * exact, "torus volume %g (exact %g), %ld bad normals", vol, exact, bad);
	/* POV-Ray's uv_mapping: u = 1 - (atan2(z, x) + pi) / 2 pi, v = (atan2(y, rho - R) + pi) / 2 pi. */
	double uv_bad = 0.0;
	for (uint32_t v = 0; v < m.num_vertices; v++) {
		vec3 p = m.positions[v];
		double u = 1.0 - (atan2(p.z, p.x) + M_PI) / (2 * M_PI), w = (atan2(p.y, hypot(p.x, p.z) - 1.0) + M_PI) / (2 * M_PI);
		double du = fabs(u - m.uvs[v].x), dw = fabs(w - m.uvs[v].y);
		du = fmin(du, fabs(1.0 - du)), dw = fmin(dw, fabs(1.0 - dw)); /* the seams: 0 and 1 */
		uv_bad = fmax(uv_bad, fmax(du, dw));
	}
	CHECK(uv_bad < 1e-5, "torus UVs differ from POV-Ray's by %g", uv_bad);
	mesh_free(&m);
}

/* ---- disc ----------------------------------------------------------------------------------- */

static double disc_dist(dvec3 p, const double *prm) /* centre 0, normal z, radius, hole */
{
	double rho = hypot(p.x, p.y), out = fmax(0.0, fmax(rho - prm[0], prm[1] - rho));
	return hypot(p.z, out);
}

static void test_disc(void)
{
	mesh m;
	double err, prm[2] = {2.0, 0.5};
	shape_accuracy a = acc(1e-3);
	CHECK(shape_disc(d3(0, 0, 0), d3(0, 0, 3), 2.0, 0.5, &a, &m, &err, &D, diag_noloc()), "disc");
	CHECK(max_distance(&m, disc_dist, prm, 8) <= 1e-6, "disc: points off the annulus");
	long bad;
	volume(&m, &bad);
	double area = 0.0;
	for (uint32_t t = 0; t < m.num_triangles; t++) {
		const uint32_t *ix = m.indices + 3 * t;
		vec3 ng = v3_cross(v3_sub(m.positions[ix[1]], m.positions[ix[0]]), v3_sub(m.positions[ix[2]], m.positions[ix[0]]));
		CHECK(ng.z > 0, "disc triangle %u faces away from its normal", t);
		area += 0.5 * v3_length(ng);
	}
	double exact = M_PI * (4.0 - 0.25);
	CHECK(bad == 0 && area < exact && area > exact * (1 - 2 * err / 0.5), "disc area %g, exact %g", area, exact);
	mesh_free(&m);
}

/* ---- superellipsoid --------------------------------------------------------------------------- */

static double super_dist(dvec3 p, const double *prm) /* the radial distance: an upper bound */
{
	double nrm = shape_superellipsoid_norm(prm[0], prm[1], p);
	return d3_length(p) * fabs(1.0 - 1.0 / nrm);
}

static void test_super(double e, double n, double tol)
{
	mesh m;
	double err, prm[2] = {e, n};
	shape_accuracy a = acc(tol);
	CHECK(shape_superellipsoid(e, n, &a, &m, &err, &D, diag_noloc()), "superellipsoid <%g, %g>", e, n);
	double worst = max_distance(&m, super_dist, prm, 16);
	/* The stated error is measured at 4 points a triangle: 16 random ones may find a little more. */
	CHECK(worst <= 1.5 * err, "superellipsoid <%g, %g>: a point %g from the surface, stated %g", e, n, worst, err);
	CHECK(err <= tol || m.num_triangles >= 2u * SHAPE_MAX_SEGMENTS * (SHAPE_MAX_SEGMENTS / 2 - 1),
	      "superellipsoid <%g, %g>: error %g over %g before the cap", e, n, err, tol);
	CHECK(open_edges(&m) == 0, "superellipsoid <%g, %g> has %ld open edges", e, n, open_edges(&m));
	long bad;
	double vol = volume(&m, &bad);
	CHECK(bad == 0 && vol > 0, "superellipsoid <%g, %g>: volume %g, %ld bad normals", e, n, vol, bad);
	if (e == 1.0 && n == 1.0)
		CHECK(fabs(vol - 4.0 * M_PI / 3.0) < 0.01, "the <1, 1> superellipsoid (a sphere) has volume %g", vol);
	mesh_free(&m);
}

/* ---- quadric ---------------------------------------------------------------------------------- */

static double sphere_dist(dvec3 p, const double *prm)
{
	return fabs(d3_length(d3_sub(p, d3(prm[0], prm[1], prm[2]))) - prm[3]);
}

static void test_quadric(void)
{
	mesh m;
	double err;
	shape_quadric_kind k;
	shape_accuracy a = acc(1e-3);
	/* (x - 1)^2 + (y + 2)^2 + z^2 = 4: a sphere of radius 2 about <1, -2, 0>. */
	const double sph[10] = {1, 1, 1, 0, 0, 0, -2, 4, 0, 1 + 4 - 4};
	double prm[4] = {1, -2, 0, 2};
	CHECK(shape_quadric(sph, &a, &m, &err, &k, &D, diag_noloc()) && k == SHAPE_QUADRIC_ELLIPSOID, "sphere quadric");
	CHECK(max_distance(&m, sphere_dist, prm, 8) <= err + 1e-6, "quadric sphere off by %g, stated %g",
	      max_distance(&m, sphere_dist, prm, 8), err);
	CHECK(open_edges(&m) == 0, "quadric sphere open");
	long bad;
	double vol = volume(&m, &bad);
	CHECK(bad == 0 && fabs(vol - 32 * M_PI / 3) < 0.01 * 32 * M_PI / 3, "quadric sphere volume %g", vol);
	mesh_free(&m);
	/* A rotated ellipsoid with mixed terms: vertices on it, normals along the gradient. */
	const double ell[10] = {2, 3, 1, 1, 0.5, -0.3, 0.2, 0, -0.1, -1};
	CHECK(shape_quadric(ell, &a, &m, &err, &k, &D, diag_noloc()) && k == SHAPE_QUADRIC_ELLIPSOID, "ellipsoid");
	double fmax_ = 0.0, nbad = 0.0;
	for (uint32_t v = 0; v < m.num_vertices; v++) {
		double x = m.positions[v].x, y = m.positions[v].y, z = m.positions[v].z;
		double f = 2 * x * x + 3 * y * y + z * z + x * y + 0.5 * x * z - 0.3 * y * z + 0.2 * x - 0.1 * z - 1;
		dvec3 g = d3_normalize(d3(4 * x + y + 0.5 * z + 0.2, 6 * y + x - 0.3 * z, 2 * z + 0.5 * x - 0.3 * y - 0.1));
		fmax_ = fmax(fmax_, fabs(f));
		nbad = fmax(nbad, 1.0 - d3_dot(g, v3_to_d3(m.normals[v])));
	}
	CHECK(fmax_ < 1e-5 && nbad < 1e-5, "ellipsoid: |f| at vertices up to %g, normals off by %g", fmax_, nbad);
	vol = volume(&m, &bad);
	CHECK(bad == 0 && vol > 0 && open_edges(&m) == 0, "ellipsoid: volume %g, %ld bad normals", vol, bad);
	mesh_free(&m);
	/* Unbounded and empty ones make no mesh. */
	const double cyl[10] = {1, 0, 1, 0, 0, 0, 0, 0, 0, -1}, hyp[10] = {1, -1, 1, 0, 0, 0, 0, 0, 0, -1},
		     none[10] = {1, 1, 1, 0, 0, 0, 0, 0, 0, 1};
	CHECK(shape_quadric(cyl, &a, &m, &err, &k, &D, diag_noloc()) && k == SHAPE_QUADRIC_UNBOUNDED && !m.num_triangles,
	      "a quadric cylinder is unbounded");
	CHECK(shape_quadric(hyp, &a, &m, &err, &k, &D, diag_noloc()) && k == SHAPE_QUADRIC_UNBOUNDED, "a hyperboloid is unbounded");
	CHECK(shape_quadric(none, &a, &m, &err, &k, &D, diag_noloc()) && k == SHAPE_QUADRIC_EMPTY, "x^2+y^2+z^2+1 is empty");
	/* Negative definite: POV-Ray's inside (below 0) of -x^2-y^2-z^2+1 is the outside of the ball,
	 * unbounded (polygonised inside its CSG box, as a poly), never the ball itself. */
	const double out_ball[10] = {-1, -1, -1, 0, 0, 0, 0, 0, 0, 1};
	dvec3 oc;
	double orad;
	CHECK(shape_quadric(out_ball, &a, &m, &err, &k, &D, diag_noloc()) && k == SHAPE_QUADRIC_UNBOUNDED &&
		      !m.num_triangles && shape_quadric_bound(out_ball, &oc, &orad) == SHAPE_QUADRIC_UNBOUNDED,
	      "-x^2-y^2-z^2+1's solid is the outside of the ball: unbounded (kind %d)", (int)k);
}

/* ---- polygon: the triangles cover exactly the even-odd inside -------------------------------- */

/* Even-odd inside of the 2-D outline (x, y of the points, subpolygons as POV-Ray's) by crossings. */
static bool even_odd(const dvec3 *p, uint32_t n, double x, double y)
{
	bool in = false;
	uint32_t start = 0;
	for (uint32_t j = 1; j < n; j++) {
		dvec3 a = p[j - 1], b = p[j];
		if ((a.y > y) != (b.y > y) && x < a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y))
			in = !in;
		if (p[j].x == p[start].x && p[j].y == p[start].y && j > start)
			start = ++j;
	}
	return in;
}

static bool in_mesh(const mesh *m, double x, double y)
{
	for (uint32_t t = 0; t < m->num_triangles; t++) {
		vec3 a = m->positions[m->indices[3 * t]], b = m->positions[m->indices[3 * t + 1]],
		     c = m->positions[m->indices[3 * t + 2]];
		double d1 = (b.x - a.x) * (y - a.y) - (b.y - a.y) * (x - a.x), d2 = (c.x - b.x) * (y - b.y) - (c.y - b.y) * (x - b.x),
		       d3_ = (a.x - c.x) * (y - c.y) - (a.y - c.y) * (x - c.x);
		if ((d1 >= 0 && d2 >= 0 && d3_ >= 0) || (d1 <= 0 && d2 <= 0 && d3_ <= 0))
			return true;
	}
	return false;
}

static void test_polygon(const char *name, const dvec3 *p, uint32_t n)
{
	mesh m;
	shape_accuracy a = acc(1e-3);
	CHECK(shape_polygon(p, n, &a, &m, &D, diag_noloc()) && m.num_triangles > 0, "polygon %s", name);
	rng r;
	rng_seed(&r, 3, 5);
	int wrong = 0;
	for (int i = 0; i < 4000; i++) {
		double x = -0.2 + 1.4 * rng_double(&r), y = -0.2 + 1.4 * rng_double(&r);
		wrong += even_odd(p, n, x, y) != in_mesh(&m, x, y);
	}
	/* Points on an edge may go either way; of 4000 random ones none should. */
	CHECK(wrong == 0, "polygon %s: %d of 4000 points disagree with the even-odd rule", name, wrong);
	for (uint32_t v = 0; v < m.num_vertices; v++)
		CHECK(fabs(m.positions[v].z) < 1e-6, "polygon %s: vertex off its plane", name);
	mesh_free(&m);
}

static void test_polygons(void)
{
	const dvec3 holed[10] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0},
				 {0.25, 0.25, 0}, {0.75, 0.25, 0}, {0.75, 0.75, 0}, {0.25, 0.75, 0}, {0.25, 0.25, 0}};
	test_polygon("square with a hole", holed, 10);
	const dvec3 star[6] = {{0.5, 1, 0}, {0.8, 0, 0}, {0, 0.62, 0}, {1, 0.62, 0}, {0.2, 0, 0}, {0.5, 1, 0}};
	test_polygon("pentagram", star, 6);
	const dvec3 two[10] = {{0, 0, 0}, {0.6, 0, 0}, {0.6, 0.6, 0}, {0, 0.6, 0}, {0, 0, 0},
			       {0.4, 0.4, 0}, {1, 0.4, 0}, {1, 1, 0}, {0.4, 1, 0}, {0.4, 0.4, 0}};
	test_polygon("overlapping squares", two, 10);
	/* Collinear points and points off one plane make an empty mesh (warned), as POV-Ray ignores them. */
	mesh m;
	shape_accuracy a = acc(1e-3);
	const dvec3 line[4] = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {0, 0, 0}};
	CHECK(shape_polygon(line, 4, &a, &m, &D, diag_noloc()) && m.num_triangles == 0, "collinear polygon ignored");
	const dvec3 bent[5] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, 0}, {0, 0, 0}};
	CHECK(shape_polygon(bent, 5, &a, &m, &D, diag_noloc()) && m.num_triangles == 0, "non-planar polygon ignored");
}

/* ---- height field ----------------------------------------------------------------------------- */

static void test_height_field(void)
{
	enum { W = 5, H = 4 };
	float h[W * H];
	for (int z = 0; z < H; z++)
		for (int x = 0; x < W; x++)
			h[z * W + x] = (float)(0.1 * x + 0.05 * z * z);
	mesh m;
	shape_accuracy a = acc(1e-3);
	CHECK(shape_height_field(h, W, H, true, 0.0, &a, &m, &D, diag_noloc()), "height field");
	CHECK(m.num_triangles == 2 * (W - 1) * (H - 1), "height field: %u triangles", m.num_triangles);
	double hb = 0.0;
	for (int z = 0; z < H; z++)
		for (int x = 0; x < W; x++) {
			vec3 p = m.positions[z * W + x];
			hb = fmax(hb, fabs(p.x - x / (W - 1.0)) + fabs(p.y - h[z * W + x]) + fabs(p.z - z / (H - 1.0)));
		}
	CHECK(hb < 1e-6, "height field vertices off their samples by %g", hb);
	long bad;
	volume(&m, &bad);
	int down = 0;
	for (uint32_t t = 0; t < m.num_triangles; t++) {
		const uint32_t *ix = m.indices + 3 * t;
		down += v3_cross(v3_sub(m.positions[ix[1]], m.positions[ix[0]]), v3_sub(m.positions[ix[2]], m.positions[ix[0]])).y <= 0;
	}
	CHECK(bad == 0 && down == 0, "height field: %d triangles face down, %ld normals disagree", down, bad);
	mesh_free(&m);
	/* The water level cuts away what lies below it: the rest keeps its area above. */
	CHECK(shape_height_field(h, W, H, false, 0.2, &a, &m, &D, diag_noloc()), "height field with water");
	float lowest = 1;
	for (uint32_t t = 0; t < m.num_triangles; t++)
		for (int k = 0; k < 3; k++)
			lowest = fminf(lowest, m.positions[m.indices[3 * t + k]].y);
	CHECK(lowest >= 0.2f - 1e-6f && m.num_triangles > 0 && !m.normals, "water 0.2: lowest %g, %u triangles", lowest,
	      m.num_triangles);
	mesh_free(&m);
	CHECK(!shape_height_field(h, 1, H, false, 0.0, &a, &m, &D, diag_noloc()), "a 1-pixel-wide field is refused");
}

/* ---- limits and refusals ------------------------------------------------------------------------- */

static void test_limits(void)
{
	mesh m;
	double err;
	shape_accuracy a = acc(1e-6);
	a.max_triangles = 100;
	diag_init(&D, fopen("/dev/null", "w"));
	int before = D.errors;
	CHECK(!shape_cone(d3(0, 0, 0), 1, d3(0, 1, 0), 1, false, &a, &m, &err, &D, diag_noloc()) && !m.num_triangles,
	      "a cylinder over the limit is refused");
	CHECK(!shape_torus(1, 0.5, &a, &m, &err, &D, diag_noloc()), "a torus over the limit is refused");
	CHECK(!shape_superellipsoid(1, 1, &a, &m, &err, &D, diag_noloc()), "a superellipsoid over the limit is refused");
	float h[400] = {0};
	CHECK(!shape_height_field(h, 20, 20, false, 0, &a, &m, &D, diag_noloc()), "a height field over the limit is refused");
	CHECK(D.errors == before + 4, "the refusals reported %d errors", D.errors - before);
	a.max_triangles = SHAPE_MAX_TRIANGLES;
	CHECK(!shape_cone(d3(0, 0, 0), 0, d3(0, 1, 0), 0, false, &a, &m, &err, &D, diag_noloc()), "a cone of radii 0");
	CHECK(!shape_torus(0.5, 1, &a, &m, &err, &D, diag_noloc()), "a spindle torus");
	CHECK(!shape_disc(d3(0, 0, 0), d3(0, 0, 0), 1, 0, &a, &m, &err, &D, diag_noloc()), "a disc without normal");
	CHECK(!shape_superellipsoid(0, 1, &a, &m, &err, &D, diag_noloc()), "a superellipsoid exponent 0");
	/* The segment rule: the finest for a tiny error, the coarsest for a huge one, the edge bound. */
	CHECK(shape_circle_segments(1, &(shape_accuracy){.max_error = 1e-300}) == SHAPE_MAX_SEGMENTS, "finest");
	CHECK(shape_circle_segments(1, &(shape_accuracy){.max_error = 10}) == SHAPE_MIN_SEGMENTS, "coarsest");
	CHECK(shape_circle_segments(1, &(shape_accuracy){.max_error = 10, .max_edge = 2 * M_PI / 100}) == 100, "edges");
	uint32_t n = shape_circle_segments(3, &(shape_accuracy){.max_error = 1e-3});
	CHECK(shape_circle_error(3, n) <= 1e-3 && shape_circle_error(3, n - 1) > 1e-3, "segments %u not the fewest", n);
}

int main(void)
{
	diag_init(&D, stderr);
	test_cone(1.0, 1.0, false, 1e-3);
	test_cone(1.0, 1.0, true, 1e-3);
	test_cone(1.0, 0.0, false, 1e-3);
	test_cone(0.0, 0.7, false, 1e-3);
	test_cone(0.3, 1.2, true, 1e-4);
	test_torus();
	test_disc();
	test_super(1.0, 1.0, 1e-3);
	test_super(0.25, 0.5, 1e-3);
	test_super(2.5, 0.1, 1e-3);
	test_super(1.5, 3.0, 1e-3);
	test_quadric();
	test_polygons();
	test_height_field();
	test_limits();
	return check_done("test_povshape");
}
