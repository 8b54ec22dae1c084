/* test_scheduler: the film and the threaded pass scheduler — bit-identical images for 1 and 2
 * threads and any tile size, four regions equal to the whole; a time budget, and a SIGINT whose
 * handler only sets the interrupt flag, stop with every pixel at the same completed count (the
 * image equal to a render of that count); checkpoints on schedule; dropped non-finite samples
 * counted and kept off the film. */
#include "base/mem.h"
#include "check.h"
#include "render/scheduler.h"
#include "scenes.h"

#include <pthread.h>
#include <signal.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define W 37
#define H 23

static ts_scene scene;
static cam camera;

static void build_scene(void)
{
	ts_floor_and_spheres(&scene);
	cam_params cp = cam_params_default();
	cp.location = d3(0, 1, -2.5);
	cp.look_at = d3(0, 0.4, 0.8);
	cam_init(&camera, &cp, W, H);
}

static render_job job_for(uint32_t spp, int threads, int tile)
{
	return (render_job){.scene = &scene.rs,
			    .camera = &camera,
			    .settings = {5, RENDER_MIS},
			    .seed = 1234,
			    .spp = spp,
			    .threads = threads,
			    .tile_size = tile};
}

/* Renders into f (a whole image or a region); returns the status. */
static render_status render(render_job j, film *f, int x0, int y0, int x1, int y1)
{
	CHECK(film_init(f, W, H, x0, y0, x1, y1), "film_init %d %d %d %d", x0, y0, x1, y1);
	return render_run(&j, f, NULL);
}

/* Bit-exact comparison of f's pixels with the same pixels of whole. */
static int differing_pixels(const film *whole, const film *f)
{
	int diff = 0;
	for (int y = f->y0; y < f->y1; y++)
		for (int x = f->x0; x < f->x1; x++) {
			const film_pixel *a =
			    &whole->acc[(y - whole->y0) * film_region_width(whole) + (x - whole->x0)];
			const film_pixel *b = &f->acc[(y - f->y0) * film_region_width(f) + (x - f->x0)];
			diff += memcmp(a, b, sizeof *a) != 0;
		}
	return diff;
}

static double now(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

/* The interrupt flag as main.c keeps it: set only by the signal handler. */
static _Atomic int stop_flag;
static void on_signal(int sig)
{
	(void)sig;
	atomic_store(&stop_flag, 1);
}

typedef struct stopper {
	double delay_s, set_at;
} stopper;

/* Sends SIGINT to the process after a delay, as Ctrl-C would. */
static void *stop_later(void *arg)
{
	stopper *s = arg;
	struct timespec ts = {0, (long)(s->delay_s * 1e9)};
	nanosleep(&ts, NULL);
	s->set_at = now();
	kill(getpid(), SIGINT);
	return NULL;
}

typedef struct ckpt {
	int calls;
	uint32_t last_spp;
	bool monotone;
} ckpt;

static void on_checkpoint(void *user, const film *f)
{
	ckpt *c = user;
	c->calls++;
	c->monotone = c->monotone && f->spp > c->last_spp;
	c->last_spp = f->spp;
}

/* What the progress callback saw: its calls, the last report, whether fraction and elapsed never
 * went back and stayed in range, and how many calls said done (only the last may). */
typedef struct progress_log {
	int calls, done_calls;
	bool ordered, done_last;
	render_progress last;
} progress_log;

static void on_progress(void *user, const render_progress *p)
{
	progress_log *l = user;
	bool in_range = p->fraction >= 0.0 && p->fraction <= 1.0 && p->rate >= 0.0 && p->elapsed >= 0.0;
	bool forward = l->calls == 0 || (p->fraction >= l->last.fraction && p->elapsed >= l->last.elapsed);
	l->ordered = (l->calls == 0 || l->ordered) && in_range && forward;
	l->done_last = l->done_calls == 0;
	l->done_calls += p->done;
	l->last = *p;
	l->calls++;
}

/* Progress reaches the caller through the callback: reports in order, the last one (done) at
 * the whole count for an spp render. */
static void check_progress(uint32_t spp, double budget_s)
{
	render_job j = job_for(spp, 2, 8);
	j.time_budget_s = budget_s;
	progress_log log = {0};
	j.progress = on_progress;
	j.progress_user = &log;
	film f;
	CHECK(film_init(&f, W, H, 0, 0, 0, 0), "film");
	CHECK(render_run(&j, &f, NULL) == RENDER_DONE, "render with progress");
	CHECK(log.calls >= 1 && log.ordered, "progress: %d calls, ordered %d", log.calls, log.ordered);
	CHECK(log.done_calls == 1 && log.done_last && log.last.done, "progress: %d calls said done, the last %d",
	      log.done_calls, log.last.done);
	CHECK(!spp || log.last.fraction == 1.0, "progress ended at %g of %u spp", log.last.fraction, spp);
	CHECK(log.last.rate > 0.0, "progress rate %g", log.last.rate);
	printf("  progress (spp %u, budget %g s): %d reports, the last at %.3g after %.3f s\n", spp, budget_s,
	       log.calls, log.last.fraction, log.last.elapsed);
	film_free(&f);
}

static void commit_nothing(void *f) { film_commit(f, ((film *)f)->spp); }

int main(void)
{
	build_scene();
	check_progress(6, 0.0);
	check_progress(0, 0.6);
	film whole, f;

	/* Threads and tiles do not change a bit. */
	CHECK(render(job_for(6, 1, 16), &whole, 0, 0, 0, 0) == RENDER_DONE, "whole render");
	CHECK(whole.spp == 6 && whole.dropped == 0, "spp %u dropped %llu", whole.spp,
	      (unsigned long long)whole.dropped);
	CHECK(render(job_for(6, 2, 7), &f, 0, 0, 0, 0) == RENDER_DONE, "2-thread render");
	int d = differing_pixels(&whole, &f);
	CHECK(d == 0, "1 vs 2 threads: %d pixels differ", d);
	film_free(&f);

	/* A render continued from 2 samples to 6 equals one render of 6. */
	CHECK(render(job_for(2, 2, 16), &f, 0, 0, 0, 0) == RENDER_DONE && f.spp == 2, "first part");
	render_job more = job_for(6, 2, 16);
	CHECK(render_run(&more, &f, NULL) == RENDER_DONE && f.spp == 6, "continued to %u spp", f.spp);
	d = differing_pixels(&whole, &f);
	CHECK(d == 0, "continued render: %d pixels differ", d);
	film_free(&f);

	/* Four uneven quarters equal the whole. */
	const int xs[3] = {0, 17, W}, ys[3] = {0, 11, H};
	for (int qy = 0; qy < 2; qy++)
		for (int qx = 0; qx < 2; qx++) {
			CHECK(render(job_for(6, 2, 5), &f, xs[qx], ys[qy], xs[qx + 1], ys[qy + 1]) ==
				  RENDER_DONE,
			      "region");
			d = differing_pixels(&whole, &f);
			CHECK(d == 0, "region %d,%d-%d,%d: %d pixels differ", xs[qx], ys[qy], xs[qx + 1],
			      ys[qy + 1], d);
			film_free(&f);
		}
	CHECK(!film_init(&f, W, H, 5, 5, 5, 9), "empty region accepted");
	CHECK(!film_init(&f, W, H, 0, 0, W + 1, H), "region outside the image accepted");

	/* The film's read-out: finite, depth where something was hit, variance non-negative. */
	float *buf = mem_alloc(W * H, 3 * sizeof(float));
	film_read(&whole, FILM_BEAUTY, buf);
	double mean = 0;
	for (int i = 0; i < 3 * W * H; i++)
		mean += buf[i];
	CHECK(isfinite(mean) && mean > 0, "beauty sum %g", mean);
	film_read(&whole, FILM_VARIANCE, buf);
	int neg = 0;
	for (int i = 0; i < 3 * W * H; i++)
		neg += !(buf[i] >= 0.0f);
	CHECK(neg == 0, "%d negative or NaN variances", neg);
	/* One pixel recomputed by hand from its streams: the mean and the variance of the mean, by
	 * the Sobol pixels' estimator (film.h): the mean against that of the first q samples, q the
	 * largest power of two below n. */
	{
		const int px = 20, py = 15;
		uint32_t q = 1;
		while (2 * q < whole.spp)
			q *= 2;
		double sum[3] = {0}, sum_q[3] = {0};
		for (uint32_t k = 0; k < whole.spp; k++) {
			if (k == q)
				memcpy(sum_q, sum, sizeof sum);
			render_sampler g = render_sampler_make(RENDER_SAMPLER_SOBOL, 1234, px, py, k);
			vec2 pu = render_sampler_2d(&g, RENDER_DIM_PIXEL), lu = render_sampler_2d(&g, RENDER_DIM_LENS);
			render_settings set = {.max_trace_level = 5, .mode = RENDER_MIS};
			render_sample smp =
			    render_path(&scene.rs, &set, cam_ray(&camera, px, py, pu, lu), &g);
			const float c[3] = {smp.radiance.x, smp.radiance.y, smp.radiance.z};
			for (int k2 = 0; k2 < 3; k2++)
				sum[k2] += c[k2];
		}
		float *beauty = mem_alloc(W * H, 3 * sizeof(float));
		film_read(&whole, FILM_BEAUTY, beauty);
		for (int k2 = 0; k2 < 3; k2++) {
			double n = whole.spp, m = sum[k2] / n, d = m - sum_q[k2] / q, v = d * d * q / (n - q);
			CHECK_NEAR(beauty[3 * (py * W + px) + k2], m, 1e-6 * (1 + m));
			CHECK_NEAR(buf[3 * (py * W + px) + k2], v, 1e-5 * (1 + v));
			CHECK(v > 0, "pixel %d,%d has no variance to compare", px, py);
		}
		mem_free(beauty);
	}
	film_read(&whole, FILM_DEPTH, buf);
	CHECK(buf[(H - 1) * W + W / 2] > 0.5f, "depth at the bottom (the floor) %g",
	      buf[(H - 1) * W + W / 2]);
	film_free(&whole);

	/* A time budget stops after a whole pass; the image equals an spp render of that count. */
	render_job j = job_for(0, 2, 8);
	j.time_budget_s = 0.3;
	render_stats st;
	CHECK(film_init(&f, W, H, 0, 0, 0, 0), "film");
	double t0 = now();
	CHECK(render_run(&j, &f, &st) == RENDER_DONE, "time-budget render");
	double took = now() - t0;
	CHECK(took >= 0.3 && took < 0.3 + 2 * RENDER_PASS_MAX_S + 1.0, "time budget 0.3 s took %g s", took);
	CHECK(st.spp == f.spp && f.spp > 0, "stats spp %u film spp %u", st.spp, f.spp);
	printf("  time budget 0.3 s: %u spp in %d passes, %.3f s, %.3g samples/s\n", st.spp, st.passes, took,
	       st.samples_per_s);
	CHECK(render(job_for(f.spp, 1, 16), &whole, 0, 0, 0, 0) == RENDER_DONE, "reference render");
	d = differing_pixels(&whole, &f);
	CHECK(d == 0, "time-budget render vs %u spp render: %d pixels differ", f.spp, d);
	film_free(&f);
	film_free(&whole);

	/* SIGINT mid-render: prompt return, one count for all pixels, the same image as a render
	 * of exactly that count. */
	struct sigaction sa;
	memset(&sa, 0, sizeof sa);
	sa.sa_handler = on_signal;
	sigemptyset(&sa.sa_mask);
	sigaction(SIGINT, &sa, NULL);
	j = job_for(1000000, 2, 8);
	j.interrupt = &stop_flag;
	ckpt ck = {0, 0, true};
	j.checkpoint = on_checkpoint;
	j.checkpoint_user = &ck;
	j.checkpoint_interval_s = 0.05;
	stopper sp = {0.4, 0};
	pthread_t th;
	pthread_create(&th, NULL, stop_later, &sp);
	CHECK(film_init(&f, W, H, 0, 0, 0, 0), "film");
	render_status rs = render_run(&j, &f, &st);
	double returned = now();
	pthread_join(th, NULL);
	CHECK(rs == RENDER_INTERRUPTED, "status %d after interrupt", (int)rs);
	CHECK(returned - sp.set_at < 0.5, "returned %g s after the interrupt", returned - sp.set_at);
	CHECK(st.spp == f.spp && f.spp > 0 && f.spp < 1000000, "interrupted at %u spp (stats %u)", f.spp,
	      st.spp);
	CHECK(ck.calls >= 1 && ck.monotone, "checkpoints: %d calls, monotone %d", ck.calls, ck.monotone);
	printf("  interrupted after %u spp (%d passes, %d checkpoints), returned %.3f s after the flag\n",
	       f.spp, st.passes, ck.calls, returned - sp.set_at);
	CHECK(render(job_for(f.spp, 2, 16), &whole, 0, 0, 0, 0) == RENDER_DONE, "reference render");
	d = differing_pixels(&whole, &f);
	CHECK(d == 0, "interrupted render vs %u spp render: %d pixels differ", f.spp, d);
	film_free(&f);
	film_free(&whole);
	/* Interrupted before the start: nothing rendered. */
	CHECK(film_init(&f, W, H, 0, 0, 0, 0), "film");
	CHECK(render_run(&j, &f, &st) == RENDER_INTERRUPTED && f.spp == 0, "pre-set flag: spp %u", f.spp);
	film_free(&f);

	/* A NaN-producing material: samples dropped and counted, the film stays finite. */
	scene.mat[2].diffuse = v3(NAN, 0.5f, 0.5f);
	CHECK(render(job_for(4, 2, 16), &f, 0, 0, 0, 0) == RENDER_DONE, "NaN render");
	CHECK(f.dropped > 0, "no dropped samples counted");
	film_read(&f, FILM_BEAUTY, buf);
	int bad = 0;
	for (int i = 0; i < 3 * W * H; i++)
		bad += !isfinite(buf[i]);
	CHECK(bad == 0, "%d non-finite values reached the film", bad);
	printf("  NaN material: %llu samples dropped\n", (unsigned long long)f.dropped);
	film_free(&f);

	/* Invalid jobs are refused. */
	j = job_for(0, 1, 16);
	CHECK(film_init(&f, W, H, 0, 0, 0, 0), "film");
	CHECK(render_run(&j, &f, NULL) == RENDER_ERROR, "no spp and no time budget accepted");
	film_free(&f);
#ifndef NDEBUG
	/* A commit that adds no samples breaks the film's invariant: film_commit asserts. */
	CHECK(film_init(&f, W, H, 0, 0, 0, 0), "film");
	CHECK(check_aborts(commit_nothing, &f), "film_commit without new samples did not assert");
	film_free(&f);
#endif
	mem_free(buf);
	light_set_free(&scene.lights);
	return check_done("test_scheduler");
}
