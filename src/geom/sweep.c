/* sweep.c - POV-Ray's swept shapes as meshes: lathe and sor (a curve turned about y), prism (an
 * outline swept along y, linearly or towards the origin) and sphere_sweep (a sphere moved along a
 * spline). The splines are POV-Ray 3.7's (core/shape/lathe.cpp, prism.cpp, sor.cpp,
 * spheresweep.cpp: the same coefficients, re-derived here). */
#include "geom/shape.h"

#include "base/mem.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

/* POV-Ray's EPSILON (core/configcore.h): two outline points this close close a sub-prism. */
#define SHAPE_POV_EPSILON 1e-10

/* One cubic piece P(t) = ((A t + B) t + C) t + D, t in [0, 1]. */
typedef struct seg2 {
	double A[2], B[2], C[2], D[2];
	bool starts_contour; /* prism: the first piece of a sub-polygon */
} seg2;

static void seg_at(const seg2 *s, double t, double *p, double *dp)
{
	for (int c = 0; c < 2; c++) {
		p[c] = ((s->A[c] * t + s->B[c]) * t + s->C[c]) * t + s->D[c];
		dp[c] = (3 * s->A[c] * t + 2 * s->B[c]) * t + s->C[c];
	}
}

/* The piece of spline `sp` starting at point i of P (POV-Ray's Compute_Lathe / Compute_Prism). */
static seg2 make_seg(shape_spline sp, const double *P, uint32_t i)
{
	seg2 s = {0};
	const double *p0 = &P[2 * i], *p1 = &P[2 * i + 2], *p2 = &P[2 * i + 4], *p3 = &P[2 * i + 6];
	for (int c = 0; c < 2; c++)
		switch (sp) {
		case SHAPE_LINEAR:
			s.C[c] = p1[c] - p0[c], s.D[c] = p0[c];
			break;
		case SHAPE_QUADRATIC:
			s.B[c] = 0.5 * p0[c] - p1[c] + 0.5 * p2[c];
			s.C[c] = -0.5 * p0[c] + 0.5 * p2[c];
			s.D[c] = p1[c];
			break;
		case SHAPE_CUBIC: /* Catmull-Rom from p1 to p2 */
			s.A[c] = -0.5 * p0[c] + 1.5 * p1[c] - 1.5 * p2[c] + 0.5 * p3[c];
			s.B[c] = p0[c] - 2.5 * p1[c] + 2.0 * p2[c] - 0.5 * p3[c];
			s.C[c] = -0.5 * p0[c] + 0.5 * p2[c];
			s.D[c] = p1[c];
			break;
		default: /* Bezier */
			s.A[c] = p3[c] - 3 * p2[c] + 3 * p1[c] - p0[c];
			s.B[c] = 3 * p2[c] - 6 * p1[c] + 3 * p0[c];
			s.C[c] = 3 * p1[c] - 3 * p0[c];
			s.D[c] = p0[c];
			break;
		}
	return s;
}

/* A lathe's pieces: n - 1, n - 2, n - 3 or n / 4 (linear, quadratic, cubic, Bezier). */
static uint32_t lathe_segs(const shape_desc *s, seg2 *out)
{
	uint32_t n = s->n_pts, k = 0;
	switch (s->spline) {
	case SHAPE_LINEAR: k = n - 1; break;
	case SHAPE_QUADRATIC: k = n - 2; break;
	case SHAPE_CUBIC: k = n - 3; break;
	default: k = n / 4; break;
	}
	for (uint32_t i = 0; i < k; i++)
		out[i] = make_seg(s->spline, s->pts, s->spline == SHAPE_BEZIER ? 4 * i : i);
	return k;
}

static bool near2(const double *a, const double *b)
{
	return fabs(a[0] - b[0]) < SHAPE_POV_EPSILON && fabs(a[1] - b[1]) < SHAPE_POV_EPSILON;
}

/* A prism's pieces, its sub-polygons delimited as Compute_Prism does: a piece whose end returns to
 * the sub-polygon's first point closes it, and the next sub-polygon begins after its control
 * points. Bezier pieces go four points at a time. */
static uint32_t prism_segs(const shape_desc *s, seg2 *out)
{
	const double *P = s->pts;
	uint32_t n = s->n_pts, k = 0;
	const double *first = s->spline == SHAPE_LINEAR ? &P[0] : &P[2];
	bool new_contour = true;
	for (uint32_t i = 0; i + 1 < n; i++) {
		uint32_t need = s->spline == SHAPE_LINEAR ? 1 : s->spline == SHAPE_QUADRATIC ? 2 : 3;
		if (i + need >= n)
			break;
		out[k] = make_seg(s->spline, P, i);
		out[k].starts_contour = new_contour;
		new_contour = false;
		k++;
		switch (s->spline) {
		case SHAPE_LINEAR:
			if (near2(&P[2 * (i + 1)], first)) {
				i++;
				if (i + 1 < n)
					first = &P[2 * (i + 1)];
				new_contour = true;
			}
			break;
		case SHAPE_QUADRATIC:
		case SHAPE_CUBIC:
			if (near2(&P[2 * (i + 2)], first)) {
				i += s->spline == SHAPE_QUADRATIC ? 2 : 3;
				if (i + 2 < n)
					first = &P[2 * (i + 2)];
				new_contour = true;
			}
			break;
		default: /* a Bezier piece ending where the contour began closes it */
			new_contour = false;
			if (k >= 1) {
				uint32_t c0 = k - 1;
				while (c0 > 0 && !out[c0].starts_contour)
					c0--;
				const double *p3 = &P[2 * (i + 3)];
				if (near2(p3, out[c0].D))
					new_contour = true;
			}
			i += 3;
			break;
		}
	}
	return k;
}

/* Appends the flattened points of piece g (without its end point) to xy; returns the count. */
static uint32_t flatten(const seg2 *g, double tol, double *xy, double *txy)
{
	uint32_t m = shape_cubic_steps(g->A, g->B, tol);
	for (uint32_t j = 0; j < m; j++) {
		double p[2], dp[2];
		seg_at(g, (double)j / m, p, dp);
		if (xy)
			xy[2 * j] = p[0], xy[2 * j + 1] = p[1];
		if (txy)
			txy[2 * j] = dp[0], txy[2 * j + 1] = dp[1];
	}
	return m;
}

/* ---- lathe and sor: a profile <r, y> turned about y ---- */

/* Segments around a circle of radius r: at least `given`, and enough that a chord stands at most
 * tol inside it (r (1 - cos(pi / S)) <= tol), at most 4096. */
static uint32_t around_segments(uint32_t given, double r, double tol)
{
	double need = r > tol ? ceil(M_PI / acos(1 - tol / r)) : 3;
	double S = fmax(given, need);
	return S > 4096 ? 4096 : S < 3 ? 3 : (uint32_t)S;
}

/* The largest |x| of a profile's points (a bound of its radius within the tolerance). */
static double max_radius(const double *pts, uint32_t n, int stride)
{
	double r = 0;
	for (uint32_t i = 0; i < n; i++)
		r = fmax(r, fabs(pts[(size_t)stride * i]));
	return r;
}

/* A profile sample: position, tangent, and v (POV-Ray's UV). */
typedef struct prof {
	double r, y, dr, dy, v;
	bool corner; /* begins a new piece: its own ring of vertices (normals do not blend across) */
} prof;

/* Turns the profile about y: rings of acc->segments vertices (one per vertex on the axis), u the
 * angle from +x towards +z over 2 pi (POV-Ray's UVCoord). `flip` turns the normals round. */
static void revolve(shape_builder *b, const prof *pr, uint32_t np, uint32_t S, bool flip)
{
	uint32_t prev = UINT32_MAX;
	bool prev_pole = false;
	for (uint32_t j = 0; j < np; j++) {
		const prof *q = &pr[j];
		bool pole = fabs(q->r) < 1e-12;
		double nr = q->dy, ny = -q->dr; /* outward when the profile rises away from the axis */
		if (flip)
			nr = -nr, ny = -ny;
		uint32_t base = b->nv;
		for (uint32_t i = 0; i <= (pole ? 0 : S); i++) {
			double th = 2 * M_PI * (double)(i % S) / S, c = cos(th), sn = sin(th);
			if (i % S == 0)
				c = 1, sn = 0;
			sb_vertex(b, d3(q->r * c, q->y, q->r * sn), d3(nr * c, ny, nr * sn), (double)i / S, q->v);
		}
		if (j > 0 && !q->corner && prev != UINT32_MAX && !(pole && prev_pole)) {
			const prof *o = &pr[j - 1];
			double mr = 0.5 * (o->dy + q->dy), my = -0.5 * (o->dr + q->dr);
			if (flip)
				mr = -mr, my = -my;
			for (uint32_t i = 0; i < S; i++) {
				double th = 2 * M_PI * (i + 0.5) / S;
				dvec3 want = d3(mr * cos(th), my, mr * sin(th));
				if (fabs(mr) + fabs(my) == 0)
					want = d3(0, 1, 0);
				uint32_t a0 = prev_pole ? prev : prev + i, a1 = prev_pole ? prev : prev + i + 1;
				uint32_t b0 = pole ? base : base + i, b1 = pole ? base : base + i + 1;
				if (!prev_pole)
					sb_tri(b, a0, a1, b1, want);
				if (!pole)
					sb_tri(b, a0, b1, b0, want);
			}
		}
		prev = base, prev_pole = pole;
	}
}

/* A disc cap of radius r at height y, normal (0, ny, 0), UV as POV-Ray's sor caps. */
static void cap_disc(shape_builder *b, double r, double y, double ny, uint32_t S, double v_centre, double v_rim)
{
	uint32_t c = sb_vertex(b, d3(0, y, 0), d3(0, ny, 0), 0, v_centre);
	uint32_t base = b->nv;
	for (uint32_t i = 0; i <= S; i++) {
		double th = 2 * M_PI * (double)(i % S) / S;
		double cs = i % S ? cos(th) : 1, sn = i % S ? sin(th) : 0;
		sb_vertex(b, d3(r * cs, y, r * sn), d3(0, ny, 0), (double)i / S, v_rim);
	}
	for (uint32_t i = 0; i < S; i++)
		sb_tri(b, c, base + i, base + i + 1, d3(0, ny, 0));
}

bool shape_lathe(const shape_desc *s, const shape_accuracy *acc, mesh *out, diag *d, diag_loc loc)
{
	seg2 *sg = mem_alloc(s->n_pts, sizeof *sg);
	if (!sg) {
		diag_error(d, loc, "out of memory while tessellating the lathe");
		return false;
	}
	uint32_t ns = lathe_segs(s, sg);
	/* half the tolerance along the profile, half around it */
	double tol = 0.5 * acc->tol;
	size_t np = 0;
	for (uint32_t i = 0; i < ns; i++)
		np += shape_cubic_steps(sg[i].A, sg[i].B, tol) + 1;
	size_t S = around_segments(acc->segments, 1.2 * max_radius(s->pts, s->n_pts, 2), tol), tris = 2 * np * S;
	if (tris > SHAPE_MAX_TRIANGLES) {
		mem_free(sg);
		diag_error(d, loc, "the lathe would make %zu triangles (the limit of one shape is %u)", tris,
			   SHAPE_MAX_TRIANGLES);
		return false;
	}
	prof *pr = mem_alloc(np, sizeof *pr);
	if (!pr) {
		mem_free(sg);
		diag_error(d, loc, "out of memory while tessellating the lathe");
		return false;
	}
	uint32_t k = 0;
	double area = 0; /* the profile's orientation: closed, by its area; open, by its rise */
	for (uint32_t i = 0; i < ns; i++) {
		uint32_t m = shape_cubic_steps(sg[i].A, sg[i].B, tol);
		for (uint32_t j = 0; j <= m; j++) {
			double p[2], dp[2], t = (double)j / m;
			seg_at(&sg[i], t, p, dp);
			pr[k] = (prof){p[0], p[1], dp[0], dp[1], fmin(1.0, (i + t) / ns), j == 0};
			if (k > 0)
				area += pr[k - 1].r * pr[k].y - pr[k].r * pr[k - 1].y;
			k++;
		}
	}
	double *f = sg[0].D, l[2], dl[2];
	seg_at(&sg[ns - 1], 1.0, l, dl);
	bool closed = near2(f, l);
	/* (dy, -dr) points away from the axis on a rising profile: outward for an open profile
	 * that rises and for a closed one running counter-clockwise in <r, y>. */
	bool flip = closed ? area < 0 : l[1] < f[1];
	shape_builder b;
	sb_init(&b);
	revolve(&b, pr, k, (uint32_t)S, flip);
	mem_free(pr), mem_free(sg);
	return sb_finish(&b, out, true, "lathe", d, loc);
}

/* The cubic r^2(y) = A y^3 + B y^2 + C y + D of sor piece i (POV-Ray's Compute_Sor: through the
 * squared radii at P[i+1], P[i+2] with the slopes of the neighbouring chords). */
static void sor_coef(const double *P, uint32_t i, double c[4])
{
	const double *p0 = &P[2 * i], *p1 = &P[2 * i + 2], *p2 = &P[2 * i + 4], *p3 = &P[2 * i + 6];
	double k[4] = {p1[0] * p1[0], p2[0] * p2[0], 2 * p1[0] * (p2[0] - p0[0]) / (p2[1] - p0[1]),
		       2 * p2[0] * (p3[0] - p1[0]) / (p3[1] - p1[1])};
	double w1 = p1[1], w2 = p2[1];
	double M[4][5] = {{w1 * w1 * w1, w1 * w1, w1, 1, k[0]}, {w2 * w2 * w2, w2 * w2, w2, 1, k[1]},
			  {3 * w1 * w1, 2 * w1, 1, 0, k[2]}, {3 * w2 * w2, 2 * w2, 1, 0, k[3]}};
	for (int col = 0; col < 4; col++) { /* Gauss-Jordan with partial pivoting */
		int piv = col;
		for (int r = col + 1; r < 4; r++)
			if (fabs(M[r][col]) > fabs(M[piv][col]))
				piv = r;
		for (int q = 0; q < 5; q++) {
			double t = M[col][q];
			M[col][q] = M[piv][q], M[piv][q] = t;
		}
		for (int r = 0; r < 4; r++)
			if (r != col && M[col][col] != 0) {
				double f = M[r][col] / M[col][col];
				for (int q = 0; q < 5; q++)
					M[r][q] -= f * M[col][q];
			}
	}
	for (int q = 0; q < 4; q++)
		c[q] = M[q][q] != 0 ? M[q][4] / M[q][q] : 0;
}

static double sor_r(const double c[4], double y) { return sqrt(fmax(0, ((c[0] * y + c[1]) * y + c[2]) * y + c[3])); }

/* Steps in y over [y0, y1] keeping the chords of r(y) within tol: halves the step until the
 * midpoint and quarter points of each chord lie within tol of the curve (at most 2^12 steps). */
static uint32_t sor_steps(const double c[4], double y0, double y1, double tol)
{
	for (uint32_t n = 1; n < 4096; n *= 2) {
		bool ok = true;
		for (uint32_t j = 0; j < n && ok; j++) {
			double a = y0 + (y1 - y0) * j / n, e = y0 + (y1 - y0) * (j + 1) / n;
			double ra = sor_r(c, a), re = sor_r(c, e);
			for (int q = 1; q < 4 && ok; q++) {
				double t = q / 4.0, y = a + (e - a) * t;
				ok = fabs(sor_r(c, y) - (ra + (re - ra) * t)) <= tol;
			}
		}
		if (ok)
			return n;
	}
	return 4096;
}

bool shape_sor(const shape_desc *s, const shape_accuracy *acc, mesh *out, diag *d, diag_loc loc)
{
	uint32_t ns = s->n_pts - 3;
	double (*cf)[4] = mem_alloc(ns, sizeof *cf);
	uint32_t *steps = mem_alloc(ns, sizeof *steps);
	if (!cf || !steps) {
		mem_free(cf), mem_free(steps);
		diag_error(d, loc, "out of memory while tessellating the sor");
		return false;
	}
	size_t np = 0;
	for (uint32_t i = 0; i < ns; i++) {
		sor_coef(s->pts, i, cf[i]);
		steps[i] = sor_steps(cf[i], s->pts[2 * i + 3], s->pts[2 * i + 5], 0.5 * acc->tol);
		np += steps[i] + 1;
	}
	/* half the tolerance along the profile, half around it */
	size_t S = around_segments(acc->segments, 1.2 * max_radius(s->pts, s->n_pts, 2), 0.5 * acc->tol);
	size_t tris = 2 * np * S + 2 * S;
	prof *pr = tris <= SHAPE_MAX_TRIANGLES ? mem_alloc(np, sizeof *pr) : NULL;
	if (!pr) {
		mem_free(cf), mem_free(steps);
		if (tris > SHAPE_MAX_TRIANGLES)
			diag_error(d, loc, "the sor would make %zu triangles (the limit of one shape is %u)", tris,
				   SHAPE_MAX_TRIANGLES);
		else
			diag_error(d, loc, "out of memory while tessellating the sor");
		return false;
	}
	uint32_t k = 0;
	for (uint32_t i = 0; i < ns; i++) {
		double y0 = s->pts[2 * i + 3], y1 = s->pts[2 * i + 5];
		for (uint32_t j = 0; j <= steps[i]; j++) {
			double t = (double)j / steps[i], y = y0 + (y1 - y0) * t, r = sor_r(cf[i], y);
			/* dr/dy = (r^2)' / 2r; the tangent <dr, dy> scaled by 2r stays finite at r = 0 */
			double dr2 = (3 * cf[i][0] * y + 2 * cf[i][1]) * y + cf[i][2];
			pr[k++] = (prof){r, y, dr2, 2 * r > 1e-12 ? 2 * r : 1e-12, (i + t) / ns, j == 0};
		}
	}
	shape_builder b;
	sb_init(&b);
	revolve(&b, pr, k, (uint32_t)S, false);
	double rb = pr[0].r, rt = pr[k - 1].r, yb = pr[0].y, yt = pr[k - 1].y;
	mem_free(pr), mem_free(cf), mem_free(steps);
	if (!s->open) { /* POV-Ray's caps: v from -1 at the centre to 0 (base), 2 to 1 (top) */
		if (rb > 1e-12)
			cap_disc(&b, rb, yb, -1, (uint32_t)S, -1, 0);
		if (rt > 1e-12)
			cap_disc(&b, rt, yt, 1, (uint32_t)S, 2, 1);
	}
	return sb_finish(&b, out, true, "sor", d, loc);
}

/* ---- prism: an outline in <x, z> swept along y ---- */

/* The prism's outline flattened: contours of points (x, z) with their tangents. */
typedef struct outline {
	double *xy, *txy;
	uint32_t *counts;
	uint32_t n_contours, n_points;
} outline;

static void outline_free(outline *o) { mem_free(o->xy), mem_free(o->txy), mem_free(o->counts); }

static bool prism_outline(const shape_desc *s, double tol, outline *o)
{
	memset(o, 0, sizeof *o);
	seg2 *sg = mem_alloc(s->n_pts, sizeof *sg);
	if (!sg)
		return false;
	uint32_t ns = prism_segs(s, sg);
	size_t np = 0;
	for (uint32_t i = 0; i < ns; i++)
		np += shape_cubic_steps(sg[i].A, sg[i].B, tol);
	o->xy = mem_alloc(2 * np + 2, sizeof *o->xy), o->txy = mem_alloc(2 * np + 2, sizeof *o->txy);
	o->counts = mem_alloc(ns + 1, sizeof *o->counts);
	if (!o->xy || !o->txy || !o->counts) {
		mem_free(sg), outline_free(o);
		return false;
	}
	for (uint32_t i = 0; i < ns; i++) {
		if (sg[i].starts_contour)
			o->counts[o->n_contours++] = 0;
		uint32_t m = flatten(&sg[i], tol, &o->xy[2 * o->n_points], &o->txy[2 * o->n_points]);
		o->n_points += m;
		o->counts[o->n_contours - 1] += m;
	}
	mem_free(sg);
	return true;
}

/* Orients the outline (poly2d_orient), its tangents turned with the contours it reversed. */
static bool orient_outline(outline *o)
{
	bool *rev = mem_calloc(o->n_contours ? o->n_contours : 1, sizeof *rev);
	if (!rev)
		return false;
	poly2d_orient(o->xy, o->counts, o->n_contours, rev);
	for (uint32_t k = 0, a = 0; k < o->n_contours; a += o->counts[k], k++) {
		uint32_t n = o->counts[k];
		if (!rev[k])
			continue;
		for (uint32_t i = 0, j = n - 1; i < j; i++, j--) /* reversed and negated */
			for (int c = 0; c < 2; c++) {
				double t = o->txy[2 * (a + i) + c];
				o->txy[2 * (a + i) + c] = -o->txy[2 * (a + j) + c];
				o->txy[2 * (a + j) + c] = -t;
			}
		if (n % 2)
			for (int c = 0; c < 2; c++)
				o->txy[2 * (a + n / 2) + c] = -o->txy[2 * (a + n / 2) + c];
	}
	mem_free(rev);
	return true;
}

/* The point of the prism's outline (x, z) at height y: as is for a linear sweep, scaled by y
 * towards the apex at the origin for a conic one. */
static dvec3 prism_point(const shape_desc *s, const double *p, double y)
{
	double k = s->conic ? y : 1.0;
	return d3(p[0] * k, y, p[1] * k);
}

static void prism_walls(shape_builder *b, const shape_desc *s, const outline *o, bool smooth)
{
	for (uint32_t k = 0, a = 0; k < o->n_contours; a += o->counts[k], k++)
		for (uint32_t i = 0, n = o->counts[k]; i < n; i++) {
			const double *p = &o->xy[2 * (a + i)], *q = &o->xy[2 * (a + (i + 1) % n)];
			/* Counter-clockwise outer contours in (x, z): outward is (dz, -dx) rotated into 3-D. */
			dvec3 P1 = prism_point(s, p, s->h1), P2 = prism_point(s, p, s->h2);
			dvec3 Q1 = prism_point(s, q, s->h1), Q2 = prism_point(s, q, s->h2);
			dvec3 want = d3_cross(d3_sub(Q1, P1), d3_sub(P2, P1));
			if (d3_length(want) == 0)
				want = d3_cross(d3_sub(Q2, P2), d3_sub(P2, P1));
			want = d3_scale(want, -1);
			dvec3 np_ = want, nq = want;
			if (smooth) {
				const double *tp = &o->txy[2 * (a + i)], *tq = &o->txy[2 * (a + (i + 1) % n)];
				np_ = d3(tp[1], 0, -tp[0]), nq = d3(tq[1], 0, -tq[0]);
				if (s->conic) /* the conic wall leans: its normal gains a y part */
					np_.y = -(p[0] * np_.x + p[1] * np_.z), nq.y = -(q[0] * nq.x + q[1] * nq.z);
			}
			uint32_t v0 = sb_vertex(b, P1, np_, 0, 0), v1 = sb_vertex(b, Q1, nq, 0, 0);
			uint32_t v2 = sb_vertex(b, Q2, nq, 0, 0), v3 = sb_vertex(b, P2, np_, 0, 0);
			if (!s->conic || s->h1 != 0)
				sb_tri(b, v0, v1, v2, want);
			if (!s->conic || s->h2 != 0)
				sb_tri(b, v0, v2, v3, want);
		}
}

static bool prism_caps(shape_builder *b, const shape_desc *s, const outline *o)
{
	uint32_t *tri;
	long nt = poly2d_triangulate(o->xy, o->counts, o->n_contours, &tri);
	if (nt < 0)
		return false;
	for (int side = 0; side < 2; side++) {
		double y = side ? s->h2 : s->h1, ny = side ? 1 : -1;
		if (s->conic && y == 0) /* the apex: no cap */
			continue;
		uint32_t base = b->nv;
		for (uint32_t i = 0; i < o->n_points; i++)
			sb_vertex(b, prism_point(s, &o->xy[2 * i], y), d3(0, ny, 0), 0, 0);
		for (long t = 0; t < nt; t++)
			sb_tri(b, base + tri[3 * t], base + tri[3 * t + 1], base + tri[3 * t + 2], d3(0, ny, 0));
	}
	mem_free(tri);
	return true;
}

/* ---- a prism whose sub-polygons cross each other: POV-Ray's even-odd rule (Prism::Inside counts
 * the crossings of a ray in the outline's plane, whatever the sub-polygons do) ---- */

typedef struct pedge {
	double ax, ay, bx, by; /* the outline's (x, z) as (x, y) */
} pedge;

/* The even-odd inside of the outline at (x, y): the crossings of the ray toward +x. */
static bool evenodd_inside(const pedge *e, size_t ne, double x, double y)
{
	bool in = false;
	for (size_t i = 0; i < ne; i++)
		if ((e[i].ay > y) != (e[i].by > y) &&
		    x < e[i].ax + (y - e[i].ay) * (e[i].bx - e[i].ax) / (e[i].by - e[i].ay))
			in = !in;
	return in;
}

/* Where segments i and j cross properly: the parameter along i (false when they do not). */
static bool seg_cross(const pedge *i, const pedge *j, double *t, double *u)
{
	double rx = i->bx - i->ax, ry = i->by - i->ay, sx = j->bx - j->ax, sy = j->by - j->ay;
	double den = rx * sy - ry * sx;
	if (den == 0)
		return false;
	double qx = j->ax - i->ax, qy = j->ay - i->ay;
	*t = (qx * sy - qy * sx) / den, *u = (qx * ry - qy * rx) / den;
	return *t > 1e-12 && *t < 1 - 1e-12 && *u > 1e-12 && *u < 1 - 1e-12;
}

static int cmp_dbl(const void *a, const void *b)
{
	double x = *(const double *)a, y = *(const double *)b;
	return x < y ? -1 : x > y;
}

/* Where two edges cross, computed once for both: walls and caps meet there at one point. */
typedef struct pcross {
	size_t i, j;
	double x, y;
} pcross;

/* The x of non-horizontal edge k at height y: exactly its ends' and its crossings' x there, so that
 * every wall and cap that meets at a point computes the same point. */
static double edge_x_at(const pedge *e, size_t k, double y, const pcross *cr, size_t nc)
{
	if (y == e[k].ay)
		return e[k].ax;
	if (y == e[k].by)
		return e[k].bx;
	for (size_t c = 0; c < nc; c++)
		if ((cr[c].i == k || cr[c].j == k) && cr[c].y == y)
			return cr[c].x;
	return e[k].ax + (y - e[k].ay) * (e[k].bx - e[k].ax) / (e[k].by - e[k].ay);
}

/* The points of the outline at height y: every edge's there (a horizontal edge's two ends),
 * sorted and unique, into out (at most 2 ne); their count. */
static size_t row_points(const pedge *e, size_t ne, double y, const pcross *cr, size_t nc, double *out)
{
	size_t n = 0;
	for (size_t k = 0; k < ne; k++) {
		if (e[k].ay == e[k].by) {
			if (e[k].ay == y)
				out[n++] = e[k].ax, out[n++] = e[k].bx;
		} else if (fmin(e[k].ay, e[k].by) <= y && y <= fmax(e[k].ay, e[k].by)) {
			out[n++] = edge_x_at(e, k, y, cr, nc);
		}
	}
	qsort(out, n, sizeof *out, cmp_dbl);
	size_t u = 0;
	for (size_t k = 0; k < n; k++)
		if (u == 0 || out[k] != out[u - 1])
			out[u++] = out[k];
	return u;
}

typedef struct slab_e {
	double xm;
	size_t k;
} slab_e;

static int cmp_slab(const void *a, const void *b)
{
	double x = ((const slab_e *)a)->xm, y = ((const slab_e *)b)->xm;
	return x < y ? -1 : x > y;
}

/* The even-odd prism (POV-Ray's region of sub-polygons crossing each other) without T-junctions:
 * every height of a vertex or a crossing cuts the outline into slabs; the walls are split at every
 * point of the outline at those heights (crossings included), each piece facing away from the
 * inside (which side is inside changes at each crossing); each slab's inside intervals are capped
 * by zipping the points of the outline on its two bounding heights, so cap and wall share every
 * vertex and the mesh is closed. Flat normals (the pieces are not smoothed). */
static bool prism_evenodd(shape_builder *b, const shape_desc *s, const outline *o, const shape_accuracy *acc, diag *d,
			  diag_loc loc)
{
	size_t ne = o->n_points, nc = 0, cap_c = 0;
	pedge *e = mem_alloc(ne ? ne : 1, sizeof *e);
	double *row = mem_alloc(2 * ne + 2, sizeof *row), *row2 = mem_alloc(2 * ne + 2, sizeof *row2);
	slab_e *se = mem_alloc(ne ? ne : 1, sizeof *se);
	pcross *cr = NULL;
	vecbuf ys;
	vecbuf_init(&ys, sizeof(double));
	bool ok = e && row && row2 && se;
	for (uint32_t k = 0, a = 0, n = 0; ok && k < o->n_contours; a += o->counts[k], k++)
		for (uint32_t i = 0; i < o->counts[k]; i++, n++) {
			const double *p = &o->xy[2 * (a + i)], *q = &o->xy[2 * (a + (i + 1) % o->counts[k])];
			e[n] = (pedge){p[0], p[1], q[0], q[1]};
			ok = vecbuf_push(&ys, &p[1]);
		}
	/* the crossings, each once: its height from the lower edge (a horizontal edge's own), its x
	 * from a non-horizontal one */
	for (size_t i = 0; ok && i < ne; i++)
		for (size_t j = i + 1; ok && j < ne; j++) {
			double t, u;
			if (!seg_cross(&e[i], &e[j], &t, &u))
				continue;
			if (nc == cap_c) {
				cap_c = cap_c ? 2 * cap_c : 16;
				pcross *g = mem_realloc(cr, cap_c, sizeof *cr);
				if (!(ok = g != NULL))
					break;
				cr = g;
			}
			bool hi = e[i].ay == e[i].by, hj = e[j].ay == e[j].by;
			double y = hj ? e[j].ay : e[i].ay + t * (e[i].by - e[i].ay);
			size_t k = hi ? j : i;
			double x = e[k].ax + (y - e[k].ay) * (e[k].bx - e[k].ax) / (e[k].by - e[k].ay);
			cr[nc++] = (pcross){i, j, x, y};
			ok = vecbuf_push(&ys, &y);
		}
	size_t ny = 0;
	double *y = ok ? (double *)ys.data : NULL;
	if (ok) {
		qsort(y, ys.len, sizeof *y, cmp_dbl);
		for (size_t k = 0; k < ys.len; k++)
			if (ny == 0 || y[k] != y[ny - 1])
				y[ny++] = y[k];
	}
	/* the triangles, counted first: two a wall piece, and per slab and side the two chains' */
	size_t tris = 0;
	for (size_t i = 0; ok && i < ne; i++)
		for (size_t k = 0; k < ny; k++)
			tris += 2 * (fmin(e[i].ay, e[i].by) <= y[k] && y[k] <= fmax(e[i].ay, e[i].by));
	for (size_t k = 0; ok && k < ny; k++)
		tris += 4 * row_points(e, ne, y[k], cr, nc, row);
	if (ok && (size_t)b->nt + tris >= SHAPE_MAX_TRIANGLES) {
		mem_free(e), mem_free(row), mem_free(row2), mem_free(se), mem_free(cr), vecbuf_free(&ys);
		diag_error(d, loc, "the prism would make more than %u triangles (the limit of one shape)", SHAPE_MAX_TRIANGLES);
		return false;
	}
	/* the walls: each edge through its points at every height it spans (a horizontal edge: the
	 * outline's points on it), piece by piece */
	for (size_t i = 0; ok && i < ne; i++) {
		double dx = e[i].bx - e[i].ax, dy = e[i].by - e[i].ay, len = hypot(dx, dy);
		if (!(len > 0))
			continue;
		size_t n = 0;
		if (dy == 0) {
			size_t m = row_points(e, ne, e[i].ay, cr, nc, row2);
			for (size_t k = 0; k < m; k++)
				if (fmin(e[i].ax, e[i].bx) <= row2[k] && row2[k] <= fmax(e[i].ax, e[i].bx))
					row[n++] = row2[k];
			if (dx < 0)
				for (size_t k = 0; k < n / 2; k++) {
					double t = row[k];
					row[k] = row[n - 1 - k], row[n - 1 - k] = t;
				}
		} else {
			for (size_t k = 0; k < ny; k++)
				if (fmin(e[i].ay, e[i].by) <= y[k] && y[k] <= fmax(e[i].ay, e[i].by))
					row[n++] = y[k];
			if (dy < 0)
				for (size_t k = 0; k < n / 2; k++) {
					double t = row[k];
					row[k] = row[n - 1 - k], row[n - 1 - k] = t;
				}
		}
		for (size_t k = 0; k + 1 < n; k++) {
			double p0[2], p1[2];
			if (dy == 0)
				p0[0] = row[k], p0[1] = e[i].ay, p1[0] = row[k + 1], p1[1] = e[i].ay;
			else
				p0[0] = edge_x_at(e, i, row[k], cr, nc), p0[1] = row[k], p1[0] = edge_x_at(e, i, row[k + 1], cr, nc),
				p1[1] = row[k + 1];
			double mx = 0.5 * (p0[0] + p1[0]), my = 0.5 * (p0[1] + p1[1]), nx = dy / len, nyy = -dx / len;
			double eps = 1e-7 * (1 + fabs(mx) + fabs(my));
			bool right_in = evenodd_inside(e, ne, mx + eps * nx, my + eps * nyy);
			dvec3 want = right_in ? d3(-nx, 0, -nyy) : d3(nx, 0, nyy);
			dvec3 P1 = prism_point(s, p0, s->h1), Q1 = prism_point(s, p1, s->h1);
			dvec3 P2 = prism_point(s, p0, s->h2), Q2 = prism_point(s, p1, s->h2);
			uint32_t v0 = sb_vertex(b, P1, want, 0, 0), v1 = sb_vertex(b, Q1, want, 0, 0);
			uint32_t v2 = sb_vertex(b, Q2, want, 0, 0), v3 = sb_vertex(b, P2, want, 0, 0);
			if (!s->conic || s->h1 != 0)
				sb_tri(b, v0, v1, v2, want);
			if (!s->conic || s->h2 != 0)
				sb_tri(b, v0, v2, v3, want);
		}
	}
	/* the caps: in each slab, between the crossing edges 2m and 2m + 1 (even-odd), the outline's
	 * points on the slab's lower and upper heights zipped together */
	for (size_t k = 0; ok && !s->open && k + 1 < ny; k++) {
		double ya = y[k], yb = y[k + 1], ym = 0.5 * (ya + yb);
		size_t c = 0;
		for (size_t i = 0; i < ne; i++)
			if ((e[i].ay > ym) != (e[i].by > ym))
				se[c++] = (slab_e){e[i].ax + (ym - e[i].ay) * (e[i].bx - e[i].ax) / (e[i].by - e[i].ay), i};
		qsort(se, c, sizeof *se, cmp_slab);
		size_t na = row_points(e, ne, ya, cr, nc, row), nb = row_points(e, ne, yb, cr, nc, row2);
		for (size_t i = 0; i + 1 < c; i += 2) {
			double a0 = edge_x_at(e, se[i].k, ya, cr, nc), a1 = edge_x_at(e, se[i + 1].k, ya, cr, nc);
			double b0 = edge_x_at(e, se[i].k, yb, cr, nc), b1 = edge_x_at(e, se[i + 1].k, yb, cr, nc);
			size_t lo_a = 0, lo_b = 0, hi_a, hi_b;
			while (lo_a < na && row[lo_a] < a0)
				lo_a++;
			for (hi_a = lo_a; hi_a + 1 < na && row[hi_a + 1] <= a1;)
				hi_a++;
			while (lo_b < nb && row2[lo_b] < b0)
				lo_b++;
			for (hi_b = lo_b; hi_b + 1 < nb && row2[hi_b + 1] <= b1;)
				hi_b++;
			for (int side = 0; side < 2; side++) {
				double h = side ? s->h2 : s->h1;
				if (s->conic && h == 0)
					continue;
				dvec3 up = d3(0, side ? 1 : -1, 0);
				size_t ia = lo_a, ib = lo_b;
				while (ia < hi_a || ib < hi_b) {
					/* the chain whose next point lies less far along its side (any
					 * monotone order tiles the trapezoid; this one keeps triangles fat) */
					bool step_a = ib == hi_b || (ia < hi_a && (row[ia + 1] - a0) * (b1 - b0) <=
										       (row2[ib + 1] - b0) * (a1 - a0));
					double pa[2] = {row[ia], ya}, pb[2] = {row2[ib], yb}, pn[2];
					if (step_a)
						pn[0] = row[ia + 1], pn[1] = ya;
					else
						pn[0] = row2[ib + 1], pn[1] = yb;
					uint32_t v0 = sb_vertex(b, prism_point(s, pa, h), up, 0, 0);
					uint32_t v1 = sb_vertex(b, prism_point(s, pn, h), up, 0, 0);
					uint32_t v2 = sb_vertex(b, prism_point(s, pb, h), up, 0, 0);
					sb_tri(b, v0, v1, v2, up);
					if (step_a)
						ia++;
					else
						ib++;
				}
			}
		}
	}
	(void)acc;
	mem_free(e), mem_free(row), mem_free(row2), mem_free(se), mem_free(cr), vecbuf_free(&ys);
	if (!ok) {
		diag_error(d, loc, "out of memory while tessellating the prism");
		return false;
	}
	return true;
}

bool shape_prism(const shape_desc *s, const shape_accuracy *acc, mesh *out, diag *d, diag_loc loc)
{
	/* A conic prism's outline is scaled by up to max |h|: flatten it finer in proportion. */
	double k = s->conic ? fmax(fmax(fabs(s->h1), fabs(s->h2)), 1e-12) : 1.0;
	outline o;
	if (!prism_outline(s, acc->tol / k, &o)) {
		diag_error(d, loc, "out of memory while tessellating the prism");
		return false;
	}
	size_t tris = 2 * (size_t)o.n_points + (s->open ? 0 : 2 * ((size_t)o.n_points + 2 * o.n_contours));
	if (tris > SHAPE_MAX_TRIANGLES) {
		outline_free(&o);
		diag_error(d, loc, "the prism would make %zu triangles (the limit of one shape is %u)", tris,
			   SHAPE_MAX_TRIANGLES);
		return false;
	}
	uint32_t ea, eb;
	/* A sub-polygon that crosses itself (a bow tie) is refused; sub-polygons that cross each other
	 * are POV-Ray's even-odd region (prism3a.pov's overlapping squares). */
	for (uint32_t k = 0, a = 0; k < o.n_contours; a += o.counts[k], k++)
		if (poly2d_self_intersects(&o.xy[2 * a], &o.counts[k], 1, &ea, &eb)) {
			outline_free(&o);
			diag_error(d, loc, "the prism's outline crosses itself: POV-Ray's inside test is undefined there");
			return false;
		}
	if (poly2d_self_intersects(o.xy, o.counts, o.n_contours, &ea, &eb)) { /* POV-Ray's even-odd rule */
		shape_builder b;
		sb_init(&b);
		bool ok = prism_evenodd(&b, s, &o, acc, d, loc);
		outline_free(&o);
		if (!ok) {
			sb_free(&b);
			return false;
		}
		return sb_finish(&b, out, false, "prism", d, loc);
	}
	if (!orient_outline(&o)) {
		outline_free(&o);
		diag_error(d, loc, "out of memory while tessellating the prism");
		return false;
	}
	shape_builder b;
	sb_init(&b);
	prism_walls(&b, s, &o, s->spline != SHAPE_LINEAR);
	bool ok = s->open || prism_caps(&b, s, &o);
	outline_free(&o);
	if (!ok) {
		sb_free(&b);
		diag_error(d, loc, "out of memory while tessellating the prism");
		return false;
	}
	return sb_finish(&b, out, false, "prism", d, loc);
}

/* ---- sphere_sweep: a sphere moved along a spline, its radius along another ---- */

/* The centre and radius of piece i at t, with their derivatives (POV-Ray's SphereSweep::Compute:
 * linear pieces between neighbours; Catmull-Rom and uniform B-spline pieces over four). */
static void sweep_at(const shape_desc *s, uint32_t i, double t, double q[4], double dq[4], double ddq[4])
{
	double w[4], dw[4], ddw[4];
	uint32_t n = s->spline == SHAPE_LINEAR ? 2 : 4;
	if (s->spline == SHAPE_LINEAR) {
		w[0] = 1 - t, w[1] = t, dw[0] = -1, dw[1] = 1, ddw[0] = ddw[1] = 0;
	} else if (s->spline == SHAPE_CUBIC) {
		double t2 = t * t, t3 = t2 * t;
		w[0] = 0.5 * (-t3 + 2 * t2 - t), w[1] = 0.5 * (3 * t3 - 5 * t2 + 2);
		w[2] = 0.5 * (-3 * t3 + 4 * t2 + t), w[3] = 0.5 * (t3 - t2);
		dw[0] = 0.5 * (-3 * t2 + 4 * t - 1), dw[1] = 0.5 * (9 * t2 - 10 * t);
		dw[2] = 0.5 * (-9 * t2 + 8 * t + 1), dw[3] = 0.5 * (3 * t2 - 2 * t);
		ddw[0] = 0.5 * (-6 * t + 4), ddw[1] = 0.5 * (18 * t - 10), ddw[2] = 0.5 * (-18 * t + 8), ddw[3] = 0.5 * (6 * t - 2);
	} else {
		double u = 1 - t, t2 = t * t, t3 = t2 * t;
		w[0] = u * u * u / 6, w[1] = (3 * t3 - 6 * t2 + 4) / 6, w[2] = (-3 * t3 + 3 * t2 + 3 * t + 1) / 6, w[3] = t3 / 6;
		dw[0] = -u * u / 2, dw[1] = (3 * t2 - 4 * t) / 2, dw[2] = (-3 * t2 + 2 * t + 1) / 2, dw[3] = t2 / 2;
		ddw[0] = u, ddw[1] = 3 * t - 2, ddw[2] = -3 * t + 1, ddw[3] = t;
	}
	for (int c = 0; c < 4; c++) {
		q[c] = dq[c] = ddq[c] = 0;
		for (uint32_t k = 0; k < n; k++) {
			double v = s->pts[4 * (i + k) + c];
			q[c] += w[k] * v, dq[c] += dw[k] * v, ddq[c] += ddw[k] * v;
		}
	}
}

/* Steps over piece i: the chord bound of the centre and radius curves, enlarged where the tube's
 * outer side moves faster than its centre (radius over the centre's curvature radius). */
static uint32_t sweep_steps(const shape_desc *s, uint32_t i, double tol)
{
	if (s->spline == SHAPE_LINEAR)
		return 1;
	double m = 0, rmax = 0, vmin = INFINITY;
	for (int k = 0; k <= 4; k++) {
		double q[4], dq[4], ddq[4];
		sweep_at(s, i, k / 4.0, q, dq, ddq);
		m = fmax(m, sqrt(ddq[0] * ddq[0] + ddq[1] * ddq[1] + ddq[2] * ddq[2]) + fabs(ddq[3]));
		rmax = fmax(rmax, fabs(q[3]));
		vmin = fmin(vmin, dq[0] * dq[0] + dq[1] * dq[1] + dq[2] * dq[2]);
	}
	m *= 1 + rmax * m / fmax(vmin, 1e-30);
	double n = ceil(sqrt(m / (8 * tol)));
	return n < 1 ? 1 : n > 4096 ? 4096 : (uint32_t)n;
}

/* The ring of the envelope at t: the circle where the moving sphere touches the swept surface,
 * (x - c) . c' = -r r' (its centre moved back along the tangent by r r' / |c'|). */
typedef struct ring {
	dvec3 c, T, N, B;
	double r, delta, rho;
	uint32_t first; /* its vertices */
} ring;

static void ring_at(const shape_desc *s, uint32_t i, double t, ring *R, const ring *prev)
{
	double q[4], dq[4], ddq[4];
	sweep_at(s, i, t, q, dq, ddq);
	R->c = d3(q[0], q[1], q[2]);
	R->r = fabs(q[3]);
	dvec3 v = d3(dq[0], dq[1], dq[2]);
	double vl = d3_length(v);
	R->T = vl > 0 ? d3_scale(v, 1 / vl) : (prev ? prev->T : d3(0, 1, 0));
	R->delta = vl > 0 ? -q[3] * dq[3] / vl : 0;
	if (fabs(R->delta) > R->r)
		R->delta = R->delta > 0 ? R->r : -R->r;
	R->rho = sqrt(fmax(0, R->r * R->r - R->delta * R->delta));
	/* the frame carried along by projection (no twist between rings) */
	dvec3 N = prev ? prev->N : (fabs(R->T.x) < 0.9 ? d3(1, 0, 0) : d3(0, 1, 0));
	N = d3_sub(N, d3_scale(R->T, d3_dot(N, R->T)));
	if (d3_length(N) < 1e-12)
		N = fabs(R->T.x) < 0.9 ? d3_cross(R->T, d3(1, 0, 0)) : d3_cross(R->T, d3(0, 1, 0));
	R->N = d3_normalize(N);
	R->B = d3_cross(R->T, R->N);
}

static void ring_vertices(shape_builder *b, ring *R, uint32_t S)
{
	R->first = b->nv;
	for (uint32_t k = 0; k < S; k++) {
		double ph = 2 * M_PI * k / S;
		dvec3 rad = d3_add(d3_scale(R->N, cos(ph)), d3_scale(R->B, sin(ph)));
		dvec3 x = d3_add(R->c, d3_add(d3_scale(R->T, R->delta), d3_scale(rad, R->rho)));
		sb_vertex(b, x, d3_sub(x, R->c), 0, 0);
	}
}

static void join_rings(shape_builder *b, const ring *A, const ring *Bn, uint32_t S)
{
	for (uint32_t k = 0; k < S; k++) {
		uint32_t a0 = A->first + k, a1 = A->first + (k + 1) % S, b0 = Bn->first + k, b1 = Bn->first + (k + 1) % S;
		double ph = 2 * M_PI * (k + 0.5) / S;
		dvec3 want = d3_add(d3_scale(A->N, cos(ph)), d3_scale(A->B, sin(ph)));
		sb_tri(b, a0, a1, b1, want);
		sb_tri(b, a0, b1, b0, want);
	}
}

/* The end of the tube at ring R closed by the rest of its sphere, towards dir (-1: back along
 * the tangent, +1: ahead), in rings of the angular step 2 pi / S down to the pole. */
static void sweep_cap(shape_builder *b, const ring *R, double dir, uint32_t S)
{
	if (R->r <= 0)
		return;
	dvec3 axis = d3_scale(R->T, dir);
	double beta0 = acos(fmax(-1, fmin(1, dir * R->delta / R->r))); /* from the pole to the ring */
	uint32_t nr = (uint32_t)ceil(beta0 / (2 * M_PI / S));
	nr = nr < 1 ? 1 : nr;
	ring prev = *R;
	for (uint32_t j = nr; j-- > 0;) {
		double beta = beta0 * j / nr;
		if (j == 0) {
			dvec3 x = d3_add(R->c, d3_scale(axis, R->r));
			uint32_t pole = sb_vertex(b, x, axis, 0, 0);
			for (uint32_t k = 0; k < S; k++)
				sb_tri(b, prev.first + k, prev.first + (k + 1) % S, pole, axis);
			break;
		}
		ring cur = *R;
		cur.first = b->nv;
		for (uint32_t k = 0; k < S; k++) {
			double ph = 2 * M_PI * k / S;
			dvec3 rad = d3_add(d3_scale(R->N, cos(ph)), d3_scale(R->B, sin(ph)));
			dvec3 x = d3_add(R->c, d3_add(d3_scale(axis, R->r * cos(beta)), d3_scale(rad, R->r * sin(beta))));
			sb_vertex(b, x, d3_sub(x, R->c), 0, 0);
		}
		for (uint32_t k = 0; k < S; k++) {
			double ph = 2 * M_PI * (k + 0.5) / S, bm = beta0 * (j + 0.5) / nr;
			dvec3 want = d3_add(d3_scale(axis, cos(bm)),
					    d3_scale(d3_add(d3_scale(R->N, cos(ph)), d3_scale(R->B, sin(ph))), sin(bm)));
			uint32_t a0 = prev.first + k, a1 = prev.first + (k + 1) % S, c0 = cur.first + k, c1 = cur.first + (k + 1) % S;
			sb_tri(b, a0, a1, c1, want);
			sb_tri(b, a0, c1, c0, want);
		}
		prev = cur;
	}
}

/* One tube over pieces [i0, i1), capped at both ends. */
static void sweep_tube(shape_builder *b, const shape_desc *s, uint32_t i0, uint32_t i1, double tol, uint32_t S)
{
	ring prev, cur, first;
	bool have = false;
	for (uint32_t i = i0; i < i1; i++) {
		uint32_t m = sweep_steps(s, i, tol);
		for (uint32_t j = have ? 1 : 0; j <= m; j++) {
			ring_at(s, i, (double)j / m, &cur, have ? &prev : NULL);
			ring_vertices(b, &cur, S);
			if (have)
				join_rings(b, &prev, &cur, S);
			else
				first = cur;
			prev = cur, have = true;
		}
	}
	sweep_cap(b, &first, -1, S);
	sweep_cap(b, &prev, 1, S);
}

bool shape_sphere_sweep(const shape_desc *s, const shape_accuracy *acc, mesh *out, diag *d, diag_loc loc)
{
	uint32_t np = s->spline == SHAPE_LINEAR ? s->n_pts - 1 : s->n_pts - 3;
	/* Around the tube, the edges the segment count gives the shape's bounding sphere on screen: the
	 * count scaled by the largest sphere's share of that radius (at least 16). */
	dvec3 lo, hi;
	shape_bounds(s, &lo, &hi);
	double rmax = 0, R = 0.5 * d3_length(d3_sub(hi, lo));
	for (uint32_t i = 0; i < s->n_pts; i++)
		rmax = fmax(rmax, s->pts[4 * i + 3]);
	uint32_t S = (uint32_t)ceil(acc->segments * fmin(1.0, rmax / fmax(R, 1e-300)));
	S = around_segments(S < 16 ? 16 : S, rmax, 0.5 * acc->tol);
	size_t rings = 0;
	for (uint32_t i = 0; i < np; i++)
		rings += sweep_steps(s, i, 0.5 * acc->tol) + 1 + (s->spline == SHAPE_LINEAR ? S : 0);
	rings += S; /* the caps' rings: at most S / 2 each */
	size_t tris = 2 * rings * S;
	if (tris > SHAPE_MAX_TRIANGLES) {
		diag_error(d, loc, "the sphere_sweep would make about %zu triangles (the limit of one shape is %u)", tris,
			   SHAPE_MAX_TRIANGLES);
		return false;
	}
	shape_builder b;
	sb_init(&b);
	if (s->spline == SHAPE_LINEAR) /* each piece its own capsule: their union is POV-Ray's sweep */
		for (uint32_t i = 0; i < np; i++)
			sweep_tube(&b, s, i, i + 1, 0.5 * acc->tol, S);
	else
		sweep_tube(&b, s, 0, np, 0.5 * acc->tol, S);
	return sb_finish(&b, out, false, "sphere_sweep", d, loc);
}

/* ---- bicubic_patch: a Bezier patch of 4 x 4 control points ---- */

/* The patch's point and tangents at (u, v) (POV-Ray's bezier_value: row i of the control points
 * along u, column j along v, Bernstein weights). */
static void patch_at(const double *cp, double u, double v, dvec3 *P, dvec3 *Pu, dvec3 *Pv)
{
	double bu[4] = {(1 - u) * (1 - u) * (1 - u), 3 * u * (1 - u) * (1 - u), 3 * u * u * (1 - u), u * u * u};
	double bv[4] = {(1 - v) * (1 - v) * (1 - v), 3 * v * (1 - v) * (1 - v), 3 * v * v * (1 - v), v * v * v};
	double du[4] = {-3 * (1 - u) * (1 - u), 3 * (1 - u) * (1 - 3 * u), 3 * u * (2 - 3 * u), 3 * u * u};
	double dv[4] = {-3 * (1 - v) * (1 - v), 3 * (1 - v) * (1 - 3 * v), 3 * v * (2 - 3 * v), 3 * v * v};
	*P = *Pu = *Pv = d3(0, 0, 0);
	for (int i = 0; i < 4; i++)
		for (int j = 0; j < 4; j++) {
			dvec3 c = d3(cp[3 * (4 * i + j)], cp[3 * (4 * i + j) + 1], cp[3 * (4 * i + j) + 2]);
			*P = d3_add(*P, d3_scale(c, bu[i] * bv[j]));
			*Pu = d3_add(*Pu, d3_scale(c, du[i] * bv[j]));
			*Pv = d3_add(*Pv, d3_scale(c, bu[i] * dv[j]));
		}
}

/* The largest second difference of the control net along one direction, times n (n - 1) = 6:
 * a bound of the patch's second derivative that way (Bezier's derivative is a Bezier of the
 * differences). */
static double patch_curvature(const double *cp, bool along_u)
{
	double m = 0;
	for (int a = 0; a < 4; a++)
		for (int k = 0; k < 2; k++) {
			double q[3];
			for (int c = 0; c < 3; c++) {
				int i0 = along_u ? 4 * k + a : 4 * a + k, st = along_u ? 4 : 1;
				q[c] = cp[3 * (i0 + 2 * st) + c] - 2 * cp[3 * (i0 + st) + c] + cp[3 * i0 + c];
			}
			m = fmax(m, 6 * sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2]));
		}
	return m;
}

bool shape_bicubic(const shape_desc *s, const shape_accuracy *acc, mesh *out, diag *d, diag_loc loc)
{
	/* a chord over a step h stands M h^2 / 8 off: a third of the tolerance each way, a third for
	 * the twist between them */
	double tu = patch_curvature(s->pts, true), tv = patch_curvature(s->pts, false), t3 = acc->tol / 3;
	double nu = fmax(1, ceil(sqrt(tu / (8 * t3)))), nv = fmax(1, ceil(sqrt(tv / (8 * t3))));
	nu = fmin(nu, 4096), nv = fmin(nv, 4096);
	size_t tris = 2 * (size_t)nu * (size_t)nv;
	if (tris > SHAPE_MAX_TRIANGLES) {
		diag_error(d, loc, "the bicubic_patch would make %zu triangles (the limit of one shape is %u)", tris,
			   SHAPE_MAX_TRIANGLES);
		return false;
	}
	uint32_t U = (uint32_t)nu, V = (uint32_t)nv;
	shape_builder b;
	sb_init(&b);
	const double *st = s->st;
	for (uint32_t i = 0; i <= U; i++)
		for (uint32_t j = 0; j <= V; j++) {
			double u = (double)i / U, v = (double)j / V;
			dvec3 P, Pu, Pv;
			patch_at(s->pts, u, v, &P, &Pu, &Pv);
			/* POV-Ray's Compute_Texture_UV of (v, u) over the corners st[0..3] */
			double a0 = st[0] + v * (st[2] - st[0]), a1 = st[1] + v * (st[3] - st[1]);
			double b0 = st[6] + v * (st[4] - st[6]), b1 = st[7] + v * (st[5] - st[7]);
			dvec3 n = d3_cross(Pu, Pv);
			sb_vertex(&b, P, d3_length(n) > 0 ? n : d3(1, 0, 0), a0 + u * (b0 - a0), a1 + u * (b1 - a1));
		}
	for (uint32_t i = 0; i < U; i++)
		for (uint32_t j = 0; j < V; j++) {
			dvec3 P, Pu, Pv;
			patch_at(s->pts, (i + 0.5) / U, (j + 0.5) / V, &P, &Pu, &Pv);
			dvec3 want = d3_cross(Pu, Pv);
			uint32_t a = i * (V + 1) + j, c = a + V + 1;
			sb_tri(&b, a, c, c + 1, want);
			sb_tri(&b, a, c + 1, a + 1, want);
		}
	return sb_finish(&b, out, true, "bicubic_patch", d, loc);
}
