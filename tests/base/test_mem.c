/* test_mem: overflow-checked allocation, injected failures, the arena's alignment and growth. */
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
