/* main.c - the circe command: parses the command line, calls the modules, decides exit codes.
 * Subcommands: render, check, compare, merge. Exit statuses: 0 success, 1 runtime or I/O error,
 * 2 bad command line, 3 scene error, 130 interrupted. */
#include "config.h"

#include "base/diag.h"
#include "lang/lang.h"
#include "scene/scene.h"

#include <getopt.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { EXIT_OK = 0, EXIT_RUNTIME = 1, EXIT_USAGE = 2, EXIT_SCENE = 3 };

static const char usage_text[] =
	"usage: circe render SCENE [-o out.exr] [--png out.png] [-W W -H H] [--spp N | --time S]\n"
	"                    [--threads N] [--sss circle|fullcircle|disk|volume]\n"
	"                    [--circle-weight exact|talk] [--seed N] [--region X0,Y0,X1,Y1]\n"
	"                    [--aov albedo,normal,depth,variance] [--tile I/N] [--clock F]\n"
	"                    [--frame N] [--checkpoint S] [--max-memory SIZE] [-I DIR] [--quiet]\n"
	"       circe check SCENE [-I DIR] [--clock F] [--dump]\n"
	"       circe compare A.exr B.exr [--fail T --fail-percent P] [--diff D.exr]\n"
	"       circe merge -o FULL.exr TILE.exr...\n"
	"       circe --help | --version\n";

static int usage_error(const char *fmt, const char *arg)
{
	fprintf(stderr, "circe: error: ");
	fprintf(stderr, fmt, arg);
	fprintf(stderr, "\n%s", usage_text);
	return EXIT_USAGE;
}

/* Prints what `circe check` knows about a parsed scene. */
static void print_check_summary(const char *path, const scene *sc)
{
	scene_stats st;
	scene_stats_get(sc, &st);
	printf("%s: ok\n", path);
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
	printf("  mesh triangles given: %zu, subdivision cage faces: %zu\n", st.mesh_triangles, st.subdiv_faces);
	printf("  triangles after tessellation: (tessellation not yet built)\n");
	printf("  estimated IR memory: %.1f KiB\n", (double)st.memory_bytes / 1024.0);
}

/* circe check SCENE [-I DIR] [--clock F]: parse and build, print statistics. */
static int cmd_check(int argc, char **argv)
{
	static const struct option opts[] = {
		{"clock", required_argument, NULL, 'c'}, {"dump", no_argument, NULL, 'd'},
		{"help", no_argument, NULL, 'h'}, {NULL, 0, NULL, 0}};
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
		case 'h':
			fputs(usage_text, stdout);
			return EXIT_OK;
		default:
			return usage_error("%s", "bad option for 'check'");
		}
	}
	if (optind != argc - 1)
		return usage_error("%s", optind >= argc ? "'check' needs a SCENE file" : "'check' takes one SCENE file");
	diag d;
	diag_init(&d, stderr);
	scene *sc = NULL;
	lang_status st = lang_parse_file(argv[optind], &lo, &d, &sc);
	int rc = st == LANG_OK ? EXIT_OK : st == LANG_SCENE_ERROR ? EXIT_SCENE : EXIT_RUNTIME;
	if (st == LANG_OK && dump)
		scene_dump(sc, stdout);
	else if (st == LANG_OK)
		print_check_summary(argv[optind], sc);
	scene_free(sc);
	diag_free(&d);
	return rc;
}

/* circe render SCENE [options]. */
static int cmd_render(int argc, char **argv)
{
	(void)argc, (void)argv;
	fprintf(stderr, "circe: error: 'render' needs the renderer, which this build lacks\n");
	return EXIT_RUNTIME;
}

/* circe compare A.exr B.exr: error figures of A against B. */
static int cmd_compare(int argc, char **argv)
{
	(void)argc, (void)argv;
	fprintf(stderr, "circe: error: 'compare' is missing from this build\n");
	return EXIT_RUNTIME;
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
	/* Each subcommand sees argv from its own name on, so getopt_long works as for a program. */
	if (!strcmp(cmd, "render"))
		return cmd_render(argc - 1, argv + 1);
	if (!strcmp(cmd, "check"))
		return cmd_check(argc - 1, argv + 1);
	if (!strcmp(cmd, "compare"))
		return cmd_compare(argc - 1, argv + 1);
	return usage_error("unknown subcommand '%s'", cmd);
}
