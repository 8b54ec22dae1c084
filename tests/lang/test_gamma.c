/* test_gamma: POV-Ray's assumed_gamma (doc/language.md "assumed_gamma", scene/gamma.c). Under
 * assumed_gamma G every colour of the scene is c^G once the parse ends (lights, background,
 * pigments and their maps and block lists, finish colours, srgb colours back to linear), in any
 * order of the text, a shared pigment raised once; under 1 nothing changes; an image_map, filter,
 * transmit and a normal's slope_map are never changed; POV-Ray 3.7's rule for a scene without
 * assumed_gamma: legacy gamma 2.2 when its #version ends below 3.7, else 1. */
#include "base/mem.h"
#include "check.h"
#include "lang/lang.h"
#include "scene/pigment.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The body of every scene: colours before and after global_settings (which the caller puts). */
static const char *body =
	"#declare P = pigment { checker color rgb <0.5, 0.25, 1> color rgbt <0.5, 0.5, 0.5, 0.4> }\n"
	"light_source { <0, 5, 0> color rgb <0.5, 1, 0.25> }\n"
	"background { rgb 0.5 }\n"
	"sphere { 0, 1 pigment { P } }\n"
	"sphere { 0, 1 pigment { P } translate x }\n"
	"sphere { 0, 1 pigment { gradient y color_map { [0 rgb 0.5] [1 rgb 0.25] } }\n"
	"  finish { ambient 0.5 reflection 0.25 } }\n"
	"sphere { 0, 1 pigment { image_map { png \"img.png\" transmit all 0.3 } } }\n"
	"sphere { 0, 1 pigment { rgbf <0.5, 0.5, 0.5, 0.6> }\n"
	"  normal { bumps 0.5 slope_map { [0 <0.5, 0.25>] [1 <0.5, 0>] } } }\n"
	"#include \"lib.inc\"\n"
	"sphere { 0, 1 pigment { Q } }\n";

/* An include that declares its pigment under #version 3.5 and restores the version, as
 * POV-Ray's textures.inc does: the version at the end of the parse decides, not this one. */
static const char *lib = "#declare Saved = version; #version 3.5;\n"
			 "#declare Q = pigment { color rgb 0.5 }\n"
			 "#version Saved;\n";

static char main_text[4096];

static int read_mem(void *user, const char *path, char **text, size_t *len)
{
	(void)user;
	const char *t = !strcmp(path, "main.pov") ? main_text : !strcmp(path, "lib.inc") ? lib : NULL;
	if (!t)
		return ENOENT;
	size_t n = strlen(t);
	*text = mem_alloc(n + 1, 1);
	if (!*text)
		return ENOMEM;
	memcpy(*text, t, n);
	*len = n;
	return 0;
}

static scene *parse(const char *head, const char *tail)
{
	snprintf(main_text, sizeof main_text, "%s\n%s%s\n", head, body, tail);
	lang_options opt = {.read = read_mem};
	char *buf = NULL;
	size_t len = 0;
	FILE *out = open_memstream(&buf, &len);
	diag d;
	diag_init(&d, out);
	scene *sc = NULL;
	lang_status st = lang_parse_file("main.pov", &opt, &d, &sc);
	fclose(out);
	CHECK(st == LANG_OK && sc, "%s: status %d: %s", head, (int)st, buf ? buf : "");
	free(buf);
	diag_free(&d);
	return st == LANG_OK ? sc : NULL;
}

static const scene_material *mat(const scene *sc, size_t i) { return scene_object_at(sc, i)->material; }

/* Every colour of the body under gamma g: the working gamma is g and the colours are as written
 * (POV-Ray computes in its working space; the written image is r^g, render/output.c). */
static void check_scene(const scene *sc, double g, const char *what)
{
	const double tol = 1e-6;
	CHECK_NEAR(sc->global.working_gamma, g, 0);
	CHECK(scene_n_lights(sc) == 1 && scene_n_objects(sc) == 7, "%s: %zu lights, %zu objects", what,
	      scene_n_lights(sc), scene_n_objects(sc));
	if (scene_n_lights(sc) != 1 || scene_n_objects(sc) != 7)
		return;
	const scene_light *l = scene_light_at(sc, 0);
	CHECK_NEAR(l->color.x, 0.5, tol);
	CHECK_NEAR(l->color.y, 1.0, tol);
	CHECK_NEAR(l->color.z, 0.25, tol);
	CHECK_NEAR(sc->background.x, 0.5, tol);
	/* the checker: both objects share one tree */
	const scene_pigment *ck = mat(sc, 0)->pigment;
	CHECK(ck && ck == mat(sc, 1)->pigment && ck->kind == SCENE_PAT_CHECKER && ck->n_entries == 2,
	      "%s: the checker tree is shared", what);
	if (ck && ck->n_entries == 2) {
		CHECK_NEAR(ck->entries[0].color[0], 0.5, tol);
		CHECK_NEAR(ck->entries[0].color[1], 0.25, tol);
		CHECK_NEAR(ck->entries[0].color[2], 1.0, tol);
		CHECK_NEAR(ck->entries[1].color[0], 0.5, tol);
		CHECK_NEAR(ck->entries[1].color[4], 0.4, tol); /* transmit: a fraction, not a colour */
	}
	/* the colour map, and the finish's ambient and reflection colours */
	const scene_material *m2 = mat(sc, 2);
	const scene_pigment *gr = m2->pigment;
	CHECK(gr && gr->kind == SCENE_PAT_GRADIENT && gr->n_entries == 2, "%s: gradient", what);
	if (gr && gr->n_entries == 2) {
		CHECK_NEAR(gr->entries[0].color[1], 0.5, tol);
		CHECK_NEAR(gr->entries[1].color[2], 0.25, tol);
		CHECK_NEAR(gr->entries[1].value, 1.0, 0); /* map values are not colours */
	}
	CHECK_NEAR(m2->finish.ambient.x, 0.5, tol);
	CHECK_NEAR(m2->finish.refl_max.y, 0.25, tol);
	/* the image map: decoded light, unchanged */
	const scene_pigment *im = mat(sc, 3)->pigment;
	CHECK(im && im->kind == SCENE_PAT_IMAGE && strstr(im->image, "img.png"), "%s: image", what);
	if (im) {
		CHECK_NEAR(im->transmit_all, 0.3, 1e-7);
		CHECK_NEAR(im->filter_all, 0.0, 0);
	}
	/* a plain colour with filter; the normal's slope_map stays heights and slopes */
	const scene_material *m4 = mat(sc, 4);
	CHECK_NEAR(m4->color.y, 0.5, tol);
	CHECK_NEAR(m4->filter, 0.6, 1e-7);
	const scene_pigment *nm = m4->normal;
	CHECK(nm && nm->slope_map && nm->n_entries == 2, "%s: slope_map", what);
	if (nm && nm->n_entries == 2) {
		CHECK_NEAR(nm->entries[0].color[0], 0.5, 0);
		CHECK_NEAR(nm->entries[0].color[1], 0.25, 0);
	}
	/* the include's pigment, declared under #version 3.5 */
	CHECK_NEAR(mat(sc, 5)->color.x, 0.5, tol);
}

int main(void)
{
	scene *sc;
	/* assumed_gamma written after the colours it concerns: it holds for the whole scene */
	if ((sc = parse("#version 3.7;", "global_settings { assumed_gamma 2.2 }\n"
					 "sphere { 0, 1 pigment { srgb <0.5, 0.04, 1> } }"))) {
		check_scene(sc, 2.2, "assumed_gamma 2.2");
		/* srgb is decoded to light, then into the working space: linear^(1/g), as POV-Ray */
		const scene_material *m = mat(sc, 6);
		CHECK_NEAR(m->color.x, pow(pow((0.5 + 0.055) / 1.055, 2.4), 1 / 2.2), 1e-6);
		CHECK_NEAR(m->color.y, pow(0.04 / 12.92, 1 / 2.2), 1e-7);
		CHECK_NEAR(m->color.z, 1.0, 1e-6);
	}
	scene_free(sc);
	if ((sc = parse("global_settings { assumed_gamma 1.0 }", "sphere { 0, 1 }")))
		check_scene(sc, 1.0, "assumed_gamma 1");
	scene_free(sc);
	/* no assumed_gamma: #version 3.6 at the end is POV-Ray's legacy mode, 3.7 or none is 1 */
	if ((sc = parse("#version 3.6;", "sphere { 0, 1 }")))
		check_scene(sc, 2.2, "#version 3.6");
	scene_free(sc);
	if ((sc = parse("#version 3.7;", "sphere { 0, 1 }")))
		check_scene(sc, 1.0, "#version 3.7");
	scene_free(sc);
	if ((sc = parse("", "sphere { 0, 1 }")))
		check_scene(sc, 1.0, "no #version");
	scene_free(sc);
	/* a 3.6 scene that writes assumed_gamma: the value written */
	if ((sc = parse("#version 3.6; global_settings { assumed_gamma 1.5 }", "sphere { 0, 1 }")))
		check_scene(sc, 1.5, "#version 3.6, assumed_gamma 1.5");
	scene_free(sc);
	return check_done("test_gamma");
}
