/* pigment.c - the pigment tree's names, POV-Ray's defaults for a node, and its dump. */
#include "scene/pigment.h"

#include <string.h>

static const char *const names[] = {
#define SCENE_PAT_NAME(e, s) s,
	SCENE_PATTERNS(SCENE_PAT_NAME)
#undef SCENE_PAT_NAME
};

const char *scene_pattern_name(scene_pattern_kind k) { return k < SCENE_PAT_COUNT ? names[k] : "?"; }

scene_pattern_kind scene_pattern_find(const char *s, size_t n)
{
	for (int k = SCENE_PAT_CHECKER; k < SCENE_PAT_COUNT; k++)
		if (strlen(names[k]) == n && !memcmp(names[k], s, n))
			return (scene_pattern_kind)k;
	return SCENE_PAT_COUNT;
}

int scene_pattern_blocks(scene_pattern_kind k)
{
	return k == SCENE_PAT_CHECKER || k == SCENE_PAT_BRICK || k == SCENE_PAT_OBJECT ? 2 : k == SCENE_PAT_HEXAGON ? 3 : 0;
}

/* POV-Ray 3.7's constructors (source/core/material/pattern.cpp): ContinuousPattern's ramp wave
 * of frequency 1; MarblePattern, WoodPattern, SpiralPattern's triangle wave; QuiltedPattern's
 * frequency 0 and controls 1; BrickPattern's size <8, 3, 4.5> and mortar 0.5; spiral's one arm;
 * agate_turb 1; GenericTurbulenceWarp's octaves 6, omega 0.5, lambda 2; gradient's <0, 1, 0>
 * only when none is written (the parser requires one, as POV-Ray does). */
scene_pigment scene_pigment_defaults(scene_pattern_kind k, diag_loc loc)
{
	scene_pigment p = {.loc = loc, .kind = k, .frequency = 1.0, .exponent = 1.0, .vector = d3(0, 1, 0),
			   .bump_amount = 0.5, .accuracy = 0.02, .mortar = 0.5 - 2.0e-10, .control0 = 1.0, .control1 = 1.0, .agate_turb = 1.0, .arms = 1,
			   .turb = {.octaves = 6, .omega = 0.5, .lambda = 2.0},
			   .crackle_form = d3(-1, 1, 0), .crackle_metric = 2.0,
			   .fractal_iterations = 1, .fractal_exponent = 2, .fractal_exterior = 1, .exterior_factor = 1.0, .interior_factor = 1.0};
	if (k == SCENE_PAT_MARBLE || k == SCENE_PAT_WOOD || k == SCENE_PAT_SPIRAL1 || k == SCENE_PAT_SPIRAL2)
		p.wave = SCENE_WAVE_TRIANGLE;
	if (k == SCENE_PAT_QUILTED)
		p.frequency = 0.0;
	if (k == SCENE_PAT_BRICK)
		p.vector = d3(8.0, 3.0, 4.5);
	if (k == SCENE_PAT_IMAGE)
		p.interpolate = false;
	if (k == SCENE_PAT_IMAGE_PATTERN)
		p.frequency = 0.0; /* Parse_Pattern's IMAGE_PATTERN_TOKEN */
	if (k == SCENE_PAT_FACETS)
		p.facets_size = 0.1; /* Parse_Pattern's FACETS_TOKEN: size 0.1, coords 0, metric 2 */
	return p;
}

static const char *const wave_names[] = {"ramp_wave", "triangle_wave", "sine_wave", "scallop_wave", "cubic_wave",
					 "poly_wave"};

void scene_pigment_dump(FILE *o, const scene_pigment *pg)
{
	if (pg->kind == SCENE_PAT_PLAIN && pg->is_normal) { /* #default's normal without a pattern */
		fprintf(o, "normal none %g", pg->bump_amount);
		return;
	}
	if (pg->kind == SCENE_PAT_PLAIN) {
		fprintf(o, "pigment rgbft <%g, %g, %g, %g, %g>", pg->color[0], pg->color[1], pg->color[2], pg->color[3],
			pg->color[4]);
		return;
	}
	if (pg->kind == SCENE_PAT_IMAGE) {
		fprintf(o, "pigment image_map \"%s\" map_type %d%s%s", pg->image ? pg->image : "", pg->map_type,
			pg->once ? " once" : "", pg->interpolate ? " interpolate" : "");
		for (int i = 0; i < 256; i++) {
			if (pg->pal_filter && pg->pal_filter[i] == pg->pal_filter[i])
				fprintf(o, " filter %d, %g", i, pg->pal_filter[i]);
			if (pg->pal_transmit && pg->pal_transmit[i] == pg->pal_transmit[i])
				fprintf(o, " transmit %d, %g", i, pg->pal_transmit[i]);
		}
	} else {
		fprintf(o, "pigment %s %s", scene_pattern_name(pg->kind), wave_names[pg->wave]);
		if (pg->frequency != 1.0 || pg->phase != 0.0)
			fprintf(o, " frequency %g phase %g", pg->frequency, pg->phase);
		if (pg->entries)
			fprintf(o, " %s %u",
				pg->pigment_map ? (pg->is_normal ? "normal_map" : "pigment_map")
				: pg->block_list ? "list"
				: pg->slope_map	 ? "slope_map"
						 : "color_map",
				pg->n_entries);
		const dvec3 f = pg->crackle_form;
		if (pg->kind == SCENE_PAT_CRACKLE &&
		    (f.x != -1 || f.y != 1 || f.z != 0 || pg->crackle_metric != 2 || pg->crackle_offset != 0))
			fprintf(o, " form <%g, %g, %g> metric %g offset %g", f.x, f.y, f.z, pg->crackle_metric,
				pg->crackle_offset);
		if (pg->solid)
			fprintf(o, " solid");
		if (pg->kind == SCENE_PAT_TILING)
			fprintf(o, " %d", pg->tiling);
		if (pg->kind == SCENE_PAT_FACETS)
			fprintf(o, " coords %g size %g metric %g", pg->facets_coords, pg->facets_size, pg->crackle_metric);
		if (pg->kind == SCENE_PAT_IMAGE_PATTERN || pg->kind == SCENE_PAT_MATERIAL_MAP)
			fprintf(o, " \"%s\" map_type %d%s%s%s", pg->image ? pg->image : "", pg->map_type, pg->once ? " once" : "",
				pg->interpolate ? " interpolate" : "", pg->use_alpha ? " use_alpha" : "");
		if (pg->kind == SCENE_PAT_DENSITY_FILE)
			fprintf(o, " df3 \"%s\" <%u, %u, %u> interpolate %d", pg->vox_file ? pg->vox_file : "", pg->vox_n[0],
				pg->vox_n[1], pg->vox_n[2], pg->vox_interp);
		if (pg->kind == SCENE_PAT_SLOPE) {
			const dvec3 d = d3_add(pg->slope_dir, d3(0, 0, 0)), a = d3_add(pg->altit_dir, d3(0, 0, 0)); /* no -0 */
			fprintf(o, " %s <%g, %g, %g> weight %g low %g width %g", pg->slope_point_at ? "point_at" : "direction", d.x,
				d.y, d.z, pg->slope_len, pg->slope_lo, pg->slope_width);
			if (pg->altit_len != 0.0)
				fprintf(o, " altitude <%g, %g, %g> weight %g low %g width %g", a.x, a.y, a.z, pg->altit_len,
					pg->altit_lo, pg->altit_width);
		}
		if (pg->kind == SCENE_PAT_MAGNET)
			fprintf(o, " type %d %s", pg->magnet_type, pg->magnet_julia ? "julia" : "mandel");
		if (pg->kind == SCENE_PAT_MANDEL || pg->kind == SCENE_PAT_JULIA || pg->kind == SCENE_PAT_MAGNET)
			fprintf(o, " c <%g, %g> iterations %d exterior %d %g interior %d %g", pg->julia_c[0], pg->julia_c[1],
				pg->fractal_iterations, pg->fractal_exterior, pg->exterior_factor, pg->fractal_interior,
				pg->interior_factor);
		if ((pg->kind == SCENE_PAT_MANDEL || pg->kind == SCENE_PAT_JULIA) && pg->fractal_exponent != 2)
			fprintf(o, " exponent %d", pg->fractal_exponent); /* only then: older dumps stay as they were */
	}
	if (pg->turb.amount.x != 0.0 || pg->turb.amount.y != 0.0 || pg->turb.amount.z != 0.0)
		fprintf(o, " turbulence <%g, %g, %g> octaves %d omega %g lambda %g", pg->turb.amount.x, pg->turb.amount.y,
			pg->turb.amount.z, pg->turb.octaves, pg->turb.omega, pg->turb.lambda);
	if (pg->n_warps)
		fprintf(o, " warps %u", pg->n_warps);
	if (pg->uv_mapping)
		fprintf(o, " uv_mapping");
	if (pg->is_normal)
		fprintf(o, " normal %g", pg->bump_amount);
}
