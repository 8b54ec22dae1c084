/* build_shapes.c - POV-Ray's shapes (cylinder, cone, torus, disc, polygon, superellipsoid,
 * height_field, quadric; src/geom/povshape.h) tessellated for the objects that use them. A shape
 * declared and never placed costs nothing (shapes.inc declares dozens), and the accuracy follows
 * the sphere's rule on screen (build_inst.c's view_px_per_unit): its surface within
 * WORLD_SPHERE_MAX_ERROR_PX and its edges along curves within WORLD_SPHERE_MAX_EDGE_PX, for the
 * most demanding object that uses it. */
#include "build/build_impl.h"

#include "base/mem.h"
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
 * height field) or not at all (an unbounded quadric, a poly). */
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

/* The error (object units) object o asks of its shape: the sphere's pixel bounds through the
 * pixels a unit of the shape takes on screen; 0 where the camera is inside its bound. */
static double object_error(const scene_object *o, const subd_camera *view, double *max_edge)
{
	dvec3 c;
	double r;
	*max_edge = 0.0;
	if (!shape_bound(o->geom, &c, &r))
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
	image img;
	if (!image_load_limited(h->path, IMAGE_RAW, (size_t)a->max_triangles * 16, &img, d)) {
		diag_note(d, h->path_loc, "the height field's image was named here");
		return false;
	}
	int depth = 8, colour = 2;
	image_format k = file_format(h->path, &depth, &colour);
	/* PNG: by its header; JPEG: 8-bit colour (a grey one reads the same, r = g); EXR: deep. */
	bool grey = k == IMAGE_PNG && (colour == 0 || colour == 4);
	bool deep = k == IMAGE_EXR || (k == IMAGE_PNG && depth > 8);
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

/* Tessellates g at the accuracy a; *err receives the bound met (0: exact). */
static bool tessellate(const scene_geom *g, const shape_accuracy *a, mesh *m, double *err, diag *d, diag_loc use)
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
		diag_error(d, use, kind == SHAPE_QUADRIC_EMPTY ? "this quadric has no points: it is empty"
							       : "an unbounded quadric is not supported by circe (it would be "
								 "polygonised inside a clipped_by or bounded_by, which circe "
								 "does not have yet)");
		if (use.line != g->loc.line || use.col != g->loc.col || use.src != g->loc.src)
			diag_note(d, g->loc, "the quadric was written here");
		return false;
	}
	case SHAPE_POLY:
		diag_error(d, use, "a %s surface is not supported by circe (it would be polygonised inside a "
				   "clipped_by or bounded_by, which circe does not have yet)", g->u.poly.keyword);
		if (use.line != g->loc.line || use.col != g->loc.col || use.src != g->loc.src)
			diag_note(d, g->loc, "the %s was written here", g->u.poly.keyword);
		return false;
	default:
		return true;
	}
}

bool build_shapes(world *w, const scene *sc, const subd_camera *view, diag *d)
{
	size_t n = scene_n_objects(sc);
	double *need = mem_alloc(sc->n_geoms ? sc->n_geoms : 1, sizeof *need);
	double *edge = mem_alloc(sc->n_geoms ? sc->n_geoms : 1, sizeof *edge);
	const scene_object **first = mem_calloc(sc->n_geoms ? sc->n_geoms : 1, sizeof *first);
	bool ok = need && edge && first;
	if (!ok) {
		mem_free(need), mem_free(edge), mem_free(first);
		diag_error(d, diag_noloc(), "out of memory");
		return false;
	}
	for (size_t i = 0; i < n; i++) {
		const scene_object *o = scene_object_at(sc, i);
		if (!is_shape(o->geom->kind))
			continue;
		uint32_t id = o->geom->id;
		double e, er = object_error(o, view, &e);
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
		ok = tessellate(o->geom, &a, &w->geoms[id].m, &err, d, o->loc);
		world_shape_stat st = {scene_shape_name(o->geom), o->geom->loc, w->geoms[id].m.num_triangles, err, -1};
		ok = ok && note_shape(w, &st, d);
	}
	mem_free(need), mem_free(edge), mem_free(first);
	return ok;
}
