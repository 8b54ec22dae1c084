/* objmods.c - POV-Ray 3.7's object modifiers that change nothing circe renders yet (the
 * CASEs of Parse_Object_Mods in source/backend/parser/parse.cpp, 3.7-stable): each is read with
 * POV-Ray's syntax, recorded in the IR where a renderer could honour it later, and warned about
 * once a parse where the image differs from POV-Ray's. The words are POV-Ray reserved words that
 * are not circe keywords (LTK_UNSUPPORTED), matched by spelling as global_settings' ignored
 * items are, so this file needs no change to the keyword table. */
#include "lang/parser.h"

#include <string.h>

typedef enum { FLAG_BOOL, FLAG_SILENT_BOOL, FLAG_BLOCK } flag_arg;

static const struct object_flag {
	const char *name;
	flag_arg arg;
	uint8_t bit; /* SCENE_OBJ_*, 0 for none recorded */
	const char *why; /* the warning's reason; NULL: no warning (nothing circe renders changes) */
} object_flags[] = {
	{"hollow", FLAG_BOOL, SCENE_OBJ_HOLLOW, NULL}, /* only media sees it; circe has none */
	{"no_image", FLAG_BOOL, SCENE_OBJ_NO_IMAGE, "circe still shows the object to camera rays"},
	{"no_reflection", FLAG_BOOL, SCENE_OBJ_NO_REFLECTION, "circe still shows the object in reflections"},
	{"no_radiosity", FLAG_BOOL, SCENE_OBJ_NO_RADIOSITY,
	 "circe's global illumination is its path tracing, which still sees the object"},
	{"double_illuminate", FLAG_BOOL, SCENE_OBJ_DOUBLE_ILLUMINATE,
	 "circe lights a surface from the side the light is on"},
	{"split_union", FLAG_SILENT_BOOL, 0, NULL}, /* circe flattens a union into its members */
	{"hierarchy", FLAG_SILENT_BOOL, 0, NULL}, /* circe builds its own bounding hierarchy */
	{"photons", FLAG_BLOCK, 0, "circe computes caustics by its own path tracing"},
	{"radiosity", FLAG_BLOCK, 0, "circe computes global illumination on its own"},
};

enum { N_FLAGS = sizeof object_flags / sizeof object_flags[0] };

static const struct object_flag *flag_of(const lang_token *t)
{
	if (t->kind != LTK_UNSUPPORTED)
		return NULL;
	for (size_t i = 0; i < N_FLAGS; i++)
		if (lang_token_is(t, object_flags[i].name))
			return &object_flags[i];
	return NULL;
}

/* Whether the lookahead begins the optional float of a flag (POV-Ray's Allow_Float): a number, a
 * sign, '(', '!', a boolean word or a declared float. */
bool lang_float_follows(parser *p)
{
	const lang_token *t = lang_peek(p);
	switch (t->kind) {
	case LTK_NUMBER:
	case LTK_LPAREN:
	case LTK_MINUS:
	case LTK_PLUS:
	case LTK_BANG:
	case LTK_KW_TRUE:
	case LTK_KW_FALSE:
	case LTK_KW_ON:
	case LTK_KW_OFF:
	case LTK_KW_YES:
	case LTK_KW_NO: return true;
	case LTK_IDENT: {
		const symbol *s = lang_lookup(p, t->text, t->len);
		return s && s->val.kind == VAL_FLOAT;
	}
	default: return false;
	}
}

/* A colour directly in an object, POV-Ray's "quick colour": povray 3.7 warns "Quick color
 * belongs in texture. Color ignored." and so does circe. */
static bool quick_colour(parser *p)
{
	diag_loc at = lang_peek(p)->loc;
	value v;
	TRY(lang_expr(p, &v));
	diag_warning(p->d, at, "a colour directly in an object is ignored, as POV-Ray ignores it (it belongs in a "
			       "texture's pigment)");
	return true;
}

bool lang_object_flag(parser *p, lang_objflags *f, bool *matched)
{
	lang_token t = *lang_peek(p);
	*matched = true;
	if (lang_colour_word(t.kind))
		return quick_colour(p);
	const struct object_flag *of = flag_of(&t);
	if (!of) {
		*matched = false;
		return true;
	}
	lang_advance(p);
	if (of->arg == FLAG_BLOCK) {
		TRY(lang_skip_block(p, of->name));
	} else {
		double x = 1;
		char ctx[64];
		snprintf(ctx, sizeof ctx, "after '%s'", of->name);
		if (lang_float_follows(p))
			TRY(lang_float(p, ctx, &x));
		f->said |= of->bit;
		f->on = (uint8_t)(x > 0 ? f->on | of->bit : f->on & ~of->bit);
	}
	unsigned once = 1u << (of - object_flags);
	if (of->why && !(p->warned_objflags & once)) {
		p->warned_objflags |= once;
		diag_warning(p->d, t.loc, "'%s' is accepted and ignored: %s (said once)", of->name, of->why);
	}
	return true;
}

/* As POV-Ray gives a CSG's flags to its members (Set_CSG_Children_Flag, Set_CSG_Tree_Flag and
 * the promotion of Parse_CSG): hollow to members that do not say their own, no_image,
 * no_reflection and no_radiosity when on, double_illuminate to every member. An object item's
 * own flags go through here too: its fresh object says none. */
void lang_apply_object_flags(scene_object *o, const lang_objflags *f)
{
	if ((f->said & SCENE_OBJ_HOLLOW) && !(o->pov_flags & SCENE_OBJ_HOLLOW_SET))
		o->pov_flags = (uint8_t)((o->pov_flags & ~SCENE_OBJ_HOLLOW) | (f->on & SCENE_OBJ_HOLLOW) | SCENE_OBJ_HOLLOW_SET);
	o->pov_flags |= f->said & f->on & (SCENE_OBJ_NO_IMAGE | SCENE_OBJ_NO_REFLECTION | SCENE_OBJ_NO_RADIOSITY);
	if (f->said & SCENE_OBJ_DOUBLE_ILLUMINATE)
		o->pov_flags = (uint8_t)((o->pov_flags & ~SCENE_OBJ_DOUBLE_ILLUMINATE) | (f->on & SCENE_OBJ_DOUBLE_ILLUMINATE));
}
