/* func.h - POV-Ray's user-defined functions and splines: `function (params) { expression }`
 * compiled once into a flat postfix program run on a small stack, functions.inc's
 * `function { internal(N) }`, `function { transform {...} }` and `function { spline {...} }` (vector
 * valued), `function { pattern {...} }` / `{ pigment {...} }` (evaluated by scene/pattern.h's
 * program, which src/scene holds so that the language and the renderer share it), and
 * `spline { ... }` values evaluated as POV-Ray 3.7 does.
 * Internal to src/lang; the evaluator (lang_fn_eval, lang_spline_eval) needs no parser and
 * allocates nothing, so a renderer may call it per ray from many threads. */
#ifndef CIRCE_LANG_FUNC_H
#define CIRCE_LANG_FUNC_H

#include "base/vec.h"
#include "scene/pattern.h"

#include <stdbool.h>
#include <stddef.h>

enum {
	LANG_FN_MAX_PARAMS = 56, /* parameters of one function (POV-Ray 3.7's MAX_PARAMETER_LIST, parse.h) */
	LANG_FN_MAX_STACK = 64, /* stack slots one function body needs at most */
	LANG_FN_MAX_OUT = 5, /* components of a vector-valued function's result */
	LANG_FN_MAX_CALL_DEPTH = 64, /* functions calling functions: each level takes C stack */
	LANG_FN_GRAY = 5, /* a call's member .gray (.grey): 0.297 red + 0.589 green + 0.114 blue */
	LANG_FN_HF = 6, /* .hf: (red + green / 255) 0.996093 (MegaPOV's, which POV-Ray 3.7 keeps) */
};

typedef enum lang_fn_kind {
	LANG_FN_CODE, /* a compiled expression */
	LANG_FN_INTERNAL, /* functions.inc's internal(N) */
	LANG_FN_TRANSFORM, /* function { transform {...} }: (x, y, z) -> the point transformed */
	LANG_FN_SPLINE, /* function { spline {...} }: (t) -> the spline's vector */
	LANG_FN_PATTERN, /* function { pattern {...} }: (x, y, z) -> the pattern's float */
	LANG_FN_PIGMENT, /* function { pigment {...} }: (x, y, z) -> the pigment's colour */
} lang_fn_kind;

typedef struct lang_fn_op lang_fn_op; /* one instruction (func.c) */
typedef struct lang_spline lang_spline;

typedef struct lang_function {
	const char *name; /* the name it was declared with ("function" before that), for messages */
	lang_fn_kind kind;
	int n_params;
	const char *params[LANG_FN_MAX_PARAMS]; /* LANG_FN_CODE: their names */
	int n_out; /* components of the result: 1 for a float function */
	int call_depth; /* 1, plus the deepest of the functions it calls */
	/* LANG_FN_CODE */
	const lang_fn_op *code;
	int n_code;
	/* LANG_FN_INTERNAL: its number and implementation (lang_fn_internal_impl) */
	int internal;
	double (*impl)(const double *args);
	const xform *xf; /* LANG_FN_TRANSFORM */
	const lang_spline *spline; /* LANG_FN_SPLINE */
	/* LANG_FN_PATTERN: the pattern's value at the point after its warps and wave (POV-Ray's
	 * f_pattern); LANG_FN_PIGMENT: the pigment's rgbft (f_pigment). The program is the
	 * function's own, in the scene's arena. */
	const pattern_prog *pattern;
	uint32_t pattern_root;
	const char *unsupported; /* LANG_FN_PATTERN: the word of a pattern circe lacks (pattern NULL) */
} lang_function;

/* Evaluates f at args (f->n_params values): out[0..f->n_out-1]. False when f, or a function it
 * calls, is a pattern function of a pattern circe lacks (f->unsupported names it): *failed is
 * that function. Results are IEEE doubles (a NaN is the caller's to refuse). */
bool lang_fn_eval(const lang_function *f, const double *args, double *out, const lang_function **failed);

/* Whether a and b compute the same values for all arguments: the same function, or compiled code
 * of the same instructions (constants equal bit for bit) calling the same functions, or the same
 * internal function. False may be said of two that are equal (a transform, a spline or a pattern
 * compared by identity only), never true of two that differ: a cache of their results may rely on
 * it. The call depth is bounded by LANG_FN_MAX_CALL_DEPTH. */
bool lang_fn_same(const lang_function *a, const lang_function *b);

/* A POV-Ray spline: entries sorted by key, each a vector of `terms` components (2..5). */
typedef enum lang_spline_kind { LANG_SPLINE_LINEAR, LANG_SPLINE_QUADRATIC, LANG_SPLINE_CUBIC, LANG_SPLINE_NATURAL } lang_spline_kind;

enum { LANG_SPLINE_TERMS = 5 };
typedef struct lang_spline_entry {
	double t;
	double v[LANG_SPLINE_TERMS];
	double d2[LANG_SPLINE_TERMS]; /* natural_spline: the second derivative at the entry */
} lang_spline_entry;

struct lang_spline {
	lang_spline_kind kind;
	int terms; /* components of its values: the most any entry gave, at least 2 */
	size_t n; /* at least 1 */
	lang_spline_entry *e;
};

/* The spline's value at t (s->terms components in out), by POV-Ray 3.7's rules
 * (source/core/math/spline.cpp): outside the keys the first or last value (cubic_spline: the
 * second or next-to-last), ... */
void lang_spline_eval(const lang_spline *s, double t, double *out);
/* Inserts (t, v) keeping the keys sorted; an equal key's value is replaced (POV-Ray's
 * Insert_Spline_Entry). e has room for one more entry. */
void lang_spline_insert(lang_spline_entry *e, size_t *n, double t, const double *v);
/* natural_spline's second derivatives, zero at both ends (POV-Ray's Precompute_Cubic_Coeffs). */
void lang_spline_natural_coeffs(lang_spline *s);

/* The float built-ins of one and two arguments by their token (a lang_tok: sin ... degrees; atan2
 * pow mod div), shared by expressions and function bodies: IEEE results, no domain check (the
 * caller's). LANG_FN_SQR: POV-Ray's sqr, of functions only. NaN for another token. */
enum { LANG_FN_SQR = -1 };
double lang_fn_float1(int tok, double x);
double lang_fn_float2(int tok, double x, double y);

/* The internal functions of functions.inc: the name POV-Ray gives internal(n) and its parameter
 * count; NULL past the table. */
const char *lang_fn_internal_name(int n, int *n_params);
/* internal(n)'s implementation, from func.c's table or internals.c's; every n of the table has
 * one (test_func checks them all); NULL past the table. */
double (*lang_fn_internal_impl(int n))(const double *args);
/* The internal functions of lang/internals.c by number (NULL for one it does not have). */
double (*lang_fn_internal_more(int n))(const double *args);

#endif
