/* test_integrator: the path tracer against closed-form answers — the white furnace (a convex
 * diffuse object under a uniform sky of radiance 1 shows albedo * 1), a closed emissive diffuse box
 * (radiance Le / (1 - albedo) everywhere), a point light's irradiance law — and light sampling,
 * BSDF sampling and MIS converging to the same image under a sphere light and an environment map. */
#include "chi2.h"
#include "render/camera.h"
#include "render/integrator.h"
#include "scenes.h"

typedef struct image {
	int w, h;
	double mean[64 * 64], var[64 * 64]; /* luminance mean and the variance of that mean */
} image;

/* Renders luminance per pixel with spp samples straight through render_path. */
static void render_image(const ts_scene *s, const cam *c, render_settings set, int spp, image *im)
{
	im->w = c->width;
	im->h = c->height;
	for (int y = 0; y < c->height; y++)
		for (int x = 0; x < c->width; x++) {
			double sum = 0, sum2 = 0;
			for (int k = 0; k < spp; k++) {
				render_sampler g = render_sampler_make(RENDER_SAMPLER_SOBOL, 77, (uint32_t)x, (uint32_t)y, (uint32_t)k);
				vec2 pu = render_sampler_2d(&g, RENDER_DIM_PIXEL);
				render_ray r = cam_ray(c, x, y, pu, v2(0, 0));
				render_sample smp = render_path(&s->rs, &set, r, &g);
				double l = v3_luminance(smp.radiance);
				sum += l;
				sum2 += l * l;
			}
			double m = sum / spp;
			im->mean[y * c->width + x] = m;
			im->var[y * c->width + x] = fmax(0.0, sum2 / spp - m * m) / (spp - 1);
		}
}

static double image_mean(const image *im)
{
	double s = 0;
	for (int i = 0; i < im->w * im->h; i++)
		s += im->mean[i];
	return s / (im->w * im->h);
}

/* Every pixel within max(tol_rel * want, 5 sigma) of want; the image mean within tol_rel. */
static void expect_image(const char *what, const image *im, double want, double tol_rel)
{
	int bad = 0;
	double worst = 0;
	for (int i = 0; i < im->w * im->h; i++) {
		double tol = fmax(tol_rel * want, 5 * sqrt(im->var[i]));
		worst = fmax(worst, fabs(im->mean[i] - want) / want);
		if (fabs(im->mean[i] - want) > tol && bad++ < 5)
			CHECK(0, "%s: pixel %d = %g, want %g +- %g", what, i, im->mean[i], want, tol);
	}
	CHECK(bad == 0, "%s: %d pixels off", what, bad);
	double m = image_mean(im);
	printf("  %-45s mean %.5f (want %g), worst pixel off by %.3f %%\n", what, m, want, 100 * worst);
	CHECK(fabs(m - want) <= tol_rel * want, "%s: image mean %g, want %g (tol %g)", what, m, want,
	      tol_rel);
}

/* A camera at loc looking at `at` with horizontal FOV angle, for a w x h image. */
static cam make_cam(vec3 loc, vec3 at, float angle, int w, int h)
{
	cam c;
	CHECK(ts_camera(loc, at, angle, w, h, &c), "camera");
	return c;
}

static void test_furnace(int spp)
{
	ts_scene s;
	ts_init(&s);
	s.sph[s.nsph++] = (ts_sphere){v3(0, 0, 0), 1.0f, 0};
	light bg = light_background(v3s(1));
	light_set_add(&s.lights, &bg);
	light_set_finish(&s.lights, 2.0f);
	cam c =
	    make_cam(v3(0, 0, -3), v3(0, 0, 0), 24, 6, 6); /* the sphere (19.5 deg radius) fills the frame */
	static image im;
	const render_mode modes[3] = {RENDER_BSDF_ONLY, RENDER_MIS, RENDER_LIGHT_ONLY};
	const char *names[3] = {"furnace albedo 1, BSDF", "furnace albedo 1, MIS", "furnace albedo 1, light"};
	for (int m = 0; m < 3; m++) {
		s.mat[0] = bsdf_diffuse(v3s(1));
		render_image(&s, &c, (render_settings){.max_trace_level = 5, .mode = modes[m]}, spp, &im);
		expect_image(names[m], &im, 1.0, 0.01);
		if (modes[m] == RENDER_BSDF_ONLY) /* importance-sampled paths: 1 everywhere, no noise */
			for (int i = 0; i < im.w * im.h; i++)
				CHECK(fabs(im.mean[i] - 1.0) <= 0.01, "BSDF-sampled furnace pixel %d = %g", i,
				      im.mean[i]);
	}
	/* A convex object sees only the sky: albedo 0.5 shows exactly 0.5 (every pixel is on it). */
	s.mat[0] = bsdf_diffuse(v3s(0.5f));
	render_image(&s, &c, (render_settings){.max_trace_level = 5, .mode = RENDER_MIS}, spp, &im);
	expect_image("furnace albedo 0.5, MIS", &im, 0.5, 0.01);
	/* The coat over a white interior never creates energy: at most 1. */
	s.mat[0] = bsdf_coat(v3s(1), 1.4f, 0.3f);
	render_image(&s, &c, (render_settings){.max_trace_level = 5, .mode = RENDER_MIS}, spp, &im);
	double m = image_mean(&im);
	CHECK(m <= 1.0 + 0.01 && m > 0.8, "coat in the furnace: %g", m);
	light_set_free(&s.lights);
}

static void test_closed_box(int spp)
{
	ts_scene s;
	ts_init(&s);
	ts_add_box(&s, v3(-1, -1, -1), v3(1, 1, 1), 0, 0);
	s.mat[0] = bsdf_diffuse(v3s(0.5f));
	vec3 v[36];
	for (int i = 0; i < s.ntri; i++)
		for (int k = 0; k < 3; k++)
			v[3 * i + k] = s.tri[i].v[k];
	light mesh;
	CHECK(light_mesh_init(&mesh, v, 12, v3s(1)), "box light");
	light_set_add(&s.lights, &mesh);
	light_set_finish(&s.lights, 2.0f);
	cam c = make_cam(v3(0.1f, 0.2f, -0.3f), v3(0.5f, 0.1f, 1), 90, 8, 8);
	static image im;
	render_image(&s, &c, (render_settings){.max_trace_level = 200, .mode = RENDER_MIS}, spp, &im);
	expect_image("closed emissive box, a = 0.5: Le / (1 - a)", &im, 2.0, 0.01);
	light_set_free(&s.lights);
}

static void test_point_light(void)
{
	ts_scene s;
	ts_init(&s);
	s.pl[s.npl++] = (ts_plane){v3(0, 1, 0), 0.0f, 0};
	s.mat[0] = bsdf_diffuse(v3s(0.5f));
	light pt = light_point(v3(1, 2, 0), v3s(8));
	light_set_add(&s.lights, &pt);
	light_set_finish(&s.lights, 10.0f);
	cam c = make_cam(v3(0, 3, -3), v3(0, 0, 0), 0.01f, 1, 1);
	static image im;
	render_image(&s, &c, (render_settings){.max_trace_level = 1, .mode = RENDER_MIS}, 4, &im);
	/* At the origin: d^2 = 5, cos = 2 / sqrt(5); L = (a / pi) I cos / d^2. */
	double want = 0.5 / M_PI * 8 * (2 / sqrt(5.0)) / 5;
	CHECK_NEAR(im.mean[0], want, 1e-3 * want);
	light_set_free(&s.lights);
}

/* Light sampling (im[0]), BSDF sampling (im[1]) and MIS (im[2]) agree pixel by pixel and in the
 * image mean within 5 sigma. */
static void compare_strategies(const image *im)
{
	const char *names[3] = {"light sampling", "BSDF sampling", "MIS"};
	int np = im[0].w * im[0].h;
	double mean_mis = image_mean(&im[2]);
	CHECK(mean_mis > 0.05, "MIS image is dark: %g", mean_mis);
	for (int a = 0; a < 3; a++)
		for (int b = a + 1; b < 3; b++) {
			int bad = 0;
			double worst = 0, sa = 0, sb = 0, va = 0, vb = 0;
			for (int i = 0; i < np; i++) {
				/* A floor of 1 % of the image mean: where one strategy almost never finds the
				 * light its variance estimate is zero although its error is not. */
				double sd = sqrt(im[a].var[i] + im[b].var[i]) + 0.002 * mean_mis;
				double z = fabs(im[a].mean[i] - im[b].mean[i]) / sd;
				worst = fmax(worst, z);
				bad += z > 5;
				sa += im[a].mean[i], sb += im[b].mean[i], va += im[a].var[i],
				    vb += im[b].var[i];
			}
			double zm = fabs(sa - sb) / sqrt(va + vb);
			CHECK(bad == 0 && zm < 5,
			      "%s vs %s: %d pixels beyond 5 sigma (worst %g), means %g vs %g (z %g)",
			      names[a], names[b], bad, worst, sa / np, sb / np, zm);
			printf("  %-15s vs %-15s worst pixel z %.2f, image means %.4f %.4f (z %.2f)\n",
			       names[a], names[b], worst, sa / np, sb / np, zm);
		}
}

/* Renders light sampling, BSDF sampling (4x the samples: it is the noisier) and MIS into im[0..2]
 * and compares them. */
static void render_three(const ts_scene *s, const cam *c, int max_level, int spp, image *im)
{
	const render_mode modes[3] = {RENDER_LIGHT_ONLY, RENDER_BSDF_ONLY, RENDER_MIS};
	for (int m = 0; m < 3; m++)
		render_image(s, c, (render_settings){.max_trace_level = max_level, .mode = modes[m]}, m == 1 ? 4 * spp : spp, &im[m]);
	compare_strategies(im);
}

static void test_mis(int spp)
{
	ts_scene s;
	ts_init(&s);
	s.pl[s.npl++] = (ts_plane){v3(0, 1, 0), 0.0f, 0};
	s.sph[s.nsph++] = (ts_sphere){v3(-0.8f, 0.4f, 0.6f), 0.4f, 1};
	s.mat[0] = bsdf_pov_finish(v3(0.8f, 0.7f, 0.6f), 0.6f, 0.5f, 0.05f);
	s.mat[1] = bsdf_coat(v3(0.3f, 0.6f, 0.9f), 1.5f, 0.3f);
	light sl = light_sphere(v3(0.5f, 1.5f, 0.5f), 0.4f, v3(3, 3, 3));
	light_set_add(&s.lights, &sl);
	light_set_finish(&s.lights, 5.0f);
	cam c = make_cam(v3(0, 1.2f, -2.5f), v3(0, 0.2f, 0.5f), 60, 8, 8);
	static image im[3];
	render_three(&s, &c, 3, spp, im);
	/* MIS should not be noisier than the worse of the two strategies. */
	double v_mis = 0, v_light = 0;
	for (int i = 0; i < 64; i++)
		v_mis += im[2].var[i], v_light += im[0].var[i];
	CHECK(v_mis <= v_light * 1.05, "MIS variance %g above light sampling's %g", v_mis, v_light);
	light_set_free(&s.lights);
}

/* The lat-long environment in the integrator: a constant map is the furnace again, and a map with
 * a sun is rendered alike by light sampling, BSDF sampling and MIS. */
static void test_envmap(int spp)
{
	enum { EW = 16, EH = 8 };
	static float img[EW * EH * 3];
	for (int i = 0; i < EW * EH * 3; i++)
		img[i] = 1.0f;
	ts_scene s;
	ts_init(&s);
	s.sph[s.nsph++] = (ts_sphere){v3(0, 0, 0), 1.0f, 0};
	s.mat[0] = bsdf_diffuse(v3s(1));
	xform rot = xform_rotate(d3(10, 40, 0));
	light env;
	CHECK(light_envmap_init(&env, img, EW, EH, 1.0f, &rot), "envmap");
	light_set_add(&s.lights, &env);
	light_set_finish(&s.lights, 2.0f);
	cam c = make_cam(v3(0, 0, -3), v3(0, 0, 0), 24, 6, 6);
	static image im[3];
	render_image(&s, &c, (render_settings){.max_trace_level = 5, .mode = RENDER_MIS}, spp, &im[0]);
	expect_image("furnace under a constant environment map", &im[0], 1.0, 0.01);

	for (int i = 0; i < EW * EH; i++) { /* a sky gradient and a small sun */
		float v = 0.2f + 0.8f * (float)(EH - i / EW) / EH;
		img[3 * i] = 0.6f * v, img[3 * i + 1] = 0.8f * v, img[3 * i + 2] = v;
	}
	img[3 * (2 * EW + 11)] = img[3 * (2 * EW + 11) + 1] = img[3 * (2 * EW + 11) + 2] = 30.0f;
	light_set_free(&s.lights);
	light_set_init(&s.lights);
	CHECK(light_envmap_init(&env, img, EW, EH, 1.0f, &rot), "envmap");
	light_set_add(&s.lights, &env);
	light_set_finish(&s.lights, 2.0f);
	s.mat[0] = bsdf_pov_finish(v3(0.8f, 0.8f, 0.8f), 0.6f, 0.4f, 0.05f);
	c = make_cam(v3(0, 0, -3), v3(0, 0, 0), 50, 6, 6);
	render_three(&s, &c, 3, spp, im);
	light_set_free(&s.lights);
}

/* The scene's shade() hook (textures, normal maps): an albedo it sets is what renders, and a
 * shading normal tilted away from the viewer does not blacken the surface. */
static int shade_mode;
static void shade_hook(void *user, const render_hit *hit, bsdf_params *params, vec3 *ns)
{
	(void)user;
	if (shade_mode == 0) {
		params->diffuse = v3s(0.5f);
	} else { /* tilt 85 degrees towards +x, within ng's hemisphere */
		vec3 t = v3_normalize(v3_sub(v3(1, 0, 0), v3_scale(hit->ng, hit->ng.x)));
		if (v3_length(t) > 0)
			*ns = v3_normalize(
			    v3_add(v3_scale(hit->ng, cosf(1.4835f)), v3_scale(t, sinf(1.4835f))));
	}
}

static void test_shade_hook(int spp)
{
	ts_scene s;
	ts_init(&s);
	s.sph[s.nsph++] = (ts_sphere){v3(0, 0, 0), 1.0f, 0};
	s.mat[0] = bsdf_diffuse(v3s(1));
	s.rs.shade = shade_hook;
	light bg = light_background(v3s(1));
	light_set_add(&s.lights, &bg);
	light_set_finish(&s.lights, 2.0f);
	cam c = make_cam(v3(0, 0, -3), v3(0, 0, 0), 24, 6, 6);
	static image im;
	shade_mode = 0;
	render_image(&s, &c, (render_settings){.max_trace_level = 5, .mode = RENDER_BSDF_ONLY}, 16, &im);
	expect_image("shade() sets albedo 0.5", &im, 0.5, 0.01);
	shade_mode = 1;
	render_image(&s, &c, (render_settings){.max_trace_level = 5, .mode = RENDER_MIS}, spp, &im);
	int dark = 0;
	for (int i = 0; i < im.w * im.h; i++)
		dark += !(im.mean[i] > 0.2);
	CHECK(dark == 0, "%d pixels dark or NaN under tilted shading normals", dark);
	light_set_free(&s.lights);
}

int main(void)
{
	double scale = test_scale();
	int spp = (int)(1024 * scale) < 64 ? 64 : (int)(1024 * scale);
	test_furnace(4 * spp);
	test_closed_box(spp);
	test_point_light();
	test_mis(spp);
	test_envmap(spp);
	test_shade_hook(spp);
	return check_done("test_integrator");
}
