/* material.h - materials of the scene IR, the measured SSS presets and the conversion between the
 * physical form (reduced scattering sigma_s', absorption sigma_a in mm^-1, and eta) and the artist
 * form (diffuse albedo colour, scattering distance in mm). Every SSS material carries both forms,
 * so every SSS method (circle, disk, volume) can render it. */
#ifndef CIRCE_SCENE_MATERIAL_H
#define CIRCE_SCENE_MATERIAL_H

#include "base/diag.h"
#include "base/vec.h"

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

typedef enum scene_sss_profile {
	PROFILE_GAUSSIAN,
	PROFILE_SUM_OF_GAUSSIANS,
	PROFILE_BURLEY,
	PROFILE_DIPOLE
} scene_sss_profile;

typedef enum scene_sss_method {
	SSS_METHOD_DEFAULT, /* whatever the command line says */
	SSS_METHOD_CIRCLE,
	SSS_METHOD_FULLCIRCLE,
	SSS_METHOD_DISK,
	SSS_METHOD_VOLUME
} scene_sss_method;

/* Which form the user wrote; the other is derived. */
typedef enum scene_sss_form { SSS_FORM_DEFAULT, SSS_FORM_PHYSICAL, SSS_FORM_ARTIST } scene_sss_form;

typedef struct scene_sss {
	const char *preset; /* NULL when none */
	scene_sss_form given;
	diag_loc physical_loc, artist_loc; /* where each form was first given */
	vec3 sigma_s_per_mm; /* reduced scattering coefficient sigma_s' */
	vec3 sigma_a_per_mm;
	vec3 albedo; /* diffuse (multiple-scattering) reflectance Rd */
	vec3 radius_mm; /* diffuse mean free path l_d = 1 / sigma_tr */
	const char *albedo_image; /* NULL: albedo is constant */
	float ior, roughness, anisotropy;
	const char *normal_map;
	float normal_strength;
	scene_sss_profile profile;
	scene_sss_method method;
	const char *group; /* NULL: the object alone */
} scene_sss;

typedef struct scene_material {
	diag_loc loc;
	scene_material_kind kind;
	uint32_t id;
	const char *name; /* the #declare name, or NULL */
	vec3 color; /* diffuse / texture albedo */
	const char *image; /* albedo texture path (resolved against the naming file's folder), or NULL */
	float diffuse, specular, roughness; /* texture finish; diffuse material: 1, 0, 1 */
	float ior; /* texture interior { ior }; 0 when none */
	vec3 emission; /* any kind may emit */
	scene_sss sss; /* MAT_SKIN, MAT_WAX, MAT_MARBLE */
	struct scene_material *next;
} scene_material;

const char *scene_material_kind_name(scene_material_kind k);
const char *scene_sss_profile_name(scene_sss_profile p);
const char *scene_sss_method_name(scene_sss_method m);

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

/* Jensen et al. 2001 measured coefficients; false when the name is not a preset. */
typedef struct scene_sss_preset {
	const char *name;
	float sigma_s_per_mm[3], sigma_a_per_mm[3];
	float eta;
} scene_sss_preset;
const scene_sss_preset *scene_sss_preset_find(const char *name);
/* The NULL-terminated list of preset names, for error messages. */
extern const scene_sss_preset scene_sss_presets[];
extern const int scene_sss_n_presets;

/* d'Eon & Luebke 2007's six-Gaussian fit of the three-layer skin profile. */
enum { SCENE_SKIN_GAUSSIANS = 6 };
extern const float scene_skin_gaussian_variance_mm2[SCENE_SKIN_GAUSSIANS];
extern const float scene_skin_gaussian_weight[SCENE_SKIN_GAUSSIANS][3];

/* Sets the block defaults of LANGUAGE.md (skin, wax, marble) into m->sss. */
void scene_sss_defaults(scene_material *m);

/* Physical -> artist, one channel: Jensen et al. 2001 diffuse reflectance Rd of the dipole
 * (their eq. for Rd with A from the diffuse Fresnel of eta), and l_d = 1/sigma_tr. */
void scene_sss_to_artist(double sigma_s, double sigma_a, double eta, double *albedo, double *radius_mm);
/* Artist -> physical, one channel: inverts Rd(alpha') numerically (bisection; Rd is monotone).
 * albedo is clamped into [0, Rd(1)); radius_mm must be > 0. */
void scene_sss_to_physical(double albedo, double radius_mm, double eta, double *sigma_s, double *sigma_a);
/* Fills the form that was not given from the one that was, per channel. */
void scene_sss_derive(scene_sss *s);

#endif
