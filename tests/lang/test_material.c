/* test_material: the SSS block defaults (the medium as written: src/sss/medium.c derives it, and
 * tests/sss/test_medium tests that), and the clamping of colours into the range their physical
 * use allows (warned once per place). */
#include "check.h"
#include "scene/material.h"
#include "scene/scene.h"

#include <math.h>
#include <string.h>

static void check_clamp(vec3 in, scene_color_use use, vec3 want, bool changed)
{
	vec3 c = in;
	bool got = scene_color_clamp(&c, use);
	CHECK(got == changed && c.x == want.x && c.y == want.y && c.z == want.z,
	      "clamp <%g %g %g> as %s: <%g %g %g> (changed %d), want <%g %g %g> (changed %d)", in.x, in.y, in.z,
	      scene_color_range_name(use), c.x, c.y, c.z, got, want.x, want.y, want.z, changed);
}

/* scene_color_clamp on each side of each range, and scene_color_finalise's one warning a place. */
static void test_color_clamp(void)
{
	check_clamp(v3(-0.5f, 0.5f, 0.5f), SCENE_COLOR_REFLECTANCE, v3(0, 0.5f, 0.5f), true);
	check_clamp(v3(0, 1, 0.25f), SCENE_COLOR_REFLECTANCE, v3(0, 1, 0.25f), false);
	check_clamp(v3(1.5f, 0.2f, -0.0f), SCENE_COLOR_REFLECTANCE, v3(1, 0.2f, 0), true);
	check_clamp(v3(NAN, 0.2f, 0.3f), SCENE_COLOR_REFLECTANCE, v3(0, 0.2f, 0.3f), true);
	check_clamp(v3(-2, 5, 0), SCENE_COLOR_RADIANCE, v3(0, 5, 0), true);
	check_clamp(v3(40, 5, 1e30f), SCENE_COLOR_RADIANCE, v3(40, 5, 1e30f), false);
	check_clamp(v3(INFINITY, 5, 1), SCENE_COLOR_RADIANCE, v3(0, 5, 1), true);
	check_clamp(v3(0.5f, INFINITY, 1), SCENE_COLOR_REFLECTANCE, v3(0.5f, 0, 1), true);

	FILE *out = tmpfile();
	CHECK(out != NULL, "tmpfile");
	if (!out)
		return;
	diag d;
	diag_init(&d, out);
	const char text[] = "pigment { color rgb <-0.5, 0.5, 0.5> }\n";
	const diag_source *src = diag_add_source(&d, "t.pov", text, sizeof text - 1);
	scene *sc = scene_new();
	CHECK(src && sc, "setup");
	diag_loc at = {src, 1, 11}, other = {src, 1, 1};
	for (int pass = 0; pass < 3; pass++) { /* a loop passing the same colour three times */
		vec3 c = v3(-0.5f, 0.5f, 0.5f);
		CHECK(scene_color_finalise(sc, &d, at, "pigment colour", SCENE_COLOR_REFLECTANCE, &c), "finalise");
		CHECK(c.x == 0 && c.y == 0.5f && c.z == 0.5f, "finalised <%g %g %g>", c.x, c.y, c.z);
	}
	vec3 fine = v3(0.5f, 0.5f, 0.5f);
	CHECK(scene_color_finalise(sc, &d, other, "pigment colour", SCENE_COLOR_REFLECTANCE, &fine), "finalise");
	CHECK(d.warnings == 1 && d.errors == 0, "%d warnings, %d errors: want one warning", d.warnings, d.errors);
	char buf[512] = {0};
	rewind(out);
	size_t n = fread(buf, 1, sizeof buf - 1, out);
	buf[n] = '\0';
	const char *want = "t.pov:1:11: warning: pigment colour <-0.5, 0.5, 0.5> is outside [0, 1], the range of a "
			   "reflectance: clamped to <0, 0.5, 0.5>";
	CHECK(strncmp(buf, want, strlen(want)) == 0, "warning: %s\nwant: %s", buf, want);
	scene_free(sc);
	diag_free(&d);
	fclose(out);
}

int main(void)
{
	/* Block defaults (LANGUAGE.md): the medium as written, nothing derived. */
	scene_material m;
	memset(&m, 0, sizeof m);
	m.kind = MAT_WAX;
	scene_sss_defaults(&m);
	CHECK_NEAR(m.sss.ior, 1.45, 1e-6);
	CHECK_NEAR(m.sss.medium.radius_mm.x, 2.0, 1e-6);
	CHECK_NEAR(m.sss.medium.albedo.y, 0.78, 1e-6);
	CHECK(m.sss.profile == SSS_PROFILE_BURLEY, "wax profile");
	CHECK(!m.sss.medium.preset && m.sss.medium.has == (SSS_HAS_ALBEDO | SSS_HAS_RADIUS) &&
		  m.sss.medium.form == SSS_FORM_DEFAULT,
	      "wax: the artist defaults alone (has %u)", m.sss.medium.has);
	m.kind = MAT_SKIN;
	scene_sss_defaults(&m);
	CHECK(m.sss.profile == SSS_PROFILE_SUM_OF_GAUSSIANS && fabs(m.sss.ior - 1.4) < 1e-6, "skin defaults");
	CHECK(m.sss.medium.preset && !strcmp(m.sss.medium.preset, "skin1") && m.sss.medium.has == 0,
	      "skin: the preset skin1 alone");
	m.kind = MAT_MARBLE;
	scene_sss_defaults(&m);
	CHECK(m.sss.profile == SSS_PROFILE_BURLEY && fabs(m.sss.roughness - 0.1) < 1e-6, "marble defaults");
	CHECK(m.sss.medium.preset && !strcmp(m.sss.medium.preset, "marble"), "marble: the preset marble");
	test_color_clamp();
	return check_done("test_material");
}
