/* stmt.c - the statements of the scene language and the scene IR they build: settings, camera,
 * lights, environment, objects (primitives, meshes, subdivision cages, instances, unions) and
 * materials. Each parse function carries its grammar rule as a comment (grammar/scene.ebnf). */
#include "lang/parser.h"
#include "lang/shapes2.h"
#include "lang/pigment.h"

#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

/* Reports "expected EXPECT or '}' to close 'what'" at the lookahead, with a note at the opening
 * brace when the file ended. */

/* The index in kws of the keyword that comes next (consumed), or -1 after reporting msg: the
 * choice of one keyword among a few (profile, method, scheme, boundary), enum values in kws order. */
static int one_of(parser *p, const lang_tok *kws, int n, const char *msg)
{
	for (int i = 0; i < n; i++)
		if (lang_accept(p, kws[i]))
			return i;
	lang_error_found(p, "%s", msg);
	return -1;
}

static bool bad_item(parser *p, diag_loc open, const char *what, const char *expect)
{
	bool at_eof = lang_peek(p)->kind == LTK_EOF && !p->failed;
	lang_error_found(p, "expected %s or '}' to close '%s' (opened at line %u)", expect, what, open.line);
	if (at_eof)
		diag_note(p->d, open, "'%s' opened here", what);
	return false;
}

/* "{" after a block keyword; *open receives its location. */
static bool open_block(parser *p, const char *what, diag_loc *open)
{
	char ctx[64];
	snprintf(ctx, sizeof ctx, "after '%s'", what);
	*open = lang_peek(p)->loc;
	return lang_expect(p, LTK_LBRACE, ctx);
}

static bool positive(parser *p, diag_loc loc, const char *what, double x)
{
	if (x > 0)
		return true;
	return lang_error(p, loc, "%s must be > 0, found %g", what, x);
}

/* A colour that becomes a physical quantity (a reflectance, a radiance): POV-Ray takes any
 * number, so one outside the use's range is clamped with a warning at it (scene_color_finalise),
 * not refused. `context` is lang_color's ("as the diffuse colour"), `what` the warning's. */
static bool physical_color(parser *p, const char *context, const char *what, scene_color_use use, vec3 *out)
{
	diag_loc loc = lang_peek(p)->loc;
	return lang_color(p, context, out) && scene_color_finalise(p->sc, p->d, loc, what, use, out);
}

static bool in_range(parser *p, diag_loc loc, const char *what, double x, double lo, double hi)
{
	if (x >= lo && x <= hi)
		return true;
	return lang_error(p, loc, "%s must be in [%g, %g], found %g", what, lo, hi, x);
}

/* True when the lookahead starts a colour where an item keyword could stand instead (a light's
 * colour, an SSS block's colour): 'color', 'colour', 'rgb' or a declared colour. */
static bool starts_colour(parser *p)
{
	lang_token *t = lang_peek(p);
	if (lang_colour_word(t->kind))
		return true;
	if (t->kind != LTK_IDENT)
		return false;
	const symbol *s = lang_lookup(p, t->text, t->len);
	return s && s->val.kind == VAL_COLOR;
}

/* A file named by the scene (mesh, cage, image, normal map): a relative path is resolved against
 * the folder of the file that names it, as #include does, so the IR holds paths that open as is.
 * The scene's asset list records it with the string's place, for the errors of opening it. */
static bool asset_path(parser *p, const char *what, scene_asset_kind kind, const char **out)
{
	diag_loc loc = lang_peek(p)->loc;
	const char *name;
	TRY(lang_string(p, what, &name));
	/* An image not beside the scene is sought in the -I folders, as POV-Ray's Locate_File searches
	 * its library paths (povray-includes ships test.png, plasma2.png, mtmandj.png, ...). */
	const char *found = kind == SCENE_ASSET_IMAGE ? lang_data_path(p, name, loc) : NULL;
	if (found) {
		*out = found;
		return scene_add_asset(p->sc, kind, found, loc) || lang_error(p, loc, "out of memory");
	}
	const char *from = loc.src ? loc.src->name : "";
	const char *slash = strrchr(from, '/');
	if (name[0] == '/' || !slash) {
		*out = name;
		return scene_add_asset(p->sc, kind, name, loc) || lang_error(p, loc, "out of memory");
	}
	size_t dlen = (size_t)(slash - from) + 1, nlen = strlen(name);
	char *path = arena_alloc(&p->sc->arena, dlen + nlen + 1, 1, 1);
	if (!path)
		return lang_error(p, loc, "out of memory");
	memcpy(path, from, dlen);
	memcpy(path + dlen, name, nlen + 1);
	*out = path;
	return scene_add_asset(p->sc, kind, path, loc) || lang_error(p, loc, "out of memory");
}

/* The value of the declared name that comes next (consumed), which must be of kind k (what: "a
 * pigment" for the message); NULL after reporting. */
static const value *declared(parser *p, value_kind k, const char *what)
{
	lang_token t = *lang_advance(p);
	const symbol *s = lang_lookup(p, t.text, t.len);
	if (!s) {
		lang_error(p, t.loc, "undeclared identifier '%.*s'", (int)t.len, t.text);
		return NULL;
	}
	const value *v = &s->val;
	if (v->kind == VAL_ARRAY && lang_raw_next(p) == LTK_LBRACKET) { /* texture { Textures[I] } */
		diag_loc at = lang_peek(p)->loc;
		lang_array *a;
		size_t i;
		if (!lang_element_target(p, &t, &a, &i))
			return NULL;
		if (!a->set[i]) {
			lang_error(p, at, "element of '%.*s' read before it was assigned", (int)t.len, t.text);
			return NULL;
		}
		v = &a->elems[i];
	}
	if (v->kind != k) {
		lang_error(p, t.loc, "'%.*s' is %s, not %s", (int)t.len, t.text, lang_value_kind_name(v), what);
		return NULL;
	}
	return v;
}

/* The kind of value a declared name gives: an array's, that of its elements (when they are of
 * one kind), for a name that is indexed next. */
static int named_kind(const symbol *s)
{
	if (s->val.kind == VAL_ARRAY && !s->val.arr->mixed && s->val.arr->kind >= 0)
		return s->val.arr->kind;
	return (int)s->val.kind;
}

/* True when the lookahead is a name declared as a value of kind k (or an array of them). */
static bool names(parser *p, value_kind k)
{
	lang_token *t = lang_peek(p);
	if (t->kind != LTK_IDENT)
		return false;
	const symbol *s = lang_lookup(p, t->text, t->len);
	return s && named_kind(s) == (int)k;
}

/* True when the lookahead is a name declared as a block (neither a number nor a string): where a
 * colour could stand too, it must be the block the context asks for. */
static bool names_block(parser *p)
{
	lang_token *t = lang_peek(p);
	if (t->kind != LTK_IDENT)
		return false;
	const symbol *s = lang_lookup(p, t->text, t->len);
	int k = s ? named_kind(s) : -1;
	return s && k != VAL_FLOAT && k != VAL_VECTOR && k != VAL_COLOR && k != VAL_STRING;
}

bool lang_asset_path(parser *p, const char *what, scene_asset_kind kind, const char **out)
{
	return asset_path(p, what, kind, out);
}

/* ---- transforms -------------------------------------------------------------------------- */

static bool transform_block(parser *p, xform *out);

/* transform_item = "translate" vector | "rotate" vector | "scale" ( float | vector )
 *                | "matrix" "<" float { "," float } ">" | transform
 * One item at the lookahead, composed after *t; *matched false (nothing read) when the
 * lookahead is none. */
static bool transform_item(parser *p, xform *t, bool *matched)
{
	lang_token k = *lang_peek(p);
	dvec3 v;
	xform x;
	*matched = true;
	switch (k.kind) {
	case LTK_KW_TRANSLATE:
		lang_advance(p);
		TRY(lang_vec3(p, "after 'translate'", &v));
		x = xform_translate(v);
		break;
	case LTK_KW_ROTATE:
		lang_advance(p);
		TRY(lang_vec3(p, "after 'rotate'", &v));
		x = xform_rotate(v);
		break;
	case LTK_KW_SCALE:
		lang_advance(p);
		TRY(lang_vec3(p, "after 'scale'", &v));
		if (!xform_scale(v, &x))
			return lang_error(p, k.loc, "scale by zero (<%g, %g, %g>) flattens the object", v.x, v.y, v.z);
		break;
	case LTK_KW_MATRIX: {
		lang_advance(p);
		diag_loc loc = lang_peek(p)->loc;
		value mv;
		TRY(lang_additive(p, &mv));
		if (mv.kind != VAL_VECTOR || mv.n != 12)
			return lang_error(p, loc, "'matrix' needs 12 numbers <m00, m01, ..., m32>, found %s",
					  lang_value_kind_name(&mv));
		if (!xform_from_pov_matrix(mv.v, &x))
			return lang_error(p, loc, "'matrix' is singular (its 3x3 part has no inverse)");
		break;
	}
	case LTK_KW_TRANSFORM:
		TRY(transform_block(p, &x));
		break;
	default:
		*matched = false;
		return true;
	}
	*t = xform_then(*t, x);
	return true;
}

bool lang_transform_item(parser *p, xform *t, bool *matched) { return transform_item(p, t, matched); }

/* The inverse of an affine transform: xform keeps it beside the matrix. */
static xform xform_inverse(xform t)
{
	xform r;
	memcpy(r.m, t.inv, sizeof r.m);
	memcpy(r.inv, t.m, sizeof r.inv);
	return r;
}

/* transform = "transform" ( identifier | "{" [ identifier ] { transform_item | "inverse" } "}" )
 * As POV-Ray 3.7: `inverse` anywhere in the block inverts the whole block. */
static bool transform_body(parser *p, xform *out)
{
	const value *v;
	if (lang_peek(p)->kind == LTK_IDENT) {
		TRY(v = declared(p, VAL_TRANSFORM, "a transform"));
		*out = *v->xf;
		return true;
	}
	diag_loc open;
	TRY(open_block(p, "transform", &open));
	xform t = xform_identity();
	if (lang_peek(p)->kind == LTK_IDENT) {
		TRY(v = declared(p, VAL_TRANSFORM, "a transform"));
		t = *v->xf;
	}
	bool inverse = false;
	for (;;) {
		if (lang_accept(p, LTK_RBRACE))
			break;
		if (lang_accept(p, LTK_KW_INVERSE)) {
			inverse = true;
			continue;
		}
		bool matched;
		TRY(transform_item(p, &t, &matched));
		if (!matched)
			return bad_item(p, open, "transform", "translate, rotate, scale, matrix, transform or inverse");
	}
	*out = inverse ? xform_inverse(t) : t;
	return true;
}

/* A transform block nests in itself (transform { transform {...} }): each counts a level. */
static bool transform_block(parser *p, xform *out)
{
	diag_loc kw = lang_advance(p)->loc;
	TRY(lang_enter(p, kw));
	bool ok = transform_body(p, out);
	lang_leave(p);
	return ok;
}

/* A texture's own transforms (of a pigment, texture or material): they move its pattern, and a
 * plain colour has none, so they change nothing; an image has one, which circe maps by the
 * surface's uv coordinates and cannot move. at: the first transform (line 0: none). */
static bool pattern_transform(parser *p, const scene_material *m, diag_loc at, const char *what)
{
	if (at.line == 0 || (!m->image && !m->sss.albedo_image))
		return true;
	return lang_error(p, at, "a transform of an image-mapped %s is not supported by circe (its image is mapped by "
				 "the surface's uv coordinates)",
			  what);
}

/* A copy of a layer's record for a layered texture's list (in the arena, not in the scene's list
 * of materials: the layered texture is the material, its layers are its parts). */
static scene_material *layer_copy(parser *p, const scene_material *t)
{
	scene_material *c = arena_alloc(&p->sc->arena, 1, sizeof *c, 16);
	if (!c)
		return NULL;
	*c = *t;
	c->next = NULL, c->name = NULL, c->layers = NULL, c->n_layers = 0;
	return c;
}

/* transform_item in a pigment, texture or material: read, recorded in *at when first; it moves
 * m's POV-Ray pigment (a copy: the tree may be shared), and nothing else has a pattern to move. */
static bool pattern_transform_item(parser *p, scene_material *m, diag_loc *at, bool *matched)
{
	diag_loc loc = lang_peek(p)->loc;
	xform moved = xform_identity();
	TRY(transform_item(p, &moved, matched));
	if (*matched && at->line == 0)
		*at = loc;
	if (*matched && m->pigment)
		TRY(m->pigment = lang_pigment_moved(p, m->pigment, &moved, loc));
	if (*matched && m->sss.pigment)
		TRY(m->sss.pigment = lang_pigment_moved(p, m->sss.pigment, &moved, loc));
	if (*matched && m->normal)
		TRY(m->normal = lang_pigment_moved(p, m->normal, &moved, loc));
	if (*matched && m->n_layers) { /* a layered texture's transform moves every layer */
		const scene_material **layers = arena_alloc(&p->sc->arena, m->n_layers, sizeof *layers, 16);
		if (!layers)
			return lang_error(p, loc, "out of memory");
		for (uint32_t i = 0; i < m->n_layers; i++) {
			scene_material *c = layer_copy(p, m->layers[i]);
			if (!c)
				return lang_error(p, loc, "out of memory");
			if (c->pigment)
				TRY(c->pigment = lang_pigment_moved(p, c->pigment, &moved, loc));
			if (c->normal)
				TRY(c->normal = lang_pigment_moved(p, c->normal, &moved, loc));
			layers[i] = c;
		}
		m->layers = layers;
	}
	return true;
}

/* ---- materials --------------------------------------------------------------------------- */

static scene_material *new_material(parser *p, diag_loc loc, scene_material_kind kind)
{
	scene_material *m = scene_new_material(p->sc, loc);
	if (!m) {
		lang_error(p, loc, "out of memory");
		return NULL;
	}
	m->kind = kind;
	if (kind == MAT_TEXTURE) {
		m->diffuse = 0.6f; /* POV-Ray's finish defaults */
		m->roughness = 0.05f;
	}
	return m;
}

/* A record that holds a declared pigment, finish or interior: a texture of which only that part
 * is read. In the arena, not the scene's list: it is no material of the scene. */
static scene_material *new_part(parser *p, diag_loc loc)
{
	scene_material *m = arena_zalloc(&p->sc->arena, 1, sizeof *m);
	if (!m) {
		lang_error(p, loc, "out of memory");
		return NULL;
	}
	m->loc = loc;
	m->kind = MAT_TEXTURE;
	m->diffuse = 0.6f; /* POV-Ray's finish defaults, as new_material */
	m->roughness = 0.05f;
	scene_finish_defaults(&m->finish);
	return m;
}

static void copy_pigment(scene_material *to, const scene_material *from)
{
	to->color = from->color;
	to->image = from->image;
	to->filter = from->filter, to->transmit = from->transmit;
	to->pigment = from->pigment;
}

/* A pigment's colour with its filter and transmit (POV-Ray's rgbf/rgbt), each clamped into
 * [0, 1] with a warning: the fractions of light a surface lets through (tinted, untinted). */
static bool pigment_color(parser *p, const char *what, scene_color_use use, scene_material *m)
{
	diag_loc loc = lang_peek(p)->loc;
	double ft[2];
	TRY(lang_color_ft(p, "as the pigment colour", &m->color, ft) &&
	    scene_color_finalise(p->sc, p->d, loc, what, use, &m->color));
	if (use != SCENE_COLOR_REFLECTANCE) {
		if (ft[0] != 0 || ft[1] != 0)
			diag_warning(p->d, loc, "filter %g and transmit %g of a sky colour are ignored", ft[0], ft[1]);
		return true;
	}
	for (int i = 0; i < 2; i++)
		if (!(ft[i] >= 0 && ft[i] <= 1)) {
			diag_warning(p->d, loc, "%s %g is outside [0, 1]: clamped", i ? "transmit" : "filter", ft[i]);
			ft[i] = ft[i] > 1 ? 1 : 0;
		}
	m->filter = (float)ft[0], m->transmit = (float)ft[1];
	return true;
}

static void copy_finish(scene_material *to, const scene_material *from)
{
	to->diffuse = from->diffuse, to->specular = from->specular, to->roughness = from->roughness;
	to->finish = from->finish;
}

/* A new texture record: POV-Ray's default texture, or the one of the last #default (POV-Ray 3.7
 * makes every texture from a copy of its default texture). */
static scene_material *new_texture(parser *p, diag_loc loc)
{
	scene_material *m = new_material(p, loc, MAT_TEXTURE);
	if (m && p->default_tex) {
		copy_pigment(m, p->default_tex);
		copy_finish(m, p->default_tex);
		m->normal = p->default_tex->normal;
	}
	return m;
}

/* A new record with the contents of base (a declared material being modified). */
static scene_material *copy_material(parser *p, const scene_material *base, diag_loc loc)
{
	scene_material *m = new_material(p, loc, base->kind);
	if (!m)
		return NULL;
	uint32_t id = m->id;
	scene_material *next = m->next;
	*m = *base;
	m->id = id, m->next = next, m->loc = loc, m->name = NULL;
	return m;
}

/* One layer of a layered texture as an entry of its pigment: its pattern, or its plain colour with
 * its filter and transmit. */
static scene_map_entry layer_entry(const scene_material *m, uint32_t index)
{
	scene_map_entry e = {.value = index, .pigment = m->pigment};
	e.color[0] = m->color.x, e.color[1] = m->color.y, e.color[2] = m->color.z;
	e.color[3] = m->filter, e.color[4] = m->transmit;
	return e;
}

/* The records of t's layers, bottom first, written to out (NULL: counted only): t itself, or a
 * layered texture's layers with its top one replaced by t with that layer's own pigment (t holds
 * the top layer's finish and normal as modified since, over the composite pigment). */
static uint32_t layer_records(parser *p, const scene_material *t, const scene_material **out)
{
	if (!t->n_layers) {
		if (out)
			out[0] = t;
		return 1;
	}
	if (out) {
		memcpy(out, t->layers, (t->n_layers - 1) * sizeof *out);
		scene_material *top = layer_copy(p, t);
		if (top)
			copy_pigment(top, t->layers[t->n_layers - 1]);
		out[t->n_layers - 1] = top;
	}
	return t->n_layers;
}

/* POV-Ray's layered texture: top over below (a texture written after a texture). The pigments
 * composite by the upper layers' filter and transmit (scene/pattern.c's PATTERN_LAYERS: the
 * material's colour, for what sees one pigment); the layers keep their own records
 * (scene_material.layers), each lit with its own finish (render/world.c shade_layers,
 * doc/language.md "Layered textures"). The layers' transparency shows the layers below, and
 * what lies behind the object where every layer lets light through. */
static bool layer_texture(parser *p, const scene_material *below, const scene_material *top, diag_loc at,
			  const scene_material **out)
{
	if (below->kind != MAT_TEXTURE || top->kind != MAT_TEXTURE)
		return lang_error(p, at, "a layered texture takes POV-Ray textures, but this layer is a %s material",
				  scene_material_kind_name(below->kind != MAT_TEXTURE ? below->kind : top->kind));
	const scene_pigment *bp = below->pigment;
	bool stacked = bp && bp->kind == SCENE_PAT_LAYERS;
	uint32_t n = (stacked ? bp->n_entries : 1) + 1;
	uint32_t nb = layer_records(p, below, NULL), nl = nb + layer_records(p, top, NULL);
	if (n > SCENE_PIGMENT_MAX_ENTRIES || nl > SCENE_PIGMENT_MAX_ENTRIES)
		return lang_error(p, at, "too many layers in a texture (limit is %d)", SCENE_PIGMENT_MAX_ENTRIES);
	scene_map_entry *e = arena_alloc(&p->sc->arena, n, sizeof *e, 16);
	const scene_material **layers = arena_alloc(&p->sc->arena, nl, sizeof *layers, 16);
	scene_pigment *lay = arena_zalloc(&p->sc->arena, 1, sizeof *lay);
	scene_material *m = e && layers && lay ? copy_material(p, top, at) : NULL;
	if (!m)
		return lang_error(p, at, "out of memory");
	layer_records(p, below, layers);
	layer_records(p, top, layers + nb);
	for (uint32_t i = 0; i < nl; i++)
		if (!layers[i])
			return lang_error(p, at, "out of memory");
	if (stacked)
		memcpy(e, bp->entries, (n - 1) * sizeof *e);
	else
		e[0] = layer_entry(below, 0);
	e[n - 1] = layer_entry(top, n - 1);
	*lay = scene_pigment_defaults(SCENE_PAT_LAYERS, at);
	lay->entries = e, lay->n_entries = n, lay->pigment_map = true;
	m->pigment = lay, m->image = NULL;
	m->filter = m->transmit = 0.0f;
	m->layers = layers, m->n_layers = nl;
	*out = m;
	return true;
}

/* True when the lookahead is a transform item (which may follow a declared pigment alone). */
static bool starts_transform(parser *p)
{
	lang_tok k = lang_peek(p)->kind;
	return k == LTK_KW_TRANSLATE || k == LTK_KW_ROTATE || k == LTK_KW_SCALE || k == LTK_KW_MATRIX ||
	       k == LTK_KW_TRANSFORM;
}

/* pigment = "pigment" "{" [ identifier ] [ colour | pigment_body ] { transform_item } "}"   (empty: unchanged)
 * pigment_body: a pattern, image_map and their modifiers (lang/pigment.c)
 * use: what the colour becomes (an albedo; a sky's radiance). */
static bool pigment(parser *p, scene_material *m, scene_color_use use)
{
	diag_loc open, moved = {0};
	lang_advance(p);
	TRY(open_block(p, "pigment", &open));
	m->map_textures = NULL, m->n_map_textures = 0; /* a patterned texture's entries: its pigment's */
	bool named = names_block(p);
	if (named) {
		const value *v;
		TRY(v = declared(p, VAL_PIGMENT, "a pigment"));
		copy_pigment(m, v->mat);
	}
	for (bool q = true; q;) /* pigment { quick_color C } over a texture's pigment (chess2.pov) */
		TRY(lang_pigment_quick_colour(p, &q));
	if (lang_pigment_starts(p, m->pigment != NULL)) {
		TRY(lang_pigment_rest(p, m->pigment, open, &m->pigment));
		m->image = NULL;
		if (m->pigment->kind == SCENE_PAT_PLAIN) { /* a declared pattern replaced by a colour */
			m->color = v3(m->pigment->color[0], m->pigment->color[1], m->pigment->color[2]);
			TRY(scene_color_finalise(p->sc, p->d, open, "pigment colour", use, &m->color));
			m->pigment = NULL;
		}
		return true;
	}
	if (lang_peek(p)->kind != LTK_RBRACE && !starts_transform(p)) { /* pigment {} changes nothing */
		const char *what = use == SCENE_COLOR_REFLECTANCE ? "pigment colour" : "sky colour";
		TRY(pigment_color(p, what, use, m));
		m->image = NULL;
		m->pigment = NULL;
	}
	for (;;) {
		if (lang_accept(p, LTK_RBRACE))
			return pattern_transform(p, m, moved, "pigment");
		bool matched;
		TRY(pattern_transform_item(p, m, &moved, &matched));
		if (!matched)
			TRY(lang_pigment_quick_colour(p, &matched));
		if (!matched)
			return lang_expect_close(p, open, "pigment");
	}
}

/* finish = "finish" "{" [ identifier ] { finish_item } "}"   (finish_item: finish.c) */
static bool finish(parser *p, scene_material *m)
{
	diag_loc open;
	lang_advance(p);
	TRY(open_block(p, "finish", &open));
	if (lang_peek(p)->kind == LTK_IDENT) {
		const value *v;
		TRY(v = declared(p, VAL_FINISH, "a finish"));
		copy_finish(m, v->mat);
	}
	lang_finish_state st = {0};
	for (;;) {
		if (lang_accept(p, LTK_RBRACE)) {
			lang_finish_end(m, &st);
			return true;
		}
		bool matched;
		TRY(lang_finish_item(p, m, &st, &matched));
		if (!matched)
			return bad_item(p, open, "finish", "a finish item (diffuse, ambient, phong, reflection, ...)");
	}
}

static void copy_interior(scene_material *to, const scene_material *from)
{
	to->ior = from->ior;
	to->fade_distance = from->fade_distance, to->fade_power = from->fade_power;
	to->fade_color = from->fade_color;
	to->media = from->media, to->n_media = from->n_media;
}

/* The interior's words that are no keywords of circe's (they lex as LTK_UNSUPPORTED). */
typedef enum interior_word { IW_NONE, IW_CAUSTICS, IW_DISPERSION, IW_DISPERSION_SAMPLES, IW_FADE_COLOR,
			     IW_FADE_COLOUR, IW_FADE_DISTANCE, IW_FADE_POWER, IW_MEDIA, IW_REFRACTION } interior_word;

/* The index in names[1..n) of the POV-Ray word t (lexed as LTK_UNSUPPORTED), or 0: the words of
 * a block that are no keywords of circe's. */
static size_t pov_word_at(const lang_token *t, const char *const *names, size_t n)
{
	if (t->kind != LTK_UNSUPPORTED)
		return 0;
	for (size_t i = 1; i < n; i++)
		if (lang_token_is(t, names[i]))
			return i;
	return 0;
}

static interior_word interior_word_at(const lang_token *t)
{
	static const char *const names[] = {"", "caustics", "dispersion", "dispersion_samples", "fade_color",
					    "fade_colour", "fade_distance", "fade_power", "media", "refraction"};
	return (interior_word)pov_word_at(t, names, sizeof names / sizeof names[0]);
}

/* ---- media ------------------------------------------------------------------------------- */

/* The largest intervals, samples or aa_level accepted (they are unused: a bound for typos). */
#define MEDIA_MAX_COUNT 1000000

static bool word_here(parser *p, const char *w) { return lang_word_is(lang_peek(p), w); }

/* An integer item of a media's sampling (accepted: circe is a path tracer) in [lo, hi]. */
static bool media_int(parser *p, const char *what, long lo, long hi, long *out)
{
	char ctx[48];
	snprintf(ctx, sizeof ctx, "after '%s'", what);
	diag_loc at = lang_peek(p)->loc;
	double x;
	TRY(lang_float(p, ctx, &x));
	if (!(x >= lo && x <= hi))
		return lang_error(p, at, "%s must be in [%ld, %ld], found %g", what, lo, hi, x);
	*out = (long)x;
	return true;
}

/* scattering = "scattering" "{" int "," colour { "eccentricity" float | "extinction" float } "}"
 * POV-Ray's types: 1 isotropic, 2 Mie haze, 3 Mie murky, 4 Rayleigh, 5 Henyey-Greenstein. */
static bool media_scattering(parser *p, scene_media *md)
{
	diag_loc open;
	lang_advance(p);
	TRY(open_block(p, "scattering", &open));
	long type;
	TRY(media_int(p, "the scattering type", 1, 5, &type));
	md->scattering_type = (int)type;
	TRY(lang_expect(p, LTK_COMMA, "after the scattering type"));
	TRY(physical_color(p, "as the scattering colour", "scattering", SCENE_COLOR_RADIANCE, &md->scattering));
	for (;;) {
		diag_loc at = lang_peek(p)->loc;
		double x;
		if (word_here(p, "eccentricity")) {
			lang_advance(p);
			TRY(lang_float(p, "after 'eccentricity'", &x));
			if (!(x > -1 && x < 1))
				return lang_error(p, at, "eccentricity must be in (-1, 1), found %g", x);
			if (type != 5)
				diag_warning(p->d, at, "'eccentricity' is used by scattering type 5 (Henyey-Greenstein) only, "
						       "as in POV-Ray");
			md->eccentricity = (float)x;
		} else if (word_here(p, "extinction")) {
			lang_advance(p);
			TRY(lang_float(p, "after 'extinction'", &x));
			if (!(x >= 0))
				return lang_error(p, at, "extinction must be >= 0, found %g", x);
			md->extinction = (float)x;
		} else {
			break;
		}
	}
	return lang_expect_close(p, open, "scattering");
}

/* One media item at the lookahead; *matched false when none. POV-Ray's parse_materials.cpp
 * Parse_Media. */
static bool media_item(parser *p, scene_media *md, xform *xf, bool *matched, bool *was_transform)
{
	*matched = true;
	*was_transform = false;
	diag_loc at = lang_peek(p)->loc;
	long n;
	double x;
	if (word_here(p, "absorption") || word_here(p, "emission")) {
		bool abs = word_here(p, "absorption");
		lang_advance(p);
		return physical_color(p, abs ? "after 'absorption'" : "after 'emission'", abs ? "absorption" : "emission",
				      SCENE_COLOR_RADIANCE, abs ? &md->absorption : &md->emission);
	}
	if (word_here(p, "scattering"))
		return media_scattering(p, md);
	if (word_here(p, "density")) {
		if (md->n_density == SCENE_MEDIA_MAX_DENSITIES)
			return lang_error(p, at, "too many densities in one media (limit is %d)", SCENE_MEDIA_MAX_DENSITIES);
		const scene_pigment *pg;
		TRY(lang_density(p, &pg));
		md->density[md->n_density++] = pg;
		return true;
	}
	if (word_here(p, "method")) {
		lang_advance(p);
		TRY(media_int(p, "method", 1, 3, &n));
		md->method = (int)n;
		return true;
	}
	if (word_here(p, "intervals") || word_here(p, "aa_level")) {
		const char *w = word_here(p, "intervals") ? "intervals" : "aa_level";
		lang_advance(p);
		return media_int(p, w, w[0] == 'i' ? 1 : 0, MEDIA_MAX_COUNT, &n);
	}
	if (word_here(p, "samples")) { /* samples Min [, Max] */
		lang_advance(p);
		TRY(media_int(p, "samples", 1, MEDIA_MAX_COUNT, &n));
		if (lang_accept(p, LTK_COMMA))
			TRY(media_int(p, "samples", 1, MEDIA_MAX_COUNT, &n));
		return true;
	}
	static const char *const floats[] = {"confidence", "variance", "ratio", "jitter", "aa_threshold"};
	for (size_t i = 0; i < sizeof floats / sizeof floats[0]; i++)
		if (word_here(p, floats[i])) {
			lang_advance(p);
			char ctx[48];
			snprintf(ctx, sizeof ctx, "after '%s'", floats[i]);
			return lang_float(p, ctx, &x);
		}
	TRY(lang_transform_item(p, xf, matched));
	*was_transform = *matched;
	return true;
}

/* media = "media" "{" [ identifier ] { media_item } "}"
 * media_item = ( "absorption" | "emission" ) colour | scattering | density
 *            | "method" int | "intervals" int | "samples" int [ "," int ] | "aa_level" int
 *            | ( "confidence" | "variance" | "ratio" | "jitter" | "aa_threshold" ) float
 *            | transform_item
 * The sampling items are accepted and unused (circe's path tracer needs none); a transform moves
 * the densities given in the block. */
static bool media_block(parser *p, scene_media *md)
{
	diag_loc open, kw = lang_advance(p)->loc;
	TRY(open_block(p, "media", &open));
	*md = (scene_media){.loc = kw, .extinction = 1.0f, .method = 3};
	if (lang_peek(p)->kind == LTK_IDENT) {
		const value *v;
		TRY(v = declared(p, VAL_MEDIA, "a media"));
		*md = v->mat->media[0];
		md->loc = kw;
	}
	xform xf = xform_identity();
	bool moved = false;
	for (;;) {
		bool matched, was_transform;
		TRY(media_item(p, md, &xf, &matched, &was_transform));
		if (!matched)
			break;
		moved |= was_transform;
	}
	if (moved)
		for (uint32_t i = 0; i < md->n_density; i++)
			TRY(md->density[i] = lang_pigment_moved(p, md->density[i], &xf, kw));
	if (lang_peek(p)->kind != LTK_RBRACE)
		return bad_item(p, open, "media",
				"absorption, emission, scattering, density, method, intervals, samples, confidence, "
				"variance, ratio, jitter, aa_level, aa_threshold or a transform");
	return lang_expect_close(p, open, "media");
}

/* An interior's media, after those it holds (each in the arena: a record is never changed once
 * made, so the list is copied). */
static bool interior_media(parser *p, scene_material *m)
{
	diag_loc at = lang_peek(p)->loc;
	if (m->n_media == SCENE_MEDIA_MAX)
		return lang_error(p, at, "too many media in one interior (limit is %d)", SCENE_MEDIA_MAX);
	scene_media *list = arena_zalloc(&p->sc->arena, m->n_media + 1u, sizeof *list);
	if (!list)
		return lang_error(p, at, "out of memory");
	for (uint32_t i = 0; i < m->n_media; i++)
		list[i] = m->media[i];
	TRY(media_block(p, &list[m->n_media]));
	m->media = list, m->n_media++;
	return true;
}

/* One interior item after its word w (at loc): POV-Ray's parse_materials.cpp Parse_Interior. */
static bool interior_item(parser *p, scene_material *m, interior_word w, diag_loc loc)
{
	double x;
	switch (w) {
	case IW_FADE_COLOR:
	case IW_FADE_COLOUR:
		return physical_color(p, "after 'fade_color'", "fade_color", SCENE_COLOR_REFLECTANCE, &m->fade_color);
	case IW_FADE_DISTANCE:
	case IW_FADE_POWER:
		TRY(lang_float(p, w == IW_FADE_POWER ? "after 'fade_power'" : "after 'fade_distance'", &x));
		if (!(x >= 0))
			return lang_error(p, loc, "%s must be >= 0, found %g", w == IW_FADE_POWER ? "fade_power" : "fade_distance",
					  x);
		*(w == IW_FADE_POWER ? &m->fade_power : &m->fade_distance) = (float)x;
		return true;
	case IW_DISPERSION:
	case IW_DISPERSION_SAMPLES:
	case IW_CAUSTICS:
	case IW_REFRACTION:
		TRY(lang_float(p, "after it", &x));
		diag_warning(p->d, loc, "'%s' is accepted and ignored by circe (%s)",
			     w == IW_DISPERSION ? "dispersion" : w == IW_CAUSTICS ? "caustics"
						: w == IW_REFRACTION ? "refraction" : "dispersion_samples",
			     w == IW_CAUSTICS ? "a path tracer finds caustics by its paths"
			     : w == IW_REFRACTION ? "POV-Ray 3's refraction is on wherever ior is given"
						 : "the ior is one for every wavelength");
		return true;
	default: /* IW_MEDIA: interior() reads it */
		return lang_error(p, loc, "internal: media");
	}
}

/* interior = "interior" "{" [ identifier ] { interior_item } "}"
 * interior_item = "ior" float | "fade_distance" float | "fade_power" float
 *               | ( "fade_color" | "fade_colour" ) colour
 *               | ( "dispersion" | "dispersion_samples" | "caustics" | "refraction" ) float   (ignored)
 * An interior gives the object an inside: ior 1 unless it says. */
static bool interior(parser *p, scene_material *m)
{
	diag_loc open;
	lang_advance(p);
	TRY(open_block(p, "interior", &open));
	if (lang_peek(p)->kind == LTK_IDENT) {
		const value *v;
		TRY(v = declared(p, VAL_INTERIOR, "an interior"));
		copy_interior(m, v->mat);
	}
	if (!(m->ior > 0))
		m->ior = 1.0f;
	for (;;) {
		lang_token t = *lang_peek(p);
		if (t.kind == LTK_KW_IOR) {
			lang_advance(p);
			double x;
			TRY(lang_float(p, "after 'ior'", &x) && positive(p, t.loc, "ior", x));
			m->ior = (float)x;
			continue;
		}
		interior_word w = interior_word_at(&t);
		if (w == IW_NONE)
			break;
		if (w == IW_MEDIA) {
			TRY(interior_media(p, m));
			continue;
		}
		lang_advance(p);
		TRY(interior_item(p, m, w, t.loc));
	}
	if ((m->fade_distance > 0) != (m->fade_power > 0))
		diag_warning(p->d, open, "an interior fades with both fade_distance and fade_power > 0; with one of them "
					 "0 (their default) circe does not fade");
	return lang_expect_close(p, open, "interior");
}

static const scene_material *declared_material(parser *p)
{
	const value *v = declared(p, VAL_MATERIAL, "a material");
	return v ? v->mat : NULL;
}

static bool texture(parser *p, const scene_material **out, bool *fresh);
static bool texture_body(parser *p, diag_loc kw, diag_loc open, lang_tok close, const scene_material **out,
			 bool *fresh);

/* lang_texture_fn for a patterned texture's entries: `texture { }`, or a body up to ']'. */
static bool texture_entry(parser *p, lang_tok close, const scene_material **out)
{
	if (close == LTK_RBRACE)
		return texture(p, out, NULL);
	diag_loc at = lang_peek(p)->loc;
	return texture_body(p, at, at, close, out, NULL);
}

/* Whether two textures light alike (every field of their finish): a patterned texture of such
 * entries is one BSDF over their blended pigment; else each entry is lit with its own. */
static bool same_finish(const scene_material *a, const scene_material *b)
{
	const scene_finish *f = &a->finish, *g = &b->finish;
	return a->diffuse == b->diffuse && a->specular == b->specular && a->roughness == b->roughness &&
	       f->phong == g->phong && f->phong_size == g->phong_size && f->metallic == g->metallic &&
	       !memcmp(&f->refl_min, &g->refl_min, sizeof f->refl_min) &&
	       !memcmp(&f->refl_max, &g->refl_max, sizeof f->refl_max) && f->refl_fresnel == g->refl_fresnel &&
	       f->refl_falloff == g->refl_falloff && f->refl_metallic == g->refl_metallic &&
	       f->brilliance == g->brilliance && f->diffuse_albedo == g->diffuse_albedo &&
	       !memcmp(&f->emission, &g->emission, sizeof f->emission) &&
	       f->has_ambient == g->has_ambient && !memcmp(&f->ambient, &g->ambient, sizeof f->ambient) &&
	       f->subsurface == g->subsurface && !memcmp(&f->translucency_mm, &g->translucency_mm, sizeof f->translucency_mm);
}

/* The normal of a patterned texture whose entries have normals: the same pattern (its
 * parameters, warps, transforms) with a normal_map of the entries' normals (render/pattern.c's
 * normal_map), an entry without one leaving the normal as it is. */
static bool pattern_texture_normal(parser *p, const scene_pigment *pig, const scene_material *const *mats,
				   uint32_t n, const scene_pigment **out)
{
	*out = NULL;
	bool any = false;
	for (uint32_t i = 0; i < n; i++)
		any = any || mats[i]->normal;
	if (!any)
		return true;
	scene_pigment *nrm = arena_zalloc(&p->sc->arena, 1, sizeof *nrm);
	scene_pigment *flat = arena_zalloc(&p->sc->arena, 1, sizeof *flat);
	scene_map_entry *e = arena_zalloc(&p->sc->arena, n, sizeof *e);
	if (!nrm || !flat || !e)
		return lang_error(p, pig->loc, "out of memory");
	*flat = scene_pigment_defaults(SCENE_PAT_PLAIN, pig->loc);
	flat->is_normal = true;
	for (uint32_t i = 0; i < n && i < pig->n_entries; i++)
		e[i] = (scene_map_entry){.value = pig->entries[i].value, .pigment = mats[i]->normal ? mats[i]->normal : flat};
	*nrm = *pig;
	nrm->entries = e, nrm->n_entries = n < pig->n_entries ? n : pig->n_entries, nrm->is_normal = true;
	*out = nrm;
	return true;
}

/* pattern_texture = pattern [ "texture" "{" texture_body "}" { [ "," ] ... } ]
 *                   { pattern_modifier | "texture_map" "{" { "[" float texture_body "]" } "}" }
 * POV-Ray's patterned texture (its pattern's value picks or blends the entries' textures). circe
 * blends the entries' pigments by the pattern (each evaluated where the surface is, SSS entry
 * points too) and their normals when they have any (as a normal_map). When the entries' finishes
 * differ or one is layered, each entry is lit with its own finish (map_textures: render/world.c's
 * shade_map); else, and when one has a subsurface, the finish is the first entry's (doc/language.md
 * "Patterned textures"). */
static bool pattern_texture(parser *p, diag_loc kw, diag_loc open, lang_tok close, const scene_material **out)
{
	const scene_pigment *pig;
	const scene_material *const *mats;
	uint32_t n;
	TRY(lang_texture_pattern(p, open, close, texture_entry, &pig, &mats, &n));
	scene_material *m = copy_material(p, mats[0], kw);
	TRY(m);
	m->pigment = pig, m->image = NULL, m->filter = m->transmit = 0.0f;
	m->layers = NULL, m->n_layers = 0; /* the entries' layers: below, with map_textures */
	m->map_textures = NULL, m->n_map_textures = 0;
	TRY(pattern_texture_normal(p, pig, mats, n, &m->normal));
	/* Layered entries, or entries of different finishes: every entry is lit with its own finish
	 * (per layer), as POV-Ray's ComputeOneTextureColour lights each entry before the blend. */
	bool own = false, sss = false;
	for (uint32_t i = 0; i < n; i++) {
		own = own || (mats[i]->n_layers && mats[i]->kind == MAT_TEXTURE) || !same_finish(mats[0], mats[i]);
		sss = sss || mats[i]->finish.subsurface;
	}
	if (own && sss) /* one medium a material (build_sss): the first entry's */
		diag_warning(p->d, kw, "the textures of this pattern differ in their finish and one has a subsurface: "
				       "circe lights them all with the first one's (the pigments and normals follow the "
				       "pattern)");
	else if (own && n == pig->n_entries)
		m->map_textures = mats, m->n_map_textures = n;
	*out = m;
	return true;
}

/* A texture's uv_mapping: its pigment's and normal's patterns evaluated at the surface's <u, v, 0>
 * (copies of their trees' roots; a plain colour has nothing to map). */
static bool texture_uv_mapping(parser *p, scene_material *m, diag_loc at)
{
	const scene_pigment **trees[2] = {&m->pigment, &m->normal};
	for (int i = 0; i < 2; i++) {
		if (!*trees[i] || (*trees[i])->uv_mapping)
			continue;
		scene_pigment *c = arena_zalloc(&p->sc->arena, 1, sizeof *c);
		if (!c)
			return lang_error(p, at, "out of memory");
		*c = **trees[i];
		c->uv_mapping = true;
		*trees[i] = c;
	}
	return true;
}

/* texture = "texture" "{" texture_body "}"
 * *fresh (may be NULL) tells whether the record is new, hence the caller's to modify. */
static bool texture(parser *p, const scene_material **out, bool *fresh)
{
	if (fresh)
		*fresh = false;
	diag_loc kw = lang_advance(p)->loc, open;
	TRY(open_block(p, "texture", &open));
	return texture_body(p, kw, open, LTK_RBRACE, out, fresh);
}

/* texture_body = [ identifier ] { pigment | finish | normal | "uv_mapping" | transform_item } | pattern_texture
 * up to close ('}', or a texture_map entry's ']'). */
static bool texture_body(parser *p, diag_loc kw, diag_loc open, lang_tok close, const scene_material **out,
			 bool *fresh)
{
	if (fresh)
		*fresh = false;
	if (lang_texture_pattern_starts(p)) {
		TRY(pattern_texture(p, kw, open, close, out));
		if (fresh)
			*fresh = true;
		return true;
	}
	const scene_material *base = NULL;
	if (lang_peek(p)->kind == LTK_IDENT)
		TRY(base = declared_material(p));
	if (base && lang_peek(p)->kind == close) {
		lang_advance(p);
		*out = base;
		return true;
	}
	scene_material *m = base ? copy_material(p, base, kw) : new_texture(p, kw);
	TRY(m);
	if (base && m->kind != MAT_TEXTURE)
		return lang_error(p, kw, "'texture' needs a texture, but this one is a %s material",
				  scene_material_kind_name(m->kind));
	diag_loc moved = {0};
	bool uv = false;
	for (;;) {
		lang_tok k = lang_peek(p)->kind;
		bool matched;
		if (k == LTK_KW_PIGMENT)
			TRY(pigment(p, m, SCENE_COLOR_REFLECTANCE));
		else if (k == LTK_KW_FINISH)
			TRY(finish(p, m));
		else if (lang_normal_starts(p))
			TRY(lang_normal(p, m));
		else if (k == close)
			break;
		else if (k == LTK_KW_OBJECT) /* POV-Ray's object pattern after a texture's items */
			return lang_error(p, lang_peek(p)->loc, "the object pattern of a texture comes first in it, before "
								"its pigment, normal and finish");
		else if (lang_word_is(lang_peek(p), "uv_mapping")) /* POV-Ray's: the whole texture at <u, v, 0> */
			lang_advance(p), uv = true;
		else {
			TRY(pattern_transform_item(p, m, &moved, &matched));
			if (!matched)
				return bad_item(p, open, "texture", "pigment, normal, finish, uv_mapping or a transform");
		}
	}
	lang_advance(p);
	TRY(pattern_transform(p, m, moved, "texture"));
	if (uv)
		TRY(texture_uv_mapping(p, m, kw));
	*out = m;
	if (fresh)
		*fresh = true;
	return true;
}

/* Records that the SSS parameter t gives form f: an error when the other form was given. */
static bool form(parser *p, scene_material *m, sss_form f, const lang_token *t)
{
	scene_sss *s = &m->sss;
	if (s->medium.form != SSS_FORM_DEFAULT && s->medium.form != f) {
		diag_loc other = f == SSS_FORM_PHYSICAL ? s->artist_loc : s->physical_loc;
		return lang_error(p, t->loc,
				  "'%.*s' gives the %s form, but the %s form was given at line %u; give sigma_s/sigma_a "
				  "(or a preset) or color/radius, not both",
				  (int)t->len, t->text, f == SSS_FORM_PHYSICAL ? "physical" : "artist",
				  f == SSS_FORM_PHYSICAL ? "artist" : "physical", other.line);
	}
	if (s->medium.form == SSS_FORM_DEFAULT) {
		if (f == SSS_FORM_PHYSICAL)
			s->physical_loc = t->loc;
		else
			s->artist_loc = t->loc;
	}
	s->medium.form = f;
	return true;
}

static bool positive3(parser *p, diag_loc loc, const char *what, vec3 c)
{
	if (c.x > 0 && c.y > 0 && c.z > 0)
		return true;
	return lang_error(p, loc, "%s must be > 0 in every channel, found <%g, %g, %g>", what, c.x, c.y, c.z);
}

/* The most characters of the list of preset names in a message. */
#define SSS_PRESET_LIST_MAX 256

/* colour: the artist form's albedo, in [0, 1]. */
static bool sss_colour(parser *p, scene_material *m, const lang_token *t)
{
	sss_medium_spec *s = &m->sss.medium;
	TRY(form(p, m, SSS_FORM_ARTIST, t));
	TRY(lang_color(p, "as the SSS colour", &s->albedo));
	if (!(s->albedo.x >= 0 && s->albedo.y >= 0 && s->albedo.z >= 0 && s->albedo.x <= 1 && s->albedo.y <= 1 &&
	      s->albedo.z <= 1))
		return lang_error(p, t->loc, "SSS colour must be in [0, 1] in every channel, found <%g, %g, %g>",
				  s->albedo.x, s->albedo.y, s->albedo.z);
	s->has |= SSS_HAS_ALBEDO;
	return true;
}

/* "preset" string: the physical form of a measured medium (sss/medium.h), replacing any sigma_s
 * or sigma_a written before it. */
static bool sss_preset_item(parser *p, scene_material *m, const lang_token *t)
{
	lang_advance(p);
	TRY(form(p, m, SSS_FORM_PHYSICAL, t));
	diag_loc sloc = lang_peek(p)->loc;
	const char *name;
	TRY(lang_string(p, "after 'preset'", &name));
	const sss_preset *pr = sss_preset_find(name);
	if (!pr) {
		char list[SSS_PRESET_LIST_MAX];
		size_t n = 0;
		for (int i = 0; i < sss_n_presets && n < sizeof list; i++)
			n += (size_t)snprintf(list + n, sizeof list - n, "%s%s", i ? ", " : "", sss_presets[i].name);
		return lang_error(p, sloc, "unknown preset '%s' (presets: %s)", name, list);
	}
	m->sss.medium.preset = pr->name;
	m->sss.medium.has &= ~(unsigned)(SSS_HAS_SIGMA_S | SSS_HAS_SIGMA_A);
	return true;
}

/* "sigma_s" colour | "sigma_a" colour: one coefficient of the physical form, per mm, > 0. */
static bool sss_sigma(parser *p, scene_material *m, const lang_token *t)
{
	bool scat = t->kind == LTK_KW_SIGMA_S;
	sss_medium_spec *s = &m->sss.medium;
	lang_advance(p);
	TRY(form(p, m, SSS_FORM_PHYSICAL, t));
	vec3 *c = scat ? &s->sigma_s_per_mm : &s->sigma_a_per_mm;
	TRY(lang_color(p, scat ? "after 'sigma_s'" : "after 'sigma_a'", c));
	TRY(positive3(p, t->loc, scat ? "sigma_s" : "sigma_a", *c));
	s->has |= scat ? SSS_HAS_SIGMA_S : SSS_HAS_SIGMA_A;
	return true;
}

/* "image" string | "radius" colour: the artist form's albedo texture, or its radius (mm, > 0). */
static bool sss_artist_item(parser *p, scene_material *m, const lang_token *t)
{
	lang_advance(p);
	TRY(form(p, m, SSS_FORM_ARTIST, t));
	if (t->kind == LTK_KW_IMAGE)
		return asset_path(p, "after 'image'", SCENE_ASSET_IMAGE, &m->sss.albedo_image);
	TRY(lang_color(p, "after 'radius'", &m->sss.medium.radius_mm));
	TRY(positive3(p, t->loc, "radius", m->sss.medium.radius_mm));
	m->sss.medium.has |= SSS_HAS_RADIUS;
	return true;
}

/* "ior" float | "roughness" float | "anisotropy" float: the boundary and the phase function. */
static bool sss_number(parser *p, scene_sss *s, const lang_token *t)
{
	double x;
	lang_advance(p);
	switch (t->kind) {
	case LTK_KW_IOR:
		TRY(lang_float(p, "after 'ior'", &x) && positive(p, t->loc, "ior", x));
		s->ior = (float)x;
		return true;
	case LTK_KW_ROUGHNESS:
		TRY(lang_float(p, "after 'roughness'", &x) && in_range(p, t->loc, "roughness", x, 0, 1));
		s->roughness = (float)x;
		return true;
	default: /* LTK_KW_ANISOTROPY */
		TRY(lang_float(p, "after 'anisotropy'", &x) && in_range(p, t->loc, "anisotropy", x, -0.99, 0.99));
		s->anisotropy = (float)x;
		return true;
	}
}

/* "profile" ( "gaussian" | "sum_of_gaussians" | "burley" | "dipole" ) | "method" ( "circle" |
 * "fullcircle" | "disk" | "volume" | "auto" ): the keywords in the order of sss_profile_kind and of
 * sss_method after its default. */
static bool sss_choice(parser *p, scene_sss *s, const lang_token *t)
{
	static const lang_tok profiles[] = {LTK_KW_GAUSSIAN, LTK_KW_SUM_OF_GAUSSIANS, LTK_KW_BURLEY, LTK_KW_DIPOLE};
	static const lang_tok methods[] = {LTK_KW_CIRCLE, LTK_KW_FULLCIRCLE, LTK_KW_DISK, LTK_KW_VOLUME, LTK_KW_AUTO};
	lang_advance(p);
	if (t->kind == LTK_KW_PROFILE) {
		int i = one_of(p, profiles, 4, "expected gaussian, sum_of_gaussians, burley or dipole after 'profile'");
		TRY(i >= 0);
		s->profile = (sss_profile_kind)i;
	} else {
		int i = one_of(p, methods, 5, "expected circle, fullcircle, disk, volume or auto after 'method'");
		TRY(i >= 0);
		s->method = (sss_method)(SSS_METHOD_CIRCLE + i);
	}
	return true;
}

/* "normal_map" string [ "strength" float ] */
static bool sss_normal_map(parser *p, scene_sss *s)
{
	lang_advance(p);
	TRY(asset_path(p, "after 'normal_map'", SCENE_ASSET_IMAGE, &s->normal_map));
	if (lang_peek(p)->kind == LTK_KW_STRENGTH) {
		double x;
		lang_advance(p);
		TRY(lang_float(p, "after 'strength'", &x));
		s->normal_strength = (float)x;
	}
	return true;
}

/* sss_param = "preset" string | "sigma_s" colour | "sigma_a" colour | colour
 *           | "image" string | "radius" colour | "ior" float | "roughness" float
 *           | "profile" ( "gaussian" | "sum_of_gaussians" | "burley" | "dipole" )
 *           | "normal_map" string [ "strength" float ] | "anisotropy" float
 *           | "method" ( "circle" | "fullcircle" | "disk" | "volume" | "auto" ) | "group" string */
/* "pigment" "{" pattern ... "}": a POV-Ray pigment as the albedo, evaluated where light leaves and
 * where it enters (circle tracing's colour blurring), each entry weighted by pigment / albedo. */
static bool sss_pigment(parser *p, scene_material *m, const lang_token *t)
{
	scene_material *part = new_part(p, t->loc);
	TRY(part);
	TRY(pigment(p, part, SCENE_COLOR_REFLECTANCE));
	if (!part->pigment)
		return lang_error(p, t->loc, "a pigment of one colour in an SSS block: give it as 'color' (the albedo)");
	m->sss.pigment = part->pigment;
	return true;
}

static bool sss_param(parser *p, scene_material *m, diag_loc open, const char *what)
{
	lang_token t = *lang_peek(p);
	if (starts_colour(p))
		return sss_colour(p, m, &t);
	switch (t.kind) {
	case LTK_KW_PRESET:
		return sss_preset_item(p, m, &t);
	case LTK_KW_SIGMA_S:
	case LTK_KW_SIGMA_A:
		return sss_sigma(p, m, &t);
	case LTK_KW_IMAGE:
	case LTK_KW_RADIUS:
		return sss_artist_item(p, m, &t);
	case LTK_KW_IOR:
	case LTK_KW_ROUGHNESS:
	case LTK_KW_ANISOTROPY:
		return sss_number(p, &m->sss, &t);
	case LTK_KW_PROFILE:
	case LTK_KW_METHOD:
		return sss_choice(p, &m->sss, &t);
	case LTK_KW_NORMAL_MAP:
		return sss_normal_map(p, &m->sss);
	case LTK_KW_GROUP:
		lang_advance(p);
		return lang_string(p, "after 'group'", &m->sss.group);
	case LTK_KW_PIGMENT:
		return sss_pigment(p, m, &t);
	default:
		return bad_item(p, open, what, "an SSS parameter (preset, sigma_s, sigma_a, color, radius, ior, ...)");
	}
}

/* sss_block = ( "skin" | "wax" | "marble" ) "{" { sss_param } "}"
 * The block's defaults (scene_sss_defaults), then the parameters as written: the medium's other
 * form is the build's to derive (sss_medium_derive). */
static bool sss_block(parser *p, scene_material *m)
{
	lang_token kw = *lang_advance(p);
	const char *what = kw.kind == LTK_KW_SKIN ? "skin" : kw.kind == LTK_KW_WAX ? "wax" : "marble";
	diag_loc open;
	TRY(open_block(p, what, &open));
	scene_sss_defaults(m);
	while (lang_peek(p)->kind != LTK_RBRACE)
		TRY(sss_param(p, m, open, what));
	lang_advance(p);
	return true;
}

/* material = "material" "{" [ identifier ] { material_item } "}"
 * material_item = "diffuse" "{" ( colour | "image" string ) "}" | sss_block | texture
 *               | interior | "emission" colour | transform_item */
static bool material(parser *p, const scene_material **out)
{
	diag_loc kw = lang_advance(p)->loc, open;
	TRY(open_block(p, "material", &open));
	const scene_material *base = NULL;
	if (lang_peek(p)->kind == LTK_IDENT)
		TRY(base = declared_material(p));
	if (base && lang_peek(p)->kind == LTK_RBRACE) {
		lang_advance(p);
		*out = base;
		return true;
	}
	scene_material *m = base ? copy_material(p, base, kw) : new_material(p, kw, MAT_DIFFUSE);
	TRY(m);
	bool has_kind = base != NULL, has_emission = false;
	diag_loc kind_loc = kw, moved = {0};
	for (;;) {
		lang_token t = *lang_peek(p);
		if (t.kind == LTK_RBRACE)
			break;
		bool matched;
		TRY(pattern_transform_item(p, m, &moved, &matched));
		if (matched)
			continue;
		bool is_kind = t.kind == LTK_KW_DIFFUSE || t.kind == LTK_KW_SKIN || t.kind == LTK_KW_WAX ||
			       t.kind == LTK_KW_MARBLE || t.kind == LTK_KW_TEXTURE;
		if (is_kind && has_kind)
			return lang_error(p, t.loc, "a material has one kind: '%.*s' after the one at line %u", (int)t.len,
					  t.text, kind_loc.line);
		if (is_kind)
			has_kind = true, kind_loc = t.loc;
		switch (t.kind) {
		case LTK_KW_DIFFUSE: {
			diag_loc dopen;
			lang_advance(p);
			TRY(open_block(p, "diffuse", &dopen));
			m->kind = MAT_DIFFUSE;
			if (lang_accept(p, LTK_KW_IMAGE))
				TRY(asset_path(p, "after 'image'", SCENE_ASSET_IMAGE, &m->image));
			else
				TRY(physical_color(p, "as the diffuse colour", "diffuse colour", SCENE_COLOR_REFLECTANCE,
						    &m->color));
			TRY(lang_expect_close(p, dopen, "diffuse"));
			break;
		}
		case LTK_KW_SKIN:
		case LTK_KW_WAX:
		case LTK_KW_MARBLE:
			m->kind = t.kind == LTK_KW_SKIN ? MAT_SKIN : t.kind == LTK_KW_WAX ? MAT_WAX : MAT_MARBLE;
			TRY(sss_block(p, m));
			break;
		case LTK_KW_TEXTURE: {
			const scene_material *tex;
			TRY(texture(p, &tex, NULL));
			scene_material keep = *m; /* an interior given before the texture stays */
			*m = *tex;
			m->id = keep.id, m->next = keep.next, m->loc = kw, m->name = NULL, m->emission = keep.emission;
			if (keep.ior > 0)
				copy_interior(m, &keep);
			break;
		}
		case LTK_KW_INTERIOR:
			TRY(interior(p, m));
			break;
		case LTK_KW_EMISSION:
			lang_advance(p);
			TRY(physical_color(p, "after 'emission'", "emission", SCENE_COLOR_RADIANCE, &m->emission));
			has_emission = true;
			break;
		default:
			return bad_item(p, open, "material", "diffuse, texture, skin, wax, marble, interior or emission");
		}
	}
	lang_advance(p);
	TRY(pattern_transform(p, m, moved, "material"));
	if (!has_kind && !has_emission)
		return lang_error(p, kw, "empty material: give diffuse, texture, skin, wax, marble, emission or a declared "
					 "material");
	if (!has_kind) {
		m->kind = MAT_EMISSION;
		m->color = v3s(0.0f);
	}
	*out = m;
	return true;
}

/* ---- object modifiers -------------------------------------------------------------------- */

typedef struct mods {
	xform t;
	const scene_material *mat;
	diag_loc mat_loc;
	xform t_at_mat; /* t when the material was given: the transforms before it do not move its pattern */
	scene_material *tex; /* made by a bare pigment or finish on this item */
	bool no_shadow;
	lang_objflags flags; /* hollow, no_image, ... (objmods.c) */
	scene_material *interior; /* a part record (new_part), or NULL */
	diag_loc interior_loc;
	bool mat_is_texture; /* mat came from texture { }: another texture layers on it */
	bool inverse; /* inverse (each one toggles) */
	/* clipped_by: its objects (in the arena; their transforms already undo the item's transforms
	 * before clipped_by, which apply_mods then applies), operands 1.. of the clip node clip_id. */
	scene_object *clip;
	size_t n_clip;
	uint32_t clip_id, clip_operands;
	diag_loc clip_loc;
	scene_object *bound; /* bounded_by's objects, kept for a clipped_by { bounded_by } */
	size_t n_bound;
	diag_loc bound_loc;
	bool bound_clips; /* the bound's objects are clipping objects already */
	bool uv; /* uv_mapping on the object: its textures at <u, v, 0> */
	diag_loc uv_loc;
} mods;

/* No CSG solid nests deeper than this (its evaluation walks the path of each hit). */
#define LANG_MAX_CSG_DEPTH 64

/* Prepends the step to the CSG paths of objs[0..n) (each gets a new path in the arena). */
static bool csg_prepend(parser *p, scene_object *objs, size_t n, scene_csg_step step)
{
	for (size_t i = 0; i < n; i++) {
		scene_object *o = &objs[i];
		if (o->csg_depth >= LANG_MAX_CSG_DEPTH)
			return lang_error(p, step.loc, "CSG nested deeper than %d levels", LANG_MAX_CSG_DEPTH);
		scene_csg_step *path = arena_zalloc(&p->sc->arena, o->csg_depth + 1, sizeof *path);
		if (!path)
			return lang_error(p, step.loc, "out of memory");
		path[0] = step;
		if (o->csg_depth)
			memcpy(path + 1, o->csg, o->csg_depth * sizeof *path);
		o->csg = path;
		o->csg_depth++;
	}
	return true;
}

static bool object_item(parser *p, vecbuf *out, bool *matched);

/* object_item where the objects are not placed in the scene (`where`: clipped_by, bounded_by,
 * looks_like, projected_through, an object pattern's object, a mesh_camera's mesh): a
 * light_source in their CSG is refused there, and a declared copy's lights light nothing
 * (declared_object). */
static bool object_item_unplaced(parser *p, vecbuf *out, bool *matched, const char *where)
{
	bool saved = p->lights_in_csg;
	const char *saved_where = p->unplaced;
	p->lights_in_csg = false, p->unplaced = where;
	bool ok = object_item(p, out, matched);
	p->lights_in_csg = saved, p->unplaced = saved_where;
	return ok;
}

/* The objects of a clipped_by or bounded_by block, parsed into a temporary buffer and kept in the
 * arena (*objs, *n, appended to): each object item one operand, numbered from *operands on, of
 * the node `id` when id is not 0. */
static bool clip_objects(parser *p, diag_loc open, const char *what, uint32_t id, uint32_t *operands,
			 scene_object **objs, size_t *n)
{
	vecbuf b;
	vecbuf_init(&b, sizeof(scene_object));
	bool ok = true, any = false;
	while (ok && lang_peek(p)->kind != LTK_RBRACE) {
		size_t from = b.len;
		bool matched;
		ok = object_item_unplaced(p, &b, &matched, what);
		if (ok && !matched)
			ok = bad_item(p, open, what, "an object");
		any = true;
		if (ok && id)
			ok = csg_prepend(p, &VECBUF_AT(&b, scene_object, from), b.len - from,
					 (scene_csg_step){id, (*operands)++, SCENE_CSG_INTERSECTION, false, open});
	}
	if (ok && !any)
		ok = lang_error(p, open, "%s has no objects", what);
	scene_object *all = NULL;
	if (ok && !(all = arena_zalloc(&p->sc->arena, *n + b.len, sizeof *all)))
		ok = lang_error(p, open, "out of memory");
	if (ok) {
		if (*n)
			memcpy(all, *objs, *n * sizeof *all);
		if (b.len)
			memcpy(all + *n, b.data, b.len * sizeof *all);
		*objs = all, *n += b.len;
		lang_advance(p);
	}
	vecbuf_free(&b);
	return ok;
}

/* The bound's objects made clipping objects (one operand of the clip node, as one union). */
static bool bound_clips(parser *p, mods *m, diag_loc kw)
{
	if (m->bound_clips)
		return true;
	m->bound_clips = true;
	if (!m->clip_id)
		m->clip_id = ++p->sc->csg_ids, m->clip_operands = 1, m->clip_loc = kw;
	scene_object *all = arena_zalloc(&p->sc->arena, m->n_clip + m->n_bound, sizeof *all);
	if (!all)
		return lang_error(p, kw, "out of memory");
	if (m->n_clip)
		memcpy(all, m->clip, m->n_clip * sizeof *all);
	memcpy(all + m->n_clip, m->bound, m->n_bound * sizeof *all);
	for (size_t i = 0; i < m->n_bound; i++) { /* the bound's transforms were undone already */
		all[m->n_clip + i].clip_only = true;
		TRY(csg_prepend(p, &all[m->n_clip + i], 1,
				(scene_csg_step){m->clip_id, m->clip_operands, SCENE_CSG_INTERSECTION, false, kw}));
	}
	m->clip_operands++;
	m->clip = all, m->n_clip += m->n_bound;
	return true;
}

/* clipped_by = "clipped_by" "{" ( object_item { object_item } | "bounded_by" ) "}"
 * bounded_by = "bounded_by" "{" ( object_item { object_item } | "clipped_by" ) "}"
 * POV-Ray's clipped_by keeps the item's surface inside every clipping object (their surfaces are
 * not seen); bounded_by is a hint for its own intersection tests, which circe needs not: read,
 * and kept for a clipped_by { bounded_by } after it, and to clip a quadric, cubic, quartic or poly
 * (csg_mods: circe polygonises those inside their bound). Transforms after the block move the
 * clipping objects with the item; those before it do not. */
static bool clip_block(parser *p, mods *m, bool clip)
{
	diag_loc kw = lang_advance(p)->loc, open;
	const char *what = clip ? "clipped_by" : "bounded_by";
	TRY(open_block(p, what, &open));
	xform undo = xform_inverse(m->t);
	size_t from = clip ? m->n_clip : m->n_bound;
	lang_token t = *lang_peek(p);
	if (t.kind == (clip ? LTK_KW_BOUNDED_BY : LTK_KW_CLIPPED_BY)) {
		lang_advance(p);
		TRY(lang_expect_close(p, open, what));
		if (!clip) /* bounded_by { clipped_by }: bounded by the clip, a hint again */
			return true;
		if (!m->n_bound)
			return lang_error(p, t.loc, "'clipped_by { bounded_by }' needs a bounded_by before it");
		return bound_clips(p, m, kw);
	}
	if (clip && !m->clip_id)
		m->clip_id = ++p->sc->csg_ids, m->clip_operands = 1, m->clip_loc = kw;
	if (clip)
		TRY(clip_objects(p, open, what, m->clip_id, &m->clip_operands, &m->clip, &m->n_clip));
	else if (!m->n_bound)
		m->bound_loc = kw;
	if (!clip)
		TRY(clip_objects(p, open, what, 0, NULL, &m->bound, &m->n_bound));
	scene_object *objs = clip ? m->clip : m->bound;
	size_t n = clip ? m->n_clip : m->n_bound;
	for (size_t i = from; i < n; i++) {
		objs[i].transform = xform_then(objs[i].transform, undo);
		objs[i].clip_only = clip;
	}
	return true;
}

static bool set_material(parser *p, mods *m, const scene_material *mat, diag_loc loc)
{
	if (m->mat)
		return lang_error(p, loc, "a second material on the same object (the first is at line %u)", m->mat_loc.line);
	m->mat = mat;
	m->mat_loc = loc;
	m->t_at_mat = m->t;
	return true;
}

/* The texture a bare pigment, finish or normal of the object changes (m->tex): made now, or, after
 * a declared texture (`texture { Black_Chocolate } normal { bumps 0.3 }`: biscuit.pov), a copy of
 * it (POV-Ray changes the object's top texture layer, a copy of the declared one). */
static bool own_texture(parser *p, mods *m, diag_loc loc)
{
	if (m->tex)
		return true;
	if (m->mat && m->mat_is_texture && m->mat->kind == MAT_TEXTURE) {
		TRY(m->tex = copy_material(p, m->mat, loc));
		m->mat = m->tex;
		return true;
	}
	TRY(m->tex = new_texture(p, loc));
	return set_material(p, m, m->tex, loc);
}

/* modifier = transform_item | material | texture | pigment | finish | interior | "no_shadow"
 *          | object_flag */
static bool modifier(parser *p, mods *m, bool *matched)
{
	lang_token t = *lang_peek(p);
	TRY(transform_item(p, &m->t, matched));
	if (*matched)
		return true;
	*matched = true;
	if (lang_normal_starts(p)) { /* normal { } on the object: its texture's, as a bare pigment */
		TRY(own_texture(p, m, t.loc));
		return lang_normal(p, m->tex);
	}
	switch (t.kind) {
	case LTK_KW_INVERSE:
		lang_advance(p);
		m->inverse = !m->inverse;
		return true;
	case LTK_KW_CLIPPED_BY:
	case LTK_KW_BOUNDED_BY:
		return clip_block(p, m, t.kind == LTK_KW_CLIPPED_BY);
	case LTK_KW_MATERIAL: {
		const scene_material *mat;
		TRY(material(p, &mat));
		return set_material(p, m, mat, t.loc);
	}
	case LTK_KW_TEXTURE: {
		const scene_material *mat;
		bool fresh;
		TRY(texture(p, &mat, &fresh));
		/* a texture after a texture, or after a bare pigment, finish or normal (POV-Ray's
		 * Link_Textures: glasschess's `pigment { rgbf 0.9 } texture { Glass }`): its layer on top */
		if (m->mat && (m->mat_is_texture || (m->mat == m->tex && m->mat->kind == MAT_TEXTURE))) {
			TRY(layer_texture(p, m->mat, mat, t.loc, &m->mat));
			m->tex = (scene_material *)m->mat;
			return true;
		}
		if (fresh)
			m->tex = (scene_material *)mat; /* made here: interior may set its ior */
		TRY(set_material(p, m, mat, t.loc));
		m->mat_is_texture = true;
		return true;
	}
	case LTK_KW_PIGMENT:
	case LTK_KW_FINISH:
		TRY(own_texture(p, m, t.loc));
		return t.kind == LTK_KW_PIGMENT ? pigment(p, m->tex, SCENE_COLOR_REFLECTANCE) : finish(p, m->tex);
	case LTK_KW_INTERIOR:
		if (!m->interior)
			TRY(m->interior = new_part(p, t.loc));
		m->interior_loc = t.loc;
		return interior(p, m->interior);
	case LTK_KW_NO_SHADOW:
		lang_advance(p);
		m->no_shadow = true;
		return true;
	case LTK_KW_STURM: /* POV-Ray's root solver for some shapes: a tessellated shape needs none */
		lang_advance(p);
		return true;
	default:
		if (lang_word_is(&t, "uv_mapping")) { /* POV-Ray's UV_MAPPING flag: the object's textures at <u, v, 0> */
			lang_advance(p);
			m->uv = true, m->uv_loc = t.loc;
			return true;
		}
		if (lang_word_is(&t, "interior_texture")) { /* read as a texture, then dropped */
			const scene_material *inner;
			lang_advance(p);
			diag_loc open;
			TRY(open_block(p, "interior_texture", &open));
			TRY(texture_body(p, t.loc, open, LTK_RBRACE, &inner, NULL));
			if (!(p->finish_warned & LANG_WARNED_INTERIOR_TEXTURE))
				diag_warning(p->d, t.loc, "'interior_texture' is ignored: circe shows the object's texture on "
							  "both sides of its surface (said once per scene)");
			p->finish_warned |= LANG_WARNED_INTERIOR_TEXTURE;
			return true;
		}
		return lang_object_flag(p, &m->flags, matched);
	}
}

/* Applies an item's modifiers to the objects it made (out[start..]). */
static bool apply_mods(parser *p, vecbuf *out, size_t start, mods *m)
{
	if (m->interior) {
		if (!m->mat && p->default_tex && p->default_tex->kind == MAT_TEXTURE) /* POV-Ray: the #default texture's */
			m->mat = p->default_tex, m->mat_loc = m->interior_loc, m->t_at_mat = m->t;
		if (!m->mat || m->mat->kind != MAT_TEXTURE)
			return lang_error(p, m->interior_loc, "'interior' sets the ior of a texture; this object has none");
		scene_material *mm = (scene_material *)m->mat; /* made or copied here, hence writable */
		if (m->mat != m->tex) {
			TRY(mm = copy_material(p, m->mat, m->mat_loc));
			m->mat = mm;
		}
		copy_interior(mm, m->interior);
	}
	const scene_material *uv_from = NULL, *uv_to = NULL; /* the last texture mapped, its copy */
	for (size_t i = start; i < out->len; i++) {
		scene_object *o = &VECBUF_AT(out, scene_object, i);
		if (m->uv && (o->material || m->mat) && (o->material ? o->material : m->mat)->kind == MAT_TEXTURE) {
			const scene_material *src = o->material ? o->material : m->mat;
			if (src != uv_from) {
				scene_material *c = copy_material(p, src, m->uv_loc);
				TRY(c && texture_uv_mapping(p, c, m->uv_loc));
				uv_from = src, uv_to = c;
			}
			if (o->material)
				o->material = uv_to;
		}
		if (!o->material && m->mat) { /* POV-Ray: a texture moves with the transforms after it */
			o->texture_from_object = xform_then(o->transform, m->t_at_mat);
			o->texture_placed = true;
		}
		o->transform = xform_then(o->transform, m->t);
		if (!o->material)
			o->material = m->uv && m->mat && m->mat == uv_from ? uv_to : m->mat;
		o->no_shadow |= m->no_shadow;
		lang_apply_object_flags(o, &m->flags);
	}
	return true;
}

/* The CSG modifiers of an item (before apply_mods): clipped_by (and bounded_by on a quadric,
 * cubic, quartic or poly) makes the item operand 0 of an intersection whose other operands are the
 * clipping objects; inverse toggles the item's own
 * inverse when it is one object, its CSG node's when it is one solid, else makes its objects one
 * inverted union. */
static bool csg_mods(parser *p, vecbuf *out, size_t start, mods *m, diag_loc kw)
{
	bool poly = false; /* a polynomial surface is polygonised inside its bound: it clips it */
	for (size_t i = start; i < out->len; i++) {
		scene_shape_kind k = VECBUF_AT(out, scene_object, i).geom->kind;
		poly |= k == SHAPE_QUADRIC || k == SHAPE_POLY;
	}
	if (poly && m->n_bound)
		TRY(bound_clips(p, m, m->bound_loc));
	if (m->n_clip) {
		TRY(csg_prepend(p, &VECBUF_AT(out, scene_object, start), out->len - start,
				(scene_csg_step){m->clip_id, 0, SCENE_CSG_INTERSECTION, false, m->clip_loc}));
		for (size_t i = 0; i < m->n_clip; i++)
			if (!vecbuf_push(out, &m->clip[i]))
				return lang_error(p, kw, "out of memory");
	}
	if (!m->inverse || out->len == start)
		return true;
	scene_object *first = &VECBUF_AT(out, scene_object, start);
	if (out->len - start == 1 && !first->csg_depth) {
		first->inverse = !first->inverse;
		return true;
	}
	bool one = first->csg_depth > 0;
	for (size_t i = start; one && i < out->len; i++) {
		const scene_object *o = &VECBUF_AT(out, scene_object, i);
		one = o->csg_depth && o->csg[0].id == first->csg[0].id;
	}
	if (!one)
		return csg_prepend(p, first, out->len - start, (scene_csg_step){++p->sc->csg_ids, 0, SCENE_CSG_UNION, true, kw});
	for (size_t i = start; i < out->len; i++) /* each path is the object's own (csg_prepend) */
		((scene_csg_step *)VECBUF_AT(out, scene_object, i).csg)[0].inverse ^= true;
	return true;
}

/* { modifier } "}" : the common tail of every object item. */
/* A light moved by t: its position, point_at, area axes and its looks_like objects. */
static void light_move(scene_light *l, const xform *t)
{
	for (uint32_t i = 0; i < l->n_looks; i++) { /* copies of the light's own (light_head, looks_like) */
		scene_object *o = (scene_object *)&l->looks[i];
		o->transform = xform_then(o->transform, *t);
	}
	for (uint32_t i = 0; i < l->n_projected; i++) { /* the same (light_head, projected_through) */
		scene_object *o = (scene_object *)&l->projected[i];
		o->transform = xform_then(o->transform, *t);
	}
	for (uint32_t i = 0; i < l->n_looks_lights; i++) /* the same (copy_looks, looks_like) */
		light_move((scene_light *)&l->looks_lights[i], t);
	l->position = xform_point(t, l->position);
	l->point_at = xform_point(t, l->point_at);
	l->axis1 = xform_vector(t, l->axis1);
	l->axis2 = xform_vector(t, l->axis2);
}

/* object_tail moving the scene's lights from `lights` on too (object { union { light_source ... } }). */
static bool object_tail_lights(parser *p, vecbuf *out, size_t start, size_t lights, diag_loc open, const char *what)
{
	mods m = {.t = xform_identity()};
	for (;;) {
		if (lang_peek(p)->kind == LTK_RBRACE) {
			diag_loc close = lang_advance(p)->loc;
			for (size_t i = lights; i < p->sc->lights.len; i++)
				light_move(&VECBUF_AT(&p->sc->lights, scene_light, i), &m.t);
			return csg_mods(p, out, start, &m, close) && apply_mods(p, out, start, &m);
		}
		bool matched;
		TRY(modifier(p, &m, &matched));
		if (!matched)
			return bad_item(p, open, what, "a transform, a material, no_shadow");
	}
}

static bool object_tail(parser *p, vecbuf *out, size_t start, diag_loc open, const char *what)
{
	return object_tail_lights(p, out, start, p->sc->lights.len, open, what);
}

static scene_geom *new_geom(parser *p, scene_shape_kind kind, diag_loc loc)
{
	scene_geom *g = scene_new_geom(p->sc, kind, loc);
	if (!g)
		lang_error(p, loc, "out of memory");
	return g;
}

static bool place(parser *p, vecbuf *out, const scene_geom *g, diag_loc loc)
{
	scene_object o = {.loc = loc, .geom = g, .transform = xform_identity()};
	if (!vecbuf_push(out, &o))
		return lang_error(p, loc, "out of memory");
	return true;
}

scene_geom *lang_new_geom(parser *p, scene_shape_kind kind, diag_loc loc) { return new_geom(p, kind, loc); }

bool lang_place_object(parser *p, vecbuf *out, const scene_geom *g, diag_loc kw, diag_loc open, const char *what)
{
	size_t start = out->len;
	return place(p, out, g, kw) && object_tail(p, out, start, open, what);
}

/* ---- primitives -------------------------------------------------------------------------- */

/* sphere = "sphere" "{" vector "," float { modifier } "}" */
static bool sphere(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	scene_geom *g;
	TRY(g = new_geom(p, SHAPE_SPHERE, kw));
	TRY(lang_vec3(p, "as the sphere centre", &g->u.sphere.center));
	TRY(lang_expect(p, LTK_COMMA, "after the sphere centre"));
	diag_loc rl = lang_peek(p)->loc;
	TRY(lang_float(p, "as the sphere radius", &g->u.sphere.radius));
	TRY(positive(p, rl, "sphere radius", g->u.sphere.radius));
	size_t start = out->len;
	TRY(place(p, out, g, kw));
	return object_tail(p, out, start, open, "sphere");
}

/* box = "box" "{" vector [ "," ] vector { modifier } "}"   (the comma optional, as POV-Ray's
 * Parse_Comma: `box { <a><b> }` is two corners) */
static bool box(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	scene_geom *g;
	TRY(g = new_geom(p, SHAPE_BOX, kw));
	TRY(lang_vec3(p, "as the first box corner", &g->u.box.corner1));
	lang_accept(p, LTK_COMMA);
	TRY(lang_vec3(p, "as the second box corner", &g->u.box.corner2));
	dvec3 a = g->u.box.corner1, b = g->u.box.corner2;
	int flat = (a.x == b.x) + (a.y == b.y) + (a.z == b.z);
	if (flat > 1) /* POV-Ray accepts it and shows nothing (float4.pov at clock 0) */
		diag_warning(p->d, kw, "box is flat in %d directions: its corners <%g, %g, %g> and <%g, %g, %g> make a %s, "
				       "which is invisible (as in POV-Ray)",
			     flat, a.x, a.y, a.z, b.x, b.y, b.z, flat == 3 ? "point" : "line");
	else if (flat == 1) /* POV-Ray renders it: its slab test meets the plane from either side */
		diag_warning(p->d, kw, "box is flat: its corners <%g, %g, %g> and <%g, %g, %g> share a coordinate; made a "
				       "two-sided rectangle (it has no inside)",
			     a.x, a.y, a.z, b.x, b.y, b.z);
	size_t start = out->len;
	TRY(place(p, out, g, kw));
	return object_tail(p, out, start, open, "box");
}

/* plane = "plane" "{" vector "," float { modifier } "}" */
static bool plane(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	scene_geom *g;
	TRY(g = new_geom(p, SHAPE_PLANE, kw));
	diag_loc nl = lang_peek(p)->loc;
	TRY(lang_vec3(p, "as the plane normal", &g->u.plane.normal));
	if (!(d3_length(g->u.plane.normal) > 0))
		return lang_error(p, nl, "plane normal is the zero vector");
	TRY(lang_expect(p, LTK_COMMA, "after the plane normal"));
	TRY(lang_float(p, "as the plane offset", &g->u.plane.offset));
	size_t start = out->len;
	TRY(place(p, out, g, kw));
	return object_tail(p, out, start, open, "plane");
}

/* ---- meshes ------------------------------------------------------------------------------ */

typedef struct meshbuf {
	vecbuf pos, nrm, uv, faces, nidx, uvidx, sizes, locs;
	vecbuf texs;  /* mesh2's texture_list: const scene_material * */
	vecbuf ftex;  /* each face's texture_list index (int32_t; -1: none), with a texture_list */
} meshbuf;

static void meshbuf_init(meshbuf *b)
{
	vecbuf_init(&b->pos, sizeof(vec3));
	vecbuf_init(&b->nrm, sizeof(vec3));
	vecbuf_init(&b->uv, sizeof(vec2));
	vecbuf_init(&b->faces, sizeof(uint32_t));
	vecbuf_init(&b->nidx, sizeof(uint32_t));
	vecbuf_init(&b->uvidx, sizeof(uint32_t));
	vecbuf_init(&b->sizes, sizeof(uint32_t));
	vecbuf_init(&b->locs, sizeof(diag_loc));
	vecbuf_init(&b->texs, sizeof(const scene_material *));
	vecbuf_init(&b->ftex, sizeof(int32_t));
}

static void meshbuf_free(meshbuf *b)
{
	vecbuf_free(&b->pos), vecbuf_free(&b->nrm), vecbuf_free(&b->uv), vecbuf_free(&b->faces);
	vecbuf_free(&b->nidx), vecbuf_free(&b->uvidx), vecbuf_free(&b->sizes), vecbuf_free(&b->locs);
	vecbuf_free(&b->texs), vecbuf_free(&b->ftex);
}

/* Hands a buffer's array to the IR (NULL when empty) and resets the buffer. */
static void *take(vecbuf *v, uint32_t *n)
{
	void *d = v->len ? v->data : NULL;
	if (d && v->cap > v->len) { /* give back the growth slack */
		void *shrunk = mem_realloc(d, v->len, v->elem);
		if (shrunk)
			d = shrunk;
	}
	if (n)
		*n = (uint32_t)v->len;
	if (!v->len)
		vecbuf_free(v);
	vecbuf_init(v, v->elem);
	return d;
}

static bool push(parser *p, vecbuf *v, const void *x)
{
	if (v->len >= UINT32_MAX - 1)
		return lang_error(p, lang_peek(p)->loc, "too many mesh elements (limit is %u)", UINT32_MAX - 1);
	if (!vecbuf_push(v, x))
		return lang_error(p, lang_peek(p)->loc, "out of memory");
	return true;
}

static bool push_v3(parser *p, vecbuf *v, dvec3 x)
{
	vec3 f = d3_to_v3(x);
	if (!v3_is_finite(f))
		return lang_error(p, p->prev.loc, "vector <%g, %g, %g> overflows a float", x.x, x.y, x.z);
	return push(p, v, &f);
}

/* A mesh's triangles (POV-Ray's Parse_Mesh):
 * triangle        = "triangle" "{" vector "," vector "," vector [ uv_vectors ] "}"
 * smooth_triangle = "smooth_triangle" "{" vector "," vector "," vector "," vector ","
 *                   vector "," vector [ uv_vectors ] "}"
 * uv_vectors      = "uv_vectors" vector "," vector "," vector   (2-D: the corners' uv, for
 *                   uv_mapping; a mesh's triangle without them has uv 0 at each corner) */
static bool triangle_body(parser *p, meshbuf *b, bool smooth, bool *any_smooth);
static bool triangle_uv(parser *p, meshbuf *b, bool smooth, bool *any_uv);

static bool triangle(parser *p, meshbuf *b, bool smooth, bool *any_smooth, bool *any_uv)
{
	const char *what = smooth ? "smooth_triangle" : "triangle";
	diag_loc open;
	lang_advance(p);
	TRY(open_block(p, what, &open));
	TRY(triangle_body(p, b, smooth, any_smooth));
	TRY(triangle_uv(p, b, smooth, any_uv));
	return lang_expect_close(p, open, what);
}

/* A mesh triangle's uv_vectors, or uv 0 at its three corners without them. */
static bool triangle_uv(parser *p, meshbuf *b, bool smooth, bool *any_uv)
{
	static const char *const nth[] = {"first", "second", "third"};
	vec2 uv[3] = {{0, 0}, {0, 0}, {0, 0}};
	if (lang_accept(p, LTK_KW_UV_VECTORS)) {
		char ctx[64];
		for (int i = 0; i < 3; i++) {
			if (i)
				TRY(lang_expect(p, LTK_COMMA, "between a triangle's uv_vectors"));
			snprintf(ctx, sizeof ctx, "as the %s uv of the %s", nth[i], smooth ? "smooth_triangle" : "triangle");
			diag_loc loc = lang_peek(p)->loc;
			value v;
			TRY(lang_additive(p, &v));
			if (v.kind != VAL_VECTOR || v.n != 2)
				return lang_error(p, loc, "expected a 2-vector <u, v> %s, found %s", ctx,
						  lang_value_kind_name(&v));
			uv[i] = v2((float)v.v[0], (float)v.v[1]);
			if (!(isfinite(uv[i].x) && isfinite(uv[i].y)))
				return lang_error(p, loc, "uv <%g, %g> overflows a float", v.v[0], v.v[1]);
		}
		*any_uv = true;
	}
	for (int i = 0; i < 3; i++)
		TRY(push(p, &b->uv, &uv[i]));
	return true;
}

/* The vertices (and normals) of a triangle, after its '{'. */
static bool triangle_body(parser *p, meshbuf *b, bool smooth, bool *any_smooth)
{
	const char *what = smooth ? "smooth_triangle" : "triangle";
	dvec3 v[3], n[3];
	static const char *const nth[] = {"first", "second", "third"};
	char ctx[64];
	for (int i = 0; i < 3; i++) {
		snprintf(ctx, sizeof ctx, "as the %s vertex of the %s", nth[i], what);
		TRY(lang_vec3(p, ctx, &v[i]));
		if (smooth) {
			snprintf(ctx, sizeof ctx, "after the %s vertex of the %s", nth[i], what);
			TRY(lang_expect(p, LTK_COMMA, ctx));
			snprintf(ctx, sizeof ctx, "as the %s normal of the smooth_triangle", nth[i]);
			TRY(lang_vec3(p, ctx, &n[i]));
		}
		if (i < 2) {
			snprintf(ctx, sizeof ctx, "after the %s %s of the %s", nth[i], smooth ? "normal" : "vertex", what);
			TRY(lang_expect(p, LTK_COMMA, ctx));
		}
	}
	uint32_t base = (uint32_t)b->pos.len;
	if (!smooth) {
		dvec3 fn = d3_cross(d3_sub(v[1], v[0]), d3_sub(v[2], v[0]));
		double len = d3_length(fn);
		n[0] = n[1] = n[2] = len > 0 ? d3_scale(fn, 1 / len) : d3(0, 1, 0);
	}
	*any_smooth |= smooth;
	for (int i = 0; i < 3; i++) {
		uint32_t k = base + (uint32_t)i;
		TRY(push_v3(p, &b->pos, v[i]) && push_v3(p, &b->nrm, n[i]) && push(p, &b->faces, &k) && push(p, &b->nidx, &k));
	}
	return true;
}

/* The triangles of b as a SHAPE_MESH geometry. */
static scene_geom *mesh_geom(parser *p, meshbuf *b, bool any_smooth, bool any_uv, diag_loc kw)
{
	scene_geom *g = new_geom(p, SHAPE_MESH, kw);
	if (!g)
		return NULL;
	scene_mesh *m = &g->u.mesh;
	m->positions = take(&b->pos, &m->n_positions);
	m->faces = take(&b->faces, &m->n_faces);
	m->n_faces /= 3;
	if (any_smooth) {
		m->normals = take(&b->nrm, &m->n_normals);
		m->normal_idx = take(&b->nidx, NULL);
	}
	if (any_uv) /* one a corner, like the positions: indexed by the faces' own indices */
		m->uvs = take(&b->uv, &m->n_uvs);
	return g;
}

/* A triangle or smooth_triangle as an object of its own (POV-Ray's triangle shape): a mesh of
 * one triangle, two-sided as POV-Ray's (it has no inside), with the object's modifiers.
 * object_triangle = ( "triangle" | "smooth_triangle" ) "{" vertices { modifier } "}" */
static bool object_triangle(parser *p, vecbuf *out, diag_loc kw, diag_loc open, bool smooth)
{
	meshbuf b;
	meshbuf_init(&b);
	bool any_smooth = false;
	scene_geom *g = NULL;
	if (triangle_body(p, &b, smooth, &any_smooth)) {
		if (lang_peek(p)->kind == LTK_KW_UV_VECTORS) /* POV-Ray's Parse_Triangle has none */
			lang_error(p, lang_peek(p)->loc, "'uv_vectors' belongs to a triangle of a mesh: a %s object "
							  "has none (give it inside 'mesh { }')", smooth ? "smooth_triangle" : "triangle");
		else
			g = mesh_geom(p, &b, any_smooth, false, kw);
	}
	meshbuf_free(&b);
	if (!g)
		return false;
	size_t start = out->len;
	TRY(place(p, out, g, kw));
	return object_tail(p, out, start, open, smooth ? "smooth_triangle" : "triangle");
}

static bool flat_triangle(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	return object_triangle(p, out, kw, open, false);
}

static bool smooth_triangle(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	return object_triangle(p, out, kw, open, true);
}

/* [ "inside_vector" vector ] after a mesh's or mesh2's data: POV-Ray's (Parse_Mesh, Parse_Mesh2),
 * the direction along which it counts crossings, without which its mesh has no inside in a CSG.
 * Read and unused: circe's mesh always has the inside of its parity along a fixed ray of its own
 * (render/world_csg.c), the same for any direction where the mesh is closed. */
static bool inside_vector(parser *p)
{
	if (!word_here(p, "inside_vector"))
		return true;
	lang_advance(p);
	dvec3 v;
	return lang_vec3(p, "as the inside_vector", &v);
}

/* mesh = "mesh" "{" ( "file" string | { triangle | smooth_triangle } [ "inside_vector" vector ] )
 *        { modifier } "}" */
static bool declared_object(parser *p, vecbuf *out, diag_loc kw);

static bool mesh(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	if (lang_peek(p)->kind == LTK_IDENT) { /* POV-Ray's mesh { Declared_Mesh mods }: a copy */
		size_t start = out->len;
		lang_token t = *lang_peek(p);
		TRY(declared_object(p, out, kw));
		for (size_t i = start; i < out->len; i++) {
			const scene_geom *g = ((const scene_object *)out->data)[i].geom;
			if (!g || (g->kind != SHAPE_MESH && g->kind != SHAPE_MESH_FILE))
				return lang_error(p, t.loc, "'%.*s' is not a mesh, after 'mesh {'", (int)t.len, t.text);
		}
		return object_tail(p, out, start, open, "mesh");
	}
	if (lang_accept(p, LTK_KW_FILE)) {
		scene_geom *g;
		TRY(g = new_geom(p, SHAPE_MESH_FILE, kw));
		TRY(asset_path(p, "after 'file'", SCENE_ASSET_MESH, &g->u.file.path));
		size_t start = out->len;
		TRY(place(p, out, g, kw));
		return object_tail(p, out, start, open, "mesh");
	}
	meshbuf b;
	meshbuf_init(&b);
	bool any_smooth = false, any_uv = false, ok = true;
	for (;;) {
		lang_tok k = lang_peek(p)->kind;
		if (k != LTK_KW_TRIANGLE && k != LTK_KW_SMOOTH_TRIANGLE)
			break;
		if (!(ok = triangle(p, &b, k == LTK_KW_SMOOTH_TRIANGLE, &any_smooth, &any_uv)))
			break;
	}
	if (ok && b.faces.len == 0)
		ok = lang_error_found(p, "expected 'triangle', 'smooth_triangle' or 'file' in 'mesh'");
	ok = ok && inside_vector(p);
	scene_geom *g = ok ? mesh_geom(p, &b, any_smooth, any_uv, kw) : NULL;
	meshbuf_free(&b);
	if (!g)
		return false;
	size_t start = out->len;
	TRY(place(p, out, g, kw));
	return object_tail(p, out, start, open, "mesh");
}

typedef bool (*item_fn)(parser *p, void *ctx, uint32_t i);

/* list = "{" count { [ "," ] item } [ "," ] "}"   with exactly count items */
static bool counted_list(parser *p, const char *what, item_fn item, void *ctx, vecbuf *reserve, size_t per_item,
			 uint32_t *count)
{
	diag_loc open;
	lang_advance(p);
	TRY(open_block(p, what, &open));
	long n;
	char ctx_s[64];
	snprintf(ctx_s, sizeof ctx_s, "as the item count of '%s'", what);
	diag_loc nloc = lang_peek(p)->loc;
	TRY(lang_int(p, ctx_s, 0, UINT32_MAX / 4, &n));
	/* Reserve what the count announces, within reason: every item takes at least two bytes of
	 * text, so a hostile count cannot make the reservation exceed the file's size. */
	size_t most = 0; /* no file left: the scene ended right after the count */
	if (p->n_files > 0) {
		const lang_lexer *lx = &p->files[p->n_files - 1].lx;
		most = (size_t)(lx->end - lx->p) / 2;
	}
	size_t want = (size_t)n < most ? (size_t)n : most;
	if (reserve && !vecbuf_reserve(reserve, want * per_item))
		return lang_error(p, nloc, "out of memory");
	uint32_t i = 0;
	for (;;) { /* the commas are optional, as POV-Ray's Parse_Comma makes them */
		diag_loc cl = lang_peek(p)->loc;
		lang_accept(p, LTK_COMMA);
		lang_tok k = lang_peek(p)->kind;
		if (k == LTK_RBRACE || k == LTK_EOF)
			break;
		if (i == (uint32_t)n)
			return lang_error(p, cl, "'%s' has more items than its count %ld", what, n);
		TRY(item(p, ctx, i));
		i++;
	}
	if (lang_peek(p)->kind == LTK_RBRACE && i < (uint32_t)n)
		return lang_error(p, lang_peek(p)->loc, "'%s' announces %ld items but gives %u", what, n, i);
	TRY(lang_expect_close(p, open, what));
	*count = i;
	return true;
}

typedef struct list_ctx {
	meshbuf *b;
	vecbuf *dst;
	const char *what;
	char item_ctx[48]; /* "in 'face_indices'": made once per list, not per item */
	uint32_t limit; /* indices must be below this (0: not checked here) */
	const char *target; /* what the indices refer to */
} list_ctx;

static const char *item_ctx(list_ctx *x)
{
	if (!x->item_ctx[0])
		snprintf(x->item_ctx, sizeof x->item_ctx, "in '%s'", x->what);
	return x->item_ctx;
}

static bool item_v3(parser *p, void *c, uint32_t i)
{
	list_ctx *x = c;
	dvec3 v;
	(void)i;
	return lang_vec3(p, item_ctx(x), &v) && push_v3(p, x->dst, v);
}

static bool item_uv(parser *p, void *c, uint32_t i)
{
	list_ctx *x = c;
	diag_loc loc = lang_peek(p)->loc;
	value v;
	TRY(lang_additive(p, &v));
	if (v.kind != VAL_VECTOR || v.n != 2)
		return lang_error(p, loc, "expected a 2-vector <u, v> as item %u of '%s', found %s", i, x->what,
				  lang_value_kind_name(&v));
	vec2 uv = v2((float)v.v[0], (float)v.v[1]);
	return push(p, x->dst, &uv);
}

/* A face's texture_list indices after its <a, b, c>, with a texture_list (POV-Ray's
 * Parse_Mesh2): [ "," ] t, or t1 "," t2 "," t3 (per-vertex textures, interpolated by POV-Ray: circe
 * takes them when the three are the same, else refuses); none: the mesh's own texture. */
static bool face_textures(parser *p, list_ctx *x, uint32_t i)
{
	int32_t t = -1;
	lang_accept(p, LTK_COMMA); /* the list's commas are optional: taking it here changes nothing */
	lang_token *k = lang_peek(p);
	const symbol *s = k->kind == LTK_IDENT ? lang_lookup(p, k->text, k->len) : NULL;
	if (k->kind == LTK_NUMBER || k->kind == LTK_LPAREN || (s && s->val.kind == VAL_FLOAT)) {
		uint32_t n = (uint32_t)x->b->texs.len;
		long v[3];
		int got = 0;
		diag_loc at = lang_peek(p)->loc;
		do {
			TRY(lang_int(p, "as the face's texture_list index", 0, (long)n - 1, &v[got]));
			got++;
		} while (got < 3 && lang_peek(p)->kind == LTK_COMMA && lang_raw_next(p) != LTK_LT &&
			 lang_accept(p, LTK_COMMA));
		if (got == 2)
			return lang_error(p, at, "face %u of 'face_indices' has 2 texture indices: give 1, or 3 (one a vertex)", i);
		if (got == 3 && (v[1] != v[0] || v[2] != v[0]))
			return lang_error(p, at, "face %u of 'face_indices' gives its vertices different textures (%ld, %ld, "
						 "%ld): POV-Ray's textures interpolated across a triangle are not supported by circe",
					  i, v[0], v[1], v[2]);
		t = (int32_t)v[0];
	}
	return push(p, &x->b->ftex, &t);
}

/* texture_list = "texture_list" "{" int { [ "," ] texture } "}": mesh2's textures, which its
 * faces name by index (before face_indices, as POV-Ray requires). */
static bool texture_list(parser *p, meshbuf *b)
{
	lang_advance(p);
	diag_loc open = lang_peek(p)->loc;
	TRY(lang_expect(p, LTK_LBRACE, "after 'texture_list'"));
	long n;
	TRY(lang_int(p, "as the number of textures in 'texture_list'", 1, 65535, &n));
	for (long i = 0; i < n; i++) {
		lang_accept(p, LTK_COMMA);
		if (lang_peek(p)->kind != LTK_KW_TEXTURE)
			return lang_error_found(p, "'texture_list' announces %ld textures but gives %ld: expected 'texture'", n, i);
		const scene_material *m;
		TRY(texture(p, &m, NULL));
		TRY(push(p, &b->texs, &m));
	}
	return lang_expect_close(p, open, "texture_list");
}

/* A triangle <a, b, c> of mesh2 (exactly three indices). */
static bool item_tri(parser *p, void *c, uint32_t i)
{
	list_ctx *x = c;
	uint32_t idx[LANG_MAX_VECTOR];
	int n;
	diag_loc loc;
	TRY(lang_index_tuple(p, item_ctx(x), idx, &n, &loc));
	if (n != 3)
		return lang_error(p, loc, "face %u of '%s' has %d indices; mesh2 faces are triangles <a, b, c>", i, x->what, n);
	for (int k = 0; k < 3; k++) {
		if (x->limit && idx[k] >= x->limit)
			return lang_error(p, loc, "face %u of '%s' refers to %s %u, but there are only %u", i, x->what,
					  x->target, idx[k], x->limit);
		TRY(push(p, x->dst, &idx[k]));
	}
	if (x->dst == &x->b->faces && x->b->texs.len)
		TRY(face_textures(p, x, i));
	return true;
}

/* A polygon of a subdivision cage (any size; fewer than 3 is reported by validation). */
static bool item_poly(parser *p, void *c, uint32_t i)
{
	list_ctx *x = c;
	uint32_t idx[LANG_MAX_VECTOR];
	int n;
	diag_loc loc;
	(void)i;
	TRY(lang_index_tuple(p, item_ctx(x), idx, &n, &loc));
	uint32_t un = (uint32_t)n;
	TRY(push(p, x->dst == &x->b->faces ? &x->b->sizes : &x->b->nidx, &un));
	if (x->dst == &x->b->faces)
		TRY(push(p, &x->b->locs, &loc));
	for (int k = 0; k < n; k++)
		TRY(push(p, x->dst, &idx[k]));
	return true;
}

static bool once(parser *p, bool *seen, const lang_token *t)
{
	if (*seen)
		return lang_error(p, t->loc, "'%.*s' given twice", (int)t->len, t->text);
	*seen = true;
	return true;
}

/* mesh2 = "mesh2" "{" "vertex_vectors" list [ "normal_vectors" list ] [ "uv_vectors" list ]
 *         [ texture_list ] "face_indices" list [ "normal_indices" list ] [ "uv_indices" list ]
 *         [ "inside_vector" vector ] { modifier } "}" */
static bool mesh2_body(parser *p, meshbuf *b, diag_loc kw, diag_loc open)
{
	bool seen[6] = {false};
	uint32_t n_faces = 0, n_nidx = 0, n_uvidx = 0, cnt;
	if (lang_peek(p)->kind != LTK_KW_VERTEX_VECTORS)
		return lang_error_found(p, "expected 'vertex_vectors' first in 'mesh2'");
	for (;;) {
		lang_token t = *lang_peek(p);
		list_ctx c = {b, NULL, NULL, "", 0, NULL};
		if (lang_word_is(&t, "texture_list")) {
			if (seen[3])
				return lang_error(p, t.loc, "'texture_list' must come before 'face_indices' (POV-Ray's order)");
			if (b->texs.len)
				return lang_error(p, t.loc, "'texture_list' given twice");
			TRY(texture_list(p, b));
			continue;
		}
		switch (t.kind) {
		case LTK_KW_VERTEX_VECTORS:
			TRY(once(p, &seen[0], &t));
			c.dst = &b->pos, c.what = "vertex_vectors";
			TRY(counted_list(p, c.what, item_v3, &c, c.dst, 1, &cnt));
			break;
		case LTK_KW_NORMAL_VECTORS:
			TRY(once(p, &seen[1], &t));
			c.dst = &b->nrm, c.what = "normal_vectors";
			TRY(counted_list(p, c.what, item_v3, &c, c.dst, 1, &cnt));
			break;
		case LTK_KW_UV_VECTORS:
			TRY(once(p, &seen[2], &t));
			c.dst = &b->uv, c.what = "uv_vectors";
			TRY(counted_list(p, c.what, item_uv, &c, c.dst, 1, &cnt));
			break;
		case LTK_KW_FACE_INDICES:
			TRY(once(p, &seen[3], &t));
			c.dst = &b->faces, c.what = "face_indices", c.limit = (uint32_t)b->pos.len, c.target = "vertex";
			if (!c.limit)
				return lang_error(p, t.loc, "'face_indices' but 'vertex_vectors' is empty");
			TRY(counted_list(p, c.what, item_tri, &c, c.dst, 3, &n_faces));
			break;
		case LTK_KW_NORMAL_INDICES:
			TRY(once(p, &seen[4], &t));
			if (!seen[1])
				return lang_error(p, t.loc, "'normal_indices' needs 'normal_vectors' before it");
			c.dst = &b->nidx, c.what = "normal_indices", c.limit = (uint32_t)b->nrm.len, c.target = "normal";
			TRY(counted_list(p, c.what, item_tri, &c, c.dst, 3, &n_nidx));
			break;
		case LTK_KW_UV_INDICES:
			TRY(once(p, &seen[5], &t));
			if (!seen[2])
				return lang_error(p, t.loc, "'uv_indices' needs 'uv_vectors' before it");
			c.dst = &b->uvidx, c.what = "uv_indices", c.limit = (uint32_t)b->uv.len, c.target = "uv";
			TRY(counted_list(p, c.what, item_tri, &c, c.dst, 3, &n_uvidx));
			break;
		default:
			if (!seen[3])
				return lang_error_found(p, "expected 'face_indices' in 'mesh2'");
			if (seen[4] && n_nidx != n_faces)
				return lang_error(p, open, "mesh2 has %u faces but %u normal_indices", n_faces, n_nidx);
			if (seen[5] && n_uvidx != n_faces)
				return lang_error(p, open, "mesh2 has %u faces but %u uv_indices", n_faces, n_uvidx);
			if (seen[1] && !seen[4] && b->nrm.len != b->pos.len)
				return lang_error(p, open,
						  "mesh2 has %zu normal_vectors but %zu vertex_vectors and no normal_indices",
						  b->nrm.len, b->pos.len);
			if (seen[2] && !seen[5] && b->uv.len != b->pos.len)
				return lang_error(p, open, "mesh2 has %zu uv_vectors but %zu vertex_vectors and no uv_indices",
						  b->uv.len, b->pos.len);
			(void)kw;
			return inside_vector(p);
		}
	}
}

/* The faces of m whose texture_list index is t (-1: those without) as a mesh of their own, its
 * vertex arrays copied whole; NULL when none has it (or out of memory: *oom). */
static scene_geom *mesh_part(parser *p, const scene_mesh *m, const int32_t *ftex, int32_t t, diag_loc kw, bool *oom)
{
	uint32_t n = 0;
	for (uint32_t f = 0; f < m->n_faces; f++)
		n += ftex[f] == t;
	if (!n)
		return NULL;
	scene_geom *g = new_geom(p, SHAPE_MESH, kw);
	if (!g)
		return *oom = true, NULL;
	scene_mesh *d = &g->u.mesh;
	*d = (scene_mesh){.n_positions = m->n_positions, .n_normals = m->n_normals, .n_uvs = m->n_uvs, .n_faces = n};
	d->positions = mem_alloc(m->n_positions, sizeof *d->positions);
	d->normals = m->normals ? mem_alloc(m->n_normals, sizeof *d->normals) : NULL;
	d->uvs = m->uvs ? mem_alloc(m->n_uvs, sizeof *d->uvs) : NULL;
	d->faces = mem_alloc(n, 3 * sizeof *d->faces);
	d->normal_idx = m->normal_idx ? mem_alloc(n, 3 * sizeof *d->normal_idx) : NULL;
	d->uv_idx = m->uv_idx ? mem_alloc(n, 3 * sizeof *d->uv_idx) : NULL;
	if (!d->positions || (m->normals && !d->normals) || (m->uvs && !d->uvs) || !d->faces ||
	    (m->normal_idx && !d->normal_idx) || (m->uv_idx && !d->uv_idx))
		return *oom = true, NULL; /* the geom's arrays are freed with the scene */
	memcpy(d->positions, m->positions, m->n_positions * sizeof *d->positions);
	if (m->normals)
		memcpy(d->normals, m->normals, m->n_normals * sizeof *d->normals);
	if (m->uvs)
		memcpy(d->uvs, m->uvs, m->n_uvs * sizeof *d->uvs);
	for (uint32_t f = 0, k = 0; f < m->n_faces; f++) {
		if (ftex[f] != t)
			continue;
		memcpy(d->faces + 3 * k, m->faces + 3 * f, 3 * sizeof *d->faces);
		if (m->normal_idx)
			memcpy(d->normal_idx + 3 * k, m->normal_idx + 3 * f, 3 * sizeof *d->normal_idx);
		if (m->uv_idx)
			memcpy(d->uv_idx + 3 * k, m->uv_idx + 3 * f, 3 * sizeof *d->uv_idx);
		k++;
	}
	return g;
}

/* A mesh2 with a texture_list is placed as one mesh per texture its faces name (and one of the
 * faces naming none, which take the object's texture), each list texture in the mesh's own space,
 * moving with the object as POV-Ray's per-triangle textures do; the pieces are one solid
 * (scene_object.pieces: a CSG asks the whole mesh's inside). */
static bool place_textured_mesh(parser *p, vecbuf *out, const scene_mesh *whole, const meshbuf *b, diag_loc kw)
{
	const int32_t *ftex = b->ftex.data;
	const scene_material *const *texs = b->texs.data;
	bool oom = false;
	size_t start = out->len;
	for (int32_t t = -1; t < (int32_t)b->texs.len; t++) {
		scene_geom *g = mesh_part(p, whole, ftex, t, kw, &oom);
		if (oom)
			return lang_error(p, kw, "out of memory");
		if (!g)
			continue;
		TRY(place(p, out, g, kw));
		if (t >= 0)
			VECBUF_AT(out, scene_object, out->len - 1).material = texs[t];
	}
	for (size_t i = start; out->len - start > 1 && i < out->len; i++) {
		scene_object *o = &VECBUF_AT(out, scene_object, i);
		o->piece = (uint32_t)(i - start), o->pieces = (uint32_t)(out->len - start);
	}
	return true;
}

static bool mesh2(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	meshbuf b;
	meshbuf_init(&b);
	if (!mesh2_body(p, &b, kw, open)) {
		meshbuf_free(&b);
		return false;
	}
	scene_mesh m = {0};
	m.positions = take(&b.pos, &m.n_positions);
	m.normals = take(&b.nrm, &m.n_normals);
	m.uvs = take(&b.uv, &m.n_uvs);
	m.faces = take(&b.faces, &m.n_faces);
	m.n_faces /= 3;
	/* Normals or uvs without their own indices follow the vertex indices. */
	if (b.nidx.len)
		m.normal_idx = take(&b.nidx, NULL);
	else if (m.normals && (m.normal_idx = mem_alloc(m.n_faces, 3 * sizeof(uint32_t))))
		memcpy(m.normal_idx, m.faces, (size_t)m.n_faces * 3 * sizeof(uint32_t));
	if (b.uvidx.len)
		m.uv_idx = take(&b.uvidx, NULL);
	else if (m.uvs && (m.uv_idx = mem_alloc(m.n_faces, 3 * sizeof(uint32_t))))
		memcpy(m.uv_idx, m.faces, (size_t)m.n_faces * 3 * sizeof(uint32_t));
	bool textured = false;
	for (size_t f = 0; f < b.ftex.len; f++)
		textured |= VECBUF_AT(&b.ftex, int32_t, f) >= 0;
	size_t start = out->len;
	bool ok = (!m.normals || m.normal_idx) && (!m.uvs || m.uv_idx);
	scene_geom *g = NULL;
	if (!ok)
		lang_error(p, kw, "out of memory");
	else if (textured)
		ok = place_textured_mesh(p, out, &m, &b, kw);
	else
		ok = (g = new_geom(p, SHAPE_MESH, kw)) != NULL && place(p, out, g, kw);
	if (g)
		g->u.mesh = m; /* the geom owns the arrays now */
	else {
		mem_free(m.positions), mem_free(m.normals), mem_free(m.uvs);
		mem_free(m.faces), mem_free(m.normal_idx), mem_free(m.uv_idx);
	}
	meshbuf_free(&b);
	TRY(ok);
	return object_tail(p, out, start, open, "mesh2");
}

/* ---- subdivision surfaces ---------------------------------------------------------------- */

typedef struct subd_ctx {
	parser *p;
	vecbuf creases, corners;
} subd_ctx;

static bool item_crease(parser *p, void *c, uint32_t i)
{
	subd_ctx *x = c;
	uint32_t idx[LANG_MAX_VECTOR];
	int n;
	scene_crease cr;
	double s;
	TRY(lang_index_tuple(p, "in 'creases'", idx, &n, &cr.loc));
	if (n != 2)
		return lang_error(p, cr.loc, "crease %u needs two vertex indices <i, j>, found %d", i, n);
	TRY(lang_expect(p, LTK_COMMA, "after the crease's vertex pair"));
	diag_loc sl = lang_peek(p)->loc;
	TRY(lang_float(p, "as the crease sharpness", &s) && in_range(p, sl, "crease sharpness", s, 0, 10));
	cr.a = idx[0], cr.b = idx[1], cr.sharpness = (float)s;
	return push(p, &x->creases, &cr);
}

static bool item_corner(parser *p, void *c, uint32_t i)
{
	subd_ctx *x = c;
	scene_corner co;
	long v;
	double s;
	(void)i;
	co.loc = lang_peek(p)->loc;
	TRY(lang_int(p, "as the corner vertex", 0, UINT32_MAX, &v));
	TRY(lang_expect(p, LTK_COMMA, "after the corner vertex"));
	diag_loc sl = lang_peek(p)->loc;
	TRY(lang_float(p, "as the corner sharpness", &s) && in_range(p, sl, "corner sharpness", s, 0, 10));
	co.vertex = (uint32_t)v, co.sharpness = (float)s;
	return push(p, &x->corners, &co);
}

/* level (uniform) and max_edge (adaptive) choose the tessellation: one of them, not both. other:
 * whether the other was given (at *first); otherwise *first becomes this one's place. */
static bool level_or_max_edge(parser *p, bool other, const lang_token *t, diag_loc *first)
{
	if (other)
		return lang_error(p, t->loc, "'%.*s' after '%s' at line %u: a subdivision_surface has a uniform 'level' or "
					     "an adaptive 'max_edge', not both",
				  (int)t->len, t->text, t->kind == LTK_KW_LEVEL ? "max_edge" : "level", first->line);
	*first = t->loc;
	return true;
}

/* subdivision_surface = "subdivision_surface" "{" { subd_item } { modifier } "}"
 * subd_item = "file" string | "vertex_vectors" list | "faces" list | "uv_vectors" list
 *           | "uv_faces" list | "creases" list | "corners" list
 *           | "scheme" ( "catmull_clark" | "loop" ) | "boundary" ( "edge_only" | "edge_and_corner" )
 *           | "level" integer | "max_edge" float */
static bool subdiv_items(parser *p, meshbuf *b, subd_ctx *sx, scene_subdiv *d, diag_loc kw)
{
	bool seen[11] = {false};
	diag_loc level_loc = kw; /* the first of level and max_edge: they are alternatives */
	uint32_t cnt;
	for (;;) {
		lang_token t = *lang_peek(p);
		list_ctx c = {b, NULL, NULL, "", 0, NULL};
		long n;
		double x;
		switch (t.kind) {
		case LTK_KW_FILE:
			TRY(once(p, &seen[0], &t));
			lang_advance(p);
			d->file_loc = t.loc;
			TRY(asset_path(p, "after 'file'", SCENE_ASSET_CAGE, &d->file));
			break;
		case LTK_KW_VERTEX_VECTORS:
			TRY(once(p, &seen[1], &t));
			c.dst = &b->pos, c.what = "vertex_vectors";
			TRY(counted_list(p, c.what, item_v3, &c, c.dst, 1, &cnt));
			break;
		case LTK_KW_FACES:
			TRY(once(p, &seen[2], &t));
			c.dst = &b->faces, c.what = "faces";
			TRY(counted_list(p, c.what, item_poly, &c, NULL, 1, &cnt));
			break;
		case LTK_KW_UV_VECTORS:
			TRY(once(p, &seen[3], &t));
			c.dst = &b->uv, c.what = "uv_vectors";
			TRY(counted_list(p, c.what, item_uv, &c, c.dst, 1, &cnt));
			break;
		case LTK_KW_UV_FACES:
			TRY(once(p, &seen[4], &t));
			c.dst = &b->uvidx, c.what = "uv_faces";
			TRY(counted_list(p, c.what, item_poly, &c, NULL, 1, &cnt));
			break;
		case LTK_KW_CREASES:
			TRY(once(p, &seen[5], &t));
			TRY(counted_list(p, "creases", item_crease, sx, NULL, 1, &cnt));
			break;
		case LTK_KW_CORNERS:
			TRY(once(p, &seen[6], &t));
			TRY(counted_list(p, "corners", item_corner, sx, NULL, 1, &cnt));
			break;
		case LTK_KW_SCHEME: {
			TRY(once(p, &seen[7], &t));
			lang_advance(p);
			int i = one_of(p, (const lang_tok[]){LTK_KW_CATMULL_CLARK, LTK_KW_LOOP}, 2,
				   "expected catmull_clark or loop after 'scheme'");
			TRY(i >= 0);
			d->scheme = (scene_subd_scheme)(SCENE_SUBD_CATMULL_CLARK + i);
			break;
		}
		case LTK_KW_BOUNDARY: {
			TRY(once(p, &seen[8], &t));
			lang_advance(p);
			int i = one_of(p, (const lang_tok[]){LTK_KW_EDGE_ONLY, LTK_KW_EDGE_AND_CORNER}, 2,
				   "expected edge_only or edge_and_corner after 'boundary'");
			TRY(i >= 0);
			d->boundary = (scene_subd_boundary)(SCENE_SUBD_EDGE_ONLY + i);
			d->boundary_given = true;
			break;
		}
		case LTK_KW_LEVEL:
			TRY(once(p, &seen[9], &t) && level_or_max_edge(p, seen[10], &t, &level_loc));
			lang_advance(p);
			TRY(lang_int(p, "after 'level'", 1, 8, &n));
			d->level = (int)n;
			break;
		case LTK_KW_MAX_EDGE:
			TRY(once(p, &seen[10], &t) && level_or_max_edge(p, seen[9], &t, &level_loc));
			lang_advance(p);
			TRY(lang_float(p, "after 'max_edge'", &x) && positive(p, t.loc, "max_edge", x));
			d->max_edge_px = x;
			break;
		default:
			if (seen[0] && (seen[1] || seen[2]))
				return lang_error(p, kw, "subdivision_surface has both a 'file' and an inline cage");
			if (!seen[0] && !(seen[1] && seen[2]))
				return lang_error_found(p, "expected %s in 'subdivision_surface'",
							!seen[1] ? "'file' or 'vertex_vectors'" : "'faces'");
			if (seen[3] != seen[4])
				return lang_error(p, kw, "subdivision_surface needs both 'uv_vectors' and 'uv_faces', or neither");
			return true;
		}
	}
}

static bool subdivision_surface(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	meshbuf b;
	meshbuf_init(&b);
	subd_ctx sx = {p, {0}, {0}};
	vecbuf_init(&sx.creases, sizeof(scene_crease));
	vecbuf_init(&sx.corners, sizeof(scene_corner));
	scene_subdiv d = {.max_edge_px = 1.5, .boundary = SCENE_SUBD_EDGE_AND_CORNER};
	scene_geom *g = subdiv_items(p, &b, &sx, &d, kw) ? new_geom(p, SHAPE_SUBDIV, kw) : NULL;
	if (!g) {
		meshbuf_free(&b);
		vecbuf_free(&sx.creases);
		vecbuf_free(&sx.corners);
		return false;
	}
	d.vertices = take(&b.pos, &d.n_vertices);
	d.face_sizes = take(&b.sizes, &d.n_faces);
	d.face_verts = take(&b.faces, &d.n_face_verts);
	d.face_locs = take(&b.locs, NULL);
	d.uvs = take(&b.uv, &d.n_uvs);
	d.uv_face_sizes = take(&b.nidx, &d.n_uv_faces);
	d.uv_face_verts = take(&b.uvidx, &d.n_uv_face_verts);
	d.creases = take(&sx.creases, &d.n_creases);
	d.corners = take(&sx.corners, &d.n_corners);
	g->u.subdiv = d;
	meshbuf_free(&b);
	size_t start = out->len;
	TRY(place(p, out, g, kw));
	return object_tail(p, out, start, open, "subdivision_surface");
}

/* ---- object items ------------------------------------------------------------------------ */

static bool object_item(parser *p, vecbuf *out, bool *matched);

static bool light_block(parser *p, scene_light *out, diag_loc kw);
static bool light_body(parser *p, scene_light *out, diag_loc kw, diag_loc open);
static bool add_light(parser *p, const scene_light *l, diag_loc kw);

/* Whether objects read unplaced in `where` (p->unplaced) refuse a light_source, as POV-Ray's
 * Parse_Bound_Clip refuses an object holding one (a light is a "patch" object there). */
static bool unplaced_refuses_lights(const char *where)
{
	return where && (!strcmp(where, "clipped_by") || !strcmp(where, "bounded_by"));
}

/* The article of a block's name: "an object", "an intersection", "a union". */
static const char *article(const char *word) { return strchr("aeio", word[0]) ? "an" : "a"; }

/* Whether a light_source (at `at`) in a block `what` is refused here: in a clipped_by or
 * bounded_by, as POV-Ray refuses it (then reported). */
static bool csg_light_refused(parser *p, diag_loc at, const char *what)
{
	if (!p->lights_in_csg && unplaced_refuses_lights(p->unplaced))
		return !lang_error(p, at,
				   "a light_source inside %s %s is not allowed in a %s, as in POV-Ray (\"Illegal texture "
				   "or patch in clip, bound or object pattern\")",
				   article(what), what, p->unplaced);
	return false;
}

/* The light l (at kw) of a block `what`, placed (add_light) where csg_light says, else dropped
 * with a warning. */
static bool csg_light_place(parser *p, const scene_light *l, diag_loc kw, const char *what)
{
	if (!p->lights_in_csg) {
		diag_warning(p->d, kw,
			     "this light_source inside %s %s lights nothing, as in POV-Ray: the %s's object is not "
			     "placed in the scene",
			     article(what), what, p->unplaced ? p->unplaced : "block");
		return true;
	}
	return add_light(p, l, kw);
}

/* A light_source in a CSG block (the lookahead): POV-Ray's light that moves with its CSG's
 * transforms (drums.pov, iortest.pov). It joins the scene's lights now, and each enclosing block
 * moves the lights from its first on (csg_lights_move); only where the object is placed in the
 * scene or in a light's looks_like (p->lights_in_csg). In an object that is never placed (an
 * object pattern's, a projected_through's) POV-Ray parses the light and never uses it: circe
 * too, with a warning; in a clipped_by or bounded_by POV-Ray refuses it. */
static bool csg_light(parser *p, const char *what)
{
	lang_token kw = *lang_peek(p);
	if (csg_light_refused(p, kw.loc, what))
		return false;
	lang_advance(p);
	scene_light l;
	TRY(light_block(p, &l, kw.loc));
	return csg_light_place(p, &l, kw.loc, what);
}

/* The block's transforms applied to the lights its items placed (the scene's lights from first). */
static void csg_lights_move(parser *p, size_t first, const mods *m)
{
	for (size_t i = first; i < p->sc->lights.len; i++)
		light_move(&VECBUF_AT(&p->sc->lights, scene_light, i), &m->t);
}

/* union = "union" "{" ( object_item | light_source ) { object_item | light_source } { modifier } "}" */
static bool union_block(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	size_t start = out->len, lights = p->sc->lights.len;
	mods m = {.t = xform_identity()};
	bool any = false;
	for (;;) {
		if (lang_peek(p)->kind == LTK_RBRACE) {
			if (!any)
				return lang_error(p, kw, "union has no objects");
			lang_advance(p);
			csg_lights_move(p, lights, &m);
			return csg_mods(p, out, start, &m, kw) && apply_mods(p, out, start, &m);
		}
		if (lang_peek(p)->kind == LTK_KW_LIGHT_SOURCE) {
			TRY(csg_light(p, "union"));
			any = true;
			continue;
		}
		bool matched;
		TRY(object_item(p, out, &matched));
		if (matched) {
			any = true;
			continue;
		}
		TRY(modifier(p, &m, &matched));
		if (!matched)
			return bad_item(p, open, "union", "an object, a transform, a material, no_shadow");
	}
}

/* csg = ( "intersection" | "difference" | "merge" ) "{" object_item { object_item } { modifier } "}"
 * Each object item is one operand (a union of several objects is one); the operands' objects
 * stay objects and carry the node in their CSG path (scene.h). */
static bool csg_block(parser *p, vecbuf *out, diag_loc kw, diag_loc open, scene_csg_op op, const char *what)
{
	size_t start = out->len, lights = p->sc->lights.len;
	mods m = {.t = xform_identity()};
	uint32_t id = ++p->sc->csg_ids, operands = 0;
	for (;;) {
		if (lang_peek(p)->kind == LTK_RBRACE) {
			if (!operands)
				return lang_error(p, kw, "%s has no objects", what);
			lang_advance(p);
			csg_lights_move(p, lights, &m);
			return csg_mods(p, out, start, &m, kw) && apply_mods(p, out, start, &m);
		}
		if (lang_peek(p)->kind == LTK_KW_LIGHT_SOURCE) { /* no operand: it only moves with the solid */
			TRY(csg_light(p, what));
			continue;
		}
		size_t from = out->len;
		bool matched;
		TRY(object_item(p, out, &matched));
		if (matched) {
			TRY(csg_prepend(p, &VECBUF_AT(out, scene_object, from), out->len - from,
					(scene_csg_step){id, operands++, op, false, kw}));
			continue;
		}
		TRY(modifier(p, &m, &matched));
		if (!matched)
			return bad_item(p, open, what, "an object, a transform, a material, inverse, clipped_by");
	}
}

static bool intersection_block(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	return csg_block(p, out, kw, open, SCENE_CSG_INTERSECTION, "intersection");
}

static bool difference_block(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	return csg_block(p, out, kw, open, SCENE_CSG_DIFFERENCE, "difference");
}

static bool merge_block(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	return csg_block(p, out, kw, open, SCENE_CSG_MERGE, "merge");
}

/* A copy of a declared object gets new CSG ids (one solid per copy): id + base, base the last id
 * given, so distinct ids stay distinct and none is reused. */
static bool csg_renumber(parser *p, scene_object *objs, size_t n, diag_loc kw)
{
	uint32_t base = p->sc->csg_ids, top = 0;
	for (size_t i = 0; i < n; i++) {
		scene_object *o = &objs[i];
		if (!o->csg_depth)
			continue;
		scene_csg_step *path = arena_zalloc(&p->sc->arena, o->csg_depth, sizeof *path);
		if (!path)
			return lang_error(p, kw, "out of memory");
		for (uint32_t k = 0; k < o->csg_depth; k++) {
			path[k] = o->csg[k];
			path[k].id += base;
			top = path[k].id > top ? path[k].id : top;
		}
		o->csg = path;
	}
	if (top)
		p->sc->csg_ids = top;
	return true;
}

static bool copy_looks(parser *p, scene_light *l, diag_loc at);

/* The light groups [first, last) of l's looks_like objects and of the lights in them (copies:
 * copy_looks) moved by shift, to a declared object's copy's groups (declared_object). */
static void shift_looks_groups(scene_light *l, uint32_t first, uint32_t last, uint32_t shift)
{
	for (uint32_t i = 0; i < l->n_looks; i++) {
		scene_object *o = (scene_object *)&l->looks[i];
		if (o->light_group >= first && o->light_group < last)
			o->light_group += shift;
	}
	for (uint32_t i = 0; i < l->n_looks_lights; i++) {
		scene_light *c = (scene_light *)&l->looks_lights[i];
		if (c->group >= first && c->group < last)
			c->group += shift;
		shift_looks_groups(c, first, last, shift);
	}
}

/* A declared object's name: its objects pushed onto out as instances placed at kw, with copies
 * of its light groups (new ids, the parent chain inside it copied) and, where the copy is placed
 * in the scene or in a looks_like (p->lights_in_csg), of its lights: POV-Ray copies a declared
 * CSG's lights with each `object { U }`, and the enclosing blocks move them (object_tail_lights,
 * csg_lights_move). */
static bool declared_object(parser *p, vecbuf *out, diag_loc kw)
{
	lang_token name = *lang_peek(p);
	const value *v = declared(p, VAL_OBJECT, "an object");
	if (!v)
		return false;
	const objlist *ol = v->obj;
	uint32_t first = ol->first_group, last = first + ol->n_groups; /* its groups: [first, last) */
	uint32_t shift = 0;
	if (ol->n_groups) {
		if (p->sc->light_groups.len > UINT32_MAX - 1 - ol->n_groups)
			return lang_error(p, kw, "too many light_groups");
		shift = (uint32_t)p->sc->light_groups.len + 1 - first;
		for (uint32_t g = first; g < last; g++) {
			scene_light_group grp = ol->groups[g - first];
			grp.parent = grp.parent >= first && grp.parent < last ? grp.parent + shift : 0;
			grp.loc = kw;
			if (!vecbuf_push(&p->sc->light_groups, &grp))
				return lang_error(p, kw, "out of memory");
		}
	}
#define SHIFTED(g) ((g) >= first && (g) < last ? (g) + shift : (g))
	size_t start = out->len;
	for (size_t i = 0; i < ol->n; i++) {
		scene_object o = ol->items[i];
		o.instance = true;
		o.loc = kw;
		o.light_group = SHIFTED(o.light_group);
		if (!vecbuf_push(out, &o))
			return lang_error(p, kw, "out of memory");
	}
	const char *where = p->unplaced ? p->unplaced : "block";
	if (ol->n_lights && !p->lights_in_csg && unplaced_refuses_lights(where))
		return lang_error(p, kw, "'%.*s' holds a light_source: not allowed in a %s, as in POV-Ray (\"Illegal "
					 "texture or patch in clip, bound or object pattern\")",
				  (int)name.len, name.text, where);
	if (ol->n_lights && !p->lights_in_csg)
		diag_warning(p->d, kw, "the light_source%s of '%.*s' light%s nothing in a %s: its object is not placed "
				       "in the scene",
			     ol->n_lights > 1 ? "s" : "", (int)name.len, name.text, ol->n_lights > 1 ? "" : "s", where);
	for (size_t i = 0; p->lights_in_csg && i < ol->n_lights; i++) {
		scene_light l = ol->lights[i];
		l.group = SHIFTED(l.group);
		l.loc = kw;
		TRY(copy_looks(p, &l, kw)); /* its projected_through objects are moved with this copy only */
		shift_looks_groups(&l, first, last, shift);
		TRY(add_light(p, &l, kw));
	}
#undef SHIFTED
	return csg_renumber(p, &VECBUF_AT(out, scene_object, start), out->len - start, kw);
}

/* instance = "object" "{" ( identifier | object_item ) { modifier } "}"
 * POV-Ray's object { } holds a declared object or an object itself (a macro's, often). */
static bool instance(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	lang_token *t = lang_peek(p);
	if (names(p, VAL_LIGHT)) { /* object { L ... } of a declared light, as POV-Ray's Parse_Object_Id */
		if (csg_light_refused(p, kw, "object"))
			return false;
		scene_light l;
		TRY(light_body(p, &l, kw, open));
		return csg_light_place(p, &l, kw, "object");
	}
	if (t->kind != LTK_IDENT) {
		size_t start = out->len, lights = p->sc->lights.len;
		bool matched;
		TRY(object_item(p, out, &matched));
		if (!matched)
			return lang_error_found(p, "expected a declared object or an object after 'object {'");
		return object_tail_lights(p, out, start, lights, open, "object");
	}
	size_t start = out->len, lights = p->sc->lights.len;
	TRY(declared_object(p, out, kw));
	return object_tail_lights(p, out, start, lights, open, "object");
}

bool lang_component_mods(parser *p, xform *t, bool *moved, const scene_material **mat, diag_loc open)
{
	mods m = {.t = xform_identity()};
	*moved = false;
	for (;;) {
		lang_token k = *lang_peek(p);
		if (k.kind == LTK_RBRACE)
			break;
		bool matched;
		if (k.kind == LTK_KW_TEXTURE || k.kind == LTK_KW_PIGMENT || k.kind == LTK_KW_FINISH ||
		    lang_normal_starts(p)) {
			TRY(modifier(p, &m, &matched));
			continue;
		}
		TRY(transform_item(p, &m.t, &matched));
		if (!matched)
			return lang_error_found(p, "expected a transform, a texture or '}' to close the blob component "
						   "(opened at line %u)", open.line);
		*moved = true;
	}
	lang_advance(p);
	*t = m.t, *mat = m.mat;
	return true;
}

/* pov_shape = lathe | sor | prism | sphere_sweep | blob | text: the body in shapes2.c; a blob's
 * component textures go to its object (scene_object.part_mat). */
static bool pov_shape(parser *p, vecbuf *out, const lang_token *word, diag_loc open)
{
	scene_geom *g;
	TRY(g = lang_pov_shape(p, lang_pov_shape_kind(word), word->loc, transform_item));
	size_t start = out->len;
	const scene_material **parts = p->blob_parts;
	uint32_t n_parts = p->n_blob_parts;
	p->blob_parts = NULL, p->n_blob_parts = 0;
	TRY(place(p, out, g, word->loc));
	for (size_t i = start; i < out->len; i++) {
		scene_object *o = &VECBUF_AT(out, scene_object, i);
		o->part_mat = parts, o->n_parts = n_parts;
	}
	char nm[32];
	snprintf(nm, sizeof nm, "%.*s", (int)word->len, word->text);
	return object_tail(p, out, start, open, nm);
}

static bool optional_bool(parser *p, bool *on);

/* The root of light group g's chain of enclosing groups (scene.h's scene_light_group). */
static uint32_t light_group_root(const parser *p, uint32_t g)
{
	while (VECBUF_AT(&p->sc->light_groups, scene_light_group, g - 1).parent)
		g = VECBUF_AT(&p->sc->light_groups, scene_light_group, g - 1).parent;
	return g;
}

/* light_group = "light_group" "{" { object_item | light_source } { transform_item
 *               | "global_lights" [ float ] | "photons" block } "}"
 * POV-Ray's (Parse_Light_Group, core/lighting/lightgroup.cpp): a union whose lights light only
 * its objects (and those of the groups inside it), its objects lit by the scene's other lights
 * only with global_lights on (off by default; the outermost group's word counts, as POV-Ray sets
 * its flag on every child). Its lights join the scene's as the CSG's do (csg_light). */
static bool light_group_block(parser *p, vecbuf *out, diag_loc kw, diag_loc open)
{
	size_t start = out->len, lights = p->sc->lights.len;
	if (p->sc->light_groups.len >= UINT32_MAX - 1)
		return lang_error(p, kw, "too many light_groups");
	scene_light_group grp = {.loc = kw, .parent = 0, .global_lights = false};
	if (!vecbuf_push(&p->sc->light_groups, &grp))
		return lang_error(p, kw, "out of memory");
	uint32_t id = (uint32_t)p->sc->light_groups.len;
	xform t = xform_identity();
	bool global_lights = false;
	for (;;) {
		lang_token k = *lang_peek(p);
		if (k.kind == LTK_RBRACE) {
			lang_advance(p);
			break;
		}
		if (k.kind == LTK_KW_LIGHT_SOURCE) {
			TRY(csg_light(p, "light_group"));
			continue;
		}
		bool matched;
		TRY(object_item(p, out, &matched));
		if (matched)
			continue;
		if (k.kind == LTK_UNSUPPORTED && lang_word_is(&k, "global_lights")) {
			lang_advance(p);
			TRY(optional_bool(p, &global_lights));
			continue;
		}
		if (lang_word_is(&k, "photons")) { /* POV-Ray's photon target flags of the group */
			lang_advance(p);
			TRY(lang_skip_block(p, "photons"));
			diag_warning(p->d, k.loc, "a light_group's 'photons' is accepted and ignored: circe computes "
						  "caustics by its own path tracing");
			continue;
		}
		TRY(transform_item(p, &t, &matched));
		if (!matched)
			return bad_item(p, open, "light_group", "an object, a light_source, a transform, global_lights");
	}
	VECBUF_AT(&p->sc->light_groups, scene_light_group, id - 1).global_lights = global_lights;
	bool any_light = false;
	for (size_t i = lights; i < p->sc->lights.len; i++) {
		scene_light *l = &VECBUF_AT(&p->sc->lights, scene_light, i);
		light_move(l, &t);
		any_light |= !l->group;
		if (!l->group) /* an inner group's light stays its group's */
			l->group = id;
	}
	for (size_t i = start; i < out->len; i++) {
		scene_object *o = &VECBUF_AT(out, scene_object, i);
		o->transform = xform_then(o->transform, t);
		if (!o->light_group)
			o->light_group = id;
		else if (light_group_root(p, o->light_group) != id)
			VECBUF_AT(&p->sc->light_groups, scene_light_group, light_group_root(p, o->light_group) - 1).parent = id;
	}
	if (start == out->len)
		diag_warning(p->d, kw, "light_group has no objects: its lights light nothing");
	else if (!any_light)
		diag_warning(p->d, kw, "light_group has no light_source of its own: its objects are lit %s",
			     global_lights ? "as any (global_lights on)" : "by no light but those of groups around it");
	return true;
}

/* object_item = sphere | box | plane | triangle | smooth_triangle | mesh | mesh2 | subdivision_surface | instance | union
 *             | pov_shape */
static bool object_item(parser *p, vecbuf *out, bool *matched)
{
	lang_token t = *lang_peek(p);
	bool (*fn)(parser *, vecbuf *, diag_loc, diag_loc) = NULL;
	switch (t.kind) {
	case LTK_KW_SPHERE: fn = sphere; break;
	case LTK_KW_BOX: fn = box; break;
	case LTK_KW_PLANE: fn = plane; break;
	case LTK_KW_MESH: fn = mesh; break;
	case LTK_KW_MESH2: fn = mesh2; break;
	case LTK_KW_SUBDIVISION_SURFACE: fn = subdivision_surface; break;
	case LTK_KW_OBJECT: fn = instance; break;
	case LTK_KW_UNION: fn = union_block; break;
	case LTK_KW_INTERSECTION: fn = intersection_block; break;
	case LTK_KW_DIFFERENCE: fn = difference_block; break;
	case LTK_KW_MERGE: fn = merge_block; break;
	case LTK_KW_TRIANGLE: fn = flat_triangle; break;
	case LTK_KW_SMOOTH_TRIANGLE: fn = smooth_triangle; break;
	default:
		if ((fn = lang_shape_parser(t.kind))) /* cylinder, torus, ... (shapes.c) */
			break;
		if (lang_pov_shape_kind(&t) >= 0) /* lathe, blob, text, ... (shapes2.c) */
			break;
		if (t.kind == LTK_UNSUPPORTED && lang_word_is(&t, "light_group")) {
			fn = light_group_block;
			break;
		}
		*matched = false;
		return true;
	}
	*matched = true;
	lang_advance(p);
	diag_loc open;
	TRY(lang_enter(p, t.loc));
	char nm[32];
	snprintf(nm, sizeof nm, "%.*s", (int)t.len, t.text);
	bool ok = open_block(p, nm, &open) && (fn ? fn(p, out, t.loc, open) : pov_shape(p, out, &t, open));
	lang_leave(p);
	return ok;
}

/* A declared pigment, finish or interior: a part record (new_part). */
static bool declare_part(parser *p, value *out, lang_tok k)
{
	diag_loc loc = lang_peek(p)->loc;
	scene_material *m;
	TRY(m = new_part(p, loc));
	out->mat = m;
	switch (k) {
	case LTK_KW_PIGMENT: out->kind = VAL_PIGMENT; return pigment(p, m, SCENE_COLOR_REFLECTANCE);
	case LTK_KW_FINISH: out->kind = VAL_FINISH; return finish(p, m);
	default: out->kind = VAL_INTERIOR; return interior(p, m);
	}
}

static bool camera_block(parser *p, scene_camera *c, diag_loc kw);
static bool light_block(parser *p, scene_light *out, diag_loc kw);

/* A declared camera, light_source or transform: its IR record, in the arena. */
static bool declare_record(parser *p, value *out, lang_tok k)
{
	lang_token kw = *lang_peek(p);
	size_t size = k == LTK_KW_CAMERA ? sizeof(scene_camera) : k == LTK_KW_LIGHT_SOURCE ? sizeof(scene_light)
											 : sizeof(xform);
	void *r = arena_zalloc(&p->sc->arena, 1, size);
	if (!r)
		return lang_error(p, kw.loc, "out of memory");
	if (k == LTK_KW_TRANSFORM) {
		out->kind = VAL_TRANSFORM, out->xf = r;
		return transform_block(p, r);
	}
	lang_advance(p);
	if (k == LTK_KW_CAMERA) {
		out->kind = VAL_CAMERA, out->cam = r;
		return camera_block(p, r, kw.loc);
	}
	out->kind = VAL_LIGHT, out->light = r;
	return light_block(p, r, kw.loc);
}

static bool declare_sky(parser *p, value *out);

bool lang_declare_block(parser *p, value *out, bool *handled)
{
	lang_tok k = lang_peek(p)->kind;
	memset(out, 0, sizeof *out);
	*handled = true;
	if (k == LTK_KW_MATERIAL) {
		out->kind = VAL_MATERIAL;
		return material(p, &out->mat);
	}
	if (k == LTK_KW_TEXTURE) { /* texture { } texture { } ...: a layered texture (stones2.inc) */
		out->kind = VAL_MATERIAL;
		TRY(texture(p, &out->mat, NULL));
		while (lang_raw_next(p) == LTK_KW_TEXTURE) { /* raw: a directive after the value runs later */
			diag_loc at = lang_peek(p)->loc;
			const scene_material *top;
			TRY(texture(p, &top, NULL));
			TRY(layer_texture(p, out->mat, top, at, &out->mat));
		}
		return true;
	}
	if (k == LTK_KW_PIGMENT || k == LTK_KW_FINISH || k == LTK_KW_INTERIOR)
		return declare_part(p, out, k);
	if (word_here(p, "density")) { /* a pigment record: density { D } reads it as its base */
		scene_material *m;
		TRY(m = new_part(p, lang_peek(p)->loc));
		out->kind = VAL_PIGMENT, out->mat = m;
		return lang_density(p, &m->pigment);
	}
	if (word_here(p, "media")) {
		scene_material *m;
		TRY(m = new_part(p, lang_peek(p)->loc));
		out->kind = VAL_MEDIA, out->mat = m;
		return interior_media(p, m);
	}
	if (k == LTK_KW_CAMERA || k == LTK_KW_LIGHT_SOURCE || k == LTK_KW_TRANSFORM)
		return declare_record(p, out, k);
	if (lang_pigment_map_starts(p))
		return lang_pigment_map_value(p, out);
	if (lang_normal_starts(p))
		return lang_normal_value(p, out);
	if (k == LTK_KW_SKY_SPHERE)
		return declare_sky(p, out);
	vecbuf tmp;
	vecbuf_init(&tmp, sizeof(scene_object));
	bool matched;
	/* A light_source in its CSG is parsed as in a placed object, then taken out of the scene's
	 * lights (and its light groups' ids noted) into the declared value: each copy places its
	 * own (declared_object). */
	size_t lights = p->sc->lights.len, objects = p->sc->objects.len;
	uint32_t groups = (uint32_t)p->sc->light_groups.len;
	bool saved = p->lights_in_csg;
	p->lights_in_csg = true;
	bool ok = object_item(p, &tmp, &matched);
	p->lights_in_csg = saved;
	if (!matched) {
		*handled = false;
		vecbuf_free(&tmp);
		return true;
	}
	/* add_light placed its lights' looks_like objects in the scene, unmoved by the blocks around
	 * them: each light's own copy (scene_light.looks, moved with it) is placed with each copy of
	 * the declared object instead (declared_object). */
	p->sc->objects.len = objects;
	objlist *l = ok ? arena_zalloc(&p->sc->arena, 1, sizeof *l) : NULL;
	if (l) {
		l->n = tmp.len;
		l->items = arena_alloc(&p->sc->arena, tmp.len ? tmp.len : 1, sizeof(scene_object), 16);
		if (l->items && tmp.len) /* none: a light_group of lights only */
			memcpy(l->items, tmp.data, tmp.len * sizeof(scene_object));
		l->first_group = groups + 1, l->n_groups = (uint32_t)p->sc->light_groups.len - groups;
		if (l->n_groups) {
			scene_light_group *copy = arena_alloc(&p->sc->arena, l->n_groups, sizeof *copy, 16);
			if (copy)
				memcpy(copy, &VECBUF_AT(&p->sc->light_groups, scene_light_group, groups),
				       l->n_groups * sizeof *copy);
			else
				l->items = NULL;
			l->groups = copy;
			p->sc->light_groups.len = groups;
		}
		l->n_lights = p->sc->lights.len - lights;
		if (l->n_lights) {
			scene_light *copy = arena_alloc(&p->sc->arena, l->n_lights, sizeof(scene_light), 16);
			if (copy)
				memcpy(copy, &VECBUF_AT(&p->sc->lights, scene_light, lights),
				       l->n_lights * sizeof(scene_light));
			else
				l->items = NULL;
			l->lights = copy;
			p->sc->lights.len = lights;
		}
	}
	vecbuf_free(&tmp);
	if (ok && (!l || !l->items))
		return lang_error(p, p->prev.loc, "out of memory");
	out->kind = VAL_OBJECT;
	out->obj = l;
	return ok;
}

/* object_ref = identifier | object_item: an object as a value's list (the object pattern's
 * object). A declared object's name is its own list, the same for every use. */
bool lang_object_list(parser *p, const char *what, const objlist **out)
{
	lang_token *t = lang_peek(p);
	if (t->kind == LTK_IDENT) {
		const symbol *s = lang_lookup(p, t->text, t->len);
		if (s && s->val.kind == VAL_OBJECT && s->val.obj) {
			lang_advance(p);
			*out = s->val.obj;
			return true;
		}
	}
	diag_loc at = t->loc;
	vecbuf tmp;
	vecbuf_init(&tmp, sizeof(scene_object));
	bool matched = true, ok;
	if (t->kind == LTK_KW_LIGHT_SOURCE) { /* POV-Ray's pattern of a light alone: inside nothing */
		bool saved = p->lights_in_csg;
		const char *saved_where = p->unplaced;
		p->lights_in_csg = false, p->unplaced = "object pattern";
		ok = csg_light(p, "object pattern");
		p->lights_in_csg = saved, p->unplaced = saved_where;
	} else
		ok = object_item_unplaced(p, &tmp, &matched, "object pattern");
	if (ok && !matched) {
		vecbuf_free(&tmp);
		return lang_error_found(p, "expected an object %s", what);
	}
	objlist *l = ok ? arena_zalloc(&p->sc->arena, 1, sizeof *l) : NULL;
	if (l) {
		l->n = tmp.len;
		l->items = arena_alloc(&p->sc->arena, tmp.len ? tmp.len : 1, sizeof(scene_object), 16);
		if (l->items && tmp.len)
			memcpy(l->items, tmp.data, tmp.len * sizeof(scene_object));
	}
	vecbuf_free(&tmp);
	if (ok && (!l || !l->items))
		return lang_error(p, at, "out of memory");
	*out = l;
	return ok;
}

/* ---- top-level statements ---------------------------------------------------------------- */

/* The items of POV-Ray 3.7's global_settings whose work circe does on its own or has no use for
 * (POV-Ray 3.7 documentation, "Global Settings"): each is read, dropped and warned about once
 * where it stands, saying why. A block's contents are not parsed: its braces are matched. An
 * integer setting takes any float, as POV-Ray's parser truncates it. */
typedef enum { IGNORED_BLOCK, IGNORED_COLOR, IGNORED_FLOAT, IGNORED_CHARSET, IGNORED_OPT_BOOL } ignored_arg;

static const struct ignored_setting {
	const char *name;
	ignored_arg arg;
	const char *why;
} ignored_settings[] = {
	{"radiosity", IGNORED_BLOCK,
	 "circe always computes global illumination; the block lets POV-Ray's background and sky_sphere "
	 "light the scene and turns the finishes' ambient off, as in POV-Ray"},
	{"photons", IGNORED_BLOCK, "circe always computes global illumination, caustics included"},
	{"noise_generator", IGNORED_FLOAT, "circe has one noise, Perlin's improved noise in POV-Ray's range"},
	{"number_of_waves", IGNORED_FLOAT, "circe has no wave patterns"},
	{"charset", IGNORED_CHARSET, "circe reads strings as bytes"},
	{"hf_gray_16", IGNORED_OPT_BOOL, "circe's output format is chosen on its command line"},
	{"adc_bailout", IGNORED_FLOAT, "circe ends paths by Russian roulette"},
	{"irid_wavelength", IGNORED_COLOR, "circe has no iridescence"},
	{"max_intersections", IGNORED_FLOAT, "circe's intersection tests need no limit"},
};

static const struct ignored_setting *ignored_setting(const lang_token *t)
{
	if (t->kind != LTK_UNSUPPORTED)
		return NULL;
	for (size_t i = 0; i < sizeof ignored_settings / sizeof ignored_settings[0]; i++)
		if (lang_token_is(t, ignored_settings[i].name))
			return &ignored_settings[i];
	return NULL;
}

bool lang_skip_block(parser *p, const char *what)
{
	diag_loc open;
	TRY(open_block(p, what, &open));
	for (unsigned long depth = 1;;) {
		lang_tok k = lang_peek(p)->kind;
		if (k == LTK_EOF || (k == LTK_RBRACE && depth == 1))
			return lang_expect_close(p, open, what);
		depth += k == LTK_LBRACE;
		depth -= k == LTK_RBRACE;
		lang_advance(p);
	}
}

/* Whether the lookahead ends hf_gray_16's optional value: '}' or the next item. */
static bool settings_item_follows(parser *p)
{
	const lang_token *t = lang_peek(p);
	return t->kind == LTK_RBRACE || t->kind == LTK_EOF || t->kind == LTK_UNSUPPORTED ||
	       t->kind == LTK_KW_MM_PER_UNIT || t->kind == LTK_KW_MAX_TRACE_LEVEL || t->kind == LTK_KW_ASSUMED_GAMMA;
}

/* One ignored item, its keyword the lookahead: its value read (and checked) and dropped. */
static bool ignored_item(parser *p, const struct ignored_setting *s)
{
	lang_token kw = *lang_advance(p);
	char ctx[64];
	snprintf(ctx, sizeof ctx, "after '%s'", s->name);
	double x;
	vec3 c;
	switch (s->arg) {
	case IGNORED_BLOCK:
		TRY(lang_skip_block(p, s->name));
		if (!strcmp(s->name, "radiosity")) {
			p->sc->global.radiosity = true;
			p->sc->global.radiosity_legacy = p->version < 3.7 - 1e-9;
		}
		break;
	case IGNORED_COLOR: TRY(lang_color(p, ctx, &c)); break;
	case IGNORED_FLOAT: TRY(lang_float(p, ctx, &x)); break;
	case IGNORED_OPT_BOOL:
		if (!settings_item_follows(p))
			TRY(lang_float(p, ctx, &x));
		break;
	case IGNORED_CHARSET: {
		const lang_token *t = lang_peek(p);
		bool word = t->kind == LTK_UNSUPPORTED || t->kind == LTK_IDENT;
		if (!word || !((t->len == 5 && !memcmp(t->text, "ascii", 5)) || (t->len == 4 && !memcmp(t->text, "utf8", 4)) ||
			       (t->len == 3 && !memcmp(t->text, "sys", 3))))
			return lang_error_found(p, "expected ascii, utf8 or sys %s", ctx);
		lang_advance(p);
		break;
	}
	}
	if (s->arg == IGNORED_BLOCK && !strcmp(s->name, "radiosity")) /* recorded: its settings are what goes */
		diag_warning(p->d, kw.loc, "'%s' settings are ignored: %s", s->name, s->why);
	else
		diag_warning(p->d, kw.loc, "'%s' is ignored: %s", s->name, s->why);
	return true;
}

/* subsurface_settings = "subsurface" "{" { "samples" integer [ "," ] integer | "radiosity" float } "}"
 * POV-Ray 3.7's (parser.cpp Parse_Global_Settings): switches the finishes' subsurface on. The
 * sample counts are recorded and warned about: circe is progressive; radiosity is recorded:
 * circe lights every entry point by global illumination anyway. */
static bool subsurface_settings(parser *p, scene_global *g)
{
	lang_advance(p);
	diag_loc open;
	TRY(open_block(p, "subsurface", &open));
	g->subsurface = true;
	for (;;) {
		const lang_token *t = lang_peek(p);
		diag_loc loc = t->loc;
		long n;
		double x;
		if (lang_accept(p, LTK_RBRACE))
			return true;
		if (lang_word_is(t, "samples")) {
			lang_advance(p);
			TRY(lang_int(p, "after 'samples'", 1, INT32_MAX, &n));
			g->subsurface_samples[0] = (int)n;
			lang_accept(p, LTK_COMMA);
			TRY(lang_int(p, "as the second sample count", 1, INT32_MAX, &n));
			g->subsurface_samples[1] = (int)n;
			diag_warning(p->d, loc, "the subsurface samples are ignored: circe is progressive (--spp, --time)");
		} else if (lang_word_is(t, "radiosity")) {
			lang_advance(p);
			TRY(lang_float(p, "after 'radiosity'", &x));
			g->subsurface_radiosity = x != 0;
		} else {
			return bad_item(p, open, "subsurface", "samples or radiosity");
		}
	}
}

/* global_settings = "global_settings" "{" { "mm_per_unit" float | "max_trace_level" integer
 *                   | "assumed_gamma" float | "noise_threshold" float | "ambient_light" color
 *                   | subsurface_settings | ignored_setting } "}"
 * ignored_setting = ( "radiosity" | "photons" ) "{" balanced-tokens "}"
 *                 | "irid_wavelength" color
 *                 | ( "adc_bailout" | "noise_generator" | "number_of_waves" | "max_intersections" ) float
 *                 | "charset" ( "ascii" | "utf8" | "sys" ) | "hf_gray_16" [ float ] */
static bool global_settings(parser *p)
{
	diag_loc open;
	lang_advance(p);
	TRY(open_block(p, "global_settings", &open));
	scene_global *g = &p->sc->global;
	for (;;) {
		lang_token t = *lang_peek(p);
		double x;
		long n;
		switch (t.kind) {
		case LTK_RBRACE:
			lang_advance(p);
			return true;
		case LTK_KW_MM_PER_UNIT:
			lang_advance(p);
			TRY(lang_float(p, "after 'mm_per_unit'", &x) && positive(p, t.loc, "mm_per_unit", x));
			g->mm_per_unit = x;
			break;
		case LTK_KW_MAX_TRACE_LEVEL:
			lang_advance(p);
			TRY(lang_int(p, "after 'max_trace_level'", 1, 256, &n));
			g->max_trace_level = (int)n;
			break;
		case LTK_KW_ASSUMED_GAMMA:
			lang_advance(p);
			TRY(lang_float(p, "after 'assumed_gamma'", &x) && positive(p, t.loc, "assumed_gamma", x));
			g->assumed_gamma = x;
			g->assumed_gamma_set = true;
			break;
		case LTK_KW_NOISE_THRESHOLD: /* circe's: adaptive sampling, as render --noise-threshold */
			lang_advance(p);
			TRY(lang_float(p, "after 'noise_threshold'", &x) && positive(p, t.loc, "noise_threshold", x));
			g->noise_threshold = x;
			break;
		default: {
			if (t.kind == LTK_UNSUPPORTED && t.len == 13 && !memcmp(t.text, "ambient_light", 13)) {
				lang_advance(p); /* scales every explicit finish ambient (finish.c) */
				TRY(physical_color(p, "after 'ambient_light'", "ambient_light", SCENE_COLOR_RADIANCE,
						   &g->ambient_light));
				break;
			}
			if (lang_word_is(&t, "subsurface")) {
				TRY(subsurface_settings(p, g));
				break;
			}
			const struct ignored_setting *s = ignored_setting(&t);
			if (!s)
				return bad_item(p, open, "global_settings",
						"mm_per_unit, max_trace_level, assumed_gamma or noise_threshold");
			TRY(ignored_item(p, s));
			break;
		}
		}
	}
}

/* The camera's projection keyword, or -1; "cylinder" (also the shape's keyword) is followed by its
 * number 1 to 4. */
static int camera_type(parser *p, const lang_token *t, bool *ok)
{
	*ok = true;
	switch (t->kind) {
	case LTK_KW_PERSPECTIVE: return SCENE_CAM_PERSPECTIVE;
	case LTK_KW_ORTHOGRAPHIC: return SCENE_CAM_ORTHOGRAPHIC;
	case LTK_KW_FISHEYE: return SCENE_CAM_FISHEYE;
	case LTK_KW_ULTRA_WIDE_ANGLE: return SCENE_CAM_ULTRA_WIDE_ANGLE;
	case LTK_KW_PANORAMIC: return SCENE_CAM_PANORAMIC;
	case LTK_KW_SPHERICAL: return SCENE_CAM_SPHERICAL;
	default: break;
	}
	if (lang_word_is(t, "omnimax"))
		return SCENE_CAM_OMNIMAX;
	if (t->kind != LTK_KW_CYLINDER)
		return -1;
	lang_advance(p);
	int64_t n;
	if (!lang_int(p, "after 'cylinder'", 1, 4, &n)) {
		*ok = false;
		return -1;
	}
	return SCENE_CAM_CYLINDER_1 + (int)(n - 1);
}

/* A camera transform (translate, rotate, scale, matrix, transform) into c->xf, applied after
 * every other setting (render/camera.c); *matched false when the lookahead is none. */
static bool camera_transform(parser *p, scene_camera *c, bool *matched)
{
	xform t = xform_identity();
	TRY(transform_item(p, &t, matched));
	if (*matched) {
		c->xf = c->has_xform ? xform_then(c->xf, t) : t;
		c->has_xform = true;
	}
	return true;
}

/* "angle" float [ "," float ] (the lookahead is 'angle'): the horizontal field of view, and a
 * spherical camera's vertical one (POV-Ray: half the horizontal unless given). */
static bool camera_angle(parser *p, scene_camera *c, diag_loc at)
{
	double x;
	lang_advance(p);
	TRY(lang_float(p, "after 'angle'", &x));
	bool screen = c->type == SCENE_CAM_PERSPECTIVE || c->type == SCENE_CAM_ORTHOGRAPHIC;
	if (!(x > 0 && (screen ? x < 180 : x <= 360)))
		return lang_error(p, at, "camera angle must be in (0, %s) degrees, found %g", screen ? "180" : "360]", x);
	c->angle_deg = x;
	c->has_angle = true;
	if (c->type != SCENE_CAM_SPHERICAL)
		return true;
	c->v_angle_deg = 0.5 * x; /* POV-Ray: the vertical half the horizontal */
	if (lang_accept(p, LTK_COMMA)) {
		diag_loc v_at = lang_peek(p)->loc;
		TRY(lang_float(p, "after 'angle' h ','", &x));
		if (!(x > 0 && x <= 180))
			return lang_error(p, v_at, "spherical camera's vertical angle must be in (0, 180], found %g", x);
		c->v_angle_deg = x;
	}
	return true;
}

/* POV-Ray's focal-blur sampling settings, read and not used: circe is progressive, every sample
 * of a pixel a lens sample, until --spp. "blur_samples" float [ "," float ] | "confidence" float
 * | "variance" float; t is the lookahead. */
static bool camera_accepted(parser *p, const lang_token *t)
{
	double x;
	lang_advance(p);
	if (t->kind == LTK_KW_BLUR_SAMPLES) {
		TRY(lang_float(p, "after 'blur_samples'", &x) && positive(p, t->loc, "blur_samples", x));
		if (lang_accept(p, LTK_COMMA))
			TRY(lang_float(p, "after 'blur_samples' min ','", &x));
		return true;
	}
	return lang_float(p, t->kind == LTK_KW_CONFIDENCE ? "after 'confidence'" : "after 'variance'", &x);
}

/* Distribution 3's faces: mesh o's non-degenerate faces of an area in uv, in order, with their uv
 * index, into c. smooth: a face whose corner normals differ takes them (POV-Ray's smooth
 * modifier, for its smooth triangles); else every face its own normal. */
static bool mesh_camera_uv(parser *p, const scene_object *o, bool smooth, scene_camera *c)
{
	const scene_mesh *m = &o->geom->u.mesh;
	scene_cam_uv_face *f = arena_zalloc(&p->sc->arena, m->n_faces ? m->n_faces : 1, sizeof *f);
	if (!f)
		return lang_error(p, o->loc, "out of memory");
	uint32_t n = 0;
	for (uint32_t i = 0; i < m->n_faces; i++) {
		dvec3 pt[3], nrm[3];
		vec2 uv[3] = {{0, 0}, {0, 0}, {0, 0}};
		bool has_n = smooth && m->normals;
		for (int k = 0; k < 3; k++) {
			uint32_t v = m->faces[3 * i + (uint32_t)k];
			uint32_t t = m->uv_idx ? m->uv_idx[3 * i + (uint32_t)k] : v;
			uint32_t q = m->normal_idx ? m->normal_idx[3 * i + (uint32_t)k] : v;
			pt[k] = v3_to_d3(m->positions[v]);
			if (m->uvs && t < m->n_uvs)
				uv[k] = m->uvs[t];
			if (has_n && q < m->n_normals) {
				/* POV-Ray's: a zero normal made <1,0,0>, each normalised */
				dvec3 x = v3_to_d3(m->normals[q]);
				double len = d3_length(x);
				nrm[k] = len > 0 ? d3_scale(x, 1 / len) : d3(1, 0, 0);
			} else {
				has_n = false;
			}
		}
		/* POV-Ray's smooth triangle: its normals differ (squared by more than its EPSILON) */
		if (has_n && !(d3_dot(d3_sub(nrm[0], nrm[1]), d3_sub(nrm[0], nrm[1])) > 1e-10 ||
			       d3_dot(d3_sub(nrm[0], nrm[2]), d3_sub(nrm[0], nrm[2])) > 1e-10))
			has_n = false;
		if (scene_cam_uv_face_make(pt, has_n ? nrm : NULL, uv, &o->transform, &f[n]))
			n++;
	}
	if (n == 0)
		return lang_error(
		    p, o->loc,
		    "the mesh_camera's mesh has no face with an area in uv (distribution 3 maps "
		    "each pixel to the uv_vectors of its faces)");
	c->uv_faces = f, c->uv_n = n, c->mesh_smooth = smooth;
	if (!scene_cam_uv_index(&p->sc->arena, f, n, &c->uv_grid, &c->uv_start, &c->uv_list))
		return lang_error(p, o->loc, "out of memory");
	return true;
}

/* POV-Ray's EPSILON: a max_distance below it is no limit (TraceRay: maxDepth >= EPSILON). */
#define MESH_CAMERA_MIN_DISTANCE 1e-10
/* A max_distance this large limits nothing a float ray can reach: taken as none. */
#define MESH_CAMERA_NO_LIMIT 1e30

/* POV-Ray's mesh_camera (Parse_Mesh_Camera), the lookahead 'mesh_camera': "{" rays_per_pixel
 * distribution_type [ max_distance ] { mesh | mesh2 } [ "smooth" ] "}". The distributions of
 * tracepixel.cpp's CreateCameraRay: 0, ray k of pixel i from face i of mesh k; 1, the meshes'
 * faces summed, ray k of pixel i from face k * width * height + i; 2, the meshes side by side;
 * 3, the first mesh's uv (render/camera.c's cam_sample). What POV-Ray refuses is refused where
 * it is written. max_distance: the camera ray's first hit is sought only that far (TraceRay's
 * maxDepth); POV-Ray takes one below its EPSILON, 1e-10, negative ones too, as no limit. */
static bool mesh_camera_block(parser *p, scene_camera *c)
{
	diag_loc open;
	lang_advance(p);
	TRY(open_block(p, "mesh_camera", &open));
	long rays, dist;
	diag_loc at = lang_peek(p)->loc, rays_at = at;
	TRY(lang_int(p, "for the mesh_camera's rays_per_pixel", 1, 1L << 30, &rays));
	at = lang_peek(p)->loc;
	TRY(lang_int(p, "for the mesh_camera's distribution_type", 0, 3, &dist));
	if (dist >= 2 && rays != 1)
		return lang_error(p, rays_at,
				  "rays per pixel must be 1 for mesh_camera distribution %ld, as in POV-Ray; "
				  "found %ld",
				  dist, rays);
	if (lang_float_follows(p)) {
		double x;
		at = lang_peek(p)->loc;
		TRY(lang_float(p, "for the mesh_camera's max_distance", &x));
		if (x < 0)
			diag_warning(p->d, at, "a negative max_distance (%g) is no limit, as in POV-Ray", x);
		else if (x >= MESH_CAMERA_MIN_DISTANCE && x < MESH_CAMERA_NO_LIMIT)
			c->mesh_max_distance = x;
	}
	vecbuf b;
	vecbuf_init(&b, sizeof(scene_object));
	bool ok = true;
	for (;;) {
		lang_token t = *lang_peek(p);
		if (t.kind != LTK_KW_MESH && t.kind != LTK_KW_MESH2)
			break;
		size_t from = b.len;
		bool matched;
		if (!(ok = object_item_unplaced(p, &b, &matched, "mesh_camera")))
			break;
		const scene_object *o = (const scene_object *)b.data + from;
		if (b.len != from + 1 || o->geom->kind != SHAPE_MESH) {
			ok = lang_error(p, t.loc, "a mesh_camera's mesh must be one plain mesh (no per-face textures, no "
						  "file)");
			break;
		}
		if (dist == 3 && from == 1)
			diag_warning(p->d, t.loc,
				     "a mesh_camera of distribution 3 uses its first mesh only: the meshes "
				     "after it are ignored, as in POV-Ray");
	}
	if (ok && b.len == 0)
		ok = lang_error(p, lang_peek(p)->loc, "a mesh_camera needs a mesh or mesh2 after its distribution type");
	if (ok && dist == 0 && (size_t)rays > b.len)
		ok = lang_error(p, rays_at, "a mesh_camera of distribution 0 needs a mesh for each of its %ld rays per pixel, "
				       "found %zu mesh%s",
				rays, b.len, b.len == 1 ? "" : "es");
	bool smooth = false;
	if (ok && lang_peek(p)->kind == LTK_KW_SMOOTH) {
		if (dist != 3)
			ok = lang_error(p, lang_peek(p)->loc,
					"smooth is for mesh_camera distribution 3 only, as in POV-Ray");
		else
			lang_advance(p), smooth = true;
	}
	if (ok && !lang_accept(p, LTK_RBRACE))
		ok = lang_error(p, lang_peek(p)->loc, "expected another mesh or '}' to close the mesh_camera opened at "
						      "line %d",
				open.line);
	if (ok && dist == 3)
		ok = mesh_camera_uv(p, (const scene_object *)b.data, smooth, c);
	/* Types 0 to 2: ray k of a pixel from mesh k (type 0), from the summed meshes (1) or the meshes
	 * side by side (2), as POV-Ray; the degenerate faces are not faces */
	if (ok && dist != 3) {
		uint32_t total = 0, nm = dist != 0 ? (uint32_t)b.len : (uint32_t)rays;
		for (uint32_t k = 0; k < nm; k++)
			total += ((const scene_object *)b.data)[k].geom->u.mesh.n_faces;
		scene_cam_face *f = arena_zalloc(&p->sc->arena, total ? total : 1, sizeof *f);
		uint32_t *first = arena_zalloc(&p->sc->arena, nm + 1, sizeof *first);
		if (!f || !first)
			ok = lang_error(p, open, "out of memory");
		uint32_t n = 0;
		for (uint32_t k = 0; ok && k < nm; k++) {
			const scene_object *o = (const scene_object *)b.data + k;
			const scene_mesh *m = &o->geom->u.mesh;
			first[k] = n;
			for (uint32_t i = 0; i < m->n_faces; i++) {
				const uint32_t *v = &m->faces[3 * i];
				if (scene_cam_face_make(v3_to_d3(m->positions[v[0]]), v3_to_d3(m->positions[v[1]]),
							v3_to_d3(m->positions[v[2]]), &o->transform, &f[n]))
					n++;
			}
			if (n == first[k])
				ok = lang_error(p, o->loc, "the mesh_camera's mesh has no face with an area");
		}
		if (ok)
			first[nm] = n;
		c->mesh_faces = f, c->mesh_n = n, c->mesh_first = first, c->mesh_count = nm;
	}
	if (ok) {
		c->mesh_distribution = (int)dist;
		c->mesh_rays = (uint32_t)rays;
		c->type = SCENE_CAM_MESH;
	}
	vecbuf_free(&b);
	return ok;
}

/* camera = "camera" "{" [ projection ] { "location" vector | "look_at" vector | "sky" vector
 *          | "direction" vector | "angle" float [ "," float ] | "right" vector | "up" vector
 *          | "aperture" float | "focal_point" vector | "blur_samples" float [ "," float ]
 *          | "confidence" float | "variance" float | transform } "}"
 * (an identifier first: a declared camera, then modified)
 * projection = "perspective" | "orthographic" | "fisheye" | "ultra_wide_angle" | "panoramic"
 *          | "cylinder" int | "spherical" | "omnimax" | mesh_camera (mesh_camera_block)
 * As POV-Ray 3.7 (Parse_Camera), the order of the settings does not matter: angle applies after
 * right and direction, look_at after angle, the transforms last (render/camera.c). */
static bool camera_block(parser *p, scene_camera *c, diag_loc kw)
{
	diag_loc open;
	TRY(open_block(p, "camera", &open));
	*c = (scene_camera){.loc = kw,
			    .location = d3(0, 0, 0),
			    .look_at = d3(0, 0, 1),
			    .sky = d3(0, 1, 0),
			    .right = d3(1.33, 0, 0),
			    .up = d3(0, 1, 0),
			    .direction = d3(0, 0, 1),
			    .v_angle_deg = 180,
			    .angle_deg = 67.380135}; /* POV-Ray's default: 2 atan(1.33 / 2) */
	if (lang_peek(p)->kind == LTK_IDENT) {
		const value *v;
		TRY(v = declared(p, VAL_CAMERA, "a camera"));
		*c = *v->cam;
		c->loc = kw;
	}
	bool first = true;
	for (;;) {
		lang_token t = *lang_peek(p);
		double x;
		dvec3 *v = NULL;
		bool ok, matched;
		int type = camera_type(p, &t, &ok);
		TRY(ok);
		if (type < 0 && lang_word_is(&t, "mesh_camera")) {
			if (!first)
				return lang_error(p, t.loc, "the projection ('mesh_camera') must come first in the camera, as "
							    "in POV-Ray");
			TRY(mesh_camera_block(p, c));
			first = false;
			continue;
		}
		if (type >= 0) {
			if (!first)
				return lang_error(p, t.loc, "the projection ('%.*s') must come first in the camera, as in POV-Ray",
						  (int)t.len, t.text);
			if (type < SCENE_CAM_CYLINDER_1 || type > SCENE_CAM_CYLINDER_4)
				lang_advance(p);
			c->type = type;
			if (type != SCENE_CAM_PERSPECTIVE && type != SCENE_CAM_ORTHOGRAPHIC)
				c->angle_deg = type == SCENE_CAM_SPHERICAL ? 360 : 90; /* POV-Ray's Camera::Init */
			first = false;
			continue;
		}
		first = false;
		TRY(camera_transform(p, c, &matched));
		if (matched)
			continue;
		if (lang_normal_starts(p)) { /* POV-Ray's camera normal: the rays' directions perturbed */
			scene_material *scratch = arena_zalloc(&p->sc->arena, 1, sizeof *scratch);
			if (!scratch)
				return lang_error(p, t.loc, "out of memory");
			scratch->loc = t.loc;
			scratch->normal = c->normal;
			TRY(lang_normal(p, scratch));
			c->normal = scratch->normal, c->normal_loc = t.loc;
			continue;
		}
		switch (t.kind) {
		case LTK_RBRACE:
			lang_advance(p);
			if (c->normal && c->type != SCENE_CAM_PERSPECTIVE && c->type != SCENE_CAM_ORTHOGRAPHIC)
				return lang_error(p, c->normal_loc, "a camera's normal is supported by circe on perspective and "
								    "orthographic cameras only");
			return true;
		case LTK_KW_LOCATION: v = &c->location; break;
		case LTK_KW_LOOK_AT:
			v = &c->look_at;
			c->has_look_at = true;
			break;
		case LTK_KW_SKY: v = &c->sky; break;
		case LTK_KW_RIGHT:
			v = &c->right;
			c->has_right = true;
			break;
		case LTK_KW_UP:
			v = &c->up;
			c->has_up = true;
			break;
		case LTK_KW_DIRECTION:
			v = &c->direction;
			c->has_direction = true;
			break;
		case LTK_KW_FOCAL_POINT:
			v = &c->focal_point;
			c->has_focal_point = true;
			break;
		case LTK_KW_ANGLE:
			TRY(camera_angle(p, c, t.loc));
			continue;
		case LTK_KW_APERTURE:
			lang_advance(p);
			TRY(lang_float(p, "after 'aperture'", &x));
			if (x < 0)
				return lang_error(p, t.loc, "aperture must be >= 0, found %g", x);
			c->aperture = x;
			continue;
		case LTK_KW_BLUR_SAMPLES:
		case LTK_KW_CONFIDENCE:
		case LTK_KW_VARIANCE:
			TRY(camera_accepted(p, &t));
			continue;
		default:
			return bad_item(p, open, "camera", "a camera setting (location, look_at, sky, angle, ..., a transform)");
		}
		lang_advance(p);
		char ctx[48];
		snprintf(ctx, sizeof ctx, "after '%.*s'", (int)t.len, t.text);
		TRY(lang_vec3(p, ctx, v));
	}
}

/* The scene's camera statement. A later one replaces the camera, as in POV-Ray 3.7 (its
 * Parse_Frame parses each into the one scene camera; screen.inc's Set_Camera_* macros rely on
 * it), with a warning, since two cameras in one file are more often a slip. */
static bool camera(parser *p)
{
	lang_token kw = *lang_advance(p);
	if (p->sc->has_camera) {
		diag_warning(p->d, kw.loc, "a second camera replaces the first (POV-Ray uses the last one)");
		diag_note(p->d, p->sc->camera.loc, "the first camera is here");
	}
	p->sc->has_camera = true;
	return camera_block(p, &p->sc->camera, kw.loc);
}

/* A light's colour: a negative component is POV-Ray's negative light, which takes light away
 * (doc/language.md, "Negative lights"). */
static bool light_colour(parser *p, vec3 *c)
{
	return lang_color(p, "as the light colour", c);
}

/* POV-Ray's light words that mean something only in a light_source. They stay out of the keyword
 * table, so anywhere else they remain "'jitter' is not supported by circe"; in a light_source they
 * are matched by spelling (and `cylinder`, a shape's keyword, by its token). */
typedef enum light_word {
	LW_NONE,
	LW_ADAPTIVE,
	LW_AREA_LIGHT,
	LW_CIRCULAR,
	LW_CYLINDER,
	LW_FADE_DISTANCE,
	LW_FADE_POWER,
	LW_JITTER,
	LW_MEDIA_ATTENUATION,
	LW_MEDIA_INTERACTION,
	LW_ORIENT,
	LW_SHADOWLESS,
	LW_TIGHTNESS
} light_word;

static light_word light_word_at(const lang_token *t)
{
	static const char *const names[] = {"", "adaptive", "area_light", "circular", "cylinder", "fade_distance",
					    "fade_power", "jitter", "media_attenuation", "media_interaction",
					    "orient", "shadowless", "tightness"};
	if (t->kind == LTK_KW_CYLINDER) /* a keyword since cylinder is a shape */
		return LW_CYLINDER;
	return (light_word)pov_word_at(t, names, sizeof names / sizeof names[0]);
}

/* Where a light_source's items that need another were given, for the checks at its '}'. */
typedef struct light_seen {
	bool tightness, fade, area_mod, projected;
	diag_loc tightness_loc, fade_loc, area_loc, area_mod_loc, projected_loc;
	const char *area_mod_name;
} light_seen;

/* area_light = "area_light" vector "," vector "," float "," float: POV-Ray's counts are integers
 * >= 1 (parse.cpp); circe samples the area continuously and keeps them for the dump only. */
static bool area_light(parser *p, scene_light *l, light_seen *seen, diag_loc at)
{
	double n1, n2;
	diag_loc n1_loc, n2_loc;
	TRY(lang_vec3(p, "after 'area_light'", &l->axis1));
	TRY(lang_expect(p, LTK_COMMA, "after area_light's first axis"));
	TRY(lang_vec3(p, "as area_light's second axis", &l->axis2));
	TRY(lang_expect(p, LTK_COMMA, "after area_light's second axis"));
	n1_loc = lang_peek(p)->loc;
	TRY(lang_float(p, "as area_light's first count", &n1));
	TRY(lang_expect(p, LTK_COMMA, "after area_light's first count"));
	n2_loc = lang_peek(p)->loc;
	TRY(lang_float(p, "as area_light's second count", &n2));
	if (!(n1 >= 1 && n1 <= INT_MAX))
		return lang_error(p, n1_loc, "area_light's counts must be >= 1 (POV-Ray truncates them to integers), found %g", n1);
	if (!(n2 >= 1 && n2 <= INT_MAX))
		return lang_error(p, n2_loc, "area_light's counts must be >= 1 (POV-Ray truncates them to integers), found %g", n2);
	l->area = true;
	l->area_n1 = (int)n1, l->area_n2 = (int)n2;
	seen->area_loc = at;
	return true;
}

/* One of POV-Ray's light words (light_word) at the lookahead, into *l; *matched says whether one
 * was there. */
/* POV-Ray's optional boolean after a flag word: on when none follows. */
static bool optional_bool(parser *p, bool *on)
{
	double x = 1;
	if (lang_float_follows(p))
		TRY(lang_float(p, "after it", &x));
	*on = x > 0;
	return true;
}

static bool light_word_item(parser *p, scene_light *l, light_seen *seen, bool *matched)
{
	lang_token t = *lang_peek(p);
	light_word w = light_word_at(&t);
	*matched = w != LW_NONE;
	if (!*matched)
		return true;
	lang_advance(p);
	char ctx[48];
	snprintf(ctx, sizeof ctx, "after '%.*s'", (int)t.len, t.text);
	double x;
	switch (w) {
	case LW_CYLINDER:
		if (l->kind == SCENE_LIGHT_SPOT || l->kind == SCENE_LIGHT_PARALLEL || l->kind == SCENE_LIGHT_CYLINDER)
			return lang_error(p, t.loc, "a light is one of spotlight, cylinder or parallel, not two");
		/* POV-Ray's defaults for a cylinder (parse.cpp): radius 0.75, falloff 1, tightness 0. */
		l->kind = SCENE_LIGHT_CYLINDER;
		l->radius = 0, l->cyl_radius = 0.75, l->cyl_falloff = 1, l->tightness = 0;
		return true;
	case LW_TIGHTNESS:
		TRY(lang_float(p, ctx, &x));
		if (x < 0)
			return lang_error(p, t.loc, "tightness must be >= 0, found %g", x);
		l->tightness = x;
		seen->tightness = true, seen->tightness_loc = t.loc;
		return true;
	case LW_FADE_DISTANCE:
	case LW_FADE_POWER:
		TRY(lang_float(p, ctx, &x));
		if (w == LW_FADE_DISTANCE && x < 0)
			return lang_error(p, t.loc, "fade_distance must be >= 0, found %g", x);
		*(w == LW_FADE_DISTANCE ? &l->fade_distance : &l->fade_power) = x;
		if (!seen->fade)
			seen->fade_loc = t.loc;
		seen->fade = true;
		return true;
	case LW_SHADOWLESS:
		l->shadowless = true;
		return true;
	case LW_MEDIA_INTERACTION: { /* [bool]: off, the light scatters in no medium */
		bool on = true;
		TRY(optional_bool(p, &on));
		l->no_media = !on;
		return true;
	}
	case LW_MEDIA_ATTENUATION: { /* [bool]: accepted; circe's shadow rays always cross media */
		bool on = true;
		TRY(optional_bool(p, &on));
		if (!on)
			diag_warning(p->d, t.loc, "'media_attenuation off' is ignored by circe: light through media is "
						  "always attenuated (physically)");
		return true;
	}
	case LW_AREA_LIGHT:
		return area_light(p, l, seen, t.loc);
	case LW_ADAPTIVE: /* accepted: circe's area sampling is continuous, nothing to subdivide */
		TRY(lang_float(p, ctx, &x));
		if (x < 0)
			return lang_error(p, t.loc, "adaptive must be >= 0, found %g", x);
		break;
	case LW_JITTER: l->jitter = true; break;
	case LW_CIRCULAR: l->circular = true; break;
	case LW_ORIENT: l->orient = true; break;
	default: break;
	}
	if (!seen->area_mod)
		seen->area_mod_loc = t.loc, seen->area_mod_name = w == LW_ADAPTIVE ? "adaptive"
							      : w == LW_JITTER ? "jitter"
							      : w == LW_CIRCULAR ? "circular" : "orient";
	seen->area_mod = true;
	return true;
}

/* The checks at a light_source's '}' of what its POV-Ray items ask of the others. */
static bool light_pov_checks(parser *p, const scene_light *l, const light_seen *seen)
{
	if (seen->tightness && l->kind != SCENE_LIGHT_SPOT && l->kind != SCENE_LIGHT_CYLINDER)
		return lang_error(p, seen->tightness_loc, "'tightness' needs 'spotlight' or 'cylinder'");
	if (l->kind == SCENE_LIGHT_CYLINDER && !(l->cyl_falloff > 0))
		return lang_error(p, l->loc, "cylinder falloff must be > 0, found %g", l->cyl_falloff);
	/* A falloff below the radius is POV-Ray's too (parser.cpp keeps both): the beam is lit fully
	 * out to the falloff and not beyond (render/light.c cylinder_factor). */
	if (seen->fade && l->has_intensity)
		return lang_error(p, seen->fade_loc, "fade_distance and fade_power are POV-Ray's distance law and "
						     "'intensity' circe's (1 / d^2): give one or the other");
	if (seen->fade && l->kind == SCENE_LIGHT_SPHERE)
		return lang_error(p, seen->fade_loc, "a sphere light is an emitter whose light falls off as 1 / d^2: "
						     "fade_distance and fade_power do not apply");
	if (seen->fade && !(l->fade_distance > 0 && l->fade_power > 0))
		diag_warning(p->d, seen->fade_loc, "the light does not fade: POV-Ray fades only with both "
						   "fade_distance and fade_power > 0 (fade_power's default is 0)");
	if (l->area && l->kind != SCENE_LIGHT_POINT && l->kind != SCENE_LIGHT_SPOT)
		return lang_error(p, seen->area_loc, "'area_light' on a %s light is not supported by circe",
				  l->kind == SCENE_LIGHT_SPHERE ? "sphere" : l->kind == SCENE_LIGHT_PARALLEL ? "parallel"
													 : "cylinder");
	if (l->kind == SCENE_LIGHT_SPHERE && !(l->color.x >= 0 && l->color.y >= 0 && l->color.z >= 0))
		return lang_error(p, l->loc, "a negative colour on a sphere light (circe's radius, an emitter that paths "
					     "hit) is not supported by circe: POV-Ray's negative light is a point, spot, "
					     "parallel or cylinder light");
	if (seen->projected && l->kind == SCENE_LIGHT_SPHERE) /* paths hit it: they would need the test too */
		return lang_error(p, seen->projected_loc, "projected_through on a sphere light (circe's radius) is not "
							  "supported by circe: give it to a point, spot, parallel or cylinder light");
	if (seen->area_mod && !l->area)
		diag_warning(p->d, seen->area_mod_loc, "'%s' only affects area_light", seen->area_mod_name);
	return true;
}

/* The light's looks_like and projected_through objects copied into the arena (each light placed
 * moves its own). */
static bool copy_looks(parser *p, scene_light *l, diag_loc at)
{
	if (l->n_looks) {
		scene_object *o = arena_zalloc(&p->sc->arena, l->n_looks, sizeof *o);
		if (!o)
			return lang_error(p, at, "out of memory");
		memcpy(o, l->looks, l->n_looks * sizeof *o);
		l->looks = o;
	}
	if (l->n_projected) {
		scene_object *o = arena_zalloc(&p->sc->arena, l->n_projected, sizeof *o);
		if (!o)
			return lang_error(p, at, "out of memory");
		memcpy(o, l->projected, l->n_projected * sizeof *o);
		l->projected = o;
	}
	if (l->n_looks_lights) { /* and the lights in its looks_like, each with its own */
		scene_light *c = arena_zalloc(&p->sc->arena, l->n_looks_lights, sizeof *c);
		if (!c)
			return lang_error(p, at, "out of memory");
		memcpy(c, l->looks_lights, l->n_looks_lights * sizeof *c);
		l->looks_lights = c;
		for (uint32_t i = 0; i < l->n_looks_lights; i++)
			TRY(copy_looks(p, &c[i], at));
	}
	return true;
}

/* The object of a light's block `what` (projected_through, looks_like): a declared object, as
 * POV-Ray's Parse_Object takes it, or an object item, into *b. A projected_through's object is
 * not placed in the scene: its lights light nothing (csg_light, declared_object). A looks_like's
 * is (POV-Ray's Post_Process walks the light's children): its lights, and a light_source written
 * as the looks_like's object itself, join the scene's lights from their index on (looks_like
 * takes them into the light). */
static bool light_object(parser *p, const char *what, vecbuf *b)
{
	bool matched = true, ok, placed = !strcmp(what, "looks_like");
	size_t lights = p->sc->lights.len;
	bool saved = p->lights_in_csg;
	const char *saved_where = p->unplaced;
	if (placed)
		p->lights_in_csg = true, p->unplaced = NULL;
	else
		p->lights_in_csg = false, p->unplaced = what;
	if (placed && names(p, VAL_LIGHT)) { /* a declared light as the looks_like's object */
		diag_loc at = lang_peek(p)->loc;
		const value *v = declared(p, VAL_LIGHT, "a light_source");
		scene_light l;
		ok = v != NULL;
		if (ok)
			l = *v->light, l.loc = at;
		ok = ok && copy_looks(p, &l, at) && add_light(p, &l, at);
	} else if (lang_peek(p)->kind == LTK_IDENT)
		ok = declared_object(p, b, lang_peek(p)->loc);
	else if (placed && lang_peek(p)->kind == LTK_KW_LIGHT_SOURCE)
		ok = csg_light(p, what);
	else
		ok = object_item(p, b, &matched);
	p->lights_in_csg = saved, p->unplaced = saved_where;
	if (ok && (!matched || (!b->len && p->sc->lights.len == lights)))
		ok = lang_error_found(p, "expected an object in '%s'", what);
	return ok;
}

/* The block's modifiers up to its '}' (moving the scene's lights from `lights` on too), then b's
 * objects copied into the scene's arena (casting no shadow when no_shadow): *out, *n. */
static bool light_object_end(parser *p, const char *what, diag_loc kw, diag_loc open, vecbuf *b, size_t lights,
			     bool no_shadow, const scene_object **out, uint32_t *n)
{
	TRY(object_tail_lights(p, b, 0, lights, open, what));
	if (!b->len) {
		*out = NULL, *n = 0;
		return true;
	}
	scene_object *o = arena_zalloc(&p->sc->arena, b->len, sizeof *o);
	if (!o)
		return lang_error(p, kw, "out of memory");
	memcpy(o, b->data, b->len * sizeof *o);
	for (size_t i = 0; no_shadow && i < b->len; i++)
		o[i].no_shadow = true;
	*out = o, *n = (uint32_t)b->len;
	return true;
}

/* projected_through = "projected_through" "{" ( identifier | object_item ) { modifier } "}":
 * POV-Ray's (Parse_Light_Source): the light reaches a point only through the object, which is
 * not placed in the scene (moved by the light's later transforms); one a light. */
static bool projected_through(parser *p, scene_light *l)
{
	diag_loc kw = lang_advance(p)->loc, open;
	if (l->n_projected)
		return lang_error(p, kw, "only one projected_through is allowed in a light_source");
	TRY(open_block(p, "projected_through", &open));
	vecbuf b;
	vecbuf_init(&b, sizeof(scene_object));
	bool ok = light_object(p, "projected_through", &b) &&
		  light_object_end(p, "projected_through", kw, open, &b, p->sc->lights.len, false, &l->projected,
				   &l->n_projected);
	vecbuf_free(&b);
	return ok;
}

/* looks_like = "looks_like" "{" ( identifier | object_item | light_source ) { modifier } "}":
 * POV-Ray's (Parse_Light_Source): the object translated to the light's position as it stands,
 * then its modifiers, no_shadow; one a light. The light_sources in it (or it) light the scene as
 * POV-Ray's Post_Process finds them among the light's children, moved with the object: taken out
 * of the scene's lights into l->looks_lights (add_light places them after l). */
static bool looks_like(parser *p, scene_light *l)
{
	diag_loc kw = lang_advance(p)->loc, open;
	if (l->n_looks || l->n_looks_lights)
		return lang_error(p, kw, "only one looks_like is allowed in a light_source");
	TRY(open_block(p, "looks_like", &open));
	vecbuf b;
	vecbuf_init(&b, sizeof(scene_object));
	size_t lights = p->sc->lights.len, objects = p->sc->objects.len;
	bool ok = light_object(p, "looks_like", &b);
	xform to = xform_translate(l->position);
	for (size_t i = 0; ok && i < b.len; i++)
		VECBUF_AT(&b, scene_object, i).transform = xform_then(VECBUF_AT(&b, scene_object, i).transform, to);
	for (size_t i = lights; ok && i < p->sc->lights.len; i++)
		light_move(&VECBUF_AT(&p->sc->lights, scene_light, i), &to);
	ok = ok && light_object_end(p, "looks_like", kw, open, &b, lights, true, &l->looks, &l->n_looks);
	vecbuf_free(&b);
	if (ok && p->sc->lights.len > lights) {
		/* add_light placed their own looks_like objects: placed again with l (add_light) */
		size_t n = p->sc->lights.len - lights;
		scene_light *c = arena_zalloc(&p->sc->arena, n, sizeof *c);
		if (!c)
			return lang_error(p, kw, "out of memory");
		memcpy(c, &VECBUF_AT(&p->sc->lights, scene_light, lights), n * sizeof *c);
		l->looks_lights = c, l->n_looks_lights = (uint32_t)n;
	}
	p->sc->lights.len = lights, p->sc->objects.len = objects;
	return ok;
}

/* What a light_source starts with: a declared light's name (copied, then modified; its
 * point_at counts as given), or the position and an optional colour after a comma (a float, a
 * vector or a name: `<0, 9, 0>, 1` is grey). */
static bool light_head(parser *p, scene_light *l, diag_loc kw, bool *point_at)
{
	if (names(p, VAL_LIGHT)) {
		const value *v;
		TRY(v = declared(p, VAL_LIGHT, "a light_source"));
		*l = *v->light;
		l->loc = kw;
		TRY(copy_looks(p, l, kw));
		*point_at = l->kind == SCENE_LIGHT_SPOT || l->kind == SCENE_LIGHT_PARALLEL || l->kind == SCENE_LIGHT_CYLINDER;
		return true;
	}
	TRY(lang_vec3(p, "as the light position", &l->position));
	if (lang_accept(p, LTK_COMMA)) { /* a colour led by no keyword: a float, a vector, a name */
		lang_tok k = lang_peek(p)->kind;
		if (k < LANG_FIRST_KEYWORD && k != LTK_RBRACE && k != LTK_UNSUPPORTED && k != LTK_EOF)
			TRY(light_colour(p, &l->color));
	}
	return true;
}

/* The checks at a light_source's '}' of what its items ask of each other: point_at and falloff
 * (given where their loc is not NULL) need a light with a direction, and a directed light's
 * point_at is not its position. */
static bool light_close(parser *p, const scene_light *l, diag_loc kw, const diag_loc *point_at, const diag_loc *falloff)
{
	bool directed = l->kind == SCENE_LIGHT_SPOT || l->kind == SCENE_LIGHT_PARALLEL || l->kind == SCENE_LIGHT_CYLINDER;
	if (point_at && !directed)
		return lang_error(p, *point_at, "'point_at' needs 'spotlight', 'cylinder' or 'parallel'");
	if (falloff && l->kind != SCENE_LIGHT_SPOT && l->kind != SCENE_LIGHT_CYLINDER)
		return lang_error(p, *falloff, "'falloff' needs 'spotlight' or 'cylinder'");
	/* A spot's falloff below its radius is POV-Ray's too: lit fully inside the radius, not outside
	 * (render/light.c light_spot). */
	if (directed && !(d3_length(d3_sub(l->point_at, l->position)) > 0))
		return lang_error(p, kw, "point_at is the light position: the light has no direction");
	return true;
}

/* light_source = "light_source" "{" ( identifier | vector [ "," colour ] ) { colour
 *                | "intensity" float | "radius" float | "spotlight" | "cylinder" | "parallel"
 *                | "point_at" vector | "falloff" float | "tightness" float | "fade_distance" float
 *                | "fade_power" float | "shadowless"
 *                | "area_light" vector "," vector "," float "," float | "jitter" | "circular"
 *                | "orient" | "adaptive" float | transform_item } "}"
 * Into *out, the keyword consumed (at kw). A float colour is grey (`<0, 9, 0>, 1`). A transform
 * moves the position and point_at given before it, and turns the area axes, as in POV-Ray. */
static bool light_body(parser *p, scene_light *out, diag_loc kw, diag_loc open);

/* A spotlight's radius or falloff in degrees: POV-Ray keeps only its cosine, so a negative angle
 * is its opposite (cornell.pov's `radius -90` for a cosine falloff) and any angle is the one in
 * [0, 180] of its cosine (laser.pov's `falloff 250` is 110). Over 90 degrees the cone is wider
 * than a half-space: POV-Ray's spot still lights nothing behind it (Attenuate_Light: cos theta >
 * 0), its spline reaching down to the falloff's negative cosine; a radius over 90 leaves the
 * tightness alone (POV-Ray's `Radius > 0` test), as render/light.c's spline gives 1 above it. */
static bool spot_angle(parser *p, diag_loc loc, const char *what, double *x)
{
	if (!isfinite(*x))
		return lang_error(p, loc, "spotlight %s must be finite", what);
	*x = fmod(fabs(*x), 360.0);
	if (*x > 180.0)
		*x = 360.0 - *x;
	return true;
}

static bool light_block(parser *p, scene_light *out, diag_loc kw)
{
	diag_loc open;
	TRY(open_block(p, "light_source", &open));
	return light_body(p, out, kw, open);
}

/* A light_source's items after its '{' (at open). */
static bool light_body(parser *p, scene_light *out, diag_loc kw, diag_loc open)
{
	scene_light l = {.loc = kw, .kind = SCENE_LIGHT_POINT, .color = v3s(1), .intensity = 1,
			 .point_at = d3(0, 0, 1), .cone_deg = 30, .falloff_deg = 45};
	bool point_at = false, falloff = false;
	diag_loc point_at_loc = kw, falloff_loc = kw;
	light_seen seen = {0};
	TRY(light_head(p, &l, kw, &point_at));
	for (;;) {
		lang_token t = *lang_peek(p);
		double x;
		if (starts_colour(p)) {
			TRY(light_colour(p, &l.color));
			continue;
		}
		xform moved = xform_identity();
		bool matched;
		TRY(transform_item(p, &moved, &matched));
		if (matched) {
			light_move(&l, &moved);
			continue;
		}
		bool directed = l.kind == SCENE_LIGHT_SPOT || l.kind == SCENE_LIGHT_PARALLEL || l.kind == SCENE_LIGHT_CYLINDER;
		switch (t.kind) {
		case LTK_RBRACE:
			lang_advance(p);
			TRY(light_close(p, &l, kw, point_at ? &point_at_loc : NULL, falloff ? &falloff_loc : NULL) &&
			    light_pov_checks(p, &l, &seen));
			*out = l;
			return true;
		case LTK_KW_INTENSITY:
			lang_advance(p);
			TRY(lang_float(p, "after 'intensity'", &x));
			if (x < 0)
				return lang_error(p, t.loc, "light intensity must be >= 0, found %g", x);
			l.intensity = x;
			l.has_intensity = true;
			break;
		case LTK_KW_RADIUS:
			lang_advance(p);
			TRY(lang_float(p, "after 'radius'", &x));
			if (l.kind == SCENE_LIGHT_SPOT) {
				TRY(spot_angle(p, t.loc, "radius", &x));
				l.cone_deg = x;
			} else if (l.kind == SCENE_LIGHT_CYLINDER) {
				if (x < 0)
					return lang_error(p, t.loc, "cylinder radius must be >= 0, found %g", x);
				l.cyl_radius = x;
			} else {
				if (x < 0)
					return lang_error(p, t.loc, "light radius must be >= 0, found %g", x);
				l.radius = x;
				l.kind = x > 0 ? SCENE_LIGHT_SPHERE : SCENE_LIGHT_POINT;
			}
			break;
		case LTK_KW_FALLOFF:
			lang_advance(p);
			if (l.kind == SCENE_LIGHT_CYLINDER) {
				TRY(lang_float(p, "after 'falloff'", &x));
				l.cyl_falloff = x;
			} else {
				TRY(lang_float(p, "after 'falloff'", &x) && spot_angle(p, t.loc, "falloff", &x));
				l.falloff_deg = x;
			}
			falloff = true, falloff_loc = t.loc;
			break;
		case LTK_KW_SPOTLIGHT:
		case LTK_KW_PARALLEL:
			lang_advance(p);
			if (directed)
				return lang_error(p, t.loc, "a light is one of spotlight, cylinder or parallel, not two");
			l.kind = t.kind == LTK_KW_SPOTLIGHT ? SCENE_LIGHT_SPOT : SCENE_LIGHT_PARALLEL;
			l.radius = 0;
			break;
		case LTK_KW_POINT_AT:
			lang_advance(p);
			TRY(lang_vec3(p, "after 'point_at'", &l.point_at));
			point_at = true, point_at_loc = t.loc;
			break;
		default: {
			bool matched;
			if (t.kind == LTK_UNSUPPORTED && lang_word_is(&t, "looks_like")) {
				TRY(looks_like(p, &l));
				continue;
			}
			if (t.kind == LTK_UNSUPPORTED && lang_word_is(&t, "projected_through")) {
				TRY(projected_through(p, &l));
				if (!seen.projected)
					seen.projected_loc = t.loc;
				seen.projected = true;
				continue;
			}
			if (lang_word_is(&t, "photons")) { /* POV-Ray's photon flags of a light (balcony.pov) */
				lang_advance(p);
				TRY(lang_skip_block(p, "photons"));
				if (!(p->finish_warned & LANG_WARNED_LIGHT_PHOTONS))
					diag_warning(p->d, t.loc, "a light_source's 'photons' is accepted and ignored: circe "
								  "computes caustics by its own path tracing (said once)");
				p->finish_warned |= LANG_WARNED_LIGHT_PHOTONS;
				continue;
			}
			TRY(light_word_item(p, &l, &seen, &matched));
			if (matched)
				continue;
			return bad_item(p, open, "light_source",
					"a colour, intensity, radius, spotlight, cylinder, parallel, point_at, falloff, "
					"tightness, fade_distance, fade_power, shadowless, area_light or a transform");
		}
		}
	}
}

/* The objects of l's looks_like and of the lights in it, pushed onto the scene's objects. */
static bool add_looks(parser *p, const scene_light *l, diag_loc kw)
{
	for (uint32_t i = 0; i < l->n_looks; i++) /* the objects that show it */
		if (!vecbuf_push(&p->sc->objects, &l->looks[i]))
			return lang_error(p, kw, "out of memory");
	for (uint32_t i = 0; i < l->n_looks_lights; i++)
		TRY(add_looks(p, &l->looks_lights[i], kw));
	return true;
}

/* A light placed in the scene, with the objects of its looks_like. The lights in its looks_like
 * stay in it (moved with it by light_move) until lang_lights_flatten places them. */
static bool add_light(parser *p, const scene_light *l, diag_loc kw)
{
	if (!vecbuf_push(&p->sc->lights, l))
		return lang_error(p, kw, "out of memory");
	return add_looks(p, l, kw);
}

static bool flatten_light(vecbuf *out, const scene_light *l)
{
	if (!vecbuf_push(out, l))
		return false;
	scene_light *pushed = &VECBUF_AT(out, scene_light, out->len - 1);
	pushed->looks_lights = NULL, pushed->n_looks_lights = 0;
	for (uint32_t i = 0; i < l->n_looks_lights; i++)
		if (!flatten_light(out, &l->looks_lights[i]))
			return false;
	return true;
}

bool lang_lights_flatten(parser *p)
{
	vecbuf *lights = &p->sc->lights;
	bool any = false;
	for (size_t i = 0; i < lights->len; i++)
		any |= VECBUF_AT(lights, scene_light, i).n_looks_lights > 0;
	if (!any)
		return true;
	vecbuf flat;
	vecbuf_init(&flat, sizeof(scene_light));
	for (size_t i = 0; i < lights->len; i++)
		if (!flatten_light(&flat, &VECBUF_AT(lights, scene_light, i))) {
			vecbuf_free(&flat);
			return lang_error(p, diag_noloc(), "out of memory");
		}
	vecbuf_free(lights);
	*lights = flat;
	return true;
}

static bool light_source(parser *p)
{
	lang_token kw = *lang_advance(p);
	scene_light l;
	TRY(light_block(p, &l, kw.loc));
	return add_light(p, &l, kw.loc);
}

/* background = "background" "{" colour "}" */
static bool background(parser *p)
{
	lang_token kw = *lang_advance(p);
	diag_loc open;
	TRY(open_block(p, "background", &open));
	vec3 c;
	TRY(physical_color(p, "as the background colour", "background colour", SCENE_COLOR_RADIANCE, &c));
	if (!p->sky_colour) { /* as POV-Ray: a sky_sphere hides the background */
		p->sc->background = c;
		p->sc->has_background = true;
		p->sc->background_loc = kw.loc;
		p->sc->background_circe = false;
	}
	return lang_expect_close(p, open, "background");
}

/* sky_sphere { pigment { C } }: a sky of one colour is circe's background (a constant
 * environment light); a patterned sky (a pattern, an image_map, several layers) is baked by the
 * build into a lat-long image (build_pattern.c), each pigment evaluated at the ray's direction as
 * POV-Ray's ComputeSky does (an image_map's map_type 1 is then POV-Ray's spherical sky image). */
static bool sky_pigments(parser *p, diag_loc kw, scene_material *const *pg, int n, const xform *moved, bool was_moved)
{
	scene_sky_sphere *s = &p->sc->sky_sphere;
	bool patterned = n > 1 || pg[0]->pigment;
	if (!patterned) {
		vec3 c = v3_scale(pg[0]->color, (float)s->intensity);
		if (!v3_is_finite(c))
			return lang_error(p, kw, "sky_sphere intensity %g makes its colour overflow a float", s->intensity);
		p->sc->background = c;
		p->sc->has_background = true;
		p->sc->background_loc = kw;
		p->sc->background_circe = s->has_intensity;
		p->sky_colour = true;
		return true;
	}
	for (int i = 0; i < n; i++) {
		const scene_pigment *t = lang_pigment_tree(p, pg[i]);
		TRY(t);
		if (was_moved)
			TRY(t = lang_pigment_moved(p, t, moved, kw));
		s->pigments[i] = t;
	}
	s->n_pigments = n;
	p->sc->has_sky_sphere = true;
	return true;
}

/* A sky_sphere as read (a statement's, or a #declare'd one that a later sky_sphere starts from). */
struct lang_sky {
	scene_sky_sphere s;
	scene_material *pg[SCENE_SKY_MAX_PIGMENTS];
	int n;
	xform moved;
	diag_loc moved_at;
};

/* The end of a sky_sphere: one image, or its pigments. */
static bool sky_close(parser *p, diag_loc kw, const struct lang_sky *k)
{
	scene_sky_sphere *s = &p->sc->sky_sphere;
	*s = k->s;
	if (k->n && s->image)
		return lang_error(p, k->pg[0]->loc, "sky_sphere has an 'image' and a pigment: give one");
	if (k->moved_at.line && !k->n)
		return lang_error(p, k->moved_at, "a sky_sphere image turns by 'rotate' only: circe maps it lat-long");
	if (k->n)
		return sky_pigments(p, kw, k->pg, k->n, &k->moved, k->moved_at.line != 0);
	if (!s->image)
		return lang_error(p, kw, "sky_sphere needs an 'image' or a pigment");
	p->sc->has_sky_sphere = true;
	return true;
}

/* One item of a sky_sphere into k; false after reporting. */
static bool sky_item(parser *p, diag_loc open, struct lang_sky *k)
{
	lang_token t = *lang_peek(p);
	double x;
	switch (t.kind) {
	case LTK_KW_PIGMENT:
		if (k->n == SCENE_SKY_MAX_PIGMENTS)
			return lang_error(p, t.loc, "too many pigments in sky_sphere (limit is %d)", SCENE_SKY_MAX_PIGMENTS);
		TRY(k->pg[k->n] = new_part(p, t.loc));
		return pigment(p, k->pg[k->n++], SCENE_COLOR_RADIANCE);
	case LTK_KW_IMAGE:
		lang_advance(p);
		return asset_path(p, "after 'image'", SCENE_ASSET_IMAGE, &k->s.image);
	case LTK_KW_INTENSITY:
		lang_advance(p);
		TRY(lang_float(p, "after 'intensity'", &x));
		if (x < 0)
			return lang_error(p, t.loc, "sky_sphere intensity must be >= 0, found %g", x);
		k->s.intensity = x;
		k->s.has_intensity = true;
		return true;
	case LTK_KW_ROTATE:
		lang_advance(p);
		return lang_vec3(p, "after 'rotate'", &k->s.rotate_deg);
	default: {
		bool matched;
		TRY(transform_item(p, &k->moved, &matched));
		if (!matched)
			return bad_item(p, open, "sky_sphere", "image, pigment, intensity or rotate");
		if (!k->moved_at.line)
			k->moved_at = t.loc;
		return true;
	}
	}
}

/* sky_sphere = "sky_sphere" "{" [ identifier ] ( "image" string | pigment | "intensity" float
 *              | "rotate" vector | transform_item )* "}"
 * (one image, or pigments: one colour is the background; patterns and layers, bottom first, a
 * baked sky; translate, scale and the like move the pigments, rotate turns the whole sky; a
 * declared sky_sphere's items come first) */
static bool sky_block(parser *p, diag_loc *kw, struct lang_sky *k)
{
	*kw = lang_advance(p)->loc;
	diag_loc open;
	TRY(open_block(p, "sky_sphere", &open));
	*k = (struct lang_sky){.s = {.loc = *kw, .intensity = 1}, .moved = xform_identity()};
	if (lang_peek(p)->kind == LTK_IDENT) {
		const value *v;
		TRY(v = declared(p, VAL_SKY, "a sky_sphere"));
		*k = *v->sky;
		k->s.loc = *kw;
	}
	while (!lang_accept(p, LTK_RBRACE))
		TRY(sky_item(p, open, k));
	return true;
}

static bool sky_sphere(parser *p)
{
	struct lang_sky k;
	diag_loc kw;
	TRY(sky_block(p, &kw, &k));
	return sky_close(p, kw, &k);
}

/* #declare S = sky_sphere { ... }: the items, kept for a sky_sphere { S } to start from. */
static bool declare_sky(parser *p, value *out)
{
	struct lang_sky *k = arena_zalloc(&p->sc->arena, 1, sizeof *k);
	if (!k)
		return lang_error(p, lang_peek(p)->loc, "out of memory");
	diag_loc kw;
	TRY(sky_block(p, &kw, k));
	out->kind = VAL_SKY, out->sky = k;
	return true;
}

/* default = "#default" "{" { texture | pigment | finish | normal } "}"
 * As POV-Ray 3.7: each item changes the default texture, which every texture made after it
 * starts from (a texture { finish {...} } takes the default's pigment and normal), and which an object
 * placed after it without a texture receives (lang_statement). Each #default makes a new record,
 * so the textures that took an earlier default keep it. */
bool lang_default(parser *p)
{
	diag_loc open;
	TRY(open_block(p, "#default", &open));
	for (;;) {
		lang_token t = *lang_peek(p);
		scene_material *d;
		const scene_material *tex;
		switch (t.kind) {
		case LTK_RBRACE:
			lang_advance(p);
			return true;
		case LTK_KW_TEXTURE:
			TRY(texture(p, &tex, NULL));
			if (tex->kind != MAT_TEXTURE)
				return lang_error(p, t.loc, "#default needs a texture, but this one is a %s material",
						  scene_material_kind_name(tex->kind));
			p->default_tex = tex;
			break;
		case LTK_KW_PIGMENT:
		case LTK_KW_FINISH:
			TRY(d = new_texture(p, t.loc));
			TRY(t.kind == LTK_KW_PIGMENT ? pigment(p, d, SCENE_COLOR_REFLECTANCE) : finish(p, d));
			p->default_tex = d;
			break;
		default:
			if (lang_normal_starts(p)) {
				TRY(d = new_texture(p, t.loc));
				TRY(lang_default_normal(p, d));
				p->default_tex = d;
				break;
			}
			return bad_item(p, open, "#default", "texture, pigment, finish or normal");
		}
	}
}

/* media = "media" "{" ... "}" at the top level: POV-Ray's atmospheric media, which fill the
 * space outside every object (and inside hollow ones); several add up, as an interior's. */
static bool atmosphere(parser *p)
{
	scene_material *m = (scene_material *)p->sc->atmosphere; /* the parser's own record */
	if (!m && !(m = new_part(p, lang_peek(p)->loc)))
		return false;
	p->sc->atmosphere = m;
	return interior_media(p, m);
}

/* Objects placed at the top level without a texture take the #default one (POV-Ray 3.7 gives
 * it when the object is placed, so a declared object placed after a #default takes it). */
static void give_default(parser *p, size_t start)
{
	if (!p->default_tex)
		return;
	for (size_t i = start; i < p->sc->objects.len; i++) {
		scene_object *o = &VECBUF_AT(&p->sc->objects, scene_object, i);
		if (!o->material)
			o->material = p->default_tex;
	}
}

bool lang_statement(parser *p)
{
	lang_token *t = lang_peek(p);
	if (t->kind == LTK_UNSUPPORTED && t->len == 3 && !memcmp(t->text, "fog", 3))
		return lang_fog(p);
	if (lang_word_is(t, "rainbow"))
		return lang_rainbow(p);
	if (lang_word_is(t, "media"))
		return atmosphere(p);
	switch (t->kind) {
	case LTK_KW_GLOBAL_SETTINGS: return global_settings(p);
	case LTK_KW_CAMERA: return camera(p);
	case LTK_KW_LIGHT_SOURCE: return light_source(p);
	case LTK_KW_BACKGROUND: return background(p);
	case LTK_KW_SKY_SPHERE: return sky_sphere(p);
	case LTK_KW_DEFAULT: /* POV-Ray 3.7 still reads the old `default {...}` as #default */
		lang_advance(p);
		return lang_default(p);
	case LTK_KW_TEXTURE: /* `#declare T = texture {...} texture {...}` (stones2.inc) */
		return lang_error(p, t->loc, "a layered texture (a texture after a texture) is not supported by circe");
	case LTK_IDENT: {
		const symbol *s = lang_lookup(p, t->text, t->len);
		const char *kw = !s ? NULL : s->val.kind == VAL_OBJECT ? "object" : s->val.kind == VAL_LIGHT ? "light_source"
					 : s->val.kind == VAL_CAMERA ? "camera" : NULL;
		if (kw)
			return lang_error(p, t->loc, "'%.*s' is a declared %s: place it with %s { %.*s }", (int)t->len,
					  t->text, kw, kw, (int)t->len, t->text);
		break;
	}
	case LTK_KW_OBJECT: { /* object { Light ... }: a declared light placed, as POV-Ray's Parse_Object_Id takes it */
		lang_token kw = *lang_advance(p);
		diag_loc open;
		TRY(open_block(p, "object", &open));
		size_t start = p->sc->objects.len;
		if (names(p, VAL_LIGHT)) {
			scene_light l;
			TRY(light_body(p, &l, kw.loc, open));
			return add_light(p, &l, kw.loc);
		}
		TRY(lang_enter(p, kw.loc));
		bool saved = p->lights_in_csg;
		p->lights_in_csg = true; /* placed in the scene: its CSG's lights join the scene's */
		bool ok = instance(p, &p->sc->objects, kw.loc, open);
		p->lights_in_csg = saved;
		lang_leave(p);
		TRY(ok);
		give_default(p, start);
		return true;
	}
	default:
		break;
	}
	bool matched;
	size_t start = p->sc->objects.len;
	bool saved = p->lights_in_csg;
	p->lights_in_csg = true; /* placed in the scene: its CSG's lights join the scene's */
	bool ok = object_item(p, &p->sc->objects, &matched);
	p->lights_in_csg = saved;
	TRY(ok);
	if (!matched)
		return lang_error_found(p, "expected a statement (camera, light_source, background, sky_sphere, "
					   "global_settings or an object)");
	give_default(p, start);
	return true;
}
