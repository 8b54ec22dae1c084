/* walk.h - the volumetric reference of `--sss volume` (DESIGN.md, "The two comparators"): a random
 * walk inside a closed mesh with scattering sigma_s, absorption sigma_a, a Henyey-Greenstein phase
 * and a smooth dielectric boundary, with one-sample MIS over the RGB channels for the free paths.
 * Also the check that a mesh is closed (an open mesh cannot hold a volume). Formulas and sources:
 * src/sss/README.md, "The volume random walk". Thread-safe; the walk allocates nothing. */
#ifndef CIRCE_SSS_WALK_H
#define CIRCE_SSS_WALK_H

#include "base/rng.h"
#include "base/vec.h"
#include "geom/mesh.h"
#include "sss/probe.h"

#include <stdbool.h>
#include <stdint.h>

/* The medium, in scene units (the caller converts from mm: sss_walk_medium_from_reduced). */
typedef struct sss_walk_medium {
	double sigma_s[3]; /* scattering coefficient per channel, per scene unit, >= 0 */
	double sigma_a[3]; /* absorption coefficient per channel, per scene unit, >= 0 */
	double g;	   /* Henyey-Greenstein anisotropy (mean cosine), in (-1, 1) */
	double eta;	   /* index of refraction of the medium over that outside, > 0; 1: index-matched */
	bool classic;	   /* false (the default): Dwivedi-guided free paths and directions mixed with
			    * the classic ones by one-sample MIS (README.md, "Guided sampling"); true:
			    * the classic walk alone (analog free paths, the phase function), for
			    * comparison */
} sss_walk_medium;

/* The medium of a material given in the physical form (src/scene: sigma_s' and sigma_a per mm,
 * HG g, ior): sigma_s = sigma_s' / (1 - g) by the similarity relation (sigma_s' = sigma_s (1 - g),
 * e.g. Jensen et al. 2001, section 2.1), each coefficient multiplied by mm_per_unit (> 0) to
 * become per scene unit. False (and *m untouched) for negative or non-finite coefficients,
 * |g| >= 1, eta <= 0 or mm_per_unit <= 0. */
bool sss_walk_medium_from_reduced(sss_walk_medium *m, const double sigma_s_prime_per_mm[3],
				  const double sigma_a_per_mm[3], double g, double eta, double mm_per_unit);

/* How a walk ended. Every status but SSS_WALK_EXITED has weight 0; the caller counts the two
 * failures (STEP_LIMIT, LOST) and reports them like circle tracing's no-hit rate. */
typedef enum sss_walk_status {
	SSS_WALK_EXITED,     /* refracted out of the medium: the exit fields are valid */
	SSS_WALK_ABSORBED,   /* the throughput became zero or Russian roulette ended it (unbiased) */
	SSS_WALK_STEP_LIMIT, /* max_steps interactions without leaving: dropped, biased low, counted */
	SSS_WALK_LOST,	     /* a ray inside the medium found no surface (open mesh, crack): counted */
	SSS_WALK_BAD_INPUT,  /* non-finite point or direction, zero direction, or max_steps < 1 */
} sss_walk_status;

typedef struct sss_walk_result {
	sss_walk_status status;
	vec3 p;		/* exit point, on the exit triangle */
	vec3 ng;	/* the exit triangle's unit geometric normal, as the probe reports it */
	vec3 dir;	/* unit exit direction, outside the medium */
	uint32_t prim;	/* exit triangle and barycentrics (for textures at the exit) */
	float u, v;
	vec3 weight;	/* RGB throughput of the walk (0 unless EXITED) */
	int steps;	/* interactions: scattering events plus boundary hits */
	int reflections; /* boundary hits that reflected back inside (Fresnel or total internal) */
	int reentries;	 /* boundary hits from outside, after a collision point rounded across the
			  * surface: the walk steps back in (README.md); about 1 in 10^6 interactions */
	int queries;	 /* nearest-surface queries asked of the probe (README.md, "Skipping casts") */
	int skipped;	 /* interactions whose ray cast was skipped: inside a ball free of surface */
	int runs;	 /* runs of classic steps inside a ball free of surface (README.md, "Runs inside a
			  * ball"); their collisions count in steps and skipped */
} sss_walk_result;

/* The default bound on interactions per walk; reaching it is counted, never silent (the renderer
 * prints the dropped walks). Measured on the wax block's defaults in a slab 200 mm deep (the
 * longest walks of circe's media; bench/sss/walkbench): 4096 dropped 1.7 % of the walks, 65536
 * about 1 in 20,000 (0.005 %); 2^20 none of 200,000. A walk that long costs about a second, so
 * the bound still ends the pathological ones (no absorption in a large object) in finite time. */
#define SSS_WALK_MAX_STEPS (1 << 20)
/* Russian roulette starts after this many interactions, with survival probability
 * min(1, max channel of the throughput): unbiased; keeps absorbing walks short. */
#define SSS_WALK_RR_START 16

/* One walk. x is the entry point on the object's surface, ng its geometric normal (either
 * orientation: the walk takes the mesh's orientation from it, so the mesh's winding must be
 * consistent, as a closed mesh's is; otherwise walks end LOST), x_scale the scale of its triangle
 * for the ray offset (accel/offset.h; 0: unknown), w the unit direction into the medium (already refracted by the caller's
 * dielectric at the entry); pr traces the object alone. Random numbers come from g (the caller's
 * per-sample stream: deterministic). At each boundary hit the walk reflects with probability
 * F (Fresnel of eta, 1 under total internal reflection) and refracts out otherwise, so the
 * boundary's weight is 1 and the radiance scale eta^2 of entering cancels at the exit. */
sss_walk_result sss_walk(const sss_walk_medium *m, const sss_probe *pr, vec3 x, vec3 ng, float x_scale, vec3 w,
			 rng *g, int max_steps);

/* Whether walks skip the casts that a ball free of surface answers (the default, true; the probe
 * must have `nearest`): the same walks either way, the casts a walk makes aside (README.md,
 * "Skipping casts"). For tests and benchmarks; set it before walks run (not thread-safe). */
void sss_walk_set_skip(bool on);
/* Whether walks make their steps inside a known ball free of surface as cheap runs of the classic
 * walk (the default, true; README.md, "Runs inside a ball": the same estimator's expectation, a
 * different sampling inside the ball). For tests and benchmarks; set it before walks run (not
 * thread-safe). */
void sss_walk_set_run(bool on);

/* Dwivedi's diffusion length nu0 (in mean free paths) of single-scattering albedo alpha: the
 * root of 1 = alpha nu0/2 ln((nu0 + 1)/(nu0 - 1)) by d'Eon & Krivanek 2020's fit (eq. 67);
 * 1 for alpha <= 0, +Inf for alpha >= 1. */
double sss_walk_dwivedi_nu(double alpha);

/* A direction about w (unit) whose cosine with w follows Henyey-Greenstein with mean cosine g:
 * cos = (1 + g^2 - ((1 - g^2)/(1 - g + 2 g u1))^2) / (2 g) (the inverse CDF), phi = 2 pi u2. */
vec3 sss_walk_sample_hg(vec3 w, double g, double u1, double u2);

/* ---- closed meshes ---------------------------------------------------------------------------- */

typedef enum sss_mesh_closure {
	SSS_MESH_CLOSED,    /* every edge is shared by exactly two triangles */
	SSS_MESH_OPEN,	    /* an edge of one triangle (a border) or of three or more, or no triangles */
	SSS_MESH_NO_MEMORY, /* the check's scratch arrays could not be allocated */
} sss_mesh_closure;

/* Whether m bounds a volume: positions are welded by exact equality (primitives and imported
 * meshes duplicate vertices along seams), triangles that collapse under welding are skipped, and
 * every remaining edge must belong to exactly two triangles. *open_edges (may be NULL) receives
 * the number of edges that do not. Allocates scratch memory (O(triangles)) and frees it. */
sss_mesh_closure sss_walk_mesh_closure(const mesh *m, uint64_t *open_edges);

#endif
