/* main.c - the circe command: parses the command line, calls the modules, decides exit codes.
 * Subcommands: render, check, compare, merge. Exit statuses: 0 success, 1 runtime or I/O error,
 * 2 bad command line, 3 scene error, 130 interrupted. */
#include "config.h"

#include "accel/bvh.h"
#include "base/diag.h"
#include "base/mem.h"
#include "io/compare.h"
#include "io/atomic.h"
#include "io/exr.h"
#include "io/merge.h"
#include "lang/lang.h"
#include "render/output.h"
#include "render/scheduler.h"
#include "render/world.h"
#include "scene/scene.h"

#include <signal.h>
#include <stdatomic.h>
#include <time.h>
#include <unistd.h>

#include <errno.h>
#include <getopt.h>
#include <limits.h>
#include <math.h>
#include <stdint.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { EXIT_OK = 0, EXIT_RUNTIME = 1, EXIT_USAGE = 2, EXIT_SCENE = 3, EXIT_INTERRUPTED = 130 };

static const char usage_text[] =
	"usage: circe render SCENE [-o out.exr] [--png out.png] [-W W -H H] [--spp N | --time S]\n"
	"                    [--threads N] [--sss circle|fullcircle|disk|volume]\n"
	"                    [--circle-weight exact|talk] [--seed N] [--region X0,Y0,X1,Y1]\n"
	"                    [--aov albedo,normal,depth,variance] [--tile I/N] [--clock F]\n"
	"                    [--frame N] [--checkpoint S] [--max-memory SIZE] [-I DIR] [--quiet]\n"
	"       circe check SCENE [-I DIR] [--clock F] [--max-memory SIZE] [--dump]\n"
	"       circe compare A.exr B.exr [--fail T --fail-percent P] [--diff D.exr]\n"
	"                     [--channels R,G,B]\n"
	"       circe merge -o FULL.exr TILE.exr...\n"
	"       circe --help | --version\n";

static int usage_error(const char *fmt, const char *arg)
{
	fprintf(stderr, "circe: error: ");
	fprintf(stderr, fmt, arg);
	fprintf(stderr, "\nTry 'circe --help' for the options.\n");
	return EXIT_USAGE;
}

/* `circe check` tessellates as a render would, at this image size (for adaptive subdivision and
 * the spheres' levels), and estimates the render's memory at it. */
enum { CHECK_WIDTH = 640, CHECK_HEIGHT = 480 };
/* The top level's cost of one instance (tlas.h: about 100 bytes) in each of its two trees, with
 * the world's record of it; check builds neither. */
#define CHECK_INSTANCE_BYTES (2 * 128 + sizeof(world_inst) + 16)

/* The memory a render at CHECK_WIDTH x CHECK_HEIGHT would need, from what check built: what is
 * allocated now (the IR and the meshes), the BVHs at bvh.h's 64 bytes a triangle, the instances
 * and the film's two buffers. Textures are not loaded by check, so not counted. */
static size_t check_estimate(const world *w)
{
	return mem_live_bytes() + 64 * w->stats.triangles + CHECK_INSTANCE_BYTES * w->n_insts +
	       2 * sizeof(film_pixel) * CHECK_WIDTH * CHECK_HEIGHT;
}

/* The machine's memory: --max-memory's default. */
static size_t physical_memory(void)
{
	long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
	return pages > 0 && page > 0 ? (size_t)pages * (size_t)page : 0;
}

/* After a failure: says so when it came from --max-memory's limit (mem.h). */
static void note_memory_limit(void)
{
	size_t asked, live;
	if (mem_limit_hit(&asked, &live))
		fprintf(stderr, "circe: note: that is the memory limit of %.1f MiB (--max-memory): %.1f MiB were in use "
				"when %.1f MiB more were asked for\n",
			(double)mem_limit() / 1048576.0, (double)live / 1048576.0, (double)asked / 1048576.0);
}

/* Prints what `circe check` knows about a parsed scene. */
static void print_check_summary(const char *path, const scene *sc, const world *w, bool fits)
{
	scene_stats st;
	scene_stats_get(sc, &st);
	printf("%s: %s\n", path, fits ? "ok" : "over the memory limit");
	printf("  objects:    %zu (%zu instances sharing geometry, %zu geometry records)\n", st.objects,
	       st.instances, st.geoms);
	printf("  lights:     %zu%s\n", st.lights, sc->has_background || sc->has_sky_sphere ? " + environment" : "");
	printf("  camera:     %s\n", sc->has_camera ? "yes" : "none (the default camera)");
	printf("  materials:");
	size_t total = 0;
	for (int k = 0; k < MAT_KIND_COUNT; k++)
		if (st.materials_by_kind[k]) {
			printf(" %s %zu", scene_material_kind_name((scene_material_kind)k), st.materials_by_kind[k]);
			total += st.materials_by_kind[k];
		}
	printf("%s\n", total ? "" : " none");
	printf("  mesh triangles given: %zu, subdivision cage faces: %zu\n", st.mesh_triangles,
	       st.subdiv_faces + w->stats.cage_file_faces);
	printf("  triangles after tessellation: %zu unique, %zu with instances (%zu subdivision surfaces)\n",
	       w->stats.triangles, w->stats.instanced_triangles, w->stats.subdiv_surfaces);
	if (st.sss_nonuniform)
		printf("  SSS objects under a non-uniform scale: %zu (circles become ellipses there: their "
		       "triangles are flattened into world space at build)\n", st.sss_nonuniform);
	/* The BVH is not built by check: bvh.h keeps it under 64 bytes a triangle. */
	printf("  estimated memory: IR %.1f KiB, meshes %.1f MiB, BVHs about %.1f MiB\n",
	       (double)st.memory_bytes / 1024.0, (double)w->stats.geometry_bytes / 1048576.0,
	       64.0 * (double)w->stats.triangles / 1048576.0);
	printf("  estimated render memory at %dx%d: %.1f MiB (limit %.1f MiB; textures not counted)\n", CHECK_WIDTH,
	       CHECK_HEIGHT, (double)check_estimate(w) / 1048576.0, (double)mem_limit() / 1048576.0);
}

static bool parse_size(const char *arg, size_t *out);

/* circe check SCENE [-I DIR] [--clock F] [--max-memory SIZE]: parse and build, print statistics;
 * a scene whose render would need more than the memory limit fails. */
static int cmd_check(int argc, char **argv)
{
	static const struct option opts[] = {
		{"clock", required_argument, NULL, 'c'}, {"dump", no_argument, NULL, 'd'},
		{"max-memory", required_argument, NULL, 'm'}, {"help", no_argument, NULL, 'h'}, {NULL, 0, NULL, 0}};
	size_t max_memory = 0;
	const char *dirs[64];
	lang_options lo = {.include_dirs = dirs};
	int c;
	bool dump = false;
	optind = 1;
	while ((c = getopt_long(argc, argv, "I:h", opts, NULL)) != -1) {
		char *end;
		switch (c) {
		case 'I':
			if (lo.n_include_dirs == sizeof dirs / sizeof dirs[0])
				return usage_error("too many -I folders (limit is %s)", "64");
			dirs[lo.n_include_dirs++] = optarg;
			break;
		case 'c':
			lo.clock = strtod(optarg, &end);
			if (end == optarg || *end || !isfinite(lo.clock))
				return usage_error("--clock needs a number, got '%s'", optarg);
			break;
		case 'd':
			dump = true;
			break;
		case 'm':
			if (!parse_size(optarg, &max_memory))
				return usage_error("--max-memory needs a size such as 512M or 2G, not '%s'", optarg);
			break;
		case 'h':
			fputs(usage_text, stdout);
			return EXIT_OK;
		default:
			return usage_error("%s", "bad option for 'check'");
		}
	}
	if (optind != argc - 1)
		return usage_error("%s", optind >= argc ? "'check' needs a SCENE file" : "'check' takes one SCENE file");
	mem_set_limit(max_memory ? max_memory : physical_memory());
	diag d;
	diag_init(&d, stderr);
	scene *sc = NULL;
	lang_status st = lang_parse_file(argv[optind], &lo, &d, &sc);
	int rc = st == LANG_OK ? EXIT_OK : st == LANG_SCENE_ERROR ? EXIT_SCENE : EXIT_RUNTIME;
	if (st != LANG_OK)
		note_memory_limit();
	if (st == LANG_OK && dump)
		scene_dump(sc, stdout);
	else if (st == LANG_OK) {
		world w;
		world_options wo = {.width = CHECK_WIDTH, .height = CHECK_HEIGHT, .max_memory = max_memory,
				    .geometry_only = true};
		if (world_build(&w, sc, &wo, &d)) {
			size_t need = check_estimate(&w);
			bool fits = need <= mem_limit();
			print_check_summary(argv[optind], sc, &w, fits);
			if (!fits) {
				fprintf(stderr, "circe: error: %s: a render at %dx%d would need about %.1f MiB, over the memory "
						"limit of %.1f MiB (--max-memory)\n",
					argv[optind], CHECK_WIDTH, CHECK_HEIGHT, (double)need / 1048576.0,
					(double)mem_limit() / 1048576.0);
				rc = EXIT_SCENE;
			}
			world_free(&w);
		} else {
			note_memory_limit();
			rc = d.errors ? EXIT_SCENE : EXIT_RUNTIME;
		}
	}
	scene_free(sc);
	diag_free(&d);
	return rc;
}

/* Parses a finite float option value; false when arg is not entirely a number. */
static bool parse_double(const char *arg, double *out)
{
	char *end;
	errno = 0;
	double v = strtod(arg, &end);
	if (end == arg || *end != '\0' || errno == ERANGE || !isfinite(v))
		return false;
	*out = v;
	return true;
}

/* Everything `circe render` takes from the command line. */
typedef struct render_cli {
	const char *scene, *out, *png;
	int width, height;
	long spp;         /* 0: not given */
	double time_s;    /* 0: not given */
	int threads;      /* 0: all cores */
	const char *sss;  /* NULL: each material's own method */
	bool talk_weight; /* --circle-weight talk */
	uint64_t seed;
	bool has_region;
	int region[4]; /* x0, y0, x1, y1 */
	unsigned aovs; /* AOV_* bits */
	int tile_i, tile_n;
	double clock;
	long frame; /* -1: none */
	double checkpoint_s;
	size_t max_memory;
	const char *include_dirs[64];
	int ninclude;
	bool quiet;
} render_cli;

enum { AOV_ALBEDO = 1, AOV_NORMAL = 2, AOV_DEPTH = 4, AOV_VARIANCE = 8 };

static bool parse_long(const char *arg, long lo, long hi, long *out)
{
	char *end;
	errno = 0;
	long v = strtol(arg, &end, 10);
	if (end == arg || *end != '\0' || errno == ERANGE || v < lo || v > hi)
		return false;
	*out = v;
	return true;
}

/* SIZE with an optional K, M or G suffix (powers of 1024). */
static bool parse_size(const char *arg, size_t *out)
{
	char *end;
	errno = 0;
	double v = strtod(arg, &end);
	double unit = 1;
	if (*end == 'K' || *end == 'k')
		unit = 1024.0, end++;
	else if (*end == 'M' || *end == 'm')
		unit = 1024.0 * 1024.0, end++;
	else if (*end == 'G' || *end == 'g')
		unit = 1024.0 * 1024.0 * 1024.0, end++;
	if (end == arg || *end != '\0' || errno == ERANGE || !(v > 0) || v * unit > 1e18)
		return false;
	*out = (size_t)(v * unit);
	return true;
}

static bool parse_aovs(const char *arg, unsigned *out)
{
	static const char *names[] = {"albedo", "normal", "depth", "variance"};
	*out = 0;
	const char *p = arg;
	while (*p) {
		size_t n = strcspn(p, ",");
		int k = 0;
		while (k < 4 && !(strlen(names[k]) == n && !strncmp(p, names[k], n)))
			k++;
		if (k == 4)
			return false;
		*out |= 1u << k;
		p += n;
		if (*p == ',')
			p++;
	}
	return *out != 0;
}

/* Parses `render`'s options; returns EXIT_OK or EXIT_USAGE (after printing why). */
static int parse_render_cli(int argc, char **argv, render_cli *o)
{
	static const struct option opts[] = {
		{"png", required_argument, NULL, 'P'},
		{"spp", required_argument, NULL, 's'},
		{"time", required_argument, NULL, 't'},
		{"threads", required_argument, NULL, 'j'},
		{"sss", required_argument, NULL, 'S'},
		{"circle-weight", required_argument, NULL, 'w'},
		{"seed", required_argument, NULL, 'e'},
		{"region", required_argument, NULL, 'r'},
		{"aov", required_argument, NULL, 'a'},
		{"tile", required_argument, NULL, 'T'},
		{"clock", required_argument, NULL, 'c'},
		{"frame", required_argument, NULL, 'f'},
		{"checkpoint", required_argument, NULL, 'k'},
		{"max-memory", required_argument, NULL, 'm'},
		{"quiet", no_argument, NULL, 'q'},
		{"help", no_argument, NULL, 'h'},
		{NULL, 0, NULL, 0},
	};
	*o = (render_cli){.width = 640, .height = 480, .frame = -1, .checkpoint_s = 60.0};
	long v;
	double f;
	int c;
	optind = 1;
	while ((c = getopt_long(argc, argv, "o:W:H:I:h", opts, NULL)) != -1) {
		switch (c) {
		case 'o':
			o->out = optarg;
			break;
		case 'P':
			o->png = optarg;
			break;
		case 'W':
		case 'H':
			if (!parse_long(optarg, 1, 65536, &v))
				return usage_error(c == 'W' ? "-W needs a width from 1 to 65536, not '%s'"
							    : "-H needs a height from 1 to 65536, not '%s'", optarg);
			*(c == 'W' ? &o->width : &o->height) = (int)v;
			break;
		case 's':
			if (!parse_long(optarg, 1, 1L << 30, &o->spp))
				return usage_error("--spp needs a sample count from 1 to 2^30, not '%s'", optarg);
			break;
		case 't':
			if (!parse_double(optarg, &o->time_s) || o->time_s <= 0)
				return usage_error("--time needs a number of seconds > 0, not '%s'", optarg);
			break;
		case 'j':
			if (!parse_long(optarg, 1, 1024, &v))
				return usage_error("--threads needs a count from 1 to 1024, not '%s'", optarg);
			o->threads = (int)v;
			break;
		case 'S':
			if (strcmp(optarg, "circle") && strcmp(optarg, "fullcircle") && strcmp(optarg, "disk") &&
			    strcmp(optarg, "volume"))
				return usage_error("--sss must be circle, fullcircle, disk or volume, not '%s'", optarg);
			o->sss = optarg;
			break;
		case 'w':
			if (strcmp(optarg, "exact") && strcmp(optarg, "talk"))
				return usage_error("--circle-weight must be exact or talk, not '%s'", optarg);
			o->talk_weight = !strcmp(optarg, "talk");
			break;
		case 'e':
			if (!parse_long(optarg, 0, LONG_MAX, &v))
				return usage_error("--seed needs an integer >= 0, not '%s'", optarg);
			o->seed = (uint64_t)v;
			break;
		case 'r': {
			int n = -1;
			if (sscanf(optarg, "%d,%d,%d,%d%n", &o->region[0], &o->region[1], &o->region[2],
				   &o->region[3], &n) != 4 || optarg[n] != '\0' || o->region[0] < 0 ||
			    o->region[1] < 0 || o->region[2] <= o->region[0] || o->region[3] <= o->region[1])
				return usage_error("--region needs X0,Y0,X1,Y1 with 0 <= X0 < X1 and 0 <= Y0 < Y1, not '%s'",
						   optarg);
			o->has_region = true;
			break;
		}
		case 'a':
			if (!parse_aovs(optarg, &o->aovs))
				return usage_error("--aov takes a list of albedo, normal, depth, variance, not '%s'", optarg);
			break;
		case 'T': {
			int n = -1;
			if (sscanf(optarg, "%d/%d%n", &o->tile_i, &o->tile_n, &n) != 2 || optarg[n] != '\0' ||
			    o->tile_n < 1 || o->tile_i < 0 || o->tile_i >= o->tile_n)
				return usage_error("--tile needs I/N with 0 <= I < N, not '%s'", optarg);
			break;
		}
		case 'c':
			if (!parse_double(optarg, &o->clock))
				return usage_error("--clock needs a number, not '%s'", optarg);
			break;
		case 'f':
			if (!parse_long(optarg, 0, 99999999, &o->frame))
				return usage_error("--frame needs a frame number >= 0, not '%s'", optarg);
			break;
		case 'k':
			if (!parse_double(optarg, &f) || f <= 0)
				return usage_error("--checkpoint needs a number of seconds > 0, not '%s'", optarg);
			o->checkpoint_s = f;
			break;
		case 'm':
			if (!parse_size(optarg, &o->max_memory))
				return usage_error("--max-memory needs a size such as 512M or 2G, not '%s'", optarg);
			break;
		case 'I':
			if (o->ninclude == 64)
				return usage_error("too many -I directories (limit is %s)", "64");
			o->include_dirs[o->ninclude++] = optarg;
			break;
		case 'q':
			o->quiet = true;
			break;
		case 'h':
			fputs(usage_text, stdout);
			return -1;
		default:
			return usage_error("%s", "bad option for 'render'");
		}
	}
	if (o->spp && o->time_s > 0)
		return usage_error("%s", "--spp and --time exclude each other");
	if (argc - optind != 1)
		return usage_error("%s", argc - optind ? "'render' takes one scene" : "'render' needs a scene");
	o->scene = argv[optind];
	if (o->has_region && (o->region[2] > o->width || o->region[3] > o->height))
		return usage_error("--region lies outside the %s image", "-W x -H");
	if (o->has_region && o->tile_n)
		return usage_error("%s", "--region and --tile exclude each other");
	return EXIT_OK;
}

/* Set by SIGINT/SIGTERM; the scheduler polls it. The handler does nothing else. */
static _Atomic int interrupted;

static void on_signal(int sig)
{
	(void)sig;
	atomic_store(&interrupted, 1);
}

/* SIGINT and SIGTERM set `interrupted` from now until the process ends; no SA_RESTART, so a
 * blocking open of an output FIFO gives up. */
static void install_stop_handlers(void)
{
	struct sigaction sa;
	memset(&sa, 0, sizeof sa);
	sa.sa_handler = on_signal;
	sigemptyset(&sa.sa_mask);
	sigaction(SIGINT, &sa, NULL);
	sigaction(SIGTERM, &sa, NULL);
}

/* Interrupted before a pass was done: an image of no samples would replace a good older one. */
static void report_nothing_written(const char *out)
{
	fprintf(stderr, "circe: interrupted before any pass was done: nothing written ('%s' is left as it was)\n",
		out);
}

/* FNV-1a (64-bit) of every source text the parser read, in the order it read them: the scene
 * and its includes. Tiles of one frame must agree on it. */
static void scene_hash(const diag *d, char out[17])
{
	uint64_t h = 0xcbf29ce484222325ULL;
	const diag_source *list[4096];
	size_t n = 0;
	for (const diag_source *s = d->sources; s && n < 4096; s = s->next)
		list[n++] = s;
	while (n-- > 0) /* the list is newest first */
		for (size_t i = 0; i < list[n]->len; i++)
			h = (h ^ (unsigned char)list[n]->text[i]) * 0x100000001b3ULL;
	snprintf(out, 17, "%016llx", (unsigned long long)h);
}

/* The output name with the frame number in place of the run of '#' (zero-padded to its length),
 * or before the extension when there is no '#'. */
static char *frame_name(const char *pattern, long frame)
{
	size_t n = strlen(pattern) + 32;
	char *out = malloc(n);
	if (!out)
		return NULL;
	const char *hash = strchr(pattern, '#');
	if (frame < 0) {
		snprintf(out, n, "%s", pattern);
	} else if (hash) {
		size_t run = strspn(hash, "#");
		snprintf(out, n, "%.*s%0*ld%s", (int)(hash - pattern), pattern, (int)run, frame, hash + run);
	} else {
		const char *dot = strrchr(pattern, '.');
		const char *slash = strrchr(pattern, '/');
		if (!dot || (slash && dot < slash))
			dot = pattern + strlen(pattern);
		snprintf(out, n, "%.*s.%04ld%s", (int)(dot - pattern), pattern, frame, dot);
	}
	return out;
}

/* The default output: the scene's name with .exr, in the current folder. */
static char *default_output(const char *scene_path)
{
	const char *base = strrchr(scene_path, '/');
	base = base ? base + 1 : scene_path;
	const char *dot = strrchr(base, '.');
	size_t stem = dot && dot != base ? (size_t)(dot - base) : strlen(base);
	char *out = malloc(stem + 5);
	if (out)
		snprintf(out, stem + 5, "%.*s.exr", (int)stem, base);
	return out;
}

typedef struct checkpoint_ctx {
	const char *path;
	output_info *info;
	diag *d;
	struct timespec start;
} checkpoint_ctx;

static double seconds_since(const struct timespec *t0)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return (double)(t.tv_sec - t0->tv_sec) + 1e-9 * (double)(t.tv_nsec - t0->tv_nsec);
}

static void on_checkpoint(void *user, const film *f)
{
	checkpoint_ctx *c = user;
	c->info->render_seconds = seconds_since(&c->start);
	output_write_exr(c->path, f, c->info, c->d);
}

/* Seconds as H:MM:SS. */
static void format_time(char *buf, size_t n, double s)
{
	long t = s > 0 && s < 1e9 ? (long)(s + 0.5) : 0;
	snprintf(buf, n, "%ld:%02ld:%02ld", t / 3600, (t / 60) % 60, t % 60);
}

/* The render's progress line on a terminal's stderr, redrawn in place (render_job.progress); the
 * last report ends the line. */
static void on_progress(void *user, const render_progress *p)
{
	(void)user;
	char el[32], left[32];
	format_time(el, sizeof el, p->elapsed);
	if (p->fraction > 0.0)
		format_time(left, sizeof left, p->elapsed * (1.0 - p->fraction) / p->fraction);
	else
		snprintf(left, sizeof left, "?");
	fprintf(stderr, "\rcirce: %5.1f%%  %.3g samples/s  elapsed %s  remaining %s   ", 100.0 * p->fraction,
		p->rate, el, left);
	if (p->done)
		fputc('\n', stderr);
	fflush(stderr);
}

/* The SSS method the EXR header records: --sss, else the materials' one, "mixed" when they
 * differ, "none" without SSS materials. */
static const char *sss_method_name(const world *w)
{
	static const char *names[] = {[RENDER_SSS_CIRCLE] = "circle", [RENDER_SSS_FULLCIRCLE] = "fullcircle",
				      [RENDER_SSS_DISK] = "disk", [RENDER_SSS_VOLUME] = "volume"};
	const char *name = "none";
	for (size_t i = 0; i < w->n_materials; i++) {
		if (!w->sss_of[i])
			continue;
		const char *m = names[w->sss_of[i]->method];
		if (strcmp(name, "none") && strcmp(name, m))
			return "mixed";
		name = m;
	}
	return name;
}

/* circe render SCENE [options]. */
static int cmd_render(int argc, char **argv)
{
	render_cli o;
	int status = parse_render_cli(argc, argv, &o);
	if (status != EXIT_OK)
		return status < 0 ? EXIT_OK : status;
	/* From here on a signal only asks the render to stop: start-up and output included. */
	install_stop_handlers();
	struct timespec start;
	clock_gettime(CLOCK_MONOTONIC, &start);
	char *out_default = o.out ? NULL : default_output(o.scene);
	char *out = frame_name(o.out ? o.out : out_default, o.frame);
	char *png = o.png ? frame_name(o.png, o.frame) : NULL;
	if (!out || (o.png && !png)) {
		fprintf(stderr, "circe: error: out of memory\n");
		free(out), free(png), free(out_default);
		return EXIT_RUNTIME;
	}
	if (png && atomic_same_output(out, png)) {
		char both[2 * PATH_MAX];
		snprintf(both, sizeof both, "'%s' and --png '%s'", out, png);
		status = usage_error("-o %s name the same file: one would overwrite the other", both);
		free(out), free(png), free(out_default);
		return status;
	}
	mem_set_limit(o.max_memory ? o.max_memory : physical_memory());
	diag d;
	diag_init(&d, stderr);
	lang_options lo = {.include_dirs = o.include_dirs, .n_include_dirs = (size_t)o.ninclude, .clock = o.clock};
	scene *sc = NULL;
	lang_status ls = lang_parse_file(o.scene, &lo, &d, &sc);
	if (ls != LANG_OK) {
		note_memory_limit();
		free(out), free(png), free(out_default), diag_free(&d);
		return ls == LANG_SCENE_ERROR ? EXIT_SCENE : EXIT_RUNTIME;
	}
	double parse_s = seconds_since(&start);
	if (atomic_load(&interrupted)) { /* during the parse: the build would be wasted */
		report_nothing_written(out);
		scene_free(sc), free(out), free(png), free(out_default), diag_free(&d);
		return EXIT_INTERRUPTED;
	}
	world w;
	scene_sss_method sss = !o.sss			 ? SSS_METHOD_DEFAULT
			       : !strcmp(o.sss, "fullcircle") ? SSS_METHOD_FULLCIRCLE
			       : !strcmp(o.sss, "disk")	 ? SSS_METHOD_DISK
			       : !strcmp(o.sss, "volume")	 ? SSS_METHOD_VOLUME
							 : SSS_METHOD_CIRCLE;
	world_options wo = {.width = o.width, .height = o.height, .max_memory = o.max_memory, .sss_method = sss};
	/* A failure to build the world is the scene's fault (a bad mesh file, a level too high) or
	 * the machine's (memory): both were reported with their place. */
	if (!world_build(&w, sc, &wo, &d)) {
		note_memory_limit();
		int rc = d.errors ? EXIT_SCENE : EXIT_RUNTIME;
		scene_free(sc), free(out), free(png), free(out_default), diag_free(&d);
		return rc;
	}
	double build_s = seconds_since(&start) - parse_s;
	int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
	char tile[32] = "";
	if (o.has_region) {
		x0 = o.region[0], y0 = o.region[1], x1 = o.region[2], y1 = o.region[3];
	} else if (o.tile_n) {
		exrfile_rect r;
		if (!merge_tile_rect(o.width, o.height, o.tile_i, o.tile_n, &r)) {
			fprintf(stderr, "circe: error: a %dx%d image cannot be cut into %d tiles\n", o.width, o.height,
				o.tile_n);
			world_free(&w), scene_free(sc), free(out), free(png), free(out_default), diag_free(&d);
			return EXIT_USAGE;
		}
		x0 = r.x0, y0 = r.y0, x1 = r.x1, y1 = r.y1;
		snprintf(tile, sizeof tile, "%d/%d", o.tile_i, o.tile_n);
	}
	film f;
	if (!film_init(&f, o.width, o.height, x0, y0, x1, y1)) {
		fprintf(stderr, "circe: error: out of memory for a %dx%d film\n", o.width, o.height);
		note_memory_limit();
		world_free(&w), scene_free(sc), free(out), free(png), free(out_default), diag_free(&d);
		return EXIT_RUNTIME;
	}
	char hash[17];
	scene_hash(&d, hash);
	output_info info = {.scene_path = o.scene, .scene_hash = hash, .seed = o.seed,
			    .sss_method = sss_method_name(&w), .clock = o.clock, .tile = tile[0] ? tile : NULL,
			    .aovs = o.aovs};
	checkpoint_ctx cp = {out, &info, &d, start};
	render_job job = {
		.scene = &w.rs, .camera = &w.camera,
		.settings = {.max_trace_level = sc->global.max_trace_level > 0 ? sc->global.max_trace_level
									: RENDER_DEFAULT_MAX_TRACE_LEVEL,
			     .mode = RENDER_MIS,
			     .circle_weight = o.talk_weight ? SSS_CIRCLE_TALK : SSS_CIRCLE_EXACT},
		.seed = o.seed, .spp = o.time_s > 0 ? 0 : (uint32_t)(o.spp ? o.spp : 64), .time_budget_s = o.time_s,
		.threads = o.threads, .checkpoint_interval_s = o.checkpoint_s,
		.checkpoint = on_checkpoint, .checkpoint_user = &cp,
		.progress = !o.quiet && isatty(fileno(stderr)) ? on_progress : NULL, .interrupt = &interrupted};
	render_stats stats;
	render_status rs = render_run(&job, &f, &stats);
	int rc = EXIT_OK;
	if (rs == RENDER_ERROR) {
		fprintf(stderr, "circe: error: the render could not start (threads or memory)\n");
		rc = EXIT_RUNTIME;
	} else if (rs == RENDER_INTERRUPTED && f.spp == 0) {
		/* No pass finished: a black 0-sample image must not replace a good older one. */
		report_nothing_written(out);
		rc = EXIT_INTERRUPTED;
	} else {
		info.interrupted = rs == RENDER_INTERRUPTED;
		info.render_seconds = seconds_since(&start);
		bool ok = output_write_exr(out, &f, &info, &d) && (!png || output_write_png(png, &f, 0.0f, &d));
		if (!o.quiet || stats.dropped)
			fprintf(stderr, "circe: %s: %u samples per pixel in %.2f s (%.3g samples/s, %d threads); %llu "
					"non-finite samples dropped\n"
					"circe: time: parse %.3f s, build %.3f s (%zu triangles: tessellation and BVHs), "
					"render %.3f s\n",
				out, f.spp, stats.seconds, stats.samples_per_s, stats.threads,
				(unsigned long long)stats.dropped, parse_s, build_s, w.stats.triangles, stats.seconds);
		if (!o.quiet && stats.sss_searches)
			fprintf(stderr, "circe: sss: %llu entry searches, %llu found no entry (no-hit rate %.4g: circles or "
					"probes that hit nothing, walks lost or at their step bound), %llu with more hits than "
					"kept\n",
				(unsigned long long)stats.sss_searches, (unsigned long long)stats.sss_nohit,
				(double)stats.sss_nohit / (double)stats.sss_searches,
				(unsigned long long)stats.sss_overflow);
		rc = !ok ? EXIT_RUNTIME : info.interrupted ? EXIT_INTERRUPTED : EXIT_OK;
	}
	film_free(&f);
	world_free(&w);
	scene_free(sc);
	free(out), free(png), free(out_default);
	diag_free(&d);
	return rc;
}

/* Restricts the reference b to the channels named in the comma-separated list (each must be in
 * both images): compare_images then sees only those. The view shares b's planes; the caller
 * frees view->names and view->planes only. False, with a message, for a channel not found. */
static bool compare_channel_view(const exrfile_image *a, const char *pa, const exrfile_image *b,
				 const char *pb, const char *list, exrfile_image *view)
{
	*view = *b;
	view->nchannels = 0;
	view->names = mem_calloc((size_t)b->nchannels + 1, sizeof(char *));
	view->planes = mem_calloc((size_t)b->nchannels + 1, sizeof(float *));
	if (!view->names || !view->planes) {
		fprintf(stderr, "circe: error: out of memory\n");
		return false;
	}
	for (const char *p = list; *p;) {
		size_t len = strcspn(p, ",");
		int found = -1;
		for (int c = 0; c < b->nchannels; c++)
			if (strlen(b->names[c]) == len && !strncmp(b->names[c], p, len))
				found = c;
		bool in_a = false;
		for (int c = 0; c < a->nchannels; c++)
			in_a |= strlen(a->names[c]) == len && !strncmp(a->names[c], p, len);
		if (found < 0 || !in_a) {
			fprintf(stderr, "%s: error: no channel '%.*s' (asked by --channels)\n", found < 0 ? pb : pa,
				(int)len, p);
			return false;
		}
		bool dup = false;
		for (int k = 0; k < view->nchannels; k++)
			dup |= view->planes[k] == b->planes[found];
		if (!dup) {
			view->names[view->nchannels] = b->names[found];
			view->planes[view->nchannels++] = b->planes[found];
		}
		p += len + (p[len] == ',');
	}
	return true;
}

/* circe compare A.exr B.exr: error figures of A against the reference B. Exit 0 when at most
 * --fail-percent of the pixels have an error above --fail, 1 otherwise or on an I/O error. */
static int cmd_compare(int argc, char **argv)
{
	static const struct option opts[] = {
		{"fail", required_argument, NULL, 'f'},
		{"fail-percent", required_argument, NULL, 'p'},
		{"diff", required_argument, NULL, 'd'},
		{"channels", required_argument, NULL, 'c'},
		{"help", no_argument, NULL, 'h'},
		{NULL, 0, NULL, 0},
	};
	double threshold = 1e-6, percent = 0.0;
	const char *diff_path = NULL, *channels = NULL;
	int c;
	optind = 1;
	while ((c = getopt_long(argc, argv, "h", opts, NULL)) != -1) {
		switch (c) {
		case 'f':
			if (!parse_double(optarg, &threshold) || threshold < 0)
				return usage_error("--fail needs a number >= 0, not '%s'", optarg);
			break;
		case 'p':
			if (!parse_double(optarg, &percent) || percent < 0 || percent > 100)
				return usage_error("--fail-percent needs a number from 0 to 100, not '%s'", optarg);
			break;
		case 'd':
			diff_path = optarg;
			break;
		case 'c':
			if (!*optarg || strspn(optarg, ",") == strlen(optarg) || strstr(optarg, ",,") ||
			    optarg[strlen(optarg) - 1] == ',')
				return usage_error("--channels needs a list of channel names such as R,G,B, not '%s'",
						   optarg);
			channels = optarg;
			break;
		case 'h':
			fputs(usage_text, stdout);
			return EXIT_OK;
		default:
			return usage_error("%s", "bad option for 'compare'");
		}
	}
	if (argc - optind != 2)
		return usage_error("%s", "'compare' needs two images: A.exr B.exr");
	const char *pa = argv[optind], *pb = argv[optind + 1];
	diag d;
	diag_init(&d, stderr);
	exrfile_image a, b, diff;
	int status = EXIT_RUNTIME;
	if (!exrfile_read(pa, &a, &d)) {
		diag_free(&d);
		return EXIT_RUNTIME;
	}
	if (!exrfile_read(pb, &b, &d)) {
		exrfile_free(&a);
		diag_free(&d);
		return EXIT_RUNTIME;
	}
	exrfile_image ref = b;
	if (channels && !compare_channel_view(&a, pa, &b, pb, channels, &ref)) {
		mem_free(ref.names), mem_free(ref.planes);
		exrfile_free(&a), exrfile_free(&b), diag_free(&d);
		return EXIT_RUNTIME;
	}
	compare_result r;
	if (compare_images(&a, pa, &ref, pb, threshold, &r, diff_path ? &diff : NULL, &d)) {
		double frac = r.pixels ? 100.0 * (double)r.over / (double)r.pixels : 0.0;
		bool pass = frac <= percent;
		printf("channels: %d\npixels: %zu\n", r.nchannels, r.pixels);
		printf("rmse: %.9g\nrelmse: %.9g (epsilon %g)\nmean_abs: %.9g\n", r.rmse, r.relmse,
		       COMPARE_RELMSE_EPS, r.mean_abs);
		printf("max_abs: %.9g at %d,%d channel %s\n", r.max_abs, r.max_x, r.max_y, r.max_channel);
		printf("mean: a %.9g b %.9g\n", r.mean_a, r.mean_b);
		printf("psnr: %.3f dB (peak %g)\n", r.psnr, COMPARE_PSNR_PEAK);
		printf("over_threshold: %.6g%% (%zu pixels with error > %g; allowed %g%%)\n", frac, r.over,
		       threshold, percent);
		printf("nonfinite_a: nan %zu inf %zu\n", r.nan_a, r.inf_a);
		printf("result: %s\n", pass ? "PASS" : "FAIL");
		status = pass ? EXIT_OK : EXIT_RUNTIME;
		if (diff_path) {
			exrfile_channel chans[64];
			for (int k = 0; k < diff.nchannels; k++)
				chans[k] = (exrfile_channel){diff.names[k], diff.planes[k], 1, (size_t)diff.width};
			exrfile_attr attr = {.name = "software", .kind = EXRFILE_ATTR_STRING,
					     .s = "circe " PACKAGE_VERSION " compare: |A - B|"};
			exrfile_write_desc desc = {diff.display, diff.data, diff.nchannels, chans, 1, &attr};
			if (!exrfile_write(diff_path, &desc, &d))
				status = EXIT_RUNTIME;
			exrfile_free(&diff);
		}
	}
	if (channels)
		mem_free(ref.names), mem_free(ref.planes);
	exrfile_free(&a);
	exrfile_free(&b);
	diag_free(&d);
	return status;
}

/* circe merge -o FULL.exr TILE.exr...: assembles tiles rendered apart. */
static int cmd_merge(int argc, char **argv)
{
	static const struct option opts[] = {
		{"help", no_argument, NULL, 'h'},
		{NULL, 0, NULL, 0},
	};
	const char *out = NULL;
	int c;
	optind = 1;
	while ((c = getopt_long(argc, argv, "o:h", opts, NULL)) != -1) {
		switch (c) {
		case 'o':
			out = optarg;
			break;
		case 'h':
			fputs(usage_text, stdout);
			return EXIT_OK;
		default:
			return usage_error("%s", "bad option for 'merge'");
		}
	}
	if (!out)
		return usage_error("%s", "'merge' needs -o FULL.exr");
	if (optind >= argc)
		return usage_error("%s", "'merge' needs at least one tile");
	diag d;
	diag_init(&d, stderr);
	d.max_errors = 0; /* every missing rectangle is worth printing */
	bool ok = merge_tiles(out, (const char *const *)argv + optind, argc - optind, &d);
	diag_free(&d);
	return ok ? EXIT_OK : EXIT_RUNTIME;
}

int main(int argc, char **argv)
{
	if (argc < 2)
		return usage_error("%s", "no subcommand given");
	const char *cmd = argv[1];
	if (!strcmp(cmd, "--help") || !strcmp(cmd, "-h")) {
		fputs(usage_text, stdout);
		return EXIT_OK;
	}
	if (!strcmp(cmd, "--version")) {
		printf("circe %s\n", PACKAGE_VERSION);
		return EXIT_OK;
	}
	/* CIRCE_SIMD=sse2 forces the BVHs' SSE2 path on a CPU with AVX2 (the same pixels, bit for bit:
	 * tests/render/determinism.sh). Read here once, before any build. */
	const char *simd = getenv("CIRCE_SIMD");
	bvh_set_simd(simd && !strcmp(simd, "sse2") ? BVH_SIMD_SSE2 : BVH_SIMD_AUTO);
	/* An output FIFO whose reader has gone is a write error (EPIPE) reported, not a silent death. */
	signal(SIGPIPE, SIG_IGN);
	/* Each subcommand sees argv from its own name on, so getopt_long works as for a program. */
	if (!strcmp(cmd, "render"))
		return cmd_render(argc - 1, argv + 1);
	if (!strcmp(cmd, "check"))
		return cmd_check(argc - 1, argv + 1);
	if (!strcmp(cmd, "compare"))
		return cmd_compare(argc - 1, argv + 1);
	if (!strcmp(cmd, "merge"))
		return cmd_merge(argc - 1, argv + 1);
	return usage_error("unknown subcommand '%s'", cmd);
}
