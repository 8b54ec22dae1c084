/* mem.h - the one allocation path of circe, and the arena that owns a scene's data.
 * Every allocation goes through mem_alloc/mem_realloc so sizes are overflow-checked in one place,
 * the bytes live are counted against a limit, and the test build can make the Nth allocation fail
 * (mem_fail_after). Allocation failure returns NULL; callers report it as a runtime error, never
 * abort. */
#ifndef CIRCE_BASE_MEM_H
#define CIRCE_BASE_MEM_H

#include <stdbool.h>
#include <stddef.h>

/* malloc(count * size), NULL on overflow or exhaustion. count * size == 0 allocates one byte. */
void *mem_alloc(size_t count, size_t size);
/* mem_alloc, zero-filled. */
void *mem_calloc(size_t count, size_t size);
/* realloc(p, count * size), NULL on overflow or exhaustion (p is then untouched). */
void *mem_realloc(void *p, size_t count, size_t size);
void mem_free(void *p);
/* A copy of the NUL-terminated s, or NULL. */
char *mem_strdup(const char *s);
/* a * b without overflow: false when it overflows. */
bool mem_mul_ok(size_t a, size_t b, size_t *out);

/* A bound on the bytes live at once through mem_alloc, mem_calloc and mem_realloc (0: none; what
 * `--max-memory` sets): an allocation that would pass it fails before anything is allocated, as
 * exhaustion does, and mem_limit_hit then says so. Set before threads start; the counts are
 * atomic. */
void mem_set_limit(size_t bytes);
size_t mem_limit(void);
/* The bytes live now, and the most live at once so far. */
size_t mem_live_bytes(void);
size_t mem_peak_bytes(void);
/* True once an allocation was refused for the limit; *asked and *live (when not NULL) get the
 * last refused one's size and the bytes live then. */
bool mem_limit_hit(size_t *asked, size_t *live);

/* Lets the next n allocations succeed and fails every one after them
 * (negative n: never). For tests of the error paths; not thread-safe, set before threads start. */
void mem_fail_after(long n);

/* Grow-only arena: many allocations, one release. Blocks are chained; an allocation larger than
 * the block size gets a block of its own. Not thread-safe: one arena per owner. */
typedef struct arena_block arena_block;
typedef struct arena {
	arena_block *head;
	size_t block_size;
	size_t total; /* bytes handed out, for memory estimates */
} arena;

void arena_init(arena *a, size_t block_size);
/* count * size bytes aligned to `align` (a power of two up to 64); NULL on overflow/exhaustion. */
void *arena_alloc(arena *a, size_t count, size_t size, size_t align);
/* A zero-filled arena_alloc aligned for any basic type. */
void *arena_zalloc(arena *a, size_t count, size_t size);
char *arena_strdup(arena *a, const char *s);
char *arena_strndup(arena *a, const char *s, size_t n);
void arena_release(arena *a);

/* A growable array of fixed-size elements living in the heap (not the arena). */
typedef struct vecbuf {
	void *data;
	size_t len, cap, elem;
} vecbuf;

void vecbuf_init(vecbuf *v, size_t elem_size);
/* Appends one element copied from elem; returns a pointer to it or NULL on exhaustion. */
void *vecbuf_push(vecbuf *v, const void *elem);
/* Makes room for n more elements (len unchanged); false on overflow/exhaustion. */
bool vecbuf_reserve(vecbuf *v, size_t n);
void vecbuf_free(vecbuf *v);
#define VECBUF_AT(v, type, i) (((type *)(v)->data)[i])

#endif
