/* build_camera.c - the scene's camera, for the tessellation (scene_view) and for the render. */
#include "build/build_impl.h"

#include <math.h>

/* The scene's camera as the tessellation sees it: eye, view and vertical field of view at the
 * image's size (the default camera when the scene has none, as build_camera does). */
subd_camera scene_view(const scene *sc, const world_options *opt)
{
	const scene_camera *c = &sc->camera;
	cam_params dc = cam_params_default();
	dvec3 from = sc->has_camera ? c->location : dc.location;
	dvec3 to = sc->has_camera ? c->look_at : dc.look_at;
	double angle_deg = sc->has_camera ? c->angle_deg : dc.angle_deg;
	double aspect = (double)opt->width / (double)opt->height;
	double half_h = tan(angle_deg * M_PI / 360.0) / aspect;
	/* The view in double: a difference of positions far from the origin would cancel in float. */
	return (subd_camera){.position = d3v(from), .look = d3v(d3_sub(to, from)), .up = sc->has_camera ? d3v(c->sky) : dc.sky,
			     .fov_y_deg = (float)(2.0 * atan(half_h) * 180.0 / M_PI),
			     .image_height = (uint32_t)opt->height};
}

/* Pixels per unit of size at unit distance, at the centre of the view. */
double view_focal_px(const subd_camera *v)
{
	return 0.5 * v->image_height / tan(v->fov_y_deg * M_PI / 360.0);
}

bool build_camera(world *w, const scene *sc, const world_options *opt, diag *d)
{
	cam_params cp = cam_params_default();
	diag_loc loc = diag_noloc();
	if (sc->has_camera) {
		const scene_camera *c = &sc->camera;
		loc = c->loc;
		cp.location = c->location;
		cp.look_at = c->look_at;
		cp.sky = d3v(c->sky);
		cp.angle_deg = (float)c->angle_deg;
		/* POV-Ray's default right <1.33,0,0> is its 4:3 default image; circe fits the image
		 * instead, unless the scene sets another right. */
		bool default_right = c->right.x == 1.33 && c->right.y == 0.0 && c->right.z == 0.0;
		cp.right = default_right ? v3s(0.0f) : d3v(c->right);
		cp.up = d3v(c->up);
		cp.aperture = (float)c->aperture;
		cp.focal_point = c->has_focal_point ? c->focal_point : cp.look_at;
	}
	if (!cam_init(&w->camera, &cp, opt->width, opt->height)) {
		diag_error(d, loc, "the camera is degenerate (look_at at the location, sky along the view, or angle out of range)");
		return false;
	}
	return true;
}
