/* raybench - build and trace speed of circe's BVH, single-threaded, optionally against Embree 3.
 * Reads an OBJ and a ray file, prints one line of `key value` pairs (bench/README.md). */
#include "config.h"

#include "accel/bvh.h"
#include "base/mem.h"
#include "obj.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef HAVE_EMBREE
#include <embree3/rtcore.h>
#endif

typedef struct ray_rec {
	float ox, oy, oz, dx, dy, dz, tmin, tmax;
} ray_rec;

static int usage(void)
{
	fprintf(stderr, "usage: raybench MESH.obj RAYS.bin [--circles N] [--circle-radius LO,HI] [--hits OUT.bin] [--embree] [--repeat N]\n");
	return 2;
}

static ray_rec *read_rays(const char *path, size_t *n)
{
	FILE *f = fopen(path, "rb");
	if (!f) {
		fprintf(stderr, "%s: cannot open\n", path);
		return NULL;
	}
	fseek(f, 0, SEEK_END);
	long size = ftell(f);
	fseek(f, 0, SEEK_SET);
	*n = size > 0 ? (size_t)size / sizeof(ray_rec) : 0;
	ray_rec *r = mem_alloc(*n, sizeof *r);
	if (!r || fread(r, sizeof *r, *n, f) != *n) {
		fprintf(stderr, "%s: cannot read %zu rays\n", path, *n);
		mem_free(r), r = NULL;
	}
	fclose(f);
	return r;
}

int main(int argc, char **argv)
{
	const char *mesh_path = NULL, *ray_path = NULL, *hits_path = NULL;
	long circles = 0, repeat = 3;
	float rlo = 1e-3f, rhi = 0.1f;
	bool embree = false;
	/* CIRCE_SIMD=sse2 times the SSE2 path on a CPU with AVX2, as it does for circe (main.c). */
	const char *simd = getenv("CIRCE_SIMD");
	bvh_set_simd(simd && strcmp(simd, "sse2") == 0 ? BVH_SIMD_SSE2 : BVH_SIMD_AUTO);
	for (int i = 1; i < argc; i++) {
		if (strcmp(argv[i], "--circles") == 0 && i + 1 < argc)
			circles = atol(argv[++i]);
		else if (strcmp(argv[i], "--circle-radius") == 0 && i + 1 < argc) {
			if (sscanf(argv[++i], "%f,%f", &rlo, &rhi) != 2 || !(rlo > 0.0f) || !(rhi >= rlo))
				return usage();
		}
		else if (strcmp(argv[i], "--hits") == 0 && i + 1 < argc)
			hits_path = argv[++i];
		else if (strcmp(argv[i], "--repeat") == 0 && i + 1 < argc)
			repeat = atol(argv[++i]);
		else if (strcmp(argv[i], "--embree") == 0)
			embree = true;
		else if (!mesh_path)
			mesh_path = argv[i];
		else if (!ray_path)
			ray_path = argv[i];
		else
			return usage();
	}
	if (!mesh_path || !ray_path || repeat < 1)
		return usage();
#ifndef HAVE_EMBREE
	if (embree) {
		fprintf(stderr, "raybench: built without Embree (configure did not find embree3)\n");
		return 2;
	}
#endif
	bench_mesh m;
	if (!bench_obj_read(mesh_path, &m))
		return 1;
	size_t nrays;
	ray_rec *rays = read_rays(ray_path, &nrays);
	if (!rays)
		return 1;

	/* Build: the best of `repeat` builds. */
	bvh *b = NULL;
	double build_s = 1e30;
	for (long k = 0; k < repeat; k++) {
		bvh_free(b);
		double t0 = bench_now();
		b = bvh_build(m.positions, m.num_vertices, m.indices, m.num_triangles);
		double t1 = bench_now();
		if (!b) {
			fprintf(stderr, "raybench: the build failed (memory or indices)\n");
			return 1;
		}
		build_s = t1 - t0 < build_s ? t1 - t0 : build_s;
	}
	float *hit_t = mem_alloc(nrays, sizeof *hit_t);
	uint32_t *hit_prim = mem_alloc(nrays, sizeof *hit_prim);
	double closest_s = 1e30, any_s = 1e30;
	long occluded = 0;
	for (long k = 0; k < repeat; k++) {
		double t0 = bench_now();
		for (size_t i = 0; i < nrays; i++) {
			const ray_rec *r = &rays[i];
			bvh_ray ray = {{r->ox, r->oy, r->oz}, {r->dx, r->dy, r->dz}, r->tmin, r->tmax};
			bvh_hit h;
			bool hit = bvh_intersect(b, &ray, &h);
			hit_t[i] = hit ? h.t : INFINITY;
			hit_prim[i] = hit ? h.prim : UINT32_MAX;
		}
		double t1 = bench_now();
		occluded = 0;
		for (size_t i = 0; i < nrays; i++) {
			const ray_rec *r = &rays[i];
			bvh_ray ray = {{r->ox, r->oy, r->oz}, {r->dx, r->dy, r->dz}, r->tmin, r->tmax};
			occluded += bvh_occluded(b, &ray);
		}
		double t2 = bench_now();
		closest_s = t1 - t0 < closest_s ? t1 - t0 : closest_s;
		any_s = t2 - t1 < any_s ? t2 - t1 : any_s;
	}
	printf("triangles %u rays %zu build_ms %.3f mtri_per_s %.3f bytes_per_tri %.2f mrays_closest %.3f mrays_any %.3f",
	       m.num_triangles, nrays, build_s * 1e3, m.num_triangles / build_s / 1e6,
	       (double)bvh_bytes(b) / m.num_triangles, nrays / closest_s / 1e6, nrays / any_s / 1e6);
	if (circles > 0) {
		vec3 lo = m.positions[0], hi = lo;
		for (uint32_t v = 1; v < m.num_vertices; v++)
			lo = v3_min(lo, m.positions[v]), hi = v3_max(hi, m.positions[v]);
		tri_circle *cs = bench_make_circles(&m, circles, v3_length(v3_sub(hi, lo)), rlo, rhi);
		static tri_circle_hit buf[4096];
		double best = 1e30;
		long total = 0;
		for (long k = 0; k < repeat; k++) {
			total = 0;
			double t0 = bench_now();
			for (long i = 0; i < circles; i++)
				total += bvh_circle(b, &cs[i], buf, 4096);
			double t1 = bench_now();
			best = t1 - t0 < best ? t1 - t0 : best;
		}
		double mc = circles / best / 1e6;
		printf(" mcircles %.3f circle_hits_mean %.2f circle_cost_in_rays %.2f", mc, (double)total / circles,
		       (nrays / closest_s / 1e6) / mc);
		mem_free(cs);
	}
	if (hits_path) {
		FILE *f = fopen(hits_path, "wb");
		for (size_t i = 0; f && i < nrays; i++) {
			fwrite(&hit_t[i], sizeof(float), 1, f);
			fwrite(&hit_prim[i], sizeof(uint32_t), 1, f);
		}
		if (!f || fclose(f) != 0) {
			fprintf(stderr, "%s: cannot write\n", hits_path);
			return 1;
		}
	}
#ifdef HAVE_EMBREE
	if (embree) {
		/* CIRCE_EMBREE_ISA=avx2 (or sse2, avx, avx512) pins Embree's kernels: on a CPU with
		 * AVX-512 Embree runs its AVX-512 ones, circe at most AVX2. */
		const char *isa = getenv("CIRCE_EMBREE_ISA");
		if (isa && (!*isa || strlen(isa) > 16))
			isa = NULL;
		char config[64];
		snprintf(config, sizeof config, "threads=1%s%s", isa ? ",isa=" : "", isa ? isa : "");
		RTCDevice dev = rtcNewDevice(config);
		double ebuild = 1e30;
		RTCScene scene = NULL;
		for (long k = 0; k < repeat; k++) {
			if (scene)
				rtcReleaseScene(scene);
			double t0 = bench_now();
			scene = rtcNewScene(dev);
			RTCGeometry geom = rtcNewGeometry(dev, RTC_GEOMETRY_TYPE_TRIANGLE);
			float *vb = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float),
							    m.num_vertices);
			memcpy(vb, m.positions, m.num_vertices * sizeof(vec3));
			unsigned *ib = rtcSetNewGeometryBuffer(geom, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned),
							       m.num_triangles);
			memcpy(ib, m.indices, m.num_triangles * 3 * sizeof(unsigned));
			rtcCommitGeometry(geom);
			rtcAttachGeometry(scene, geom);
			rtcReleaseGeometry(geom);
			rtcCommitScene(scene);
			double t1 = bench_now();
			ebuild = t1 - t0 < ebuild ? t1 - t0 : ebuild;
		}
		double eclosest = 1e30, eany = 1e30;
		long agree = 0, eocc = 0;
		for (long k = 0; k < repeat; k++) {
			agree = 0, eocc = 0;
			struct RTCIntersectContext ctx;
			rtcInitIntersectContext(&ctx);
			double t0 = bench_now();
			for (size_t i = 0; i < nrays; i++) {
				const ray_rec *r = &rays[i];
				struct RTCRayHit rh;
				rh.ray.org_x = r->ox, rh.ray.org_y = r->oy, rh.ray.org_z = r->oz;
				rh.ray.dir_x = r->dx, rh.ray.dir_y = r->dy, rh.ray.dir_z = r->dz;
				rh.ray.tnear = r->tmin, rh.ray.tfar = r->tmax, rh.ray.time = 0, rh.ray.mask = 0xffffffffu;
				rh.ray.id = 0, rh.ray.flags = 0;
				rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
				rtcIntersect1(scene, &ctx, &rh);
				bool eh = rh.hit.geomID != RTC_INVALID_GEOMETRY_ID;
				bool oh = hit_prim[i] != UINT32_MAX;
				agree += eh == oh && (!eh || rh.hit.primID == hit_prim[i] ||
						      fabsf(rh.ray.tfar - hit_t[i]) <= 1e-4f * fabsf(hit_t[i]));
			}
			double t1 = bench_now();
			for (size_t i = 0; i < nrays; i++) {
				const ray_rec *r = &rays[i];
				struct RTCRay ray;
				ray.org_x = r->ox, ray.org_y = r->oy, ray.org_z = r->oz;
				ray.dir_x = r->dx, ray.dir_y = r->dy, ray.dir_z = r->dz;
				ray.tnear = r->tmin, ray.tfar = r->tmax, ray.time = 0, ray.mask = 0xffffffffu, ray.id = 0, ray.flags = 0;
				rtcOccluded1(scene, &ctx, &ray);
				eocc += ray.tfar < 0.0f;
			}
			double t2 = bench_now();
			eclosest = t1 - t0 < eclosest ? t1 - t0 : eclosest;
			eany = t2 - t1 < eany ? t2 - t1 : eany;
		}
		printf(" embree_build_ms %.3f embree_mrays_closest %.3f embree_mrays_any %.3f hits_agree %.5f occluded_agree %.5f"
		       " ratio_build %.3f ratio_closest %.3f ratio_any %.3f",
		       ebuild * 1e3, nrays / eclosest / 1e6, nrays / eany / 1e6, (double)agree / nrays,
		       1.0 - fabs((double)(eocc - occluded)) / nrays, ebuild / build_s, eclosest / closest_s, eany / any_s);
		rtcReleaseScene(scene);
		rtcReleaseDevice(dev);
	}
#endif
	printf("\n");
	bvh_free(b);
	mem_free(hit_t), mem_free(hit_prim), mem_free(rays);
	bench_mesh_free(&m);
	return 0;
}
