/* test_func: user-defined functions compiled by the parser give what C computes for the same
 * expressions at many random arguments; functions.inc's internal functions match their closed
 * forms; splines reproduce what each kind must (lines, parabolas, natural splines' continuity
 * and free ends, Catmull-Rom's tangents); lang_fn_same tells functions compiled apart from one
 * text alike and others apart. POV-Ray 3.7's own spline values are tests/good/splines. */
#include "base/mem.h"
#include "check.h"
#include "lang/func.h"
#include "lang/lang.h"
#include "geom/shape.h"
#include "scene/scene.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

/* One expression as POV-Ray writes it and as C computes it, of the parameters a, b, c. */
typedef struct expr_case {
	const char *pov;
	double (*c)(double a, double b, double c);
} expr_case;

static double sel3(double a, double b, double c) { return a < 0 ? b : c; }
static double sel4(double a, double b, double c, double d) { return a < 0 ? b : a == 0 ? c : d; }

static double e0(double a, double b, double c) { return a * b + sin(a) - c / 2; }
static double e1(double a, double b, double c) { return pow(fabs(a), 1.5) + cos(b * c) * 3 - tan(a / 4); }
static double e2(double a, double b, double c) { return fmin(fmin(a, b), c) * 2 + fmax(fmax(fmax(a, b), c), 0.5); }
static double e3(double a, double b, double c) { return (a < b) + (b <= c) * 2 + (a == a) * 4 + (c != b) * 8 + (a >= c) * 16 + (b > a) * 32; }
static double e4(double a, double b, double c) { return ((a > 0) && (b > 0)) + 2 * ((a > 0) || (c > 0)) + 4 * !(b > 0); }
static double e5(double a, double b, double c) { return sel3(a, b, c) + sel4(b, a, 7, c) + sel4(0, 1, 2, 3); }
static double e6(double a, double b, double c) { return fmod(a * 10, 3) + trunc(b * 3) + floor(c * 2) + ceil(a - b); }
static double e7(double a, double b, double c) { return sqrt(a * a + b * b + c * c) + exp(a / 3) + log(1 + b * b) + log10(2 + c * c); }
static double e8(double a, double b, double c) { return atan2(a, b) + asin(sin(c)) + acos(cos(a)) + atan(b); }
static double e9(double a, double b, double c) { return sinh(a / 2) + cosh(b / 2) + tanh(c) + asinh(a) + acosh(1 + b * b) + atanh(tanh(c)); }
static double e10(double a, double b, double c) { return -a - -b + +c - 3.14159265358979323846 * 2 + a * 180.0 / 3.14159265358979323846 + b * 3.14159265358979323846 / 180.0; }
static double e11(double a, double b, double c) { return a < 0 ? b * b : c + 1; }
static double e12(double a, double b, double c) { return (a * a) + (b + c) * (b - c) / (1 + a * a); }
static double e13(double a, double b, double c) { return 1 - 2 * 3 + 4 / 5.0 - a * b / (c * c + 1) * 2; }
static double e14(double a, double b, double c) { return (a + b) * 0.5 + 3 + (c * c + 1) + (c + 1) * (c + 2) * (c + 3) / 10; }

static const expr_case cases[] = {
	{"a*b + sin(a) - c/2", e0},
	{"pow(abs(a), 1.5) + cos(b*c)*3 - tan(a/4)", e1},
	{"min(a, b, c)*2 + max(a, b, c, 0.5)", e2},
	{"(a < b) + (b <= c)*2 + (a = a)*4 + (c != b)*8 + (a >= c)*16 + (b > a)*32", e3},
	{"(a > 0 & b > 0) + 2*(a > 0 | c > 0) + 4*!(b > 0)", e4},
	{"select(a, b, c) + select(b, a, 7, c) + select(0, 1, 2, 3)", e5},
	{"mod(a*10, 3) + int(b*3) + floor(c*2) + ceil(a - b)", e6},
	{"sqrt(a*a + b*b + c*c) + exp(a/3) + ln(1 + b*b) + log(2 + c*c)", e7},
	{"atan2(a, b) + asin(sin(c)) + acos(cos(a)) + atan(b)", e8},
	{"sinh(a/2) + cosh(b/2) + tanh(c) + asinh(a) + acosh(1 + b*b) + atanh(tanh(c))", e9},
	{"-a - -b + +c - pi*2 + degrees(a) + radians(b)", e10},
	{"a < 0 ? b*b : c + 1", e11},
	{"sqr(a) + (b + c)*(b - c)/(1 + a*a)", e12},
	{"1 - 2*3 + 4/5 - a*b/(c*c + 1)*2", e13},
	{"G(a, b) + 3 + K2(c)", e14}, /* calls of declared functions */
};

enum { N_ARGS = 200 };

/* The internal functions against their closed forms (fnintern.cpp's definitions), at x, y, z. */
static double c_sphere(double x, double y, double z) { return sqrt(x * x + y * y + z * z) - 0.7; }
static double c_torus(double x, double y, double z)
{
	double r = sqrt(x * x + z * z) - 1.2;
	return sqrt(r * r + y * y) - 0.3;
}
static double c_r(double x, double y, double z) { return sqrt(x * x + y * y + z * z); }
static double c_th(double x, double y, double z) { (void)y; return atan2(x, z); }
static double c_ph(double x, double y, double z) { return atan2(sqrt(x * x + z * z), y); }
static double c_rounded_box(double x, double y, double z)
{ /* the distance to a box of half sizes 1, 2, 1.5 rounded by 0.25, less POV-Ray's 1e-6 */
	double d[3] = {fmax(fabs(x) - 0.75, 0), fmax(fabs(y) - 1.75, 0), fmax(fabs(z) - 1.25, 0)};
	return sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - 0.25 - 1e-6;
}

static const expr_case internals[] = {
	{"f_sphere(a, b, c, 0.7)", c_sphere}, {"f_torus(a, b, c, 1.2, 0.3)", c_torus}, {"f_r(a, b, c)", c_r},
	{"f_th(a, b, c)", c_th}, {"f_ph(a, b, c)", c_ph}, {"f_rounded_box(a, b, c, 0.25, 1, 2, 1.5)", c_rounded_box},
};

static uint64_t lcg = 0x9e3779b97f4a7c15u;
static double uniform(double lo, double hi)
{
	lcg = lcg * 6364136223846793005u + 1442695040888963407u;
	return lo + (hi - lo) * (double)(lcg >> 11) / 9007199254740992.0;
}

static char *scene_text;
static size_t scene_len;

static int read_mem(void *user, const char *path, char **text, size_t *len)
{
	if (strcmp(path, "f.pov"))
		return lang_read_file(user, path, text, len); /* an include file */
	*text = mem_alloc(scene_len, 1);
	if (!*text)
		return ENOMEM;
	memcpy(*text, scene_text, scene_len);
	*len = scene_len;
	return 0;
}

/* Writes a scene declaring each case as a function, calling it at random arguments and printing
 * the values; parses it and compares each line with C's value. */
static void check_cases(const expr_case *cs, size_t n, const char *prelude)
{
	FILE *f = open_memstream(&scene_text, &scene_len);
	fprintf(f, "%s\n#declare G = function(p, q) { p*0.5 + q*0.5 }\n#declare K = function { x*x + 1 }\n"
		   "#declare K2 = function(r) { K(r, 0, 0) + (r + 1)*(r + 2)*(r + 3)/10 - 3 + 3 }\n", prelude);
	static double args[64][N_ARGS][3];
	for (size_t i = 0; i < n; i++) {
		fprintf(f, "#declare F%zu = function(a, b, c) { %s }\n", i, cs[i].pov);
		for (int k = 0; k < N_ARGS; k++) {
			for (int j = 0; j < 3; j++) /* a few exact zeros and ties for the comparisons */
				args[i][k][j] = k % 17 == 0 ? 0 : k % 13 == 0 ? 0.5 : uniform(-3, 3);
			fprintf(f, "#debug concat(str(F%zu(%.17g, %.17g, %.17g), 0, 15), \"\\n\")\n", i, args[i][k][0],
				args[i][k][1], args[i][k][2]);
		}
	}
	fclose(f);
	char *buf = NULL;
	size_t len = 0;
	FILE *out = open_memstream(&buf, &len);
	diag d;
	diag_init(&d, out);
	const char *dirs[] = {"/usr/share/povray-3.7/include"};
	lang_options opt = {.read = read_mem, .include_dirs = dirs, .n_include_dirs = prelude[0] ? 1 : 0};
	scene *sc = NULL;
	lang_status st = lang_parse_file("f.pov", &opt, &d, &sc);
	fclose(out);
	CHECK(st == LANG_OK, "the scene does not parse: %.400s", buf ? buf : "");
	char *line = buf;
	for (size_t i = 0; st == LANG_OK && i < n; i++)
		for (int k = 0; k < N_ARGS; k++) {
			char *end;
			double got = strtod(line, &end);
			double want = cs[i].c(args[i][k][0], args[i][k][1], args[i][k][2]);
			CHECK(end != line && fabs(got - want) <= 1e-12 * (1 + fabs(want)), "%s at (%.17g, %.17g, %.17g): %.17g, C %.17g",
			      cs[i].pov, args[i][k][0], args[i][k][1], args[i][k][2], got, want);
			line = strchr(end, '\n') ? strchr(end, '\n') + 1 : end;
		}
	free(buf);
	free(scene_text);
	if (sc)
		scene_free(sc);
	diag_free(&d);
}

/* lang_fn_same: two isosurfaces' functions compiled apart from one text are the same; another
 * constant, parameter or called function is not (the shape cache of geom/shape.h relies on it). */
static void check_same(void)
{
	static const char text[] =
		"#declare K = function { x*x + 1 }\n"
		"#declare I = isosurface { function { x*x + y - 0.5 + K(x, y, z) } contained_by { box { -1, 1 } } }\n"
		"#declare I = isosurface { function { x*x + y - 0.5 + K(x, y, z) } contained_by { box { -1, 1 } } }\n"
		"#declare I = isosurface { function { x*x + y - 0.50000000000000011 + K(x, y, z) } contained_by { box { -1, 1 } } }\n"
		"#declare I = isosurface { function { x*x + z - 0.5 + K(x, y, z) } contained_by { box { -1, 1 } } }\n"
		"#declare K = function { x*x + 2 }\n"
		"#declare I = isosurface { function { x*x + y - 0.5 + K(x, y, z) } contained_by { box { -1, 1 } } }\n";
	scene_text = (char *)text, scene_len = sizeof text - 1;
	diag d;
	diag_init(&d, stderr);
	lang_options opt = {.read = read_mem};
	scene *sc = NULL;
	lang_status st = lang_parse_file("f.pov", &opt, &d, &sc);
	CHECK(st == LANG_OK, "the isosurfaces parse");
	const lang_function *f[5] = {0};
	int n = 0;
	for (const scene_geom *g = sc ? sc->geoms : NULL; g; g = g->next)
		if (g->kind == SHAPE_POV && n < 5)
			f[n++] = g->u.pov->fn_ctx;
	CHECK(n == 5, "five isosurfaces, %d", n);
	if (n == 5) { /* the geoms' list runs from the last made to the first */
		const lang_function *a = f[4], *b = f[3], *c = f[2], *e = f[1], *k = f[0];
		CHECK(a != b && lang_fn_same(a, b) && lang_fn_same(b, a), "one text compiled twice is one function");
		CHECK(lang_fn_same(a, a), "a function is itself");
		CHECK(!lang_fn_same(a, c), "another constant (0.5 and the next double) is another function");
		CHECK(!lang_fn_same(a, e), "another parameter is another function");
		CHECK(!lang_fn_same(a, k), "another called function (K redeclared) is another function");
		const double at[3] = {0.25, 0.5, -0.125};
		double va = 0, vb = 1, vk = 0;
		const lang_function *failed;
		CHECK(lang_fn_eval(a, at, &va, &failed) && lang_fn_eval(b, at, &vb, &failed) && va == vb &&
			      lang_fn_eval(k, at, &vk, &failed) && vk != va,
		      "their values: %g %g, another K %g", va, vb, vk);
	}
	scene_free(sc);
	diag_free(&d);
	scene_text = NULL;
}

/* ---- splines ---- */

static lang_spline make_spline(lang_spline_entry *e, size_t n, lang_spline_kind kind, double (*f)(double),
			       const double *keys)
{
	size_t m = 0;
	for (size_t i = 0; i < n; i++) {
		double v[LANG_SPLINE_TERMS] = {f(keys[i]), -f(keys[i])};
		lang_spline_insert(e, &m, keys[i], v);
	}
	lang_spline s = {.kind = kind, .terms = 2, .n = m, .e = e};
	if (kind == LANG_SPLINE_NATURAL)
		lang_spline_natural_coeffs(&s);
	return s;
}

static double line(double t) { return 3 * t - 2; }
static double parabola(double t) { return 2 * t * t - t + 0.5; }
static double wiggly(double t) { return sin(3 * t) + t * t * t / 4; }

static double at(const lang_spline *s, double t)
{
	double v[LANG_SPLINE_TERMS];
	lang_spline_eval(s, t, v);
	CHECK(v[1] == -v[0], "the second component mirrors the first: %g %g", v[0], v[1]);
	return v[0];
}

static void check_splines(void)
{
	lang_spline_entry e[16];
	const double shuffled[] = {0.7, -1, 2.5, 0, 1.2, 3.1, 4}; /* out of order: inserted sorted */
	/* linear reproduces lines, quadratic parabolas (keys at any spacing), inside the keys; outside,
	 * the end values */
	lang_spline s = make_spline(e, 7, LANG_SPLINE_LINEAR, line, shuffled);
	CHECK(s.n == 7 && s.e[0].t == -1 && s.e[6].t == 4, "sorted: %g .. %g", s.e[0].t, s.e[6].t);
	for (double t = -1; t <= 4; t += 0.01)
		CHECK_NEAR(at(&s, t), line(t), 1e-12);
	CHECK_NEAR(at(&s, -5), line(-1), 0);
	CHECK_NEAR(at(&s, 9), line(4), 0);
	s = make_spline(e, 7, LANG_SPLINE_QUADRATIC, parabola, shuffled);
	for (double t = -1; t <= 4; t += 0.01)
		CHECK_NEAR(at(&s, t), parabola(t), 1e-11);
	/* a repeated key replaces the value */
	size_t n = s.n;
	double v[LANG_SPLINE_TERMS] = {42, -42};
	lang_spline_insert(e, &n, 2.5, v);
	CHECK(n == 7 && e[4].t == 2.5 && e[4].v[0] == 42, "replaced: n %zu, %g", n, e[4].v[0]);
	/* cubic_spline (Catmull-Rom) on evenly spaced keys reproduces a parabola between the second and
	 * the next-to-last keys, and is the second / next-to-last value outside */
	const double even[] = {0, 0.5, 1, 1.5, 2, 2.5};
	s = make_spline(e, 6, LANG_SPLINE_CUBIC, parabola, even);
	for (double t = 0.5; t <= 2; t += 0.01)
		CHECK_NEAR(at(&s, t), parabola(t), 1e-12);
	CHECK_NEAR(at(&s, 0.25), parabola(0.5), 0);
	CHECK_NEAR(at(&s, 2.25), parabola(2), 0);
	/* natural_spline: interpolates, continuous first and second derivatives at the keys, zero
	 * second derivative at both ends, checked by finite differences */
	s = make_spline(e, 7, LANG_SPLINE_NATURAL, wiggly, shuffled);
	const double h = 1e-4;
	for (size_t i = 0; i < s.n; i++) {
		double t = s.e[i].t;
		CHECK_NEAR(at(&s, t), wiggly(t), 1e-12);
		if (i == 0 || i + 1 == s.n) {
			double in = i == 0 ? 1 : -1; /* the second difference inside the range */
			double d2 = (at(&s, t) - 2 * at(&s, t + in * h) + at(&s, t + 2 * in * h)) / (h * h);
			CHECK(fabs(d2) < 1e-2 * (1 + fabs(s.e[1].d2[0])), "free end at %g: second derivative %g", t, d2);
			continue;
		}
		double l1 = (at(&s, t) - at(&s, t - h)) / h, r1 = (at(&s, t + h) - at(&s, t)) / h;
		double l2 = (at(&s, t) - 2 * at(&s, t - h) + at(&s, t - 2 * h)) / (h * h);
		double r2 = (at(&s, t + 2 * h) - 2 * at(&s, t + h) + at(&s, t)) / (h * h);
		CHECK(fabs(l1 - r1) < 1e-2, "C1 at %g: %g %g", t, l1, r1);
		CHECK(fabs(l2 - r2) < 1e-2 * (1 + fabs(l2)), "C2 at %g: %g %g", t, l2, r2);
		CHECK_NEAR(l2, s.e[i].d2[0], 1e-2 * (1 + fabs(l2)));
	}
	/* one entry: that value everywhere */
	s = make_spline(e, 1, LANG_SPLINE_NATURAL, wiggly, shuffled);
	CHECK_NEAR(at(&s, -3), wiggly(0.7), 0);
	CHECK_NEAR(at(&s, 3), wiggly(0.7), 0);
}

/* Every internal(N) of POV-Ray's table has an implementation (func.c's or internals.c's): the
 * evaluator relies on it. */
static void check_internals_complete(void)
{
	int np, n = 0;
	for (; lang_fn_internal_name(n, &np); n++)
		CHECK(lang_fn_internal_impl(n) != NULL, "internal(%d) '%s' has no implementation", n,
		      lang_fn_internal_name(n, &np));
	CHECK(n == 79 && !lang_fn_internal_impl(n) && !lang_fn_internal_impl(-1), "%d internals", n);
}

int main(void)
{
	check_cases(cases, sizeof cases / sizeof cases[0], "");
	check_internals_complete();
	FILE *probe = fopen("/usr/share/povray-3.7/include/functions.inc", "r");
	if (probe) { /* functions.inc itself: skipped without povray-includes */
		fclose(probe);
		check_cases(internals, sizeof internals / sizeof internals[0], "#include \"functions.inc\"");
	} else {
		fprintf(stderr, "test_func: no functions.inc: its internal functions not checked\n");
	}
	check_splines();
	check_same();
	return check_done("test_func");
}
