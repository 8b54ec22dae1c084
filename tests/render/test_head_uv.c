/* test_head_uv: the head scan's colour map lands where it belongs. Rays along -z down the face's
 * midline (x = 0) of scenes/default.pov hit the lips and the chin; the albedo the shading applies
 * there must be the lips' red on the lips and skin on the chin. With V flipped (the OBJ's first
 * conversion wrote vt = 1 - v of the glb, though three.js samples this mesh's maps with flipY),
 * the lips' red fell on the chin and both checks fail. */
#include "check.h"
#include "lang/lang.h"
#include "build/build.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* The albedo at the first hit of a ray along -z from (0, y, 20). */
static bool albedo_at(const world *w, float y, vec3 *albedo)
{
	const render_scene *rs = world_scene(w);
	render_ray r = {v3(0, y, 20), v3(0, 0, -1)};
	render_hit h = {0};
	if (!rs->intersect(rs->user, &r, 0.0f, INFINITY, &h) || h.material < 0)
		return false;
	bsdf_params b = rs->materials[h.material];
	vec3 ns = h.ns;
	rs->shade(rs->user, &h, &b, &ns);
	*albedo = b.diffuse;
	return true;
}

/* The mean red/green ratio of the albedo over n rays from y0 to y1. */
static double redness(const world *w, float y0, float y1, int n)
{
	double sum = 0.0;
	int hits = 0;
	for (int i = 0; i < n; i++) {
		vec3 a;
		if (albedo_at(w, y0 + (y1 - y0) * (float)i / (float)(n - 1), &a) && a.y > 0.0f) {
			sum += a.x / a.y;
			hits++;
		}
	}
	CHECK(hits == n, "%d of %d rays in [%g, %g] hit the head", hits, n, (double)y0, (double)y1);
	return hits ? sum / hits : 0.0;
}

int main(void)
{
	const char *src = getenv("srcdir");
	char path[4096];
	snprintf(path, sizeof path, "%s/scenes/default.pov", src ? src : ".");
	diag d;
	diag_init(&d, stderr);
	scene *sc = NULL;
	world *w = NULL;
	world_options o = {.width = 64, .height = 48};
	bool ok = lang_parse_file(path, NULL, &d, &sc) == LANG_OK && (w = world_build(sc, &o, &d));
	CHECK(ok, "%s parsed and built", path);
	if (ok) {
		/* The midline in the head's frame (y up, face towards +z; about 8 units tall): the lips
		 * span y 0.35 to 0.55, the chin y -0.25 to -0.05. Skin's albedo has red about 1.7 times
		 * green; the lips' about 4 times. */
		double lips = redness(w, 0.40f, 0.55f, 8), chin = redness(w, -0.25f, -0.05f, 8);
		CHECK(lips > 3.0, "the lips are red: red/green %.2f (expected > 3)", lips);
		CHECK(chin < 2.2, "the chin is skin: red/green %.2f (expected < 2.2)", chin);
		world_free(w);
	}
	scene_free(sc);
	diag_free(&d);
	return check_done("test_head_uv");
}
