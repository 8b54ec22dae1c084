/* test_world: the scene IR made renderable — rays hit tessellated spheres where the analytic
 * sphere is (within the tessellation error), instances share one mesh, an SSS object under a
 * non-uniform scale is flattened into world space, no_shadow objects cast no shadow, textures
 * and materials reach the hit, and bad assets are errors at their place in the scene. */
#include "check.h"
#include "lang/lang.h"
#include "geom/prim.h"
#include "render/bsdf_pov.h"
#include "render/world.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[] = "/tmp/circe-test-world-XXXXXX";

/* Parses text as a scene file and builds its world; false when either fails. */
static bool build(const char *text, world **w, char **errors)
{
	char path[256];
	snprintf(path, sizeof path, "%s/s.pov", dir);
	FILE *f = fopen(path, "w");
	fputs(text, f);
	fclose(f);
	size_t len = 0;
	FILE *mem = open_memstream(errors, &len);
	diag d;
	diag_init(&d, mem);
	scene *sc = NULL;
	bool ok = lang_parse_file(path, NULL, &d, &sc) == LANG_OK;
	world_options o = {.width = 640, .height = 480};
	*w = ok ? world_build(sc, &o, &d) : NULL;
	ok = *w != NULL;
	scene_free(sc);
	diag_free(&d);
	fclose(mem);
	unlink(path);
	return ok;
}

/* The camera ray through pixel (px, py)'s corner of build()'s 640x480 image, of the scene text. */
static render_ray camera_ray(const char *text, float px, float py)
{
	world *w;
	char *err = NULL;
	render_ray r = {v3(NAN, NAN, NAN), v3(NAN, NAN, NAN)};
	if (build(text, &w, &err)) {
		r = cam_ray(world_camera(w), 0, 0, v2(px, py), v2(0.5f, 0.5f));
		world_free(w);
	} else {
		fprintf(stderr, "%s", err);
	}
	free(err);
	return r;
}

static bool same_ray(render_ray a, render_ray b, float tol)
{
	return v3_length(v3_sub(a.o, b.o)) <= tol && v3_length(v3_sub(a.d, b.d)) <= tol;
}

/* The camera block as POV-Ray 3.7 reads it: the order of the settings does not matter, angle sets
 * |direction|, right x*image_width/image_height is the default's aspect, no look_at looks along
 * direction, the camera's transforms come last. */
static void check_camera_text(void)
{
	render_ray a = camera_ray("camera { angle 60 right 2*x location <1, 2, -5> look_at <0, 0, 0> }\n", 100, 50);
	render_ray b = camera_ray("camera { look_at <0, 0, 0> location <1, 2, -5> right 2*x angle 60 }\n", 100, 50);
	CHECK(same_ray(a, b, 0.0f), "camera settings' order changed the ray: (%g %g %g) vs (%g %g %g)", a.d.x, a.d.y,
	      a.d.z, b.d.x, b.d.y, b.d.z);
	a = camera_ray("camera { location <0, 0, -5> look_at 0 angle 50 }\n", 10, 400);
	b = camera_ray("camera { location <0, 0, -5> look_at 0 angle 50 right x*image_width/image_height }\n", 10, 400);
	CHECK(same_ray(a, b, 1e-6f), "right x*image_width/image_height differs from the default at 4:3");
	/* angle overrides direction's length; without angle the length sets the width. */
	a = camera_ray("camera { direction <0, 0, 3> angle 90 }\n", 640, 240);
	CHECK(fabsf(a.d.x - a.d.z) < 1e-5f && fabsf(a.d.y) < 1e-5f, "angle 90 with direction 3: edge ray (%g %g %g)",
	      a.d.x, a.d.y, a.d.z);
	a = camera_ray("camera { direction <0, 0, 2> right x }\n", 640, 240);
	CHECK(fabsf(a.d.x * 4 - a.d.z) < 1e-5f, "direction 2, right 1: edge ray (%g %g %g), want x / z = 1/4", a.d.x,
	      a.d.y, a.d.z);
	a = camera_ray("camera { location <0, 2, -5> }\n", 320, 240);
	CHECK(same_ray(a, (render_ray){v3(0, 2, -5), v3(0, 0, 1)}, 1e-6f),
	      "no look_at: the centre ray (%g %g %g) should run along direction +z", a.d.x, a.d.y, a.d.z);
	a = camera_ray("camera { location <0, 0, -5> look_at 0 rotate <0, 90, 0> translate <0, 1, 0> }\n", 320, 240);
	CHECK(same_ray(a, (render_ray){v3(-5, 1, 0), v3(1, 0, 0)}, 1e-5f),
	      "camera transform: centre ray (%g %g %g) + t (%g %g %g)", a.o.x, a.o.y, a.o.z, a.d.x, a.d.y, a.d.z);
	/* The mirrored camera: right -x*4/3 turns the image's left column to +x. */
	a = camera_ray("camera { location <0, 0, -5> look_at 0 right -x*4/3 }\n", 0, 240);
	CHECK(a.d.x > 0.3f, "right -x*4/3: left column looks along (%g %g %g)", a.d.x, a.d.y, a.d.z);
}

static bool trace(const world *w, vec3 o, vec3 dir_, render_hit *h)
{
	render_ray r = {o, v3_normalize(dir_)};
	return w->rs.intersect(w->rs.user, &r, 0.0f, INFINITY, h);
}

/* Pixels of the silhouette's radius of a sphere of radius r at distance dist, in the 640x480
 * image of build() under POV-Ray's default angle (2 atan(1.33 / 2); vertical half-angle 0.5). */
static double radius_px(double r, double dist) { return 240.0 / 0.5 * r / sqrt(dist * dist - r * r); }

/* Level k on a sphere of radius px on screen: silhouette and edges within world.h's bounds. */
static bool level_fits(uint32_t k, double px)
{
	uint32_t seg = prim_sphere_level_segments(k);
	return prim_sphere_rel_error(seg) * px <= WORLD_SPHERE_MAX_ERROR_PX && 2 * M_PI * px / seg <= WORLD_SPHERE_MAX_EDGE_PX;
}

/* Spheres are instances of shared unit spheres, each at the coarsest level whose silhouette is
 * within WORLD_SPHERE_MAX_ERROR_PX of the round one and whose edges are short enough on screen
 * (WORLD_SPHERE_MAX_EDGE_PX), else the finest: a small far sphere and a large near one get
 * different levels, and the rays still meet them where the analytic sphere is, within that error. */
static void check_sphere_levels(void)
{
	world *w;
	char *err = NULL;
	bool ok = build("camera { location <0, 0, -10> look_at 0 }\n"
			"sphere { <0, 0, 100>, 0.1 }\n"
			"sphere { <0, 0, -5>, 2 }\n"
			"sphere { <3, 0, 100>, 0.1 }\n",
			&w, &err);
	CHECK(ok, "spheres: %s", err);
	free(err);
	if (!ok)
		return;
	/* The third is off the axis: its image stretches by 1 / cos^2 along the radius. */
	double r[3] = {0.1, 2, 0.1}, dist[3] = {110, 5, sqrt(110 * 110 + 9)}, cos2[3] = {1, 1, 110 * 110 / (110 * 110 + 9.0)};
	uint32_t level[3];
	for (int i = 0; i < 3; i++) {
		ptrdiff_t k = w->insts[i].g - w->geoms - (ptrdiff_t)w->unit_spheres;
		CHECK(k >= 0 && k < (ptrdiff_t)PRIM_SPHERE_LEVELS, "sphere %d is an instance of a unit sphere (%td)", i, k);
		level[i] = k >= 0 && k < (ptrdiff_t)PRIM_SPHERE_LEVELS ? (uint32_t)k : 0;
		double px = radius_px(r[i], dist[i]) / cos2[i];
		CHECK((level_fits(level[i], px) || level[i] == PRIM_SPHERE_LEVELS - 1) &&
			      (level[i] == 0 || !level_fits(level[i] - 1, px)),
		      "sphere %d, %.1f px: level %u errs %.3g px, edges %.3g px", i, px, level[i],
		      prim_sphere_rel_error(prim_sphere_level_segments(level[i])) * px,
		      2 * M_PI * px / prim_sphere_level_segments(level[i]));
	}
	CHECK(level[0] == 0 && level[1] >= 3, "the small far sphere gets level %u, the large near one %u", level[0],
	      level[1]);
	CHECK(w->insts[0].g == w->insts[2].g, "spheres alike on screen share one mesh");
	render_hit h;
	CHECK(trace(w, v3(0, 0, -10), v3(0, 0, 1), &h), "hit the near sphere");
	CHECK_NEAR(h.t, 3.0, 2 * prim_sphere_rel_error(prim_sphere_level_segments(level[1])));
	CHECK(trace(w, v3(3, 0, 0), v3(0, 0, 1), &h) && h.object == 2, "hit the far sphere at x = 3");
	CHECK_NEAR(h.t, 99.9, 0.1 * prim_sphere_rel_error(prim_sphere_level_segments(level[2])) + 1e-4);
	world_free(w);
}

/* Ten thousand spheres cost a few unit spheres and their instances, not ten thousand meshes. */
static void check_many_spheres(void)
{
	world *w;
	char *err = NULL;
	bool ok = build("camera { location <0, 0, -30> look_at 0 }\n"
			"#declare I = 0;\n"
			"#while (I < 10000)\n"
			"  sphere { <mod(I, 100) * 0.2 - 10, floor(I / 100) * 0.2 - 10, 0>, 0.08 }\n"
			"  #declare I = I + 1;\n"
			"#end\n",
			&w, &err);
	CHECK(ok, "10^4 spheres: %s", err);
	free(err);
	if (!ok)
		return;
	CHECK(w->n_insts == 10000, "%zu instances", w->n_insts);
	CHECK(w->stats.triangles <= 20000, "%zu unique triangles for 10^4 spheres", w->stats.triangles);
	CHECK(w->stats.geometry_bytes <= (size_t)8 << 20, "meshes and BVHs of 10^4 spheres: %.1f MiB",
	      w->stats.geometry_bytes / 1048576.0);
	world_free(w);
}

/* Normal maps need tangents, made for the mesh an object shows: the shared unit sphere of a
 * plain instance, and the world-space copy of a flattened one made from its own triangles (not
 * the shared mesh's tangents carried through the transform). */
static void check_tangents(void)
{
	const char *top = getenv("top_srcdir");
	char text[1024];
	snprintf(text, sizeof text,
		 "camera { location <0, 0, -10> look_at 0 }\n"
		 "#declare M = material { wax { normal_map \"%s/scenes/assets/lee_perry_smith_head/"
		 "Infinite-Level_02_Tangent_SmoothUV.jpg\" } }\n"
		 "sphere { <-2, 0, 0>, 1 material { M } }\n"
		 "sphere { 0, 1 scale <1, 0.8, 1> translate <2, 0, 0> material { M } }\n",
		 top ? top : "..");
	world *w;
	char *err = NULL;
	bool ok = build(text, &w, &err);
	CHECK(ok, "normal-mapped spheres: %s", err);
	free(err);
	if (!ok)
		return;
	const world_geom *shared = w->insts[0].g, *copy = w->insts[1].g;
	CHECK(shared->m.tangents && shared->tangents_made, "the unit sphere has tangents");
	CHECK(copy != shared && copy->m.tangents && w->stats.flattened == 1, "the flattened copy has tangents");
	mesh fresh;
	if (copy->m.tangents && mesh_copy(&fresh, &copy->m)) {
		CHECK(mesh_generate_tangents(&fresh) &&
			      !memcmp(fresh.tangents, copy->m.tangents, fresh.num_vertices * sizeof *fresh.tangents),
		      "the copy's tangents are made from its world-space triangles");
		mesh_free(&fresh);
	}
	world_free(w);
}

/* Bit for bit. */
static bool same_vec(vec3 a, vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

static bool near_vec(vec3 a, vec3 b, float tol)
{
	return fabsf(a.x - b.x) <= tol && fabsf(a.y - b.y) <= tol && fabsf(a.z - b.z) <= tol;
}

/* A layered texture's BSDF at a hit, shaded for LAYER_STEPS evenly spaced u_layer: the mean of
 * the picked layer's diffuse reflectance and of its albedo bound, each times its pov_weight (the
 * sum over the layers the picks estimate); *last the shading of the last step. */
#define LAYER_STEPS 8192
static void layer_means(const world *w, render_hit h, vec3 *diffuse, vec3 *bound, bsdf_params *last)
{
	*diffuse = *bound = v3s(0.0f);
	for (int i = 0; i < LAYER_STEPS; i++) {
		h.u_layer = ((float)i + 0.5f) / LAYER_STEPS;
		bsdf_params at = w->bsdfs[h.material];
		vec3 ns = h.ns;
		w->rs.shade(w->rs.user, &h, &at, &ns);
		*diffuse = v3_add(*diffuse, v3_scale(bsdf_albedo(&at), 1.0f / LAYER_STEPS));
		*bound = v3_add(*bound, v3_scale(bsdf_pov_albedo_bound(&at), 1.0f / LAYER_STEPS));
		*last = at;
	}
}

/* An image_map's transparency per texel (scene/pattern.c image_color): an alpha channel
 * transmits 1 - alpha, as POV-Ray's GetRGBFTValue (alpha2.png: an opaque texel, and one of
 * alpha 64/255; palette2.png: two texels of palette indices 0 and 1); a palette index's `transmit I, F` makes a texture transparent there, the
 * image not `once` (build_material.c image_can_clear). */
static void check_image_clear(void)
{
	const char *top = getenv("top_srcdir");
	char text[1024];
	snprintf(text, sizeof text,
		 "polygon { 5, <0, 0, 0>, <1, 0, 0>, <1, 1, 0>, <0, 1, 0>, <0, 0, 0>\n"
		 "  pigment { image_map { png \"%s/tests/render/alpha2.png\" } } finish { diffuse 0.6 } }\n"
		 "sphere { <0, 0, 5>, 1 pigment { image_map { png \"%s/tests/render/palette2.png\" transmit 1, 0.5 } } }\n"
		 "sphere { <0, 0, 9>, 1 pigment { image_map { png \"%s/tests/render/palette2.png\" } } }\n",
		 top ? top : "..", top ? top : "..", top ? top : "..");
	world *w;
	char *err = NULL;
	bool ok = build(text, &w, &err);
	CHECK(ok, "image_map transparency: %s", err);
	free(err);
	if (!ok)
		return;
	render_hit h;
	CHECK(trace(w, v3(0.25f, 0.5f, -1), v3(0, 0, 1), &h), "hit the opaque texel");
	bsdf_params at = w->bsdfs[h.material];
	CHECK(at.clear.kind == BSDF_CLEAR_THIN && at.clear.patterned, "an image with alpha: a patterned clear surface");
	vec3 ns = h.ns;
	w->rs.shade(w->rs.user, &h, &at, &ns);
	CHECK(v3_max_comp(at.clear.tint) == 0.0f && fabsf(at.pov.diffuse - 0.6f) < 1e-6f,
	      "alpha 1: opaque (tint %g, diffuse %g)", v3_max_comp(at.clear.tint), at.pov.diffuse);
	CHECK(trace(w, v3(0.75f, 0.5f, -1), v3(0, 0, 1), &h), "hit the clear texel");
	at = w->bsdfs[h.material];
	w->rs.shade(w->rs.user, &h, &at, &ns);
	float t = 1.0f - 64.0f / 255.0f;
	CHECK(near_vec(at.clear.tint, v3s(t), 1e-6f) && fabsf(at.pov.diffuse - 0.6f * (1.0f - t)) < 1e-6f,
	      "alpha 64/255: tint (%g %g %g) want %g, diffuse %g", at.clear.tint.x, at.clear.tint.y, at.clear.tint.z, t,
	      at.pov.diffuse);
	CHECK(trace(w, v3(0, 0, 0.5f), v3(0, 0, 1), &h) && w->bsdfs[h.material].clear.patterned,
	      "a palette index's transmit: a patterned clear surface");
	CHECK(trace(w, v3(0, 0, 7.5f), v3(0, 0, 1), &h) && w->bsdfs[h.material].clear.kind == BSDF_CLEAR_NONE,
	      "the same palette image without transmit: opaque");
	world_free(w);
}

/* Layered textures light each layer with its own finish (render/world.c shade_layers): the
 * weights of the layers against sums computed by hand from POV-Ray's rule (trace.cpp
 * ComputeLightedTexture): layer i's diffuse Kd_i * opacity_i * pigment_i, its ambient likewise,
 * each times the product of the upper layers' pigment * filter + transmit. */
static void check_layers(void)
{
	world *w;
	char *err = NULL;
	/* x < 0: top rgbft <0.8, 0.4, 0.2, 0.5, 0.2> (opacity 0.3, lets <0.6, 0.4, 0.3> through) over
	 * an opaque rgb <0.5, 0.5, 1>; x > 0: the same over rgbt <0.5, 0.5, 1, 0.5>; z > 0: a
	 * highlight of albedo 1 (phong 1, phong_size 1) on a clear top over a white diffuse 1. */
	bool ok = build("#declare Top = texture { pigment { rgbft <0.8, 0.4, 0.2, 0.5, 0.2> } finish { diffuse 0.5 ambient 0 } }\n"
			"box { <-2, -1, -2>, <0, 0, 0> texture { pigment { rgb <0.5, 0.5, 1> } finish { diffuse 0.7 ambient 0.2 } }\n"
			"  texture { Top } }\n"
			"box { <0, -1, -2>, <2, 0, 0> texture { pigment { rgbt <0.5, 0.5, 1, 0.5> } finish { diffuse 0.7 ambient 0.2 } }\n"
			"  texture { Top } }\n"
			"box { <-2, -1, 0>, <2, 0, 2> texture { pigment { rgb 1 } finish { diffuse 1 ambient 0 } }\n"
			"  texture { pigment { rgbf 1 } finish { phong 1 phong_size 1 diffuse 0.6 ambient 0 } } }\n",
			&w, &err);
	CHECK(ok, "layered textures: %s", err);
	free(err);
	if (!ok)
		return;
	render_hit h;
	vec3 dif, bound;
	bsdf_params at;
	CHECK(trace(w, v3(-1, 1, -1), v3(0, -1, 0), &h) && w->bsdfs[h.material].layered, "a layered texture");
	layer_means(w, h, &dif, &bound, &at);
	/* 0.3 * 0.5 * <0.8, 0.4, 0.2> + <0.6, 0.4, 0.3> * 0.7 * <0.5, 0.5, 1> */
	CHECK(near_vec(dif, v3(0.33f, 0.20f, 0.24f), 2e-3f), "opaque base: diffuse (%g %g %g)", dif.x, dif.y, dif.z);
	/* the ambient: <0.6, 0.4, 0.3> * 0.2 * <0.5, 0.5, 1>, the same at every u */
	CHECK(near_vec(at.emit, v3(0.06f, 0.04f, 0.06f), 1e-6f), "opaque base: emit (%g %g %g)", at.emit.x, at.emit.y,
	      at.emit.z);
	CHECK(at.clear.kind == BSDF_CLEAR_THIN && v3_max_comp(at.clear.tint) == 0.0f, "an opaque base: nothing through");
	/* Both layers Lambertian under one normal: their diffuse is one exact lobe, the same at every
	 * u_layer (nothing else to pick: the picked lobes at weight 0) */
	bool exact = true;
	for (int i = 0; i < 16; i++) {
		render_hit hu = h;
		hu.u_layer = ((float)i + 0.5f) / 16;
		bsdf_params b = w->bsdfs[h.material];
		vec3 ns = h.ns;
		w->rs.shade(w->rs.user, &hu, &b, &ns);
		exact &= near_vec(bsdf_albedo(&b), v3(0.33f, 0.20f, 0.24f), 1e-5f) &&
			 near_vec(b.pov_layer_diffuse, v3(0.33f, 0.20f, 0.24f), 1e-5f) && same_vec(b.pov_weight, v3s(0.0f));
	}
	CHECK(exact, "the layers' diffuse summed into one lobe at every u");

	CHECK(trace(w, v3(1, 1, -1), v3(0, -1, 0), &h) && w->bsdfs[h.material].layered, "the second layered texture");
	layer_means(w, h, &dif, &bound, &at);
	/* <0.12, 0.06, 0.03> + <0.6, 0.4, 0.3> * 0.7 * 0.5 * <0.5, 0.5, 1> */
	CHECK(near_vec(dif, v3(0.225f, 0.13f, 0.135f), 2e-3f), "half-clear base: diffuse (%g %g %g)", dif.x, dif.y,
	      dif.z);
	CHECK(near_vec(at.emit, v3(0.03f, 0.02f, 0.03f), 1e-6f), "half-clear base: emit (%g %g %g)", at.emit.x,
	      at.emit.y, at.emit.z);
	/* through both: <0.6, 0.4, 0.3> * 0.5 */
	CHECK(at.clear.kind == BSDF_CLEAR_THIN && near_vec(at.clear.tint, v3(0.3f, 0.2f, 0.15f), 1e-6f),
	      "half-clear base: tint (%g %g %g)", at.clear.tint.x, at.clear.tint.y, at.clear.tint.z);

	/* The highlight (albedo 1) and the base (1) would reflect 2: both weights halve. */
	CHECK(trace(w, v3(0, 1, 1), v3(0, -1, 0), &h) && w->bsdfs[h.material].layered, "the third layered texture");
	layer_means(w, h, &dif, &bound, &at);
	CHECK(near_vec(bound, v3s(1.0f), 2e-3f), "energy bound: (%g %g %g)", bound.x, bound.y, bound.z);
	CHECK(near_vec(dif, v3s(0.5f), 2e-3f), "the base at half weight: (%g %g %g)", dif.x, dif.y, dif.z);
	world_free(w);

	/* An opaque top layer hides the layers below: its own finish at weight 1, at every u; a
	 * transform of a declared layered texture moves every layer (the base's checker here). */
	ok = build("#declare T = texture { pigment { checker rgb 1 rgb 0 } finish { diffuse 1 ambient 0 } }\n"
		   "  texture { pigment { rgbt 1 } finish { diffuse 0 ambient 0 } }\n"
		   "plane { y, 0.5 texture { T scale 2 } }\n"
		   "sphere { <0, 5, 0>, 1 texture { T } texture { pigment { rgb 0.5 } finish { phong 0.7 ambient 0 } } }\n",
		   &w, &err);
	CHECK(ok, "layered textures: %s", err);
	free(err);
	if (!ok)
		return;
	/* (1.5, 0.5, 0.5) / 2: the checker's first colour; unscaled it would be the second */
	CHECK(trace(w, v3(1.5f, 3, 0.5f), v3(0, -1, 0), &h), "hit the plane");
	layer_means(w, h, &dif, &bound, &at);
	CHECK(same_vec(at.pov_layer_diffuse, v3s(1.0f)), "the scaled base: its diffuse (%g %g %g)",
	      at.pov_layer_diffuse.x, at.pov_layer_diffuse.y, at.pov_layer_diffuse.z);
	CHECK(trace(w, v3(0, 10, 0), v3(0, -1, 0), &h), "hit the sphere");
	bool top = true;
	for (int i = 0; i < 16; i++) {
		h.u_layer = ((float)i + 0.5f) / 16;
		at = w->bsdfs[h.material];
		vec3 ns = h.ns;
		w->rs.shade(w->rs.user, &h, &at, &ns);
		top &= same_vec(at.pov_weight, v3s(1.0f)) && at.pov.phong == 0.7f && same_vec(at.pigment, v3s(0.5f));
	}
	CHECK(top, "an opaque top layer: its own lobes at weight 1");
	world_free(w);
}

int main(void)
{
	if (!mkdtemp(dir))
		return 99;
	world *w;
	char *err = NULL;
	/* Two instances of one declared sphere (radius 1), one scaled non-uniformly in wax (flattened),
	 * one diffuse with no_shadow, and a plane. */
	bool ok = build("camera { location <0, 0, -10> look_at <0, 0, 0> }\n"
			"light_source { <0, 10, 0> color rgb 1 }\n"
			"#declare S = sphere { <0, 0, 0>, 1 }\n"
			"object { S translate <-3, 0, 0> material { diffuse { color rgb <0.2, 0.4, 0.6> } } no_shadow }\n"
			"object { S scale <2, 1, 1> translate <3, 0, 0> material { wax {} } }\n"
			"plane { y, -1 material { diffuse { color rgb 0.5 } } }\n",
			&w, &err);
	CHECK(ok, "world built: %s", err);
	free(err);
	if (!ok)
		return check_done("test_world");
	CHECK(w->stats.flattened == 1, "%zu instances flattened, expected 1", w->stats.flattened);
	CHECK(w->insts[1].identity && !w->insts[0].identity, "the flattened instance has no transform left");
	/* Sphere 0 at x = -3: a ray along +z through its centre enters at z = -1. */
	render_hit h;
	CHECK(trace(w, v3(-3, 0, -5), v3(0, 0, 1), &h), "hit sphere 0");
	CHECK_NEAR(h.t, 4.0, 1e-3);
	CHECK_NEAR(h.ng.z, -1.0, 1e-3);
	CHECK(h.material >= 0 && w->bsdfs[h.material].kind == BSDF_DIFFUSE &&
		      fabsf(w->bsdfs[h.material].diffuse.y - 0.4f) < 1e-6f,
	      "sphere 0's material reaches the hit");
	/* The flattened ellipsoid at x = 3 has half-axis 2 along x: a ray along -x from x = 10 enters at x = 5. */
	CHECK(trace(w, v3(10, 0, 0), v3(-1, 0, 0), &h), "hit the ellipsoid");
	CHECK_NEAR(h.t, 5.0, 2e-3);
	CHECK_NEAR(h.p.x, 5.0, 2e-3);
	CHECK(w->bsdfs[h.material].kind == BSDF_COAT, "wax wears the coat");
	/* A ray grazing the ellipsoid at y = 0.9: x^2/4 + y^2 = 1 gives x = 3 +- 2 sqrt(0.19). */
	CHECK(trace(w, v3(10, 0.9f, 0), v3(-1, 0, 0), &h), "hit the ellipsoid off centre");
	CHECK_NEAR(h.p.x, 3.0 + 2.0 * sqrt(0.19), 5e-3);
	/* The plane under everything, at y = -1. */
	CHECK(trace(w, v3(0, 5, 0), v3(0, -1, 0), &h), "hit the plane");
	CHECK_NEAR(h.p.y, -1.0, 1e-5);
	/* Shadows: the no_shadow sphere does not occlude, the ellipsoid does. */
	render_ray down0 = {v3(-3, 5, 0), v3(0, -1, 0)}, down1 = {v3(3, 5, 0), v3(0, -1, 0)};
	CHECK(!w->rs.occluded(w->rs.user, &down0, 0.0f, 5.9f), "no_shadow sphere casts no shadow");
	CHECK(w->rs.occluded(w->rs.user, &down1, 0.0f, 5.9f), "the ellipsoid casts a shadow");
	/* Misses, and a ray with a NaN never hits. */
	CHECK(!trace(w, v3(0, 5, 0), v3(0, 1, 0), &h), "a ray to the sky misses");
	CHECK(!trace(w, v3(NAN, 0, 0), v3(1, 0, 0), &h), "a NaN ray misses");
	/* Instances share: two objects, one sphere mesh (plus the flattened copy). */
	CHECK(w->insts[0].g != w->insts[1].g, "the flattened object has its own mesh");
	world_free(w);

	/* Two plain instances of one geometry, alike on screen, share its mesh. */
	ok = build("camera { location <0, 0, -10> look_at 0 }\n#declare S = sphere { <0, 0, 0>, 1 }\nobject { S }\n"
		   "object { S translate x * 3 }\n", &w, &err);
	CHECK(ok, "instances: %s", err);
	free(err);
	if (ok) {
		CHECK(w->insts[0].g == w->insts[1].g, "object { Name } shares the mesh");
		CHECK(w->stats.instanced_triangles == 2 * w->stats.triangles, "triangles %zu, instanced %zu",
		      w->stats.triangles, w->stats.instanced_triangles);
		world_free(w);
	}

	/* An SSS group (a box and a far sphere) beside 40 small boxes of another material set along
	 * a circle's arc: the group's circle and nearest-hit queries see the members alone, and the
	 * others' 80-odd hits neither crowd the circle's buffer nor hide the member's hit. */
	{
		char text[8192];
		int len = snprintf(text, sizeof text,
				   "box { <-1, -1, -1>, <1, 0, 1> material { skin { group \"g\" } } }\n"
				   "sphere { <5, 5, 5>, 0.5 material { skin { group \"g\" } } }\n");
		for (int k = 0; k < 40; k++) {
			double a = (10.0 + 70.0 * k / 39.0) * M_PI / 180.0, x = 0.5 * cos(a), y = 0.5 * sin(a);
			len += snprintf(text + len, sizeof text - (size_t)len,
					"box { <%.4f, %.4f, -0.005>, <%.4f, %.4f, 0.005> }\n", x - 0.005, y - 0.005,
					x + 0.005, y + 0.005);
		}
		ok = build(text, &w, &err);
		CHECK(ok, "SSS group: %s", err);
		free(err);
		if (ok) {
			render_hit at = {0};
			at.object = 0;
			tri_circle_hit hits[RENDER_SSS_MAX_HITS];
			bool more = true;
			tri_circle q = {v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0), 0.5f, false};
			uint32_t k = w->rs.circle(w->rs.user, &at, &q, hits, RENDER_SSS_MAX_HITS, &more);
			CHECK(k == 1 && !more && hits[0].inst == 0 && fabsf(hits[0].pos.x - 0.5f) < 1e-5f &&
				  fabsf(hits[0].pos.y) < 1e-5f,
			      "group circle: %u hits (more %d), the first on object %u at (%g %g)", k, more,
			      k ? hits[0].inst : 0, k ? hits[0].pos.x : 0, k ? hits[0].pos.y : 0);
			/* The chosen hit's full record: the circle's position, the normal the weights saw. */
			if (k == 1) {
				render_hit full;
				w->rs.circle_surface(w->rs.user, &hits[0], &full);
				CHECK(full.object == 0 && same_vec(full.p, hits[0].pos) && same_vec(full.ng, hits[0].ng) &&
					  full.prim == hits[0].prim && full.t == 0.0f,
				      "the circle hit's surface: object %u, p (%g %g %g), ng (%g %g %g) of (%g %g %g)",
				      full.object, full.p.x, full.p.y, full.p.z, full.ng.x, full.ng.y, full.ng.z,
				      hits[0].ng.x, hits[0].ng.y, hits[0].ng.z);
			}
			render_ray down = {v3(0.25f, 1, 0), v3(0, -1, 0)};
			render_hit h;
			CHECK(trace(w, down.o, down.d, &h) && h.object != 0 && h.t < 0.6f, "the ray meets a small box first");
			CHECK(w->rs.sss_closest(w->rs.user, &at, &down, 0.0f, INFINITY, &h) && h.object == 0 &&
				  fabsf(h.t - 1.0f) < 1e-5f,
			      "group nearest hit on object %u at t %g", h.object, h.t);
			world_free(w);
		}
	}

	check_layers();
	check_image_clear();

	/* A checker of an opaque colour and POV-Ray's Clear-like rgbf: the texture is transparent
	 * where the pattern says (thin: no interior), its tint pigment * filter + transmit and its
	 * diffuse scaled by the opacity there; opaque and at its full diffuse elsewhere. */
	ok = build("plane { y, 0.5 pigment { checker rgb <0.2, 0.4, 0.6> rgbf <1, 0.5, 1, 1> } finish { diffuse 0.6 } }\n"
		   "sphere { <0, 5, 0>, 1 pigment { rgb 0.5 } }\n"
		   "sphere { <5, 5, 0>, 1 pigment { rgbt <0.5, 0.5, 0.5, 0.75> } }\n",
		   &w, &err);
	CHECK(ok, "checker with filter: %s", err);
	free(err);
	if (ok) {
		render_hit hc;
		CHECK(trace(w, v3(0.5f, 3, 0.5f), v3(0, -1, 0), &hc), "hit the checker's first square");
		const bsdf_params base = w->bsdfs[hc.material];
		CHECK(base.clear.kind == BSDF_CLEAR_THIN && base.clear.patterned, "a patterned thin surface");
		bsdf_params at = base;
		vec3 ns = hc.ns;
		w->rs.shade(w->rs.user, &hc, &at, &ns);
		CHECK(v3_max_comp(at.clear.tint) == 0.0f && at.clear.reflect == 0.0f, "opaque square: tint %g",
		      v3_max_comp(at.clear.tint));
		CHECK_NEAR(at.pov.diffuse, 0.6, 1e-6);
		/* the implicit ambient 0.1 glows where the colour is opaque, not where it is clear
		 * (POV-Ray's layCol * emission * att) */
		CHECK(near_vec(at.emit, v3(0.02f, 0.04f, 0.06f), 1e-6f), "opaque square: emit (%g %g %g)", at.emit.x,
		      at.emit.y, at.emit.z);
		CHECK(trace(w, v3(1.5f, 3, 0.5f), v3(0, -1, 0), &hc), "hit the checker's second square");
		at = base;
		w->rs.shade(w->rs.user, &hc, &at, &ns);
		CHECK(same_vec(at.clear.tint, v3(1, 0.5f, 1)), "clear square: tint (%g %g %g)", at.clear.tint.x,
		      at.clear.tint.y, at.clear.tint.z);
		CHECK_NEAR(at.pov.diffuse, 0.0, 0);
		CHECK(v3_max_comp(at.emit) == 0.0f, "clear square: no glow (%g)", v3_max_comp(at.emit));
		/* a plain rgbt colour glows its ambient times its opacity: 0.1 * 0.5 * 0.25 */
		CHECK(trace(w, v3(5, 10, 0), v3(0, -1, 0), &hc), "hit the transmitting sphere");
		CHECK(near_vec(w->bsdfs[hc.material].emit, v3s(0.0125f), 1e-6f), "rgbt 0.75: emit %g",
		      w->bsdfs[hc.material].emit.x);
		/* the plain sphere stays opaque */
		CHECK(trace(w, v3(0, 10, 0), v3(0, -1, 0), &hc) && w->bsdfs[hc.material].clear.kind == BSDF_CLEAR_NONE &&
			      !w->bsdfs[hc.material].clear.patterned,
		      "an opaque pigment is no transparent surface");
		world_free(w);
	}

	/* brilliance b: a Lambert lobe of the energy POV-Ray's cos^b reflects, 2 / (b + 1) of the
	 * diffuse; `diffuse albedo` undoes it as POV-Ray's (b + 1) / 2 does; b = 1 changes nothing. */
	ok = build("sphere { <-3, 0, 0>, 1 pigment { rgb 1 } finish { diffuse 0.6 brilliance 5 } }\n"
		   "sphere { <0, 0, 0>, 1 pigment { rgb 1 } finish { diffuse albedo 0.6 brilliance 5 } }\n"
		   "sphere { <3, 0, 0>, 1 pigment { rgb 1 } finish { diffuse 0.6 brilliance 1 } }\n",
		   &w, &err);
	CHECK(ok, "brilliance: %s", err);
	free(err);
	if (ok) {
		const float want[3] = {0.6f * 2.0f / 6.0f, 0.6f, 0.6f};
		for (int i = 0; i < 3; i++) {
			render_hit hb;
			CHECK(trace(w, v3(3.0f * (float)(i - 1), 0, -5), v3(0, 0, 1), &hb), "hit sphere %d", i);
			CHECK_NEAR(w->bsdfs[hb.material].pov.diffuse, want[i], 1e-6);
		}
		world_free(w);
	}

	check_sphere_levels();
	check_many_spheres();
	check_camera_text();
	check_tangents();

	/* Errors name the scene's place, the string of the file: a missing mesh file, a missing texture. */
	ok = build("mesh { file \"nothere.obj\" }\n", &w, &err);
	CHECK(!ok && strstr(err, "s.pov:1:13: error: mesh file '") && strstr(err, "nothere.obj': cannot open it"),
	      "missing mesh:\n%s", err);
	free(err);
	ok = build("sphere { 0, 1 material { diffuse { image \"none.png\" } } }\n", &w, &err);
	CHECK(!ok && strstr(err, "s.pov:1:42: error: image file '") && strstr(err, "none.png': cannot open it"),
	      "missing image:\n%s", err);
	free(err);
	rmdir(dir);
	return check_done("test_world");
}
