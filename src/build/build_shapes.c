/* build_shapes.c - POV-Ray's shapes (cylinder, cone, torus, disc, polygon, superellipsoid,
 * height_field, quadric; src/geom/povshape.h) tessellated for the objects that use them. A shape
 * declared and never placed costs nothing (shapes.inc declares dozens), and the accuracy follows
 * the sphere's rule on screen (build_inst.c's view_px_per_unit): its surface within
 * WORLD_SPHERE_MAX_ERROR_PX and its edges along curves within WORLD_SPHERE_MAX_EDGE_PX, for the
 * most demanding object that uses it. A quadric that is not an ellipsoid and a poly (cubic,
 * quartic) are polygonised inside the box their objects' CSG confines them to (clipped_by,
 * bounded_by, the bounded operands of an intersection; geom/polysurf.h). */
#include "build/build_impl.h"

#include "base/mem.h"
#include "geom/polysurf.h"
#include "geom/povshape.h"
#include "io/image.h"

#include <float.h>
#include <stdio.h>
#include <string.h>

static bool is_shape(scene_shape_kind k) { return k >= SHAPE_CONE; }

/* The quadric's A .. J. */
static void quadric_coeffs(const scene_quadric *q, double c[10])
{
	const double v[10] = {q->square.x, q->square.y, q->square.z, q->mixed.x, q->mixed.y,
			      q->mixed.z, q->linear.x, q->linear.y, q->linear.z, q->constant};
	memcpy(c, v, sizeof v);
}

/* The shape's bounding sphere in its own space; false for shapes tessellated exactly (polygon,
 * height field) or inside a box (an unbounded quadric, a poly: surface_box). */
static bool shape_bound(const scene_geom *g, dvec3 *centre, double *r)
{
	switch (g->kind) {
	case SHAPE_CONE: {
		const scene_cone *c = &g->u.cone;
		*centre = d3_scale(d3_add(c->base, c->cap), 0.5);
		*r = 0.5 * d3_length(d3_sub(c->cap, c->base)) + fmax(c->base_radius, c->cap_radius);
		return true;
	}
	case SHAPE_TORUS:
		*centre = d3(0, 0, 0), *r = g->u.torus.major + g->u.torus.minor;
		return true;
	case SHAPE_DISC:
		*centre = g->u.disc.center, *r = g->u.disc.radius;
		return true;
	case SHAPE_SUPERELLIPSOID:
		*centre = d3(0, 0, 0), *r = sqrt(3.0);
		return true;
	case SHAPE_QUADRIC: {
		double q[10];
		quadric_coeffs(&g->u.quadric, q);
		return shape_quadric_bound(q, centre, r) == SHAPE_QUADRIC_ELLIPSOID;
	}
	default:
		return false;
	}
}

/* ---- the bounds of polynomial surfaces (quadric, cubic, quartic, poly) -------------------------- */

/* A box whose sides may be infinite; lo > hi on an axis: empty. */
typedef struct bbox {
	dvec3 lo, hi;
} bbox;

static double comp(dvec3 v, int a) { return a == 0 ? v.x : a == 1 ? v.y : v.z; }
static dvec3 with(dvec3 v, int a, double x)
{
	if (a == 0)
		v.x = x;
	else if (a == 1)
		v.y = x;
	else
		v.z = x;
	return v;
}
static bbox box_all(void) { return (bbox){d3(-INFINITY, -INFINITY, -INFINITY), d3(INFINITY, INFINITY, INFINITY)}; }
static bbox box_none(void) { return (bbox){d3(INFINITY, INFINITY, INFINITY), d3(-INFINITY, -INFINITY, -INFINITY)}; }
static bbox box_meet(bbox a, bbox b)
{
	return (bbox){d3(fmax(a.lo.x, b.lo.x), fmax(a.lo.y, b.lo.y), fmax(a.lo.z, b.lo.z)),
		      d3(fmin(a.hi.x, b.hi.x), fmin(a.hi.y, b.hi.y), fmin(a.hi.z, b.hi.z))};
}
static bbox box_join(bbox a, bbox b)
{
	return (bbox){d3(fmin(a.lo.x, b.lo.x), fmin(a.lo.y, b.lo.y), fmin(a.lo.z, b.lo.z)),
		      d3(fmax(a.hi.x, b.hi.x), fmax(a.hi.y, b.hi.y), fmax(a.hi.z, b.hi.z))};
}
static bool box_empty(bbox b) { return b.lo.x > b.hi.x || b.lo.y > b.hi.y || b.lo.z > b.hi.z; }
static bool box_finite(bbox b)
{
	return isfinite(b.lo.x) && isfinite(b.lo.y) && isfinite(b.lo.z) && isfinite(b.hi.x) && isfinite(b.hi.y) &&
	       isfinite(b.hi.z);
}
static bbox box_sphere(dvec3 c, double r) { return (bbox){d3_sub(c, d3(r, r, r)), d3_add(c, d3(r, r, r))}; }

/* The box of m applied to b (m: 3 rows of a linear part and a translation), by interval
 * arithmetic: a coefficient negligible in its row (a rotation's cos 90) adds nothing, so an
 * infinite side stays on the axes it maps to. */
static bbox box_map(const double m[3][4], bbox b)
{
	if (box_empty(b))
		return b;
	bbox r;
	for (int j = 0; j < 3; j++) {
		double big = fmax(fabs(m[j][0]), fmax(fabs(m[j][1]), fabs(m[j][2]))), lo = m[j][3], hi = m[j][3];
		for (int i = 0; i < 3; i++) {
			double c = m[j][i];
			if (fabs(c) <= 1e-12 * big)
				continue;
			double a = c * comp(b.lo, i), e = c * comp(b.hi, i);
			lo += fmin(a, e), hi += fmax(a, e);
		}
		r.lo = with(j ? r.lo : d3(0, 0, 0), j, lo), r.hi = with(j ? r.hi : d3(0, 0, 0), j, hi);
	}
	return r;
}

/* A plane's solid n . p <= d (its inverse: n . p >= d), bounded on one side when n is along an
 * axis; all of space otherwise. */
static bbox plane_box(const scene_geom *g, bool inverse)
{
	dvec3 n = g->u.plane.normal;
	double len = d3_length(n);
	bbox b = box_all();
	for (int a = 0; a < 3; a++) {
		double na = comp(n, a);
		if (len > 0.0 && fabs(na) >= (1.0 - 1e-12) * len)
			b = (na > 0) != inverse ? (bbox){b.lo, with(b.hi, a, g->u.plane.offset * len / na)}
						: (bbox){with(b.lo, a, g->u.plane.offset * len / na), b.hi};
	}
	return b;
}

/* The box of an object's solid in its own space (all of space where circe cannot tell). */
static bbox own_box(const world *w, const scene_geom *g)
{
	dvec3 c;
	double r;
	switch (g->kind) {
	case SHAPE_SPHERE:
		return box_sphere(g->u.sphere.center, g->u.sphere.radius);
	case SHAPE_BOX: {
		bbox b = {g->u.box.corner1, g->u.box.corner1};
		return box_join(b, (bbox){g->u.box.corner2, g->u.box.corner2});
	}
	case SHAPE_PLANE:
		return plane_box(g, false);
	case SHAPE_POLYGON: {
		bbox b = box_none();
		for (uint32_t i = 0; i < g->u.polygon.n; i++)
			b = box_join(b, (bbox){g->u.polygon.points[i], g->u.polygon.points[i]});
		return b;
	}
	case SHAPE_HEIGHT_FIELD:
		return (bbox){d3(0, 0, 0), d3(1, 1, 1)};
	case SHAPE_QUADRIC: {
		double q[10];
		bbox b;
		quadric_coeffs(&g->u.quadric, q);
		return shape_quadric_box(q, &b.lo, &b.hi) ? b : box_none();
	}
	case SHAPE_POLY: { /* bounded by its own solid where its top form is positive everywhere */
		double r;
		if (shape_poly_ball(g->u.poly.order, g->u.poly.coeffs, &r))
			return box_sphere(d3(0, 0, 0), r);
		return box_all();
	}
	case SHAPE_MESH: case SHAPE_MESH_FILE: case SHAPE_SUBDIV: case SHAPE_POV: {
		vec3 lo, hi;
		const mesh *m = &w->geoms[g->id].m;
		if (!m->num_triangles || !mesh_bounds(m, &lo, &hi))
			return box_all();
		return (bbox){v3_to_d3(lo), v3_to_d3(hi)};
	}
	default:
		return shape_bound(g, &c, &r) ? box_sphere(c, r) : box_all();
	}
}

/* Whether q's inside below CSG depth k (inside the operand of that node) is turned inside out. */
static bool inverted_below(const scene_object *q, uint32_t k)
{
	if (q->inverse)
		return true;
	for (uint32_t j = k + 1; j < q->csg_depth; j++)
		if (q->csg[j].inverse)
			return true;
	return false;
}

/* Whether q is a plane turned inside out by its own `inverse` alone below CSG depth k (its solid
 * is then the other half-space: `plane { x, -30 inverse }` bounds x from below). */
static bool inverse_plane(const scene_object *q, uint32_t k)
{
	if (!q->inverse || q->geom->kind != SHAPE_PLANE)
		return false;
	for (uint32_t j = k + 1; j < q->csg_depth; j++)
		if (q->csg[j].inverse)
			return false;
	return true;
}

/* The box (in o's shape's own space) that o's CSG solid confines o's surface to: at each
 * intersection on its path the boxes of the other operands, at each difference where o is
 * subtracted the first operand's (an operand's box: the join of its objects', all of space where
 * one is turned inside out). Each is taken into o's space by its transform then o's inverse, so
 * that transforms they share (a clipped_by's, an intersection's) cancel and leave no axis open. */
static bbox context_box(const world *w, const scene *sc, const scene_object *o)
{
	bbox ctx = box_all();
	xform back; /* o's inverse: xform keeps it beside the matrix */
	memcpy(back.m, o->transform.inv, sizeof back.m);
	memcpy(back.inv, o->transform.m, sizeof back.inv);
	size_t n = scene_n_objects(sc);
	for (uint32_t k = 0; k < o->csg_depth; k++) {
		const scene_csg_step *st = &o->csg[k];
		bool inter = st->op == SCENE_CSG_INTERSECTION, diff = st->op == SCENE_CSG_DIFFERENCE && st->operand != 0;
		if (!inter && !diff)
			continue;
		uint32_t nops = 0;
		for (size_t i = 0; i < n; i++) {
			const scene_object *q = scene_object_at(sc, i);
			if (q->csg_depth > k && q->csg[k].id == st->id && q->csg[k].operand + 1 > nops)
				nops = q->csg[k].operand + 1;
		}
		for (uint32_t op = 0; op < (diff ? 1 : nops); op++) {
			if (op == st->operand)
				continue;
			bbox b = box_none();
			bool any = false;
			for (size_t i = 0; i < n; i++) {
				const scene_object *q = scene_object_at(sc, i);
				if (q == o || q->csg_depth <= k || q->csg[k].id != st->id || q->csg[k].operand != op)
					continue;
				any = true;
				xform rel = xform_then(q->transform, back);
				b = box_join(b, !inverted_below(q, k)	 ? box_map(rel.m, own_box(w, q->geom))
						: inverse_plane(q, k) ? box_map(rel.m, plane_box(q->geom, true))
									: box_all());
			}
			if (any)
				ctx = box_meet(ctx, b);
		}
	}
	return ctx;
}

/* Whether g is a polynomial surface circe polygonises inside a box: a poly, or a quadric that is
 * not an ellipsoid. */
static bool boxed_surface(const scene_geom *g)
{
	if (g->kind == SHAPE_POLY)
		return true;
	if (g->kind != SHAPE_QUADRIC)
		return false;
	double q[10], r;
	dvec3 c;
	quadric_coeffs(&g->u.quadric, q);
	return shape_quadric_bound(q, &c, &r) == SHAPE_QUADRIC_UNBOUNDED;
}

/* The box (in o's shape's own space) o's polynomial surface is polygonised in: o's CSG context and
 * its own solid's box; not finite where nothing bounds it. (polysurf.c grows it, so that the faces
 * closing the mesh lie outside the bounding objects, where the CSG drops them.) */
static bbox surface_box(const world *w, const scene *sc, const scene_object *o)
{
	return box_meet(context_box(w, sc, o), own_box(w, o->geom));
}

/* The error (object units) object o asks of its shape: the sphere's pixel bounds through the
 * pixels a unit of the shape takes on screen; 0 where the camera is inside its bound. A polynomial
 * surface is bounded by its box (box: NULL for the others). */
static double object_error(const scene_object *o, const bbox *box, const subd_camera *view, double *max_edge)
{
	dvec3 c;
	double r;
	*max_edge = 0.0;
	if (box && box_finite(*box) && !box_empty(*box))
		c = d3_scale(d3_add(box->lo, box->hi), 0.5), r = 0.5 * d3_length(d3_sub(box->hi, box->lo));
	else if (box || !shape_bound(o->geom, &c, &r))
		return INFINITY;
	double s = axis_scale(&o->transform);
	double ppu = view_px_per_unit(view, xform_point(&o->transform, c), r * s) * s;
	if (!(ppu > 0.0) || !isfinite(ppu))
		return 0.0;
	*max_edge = WORLD_SPHERE_MAX_EDGE_PX / ppu;
	return WORLD_SPHERE_MAX_ERROR_PX / ppu;
}

/* The height of a pixel as POV-Ray's image_height_at (source/backend/support/imageutil.cpp), in
 * 0 .. 65535: grey images by their grey, 8-bit colour ones red as the high byte and green as the
 * low one, deeper colour ones by their grey (0.297, 0.589, 0.114). A palette image is read by its
 * colours (POV-Ray takes index * 256: the same for a grey ramp, within 1/257). */
static float pixel_height(const float *px, bool grey, bool deep)
{
	double h;
	if (grey)
		h = floor(px[0] * 65535.0);
	else if (!deep)
		h = floor(px[0] * 255.0 + 0.5) * 256.0 + floor(px[1] * 255.0 + 0.5);
	else
		h = floor((0.297 * px[0] + 0.589 * px[1] + 0.114 * px[2]) * 65535.0);
	return (float)(fmin(fmax(h, 0.0), 65535.0) / 65536.0);
}

/* The format of a file by its first bytes, and a PNG's bit depth and colour type (IHDR bytes 24, 25). */
static image_format file_format(const char *path, int *depth, int *colour)
{
	unsigned char b[26] = {0};
	FILE *f = fopen(path, "rb");
	size_t got = f ? fread(b, 1, sizeof b, f) : 0;
	if (f)
		fclose(f);
	image_format k = image_format_of(b, got);
	if (k == IMAGE_PNG && got == sizeof b)
		*depth = b[24], *colour = b[25];
	return k;
}

/* The field of g's image, tessellated. The image may hold 16 bytes a pixel for each triangle the
 * shape may make (a field has two a pixel): anything larger would be refused after loading. */
static bool build_height_field(const scene_geom *g, const shape_accuracy *a, mesh *m, diag *d)
{
	const scene_height_field *h = &g->u.height_field;
	if (h->heights) /* a function's field: its heights, computed by the parser */
		return shape_height_field(h->heights, h->fn_w, h->fn_h, h->smooth, h->water_level, a, m, d, g->loc);
	image img;
	if (!image_load_limited(h->path, IMAGE_RAW, (size_t)a->max_triangles * 16, &img, d)) {
		diag_note(d, h->path_loc, "the height field's image was named here");
		return false;
	}
	int depth = 8, colour = 2;
	image_format k = file_format(h->path, &depth, &colour);
	/* PNG: by its header; JPEG: 8-bit colour (a grey one reads the same, r = g); EXR: deep. */
	bool grey = k == IMAGE_PNG && (colour == 0 || colour == 4);
	bool deep = k == IMAGE_EXR || k == IMAGE_HDR || (k == IMAGE_PNG && depth > 8);
	uint32_t w = (uint32_t)img.width, hh = (uint32_t)img.height;
	float *heights = mem_alloc((size_t)w * hh, sizeof *heights);
	bool ok = heights != NULL;
	if (!ok)
		diag_error(d, g->loc, "out of memory while reading the height field");
	for (uint32_t z = 0; ok && z < hh; z++) /* z = 0 is the image's bottom row (POV-Ray's Map) */
		for (uint32_t x = 0; x < w; x++)
			heights[(size_t)z * w + x] = pixel_height(&img.rgba[4 * ((size_t)(hh - 1 - z) * w + x)], grey, deep);
	ok = ok && shape_height_field(heights, w, hh, h->smooth, h->water_level, a, m, d, g->loc);
	mem_free(heights);
	image_free(&img);
	return ok;
}

/* How far the scene's box reaches (BUILD_SCENE_BOX_GROWTH times its diagonal beyond it on each
 * side) where it bounds a polynomial surface nothing else bounds. */
#define BUILD_SCENE_BOX_GROWTH 1.0

/* The scene's box, world space: the camera, its look_at and every object circe can bound (planes and other
 * unbounded solids left out), grown by BUILD_SCENE_BOX_GROWTH diagonals on each side (at least a
 * unit). POV-Ray's unbounded quadric or poly is infinite; circe's mesh ends there. */
static bbox scene_box(const world *w, const scene *sc)
{
	bbox b = box_none();
	if (sc->has_camera) {
		b = (bbox){sc->camera.location, sc->camera.location};
		if (sc->camera.has_look_at)
			b = box_join(b, (bbox){sc->camera.look_at, sc->camera.look_at});
	}
	for (size_t i = 0; i < scene_n_objects(sc); i++) {
		const scene_object *o = scene_object_at(sc, i);
		bbox ob = own_box(w, o->geom);
		if (!box_empty(ob) && box_finite(ob))
			b = box_join(b, box_map(o->transform.m, ob));
	}
	if (box_empty(b))
		b = (bbox){d3(0, 0, 0), d3(0, 0, 0)};
	double g = fmax(BUILD_SCENE_BOX_GROWTH * d3_length(d3_sub(b.hi, b.lo)), 1.0);
	return (bbox){d3_sub(b.lo, d3(g, g, g)), d3_add(b.hi, d3(g, g, g))};
}

/* A polynomial surface (a poly, a quadric that is not an ellipsoid) inside its box; nothing where
 * the box is empty (its CSG keeps none of it). Where an object leaves it unbounded (`unbounded`:
 * the first), its box holds the scene's box there (build_shapes), and a warning says so. */
static bool boxed_tessellate(const world *w, const scene *sc, const scene_geom *g, bbox box,
			     const scene_object *unbounded, const shape_accuracy *a, mesh *m, double *err, diag *d)
{
	const char *what = g->kind == SHAPE_POLY ? g->u.poly.keyword : "quadric";
	(void)w, (void)sc;
	if (unbounded)
		diag_warning(d, unbounded->loc,
			     "an unbounded %s: circe polygonises it inside the scene's box (the camera and the bounded "
			     "objects, grown by their size on each side), where POV-Ray's is infinite; bound it "
			     "(clipped_by, bounded_by, an intersection) to choose",
			     what);
	if (unbounded && (unbounded->loc.line != g->loc.line || unbounded->loc.col != g->loc.col ||
			  unbounded->loc.src != g->loc.src))
		diag_note(d, g->loc, "the %s was written here", what);
	memset(m, 0, sizeof *m);
	if (box_empty(box))
		return true;
	double qc[10];
	const double *c = g->u.poly.coeffs;
	int order = g->u.poly.order;
	if (g->kind == SHAPE_QUADRIC) {
		double q[10];
		quadric_coeffs(&g->u.quadric, q);
		shape_quadric_poly(q, qc);
		c = qc, order = 2;
	}
	return shape_poly_surface(order, c, box.lo, box.hi, a->max_error, m, err, what, d, g->loc);
}

/* Tessellates g at the accuracy a; *err receives the bound met (0: exact). A polynomial surface
 * is polygonised in box (unbounded: the first object that leaves it unbounded, or NULL). */
static bool tessellate(const world *w, const scene *sc, const scene_geom *g, const shape_accuracy *a, bbox box,
		       const scene_object *unbounded, mesh *m, double *err, diag *d, diag_loc use)
{
	*err = 0.0;
	switch (g->kind) {
	case SHAPE_CONE: {
		const scene_cone *c = &g->u.cone;
		return shape_cone(c->base, c->base_radius, c->cap, c->cap_radius, c->open, a, m, err, d, g->loc);
	}
	case SHAPE_TORUS:
		return shape_torus(g->u.torus.major, g->u.torus.minor, a, m, err, d, g->loc);
	case SHAPE_DISC:
		return shape_disc(g->u.disc.center, g->u.disc.normal, g->u.disc.radius, g->u.disc.hole, a, m, err, d, g->loc);
	case SHAPE_POLYGON:
		return shape_polygon(g->u.polygon.points, g->u.polygon.n, a, m, d, g->loc);
	case SHAPE_SUPERELLIPSOID:
		return shape_superellipsoid(g->u.superellipsoid.e, g->u.superellipsoid.n, a, m, err, d, g->loc);
	case SHAPE_HEIGHT_FIELD:
		return build_height_field(g, a, m, d);
	case SHAPE_QUADRIC: {
		double q[10];
		shape_quadric_kind kind;
		quadric_coeffs(&g->u.quadric, q);
		if (!shape_quadric(q, a, m, err, &kind, d, g->loc))
			return false;
		if (kind == SHAPE_QUADRIC_ELLIPSOID)
			return true;
		if (kind == SHAPE_QUADRIC_UNBOUNDED)
			return boxed_tessellate(w, sc, g, box, unbounded, a, m, err, d);
		diag_error(d, use, "this quadric has no points: it is empty");
		if (use.line != g->loc.line || use.col != g->loc.col || use.src != g->loc.src)
			diag_note(d, g->loc, "the quadric was written here");
		return false;
	}
	case SHAPE_POLY:
		return boxed_tessellate(w, sc, g, box, unbounded, a, m, err, d);
	default:
		return true;
	}
}

bool build_shapes(world *w, const scene *sc, const subd_camera *view, diag *d)
{
	size_t n = scene_n_objects(sc), ng = sc->n_geoms ? sc->n_geoms : 1;
	double *need = mem_alloc(ng, sizeof *need);
	double *edge = mem_alloc(ng, sizeof *edge);
	const scene_object **first = mem_calloc(ng, sizeof *first);
	const scene_object **unbounded = mem_calloc(ng, sizeof *unbounded);
	bbox *boxes = mem_alloc(ng, sizeof *boxes);
	bool ok = need && edge && first && unbounded && boxes;
	if (!ok) {
		mem_free(need), mem_free(edge), mem_free(first), mem_free(unbounded), mem_free(boxes);
		diag_error(d, diag_noloc(), "out of memory");
		return false;
	}
	bbox world_box = scene_box(w, sc);
	for (size_t i = 0; i < n; i++) {
		const scene_object *o = scene_object_at(sc, i);
		if (!is_shape(o->geom->kind))
			continue;
		uint32_t id = o->geom->id;
		bbox b, *bp = NULL;
		if (boxed_surface(o->geom)) { /* its box: where this object's CSG keeps it */
			if (!first[id])
				boxes[id] = box_none();
			b = surface_box(w, sc, o), bp = &b;
			if (!box_empty(b) && !box_finite(b)) { /* within the scene's box, in the object's space */
				if (!unbounded[id])
					unbounded[id] = o;
				b = box_meet(b, box_map(o->transform.inv, world_box));
			}
			boxes[id] = box_join(boxes[id], b);
		}
		double e, er = object_error(o, bp, view, &e);
		if (!first[id] || er < need[id])
			need[id] = er, edge[id] = e;
		if (!first[id])
			first[id] = o;
	}
	/* In the order of the scene's objects' first use, so check's list reads like the scene. */
	for (size_t i = 0; ok && i < n; i++) {
		const scene_object *o = scene_object_at(sc, i);
		uint32_t id = o->geom->id;
		if (!is_shape(o->geom->kind) || first[id] != o)
			continue;
		/* The camera inside the bound: the finest tessellation (a tiny error asks for it). */
		double er = need[id] > 0.0 ? need[id] : DBL_MIN, ed = need[id] > 0.0 ? edge[id] : DBL_MIN;
		shape_accuracy a = {.max_error = er, .max_edge = ed, .max_triangles = SHAPE_MAX_TRIANGLES};
		double err;
		bbox b = boxed_surface(o->geom) ? boxes[id] : box_all();
		ok = tessellate(w, sc, o->geom, &a, b, unbounded[id], &w->geoms[id].m, &err, d, o->loc);
		world_shape_stat st = {scene_shape_name(o->geom), o->geom->loc, w->geoms[id].m.num_triangles, err, -1};
		ok = ok && note_shape(w, &st, d);
	}
	mem_free(need), mem_free(edge), mem_free(first), mem_free(unbounded), mem_free(boxes);
	return ok;
}
