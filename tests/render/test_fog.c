/* test_fog: POV-Ray's fog depths in closed form against a brute-force quadrature of the density
 * POV-Ray documents (1 below the offset, 1 / (1 + h^2) above, h in units of fog_alt), for rays
 * up, down, level and across the offset, infinite upward rays, the sharp layer of fog_alt 0, and
 * the attenuation and colour of a segment through two fogs. */
#include "check.h"
#include "render/fog.h"

#include <math.h>

static double density(const render_fog *f, vec3 p)
{
	double y = v3_dot(p, f->up) - f->offset;
	if (f->alt <= 0.0f)
		return y < 0.0 ? 1.0 : 0.0;
	double h = y / f->alt;
	return h <= 0.0 ? 1.0 : 1.0 / (1.0 + h * h);
}

/* Midpoint rule over [0, t]. */
static double brute_depth(const render_fog *f, vec3 o, vec3 d, double t)
{
	const int n = 200000;
	double s = 0.0;
	for (int i = 0; i < n; i++)
		s += density(f, v3_madd(o, d, (float)((i + 0.5) / n * t)));
	return s * t / n;
}

int main(void)
{
	render_fog ground = {.ground = true, .distance = 10.0f, .color = v3s(1), .offset = 1.0f, .alt = 2.0f,
			     .up = v3(0, 1, 0)};
	render_fog constant = {.ground = false, .distance = 5.0f, .color = v3(0.2f, 0.4f, 0.6f)};
	vec3 o = v3(0.0f, 0.5f, 0.0f);
	struct { vec3 o, d; double t; } rays[] = {
		{o, v3(0, 0, 1), 30},			       /* level, below the offset: density 1 */
		{v3(0, 4, 0), v3(0, 0, 1), 30},		       /* level above it: 1 / (1 + 1.5^2) */
		{o, v3_normalize(v3(0, 1, 2)), 40},	       /* up across the offset */
		{v3(0, 9, 0), v3_normalize(v3(0, -1, 1)), 20}, /* down across it */
		{v3(0, 3, 0), v3_normalize(v3(0, 1, 3)), 25},  /* up, above */
	};
	for (size_t i = 0; i < sizeof rays / sizeof rays[0]; i++) {
		double want = brute_depth(&ground, rays[i].o, rays[i].d, rays[i].t);
		double got = render_fog_depth(&ground, rays[i].o, rays[i].d, rays[i].t);
		CHECK(fabs(got - want) < 1e-5 * want + 1e-6, "ground fog ray %zu: depth %g, quadrature %g", i, got, want);
	}
	/* An infinite ray upward has a finite depth: alt (pi / 2 - atan(h1)) / dy; downward or level
	 * an infinite one. */
	vec3 up = v3_normalize(v3(0, 1, 1));
	double h1 = (3.0 - 1.0) / 2.0, want = 2.0 * (M_PI / 2 - atan(h1)) / up.y;
	CHECK_NEAR(render_fog_depth(&ground, v3(0, 3, 0), up, INFINITY), want, 1e-9 * want);
	CHECK(isinf(render_fog_depth(&ground, v3(0, 3, 0), v3(0, 0, 1), INFINITY)), "level ray to infinity");
	CHECK(isinf(render_fog_depth(&ground, v3(0, 3, 0), v3(0, -1, 0), INFINITY)), "downward ray to infinity");
	/* fog_alt 0: a sharp layer, the length of the segment below the offset. */
	render_fog sharp = ground;
	sharp.alt = 0.0f;
	CHECK_NEAR(render_fog_depth(&sharp, v3(0, 3, 0), v3(0, -1, 0), 5.0), 3.0, 1e-6);
	CHECK_NEAR(render_fog_depth(&sharp, v3(0, -1, 0), v3(0, 1, 0), 5.0), 2.0, 1e-6);
	CHECK_NEAR(render_fog_depth(&sharp, v3(0, 3, 0), v3(0, 1, 0), INFINITY), 0.0, 1e-9);
	/* A constant fog's depth is the length; two fogs multiply att and add (1 - att) colour. */
	CHECK_NEAR(render_fog_depth(&constant, o, v3(1, 0, 0), 7.0), 7.0, 1e-9);
	render_fog two[2] = {constant, ground};
	vec3 att, add;
	render_fog_segment(two, 2, o, v3(0, 0, 1), 10.0f, &att, &add);
	double a1 = exp(-10.0 / 5.0), a2 = exp(-10.0 / 10.0); /* ground: density 1 below the offset */
	CHECK_NEAR(att.x, a1 * a2, 1e-6);
	CHECK_NEAR(add.y, 0.4 * (1 - a1) + 1.0 * (1 - a2), 1e-6);
	render_fog_segment(two, 2, o, v3(0, 0, 1), INFINITY, &att, &add);
	CHECK(att.x == 0.0f && fabsf(add.z - 1.6f) < 1e-6f, "the sky through fog: att %g, colour %g", att.x, add.z);
	return check_done("test_fog");
}
