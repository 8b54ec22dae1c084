/* output.h - a film written out: the EXR with beauty and the chosen AOVs and the header that
 * records how it was made, and the PNG preview. Data window = the film's region, display window
 * = the whole frame, so tiles and regions are EXRs that compositing tools and `circe merge`
 * understand. */
#ifndef CIRCE_RENDER_OUTPUT_H
#define CIRCE_RENDER_OUTPUT_H

#include "base/diag.h"
#include "render/film.h"

#include <stdbool.h>
#include <stdint.h>

enum {
	OUTPUT_AOV_ALBEDO = 1,
	OUTPUT_AOV_NORMAL = 2,
	OUTPUT_AOV_DEPTH = 4,
	OUTPUT_AOV_VARIANCE = 8,
	OUTPUT_AOV_ERROR = 16,
	OUTPUT_AOV_SAMPLES = 32,
	OUTPUT_AOV_COUNT = 6
};

typedef struct output_info {
	const char *scene_path;
	const char *scene_hash; /* hex digest of the scene text and its includes */
	uint64_t seed;
	const char *sampler; /* "sobol" or "random" (render_sampler_name) */
	const char *part;    /* render_part_name of a --part render, NULL for the whole light */
	const char *sss_method;
	double clock;
	double render_seconds;
	const char *tile; /* "I/N" or NULL */
	unsigned aovs;    /* OUTPUT_AOV_* */
	double noise_threshold; /* adaptive sampling's; 0: off */
	/* POV-Ray's working gamma G (scene/gamma.c): the beauty is written as r^G; 0 or 1: as it is */
	double working_gamma;
	bool interrupted;
} output_info;

/* Writes f as an EXR (atomically). Channels: R G B A, then albedo.R/G/B, N.X/Y/Z, Z,
 * variance.R/G/B, error (film_pixel_error) and samples (each pixel's count) as asked. Attributes:
 * software, circe.scene, circe.scene_hash, circe.seed, circe.sampler, circe.spp (samples completed in every pixel
 * adaptive sampling did not stop), circe.sss, circe.clock, circe.render_time_s,
 * circe.dropped_samples, circe.interrupted, circe.tile when set, circe.noise_threshold when
 * adaptive, circe.part for a part of the light and circe.working_gamma when it is not 1. */
bool output_write_exr(const char *path, const film *f, const output_info *info, diag *d);
/* Writes the beauty of f as an 8-bit sRGB PNG (atomically), exposure in stops, working_gamma as
 * output_info's. */
bool output_write_png(const char *path, const film *f, float exposure_stops, double working_gamma, diag *d);

#endif
