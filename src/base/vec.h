/* vec.h - vector and matrix math for circe, inline and in plain C (no GLM).
 * vec3 is single precision: geometry, rays and shading. dvec3 is double precision: the scene
 * language evaluates in it and the IR stores it. xform is an affine transform in double with its
 * inverse kept beside it, so normals and inverse rays cost no inversion at use. */
#ifndef CIRCE_BASE_VEC_H
#define CIRCE_BASE_VEC_H

#include <math.h>
#include <stdbool.h>

typedef struct vec2 { float x, y; } vec2;
typedef struct vec3 { float x, y, z; } vec3;
typedef struct dvec3 { double x, y, z; } dvec3;

static inline vec2 v2(float x, float y) { return (vec2){x, y}; }
static inline vec3 v3(float x, float y, float z) { return (vec3){x, y, z}; }
static inline vec3 v3s(float s) { return (vec3){s, s, s}; }
static inline vec3 v3_add(vec3 a, vec3 b) { return v3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline vec3 v3_sub(vec3 a, vec3 b) { return v3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline vec3 v3_mul(vec3 a, vec3 b) { return v3(a.x * b.x, a.y * b.y, a.z * b.z); }
static inline vec3 v3_div(vec3 a, vec3 b) { return v3(a.x / b.x, a.y / b.y, a.z / b.z); }
static inline vec3 v3_scale(vec3 a, float s) { return v3(a.x * s, a.y * s, a.z * s); }
static inline vec3 v3_neg(vec3 a) { return v3(-a.x, -a.y, -a.z); }
/* a + b * s */
static inline vec3 v3_madd(vec3 a, vec3 b, float s) { return v3(a.x + b.x * s, a.y + b.y * s, a.z + b.z * s); }
static inline float v3_dot(vec3 a, vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline vec3 v3_cross(vec3 a, vec3 b)
{
	return v3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline float v3_length2(vec3 a) { return v3_dot(a, a); }
static inline float v3_length(vec3 a) { return sqrtf(v3_dot(a, a)); }
/* Unit vector along a; the zero vector stays zero (callers test degenerate input themselves). */
static inline vec3 v3_normalize(vec3 a)
{
	float l = v3_length(a);
	return l > 0.0f ? v3_scale(a, 1.0f / l) : a;
}
static inline vec3 v3_min(vec3 a, vec3 b) { return v3(fminf(a.x, b.x), fminf(a.y, b.y), fminf(a.z, b.z)); }
static inline vec3 v3_max(vec3 a, vec3 b) { return v3(fmaxf(a.x, b.x), fmaxf(a.y, b.y), fmaxf(a.z, b.z)); }
static inline vec3 v3_abs(vec3 a) { return v3(fabsf(a.x), fabsf(a.y), fabsf(a.z)); }
static inline float v3_max_comp(vec3 a) { return fmaxf(a.x, fmaxf(a.y, a.z)); }
static inline float v3_min_comp(vec3 a) { return fminf(a.x, fminf(a.y, a.z)); }
static inline float v3_get(vec3 a, int axis) { return axis == 0 ? a.x : axis == 1 ? a.y : a.z; }
static inline bool v3_is_finite(vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }
static inline vec3 v3_lerp(vec3 a, vec3 b, float t) { return v3_madd(v3_scale(a, 1.0f - t), b, t); }
/* Rec. 709 luminance of a linear RGB colour. */
static inline float v3_luminance(vec3 c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

/* An orthonormal basis (b1, b2) completing unit n: Duff et al. 2017, "Building an Orthonormal
 * Basis, Revisited", JCGT 6(1), listing 3. Continuous except at n.z = -0 / +0. */
static inline void v3_basis(vec3 n, vec3 *b1, vec3 *b2)
{
	float sign = copysignf(1.0f, n.z);
	float a = -1.0f / (sign + n.z);
	float b = n.x * n.y * a;
	*b1 = v3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
	*b2 = v3(b, sign + n.y * n.y * a, -n.y);
}

static inline dvec3 d3(double x, double y, double z) { return (dvec3){x, y, z}; }
static inline dvec3 d3_add(dvec3 a, dvec3 b) { return d3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline dvec3 d3_sub(dvec3 a, dvec3 b) { return d3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline dvec3 d3_mul(dvec3 a, dvec3 b) { return d3(a.x * b.x, a.y * b.y, a.z * b.z); }
static inline dvec3 d3_scale(dvec3 a, double s) { return d3(a.x * s, a.y * s, a.z * s); }
static inline double d3_dot(dvec3 a, dvec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline dvec3 d3_cross(dvec3 a, dvec3 b)
{
	return d3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double d3_length(dvec3 a) { return sqrt(d3_dot(a, a)); }
static inline dvec3 d3_normalize(dvec3 a)
{
	double l = d3_length(a);
	return l > 0.0 ? d3_scale(a, 1.0 / l) : a;
}
static inline vec3 d3_to_v3(dvec3 a) { return v3((float)a.x, (float)a.y, (float)a.z); }
static inline dvec3 v3_to_d3(vec3 a) { return d3(a.x, a.y, a.z); }

/* Affine transform: p' = m[0..2][0..2] p + m[0..2][3]. inv is the inverse of m. */
typedef struct xform {
	double m[3][4];
	double inv[3][4];
} xform;

xform xform_identity(void);
xform xform_translate(dvec3 t);
/* Scale by s; returns false (and the identity) when a component is zero. */
bool xform_scale(dvec3 s, xform *out);
/* Rotation about one axis (0 x, 1 y, 2 z) by deg degrees, POV-Ray's left-handed sense. */
xform xform_rotate_axis(int axis, double deg);
/* POV-Ray's `rotate <a,b,c>`: about x, then y, then z. */
xform xform_rotate(dvec3 deg);
/* The 12-number POV-Ray `matrix`: rows of three, the last row the translation. Returns false
 * when the matrix is singular (|det| below a relative epsilon). */
bool xform_from_pov_matrix(const double v[12], xform *out);
/* a then b: the result applies a first. */
xform xform_then(xform a, xform b);
dvec3 xform_point(const xform *t, dvec3 p);
dvec3 xform_vector(const xform *t, dvec3 v);
/* Normals transform by the inverse transpose; the result is not normalized. */
dvec3 xform_normal(const xform *t, dvec3 n);
dvec3 xform_inv_point(const xform *t, dvec3 p);
dvec3 xform_inv_vector(const xform *t, dvec3 v);
double xform_det(const xform *t);
/* True when the linear part is a rotation times a uniform scale (within 1e-9 relative);
 * *scale receives that scale. Circles survive such transforms (DESIGN.md). */
bool xform_is_similarity(const xform *t, double *scale);

#endif
