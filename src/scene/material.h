/* material.h - materials of the scene IR. An SSS material keeps its medium as the scene wrote
 * it (a preset, or physical coefficients, or artist colour and radius); src/sss/medium.h owns the
 * presets and derives the other form at build time, so every SSS method (circle, disk, volume)
 * can render it. */
#ifndef CIRCE_SCENE_MATERIAL_H
#define CIRCE_SCENE_MATERIAL_H

#include "base/diag.h"
#include "base/vec.h"
#include "scene/finish.h"
#include "sss/medium.h"

#include <stdbool.h>

typedef enum scene_material_kind {
	MAT_DIFFUSE, /* material { diffuse {...} } */
	MAT_TEXTURE, /* POV-Ray texture { pigment finish }: diffuse + specular */
	MAT_EMISSION, /* material { emission C } alone */
	MAT_SKIN,
	MAT_WAX,
	MAT_MARBLE,
	MAT_KIND_COUNT
} scene_material_kind;

/* An SSS material as the scene wrote it (LANGUAGE.md's skin, wax and marble blocks, their
 * defaults filled in): the medium's parameters stay as written, the build derives the rest
 * (sss_medium_derive). */
typedef struct scene_sss {
	sss_medium_spec medium; /* preset, form, the parameters written (or the block's defaults) */
	diag_loc physical_loc, artist_loc; /* where each form was first given */
	const char *albedo_image; /* NULL: albedo is constant */
	const struct scene_pigment *pigment; /* a POV-Ray pigment as the albedo (scene/pigment.h), or NULL */
	float ior, roughness, anisotropy;
	const char *normal_map;
	float normal_strength;
	sss_profile_kind profile;
	sss_method method;
	const char *group; /* NULL: the object alone */
} scene_sss;

/* POV-Ray's media { } of an interior (doc/language.md "Media"): coefficients per scene unit at
 * density 1, the scattering type (1 isotropic .. 5 Henyey-Greenstein), and the densities whose
 * colours multiply (each a pigment tree: a pattern with its density_map, or one colour). */
enum { SCENE_MEDIA_MAX = 8, SCENE_MEDIA_MAX_DENSITIES = 8 };
typedef struct scene_media {
	diag_loc loc;
	vec3 absorption, emission, scattering;
	int scattering_type; /* 1..5; 0: no scattering block */
	float eccentricity, extinction;
	int method; /* POV-Ray's sampling method, kept for the dump: circe is a path tracer */
	const struct scene_pigment *density[SCENE_MEDIA_MAX_DENSITIES];
	uint32_t n_density;
} scene_media;

typedef struct scene_material {
	diag_loc loc;
	scene_material_kind kind;
	uint32_t id;
	const char *name; /* the #declare name, or NULL */
	vec3 color; /* diffuse / texture albedo */
	const char *image; /* albedo texture path (resolved against the naming file's folder), or NULL */
	const struct scene_pigment *pigment; /* a POV-Ray pigment (scene/pigment.h) beyond one colour, or NULL */
	const struct scene_pigment *normal;  /* a POV-Ray normal { } (a pattern perturbing the normal), or NULL */
	float diffuse, specular, roughness; /* texture finish; diffuse material: 1, 0, 1 */
	scene_finish finish; /* the rest of a texture's POV-Ray finish (scene/finish.h) */
	float ior; /* texture interior { ior }; 0 when none, 1 for an interior without ior */
	/* POV-Ray's transparency (doc/language.md "Transparency and interiors"): the pigment
	 * colour's filter and transmit, each in [0, 1], and the interior's fade. */
	float filter, transmit;
	float fade_distance, fade_power; /* 0: no fade */
	vec3 fade_color;		 /* in [0, 1] */
	const scene_media *media; /* the interior's media, n_media of them (in the arena), or NULL */
	uint32_t n_media;
	vec3 emission; /* any kind may emit */
	scene_sss sss; /* MAT_SKIN, MAT_WAX, MAT_MARBLE, and a pov_sss texture */
	/* A MAT_TEXTURE whose finish has POV-Ray's subsurface in a scene that switches it on
	 * (scene_resolve_pov_sss): its diffuse is the BSSRDF, sss holds ior, profile and method; the
	 * build derives the medium from the pigment and the translucency (sss/medium.h). */
	bool pov_sss;
	/* A layered texture (POV-Ray's texture after a texture): its layers' own records, bottom
	 * first, n_layers >= 2, in the scene's arena; NULL otherwise. The material itself is the top
	 * layer (its finish, normal and interior, which later modifiers change) over the composite
	 * pigment; each layer is lit with its own pigment, finish and normal (doc/language.md
	 * "Layered textures"), the top one with the material's finish and normal. */
	const struct scene_material *const *layers;
	uint32_t n_layers;
	/* A patterned texture (texture_map, checker of textures, material_map) with a layered texture
	 * among its entries: the entries' textures, in the order of its pigment's entries (the
	 * material's pigment is their pigment map), each lit per layer with its own finishes at the
	 * point its entry is evaluated (render/world.c shade_map); NULL otherwise (the first entry's
	 * finish lights every entry). A later pigment drops them. */
	const struct scene_material *const *map_textures;
	uint32_t n_map_textures;
	struct scene_material *next;
} scene_material;

const char *scene_material_kind_name(scene_material_kind k);

/* What a colour of the scene becomes, and so the range physics allows it. POV-Ray accepts any
 * number in a colour (its sombrero sample paints with rgb <-0.5, ...>: "negative light"); a
 * physically based renderer cannot honour a reflectance outside [0, 1] (below 0 it subtracts
 * light, above 1 it creates it: either turns a path's weights and the lobe probabilities
 * meaningless, and its samples NaN) nor a negative radiance. */
typedef enum scene_color_use {
	SCENE_COLOR_REFLECTANCE, /* an albedo (diffuse, pigment): [0, 1] */
	SCENE_COLOR_RADIANCE	 /* emitted light (emission, background): [0, inf) */
} scene_color_use;

/* Clamps each channel of *c into the range of its use (a NaN or an infinity becomes 0: no value
 * is known). True when any channel changed. */
bool scene_color_clamp(vec3 *c, scene_color_use use);
/* "[0, 1]" or "[0, inf)": the range of a use, for messages. */
const char *scene_color_range_name(scene_color_use use);

/* Sets the block defaults of LANGUAGE.md (skin, wax, marble) into m->sss: skin and marble take
 * a preset (skin1, marble), wax an artist albedo and radius. */
void scene_sss_defaults(scene_material *m);

#endif
