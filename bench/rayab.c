/* rayab - two versions of accel's BVH in one process: `base_*` (another revision's bvh.c, its global
 * symbols renamed by bench/rayab.sh) against this tree's, on the same mesh, rays and circles. For
 * a machine without Embree, or to see a change's own effect: each repeat times both, closest hit,
 * any hit and circles in turn, the version that goes first alternating from repeat to repeat, and
 * the medians of the per-repeat time ratios are printed (base time / new time: > 1 is faster), as
 * one line of `key value` pairs. Hits are compared bit for bit: t, u, v and triangle of every
 * closest hit, every any-hit answer, and every circle's hits in their canonical order. */
#include "config.h"
#include "accel/bvh.h"
#include "base/mem.h"
#include "obj.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

bvh *base_bvh_build(const vec3 *positions, uint32_t num_vertices, const uint32_t *indices, uint32_t num_triangles);
void base_bvh_free(bvh *b);
bool base_bvh_intersect(const bvh *b, const bvh_ray *ray, bvh_hit *hit);
bool base_bvh_occluded(const bvh *b, const bvh_ray *ray);
uint32_t base_bvh_circle(const bvh *b, const tri_circle *q, tri_circle_hit *hits, uint32_t max_hits);
size_t base_bvh_bytes(const bvh *b);
void base_bvh_set_simd(bvh_simd simd);

typedef struct ray_rec {
	float ox, oy, oz, dx, dy, dz, tmin, tmax;
} ray_rec;

static int cmp_double(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return x < y ? -1 : x > y;
}
static double median(double *v, int n)
{
	qsort(v, (size_t)n, sizeof *v, cmp_double);
	return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

static bvh_ray ray_of(const ray_rec *r) { return (bvh_ray){{r->ox, r->oy, r->oz}, {r->dx, r->dy, r->dz}, r->tmin, r->tmax}; }

#define MAX_REPEAT 101
#define MAX_HITS 4096

int main(int argc, char **argv)
{
	if (argc != 6) {
		fprintf(stderr, "usage: rayab MESH.obj RAYS.bin REPEAT CIRCLES LO,HI\n");
		return 2;
	}
	const char *simd = getenv("CIRCE_SIMD");
	bvh_simd path = simd && strcmp(simd, "sse2") == 0 ? BVH_SIMD_SSE2 : BVH_SIMD_AUTO;
	bvh_set_simd(path), base_bvh_set_simd(path);
	int repeat = atoi(argv[3]);
	long nc = atol(argv[4]);
	float rlo, rhi;
	if (repeat < 1 || repeat > MAX_REPEAT || nc < 1 || sscanf(argv[5], "%f,%f", &rlo, &rhi) != 2 || !(rlo > 0.0f) ||
	    !(rhi >= rlo)) {
		fprintf(stderr, "rayab: REPEAT 1 to %d, CIRCLES > 0, radii LO,HI with 0 < LO <= HI\n", MAX_REPEAT);
		return 2;
	}
	bench_mesh m;
	if (!bench_obj_read(argv[1], &m))
		return 1;
	FILE *f = fopen(argv[2], "rb");
	if (!f) {
		fprintf(stderr, "%s: cannot open\n", argv[2]);
		return 1;
	}
	fseek(f, 0, SEEK_END);
	long size = ftell(f);
	fseek(f, 0, SEEK_SET);
	size_t n = size > 0 ? (size_t)size / sizeof(ray_rec) : 0;
	ray_rec *rays = mem_alloc(n, sizeof *rays);
	if (!rays || fread(rays, sizeof *rays, n, f) != n) {
		fprintf(stderr, "%s: cannot read %zu rays\n", argv[2], n);
		return 1;
	}
	fclose(f);
	/* v = 0: base, 1: new. */
	bvh *b[2] = {NULL, NULL};
	double build[2][MAX_REPEAT], t[3][2][MAX_REPEAT];
	for (int k = 0; k < repeat; k++) {
		for (int s = 0; s < 2; s++) {
			int v = (k + s) % 2;
			double t0 = bench_now();
			bvh *x = v ? bvh_build(m.positions, m.num_vertices, m.indices, m.num_triangles)
				   : base_bvh_build(m.positions, m.num_vertices, m.indices, m.num_triangles);
			build[v][k] = bench_now() - t0;
			if (!x) {
				fprintf(stderr, "rayab: a build failed\n");
				return 1;
			}
			if (b[v])
				v ? bvh_free(b[v]) : base_bvh_free(b[v]);
			b[v] = x;
		}
	}
	vec3 lo = m.positions[0], hi = lo;
	for (uint32_t i = 1; i < m.num_vertices; i++)
		lo = v3_min(lo, m.positions[i]), hi = v3_max(hi, m.positions[i]);
	tri_circle *cs = bench_make_circles(&m, nc, v3_length(v3_sub(hi, lo)), rlo, rhi);
	static tri_circle_hit buf[2][MAX_HITS];
	long sink = 0;
	for (int k = 0; k < repeat; k++) {
		for (int s = 0; s < 2; s++) {
			int v = (k + s) % 2;
			double t0 = bench_now();
			for (size_t i = 0; i < n; i++) {
				bvh_ray ray = ray_of(&rays[i]);
				bvh_hit h;
				sink += v ? bvh_intersect(b[v], &ray, &h) : base_bvh_intersect(b[v], &ray, &h);
			}
			double t1 = bench_now();
			for (size_t i = 0; i < n; i++) {
				bvh_ray ray = ray_of(&rays[i]);
				sink += v ? bvh_occluded(b[v], &ray) : base_bvh_occluded(b[v], &ray);
			}
			double t2 = bench_now();
			for (long i = 0; i < nc; i++)
				sink += v ? bvh_circle(b[v], &cs[i], buf[v], MAX_HITS) : base_bvh_circle(b[v], &cs[i], buf[v], MAX_HITS);
			double t3 = bench_now();
			t[0][v][k] = t1 - t0, t[1][v][k] = t2 - t1, t[2][v][k] = t3 - t2;
		}
	}
	long ray_diff = 0, any_diff = 0, circle_diff = 0;
	for (size_t i = 0; i < n; i++) {
		bvh_ray ray = ray_of(&rays[i]);
		bvh_hit h0, h1;
		bool a = base_bvh_intersect(b[0], &ray, &h0), c = bvh_intersect(b[1], &ray, &h1);
		ray_diff += a != c || (a && (h0.prim != h1.prim || memcmp(&h0.t, &h1.t, sizeof h0.t) ||
					     memcmp(&h0.u, &h1.u, sizeof h0.u) || memcmp(&h0.v, &h1.v, sizeof h0.v)));
		any_diff += base_bvh_occluded(b[0], &ray) != bvh_occluded(b[1], &ray);
	}
	for (long i = 0; i < nc; i++) {
		uint32_t x = base_bvh_circle(b[0], &cs[i], buf[0], MAX_HITS), y = bvh_circle(b[1], &cs[i], buf[1], MAX_HITS);
		uint32_t kept = x < MAX_HITS ? x : MAX_HITS;
		circle_diff += x != y || memcmp(buf[0], buf[1], kept * sizeof buf[0][0]) != 0;
	}
	double ratio[4][MAX_REPEAT], cost[2][MAX_REPEAT], best[3][2];
	for (int k = 0; k < repeat; k++) {
		for (int q = 0; q < 3; q++)
			ratio[q][k] = t[q][0][k] / t[q][1][k];
		ratio[3][k] = build[0][k] / build[1][k];
		for (int v = 0; v < 2; v++)
			cost[v][k] = (t[2][v][k] / (double)nc) / (t[0][v][k] / (double)n);
	}
	for (int q = 0; q < 3; q++)
		for (int v = 0; v < 2; v++) {
			best[q][v] = 1e30;
			for (int k = 0; k < repeat; k++)
				best[q][v] = t[q][v][k] < best[q][v] ? t[q][v][k] : best[q][v];
		}
	printf("triangles %u rays %zu circles %ld base_mrays_closest %.3f mrays_closest %.3f base_mrays_any %.3f mrays_any %.3f"
	       " base_mcircles %.4f mcircles %.4f ratio_closest %.3f ratio_any %.3f ratio_circles %.3f ratio_build %.3f"
	       " base_circle_cost_in_rays %.2f circle_cost_in_rays %.2f base_bytes_per_tri %.2f bytes_per_tri %.2f"
	       " closest_differ %ld any_differ %ld circles_differ %ld\n",
	       m.num_triangles, n, nc, n / best[0][0] / 1e6, n / best[0][1] / 1e6, n / best[1][0] / 1e6,
	       n / best[1][1] / 1e6, nc / best[2][0] / 1e6, nc / best[2][1] / 1e6, median(ratio[0], repeat),
	       median(ratio[1], repeat), median(ratio[2], repeat), median(ratio[3], repeat), median(cost[0], repeat),
	       median(cost[1], repeat), (double)base_bvh_bytes(b[0]) / m.num_triangles,
	       (double)bvh_bytes(b[1]) / m.num_triangles, ray_diff, any_diff, circle_diff);
	if (sink == -1)
		printf("\n");
	base_bvh_free(b[0]), bvh_free(b[1]);
	mem_free(cs), mem_free(rays);
	bench_mesh_free(&m);
	return ray_diff || any_diff || circle_diff ? 3 : 0;
}
