/* material.c - material names, colour ranges and the SSS block defaults (the physics of SSS media
 * is src/sss/medium.c's). */
#include "scene/material.h"

#include <math.h>
#include <string.h>

const char *scene_material_kind_name(scene_material_kind k)
{
	static const char *const names[MAT_KIND_COUNT] = {"diffuse", "texture", "emission",
							  "skin",    "wax",     "marble"};
	return (unsigned)k < MAT_KIND_COUNT ? names[k] : "?";
}

static float clamp_channel(float x, scene_color_use use)
{
	if (!(x > 0.0f) || !isfinite(x)) /* negative, zero, NaN, or +inf (no radiance is infinite) */
		return 0.0f;
	return use == SCENE_COLOR_REFLECTANCE && x > 1.0f ? 1.0f : x;
}

bool scene_color_clamp(vec3 *c, scene_color_use use)
{
	vec3 k = v3(clamp_channel(c->x, use), clamp_channel(c->y, use), clamp_channel(c->z, use));
	bool changed = k.x != c->x || k.y != c->y || k.z != c->z; /* a NaN differs; -0 is 0 */
	*c = k;
	return changed;
}

const char *scene_color_range_name(scene_color_use use)
{
	return use == SCENE_COLOR_REFLECTANCE ? "[0, 1]" : "[0, inf)";
}

void scene_finish_defaults(scene_finish *f)
{
	*f = (scene_finish){.brilliance = 1.0f, .phong_size = 40.0f, .refl_falloff = 1.0f};
}

static bool v3_eq(vec3 a, vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

bool scene_finish_is_default(const scene_finish *f)
{
	scene_finish d;
	scene_finish_defaults(&d);
	return f->has_ambient == d.has_ambient && v3_eq(f->emission, d.emission) && f->brilliance == d.brilliance &&
	       f->phong == d.phong && f->phong_size == d.phong_size && f->metallic == d.metallic &&
	       v3_eq(f->refl_min, d.refl_min) && v3_eq(f->refl_max, d.refl_max) && f->refl_falloff == d.refl_falloff &&
	       f->refl_fresnel == d.refl_fresnel && f->refl_metallic == d.refl_metallic &&
	       f->conserve_energy == d.conserve_energy && f->subsurface == d.subsurface;
}

void scene_sss_defaults(scene_material *m)
{
	scene_sss *s = &m->sss;
	memset(s, 0, sizeof *s);
	s->normal_strength = 1.0f;
	s->anisotropy = 0.0f;
	s->method = SSS_METHOD_DEFAULT;
	/* LANGUAGE.md, "Block defaults". */
	switch (m->kind) {
	case MAT_MARBLE:
		s->medium.preset = "marble";
		s->profile = SSS_PROFILE_BURLEY;
		s->ior = 1.5f;
		s->roughness = 0.1f;
		break;
	case MAT_WAX:
		s->medium.albedo = v3(0.95f, 0.78f, 0.45f);
		s->medium.radius_mm = v3(2.0f, 1.2f, 0.6f);
		s->medium.has = SSS_HAS_ALBEDO | SSS_HAS_RADIUS;
		s->profile = SSS_PROFILE_BURLEY;
		s->ior = 1.45f;
		s->roughness = 0.25f;
		break;
	default: /* skin */
		s->medium.preset = "skin1";
		s->profile = SSS_PROFILE_SUM_OF_GAUSSIANS;
		s->ior = 1.4f;
		s->roughness = 0.35f;
		break;
	}
}
