/* csgbench: the cost of CSG per ray - the same objects as a CSG solid and as a plain union (every
 * hit kept), traced by the same random rays (from a sphere of radius 4 towards the unit cube):
 * closest hits, shadow rays and SSS circles, in ns each on one thread, and the memory of each
 * world. Usage: bench/csgbench [RAYS]. Not part of make check (bench/README.md). */
#include "lang/lang.h"
#include "base/rng.h"
#include "render/world.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static double now(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

static world *build(const char *body)
{
	char path[] = "/tmp/csgbench-XXXXXX.pov";
	int fd = mkstemps(path, 4);
	if (fd < 0)
		return NULL;
	FILE *f = fdopen(fd, "w");
	fprintf(f, "camera { location <0, 0, -6> look_at 0 }\nlight_source { <0, 5, -5> color 1 }\n%s\n", body);
	fclose(f);
	diag d;
	diag_init(&d, stderr);
	scene *sc = NULL;
	world_options o = {.width = 640, .height = 480};
	world *w = lang_parse_file(path, NULL, &d, &sc) == LANG_OK ? world_build(sc, &o, &d) : NULL;
	scene_free(sc);
	diag_free(&d);
	unlink(path);
	return w;
}

static vec3 rand_in(rng *g, float s)
{
	return v3(s * (2 * rng_float(g) - 1), s * (2 * rng_float(g) - 1), s * (2 * rng_float(g) - 1));
}

typedef struct result {
	double closest_ns, shadow_ns, circle_ns, hit_rate;
	size_t bytes;
} result;

static result measure(const char *body, long n)
{
	result r = {0};
	world *w = build(body);
	if (!w) {
		fprintf(stderr, "csgbench: scene failed: %s\n", body);
		exit(1);
	}
	rng g;
	rng_seed(&g, 3, 0);
	long hits = 0;
	double t0 = now();
	for (long k = 0; k < n; k++) {
		vec3 o = v3_scale(v3_normalize(rand_in(&g, 1.0f)), 4.0f);
		render_ray ray = {o, v3_normalize(v3_sub(rand_in(&g, 1.0f), o))};
		render_hit h;
		hits += w->rs.intersect(w->rs.user, &ray, 0.0f, INFINITY, &h);
	}
	r.closest_ns = (now() - t0) / n * 1e9;
	r.hit_rate = (double)hits / n;
	rng_seed(&g, 3, 1);
	t0 = now();
	for (long k = 0; k < n; k++) {
		vec3 o = v3_scale(v3_normalize(rand_in(&g, 1.0f)), 4.0f);
		render_ray ray = {o, v3_normalize(v3_sub(rand_in(&g, 1.0f), o))};
		hits += w->rs.occluded(w->rs.user, &ray, 0.0f, 8.0f);
	}
	r.shadow_ns = (now() - t0) / n * 1e9;
	/* Circles about points near the surface, on the SSS volume of instance 0. */
	rng_seed(&g, 3, 2);
	long nc = n / 10;
	render_hit at = {.object = 0};
	t0 = now();
	for (long k = 0; k < nc; k++) {
		vec3 t = v3_normalize(rand_in(&g, 1.0f)), m = v3_normalize(v3_cross(t, v3_normalize(rand_in(&g, 1.0f))));
		tri_circle q = {rand_in(&g, 0.9f), t, m, 0.2f + 0.3f * rng_float(&g), true};
		tri_circle_hit ch[256];
		bool more;
		hits += w->rs.circle(w->rs.user, &at, &q, ch, 256, &more);
	}
	r.circle_ns = (now() - t0) / nc * 1e9;
	world_stats st;
	world_stats_get(w, &st);
	r.bytes = st.geometry_bytes;
	world_free(w);
	return r;
}

int main(int argc, char **argv)
{
	long n = argc > 1 ? atol(argv[1]) : 200000;
	static const char *const pairs[][3] = {
		{"sphere and box", "intersection { sphere { 0, 1 } box { -0.8, 0.8 } material { wax { } } }",
		 "union { sphere { 0, 1 } box { -0.8, 0.8 } material { wax { } } }"},
		{"bored rounded cube (5 operands, 2 levels)",
		 "difference { intersection { sphere { 0, 1 } box { -0.8, 0.8 } } cylinder { -2*x, 2*x, 0.4 }\n"
		 "  cylinder { -2*y, 2*y, 0.4 } cylinder { -2*z, 2*z, 0.4 } material { wax { } } }",
		 "union { sphere { 0, 1 } box { -0.8, 0.8 } cylinder { -2*x, 2*x, 0.4 }\n"
		 "  cylinder { -2*y, 2*y, 0.4 } cylinder { -2*z, 2*z, 0.4 } material { wax { } } }"},
		{"sphere cut by a plane", "intersection { sphere { 0, 1 } plane { <1, 1, 0>, 0.2 } material { wax { } } }",
		 "union { sphere { 0, 1 } plane { <1, 1, 0>, 0.2 } material { wax { } } }"},
		{"merge of three spheres",
		 "merge { sphere { -0.4*x, 0.7 } sphere { 0.4*x, 0.7 } sphere { 0.5*y, 0.6 } material { wax { } } }",
		 "union { sphere { -0.4*x, 0.7 } sphere { 0.4*x, 0.7 } sphere { 0.5*y, 0.6 } material { wax { } } }"},
		{"box less 16 cylinders",
		 "difference { box { -1, 1 }\n"
		 "#for (i, 0, 15) cylinder { <-0.75 + 0.5*mod(i, 4), -2, -0.75 + 0.5*div(i, 4)>, "
		 "<-0.75 + 0.5*mod(i, 4), 2, -0.75 + 0.5*div(i, 4)>, 0.15 } #end material { wax { } } }",
		 "union { box { -1, 1 }\n"
		 "#for (i, 0, 15) cylinder { <-0.75 + 0.5*mod(i, 4), -2, -0.75 + 0.5*div(i, 4)>, "
		 "<-0.75 + 0.5*mod(i, 4), 2, -0.75 + 0.5*div(i, 4)>, 0.15 } #end material { wax { } } }"},
	};
	printf("| solid | closest ns/ray (CSG / union) | shadow ns/ray | circle ns (SSS volume) | rays hitting (CSG / union) | geometry bytes |\n");
	printf("|---|---|---|---|---|---|\n");
	for (size_t i = 0; i < sizeof pairs / sizeof pairs[0]; i++) {
		result c = measure(pairs[i][1], n), u = measure(pairs[i][2], n);
		printf("| %s | %.0f / %.0f (%.2fx) | %.0f / %.0f (%.2fx) | %.0f / %.0f (%.2fx) | %.2f / %.2f | %zu / %zu |\n",
		       pairs[i][0], c.closest_ns, u.closest_ns, c.closest_ns / u.closest_ns, c.shadow_ns, u.shadow_ns,
		       c.shadow_ns / u.shadow_ns, c.circle_ns, u.circle_ns, c.circle_ns / u.circle_ns, c.hit_rate,
		       u.hit_rate, c.bytes, u.bytes);
	}
	return 0;
}
