/* povshape.h - POV-Ray's finite shapes as triangle meshes: cone and cylinder, torus, disc, polygon,
 * superellipsoid, height field and the ellipsoid a quadric may be. Each fills a mesh (mesh.h) in the
 * shape's own space with outward unit normals (geometric normals agree: counter-clockwise seen
 * from outside) and UVs, closed where the shape is closed (cone, cylinder and torus unless open,
 * superellipsoid, ellipsoid), and reports the distance bound it met. The accuracy comes from the
 * caller (the build derives it from the screen, as a sphere's level); every shape refuses, before
 * allocating, a mesh of more than a->max_triangles triangles, with a message at loc. */
#ifndef CIRCE_GEOM_POVSHAPE_H
#define CIRCE_GEOM_POVSHAPE_H

#include "geom/mesh.h"
#include "geom/prim.h"

/* Segments around a circle: at least the coarsest sphere's (within 0.5 % of the radius wherever
 * it is seen), at most the finest sphere's (prim.h): a circle gets what a sphere of its radius
 * would. */
#define SHAPE_MIN_SEGMENTS PRIM_SPHERE_MIN_SEGMENTS
#define SHAPE_MAX_SEGMENTS (PRIM_SPHERE_MIN_SEGMENTS << (PRIM_SPHERE_LEVELS - 1))
/* The triangles one shape may make by default: 10 M, about 1.3 GB of mesh and BVH. */
#define SHAPE_MAX_TRIANGLES 10000000u
/* A polygon's points: its triangulation tests every pair of edges for crossings. */
#define SHAPE_POLYGON_MAX_POINTS 10000u

typedef struct shape_accuracy {
	double max_error;       /* largest distance of the mesh from the surface, object units (> 0) */
	double max_edge;        /* longest edge along a curve, object units; 0: no bound */
	uint32_t max_triangles; /* refused beyond this (SHAPE_MAX_TRIANGLES) */
} shape_accuracy;

/* The segments a circle of this radius needs: chord error r (1 - cos(pi / n)) <= max_error and
 * chord 2 pi r / n <= max_edge, clamped to [SHAPE_MIN_SEGMENTS, SHAPE_MAX_SEGMENTS]. */
uint32_t shape_circle_segments(double radius, const shape_accuracy *a);
/* The chord error r (1 - cos(pi / n)) of n segments. */
double shape_circle_error(double radius, uint32_t n);

/* A truncated cone between base (radius rb) and cap (radius rc), either radius possibly 0 (an
 * apex), not both; base != cap. Closed by flat end discs unless open. UV (circe's: POV-Ray 3.7
 * has no uv_mapping for cones): side u = angle / 2 pi, v = 0 at base to 1 at cap; end discs
 * u, v = 0.5 + local x, y / (2 r). */
bool shape_cone(dvec3 base, double rb, dvec3 cap, double rc, bool open, const shape_accuracy *a, mesh *out,
		double *err, diag *d, diag_loc loc);

/* POV-Ray's torus: major radius R in the x-z plane about the y axis, minor radius r (0 < r <= R).
 * UV as POV-Ray's Torus::CalcUV: u = 1 - (atan2(z, x) + pi) / 2 pi, v = (atan2(y, rho - R) + pi) / 2 pi. */
bool shape_torus(double major, double minor, const shape_accuracy *a, mesh *out, double *err, diag *d,
		 diag_loc loc);

/* A disc of radius r about centre facing normal, with a hole of radius hole (0: none; < r): one
 * sided, open. UV: 0.5 + local x, y / (2 r) in a frame about the normal. */
bool shape_disc(dvec3 centre, dvec3 normal, double radius, double hole, const shape_accuracy *a, mesh *out,
		double *err, diag *d, diag_loc loc);

/* POV-Ray's polygon: n points in one plane, subpolygons closed by repeating their first point
 * (the parser has closed the last), filled by the even-odd rule (holes, overlaps cancel). The
 * normal is Newell's over the edges. Triangulated exactly (trapezoids between the y's of every
 * vertex and edge crossing, in the plane); UV: the plane coordinates. Errors: fewer than 3
 * distinct points, collinear points, points off one plane, more than SHAPE_POLYGON_MAX_POINTS. */
bool shape_polygon(const dvec3 *points, uint32_t n, const shape_accuracy *a, mesh *out, diag *d, diag_loc loc);

/* POV-Ray's superellipsoid { <e, n> }: (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1 in [-1, 1]^3,
 * from Barr's signed-power parametrisation (longitude u about z, latitude v), from the segments a
 * circle of radius 1 needs (shape_circle_segments: the edge bound too), refined by doubling
 * until the largest radial distance of the triangles' sample points (centroid, edge midpoints) from
 * the surface is within max_error, or SHAPE_MAX_SEGMENTS is reached; *err is that measured
 * distance. UV: u = (lon + pi) / 2 pi, v = (lat + pi / 2) / pi. */
bool shape_superellipsoid(double e, double n, const shape_accuracy *a, mesh *out, double *err, diag *d,
			  diag_loc loc);
/* The surface's radial measure: 1 on it, homogeneous of degree 1 (POV-Ray's evaluate_g twice). */
double shape_superellipsoid_norm(double e, double n, dvec3 p);

/* A height field of w x h samples (w, h >= 2), heights[z * w + x] in the field's units (POV-Ray:
 * 0 .. 65535 / 65536), at x / (w - 1), y = height, z / (h - 1), two triangles per cell split as
 * POV-Ray's (x + z < 1 in the cell is the first). Parts below water_level are cut away (POV-Ray's
 * box starts there). smooth: vertex normals averaged over the four neighbouring cross products,
 * as POV-Ray's smooth_height_field; otherwise each triangle's own. Open; UV: u = x, v = z. */
bool shape_height_field(const float *heights, uint32_t w, uint32_t h, bool smooth, double water_level,
			const shape_accuracy *a, mesh *out, diag *d, diag_loc loc);

/* The kinds of surface a quadric is, for shape_quadric. */
typedef enum shape_quadric_kind {
	SHAPE_QUADRIC_ELLIPSOID,
	SHAPE_QUADRIC_EMPTY,
	SHAPE_QUADRIC_UNBOUNDED
} shape_quadric_kind;
/* A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J = 0 (q[0..9] = A..J): a definite
 * quadratic part with a solution is an ellipsoid, tessellated as the unit sphere mapped onto it
 * (its error: the sphere's relative error times the longest semi-axis); anything else is empty or
 * unbounded, and only classified (*kind), with no mesh and no message. */
bool shape_quadric(const double q[10], const shape_accuracy *a, mesh *out, double *err, shape_quadric_kind *kind,
		   diag *d, diag_loc loc);
/* The quadric's kind and, for an ellipsoid, its centre and longest semi-axis. */
shape_quadric_kind shape_quadric_bound(const double q[10], dvec3 *centre, double *radius);
/* shape_quadric_box (the box of any quadric's solid) is in polysurf.h. */

#endif
