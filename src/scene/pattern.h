/* pattern.h - POV-Ray's pigments and normals as a flat program evaluated at a shading point:
 * nodes (a plain colour, an image_map or bump_map, or a pattern with its wave, colour map or
 * pigment map, or a normal's amount), their warps
 * (transforms, turbulence, repeat, black_hole) in the order they are applied to a point, and
 * the map entries. pattern_compile turns the IR's pigment trees (scene/pigment.h) into a
 * program: src/build one per world, which render/world.c evaluates at each hit and at circle
 * tracing's entry points; src/lang one per `function { pattern {...} }` or `{ pigment {...} }`.
 * It lives in src/scene, beside the trees, because both the language and the renderer evaluate
 * it and the language may not call the renderer (DESIGN.md: data flows one way). Pure: no
 * render state, read-only once built, any number of threads evaluate it.
 *
 * Every pattern follows the definition of POV-Ray 3.7's source (source/core/material/pattern.cpp,
 * github.com/POV-Ray/povray), cited at each; the noise is Perlin's improved noise (Perlin 2002,
 * "Improving Noise", SIGGRAPH), scaled to POV-Ray's range [0, 1]: noise-based patterns (bozo,
 * granite, turbulence, ...) have POV-Ray's look and range, not its exact values. */
#ifndef CIRCE_SCENE_PATTERN_H
#define CIRCE_SCENE_PATTERN_H

#include "base/diag.h"
#include "base/vec.h"
#include "io/image.h"
#include "scene/pigment.h"

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* In the order of scene/pigment.h's scene_pattern_kind (the build checks the counts agree). */
typedef enum pattern_kind {
	PATTERN_PLAIN, PATTERN_IMAGE,
	/* block patterns: the value is an index into the node's list (0, 1, 2) */
	PATTERN_CHECKER, PATTERN_HEXAGON, PATTERN_BRICK,
	/* continuous patterns: a value in [0, 1] through the wave and the colour map */
	PATTERN_GRADIENT, PATTERN_RADIAL, PATTERN_ONION, PATTERN_LEOPARD, PATTERN_MARBLE, PATTERN_WOOD,
	PATTERN_AGATE, PATTERN_GRANITE, PATTERN_BOZO, PATTERN_SPOTTED, PATTERN_BUMPS, PATTERN_DENTS,
	PATTERN_WRINKLES, PATTERN_RIPPLES, PATTERN_WAVES, PATTERN_CRACKLE, PATTERN_CELLS, PATTERN_SPIRAL1,
	PATTERN_SPIRAL2, PATTERN_QUILTED, PATTERN_PLANAR, PATTERN_BOXED, PATTERN_CYLINDRICAL,
	PATTERN_SPHERICAL,
	PATTERN_PIGMENT_PATTERN, /* the grey of a pigment (its node: pattern_node.child) */
	PATTERN_FUNCTION, /* a user function of (x, y, z) (pattern_node.fn) */
	PATTERN_LAYERS, /* a layered texture's pigments (its entries, bottom first), composited by the
			 * upper layers' filter and transmit */
	PATTERN_AVERAGE, /* its entries' colours (or normals) averaged, each weighted by its value */
	PATTERN_MANDEL, PATTERN_JULIA, /* POV-Ray's fractals of z^2 + c in the x-y plane */
	PATTERN_MAGNET, /* POV-Ray's magnet fractals, types 1 and 2, mandel's or julia's form */
	PATTERN_SLOPE,	/* the surface normal's angle to a direction (and an altitude): pattern_surface */
	PATTERN_DENSITY_FILE, /* a df3 file's voxels on the unit cube */
	PATTERN_IMAGE_PATTERN, /* an image's grey (or alpha), mapped as an image_map */
	PATTERN_FACETS, /* a normal's only: the normal quantised (or the point's cells' noise: coords) */
	PATTERN_TILING, /* POV-Ray's 27 tilings of the x-z plane */
	PATTERN_MATERIAL_MAP, /* a block pattern: an image's palette index (or red) picks the entry */
	PATTERN_OBJECT, /* a block pattern: entry 1 inside an object, 0 outside (pattern_node.fn) */
	PATTERN_KIND_COUNT
} pattern_kind;

/* POV-Ray's wave types (ContinuousPattern::Evaluate). */
typedef enum pattern_wave { WAVE_RAMP, WAVE_TRIANGLE, WAVE_SINE, WAVE_SCALLOP, WAVE_CUBIC, WAVE_POLY } pattern_wave;

/* In the order of scene/pigment.h's scene_warp_kind. */
typedef enum pattern_warp_kind {
	WARP_TRANSFORM, WARP_TURBULENCE, WARP_REPEAT, WARP_BLACK_HOLE,
	WARP_PLANAR, WARP_CYLINDRICAL, WARP_SPHERICAL, WARP_TOROIDAL, WARP_CUBIC
} pattern_warp_kind;

/* Turbulence's parameters (POV-Ray's defaults: octaves 6, omega 0.5, lambda 2). */
typedef struct pattern_turb {
	dvec3 amount;
	int octaves;
	double omega, lambda;
} pattern_turb;

typedef struct pattern_warp {
	pattern_warp_kind kind;
	xform xf;	   /* WARP_TRANSFORM: the transform written; points go through its inverse */
	pattern_turb turb; /* WARP_TURBULENCE */
	int axis;	   /* WARP_REPEAT: the axis of the repeat vector, its width, offset and flip */
	double width;
	dvec3 offset, flip;
	dvec3 center;	   /* WARP_BLACK_HOLE: centre, radius, strength, falloff, inverse, repeat */
	double radius, strength, falloff;
	bool inverse;
	dvec3 repeat;
	dvec3 uncertainty; /* WARP_BLACK_HOLE: turbulence, the repeated centres' random offsets */
	dvec3 orientation; /* the mapping warps: unit; dist_exp, plane_offset, major_radius as POV-Ray's */
	double dist_exp, plane_offset, major_radius;
} pattern_warp;

/* One entry of a colour map, a pigment map or a block pattern's list: a colour, or a node. */
typedef struct pattern_entry {
	double value;
	float color[5]; /* red, green, blue, filter, transmit */
	int32_t node;	/* >= 0: a pigment's node, evaluated at the same point; -1: color */
} pattern_entry;

/* Limits of a pigment tree (the parser states them in its messages). */
enum {
	PATTERN_MAX_ENTRIES = 256, /* entries in one colour or pigment map: POV-Ray's limit */
	PATTERN_MAX_DEPTH = 16	   /* pigments nested in pigment maps */
};

typedef struct pattern_node {
	pattern_kind kind;
	float color[5];	  /* PATTERN_PLAIN */
	const image *img; /* PATTERN_IMAGE, _IMAGE_PATTERN, _MATERIAL_MAP: map_type 0 planar, 1 spherical, 2 cylindrical */
	int map_type;
	bool once, interpolate;
	float filter_all, transmit_all;
	dvec3 vector;	   /* gradient's direction; brick's size */
	double mortar;	   /* brick */
	double control0, control1; /* quilted */
	int arms;	   /* spiral1, spiral2 */
	bool solid;	   /* crackle solid: the noise at the nearest feature point */
	dvec3 crackle_form; /* crackle: weights of the three nearest distances (default <-1, 1, 0>) */
	double crackle_metric, crackle_offset; /* crackle: the distance's exponent (2), its offset (0) */
	int fractal_iterations;		       /* mandel, julia: the iterations limit */
	int fractal_exponent;		       /* mandel, julia: E of z^E + c, 2..33 */
	double julia_c[2];		       /* julia's c (and a julia magnet's) */
	int magnet_type;		       /* magnet: 1 or 2 */
	bool slope_map; /* a normal's slope_map: the entries' color[0] heights, color[1] slopes */
	bool magnet_julia;		       /* magnet: julia's form */
	int fractal_exterior, fractal_interior; /* POV-Ray's exterior and interior types */
	double exterior_factor, interior_factor;
	double agate_turb; /* agate */
	pattern_wave wave;
	double frequency, phase, exponent;
	bool turb_in_pattern; /* marble, wood, spiral, agate: the pattern uses turb itself */
	pattern_turb turb;     /* its classic turbulence (amount 0: none) */
	double bump_amount, accuracy; /* a normal's: its amount (0.5) and slope step (0.02) */
	int32_t child;	   /* PATTERN_PIGMENT_PATTERN: its pigment's node (-1: none, value 0) */
	scene_fn fn;	   /* PATTERN_FUNCTION: the function (eval NULL, or failing: value 0); PATTERN_OBJECT: the inside */
	/* slope: its unit direction (point_at: the point) and weight, the altitude's unit direction
	 * and weight, each one's low and width (0: none given) */
	dvec3 slope_dir, altit_dir;
	double slope_len, altit_len, slope_lo, slope_width, altit_lo, altit_width;
	bool slope_point_at;
	const float *voxels; /* density_file: x fastest, each in [0, 1]; its size; 0 none, 1 trilinear, 2 tricubic */
	uint32_t vox_n[3];
	int vox_interp;
	bool use_alpha, img_alpha; /* image_pattern: its alpha as the value; whether the image has any */
	double facets_coords, facets_size; /* facets: coords' amount (0: the normal's facets), cell size */
	int tiling; /* tiling: its number */
	const image *img_index; /* image_map with palette filter/transmit: its indices (IMAGE_INDEX) */
	const float *pal_filter, *pal_transmit; /* per palette index, NaN: filter_all / transmit_all */
	uint32_t warp0, n_warps;   /* into pattern_prog.warps, in the order applied to a point */
	uint32_t entry0, n_entries; /* into pattern_prog.entries, by increasing value */
} pattern_node;

typedef struct pattern_prog {
	pattern_node *nodes;
	size_t n_nodes;
	pattern_warp *warps;
	size_t n_warps;
	pattern_entry *entries;
	size_t n_entries;
} pattern_prog;

/* An image_map's or bump_map's file loaded for pattern_compile (pg->image, pg->is_normal: a
 * bump_map's heights, read as stored): the image, alive as long as the program, or NULL after
 * reporting why. */
typedef const image *(*pattern_image_loader)(void *ctx, const scene_pigment *pg, diag *d);
/* pg's tree appended to *pp (scene/pattern_compile.c); *node receives its root. load NULL refuses
 * an image_map with a message (a function's pigment: src/lang loads no images). False after
 * reporting. */
bool pattern_compile(pattern_prog *pp, const scene_pigment *pg, pattern_image_loader load, void *ctx, uint32_t *node,
		     diag *d);
void pattern_prog_free(pattern_prog *pp);

/* The surface a pattern is evaluated on, for the patterns that need more than the point (slope):
 * its unit normal, facing the viewer, and the point, in world space (POV-Ray's Intersection's
 * PNormal and IPoint). NULL where there is none (a function, a medium, a sky). */
typedef struct pattern_surface {
	dvec3 normal, point;
} pattern_surface;

/* The pigment of node `node` at point p (the pigment's space before its own warps): red, green,
 * blue, filter, transmit, each finite. tol: how far p may be from the true point (a float hit's
 * rounding; 0 for an exact point): a point that close to a cell's boundary (checker, brick,
 * cells) takes the side POV-Ray's EPSILON gives it, so a face lying on a boundary is one colour. */
void pattern_eval(const pattern_prog *pg, uint32_t node, dvec3 p, double tol, float out[5]);
/* pattern_eval on surface sf (NULL: none). */
void pattern_eval_at(const pattern_prog *pg, uint32_t node, dvec3 p, const pattern_surface *sf, double tol,
		     float out[5]);
/* A normal pattern (POV-Ray's Perturb_Normal) at p: *n, a normal in p's space, moved by the
 * pattern's perturbation (bumps, dents, wrinkles, ripples and waves their own way; any other
 * pattern by its slope, sampled at four points `accuracy` apart), through the pattern's
 * transforms and back. Not normalised. */
void pattern_perturb(const pattern_prog *pg, uint32_t node, dvec3 p, dvec3 *n);
/* pattern_perturb on surface sf (NULL: none). */
void pattern_perturb_at(const pattern_prog *pg, uint32_t node, dvec3 p, const pattern_surface *sf, dvec3 *n);
/* A normal seen through a transform t whose inverse takes points into a pattern's space: into it
 * (t's transpose), or back out (its inverse transpose). Not normalised. */
dvec3 pattern_normal_through(const xform *t, dvec3 n, bool into);
/* The largest row sum of |t's inverse|: how much t's inverse can lengthen a vector (max norm). */
double pattern_inv_gain(const xform *t);
/* The pattern's value at p after its warps, its wave applied (continuous kinds, in [0, 1]) or
 * the block index (checker, hexagon, brick). */
double pattern_value(const pattern_prog *pg, const pattern_node *n, dvec3 p);
/* The raw pattern before the wave (POV-Ray's EvaluateRaw), at a point already warped; a
 * pigment_pattern (which needs its program) is 0 here. */
double pattern_raw(const pattern_node *n, dvec3 p);
/* POV-Ray's wave function of a raw value v. */
double pattern_wave_apply(pattern_wave w, double v, double frequency, double phase, double exponent);
/* The colour map lookup (POV-Ray's Search_Blend_Map: clamped at the ends, linear between
 * entries, a step where two share a value). */
void pattern_map_lookup(const pattern_prog *pg, const pattern_node *n, double v, dvec3 p, int depth, float out[5]);

/* The entries of node's map that point p picks, as its colour lookup would blend them (POV-Ray's
 * texture map, trace.cpp ComputeOneTextureColour): a block pattern's one entry, a continuous
 * pattern's two around its value (or one at the ends), average's every entry of non-zero value
 * (at most max); their indices into the node's list in entry[], their weights (adding to 1) in
 * weight[]. *q is p after the node's warps, where the entries are evaluated, *q_tol its
 * tolerance. Returns how many (0: node has no map, or the index names no entry). */
uint32_t pattern_pick(const pattern_prog *pg, uint32_t node, dvec3 p, const pattern_surface *sf, double tol,
		      uint32_t max, uint32_t *entry, double *weight, dvec3 *q, double *q_tol);

/* POV-Ray 3.7's Noise() (noise_generator 2): in [0, 1], its own values (base/noise.c). */
double pattern_noise(dvec3 p);
/* POV-Ray 3.7's DNoise: each component its bare lattice sum, about [-0.6, 0.6], 0 on average. */
dvec3 pattern_dnoise(dvec3 p);
/* POV-Ray's Turbulence (a sum of octaves of noise) and DTurbulence (of vector noise). */
double pattern_turbulence(dvec3 p, const pattern_turb *t);
dvec3 pattern_dturbulence(dvec3 p, const pattern_turb *t);
/* Perlin's 2002 permutation (the i-th entry), for tests. */
int pattern_perm(int i);
/* crackle's feature point of the unit cube at <x, y, z> (exposed for tests). */
dvec3 pattern_crackle_point(int x, int y, int z);
/* The point p moved by one warp. */
dvec3 pattern_warp_point(const pattern_warp *w, dvec3 p);
/* A node with POV-Ray's defaults for kind (wave, frequency 1, turbulence parameters). */
pattern_node pattern_node_default(pattern_kind kind);
/* POV-Ray's default colour map of a pattern kind, as entries written to out (at most 6);
 * returns how many. */
int pattern_default_map(pattern_kind kind, pattern_entry out[6]);

#endif
