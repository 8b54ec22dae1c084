/* test_pattern: POV-Ray's patterns against values worked out by hand from POV-Ray 3.7's
 * definitions (source/core/material/pattern.cpp: each table row is the formula evaluated at that
 * point), the wave functions, the colour map's interpolation, block lists, pigment maps, warps,
 * image_map's planar/spherical/cylindrical/torus mappings and palette filter/transmit, the noise's
 * and turbulence's range, crackle's form, metric and offset against a brute force, average
 * (pigments and normals), slope, density_file's three interpolations, image_pattern, facets
 * against a brute-force nearest point, material_map, and the 27 tilings against povray's own
 * render. */
#include "check.h"
#include "scene/pattern.h"

#include <string.h>

typedef struct row {
	pattern_kind kind;
	dvec3 p;
	double want;
} row;

static double raw(pattern_kind k, dvec3 p)
{
	pattern_node n = pattern_node_default(k);
	if (k == PATTERN_GRADIENT)
		n.vector = d3(1, 0, 0);
	return pattern_raw(&n, p);
}

static void check_table(void)
{
	const double half_pi = M_PI / 2.0;
	static const double quilt = 0.25 * (0.015625 + 0.421875 + 0.140625) * 1.1547005383792517 / 3.0;
	const row rows[] = {
		/* CheckerPattern: (floor x + floor y + floor z) & 1 */
		{PATTERN_CHECKER, {0.5, 0.5, 0.5}, 0},
		{PATTERN_CHECKER, {1.5, 0.5, 0.5}, 1},
		{PATTERN_CHECKER, {-0.5, 0.5, 0.5}, 1},
		{PATTERN_CHECKER, {-0.5, -0.5, 0.5}, 0},
		{PATTERN_CHECKER, {2.0, 0.0, 0.0}, 0}, /* on a plane: floor(2 + eps) */
		/* GradientPattern: p . g, and fmod 1 above 1 */
		{PATTERN_GRADIENT, {0.3, 9, 9}, 0.3},
		{PATTERN_GRADIENT, {1.3, 0, 0}, 0.3},
		{PATTERN_GRADIENT, {-0.25, 0, 0}, -0.25},
		/* RadialPattern: 0.25 + (atan2(x, z) + pi) / 2 pi; 0.25 on the axis */
		{PATTERN_RADIAL, {1, 0, 0}, 1.0},
		{PATTERN_RADIAL, {0, 5, 1}, 0.75},
		{PATTERN_RADIAL, {-1, 0, 0}, 0.5},
		{PATTERN_RADIAL, {0, 3, 0}, 0.25},
		/* OnionPattern: fmod(|p|, 1) */
		{PATTERN_ONION, {0.3, 0.4, 0}, 0.5},
		{PATTERN_ONION, {1.2, 1.6, 0}, 0.0},
		/* LeopardPattern: ((sin x + sin y + sin z) / 3)^2 */
		{PATTERN_LEOPARD, {half_pi, half_pi, half_pi}, 1.0},
		{PATTERN_LEOPARD, {half_pi, 0, 0}, 1.0 / 9.0},
		/* MarblePattern without turbulence: x */
		{PATTERN_MARBLE, {0.7, 3, 3}, 0.7},
		/* WoodPattern without turbulence: the distance from the z axis */
		{PATTERN_WOOD, {0.3, 0.4, 7}, 0.5},
		/* CLIP_DENSITY patterns: 1 - r in [0, 1] */
		{PATTERN_PLANAR, {5, 0.25, 5}, 0.75},
		{PATTERN_PLANAR, {0, -2, 0}, 0.0},
		{PATTERN_BOXED, {0.5, -0.7, 0.2}, 0.3},
		{PATTERN_CYLINDRICAL, {0.6, 5, 0.8}, 0.0},
		{PATTERN_CYLINDRICAL, {0.3, 5, 0.4}, 0.5},
		{PATTERN_SPHERICAL, {0.3, 0.4, 0}, 0.5},
		/* Spiral1Pattern, one arm: z + r + phi / 2 pi, phi = pi/2 + asin(y / r) for x >= 0 */
		{PATTERN_SPIRAL1, {1, 0, 0}, 1.25},
		{PATTERN_SPIRAL1, {-1, 0, 0.5}, 0.5 + 1 + 0.75},
		/* Spiral2Pattern: triangle(r) + triangle(spiral1) */
		{PATTERN_SPIRAL2, {1, 0, 0}, 0.0 + 0.5},
		/* QuiltedPattern, controls 1 1: v = frac - 0.5, v * quilt_cubic(|v|), (|x|+|y|+|z|) / 3 */
		{PATTERN_QUILTED, {0.5, 0.5, 0.5}, 0.0},
		{PATTERN_QUILTED, {0.75, 0.5, 0.5}, quilt},
		/* BrickPattern, <8, 3, 4.5> mortar 0.5 */
		{PATTERN_BRICK, {1, 1.5, 1}, 1},
		{PATTERN_BRICK, {-0.2, 1.5, 1}, 0},
		{PATTERN_BRICK, {1, -0.3, 1}, 0},
		{PATTERN_BRICK, {3.7, 4.5, 1}, 0}, /* the next row is shifted by half a brick: mortar at x = 3.5 */
		/* HexagonPattern: 0 at the origin; cells of 0.5 x sqrt(3)/2 */
		{PATTERN_HEXAGON, {0, 0, 0}, 0},
		{PATTERN_HEXAGON, {0, 0, 1.0}, 1},
		{PATTERN_HEXAGON, {0, 0, 3.0}, 2},
		{PATTERN_HEXAGON, {1.25, 0, 0.4}, 2},
		{PATTERN_HEXAGON, {-1.25, 7, 0.4}, 2}, /* |x|: symmetric in x */
	};
	for (size_t i = 0; i < sizeof rows / sizeof *rows; i++) {
		double got = raw(rows[i].kind, rows[i].p);
		CHECK(fabs(got - rows[i].want) < 1e-9, "row %zu (kind %d at <%g, %g, %g>): %.12g, want %.12g", i,
		      rows[i].kind, rows[i].p.x, rows[i].p.y, rows[i].p.z, got, rows[i].want);
	}
}

static void check_waves(void)
{
	CHECK_NEAR(pattern_wave_apply(WAVE_RAMP, 0.3, 1, 0, 1), 0.3, 1e-12);
	CHECK_NEAR(pattern_wave_apply(WAVE_RAMP, -0.2, 1, 0, 1), 0.8, 1e-12);
	CHECK_NEAR(pattern_wave_apply(WAVE_RAMP, 0.3, 2, 0.1, 1), 0.7, 1e-12);
	CHECK_NEAR(pattern_wave_apply(WAVE_RAMP, 1.0, 1, 0, 1), 1.0, 1e-12); /* fmod by 1.00001 */
	CHECK_NEAR(pattern_wave_apply(WAVE_TRIANGLE, 0.25, 1, 0, 1), 0.5, 1e-12);
	CHECK_NEAR(pattern_wave_apply(WAVE_TRIANGLE, 0.5, 1, 0, 1), 1.0, 1e-12);
	CHECK_NEAR(pattern_wave_apply(WAVE_TRIANGLE, 0.75, 1, 0, 1), 0.5, 1e-12);
	CHECK_NEAR(pattern_wave_apply(WAVE_SINE, 0.25, 1, 0, 1), 1.0, 1e-12);
	CHECK_NEAR(pattern_wave_apply(WAVE_SINE, 0.75, 1, 0, 1), 0.0, 1e-12);
	CHECK_NEAR(pattern_wave_apply(WAVE_SCALLOP, 0.5, 1, 0, 1), sin(M_PI / 2), 1e-12);
	CHECK_NEAR(pattern_wave_apply(WAVE_SCALLOP, 0.25, 1, 0, 1), sin(M_PI / 4), 1e-12);
	CHECK_NEAR(pattern_wave_apply(WAVE_CUBIC, 0.25, 1, 0, 1), 0.15625, 1e-12);
	CHECK_NEAR(pattern_wave_apply(WAVE_POLY, 0.5, 1, 0, 2), 0.25, 1e-12);
	CHECK_NEAR(pattern_wave_apply(WAVE_RAMP, 0.3, 0, 0, 1), 0.3, 1e-12); /* frequency 0: untouched */
}

static pattern_entry col(double v, float r, float g, float b)
{
	return (pattern_entry){.value = v, .color = {r, g, b, 0, 0}, .node = -1};
}

static void check5(const char *what, const float got[5], float r, float g, float b)
{
	CHECK(fabsf(got[0] - r) < 1e-6f && fabsf(got[1] - g) < 1e-6f && fabsf(got[2] - b) < 1e-6f,
	      "%s: <%g, %g, %g>, want <%g, %g, %g>", what, got[0], got[1], got[2], r, g, b);
}

/* A gradient x with the map [0 black] [0.5 red] [0.5 blue] [1 white]. */
static void check_colour_map(void)
{
	pattern_entry e[4] = {col(0, 0, 0, 0), col(0.5, 1, 0, 0), col(0.5, 0, 0, 1), col(1, 1, 1, 1)};
	pattern_node n = pattern_node_default(PATTERN_GRADIENT);
	n.vector = d3(1, 0, 0), n.n_entries = 4;
	pattern_prog pg = {.nodes = &n, .n_nodes = 1, .entries = e, .n_entries = 4};
	float c[5];
	pattern_eval(&pg, 0, d3(0.25, 0, 0), 0, c);
	check5("between black and red", c, 0.5f, 0, 0);
	pattern_eval(&pg, 0, d3(0.75, 0, 0), 0, c);
	check5("between blue and white", c, 0.5f, 0.5f, 1);
	pattern_eval(&pg, 0, d3(0.49, 0, 0), 0, c);
	check5("just below the step", c, 0.98f, 0, 0);
	pattern_eval(&pg, 0, d3(0.51, 0, 0), 0, c);
	check5("just above the step", c, 0.02f, 0.02f, 1);
	pattern_map_lookup(&pg, &n, -1.0, d3(0, 0, 0), 0, c);
	check5("below the first entry", c, 0, 0, 0);
	pattern_map_lookup(&pg, &n, 2.0, d3(0, 0, 0), 0, c);
	check5("above the last entry", c, 1, 1, 1);
	/* The filter and transmit channels interpolate too. */
	e[0].color[4] = 1.0f;
	pattern_eval(&pg, 0, d3(0.25, 0, 0), 0, c);
	CHECK_NEAR(c[4], 0.5, 1e-6);
}

/* checker with a colour and a pigment (a gradient of its own), and a pigment_map. */
static void check_nested(void)
{
	pattern_node nodes[2] = {pattern_node_default(PATTERN_CHECKER), pattern_node_default(PATTERN_GRADIENT)};
	nodes[0].entry0 = 0, nodes[0].n_entries = 2;
	nodes[1].vector = d3(1, 0, 0), nodes[1].entry0 = 2, nodes[1].n_entries = 2;
	pattern_entry e[4] = {col(0, 1, 0, 0), {.value = 1, .node = 1}, col(0, 0, 0, 0), col(1, 0, 1, 0)};
	pattern_prog pg = {.nodes = nodes, .n_nodes = 2, .entries = e, .n_entries = 4};
	float c[5];
	pattern_eval(&pg, 0, d3(0.5, 0.5, 0.5), 0, c);
	check5("checker's first entry", c, 1, 0, 0);
	pattern_eval(&pg, 0, d3(1.5, 0.5, 0.5), 0, c);
	check5("checker's second: the gradient's value 1.5 -> 0.5", c, 0, 0.5f, 0);
	/* The same as a pigment_map of a gradient over x: entry 1 at 1 is the gradient pigment. */
	nodes[0] = pattern_node_default(PATTERN_GRADIENT);
	nodes[0].vector = d3(0, 1, 0), nodes[0].entry0 = 0, nodes[0].n_entries = 2;
	pattern_eval(&pg, 0, d3(0.25, 0.5, 0), 0, c); /* half red, half the gradient's 0.25 green */
	check5("pigment_map", c, 0.5f, 0.125f, 0);
}

/* A point within tol of a checker's boundary takes POV-Ray's side, floor(x + EPSILON): a float
 * hit on the face x = 1 of a box, 1e-9 short of it, is in the cell at 1 like the face itself. */
static void check_tolerance(void)
{
	pattern_node n = pattern_node_default(PATTERN_CHECKER);
	n.n_entries = 2;
	pattern_entry e[2] = {col(0, 1, 0, 0), col(1, 0, 0, 1)};
	pattern_prog pg = {.nodes = &n, .n_nodes = 1, .entries = e, .n_entries = 2};
	float c[5];
	pattern_eval(&pg, 0, d3(1.0, 0.5, 0.5), 0, c);
	check5("on the face", c, 0, 0, 1);
	pattern_eval(&pg, 0, d3(1.0 - 1e-9, 0.5, 0.5), 1e-7, c);
	check5("just short of the face, within tol", c, 0, 0, 1);
	pattern_eval(&pg, 0, d3(1.0 - 1e-9, 0.5, 0.5), 0, c);
	check5("just short of the face, exact", c, 1, 0, 0);
}

/* pigment_pattern: the grey of its pigment (a plain colour here) selects in its colour map. */
static void check_pigment_pattern(void)
{
	pattern_node nodes[2] = {pattern_node_default(PATTERN_PIGMENT_PATTERN), pattern_node_default(PATTERN_PLAIN)};
	nodes[0].child = 1, nodes[0].n_entries = 2;
	nodes[1].color[0] = 1, nodes[1].color[1] = 0.5f, nodes[1].color[2] = 0;
	pattern_entry e[2] = {col(0, 0, 0, 0), col(1, 1, 1, 1)};
	pattern_prog pg = {.nodes = nodes, .n_nodes = 2, .entries = e, .n_entries = 2};
	float c[5];
	pattern_eval(&pg, 0, d3(0.3, 0.2, 0.1), 0, c);
	float g = 0.297f + 0.589f * 0.5f;
	check5("grey of <1, 0.5, 0>", c, g, g, g);
}

/* A layered texture's pigment: a blue bottom, a half-transmitting red layer, then a yellow layer
 * that filters half and transmits a quarter (values worked by hand from the layering rule:
 * colour * (1 - f - t) + below * (t + f * colour)). */
static void check_layers(void)
{
	pattern_node n = pattern_node_default(PATTERN_LAYERS);
	n.n_entries = 3;
	pattern_entry e[3] = {col(0, 0, 0, 1), col(1, 1, 0, 0), col(2, 1, 1, 0)};
	e[1].color[4] = 0.5f;
	e[2].color[3] = 0.5f, e[2].color[4] = 0.25f;
	pattern_prog pg = {.nodes = &n, .n_nodes = 1, .entries = e, .n_entries = 3};
	float c[5];
	n.n_entries = 2;
	pattern_eval(&pg, 0, d3(0.3, 0.2, 0.1), 0, c);
	check5("red half over blue", c, 0.5f, 0, 0.5f);
	n.n_entries = 3;
	pattern_eval(&pg, 0, d3(0.3, 0.2, 0.1), 0, c);
	/* yellow: opaque 0.25; r = 0.25 + 0.5 * (0.25 + 0.5) = 0.625, g = 0.25 + 0 = 0.25,
	 * b = 0 + 0.5 * (0.25 + 0.5 * 0) = 0.125 */
	check5("yellow filtering over both", c, 0.625f, 0.25f, 0.125f);
}

static void check_warps(void)
{
	pattern_warp rep = {.kind = WARP_REPEAT, .axis = 0, .width = 1, .flip = d3(1, 1, 1)};
	dvec3 q = pattern_warp_point(&rep, d3(1.3, 0.2, 0));
	CHECK_NEAR(q.x, 0.3, 1e-12);
	rep.offset = d3(0, 1, 0);
	q = pattern_warp_point(&rep, d3(2.3, 0.2, 0));
	CHECK_NEAR(q.y, 2.2, 1e-12); /* two blocks: offset twice */
	rep.flip = d3(-1, 1, 1), rep.offset = d3(0, 0, 0);
	q = pattern_warp_point(&rep, d3(1.3, 0, 0));
	CHECK_NEAR(q.x, 0.7, 1e-12); /* an odd block is mirrored within its width */
	pattern_warp bh = {.kind = WARP_BLACK_HOLE, .radius = 1, .strength = 1, .falloff = 2};
	q = pattern_warp_point(&bh, d3(0.5, 0, 0));
	CHECK_NEAR(q.x, 0.625, 1e-12); /* p + d ((r - |d|) / r)^2 */
	q = pattern_warp_point(&bh, d3(2, 0, 0));
	CHECK_NEAR(q.x, 2.0, 1e-12);
	bh.inverse = true;
	q = pattern_warp_point(&bh, d3(0.5, 0, 0));
	CHECK_NEAR(q.x, 0.375, 1e-12);
	/* A repeated black hole's turbulence (POV-Ray's uncertainty): each block's centre moved by a
	 * fraction in [0, 1) of the vector per axis, the same for every point of the block, others
	 * elsewhere. Falloff 0 and strength 1 move a point by its whole offset from the centre (q =
	 * 2p - c), so the centre reads back from q. */
	pattern_warp un = {.kind = WARP_BLACK_HOLE, .radius = 10, .strength = 1, .falloff = 0,
			   .repeat = d3(4, 4, 4), .uncertainty = d3(1, 0.5, 0.25)};
	dvec3 first = d3(0, 0, 0);
	int differ = 0;
	for (int bx = -3; bx <= 3; bx++)
		for (int k = 0; k < 2; k++) {
			dvec3 p = d3(4 * bx + 1 + k, 1.5 + 0.5 * k, 2.2), c = d3_sub(d3_scale(p, 2), pattern_warp_point(&un, p));
			dvec3 f = d3_sub(c, d3(4 * bx, 0, 0)); /* the block's offset from its unmoved centre */
			CHECK(f.x >= 0 && f.x < 1 && f.y >= 0 && f.y < 0.5 && f.z >= 0 && f.z < 0.25,
			      "block %d: the centre's offset <%g, %g, %g>", bx, f.x, f.y, f.z);
			if (k == 0 && bx == -3)
				first = f;
			else if (k == 0 && d3_length(d3_sub(f, first)) > 1e-6)
				differ++;
			if (k == 1) { /* the same block, another point: the same centre */
				dvec3 p0 = d3(4 * bx + 1, 1.5, 2.2), c0 = d3_sub(d3_scale(p0, 2), pattern_warp_point(&un, p0));
				CHECK(d3_length(d3_sub(c, c0)) < 1e-9, "block %d: one centre", bx);
			}
		}
	CHECK(differ >= 5, "the blocks' centres differ: %d of 6", differ);
	pattern_warp sc = {.kind = WARP_TRANSFORM};
	CHECK(xform_scale(d3(2, 2, 2), &sc.xf), "scale");
	q = pattern_warp_point(&sc, d3(1, 0, 0));
	CHECK_NEAR(q.x, 0.5, 1e-12);
	/* Turbulence moves a point by at most |amount| (1 + omega + ...) L, each octave's vector
	 * noise in [-L, L], L = 0.5 / 0.48985582 (POV-Ray's DNoise: its noise's sum, pattern_dnoise). */
	pattern_warp tw = {.kind = WARP_TURBULENCE, .turb = {d3(0.5, 0.5, 0.5), 6, 0.5, 2.0}};
	double most = 0;
	for (int i = 0; i < 2000; i++) {
		dvec3 p = d3(i * 0.137, i * 0.071 - 3, i * 0.0191);
		dvec3 d = d3_sub(pattern_warp_point(&tw, p), p);
		most = fmax(most, fmax(fabs(d.x), fmax(fabs(d.y), fabs(d.z))));
	}
	CHECK(most <= 0.5 * (0.5 / 0.48985582) * (2 - 1.0 / 32) + 1e-12 && most > 0.1, "turbulence displacement %g", most);
}

static void check_noise(void)
{
	bool perm_ok = true, seen[256] = {0, 0, 0};
	for (int i = 0; i < 256; i++) {
		perm_ok &= !seen[pattern_perm(i)];
		seen[pattern_perm(i)] = true;
	}
	CHECK(perm_ok, "Perlin's table is a permutation of 0..255");
	{ /* POV-Ray 3.7's own noise and DNoise, as povray 3.7.0.10 prints them (#debug of f_noise3d
	   * and of vturbulence(2, 0.5, 1, P), one octave: DNoise, at assumed_gamma 1): the same
	   * numbers to 1e-9, on and off the lattice, at negative coordinates too */
		const dvec3 at[6] = {{0.3, 1.7, -2.2},	  {12.25, -3.5, 7.75}, {-0.61, -0.13, 0.97},
				     {100.2, 33.3, -57.9}, {3, -7, 12},	       {-4.5, 2.25, 0.125}};
		const double want[6][4] = {{0.5288514781, 0.0271863994, 0.3209507833, 0.2678770334},
					   {0.6090963306, 0.1909996057, 0.1606372757, -0.2244817187},
					   {0.6068633328, 0.1864411260, -0.6025423188, -0.0828901506},
					   {0.3794376056, -0.2778296203, 0.1837101964, -0.2537354306},
					   {0.6467341058, 0.2678340000, -0.2219045000, 0.0828945000},
					   {0.5172905143, 0.0035856514, -0.2973617705, -0.4577620183}};
		for (int i = 0; i < 6; i++) {
			dvec3 d = pattern_dnoise(at[i]);
			CHECK_NEAR(pattern_noise(at[i]), want[i][0], 1e-9);
			CHECK_NEAR(d.x, want[i][1], 1e-9);
			CHECK_NEAR(d.y, want[i][2], 1e-9);
			CHECK_NEAR(d.z, want[i][3], 1e-9);
		}
	}
	{ /* cells and crackle from POV-Ray's Hash3d and gPatternRands: povray 3.7.0.10's #debug of
	   * function { pattern { cells } } and { crackle } at six points */
		const dvec3 at[6] = {{0.3, 1.7, -2.2},	   {12.25, -3.5, 7.75}, {-0.61, -0.13, 0.97},
				     {100.2, 33.3, -57.9}, {3.5, -7.5, 12.5},	{-4.5, 2.25, 0.125}};
		const double want[6][2] = {{0.9564163543, 0.1058904655}, {0.4167994647, 0.4122530295},
					   {0.8008794207, 0.1172139950}, {0.1965205926, 0.1323610083},
					   {0.6417353761, 0.4065015991}, {0.3872454274, 0.1233842829}};
		pattern_node c = pattern_node_default(PATTERN_CELLS), k = pattern_node_default(PATTERN_CRACKLE);
		for (int i = 0; i < 6; i++) {
			CHECK_NEAR(pattern_raw(&c, at[i]), want[i][0], 1e-9);
			CHECK_NEAR(pattern_raw(&k, at[i]), want[i][1], 1e-9);
		}
	}
	double lo = 1, hi = 0, sum = 0, tlo = 10, thi = -10;
	pattern_turb t = {d3(1, 1, 1), 6, 0.5, 2.0};
	int n = 20000;
	for (int i = 0; i < n; i++) {
		dvec3 p = d3(i * 0.3713, i * 0.1171 + 0.5, i * 0.0533 - 9);
		double v = pattern_noise(p);
		lo = fmin(lo, v), hi = fmax(hi, v), sum += v;
		double tv = pattern_turbulence(p, &t);
		tlo = fmin(tlo, tv), thi = fmax(thi, tv);
	}
	CHECK(lo >= 0 && hi <= 1 && lo < 0.2 && hi > 0.8, "noise range [%g, %g]", lo, hi);
	CHECK(fabs(sum / n - 0.5) < 0.02, "noise mean %g", sum / n);
	/* Turbulence, POV-Ray's generator 2: clamp(2 N - 0.5, 0, 1) + 0.5 (2 N - 0.5) + ... +
	 * 1/32 (2 N - 0.5), each 2 N - 0.5 in [-0.5, 1.5]: within [-0.484375, 2.453125]. */
	CHECK(tlo >= -0.484375 && thi <= 2.453125 && thi - tlo > 1.6, "turbulence range [%g, %g]", tlo, thi);
	{ /* its value at a point, term by term; granite's (min(|1 - 2 N|, 0.5) over six octaves at 4 p) */
		dvec3 p = d3(0.37, -1.21, 2.83);
		double want = fmin(1.0, fmax(0.0, 2 * pattern_noise(p) - 0.5)), l = 2, o = 0.5;
		for (int i = 2; i <= 6; i++, l *= 2, o *= 0.5)
			want += o * (2 * pattern_noise(d3_scale(p, l)) - 0.5);
		CHECK_NEAR(pattern_turbulence(p, &t), want, 1e-12);
		pattern_node g = pattern_node_default(PATTERN_GRANITE);
		double gw = 0, f = 1;
		for (int i = 0; i < 6; i++, f *= 2)
			gw += fmin(fabs(1 - 2 * pattern_noise(d3_scale(p, 4 * f))), 0.5) / f;
		CHECK_NEAR(pattern_raw(&g, p), gw, 1e-12);
	}
	/* Every noise-based pattern stays in [0, 1] and finite, whatever the point. */
	const pattern_kind k[] = {PATTERN_BOZO,	   PATTERN_GRANITE, PATTERN_AGATE,   PATTERN_DENTS, PATTERN_WRINKLES,
				  PATTERN_RIPPLES, PATTERN_WAVES,   PATTERN_CRACKLE, PATTERN_CELLS};
	const dvec3 odd[] = {{NAN, 0, 0}, {INFINITY, 1, 2}, {1e300, -1e300, 0}, {0, 0, 0}};
	for (size_t j = 0; j < sizeof k / sizeof *k; j++) {
		pattern_node nd = pattern_node_default(k[j]);
		double a = 1, b = 0;
		for (int i = 0; i < 3000; i++) {
			double v = pattern_raw(&nd, d3(i * 0.219, i * 0.0137, 1 - i * 0.071));
			a = fmin(a, v), b = fmax(b, v);
		}
		CHECK(a >= 0 && b <= 1 && b > a, "kind %d: range [%g, %g]", k[j], a, b);
		for (size_t i = 0; i < 4; i++) {
			pattern_prog pg = {.nodes = &nd, .n_nodes = 1};
			double v = pattern_value(&pg, &nd, odd[i]);
			CHECK(v == v, "kind %d at an odd point: NaN", k[j]);
		}
	}
	/* cells: one value per unit cell */
	pattern_node cells = pattern_node_default(PATTERN_CELLS);
	CHECK(pattern_raw(&cells, d3(0.1, 0.2, 0.3)) == pattern_raw(&cells, d3(0.9, 0.8, 0.7)), "cells constant in a cell");
}

/* A 2 x 2 image: red, green on the top row; blue, white below. */
static void check_image(void)
{
	float px[16] = {1, 0, 0, 1, 0, 1, 0, 1, 0, 0, 1, 1, 1, 1, 1, 1};
	image img = {.width = 2, .height = 2, .rgba = px};
	pattern_node n = pattern_node_default(PATTERN_IMAGE);
	n.img = &img;
	pattern_prog pg = {.nodes = &n, .n_nodes = 1};
	float c[5];
	pattern_eval(&pg, 0, d3(0.25, 0.75, 5), 0, c); /* planar: x right, y up, z ignored */
	check5("planar top left", c, 1, 0, 0);
	pattern_eval(&pg, 0, d3(0.75, 0.25, -5), 0, c);
	check5("planar bottom right", c, 1, 1, 1);
	pattern_eval(&pg, 0, d3(1.25, -0.75, 0), 0, c);
	check5("planar repeats", c, 0, 0, 1);
	n.once = true;
	pattern_eval(&pg, 0, d3(1.25, 0.25, 0), 0, c);
	CHECK(c[4] == 1.0f && c[0] == 0.0f, "outside a once image: clear (%g, transmit %g)", c[0], c[4]);
	n.once = false, n.map_type = 1; /* spherical: u from +x towards +z, v the latitude */
	pattern_eval(&pg, 0, d3(0, 1, 0.1), 0, c);
	CHECK(c[2] == 0.0f, "spherical north pole: top row");
	pattern_eval(&pg, 0, d3(0.1, -1, 0.3), 0, c);
	CHECK(c[2] == 1.0f, "spherical south pole: bottom row");
	pattern_eval(&pg, 0, d3(0, 0.5, -1), 0, c); /* theta = 3 pi / 2: u = 0.75, upper half */
	check5("spherical -z, above the equator", c, 0, 1, 0);
	n.map_type = 2; /* cylindrical: v = y */
	pattern_eval(&pg, 0, d3(0, 0.25, 1), 0, c); /* theta = pi / 2: u = 0.25, lower row */
	check5("cylindrical +z, low", c, 0, 0, 1);
	/* torus (5, imageutil.cpp's torus_image_map, major radius 1): u the angle about y, v the angle
	 * about the ring from its inside (0), through the outer equator (1/2), the top (3/4) */
	n.map_type = 5;
	pattern_eval(&pg, 0, d3(1.5, 0, 0), 0, c); /* u 0, v 1/2: the lower row's first */
	check5("torus outer equator", c, 0, 0, 1);
	pattern_eval(&pg, 0, d3(1, 0.5, 0), 0, c); /* u 0, v 3/4: the top row */
	check5("torus top", c, 1, 0, 0);
	pattern_eval(&pg, 0, d3(0, 0, -1.5), 0, c); /* u 3/4, v 1/2 */
	check5("torus at -z", c, 1, 1, 1);
	pattern_eval(&pg, 0, d3(0, 0.3, 0), 0, c);
	CHECK(c[4] == 1.0f, "torus on the y axis: off the image");
	n.map_type = 2;
	n.filter_all = 0.5f, n.transmit_all = 0.25f;
	pattern_eval(&pg, 0, d3(0, 0.25, 1), 0, c);
	CHECK(c[3] == 0.5f && c[4] == 0.25f, "filter all, transmit all: %g %g", c[3], c[4]);
	/* a palette image's `transmit 1, 0.9` and `filter 3, 0.4`: the texels of those indices; the
	 * others keep transmit all and filter all */
	float ix[16] = {1, 0, 0, 1, 3, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1}; /* top: 1 3; bottom: 0 1 */
	image idx = {.width = 2, .height = 2, .rgba = ix, .indexed = true, .palette = 4};
	float ft[256], tt[256];
	for (int i = 0; i < 256; i++)
		ft[i] = tt[i] = NAN;
	tt[1] = 0.9f, ft[3] = 0.4f;
	n.map_type = 0, n.img_index = &idx, n.pal_filter = ft, n.pal_transmit = tt;
	pattern_eval(&pg, 0, d3(0.25, 0.75, 0), 0, c); /* top left: index 1 */
	CHECK(c[0] == 1 && c[3] == 0.5f && c[4] == 0.9f, "palette index 1: transmit %g filter %g", c[4], c[3]);
	pattern_eval(&pg, 0, d3(0.75, 0.75, 0), 0, c); /* top right: index 3 */
	CHECK(c[3] == 0.4f && c[4] == 0.25f, "palette index 3: filter %g transmit %g", c[3], c[4]);
	pattern_eval(&pg, 0, d3(0.25, 0.25, 0), 0, c); /* bottom left: index 0, none given */
	CHECK(c[3] == 0.5f && c[4] == 0.25f, "palette index 0: filter %g transmit %g", c[3], c[4]);
	/* the image's own alpha (a PNG's alpha or a palette's tRNS) is transmit 1 - alpha, and filter
	 * all and transmit all add to it (imageutil.cpp's AllTransmitLegacyMode, every scene below
	 * #version 3.8): povmap.png's transparent frame is see-through in POV-Ray. povray 3.7.0 itself,
	 * a white texel of alpha 0.25 with transmit all 0.5 over a red background, shows pure red:
	 * transmit 0.75 + 0.5 (legacy), not 0.75 + 0.5 * 0.25 (3.8's proper mode) */
	float pa[16] = {1, 0, 0, 0.25f, 0, 1, 0, 1, 0, 0, 1, 0, 1, 1, 1, 1};
	image al = {.width = 2, .height = 2, .rgba = pa};
	n = pattern_node_default(PATTERN_IMAGE);
	n.img = &al, n.img_alpha = true;
	pattern_eval(&pg, 0, d3(0.25, 0.75, 0), 0, c); /* top left: alpha 0.25 */
	CHECK(c[0] == 1 && c[3] == 0.0f && c[4] == 0.75f, "alpha 0.25: transmit %g filter %g", c[4], c[3]);
	pattern_eval(&pg, 0, d3(0.25, 0.25, 0), 0, c); /* bottom left: alpha 0 */
	CHECK(c[4] == 1.0f, "alpha 0: clear (transmit %g)", c[4]);
	n.filter_all = 0.4f, n.transmit_all = 0.2f;
	pattern_eval(&pg, 0, d3(0.25, 0.75, 0), 0, c);
	CHECK(fabsf(c[3] - 0.4f) < 1e-6f && fabsf(c[4] - 0.95f) < 1e-6f, "alpha 0.25, filter all 0.4, transmit all 0.2: %g %g",
	      c[3], c[4]);
	pattern_eval(&pg, 0, d3(0.75, 0.75, 0), 0, c); /* top right: opaque */
	CHECK(fabsf(c[3] - 0.4f) < 1e-6f && fabsf(c[4] - 0.2f) < 1e-6f, "opaque texel: filter all, transmit all");
}

static void check_defaults(void)
{
	pattern_entry e[6];
	CHECK(pattern_default_map(PATTERN_CHECKER, e) == 2 && e[0].color[2] == 1 && e[1].color[1] == 1,
	      "checker: blue, green");
	CHECK(pattern_default_map(PATTERN_HEXAGON, e) == 3 && e[2].color[0] == 1, "hexagon: blue, green, red");
	CHECK(pattern_default_map(PATTERN_GRANITE, e) == 2 && e[1].color[0] == 1, "granite: black to white");
	CHECK(pattern_node_default(PATTERN_MARBLE).wave == WAVE_TRIANGLE, "marble's triangle wave");
	CHECK(pattern_node_default(PATTERN_QUILTED).frequency == 0, "quilted's frequency 0");
}

/* Perturb_Normal: bumps adds amount * DNoise; any other pattern its slope on the tetrahedron,
 * which for gradient x (value x) is -5 * 0.02 * amount * (4/3) e_x whatever the accuracy (the
 * four unit vectors of a regular tetrahedron have sum 0 and sum v v^T = 4/3 I); the result is
 * unit (UnWarp_Normal). A scale 2 of the pattern keeps the angle: Warp_Normal makes the normal
 * unit in the pattern's space before the slope is added (warps.cpp, without no_bump_scale). */
static void check_normals(void)
{
	pattern_node n = pattern_node_default(PATTERN_BUMPS);
	n.bump_amount = 0.8;
	pattern_prog pg = {.nodes = &n, .n_nodes = 1};
	dvec3 p = d3(0.3, 1.7, -2.2), v = d3(0, 0, 1);
	pattern_perturb(&pg, 0, p, &v);
	dvec3 want = d3_normalize(d3_add(d3(0, 0, 1), d3_scale(pattern_dnoise(p), 0.8)));
	CHECK(d3_length(d3_sub(v, want)) < 1e-12, "bumps: <%g, %g, %g>", v.x, v.y, v.z);
	/* the same bumps under a normal of length 3: the normal is made unit first */
	v = d3(0, 0, 3);
	pattern_perturb(&pg, 0, p, &v);
	CHECK(d3_length(d3_sub(v, want)) < 1e-12, "bumps on a long normal: <%g, %g, %g>", v.x, v.y, v.z);
	n = pattern_node_default(PATTERN_GRADIENT);
	n.vector = d3(1, 0, 0), n.bump_amount = 0.3, n.frequency = 0; /* the raw value x, no wrap */
	for (double acc = 0.01; acc < 0.1; acc *= 3) {
		n.accuracy = acc;
		v = d3(0, 1, 0);
		pattern_perturb(&pg, 0, d3(0.2, 0, 0), &v);
		CHECK(fabs(v.x / v.y + 0.1 * 0.3 * 4.0 / 3.0) < 1e-9 && fabs(d3_length(v) - 1) < 1e-12 && fabs(v.z) < 1e-9,
		      "gradient x's slope at accuracy %g: <%g, %g, %g>", acc, v.x, v.y, v.z);
	}
	pattern_warp sc = {.kind = WARP_TRANSFORM};
	CHECK(xform_scale(d3(2, 2, 2), &sc.xf), "scale");
	pg.warps = &sc, pg.n_warps = 1, n.warp0 = 0, n.n_warps = 1;
	v = d3(0, 1, 0);
	pattern_perturb(&pg, 0, d3(0.2, 0, 0), &v);
	/* into: n' = 2 n, made unit; slope as before; out: / 2, made unit -> the unscaled angle */
	CHECK(fabs(v.x / v.y + 0.1 * 0.3 * 4.0 / 3.0) < 1e-9 && fabs(d3_length(v) - 1) < 1e-12, "scaled slope: <%g, %g, %g>",
	      v.x, v.y, v.z);
	/* bump_map: a flat image leaves the normal; a ramp rising to +x tilts it towards -x (the
	 * triangle of heights faces away from the rise), in the frame of the normal and world y */
	float flat[4 * 4 * 4], ramp[4 * 4 * 4];
	for (int i = 0; i < 16; i++)
		for (int c = 0; c < 4; c++)
			flat[i * 4 + c] = 0.5f, ramp[i * 4 + c] = c == 3 ? 1.0f : (float)(i % 4) / 3.0f;
	image fi = {.width = 4, .height = 4, .rgba = flat}, ri = {.width = 4, .height = 4, .rgba = ramp};
	n = pattern_node_default(PATTERN_IMAGE);
	n.img = &fi, n.bump_amount = 1.0, n.n_warps = 0;
	pg.n_warps = 0;
	v = d3(0, 0, -1);
	pattern_perturb(&pg, 0, d3(0.4, 0.6, 0), &v);
	CHECK(d3_length(d3_sub(d3_normalize(v), d3(0, 0, -1))) < 1e-9, "flat bump_map: <%g, %g, %g>", v.x, v.y, v.z);
	n.img = &ri;
	v = d3(0, 0, -1);
	pattern_perturb(&pg, 0, d3(0.4, 0.6, 0), &v);
	CHECK(fabs(d3_length(v) - 1) < 1e-9 && fabs(v.x) > 0.05 && fabs(v.y) < 1e-9, "ramp bump_map tilts in x: <%g, %g, %g>",
	      v.x, v.y, v.z);
	/* ripples at a point: finite, and the normal moves along p - source sums */
	n = pattern_node_default(PATTERN_RIPPLES);
	pg.n_warps = 0, n.n_warps = 0;
	v = d3(0, 1, 0);
	pattern_perturb(&pg, 0, d3(NAN, 1e300, 0), &v);
	CHECK(isfinite(v.x) && isfinite(v.y) && isfinite(v.z), "ripples at an odd point stay finite");
}

/* crackle (POV-Ray 3.7 CracklePattern::EvaluateRaw) against a brute force over the 9x9x9 cubes
 * around each point, from the same feature points: the three nearest distances under the metric
 * (sum |d|^m, then the m-th root), each with offset^m added, weighted by the form, clamped. */
static double crackle_brute(dvec3 p, dvec3 form, double m, double offset)
{
	double d[3] = {1e300, 1e300, 1e300};
	int cx = (int)floor(p.x), cy = (int)floor(p.y), cz = (int)floor(p.z);
	for (int i = -4; i <= 4; i++)
		for (int j = -4; j <= 4; j++)
			for (int k = -4; k <= 4; k++) {
				dvec3 f = pattern_crackle_point(cx + i, cy + j, cz + k);
				double s = pow(fabs(f.x - p.x), m) + pow(fabs(f.y - p.y), m) + pow(fabs(f.z - p.z), m);
				if (s < d[0])
					d[2] = d[1], d[1] = d[0], d[0] = s;
				else if (s < d[1])
					d[2] = d[1], d[1] = s;
				else if (s < d[2])
					d[2] = s;
			}
	double v = 0.0, w[3] = {form.x, form.y, form.z};
	for (int c = 0; c < 3; c++)
		v += w[c] * pow(d[c] + pow(offset, m), 1.0 / m);
	return v < 0.0 ? 0.0 : v > 1.0 ? 1.0 : v;
}

static void check_crackle(void)
{
	struct { dvec3 form; double metric, offset; } cases[] = {
		{{-1, 1, 0}, 2, 0},	 /* POV-Ray's default */
		{{1, 0, 0}, 2, 0},	 /* the distance to the nearest point */
		{{0, 0.5, 0.5}, 2, 0.3}, /* the 2nd and 3rd, offset */
		{{-1, 1, 0}, 1, 0},	 /* Manhattan */
		{{1, 0, 0}, 1, 0.2},
		{{-1, 0.5, 0.7}, 3, 0.1}, /* a general metric */
	};
	int worst_case = -1;
	double worst = 0.0;
	for (size_t c = 0; c < sizeof cases / sizeof cases[0]; c++) {
		pattern_node n = pattern_node_default(PATTERN_CRACKLE);
		n.crackle_form = cases[c].form, n.crackle_metric = cases[c].metric, n.crackle_offset = cases[c].offset;
		for (int i = 0; i < 200; i++) {
			dvec3 p = d3(7.3 * sin(i * 1.7) + 0.11 * i, 5.1 * cos(i * 0.9) - 0.07 * i, 3.7 * sin(i * 2.3 + 1));
			double got = pattern_raw(&n, p), want = crackle_brute(p, cases[c].form, cases[c].metric, cases[c].offset);
			if (fabs(got - want) > worst)
				worst = fabs(got - want), worst_case = (int)c;
		}
	}
	CHECK(worst < 1e-12, "crackle against the brute force: worst difference %g (case %d)", worst, worst_case);
	/* The default form through the metric 2 closed form at one point, by hand from the points. */
	pattern_node n = pattern_node_default(PATTERN_CRACKLE);
	dvec3 p = d3(0.5, 0.5, 0.5);
	CHECK_NEAR(pattern_raw(&n, p), crackle_brute(p, d3(-1, 1, 0), 2, 0), 1e-12);
	/* solid: one value per cell of the nearest point, so constant near a feature point. */
	n.solid = true;
	dvec3 f = pattern_crackle_point(2, -3, 1);
	CHECK_NEAR(pattern_raw(&n, f), pattern_raw(&n, d3_add(f, d3(1e-4, -1e-4, 1e-4))), 0);
}

/* average (POV-Ray 3.7 ComputeAverage): the entries' colours weighted by their values over the
 * weights' sum, whatever the point; an entry may be a pigment of its own. */
static void check_average(void)
{
	pattern_node nodes[2] = {pattern_node_default(PATTERN_AVERAGE), pattern_node_default(PATTERN_GRADIENT)};
	nodes[0].entry0 = 0, nodes[0].n_entries = 3;
	nodes[1].vector = d3(1, 0, 0), nodes[1].entry0 = 3, nodes[1].n_entries = 2;
	pattern_entry e[5] = {col(1, 1, 0, 0), col(2, 0, 1, 0), {.value = 1, .node = 1}, col(0, 0, 0, 0), col(1, 0, 0, 1)};
	pattern_prog pg = {.nodes = nodes, .n_nodes = 2, .entries = e, .n_entries = 5};
	float c[5];
	pattern_eval(&pg, 0, d3(0.5, 7, -3), 0, c); /* (1 red + 2 green + 1 * 0.5 blue) / 4 */
	check5("average of red 1, green 2, gradient 1", c, 0.25f, 0.5f, 0.125f);
	pattern_eval(&pg, 0, d3(0.25, 0, 0), 0, c);
	check5("and where the gradient is 0.25", c, 0.25f, 0.5f, 0.0625f);
}

/* A normal's normal_map: average weights the entries' perturbed normals (not normalised, as
 * POV-Ray's NormalBlendMap::ComputeAverage); another pattern blends the two entries about its
 * value by the map's weights and normalises (Perturb_Normal). The entries: gradient x normals of
 * amounts 0.3 and 0.6, each alone computed first. */
static void check_normal_map(void)
{
	pattern_node nodes[3] = {pattern_node_default(PATTERN_AVERAGE), pattern_node_default(PATTERN_GRADIENT),
				 pattern_node_default(PATTERN_GRADIENT)};
	for (int i = 1; i < 3; i++)
		nodes[i].vector = d3(1, 0, 0), nodes[i].frequency = 0, nodes[i].bump_amount = 0.3 * i;
	nodes[0].entry0 = 0, nodes[0].n_entries = 2;
	pattern_entry e[2] = {{.value = 1, .node = 1}, {.value = 3, .node = 2}};
	pattern_prog pg = {.nodes = nodes, .n_nodes = 3, .entries = e, .n_entries = 2};
	dvec3 p = d3(0.2, 0.4, 0), v1 = d3(0, 1, 0), v2 = d3(0, 1, 0), v = d3(0, 1, 0);
	pattern_perturb(&pg, 1, p, &v1);
	pattern_perturb(&pg, 2, p, &v2);
	CHECK(fabs(v1.x) > 1e-3 && fabs(v2.x / v2.y - 2 * v1.x / v1.y) < 1e-9, "the entries alone: %g, %g", v1.x, v2.x);
	pattern_perturb(&pg, 0, p, &v);
	dvec3 want = d3_normalize(d3_scale(d3_add(v1, d3_scale(v2, 3)), 0.25)); /* UnWarp_Normal's unit */
	CHECK(d3_length(d3_sub(v, want)) < 1e-12, "average normal <%g, %g, %g>, want <%g, %g, %g>", v.x, v.y, v.z, want.x,
	      want.y, want.z);
	/* gradient y (value 0.4 at p) with normal_map [0 n1] [1 n2]: 0.6 n1 + 0.4 n2, normalised */
	nodes[0] = pattern_node_default(PATTERN_GRADIENT);
	nodes[0].vector = d3(0, 1, 0), nodes[0].entry0 = 0, nodes[0].n_entries = 2;
	e[0].value = 0, e[1].value = 1;
	v = d3(0, 1, 0);
	pattern_perturb(&pg, 0, p, &v);
	want = d3_normalize(d3_add(d3_scale(v1, 0.6), d3_scale(v2, 0.4)));
	CHECK(d3_length(d3_sub(v, want)) < 1e-12, "normal_map blend <%g, %g, %g>, want <%g, %g, %g>", v.x, v.y, v.z,
	      want.x, want.y, want.z);
}

/* mandel and julia (POV-Ray 3.7 Mandel2Pattern, JuliaPattern, FractalPattern's Exterior/
 * InteriorColour) at points traced by hand: z <- z^2 + c until |z|^2 > 4. */
static void check_fractals(void)
{
	pattern_node n = pattern_node_default(PATTERN_MANDEL);
	n.fractal_iterations = 10;
	CHECK_NEAR(pattern_raw(&n, d3(0, 0, 5)), 1.0, 0);	 /* z stays 0: interior type 0, factor 1 */
	CHECK_NEAR(pattern_raw(&n, d3(2, 0, 0)), 0.0, 0);	 /* z1 = 6: escapes at iteration 0 */
	CHECK_NEAR(pattern_raw(&n, d3(1, 0, 0)), 0.1, 1e-15); /* z1 = 2 (|z|^2 = 4 stays), z2 = 5: 1 / 10 */
	n.fractal_exterior = 6, n.exterior_factor = 0.5;	 /* |z| at escape, times 0.5 */
	CHECK_NEAR(pattern_raw(&n, d3(1, 0, 0)), 2.5, 1e-15);
	n.fractal_interior = 1, n.interior_factor = 2;	 /* -1 -> 0 -> -1 ...: the least |z| is 0 */
	CHECK_NEAR(pattern_raw(&n, d3(-1, 0, 0)), 0.0, 0);
	pattern_node j = pattern_node_default(PATTERN_JULIA);
	j.fractal_iterations = 8, j.julia_c[0] = 0, j.julia_c[1] = 0;
	CHECK_NEAR(pattern_raw(&j, d3(0.5, 0, 0)), 1.0, 0);	  /* 0.5 -> 0.25 -> ...: never escapes */
	CHECK_NEAR(pattern_raw(&j, d3(0, 1.5, 0)), 0.0, 0);	  /* z1 = -2.25: escapes at iteration 0 */
	j.julia_c[0] = -1, j.julia_c[1] = 0;
	CHECK_NEAR(pattern_raw(&j, d3(1.7, 0, 0)), 1.0 / 8, 1e-15); /* 1.89 (|z|^2 3.57), then 2.5721: 1 / 8 */
	CHECK_NEAR(pattern_raw(&j, d3(1.5, 0, 0)), 1.0, 0);	    /* 1.25, 0.5625, -0.684, ...: stays */
	/* magnet (Magnet1M/2MPattern): z <- ((z^2 + c - 1) / (2z + c - 2))^2 from 0; at c = 3 it sits
	 * at z = 4 (interior); at c = -100 it reaches 1 (|z - 1|^2 < 1e-4) at iteration 1 (type 1),
	 * at iteration 0 (type 2), and type 2 at c = 3 at iteration 2 (traced in Python). */
	pattern_node m = pattern_node_default(PATTERN_MAGNET);
	m.fractal_iterations = 10, m.magnet_type = 1;
	CHECK_NEAR(pattern_raw(&m, d3(3, 0, 0)), 1.0, 0);
	CHECK_NEAR(pattern_raw(&m, d3(-100, 0, 0)), 0.1, 1e-15);
	m.magnet_type = 2;
	CHECK_NEAR(pattern_raw(&m, d3(-100, 0, 0)), 0.0, 0);
	CHECK_NEAR(pattern_raw(&m, d3(3, 0, 0)), 0.2, 1e-15);
}

/* slope_map (normal.cpp Do_Slope_Map): gradient x (its value x) through [0 <0, 0>] [1 <1, 0>] is
 * POV-Ray's Hermite cubic h = 3t^2 - 2t^3; the normal then moves by POV-Ray's four-point slope of
 * h (amount -5 * 0.3, the tetrahedron's x components 0.9428, -0.4714, -0.4714, 0 at 0.02),
 * worked here from h itself: about the derivative 6t - 6t^2 (1.5 at 0.5, 0.96 at 0.2) times what
 * the bare gradient gives (-0.04), plus the scheme's own curvature term. */
static double smooth_h(double t) { return t <= 0 ? 0 : t >= 1 ? 1 : 3 * t * t - 2 * t * t * t; }
static void check_slope_map(void)
{
	pattern_node n = pattern_node_default(PATTERN_GRADIENT);
	n.vector = d3(1, 0, 0), n.bump_amount = 0.3, n.frequency = 0, n.slope_map = true, n.n_entries = 2;
	pattern_entry e[2] = {{.value = 0, .color = {0, 0}, .node = -1}, {.value = 1, .color = {1, 0}, .node = -1}};
	pattern_prog pg = {.nodes = &n, .n_nodes = 1, .entries = e, .n_entries = 2};
	const double xs[2] = {0.5, 0.2}, slopes[2] = {1.5, 0.96}, ax[4] = {0.942809041, -0.471404521, -0.471404521, 0},
		     ay[4] = {-0.333333333, -0.333333333, -0.333333333, 1}, az[4] = {0, 0.816496581, -0.816496581, 0};
	for (int i = 0; i < 2; i++) {
		dvec3 v = d3(0, 1, 0);
		pattern_perturb(&pg, 0, d3(xs[i], 0, 0), &v);
		double want = 0.0, wy = 1.0, wz = 0.0; /* the normal before it is made unit */
		for (int k = 0; k < 4; k++) {
			double h = smooth_h(xs[i] + 0.02 * ax[k]) * -5.0 * 0.3;
			want += ax[k] * h, wy += ay[k] * h, wz += az[k] * h;
		}
		double len = sqrt(want * want + wy * wy + wz * wz);
		CHECK(fabs(v.x - want / len) < 1e-9 && fabs(v.y - wy / len) < 1e-9 && fabs(v.z - wz / len) < 1e-9,
		      "slope_map at x %g: <%g, %g, %g>, want <%.9g, %.9g, %.9g>", xs[i], v.x, v.y, v.z, want / len, wy / len,
		      wz / len);
		CHECK(fabs(want / (-0.04 * slopes[i]) - 1) < 0.02, "the four-point slope %g against the derivative's %g", want,
		      -0.04 * slopes[i]);
	}
}

/* POV-Ray 3.7.0's slope_pattern worked by hand: v1 = (asin(n . d) / (pi / 2) + 1) / 2, through
 * (v1 - lo) / width, blended with the altitude's (p . a - lo) / width by the weights, wrapped
 * into [0, 1) (1 itself just below 1). The normal is the surface's, not the point's. */
static void check_slope(void)
{
	const double r = sqrt(0.5);
	struct {
		dvec3 dir, normal, point, p;
		double lo, width, alen, alo, awidth;
		bool point_at;
		double want;
	} rows[] = {
		{{0, 1, 0}, {0, 1, 0}, {0, 0, 0}, {0, 0, 0}, 0, 0, 0, 0, 0, false, 1.0 - 1e-10}, /* along: 1, kept below 1 */
		{{0, 1, 0}, {1, 0, 0}, {0, 0, 0}, {0, 0, 0}, 0, 0, 0, 0, 0, false, 0.5},	     /* across */
		{{0, 1, 0}, {0, -1, 0}, {0, 0, 0}, {0, 0, 0}, 0, 0, 0, 0, 0, false, 0.0},	     /* facing away */
		{{0, 1, 0}, {r, r, 0}, {0, 0, 0}, {0, 0, 0}, 0, 0, 0, 0, 0, false, 0.75},	     /* 45 degrees: asin = pi/4 */
		{{0, 1, 0}, {r, r, 0}, {0, 0, 0}, {0, 0, 0}, 0.5, 0.5, 0, 0, 0, false, 0.5},    /* slope 0.5 to 1 stretched */
		{{0, 1, 0}, {r, r, 0}, {0, 0, 0}, {0, 0, 0}, 0, 0.5, 0, 0, 0, false, 0.5},	     /* 1.5 wraps to 0.5 */
		{{0, -1, 0}, {0.6, -0.8, 0}, {0, 0, 0}, {0, 0, 0}, 0, 0, 0, 0, 0, false, (asin(0.8) / M_PI * 2 + 1) / 2},
		/* weights 1/4 and 3/4 (|<0,-1,0>| and |3y|): 0.25 * 0.5 + 0.75 * (0.4 + 1) / 2 */
		{{0, -1, 0}, {1, 0, 0}, {0, 0, 0}, {0, 0.4, 0}, 0, 0, 0.75, -1, 2, false, 0.65},
		{{0, -1, 0}, {1, 0, 0}, {0, 0, 0}, {0, 0.4, 5}, 0, 0, 0.75, 0, 0, false, 0.125 + 0.3}, /* no range: p . y */
		{{0, -1, 0}, {1, 0, 0}, {0, 0, 0}, {0, 5.4, 0}, 0, 0, 0.75, 0, 0, false, 0.175}, /* 4.175 wraps */
		/* point_at <10, 10, 0> seen from the origin with normal x: cos 45 degrees */
		{{10, 10, 0}, {1, 0, 0}, {0, 0, 0}, {0, 0, 0}, 0, 0, 0, 0, 0, true, 0.75},
		{{0, 10, 0}, {0, 1, 0}, {0, 0, 0}, {0, 0, 0}, 0, 0, 0, 0, 0, true, 1.0 - 1e-10},
		{{0, -10, 0}, {0, 1, 0}, {0, 0, 0}, {0, 0, 0}, 0, 0, 0, 0, 0, true, 0.0},
	};
	for (size_t i = 0; i < sizeof rows / sizeof *rows; i++) {
		pattern_node n = pattern_node_default(PATTERN_SLOPE);
		n.slope_dir = rows[i].dir, n.slope_point_at = rows[i].point_at;
		n.slope_lo = rows[i].lo, n.slope_width = rows[i].width;
		n.altit_len = rows[i].alen, n.slope_len = 1.0 - rows[i].alen, n.altit_dir = d3(0, 1, 0);
		n.altit_lo = rows[i].alo, n.altit_width = rows[i].awidth;
		pattern_prog pg = {.nodes = &n, .n_nodes = 1};
		pattern_surface sf = {rows[i].normal, rows[i].point};
		double v = pattern_value(&pg, &n, rows[i].p);
		CHECK(v == 0.0, "slope %zu without a surface gives 0 (POV-Ray's), got %g", i, v);
		float c[5];
		pattern_entry e[2] = {{.value = 0, .color = {0, 0, 0}, .node = -1}, {.value = 1, .color = {1, 1, 1}, .node = -1}};
		pg.entries = e, pg.n_entries = 2, n.entry0 = 0, n.n_entries = 2;
		pattern_eval_at(&pg, 0, rows[i].p, &sf, 0.0, c);
		CHECK(fabs(c[0] - rows[i].want) < 1e-6, "slope row %zu: %.9g, want %.9g", i, c[0], rows[i].want);
	}
	/* In a normal, the slope part is the same at the four samples: only the altitude tilts it,
	 * as a gradient of weight 3/4 along y would (amount 0.5, the four-point scheme's -5 factor). */
	pattern_node n = pattern_node_default(PATTERN_SLOPE);
	n.slope_dir = d3(0, -1, 0), n.slope_len = 0.25, n.altit_len = 0.75, n.altit_dir = d3(1, 0, 0);
	pattern_node g = pattern_node_default(PATTERN_GRADIENT);
	g.vector = d3(0.75, 0, 0);
	pattern_prog ps = {.nodes = &n, .n_nodes = 1}, pgr = {.nodes = &g, .n_nodes = 1};
	pattern_surface sf = {d3(0, 1, 0), d3(0, 0, 0)};
	dvec3 a = d3(0, 1, 0), b = d3(0, 1, 0);
	pattern_perturb_at(&ps, 0, d3(0.3, 0, 0), &sf, &a);
	pattern_perturb(&pgr, 0, d3(0.3, 0, 0), &b);
	CHECK(fabs(a.x - b.x) < 1e-9 && fabs(a.y - b.y) < 1e-9 && fabs(a.z - b.z) < 1e-9 && fabs(a.x) > 0.01,
	      "a slope normal tilts as its altitude's gradient: <%g, %g, %g> against <%g, %g, %g>", a.x, a.y, a.z, b.x, b.y,
	      b.z);
}

/* POV-Ray 3.7's density_pattern on small grids worked by hand: the voxel a point is in; trilinear
 * (wrapping at the far face); tricubic (Catmull-Rom: the midpoint of 0 0 1 0 is 9/16, a line is
 * kept); 0 outside the unit cube. */
static double density_at(const float *v, uint32_t nx, uint32_t ny, uint32_t nz, int interp, dvec3 p)
{
	pattern_node n = pattern_node_default(PATTERN_DENSITY_FILE);
	n.voxels = v, n.vox_n[0] = nx, n.vox_n[1] = ny, n.vox_n[2] = nz, n.vox_interp = interp;
	return pattern_raw(&n, p);
}

static void check_density_file(void)
{
	float g[8]; /* x + 2y + 4z over 7, on 2 x 2 x 2 */
	for (int i = 0; i < 8; i++)
		g[i] = (float)((i & 1) + 2 * (i >> 1 & 1) + 4 * (i >> 2)) / 7.0f;
	CHECK_NEAR(density_at(g, 2, 2, 2, 0, d3(0.3, 0.6, 0.1)), 2.0 / 7.0, 1e-7);
	CHECK_NEAR(density_at(g, 2, 2, 2, 0, d3(0.9, 0.9, 0.9)), 1.0, 1e-7);
	/* trilinear at <0.6, 1.2, 0.2> voxels: x 0.6, y from 1 towards 0 (wrapped) by 0.2: 0.8, z 0.2 */
	CHECK_NEAR(density_at(g, 2, 2, 2, 1, d3(0.3, 0.6, 0.1)), (0.6 + 2 * 0.8 + 4 * 0.2) / 7.0, 1e-7);
	CHECK_NEAR(density_at(g, 2, 2, 2, 1, d3(1.0, 0.5, 0.5)), 0.0, 0.0);  /* outside: x = 1 */
	CHECK_NEAR(density_at(g, 2, 2, 2, 1, d3(0.5, -1e-9, 0.5)), 0.0, 0.0); /* outside: y < 0 */
	const float spike[4] = {0, 0, 1, 0}, line[4] = {0, 1.0f / 3, 2.0f / 3, 1};
	CHECK_NEAR(density_at(spike, 4, 1, 1, 2, d3(0.375, 0.5, 0.5)), 9.0 / 16.0, 1e-7);
	CHECK_NEAR(density_at(line, 4, 1, 1, 2, d3(0.3, 0.2, 0.7)), 0.4, 1e-7);
	CHECK_NEAR(density_at(line, 4, 1, 1, 1, d3(0.3, 0.2, 0.7)), 0.4, 1e-7);
	CHECK_NEAR(density_at(spike, 4, 1, 1, 12, d3(0.375, 0.5, 0.5)), 9.0 / 16.0, 1e-7); /* interpolate mod 10 */
	CHECK_NEAR(density_at(NULL, 4, 1, 1, 1, d3(0.3, 0.2, 0.7)), 0.0, 0.0);
}

/* image_pattern (imageutil.cpp): the texel's grey 0.297 r + 0.589 g + 0.114 b, with use_alpha
 * 1 - alpha (an image without alpha: its red), 0 outside a once image; mapped as image_map. */
static void check_image_pattern(void)
{
	float px[8] = {1, 0.5f, 0, 1, 0, 0, 1, 0.25f}; /* left: orange, opaque; right: blue, alpha 0.25 */
	image img = {.width = 2, .height = 1, .rgba = px};
	pattern_node n = pattern_node_default(PATTERN_IMAGE_PATTERN);
	n.img = &img, n.img_alpha = true, n.frequency = 0;
	CHECK_NEAR(pattern_raw(&n, d3(0.25, 0.5, 3)), 0.297 + 0.589 * 0.5, 1e-7);
	CHECK_NEAR(pattern_raw(&n, d3(0.75, 0.5, 3)), 0.114, 1e-7);
	CHECK_NEAR(pattern_raw(&n, d3(-0.25, 7.5, 0)), 0.114, 1e-7); /* repeated */
	n.use_alpha = true;
	CHECK_NEAR(pattern_raw(&n, d3(0.25, 0.5, 0)), 0.0, 1e-7);
	CHECK_NEAR(pattern_raw(&n, d3(0.75, 0.5, 0)), 0.75, 1e-7);
	n.img_alpha = false; /* no transparency in the image: the red channel */
	CHECK_NEAR(pattern_raw(&n, d3(0.25, 0.5, 0)), 1.0, 1e-7);
	n.use_alpha = false, n.once = true;
	CHECK_NEAR(pattern_raw(&n, d3(1.25, 0.5, 0)), 0.0, 0.0);
	n.once = false, n.map_type = 2; /* cylindrical: u the angle about y from +x towards +z */
	CHECK_NEAR(pattern_raw(&n, d3(0, 0.3, -1)), 0.114, 1e-7); /* 3 pi / 2: u = 0.75 */
	CHECK_NEAR(pattern_raw(&n, d3(0, 0.3, 1)), 0.297 + 0.589 * 0.5, 1e-7);
}

/* facets (normal.cpp): without coords the new normal is the feature point nearest the unit normal
 * over size (brute force over 7^3 cells here), made unit as every perturbed normal is; normals in
 * one facet get the same one; with coords the push is tangent to the normal. */
static void check_facets(void)
{
	pattern_node n = pattern_node_default(PATTERN_FACETS);
	n.facets_size = 0.1;
	pattern_prog pg = {.nodes = &n, .n_nodes = 1};
	const dvec3 dirs[3] = {{0, 1, 0}, {0.6, 0, 0.8}, {-0.48, 0.6, -0.64}};
	for (int d = 0; d < 3; d++) {
		dvec3 v = d3_scale(dirs[d], 2.0), t = d3_scale(dirs[d], 10.0); /* not unit: facets normalises */
		pattern_perturb(&pg, 0, d3(5, 6, 7), &v);
		dvec3 best = t;
		double bd = 1e300;
		for (int i = -3; i <= 3; i++)
			for (int j = -3; j <= 3; j++)
				for (int k = -3; k <= 3; k++) {
					dvec3 f = pattern_crackle_point((int)floor(t.x) + i, (int)floor(t.y) + j, (int)floor(t.z) + k);
					double e = d3_dot(d3_sub(f, t), d3_sub(f, t));
					if (e < bd)
						bd = e, best = f;
				}
		best = d3_normalize(best);
		CHECK(d3_length(d3_sub(v, best)) < 1e-12, "facets %d: <%g, %g, %g>, the nearest point <%g, %g, %g>", d, v.x,
		      v.y, v.z, best.x, best.y, best.z);
		dvec3 w = d3_add(dirs[d], d3(1e-7, -1e-7, 1e-7)); /* a normal next to it: the same facet */
		pattern_perturb(&pg, 0, d3(-3, 1, 2), &w);
		CHECK(d3_length(d3_sub(w, best)) < 1e-12, "facets are flat: <%g, %g, %g>", w.x, w.y, w.z);
	}
	n.facets_coords = 0.5;
	dvec3 v = d3(0, 0, 1);
	pattern_perturb(&pg, 0, d3(0.33, 0.77, 1.5), &v);
	CHECK(fabs(d3_length(v) - 1.0) < 1e-12 && v.z > 0.0 && (v.x != 0.0 || v.y != 0.0),
	      "facets coords pushes the normal sideways: <%g, %g, %g>",
	      v.x, v.y, v.z);
}

/* POV-Ray's 27 tilings, against povray 3.7.0 itself: a plane `pigment { tiling T color_map {
 * [0 rgb 0] [1 rgb 1] } }` seen from above by an orthographic camera (16 x 16 pixels over [0, 4]^2,
 * no antialiasing, ambient 1, assumed_gamma 1, File_Gamma 1, a 16-bit PNG): the pixel's value
 * over 65535 at its centre <x, 0, z>. (All 1536 pixels of the six agree to 1/65535; these are
 * six of each.) */
static void check_tiling(void)
{
	static const struct {
		int tiling;
		double x, z;
		int pov16;
	} rows[] = {
		{1, 3.375, 3.875, 49151},
		{1, 3.625, 3.125, 49151},
		{1, 2.875, 2.375, 49151},
		{1, 1.625, 1.375, 16384},
		{1, 0.625, 0.625, 16384},
		{1, 2.375, 0.125, 49151},
		{2, 3.375, 3.875, 34441},
		{2, 3.625, 3.125, 39874},
		{2, 2.875, 2.375, 49400},
		{2, 1.625, 1.375, 38085},
		{2, 0.625, 0.625, 18239},
		{2, 2.375, 0.125, 29305},
		{3, 3.375, 3.875, 19225},
		{3, 3.625, 3.125, 47917},
		{3, 2.875, 2.375, 41332},
		{3, 1.625, 1.375, 48936},
		{3, 0.625, 0.625, 31376},
		{3, 2.375, 0.125, 18579},
		{4, 3.375, 3.875, 47478},
		{4, 3.625, 3.125, 42045},
		{4, 2.875, 2.375, 31773},
		{4, 1.625, 1.375, 43403},
		{4, 0.625, 0.625, 30912},
		{4, 2.375, 0.125, 46617},
		{5, 3.375, 3.875, 15826},
		{5, 3.625, 3.125, 48428},
		{5, 2.875, 2.375, 32933},
		{5, 1.625, 1.375, 36313},
		{5, 0.625, 0.625, 10304},
		{5, 2.375, 0.125, 59229},
		{6, 3.375, 3.875, 40959},
		{6, 3.625, 3.125, 57343},
		{6, 2.875, 2.375, 57343},
		{6, 1.625, 1.375, 40959},
		{6, 0.625, 0.625, 40959},
		{6, 2.375, 0.125, 24576},
		/* tilings 7 to 24, from a 64 x 64 render over [-6, 6]^2 (all 4096 pixels of each of 1 to 24 agree) */
		{7, -0.65625, 5.71875, 58096},
		{7, 4.40625, 3.65625, 63246},
		{7, 0.84375, 1.59375, 63547},
		{7, -2.53125, -0.46875, 32768},
		{7, 1.96875, -2.90625, 32768},
		{7, -5.15625, -5.34375, 32768},
		{8, -0.65625, 5.71875, 56403},
		{8, 4.40625, 3.65625, 37954},
		{8, 0.84375, 1.59375, 31464},
		{8, -2.53125, -0.46875, 30706},
		{8, 1.96875, -2.90625, 63170},
		{8, -5.15625, -5.34375, 46289},
		{9, -0.65625, 5.71875, 43690},
		{9, 4.40625, 3.65625, 50995},
		{9, 0.84375, 1.59375, 55069},
		{9, -2.53125, -0.46875, 43690},
		{9, 1.96875, -2.90625, 46476},
		{9, -5.15625, -5.34375, 54366},
		{10, -0.65625, 5.71875, 45055},
		{10, 4.40625, 3.65625, 53247},
		{10, 0.84375, 1.59375, 20480},
		{10, -2.53125, -0.46875, 61439},
		{10, 1.96875, -2.90625, 53247},
		{10, -5.15625, -5.34375, 45055},
		{11, -0.65625, 5.71875, 53247},
		{11, 4.40625, 3.65625, 28672},
		{11, 0.84375, 1.59375, 58708},
		{11, -2.53125, -0.46875, 23210},
		{11, 1.96875, -2.90625, 39594},
		{11, -5.15625, -5.34375, 58708},
		{12, -0.65625, 5.71875, 53247},
		{12, 4.40625, 3.65625, 28672},
		{12, 0.84375, 1.59375, 58708},
		{12, -2.53125, -0.46875, 23210},
		{12, 1.96875, -2.90625, 42325},
		{12, -5.15625, -5.34375, 58708},
		{13, -0.65625, 5.71875, 39866},
		{13, 4.40625, 3.65625, 14386},
		{13, 0.84375, 1.59375, 13402},
		{13, -2.53125, -0.46875, 58039},
		{13, 1.96875, -2.90625, 38882},
		{13, -5.15625, -5.34375, 35498},
		{14, -0.65625, 5.71875, 37026},
		{14, 4.40625, 3.65625, 61060},
		{14, 0.84375, 1.59375, 60469},
		{14, -2.53125, -0.46875, 21716},
		{14, 1.96875, -2.90625, 49543},
		{14, -5.15625, -5.34375, 34406},
		{15, -0.65625, 5.71875, 32768},
		{15, 4.40625, 3.65625, 38911},
		{15, 0.84375, 1.59375, 32768},
		{15, -2.53125, -0.46875, 32768},
		{15, 1.96875, -2.90625, 63487},
		{15, -5.15625, -5.34375, 43007},
		{16, -0.65625, 5.71875, 43690},
		{16, 4.40625, 3.65625, 19066},
		{16, 0.84375, 1.59375, 43690},
		{16, -2.53125, -0.46875, 11226},
		{16, 1.96875, -2.90625, 35916},
		{16, -5.15625, -5.34375, 43690},
		{17, -0.65625, 5.71875, 54613},
		{17, 4.40625, 3.65625, 20456},
		{17, 0.84375, 1.59375, 54613},
		{17, -2.53125, -0.46875, 16536},
		{17, 1.96875, -2.90625, 39803},
		{17, -5.15625, -5.34375, 54613},
		{18, -0.65625, 5.71875, 14336},
		{18, 4.40625, 3.65625, 10240},
		{18, 0.84375, 1.59375, 55295},
		{18, -2.53125, -0.46875, 2048},
		{18, 1.96875, -2.90625, 63487},
		{18, -5.15625, -5.34375, 55295},
		{19, -0.65625, 5.71875, 19091},
		{19, 4.40625, 3.65625, 7304},
		{19, 0.84375, 1.59375, 43690},
		{19, -2.53125, -0.46875, 30706},
		{19, 1.96875, -2.90625, 43690},
		{19, -5.15625, -5.34375, 39035},
		{20, -0.65625, 5.71875, 43690},
		{20, 4.40625, 3.65625, 7304},
		{20, 0.84375, 1.59375, 43690},
		{20, -2.53125, -0.46875, 30706},
		{20, 1.96875, -2.90625, 46476},
		{20, -5.15625, -5.34375, 43690},
		{21, -0.65625, 5.71875, 61159},
		{21, 4.40625, 3.65625, 61611},
		{21, 0.84375, 1.59375, 64576},
		{21, -2.53125, -0.46875, 62760},
		{21, 1.96875, -2.90625, 50848},
		{21, -5.15625, -5.34375, 4306},
		{22, -0.65625, 5.71875, 43690},
		{22, 4.40625, 3.65625, 44326},
		{22, 0.84375, 1.59375, 43690},
		{22, -2.53125, -0.46875, 43690},
		{22, 1.96875, -2.90625, 52353},
		{22, -5.15625, -5.34375, 43690},
		{23, -0.65625, 5.71875, 43690},
		{23, 4.40625, 3.65625, 5987},
		{23, 0.84375, 1.59375, 20908},
		{23, -2.53125, -0.46875, 4488},
		{23, 1.96875, -2.90625, 2845},
		{23, -5.15625, -5.34375, 40378},
		{24, -0.65625, 5.71875, 52428},
		{24, 4.40625, 3.65625, 3592},
		{24, 0.84375, 1.59375, 12545},
		{24, -2.53125, -0.46875, 2693},
		{24, 1.96875, -2.90625, 1707},
		{24, -5.15625, -5.34375, 24227},
		/* the Penrose tilings 25 to 27, from 64 x 64 renders over [-60, 60]^2 (all pixels agree; 25 also
		 * over [-6, 6]^2: its last two rows here) */
		{25, -6.5625, 57.1875, 24562},
		{25, 44.0625, 36.5625, 28657},
		{25, 8.4375, 15.9375, 54216},
		{25, -25.3125, -4.6875, 30182},
		{25, 19.6875, -29.0625, 38246},
		{25, -51.5625, -53.4375, 21071},
		{25, 4.59375, 3.28125, 28153},
		{25, -0.09375, -4.78125, 25325},
		{26, -6.5625, 57.1875, 55622},
		{26, 44.0625, 36.5625, 20552},
		{26, 8.4375, 15.9375, 19939},
		{26, -25.3125, -4.6875, 0},
		{26, 19.6875, -29.0625, 32623},
		{26, -51.5625, -53.4375, 55680},
		{27, -6.5625, 57.1875, 25143},
		{27, 44.0625, 36.5625, 4423},
		{27, 8.4375, 15.9375, 10362},
		{27, -25.3125, -4.6875, 64580},
		{27, 19.6875, -29.0625, 65424},
		{27, -51.5625, -53.4375, 0},
	};
	for (size_t i = 0; i < sizeof rows / sizeof *rows; i++) {
		pattern_node n = pattern_node_default(PATTERN_TILING);
		n.tiling = rows[i].tiling;
		double v = pattern_raw(&n, d3(rows[i].x, 0.0, rows[i].z)), want = rows[i].pov16 / 65535.0;
		CHECK(fabs(v - want) <= 1.0 / 65535.0, "tiling %d at <%g, 0, %g>: %.6f, povray %.6f", rows[i].tiling, rows[i].x,
		      rows[i].z, v, want);
	}
	pattern_node n = pattern_node_default(PATTERN_TILING);
	n.tiling = 0; /* 0 (and POV-Ray's numbers past 27): squares */
	CHECK_NEAR(pattern_raw(&n, d3(-1.25, 3, 0.5)), 0.5, 1e-12);
}

/* material_map (imageutil.cpp): the entry a palette image's index names (or another image's red
 * times 255), past the count n wrapped mod n, n itself the last entry; the first outside a once
 * image. Entries: three colours. */
static void check_material_map(void)
{
	float px[16] = {0, 0, 0, 1, 2, 0, 0, 1, 4, 0, 0, 1, 3, 0, 0, 1}; /* indices 0, 2, 4, 3 in a row */
	image img = {.width = 4, .height = 1, .rgba = px, .indexed = true};
	pattern_node n = pattern_node_default(PATTERN_MATERIAL_MAP);
	pattern_entry e[3] = {{.value = 0, .color = {1, 0, 0}, .node = -1},
			      {.value = 1, .color = {0, 1, 0}, .node = -1},
			      {.value = 2, .color = {0, 0, 1}, .node = -1}};
	n.img = &img, n.n_entries = 3;
	pattern_prog pg = {.nodes = &n, .n_nodes = 1, .entries = e, .n_entries = 3};
	const double want[4] = {0, 2, 1, 2}; /* 4 > 3: 4 mod 3 = 1; 3 = n: the last */
	for (int i = 0; i < 4; i++) {
		float c[5];
		pattern_eval(&pg, 0, d3(0.125 + 0.25 * i, 0.5, 0), 0, c);
		int got = c[0] == 1 ? 0 : c[1] == 1 ? 1 : c[2] == 1 ? 2 : -1;
		CHECK(got == (int)want[i], "material_map texel %d: entry %d, want %g", i, got, want[i]);
	}
	n.once = true;
	CHECK_NEAR(pattern_raw(&n, d3(1.5, 0.5, 0)), 0.0, 0.0);
	n.once = false, img.indexed = false; /* a colour image: red times 255 (2/255 is entry 2) */
	px[4] = 2.0f / 255.0f;
	CHECK_NEAR(pattern_raw(&n, d3(0.375, 0.5, 0)), 2.0, 0.0);
}

int main(void)
{
	check_slope();
	check_material_map();
	check_tiling();
	check_facets();
	check_image_pattern();
	check_density_file();
	check_normals();
	check_crackle();
	check_fractals();
	check_slope_map();
	check_average();
	check_normal_map();
	check_tolerance();
	check_pigment_pattern();
	check_layers();
	check_table();
	check_waves();
	check_colour_map();
	check_nested();
	check_warps();
	check_noise();
	check_image();
	check_defaults();
	return check_done("test_pattern");
}
