/* test_cage: subdivision cages from files - polygons kept, vertices welded, UVs and OpenSubdiv's
 * tags read - give bit for bit the surface of the same cage written inline in the scene. */
#include "check.h"
#include "lang/lang.h"
#include "render/world.h"
#include "shapes.h"

#include <limits.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[] = "/tmp/circe-test-cage-XXXXXX";
static char shapes[PATH_MAX]; /* the absolute folder of OpenSubdiv's shapes */

static void write_file(const char *name, const char *text)
{
	FILE *f = fopen(check_path(dir, name), "w");
	fputs(text, f);
	fclose(f);
}

/* Parses text as a scene in dir and tessellates its one geometry into m (moved out of the
 * world); false when parsing or building fails, with the diagnostics in *errors if asked. */
static bool tessellate_scene(const char *text, mesh *m, char **errors)
{
	write_file("s.pov", text);
	char *err = NULL;
	size_t len = 0;
	FILE *mem = open_memstream(&err, &len);
	diag d;
	diag_init(&d, mem);
	scene *sc = NULL;
	world *w = NULL;
	world_options o = {.width = 64, .height = 48, .geometry_only = true};
	bool ok = lang_parse_file(check_path(dir, "s.pov"), NULL, &d, &sc) == LANG_OK &&
		  (w = world_build(sc, &o, &d));
	memset(m, 0, sizeof *m);
	if (ok) {
		*m = w->geoms[0].m;
		memset(&w->geoms[0].m, 0, sizeof w->geoms[0].m);
		world_free(w);
	}
	scene_free(sc);
	diag_free(&d);
	fclose(mem);
	if (errors)
		*errors = err;
	else
		free(err);
	return ok;
}

/* The same vertices, normals, UVs and triangles, bit for bit. */
static bool same_mesh(const mesh *a, const mesh *b)
{
	return a->num_vertices == b->num_vertices && a->num_triangles == b->num_triangles &&
	       !memcmp(a->positions, b->positions, a->num_vertices * sizeof(vec3)) &&
	       !memcmp(a->normals, b->normals, a->num_vertices * sizeof(vec3)) && !a->uvs == !b->uvs &&
	       (!a->uvs || !memcmp(a->uvs, b->uvs, a->num_vertices * sizeof(vec2))) &&
	       !memcmp(a->indices, b->indices, 3 * (size_t)a->num_triangles * sizeof(uint32_t));
}

/* Tessellates the two scenes and checks they give the same mesh with `triangles` triangles. */
static void check_same(const char *what, const char *scene_a, const char *scene_b, uint32_t triangles)
{
	mesh a, b;
	char *ea = NULL, *eb = NULL;
	bool ok = tessellate_scene(scene_a, &a, &ea) & tessellate_scene(scene_b, &b, &eb);
	CHECK(ok, "%s: %s%s", what, ea, eb);
	if (ok) {
		CHECK(a.num_triangles == triangles, "%s: %u triangles, expected %u", what, a.num_triangles,
		      triangles);
		CHECK(same_mesh(&a, &b), "%s: the meshes differ (%u and %u vertices)", what, a.num_vertices,
		      b.num_vertices);
	}
	mesh_free(&a), mesh_free(&b), free(ea), free(eb);
}

/* OpenSubdiv's catmark_cube, inline: its 8 vertices, 6 quads and 14 UVs as the OBJ file has them. */
#define CUBE_INLINE_CAGE                                                                                     \
	"vertex_vectors { 8, <0, -1.414214, 1>, <1.414214, 0, 1>, <-1.414214, 0, 1>, <0, 1.414214, 1>,\n"    \
	"  <-1.414214, 0, -1>, <0, 1.414214, -1>, <0, -1.414214, -1>, <1.414214, 0, -1> }\n"                 \
	"faces { 6, <0, 1, 3, 2>, <2, 3, 5, 4>, <4, 5, 7, 6>, <6, 7, 1, 0>, <1, 7, 5, 3>, <6, 0, 2, 4> }\n"  \
	"uv_vectors { 14, <0.375, 0>, <0.625, 0>, <0.375, 0.25>, <0.625, 0.25>, <0.375, 0.5>, <0.625, "      \
	"0.5>,\n"                                                                                            \
	"  <0.375, 0.75>, <0.625, 0.75>, <0.375, 1>, <0.625, 1>, <0.875, 0>, <0.875, 0.25>, <0.125, 0>,\n"   \
	"  <0.125, 0.25> }\n"                                                                                \
	"uv_faces { 6, <0, 1, 3, 2>, <2, 3, 5, 4>, <4, 5, 7, 6>, <6, 7, 9, 8>, <1, 10, 11, 3>, <12, 0, 2, "  \
	"13> }\n"

/* catmark_cube_creases1's tags: 11 edges at 5 and one at 0.1, boundary rule 2 (edge_only). */
#define CUBE_TAG_CREASES                                                                                     \
	"creases { 12, <0, 1>, 5, <1, 3>, 5, <3, 2>, 5, <2, 0>, 5, <4, 5>, 5, <5, 7>, 5, <7, 6>, 5, <6, "    \
	"4>, 5,\n"                                                                                           \
	"  <0, 6>, 5, <1, 7>, 5, <2, 4>, 5, <3, 5>, 0.1 }\n"

/* The cube from its file equals the cube written inline: 768 triangles at level 3. */
static void check_file_equals_inline(void)
{
	char a[8192];
	snprintf(a, sizeof a, "subdivision_surface { file \"%s/catmark_cube.obj\" level 3 }\n", shapes);
	check_same("cube file vs inline", a, "subdivision_surface {\n" CUBE_INLINE_CAGE "level 3 }\n", 768);
	/* And without UVs (the UV-less mode shares vertices between faces). */
	write_file("cube_nouv.obj", "v 0 -1.414214 1\nv 1.414214 0 1\nv -1.414214 0 1\nv 0 1.414214 1\n"
				    "v -1.414214 0 -1\nv 0 1.414214 -1\nv 0 -1.414214 -1\nv 1.414214 0 -1\n"
				    "f 1 2 4 3\nf 3 4 6 5\nf 5 6 8 7\nf 7 8 2 1\nf 2 8 6 4\nf 7 1 3 5\n");
	check_same(
	    "cube file vs inline, no UVs", "subdivision_surface { file \"cube_nouv.obj\" level 3 }\n",
	    "subdivision_surface {\n"
	    "vertex_vectors { 8, <0, -1.414214, 1>, <1.414214, 0, 1>, <-1.414214, 0, 1>, <0, 1.414214, 1>,\n"
	    "  <-1.414214, 0, -1>, <0, 1.414214, -1>, <0, -1.414214, -1>, <1.414214, 0, -1> }\n"
	    "faces { 6, <0, 1, 3, 2>, <2, 3, 5, 4>, <4, 5, 7, 6>, <6, 7, 1, 0>, <1, 7, 5, 3>, <6, 0, 2, 4> "
	    "}\n"
	    "level 3 }\n",
	    768);
}

/* The creases of catmark_cube_creases1's tags shape the surface exactly as the same creases
 * written in the scene; a scene crease on an edge the file creases overrides the file's. */
static void check_tags(void)
{
	char a[8192], b[8192];
	snprintf(a, sizeof a, "subdivision_surface { file \"%s/catmark_cube_creases1.obj\" level 3 }\n",
		 shapes);
	check_same("creases1 tags vs inline creases", a,
		   "subdivision_surface {\n" CUBE_INLINE_CAGE CUBE_TAG_CREASES
		   "boundary edge_only level 3 }\n",
		   768);
	/* The tags change the surface. */
	mesh creased, smooth;
	snprintf(b, sizeof b, "subdivision_surface { file \"%s/catmark_cube.obj\" level 3 }\n", shapes);
	if (tessellate_scene(a, &creased, NULL) && tessellate_scene(b, &smooth, NULL))
		CHECK(!same_mesh(&creased, &smooth), "the file's creases change the surface");
	else
		CHECK(0, "tessellate creases1 and the plain cube");
	mesh_free(&creased), mesh_free(&smooth);
	/* The scene's crease replaces the file's 0.1 on <3, 5>; the others stay. */
	snprintf(a, sizeof a,
		 "subdivision_surface { file \"%s/catmark_cube_creases1.obj\" creases { 1, <5, 3>, 5 } level "
		 "3 }\n",
		 shapes);
	char inl[8192];
	snprintf(inl, sizeof inl,
		 "subdivision_surface {\n%screases { 12, <0, 1>, 5, <1, 3>, 5, <3, 2>, 5, <2, 0>, 5, "
		 "<4, 5>, 5, <5, 7>, 5, <7, 6>, 5, <6, 4>, 5,\n <0, 6>, 5, <1, 7>, 5, <2, 4>, 5, "
		 "<3, 5>, 5 }\nboundary edge_only level 3 }\n",
		 CUBE_INLINE_CAGE);
	check_same("scene crease overrides the file's", a, inl, 768);
	/* Scene creases and corners add to the file's cage, in the file's vertex numbers. */
	snprintf(a, sizeof a,
		 "subdivision_surface { file \"%s/catmark_cube.obj\" creases { 1, <0, 1>, 3 } corners { 1, "
		 "7, 10 } "
		 "level 2 }\n",
		 shapes);
	check_same("scene creases on a file cage", a,
		   "subdivision_surface {\n" CUBE_INLINE_CAGE
		   "creases { 1, <0, 1>, 3 } corners { 1, 7, 10 } level 2 }\n",
		   192);
}

/* A corner tag, a scene corner that cancels it, and a hole tag, on the UV-less cube. */
static void check_corner_and_hole(void)
{
	static const char *const cube =
	    "v 0 -1.414214 1\nv 1.414214 0 1\nv -1.414214 0 1\nv 0 1.414214 1\n"
	    "v -1.414214 0 -1\nv 0 1.414214 -1\nv 0 -1.414214 -1\nv 1.414214 0 -1\n"
	    "f 1 2 4 3\nf 3 4 6 5\nf 5 6 8 7\nf 7 8 2 1\nf 2 8 6 4\nf 7 1 3 5\n";
	char text[1024];
	snprintf(text, sizeof text, "%st corner 1/1/0 7 10\n", cube);
	write_file("corner.obj", text);
	snprintf(text, sizeof text, "%st hole 1/0/0 2\n", cube);
	write_file("hole.obj", text);
	check_same("a corner tag", "subdivision_surface { file \"corner.obj\" level 2 }\n",
		   "subdivision_surface { file \"cube_nouv.obj\" corners { 1, 7, 10 } level 2 }\n", 192);
	check_same("a scene corner cancels the file's",
		   "subdivision_surface { file \"corner.obj\" corners { 1, 7, 0 } level 2 }\n",
		   "subdivision_surface { file \"cube_nouv.obj\" level 2 }\n", 192);
	mesh m;
	CHECK(tessellate_scene("subdivision_surface { file \"hole.obj\" level 2 }\n", &m, NULL) &&
		  m.num_triangles == 5 * 32 && open_edges(&m) == 4 * 4,
	      "a hole tag leaves face 2 out: %u triangles, %ld open edges", m.num_triangles, open_edges(&m));
	mesh_free(&m);
}

/* An OBJ whose faces use duplicates of vertices (as exporters write at UV seams) gives the
 * surface of the welded file; the scene's indices may name a duplicate. */
static void check_weld(void)
{
	static const char *const head =
	    "v 0 -1.414214 1\nv 1.414214 0 1\nv -1.414214 0 1\nv 0 1.414214 1\n"
	    "v -1.414214 0 -1\nv 0 1.414214 -1\nv 0 -1.414214 -1\nv 1.414214 0 -1\n"
	    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n";
	char welded[1024], split[1024];
	snprintf(welded, sizeof welded,
		 "%sf 1/1 2/2 4/3 3/4\nf 3/1 4/2 6/3 5/4\nf 5/1 6/2 8/3 7/4\nf 7/1 8/2 2/3 1/4\n"
		 "f 2/1 8/2 6/3 4/4\nf 7/1 1/2 3/3 5/4\n",
		 head);
	/* Vertices 9 to 12 repeat 1, 2, 7 and 8 (-0 for 0 in one of them); the last two faces use them. */
	snprintf(split, sizeof split,
		 "%sv -0 -1.414214 1\nv 1.414214 0 1\nv 0 -1.414214 -1\nv 1.414214 0 -1\n"
		 "f 1/1 2/2 4/3 3/4\nf 3/1 4/2 6/3 5/4\nf 5/1 6/2 8/3 7/4\nf 7/1 8/2 2/3 1/4\n"
		 "f 10/1 12/2 6/3 4/4\nf 11/1 9/2 3/3 5/4\n",
		 head);
	write_file("welded.obj", welded);
	write_file("split.obj", split);
	test_cage *t = cage_read(check_path(dir, "split.obj"));
	CHECK(t && t->data.num_vertices == 8 && t->data.num_file_vertices == 12,
	      "split.obj welds to 8 vertices");
	if (t) {
		CHECK(t->data.weld[8] == 0 && t->data.weld[9] == 1 && t->data.weld[10] == 6 &&
			  t->data.weld[11] == 7,
		      "duplicates map to their first vertex: %u %u %u %u", t->data.weld[8], t->data.weld[9],
		      t->data.weld[10], t->data.weld[11]);
		CHECK(t->data.num_faces == 6 && t->data.face_indices[16] == 1 &&
			  t->data.face_indices[21] == 0,
		      "faces use the welded vertices");
	}
	test_cage_free(t);
	check_same("duplicated vertices weld", "subdivision_surface { file \"welded.obj\" level 3 }\n",
		   "subdivision_surface { file \"split.obj\" level 3 }\n", 768);
	check_same("a crease on a duplicate's number",
		   "subdivision_surface { file \"welded.obj\" creases { 1, <1, 7>, 4 } level 2 }\n",
		   "subdivision_surface { file \"split.obj\" creases { 1, <9, 11>, 4 } level 2 }\n", 192);
	/* Without welding the split cube would open along the seam; welded it is closed. */
	mesh m;
	CHECK(tessellate_scene("subdivision_surface { file \"split.obj\" level 2 }\n", &m, NULL) &&
		  open_edges(&m) == 0,
	      "the welded cube is closed");
	mesh_free(&m);
}

/* Quads, triangles and n-gons stay as they are; UVs are kept; unknown lines are skipped. */
static void check_polygons(void)
{
	write_file("ngons.obj",
		   "# a pentagon, a triangle and a quad\no thing\ng part\ns 1\nusemtl none\n"
		   "v 0 0 0\nv 1 0 0\nv 1.5 1 0\nv 0.5 1.5 0\nv -0.5 1 0\nv 2 0 0\nv 2 1 0\nv 1 -1 0\n"
		   "vn 0 0 1\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n"
		   "f 1/1/1 2/2/1 3/3/1 4/4/1 5/5/1\nf 2/1/1 6/2/1 3/3/1\nf -8/1 -1/2 -3/3 -7/4\nl 1 2\n");
	test_cage *t = cage_read(check_path(dir, "ngons.obj"));
	CHECK(t != NULL, "read ngons.obj");
	if (!t)
		return;
	const cage_data *c = &t->data;
	CHECK(c->num_faces == 3 && c->face_sizes[0] == 5 && c->face_sizes[1] == 3 && c->face_sizes[2] == 4,
	      "faces keep their sizes: %u faces", c->num_faces);
	CHECK(c->uvs != NULL && c->num_uvs == 10, "face-varying UVs kept: %u values", c->num_uvs);
	/* Relative indices: -8 is vertex 1, -1 vertex 8, -3 vertex 6, -7 vertex 2. */
	CHECK(c->face_indices[8] == 0 && c->face_indices[9] == 7 && c->face_indices[10] == 5 &&
		  c->face_indices[11] == 1,
	      "relative indices: %u %u %u %u", c->face_indices[8], c->face_indices[9], c->face_indices[10],
	      c->face_indices[11]);
	CHECK(c->num_edges == 9, "%zu edges", c->num_edges);
	CHECK(cage_has_edge(c, 0, 4) && cage_has_edge(c, 4, 0) && !cage_has_edge(c, 0, 2), "edge lookup");
	test_cage_free(t);
	/* A PLY's quads through Assimp: the same cube as the OBJ. */
	write_file("cube.ply",
		   "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
		   "property float z\nelement face 6\nproperty list uchar int vertex_indices\nend_header\n"
		   "0 -1.414214 1\n1.414214 0 1\n-1.414214 0 1\n0 1.414214 1\n-1.414214 0 -1\n"
		   "0 1.414214 -1\n0 -1.414214 -1\n1.414214 0 -1\n"
		   "4 0 1 3 2\n4 2 3 5 4\n4 4 5 7 6\n4 6 7 1 0\n4 1 7 5 3\n4 6 0 2 4\n");
	t = cage_read(check_path(dir, "cube.ply"));
	CHECK(t && t->data.num_faces == 6 && t->data.num_vertices == 8 && t->data.face_sizes[5] == 4 &&
		  !t->data.uvs,
	      "cube.ply: 6 quads on 8 vertices");
	test_cage_free(t);
	mesh a, b;
	if (tessellate_scene("subdivision_surface { file \"cube.ply\" level 3 }\n", &a, NULL) &&
	    tessellate_scene("subdivision_surface { file \"cube_nouv.obj\" level 3 }\n", &b, NULL)) {
		vec3 la, ha, lb, hb;
		mesh_bounds(&a, &la, &ha), mesh_bounds(&b, &lb, &hb);
		CHECK(a.num_triangles == 768 && open_edges(&a) == 0, "cube.ply: %u triangles, closed",
		      a.num_triangles);
		CHECK(v3_length(v3_sub(la, lb)) < 1e-6f && v3_length(v3_sub(ha, hb)) < 1e-6f,
		      "the PLY and OBJ cubes agree");
	} else {
		CHECK(0, "tessellate cube.ply and cube_nouv.obj");
	}
	mesh_free(&a), mesh_free(&b);
}

/* OpenSubdiv's torus and pawn from their files tessellate without a crack. */
static void check_watertight(void)
{
	static const char *const names[] = {"catmark_torus.obj", "catmark_torus_creases0.obj",
					    "catmark_pawn.obj"};
	for (int i = 0; i < 3; i++) {
		char s[8192];
		snprintf(s, sizeof s, "subdivision_surface { file \"%s/%s\" level 3 }\n", shapes, names[i]);
		mesh m;
		char *err = NULL;
		bool ok = tessellate_scene(s, &m, &err);
		CHECK(ok, "%s: %s", names[i], err);
		free(err);
		if (!ok)
			continue;
		long open = open_edges(&m);
		/* The pawn is open at its base: a ring of 24 cage edges, each 8 segments at level 3. */
		long expected = strstr(names[i], "pawn") ? 24 * 8 : 0;
		CHECK(open == expected, "%s: %ld open edges, expected %ld", names[i], open, expected);
		mesh_free(&m);
	}
}

/* Errors name the cage file and the reason at the scene's 'file' keyword. */
static void check_errors(void)
{
	/* The path is the resolved one, dir/e.obj: where circe looked. */
	static const struct {
		const char *obj, *scene_tail, *where, *message;
	} cases[] = {
	    {"v 0 0 0\nv 1 0 0\nv 0 1 0\n", "", "s.pov:1:23: error: cage file '",
	     "/e.obj': the file has no faces"},
	    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", "", "s.pov:1:23: error: cage file '",
	     "/e.obj', line 4: face 0 refers to vertex 4, but the file has 3 vertices\n"},
	    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0 0\nf 1 2 3 4\n", "", "s.pov:1:23: error: cage file '",
	     "/e.obj', line 5: face 0 uses vertex 1 twice (after welding the vertices at equal positions)\n"},
	    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nt crease 2/1/0 0 3 1\n", "",
	     "s.pov:1:23: error: cage file '",
	     "/e.obj', line 5: crease <0, 3>: vertex 3 is out of range (the file has 3 vertices; tags count "
	     "from 0)\n"},
	    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "creases { 1, <0, 3>, 1 }",
	     "s.pov:1:49: error: crease 0: vertex 3 is out of range (the cage file '",
	     "/e.obj' has 3 vertices)\n"},
	    {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nt smoothtriangles 0/0/1 smooth\n", "scheme loop level 1",
	     "s.pov:1:23: warning: cage file '",
	     "/e.obj', line 5: tag 'smoothtriangles' is not supported by circe; ignored\n"},
	};
	for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
		write_file("e.obj", cases[i].obj);
		char s[512], *err = NULL;
		snprintf(s, sizeof s, "subdivision_surface { file \"e.obj\" %s }\n", cases[i].scene_tail);
		mesh m;
		bool ok = tessellate_scene(s, &m, &err);
		bool warning = strstr(cases[i].where, "warning") != NULL; /* the cage still renders */
		CHECK(ok == warning && strstr(err, cases[i].where) && strstr(err, cases[i].message),
		      "case %zu: expected '%s...%s', got:\n%s", i, cases[i].where, cases[i].message, err);
		mesh_free(&m);
		free(err);
	}
}

int main(void)
{
	const char *top = getenv("top_srcdir");
	char rel[PATH_MAX];
	snprintf(rel, sizeof rel, "%s/scenes/assets/opensubdiv_shapes", top ? top : ".");
	if (!mkdtemp(dir) || !realpath(rel, shapes))
		return 99;
	check_file_equals_inline();
	check_tags();
	check_corner_and_hole();
	check_weld();
	check_polygons();
	check_watertight();
	check_errors();
	static const char *const files[] = {"s.pov",	 "cube_nouv.obj", "welded.obj",
					    "split.obj", "ngons.obj",	  "cube.ply",
					    "e.obj",	 "corner.obj",	  "hole.obj"};
	for (size_t i = 0; i < sizeof files / sizeof files[0]; i++)
		unlink(check_path(dir, files[i]));
	rmdir(dir);
	return check_done("test_cage");
}
