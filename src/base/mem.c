/* mem.c - checked allocation, the scene arena and growable arrays. */
#include "base/mem.h"

#include <assert.h>
#include <stdalign.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

static long fail_countdown = -1;

void mem_fail_after(long n) { fail_countdown = n; }

static bool should_fail(void)
{
	if (fail_countdown < 0)
		return false;
	if (fail_countdown == 0)
		return true;
	fail_countdown--;
	return false;
}

bool mem_mul_ok(size_t a, size_t b, size_t *out)
{
	if (b != 0 && a > SIZE_MAX / b)
		return false;
	*out = a * b;
	return true;
}

/* Every block carries its size in a header as wide as malloc's alignment, so that the block after
 * it keeps that alignment and mem_free knows what it gives back. */
#define MEM_HEADER ((size_t)alignof(max_align_t))

static size_t limit_bytes; /* 0: none */
static atomic_size_t live_bytes, peak_bytes, refused_bytes, refused_live;

void mem_set_limit(size_t bytes) { limit_bytes = bytes; }
size_t mem_limit(void) { return limit_bytes; }
size_t mem_live_bytes(void) { return atomic_load(&live_bytes); }
size_t mem_peak_bytes(void) { return atomic_load(&peak_bytes); }

bool mem_limit_hit(size_t *asked, size_t *live)
{
	size_t n = atomic_load(&refused_bytes);
	if (asked)
		*asked = n;
	if (live)
		*live = atomic_load(&refused_live);
	return n > 0;
}

/* Counts n more bytes live; false (nothing counted) when that would pass the limit. */
static bool take(size_t n)
{
	size_t now = atomic_fetch_add(&live_bytes, n) + n;
	if (limit_bytes && (now > limit_bytes || now < n)) {
		atomic_store(&refused_live, atomic_fetch_sub(&live_bytes, n) - n);
		atomic_store(&refused_bytes, n ? n : 1);
		return false;
	}
	size_t peak = atomic_load(&peak_bytes);
	while (now > peak && !atomic_compare_exchange_weak(&peak_bytes, &peak, now))
		;
	return true;
}

static void give(size_t n)
{
	size_t before = atomic_fetch_sub(&live_bytes, n);
	assert(before >= n); /* only bytes taken are given back */
	(void)before;
}

/* The user's block of a header, the size it records. */
static void *block_of(void *h, size_t n)
{
	memcpy(h, &n, sizeof n);
	return (unsigned char *)h + MEM_HEADER;
}

static void *header_of(void *p) { return (unsigned char *)p - MEM_HEADER; }

static size_t size_of(void *p)
{
	size_t n;
	memcpy(&n, header_of(p), sizeof n);
	return n;
}

/* The bytes of count * size, at least one, with room for the header; false on overflow. */
static bool request(size_t count, size_t size, size_t *n)
{
	if (!mem_mul_ok(count, size, n) || *n > SIZE_MAX - MEM_HEADER)
		return false;
	if (*n == 0)
		*n = 1;
	return true;
}

void *mem_alloc(size_t count, size_t size)
{
	size_t n;
	if (!request(count, size, &n) || should_fail() || !take(n))
		return NULL;
	void *h = malloc(MEM_HEADER + n);
	if (!h) {
		give(n);
		return NULL;
	}
	return block_of(h, n);
}

void *mem_calloc(size_t count, size_t size)
{
	size_t n;
	if (!request(count, size, &n) || should_fail() || !take(n))
		return NULL;
	void *h = calloc(MEM_HEADER + n, 1);
	if (!h) {
		give(n);
		return NULL;
	}
	return block_of(h, n);
}

void *mem_realloc(void *p, size_t count, size_t size)
{
	if (!p)
		return mem_alloc(count, size);
	size_t n, old = size_of(p);
	if (!request(count, size, &n) || should_fail())
		return NULL;
	if (n > old && !take(n - old))
		return NULL;
	void *h = realloc(header_of(p), MEM_HEADER + n);
	if (!h) {
		if (n > old)
			give(n - old);
		return NULL;
	}
	if (n < old)
		give(old - n);
	return block_of(h, n);
}

void mem_free(void *p)
{
	if (!p)
		return;
	give(size_of(p));
	free(header_of(p));
}

char *mem_strdup(const char *s)
{
	size_t n = strlen(s) + 1;
	char *r = mem_alloc(n, 1);
	if (r)
		memcpy(r, s, n);
	return r;
}

struct arena_block {
	arena_block *next;
	size_t used, size;
	unsigned char data[];
};

#define ARENA_DEFAULT_BLOCK (64u * 1024u)

void arena_init(arena *a, size_t block_size)
{
	a->head = NULL;
	a->block_size = block_size ? block_size : ARENA_DEFAULT_BLOCK;
	a->total = 0;
}

/* Offset from b->data + used to the next address aligned to align. */
static size_t align_pad(const arena_block *b, size_t align)
{
	uintptr_t at = (uintptr_t)(b->data + b->used);
	return (size_t)((align - (at & (align - 1))) & (align - 1));
}

void *arena_alloc(arena *a, size_t count, size_t size, size_t align)
{
	size_t n;
	if (!mem_mul_ok(count, size, &n) || align == 0 || align > 64 || (align & (align - 1)))
		return NULL;
	arena_block *b = a->head;
	if (b) {
		size_t pad = align_pad(b, align);
		if (pad <= b->size - b->used && n <= b->size - b->used - pad) {
			void *r = b->data + b->used + pad;
			b->used += pad + n;
			assert(b->used <= b->size);
			a->total += n;
			return r;
		}
	}
	size_t cap = n > a->block_size ? n : a->block_size;
	if (cap > SIZE_MAX - sizeof(arena_block) - 64)
		return NULL;
	cap += 64; /* room to align the first allocation whatever malloc returned */
	arena_block *nb = mem_alloc(1, sizeof(arena_block) + cap);
	if (!nb)
		return NULL;
	nb->size = cap;
	nb->used = 0;
	nb->used = align_pad(nb, align);
	void *r = nb->data + nb->used;
	nb->used += n;
	/* A block of its own for a large request keeps the current block open for small ones. */
	if (b && n > a->block_size) {
		nb->next = b->next;
		b->next = nb;
	} else {
		nb->next = b;
		a->head = nb;
	}
	a->total += n;
	return r;
}

void *arena_zalloc(arena *a, size_t count, size_t size)
{
	void *p = arena_alloc(a, count, size, 16);
	if (p)
		memset(p, 0, count * size);
	return p;
}

char *arena_strndup(arena *a, const char *s, size_t n)
{
	char *r = arena_alloc(a, n + 1, 1, 1);
	if (r) {
		memcpy(r, s, n);
		r[n] = '\0';
	}
	return r;
}

char *arena_strdup(arena *a, const char *s) { return arena_strndup(a, s, strlen(s)); }

void arena_release(arena *a)
{
	arena_block *b = a->head;
	while (b) {
		arena_block *next = b->next;
		mem_free(b);
		b = next;
	}
	a->head = NULL;
	a->total = 0;
}

void vecbuf_init(vecbuf *v, size_t elem_size)
{
	v->data = NULL;
	v->len = v->cap = 0;
	v->elem = elem_size;
}

bool vecbuf_reserve(vecbuf *v, size_t n)
{
	assert(v->elem > 0 && v->len <= v->cap);
	if (n > SIZE_MAX - v->len)
		return false;
	size_t need = v->len + n;
	if (need <= v->cap)
		return true;
	size_t cap = v->cap ? v->cap : 16;
	while (cap < need)
		cap = cap > SIZE_MAX / 2 ? need : cap * 2;
	void *d = mem_realloc(v->data, cap, v->elem);
	if (!d)
		return false;
	v->data = d;
	v->cap = cap;
	return true;
}

void *vecbuf_push(vecbuf *v, const void *elem)
{
	if (!vecbuf_reserve(v, 1))
		return NULL;
	void *dst = (unsigned char *)v->data + v->len * v->elem;
	memcpy(dst, elem, v->elem);
	v->len++;
	return dst;
}

void vecbuf_free(vecbuf *v)
{
	mem_free(v->data);
	v->data = NULL;
	v->len = v->cap = 0;
}
