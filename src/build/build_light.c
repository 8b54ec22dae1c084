/* build_light.c - the scene's lights, its environment and its emissive objects as one light set. */
#include "build/build_impl.h"

#include "base/mem.h"

/* Adds an emissive instance as a mesh light over its world-space triangles. */
static bool add_mesh_light(world *w, world_inst *in, vec3 radiance, diag *d, diag_loc loc)
{
	const mesh *m = &in->g->m;
	vec3 *v = mem_alloc((size_t)m->num_triangles * 3, sizeof *v);
	if (!v) {
		diag_error(d, loc, "out of memory");
		return false;
	}
	for (size_t t = 0; t < (size_t)m->num_triangles * 3; t++) {
		vec3 p = m->positions[m->indices[t]];
		v[t] = in->identity ? p : d3v(xform_point(&in->xf, v3_to_d3(p)));
	}
	light l;
	bool ok = light_mesh_init(&l, v, m->num_triangles, radiance);
	mem_free(v);
	if (!ok)
		return true; /* zero area: it emits nothing */
	in->light = (int)w->lights.count;
	if (!light_set_add(&w->lights, &l)) {
		light_free(&l);
		diag_error(d, loc, "out of memory");
		return false;
	}
	return true;
}

/* The distance law of a light_source (grammar/README.md, "Lights"): circe's `intensity` is the
 * physical inverse square; without it, POV-Ray's: none, or its fade. Parallel and cylinder lights
 * never fall off as 1 / d^2. */
static void set_distance_law(light *l, const scene_light *sl)
{
	bool fades = sl->fade_distance > 0 && sl->fade_power > 0;
	bool beam = sl->kind == SCENE_LIGHT_PARALLEL || sl->kind == SCENE_LIGHT_CYLINDER;
	l->falloff = fades ? LIGHT_FALLOFF_FADE
		     : sl->has_intensity && !beam ? LIGHT_FALLOFF_INVERSE_SQUARE
		     : LIGHT_FALLOFF_NONE;
	l->fade_distance = (float)sl->fade_distance;
	l->fade_power = (float)sl->fade_power;
}

/* POV-Ray's brightness: its diffuse has no 1 / pi (a surface of pigment P under a light of colour
 * C at normal incidence shows P * diffuse * C), circe's Lambert is albedo / pi; so a POV-Ray light
 * (no circe `intensity`) delivers pi * C to make the two images alike. A light with `intensity`
 * keeps its physical meaning. (A sphere light is circe's own emitter: never scaled.) */
#define BUILD_POV_LIGHT_SCALE 3.14159265358979323846f

/* The scene's light_source as circe's light. */
static light scene_light_to_light(const scene_light *sl)
{
	float k = sl->has_intensity || sl->kind == SCENE_LIGHT_SPHERE ? 1.0f : BUILD_POV_LIGHT_SCALE;
	/* a negative light's magnitude: its sign is world.light_sign's */
	vec3 mag = v3(fabsf(sl->color.x), fabsf(sl->color.y), fabsf(sl->color.z));
	vec3 c = v3_scale(mag, (float)sl->intensity * k);
	vec3 pos = d3v(sl->position), at = d3v(sl->point_at);
	light l;
	switch (sl->kind) {
	case SCENE_LIGHT_POINT:
		l = light_point(pos, c);
		break;
	case SCENE_LIGHT_SPHERE:
		return light_sphere(pos, (float)sl->radius, c); /* an emitter: always physical */
	case SCENE_LIGHT_SPOT:
		l = light_spot(pos, at, c, (float)sl->cone_deg, (float)sl->falloff_deg);
		break;
	case SCENE_LIGHT_CYLINDER:
		l = light_cylinder(pos, at, c, (float)sl->cyl_radius, (float)sl->cyl_falloff, 0.0f);
		break;
	default:
		l = light_parallel(pos, at, c);
		break;
	}
	set_distance_law(&l, sl);
	l.tightness = (float)sl->tightness;
	l.shadowless = sl->shadowless;
	l.no_media = sl->no_media;
	if (sl->area)
		light_set_area(&l, d3v(sl->axis1), d3v(sl->axis2), sl->circular, sl->orient);
	return l;
}

/* The scene's fogs as the integrator's (fog.h). */
static void build_fogs(world *w, const scene *sc, diag *d)
{
	w->n_fogs = 0;
	for (const scene_fog *f = sc->fogs; f; f = f->next) {
		if (w->n_fogs == RENDER_MAX_FOGS) {
			diag_warning(d, f->loc, "more than %d fogs: this one and those before it are not rendered",
				     RENDER_MAX_FOGS);
			break;
		}
		w->fogs[w->n_fogs++] = (render_fog){.ground = f->type == SCENE_FOG_GROUND,
						    .distance = (float)f->distance,
						    .color = f->color,
						    .offset = (float)f->offset,
						    .alt = (float)f->alt,
						    .up = d3v(f->up)};
	}
}

/* POV-Ray's light_group and projected_through: w->reach and the groups' table, when some light
 * or object has either. A light's projected_through objects are a scene of their own
 * (build_object_scene), tessellated as the render's objects. */
bool build_reach(world *w, const scene *sc, const world_options *opt, diag *d)
{
	size_t n = scene_n_lights(sc), ng = sc->light_groups.len;
	bool any = ng > 0;
	for (size_t i = 0; i < n && !any; i++)
		any = scene_light_at(sc, i)->n_projected > 0;
	if (!any)
		return true;
	w->reach = mem_calloc(n ? n : 1, sizeof *w->reach);
	w->group_parent = mem_calloc(ng ? ng : 1, sizeof *w->group_parent);
	w->group_global = mem_calloc(ng ? ng : 1, sizeof *w->group_global);
	if (!w->reach || !w->group_parent || !w->group_global) {
		diag_error(d, diag_noloc(), "out of memory");
		return false;
	}
	w->n_reach = n, w->n_groups = ng;
	for (size_t g = 0; g < ng; g++) {
		const scene_light_group *lg = &VECBUF_AT(&sc->light_groups, scene_light_group, g);
		w->group_parent[g] = lg->parent;
		w->group_global[g] = lg->global_lights;
	}
	for (size_t i = 0; i < n; i++) {
		const scene_light *sl = scene_light_at(sc, i);
		w->reach[i].group = sl->group;
		if (!sl->n_projected)
			continue;
		scene *ps = w->reach[i].through_sc = build_object_scene(sc, sl->projected, sl->n_projected);
		if (!ps) {
			diag_error(d, sl->loc, "out of memory");
			return false;
		}
		/* Quietly: the render builds (and warns about) the same records. A failure is built
		 * again aloud, for its messages. */
		diag quiet;
		diag_init(&quiet, NULL);
		bool valid = scene_validate(ps, &quiet) == 0;
		w->reach[i].through = valid ? world_build(ps, opt, &quiet) : NULL;
		diag_free(&quiet);
		if (!w->reach[i].through) {
			if (valid)
				world_free(world_build(ps, opt, d));
			else
				scene_validate(ps, d);
			diag_error(d, sl->loc, "the light's projected_through object cannot be built (above)");
			return false;
		}
	}
	return true;
}

/* POV-Ray's negative lights: the signs of the light_sources' colours (world.light_sign), when one
 * is negative. */
static bool build_signs(world *w, const scene *sc, diag *d)
{
	size_t n = scene_n_lights(sc);
	bool any = false;
	for (size_t i = 0; i < n && !any; i++) {
		vec3 c = scene_light_at(sc, i)->color;
		any = c.x < 0 || c.y < 0 || c.z < 0;
	}
	if (!any)
		return true;
	if (!(w->light_sign = mem_alloc(n, sizeof *w->light_sign))) {
		diag_error(d, diag_noloc(), "out of memory");
		return false;
	}
	w->n_light_sign = n;
	for (size_t i = 0; i < n; i++) {
		vec3 c = scene_light_at(sc, i)->color;
		w->light_sign[i] = v3(c.x < 0 ? -1.0f : 1.0f, c.y < 0 ? -1.0f : 1.0f, c.z < 0 ? -1.0f : 1.0f);
	}
	return true;
}

bool build_lights(world *w, const scene *sc, diag *d)
{
	build_fogs(w, sc, d);
	light_set_init(&w->lights);
	if (!build_signs(w, sc, d))
		return false;
	for (size_t i = 0; i < scene_n_lights(sc); i++) {
		const scene_light *sl = scene_light_at(sc, i);
		light l = scene_light_to_light(sl);
		if (!light_set_add(&w->lights, &l)) {
			diag_error(d, sl->loc, "out of memory");
			return false;
		}
	}
	if (sc->has_background) {
		light l = light_background(sc->background);
		l.seen_only = !scene_background_lights(sc);
		if (!light_set_add(&w->lights, &l)) {
			diag_error(d, sc->background_loc, "out of memory");
			return false;
		}
	}
	if (sc->has_sky_sphere && sc->sky_sphere.n_pigments) {
		const scene_sky_sphere *sky = &sc->sky_sphere;
		xform rot = xform_rotate(sky->rotate_deg);
		light l;
		if (!build_sky_pigments(w, sky, d))
			return false;
		bool ok = light_envmap_init(&l, w->env_rgb, WORLD_SKY_WIDTH, WORLD_SKY_HEIGHT, (float)sky->intensity, &rot);
		l.seen_only = !scene_sky_sphere_lights(sc);
		if (!ok || !light_set_add(&w->lights, &l)) {
			diag_error(d, sky->loc, "out of memory");
			return false;
		}
	} else if (sc->has_sky_sphere) {
		const scene_sky_sphere *sky = &sc->sky_sphere;
		const image *img = world_image(w, sky->loc, sky->image, IMAGE_SRGB, d);
		if (!img)
			return false;
		size_t n = (size_t)img->width * (size_t)img->height;
		w->env_rgb = mem_alloc(n, 3 * sizeof(float));
		if (!w->env_rgb) {
			diag_error(d, sky->loc, "out of memory");
			return false;
		}
		size_t clamped = clamp_texels(img, SCENE_COLOR_RADIANCE, w->env_rgb);
		if (clamped)
			diag_warning(d, sky->loc, "%zu texels of the environment are outside [0, inf), the range of a "
						  "radiance (negative, NaN or infinite): clamped, a non-finite one to 0",
				     clamped);
		xform rot = xform_rotate(sky->rotate_deg);
		light l;
		if (!light_envmap_init(&l, w->env_rgb, img->width, img->height, (float)sky->intensity, &rot) ||
		    !light_set_add(&w->lights, &l)) {
			diag_error(d, sky->loc, "out of memory");
			return false;
		}
	}
	for (size_t i = 0; i < w->n_insts; i++) {
		const scene_object *o = scene_object_at(sc, w->insts[i].object);
		if (o->material && v3_max_comp(o->material->emission) > 0.0f && !w->insts[i].hidden &&
		    !add_mesh_light(w, &w->insts[i], o->material->emission, d, o->loc))
			return false;
	}
	/* The scene's own radius, however small: a floor in absolute units would weigh infinite and
	 * parallel lights against the others differently at different scales. */
	if (!light_set_finish(&w->lights, w->radius)) {
		diag_error(d, diag_noloc(), "out of memory");
		return false;
	}
	return true;
}
