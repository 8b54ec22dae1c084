/* light.c - sampling and evaluation of circe's lights (light.h). Solid-angle densities throughout;
 * a mesh's area density converts by dist^2 / |cos_light| (Veach 1997, eq. 8.10). */
#include "render/light.h"

#include "base/mem.h"

#include <stdlib.h>
#include <string.h>

/* Below this |cos| at the light, a mesh sample is grazing: its solid-angle pdf would overflow. */
#define LIGHT_GRAZING_COS 1e-6f

static float deg_to_rad(float d)
{
	return d * RENDER_PI / 180.0f;
}

light light_point(vec3 pos, vec3 intensity)
{
	return (light){.kind = LIGHT_POINT, .color = intensity, .pos = pos};
}

light light_spot(vec3 pos, vec3 point_at, vec3 intensity, float radius_deg, float falloff_deg)
{
	/* POV-Ray keeps a falloff below the radius, but its spline (cubic_spline(cos falloff, cos
	 * radius, cos theta), only outside the radius) is 0 there: the same hard edge at the radius as
	 * this clamp, which also gives light_power the lit cone. */
	if (falloff_deg < radius_deg)
		falloff_deg = radius_deg;
	return (light){.kind = LIGHT_SPOT,
		       .color = intensity,
		       .pos = pos,
		       .dir = v3_normalize(v3_sub(point_at, pos)),
		       .cos_hot = cosf(deg_to_rad(radius_deg)),
		       .cos_fall = cosf(deg_to_rad(falloff_deg))};
}

light light_parallel(vec3 from, vec3 point_at, vec3 irradiance)
{
	return (light){
	    .kind = LIGHT_PARALLEL, .color = irradiance, .dir = v3_normalize(v3_sub(point_at, from))};
}

light light_cylinder(vec3 from, vec3 point_at, vec3 irradiance, float radius, float falloff, float tightness)
{
	light l = light_parallel(from, point_at, irradiance);
	l.kind = LIGHT_CYLINDER;
	l.pos = from;
	l.cyl_radius = radius;
	l.cyl_falloff = falloff;
	l.tightness = tightness;
	return l;
}

void light_set_area(light *l, vec3 axis1, vec3 axis2, bool ellipse, bool orient)
{
	l->area_shape = ellipse ? LIGHT_AREA_ELLIPSE : LIGHT_AREA_PARALLELOGRAM;
	l->area_orient = orient;
	l->axis1 = axis1;
	l->axis2 = axis2;
}

float light_fade(float d, float fade_distance, float fade_power)
{
	if (!(fade_power > 0.0f) || !(fade_distance > 0.0f))
		return 1.0f;
	return 2.0f / (1.0f + powf(d / fade_distance, fade_power)); /* POV-Ray 3.7 point.cpp, Attenuate_Light */
}

light light_sphere(vec3 center, float radius, vec3 color)
{
	return (light){.kind = LIGHT_SPHERE,
		       .color = v3_scale(color, 1.0f / (RENDER_PI * radius * radius)),
		       .pos = center,
		       .radius = radius};
}

light light_background(vec3 radiance)
{
	return (light){.kind = LIGHT_BACKGROUND, .color = radiance};
}

static float tri_area(const vec3 *v)
{
	return 0.5f * v3_length(v3_cross(v3_sub(v[1], v[0]), v3_sub(v[2], v[0])));
}

bool light_mesh_init(light *l, const vec3 *verts, size_t tri_count, vec3 radiance)
{
	*l = (light){.kind = LIGHT_MESH, .color = radiance};
	float *areas = mem_alloc(tri_count, sizeof *areas);
	l->tri = mem_alloc(tri_count, 3 * sizeof *l->tri);
	if (!areas || !l->tri || tri_count == 0) {
		mem_free(areas);
		light_free(l);
		return false;
	}
	memcpy(l->tri, verts, tri_count * 3 * sizeof *l->tri);
	l->tri_count = tri_count;
	double total = 0.0;
	for (size_t i = 0; i < tri_count; i++) {
		areas[i] = tri_area(verts + 3 * i);
		total += areas[i];
	}
	l->area = (float)total;
	bool ok = total > 0.0 && render_distrib1d_init(&l->tri_select, areas, tri_count);
	mem_free(areas);
	if (!ok)
		light_free(l);
	return ok;
}

vec2 light_env_uv(vec3 d)
{
	float u = 0.5f + atan2f(d.x, d.z) * (0.5f * RENDER_INV_PI);
	float v = acosf(fminf(fmaxf(d.y, -1.0f), 1.0f)) * RENDER_INV_PI;
	return v2(u - floorf(u), fminf(v, nextafterf(1.0f, 0.0f)));
}

vec3 light_env_dir(vec2 uv)
{
	float theta = uv.y * RENDER_PI, phi = 2.0f * RENDER_PI * (uv.x - 0.5f);
	float s = sinf(theta);
	return v3(s * sinf(phi), cosf(theta), s * cosf(phi));
}

static size_t env_pixel(const light *l, vec2 uv)
{
	int x = (int)(uv.x * (float)l->width), y = (int)(uv.y * (float)l->height);
	x = x < 0 ? 0 : x >= l->width ? l->width - 1 : x;
	y = y < 0 ? 0 : y >= l->height ? l->height - 1 : y;
	return (size_t)y * (size_t)l->width + (size_t)x;
}

static vec3 env_texel(const light *l, size_t i)
{
	const float *p = l->image + 3 * i;
	return v3(p[0], p[1], p[2]);
}

bool light_envmap_init(light *l, const float *rgb, int width, int height, float scale, const xform *rot)
{
	*l = (light){
	    .kind = LIGHT_ENVMAP, .color = v3s(scale), .image = rgb, .width = width, .height = height};
	for (int i = 0; i < 3; i++)
		for (int j = 0; j < 3; j++)
			l->rot[i][j] = rot ? (float)rot->m[i][j] : (i == j ? 1.0f : 0.0f);
	if (width <= 0 || height <= 0)
		return false;
	size_t n = (size_t)width * (size_t)height;
	float *func = mem_alloc(n, sizeof *func);
	if (!func)
		return false;
	for (int y = 0; y < height; y++) {
		float sin_theta = sinf(RENDER_PI * ((float)y + 0.5f) / (float)height);
		for (int x = 0; x < width; x++) {
			size_t i = (size_t)y * (size_t)width + (size_t)x;
			func[i] = v3_luminance(env_texel(l, i)) * sin_theta;
		}
	}
	bool ok = render_distrib2d_init(&l->env_dist, func, (size_t)width, (size_t)height);
	mem_free(func);
	return ok;
}

void light_free(light *l)
{
	mem_free(l->tri);
	l->tri = NULL;
	render_distrib1d_free(&l->tri_select);
	if (l->kind == LIGHT_ENVMAP)
		render_distrib2d_free(&l->env_dist);
	mem_free(l->imp_env);
	l->imp_env = NULL;
}

static vec3 rot_apply(const float r[3][3], vec3 v)
{
	return v3(r[0][0] * v.x + r[0][1] * v.y + r[0][2] * v.z,
		  r[1][0] * v.x + r[1][1] * v.y + r[1][2] * v.z,
		  r[2][0] * v.x + r[2][1] * v.y + r[2][2] * v.z);
}

static vec3 rot_apply_inverse(const float r[3][3], vec3 v)
{
	return v3(r[0][0] * v.x + r[1][0] * v.y + r[2][0] * v.z,
		  r[0][1] * v.x + r[1][1] * v.y + r[2][1] * v.z,
		  r[0][2] * v.x + r[1][2] * v.y + r[2][2] * v.z);
}

/* A vector in the frame whose +z is axis (unit), expressed in world space. */
static vec3 from_frame(vec3 axis, vec3 local)
{
	vec3 b1, b2;
	v3_basis(axis, &b1, &b2);
	return v3_add(v3_add(v3_scale(b1, local.x), v3_scale(b2, local.y)), v3_scale(axis, local.z));
}

/* A receiver's normal was given (light_sample_from's n, light_pdf's n_p): not the zero vector. */
static bool has_normal(vec3 n) { return v3_length2(n) > 0.0f; }

/* Density of the background's cosine-weighted directions about the unit normal n. */
static float background_pdf(vec3 n, vec3 wi)
{
	float c = v3_dot(n, wi);
	return c > 0.0f ? render_cosine_hemisphere_pdf(c) : 0.0f;
}

/* The cone a sphere light subtends from p: its axis, the distance to the centre and sin^2 of the
 * half angle; false when p is inside. */
static bool sphere_cone(const light *l, vec3 p, vec3 *axis, float *dist, float *sin2_max)
{
	vec3 to = v3_sub(l->pos, p);
	*dist = v3_length(to);
	if (!(*dist > l->radius))
		return false;
	*axis = v3_scale(to, 1.0f / *dist);
	*sin2_max = (l->radius * l->radius) / (*dist * *dist);
	return *sin2_max > 0.0f;
}

/* POV-Ray's cubic_spline (lightsource.cpp): 0 below lo, 1 from hi on (hi first when lo = hi, the
 * spot whose falloff was clamped up to its radius: lit on the radius, as POV-Ray, which skips the
 * spline there), a smoothstep between. */
static float cubic_spline(float lo, float hi, float x)
{
	if (x >= hi)
		return 1.0f;
	if (x < lo)
		return 0.0f;
	float t = (x - lo) / (hi - lo);
	return t * t * (3.0f - 2.0f * t);
}

/* POV-Ray's tightness: x^tightness, exactly 1 for the default 0 (images without it unchanged). */
static float tight(const light *l, float x)
{
	return l->tightness != 0.0f ? powf(x, l->tightness) : 1.0f;
}

/* POV-Ray's spot factor: cos^tightness cubic_spline(cos falloff, cos radius, cos theta). */
static float spot_factor(const light *l, float cos_theta)
{
	if (!(cos_theta > 0.0f))
		return 0.0f;
	return tight(l, cos_theta) * cubic_spline(l->cos_fall, l->cos_hot, cos_theta);
}

/* POV-Ray's cylinder factor at distance r from the axis (Attenuate_Light's CYLINDER_SOURCE). */
static float cylinder_factor(const light *l, float r)
{
	if (!(r < l->cyl_falloff))
		return 0.0f;
	float x = 1.0f - r / l->cyl_falloff;
	float k = tight(l, x);
	if (l->cyl_radius > 0.0f && r > l->cyl_radius)
		k *= cubic_spline(0.0f, 1.0f - l->cyl_radius / l->cyl_falloff, x);
	return k;
}

/* A light's distance law at distance d (d2 = d^2), the inverse square kept as before: k / d2. */
static float distance_factor(const light *l, float k, float d, float d2)
{
	switch (l->falloff) {
	case LIGHT_FALLOFF_INVERSE_SQUARE: return k / d2;
	case LIGHT_FALLOFF_FADE: return k * light_fade(d, l->fade_distance, l->fade_power);
	default: return k;
	}
}

/* The point a point or spot light shines from for this sample: its position, or a uniform point of
 * its area (POV-Ray's area_light: pos + s axis1 + t axis2, s, t in [-1/2, 1/2]; circular: the
 * inscribed ellipse by the concentric map; orient: axes turned square to the receiver p). */
static vec3 emitting_point(const light *l, vec3 p, vec2 u)
{
	if (l->area_shape == LIGHT_AREA_NONE)
		return l->pos;
	vec3 a1 = l->axis1, a2 = l->axis2, to = v3_sub(l->pos, p);
	if (l->area_orient && v3_length2(to) > 0.0f) {
		float len = v3_length(a1);
		v3_basis(v3_normalize(to), &a1, &a2);
		a1 = v3_scale(a1, len);
		a2 = v3_scale(a2, len);
	}
	vec2 s = l->area_shape == LIGHT_AREA_ELLIPSE ? render_concentric_disk(u) : v2(2.0f * u.x - 1.0f, 2.0f * u.y - 1.0f);
	return v3_add(l->pos, v3_add(v3_scale(a1, 0.5f * s.x), v3_scale(a2, 0.5f * s.y)));
}

/* A sphere light: a direction uniform in the cone the sphere subtends from p, to its near side. */
static bool sample_sphere(const light *l, vec3 p, vec2 u, light_sample *out)
{
	vec3 axis;
	float dist, sin2_max;
	if (!sphere_cone(l, p, &axis, &dist, &sin2_max))
		return false;
	out->wi = v3_normalize(from_frame(axis, render_uniform_cone(u, sin2_max)));
	/* Distance to the near side: b - sqrt(r^2 - |to - b wi|^2), b = to . wi; the squared
	 * distance of the centre from the ray avoids the cancellation of d^2 - b^2. */
	vec3 to = v3_scale(axis, dist);
	float b = v3_dot(to, out->wi);
	vec3 perp = v3_sub(to, v3_scale(out->wi, b));
	float disc = l->radius * l->radius - v3_length2(perp);
	out->dist = b - sqrtf(fmaxf(0.0f, disc));
	out->li = l->color;
	out->pdf = render_uniform_cone_pdf(sin2_max);
	return out->dist > 0.0f;
}

/* A mesh light: a triangle chosen by area (its table), a point uniform on it. */
static bool sample_mesh(const light *l, vec3 p, vec2 u, light_sample *out)
{
	size_t tri;
	float x = render_distrib1d_sample(&l->tri_select, u.x, NULL, &tri);
	float ux =
	    fminf(x * (float)l->tri_count - (float)tri, nextafterf(1.0f, 0.0f)); /* reuse u.x */
	vec2 b = render_uniform_triangle(v2(fmaxf(ux, 0.0f), u.y));
	const vec3 *v = l->tri + 3 * tri;
	vec3 y = v3_add(v3_add(v3_scale(v[0], b.x), v3_scale(v[1], b.y)),
			v3_scale(v[2], 1.0f - b.x - b.y));
	vec3 nl = v3_normalize(v3_cross(v3_sub(v[1], v[0]), v3_sub(v[2], v[0])));
	vec3 to = v3_sub(y, p);
	float d2 = v3_length2(to);
	if (!(d2 > 0.0f))
		return false;
	out->dist = sqrtf(d2);
	out->wi = v3_scale(to, 1.0f / out->dist);
	out->li = l->color;
	out->pdf = light_pdf(l, p, v3s(0.0f), out->wi, out->dist, nl);
	return out->pdf > 0.0f;
}

bool light_sample_from(const light *l, vec3 p, vec3 n, vec2 u, light_sample *out)
{
	out->delta = light_is_delta(l);
	out->shadowless = l->shadowless;
	switch (l->kind) {
	case LIGHT_POINT:
	case LIGHT_SPOT: {
		vec3 to = v3_sub(emitting_point(l, p, u), p);
		float d2 = v3_length2(to);
		if (!(d2 > 0.0f))
			return false;
		out->dist = sqrtf(d2);
		out->wi = v3_scale(to, 1.0f / out->dist);
		float k = l->kind == LIGHT_SPOT ? spot_factor(l, -v3_dot(out->wi, l->dir)) : 1.0f;
		out->li = v3_scale(l->color, distance_factor(l, k, out->dist, d2));
		out->pdf = 1.0f;
		return k > 0.0f;
	}
	case LIGHT_PARALLEL:
		out->wi = v3_neg(l->dir);
		out->dist = INFINITY;
		out->li = l->color;
		if (l->falloff == LIGHT_FALLOFF_FADE) /* POV-Ray: the distance to the light's plane */
			out->li = v3_scale(l->color, light_fade(fmaxf(0.0f, v3_dot(v3_sub(p, l->pos), l->dir)),
								l->fade_distance, l->fade_power));
		out->pdf = 1.0f;
		return true;
	case LIGHT_CYLINDER: {
		vec3 v = v3_sub(p, l->pos);
		float ahead = v3_dot(v, l->dir);
		float k = ahead > 0.0f ? cylinder_factor(l, v3_length(v3_sub(v, v3_scale(l->dir, ahead)))) : 0.0f;
		out->wi = v3_neg(l->dir);
		out->dist = ahead; /* the shadow ray ends at the light's plane, as POV-Ray's */
		out->li = v3_scale(l->color, l->falloff == LIGHT_FALLOFF_FADE
						 ? k * light_fade(ahead, l->fade_distance, l->fade_power)
						 : k);
		out->pdf = 1.0f;
		return k > 0.0f;
	}
	case LIGHT_SPHERE: return sample_sphere(l, p, u, out);
	case LIGHT_MESH: return sample_mesh(l, p, u, out);
	case LIGHT_BACKGROUND:
		/* Constant radiance: what a receiver needs is its cosine, so with a normal the
		 * directions follow it (half the uniform sphere's samples would fall below it). */
		out->dist = INFINITY;
		out->li = l->color;
		if (has_normal(n)) {
			out->wi = v3_normalize(from_frame(n, render_cosine_hemisphere(u)));
			out->pdf = background_pdf(n, out->wi);
			return out->pdf > 0.0f;
		}
		out->wi = render_uniform_sphere(u);
		out->pdf = RENDER_UNIFORM_SPHERE_PDF;
		return true;
	case LIGHT_ENVMAP: {
		float pdf_uv;
		vec2 uv = render_distrib2d_sample(&l->env_dist, u, &pdf_uv);
		vec3 local = light_env_dir(uv);
		float sin_theta = sinf(uv.y * RENDER_PI);
		if (!(pdf_uv > 0.0f) || !(sin_theta > 0.0f))
			return false;
		out->wi = rot_apply(l->rot, local);
		out->dist = INFINITY;
		out->li = v3_mul(l->color, env_texel(l, env_pixel(l, uv)));
		out->pdf = pdf_uv / (2.0f * RENDER_PI * RENDER_PI * sin_theta);
		return true;
	}
	}
	return false;
}

float light_pdf(const light *l, vec3 p, vec3 n_p, vec3 wi, float dist, vec3 n)
{
	switch (l->kind) {
	case LIGHT_SPHERE: {
		vec3 axis;
		float d, sin2_max, t;
		render_ray ray = {p, wi};
		if (!sphere_cone(l, p, &axis, &d, &sin2_max) ||
		    !light_sphere_hit(l, &ray, 0.0f, INFINITY, &t))
			return 0.0f;
		return render_uniform_cone_pdf(sin2_max);
	}
	case LIGHT_MESH: {
		float cos_l = fabsf(v3_dot(n, wi));
		if (cos_l < LIGHT_GRAZING_COS)
			return 0.0f;
		return dist * dist / (cos_l * l->area);
	}
	case LIGHT_BACKGROUND:
		return has_normal(n_p) ? background_pdf(n_p, wi) : RENDER_UNIFORM_SPHERE_PDF;
	case LIGHT_ENVMAP: {
		vec2 uv = light_env_uv(rot_apply_inverse(l->rot, wi));
		float sin_theta = sinf(uv.y * RENDER_PI);
		if (!(sin_theta > 0.0f))
			return 0.0f;
		return render_distrib2d_pdf(&l->env_dist, uv) / (2.0f * RENDER_PI * RENDER_PI * sin_theta);
	}
	default:
		return 0.0f;
	}
}

vec3 light_radiance_dir(const light *l, vec3 d)
{
	if (l->kind == LIGHT_BACKGROUND)
		return l->color;
	if (l->kind == LIGHT_ENVMAP)
		return v3_mul(l->color,
			      env_texel(l, env_pixel(l, light_env_uv(rot_apply_inverse(l->rot, d)))));
	return v3s(0.0f);
}

bool light_sphere_hit(const light *l, const render_ray *ray, float tmin, float tmax, float *t)
{
	/* Haines et al. 2019, "Precision Improvements for Ray/Sphere Intersection" (Ray Tracing Gems
	 * ch. 7): the discriminant from the centre's distance to the ray, the near root as c / q. */
	vec3 oc = v3_sub(ray->o, l->pos);
	float b = v3_dot(oc, ray->d);
	vec3 perp = v3_sub(oc, v3_scale(ray->d, b));
	float disc = l->radius * l->radius - v3_length2(perp);
	if (disc < 0.0f)
		return false;
	float c = v3_length2(oc) - l->radius * l->radius;
	float q = -b - copysignf(sqrtf(disc), b);
	float t0 = q != 0.0f ? c / q : 0.0f, t1 = q;
	if (t0 > t1) {
		float x = t0;
		t0 = t1;
		t1 = x;
	}
	float hit = t0 > tmin ? t0 : t1;
	if (!(hit > tmin && hit < tmax))
		return false;
	*t = hit;
	return true;
}

float light_power(const light *l, float scene_radius)
{
	float lum = v3_luminance(l->color), r2 = scene_radius * scene_radius;
	/* A light without the inverse square delivers at the scene's radius what an intensity of
	 * r^2 times its colour (times its fade there) would: weigh it as that. */
	float far = l->falloff == LIGHT_FALLOFF_INVERSE_SQUARE ? 1.0f
		    : l->falloff == LIGHT_FALLOFF_NONE	      ? r2
							      : r2 * light_fade(scene_radius, l->fade_distance, l->fade_power);
	switch (l->kind) {
	case LIGHT_POINT:
		return 4.0f * RENDER_PI * lum * far;
	case LIGHT_SPOT:
		/* The cone's solid angle, counting the falloff band as half (PBRT's choice). A POV-Ray
		 * spot (no inverse square) is weighed as its point light: it is aimed at what the
		 * scene shows, and its cone's share would pick it too seldom for the light it gives
		 * there (fireflies where it lands). */
		if (l->falloff != LIGHT_FALLOFF_INVERSE_SQUARE)
			return 4.0f * RENDER_PI * lum * far;
		return 2.0f * RENDER_PI * lum * (1.0f - 0.5f * (l->cos_hot + l->cos_fall));
	case LIGHT_PARALLEL:
		return RENDER_PI * r2 * lum;
	case LIGHT_CYLINDER: /* the beam's cross-section, up to its falloff radius */
		return RENDER_PI * l->cyl_falloff * l->cyl_falloff * lum;
	case LIGHT_SPHERE:
		return RENDER_PI * 4.0f * RENDER_PI * l->radius * l->radius * lum;
	case LIGHT_MESH:
		return 2.0f * RENDER_PI * l->area * lum; /* two-sided */
	case LIGHT_BACKGROUND:
		return 4.0f * RENDER_PI * RENDER_PI * r2 * lum;
	case LIGHT_ENVMAP: {
		double sum = 0.0;
		size_t n = (size_t)l->width * (size_t)l->height;
		for (size_t i = 0; i < n; i++)
			sum += v3_luminance(env_texel(l, i));
		return 4.0f * RENDER_PI * RENDER_PI * r2 * lum * (float)(sum / (double)n);
	}
	}
	return 0.0f;
}

/* The largest cos(n, w) over the directions w from p into the sphere of radius r about c, d the
 * distance to c: cos(max(0, theta - theta_s)), theta the angle between n and c - p and
 * sin theta_s = r / d; 1 when p is inside the sphere. Clamped at 0. */
static float cos_bound(vec3 n, vec3 to_c, float d, float r)
{
	if (!(d > r))
		return 1.0f;
	float c = v3_dot(n, to_c) / d;
	if (r <= 0.0f)
		return fmaxf(c, 0.0f);
	float sin_s = r / d, cos_s = sqrtf(fmaxf(0.0f, 1.0f - sin_s * sin_s));
	if (c >= cos_s)
		return 1.0f;
	float sin_t = sqrtf(fmaxf(0.0f, 1.0f - c * c));
	return fmaxf(0.0f, c * cos_s + sin_t * sin_s);
}

float light_importance(const light *l, vec3 p, vec3 n, bool cosine)
{
	if (l->seen_only) /* a sky only seen (light.h): never picked */
		return 0.0f;
	bool normal = has_normal(n);
	switch (l->kind) {
	case LIGHT_BACKGROUND:
	case LIGHT_ENVMAP:
		if (!normal)
			return 4.0f * RENDER_PI * l->imp_lum;
		if (l->kind == LIGHT_BACKGROUND)
			return LIGHT_IMP_BACKGROUND * RENDER_PI * l->imp_lum;
		if (l->imp_env) {
			vec2 uv = light_env_uv(rot_apply_inverse(l->rot, n));
			int x = (int)(uv.x * LIGHT_IMP_NU), y = (int)(uv.y * LIGHT_IMP_NV);
			x = x < 0 ? 0 : x >= LIGHT_IMP_NU ? LIGHT_IMP_NU - 1 : x;
			y = y < 0 ? 0 : y >= LIGHT_IMP_NV ? LIGHT_IMP_NV - 1 : y;
			return l->imp_env[y * LIGHT_IMP_NU + x];
		}
		return RENDER_PI * l->imp_lum;
	case LIGHT_PARALLEL:
	case LIGHT_CYLINDER: {
		float c = normal ? fmaxf(0.0f, -v3_dot(n, l->dir)) : 1.0f;
		return l->imp_lum * (cosine || !(c > 0.0f) ? c : 1.0f);
	}
	default:
		break;
	}
	vec3 to_c = v3_sub(l->imp_c, p);
	float d2 = v3_length2(to_c), d = sqrtf(d2), r = l->imp_r;
	float cosb = normal ? cos_bound(n, to_c, d, r) : 1.0f;
	if (!(cosb > 0.0f))
		return 0.0f;
	if (!cosine)
		cosb = 1.0f;
	float law;
	if ((l->kind == LIGHT_POINT || l->kind == LIGHT_SPOT) && l->falloff == LIGHT_FALLOFF_NONE)
		law = 1.0f;
	else if ((l->kind == LIGHT_POINT || l->kind == LIGHT_SPOT) && l->falloff == LIGHT_FALLOFF_FADE)
		law = light_fade(fmaxf(d - r, 0.0f), l->fade_distance, l->fade_power);
	else /* the inverse square, from no nearer than the bounding sphere's radius */
		law = 1.0f / fmaxf(d2, fmaxf(r * r, 1e-30f));
	return l->imp_lum * law * cosb;
}

/* The environment's irradiance E(n) = integral L max(0, n . w) dw at the centres of the
 * LIGHT_IMP_NU x LIGHT_IMP_NV grid of normals (map frame), times scale; from the map averaged
 * over blocks of at most ENV_IMP_W x ENV_IMP_H (each block's radiance at its centre's direction,
 * its solid angle the sum of its texels'). Left NULL when memory runs out (importance then
 * takes the mean). */
#define ENV_IMP_W 64
#define ENV_IMP_H 32
static void env_irradiance_table(light *l, float scale)
{
	int bw = l->width < ENV_IMP_W ? l->width : ENV_IMP_W, bh = l->height < ENV_IMP_H ? l->height : ENV_IMP_H;
	double *rad = mem_calloc((size_t)bw * (size_t)bh, sizeof *rad), *omega = mem_calloc((size_t)bw * (size_t)bh, sizeof *omega);
	l->imp_env = mem_alloc(LIGHT_IMP_NU * LIGHT_IMP_NV, sizeof *l->imp_env);
	if (!rad || !omega || !l->imp_env) {
		mem_free(rad), mem_free(omega), mem_free(l->imp_env);
		l->imp_env = NULL;
		return;
	}
	double texel = (2.0 * RENDER_PI / l->width) * (RENDER_PI / l->height);
	for (int y = 0; y < l->height; y++) {
		double dw = sin(RENDER_PI * ((double)y + 0.5) / (double)l->height) * texel;
		int by = (int)((long)y * bh / l->height);
		for (int x = 0; x < l->width; x++) {
			size_t b = (size_t)by * (size_t)bw + (size_t)((long)x * bw / l->width);
			rad[b] += dw * v3_luminance(env_texel(l, (size_t)y * (size_t)l->width + (size_t)x));
			omega[b] += dw;
		}
	}
	for (int j = 0; j < LIGHT_IMP_NV; j++)
		for (int i = 0; i < LIGHT_IMP_NU; i++) {
			vec3 n = light_env_dir(v2((i + 0.5f) / LIGHT_IMP_NU, (j + 0.5f) / LIGHT_IMP_NV));
			double e = 0.0;
			for (int by = 0; by < bh; by++)
				for (int bx = 0; bx < bw; bx++) {
					vec3 w = light_env_dir(v2((bx + 0.5f) / bw, (by + 0.5f) / bh));
					double c = v3_dot(n, w);
					if (c > 0.0)
						e += c * rad[(size_t)by * (size_t)bw + (size_t)bx];
				}
			l->imp_env[j * LIGHT_IMP_NU + i] = (float)(scale * e);
		}
	mem_free(rad), mem_free(omega);
}

/* light_importance's constants of one light (light.h's imp_* fields). */
static void light_importance_init(light *l)
{
	float lum = v3_luminance(l->color);
	l->imp_lum = lum, l->imp_c = l->pos, l->imp_r = 0.0f;
	switch (l->kind) {
	case LIGHT_POINT:
	case LIGHT_SPOT:
		/* every point of the area: within half its diagonal, |a1 + a2| / 2, of pos (a turned
		 * one is a square of side |axis1|) */
		if (l->area_shape != LIGHT_AREA_NONE)
			l->imp_r = l->area_orient ? v3_length(l->axis1)
						  : 0.5f * (v3_length(l->axis1) + v3_length(l->axis2));
		break;
	case LIGHT_SPHERE: /* radiance Le: pi R^2 Le / d^2 from afar */
		l->imp_lum = lum * RENDER_PI * l->radius * l->radius, l->imp_r = l->radius;
		break;
	case LIGHT_MESH: {
		vec3 lo = l->tri[0], hi = l->tri[0];
		for (size_t i = 1; i < 3 * l->tri_count; i++)
			lo = v3_min(lo, l->tri[i]), hi = v3_max(hi, l->tri[i]);
		l->imp_c = v3_scale(v3_add(lo, hi), 0.5f);
		l->imp_r = 0.5f * v3_length(v3_sub(hi, lo));
		l->imp_lum = lum * l->area;
		break;
	}
	case LIGHT_ENVMAP: { /* the mean radiance over the sphere: texels weighed by sin theta */
		double sum = 0.0, wsum = 0.0;
		for (int y = 0; y < l->height; y++) {
			double w = sin(RENDER_PI * ((double)y + 0.5) / (double)l->height);
			for (int x = 0; x < l->width; x++)
				sum += w * v3_luminance(env_texel(l, (size_t)y * (size_t)l->width + (size_t)x));
			wsum += w * l->width;
		}
		l->imp_lum = lum * (float)(wsum > 0.0 ? sum / wsum : 0.0);
		env_irradiance_table(l, lum);
		break;
	}
	default:
		break;
	}
}

void light_set_init(light_set *s)
{
	memset(s, 0, sizeof *s);
}

light *light_set_add(light_set *s, const light *l)
{
	if (s->count == s->cap) {
		size_t cap = s->cap ? 2 * s->cap : 8;
		light *grown = mem_realloc(s->lights, cap, sizeof *grown);
		if (!grown)
			return NULL;
		s->lights = grown;
		s->cap = cap;
	}
	s->lights[s->count] = *l;
	return &s->lights[s->count++];
}

/* ---- the light tree ---------------------------------------------------------------------- */

static bool in_tree(const light *l)
{
	return ((l->kind == LIGHT_POINT || l->kind == LIGHT_SPOT) && l->falloff == LIGHT_FALLOFF_INVERSE_SQUARE) ||
	       l->kind == LIGHT_SPHERE || l->kind == LIGHT_MESH;
}

static const light *sort_lights; /* qsort's context (the build runs once, single-threaded) */
static int sort_axis;
static int tree_cmp(const void *a, const void *b)
{
	size_t i = *(const size_t *)a, j = *(const size_t *)b;
	float x = v3_get(sort_lights[i].imp_c, sort_axis), y = v3_get(sort_lights[j].imp_c, sort_axis);
	return x < y ? -1 : x > y ? 1 : (i > j) - (i < j); /* ties by index: a deterministic tree */
}

/* The node over idx[0..n) and its subtree; returns its index. Splits at the median
 * along the longest axis of the lights' centres. */
static int32_t tree_node(light_set *s, size_t *idx, size_t n)
{
	int32_t k = (int32_t)s->node_count++;
	light_node *nd = &s->nodes[k];
	if (n == 1) {
		const light *l = &s->lights[idx[0]];
		*nd = (light_node){l->imp_c, l->imp_r, l->imp_lum, (int32_t)idx[0], {-1, -1}};
		return k;
	}
	vec3 lo = s->lights[idx[0]].imp_c, hi = lo;
	for (size_t i = 1; i < n; i++)
		lo = v3_min(lo, s->lights[idx[i]].imp_c), hi = v3_max(hi, s->lights[idx[i]].imp_c);
	vec3 e = v3_sub(hi, lo);
	sort_lights = s->lights;
	sort_axis = e.x >= e.y && e.x >= e.z ? 0 : e.y >= e.z ? 1 : 2;
	qsort(idx, n, sizeof *idx, tree_cmp);
	size_t h = n / 2;
	int32_t a = tree_node(s, idx, h), b = tree_node(s, idx + h, n - h);
	nd = &s->nodes[k]; /* (the array does not move: it was allocated for every node) */
	const light_node *na = &s->nodes[a], *nb = &s->nodes[b];
	/* the sphere about both children's spheres */
	vec3 dv = v3_sub(nb->c, na->c);
	float dist = v3_length(dv);
	vec3 c;
	float r;
	if (dist + nb->r <= na->r)
		c = na->c, r = na->r;
	else if (dist + na->r <= nb->r)
		c = nb->c, r = nb->r;
	else {
		r = 0.5f * (dist + na->r + nb->r);
		c = dist > 0.0f ? v3_madd(na->c, dv, (r - na->r) / dist) : na->c;
	}
	*nd = (light_node){c, r * 1.0001f, na->lum + nb->lum, -1, {a, b}};
	return k;
}

/* The trail of every light under node k reached by bits `trail` at depth d. */
static void tree_trails(light_set *s, int32_t k, uint64_t trail, int d)
{
	const light_node *nd = &s->nodes[k];
	if (nd->light >= 0) {
		s->trail[nd->light] = trail | ((uint64_t)d << 58);
		return;
	}
	tree_trails(s, nd->child[0], trail, d + 1);
	tree_trails(s, nd->child[1], trail | (1ull << d), d + 1);
}

static bool tree_build(light_set *s)
{
	size_t *idx = mem_alloc(s->count, sizeof *idx);
	s->loose = mem_alloc(s->count, sizeof *s->loose);
	s->trail = mem_calloc(s->count, sizeof *s->trail);
	s->nodes = mem_alloc(2 * s->count, sizeof *s->nodes);
	if (!idx || !s->loose || !s->trail || !s->nodes) {
		mem_free(idx);
		return false;
	}
	size_t n = 0;
	s->loose_count = 0, s->node_count = 0;
	for (size_t i = 0; i < s->count; i++) {
		if (in_tree(&s->lights[i]))
			idx[n++] = i;
		else
			s->loose[s->loose_count++] = i;
	}
	if (n > 0) {
		tree_node(s, idx, n);
		tree_trails(s, 0, 0, 0);
	}
	mem_free(idx);
	/* a median split halves the lights: the depth stays below the trail's 58 bits. More loose
	 * lights than LIGHT_SET_LOCAL_MAX: no tree (the choice is by power). */
	if (s->loose_count > LIGHT_SET_LOCAL_MAX) {
		mem_free(s->nodes);
		s->nodes = NULL, s->node_count = 0;
	}
	return true;
}

/* A tree node's importance at (p, n) (a leaf's: its light's own). */
static float node_importance(const light_set *s, const light_node *nd, vec3 p, vec3 n, bool cosine)
{
	if (nd->light >= 0)
		return light_importance(&s->lights[nd->light], p, n, cosine);
	vec3 to_c = v3_sub(nd->c, p);
	float d2 = v3_length2(to_c), d = sqrtf(d2);
	float cosb = has_normal(n) ? cos_bound(n, to_c, d, nd->r) : 1.0f;
	if (!(cosb > 0.0f))
		return 0.0f;
	if (!cosine)
		cosb = 1.0f;
	float x = nd->lum / fmaxf(d2, fmaxf(nd->r * nd->r, 1e-30f)) * cosb;
	return x > 0.0f && isfinite(x) ? x : 0.0f;
}

bool light_set_finish(light_set *s, float scene_radius)
{
	if (s->count == 0)
		return true;
	float *power = mem_alloc(s->count, sizeof *power);
	s->infinite = mem_alloc(s->count, sizeof *s->infinite);
	if (!power || !s->infinite) {
		mem_free(power);
		return false;
	}
	s->infinite_count = 0;
	for (size_t i = 0; i < s->count; i++) {
		light_importance_init(&s->lights[i]);
		power[i] = s->lights[i].seen_only ? 0.0f : light_power(&s->lights[i], scene_radius);
		if (light_is_infinite(&s->lights[i]))
			s->infinite[s->infinite_count++] = i;
	}
	bool ok = render_distrib1d_init(&s->select, power, s->count);
	mem_free(power);
	return ok && (s->count <= LIGHT_SET_LOCAL_MAX || tree_build(s));
}

void light_set_free(light_set *s)
{
	mem_free(s->nodes), mem_free(s->loose), mem_free(s->trail);
	for (size_t i = 0; i < s->count; i++)
		light_free(&s->lights[i]);
	mem_free(s->lights);
	mem_free(s->infinite);
	render_distrib1d_free(&s->select);
	memset(s, 0, sizeof *s);
}

size_t light_set_pick(const light_set *s, float u, float *prob)
{
	return render_distrib1d_sample_discrete(&s->select, u, prob);
}

float light_set_prob(const light_set *s, size_t i)
{
	return render_distrib1d_discrete_prob(&s->select, i);
}

/* The weights light_set_pick_at chooses by at (p, n), and their sum; false when the set is too
 * large or no weight is positive (then the choice is by power). One function for the pick and
 * its probability: the same operations, the same bits. */
static bool local_weights(const light_set *s, vec3 p, vec3 n, bool cosine, float w[LIGHT_SET_LOCAL_MAX], float *total)
{
	if (s->count > LIGHT_SET_LOCAL_MAX || s->count < 2)
		return false;
	float t = 0.0f;
	for (size_t i = 0; i < s->count; i++) {
		float x = light_importance(&s->lights[i], p, n, cosine);
		w[i] = x > 0.0f && isfinite(x) ? x : 0.0f;
		t += w[i];
	}
	*total = t;
	return t > 0.0f && isfinite(t);
}

/* The tree's top choice at (p, n): the loose lights' importances and the root's (last), their
 * sum in *total; false when none is positive. w holds loose_count + 1 values. */
static bool top_weights(const light_set *s, vec3 p, vec3 n, bool cosine, float *w, float *total)
{
	float t = 0.0f;
	for (size_t k = 0; k < s->loose_count; k++) {
		float x = light_importance(&s->lights[s->loose[k]], p, n, cosine);
		w[k] = x > 0.0f && isfinite(x) ? x : 0.0f;
		t += w[k];
	}
	w[s->loose_count] = s->node_count ? node_importance(s, &s->nodes[0], p, n, cosine) : 0.0f;
	t += w[s->loose_count];
	*total = t;
	return t > 0.0f && isfinite(t);
}

/* Picks among n weights of sum total with u: the index (the last positive one when rounding
 * leaves u over), its probability and the rest of u. */
static size_t pick_weight(const float *w, size_t n, float total, float u, float *prob, float *u_rest)
{
	float x = u * total, acc = 0.0f, lo = 0.0f;
	size_t i = 0;
	for (size_t k = 0; k < n; k++) {
		if (!(w[k] > 0.0f))
			continue;
		i = k, lo = acc;
		if (x < acc + w[k])
			break;
		acc += w[k];
	}
	*prob = w[i] / total;
	float r = *prob > 0.0f ? (u - lo / total) / *prob : 0.0f;
	*u_rest = fminf(fmaxf(r, 0.0f), 0x1.fffffep-1f);
	return i;
}

/* The descent through the tree, from the top weights w (top_weights, of sum total > 0). */
static size_t tree_pick(const light_set *s, vec3 p, vec3 n, bool cosine, const float *w, float total, float u, float *prob,
			float *u_rest)
{
	float pr;
	size_t k = pick_weight(w, s->loose_count + 1, total, u, &pr, &u);
	if (k < s->loose_count) {
		*prob = pr, *u_rest = u;
		return s->loose[k];
	}
	const light_node *nd = &s->nodes[0];
	while (nd->light < 0) {
		float wc[2] = {node_importance(s, &s->nodes[nd->child[0]], p, n, cosine),
			       node_importance(s, &s->nodes[nd->child[1]], p, n, cosine)};
		float t = wc[0] + wc[1], pc;
		if (!(t > 0.0f)) {
			*prob = 0.0f, *u_rest = u;
			return 0;
		}
		size_t c = pick_weight(wc, 2, t, u, &pc, &u);
		pr *= pc;
		nd = &s->nodes[nd->child[c]];
	}
	*prob = pr, *u_rest = u;
	return (size_t)nd->light;
}

static float tree_prob(const light_set *s, size_t i, vec3 p, vec3 n, bool cosine, const float *w, float total)
{
	for (size_t k = 0; k < s->loose_count; k++)
		if (s->loose[k] == i)
			return w[k] / total;
	float pr = w[s->loose_count] / total;
	uint64_t trail = s->trail[i];
	int depth = (int)(trail >> 58);
	const light_node *nd = &s->nodes[0];
	for (int d = 0; d < depth; d++) {
		float wc[2] = {node_importance(s, &s->nodes[nd->child[0]], p, n, cosine),
			       node_importance(s, &s->nodes[nd->child[1]], p, n, cosine)};
		float t = wc[0] + wc[1];
		int c = (int)((trail >> d) & 1u);
		if (!(t > 0.0f))
			return 0.0f;
		pr *= wc[c] / t;
		nd = &s->nodes[nd->child[c]];
	}
	return pr;
}

size_t light_set_pick_at(const light_set *s, vec3 p, vec3 n, bool cosine, float u, float *prob, float *u_rest)
{
	float w[LIGHT_SET_LOCAL_MAX], total;
	float tw[LIGHT_SET_LOCAL_MAX + 1];
	if (s->nodes && top_weights(s, p, n, cosine, tw, &total))
		return tree_pick(s, p, n, cosine, tw, total, u, prob, u_rest);
	if (local_weights(s, p, n, cosine, w, &total))
		return pick_weight(w, s->count, total, u, prob, u_rest);
	size_t i = light_set_pick(s, u, prob);
	float lo = s->count ? (float)s->select.cdf[i] : 0.0f, share = *prob;
	float r = share > 0.0f ? (u - lo) / share : 0.0f;
	*u_rest = fminf(fmaxf(r, 0.0f), 0x1.fffffep-1f);
	return i;
}

float light_set_prob_at(const light_set *s, size_t i, vec3 p, vec3 n, bool cosine)
{
	float w[LIGHT_SET_LOCAL_MAX], total;
	if (i >= s->count)
		return 0.0f;
	float tw[LIGHT_SET_LOCAL_MAX + 1];
	if (s->nodes && top_weights(s, p, n, cosine, tw, &total))
		return tree_prob(s, i, p, n, cosine, tw, total);
	if (local_weights(s, p, n, cosine, w, &total))
		return w[i] / total;
	return light_set_prob(s, i);
}
