/* extent.c - POV-Ray's min_extent(object) and max_extent(object): the corners of the object's
 * bounding box, as POV-Ray's parser computes it (Compute_BBox, then the transform's box of it;
 * source/core/shape/csg.cpp for CSG: a union or merge joins its operands' boxes, an intersection
 * meets them, a difference keeps its first operand's; clipped_by is an intersection with the
 * clipping objects). Each shape's own box comes from its IR record: exact for spheres, boxes,
 * cones, tori, discs, polygons, meshes and inline cages, POV-Ray's unit boxes for the
 * superellipsoid and the height field, geom's for the quadric (shape_quadric_box) and the shapes
 * of geom/shape.h (shape_bounds: a text's is estimated, an em a character). What is unbounded (a
 * plane, an unbounded quadric, a poly, an inverted object, a mesh file whose size is not read at
 * parse time) gives POV-Ray's huge box, -1e10 .. 1e10 (BOUND_HUGE / 2). The words are no keywords
 * (LTK_UNSUPPORTED, matched by spelling). */
#include "lang/parser.h"

#include "geom/polysurf.h"
#include "geom/shape.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* POV-Ray's BOUND_HUGE / 2: an unbounded object's box (Make_BBox(-BOUND_HUGE / 2, BOUND_HUGE)). */
#define EXTENT_HUGE 1e10

typedef struct ebox {
	double lo[3], hi[3];
} ebox;

static ebox e_all(void) { return (ebox){{-INFINITY, -INFINITY, -INFINITY}, {INFINITY, INFINITY, INFINITY}}; }
static ebox e_none(void) { return (ebox){{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}}; }
static ebox e_pt(dvec3 a) { return (ebox){{a.x, a.y, a.z}, {a.x, a.y, a.z}}; }
static ebox e_join(ebox a, ebox b)
{
	for (int i = 0; i < 3; i++)
		a.lo[i] = fmin(a.lo[i], b.lo[i]), a.hi[i] = fmax(a.hi[i], b.hi[i]);
	return a;
}
static ebox e_meet(ebox a, ebox b)
{
	for (int i = 0; i < 3; i++)
		a.lo[i] = fmax(a.lo[i], b.lo[i]), a.hi[i] = fmin(a.hi[i], b.hi[i]);
	return a;
}
static ebox e_grow(dvec3 c, dvec3 r) { return (ebox){{c.x - r.x, c.y - r.y, c.z - r.z}, {c.x + r.x, c.y + r.y, c.z + r.z}}; }

/* The box of t applied to b, by interval arithmetic (an infinite side stays infinite only on the
 * axes it maps to). */
static ebox e_map(const xform *t, ebox b)
{
	if (b.lo[0] > b.hi[0] || b.lo[1] > b.hi[1] || b.lo[2] > b.hi[2])
		return b;
	ebox r;
	for (int j = 0; j < 3; j++) {
		double big = fmax(fabs(t->m[j][0]), fmax(fabs(t->m[j][1]), fabs(t->m[j][2])));
		r.lo[j] = r.hi[j] = t->m[j][3];
		for (int i = 0; i < 3; i++) {
			double c = t->m[j][i];
			if (fabs(c) <= 1e-12 * big)
				continue;
			double a = c * b.lo[i], e = c * b.hi[i];
			r.lo[j] += fmin(a, e), r.hi[j] += fmax(a, e);
		}
	}
	return r;
}

/* A disc of radius r about c facing n: its box (r sqrt(1 - n_a^2) along each axis a). */
static ebox e_disc(dvec3 c, dvec3 n, double r)
{
	double l = d3_length(n);
	dvec3 u = l > 0 ? d3_scale(n, 1 / l) : d3(0, 1, 0);
	return e_grow(c, d3(r * sqrt(fmax(0, 1 - u.x * u.x)), r * sqrt(fmax(0, 1 - u.y * u.y)), r * sqrt(fmax(0, 1 - u.z * u.z))));
}

/* The box of a geometry record in its own space. */
static ebox own(const scene_geom *g)
{
	switch (g->kind) {
	case SHAPE_SPHERE: {
		double r = g->u.sphere.radius;
		return e_grow(g->u.sphere.center, d3(r, r, r));
	}
	case SHAPE_BOX: return e_join(e_pt(g->u.box.corner1), e_pt(g->u.box.corner2));
	case SHAPE_MESH: {
		ebox b = e_none();
		for (uint32_t i = 0; i < g->u.mesh.n_positions; i++)
			b = e_join(b, e_pt(v3_to_d3(g->u.mesh.positions[i])));
		return b;
	}
	case SHAPE_SUBDIV: { /* the limit surface lies in its cage's hull */
		if (g->u.subdiv.file || !g->u.subdiv.n_vertices)
			return e_all();
		ebox b = e_none();
		for (uint32_t i = 0; i < g->u.subdiv.n_vertices; i++)
			b = e_join(b, e_pt(v3_to_d3(g->u.subdiv.vertices[i])));
		return b;
	}
	case SHAPE_POV: {
		dvec3 lo, hi;
		shape_bounds(g->u.pov, &lo, &hi);
		return e_join(e_pt(lo), e_pt(hi));
	}
	case SHAPE_CONE: {
		const scene_cone *c = &g->u.cone;
		dvec3 ax = d3_sub(c->cap, c->base);
		return e_join(e_disc(c->base, ax, c->base_radius), e_disc(c->cap, ax, c->cap_radius));
	}
	case SHAPE_TORUS: {
		double R = g->u.torus.major + g->u.torus.minor, r = g->u.torus.minor;
		return e_grow(d3(0, 0, 0), d3(R, r, R));
	}
	case SHAPE_DISC: return e_disc(g->u.disc.center, g->u.disc.normal, g->u.disc.radius);
	case SHAPE_POLYGON: {
		ebox b = e_none();
		for (uint32_t i = 0; i < g->u.polygon.n; i++)
			b = e_join(b, e_pt(g->u.polygon.points[i]));
		return b;
	}
	case SHAPE_SUPERELLIPSOID: return e_grow(d3(0, 0, 0), d3(1, 1, 1));
	case SHAPE_HEIGHT_FIELD: return e_join(e_pt(d3(0, 0, 0)), e_pt(d3(1, 1, 1)));
	case SHAPE_QUADRIC: {
		const scene_quadric *q = &g->u.quadric;
		const double c[10] = {q->square.x, q->square.y, q->square.z, q->mixed.x, q->mixed.y,
				      q->mixed.z, q->linear.x, q->linear.y, q->linear.z, q->constant};
		dvec3 lo, hi;
		if (!shape_quadric_box(c, &lo, &hi))
			return e_none();
		return (ebox){{lo.x, lo.y, lo.z}, {hi.x, hi.y, hi.z}};
	}
	case SHAPE_PLANE: case SHAPE_MESH_FILE: case SHAPE_POLY:
	default: return e_all();
	}
}

/* The box of objs[idx[0..n)] at CSG depth d: each object alone there, each CSG node by its operator
 * over its operands. */
static bool list_box(parser *p, const scene_object *objs, const size_t *idx, size_t n, uint32_t d, ebox *out)
{
	ebox acc = e_none();
	bool *done = mem_calloc(n ? n : 1, sizeof *done);
	size_t *sub = mem_alloc(n ? n : 1, sizeof *sub);
	bool ok = done && sub;
	for (size_t i = 0; ok && i < n; i++) {
		if (done[i])
			continue;
		const scene_object *o = &objs[idx[i]];
		if (o->csg_depth <= d) {
			acc = e_join(acc, o->inverse ? e_all() : e_map(&o->transform, own(o->geom)));
			done[i] = true;
			continue;
		}
		const scene_csg_step *st = &o->csg[d];
		uint32_t maxop = 0;
		for (size_t j = i; j < n; j++) {
			const scene_object *q = &objs[idx[j]];
			if (!done[j] && q->csg_depth > d && q->csg[d].id == st->id && q->csg[d].operand > maxop)
				maxop = q->csg[d].operand;
		}
		ebox node = st->op == SCENE_CSG_INTERSECTION ? e_all() : e_none();
		for (uint32_t k = 0; ok && k <= maxop; k++) {
			size_t m = 0;
			for (size_t j = i; j < n; j++) {
				const scene_object *q = &objs[idx[j]];
				if (!done[j] && q->csg_depth > d && q->csg[d].id == st->id && q->csg[d].operand == k)
					sub[m++] = idx[j];
			}
			if (!m)
				continue;
			ebox b;
			size_t *copy = mem_alloc(m, sizeof *copy);
			ok = copy && (memcpy(copy, sub, m * sizeof *copy), list_box(p, objs, copy, m, d + 1, &b));
			mem_free(copy);
			if (!ok)
				break;
			if (st->op == SCENE_CSG_INTERSECTION)
				node = e_meet(node, b);
			else if (st->op != SCENE_CSG_DIFFERENCE || k == 0)
				node = e_join(node, b);
		}
		for (size_t j = i; j < n; j++) {
			const scene_object *q = &objs[idx[j]];
			if (q->csg_depth > d && q->csg[d].id == st->id)
				done[j] = true;
		}
		acc = e_join(acc, st->inverse ? e_all() : node);
	}
	mem_free(done), mem_free(sub);
	if (!ok)
		return lang_error(p, p->prev.loc, "out of memory");
	*out = acc;
	return true;
}

bool lang_extent(parser *p, value *out)
{
	lang_token name = *lang_advance(p);
	bool max = lang_word_is(&name, "max_extent");
	char ctx[64];
	snprintf(ctx, sizeof ctx, "after '%s'", max ? "max_extent" : "min_extent");
	TRY(lang_expect(p, LTK_LPAREN, ctx));
	diag_loc at = lang_peek(p)->loc;
	value v;
	TRY(lang_expr(p, &v));
	if (v.kind != VAL_OBJECT || !v.obj)
		return lang_error(p, at, "'%s' needs an object, found %s", max ? "max_extent" : "min_extent",
				  lang_value_kind_name(&v));
	snprintf(ctx, sizeof ctx, "to close the argument of '%s'", max ? "max_extent" : "min_extent");
	TRY(lang_expect(p, LTK_RPAREN, ctx));
	size_t n = v.obj->n, *idx = mem_alloc(n ? n : 1, sizeof *idx);
	if (!idx)
		return lang_error(p, at, "out of memory");
	for (size_t i = 0; i < n; i++)
		idx[i] = i;
	ebox b;
	bool ok = list_box(p, v.obj->items, idx, n, 0, &b);
	mem_free(idx);
	TRY(ok);
	memset(out, 0, sizeof *out);
	out->kind = VAL_VECTOR, out->n = 3;
	for (int i = 0; i < 3; i++) {
		double x = max ? b.hi[i] : b.lo[i];
		if (b.lo[i] > b.hi[i]) /* nothing at all (an empty intersection): POV-Ray's box is empty too */
			x = 0;
		out->v[i] = fmin(fmax(x, -EXTENT_HUGE), EXTENT_HUGE);
	}
	return true;
}

/* The opening of trace's and inside's arguments: the function's name, "(", an object value and ",". */
static bool object_argument(parser *p, const char *fn, lang_token *name, value *v)
{
	*name = *lang_advance(p);
	char after[32];
	snprintf(after, sizeof after, "after '%s'", fn);
	TRY(lang_expect(p, LTK_LPAREN, after));
	diag_loc at = lang_peek(p)->loc;
	TRY(lang_expr(p, v));
	if (v->kind != VAL_OBJECT || !v->obj)
		return lang_error(p, at, "'%s' needs an object, found %s", fn, lang_value_kind_name(v));
	snprintf(after, sizeof after, "after the object of '%s'", fn);
	return lang_expect(p, LTK_COMMA, after);
}

/* trace = "trace" "(" expression "," vector "," vector [ "," identifier ] ")"
 * POV-Ray's Parse_Trace (source/parser/parser_functions.cpp): the first hit of the ray from the
 * start along the direction on the object, <0, 0, 0> when there is none; the identifier, a
 * declared one, receives the unit outward normal there (<0, 0, 0> without a hit). The hit is
 * found by the caller's lang_options.trace (main.c gives the build's, which traces the object's
 * tessellated surface, as rendered); the object is any object value, its declared name the key
 * of the callee's cache. */
bool lang_trace(parser *p, value *out)
{
	lang_token name;
	value v;
	TRY(object_argument(p, "trace", &name, &v));
	dvec3 org, dir;
	TRY(lang_vec3(p, "(the start of 'trace')", &org));
	TRY(lang_expect(p, LTK_COMMA, "after the start of 'trace'"));
	diag_loc dir_at = lang_peek(p)->loc;
	TRY(lang_vec3(p, "(the direction of 'trace')", &dir));
	lang_token normal = {0};
	bool has_normal = false;
	if (lang_accept(p, LTK_COMMA) && lang_peek(p)->kind != LTK_RPAREN) {
		p->no_expand = true;
		normal = *lang_peek(p);
		p->no_expand = false;
		if (normal.kind != LTK_IDENT)
			return lang_error_found(p, "expected the name of a declared vector to receive the normal of 'trace'");
		if (!lang_lookup(p, normal.text, normal.len))
			return lang_error(p, normal.loc, "the normal of 'trace' goes into a declared identifier: '%.*s' is "
							 "not declared (#declare it first, as POV-Ray asks)",
					  (int)normal.len, normal.text);
		lang_advance(p);
		has_normal = true;
	}
	TRY(lang_expect(p, LTK_RPAREN, "to close the arguments of 'trace'"));
	if (!(d3_length(dir) > 0))
		return lang_error(p, dir_at, "the direction of 'trace' is the zero vector");
	if (!p->opt.trace)
		return lang_error(p, name.loc, "'trace' is not supported by circe here (no tracer: it needs the build)");
	dvec3 hit, n;
	int r = p->opt.trace(p->opt.trace_user, p->sc, v.obj->items, v.obj->n, v.obj, org, dir, &hit, &n, p->d, name.loc);
	if (r < 0)
		return false;
	memset(out, 0, sizeof *out);
	out->kind = VAL_VECTOR, out->n = 3;
	out->v[0] = hit.x, out->v[1] = hit.y, out->v[2] = hit.z;
	if (has_normal) {
		value nv = {.kind = VAL_VECTOR, .n = 3, .v = {n.x, n.y, n.z}};
		TRY(lang_define(p, &normal, false, &nv));
	}
	return true;
}

/* inside = "inside" "(" expression "," vector ")"   POV-Ray's Inside_Object at parse time: 1 when
 * the point is inside the object (its tessellated solid; CSG by its trees), else 0, by
 * lang_options.inside (main.c gives the build's). */
bool lang_inside(parser *p, value *out)
{
	lang_token name;
	value v;
	TRY(object_argument(p, "inside", &name, &v));
	dvec3 q;
	TRY(lang_vec3(p, "(the point of 'inside')", &q));
	TRY(lang_expect(p, LTK_RPAREN, "to close the arguments of 'inside'"));
	if (!p->opt.inside)
		return lang_error(p, name.loc, "'inside' is not supported by circe here (no inside test: it needs the build)");
	scene_fn fn;
	TRY(p->opt.inside(p->opt.trace_user, p->sc, v.obj->items, v.obj->n, v.obj, &fn, p->d, name.loc));
	double xyz[3] = {q.x, q.y, q.z}, r = 0;
	if (!fn.eval || !fn.eval(fn.ctx, xyz, &r))
		r = 0;
	memset(out, 0, sizeof *out);
	out->kind = VAL_FLOAT, out->n = 1;
	out->v[0] = r > 0.5 ? 1.0 : 0.0;
	return true;
}
