/* shapes.c - POV-Ray 3.7's finite shapes and polynomial surfaces in the scene language: cylinder,
 * cone, torus, disc, polygon, superellipsoid, height_field, quadric, cubic, quartic and poly, with
 * POV-Ray's syntax (Parse_Comma: commas between the parameters optional) and defaults. Each makes
 * one geometry record (scene.h) and its object, with the common modifiers (stmt.c). */
#include "lang/parser.h"
#include "lang/func.h"

#include <math.h>
#include <string.h>

/* POV-Ray's polynomial order limit (MAX_ORDER, source/backend/math/polysolv.h). */
#define POLY_MAX_ORDER 35
/* A polygon's points (SHAPE_POLYGON_MAX_POINTS of src/geom/povshape.h: its triangulation pairs edges). */
#define POLYGON_MAX_POINTS 10000
/* POV-Ray's EPSILON (configbackend.h): a polygon point this close to its subpolygon's first closes it. */
#define POV_EPSILON 1.0e-10

static bool nonneg(parser *p, diag_loc loc, const char *what, double x)
{
	return x >= 0 || lang_error(p, loc, "%s must be >= 0, found %g", what, x);
}

/* float, with its place */
static bool float_at(parser *p, const char *what, double *x, diag_loc *loc)
{
	*loc = lang_peek(p)->loc;
	return lang_float(p, what, x);
}

/* The common end of a cone and a cylinder: distinct end points (POV-Ray's Compute_Cone_Data
 * throws "Degenerate cone/cylinder" within EPSILON), then [ "open" ] and the modifiers. */
static bool cone_tail(parser *p, vecbuf *out, scene_geom *g, diag_loc kw, diag_loc open, const char *what)
{
	scene_cone *c = &g->u.cone;
	if (d3_length(d3_sub(c->cap, c->base)) < POV_EPSILON)
		return lang_error(p, kw, "degenerate %s: its base and cap points are the same", what);
	c->open = lang_accept(p, LTK_KW_OPEN);
	return lang_place_object(p, out, g, kw, open, what);
}

/* cylinder = "cylinder" "{" vector [","] vector [","] float [ "open" ] { modifier } "}" */
static bool cylinder(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	scene_geom *g;
	TRY(g = lang_new_geom(p, SHAPE_CONE, kw));
	scene_cone *c = &g->u.cone;
	c->cylinder = true;
	diag_loc rl;
	TRY(lang_vec3(p, "as the cylinder's base point", &c->base));
	lang_accept(p, LTK_COMMA);
	TRY(lang_vec3(p, "as the cylinder's cap point", &c->cap));
	lang_accept(p, LTK_COMMA);
	TRY(float_at(p, "as the cylinder radius", &c->base_radius, &rl));
	c->cap_radius = c->base_radius;
	if (!(c->base_radius > 0))
		return lang_error(p, rl, "cylinder radius must be > 0, found %g", c->base_radius);
	return cone_tail(p, out, g, kw, open, "cylinder");
}

/* cone = "cone" "{" vector [","] float [","] vector [","] float [ "open" ] { modifier } "}" */
static bool cone(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	scene_geom *g;
	TRY(g = lang_new_geom(p, SHAPE_CONE, kw));
	scene_cone *c = &g->u.cone;
	diag_loc bl, cl;
	TRY(lang_vec3(p, "as the cone's base point", &c->base));
	lang_accept(p, LTK_COMMA);
	TRY(float_at(p, "as the cone's base radius", &c->base_radius, &bl));
	TRY(nonneg(p, bl, "cone base radius", c->base_radius));
	lang_accept(p, LTK_COMMA);
	TRY(lang_vec3(p, "as the cone's cap point", &c->cap));
	lang_accept(p, LTK_COMMA);
	TRY(float_at(p, "as the cone's cap radius", &c->cap_radius, &cl));
	TRY(nonneg(p, cl, "cone cap radius", c->cap_radius));
	if (c->base_radius == 0 && c->cap_radius == 0)
		return lang_error(p, cl, "degenerate cone: both radii are 0");
	return cone_tail(p, out, g, kw, open, "cone");
}

/* torus = "torus" "{" float [","] float { modifier | "sturm" } "}"   (major, minor radius) */
static bool torus(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	scene_geom *g;
	TRY(g = lang_new_geom(p, SHAPE_TORUS, kw));
	diag_loc ml, nl;
	TRY(float_at(p, "as the torus major radius", &g->u.torus.major, &ml));
	lang_accept(p, LTK_COMMA);
	TRY(float_at(p, "as the torus minor radius", &g->u.torus.minor, &nl));
	if (!(g->u.torus.minor > 0))
		return lang_error(p, nl, "torus minor radius must be > 0, found %g", g->u.torus.minor);
	if (!(g->u.torus.major >= g->u.torus.minor))
		return lang_error(p, ml, "a torus whose major radius (%g) is smaller than its minor radius (%g) (a spindle "
					 "torus) is not supported by circe",
				  g->u.torus.major, g->u.torus.minor);
	return lang_place_object(p, out, g, kw, open, "torus");
}

/* Whether the lookahead begins a float (POV-Ray's CASE_FLOAT): a number, a sign, a parenthesis, or
 * a name declared as a float. */
static bool float_ahead(parser *p)
{
	const lang_token *t = lang_peek(p);
	if (t->kind == LTK_NUMBER || t->kind == LTK_MINUS || t->kind == LTK_PLUS || t->kind == LTK_LPAREN)
		return true;
	if (t->kind != LTK_IDENT)
		return false;
	const symbol *s = lang_lookup(p, t->text, t->len);
	return s && s->val.kind == VAL_FLOAT;
}

/* disc = "disc" "{" vector [","] vector [","] float [ [","] float ] { modifier } "}"
 *        (centre, normal, radius, hole radius; POV-Ray's default hole 0) */
static bool disc(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	scene_geom *g;
	TRY(g = lang_new_geom(p, SHAPE_DISC, kw));
	diag_loc nl, rl, hl;
	TRY(lang_vec3(p, "as the disc centre", &g->u.disc.center));
	lang_accept(p, LTK_COMMA);
	nl = lang_peek(p)->loc;
	TRY(lang_vec3(p, "as the disc normal", &g->u.disc.normal));
	if (!(d3_length(g->u.disc.normal) > 0))
		return lang_error(p, nl, "the disc's normal is zero");
	lang_accept(p, LTK_COMMA);
	TRY(float_at(p, "as the disc radius", &g->u.disc.radius, &rl));
	/* POV-Ray stores radius^2: a negative radius is its magnitude. */
	g->u.disc.radius = fabs(g->u.disc.radius);
	if (!(g->u.disc.radius > 0))
		return lang_error(p, rl, "disc radius must be > 0, found %g", g->u.disc.radius);
	bool comma = lang_accept(p, LTK_COMMA);
	if (comma || float_ahead(p)) {
		TRY(float_at(p, "as the disc's hole radius", &g->u.disc.hole, &hl));
		g->u.disc.hole = fabs(g->u.disc.hole);
		if (!(g->u.disc.hole < g->u.disc.radius))
			return lang_error(p, hl, "the disc's hole radius (%g) is not smaller than its radius (%g)",
					  g->u.disc.hole, g->u.disc.radius);
	}
	return lang_place_object(p, out, g, kw, open, "disc");
}

/* Closes the subpolygons as POV-Ray's Parse_Polygon: a point within POV_EPSILON of its
 * subpolygon's first becomes exactly that point and ends it; an unclosed last one is closed by
 * repeating its first point, with POV-Ray's warning. Returns the count, *pts holding room for n + 1. */
static uint32_t close_polygon(parser *p, dvec3 *pts, uint32_t n, diag_loc kw)
{
	dvec3 first = pts[0];
	bool closed = false;
	for (uint32_t i = 1; i < n; i++) {
		closed = false;
		if (fabs(first.x - pts[i].x) < POV_EPSILON && fabs(first.y - pts[i].y) < POV_EPSILON &&
		    fabs(first.z - pts[i].z) < POV_EPSILON) {
			pts[i] = first;
			i++;
			if (i < n)
				first = pts[i];
			closed = true;
		}
	}
	if (closed)
		return n;
	diag_warning(p->d, kw, "polygon not closed: closing it (as POV-Ray does)");
	pts[n] = first;
	return n + 1;
}

/* polygon = "polygon" "{" int { [","] vector } { modifier } "}"   (the count, then the points) */
static bool polygon(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	scene_geom *g;
	TRY(g = lang_new_geom(p, SHAPE_POLYGON, kw));
	diag_loc nl;
	double count;
	TRY(float_at(p, "as the polygon's number of points", &count, &nl));
	if (!(count >= 3))
		return lang_error(p, nl, "polygon needs at least 3 points, found %g", count);
	if (count > POLYGON_MAX_POINTS)
		return lang_error(p, nl, "polygon has too many points (limit is %d)", POLYGON_MAX_POINTS);
	uint32_t n = (uint32_t)count; /* POV-Ray truncates */
	dvec3 *pts = arena_zalloc(&p->sc->arena, (size_t)n + 1, sizeof *pts);
	if (!pts)
		return lang_error(p, kw, "out of memory");
	for (uint32_t i = 0; i < n; i++) {
		lang_accept(p, LTK_COMMA);
		TRY(lang_vec3(p, "as a polygon point", &pts[i]));
	}
	g->u.polygon.points = pts;
	g->u.polygon.n = close_polygon(p, pts, n, kw);
	return lang_place_object(p, out, g, kw, open, "polygon");
}

/* superellipsoid = "superellipsoid" "{" vector { modifier } "}"   (<e, n>: POV-Ray's UV vector; a
 * float f is <f, f>) */
static bool superellipsoid(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	scene_geom *g;
	TRY(g = lang_new_geom(p, SHAPE_SUPERELLIPSOID, kw));
	diag_loc vl = lang_peek(p)->loc;
	value v;
	TRY(lang_expr(p, &v));
	if (v.kind == VAL_FLOAT) /* POV-Ray's Parse_UV_Vect promotes a float to <f, f> (cliche.pov) */
		v.kind = VAL_VECTOR, v.n = 2, v.v[1] = v.v[0];
	if (v.kind != VAL_VECTOR || v.n < 2)
		return lang_error(p, vl, "expected the vector <e, n> of the superellipsoid's exponents");
	g->u.superellipsoid.e = v.v[0], g->u.superellipsoid.n = v.v[1];
	if (!(v.v[0] > 0) || !(v.v[1] > 0))
		return lang_error(p, vl, "superellipsoid exponents must be > 0, found <%g, %g>", v.v[0], v.v[1]);
	return lang_place_object(p, out, g, kw, open, "superellipsoid");
}

/* The most points a height field's function may have (its grid: two triangles a cell). */
#define LANG_HF_FUNCTION_MAX_POINTS (1u << 22)

/* A 16-bit image channel as POV-Ray stores a function image's value (clamped, rounded). */
static double hf_channel(double v)
{
	return floor(fmin(fmax(v, 0.0), 1.0) * 65535.0 + 0.5) / 65535.0;
}

/* `function W, H { ... }` after its keyword kw: POV-Ray's function image (parser_materials.cpp
 * Make_Pattern_Image: the function at <i / (W - 1), j / (H - 1), 0> for pixel column i and row j,
 * 16-bit grey; a colour function (a pigment's) as a 16-bit colour image, whose height is its grey
 * 0.297 r + 0.589 g + 0.114 b) read as the field reads an image: row z = 0 is the image's last. */
static bool hf_function(parser *p, scene_height_field *h, lang_token kw)
{
	double w, hh;
	diag_loc wl = lang_peek(p)->loc;
	TRY(lang_float(p, "as the height field function's width", &w));
	lang_accept(p, LTK_COMMA);
	TRY(lang_float(p, "as the height field function's height", &hh));
	long W = (long)(w + 0.5), H = (long)(hh + 0.5);
	if (!(W >= 2 && H >= 2) || (double)W * (double)H > LANG_HF_FUNCTION_MAX_POINTS)
		return lang_error(p, wl, "a height field function's size must be at least 2 x 2 and at most %u points, found %ld x %ld",
				  LANG_HF_FUNCTION_MAX_POINTS, W, H);
	value v;
	diag_loc fl = lang_peek(p)->loc;
	TRY(lang_func_body(p, kw, &v));
	const lang_function *f = v.fn;
	if (f->n_params != 3 || (f->n_out != 1 && f->n_out != 5))
		return lang_error(p, fl, "a height field's function must give a float or a colour of x, y and z: '%s' takes %d "
					 "parameter%s and gives %d value%s",
				  f->name, f->n_params, f->n_params == 1 ? "" : "s", f->n_out, f->n_out == 1 ? "" : "s");
	float *z = arena_alloc(&p->sc->arena, (size_t)W * (size_t)H, sizeof *z, sizeof(float));
	if (!z)
		return lang_error(p, fl, "out of memory for the height field's %ld x %ld points", W, H);
	for (long j = 0; j < H; j++)
		for (long i = 0; i < W; i++) {
			double a[3] = {(double)i / (double)(W - 1), (double)j / (double)(H - 1), 0}, r[5] = {0};
			const lang_function *failed = NULL;
			if (!lang_fn_eval(f, a, r, &failed))
				return lang_fn_report(p, fl, failed);
			double g = f->n_out == 1 ? hf_channel(r[0])
						 : 0.297 * hf_channel(r[0]) + 0.589 * hf_channel(r[1]) + 0.114 * hf_channel(r[2]);
			/* circe's field reads an image's grey as floor(g * 65535) / 65536 (build_shapes.c) */
			z[(size_t)(H - 1 - j) * (size_t)W + (size_t)i] = (float)(floor(g * 65535.0 + 1e-6) / 65536.0);
		}
	h->heights = z, h->fn_w = (uint32_t)W, h->fn_h = (uint32_t)H;
	return true;
}

/* height_field = "height_field" "{" ( [ "png" | "exr" | "jpeg" | "hdr" ] string | "function" float [","] float
 *                "{" function body "}" ) { "smooth" | "water_level" float } { modifier } "}"
 * (POV-Ray's other image types are not supported) */
static bool height_field(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	scene_geom *g;
	TRY(g = lang_new_geom(p, SHAPE_HEIGHT_FIELD, kw));
	scene_height_field *h = &g->u.height_field;
	lang_tok k = lang_peek(p)->kind;
	if (k == LTK_KW_PNG || k == LTK_KW_EXR || k == LTK_KW_JPEG || lang_word_is(lang_peek(p), "hdr"))
		lang_advance(p);
	h->path_loc = lang_peek(p)->loc;
	if (k == LTK_KW_FUNCTION)
		TRY(hf_function(p, h, *lang_advance(p)));
	else
		TRY(lang_asset_path(p, "as the height field's image file", SCENE_ASSET_IMAGE, &h->path));
	for (;;) {
		diag_loc wl;
		if (lang_accept(p, LTK_KW_SMOOTH)) {
			h->smooth = true;
		} else if (lang_accept(p, LTK_KW_WATER_LEVEL)) {
			TRY(float_at(p, "after 'water_level'", &h->water_level, &wl));
		} else {
			break;
		}
	}
	return lang_place_object(p, out, g, kw, open, "height_field");
}

/* quadric = "quadric" "{" vector [","] vector [","] vector [","] float { modifier } "}" */
static bool quadric(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	scene_geom *g;
	TRY(g = lang_new_geom(p, SHAPE_QUADRIC, kw));
	scene_quadric *q = &g->u.quadric;
	TRY(lang_vec3(p, "as the quadric's square terms <A, B, C>", &q->square));
	lang_accept(p, LTK_COMMA);
	TRY(lang_vec3(p, "as the quadric's mixed terms <D, E, F>", &q->mixed));
	lang_accept(p, LTK_COMMA);
	TRY(lang_vec3(p, "as the quadric's linear terms <G, H, I>", &q->linear));
	lang_accept(p, LTK_COMMA);
	TRY(lang_float(p, "as the quadric's constant J", &q->constant));
	return lang_place_object(p, out, g, kw, open, "quadric");
}

/* The coefficient list of a polynomial surface: '<' float { [","] float } '>', exactly `n` of them
 * (POV-Ray's Parse_Coeffs). '>' ends it: comparisons need parentheses there, as in a vector. */
static bool poly_coeffs(parser *p, const char *what, double *c, uint32_t n)
{
	char ctx[64];
	snprintf(ctx, sizeof ctx, "to begin the %s's coefficients", what);
	TRY(lang_expect(p, LTK_LT, ctx));
	bool saved = p->no_gt;
	p->no_gt = true;
	bool ok = true;
	for (uint32_t i = 0; ok && i < n; i++) {
		if (i)
			lang_accept(p, LTK_COMMA);
		if (lang_peek(p)->kind == LTK_GT)
			ok = lang_error(p, lang_peek(p)->loc, "the %s needs %u coefficients, found %u", what, n, i);
		else
			ok = lang_float(p, "as a coefficient", &c[i]);
	}
	p->no_gt = saved;
	TRY(ok);
	snprintf(ctx, sizeof ctx, "after the %s's %u coefficients", what, n);
	return lang_expect(p, LTK_GT, ctx);
}

/* poly = ( "poly" "{" int [","] | "cubic" "{" | "quartic" "{" ) coefficients { modifier } "}" */
static bool poly_common(parser *p, vecbuf *out, diag_loc kw, diag_loc open, int order, const char *what)
{
	scene_geom *g;
	TRY(g = lang_new_geom(p, SHAPE_POLY, kw));
	if (!order) {
		diag_loc ol;
		double o;
		TRY(float_at(p, "as the poly's order", &o, &ol));
		if (!(o >= 2 && o <= POLY_MAX_ORDER))
			return lang_error(p, ol, "poly order must be 2 to %d, found %g", POLY_MAX_ORDER, o);
		order = (int)o;
		lang_accept(p, LTK_COMMA);
	}
	scene_poly *s = &g->u.poly;
	s->order = order;
	s->keyword = what;
	s->n = (uint32_t)((order + 1) * (order + 2) * (order + 3) / 6);
	if (!(s->coeffs = arena_zalloc(&p->sc->arena, s->n, sizeof *s->coeffs)))
		return lang_error(p, kw, "out of memory");
	TRY(poly_coeffs(p, what, s->coeffs, s->n));
	return lang_place_object(p, out, g, kw, open, what);
}

static bool poly(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	return poly_common(p, out, kw, open, 0, "poly");
}

static bool cubic(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	return poly_common(p, out, kw, open, 3, "cubic");
}

static bool quartic(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	return poly_common(p, out, kw, open, 4, "quartic");
}

lang_shape_fn lang_shape_parser(lang_tok k)
{
	switch (k) {
	case LTK_KW_CYLINDER: return cylinder;
	case LTK_KW_CONE: return cone;
	case LTK_KW_TORUS: return torus;
	case LTK_KW_DISC: return disc;
	case LTK_KW_POLYGON: return polygon;
	case LTK_KW_SUPERELLIPSOID: return superellipsoid;
	case LTK_KW_HEIGHT_FIELD: return height_field;
	case LTK_KW_QUADRIC: return quadric;
	case LTK_KW_POLY: return poly;
	case LTK_KW_CUBIC: return cubic;
	case LTK_KW_QUARTIC: return quartic;
	default: return NULL;
	}
}
