/* fuzz_parse: libFuzzer target for the scene parser. The input is split at NUL bytes into the
 * main scene and up to three include files ("a.inc", "b.inc", "c.inc"), all served from memory
 * through the parser's file hook; any other include is "not found". Built by `make fuzz`. */
#include "base/mem.h"
#include "lang/lang.h"

#include <errno.h>
#include <stdint.h>
#include <string.h>

enum { N_FILES = 4 };
static const char *const names[N_FILES] = {"main.pov", "a.inc", "b.inc", "c.inc"};

typedef struct chunks {
	const char *text[N_FILES];
	size_t len[N_FILES];
} chunks;

static int read_chunk(void *user, const char *path, char **text, size_t *len)
{
	const chunks *c = user;
	for (int i = 0; i < N_FILES; i++)
		if (!strcmp(path, names[i]) && c->text[i]) {
			*text = mem_alloc(c->len[i] ? c->len[i] : 1, 1);
			if (!*text)
				return ENOMEM;
			memcpy(*text, c->text[i], c->len[i]);
			*len = c->len[i];
			return 0;
		}
	return ENOENT;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	chunks c = {{0}, {0}};
	const char *p = (const char *)data, *end = p + size;
	for (int i = 0; i < N_FILES && p <= end; i++) {
		const char *z = memchr(p, '\0', (size_t)(end - p));
		c.text[i] = p;
		c.len[i] = (size_t)((z ? z : end) - p);
		if (!z)
			break;
		p = z + 1;
	}
	/* A lower loop bound keeps every input fast; the limit's own error path is still reached. */
	lang_options opt = {.read = read_chunk, .read_user = &c, .max_loop_iterations = 200};
	diag d;
	diag_init(&d, NULL);
	scene *sc = NULL;
	if (lang_parse_file("main.pov", &opt, &d, &sc) == LANG_OK) {
		scene_stats st;
		scene_stats_get(sc, &st);
	}
	scene_free(sc);
	diag_free(&d);
	return 0;
}
