/* material.c - SSS presets, block defaults and the physical <-> artist conversion.
 * Sources: H. W. Jensen, S. R. Marschner, M. Levoy, P. Hanrahan, "A Practical Model for Subsurface
 * Light Transport", SIGGRAPH 2001 (JMLH01); H. W. Jensen, J. Buhler, "A Rapid Hierarchical Rendering
 * Technique for Translucent Materials", SIGGRAPH 2002 (JB02); E. d'Eon, D. Luebke, "Advanced
 * Techniques for Realistic Real-Time Skin Rendering", GPU Gems 3, chapter 14, 2007. */
#include "scene/material.h"

#include <math.h>
#include <string.h>

/* JMLH01, Figure 5: sigma_s' and sigma_a in mm^-1 for R, G, B, with the eta their Rd column implies. */
const scene_sss_preset scene_sss_presets[] = {
	{"apple", {2.29f, 2.39f, 1.97f}, {0.0030f, 0.0034f, 0.046f}, 1.3f},
	{"chicken1", {0.15f, 0.21f, 0.38f}, {0.015f, 0.077f, 0.19f}, 1.3f},
	{"chicken2", {0.19f, 0.25f, 0.32f}, {0.018f, 0.088f, 0.20f}, 1.3f},
	{"cream", {7.38f, 5.47f, 3.15f}, {0.0002f, 0.0028f, 0.0163f}, 1.3f},
	{"ketchup", {0.18f, 0.07f, 0.03f}, {0.061f, 0.97f, 1.45f}, 1.3f},
	/* marble: the Rd column of Figure 5 is reproduced with eta 1.5 (1.3 gives 0.83/0.83/0.80). */
	{"marble", {2.19f, 2.62f, 3.00f}, {0.0021f, 0.0041f, 0.0071f}, 1.5f},
	{"potato", {0.68f, 0.70f, 0.55f}, {0.0024f, 0.0090f, 0.12f}, 1.3f},
	{"skimmilk", {0.70f, 1.22f, 1.90f}, {0.0014f, 0.0025f, 0.0142f}, 1.3f},
	{"skin1", {0.74f, 0.88f, 1.01f}, {0.032f, 0.17f, 0.48f}, 1.3f},
	{"skin2", {1.09f, 1.59f, 1.79f}, {0.013f, 0.070f, 0.145f}, 1.3f},
	{"wholemilk", {2.55f, 3.21f, 3.77f}, {0.0011f, 0.0024f, 0.014f}, 1.3f},
};
const int scene_sss_n_presets = (int)(sizeof scene_sss_presets / sizeof scene_sss_presets[0]);

/* d'Eon & Luebke 2007, GPU Gems 3 ch. 14, section 14.4.2 ("the sum-of-Gaussians fit of the
 * three-layer skin model"): variances in mm^2 and the R, G, B weight of each Gaussian. */
const float scene_skin_gaussian_variance_mm2[SCENE_SKIN_GAUSSIANS] = {
	0.0064f, 0.0484f, 0.187f, 0.567f, 1.99f, 7.41f};
const float scene_skin_gaussian_weight[SCENE_SKIN_GAUSSIANS][3] = {
	{0.233f, 0.455f, 0.649f}, {0.100f, 0.336f, 0.344f}, {0.118f, 0.198f, 0.0f},
	{0.113f, 0.007f, 0.007f}, {0.358f, 0.004f, 0.0f},   {0.078f, 0.0f, 0.0f}};

const scene_sss_preset *scene_sss_preset_find(const char *name)
{
	for (int i = 0; i < scene_sss_n_presets; i++)
		if (!strcmp(scene_sss_presets[i].name, name))
			return &scene_sss_presets[i];
	return NULL;
}

const char *scene_material_kind_name(scene_material_kind k)
{
	static const char *const names[MAT_KIND_COUNT] = {"diffuse", "texture", "emission",
							  "skin",    "wax",     "marble"};
	return (unsigned)k < MAT_KIND_COUNT ? names[k] : "?";
}

const char *scene_sss_profile_name(scene_sss_profile p)
{
	static const char *const names[] = {"gaussian", "sum_of_gaussians", "burley", "dipole"};
	return (unsigned)p < 4 ? names[p] : "?";
}

const char *scene_sss_method_name(scene_sss_method m)
{
	static const char *const names[] = {"default", "circle", "fullcircle", "disk", "volume"};
	return (unsigned)m < 5 ? names[m] : "?";
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

static void set_preset(scene_sss *s, const scene_sss_preset *p)
{
	s->sigma_s_per_mm = v3(p->sigma_s_per_mm[0], p->sigma_s_per_mm[1], p->sigma_s_per_mm[2]);
	s->sigma_a_per_mm = v3(p->sigma_a_per_mm[0], p->sigma_a_per_mm[1], p->sigma_a_per_mm[2]);
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
		set_preset(s, scene_sss_preset_find("marble"));
		s->profile = PROFILE_BURLEY;
		s->ior = 1.5f;
		s->roughness = 0.1f;
		break;
	case MAT_WAX:
		s->albedo = v3(0.95f, 0.78f, 0.45f);
		s->radius_mm = v3(2.0f, 1.2f, 0.6f);
		s->profile = PROFILE_BURLEY;
		s->ior = 1.45f;
		s->roughness = 0.25f;
		break;
	default: /* skin */
		set_preset(s, scene_sss_preset_find("skin1"));
		s->profile = PROFILE_SUM_OF_GAUSSIANS;
		s->ior = 1.4f;
		s->roughness = 0.35f;
		break;
	}
}

/* Diffuse Fresnel reflectance of a boundary with relative index eta: the polynomial fit quoted
 * in JMLH01 section 2.4 (after Egan & Hilgeman). */
static double fresnel_diffuse(double eta)
{
	return -1.440 / (eta * eta) + 0.710 / eta + 0.668 + 0.0636 * eta;
}

/* JMLH01 eq. for the total diffuse reflectance of the dipole, as written in JB02 eq. 4:
 * Rd = (a'/2) (1 + exp(-4/3 A sqrt(3 (1 - a')))) exp(-sqrt(3 (1 - a'))). */
static double diffuse_reflectance(double alpha_p, double eta)
{
	double fdr = fresnel_diffuse(eta);
	double A = (1.0 + fdr) / (1.0 - fdr);
	double s = sqrt(3.0 * (1.0 - alpha_p));
	return 0.5 * alpha_p * (1.0 + exp(-4.0 / 3.0 * A * s)) * exp(-s);
}

void scene_sss_to_artist(double sigma_s, double sigma_a, double eta, double *albedo, double *radius_mm)
{
	double sigma_t = sigma_s + sigma_a; /* reduced extinction sigma_t' */
	double alpha_p = sigma_t > 0 ? sigma_s / sigma_t : 0.0;
	*albedo = diffuse_reflectance(alpha_p, eta);
	/* JMLH01: sigma_tr = sqrt(3 sigma_a sigma_t'); JB02 calls l_d = 1/sigma_tr the diffuse mean
	 * free path and uses it as the artist's "scattering distance". */
	double sigma_tr = sqrt(3.0 * sigma_a * sigma_t);
	*radius_mm = sigma_tr > 0 ? 1.0 / sigma_tr : INFINITY;
}

void scene_sss_to_physical(double albedo, double radius_mm, double eta, double *sigma_s, double *sigma_a)
{
	/* JB02 section 4: find a' with Rd(a') = albedo, then sigma_t' = sigma_tr / sqrt(3 (1 - a')). */
	double lo = 0.0, hi = 1.0;
	double rmax = diffuse_reflectance(1.0 - 1e-12, eta);
	if (albedo >= rmax)
		albedo = rmax * (1.0 - 1e-9);
	if (albedo < 0)
		albedo = 0;
	for (int i = 0; i < 64; i++) {
		double mid = 0.5 * (lo + hi);
		if (diffuse_reflectance(mid, eta) < albedo)
			lo = mid;
		else
			hi = mid;
	}
	double alpha_p = 0.5 * (lo + hi);
	double sigma_tr = 1.0 / radius_mm;
	double sigma_t = sigma_tr / sqrt(3.0 * (1.0 - alpha_p));
	*sigma_s = alpha_p * sigma_t;
	*sigma_a = sigma_t - *sigma_s;
}

static float comp(vec3 v, int i) { return i == 0 ? v.x : i == 1 ? v.y : v.z; }
static void set_comp(vec3 *v, int i, float x)
{
	if (i == 0)
		v->x = x;
	else if (i == 1)
		v->y = x;
	else
		v->z = x;
}

void scene_sss_derive(scene_sss *s)
{
	bool artist = s->given == SSS_FORM_ARTIST ||
		      (s->given == SSS_FORM_DEFAULT && s->radius_mm.x > 0 && s->sigma_s_per_mm.x == 0);
	for (int i = 0; i < 3; i++) {
		double a, b;
		if (artist) {
			scene_sss_to_physical(comp(s->albedo, i), comp(s->radius_mm, i), s->ior, &a, &b);
			set_comp(&s->sigma_s_per_mm, i, (float)a);
			set_comp(&s->sigma_a_per_mm, i, (float)b);
		} else {
			scene_sss_to_artist(comp(s->sigma_s_per_mm, i), comp(s->sigma_a_per_mm, i), s->ior, &a, &b);
			set_comp(&s->albedo, i, (float)a);
			set_comp(&s->radius_mm, i, (float)b);
		}
	}
}
