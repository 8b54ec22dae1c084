/* gamma.c - POV-Ray's assumed_gamma (doc/language.md, "assumed_gamma"). POV-Ray 3.7 computes in
 * a "working" colour space of gamma G: the scene's colour numbers are used as written, lights add
 * and pigments multiply in that space, and the result r is written as the light r^G
 * (frontend/renderfrontend.h CreateView: a transcoding curve from the working gamma to the
 * file's). Images are decoded by their file's gamma and re-encoded into the working space,
 * linear^(1/G) (parser/parstxtr.cpp Parse_Image), and so are srgb colours (express.cpp). circe
 * does the same: it renders the numbers as written, image texels read as colour are raised to
 * 1/G (build/build_material.c world_image), and the beauty pass is written as r^G
 * (render/output.c). Under G = 1, circe's own scenes, nothing changes. */
#include "scene/scene.h"

double scene_working_gamma(const scene_global *g, double version)
{
	if (g->assumed_gamma_set)
		return g->assumed_gamma;
	return version < 3.7 ? SCENE_LEGACY_GAMMA : 1.0;
}
