/* shapes2.c - the bodies of POV-Ray 3.7's lathe, sor, prism, sphere_sweep, blob and text
 * (parser.cpp's Parse_Lathe, Parse_Sor, Parse_Prism, Parse_Sphere_Sweep, Parse_Blob,
 * Parse_TrueType): the same syntax, defaults, limits and messages where POV-Ray gives one. The
 * words of these shapes are matched by spelling, so they work whether the lexer's keyword table
 * holds them or they lex as POV-Ray words (LTK_UNSUPPORTED). stmt.c places the geometry and reads
 * the object's modifiers. */
#include "lang/shapes2.h"

#include "geom/shape.h"
#include "lang/func.h"
#include "lang/pigment.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

/* The most points or components one shape may list (POV-Ray has no limit; this keeps a typo's
 * count from asking for gigabytes before the points are read). */
#define LANG_MAX_SHAPE_POINTS 1000000

static bool accept_word(parser *p, const char *w)
{
	if (!lang_word_is(lang_peek(p), w))
		return false;
	lang_advance(p);
	return true;
}

int lang_pov_shape_kind(const lang_token *t)
{
	static const char *const words[] = {"lathe", "sor",	   "prism",	 "sphere_sweep", "blob",
					    "text",  "bicubic_patch", "isosurface", "parametric",	  "julia_fractal"};
	for (int k = 0; k < 10; k++)
		if (lang_word_is(t, words[k]))
			return k;
	return -1;
}

/* A number that a point may follow without a comma (`u_steps 4 <0, 0, 0>`): read as an additive
 * expression, where '<' begins the next vector rather than a comparison, as in POV-Ray. */
static bool num(parser *p, const char *what, double *out)
{
	dvec3 v;
	TRY(lang_vec3(p, what, &v));
	*out = v.x;
	return true;
}

/* POV-Ray's Parse_Comma: an optional ','. */
static void comma(parser *p) { lang_accept(p, LTK_COMMA); }

static bool count(parser *p, const char *what, long lo, uint32_t *out)
{
	long n;
	diag_loc at = lang_peek(p)->loc;
	double x;
	TRY(num(p, what, &x));
	if (!(x >= lo) || !(x <= LANG_MAX_SHAPE_POINTS))
		return lang_error(p, at, "%s must be %ld to %d, found %g", what, lo, LANG_MAX_SHAPE_POINTS, x);
	n = (long)x; /* POV-Ray truncates: (int)Parse_Float() */
	*out = (uint32_t)n;
	return true;
}

/* n points <u, v> (POV-Ray's Parse_UV_Vect: a float is promoted), each followed by an optional ','. */
static bool uv_points(parser *p, uint32_t n, double **out)
{
	double *pts = arena_alloc(&p->sc->arena, 2 * (size_t)n, sizeof *pts, sizeof(double));
	if (!pts)
		return lang_error(p, lang_peek(p)->loc, "out of memory");
	for (uint32_t i = 0; i < n; i++) {
		dvec3 v;
		TRY(lang_vec3(p, "as a point <u, v>", &v));
		pts[2 * i] = v.x, pts[2 * i + 1] = v.y;
		comma(p);
	}
	*out = pts;
	return true;
}

static shape_desc *new_desc(parser *p, shape_kind k)
{
	shape_desc *s = arena_zalloc(&p->sc->arena, 1, sizeof *s);
	if (!s) {
		lang_error(p, lang_peek(p)->loc, "out of memory");
		return NULL;
	}
	s->kind = k;
	return s;
}

/* [ linear_spline | quadratic_spline | cubic_spline | bezier_spline ] (and, for a prism,
 * linear_sweep | conic_sweep), in any order, the last of each kind winning as in POV-Ray. */
static void spline_words(parser *p, shape_desc *s, bool sweeps)
{
	for (;;) {
		if (accept_word(p, "linear_spline"))
			s->spline = SHAPE_LINEAR;
		else if (accept_word(p, "quadratic_spline"))
			s->spline = SHAPE_QUADRATIC;
		else if (accept_word(p, "cubic_spline"))
			s->spline = SHAPE_CUBIC;
		else if (accept_word(p, "bezier_spline"))
			s->spline = SHAPE_BEZIER;
		else if (sweeps && accept_word(p, "linear_sweep"))
			s->conic = false;
		else if (sweeps && accept_word(p, "conic_sweep"))
			s->conic = true;
		else
			return;
	}
}

/* The point count of a lathe or prism (`what`), checked against the least its spline needs
 * (least[spline]; Bezier: four a segment), with POV-Ray's messages. */
static bool spline_count(parser *p, shape_desc *s, const char *what, const long least[4])
{
	static const char *const names[] = {"linear", "quadratic", "cubic", "Bezier"};
	char ctx[40];
	snprintf(ctx, sizeof ctx, "the %s's point count", what);
	diag_loc at = lang_peek(p)->loc;
	TRY(count(p, ctx, 0, &s->n_pts));
	if (s->spline == SHAPE_BEZIER && (s->n_pts % 4 != 0 || s->n_pts == 0))
		return lang_error(p, at, "a %s with Bezier splines must have four points per segment, found %u", what,
				  s->n_pts);
	if (s->n_pts < least[s->spline])
		return lang_error(p, at, "a %s with %s splines must have at least %ld points, found %u", what,
				  names[s->spline], least[s->spline], s->n_pts);
	return true;
}

/* lathe = "lathe" "{" [ spline_type ] int [ "," ] uv { [ "," ] uv } ... (POV-Ray's counts:
 * linear 2, quadratic 3, cubic 4, Bezier four a segment). */
static bool lathe(parser *p, shape_desc *s)
{
	spline_words(p, s, false);
	static const long least[] = {2, 3, 4, 4};
	diag_loc at = lang_peek(p)->loc;
	TRY(spline_count(p, s, "lathe", least));
	comma(p);
	TRY(uv_points(p, s->n_pts, &s->pts));
	/* POV-Ray refuses a negative radius, but at the spline's control points. */
	for (uint32_t i = 0; i < s->n_pts; i++) {
		bool ctrl = (s->spline == SHAPE_QUADRATIC && i == 0) ||
			    (s->spline == SHAPE_CUBIC && (i == 0 || i == s->n_pts - 1)) ||
			    (s->spline == SHAPE_BEZIER && i % 4 != 0 && i % 4 != 3);
		if (!ctrl && s->pts[2 * i] < 0)
			return lang_error(p, at, "lathe point %u has a radius (x) < 0: %g", i, s->pts[2 * i]);
	}
	return true;
}

/* sor = "sor" "{" int [ "," ] uv { [ "," ] uv } [ "open" ] ... : at least four points, radii >= 0,
 * heights rising from the second point to the one before the last (POV-Ray's checks). */
static bool sor(parser *p, shape_desc *s)
{
	diag_loc at = lang_peek(p)->loc;
	TRY(count(p, "the sor's point count", 0, &s->n_pts));
	if (s->n_pts < 4)
		return lang_error(p, at, "a surface of revolution must have at least four points, found %u", s->n_pts);
	comma(p);
	TRY(uv_points(p, s->n_pts, &s->pts));
	for (uint32_t i = 0; i < s->n_pts; i++) {
		const double *q = &s->pts[2 * i];
		if (q[0] < 0 || (i > 1 && i < s->n_pts - 1 && q[1] <= q[-1]))
			return lang_error(p, at, "sor point %u is incorrect: radii must be >= 0 and heights rise from "
						 "the second point to the one before the last",
					  i);
	}
	for (uint32_t i = 0; i + 3 < s->n_pts; i++) /* Compute_Sor's check of the slopes' chords */
		if (fabs(s->pts[2 * i + 5] - s->pts[2 * i + 1]) < 1e-10 || fabs(s->pts[2 * i + 7] - s->pts[2 * i + 3]) < 1e-10)
			return lang_error(p, at, "sor point %u is incorrect: two points two apart at the same height", i);
	s->open = accept_word(p, "open");
	return true;
}

/* Whether the prism's outline closes as POV-Ray's Parse_Prism checks it (linear: a point equal
 * to the sub-polygon's first; quadratic and cubic: to its second; Bezier: each run of segments
 * ending where it began). */
static bool prism_closed(const shape_desc *s)
{
	const double *P = s->pts, eps = 1e-10;
	uint32_t n = s->n_pts;
	if (s->spline == SHAPE_BEZIER) {
		uint32_t start = 0;
		for (uint32_t i = 4; i < n; i += 4)
			if (fabs(P[2 * i] - P[2 * i - 2]) > eps || fabs(P[2 * i + 1] - P[2 * i - 1]) > eps) {
				if (fabs(P[2 * i - 2] - P[2 * start]) > eps || fabs(P[2 * i - 1] - P[2 * start + 1]) > eps)
					return false;
				start = i;
			}
		return fabs(P[2 * n - 2] - P[2 * start]) <= eps && fabs(P[2 * n - 1] - P[2 * start + 1]) <= eps;
	}
	uint32_t i = s->spline == SHAPE_LINEAR ? 1 : 2, step = s->spline == SHAPE_LINEAR ? 1 : s->spline == SHAPE_QUADRATIC ? 2 : 3;
	const double *first = &P[2 * (i - 1)];
	bool closed = false;
	for (; i < n; i++) {
		closed = false;
		if (fabs(first[0] - P[2 * i]) < eps && fabs(first[1] - P[2 * i + 1]) < eps) {
			i += step;
			if (i < n)
				first = &P[2 * i];
			closed = true;
		}
	}
	return closed;
}

/* prism = "prism" "{" { spline_type | sweep_type } float [ "," ] float [ "," ] int [ "," ]
 *         uv { [ "," ] uv } [ "open" ] ... */
static bool prism(parser *p, shape_desc *s, diag_loc kw)
{
	spline_words(p, s, true);
	TRY(lang_float(p, "as the prism's first height", &s->h1));
	comma(p);
	TRY(lang_float(p, "as the prism's second height", &s->h2));
	comma(p);
	if (s->h1 > s->h2) {
		double t = s->h1;
		s->h1 = s->h2, s->h2 = t;
	}
	static const long least[] = {3, 5, 6, 4};
	TRY(spline_count(p, s, "prism", least));
	if (s->h1 == s->h2)
		return lang_error(p, kw, "the prism is flat: its two heights are both %g", s->h1);
	comma(p);
	TRY(uv_points(p, s->n_pts, &s->pts));
	s->open = accept_word(p, "open");
	if (!prism_closed(s)) {
		if (s->spline != SHAPE_LINEAR) /* POV-Ray: "Prism not closed. Ignoring it." */
			return lang_error(p, kw, "the prism's outline is not closed (POV-Ray ignores such a prism)");
		/* POV-Ray closes a linear one with the sub-polygon's first point */
		double *q = arena_alloc(&p->sc->arena, 2 * ((size_t)s->n_pts + 1), sizeof *q, sizeof(double));
		if (!q)
			return lang_error(p, kw, "out of memory");
		memcpy(q, s->pts, 2 * (size_t)s->n_pts * sizeof *q);
		uint32_t first = 0;
		for (uint32_t i = 1; i < s->n_pts; i++)
			if (fabs(q[2 * i] - q[2 * first]) < 1e-10 && fabs(q[2 * i + 1] - q[2 * first + 1]) < 1e-10)
				first = i + 1 < s->n_pts ? i + 1 : first, i++;
		q[2 * s->n_pts] = q[2 * first], q[2 * s->n_pts + 1] = q[2 * first + 1];
		s->pts = q, s->n_pts++;
		diag_warning(p->d, kw, "linear prism not closed: closing it (as POV-Ray)");
	}
	return true;
}

/* sphere_sweep = "sphere_sweep" "{" ( "linear_spline" | "cubic_spline" | "b_spline" ) [ "," ] int
 *                [ "," ] vector [ "," ] float { [ "," ] vector [ "," ] float } [ "tolerance" float ] ... */
static bool sphere_sweep(parser *p, shape_desc *s)
{
	if (accept_word(p, "linear_spline"))
		s->spline = SHAPE_LINEAR;
	else if (accept_word(p, "cubic_spline"))
		s->spline = SHAPE_CUBIC;
	else if (accept_word(p, "b_spline"))
		s->spline = SHAPE_BSPLINE;
	else
		return lang_error_found(p, "expected linear_spline, cubic_spline or b_spline in 'sphere_sweep'");
	comma(p);
	diag_loc at = lang_peek(p)->loc;
	TRY(count(p, "the sphere_sweep's sphere count", 0, &s->n_pts));
	if (s->n_pts < 2 || (s->spline != SHAPE_LINEAR && s->n_pts < 4))
		return lang_error(p, at, "too few modeling spheres for the interpolation type: %u (linear needs 2, "
					 "cubic_spline and b_spline 4)",
				  s->n_pts);
	comma(p);
	s->pts = arena_alloc(&p->sc->arena, 4 * (size_t)s->n_pts, sizeof *s->pts, sizeof(double));
	if (!s->pts)
		return lang_error(p, at, "out of memory");
	for (uint32_t i = 0; i < s->n_pts; i++) {
		dvec3 c;
		double r;
		TRY(lang_vec3(p, "as a sphere's centre", &c));
		comma(p);
		diag_loc rl = lang_peek(p)->loc;
		TRY(lang_float(p, "as a sphere's radius", &r));
		if (!(r > 0))
			return lang_error(p, rl, "a sphere_sweep's radius must be > 0, found %g", r);
		comma(p);
		double *q = &s->pts[4 * i];
		q[0] = c.x, q[1] = c.y, q[2] = c.z, q[3] = r;
	}
	s->tolerance = 1e-6; /* POV-Ray's default depth tolerance */
	if (accept_word(p, "tolerance"))
		TRY(lang_float(p, "after 'tolerance'", &s->tolerance));
	return true;
}

/* A blob component's modifiers: transforms (its field read back through them) and a texture of
 * its own (*mat; its part is given by blob()). */
static bool component_mods(parser *p, shape_blob_comp *c, diag_loc open, const scene_material **mat)
{
	xform t = xform_identity();
	bool any = false;
	TRY(lang_component_mods(p, &t, &any, mat, open));
	c->has_xf = any, c->xf = t;
	return true;
}

/* Gives each textured component its part: one a distinct material, in order (shape_blob_comp). */
static bool blob_parts(parser *p, vecbuf *comps, const vecbuf *mats, diag_loc kw)
{
	const scene_material **parts = NULL;
	uint32_t n = 0;
	for (size_t i = 0; i < comps->len; i++) {
		const scene_material *m = VECBUF_AT(mats, const scene_material *, i);
		if (!m)
			continue;
		uint32_t k = 0;
		while (k < n && parts[k] != m)
			k++;
		if (k == n) {
			if (n == SHAPE_BLOB_MAX_PARTS)
				return lang_error(p, kw, "a blob has at most %d component textures", SHAPE_BLOB_MAX_PARTS);
			if (!parts && !(parts = arena_alloc(&p->sc->arena, SHAPE_BLOB_MAX_PARTS, sizeof *parts, sizeof(void *))))
				return lang_error(p, kw, "out of memory");
			parts[n++] = m;
		}
		VECBUF_AT(comps, shape_blob_comp, i).part = k + 1;
	}
	p->blob_parts = parts, p->n_blob_parts = n;
	return true;
}

/* blob = "blob" "{" { "threshold" float | "component" float, float, vector
 *        | "sphere" "{" vector, float, [ "strength" ] float { transform } "}"
 *        | "cylinder" "{" vector, vector, float, [ "strength" ] float { transform } "}" } ... */
static bool blob(parser *p, shape_desc *s, diag_loc kw, lang_xform_item_fn xf_item)
{
	(void)xf_item; /* the components' transforms are read by lang_component_mods */
	vecbuf comps, mats;
	vecbuf_init(&comps, sizeof(shape_blob_comp));
	vecbuf_init(&mats, sizeof(const scene_material *));
	p->n_blob_parts = 0;
	s->threshold = 1.0;
	bool ok = true;
	for (; ok;) {
		lang_token t = *lang_peek(p);
		shape_blob_comp c = {0};
		const scene_material *mat = NULL;
		if (accept_word(p, "threshold")) {
			ok = lang_float(p, "after 'threshold'", &s->threshold);
			continue;
		}
		if (accept_word(p, "component")) { /* the old syntax: strength, radius, centre */
			ok = lang_float(p, "as the component's strength", &c.strength) && (comma(p), true) &&
			     lang_float(p, "as the component's radius", &c.radius) && (comma(p), true) &&
			     lang_vec3(p, "as the component's centre", &c.a);
		} else if (t.kind == LTK_KW_SPHERE || lang_word_is(&t, "cylinder")) {
			c.cylinder = t.kind != LTK_KW_SPHERE;
			lang_advance(p);
			diag_loc open = lang_peek(p)->loc;
			ok = lang_expect(p, LTK_LBRACE, c.cylinder ? "after 'cylinder'" : "after 'sphere'") &&
			     lang_vec3(p, c.cylinder ? "as the cylinder's base" : "as the sphere's centre", &c.a);
			comma(p);
			if (ok && c.cylinder) {
				ok = lang_vec3(p, "as the cylinder's apex", &c.b);
				comma(p);
				if (ok && d3_length(d3_sub(c.b, c.a)) < 1e-10)
					ok = lang_error(p, t.loc, "degenerate cylindrical component in blob: its ends coincide");
			}
			ok = ok && lang_float(p, "as the component's radius", &c.radius);
			comma(p);
			if (ok)
				lang_accept(p, LTK_KW_STRENGTH);
			ok = ok && lang_float(p, "as the component's strength", &c.strength) &&
			     component_mods(p, &c, open, &mat);
		} else
			break;
		if (ok && !(c.radius > 0))
			ok = lang_error(p, t.loc, "a blob component's radius must be > 0, found %g", c.radius);
		if (ok && (!vecbuf_push(&comps, &c) || !vecbuf_push(&mats, &mat)))
			ok = lang_error(p, t.loc, "out of memory");
	}
	ok = ok && blob_parts(p, &comps, &mats, kw);
	vecbuf_free(&mats);
	bool positive = false;
	for (size_t i = 0; i < comps.len; i++)
		positive |= VECBUF_AT(&comps, shape_blob_comp, i).strength > 0;
	if (ok && !comps.len)
		ok = lang_error(p, kw, "a blob needs at least one component");
	else if (ok && !positive)
		ok = lang_error(p, kw, "the blob has no component of positive strength: its surface is empty");
	else if (ok && !(s->threshold > 0))
		ok = lang_error(p, kw, "a blob's threshold must be > 0 (circe polygonises a bounded surface), found %g",
				s->threshold);
	if (ok) {
		s->n_comps = (uint32_t)comps.len;
		s->comps = arena_alloc(&p->sc->arena, comps.len, sizeof *s->comps, sizeof(double));
		if (!s->comps)
			ok = lang_error(p, kw, "out of memory");
		else
			memcpy(s->comps, comps.data, comps.len * sizeof *s->comps);
	}
	vecbuf_free(&comps);
	return ok;
}

/* The font as an include file is found: beside the file that names it, then in each -I folder;
 * in each, the name as written, then with POV-Ray's font extensions (.ttf, .TTF) appended. */
static bool font_path(parser *p, const char *name, diag_loc at, const char **out)
{
	static const char *const ext[] = {"", ".ttf", ".TTF"};
	if (!lang_find_data(p, name, ext, 3, at, out))
		return lang_error(p, at, "out of memory");
	if (*out)
		return scene_add_asset(p->sc, SCENE_ASSET_FONT, *out, at) || lang_error(p, at, "out of memory");
	return lang_error(p, at, "cannot find font file '%s' (searched the including file's folder%s)", name,
			  p->opt.n_include_dirs ? " and the -I folders" : "");
}

/* text = "text" "{" "ttf" string [ "," ] string [ "," ] float [ "," ] vector ... */
static bool text(parser *p, shape_desc *s)
{
	diag_loc fl = lang_peek(p)->loc;
	const char *name;
	if (accept_word(p, "internal")) {
		/* POV-Ray's fonts compiled into it (base/fileinputoutput.cpp, Internal_Font_File): 1
		 * timrom, 2 cyrvetic, 3 crystal, any other number povlogo; circe reads the same files of
		 * povray-includes / fonts-povray from the -I folders (benchmark.pov's `internal 1`). */
		double n;
		TRY(lang_float(p, "after 'internal'", &n));
		name = n == 1 ? "timrom.ttf" : n == 2 ? "cyrvetic.ttf" : n == 3 ? "crystal.ttf" : "povlogo.ttf";
	} else {
		if (!accept_word(p, "ttf"))
			return lang_error_found(p, "expected 'ttf' or 'internal' in 'text'");
		fl = lang_peek(p)->loc;
		TRY(lang_string(p, "after 'ttf'", &name));
	}
	comma(p);
	diag_loc sl = lang_peek(p)->loc;
	TRY(lang_string(p, "as the text's string", &s->text));
	if (!s->text[0])
		return lang_error(p, sl, "the text's string is empty: it makes no shape");
	comma(p);
	TRY(lang_float(p, "as the text's depth", &s->depth));
	comma(p);
	TRY(lang_vec3(p, "as the text's offset", &s->offset));
	/* found as POV-Ray opens it: after its string and numbers are read */
	return font_path(p, name, fl, &s->font);
}

/* bicubic_patch = "bicubic_patch" "{" ( bicubic_item* | float float float ) ','? vector ( ','? vector )*15
 *                  ','? ...   (bicubic_item: type, flatness, u_steps, v_steps, accuracy, uv_vectors) */
static bool bicubic_patch(parser *p, shape_desc *s)
{
	static const double st0[8] = {0, 0, 1, 0, 1, 1, 0, 1}; /* POV-Ray's default corners */
	memcpy(s->st, st0, sizeof st0);
	s->flatness = 0.1; /* POV-Ray's constructor */
	double x;
	if (lang_peek(p)->kind == LTK_NUMBER) { /* the old form: type [flatness] u_steps v_steps */
		TRY(num(p, "as the patch type", &x));
		s->patch_type = (int)x;
		if (s->patch_type == 2 || s->patch_type == 3)
			TRY(num(p, "as the flatness", &s->flatness));
		TRY(num(p, "as u_steps", &x));
		s->u_steps = (int)x;
		TRY(num(p, "as v_steps", &x));
		s->v_steps = (int)x;
	} else
		for (;;) {
			diag_loc at = lang_peek(p)->loc;
			if (accept_word(p, "type")) {
				TRY(num(p, "after 'type'", &x));
				s->patch_type = (int)x;
				if (s->patch_type < 0)
					return lang_error(p, at, "undefined bicubic patch type %d", s->patch_type);
			} else if (accept_word(p, "flatness")) {
				TRY(num(p, "after 'flatness'", &s->flatness));
			} else if (accept_word(p, "u_steps")) {
				TRY(num(p, "after 'u_steps'", &x));
				s->u_steps = (int)x;
			} else if (accept_word(p, "v_steps")) {
				TRY(num(p, "after 'v_steps'", &x));
				s->v_steps = (int)x;
			} else if (accept_word(p, "accuracy")) {
				TRY(num(p, "after 'accuracy'", &x));
			} else if (accept_word(p, "uv_vectors")) { /* ends the settings, as in POV-Ray */
				for (int k = 0; k < 4; k++) {
					dvec3 v;
					TRY(lang_vec3(p, "as a corner's <u, v>", &v));
					s->st[2 * k] = v.x, s->st[2 * k + 1] = v.y;
					if (k < 3)
						comma(p);
				}
				break;
			} else
				break;
		}
	if (s->patch_type > 1)
		s->patch_type = 1; /* POV-Ray: "Patch type no longer supported. Using type 1." */
	comma(p);
	s->n_pts = 16;
	s->pts = arena_alloc(&p->sc->arena, 48, sizeof *s->pts, sizeof(double));
	if (!s->pts)
		return lang_error(p, lang_peek(p)->loc, "out of memory");
	for (int i = 0; i < 16; i++) {
		dvec3 v;
		if (lang_peek(p)->kind == LTK_RBRACE)
			return lang_error(p, lang_peek(p)->loc, "a bicubic_patch needs 16 control points, found %d", i);
		TRY(lang_vec3(p, "as a control point of the patch", &v));
		s->pts[3 * i] = v.x, s->pts[3 * i + 1] = v.y, s->pts[3 * i + 2] = v.z;
		comma(p);
	}
	return true;
}

/* The isosurface's function called from the tessellator (geom knows no language). */
static bool iso_call(const void *ctx, const double xyz[3], double *out)
{
	const lang_function *failed;
	return lang_fn_eval(ctx, xyz, out, &failed);
}

/* shape_desc.fn_same of the isosurface's function: compiled functions live in the scene's arena. */
static bool iso_same_fn(const void *a, const void *b) { return lang_fn_same(a, b); }

/* "function" "{" ... "}" or a declared function's name: a float function of x, y and z (of u, v
 * and a third for a parametric: u and v are x and y), evaluable by circe; *out the function. */
static bool float_function(parser *p, const char *what, const lang_function **out)
{
	lang_token t = *lang_peek(p);
	const lang_function *f = NULL;
	if (t.kind == LTK_KW_FUNCTION) {
		value v;
		TRY(lang_func_value(p, NULL, &v));
		f = v.fn;
	} else {
		const symbol *sym = lang_lookup(p, t.text, t.len);
		if (!sym || sym->val.kind != VAL_FUNCTION)
			return lang_error_found(p, "expected 'function { ... }' or a declared function %s", what);
		lang_advance(p);
		f = sym->val.fn;
	}
	if (f->n_params != 3 || f->n_out != 1)
		return lang_error(p, t.loc, "%s must be a float function of x, y and z: '%s' takes %d parameter%s and gives %d "
					    "value%s",
				  what, f->name, f->n_params, f->n_params == 1 ? "" : "s", f->n_out, f->n_out == 1 ? "" : "s");
	double a[3] = {0, 0, 0}, r;
	const lang_function *failed = NULL;
	if (!lang_fn_eval(f, a, &r, &failed)) /* what circe cannot evaluate is refused here, not per point */
		return lang_fn_report(p, t.loc, failed);
	*out = f;
	return true;
}

static bool iso_function(parser *p, shape_desc *s, const char *what)
{
	const lang_function *f;
	TRY(float_function(p, what, &f));
	s->fn = iso_call, s->fn_ctx = f, s->fn_name = f->name, s->fn_same = iso_same_fn;
	return true;
}

/* contained_by = "contained_by" "{" ( "box" "{" vector, vector "}" | "sphere" "{" vector, float "}" ) "}" */
static bool contained_by(parser *p, shape_desc *s, diag_loc kw)
{
	diag_loc open = lang_peek(p)->loc;
	TRY(lang_expect(p, LTK_LBRACE, "after 'contained_by'"));
	lang_token t = *lang_peek(p);
	diag_loc inner = lang_peek(p)->loc;
	if (t.kind == LTK_KW_BOX) {
		lang_advance(p);
		inner = lang_peek(p)->loc;
		TRY(lang_expect(p, LTK_LBRACE, "after 'box'"));
		dvec3 a, b;
		TRY(lang_vec3(p, "as the box's first corner", &a));
		comma(p);
		TRY(lang_vec3(p, "as the box's second corner", &b));
		s->contained_sphere = false;
		s->box_lo = d3(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z));
		s->box_hi = d3(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z));
		dvec3 e = d3_sub(s->box_hi, s->box_lo);
		if (!(e.x > 0 && e.y > 0 && e.z > 0))
			return lang_error(p, t.loc, "the isosurface's container box is flat: its corners <%g, %g, %g> and <%g, %g, "
						    "%g> share a coordinate",
					  a.x, a.y, a.z, b.x, b.y, b.z);
	} else if (t.kind == LTK_KW_SPHERE) {
		lang_advance(p);
		inner = lang_peek(p)->loc;
		TRY(lang_expect(p, LTK_LBRACE, "after 'sphere'"));
		TRY(lang_vec3(p, "as the sphere's centre", &s->box_lo));
		comma(p);
		TRY(lang_float(p, "as the sphere's radius", &s->sphere_r));
		s->contained_sphere = true;
		if (!(s->sphere_r > 0))
			return lang_error(p, t.loc, "the isosurface's container sphere needs a radius > 0, found %g", s->sphere_r);
	} else
		return lang_error_found(p, "expected 'box' or 'sphere' in 'contained_by'");
	(void)kw;
	return lang_expect_close(p, inner, t.kind == LTK_KW_BOX ? "box" : "sphere") &&
	       lang_expect_close(p, open, "contained_by");
}

/* isosurface = "isosurface" "{" ( "function" "{" expression "}" | function_name )
 *              { "contained_by" "{" ... "}" | "threshold" float | "accuracy" float
 *              | "max_gradient" float | "evaluate" float, float, float | "open"
 *              | "max_trace" float | "all_intersections" } ...: POV-Ray 3.7's Parse_Isosurface,
 *              its defaults (a box from <-1,-1,-1> to <1,1,1>, threshold 0, accuracy 0.001,
 *              max_gradient 1.1, max_trace 1). */
static bool isosurface(parser *p, shape_desc *s, diag_loc kw)
{
	s->box_lo = d3(-1, -1, -1), s->box_hi = d3(1, 1, 1);
	s->threshold = 0, s->iso_accuracy = 0.001, s->max_gradient = 1.1, s->max_trace = 1;
	if (lang_peek(p)->kind != LTK_KW_FUNCTION && !lang_word_is(lang_peek(p), "contained_by"))
		TRY(iso_function(p, s, "the isosurface's function"));
	for (;;) {
		lang_token t = *lang_peek(p);
		if (t.kind == LTK_KW_FUNCTION) {
			if (s->fn)
				return lang_error(p, t.loc, "the isosurface has a second function (the first is '%s')", s->fn_name);
			TRY(iso_function(p, s, "the isosurface's function"));
		} else if (accept_word(p, "contained_by")) {
			TRY(contained_by(p, s, t.loc));
		} else if (accept_word(p, "threshold")) {
			TRY(lang_float(p, "after 'threshold'", &s->threshold));
		} else if (accept_word(p, "accuracy")) {
			TRY(lang_float(p, "after 'accuracy'", &s->iso_accuracy));
			if (!(s->iso_accuracy > 0))
				return lang_error(p, t.loc, "an isosurface's accuracy must be > 0, found %g", s->iso_accuracy);
		} else if (accept_word(p, "max_gradient")) {
			TRY(lang_float(p, "after 'max_gradient'", &s->max_gradient));
			if (!(s->max_gradient > 0))
				return lang_error(p, t.loc, "an isosurface's max_gradient must be > 0, found %g", s->max_gradient);
		} else if (accept_word(p, "evaluate")) {
			TRY(lang_float(p, "as evaluate's first value", &s->evaluate[0]));
			comma(p);
			TRY(lang_float(p, "as evaluate's second value", &s->evaluate[1]));
			comma(p);
			TRY(lang_float(p, "as evaluate's third value", &s->evaluate[2]));
			s->has_evaluate = true;
		} else if (accept_word(p, "open")) {
			s->open = true;
		} else if (accept_word(p, "max_trace")) {
			double m;
			TRY(lang_float(p, "after 'max_trace'", &m));
			s->max_trace = m < 1 ? 1 : m > 1e6 ? 1000000 : (int)m;
		} else if (accept_word(p, "all_intersections")) {
			s->all_intersections = true;
		} else
			break;
	}
	if (!s->fn)
		return lang_error(p, kw, "an isosurface needs a function: 'function { ... }'");
	return true;
}

/* parametric = "parametric" "{" function function function vector ","? vector
 *              { "contained_by" "{" ... "}" | "max_gradient" float | "accuracy" float
 *              | "precompute" float [ "x" ] [ ","? "y" ] [ ","? "z" ] } ...: POV-Ray 3.7's
 *              Parse_Parametric and its defaults (a box from <-1,-1,-1> to <1,1,1>, max_gradient 1,
 *              accuracy 0.001); the functions give x, y and z of (u, v). */
static bool parametric(parser *p, shape_desc *s, diag_loc kw)
{
	static const char *const which[] = {"the parametric's x function", "the parametric's y function",
					    "the parametric's z function"};
	s->box_lo = d3(-1, -1, -1), s->box_hi = d3(1, 1, 1);
	s->max_gradient = 1, s->iso_accuracy = 0.001;
	for (int k = 0; k < 3; k++) {
		if (lang_peek(p)->kind != LTK_KW_FUNCTION)
			return lang_error_found(p, "expected 'function { ... }' as %s (a parametric takes three)", which[k]);
		const lang_function *f;
		TRY(float_function(p, which[k], &f));
		s->fn_ctxs[k] = f;
	}
	s->fn = iso_call, s->fn_ctx = s->fn_ctxs[0], s->fn_name = "function";
	dvec3 a, b;
	diag_loc at = lang_peek(p)->loc;
	TRY(lang_vec3(p, "as the parametric's first <u, v> corner", &a));
	comma(p);
	TRY(lang_vec3(p, "as the parametric's second <u, v> corner", &b));
	s->uv_lo[0] = a.x, s->uv_lo[1] = a.y, s->uv_hi[0] = b.x, s->uv_hi[1] = b.y;
	if (!(b.x > a.x) || !(b.y > a.y))
		return lang_error(p, at, "the parametric's <u, v> corners <%g, %g> and <%g, %g> span no area (u2 > u1 and "
					 "v2 > v1 are needed)",
				  a.x, a.y, b.x, b.y);
	for (;;) {
		lang_token t = *lang_peek(p);
		if (accept_word(p, "contained_by")) {
			TRY(contained_by(p, s, t.loc));
		} else if (accept_word(p, "max_gradient")) {
			TRY(lang_float(p, "after 'max_gradient'", &s->max_gradient));
		} else if (accept_word(p, "accuracy")) {
			TRY(lang_float(p, "after 'accuracy'", &s->iso_accuracy));
		} else if (accept_word(p, "precompute")) {
			double depth;
			TRY(lang_float(p, "as precompute's depth", &depth));
			s->precompute_depth = depth < 0 ? 0 : depth > 20 ? 20 : (int)depth;
			for (int k = 0; k < 3; k++) {
				comma(p);
				static const char *const xyz[] = {"x", "y", "z"};
				if (accept_word(p, xyz[k]))
					s->precompute_xyz[k] = true;
			}
		} else
			break;
	}
	(void)kw;
	return true;
}

/* A 4-D vector: <a, b, c, d>. */
static bool vec4(parser *p, const char *what, double out[4])
{
	diag_loc at = lang_peek(p)->loc;
	value v;
	TRY(lang_expr(p, &v));
	if (!(v.kind == VAL_VECTOR || v.kind == VAL_COLOR) || v.n < 4)
		return lang_error(p, at, "expected a 4-D vector <a, b, c, d> %s", what);
	for (int k = 0; k < 4; k++)
		out[k] = v.v[k];
	return true;
}

/* julia_fractal = "julia_fractal" "{" vector4 { "quaternion" | "hypercomplex" | "sqr" | "cube"
 *                 | "max_iteration" float | "precision" float | "slice" vector4 "," float } ...:
 *                 POV-Ray 3.7's Parse_Julia_Fractal and its defaults (quaternion sqr,
 *                 max_iteration 20, precision 20, slice <0, 0, 0, 1>, 0); POV-Ray's other
 *                 functions (exp, reciprocal, sin, ..., pwr) are not supported by circe. */
static bool julia_fractal(parser *p, shape_desc *s, diag_loc kw)
{
	TRY(vec4(p, "as the julia_fractal's parameter", s->julia));
	s->max_iteration = 20, s->precision = 20;
	s->slice[0] = s->slice[1] = s->slice[2] = 0, s->slice[3] = 1, s->slice_dist = 0;
	static const char *const other[] = {"exp",  "reciprocal", "sin",   "asin", "sinh", "asinh", "cos",
					    "acos", "cosh",	  "acosh", "tan",  "atan", "tanh",  "atanh",
					    "ln",   "log",	  "pwr"};
	for (;;) {
		lang_token t = *lang_peek(p);
		if (accept_word(p, "quaternion"))
			s->algebra = 0;
		else if (accept_word(p, "hypercomplex"))
			s->algebra = 1;
		else if (accept_word(p, "sqr"))
			s->jfunc = 0;
		else if (accept_word(p, "cube"))
			s->jfunc = 1;
		else if (accept_word(p, "max_iteration")) {
			double m;
			TRY(lang_float(p, "after 'max_iteration'", &m));
			if (!(m >= 1) || !(m <= 1000))
				return lang_error(p, t.loc, "a julia_fractal's max_iteration must be 1 to 1000, found %g", m);
			s->max_iteration = (int)m;
		} else if (accept_word(p, "precision")) {
			TRY(lang_float(p, "after 'precision'", &s->precision));
			if (!(s->precision >= 1))
				s->precision = 1; /* POV-Ray: "Precision must be at least 1" and uses 1 */
		} else if (accept_word(p, "slice")) {
			TRY(vec4(p, "as the slice's normal", s->slice));
			comma(p);
			TRY(lang_float(p, "as the slice's distance", &s->slice_dist));
			double l = sqrt(s->slice[0] * s->slice[0] + s->slice[1] * s->slice[1] + s->slice[2] * s->slice[2] +
					s->slice[3] * s->slice[3]);
			if (!(l > 0))
				return lang_error(p, t.loc, "the julia_fractal's slice normal is the zero vector");
			if (fabs(s->slice[3]) < 1e-9 * l)
				return lang_error(p, t.loc, "a julia_fractal slice whose normal has no fourth component is not "
							    "supported by circe");
			for (int k = 0; k < 4; k++)
				s->slice[k] /= l;
			s->slice_dist /= l;
		} else {
			for (size_t k = 0; k < sizeof other / sizeof *other; k++)
				if (lang_word_is(&t, other[k]))
					return lang_error(p, t.loc, "julia_fractal's '%.*s' is not supported by circe (sqr and cube are)",
							  (int)t.len, t.text);
			break;
		}
	}
	(void)kw;
	return true;
}

scene_geom *lang_pov_shape(parser *p, int kind, diag_loc kw, lang_xform_item_fn xf_item)
{
	shape_desc *s = new_desc(p, (shape_kind)kind);
	if (!s)
		return NULL;
	bool ok;
	switch ((shape_kind)kind) {
	case SHAPE2_LATHE: ok = lathe(p, s); break;
	case SHAPE2_SOR: ok = sor(p, s); break;
	case SHAPE2_PRISM: ok = prism(p, s, kw); break;
	case SHAPE2_SPHERE_SWEEP: ok = sphere_sweep(p, s); break;
	case SHAPE2_BLOB: ok = blob(p, s, kw, xf_item); break;
	case SHAPE2_BICUBIC: ok = bicubic_patch(p, s); break;
	case SHAPE2_ISOSURFACE: ok = isosurface(p, s, kw); break;
	case SHAPE2_PARAMETRIC: ok = parametric(p, s, kw); break;
	case SHAPE2_JULIA: ok = julia_fractal(p, s, kw); break;
	default: ok = text(p, s); break;
	}
	if (!ok)
		return NULL;
	scene_geom *g = scene_new_geom(p->sc, SHAPE_POV, kw);
	if (!g) {
		lang_error(p, kw, "out of memory");
		return NULL;
	}
	g->u.pov = s;
	return g;
}
