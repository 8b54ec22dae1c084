/* build_material.c - scene materials to BSDF parameters and textures: the images a scene names,
 * loaded once per world, and their texels checked against the range of their use. */
#include "build/build_impl.h"

#include "base/mem.h"
#include "render/bsdf_pov.h"
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
	/* The cache's key is the path and the encoding: one file read as colour and as data (an
	 * image_map and a bump_map of it) is two images. */
	size_t n = strlen(path);
	char *full = mem_alloc(n + 3, 1);
	if (!full) {
		diag_error(d, loc, "out of memory");
		return NULL;
	}
	memcpy(full, path, n);
	full[n] = '\x1f', full[n + 1] = (char)('0' + (int)enc), full[n + 2] = '\0';
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
	if (!image_load_limited(path, enc, max_bytes, img, d)) {
		diag_note(d, loc, "the image was named here");
		mem_free(img);
		mem_free(full);
		return NULL;
	}
	/* Colour into POV-Ray's working space (scene/gamma.c): linear^(1/G), as its Parse_Image */
	double g = w->working_gamma;
	if (enc == IMAGE_SRGB && g > 0.0 && g != 1.0) {
		size_t n = (size_t)img->width * (size_t)img->height;
		for (size_t i = 0; i < n; i++)
			for (int c = 0; c < 3; c++) {
				float *v = &img->rgba[i * 4 + (size_t)c];
				*v = *v > 0.0f ? (float)pow(*v, 1.0 / g) : *v;
			}
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

/* The Fresnel reflection's ior when the texture has no interior: POV-Ray refuses the scene
 * ("fresnel reflection used with no interior"); circe warns and takes glass's. */
#define BUILD_FRESNEL_DEFAULT_IOR 1.5f

/* POV-Ray 3.7's default ambient (texture.cpp Create_Finish). */
#define BUILD_POV_DEFAULT_AMBIENT 0.1f

/* A texture's POV-Ray finish as BSDF_POV's spec (the mapping: bsdf_pov.h). The ambient, the
 * implicit 0.1 too, glows ambient * ambient_light * pigment as POV-Ray adds it, unless the scene
 * has radiosity, under which POV-Ray 3.7 drops it (trace.cpp ComputeLightedTexture); the implicit
 * one not under circe's own environment either (scene_ambient_glows). */
static void pov_finish_spec(const scene *sc, const scene_material *sm, bsdf_pov_finish_spec *out, diag *d)
{
	const scene_finish *f = &sm->finish;
	/* POV-Ray's brilliance b lights by Kd cos^b (trace.cpp ComputeDiffuseColour), which reflects
	 * 2 / (b + 1) of a Lambert surface's energy, the factor its `diffuse albedo` undoes
	 * (parstxtr.cpp Parse_Finish: Diffuse *= (b + 1) / 2): paths carry Lambert's lobe (reciprocal,
	 * energy-conserving) at that energy, light sources see POV-Ray's cos^b (bsdf_pov.h). */
	float b = f->brilliance;
	bool bright = b != 1.0f && b >= 0.0f;
	float bril = bright && !f->diffuse_albedo ? 2.0f / (b + 1.0f) : 1.0f;
	*out = (bsdf_pov_finish_spec){.diffuse = sm->diffuse * bril,
				      .brilliance_less_1 = bright ? b - 1.0f : 0.0f,
				      .specular = sm->specular,
				      .roughness = sm->roughness,
				      .phong = f->phong,
				      .phong_size = f->phong_size,
				      .metallic = f->metallic,
				      .refl_min = f->refl_min,
				      .refl_max = f->refl_max,
				      .refl_falloff = f->refl_falloff,
				      .refl_metallic = f->refl_metallic,
				      .glow = f->emission};
	if (scene_ambient_glows(sc, f->has_ambient))
		out->glow = v3_add(out->glow, v3_mul(f->has_ambient ? f->ambient : v3s(BUILD_POV_DEFAULT_AMBIENT),
						     sc->global.ambient_light));
	if (f->refl_fresnel) {
		out->refl_ior = sm->ior > 0.0f ? sm->ior : BUILD_FRESNEL_DEFAULT_IOR;
		if (!(sm->ior > 0.0f))
			diag_warning(d, sm->loc, "a fresnel reflection without an interior ior: circe takes ior %g",
				     (double)BUILD_FRESNEL_DEFAULT_IOR);
	}
}

/* POV-Ray's filter and transmit on a texture (doc/language.md "Transparency and interiors"): the
 * surface lets pigment * filter + transmit through, a smooth dielectric where the object has an
 * interior, straight through where it has none; its diffuse is scaled by POV-Ray's opacity
 * 1 - filter - transmit (core/render/trace.cpp: att = Opacity(), highlights unscaled). */
static bool palette_clears(const float *tab)
{
	for (int i = 0; tab && i < 256; i++)
		if (tab[i] > 0.0f) /* NaN: not given */
			return true;
	return false;
}

/* Whether an image_map can let light through: outside a `once` image POV-Ray's pigment is clear,
 * `filter all`, `transmit all`, a palette index's filter or transmit, and an alpha channel below 1
 * somewhere (scene/pattern.c image_color) make texels clear. The image is the world's (loaded once:
 * the pattern's compile finds it so). */
static bool image_can_clear(world *w, const scene_pigment *pg, diag *d)
{
	if (pg->filter_all + pg->transmit_all > 0.0f || pg->once || palette_clears(pg->pal_filter) ||
	    palette_clears(pg->pal_transmit))
		return true;
	const image *img = world_image(w, pg->loc, pg->image, IMAGE_SRGB, d);
	size_t n = img ? (size_t)img->width * (size_t)img->height : 0;
	for (size_t i = 0; i < n; i++)
		if (img->rgba[4 * i + 3] < 1.0f)
			return true;
	return false;
}

static bool pigment_can_clear(world *w, const scene_pigment *pg, int depth, diag *d)
{
	if (!pg || depth > SCENE_PIGMENT_MAX_DEPTH || pg->is_normal)
		return false;
	if (pg->kind == SCENE_PAT_PLAIN)
		return pg->color[3] + pg->color[4] > 0.0f;
	if (pg->kind == SCENE_PAT_IMAGE)
		return image_can_clear(w, pg, d);
	for (uint32_t i = 0; i < pg->n_entries; i++) {
		const scene_map_entry *e = &pg->entries[i];
		if (e->pigment ? pigment_can_clear(w, e->pigment, depth + 1, d) : e->color[3] + e->color[4] > 0.0f)
			return true;
	}
	return false;
}

/* A texture whose pattern pigment can let light through somewhere: its transparency is the
 * point's (bsdf_clear.patterned, set at each hit by render/world.c's shade_pattern), the
 * material's own filter and transmit unused (POV-Ray's pigment gives all five channels). */
static bool pattern_clear(world *w, const scene_material *sm, diag *d)
{
	return sm->kind == MAT_TEXTURE && !sm->pov_sss && sm->pigment && pigment_can_clear(w, sm->pigment, 0, d);
}

static void build_clear(world *w, bsdf_params *b, world_material *wm, const scene_material *sm, diag *d)
{
	float f = sm->filter, t = sm->transmit;
	bool patterned = pattern_clear(w, sm, d);
	if (!(f + t > 0.0f) && !patterned)
		return;
	bsdf_clear *c = &b->clear;
	if (patterned) {
		f = t = 0.0f;
		c->patterned = true;
		wm->opaque_diffuse = b->pov.diffuse;
	}
	c->tint = v3_min(v3_add(v3_scale(sm->color, f), v3s(t)), v3s(1.0f));
	/* A finish's own reflection (glass.inc's reflection { 0.1, 1 fresnel }) is the surface's
	 * mirror: the dielectric does not reflect a second time on top of it. */
	const bsdf_pov_finish_spec *fs = &b->pov;
	bool finish_reflects = v3_max_comp(fs->refl_min) > 0.0f || v3_max_comp(fs->refl_max) > 0.0f;
	c->reflect = finish_reflects ? 0.0f : patterned ? 1.0f : fminf(1.0f, f + t);
	b->pov.diffuse *= fmaxf(0.0f, 1.0f - f - t); /* bsdf_pov_set_pigment derives the lobe from it */
	b->pov.glow = v3_scale(b->pov.glow, fmaxf(0.0f, 1.0f - f - t)); /* POV-Ray's emission * att too */
	if (!(sm->ior > 0.0f)) {
		c->kind = BSDF_CLEAR_THIN;
		return;
	}
	c->kind = BSDF_CLEAR_DIELECTRIC;
	c->ior = sm->ior;
	c->fade = (bsdf_fade){.distance = sm->fade_distance, .power = sm->fade_power, .color = sm->fade_color};
}

/* The layers (world_layer) of texture sm into out[0..n), bottom first: its n_layers, or sm alone
 * when it has none; each with its own finish (its diffuse before the point's opacity), pigment
 * and normal, under the interior's ior; the top one with the material's finish and normal (what
 * later modifiers changed) and, when the material's pigment was replaced since, its pigment.
 * normals false: the layers get none. *has_normal is set when one has. */
static bool fill_layers(world *w, const scene *sc, const scene_material *sm, float ior, bool normals,
			world_layer *out, bool *has_normal, diag *d)
{
	uint32_t n = sm->n_layers ? sm->n_layers : 1;
	bool replaced = !sm->n_layers || !sm->pigment || sm->pigment->kind != SCENE_PAT_LAYERS;
	for (uint32_t i = 0; i < n; i++) {
		world_layer *l = &out[i];
		bool top = i + 1 == n;
		scene_material fin = top ? *sm : *sm->layers[i]; /* the interior is the object's */
		fin.ior = ior;
		pov_finish_spec(sc, &fin, &l->finish, d);
		const scene_material *pig = top && replaced ? sm : sm->layers[i];
		const scene_pigment *nrm = !normals ? NULL : top ? sm->normal : sm->layers[i]->normal;
		if (pig->pigment) {
			if (!build_pattern(w, pig->pigment, &l->pattern, d))
				return false;
			l->has_pattern = true, l->pattern_uv = pig->pigment->uv_mapping;
		}
		l->color[0] = pig->color.x, l->color[1] = pig->color.y, l->color[2] = pig->color.z;
		l->color[3] = pig->filter, l->color[4] = pig->transmit;
		if (nrm) {
			if (!build_pattern(w, nrm, &l->normal, d))
				return false;
			l->has_normal = true, l->normal_uv = nrm->uv_mapping;
			*has_normal = true;
		}
	}
	return true;
}

/* A layered texture's layers (fill_layers), each lit with its own finish (render/world.c). */
static bool build_layers(world *w, size_t k, const scene *sc, const scene_material *sm, diag *d)
{
	world_material *wm = &w->materials[k];
	uint32_t n = sm->n_layers;
	if (!(wm->layers = mem_calloc(n, sizeof *wm->layers))) {
		diag_error(d, sm->loc, "out of memory");
		return false;
	}
	wm->n_layers = n;
	bool has_normal = false;
	if (!fill_layers(w, sc, sm, sm->ior, true, wm->layers, &has_normal, d))
		return false;
	wm->layers_mix = !has_normal;
	w->bsdfs[k].layered = true;
	return true;
}

/* A patterned texture whose entries include layered textures (scene_material.map_textures): each
 * entry's layers, lit with their own finishes; their normals are the material's (the pattern's
 * normal_map of the entries' normals, lang/stmt.c pattern_texture_normal), shared by every layer
 * of an entry. */
static bool build_map(world *w, size_t k, const scene *sc, const scene_material *sm, diag *d)
{
	world_material *wm = &w->materials[k];
	uint32_t n = sm->n_map_textures;
	if (!(wm->map = mem_calloc(n, sizeof *wm->map))) {
		diag_error(d, sm->loc, "out of memory");
		return false;
	}
	wm->n_map = n;
	for (uint32_t i = 0; i < n; i++) {
		const scene_material *e = sm->map_textures[i];
		if (e->kind != MAT_TEXTURE) /* the parser takes textures only */
			continue;
		world_stack *st = &wm->map[i];
		st->n = e->n_layers ? e->n_layers : 1;
		bool has_normal = false;
		if (!(st->layers = mem_calloc(st->n, sizeof *st->layers))) {
			diag_error(d, sm->loc, "out of memory");
			return false;
		}
		if (!fill_layers(w, sc, e, sm->ior, false, st->layers, &has_normal, d))
			return false;
	}
	w->bsdfs[k].layered = true;
	return true;
}

/* A bound of every colour density pg can give (a map interpolates between its entries). */
static vec3 density_bound(const scene_pigment *pg, int depth)
{
	if (pg->kind == SCENE_PAT_PLAIN)
		return v3_max(v3(pg->color[0], pg->color[1], pg->color[2]), v3s(0.0f));
	if (!pg->n_entries || depth > SCENE_PIGMENT_MAX_DEPTH)
		return v3s(1.0f); /* an image's texels, the default map: in [0, 1] */
	vec3 b = v3s(0.0f);
	for (uint32_t i = 0; i < pg->n_entries; i++) {
		const scene_map_entry *e = &pg->entries[i];
		b = v3_max(b, e->pigment ? density_bound(e->pigment, depth + 1) : v3(e->color[0], e->color[1], e->color[2]));
	}
	return b;
}

static bool fill_media(world *w, const scene_material *sm, render_media *md, diag *d);

/* The interior's media of material k as the integrator's (render/media.h): coefficients, the
 * densities compiled as patterns, their bounds and the majorant. */
static bool build_media(world *w, size_t k, const scene_material *sm, diag *d)
{
	if (!sm->n_media)
		return true;
	if (w->bsdfs[k].clear.kind != BSDF_CLEAR_DIELECTRIC) {
		diag_warning(d, sm->media[0].loc, "media in an object that is not transparent: nothing reaches it (give "
						  "the container a pigment with filter or transmit, e.g. rgbt 1)");
		return true;
	}
	if (!fill_media(w, sm, &w->media[k], d))
		return false;
	w->media_of[k] = &w->media[k];
	return true;
}

/* POV-Ray's atmospheric media (scene.atmosphere) as w->atmosphere. */
bool build_atmosphere(world *w, const scene *sc, diag *d)
{
	if (!sc->atmosphere)
		return true;
	if (!fill_media(w, sc->atmosphere, &w->atmosphere, d))
		return false;
	w->has_atmosphere = true;
	return true;
}

/* The media of sm as the integrator's md. */
static bool fill_media(world *w, const scene_material *sm, render_media *md, diag *d)
{
	md->n = sm->n_media < RENDER_MEDIA_MAX ? sm->n_media : RENDER_MEDIA_MAX;
	for (uint32_t i = 0; i < md->n; i++) {
		const scene_media *s = &sm->media[i];
		render_medium *m = &md->m[i];
		*m = (render_medium){.absorption = s->absorption, .emission = s->emission, .extinction = s->extinction,
				     .phase = s->scattering_type ? (render_phase)s->scattering_type : RENDER_PHASE_ISOTROPIC,
				     .g = s->eccentricity, .density_max = v3s(1.0f)};
		if (s->scattering_type)
			m->scattering = s->scattering;
		for (uint32_t j = 0; j < s->n_density && j < RENDER_MEDIUM_MAX_DENSITIES; j++) {
			if (!build_pattern(w, s->density[j], &m->density[j], d))
				return false;
			m->density_max = v3_mul(m->density_max, density_bound(s->density[j], 0));
			m->n_density++;
		}
	}
	render_media_finish(md);
	w->has_media = true;
	return true;
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
		w->bsdfs[k] = bsdf_pov(&(bsdf_pov_finish_spec){0}, v3s(0.0f)); /* filled below */
		pov_finish_spec(sc, sm, &w->bsdfs[k].pov, d);
		if (sm->pov_sss) { /* POV-Ray's subsurface: the BSSRDF is the diffuse term (trace.cpp) */
			w->bsdfs[k].pov.sss_diffuse = w->bsdfs[k].pov.diffuse;
			w->bsdfs[k].pov.diffuse = 0.0f;
		}
		break; /* its transparency once its pigment is built (below) */
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
	if (sm->kind == MAT_TEXTURE) { /* after the pigment: its images are the world's (image_can_clear) */
		build_clear(w, &w->bsdfs[k], wm, sm, d);
		bsdf_pov_set_pigment(&w->bsdfs[k], sm->color);
	}
	if (sm->kind == MAT_TEXTURE && sm->n_layers && !sm->pov_sss && !build_layers(w, k, sc, sm, d))
		return false;
	if (sm->kind == MAT_TEXTURE && !sm->n_layers && sm->n_map_textures && !sm->pov_sss && wm->has_pattern &&
	    sm->pigment->n_entries == sm->n_map_textures && !build_map(w, k, sc, sm, d))
		return false;
	/* A POV-Ray subsurface texture's medium is derived from its pigment (its pattern's mean). */
	if (sm->pov_sss && !build_sss(w, k, sc, opt, sm, d))
		return false;
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
	return build_media(w, k, sm, d);
}
