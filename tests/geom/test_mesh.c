/* test_mesh: primitives (the spheres' levels and their error bound, the plane out to its horizon),
 * mesh2 arrays, the Assimp importer (OBJ, GLB, PLY) and its errors, tangents and transforms. */
#include "check.h"
#include "geom/mesh.h"
#include "geom/ply.h"
#include "geom/prim.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const char *asset(const char *rel)
{
	static char buf[4096];
	const char *top = getenv("top_srcdir");
	snprintf(buf, sizeof buf, "%s/scenes/assets/%s", top ? top : ".", rel);
	return buf;
}

/* Every triangle's geometric normal agrees with its vertices' shading normals and points away
 * from `inside`; the mesh's area is returned. */
static double check_outward(const char *name, const mesh *m, vec3 inside)
{
	double area = 0;
	long bad = 0;
	for (uint32_t f = 0; f < m->num_triangles; f++) {
		const uint32_t *ix = m->indices + 3 * f;
		vec3 a = m->positions[ix[0]], b = m->positions[ix[1]], c = m->positions[ix[2]];
		vec3 ng = v3_cross(v3_sub(b, a), v3_sub(c, a));
		area += 0.5 * v3_length(ng);
		vec3 centre = v3_scale(v3_add(a, v3_add(b, c)), 1.0f / 3.0f);
		bool ok = v3_dot(ng, v3_sub(centre, inside)) > 0;
		for (int k = 0; k < 3 && m->normals; k++)
			ok = ok && v3_dot(ng, m->normals[ix[k]]) > 0;
		bad += !ok;
	}
	CHECK(bad == 0, "%s: %ld triangles face inwards", name, bad);
	return area;
}

static void check_prims(void)
{
	mesh m;
	CHECK(prim_sphere(v3(1, 2, 3), 2.0f, 64, &m), "sphere");
	double area = check_outward("sphere", &m, v3(1, 2, 3));
	CHECK(fabs(area - 4 * M_PI * 4) < 0.01 * 4 * M_PI * 4, "sphere area %g", area);
	long off = 0;
	for (uint32_t v = 0; v < m.num_vertices; v++)
		off += fabsf(v3_length(v3_sub(m.positions[v], v3(1, 2, 3))) - 2.0f) > 1e-5f;
	CHECK(off == 0, "%ld sphere vertices off the sphere", off);
	mesh_free(&m);
	CHECK(prim_sphere_segments(1.0f, 1e-3f) >= 70 && prim_sphere_segments(1.0f, 1e-3f) <= 72,
	      "segments for 1e-3 error: %u", prim_sphere_segments(1.0f, 1e-3f));

	CHECK(prim_box(v3(1, 1, 1), v3(-1, 0, 2), &m) && m.num_triangles == 12, "box");
	area = check_outward("box", &m, v3(0, 0.5f, 1.5f));
	CHECK_NEAR(area, 2 * (2 * 1 + 2 * 1 + 1 * 1), 1e-5);
	mesh_free(&m);

	/* The plane y = 1 cut by the box [-1, 1]^3 grown 1 % of its size on each side: a square of side 2.04. */
	CHECK(prim_plane(v3(0, 2, 0), 1.0f, v3(-1, -1, -1), v3(1, 1, 1), &m), "plane");
	area = 0;
	for (uint32_t f = 0; f < m.num_triangles; f++) {
		const uint32_t *ix = m.indices + 3 * f;
		vec3 ng = v3_cross(v3_sub(m.positions[ix[1]], m.positions[ix[0]]), v3_sub(m.positions[ix[2]], m.positions[ix[0]]));
		CHECK(ng.y > 0, "plane triangle %u faces along the normal", f);
		area += 0.5 * v3_length(ng);
	}
	CHECK_NEAR(area, 2.04 * 2.04, 1e-4);
	for (uint32_t v = 0; v < m.num_vertices; v++)
		CHECK_NEAR(m.positions[v].y, 1.0, 1e-6);
	mesh_free(&m);
	/* A slanted plane through a box: a hexagon. */
	CHECK(prim_plane(v3(1, 1, 1), 0.0f, v3(-1, -1, -1), v3(1, 1, 1), &m) && m.num_vertices == 6, "hexagon: %u vertices", m.num_vertices);
	mesh_free(&m);
	CHECK(!prim_plane(v3(0, 1, 0), 5.0f, v3(-1, -1, -1), v3(1, 1, 1), &m), "a plane missing the bounds is empty");
	CHECK(!prim_plane(v3(0, 0, 0), 0.0f, v3(-1, -1, -1), v3(1, 1, 1), &m), "a zero normal is refused");
}

/* prim_sphere_rel_error bounds how deep each level's unit sphere lies inside the true one, and
 * nearly reaches it: points over every triangle stay within the bound, the deepest near it. */
static void check_sphere_levels(void)
{
	double last = 1.0;
	for (uint32_t k = 0; k < PRIM_SPHERE_LEVELS; k++) {
		uint32_t seg = prim_sphere_level_segments(k);
		double bound = prim_sphere_rel_error(seg), deepest = 0.0;
		mesh m;
		CHECK(prim_sphere(v3(0, 0, 0), 1.0f, seg, &m), "level %u", k);
		for (uint32_t f = 0; f < m.num_triangles; f++) {
			const uint32_t *ix = m.indices + 3 * f;
			for (int a = 0; a <= 8; a++)
				for (int b = 0; a + b <= 8; b++) {
					double u = a / 8.0, v = b / 8.0, w = 1.0 - u - v;
					dvec3 p = d3_add(d3_add(d3_scale(v3_to_d3(m.positions[ix[0]]), w),
								d3_scale(v3_to_d3(m.positions[ix[1]]), u)),
							 d3_scale(v3_to_d3(m.positions[ix[2]]), v));
					deepest = fmax(deepest, 1.0 - d3_length(p));
				}
		}
		CHECK(deepest <= bound * (1 + 1e-6) + 1e-7 && deepest >= 0.8 * bound,
		      "level %u (%u segments): deepest point %.4g, bound %.4g", k, seg, deepest, bound);
		CHECK(bound < last / 3.9, "level %u's error %.3g is a quarter of the coarser one's %.3g", k, bound, last);
		last = bound;
		mesh_free(&m);
	}
	CHECK(prim_sphere_rel_error(PRIM_SPHERE_MIN_SEGMENTS) < 0.01, "the coarsest level errs %.3g of the radius",
	      prim_sphere_rel_error(PRIM_SPHERE_MIN_SEGMENTS));
}

/* The plane seen from an eye: on the plane, facing its normal, closed (every inner edge shared by
 * two triangles: no T-junctions), covering the square out to the horizon's distance around the
 * eye's foot, and its UVs do not move with the eye. */
static void check_plane_view(void)
{
	mesh m, m2;
	vec3 eye = v3(3, 2, -1);
	CHECK(prim_plane_view(v3(0, 2, 0), 0.5f, eye, 1e-4f, &m), "plane seen from an eye");
	double half = 1.5 / tan(1e-4), lo_x = INFINITY, hi_x = -INFINITY, area = 0.0;
	for (uint32_t v = 0; v < m.num_vertices; v++) {
		CHECK_NEAR(m.positions[v].y, 0.5, 1e-6 * half);
		lo_x = fmin(lo_x, m.positions[v].x), hi_x = fmax(hi_x, m.positions[v].x);
	}
	CHECK(lo_x <= 3 - half && hi_x >= 3 + half, "the plane spans x %g to %g, %g either side of the foot wanted",
	      lo_x, hi_x, half);
	long open = 0;
	for (uint32_t f = 0; f < m.num_triangles; f++) {
		const uint32_t *ix = m.indices + 3 * f;
		vec3 ng = v3_cross(v3_sub(m.positions[ix[1]], m.positions[ix[0]]), v3_sub(m.positions[ix[2]], m.positions[ix[0]]));
		CHECK(ng.y > 0, "plane triangle %u faces along the normal", f);
		area += 0.5 * v3_length(ng);
		for (int e = 0; e < 3; e++) {
			uint32_t a = ix[e], b = ix[(e + 1) % 3];
			int shared = 0;
			for (uint32_t g = 0; g < m.num_triangles; g++)
				for (int k = 0; k < 3; k++)
					shared += m.indices[3 * g + k] == b && m.indices[3 * g + (k + 1) % 3] == a;
			open += shared != 1;
		}
	}
	CHECK(open == 4, "%ld edges without their twin (the outer square's 4 expected)", open);
	CHECK_NEAR(area, (hi_x - lo_x) * (hi_x - lo_x), 1e-4 * (hi_x - lo_x) * (hi_x - lo_x));
	/* The same point of the plane has the same UV seen from elsewhere. */
	CHECK(prim_plane_view(v3(0, 2, 0), 0.5f, v3(-7, 9, 4), 1e-4f, &m2), "another eye");
	vec2 uv = m.uvs[0];
	vec3 p = m.positions[0];
	vec3 b1, b2;
	v3_basis(v3(0, 1, 0), &b1, &b2);
	vec3 q = m2.positions[0];
	vec3 d = v3_sub(p, q);
	CHECK_NEAR(uv.x - m2.uvs[0].x, v3_dot(d, b1), 1e-6 * half);
	CHECK_NEAR(uv.y - m2.uvs[0].y, v3_dot(d, b2), 1e-6 * half);
	mesh_free(&m), mesh_free(&m2);
	CHECK(!prim_plane_view(v3(0, 0, 0), 0.0f, eye, 1e-4f, &m), "a zero normal is refused");
	/* An eye on the plane still gets a plane reaching out under the scene. */
	CHECK(prim_plane_view(v3(0, 1, 0), 0.0f, v3(0, 0, 0), 1e-4f, &m) && m.num_triangles > 0, "eye on the plane");
	mesh_free(&m);
	/* The rings scale with the scene: seen from 1e-8 above, the innermost square is 1e-8 wide. */
	CHECK(prim_plane_view(v3(0, 1, 0), 0.0f, v3(3e-8f, 1e-8f, 0), 1e-4f, &m), "a scene of 1e-8");
	float inner = 0.0f;
	for (uint32_t v = 0; v < 4; v++)
		inner = fmaxf(inner, fabsf(m.positions[v].z));
	CHECK(inner > 0.99e-8f && inner < 1.01e-8f, "the innermost ring's half-size is %g, expected 1e-8", inner);
	mesh_free(&m);
}

static void check_arrays(void)
{
	vec3 p[4] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
	vec3 n[1] = {{0, 0, 2}};
	vec2 uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
	uint32_t fi[6] = {0, 1, 2, 0, 2, 3}, ni[6] = {0, 0, 0, 0, 0, 0};
	mesh_arrays a = {p, 4, n, 1, uv, 4, fi, ni, NULL, 2};
	diag d;
	FILE *log = tmpfile();
	diag_init(&d, log);
	mesh m;
	CHECK(mesh_from_arrays(&a, &m, &d, diag_noloc()) && m.num_vertices == 4 && m.num_triangles == 2, "mesh2 quad");
	CHECK(m.normals && fabsf(m.normals[0].z - 1.0f) < 1e-6f, "normals normalised");
	CHECK(mesh_generate_tangents(&m) && fabsf(m.tangents[0].t.x - 1.0f) < 1e-5f && m.tangents[0].sign == 1.0f,
	      "tangent along +u");
	xform t = xform_translate(d3(0, 0, 5));
	mesh_transform(&m, &t);
	CHECK_NEAR(m.positions[2].z, 5.0, 0);
	xform s;
	xform_scale(d3(-1, 1, 1), &s);
	uint32_t before = m.indices[1];
	mesh_transform(&m, &s);
	CHECK(m.indices[2] == before, "a mirror flips the winding");
	mesh_free(&m);
	fi[4] = 7;
	CHECK(!mesh_from_arrays(&a, &m, &d, diag_noloc()), "index out of range refused");
	rewind(log);
	char text[512] = {0};
	fread(text, 1, sizeof text - 1, log);
	CHECK(strstr(text, "face 1: vertex index 7 out of range (there are 4)") != NULL, "message: %s", text);
	fclose(log);
	diag_free(&d);
}

static void check_import(void)
{
	diag d;
	diag_init(&d, stderr);
	mesh obj, glb;
	CHECK(mesh_import(asset("lee_perry_smith_head/LeePerrySmith.obj"), &obj, &d), "head OBJ");
	CHECK(obj.num_triangles == 17684 && obj.uvs && obj.normals, "head OBJ: %u triangles", obj.num_triangles);
	CHECK(mesh_import(asset("lee_perry_smith_head/LeePerrySmith.glb"), &glb, &d), "head GLB");
	CHECK(glb.num_triangles == 17684 && glb.uvs && glb.normals, "head GLB: %u triangles", glb.num_triangles);
	/* The normal map needs tangents; the files have none, so they are generated. */
	if (!glb.tangents)
		CHECK(mesh_generate_tangents(&glb), "tangents of the head");
	long bad = 0;
	for (uint32_t v = 0; glb.tangents && v < glb.num_vertices; v++)
		bad += !(fabsf(v3_length(glb.tangents[v].t) - 1.0f) < 1e-3f && fabsf(v3_dot(glb.tangents[v].t, glb.normals[v])) < 1e-3f);
	CHECK(bad == 0, "%ld tangents not unit or not orthogonal to the normal", bad);
	vec3 lo1, hi1, lo2, hi2;
	mesh_bounds(&obj, &lo1, &hi1), mesh_bounds(&glb, &lo2, &hi2);
	CHECK(v3_length(v3_sub(hi1, lo1)) > 0 && v3_length(v3_sub(hi2, lo2)) > 0, "bounds");
	mesh_free(&obj), mesh_free(&glb);

	/* PLY, written to the build directory. */
	FILE *f = fopen("test_mesh_quad.ply", "w");
	fputs("ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
	      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n",
	      f);
	fclose(f);
	mesh ply;
	CHECK(mesh_import("test_mesh_quad.ply", &ply, &d) && ply.num_triangles == 2, "PLY quad: %u triangles", ply.num_triangles);
	mesh_free(&ply);
	remove("test_mesh_quad.ply");
	diag_free(&d);

	/* Errors name the file and give Assimp's reason. */
	FILE *log = tmpfile();
	diag_init(&d, log);
	mesh m;
	CHECK(!mesh_import("no/such/file.obj", &m, &d) && d.errors == 1, "a missing file is an error");
	/* A truncated PLY (Assimp 5 would abort on it: ply.c checks first). */
	f = fopen("test_mesh_short.ply", "w");
	fputs("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
	      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n",
	      f);
	fclose(f);
	CHECK(!mesh_import("test_mesh_short.ply", &m, &d), "a truncated PLY is an error");
	remove("test_mesh_short.ply");
	f = fopen("test_mesh_bad.obj", "w");
	fputs("v 0 0 0\nf 1 2 3\n", f);
	fclose(f);
	CHECK(!mesh_import("test_mesh_bad.obj", &m, &d), "a broken OBJ is an error");
	remove("test_mesh_bad.obj");
	rewind(log);
	char text[2048] = {0};
	fread(text, 1, sizeof text - 1, log);
	CHECK(strstr(text, "no/such/file.obj: error: cannot import mesh: ") &&
		  strstr(text, "test_mesh_bad.obj: error: cannot import mesh: OBJ: vertex index out of range") &&
		  strstr(text, "test_mesh_short.ply: error: cannot import mesh: the PLY data ends in element 'face' 1 of "
			       "the 1 its header declares (a truncated file?)"),
	      "messages: %s", text);
	fclose(log);
	diag_free(&d);
}

/* ply_check on files in memory: each structural fault with its reason, and complete files of
 * every format pass (a binary one truncated by a byte does not). */
static void check_ply(void)
{
	const char *vtx = "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n";
	const char *face = "element face 1\nproperty list uchar int vertex_indices\n";
	static const struct {
		const char *text, *why; /* why NULL: passes */
	} cases[] = {
	    {"not a ply file at all", NULL},
	    {"ply\nformat ascii 1.0\n%s%send_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", NULL},
	    {"ply\r\nformat ascii 1.0\r\ncomment made by hand\r\n%s%send_header\r\n0 0 0 1 0 0 0 1 0 3 0 1 2", NULL},
	    {"ply\nformat ascii 1.0\n%s%s", "the PLY header has no end_header line (a truncated file?)"},
	    {"ply\nformat ascii 1.0\n%s%send_header\n0 0 0\n1 0 0\n0 1 0\n",
	     "the PLY data ends in element 'face' 1 of the 1 its header declares (a truncated file?)"},
	    {"ply\nformat ascii 1.0\n%s%send_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n",
	     "the PLY data ends in element 'face' 1 of the 1 its header declares (a truncated file?)"},
	    {"ply\nformat ascii 1.0\n%s%send_header\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n",
	     "the PLY data has 'zero' where element 'vertex' 1 needs a number"},
	    {"ply\nformat ascii 1.0\n%s%send_header\n0 0 0\n1 0 0\n0 1 0\n99999 0 1 2\n",
	     "a list of PLY element 'face' 0 has a count outside 0 to 65535"},
	    {"ply\nformat ascii 1.0\n%s%send_header\n0 0 0\n1 0 0\n0 1 0\n-3 0 1 2\n",
	     "a list of PLY element 'face' 0 has a count outside 0 to 65535"},
	    {"ply\nformat utf8 1.0\n%s%send_header\n", "unknown PLY format 'utf8'"},
	    {"ply\n%s%send_header\n", "the PLY header has no format line"},
	    {"ply\nformat ascii 1.0\nproperty float x\n%s%send_header\n", "a PLY property comes before any element"},
	    {"ply\nformat ascii 1.0\n%s%sproperty quad q\nend_header\n", "unknown PLY type 'quad'"},
	    {"ply\nformat ascii 1.0\n%s%sproperty list float int q\nend_header\n",
	     "the count type of a PLY list must be an integer type, not 'float'"},
	    {"ply\nformat ascii 1.0\nelement vertex many\n%s%send_header\n",
	     "the count of PLY element 'vertex' is 'many', not a number"},
	    {"ply\nformat ascii 1.0\n%s%swhatever this is\nend_header\n",
	     "unexpected line in the PLY header: 'whatever this is'"},
	};
	for (size_t i = 0; i < sizeof cases / sizeof *cases; i++) {
		char text[1024], why[256] = "";
		snprintf(text, sizeof text, cases[i].text, vtx, face);
		bool ok = ply_check(text, strlen(text), why, sizeof why);
		CHECK(cases[i].why ? !ok && !strcmp(why, cases[i].why) : ok, "case %zu: %s, reason '%s', expected '%s'", i,
		      ok ? "passes" : "refused", why, cases[i].why ? cases[i].why : "(passes)");
	}
	/* Binary, both byte orders: 3 vertices of 3 floats, one face of a uchar count and 3 ints. */
	for (int big = 0; big < 2; big++) {
		char buf[512];
		int n = snprintf(buf, sizeof buf, "ply\nformat binary_%s_endian 1.0\n%s%send_header\n", big ? "big" : "little",
				 vtx, face);
		memset(buf + n, 0, 36), n += 36;
		buf[n++] = 3;
		for (int k = 0; k < 3; k++) {
			unsigned char idx[4] = {0, 0, 0, 0};
			idx[big ? 3 : 0] = (unsigned char)k;
			memcpy(buf + n, idx, 4), n += 4;
		}
		char why[256] = "";
		CHECK(ply_check(buf, (size_t)n, why, sizeof why), "binary %s: refused: %s", big ? "big" : "little", why);
		CHECK(!ply_check(buf, (size_t)n - 1, why, sizeof why) &&
			  !strcmp(why, "the PLY data ends in element 'face' 1 of the 1 its header declares (a truncated file?)"),
		      "binary %s, one byte short: '%s'", big ? "big" : "little", why);
		buf[n - 13] = (char)200; /* a count of 200 items that are not there */
		CHECK(!ply_check(buf, (size_t)n, why, sizeof why), "binary %s, a long list past the end", big ? "big" : "little");
	}
}

/* Exact duplicate triangles, in either winding and with -0 for +0, are removed, the first kept;
 * a triangle sharing two corners, or all three up to one float step, is not a duplicate. */
static void check_duplicates(void)
{
	mesh m;
	CHECK(mesh_alloc(&m, 5, 6, false, false, false), "alloc");
	vec3 p[5] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {-0.0f, 0, 0}, {0, nextafterf(1.0f, 2.0f), 0}};
	/* Kept; reversed; rotated with -0; one float step off (kept); again; another (kept). */
	uint32_t ix[18] = {0, 1, 2, 2, 1, 0, 1, 2, 3, 0, 1, 4, 0, 1, 2, 0, 2, 4};
	memcpy(m.positions, p, sizeof p), memcpy(m.indices, ix, sizeof ix);
	CHECK(mesh_remove_duplicate_triangles(&m) == 3 && m.num_triangles == 3, "%u triangles kept",
	      m.num_triangles);
	uint32_t want[9] = {0, 1, 2, 0, 1, 4, 0, 2, 4};
	CHECK(!memcmp(m.indices, want, sizeof want), "the first of each kept, in order");
	CHECK(mesh_remove_duplicate_triangles(&m) == 0, "nothing left to remove");
	mesh_free(&m);
}

static void tangents_of(void *m) { (void)mesh_generate_tangents(m); }

/* The invariant of a mesh, every index below num_vertices, at its boundary; mesh_generate_tangents
 * asserts it. */
static void check_indices_valid(void)
{
	mesh m;
	CHECK(mesh_alloc(&m, 3, 1, true, true, false), "mesh of one triangle");
	for (int i = 0; i < 3; i++) {
		m.positions[i] = v3(i == 1, i == 2, 0);
		m.normals[i] = v3(0, 0, 1);
		m.uvs[i] = v2(i == 1, i == 2);
		m.indices[i] = (uint32_t)i;
	}
	CHECK(mesh_indices_valid(&m), "indices 0, 1, 2 of three vertices refused");
	CHECK(mesh_generate_tangents(&m), "tangents of a valid mesh");
	m.indices[2] = 3;
	CHECK(!mesh_indices_valid(&m), "index 3 of three vertices accepted");
#ifndef NDEBUG
	CHECK(check_aborts(tangents_of, &m), "mesh_generate_tangents on an index out of range did not assert");
#endif
	mesh_free(&m);
}

int main(void)
{
	check_duplicates();
	check_ply();
	check_prims();
	check_sphere_levels();
	check_plane_view();
	check_arrays();
	check_import();
	check_indices_valid();
	return check_done("test_mesh");
}
