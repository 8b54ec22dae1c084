/* xform.c - affine transforms: construction, composition, application.
 * Each transform carries its inverse, built alongside rather than by inverting at use. */
#include "base/vec.h"

#include <string.h>

/* A determinant smaller than this relative to the product of the column norms is singular. */
#define XFORM_SINGULAR_EPS 1e-12

static void mat_identity(double m[3][4])
{
	memset(m, 0, sizeof(double[3][4]));
	m[0][0] = m[1][1] = m[2][2] = 1.0;
}

/* c = a * b as 4x4 affine matrices (the last row implicit 0 0 0 1). */
static void mat_mul(const double a[3][4], const double b[3][4], double c[3][4])
{
	double r[3][4];
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 4; j++) {
			double s = a[i][0] * b[0][j] + a[i][1] * b[1][j] + a[i][2] * b[2][j];
			r[i][j] = j == 3 ? s + a[i][3] : s;
		}
	memcpy(c, r, sizeof r);
}

static double mat_det(const double m[3][4])
{
	return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
	       m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
	       m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

/* Inverse of an affine matrix by the adjugate; false when singular. */
static bool mat_invert(const double m[3][4], double out[3][4])
{
	double det = mat_det(m);
	double scale = 1.0;
	for (int j = 0; j < 3; j++)
		scale *= sqrt(m[0][j] * m[0][j] + m[1][j] * m[1][j] + m[2][j] * m[2][j]);
	if (!(fabs(det) > XFORM_SINGULAR_EPS * scale) || !isfinite(det))
		return false;
	double r[3][4];
	double id = 1.0 / det;
	r[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) * id;
	r[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * id;
	r[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * id;
	r[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) * id;
	r[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * id;
	r[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * id;
	r[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) * id;
	r[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * id;
	r[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * id;
	for (int i = 0; i < 3; i++)
		r[i][3] = -(r[i][0] * m[0][3] + r[i][1] * m[1][3] + r[i][2] * m[2][3]);
	memcpy(out, r, sizeof r);
	return true;
}

xform xform_identity(void)
{
	xform t;
	mat_identity(t.m);
	mat_identity(t.inv);
	return t;
}

xform xform_translate(dvec3 v)
{
	xform t = xform_identity();
	t.m[0][3] = v.x, t.m[1][3] = v.y, t.m[2][3] = v.z;
	t.inv[0][3] = -v.x, t.inv[1][3] = -v.y, t.inv[2][3] = -v.z;
	return t;
}

bool xform_scale(dvec3 s, xform *out)
{
	*out = xform_identity();
	if (s.x == 0.0 || s.y == 0.0 || s.z == 0.0 || !isfinite(s.x) || !isfinite(s.y) || !isfinite(s.z))
		return false;
	out->m[0][0] = s.x, out->m[1][1] = s.y, out->m[2][2] = s.z;
	out->inv[0][0] = 1.0 / s.x, out->inv[1][1] = 1.0 / s.y, out->inv[2][2] = 1.0 / s.z;
	return true;
}

xform xform_rotate_axis(int axis, double deg)
{
	/* Exact values at multiples of 90 degrees keep axis-aligned scenes exact. */
	double q = deg / 90.0;
	double c, s;
	if (q == floor(q) && fabs(q) < 1e9) {
		static const double cs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
		long k = ((long)q % 4 + 4) % 4;
		c = cs[k][0], s = cs[k][1];
	} else {
		double rad = deg * (M_PI / 180.0);
		c = cos(rad), s = sin(rad);
	}
	int a = (axis + 1) % 3, b = (axis + 2) % 3;
	xform t = xform_identity();
	/* POV-Ray's rotation matrices, written for column vectors. */
	t.m[a][a] = c, t.m[a][b] = -s, t.m[b][a] = s, t.m[b][b] = c;
	t.inv[a][a] = c, t.inv[a][b] = s, t.inv[b][a] = -s, t.inv[b][b] = c;
	return t;
}

xform xform_rotate(dvec3 deg)
{
	xform t = xform_rotate_axis(0, deg.x);
	t = xform_then(t, xform_rotate_axis(1, deg.y));
	return xform_then(t, xform_rotate_axis(2, deg.z));
}

bool xform_from_pov_matrix(const double v[12], xform *out)
{
	*out = xform_identity();
	xform t;
	/* POV-Ray multiplies row vectors: x' = v00 x + v10 y + v20 z + v30. */
	for (int i = 0; i < 3; i++) {
		for (int j = 0; j < 3; j++)
			t.m[i][j] = v[j * 3 + i];
		t.m[i][3] = v[9 + i];
	}
	if (!mat_invert(t.m, t.inv))
		return false;
	*out = t;
	return true;
}

xform xform_then(xform a, xform b)
{
	xform r;
	mat_mul(b.m, a.m, r.m);
	mat_mul(a.inv, b.inv, r.inv);
	return r;
}

dvec3 xform_point(const xform *t, dvec3 p)
{
	const double(*m)[4] = t->m;
	return d3(m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
		  m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
		  m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]);
}

dvec3 xform_vector(const xform *t, dvec3 v)
{
	const double(*m)[4] = t->m;
	return d3(m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z,
		  m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
		  m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z);
}

dvec3 xform_normal(const xform *t, dvec3 n)
{
	const double(*m)[4] = t->inv;
	return d3(m[0][0] * n.x + m[1][0] * n.y + m[2][0] * n.z,
		  m[0][1] * n.x + m[1][1] * n.y + m[2][1] * n.z,
		  m[0][2] * n.x + m[1][2] * n.y + m[2][2] * n.z);
}

dvec3 xform_inv_point(const xform *t, dvec3 p)
{
	xform s = {.m = {{0}}};
	memcpy(s.m, t->inv, sizeof s.m);
	return xform_point(&s, p);
}

dvec3 xform_inv_vector(const xform *t, dvec3 v)
{
	xform s = {.m = {{0}}};
	memcpy(s.m, t->inv, sizeof s.m);
	return xform_vector(&s, v);
}

double xform_det(const xform *t) { return mat_det(t->m); }

bool xform_is_similarity(const xform *t, double *scale)
{
	/* M^T M must be s^2 I. */
	double g[3][3];
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			g[i][j] = t->m[0][i] * t->m[0][j] + t->m[1][i] * t->m[1][j] + t->m[2][i] * t->m[2][j];
	double s2 = (g[0][0] + g[1][1] + g[2][2]) / 3.0;
	const double tol = 1e-9 * s2;
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			if (fabs(g[i][j] - (i == j ? s2 : 0.0)) > tol)
				return false;
	if (scale)
		*scale = sqrt(s2);
	return s2 > 0.0;
}
