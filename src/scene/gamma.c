/* gamma.c - POV-Ray's assumed_gamma emulated on circe's linear colours (doc/language.md,
 * "assumed_gamma"). POV-Ray 3.7 computes in a "working" colour space of gamma G and writes its
 * result r as the linear value r^G (frontend/renderfrontend.h CreateView: a transcoding curve
 * from the working gamma to the display's), so its colour numbers are r^G-encoded. A power law
 * keeps products: (light * pigment)^G = light^G * pigment^G, so raising every colour of the
 * scene to c^G once the parse ends gives circe's linear pipeline POV-Ray's look (the sums of
 * several lights, the cosine of a diffuse surface and the interpolation of colour maps stay
 * linear in circe, so the match is close, not exact). Images are left alone: POV-Ray 3.7
 * decodes them by their file's gamma and re-encodes them into the working space
 * (parser/parstxtr.cpp Parse_Image), so what they mean in light is their decoded value, which
 * is what circe reads. */
#include "scene/scene.h"

#include "scene/pigment.h"

#include <math.h>
#include <stdint.h>

/* A small set of addresses (pigment nodes, their entry arrays, media, materials): the trees
 * are shared, and each colour must be raised once. Open addressing, grown at half full. */
typedef struct ptr_set {
	const void **slot;
	size_t cap, len;
	bool failed; /* out of memory: the pass stops */
} ptr_set;

static size_t ptr_hash(const void *p, size_t cap)
{
	uint64_t h = (uint64_t)(uintptr_t)p * 0x9E3779B97F4A7C15ull;
	return (size_t)(h >> 32) & (cap - 1);
}

/* True when p was not in the set (and is now). */
static bool ptr_set_add(ptr_set *s, const void *p)
{
	if (s->failed)
		return false;
	if (2 * (s->len + 1) > s->cap) {
		size_t cap = s->cap ? 2 * s->cap : 64;
		const void **slot = mem_calloc(cap, sizeof *slot);
		if (!slot) {
			s->failed = true;
			return false;
		}
		for (size_t i = 0; i < s->cap; i++)
			if (s->slot[i]) {
				size_t j = ptr_hash(s->slot[i], cap);
				while (slot[j])
					j = (j + 1) & (cap - 1);
				slot[j] = s->slot[i];
			}
		mem_free(s->slot);
		s->slot = slot, s->cap = cap;
	}
	size_t j = ptr_hash(p, s->cap);
	while (s->slot[j]) {
		if (s->slot[j] == p)
			return false;
		j = (j + 1) & (s->cap - 1);
	}
	s->slot[j] = p;
	s->len++;
	return true;
}

typedef struct gamma_pass {
	double g;
	ptr_set seen;
} gamma_pass;

/* c^g, odd in c (a colour the parser did not clamp may be negative: POV-Ray's "negative light"). */
static float gpow(float c, double g)
{
	return c > 0.0f ? (float)pow(c, g) : c < 0.0f ? -(float)pow(-c, g) : 0.0f;
}

static void raise3(vec3 *c, double g) { c->x = gpow(c->x, g), c->y = gpow(c->y, g), c->z = gpow(c->z, g); }

/* Red, green and blue of a five-channel colour; filter and transmit are fractions of light
 * let through, not colours (POV-Ray 3.7 leaves them out of its gamma too). */
static void raise5(float *c, double g)
{
	for (int i = 0; i < 3; i++)
		c[i] = gpow(c[i], g);
}

/* The colours of a pigment tree: plain nodes and the colour entries of maps and block lists.
 * A normal's tree holds slopes and heights, a pigment_pattern's child and a function give
 * values, not colours, and an image is decoded light: none is changed. */
static void raise_pigment(gamma_pass *gp, const scene_pigment *cpg)
{
	if (!cpg || cpg->is_normal || !ptr_set_add(&gp->seen, cpg))
		return;
	scene_pigment *pg = (scene_pigment *)cpg; /* the pass runs once, before anything reads the trees */
	if (pg->kind == SCENE_PAT_PLAIN)
		raise5(pg->color, gp->g);
	if (pg->slope_map || !pg->entries || !ptr_set_add(&gp->seen, pg->entries))
		return;
	scene_map_entry *e = (scene_map_entry *)pg->entries;
	for (uint32_t i = 0; i < pg->n_entries; i++) {
		if (e[i].pigment)
			raise_pigment(gp, e[i].pigment);
		else
			raise5(e[i].color, gp->g);
	}
}

static void raise_media(gamma_pass *gp, const scene_media *cm, uint32_t n)
{
	if (!cm || !ptr_set_add(&gp->seen, cm))
		return;
	scene_media *m = (scene_media *)cm;
	for (uint32_t i = 0; i < n; i++)
		raise3(&m[i].emission, gp->g); /* emitted light; absorption and scattering are coefficients */
}

static void raise_material(gamma_pass *gp, const scene_material *cm)
{
	if (!cm || !ptr_set_add(&gp->seen, cm))
		return;
	scene_material *m = (scene_material *)cm;
	double g = gp->g;
	raise3(&m->color, g);
	raise3(&m->emission, g);
	raise_pigment(gp, m->pigment);
	raise_pigment(gp, m->sss.pigment);
	raise3(&m->finish.ambient, g);
	raise3(&m->finish.emission, g);
	raise3(&m->finish.refl_min, g);
	raise3(&m->finish.refl_max, g);
	raise3(&m->fade_color, g);
	raise_media(gp, m->media, m->n_media);
}

double scene_working_gamma(const scene_global *g, double version)
{
	if (g->assumed_gamma_set)
		return g->assumed_gamma;
	return version < 3.7 ? SCENE_LEGACY_GAMMA : 1.0;
}

bool scene_apply_working_gamma(scene *s, double g)
{
	if (g == 1.0)
		return true;
	gamma_pass gp = {.g = g};
	raise3(&s->global.ambient_light, g);
	if (s->has_background)
		raise3(&s->background, g);
	for (scene_fog *f = s->fogs; f; f = f->next)
		raise3(&f->color, g);
	for (int i = 0; i < s->sky_sphere.n_pigments; i++)
		raise_pigment(&gp, s->sky_sphere.pigments[i]);
	for (size_t i = 0; i < scene_n_lights(s); i++) {
		scene_light *l = &VECBUF_AT(&s->lights, scene_light, i);
		raise3(&l->color, g);
		for (uint32_t k = 0; k < l->n_looks; k++)
			raise_material(&gp, l->looks[k].material);
	}
	for (scene_material *m = s->materials; m; m = m->next)
		raise_material(&gp, m);
	for (size_t i = 0; i < scene_n_objects(s); i++)
		raise_material(&gp, scene_object_at(s, i)->material);
	mem_free(gp.seen.slot);
	return !gp.seen.failed;
}
