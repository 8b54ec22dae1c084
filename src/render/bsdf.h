/* bsdf.h - the reflection models of circe's materials, evaluated in a local shading frame whose
 * +z is the shading normal on the side of the outgoing direction wo (the integrator flips the
 * normal to wo's side, so every model here is two-sided). Directions point away from the surface.
 *   BSDF_DIFFUSE  Lambert: diffuse / pi.
 *   BSDF_PLASTIC  POV-Ray's finish { diffuse Kd specular Ks roughness r }: Kd * pigment / pi plus
 *                 Ks * GGX(alpha) with no Fresnel (POV-Ray's highlight is a plain lobe). POV-Ray's
 *                 roughness r is a Phong/Blinn exponent n = 1/r; the GGX alpha with the same
 *                 highlight width is alpha = sqrt(2 / (n + 2)) (Walter et al. 2007, sec. 5.2).
 *   BSDF_COAT     A rough dielectric coat over a diffuse interior (skin, wax, marble until SSS):
 *                 GGX reflection * F(ior) plus (1 - F(cos_o)) (1 - F(cos_i)) * albedo / pi.
 *   BSDF_SSS_ENTRY The light entering a subsurface material at its entry point x_i (DESIGN.md's f_t
 *                 at x_i): diffuse * (1 - F(cos_i)) / pi, sampled by the cosine lobe; the integrator
 *                 sets diffuse to 1/c, c the normalisation that makes the lobe integrate to 1.
 *   BSDF_POV      POV-Ray's finish { diffuse specular phong metallic reflection } as lobes that
 *                 add (bsdf_pov.h, where they live).
 * GGX uses Smith's height-correlated masking-shadowing (Heitz 2014, eq. 99) and is sampled by its
 * visible normals (Heitz 2018, "Sampling the GGX Distribution of Visible Normals"). */
#ifndef CIRCE_RENDER_BSDF_H
#define CIRCE_RENDER_BSDF_H

#include "base/vec.h"

#include <stdbool.h>

typedef enum bsdf_kind { BSDF_DIFFUSE, BSDF_PLASTIC, BSDF_COAT, BSDF_SSS_ENTRY, BSDF_POV } bsdf_kind;

/* BSDF_POV's finish in POV-Ray's own terms (as scene/finish.h holds it), and what glows. */
typedef struct bsdf_pov_finish_spec {
	float diffuse;		   /* Kd of the Lambert lobe paths carry */
	/* POV-Ray's brilliance b less 1 (0: none, so that a zeroed spec has none). Under another b,
	 * light sources light the diffuse by POV-Ray's Kd' cos^b (bsdf_pov.h), Kd' = diffuse (b + 1) / 2. */
	float brilliance_less_1;
	float specular, roughness; /* Ks, POV-Ray's roughness (the Blinn exponent is 1 / roughness) */
	float phong, phong_size;   /* Kp, the Phong exponent */
	float metallic;		   /* highlights tinted by the pigment */
	vec3 refl_min, refl_max;
	float refl_falloff;
	float refl_ior; /* > 0: Fresnel reflection of this relative ior; 0: the falloff form */
	float refl_metallic;
	vec3 glow; /* ambient * ambient_light + emission: emitted radiance per unit pigment */
	/* > 0 on a POV-Ray subsurface texture: its Kd, with diffuse 0 (no Lambert lobe). The
	 * BSSRDF reflects b->diffuse = pigment * sss_diffuse in its place (integrator.c). */
	float sss_diffuse;
} bsdf_pov_finish_spec;

/* The transparent part of a surface (POV-Ray's filter and transmit, doc/language.md "Transparency
 * and interiors"), beside the lobes of bsdf_kind, which then hold only the opaque part:
 *   BSDF_CLEAR_THIN       straight through (no interior): wi = -wo, weight tint.
 *   BSDF_CLEAR_DIELECTRIC a smooth boundary of index ior (an interior): Fresnel reflection
 *                         weighted by `reflect`, refraction (1 - F) tint; both delta lobes. */
typedef enum bsdf_clear_kind { BSDF_CLEAR_NONE, BSDF_CLEAR_THIN, BSDF_CLEAR_DIELECTRIC } bsdf_clear_kind;

/* POV-Ray's interior fade: the light a path keeps after a distance d inside (bsdf_fade_apply). */
typedef struct bsdf_fade {
	float distance; /* fade_distance, scene units; 0: no fade */
	float power;	/* fade_power; >= 1000: exponential (Beer-Lambert) */
	vec3 color;	/* fade_color, the colour kept at infinite depth, in [0, 1] */
} bsdf_fade;

typedef struct bsdf_clear {
	bsdf_clear_kind kind;
	vec3 tint;     /* the fraction one crossing transmits: pigment * filter + transmit, in [0, 1] */
	float reflect; /* DIELECTRIC: weight of the Fresnel reflection, min(1, filter + transmit) */
	float ior;     /* DIELECTRIC: of the inside (outside is 1) */
	bsdf_fade fade;
	/* The pigment is a pattern whose colours carry filter or transmit (a checker of Clear):
	 * tint and reflect are the point's, set by the shading (render/world.c shade_pattern), where
	 * the built reflect is the factor (0 or 1) on min(1, filter + transmit). */
	bool patterned;
} bsdf_clear;

/* A material's reflection parameters at one shading point (textures already applied). */
typedef struct bsdf_params {
	bsdf_kind kind;
	vec3 diffuse;  /* reflectance of the diffuse part: Kd * pigment, or the coat's interior albedo */
	vec3 specular; /* BSDF_PLASTIC: Ks (as a colour) */
	float alpha;   /* GGX roughness alpha, clamped to [BSDF_MIN_ALPHA, 1] */
	float ior;     /* BSDF_COAT: index of refraction of the coat (outside is 1) */
	vec3 emit;     /* radiance emitted toward every direction (BSDF_POV's ambient and emission) */
	bsdf_pov_finish_spec pov; /* BSDF_POV: the finish */
	vec3 pigment;		  /* BSDF_POV: the pigment at the shading point */
	float pov_scale;	  /* BSDF_POV: <= 1, keeps the lobes' sum at most 1 */
	/* BSDF_POV: multiplies every lobe (1; at a layered texture, the one layer shade() picked:
	 * that layer's weight over the probability of picking it, render/world.c shade_layers) */
	vec3 pov_weight;
	/* BSDF_POV: a Lambert reflectance added to the lobes as it is (not times pov_scale or
	 * pov_weight): at a layered texture, the sum of the layers' diffuse terms that shade()
	 * evaluates exactly rather than by the layer it picks (render/world.c shade_layers); else 0 */
	vec3 pov_layer_diffuse;
	/* A layered texture's material: shade() picks one of its layers by render_hit.u_layer, a
	 * number the integrator draws for it */
	bool layered;
	bsdf_clear clear; /* zero: opaque */
} bsdf_params;

/* Below this GGX's peak is too sharp for float; such surfaces are treated as this rough. */
#define BSDF_MIN_ALPHA 1e-3f

bsdf_params bsdf_diffuse(vec3 albedo);
/* POV-Ray finish: diffuse Kd, specular Ks, roughness r (POV-Ray default 0.05) over pigment. */
bsdf_params bsdf_pov_finish(vec3 pigment, float kd, float ks, float roughness);
/* The coat: interior albedo, ior, roughness used as GGX alpha directly. */
bsdf_params bsdf_coat(vec3 albedo, float ior, float roughness);

/* f(wo, wi) without the cosine; zero unless both directions are above the surface (z > 0).
 * BSDF_POV's includes its highlights of light sources (bsdf_highlights). */
vec3 bsdf_eval(const bsdf_params *b, vec3 wo, vec3 wi);
/* The part of bsdf_eval only light sources show in (POV-Ray's highlights; zero for other kinds):
 * next-event estimation weighs it fully, as no BSDF sample ever finds it. */
vec3 bsdf_highlights(const bsdf_params *b, vec3 wo, vec3 wi);
/* The part of bsdf_highlights that is specular and phong (without brilliance's part): what a
 * POV-Ray shadowless light, a fill light, does not show (trace.cpp gives it no highlights). */
vec3 bsdf_shine(const bsdf_params *b, vec3 wo, vec3 wi);
/* bsdf_eval as a delta light (point, spot, parallel; found by light samples only) sees it:
 * BSDF_POV's without its near-mirror reflection, which in POV-Ray sees no light source. */
vec3 bsdf_eval_delta_light(const bsdf_params *b, vec3 wo, vec3 wi);
/* Solid-angle density of bsdf_sample returning wi. */
float bsdf_pdf(const bsdf_params *b, vec3 wo, vec3 wi);
/* Samples wi given wo (u_lobe chooses the lobe, u the direction). On success *f is the BSDF value
 * (BSDF_POV's without its highlights, which paths never carry: bsdf_pov.h) and *pdf its density; false when the sample falls below the surface or has zero pdf (the pdf
 * then integrates to less than one over the hemisphere: that mass is the failure probability). */
bool bsdf_sample(const bsdf_params *b, vec3 wo, float u_lobe, vec2 u, vec3 *wi, vec3 *f, float *pdf);
/* The colour the albedo AOV records: the diffuse reflectance (plus Ks for plastic), clamped to 1. */
vec3 bsdf_albedo(const bsdf_params *b);

/* Unpolarised Fresnel reflectance of a dielectric seen from outside, cos_i >= 0, eta = ior. */
float bsdf_fresnel_dielectric(float cos_i, float eta);
/* GGX pieces, exposed for tests: the normal distribution D(h) and the visible-normal sample. */
float bsdf_ggx_d(vec3 h, float alpha);
vec3 bsdf_ggx_sample_vndf(vec3 wo, float alpha, vec2 u);
/* GGX reflection without Fresnel, D G2 / (4 cos_o cos_i), and the density of wi under
 * bsdf_ggx_sample_vndf (both directions above the surface). */
float bsdf_ggx_reflection(vec3 wo, vec3 wi, float alpha);
float bsdf_ggx_pdf(vec3 wo, vec3 wi, float alpha);

/* ---- the transparent part (bsdf_clear) ----------------------------------------------------- */

/* The smooth dielectric's delta lobes at wo (local, wo.z > 0), eta = n_behind / n_front (ior when
 * entering, 1 / ior when leaving): with probability *prob the reflection wi = (-wo.x, -wo.y, wo.z),
 * else the refraction by Snell's law (wi.z < 0). u chooses; the choice is proportional to the
 * lobes' weights, so *weight (f cos / pdf) is reflect*F/prob or (1-F) tint/(1-prob). Under total
 * internal reflection F = 1: only the reflection. False only when nothing is carried. */
bool bsdf_dielectric_sample(vec3 wo, float eta, float reflect, vec3 tint, float u, vec3 *wi, vec3 *weight,
			    bool *refracted);
/* The total weight of the delta lobes of b at wo (for choosing them against the opaque lobes):
 * THIN: luminance(tint); DIELECTRIC: reflect F + (1 - F) luminance(tint); NONE: 0. */
float bsdf_clear_weight(const bsdf_params *b, vec3 wo, bool entering);
/* A sample of b's delta lobes (see bsdf_dielectric_sample); THIN: wi = -wo, weight tint. */
bool bsdf_clear_sample(const bsdf_params *b, vec3 wo, bool entering, float u, vec3 *wi, vec3 *weight,
		       bool *refracted);
/* The fraction a straight shadow ray keeps crossing b's surface at cosine cos (either side):
 * tint, times 1 - F(|cos|, ior) for a dielectric (the Fresnel loss of the refracted path it
 * stands for, seen from outside so no total internal reflection darkens it). */
vec3 bsdf_clear_shadow(const bsdf_params *b, float cos);
/* POV-Ray's fade after d units inside (its source, core/render/trace.cpp, ComputeLightedTexture):
 * power >= 1000: exp(-(1 - color) d / distance) per channel; else
 * color + (1 - color) / (1 + (d / distance)^power). 1 when distance or power is 0. */
vec3 bsdf_fade_apply(const bsdf_fade *f, float d);

#endif
