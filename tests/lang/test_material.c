/* test_material: SSS presets, block defaults, the physical <-> artist inversion round trip, and
 * the clamping of colours into the range their physical use allows (warned once per place). */
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
	static const char *const names[] = {"skin1", "skin2", "marble", "wholemilk", "skimmilk", "cream",
					    "ketchup", "apple", "potato", "chicken1", "chicken2"};
	for (size_t i = 0; i < sizeof names / sizeof names[0]; i++)
		CHECK(scene_sss_preset_find(names[i]) != NULL, "preset %s missing", names[i]);
	CHECK(scene_sss_preset_find("skin3") == NULL, "unknown preset found");
	CHECK(scene_sss_n_presets == 11, "%d presets", scene_sss_n_presets);
	const scene_sss_preset *skin1 = scene_sss_preset_find("skin1");
	CHECK_NEAR(skin1->sigma_s_per_mm[0], 0.74, 1e-6);
	CHECK_NEAR(skin1->sigma_a_per_mm[2], 0.48, 1e-6);

	/* Jensen et al. 2001, Figure 5 lists the diffuse reflectance Rd the coefficients give
	 * with the preset's eta: the forward formula must reproduce it to about the table's two digits. */
	struct { const char *name; double rd[3]; } rd[] = {
		{"marble", {0.83, 0.79, 0.75}}, {"skin1", {0.44, 0.22, 0.13}}, {"ketchup", {0.16, 0.01, 0.00}},
		{"potato", {0.77, 0.62, 0.21}}, {"wholemilk", {0.91, 0.88, 0.76}}, {"apple", {0.85, 0.84, 0.53}}};
	for (size_t i = 0; i < sizeof rd / sizeof rd[0]; i++) {
		const scene_sss_preset *p = scene_sss_preset_find(rd[i].name);
		for (int c = 0; c < 3; c++) {
			double a, r;
			scene_sss_to_artist(p->sigma_s_per_mm[c], p->sigma_a_per_mm[c], p->eta, &a, &r);
			CHECK(a > rd[i].rd[c] - 0.04 && a < rd[i].rd[c] + 0.04, "%s channel %d: Rd %.4f, paper %.2f",
			      rd[i].name, c, a, rd[i].rd[c]);
		}
	}

	/* Round trips: physical -> artist -> physical, and artist -> physical -> artist. */
	for (int i = 0; i < scene_sss_n_presets; i++)
		for (int c = 0; c < 3; c++) {
			const scene_sss_preset *p = &scene_sss_presets[i];
			double a, r, s2, a2;
			scene_sss_to_artist(p->sigma_s_per_mm[c], p->sigma_a_per_mm[c], 1.4, &a, &r);
			scene_sss_to_physical(a, r, 1.4, &s2, &a2);
			CHECK(fabs(s2 - p->sigma_s_per_mm[c]) < 1e-6 * (1 + p->sigma_s_per_mm[c]) &&
				      fabs(a2 - p->sigma_a_per_mm[c]) < 1e-6 * (1 + p->sigma_a_per_mm[c]),
			      "%s channel %d: sigma_s %g -> %g, sigma_a %g -> %g", p->name, c, p->sigma_s_per_mm[c], s2,
			      p->sigma_a_per_mm[c], a2);
		}
	for (double alb = 0.05; alb < 0.9; alb += 0.1)
		for (double rad = 0.1; rad < 20; rad *= 3) {
			double s, a, alb2, rad2;
			scene_sss_to_physical(alb, rad, 1.3, &s, &a);
			scene_sss_to_artist(s, a, 1.3, &alb2, &rad2);
			CHECK_NEAR(alb2, alb, 1e-9);
			CHECK_NEAR(rad2, rad, 1e-9 * rad);
		}

	/* Block defaults (LANGUAGE.md). */
	scene_material m;
	memset(&m, 0, sizeof m);
	m.kind = MAT_WAX;
	scene_sss_defaults(&m);
	scene_sss_derive(&m.sss);
	CHECK_NEAR(m.sss.ior, 1.45, 1e-6);
	CHECK_NEAR(m.sss.radius_mm.x, 2.0, 1e-6);
	CHECK(m.sss.profile == PROFILE_BURLEY, "wax profile");
	CHECK(m.sss.sigma_s_per_mm.x > 0 && m.sss.sigma_a_per_mm.z > 0, "wax derived physical form");
	m.kind = MAT_SKIN;
	scene_sss_defaults(&m);
	CHECK(m.sss.profile == PROFILE_SUM_OF_GAUSSIANS && fabs(m.sss.ior - 1.4) < 1e-6, "skin defaults");
	CHECK_NEAR(m.sss.sigma_a_per_mm.y, 0.17, 1e-6);
	m.kind = MAT_MARBLE;
	scene_sss_defaults(&m);
	CHECK(m.sss.profile == PROFILE_BURLEY && fabs(m.sss.roughness - 0.1) < 1e-6, "marble defaults");

	/* d'Eon & Luebke's weights: each channel's six weights sum to about 1. */
	for (int c = 0; c < 3; c++) {
		double sum = 0;
		for (int g = 0; g < SCENE_SKIN_GAUSSIANS; g++)
			sum += scene_skin_gaussian_weight[g][c];
		CHECK(fabs(sum - 1.0) < 0.01, "channel %d weights sum to %g", c, sum);
	}
	test_color_clamp();
	return check_done("test_material");
}
