/* fuzz_mesh: libFuzzer target for mesh files as `mesh { file }` reads them. Each input is written
 * to a temporary file and imported by mesh_import, the function the renderer calls (the checks
 * before Assimp, Assimp itself, the checks after it, duplicates removed), then freed. The file's
 * extension follows its first bytes, as real files would be named: "ply" -> .ply, "glTF" -> .glb,
 * '{' -> .gltf, anything else -> .obj; so mutations move between the formats. Diagnostics are
 * counted, not printed. Built by `make fuzz-mesh`. */
#include "geom/mesh.h"

#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[] = "/tmp/circe-fuzz-mesh-XXXXXX";

/* The folder goes with the process (libFuzzer's -fork mode starts one every few seconds). */
static void remove_dir(void)
{
	rmdir(dir);
}

static const char *extension(const uint8_t *data, size_t size)
{
	if (size >= 3 && !memcmp(data, "ply", 3))
		return "ply";
	if (size >= 4 && !memcmp(data, "glTF", 4))
		return "glb";
	if (size >= 1 && data[0] == '{')
		return "gltf";
	return "obj";
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static bool ready;
	if (!ready) {
		if (!mkdtemp(dir))
			abort();
		atexit(remove_dir);
		ready = true;
	}
	char path[sizeof dir + 16];
	snprintf(path, sizeof path, "%s/in.%s", dir, extension(data, size));
	FILE *f = fopen(path, "wb");
	if (!f || (size && fwrite(data, 1, size, f) != size) || fclose(f) != 0)
		abort();
	diag d;
	diag_init(&d, NULL);
	mesh m;
	if (mesh_import(path, &m, &d))
		mesh_free(&m);
	diag_free(&d);
	unlink(path);
	return 0;
}
