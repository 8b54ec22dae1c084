/* main.c - the circe command: parses the command line, calls the modules, decides exit codes.
 * Subcommands: render, check, compare, merge. Exit statuses: 0 success, 1 runtime or I/O error,
 * 2 bad command line, 3 scene error, 130 interrupted. */
#include "config.h"

#include "base/diag.h"
#include "io/compare.h"
#include "io/exr.h"

#include <errno.h>
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

/* circe compare A.exr B.exr: error figures of A against the reference B. Exit 0 when at most
 * --fail-percent of the pixels have an error above --fail, 1 otherwise or on an I/O error. */
static int cmd_compare(int argc, char **argv)
{
	static const struct option opts[] = {
		{"fail", required_argument, NULL, 'f'},
		{"fail-percent", required_argument, NULL, 'p'},
		{"diff", required_argument, NULL, 'd'},
		{"help", no_argument, NULL, 'h'},
		{NULL, 0, NULL, 0},
	};
	double threshold = 1e-6, percent = 0.0;
	const char *diff_path = NULL;
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
	compare_result r;
	if (compare_images(&a, pa, &b, pb, threshold, &r, diff_path ? &diff : NULL, &d)) {
		double frac = r.pixels ? 100.0 * (double)r.over / (double)r.pixels : 0.0;
		bool pass = frac <= percent;
		printf("channels: %d\npixels: %zu\n", r.nchannels, r.pixels);
		printf("rmse: %.9g\nrelmse: %.9g (epsilon %g)\nmean_abs: %.9g\n", r.rmse, r.relmse,
		       COMPARE_RELMSE_EPS, r.mean_abs);
		printf("max_abs: %.9g at %d,%d channel %s\n", r.max_abs, r.max_x, r.max_y, r.max_channel);
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
	exrfile_free(&a);
	exrfile_free(&b);
	diag_free(&d);
	return status;
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
