/* pigment.h - a POV-Ray pigment (or normal) in the scene IR: a small tree. A node is a plain
 * colour, an image_map (a normal's bump_map), or a pattern with its parameters, its colour map (or pigment map, whose entries
 * are pigments, or the two or three entries of a block pattern), its wave, its turbulence and
 * its warps and transforms in the order written. Colours keep POV-Ray's five channels (red,
 * green, blue, filter, transmit). The tree lives in the scene's arena and is shared, never
 * changed once made: a pigment moved or modified later is a copy. src/build compiles it into
 * scene/pattern.h's flat program. */
#ifndef CIRCE_SCENE_PIGMENT_H
#define CIRCE_SCENE_PIGMENT_H

#include "base/diag.h"
#include "base/vec.h"

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>

/* X(enum suffix, POV-Ray's word): in the order of scene/pattern.h's pattern_kind. */
#define SCENE_PATTERNS(X)                                                                           \
	X(PLAIN, "color") X(IMAGE, "image_map") X(CHECKER, "checker") X(HEXAGON, "hexagon")         \
	X(BRICK, "brick") X(GRADIENT, "gradient") X(RADIAL, "radial") X(ONION, "onion")             \
	X(LEOPARD, "leopard") X(MARBLE, "marble") X(WOOD, "wood") X(AGATE, "agate")                 \
	X(GRANITE, "granite") X(BOZO, "bozo") X(SPOTTED, "spotted") X(BUMPS, "bumps")               \
	X(DENTS, "dents") X(WRINKLES, "wrinkles") X(RIPPLES, "ripples") X(WAVES, "waves")           \
	X(CRACKLE, "crackle") X(CELLS, "cells") X(SPIRAL1, "spiral1") X(SPIRAL2, "spiral2")         \
	X(QUILTED, "quilted") X(PLANAR, "planar") X(BOXED, "boxed") X(CYLINDRICAL, "cylindrical")   \
	X(SPHERICAL, "spherical") X(PIGMENT_PATTERN, "pigment_pattern") X(FUNCTION, "function")   \
	X(LAYERS, "(layers)") X(AVERAGE, "average")   \
	X(MANDEL, "mandel") X(JULIA, "julia") X(MAGNET, "magnet") X(SLOPE, "slope")   \
	X(DENSITY_FILE, "density_file") X(IMAGE_PATTERN, "image_pattern")    \
	X(FACETS, "facets") X(TILING, "tiling") X(MATERIAL_MAP, "material_map")          \
	X(OBJECT, "object")

typedef enum scene_pattern_kind {
#define SCENE_PAT_ENUM(e, s) SCENE_PAT_##e,
	SCENE_PATTERNS(SCENE_PAT_ENUM)
#undef SCENE_PAT_ENUM
	SCENE_PAT_COUNT
} scene_pattern_kind;

/* In the order of scene/pattern.h's pattern_wave. */
typedef enum scene_wave {
	SCENE_WAVE_RAMP, SCENE_WAVE_TRIANGLE, SCENE_WAVE_SINE, SCENE_WAVE_SCALLOP, SCENE_WAVE_CUBIC, SCENE_WAVE_POLY
} scene_wave;

typedef struct scene_turb {
	dvec3 amount; /* 0: none */
	int octaves;
	double omega, lambda;
} scene_turb;

typedef enum scene_warp_kind {
	SCENE_WARP_TRANSFORM, SCENE_WARP_TURBULENCE, SCENE_WARP_REPEAT, SCENE_WARP_BLACK_HOLE,
	/* POV-Ray's mapping warps (warp.cpp): the point mapped onto a plane, a cylinder, a sphere, a
	 * torus or a cube's net */
	SCENE_WARP_PLANAR, SCENE_WARP_CYLINDRICAL, SCENE_WARP_SPHERICAL, SCENE_WARP_TOROIDAL, SCENE_WARP_CUBIC
} scene_warp_kind;

typedef struct scene_warp {
	scene_warp_kind kind;
	diag_loc loc;
	xform xf;	 /* TRANSFORM: as written (points go through its inverse) */
	scene_turb turb; /* TURBULENCE */
	int axis;	 /* REPEAT: the axis of its vector, the vector's length there, offset, flip (+-1) */
	double width;
	dvec3 offset, flip;
	dvec3 center;	 /* BLACK_HOLE */
	double radius, strength, falloff;
	bool inverse;
	dvec3 repeat;
	dvec3 uncertainty; /* BLACK_HOLE's turbulence: each repeated centre moved by up to it */
	dvec3 orientation; /* the mapping warps': unit, <0, 0, 1> by default */
	double dist_exp;   /* cylindrical, spherical, toroidal: 0 */
	double plane_offset; /* planar: 0 */
	double major_radius; /* toroidal: 1 */
} scene_warp;

struct scene_pigment;

/* A float function of (x, y, z) the language compiled (the `function { }` pattern), called
 * through the language's evaluator: the IR knows no syntax. eval NULL: none. eval is pure and
 * allocates nothing, so any number of threads call it; false when it cannot evaluate. */
typedef bool (*scene_fn_eval)(const void *ctx, const double xyz[3], double *out);
typedef struct scene_fn {
	scene_fn_eval eval;
	const void *ctx;
	const char *name; /* for the dump */
} scene_fn;

/* Entries in one colour or pigment map (POV-Ray's limit); pigments nested in maps and lists. */
enum { SCENE_PIGMENT_MAX_ENTRIES = 256, SCENE_PIGMENT_MAX_DEPTH = 16 };

/* [value colour] or [value pigment], or a block pattern's entry (value: its index). */
typedef struct scene_map_entry {
	double value;
	float color[5];
	const struct scene_pigment *pigment; /* NULL: color */
} scene_map_entry;

typedef struct scene_pigment {
	diag_loc loc;
	scene_pattern_kind kind;
	float color[5];	   /* PLAIN */
	const char *image; /* IMAGE: the file (resolved), its mapping, once, interpolate, filter/transmit all */
	int map_type;
	bool once, interpolate;
	float filter_all, transmit_all;
	bool uv_mapping; /* evaluated at <u, v, 0> of the surface (POV-Ray's uv_mapping) */
	dvec3 vector;	 /* gradient; brick_size */
	double mortar, control0, control1, agate_turb;
	int arms;
	bool solid; /* crackle solid */
	dvec3 crackle_form;	     /* crackle's form: weights of the 3 nearest distances, <-1, 1, 0> */
	double crackle_metric;	     /* crackle's metric: the exponent of its distance, 2 */
	double crackle_offset;	     /* crackle's offset: added to each distance (in the metric), 0 */
	int fractal_iterations;	     /* mandel, julia: the iterations limit, >= 1 */
	int fractal_exponent;	     /* mandel, julia: z^E + c, E in 2..33 (POV-Ray's), default 2 */
	double julia_c[2];	     /* julia: the constant c = <re, im> */
	int magnet_type;	     /* magnet: 1 or 2 */
	bool magnet_julia;	     /* magnet: julia's form (z starts at the point, c given), else mandel's */
	int fractal_exterior, fractal_interior; /* POV-Ray's types: 1 and 0 */
	double exterior_factor, interior_factor; /* 1 and 1 */
	scene_wave wave;
	double frequency, phase, exponent;
	scene_turb turb; /* the pigment's own `turbulence` (classic) */
	const scene_warp *warps; /* in the order written */
	uint32_t n_warps;
	const struct scene_pigment *child; /* PIGMENT_PATTERN: the pigment whose grey is the value */
	const scene_map_entry *entries; /* NULL: the pattern's default map */
	uint32_t n_entries;
	bool pigment_map; /* entries are pigments (a normal's normal_map: normals) */
	bool is_normal;	  /* a normal { }: the pattern perturbs the shading normal */
	double bump_amount, accuracy; /* a normal's amount (POV-Ray's 0.5) and slope step (0.02) */
	bool block_list;  /* entries are a block pattern's list */
	scene_fn fn;	  /* FUNCTION: its function; OBJECT: its object's inside (1 inside, 0 outside) */
	bool slope_map;	  /* a normal's slope_map: each entry's color[0] a height, color[1] its slope */
	/* SLOPE, as POV-Ray's parser leaves it: the unit direction (point_at: the point) and its
	 * weight, the altitude's unit direction and weight (the weights add to 1), each one's low and
	 * width (hi - lo; 0: not given) */
	dvec3 slope_dir, altit_dir;
	double slope_len, altit_len, slope_lo, slope_width, altit_lo, altit_width;
	bool slope_point_at;
	/* DENSITY_FILE: the df3 file's voxels (x fastest, then y, then z), each its integer over its
	 * type's largest, its size in voxels, and interpolate (0 none, 1 trilinear, 2 tricubic) */
	const float *voxels;
	uint32_t vox_n[3];
	int vox_interp;
	const char *vox_file; /* for the dump */
	bool use_alpha; /* IMAGE_PATTERN (its file in image): the value is the image's transparency */
	double facets_coords, facets_size; /* FACETS (a normal's only; its metric: crackle_metric): 0, 0.1 */
	int tiling; /* TILING: POV-Ray's tiling number, 1 to 27 (0 and above 27 are 1, as POV-Ray) */
	/* IMAGE: `filter I, F` / `transmit I, F` of a palette image: 256 entries each, NaN where not
	 * given (NULL: none given); the largest index given, for the check against the palette */
	const float *pal_filter, *pal_transmit;
	int pal_max;
} scene_pigment;

/* POV-Ray's word of a pattern kind ("checker"). */
const char *scene_pattern_name(scene_pattern_kind k);
/* The pattern whose word is the n bytes at s, or SCENE_PAT_COUNT. PLAIN and IMAGE are not
 * patterns and are not found. */
scene_pattern_kind scene_pattern_find(const char *s, size_t n);
/* A pattern's number of entries when it is a block pattern (checker, brick: 2; hexagon: 3), 0
 * for the others. */
int scene_pattern_blocks(scene_pattern_kind k);
/* POV-Ray's defaults for a node of kind k (frequency 1, turbulence octaves 6 omega 0.5 lambda 2,
 * marble/wood/spiral's triangle wave, brick's size and mortar, ...). */
scene_pigment scene_pigment_defaults(scene_pattern_kind k, diag_loc loc);
/* One line of the IR dump: the tree in brief ("checker 2 entries", "marble map 3 turb"). */
void scene_pigment_dump(FILE *o, const scene_pigment *pg);

#endif
