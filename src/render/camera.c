/* camera.c - POV-Ray's perspective camera. POV-Ray sets |direction| so that `angle` spans |right|:
 * half width = tan(angle / 2) at unit distance; the vertical extent follows |up| / |right|.
 * Handedness: in POV-Ray's left-handed frame right = sky x forward (x = y x z). */
#include "render/camera.h"

#include "render/sampling.h"

/* Below this the view and sky are treated as parallel: the frame would be meaningless. */
#define CAM_DEGENERATE 1e-6f

cam_params cam_params_default(void)
{
	return (cam_params){
	    .location = v3(0, 0, 0),
	    .look_at = v3(0, 0, 1),
	    .sky = v3(0, 1, 0),
	    .angle_deg = 67.380135f, /* POV-Ray's, as src/lang gives a camera block: 2 atan(1.33 / 2) */
	    .right = v3(0, 0, 0),
	    .up = v3(0, 0, 0),
	    .aperture = 0.0f,
	    .focal_point = v3(0, 0, 1),
	};
}

bool cam_init(cam *c, const cam_params *p, int width, int height)
{
	if (width <= 0 || height <= 0 || !(p->angle_deg > 0.0f && p->angle_deg < 180.0f))
		return false;
	vec3 view = v3_sub(p->look_at, p->location);
	if (v3_length(view) < CAM_DEGENERATE)
		return false;
	c->forward = v3_normalize(view);
	vec3 r = v3_cross(v3_normalize(p->sky), c->forward);
	if (v3_length(r) < CAM_DEGENERATE)
		return false;
	c->right = v3_normalize(r);
	c->up = v3_cross(c->forward, c->right);
	c->origin = p->location;
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
	c->focal_distance = v3_dot(v3_sub(p->focal_point, p->location), c->forward);
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
