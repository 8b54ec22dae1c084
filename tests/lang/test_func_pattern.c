/* test_func_pattern: the language's pattern and pigment functions and the function pattern.
 * - `function { pattern { P } }` equals the pattern P as the renderer evaluates it (the same
 *   pattern in a pigment with a grey ramp colour map, compiled by scene/pattern_compile.c and
 *   run by pattern_eval) at random points, for every pattern kind with warps, turbulence and waves;
 * - pattern functions at points where POV-Ray's definitions give closed forms (gradient, onion,
 *   leopard, spherical, checker), and f_noise3d equal to the bozo pattern (functions.inc's
 *   f_bozo is f_noise3d: POV-Ray's Noise() is both), in [0, 1] with mean 0.5; the noise-based
 *   internal functions (f_ridged_mf, f_ridge, f_hetero_mf) against their definitions over it;
 * - `function { pigment { ... } }`: each of the five components, .gray, a declared pigment;
 * - `pigment { function { expression } }`: the value the function gives, above 1 taken mod 1
 *   and below 0 wrapped (POV-Ray's FunctionPattern and ramp wave), through the colour map; as
 *   a normal, the slope perturbation POV-Ray's Perturb_Normal gives a linear function;
 * - vturbulence() is the turbulence warp's vector. */
#include "base/mem.h"
#include "check.h"
#include "lang/lang.h"
#include "scene/pattern.h"
#include "scene/scene.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

static const char *scene_text;

static int read_mem(void *user, const char *path, char **text, size_t *len)
{
	if (strcmp(path, "f.pov"))
		return lang_read_file(user, path, text, len); /* an include file */
	size_t n = strlen(scene_text);
	*text = mem_alloc(n ? n : 1, 1);
	if (!*text)
		return ENOMEM;
	memcpy(*text, scene_text, n);
	*len = n;
	return 0;
}

static bool have_includes;

/* Parses text; *out receives what it printed (#debug), the caller frees it and the scene. */
static scene *parse(const char *text, char **out)
{
	scene_text = text;
	size_t len = 0;
	*out = NULL;
	FILE *o = open_memstream(out, &len);
	diag d;
	diag_init(&d, o);
	const char *dirs[] = {"/usr/share/povray-3.7/include"};
	lang_options opt = {.read = read_mem, .include_dirs = dirs, .n_include_dirs = 1};
	scene *sc = NULL;
	lang_status st = lang_parse_file("f.pov", &opt, &d, &sc);
	fclose(o);
	diag_free(&d);
	CHECK(st == LANG_OK, "the scene does not parse: %.600s\n%.300s", *out ? *out : "", text);
	if (st != LANG_OK && sc) {
		scene_free(sc);
		sc = NULL;
	}
	return sc;
}

static uint64_t lcg = 0x2545f4914f6cdd1du;
static double uniform(double lo, double hi)
{
	lcg = lcg * 6364136223846793005u + 1442695040888963407u;
	return lo + (hi - lo) * (double)(lcg >> 11) / 9007199254740992.0;
}

/* A pattern as a function and as a pigment: the function's pattern body, the pigment's body
 * (the same pattern with a map giving its value as the grey), and the value's scale (a
 * hexagon's grey is its index over 2). */
typedef struct pat_case {
	const char *fn, *pig;
	double scale;
} pat_case;

#define RAMP " color_map { [0 rgb 0] [1 rgb 1] }"
static const pat_case pats[] = {
	{"bozo scale 0.7", "bozo scale 0.7" RAMP, 1},
	{"agate", "agate" RAMP, 1},
	{"granite scale 2", "granite scale 2" RAMP, 1},
	{"marble turbulence 0.5", "marble turbulence 0.5" RAMP, 1},
	{"wood turbulence 0.1 scale 0.3", "wood turbulence 0.1 scale 0.3" RAMP, 1},
	{"leopard scale 0.2", "leopard scale 0.2" RAMP, 1},
	{"onion", "onion" RAMP, 1},
	{"gradient <1, 1, 0>", "gradient <1, 1, 0>" RAMP, 1},
	{"radial frequency 3", "radial frequency 3" RAMP, 1},
	{"spiral1 3", "spiral1 3" RAMP, 1},
	{"spiral2 2 rotate 20*x", "spiral2 2" RAMP " rotate 20*x", 1},
	{"ripples", "ripples" RAMP, 1},
	{"waves frequency 2", "waves frequency 2" RAMP, 1},
	{"wrinkles", "wrinkles" RAMP, 1},
	{"dents", "dents" RAMP, 1},
	{"bumps", "bumps" RAMP, 1},
	{"spotted", "spotted" RAMP, 1},
	{"crackle", "crackle" RAMP, 1},
	{"cells", "cells" RAMP, 1},
	{"quilted control0 0.5", "quilted control0 0.5" RAMP, 1},
	{"planar", "planar" RAMP, 1},
	{"boxed", "boxed" RAMP, 1},
	{"cylindrical", "cylindrical" RAMP, 1},
	{"spherical scale 2", "spherical scale 2" RAMP, 1},
	{"bozo warp { turbulence 0.5 } rotate 30*y", "bozo" RAMP " warp { turbulence 0.5 } rotate 30*y", 1},
	{"gradient x sine_wave", "gradient x sine_wave" RAMP, 1},
	{"gradient y triangle_wave phase 0.3", "gradient y triangle_wave phase 0.3" RAMP, 1},
	{"gradient z scallop_wave", "gradient z scallop_wave" RAMP, 1},
	{"onion cubic_wave", "onion cubic_wave" RAMP, 1},
	{"onion poly_wave 2", "onion poly_wave 2" RAMP, 1},
	{"gradient x warp { repeat x*0.5 flip x }", "gradient x" RAMP " warp { repeat x*0.5 flip x }", 1},
	{"checker scale 0.5", "checker rgb 0, rgb 1 scale 0.5", 1},
	{"brick", "brick rgb 0, rgb 1", 1},
	{"hexagon", "hexagon rgb 0, rgb 0.5, rgb 1", 2},
	{"pigment_pattern { gradient x" RAMP " }", "pigment_pattern { gradient x" RAMP " }" RAMP, 1},
};
enum { N_PATS = sizeof pats / sizeof pats[0], N_POINTS = 40 };

/* Each pattern function at random points against the same pattern as a pigment's grey. */
static void check_patterns(void)
{
	static double pts[N_PATS][N_POINTS][3];
	char *text = NULL;
	size_t tl = 0;
	FILE *f = open_memstream(&text, &tl);
	for (int i = 0; i < N_PATS; i++) {
		fprintf(f, "#declare F%d = function { pattern { %s } }\n", i, pats[i].fn);
		fprintf(f, "sphere { 0, 1 pigment { %s } }\n", pats[i].pig);
		for (int k = 0; k < N_POINTS; k++) {
			for (int j = 0; j < 3; j++)
				pts[i][k][j] = uniform(-3, 3);
			fprintf(f, "#debug concat(str(F%d(%.17g, %.17g, %.17g), 0, 15), \"\\n\")\n", i, pts[i][k][0], pts[i][k][1],
				pts[i][k][2]);
		}
	}
	fclose(f);
	char *out;
	scene *sc = parse(text, &out);
	if (sc) {
		CHECK(scene_n_objects(sc) == N_PATS, "%zu objects", scene_n_objects(sc));
		const char *line = out;
		for (int i = 0; i < N_PATS && i < (int)scene_n_objects(sc); i++) {
			const scene_material *m = scene_object_at(sc, (size_t)i)->material;
			CHECK(m && m->pigment, "sphere %d has no pattern", i);
			if (!m || !m->pigment)
				break;
			pattern_prog pp = {0};
			uint32_t root;
			diag d;
			diag_init(&d, stderr);
			CHECK(pattern_compile(&pp, m->pigment, NULL, NULL, &root, &d), "%s does not compile", pats[i].pig);
			diag_free(&d);
			for (int k = 0; k < N_POINTS; k++) {
				char *end;
				double got = strtod(line, &end);
				float c[5];
				pattern_eval(&pp, root, d3(pts[i][k][0], pts[i][k][1], pts[i][k][2]), 0.0, c);
				double want = c[0] * pats[i].scale;
				CHECK(end != line && fabs(got - want) <= 2e-6, "pattern { %s } at (%.17g, %.17g, %.17g): %.9g, the pigment %.9g",
				      pats[i].fn, pts[i][k][0], pts[i][k][1], pts[i][k][2], got, want);
				line = strchr(end, '\n') ? strchr(end, '\n') + 1 : end;
			}
			pattern_prog_free(&pp);
		}
		scene_free(sc);
	}
	free(out);
	free(text);
}

/* The values of the expressions of text's #debug lines, one a line, into v (at most n). */
static int values(const char *text, double *v, int n)
{
	char *out;
	scene *sc = parse(text, &out);
	int k = 0;
	for (const char *l = out; sc && l && *l && k < n;) {
		char *end;
		v[k++] = strtod(l, &end);
		l = strchr(end, '\n') ? strchr(end, '\n') + 1 : NULL;
	}
	if (sc)
		scene_free(sc);
	free(out);
	return k;
}

#define DBG(e) "#debug concat(str(" e ", 0, 15), \"\\n\")\n"

/* Closed forms of POV-Ray's pattern definitions, through functions.inc's pattern functions. */
static void check_closed_forms(void)
{
	double v[16];
	int n = values("#include \"functions.inc\"\n" DBG("f_gradientX(0.3, 7, 9)") DBG("f_gradientX(1.25, 0, 0)")
		       DBG("f_gradientX(-0.3, 0, 0)") DBG("f_onion(0.3, 0.4, 0)") DBG("f_spherical(0.3, 0.4, 0)")
		       DBG("f_checker(0.5, 0.5, 0.5)") DBG("f_checker(1.5, 0.5, 0.5)") DBG("f_leopard(0.4, 1.1, -2)")
		       DBG("f_cylindrical(0.6, 5, 0)") DBG("f_boxed(0.1, -0.7, 0.2)"),
		       v, 16);
	CHECK(n == 10, "%d values", n);
	if (n != 10)
		return;
	CHECK_NEAR(v[0], 0.3, 1e-12);
	CHECK_NEAR(v[1], 0.25, 1e-12); /* GradientPattern: above 1, mod 1 */
	CHECK_NEAR(v[2], 0.7, 1e-12);  /* the ramp wave wraps a negative value */
	CHECK_NEAR(v[3], 0.5, 1e-12);
	CHECK_NEAR(v[4], 0.5, 1e-12); /* SphericalPattern: 1 - r inside the unit sphere */
	CHECK_NEAR(v[5], 0.0, 0);
	CHECK_NEAR(v[6], 1.0, 0);
	double s = (sin(0.4) + sin(1.1) + sin(-2.0)) / 3;
	CHECK_NEAR(v[7], s * s, 1e-12);
	CHECK_NEAR(v[8], 0.4, 1e-12);
	CHECK_NEAR(v[9], 0.3, 1e-12);
}

/* function { pattern { slope ... } }: POV-Ray's SlopePattern::EvaluateRaw gives 0 without a
 * surface (a function has none), whatever the point, the direction or an altitude; the wave
 * then applies (ramp: (0 * frequency + phase) mod 1). */
static void check_slope_function(void)
{
	double v[8];
	int n = values("#declare F = function { pattern { slope y } }\n"
		       "#declare G = function { pattern { slope { <0.3, 1, 0.2>, 0.2, 0.8 altitude y, 0, 4 } phase 0.25 } }\n"
		       "#declare H = function { pattern { slope { point_at <1, 2, 3> } frequency 3 phase 0.6 } }\n"
		       DBG("F(0.3, 0.4, 0.5)") DBG("F(-7, 11, 2)") DBG("G(0.3, 0.4, 0.5)") DBG("G(4, -9, 1)")
		       DBG("H(0.1, 0.2, 0.3)"),
		       v, 8);
	CHECK(n == 5, "%d values", n);
	if (n != 5)
		return;
	CHECK_NEAR(v[0], 0.0, 0);
	CHECK_NEAR(v[1], 0.0, 0);
	CHECK_NEAR(v[2], 0.25, 1e-12);
	CHECK_NEAR(v[3], 0.25, 1e-12);
	CHECK_NEAR(v[4], 0.6, 1e-12);
}

/* f_noise3d is the bozo pattern (POV-Ray's Noise under both), in [0, 1], mean about 0.5. */
static void check_noise(void)
{
	enum { N = 400 };
	static double pts[N][3];
	char *text = NULL;
	size_t tl = 0;
	FILE *f = open_memstream(&text, &tl);
	fprintf(f, "#include \"functions.inc\"\n#declare B = function { pattern { bozo } }\n");
	for (int k = 0; k < N; k++) {
		for (int j = 0; j < 3; j++)
			pts[k][j] = uniform(-50, 50);
		fprintf(f, DBG("f_noise3d(%.17g, %.17g, %.17g)") DBG("B(%.17g, %.17g, %.17g)"), pts[k][0], pts[k][1], pts[k][2],
			pts[k][0], pts[k][1], pts[k][2]);
	}
	fclose(f);
	static double v[2 * N];
	int n = values(text, v, 2 * N);
	free(text);
	CHECK(n == 2 * N, "%d values", n);
	double sum = 0, lo = 1, hi = 0;
	for (int k = 0; k + 1 < n; k += 2) {
		CHECK_NEAR(v[k], v[k + 1], 1e-15);
		sum += v[k], lo = fmin(lo, v[k]), hi = fmax(hi, v[k]);
	}
	CHECK(lo >= 0 && hi <= 1 && hi - lo > 0.5, "f_noise3d spans [%g, %g]", lo, hi);
	CHECK(fabs(sum / N - 0.5) < 0.03, "f_noise3d's mean %g", sum / N);
}

/* The noise-based internal functions against their definitions (fnintern.cpp) written over
 * f_noise3d, circe's noise: f_noise_generator is the noise for any generator; f_ridged_mf of two
 * octaves, f_ridge and f_hetero_mf of one and a half. */
static void check_noise_fractals(void)
{
	enum { N = 12 };
	static double pts[N][3];
	char *text = NULL;
	size_t tl = 0;
	FILE *f = open_memstream(&text, &tl);
	fprintf(f, "#include \"functions.inc\"\n");
	for (int k = 0; k < N; k++) {
		for (int j = 0; j < 3; j++)
			pts[k][j] = uniform(-5, 5);
		double x = pts[k][0], y = pts[k][1], z = pts[k][2];
		fprintf(f, DBG("f_noise3d(%.17g, %.17g, %.17g)") DBG("f_noise3d(%.17g, %.17g, %.17g)")
			DBG("f_noise3d(%.17g, %.17g, %.17g)") DBG("f_noise_generator(%.17g, %.17g, %.17g, 3)")
			DBG("f_ridged_mf(%.17g, %.17g, %.17g, 0.7, 2, 2, 1.1, 1.5, 2)")
			DBG("f_ridge(%.17g, %.17g, %.17g, 2, 1.5, 0.5, 0.3, 0.4, 2)")
			DBG("f_hetero_mf(%.17g, %.17g, %.17g, 0.7, 2, 1.5, 0.2, 1, 2)"),
			x, y, z, 2 * x, 2 * y, 2 * z, 4 * x, 4 * y, 4 * z, x, y, z, x, y, z, x, y, z, x, y, z);
	}
	fclose(f);
	static double v[7 * N];
	int n = values(text, v, 7 * N);
	free(text);
	CHECK(n == 7 * N, "%d values", n);
	for (int k = 0; k + 7 <= n; k += 7) {
		double n1 = v[k], n2 = v[k + 1], n4 = v[k + 2];
		CHECK_NEAR(v[k + 3], n1, 1e-15);
		/* ridged: s1 = (1.1 - |2 n - 1|)^2; weight clamp(1.5 s1); s2 = (1.1 - |2 n2 - 1|)^2 weight;
		 * result s1 + s2 2^-0.7 */
		double s1 = pow(1.1 - fabs(2 * n1 - 1), 2), w = fmin(1, fmax(0, s1 * 1.5));
		double s2 = pow(1.1 - fabs(2 * n2 - 1), 2) * w;
		CHECK_NEAR(v[k + 4], s1 + s2 * pow(2, -0.7), 1e-12);
		/* ridge: lambda 2, octaves 1.5, omega 0.5, offset 0.3, ridge 0.4: rscale 1/0.6, scale 1/0.7;
		 * one octave and half of the next (weight 0.5 * 0.5), normalised by 1 + 0.25 */
		double r1 = fabs(n1 - 0.4) / 0.6 - 0.3, r2 = fabs(n2 - 0.4) / 0.6 - 0.3;
		CHECK_NEAR(v[k + 5], (r1 + 0.5 * r2 * 0.5) / 0.7 / 1.25, 1e-12);
		/* hetero: H 0.7, lacunarity 2, octaves 1.5, offset 0.2, power 1: signal 2 n - 1 + 0.2;
		 * inc (2 n2 - 1 + 0.2) 2^-0.7 signal; then half of (2 n4 - 1 + 0.2) 2^-1.4 signal */
		double sg = 2 * n1 - 1 + 0.2, e = pow(2, -0.7);
		sg += (2 * n2 - 1 + 0.2) * e * sg;
		sg += 0.5 * (2 * n4 - 1 + 0.2) * e * e * sg;
		CHECK_NEAR(v[k + 6], sg, 1e-12);
	}
}

/* vturbulence(Lambda, Omega, Octaves, A) is the turbulence warp's vector (pattern_dturbulence),
 * its octaves limited to 1..10 as POV-Ray's parser limits them. */
static void check_vturbulence(void)
{
	double v[9];
	int n = values(DBG("vturbulence(2, 0.5, 6, <0.3, 0.4, 0.5>).x") DBG("vturbulence(2, 0.5, 6, <0.3, 0.4, 0.5>).y")
			       DBG("vturbulence(2.5, 0.6, 3, <-1, 2, 7>).z") DBG("vturbulence(2, 0.5, 0, 1).x")
				       DBG("vturbulence(2, 0.5, 25, 1).x"),
		       v, 9);
	CHECK(n == 5, "%d values", n);
	if (n != 5)
		return;
	pattern_turb t = {.amount = d3(1, 1, 1), .octaves = 6, .omega = 0.5, .lambda = 2};
	dvec3 r = pattern_dturbulence(d3(0.3, 0.4, 0.5), &t);
	CHECK_NEAR(v[0], r.x, 1e-12);
	CHECK_NEAR(v[1], r.y, 1e-12);
	t = (pattern_turb){.amount = d3(1, 1, 1), .octaves = 3, .omega = 0.6, .lambda = 2.5};
	CHECK_NEAR(v[2], pattern_dturbulence(d3(-1, 2, 7), &t).z, 1e-12);
	t = (pattern_turb){.amount = d3(1, 1, 1), .octaves = 1, .omega = 0.5, .lambda = 2};
	CHECK_NEAR(v[3], pattern_dturbulence(d3(1, 1, 1), &t).x, 1e-12);
	t.octaves = 10;
	CHECK_NEAR(v[4], pattern_dturbulence(d3(1, 1, 1), &t).x, 1e-12);
	CHECK(fabs(v[3] - v[4]) > 1e-6, "octaves make no difference: %g", v[3]);
}

/* Pigment functions: the five components, .gray, a declared pigment moved. */
static void check_pigments(void)
{
	double v[16];
	int n = values("#declare P = function { pigment { gradient x color_map { [0 rgbft <1, 0, 0, 0.2, 0.1>] "
		       "[1 rgbft <0, 0, 1, 0.4, 0.3>] } } }\n"
		       "#declare Q = function { P(x, y, z).gray * 2 + P(x, y, z).transmit }\n"
		       "#declare R = function { pigment { rgbft <0.1, 0.2, 0.3, 0.4, 0.5> } }\n"
		       "#declare PG = pigment { checker rgb <1, 0, 0>, rgb <0, 1, 0> }\n"
		       "#declare S = function { pigment { PG scale 2 } }\n"
		       "#declare C = P(0.25, 0, 0);\n" DBG("C.red") DBG("C.green") DBG("C.blue") DBG("C.filter")
			       DBG("C.transmit") DBG("Q(0.25, 0, 0)") DBG("R(5, 5, 5).filter") DBG("R(5, 5, 5).transmit")
				       DBG("S(0.5, 0.5, 0.5).red") DBG("S(2.5, 0.5, 0.5).green"),
		       v, 16);
	CHECK(n == 10, "%d values", n);
	if (n != 10)
		return;
	CHECK_NEAR(v[0], 0.75, 1e-6);
	CHECK_NEAR(v[1], 0.0, 1e-6);
	CHECK_NEAR(v[2], 0.25, 1e-6);
	CHECK_NEAR(v[3], 0.25, 1e-6);
	CHECK_NEAR(v[4], 0.15, 1e-6);
	CHECK_NEAR(v[5], (0.297 * 0.75 + 0.114 * 0.25) * 2 + 0.15, 1e-6);
	CHECK_NEAR(v[6], 0.4, 1e-6);
	CHECK_NEAR(v[7], 0.5, 1e-6);
	CHECK_NEAR(v[8], 1.0, 0);
	CHECK_NEAR(v[9], 1.0, 0);
}

/* The function pattern in a pigment and a normal, evaluated as the renderer does. */
static void check_function_pattern(void)
{
	char *out;
	scene *sc = parse("#declare F = function { pattern { onion } }\n"
			  "sphere { 0, 1 pigment { function { x*0.5 + 0.25 } color_map { [0 rgb 0] [1 rgb 1] } } }\n"
			  "sphere { 0, 1 pigment { function { F(x, y, z) } color_map { [0 rgb 0] [1 rgb 1] } } }\n"
			  "sphere { 0, 1 pigment { function { y } frequency 2 color_map { [0 rgb 0] [1 rgb 1] } } }\n"
			  "sphere { 0, 1 normal { function { y*0.5 + 0.25 } } }\n",
			  &out);
	free(out);
	if (!sc)
		return;
	CHECK(scene_n_objects(sc) == 4, "%zu objects", scene_n_objects(sc));
	const scene_pigment *t[4];
	for (int i = 0; i < 4; i++) {
		const scene_material *m = scene_object_at(sc, (size_t)i)->material;
		t[i] = i < 3 ? m->pigment : m->normal;
		CHECK(t[i] && t[i]->kind == SCENE_PAT_FUNCTION && t[i]->fn.eval, "object %d: no function pattern", i);
		if (!t[i] || !t[i]->fn.eval) {
			scene_free(sc);
			return;
		}
	}
	pattern_prog pp = {0};
	uint32_t r[4];
	diag d;
	diag_init(&d, stderr);
	for (int i = 0; i < 4; i++)
		CHECK(pattern_compile(&pp, t[i], NULL, NULL, &r[i], &d), "object %d does not compile", i);
	diag_free(&d);
	static const double xs[][2] = {{0.5, 0.5}, {2.0, 0.25}, {-1.0, 0.75}, {1.5, 1.0}, {0.1, 0.3}};
	for (size_t k = 0; k < sizeof xs / sizeof xs[0]; k++) {
		float c[5];
		pattern_eval(&pp, r[0], d3(xs[k][0], 9, 9), 0.0, c);
		/* 1.0 exactly: mod 1 only above 1, and the ramp's 1.00001 keeps it */
		CHECK_NEAR(c[0], xs[k][1], 1e-6);
	}
	float c[5];
	pattern_eval(&pp, r[1], d3(0.3, 0.4, 0.0), 0.0, c);
	CHECK_NEAR(c[0], 0.5, 1e-6);
	pattern_eval(&pp, r[2], d3(0.0, 0.3, 0.0), 0.0, c); /* frequency 2: 0.6 */
	CHECK_NEAR(c[0], 0.6, 1e-6);
	/* Perturb_Normal's slope of v = y/2 + 1/4 (accuracy 0.02, bump_size 0.5): the four pyramid
	 * directions v_i sum to 0 and sum v_i v_i.y = 4/3 y, so n moves by
	 * 0.5 * -5 * (0.02 / 0.02) * 0.5 * 0.02 * 4/3 along y, i.e. by -1/30 (the value rises with y:
	 * the normal tips down the slope), and is made unit (UnWarp_Normal). */
	dvec3 n = d3(0, 0, 1);
	pattern_perturb(&pp, r[3], d3(0.2, 0.3, -0.4), &n);
	double len = sqrt(1.0 + 1.0 / 900.0);
	CHECK_NEAR(n.x, 0.0, 1e-8); /* the pyramid's directions to 9 digits */
	CHECK_NEAR(n.y, -1.0 / 30.0 / len, 1e-8);
	CHECK_NEAR(n.z, 1.0 / len, 1e-8);
	pattern_prog_free(&pp);
	scene_free(sc);
}

int main(void)
{
	FILE *probe = fopen("/usr/share/povray-3.7/include/functions.inc", "r");
	have_includes = probe != NULL;
	if (probe)
		fclose(probe);
	check_patterns();
	check_pigments();
	check_function_pattern();
	check_vturbulence();
	check_slope_function();
	if (have_includes) { /* functions.inc itself: skipped without povray-includes */
		check_closed_forms();
		check_noise();
		check_noise_fractals();
	} else {
		fprintf(stderr, "test_func_pattern: no functions.inc: its pattern functions not checked\n");
	}
	return check_done("test_func_pattern");
}
