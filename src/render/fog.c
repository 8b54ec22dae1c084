/* fog.c - the optical depth of POV-Ray's constant and ground fogs along a segment, in closed form. */
#include "render/fog.h"

#include <math.h>

/* Below this |slope| of the height along the ray, the density is taken constant (a horizontal
 * ray), as POV-Ray's EPSILON test does. */
#define FOG_FLAT_SLOPE 1e-9

/* The antiderivative of the ground fog's density over the height h: h below 0, atan(h) above. */
static double ground_integral(double h)
{
	return h <= 0.0 ? h : atan(h);
}

static double ground_density(double h)
{
	return h <= 0.0 ? 1.0 : 1.0 / (1.0 + h * h);
}

/* alt 0: the length of the segment below offset. */
static double sharp_depth(double y1, double slope, double t)
{
	if (fabs(slope) < FOG_FLAT_SLOPE)
		return y1 < 0.0 ? t : 0.0;
	double cross = -y1 / slope; /* where the height is 0 */
	if (slope > 0.0)
		return y1 >= 0.0 ? 0.0 : fmin(cross, t);
	return y1 < 0.0 ? t : (cross < t ? t - cross : 0.0);
}

double render_fog_depth(const render_fog *f, vec3 o, vec3 d, double t)
{
	if (!f->ground)
		return t;
	double y1 = (double)v3_dot(o, f->up) - f->offset, dy = v3_dot(d, f->up);
	if (!(f->alt > 0.0f))
		return sharp_depth(y1, dy, t);
	double h1 = y1 / f->alt, slope = dy / f->alt; /* heights in units of alt, per unit length */
	if (fabs(slope) < FOG_FLAT_SLOPE)
		return t * ground_density(h1);
	if (isinf(t)) /* upward: a finite depth (atan tends to pi / 2); downward: infinite */
		return slope > 0.0 ? (M_PI / 2.0 - ground_integral(h1)) / slope : INFINITY;
	return (ground_integral(h1 + slope * t) - ground_integral(h1)) / slope;
}

void render_fog_segment(const render_fog *fogs, size_t n, vec3 o, vec3 d, float t, vec3 *att, vec3 *add)
{
	*att = v3s(1.0f);
	*add = v3s(0.0f);
	for (size_t i = 0; i < n; i++) {
		double depth = render_fog_depth(&fogs[i], o, d, t);
		float a = (float)exp(-depth / fogs[i].distance); /* 0 for an infinite depth */
		*att = v3_scale(*att, a);
		*add = v3_madd(*add, fogs[i].color, 1.0f - a);
	}
}
