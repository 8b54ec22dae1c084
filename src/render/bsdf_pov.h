/* bsdf_pov.h - POV-Ray's finish as lobes of circe's BSDF (bsdf.h's BSDF_POV; the mapping and its
 * reasons are doc/language.md's "Finishes" table):
 *   diffuse    Kd * pigment / pi (Lambert). With lights scaled by pi (build_light.c) a surface
 *              under a light of colour C at normal incidence shows Kd * pigment * C, as POV-Ray's.
 *   brilliance POV-Ray lights the diffuse by Kd' cos^b (trace.cpp ComputeDiffuseColour), which
 *              reflects Kd' 2 / (b + 1): paths carry the Lambert lobe of that energy, Kd =
 *              Kd' 2 / (b + 1), and light sources see POV-Ray's Kd' cos^b, the difference
 *              (Kd' cos^(b-1) - Kd) pigment / pi counted with the highlights (a signed part:
 *              under POV-Ray's lights, delta lights, the sum is POV-Ray's term exactly; under
 *              circe's own lights, weighed by MIS, integrator.c keeps the sum at least 0).
 *   specular   POV-Ray's own highlight of light sources (trace.cpp ComputeSpecularColour):
 *              Ks (N.H)^(1/roughness) added under a light without the cosine diffuse has, so the
 *              BSDF is that / (pi cos_i) under a light scaled by pi. As in POV-Ray it reflects light
 *              sources only: next-event estimation sees it (bsdf_eval), paths never sample or carry
 *              it (bsdf_sample's f and bsdf_pdf leave it out), so neither the sky, nor a glowing or
 *              lit surface shows in it. Its size and peak are POV-Ray's exactly; not reciprocal.
 *   phong      The same for ComputePhongColour: Kp (R.L)^phong_size, R the mirror of the eye.
 *   metallic   Both highlights tinted 1 + m (1 - F(c)) (pigment - 1), F POV-Ray's empirical
 *              Fresnel curve (trace.cpp ComputeMetallic), c = wi.h (phong: c = wi.n, as POV-Ray).
 *   reflection A near-mirror GGX lobe (alpha BSDF_POV_MIRROR_ALPHA), which paths sample and carry
 *              but a point, spot, parallel or POV-Ray area light (a delta light, found by light
 *              samples only) never shows in: POV-Ray's reflection rays see no light source, its
 *              highlights stand for them (bsdf_pov_eval_delta_light; else each such light made
 *              a caustic of fireflies through every mirror and floor reflection). Its weight is
 *              R(c) = f max + (1 - f) min, f = (1 - c)^falloff, or f = Fresnel(c, ior) with
 *              `fresnel` (trace.cpp ComputeReflectivity), tinted like metallic by its own amount.
 *   ambient, emission: no lobe: the radiance b->emit, seen by every ray that hits the surface.
 * The lobes paths carry evaluate at c = wi.h, symmetric in wi and wo (reciprocity). The lobes add,
 * as in POV-Ray; when their sum could reflect more than 1 in some channel (Kd P + Ks' + Kp' + max R,
 * Ks' and Kp' the highlights' albedos at normal incidence), all are scaled by the same factor so
 * that it is 1: the BSDF never creates energy. */
#ifndef CIRCE_RENDER_BSDF_POV_H
#define CIRCE_RENDER_BSDF_POV_H

#include "render/bsdf.h"

/* A mirror's GGX roughness: the sharpest circe's float GGX renders (bsdf.h's floor). */
#define BSDF_POV_MIRROR_ALPHA BSDF_MIN_ALPHA

/* The BSDF of a finish over a pigment (clamped to [0, 1]). */
bsdf_params bsdf_pov(const bsdf_pov_finish_spec *f, vec3 pigment);
/* The same BSDF over another pigment (a texture's texel at the shading point). */
void bsdf_pov_set_pigment(bsdf_params *b, vec3 pigment);

/* A bound of what b's lobes reflect in each channel (at most 1 times pov_weight): its diffuse
 * reflectance, the highlights' albedos at normal incidence, the reflection's largest. */
vec3 bsdf_pov_albedo_bound(const bsdf_params *b);

/* The highlights' albedo per unit Ks or Kp at normal incidence (at most 1): specular of Blinn
 * exponent n = 1 / roughness, phong of exponent phong_size (exposed for tests). */
float bsdf_pov_specular_albedo(float n);
float bsdf_pov_phong_albedo(float p);
/* POV-Ray's empirical metallic Fresnel curve F(cos) in [0, 1] (0 at normal incidence). */
float bsdf_pov_metallic_fresnel(float cos_angle);

/* bsdf.h's verbs for BSDF_POV (bsdf.c dispatches here): eval is every lobe, eval_paths the
 * lobes paths sample and carry (all but the highlights), highlights the rest. */
vec3 bsdf_pov_eval(const bsdf_params *b, vec3 wo, vec3 wi);
vec3 bsdf_pov_eval_paths(const bsdf_params *b, vec3 wo, vec3 wi);
vec3 bsdf_pov_highlights(const bsdf_params *b, vec3 wo, vec3 wi);
/* The specular and phong part of the highlights (not the brilliance's). */
vec3 bsdf_pov_shine(const bsdf_params *b, vec3 wo, vec3 wi);
/* What a delta light shows in: eval without the reflection lobe. */
vec3 bsdf_pov_eval_delta_light(const bsdf_params *b, vec3 wo, vec3 wi);
float bsdf_pov_pdf(const bsdf_params *b, vec3 wo, vec3 wi);
bool bsdf_pov_sample(const bsdf_params *b, vec3 wo, float u_lobe, vec2 u, vec3 *wi);

#endif
