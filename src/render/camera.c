/* camera.c - POV-Ray's perspective camera. POV-Ray sets |direction| so that `angle` spans |right|:
 * half width = tan(angle / 2) at unit distance; the vertical extent follows |up| / |right|.
 * Handedness: in POV-Ray's left-handed frame right = sky x forward (x = y x z). */
#include "render/camera.h"

#include "render/sampling.h"

/* Below this sine of the angle between the view and the sky they are treated as parallel: the
 * frame would be meaningless. Dimensionless (both are unit vectors), so it holds at any scale. */
#define CAM_PARALLEL_SIN 1e-6

cam_params cam_params_default(void)
{
	return (cam_params){
	    .location = d3(0, 0, 0),
	    .look_at = d3(0, 0, 1),
	    .sky = v3(0, 1, 0),
	    .angle_deg = 67.380135f, /* POV-Ray's, as src/lang gives a camera block: 2 atan(1.33 / 2) */
	    .right = v3(0, 0, 0),
	    .up = v3(0, 0, 0),
	    .aperture = 0.0f,
	    .focal_point = d3(0, 0, 1),
	};
}

bool cam_init(cam *c, const cam_params *p, int width, int height)
{
	if (width <= 0 || height <= 0 || !(p->angle_deg > 0.0f && p->angle_deg < 180.0f))
		return false;
	/* The frame in double, from the positions in double: only a view of length exactly 0 (or
	 * one that overflows) has no direction, whatever the scene's scale. */
	double view_len = d3_length(d3_sub(p->look_at, p->location));
	dvec3 sky = v3_to_d3(p->sky);
	double sky_len = d3_length(sky);
	if (!(view_len > 0.0) || !isfinite(view_len) || !(sky_len > 0.0) || !isfinite(sky_len))
		return false;
	dvec3 forward = d3_scale(d3_sub(p->look_at, p->location), 1.0 / view_len);
	dvec3 r = d3_cross(d3_scale(sky, 1.0 / sky_len), forward);
	double r_len = d3_length(r);
	if (!(r_len >= CAM_PARALLEL_SIN))
		return false;
	dvec3 right = d3_scale(r, 1.0 / r_len);
	c->forward = d3_to_v3(forward);
	c->right = d3_to_v3(right);
	c->up = d3_to_v3(d3_cross(forward, right));
	c->origin = d3_to_v3(p->location);
	float right_len = v3_length(p->right) > 0.0f ? v3_length(p->right) : (float)width / (float)height;
	float up_len = v3_length(p->up) > 0.0f ? v3_length(p->up) : 1.0f;
	/* POV-Ray's handedness test on the vectors as given, before look_at: with the default
	 * direction +z and up +y, a right along -x is a right-handed (mirrored) camera. */
	vec3 up0 = v3_length(p->up) > 0.0f ? p->up : v3(0, 1, 0);
	if (v3_length(p->right) > 0.0f && v3_dot(v3_cross(up0, v3(0, 0, 1)), p->right) < 0.0f)
		c->right = v3_neg(c->right);
	c->half_w = tanf(0.5f * p->angle_deg * RENDER_PI / 180.0f);
	c->half_h = c->half_w * up_len / right_len;
	c->lens_radius = 0.5f * fmaxf(p->aperture, 0.0f);
	c->focal_distance = (float)d3_dot(d3_sub(p->focal_point, p->location), forward);
	if (c->lens_radius > 0.0f && !(c->focal_distance > 0.0f))
		return false;
	c->width = width;
	c->height = height;
	return true;
}

render_ray cam_ray(const cam *c, int px, int py, vec2 pixel_u, vec2 lens_u)
{
	float sx = 2.0f * (((float)px + pixel_u.x) / (float)c->width) - 1.0f;  /* -1 left, +1 right */
	float sy = 1.0f - 2.0f * (((float)py + pixel_u.y) / (float)c->height); /* +1 top */
	vec3 d = v3_madd(v3_madd(c->forward, c->right, sx * c->half_w), c->up, sy * c->half_h);
	render_ray ray = {c->origin, v3_normalize(d)};
	if (c->lens_radius > 0.0f) {
		/* Thin lens: every ray through the lens point meets the pinhole ray on the focal plane. */
		vec3 focus = v3_madd(c->origin, d, c->focal_distance); /* d has unit forward component */
		vec2 l = render_concentric_disk(lens_u);
		vec3 o =
		    v3_madd(v3_madd(c->origin, c->right, l.x * c->lens_radius), c->up, l.y * c->lens_radius);
		ray.o = o;
		ray.d = v3_normalize(v3_sub(focus, o));
	}
	return ray;
}
