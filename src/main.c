/* main.c - the circe command: parses the command line, calls the modules, decides exit codes.
 * Subcommands: render, check, compare, merge. Exit statuses: 0 success, 1 runtime or I/O error,
 * 2 bad command line, 3 scene error, 130 interrupted. */
#include "config.h"

#include <getopt.h>
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
	"       circe check SCENE [-I DIR] [--clock F]\n"
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

/* circe check SCENE: parse and build, print statistics. */
static int cmd_check(int argc, char **argv)
{
	(void)argc, (void)argv;
	fprintf(stderr, "circe: error: 'check' needs the scene language, which this build lacks\n");
	return EXIT_RUNTIME;
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
