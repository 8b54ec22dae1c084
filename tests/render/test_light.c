/* test_light: each light samples the density its pdf states (chi-square over directions or over
 * the light's own domain), the pdfs integrate to one, the radiance a sample reports matches what a
 * ray sees, and delta lights follow POV-Ray's point/spot/parallel laws: its fade, tightness and
 * cylinder; area lights sample their area uniformly and give the analytic irradiance. */
#include "chi2.h"
#include "render/light.h"
#include "scenes.h"

typedef struct lctx {
	const light *l;
	vec3 p, n; /* n: the receiver's normal, or zero */
} lctx;

static bool s_light(void *ctx, rng *g, vec3 *d)
{
	lctx *c = ctx;
	light_sample ls;
	if (!light_sample_from(c->l, c->p, c->n, v2(rng_float(g), rng_float(g)), &ls))
		return false;
	*d = ls.wi;
	return true;
}

static double p_light(void *ctx, vec3 d)
{
	lctx *c = ctx;
	return light_pdf(c->l, c->p, c->n, d, INFINITY, v3s(0));
}

static void test_sphere_light(long n)
{
	light l = light_sphere(v3(1, 2, 3), 0.8f, v3(2, 2, 2));
	lctx c = {&l, v3(0.2f, -0.5f, 0.1f), v3s(0)};
	vec3 axis = v3_normalize(v3_sub(l.pos, c.p));
	float d = v3_length(v3_sub(l.pos, c.p));
	double cos_max = sqrt(1.0 - 0.64 / ((double)d * d));
	chi2_sphere("sphere light", s_light, p_light, &c, axis, cos_max, 10, 32, 4, n, 20);
	/* Sampled points lie on the near side of the sphere, and pdf() agrees with the sample. */
	rng g;
	rng_seed(&g, 1, 1);
	for (int i = 0; i < 1000; i++) {
		light_sample ls;
		CHECK(light_sample_from(&l, c.p, v3s(0), v2(rng_float(&g), rng_float(&g)), &ls),
		      "sphere sample failed");
		vec3 y = v3_madd(c.p, ls.wi, ls.dist);
		CHECK_NEAR(v3_length(v3_sub(y, l.pos)), 0.8, 1e-4);
		CHECK(v3_dot(v3_sub(y, l.pos), ls.wi) <= 1e-4f, "sample on the far side");
		CHECK_NEAR(ls.pdf, light_pdf(&l, c.p, v3s(0), ls.wi, ls.dist, v3s(0)), 1e-3 * ls.pdf);
		float t;
		render_ray r = {c.p, ls.wi};
		CHECK(light_sphere_hit(&l, &r, 0, INFINITY, &t) && fabsf(t - ls.dist) < 1e-3f * ls.dist,
		      "ray misses: %g vs %g", t, ls.dist);
	}
	/* Far away a sphere light gives the irradiance of the point light of the same colour. */
	light far = light_sphere(v3(0, 50, 0), 0.5f, v3(100, 100, 100));
	double e = 0;
	for (int i = 0; i < 10000; i++) {
		light_sample ls;
		if (light_sample_from(&far, v3s(0), v3s(0), v2(rng_float(&g), rng_float(&g)), &ls))
			e += ls.li.x * ls.wi.y / ls.pdf;
	}
	CHECK_NEAR(e / 10000, 100.0 / 2500.0, 1e-3 * 100.0 / 2500.0);
	/* A tiny, distant sphere (r / d = 1e-3, cos_max within 4 ulps of 1) keeps its cone exact:
	 * every sample hits it, pdf() agrees, and the irradiance is the point light's. */
	light tiny = light_sphere(v3(0, 50, 0), 0.05f, v3(100, 100, 100));
	e = 0;
	int misses = 0;
	for (int i = 0; i < 10000; i++) {
		light_sample ls;
		float t;
		if (!light_sample_from(&tiny, v3s(0), v3s(0), v2(rng_float(&g), rng_float(&g)), &ls))
			continue;
		render_ray r = {v3s(0), ls.wi};
		misses += !light_sphere_hit(&tiny, &r, 0, INFINITY, &t) ||
			  light_pdf(&tiny, v3s(0), v3s(0), ls.wi, 0, v3s(0)) != ls.pdf;
		e += ls.li.x * ls.wi.y / ls.pdf;
	}
	CHECK(misses == 0, "tiny sphere light: %d of 10000 samples miss it or disagree on the pdf", misses);
	CHECK_NEAR(e / 10000, 100.0 / 2500.0, 1e-3 * 100.0 / 2500.0);
	light_sample ls;
	CHECK(!light_sample_from(&l, l.pos, v3s(0), v2(0.5f, 0.5f), &ls), "sampling from inside a sphere light");
}

static void test_background(long n)
{
	light l = light_background(v3(0.5f, 1, 2));
	lctx c = {&l, v3(3, 1, 2), v3s(0)};
	chi2_sphere("background", s_light, p_light, &c, v3(0, 1, 0), -1.0, 16, 32, 4, n, 21);
	/* With a receiver's normal: cosine-weighted about it, nothing below it (the chi-square's
	 * cells below the horizon expect zero). */
	vec3 nr = v3_normalize(v3(0.3f, -0.8f, 0.5f));
	lctx cn = {&l, v3(3, 1, 2), nr};
	chi2_sphere("background, cosine about a normal", s_light, p_light, &cn, nr, -1.0, 16, 32, 4, n, 22);
	rng g;
	rng_seed(&g, 4, 4);
	for (int i = 0; i < 1000; i++) {
		light_sample ls;
		CHECK(light_sample_from(&l, cn.p, nr, v2(rng_float(&g), rng_float(&g)), &ls), "background sample");
		CHECK(v3_dot(ls.wi, nr) > 0.0f && isinf(ls.dist), "background sample below the normal");
		CHECK_NEAR(ls.pdf, v3_dot(ls.wi, nr) / M_PI, 1e-5);
		CHECK_NEAR(ls.pdf, light_pdf(&l, cn.p, nr, ls.wi, INFINITY, v3s(0)), 1e-6);
	}
	CHECK(light_pdf(&l, cn.p, nr, v3_neg(nr), INFINITY, v3s(0)) == 0.0f, "no density below the normal");
	CHECK_NEAR(light_radiance_dir(&l, v3(0, 0, 1)).z, 2.0, 0);
}

static void test_envmap(long n)
{
	enum { W = 16, H = 8 };
	float img[W * H * 3];
	for (int i = 0; i < W * H; i++) {
		float v = (float)((i * 37) % 11) * 0.1f; /* includes zeros */
		img[3 * i] = v;
		img[3 * i + 1] = 0.5f * v;
		img[3 * i + 2] = 2.0f * v;
	}
	img[3 * (3 * W + 5) + 1] = 40.0f; /* a sun */
	xform rot = xform_rotate(d3(20, 75, -10));
	light l;
	CHECK(light_envmap_init(&l, img, W, H, 1.5f, &rot), "envmap init");

	/* (u, v) cells are drawn in proportion to luminance * sin(theta at the row centre). */
	double obs[W * H] = {0}, ex[W * H], sum = 0;
	for (int i = 0; i < W * H; i++) {
		const float *p = img + 3 * i;
		ex[i] = v3_luminance(v3(p[0], p[1], p[2])) * sin(M_PI * (i / W + 0.5) / H);
		sum += ex[i];
	}
	rng g;
	rng_seed(&g, 9, 2);
	xform inv = {0};
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			inv.m[i][j] = rot.m[j][i];
	for (long i = 0; i < n; i++) {
		light_sample ls;
		if (!light_sample_from(&l, v3s(0), v3s(0), v2(rng_float(&g), rng_float(&g)), &ls))
			continue;
		vec3 local = d3_to_v3(xform_vector(&inv, v3_to_d3(ls.wi)));
		vec2 uv = light_env_uv(local);
		int x = (int)(uv.x * W), y = (int)(uv.y * H);
		x = x >= W ? W - 1 : x;
		y = y >= H ? H - 1 : y;
		obs[y * W + x] += 1;
		if (i < 2000) {
			CHECK_NEAR(ls.pdf, light_pdf(&l, v3s(0), v3s(0), ls.wi, INFINITY, v3s(0)), 2e-3 * ls.pdf);
			vec3 seen = light_radiance_dir(&l, ls.wi);
			CHECK_NEAR(seen.y, ls.li.y, 1e-5);
		}
	}
	for (int i = 0; i < W * H; i++)
		ex[i] *= n / sum;
	chi2_counts("environment map (u,v cells)", obs, ex, W * H);

	/* The solid-angle pdf integrates to one over the sphere (midpoint rule in (u, v)). */
	double integral = 0;
	const int NU = 8 * W, NV = 8 * H;
	for (int j = 0; j < NV; j++)
		for (int i = 0; i < NU; i++) {
			vec2 uv = v2((i + 0.5f) / NU, (j + 0.5f) / NV);
			vec3 wd = d3_to_v3(xform_vector(&rot, v3_to_d3(light_env_dir(uv))));
			float st = sinf(uv.y * RENDER_PI);
			integral += light_pdf(&l, v3s(0), v3s(0), wd, INFINITY, v3s(0)) * st * 2 * M_PI * M_PI /
				    ((double)NU * NV);
		}
	CHECK_NEAR(integral, 1.0, 1e-3);

	/* The convention: the map's centre is straight ahead (+z), row 0 is up, u = 0.75 is +x. */
	vec3 ahead = light_env_dir(v2(0.5f, 0.5f)), up = light_env_dir(v2(0.3f, 0.0f)),
	     right = light_env_dir(v2(0.75f, 0.5f));
	CHECK(ahead.z > 0.999f && up.y > 0.999f && right.x > 0.999f,
	      "ahead (%g %g %g) up (%g %g %g) right (%g %g %g)", ahead.x, ahead.y, ahead.z, up.x, up.y, up.z,
	      right.x, right.y, right.z);
	vec2 back = light_env_uv(light_env_dir(v2(0.3f, 0.6f)));
	CHECK(fabsf(back.x - 0.3f) < 1e-5f && fabsf(back.y - 0.6f) < 1e-5f, "uv round trip (%g %g)", back.x,
	      back.y);
	light_free(&l);
}

static void test_mesh(long n)
{
	/* Three triangles far apart, of areas 0.5, 2 and 4.5, one of them seen from behind. */
	vec3 v[9] = {v3(0, 2, 0), v3(1, 2, 0),	 v3(0, 2, 1),  v3(3, 0, -1), v3(3, 2, -1),
		     v3(3, 0, 1), v3(-2, -1, 4), v3(1, -1, 4), v3(-2, 2, 4)};
	light l;
	CHECK(light_mesh_init(&l, v, 3, v3(1, 2, 3)), "mesh init");
	CHECK_NEAR(l.area, 7.0, 1e-5);
	vec3 p = v3(0.5f, 0.3f, 0.2f);
	enum { NB = 6, NBIN = 3 * NB * NB };
	double obs[NBIN] = {0}, ex[NBIN];
	rng g;
	rng_seed(&g, 4, 4);
	for (long i = 0; i < n; i++) {
		light_sample ls;
		if (!light_sample_from(&l, p, v3s(0), v2(rng_float(&g), rng_float(&g)), &ls))
			continue;
		vec3 y = v3_madd(p, ls.wi, ls.dist);
		int k = y.y > 1.99f ? 0 : y.x > 2.99f ? 1 : 2; /* which triangle, by its plane */
		const vec3 *t = v + 3 * k;
		/* Barycentric of vertex 0 and vertex 1 from sub-triangle areas. */
		vec3 nrm = v3_cross(v3_sub(t[1], t[0]), v3_sub(t[2], t[0]));
		float a = v3_length(nrm);
		float b0 = v3_length(v3_cross(v3_sub(t[1], y), v3_sub(t[2], y))) / a;
		float b1 = v3_length(v3_cross(v3_sub(t[2], y), v3_sub(t[0], y))) / a;
		int i0 = (int)(b0 * NB), i1 = (int)(b1 / fmaxf(1e-6f, 1 - b0) * NB);
		i0 = i0 >= NB ? NB - 1 : i0;
		i1 = i1 >= NB ? NB - 1 : i1;
		obs[k * NB * NB + i0 * NB + i1] += 1;
		if (i < 1000) {
			float pdf = light_pdf(&l, p, v3s(0), ls.wi, ls.dist, v3_normalize(nrm));
			CHECK_NEAR(ls.pdf, pdf, 1e-3 * pdf);
		}
	}
	const double area[3] = {0.5, 2.0, 4.5};
	for (int k = 0; k < 3; k++)
		for (int i0 = 0; i0 < NB; i0++)
			for (int i1 = 0; i1 < NB; i1++) {
				double lo = (double)i0 / NB, hi = (double)(i0 + 1) / NB;
				ex[k * NB * NB + i0 * NB + i1] =
				    n * area[k] / 7.0 * ((1 - lo) * (1 - lo) - (1 - hi) * (1 - hi)) / NB;
			}
	chi2_counts("mesh light (triangle, barycentrics)", obs, ex, NBIN);

	/* The solid-angle pdf integrates to one: 4 pi E[pdf(d)] over uniform directions d that hit. */
	double sum = 0, sum2 = 0;
	long m = test_samples(400000);
	for (long i = 0; i < m; i++) {
		vec3 d = render_uniform_sphere(v2(rng_float(&g), rng_float(&g)));
		render_ray r = {p, d};
		double best = INFINITY, pdf = 0;
		for (int k = 0; k < 3; k++) {
			float t;
			if (ts_tri_hit(v + 3 * k, &r, 0, (float)best, &t)) {
				best = t;
				vec3 nrm = v3_normalize(
				    v3_cross(v3_sub(v[3 * k + 1], v[3 * k]), v3_sub(v[3 * k + 2], v[3 * k])));
				pdf = light_pdf(&l, p, v3s(0), d, t, nrm);
			}
		}
		sum += pdf * 4 * M_PI;
		sum2 += pdf * pdf * 16 * M_PI * M_PI;
	}
	double mean = sum / m, se = sqrt((sum2 / m - mean * mean) / m);
	CHECK(fabs(mean - 1.0) < 5 * se + 1e-3, "mesh pdf integrates to %g +- %g", mean, se);
	light_free(&l);
}

static void test_delta_and_set(void)
{
	light pt = light_point(v3(0, 4, 0), v3(8, 8, 8));
	light_sample ls;
	CHECK(light_sample_from(&pt, v3(0, 2, 0), v3s(0), v2(0, 0), &ls) && ls.delta, "point sample");
	CHECK_NEAR(ls.li.x, 2.0, 1e-6);
	CHECK_NEAR(ls.dist, 2.0, 1e-6);

	/* Spot: radius 20, falloff 40 degrees about -y; full at 10 deg, zero at 45, smoothstep at 30. */
	light sp = light_spot(v3(0, 1, 0), v3(0, 0, 0), v3s(1), 20, 40);
	for (float deg = 10; deg <= 45; deg += 5) {
		float r = deg * RENDER_PI / 180;
		vec3 q = v3(sinf(r), 1 - cosf(r), 0); /* at distance 1 from the light */
		bool ok = light_sample_from(&sp, q, v3s(0), v2(0, 0), &ls);
		float c20 = cosf(20 * RENDER_PI / 180), c40 = cosf(40 * RENDER_PI / 180),
		      t = (cosf(r) - c40) / (c20 - c40);
		double want = deg <= 20 ? 1.0 : deg >= 40 ? 0.0 : t * t * (3 - 2 * t);
		CHECK(fabs((ok ? ls.li.x : 0.0) - want) < 1e-4, "spot at %g deg: %g, want %g", deg,
		      ok ? ls.li.x : 0.0, want);
	}

	/* A cone wider than a half-space (POV-Ray's laser.pov: radius 50, falloff 110): the spline
	 * reaches down to cos 110 < 0, but nothing behind the light's plane is lit (POV-Ray's
	 * Attenuate_Light: cos theta > 0). */
	light wide = light_spot(v3(0, 1, 0), v3(0, 0, 0), v3s(1), 50, 110);
	for (float deg = 40; deg <= 130; deg += 10) {
		float r = deg * RENDER_PI / 180;
		vec3 q = v3(sinf(r), 1 - cosf(r), 0);
		bool ok = light_sample_from(&wide, q, v3s(0), v2(0, 0), &ls);
		float c50 = cosf(50 * RENDER_PI / 180), c110 = cosf(110 * RENDER_PI / 180),
		      t = (cosf(r) - c110) / (c50 - c110);
		double want = deg <= 50 ? 1.0 : deg >= 90 ? 0.0 : t * t * (3 - 2 * t);
		CHECK(fabs((ok ? ls.li.x : 0.0) - want) < 1e-4, "wide spot at %g deg: %g, want %g", deg,
		      ok ? ls.li.x : 0.0, want);
	}

	/* falloff below radius (radius 30, falloff 15). POV-Ray keeps both (parser.cpp: no clamp);
	 * its Attenuate_Light, written here from its formula, applies cubic_spline(cos falloff,
	 * cos radius, cos theta) only outside the radius, where cos theta < cos radius < cos falloff
	 * makes it 0: full light inside the radius, none outside, a hard edge at the radius (not
	 * at the falloff). light_spot's clamp of falloff up to radius gives the same. */
	light narrow = light_spot(v3(0, 1, 0), v3(0, 0, 0), v3s(1), 30, 15);
	for (float deg = 1; deg <= 61; deg += 4) { /* off the edge: 29 and 33 beside it */
		float r = deg * RENDER_PI / 180;
		vec3 q = v3(sinf(r), 1 - cosf(r), 0);
		bool ok = light_sample_from(&narrow, q, v3s(0), v2(0, 0), &ls);
		double ct = cos(deg * M_PI / 180), rad = cos(30 * M_PI / 180), fall = cos(15 * M_PI / 180);
		double want = 1.0; /* pow(cos theta, tightness 0) */
		if (ct < rad) {	   /* POV-Ray's cubic_spline(low, high, pos) */
			double lo = fall, hi = rad, t = (ct - lo) / (hi - lo);
			want *= ct < lo ? 0.0 : ct >= hi ? 1.0 : (3 - 2 * t) * t * t;
		}
		CHECK(fabs((ok ? ls.li.x : 0.0) - want) < 1e-4, "falloff < radius at %g deg: %g, want %g", deg,
		      ok ? ls.li.x : 0.0, want);
	}
	/* Exactly on the radius POV-Ray does not call the spline (cos theta < cos radius fails): full. */
	{
		float c30 = cosf(30 * RENDER_PI / 180), s30 = sinf(30 * RENDER_PI / 180);
		vec3 q = v3(s30, 1 - c30, 0);
		vec3 toq = v3_normalize(v3_sub(q, v3(0, 1, 0)));
		float ct = -toq.y;
		bool ok = light_sample_from(&narrow, q, v3s(0), v2(0, 0), &ls);
		if (ct == narrow.cos_hot)
			CHECK(ok && ls.li.x == 1.0f, "on the radius: %g, want 1", ok ? ls.li.x : 0.0);
	}

	/* A cylinder whose falloff (1) is below its radius (2): POV-Ray's Attenuate_Light lights only
	 * len < falloff, with (1 - len / falloff)^tightness times cubic_spline(0, 1 - radius / falloff,
	 * 1 - len / falloff) beyond the radius, never reached here: full out to the falloff, then none. */
	light cyl = light_cylinder(v3(0, 5, 0), v3(0, 0, 0), v3s(1), 2.0f, 1.0f, 0.0f);
	for (float x = 0.05f; x < 2.5f; x += 0.1f) {
		bool ok = light_sample_from(&cyl, v3(x, 0, 0), v3s(0), v2(0, 0), &ls);
		double len = x, want = 0.0;
		if (len < 1.0) {
			double dist = 1 - len / 1.0, lo = 0.0, hi = 1 - 2.0 / 1.0;
			want = 1.0; /* pow(dist, tightness 0) */
			if (len > 2.0)
				want *= dist < lo ? 0.0 : dist >= hi ? 1.0 : 0.0;
		}
		CHECK(fabs((ok ? ls.li.x : 0.0) - want) < 1e-5, "cylinder falloff < radius at %g: %g, want %g", x,
		      ok ? ls.li.x : 0.0, want);
	}

	light par = light_parallel(v3(0, 10, -10), v3(0, 0, 0), v3(3, 3, 3));
	CHECK(light_sample_from(&par, v3(5, 5, 5), v3s(0), v2(0.3f, 0.3f), &ls) && isinf(ls.dist), "parallel sample");
	CHECK(fabsf(ls.wi.y - sqrtf(0.5f)) < 1e-6f && fabsf(ls.wi.z + sqrtf(0.5f)) < 1e-6f && ls.li.y == 3.0f,
	      "parallel wi (%g %g %g) li %g", ls.wi.x, ls.wi.y, ls.wi.z, ls.li.y);

	/* Selection by power: a point light of intensity I has power 4 pi I. */
	light_set s;
	light_set_init(&s);
	light a = light_point(v3s(0), v3s(1)), b = light_point(v3s(1), v3s(3)), bg = light_background(v3s(1));
	light_set_add(&s, &a);
	light_set_add(&s, &b);
	light_set_add(&s, &bg);
	CHECK(light_set_finish(&s, 1.0f), "set finish");
	double total = 4 * M_PI * 4 + 4 * M_PI * M_PI;
	CHECK_NEAR(light_set_prob(&s, 1), 4 * M_PI * 3 / total, 1e-6);
	CHECK_NEAR(light_set_prob(&s, 2), 4 * M_PI * M_PI / total, 1e-6);
	CHECK(s.infinite_count == 1 && s.infinite[0] == 2, "infinite lights: %zu", s.infinite_count);
	light_set_free(&s);
}

/* POV-Ray's fade, 2 / (1 + (d / fade_distance)^fade_power), at values worked by hand; no fade
 * unless both are > 0 (POV-Ray 3.7 Attenuate_Light). */
static void test_fade(void)
{
	CHECK_NEAR(light_fade(0, 5, 2), 2.0, 1e-6);	  /* at the light: twice the colour */
	CHECK_NEAR(light_fade(5, 5, 2), 1.0, 1e-6);	  /* at fade_distance: the colour */
	CHECK_NEAR(light_fade(15, 5, 2), 0.2, 1e-6);	  /* 2 / (1 + 9) */
	CHECK_NEAR(light_fade(10, 5, 1), 2.0 / 3.0, 1e-6); /* linear: 2 / (1 + 2) */
	CHECK_NEAR(light_fade(10, 5, 3), 2.0 / 9.0, 1e-6); /* 2 / (1 + 8) */
	CHECK(light_fade(10, 5, 0) == 1.0f && light_fade(10, 0, 2) == 1.0f && light_fade(10, 5, -1) == 1.0f,
	      "no fade without both fade_distance and fade_power > 0");

	/* A point light: constant without falloff, faded with fade, 1 / d^2 by default. */
	light pt = light_point(v3(0, 10, 0), v3s(3));
	light_sample ls;
	pt.falloff = LIGHT_FALLOFF_NONE;
	CHECK(light_sample_from(&pt, v3(0, -3, 0), v3s(0), v2(0, 0), &ls), "point, no falloff");
	CHECK_NEAR(ls.li.x, 3.0, 1e-6);
	pt.falloff = LIGHT_FALLOFF_FADE, pt.fade_distance = 6.5f, pt.fade_power = 2;
	CHECK(light_sample_from(&pt, v3(0, -3, 0), v3s(0), v2(0, 0), &ls), "point, fade");
	CHECK_NEAR(ls.li.x, 3.0 * 2.0 / (1.0 + 4.0), 1e-5); /* d = 13 = 2 fade_distance */
	pt.falloff = LIGHT_FALLOFF_INVERSE_SQUARE;
	CHECK(light_sample_from(&pt, v3(0, -3, 0), v3s(0), v2(0, 0), &ls), "point, 1/d^2");
	CHECK_NEAR(ls.li.x, 3.0 / 169.0, 1e-7);
}

/* POV-Ray's spot with tightness and its cylinder light, against Attenuate_Light's formulas
 * written out here. */
static void test_spot_tightness_and_cylinder(void)
{
	light sp = light_spot(v3(0, 1, 0), v3(0, 0, 0), v3s(1), 20, 40);
	sp.tightness = 10;
	sp.falloff = LIGHT_FALLOFF_NONE;
	light_sample ls;
	for (float deg = 0; deg <= 45; deg += 7.5f) {
		float r = deg * RENDER_PI / 180, c = cosf(r);
		vec3 q = v3(3 * sinf(r), 1 - 3 * cosf(r), 0); /* at distance 3: no falloff */
		bool ok = light_sample_from(&sp, q, v3s(0), v2(0, 0), &ls);
		float c20 = cosf(20 * RENDER_PI / 180), c40 = cosf(40 * RENDER_PI / 180),
		      t = (c - c40) / (c20 - c40);
		double want = pow(c, 10) * (deg <= 20 ? 1.0 : deg >= 40 ? 0.0 : t * t * (3 - 2 * t));
		CHECK(fabs((ok ? ls.li.x : 0.0) - want) < 1e-4, "spot, tightness 10, at %g deg: %g, want %g", deg,
		      ok ? ls.li.x : 0.0, want);
	}

	/* Cylinder along -y from (0, 5, 0): radius 1, falloff 2, tightness 2. */
	light cy = light_cylinder(v3(0, 5, 0), v3(0, 0, 0), v3s(2), 1, 2, 2);
	for (float r = 0; r <= 2.2f; r += 0.25f) {
		bool ok = light_sample_from(&cy, v3(r, 1, 0), v3s(0), v2(0, 0), &ls);
		double x = 1 - r / 2.0, t = x / (1 - 1 / 2.0);
		double want = r >= 2 ? 0 : 2 * x * x * (r > 1 ? t * t * (3 - 2 * t) : 1);
		CHECK(fabs((ok ? ls.li.x : 0.0) - want) < 1e-5, "cylinder at r %g: %g, want %g", r, ok ? ls.li.x : 0.0,
		      want);
		if (ok)
			CHECK(fabsf(ls.wi.y - 1) < 1e-6f && fabsf(ls.dist - 4) < 1e-5f, "cylinder wi.y %g dist %g",
			      ls.wi.y, ls.dist);
	}
	CHECK(!light_sample_from(&cy, v3(0, 6, 0), v3s(0), v2(0, 0), &ls), "cylinder: nothing behind the light");
}

/* Where an area light's sample lies in its own frame: (s, t) with y = pos + s a1 + t a2, through
 * the dual basis of a1, a2 (independent of the sampler's construction). */
static vec2 area_coords(vec3 y, vec3 pos, vec3 a1, vec3 a2)
{
	vec3 d = v3_sub(y, pos);
	float g11 = v3_dot(a1, a1), g12 = v3_dot(a1, a2), g22 = v3_dot(a2, a2), det = g11 * g22 - g12 * g12;
	float b1 = v3_dot(d, a1), b2 = v3_dot(d, a2);
	return v2((g22 * b1 - g12 * b2) / det, (g11 * b2 - g12 * b1) / det);
}

/* The points an area light shines from are uniform over its parallelogram (cells of equal area in
 * (s, t) in [-1/2, 1/2]^2) or its ellipse (cells of equal area in the unit disk: rings of equal
 * r^2, sectors of equal angle), affine maps keeping area ratios; orient turns a disk to face p. */
static void test_area_sampling(long n)
{
	enum { NB = 8, NBIN = NB * NB };
	vec3 pos = v3(0.5f, 4, 1), a1 = v3(3, 0, 0.5f), a2 = v3(1, 0.2f, 2); /* skewed, tilted */
	vec3 p = v3(0.2f, 0, -0.3f);
	for (int ellipse = 0; ellipse <= 1; ellipse++) {
		light l = light_point(pos, v3s(1));
		light_set_area(&l, a1, a2, ellipse, false);
		double obs[NBIN] = {0}, ex[NBIN];
		rng g;
		rng_seed(&g, 5, (uint64_t)ellipse);
		for (long i = 0; i < n; i++) {
			light_sample ls;
			if (!light_sample_from(&l, p, v3s(0), v2(rng_float(&g), rng_float(&g)), &ls))
				continue;
			CHECK(i > 10 || (ls.delta && ls.pdf == 1.0f), "area sample: delta-like");
			vec2 st = area_coords(v3_madd(p, ls.wi, ls.dist), pos, a1, a2);
			int i0, i1;
			if (ellipse) {
				float r2 = 4 * (st.x * st.x + st.y * st.y), phi = atan2f(st.y, st.x) + RENDER_PI;
				CHECK(r2 <= 1.0001f, "ellipse sample outside: r^2 %g", r2);
				i0 = (int)(r2 * NB), i1 = (int)(phi / (2 * RENDER_PI) * NB);
			} else {
				CHECK(fabsf(st.x) <= 0.5001f && fabsf(st.y) <= 0.5001f, "parallelogram sample outside: %g %g",
				      st.x, st.y);
				i0 = (int)((st.x + 0.5f) * NB), i1 = (int)((st.y + 0.5f) * NB);
			}
			i0 = i0 < 0 ? 0 : i0 >= NB ? NB - 1 : i0;
			i1 = i1 < 0 ? 0 : i1 >= NB ? NB - 1 : i1;
			obs[i0 * NB + i1] += 1;
		}
		for (int i = 0; i < NBIN; i++)
			ex[i] = (double)n / NBIN;
		chi2_counts(ellipse ? "area light (ellipse, rings and sectors)" : "area light (parallelogram cells)", obs,
			    ex, NBIN);
		light_free(&l);
	}

	/* orient + circular: a disk of diameter |a1| square to p -> pos, uniform on it. */
	light l = light_point(pos, v3s(1));
	light_set_area(&l, a1, a2, true, true);
	vec3 axis = v3_normalize(v3_sub(pos, p)), e1, e2;
	v3_basis(axis, &e1, &e2);
	float rad = 0.5f * v3_length(a1);
	double obs[NBIN] = {0}, ex[NBIN];
	rng g;
	rng_seed(&g, 5, 7);
	for (long i = 0; i < n; i++) {
		light_sample ls;
		if (!light_sample_from(&l, p, v3s(0), v2(rng_float(&g), rng_float(&g)), &ls))
			continue;
		vec3 d = v3_sub(v3_madd(p, ls.wi, ls.dist), pos);
		CHECK(fabsf(v3_dot(d, axis)) < 1e-4f * rad, "oriented sample off its plane: %g", v3_dot(d, axis));
		float x = v3_dot(d, e1) / rad, y = v3_dot(d, e2) / rad;
		float r2 = x * x + y * y, phi = atan2f(y, x) + RENDER_PI;
		CHECK(r2 <= 1.0001f, "oriented disk sample outside: r^2 %g", r2);
		int i0 = (int)(r2 * NB), i1 = (int)(phi / (2 * RENDER_PI) * NB);
		i0 = i0 >= NB ? NB - 1 : i0;
		i1 = i1 < 0 ? 0 : i1 >= NB ? NB - 1 : i1;
		obs[i0 * NB + i1] += 1;
	}
	for (int i = 0; i < NBIN; i++)
		ex[i] = (double)n / NBIN;
	chi2_counts("area light (oriented disk)", obs, ex, NBIN);
	light_free(&l);
}

/* Irradiance at a point below a rectangle [x1, x2] x [y1, y2] at height h, parallel to the
 * receiver, the light's colour C spread over its area A, by inclusion-exclusion over corner
 * rectangles. With 1/d^2: E = C / A * solid angle, the corner's solid angle
 * atan(x y / (h sqrt(x^2 + y^2 + h^2))). Without falloff: E = C / A * h * integral of 1 / r,
 * antiderivative x ln(y + r) + y ln(x + r) - h atan(x y / (h r)) (r = sqrt(x^2 + y^2 + h^2)). */
static double corner(double x, double y, double h, bool inverse_square)
{
	double r = sqrt(x * x + y * y + h * h);
	if (inverse_square)
		return atan(x * y / (h * r));
	return h * (x * log(y + r) + y * log(x + r) - h * atan(x * y / (h * r)));
}

static double rect_irradiance(double x1, double x2, double y1, double y2, double h, bool inverse_square)
{
	double s = corner(x2, y2, h, inverse_square) - corner(x1, y2, h, inverse_square) -
		   corner(x2, y1, h, inverse_square) + corner(x1, y1, h, inverse_square);
	return s / ((x2 - x1) * (y2 - y1));
}

/* Monte Carlo irradiance of light l on a receiver at p with normal n (no occluders). */
static void mc_irradiance(const light *l, vec3 p, vec3 n, long m, uint64_t seed, double *mean, double *se)
{
	rng g;
	rng_seed(&g, 6, seed);
	double sum = 0, sum2 = 0;
	for (long i = 0; i < m; i++) {
		light_sample ls;
		if (!light_sample_from(l, p, n, v2(rng_float(&g), rng_float(&g)), &ls))
			continue;
		double e = ls.li.x * fmax(0.0, v3_dot(n, ls.wi)) / ls.pdf;
		sum += e, sum2 += e * e;
	}
	*mean = sum / m;
	*se = sqrt(fmax(0.0, sum2 / m - *mean * *mean) / m);
}

static void test_area_irradiance(long n)
{
	/* A 2 x 3 rectangle at height 1.5 over a point off its centre, facing down; the receiver up. */
	vec3 pos = v3(0, 1.5f, 0), p = v3(0.4f, 0, -0.7f), up = v3(0, 1, 0);
	for (int inv = 0; inv <= 1; inv++) {
		light l = light_point(pos, v3s(2));
		l.falloff = inv ? LIGHT_FALLOFF_INVERSE_SQUARE : LIGHT_FALLOFF_NONE;
		light_set_area(&l, v3(2, 0, 0), v3(0, 0, 3), false, false);
		double want = 2 * rect_irradiance(-1 - 0.4, 1 - 0.4, -1.5 + 0.7, 1.5 + 0.7, 1.5, inv), got, se;
		mc_irradiance(&l, p, up, n, (uint64_t)inv, &got, &se);
		CHECK(fabs(got - want) < 5 * se + 1e-4 * want, "rectangle, %s: irradiance %g +- %g, analytic %g",
		      inv ? "1/d^2" : "no falloff", got, se, want);
		light_free(&l);
	}
	/* A disk of radius R = 1 at height h = 2 on axis: with 1/d^2, 2 C / R^2 (1 - h / sqrt(h^2 + R^2));
	 * without falloff, 2 C h / R^2 (sqrt(h^2 + R^2) - h). */
	for (int inv = 0; inv <= 1; inv++) {
		light l = light_point(v3(0, 2, 0), v3s(1));
		l.falloff = inv ? LIGHT_FALLOFF_INVERSE_SQUARE : LIGHT_FALLOFF_NONE;
		light_set_area(&l, v3(2, 0, 0), v3(0, 0, 2), true, false);
		double want = inv ? 2 * (1 - 2 / sqrt(5.0)) : 2 * 2 * (sqrt(5.0) - 2), got, se;
		mc_irradiance(&l, v3s(0), up, n, 2 + (uint64_t)inv, &got, &se);
		CHECK(fabs(got - want) < 5 * se + 1e-4 * want, "disk, %s: irradiance %g +- %g, analytic %g",
		      inv ? "1/d^2" : "no falloff", got, se, want);
		light_free(&l);
	}
}

/* At each of the np points (p, normal or zero): the probabilities light_set_prob_at gives sum to
 * 1, each pick's own probability is the same bits, the picks' frequencies and the rest of u (8
 * bins, uniform given the light) pass one chi-square, a stratified u gives each light its share
 * (within 1.5, plus the float rounding of a long descent), and a light of probability 0 sends
 * no sample above the horizon. */
static void check_set_choice(const char *name, const light_set *s, const vec3 *pts, const vec3 *nrm, int np, long n,
			     bool tree, bool cosine)
{
	enum { RB = 8 };
	size_t L = s->count;
	int nb = np * (int)L * RB + np; /* and per point a bin for picks of none (the tree's) */
	double *obs = mem_calloc((size_t)nb, sizeof *obs), *ex = mem_calloc((size_t)nb, sizeof *ex);
	rng g;
	rng_seed(&g, 83 + L, 5);
	long per = n / np;
	for (int k = 0; k < np; k++) {
		double sum = 0.0;
		float *pr = mem_alloc(L, sizeof *pr);
		long *strat = mem_calloc(L, sizeof *strat);
		for (size_t i = 0; i < L; i++) {
			pr[i] = light_set_prob_at(s, i, pts[k], nrm[k], cosine);
			sum += pr[i];
			for (int b = 0; b < RB; b++)
				ex[(k * L + i) * RB + b] = per * (double)pr[i] / RB;
		}
		/* A descent through the tree can end at a node whose children are both 0 (its sphere
		 * reaches above the horizon, theirs do not): no light, as pbrt-v4's; so the sum can be
		 * below 1 there, and such picks say probability 0. */
		CHECK(tree ? sum < 1.0 + 1e-5 && sum > 0.5 : fabs(sum - 1.0) < 1e-5, "point %d: probabilities sum to %g", k,
		      sum);
		ex[np * L * RB + k] = per * fmax(0.0, 1.0 - sum);
		/* Zero importance: every sample of that light from here is below the horizon. */
		for (size_t i = 0; i < L && v3_length2(nrm[k]) > 0.0f; i++) {
			if (pr[i] > 0.0f)
				continue;
			for (int j = 0; j < 256; j++) {
				light_sample ls;
				if (light_sample_from(&s->lights[i], pts[k], nrm[k], v2(rng_float(&g), rng_float(&g)), &ls))
					CHECK(v3_dot(ls.wi, nrm[k]) <= 1e-6f, "point %d light %zu: importance 0 but wi.n %g", k,
					      i, v3_dot(ls.wi, nrm[k]));
			}
		}
		for (long j = 0; j < per; j++) {
			float prob, rest;
			size_t si = light_set_pick_at(s, pts[k], nrm[k], cosine, (float)((j + 0.5) / per), &prob, &rest);
			strat[si] += prob > 0.0f;
			size_t i = light_set_pick_at(s, pts[k], nrm[k], cosine, rng_float(&g), &prob, &rest);
			if (tree && prob == 0.0f) {
				obs[np * L * RB + k] += 1.0;
				continue;
			}
			CHECK(i < L && prob == pr[i] && prob > 0.0f, "point %d: pick %zu with %g, prob_at %g", k, i, prob,
			      i < L ? pr[i] : -1.0f);
			CHECK(rest >= 0.0f && rest < 1.0f, "rest of u %g", rest);
			int b = (int)(rest * RB);
			obs[(k * L + i) * RB + (b < RB ? b : RB - 1)] += 1.0;
		}
		for (size_t i = 0; i < L; i++)
			CHECK(fabs(strat[i] - per * (double)pr[i]) <= 1.5 + 1e-4 * per, "point %d light %zu: stratified %ld, want %g", k, i,
			      strat[i], per * (double)pr[i]);
		mem_free(pr), mem_free(strat);
	}
	chi2_counts(name, obs, ex, nb);
	mem_free(obs), mem_free(ex);
}

/* The choice among few lights by their importance at the shading point (light_set_pick_at): at
 * several points (with a normal and without) the picks' frequencies are the probabilities the
 * estimator uses (light_set_prob_at, bit for bit the pick's own), and the rest of u handed to
 * the light is uniform given the light (one chi-square over point x light x 8 bins of it); a
 * stratified u gives each light its share within one; a light of importance 0 sends no sample
 * above the horizon; the importances follow the distance law and the environment's
 * irradiance; a larger set chooses through its light tree, checked the same way. */
static void test_local_selection(long n)
{
	enum { W = 16, H = 8, NP = 4 };
	float img[W * H * 3];
	for (int i = 0; i < W * H; i++) {
		float v = (i / W) < H / 2 ? 2.0f : 0.1f; /* a bright upper hemisphere */
		img[3 * i] = img[3 * i + 1] = img[3 * i + 2] = v;
	}
	light_set s;
	light_set_init(&s);
	light l[8];
	l[0] = light_point(v3(0, 3, 0), v3s(2));
	l[1] = light_sphere(v3(2, 1, -1), 0.5f, v3s(5));
	l[2] = light_spot(v3(-2, 2, 0), v3(0, 0, 0), v3s(3), 20, 30);
	l[3] = light_parallel(v3(1, 1, 1), v3(0, 0, 0), v3s(0.7f));
	vec3 tri[3] = {v3(-1, -1, 3), v3(1, -1, 3), v3(0, 1, 3)};
	CHECK(light_mesh_init(&l[4], tri, 1, v3s(4)), "mesh init");
	l[5] = light_background(v3s(0.3f));
	CHECK(light_envmap_init(&l[6], img, W, H, 1.0f, NULL), "envmap init");
	l[7] = light_point(v3(0, -2, 1), v3s(1));
	light_set_area(&l[7], v3(1, 0, 0), v3(0, 0, 1), false, false);
	for (int i = 0; i < 8; i++)
		light_set_add(&s, &l[i]);
	CHECK(light_set_finish(&s, 5.0f), "set finish");
	const vec3 pts[NP] = {v3(0, 0, 0), v3(0.5f, 0.2f, -0.3f), v3(0, 0, 0), v3(-0.4f, 0.1f, 0.6f)};
	const vec3 nrm[NP] = {v3(0, 1, 0), v3_normalize(v3(1, -1, 0.2f)), v3(0, 0, 0), v3(0, 0, -1)};
	check_set_choice("light choice at a point, rest of u", &s, pts, nrm, NP, n / 2, false, true);
	check_set_choice("light choice without the cosine", &s, pts, nrm, NP, n / 2, false, false);

	/* At p = 0 with n = +y: the point light 3 above gives 2 / 9; the spot (a point light for
	 * the choice) at distance sqrt 8, cos 2 / sqrt 8; the parallel light 0.7 cos; the sphere
	 * pi R^2 Le / d^2 = 5 / 6 times the cosine at the edge of its disk nearest the normal,
	 * cos(theta - theta_s); the area light below, none, but around a receiver inside its
	 * bounding sphere, some; the background LIGHT_IMP_BACKGROUND pi L, 4 pi L without a normal. */
	const light *L = s.lights;
	vec3 o = v3s(0), up = v3(0, 1, 0);
	CHECK_NEAR(light_importance(&L[0], o, up, true), 2.0 / 9.0, 1e-6);
	CHECK_NEAR(light_importance(&L[2], o, up, true), 3.0 / 8.0 * (2.0 / sqrt(8.0)), 1e-5);
	CHECK_NEAR(light_importance(&L[3], o, up, true), 0.7 / sqrt(3.0), 1e-5);
	CHECK_NEAR(light_importance(&L[0], o, v3s(0), true), 2.0 / 9.0, 1e-6);
	CHECK(light_importance(&L[0], o, v3(0, -1, 0), true) == 0.0f, "a point light below the horizon");
	CHECK(light_importance(&L[7], o, up, true) == 0.0f, "an area light below the horizon");
	/* Without the cosine (a glossy lobe's choice): the distance law alone above the horizon. */
	CHECK_NEAR(light_importance(&L[2], o, up, false), 3.0 / 8.0, 1e-5);
	CHECK_NEAR(light_importance(&L[3], o, up, false), 0.7, 1e-5);
	CHECK(light_importance(&L[0], o, v3(0, -1, 0), false) == 0.0f, "below the horizon without the cosine");
	CHECK(light_importance(&L[7], v3(0, -1.9f, 1.0f), up, true) > 0.0f, "an area light around the receiver");
	double d2 = 6.0, sin_s = 0.5 / sqrt(d2), c = 1.0 / sqrt(d2), theta = acos(c) - asin(sin_s);
	CHECK_NEAR(light_importance(&L[1], o, up, true), 5.0 / d2 * cos(theta), 1e-5);
	CHECK_NEAR(light_importance(&L[5], o, up, true), LIGHT_IMP_BACKGROUND * M_PI * 0.3, 1e-5);
	CHECK_NEAR(light_importance(&L[5], o, v3s(0), true), 4.0 * M_PI * 0.3, 1e-5);
	/* E(+y) of a hemisphere of 2 above and 0.1 below: 2 pi (tabulated at a grid normal near +y,
	 * from 64 x 32 blocks: within 5 %); E(-y) = 0.1 pi. */
	double up_e = light_importance(&L[6], o, up, true), down_e = light_importance(&L[6], o, v3(0, -1, 0), true);
	CHECK(fabs(up_e / (2.0 * M_PI) - 1.0) < 0.05, "environment E(+y) %g, want about %g", up_e, 2.0 * M_PI);
	CHECK(fabs(down_e / (0.1 * M_PI) - 1.0) < 0.05, "environment E(-y) %g, want about %g", down_e, 0.1 * M_PI);
	light_set_free(&s);

	/* More than LIGHT_SET_LOCAL_MAX lights: the tree (40 lights: points of the inverse square,
	 * spheres, a mesh in it; parallel lights, a POV-Ray point light without falloff and the
	 * background beside it), checked as the small set. */
	light_set big;
	light_set_init(&big);
	rng g;
	rng_seed(&g, 97, 1);
	for (int i = 0; i < 40; i++) {
		vec3 pos = v3(8.0f * rng_float(&g) - 4.0f, 8.0f * rng_float(&g) - 4.0f, 8.0f * rng_float(&g) - 4.0f);
		light x;
		if (i < 30)
			x = light_point(pos, v3s(0.5f + 3.0f * rng_float(&g)));
		else if (i < 34)
			x = light_sphere(pos, 0.3f + 0.5f * rng_float(&g), v3s(4));
		else if (i == 34) {
			vec3 t[3] = {pos, v3_add(pos, v3(1, 0, 0)), v3_add(pos, v3(0, 1, 0.5f))};
			CHECK(light_mesh_init(&x, t, 1, v3s(2)), "mesh init");
		} else if (i < 37)
			x = light_parallel(pos, v3s(0), v3s(0.3f));
		else if (i == 37) {
			x = light_point(pos, v3s(0.2f));
			x.falloff = LIGHT_FALLOFF_NONE;
		} else if (i == 38)
			x = light_background(v3s(0.1f));
		else
			x = light_point(v3(0, -3, 0), v3s(1));
		light_set_add(&big, &x);
	}
	CHECK(light_set_finish(&big, 8.0f), "set finish");
	CHECK(big.nodes && big.node_count == 2 * 36 - 1 && big.loose_count == 4, "the tree: %zu nodes, %zu loose",
	      big.node_count, big.loose_count);
	const vec3 bp[NP] = {v3(0, 0, 0), v3(1.5f, -0.5f, 2.0f), v3(-3, 3, 0), v3(0, -2.0f, 0)};
	const vec3 bn[NP] = {v3(0, 1, 0), v3_normalize(v3(-1, 0.3f, -1)), v3(0, 0, 0), v3(0, 1, 0)};
	check_set_choice("light tree choice, rest of u", &big, bp, bn, NP, n / 2, true, true);
	check_set_choice("light tree choice without the cosine", &big, bp, bn, NP, n / 2, true, false);
	/* The light just below (0, -2, 0) facing up: never picked from there. */
	CHECK(light_set_prob_at(&big, 39, v3(0, -2.0f, 0), v3(0, 1, 0), true) == 0.0f, "a light below the horizon");
	light_set_free(&big);
}

int main(void)
{
	long n = test_samples(1000000);
	test_sphere_light(n);
	test_background(n);
	test_envmap(n);
	test_mesh(n);
	test_delta_and_set();
	test_fade();
	test_spot_tightness_and_cylinder();
	test_area_sampling(n);
	test_area_irradiance(n);
	test_local_selection(n);
	return check_done("test_light");
}
