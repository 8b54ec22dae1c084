/* mem.c - checked allocation, the scene arena and growable arrays. */
#include "base/mem.h"

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

void *mem_alloc(size_t count, size_t size)
{
	size_t n;
	if (!mem_mul_ok(count, size, &n) || should_fail())
		return NULL;
	return malloc(n ? n : 1);
}

void *mem_calloc(size_t count, size_t size)
{
	size_t n;
	if (!mem_mul_ok(count, size, &n) || should_fail())
		return NULL;
	return calloc(n ? n : 1, 1);
}

void *mem_realloc(void *p, size_t count, size_t size)
{
	size_t n;
	if (!mem_mul_ok(count, size, &n) || should_fail())
		return NULL;
	return realloc(p, n ? n : 1);
}

void mem_free(void *p) { free(p); }

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
