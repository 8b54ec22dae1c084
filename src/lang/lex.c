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

/* POV-Ray words outside the language, recognised so the error can name them. Sorted: looked up by
 * binary search (test_lex checks every entry is found). */
static const char *const unsupported_words[] = {
	"agate", "ambient", "area_light", "bicubic_patch", "blob", "bounded_by", "bozo", "brilliance",
	"caustics", "checker", "clipped_by", "cone", "conserve_energy", "cubic", "cylinder", "cylindrical",
	"density", "difference", "disc", "fade_distance", "fade_power", "filter", "fisheye", "fog",
	"fresnel", "function", "gradient", "granite", "height_field", "hollow", "interpolate",
	"intersection", "inverse", "irid", "isosurface", "julia_fractal", "lathe", "lemon", "looks_like",
	"material_map", "media", "merge", "mesh_camera", "metallic", "normal", "omnimax", "open",
	"orthographic", "ovus", "panoramic", "parametric", "pattern", "phong", "photons", "pigment_map",
	"poly", "polygon", "prism", "projected_through", "quadric", "quartic", "radiosity", "rainbow",
	"reflection", "refraction", "rgbf", "rgbft", "rgbt", "scattering", "smooth", "sor", "sphere_sweep",
	"spherical", "spline", "srgb", "sturm", "subsurface", "superellipsoid", "text", "texture_map",
	"torus", "translucency", "transmit", "turbulence", "ultra_wide_angle", "uv_mapping"};
static const char *const unsupported_directives[] = {
	"append", "break", "case", "debug", "default", "elseif", "error", "fclose", "fopen", "for",
	"ifdef", "ifndef", "macro", "range", "read", "render", "statistics", "switch", "undef",
	"warning", "write"};

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
	return find_word(unsupported_words, N_OF(unsupported_words), sizeof(char *), s, len) >= 0;
}

const char *lang_tok_name(lang_tok k)
{
	static const char *const punct[] = {
		"end of file", "a number", "a string", "an identifier", "an unsupported word",
		"an unsupported directive",
		"'{'", "'}'", "'('", "')'", "'<'", "'>'", "'<='", "'>='", "'='", "'!='", "','", "';'",
		"'+'", "'-'", "'*'", "'/'", "'!'", "'&'", "'|'", "'?'", "':'", "'.'"};
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
			if (p + 1 < lx->end && (p[1] == '"' || p[1] == '\\')) {
				p += 2;
				continue;
			}
			diag_error(d, here(lx, p), "unknown escape in string: only \\\" and \\\\ are allowed");
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
