/* test_adaptive: adaptive sampling (adaptive.h) — the check schedule and Cycles' automatic
 * minimum; bit-identical films for 1 and 2 threads, any tile size, regions with their apron, a
 * time budget and a continued render; a constant scene stops every pixel at the minimum and a
 * noisy pixel goes on to the maximum; the estimated error against the error measured over many
 * seeds, for both samplers; no NaN in the error a NaN-producing material leaves. */
#include "base/mem.h"
#include "check.h"
#include "render/adaptive.h"
#include "render/scheduler.h"
#include "scenes.h"

#include <string.h>

#define W 37
#define H 23

static ts_scene scene, flat;
static cam camera;

/* The noisy scene: a floor and two spheres under a small sphere light; the flat one: nothing but
 * a constant background, whose every sample is the same. */
static void build_scenes(void)
{
	ts_floor_and_spheres(&scene);
	ts_init(&flat);
	light bg = light_background(v3(0.2f, 0.25f, 0.3f));
	light_set_add(&flat.lights, &bg);
	light_set_finish(&flat.lights, 5.0f);
	cam_params cp = cam_params_default();
	cp.location = d3(0, 1, -2.5);
	cp.look_at = d3(0, 0.4, 0.8);
	cam_init(&camera, &cp, W, H);
}

static render_job job_for(const ts_scene *s, uint32_t spp, int threads, int tile, double threshold,
			  uint32_t min)
{
	return (render_job){.scene = &s->rs,
			    .camera = &camera,
			    .settings = {5, RENDER_MIS},
			    .seed = 1234,
			    .spp = spp,
			    .threads = threads,
			    .tile_size = tile,
			    .adaptive = {.threshold = threshold, .min_spp = min}};
}

/* Renders into f (a whole image or a region, with the apron); returns the status. */
static render_status render(render_job j, film *f, int x0, int y0, int x1, int y1)
{
	CHECK(film_init_apron(f, W, H, x0, y0, x1, y1, ADAPTIVE_APRON), "film_init %d %d %d %d", x0, y0, x1,
	      y1);
	return render_run(&j, f, NULL);
}

/* Bit-exact comparison of f's region pixels with the same pixels of whole. */
static int differing_pixels(const film *whole, const film *f)
{
	int diff = 0;
	for (int y = f->y0; y < f->y1; y++)
		for (int x = f->x0; x < f->x1; x++)
			diff += memcmp(film_at(whole->acc, whole, x, y), film_at(f->acc, f, x, y),
				       sizeof(film_pixel)) != 0;
	return diff;
}

static void check_schedule(void)
{
	/* Cycles' comment: threshold 0.1 -> 32, 0.01 -> 64, 0.001 -> 128; never below 4. */
	CHECK(adaptive_auto_min_spp(0.1) == 32, "%u", adaptive_auto_min_spp(0.1));
	CHECK(adaptive_auto_min_spp(0.01) == 64, "%u", adaptive_auto_min_spp(0.01));
	CHECK(adaptive_auto_min_spp(0.001) == 128, "%u", adaptive_auto_min_spp(0.001));
	CHECK(adaptive_auto_min_spp(1000.0) == 4, "%u", adaptive_auto_min_spp(1000.0));
	adaptive_params a = {.threshold = 0.05, .min_spp = 10};
	CHECK(!adaptive_is_check(&a, 9) && adaptive_is_check(&a, 10) && !adaptive_is_check(&a, 11) &&
		  adaptive_is_check(&a, 10 + ADAPTIVE_STEP) && adaptive_is_check(&a, 10 + 5 * ADAPTIVE_STEP),
	      "checks at 10 + k 16");
	CHECK(adaptive_next_check(&a, 0) == 10 && adaptive_next_check(&a, 9) == 10 &&
		  adaptive_next_check(&a, 10) == 26 && adaptive_next_check(&a, 25) == 26,
	      "next checks %u %u", adaptive_next_check(&a, 10), adaptive_next_check(&a, 25));
	a.min_spp = 0;
	CHECK(adaptive_first_check(&a) == adaptive_auto_min_spp(0.05), "automatic first check");
}

/* Threads, tiles, regions, a continued render and a time budget change no bit. */
static void check_determinism(void)
{
	film whole, f;
	render_job jw = job_for(&scene, 72, 1, 16, 0.03, 8);
	CHECK(render(jw, &whole, 0, 0, 0, 0) == RENDER_DONE, "whole render");
	uint32_t lo = UINT32_MAX, hi = 0;
	for (int i = 0; i < W * H; i++)
		lo = whole.acc[i].n < lo ? whole.acc[i].n : lo,
		hi = whole.acc[i].n > hi ? whole.acc[i].n : hi;
	CHECK(lo < hi && hi == 72,
	      "samples from %u to %u: the test needs pixels that stopped and others that did not", lo, hi);
	printf("  threshold 0.03: samples per pixel %u to %u\n", lo, hi);
	CHECK(render(job_for(&scene, 72, 2, 5, 0.03, 8), &f, 0, 0, 0, 0) == RENDER_DONE, "2 threads");
	CHECK(differing_pixels(&whole, &f) == 0, "1 vs 2 threads, tile 5: %d pixels differ",
	      differing_pixels(&whole, &f));
	film_free(&f);
	const int xs[3] = {0, 17, W}, ys[3] = {0, 11, H};
	for (int qy = 0; qy < 2; qy++)
		for (int qx = 0; qx < 2; qx++) {
			render_job jr = job_for(&scene, 72, 2, 7, 0.03, 8);
			CHECK(render(jr, &f, xs[qx], ys[qy], xs[qx + 1], ys[qy + 1]) == RENDER_DONE,
			      "region");
			int d = differing_pixels(&whole, &f);
			CHECK(d == 0, "region %d,%d-%d,%d: %d pixels differ", xs[qx], ys[qy], xs[qx + 1],
			      ys[qy + 1], d);
			film_free(&f);
		}
	/* A region's film without the apron is refused rather than rendered differently. */
	CHECK(film_init(&f, W, H, 3, 3, 20, 20), "film");
	CHECK(render_run(&jw, &f, NULL) == RENDER_ERROR, "a region without its apron was rendered");
	film_free(&f);
	/* Continued: 30 samples (between checks), then on to 72. */
	CHECK(render(job_for(&scene, 30, 2, 16, 0.03, 8), &f, 0, 0, 0, 0) == RENDER_DONE && f.spp == 30,
	      "first part");
	render_job more = job_for(&scene, 72, 2, 16, 0.03, 8);
	CHECK(render_run(&more, &f, NULL) == RENDER_DONE && f.spp == 72, "continued to %u", f.spp);
	CHECK(differing_pixels(&whole, &f) == 0, "continued render: %d pixels differ",
	      differing_pixels(&whole, &f));
	film_free(&f);
	/* A time budget ends on some count; a render of that count is the same. */
	render_job jt = job_for(&scene, 0, 2, 8, 0.03, 8);
	jt.time_budget_s = 0.3;
	CHECK(render(jt, &f, 0, 0, 0, 0) == RENDER_DONE && f.spp > 0, "time budget");
	film ref;
	CHECK(render(job_for(&scene, f.spp, 1, 16, 0.03, 8), &ref, 0, 0, 0, 0) == RENDER_DONE, "reference");
	CHECK(differing_pixels(&ref, &f) == 0, "time budget (%u spp) vs spp render: %d differ", f.spp,
	      differing_pixels(&ref, &f));
	printf("  time budget 0.3 s: %u spp\n", f.spp);
	film_free(&ref);
	film_free(&f);
	film_free(&whole);
}

/* A constant scene stops at the minimum (and the render ends there); a noisy pixel goes on. */
static void check_stops(void)
{
	film f;
	render_stats st;
	render_job j = job_for(&flat, 512, 2, 16, 0.01, 12);
	CHECK(film_init(&f, W, H, 0, 0, 0, 0), "film");
	CHECK(render_run(&j, &f, &st) == RENDER_DONE && f.spp == 512, "flat render: spp %u", f.spp);
	int off = 0;
	for (int i = 0; i < W * H; i++)
		off += f.acc[i].n != 12 || !f.acc[i].stopped;
	CHECK(off == 0, "%d pixels of a constant image did not stop at the minimum 12", off);
	CHECK(st.samples == 12u * W * H, "flat render took %llu samples, expected %u",
	      (unsigned long long)st.samples, 12u * W * H);
	film_free(&f);
	/* The noisy scene at a threshold its lit pixels cannot meet in 96 samples. */
	j = job_for(&scene, 96, 2, 16, 1e-3, 16);
	CHECK(film_init(&f, W, H, 0, 0, 0, 0), "film");
	CHECK(render_run(&j, &f, &st) == RENDER_DONE, "noisy render");
	const film_pixel *p = film_at(f.acc, &f, 26, 17); /* on the diffuse sphere */
	double e = film_pixel_error(p);
	CHECK(p->n == 96 && e > 1e-3, "a noisy pixel (error %g) stopped at %u of 96 samples", e, p->n);
	int early = 0;
	for (int i = 0; i < W * H; i++)
		early += f.acc[i].n < 96 && film_pixel_error(&f.acc[i]) > 1e-3;
	CHECK(early == 0, "%d pixels above the threshold stopped early", early);
	film_free(&f);
}

/* The film's error estimates against the errors measured over SEEDS renders (16 samples each,
 * no adaptive sampling): the variance of each pixel's mean, the summary's NMSE and the relative
 * error adaptive sampling tests (film_pixel_error). Random samples: each within a factor of 1.3.
 * Sobol: the prefix estimator (film_pixel_variance) is exact for independent samples and
 * conservative for a sequence of nets whose error falls as n^-a: it expects 2^2a - 1 times the
 * variance, 1 to 3 for a from 1/2 to 1; here from 1 to 3 (about 2.3 on this scene), and the
 * relative error (a square root) from 1/1.3 to 1.8. */
#define SEEDS 48
static void check_estimate(render_sampler_kind kind)
{
	size_t n = (size_t)W * H * 3;
	double *m = mem_calloc(n, sizeof *m), *m2 = mem_calloc(n, sizeof *m2), *v = mem_calloc(n, sizeof *v);
	double *e = mem_calloc((size_t)W * H, sizeof *e), nmse_est = 0.0;
	float *buf = mem_alloc(n, sizeof *buf), *err = mem_alloc((size_t)W * H, sizeof *err);
	for (int s = 0; s < SEEDS; s++) {
		film f;
		render_job j = job_for(&scene, 16, 2, 16, 0.0, 0);
		j.seed = 100 + (uint64_t)s;
		j.sampler = kind;
		CHECK(film_init(&f, W, H, 0, 0, 0, 0) && render_run(&j, &f, NULL) == RENDER_DONE, "seed %d",
		      s);
		film_read(&f, FILM_BEAUTY, buf);
		for (size_t i = 0; i < n; i++)
			m[i] += buf[i], m2[i] += (double)buf[i] * buf[i];
		film_read(&f, FILM_VARIANCE, buf);
		for (size_t i = 0; i < n; i++)
			v[i] += buf[i] / SEEDS;
		film_read(&f, FILM_ERROR, err);
		for (int i = 0; i < W * H; i++)
			e[i] += err[i] / SEEDS;
		adaptive_summary a;
		adaptive_summarise(&f, &a);
		nmse_est += a.nmse / SEEDS;
		film_free(&f);
	}
	double var_meas = 0.0, var_est = 0.0, mean = 0.0, e_meas = 0.0, e_est = 0.0;
	for (size_t i = 0; i < n; i++) {
		double mu = m[i] / SEEDS, var = (m2[i] - SEEDS * mu * mu) / (SEEDS - 1);
		m[i] = mu, m2[i] = var > 0.0 ? var : 0.0;
		var_meas += m2[i], var_est += v[i], mean += mu;
	}
	for (int i = 0; i < W * H; i++) {
		double lum = (m[3 * i] + m[3 * i + 1] + m[3 * i + 2]) / 3.0;
		double sd = sqrt((m2[3 * i] + m2[3 * i + 1] + m2[3 * i + 2]) / 3.0);
		if (lum > 0.0)
			e_meas += sd / (lum >= 1.0 ? lum : sqrt(lum)), e_est += e[i];
	}
	mean /= (double)n;
	double nmse_meas = var_meas / (double)n / (mean * mean);
	printf("  %s, over %d seeds: variance of the mean estimated %.4g measured %.4g; NMSE %.4g vs %.4g; mean "
	       "relative error %.4g vs %.4g\n",
	       render_sampler_name(kind), SEEDS, var_est, var_meas, nmse_est, nmse_meas, e_est / (W * H),
	       e_meas / (W * H));
	bool sobol = kind == RENDER_SAMPLER_SOBOL;
	double lo = sobol ? 1.0 : 1 / 1.3, hi = sobol ? 3.0 : 1.3, elo = 1 / 1.3, ehi = sobol ? 1.8 : 1.3;
	CHECK(var_est > var_meas * lo && var_est < var_meas * hi, "%s: variance %g vs %g", render_sampler_name(kind),
	      var_est, var_meas);
	CHECK(nmse_est > nmse_meas * lo && nmse_est < nmse_meas * hi, "%s: NMSE %g vs %g", render_sampler_name(kind),
	      nmse_est, nmse_meas);
	CHECK(e_est > e_meas * elo && e_est < e_meas * ehi, "%s: relative error %g vs %g", render_sampler_name(kind),
	      e_est, e_meas);
	mem_free(m), mem_free(m2), mem_free(v), mem_free(e), mem_free(buf), mem_free(err);
}

/* A NaN-producing material with adaptive sampling: samples dropped, every value read finite. */
static void check_nan(void)
{
	scene.mat[2].diffuse = v3(NAN, 0.5f, 0.5f);
	film f;
	CHECK(render(job_for(&scene, 40, 2, 16, 0.05, 8), &f, 0, 0, 0, 0) == RENDER_DONE && f.dropped > 0,
	      "NaN render: %llu dropped", (unsigned long long)f.dropped);
	float *buf = mem_alloc(W * H, 3 * sizeof(float));
	const film_channel chans[3] = {FILM_BEAUTY, FILM_ERROR, FILM_SAMPLES};
	int bad = 0;
	for (int c = 0; c < 3; c++) {
		film_read(&f, chans[c], buf);
		for (int i = 0; i < film_channel_components(chans[c]) * W * H; i++)
			bad += !isfinite(buf[i]) || buf[i] < 0.0f;
	}
	CHECK(bad == 0, "%d non-finite or negative values read", bad);
	adaptive_summary a;
	adaptive_summarise(&f, &a);
	CHECK(isfinite(a.nmse) && isfinite(a.mean_error), "summary %g %g", a.nmse, a.mean_error);
	mem_free(buf);
	film_free(&f);
	scene.mat[2] = bsdf_diffuse(v3(0.2f, 0.5f, 0.8f));
}

int main(void)
{
	build_scenes();
	check_schedule();
	check_determinism();
	check_stops();
	check_estimate(RENDER_SAMPLER_RANDOM);
	check_estimate(RENDER_SAMPLER_SOBOL);
	check_nan();
	light_set_free(&scene.lights);
	light_set_free(&flat.lights);
	return check_done("test_adaptive");
}
