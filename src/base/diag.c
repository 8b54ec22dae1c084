/* diag.c - formats diagnostics and quotes the source line with a caret. */
#include "base/diag.h"

#include "base/mem.h"

#include <string.h>
#include <sys/mman.h>

void diag_init(diag *d, FILE *out)
{
	d->out = out;
	d->errors = d->warnings = 0;
	d->max_errors = 20;
	d->sources = NULL;
}

void diag_free(diag *d)
{
	diag_source *s = d->sources;
	while (s) {
		diag_source *next = s->next;
		mem_free(s->name);
		if (s->map)
			munmap(s->map, s->map_len);
		else
			mem_free(s->text);
		mem_free(s);
		s = next;
	}
	d->sources = NULL;
}

const diag_source *diag_add_source(diag *d, const char *name, const char *text, size_t len)
{
	diag_source *s = mem_calloc(1, sizeof *s);
	if (!s)
		return NULL;
	s->name = mem_strdup(name);
	s->text = len < SIZE_MAX ? mem_alloc(len + 1, 1) : NULL;
	if (!s->name || !s->text) {
		mem_free(s->name);
		mem_free(s->text);
		mem_free(s);
		return NULL;
	}
	memcpy(s->text, text, len);
	s->text[len] = '\0';
	s->len = len;
	s->next = d->sources;
	d->sources = s;
	return s;
}

const diag_source *diag_adopt_source(diag *d, const char *name, char *text, size_t len)
{
	diag_source *s = mem_calloc(1, sizeof *s);
	if (s)
		s->name = mem_strdup(name);
	if (!s || !s->name) {
		mem_free(s);
		mem_free(text);
		return NULL;
	}
	text[len] = '\0';
	s->text = text;
	s->len = len;
	s->next = d->sources;
	d->sources = s;
	return s;
}

const diag_source *diag_adopt_mapped(diag *d, const char *name, void *map, size_t map_len, size_t skip)
{
	diag_source *s = mem_calloc(1, sizeof *s);
	if (s)
		s->name = mem_strdup(name);
	if (!s || !s->name) {
		mem_free(s);
		munmap(map, map_len);
		return NULL;
	}
	s->map = map;
	s->map_len = map_len;
	s->text = (char *)map + skip;
	s->len = map_len - skip;
	s->next = d->sources;
	d->sources = s;
	return s;
}

static const char *kind_name(diag_kind k)
{
	switch (k) {
	case DIAG_ERROR:
		return "error";
	case DIAG_WARNING:
		return "warning";
	case DIAG_NOTE:
		return "note";
	}
	return "error";
}

/* Prints line `line` of src and a caret under byte column col. Tabs in the prefix are kept so the
 * caret lines up in a terminal; UTF-8 continuation bytes take no column on screen. */
static void quote_line(FILE *out, const diag_source *src, uint32_t line, uint32_t col)
{
	const char *p = src->text, *end = src->text + src->len;
	for (uint32_t l = 1; l < line && p < end; p++)
		if (*p == '\n')
			l++;
	if (p > end)
		return;
	const char *e = p;
	while (e < end && *e != '\n' && *e != '\r')
		e++;
	fprintf(out, "%.*s\n", (int)(e - p), p);
	for (uint32_t c = 1; c < col && p < e; c++, p++) {
		unsigned char ch = (unsigned char)*p;
		if ((ch & 0xC0) == 0x80)
			continue;
		fputc(ch == '\t' ? '\t' : ' ', out);
	}
	fputs("^\n", out);
}

void diag_vreport(diag *d, diag_kind kind, diag_loc loc, const char *fmt, va_list ap)
{
	if (kind == DIAG_ERROR)
		d->errors++;
	else if (kind == DIAG_WARNING)
		d->warnings++;
	if (d->max_errors > 0 && d->errors > d->max_errors)
		return; /* notes of a suppressed error go with it */
	if (!d->out)
		return;
	if (loc.src)
		fprintf(d->out, "%s:%u:%u: %s: ", loc.src->name, loc.line, loc.col, kind_name(kind));
	else
		fprintf(d->out, "circe: %s: ", kind_name(kind));
	vfprintf(d->out, fmt, ap);
	fputc('\n', d->out);
	if (loc.src && loc.line > 0)
		quote_line(d->out, loc.src, loc.line, loc.col);
	if (kind == DIAG_ERROR && d->max_errors > 0 && d->errors == d->max_errors)
		fprintf(d->out, "circe: note: too many errors (limit is %d); the rest are not shown\n",
			d->max_errors);
}

void diag_report(diag *d, diag_kind kind, diag_loc loc, const char *fmt, ...)
{
	va_list ap;
	va_start(ap, fmt);
	diag_vreport(d, kind, loc, fmt, ap);
	va_end(ap);
}

static void file_vreport(diag *d, diag_kind kind, const char *name, const char *fmt, va_list ap)
{
	if (!d->out)
		return;
	fprintf(d->out, "%s: %s: ", name, kind_name(kind));
	vfprintf(d->out, fmt, ap);
	fputc('\n', d->out);
}

void diag_file_error(diag *d, const char *name, const char *fmt, ...)
{
	d->errors++;
	va_list ap;
	va_start(ap, fmt);
	file_vreport(d, DIAG_ERROR, name, fmt, ap);
	va_end(ap);
}

void diag_file_warning(diag *d, const char *name, const char *fmt, ...)
{
	d->warnings++;
	va_list ap;
	va_start(ap, fmt);
	file_vreport(d, DIAG_WARNING, name, fmt, ap);
	va_end(ap);
}
