/* test_vec: vector helpers, the orthonormal basis, and affine transforms against hand-worked values. */
#include "base/rng.h"
#include "base/vec.h"
#include "check.h"

static void check_xform_close(const xform *a, const xform *b, double tol, const char *what)
{
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 4; j++) {
			CHECK(fabs(a->m[i][j] - b->m[i][j]) <= tol, "%s m[%d][%d] %g vs %g", what, i, j,
			      a->m[i][j], b->m[i][j]);
			CHECK(fabs(a->inv[i][j] - b->inv[i][j]) <= tol, "%s inv[%d][%d] %g vs %g", what, i,
			      j, a->inv[i][j], b->inv[i][j]);
		}
}

int main(void)
{
	vec3 a = v3(1, 2, 3), b = v3(-2, 0.5f, 4);
	CHECK_NEAR(v3_dot(a, b), -2 + 1 + 12, 0);
	vec3 c = v3_cross(v3(1, 0, 0), v3(0, 1, 0));
	CHECK(c.x == 0 && c.y == 0 && c.z == 1, "x cross y = (%g %g %g)", c.x, c.y, c.z);
	CHECK_NEAR(v3_length(v3_normalize(b)), 1.0, 1e-6);
	vec3 zero = v3_normalize(v3s(0));
	CHECK(zero.x == 0 && zero.y == 0 && zero.z == 0, "normalize(0) stays 0");

	/* The basis is orthonormal for random normals, including the poles. */
	rng g;
	rng_seed(&g, 1, 2);
	for (int i = 0; i < 10000; i++) {
		vec3 n;
		if (i == 0)
			n = v3(0, 0, 1);
		else if (i == 1)
			n = v3(0, 0, -1);
		else
			n = v3_normalize(v3(rng_float(&g) * 2 - 1, rng_float(&g) * 2 - 1, rng_float(&g) * 2 - 1));
		vec3 b1, b2;
		v3_basis(n, &b1, &b2);
		CHECK(fabsf(v3_dot(b1, n)) < 1e-5f && fabsf(v3_dot(b2, n)) < 1e-5f &&
			      fabsf(v3_dot(b1, b2)) < 1e-5f && fabsf(v3_length(b1) - 1) < 1e-5f &&
			      fabsf(v3_length(b2) - 1) < 1e-5f,
		      "basis of (%g %g %g)", n.x, n.y, n.z);
	}

	/* POV-Ray rotations: rotate y*90 takes +x to -z; rotate x*90 takes +y to +z; z*90 takes +x to +y. */
	xform ry = xform_rotate(d3(0, 90, 0));
	dvec3 q = xform_point(&ry, d3(1, 0, 0));
	CHECK(q.x == 0 && q.y == 0 && q.z == -1, "rotate y*90 of +x = (%g %g %g)", q.x, q.y, q.z);
	xform rx = xform_rotate(d3(90, 0, 0));
	q = xform_point(&rx, d3(0, 1, 0));
	CHECK(q.x == 0 && q.y == 0 && q.z == 1, "rotate x*90 of +y = (%g %g %g)", q.x, q.y, q.z);
	xform rz = xform_rotate(d3(0, 0, 90));
	q = xform_point(&rz, d3(1, 0, 0));
	CHECK(q.x == 0 && q.y == 1 && q.z == 0, "rotate z*90 of +x = (%g %g %g)", q.x, q.y, q.z);

	/* Composition order: scale then translate. */
	xform s;
	CHECK(xform_scale(d3(2, 3, 4), &s), "scale ok");
	xform st = xform_then(s, xform_translate(d3(1, 1, 1)));
	q = xform_point(&st, d3(1, 1, 1));
	CHECK(q.x == 3 && q.y == 4 && q.z == 5, "scale then translate (%g %g %g)", q.x, q.y, q.z);
	dvec3 back = xform_inv_point(&st, q);
	CHECK_NEAR(back.x, 1, 1e-15);
	CHECK_NEAR(back.y, 1, 1e-15);
	CHECK_NEAR(back.z, 1, 1e-15);
	CHECK(!xform_scale(d3(1, 0, 1), &s), "zero scale is refused");

	/* A random chain: inverse times forward is the identity; normals stay perpendicular. */
	xform t = xform_identity();
	t = xform_then(t, xform_rotate(d3(17, -33, 71)));
	CHECK(xform_scale(d3(0.5, 2, 7), &s), "scale ok");
	t = xform_then(t, s);
	t = xform_then(t, xform_translate(d3(-3, 8, 1e3)));
	dvec3 tangent = d3(1, 2, 0), normal = d3(-2, 1, 5);
	CHECK_NEAR(d3_dot(tangent, normal), 0, 0);
	dvec3 tt = xform_vector(&t, tangent), nn = xform_normal(&t, normal);
	CHECK_NEAR(d3_dot(tt, nn), 0, 1e-12);
	for (int i = 0; i < 3; i++) {
		double r[3] = {0};
		for (int j = 0; j < 3; j++)
			for (int k = 0; k < 3; k++)
				r[j] += t.inv[i][k] * t.m[k][j];
		for (int j = 0; j < 3; j++)
			CHECK_NEAR(r[j], i == j ? 1.0 : 0.0, 1e-12);
	}
	double scale = 0;
	CHECK(!xform_is_similarity(&t, &scale), "non-uniform scale is not a similarity");
	xform sim = xform_then(xform_rotate(d3(10, 20, 30)), xform_translate(d3(1, 2, 3)));
	CHECK(xform_scale(d3(2.5, 2.5, 2.5), &s), "scale ok");
	sim = xform_then(sim, s);
	CHECK(xform_is_similarity(&sim, &scale), "rotation and uniform scale is a similarity");
	CHECK_NEAR(scale, 2.5, 1e-12);

	/* POV-Ray matrix: rows are images of x, y, z, then the translation. */
	double mv[12] = {0, 1, 0, -1, 0, 0, 0, 0, 1, 5, 6, 7};
	xform m;
	CHECK(xform_from_pov_matrix(mv, &m), "matrix ok");
	q = xform_point(&m, d3(1, 0, 0));
	CHECK(q.x == 5 && q.y == 7 && q.z == 7, "matrix of +x (%g %g %g)", q.x, q.y, q.z);
	double sing[12] = {1, 0, 0, 2, 0, 0, 0, 0, 1, 0, 0, 0};
	CHECK(!xform_from_pov_matrix(sing, &m), "singular matrix refused");
	xform r2 = xform_then(xform_rotate(d3(0, 45, 0)), xform_rotate(d3(0, 45, 0)));
	xform r90 = xform_rotate(d3(0, 90, 0));
	check_xform_close(&r2, &r90, 1e-15, "45+45");
	return check_done("test_vec");
}
