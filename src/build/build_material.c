/* build_material.c - scene materials to BSDF parameters and textures: the images a scene names,
 * loaded once per world, and their texels checked against the range of their use. */
#include "build/build_impl.h"

#include "base/mem.h"
#include "scene/pigment.h"

#include <string.h>

/* The bytes a texture may take: what the allocator's limit leaves (main sets it to --max-memory,
 * or the machine's memory), 0 when there is no limit. */
static size_t texture_room(void)
{
	size_t limit = mem_limit(), live = mem_live_bytes();
	return !limit ? 0 : limit > live ? limit - live : 1;
}

/* The image at path (the language resolved it against the scene's folders), loaded once per
 * world; NULL after reporting an error at loc. One that would not fit in texture_room() is
 * refused from its header's size, before it is decoded. */
const image *world_image(world *w, diag_loc loc, const char *path, image_encoding enc, diag *d)
{
	size_t max_bytes = texture_room();
	char *full = mem_strdup(path);
	if (!full) {
		diag_error(d, loc, "out of memory");
		return NULL;
	}
	for (size_t i = 0; i < w->n_images; i++)
		if (!strcmp(w->image_paths[i], full)) {
			mem_free(full);
			return w->images[i];
		}
	image **imgs = mem_realloc(w->images, w->n_images + 1, sizeof *imgs);
	char **paths = imgs ? mem_realloc(w->image_paths, w->n_images + 1, sizeof *paths) : NULL;
	image *img = paths ? mem_calloc(1, sizeof *img) : NULL;
	if (imgs)
		w->images = imgs;
	if (paths)
		w->image_paths = paths;
	if (!img) {
		mem_free(full);
		diag_error(d, loc, "out of memory");
		return NULL;
	}
	if (!image_load_limited(full, enc, max_bytes, img, d)) {
		diag_note(d, loc, "the image was named here");
		mem_free(img);
		mem_free(full);
		return NULL;
	}
	w->images[w->n_images] = img;
	w->image_paths[w->n_images++] = full;
	return img;
}

/* The number of img's texels outside the range of `use` (a float EXR may hold any number); with
 * rgb non-NULL, every texel's RGB clamped into it (scene_color_clamp) is written there. */
size_t clamp_texels(const image *img, scene_color_use use, float *rgb)
{
	size_t n = (size_t)img->width * (size_t)img->height, clamped = 0;
	for (size_t i = 0; i < n; i++) {
		vec3 texel = v3(img->rgba[i * 4], img->rgba[i * 4 + 1], img->rgba[i * 4 + 2]);
		clamped += scene_color_clamp(&texel, use);
		if (rgb)
			rgb[i * 3] = texel.x, rgb[i * 3 + 1] = texel.y, rgb[i * 3 + 2] = texel.z;
	}
	return clamped;
}

/* An albedo texture's texels outside [0, 1]: the shade hook clamps each lookup, and this says so
 * once, at the material. */
void warn_reflectance_image(const image *img, diag_loc loc, const char *path, diag *d)
{
	size_t clamped = clamp_texels(img, SCENE_COLOR_REFLECTANCE, NULL);
	if (clamped)
		diag_warning(d, loc, "%zu texels of '%s' are outside [0, 1], the range of a reflectance: clamped, a "
				     "non-finite one to 0",
			     clamped, path);
}

/* BSDF parameters and textures of a scene material. */
bool build_material(world *w, size_t k, const scene *sc, const world_options *opt,
			   const scene_material *sm, diag *d)
{
	world_material *wm = &w->materials[k];
	switch (sm->kind) {
	case MAT_DIFFUSE:
		w->bsdfs[k] = bsdf_diffuse(sm->color);
		break;
	case MAT_TEXTURE:
		w->bsdfs[k] = bsdf_pov_finish(sm->color, sm->diffuse, sm->specular, sm->roughness);
		break;
	case MAT_EMISSION:
		w->bsdfs[k] = bsdf_diffuse(v3s(0.0f));
		break;
	case MAT_SKIN:
	case MAT_WAX:
	case MAT_MARBLE:
		/* The coat's reflection; its diffuse interior is replaced by the BSSRDF in the
		 * integrator, but keeps the albedo for the AOV and the choice of lobe. */
		if (!build_sss(w, k, sc, opt, sm, d))
			return false;
		w->bsdfs[k] = bsdf_coat(w->sss[k].albedo, sm->sss.ior, sm->sss.roughness);
		break;
	default:
		w->bsdfs[k] = bsdf_diffuse(v3s(WORLD_DEFAULT_GREY));
		break;
	}
	bool sss = sm->kind == MAT_SKIN || sm->kind == MAT_WAX || sm->kind == MAT_MARBLE;
	const scene_pigment *pig = sss && sm->sss.pigment ? sm->sss.pigment : sm->pigment;
	if (pig) {
		if (!build_pattern(w, pig, &wm->pattern, d))
			return false;
		wm->has_pattern = true;
		wm->pattern_uv = pig->uv_mapping;
		wm->pattern_kd = sm->kind == MAT_TEXTURE ? sm->diffuse : 1.0f;
	}
	if (sm->normal) {
		if (!build_pattern(w, sm->normal, &wm->normal, d))
			return false;
		wm->has_normal = true;
		wm->normal_uv = sm->normal->uv_mapping;
	}
	const char *albedo = sss ? sm->sss.albedo_image : sm->image;
	if (albedo && !(wm->albedo = world_image(w, sm->loc, albedo, IMAGE_SRGB, d)))
		return false;
	if (albedo)
		warn_reflectance_image(wm->albedo, sm->loc, albedo, d);
	if (sss && sm->sss.normal_map) {
		if (!(wm->normal_map =
			  world_image(w, sm->loc, sm->sss.normal_map, IMAGE_RAW, d)))
			return false;
		wm->normal_strength = sm->sss.normal_strength;
	}
	return true;
}
