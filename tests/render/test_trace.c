/* test_trace: POV-Ray's trace(object, start, direction [, normal]) as the build answers it
 * (build_trace.c) against analytic intersections: a sphere, a rotated box, a difference of a box
 * and a sphere, an intersection (random rays' first hits, within the tessellation's distance of
 * the exact point, and their normals, outward, within a small angle of the exact ones; rays
 * aimed clear of the solid miss, with both vectors zero); the cache (one world per object
 * however often it is traced); bad input (a zero direction) reported with a non-zero status; and
 * the language's trace() through lang_options (hit, normal into a declared name, a miss); trace()
 * on an isosurface whose grid came from the shape cache, against the same trace without it. */
#include "check.h"
#include "base/rng.h"
#include "build/build.h"
#include "geom/shape.h"
#include "lang/lang.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[] = "/tmp/circe-test-trace-XXXXXX";

static int trace_cb(void *user, const scene *sc, const scene_object *objs, size_t n, const void *key, dvec3 org,
		    dvec3 dir_, dvec3 *hit, dvec3 *normal, diag *d, diag_loc loc)
{
	return world_trace(user, sc, objs, n, key, org, dir_, hit, normal, d, loc);
}

static bool inside_cb(void *user, const scene *sc, const scene_object *objs, size_t n, const void *key, scene_fn *out,
		      diag *d, diag_loc loc)
{
	return world_inside_fn(user, sc, objs, n, key, out, d, loc);
}

static scene *parse(const char *text, world_tracer *t, FILE *err)
{
	const char *path = check_path(dir, "s.pov");
	FILE *f = fopen(path, "w");
	fputs(text, f);
	fclose(f);
	diag d;
	diag_init(&d, err ? err : stderr);
	scene *sc = NULL;
	lang_options o = {.trace = t ? trace_cb : NULL, .inside = t ? inside_cb : NULL, .trace_user = t};
	if (lang_parse_file(path, &o, &d, &sc) != LANG_OK)
		sc = NULL;
	diag_free(&d);
	unlink(path);
	return sc;
}

/* The camera near: the tessellation fine (spheres within 0.1 px at 640 x 480). */
static const char CAMERA[] = "camera { location <0, 0, -4> look_at 0 }\n";

/* Exact answers: the first t > 0 of the ray o + t u on the solid, its outward normal; false for
 * none. */
typedef bool (*exact_fn)(dvec3 o, dvec3 u, double *t, dvec3 *n);

/* Ray against sphere (c, r): both roots. */
static bool sphere_roots(dvec3 o, dvec3 u, dvec3 c, double r, double *t0, double *t1)
{
	dvec3 oc = d3_sub(o, c);
	double b = d3_dot(oc, u), q = d3_dot(oc, oc) - r * r, disc = b * b - q;
	if (disc <= 0)
		return false;
	double s = sqrt(disc);
	*t0 = -b - s, *t1 = -b + s;
	return true;
}

/* Ray against the box [lo, hi]: its slab interval and the normals at both ends. */
static bool box_span(dvec3 o, dvec3 u, dvec3 lo, dvec3 hi, double *t0, double *t1, dvec3 *n0, dvec3 *n1)
{
	double a = -INFINITY, b = INFINITY;
	const double O[3] = {o.x, o.y, o.z}, U[3] = {u.x, u.y, u.z}, L[3] = {lo.x, lo.y, lo.z}, H[3] = {hi.x, hi.y, hi.z};
	int ia = 0, ib = 0;
	double sa = 0, sb = 0;
	for (int i = 0; i < 3; i++) {
		if (U[i] == 0) {
			if (O[i] < L[i] || O[i] > H[i])
				return false;
			continue;
		}
		double e = (L[i] - O[i]) / U[i], f = (H[i] - O[i]) / U[i];
		double ne = -1, nf = 1; /* the face of e is the low one */
		if (e > f) {
			double s = e;
			e = f, f = s, ne = 1, nf = -1;
		}
		if (e > a)
			a = e, ia = i, sa = ne;
		if (f < b)
			b = f, ib = i, sb = nf;
	}
	if (a >= b)
		return false;
	double na[3] = {0, 0, 0}, nb[3] = {0, 0, 0};
	na[ia] = sa, nb[ib] = sb;
	*t0 = a, *t1 = b, *n0 = d3(na[0], na[1], na[2]), *n1 = d3(nb[0], nb[1], nb[2]);
	return true;
}

static bool exact_sphere(dvec3 o, dvec3 u, double *t, dvec3 *n)
{
	double t0, t1;
	dvec3 c = d3(0.2, -0.1, 0.3);
	if (!sphere_roots(o, u, c, 1.1, &t0, &t1) || t1 <= 0)
		return false;
	*t = t0 > 0 ? t0 : t1;
	*n = d3_scale(d3_sub(d3_add(o, d3_scale(u, *t)), c), 1 / 1.1);
	return true;
}

/* box { <-1, -0.5, -0.7>, <1, 0.5, 0.7> rotate <0, 30, 20> }: the ray taken into the box's space. */
static dvec3 rot_inv(dvec3 v)
{
	/* POV-Ray's rotate <0, 30, 20>: about y by 30 degrees, then about z by 20; inverse: z by -20, then y by -30. */
	double a = -20 * M_PI / 180, b = -30 * M_PI / 180;
	dvec3 w = d3(v.x * cos(a) - v.y * sin(a), v.x * sin(a) + v.y * cos(a), v.z);
	return d3(w.x * cos(b) + w.z * sin(b), w.y, -w.x * sin(b) + w.z * cos(b));
}
static dvec3 rot_fwd(dvec3 v)
{
	double a = 20 * M_PI / 180, b = 30 * M_PI / 180;
	dvec3 w = d3(v.x * cos(b) + v.z * sin(b), v.y, -v.x * sin(b) + v.z * cos(b));
	return d3(w.x * cos(a) - w.y * sin(a), w.x * sin(a) + w.y * cos(a), w.z);
}
static bool exact_box(dvec3 o, dvec3 u, double *t, dvec3 *n)
{
	double t0, t1;
	dvec3 n0, n1;
	if (!box_span(rot_inv(o), rot_inv(u), d3(-1, -0.5, -0.7), d3(1, 0.5, 0.7), &t0, &t1, &n0, &n1) || t1 <= 0)
		return false;
	*t = t0 > 0 ? t0 : t1;
	*n = rot_fwd(t0 > 0 ? n0 : n1);
	return true;
}

/* difference { box { -1, 1 } sphere { <0, 0, -1>, 0.6 } }: the box's span less the sphere's. */
static bool exact_difference(dvec3 o, dvec3 u, double *t, dvec3 *n)
{
	double b0, b1, s0 = 0, s1 = 0;
	dvec3 n0, n1;
	if (!box_span(o, u, d3(-1, -1, -1), d3(1, 1, 1), &b0, &b1, &n0, &n1))
		return false;
	dvec3 c = d3(0, 0, -1);
	bool cut = sphere_roots(o, u, c, 0.6, &s0, &s1);
	/* Boundary events along the ray, in order: inside the solid = in box and not in sphere. */
	double ev[4] = {b0, b1, cut ? s0 : INFINITY, cut ? s1 : INFINITY};
	for (int i = 0; i < 4; i++)
		for (int j = i + 1; j < 4; j++)
			if (ev[j] < ev[i]) {
				double s = ev[i];
				ev[i] = ev[j], ev[j] = s;
			}
	for (int i = 0; i < 4 && isfinite(ev[i]); i++) {
		if (ev[i] <= 0)
			continue;
		double before = ev[i] - 1e-9, after = ev[i] + 1e-9;
		bool in_b = before > b0 && before < b1, in_a = after > b0 && after < b1;
		bool sb = cut && before > s0 && before < s1, sa = cut && after > s0 && after < s1;
		if ((in_b && !sb) == (in_a && !sa))
			continue; /* not a boundary of the solid */
		*t = ev[i];
		dvec3 p = d3_add(o, d3_scale(u, *t));
		if (cut && (ev[i] == s0 || ev[i] == s1))
			*n = d3_scale(d3_sub(c, p), 1 / 0.6); /* the sphere's inside is outside the solid */
		else
			*n = ev[i] == b0 ? n0 : n1;
		return true;
	}
	return false;
}

/* intersection { sphere { 0, 1 } plane { y, 0.3 } }: the ball below y = 0.3. */
static bool exact_intersection(dvec3 o, dvec3 u, double *t, dvec3 *n)
{
	double s0, s1;
	if (!sphere_roots(o, u, d3(0, 0, 0), 1, &s0, &s1))
		return false;
	double p0 = -INFINITY, p1 = INFINITY; /* the half-space y < 0.3 along the ray */
	if (u.y != 0) {
		double tp = (0.3 - o.y) / u.y;
		if (u.y > 0)
			p1 = tp;
		else
			p0 = tp;
	} else if (o.y > 0.3) {
		return false;
	}
	double a = fmax(s0, p0), b = fmin(s1, p1);
	if (a >= b || b <= 0)
		return false;
	*t = a > 0 ? a : b;
	bool plane = a > 0 ? p0 > s0 : p1 < s1;
	dvec3 p = d3_add(o, d3_scale(u, *t));
	*n = plane ? d3(0, 1, 0) : p;
	return true;
}

/* The exact insides of the cases' solids. */
static bool in_sphere(dvec3 q) { return d3_length(d3_sub(q, d3(0.2, -0.1, 0.3))) < 1.1; }
static bool in_box(dvec3 q)
{
	dvec3 r = rot_inv(q);
	return fabs(r.x) < 1 && fabs(r.y) < 0.5 && fabs(r.z) < 0.7;
}
static bool in_difference(dvec3 q)
{
	return fabs(q.x) < 1 && fabs(q.y) < 1 && fabs(q.z) < 1 && d3_length(d3_sub(q, d3(0, 0, -1))) >= 0.6;
}
static bool in_intersection(dvec3 q) { return d3_length(q) < 1 && q.y < 0.3; }

typedef struct trace_case {
	const char *name, *decl; /* declares O */
	exact_fn exact;
	bool (*inside)(dvec3 q);
	double tol; /* the distance the tessellation may keep from the surface */
	double rad; /* rays from a sphere of this radius around the origin... */
} trace_case;

static const trace_case cases[] = {
	{"sphere", "#declare O = sphere { <0.2, -0.1, 0.3>, 1.1 }\n", exact_sphere, in_sphere, 2e-3, 4},
	{"rotated box", "#declare O = box { <-1, -0.5, -0.7>, <1, 0.5, 0.7> rotate <0, 30, 20> }\n", exact_box, in_box,
	 1e-5, 4},
	{"difference", "#declare O = difference { box { -1, 1 } sphere { <0, 0, -1>, 0.6 } }\n", exact_difference,
	 in_difference, 2e-3, 4},
	{"intersection with a plane", "#declare O = intersection { sphere { 0, 1 } plane { y, 0.3 } }\n",
	 exact_intersection, in_intersection, 2e-3, 4},
};

/* A uniform unit vector. */
static dvec3 rng_sphere(rng *r)
{
	double z = 2 * rng_double(r) - 1, phi = 2 * M_PI * rng_double(r), s = sqrt(fmax(0, 1 - z * z));
	return d3(s * cos(phi), s * sin(phi), z);
}

static void test_case(const trace_case *c)
{
	char text[1024];
	snprintf(text, sizeof text, "%s%sobject { O }\n", CAMERA, c->decl);
	world_tracer *t = world_tracer_new(0);
	scene *sc = parse(text, NULL, NULL); /* the objects alone: traced here through world_trace */
	CHECK(sc && t, "%s: parsed", c->name);
	if (!sc || !t) {
		world_tracer_free(t);
		scene_free(sc);
		return;
	}
	const scene_object *objs = scene_object_at(sc, 0);
	size_t n = scene_n_objects(sc);
	diag d;
	diag_init(&d, stderr);
	rng r;
	rng_seed(&r, 19, 7);
	int hits = 0, misses = 0, bad_p = 0, bad_n = 0, bad_hit = 0;
	double worst_p = 0, worst_n = 0;
	for (int i = 0; i < 2000; i++) {
		/* From a random point on a sphere of radius rad towards a random point in the unit ball
		 * (grown by 1.6: some miss). */
		dvec3 o = d3_scale(rng_sphere(&r), c->rad * (1 + rng_double(&r)));
		dvec3 aim = d3_scale(rng_sphere(&r), 1.6 * cbrt(rng_double(&r)));
		dvec3 u = d3_normalize(d3_sub(aim, o));
		double te;
		dvec3 ne;
		bool want = c->exact(o, u, &te, &ne);
		dvec3 p, nn;
		int got = world_trace(t, sc, objs, n, objs, o, d3_scale(u, 3.0), &p, &nn, &d, diag_noloc());
		/* Grazing rays may go either way within the tessellation's distance: skip those whose
		 * exact answer changes under a nudge of the start by tol. */
		if (want != (got == 1)) {
			double t2;
			dvec3 n2;
			bool near_edge = false;
			for (int k = 0; k < 6 && !near_edge; k++) {
				dvec3 dv = d3(k / 2 == 0 ? 1 : 0, k / 2 == 1 ? 1 : 0, k / 2 == 2 ? 1 : 0);
				dvec3 o2 = d3_add(o, d3_scale(dv, (k & 1 ? -3 : 3) * c->tol + 1e-4));
				near_edge = c->exact(o2, u, &t2, &n2) != want;
			}
			if (!near_edge)
				bad_hit++;
			continue;
		}
		if (!want) {
			misses++;
			if (p.x != 0 || p.y != 0 || p.z != 0 || nn.x != 0 || nn.y != 0 || nn.z != 0)
				bad_p++;
			continue;
		}
		hits++;
		dvec3 pe = d3_add(o, d3_scale(u, te));
		double e = d3_length(d3_sub(p, pe));
		/* Near an edge of the solid (a box's, the difference's rim) the nearest exact point may be
		 * on another face: measure the angle only away from them. */
		double a = acos(fmin(1.0, d3_dot(nn, ne)));
		if (e > worst_p)
			worst_p = e;
		if (e > c->tol * 4 + 1e-4)
			bad_p++;
		if (a > 0.05) {
			/* allowed at an edge of the exact solid: a nudge along the ray's normal plane
			 * changes the exact normal there */
			double t2;
			dvec3 n2, side = d3_normalize(d3_cross(u, d3_cross(ne, u)));
			bool edge = false;
			for (int k = -1; k <= 1 && !edge; k += 2) {
				dvec3 o2 = d3_add(o, d3_scale(side, k * 0.02));
				edge = !c->exact(o2, u, &t2, &n2) || d3_dot(n2, ne) < 0.999;
			}
			if (!edge)
				bad_n++;
		} else if (a > worst_n) {
			worst_n = a;
		}
	}
	printf("%s: %d hits, %d misses; worst distance %.3g, worst normal angle %.3g rad\n", c->name, hits, misses,
	       worst_p, worst_n);
	CHECK(hits > 400 && misses > 100, "%s: %d hits, %d misses of 2000 rays", c->name, hits, misses);
	CHECK(bad_hit == 0, "%s: %d rays hit where the exact solid does not or the reverse", c->name, bad_hit);
	CHECK(bad_p == 0, "%s: %d points off the exact ones by more than %g (worst %g)", c->name, bad_p, c->tol * 4 + 1e-4,
	      worst_p);
	CHECK(bad_n == 0, "%s: %d normals more than 0.05 rad from the exact ones", c->name, bad_n);
	CHECK(worst_n < 0.05, "%s: worst normal angle %g", c->name, worst_n);
	CHECK(world_tracer_builds(t) == 1, "%s: one world for one object, built %zu", c->name, world_tracer_builds(t));
	CHECK(d.errors == 0, "%s: no errors, %d", c->name, d.errors);
	/* The inside (POV-Ray's inside() and object pattern) at random points against the exact
	 * solid's, away from its surface by more than the tessellation's distance. */
	scene_fn fn;
	bool made = world_inside_fn(t, sc, objs, n, objs, &fn, &d, diag_noloc());
	CHECK(made && fn.eval, "%s: an inside function", c->name);
	int wrong = 0, tested = 0, in = 0;
	for (int i = 0; made && i < 20000; i++) {
		dvec3 q = d3(3 * rng_double(&r) - 1.5, 3 * rng_double(&r) - 1.5, 3 * rng_double(&r) - 1.5);
		bool want = c->inside(q), near = false;
		for (int k = 0; k < 6 && !near; k++) {
			dvec3 dv = d3(k / 2 == 0 ? 1 : 0, k / 2 == 1 ? 1 : 0, k / 2 == 2 ? 1 : 0);
			near = c->inside(d3_add(q, d3_scale(dv, (k & 1 ? -2 : 2) * c->tol + 1e-5))) != want;
		}
		if (near)
			continue;
		double xyz[3] = {q.x, q.y, q.z}, v = -1;
		bool ok = fn.eval(fn.ctx, xyz, &v);
		tested++, in += want;
		if (!ok || (v == 1.0) != want || (v != 0.0 && v != 1.0))
			wrong++;
	}
	printf("%s: inside at %d points (%d inside), %d wrong\n", c->name, tested, in, wrong);
	CHECK(tested > 15000 && in > 1000 && wrong == 0, "%s: inside wrong at %d of %d points (%d inside)", c->name,
	      wrong, tested, in);
	CHECK(world_tracer_builds(t) == 1, "%s: the inside test takes the traced world, built %zu", c->name,
	      world_tracer_builds(t));
	/* A zero direction: an error, reported. */
	dvec3 p, nn;
	int got = world_trace(t, sc, objs, n, objs, d3(0, 0, -5), d3(0, 0, 0), &p, &nn, &d, diag_noloc());
	CHECK(got == -1 && d.errors == 1, "%s: a zero direction is an error (%d, %d errors)", c->name, got, d.errors);
	diag_free(&d);
	world_tracer_free(t);
	scene_free(sc);
}

/* The language's trace(): the hit, the normal written into a declared name, a miss; the scene
 * places spheres at what it computed, read back from the IR. */
static void test_language(void)
{
	world_tracer *t = world_tracer_new(0);
	scene *sc = parse("camera { location <0, 0, -4> look_at 0 }\n"
			  "#declare B = box { -1, 1 }\n"
			  "#declare N = 0;\n"
			  "#declare P = trace(B, <0.25, 0.5, -5>, <0, 0, 2>, N);\n"
			  "sphere { P, 0.1 }\nsphere { N, 0.1 }\n"
			  "#declare Q = trace(B, <5, 5, 5>, x);\n"
			  "#declare M = <1, 2, 3>;\n"
			  "#declare R = trace(B, <5, 5, 5>, x, M);\n"
			  "sphere { Q, 0.1 }\nsphere { M + 1, 0.1 }\nsphere { R, 0.1 }\n",
			  t, NULL);
	CHECK(sc != NULL, "the trace scene parses");
	if (sc) {
		CHECK(scene_n_objects(sc) == 5, "five spheres, %zu", scene_n_objects(sc));
		const dvec3 want[5] = {{0.25, 0.5, -1}, {0, 0, -1}, {0, 0, 0}, {1, 1, 1}, {0, 0, 0}};
		for (size_t i = 0; i < 5 && i < scene_n_objects(sc); i++) {
			const scene_geom *g = scene_object_at(sc, i)->geom;
			CHECK(g->kind == SHAPE_SPHERE, "sphere %zu", i);
			dvec3 c = g->u.sphere.center;
			CHECK(d3_length(d3_sub(c, want[i])) < 1e-5, "sphere %zu at <%g, %g, %g>, want <%g, %g, %g>", i, c.x,
			      c.y, c.z, want[i].x, want[i].y, want[i].z);
		}
	}
	CHECK(world_tracer_builds(t) == 1, "one declared object, one world: %zu", world_tracer_builds(t));
	scene_free(sc);
	world_tracer_free(t);
	/* inside() and the object pattern: both the object's inside, by the same world. */
	t = world_tracer_new(0);
	sc = parse("#declare B = difference { box { -1, 1 } sphere { <0, 0, -1>, 0.6 } }\n"
		   "sphere { <inside(B, <0.5, 0.5, 0>), inside(B, <0, 0, -0.8>), inside(B, <2, 0, 0>)>, 0.1 }\n"
		   "plane { z, 0 pigment { object { B color rgb <1, 0, 0> color rgb <0, 0, 1> } } }\n",
		   t, NULL);
	CHECK(sc != NULL, "the inside scene parses");
	if (sc && scene_n_objects(sc) == 2) {
		dvec3 c = scene_object_at(sc, 0)->geom->u.sphere.center;
		CHECK(c.x == 1 && c.y == 0 && c.z == 0, "inside() gives 1, 0, 0: <%g, %g, %g>", c.x, c.y, c.z);
		const scene_material *m = scene_object_at(sc, 1)->material;
		const scene_pigment *pg = m ? m->pigment : NULL;
		CHECK(pg && pg->kind == SCENE_PAT_OBJECT && pg->fn.eval, "an object pattern");
		CHECK(pg && pg->n_entries == 2 && pg->entries[0].color[0] == 1 && pg->entries[1].color[2] == 1,
		      "its entries: outside red, inside blue");
		if (pg && pg->fn.eval) {
			const double in[3] = {0.5, -0.5, 0.9}, out[3] = {0, 0, -0.7}, far[3] = {3, 0, 0};
			double a = -1, b = -1, e = -1;
			pg->fn.eval(pg->fn.ctx, in, &a), pg->fn.eval(pg->fn.ctx, out, &b), pg->fn.eval(pg->fn.ctx, far, &e);
			CHECK(a == 1 && b == 0 && e == 0, "the pattern's inside: %g %g %g", a, b, e);
		}
	}
	CHECK(world_tracer_builds(t) == 1, "inside() and the pattern share the world: %zu", world_tracer_builds(t));
	scene_free(sc);
	world_tracer_free(t);
	/* Without a tracer the language refuses trace() with an error. */
	FILE *err = tmpfile();
	sc = parse("#declare B = box { -1, 1 }\n#declare P = trace(B, -5*z, z);\n", NULL, err);
	CHECK(sc == NULL, "trace without a tracer is an error");
	char buf[512] = "";
	rewind(err);
	size_t k = fread(buf, 1, sizeof buf - 1, err);
	buf[k] = 0;
	fclose(err);
	CHECK(strstr(buf, "s.pov:2:14: error: 'trace' is not supported by circe here") != NULL, "the message: %s", buf);
}

/* The hit of the n-th sphere the scene placed (its centre). */
static dvec3 sphere_at(const scene *sc, size_t i)
{
	return i < scene_n_objects(sc) ? scene_object_at(sc, i)->geom->u.sphere.center : d3(NAN, NAN, NAN);
}

/* trace() on an isosurface whose grid came from the shape cache (geom/shape.h shape_cache: a
 * second isosurface of the same function text, compiled apart) hits bit for bit where the same
 * trace hits without the cache (a tracer that never saw the first); one of another constant is
 * made anew. */
static void test_iso_cache(void)
{
	const char *iso = "isosurface { function { sqrt(x*x + y*y + z*z) - 0.8 + %s * sin(7 * x) } "
			  "contained_by { box { -1, 1 } } }\n";
	char a[256], b[256], c[256], text[2048];
	snprintf(a, sizeof a, iso, "0.1"), snprintf(b, sizeof b, iso, "0.1"), snprintf(c, sizeof c, iso, "0.11");
	snprintf(text, sizeof text,
		 "camera { location <0, 0, -4> look_at 0 }\n#declare A = %s#declare B = %s#declare C = %s"
		 "#declare P = trace(A, <0.3, 0.2, -5>, z);\n#declare Q = trace(B, <0.3, 0.2, -5>, z);\n"
		 "#declare R = trace(C, <0.3, 0.2, -5>, z);\nsphere { P, 0.1 }\nsphere { Q, 0.1 }\nsphere { R, 0.1 }\n",
		 a, b, c);
	world_tracer *t = world_tracer_new(0);
	scene *sc = parse(text, t, NULL);
	CHECK(sc && scene_n_objects(sc) == 3, "the cached trace scene parses");
	size_t hits = shape_cache_hits(world_tracer_shapes(t));
	CHECK(world_tracer_builds(t) == 3, "three objects, three worlds: %zu", world_tracer_builds(t));
	CHECK(hits >= 1, "B's grid is A's, from the cache: %zu hits", hits);
	/* B alone, by a tracer that never made A's grid */
	snprintf(text, sizeof text,
		 "camera { location <0, 0, -4> look_at 0 }\n#declare B = %s#declare C = %s"
		 "#declare Q = trace(B, <0.3, 0.2, -5>, z);\n#declare R = trace(C, <0.3, 0.2, -5>, z);\n"
		 "sphere { Q, 0.1 }\nsphere { R, 0.1 }\n",
		 b, c);
	world_tracer *u = world_tracer_new(0);
	scene *sb = parse(text, u, NULL);
	CHECK(sb && scene_n_objects(sb) == 2, "the uncached trace scene parses");
	CHECK(shape_cache_hits(world_tracer_shapes(u)) == 0, "B and C share no grid: %zu hits",
	      shape_cache_hits(world_tracer_shapes(u)));
	if (sc && sb && scene_n_objects(sc) == 3 && scene_n_objects(sb) == 2) {
		dvec3 p = sphere_at(sc, 0), q = sphere_at(sc, 1), r = sphere_at(sc, 2), q0 = sphere_at(sb, 0),
		      r0 = sphere_at(sb, 1);
		printf("iso cache: A hit <%.17g, %.17g, %.17g>, B <%.17g, %.17g, %.17g>, C <%.17g, %.17g, %.17g>\n", p.x,
		       p.y, p.z, q.x, q.y, q.z, r.x, r.y, r.z);
		CHECK(q.z > -1 && q.z < -0.5, "the trace hit the isosurface: z %g", q.z);
		CHECK(!memcmp(&q, &q0, sizeof q), "B's hit from the cached grid <%.17g, %.17g, %.17g> is the uncached "
						   "<%.17g, %.17g, %.17g>",
		      q.x, q.y, q.z, q0.x, q0.y, q0.z);
		CHECK(!memcmp(&p, &q, sizeof p), "A and B, one function, hit alike: %.17g against %.17g", p.z, q.z);
		CHECK(!memcmp(&r, &r0, sizeof r) && r.z != q.z, "C, another constant, its own grid: %.17g (%.17g), B %.17g",
		      r.z, r0.z, q.z);
	}
	scene_free(sc), scene_free(sb);
	world_tracer_free(t), world_tracer_free(u);
}

int main(void)
{
	if (!mkdtemp(dir)) {
		perror("mkdtemp");
		return 99;
	}
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
		test_case(&cases[i]);
	test_language();
	test_iso_cache();
	rmdir(dir);
	return check_done("test_trace");
}
