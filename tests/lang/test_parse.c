/* test_parse: the parse entry point through an in-memory file hook: includes, -I search, clock,
 * instancing (one shared geometry), error status and that nothing leaks on either path. */
#include "base/mem.h"
#include "check.h"
#include "lang/lang.h"

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
	{"bad.pov", "sphere { 0, 1 }\nsphere { 0 1 }\n"},
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
	CHECK(strstr(buf, "bad.pov:2:12: error: expected ',' after the sphere centre, found '1'"), "got: %s", buf);
	st = lang_parse_file("missing.pov", &opt, &d, &sc);
	CHECK(st == LANG_IO_ERROR && sc == NULL, "missing file: status %d", (int)st);

	/* Allocation failure anywhere is an error, never a crash or a leak (under the sanitizers). */
	for (long n = 0; n < 400; n += 7) {
		mem_fail_after(n);
		st = lang_parse_file("main.pov", &opt, &d, &sc);
		mem_fail_after(-1);
		CHECK(st == LANG_OK || st == LANG_NO_MEMORY || st == LANG_SCENE_ERROR, "fail after %ld: %d", n, (int)st);
		scene_free(sc);
		sc = NULL;
	}
	fclose(out);
	free(buf);
	diag_free(&d);
	return check_done("test_parse");
}
