/* lex.c - hand-written lexer: whitespace, comments, numbers, strings, words, punctuation and
 * `#directive` words. The source text is NUL-terminated (diag_source guarantees it). */
#include "lang/lex.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct word {
	const char *s;
	lang_tok tok;
	size_t len;
} word;

static const word keywords[] = {
#define LANG_KW_WORD(e, s) {s, LTK_KW_##e, sizeof s - 1},
	LANG_KEYWORDS(LANG_KW_WORD)
#undef LANG_KW_WORD
};

static const word directives[] = {
#define LANG_DIR_WORD(e, s) {s, LTK_DIR_##e, sizeof s - 1},
	LANG_DIRECTIVES(LANG_DIR_WORD)
#undef LANG_DIR_WORD
};

/* Every reserved word of POV-Ray 3.7, as listed in its Reserved_Words table
 * (source/backend/parser/reswords.cpp on the 3.7-stable branch of github.com/POV-Ray/povray; the
 * table's descriptive token names such as "float identifier" and its punctuation left out), plus
 * "lemon", a shape of POV-Ray 3.8. A word here that is not a circe keyword (the keywords table
 * wins) lexes as LTK_UNSUPPORTED, so the parser can say "'WORD' is not supported by circe"; a
 * feature added moves its word into LANG_KEYWORDS. The directive names are here too, as in
 * POV-Ray's table. Sorted: looked up by binary search (test_lex checks every entry is found). */
static const char *const pov_words[] = {
	"aa_level", "aa_threshold", "abs", "absorption", "accuracy", "acos", "acosh", "adaptive",
	"adc_bailout", "agate", "agate_turb", "albedo", "all", "all_intersections", "alpha", "altitude",
	"always_sample", "ambient", "ambient_light", "angle", "anisotropy", "aoi", "aperture", "append",
	"arc_angle", "area_illumination", "area_light", "array", "asc", "ascii", "asin", "asinh",
	"assumed_gamma", "atan", "atan2", "atanh", "autostop", "average", "b_spline", "background",
	"bezier_spline", "bicubic_patch", "bitwise_and", "bitwise_or", "bitwise_xor", "black_hole", "blob",
	"blue", "blur_samples", "bmp", "bokeh", "bounded_by", "box", "boxed", "bozo", "break", "brick",
	"brick_size", "brightness", "brilliance", "bump_map", "bump_size", "bumps", "camera", "case",
	"caustics", "ceil", "cells", "charset", "checker", "chr", "circular", "clipped_by", "clock",
	"clock_on", "collect", "color", "color_map", "colour", "colour_map", "component", "composite",
	"concat", "cone", "confidence", "conic_sweep", "conserve_energy", "contained_by", "control0",
	"control1", "coords", "cos", "cosh", "count", "crackle", "crand", "cube", "cubic", "cubic_spline",
	"cubic_wave", "cutaway_textures", "cylinder", "cylindrical", "datetime", "debug", "declare",
	"default", "defined", "degrees", "density", "density_file", "density_map", "dents", "deprecated",
	"df3", "difference", "diffuse", "dimension_size", "dimensions", "direction", "disc", "dispersion",
	"dispersion_samples", "dist_exp", "distance", "distance_maximum", "div", "double_illuminate",
	"dtag", "eccentricity", "else", "elseif", "emission", "end", "error", "error_bound", "evaluate",
	"exp", "expand_thresholds", "exponent", "exr", "exterior", "extinction", "face_indices", "facets",
	"fade_color", "fade_colour", "fade_distance", "fade_power", "falloff", "falloff_angle", "false",
	"fclose", "file_exists", "filter", "finish", "fisheye", "flatness", "flip", "floor", "focal_point",
	"fog", "fog_alt", "fog_offset", "fog_type", "fopen", "for", "form", "frequency", "fresnel",
	"function", "gamma", "gather", "gif", "global", "global_lights", "global_settings", "gradient",
	"granite", "gray", "gray_threshold", "green", "hdr", "height_field", "hexagon", "hf_gray_16",
	"hierarchy", "hollow", "hypercomplex", "if", "ifdef", "iff", "ifndef", "image_map",
	"image_pattern", "importance", "include", "inside", "inside_vector", "int", "interior",
	"interior_texture", "internal", "interpolate", "intersection", "intervals", "inverse", "ior",
	"irid", "irid_wavelength", "isosurface", "jitter", "jpeg", "julia", "julia_fractal", "lambda",
	"lathe", "lemon", "leopard", "light_group", "light_source", "linear_spline", "linear_sweep", "ln",
	"load_file", "local", "location", "log", "look_at", "looks_like", "low_error_factor", "macro",
	"magnet", "major_radius", "mandel", "map_type", "marble", "material", "material_map", "matrix",
	"max", "max_extent", "max_gradient", "max_intersections", "max_iteration", "max_sample",
	"max_trace", "max_trace_level", "maximum_reuse", "media", "media_attenuation", "media_interaction",
	"merge", "mesh", "mesh2", "mesh_camera", "metallic", "method", "metric", "min", "min_extent",
	"minimum_reuse", "mm_per_unit", "mod", "mortar", "natural_spline", "nearest_count", "no",
	"no_bump_scale", "no_image", "no_radiosity", "no_reflection", "no_shadow", "noise_generator",
	"normal", "normal_indices", "normal_map", "normal_vectors", "now", "number_of_sides",
	"number_of_tiles", "number_of_waves", "object", "octaves", "off", "offset", "omega", "omnimax",
	"on", "once", "onion", "open", "orient", "orientation", "orthographic", "ovus", "panoramic",
	"parallel", "parametric", "pass_through", "pattern", "pavement", "perspective", "pgm", "phase",
	"phong", "phong_size", "photons", "pi", "pigment", "pigment_map", "pigment_pattern", "planar",
	"plane", "png", "point_at", "poly", "poly_wave", "polygon", "polynomial", "pot", "pow", "ppm",
	"precision", "precompute", "premultiplied", "pretrace_end", "pretrace_start", "prism", "prod",
	"projected_through", "pwr", "quadratic_spline", "quadric", "quartic", "quaternion", "quick_color",
	"quick_colour", "quilted", "radial", "radians", "radiosity", "radius", "rainbow", "ramp_wave",
	"rand", "range", "ratio", "read", "reciprocal", "recursion_limit", "red", "reflection",
	"reflection_exponent", "refraction", "render", "repeat", "rgb", "rgbf", "rgbft", "rgbt", "right",
	"ripples", "rotate", "roughness", "samples", "save_file", "sblue", "scale", "scallop_wave",
	"scattering", "seed", "select", "sgreen", "shadowless", "sin", "sine_wave", "sinh", "sint16be",
	"sint16le", "sint32be", "sint32le", "sint8", "size", "sky", "sky_sphere", "slice", "slope",
	"slope_map", "smooth", "smooth_triangle", "solid", "sor", "spacing", "specular", "sphere",
	"sphere_sweep", "spherical", "spiral1", "spiral2", "spline", "split_union", "spotlight", "spotted",
	"sqr", "sqrt", "square", "sred", "srgb", "srgbf", "srgbft", "srgbt", "statistics", "steps", "str",
	"strcmp", "strength", "strlen", "strlwr", "strupr", "sturm", "substr", "subsurface", "sum",
	"superellipsoid", "switch", "sys", "t", "tan", "tanh", "target", "text", "texture", "texture_list",
	"texture_map", "tga", "thickness", "threshold", "tiff", "tightness", "tile2", "tiles", "tiling",
	"tolerance", "toroidal", "torus", "trace", "transform", "translate", "translucency", "transmit",
	"triangle", "triangle_wave", "triangular", "true", "ttf", "turb_depth", "turbulence", "type", "u",
	"u_steps", "uint16be", "uint16le", "uint8", "ultra_wide_angle", "undef", "union", "up",
	"use_alpha", "use_color", "use_colour", "use_index", "utf8", "uv_indices", "uv_mapping",
	"uv_vectors", "v", "v_steps", "val", "variance", "vaxis_rotate", "vcross", "vdot", "version",
	"vertex_vectors", "vlength", "vnormalize", "vrotate", "vstr", "vturbulence", "warning", "warp",
	"water_level", "waves", "while", "width", "wood", "wrinkles", "write", "x", "xyz", "y", "yes", "z"};
static const char *const unsupported_directives[] = {
	"append", "render", "statistics"};

/* strcmp of the NUL-terminated w against the n bytes at s. */
static int cmp_word(const char *w, const char *s, size_t n)
{
	int r = strncmp(w, s, n);
	return r ? r : (w[n] != '\0');
}

/* Binary search in a sorted array of n entries, each `stride` bytes, whose first member is the
 * spelling. Returns the index or -1. */
static long find_word(const void *tab, size_t n, size_t stride, const char *s, size_t len)
{
	size_t lo = 0, hi = n;
	while (lo < hi) {
		size_t mid = lo + (hi - lo) / 2;
		const char *w = *(const char *const *)((const char *)tab + mid * stride);
		int r = cmp_word(w, s, len);
		if (r == 0)
			return (long)mid;
		if (r < 0)
			lo = mid + 1;
		else
			hi = mid;
	}
	return -1;
}

#define N_OF(a) (sizeof(a) / sizeof(a)[0])

lang_tok lang_keyword(const char *s, size_t len)
{
	long i = find_word(keywords, N_OF(keywords), sizeof keywords[0], s, len);
	return i < 0 ? LTK_IDENT : keywords[i].tok;
}

bool lang_unsupported_word(const char *s, size_t len)
{
	return lang_keyword(s, len) == LTK_IDENT && find_word(pov_words, N_OF(pov_words), sizeof(char *), s, len) >= 0;
}

size_t lang_pov_word_count(void) { return N_OF(pov_words); }

const char *lang_pov_word(size_t i) { return i < N_OF(pov_words) ? pov_words[i] : NULL; }

const char *lang_tok_name(lang_tok k)
{
	static const char *const punct[] = {
		"end of file", "a number", "a string", "an identifier", "an unsupported word",
		"an unsupported directive",
		"'{'", "'}'", "'('", "')'", "'<'", "'>'", "'<='", "'>='", "'='", "'!='", "','", "';'",
		"'+'", "'-'", "'*'", "'/'", "'!'", "'&'", "'|'", "'?'", "':'", "'.'", "'['", "']'"};
	static const char *const names[] = {
#define LANG_KW_NAME(e, s) "'" s "'",
		LANG_KEYWORDS(LANG_KW_NAME)
#undef LANG_KW_NAME
#define LANG_DIR_NAME(e, s) "'#" s "'",
		LANG_DIRECTIVES(LANG_DIR_NAME)
#undef LANG_DIR_NAME
	};
	if ((unsigned)k < LANG_FIRST_KEYWORD)
		return punct[k];
	if (k < LTK_COUNT)
		return names[k - LANG_FIRST_KEYWORD];
	return "?";
}

void lang_lexer_init(lang_lexer *lx, const diag_source *src)
{
	lx->src = src;
	lx->p = src->text;
	lx->end = src->text + src->len;
	lx->line = 1;
	lx->line_start = src->text;
}

static diag_loc here(const lang_lexer *lx, const char *p)
{
	return (diag_loc){lx->src, lx->line, (uint32_t)(p - lx->line_start) + 1};
}

static bool is_ident_start(int c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_'; }
static bool is_digit(int c) { return c >= '0' && c <= '9'; }
static bool is_ident_char(int c) { return is_ident_start(c) || is_digit(c); }

/* Skips whitespace and comments; false after an unterminated block comment. */
static bool skip_space(lang_lexer *lx, diag *d)
{
	const char *p = lx->p;
	for (;;) {
		if (p >= lx->end)
			break;
		char c = *p;
		if (c == '\n') {
			p++;
			lx->line++;
			lx->line_start = p;
		} else if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
			p++;
		} else if (c == '/' && p + 1 < lx->end && p[1] == '/') {
			while (p < lx->end && *p != '\n')
				p++;
		} else if (c == '/' && p + 1 < lx->end && p[1] == '*') {
			diag_loc open = here(lx, p);
			p += 2;
			for (;;) {
				if (p >= lx->end) {
					lx->p = p;
					diag_error(d, open, "unterminated comment: '/*' has no matching '*/'");
					return false;
				}
				if (*p == '*' && p + 1 < lx->end && p[1] == '/') {
					p += 2;
					break;
				}
				if (*p == '\n') {
					lx->line++;
					lx->line_start = p + 1;
				}
				p++;
			}
		} else {
			break;
		}
	}
	lx->p = p;
	return true;
}

/* The value of the number s..e. Plain decimals of up to 15 digits take Clinger's fast path: the
 * digits form an exact integer below 2^53 and the power of ten is exact, so one division rounds
 * correctly. Everything else goes to strtod (buf has room for n + 1 bytes). */
static double fast_decimal(const char *s, const char *e, char *buf, size_t n)
{
	static const double pow10[] = {1e0, 1e1, 1e2,  1e3,  1e4,  1e5,  1e6,  1e7,
				       1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
	uint64_t mant = 0;
	int digits = 0, frac = -1;
	for (const char *q = s; q < e; q++) {
		if (*q == '.') {
			frac = 0;
			continue;
		}
		if (!is_digit(*q) || ++digits > 15)
			goto slow;
		mant = mant * 10 + (uint64_t)(*q - '0');
		if (frac >= 0)
			frac++;
	}
	return (double)mant / pow10[frac > 0 ? frac : 0];
slow:
	memcpy(buf, s, n);
	buf[n] = '\0';
	return strtod(buf, NULL);
}

static bool lex_number(lang_lexer *lx, diag *d, lang_token *t)
{
	const char *s = lx->p, *p = s;
	while (p < lx->end && is_digit(*p))
		p++;
	if (p < lx->end && *p == '.') {
		p++;
		while (p < lx->end && is_digit(*p))
			p++;
	}
	if (p < lx->end && (*p == 'e' || *p == 'E')) {
		const char *q = p + 1;
		if (q < lx->end && (*q == '+' || *q == '-'))
			q++;
		if (q < lx->end && is_digit(*q)) {
			while (q < lx->end && is_digit(*q))
				q++;
			p = q;
		} else {
			lx->p = p;
			diag_error(d, t->loc, "malformed number: exponent '%c' needs digits", *p);
			return false;
		}
	}
	size_t n = (size_t)(p - s);
	char buf[512];
	if (n >= sizeof buf) {
		diag_error(d, t->loc, "number too long (limit is %d characters)", (int)sizeof buf - 1);
		return false;
	}
	if (n == 1 && *s == '.') {
		diag_error(d, t->loc, "unexpected character '.'");
		return false;
	}
	t->number = fast_decimal(s, p, buf, n);
	t->kind = LTK_NUMBER;
	t->text = s;
	t->len = (uint32_t)n;
	lx->p = p;
	if (!isfinite(t->number)) {
		diag_error(d, t->loc, "number '%.*s' overflows a double (limit is about 1.8e308)",
			   n > 40 ? 40 : (int)n, s);
		return false;
	}
	return true;
}

/* The escapes of POV-Ray 3.7's strings (String_To_UCS2 in parsestr.cpp) but \\u: a backslash and
 * one of these; lang_string_escape gives each one's byte. */
static const char STRING_ESCAPES[] = "abfnrtv'\"\\";

char lang_string_escape(char c)
{
	switch (c) {
	case 'a': return '\a';
	case 'b': return '\b';
	case 'f': return '\f';
	case 'n': return '\n';
	case 'r': return '\r';
	case 't': return '\t';
	case 'v': return '\v';
	default: return c; /* ' " \ */
	}
}

static bool lex_string(lang_lexer *lx, diag *d, lang_token *t)
{
	const char *p = lx->p + 1;
	for (;;) {
		if (p >= lx->end || *p == '\n' || *p == '\r') {
			diag_error(d, t->loc, "unterminated string: a string must end on the line where it starts");
			return false;
		}
		if (*p == '"')
			break;
		if (*p == '\\') {
			if (p + 1 < lx->end && p[1] != '\0' && strchr(STRING_ESCAPES, p[1])) {
				p += 2;
				continue;
			}
			diag_error(d, here(lx, p), "unknown escape in string: circe reads \\a \\b \\f \\n \\r \\t \\v "
						   "\\' \\\" and \\\\");
			return false;
		}
		p++;
	}
	size_t n = (size_t)(p - lx->p - 1);
	if (n > LANG_MAX_STRING) {
		diag_error(d, t->loc, "string too long (limit is %d bytes)", LANG_MAX_STRING);
		return false;
	}
	t->kind = LTK_STRING;
	t->text = lx->p + 1;
	t->len = (uint32_t)n;
	lx->p = p + 1;
	return true;
}

static bool lex_word(lang_lexer *lx, diag *d, lang_token *t, bool directive)
{
	const char *s = lx->p, *p = s;
	while (p < lx->end && is_ident_char(*p))
		p++;
	size_t n = (size_t)(p - s);
	lx->p = p;
	t->text = s;
	t->len = (uint32_t)(n > LANG_MAX_IDENT ? LANG_MAX_IDENT : n);
	if (n > LANG_MAX_IDENT) {
		diag_error(d, t->loc, "identifier too long (limit is %d characters)", LANG_MAX_IDENT);
		return false;
	}
	if (directive) {
		for (size_t i = 0; i < N_OF(directives); i++)
			if (directives[i].len == n && !memcmp(directives[i].s, s, n)) {
				t->kind = directives[i].tok;
				return true;
			}
		if (find_word(unsupported_directives, N_OF(unsupported_directives), sizeof(char *), s, n) >= 0) {
			t->kind = LTK_UNSUPPORTED_DIRECTIVE;
			return true;
		}
		if (n == 0)
			diag_error(d, t->loc, "'#' must be followed by a directive name");
		else
			diag_error(d, t->loc, "unknown directive '#%.*s'", (int)n, s);
		return false;
	}
	t->kind = lang_keyword(s, n);
	if (t->kind == LTK_IDENT && lang_unsupported_word(s, n))
		t->kind = LTK_UNSUPPORTED;
	return true;
}

bool lang_lex(lang_lexer *lx, diag *d, lang_token *t)
{
	t->text = NULL;
	t->len = 0;
	t->number = 0;
	bool ok = skip_space(lx, d);
	t->loc = here(lx, lx->p);
	if (!ok) {
		t->kind = LTK_EOF;
		return false;
	}
	const char *p = lx->p;
	if (p >= lx->end) {
		t->kind = LTK_EOF;
		return true;
	}
	char c = *p;
	if (is_digit(c) || (c == '.' && p + 1 < lx->end && is_digit(p[1])))
		return lex_number(lx, d, t);
	if (c == '"')
		return lex_string(lx, d, t);
	if (is_ident_start(c))
		return lex_word(lx, d, t, false);
	if (c == '#') {
		/* POV-Ray 3.7 reads the directive's name as the next token after '#', so whitespace,
		 * newlines and comments may stand between them; the token stays at the '#'. */
		lx->p = p + 1;
		if (!skip_space(lx, d)) {
			t->kind = LTK_EOF;
			return false;
		}
		if (lx->p >= lx->end || !is_ident_start(*lx->p)) {
			/* `look_at <0, 2, 0>#` (POV-Ray's language/image_size.pov): povray 3.7.0 drops a '#'
			 * that no name follows, silently; circe drops it too, with a warning. */
			diag_warning(d, t->loc, "'#' not followed by a directive name is ignored (as POV-Ray does)");
			return lang_lex(lx, d, t);
		}
		return lex_word(lx, d, t, true);
	}
	t->text = p;
	t->len = 1;
	lx->p = p + 1;
	bool two = p + 1 < lx->end && p[1] == '=';
	switch (c) {
	case '{': t->kind = LTK_LBRACE; return true;
	case '}': t->kind = LTK_RBRACE; return true;
	case '(': t->kind = LTK_LPAREN; return true;
	case ')': t->kind = LTK_RPAREN; return true;
	case ',': t->kind = LTK_COMMA; return true;
	case ';': t->kind = LTK_SEMI; return true;
	case '+': t->kind = LTK_PLUS; return true;
	case '-': t->kind = LTK_MINUS; return true;
	case '*': t->kind = LTK_STAR; return true;
	case '/': t->kind = LTK_SLASH; return true;
	case '&': t->kind = LTK_AMP; return true;
	case '|': t->kind = LTK_BAR; return true;
	case '?': t->kind = LTK_QUESTION; return true;
	case ':': t->kind = LTK_COLON; return true;
	case '.': t->kind = LTK_DOT; return true;
	case '[': t->kind = LTK_LBRACKET; return true;
	case ']': t->kind = LTK_RBRACKET; return true;
	case '=': t->kind = LTK_EQ; return true;
	case '<': t->kind = two ? LTK_LE : LTK_LT; break;
	case '>': t->kind = two ? LTK_GE : LTK_GT; break;
	case '!': t->kind = two ? LTK_NE : LTK_BANG; break;
	default:
		if ((unsigned char)c >= 0x20 && (unsigned char)c < 0x7f)
			diag_error(d, t->loc, "unexpected character '%c'", c);
		else
			diag_error(d, t->loc, "unexpected byte 0x%02x (circe reads ASCII or UTF-8 text; non-ASCII is "
					      "allowed only in comments and strings)",
				   (unsigned char)c);
		t->kind = LTK_EOF;
		return false;
	}
	if (two) {
		lx->p++;
		t->len = 2;
	}
	return true;
}
