/* build_camera.c - the scene's camera, for the tessellation (scene_view) and for the render. */
#include "build/build_impl.h"

#include "scene/pattern.h"

#include <math.h>
#include <stddef.h>

/* The scene's camera as cam_params, POV-Ray's default when it has none: the one derivation that
 * the render's camera (build_camera) and the tessellation's view (scene_view) both start from.
 * The field of view comes back in double too, as the scene wrote it (cam_params keeps a float),
 * for the view; loc is the camera's place, for its errors. */
static cam_params scene_cam(const scene *sc, double *angle_deg, diag_loc *loc)
{
	cam_params cp = cam_params_default();
	*angle_deg = cp.angle_deg;
	*loc = diag_noloc();
	if (!sc->has_camera)
		return cp;
	const scene_camera *c = &sc->camera;
	*loc = c->loc;
	*angle_deg = c->angle_deg;
	cp.location = c->location;
	cp.look_at = c->look_at;
	cp.sky = d3v(c->sky);
	cp.angle_deg = (float)c->angle_deg;
	/* POV-Ray's default right <1.33,0,0> is its 4:3 default image; circe fits the image
	 * instead (square pixels at any size), unless the scene writes a right. */
	cp.right = c->has_right ? d3v(c->right) : v3s(0.0f);
	cp.up = c->has_up ? d3v(c->up) : v3s(0.0f);
	cp.aperture = (float)c->aperture;
	cp.focal_point = c->has_focal_point ? c->focal_point : cp.look_at;
	cp.type = (cam_type)c->type;
	cp.has_look_at = c->has_look_at;
	cp.has_angle = c->has_angle;
	cp.direction = c->has_direction ? d3v(c->direction) : v3s(0.0f);
	cp.v_angle_deg = (float)c->v_angle_deg;
	cp.has_xform = c->has_xform;
	cp.xf = c->xf;
	if (cp.type == CAM_MESH) {
		_Static_assert(sizeof(scene_cam_face) == sizeof(cam_mesh_face) &&
				   offsetof(scene_cam_face, offset) == offsetof(cam_mesh_face, offset) &&
				   offsetof(scene_cam_face, dir) == offsetof(cam_mesh_face, dir),
			       "scene_cam_face is cam_mesh_face");
		cp.mesh_faces = (const cam_mesh_face *)c->mesh_faces;
		cp.mesh_n = c->mesh_n;
		cp.mesh_first = c->mesh_first, cp.mesh_count = c->mesh_count;
		cp.mesh_distribution = c->mesh_distribution;
		cp.mesh_rays = c->mesh_rays;
		_Static_assert(sizeof(scene_cam_uv_face) == sizeof(cam_uv_face) &&
				   offsetof(scene_cam_uv_face, offset) == offsetof(cam_uv_face, offset) &&
				   offsetof(scene_cam_uv_face, dir) == offsetof(cam_uv_face, dir) &&
				   offsetof(scene_cam_uv_face, uv) == offsetof(cam_uv_face, uv),
			       "scene_cam_uv_face is cam_uv_face");
		cp.uv_faces = (const cam_uv_face *)c->uv_faces;
		cp.uv_n = c->uv_n, cp.uv_grid = c->uv_grid;
		cp.uv_start = c->uv_start, cp.uv_list = c->uv_list;
		cp.mesh_offset = (float)c->location.z; /* POV-Ray's Location[Z], along the normal */
		cp.mesh_invert = c->has_direction && c->direction.z < -1e-10; /* POV-Ray's -EPSILON */
		cp.max_distance = (float)c->mesh_max_distance;
	}
	return cp;
}

/* The scene's camera as the tessellation sees it: eye, view and vertical field of view at the
 * image's size. */
subd_camera scene_view(const scene *sc, const world_options *opt)
{
	double angle_deg;
	diag_loc loc;
	cam_params cp = scene_cam(sc, &angle_deg, &loc);
	cam c;
	bool simple = cp.type == CAM_PERSPECTIVE && cp.has_look_at && !cp.has_xform && v3_length(cp.direction) == 0.0f;
	if (!simple && cam_init(&c, &cp, opt->width, opt->height)) {
		/* The derived frame. An orthographic screen as the perspective one of the same size
		 * at the look_at distance; a wide projection as a 90 degree view, its centre's
		 * pixel size roughly. */
		double view = d3_length(d3_sub(cp.look_at, cp.location));
		float half_h = c.type == CAM_PERSPECTIVE	 ? c.half_h
			       : c.type == CAM_ORTHOGRAPHIC && view > 0.0 ? (float)(c.half_h / view)
								       : 1.0f;
		return (subd_camera){.position = c.origin, .look = c.forward, .up = c.up,
				     .fov_y_deg = (float)(2.0 * atan(half_h) * 180.0 / M_PI),
				     .image_height = (uint32_t)opt->height};
	}
	double aspect = (double)opt->width / (double)opt->height;
	double half_h = tan(angle_deg * M_PI / 360.0) / aspect;
	/* The view in double: a difference of positions far from the origin would cancel in float. */
	return (subd_camera){.position = d3v(cp.location), .look = d3v(d3_sub(cp.look_at, cp.location)), .up = cp.sky,
			     .fov_y_deg = (float)(2.0 * atan(half_h) * 180.0 / M_PI),
			     .image_height = (uint32_t)opt->height};
}

/* Pixels per unit of size at unit distance, at the centre of the view. */
double view_focal_px(const subd_camera *v)
{
	return 0.5 * v->image_height / tan(v->fov_y_deg * M_PI / 360.0);
}

/* cam.perturb of a camera normal: POV-Ray's Perturb_Normal of the ray's direction at <x0, y0, 0>. */
static void cam_perturb(const void *user, float x0, float y0, vec3 *d)
{
	const world *w = user;
	dvec3 n = v3_to_d3(*d);
	pattern_perturb(&w->patterns, w->cam_normal, d3(x0, y0, 0), &n);
	*d = d3v(n);
}

bool build_camera(world *w, const scene *sc, const world_options *opt, diag *d)
{
	double angle_deg;
	diag_loc loc;
	cam_params cp = scene_cam(sc, &angle_deg, &loc);
	const char *why;
	if (!cam_init_why(&w->camera, &cp, opt->width, opt->height, &why)) {
		diag_error(d, loc, "the camera is degenerate: %s", why);
		return false;
	}
	if (sc->has_camera && sc->camera.normal) {
		if (!build_pattern(w, sc->camera.normal, &w->cam_normal, d))
			return false;
		w->camera.perturb = cam_perturb, w->camera.perturb_user = w;
	}
	return true;
}
