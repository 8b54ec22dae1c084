/* camera.h - POV-Ray's perspective camera: location, look_at, sky, angle, right/up, and a thin
 * lens (aperture, focal_point). Coordinates are POV-Ray's: left-handed, +y up, the default camera
 * at the origin looking along +z. Pixel (0,0) is the top-left corner of the image. */
#ifndef CIRCE_RENDER_CAMERA_H
#define CIRCE_RENDER_CAMERA_H

#include "base/vec.h"

#include <stdbool.h>

/* A ray: origin, unit direction. */
typedef struct render_ray {
	vec3 o, d;
} render_ray;

/* What the scene says; the defaults of cam_params_default() are POV-Ray's. The positions are
 * doubles, as the scene gives them: the view look_at - location and the focal distance are
 * differences of positions, which in float would cancel when both lie far from the origin. */
typedef struct cam_params {
	dvec3 location;	  /* default <0,0,0> */
	dvec3 look_at;	  /* default <0,0,1> */
	vec3 sky;	  /* default <0,1,0>: the up direction look_at keeps */
	float angle_deg;  /* horizontal field of view in degrees, default 90 */
	vec3 right;	  /* POV-Ray's right: its length sets the aspect (the zero vector: image
			     width / height); its sense sets handedness (right = -x mirrors the
			     image, POV-Ray's right-handed trick); look_at re-aims it */
	vec3 up;	  /* POV-Ray's up: only its length counts (the zero vector: 1) */
	float aperture;	   /* lens diameter in scene units; 0 is a pinhole */
	dvec3 focal_point; /* the plane through it, facing the camera, is in focus */
} cam_params;

/* The ready camera: an orthonormal frame and the screen vectors at unit forward distance. */
typedef struct cam {
	vec3 origin;
	vec3 forward, right, up; /* unit vectors */
	float half_w, half_h;	 /* screen half extents at distance 1 along forward */
	float lens_radius, focal_distance;
	int width, height;
} cam;

cam_params cam_params_default(void);
/* Builds the camera for an image of width x height pixels. False when the parameters are
 * degenerate (look_at == location, sky zero or parallel to the view, angle outside (0, 180)).
 * Nothing depends on the scene's scale: a camera 1e-9 from its look_at is as good as one 1e9
 * away, and so is one at 1e8 looking at a point 1 away. */
bool cam_init(cam *c, const cam_params *p, int width, int height);
/* The primary ray through image point (px + pixel_u.x, py + pixel_u.y), pixel_u in [0,1)^2, with
 * lens_u in [0,1)^2 choosing the point on the lens (ignored for a pinhole). */
render_ray cam_ray(const cam *c, int px, int py, vec2 pixel_u, vec2 lens_u);

#endif
