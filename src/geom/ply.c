/* ply.c - the structural check of PLY files (ply.h): the header's elements and properties, then a
 * walk over the body that consumes exactly what they declare. */
#include "geom/ply.h"

#include "base/mem.h"

#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* More than any PLY writer produces; the header is refused beyond them. */
enum { PLY_MAX_ELEMENTS = 64, PLY_MAX_PROPS = 64, PLY_MAX_LINE = 256, PLY_MAX_TOKEN = 64 };

typedef enum ply_format { PLY_NONE, PLY_ASCII, PLY_BINARY_LE, PLY_BINARY_BE } ply_format;

typedef struct ply_prop {
	int size;	   /* bytes of a scalar, or of each item of a list */
	int count_size;	   /* a list: bytes of its count; 0 for a scalar */
	bool count_signed; /* the count's type is signed */
} ply_prop;

typedef struct ply_element {
	char name[32];
	unsigned long long count;
	int n_props;
	ply_prop props[PLY_MAX_PROPS];
} ply_element;

typedef struct ply_header {
	ply_format format;
	int n_elements;
	ply_element elements[PLY_MAX_ELEMENTS];
	size_t body; /* offset of the first byte after the end_header line */
} ply_header;

static bool fail(char *why, size_t why_len, const char *fmt, ...) __attribute__((format(printf, 3, 4)));
static bool fail(char *why, size_t why_len, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(why, why_len, fmt, ap);
	va_end(ap);
	return false;
}

/* Bytes of a PLY scalar type (both spellings of the specification), 0 for an unknown one. */
static int type_size(const char *t, bool *is_signed, bool *is_int)
{
	static const struct {
		const char *name;
		int size;
		bool is_signed, is_int;
	} types[] = {{"char", 1, true, true},	   {"int8", 1, true, true},	{"uchar", 1, false, true},
		     {"uint8", 1, false, true},	   {"short", 2, true, true},	{"int16", 2, true, true},
		     {"ushort", 2, false, true},   {"uint16", 2, false, true},	{"int", 4, true, true},
		     {"int32", 4, true, true},	   {"uint", 4, false, true},	{"uint32", 4, false, true},
		     {"float", 4, true, false},	   {"float32", 4, true, false}, {"double", 8, true, false},
		     {"float64", 8, true, false}};
	for (size_t i = 0; i < sizeof types / sizeof *types; i++)
		if (!strcmp(t, types[i].name)) {
			*is_signed = types[i].is_signed, *is_int = types[i].is_int;
			return types[i].size;
		}
	return 0;
}

/* One header line (without its end of line) into h; false with the reason. */
static bool header_line(ply_header *h, const char *line, char *why, size_t why_len)
{
	char w[5][PLY_MAX_LINE];
	int n = sscanf(line, "%255s %255s %255s %255s %255s", w[0], w[1], w[2], w[3], w[4]);
	if (n <= 0 || !strcmp(w[0], "comment") || !strcmp(w[0], "obj_info"))
		return true;
	if (!strcmp(w[0], "format")) {
		if (n < 2)
			return fail(why, why_len, "the PLY format line names no format");
		h->format = !strcmp(w[1], "ascii")		  ? PLY_ASCII
			    : !strcmp(w[1], "binary_little_endian") ? PLY_BINARY_LE
			    : !strcmp(w[1], "binary_big_endian")    ? PLY_BINARY_BE
								    : PLY_NONE;
		if (h->format == PLY_NONE)
			return fail(why, why_len, "unknown PLY format '%s'", w[1]);
		return true;
	}
	if (!strcmp(w[0], "element")) {
		char *end;
		if (n != 3 || h->n_elements == PLY_MAX_ELEMENTS)
			return fail(why, why_len, n != 3 ? "a PLY element line needs a name and a count"
							 : "more than 64 elements in the PLY header");
		ply_element *e = &h->elements[h->n_elements++];
		memset(e, 0, sizeof *e);
		snprintf(e->name, sizeof e->name, "%.31s", w[1]);
		e->count = strtoull(w[2], &end, 10);
		if (*end || w[2][0] == '-')
			return fail(why, why_len, "the count of PLY element '%s' is '%s', not a number", e->name, w[2]);
		return true;
	}
	if (!strcmp(w[0], "property")) {
		if (!h->n_elements)
			return fail(why, why_len, "a PLY property comes before any element");
		ply_element *e = &h->elements[h->n_elements - 1];
		if (e->n_props == PLY_MAX_PROPS)
			return fail(why, why_len, "more than 64 properties in PLY element '%s'", e->name);
		ply_prop *p = &e->props[e->n_props++];
		bool is_signed, is_int;
		if (n >= 2 && !strcmp(w[1], "list")) {
			if (n != 5)
				return fail(why, why_len, "a PLY list property needs a count type, an item type and a name");
			p->count_size = type_size(w[2], &p->count_signed, &is_int);
			if (!p->count_size || !is_int)
				return fail(why, why_len, "the count type of a PLY list must be an integer type, not '%s'", w[2]);
			p->size = type_size(w[3], &is_signed, &is_int);
			if (!p->size)
				return fail(why, why_len, "unknown PLY type '%s'", w[3]);
			return true;
		}
		if (n != 3)
			return fail(why, why_len, "a PLY property needs a type and a name");
		p->size = type_size(w[1], &is_signed, &is_int);
		return p->size ? true : fail(why, why_len, "unknown PLY type '%s'", w[1]);
	}
	return fail(why, why_len, "unexpected line in the PLY header: '%.40s'", line);
}

/* A header line's bytes are printable ASCII and tabs, and any byte from 0x80 in a comment. A NUL,
 * a lone CR or another control byte ends a line or a token for this reader but not for Assimp's,
 * which then reads a different header: a fuzzed "element vertex 33" followed by NUL bytes
 * overflowed its heap. */
static bool clean_line(const char *s, size_t n, bool is_comment)
{
	for (size_t i = 0; i < n; i++) {
		unsigned char c = (unsigned char)s[i];
		if ((c < 0x20 && c != '\t') || c == 0x7f || (c >= 0x80 && !is_comment))
			return false;
	}
	return true;
}

static bool read_header(ply_header *h, const char *data, size_t len, char *why, size_t why_len)
{
	size_t limit = len < PLY_MAX_HEADER ? len : PLY_MAX_HEADER, pos = 0;
	for (int first = 1, lineno = 1;; first = 0, lineno++) {
		const char *nl = memchr(data + pos, '\n', limit - pos);
		if (!nl)
			return fail(why, why_len, "the PLY header has no end_header line (a truncated file?)");
		size_t n = (size_t)(nl - (data + pos));
		if (n && data[pos + n - 1] == '\r')
			n--;
		char line[PLY_MAX_LINE];
		bool is_comment = n >= 7 && (!memcmp(data + pos, "comment", 7) || !memcmp(data + pos, "obj_info", 7));
		if (n >= sizeof line && !is_comment)
			return fail(why, why_len, "a PLY header line is longer than %d characters", PLY_MAX_LINE - 1);
		if (!clean_line(data + pos, n, is_comment))
			return fail(why, why_len,
				    "line %d of the PLY header holds a control byte (NUL, CR, ...) or, outside a "
				    "comment, a byte that is not ASCII",
				    lineno);
		memcpy(line, data + pos, n < sizeof line ? n : sizeof line - 1);
		line[n < sizeof line ? n : sizeof line - 1] = '\0';
		pos = (size_t)(nl - data) + 1;
		if (first)
			continue; /* "ply", checked by the caller */
		if (!strcmp(line, "end_header")) {
			h->body = pos;
			return h->format != PLY_NONE ? true : fail(why, why_len, "the PLY header has no format line");
		}
		if (!is_comment && !header_line(h, line, why, why_len))
			return false;
	}
}

/* The next whitespace-separated token of an ASCII body. */
static bool next_token(const char *d, size_t len, size_t *pos, const char **tok, size_t *n)
{
	size_t p = *pos;
	while (p < len && (d[p] == ' ' || d[p] == '\t' || d[p] == '\r' || d[p] == '\n'))
		p++;
	if (p == len)
		return false;
	size_t s = p;
	while (p < len && !(d[p] == ' ' || d[p] == '\t' || d[p] == '\r' || d[p] == '\n'))
		p++;
	*tok = d + s, *n = p - s, *pos = p;
	return true;
}

/* The token as a number: true with its value when all of it is one. */
static bool token_number(const char *tok, size_t n, double *v)
{
	char buf[PLY_MAX_TOKEN];
	if (n >= sizeof buf)
		return false;
	memcpy(buf, tok, n);
	buf[n] = '\0';
	char *end;
	*v = strtod(buf, &end);
	return end == buf + n;
}

/* An unsigned or two's complement integer of `size` bytes in the file's byte order. */
static long long read_int(const unsigned char *b, int size, bool is_signed, bool big_endian)
{
	unsigned long long u = 0;
	for (int i = 0; i < size; i++)
		u |= (unsigned long long)b[big_endian ? size - 1 - i : i] << (8 * i);
	if (is_signed && size < 8 && (u >> (8 * size - 1)) & 1)
		return (long long)u - (1LL << (8 * size));
	return (long long)u;
}

static bool check_body(const ply_header *h, const char *d, size_t len, char *why, size_t why_len)
{
	size_t pos = h->body;
	for (int k = 0; k < h->n_elements; k++) {
		const ply_element *e = &h->elements[k];
		if (!e->n_props)
			continue;
		for (unsigned long long i = 0; i < e->count; i++)
			for (int j = 0; j < e->n_props; j++) {
				const ply_prop *p = &e->props[j];
				long long items = 1;
				if (h->format == PLY_ASCII) {
					const char *tok;
					size_t n;
					double v;
					if (!next_token(d, len, &pos, &tok, &n))
						goto early;
					if (!token_number(tok, n, &v))
						return fail(why, why_len, "the PLY data has '%.*s' where element '%s' %llu needs a number",
							    (int)(n < 20 ? n : 20), tok, e->name, i);
					if (p->count_size) {
						if (!(v >= 0 && v <= PLY_MAX_LIST) || v != (double)(long long)v)
							goto bad_list;
						items = (long long)v;
					}
					for (long long t = 0; p->count_size && t < items; t++) {
						if (!next_token(d, len, &pos, &tok, &n))
							goto early;
						if (!token_number(tok, n, &v))
							return fail(why, why_len,
								    "the PLY data has '%.*s' where element '%s' %llu needs a number",
								    (int)(n < 20 ? n : 20), tok, e->name, i);
					}
				} else {
					if (p->count_size) {
						if (len - pos < (size_t)p->count_size)
							goto early;
						items = read_int((const unsigned char *)d + pos, p->count_size, p->count_signed,
								 h->format == PLY_BINARY_BE);
						pos += (size_t)p->count_size;
						if (items < 0 || items > PLY_MAX_LIST)
							goto bad_list;
					}
					if (len - pos < (size_t)items * (size_t)p->size)
						goto early;
					pos += (size_t)items * (size_t)p->size;
				}
				continue;
			early:
				return fail(why, why_len,
					    "the PLY data ends in element '%s' %llu of the %llu its header declares (a truncated "
					    "file?)",
					    e->name, i + 1, e->count);
			bad_list:
				return fail(why, why_len, "a list of PLY element '%s' %llu has a count outside 0 to %d",
					    e->name, i, PLY_MAX_LIST);
			}
	}
	return true;
}

bool ply_check(const char *data, size_t len, char *why, size_t why_len)
{
	if (len < 4 || (memcmp(data, "ply", 3) && memcmp(data, "PLY", 3)) ||
	    (data[3] != '\n' && data[3] != '\r'))
		return true; /* not a PLY file: not ours to judge */
	ply_header *h = mem_calloc(1, sizeof *h);
	if (!h)
		return fail(why, why_len, "out of memory");
	bool ok = read_header(h, data, len, why, why_len) && check_body(h, data, len, why, why_len);
	mem_free(h);
	return ok;
}
