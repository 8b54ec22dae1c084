/* parser.h - internals shared by the two halves of the parser: the token stream with directives,
 * includes and expressions (parser.c), and the statements that build the scene IR (stmt.c).
 * Not a public interface: the renderer uses lang.h. */
#ifndef CIRCE_LANG_PARSER_H
#define CIRCE_LANG_PARSER_H

#include "base/mem.h"
#include "lang/lang.h"
#include "lang/lex.h"
#include "scene/scene.h"
#include "scene/pigment.h"

#include <stdbool.h>
#include <string.h>

/* Returns false from the calling parse function when x is false: every parse function reports its
 * error where it finds it and returns false, so its callers only pass the failure on. */
#define TRY(x)                                                                                      \
	do {                                                                                        \
		if (!(x))                                                                           \
			return false;                                                               \
	} while (0)

/* Whether the token is spelled w (any kind): how the words of POV-Ray that are no keywords of
 * circe's, which lex as LTK_UNSUPPORTED or identifiers, are recognised. */
static inline bool lang_token_is(const lang_token *t, const char *w)
{
	size_t n = strlen(w);
	return t->len == n && !memcmp(t->text, w, n);
}

/* Whether t is the word w, as a keyword of circe's or a POV-Ray word circe does not reserve
 * (LTK_UNSUPPORTED): a test that stays right when a word becomes a keyword. The finish, pigment
 * and shape bodies read POV-Ray's words so. */
static inline bool lang_word_is(const lang_token *t, const char *w)
{
	bool wordlike = t->kind == LTK_UNSUPPORTED || (t->kind >= LANG_FIRST_KEYWORD && t->kind < LANG_FIRST_DIRECTIVE);
	return wordlike && lang_token_is(t, w);
}

typedef enum value_kind {
	VAL_FLOAT, VAL_VECTOR, VAL_COLOR, VAL_STRING, VAL_MATERIAL, VAL_OBJECT, VAL_MACRO,
	/* expressions (expr.c): */
	VAL_ARRAY, /* arr; POV-Ray's array[N]... */
	/* declared scene blocks (stmt.c): a pigment, finish or interior is a texture record of which
	 * only its part is read (in `mat`); a camera, light or transform is its IR record */
	VAL_PIGMENT, VAL_FINISH, VAL_INTERIOR, VAL_CAMERA, VAL_LIGHT, VAL_TRANSFORM,
	VAL_COLOR_MAP, /* a color_map or pigment_map (lang/pigment.c): `mat`'s pigment holds its entries */
	VAL_NORMAL,    /* a normal { } (lang/pigment.c): `mat`'s normal */
	VAL_MEDIA,     /* a media { } (stmt.c): `mat`'s one media */
	VAL_SKY,       /* a sky_sphere { } as read (stmt.c's lang_sky) */
	VAL_FILE, /* a data file of #fopen (datafile.c) */
	VAL_FUNCTION, VAL_SPLINE /* func.c */
} value_kind;

/* A colour is POV-Ray's 5-vector: red, green, blue, filter, transmit (VAL_COLOR has n == 5). */
enum { LANG_COLOR_TERMS = 5 };

/* A list of placed objects made by one object item (a union gives several). */
typedef struct objlist {
	scene_object *items;
	size_t n;
	/* A declared object's light_sources (POV-Ray's lights in a declared union, CSG or
	 * light_group), in the declared object's space, and the light groups it made, taken out of
	 * the scene's: its lights and objects name them by the ids they had, first_group on (1-based
	 * as scene_light.group). Each copy placed in the scene gets moved copies of the lights and a
	 * new group for each of its groups (stmt.c's declared_object). */
	const scene_light *lights;
	size_t n_lights;
	const scene_light_group *groups;
	uint32_t first_group, n_groups;
} objlist;

typedef struct value {
	value_kind kind;
	int n; /* components of a vector or colour */
	double v[LANG_MAX_VECTOR];
	const char *str; /* VAL_STRING, in the scene arena */
	const scene_material *mat;
	const objlist *obj;
	const struct lang_macro *mac; /* VAL_MACRO */
	struct lang_array *arr; /* VAL_ARRAY: shared by reference, as a macro's parameter is */
	/* declared scene blocks (stmt.c) */
	const scene_camera *cam; /* VAL_CAMERA */
	const scene_light *light; /* VAL_LIGHT */
	const xform *xf; /* VAL_TRANSFORM */
	const struct lang_sky *sky; /* VAL_SKY */
	int file; /* VAL_FILE: its index in the parser's datafiles */
	const struct lang_function *fn; /* VAL_FUNCTION */
	const struct lang_spline *spl; /* VAL_SPLINE */
} value;

/* An array: its dimensions and its elements in row-major order, each unset until assigned (kind
 * `set` false). POV-Ray 3.7's arrays: at most LANG_MAX_ARRAY_DIMS dimensions; `mixed` lets the
 * elements be of different kinds (otherwise all take the kind of the first one assigned). */
enum { LANG_MAX_ARRAY_DIMS = 5 }; /* POV-Ray 3.7's limit (EXPRESS terms of a subscript) */
typedef struct lang_array {
	int dims;
	long size[LANG_MAX_ARRAY_DIMS];
	size_t count; /* the product of the sizes */
	bool mixed;
	int kind; /* not mixed: the value_kind of its elements once one is set; -1 before */
	value *elems;
	bool *set;
} lang_array;

/* A #macro: its parameters and where its body lies in its source (read again at each call, as a
 * #while body is; their tokens are lexed once, parser.c's token memo). */
typedef struct lang_macro {
	const char *name;
	diag_loc loc; /* its #macro */
	int n_params;
	const char *params[LANG_MAX_MACRO_PARAMS];
	bool optional[LANG_MAX_MACRO_PARAMS];
	lang_lexer body; /* just after the parameter list's ')' */
	const char *body_end; /* the start of the #end that closes it */
	const char *path; /* the file that defines it (the folder of includes in its body) */
} lang_macro;

typedef struct include_frame {
	lang_lexer lx;
	const char *path; /* as resolved; the folder of later includes */
	diag_loc included_at; /* the #include directive (no source for the main file) */
	int cond_base; /* the conditional stack depth when the file was entered */
	const char *released; /* mapped sources: text before this was handed back to the kernel */
	const lang_macro *macro; /* a macro call's frame (included_at: the call), or NULL */
	bool saved_directive_expr; /* macro frames: the caller's directive_expr, restored at the end */
	int saved_directive_expr_at;
} include_frame;

typedef enum cond_kind { COND_IF, COND_ELSE, COND_WHILE, COND_FOR, COND_SWITCH } cond_kind;

typedef struct cond {
	cond_kind kind;
	diag_loc loc;
	const char *what; /* its directive for messages: "#if", "#ifdef", "#ifndef", "#while" */
	int file; /* index into files */
	diag_loc else_loc; /* COND_ELSE: its #else */
	lang_lexer restart; /* COND_WHILE: just after the `#while` word; COND_FOR: after its ')' */
	long iterations; /* COND_WHILE, COND_FOR: begun so far */
	const char *var; /* COND_FOR: the loop variable, its end and step */
	double end, step;
	double value; /* COND_SWITCH (running a case that matched, or its #else): the switch's value */
} cond;

/* `#declare deprecated [once] ["message"] Name = ...`: a warning at each use of Name (the first
 * only, with once), the message or POV-Ray's own. */
typedef struct deprecation {
	bool on, once, warned;
	const char *msg; /* NULL: "identifier 'Name' was declared deprecated" */
} deprecation;

typedef struct symbol {
	const char *name;
	int depth; /* 0 global; k the k-th include level for #local */
	diag_loc loc;
	value val;
	bool param; /* a parameter of a macro call */
	long ref; /* a parameter passed by reference: 0 none; k > 0 globals[k-1]; k < 0 locals[-k-1] */
	deprecation dep;
} symbol;

typedef struct parser {
	diag *d;
	scene *sc;
	lang_options opt;
	include_frame files[LANG_MAX_INCLUDE_DEPTH + LANG_MAX_MACRO_DEPTH + 1];
	int n_files;
	cond conds[LANG_MAX_DEPTH];
	int n_conds;
	lang_token tok; /* the lookahead, when have_tok */
	bool have_tok;
	lang_token prev; /* the last token consumed */
	lang_token eof; /* returned after the last file or an error */
	bool failed; /* the first error was reported: report no more */
	bool no_gt; /* inside < >: a '>' closes the vector */
	bool directive_expr; /* parsing a directive's own expression: directives there are errors */
	int directive_expr_at; /* the frame (n_files) of the directive that set directive_expr: a
				  macro body read inside its expression (a deeper frame) runs directives */
	int dir_frame; /* n_files where the running directive was read */
	int depth; /* recursion guard for expressions and nested blocks */
	long total_iterations;
	struct lex_memo *memo; /* parser.c: the tokens of loop and macro bodies, lexed once */
	size_t memo_cap, memo_n;
	int n_macro_calls; /* macro frames in files */
	const char *skip_stop_at; /* skip_block: where the directive that ended it begins (before blanks) */
	bool no_expand; /* reading a directive's name: a macro's name is not a call */
	double version; /* `version`: 3.7 until a #version sets it */
	/* statements' state (stmt.c) */
	const scene_material *default_tex; /* #default's texture; NULL until a #default */
	bool sky_colour; /* a sky_sphere's colour pigment set the background: a background {} leaves it */
	/* stmt.c: a light_source in a CSG block goes into the scene's lights, moved by the block's
	 * transforms, only while an object statement places its objects in the scene (not in a
	 * #declare, a clipped_by or a pattern's object) */
	bool lights_in_csg;
	/* Where objects are read unplaced, without lights_in_csg: "clipped_by", "bounded_by",
	 * "looks_like", ... (stmt.c's object_item_unplaced); NULL when placed or declared. */
	const char *unplaced;
	/* shapes2.c's blob just parsed: the materials of its textured components, part k's at
	 * [k - 1] (in the arena), for stmt.c's pov_shape to give its object; 0: none */
	const scene_material **blob_parts;
	uint32_t n_blob_parts;
	unsigned finish_warned; /* finish.c: the ignored finish words already warned about, one bit each
				 * (and stmt.c's LANG_WARNED_INTERIOR_TEXTURE) */
	deprecation pending_dep; /* the running #declare's, given to the symbol it defines */
	vecbuf datafiles; /* lang_datafile (datafile.c): every data file opened, open or not */
	lang_token held; /* with has_held: the token after a #declare without ';', read again next */
	bool has_held;
	vecbuf globals, locals; /* symbol */
	/* expressions (expr.c): */
	vecbuf rand_streams; /* rng, one per seed() call: rand(S) draws from stream S */
	unsigned warned_objflags; /* objmods.c: the object flags warned about (once a parse each) */
} parser;

/* ---- token stream (parser.c) ---- */
lang_token *lang_peek(parser *p);
lang_token *lang_advance(parser *p);
bool lang_accept(parser *p, lang_tok k);
/* Expects k; otherwise "expected K CONTEXT, found X". context: e.g. "after the sphere centre".
 * A comma is optional (true without reading anything), as POV-Ray 3.7's Parse_Comma makes every
 * comma of its grammar but those between a built-in function's arguments. */
bool lang_expect(parser *p, lang_tok k, const char *context);
/* Expects '}' closing what opened at open; names the opening on failure. */
bool lang_expect_close(parser *p, diag_loc open, const char *what);
/* Reports at the lookahead: "expected WHAT, found X" (or "'X' is not supported by circe"). */
bool lang_error_found(parser *p, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/* Reports at loc; false. Nothing is printed once an error was reported. */
bool lang_error(parser *p, diag_loc loc, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
/* A description of a token for messages: "'1'", "'sphere'", "end of file", "identifier 'Foo'". */
const char *lang_describe(const lang_token *t, char *buf, size_t size);
bool lang_enter(parser *p, diag_loc loc); /* recursion guard */
/* The value of a string token, escapes resolved, in the scene arena. */
bool lang_decode_string(parser *p, const lang_token *s, value *out);
static inline void lang_leave(parser *p) { p->depth--; }
/* The kind of the token after the lookahead (the next one when none is held), read without running
 * directives: for constructs that end without a terminator (#debug's operand, an array's size). */
lang_tok lang_raw_next(parser *p);
/* After a block value of #declare: consumes an optional ';' without running directives. */
void lang_skip_optional_semi(parser *p);

/* ---- expressions (expr.c) ---- */
bool lang_expr(parser *p, value *out);
/* POV-Ray's truth of a float: |x| > 1e-10 (its EPSILON), for conditions and logic. */
bool lang_truth(double x);
/* One primary with its members and indices but no operator after it: the operand of #debug, which
 * has no terminator to read an operator up to. */
bool lang_primary(parser *p, value *out);
/* True for a word that begins a colour: color colour rgb rgbf ... srgbft red green blue filter
 * transmit. */
bool lang_colour_word(lang_tok k);
/* array = "array" [ "mixed" ] "[" int "]" { "[" int "]" } [ "{" items "}" ]; the lookahead is
 * "array". */
bool lang_array_value(parser *p, value *out);
/* "[" int "]" ... after an array's name: the element's index into (*a)->elems, bounds checked; an
 * element that is an array indexed on makes *a that array. */
bool lang_array_index(parser *p, lang_array **a, const char *name, size_t *index);
/* `Name [ index ]` as the target of #declare or #read: the array the name holds (declared) and
 * the element's index. */
bool lang_element_target(parser *p, const lang_token *name, lang_array **arr, size_t *index);
/* A copy of an array (for #declare B = A: POV-Ray copies; a macro's argument is by reference). */
bool lang_array_copy(parser *p, diag_loc loc, value *v);
/* Stores v in element i of a (a non-mixed array holds one kind). */
bool lang_array_store(parser *p, diag_loc loc, lang_array *a, size_t i, const value *v);
/* A float as POV-Ray's Parse_Float reads it: an additive expression (a comparison, '&', '|' or '?'
 * only inside parentheses). */
bool lang_float(parser *p, const char *what, double *out);
/* A value as POV-Ray's Parse_Vector or Parse_UV_Vect reads one: an additive expression, so that a
 * '<' after it begins the next item (mesh2's uv_vectors written without commas). */
bool lang_additive(parser *p, value *out);
/* A float from a whole expression, comparisons and all (a directive's parenthesised condition). */
bool lang_float_expr(parser *p, const char *what, double *out);
bool lang_int(parser *p, const char *what, long lo, long hi, long *out);
bool lang_vec3(parser *p, const char *what, dvec3 *out); /* a float is promoted */
/* A colour's red, green and blue (a float is promoted); a filter or transmit other than 0 is
 * warned about and dropped (circe's materials have none yet). */
bool lang_color(parser *p, const char *what, vec3 *out);
/* lang_color keeping the filter and transmit (ft[0], ft[1]) as written. */
bool lang_color_ft(parser *p, const char *what, vec3 *out, double ft[2]);
/* A colour's five terms (red, green, blue, filter, transmit) as written: nothing dropped. */
bool lang_color5(parser *p, const char *what, double out[LANG_COLOR_TERMS]);
bool lang_string(parser *p, const char *what, const char **out);
/* A vector literal of 1..LANG_MAX_VECTOR integer components (face index lists). */
bool lang_index_tuple(parser *p, const char *what, uint32_t *idx, int *n, diag_loc *loc);
const symbol *lang_lookup(parser *p, const char *name, size_t len);
/* A member (.x .red ...) of v, after the '.' lookahead. */
bool lang_member(parser *p, value *v);
/* "'FNAME' takes N arguments, found M" at at (lo..hi required; hi < 0: no limit). */
bool lang_wrong_count(parser *p, diag_loc at, const char *fname, int lo, int hi, int found);
const char *lang_value_kind_name(const value *v);
/* extent.c: min_extent(object) or max_extent(object), the word at the current token. */
bool lang_extent(parser *p, value *out);
/* extent.c: trace(object, start, direction [, normal]), the word at the current token. */
bool lang_trace(parser *p, value *out);
/* extent.c: inside(object, point), the word at the current token. */
bool lang_inside(parser *p, value *out);

/* Declares name (#declare, or #local with local) as v; false after reporting. */
bool lang_define(parser *p, const lang_token *name, bool local, const value *v);
/* Forgets the innermost declaration of the name (#undef). */
void lang_forget(parser *p, const char *name, size_t len);

/* ---- functions and splines (func.c) ---- */
/* The value of `function ...` or `spline { ... }` (the lookahead); name: the identifier being
 * declared (its use in the body is recursion, refused), or NULL. */
bool lang_func_value(parser *p, const lang_token *name, value *out);
/* A function's parameters and body after its `function` keyword kw, read by the caller (the
 * height field's `function W, H { ... }`). */
bool lang_func_body(parser *p, lang_token kw, value *out);
/* A call NAME "(" args ")" of fv, a VAL_FUNCTION or VAL_SPLINE (the lookahead is '('). */
bool lang_func_call(parser *p, const lang_token *name, const value *fv, value *out);
/* The function pattern's `function { expression }` (the lookahead is `function`): a float
 * function of x, y and z circe can evaluate, as the IR's hook (scene/pigment.h's scene_fn). */
bool lang_func_pattern(parser *p, scene_fn *out);
struct lang_function;
/* Why `failed` (where lang_fn_eval gave up) cannot be evaluated by circe, reported at `at`: an
 * internal(N) or a pattern circe lacks. False. */
bool lang_fn_report(parser *p, diag_loc at, const struct lang_function *failed);

/* ---- data files (datafile.c) ---- */
bool lang_fopen(parser *p, diag_loc at); /* after '#fopen' */
bool lang_fclose(parser *p);
bool lang_read_directive(parser *p, diag_loc at);
bool lang_write_directive(parser *p);
void lang_datafiles_init(parser *p);
void lang_datafiles_close(parser *p); /* the end of the parse: streams closed, the list freed */

/* ---- object flags (objmods.c) ---- */
/* The POV-Ray object flags one object item says: which (said) and their values (on), SCENE_OBJ_*. */
typedef struct lang_objflags {
	uint8_t said, on;
} lang_objflags;
/* object_flag = ( "hollow" | "no_image" | "no_reflection" | "no_radiosity" | "double_illuminate"
 *               | "split_union" | "hierarchy" ) [ float ] | ( "photons" | "radiosity" ) "{" ... "}"
 *             | colour
 * at the lookahead; *matched false (nothing read) for any other token. */
bool lang_object_flag(parser *p, lang_objflags *f, bool *matched);
/* Whether the lookahead begins POV-Ray's optional float of a flag (a number, a sign, '(', '!', a
 * boolean word or a declared float). */
bool lang_float_follows(parser *p);
/* Gives an object the flags an item that made or holds it says, as POV-Ray's CSG does. */
void lang_apply_object_flags(scene_object *o, const lang_objflags *f);

/* ---- statements (stmt.c) ---- */
/* statement = global_settings | camera | light_source | background | sky_sphere | object_item */
bool lang_statement(parser *p);
/* After the last statement: each light's looks_like lights (scene_light.looks_lights) placed in
 * the scene's lights after it, as POV-Ray's Post_Process lists them; false when memory runs out. */
bool lang_lights_flatten(parser *p);
/* The right-hand side of #declare that is a block (object, material, texture); false with
 * *handled false when the lookahead starts none of them. */
bool lang_declare_block(parser *p, value *out, bool *handled);
/* An object (a declared object's name, or an object item) as a list of placed objects; what: the
 * error's context ("in the object pattern"). */
bool lang_object_list(parser *p, const char *what, const objlist **out);
/* "{" ... "}" after `what`, any tokens between, the braces balanced (directives still run). */
bool lang_skip_block(parser *p, const char *what);
/* For shapes.c: a new geometry record (NULL after reporting), and an object of g placed in out with
 * its modifiers up to the closing '}' of the item `what` opened at open. */
scene_geom *lang_new_geom(parser *p, scene_shape_kind kind, diag_loc loc);
/* A string naming a file, resolved against the folder of the text and recorded as an asset. */
bool lang_asset_path(parser *p, const char *what, scene_asset_kind kind, const char **out);
bool lang_place_object(parser *p, vecbuf *out, const scene_geom *g, diag_loc kw, diag_loc open, const char *what);

/* shapes.c: the parser of a POV-Ray shape keyword (cylinder, cone, torus, ...), or NULL; called
 * after the keyword and its '{', it reads up to the item's closing '}'. */
typedef bool (*lang_shape_fn)(parser *p, vecbuf *out, diag_loc kw, diag_loc open);
lang_shape_fn lang_shape_parser(lang_tok k);
/* default = "#default" "{" { texture | pigment | finish } "}"   (after the directive's word) */
bool lang_default(parser *p);

/* ---- finish items and fog (finish.c) ---- */
/* What a finish block remembers until it closes: the albedo forms of its highlights, which
 * POV-Ray applies with the exponents the block ends with. */
/* parser.finish_warned's bit for stmt.c's interior_texture warning (finish.c's use the low ones). */
#define LANG_WARNED_INTERIOR_TEXTURE (1u << 31)
/* ... and for a light_source's ignored photons block. */
#define LANG_WARNED_LIGHT_PHOTONS (1u << 30)

typedef struct lang_finish_state {
	bool phong_albedo, specular_albedo;
} lang_finish_state;
/* One item of a finish block into m (its diffuse, specular, roughness, ior and m->finish);
 * *matched false when the lookahead is no finish item. */
bool lang_finish_item(parser *p, scene_material *m, lang_finish_state *st, bool *matched);
/* At the finish block's '}': POV-Ray's albedo adjustments and fresnel's default minimum. */
void lang_finish_end(scene_material *m, const lang_finish_state *st);
/* fog = "fog" "{" ... "}" (the lookahead spells fog): appended to the scene's fogs. */
bool lang_fog(parser *p);

#endif
