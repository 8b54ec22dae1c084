/* circle.c - circles, the area density of their hits, the leak filter and the resampling among
 * hits. The density is derived in README.md ("The density of a hit"): for the family of circles
 * whose planes contain the axis a, a hit at direction d from x with normal n_i has
 * p_A = p(r) p_phi |n_i . e_a| / (r sqrt(1 - (a . d)^2)), e_a the unit tangent of the circle there. */
#include "sss/circle.h"

#include <assert.h>

#define PI_F 3.14159265358979f

sss_circle_opts sss_circle_default_opts(void)
{
	return (sss_circle_opts){SSS_CIRCLE_HALF, SSS_CIRCLE_EXACT, false, SSS_CIRCLE_GRAZING_MIN};
}

/* The probability of circle family f (0: axis n, 1: b1, 2: b2). */
static float family_q(const sss_circle_opts *o, int f)
{
	if (!o->mis_axes)
		return f == 0 ? 1.0f : 0.0f;
	return f == 0 ? SSS_CIRCLE_MIS_Q_NORMAL : 0.5f * (1.0f - SSS_CIRCLE_MIS_Q_NORMAL);
}

/* The axis of family f and the two vectors completing it (a right-handed cycle of n, b1, b2). */
static void family_frame(const sss_circle *c, int f, vec3 *a, vec3 *u1, vec3 *u2)
{
	const vec3 fr[3] = {c->n, c->b1, c->b2};
	*a = fr[f];
	*u1 = fr[(f + 1) % 3];
	*u2 = fr[(f + 2) % 3];
}

sss_circle sss_circle_make(vec3 x, vec3 n, float r, float u_family, float u_phi, const sss_circle_opts *o)
{
	sss_circle c;
	c.q.centre = x;
	c.n = n;
	v3_basis(n, &c.b1, &c.b2);
	c.q.radius = r;
	c.family = 0;
	if (o->mis_axes)
		c.family = u_family < family_q(o, 0) ? 0 : u_family < family_q(o, 0) + family_q(o, 1) ? 1 : 2;
	vec3 u1, u2;
	family_frame(&c, c.family, &c.q.n, &u1, &u2);
	bool half = o->kind == SSS_CIRCLE_HALF;
	c.q.full = !half;
	float phi = (half ? 2.0f * PI_F : PI_F) * u_phi;
	c.q.t = v3_add(v3_scale(u1, cosf(phi)), v3_scale(u2, sinf(phi)));
	c.theta_min = half ? -0.5f * PI_F : 0.0f;
	c.theta_max = half ? 0.5f * PI_F : 2.0f * PI_F;
	c.p_phi = half ? 1.0f / (2.0f * PI_F) : 1.0f / PI_F;
	return c;
}

vec3 sss_circle_point(const sss_circle *c, float theta)
{
	vec3 d = v3_add(v3_scale(c->q.t, cosf(theta)), v3_scale(c->q.n, sinf(theta)));
	return v3_madd(c->q.centre, d, c->q.radius);
}

vec3 sss_circle_tangent(const sss_circle *c, float theta)
{
	return v3_add(v3_scale(c->q.t, -sinf(theta)), v3_scale(c->q.n, cosf(theta)));
}

/* The unit direction d = (x_i - x)/r of the point at theta. */
static vec3 circle_dir(const sss_circle *c, float theta)
{
	return v3_add(v3_scale(c->q.t, cosf(theta)), v3_scale(c->q.n, sinf(theta)));
}

/* H_a = p_phi |n_i . e_a| / sqrt(1 - (a . d)^2) of the family with axis a, with
 * e_a = (a - (a.d) d) / sqrt(1 - (a.d)^2): the density's factor r p_A / p(r). +Inf on the axis. */
static float family_h(vec3 a, vec3 d, vec3 n_i, float p_phi, const sss_circle_opts *o)
{
	/* sqrt(1 - (a.d)^2) as |a x d|: accurate near the axis, where 1 - (a.d)^2 cancels. */
	float ad = v3_dot(a, d), s = v3_length(v3_cross(a, d)), ne;
	if (!(s > 0.0f))
		return INFINITY;
	if (o->weight == SSS_CIRCLE_TALK) {
		float nd = v3_dot(n_i, d);
		ne = sqrtf(fmaxf(0.0f, 1.0f - nd * nd));
	} else {
		ne = fabsf(v3_dot(n_i, a) - ad * v3_dot(n_i, d)) / s;
	}
	return p_phi * fmaxf(fminf(ne, 1.0f), o->grazing_min) / s;
}

/* H = r p_A / p(r) of a hit: the sampled family's, or the q-weighted sum over the families. */
static float hit_h(const sss_circle *c, const tri_circle_hit *h, const sss_circle_opts *o)
{
	vec3 d = circle_dir(c, h->theta);
	if (!o->mis_axes)
		return family_h(c->q.n, d, h->ng, c->p_phi, o);
	float sum = 0.0f;
	for (int f = 0; f < 3; f++) {
		vec3 a, u1, u2;
		family_frame(c, f, &a, &u1, &u2);
		sum += family_q(o, f) * family_h(a, d, h->ng, c->p_phi, o);
	}
	return sum;
}

float sss_circle_pdf_area(const sss_circle *c, float pdf_r, const tri_circle_hit *h, const sss_circle_opts *o)
{
	return pdf_r * hit_h(c, h, o) / c->q.radius;
}

float sss_circle_leak(vec3 n, vec3 n_i, vec3 d)
{
	/* Both dot products clamped to [0, 1]: rounding must not push f_t out of [0, 1]. */
	float t = fminf(1.0f, fmaxf(0.0f, v3_dot(n, d)));
	return 1.0f + (fminf(1.0f, fmaxf(0.0f, v3_dot(n, n_i))) - 1.0f) * t;
}

vec3 sss_circle_hit_weight(const sss_circle *c, vec3 ratio, const tri_circle_hit *h, const sss_circle_opts *o)
{
	float H = hit_h(c, h, o);
	/* H = 0 only for an exactly grazing hit under grazing_min = 0: density zero, never sampled. */
	if (!(H > 0.0f) || isinf(H))
		return v3s(0.0f);
	float ft = sss_circle_leak(c->n, h->ng, circle_dir(c, h->theta));
	return v3_scale(ratio, ft / (2.0f * PI_F * H));
}

bool sss_circle_repeats(const tri_circle_hit *hits, int i)
{
	for (int j = 0; j < i; j++) {
		float d = fabsf(hits[i].theta - hits[j].theta);
		if (fminf(d, 2.0f * PI_F - d) <= SSS_CIRCLE_SAME_THETA)
			return true;
	}
	return false;
}

int sss_circle_choose(const sss_circle *c, vec3 ratio, const tri_circle_hit *hits, int k, float u,
		      const sss_circle_opts *o, vec3 *weight, float *prob)
{
	assert(k >= 0 && k <= SSS_CIRCLE_MAX_HITS);
	*weight = v3s(0.0f);
	*prob = 0.0f;
	/* Each hit's weight once (zero for a repeat of an earlier hit's point), then the walk. */
	vec3 w[SSS_CIRCLE_MAX_HITS];
	float lum[SSS_CIRCLE_MAX_HITS], total = 0.0f;
	for (int i = 0; i < k; i++) {
		w[i] = sss_circle_repeats(hits, i) ? v3s(0.0f) : sss_circle_hit_weight(c, ratio, &hits[i], o);
		lum[i] = v3_luminance(w[i]);
		total += lum[i];
	}
	if (!(total > 0.0f) || !isfinite(total))
		return -1;
	float x = u * total;
	int last = -1;
	for (int i = 0; i < k; i++) {
		if (lum[i] <= 0.0f)
			continue;
		last = i;
		if (x < lum[i])
			break;
		x -= lum[i];
	}
	/* `last` is the hit where x ran out, or the last hit of positive weight when rounding left
	 * x over: either way a hit of positive weight (total > 0 has one). */
	assert(last >= 0 && lum[last] > 0.0f);
	*prob = lum[last] / total;
	*weight = v3_scale(w[last], 1.0f / *prob);
	return last;
}
