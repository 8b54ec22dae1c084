/* obj.h - the benchmark's own OBJ reader: `v` and `f` lines only, faces kept in file order and
 * polygons fanned into triangles in order (v0 v1 v2, v0 v2 v3, ...), so triangle ids are stable
 * across tools (bench/README.md). The renderer reads meshes through geom's Assimp importer. */
#ifndef CIRCE_BENCH_OBJ_H
#define CIRCE_BENCH_OBJ_H

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

#endif
