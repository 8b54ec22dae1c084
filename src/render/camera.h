/* camera.h - POV-Ray's camera: location, look_at, sky, angle, direction, right/up, its own
 * transform, the projections of POV-Ray 3.7 but omnimax, and a thin lens (aperture, focal_point).
 * Coordinates are POV-Ray's: left-handed, +y up, the default camera at the origin looking along
 * +z. Pixel (0,0) is the top-left corner of the image. grammar/README.md (Cameras) says what the
 * scene means; this file is the one derivation of it (the render's camera and build_camera.c's
 * view for tessellation). */
#ifndef CIRCE_RENDER_CAMERA_H
#define CIRCE_RENDER_CAMERA_H

#include "base/vec.h"

#include <stdbool.h>
#include <stdint.h>

/* A ray: origin, unit direction. */
typedef struct render_ray {
	vec3 o, d;
} render_ray;

/* POV-Ray's projections (source/core/render/tracepixel.cpp, TracePixel::CreateCameraRay). */
typedef enum cam_type {
	CAM_PERSPECTIVE,
	CAM_ORTHOGRAPHIC,
	CAM_FISHEYE,
	CAM_ULTRA_WIDE_ANGLE,
	CAM_PANORAMIC,
	CAM_CYLINDER_1, /* axis along up */
	CAM_CYLINDER_2, /* axis along right */
	CAM_CYLINDER_3, /* axis along up, orthographic along up */
	CAM_CYLINDER_4, /* axis along right, orthographic along right */
	CAM_SPHERICAL,
	CAM_OMNIMAX, /* POV-Ray's: a fisheye of 180 degrees on the dome's curve, 45 below the axis cut */
	CAM_MESH,    /* POV-Ray's mesh_camera (cam_params.mesh_distribution says how a pixel finds its
			face; cam_sample) */
} cam_type;

/* A mesh_camera's faces in world space, one ray each (POV-Ray's CreateCameraRay, MESH_CAMERA):
 * the face's centroid, the mesh transform's linear part applied to the face's unit normal (the
 * offset of POV-Ray's location z, taken along the normal before the transform), and the
 * transformed unit normal (the direction). In the scene's arena; the camera only points here. */
typedef struct cam_mesh_face {
	vec3 centroid, offset, dir;
} cam_mesh_face;

/* A distribution 3 mesh_camera's face (POV-Ray's uv reverse mapping): the corners in world
 * space, at each the transform's linear part of its unit normal (the offset) and the transformed
 * normal (not renormalised: the ray's direction interpolates the three, then is normalised), and
 * the corners' uv. scene_cam_uv_face makes them, the same layout. */
typedef struct cam_uv_face {
	vec3 p[3], offset[3], dir[3];
	vec2 uv[3];
} cam_uv_face;

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
	cam_type type;	   /* default CAM_PERSPECTIVE */
	bool has_look_at;  /* false: the frame is direction, right, up as given (POV-Ray without
			      look_at; sky unused); default true */
	bool has_angle;	   /* false: the width comes from |right| / |direction| (default true) */
	vec3 direction;	   /* the zero vector: <0,0,1> */
	float v_angle_deg; /* spherical: the vertical field of view (angle_deg the horizontal) */
	bool has_xform;	   /* the camera's own translate/rotate/scale/matrix, applied last */
	xform xf;
	/* CAM_MESH: its faces, mesh k's (mesh_count of them) from mesh_first[k] to
	 * mesh_first[k + 1], the offset along each face's normal (POV-Ray's location z) and whether
	 * the rays run against the normals (direction z < 0); the frame, angle, lens and transform
	 * do not apply, as in POV-Ray. Distribution 0: face i of mesh k for ray k of pixel i (a
	 * mesh a ray per pixel); 1: face k * width * height + i of all the meshes' faces in order
	 * for ray k of mesh_rays; 2: POV-Ray's side-by-side cameras, mesh k for the k-th strip;
	 * 3: the pixel's uv on uv_faces, the first face in order holding it (uv_grid x uv_grid
	 * cells, scene_cam_uv_index's uv_start and uv_list). */
	const cam_mesh_face *mesh_faces;
	const uint32_t *mesh_first;
	uint32_t mesh_n, mesh_count;
	int mesh_distribution;
	uint32_t mesh_rays;
	const cam_uv_face *uv_faces;
	uint32_t uv_n, uv_grid;
	const uint32_t *uv_start, *uv_list;
	float mesh_offset;
	bool mesh_invert;
	float max_distance; /* POV-Ray's mesh_camera max_distance: see cam.max_distance */
} cam_params;

/* The ready camera: an orthonormal frame and the screen vectors at unit forward distance. */
typedef struct cam {
	vec3 origin;
	vec3 forward, right, up; /* unit vectors */
	float half_w, half_h;	 /* screen half extents at distance 1 along forward (orthographic:
				    in scene units) */
	float len_right, len_up; /* POV-Ray's |right| and |up|: the other projections' aspect */
	float angle;		 /* the projections' angle in radians (spherical: horizontal) */
	float v_angle;		 /* spherical: vertical, radians */
	cam_type type;
	float lens_radius, focal_distance;
	int width, height;
	/* POV-Ray's camera normal: perturbs a ray's unit direction *d as a normal pattern perturbs
	 * a surface normal, at the image point (x0, y0) in [-0.5, 0.5] (POV-Ray's x0, y0 of its
	 * perspective and orthographic cameras); thread-safe. NULL: none. */
	void (*perturb)(const void *user, float x0, float y0, vec3 *d);
	const void *perturb_user;
	const cam_mesh_face *mesh_faces; /* CAM_MESH, as cam_params */
	const uint32_t *mesh_first;
	uint32_t mesh_n, mesh_count;
	int mesh_distribution;
	uint32_t mesh_rays;
	const cam_uv_face *uv_faces;
	uint32_t uv_n, uv_grid;
	const uint32_t *uv_start, *uv_list;
	float mesh_offset;
	bool mesh_invert;
	/* POV-Ray's mesh_camera max_distance: the camera ray's first hit is sought only this far
	 * along it (the rays are unit), beyond it the ray misses (the background, fog that deep);
	 * the rays after that hit are not limited, as in POV-Ray (TraceRay's maxDepth). 0: none. */
	float max_distance;
} cam;

cam_params cam_params_default(void);
/* Builds the camera for an image of width x height pixels. False when the parameters are
 * degenerate (look_at == location, sky zero or parallel to the view, angle outside (0, 180)).
 * Nothing depends on the scene's scale: a camera 1e-9 from its look_at is as good as one 1e9
 * away, and so is one at 1e8 looking at a point 1 away. */
bool cam_init(cam *c, const cam_params *p, int width, int height);
/* cam_init with the reason of a refusal in *why (a constant string), for the scene's error. */
bool cam_init_why(cam *c, const cam_params *p, int width, int height, const char **why);
/* The primary ray through image point (px + pixel_u.x, py + pixel_u.y), pixel_u in [0,1)^2, with
 * lens_u in [0,1)^2 choosing the point on the lens (ignored for a pinhole). */
render_ray cam_ray(const cam *c, int px, int py, vec2 pixel_u, vec2 lens_u);
/* cam_ray for every projection: false where the projection has no ray (outside fisheye's
 * circle; a mesh camera's pixel past its last face), the pixel then black as in POV-Ray. */
bool cam_sample(const cam *c, int px, int py, vec2 pixel_u, vec2 lens_u, render_ray *out);

#endif
