/* prim.c - tessellation of sphere, box and plane. */
#include "geom/prim.h"

#include <string.h>

uint32_t prim_sphere_segments(float radius, float max_error)
{
	/* Chord error of an arc of angle a: r (1 - cos(a / 2)); solve for a. */
	if (!(radius > 0.0f) || !(max_error > 0.0f) || max_error >= radius)
		return 8;
	double a = 2.0 * acos(1.0 - (double)max_error / radius);
	double n = ceil(2.0 * M_PI / a);
	return n < 8 ? 8 : n > 4096 ? 4096 : (uint32_t)n;
}

uint32_t prim_sphere_level_segments(uint32_t level)
{
	return PRIM_SPHERE_MIN_SEGMENTS << (level < PRIM_SPHERE_LEVELS ? level : PRIM_SPHERE_LEVELS - 1);
}

/* The point of the unit sphere at colatitude th (from +y) and longitude ph, as prim_sphere. */
static dvec3 sphere_point(double th, double ph)
{
	return d3(sin(th) * cos(ph), cos(th), sin(th) * sin(ph));
}

double prim_sphere_rel_error(uint32_t segments)
{
	/* Every triangle of a band lies in the plane of its quad (an isosceles trapezoid) or pole fan
	 * triangle; the surface is no deeper than that plane's distance below the sphere. */
	uint32_t rings = segments / 2 < 2 ? 2 : segments / 2;
	double dph = 2.0 * M_PI / segments, worst = 0.0;
	for (uint32_t i = 0; i < rings; i++) {
		double t0 = M_PI * i / rings, t1 = M_PI * (i + 1) / rings;
		dvec3 a = sphere_point(t0, 0.0), b = sphere_point(t1, 0.0);
		dvec3 c = i + 1 < rings ? sphere_point(t1, dph) : sphere_point(t0, dph);
		dvec3 n = d3_cross(d3_sub(b, a), d3_sub(c, a));
		double dist = fabs(d3_dot(n, a)) / d3_length(n);
		worst = fmax(worst, 1.0 - dist);
	}
	return worst;
}

bool prim_sphere(vec3 centre, float radius, uint32_t segments, mesh *out)
{
	if (segments < 3)
		segments = 3;
	uint32_t rings = segments / 2 < 2 ? 2 : segments / 2;
	/* Rows 1 .. rings-1 have segments + 1 vertices (the seam is duplicated for UVs); the poles
	 * have one each. */
	size_t nv = (size_t)(rings - 1) * (segments + 1) + 2;
	size_t nt = (size_t)2 * segments * (rings - 1);
	if (!mesh_alloc(out, nv, nt, true, true, false))
		return false;
	uint32_t north = (uint32_t)nv - 2, south = (uint32_t)nv - 1;
	for (uint32_t i = 1; i < rings; i++) {
		double th = M_PI * i / rings; /* from the north pole (+y) */
		for (uint32_t j = 0; j <= segments; j++) {
			double ph = 2.0 * M_PI * (j % segments) / segments;
			vec3 n = v3((float)(sin(th) * cos(ph)), (float)cos(th), (float)(sin(th) * sin(ph)));
			uint32_t v = (i - 1) * (segments + 1) + j;
			out->normals[v] = n;
			out->positions[v] = v3_madd(centre, n, radius);
			out->uvs[v] = v2((float)j / segments, 1.0f - (float)i / rings);
		}
	}
	out->normals[north] = v3(0, 1, 0), out->normals[south] = v3(0, -1, 0);
	out->positions[north] = v3_madd(centre, v3(0, 1, 0), radius);
	out->positions[south] = v3_madd(centre, v3(0, -1, 0), radius);
	out->uvs[north] = v2(0.5f, 1.0f), out->uvs[south] = v2(0.5f, 0.0f);
	uint32_t *ix = out->indices;
	/* Winding: counter-clockwise seen from outside. */
	for (uint32_t j = 0; j < segments; j++) {
		*ix++ = north, *ix++ = j + 1, *ix++ = j;
		uint32_t base = (rings - 2) * (segments + 1);
		*ix++ = south, *ix++ = base + j, *ix++ = base + j + 1;
	}
	for (uint32_t i = 1; i + 1 < rings; i++) {
		for (uint32_t j = 0; j < segments; j++) {
			uint32_t a = (i - 1) * (segments + 1) + j, b = a + 1, c = a + segments + 1, d = c + 1;
			*ix++ = a, *ix++ = b, *ix++ = c;
			*ix++ = b, *ix++ = d, *ix++ = c;
		}
	}
	return true;
}

bool prim_box(vec3 c1, vec3 c2, mesh *out)
{
	vec3 lo = v3_min(c1, c2), hi = v3_max(c1, c2);
	int flat = lo.x == hi.x ? 0 : lo.y == hi.y ? 1 : lo.z == hi.z ? 2 : -1;
	if (!mesh_alloc(out, flat < 0 ? 24 : 4, flat < 0 ? 12 : 2, true, true, false))
		return false;
	uint32_t v = 0, *ix = out->indices;
	for (int axis = 0; axis < 3; axis++) {
		for (int side = 0; side < 2; side++) {
			if (flat >= 0 && (axis != flat || !side))
				continue; /* a flat box: the one rectangle, facing +axis */
			float s = side ? 1.0f : -1.0f;
			vec3 n = v3(axis == 0 ? s : 0, axis == 1 ? s : 0, axis == 2 ? s : 0);
			/* u, w span the face so that u x w = n. */
			int ua = (axis + 1) % 3, wa = (axis + 2) % 3;
			if (!side) {
				int t = ua;
				ua = wa, wa = t;
			}
			for (int k = 0; k < 4; k++) {
				float p[3] = {0, 0, 0};
				const float *l = &lo.x, *h = &hi.x;
				p[axis] = side ? h[axis] : l[axis];
				int bu = k == 1 || k == 2, bw = k >= 2;
				p[ua] = bu ? h[ua] : l[ua];
				p[wa] = bw ? h[wa] : l[wa];
				out->positions[v + k] = v3(p[0], p[1], p[2]);
				out->normals[v + k] = n;
				out->uvs[v + k] = v2((float)bu, (float)bw);
			}
			*ix++ = v, *ix++ = v + 1, *ix++ = v + 2;
			*ix++ = v, *ix++ = v + 2, *ix++ = v + 3;
			v += 4;
		}
	}
	return true;
}

bool prim_plane(vec3 normal, float offset, vec3 lo, vec3 hi, mesh *out)
{
	memset(out, 0, sizeof *out);
	float len = v3_length(normal);
	if (!(len > 0.0f) || !isfinite(len))
		return false;
	vec3 n = v3_scale(normal, 1.0f / len);
	vec3 pad = v3_scale(v3_sub(hi, lo), 0.01f);
	lo = v3_sub(lo, pad), hi = v3_add(hi, pad);
	/* A square on the plane around the box centre's projection, larger than the box, clipped by
	 * the box's six planes (Sutherland-Hodgman). */
	vec3 mid = v3_scale(v3_add(lo, hi), 0.5f);
	vec3 o = v3_madd(mid, n, offset - v3_dot(mid, n));
	float half = v3_length(v3_sub(hi, lo)) * 2.0f;
	vec3 b1, b2;
	v3_basis(n, &b1, &b2);
	vec3 poly[16], tmp[16];
	int np = 4;
	poly[0] = v3_add(o, v3_add(v3_scale(b1, -half), v3_scale(b2, -half)));
	poly[1] = v3_add(o, v3_add(v3_scale(b1, half), v3_scale(b2, -half)));
	poly[2] = v3_add(o, v3_add(v3_scale(b1, half), v3_scale(b2, half)));
	poly[3] = v3_add(o, v3_add(v3_scale(b1, -half), v3_scale(b2, half)));
	for (int plane = 0; plane < 6 && np > 0; plane++) {
		int axis = plane / 2;
		float bound = plane % 2 ? v3_get(hi, axis) : v3_get(lo, axis);
		float sign = plane % 2 ? -1.0f : 1.0f; /* inside: sign * (x - bound) >= 0 */
		int nt = 0;
		for (int i = 0; i < np; i++) {
			vec3 a = poly[i], b = poly[(i + 1) % np];
			float da = sign * (v3_get(a, axis) - bound), db = sign * (v3_get(b, axis) - bound);
			if (da >= 0.0f)
				tmp[nt++] = a;
			if ((da >= 0.0f) != (db >= 0.0f))
				tmp[nt++] = v3_lerp(a, b, da / (da - db));
		}
		memcpy(poly, tmp, (size_t)nt * sizeof *poly);
		np = nt;
	}
	if (np < 3)
		return false;
	if (!mesh_alloc(out, (size_t)np, (size_t)np - 2, true, true, false))
		return false;
	for (int i = 0; i < np; i++) {
		out->positions[i] = poly[i];
		out->normals[i] = n;
		vec3 r = v3_sub(poly[i], o);
		out->uvs[i] = v2(v3_dot(r, b1), v3_dot(r, b2));
	}
	/* The square runs counter-clockwise around n (b1 x b2 = n), and clipping keeps the order. */
	for (int i = 0; i + 2 < np; i++) {
		out->indices[3 * i] = 0, out->indices[3 * i + 1] = (uint32_t)i + 1, out->indices[3 * i + 2] = (uint32_t)i + 2;
	}
	return true;
}

/* An eye on the plane (h = 0) sees it edge on; its rings then start at this fraction of the
 * foot's distance from the origin (one unit for an eye at the origin: nothing else gives a size),
 * so the plane still reaches out under the objects near the eye. Relative, not absolute: a scene
 * of size 1e-8 keeps rings of its own size. */
#define PRIM_PLANE_MIN_RING 1e-3

bool prim_plane_view(vec3 normal, float offset, vec3 eye, float horizon_rad, mesh *out)
{
	memset(out, 0, sizeof *out);
	dvec3 nd = v3_to_d3(normal);
	double len = d3_length(nd);
	if (!(len > 0.0) || !isfinite(len) || !(horizon_rad > 0.0f) || !(horizon_rad < 1.0f))
		return false;
	dvec3 n = d3_scale(nd, 1.0 / len), e = v3_to_d3(eye);
	double height = d3_dot(n, e) - offset;
	dvec3 foot = d3_sub(e, d3_scale(n, height)), origin = d3_scale(n, offset);
	double a0 = fmax(fabs(height), PRIM_PLANE_MIN_RING * d3_length(foot));
	if (!(a0 > 0.0))
		a0 = 1.0;
	/* The plane at distance D from the foot is seen h / D below the horizon (tan). */
	double rings = ceil(log2(1.0 / tan((double)horizon_rad)));
	if (!isfinite(a0) || rings > PRIM_PLANE_MAX_RINGS)
		return false;
	uint32_t k_max = rings < 1.0 ? 1 : (uint32_t)rings;
	if (!mesh_alloc(out, 4 * ((size_t)k_max + 1), 2 + 8 * (size_t)k_max, true, true, false))
		return false;
	vec3 b1f, b2f;
	v3_basis(d3_to_v3(n), &b1f, &b2f);
	dvec3 b1 = v3_to_d3(b1f), b2 = v3_to_d3(b2f);
	static const int sx[4] = {-1, 1, 1, -1}, sy[4] = {-1, -1, 1, 1}; /* counter-clockwise about n */
	for (uint32_t k = 0; k <= k_max; k++) {
		double a = ldexp(a0, (int)k);
		for (int c = 0; c < 4; c++) {
			dvec3 p = d3_add(foot, d3_add(d3_scale(b1, a * sx[c]), d3_scale(b2, a * sy[c])));
			uint32_t v = 4 * k + (uint32_t)c;
			out->positions[v] = d3_to_v3(p);
			out->normals[v] = d3_to_v3(n);
			dvec3 r = d3_sub(p, origin);
			out->uvs[v] = v2((float)d3_dot(r, b1), (float)d3_dot(r, b2));
		}
	}
	uint32_t *ix = out->indices;
	*ix++ = 0, *ix++ = 1, *ix++ = 2;
	*ix++ = 0, *ix++ = 2, *ix++ = 3;
	/* Ring k joins the square of ring k - 1 (inside) to its own: a trapezoid per side. */
	for (uint32_t k = 1; k <= k_max; k++) {
		for (uint32_t i = 0; i < 4; i++) {
			uint32_t in0 = 4 * (k - 1) + i, in1 = 4 * (k - 1) + (i + 1) % 4;
			uint32_t out0 = 4 * k + i, out1 = 4 * k + (i + 1) % 4;
			*ix++ = out0, *ix++ = out1, *ix++ = in1;
			*ix++ = out0, *ix++ = in1, *ix++ = in0;
		}
	}
	return true;
}
