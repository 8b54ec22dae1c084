/* test_csg: POV-Ray's CSG against brute force. For each solid (every operator, nested, inverse
 * on an object and on a node, planes as half-spaces, clipped_by, under transforms, a mesh2 split
 * by its texture_list as an operand, its inside the whole mesh's): random rays'
 * closest hits and shadow rays against a loop over every triangle of every operand whose hits are
 * kept by the boolean's sensitivity (a point of operand i's surface bounds the solid where the
 * solid's inside changes with i's), the insides of points against a parity count over every
 * triangle along another direction, normals facing a ray that enters, and circles traced on an
 * SSS solid against sampling the circle densely. */
#include "check.h"
#include "base/rng.h"
#include "lang/lang.h"
#include "render/world.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[] = "/tmp/circe-test-csg-XXXXXX";

static bool build(const char *text, world **w)
{
	char path[256];
	snprintf(path, sizeof path, "%s/s.pov", dir);
	FILE *f = fopen(path, "w");
	fputs(text, f);
	fclose(f);
	diag d;
	diag_init(&d, stderr);
	scene *sc = NULL;
	bool ok = lang_parse_file(path, NULL, &d, &sc) == LANG_OK;
	world_options o = {.width = 320, .height = 240};
	*w = ok ? world_build(sc, &o, &d) : NULL;
	scene_free(sc);
	diag_free(&d);
	unlink(path);
	return *w != NULL;
}

#define MAX_LEAVES 8

/* A solid: its text (the camera far, so that the meshes are coarse and brute force cheap), which
 * of its objects are inverted (their own inverse) and clip-only, and its boolean over the
 * objects' insides (inverse applied), in the scene's order. */
typedef struct csg_case {
	const char *name, *text;
	int n;
	bool inverse[MAX_LEAVES], clip[MAX_LEAVES];
	bool (*f)(const bool *in);
	/* The first `joined` objects are the pieces of one mesh (mesh2's texture_list: one mesh a
	 * texture): each piece's inside is the whole mesh's, by the parity over all their triangles. */
	int joined;
} csg_case;

static bool f_nested(const bool *in) { return in[0] && in[1] && !in[2] && !in[3]; }
static bool f_merge(const bool *in) { return in[0] || in[1] || in[2]; }
static bool f_inv_node(const bool *in) { return in[0] && !(in[1] && in[2]) && in[3]; }
static bool f_clip(const bool *in) { return in[0] && in[1] && in[2]; }
static bool f_union_op(const bool *in) { return in[0] && !(in[1] || in[2]); }
/* The planes' wedge case: cylinder, y < 0.6, y > -0.6, minus (x < 0 and z < 0). */
static bool f_wedge(const bool *in) { return in[0] && in[1] && in[2] && !(in[3] && in[4]); }
static bool f_open(const bool *in) { return in[0] && !in[1]; }
/* A tetrahedron of two textures (two pieces, each the whole mesh's inside) less a sphere. */
static bool f_split(const bool *in) { return in[0] && in[1] && !in[2]; }

static const char CAMERA[] = "camera { location <0, 0, -60> look_at 0 }\nlight_source { <0, 50, -50> color 1 }\n";

static const csg_case cases[] = {
	{"difference of an intersection, an inverted plane", /* a plane inverted: subtracting it keeps y < 0.5 */
	 "difference { intersection { sphere { 0, 1 } box { -0.8, 0.8 } } cylinder { -2*x, 2*x, 0.4 }\n"
	 "  plane { y, 0.5 inverse } rotate <20, 30, 0> translate <0.1, 0, 0> }\n",
	 4, {false, false, false, true}, {false}, f_nested},
	{"merge of three spheres",
	 "merge { sphere { 0, 1 } sphere { <0.8, 0, 0>, 1 } sphere { <0, 0.8, 0>, 0.7 } scale <1, 1.2, 1> }\n", 3, {false},
	 {false}, f_merge},
	{"inverse of an intersection inside an intersection",
	 "intersection { sphere { 0, 1.2 } object { intersection { box { -0.5, 0.5 } sphere { 0, 0.7 } } inverse }\n"
	 "  plane { z, 0.3 } rotate 40*y }\n",
	 4, {false}, {false}, f_inv_node},
	{"clipped_by two planes",
	 "sphere { 0, 1 clipped_by { plane { x, 0.2 } plane { -y, 0.3 } } rotate 10*z }\n", 3, {false}, {false, true, true},
	 f_clip},
	{"difference of a union", /* the union's spheres do not overlap: its surfaces are all boundary */
	 "difference { box { -1, 1 } union { sphere { <1, 1, -1>, 0.6 } sphere { <-1, -1, -1>, 0.6 } } }\n", 3, {false},
	 {false}, f_union_op},
	{"planes as half-spaces", /* a slab of a cylinder, a wedge cut out */
	 "difference { intersection { cylinder { -2*y, 2*y, 1 } plane { y, 0.6 } plane { -y, 0.6 } }\n"
	 "  intersection { plane { x, 0 } plane { z, 0 } } }\n",
	 5, {false}, {false}, f_wedge},
	{"an open cylinder subtracted", /* its inside is the closed cylinder's, as POV-Ray's */
	 "difference { sphere { 0, 1 } cylinder { -0.5*y, 2*y, 0.4 open } rotate 20*x }\n", 2, {false}, {false}, f_open},
	{"a mesh2 of two textures less a sphere", /* each piece open; the operand is the whole mesh */
	 "difference { mesh2 { vertex_vectors { 4, <-1.2, -1, -1>, <1.3, -1.1, -0.8>, <0, 1.3, -0.6>, <0.1, -0.2, 1.4> }\n"
	 "  texture_list { 2, texture { pigment { rgb x } } texture { pigment { rgb y } } }\n"
	 "  face_indices { 4, <0, 2, 1>, 0, <0, 1, 3>, 0, <1, 2, 3>, 1, <0, 3, 2>, 1 } }\n"
	 "  sphere { <0.5, 0.3, -0.2>, 0.6 } rotate 25*y }\n",
	 3, {false}, {false}, f_split, 2},
};

/* World-space triangles of every instance. */
typedef struct tris {
	vec3 *v;
	uint32_t n;
} tris;

static tris world_tris(const world_inst *in)
{
	const mesh *m = &in->g->m;
	tris t = {malloc((size_t)m->num_triangles * 3 * sizeof(vec3) + 1), m->num_triangles};
	for (size_t k = 0; k < (size_t)m->num_triangles * 3; k++)
		t.v[k] = d3_to_v3(xform_point(&in->xf, v3_to_d3(m->positions[m->indices[k]])));
	return t;
}

/* Brute-force inside of instance i (its own inverse not applied): a plane's half-space, else the
 * parity of every triangle's crossings along a direction of its own (crossings at one t once). */
static bool ref_inside_raw(const world *w, const tris *T, size_t i, vec3 p)
{
	const world_inst *in = &w->insts[i];
	if (in->inside_kind == WORLD_INSIDE_PLANE) {
		dvec3 q = xform_inv_point(&in->xf, v3_to_d3(p));
		return d3_dot(in->plane_n, q) < in->plane_d;
	}
	if (in->inside_kind == WORLD_INSIDE_CONE) { /* the closed solid: caps at y = -0.5 and 2, radius 0.4 */
		dvec3 q = xform_inv_point(&in->xf, v3_to_d3(p));
		return q.y > -0.5 && q.y < 2.0 && q.x * q.x + q.z * q.z < 0.16;
	}
	tri_ray r;
	if (!tri_ray_prepare(&r, p, v3_normalize(v3(-0.31f, 0.72f, 0.62f)), 0.0f, INFINITY))
		return false;
	float ts[512];
	int n = 0;
	for (uint32_t k = 0; k < T[i].n; k++) {
		float t, u, v;
		if (n < 512 && tri_intersect(&r, T[i].v[3 * k], T[i].v[3 * k + 1], T[i].v[3 * k + 2], INFINITY, &t, &u, &v))
			ts[n++] = t;
	}
	int distinct = 0;
	for (int a = 0; a < n; a++) {
		bool seen = false;
		for (int b = 0; b < a; b++)
			seen |= ts[b] == ts[a];
		distinct += !seen;
	}
	return distinct & 1;
}

static bool ref_inside(const world *w, const tris *T, const csg_case *c, size_t i, vec3 p)
{
	if ((int)i < c->joined) { /* the parity of the crossings of every piece: one mesh's */
		bool in = false;
		for (int k = 0; k < c->joined; k++)
			in ^= ref_inside_raw(w, T, (size_t)k, p);
		return in != c->inverse[i];
	}
	return ref_inside_raw(w, T, i, p) != c->inverse[i];
}

/* The solid's inside at p, by brute force; `leaf` (>= 0) forced to `value`. */
static bool ref_solid(const world *w, const tris *T, const csg_case *c, bool (*f)(const bool *), vec3 p, int leaf,
		      bool value)
{
	bool in[MAX_LEAVES];
	for (int i = 0; i < c->n; i++) /* a piece of the joined mesh forces every piece */
		in[i] = i == leaf || (i < c->joined && leaf >= 0 && leaf < c->joined) ? value : ref_inside(w, T, c, (size_t)i, p);
	return f(in);
}

/* The first hit of the ray on the solid's boundary, by brute force: the first triangle hit of a
 * visible object where the solid's inside depends on that object's. */
static bool ref_hit(const world *w, const tris *T, const csg_case *c, bool (*f)(const bool *), vec3 o, vec3 d,
		    float *t_out)
{
	tri_ray r;
	if (!tri_ray_prepare(&r, o, d, 0.0f, INFINITY))
		return false;
	float best = INFINITY;
	for (int i = 0; i < c->n; i++) {
		if (c->clip[i])
			continue;
		for (uint32_t k = 0; k < T[i].n; k++) {
			float t, u, v;
			if (!tri_intersect(&r, T[i].v[3 * k], T[i].v[3 * k + 1], T[i].v[3 * k + 2], INFINITY, &t, &u, &v) ||
			    t >= best)
				continue;
			vec3 p = v3_add(o, v3_scale(d, t));
			if (ref_solid(w, T, c, f, p, i, true) != ref_solid(w, T, c, f, p, i, false))
				best = t;
		}
	}
	*t_out = best;
	return best < INFINITY;
}

static vec3 rand_in(rng *g, float s)
{
	return v3(s * (2 * rng_float(g) - 1), s * (2 * rng_float(g) - 1), s * (2 * rng_float(g) - 1));
}

static void check_case(const csg_case *c, bool (*f)(const bool *))
{
	char text[2048];
	snprintf(text, sizeof text, "%s%s", CAMERA, c->text);
	world *w;
	CHECK(build(text, &w), "%s: built", c->name);
	if (!w)
		return;
	CHECK(w->n_insts == (size_t)c->n, "%s: %zu objects, expected %d", c->name, w->n_insts, c->n);
	if (w->n_insts != (size_t)c->n) {
		world_free(w);
		return;
	}
	tris T[MAX_LEAVES];
	for (int i = 0; i < c->n; i++)
		T[i] = world_tris(&w->insts[i]);
	rng g;
	rng_seed(&g, 7, (uint64_t)(c - cases));
	/* Insides of points: the build's (world_inside) against brute force. */
	int points = 2000, bad_in = 0;
	for (int k = 0; k < points; k++) {
		vec3 p = rand_in(&g, 1.5f);
		for (int i = 0; i < c->n; i++)
			bad_in += world_inside(w, (uint32_t)i, p) != ref_inside(w, T, c, (size_t)i, p);
	}
	CHECK(bad_in <= 2, "%s: %d of %d inside tests differ from brute force", c->name, bad_in, points * c->n);
	/* Rays: closest hits, shadow rays, normals. */
	int rays = 2000, bad_t = 0, bad_shadow = 0, bad_normal = 0, hits = 0;
	for (int k = 0; k < rays; k++) {
		vec3 o = v3_scale(v3_normalize(rand_in(&g, 1.0f)), 3.0f);
		if (k % 4 == 0)
			o = rand_in(&g, 1.2f); /* from inside the operands too */
		vec3 d = v3_normalize(v3_sub(rand_in(&g, 1.0f), o));
		float tref;
		bool href = ref_hit(w, T, c, f, o, d, &tref);
		render_ray ray = {o, d};
		render_hit h;
		bool hw = w->rs.intersect(w->rs.user, &ray, 0.0f, INFINITY, &h);
		hits += hw;
		if (hw != href || (hw && fabsf(h.t - tref) > 1e-4f)) {
			bad_t++;
			continue;
		}
		float tmax = 3.0f * rng_float(&g);
		bool occ = w->rs.occluded(w->rs.user, &ray, 0.0f, tmax);
		bad_shadow += occ != (href && tref <= tmax);
		/* A ray from outside a closed solid (not clipped: that one is open) enters at its first
		 * boundary hit: the normal faces it. */
		bool closed = true;
		for (int i = 0; i < c->n; i++)
			closed &= !c->clip[i];
		if (hw && closed && !ref_solid(w, T, c, f, o, -1, false) && v3_dot(h.ng, d) >= 0.0f)
			bad_normal++;
	}
	CHECK(hits > rays / 4, "%s: only %d of %d rays hit the solid", c->name, hits, rays);
	CHECK(bad_t <= 3, "%s: %d of %d closest hits differ from brute force", c->name, bad_t, rays);
	CHECK(bad_shadow <= 3, "%s: %d of %d shadow rays differ from brute force", c->name, bad_shadow, rays);
	/* An open cylinder's analytic inside and its inscribed tube differ by the tessellation's
	 * error: a ray starting in that sliver sees the tube from the other side (a few in 2000). */
	CHECK(bad_normal <= 10, "%s: %d entering hits have a normal away from the ray", c->name, bad_normal);
	printf("%s: %d rays (%d hit), %d differ; %d inside tests, %d differ\n", c->name, rays, hits, bad_t, points * c->n,
	       bad_in);
	for (int i = 0; i < c->n; i++)
		free(T[i].v);
	world_free(w);
}

/* A circle traced on an SSS solid (a wax sphere less a box and a cylinder: a hit on the sphere
 * is kept outside them, one on the box or cylinder inside the sphere): every crossing of its
 * boundary found by sampling the circle at 50000 angles is a hit of the circle query within a
 * sample's angle, and the query has no other. */
static bool f_circle(const bool *in) { return in[0] && !in[1] && !in[2]; }

static void check_circle(void)
{
	char text[1024];
	snprintf(text, sizeof text,
		 "%sdifference { sphere { 0, 1 } box { <0.3, -2, -2>, <2, 2, 2> } cylinder { -2*z, 2*z, 0.35 }\n"
		 "  material { wax { } } rotate 15*y }\n",
		 CAMERA);
	world *w;
	CHECK(build(text, &w), "circle: built");
	if (!w)
		return;
	rng g;
	rng_seed(&g, 11, 0);
	int circles = 40, missing = 0, extra = 0, crossings = 0;
	enum { N = 50000, MAXH = 256 };
	for (int k = 0; k < circles; k++) {
		/* A circle about a point near the origin, in a random plane. */
		vec3 centre = rand_in(&g, 0.6f);
		vec3 t = v3_normalize(rand_in(&g, 1.0f)), n = v3_normalize(v3_cross(t, v3_normalize(rand_in(&g, 1.0f))));
		tri_circle q = {centre, t, n, 0.3f + 0.6f * rng_float(&g), true};
		render_hit at = {.object = 0};
		tri_circle_hit hits[MAXH];
		bool more;
		uint32_t nh = w->rs.circle(w->rs.user, &at, &q, hits, MAXH, &more);
		CHECK(!more, "circle %d: more hits than the buffer", k);
		bool used[MAXH] = {false};
		bool prev = false;
		float step = 2.0f * (float)M_PI / N;
		for (int s = 0; s <= N; s++) {
			float a = s * step;
			vec3 p = v3_add(centre, v3_scale(v3_add(v3_scale(t, cosf(a)), v3_scale(n, sinf(a))), q.radius));
			/* world_inside: the parity test the rays' cases checked against brute force */
			bool ins[3] = {world_inside(w, 0, p), world_inside(w, 1, p), world_inside(w, 2, p)};
			bool in = f_circle(ins);
			if (s > 0 && in != prev) {
				crossings++;
				bool found = false;
				for (uint32_t h = 0; h < nh && !found; h++) {
					float d = fabsf(remainderf(hits[h].theta - (a - 0.5f * step), 2.0f * (float)M_PI));
					if (!used[h] && d <= 1.5f * step)
						used[h] = found = true;
				}
				missing += !found;
			}
			prev = in;
		}
		for (uint32_t h = 0; h < nh; h++)
			extra += !used[h];
	}
	CHECK(crossings > circles, "circle: only %d crossings in %d circles", crossings, circles);
	CHECK(missing <= 2 && extra <= 2, "circle: of %d crossings %d missing from the query, %d hits not crossings",
	      crossings, missing, extra);
	printf("circle: %d circles, %d crossings, %d missing, %d extra\n", circles, crossings, missing, extra);
	world_free(w);
}

int main(void)
{
	if (!mkdtemp(dir))
		return 99;
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
		check_case(&cases[i], cases[i].f);
	check_circle();
	rmdir(dir);
	return check_done("test_csg");
}
