/* scenes.h - analytic test scenes behind the integrator's render_scene interface: spheres, planes
 * and triangles intersected directly (no BVH), with a material table and a light set. */
#ifndef CIRCE_TESTS_RENDER_SCENES_H
#define CIRCE_TESTS_RENDER_SCENES_H

#include "render/camera.h"
#include "render/integrator.h"

#include <string.h>

#define TS_MAX 32

typedef struct ts_sphere {
	vec3 c;
	float r;
	int material;
} ts_sphere;

typedef struct ts_plane { /* points p with dot(n, p) = d */
	vec3 n;
	float d;
	int material;
} ts_plane;

typedef struct ts_tri {
	vec3 v[3];
	int material, light;
} ts_tri;

typedef struct ts_scene {
	ts_sphere sph[TS_MAX];
	ts_plane pl[TS_MAX];
	ts_tri tri[TS_MAX];
	int nsph, npl, ntri;
	bsdf_params mat[TS_MAX];
	light_set lights;
	render_scene rs;
} ts_scene;

/* Moller & Trumbore 1997. */
static inline bool ts_tri_hit(const vec3 v[3], const render_ray *r, float tmin, float tmax, float *t)
{
	vec3 e1 = v3_sub(v[1], v[0]), e2 = v3_sub(v[2], v[0]);
	vec3 pv = v3_cross(r->d, e2);
	float det = v3_dot(e1, pv);
	if (fabsf(det) < 1e-12f)
		return false;
	float inv = 1.0f / det;
	vec3 tv = v3_sub(r->o, v[0]);
	float u = v3_dot(tv, pv) * inv;
	if (u < 0.0f || u > 1.0f)
		return false;
	vec3 qv = v3_cross(tv, e1);
	float w = v3_dot(r->d, qv) * inv;
	if (w < 0.0f || u + w > 1.0f)
		return false;
	float tt = v3_dot(e2, qv) * inv;
	if (!(tt > tmin && tt < tmax))
		return false;
	*t = tt;
	return true;
}

static inline bool ts_intersect(void *user, const render_ray *r, float tmin, float tmax, render_hit *hit)
{
	const ts_scene *s = user;
	bool found = false;
	for (int i = 0; i < s->nsph; i++) {
		vec3 oc = v3_sub(r->o, s->sph[i].c);
		float b = v3_dot(oc, r->d), c = v3_dot(oc, oc) - s->sph[i].r * s->sph[i].r;
		float disc = b * b - c;
		if (disc < 0)
			continue;
		float q = sqrtf(disc), t = -b - q > tmin ? -b - q : -b + q;
		if (t > tmin && t < tmax) {
			tmax = t;
			found = true;
			hit->t = t;
			hit->p = v3_madd(r->o, r->d, t);
			hit->ng = hit->ns = v3_normalize(v3_sub(hit->p, s->sph[i].c));
			hit->material = s->sph[i].material;
			hit->light = -1;
		}
	}
	for (int i = 0; i < s->npl; i++) {
		float dn = v3_dot(r->d, s->pl[i].n);
		if (fabsf(dn) < 1e-12f)
			continue;
		float t = (s->pl[i].d - v3_dot(r->o, s->pl[i].n)) / dn;
		if (t > tmin && t < tmax) {
			tmax = t;
			found = true;
			hit->t = t;
			hit->p = v3_madd(r->o, r->d, t);
			hit->ng = hit->ns = s->pl[i].n;
			hit->material = s->pl[i].material;
			hit->light = -1;
		}
	}
	for (int i = 0; i < s->ntri; i++) {
		float t;
		if (ts_tri_hit(s->tri[i].v, r, tmin, tmax, &t)) {
			tmax = t;
			found = true;
			const vec3 *v = s->tri[i].v;
			hit->t = t;
			hit->p = v3_madd(r->o, r->d, t);
			hit->ng = hit->ns = v3_normalize(v3_cross(v3_sub(v[1], v[0]), v3_sub(v[2], v[0])));
			hit->material = s->tri[i].material;
			hit->light = s->tri[i].light;
		}
	}
	if (found) {
		hit->uv = v2(0, 0);
		hit->object = hit->prim = 0;
	}
	return found;
}

static inline bool ts_occluded(void *user, const render_ray *r, float tmin, float tmax)
{
	render_hit h;
	return ts_intersect(user, r, tmin, tmax, &h);
}

/* A camera at loc looking at `at` with horizontal FOV angle, for a w x h image; false when
 * cam_init refuses it. */
static inline bool ts_camera(vec3 loc, vec3 at, float angle, int w, int h, cam *c)
{
	cam_params cp = cam_params_default();
	cp.location = v3_to_d3(loc);
	cp.look_at = v3_to_d3(at);
	cp.angle_deg = angle;
	return cam_init(c, &cp, w, h);
}

static inline void ts_init(ts_scene *s)
{
	memset(s, 0, sizeof *s);
	light_set_init(&s->lights);
	s->rs = (render_scene){.user = s,
			       .intersect = ts_intersect,
			       .occluded = ts_occluded,
			       .materials = s->mat,
			       .material_count = TS_MAX,
			       .lights = &s->lights};
}

/* The scheduler's and adaptive sampling's test scene: a floor (a POV-Ray finish) and two spheres
 * (a coated one, a diffuse one) under a small sphere light and a constant background. */
static inline void ts_floor_and_spheres(ts_scene *s)
{
	ts_init(s);
	s->pl[s->npl++] = (ts_plane){v3(0, 1, 0), 0.0f, 0};
	s->sph[s->nsph++] = (ts_sphere){v3(-0.6f, 0.5f, 1.0f), 0.5f, 1};
	s->sph[s->nsph++] = (ts_sphere){v3(0.7f, 0.4f, 0.6f), 0.4f, 2};
	s->mat[0] = bsdf_pov_finish(v3(0.7f, 0.7f, 0.7f), 0.7f, 0.3f, 0.05f);
	s->mat[1] = bsdf_coat(v3(0.9f, 0.5f, 0.4f), 1.4f, 0.35f);
	s->mat[2] = bsdf_diffuse(v3(0.2f, 0.5f, 0.8f));
	light sl = light_sphere(v3(0.5f, 2.0f, 0.0f), 0.3f, v3(4, 4, 4));
	light bg = light_background(v3(0.2f, 0.25f, 0.3f));
	light_set_add(&s->lights, &sl);
	light_set_add(&s->lights, &bg);
	light_set_finish(&s->lights, 5.0f);
}

/* Adds the 12 triangles of the axis-aligned box [lo, hi], normals outwards. */
static inline void ts_add_box(ts_scene *s, vec3 lo, vec3 hi, int material, int light)
{
	vec3 c[8];
	for (int i = 0; i < 8; i++)
		c[i] = v3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
	static const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4},
				    {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
	for (int f = 0; f < 6; f++) {
		ts_tri a = {{c[q[f][0]], c[q[f][1]], c[q[f][2]]}, material, light};
		ts_tri b = {{c[q[f][0]], c[q[f][2]], c[q[f][3]]}, material, light};
		s->tri[s->ntri++] = a;
		s->tri[s->ntri++] = b;
	}
}

#endif
