/* bsdf_pov.h - POV-Ray's finish as lobes of circe's BSDF (bsdf.h's BSDF_POV; the mapping and its
 * reasons are doc/language.md's "Finishes" table):
 *   diffuse    Kd * pigment / pi (Lambert). With lights scaled by pi (build_light.c) a surface
 *              under a light of colour C at normal incidence shows Kd * pigment * C, as POV-Ray's.
 *   specular   A GGX lobe without Fresnel (POV-Ray's highlight is a plain lobe). Its Blinn exponent
 *              n = 1 / roughness becomes alpha = sqrt(2 / (n + 2)) (Walter et al. 2007, sec. 5.2: the
 *              same width), its weight 4 alpha^2 Ks = 8 Ks / (n + 2) (capped at Ks... at 1): the
 *              lobe's peak at normal incidence, 1 / (4 pi alpha^2) per unit weight, then equals
 *              POV-Ray's Ks (N.H)^n / pi, so a point light's highlight is as bright as POV-Ray's.
 *   phong      The same with n = 4 phong_size: (R.L)^p falls off with twice the angle of (N.H)^n,
 *              cos(2t)^p ~ exp(-2 p t^2) = exp(-n t^2 / 2) when n = 4 p.
 *   metallic   Both highlights tinted 1 + m (1 - F(c)) (pigment - 1), F POV-Ray's empirical
 *              Fresnel curve (trace.cpp ComputeMetallic), c = wi.h.
 *   reflection A near-mirror GGX lobe (alpha BSDF_POV_MIRROR_ALPHA) of weight
 *              R(c) = f max + (1 - f) min, f = (1 - c)^falloff, or f = Fresnel(c, ior) with
 *              `fresnel` (trace.cpp ComputeReflectivity), tinted like metallic by its own amount.
 *   ambient, emission: no lobe: the radiance b->emit, seen by every ray that hits the surface.
 * All weights evaluate at c = wi.h, symmetric in wi and wo (reciprocity). The lobes add, as in
 * POV-Ray; when their sum could reflect more than 1 in some channel (Kd P + Ks' + Kp' + max R), all
 * are scaled by the same factor so that it is 1: the BSDF never creates energy. */
#ifndef CIRCE_RENDER_BSDF_POV_H
#define CIRCE_RENDER_BSDF_POV_H

#include "render/bsdf.h"

/* A mirror's GGX roughness: the sharpest circe's float GGX renders (bsdf.h's floor). */
#define BSDF_POV_MIRROR_ALPHA BSDF_MIN_ALPHA

/* The BSDF of a finish over a pigment (clamped to [0, 1]). */
bsdf_params bsdf_pov(const bsdf_pov_finish_spec *f, vec3 pigment);
/* The same BSDF over another pigment (a texture's texel at the shading point). */
void bsdf_pov_set_pigment(bsdf_params *b, vec3 pigment);

/* POV-Ray's exponents as circe's GGX alpha, and the lobes' weights (exposed for tests). */
float bsdf_pov_blinn_alpha(float n);
float bsdf_pov_blinn_weight(float n);
/* POV-Ray's empirical metallic Fresnel curve F(cos) in [0, 1] (0 at normal incidence). */
float bsdf_pov_metallic_fresnel(float cos_angle);

/* bsdf.h's verbs for BSDF_POV (bsdf.c dispatches here). */
vec3 bsdf_pov_eval(const bsdf_params *b, vec3 wo, vec3 wi);
float bsdf_pov_pdf(const bsdf_params *b, vec3 wo, vec3 wi);
bool bsdf_pov_sample(const bsdf_params *b, vec3 wo, float u_lobe, vec2 u, vec3 *wi);

#endif
