/* text.c - POV-Ray's text { ttf "font" "string" depth, offset } as a mesh: each glyph's outline
 * read through FreeType (unscaled, in font units; 1 em is 1 unit, as POV-Ray), its quadratic and
 * cubic pieces flattened to the accuracy, the caps at z = 0 (facing -z) and z = depth filled by the
 * even-odd rule (poly2d.c), the sides extruded. Glyphs are placed as POV-Ray's ProcessNewTTF does
 * (core/shape/truetype.cpp): the first glyph's left edge at x = 0, each next one at the previous
 * advance plus its kerning (the font's 'kern' table), and `offset` added after every character. */
#include "geom/shape.h"

#include "base/mem.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <math.h>
#include <string.h>

/* The outline of one glyph, flattened: contours of points in em units. */
typedef struct glyph_path {
	double *xy;
	uint32_t n, cap;
	uint32_t *counts;
	uint32_t nc, cap_c;
	double tol_fu; /* the tolerance in font units */
	double scale; /* em per font unit */
	double last[2]; /* the pen, font units */
	bool failed;
} glyph_path;

static void gp_point(glyph_path *g, double x, double y)
{
	if (g->failed || !g->nc)
		return;
	if (g->n == g->cap) {
		uint32_t cap = g->cap ? 2 * g->cap : 256;
		double *p = mem_realloc(g->xy, 2 * (size_t)cap, sizeof *p);
		if (!p) {
			g->failed = true;
			return;
		}
		g->xy = p, g->cap = cap;
	}
	g->xy[2 * g->n] = x * g->scale, g->xy[2 * g->n + 1] = y * g->scale;
	g->n++;
	g->counts[g->nc - 1]++;
	g->last[0] = x, g->last[1] = y;
}

static int gp_move(const FT_Vector *to, void *user)
{
	glyph_path *g = user;
	if (g->nc == g->cap_c) {
		uint32_t cap = g->cap_c ? 2 * g->cap_c : 16;
		uint32_t *c = mem_realloc(g->counts, cap, sizeof *c);
		if (!c) {
			g->failed = true;
			return 1;
		}
		g->counts = c, g->cap_c = cap;
	}
	g->counts[g->nc++] = 0;
	gp_point(g, (double)to->x, (double)to->y);
	return 0;
}

static int gp_line(const FT_Vector *to, void *user)
{
	gp_point(user, (double)to->x, (double)to->y);
	return 0;
}

/* A Bezier piece of degree 2 or 3 in power form (A t^3 + B t^2 + C t + D), flattened. */
static void gp_curve(glyph_path *g, const double P[4][2], int degree)
{
	double A[2], B[2], C[2], D[2];
	for (int c = 0; c < 2; c++) {
		if (degree == 2) {
			A[c] = 0, B[c] = P[0][c] - 2 * P[1][c] + P[2][c], C[c] = 2 * (P[1][c] - P[0][c]), D[c] = P[0][c];
		} else {
			A[c] = P[3][c] - 3 * P[2][c] + 3 * P[1][c] - P[0][c];
			B[c] = 3 * P[2][c] - 6 * P[1][c] + 3 * P[0][c];
			C[c] = 3 * P[1][c] - 3 * P[0][c], D[c] = P[0][c];
		}
	}
	uint32_t m = shape_cubic_steps(A, B, g->tol_fu);
	for (uint32_t j = 1; j <= m; j++) {
		double t = (double)j / m;
		gp_point(g, ((A[0] * t + B[0]) * t + C[0]) * t + D[0], ((A[1] * t + B[1]) * t + C[1]) * t + D[1]);
	}
}

static int gp_conic(const FT_Vector *c, const FT_Vector *to, void *user)
{
	glyph_path *g = user;
	double P[4][2] = {{g->last[0], g->last[1]}, {(double)c->x, (double)c->y}, {(double)to->x, (double)to->y}};
	gp_curve(g, P, 2);
	return 0;
}

static int gp_cubic(const FT_Vector *c1, const FT_Vector *c2, const FT_Vector *to, void *user)
{
	glyph_path *g = user;
	double P[4][2] = {{g->last[0], g->last[1]}, {(double)c1->x, (double)c1->y}, {(double)c2->x, (double)c2->y},
			  {(double)to->x, (double)to->y}};
	gp_curve(g, P, 3);
	return 0;
}

/* Drops repeated points (a contour's closing point, zero-length pieces) and contours of fewer
 * than three points, in place. */
static void gp_clean(glyph_path *g)
{
	uint32_t w = 0, wc = 0;
	for (uint32_t k = 0, a = 0, n; k < g->nc; a += n, k++) {
		uint32_t start = w;
		n = g->counts[k]; /* read before counts[wc] (wc <= k) is written */
		for (uint32_t i = 0; i < n; i++) {
			const double *p = &g->xy[2 * (a + i)];
			if (w > start && p[0] == g->xy[2 * (w - 1)] && p[1] == g->xy[2 * (w - 1) + 1])
				continue;
			g->xy[2 * w] = p[0], g->xy[2 * w + 1] = p[1];
			w++;
		}
		while (w - start > 1 && g->xy[2 * (w - 1)] == g->xy[2 * start] && g->xy[2 * (w - 1) + 1] == g->xy[2 * start + 1])
			w--;
		if (w - start < 3) {
			w = start;
			continue;
		}
		g->counts[wc++] = w - start;
	}
	g->n = w, g->nc = wc;
}

/* The next code point of the UTF-8 string at *s (a bad byte reads as itself). */
static uint32_t utf8_next(const unsigned char **s)
{
	const unsigned char *p = *s;
	uint32_t c = *p++;
	int more = c >= 0xF0 ? 3 : c >= 0xE0 ? 2 : c >= 0xC0 ? 1 : 0;
	uint32_t v = more == 3 ? c & 7 : more == 2 ? c & 15 : more == 1 ? c & 31 : c;
	for (int i = 0; i < more; i++) {
		if ((*p & 0xC0) != 0x80) {
			*s = *s + 1;
			return c;
		}
		v = v << 6 | (*p++ & 63);
	}
	*s = p;
	return v;
}

/* Adds one glyph's caps and sides, moved by (dx, dy, dz), to the builder. */
static bool add_glyph(shape_builder *b, glyph_path *g, double depth, dvec3 at)
{
	gp_clean(g);
	if (!g->nc)
		return true;
	poly2d_orient(g->xy, g->counts, g->nc, NULL);
	uint32_t *tri;
	long nt = poly2d_triangulate(g->xy, g->counts, g->nc, &tri);
	if (nt < 0)
		return false;
	double z0 = fmin(0, depth) + at.z, z1 = fmax(0, depth) + at.z;
	for (int side = 0; side < 2; side++) {
		double z = side ? z1 : z0, nz = side ? 1 : -1;
		uint32_t base = b->nv;
		for (uint32_t i = 0; i < g->n; i++)
			sb_vertex(b, d3(g->xy[2 * i] + at.x, g->xy[2 * i + 1] + at.y, z), d3(0, 0, nz), 0, 0);
		for (long t = 0; t < nt; t++)
			sb_tri(b, base + tri[3 * t], base + tri[3 * t + 1], base + tri[3 * t + 2], d3(0, 0, nz));
	}
	mem_free(tri);
	for (uint32_t k = 0, a = 0; k < g->nc; a += g->counts[k], k++)
		for (uint32_t i = 0, n = g->counts[k]; i < n; i++) {
			const double *p = &g->xy[2 * (a + i)], *q = &g->xy[2 * (a + (i + 1) % n)];
			dvec3 want = d3(q[1] - p[1], -(q[0] - p[0]), 0); /* outward of a counter-clockwise outline */
			dvec3 P0 = d3(p[0] + at.x, p[1] + at.y, z0), Q0 = d3(q[0] + at.x, q[1] + at.y, z0);
			dvec3 P1 = d3(P0.x, P0.y, z1), Q1 = d3(Q0.x, Q0.y, z1);
			uint32_t v0 = sb_vertex(b, P0, want, 0, 0), v1 = sb_vertex(b, Q0, want, 0, 0);
			uint32_t v2 = sb_vertex(b, Q1, want, 0, 0), v3 = sb_vertex(b, P1, want, 0, 0);
			sb_tri(b, v0, v1, v2, want);
			sb_tri(b, v0, v2, v3, want);
		}
	return !b->failed;
}

static bool load_outline(FT_Face face, FT_UInt gi, glyph_path *g)
{
	if (FT_Load_Glyph(face, gi, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP))
		return false;
	if (face->glyph->format != FT_GLYPH_FORMAT_OUTLINE)
		return true; /* no outline (a space): advance only */
	FT_Outline_Funcs fn = {gp_move, gp_line, gp_conic, gp_cubic, 0, 0};
	return FT_Outline_Decompose(&face->glyph->outline, &fn, g) == 0 && !g->failed;
}

bool shape_text(const shape_desc *s, const shape_accuracy *acc, mesh *out, diag *d, diag_loc loc)
{
	FT_Library lib;
	FT_Face face;
	if (FT_Init_FreeType(&lib)) {
		diag_error(d, loc, "FreeType could not start");
		return false;
	}
	if (FT_New_Face(lib, s->font, 0, &face)) {
		FT_Done_FreeType(lib);
		diag_error(d, loc, "font '%s': FreeType cannot read it as a TrueType font", s->font);
		return false;
	}
	FT_Select_Charmap(face, FT_ENCODING_UNICODE);
	double fu = 1.0 / (face->units_per_EM ? face->units_per_EM : 2048);
	shape_builder b;
	sb_init(&b);
	bool ok = true;
	dvec3 total = d3(0, 0, 0);
	FT_UInt last = 0;
	const unsigned char *p = (const unsigned char *)s->text;
	for (int i = 0; *p && ok; i++) {
		FT_UInt gi = FT_Get_Char_Index(face, utf8_next(&p));
		glyph_path g = {.tol_fu = acc->tol / fu, .scale = fu};
		ok = load_outline(face, gi, &g);
		if (!ok)
			break;
		FT_BBox box;
		FT_Outline_Get_CBox(&face->glyph->outline, &box);
		double xmin = face->glyph->format == FT_GLYPH_FORMAT_OUTLINE && face->glyph->outline.n_points ? (double)box.xMin : 0;
		double aw = (double)face->glyph->metrics.horiAdvance, lsb = (double)face->glyph->metrics.horiBearingX;
		dvec3 at;
		if (i == 0) { /* the first glyph's left edge at 0; the pen then at its advance less its bearing */
			at = d3(-xmin * fu, 0, 0);
			total.x = (aw - lsb) * fu;
		} else {
			FT_Vector kern = {0, 0};
			if (FT_HAS_KERNING(face))
				FT_Get_Kerning(face, last, gi, FT_KERNING_UNSCALED, &kern);
			at = d3(total.x + (lsb - xmin + (double)kern.x) * fu, total.y, total.z);
			total.x += (aw + (double)kern.x) * fu;
		}
		ok = add_glyph(&b, &g, s->depth, at);
		mem_free(g.xy), mem_free(g.counts);
		total = d3_add(total, s->offset);
		last = gi;
		if (b.nt >= SHAPE_MAX_TRIANGLES)
			break;
	}
	FT_Done_Face(face);
	FT_Done_FreeType(lib);
	if (!ok) {
		sb_free(&b);
		diag_error(d, loc, "out of memory while tessellating the text");
		return false;
	}
	return sb_finish(&b, out, false, "text", d, loc);
}
