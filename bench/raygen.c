/* raygen - writes ray files for bench/raybench: `primary` rays of a pinhole camera framing the
 * mesh, or `incoherent` rays leaving its surface (uniform by area, origins offset off the
 * surface, cosine-distributed directions about the geometric normal). Format: bench/README.md. */
#include "accel/bvh.h"
#include "accel/offset.h"
#include "base/mem.h"
#include "base/rng.h"
#include "obj.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int usage(void)
{
	fprintf(stderr, "usage: raygen MESH.obj primary|incoherent COUNT OUT.bin [--seed N]\n");
	return 2;
}

static void put(FILE *f, vec3 o, vec3 d)
{
	float rec[8] = {o.x, o.y, o.z, d.x, d.y, d.z, 0.0f, INFINITY};
	fwrite(rec, sizeof rec, 1, f);
}

int main(int argc, char **argv)
{
	if (argc < 5)
		return usage();
	const char *mode = argv[2];
	long count = atol(argv[3]);
	uint64_t seed = argc >= 7 && strcmp(argv[5], "--seed") == 0 ? strtoull(argv[6], NULL, 10) : 1;
	bool primary = strcmp(mode, "primary") == 0;
	if ((!primary && strcmp(mode, "incoherent") != 0) || count <= 0)
		return usage();
	bench_mesh m;
	if (!bench_obj_read(argv[1], &m))
		return 1;
	FILE *out = fopen(argv[4], "wb");
	if (!out) {
		fprintf(stderr, "%s: cannot write\n", argv[4]);
		return 1;
	}
	vec3 lo = m.positions[0], hi = lo;
	for (uint32_t v = 1; v < m.num_vertices; v++)
		lo = v3_min(lo, m.positions[v]), hi = v3_max(hi, m.positions[v]);
	rng g;
	rng_seed(&g, seed, 7);
	if (primary) {
		/* A square image looking down -z at the centre, from 2 diagonals away, the bounds
		 * filling 90 % of it; pixels in scanline order (coherent). */
		vec3 mid = v3_scale(v3_add(lo, hi), 0.5f);
		float diag = v3_length(v3_sub(hi, lo));
		vec3 eye = v3_add(mid, v3(0, 0, 2.0f * diag));
		long res = 1;
		while (res * res < count)
			res++;
		float half = 0.5f * diag / 0.9f;
		for (long i = 0; i < count; i++) {
			float px = ((float)(i % res) + rng_float(&g)) / res, py = ((float)(i / res) + rng_float(&g)) / res;
			vec3 target = v3(mid.x + (2 * px - 1) * half, mid.y + (1 - 2 * py) * half, mid.z);
			put(out, eye, v3_normalize(v3_sub(target, eye)));
		}
	} else {
		/* Triangles by area through a cumulative table. */
		double *cdf = mem_alloc(m.num_triangles, sizeof *cdf);
		double acc = 0;
		for (uint32_t f = 0; f < m.num_triangles; f++) {
			const uint32_t *ix = m.indices + 3 * f;
			vec3 a = m.positions[ix[0]];
			acc += 0.5 * v3_length(v3_cross(v3_sub(m.positions[ix[1]], a), v3_sub(m.positions[ix[2]], a)));
			cdf[f] = acc;
		}
		for (long i = 0; i < count;) {
			double x = rng_double(&g) * acc;
			uint32_t a = 0, b = m.num_triangles - 1;
			while (a < b) {
				uint32_t c = (a + b) / 2;
				if (cdf[c] < x)
					a = c + 1;
				else
					b = c;
			}
			const uint32_t *ix = m.indices + 3 * a;
			vec3 v0 = m.positions[ix[0]], v1 = m.positions[ix[1]], v2 = m.positions[ix[2]];
			vec3 n = v3_normalize(v3_cross(v3_sub(v1, v0), v3_sub(v2, v0)));
			if (!(v3_length2(n) > 0.5f))
				continue;
			float u = rng_float(&g), w = rng_float(&g);
			if (u + w > 1)
				u = 1 - u, w = 1 - w;
			vec3 p = v3_add(v0, v3_add(v3_scale(v3_sub(v1, v0), u), v3_scale(v3_sub(v2, v0), w)));
			/* Cosine-distributed about n (Malley's method). */
			float r = sqrtf(rng_float(&g)), phi = 6.2831853f * rng_float(&g);
			vec3 b1, b2;
			v3_basis(n, &b1, &b2);
			vec3 d = v3_add(v3_scale(n, sqrtf(fmaxf(0.0f, 1 - r * r))),
					v3_add(v3_scale(b1, r * cosf(phi)), v3_scale(b2, r * sinf(phi))));
			put(out, bvh_offset_origin(p, n), d);
			i++;
		}
		mem_free(cdf);
	}
	fclose(out);
	bench_mesh_free(&m);
	return 0;
}
