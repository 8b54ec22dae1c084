/* camera.c - POV-Ray's camera. POV-Ray sets |direction| so that `angle` spans |right|: half
 * width = tan(angle / 2) at unit distance; the vertical extent follows |up| / |right|. Without an
 * angle the half width is |right| / (2 |direction|). Handedness: in POV-Ray's left-handed frame
 * right = sky x forward (x = y x z). The projections other than perspective follow
 * TracePixel::CreateCameraRay and TracePixel::SetupCamera (POV-Ray 3.7,
 * source/core/render/tracepixel.cpp; read, not copied): their screen vectors normalised where
 * POV-Ray normalises them, |right| and |up| kept as the aspect they read. */
#include "render/camera.h"

#include "render/sampling.h"
#include "scene/scene.h" /* scene_cam_uv_cell: the uv index's cell rule */

/* Below this sine of the angle between the view and the sky they are treated as parallel: the
 * frame would be meaningless. Dimensionless (both are unit vectors), so it holds at any scale. */
#define CAM_PARALLEL_SIN 1e-6
/* The thin lens refocuses only rays within about 89.4 degrees of forward: the focal plane's
 * distance along a ray is focal_distance / cos, unbounded at 90 degrees. */
#define CAM_LENS_MIN_COS 1e-2f
/* Panoramic's tan(y0) is kept finite: POV-Ray's BOUND_HUGE at the poles; this bound is a
 * millionth of a radian short of them, tan ~ 1e6, enough to look straight up. */
#define CAM_PANORAMIC_MAX (0.5f * RENDER_PI - 1e-6f)

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
	    .type = CAM_PERSPECTIVE,
	    .has_look_at = true,
	    .has_angle = true,
	    .v_angle_deg = 180.0f,
	};
}

/* POV-Ray's camera, as its parser applies the modifiers whatever their order
 * (source/parser/parser.cpp, Parse_Camera, language >= 3.5): right, direction, angle (sets
 * |direction| = |right| / (2 tan(angle / 2))), up, sky, location, look_at (re-aims direction,
 * right = sky x direction and up = direction x right, keeping their lengths and the handedness
 * sign of (up x direction) . right), then the camera's transforms. Here the frame is kept as unit
 * vectors and the half widths at unit forward distance, the same rays. */
static const char *cam_frame(cam *c, const cam_params *p, int width, int height)
{
	float right_len = v3_length(p->right) > 0.0f ? v3_length(p->right) : (float)width / (float)height;
	float up_len = v3_length(p->up) > 0.0f ? v3_length(p->up) : 1.0f;
	vec3 dir0 = v3_length(p->direction) > 0.0f ? p->direction : v3(0, 0, 1);
	vec3 up0 = v3_length(p->up) > 0.0f ? p->up : v3(0, 1, 0);
	vec3 right0 = v3_length(p->right) > 0.0f ? p->right : v3(1, 0, 0);
	if (p->has_look_at) {
		/* The frame in double, from the positions in double: only a view of length exactly 0
		 * (or one that overflows) has no direction, whatever the scene's scale. */
		double view_len = d3_length(d3_sub(p->look_at, p->location));
		dvec3 sky = v3_to_d3(p->sky);
		double sky_len = d3_length(sky);
		if (!(view_len > 0.0) || !isfinite(view_len))
			return "look_at is the camera's location";
		if (!(sky_len > 0.0) || !isfinite(sky_len))
			return "sky is the zero vector";
		dvec3 forward = d3_scale(d3_sub(p->look_at, p->location), 1.0 / view_len);
		dvec3 r = d3_cross(d3_scale(sky, 1.0 / sky_len), forward);
		double r_len = d3_length(r);
		if (!(r_len >= CAM_PARALLEL_SIN)) {
			/* POV-Ray: sky along the view, "using default/supplied right vector instead"
			 * (scene_validate warns); up = direction x right as always */
			dvec3 r0 = v3_to_d3(right0);
			r = d3_sub(r0, d3_scale(forward, d3_dot(r0, forward)));
			r_len = d3_length(r);
			if (!(r_len >= CAM_PARALLEL_SIN * d3_length(r0)) || !(r_len > 0.0))
				return "sky and right are both parallel to the view direction";
		}
		dvec3 right = d3_scale(r, 1.0 / r_len);
		c->forward = d3_to_v3(forward);
		c->right = d3_to_v3(right);
		c->up = d3_to_v3(d3_cross(forward, right));
		c->focal_distance = (float)d3_dot(d3_sub(p->focal_point, p->location), forward);
		/* POV-Ray's handedness test on the vectors as given, before look_at: with the
		 * default direction +z and up +y, a right along -x is a right-handed (mirrored)
		 * camera; so is one whose up and direction are parallel (a handedness of 0: POV-Ray
		 * flips unless it is > 0; diffract.pov's up and direction are both z). */
		if (v3_length(p->right) > 0.0f && !(v3_dot(v3_cross(up0, dir0), p->right) > 0.0f))
			c->right = v3_neg(c->right);
	} else {
		/* No look_at: direction, right and up as given, not made orthogonal (POV-Ray's
		 * sheared cameras). */
		if (!(v3_length(dir0) > 0.0f))
			return "direction is the zero vector";
		c->forward = v3_normalize(dir0);
		c->right = v3_normalize(right0);
		c->up = v3_normalize(up0);
		if (v3_length(v3_cross(c->right, c->up)) < CAM_PARALLEL_SIN ||
		    fabsf(v3_dot(v3_cross(c->right, c->up), c->forward)) < CAM_PARALLEL_SIN)
			return "direction, right and up do not span space";
		c->focal_distance = (float)d3_dot(d3_sub(p->focal_point, p->location), v3_to_d3(c->forward));
	}
	c->origin = d3_to_v3(p->location);
	if (p->has_angle)
		c->half_w = tanf(0.5f * p->angle_deg * RENDER_PI / 180.0f);
	else
		c->half_w = 0.5f * right_len / v3_length(dir0); /* POV-Ray: x0 in [-0.5, 0.5] of right */
	c->half_h = c->half_w * up_len / right_len;
	c->len_right = right_len;
	c->len_up = up_len;
	return NULL;
}

/* The camera's own transform on the frame: points move, the screen vectors transform as
 * directions (POV-Ray's Camera::Transform: MTransPoint, MTransDirection), and |right|, |up| with
 * them (SetupCamera reads them after the transform). An orthographic screen's half widths are
 * lengths in the scene; the others' are per unit of forward. */
static const char *cam_transform(cam *c, const xform *t, bool orthographic)
{
	dvec3 f = xform_vector(t, v3_to_d3(c->forward));
	dvec3 r = xform_vector(t, v3_to_d3(c->right));
	dvec3 u = xform_vector(t, v3_to_d3(c->up));
	double fl = d3_length(f), rl = d3_length(r), ul = d3_length(u);
	if (!(fl > 0.0 && rl > 0.0 && ul > 0.0))
		return "its transform flattens it";
	double per = orthographic ? 1.0 : fl;
	c->origin = d3_to_v3(xform_point(t, v3_to_d3(c->origin)));
	c->forward = d3_to_v3(d3_scale(f, 1.0 / fl));
	c->right = d3_to_v3(d3_scale(r, 1.0 / rl));
	c->up = d3_to_v3(d3_scale(u, 1.0 / ul));
	c->half_w = (float)(c->half_w * rl / per);
	c->half_h = (float)(c->half_h * ul / per);
	c->len_right = (float)(c->len_right * rl);
	c->len_up = (float)(c->len_up * ul);
	return NULL;
}

/* POV-Ray's orthographic size (Parse_Camera, "apply orthographic"): with neither up nor right
 * given, or with an angle, right and up are scaled by |look_at - location| / |direction|, the
 * perspective camera's image area at the look_at distance; otherwise they are the screen's
 * size in scene units. */
static void cam_orthographic(cam *c, const cam_params *p)
{
	bool given = v3_length(p->right) > 0.0f || v3_length(p->up) > 0.0f;
	if (!given || p->has_angle) {
		float k = (float)d3_length(d3_sub(p->look_at, p->location));
		c->half_w *= k;
		c->half_h *= k;
	} else {
		c->half_w = 0.5f * c->len_right;
		c->half_h = 0.5f * c->len_up;
	}
}

bool cam_init_why(cam *c, const cam_params *p, int width, int height, const char **why)
{
	bool screen = p->type == CAM_PERSPECTIVE || p->type == CAM_ORTHOGRAPHIC;
	*why = NULL;
	if (width <= 0 || height <= 0)
		*why = "the image has no pixels";
	else if (screen && !(p->angle_deg > 0.0f && p->angle_deg < 180.0f))
		*why = "its angle is outside (0, 180) degrees";
	else if (!(p->angle_deg > 0.0f && p->angle_deg <= 360.0f))
		*why = "its angle is outside (0, 360] degrees";
	else if (p->type == CAM_SPHERICAL && !(p->v_angle_deg > 0.0f && p->v_angle_deg <= 180.0f))
		*why = "its vertical angle is outside (0, 180] degrees";
	if (*why)
		return false;
	*c = (cam){0}; /* no perturb unless the caller sets one after */
	if (p->type == CAM_MESH) { /* POV-Ray: the faces alone make the rays */
		c->type = CAM_MESH;
		c->mesh_faces = p->mesh_faces, c->mesh_n = p->mesh_n;
		c->mesh_first = p->mesh_first, c->mesh_count = p->mesh_count;
		c->mesh_distribution = p->mesh_distribution;
		c->mesh_rays = p->mesh_rays;
		c->uv_faces = p->uv_faces, c->uv_n = p->uv_n, c->uv_grid = p->uv_grid;
		c->uv_start = p->uv_start, c->uv_list = p->uv_list;
		c->mesh_offset = p->mesh_offset, c->mesh_invert = p->mesh_invert;
		c->max_distance = p->max_distance;
		c->width = width, c->height = height;
		bool uv = p->mesh_distribution == 3;
		if (uv ? !p->uv_faces || p->uv_n == 0 || p->uv_grid == 0 || !p->uv_start || !p->uv_list
		       : !p->mesh_faces || p->mesh_n == 0 || !p->mesh_first || p->mesh_count == 0 ||
			     (p->mesh_distribution == 1 && p->mesh_rays == 0)) {
			*why = "its mesh_camera has no faces";
			return false;
		}
		/* The first face's ray stands for the camera where one point is wanted (the
		 * tessellation's view, cam_ray's fallback). */
		if (uv) {
			const cam_uv_face *f = &p->uv_faces[0];
			c->origin = v3_scale(v3_add(v3_add(f->p[0], f->p[1]), f->p[2]), 1.0f / 3.0f);
			c->forward = v3_normalize(v3_add(v3_add(f->dir[0], f->dir[1]), f->dir[2]));
			if (!v3_is_finite(c->forward) || v3_length2(c->forward) < 0.5f)
				c->forward = v3_normalize(f->dir[0]);
		} else {
			c->origin = p->mesh_faces[0].centroid, c->forward = p->mesh_faces[0].dir;
		}
		vec3 side = fabsf(c->forward.y) < 0.9f ? v3(0.0f, 1.0f, 0.0f) : v3(1.0f, 0.0f, 0.0f);
		c->right = v3_normalize(v3_cross(side, c->forward));
		c->up = v3_cross(c->forward, c->right);
		return true;
	}
	cam_params q = *p;
	if (p->type != CAM_PERSPECTIVE && p->type != CAM_ORTHOGRAPHIC)
		q.has_angle = false; /* the angle is the projection's own, not the screen's */
	*why = cam_frame(c, &q, width, height);
	if (!*why && p->type == CAM_ORTHOGRAPHIC)
		cam_orthographic(c, p);
	if (!*why && p->has_xform)
		*why = cam_transform(c, &p->xf, p->type == CAM_ORTHOGRAPHIC);
	if (*why)
		return false;
	c->type = p->type;
	c->angle = p->angle_deg * RENDER_PI / 180.0f;
	c->v_angle = p->v_angle_deg * RENDER_PI / 180.0f;
	c->lens_radius = 0.5f * fmaxf(p->aperture, 0.0f);
	if (c->lens_radius > 0.0f && !(c->focal_distance > 0.0f)) {
		*why = "focal_point is not in front of it";
		return false;
	}
	c->width = width;
	c->height = height;
	return true;
}

bool cam_init(cam *c, const cam_params *p, int width, int height)
{
	const char *why;
	return cam_init_why(c, p, width, height, &why);
}

/* The thin lens for the projections other than perspective: the ray through a lens point meets
 * the pinhole ray on the focal plane (distance focal_distance along forward); a ray that does not
 * run forward (wide projections) keeps its pinhole. */
static render_ray cam_lens(const cam *c, render_ray ray, vec2 lens_u)
{
	float along = v3_dot(ray.d, c->forward);
	if (!(c->lens_radius > 0.0f) || !(along > CAM_LENS_MIN_COS))
		return ray;
	vec3 focus = v3_madd(ray.o, ray.d, c->focal_distance / along);
	vec2 l = render_concentric_disk(lens_u);
	vec3 o = v3_madd(v3_madd(ray.o, c->right, l.x * c->lens_radius), c->up, l.y * c->lens_radius);
	return (render_ray){o, v3_normalize(v3_sub(focus, o))};
}

/* A direction from the frame: a along right, b along up, f along forward. */
static vec3 cam_dir(const cam *c, float a, float b, float f)
{
	return v3_normalize(v3_madd(v3_madd(v3_scale(c->forward, f), c->right, a), c->up, b));
}

/* The projections of TracePixel::CreateCameraRay (POV-Ray 3.7, tracepixel.cpp), with sx, sy the
 * image point in [-1, 1] (POV-Ray's x0, y0 are sx / 2, sy / 2 for most). False: no ray. */
static bool cam_project(const cam *c, float sx, float sy, render_ray *ray)
{
	ray->o = c->origin;
	switch (c->type) {
	case CAM_ORTHOGRAPHIC:
		ray->o = v3_madd(v3_madd(c->origin, c->right, sx * c->half_w), c->up, sy * c->half_h);
		ray->d = c->forward;
		return true;
	case CAM_FISHEYE: {
		/* x0 = sx |right|, y0 = sy |up|; outside the unit circle no ray; the polar angle
		 * rad * angle / 2 from forward. */
		float x = sx * c->len_right, y = sy * c->len_up, rad = sqrtf(x * x + y * y);
		if (rad > 1.0f)
			return false;
		float phi = rad > 0.0f ? atan2f(y, x) : 0.0f, theta = 0.5f * rad * c->angle;
		ray->d = cam_dir(c, cosf(phi) * sinf(theta), sinf(phi) * sinf(theta), cosf(theta));
		return true;
	}
	case CAM_ULTRA_WIDE_ANGLE: {
		/* x0 = sx / 2 angle, y0 = sy / 2 angle |up| / |right|. */
		float x = 0.5f * sx * c->angle, y = 0.5f * sy * c->angle * c->len_up / c->len_right;
		ray->d = cam_dir(c, sinf(x), sinf(y), cosf(x) * cosf(y));
		return true;
	}
	case CAM_PANORAMIC: {
		/* Graphics Gems III's: x0 = (1 - x / width) pi across a half turn, y0 = sy pi / 2
		 * through tan; the screen vectors at their lengths (2 half_w right, 2 half_h up). */
		float x = 0.5f * (1.0f - sx) * RENDER_PI;
		float y = fminf(fmaxf(0.5f * sy * RENDER_PI, -CAM_PANORAMIC_MAX), CAM_PANORAMIC_MAX);
		ray->d = cam_dir(c, cosf(x) * 2.0f * c->half_w, tanf(y) * 2.0f * c->half_h, sinf(x));
		return true;
	}
	case CAM_CYLINDER_1:
	case CAM_CYLINDER_3: {
		/* The axis along up: x0 = sx / 2 angle around it, y0 = sy / 2 |up| along it. */
		float x = 0.5f * sx * c->angle, y = 0.5f * sy * c->len_up;
		if (c->type == CAM_CYLINDER_1) {
			ray->d = cam_dir(c, sinf(x), y, cosf(x));
		} else {
			ray->d = cam_dir(c, sinf(x), 0.0f, cosf(x));
			ray->o = v3_madd(c->origin, c->up, y);
		}
		return true;
	}
	case CAM_CYLINDER_2:
	case CAM_CYLINDER_4: {
		/* The axis along right: y0 = sy / 2 angle around it, x0 = sx / 2 |right| along it. */
		float y = 0.5f * sy * c->angle, x = 0.5f * sx * c->len_right;
		if (c->type == CAM_CYLINDER_2) {
			ray->d = cam_dir(c, x, sinf(y), cosf(y));
		} else {
			ray->d = cam_dir(c, 0.0f, sinf(y), cosf(y));
			ray->o = v3_madd(c->origin, c->right, x);
		}
		return true;
	}
	case CAM_SPHERICAL: {
		/* Latitude sy / 2 v_angle about right, then longitude sx / 2 h_angle about up. */
		float lon = 0.5f * sx * c->angle, lat = 0.5f * sy * c->v_angle;
		ray->d = cam_dir(c, cosf(lat) * sinf(lon), sinf(lat), cosf(lat) * cosf(lon));
		return true;
	}
	case CAM_OMNIMAX: {
		/* POV-Ray's omnimax: sx, sy fitted to its 4:3 aspect (1.283458 the dome's), the polar
		 * angle 1.411269 r - 0.09439 r^3 + 0.25674 r^5 of the radius r (no ray outside the
		 * unit circle, nor below 45 degrees under the axis). */
		const float aspect = 4.0f / 3.0f;
		float x = sx, y = sy;
		if (aspect > 1.283458f)
			x *= aspect / 1.283458f, y = (y - 1.0f) / 1.283458f + 1.0f;
		float rad = sqrtf(x * x + y * y);
		if (rad > 1.0f)
			return false;
		float phi = rad == 0.0f ? 0.0f : x < 0.0f ? RENDER_PI - asinf(y / rad) : asinf(y / rad);
		float th = 1.411269f * rad - 0.09439f * rad * rad * rad + 0.25674f * rad * rad * rad * rad * rad;
		float cx = cosf(phi), sx2 = sinf(phi), cy = cosf(th), sy2 = sinf(th);
		if (sx2 * sy2 < tanf(135.0f * RENDER_PI / 180.0f) * cy)
			return false;
		ray->d = cam_dir(c, cx * sy2, sx2 * sy2, cy);
		return true;
	}
	case CAM_PERSPECTIVE:
	case CAM_MESH: break; /* cam_sample's own */
	}
	return false;
}

static render_ray cam_perspective(const cam *c, float sx, float sy, vec2 lens_u)
{
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

/* POV-Ray's distribution 3 (tracepixel.cpp's CreateCameraRay, 3.8's pixel centres): the image
 * point (px + pixel_u.x, py + pixel_u.y) is uv (x / width, 1 - y / height); the first face in order
 * whose uv triangle holds it (its barycentrics from the uv, none below 0, as POV-Ray computes
 * them) gives the ray: from the point of the same barycentrics on the face, moved mesh_offset
 * along the interpolated normal, in the direction of the interpolated transformed normal
 * (normalised). No face, no ray. The sub-pixel position counts here, as POV-Ray's antialiasing
 * does for this type. */
static bool cam_uv_sample(const cam *c, int px, int py, vec2 pixel_u, render_ray *out)
{
	double u = ((double)px + (double)pixel_u.x) / (double)c->width;
	double v = 1.0 - ((double)py + (double)pixel_u.y) / (double)c->height;
	uint32_t g = c->uv_grid, cell = scene_cam_uv_cell(v, g) * g + scene_cam_uv_cell(u, g);
	for (uint32_t k = c->uv_start[cell]; k < c->uv_start[cell + 1]; k++) {
		const cam_uv_face *f = &c->uv_faces[c->uv_list[k]];
		double p1u = f->uv[0].x, p2u = f->uv[1].x, p3u = f->uv[2].x;
		double p1v = f->uv[0].y, p2v = f->uv[1].y, p3v = f->uv[2].y;
		double scale = (p2u - p1u) * (p3v - p1v) - (p3u - p1u) * (p2v - p1v);
		double b1 = ((p2u - u) * (p3v - v) - (p3u - u) * (p2v - v)) / scale;
		double b2 = ((p3u - u) * (p1v - v) - (p1u - u) * (p3v - v)) / scale;
		double b3 = ((p1u - u) * (p2v - v) - (p2u - u) * (p1v - v)) / scale;
		if (b1 < 0 || b2 < 0 || b3 < 0)
			continue;
		float w[3] = {(float)b1, (float)b2, (float)b3};
		vec3 o = v3s(0.0f), off = v3s(0.0f), d = v3s(0.0f);
		for (int i = 0; i < 3; i++) {
			o = v3_madd(o, f->p[i], w[i]);
			off = v3_madd(off, f->offset[i], w[i]);
			d = v3_madd(d, f->dir[i], w[i]);
		}
		d = v3_normalize(d);
		if (!v3_is_finite(d) || !(v3_length2(d) > 0.5f)) /* opposite normals cancelling */
			return false;
		out->o = v3_madd(o, off, c->mesh_offset);
		out->d = c->mesh_invert ? v3_scale(d, -1.0f) : d;
		return v3_is_finite(out->o);
	}
	return false;
}

bool cam_sample(const cam *c, int px, int py, vec2 pixel_u, vec2 lens_u, render_ray *out)
{
	float sx = 2.0f * (((float)px + pixel_u.x) / (float)c->width) - 1.0f;  /* -1 left, +1 right */
	float sy = 1.0f - 2.0f * (((float)py + pixel_u.y) / (float)c->height); /* +1 top */
	if (c->type == CAM_MESH) {
		if (px < 0 || py < 0 || px >= c->width || py >= c->height)
			return false;
		if (c->mesh_distribution == 3)
			return cam_uv_sample(c, px, py, pixel_u, out);
		/* POV-Ray's distribution 0: the pixel's index is its face's in the mesh of the ray; past
		 * the mesh's last face, no ray. The sub-pixel position is lost, as in POV-Ray (its x, y
		 * floored); pixel_u.x picks one of the pixel's rays that exist instead, so the samples
		 * average those alone, as POV-Ray divides by the rays it shot. */
		uint32_t k = 0;
		uint64_t i = (uint64_t)py * (uint64_t)c->width + (uint64_t)px;
		if (c->mesh_distribution == 1) {
			/* POV-Ray's distribution 1 as its documentation and tracepixel.cpp's comment
			 * give it: the meshes' faces summed in order, ray k of pixel i from face
			 * k * width * height + i, no ray where that passes the last face; pixel_u.x
			 * picks one of the pixel's rays that exist, so the samples average those alone,
			 * as POV-Ray divides by the rays it shot. (POV-Ray 3.7's code adds k times the
			 * faces, not the pixels: its rays after the first never exist.) */
			uint64_t npix = (uint64_t)c->width * (uint64_t)c->height, total = c->mesh_n;
			if (i >= total)
				return false;
			uint64_t count = (total - 1 - i) / npix + 1;
			if (count > c->mesh_rays)
				count = c->mesh_rays;
			uint64_t r = (uint64_t)(pixel_u.x * (float)count);
			if (r >= count)
				r = count - 1;
			const cam_mesh_face *f = &c->mesh_faces[i + r * npix];
			out->o = v3_madd(f->centroid, f->offset, c->mesh_offset);
			out->d = c->mesh_invert ? v3_scale(f->dir, -1.0f) : f->dir;
			return true;
		}
		if (c->mesh_distribution == 2) {
			/* POV-Ray's distribution 2: mesh k for the k-th of mesh_count strips, its face
			 * y * (width / mesh_count) + x with x the image's column (not the strip's), as
			 * POV-Ray 3.7 computes it */
			k = (uint32_t)((double)px / ((double)c->width / (double)c->mesh_count));
			i = (uint64_t)py * (uint64_t)((uint32_t)c->width / c->mesh_count) + (uint64_t)px;
		}
		if (c->mesh_distribution == 0) { /* the j-th of the meshes with a face i */
			uint32_t have = 0;
			for (uint32_t m = 0; m < c->mesh_count; m++)
				have += i < (uint64_t)(c->mesh_first[m + 1] - c->mesh_first[m]);
			if (have == 0)
				return false;
			uint32_t j = (uint32_t)(pixel_u.x * (float)have);
			j = j < have ? j : have - 1;
			for (k = 0; k < c->mesh_count; k++)
				if (i < (uint64_t)(c->mesh_first[k + 1] - c->mesh_first[k]) && j-- == 0)
					break;
		}
		if (k >= c->mesh_count)
			k = c->mesh_count - 1;
		uint32_t from = c->mesh_first[k], to = c->mesh_first[k + 1];
		if (i >= (uint64_t)(to - from))
			return false;
		const cam_mesh_face *f = &c->mesh_faces[from + i];
		out->o = v3_madd(f->centroid, f->offset, c->mesh_offset);
		out->d = c->mesh_invert ? v3_scale(f->dir, -1.0f) : f->dir;
		return true;
	}
	if (c->type == CAM_PERSPECTIVE) {
		*out = cam_perspective(c, sx, sy, lens_u);
	} else {
		if (!cam_project(c, sx, sy, out))
			return false;
		*out = cam_lens(c, *out, lens_u);
	}
	if (c->perturb) { /* TracePixel::CreateCameraRay's Perturb_Normal of the direction, last */
		vec3 d = out->d;
		c->perturb(c->perturb_user, 0.5f * sx, 0.5f * sy, &d);
		d = v3_normalize(d);
		if (v3_is_finite(d) && v3_length2(d) > 0.5f)
			out->d = d;
	}
	return true;
}

render_ray cam_ray(const cam *c, int px, int py, vec2 pixel_u, vec2 lens_u)
{
	render_ray r;
	if (!cam_sample(c, px, py, pixel_u, lens_u, &r))
		r = (render_ray){c->origin, c->forward};
	return r;
}
