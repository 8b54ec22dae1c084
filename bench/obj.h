/* obj.h - the benchmark's own OBJ reader: `v` and `f` lines only, faces kept in file order and
 * polygons fanned into triangles in order (v0 v1 v2, v0 v2 v3, ...), so triangle ids are stable
 * across tools (bench/README.md). The renderer reads meshes through geom's Assimp importer. */
#ifndef CIRCE_BENCH_OBJ_H
#define CIRCE_BENCH_OBJ_H

#include "accel/tri.h"
#include "base/vec.h"

#include <stdbool.h>
#include <stdint.h>

typedef struct bench_mesh {
	vec3 *positions;
	uint32_t num_vertices;
	uint32_t *indices;
	uint32_t num_triangles;
} bench_mesh;

/* False (with a message on stderr) when the file cannot be read or an index is out of range. */
bool bench_obj_read(const char *path, bench_mesh *m);
void bench_mesh_free(bench_mesh *m);

/* CPU seconds used by the process (all its threads): timings stay fair on a shared, loaded
 * machine, where wall-clock time would count other processes' turns. */
double bench_now(void);

/* Circles as circle tracing makes them: centre uniform on a random triangle, n its normal, t
 * random in the tangent plane, radius log-uniform between rlo and rhi times diag; seeded, so every
 * benchmark (raybench, rayab) gets the same n circles of a mesh. NULL when out of memory. */
tri_circle *bench_make_circles(const bench_mesh *m, long n, float diag, float rlo, float rhi);

#endif
