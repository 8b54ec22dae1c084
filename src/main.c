/* main.c - the circe command: parses the command line, calls the modules, decides exit codes.
 * Subcommands: render, check, compare, merge. Exit statuses: 0 success, 1 runtime or I/O error,
 * 2 bad command line, 3 scene error, 130 interrupted. */
#include "config.h"

#include "accel/bvh.h"
#include "build/build.h"
#include "base/diag.h"
#include "base/mem.h"
#include "io/compare.h"
#include "io/atomic.h"
#include "io/exr.h"
#include "io/merge.h"
#include "lang/lang.h"
#include "render/output.h"
#include "render/scheduler.h"
#include "scene/scene.h"

#include <signal.h>
#include <stdatomic.h>
#include <time.h>
#include <unistd.h>

#include <assert.h>
#include <errno.h>
#include <getopt.h>
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { EXIT_OK = 0, EXIT_RUNTIME = 1, EXIT_USAGE = 2, EXIT_SCENE = 3, EXIT_INTERRUPTED = 130 };

static const char usage_text[] =
	"usage: circe render SCENE [-o out.exr] [--png out.png] [-W W -H H] [--spp N | --time S]\n"
	"                    [--threads N] [--sss circle|fullcircle|disk|volume|auto]\n"
	"                    [--circle-weight exact|talk] [--seed N] [--sampler sobol|random]\n"
	"                    [--part camera|coat|sss|direct|indirect] [--region X0,Y0,X1,Y1]\n"
	"                    [--noise-threshold T [--min-spp N]]\n"
	"                    [--aov albedo,normal,depth,variance,error,samples] [--tile I/N]\n"
	"                    [--clock F] [--frame N] [--checkpoint S] [--max-memory SIZE] [-I DIR]\n"
	"                    [--quiet]\n"
	"       circe check SCENE [-I DIR] [--clock F] [--frame N] [--max-memory SIZE] [--threads N] [--dump]\n"
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

/* ---- Options: each subcommand's options are one table (cli_opt) that getopt_long, the parse of
 * each value into its destination and `circe SUBCOMMAND --help` all read. */

typedef struct cli_opt cli_opt;
/* Reads arg into dest (the option's destination); false when arg is not a value the option takes. */
typedef bool (*cli_parse)(const cli_opt *op, const char *arg, void *dest);
struct cli_opt {
	const char *name;  /* long name (--spp); NULL: short only */
	char letter;	   /* short name (-W); 0: long only */
	const char *arg;   /* the argument's name in --help; NULL: the option takes none */
	const char *help;  /* one line for --help */
	cli_parse parse;   /* NULL: --help itself */
	size_t dest;	   /* offset of the destination in the subcommand's options struct */
	long lo, hi;	   /* the range of opt_int, opt_long and opt_u64 */
	const char *error; /* usage_error's message when parse fails (%s: the argument) */
};
/* The most options a subcommand has, and getopt_long's value of long option i (past any char). */
enum { CLI_MAX_OPTIONS = 32, CLI_LONG = 256 };

/* -I DIR, up to MAX_INCLUDE_DIRS of them. */
#define MAX_INCLUDE_DIRS 64
typedef struct include_list {
	const char *dir[MAX_INCLUDE_DIRS];
	int n;
} include_list;

static bool parse_double(const char *arg, double *out);
static bool parse_long(const char *arg, long lo, long hi, long *out);
static bool parse_size(const char *arg, size_t *out);

static bool opt_flag(const cli_opt *op, const char *arg, void *dest)
{
	(void)op, (void)arg;
	*(bool *)dest = true;
	return true;
}
static bool opt_string(const cli_opt *op, const char *arg, void *dest)
{
	(void)op;
	*(const char **)dest = arg;
	return true;
}
static bool opt_long(const cli_opt *op, const char *arg, void *dest)
{
	return parse_long(arg, op->lo, op->hi, dest);
}
static bool opt_int(const cli_opt *op, const char *arg, void *dest)
{
	long v;
	if (!parse_long(arg, op->lo, op->hi, &v))
		return false;
	*(int *)dest = (int)v;
	return true;
}
static bool opt_u64(const cli_opt *op, const char *arg, void *dest)
{
	long v;
	if (!parse_long(arg, op->lo, op->hi, &v))
		return false;
	*(uint64_t *)dest = (uint64_t)v;
	return true;
}
/* A finite number (parse_double). */
static bool opt_double(const cli_opt *op, const char *arg, void *dest)
{
	(void)op;
	return parse_double(arg, dest);
}
/* A finite number > 0. */
static bool opt_positive(const cli_opt *op, const char *arg, void *dest)
{
	(void)op;
	double v;
	if (!parse_double(arg, &v) || v <= 0)
		return false;
	*(double *)dest = v;
	return true;
}
static bool opt_size(const cli_opt *op, const char *arg, void *dest)
{
	(void)op;
	return parse_size(arg, dest);
}
static bool opt_include(const cli_opt *op, const char *arg, void *dest)
{
	(void)op;
	include_list *l = dest;
	if (l->n == MAX_INCLUDE_DIRS)
		return false;
	l->dir[l->n++] = arg;
	return true;
}

/* The table's entry for getopt_long's value c; NULL for an unknown option. */
static const cli_opt *cli_find(const cli_opt *table, size_t n, int c)
{
	if (c >= CLI_LONG && (size_t)(c - CLI_LONG) < n)
		return &table[c - CLI_LONG];
	for (size_t i = 0; i < n; i++)
		if (table[i].letter && table[i].letter == c)
			return &table[i];
	return NULL;
}

/* `circe SUBCOMMAND --help`: the usage, then the subcommand's options from its table. */
static void cli_print_help(const char *cmd, const cli_opt *table, size_t n)
{
	fputs(usage_text, stdout);
	printf("\n%s options:\n", cmd);
	for (size_t i = 0; i < n; i++) {
		const cli_opt *op = &table[i];
		char name[64];
		snprintf(name, sizeof name, "%s%c%s%s%s%s%s", op->letter ? "-" : "", op->letter ? op->letter : ' ',
			 op->letter && op->name ? ", " : "", op->name ? "--" : "", op->name ? op->name : "",
			 op->arg ? " " : "", op->arg ? op->arg : "");
		printf("  %-26s %s\n", op->letter ? name : name + 1, op->help);
	}
}

/* Parses argv (from the subcommand's name on) by the table into cli. Returns EXIT_OK, EXIT_USAGE
 * (after printing why) or -1 after --help. optind is then at the first operand. */
static int cli_parse_options(int argc, char **argv, const char *cmd, const cli_opt *table, size_t n, void *cli)
{
	struct option longs[CLI_MAX_OPTIONS + 1];
	char shorts[2 * CLI_MAX_OPTIONS + 1];
	size_t nl = 0, ns = 0;
	assert(n <= CLI_MAX_OPTIONS);
	for (size_t i = 0; i < n; i++) {
		int has_arg = table[i].arg ? required_argument : no_argument;
		if (table[i].name)
			longs[nl++] = (struct option){table[i].name, has_arg, NULL, CLI_LONG + (int)i};
		if (table[i].letter) {
			shorts[ns++] = table[i].letter;
			if (table[i].arg)
				shorts[ns++] = ':';
		}
	}
	longs[nl] = (struct option){NULL, 0, NULL, 0};
	shorts[ns] = '\0';
	int c;
	optind = 1;
	while ((c = getopt_long(argc, argv, shorts, longs, NULL)) != -1) {
		const cli_opt *op = cli_find(table, n, c);
		if (!op)
			return usage_error("bad option for '%s'", cmd);
		if (!op->parse) {
			cli_print_help(cmd, table, n);
			return -1;
		}
		if (!op->parse(op, optarg, (char *)cli + op->dest))
			return usage_error(op->error, optarg);
	}
	return EXIT_OK;
}

#define CLI_HELP {"help", 'h', NULL, "this help", NULL, 0, 0, 0, NULL}

/* `circe check` tessellates as a render would, at this image size (for adaptive subdivision and
 * the spheres' levels), and estimates the render's memory at it. */
enum { CHECK_WIDTH = 640, CHECK_HEIGHT = 480 };
/* The top level's cost of one instance (tlas.h: about 100 bytes) in each of its two trees, and
 * 16 more beside the world's record of it (world_stats.instance_bytes); check builds neither. */
#define CHECK_INSTANCE_BYTES (2 * 128 + 16)

/* The memory a render at CHECK_WIDTH x CHECK_HEIGHT would need, from what check built: what is
 * allocated now (the IR and the meshes), the BVHs at bvh.h's 64 bytes a triangle, the instances
 * and the film's two buffers. Textures are not loaded by check, so not counted. */
static size_t check_estimate(const world_stats *ws)
{
	return mem_live_bytes() + 64 * ws->triangles + CHECK_INSTANCE_BYTES * ws->instances + ws->instance_bytes +
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

/* The shapes check lists one by one before a count of the rest. */
enum { CHECK_MAX_SHAPES_LISTED = 40 };

/* Each tessellated POV-Ray shape: its place, triangles and the accuracy the screen asked of it. */
static void print_check_shapes(const world_stats *ws)
{
	for (size_t i = 0; i < ws->n_shapes && i < CHECK_MAX_SHAPES_LISTED; i++) {
		const world_shape_stat *s = &ws->shapes[i];
		printf("  %s at %s:%u:%u: %zu triangles, ", s->name, s->loc.src ? s->loc.src->name : "?", s->loc.line,
		       s->loc.col, s->triangles);
		if (s->level >= 0)
			printf("level %d, ", s->level);
		if (s->max_error > 0.0)
			printf("within %.3g units of the surface\n", s->max_error);
		else
			printf("exact\n");
	}
	if (ws->n_shapes > CHECK_MAX_SHAPES_LISTED)
		printf("  ... and %zu more shapes\n", ws->n_shapes - CHECK_MAX_SHAPES_LISTED);
}

/* Prints what `circe check` knows about a parsed scene. */
static void print_check_summary(const char *path, const scene *sc, const world_stats *ws, bool fits)
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
	       st.subdiv_faces + ws->cage_file_faces);
	printf("  triangles after tessellation: %zu unique, %zu with instances (%zu subdivision surfaces)\n",
	       ws->triangles, ws->instanced_triangles, ws->subdiv_surfaces);
	print_check_shapes(ws);
	if (ws->reused_shapes)
		printf("  shapes copied from trace()'s worlds: %zu (tessellated once for both)\n", ws->reused_shapes);
	if (ws->cached_shapes)
		printf("  isosurfaces with a grid made before (the same function, container and step): %zu\n",
		       ws->cached_shapes);
	if (ws->csg_solids)
		printf("  CSG: %zu solids, %zu nodes (unions of several objects in one operand included), %zu "
		       "clipping objects (never traced: only their insides are asked)\n",
		       ws->csg_solids, ws->csg_nodes, ws->csg_clips);
	if (st.sss_nonuniform)
		printf("  SSS objects under a non-uniform scale: %zu (circles become ellipses there: their "
		       "triangles are flattened into world space at build)\n", st.sss_nonuniform);
	/* The BVH is not built by check: bvh.h keeps it under 64 bytes a triangle. */
	printf("  estimated memory: IR %.1f KiB, meshes %.1f MiB, BVHs about %.1f MiB\n",
	       (double)st.memory_bytes / 1024.0, (double)ws->geometry_bytes / 1048576.0,
	       64.0 * (double)ws->triangles / 1048576.0);
	printf("  estimated render memory at %dx%d: %.1f MiB (limit %.1f MiB; textures not counted)\n", CHECK_WIDTH,
	       CHECK_HEIGHT, (double)check_estimate(ws) / 1048576.0, (double)mem_limit() / 1048576.0);
}


/* `check`'s options. */
typedef struct check_cli {
	include_list includes;
	double clock;
	long frame; /* -1: none (frame_number and its range are 0) */
	bool dump;
	size_t max_memory;
	int threads; /* 0: every core */
} check_cli;

/* --clock of check: a number strtod reads whole, finite. */
static bool opt_check_clock(const cli_opt *op, const char *arg, void *dest)
{
	(void)op;
	char *end;
	double v = strtod(arg, &end);
	if (end == arg || *end || !isfinite(v))
		return false;
	*(double *)dest = v;
	return true;
}

#define C(field) offsetof(check_cli, field)
static const cli_opt check_options[] = {
	{NULL, 'I', "DIR", "a folder searched for included files and assets (up to 64)", opt_include, C(includes), 0,
	 0, "too many -I folders (limit is 64)"},
	{"clock", 0, "F", "the scene's clock (default 0)", opt_check_clock, C(clock), 0, 0,
	 "--clock needs a number, got '%s'"},
	{"frame", 0, "N", "the frame number an animated scene reads as frame_number (default: none, 0)", opt_long,
	 C(frame), 0, 99999999, "--frame needs a frame number >= 0, not '%s'"},
	{"dump", 0, NULL, "print the parsed scene instead of its statistics", opt_flag, C(dump), 0, 0, NULL},
	{"max-memory", 0, "SIZE", "memory limit such as 512M or 2G (default: the machine's memory)", opt_size,
	 C(max_memory), 0, 0, "--max-memory needs a size such as 512M or 2G, not '%s'"},
	{"threads", 0, "N", "threads isosurfaces are tessellated on (default: every core; the same meshes for any)",
	 opt_int, C(threads), 1, 1024, "--threads needs a count from 1 to 1024, not '%s'"},
	CLI_HELP,
};
#undef C

/* lang_options.trace: the build's world_trace, user its world_tracer. */
static int trace_object(void *user, const scene *sc, const scene_object *objs, size_t n, const void *key, dvec3 org,
			dvec3 dir, dvec3 *hit, dvec3 *normal, diag *d, diag_loc loc)
{
	return world_trace(user, sc, objs, n, key, org, dir, hit, normal, d, loc);
}

/* lang_options.inside: the build's world_inside_fn (its worlds live as long as the tracer: free it
 * after the scene's render). */
static bool inside_object(void *user, const scene *sc, const scene_object *objs, size_t n, const void *key,
			  scene_fn *out, diag *d, diag_loc loc)
{
	return world_inside_fn(user, sc, objs, n, key, out, d, loc);
}

/* circe check SCENE [-I DIR] [--clock F] [--frame N] [--max-memory SIZE] [--threads N]: parse and build, print statistics;
 * a scene whose render would need more than the memory limit fails. */
static int cmd_check(int argc, char **argv)
{
	check_cli o = {.frame = -1};
	int status = cli_parse_options(argc, argv, "check", check_options,
				       sizeof check_options / sizeof check_options[0], &o);
	if (status != EXIT_OK)
		return status < 0 ? EXIT_OK : status;
	size_t max_memory = o.max_memory;
	bool dump = o.dump;
	lang_options lo = {.include_dirs = o.includes.dir, .n_include_dirs = (size_t)o.includes.n, .clock = o.clock,
			   .animated = o.frame >= 0, .frame = o.frame};
	if (optind != argc - 1)
		return usage_error("%s", optind >= argc ? "'check' needs a SCENE file" : "'check' takes one SCENE file");
	mem_set_limit(max_memory ? max_memory : physical_memory());
	diag d;
	diag_init(&d, stderr);
	scene *sc = NULL;
	world_tracer *tracer = world_tracer_new(max_memory); /* the object patterns' too: freed last */
	world_tracer_set_threads(tracer, o.threads);
	lo.trace = trace_object, lo.inside = inside_object, lo.trace_user = tracer;
	lang_status st = tracer ? lang_parse_file(argv[optind], &lo, &d, &sc) : LANG_NO_MEMORY;
	int rc = st == LANG_OK ? EXIT_OK : st == LANG_SCENE_ERROR ? EXIT_SCENE : EXIT_RUNTIME;
	if (st != LANG_OK)
		note_memory_limit();
	if (st == LANG_OK && dump)
		scene_dump(sc, stdout);
	else if (st == LANG_OK) {
		world_options wo = {.width = CHECK_WIDTH, .height = CHECK_HEIGHT, .max_memory = max_memory,
				    .geometry_only = true, .reuse = tracer, .shape_cache = world_tracer_shapes(tracer),
				    .threads = o.threads};
		world *w = world_build(sc, &wo, &d);
		if (w) {
			world_stats ws;
			world_stats_get(w, &ws);
			size_t need = check_estimate(&ws);
			bool fits = need <= mem_limit();
			print_check_summary(argv[optind], sc, &ws, fits);
			if (!fits) {
				fprintf(stderr, "circe: error: %s: a render at %dx%d would need about %.1f MiB, over the memory "
						"limit of %.1f MiB (--max-memory)\n",
					argv[optind], CHECK_WIDTH, CHECK_HEIGHT, (double)need / 1048576.0,
					(double)mem_limit() / 1048576.0);
				rc = EXIT_SCENE;
			}
			world_free(w);
		} else {
			note_memory_limit();
			rc = d.errors ? EXIT_SCENE : EXIT_RUNTIME;
		}
	}
	scene_free(sc);
	world_tracer_free(tracer);
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
	render_sampler_kind sampler; /* --sampler: sobol (default) or random */
	render_part part;	     /* --part: all (default) or one part of the light */
	bool has_region;
	int region[4]; /* x0, y0, x1, y1 */
	unsigned aovs; /* OUTPUT_AOV_* bits */
	double noise_threshold; /* 0: no adaptive sampling */
	long min_spp;		/* 0: automatic */
	int tile_i, tile_n;
	double clock;
	long frame; /* -1: none */
	double checkpoint_s;
	size_t max_memory;
	include_list includes;
	bool quiet;
} render_cli;

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
	/* In the order of the OUTPUT_AOV_* bits. */
	static const char *names[OUTPUT_AOV_COUNT] = {"albedo", "normal", "depth", "variance", "error", "samples"};
	*out = 0;
	const char *p = arg;
	while (*p) {
		size_t n = strcspn(p, ",");
		int k = 0;
		while (k < OUTPUT_AOV_COUNT && !(strlen(names[k]) == n && !strncmp(p, names[k], n)))
			k++;
		if (k == OUTPUT_AOV_COUNT)
			return false;
		*out |= 1u << k;
		p += n;
		if (*p == ',')
			p++;
	}
	return *out != 0;
}

static bool opt_sss(const cli_opt *op, const char *arg, void *dest)
{
	(void)op;
	sss_method m;
	if (!sss_method_from_name(arg, &m) || m == SSS_METHOD_DEFAULT)
		return false;
	*(const char **)dest = arg;
	return true;
}
static bool opt_circle_weight(const cli_opt *op, const char *arg, void *dest)
{
	(void)op;
	if (strcmp(arg, "exact") && strcmp(arg, "talk"))
		return false;
	*(bool *)dest = !strcmp(arg, "talk");
	return true;
}
static bool opt_sampler(const cli_opt *op, const char *arg, void *dest)
{
	(void)op;
	return render_sampler_from_name(arg, (render_sampler_kind *)dest);
}
static bool opt_part(const cli_opt *op, const char *arg, void *dest)
{
	(void)op;
	return render_part_from_name(arg, (render_part *)dest);
}
static bool opt_region(const cli_opt *op, const char *arg, void *dest)
{
	(void)op;
	render_cli *o = dest;
	int n = -1;
	if (sscanf(arg, "%d,%d,%d,%d%n", &o->region[0], &o->region[1], &o->region[2], &o->region[3], &n) != 4 ||
	    arg[n] != '\0' || o->region[0] < 0 || o->region[1] < 0 || o->region[2] <= o->region[0] ||
	    o->region[3] <= o->region[1])
		return false;
	o->has_region = true;
	return true;
}
static bool opt_aov(const cli_opt *op, const char *arg, void *dest)
{
	(void)op;
	return parse_aovs(arg, dest);
}
static bool opt_tile(const cli_opt *op, const char *arg, void *dest)
{
	(void)op;
	render_cli *o = dest;
	int n = -1;
	return sscanf(arg, "%d/%d%n", &o->tile_i, &o->tile_n, &n) == 2 && arg[n] == '\0' && o->tile_n >= 1 &&
	       o->tile_i >= 0 && o->tile_i < o->tile_n;
}

#define R(field) offsetof(render_cli, field)
static const cli_opt render_options[] = {
	{NULL, 'o', "FILE", "the EXR image to write (default: the scene's name with .exr)", opt_string, R(out), 0, 0, NULL},
	{"png", 0, "FILE", "also write the image as an 8-bit sRGB PNG", opt_string, R(png), 0, 0, NULL},
	{NULL, 'W', "W", "image width in pixels (default 640)", opt_int, R(width), 1, 65536,
	 "-W needs a width from 1 to 65536, not '%s'"},
	{NULL, 'H', "H", "image height in pixels (default 480)", opt_int, R(height), 1, 65536,
	 "-H needs a height from 1 to 65536, not '%s'"},
	{"spp", 0, "N", "samples per pixel (default 64)", opt_long, R(spp), 1, 1L << 30,
	 "--spp needs a sample count from 1 to 2^30, not '%s'"},
	{"time", 0, "S", "render for about S seconds instead of a sample count", opt_positive, R(time_s), 0, 0,
	 "--time needs a number of seconds > 0, not '%s'"},
	{"threads", 0, "N", "worker threads (default: every core)", opt_int, R(threads), 1, 1024,
	 "--threads needs a count from 1 to 1024, not '%s'"},
	{"sss", 0, "METHOD", "circle, fullcircle, disk, volume or auto for every SSS material", opt_sss, R(sss), 0, 0,
	 "--sss must be circle, fullcircle, disk, volume or auto, not '%s'"},
	{"circle-weight", 0, "W", "the circle estimator's weight: exact (default) or talk", opt_circle_weight,
	 R(talk_weight), 0, 0, "--circle-weight must be exact or talk, not '%s'"},
	{"seed", 0, "N", "the random seed (default 0)", opt_u64, R(seed), 0, LONG_MAX,
	 "--seed needs an integer >= 0, not '%s'"},
	{"sampler", 0, "S", "the samples: sobol (Owen-scrambled, the default) or random (independent)", opt_sampler,
	 R(sampler), 0, 0, "--sampler must be sobol or random, not '%s'"},
	{"part", 0, "P", "only this part of the light: camera, coat, sss, direct, indirect (default all)", opt_part,
	 R(part), 0, 0, "--part must be all, camera, coat, sss, direct or indirect, not '%s'"},
	{"region", 0, "X0,Y0,X1,Y1", "render only this rectangle of the image", opt_region, 0, 0, 0,
	 "--region needs X0,Y0,X1,Y1 with 0 <= X0 < X1 and 0 <= Y0 < Y1, not '%s'"},
	{"noise-threshold", 0, "T", "adaptive sampling: a pixel stops below this relative error (--spp: the most)",
	 opt_positive, R(noise_threshold), 0, 0, "--noise-threshold needs a relative error > 0 such as 0.05, not '%s'"},
	{"min-spp", 0, "N", "adaptive sampling's first check (default: 16 / T^0.3, as Cycles)", opt_long, R(min_spp), 1,
	 1L << 30, "--min-spp needs a sample count from 1 to 2^30, not '%s'"},
	{"aov", 0, "LIST", "extra layers: albedo, normal, depth, variance, error, samples", opt_aov, R(aovs), 0, 0,
	 "--aov takes a list of albedo, normal, depth, variance, error, samples, not '%s'"},
	{"tile", 0, "I/N", "render tile I of N (circe merge assembles them)", opt_tile, 0, 0, 0,
	 "--tile needs I/N with 0 <= I < N, not '%s'"},
	{"clock", 0, "F", "the scene's clock (default 0)", opt_double, R(clock), 0, 0, "--clock needs a number, not '%s'"},
	{"frame", 0, "N", "frame number for the output names (their #s, else .NNNN)",
	 opt_long, R(frame), 0, 99999999, "--frame needs a frame number >= 0, not '%s'"},
	{"checkpoint", 0, "S", "write the image so far every S seconds (default 60)", opt_positive, R(checkpoint_s),
	 0, 0, "--checkpoint needs a number of seconds > 0, not '%s'"},
	{"max-memory", 0, "SIZE", "memory limit such as 512M or 2G (default: the machine's memory)", opt_size,
	 R(max_memory), 0, 0, "--max-memory needs a size such as 512M or 2G, not '%s'"},
	{NULL, 'I', "DIR", "a folder searched for included files and assets (up to 64)", opt_include, R(includes), 0,
	 0, "too many -I directories (limit is 64)"},
	{"quiet", 0, NULL, "no progress line; statistics only when samples were dropped", opt_flag, R(quiet), 0, 0, NULL},
	CLI_HELP,
};
#undef R

/* Parses `render`'s options; returns EXIT_OK, EXIT_USAGE (after printing why) or -1 after --help. */
static int parse_render_cli(int argc, char **argv, render_cli *o)
{
	*o = (render_cli){.width = 640, .height = 480, .frame = -1, .checkpoint_s = 60.0};
	int status = cli_parse_options(argc, argv, "render", render_options,
				       sizeof render_options / sizeof render_options[0], o);
	if (status != EXIT_OK)
		return status;
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

/* What `circe render` holds while it runs, released in one place (render_free). */
typedef struct render_state {
	struct timespec start;
	char *out, *png, *out_default; /* the output names, the frame number put in */
	diag d;
	scene *sc;
	world *w;
	world_tracer *tracer; /* trace()'s and the object patterns' worlds: the render calls the latter */
	film f;
	bool has_film;
	double parse_s, build_s;
	double noise_threshold; /* --noise-threshold, else the scene's; 0: no adaptive sampling */
} render_state;

static void render_free(render_state *s)
{
	if (s->has_film)
		film_free(&s->f);
	world_free(s->w);
	scene_free(s->sc);
	world_tracer_free(s->tracer);
	free(s->out), free(s->png), free(s->out_default);
	diag_free(&s->d);
}

/* The output names (-o or the scene's name, --png), with the frame number; EXIT_OK, or the exit
 * status after saying why not. */
static int render_names(const render_cli *o, render_state *s)
{
	s->out_default = o->out ? NULL : default_output(o->scene);
	s->out = frame_name(o->out ? o->out : s->out_default, o->frame);
	s->png = o->png ? frame_name(o->png, o->frame) : NULL;
	if (!s->out || (o->png && !s->png)) {
		fprintf(stderr, "circe: error: out of memory\n");
		return EXIT_RUNTIME;
	}
	if (s->png && atomic_same_output(s->out, s->png)) {
		char both[2 * PATH_MAX];
		snprintf(both, sizeof both, "'%s' and --png '%s'", s->out, s->png);
		return usage_error("-o %s name the same file: one would overwrite the other", both);
	}
	return EXIT_OK;
}

/* Parses the scene, then builds its world; EXIT_OK or the exit status (the errors reported). */
static int render_scene_of(const render_cli *o, render_state *s)
{
	lang_options lo = {.include_dirs = o->includes.dir, .n_include_dirs = (size_t)o->includes.n,
			   .clock = o->clock, .width = o->width, .height = o->height, .animated = o->frame >= 0,
			   .frame = o->frame};
	s->tracer = world_tracer_new(o->max_memory);
	world_tracer_set_threads(s->tracer, o->threads);
	lo.trace = trace_object, lo.inside = inside_object, lo.trace_user = s->tracer;
	lang_status ls = s->tracer ? lang_parse_file(o->scene, &lo, &s->d, &s->sc) : LANG_NO_MEMORY;
	if (ls != LANG_OK) {
		note_memory_limit();
		return ls == LANG_SCENE_ERROR ? EXIT_SCENE : EXIT_RUNTIME;
	}
	s->parse_s = seconds_since(&s->start);
	if (atomic_load(&interrupted)) { /* during the parse: the build would be wasted */
		report_nothing_written(s->out);
		return EXIT_INTERRUPTED;
	}
	sss_method sss = SSS_METHOD_DEFAULT;
	if (o->sss && !sss_method_from_name(o->sss, &sss))
		assert(!"--sss was checked by its option parser");
	world_options wo = {.width = o->width, .height = o->height, .max_memory = o->max_memory, .sss_method = sss,
			    .reuse = s->tracer, .shape_cache = world_tracer_shapes(s->tracer), .threads = o->threads};
	/* A failure to build the world is the scene's fault (a bad mesh file, a level too high) or
	 * the machine's (memory): both were reported with their place. */
	if (!(s->w = world_build(s->sc, &wo, &s->d))) {
		note_memory_limit();
		return s->d.errors ? EXIT_SCENE : EXIT_RUNTIME;
	}
	s->build_s = seconds_since(&s->start) - s->parse_s;
	s->noise_threshold = o->noise_threshold > 0 ? o->noise_threshold : s->sc->global.noise_threshold;
	if (o->min_spp && !(s->noise_threshold > 0))
		fprintf(stderr, "circe: warning: --min-spp has no effect without a noise threshold (--noise-threshold, "
				"or global_settings' noise_threshold)\n");
	return EXIT_OK;
}

/* The film of the whole image, of --region or of --tile's rectangle (named in tile, "" for none);
 * EXIT_OK or the exit status after saying why not. */
static int render_film(const render_cli *o, render_state *s, char tile[32])
{
	int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
	tile[0] = '\0';
	if (o->has_region) {
		x0 = o->region[0], y0 = o->region[1], x1 = o->region[2], y1 = o->region[3];
	} else if (o->tile_n) {
		exrfile_rect r;
		if (!merge_tile_rect(o->width, o->height, o->tile_i, o->tile_n, &r)) {
			fprintf(stderr, "circe: error: a %dx%d image cannot be cut into %d tiles\n", o->width, o->height,
				o->tile_n);
			return EXIT_USAGE;
		}
		x0 = r.x0, y0 = r.y0, x1 = r.x1, y1 = r.y1;
		snprintf(tile, 32, "%d/%d", o->tile_i, o->tile_n);
	}
	int apron = s->noise_threshold > 0 ? ADAPTIVE_APRON : 0;
	if (!film_init_apron(&s->f, o->width, o->height, x0, y0, x1, y1, apron)) {
		fprintf(stderr, "circe: error: out of memory for a %dx%d film\n", o->width, o->height);
		note_memory_limit();
		return EXIT_RUNTIME;
	}
	s->has_film = true;
	return EXIT_OK;
}

/* The image's own estimate of its noise, beside the render's time, so the trade of samples (or
 * of a --noise-threshold) against time shows; with adaptive sampling, how the samples spread. */
static void report_noise(const render_state *s, double seconds)
{
	adaptive_summary a;
	adaptive_summarise(&s->f, &a);
	fprintf(stderr,
		"circe: noise: estimated NMSE %.3g (relative RMS error %.3g %%), mean pixel error %.3g, in %.2f s\n",
		a.nmse, 100.0 * sqrt(a.nmse), a.mean_error, seconds);
	if (s->noise_threshold > 0)
		fprintf(stderr, "circe: adaptive: threshold %g: %.1f samples per pixel on average (%u to %u)\n",
			s->noise_threshold, a.mean_spp, a.min_spp, a.max_spp);
}

/* The render's closing lines on stderr: samples, times, dropped samples, SSS searches, noise. */
static void report_render(const render_cli *o, const render_state *s, const render_stats *stats)
{
	world_stats ws;
	world_stats_get(s->w, &ws);
	if (!o->quiet || stats->dropped)
		fprintf(stderr, "circe: %s: %u samples per pixel in %.2f s (%.3g samples/s, %d threads); %llu "
				"non-finite samples dropped\n"
				"circe: time: parse %.3f s, build %.3f s (%zu triangles: tessellation and BVHs), "
				"render %.3f s\n",
			s->out, s->f.spp, stats->seconds, stats->samples_per_s, stats->threads,
			(unsigned long long)stats->dropped, s->parse_s, s->build_s, ws.triangles, stats->seconds);
	if (!o->quiet && ws.reused_shapes)
		fprintf(stderr, "circe: build: %zu shapes copied from trace()'s worlds (tessellated once for both)\n",
			ws.reused_shapes);
	if (!o->quiet && stats->sss_searches)
		fprintf(stderr, "circe: sss: %llu entry searches, %llu found no entry (no-hit rate %.4g: circles or "
				"probes that hit nothing, walks lost or at their step bound), %llu with more hits than "
				"kept\n",
			(unsigned long long)stats->sss_searches, (unsigned long long)stats->sss_nohit,
			(double)stats->sss_nohit / (double)stats->sss_searches, (unsigned long long)stats->sss_overflow);
	if (!o->quiet && stats->sss_walks)
		fprintf(stderr, "circe: sss: %llu volume walks (%.4g of the searches), %.4g interactions each, %llu dropped "
				"at the step bound of %d interactions\n",
			(unsigned long long)stats->sss_walks, (double)stats->sss_walks / (double)stats->sss_searches,
			(double)stats->sss_walk_steps / (double)stats->sss_walks, (unsigned long long)stats->sss_walk_dropped,
			SSS_WALK_MAX_STEPS);
	if (!o->quiet && stats->sss_walks && stats->sss_walk_queries)
		fprintf(stderr, "circe: sss: walks: %.4g of the interactions without a ray cast (inside a ball free of "
				"surface), %.4g nearest-surface queries a walk\n",
			(double)stats->sss_walk_skipped / (double)stats->sss_walk_steps,
			(double)stats->sss_walk_queries / (double)stats->sss_walks);
	if (!o->quiet)
		report_noise(s, stats->seconds);
}

/* Renders the built world into the film, checkpointing to the output, and writes the outputs;
 * the exit status. */
static int render_and_write(const render_cli *o, render_state *s, const char *tile)
{
	char hash[17];
	snprintf(hash, sizeof hash, "%016llx", (unsigned long long)s->sc->source_hash);
	output_info info = {.scene_path = o->scene, .scene_hash = hash, .seed = o->seed,
			    .sampler = render_sampler_name(o->sampler),
			    .part = o->part != RENDER_PART_ALL ? render_part_name(o->part) : NULL,
			    .sss_method = world_sss_method(s->w), .clock = o->clock, .tile = tile[0] ? tile : NULL,
			    .aovs = o->aovs, .noise_threshold = s->noise_threshold,
			    .working_gamma = s->sc->global.working_gamma};
	checkpoint_ctx cp = {s->out, &info, &s->d, s->start};
	int max_level = s->sc->global.max_trace_level;
	render_job job = {
		.scene = world_scene(s->w), .camera = world_camera(s->w),
		.settings = {.max_trace_level = max_level > 0 ? max_level : RENDER_DEFAULT_MAX_TRACE_LEVEL,
			     .mode = RENDER_MIS, .part = o->part,
			     .circle_weight = o->talk_weight ? SSS_CIRCLE_TALK : SSS_CIRCLE_EXACT,
			     .camera_tmax = world_camera(s->w)->max_distance},
		.seed = o->seed, .sampler = o->sampler, .spp = o->time_s > 0 ? 0 : (uint32_t)(o->spp ? o->spp : 64), .time_budget_s = o->time_s,
		.threads = o->threads, .checkpoint_interval_s = o->checkpoint_s,
		.checkpoint = on_checkpoint, .checkpoint_user = &cp,
		.progress = !o->quiet && isatty(fileno(stderr)) ? on_progress : NULL, .interrupt = &interrupted,
		.adaptive = {.threshold = s->noise_threshold, .min_spp = (uint32_t)o->min_spp}};
	render_stats stats;
	render_status rs = render_run(&job, &s->f, &stats);
	if (rs == RENDER_ERROR) {
		fprintf(stderr, "circe: error: the render could not start (threads or memory)\n");
		return EXIT_RUNTIME;
	}
	if (rs == RENDER_INTERRUPTED && s->f.spp == 0) {
		/* No pass finished: a black 0-sample image must not replace a good older one. */
		report_nothing_written(s->out);
		return EXIT_INTERRUPTED;
	}
	info.interrupted = rs == RENDER_INTERRUPTED;
	info.render_seconds = seconds_since(&s->start);
	bool ok = output_write_exr(s->out, &s->f, &info, &s->d) && (!s->png || output_write_png(s->png, &s->f, 0.0f, info.working_gamma, &s->d));
	report_render(o, s, &stats);
	return !ok ? EXIT_RUNTIME : info.interrupted ? EXIT_INTERRUPTED : EXIT_OK;
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
	render_state s = {0};
	clock_gettime(CLOCK_MONOTONIC, &s.start);
	diag_init(&s.d, stderr);
	char tile[32] = "";
	status = render_names(&o, &s);
	if (status == EXIT_OK) {
		mem_set_limit(o.max_memory ? o.max_memory : physical_memory());
		status = render_scene_of(&o, &s);
	}
	if (status == EXIT_OK)
		status = render_film(&o, &s, tile);
	if (status == EXIT_OK)
		status = render_and_write(&o, &s, tile);
	render_free(&s);
	return status;
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

/* `compare`'s options. */
typedef struct compare_cli {
	double threshold, percent;
	const char *diff_path, *channels;
} compare_cli;

static bool opt_threshold(const cli_opt *op, const char *arg, void *dest)
{
	(void)op;
	return parse_double(arg, dest) && *(double *)dest >= 0;
}
static bool opt_percent(const cli_opt *op, const char *arg, void *dest)
{
	(void)op;
	return parse_double(arg, dest) && *(double *)dest >= 0 && *(double *)dest <= 100;
}
/* A comma-separated list of non-empty names. */
static bool opt_channels(const cli_opt *op, const char *arg, void *dest)
{
	(void)op;
	if (!*arg || strspn(arg, ",") == strlen(arg) || strstr(arg, ",,") || arg[strlen(arg) - 1] == ',')
		return false;
	*(const char **)dest = arg;
	return true;
}

#define P(field) offsetof(compare_cli, field)
static const cli_opt compare_options[] = {
	{"fail", 0, "T", "a pixel fails when its error exceeds T (default 1e-6)", opt_threshold, P(threshold), 0, 0,
	 "--fail needs a number >= 0, not '%s'"},
	{"fail-percent", 0, "P", "the comparison fails when more than P % of the pixels fail (default 0)",
	 opt_percent, P(percent), 0, 0, "--fail-percent needs a number from 0 to 100, not '%s'"},
	{"diff", 0, "D.exr", "write |A - B| to D.exr", opt_string, P(diff_path), 0, 0, NULL},
	{"channels", 0, "R,G,B", "compare only these channels", opt_channels, P(channels), 0, 0,
	 "--channels needs a list of channel names such as R,G,B, not '%s'"},
	CLI_HELP,
};
#undef P

/* Compares a with the reference b, prints the figures and writes --diff; the exit status. */
static int compare_report(const exrfile_image *a, const char *pa, const exrfile_image *b, const char *pb,
			  const compare_cli *o, diag *d)
{
	compare_result r;
	exrfile_image diff;
	if (!compare_images(a, pa, b, pb, o->threshold, &r, o->diff_path ? &diff : NULL, d))
		return EXIT_RUNTIME;
	double frac = r.pixels ? 100.0 * (double)r.over / (double)r.pixels : 0.0;
	bool pass = frac <= o->percent;
	printf("channels: %d\npixels: %zu\n", r.nchannels, r.pixels);
	printf("rmse: %.9g\nrelmse: %.9g (epsilon %g)\nmean_abs: %.9g\n", r.rmse, r.relmse,
	       COMPARE_RELMSE_EPS, r.mean_abs);
	printf("max_abs: %.9g at %d,%d channel %s\n", r.max_abs, r.max_x, r.max_y, r.max_channel);
	printf("mean: a %.9g b %.9g\n", r.mean_a, r.mean_b);
	printf("psnr: %.3f dB (peak %g)\n", r.psnr, COMPARE_PSNR_PEAK);
	printf("over_threshold: %.6g%% (%zu pixels with error > %g; allowed %g%%)\n", frac, r.over,
	       o->threshold, o->percent);
	printf("nonfinite_a: nan %zu inf %zu\n", r.nan_a, r.inf_a);
	printf("result: %s\n", pass ? "PASS" : "FAIL");
	int status = pass ? EXIT_OK : EXIT_RUNTIME;
	if (o->diff_path) {
		exrfile_channel chans[64];
		for (int k = 0; k < diff.nchannels; k++)
			chans[k] = (exrfile_channel){diff.names[k], diff.planes[k], 1, (size_t)diff.width};
		exrfile_attr attr = {.name = "software", .kind = EXRFILE_ATTR_STRING,
				     .s = "circe " PACKAGE_VERSION " compare: |A - B|"};
		exrfile_write_desc desc = {diff.display, diff.data, diff.nchannels, chans, 1, &attr};
		if (!exrfile_write(o->diff_path, &desc, d))
			status = EXIT_RUNTIME;
		exrfile_free(&diff);
	}
	return status;
}

/* circe compare A.exr B.exr: error figures of A against the reference B. Exit 0 when at most
 * --fail-percent of the pixels have an error above --fail, 1 otherwise or on an I/O error. */
static int cmd_compare(int argc, char **argv)
{
	compare_cli o = {.threshold = 1e-6, .percent = 0.0};
	int status = cli_parse_options(argc, argv, "compare", compare_options,
				       sizeof compare_options / sizeof compare_options[0], &o);
	if (status != EXIT_OK)
		return status < 0 ? EXIT_OK : status;
	const char *channels = o.channels;
	if (argc - optind != 2)
		return usage_error("%s", "'compare' needs two images: A.exr B.exr");
	const char *pa = argv[optind], *pb = argv[optind + 1];
	diag d;
	diag_init(&d, stderr);
	exrfile_image a, b, ref = {0};
	bool read_a = exrfile_read(pa, &a, &d), read_b = read_a && exrfile_read(pb, &b, &d);
	if (read_b)
		ref = b;
	status = EXIT_RUNTIME;
	if (read_b && (!channels || compare_channel_view(&a, pa, &b, pb, channels, &ref)))
		status = compare_report(&a, pa, &ref, pb, &o, &d);
	if (read_b && channels) /* the view's own arrays; its planes are b's */
		mem_free(ref.names), mem_free(ref.planes);
	if (read_b)
		exrfile_free(&b);
	if (read_a)
		exrfile_free(&a);
	diag_free(&d);
	return status;
}

static const cli_opt merge_options[] = {
	{NULL, 'o', "FULL.exr", "the assembled image to write", opt_string, 0, 0, 0, NULL},
	CLI_HELP,
};

/* circe merge -o FULL.exr TILE.exr...: assembles tiles rendered apart. */
static int cmd_merge(int argc, char **argv)
{
	const char *out = NULL;
	int status = cli_parse_options(argc, argv, "merge", merge_options,
				       sizeof merge_options / sizeof merge_options[0], &out);
	if (status != EXIT_OK)
		return status < 0 ? EXIT_OK : status;
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
	/* CIRCE_WALK_SKIP=off: the volume walk casts every step (src/sss/README.md, "Skipping casts":
	 * the same estimator; for the tests and bench/sss that compare the two in one binary). */
	const char *skip = getenv("CIRCE_WALK_SKIP");
	sss_walk_set_skip(!(skip && !strcmp(skip, "off")));
	/* CIRCE_WALK_RUN=off: no cheap runs of classic steps inside a ball free of surface (src/sss/
	 * README.md, "Runs inside a ball": the same expectation, other samples; for the comparison). */
	const char *run = getenv("CIRCE_WALK_RUN");
	sss_walk_set_run(!(run && !strcmp(run, "off")));
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
