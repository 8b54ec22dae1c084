/* test_subdiv: OpenSubdiv tessellation - counts, limit positions, creases, corners, boundaries,
 * adaptive rates, crack-free output, and levels or memory over the limit refused. */
#include "check.h"
#include "shapes.h"
#include "geom/subdiv.h"

#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* OpenSubdiv's catmark_cube is the cube [-1, 1]^3 turned 45 degrees about z: the largest
 * coordinate of the output in the cube's own axes. */
static float cube_extent(const mesh *m)
{
	float r = 0;
	for (uint32_t v = 0; v < m->num_vertices; v++) {
		vec3 p = m->positions[v];
		vec3 q = v3((p.x + p.y) * 0.70710678f, (p.x - p.y) * 0.70710678f, p.z);
		r = fmaxf(r, v3_max_comp(v3_abs(q)));
	}
	return r;
}

/* The mean of that over the vertices: grows as creases pull the surface to the cage. */
static float cube_mean(const mesh *m)
{
	double sum = 0;
	for (uint32_t v = 0; v < m->num_vertices; v++) {
		vec3 p = m->positions[v];
		vec3 q = v3((p.x + p.y) * 0.70710678f, (p.x - p.y) * 0.70710678f, p.z);
		sum += v3_max_comp(v3_abs(q));
	}
	return (float)(sum / m->num_vertices);
}

/* The output vertex nearest the ray from the origin along dir. */
static vec3 vertex_along(const mesh *m, vec3 dir)
{
	dir = v3_normalize(dir);
	vec3 best = m->positions[0];
	float bd = -2;
	for (uint32_t v = 0; v < m->num_vertices; v++) {
		float d = v3_dot(v3_normalize(m->positions[v]), dir);
		if (d > bd)
			bd = d, best = m->positions[v];
	}
	return best;
}

static bool has_vertex(const mesh *m, vec3 p, float tol)
{
	for (uint32_t v = 0; v < m->num_vertices; v++)
		if (v3_length(v3_sub(m->positions[v], p)) <= tol)
			return true;
	return false;
}

static bool tess(const subd_cage *c, int level, mesh *m)
{
	diag d;
	diag_init(&d, stderr);
	subd_options o = {.level = level};
	bool ok = subd_tessellate(c, &o, m, &d, diag_noloc());
	diag_free(&d);
	return ok;
}

static void check_cube(void)
{
	test_cage *t = cage_read(shape_path("catmark_cube.obj"));
	CHECK(t != NULL, "read the cube");
	if (!t)
		return;
	mesh m;
	CHECK(tess(&t->c, 3, &m) && m.num_triangles == 768, "cube level 3: %u triangles", m.num_triangles);
	CHECK(open_edges(&m) == 0, "cube level 3 with UVs is closed (%ld open edges)", open_edges(&m));
	CHECK(m.uvs != NULL, "the cube's UVs are kept");
	mesh_free(&m);
	/* Without UVs, shared points are shared vertices: closed by index alone. */
	subd_cage c = t->c;
	c.uvs = NULL, c.uv_indices = NULL, c.num_uvs = 0;
	CHECK(tess(&c, 6, &m) && m.num_triangles == 6 * 2 * 4096, "level 6: %u triangles", m.num_triangles);
	CHECK(open_edges(&m) == 0, "cube level 6 is closed");
	/* Limit points of the cube [-1, 1]^3 (Catmull-Clark limit masks, Halstead et al. 1993): a
	 * corner goes halfway to the centre, a face centre to 68/81 along its axis. */
	vec3 corner = vertex_along(&m, t->data.positions[0]), face = vertex_along(&m, v3(0, 0, 1));
	CHECK_NEAR(corner.y, 0.5 * t->data.positions[0].y, 1e-6);
	CHECK_NEAR(corner.z, 0.5 * t->data.positions[0].z, 1e-6);
	CHECK_NEAR(face.z, 68.0 / 81.0, 1e-6);
	CHECK_NEAR(face.x, 0.0, 1e-6);
	/* Limit normals are unit and outward; at the face centre they are the axis. */
	long bad = 0;
	for (uint32_t v = 0; v < m.num_vertices; v++)
		bad += !(fabsf(v3_length(m.normals[v]) - 1.0f) < 1e-4f && v3_dot(m.normals[v], m.positions[v]) > 0);
	CHECK(bad == 0, "%ld normals not unit and outward", bad);
	float smooth_max = cube_extent(&m), smooth_mean = cube_mean(&m);
	mesh_free(&m);

	/* Creases: every edge infinitely sharp gives the cage itself (corners stay, faces flat). */
	uint32_t pairs[24];
	float sharp[12];
	int ne = 0;
	for (uint32_t f = 0, k = 0; f < c.num_faces; k += c.face_sizes[f], f++)
		for (uint32_t i = 0; i < 4; i++) {
			uint32_t a = c.face_indices[k + i], b = c.face_indices[k + (i + 1) % 4];
			if (a < b)
				pairs[2 * ne] = a, pairs[2 * ne + 1] = b, sharp[ne++] = 10.0f;
		}
	c.crease_vertices = pairs, c.crease_sharpness = sharp, c.num_creases = (uint32_t)ne;
	CHECK(tess(&c, 4, &m), "all-sharp cube");
	CHECK_NEAR(cube_extent(&m), 1.0, 1e-6);
	CHECK(has_vertex(&m, t->data.positions[0], 1e-6f), "a sharp corner stays on its cage vertex");
	CHECK(open_edges(&m) == 0, "the sharp cube is closed");
	mesh_free(&m);
	/* Semi-sharp creases pull the surface towards the cage, monotonically in sharpness. */
	float prev = smooth_mean;
	for (float s = 1.0f; s <= 3.0f; s += 1.0f) {
		for (int i = 0; i < ne; i++)
			sharp[i] = s;
		CHECK(tess(&c, 4, &m), "sharpness %g", s);
		float mx = cube_mean(&m);
		CHECK(mx > prev && cube_extent(&m) <= 1.0f + 1e-6f, "sharpness %g: mean %g after %g", s, mx, prev);
		prev = mx;
		mesh_free(&m);
	}
	/* A corner: one sharp vertex is interpolated, the others are not. */
	c.num_creases = 0;
	uint32_t cv = 0;
	float cs = 10.0f;
	c.corner_vertices = &cv, c.corner_sharpness = &cs, c.num_corners = 1;
	CHECK(tess(&c, 4, &m), "cube with a corner");
	CHECK(has_vertex(&m, t->data.positions[0], 1e-6f) && !has_vertex(&m, t->data.positions[7], 1e-3f), "the corner interpolates vertex 0 only");
	mesh_free(&m);

	/* The creased test shape of OpenSubdiv: differs from the smooth cube, stays closed. */
	test_cage *cr = cage_read(shape_path("catmark_cube_creases1.obj"));
	CHECK(cr && tess(&cr->c, 4, &m), "catmark_cube_creases1");
	if (cr) {
		CHECK(cube_extent(&m) > smooth_max + 0.01f, "creases1 is sharper than the smooth cube: %g vs %g", cube_extent(&m), smooth_max);
		CHECK(open_edges(&m) == 0, "creases1 is closed");
		mesh_free(&m);
	}
	test_cage_free(cr);
	test_cage_free(t);
}

/* An open 2x2-quad patch: edge_and_corner interpolates the patch corners, edge_only does not. */
static void check_boundary(void)
{
	vec3 p[9];
	for (int i = 0; i < 9; i++)
		p[i] = v3((float)(i % 3), (float)(i / 3), (i == 4) ? 0.5f : 0.0f);
	uint32_t sizes[4] = {4, 4, 4, 4}, idx[16] = {0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7};
	subd_cage c = {.positions = p, .num_vertices = 9, .face_sizes = sizes, .num_faces = 4, .face_indices = idx};
	mesh m;
	c.boundary = SUBD_BOUNDARY_EDGE_AND_CORNER;
	CHECK(tess(&c, 3, &m) && has_vertex(&m, p[0], 1e-6f) && has_vertex(&m, p[8], 1e-6f), "edge_and_corner keeps corners");
	mesh_free(&m);
	c.boundary = SUBD_BOUNDARY_EDGE_ONLY;
	CHECK(tess(&c, 3, &m) && !has_vertex(&m, p[0], 1e-3f), "edge_only rounds corners");
	mesh_free(&m);
}

/* Loop on an octahedron: 8 * 4^level triangles, closed, on the unit sphere's inside. */
static void check_loop(void)
{
	vec3 p[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
	uint32_t sizes[8] = {3, 3, 3, 3, 3, 3, 3, 3};
	uint32_t idx[24] = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
	subd_cage c = {.positions = p, .num_vertices = 6, .face_sizes = sizes, .num_faces = 8, .face_indices = idx,
		       .scheme = SUBD_LOOP};
	mesh m;
	CHECK(tess(&c, 3, &m) && m.num_triangles == 8 * 64, "loop octahedron level 3: %u", m.num_triangles);
	CHECK(open_edges(&m) == 0, "loop octahedron is closed");
	float r = 0;
	for (uint32_t v = 0; v < m.num_vertices; v++)
		r = fmaxf(r, v3_max_comp(v3_abs(m.positions[v])));
	CHECK(r < 1.0f, "the loop limit lies inside the cage (%g)", r);
	mesh_free(&m);
	/* Quads are refused by loop. */
	uint32_t qs[1] = {4}, qi[4] = {0, 2, 1, 3};
	subd_cage q = {.positions = p, .num_vertices = 6, .face_sizes = qs, .num_faces = 1, .face_indices = qi,
		       .scheme = SUBD_LOOP};
	CHECK(!tess(&q, 1, &m), "loop with a quad is an error");
}

static void check_adaptive(void)
{
	test_cage *t = cage_read(shape_path("catmark_torus.obj"));
	CHECK(t != NULL, "read the torus");
	if (!t)
		return;
	diag d;
	diag_init(&d, stderr);
	uint32_t counts[2];

	for (int i = 0; i < 2; i++) {
		subd_camera cam = {v3(0, 2, i ? -40.0f : -4.0f), v3(0, 0, 1), v3(0, 1, 0), 40.0f, 480};
		subd_options o = {.max_edge_px = 1.0f, .camera = &cam};
		mesh m;
		CHECK(subd_tessellate(&t->c, &o, &m, &d, diag_noloc()), "adaptive torus");
		counts[i] = m.num_triangles;
		CHECK(open_edges(&m) == 0, "adaptive torus %d: %ld open edges", i, open_edges(&m));
		uint64_t bytes, est = subd_estimate(&t->c, &o, &bytes);
		CHECK(est >= m.num_triangles, "estimate %llu >= actual %u", (unsigned long long)est, m.num_triangles);
		mesh_free(&m);
	}
	CHECK(counts[1] < counts[0] / 4, "far torus %u triangles, near %u", counts[1], counts[0]);
	diag_free(&d);
	test_cage_free(t);
}

static void check_errors(void)
{
	test_cage *t = cage_read(shape_path("catmark_cube.obj"));
	if (!t)
		return;
	FILE *log = tmpfile();
	diag d;
	diag_init(&d, log);
	mesh m;
	int levels[] = {16, -1, 31};
	for (int i = 0; i < 3; i++) {
		subd_options o = {.level = levels[i]};
		CHECK(!subd_tessellate(&t->c, &o, &m, &d, diag_noloc()) && m.num_triangles == 0, "level %d refused", levels[i]);
	}
	/* Level 12 of the cube: 2.0e8 triangles, about 19 GiB: over the default limit. */
	subd_options big = {.level = 12};
	CHECK(!subd_tessellate(&t->c, &big, &m, &d, diag_noloc()), "level 12 over 1 GiB refused");
	subd_options small = {.level = 5, .max_bytes = 1 << 20};
	CHECK(!subd_tessellate(&t->c, &small, &m, &d, diag_noloc()), "level 5 over 1 MiB refused");
	subd_cage c = t->c;
	uint32_t pair[2] = {0, 7};
	float s = 2.0f;
	c.crease_vertices = pair, c.crease_sharpness = &s, c.num_creases = 1;
	subd_options o = {.level = 1};
	CHECK(!subd_tessellate(&c, &o, &m, &d, diag_noloc()), "a crease on a non-edge is refused");
	c = t->c;
	t->data.face_indices[5] = 99;
	CHECK(!subd_tessellate(&c, &o, &m, &d, diag_noloc()), "an index out of range is refused");
	CHECK(d.errors == 7, "%d errors reported", d.errors);
	rewind(log);
	char text[4096] = {0};
	fread(text, 1, sizeof text - 1, log);
	CHECK(strstr(text, "level 16 out of range") && strstr(text, "MiB") && strstr(text, "not an edge") &&
		      strstr(text, "out of range (there are 8)"),
	      "messages: %s", text);
	fclose(log);
	diag_free(&d);
	test_cage_free(t);
}

/* The topology OpenSubdiv itself refuses (its Create returns null): a vertex of valence 65536, one
 * over its limit, at the centre of a fan of triangles. Other oddities - an edge of three faces,
 * a vertex repeated in a face, inconsistent winding - it accepts. */
static void check_valence_limit(void)
{
	enum { N = 65536 };
	vec3 *p = malloc((N + 1) * sizeof *p);
	uint32_t *sizes = malloc(N * sizeof *sizes), *idx = malloc(3 * (size_t)N * sizeof *idx);
	p[0] = v3(0, 0, 0);
	for (uint32_t i = 0; i < N; i++) {
		double a = 2 * M_PI * i / N;
		p[i + 1] = v3((float)cos(a), (float)sin(a), 0);
		sizes[i] = 3, idx[3 * i] = 0, idx[3 * i + 1] = i + 1, idx[3 * i + 2] = (i + 1) % N + 1;
	}
	subd_cage c = {.positions = p, .num_vertices = N + 1, .face_sizes = sizes, .num_faces = N, .face_indices = idx,
		       .source = "fan.obj"};
	FILE *log = tmpfile();
	diag d;
	diag_init(&d, log);
	subd_options o = {.level = 1};
	mesh m;
	CHECK(!subd_tessellate(&c, &o, &m, &d, diag_noloc()), "a vertex of valence %d is refused", N);
	rewind(log);
	char text[1024] = {0};
	fread(text, 1, sizeof text - 1, log);
	CHECK(strstr(text, "subdivision surface of 'fan.obj': invalid cage topology") && strstr(text, "valence 65536"),
	      "message: %s", text);
	fclose(log);
	diag_free(&d);
	free(p), free(sizes), free(idx);
}

int main(void)
{
	check_cube();
	check_boundary();
	check_loop();
	check_adaptive();
	check_errors();
	check_valence_limit();
	return check_done("test_subdiv");
}
