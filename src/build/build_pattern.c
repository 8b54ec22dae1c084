/* build_pattern.c - the IR's pigment trees (scene/pigment.h) compiled into the world's flat
 * pattern program (render/pattern.h): nodes with their warps in the order they are applied to a
 * point (the reverse of the order written: POV-Ray's Warp_EPoint walks its list backwards), map
 * entries by node index, images loaded once, the default colour maps and block colours filled. */
#include "build/build_impl.h"

#include "base/mem.h"
#include "scene/pigment.h"

#include <string.h>

_Static_assert((int)SCENE_PAT_COUNT == (int)PATTERN_KIND_COUNT, "scene/pigment.h and render/pattern.h kinds agree");
_Static_assert((int)SCENE_WAVE_POLY == (int)WAVE_POLY, "the wave orders agree");
_Static_assert((int)SCENE_PIGMENT_MAX_ENTRIES == (int)PATTERN_MAX_ENTRIES, "the entry limits agree");

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
			  .strength = s->strength, .falloff = s->falloff, .inverse = s->inverse, .repeat = s->repeat};
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
	n.fractal_iterations = pg->fractal_iterations, n.julia_c[0] = pg->julia_c[0], n.julia_c[1] = pg->julia_c[1];
	n.fractal_exterior = pg->fractal_exterior, n.fractal_interior = pg->fractal_interior;
	n.magnet_type = pg->magnet_type, n.magnet_julia = pg->magnet_julia, n.slope_map = pg->slope_map;
	n.exterior_factor = pg->exterior_factor, n.interior_factor = pg->interior_factor;
	n.bump_amount = pg->bump_amount, n.accuracy = pg->accuracy;
	n.wave = (pattern_wave)pg->wave, n.frequency = pg->frequency, n.phase = pg->phase, n.exponent = pg->exponent;
	n.turb = (pattern_turb){pg->turb.amount, pg->turb.octaves, pg->turb.omega, pg->turb.lambda};
	return n;
}

static bool compile(world *w, const scene_pigment *pg, int depth, uint32_t *out, diag *d);

/* The entries of node k: the written ones (a pigment's compiled in turn), the block colours
 * not written and a pattern without a map taking POV-Ray's defaults. */
static bool compile_entries(world *w, const scene_pigment *pg, uint32_t k, int depth, diag *d)
{
	pattern_prog *pp = &w->patterns;
	pattern_entry defaults[6];
	int n_def = pattern_default_map((pattern_kind)pg->kind, defaults);
	uint32_t n = pg->entries ? pg->n_entries : (uint32_t)n_def;
	if (pg->block_list && n < (uint32_t)scene_pattern_blocks(pg->kind))
		n = (uint32_t)scene_pattern_blocks(pg->kind);
	uint32_t e0;
	if (!grow((void **)&pp->entries, &pp->n_entries, n, sizeof *pp->entries, &e0)) {
		diag_error(d, pg->loc, "out of memory");
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
				if (!compile(w, s->pigment, depth + 1, &child, d))
					return false;
				e.node = (int32_t)child;
			}
		}
		pp->entries[e0 + i] = e;
	}
	return true;
}

static bool compile(world *w, const scene_pigment *pg, int depth, uint32_t *out, diag *d)
{
	pattern_prog *pp = &w->patterns;
	uint32_t k, w0 = 0;
	if (depth > PATTERN_MAX_DEPTH || !grow((void **)&pp->nodes, &pp->n_nodes, 1, sizeof *pp->nodes, &k) ||
	    (pg->n_warps && !grow((void **)&pp->warps, &pp->n_warps, pg->n_warps, sizeof *pp->warps, &w0))) {
		diag_error(d, pg->loc, depth > PATTERN_MAX_DEPTH ? "pigments nested too deep" : "out of memory");
		return false;
	}
	pattern_node n = node_of(pg);
	n.warp0 = w0, n.n_warps = pg->n_warps;
	for (uint32_t i = 0; i < pg->n_warps; i++)
		pp->warps[w0 + i] = warp_of(&pg->warps[pg->n_warps - 1 - i]);
	if (pg->kind == SCENE_PAT_IMAGE) {
		/* a bump_map's grey is a height, not a colour: read as stored */
		if (!(n.img = world_image(w, pg->loc, pg->image, pg->is_normal ? IMAGE_RAW : IMAGE_SRGB, d)))
			return false;
		if (!pg->is_normal)
			warn_reflectance_image(n.img, pg->loc, pg->image, d);
	}
	if (pg->kind == SCENE_PAT_PIGMENT_PATTERN && pg->child) {
		uint32_t child;
		if (!compile(w, pg->child, depth + 1, &child, d))
			return false;
		n.child = (int32_t)child;
	}
	pp->nodes[k] = n;
	*out = k;
	if (pg->kind == SCENE_PAT_PLAIN || pg->kind == SCENE_PAT_IMAGE)
		return true;
	return compile_entries(w, pg, k, depth, d);
}

bool build_pattern(world *w, const scene_pigment *pg, uint32_t *node, diag *d) { return compile(w, pg, 0, node, d); }

void pattern_prog_free(pattern_prog *pg)
{
	mem_free(pg->nodes), mem_free(pg->warps), mem_free(pg->entries);
	*pg = (pattern_prog){0};
}

/* POV-Ray 3.7's sky_sphere (Trace::ComputeSky): the layers from the top one down, each adding its
 * colour times its opacity (1 - filter - transmit) times what the layers above let through, and
 * passing on colour * filter + transmit of its own. */
static vec3 sky_at(const world *w, const uint32_t *roots, int n, dvec3 dir)
{
	vec3 col = v3s(0.0f), through = v3s(1.0f);
	for (int i = n - 1; i >= 0; i--) {
		float c[5];
		pattern_eval(&w->patterns, roots[i], dir, 0.0, c);
		vec3 rgb = v3(c[0], c[1], c[2]);
		col = v3_add(col, v3_scale(v3_mul(rgb, through), 1.0f - c[3] - c[4]));
		through = v3_mul(through, v3_add(v3_scale(rgb, c[3]), v3s(c[4])));
	}
	return col;
}

bool build_sky_pigments(world *w, const scene_sky_sphere *sky, diag *d)
{
	uint32_t roots[SCENE_SKY_MAX_PIGMENTS];
	for (int i = 0; i < sky->n_pigments; i++)
		if (!build_pattern(w, sky->pigments[i], &roots[i], d))
			return false;
	size_t n = (size_t)WORLD_SKY_WIDTH * WORLD_SKY_HEIGHT;
	w->env_rgb = mem_alloc(n, 3 * sizeof(float));
	if (!w->env_rgb) {
		diag_error(d, sky->loc, "out of memory");
		return false;
	}
	size_t clamped = 0;
	for (int y = 0; y < WORLD_SKY_HEIGHT; y++)
		for (int x = 0; x < WORLD_SKY_WIDTH; x++) {
			vec3 dir = light_env_dir(v2((x + 0.5f) / WORLD_SKY_WIDTH, (y + 0.5f) / WORLD_SKY_HEIGHT));
			vec3 c = sky_at(w, roots, sky->n_pigments, v3_to_d3(dir));
			clamped += scene_color_clamp(&c, SCENE_COLOR_RADIANCE);
			float *px = w->env_rgb + 3 * ((size_t)y * WORLD_SKY_WIDTH + (size_t)x);
			px[0] = c.x, px[1] = c.y, px[2] = c.z;
		}
	if (clamped)
		diag_warning(d, sky->loc, "%zu texels of the sky_sphere's pigments are negative: clamped to 0", clamped);
	return true;
}
