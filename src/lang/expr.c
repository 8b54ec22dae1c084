/* expr.c - expressions, evaluated at parse time as POV-Ray 3.7 does (its parser_expressions.cpp
 * and parser_strings.cpp, read to learn the semantics): floats, vectors of 2 to LANG_MAX_VECTOR
 * components, colours (5-vectors: red, green, blue, filter, transmit), strings, arrays, and the
 * built-in functions that need no geometry. Operands of different sizes are promoted as POV-Ray's
 * Promote_Express does: a float is copied into every component, a shorter vector is padded with
 * zeros. The first error is reported and ends the parse. */
#include "lang/func.h"
#include "lang/parser.h"

#include "base/rng.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

static const double PI = 3.14159265358979323846;

static bool expr_cond(parser *p, value *out);
static bool expr_additive(parser *p, value *out);
static bool primary(parser *p, value *out);

/* POV-Ray's truth of a float (ftrue in express.cpp): |x| > EPSILON, 1e-10 (configbackend.h). */
static const double TRUTH_EPSILON = 1e-10;
static bool truth(double x) { return fabs(x) > TRUTH_EPSILON; }

static bool no_memory(parser *p, diag_loc loc) { return lang_error(p, loc, "out of memory"); }

/* ---- values ------------------------------------------------------------------------------ */

const char *lang_value_kind_name(const value *v)
{
	static const char *const vectors[] = {"a vector", "a 1-vector", "a 2-vector", "a vector", "a 4-vector",
					      "a 5-vector"};
	switch (v->kind) {
	case VAL_FLOAT: return "a float";
	case VAL_VECTOR: return v->n >= 0 && v->n <= 5 ? vectors[v->n] : "a vector of another size";
	case VAL_COLOR: return "a colour";
	case VAL_STRING: return "a string";
	case VAL_MATERIAL: return "a material";
	case VAL_OBJECT: return "an object";
	case VAL_MACRO: return "a macro";
	case VAL_ARRAY: return "an array";
	case VAL_PIGMENT: return "a pigment";
	case VAL_FINISH: return "a finish";
	case VAL_INTERIOR: return "an interior";
	case VAL_MEDIA: return "a media";
	case VAL_CAMERA: return "a camera";
	case VAL_LIGHT: return "a light_source";
	case VAL_TRANSFORM: return "a transform";
	case VAL_FILE: return "a data file";
	case VAL_FUNCTION: return "a function";
	case VAL_SPLINE: return "a spline";
	case VAL_COLOR_MAP: return "a color_map";
	case VAL_NORMAL: return "a normal";
	case VAL_SKY: return "a sky_sphere";
	}
	return "a value";
}

static void clear(value *v)
{
	memset(v, 0, sizeof *v);
}

static void set_float(value *v, double x)
{
	clear(v);
	v->kind = VAL_FLOAT;
	v->n = 1;
	v->v[0] = x;
}

static bool set_string(parser *p, diag_loc loc, value *v, const char *s, size_t len)
{
	clear(v);
	v->kind = VAL_STRING;
	v->str = arena_strndup(&p->sc->arena, s, len);
	return v->str || no_memory(p, loc);
}

static bool finite_result(parser *p, diag_loc loc, const value *v, const char *op)
{
	for (int i = 0; i < v->n; i++)
		if (!isfinite(v->v[i]))
			return lang_error(p, loc, "%s produces %s", op, isnan(v->v[i]) ? "NaN (not a number)" : "an infinity");
	return true;
}

static bool is_numeric(const value *v) { return v->kind == VAL_FLOAT || v->kind == VAL_VECTOR || v->kind == VAL_COLOR; }

/* POV-Ray's Promote_Express: to n components, a float copied, a vector padded with zeros. */
static void promote(value *v, int n)
{
	if (v->n >= n)
		return;
	for (int i = v->n; i < n; i++)
		v->v[i] = v->n == 1 ? v->v[0] : 0.0;
	v->n = n;
}

/* Brings a and b to the same size for a component-wise operation; the result is a colour when
 * either is one, else a vector when either is one. */
static bool unify(parser *p, diag_loc loc, value *a, value *b, const char *op)
{
	if (!is_numeric(a) || !is_numeric(b))
		return lang_error(p, loc, "cannot apply '%s' to %s and %s", op, lang_value_kind_name(a), lang_value_kind_name(b));
	int n = a->n > b->n ? a->n : b->n;
	value_kind k = a->kind == VAL_COLOR || b->kind == VAL_COLOR    ? VAL_COLOR
		       : a->kind == VAL_VECTOR || b->kind == VAL_VECTOR ? VAL_VECTOR
									 : VAL_FLOAT;
	if (k == VAL_COLOR && n > LANG_COLOR_TERMS)
		return lang_error(p, loc, "cannot apply '%s' to a colour and a vector of %d components", op, n);
	promote(a, n);
	promote(b, n);
	a->kind = k;
	return true;
}

static bool need_float(parser *p, diag_loc loc, const value *v, const char *what)
{
	if (v->kind == VAL_FLOAT)
		return true;
	return lang_error(p, loc, "%s needs a float, found %s", what, lang_value_kind_name(v));
}

/* Whether a token can begin an operand (a number, a name, '(', '<', a sign, '!', a string):
 * what may follow a vector component without its comma. */
static bool starts_operand(lang_tok k)
{
	return k == LTK_NUMBER || k == LTK_IDENT || k == LTK_LPAREN || k == LTK_LT || k == LTK_MINUS ||
	       k == LTK_PLUS || k == LTK_BANG || k == LTK_STRING || (k >= LANG_FIRST_KEYWORD && k < LANG_FIRST_DIRECTIVE);
}

/* vector = "<" expression { [ "," ] expression } ">"   (a '>' here closes the vector; the commas
 * are optional, as POV-Ray's Parse_Comma makes them: woods.inc writes `< -1 0 0 >`) */
static bool vector_literal(parser *p, value *out)
{
	diag_loc open = p->prev.loc;
	bool saved = p->no_gt;
	p->no_gt = true;
	clear(out);
	out->kind = VAL_VECTOR;
	for (;;) {
		value c;
		if (!expr_cond(p, &c))
			return false;
		if (!need_float(p, p->prev.loc, &c, "a vector component"))
			return false;
		if (out->n >= LANG_MAX_VECTOR)
			return lang_error(p, open, "vector has too many components (limit is %d)", LANG_MAX_VECTOR);
		out->v[out->n++] = c.v[0];
		/* a comma before the '>' is allowed, as POV-Ray's (animations/float4: rgb<0.2,0.1,0.5,>) */
		if (lang_accept(p, LTK_COMMA) && lang_peek(p)->kind != LTK_GT)
			continue;
		lang_tok k = lang_peek(p)->kind;
		if (k == LTK_GT)
			break;
		if (starts_operand(lang_peek(p)->kind))
			continue;
		p->no_gt = saved;
		return lang_error_found(p, "expected ',' or '>' in the vector opened at line %u, column %u", open.line, open.col);
	}
	lang_advance(p);
	p->no_gt = saved;
	return true;
}

/* ---- colours ----------------------------------------------------------------------------- */

/* The words that set a colour from one operand: how many components it takes (the 4th is filter,
 * or transmit for rgbt) and whether red, green and blue are sRGB-encoded (POV-Ray 3.7's
 * Parse_Colour). */
typedef struct colour_form {
	lang_tok tok;
	int terms;
	bool fourth_is_transmit;
	bool srgb;
} colour_form;

static const colour_form colour_forms[] = {
	{LTK_KW_RGB, 3, false, false},  {LTK_KW_RGBF, 4, false, false},  {LTK_KW_RGBT, 4, true, false},
	{LTK_KW_RGBFT, 5, false, false}, {LTK_KW_SRGB, 3, false, true},  {LTK_KW_SRGBF, 4, false, true},
	{LTK_KW_SRGBT, 4, true, true},   {LTK_KW_SRGBFT, 5, false, true},
};

static const colour_form *colour_form_of(lang_tok k)
{
	for (size_t i = 0; i < sizeof colour_forms / sizeof colour_forms[0]; i++)
		if (colour_forms[i].tok == k)
			return &colour_forms[i];
	return NULL;
}

/* The component a colour keyword sets (red 0 ... transmit 4), or -1. */
static int colour_component_of(lang_tok k)
{
	switch (k) {
	case LTK_KW_RED: return 0;
	case LTK_KW_GREEN: return 1;
	case LTK_KW_BLUE: return 2;
	case LTK_KW_FILTER: return 3;
	case LTK_KW_TRANSMIT: return 4;
	default: return -1;
	}
}

bool lang_colour_word(lang_tok k)
{
	return k == LTK_KW_COLOR || k == LTK_KW_COLOUR || colour_form_of(k) || colour_component_of(k) >= 0;
}

/* sRGB to linear (IEC 61966-2-1's decoding curve). */
static double srgb_decode(double c) { return c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4); }

static void set_colour(value *c)
{
	promote(c, LANG_COLOR_TERMS);
	c->kind = VAL_COLOR;
}

/* The operand of rgb, rgbf, ...: a float sets every component the word takes, a vector must have
 * exactly that many, a colour is taken whole. */
static bool colour_operand(parser *p, const colour_form *f, const lang_token *kw, value *c)
{
	diag_loc at = lang_peek(p)->loc;
	value o;
	if (!expr_additive(p, &o))
		return false;
	if (o.kind == VAL_COLOR) {
		*c = o;
	} else if (o.kind == VAL_FLOAT || (o.kind == VAL_VECTOR && o.n == f->terms)) {
		promote(&o, f->terms);
		for (int i = 0; i < 3; i++)
			c->v[i] = o.v[i];
		if (f->terms >= 4)
			c->v[f->fourth_is_transmit ? 4 : 3] = o.v[3];
		if (f->terms == 5)
			c->v[4] = o.v[4];
	} else {
		return lang_error(p, at, "'%.*s' needs a float or a %d-vector, found %s", (int)kw->len, kw->text, f->terms,
				  lang_value_kind_name(&o));
	}
	if (f->srgb) { /* POV-Ray 3.7 decodes sRGB into its working space (express.cpp Parse_Express's
			* workingGammaToSRGB): linear^(1/G), which the written image's r^G makes light again */
		double g = scene_working_gamma(&p->sc->global, p->version);
		for (int i = 0; i < 3; i++) {
			double l = srgb_decode(c->v[i]);
			c->v[i] = g == 1.0 || l == 0.0 ? l : l > 0.0 ? pow(l, 1.0 / g) : -pow(-l, 1.0 / g);
		}
	}
	return finite_result(p, kw->loc, c, "the colour");
}

/* A colour from the operand of a bare color/colour: a float is a grey (POV-Ray would copy it
 * into filter and transmit as well, with a warning; circe keeps the grey), a vector of 3 to 5
 * components is red, green, blue [, filter [, transmit]], a colour is itself. False when o is
 * none of them. */
static bool colour_from(const value *o, value *c)
{
	if (o->kind == VAL_FLOAT) {
		c->v[0] = c->v[1] = c->v[2] = o->v[0];
		return true;
	}
	if (o->kind == VAL_COLOR || (o->kind == VAL_VECTOR && o->n >= 3 && o->n <= LANG_COLOR_TERMS)) {
		for (int i = 0; i < o->n; i++)
			c->v[i] = o->v[i];
		return true;
	}
	return false;
}

/* The items of a colour after its start: started, an rgb-like word ends it; bare, an operand may
 * start it (after "color"). */
static bool colour_items(parser *p, value *c, bool bare, bool started)
{
	for (;;) {
		lang_token t = *lang_peek(p);
		const colour_form *f = colour_form_of(t.kind);
		int comp = colour_component_of(t.kind);
		diag_loc at = t.loc;
		value o;
		if (f && !started) {
			lang_advance(p);
			if (!colour_operand(p, f, &t, c))
				return false;
		} else if (comp >= 0) {
			lang_advance(p);
			at = lang_peek(p)->loc;
			if (!expr_additive(p, &o))
				return false;
			if (o.kind != VAL_FLOAT)
				return lang_error(p, at, "'%.*s' needs a float, found %s", (int)t.len, t.text, lang_value_kind_name(&o));
			c->v[comp] = o.v[0];
		} else if (bare && !started) {
			if (!expr_additive(p, &o))
				return false;
			if (!colour_from(&o, c))
				return lang_error(p, at, "a colour needs a float, a vector of 3 to 5 components or a colour, found %s",
						  lang_value_kind_name(&o));
		} else {
			return true;
		}
		started = true;
	}
}

/* colour = [ "color" | "colour" ] colour_item { colour_item }
 * colour_item = ( "rgb" | "rgbf" | "rgbt" | "rgbft" | "srgb" | "srgbf" | "srgbt" | "srgbft" ) additive
 *             | ( "red" | "green" | "blue" | "filter" | "transmit" ) additive
 *             | additive   (only first, after "color")
 * As POV-Ray 3.7's Parse_Colour: one rgb-like word or operand, then components set by name; a
 * second rgb-like word ends the colour. */
static bool colour_value(parser *p, value *out)
{
	lang_token first = *lang_peek(p);
	if (!lang_enter(p, first.loc)) /* rgb rgb rgb ... recurses */
		return false;
	value c;
	clear(&c);
	set_colour(&c);
	bool keyword = first.kind == LTK_KW_COLOR || first.kind == LTK_KW_COLOUR;
	if (keyword)
		lang_advance(p);
	bool ok = colour_items(p, &c, keyword, false);
	lang_leave(p);
	if (!ok)
		return false;
	*out = c;
	return true;
}

/* ---- members ----------------------------------------------------------------------------- */

/* POV-Ray 3.7's members (Parse_Num_Factor's period operator); gray is its Greyscale(). */
static const struct {
	const char *name;
	int index; /* -1: gray */
} members[] = {
	{"x", 0},   {"y", 1},     {"z", 2},     {"t", 3},      {"u", 0},        {"v", 1},
	{"red", 0}, {"green", 1}, {"blue", 2},  {"filter", 3}, {"transmit", 4}, {"gray", -1},
};

/* POV-Ray's grey of a colour (kRedIntensity, kGreenIntensity, kBlueIntensity in base/colour.h). */
static const double GRAY_RED = 0.297, GRAY_GREEN = 0.589, GRAY_BLUE = 0.114;

static bool is_word(const lang_token *t)
{
	return t->kind == LTK_IDENT || t->kind == LTK_UNSUPPORTED || (t->kind >= LANG_FIRST_KEYWORD && t->kind < LANG_FIRST_DIRECTIVE);
}

/* member = "." ( "x" | "y" | "z" | "t" | "u" | "v" | "red" | "green" | "blue" | "filter" | "transmit" | "gray" ) */
bool lang_member(parser *p, value *v)
{
	lang_advance(p);
	if (!is_word(lang_peek(p)))
		return lang_error_found(p, "expected a member name after '.'");
	lang_token name = *lang_advance(p);
	int index = -2;
	for (size_t i = 0; i < sizeof members / sizeof members[0]; i++)
		if (strlen(members[i].name) == name.len && !memcmp(members[i].name, name.text, name.len))
			index = members[i].index;
	if (index == -2)
		return lang_error(p, name.loc,
				  "'.%.*s' is not a member POV-Ray 3.7 knows (they are x, y, z, t, u, v, red, green, blue, "
				  "filter, transmit and gray)",
				  (int)name.len, name.text);
	if (!is_numeric(v))
		return lang_error(p, name.loc, "'.%.*s' of %s: members belong to vectors and colours", (int)name.len,
				  name.text, lang_value_kind_name(v));
	if (index == -1) {
		if (v->n < 3)
			return lang_error(p, name.loc, "'.gray' needs a colour or a vector of 3 or more components, found %s",
					  lang_value_kind_name(v));
		set_float(v, GRAY_RED * v->v[0] + GRAY_GREEN * v->v[1] + GRAY_BLUE * v->v[2]);
		return true;
	}
	if (index >= v->n)
		return lang_error(p, name.loc, "'.%.*s' of %s: it has %d component%s", (int)name.len, name.text,
				  lang_value_kind_name(v), v->n, v->n == 1 ? "" : "s");
	set_float(v, v->v[index]);
	return true;
}

/* ---- arrays ------------------------------------------------------------------------------ */

/* Elements of one array at most: 2^24 values of ~170 bytes is some 3 GB, beyond what a scene
 * needs (POV-Ray's own limit is its memory). */
enum { MAX_ARRAY_ELEMENTS = 1 << 24 };

static lang_array *new_array(parser *p, diag_loc loc, int dims, const long *size, bool mixed)
{
	size_t count = 1;
	for (int i = 0; i < dims; i++)
		count *= (size_t)size[i];
	lang_array *a = arena_zalloc(&p->sc->arena, 1, sizeof *a);
	value *elems = a ? arena_zalloc(&p->sc->arena, count, sizeof *elems) : NULL;
	bool *set = elems ? arena_zalloc(&p->sc->arena, count, sizeof *set) : NULL;
	if (!set) {
		no_memory(p, loc);
		return NULL;
	}
	a->dims = dims;
	memcpy(a->size, size, (size_t)dims * sizeof *size);
	a->count = count;
	a->mixed = mixed;
	a->kind = -1;
	a->elems = elems;
	a->set = set;
	return a;
}

bool lang_array_copy(parser *p, diag_loc loc, value *v)
{
	const lang_array *a = v->arr;
	lang_array *b = new_array(p, loc, a->dims, a->size, a->mixed);
	if (!b)
		return false;
	memcpy(b->elems, a->elems, a->count * sizeof *a->elems);
	memcpy(b->set, a->set, a->count * sizeof *a->set);
	b->kind = a->kind;
	for (size_t i = 0; i < b->count; i++)
		if (b->set[i] && b->elems[i].kind == VAL_ARRAY && !lang_array_copy(p, loc, &b->elems[i]))
			return false;
	v->arr = b;
	return true;
}

/* A non-mixed array holds one kind of value: that of the first element assigned. */
bool lang_array_store(parser *p, diag_loc loc, lang_array *a, size_t i, const value *v)
{
	if (!a->mixed && a->kind >= 0 && a->kind != (int)v->kind) {
		value held = {.kind = (value_kind)a->kind, .n = 1};
		return lang_error(p, loc, "this array holds %s, not %s (declare it 'array mixed' to hold both)",
				  lang_value_kind_name(&held), lang_value_kind_name(v));
	}
	a->kind = (int)v->kind;
	a->elems[i] = *v;
	a->set[i] = true;
	return true;
}

/* One element's index into a: "[" int "]" for each of its dimensions. */
static bool index_of(parser *p, const lang_array *a, const char *name, size_t *index)
{
	size_t at = 0;
	for (int d = 0; d < a->dims; d++) {
		if (!lang_expect(p, LTK_LBRACKET, d ? "for the array's next index" : "after the array's name"))
			return false;
		diag_loc loc = lang_peek(p)->loc;
		double x;
		if (!lang_float(p, "as an array index", &x) || !lang_expect(p, LTK_RBRACKET, "to close the array index"))
			return false;
		double k = trunc(x); /* POV-Ray truncates a subscript (Parse_Array_Subscript's (int)) */
		if (!(k >= 0 && k < (double)a->size[d]))
			return lang_error(p, loc, "array index %g out of range 0..%ld%s%s%s", x, a->size[d] - 1,
					  name ? " of '" : "", name ? name : "", name ? "'" : "");
		at = at * (size_t)a->size[d] + (size_t)k;
	}
	*index = at;
	return true;
}

/* An element whose value is an array is indexed on (A[i][j] of an array of arrays, as POV-Ray
 * 3.7 allows): *a becomes the innermost array. */
bool lang_array_index(parser *p, lang_array **a, const char *name, size_t *index)
{
	for (;;) {
		if (!index_of(p, *a, name, index))
			return false;
		if (lang_raw_next(p) != LTK_LBRACKET) /* raw: #debug A[i] has no terminator to read up to */
			return true;
		const lang_array *in = *a;
		if (!in->set[*index] || in->elems[*index].kind != VAL_ARRAY)
			return lang_error(p, lang_peek(p)->loc, "'%s' has %d dimension%s%s", name ? name : "the array",
					  in->dims, in->dims == 1 ? "" : "s",
					  in->set[*index] ? " and this element is not an array" : "");
		*a = in->elems[*index].arr;
	}
}

/* item = block_value | array | additive: as POV-Ray's Parse_Initalizer reads an item (its
 * Parse_RValue), a block (texture { }, an object, ...) or an expression without a comparison at its
 * top, so that `<1, 2> <3, 4>` is two items. */
static bool array_item(parser *p, value *v)
{
	bool handled;
	if (!lang_declare_block(p, v, &handled))
		return false;
	if (handled)
		return true;
	bool saved = p->no_gt;
	p->no_gt = false;
	bool ok = expr_additive(p, v);
	p->no_gt = saved;
	return ok;
}

/* items = "{" ( item | items ) { [ "," ] ( item | items ) } [ "," ] "}": one level of braces a
 * dimension, each level exactly as long as its dimension; the commas are optional (Parse_Comma). */
static bool array_items(parser *p, lang_array *a, int d, size_t base)
{
	diag_loc open = lang_peek(p)->loc;
	if (!lang_expect(p, LTK_LBRACE, d ? "for the next dimension's items" : "for the array's items"))
		return false;
	size_t stride = 1;
	for (int k = d + 1; k < a->dims; k++)
		stride *= (size_t)a->size[k];
	for (long i = 0;; i++) {
		if (lang_peek(p)->kind == LTK_RBRACE && i == a->size[d])
			break;
		if (i == a->size[d])
			return lang_error_found(p, "expected '}' after %ld items (the dimension's size)", a->size[d]);
		if (lang_peek(p)->kind == LTK_RBRACE)
			return lang_error(p, lang_peek(p)->loc, "%ld item%s where the dimension has %ld", i, i == 1 ? "" : "s",
					  a->size[d]);
		if (i > 0)
			lang_accept(p, LTK_COMMA); /* optional, as POV-Ray's Parse_Comma makes it (lemon.inc) */
		if (d + 1 < a->dims) {
			if (!array_items(p, a, d + 1, base + (size_t)i * stride))
				return false;
			continue;
		}
		diag_loc at = lang_peek(p)->loc;
		bool fresh = lang_peek(p)->kind == LTK_KW_ARRAY;
		value v;
		if (!array_item(p, &v))
			return false;
		/* an array named as an item is copied, as #declare copies it */
		if (v.kind == VAL_ARRAY && !fresh && !lang_array_copy(p, at, &v))
			return false;
		if (!lang_array_store(p, at, a, base + (size_t)i, &v))
			return false;
		if (i + 1 == a->size[d])
			lang_accept(p, LTK_COMMA); /* a trailing comma, as POV-Ray allows */
	}
	return lang_expect_close(p, open, "array items");
}

bool lang_array_value(parser *p, value *out)
{
	lang_token kw = *lang_advance(p);
	bool mixed = lang_raw_next(p) == LTK_KW_MIXED && lang_advance(p);
	long size[LANG_MAX_ARRAY_DIMS];
	int dims = 0;
	size_t count = 1;
	while (lang_raw_next(p) == LTK_LBRACKET) {
		if (dims == LANG_MAX_ARRAY_DIMS)
			return lang_error(p, lang_peek(p)->loc, "too many dimensions (limit is %d)", LANG_MAX_ARRAY_DIMS);
		lang_advance(p);
		if (!lang_int(p, "as an array size", 1, MAX_ARRAY_ELEMENTS, &size[dims]) ||
		    !lang_expect(p, LTK_RBRACKET, "after the array size"))
			return false;
		count *= (size_t)size[dims++];
		if (count > MAX_ARRAY_ELEMENTS)
			return lang_error(p, kw.loc, "array too large (limit is %d elements)", MAX_ARRAY_ELEMENTS);
	}
	if (dims == 0)
		return lang_error_found(p, "expected '[' and the size after 'array'");
	lang_array *a = new_array(p, kw.loc, dims, size, mixed);
	if (!a)
		return false;
	if (lang_raw_next(p) == LTK_LBRACE && !array_items(p, a, 0, 0))
		return false;
	clear(out);
	out->kind = VAL_ARRAY;
	out->arr = a;
	return true;
}

/* An element of the array named by the identifier just read: set, or an error. */
static bool element(parser *p, const lang_token *name, const value *arr, value *out)
{
	char nm[LANG_MAX_IDENT + 1];
	snprintf(nm, sizeof nm, "%.*s", (int)name->len, name->text);
	diag_loc at = lang_peek(p)->loc;
	size_t i;
	lang_array *a = arr->arr;
	if (!lang_array_index(p, &a, nm, &i))
		return false;
	if (!a->set[i])
		return lang_error(p, at, "element of '%s' read before it was assigned", nm);
	*out = a->elems[i];
	return true;
}

/* defined = "defined" "(" identifier [ index ] ")": 1 when declared (an element: assigned). */
static bool defined(parser *p, value *out)
{
	lang_advance(p);
	if (!lang_expect(p, LTK_LPAREN, "after 'defined'"))
		return false;
	p->no_expand = true;
	lang_token *t = lang_peek(p);
	p->no_expand = false;
	bool is = false;
	if (is_word(t) && t->kind != LTK_IDENT) {
		lang_advance(p); /* a keyword is never declared */
	} else if (t->kind == LTK_IDENT) {
		lang_token name = *lang_advance(p);
		const symbol *s = lang_lookup(p, name.text, name.len);
		is = s != NULL;
		if (s && s->val.kind == VAL_ARRAY && lang_peek(p)->kind == LTK_LBRACKET) {
			size_t i;
			char nm[LANG_MAX_IDENT + 1];
			snprintf(nm, sizeof nm, "%.*s", (int)name.len, name.text);
			lang_array *a = s->val.arr;
			if (!lang_array_index(p, &a, nm, &i))
				return false;
			is = a->set[i];
		} else {
			while (lang_accept(p, LTK_LBRACKET)) { /* an element of no array: not defined */
				double x;
				if (!lang_float(p, "as an array index", &x) || !lang_expect(p, LTK_RBRACKET, "to close the array index"))
					return false;
				is = false;
			}
		}
	} else {
		return lang_error_found(p, "expected an identifier after 'defined ('");
	}
	set_float(out, is);
	return lang_expect(p, LTK_RPAREN, "to close 'defined ('");
}

/* ---- built-in functions ------------------------------------------------------------------ */

/* The arguments of one call, read and checked against the function's parameter types. */
typedef struct args {
	lang_token name;
	char fname[32];
	int n;
	value v[LANG_MAX_VECTOR];
	diag_loc at[LANG_MAX_VECTOR];
} args;

typedef bool (*builtin_fn)(parser *p, const args *a, value *out);

/* types: one letter a parameter: f float, v 3-vector (a float or 2-vector promoted, as POV-Ray's
 * Parse_Vector), n float or vector of any size, s string, a array; those after '|' are optional;
 * a trailing '*' repeats the last letter without limit. */
typedef struct builtin {
	lang_tok tok;
	const char *types;
	builtin_fn fn;
} builtin;

static double arg_f(const args *a, int i) { return a->v[i].v[0]; }

static dvec3 arg_v(const args *a, int i) { return d3(a->v[i].v[0], a->v[i].v[1], a->v[i].v[2]); }

static void set_vec3(value *out, dvec3 r)
{
	clear(out);
	out->kind = VAL_VECTOR;
	out->n = 3;
	out->v[0] = r.x, out->v[1] = r.y, out->v[2] = r.z;
}

static bool domain_error(parser *p, const args *a, const char *range)
{
	return lang_error(p, a->at[0], "'%s' of %g: the argument must be %s", a->fname, arg_f(a, 0), range);
}

/* The functions of one float: the domain checked, then computed as a function body computes it. */
static bool fn_float1(parser *p, const args *a, value *out)
{
	double x = arg_f(a, 0);
	switch (a->name.kind) {
	case LTK_KW_ASIN:
	case LTK_KW_ACOS:
		if (x < -1 || x > 1)
			return lang_error(p, a->at[0], "'%s' of %g is outside [-1, 1]", a->fname, x);
		break;
	case LTK_KW_ACOSH:
		if (!(x >= 1))
			return domain_error(p, a, "1 or more");
		break;
	case LTK_KW_ATANH:
		if (!(x > -1 && x < 1))
			return domain_error(p, a, "inside (-1, 1)");
		break;
	case LTK_KW_SQRT:
		if (x < 0)
			return lang_error(p, a->at[0], "'sqrt' of a negative number (%g)", x);
		break;
	case LTK_KW_LOG: /* POV-Ray's log is base 10; ln is the natural one */
	case LTK_KW_LN:
		if (!(x > 0))
			return domain_error(p, a, "positive");
		break;
	default: break;
	}
	set_float(out, lang_fn_float1(a->name.kind, x));
	return true;
}

/* The functions of two floats. */
static bool fn_float2(parser *p, const args *a, value *out)
{
	double x = arg_f(a, 0), y = arg_f(a, 1);
	if ((a->name.kind == LTK_KW_MOD || a->name.kind == LTK_KW_DIV) && y == 0)
		return lang_error(p, a->at[1], "'%s' by zero", a->fname);
	set_float(out, lang_fn_float2(a->name.kind, x, y));
	return true;
}

static bool fn_min_max(parser *p, const args *a, value *out)
{
	(void)p;
	double r = arg_f(a, 0);
	for (int i = 1; i < a->n; i++)
		r = a->name.kind == LTK_KW_MIN ? fmin(r, arg_f(a, i)) : fmax(r, arg_f(a, i));
	set_float(out, r);
	return true;
}

/* select(A, B, C): B when A < 0, else C; select(A, B, C, D): B, C or D as A is < 0, 0 or > 0. */
static bool fn_select(parser *p, const args *a, value *out)
{
	(void)p;
	double x = arg_f(a, 0);
	if (a->n == 3)
		set_float(out, x < 0 ? arg_f(a, 1) : arg_f(a, 2));
	else
		set_float(out, x < 0 ? arg_f(a, 1) : x == 0 ? arg_f(a, 2) : arg_f(a, 3));
	return true;
}

/* bitwise_and/or/xor of integers, as POV-Ray 3.7 (each operand truncated to an int). */
static bool fn_bitwise(parser *p, const args *a, value *out)
{
	long long r = 0;
	for (int i = 0; i < a->n; i++) {
		double x = trunc(arg_f(a, i));
		if (x < -2147483648.0 || x > 2147483647.0)
			return lang_error(p, a->at[i], "'%s' needs integers of 32 bits, found %g", a->fname, arg_f(a, i));
		long long k = (long long)x;
		if (i == 0)
			r = k;
		else
			r = a->name.kind == LTK_KW_BITWISE_AND ? (r & k) : a->name.kind == LTK_KW_BITWISE_OR ? (r | k) : (r ^ k);
	}
	set_float(out, (double)(int)r);
	return true;
}

/* seed(N) makes a stream of random numbers and gives its number; rand(S) draws the next number of
 * stream S, in [0, 1). As POV-Ray, each seed() call is a stream of its own and the same N gives the
 * same numbers; the numbers are PCG32's, not POV-Ray's generator's. */
static bool fn_seed(parser *p, const args *a, value *out)
{
	rng g;
	rng_seed(&g, (uint64_t)(int64_t)trunc(fmax(fmin(arg_f(a, 0), 9.2e18), -9.2e18)), 0);
	if (!vecbuf_push(&p->rand_streams, &g))
		return no_memory(p, a->name.loc);
	set_float(out, (double)(p->rand_streams.len - 1));
	return true;
}

static bool fn_rand(parser *p, const args *a, value *out)
{
	double s = arg_f(a, 0);
	if (!(s >= 0 && s < (double)p->rand_streams.len && s == floor(s)))
		return lang_error(p, a->at[0], "'rand' needs a stream made by 'seed', found %g", s);
	set_float(out, rng_double(&VECBUF_AT(&p->rand_streams, rng, (size_t)s)));
	return true;
}

static bool fn_vector(parser *p, const args *a, value *out)
{
	dvec3 u = arg_v(a, 0);
	switch (a->name.kind) {
	case LTK_KW_VLENGTH: set_float(out, d3_length(u)); return true;
	case LTK_KW_VDOT: set_float(out, d3_dot(u, arg_v(a, 1))); return true;
	case LTK_KW_VCROSS: set_vec3(out, d3_cross(u, arg_v(a, 1))); return true;
	case LTK_KW_VROTATE: {
		xform r = xform_rotate(arg_v(a, 1));
		set_vec3(out, xform_vector(&r, u));
		return true;
	}
	case LTK_KW_VNORMALIZE:
	case LTK_KW_VAXIS_ROTATE: {
		dvec3 axis = a->name.kind == LTK_KW_VNORMALIZE ? u : arg_v(a, 1);
		double len = d3_length(axis);
		if (!(len > 0))
			return lang_error(p, a->at[a->name.kind == LTK_KW_VNORMALIZE ? 0 : 1], "'%s' of a zero-length vector",
					  a->fname);
		dvec3 k = d3_scale(axis, 1.0 / len);
		if (a->name.kind == LTK_KW_VNORMALIZE) {
			set_vec3(out, k);
			return true;
		}
		/* Rodrigues' rotation about k, in the sense of POV-Ray's rotate (vrotate, xform_rotate_axis):
		 * u cos + (k x u) sin + k (k.u)(1 - cos). */
		double th = arg_f(a, 2) * PI / 180.0, c = cos(th), s = sin(th);
		dvec3 r = d3_add(d3_add(d3_scale(u, c), d3_scale(d3_cross(k, u), s)), d3_scale(k, d3_dot(k, u) * (1 - c)));
		set_vec3(out, r);
		return true;
	}
	default: return true;
	}
}

/* ---- string functions ---- */

/* Strings built by the functions at most: POV-Ray's literal limit, so a loop of concat cannot
 * grow one without bound. */
enum { MAX_BUILT_STRING = 1 << 16 };

static bool fn_concat(parser *p, const args *a, value *out)
{
	size_t len = 0;
	for (int i = 0; i < a->n; i++)
		len += strlen(a->v[i].str);
	if (len > MAX_BUILT_STRING)
		return lang_error(p, a->name.loc, "'concat' makes a string of %zu bytes (limit is %d)", len, MAX_BUILT_STRING);
	char *s = arena_alloc(&p->sc->arena, len + 1, 1, 1);
	if (!s)
		return no_memory(p, a->name.loc);
	size_t k = 0;
	for (int i = 0; i < a->n; i++) {
		size_t n = strlen(a->v[i].str);
		memcpy(s + k, a->v[i].str, n);
		k += n;
	}
	s[k] = '\0';
	clear(out);
	out->kind = VAL_STRING;
	out->str = s;
	return true;
}

/* The printf format of str() and vstr(): width L (negative: padded with zeros), precision P
 * (negative: printf's default), as POV-Ray 3.7's Parse_Str. */
static bool number_format(parser *p, const args *a, int li, char *fmt, size_t size)
{
	double l = arg_f(a, li), d = arg_f(a, li + 1);
	if (fabs(l) > 100 || d > 100)
		return lang_error(p, a->at[fabs(l) > 100 ? li : li + 1], "'%s' width and precision must be at most 100", a->fname);
	int w = (int)l, pr = d < 0 ? -1 : (int)d; /* d may be any negative float */
	int k = snprintf(fmt, size, "%%");
	if (w > 0)
		k += snprintf(fmt + k, size - (size_t)k, "%d", w);
	else if (w < 0)
		k += snprintf(fmt + k, size - (size_t)k, "0%d", -w);
	if (pr >= 0)
		k += snprintf(fmt + k, size - (size_t)k, ".%d", pr);
	snprintf(fmt + k, size - (size_t)k, "f");
	return true;
}

static bool append_number(char *buf, size_t size, size_t *k, const char *fmt, double x)
{
	char num[400];
	int n = snprintf(num, sizeof num, fmt, x);
	if (n < 0 || (size_t)n >= sizeof num || *k + (size_t)n >= size)
		return false;
	memcpy(buf + *k, num, (size_t)n + 1);
	*k += (size_t)n;
	return true;
}

static bool fn_str(parser *p, const args *a, value *out)
{
	char fmt[32], buf[512];
	size_t k = 0;
	if (!number_format(p, a, 1, fmt, sizeof fmt))
		return false;
	if (!append_number(buf, sizeof buf, &k, fmt, arg_f(a, 0)))
		return lang_error(p, a->at[0], "'str' of %g is too long a string", arg_f(a, 0));
	return set_string(p, a->name.loc, out, buf, k);
}

/* vstr(N, V, S, L, P): N components of V (N clamped to 2..5), separated by S; those V lacks are 0
 * (a float too is not copied, as povray 3.7.0 prints it). */
static bool fn_vstr(parser *p, const args *a, value *out)
{
	char fmt[32], buf[4096];
	size_t k = 0;
	double nd = fmin(fmax(trunc(arg_f(a, 0)), 2), 5);
	int n = (int)nd;
	value v = a->v[1];
	for (int i = v.n; i < n; i++)
		v.v[i] = 0;
	if (!number_format(p, a, 3, fmt, sizeof fmt))
		return false;
	const char *sep = a->v[2].str;
	for (int i = 0; i < n; i++) {
		size_t sl = strlen(sep);
		if (i > 0 && k + sl < sizeof buf)
			memcpy(buf + k, sep, sl + 1), k += sl;
		if (!append_number(buf, sizeof buf, &k, fmt, v.v[i]))
			return lang_error(p, a->at[1], "'vstr' makes too long a string");
	}
	buf[k] = '\0';
	return set_string(p, a->name.loc, out, buf, k);
}

static bool fn_chr(parser *p, const args *a, value *out)
{
	double c = arg_f(a, 0);
	if (!(c >= 1 && c <= 127 && c == floor(c)))
		return lang_error(p, a->at[0], "'chr' needs a character code in 1..127 (circe's strings are ASCII), found %g", c);
	char s = (char)c;
	return set_string(p, a->name.loc, out, &s, 1);
}

static bool fn_substr(parser *p, const args *a, value *out)
{
	const char *s = a->v[0].str;
	double len = (double)strlen(s), from = trunc(arg_f(a, 1)), n = trunc(arg_f(a, 2));
	if (from < 1 || n < 0 || from + n - 1 > len)
		return lang_error(p, a->name.loc, "'substr' of a string of %g characters from %g for %g: out of range", len,
				  from, n);
	return set_string(p, a->name.loc, out, s + (size_t)from - 1, (size_t)n);
}

static bool fn_case(parser *p, const args *a, value *out)
{
	const char *s = a->v[0].str;
	size_t n = strlen(s);
	if (!set_string(p, a->name.loc, out, s, n))
		return false;
	char *w = (char *)out->str;
	for (size_t i = 0; i < n; i++)
		if (a->name.kind == LTK_KW_STRUPR && w[i] >= 'a' && w[i] <= 'z')
			w[i] = (char)(w[i] - 'a' + 'A');
		else if (a->name.kind == LTK_KW_STRLWR && w[i] >= 'A' && w[i] <= 'Z')
			w[i] = (char)(w[i] - 'A' + 'a');
	return true;
}

/* The floats of strings: asc, strlen, strcmp, val, file_exists. */
static bool fn_string_float(parser *p, const args *a, value *out)
{
	const char *s = a->v[0].str;
	switch (a->name.kind) {
	case LTK_KW_ASC: set_float(out, (unsigned char)s[0]); return true;
	case LTK_KW_STRLEN: set_float(out, (double)strlen(s)); return true;
	case LTK_KW_STRCMP: { /* as POV-Ray: the difference of the first characters that differ */
		const unsigned char *x = (const unsigned char *)s, *y = (const unsigned char *)a->v[1].str;
		while (*x && *x == *y)
			x++, y++;
		set_float(out, (double)*x - (double)*y);
		return true;
	}
	case LTK_KW_VAL: {
		char *end;
		double x = strtod(s, &end);
		if (end == s)
			return lang_error(p, a->at[0], "'val' of \"%s\": not a number", s);
		set_float(out, x);
		return true;
	}
	default: { /* file_exists: relative to the folder of the file that asks, as #include */
		const char *from = a->name.loc.src ? a->name.loc.src->name : "";
		const char *slash = strrchr(from, '/');
		char path[4096];
		if (s[0] == '/' || !slash)
			snprintf(path, sizeof path, "%s", s);
		else
			snprintf(path, sizeof path, "%.*s/%s", (int)(slash - from), from, s);
		set_float(out, access(path, R_OK) == 0);
		return true;
	}
	}
}

/* Seconds from 1970-01-01 to 2000-01-01: `now` and datetime count days from 2000, as POV-Ray. */
static const double EPOCH_2000 = 946684800.0;

/* datetime(F [, format]): F days after 2000-01-01 00:00 UTC through strftime (POV-Ray's default
 * format "%Y-%m-%d %H:%M:%SZ"). */
static bool fn_datetime(parser *p, const args *a, value *out)
{
	double secs = floor(arg_f(a, 0) * 86400.0 + 0.5) + EPOCH_2000;
	if (!(fabs(secs) < 1e15))
		return lang_error(p, a->at[0], "'datetime' of %g days: out of range", arg_f(a, 0));
	time_t t = (time_t)secs;
	struct tm tm;
	const char *fmt = a->n > 1 ? a->v[1].str : "%Y-%m-%d %H:%M:%SZ";
	char buf[256];
	size_t n = gmtime_r(&t, &tm) && fmt[0] ? strftime(buf, sizeof buf, fmt, &tm) : 0;
	if (n == 0)
		return lang_error(p, a->at[a->n > 1 ? 1 : 0], "'datetime' made an empty string (a bad or empty format?)");
	return set_string(p, a->name.loc, out, buf, n);
}

static bool fn_dimensions(parser *p, const args *a, value *out)
{
	const lang_array *arr = a->v[0].arr;
	if (a->name.kind == LTK_KW_DIMENSIONS) {
		set_float(out, arr->dims);
		return true;
	}
	double d = arg_f(a, 1);
	if (!(d >= 1 && d <= arr->dims && d == floor(d)))
		return lang_error(p, a->at[1], "'dimension_size' of dimension %g: the array has %d", d, arr->dims);
	set_float(out, (double)arr->size[(int)d - 1]);
	return true;
}

/* vturbulence(Lambda, Omega, Octaves, A): POV-Ray's DTurbulence at A, the vector turbulence a
 * turbulence warp moves points by (scene/pattern.h's pattern_dturbulence: circe's noise, so
 * POV-Ray's size and smoothness, not its values); octaves limited to 1..10 as POV-Ray's parser does. */
static bool fn_vturbulence(parser *p, const args *a, value *out)
{
	(void)p;
	double oct = fmax(1.0, fmin(10.0, trunc(arg_f(a, 2))));
	pattern_turb t = {.amount = d3(1, 1, 1), .octaves = (int)oct, .omega = arg_f(a, 1), .lambda = arg_f(a, 0)};
	set_vec3(out, pattern_dturbulence(arg_v(a, 3), &t));
	return true;
}
/* Not a keyword of circe's table (it lexes as a POV-Ray word circe lacks): found by spelling. */
static const builtin vturbulence_builtin = {LTK_UNSUPPORTED, "fffv", fn_vturbulence};

static const builtin builtins[] = {
	{LTK_KW_SIN, "f", fn_float1},	   {LTK_KW_COS, "f", fn_float1},	  {LTK_KW_TAN, "f", fn_float1},
	{LTK_KW_ASIN, "f", fn_float1},	   {LTK_KW_ACOS, "f", fn_float1},	  {LTK_KW_ATAN, "f", fn_float1},
	{LTK_KW_SINH, "f", fn_float1},	   {LTK_KW_COSH, "f", fn_float1},	  {LTK_KW_TANH, "f", fn_float1},
	{LTK_KW_ASINH, "f", fn_float1},	   {LTK_KW_ACOSH, "f", fn_float1},	  {LTK_KW_ATANH, "f", fn_float1},
	{LTK_KW_SQRT, "f", fn_float1},	   {LTK_KW_EXP, "f", fn_float1},	  {LTK_KW_LOG, "f", fn_float1},
	{LTK_KW_LN, "f", fn_float1},	   {LTK_KW_ABS, "f", fn_float1},	  {LTK_KW_FLOOR, "f", fn_float1},
	{LTK_KW_CEIL, "f", fn_float1},	   {LTK_KW_INT, "f", fn_float1},	  {LTK_KW_RADIANS, "f", fn_float1},
	{LTK_KW_DEGREES, "f", fn_float1},   {LTK_KW_ATAN2, "ff", fn_float2},	  {LTK_KW_POW, "ff", fn_float2},
	{LTK_KW_MOD, "ff", fn_float2},	   {LTK_KW_DIV, "ff", fn_float2},	  {LTK_KW_MIN, "ff*", fn_min_max},
	{LTK_KW_MAX, "ff*", fn_min_max},    {LTK_KW_SELECT, "fff|f", fn_select}, {LTK_KW_BITWISE_AND, "ff*", fn_bitwise},
	{LTK_KW_BITWISE_OR, "ff*", fn_bitwise}, {LTK_KW_BITWISE_XOR, "ff*", fn_bitwise},
	{LTK_KW_SEED, "f", fn_seed},	   {LTK_KW_RAND, "f", fn_rand},	  {LTK_KW_VLENGTH, "v", fn_vector},
	{LTK_KW_VNORMALIZE, "v", fn_vector}, {LTK_KW_VDOT, "vv", fn_vector},	  {LTK_KW_VCROSS, "vv", fn_vector},
	{LTK_KW_VROTATE, "vv", fn_vector},  {LTK_KW_VAXIS_ROTATE, "vvf", fn_vector},
	{LTK_KW_CONCAT, "s*", fn_concat},   {LTK_KW_STR, "fff", fn_str},	  {LTK_KW_VSTR, "fnsff", fn_vstr},
	{LTK_KW_CHR, "f", fn_chr},	   {LTK_KW_SUBSTR, "sff", fn_substr},	  {LTK_KW_STRUPR, "s", fn_case},
	{LTK_KW_STRLWR, "s", fn_case},	   {LTK_KW_ASC, "s", fn_string_float},	  {LTK_KW_STRLEN, "s", fn_string_float},
	{LTK_KW_STRCMP, "ss", fn_string_float}, {LTK_KW_VAL, "s", fn_string_float},
	{LTK_KW_FILE_EXISTS, "s", fn_string_float}, {LTK_KW_DATETIME, "f|s", fn_datetime},
	{LTK_KW_DIMENSIONS, "a", fn_dimensions}, {LTK_KW_DIMENSION_SIZE, "af", fn_dimensions},
};

static const builtin *builtin_of(lang_tok k)
{
	for (size_t i = 0; i < sizeof builtins / sizeof builtins[0]; i++)
		if (builtins[i].tok == k)
			return &builtins[i];
	return NULL;
}

/* "(" expression { "," expression } ")" after a function's name. */
static bool read_args(parser *p, args *a)
{
	char ctx[64];
	snprintf(ctx, sizeof ctx, "after '%s'", a->fname);
	if (!lang_expect(p, LTK_LPAREN, ctx))
		return false;
	bool saved = p->no_gt;
	p->no_gt = false;
	a->n = 0;
	if (lang_peek(p)->kind != LTK_RPAREN)
		for (;;) {
			if (a->n == LANG_MAX_VECTOR)
				return lang_error(p, a->name.loc, "too many arguments to '%s' (limit is %d)", a->fname, LANG_MAX_VECTOR);
			a->at[a->n] = lang_peek(p)->loc;
			if (!expr_cond(p, &a->v[a->n]))
				return false;
			a->n++;
			if (!lang_accept(p, LTK_COMMA))
				break;
		}
	snprintf(ctx, sizeof ctx, "to close the arguments of '%s'", a->fname);
	if (!lang_expect(p, LTK_RPAREN, ctx))
		return false;
	p->no_gt = saved;
	return true;
}

/* The number of arguments a type string takes: *lo required, *hi at most (-1: no limit). */
static void arg_counts(const char *types, int *lo, int *hi)
{
	*lo = 0, *hi = 0;
	bool optional = false;
	for (const char *c = types; *c; c++) {
		if (*c == '|')
			optional = true;
		else if (*c == '*')
			*hi = -1;
		else {
			*lo += !optional;
			*hi += 1;
		}
	}
}

bool lang_wrong_count(parser *p, diag_loc at, const char *fname, int lo, int hi, int found)
{
	char want[64];
	if (hi < 0)
		snprintf(want, sizeof want, "at least %d argument%s", lo, lo == 1 ? "" : "s");
	else if (lo == hi)
		snprintf(want, sizeof want, "%d argument%s", lo, lo == 1 ? "" : "s");
	else
		snprintf(want, sizeof want, "%d to %d arguments", lo, hi);
	return lang_error(p, at, "'%s' takes %s, found %d", fname, want, found);
}

/* Checks argument i against its type letter t (promoting a vector argument). */
static bool check_arg(parser *p, args *a, int i, char t)
{
	value *v = &a->v[i];
	const char *want = NULL;
	switch (t) {
	case 'f':
		if (v->kind != VAL_FLOAT)
			want = "a float";
		break;
	case 'v':
		if (v->kind == VAL_FLOAT || (v->kind == VAL_VECTOR && v->n <= 3))
			promote(v, 3);
		else
			want = "a vector";
		break;
	case 'n':
		if (!is_numeric(v))
			want = "a float or a vector";
		break;
	case 's':
		if (v->kind != VAL_STRING)
			want = "a string";
		break;
	default:
		if (v->kind != VAL_ARRAY)
			want = "an array";
		break;
	}
	if (!want)
		return true;
	return lang_error(p, a->at[i], "argument %d of '%s' must be %s, found %s", i + 1, a->fname, want,
			  lang_value_kind_name(v));
}

static bool check_args(parser *p, const builtin *b, args *a)
{
	int lo, hi;
	arg_counts(b->types, &lo, &hi);
	if (a->n < lo || (hi >= 0 && a->n > hi))
		return lang_wrong_count(p, a->name.loc, a->fname, lo, hi, a->n);
	char last = 0;
	const char *c = b->types;
	for (int i = 0; i < a->n; i++) {
		while (*c == '|')
			c++;
		if (*c && *c != '*')
			last = *c++;
		if (!check_arg(p, a, i, last))
			return false;
	}
	return true;
}

/* call = function "(" expression { "," expression } ")" */
static bool call(parser *p, const builtin *b, value *out)
{
	args a;
	a.name = *lang_advance(p);
	snprintf(a.fname, sizeof a.fname, "%.*s", (int)a.name.len, a.name.text);
	if (!read_args(p, &a) || !check_args(p, b, &a) || !b->fn(p, &a, out))
		return false;
	return out->kind == VAL_STRING || finite_result(p, a.name.loc, out, a.fname);
}

/* ---- operators --------------------------------------------------------------------------- */

/* An identifier's value: an array's element when an index follows. */
static bool identifier(parser *p, value *out)
{
	lang_token name = *lang_advance(p);
	const symbol *s = lang_lookup(p, name.text, name.len);
	if (!s)
		return lang_error(p, name.loc, "undeclared identifier '%.*s'", (int)name.len, name.text);
	if ((s->val.kind == VAL_FUNCTION || s->val.kind == VAL_SPLINE) && lang_raw_next(p) == LTK_LPAREN)
		return lang_func_call(p, &name, &s->val, out);
	if (lang_raw_next(p) == LTK_LBRACKET) { /* raw: a value's end is not read past (lone_value) */
		if (s->val.kind != VAL_ARRAY)
			return lang_error(p, lang_peek(p)->loc, "'%.*s' is %s, not an array", (int)name.len, name.text,
					  lang_value_kind_name(&s->val));
		return element(p, &name, &s->val, out);
	}
	*out = s->val;
	return true;
}

/* The 2- and 4-vectors POV-Ray names: u <1, 0>, v <0, 1>, t <0, 0, 0, 1>; x, y, z the axes. */
static void named_vector(lang_tok k, value *out)
{
	clear(out);
	out->kind = VAL_VECTOR;
	out->n = k == LTK_KW_U || k == LTK_KW_V ? 2 : k == LTK_KW_T ? 4 : 3;
	int one = k == LTK_KW_X || k == LTK_KW_U ? 0 : k == LTK_KW_Y || k == LTK_KW_V ? 1 : k == LTK_KW_Z ? 2 : 3;
	out->v[one] = 1;
}

/* primary = number | string | "(" expression ")" | vector | colour | identifier [ index ]
 *         | "x" | "y" | "z" | "t" | "u" | "v" | "pi" | "clock" | "clock_on" | "version" | "now"
 *         | "true" | "yes" | "on" | "false" | "no" | "off" | defined | call */
bool lang_primary(parser *p, value *out)
{
	lang_token *t = lang_peek(p);
	clear(out);
	switch (t->kind) {
	case LTK_NUMBER:
		set_float(out, t->number);
		lang_advance(p);
		return true;
	case LTK_STRING:
		return lang_decode_string(p, lang_advance(p), out);
	case LTK_LPAREN: {
		lang_advance(p);
		bool saved = p->no_gt;
		p->no_gt = false;
		if (!expr_cond(p, out) || !lang_expect(p, LTK_RPAREN, "to close '('"))
			return false;
		p->no_gt = saved;
		return true;
	}
	case LTK_LT:
		lang_advance(p);
		return vector_literal(p, out);
	case LTK_KW_X:
	case LTK_KW_Y:
	case LTK_KW_Z:
	case LTK_KW_T:
	case LTK_KW_U:
	case LTK_KW_V:
		named_vector(t->kind, out);
		lang_advance(p);
		return true;
	case LTK_KW_PI: set_float(out, PI); break;
	case LTK_KW_CLOCK: set_float(out, p->opt.clock); break;
	case LTK_KW_TRUE:
	case LTK_KW_YES:
	case LTK_KW_ON:
	case LTK_KW_FALSE:
	case LTK_KW_NO:
	case LTK_KW_OFF: set_float(out, t->kind == LTK_KW_TRUE || t->kind == LTK_KW_YES || t->kind == LTK_KW_ON); break;
	case LTK_KW_VERSION: set_float(out, p->version); break;
	case LTK_KW_CLOCK_ON: set_float(out, p->opt.animated); break;
	case LTK_KW_NOW: set_float(out, ((double)time(NULL) - EPOCH_2000) / 86400.0); break;
	case LTK_KW_DEFINED: return defined(p, out);
	case LTK_KW_FUNCTION: /* values of #declare and macro arguments only: here POV-Ray's function pattern */
	case LTK_KW_SPLINE:
		return lang_error(p, t->loc, "'%s' is not supported by circe here (a %s is the value of a #declare, "
					     "a #local or a macro's argument)", t->kind == LTK_KW_SPLINE ? "spline" : "function",
				  t->kind == LTK_KW_SPLINE ? "spline" : "function");
	case LTK_KW_ARRAY: return lang_array_value(p, out); /* an element of an array of arrays */
	case LTK_IDENT: return identifier(p, out);
	default: {
		if (lang_colour_word(t->kind))
			return colour_value(p, out);
		if (t->kind == LTK_UNSUPPORTED && (lang_word_is(t, "min_extent") || lang_word_is(t, "max_extent")))
			return lang_extent(p, out); /* extent.c */
		if (t->kind == LTK_UNSUPPORTED && lang_word_is(t, "trace"))
			return lang_trace(p, out); /* extent.c */
		if (t->kind == LTK_UNSUPPORTED && lang_word_is(t, "inside"))
			return lang_inside(p, out); /* extent.c */
		const builtin *b = builtin_of(t->kind);
		if (!b && t->kind == LTK_UNSUPPORTED && lang_token_is(t, "vturbulence"))
			b = &vturbulence_builtin;
		if (b)
			return call(p, b, out);
		return lang_error_found(p, "expected an expression");
	}
	}
	lang_advance(p);
	return true;
}

/* postfix = primary { member } */
static bool primary(parser *p, value *out)
{
	if (!lang_primary(p, out))
		return false;
	while (lang_peek(p)->kind == LTK_DOT)
		if (!lang_member(p, out))
			return false;
	return true;
}

/* unary = ( "-" | "+" | "!" ) unary | postfix */
static bool unary(parser *p, value *out)
{
	lang_token *t = lang_peek(p);
	if (t->kind != LTK_MINUS && t->kind != LTK_PLUS && t->kind != LTK_BANG)
		return primary(p, out);
	lang_token op = *lang_advance(p);
	if (!lang_enter(p, op.loc))
		return false;
	bool ok = unary(p, out);
	lang_leave(p);
	if (!ok)
		return false;
	if (op.kind == LTK_BANG) {
		if (!need_float(p, op.loc, out, "'!'"))
			return false;
		set_float(out, !truth(out->v[0]));
	} else if (op.kind == LTK_MINUS) {
		if (!is_numeric(out))
			return lang_error(p, op.loc, "cannot negate %s", lang_value_kind_name(out));
		for (int i = 0; i < out->n; i++)
			out->v[i] = -out->v[i];
	} else if (!is_numeric(out)) {
		return lang_error(p, op.loc, "unary '+' needs a number, found %s", lang_value_kind_name(out));
	}
	return true;
}

/* term = unary { ( "*" | "/" ) unary } */
static bool term(parser *p, value *out)
{
	if (!unary(p, out))
		return false;
	for (;;) {
		lang_tok k = lang_peek(p)->kind;
		if (k != LTK_STAR && k != LTK_SLASH)
			return true;
		lang_token op = *lang_advance(p);
		value b;
		if (!unary(p, &b) || !unify(p, op.loc, out, &b, k == LTK_STAR ? "*" : "/"))
			return false;
		for (int i = 0; i < out->n; i++) {
			if (k == LTK_SLASH && b.v[i] == 0.0)
				return lang_error(p, op.loc, "division by zero");
			out->v[i] = k == LTK_STAR ? out->v[i] * b.v[i] : out->v[i] / b.v[i];
		}
		if (!finite_result(p, op.loc, out, k == LTK_STAR ? "'*'" : "'/'"))
			return false;
	}
}

/* additive = term { ( "+" | "-" ) term } */
static bool expr_additive(parser *p, value *out)
{
	if (!term(p, out))
		return false;
	for (;;) {
		lang_tok k = lang_peek(p)->kind;
		if (k != LTK_PLUS && k != LTK_MINUS)
			return true;
		lang_token op = *lang_advance(p);
		value b;
		if (!term(p, &b) || !unify(p, op.loc, out, &b, k == LTK_PLUS ? "+" : "-"))
			return false;
		for (int i = 0; i < out->n; i++)
			out->v[i] = k == LTK_PLUS ? out->v[i] + b.v[i] : out->v[i] - b.v[i];
		if (!finite_result(p, op.loc, out, k == LTK_PLUS ? "'+'" : "'-'"))
			return false;
	}
}

/* Two strings compared as POV-Ray 3.7 compares them (Parse_Rel_String_Term in express.cpp): by
 * strcmp of their bytes, the result 1 or 0. */
static bool string_comparison(parser *p, const lang_token *op, value *a, const value *b)
{
	if (a->kind != VAL_STRING || b->kind != VAL_STRING)
		return lang_error(p, op->loc, "a comparison of a string needs a string on both sides, found %s",
				  lang_value_kind_name(a->kind == VAL_STRING ? b : a));
	int c = strcmp(a->str, b->str);
	lang_tok k = op->kind;
	set_float(a, k == LTK_LT ? c < 0 : k == LTK_LE ? c <= 0 : k == LTK_EQ ? c == 0 : k == LTK_NE ? c != 0
		     : k == LTK_GE ? c >= 0 : c > 0);
	return true;
}

/* comparison = additive { ( "<" | "<=" | "=" | "!=" | ">=" | ">" ) additive }
 * Two strings compare by strcmp (POV-Ray 3.7); otherwise both sides are floats.
 * Inside a vector literal a '>' is not an operator: it closes the vector. */
static bool comparison(parser *p, value *out)
{
	if (!expr_additive(p, out))
		return false;
	for (;;) {
		lang_tok k = lang_peek(p)->kind;
		if (k != LTK_LT && k != LTK_LE && k != LTK_EQ && k != LTK_NE && k != LTK_GE && k != LTK_GT)
			return true;
		if (k == LTK_GT && p->no_gt)
			return true;
		lang_token op = *lang_advance(p);
		value b;
		if (!expr_additive(p, &b))
			return false;
		if (out->kind == VAL_STRING || b.kind == VAL_STRING) {
			if (!string_comparison(p, &op, out, &b))
				return false;
			continue;
		}
		if (!need_float(p, op.loc, out, "a comparison") || !need_float(p, op.loc, &b, "a comparison"))
			return false;
		/* POV-Ray's Parse_Rel_Term: '=', '<=', '>=' and '!=' within EPSILON */
		double x = out->v[0], y = b.v[0];
		bool near = !truth(x - y);
		bool r = k == LTK_LT ? x < y : k == LTK_LE ? x <= y || near : k == LTK_EQ ? near : k == LTK_NE ? !near
			 : k == LTK_GE ? x >= y || near : x > y;
		set_float(out, r);
	}
}

/* logical = comparison { ( "&" | "|" ) comparison }
 * As POV-Ray 3.7's Parse_Logical: '&' and '|' at one level, from the left. */
static bool expr_logical(parser *p, value *out)
{
	if (!comparison(p, out))
		return false;
	for (;;) {
		lang_tok k = lang_peek(p)->kind;
		if (k != LTK_AMP && k != LTK_BAR)
			return true;
		lang_token op = *lang_advance(p);
		const char *name = k == LTK_AMP ? "'&'" : "'|'";
		value b;
		if (!comparison(p, &b) || !need_float(p, op.loc, out, name) || !need_float(p, op.loc, &b, name))
			return false;
		bool x = truth(out->v[0]), y = truth(b.v[0]);
		set_float(out, k == LTK_AMP ? x && y : x || y);
	}
}

/* expression = logical [ "?" expression ":" expression ]
 * POV-Ray's conditional (Parse_Express): the condition a float; both branches are read (and
 * evaluated, as POV-Ray evaluates them), the chosen one is the value. */
static bool expr_cond(parser *p, value *out)
{
	if (!lang_enter(p, lang_peek(p)->loc))
		return false;
	bool ok = expr_logical(p, out);
	if (ok && lang_peek(p)->kind == LTK_QUESTION) {
		lang_token op = *lang_advance(p);
		value a, b;
		ok = need_float(p, op.loc, out, "the condition of '?'") && expr_cond(p, &a) &&
		     lang_expect(p, LTK_COLON, "between the two values of '?'") && expr_cond(p, &b);
		if (ok)
			*out = truth(out->v[0]) ? a : b;
	}
	lang_leave(p);
	return ok;
}

/* ---- typed entry points ------------------------------------------------------------------ */

bool lang_expr(parser *p, value *out) { return expr_cond(p, out); }

bool lang_truth(double x) { return truth(x); }

/* A float from an expression: full (a directive's condition, in its parentheses) or, as POV-Ray
 * 3.7's Parse_Float reads one, additive: no comparison at its top, so that mesh2's
 * `vertex_vectors { 14 <-1, -1, -1> ...` is a count and a vector (a comparison needs parentheses). */
static bool float_of(parser *p, const char *what, bool full, double *out)
{
	diag_loc loc = lang_peek(p)->loc;
	value v;
	bool saved = p->no_gt;
	if (!full)
		p->no_gt = false;
	bool ok = full ? lang_expr(p, &v) : expr_additive(p, &v);
	p->no_gt = saved;
	if (!ok)
		return false;
	if (v.kind != VAL_FLOAT)
		return lang_error(p, loc, "expected a float %s, found %s", what, lang_value_kind_name(&v));
	*out = v.v[0];
	return true;
}

bool lang_float(parser *p, const char *what, double *out) { return float_of(p, what, false, out); }

bool lang_additive(parser *p, value *out)
{
	bool saved = p->no_gt;
	p->no_gt = false;
	bool ok = expr_additive(p, out);
	p->no_gt = saved;
	return ok;
}

bool lang_float_expr(parser *p, const char *what, double *out) { return float_of(p, what, true, out); }

bool lang_int(parser *p, const char *what, long lo, long hi, long *out)
{
	diag_loc loc = lang_peek(p)->loc;
	double x;
	if (!lang_float(p, what, &x))
		return false;
	if (x != floor(x))
		return lang_error(p, loc, "expected an integer %s, found %g", what, x);
	if (x < (double)lo || x > (double)hi)
		return lang_error(p, loc, "%g is out of range %s (limit is %ld to %ld)", x, what, lo, hi);
	*out = (long)x;
	return true;
}

/* As POV-Ray 3.7's Parse_Vector: an additive expression (so `<a><b>` is two vectors, not a
 * comparison), a float copied into x, y and z, a 2-vector padded with z = 0; a colour or a longer
 * vector is an error. */
bool lang_vec3(parser *p, const char *what, dvec3 *out)
{
	diag_loc loc = lang_peek(p)->loc;
	value v;
	bool saved = p->no_gt;
	p->no_gt = false;
	bool ok = expr_additive(p, &v);
	p->no_gt = saved;
	if (!ok)
		return false;
	if (v.kind != VAL_FLOAT && (v.kind != VAL_VECTOR || v.n > 3))
		return lang_error(p, loc, "expected a vector %s, found %s", what, lang_value_kind_name(&v));
	promote(&v, 3);
	*out = d3(v.v[0], v.v[1], v.v[2]);
	return true;
}

bool lang_color(parser *p, const char *what, vec3 *out)
{
	diag_loc loc = lang_peek(p)->loc;
	double ft[2];
	if (!lang_color_ft(p, what, out, ft))
		return false;
	if (ft[0] != 0 || ft[1] != 0)
		diag_warning(p->d, loc, "filter %g and transmit %g of this colour are ignored: only a pigment's colour "
					"is transparent in circe", ft[0], ft[1]);
	return true;
}

bool lang_color5(parser *p, const char *what, double out[LANG_COLOR_TERMS])
{
	diag_loc loc = lang_peek(p)->loc;
	value c;
	bool saved = p->no_gt, ok;
	p->no_gt = false;
	if (lang_colour_word(lang_peek(p)->kind)) {
		ok = colour_value(p, &c);
	} else { /* a declared colour or an expression, and then its components by name */
		value o;
		clear(&c);
		set_colour(&c);
		ok = expr_additive(p, &o);
		if (ok && !colour_from(&o, &c))
			ok = lang_error(p, loc, "expected a colour %s, found %s", what, lang_value_kind_name(&o));
		ok = ok && colour_items(p, &c, false, true);
	}
	p->no_gt = saved;
	if (!ok)
		return false;
	for (int i = 0; i < LANG_COLOR_TERMS; i++)
		out[i] = c.v[i];
	return true;
}

bool lang_color_ft(parser *p, const char *what, vec3 *out, double ft[2])
{
	double c[LANG_COLOR_TERMS];
	if (!lang_color5(p, what, c))
		return false;
	ft[0] = c[3], ft[1] = c[4];
	*out = v3((float)c[0], (float)c[1], (float)c[2]);
	return true;
}

bool lang_string(parser *p, const char *what, const char **out)
{
	diag_loc loc = lang_peek(p)->loc;
	value v;
	if (!lang_expr(p, &v))
		return false;
	if (v.kind != VAL_STRING)
		return lang_error(p, loc, "expected a string %s, found %s", what, lang_value_kind_name(&v));
	*out = v.str;
	return true;
}

bool lang_index_tuple(parser *p, const char *what, uint32_t *idx, int *n, diag_loc *loc)
{
	*loc = lang_peek(p)->loc;
	value v;
	/* An additive expression, as POV-Ray's Parse_Vector: `<0, 1, 2> <1, 2, 3>` is two index
	 * vectors (the commas between them are optional), not a comparison. */
	if (!lang_additive(p, &v))
		return false;
	if (v.kind != VAL_VECTOR)
		return lang_error(p, *loc, "expected a vector of indices %s, found %s", what, lang_value_kind_name(&v));
	for (int i = 0; i < v.n; i++) {
		double x = v.v[i];
		if (x != floor(x) || x < 0 || x > 4294967295.0)
			return lang_error(p, *loc, "index %g %s is not a non-negative integer", x, what);
		idx[i] = (uint32_t)x;
	}
	*n = v.n;
	return true;
}
