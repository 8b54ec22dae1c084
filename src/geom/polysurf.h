/* polysurf.h - POV-Ray's polynomial surfaces (quadric, cubic, quartic, poly) as meshes inside a
 * box: the solid where the polynomial is below 0 (POV-Ray's Poly::Inside and Quadric::Inside) cut by
 * the box, polygonised by field.c as an isosurface is (iso.c), closed by the box's faces, normals
 * outward (along the polynomial's gradient). The caller finds the box (a clipped_by, a bounded_by,
 * an intersection's bounded operand) and cuts the faces away by CSG. Only mesh.h's and diag's types
 * here, so that povshape.h's users may include it. */
#ifndef CIRCE_GEOM_POLYSURF_H
#define CIRCE_GEOM_POLYSURF_H

#include "base/diag.h"
#include "base/vec.h"
#include "geom/mesh.h"

#include <stdbool.h>
#include <stdint.h>

/* POV-Ray's order limit (MAX_ORDER of its polynomial solver). */
#define SHAPE_POLY_MAX_ORDER 35

/* The terms of a polynomial of this order in three variables: (n+1)(n+2)(n+3)/6. */
uint32_t shape_poly_terms(int order);
/* sum c[t] x^i y^j z^k in POV-Ray's term order (Poly::inside): i from the order down to 0, then j
 * from order - i down to 0, then k from order - i - j down to 0. */
double shape_poly_eval(int order, const double *c, dvec3 p);
/* A ball about the origin holding the solid P < 0, when P's top-degree form is positive on every
 * direction (an even order; x^4 + y^4 + z^4 - 1000 bounds itself): its least value on the unit
 * sphere bounded from below by dense sampling less a Lipschitz margin, then the radius past which
 * that form outweighs the lower terms. False where this cannot be shown (then the solid may still
 * be bounded: a piriform's top form vanishes along a plane). */
bool shape_poly_ball(int order, const double *c, double *radius);
/* A quadric's A .. J (A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y + I z + J) as the
 * 10 coefficients of an order-2 poly. */
void shape_quadric_poly(const double q[10], double c[10]);
/* The box of a quadric's solid (q[0..9] = A..J as shape_quadric's; bounds.c) (POV-Ray's inside: the value <= 0), an axis infinite (+-INFINITY)
 * where the solid is unbounded along it: an ellipsoid or an elliptic cylinder bounds the axes its
 * axis has no part along; cones, hyperboloids, paraboloids and half-spaces bound none. False when
 * the solid is empty (a positive semi-definite quadric whose minimum is above 0). */
bool shape_quadric_box(const double q[10], dvec3 *lo, dvec3 *hi);
/* The eigen decomposition of the symmetric 3 x 3 matrix a (Jacobi rotations; a is overwritten):
 * a = V diag(l) V^T, the columns of v the eigenvectors (bounds.c). */
void shape_sym3_eigen(double a[3][3], double l[3], double v[3][3]);

/* The fraction of the box's largest extent the grid's box grows by on every side (polysurf.c). */
#define SHAPE_POLY_MARGIN 0.1

/* The surface of the solid {p : P(p) < 0} inside [lo, hi] within max_error (the grid refined, twice at
 * most, where the measured distance asks for it; *err the distance reached, measured at the triangles'
 * centres and edge midpoints inside [lo, hi]), `what` naming it in messages ("quartic"): a closed
 * mesh of the solid cut by [lo, hi] grown by SHAPE_POLY_MARGIN, the cut's faces and the crease
 * along them outside [lo, hi]. Refuses past the triangle limit before making them. */
bool shape_poly_surface(int order, const double *c, dvec3 lo, dvec3 hi, double max_error, mesh *out, double *err,
			const char *what, diag *d, diag_loc loc);

#endif
