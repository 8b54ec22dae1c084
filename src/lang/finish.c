/* finish.c - the items of POV-Ray's finish block and POV-Ray's fog statement, read into the IR
 * as POV-Ray 3.7 means them (parser_materials.cpp Parse_Finish, texture.cpp's defaults);
 * stmt.c opens and closes the finish block, this file reads what stands inside. What each item
 * becomes in circe's physically based model is doc/language.md's "Finishes" table. */
#include "lang/parser.h"

#include <math.h>
#include <string.h>

/* The finish words circe reads but does not render, each warned about once per scene
 * (parser.finish_warned, one bit each). */
enum {
	WARN_BRILLIANCE = 1u << 0,
	WARN_CRAND = 1u << 1,
	WARN_IRID = 1u << 2,
	WARN_DIFFUSE_BACK = 1u << 3,
	WARN_REFL_EXPONENT = 1u << 4,
	WARN_OLD_REFRACTION = 1u << 5,
	WARN_USE_ALPHA = 1u << 6,
	WARN_FOG_TURBULENCE = 1u << 7,
};

static bool accept_word(parser *p, const char *word)
{
	if (!lang_word_is(lang_peek(p), word))
		return false;
	lang_advance(p);
	return true;
}

static void warn_once(parser *p, unsigned bit, diag_loc loc, const char *msg)
{
	if (p->finish_warned & bit)
		return;
	p->finish_warned |= bit;
	diag_warning(p->d, loc, "%s (said once per scene)", msg);
}

/* True when an optional float follows (metallic [F], fresnel [F]): a number, a sign, a
 * parenthesis, a boolean word (fresnel on) or a name declared as a float; not the next item's
 * keyword nor '}'. */
static bool float_follows(parser *p)
{
	const lang_token *t = lang_peek(p);
	if (t->kind == LTK_NUMBER || t->kind == LTK_LPAREN || t->kind == LTK_MINUS || t->kind == LTK_PLUS ||
	    t->kind == LTK_KW_ON || t->kind == LTK_KW_OFF || t->kind == LTK_KW_TRUE || t->kind == LTK_KW_FALSE ||
	    t->kind == LTK_KW_YES || t->kind == LTK_KW_NO)
		return true;
	if (t->kind != LTK_IDENT)
		return false;
	const symbol *s = lang_lookup(p, t->text, t->len);
	return s && s->val.kind == VAL_FLOAT;
}

static bool at_least(parser *p, diag_loc loc, const char *what, double x, double lo)
{
	if (x >= lo && isfinite(x))
		return true;
	return lang_error(p, loc, "%s must be >= %g, found %g", what, lo, x);
}

/* A float in [0, 1] after the keyword at loc (the error points at the keyword). */
static bool unit_float(parser *p, diag_loc loc, const char *what, double *x)
{
	char ctx[64];
	snprintf(ctx, sizeof ctx, "after '%s'", what);
	TRY(lang_float(p, ctx, x));
	if (*x >= 0 && *x <= 1)
		return true;
	return lang_error(p, loc, "finish %s must be in [0, 1], found %g", what, *x);
}

/* An emitted colour (ambient, emission): a radiance, clamped into [0, inf) with a warning. */
static bool glow_color(parser *p, const char *what, vec3 *c)
{
	diag_loc loc = lang_peek(p)->loc;
	char ctx[64];
	snprintf(ctx, sizeof ctx, "after '%s'", what);
	return lang_color(p, ctx, c) && scene_color_finalise(p->sc, p->d, loc, what, SCENE_COLOR_RADIANCE, c);
}

/* reflection_body = colour [ "," ] [ colour ] { "fresnel" [ float ] | "falloff" float
 *                   | "exponent" float | "metallic" [ float ] }   (inside braces)
 * reflection = "reflection" ( colour | "{" reflection_body "}" ) */
static bool reflection(parser *p, scene_finish *f)
{
	diag_loc open = lang_peek(p)->loc;
	if (!lang_accept(p, LTK_LBRACE)) { /* the old form: one colour, falloff 1 */
		TRY(lang_color(p, "after 'reflection'", &f->refl_max));
		scene_color_clamp(&f->refl_max, SCENE_COLOR_REFLECTANCE);
		f->refl_min = f->refl_max;
		f->refl_falloff = 1.0f;
		return true;
	}
	TRY(lang_color(p, "as the reflection colour", &f->refl_min));
	lang_accept(p, LTK_COMMA);
	f->refl_max = f->refl_min;
	lang_tok k = lang_peek(p)->kind;
	if (float_follows(p) || lang_colour_word(k) || k == LTK_LT || k == LTK_IDENT)
		TRY(lang_color(p, "as the second reflection colour", &f->refl_max));
	scene_color_clamp(&f->refl_min, SCENE_COLOR_REFLECTANCE);
	scene_color_clamp(&f->refl_max, SCENE_COLOR_REFLECTANCE);
	for (;;) {
		diag_loc loc = lang_peek(p)->loc;
		double x = 1.0;
		if (lang_accept(p, LTK_RBRACE))
			return true;
		if (accept_word(p, "fresnel")) {
			if (float_follows(p))
				TRY(lang_float(p, "after 'fresnel'", &x));
			f->refl_fresnel = x != 0;
		} else if (lang_accept(p, LTK_KW_FALLOFF)) {
			TRY(lang_float(p, "after 'falloff'", &x) && at_least(p, loc, "reflection falloff", x, 0));
			f->refl_falloff = (float)x;
		} else if (accept_word(p, "exponent")) {
			TRY(lang_float(p, "after 'exponent'", &x));
			warn_once(p, WARN_REFL_EXPONENT, loc,
				  "the reflection's exponent is ignored: circe's reflection is linear");
		} else if (accept_word(p, "metallic")) {
			if (float_follows(p))
				TRY(lang_float(p, "after 'metallic'", &x));
			TRY(at_least(p, loc, "reflection metallic", x, 0));
			f->refl_metallic = (float)fmin(x, 1.0);
		} else {
			return lang_error_found(p, "expected fresnel, falloff, exponent, metallic or '}' to close "
						   "'reflection' (opened at line %u)",
						open.line);
		}
	}
}

/* irid = "irid" "{" float { "thickness" float | "turbulence" vector } "}": read and ignored. */
static bool irid(parser *p, diag_loc kw)
{
	diag_loc open = lang_peek(p)->loc;
	double x;
	dvec3 v;
	TRY(lang_expect(p, LTK_LBRACE, "after 'irid'") && lang_float(p, "after 'irid {'", &x));
	for (;;) {
		if (accept_word(p, "thickness"))
			TRY(lang_float(p, "after 'thickness'", &x));
		else if (accept_word(p, "turbulence"))
			TRY(lang_vec3(p, "after 'turbulence'", &v));
		else
			break;
	}
	warn_once(p, WARN_IRID, kw, "'irid' is ignored: circe has no thin-film iridescence");
	return lang_expect_close(p, open, "irid");
}

/* subsurface = "subsurface" "{" { "translucency" colour | "anisotropy" colour } "}"
 * POV-Ray 3.7's (parser_materials.cpp Parse_Finish): translucency is 1 / sigma_s' in mm per
 * channel (a float is grey); anisotropy is read and, as POV-Ray's trace.cpp does (g = 0), not used. */
static bool subsurface(parser *p, scene_finish *f, diag_loc kw)
{
	diag_loc open = lang_peek(p)->loc;
	TRY(lang_expect(p, LTK_LBRACE, "after 'subsurface'"));
	bool has_t = false;
	for (;;) {
		diag_loc loc = lang_peek(p)->loc;
		vec3 c;
		if (lang_accept(p, LTK_RBRACE))
			break;
		if (accept_word(p, "translucency")) {
			TRY(lang_color(p, "after 'translucency'", &c));
			if (!(c.x > 0 && c.y > 0 && c.z > 0 && isfinite(c.x) && isfinite(c.y) && isfinite(c.z)))
				return lang_error(p, loc, "subsurface translucency must be > 0 mm in every channel, found "
							  "<%g, %g, %g> (0 is no subsurface transport: leave 'subsurface' out)",
						  c.x, c.y, c.z);
			f->translucency_mm = c;
			has_t = true;
		} else if (accept_word(p, "anisotropy")) {
			TRY(lang_color(p, "after 'anisotropy'", &c));
		} else {
			return lang_error_found(p, "expected translucency, anisotropy or '}' to close 'subsurface' "
						   "(opened at line %u)",
						open.line);
		}
	}
	if (!has_t && !f->subsurface)
		return lang_error(p, kw, "a finish's subsurface needs its 'translucency' (mm, > 0)");
	f->subsurface = true;
	f->subsurface_loc = kw;
	return true;
}

/* The highlight items: specular, roughness, phong, phong_size, metallic. */
static bool highlight_item(parser *p, scene_material *m, lang_finish_state *st, bool *matched)
{
	lang_token t = *lang_peek(p);
	double x = 1.0;
	*matched = true;
	if (t.kind == LTK_KW_SPECULAR) {
		lang_advance(p);
		st->specular_albedo = accept_word(p, "albedo");
		TRY(lang_float(p, "after 'specular'", &x) && at_least(p, t.loc, "finish specular", x, 0));
		m->specular = (float)x;
	} else if (t.kind == LTK_KW_ROUGHNESS) {
		lang_advance(p);
		TRY(unit_float(p, t.loc, "roughness", &x));
		m->roughness = (float)x;
	} else if (accept_word(p, "phong")) {
		st->phong_albedo = accept_word(p, "albedo");
		TRY(lang_float(p, "after 'phong'", &x) && at_least(p, t.loc, "finish phong", x, 0));
		m->finish.phong = (float)x;
	} else if (accept_word(p, "phong_size")) {
		TRY(lang_float(p, "after 'phong_size'", &x) && at_least(p, t.loc, "finish phong_size", x, 0));
		m->finish.phong_size = (float)x;
	} else if (accept_word(p, "metallic")) {
		if (float_follows(p))
			TRY(lang_float(p, "after 'metallic'", &x));
		TRY(at_least(p, t.loc, "finish metallic", x, 0));
		m->finish.metallic = (float)fmin(x, 1.0);
	} else {
		*matched = false;
	}
	return true;
}

/* The items read and dropped with a warning: crand, irid, reflection_exponent, use_alpha and
 * the old finish-level refraction and caustics. */
static bool ignored_item(parser *p, bool *matched)
{
	diag_loc loc = lang_peek(p)->loc;
	double x;
	*matched = true;
	if (accept_word(p, "crand")) {
		TRY(lang_float(p, "after 'crand'", &x));
		warn_once(p, WARN_CRAND, loc, "'crand' is ignored: circe's Monte Carlo noise is its own graininess");
	} else if (accept_word(p, "irid")) {
		TRY(irid(p, loc));
	} else if (accept_word(p, "reflection_exponent")) {
		TRY(lang_float(p, "after 'reflection_exponent'", &x));
		warn_once(p, WARN_REFL_EXPONENT, loc, "the reflection's exponent is ignored: circe's reflection is linear");
	} else if (accept_word(p, "use_alpha")) {
		if (float_follows(p))
			TRY(lang_float(p, "after 'use_alpha'", &x));
		warn_once(p, WARN_USE_ALPHA, loc, "'use_alpha' is ignored");
	} else if (accept_word(p, "refraction") || accept_word(p, "caustics")) {
		TRY(lang_float(p, "after the finish's old refraction item", &x));
		warn_once(p, WARN_OLD_REFRACTION, loc,
			  "a finish's 'refraction' and 'caustics' are ignored: circe refracts by the interior's ior");
	} else {
		*matched = false;
	}
	return true;
}

bool lang_finish_item(parser *p, scene_material *m, lang_finish_state *st, bool *matched)
{
	lang_token t = *lang_peek(p);
	scene_finish *f = &m->finish;
	double x;
	*matched = true;
	if (t.kind == LTK_KW_DIFFUSE) {
		lang_advance(p);
		f->diffuse_albedo = accept_word(p, "albedo"); /* POV-Ray's adjustment (b + 1) / 2 (build) */
		/* Above 1 as POV-Ray allows (soft.pov's 1.5): the BSDF scales its lobes' sum to 1. */
		TRY(lang_float(p, "after 'diffuse'", &x) && at_least(p, t.loc, "finish diffuse", x, 0));
		m->diffuse = (float)x;
		if (lang_accept(p, LTK_COMMA)) {
			TRY(lang_float(p, "as the backside diffuse", &x));
			if (x != 0)
				warn_once(p, WARN_DIFFUSE_BACK, t.loc,
					  "the backside diffuse is ignored: circe lights a surface from its side only");
		}
	} else if (accept_word(p, "ambient")) {
		TRY(glow_color(p, "ambient", &f->ambient));
		f->has_ambient = true;
	} else if (t.kind == LTK_KW_EMISSION) {
		lang_advance(p);
		TRY(glow_color(p, "emission", &f->emission));
	} else if (accept_word(p, "brilliance")) {
		TRY(lang_float(p, "after 'brilliance'", &x) && at_least(p, t.loc, "finish brilliance", x, 0));
		f->brilliance = (float)x;
		if (x != 1)
			warn_once(p, WARN_BRILLIANCE, t.loc,
				  "'brilliance' other than 1: light sources light the diffuse by POV-Ray's cos^b, "
				  "light from other surfaces by a Lambert lobe of its energy (2 / (b + 1))");
	} else if (accept_word(p, "reflection")) {
		TRY(reflection(p, f));
	} else if (accept_word(p, "fresnel")) {
		x = 1.0;
		if (float_follows(p))
			TRY(lang_float(p, "after 'fresnel'", &x));
		f->refl_fresnel = x != 0;
	} else if (accept_word(p, "subsurface")) {
		TRY(subsurface(p, f, t.loc));
	} else if (accept_word(p, "conserve_energy")) {
		f->conserve_energy = true;
	} else if (t.kind == LTK_KW_IOR) { /* POV-Ray's old place for the interior's ior */
		lang_advance(p);
		TRY(lang_float(p, "after 'ior'", &x));
		if (!(x > 0))
			return lang_error(p, t.loc, "ior must be > 0, found %g", x);
		m->ior = (float)x;
	} else {
		TRY(highlight_item(p, m, st, matched));
		if (!*matched)
			TRY(ignored_item(p, matched));
	}
	return true;
}

void lang_finish_end(scene_material *m, const lang_finish_state *st)
{
	/* POV-Ray's albedo forms (Parse_Finish): the value is what the highlight reflects in all. */
	double n = 1.0 / fmax(m->roughness, 1e-6);
	if (st->phong_albedo)
		m->finish.phong *= (m->finish.phong_size + 1.0f) / 2.0f;
	if (st->specular_albedo)
		m->specular = (float)(m->specular * (n + 2.0) / (4.0 * (2.0 - pow(2.0, -n / 2.0))));
	/* As POV-Ray: a Fresnel reflection without two colours reflects from 0 at normal incidence. */
	scene_finish *f = &m->finish;
	if (f->refl_fresnel && f->refl_min.x == f->refl_max.x && f->refl_min.y == f->refl_max.y &&
	    f->refl_min.z == f->refl_max.z)
		f->refl_min = v3s(0.0f);
}

/* ---- fog ----------------------------------------------------------------------------------- */

/* One fog item; false after an error, *matched false when the lookahead is none. */
/* Whether a declared colour comes next (`fog { distance 200 Wheat * .5 }`: POV-Ray's Parse_Fog
 * reads a colour identifier as the fog's colour). */
static bool colour_name_follows(parser *p)
{
	const lang_token *t = lang_peek(p);
	const symbol *s = t->kind == LTK_IDENT ? lang_lookup(p, t->text, t->len) : NULL;
	return s && s->val.kind == VAL_COLOR;
}

static bool fog_item(parser *p, scene_fog *f, bool *matched)
{
	lang_token t = *lang_peek(p);
	double x;
	dvec3 v;
	long n;
	*matched = true;
	if (accept_word(p, "fog_type")) {
		TRY(lang_int(p, "after 'fog_type'", 1, 2, &n));
		f->type = (scene_fog_type)n;
	} else if (accept_word(p, "distance")) {
		TRY(lang_float(p, "after 'distance'", &x));
		if (!(x > 0) || !isfinite(x))
			return lang_error(p, t.loc, "fog distance must be > 0, found %g", x);
		f->distance = x;
	} else if (lang_colour_word(t.kind) || colour_name_follows(p)) {
		TRY(lang_color(p, "as the fog colour", &f->color));
		TRY(scene_color_finalise(p->sc, p->d, t.loc, "fog colour", SCENE_COLOR_RADIANCE, &f->color));
	} else if (accept_word(p, "fog_offset")) {
		TRY(lang_float(p, "after 'fog_offset'", &f->offset));
	} else if (accept_word(p, "fog_alt")) {
		TRY(lang_float(p, "after 'fog_alt'", &x) && at_least(p, t.loc, "fog_alt", x, 0));
		f->alt = x;
	} else if (float_follows(p)) { /* POV-Ray 1.5's form: the distance without its keyword */
		TRY(lang_float(p, "as the fog distance", &x));
		if (!(x > 0) || !isfinite(x))
			return lang_error(p, t.loc, "fog distance must be > 0, found %g", x);
		f->distance = x;
	} else if (t.kind == LTK_KW_ROTATE) { /* turns up, as POV-Ray's Parse_Fog */
		lang_advance(p);
		TRY(lang_vec3(p, "after 'rotate'", &v));
		xform r = xform_rotate(v);
		f->up = d3_normalize(xform_vector(&r, f->up));
	} else if (t.kind == LTK_KW_UP) {
		lang_advance(p);
		TRY(lang_vec3(p, "after 'up'", &v));
		if (!(d3_length(v) > 0))
			return lang_error(p, t.loc, "the fog's up must not be the zero vector");
		f->up = d3_normalize(v);
	} else if (accept_word(p, "turbulence") || accept_word(p, "omega") || accept_word(p, "lambda") ||
		   accept_word(p, "octaves") || accept_word(p, "turb_depth")) {
		TRY(lang_vec3(p, "after the fog's turbulence item", &v));
		warn_once(p, WARN_FOG_TURBULENCE, t.loc, "the fog's turbulence is ignored: circe's fog is smooth");
	} else {
		*matched = false;
	}
	return true;
}

/* fog = "fog" "{" { "fog_type" ( "1" | "2" ) | [ "distance" ] float | colour
 *       | "fog_offset" float | "fog_alt" float | "up" vector | "rotate" vector
 *       | ( "turbulence" | "omega" | "lambda" | "octaves" | "turb_depth" ) vector } "}" */
bool lang_fog(parser *p)
{
	diag_loc kw = lang_advance(p)->loc, open = lang_peek(p)->loc;
	TRY(lang_expect(p, LTK_LBRACE, "after 'fog'"));
	scene_fog *f = arena_zalloc(&p->sc->arena, 1, sizeof *f);
	if (!f)
		return lang_error(p, kw, "out of memory");
	/* POV-Ray 3.7's defaults (atmosphere.cpp Create_Fog): constant, black, up y, offset 0, alt 0. */
	*f = (scene_fog){.loc = kw, .type = SCENE_FOG_CONSTANT, .up = d3(0, 1, 0)};
	for (;;) {
		if (lang_accept(p, LTK_RBRACE))
			break;
		bool matched;
		TRY(fog_item(p, f, &matched));
		if (!matched)
			return lang_error_found(p, "expected fog_type, distance, a colour, fog_offset, fog_alt, up, rotate, turbulence "
						   "or '}' to close 'fog' (opened at line %u)",
						open.line);
	}
	if (!(f->distance > 0))
		return lang_error(p, kw, "a fog needs its 'distance'");
	f->next = p->sc->fogs;
	p->sc->fogs = f;
	return true;
}
