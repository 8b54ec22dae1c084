/* finish.h - POV-Ray's finish beyond diffuse/specular/roughness, and POV-Ray's fog, in the scene
 * IR as the scene wrote them (POV-Ray 3.7's meanings and defaults, texture.cpp Create_Finish);
 * src/render/bsdf_pov.c maps a finish onto circe's lobes (doc/language.md, "Finishes"), and
 * src/render/fog.c applies a fog along rays. */
#ifndef CIRCE_SCENE_FINISH_H
#define CIRCE_SCENE_FINISH_H

#include "base/diag.h"
#include "base/vec.h"

#include <stdbool.h>

typedef struct scene_finish {
	vec3 ambient;	  /* an explicit `ambient`: glows ambient * pigment * ambient_light */
	bool has_ambient; /* POV-Ray's implicit 0.1 is what circe's global illumination replaces */
	vec3 emission;	  /* glows emission * pigment */
	float brilliance; /* 1: Lambert; another: a Lambert lobe of the energy of POV-Ray's cos^b (build) */
	bool diffuse_albedo; /* `diffuse albedo`: POV-Ray's (b + 1) / 2, which undoes that energy */
	float phong, phong_size; /* POV-Ray's phong highlight and its exponent on the reflected vector */
	float metallic;		 /* highlights tinted by the pigment, in [0, 1] */
	vec3 refl_min, refl_max; /* reflection at normal and at grazing incidence */
	float refl_falloff;	 /* the exponent of (1 - cos) between them */
	bool refl_fresnel;	 /* the Fresnel of the interior's ior between them instead */
	float refl_metallic;	 /* reflection tinted by the pigment, in [0, 1] */
	bool conserve_energy;	 /* recorded: circe's lobes always conserve energy */
	/* subsurface { translucency T }: POV-Ray's SSS (doc/language.md "POV-Ray's subsurface"),
	 * rendered by circle tracing when the scene's global_settings has its subsurface block. */
	bool subsurface;
	vec3 translucency_mm; /* 1 / sigma_s' per channel, mm, > 0 */
	diag_loc subsurface_loc;
} scene_finish;

/* POV-Ray 3.7's finish defaults (no reflection, phong_size 40, falloff 1, brilliance 1). */
void scene_finish_defaults(scene_finish *f);
/* True when f is scene_finish_defaults' (the IR dump leaves such a finish out). */
bool scene_finish_is_default(const scene_finish *f);

/* fog { fog_type 1|2 distance D color C [fog_offset fog_alt up] } (POV-Ray 3.7 trace.cpp,
 * ComputeFog): a ray of length t keeps exp(-t / distance) of what it sees and gains the rest as
 * the fog's colour; a ground fog's density is 1 below offset and 1 / (1 + h^2) above it, h the
 * height over offset in units of alt along up. */
typedef enum scene_fog_type { SCENE_FOG_CONSTANT = 1, SCENE_FOG_GROUND = 2 } scene_fog_type;

typedef struct scene_fog {
	diag_loc loc;
	scene_fog_type type;
	double distance;
	vec3 color;
	double offset, alt; /* ground fog: default 0 and 0 (alt 0: density 1 below offset, 0 above) */
	dvec3 up;	    /* ground fog: default y, normalised */
	struct scene_fog *next;
} scene_fog;

#endif
