/* output.c - film to EXR channels and header attributes; film to PNG. */
#include "config.h"

#include "render/output.h"

#include "base/mem.h"
#include "io/exr.h"
#include "io/image.h"

#include <inttypes.h>
#include <math.h>
#include <stdio.h>

/* POV-Ray's working space to light (scene/gamma.c): each of the n RGB triples r, stride floats
 * apart, becomes r^g (odd in r: a negative light of POV-Ray's stays negative). */
static void working_to_light(float *rgb, size_t n, size_t stride, double g)
{
	if (!(g > 0.0) || g == 1.0)
		return;
	for (size_t i = 0; i < n; i++)
		for (int c = 0; c < 3; c++) {
			float *v = &rgb[i * stride + (size_t)c];
			*v = *v > 0.0f ? (float)pow(*v, g) : *v < 0.0f ? -(float)pow(-*v, g) : 0.0f;
		}
}

/* Planar copies of the film's channels, freed together. */
typedef struct planes {
	float *data[4];
} planes;

bool output_write_exr(const char *path, const film *f, const output_info *info, diag *d)
{
	int w = film_region_width(f), h = film_region_height(f);
	size_t n = (size_t)w * (size_t)h;
	enum { NAOV = OUTPUT_AOV_COUNT };
	static const film_channel chans[NAOV] = {FILM_ALBEDO,	FILM_NORMAL, FILM_DEPTH,
						 FILM_VARIANCE, FILM_ERROR,  FILM_SAMPLES};
	static const char *const names[NAOV][3] = {
		{"albedo.R", "albedo.G", "albedo.B"}, {"N.X", "N.Y", "N.Z"}, {"Z", NULL, NULL},
		{"variance.R", "variance.G", "variance.B"}, {"error", NULL, NULL}, {"samples", NULL, NULL}};
	float *beauty = mem_alloc(n, 4 * sizeof(float));
	float *aov[NAOV] = {NULL};
	exrfile_channel ch[4 + NAOV * 3];
	int nch = 0;
	bool ok = beauty != NULL;
	if (ok) {
		/* Beauty RGB is read three-wide, then spread to RGBA with A = 1. */
		film_read(f, FILM_BEAUTY, beauty);
		working_to_light(beauty, n, 3, info->working_gamma);
		for (size_t i = n; i-- > 0;) {
			float r = beauty[i * 3], g = beauty[i * 3 + 1], b = beauty[i * 3 + 2];
			beauty[i * 4] = r, beauty[i * 4 + 1] = g, beauty[i * 4 + 2] = b, beauty[i * 4 + 3] = 1.0f;
		}
		static const char *const rgba[4] = {"R", "G", "B", "A"};
		for (int c = 0; c < 4; c++)
			ch[nch++] = (exrfile_channel){rgba[c], beauty + c, 4, (size_t)w * 4};
	}
	for (int k = 0; ok && k < NAOV; k++) {
		if (!(info->aovs & (1u << k)))
			continue;
		int comps = film_channel_components(chans[k]);
		aov[k] = mem_alloc(n, (size_t)comps * sizeof(float));
		if (!(ok = aov[k] != NULL))
			break;
		film_read(f, chans[k], aov[k]);
		for (int c = 0; c < comps; c++)
			ch[nch++] = (exrfile_channel){names[k][c], aov[k] + c, (size_t)comps, (size_t)w * comps};
	}
	if (!ok) {
		diag_file_error(d, path, "out of memory for a %dx%d image", w, h);
	} else {
		char seed[32];
		snprintf(seed, sizeof seed, "%" PRIu64, info->seed);
		exrfile_attr at[16];
		int na = 0;
		at[na++] = (exrfile_attr){.name = "software", .kind = EXRFILE_ATTR_STRING, .s = "circe " PACKAGE_VERSION};
		at[na++] = (exrfile_attr){.name = "circe.scene", .kind = EXRFILE_ATTR_STRING, .s = info->scene_path};
		at[na++] = (exrfile_attr){.name = "circe.scene_hash", .kind = EXRFILE_ATTR_STRING, .s = info->scene_hash};
		at[na++] = (exrfile_attr){.name = "circe.seed", .kind = EXRFILE_ATTR_STRING, .s = seed};
		if (info->sampler)
			at[na++] = (exrfile_attr){.name = "circe.sampler", .kind = EXRFILE_ATTR_STRING, .s = info->sampler};
		if (info->part)
			at[na++] = (exrfile_attr){.name = "circe.part", .kind = EXRFILE_ATTR_STRING, .s = info->part};
		at[na++] = (exrfile_attr){.name = "circe.spp", .kind = EXRFILE_ATTR_INT, .i = (int)f->spp};
		at[na++] = (exrfile_attr){.name = "circe.sss", .kind = EXRFILE_ATTR_STRING, .s = info->sss_method};
		at[na++] = (exrfile_attr){.name = "circe.clock", .kind = EXRFILE_ATTR_DOUBLE, .d = info->clock};
		at[na++] = (exrfile_attr){.name = "circe.render_time_s", .kind = EXRFILE_ATTR_DOUBLE,
					  .d = info->render_seconds};
		at[na++] = (exrfile_attr){.name = "circe.dropped_samples", .kind = EXRFILE_ATTR_DOUBLE,
					  .d = (double)f->dropped};
		at[na++] = (exrfile_attr){.name = "circe.interrupted", .kind = EXRFILE_ATTR_INT, .i = info->interrupted};
		if (info->tile)
			at[na++] = (exrfile_attr){.name = "circe.tile", .kind = EXRFILE_ATTR_STRING, .s = info->tile};
		if (info->working_gamma > 0.0 && info->working_gamma != 1.0)
			at[na++] = (exrfile_attr){.name = "circe.working_gamma", .kind = EXRFILE_ATTR_DOUBLE,
						  .d = info->working_gamma};
		if (info->noise_threshold > 0.0)
			at[na++] = (exrfile_attr){.name = "circe.noise_threshold", .kind = EXRFILE_ATTR_DOUBLE,
						  .d = info->noise_threshold};
		exrfile_write_desc desc = {{0, 0, f->width, f->height}, {f->x0, f->y0, f->x1, f->y1}, nch, ch, na, at};
		ok = exrfile_write(path, &desc, d);
	}
	mem_free(beauty);
	for (int k = 0; k < NAOV; k++)
		mem_free(aov[k]);
	return ok;
}

bool output_write_png(const char *path, const film *f, float exposure_stops, double working_gamma, diag *d)
{
	int w = film_region_width(f), h = film_region_height(f);
	float *rgb = mem_alloc((size_t)w * (size_t)h, 3 * sizeof(float));
	if (!rgb) {
		diag_file_error(d, path, "out of memory for a %dx%d image", w, h);
		return false;
	}
	film_read(f, FILM_BEAUTY, rgb);
	working_to_light(rgb, (size_t)w * (size_t)h, 3, working_gamma);
	bool ok = png_write(path, w, h, rgb, 3, (size_t)w * 3, exposure_stops, d);
	mem_free(rgb);
	return ok;
}
