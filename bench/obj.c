/* obj.c - a minimal OBJ reader for the benchmarks, and a clock. */
#include "obj.h"

#include "base/mem.h"
#include "base/rng.h"

#include <math.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

double bench_now(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
	return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

bool bench_obj_read(const char *path, bench_mesh *m)
{
	memset(m, 0, sizeof *m);
	FILE *f = fopen(path, "r");
	if (!f) {
		fprintf(stderr, "%s: cannot open\n", path);
		return false;
	}
	vecbuf pos, idx;
	vecbuf_init(&pos, sizeof(vec3));
	vecbuf_init(&idx, sizeof(uint32_t));
	char line[4096];
	bool ok = true;
	long lineno = 0;
	while (ok && fgets(line, sizeof line, f)) {
		lineno++;
		if (line[0] == 'v' && line[1] == ' ') {
			vec3 p;
			if (sscanf(line + 2, "%f %f %f", &p.x, &p.y, &p.z) == 3)
				ok = vecbuf_push(&pos, &p) != NULL;
		} else if (line[0] == 'f' && line[1] == ' ') {
			uint32_t first = 0, prev = 0;
			int n = 0;
			char *p = line + 2, *end;
			for (;;) {
				long v = strtol(p, &end, 10);
				if (end == p)
					break;
				p = end;
				while (*p && *p != ' ' && *p != '\t' && *p != '\n' && *p != '\r')
					p++;
				long nv = (long)pos.len;
				long i = v < 0 ? nv + v : v - 1;
				if (i < 0 || i >= nv) {
					fprintf(stderr, "%s:%ld: vertex index %ld out of range\n", path, lineno, v);
					ok = false;
					break;
				}
				uint32_t u = (uint32_t)i;
				if (n == 0)
					first = u;
				else if (n >= 2) {
					uint32_t tri[3] = {first, prev, u};
					for (int k = 0; k < 3; k++)
						ok = ok && vecbuf_push(&idx, &tri[k]) != NULL;
				}
				prev = u;
				n++;
			}
		}
	}
	fclose(f);
	if (!ok) {
		vecbuf_free(&pos), vecbuf_free(&idx);
		return false;
	}
	m->positions = pos.data, m->num_vertices = (uint32_t)pos.len;
	m->indices = idx.data, m->num_triangles = (uint32_t)(idx.len / 3);
	return true;
}

void bench_mesh_free(bench_mesh *m)
{
	mem_free(m->positions), mem_free(m->indices);
	memset(m, 0, sizeof *m);
}

/* Circles as circle tracing makes them: centre uniform on a random triangle, n its normal, t
 * random in the tangent plane, radius log-uniform between rlo and rhi times the diagonal, half. */
tri_circle *bench_make_circles(const bench_mesh *m, long n, float diag, float rlo, float rhi)
{
	tri_circle *c = mem_alloc((size_t)n, sizeof *c);
	rng g;
	rng_seed(&g, 42, 42);
	for (long i = 0; c && i < n;) {
		const uint32_t *ix = m->indices + 3 * rng_below(&g, m->num_triangles);
		vec3 v0 = m->positions[ix[0]], v1 = m->positions[ix[1]], v2 = m->positions[ix[2]];
		vec3 nn = v3_normalize(v3_cross(v3_sub(v1, v0), v3_sub(v2, v0)));
		if (!(v3_length2(nn) > 0.5f))
			continue;
		float a = rng_float(&g), b = rng_float(&g);
		if (a + b > 1)
			a = 1 - a, b = 1 - b;
		vec3 b1, b2;
		v3_basis(nn, &b1, &b2);
		float phi = 6.2831853f * rng_float(&g);
		c[i].centre = v3_add(v0, v3_add(v3_scale(v3_sub(v1, v0), a), v3_scale(v3_sub(v2, v0), b)));
		c[i].t = v3_normalize(v3_add(v3_scale(b1, cosf(phi)), v3_scale(b2, sinf(phi))));
		c[i].n = nn;
		c[i].radius = diag * rlo * powf(rhi / rlo, rng_float(&g));
		c[i].full = false;
		i++;
	}
	return c;
}
