/* build_pattern.c - the IR's pigment trees compiled into the world's flat pattern program by
 * scene/pattern_compile.c, the images they name loaded once into the world; a patterned
 * sky_sphere baked into a lat-long image. */
#include "build/build_impl.h"

#include "base/mem.h"
#include "scene/pigment.h"

#include <string.h>

/* The loader pattern_compile calls for an image_map, bump_map, image_pattern or material_map: the
 * world's image, loaded once (a bump_map's grey is a height and an image_pattern's a pattern value,
 * not colours: read as stored; a material_map's palette PNG as its indices). */
static const image *load_image(void *ctx, const scene_pigment *pg, diag *d)
{
	world *w = ctx;
	/* image_pattern's grey and material_map's index are data too */
	bool raw = pg->is_normal || pg->kind == SCENE_PAT_IMAGE_PATTERN || pg->kind == SCENE_PAT_MATERIAL_MAP;
	image_encoding enc = pg->kind == SCENE_PAT_MATERIAL_MAP ? IMAGE_INDEX : raw ? IMAGE_RAW : IMAGE_SRGB;
	const image *img = world_image(w, pg->loc, pg->image, enc, d);
	if (img && !raw)
		warn_reflectance_image(img, pg->loc, pg->image, d);
	return img;
}

bool build_pattern(world *w, const scene_pigment *pg, uint32_t *node, diag *d)
{
	return pattern_compile(&w->patterns, pg, load_image, w, node, d);
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
