/* test_mem: overflow-checked allocation, injected failures, the limit on the bytes live
 * (--max-memory), the arena's alignment and growth. */
#include "base/mem.h"
#include "check.h"

#include <stdint.h>
#include <string.h>

int main(void)
{
	CHECK(mem_alloc(SIZE_MAX / 2, 3) == NULL, "overflowing count * size is refused");
	CHECK(mem_realloc(NULL, SIZE_MAX, 2) == NULL, "overflowing realloc is refused");
	void *p = mem_alloc(0, 8);
	CHECK(p != NULL, "zero-size allocation gives a pointer");
	mem_free(p);

	mem_fail_after(2);
	void *a = mem_alloc(1, 1), *b = mem_alloc(1, 1), *c = mem_alloc(1, 1);
	CHECK(a && b && !c, "the third allocation fails (%p %p %p)", a, b, c);
	mem_fail_after(-1);
	mem_free(a), mem_free(b);

	/* The limit: what would pass it is refused before allocating, and says so; a failed realloc
	 * keeps the block; frees give the bytes back. */
	size_t base = mem_live_bytes();
	CHECK(!mem_limit_hit(NULL, NULL), "no refusal yet");
	mem_set_limit(base + 1000);
	void *big = mem_alloc(2000, 1);
	size_t asked = 0, live = 1;
	CHECK(!big && mem_limit_hit(&asked, &live) && asked == 2000 && live == base,
	      "2000 bytes over a limit of 1000 more: %p, asked %zu with %zu live", big, asked, live - base);
	unsigned char *m = mem_calloc(600, 1);
	CHECK(m && m[599] == 0 && mem_live_bytes() == base + 600, "600 bytes fit: live %zu", mem_live_bytes() - base);
	CHECK(!mem_alloc(500, 1), "600 + 500 pass the limit");
	m[0] = 7;
	CHECK(!mem_realloc(m, 1500, 1) && m[0] == 7, "a realloc past the limit fails and keeps the block");
	unsigned char *m2 = mem_realloc(m, 900, 1);
	CHECK(m2 && m2[0] == 7 && mem_live_bytes() == base + 900, "a realloc within it: live %zu",
	      mem_live_bytes() - base);
	m2 = mem_realloc(m2, 100, 1);
	CHECK(m2 && mem_live_bytes() == base + 100, "a shrinking realloc gives back: live %zu", mem_live_bytes() - base);
	mem_free(m2);
	CHECK(mem_live_bytes() == base && mem_peak_bytes() >= base + 900, "all given back: live %zu, peak %zu",
	      mem_live_bytes() - base, mem_peak_bytes() - base);
	mem_set_limit(0);
	big = mem_alloc(2000, 1);
	CHECK(big != NULL, "no limit");
	mem_free(big);

	arena ar;
	arena_init(&ar, 256);
	for (size_t align = 1; align <= 64; align *= 2) {
		unsigned char *q = arena_alloc(&ar, 3, 1, align);
		CHECK(q && ((uintptr_t)q % align) == 0, "alignment %zu gives %p", align, (void *)q);
	}
	/* Many small and a few large allocations keep their contents. */
	char *strs[500];
	for (int i = 0; i < 500; i++) {
		char buf[32];
		snprintf(buf, sizeof buf, "string %d", i);
		strs[i] = arena_strdup(&ar, buf);
		if (i % 100 == 0)
			CHECK(arena_zalloc(&ar, 1000, 8) != NULL, "large block");
	}
	for (int i = 0; i < 500; i++) {
		char buf[32];
		snprintf(buf, sizeof buf, "string %d", i);
		CHECK(strcmp(strs[i], buf) == 0, "arena string %d is '%s'", i, strs[i]);
	}
	CHECK(arena_alloc(&ar, SIZE_MAX, 2, 8) == NULL, "arena refuses overflow");
	CHECK(arena_alloc(&ar, 1, 1, 3) == NULL, "arena refuses a non-power-of-two alignment");
	arena_release(&ar);

	vecbuf v;
	vecbuf_init(&v, sizeof(int));
	for (int i = 0; i < 10000; i++)
		CHECK(vecbuf_push(&v, &i) != NULL, "push %d", i);
	CHECK(v.len == 10000 && VECBUF_AT(&v, int, 9999) == 9999, "vecbuf holds its elements");
	vecbuf_free(&v);
	return check_done("test_mem");
}
