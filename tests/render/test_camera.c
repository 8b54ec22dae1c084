/* test_camera: the centre ray points at look_at, `angle` is the horizontal field of view, the image
 * is upright and not mirrored in POV-Ray's left-handed frame, and the thin lens focuses. */
#include "base/rng.h"
#include "check.h"
#include "render/camera.h"
#include "scene/scene.h"

/* The ray through image point (sx, sy) in [-1, 1]^2 (+1 right, +1 top) of a 2 x 2 image. */
static bool ray_at(const cam *c, float sx, float sy, render_ray *r)
{
	return cam_sample(c, 0, 0, v2(sx + 1.0f, 1.0f - sy), v2(0.5f, 0.5f), r);
}

static bool near3(vec3 a, vec3 b, float tol)
{
	return fabsf(a.x - b.x) <= tol && fabsf(a.y - b.y) <= tol && fabsf(a.z - b.z) <= tol;
}

#define CHECK_RAY(c, sx, sy, want_o, want_d, what)                                                        \
	do {                                                                                              \
		render_ray r_;                                                                            \
		CHECK(ray_at(c, sx, sy, &r_), "%s: no ray at (%g, %g)", what, (double)(sx), (double)(sy)); \
		vec3 wd_ = v3_normalize(want_d), wo_ = (want_o);                                          \
		CHECK(near3(r_.d, wd_, 1e-5f) && near3(r_.o, wo_, 1e-5f),                                 \
		      "%s at (%g, %g): ray (%g %g %g) + t (%g %g %g), want (%g %g %g) + t (%g %g %g)", what,  \
		      (double)(sx), (double)(sy), r_.o.x, r_.o.y, r_.o.z, r_.d.x, r_.d.y, r_.d.z, wo_.x, wo_.y, \
		      wo_.z, wd_.x, wd_.y, wd_.z);                                                        \
	} while (0)

/* Each projection against rays worked by hand from POV-Ray 3.7's formulas (tracepixel.cpp,
 * CreateCameraRay), the default frame: forward +z, right +x, up +y. */
static void test_projections(void)
{
	cam c;
	const float h = 0.70710678f; /* sin 45 = cos 45 */
	vec3 o = v3(0, 0, 0);
	cam_params p = cam_params_default();
	p.right = v3(1, 0, 0);
	p.up = v3(0, 1, 0);
	p.has_angle = false;

	/* Perspective without angle: half width |right| / (2 |direction|). */
	p.direction = v3(0, 0, 2);
	p.has_look_at = false;
	CHECK(cam_init(&c, &p, 2, 2), "perspective from direction");
	CHECK_RAY(&c, 1, 0, o, v3(0.25f, 0, 1), "perspective |direction| 2");
	/* ... and angle wins over direction's length (POV-Ray sets |direction| from it). */
	p.has_angle = true;
	p.angle_deg = 90;
	CHECK(cam_init(&c, &p, 2, 2), "perspective angle 90");
	CHECK_RAY(&c, 1, -1, o, v3(1, -1, 1), "perspective angle 90");
	p.direction = v3(0, 0, 0);
	p.has_look_at = true;

	/* Orthographic, right and up given without angle: the screen is right x up in scene units. */
	cam_params q = p;
	q.type = CAM_ORTHOGRAPHIC;
	q.has_angle = false;
	q.right = v3(4, 0, 0);
	q.up = v3(0, 3, 0);
	q.location = d3(1, 2, -5);
	q.look_at = d3(1, 2, 0);
	CHECK(cam_init(&c, &q, 2, 2), "orthographic");
	CHECK_RAY(&c, 0.5f, -1, v3(2, 0.5f, -5), v3(0, 0, 1), "orthographic right 4 up 3");
	/* A camera scale scales the orthographic screen (and the location) with the scene. */
	q.has_xform = xform_scale(d3(2, 2, 2), &q.xf);
	CHECK(cam_init(&c, &q, 2, 2), "scaled orthographic");
	CHECK_RAY(&c, 0.5f, -1, v3(4, 1, -10), v3(0, 0, 1), "orthographic scaled by 2");
	q.has_xform = false;
	/* With an angle: the perspective image's area at the look_at distance (5 tan 45 = 5). */
	q.has_angle = true;
	q.angle_deg = 90;
	q.right = v3(1, 0, 0);
	q.up = v3(0, 1, 0);
	CHECK(cam_init(&c, &q, 2, 2), "orthographic angle");
	CHECK_RAY(&c, 1, 1, v3(6, 7, -5), v3(0, 0, 1), "orthographic angle 90 at distance 5");
	/* Thin lens on it: every lens ray meets the pinhole ray at the focal distance 4. */
	q.aperture = 1;
	q.focal_point = d3(1, 2, -1);
	CHECK(cam_init(&c, &q, 2, 2), "orthographic lens");
	for (int i = 0; i < 16; i++) {
		render_ray lr;
		CHECK(cam_sample(&c, 0, 0, v2(1.5f, 0.5f), v2((float)(i % 4) / 4, (float)(i / 4) / 4), &lr), "lens ray");
		vec3 at = v3_madd(lr.o, lr.d, (-1.0f - lr.o.z) / lr.d.z);
		CHECK(near3(at, v3(3.5f, 4.5f, -1), 1e-4f), "orthographic lens ray meets (%g %g %g)", at.x, at.y, at.z);
	}

	/* Fisheye 180: the circle's edge looks sideways, its inside at rad * 90 degrees. */
	q = p;
	q.type = CAM_FISHEYE;
	q.angle_deg = 180;
	CHECK(cam_init(&c, &q, 2, 2), "fisheye");
	CHECK_RAY(&c, 1, 0, o, v3(1, 0, 0), "fisheye edge");
	float th = 0.70710678f * 0.5f * (float)M_PI;
	CHECK_RAY(&c, 0.5f, 0.5f, o, v3(h * sinf(th), h * sinf(th), cosf(th)), "fisheye diagonal");
	render_ray none;
	CHECK(!ray_at(&c, 1, 1, &none), "fisheye: a corner outside the circle has a ray");

	q.type = CAM_ULTRA_WIDE_ANGLE;
	CHECK(cam_init(&c, &q, 2, 2), "ultra_wide_angle");
	CHECK_RAY(&c, 1, 0, o, v3(1, 0, 0), "ultra_wide_angle edge");
	CHECK_RAY(&c, 0.5f, 0.5f, o, v3(h, h, 0.5f), "ultra_wide_angle diagonal");

	/* Panoramic: x0 = (1 - x / width) pi, the vertical through tan. */
	q.type = CAM_PANORAMIC;
	CHECK(cam_init(&c, &q, 2, 2), "panoramic");
	CHECK_RAY(&c, -1, 0, o, v3(-1, 0, 0), "panoramic left edge");
	CHECK_RAY(&c, 0, 0.5f, o, v3(0, 1, 1), "panoramic centre column, 45 up");

	q.type = CAM_CYLINDER_1;
	q.angle_deg = 90;
	CHECK(cam_init(&c, &q, 2, 2), "cylinder 1");
	CHECK_RAY(&c, 1, 1, o, v3(h, 0.5f, h), "cylinder 1");
	q.type = CAM_CYLINDER_2;
	CHECK(cam_init(&c, &q, 2, 2), "cylinder 2");
	CHECK_RAY(&c, 1, 1, o, v3(0.5f, h, h), "cylinder 2");
	q.type = CAM_CYLINDER_3;
	CHECK(cam_init(&c, &q, 2, 2), "cylinder 3");
	CHECK_RAY(&c, 1, 1, v3(0, 0.5f, 0), v3(h, 0, h), "cylinder 3");
	q.type = CAM_CYLINDER_4;
	CHECK(cam_init(&c, &q, 2, 2), "cylinder 4");
	CHECK_RAY(&c, 1, 1, v3(0.5f, 0, 0), v3(0, h, h), "cylinder 4");

	q.type = CAM_SPHERICAL;
	q.angle_deg = 360;
	q.v_angle_deg = 180;
	CHECK(cam_init(&c, &q, 2, 2), "spherical");
	CHECK_RAY(&c, 0.5f, 0, o, v3(1, 0, 0), "spherical quarter turn");
	CHECK_RAY(&c, 0, 1, o, v3(0, 1, 0), "spherical top");
	CHECK_RAY(&c, -1, 0, o, v3(0, 0, -1), "spherical half turn");

	/* The camera's transform, after everything: rotate y 90 (+z to +x), then translate. */
	q = cam_params_default();
	q.has_xform = true;
	q.xf = xform_then(xform_rotate(d3(0, 90, 0)), xform_translate(d3(1, 2, 3)));
	CHECK(cam_init(&c, &q, 2, 2), "transformed camera");
	CHECK_RAY(&c, 0, 0, v3(1, 2, 3), v3(1, 0, 0), "rotated and translated camera");

	/* Degenerate frames are refused with a reason. */
	const char *why = NULL;
	q = p;
	q.has_look_at = false;
	q.up = v3(1, 0, 0);
	CHECK(!cam_init_why(&c, &q, 2, 2, &why) && why, "up parallel to right accepted");
	q = p;
	q.has_look_at = false;
	q.direction = v3(0, 1, 0);
	CHECK(!cam_init_why(&c, &q, 2, 2, &why) && why, "direction in the right-up plane accepted");
}

static double angle_deg(vec3 a, vec3 b)
{
	double c = v3_dot(v3_normalize(a), v3_normalize(b));
	return acos(c > 1 ? 1 : c < -1 ? -1 : c) * 180.0 / M_PI;
}

/* A camera normal's callback for the test: tilts the direction by (x0, y0) along the camera's
 * right and up, and records what it was given. */
static float seen_x0, seen_y0;
static void tilt(const void *user, float x0, float y0, vec3 *d)
{
	const cam *c = user;
	seen_x0 = x0, seen_y0 = y0;
	*d = v3_add(*d, v3_add(v3_scale(c->right, 0.3f * x0), v3_scale(c->up, 0.3f * y0)));
}

/* POV-Ray's camera normal (cam.perturb): called with the image point in [-0.5, 0.5] (+y up), the
 * ray's direction perturbed and normalised, its origin unchanged. */
static void test_perturb(void)
{
	cam c;
	cam_params p = cam_params_default();
	p.location = d3(0, 1, -4);
	p.look_at = d3(0, 1, 0);
	for (int type = 0; type < 2; type++) {
		p.type = type ? CAM_ORTHOGRAPHIC : CAM_PERSPECTIVE;
		CHECK(cam_init(&c, &p, 200, 100), "cam_init");
		render_ray plain = cam_ray(&c, 150, 20, v2(0.5f, 0.5f), v2(0, 0));
		c.perturb = tilt, c.perturb_user = &c;
		render_ray bent = cam_ray(&c, 150, 20, v2(0.5f, 0.5f), v2(0, 0));
		c.perturb = NULL;
		CHECK_NEAR(seen_x0, 150.5 / 200 - 0.5, 1e-6);
		CHECK_NEAR(seen_y0, 0.5 - 20.5 / 100, 1e-6);
		vec3 want = v3_normalize(v3_add(plain.d, v3_add(v3_scale(c.right, 0.3f * seen_x0), v3_scale(c.up, 0.3f * seen_y0))));
		CHECK(angle_deg(bent.d, want) < 1e-3, "type %d: the bent ray (%g %g %g), want (%g %g %g)", type, bent.d.x,
		      bent.d.y, bent.d.z, want.x, want.y, want.z);
		CHECK(angle_deg(bent.d, plain.d) > 1.0, "type %d: the ray is bent", type);
		CHECK(v3_length(v3_sub(bent.o, plain.o)) < 1e-6f, "type %d: the origin stays", type);
		CHECK_NEAR(v3_length(bent.d), 1.0, 1e-5);
	}
}

/* POV-Ray's omnimax (tracepixel.cpp): the image centre looks forward; at image radius r (in its
 * 4:3 frame fitted to 1.283458) the ray is 1.411269 r - 0.09439 r^3 + 0.25674 r^5 radians off the
 * axis; no ray outside the unit circle, nor more than 45 degrees below the axis. */
static void test_omnimax(void)
{
	cam c;
	cam_params p = cam_params_default();
	p.location = d3(0, 0, 0);
	p.look_at = d3(0, 0, 1);
	p.type = CAM_OMNIMAX;
	CHECK(cam_init(&c, &p, 400, 400), "cam_init omnimax");
	render_ray r;
	/* the axis lies below the image's centre, at sy = 1 - 1.283458: pixel row 256.69 of 400 */
	CHECK(cam_sample(&c, 199, 256, v2(1, 0.6917f), v2(0, 0), &r) && angle_deg(r.d, c.forward) < 2e-2,
	      "omnimax axis: %g degrees off", angle_deg(r.d, c.forward));
	/* along +x from the centre: sx = 0.5 is x = 0.5 * (4/3) / 1.283458 in the dome's frame */
	CHECK(cam_sample(&c, 299, 199, v2(1, 1), v2(0, 0), &r), "omnimax at sx 0.5");
	double x = 0.5 * (4.0 / 3.0) / 1.283458, y = (0.0 - 1.0) / 1.283458 + 1.0, rad = sqrt(x * x + y * y);
	double th = 1.411269 * rad - 0.09439 * pow(rad, 3) + 0.25674 * pow(rad, 5);
	CHECK_NEAR(angle_deg(r.d, c.forward), th * 180 / M_PI, 2e-2);
	CHECK(!cam_sample(&c, 0, 0, v2(0, 0), v2(0, 0), &r), "omnimax: no ray in the corner");
	/* the top edge's middle: r = 1, 1.411269 - 0.09439 + 0.25674 radians (90.16 degrees) above the axis */
	CHECK(cam_sample(&c, 199, 0, v2(1, 0), v2(0, 0), &r) && r.d.y > 0, "omnimax top");
	CHECK_NEAR(angle_deg(r.d, c.forward), (1.411269 - 0.09439 + 0.25674) * 180 / M_PI, 2e-2);
}

/* POV-Ray's mesh_camera, distribution 0 (tracepixel.cpp's MESH_CAMERA): pixel i shoots from face i
 * of the ray's mesh, at the centroid moved location z along the face normal, in the direction of
 * the normal cross(P3 - P1, P2 - P1) (reversed by direction z < 0), under the mesh's transform;
 * no ray past the mesh's last face. Values by hand. */
static void test_mesh_camera(void)
{
	xform sc, t;
	CHECK(xform_scale(d3(2, 2, 2), &sc), "scale");
	t = xform_then(xform_translate(d3(2, 0, 0)), sc); /* x' = 2 (x + 2), y' = 2 y, z' = 2 z */
	scene_cam_face f[3];
	CHECK(scene_cam_face_make(d3(0, 0, 0), d3(0, 1, 0), d3(1, 0, 0), &t, &f[0]), "face A");
	CHECK(scene_cam_face_make(d3(0, 0, 0), d3(1, 0, 0), d3(0, 1, 0), &t, &f[1]), "face B");
	CHECK(!scene_cam_face_make(d3(0, 0, 0), d3(1, 1, 1), d3(2, 2, 2), &t, &f[2]), "a degenerate face is a face");
	/* A and B: centroid (1/3, 1/3, 0) -> (14/3, 2/3, 0); normals +z (A) and -z (B), offset twice that. */
	CHECK(near3(f[0].centroid, v3(14.0f / 3, 2.0f / 3, 0), 1e-5f) && near3(f[0].dir, v3(0, 0, 1), 1e-6f) &&
		  near3(f[0].offset, v3(0, 0, 2), 1e-6f),
	      "face A: centroid (%g %g %g) dir (%g %g %g)", f[0].centroid.x, f[0].centroid.y, f[0].centroid.z,
	      f[0].dir.x, f[0].dir.y, f[0].dir.z);
	CHECK(near3(f[1].dir, v3(0, 0, -1), 1e-6f), "face B's normal (%g %g %g)", f[1].dir.x, f[1].dir.y, f[1].dir.z);
	/* A non-uniform scale <2,1,1> of (0,0,0) (0,0,1) (1,1,0): normal (1,-1,0)/sqrt 2, centroid
	 * (1/3,1/3,1/3) -> (2/3,1/3,1/3); offset S n = (2,-1,0)/sqrt 2; direction S^-T n ~ (1,-2,0)/sqrt 5. */
	xform s2;
	CHECK(xform_scale(d3(2, 1, 1), &s2), "scale 2 1 1");
	CHECK(scene_cam_face_make(d3(0, 0, 0), d3(0, 0, 1), d3(1, 1, 0), &s2, &f[2]), "face C");
	float r2 = 1.0f / sqrtf(2.0f), r5 = 1.0f / sqrtf(5.0f);
	CHECK(near3(f[2].centroid, v3(2.0f / 3, 1.0f / 3, 1.0f / 3), 1e-6f) && near3(f[2].offset, v3(2 * r2, -r2, 0), 1e-6f) &&
		  near3(f[2].dir, v3(r5, -2 * r5, 0), 1e-6f),
	      "face C: centroid (%g %g %g) offset (%g %g %g) dir (%g %g %g)", f[2].centroid.x, f[2].centroid.y,
	      f[2].centroid.z, f[2].offset.x, f[2].offset.y, f[2].offset.z, f[2].dir.x, f[2].dir.y, f[2].dir.z);

	/* Two meshes on a 2 x 2 image: mesh 0 = A, B; mesh 1 = C; location z 0.5. */
	_Static_assert(sizeof(scene_cam_face) == sizeof(cam_mesh_face), "layout");
	const uint32_t first[3] = {0, 2, 3};
	cam_params p = cam_params_default();
	p.type = CAM_MESH;
	p.mesh_faces = (const cam_mesh_face *)f, p.mesh_n = 3, p.mesh_first = first, p.mesh_count = 2;
	p.mesh_offset = 0.5f;
	cam c;
	CHECK(cam_init(&c, &p, 2, 2), "mesh camera");
	CHECK(near3(c.origin, f[0].centroid, 0) && near3(c.forward, f[0].dir, 0) && fabsf(v3_dot(c.up, c.forward)) < 1e-6f &&
		  fabsf(v3_length(c.up) - 1) < 1e-6f && fabsf(v3_dot(c.right, c.up)) < 1e-6f,
	      "mesh camera's frame: the first face's ray, an orthonormal up and right");
	render_ray r;
	CHECK(cam_sample(&c, 0, 0, v2(0.1f, 0.9f), v2(0, 0), &r), "pixel 0, mesh 0");
	CHECK(near3(r.o, v3(14.0f / 3, 2.0f / 3, 1), 1e-5f) && near3(r.d, v3(0, 0, 1), 1e-6f),
	      "pixel 0: o (%g %g %g) d (%g %g %g)", r.o.x, r.o.y, r.o.z, r.d.x, r.d.y, r.d.z);
	CHECK(cam_sample(&c, 1, 0, v2(0.4f, 0.2f), v2(0, 0), &r), "pixel 1, mesh 0");
	CHECK(near3(r.o, v3(14.0f / 3, 2.0f / 3, -1), 1e-5f) && near3(r.d, v3(0, 0, -1), 1e-6f),
	      "pixel 1: o (%g %g %g) d (%g %g %g)", r.o.x, r.o.y, r.o.z, r.d.x, r.d.y, r.d.z);
	CHECK(!cam_sample(&c, 0, 1, v2(0.1f, 0.5f), v2(0, 0), &r), "pixel 2 past mesh 0's faces has a ray");
	CHECK(cam_sample(&c, 0, 0, v2(0.75f, 0.5f), v2(0, 0), &r), "pixel 0, mesh 1");
	CHECK(near3(r.o, v3(2.0f / 3 + r2, 1.0f / 3 - 0.5f * r2, 1.0f / 3), 1e-5f) && near3(r.d, v3(r5, -2 * r5, 0), 1e-6f),
	      "pixel 0 of mesh 1: o (%g %g %g) d (%g %g %g)", r.o.x, r.o.y, r.o.z, r.d.x, r.d.y, r.d.z);
	/* pixel 1 is past mesh 1's one face: POV-Ray shoots its ray 0 alone and divides by 1, so
	 * every sample takes mesh 0's face 1 */
	for (float x = 0.05f; x < 1.0f; x += 0.3f)
		CHECK(cam_sample(&c, 1, 0, v2(x, 0.5f), v2(0, 0), &r) && near3(r.o, v3(14.0f / 3, 2.0f / 3, -1), 1e-5f) &&
			  near3(r.d, v3(0, 0, -1), 1e-6f),
		      "pixel 1 at %g, past mesh 1's faces: mesh 0's face 1 (o %g %g %g)", x, r.o.x, r.o.y, r.o.z);
	p.mesh_invert = true; /* direction z < 0 */
	CHECK(cam_init(&c, &p, 2, 2), "inverted mesh camera");
	CHECK(cam_sample(&c, 1, 0, v2(0.4f, 0.2f), v2(0, 0), &r), "pixel 1 inverted");
	CHECK(near3(r.o, v3(14.0f / 3, 2.0f / 3, -1), 1e-5f) && near3(r.d, v3(0, 0, 1), 1e-6f),
	      "pixel 1 inverted: o (%g %g %g) d (%g %g %g)", r.o.x, r.o.y, r.o.z, r.d.x, r.d.y, r.d.z);
	/* Distribution 2 on a 4 x 1 image, mesh 0 = A, B and mesh 1 = A, B, C: pixels 0 and 1 the left
	 * strip (faces 0, 1 of mesh 0), pixels 2 and 3 the right (faces 2, 3 of mesh 1: POV-Ray's
	 * y * (width / 2) + x with the image's x), face 3 past mesh 1's last. */
	const scene_cam_face g[5] = {f[0], f[1], f[0], f[1], f[2]};
	const uint32_t first2[3] = {0, 2, 5};
	p.mesh_faces = (const cam_mesh_face *)g, p.mesh_n = 5, p.mesh_first = first2;
	p.mesh_distribution = 2, p.mesh_invert = false;
	CHECK(cam_init(&c, &p, 4, 1), "mesh camera distribution 2");
	CHECK(cam_sample(&c, 1, 0, v2(0.9f, 0.5f), v2(0, 0), &r) && near3(r.d, v3(0, 0, -1), 1e-6f),
	      "distribution 2, pixel 1: face B of mesh 0");
	CHECK(cam_sample(&c, 2, 0, v2(0.1f, 0.5f), v2(0, 0), &r) && near3(r.d, v3(r5, -2 * r5, 0), 1e-6f),
	      "distribution 2, pixel 2: face C of mesh 1 (d %g %g %g)", r.d.x, r.d.y, r.d.z);
	CHECK(!cam_sample(&c, 3, 0, v2(0.1f, 0.5f), v2(0, 0), &r), "distribution 2, pixel 3 past mesh 1 has a ray");
	p.mesh_n = 0;
	CHECK(!cam_init(&c, &p, 2, 2), "a mesh camera without faces is accepted");
}

/* POV-Ray's distribution 1 (its documentation; tracepixel.cpp's comment): the meshes' faces
 * summed, ray k of pixel i from face k * width * height + i, no ray past the last face, the
 * samples picking among the pixel's rays that exist. Three faces of distinct directions. */
static void test_mesh_camera_summed(void)
{
	scene_cam_face f[3];
	xform id = xform_identity();
	CHECK(scene_cam_face_make(d3(0, 0, 0), d3(0, 1, 0), d3(1, 0, 0), &id, &f[0]), "face 0 (+z)");
	CHECK(scene_cam_face_make(d3(0, 0, 0), d3(1, 0, 0), d3(0, 1, 0), &id, &f[1]), "face 1 (-z)");
	CHECK(scene_cam_face_make(d3(0, 0, 0), d3(0, 0, 1), d3(0, 1, 0), &id, &f[2]), "face 2 (+x)");
	CHECK(near3(f[0].dir, v3(0, 0, 1), 1e-6f) && near3(f[1].dir, v3(0, 0, -1), 1e-6f) &&
		  near3(f[2].dir, v3(1, 0, 0), 1e-6f),
	      "the three normals");
	const uint32_t first[3] = {0, 2, 3}; /* mesh 0: faces 0, 1; mesh 1: face 2 (summed: 0 1 2) */
	cam_params p = cam_params_default();
	p.type = CAM_MESH;
	p.mesh_faces = (const cam_mesh_face *)f, p.mesh_n = 3, p.mesh_first = first, p.mesh_count = 2;
	p.mesh_distribution = 1, p.mesh_rays = 2;
	cam c;
	render_ray r;
	/* 2 x 1 image: pixel 0 has rays from faces 0 and 2, pixel 1 from face 1 alone (face 3 is none) */
	CHECK(cam_init(&c, &p, 2, 1), "distribution 1");
	CHECK(cam_sample(&c, 0, 0, v2(0.2f, 0.5f), v2(0, 0), &r) && near3(r.d, v3(0, 0, 1), 1e-6f),
	      "pixel 0, ray 0: face 0 (d %g %g %g)", r.d.x, r.d.y, r.d.z);
	CHECK(cam_sample(&c, 0, 0, v2(0.7f, 0.5f), v2(0, 0), &r) && near3(r.d, v3(1, 0, 0), 1e-6f),
	      "pixel 0, ray 1: face 2 = 1 * 2 + 0 (d %g %g %g)", r.d.x, r.d.y, r.d.z);
	for (float x = 0.05f; x < 1.0f; x += 0.3f)
		CHECK(cam_sample(&c, 1, 0, v2(x, 0.5f), v2(0, 0), &r) && near3(r.d, v3(0, 0, -1), 1e-6f),
		      "pixel 1 at %g: its one ray, face 1 (its second, face 3, is past the last)", x);
	/* 4 x 1: pixel 2 from face 2 (of the second mesh: summed), pixel 3 past the faces has none */
	CHECK(cam_init(&c, &p, 4, 1), "distribution 1, 4 x 1");
	CHECK(cam_sample(&c, 2, 0, v2(0.9f, 0.5f), v2(0, 0), &r) && near3(r.d, v3(1, 0, 0), 1e-6f),
	      "4 x 1, pixel 2: face 2");
	CHECK(!cam_sample(&c, 3, 0, v2(0.1f, 0.5f), v2(0, 0), &r), "4 x 1, pixel 3 past the faces has a ray");
	CHECK(!cam_sample(&c, 4, 0, v2(0.1f, 0.5f), v2(0, 0), &r), "a pixel outside the image has a ray");
	/* one ray per pixel: pixel 0 is face 0 for every sample */
	p.mesh_rays = 1;
	CHECK(cam_init(&c, &p, 2, 1), "distribution 1, one ray");
	CHECK(cam_sample(&c, 0, 0, v2(0.9f, 0.5f), v2(0, 0), &r) && near3(r.d, v3(0, 0, 1), 1e-6f),
	      "one ray: pixel 0 is face 0 alone");
	p.location = d3(0, 0, 0);
	p.mesh_offset = 0.25f, p.mesh_invert = true, p.mesh_rays = 2;
	CHECK(cam_init(&c, &p, 2, 1), "distribution 1, offset and inverted");
	CHECK(cam_sample(&c, 0, 0, v2(0.7f, 0.5f), v2(0, 0), &r) && near3(r.d, v3(-1, 0, 0), 1e-6f) &&
		  near3(r.o, v3(0.25f, 1.0f / 3, 1.0f / 3), 1e-6f),
	      "face 2 offset 0.25 along +x, inverted: o (%g %g %g) d (%g %g %g)", r.o.x, r.o.y, r.o.z, r.d.x,
	      r.d.y, r.d.z);
	p.mesh_rays = 0;
	CHECK(!cam_init(&c, &p, 2, 1), "distribution 1 with no rays accepted");
}

/* The camera of distribution 3 over n faces (their uv index in a). */
static bool uv_cam(cam *c, arena *a, const scene_cam_uv_face *f, uint32_t n, int w, int h, float offset)
{
	cam_params p = cam_params_default();
	p.type = CAM_MESH, p.mesh_distribution = 3, p.mesh_rays = 1;
	p.uv_faces = (const cam_uv_face *)f, p.uv_n = n, p.mesh_offset = offset;
	if (!scene_cam_uv_index(a, f, n, &p.uv_grid, &p.uv_start, &p.uv_list))
		return false;
	return cam_init(c, &p, w, h);
}

/* The first of n faces whose uv triangle holds (u, v) (POV-Ray's test, no index): -1 for none. */
static int uv_brute(const scene_cam_uv_face *f, uint32_t n, double u, double v, double b[3])
{
	for (uint32_t k = 0; k < n; k++) {
		double p1u = f[k].uv[0].x, p2u = f[k].uv[1].x, p3u = f[k].uv[2].x;
		double p1v = f[k].uv[0].y, p2v = f[k].uv[1].y, p3v = f[k].uv[2].y;
		double s = (p2u - p1u) * (p3v - p1v) - (p3u - p1u) * (p2v - p1v);
		b[0] = ((p2u - u) * (p3v - v) - (p3u - u) * (p2v - v)) / s;
		b[1] = ((p3u - u) * (p1v - v) - (p1u - u) * (p3v - v)) / s;
		b[2] = ((p1u - u) * (p2v - v) - (p2u - u) * (p1v - v)) / s;
		if (b[0] >= 0 && b[1] >= 0 && b[2] >= 0)
			return (int)k;
	}
	return -1;
}

/* POV-Ray's distribution 3 (tracepixel.cpp, 3.8's pixel centres): the image point (x, y) is uv
 * (x / w, 1 - y / h); the first face in order holding it gives the ray from the point of the same
 * barycentrics, offset along the (interpolated) normal, in the (interpolated) transformed
 * normal's direction. A quad, a smooth face, a non-uniform scale, overlapping faces, and the uv
 * index against brute force. */
static void test_mesh_camera_uv(void)
{
	arena a;
	arena_init(&a, 1 << 16);
	xform sc, t;
	CHECK(xform_scale(d3(2, 1, 1), &sc), "scale");
	t = xform_then(xform_translate(d3(0, 0, 5)), sc); /* x' = 2 x, y' = y, z' = z + 5 */
	/* The quad (-1,-1) to (1,1) at z 0, uv (0,0) to (1,1) in two faces; POV-Ray's normal
	 * cross(P3 - P1, P2 - P1) is -z for both. */
	const dvec3 q[2][3] = {{d3(-1, -1, 0), d3(1, -1, 0), d3(1, 1, 0)},
			       {d3(-1, -1, 0), d3(1, 1, 0), d3(-1, 1, 0)}};
	const vec2 quv[2][3] = {{v2(0, 0), v2(1, 0), v2(1, 1)}, {v2(0, 0), v2(1, 1), v2(0, 1)}};
	scene_cam_uv_face f[8];
	CHECK(scene_cam_uv_face_make(q[0], NULL, quv[0], &t, &f[0]) &&
		  scene_cam_uv_face_make(q[1], NULL, quv[1], &t, &f[1]),
	      "the quad's faces");
	CHECK(near3(f[0].dir[0], v3(0, 0, -1), 1e-6f) && near3(f[1].offset[2], v3(0, 0, -1), 1e-6f) &&
		  near3(f[0].p[1], v3(2, -1, 5), 1e-6f),
	      "the quad's normals and corners under the transform");
	const vec2 zero[3] = {v2(0, 0), v2(0, 0), v2(0, 0)}, line[3] = {v2(0, 0), v2(0.5f, 0.5f), v2(1, 1)};
	CHECK(!scene_cam_uv_face_make(q[0], NULL, zero, &t, &f[2]),
	      "a face of uv 0 (no uv_vectors) is a face");
	CHECK(!scene_cam_uv_face_make(q[0], NULL, line, &t, &f[2]), "a face of no area in uv is a face");
	const dvec3 flat[3] = {d3(0, 0, 0), d3(1, 1, 1), d3(2, 2, 2)};
	CHECK(!scene_cam_uv_face_make(flat, NULL, quv[0], &t, &f[2]), "a degenerate face is a face");
	cam c;
	render_ray r;
	CHECK(uv_cam(&c, &a, f, 2, 4, 2, 0.5f), "distribution 3 on a 4 x 2 image");
	/* every pixel's centre: u = (px + 0.5) / 4, v = 1 - (py + 0.5) / 2, the point (2 (2u - 1),
	 * 2v - 1, 5), offset 0.5 along the scale of -z, direction -z */
	for (int py = 0; py < 2; py++)
		for (int px = 0; px < 4; px++) {
			double u = (px + 0.5) / 4, v = 1 - (py + 0.5) / 2;
			vec3 want = v3((float)(2 * (2 * u - 1)), (float)(2 * v - 1), 4.5f);
			CHECK(cam_sample(&c, px, py, v2(0.5f, 0.5f), v2(0, 0), &r) &&
				  near3(r.o, want, 1e-6f) && near3(r.d, v3(0, 0, -1), 1e-6f),
			      "pixel %d %d: o (%g %g %g) d (%g %g %g), want o (%g %g %g)", px, py, r.o.x,
			      r.o.y, r.o.z, r.d.x, r.d.y, r.d.z, want.x, want.y, want.z);
		}
	/* the sub-pixel position counts (POV-Ray's antialiasing works for this type) */
	CHECK(cam_sample(&c, 0, 0, v2(0, 0), v2(0, 0), &r) && near3(r.o, v3(-2, 1, 4.5f), 1e-6f),
	      "the image's top-left corner is uv (0, 1): o (%g %g %g)", r.o.x, r.o.y, r.o.z);
	CHECK(!cam_sample(&c, 4, 0, v2(0.5f, 0.5f), v2(0, 0), &r), "a pixel outside the image has a ray");

	/* Half the uv square covered (face 0 only): the pixels above its diagonal have none. */
	CHECK(uv_cam(&c, &a, f, 1, 4, 4, 0), "one face");
	CHECK(cam_sample(&c, 3, 3, v2(0.5f, 0.5f), v2(0, 0), &r), "below the diagonal: face 0");
	CHECK(!cam_sample(&c, 0, 0, v2(0.5f, 0.5f), v2(0, 0), &r), "uv (1/8, 7/8), on no face, has a ray");

	/* Smooth: corner normals +z, +z, (0.6, 0, 0.8) on face (0,0,0) (1,0,0) (0,1,0), uv the same;
	 * at uv (0.25, 0.25) the barycentrics are 1/2, 1/4, 1/4: normal (0.15, 0, 0.95) (before the
	 * identity transform), the origin (0.25, 0.25, 0) + 0.1 of that unnormalised sum. */
	const dvec3 s3[3] = {d3(0, 0, 0), d3(1, 0, 0), d3(0, 1, 0)},
		    sn[3] = {d3(0, 0, 1), d3(0, 0, 1), d3(0.6, 0, 0.8)};
	const vec2 suv[3] = {v2(0, 0), v2(1, 0), v2(0, 1)};
	xform id = xform_identity();
	CHECK(scene_cam_uv_face_make(s3, sn, suv, &id, &f[2]), "the smooth face");
	CHECK(uv_cam(&c, &a, &f[2], 1, 4, 4, 0.1f), "smooth");
	CHECK(cam_sample(&c, 1, 3, v2(0, 0), v2(0, 0), &r), "smooth: uv (1/4, 1/4)");
	vec3 nsum = v3(0.15f, 0, 0.95f);
	CHECK(near3(r.d, v3_normalize(nsum), 1e-6f) &&
		  near3(r.o, v3_madd(v3(0.25f, 0.25f, 0), nsum, 0.1f), 1e-6f),
	      "smooth: o (%g %g %g) d (%g %g %g)", r.o.x, r.o.y, r.o.z, r.d.x, r.d.y, r.d.z);

	/* Overlapping faces: the first in order wins, here the clockwise (negative area) face 3 of
	 * direction +z before face 4 covering the same uv with -z. */
	const dvec3 cw[3] = {d3(0, 0, 0), d3(0, 1, 0), d3(1, 0, 0)};
	const vec2 cwuv[3] = {v2(0, 0), v2(0, 1), v2(1, 0)};
	CHECK(scene_cam_uv_face_make(cw, NULL, cwuv, &id, &f[3]) && near3(f[3].dir[0], v3(0, 0, 1), 1e-6f),
	      "face 3 (+z)");
	CHECK(scene_cam_uv_face_make(s3, NULL, suv, &id, &f[4]) && near3(f[4].dir[0], v3(0, 0, -1), 1e-6f),
	      "face 4 (-z)");
	CHECK(uv_cam(&c, &a, &f[3], 2, 4, 4, 0), "overlapping");
	CHECK(cam_sample(&c, 1, 3, v2(0, 0), v2(0, 0), &r) && near3(r.d, v3(0, 0, 1), 1e-6f),
	      "the first of two faces holding the uv (d %g %g %g)", r.d.x, r.d.y, r.d.z);

	/* The index against brute force: 300 random faces (many overlapping, some reaching outside
	 * [0,1]^2) on a 64 x 48 image at random sub-pixel points, the same face or none. */
	enum { N = 300 };
	scene_cam_uv_face *g = arena_zalloc(&a, N, sizeof *g);
	rng s;
	rng_seed(&s, 19, 5);
	uint32_t n = 0;
	while (n < N) {
		dvec3 pt[3];
		vec2 uv[3];
		double cu = rng_double(&s) * 1.2 - 0.1, cv = rng_double(&s) * 1.2 - 0.1,
		       size = 0.02 + 0.3 * rng_double(&s);
		for (int k = 0; k < 3; k++) {
			pt[k] = d3(rng_double(&s), rng_double(&s), rng_double(&s));
			uv[k] = v2((float)(cu + size * (rng_double(&s) - 0.5)),
				   (float)(cv + size * (rng_double(&s) - 0.5)));
		}
		if (scene_cam_uv_face_make(pt, NULL, uv, &id, &g[n]))
			n++;
	}
	CHECK(uv_cam(&c, &a, g, N, 64, 48, 0), "the random faces");
	CHECK(c.uv_grid > 1, "a grid of more than one cell (%u)", c.uv_grid);
	int hits = 0, bad = 0;
	for (int i = 0; i < 20000; i++) {
		int px = (int)(rng_u32(&s) % 64), py = (int)(rng_u32(&s) % 48);
		vec2 pu = v2(rng_float(&s), rng_float(&s));
		double u = ((double)px + pu.x) / 64, v = 1.0 - ((double)py + pu.y) / 48, b[3];
		int k = uv_brute(g, N, u, v, b);
		bool got = cam_sample(&c, px, py, pu, v2(0, 0), &r);
		if (k < 0) {
			bad += got;
			continue;
		}
		hits++;
		vec3 o = v3_madd(v3_madd(v3_scale(g[k].p[0], (float)b[0]), g[k].p[1], (float)b[1]), g[k].p[2],
				 (float)b[2]);
		bad += !got || !near3(r.o, o, 1e-5f) || !near3(r.d, g[k].dir[0], 1e-5f);
	}
	CHECK(bad == 0 && hits > 5000, "the index's first face is brute force's: %d wrong of %d hits", bad,
	      hits);
	arena_release(&a);
}

int main(void)
{
	test_mesh_camera();
	test_mesh_camera_summed();
	test_mesh_camera_uv();
	test_perturb();
	test_omnimax();
	cam c;
	cam_params p = cam_params_default();
	p.location = d3(1, 2, -5);
	p.look_at = d3(0.5, 1, 3);
	p.angle_deg = 60;
	CHECK(cam_init(&c, &p, 641, 481), "cam_init");
	render_ray r = cam_ray(&c, 320, 240, v2(0.5f, 0.5f), v2(0, 0));
	vec3 want = v3_normalize(d3_to_v3(d3_sub(p.look_at, p.location)));
	CHECK(angle_deg(r.d, want) < 1e-3, "centre ray (%g %g %g) vs look_at direction (%g %g %g)", r.d.x,
	      r.d.y, r.d.z, want.x, want.y, want.z);

	/* Horizontal FOV: the left and right image edges through the middle row span `angle`. */
	for (float a = 30; a <= 150; a += 40) {
		p.angle_deg = a;
		CHECK(cam_init(&c, &p, 640, 480), "cam_init angle %g", a);
		render_ray l = cam_ray(&c, 0, 240, v2(0, 0), v2(0, 0));
		render_ray rr = cam_ray(&c, 639, 240, v2(1, 0), v2(0, 0)); /* right edge of the last pixel */
		CHECK_NEAR(angle_deg(l.d, rr.d), a, 1e-2);
		/* Vertical FOV from the aspect: tan(v/2) = tan(h/2) * 480/640. */
		render_ray top = cam_ray(&c, 320, 0, v2(0, 0), v2(0, 0));
		render_ray bottom = cam_ray(&c, 320, 479, v2(0, 1), v2(0, 0));
		double v = 2 * atan(tan(a * M_PI / 360) * 0.75) * 180 / M_PI;
		CHECK_NEAR(angle_deg(top.d, bottom.d), v, 1e-2);
	}

	/* Default camera: looks along +z, pixel x grows towards +x, pixel y grows towards -y. */
	p = cam_params_default();
	CHECK(cam_init(&c, &p, 100, 100), "default camera");
	render_ray left = cam_ray(&c, 0, 50, v2(0.5f, 0.5f), v2(0, 0));
	render_ray top = cam_ray(&c, 50, 0, v2(0.5f, 0.5f), v2(0, 0));
	CHECK(left.d.x < 0 && left.d.z > 0, "left column looks to -x: (%g %g %g)", left.d.x, left.d.y,
	      left.d.z);
	CHECK(top.d.y > 0, "top row looks up: (%g %g %g)", top.d.x, top.d.y, top.d.z);
	/* POV-Ray's default angle, 2 atan(1.33 / 2): the edge of the image is half of it off axis */
	CHECK_NEAR(angle_deg(cam_ray(&c, 0, 50, v2(0, 0.5f), v2(0, 0)).d, v3(0, 0, 1)), 67.380135 / 2, 1e-2);

	/* right = -x mirrors (POV-Ray's right-handed camera); |right| and |up| set the aspect. */
	p.right = v3(-2, 0, 0);
	p.up = v3(0, 1, 0);
	CHECK(cam_init(&c, &p, 100, 100), "mirrored camera");
	left = cam_ray(&c, 0, 50, v2(0.5f, 0.5f), v2(0, 0));
	CHECK(left.d.x > 0, "mirrored: left column looks to +x: (%g %g %g)", left.d.x, left.d.y, left.d.z);
	render_ray top2 = cam_ray(&c, 50, 0, v2(0.5f, 0), v2(0, 0));
	CHECK_NEAR(angle_deg(top2.d, v3(0, 0, 1)), atan(0.5 * tan(67.380135 / 2 * M_PI / 180)) * 180 / M_PI, 1e-2);

	/* Degenerate input is refused. */
	p.look_at = p.location;
	CHECK(!cam_init(&c, &p, 10, 10), "look_at == location accepted");
	/* a view along sky: POV-Ray takes the right vector (the default x) instead of sky x view */
	p = cam_params_default();
	p.look_at = d3(0, 5, 0);
	CHECK(cam_init(&c, &p, 100, 100), "view parallel to sky: the right vector");
	render_ray r_edge = cam_ray(&c, 99, 50, v2(0.5f, 0.5f), v2(0, 0));
	CHECK(r_edge.d.x > 0.5f && fabsf(r_edge.d.z) < 0.02f, "right of the image along +x: (%g %g %g)", r_edge.d.x, r_edge.d.y,
	      r_edge.d.z);
	p.right = v3(0, 1, 0); /* right along the view too: refused */
	CHECK(!cam_init(&c, &p, 10, 10), "view parallel to sky and right accepted");
	p = cam_params_default();
	p.sky = v3(0, 0, 0);
	CHECK(!cam_init(&c, &p, 10, 10), "zero sky accepted");

	/* Scale: the same view at 1e-9 and at 1e9 of the first camera's size gives the same rays (a
	 * fixed length below which a view was "degenerate" refused every camera under 1e-6). */
	for (double s = 1e-9; s <= 1e9; s *= 1e3) {
		p = cam_params_default();
		p.location = d3(1 * s, 2 * s, -5 * s);
		p.look_at = d3(0.5 * s, 1 * s, 3 * s);
		p.angle_deg = 60;
		CHECK(cam_init(&c, &p, 64, 48), "camera at scale %g refused", s);
		render_ray sr = cam_ray(&c, 5, 40, v2(0.25f, 0.75f), v2(0, 0));
		cam_params q = p;
		q.location = d3(1, 2, -5), q.look_at = d3(0.5, 1, 3);
		cam c1;
		CHECK(cam_init(&c1, &q, 64, 48), "camera at scale 1");
		render_ray r1 = cam_ray(&c1, 5, 40, v2(0.25f, 0.75f), v2(0, 0));
		CHECK(angle_deg(sr.d, r1.d) < 1e-4, "scale %g: ray (%g %g %g) vs (%g %g %g) at scale 1", s, sr.d.x,
		      sr.d.y, sr.d.z, r1.d.x, r1.d.y, r1.d.z);
	}
	/* Far from the origin: a camera at x = 1e8 looking at a point 1 further along x. In float the
	 * two positions are the same number (its ulp there is 8): the view must come from the doubles. */
	p = cam_params_default();
	p.location = d3(1e8, 0, 0);
	p.look_at = d3(1e8 + 1, 0.5, 0);
	CHECK(cam_init(&c, &p, 32, 32), "camera at 1e8 looking 1 away refused");
	r = cam_ray(&c, 16, 16, v2(0, 0), v2(0, 0));
	want = v3_normalize(v3(1, 0.5f, 0));
	CHECK(angle_deg(r.d, want) < 1e-3, "camera at 1e8: centre ray (%g %g %g), want (%g %g %g)", r.d.x, r.d.y,
	      r.d.z, want.x, want.y, want.z);

	/* Thin lens: rays from anywhere on the lens through one pixel meet on the focal plane, and
	 * their origins lie within aperture / 2 of the location. */
	p = cam_params_default();
	p.aperture = 0.5f;
	p.focal_point = d3(0, 0, 4);
	CHECK(cam_init(&c, &p, 64, 64), "thin lens");
	rng g;
	rng_seed(&g, 3, 4);
	render_ray pin = cam_ray(&c, 10, 20, v2(0.5f, 0.5f), v2(0.5f, 0.5f));
	vec3 focus = v3_madd(pin.o, pin.d, 4.0f / pin.d.z);
	float max_off = 0;
	for (int i = 0; i < 1000; i++) {
		render_ray lr = cam_ray(&c, 10, 20, v2(0.5f, 0.5f), v2(rng_float(&g), rng_float(&g)));
		vec3 q = v3_madd(lr.o, lr.d, (4.0f - lr.o.z) / lr.d.z);
		CHECK(v3_length(v3_sub(q, focus)) < 1e-4f, "lens ray misses focus by %g",
		      v3_length(v3_sub(q, focus)));
		CHECK(v3_length(lr.o) <= 0.25f + 1e-6f, "lens origin %g from the centre", v3_length(lr.o));
		max_off = fmaxf(max_off, v3_length(lr.o));
	}
	CHECK(max_off > 0.2f, "lens samples cover the aperture: max offset %g", max_off);
	test_projections();
	return check_done("test_camera");
}
