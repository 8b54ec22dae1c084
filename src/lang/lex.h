/* lex.h - the lexer of the scene language: turns one source text into tokens that carry their
 * file:line:col. Keywords come from one table (LANG_KEYWORDS) tied to the token enum; POV-Ray words
 * outside the language come from a second table and lex as LTK_UNSUPPORTED (directives as
 * LTK_UNSUPPORTED_DIRECTIVE), so the parser can say "X is not supported by circe" wherever they
 * appear. Directives (`#declare`, `#  declare`, ...) are single tokens. */
#ifndef CIRCE_LANG_LEX_H
#define CIRCE_LANG_LEX_H

#include "base/diag.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Limits that keep hostile input harmless; each is stated in its error message. */
enum {
	LANG_MAX_IDENT = 255, /* characters in an identifier */
	LANG_MAX_STRING = 4096, /* bytes in a string literal */
};

/* KW(enum suffix, spelling), sorted by spelling: lang_keyword searches it by bisection. */
#define LANG_KEYWORDS(KW) \
	KW(ABS, "abs") KW(ACOS, "acos") KW(ACOSH, "acosh") KW(ANGLE, "angle") KW(ANISOTROPY, "anisotropy") \
	KW(APERTURE, "aperture") KW(ARRAY, "array") KW(ASC, "asc") KW(ASIN, "asin") KW(ASINH, "asinh") \
	KW(ASSUMED_GAMMA, "assumed_gamma") KW(ATAN, "atan") KW(ATAN2, "atan2") KW(ATANH, "atanh") KW(AUTO, "auto") \
	KW(BACKGROUND, "background") KW(BITWISE_AND, "bitwise_and") KW(BITWISE_OR, "bitwise_or") \
	KW(BITWISE_XOR, "bitwise_xor") KW(BLUE, "blue") KW(BLUR_SAMPLES, "blur_samples") \
	KW(BOUNDARY, "boundary") KW(BOUNDED_BY, "bounded_by") KW(BOX, "box") KW(BURLEY, "burley") KW(CAMERA, "camera") \
	KW(CATMULL_CLARK, "catmull_clark") KW(CEIL, "ceil") KW(CHR, "chr") KW(CIRCLE, "circle") \
	KW(CLIPPED_BY, "clipped_by") KW(CLOCK, "clock") KW(CLOCK_ON, "clock_on") KW(COLOR, "color") KW(COLOUR, "colour") \
	KW(CONCAT, "concat") KW(CONE, "cone") KW(CONFIDENCE, "confidence") KW(CORNERS, "corners") \
	KW(COS, "cos") KW(COSH, "cosh") KW(CREASES, "creases") KW(CUBIC, "cubic") \
	KW(CUBIC_SPLINE, "cubic_spline") KW(CYLINDER, "cylinder") KW(DATETIME, "datetime") \
	KW(DEFAULT, "default") KW(DEFINED, "defined") KW(DEGREES, "degrees") KW(DEPRECATED, "deprecated") \
	KW(DIFFERENCE, "difference") KW(DIFFUSE, "diffuse") KW(DIMENSION_SIZE, "dimension_size") KW(DIMENSIONS, "dimensions") \
	KW(DIPOLE, "dipole") KW(DIRECTION, "direction") KW(DISC, "disc") KW(DISK, "disk") KW(DIV, "div") \
	KW(EDGE_AND_CORNER, "edge_and_corner") KW(EDGE_ONLY, "edge_only") KW(EMISSION, "emission") \
	KW(EXP, "exp") KW(EXR, "exr") KW(FACE_INDICES, "face_indices") KW(FACES, "faces") \
	KW(FALLOFF, "falloff") KW(FALSE, "false") KW(FILE, "file") KW(FILE_EXISTS, "file_exists") \
	KW(FILTER, "filter") KW(FINISH, "finish") KW(FISHEYE, "fisheye") KW(FLOOR, "floor") \
	KW(FOCAL_POINT, "focal_point") KW(FULLCIRCLE, "fullcircle") KW(FUNCTION, "function") \
	KW(GAUSSIAN, "gaussian") KW(GLOBAL_SETTINGS, "global_settings") KW(GRAY, "gray") \
	KW(GREEN, "green") KW(GROUP, "group") KW(HEIGHT_FIELD, "height_field") KW(IMAGE, "image") \
	KW(IMAGE_MAP, "image_map") KW(INT, "int") KW(INTENSITY, "intensity") KW(INTERIOR, "interior") \
	KW(INTERNAL, "internal") KW(INTERSECTION, "intersection") KW(INVERSE, "inverse") KW(IOR, "ior") KW(JPEG, "jpeg") KW(LEVEL, "level") \
	KW(LIGHT_SOURCE, "light_source") KW(LINEAR_SPLINE, "linear_spline") KW(LN, "ln") \
	KW(LOCATION, "location") KW(LOG, "log") KW(LOOK_AT, "look_at") KW(LOOP, "loop") \
	KW(MARBLE, "marble") KW(MATERIAL, "material") KW(MATRIX, "matrix") KW(MAX, "max") \
	KW(MAX_EDGE, "max_edge") KW(MAX_TRACE_LEVEL, "max_trace_level") KW(MERGE, "merge") KW(MESH, "mesh") \
	KW(MESH2, "mesh2") KW(METHOD, "method") KW(MIN, "min") KW(MIXED, "mixed") \
	KW(MM_PER_UNIT, "mm_per_unit") KW(MOD, "mod") KW(NATURAL_SPLINE, "natural_spline") KW(NO, "no") \
	KW(NO_SHADOW, "no_shadow") KW(NOISE_THRESHOLD, "noise_threshold") \
	KW(NORMAL_INDICES, "normal_indices") KW(NORMAL_MAP, "normal_map") \
	KW(NORMAL_VECTORS, "normal_vectors") KW(NOW, "now") KW(OBJECT, "object") KW(OFF, "off") \
	KW(ON, "on") KW(ONCE, "once") KW(OPEN, "open") KW(ORTHOGRAPHIC, "orthographic") \
	KW(PANORAMIC, "panoramic") KW(PARALLEL, "parallel") KW(PERSPECTIVE, "perspective") KW(PI, "pi") \
	KW(PIGMENT, "pigment") KW(PLANE, "plane") KW(PNG, "png") KW(POINT_AT, "point_at") KW(POLY, "poly") \
	KW(POLYGON, "polygon") KW(POW, "pow") KW(PRESET, "preset") KW(PROFILE, "profile") \
	KW(QUADRATIC_SPLINE, "quadratic_spline") KW(QUADRIC, "quadric") KW(QUARTIC, "quartic") \
	KW(RADIANS, "radians") KW(RADIUS, "radius") KW(RAND, "rand") KW(RED, "red") KW(RGB, "rgb") \
	KW(RGBF, "rgbf") KW(RGBFT, "rgbft") KW(RGBT, "rgbt") KW(RIGHT, "right") KW(ROTATE, "rotate") \
	KW(ROUGHNESS, "roughness") KW(SCALE, "scale") KW(SCHEME, "scheme") KW(SEED, "seed") \
	KW(SELECT, "select") KW(SIGMA_A, "sigma_a") KW(SIGMA_S, "sigma_s") KW(SIN, "sin") KW(SINH, "sinh") \
	KW(SKIN, "skin") KW(SKY, "sky") KW(SKY_SPHERE, "sky_sphere") KW(SMOOTH, "smooth") \
	KW(SMOOTH_TRIANGLE, "smooth_triangle") KW(SPECULAR, "specular") KW(SPHERE, "sphere") \
	KW(SPHERICAL, "spherical") KW(SPLINE, "spline") KW(SPOTLIGHT, "spotlight") KW(SQRT, "sqrt") \
	KW(SRGB, "srgb") KW(SRGBF, "srgbf") KW(SRGBFT, "srgbft") KW(SRGBT, "srgbt") KW(STR, "str") \
	KW(STRCMP, "strcmp") KW(STRENGTH, "strength") KW(STRLEN, "strlen") KW(STRLWR, "strlwr") \
	KW(STRUPR, "strupr") KW(STURM, "sturm") KW(SUBDIVISION_SURFACE, "subdivision_surface") \
	KW(SUBSTR, "substr") KW(SUM_OF_GAUSSIANS, "sum_of_gaussians") KW(SUPERELLIPSOID, "superellipsoid") \
	KW(T, "t") KW(TAN, "tan") KW(TANH, "tanh") KW(TEXTURE, "texture") KW(TORUS, "torus") \
	KW(TRANSFORM, "transform") KW(TRANSLATE, "translate") KW(TRANSMIT, "transmit") \
	KW(TRIANGLE, "triangle") KW(TRUE, "true") KW(U, "u") KW(ULTRA_WIDE_ANGLE, "ultra_wide_angle") \
	KW(UNION, "union") KW(UP, "up") KW(UV_FACES, "uv_faces") KW(UV_INDICES, "uv_indices") \
	KW(UV_VECTORS, "uv_vectors") KW(V, "v") KW(VAL, "val") KW(VARIANCE, "variance") \
	KW(VAXIS_ROTATE, "vaxis_rotate") KW(VCROSS, "vcross") KW(VDOT, "vdot") KW(VERSION, "version") \
	KW(VERTEX_VECTORS, "vertex_vectors") KW(VLENGTH, "vlength") KW(VNORMALIZE, "vnormalize") \
	KW(VOLUME, "volume") KW(VROTATE, "vrotate") KW(VSTR, "vstr") KW(WATER_LEVEL, "water_level") \
	KW(WAX, "wax") KW(X, "x") KW(Y, "y") KW(YES, "yes") KW(Z, "z")

/* X(enum suffix, spelling without '#'). */
#define LANG_DIRECTIVES(X)                                                                          \
	X(DECLARE, "declare") X(LOCAL, "local") X(INCLUDE, "include") X(IF, "if") X(ELSE, "else") X(ELSEIF, "elseif")    \
	X(END, "end") X(WHILE, "while") X(VERSION, "version") X(IFDEF, "ifdef") X(IFNDEF, "ifndef") \
	X(UNDEF, "undef") X(DEBUG, "debug") X(WARNING, "warning") X(ERROR, "error") X(FOR, "for") X(SWITCH, "switch")     \
	X(CASE, "case") X(RANGE, "range") X(BREAK, "break") X(MACRO, "macro") \
	X(DEFAULT, "default") X(FOPEN, "fopen") X(FCLOSE, "fclose") X(READ, "read") X(WRITE, "write")

typedef enum lang_tok {
	LTK_EOF,
	LTK_NUMBER,
	LTK_STRING,
	LTK_IDENT,
	LTK_UNSUPPORTED, /* a POV-Ray word outside the language */
	LTK_UNSUPPORTED_DIRECTIVE, /* a POV-Ray directive outside the language: text is its name, no '#' */
	LTK_LBRACE, LTK_RBRACE, LTK_LPAREN, LTK_RPAREN, LTK_LT, LTK_GT, LTK_LE, LTK_GE,
	LTK_EQ, LTK_NE, LTK_COMMA, LTK_SEMI, LTK_PLUS, LTK_MINUS, LTK_STAR, LTK_SLASH,
	LTK_BANG, LTK_AMP, LTK_BAR, LTK_QUESTION, LTK_COLON, LTK_DOT, LTK_LBRACKET, LTK_RBRACKET,
#define LANG_KW_ENUM(e, s) LTK_KW_##e,
	LANG_KEYWORDS(LANG_KW_ENUM)
#undef LANG_KW_ENUM
#define LANG_DIR_ENUM(e, s) LTK_DIR_##e,
	LANG_DIRECTIVES(LANG_DIR_ENUM)
#undef LANG_DIR_ENUM
	LTK_COUNT
} lang_tok;

#define LANG_FIRST_KEYWORD LTK_KW_ABS
#define LANG_FIRST_DIRECTIVE LTK_DIR_DECLARE

typedef struct lang_token {
	lang_tok kind;
	diag_loc loc;
	const char *text; /* into the source: the spelling (a string's contents without quotes) */
	uint32_t len;
	double number; /* LTK_NUMBER */
} lang_token;

/* The position of a lexer in its source; copyable, so #while can jump back. */
typedef struct lang_lexer {
	const diag_source *src;
	const char *p, *end;
	uint32_t line;
	const char *line_start;
} lang_lexer;

void lang_lexer_init(lang_lexer *lx, const diag_source *src);
/* Reads the next token. Returns false after reporting a lexical error through d. */
bool lang_lex(lang_lexer *lx, diag *d, lang_token *tok);
/* The spelling of a token kind for messages: "'{'", "'sphere'", "a number", "end of file". */
const char *lang_tok_name(lang_tok k);
/* The byte a string escape stands for: 'n' gives '\n' (the lexer accepts only POV-Ray's escapes). */
char lang_string_escape(char c);
/* The keyword with this spelling, or LTK_IDENT. */
lang_tok lang_keyword(const char *s, size_t len);
/* True for a POV-Ray 3.7 reserved word that is not a keyword of circe ("difference", "media", ...). */
bool lang_unsupported_word(const char *s, size_t len);
/* POV-Ray 3.7's reserved words (the table lang_unsupported_word searches), for tests: the i-th
 * in sorted order, NULL past the end. */
size_t lang_pov_word_count(void);
const char *lang_pov_word(size_t i);

#endif
