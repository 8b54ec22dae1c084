/* pattern_compile.c - the IR's pigment trees (scene/pigment.h) compiled into a flat pattern
 * program (scene/pattern.h): nodes with their warps in the order they are applied to a point
 * (the reverse of the order written: POV-Ray's Warp_EPoint walks its list backwards), map
 * entries by node index, the default colour maps and block colours filled, images through the
 * caller's loader. src/build compiles a world's program with it, src/lang a pattern or pigment
 * function's own. */
#include "scene/pattern.h"

#include "base/mem.h"

#include <string.h>

_Static_assert((int)SCENE_PAT_COUNT == (int)PATTERN_KIND_COUNT, "scene/pigment.h and scene/pattern.h kinds agree");
_Static_assert((int)SCENE_WAVE_POLY == (int)WAVE_POLY, "the wave orders agree");
_Static_assert((int)SCENE_PIGMENT_MAX_ENTRIES == (int)PATTERN_MAX_ENTRIES, "the entry limits agree");

typedef struct compiler {
	pattern_prog *pp;
	pattern_image_loader load;
	void *ctx;
	diag *d;
} compiler;

/* Grows *items (n of them, each size bytes) by k; the first new index in *at. */
static bool grow(void **items, size_t *n, size_t k, size_t size, uint32_t *at)
{
	if (*n + k > UINT32_MAX)
		return false;
	void *r = mem_realloc(*items, *n + k ? *n + k : 1, size);
	if (!r)
		return false;
	*items = r;
	memset((char *)r + *n * size, 0, k * size);
	*at = (uint32_t)*n;
	*n += k;
	return true;
}

static pattern_warp warp_of(const scene_warp *s)
{
	pattern_warp w = {.kind = (pattern_warp_kind)s->kind, .xf = s->xf, .axis = s->axis, .width = s->width,
			  .offset = s->offset, .flip = s->flip, .center = s->center, .radius = s->radius,
			  .strength = s->strength, .falloff = s->falloff, .inverse = s->inverse, .repeat = s->repeat,
			  .uncertainty = s->uncertainty,
			  .orientation = s->orientation, .dist_exp = s->dist_exp, .plane_offset = s->plane_offset,
			  .major_radius = s->major_radius};
	w.turb = (pattern_turb){s->turb.amount, s->turb.octaves, s->turb.omega, s->turb.lambda};
	return w;
}

/* The node's own parameters (no warps, entries or image). */
static pattern_node node_of(const scene_pigment *pg)
{
	pattern_node n = pattern_node_default((pattern_kind)pg->kind);
	memcpy(n.color, pg->color, sizeof n.color);
	n.map_type = pg->map_type, n.once = pg->once, n.interpolate = pg->interpolate;
	n.filter_all = pg->filter_all, n.transmit_all = pg->transmit_all;
	n.vector = pg->vector, n.mortar = pg->mortar, n.control0 = pg->control0, n.control1 = pg->control1;
	n.arms = pg->arms, n.agate_turb = pg->agate_turb, n.solid = pg->solid;
	n.crackle_form = pg->crackle_form, n.crackle_metric = pg->crackle_metric, n.crackle_offset = pg->crackle_offset;
	n.fractal_exponent = pg->fractal_exponent;
	n.fractal_iterations = pg->fractal_iterations, n.julia_c[0] = pg->julia_c[0], n.julia_c[1] = pg->julia_c[1];
	n.fractal_exterior = pg->fractal_exterior, n.fractal_interior = pg->fractal_interior;
	n.magnet_type = pg->magnet_type, n.magnet_julia = pg->magnet_julia, n.slope_map = pg->slope_map;
	n.exterior_factor = pg->exterior_factor, n.interior_factor = pg->interior_factor;
	n.bump_amount = pg->bump_amount, n.accuracy = pg->accuracy;
	n.wave = (pattern_wave)pg->wave, n.frequency = pg->frequency, n.phase = pg->phase, n.exponent = pg->exponent;
	n.turb = (pattern_turb){pg->turb.amount, pg->turb.octaves, pg->turb.omega, pg->turb.lambda};
	n.fn = pg->fn;
	n.slope_dir = pg->slope_dir, n.altit_dir = pg->altit_dir, n.slope_len = pg->slope_len, n.altit_len = pg->altit_len;
	n.slope_lo = pg->slope_lo, n.slope_width = pg->slope_width, n.altit_lo = pg->altit_lo;
	n.altit_width = pg->altit_width, n.slope_point_at = pg->slope_point_at;
	n.voxels = pg->voxels, n.vox_interp = pg->vox_interp, n.use_alpha = pg->use_alpha;
	n.facets_coords = pg->facets_coords, n.facets_size = pg->facets_size, n.tiling = pg->tiling;
	memcpy(n.vox_n, pg->vox_n, sizeof n.vox_n);
	return n;
}

static bool compile(compiler *c, const scene_pigment *pg, int depth, uint32_t *out);

/* The entries of node k: the written ones (a pigment's compiled in turn), the block colours
 * not written and a pattern without a map taking POV-Ray's defaults. */
static bool compile_entries(compiler *c, const scene_pigment *pg, uint32_t k, int depth)
{
	pattern_prog *pp = c->pp;
	pattern_entry defaults[6];
	int n_def = pattern_default_map((pattern_kind)pg->kind, defaults);
	uint32_t n = pg->entries ? pg->n_entries : (uint32_t)n_def;
	if (pg->block_list && n < (uint32_t)scene_pattern_blocks(pg->kind))
		n = (uint32_t)scene_pattern_blocks(pg->kind);
	uint32_t e0;
	if (!grow((void **)&pp->entries, &pp->n_entries, n, sizeof *pp->entries, &e0)) {
		diag_error(c->d, pg->loc, "out of memory");
		return false;
	}
	pp->nodes[k].entry0 = e0, pp->nodes[k].n_entries = n;
	for (uint32_t i = 0; i < n; i++) {
		pattern_entry e = i < (uint32_t)n_def ? defaults[i] : (pattern_entry){.node = -1};
		if (pg->entries && i < pg->n_entries) {
			const scene_map_entry *s = &pg->entries[i];
			e = (pattern_entry){.value = s->value, .node = -1};
			memcpy(e.color, s->color, sizeof e.color);
			uint32_t child;
			if (s->pigment) {
				if (!compile(c, s->pigment, depth + 1, &child))
					return false;
				e.node = (int32_t)child;
			}
		}
		c->pp->entries[e0 + i] = e;
	}
	return true;
}

static bool compile(compiler *c, const scene_pigment *pg, int depth, uint32_t *out)
{
	pattern_prog *pp = c->pp;
	uint32_t k, w0 = 0;
	if (depth > PATTERN_MAX_DEPTH || !grow((void **)&pp->nodes, &pp->n_nodes, 1, sizeof *pp->nodes, &k) ||
	    (pg->n_warps && !grow((void **)&pp->warps, &pp->n_warps, pg->n_warps, sizeof *pp->warps, &w0))) {
		diag_error(c->d, pg->loc, depth > PATTERN_MAX_DEPTH ? "pigments nested too deep" : "out of memory");
		return false;
	}
	pattern_node n = node_of(pg);
	n.warp0 = w0, n.n_warps = pg->n_warps;
	for (uint32_t i = 0; i < pg->n_warps; i++)
		pp->warps[w0 + i] = warp_of(&pg->warps[pg->n_warps - 1 - i]);
	if (pg->kind == SCENE_PAT_IMAGE || pg->kind == SCENE_PAT_IMAGE_PATTERN || pg->kind == SCENE_PAT_MATERIAL_MAP) {
		if (!c->load) {
			diag_error(c->d, pg->loc, "an %s in a function's pigment is not supported by circe",
				   scene_pattern_name(pg->kind));
			return false;
		}
		if (!(n.img = c->load(c->ctx, pg, c->d)))
			return false;
		if (pg->kind == SCENE_PAT_IMAGE && (pg->pal_filter || pg->pal_transmit)) {
			scene_pigment ix = *pg; /* the same file's palette indices: the loader reads a material_map so */
			ix.kind = SCENE_PAT_MATERIAL_MAP;
			if (!(n.img_index = c->load(c->ctx, &ix, c->d)))
				return false;
			if (!n.img_index->indexed) {
				diag_error(c->d, pg->loc, "'filter' or 'transmit' of a palette index needs a palette image, and "
							  "'%s' is not one (POV-Ray: not with a non color-mapped image)",
					   pg->image);
				return false;
			}
			if (pg->pal_max >= n.img_index->palette) {
				diag_error(c->d, pg->loc, "palette index %d of 'filter' or 'transmit' is out of range: '%s' has %d "
							  "colours (POV-Ray: color register value out of range)",
					   pg->pal_max, pg->image, n.img_index->palette);
				return false;
			}
			n.pal_filter = pg->pal_filter, n.pal_transmit = pg->pal_transmit;
		}
		size_t texels = (size_t)n.img->width * (size_t)n.img->height;
		for (size_t i = 0; i < texels && !n.img_alpha; i++) /* POV-Ray's HasTransparency */
			n.img_alpha = n.img->rgba[4 * i + 3] != 1.0f;
	}
	if (pg->kind == SCENE_PAT_PIGMENT_PATTERN && pg->child) {
		uint32_t child;
		if (!compile(c, pg->child, depth + 1, &child))
			return false;
		n.child = (int32_t)child;
	}
	pp->nodes[k] = n;
	*out = k;
	if (pg->kind == SCENE_PAT_PLAIN || pg->kind == SCENE_PAT_IMAGE)
		return true;
	return compile_entries(c, pg, k, depth);
}

bool pattern_compile(pattern_prog *pp, const scene_pigment *pg, pattern_image_loader load, void *ctx, uint32_t *node,
		     diag *d)
{
	compiler c = {.pp = pp, .load = load, .ctx = ctx, .d = d};
	return compile(&c, pg, 0, node);
}

void pattern_prog_free(pattern_prog *pg)
{
	mem_free(pg->nodes), mem_free(pg->warps), mem_free(pg->entries);
	*pg = (pattern_prog){0};
}
