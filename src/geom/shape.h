/* shape.h - POV-Ray 3.7's lathe, sor, prism, sphere_sweep, blob, text, bicubic_patch and isosurface made triangle meshes
 * (mesh.h), in the shape's own space, closed where the shape is closed, with outward geometric
 * and shading normals and POV-Ray's UVs where it defines them (lathe, sor). Each takes a
 * shape_desc (plain arrays: the IR points at one) and an accuracy: the largest distance, in the
 * shape's units, its triangles may lie from the true surface, and the segment count around a
 * surface of revolution (build chooses both from the shape's size on screen, as a sphere's level).
 * Every tessellator counts its triangles first and refuses more than SHAPE_MAX_TRIANGLES with a
 * message before allocating the mesh. Errors are reported at the diag_loc given. */
#ifndef CIRCE_GEOM_SHAPE_H
#define CIRCE_GEOM_SHAPE_H

#include "base/diag.h"
#include "base/vec.h"
#include "geom/mesh.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

/* The most triangles one shape may make (a sphere's finest level makes 65,024). */
#define SHAPE_MAX_TRIANGLES 4000000u

typedef enum shape_kind {
	SHAPE2_LATHE, SHAPE2_SOR, SHAPE2_PRISM, SHAPE2_SPHERE_SWEEP, SHAPE2_BLOB, SHAPE2_TEXT, SHAPE2_BICUBIC,
	SHAPE2_ISOSURFACE, SHAPE2_PARAMETRIC, SHAPE2_JULIA
} shape_kind;

/* POV-Ray's spline types (lathe, prism: linear, quadratic, cubic, bezier; sphere_sweep: linear,
 * cubic (Catmull-Rom), b_spline). */
typedef enum shape_spline { SHAPE_LINEAR, SHAPE_QUADRATIC, SHAPE_CUBIC, SHAPE_BEZIER, SHAPE_BSPLINE } shape_spline;

/* A blob component: a sphere (centre a) or a cylinder (axis a to b) of `radius` and `strength`,
 * with its own transform when has_xf (POV-Ray's component modifiers: the field is read at the
 * point taken back through xf). */
typedef struct shape_blob_comp {
	bool cylinder;
	dvec3 a, b;
	double radius, strength;
	bool has_xf;
	xform xf;
	/* POV-Ray's texture of a component: 0 the blob's own, k >= 1 the k-th of the textures its
	 * components carry (the language's); a point takes the part of the component whose field
	 * is strongest there (shape_blob_part_at). */
	uint32_t part;
} shape_blob_comp;

/* The most distinct component textures a blob may carry. */
#define SHAPE_BLOB_MAX_PARTS 255

typedef struct shape_desc {
	shape_kind kind;
	shape_spline spline;
	double *pts; /* lathe, sor, prism: n_pts points <u, v>, 2 doubles each; sphere_sweep: 4 each (centre, radius) */
	uint32_t n_pts;
	bool open; /* sor, prism: no caps */
	bool conic; /* prism: conic_sweep */
	double h1, h2; /* prism: heights, h1 <= h2 */
	double tolerance; /* sphere_sweep: POV-Ray's depth tolerance (kept, not used by a mesh) */
	shape_blob_comp *comps; /* blob */
	uint32_t n_comps;
	double threshold;
	const char *font; /* text: the resolved font path, the UTF-8 string, depth and offset */
	const char *text;
	double depth;
	dvec3 offset;
	/* bicubic_patch: pts holds 16 control points (3 doubles each, row i along u, column j along
	 * v, as POV-Ray reads them); st the corners' texture coordinates (uv_vectors); POV-Ray's
	 * type, flatness, u_steps and v_steps are kept for the dump (the mesh follows the accuracy) */
	double st[8];
	int patch_type, u_steps, v_steps;
	double flatness;
	/* isosurface: the function f(x, y, z) (called through fn with fn_ctx; false when it cannot be
	 * evaluated), inside where f < threshold (the threshold above), cut by the container: a box
	 * (box_lo, box_hi) or a sphere (centre box_lo, radius sphere_r) when contained_sphere; open: the
	 * cut left open. max_gradient, accuracy, evaluate, max_trace, all_intersections: POV-Ray's ray
	 * marching's settings, kept for the dump (the mesh follows the accuracy it is given). */
	bool (*fn)(const void *fn_ctx, const double xyz[3], double *out);
	const void *fn_ctx;
	/* Whether two fn_ctx compute the same function (NULL: only the same fn_ctx does): set by a
	 * caller whose fn_ctx outlive every shape_cache (the language's compiled functions, in the
	 * scene's arena); an isosurface without it is never cached. */
	bool (*fn_same)(const void *a, const void *b);
	const char *fn_name;
	bool contained_sphere;
	dvec3 box_lo, box_hi;
	double sphere_r;
	double max_gradient, iso_accuracy, evaluate[3];
	bool has_region; /* the distance reached measured only inside [region_lo, region_hi] (shape_field's) */
	int max_passes; /* grids made at most (0: 2, the first and one at the step it asks for) */
	dvec3 region_lo, region_hi;
	bool has_evaluate, all_intersections;
	int max_trace;
	/* parametric: x, y and z as functions of (u, v) (fn called with fn_ctxs[k] and <u, v, 0>) over
	 * [uv_lo, uv_hi], clipped by the container above (box_lo/box_hi or the sphere); precompute's
	 * depth and flags kept for the dump */
	const void *fn_ctxs[3];
	double uv_lo[2], uv_hi[2];
	int precompute_depth;
	bool precompute_xyz[3];
	/* julia_fractal: q <- f(q) + julia while |q|^2 stays within POV-Ray's exit value, for
	 * max_iteration steps, q starting at (x, y, z, w) on the slice (slice . q = slice_dist); the
	 * algebra (0 quaternion, 1 hypercomplex) and f (0 sqr, 1 cube); precision kept for the dump */
	double julia[4], slice[4], slice_dist, precision;
	int algebra, jfunc, max_iteration;
} shape_desc;

/* What isosurfaces made, kept for the next with the same description (shape_cache_new). */
typedef struct shape_cache shape_cache;

/* tol: the largest distance of the mesh from the surface, in the shape's units; segments: around
 * a surface of revolution and a sphere_sweep's rings (>= 3); cache: where an isosurface's grids
 * are looked up and kept (NULL: none). */
typedef struct shape_accuracy {
	double tol;
	uint32_t segments;
	shape_cache *cache;
	/* threads an isosurface is tessellated on (shape_field.workers; 0 or 1: the caller's only):
	 * the same mesh, bit for bit, for any count */
	int threads;
} shape_accuracy;

/* A cache of isosurface grids (iso.c): what one grid step of an isosurface made (each of
 * shape_isosurface's passes: the mesh, the distance it reached, the largest gradient met), kept
 * for an isosurface of the same description (fn_same's function, threshold, container, open,
 * max_gradient, region) at the same step, whatever tolerance asked for that step. POV-Ray's
 * isocacti places 750 rocks of one function, each tessellated anew before. A hit gives the bytes
 * a miss makes (a function is a pure one), so results do not depend on what was cached; passes
 * of more than max_bytes in all are not kept. Not thread-safe: one builder at a time. NULL when
 * memory runs out. */
shape_cache *shape_cache_new(size_t max_bytes);
void shape_cache_free(shape_cache *c);
/* Passes taken from the cache, and passes made and kept (for tests and `circe check`). */
size_t shape_cache_hits(const shape_cache *c);
size_t shape_cache_kept(const shape_cache *c);

const char *shape_kind_name(shape_kind k);
/* A bound of the shape in its own space, from its description alone (text: estimated from the
 * string's length, 1 em a character); the build sizes its accuracy from it. */
void shape_bounds(const shape_desc *s, dvec3 *lo, dvec3 *hi);
/* Tessellates s into out (positions, normals, UVs where defined). False after reporting to d. The
 * tolerance actually reached is written to *tol_out (a blob's grid may be coarsened to fit). */
bool shape_tessellate(const shape_desc *s, const shape_accuracy *acc, mesh *out, double *tol_out, diag *d,
		      diag_loc loc);
/* The IR dump of s (one line, then one per point or component). */
void shape_dump(FILE *o, const shape_desc *s);

/* The value of POV-Ray's blob field at p: the sum over components of s (1 - d^2/r^2)^2 for d < r,
 * d the distance to the centre (sphere) or the axis segment (cylinder, hemispheres at its ends). */
double shape_blob_field(const shape_desc *s, dvec3 p);
/* The part (shape_blob_comp.part) of the component whose field's magnitude is largest at p (the
 * first such; POV-Ray blends the textures by these magnitudes, circe takes the strongest), 0 where
 * none reaches p. */
uint32_t shape_blob_part_at(const shape_desc *s, dvec3 p);

/* ---- what the tessellators share (shape.c) ---- */

/* A growing mesh: positions, normals and UVs per vertex, three indices per triangle. */
typedef struct shape_builder {
	vec3 *pos, *nrm;
	vec2 *uv;
	uint32_t nv, cap_v;
	uint32_t *idx;
	uint32_t nt, cap_t;
	bool failed; /* memory ran out or a limit was passed */
} shape_builder;

void sb_init(shape_builder *b);
void sb_free(shape_builder *b);
uint32_t sb_vertex(shape_builder *b, dvec3 p, dvec3 n, double u, double v);
/* A triangle a b c, its winding turned so its geometric normal faces `want` (if they disagree). */
void sb_tri(shape_builder *b, uint32_t a, uint32_t c1, uint32_t c2, dvec3 want);
/* Drops the vertices no triangle uses, renumbering the triangles' (sets failed when memory runs out). */
void sb_compact(shape_builder *b);
/* The builder's contents as a mesh; false (reported) when it failed or passed the limit. */
bool sb_finish(shape_builder *b, mesh *out, bool uvs, const char *what, diag *d, diag_loc loc);

/* A plane region bounded by closed polygons, filled by the even-odd rule (POV-Ray's inside test
 * for prism and text): triangles as index triples into the concatenated vertices of the
 * contours, oriented counter-clockwise in (x, y). contours[k] has counts[k] points (x, y pairs).
 * Returns the triangle count, or -1 when memory runs out or it cannot be done. */
long poly2d_triangulate(const double *xy, const uint32_t *counts, uint32_t n_contours, uint32_t **tris);
/* Whether two edges of the contours cross (other than at shared endpoints); *ea, *eb their indices. */
bool poly2d_self_intersects(const double *xy, const uint32_t *counts, uint32_t n_contours, uint32_t *ea, uint32_t *eb);
/* Orients each contour of the even-odd region: counter-clockwise where it bounds the region from
 * outside (even nesting depth), clockwise around a hole. Reverses in place; reversed[k] (when not
 * NULL) says whether contour k was. */
void poly2d_orient(double *xy, const uint32_t *counts, uint32_t n_contours, bool *reversed);

/* Flattens a cubic A t^3 + B t^2 + C t + D (2-D, t in [0, 1]) into steps whose chords lie within
 * tol of it: the bound max|P''| h^2 / 8 of a chord over a step h. */
uint32_t shape_cubic_steps(const double A[2], const double B[2], double tol);

/* A scalar field for the polygoniser (field.c), positive inside: eval gives its value at p and,
 * when g is not NULL, its gradient; fill (may be NULL: eval at each point) writes the field at the
 * grid points lo + h (i, j, k), i fastest, nx * ny * nz floats; on_edges: vertices are found on
 * their grid edge by regula falsi (a field without a cheap gradient, or with creases) rather than
 * moved off it by Newton steps; shift: the grid's first point lies shift * h before lo (0: one
 * cell), a fraction that keeps flat faces at lo (a container's) off the grid points. */
typedef struct shape_field {
	double (*eval)(const void *ctx, dvec3 p, dvec3 *g);
	void (*fill)(const void *ctx, dvec3 lo, double h, uint32_t nx, uint32_t ny, uint32_t nz, float *f);
	const void *ctx;
	bool on_edges;
	double shift;
	/* has_region: the distance reached is measured only at triangles whose centre lies in
	 * [region_lo, region_hi] (a polynomial surface's box within its grid: what lies outside is cut
	 * away by its CSG) */
	bool has_region;
	dvec3 region_lo, region_hi;
	/* > 0: a bound on |grad eval| (a Lipschitz constant: an isosurface's max_gradient). The grid is
	 * then filled by an octree: a block whose centre's |value| exceeds lipschitz times (its half
	 * diagonal + a cell's diagonal) holds no surface within a cell of its points, so its points take
	 * the centre's value (the right sign) unevaluated. 0: every grid point is evaluated. */
	double lipschitz;
	/* workers > 1: the grid's points, the edges' vertices, the normals and the distance reached are
	 * computed on that many threads (base/par.h), worker w calling eval with worker_ctx[w] (a ctx of
	 * its own, which eval may write: the caller merges what the workers' ctx gathered); every value
	 * depends on its point alone, so the mesh and the distance are the same bits for any count.
	 * 0 or 1: one thread, with ctx. */
	int workers;
	const void *const *worker_ctx;
} shape_field;
/* The zero set of F inside [lo, hi] (the field must be <= 0 at the bound, or the surface is cut
 * open there) at grid step h, into b (initialised here), closed and with outward normals (-grad).
 * False (reported, b untouched) when the triangles counted from the grid pass the limit or memory
 * runs out; b->failed when making them failed. */
bool shape_field_polygonise(const shape_field *F, dvec3 lo, dvec3 hi, double h, const char *what, shape_builder *b,
			    diag *d, diag_loc loc);
/* The largest distance of b's triangles from F's zero set, to first order (|F| / |grad F|) at
 * their centres and edge midpoints (within F's region when it has one). */
double shape_field_error(const shape_field *F, const shape_builder *b);
/* Adaptive refinement where the grid missed: for up to `rounds` rounds, every triangle of b whose
 * distance (as shape_field_error measures it) is above tol has its edges split at the zero set
 * near their midpoints (Newton steps along F's gradient), and every triangle sharing a split edge
 * is split with it (red-green: 2, 3 or 4 triangles), so the mesh stays closed. Stops early when
 * every triangle is within tol, or before passing the triangle limit. Returns the distance reached
 * (shape_field_error's measure, each triangle measured once), the rounds made in *rounds_made
 * (may be NULL). F needs a gradient that Newton steps can follow (the blob's). */
double shape_field_refine(const shape_field *F, shape_builder *b, double tol, int rounds, uint32_t *rounds_made);
/* h grown until a grid of ext at step h has at most max_points points. */
double shape_field_fit_step(dvec3 ext, double h, size_t max_points);

bool shape_lathe(const shape_desc *s, const shape_accuracy *acc, mesh *out, diag *d, diag_loc loc);
bool shape_sor(const shape_desc *s, const shape_accuracy *acc, mesh *out, diag *d, diag_loc loc);
bool shape_prism(const shape_desc *s, const shape_accuracy *acc, mesh *out, diag *d, diag_loc loc);
bool shape_sphere_sweep(const shape_desc *s, const shape_accuracy *acc, mesh *out, diag *d, diag_loc loc);
bool shape_blob(const shape_desc *s, const shape_accuracy *acc, mesh *out, double *tol_out, diag *d, diag_loc loc);
bool shape_text(const shape_desc *s, const shape_accuracy *acc, mesh *out, diag *d, diag_loc loc);
bool shape_bicubic(const shape_desc *s, const shape_accuracy *acc, mesh *out, diag *d, diag_loc loc);
bool shape_isosurface(const shape_desc *s, const shape_accuracy *acc, mesh *out, double *tol_out, diag *d, diag_loc loc);
/* The same, its messages naming the shape `what` (polysurf.c's quadric, cubic, quartic and poly). */
bool shape_isosurface_named(const shape_desc *s, const shape_accuracy *acc, const char *what, mesh *out, double *tol_out,
			    diag *d, diag_loc loc);
bool shape_julia(const shape_desc *s, const shape_accuracy *acc, mesh *out, double *tol_out, diag *d, diag_loc loc);
/* POV-Ray's julia_fractal bound: the radius of its sphere (Fractal::Compute_BBox) and the exit value. */
double shape_julia_radius(const shape_desc *s, double *exit_value);
bool shape_parametric(const shape_desc *s, const shape_accuracy *acc, mesh *out, double *tol_out, diag *d, diag_loc loc);

#endif
