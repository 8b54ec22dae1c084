/* pigment.c - POV-Ray's pigment and normal bodies beyond one colour, read into a scene_pigment
 * tree: patterns and their arguments, color_map / colour_map / pigment_map, the block patterns'
 * lists of colours or pigments, image_map and bump_map, turbulence, waves, warps and transforms,
 * a normal's amount. The pattern words
 * are POV-Ray reserved words that are not circe keywords (they lex as LTK_UNSUPPORTED), so they
 * are matched here by their spelling: the keyword table stays as it is. */
#include "lang/pigment.h"

#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

enum {
	MAX_WARPS = 64, /* warps and transforms of one pigment (consecutive transforms are one) */
	MAX_DF3_VOXELS = 1 << 26 /* a density_file's voxels: 256 MiB as floats */
};

/* A pigment being read: the node and the warps and entries it will own. */
typedef struct pig_build {
	scene_pigment pg;
	scene_warp warps[MAX_WARPS];
	uint32_t n_warps;
	int depth;   /* pigments around this one */
	bool normal; /* a normal { }: an amount after the pattern, bump_size, accuracy */
	bool density; /* a media's density { }: its map may be written density_map */
	bool default_normal; /* #default's normal: it may have no pattern (only its amount, for later ones) */
	/* A patterned texture's (lang_texture_pattern): the texture reader, and the entries' textures. */
	lang_texture_fn tex;
	const scene_material **tex_mats;
	uint32_t n_tex;
} pig_build;

static bool body(parser *p, const scene_pigment *base, lang_tok close, diag_loc open, int depth, bool normal,
		 const scene_pigment **out);

static bool peek_word(parser *p, const char *w) { return lang_word_is(lang_peek(p), w); }

static bool accept_word(parser *p, const char *w)
{
	if (!peek_word(p, w))
		return false;
	lang_advance(p);
	return true;
}

static scene_pattern_kind peek_pattern(parser *p)
{
	lang_token *t = lang_peek(p);
	if (t->kind != LTK_UNSUPPORTED && !(t->kind >= LANG_FIRST_KEYWORD && t->kind < LANG_FIRST_DIRECTIVE))
		return SCENE_PAT_COUNT;
	return scene_pattern_find(t->text, t->len);
}

/* The declared symbol the lookahead names when it is of kind k, else NULL. */
static const symbol *peek_declared(parser *p, value_kind k)
{
	lang_token *t = lang_peek(p);
	if (t->kind != LTK_IDENT)
		return NULL;
	const symbol *s = lang_lookup(p, t->text, t->len);
	return s && s->val.kind == k ? s : NULL;
}

static bool starts_colour(parser *p) { return lang_colour_word(lang_peek(p)->kind) || peek_declared(p, VAL_COLOR); }

static const char *const modifier_words[] = {
	"color_map",   "colour_map",	"pigment_map",	 "turbulence", "octaves",      "omega",	       "lambda",
	"frequency",   "phase",		"ramp_wave",	 "triangle_wave", "sine_wave", "scallop_wave", "cubic_wave",
	"poly_wave",   "warp",		"brick_size",	 "mortar",     "agate_turb",   "control0",     "control1",
	"quick_color", "quick_colour",	"noise_generator", "uv_mapping"};

static bool starts_modifier(parser *p)
{
	lang_tok k = lang_peek(p)->kind;
	if (k == LTK_KW_TRANSLATE || k == LTK_KW_ROTATE || k == LTK_KW_SCALE || k == LTK_KW_MATRIX ||
	    k == LTK_KW_TRANSFORM)
		return true;
	for (size_t i = 0; i < sizeof modifier_words / sizeof *modifier_words; i++)
		if (peek_word(p, modifier_words[i]))
			return true;
	return false;
}

bool lang_pigment_quick_colour(parser *p, bool *matched)
{
	*matched = accept_word(p, "quick_color") || accept_word(p, "quick_colour");
	double c[5];
	return !*matched || lang_color5(p, "after 'quick_color'", c); /* a preview colour: circe has no preview */
}

bool lang_pigment_starts(parser *p, bool has_base)
{
	if (peek_pattern(p) != SCENE_PAT_COUNT || lang_peek(p)->kind == LTK_KW_IMAGE_MAP || peek_word(p, "uv_mapping"))
		return true;
	return has_base && starts_modifier(p);
}

static void set5(float out[5], const double c[5])
{
	for (int i = 0; i < 5; i++)
		out[i] = (float)c[i];
}

/* A plain colour node (a declared pigment of one colour, an entry's colour). */
static const scene_pigment *plain(parser *p, const float c[5], diag_loc loc)
{
	scene_pigment *pg = arena_zalloc(&p->sc->arena, 1, sizeof *pg);
	if (!pg) {
		lang_error(p, loc, "out of memory");
		return NULL;
	}
	*pg = scene_pigment_defaults(SCENE_PAT_PLAIN, loc);
	memcpy(pg->color, c, sizeof pg->color);
	return pg;
}

/* The tree of a declared pigment (its part record's pigment, or a plain node of its colour). */
static const scene_pigment *declared_tree(parser *p, const scene_material *m, diag_loc loc)
{
	if (m->pigment)
		return m->pigment;
	float c[5] = {m->color.x, m->color.y, m->color.z, 0.0f, 0.0f};
	return plain(p, c, loc);
}

/* The node b holds, with its warps, copied into the arena. */
static const scene_pigment *finish_build(parser *p, pig_build *b, diag_loc loc)
{
	scene_pigment *pg = arena_zalloc(&p->sc->arena, 1, sizeof *pg);
	scene_warp *w = b->n_warps ? arena_zalloc(&p->sc->arena, b->n_warps, sizeof *w) : NULL;
	if (!pg || (b->n_warps && !w)) {
		lang_error(p, loc, "out of memory");
		return NULL;
	}
	if (b->n_warps)
		memcpy(w, b->warps, b->n_warps * sizeof *w);
	*pg = b->pg;
	pg->warps = w, pg->n_warps = b->n_warps;
	return pg;
}

static bool push_warp(parser *p, pig_build *b, const scene_warp *w)
{
	if (b->n_warps == MAX_WARPS)
		return lang_error(p, w->loc, "too many warps and transforms in one pigment (limit is %d)", MAX_WARPS);
	b->warps[b->n_warps++] = *w;
	return true;
}

/* A transform after the warps: composed into the last warp when that is a transform too. */
static bool push_transform(parser *p, pig_build *b, const xform *xf, diag_loc loc)
{
	if (b->n_warps && b->warps[b->n_warps - 1].kind == SCENE_WARP_TRANSFORM) {
		scene_warp *last = &b->warps[b->n_warps - 1];
		last->xf = xform_then(last->xf, *xf);
		return true;
	}
	scene_warp w = {.kind = SCENE_WARP_TRANSFORM, .loc = loc, .xf = *xf};
	return push_warp(p, b, &w);
}

static void begin_from(pig_build *b, const scene_pigment *base)
{
	b->pg = *base;
	b->n_warps = base->n_warps < MAX_WARPS ? base->n_warps : MAX_WARPS;
	if (b->n_warps) /* a base without warps has none to copy (and warps may be NULL) */
		memcpy(b->warps, base->warps, b->n_warps * sizeof *b->warps);
}

/* A pig_build on the heap (its warps make it too big to nest on the stack). */
static pig_build *new_build(parser *p, diag_loc loc)
{
	pig_build *b = mem_calloc(1, sizeof *b);
	if (!b)
		lang_error(p, loc, "out of memory");
	return b;
}

const scene_pigment *lang_pigment_moved(parser *p, const scene_pigment *pg, const xform *xf, diag_loc loc)
{
	pig_build *b = new_build(p, loc);
	if (!b)
		return NULL;
	begin_from(b, pg);
	const scene_pigment *out = push_transform(p, b, xf, loc) ? finish_build(p, b, loc) : NULL;
	mem_free(b);
	return out;
}

/* ---- maps and lists ------------------------------------------------------------------------ */

/* A patterned texture's entry: a texture (`texture { }` in a list, a texture body up to ']' in a
 * texture_map), kept in b->tex_mats; the entry's pigment is the texture's. */
static bool texture_entry(parser *p, pig_build *b, lang_tok close, scene_map_entry *e)
{
	diag_loc at = lang_peek(p)->loc;
	const scene_material *m;
	TRY(b->tex(p, close, &m));
	if (m->kind != MAT_TEXTURE)
		return lang_error(p, at, "a patterned texture's entries are POV-Ray textures, but this one is a %s material",
				  scene_material_kind_name(m->kind));
	b->tex_mats[b->n_tex++] = m;
	return (e->pigment = declared_tree(p, m, at)) != NULL;
}

/* An entry's colour, or pigment: "pigment" "{" body "}" or (in a pigment_map) a body up to ']'. */
static bool entry_item(parser *p, pig_build *b, bool pigment_body, lang_tok close, scene_map_entry *e)
{
	diag_loc at = lang_peek(p)->loc;
	if (b->tex) {
		if (!pigment_body && lang_peek(p)->kind != LTK_KW_TEXTURE)
			return lang_error_found(p, "expected a texture in the patterned texture's list");
		return texture_entry(p, b, pigment_body ? close : LTK_RBRACE, e);
	}
	/* A normal's entry starts from #default's normal (its pattern, amount and transforms), as
	 * POV-Ray's Parse_BlendMapData and Parse_BlendListData copy Default_Texture->Tnormal. */
	const scene_pigment *normal_base = b->normal && p->default_tex ? p->default_tex->normal : NULL;
	if (!pigment_body && b->normal && peek_word(p, "normal")) { /* a normal's block list: normal { body } */
		lang_advance(p);
		diag_loc open = lang_peek(p)->loc;
		TRY(lang_expect(p, LTK_LBRACE, "after 'normal'"));
		return body(p, normal_base, LTK_RBRACE, open, b->depth + 1, true, &e->pigment);
	}
	if (!pigment_body && lang_peek(p)->kind == LTK_KW_PIGMENT) {
		diag_loc open;
		lang_advance(p);
		open = lang_peek(p)->loc;
		TRY(lang_expect(p, LTK_LBRACE, "after 'pigment'"));
		return body(p, NULL, LTK_RBRACE, open, b->depth + 1, false, &e->pigment);
	}
	if (pigment_body) /* a pigment_map's pigment, or a normal_map's normal */
		return body(p, normal_base, close, at, b->depth + 1, b->normal, &e->pigment);
	double c[5];
	TRY(lang_color5(p, "in the map", c));
	set5(e->color, c);
	return true;
}

/* map_entry = "[" float [ "," float ] ( colour [ colour ] | pigment_body ) "]" */
static bool map_entry(parser *p, pig_build *b, bool pigments, scene_map_entry *e, uint32_t *n, const char *what)
{
	diag_loc open = lang_advance(p)->loc; /* '[' */
	double v = 1.0, v2;
	bool two;
	lang_tok k = lang_peek(p)->kind;
	bool weight_follows = k == LTK_NUMBER || k == LTK_LPAREN || k == LTK_MINUS || k == LTK_PLUS ||
			      peek_declared(p, VAL_FLOAT);
	/* average's weight is optional, 1 when left out (POV-Ray's Parse_Blend_Map: Allow_Float(1.0)) */
	if (b->pg.kind != SCENE_PAT_AVERAGE || weight_follows)
		TRY(lang_float(p, "as the map entry's value", &v));
	/* [v colour], [v, colour], or the old form [v1 v2 colour1 colour2] (commas optional) */
	lang_accept(p, LTK_COMMA);
	two = !pigments && !starts_colour(p) && lang_peek(p)->kind != LTK_KW_PIGMENT && lang_peek(p)->kind != LTK_LT;
	if (two)
		TRY(lang_float(p, "as the map entry's second value", &v2));
	if (*n + (two ? 2 : 1) > SCENE_PIGMENT_MAX_ENTRIES)
		return lang_error(p, open, "too many entries in '%s' (limit is %d)", what, SCENE_PIGMENT_MAX_ENTRIES);
	scene_map_entry *a = &e[(*n)++];
	*a = (scene_map_entry){.value = v};
	if (pigments) {
		TRY(entry_item(p, b, true, LTK_RBRACKET, a));
		return true; /* the body read its ']' */
	}
	if (two)
		lang_accept(p, LTK_COMMA);
	TRY(entry_item(p, b, false, LTK_RBRACKET, a));
	if (two) { /* POV-Ray's old form: colour1 at v1, colour2 at v2 */
		scene_map_entry *c = &e[(*n)++];
		*c = (scene_map_entry){.value = v2};
		lang_accept(p, LTK_COMMA);
		TRY(entry_item(p, b, false, LTK_RBRACKET, c));
	}
	return lang_expect(p, LTK_RBRACKET, "to close the map entry");
}

/* color_map = ( "color_map" | "colour_map" | "pigment_map" ) "{" map_entry { map_entry } "}" */
static bool map_block(parser *p, pig_build *b, bool pigments)
{
	const char *what = !pigments ? "color_map" : b->tex ? "texture_map" : b->normal ? "normal_map" : "pigment_map";
	if (b->pg.kind == SCENE_PAT_AVERAGE && !pigments)
		return lang_error(p, lang_peek(p)->loc, "'average' takes a %s, not a color_map (as POV-Ray)",
				  b->normal ? "normal_map" : "pigment_map");
	diag_loc kw = lang_advance(p)->loc, open = lang_peek(p)->loc;
	char ctx[32];
	snprintf(ctx, sizeof ctx, "after '%s'", what);
	TRY(lang_expect(p, LTK_LBRACE, ctx));
	const symbol *s = peek_declared(p, VAL_COLOR_MAP);
	if (s) { /* color_map { Name } */
		const scene_pigment *held = s->val.mat->pigment;
		lang_advance(p);
		if (held->pigment_map != pigments)
			return lang_error(p, p->prev.loc, "'%.*s' is a %s, not a %s", (int)p->prev.len, p->prev.text,
					  held->pigment_map ? "pigment_map" : "color_map", what);
		TRY(lang_expect_close(p, open, what));
		b->pg.entries = held->entries, b->pg.n_entries = held->n_entries;
		b->pg.pigment_map = pigments, b->pg.block_list = false;
		return true;
	}
	scene_map_entry *e = arena_zalloc(&p->sc->arena, SCENE_PIGMENT_MAX_ENTRIES, sizeof *e);
	if (!e)
		return lang_error(p, kw, "out of memory");
	uint32_t n = 0;
	while (lang_peek(p)->kind == LTK_LBRACKET)
		TRY(map_entry(p, b, pigments, e, &n, what));
	if (!n)
		return lang_error_found(p, "expected '[' (a %s needs at least one entry)", what);
	TRY(lang_expect_close(p, open, what));
	b->pg.entries = e, b->pg.n_entries = n, b->pg.pigment_map = pigments, b->pg.block_list = false;
	return true;
}

/* block_list = [ entry [ "," entry [ "," entry ] ] ]   (checker, brick: 2; hexagon: 3) */
static bool block_list(parser *p, pig_build *b)
{
	int most = scene_pattern_blocks(b->pg.kind);
	lang_tok first = b->tex ? LTK_KW_TEXTURE : LTK_KW_PIGMENT; /* a patterned texture lists textures */
	if (b->normal) { /* a normal's block pattern lists normals: `normal { checker normal {..} normal {..} }` */
		if (!peek_word(p, "normal"))
			return true;
		first = lang_peek(p)->kind;
	} else if ((b->tex || !starts_colour(p)) && lang_peek(p)->kind != first) {
		return true;
	}
	scene_map_entry *e = arena_zalloc(&p->sc->arena, (size_t)most, sizeof *e);
	if (!e)
		return lang_error(p, lang_peek(p)->loc, "out of memory");
	/* The entries not written keep the pattern's defaults (Parse_Blend_List; the build fills them). */
	int n = 0;
	do {
		if (n == most)
			return lang_error(p, lang_peek(p)->loc, "'%s' takes at most %d %s", scene_pattern_name(b->pg.kind),
					  most, b->tex ? "textures" : "colours or pigments");
		e[n].value = n;
		TRY(entry_item(p, b, false, LTK_RBRACE, &e[n]));
		n++;
		lang_accept(p, LTK_COMMA); /* POV-Ray's commas in a list are optional */
	} while ((!b->tex && !b->normal && starts_colour(p)) || (b->normal ? peek_word(p, "normal") : lang_peek(p)->kind == first));
	b->pg.entries = e, b->pg.n_entries = (uint32_t)n, b->pg.block_list = true, b->pg.pigment_map = false;
	return true;
}

/* ---- warps ------------------------------------------------------------------------------- */

/* turbulence's parameters after its amount: { "octaves" int | "omega" float | "lambda" float } */
static bool turb_params(parser *p, scene_turb *t)
{
	for (;;) {
		double x;
		long n;
		if (accept_word(p, "octaves")) {
			TRY(lang_int(p, "after 'octaves'", 1, 10, &n));
			t->octaves = (int)n; /* POV-Ray's limit: 10 */
		} else if (accept_word(p, "omega")) {
			TRY(lang_float(p, "after 'omega'", &x));
			t->omega = x;
		} else if (accept_word(p, "lambda")) {
			TRY(lang_float(p, "after 'lambda'", &x));
			t->lambda = x;
		} else {
			return true;
		}
	}
}

/* "repeat" vector { "offset" vector | "flip" vector }: the vector names one axis and the width. */
static bool warp_repeat(parser *p, scene_warp *w)
{
	dvec3 v;
	diag_loc at = lang_peek(p)->loc;
	TRY(lang_vec3(p, "after 'repeat'", &v));
	int nonzero = (v.x != 0) + (v.y != 0) + (v.z != 0);
	if (nonzero != 1)
		return lang_error(p, at, "'repeat' needs a vector along one axis (x, y or z times the width), found <%g, %g, %g>",
				  v.x, v.y, v.z);
	w->axis = v.x != 0 ? 0 : v.y != 0 ? 1 : 2;
	w->width = fabs(v.x + v.y + v.z);
	w->flip = d3(1, 1, 1);
	for (;;) {
		dvec3 f;
		if (accept_word(p, "offset")) {
			TRY(lang_vec3(p, "after 'offset'", &w->offset));
		} else if (accept_word(p, "flip")) {
			TRY(lang_vec3(p, "after 'flip'", &f));
			w->flip = d3(f.x != 0 ? -1 : 1, f.y != 0 ? -1 : 1, f.z != 0 ? -1 : 1);
		} else {
			return true;
		}
	}
}

/* "black_hole" vector "," float { "strength" float | "falloff" float | "inverse" | "repeat" vector } */
static bool warp_black_hole(parser *p, scene_warp *w)
{
	diag_loc at = lang_peek(p)->loc;
	TRY(lang_vec3(p, "as the black hole's centre", &w->center));
	TRY(lang_expect(p, LTK_COMMA, "after the black hole's centre"));
	TRY(lang_float(p, "as the black hole's radius", &w->radius));
	if (!(w->radius > 0))
		return lang_error(p, at, "the black hole's radius must be > 0, found %g", w->radius);
	w->strength = 1.0, w->falloff = 2.0; /* BlackHoleWarp's defaults */
	for (;;) {
		if (accept_word(p, "strength")) {
			TRY(lang_float(p, "after 'strength'", &w->strength));
		} else if (lang_accept(p, LTK_KW_FALLOFF)) {
			TRY(lang_float(p, "after 'falloff'", &w->falloff));
		} else if (lang_accept(p, LTK_KW_INVERSE)) {
			w->inverse = true;
		} else if (accept_word(p, "repeat")) {
			TRY(lang_vec3(p, "after 'repeat'", &w->repeat));
		} else if (accept_word(p, "turbulence")) { /* POV-Ray's uncertainty of a repeated hole's centre */
			TRY(lang_vec3(p, "after the black hole's 'turbulence'", &w->uncertainty));
		} else {
			return true;
		}
	}
}

/* The mapping warps' options (POV-Ray's Parse_Warp): planar [ vector [ "," ] float ] (the plane's
 * orientation and offset); cylindrical, spherical, toroidal { "orientation" vector | "dist_exp"
 * float | "major_radius" float (toroidal) }; cubic. */
static bool warp_mapping(parser *p, scene_warp *w)
{
	w->orientation = d3(0, 0, 1), w->dist_exp = 0.0, w->major_radius = 1.0, w->plane_offset = 0.0;
	if (w->kind == SCENE_WARP_CUBIC)
		return true;
	if (w->kind == SCENE_WARP_PLANAR) {
		if (lang_peek(p)->kind == LTK_RBRACE)
			return true;
		diag_loc at = lang_peek(p)->loc;
		dvec3 o;
		TRY(lang_vec3(p, "(the orientation of 'planar')", &o));
		if (!(d3_length(o) > 0))
			return lang_error(p, at, "the orientation of a warp is the zero vector");
		w->orientation = d3_normalize(o);
		lang_accept(p, LTK_COMMA);
		return lang_float(p, "as the planar warp's offset", &w->plane_offset);
	}
	for (;;) {
		diag_loc at = lang_peek(p)->loc;
		if (accept_word(p, "orientation")) {
			dvec3 o;
			TRY(lang_vec3(p, "after 'orientation'", &o));
			if (!(d3_length(o) > 0))
				return lang_error(p, at, "the orientation of a warp is the zero vector");
			w->orientation = d3_normalize(o);
		} else if (accept_word(p, "dist_exp")) {
			TRY(lang_float(p, "after 'dist_exp'", &w->dist_exp));
		} else if (w->kind == SCENE_WARP_TOROIDAL && accept_word(p, "major_radius")) {
			TRY(lang_float(p, "after 'major_radius'", &w->major_radius));
		} else {
			return true;
		}
	}
}

/* warp = "warp" "{" ( "turbulence" ( float | vector ) turb_params | "repeat" ... | "black_hole" ...
 *        | "planar" ... | "cylindrical" ... | "spherical" ... | "toroidal" ... | "cubic" ) "}" */
static bool warp_block(parser *p, pig_build *b)
{
	diag_loc kw = lang_advance(p)->loc, open = lang_peek(p)->loc;
	TRY(lang_expect(p, LTK_LBRACE, "after 'warp'"));
	scene_warp w = {.loc = kw};
	if (accept_word(p, "turbulence")) {
		w.kind = SCENE_WARP_TURBULENCE;
		w.turb = (scene_turb){.octaves = 6, .omega = 0.5, .lambda = 2.0};
		TRY(lang_vec3(p, "after 'turbulence'", &w.turb.amount));
		TRY(turb_params(p, &w.turb));
	} else if (accept_word(p, "repeat")) {
		w.kind = SCENE_WARP_REPEAT;
		TRY(warp_repeat(p, &w));
	} else if (accept_word(p, "black_hole")) {
		w.kind = SCENE_WARP_BLACK_HOLE;
		TRY(warp_black_hole(p, &w));
	} else {
		static const struct {
			const char *word;
			scene_warp_kind kind;
		} maps[] = {{"planar", SCENE_WARP_PLANAR},     {"cylindrical", SCENE_WARP_CYLINDRICAL},
			    {"spherical", SCENE_WARP_SPHERICAL}, {"toroidal", SCENE_WARP_TOROIDAL},
			    {"cubic", SCENE_WARP_CUBIC}};
		size_t i = 0;
		while (i < sizeof maps / sizeof maps[0] && !accept_word(p, maps[i].word))
			i++;
		if (i == sizeof maps / sizeof maps[0]) {
			lang_token *t = lang_peek(p);
			if (t->kind == LTK_UNSUPPORTED || (t->kind >= LANG_FIRST_KEYWORD && t->kind < LANG_FIRST_DIRECTIVE))
				return lang_error(p, t->loc, "'warp { %.*s }' is not supported by circe (turbulence, repeat, "
							     "black_hole, planar, cylindrical, spherical, toroidal and cubic are)",
						  (int)t->len, t->text);
			return lang_error_found(p, "expected turbulence, repeat, black_hole, planar, cylindrical, spherical, "
						   "toroidal or cubic in 'warp'");
		}
		w.kind = maps[i].kind;
		TRY(warp_mapping(p, &w));
	}
	TRY(lang_expect_close(p, open, "warp"));
	return push_warp(p, b, &w);
}

/* ---- image_map --------------------------------------------------------------------------- */

static bool image_block(parser *p, pig_build *b, scene_pattern_kind kind);

static bool image_map(parser *p, pig_build *b) { return image_block(p, b, SCENE_PAT_IMAGE); }

/* image_map = "image_map" "{" [ "png" | "jpeg" | "exr" | "hdr" ] string { "map_type" int | "once"
 *             | "interpolate" int | ( "filter" | "transmit" ) "all" float } "}" */
/* image_pattern = "image_pattern" "{" the same head { "map_type" int | "once" | "interpolate" int
 *                 | "use_color" | "use_colour" | "use_index" | "use_alpha" | "gamma" float } "}"
 * (POV-Ray's Parse_Image_Pattern): the image's grey or alpha as a pattern. */
static bool image_block(parser *p, pig_build *b, scene_pattern_kind kind)
{
	const char *what = kind == SCENE_PAT_IMAGE_PATTERN ? "image_pattern"
			   : kind == SCENE_PAT_MATERIAL_MAP  ? "material_map"
			   : b->normal			     ? "bump_map"
							     : "image_map";
	bool pat = kind == SCENE_PAT_IMAGE_PATTERN, mat = kind == SCENE_PAT_MATERIAL_MAP;
	scene_map_entry *e = NULL;
	uint32_t n_tex = 0;
	diag_loc kw = lang_advance(p)->loc, open = lang_peek(p)->loc;
	char ctx[32];
	snprintf(ctx, sizeof ctx, "after '%s'", what);
	TRY(lang_expect(p, LTK_LBRACE, ctx));
	double amount = b->pg.bump_amount, accuracy = b->pg.accuracy; /* a bump_map keeps its normal's amount */
	bool uv = b->pg.uv_mapping;
	b->pg = scene_pigment_defaults(kind, kw);
	b->pg.bump_amount = amount, b->pg.is_normal = b->normal, b->pg.uv_mapping = uv;
	if (pat)
		b->pg.accuracy = accuracy;
	lang_tok k = lang_peek(p)->kind;
	if (k == LTK_KW_PNG || k == LTK_KW_JPEG || k == LTK_KW_EXR || peek_word(p, "hdr"))
		lang_advance(p);
	else if (lang_peek(p)->kind != LTK_STRING)
		return lang_error_found(p, "expected the image type (png, jpeg, exr or hdr) or its file in '%s'", what);
	TRY(lang_asset_path(p, "as the image file", SCENE_ASSET_IMAGE, &b->pg.image));
	for (;;) {
		long n;
		double x;
		if (mat && lang_peek(p)->kind == LTK_RBRACE) {
			if (!n_tex)
				return lang_error_found(p, "expected a texture in 'material_map' (its textures, which the image's "
							   "indices pick)");
			lang_advance(p);
			b->pg.entries = e, b->pg.n_entries = n_tex, b->pg.block_list = true, b->pg.pigment_map = false;
			return true;
		}
		if (lang_accept(p, LTK_RBRACE))
			return true;
		if (mat && lang_peek(p)->kind == LTK_KW_TEXTURE) { /* the textures, by index */
			if (!e && !(e = arena_zalloc(&p->sc->arena, SCENE_PIGMENT_MAX_ENTRIES, sizeof *e)))
				return lang_error(p, kw, "out of memory");
			if (n_tex == SCENE_PIGMENT_MAX_ENTRIES)
				return lang_error(p, lang_peek(p)->loc, "too many textures in 'material_map' (limit is %d)",
						  SCENE_PIGMENT_MAX_ENTRIES);
			e[n_tex].value = n_tex;
			TRY(texture_entry(p, b, LTK_RBRACE, &e[n_tex]));
			n_tex++;
			continue;
		}
		if (accept_word(p, "map_type")) {
			TRY(lang_int(p, "after 'map_type'", 0, 7, &n));
			b->pg.map_type = n == 1 || n == 2 || n == 5 ? (int)n : 0; /* POV-Ray's map_pos: others planar */
		} else if (lang_accept(p, LTK_KW_ONCE)) {
			b->pg.once = true;
		} else if (accept_word(p, "interpolate")) {
			TRY(lang_int(p, "after 'interpolate'", 0, 4, &n));
			b->pg.interpolate = n != 0; /* 2 bilinear, 4 normalised distance: both bilinear here */
		} else if (pat && (accept_word(p, "use_color") || accept_word(p, "use_colour") ||
				   accept_word(p, "use_index"))) {
			b->pg.use_alpha = false; /* circe's images have no palette: the grey of the colour */
		} else if (pat && accept_word(p, "use_alpha")) {
			b->pg.use_alpha = true;
		} else if (!pat && !mat && (lang_peek(p)->kind == LTK_KW_FILTER || lang_peek(p)->kind == LTK_KW_TRANSMIT)) {
			bool filter = lang_advance(p)->kind == LTK_KW_FILTER;
			if (accept_word(p, "all")) {
				TRY(lang_float(p, filter ? "after 'filter all'" : "after 'transmit all'", &x));
				*(filter ? &b->pg.filter_all : &b->pg.transmit_all) = (float)x;
				/* POV-Ray sets every palette entry too: those given before are overwritten */
				*(filter ? &b->pg.pal_filter : &b->pg.pal_transmit) = NULL;
			} else { /* a palette index: POV-Ray's (int)(index + 0.01), then the value */
				diag_loc at = lang_peek(p)->loc;
				TRY(lang_float(p, filter ? "as the palette index after 'filter'" : "as the palette index after 'transmit'", &x));
				int reg = (int)(x + 0.01);
				if (!(x + 0.01 >= 0.0 && reg < 256))
					return lang_error(p, at, "palette index %g after '%s' is out of range (0 to 255)", x,
							  filter ? "filter" : "transmit");
				lang_accept(p, LTK_COMMA);
				TRY(lang_float(p, filter ? "as the palette entry's filter" : "as the palette entry's transmit", &x));
				const float **slot = filter ? &b->pg.pal_filter : &b->pg.pal_transmit;
				if (!*slot) {
					float *tab = arena_alloc(&p->sc->arena, 256, sizeof *tab, sizeof *tab);
					if (!tab)
						return lang_error(p, at, "out of memory");
					for (int i = 0; i < 256; i++)
						tab[i] = NAN;
					*slot = tab;
				}
				((float *)*slot)[reg] = (float)x;
				b->pg.pal_max = reg > b->pg.pal_max ? reg : b->pg.pal_max;
			}
		} else if (b->normal && accept_word(p, "bump_size")) {
			TRY(lang_float(p, "after 'bump_size'", &b->pg.bump_amount));
		} else if (b->normal && (accept_word(p, "use_color") || accept_word(p, "use_colour") ||
					 accept_word(p, "use_index"))) {
			/* circe's images have no palette: the grey of the colour either way */
		} else if (accept_word(p, "gamma")) {
			diag_loc at = p->prev.loc;
			TRY(lang_float(p, "after 'gamma'", &x));
			diag_warning(p->d, at, pat ? "'gamma' of an image_pattern is ignored: circe reads its values as stored, as "
						     "POV-Ray does without gamma"
						   : "'gamma' of an image_map is ignored: circe decodes PNG and JPEG from sRGB "
						     "and reads EXR as linear");
		} else {
			return lang_expect_close(p, open, what);
		}
	}
}

/* ---- pattern heads and modifiers --------------------------------------------------------- */

/* A float when one follows (POV-Ray's Allow_Float), else def. */
static bool optional_float(parser *p, const char *ctx, double def, double *out)
{
	lang_tok k = lang_peek(p)->kind;
	*out = def;
	if (k == LTK_NUMBER || k == LTK_LPAREN || k == LTK_MINUS || k == LTK_PLUS || peek_declared(p, VAL_FLOAT))
		return lang_float(p, ctx, out);
	return true;
}

/* [ "," ] [ lo ] [ "," ] [ hi ] after a slope's or altitude's vector, as POV-Ray's Parse_Pattern
 * reads them: kept as lo and hi - lo, or both 0 (with a warning) when hi = lo != 0. */
static bool slope_range(parser *p, const char *what, double *lo, double *width)
{
	diag_loc at = lang_peek(p)->loc;
	double l, h;
	lang_accept(p, LTK_COMMA);
	TRY(optional_float(p, "as the low end of the range", 0.0, &l));
	lang_accept(p, LTK_COMMA);
	TRY(optional_float(p, "as the high end of the range", 0.0, &h));
	if (h != 0.0 && h == l) {
		diag_warning(p->d, at, "zero %s range, ignored (as POV-Ray does)", what);
		*lo = *width = 0.0;
	} else {
		*lo = l, *width = h - l;
	}
	return true;
}

bool lang_find_data(parser *p, const char *name, const char *const *ext, int n_ext, diag_loc at, const char **out)
{
	const char *from = at.src ? at.src->name : "";
	const char *slash = strrchr(from, '/');
	size_t nl = strlen(name), el = 0;
	for (int e = 0; e < n_ext; e++)
		el = strlen(ext[e]) > el ? strlen(ext[e]) : el;
	*out = NULL;
	for (size_t i = 0; i <= p->opt.n_include_dirs; i++) {
		const char *dir = i == 0 ? from : p->opt.include_dirs[i - 1];
		size_t dl = name[0] == '/' ? 0 : i == 0 ? (slash ? (size_t)(slash - from) : 0) : strlen(dir);
		for (int e = 0; e < n_ext; e++) {
			char *path = arena_alloc(&p->sc->arena, dl + nl + el + 2, 1, 1);
			if (!path)
				return false;
			memcpy(path, dir, dl);
			size_t k = dl;
			if (dl && dir[dl - 1] != '/')
				path[k++] = '/';
			memcpy(path + k, name, nl);
			strcpy(path + k + nl, ext[e]);
			if (access(path, R_OK) == 0) {
				*out = path;
				return true;
			}
		}
		if (name[0] == '/')
			break;
	}
	return true;
}

const char *lang_data_path(parser *p, const char *name, diag_loc at)
{
	static const char *const as_written[] = {""};
	const char *path;
	return lang_find_data(p, name, as_written, 1, at, &path) ? path : NULL;
}

/* POV-Ray 3.7's Read_Density_File: three big-endian 16-bit sizes, then the voxels, x fastest, of
 * 8, 16 or 32 bits (big-endian), whichever the file's length fits; each kept as its integer over
 * its type's largest. */
static bool read_df3(parser *p, scene_pigment *g, const char *path, diag_loc at)
{
	FILE *f = fopen(path, "rb");
	if (!f)
		return lang_error(p, at, "density_file '%s': cannot open it: %s", path, strerror(errno));
	unsigned char h[6];
	long len = -1;
	bool ok = fread(h, 1, 6, f) == 6 && fseek(f, 0, SEEK_END) == 0 && (len = ftell(f)) >= 6 && fseek(f, 6, SEEK_SET) == 0;
	if (!ok) {
		fclose(f);
		return lang_error(p, at, "density_file '%s': not a df3 file (it has no 6-byte header of its size)", path);
	}
	uint32_t n[3] = {(uint32_t)h[0] << 8 | h[1], (uint32_t)h[2] << 8 | h[3], (uint32_t)h[4] << 8 | h[5]};
	uint64_t count = (uint64_t)n[0] * n[1] * n[2], data = (uint64_t)len - 6;
	int bytes = count && data == count ? 1 : count && data == 2 * count ? 2 : count && data == 4 * count ? 4 : 0;
	if (!bytes) {
		fclose(f);
		return lang_error(p, at, "density_file '%s': %u x %u x %u voxels, but %llu bytes of data fit none of 8, 16 or "
					 "32 bits a voxel (POV-Ray: \"Invalid density file size\")",
				  path, n[0], n[1], n[2], (unsigned long long)data);
	}
	if (count > MAX_DF3_VOXELS) {
		fclose(f);
		return lang_error(p, at, "density_file '%s' has %llu voxels, more than circe's limit of %d", path,
				  (unsigned long long)count, MAX_DF3_VOXELS);
	}
	float *v = arena_alloc(&p->sc->arena, (size_t)count, sizeof *v, sizeof *v);
	unsigned char *raw = mem_alloc((size_t)data, 1);
	ok = v && raw && fread(raw, 1, (size_t)data, f) == (size_t)data;
	fclose(f);
	if (ok) {
		const double top = bytes == 1 ? 255.0 : bytes == 2 ? 65535.0 : 4294967295.0;
		for (uint64_t i = 0; i < count; i++) {
			const unsigned char *b = raw + i * (uint64_t)bytes;
			uint32_t x = bytes == 1 ? b[0]
				     : bytes == 2 ? (uint32_t)b[0] << 8 | b[1]
						  : (uint32_t)b[0] << 24 | (uint32_t)b[1] << 16 | (uint32_t)b[2] << 8 | b[3];
			v[i] = (float)(x / top);
		}
	}
	mem_free(raw);
	if (!ok)
		return lang_error(p, at, v && raw ? "density_file '%s': cannot read its voxels" : "out of memory", path);
	g->voxels = v, g->vox_file = path;
	memcpy(g->vox_n, n, sizeof n);
	return true;
}

/* density_args = "df3" string: the file, found as POV-Ray finds it, read while parsing. */
static bool density_file_args(parser *p, scene_pigment *g)
{
	if (!accept_word(p, "df3"))
		return lang_error_found(p, "expected 'df3' after 'density_file' (POV-Ray's one density file format)");
	diag_loc at = lang_peek(p)->loc;
	const char *name, *path;
	TRY(lang_string(p, "as the density file", &name));
	if (!(path = lang_data_path(p, name, at)))
		return lang_error(p, at, "cannot find density file '%s' (searched the including file's folder%s)", name,
				  p->opt.n_include_dirs ? " and the -I folders" : "");
	return read_df3(p, g, path, at);
}

/* slope_args = vector | "{" [ "point_at" ] vector [ "," lo [ "," hi ] ]
 *              [ "altitude" vector [ "," lo [ "," hi ] ] ] "}"   (POV-Ray 3.7's Parse_Pattern):
 * the vectors' lengths weight the slope and the altitude, then both are made unit. */
static bool slope_args(parser *p, scene_pigment *g, diag_loc kw)
{
	dvec3 alt = d3(0, 0, 0);
	if (lang_peek(p)->kind == LTK_LBRACE) {
		diag_loc open = lang_advance(p)->loc;
		g->slope_point_at = accept_word(p, "point_at");
		TRY(lang_vec3(p, g->slope_point_at ? "after 'point_at'" : "as the slope's direction", &g->slope_dir));
		TRY(slope_range(p, "slope", &g->slope_lo, &g->slope_width));
		if (peek_word(p, "altitude")) {
			if (g->slope_point_at)
				return lang_error(p, lang_peek(p)->loc, "'altitude' cannot be used with 'point_at' in a slope pattern");
			lang_advance(p);
			TRY(lang_vec3(p, "after 'altitude'", &alt));
			TRY(slope_range(p, "altitude", &g->altit_lo, &g->altit_width));
		}
		TRY(lang_expect_close(p, open, "slope"));
	} else {
		TRY(lang_vec3(p, "after 'slope'", &g->slope_dir));
	}
	if (g->slope_point_at) {
		g->slope_len = 1.0, g->altit_len = 0.0;
		return true;
	}
	double sl = d3_length(g->slope_dir), al = d3_length(alt), total = sl + al;
	if (!(total > 0.0) || !isfinite(total))
		return lang_error(p, kw, "the slope's direction and altitude both have length 0");
	if (sl > 0.0)
		g->slope_dir = d3_scale(g->slope_dir, 1.0 / sl);
	g->altit_dir = al > 0.0 ? d3_scale(alt, 1.0 / al) : alt;
	g->slope_len = sl / total, g->altit_len = 1.0 - g->slope_len;
	return true;
}

/* object_pattern = "object" "{" object_ref block_list "}"   POV-Ray's object pattern: entry 0
 * outside the object, 1 inside (the object in the pattern's space), by lang_options.inside (main.c
 * gives the build's: the inside of the object's tessellated solid, as CSG classifies it). */
static bool object_pattern(parser *p, pig_build *b, diag_loc kw)
{
	lang_advance(p);
	diag_loc open = lang_peek(p)->loc;
	TRY(lang_expect(p, LTK_LBRACE, "after 'object' (the object pattern)"));
	const objlist *l;
	TRY(lang_object_list(p, "in the object pattern", &l));
	TRY(block_list(p, b));
	TRY(lang_expect_close(p, open, "object pattern"));
	if (!p->opt.inside)
		return lang_error(p, kw, "'object' as a pattern is not supported by circe here (no inside test: it needs "
					 "the build)");
	return p->opt.inside(p->opt.trace_user, p->sc, l->items, l->n, l, &b->pg.fn, p->d, kw);
}

/* pattern_head = pattern_word [ arguments ]: gradient's vector, spiral's arms, a block pattern's
 * list. A new pattern starts afresh, its warps and turbulence too (POV-Ray 3.7 makes a new pattern
 * object, which holds them), over a declared pigment or normal. */
static bool pattern_head(parser *p, pig_build *b, scene_pattern_kind k)
{
	diag_loc kw = lang_peek(p)->loc;
	scene_pigment d = scene_pigment_defaults(k, kw);
	d.uv_mapping = b->pg.uv_mapping;
	b->pg = d;
	b->n_warps = 0;
	if (k == SCENE_PAT_FUNCTION) /* function { expression }: lang/func.c compiles it */
		return lang_func_pattern(p, &b->pg.fn);
	if (k == SCENE_PAT_IMAGE_PATTERN)
		return image_block(p, b, k);
	if (k == SCENE_PAT_OBJECT)
		return object_pattern(p, b, kw);
	if (k == SCENE_PAT_MATERIAL_MAP) /* a texture's (head() reads it there) */
		return lang_error(p, kw, "'material_map' picks textures: it belongs in a texture, not in a %s",
				  b->normal ? "normal" : b->density ? "density" : "pigment");
	if (k == SCENE_PAT_FACETS && !b->normal) /* POV-Ray's Only_In("facets", "normal") */
		return lang_error(p, kw, "'facets' is a normal's pattern: it cannot be used in a %s",
				  b->tex ? "texture" : b->density ? "density" : "pigment");
	lang_advance(p);
	if (k == SCENE_PAT_GRADIENT) { /* POV-Ray's Parse_Pattern normalises the vector */
		diag_loc at = lang_peek(p)->loc;
		TRY(lang_vec3(p, "after 'gradient'", &b->pg.vector));
		double len = d3_length(b->pg.vector);
		if (!(len > 0) || !isfinite(len))
			return lang_error(p, at, "the vector of 'gradient' must not be zero (POV-Ray makes it unit length)");
		b->pg.vector = d3_scale(b->pg.vector, 1.0 / len);
		return true;
	}
	if (k == SCENE_PAT_SLOPE)
		return slope_args(p, &b->pg, kw);
	if (k == SCENE_PAT_DENSITY_FILE)
		return density_file_args(p, &b->pg);
	if (k == SCENE_PAT_TILING) { /* tiling N: POV-Ray reads an unsigned char */
		double v;
		TRY(lang_float(p, "after 'tiling'", &v));
		int t = (int)(unsigned char)(long long)fmax(-1e18, fmin(1e18, v));
		b->pg.tiling = t;
		return true;
	}
	if (k == SCENE_PAT_PIGMENT_PATTERN) { /* pigment_pattern { pigment_body } */
		diag_loc open = lang_peek(p)->loc;
		TRY(lang_expect(p, LTK_LBRACE, "after 'pigment_pattern'"));
		return body(p, NULL, LTK_RBRACE, open, b->depth + 1, false, &b->pg.child);
	}
	if (k == SCENE_PAT_MAGNET) { /* magnet ( 1 | 2 ) ( mandel N | julia <re, im>, N ) */
		long type;
		TRY(lang_int(p, "as the magnet's type", 1, 2, &type));
		b->pg.magnet_type = (int)type;
		if (!peek_word(p, "julia") && !peek_word(p, "mandel"))
			return lang_error(p, lang_peek(p)->loc, "expected mandel or julia after 'magnet %ld', found '%.*s'", type,
					  (int)lang_peek(p)->len, lang_peek(p)->text);
		b->pg.magnet_julia = peek_word(p, "julia");
		lang_advance(p);
		k = b->pg.magnet_julia ? SCENE_PAT_JULIA : SCENE_PAT_MANDEL;
	}
	if (k == SCENE_PAT_MANDEL || k == SCENE_PAT_JULIA) { /* mandel N | julia <re, im>, N */
		long it;
		if (k == SCENE_PAT_JULIA) {
			dvec3 c;
			TRY(lang_vec3(p, "after 'julia'", &c));
			b->pg.julia_c[0] = c.x, b->pg.julia_c[1] = c.y;
			lang_accept(p, LTK_COMMA);
		}
		TRY(lang_int(p, "as the fractal's iterations limit", 1, 1000000, &it));
		b->pg.fractal_iterations = (int)it;
		return true;
	}
	if (k == SCENE_PAT_SPIRAL1 || k == SCENE_PAT_SPIRAL2) {
		long arms;
		TRY(lang_int(p, "as the spiral's number of arms", -1000000, 1000000, &arms));
		b->pg.arms = (int)arms;
		return true;
	}
	return scene_pattern_blocks(k) ? block_list(p, b) : true;
}

/* The wave words: ramp_wave triangle_wave sine_wave scallop_wave cubic_wave poly_wave [ float ]. */
static bool wave_word(parser *p, pig_build *b, bool *matched)
{
	static const char *const waves[] = {"ramp_wave", "triangle_wave", "sine_wave", "scallop_wave", "cubic_wave",
					    "poly_wave"};
	*matched = false;
	for (int i = 0; i < 6; i++)
		if (accept_word(p, waves[i])) {
			*matched = true;
			b->pg.wave = (scene_wave)i;
			lang_tok k = lang_peek(p)->kind;
			if (i == SCENE_WAVE_POLY && (k == LTK_NUMBER || k == LTK_LPAREN || peek_declared(p, VAL_FLOAT)))
				TRY(lang_float(p, "after 'poly_wave'", &b->pg.exponent));
			return true;
		}
	return true;
}

/* A float after the word w into *out. */
static bool word_float(parser *p, const char *w, double *out, bool *matched)
{
	if (!(*matched = accept_word(p, w)))
		return true;
	char ctx[48];
	snprintf(ctx, sizeof ctx, "after '%s'", w);
	return lang_float(p, ctx, out);
}

/* The numeric modifiers: frequency phase mortar agate_turb control0 control1. */
static bool number_modifier(parser *p, pig_build *b, bool *matched)
{
	scene_pigment *g = &b->pg;
	TRY(word_float(p, "frequency", &g->frequency, matched));
	if (!*matched)
		TRY(word_float(p, "phase", &g->phase, matched));
	if (!*matched)
		TRY(word_float(p, "mortar", &g->mortar, matched));
	if (!*matched)
		TRY(word_float(p, "agate_turb", &g->agate_turb, matched));
	if (!*matched)
		TRY(word_float(p, "control0", &g->control0, matched));
	if (!*matched)
		TRY(word_float(p, "control1", &g->control1, matched));
	return true;
}

/* crackle's modifiers (POV-Ray's Parse_Pattern): "form" vector | "metric" vector (its x: POV-Ray
 * reads a vector for compatibility) | "offset" float | "solid"; an error on another pattern. */
static bool crackle_modifier(parser *p, pig_build *b, bool *matched)
{
	static const char *const words[] = {"form", "metric", "offset", "solid"};
	const lang_token t = *lang_peek(p);
	int w = -1;
	for (int i = 0; i < 4 && w < 0; i++)
		if (lang_word_is(&t, words[i]))
			w = i;
	if (!(*matched = w >= 0))
		return true;
	if (b->pg.kind != SCENE_PAT_CRACKLE && !(w == 1 && b->pg.kind == SCENE_PAT_FACETS)) /* facets' metric too */
		return lang_error(p, t.loc, "'%s' belongs to crackle, not to %s", words[w],
				  b->pg.kind == SCENE_PAT_PLAIN ? "a plain colour" : scene_pattern_name(b->pg.kind));
	lang_advance(p);
	dvec3 v;
	switch (w) {
	case 0: return lang_vec3(p, "after 'form'", &b->pg.crackle_form);
	case 1:
		TRY(lang_vec3(p, "after 'metric'", &v));
		if (!(v.x > 0) || !isfinite(v.x))
			return lang_error(p, t.loc, "crackle's metric must be > 0, found %g", v.x);
		b->pg.crackle_metric = v.x;
		return true;
	case 2:
		TRY(lang_float(p, "after 'offset'", &v.x));
		if (!(v.x >= 0) || !isfinite(v.x))
			return lang_error(p, t.loc, "crackle's offset must be >= 0, found %g", v.x);
		b->pg.crackle_offset = v.x;
		return true;
	default: b->pg.solid = true; return true;
	}
}

/* slope_map = "slope_map" "{" { "[" float [ "," ] vector "]" } "}": a normal's map of the
 * pattern's value to <height, slope> (POV-Ray's Parse_Blend_Map of kBlendMapType_Slope: a UV
 * vector each), read into the entries' first two colour channels. */
static bool slope_map(parser *p, pig_build *b)
{
	diag_loc kw = lang_advance(p)->loc, open = lang_peek(p)->loc;
	TRY(lang_expect(p, LTK_LBRACE, "after 'slope_map'"));
	scene_map_entry *e = arena_zalloc(&p->sc->arena, SCENE_PIGMENT_MAX_ENTRIES, sizeof *e);
	if (!e)
		return lang_error(p, kw, "out of memory");
	uint32_t n = 0;
	while (lang_peek(p)->kind == LTK_LBRACKET) {
		diag_loc at = lang_advance(p)->loc;
		if (n == SCENE_PIGMENT_MAX_ENTRIES)
			return lang_error(p, at, "too many entries in 'slope_map' (limit is %d)", SCENE_PIGMENT_MAX_ENTRIES);
		double v;
		dvec3 hs;
		TRY(lang_float(p, "as the slope_map entry's value", &v));
		lang_accept(p, LTK_COMMA);
		TRY(lang_vec3(p, "as the slope_map entry's <height, slope>", &hs));
		TRY(lang_expect(p, LTK_RBRACKET, "to close the slope_map entry"));
		e[n++] = (scene_map_entry){.value = v, .color = {(float)hs.x, (float)hs.y, 0, 0, 0}};
	}
	if (!n)
		return lang_error_found(p, "expected '[' (a slope_map needs at least one entry)");
	TRY(lang_expect_close(p, open, "slope_map"));
	b->pg.entries = e, b->pg.n_entries = n, b->pg.slope_map = true, b->pg.pigment_map = b->pg.block_list = false;
	return true;
}

/* The fractals' modifiers (POV-Ray's Parse_Pattern): "exterior" int [","] float (types 0 to 8) |
 * "interior" int [","] float (0 to 6) | "exponent" 2 (the only one circe has); errors elsewhere. */
static bool fractal_modifier(parser *p, pig_build *b, bool *matched)
{
	const lang_token t = *lang_peek(p);
	bool ext = lang_word_is(&t, "exterior"), in = lang_word_is(&t, "interior"), ex = lang_word_is(&t, "exponent");
	if (!(*matched = ext || in || ex))
		return true;
	bool fractal = b->pg.kind == SCENE_PAT_MANDEL || b->pg.kind == SCENE_PAT_JULIA || b->pg.kind == SCENE_PAT_MAGNET;
	if (!fractal || (ex && b->pg.kind == SCENE_PAT_MAGNET))
		return lang_error(p, t.loc, "'%.*s' belongs to mandel and julia, not to %s", (int)t.len, t.text,
				  b->pg.kind == SCENE_PAT_PLAIN ? "a plain colour" : scene_pattern_name(b->pg.kind));
	lang_advance(p);
	long type;
	double f;
	if (ex) {
		diag_loc at = lang_peek(p)->loc;
		TRY(lang_float(p, "after 'exponent'", &f));
		long e = (long)fmax(-1e9, fmin(1e9, f)); /* POV-Ray's (int) */
		if (e < 2 || e > 33) { /* POV-Ray's warning, and its exponent 2 */
			diag_warning(p->d, at, "a fractal's exponent is 2 to 33, found %g: exponent 2 is used, as POV-Ray does", f);
			e = 2;
		}
		b->pg.fractal_exponent = (int)e;
		return true;
	}
	TRY(lang_int(p, ext ? "as the exterior type" : "as the interior type", 0, ext ? 8 : 6, &type));
	lang_accept(p, LTK_COMMA);
	TRY(lang_float(p, "as the factor", &f));
	if (ext && (type == 7 || type == 8) && !(f >= 1.0 && f < 4294967296.0))
		return lang_error(p, t.loc, "exterior type %ld counts iterations modulo its factor: it must be >= 1, found %g",
				  type, f);
	if (ext)
		b->pg.fractal_exterior = (int)type, b->pg.exterior_factor = f;
	else
		b->pg.fractal_interior = (int)type, b->pg.interior_factor = f;
	return true;
}

/* pattern_modifier = color_map | pigment_map | "turbulence" ( float | vector ) | "octaves" int
 *   | "omega" float | "lambda" float | wave | "frequency" float | "phase" float | warp
 *   | "brick_size" vector | "mortar" float | "agate_turb" float | "control0" float
 *   | "control1" float | "quick_color" colour | "noise_generator" int | "uv_mapping" | transform_item
 *   | normal_map (a normal's) | crackle_modifier | fractal_modifier
 * *matched false when the lookahead is none. */
static bool modifier(parser *p, pig_build *b, bool *matched)
{
	diag_loc at = lang_peek(p)->loc;
	xform xf = xform_identity();
	TRY(lang_transform_item(p, &xf, matched));
	if (*matched)
		return push_transform(p, b, &xf, at);
	TRY(wave_word(p, b, matched));
	if (!*matched)
		TRY(number_modifier(p, b, matched));
	if (*matched)
		return true;
	*matched = true;
	if (b->tex && peek_word(p, "texture_map")) /* its entries are texture bodies */
		return map_block(p, b, true);
	if (b->tex && (peek_word(p, "color_map") || peek_word(p, "colour_map") || peek_word(p, "pigment_map")))
		return lang_error(p, at, "a patterned texture takes a texture_map, not a %.*s", (int)lang_peek(p)->len,
				  lang_peek(p)->text);
	if (peek_word(p, "color_map") || peek_word(p, "colour_map") || peek_word(p, "pigment_map"))
		return map_block(p, b, peek_word(p, "pigment_map"));
	if (b->density && peek_word(p, "density_map")) /* its entries are density bodies, as a pigment_map's */
		return map_block(p, b, true);
	if (peek_word(p, "warp"))
		return warp_block(p, b);
	if (accept_word(p, "turbulence")) {
		TRY(lang_vec3(p, "after 'turbulence'", &b->pg.turb.amount));
		return true;
	}
	if (peek_word(p, "octaves") || peek_word(p, "omega") || peek_word(p, "lambda"))
		return turb_params(p, &b->pg.turb);
	if (accept_word(p, "brick_size"))
		return lang_vec3(p, "after 'brick_size'", &b->pg.vector);
	if (b->normal && accept_word(p, "bump_size"))
		return lang_float(p, "after 'bump_size'", &b->pg.bump_amount);
	if (b->normal && accept_word(p, "accuracy"))
		return lang_float(p, "after 'accuracy'", &b->pg.accuracy);
	if (b->normal && peek_word(p, "normal_map")) /* its entries are normal bodies */
		return map_block(p, b, true);
	if (b->normal && peek_word(p, "slope_map"))
		return slope_map(p, b);
	TRY(crackle_modifier(p, b, matched));
	if (!*matched)
		TRY(fractal_modifier(p, b, matched));
	if (*matched)
		return true;
	*matched = true;
	if (accept_word(p, "uv_mapping")) {
		b->pg.uv_mapping = true;
		return true;
	}
	if (peek_word(p, "coords") || peek_word(p, "size")) { /* facets' (POV-Ray: Only_In("coords", "facets")) */
		bool coords = peek_word(p, "coords");
		if (b->pg.kind != SCENE_PAT_FACETS)
			return lang_error(p, at, "'%s' belongs to facets, not to %s", coords ? "coords" : "size",
					  b->pg.kind == SCENE_PAT_PLAIN ? "a plain colour" : scene_pattern_name(b->pg.kind));
		lang_advance(p);
		return lang_float(p, coords ? "after 'coords'" : "after 'size'", coords ? &b->pg.facets_coords : &b->pg.facets_size);
	}
	if (peek_word(p, "interpolate")) { /* density_file's (POV-Ray: "Cannot use interpolate with non-density_file") */
		if (b->pg.kind != SCENE_PAT_DENSITY_FILE)
			return lang_error(p, at, "'interpolate' belongs to density_file (or an image_map's block), not to %s",
					  b->pg.kind == SCENE_PAT_PLAIN ? "a plain colour" : scene_pattern_name(b->pg.kind));
		lang_advance(p);
		double v;
		TRY(lang_float(p, "after 'interpolate'", &v));
		b->pg.vox_interp = (int)v;
		return true;
	}
	TRY(lang_pigment_quick_colour(p, matched));
	if (*matched)
		return true;
	*matched = true;
	if (accept_word(p, "noise_generator")) {
		long n;
		TRY(lang_int(p, "after 'noise_generator'", 1, 3, &n));
		diag_warning(p->d, at, "'noise_generator' is ignored: circe has one noise (Perlin's improved noise)");
		return true;
	}
	*matched = false;
	return true;
}

/* The first item of a body: a pattern and its arguments, image_map, a colour, a declared
 * pigment (in maps and lists, where stmt.c's pigment did not read it), or nothing. */
/* A normal's amount after its pattern: [ "," ] float, when one follows. */
static bool normal_amount(parser *p, pig_build *b)
{
	lang_accept(p, LTK_COMMA);
	lang_tok k = lang_peek(p)->kind;
	if (k == LTK_NUMBER || k == LTK_LPAREN || k == LTK_MINUS || peek_declared(p, VAL_FLOAT))
		return lang_float(p, "as the normal's amount", &b->pg.bump_amount);
	return true;
}

/* tiles = "tiles" "{" texture "tile2" texture "}": POV-Ray's old checker of two textures
 * (3.7's Parse_Tiles: the first texture on the checker's odd cells, entry 1, tile2's on the even
 * ones, entry 0). A tile of layered textures is not supported, as a layered texture in any
 * patterned texture's entry. */
static bool tiles(parser *p, pig_build *b)
{
	diag_loc kw = lang_advance(p)->loc, open = lang_peek(p)->loc;
	TRY(lang_expect(p, LTK_LBRACE, "after 'tiles'"));
	b->pg = scene_pigment_defaults(SCENE_PAT_CHECKER, kw);
	b->n_warps = 0;
	scene_map_entry *e = arena_zalloc(&p->sc->arena, 2, sizeof *e);
	if (!e)
		return lang_error(p, kw, "out of memory");
	for (int i = 1; i >= 0; i--) {
		if (i == 0 && !accept_word(p, "tile2"))
			return lang_error_found(p, "expected 'tile2' and the second tile's texture in 'tiles'");
		if (lang_peek(p)->kind != LTK_KW_TEXTURE)
			return lang_error_found(p, "expected the %s tile's texture in 'tiles'", i ? "first" : "second");
		e[i].value = i;
		TRY(texture_entry(p, b, LTK_RBRACE, &e[i]));
		if (lang_peek(p)->kind == LTK_KW_TEXTURE)
			return lang_error(p, lang_peek(p)->loc, "a layered texture in a tile (a texture after a texture) is "
								"not supported by circe");
	}
	TRY(lang_expect_close(p, open, "tiles"));
	const scene_material *first = b->tex_mats[0]; /* the textures in the entries' order */
	b->tex_mats[0] = b->tex_mats[1], b->tex_mats[1] = first;
	b->pg.entries = e, b->pg.n_entries = 2, b->pg.block_list = true, b->pg.pigment_map = false;
	return true;
}

static bool head(parser *p, pig_build *b)
{
	while (peek_word(p, "uv_mapping") &&
	       (lang_raw_next(p) == LTK_UNSUPPORTED ||
		(lang_raw_next(p) >= LANG_FIRST_KEYWORD && lang_raw_next(p) < LANG_FIRST_DIRECTIVE))) {
		lang_advance(p); /* POV-Ray's `pigment { uv_mapping spiral2 8 }`: uv_mapping before the pattern */
		b->pg.uv_mapping = true;
	}
	if (b->tex && peek_word(p, "tiles"))
		return tiles(p, b);
	if (b->tex && peek_word(p, "material_map"))
		return image_block(p, b, SCENE_PAT_MATERIAL_MAP);
	scene_pattern_kind k = peek_pattern(p);
	if (k != SCENE_PAT_COUNT) {
		double amount = b->pg.bump_amount, accuracy = b->pg.accuracy;
		TRY(pattern_head(p, b, k));
		b->pg.is_normal = b->normal;
		if (b->normal) /* a new pattern keeps the amount and accuracy of a declared normal */
			b->pg.bump_amount = amount, b->pg.accuracy = accuracy;
		return b->normal ? normal_amount(p, b) : true;
	}
	if (b->normal) {
		const symbol *sn = peek_declared(p, VAL_NORMAL);
		if (sn) {
			lang_advance(p);
			begin_from(b, sn->val.mat->normal);
			return true;
		}
		const symbol *sa = peek_declared(p, VAL_ARRAY);
		if (sa && lang_raw_next(p) == LTK_LBRACKET) { /* normal { Normals[I] } (the portfolio's allnormals) */
			lang_token t = *lang_advance(p);
			diag_loc at = lang_peek(p)->loc;
			lang_array *a;
			size_t i;
			TRY(lang_element_target(p, &t, &a, &i));
			if (!a->set[i])
				return lang_error(p, at, "element of '%.*s' read before it was assigned", (int)t.len, t.text);
			if (a->elems[i].kind != VAL_NORMAL)
				return lang_error(p, t.loc, "an element of '%.*s' is %s, not a normal", (int)t.len, t.text,
						  lang_value_kind_name(&a->elems[i]));
			begin_from(b, a->elems[i].mat->normal);
			return true;
		}
		if (lang_peek(p)->kind == LTK_KW_IMAGE_MAP)
			return lang_error(p, lang_peek(p)->loc, "'image_map' in a normal is not supported by circe: give a "
								"bump_map");
		if (peek_word(p, "bump_map")) { /* an image's grey as heights (imageutil.cpp's bump_map) */
			TRY(image_map(p, b));
			return normal_amount(p, b);
		}
		return true;
	}
	if (lang_peek(p)->kind == LTK_KW_IMAGE_MAP)
		return image_map(p, b);
	const symbol *s = peek_declared(p, VAL_PIGMENT);
	if (s) {
		diag_loc at = lang_advance(p)->loc;
		const scene_pigment *t = declared_tree(p, s->val.mat, at);
		TRY(t);
		begin_from(b, t);
		return true;
	}
	if (starts_colour(p)) {
		double c[5];
		TRY(lang_color5(p, "as the pigment colour", c));
		b->pg = scene_pigment_defaults(SCENE_PAT_PLAIN, b->pg.loc);
		set5(b->pg.color, c);
	}
	return true;
}

/* average: POV-Ray divides by its entries' weights, which must be there and add to more than 0. */
static bool average_check(parser *p, const pig_build *b)
{
	if (b->pg.kind != SCENE_PAT_AVERAGE)
		return true;
	if (!b->pg.entries)
		return lang_error(p, b->pg.loc, "'average' needs a %s: the entries it averages, weighted by their values",
				  b->normal ? "normal_map" : "pigment_map");
	double total = 0.0;
	for (uint32_t i = 0; i < b->pg.n_entries; i++)
		total += b->pg.entries[i].value;
	if (!(total > 0) || !isfinite(total))
		return lang_error(p, b->pg.loc, "the weights of 'average' add up to %g: they must add up to more than 0",
				  total);
	return true;
}

/* body = [ head ] { pattern_modifier } close */
static bool body_in(parser *p, pig_build *b, lang_tok close, diag_loc open, const scene_pigment **out)
{
	TRY(head(p, b));
	for (;;) {
		if (lang_accept(p, close)) {
			if (b->normal && b->pg.kind == SCENE_PAT_PLAIN && !b->default_normal)
				return lang_error(p, open, "a normal needs a pattern (bumps, dents, ripples, ...)");
			if (b->pg.kind == SCENE_PAT_PLAIN && (b->n_warps || b->pg.entries))
				b->n_warps = 0; /* a colour has no pattern to move or map */
			TRY(average_check(p, b));
			return (*out = finish_build(p, b, open)) != NULL;
		}
		bool matched;
		TRY(modifier(p, b, &matched));
		if (!matched) {
			if (close == LTK_RBRACKET)
				return lang_error_found(p, "expected a pattern modifier or ']' to close the map entry");
			return lang_error_found(p, "expected a pattern modifier or '}' to close '%s' (opened at line %u)",
						b->tex ? "texture" : "pigment", open.line);
		}
	}
}

static bool body_as(parser *p, const scene_pigment *base, lang_tok close, diag_loc open, int depth, bool normal,
		    bool density, const scene_pigment **out);

static bool body(parser *p, const scene_pigment *base, lang_tok close, diag_loc open, int depth, bool normal,
		 const scene_pigment **out)
{
	return body_as(p, base, close, open, depth, normal, false, out);
}

static bool body_as(parser *p, const scene_pigment *base, lang_tok close, diag_loc open, int depth, bool normal,
		    bool density, const scene_pigment **out)
{
	if (depth >= SCENE_PIGMENT_MAX_DEPTH)
		return lang_error(p, open, "pigments nested too deep (limit is %d)", SCENE_PIGMENT_MAX_DEPTH);
	TRY(lang_enter(p, open));
	pig_build *b = new_build(p, open);
	bool ok = b != NULL;
	if (ok) {
		if (base)
			begin_from(b, base);
		else
			b->pg = scene_pigment_defaults(SCENE_PAT_PLAIN, open);
		b->depth = depth;
		b->normal = normal;
		b->density = density;
		if (normal && !base)
			b->pg.is_normal = true;
		ok = body_in(p, b, close, open, out);
	}
	mem_free(b);
	lang_leave(p);
	return ok;
}

bool lang_pigment_rest(parser *p, const scene_pigment *base, diag_loc open, const scene_pigment **out)
{
	return body(p, base, LTK_RBRACE, open, 0, false, out);
}

bool lang_density(parser *p, const scene_pigment **out)
{
	lang_advance(p);
	diag_loc open = lang_peek(p)->loc;
	TRY(lang_expect(p, LTK_LBRACE, "after 'density'"));
	TRY(body_as(p, NULL, LTK_RBRACE, open, 0, false, true, out));
	const scene_pigment *pg = *out;
	if (pg->kind == SCENE_PAT_PLAIN || pg->kind == SCENE_PAT_IMAGE || pg->n_entries)
		return true;
	scene_pigment *c = arena_zalloc(&p->sc->arena, 1, sizeof *c);
	scene_map_entry *e = arena_zalloc(&p->sc->arena, 2, sizeof *e);
	if (!c || !e)
		return lang_error(p, open, "out of memory");
	*c = *pg;
	e[0] = (scene_map_entry){.value = 0.0};
	e[1] = (scene_map_entry){.value = 1.0, .color = {1, 1, 1, 0, 0}};
	c->entries = e, c->n_entries = 2;
	*out = c;
	return true;
}

bool lang_pigment_map_starts(parser *p)
{
	return peek_word(p, "color_map") || peek_word(p, "colour_map") || peek_word(p, "pigment_map");
}

bool lang_pigment_map_value(parser *p, value *out)
{
	diag_loc at = lang_peek(p)->loc;
	pig_build *b = new_build(p, at);
	scene_material *m = b ? arena_zalloc(&p->sc->arena, 1, sizeof *m) : NULL;
	bool ok = m != NULL;
	if (b && !m)
		lang_error(p, at, "out of memory");
	if (ok) {
		b->pg = scene_pigment_defaults(SCENE_PAT_PLAIN, at);
		ok = map_block(p, b, peek_word(p, "pigment_map")) && (m->pigment = finish_build(p, b, at)) != NULL;
	}
	mem_free(b);
	if (!ok)
		return false;
	m->loc = at;
	out->kind = VAL_COLOR_MAP, out->mat = m;
	return true;
}

const scene_pigment *lang_pigment_tree(parser *p, const scene_material *m) { return declared_tree(p, m, m->loc); }

bool lang_normal_starts(parser *p) { return peek_word(p, "normal"); }

bool lang_default_normal(parser *p, scene_material *m)
{
	lang_advance(p);
	diag_loc open = lang_peek(p)->loc;
	TRY(lang_expect(p, LTK_LBRACE, "after 'normal'"));
	TRY(lang_enter(p, open));
	pig_build *b = new_build(p, open);
	bool ok = b != NULL;
	if (ok) {
		if (m->normal)
			begin_from(b, m->normal);
		else
			b->pg = scene_pigment_defaults(SCENE_PAT_PLAIN, open);
		b->normal = b->default_normal = b->pg.is_normal = true;
		ok = body_in(p, b, LTK_RBRACE, open, &m->normal);
	}
	mem_free(b);
	lang_leave(p);
	return ok;
}

bool lang_normal(parser *p, scene_material *m)
{
	lang_advance(p);
	diag_loc open = lang_peek(p)->loc;
	TRY(lang_expect(p, LTK_LBRACE, "after 'normal'"));
	return body(p, m->normal, LTK_RBRACE, open, 0, true, &m->normal);
}

bool lang_normal_value(parser *p, value *out)
{
	diag_loc at = lang_peek(p)->loc;
	scene_material *m = arena_zalloc(&p->sc->arena, 1, sizeof *m);
	if (!m)
		return lang_error(p, at, "out of memory");
	m->loc = at;
	TRY(lang_normal(p, m));
	out->kind = VAL_NORMAL, out->mat = m;
	return true;
}

/* ---- patterned textures ------------------------------------------------------------------------ */

bool lang_texture_pattern_starts(parser *p)
{
	scene_pattern_kind k = peek_pattern(p);
	return (k != SCENE_PAT_COUNT && k != SCENE_PAT_MATERIAL_MAP) || peek_word(p, "tiles") || peek_word(p, "material_map");
}

bool lang_texture_pattern(parser *p, diag_loc open, lang_tok close, lang_texture_fn tex, const scene_pigment **pig,
			  const scene_material *const **mats, uint32_t *n)
{
	TRY(lang_enter(p, open));
	pig_build *b = new_build(p, open);
	bool ok = b != NULL;
	if (ok) {
		b->pg = scene_pigment_defaults(SCENE_PAT_PLAIN, open);
		b->tex = tex;
		b->tex_mats = arena_zalloc(&p->sc->arena, SCENE_PIGMENT_MAX_ENTRIES, sizeof *b->tex_mats);
		ok = b->tex_mats ? body_in(p, b, close, open, pig) : lang_error(p, open, "out of memory");
		*mats = b->tex_mats, *n = b->n_tex;
		if (ok && !b->n_tex)
			ok = lang_error(p, open, "a patterned texture needs its textures: a texture_map, or a list of "
						 "texture { } after its block pattern");
	}
	mem_free(b);
	lang_leave(p);
	return ok;
}

/* ---- rainbow ----------------------------------------------------------------------------------- */

/* rainbow = "rainbow" "{" { "angle" float | "width" float | "distance" float | "jitter" float
 *           | "direction" vector | "up" vector | "arc_angle" float | "falloff_angle" float
 *           | colour_map } "}"   (POV-Ray 3.7's Parse_Rainbow, its checks included).
 * Read and ignored with a warning: POV-Ray's rainbow is a colour added to the rays that pass
 * `distance` at an angle to `direction`, an atmospheric effect circe does not render. */
bool lang_rainbow(parser *p)
{
	diag_loc kw = lang_advance(p)->loc, open = lang_peek(p)->loc;
	TRY(lang_expect(p, LTK_LBRACE, "after 'rainbow'"));
	dvec3 dir = d3(0, 0, 0), up = d3(0, 1, 0);
	double arc = 180.0, falloff = 180.0, x;
	bool has_arc = false, has_falloff = false;
	for (;;) {
		diag_loc at = lang_peek(p)->loc;
		if (lang_accept(p, LTK_RBRACE))
			break;
		if (accept_word(p, "angle") || accept_word(p, "width") || accept_word(p, "distance") ||
		    accept_word(p, "jitter")) {
			TRY(lang_float(p, "in 'rainbow'", &x));
		} else if (accept_word(p, "direction")) {
			TRY(lang_vec3(p, "after 'direction'", &dir));
		} else if (accept_word(p, "up")) {
			TRY(lang_vec3(p, "after 'up'", &up));
		} else if (peek_word(p, "arc_angle") || peek_word(p, "falloff_angle")) {
			bool is_arc = peek_word(p, "arc_angle");
			lang_advance(p);
			TRY(lang_float(p, is_arc ? "after 'arc_angle'" : "after 'falloff_angle'", &x));
			if (!(x >= 0.0 && x <= 360.0))
				return lang_error(p, at, "a rainbow's %s must be from 0 to 360 degrees, found %g",
						  is_arc ? "arc_angle" : "falloff_angle", x);
			*(is_arc ? &arc : &falloff) = x;
			*(is_arc ? &has_arc : &has_falloff) = true;
		} else if (lang_pigment_map_starts(p)) {
			value v;
			TRY(lang_pigment_map_value(p, &v));
		} else {
			return lang_expect_close(p, open, "rainbow");
		}
	}
	if (has_arc && !has_falloff)
		falloff = arc;
	if (arc < falloff)
		return lang_error(p, kw, "a rainbow's arc_angle %g is smaller than its falloff_angle %g", arc, falloff);
	double dd = d3_dot(dir, dir), uu = d3_dot(up, up);
	if (dd < 1e-10 || uu < 1e-10)
		return lang_error(p, kw, "a rainbow's %s vector is zero", dd < 1e-10 ? "direction" : "up");
	if (fabs(1.0 - fabs(d3_dot(dir, up) / sqrt(dd * uu))) < 1e-10)
		return lang_error(p, kw, "a rainbow's up and direction vectors are colinear");
	diag_warning(p->d, kw, "'rainbow' is ignored: circe does not render POV-Ray's rainbow (a colour added to the "
			       "rays at an angle to its direction, an atmospheric effect)");
	return true;
}
