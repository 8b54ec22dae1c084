/* func.c - POV-Ray's user-defined functions and splines: the compiler of `function` bodies into
 * postfix code, its evaluator, functions.inc's internal functions, `spline { }` and the calls of
 * both from expressions. POV-Ray 3.7's semantics; its sources (source/backend/vm/fncode.cpp,
 * fnintern.cpp, source/core/math/spline.cpp) were read to learn them, none copied. */
#include "lang/func.h"

#include "lang/parser.h"
#include "lang/pigment.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const double PI = 3.14159265358979323846;

/* ---- the code -------------------------------------------------------------------------- */

typedef enum fn_opcode {
	OP_CONST, OP_PARAM, OP_ADD, OP_SUB, OP_MUL, OP_DIV, OP_NEG, OP_NOT,
	OP_LT, OP_LE, OP_EQ, OP_NE, OP_GE, OP_GT, OP_AND, OP_OR, OP_COND,
	OP_FN1, /* which: the built-in's token */
	OP_FN2,
	OP_MIN, OP_MAX, /* n operands */
	OP_SELECT, /* n = 3 or 4 */
	OP_CALL, /* fn with n arguments; component comp of its result */
	/* what the peephole pass (fuse) makes of the common sequences, the same operations on the
	 * same values: a binary operator whose right operand is a constant k or a parameter which */
	OP_ADDK, OP_SUBK, OP_MULK, OP_DIVK,
	OP_ADDP, OP_SUBP, OP_MULP, OP_DIVP,
	OP_CALLI, /* an internal function fn (functions.inc's) of n arguments, its one value */
	OP_CALLI_XYZ, /* the same of the function's own x, y and z (its parameters 0, 1, 2) */
} fn_opcode;

struct lang_fn_op {
	fn_opcode op;
	int which; /* OP_FN1, OP_FN2: a lang_tok; OP_PARAM: the parameter */
	int n;
	int comp;
	double k; /* OP_CONST */
	const lang_function *fn; /* OP_CALL */
};

double lang_fn_float1(int which, double x)
{
	switch (which) {
	case LTK_KW_SIN: return sin(x);
	case LTK_KW_COS: return cos(x);
	case LTK_KW_TAN: return tan(x);
	case LTK_KW_ASIN: return asin(x);
	case LTK_KW_ACOS: return acos(x);
	case LTK_KW_ATAN: return atan(x);
	case LTK_KW_SINH: return sinh(x);
	case LTK_KW_COSH: return cosh(x);
	case LTK_KW_TANH: return tanh(x);
	case LTK_KW_ASINH: return asinh(x);
	case LTK_KW_ACOSH: return acosh(x);
	case LTK_KW_ATANH: return atanh(x);
	case LTK_KW_SQRT: return sqrt(x);
	case LTK_KW_EXP: return exp(x);
	case LTK_KW_LN: return log(x);
	case LTK_KW_LOG: return log10(x); /* POV-Ray's log is base 10 */
	case LTK_KW_ABS: return fabs(x);
	case LTK_KW_FLOOR: return floor(x);
	case LTK_KW_CEIL: return ceil(x);
	case LTK_KW_INT: return trunc(x);
	case LTK_KW_RADIANS: return x * PI / 180.0;
	case LTK_KW_DEGREES: return x * 180.0 / PI;
	case LANG_FN_SQR: return x * x;
	default: return NAN;
	}
}

double lang_fn_float2(int which, double x, double y)
{
	switch (which) {
	case LTK_KW_ATAN2: return atan2(x, y);
	case LTK_KW_POW: return pow(x, y);
	case LTK_KW_MOD: return fmod(x, y);
	case LTK_KW_DIV: return trunc(x / y);
	default: return NAN;
	}
}

/* Runs f's code; the stack depth was bounded by the compiler. */
static bool run_code(const lang_function *f, const double *args, double *out, const lang_function **failed)
{
	double st[LANG_FN_MAX_STACK];
	int sp = 0;
	for (int i = 0; i < f->n_code; i++) {
		const lang_fn_op *o = &f->code[i];
		switch (o->op) {
		case OP_CONST: st[sp++] = o->k; break;
		case OP_PARAM: st[sp++] = args[o->which]; break;
		case OP_NEG: st[sp - 1] = -st[sp - 1]; break;
		case OP_NOT: st[sp - 1] = st[sp - 1] == 0.0; break;
		case OP_FN1: st[sp - 1] = lang_fn_float1(o->which, st[sp - 1]); break;
		case OP_FN2: sp--, st[sp - 1] = lang_fn_float2(o->which, st[sp - 1], st[sp]); break;
		case OP_COND: sp -= 2, st[sp - 1] = st[sp - 1] != 0.0 ? st[sp] : st[sp + 1]; break;
		case OP_MIN:
		case OP_MAX: {
			double r = st[sp - o->n];
			for (int k = sp - o->n + 1; k < sp; k++)
				r = o->op == OP_MIN ? fmin(r, st[k]) : fmax(r, st[k]);
			sp -= o->n - 1, st[sp - 1] = r;
			break;
		}
		case OP_SELECT: { /* B when A < 0, else C; with D: B, C, D as A < 0, = 0, > 0 */
			double *a = &st[sp - o->n];
			double r = a[0] < 0 ? a[1] : o->n == 3 ? a[2] : a[0] == 0 ? a[2] : a[3];
			sp -= o->n - 1, st[sp - 1] = r;
			break;
		}
		case OP_CALL: {
			double r[LANG_FN_MAX_OUT];
			if (!lang_fn_eval(o->fn, &st[sp - o->n], r, failed))
				return false;
			sp -= o->n;
			st[sp++] = o->comp == LANG_FN_GRAY ? 0.297 * r[0] + 0.589 * r[1] + 0.114 * r[2]
				   : o->comp == LANG_FN_HF ? (r[0] + r[1] / 255.0) * 0.996093
							   : r[o->comp];
			break;
		}
		/* the binary operators, each its own case: one dispatch an instruction */
#define BINARY(OP, EXPR)                                                                                               \
	case OP: {                                                                                                     \
		double a = st[sp - 2], b = st[sp - 1];                                                                 \
		sp--, st[sp - 1] = (EXPR);                                                                             \
		break;                                                                                                 \
	}
		BINARY(OP_ADD, a + b)
		BINARY(OP_SUB, a - b)
		BINARY(OP_MUL, a * b)
		BINARY(OP_DIV, a / b)
		BINARY(OP_LT, a < b)
		BINARY(OP_LE, a <= b)
		BINARY(OP_EQ, a == b)
		BINARY(OP_NE, a != b)
		BINARY(OP_GE, a >= b)
		BINARY(OP_GT, a > b)
		BINARY(OP_AND, a != 0.0 && b != 0.0)
		BINARY(OP_OR, a != 0.0 || b != 0.0)
#undef BINARY
		case OP_ADDK: st[sp - 1] = st[sp - 1] + o->k; break;
		case OP_SUBK: st[sp - 1] = st[sp - 1] - o->k; break;
		case OP_MULK: st[sp - 1] = st[sp - 1] * o->k; break;
		case OP_DIVK: st[sp - 1] = st[sp - 1] / o->k; break;
		case OP_ADDP: st[sp - 1] = st[sp - 1] + args[o->which]; break;
		case OP_SUBP: st[sp - 1] = st[sp - 1] - args[o->which]; break;
		case OP_MULP: st[sp - 1] = st[sp - 1] * args[o->which]; break;
		case OP_DIVP: st[sp - 1] = st[sp - 1] / args[o->which]; break;
		case OP_CALLI: {
			double r = o->fn->impl(&st[sp - o->n]);
			sp -= o->n, st[sp++] = r;
			break;
		}
		case OP_CALLI_XYZ: st[sp++] = o->fn->impl(args); break;
		}
	}
	out[0] = st[0];
	return true;
}

bool lang_fn_eval(const lang_function *f, const double *args, double *out, const lang_function **failed)
{
	switch (f->kind) {
	case LANG_FN_CODE: return run_code(f, args, out, failed);
	case LANG_FN_INTERNAL:
		out[0] = f->impl(args);
		return true;
	case LANG_FN_TRANSFORM: {
		dvec3 q = xform_point(f->xf, d3(args[0], args[1], args[2]));
		out[0] = q.x, out[1] = q.y, out[2] = q.z;
		return true;
	}
	case LANG_FN_SPLINE: lang_spline_eval(f->spline, args[0], out); return true;
	case LANG_FN_PATTERN: /* fnintern.cpp's f_pattern: Warp_EPoint, then Evaluate_TPat */
		if (!f->pattern)
			break;
		out[0] = pattern_value(f->pattern, &f->pattern->nodes[f->pattern_root], d3(args[0], args[1], args[2]));
		return true;
	case LANG_FN_PIGMENT: { /* f_pigment: Compute_Pigment's rgbft */
		float c[5];
		pattern_eval(f->pattern, f->pattern_root, d3(args[0], args[1], args[2]), 0.0, c);
		for (int k = 0; k < 5; k++)
			out[k] = c[k];
		return true;
	}
	}
	*failed = f;
	return false;
}

bool lang_fn_same(const lang_function *a, const lang_function *b)
{
	if (a == b)
		return true;
	if (!a || !b || a->kind != b->kind || a->n_params != b->n_params || a->n_out != b->n_out)
		return false;
	switch (a->kind) {
	case LANG_FN_CODE:
		if (a->n_code != b->n_code)
			return false;
		for (int i = 0; i < a->n_code; i++) {
			const lang_fn_op *x = &a->code[i], *y = &b->code[i];
			if (x->op != y->op || x->which != y->which || x->n != y->n || x->comp != y->comp ||
			    memcmp(&x->k, &y->k, sizeof x->k) != 0 || !lang_fn_same(x->fn, y->fn))
				return false;
		}
		return true;
	case LANG_FN_INTERNAL: return a->internal == b->internal && a->impl == b->impl;
	default: return false; /* a transform, spline or pattern: only itself (a == b above) */
	}
}

/* ---- functions.inc's internal functions --------------------------------------------------- */

/* The arguments: x, y, z, then the function's own parameters P0, P1, ... (fnintern.cpp's PARAM). */
#define X a[0]
#define Y a[1]
#define Z a[2]
#define P(i) a[3 + (i)]

static double clamp10(double r) { return fmin(10.0, fmax(r, -10.0)); } /* POV-Ray's field clamp */

static double f_ellipsoid(const double *a) { return sqrt(X * X * P(0) * P(0) + Y * Y * P(1) * P(1) + Z * Z * P(2) * P(2)); }
static double f_heart(const double *a)
{
	double x2 = X * X, y2 = Y * Y, z2 = Z * Z, q = 2 * x2 + y2 + z2 - 1;
	return clamp10(P(0) * -(q * q * q - 0.1 * x2 * z2 * Z - y2 * z2 * Z));
}
static double f_paraboloid(const double *a) { return clamp10(P(0) * -(X * X - Y + Z * Z)); }
static double f_ph(const double *a) { return atan2(sqrt(X * X + Z * Z), Y); }
static double f_quartic_cylinder(const double *a)
{
	double s = X * X + Z * Z, b = P(2) * P(2);
	return clamp10(P(0) * -(s * Y * Y + b * s - b * P(1) * P(1)));
}
static double f_r(const double *a) { return sqrt(X * X + Y * Y + Z * Z); }
/* A box of half sizes P1..P3 with edges rounded by radius P0, as a distance less 1e-6 (POV-Ray's). */
static double f_rounded_box(const double *a)
{
	double d[3];
	for (int i = 0; i < 3; i++) {
		double inner = P(i + 1) - P(0), c = a[i];
		double out_hi = c < inner ? 0 : c - inner, out_lo = c > -inner ? 0 : -inner - c;
		d[i] = fmax(out_lo, out_hi);
	}
	return -P(0) + sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - 1e-6;
}
static double f_sphere(const double *a) { return -P(0) + sqrt(X * X + Y * Y + Z * Z); }
/* POV-Ray's superellipsoid { <E, N> } as a field: P0 east-west, P1 north-south exponents. */
static double f_superellipsoid(const double *a)
{
	double e = P(0), n = P(1);
	double xy = pow(pow(fabs(X), 2 / e) + pow(fabs(Y), 2 / e), e / n);
	return 1 - pow(xy + pow(fabs(Z), 2 / n), n * 0.5);
}
/* POV-Ray's Noise at the point, in [0, 1] (portablenoise.cpp: its range-corrected generator's
 * value clamped to [0, 1], mean about 0.5): the noise of the noise patterns (scene/pattern.h's
 * pattern_noise, bozo's value), so f_noise3d, functions.inc's f_bozo and a bozo pigment agree. */
static double f_noise3d(const double *a) { return pattern_noise(d3(X, Y, Z)); }
static double f_th(const double *a) { return atan2(X, Z); }
static double f_torus(const double *a)
{
	double r = sqrt(X * X + Z * Z) - P(0);
	return -P(1) + sqrt(r * r + Y * Y);
}
static double f_torus2(const double *a)
{
	double x2 = X * X, y2 = Y * Y, z2 = Z * Z, R = P(1) * P(1), r = P(2) * P(2);
	double q = x2 * x2 + y2 * y2 + z2 * z2 + 2 * x2 * y2 + 2 * x2 * z2 + 2 * y2 * z2 - 2 * (R + r) * x2 + 2 * (R - r) * y2 -
		   2 * (R + r) * z2 + (R - r) * (R - r);
	return clamp10(P(0) * -q);
}
#undef X
#undef Y
#undef Z
#undef P

/* POV-Ray 3.7's internal functions by number (fnintern.cpp's POVFPU_TrapTable: names and
 * parameter counts, the counts including x, y and z), with circe's implementation where it has one. */
static const struct internal_fn {
	const char *name;
	int n_params;
	double (*impl)(const double *args);
} internals[] = {
	{"f_algbr_cyl1", 8, NULL}, {"f_algbr_cyl2", 8, NULL}, {"f_algbr_cyl3", 8, NULL}, {"f_algbr_cyl4", 8, NULL},
	{"f_bicorn", 5, NULL}, {"f_bifolia", 5, NULL}, {"f_blob", 8, NULL}, {"f_blob2", 7, NULL},
	{"f_boy_surface", 5, NULL}, {"f_comma", 4, NULL}, {"f_cross_ellipsoids", 7, NULL},
	{"f_crossed_trough", 4, NULL}, {"f_cubic_saddle", 4, NULL}, {"f_cushion", 4, NULL},
	{"f_devils_curve", 4, NULL}, {"f_devils_curve_2d", 9, NULL}, {"f_dupin_cyclid", 9, NULL},
	{"f_ellipsoid", 6, f_ellipsoid}, {"f_enneper", 4, NULL}, {"f_flange_cover", 7, NULL},
	{"f_folium_surface", 6, NULL}, {"f_folium_surface_2d", 9, NULL}, {"f_glob", 4, NULL},
	{"f_heart", 4, f_heart}, {"f_helical_torus", 13, NULL}, {"f_helix1", 10, NULL}, {"f_helix2", 10, NULL},
	{"f_hex_x", 4, NULL}, {"f_hex_y", 4, NULL}, {"f_hetero_mf", 9, NULL}, {"f_hunt_surface", 4, NULL},
	{"f_hyperbolic_torus", 6, NULL}, {"f_isect_ellipsoids", 7, NULL}, {"f_kampyle_of_eudoxus", 6, NULL},
	{"f_kampyle_of_eudoxus_2d", 9, NULL}, {"f_klein_bottle", 4, NULL}, {"f_kummer_surface_v1", 4, NULL},
	{"f_kummer_surface_v2", 7, NULL}, {"f_lemniscate_of_gerono", 4, NULL},
	{"f_lemniscate_of_gerono_2d", 9, NULL}, {"f_mesh1", 8, NULL}, {"f_mitre", 4, NULL},
	{"f_nodal_cubic", 4, NULL}, {"f_odd", 4, NULL}, {"f_ovals_of_cassini", 7, NULL},
	{"f_paraboloid", 4, f_paraboloid}, {"f_parabolic_torus", 6, NULL}, {"f_ph", 3, f_ph}, {"f_pillow", 4, NULL},
	{"f_piriform", 4, NULL}, {"f_piriform_2d", 10, NULL}, {"f_poly4", 8, NULL}, {"f_polytubes", 9, NULL},
	{"f_quantum", 4, NULL}, {"f_quartic_paraboloid", 4, NULL}, {"f_quartic_saddle", 4, NULL},
	{"f_quartic_cylinder", 6, f_quartic_cylinder}, {"f_r", 3, f_r}, {"f_ridge", 9, NULL},
	{"f_ridged_mf", 9, NULL}, {"f_rounded_box", 7, f_rounded_box}, {"f_sphere", 4, f_sphere},
	{"f_spikes", 8, NULL}, {"f_spikes_2d", 7, NULL}, {"f_spiral", 9, NULL}, {"f_steiners_roman", 4, NULL},
	{"f_strophoid", 7, NULL}, {"f_strophoid_2d", 10, NULL}, {"f_superellipsoid", 5, f_superellipsoid},
	{"f_th", 3, f_th}, {"f_torus", 5, f_torus}, {"f_torus2", 6, f_torus2}, {"f_torus_gumdrop", 4, NULL},
	{"f_umbrella", 4, NULL}, {"f_witch_of_agnesi", 5, NULL}, {"f_witch_of_agnesi_2d", 9, NULL},
	{"f_noise3d", 3, f_noise3d}, {"f_pattern", 3, NULL}, {"f_noise_generator", 4, NULL},
};

const char *lang_fn_internal_name(int n, int *n_params)
{
	if (n < 0 || (size_t)n >= sizeof internals / sizeof internals[0])
		return NULL;
	*n_params = internals[n].n_params;
	return internals[n].name;
}

double (*lang_fn_internal_impl(int n))(const double *args)
{
	if (n < 0 || (size_t)n >= sizeof internals / sizeof internals[0])
		return NULL;
	return internals[n].impl ? internals[n].impl : lang_fn_internal_more(n);
}

/* ---- splines ----------------------------------------------------------------------------- */

/* The first entry whose key is >= t; 0 when t is at or before the first key, n at or after the
 * last (spline.cpp's findt). */
static size_t spline_find(const lang_spline *s, double t)
{
	if (t <= s->e[0].t)
		return 0;
	if (t >= s->e[s->n - 1].t)
		return s->n;
	size_t lo = 0, hi = s->n - 1; /* e[lo].t < t <= e[hi].t */
	while (hi - lo > 1) {
		size_t mid = lo + (hi - lo) / 2;
		if (t > s->e[mid].t)
			lo = mid;
		else
			hi = mid;
	}
	return hi;
}

static double lerp_at(const lang_spline_entry *a, const lang_spline_entry *b, int k, double t)
{
	return a->v[k] + (t - a->t) * (b->v[k] - a->v[k]) / (b->t - a->t);
}

/* The parabola through entries c-1, c, c+1 at t (Lagrange's form). */
static double parabola_at(const lang_spline_entry *e, size_t c, int k, double t)
{
	const lang_spline_entry *a = &e[c - 1], *b = &e[c], *d = &e[c + 1];
	return a->v[k] * (t - b->t) * (t - d->t) / ((a->t - b->t) * (a->t - d->t)) +
	       b->v[k] * (t - a->t) * (t - d->t) / ((b->t - a->t) * (b->t - d->t)) +
	       d->v[k] * (t - a->t) * (t - b->t) / ((d->t - a->t) * (d->t - b->t));
}

/* The cubic of segment [i, i+1] with second derivatives d2 at its ends (the natural spline's
 * piece, in Taylor form about t_i). */
static double natural_at(const lang_spline_entry *e, size_t i, int k, double t)
{
	double h = e[i + 1].t - e[i].t, u = t - e[i].t, m0 = e[i].d2[k], m1 = e[i + 1].d2[k];
	double slope = (e[i + 1].v[k] - e[i].v[k]) / h - h * (m1 + 2 * m0) / 6;
	return e[i].v[k] + u * (slope + u * (m0 / 2 + u * (m1 - m0) / (6 * h)));
}

/* Segment [i, i+1] as a cubic Hermite curve whose tangents are the mean of the chord slopes on
 * either side scaled by the segment's length (POV-Ray's cubic_spline, a non-uniform Catmull-Rom). */
static double catmull_rom_at(const lang_spline_entry *e, size_t i, int k, double t)
{
	double dt = e[i + 1].t - e[i].t, u = (t - e[i].t) / dt;
	double s0 = (e[i].v[k] - e[i - 1].v[k]) / (e[i].t - e[i - 1].t);
	double s1 = (e[i + 1].v[k] - e[i].v[k]) / dt;
	double s2 = (e[i + 2].v[k] - e[i + 1].v[k]) / (e[i + 2].t - e[i + 1].t);
	double m0 = (s0 + s1) / 2 * dt, m1 = (s1 + s2) / 2 * dt;
	double u2 = u * u, u3 = u2 * u;
	return e[i].v[k] * (2 * u3 - 3 * u2 + 1) + e[i + 1].v[k] * (3 * u2 - 2 * u3) + m0 * (u3 - 2 * u2 + u) +
	       m1 * (u3 - u2);
}

void lang_spline_eval(const lang_spline *s, double t, double *out)
{
	const lang_spline_entry *e = s->e;
	size_t n = s->n, i = spline_find(s, t);
	for (int k = 0; k < s->terms; k++) {
		double r;
		if (n == 1)
			r = e[0].v[k];
		else if (s->kind == LANG_SPLINE_CUBIC) /* defined between the second and next-to-last keys */
			r = n == 2 ? (e[0].v[k] + e[1].v[k]) / 2 : i < 2 ? e[1].v[k] : i >= n - 1 ? e[n - 2].v[k]
				: catmull_rom_at(e, i - 1, k, t);
		else if (i == 0)
			r = e[0].v[k];
		else if (i >= n)
			r = e[n - 1].v[k];
		else if (s->kind == LANG_SPLINE_NATURAL)
			r = natural_at(e, i - 1, k, t);
		else if (s->kind == LANG_SPLINE_QUADRATIC && n > 2) /* the first segment shares the second's parabola */
			r = parabola_at(e, i > 1 ? i - 1 : 1, k, t);
		else
			r = lerp_at(&e[i - 1], &e[i], k, t);
		out[k] = r;
	}
}

void lang_spline_insert(lang_spline_entry *e, size_t *n, double t, const double *v)
{
	size_t i = 0;
	while (i < *n && e[i].t < t)
		i++;
	if (i == *n || e[i].t != t) {
		memmove(&e[i + 1], &e[i], (*n - i) * sizeof *e);
		(*n)++;
	}
	memset(&e[i], 0, sizeof e[i]);
	e[i].t = t;
	memcpy(e[i].v, v, sizeof e[i].v);
}

/* The second derivatives M of the natural cubic spline (M = 0 at both ends): the tridiagonal
 * system h[i-1] M[i-1] + 2 (h[i-1] + h[i]) M[i] + h[i] M[i+1] = 6 (b[i] - b[i-1]), b the chord
 * slopes, solved by forward elimination and back substitution. */
void lang_spline_natural_coeffs(lang_spline *s)
{
	size_t n = s->n;
	lang_spline_entry *e = s->e;
	for (size_t i = 0; i < n; i++)
		memset(e[i].d2, 0, sizeof e[i].d2);
	if (n < 3)
		return;
	double *diag = malloc(2 * n * sizeof *diag);
	if (!diag)
		return; /* no memory: the spline stays piecewise linear */
	double *rhs = diag + n;
	for (int k = 0; k < LANG_SPLINE_TERMS; k++) {
		for (size_t i = 1; i + 1 < n; i++) {
			double h0 = e[i].t - e[i - 1].t, h1 = e[i + 1].t - e[i].t;
			double r = 6 * ((e[i + 1].v[k] - e[i].v[k]) / h1 - (e[i].v[k] - e[i - 1].v[k]) / h0);
			diag[i] = 2 * (h0 + h1);
			if (i > 1) {
				diag[i] -= h0 * h0 / diag[i - 1];
				r -= h0 * rhs[i - 1] / diag[i - 1];
			}
			rhs[i] = r;
		}
		for (size_t i = n - 2; i > 0; i--)
			e[i].d2[k] = (rhs[i] - (e[i + 1].t - e[i].t) * e[i + 1].d2[k]) / diag[i];
	}
	free(diag);
}

/* ---- the compiler ------------------------------------------------------------------------ */

typedef struct compiler {
	parser *p;
	lang_function *f;
	const lang_token *self; /* the name being declared: calling it is recursion */
	bool defaults; /* function { } without a parameter list: x, y, z (u, v the same as x, y) */
	int call_depth; /* the deepest function called so far */
	vecbuf code; /* lang_fn_op */
	int depth, max_depth; /* the stack's, as the code is emitted */
	diag_loc open; /* the body's '{' */
} compiler;

static bool cexpr(compiler *c);

static bool emit(compiler *c, lang_fn_op o, int pushes, int pops)
{
	c->depth += pushes - pops;
	if (c->depth > c->max_depth)
		c->max_depth = c->depth;
	if (c->depth > LANG_FN_MAX_STACK)
		return lang_error(c->p, lang_peek(c->p)->loc, "function too deeply nested (limit is %d values on its stack)",
				  LANG_FN_MAX_STACK);
	if (!vecbuf_push(&c->code, &o))
		return lang_error(c->p, lang_peek(c->p)->loc, "out of memory");
	return true;
}

static bool emit_op(compiler *c, fn_opcode op, int pops) { return emit(c, (lang_fn_op){.op = op}, 1, pops); }

static bool emit_const(compiler *c, double k) { return emit(c, (lang_fn_op){.op = OP_CONST, .k = k}, 1, 0); }

static bool is_word_token(const lang_token *t)
{
	return t->kind == LTK_IDENT || t->kind == LTK_UNSUPPORTED || (t->kind >= LANG_FIRST_KEYWORD && t->kind < LANG_FIRST_DIRECTIVE);
}

static bool token_is(const lang_token *t, const char *s) { return lang_token_is(t, s); }

/* The parameter a word names, or -1. */
static int param_of(const compiler *c, const lang_token *t)
{
	if (!is_word_token(t))
		return -1;
	for (int i = 0; i < c->f->n_params; i++)
		if (token_is(t, c->f->params[i]))
			return i;
	if (c->defaults && (token_is(t, "u") || token_is(t, "v")))
		return token_is(t, "u") ? 0 : 1;
	return -1;
}

/* The component a member name selects (.x .u .red 0, ... .transmit 4, .gray .grey LANG_FN_GRAY,
 * .hf LANG_FN_HF: fncode.cpp's compile_member), or -1. */
static int component_of(const lang_token *t)
{
	if (token_is(t, "gray") || token_is(t, "grey"))
		return LANG_FN_GRAY;
	if (token_is(t, "hf"))
		return LANG_FN_HF;
	static const char *const names[][3] = {{"x", "u", "red"}, {"y", "v", "green"}, {"z", "blue", "blue"},
					      {"t", "filter", "filter"}, {"transmit", "transmit", "transmit"}};
	for (int i = 0; i < 5; i++)
		for (int j = 0; j < 3; j++)
			if (token_is(t, names[i][j]))
				return i;
	return -1;
}

/* The built-ins a function body may call: one float (op FN1), two (FN2), N (min, max), select. */
static int builtin_arity(const lang_token *t)
{
	switch (t->kind) {
	case LTK_KW_SIN: case LTK_KW_COS: case LTK_KW_TAN: case LTK_KW_ASIN: case LTK_KW_ACOS: case LTK_KW_ATAN:
	case LTK_KW_SINH: case LTK_KW_COSH: case LTK_KW_TANH: case LTK_KW_ASINH: case LTK_KW_ACOSH: case LTK_KW_ATANH:
	case LTK_KW_SQRT: case LTK_KW_EXP: case LTK_KW_LN: case LTK_KW_LOG: case LTK_KW_ABS: case LTK_KW_FLOOR:
	case LTK_KW_CEIL: case LTK_KW_INT: case LTK_KW_RADIANS: case LTK_KW_DEGREES: return 1;
	case LTK_KW_ATAN2: case LTK_KW_POW: case LTK_KW_MOD: case LTK_KW_DIV: return 2;
	case LTK_KW_MIN: case LTK_KW_MAX: case LTK_KW_SELECT: return -1;
	default: return t->kind == LTK_UNSUPPORTED && token_is(t, "sqr") ? 1 : 0; /* sqr: POV-Ray's, in functions only */
	}
}

/* "(" expression { "," expression } ")": the count of arguments compiled onto the stack. */
static bool cargs(compiler *c, const char *fname, int *n)
{
	char ctx[96];
	snprintf(ctx, sizeof ctx, "after '%s'", fname);
	if (!lang_expect(c->p, LTK_LPAREN, ctx))
		return false;
	*n = 0;
	if (lang_peek(c->p)->kind != LTK_RPAREN)
		do {
			if (*n == LANG_FN_MAX_PARAMS)
				return lang_error(c->p, lang_peek(c->p)->loc, "too many arguments to '%s' (limit is %d)", fname,
						  LANG_FN_MAX_PARAMS);
			if (!cexpr(c))
				return false;
			(*n)++;
		} while (lang_accept(c->p, LTK_COMMA));
	snprintf(ctx, sizeof ctx, "to close the arguments of '%s'", fname);
	return lang_expect(c->p, LTK_RPAREN, ctx);
}

static bool cbuiltin(compiler *c, int arity)
{
	lang_token name = *lang_advance(c->p);
	char fname[32];
	snprintf(fname, sizeof fname, "%.*s", (int)name.len, name.text);
	int n;
	if (!cargs(c, fname, &n))
		return false;
	bool sel = name.kind == LTK_KW_SELECT;
	int lo = arity > 0 ? arity : sel ? 3 : 2, hi = arity > 0 ? arity : sel ? 4 : -1;
	if (n < lo || (hi >= 0 && n > hi))
		return lang_wrong_count(c->p, name.loc, fname, lo, hi, n);
	lang_fn_op o = {.op = arity == 1 ? OP_FN1 : arity == 2 ? OP_FN2 : sel ? OP_SELECT
			: name.kind == LTK_KW_MIN ? OP_MIN : OP_MAX, .which = name.kind == LTK_UNSUPPORTED ? LANG_FN_SQR
			: (int)name.kind, .n = n};
	return emit(c, o, 1, n);
}

/* A call of a declared function: its arguments, then a component of a vector result (.x ...). */
static bool ccall(compiler *c, const lang_token *name, const lang_function *g)
{
	char fname[64];
	snprintf(fname, sizeof fname, "%.*s", (int)name->len, name->text);
	int n;
	if (!cargs(c, fname, &n))
		return false;
	if (n != g->n_params)
		return lang_wrong_count(c->p, name->loc, fname, g->n_params, g->n_params, n);
	int comp = 0;
	if (lang_peek(c->p)->kind == LTK_DOT) {
		lang_advance(c->p);
		lang_token *m = lang_peek(c->p);
		comp = component_of(m);
		int needs = comp == LANG_FN_GRAY ? 3 : comp == LANG_FN_HF ? 2 : comp + 1;
		if (comp < 0 || needs > g->n_out)
			return lang_error_found(c->p, "expected a component of the %d of '%s' after '.'", g->n_out, fname);
		lang_advance(c->p);
	} else if (g->n_out > 1) {
		return lang_error(c->p, name->loc, "'%s' gives a vector of %d components: choose one (.x, .y, ...)", fname,
				  g->n_out);
	}
	if (g->call_depth >= LANG_FN_MAX_CALL_DEPTH)
		return lang_error(c->p, name->loc, "functions calling functions nested too deeply calling '%s' (limit is %d)",
				  fname, LANG_FN_MAX_CALL_DEPTH);
	if (g->call_depth > c->call_depth)
		c->call_depth = g->call_depth;
	return emit(c, (lang_fn_op){.op = OP_CALL, .fn = g, .n = n, .comp = comp}, 1, n);
}

/* A declared name in a body: a function called, or a value of the time of the definition (a
 * float, a vector's or an array element's component) taken as a constant, as POV-Ray does. */
static bool cidentifier(compiler *c)
{
	lang_token name = *lang_peek(c->p);
	if (c->self && name.len == c->self->len && !memcmp(name.text, c->self->text, name.len))
		return lang_error(c->p, name.loc, "function '%.*s' calls itself: POV-Ray's functions cannot be recursive",
				  (int)name.len, name.text);
	const symbol *s = lang_lookup(c->p, name.text, name.len);
	if (!s)
		return lang_error(c->p, name.loc, "undeclared identifier '%.*s' in a function", (int)name.len, name.text);
	if (s->val.kind == VAL_FUNCTION) {
		lang_advance(c->p);
		return ccall(c, &name, s->val.fn);
	}
	if (s->val.kind == VAL_SPLINE) /* POV-Ray's function parser refuses it too */
		return lang_error(c->p, name.loc, "'%.*s' is a spline: a function calls it through a function { spline { %.*s } }",
				  (int)name.len, name.text, (int)name.len, name.text);
	value v;
	if (!lang_primary(c->p, &v))
		return false;
	while (lang_peek(c->p)->kind == LTK_DOT)
		if (!lang_member(c->p, &v))
			return false;
	if (v.kind != VAL_FLOAT)
		return lang_error(c->p, name.loc, "'%.*s' is %s: a function's values are floats", (int)name.len, name.text,
				  lang_value_kind_name(&v));
	return emit_const(c, v.v[0]);
}

/* primary = number | parameter | identifier | builtin "(" args ")" | "(" expression ")" | "pi"
 *         | "clock" | "true" | ... */
static bool cprimary(compiler *c)
{
	lang_token *t = lang_peek(c->p);
	int pi = param_of(c, t);
	if (pi >= 0) {
		lang_advance(c->p);
		return emit(c, (lang_fn_op){.op = OP_PARAM, .which = pi}, 1, 0);
	}
	int arity = builtin_arity(t);
	if (arity != 0)
		return cbuiltin(c, arity);
	switch (t->kind) {
	case LTK_NUMBER: {
		double k = t->number;
		lang_advance(c->p);
		return emit_const(c, k);
	}
	case LTK_LPAREN:
		lang_advance(c->p);
		return cexpr(c) && lang_expect(c->p, LTK_RPAREN, "to close '('");
	case LTK_IDENT: return cidentifier(c);
	case LTK_KW_PI: case LTK_KW_CLOCK: case LTK_KW_TRUE: case LTK_KW_YES: case LTK_KW_ON: case LTK_KW_FALSE:
	case LTK_KW_NO: case LTK_KW_OFF: case LTK_KW_VERSION: case LTK_KW_CLOCK_ON: {
		value v;
		if (!lang_primary(c->p, &v))
			return false;
		return emit_const(c, v.v[0]);
	}
	default:
		if (t->kind == LTK_UNSUPPORTED)
			return lang_error(c->p, t->loc, "'%.*s' is not supported by circe", (int)t->len, t->text);
		return lang_error_found(c->p, "expected a float expression in the function");
	}
}

/* unary = ( "-" | "+" | "!" ) unary | primary */
static bool cunary(compiler *c)
{
	lang_tok k = lang_peek(c->p)->kind;
	if (k != LTK_MINUS && k != LTK_PLUS && k != LTK_BANG)
		return cprimary(c);
	lang_token op = *lang_advance(c->p);
	if (!lang_enter(c->p, op.loc))
		return false;
	bool ok = cunary(c);
	lang_leave(c->p);
	if (!ok || k == LTK_PLUS)
		return ok;
	return emit_op(c, k == LTK_MINUS ? OP_NEG : OP_NOT, 1);
}

/* The binary operators by precedence level, lowest first (POV-Ray's expression grammar). */
static const struct binop {
	int level;
	lang_tok tok;
	fn_opcode op;
} binops[] = {
	{0, LTK_BAR, OP_OR},  {1, LTK_AMP, OP_AND}, {2, LTK_LT, OP_LT},	  {2, LTK_LE, OP_LE},	 {2, LTK_EQ, OP_EQ},
	{2, LTK_NE, OP_NE},   {2, LTK_GE, OP_GE},   {2, LTK_GT, OP_GT},	  {3, LTK_PLUS, OP_ADD}, {3, LTK_MINUS, OP_SUB},
	{4, LTK_STAR, OP_MUL}, {4, LTK_SLASH, OP_DIV},
};

static const struct binop *binop_of(lang_tok k, int level)
{
	for (size_t i = 0; i < sizeof binops / sizeof binops[0]; i++)
		if (binops[i].tok == k && binops[i].level == level)
			return &binops[i];
	return NULL;
}

/* level L = level L+1 { op_L level L+1 }; level 5 is unary. */
static bool cbinary(compiler *c, int level)
{
	if (level == 5)
		return cunary(c);
	if (!cbinary(c, level + 1))
		return false;
	for (;;) {
		const struct binop *b = binop_of(lang_peek(c->p)->kind, level);
		if (!b)
			return true;
		lang_advance(c->p);
		if (!cbinary(c, level + 1) || !emit_op(c, b->op, 2))
			return false;
	}
}

/* expression = or [ "?" expression ":" expression ] */
static bool cexpr(compiler *c)
{
	if (!lang_enter(c->p, lang_peek(c->p)->loc))
		return false;
	bool ok = cbinary(c, 0);
	if (ok && lang_accept(c->p, LTK_QUESTION))
		ok = cexpr(c) && lang_expect(c->p, LTK_COLON, "in the function's '? :'") && cexpr(c) && emit_op(c, OP_COND, 3);
	lang_leave(c->p);
	return ok;
}

/* ---- function and spline values ------------------------------------------------------------ */

static lang_function *new_function(parser *p, const lang_token *name, lang_fn_kind kind)
{
	lang_function *f = arena_zalloc(&p->sc->arena, 1, sizeof *f);
	if (!f)
		return NULL;
	f->kind = kind;
	f->n_out = 1;
	f->call_depth = 1;
	f->name = name ? arena_strndup(&p->sc->arena, name->text, name->len) : "function";
	return f;
}

/* params = "(" identifier { "," identifier } ")"; any word may name a parameter (x, y, z, u, v
 * are keywords of circe). */
static bool params(parser *p, lang_function *f)
{
	lang_advance(p);
	do {
		lang_token *t = lang_peek(p);
		if (!is_word_token(t))
			return lang_error_found(p, "expected a parameter name in the function's list");
		if (f->n_params == LANG_FN_MAX_PARAMS)
			return lang_error(p, t->loc, "too many parameters (limit is %d)", LANG_FN_MAX_PARAMS);
		for (int i = 0; i < f->n_params; i++)
			if (token_is(t, f->params[i]))
				return lang_error(p, t->loc, "parameter '%.*s' named twice", (int)t->len, t->text);
		f->params[f->n_params++] = arena_strndup(&p->sc->arena, t->text, t->len);
		lang_advance(p);
	} while (lang_accept(p, LTK_COMMA));
	return lang_expect(p, LTK_RPAREN, "to close the function's parameters");
}

/* The peephole pass over code[0..*n) (in place): a constant or a parameter followed by + - * /
 * becomes one operation with its operand (OP_ADDK ... OP_DIVP), a call of an internal function
 * OP_CALLI, and of one of x, y, z given as they come OP_CALLI_XYZ, which reads them where they
 * are. The code has no jumps, so any instruction may be fused with the one before it; each
 * fused operation computes what the pair did, in the same order, to the same bits. */
static void fuse(lang_fn_op *code, size_t *n)
{
	size_t o = 0;
	for (size_t i = 0; i < *n; i++) {
		lang_fn_op x = code[i];
		lang_fn_op *last = o ? &code[o - 1] : NULL;
		int bin = x.op == OP_ADD ? 0 : x.op == OP_SUB ? 1 : x.op == OP_MUL ? 2 : x.op == OP_DIV ? 3 : -1;
		if (bin >= 0 && last && (last->op == OP_CONST || last->op == OP_PARAM)) {
			static const fn_opcode ks[4] = {OP_ADDK, OP_SUBK, OP_MULK, OP_DIVK}, ps[4] = {OP_ADDP, OP_SUBP, OP_MULP, OP_DIVP};
			last->op = last->op == OP_CONST ? ks[bin] : ps[bin];
			continue;
		}
		if (x.op == OP_CALL && x.fn->kind == LANG_FN_INTERNAL && x.comp == 0 && x.fn->impl) {
			bool xyz = x.n == 3 && x.fn->n_params == 3 && o >= 3;
			for (int a = 0; xyz && a < 3; a++)
				xyz = code[o - 3 + a].op == OP_PARAM && code[o - 3 + a].which == a;
			if (xyz) {
				o -= 3;
				code[o++] = (lang_fn_op){.op = OP_CALLI_XYZ, .fn = x.fn, .n = 3};
				continue;
			}
			x.op = OP_CALLI;
		}
		code[o++] = x;
	}
	*n = o;
}

/* The body's expression compiled into f's code. */
static bool code_body(parser *p, lang_function *f, const lang_token *self, bool defaults)
{
	compiler c = {.p = p, .f = f, .self = self, .defaults = defaults};
	vecbuf_init(&c.code, sizeof(lang_fn_op));
	bool saved = p->no_gt;
	p->no_gt = false;
	bool ok = cexpr(&c);
	p->no_gt = saved;
	if (ok)
		fuse(c.code.data, &c.code.len);
	lang_fn_op *code = ok ? arena_alloc(&p->sc->arena, c.code.len, sizeof *code, 16) : NULL;
	if (ok && !code)
		ok = lang_error(p, p->prev.loc, "out of memory");
	if (ok) {
		memcpy(code, c.code.data, c.code.len * sizeof *code);
		f->code = code;
		f->n_code = (int)c.code.len;
		f->call_depth = c.call_depth + 1;
	}
	vecbuf_free(&c.code);
	return ok;
}

/* internal = "internal" "(" int ")" */
static bool internal_body(parser *p, lang_function *f)
{
	lang_advance(p);
	long n;
	if (!lang_expect(p, LTK_LPAREN, "after 'internal'") || !lang_int(p, "as the internal function's number", 0, 1000, &n))
		return false;
	int np;
	if (!lang_fn_internal_name((int)n, &np))
		return lang_error(p, p->prev.loc, "'internal(%ld)' does not exist (POV-Ray 3.7's are 0 to %d)", n,
				  (int)(sizeof internals / sizeof internals[0]) - 1);
	f->kind = LANG_FN_INTERNAL;
	f->internal = (int)n;
	f->n_params = np;
	f->impl = lang_fn_internal_impl((int)n);
	assert(f->impl); /* every internal has one: test_func */
	return lang_expect(p, LTK_RPAREN, "to close 'internal ('");
}

/* The program of tree, copied into the scene's arena (released with it); NULL after reporting. */
static const pattern_prog *compile_tree(parser *p, const scene_pigment *tree, uint32_t *root)
{
	pattern_prog pp = {0}, *out = NULL;
	if (pattern_compile(&pp, tree, NULL, NULL, root, p->d)) {
		out = arena_zalloc(&p->sc->arena, 1, sizeof *out);
		pattern_node *nodes = out ? arena_alloc(&p->sc->arena, pp.n_nodes, sizeof *nodes, 16) : NULL;
		pattern_warp *warps = pp.n_warps ? arena_alloc(&p->sc->arena, pp.n_warps, sizeof *warps, 16) : NULL;
		pattern_entry *entries = pp.n_entries ? arena_alloc(&p->sc->arena, pp.n_entries, sizeof *entries, 16) : NULL;
		if (!nodes || (pp.n_warps && !warps) || (pp.n_entries && !entries)) {
			lang_error(p, tree->loc, "out of memory");
			out = NULL;
		} else {
			memcpy(nodes, pp.nodes, pp.n_nodes * sizeof *nodes);
			if (pp.n_warps)
				memcpy(warps, pp.warps, pp.n_warps * sizeof *warps);
			if (pp.n_entries)
				memcpy(entries, pp.entries, pp.n_entries * sizeof *entries);
			*out = (pattern_prog){nodes, pp.n_nodes, warps, pp.n_warps, entries, pp.n_entries};
		}
	} else {
		p->failed = true;
	}
	pattern_prog_free(&pp);
	return out;
}

/* pattern = "pattern" "{" pattern_body "}"; pigment = "pigment" "{" ... "}" as anywhere else:
 * the tree read by lang/pigment.c, compiled into the function's own pattern program
 * (scene/pattern.h), which lang_fn_eval runs at the point. */
static bool pattern_block(parser *p, lang_function *f, bool pigment)
{
	f->kind = pigment ? LANG_FN_PIGMENT : LANG_FN_PATTERN;
	f->n_params = 3;
	f->n_out = pigment ? 5 : 1;
	const scene_pigment *tree;
	if (pigment) {
		value v;
		bool handled;
		if (!lang_declare_block(p, &v, &handled))
			return false;
		if (!(tree = lang_pigment_tree(p, v.mat)))
			return false;
		if (tree->kind == SCENE_PAT_PLAIN && !v.mat->pigment) { /* a colour's filter and transmit too */
			scene_pigment *c = arena_zalloc(&p->sc->arena, 1, sizeof *c);
			if (!c)
				return lang_error(p, tree->loc, "out of memory");
			*c = *tree;
			c->color[3] = v.mat->filter, c->color[4] = v.mat->transmit;
			tree = c;
		}
	} else {
		lang_token kw = *lang_advance(p);
		diag_loc open = lang_peek(p)->loc;
		if (!lang_expect(p, LTK_LBRACE, "after 'pattern'"))
			return false;
		/* functions.inc's f_mandel: an error only when called. slope evaluates as POV-Ray's,
		 * whose SlopePattern gives 0 without a surface (scene/pattern.c slope), then its wave */
		if (!lang_pigment_starts(p, false)) {
			lang_token *t = lang_peek(p);
			if (t->kind != LTK_UNSUPPORTED)
				return lang_error_found(p, "expected a pattern (bozo, checker, gradient, ...) in 'pattern { }'");
			f->unsupported = arena_strndup(&p->sc->arena, t->text, t->len);
			for (int depth = 1; depth > 0;) {
				t = lang_peek(p);
				if (t->kind == LTK_EOF)
					return lang_expect_close(p, kw.loc, "pattern");
				depth += t->kind == LTK_LBRACE ? 1 : t->kind == LTK_RBRACE ? -1 : 0;
				lang_advance(p);
			}
			return f->unsupported != NULL || lang_error(p, kw.loc, "out of memory");
		}
		if (!lang_pigment_rest(p, NULL, open, &tree))
			return false;
	}
	return (f->pattern = compile_tree(p, tree, &f->pattern_root)) != NULL;
}

static bool spline_kind_of(lang_tok k, lang_spline_kind *kind)
{
	switch (k) {
	case LTK_KW_LINEAR_SPLINE: *kind = LANG_SPLINE_LINEAR; return true;
	case LTK_KW_QUADRATIC_SPLINE: *kind = LANG_SPLINE_QUADRATIC; return true;
	case LTK_KW_CUBIC_SPLINE: *kind = LANG_SPLINE_CUBIC; return true;
	case LTK_KW_NATURAL_SPLINE: *kind = LANG_SPLINE_NATURAL; return true;
	default: return false;
	}
}

/* A copy of s in the arena, of another kind, its natural_spline coefficients computed. */
static lang_spline *spline_copy(parser *p, const lang_spline_entry *e, size_t n, int terms, lang_spline_kind kind)
{
	lang_spline *s = arena_zalloc(&p->sc->arena, 1, sizeof *s);
	lang_spline_entry *ce = s ? arena_alloc(&p->sc->arena, n, sizeof *ce, 16) : NULL;
	if (!ce)
		return NULL;
	memcpy(ce, e, n * sizeof *ce);
	*s = (lang_spline){.kind = kind, .terms = terms, .n = n, .e = ce};
	if (kind == LANG_SPLINE_NATURAL)
		lang_spline_natural_coeffs(s);
	return s;
}

/* One entry's value: a float (given to every component, as POV-Ray's Promote_Express) or a vector
 * or colour of up to 5 components; *terms grows to its count. */
static bool spline_value(parser *p, double *v, int *terms)
{
	diag_loc at = lang_peek(p)->loc;
	value x;
	if (!lang_expr(p, &x))
		return false;
	if (x.kind != VAL_FLOAT && x.kind != VAL_VECTOR && x.kind != VAL_COLOR)
		return lang_error(p, at, "expected a float or vector as a spline's value, found %s", lang_value_kind_name(&x));
	int n = x.kind == VAL_FLOAT ? 2 : x.n;
	if (n > LANG_SPLINE_TERMS) /* POV-Ray's "Too many components in vector!" */
		return lang_error(p, at, "a spline's value has at most %d components, found %d", LANG_SPLINE_TERMS, n);
	memset(v, 0, LANG_SPLINE_TERMS * sizeof *v);
	for (int k = 0; k < n; k++)
		v[k] = x.kind == VAL_FLOAT ? x.v[0] : x.v[k];
	if (n > *terms)
		*terms = n;
	return true;
}

/* spline = "spline" "{" [ spline_identifier ] [ spline_kind ] { float [","] value [","] } "}" */
static bool spline_block(parser *p, const lang_spline **out)
{
	lang_token kw = *lang_advance(p);
	if (!lang_expect(p, LTK_LBRACE, "after 'spline'"))
		return false;
	vecbuf es;
	vecbuf_init(&es, sizeof(lang_spline_entry));
	lang_spline_kind kind = LANG_SPLINE_LINEAR;
	int terms = 2;
	bool ok = true;
	lang_token *t = lang_peek(p);
	if (t->kind == LTK_IDENT) {
		const symbol *s = lang_lookup(p, t->text, t->len);
		if (s && s->val.kind == VAL_SPLINE) {
			const lang_spline *old = s->val.spl;
			for (size_t i = 0; ok && i < old->n; i++)
				ok = vecbuf_push(&es, &old->e[i]) != NULL;
			kind = old->kind, terms = old->terms;
			lang_advance(p);
		}
	}
	if (spline_kind_of(lang_peek(p)->kind, &kind))
		lang_advance(p);
	while (ok && lang_peek(p)->kind != LTK_RBRACE && lang_peek(p)->kind != LTK_EOF) {
		double key, v[LANG_SPLINE_TERMS];
		lang_spline_entry room = {0};
		ok = lang_float(p, "as a spline's key", &key);
		lang_accept(p, LTK_COMMA);
		ok = ok && spline_value(p, v, &terms);
		lang_accept(p, LTK_COMMA);
		if (ok && !vecbuf_push(&es, &room))
			ok = lang_error(p, kw.loc, "out of memory");
		if (ok) {
			size_t n = es.len - 1;
			lang_spline_insert(es.data, &n, key, v);
			es.len = n;
		}
	}
	if (ok && es.len == 0)
		ok = lang_error(p, lang_peek(p)->loc, "a spline needs at least one entry (a key and its value)");
	ok = ok && lang_expect_close(p, kw.loc, "spline");
	if (ok && !(*out = spline_copy(p, es.data, es.len, terms, kind)))
		ok = lang_error(p, kw.loc, "out of memory");
	vecbuf_free(&es);
	return ok;
}

/* function = "function" [ params ] "{" ( expression | internal | "transform" "{" ... "}"
 *          | spline | "pattern" "{" ... "}" | "pigment" "{" ... "}" ) "}" */
static bool function_rest(parser *p, const lang_token *self, lang_token kw, value *out);

static bool function_value(parser *p, const lang_token *self, value *out)
{
	return function_rest(p, self, *lang_advance(p), out);
}

bool lang_func_body(parser *p, lang_token kw, value *out)
{
	return function_rest(p, NULL, kw, out);
}

/* A function after its keyword kw (consumed): its parameters or none, its body in braces. */
static bool function_rest(parser *p, const lang_token *self, lang_token kw, value *out)
{
	lang_function *f = new_function(p, self, LANG_FN_CODE);
	if (!f)
		return lang_error(p, kw.loc, "out of memory");
	bool defaults = lang_peek(p)->kind != LTK_LPAREN;
	if (!defaults && !params(p, f))
		return false;
	if (!lang_expect(p, LTK_LBRACE, defaults ? "after 'function'" : "after the function's parameters"))
		return false;
	lang_token *t = lang_peek(p);
	bool ok;
	if (t->kind == LTK_KW_INTERNAL) {
		ok = internal_body(p, f);
	} else if (t->kind == LTK_KW_TRANSFORM) {
		value xv;
		bool handled;
		ok = lang_declare_block(p, &xv, &handled);
		f->kind = LANG_FN_TRANSFORM, f->xf = xv.xf, f->n_params = 3, f->n_out = 3;
	} else if (t->kind == LTK_KW_SPLINE) {
		ok = spline_block(p, &f->spline);
		f->kind = LANG_FN_SPLINE, f->n_params = 1, f->n_out = ok ? f->spline->terms : 1;
	} else if (t->kind == LTK_KW_PIGMENT || token_is(t, "pattern")) {
		ok = pattern_block(p, f, t->kind == LTK_KW_PIGMENT);
	} else {
		if (defaults) {
			f->n_params = 3;
			f->params[0] = "x", f->params[1] = "y", f->params[2] = "z";
		}
		ok = code_body(p, f, self, defaults);
	}
	if (!ok || !lang_expect_close(p, kw.loc, "function"))
		return false;
	memset(out, 0, sizeof *out);
	out->kind = VAL_FUNCTION;
	out->fn = f;
	return true;
}

bool lang_fn_report(parser *p, diag_loc at, const lang_function *failed)
{
	return lang_error(p, at, "the pattern '%s' is not supported by circe (in the function '%s')",
			  failed->unsupported ? failed->unsupported : "?", failed->name);
}

/* The function pattern's call of its function (scene_fn's eval). */
static bool pattern_call(const void *ctx, const double xyz[3], double *out)
{
	const lang_function *failed;
	return lang_fn_eval(ctx, xyz, out, &failed);
}

bool lang_func_pattern(parser *p, scene_fn *out)
{
	diag_loc at = lang_peek(p)->loc;
	value v;
	if (!function_value(p, NULL, &v))
		return false;
	const lang_function *f = v.fn;
	if (f->n_params != 3 || f->n_out != 1)
		return lang_error(p, at, "the function of a 'function' pattern must be a float function of x, y and z: this "
					 "one takes %d parameter%s and gives %d value%s",
				  f->n_params, f->n_params == 1 ? "" : "s", f->n_out, f->n_out == 1 ? "" : "s");
	double a[3] = {0, 0, 0}, r;
	const lang_function *failed = NULL;
	if (!lang_fn_eval(f, a, &r, &failed)) /* refused here, not per shading point */
		return lang_fn_report(p, at, failed);
	*out = (scene_fn){pattern_call, f, f->name};
	return true;
}

bool lang_func_value(parser *p, const lang_token *name, value *out)
{
	if (lang_peek(p)->kind == LTK_KW_FUNCTION)
		return function_value(p, name, out);
	memset(out, 0, sizeof *out);
	out->kind = VAL_SPLINE;
	return spline_block(p, &out->spl);
}

/* ---- calls from expressions ---------------------------------------------------------------- */

/* "(" float { "," float } ")" after a function's or spline's name; a spline's second argument may
 * be a spline kind (POV-Ray's S(t, cubic_spline)). */
static bool call_args(parser *p, const char *fname, double *a, int *n, lang_tok *kind_word)
{
	char ctx[96];
	snprintf(ctx, sizeof ctx, "after '%s'", fname);
	if (!lang_expect(p, LTK_LPAREN, ctx))
		return false;
	bool saved = p->no_gt;
	p->no_gt = false;
	*n = 0;
	if (lang_peek(p)->kind != LTK_RPAREN)
		do {
			lang_spline_kind k;
			if (kind_word && *n == 1 && spline_kind_of(lang_peek(p)->kind, &k)) {
				*kind_word = lang_advance(p)->kind;
				(*n)++;
				continue;
			}
			if (*n == LANG_FN_MAX_PARAMS)
				return lang_error(p, lang_peek(p)->loc, "too many arguments to '%s' (limit is %d)", fname,
						  LANG_FN_MAX_PARAMS);
			snprintf(ctx, sizeof ctx, "as argument %d of '%s'", *n + 1, fname);
			if (!lang_float(p, ctx, &a[(*n)++]))
				return false;
		} while (lang_accept(p, LTK_COMMA));
	p->no_gt = saved;
	snprintf(ctx, sizeof ctx, "to close the arguments of '%s'", fname);
	return lang_expect(p, LTK_RPAREN, ctx);
}

static void set_result(value *out, const double *r, int n, bool colour)
{
	memset(out, 0, sizeof *out);
	out->kind = n == 1 ? VAL_FLOAT : colour ? VAL_COLOR : VAL_VECTOR;
	out->n = n;
	memcpy(out->v, r, (size_t)n * sizeof *r);
}

static bool call_function(parser *p, const lang_token *name, const char *fname, const lang_function *f, value *out)
{
	double a[LANG_FN_MAX_PARAMS], r[LANG_FN_MAX_OUT];
	int n;
	if (!call_args(p, fname, a, &n, NULL))
		return false;
	if (n != f->n_params)
		return lang_wrong_count(p, name->loc, fname, f->n_params, f->n_params, n);
	const lang_function *failed = NULL;
	if (!lang_fn_eval(f, a, r, &failed))
		return lang_fn_report(p, name->loc, failed);
	for (int i = 0; i < f->n_out; i++)
		if (!isfinite(r[i]))
			return lang_error(p, name->loc, "'%s' gives %g at these arguments (a domain error or a division by zero)",
					  fname, r[i]);
	set_result(out, r, f->n_out, f->kind == LANG_FN_PIGMENT);
	return true;
}

static bool call_spline(parser *p, const lang_token *name, const char *fname, const lang_spline *s, value *out)
{
	double a[LANG_FN_MAX_PARAMS], r[LANG_SPLINE_TERMS];
	int n;
	lang_tok kw = LTK_EOF;
	if (!call_args(p, fname, a, &n, &kw))
		return false;
	if (n < 1 || n > 2)
		return lang_wrong_count(p, name->loc, fname, 1, 2, n);
	if (n == 2 && kw == LTK_EOF)
		return lang_error(p, name->loc, "the second argument of '%s' must be a spline kind (linear_spline, "
						"quadratic_spline, cubic_spline or natural_spline)", fname);
	lang_spline_kind kind;
	if (kw != LTK_EOF && spline_kind_of(kw, &kind) && kind != s->kind) { /* a copy of the other kind */
		lang_spline tmp = {.kind = kind, .terms = s->terms, .n = s->n, .e = malloc(s->n * sizeof *s->e)};
		if (!tmp.e)
			return lang_error(p, name->loc, "out of memory");
		memcpy(tmp.e, s->e, s->n * sizeof *s->e);
		if (kind == LANG_SPLINE_NATURAL)
			lang_spline_natural_coeffs(&tmp);
		lang_spline_eval(&tmp, a[0], r);
		free(tmp.e);
	} else {
		lang_spline_eval(s, a[0], r);
	}
	set_result(out, r, s->terms, false);
	return true;
}

bool lang_func_call(parser *p, const lang_token *name, const value *fv, value *out)
{
	char fname[64];
	snprintf(fname, sizeof fname, "%.*s", (int)name->len, name->text);
	if (fv->kind == VAL_SPLINE)
		return call_spline(p, name, fname, fv->spl, out);
	return call_function(p, name, fname, fv->fn, out);
}
