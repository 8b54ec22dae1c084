/* test_parse: the parse entry point through an in-memory file hook: includes, -I search, clock,
 * instancing (one shared geometry), error status and that nothing leaks on either path. */
#include "base/mem.h"
#include "check.h"
#include "lang/lang.h"
#include "scene/pigment.h"

#include <errno.h>
#include <stdlib.h>
#include <string.h>

typedef struct memfile {
	const char *path, *text;
} memfile;

static const memfile files[] = {
	{"main.pov", "#include \"a.inc\"\n#include \"lib.inc\"\n#declare B = sphere { 0, clock }\n"
		     "object { B } object { B translate x } mesh { #include \"t.inc\" }\n"},
	{"a.inc", "#local L = 2; #declare G = L * 3;\n"},
	{"inc/lib.inc", "box { -G, G }\n"},
	{"t.inc", "triangle { 0, x, y }"},
	{"bad.pov", "sphere { 0, 1 }\nsphere { 0, 1 ] }\n"},
	/* ten loops of 3: exactly the per-loop (3) and total (30) limits when max_loop_iterations is 3 */
	{"loops.pov", "#include \"l3.inc\" #include \"l3.inc\" #include \"l3.inc\" #include \"l3.inc\" "
		      "#include \"l3.inc\" #include \"l3.inc\" #include \"l3.inc\" #include \"l3.inc\" "
		      "#include \"l3.inc\" #include \"l3.inc\" sphere { 0, 1 }"},
	{"loops31.pov", "#include \"loops.pov\"\n#while (I = 3) #declare I = 0; #end"},
	{"l3.inc", "#declare I = 0; #while (I < 3) #declare I = I + 1; #end"},
	{"loop4.pov", "#declare I = 0;\n#while (I < 4) #declare I = I + 1; #end sphere { 0, 1 }"},
	/* the values the caller gives: a box of the image size, spheres of the animation's values */
	/* normal_map and block-list entries start from #default's normal (its amount, 0.3 here), as
	 * POV-Ray's Parse_BlendMapData copies Default_Texture->Tnormal; one's own amount wins */
	{"normals.pov", "#default { normal { bumps 0.3 } }\n"
			"sphere { 0, 1 normal { gradient x normal_map { [0 dents] [1 wrinkles 0.7] } } }\n"
			"sphere { 0, 1 normal { checker normal { ripples } normal { bumps 0.1 } } }\n"
			"sphere { 0, 1 normal { gradient x normal_map { [0 dents] [1 ripples] } } }\n"},
	{"normals_none.pov", "sphere { 0, 1 normal { gradient x normal_map { [0 dents] [1 wrinkles 0.7] } } }\n"},
	{"values.pov", "box { -1, <image_width, image_height, clock_on> }\n"
		       "sphere { <frame_number, initial_frame, final_frame>, clock + 1 }\n"
		       "sphere { <clock_delta, initial_clock, final_clock>, 1 }\n"},
	/* POV-Ray copies a declared union's and light_group's lights with each object { }: two lamps
	 * moved by their copies, then two copies of a group of a light with a group inside it */
	{"lights.pov", "#declare U = union { light_source { <0, 5, 0> color 1 } sphere { 0, 1 } }\n"
		       "object { U translate x * 3 } object { U translate -x * 3 }\n"
		       "#declare G = light_group { light_source { <1, 2, 3> color 1 } sphere { 0, 1 }\n"
		       "  light_group { light_source { <0, 1, 0> color 1 } box { -1, 1 } } }\n"
		       "object { G translate z } object { G scale 2 }\n"},
	/* A light in a light's looks_like lights the scene, moved with it, listed after it: in a
	 * declared union's light (each copy its own), and as the looks_like's object itself */
	{"looks.pov", "#declare U = union {\n"
		      "  light_source { <0, 5, 0> color 1 looks_like { union { sphere { 0, 0.1 } light_source { x color 1 } } } }\n"
		      "  sphere { 0, 1 } }\n"
		      "object { U translate x * 3 } object { U rotate y * 90 }\n"
		      "light_source { <0, 1, 0> color 1 looks_like { light_source { y color 1 } } translate z }\n"},
};

static int read_mem(void *user, const char *path, char **text, size_t *len)
{
	int *reads = user;
	for (size_t i = 0; i < sizeof files / sizeof files[0]; i++)
		if (!strcmp(files[i].path, path)) {
			size_t n = strlen(files[i].text);
			*text = mem_alloc(n, 1);
			if (!*text)
				return ENOMEM;
			memcpy(*text, files[i].text, n);
			*len = n;
			(*reads)++;
			return 0;
		}
	return ENOENT;
}

/* Parses path with a diagnostics object of its own; its messages go to msg (truncated). */
static lang_status parse_quiet(const char *path, const lang_options *opt, scene **sc, char *msg, size_t size)
{
	char *buf = NULL;
	size_t len = 0;
	FILE *out = open_memstream(&buf, &len);
	diag d;
	diag_init(&d, out);
	lang_status st = lang_parse_file(path, opt, &d, sc);
	fclose(out);
	snprintf(msg, size, "%s", buf ? buf : "");
	free(buf);
	diag_free(&d);
	return st;
}

int main(void)
{
	int reads = 0;
	const char *dirs[] = {"inc"};
	lang_options opt = {.include_dirs = dirs, .n_include_dirs = 1, .clock = 0.25, .read = read_mem,
			    .read_user = &reads};
	char *buf = NULL;
	size_t len = 0;
	FILE *out = open_memstream(&buf, &len);
	diag d;
	diag_init(&d, out);
	scene *sc = NULL;
	lang_status st = lang_parse_file("main.pov", &opt, &d, &sc);
	fflush(out);
	CHECK(st == LANG_OK && sc, "status %d, messages: %s", (int)st, buf);
	CHECK(reads == 4, "%d files read", reads);
	if (sc) {
		CHECK(scene_n_objects(sc) == 4, "%zu objects", scene_n_objects(sc));
		const scene_object *box = scene_object_at(sc, 0), *i1 = scene_object_at(sc, 1),
				   *i2 = scene_object_at(sc, 2), *mesh = scene_object_at(sc, 3);
		CHECK(box->geom->kind == SHAPE_BOX && box->geom->u.box.corner2.x == 6, "box from -I with G = 6");
		CHECK(i1->geom == i2->geom && i1->instance && i2->instance, "instances share one geometry");
		CHECK(i1->geom->u.sphere.radius == 0.25, "clock is %g", i1->geom->u.sphere.radius);
		CHECK(i2->transform.m[0][3] == 1 && i1->transform.m[0][3] == 0, "instance transforms differ");
		CHECK(mesh->geom->kind == SHAPE_MESH && mesh->geom->u.mesh.n_faces == 1, "mesh from include");
		CHECK(strstr(box->geom->loc.src->name, "lib.inc") && box->geom->loc.line == 1, "box loc %s:%u",
		      box->geom->loc.src->name, box->geom->loc.line);
		scene_stats stats;
		scene_stats_get(sc, &stats);
		CHECK(stats.instances == 2 && stats.geoms == 3 && stats.memory_bytes > 0, "stats");
	}
	scene_free(sc);

	/* A scene error: status, no scene, the message at its place. */
	sc = (scene *)&sc;
	fseek(out, 0, SEEK_SET);
	st = lang_parse_file("bad.pov", &opt, &d, &sc);
	fflush(out);
	CHECK(st == LANG_SCENE_ERROR && sc == NULL, "status %d", (int)st);
	CHECK(strstr(buf, "bad.pov:2:15: error: expected a transform, a material, no_shadow or '}' to close 'sphere' (opened at line 2), found ']'"), "got: %s", buf);
	st = lang_parse_file("missing.pov", &opt, &d, &sc);
	CHECK(st == LANG_IO_ERROR && sc == NULL, "missing file: status %d", (int)st);

	/* normal_map entries: #default's bump_size, else POV-Ray's 0.5 */
	{
		char nmsg[512];
		st = parse_quiet("normals.pov", &opt, &sc, nmsg, sizeof nmsg);
		CHECK(st == LANG_OK && sc && scene_n_objects(sc) == 3, "normals.pov: status %d: %s", (int)st, nmsg);
		if (st == LANG_OK && sc && scene_n_objects(sc) == 3) {
			const double want[3][2] = {{0.3, 0.7}, {0.3, 0.1}, {0.3, 0.3}};
			const scene_pattern_kind kinds[3][2] = {{SCENE_PAT_DENTS, SCENE_PAT_WRINKLES},
								{SCENE_PAT_RIPPLES, SCENE_PAT_BUMPS},
								{SCENE_PAT_DENTS, SCENE_PAT_RIPPLES}};
			for (size_t i = 0; i < 3; i++) {
				const scene_pigment *n = scene_object_at(sc, i)->material->normal;
				CHECK(n && n->n_entries == 2, "object %zu: a normal of two entries", i);
				for (uint32_t j = 0; n && j < 2 && j < n->n_entries; j++) {
					const scene_pigment *e = n->entries[j].pigment;
					CHECK(e && e->kind == kinds[i][j] && e->bump_amount == want[i][j],
					      "object %zu entry %u: kind %d amount %g, want %d %g", i, j, e ? (int)e->kind : -1,
					      e ? e->bump_amount : -1, (int)kinds[i][j], want[i][j]);
				}
			}
		}
		scene_free(sc);
		st = parse_quiet("normals_none.pov", &opt, &sc, nmsg, sizeof nmsg);
		const scene_pigment *n = st == LANG_OK && sc ? scene_object_at(sc, 0)->material->normal : NULL;
		CHECK(n && n->n_entries == 2 && n->entries[0].pigment->bump_amount == 0.5 &&
			      n->entries[1].pigment->bump_amount == 0.7,
		      "without #default: POV-Ray's 0.5: %s", nmsg);
		scene_free(sc);
	}

	/* The loop limits count iterations begun: exactly the limit runs, one more is refused. */
	opt.max_loop_iterations = 3;
	char msg[512];
	st = parse_quiet("loops.pov", &opt, &sc, msg, sizeof msg);
	CHECK(st == LANG_OK, "ten loops of 3 with limits of 3 per loop and 30 in all: status %d: %s", (int)st, msg);
	scene_free(sc);
	st = parse_quiet("loop4.pov", &opt, &sc, msg, sizeof msg);
	CHECK(st == LANG_SCENE_ERROR && strstr(msg, "loop4.pov:2:1: error: #while loop runs too long (limit is 3 "),
	      "a loop of 4 with a limit of 3: %s", msg);
	st = parse_quiet("loops31.pov", &opt, &sc, msg, sizeof msg);
	CHECK(st == LANG_SCENE_ERROR && strstr(msg, "loops31.pov:2:1: error: too many loop iterations in this scene "
						    "(limit is 30 in all)"),
	      "31 iterations with a total limit of 30: %s", msg);
	opt.max_loop_iterations = 0;

	/* image_width, image_height, clock_on and the animation's frame from the options. */
	lang_options vo = {.read = read_mem, .read_user = &reads, .clock = 0.5, .animated = true, .frame = 7,
			   .width = 32, .height = 24};
	st = parse_quiet("values.pov", &vo, &sc, msg, sizeof msg);
	CHECK(st == LANG_OK && sc, "values.pov: status %d: %s", (int)st, msg);
	if (sc) {
		const scene_geom *b = scene_object_at(sc, 0)->geom, *s1 = scene_object_at(sc, 1)->geom,
			    *s2 = scene_object_at(sc, 2)->geom;
		CHECK(b->u.box.corner2.x == 32 && b->u.box.corner2.y == 24 && b->u.box.corner2.z == 1,
		      "image_width, image_height, clock_on: %g %g %g", b->u.box.corner2.x, b->u.box.corner2.y,
		      b->u.box.corner2.z);
		CHECK(s1->u.sphere.center.x == 7 && s1->u.sphere.center.y == 7 && s1->u.sphere.center.z == 7 &&
			      s1->u.sphere.radius == 1.5,
		      "frame_number, initial_frame, final_frame, clock");
		CHECK(s2->u.sphere.center.x == 0 && s2->u.sphere.center.y == 0.5 && s2->u.sphere.center.z == 0.5,
		      "clock_delta, initial_clock, final_clock");
	}
	scene_free(sc);
	vo.animated = false, vo.width = 0, vo.height = 0;
	st = parse_quiet("values.pov", &vo, &sc, msg, sizeof msg);
	CHECK(st == LANG_OK && sc, "values.pov, no animation: status %d: %s", (int)st, msg);
	if (sc) {
		const scene_geom *b = scene_object_at(sc, 0)->geom, *s1 = scene_object_at(sc, 1)->geom;
		CHECK(b->u.box.corner2.x == LANG_DEFAULT_WIDTH && b->u.box.corner2.y == LANG_DEFAULT_HEIGHT &&
			      b->u.box.corner2.z == 0,
		      "default image size, clock_on 0");
		CHECK(s1->u.sphere.center.x == 0 && s1->u.sphere.center.z == 0, "frame_number 0 outside an animation");
	}
	scene_free(sc);

	/* Lights in declared objects: one moved copy per object { }, a new group per declared group. */
	st = parse_quiet("lights.pov", &vo, &sc, msg, sizeof msg);
	CHECK(st == LANG_OK && sc, "lights.pov: status %d: %s", (int)st, msg);
	if (sc) {
		CHECK(scene_n_lights(sc) == 6 && scene_n_objects(sc) == 6 && sc->light_groups.len == 4,
		      "lights.pov: %zu lights (6), %zu objects (6), %zu groups (4)", scene_n_lights(sc),
		      scene_n_objects(sc), sc->light_groups.len);
		static const double want[6][3] = {{3, 5, 0}, {-3, 5, 0}, {1, 2, 4}, {0, 1, 1}, {2, 4, 6}, {0, 2, 0}};
		static const uint32_t group[6] = {0, 0, 1, 2, 3, 4}, parent[4] = {0, 1, 0, 3};
		for (size_t i = 0; i < 6 && i < scene_n_lights(sc); i++) {
			const scene_light *l = scene_light_at(sc, i);
			CHECK(l->position.x == want[i][0] && l->position.y == want[i][1] && l->position.z == want[i][2] &&
				      l->group == group[i],
			      "lights.pov: light %zu at <%g, %g, %g> group %u, expected <%g, %g, %g> group %u", i,
			      l->position.x, l->position.y, l->position.z, l->group, want[i][0], want[i][1], want[i][2],
			      group[i]);
		}
		for (size_t g = 0; g < 4 && g < sc->light_groups.len; g++)
			CHECK(VECBUF_AT(&sc->light_groups, scene_light_group, g).parent == parent[g],
			      "lights.pov: group %zu's parent %u, expected %u", g + 1,
			      VECBUF_AT(&sc->light_groups, scene_light_group, g).parent, parent[g]);
		for (size_t i = 2; i < 6 && i < scene_n_objects(sc); i++) /* sphere, box of each copy of G */
			CHECK(scene_object_at(sc, i)->light_group == group[i],
			      "lights.pov: object %zu in group %u, expected %u", i, scene_object_at(sc, i)->light_group,
			      group[i]);
	}
	scene_free(sc);

	st = parse_quiet("looks.pov", &vo, &sc, msg, sizeof msg);
	CHECK(st == LANG_OK && sc, "looks.pov: status %d: %s", (int)st, msg);
	if (sc) {
		CHECK(scene_n_lights(sc) == 6 && scene_n_objects(sc) == 4, "looks.pov: %zu lights (6), %zu objects (4)",
		      scene_n_lights(sc), scene_n_objects(sc));
		static const double want[6][3] = {{3, 5, 0}, {4, 5, 0}, {0, 5, 0}, {0, 5, -1}, {0, 1, 1}, {0, 2, 1}};
		for (size_t i = 0; i < 6 && i < scene_n_lights(sc); i++) {
			const scene_light *l = scene_light_at(sc, i);
			CHECK(fabs(l->position.x - want[i][0]) < 1e-12 && fabs(l->position.y - want[i][1]) < 1e-12 &&
				      fabs(l->position.z - want[i][2]) < 1e-12 && l->group == 0 && l->n_looks_lights == 0,
			      "looks.pov: light %zu at <%g, %g, %g> group %u (%u inner), expected <%g, %g, %g> group 0", i,
			      l->position.x, l->position.y, l->position.z, l->group, l->n_looks_lights, want[i][0],
			      want[i][1], want[i][2]);
		}
	}
	scene_free(sc);

	/* Allocation failure anywhere is an error, never a crash or a leak (under the sanitizers). */
	for (long n = 0; n < 400; n += 7) {
		mem_fail_after(n);
		st = lang_parse_file("main.pov", &opt, &d, &sc);
		mem_fail_after(-1);
		CHECK(st == LANG_OK || st == LANG_NO_MEMORY || st == LANG_SCENE_ERROR, "fail after %ld: %d", n, (int)st);
		scene_free(sc);
		sc = NULL;
	}
	static const char *const light_files[] = {"lights.pov", "looks.pov"}; /* the lights' copies */
	for (size_t f = 0; f < 2; f++)
		for (long n = 0; n < 600; n += 3) {
			mem_fail_after(n);
			st = lang_parse_file(light_files[f], &vo, &d, &sc);
			mem_fail_after(-1);
			CHECK(st == LANG_OK || st == LANG_NO_MEMORY || st == LANG_SCENE_ERROR, "%s, fail after %ld: %d",
			      light_files[f], n, (int)st);
			scene_free(sc);
			sc = NULL;
		}
	fclose(out);
	free(buf);
	diag_free(&d);
	return check_done("test_parse");
}
