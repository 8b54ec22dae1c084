/* pigment.h - the pigment bodies of POV-Ray beyond one colour (lang/pigment.c): patterns with
 * their colour maps, pigment maps and block lists, image_map, turbulence, waves, warps and
 * transforms, read into a scene_pigment tree (scene/pigment.h). stmt.c's `pigment` hands over
 * to it when the body is one of these. Internal to src/lang. */
#ifndef CIRCE_LANG_PIGMENT_H
#define CIRCE_LANG_PIGMENT_H

#include "lang/parser.h"
#include "scene/pigment.h"

/* True when the lookahead begins a body lang_pigment_rest reads: a pattern's word, image_map,
 * uv_mapping, or, over a declared pigment (has_base), one of a pattern's modifiers. */
bool lang_pigment_starts(parser *p, bool has_base);
/* rainbow { ... }: read, checked as POV-Ray checks it, and ignored with a warning (the lookahead
 * is "rainbow"). */
bool lang_rainbow(parser *p);
/* A data file the scene names (an image, a df3), as POV-Ray's Locate_File finds it: beside the
 * file that names it at `at`, then in each -I folder; the readable path (in the arena), or NULL. */
const char *lang_data_path(parser *p, const char *name, diag_loc at);
/* The same search trying, in each folder, the name with each of the n_ext endings appended (""
 * for the name as written): *out the first readable path, or NULL when none is; false only when
 * memory runs out. */
bool lang_find_data(parser *p, const char *name, const char *const *ext, int n_ext, diag_loc at, const char **out);
/* "quick_color" colour (or quick_colour) when the lookahead is one: POV-Ray's preview colour,
 * read and ignored (circe has no quick preview). *matched says whether it was. */
bool lang_pigment_quick_colour(parser *p, bool *matched);
/* The rest of a pigment's body up to its '}' (consumed), over base (a declared pigment's tree,
 * or NULL); *out receives the new tree (in the scene's arena). open: the pigment's '{'. */
bool lang_pigment_rest(parser *p, const scene_pigment *base, diag_loc open, const scene_pigment **out);
/* A copy of pg with xf after its warps: a transform written after the pigment (in a texture, a
 * material, a declared pigment reused) moves its pattern, as POV-Ray's do. NULL: out of memory,
 * reported at loc. */
const scene_pigment *lang_pigment_moved(parser *p, const scene_pigment *pg, const xform *xf, diag_loc loc);

/* The tree of a pigment's record (a declared pigment, a sky's layer): its pattern, or a plain
 * node of its colour. NULL: out of memory, reported. */
const scene_pigment *lang_pigment_tree(parser *p, const scene_material *m);

/* True when the lookahead is color_map, colour_map or pigment_map (a #declare's value). */
bool lang_pigment_map_starts(parser *p);
/* The map at the lookahead as a VAL_COLOR_MAP value (for #declare). */
bool lang_pigment_map_value(parser *p, value *out);

/* density = "density" "{" [ identifier ] pigment_body "}": a media's density, read as a pigment
 * whose map may be written density_map; a pattern without a map gets POV-Ray's default density
 * map, black at 0 to white at 1. The lookahead is `density`. */
bool lang_density(parser *p, const scene_pigment **out);

/* True when the lookahead is `normal` (a POV-Ray word circe reads here). */
bool lang_normal_starts(parser *p);
/* normal = "normal" "{" [ identifier ] [ pattern [ [","] float ] ] { pattern_modifier
 *          | "bump_size" float | "accuracy" float } "}": m's normal (a copy over a declared one). */
bool lang_normal(parser *p, scene_material *m);
/* #default's normal: as lang_normal, but it may have no pattern (POV-Ray's `#default { normal {
 * bump_size 1.5 } }`: an amount the normals written later start from; it perturbs nothing). */
bool lang_default_normal(parser *p, scene_material *m);
/* A normal { } as a VAL_NORMAL value (for #declare). */
bool lang_normal_value(parser *p, value *out);

/* POV-Ray's patterned texture: `texture { PATTERN [texture { } ...] { pattern_modifier |
 * texture_map { [v texture_body] ... } } }`. tex reads one entry's texture: `texture { ... }`
 * when close is '}', a texture body up to ']' (consumed) when it is ']'. */
typedef bool (*lang_texture_fn)(parser *p, lang_tok close, const scene_material **out);
/* True when the lookahead is a pattern's word (a texture's body is then a patterned texture). */
bool lang_texture_pattern_starts(parser *p);
/* The rest of a patterned texture's body up to close (consumed), open its '{': *pig is the
 * pattern whose entries are the entries' pigments (in the arena), mats[0..*n) the entries'
 * textures in the order written (at least one). */
bool lang_texture_pattern(parser *p, diag_loc open, lang_tok close, lang_texture_fn tex, const scene_pigment **pig,
			  const scene_material *const **mats, uint32_t *n);

/* stmt.c's helpers pigment.c reads with: lang_asset_path (parser.h), and one transform item
 * composed after *t (*matched false when the lookahead is none). */
bool lang_transform_item(parser *p, xform *t, bool *matched);

#endif
