/* diag.h - diagnostics in the GCC style: `file:line:col: error: message`, then the source line and
 * a caret under the column, then `note:` lines for related places (an include chain, the brace
 * that opened an unclosed block). Library code reports here and returns a status; only main.c
 * decides exit codes. The diag object owns copies of every source text it may quote. */
#ifndef CIRCE_BASE_DIAG_H
#define CIRCE_BASE_DIAG_H

#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

typedef struct diag_source {
	char *name; /* as the user wrote it (or as found on the search path) */
	char *text; /* the bytes of the file, NUL-terminated unless mapped */
	size_t len;
	void *map; /* non-NULL: text lies in this read-only file mapping of map_len bytes */
	size_t map_len;
	struct diag_source *next;
} diag_source;

/* A place in a source: line and col count from 1; col counts bytes, a tab is one column. */
typedef struct diag_loc {
	const diag_source *src;
	uint32_t line, col;
} diag_loc;

typedef enum diag_kind { DIAG_ERROR, DIAG_WARNING, DIAG_NOTE } diag_kind;

typedef struct diag {
	FILE *out;
	int errors, warnings;
	int max_errors; /* after this many errors further ones are counted, not printed (0: no limit) */
	diag_source *sources;
} diag;

void diag_init(diag *d, FILE *out);
void diag_free(diag *d);

/* Registers a copy of a source text so later reports can quote it; NULL when memory runs out. */
const diag_source *diag_add_source(diag *d, const char *name, const char *text, size_t len);

/* Like diag_add_source, but takes ownership of text (from mem_alloc, len + 1 bytes with
 * text[len] == '\0'), so a large file is not held twice. On failure text is freed, NULL returned. */
const diag_source *diag_adopt_source(diag *d, const char *name, char *text, size_t len);

/* Registers a read-only file mapping (mmap) as a source: text is map + skip, len map_len - skip,
 * and no NUL follows it (readers must stop at len). diag_free unmaps it; NULL on failure (the
 * mapping is then unmapped). Its pages may be dropped (madvise) and fault back in when quoted. */
const diag_source *diag_adopt_mapped(diag *d, const char *name, void *map, size_t map_len, size_t skip);

/* Reports at loc (loc.src may be NULL: then `circe: error: message`). */
void diag_report(diag *d, diag_kind kind, diag_loc loc, const char *fmt, ...)
	__attribute__((format(printf, 4, 5)));
void diag_vreport(diag *d, diag_kind kind, diag_loc loc, const char *fmt, va_list ap);
/* `name: error: message`, for files that have no line to quote (I/O errors, binary files). */
void diag_file_error(diag *d, const char *name, const char *fmt, ...)
	__attribute__((format(printf, 3, 4)));
/* `name: warning: message`, the same for a warning about a file's contents. */
void diag_file_warning(diag *d, const char *name, const char *fmt, ...) __attribute__((format(printf, 3, 4)));

#define diag_error(d, loc, ...) diag_report((d), DIAG_ERROR, (loc), __VA_ARGS__)
#define diag_warning(d, loc, ...) diag_report((d), DIAG_WARNING, (loc), __VA_ARGS__)
#define diag_note(d, loc, ...) diag_report((d), DIAG_NOTE, (loc), __VA_ARGS__)

/* The location with no source: reports print `circe:` as their place. */
static inline diag_loc diag_noloc(void) { return (diag_loc){0, 0, 0}; }

#endif
