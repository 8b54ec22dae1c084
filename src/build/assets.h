/* assets.h - the files a scene names (images, meshes, cages), opened before the build: a missing,
 * unreadable or non-regular one, or an image whose first bytes are no known format, is a scene
 * error at the string that names it. `check` and `render` both go through here, so they say the
 * same thing; the files' contents are read later by their importers. */
#ifndef CIRCE_BUILD_ASSETS_H
#define CIRCE_BUILD_ASSETS_H

#include "base/diag.h"
#include "scene/scene.h"

#include <stdbool.h>

/* Opens every file in sc->assets and reads its first bytes; false after reporting each bad one to d. */
bool assets_open(const scene *sc, diag *d);

#endif
