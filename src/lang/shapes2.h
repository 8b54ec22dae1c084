/* shapes2.h - POV-Ray's lathe, sor, prism, sphere_sweep, blob and text in the language
 * (shapes2.c), for stmt.c's object items. Not public. */
#ifndef CIRCE_LANG_SHAPES2_H
#define CIRCE_LANG_SHAPES2_H

#include "lang/parser.h"

/* stmt.c's transform_item: one transform at the lookahead composed after *t (*matched false when
 * the lookahead is none). */
typedef bool (*lang_xform_item_fn)(parser *p, xform *t, bool *matched);

/* stmt.c: a blob component's modifiers after its numbers, up to its '}' (consumed; open: its '{'):
 * transforms composed into *t (*moved: any), and a texture, pigment, finish or normal of its own
 * (*mat: the material they make, NULL without). */
bool lang_component_mods(parser *p, xform *t, bool *moved, const scene_material **mat, diag_loc open);

/* The shape a word begins (geom/shape.h's shape_kind), or -1. */
int lang_pov_shape_kind(const lang_token *t);
/* The body of shape `kind` after its '{', up to its modifiers: a new geometry record, or NULL
 * after reporting. */
scene_geom *lang_pov_shape(parser *p, int kind, diag_loc kw, lang_xform_item_fn xf_item);

#endif
