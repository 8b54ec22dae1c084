/* cage.h - a reader of the OpenSubdiv test shapes (OBJ with `t crease` and `t corner` tags) into a
 * subd_cage, for the tests only; circe's scenes reach cages through the scene language. */
#ifndef CIRCE_TESTS_GEOM_CAGE_H
#define CIRCE_TESTS_GEOM_CAGE_H

#include "geom/subdiv.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct test_cage {
	subd_cage c;
	vec3 pos[4096];
	vec2 uv[4096];
	uint32_t sizes[4096], idx[16384], uvidx[16384], creases[2048], corners[512];
	float crease_s[1024], corner_s[512];
} test_cage;

/* Reads path into a heap-allocated test_cage (free with free()); NULL when unreadable. */
static inline test_cage *cage_read(const char *path)
{
	FILE *f = fopen(path, "r");
	if (!f)
		return NULL;
	test_cage *t = calloc(1, sizeof *t);
	subd_cage *c = &t->c;
	c->positions = t->pos, c->face_sizes = t->sizes, c->face_indices = t->idx;
	c->crease_vertices = t->creases, c->crease_sharpness = t->crease_s;
	c->corner_vertices = t->corners, c->corner_sharpness = t->corner_s;
	size_t nidx = 0;
	char line[1024];
	while (fgets(line, sizeof line, f)) {
		float x, y, z;
		if (sscanf(line, "v %f %f %f", &x, &y, &z) == 3) {
			t->pos[c->num_vertices++] = v3(x, y, z);
		} else if (sscanf(line, "vt %f %f", &x, &y) == 2) {
			t->uv[c->num_uvs++] = v2(x, y);
		} else if (line[0] == 'f' && line[1] == ' ') {
			uint32_t n = 0;
			char *p = line + 2, *end;
			for (;;) {
				long v = strtol(p, &end, 10);
				if (end == p)
					break;
				t->idx[nidx + n] = (uint32_t)(v - 1);
				t->uvidx[nidx + n] = 0;
				p = end;
				if (*p == '/') {
					long vt = strtol(p + 1, &end, 10);
					if (end != p + 1)
						t->uvidx[nidx + n] = (uint32_t)(vt - 1);
					p = end;
					while (*p && *p != ' ' && *p != '\n')
						p++;
				}
				n++;
			}
			t->sizes[c->num_faces++] = n;
			nidx += n;
		} else if (strncmp(line, "t crease", 8) == 0) {
			int a, b;
			float s;
			if (sscanf(line, "t crease %*s %d %d %f", &a, &b, &s) == 3) {
				t->creases[2 * c->num_creases] = (uint32_t)a, t->creases[2 * c->num_creases + 1] = (uint32_t)b;
				t->crease_s[c->num_creases++] = s;
			}
		} else if (strncmp(line, "t corner", 8) == 0) {
			int a;
			float s;
			if (sscanf(line, "t corner %*s %d %f", &a, &s) == 2) {
				t->corners[c->num_corners] = (uint32_t)a;
				t->corner_s[c->num_corners++] = s;
			}
		}
	}
	fclose(f);
	if (c->num_uvs) {
		c->uvs = t->uv;
		c->uv_indices = t->uvidx;
	}
	return t;
}

#endif
