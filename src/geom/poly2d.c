/* poly2d.c - plane regions bounded by closed polygons (prism and text caps): nesting by the
 * even-odd rule, orientation, holes bridged into their outer polygon, ear clipping, and the
 * crossing test of a prism's outline. Written for circe (the bridge is Eberly's "Triangulation by
 * Ear Clipping", 2008, section 3: the hole's rightmost vertex joined to a visible outer vertex). */
#include "geom/shape.h"

#include "base/mem.h"

#include <math.h>
#include <string.h>

static double area2(const double *xy, uint32_t n)
{
	double a = 0;
	for (uint32_t i = 0, j = n - 1; i < n; j = i++)
		a += xy[2 * j] * xy[2 * i + 1] - xy[2 * i] * xy[2 * j + 1];
	return a;
}

/* Whether (x, y) is inside the polygon (crossing parity). */
static bool inside(const double *xy, uint32_t n, double x, double y)
{
	bool in = false;
	for (uint32_t i = 0, j = n - 1; i < n; j = i++) {
		double xi = xy[2 * i], yi = xy[2 * i + 1], xj = xy[2 * j], yj = xy[2 * j + 1];
		if ((yi > y) != (yj > y) && x < (xj - xi) * (y - yi) / (yj - yi) + xi)
			in = !in;
	}
	return in;
}

/* The nesting depth of contour k: how many other contours hold its first vertex. */
static uint32_t depth_of(const double *xy, const uint32_t *counts, const uint32_t *start, uint32_t n, uint32_t k)
{
	uint32_t dep = 0;
	const double *p = &xy[2 * start[k]];
	for (uint32_t j = 0; j < n; j++)
		if (j != k && inside(&xy[2 * start[j]], counts[j], p[0], p[1]))
			dep++;
	return dep;
}

static uint32_t *starts(const uint32_t *counts, uint32_t n)
{
	uint32_t *s = mem_alloc(n ? n : 1, sizeof *s);
	if (s)
		for (uint32_t k = 0, a = 0; k < n; a += counts[k], k++)
			s[k] = a;
	return s;
}

static void reverse(double *xy, uint32_t n)
{
	for (uint32_t i = 0, j = n - 1; i < j; i++, j--) {
		double x = xy[2 * i], y = xy[2 * i + 1];
		xy[2 * i] = xy[2 * j], xy[2 * i + 1] = xy[2 * j + 1];
		xy[2 * j] = x, xy[2 * j + 1] = y;
	}
}

void poly2d_orient(double *xy, const uint32_t *counts, uint32_t n, bool *reversed)
{
	uint32_t *st = starts(counts, n);
	if (!st)
		return;
	for (uint32_t k = 0; k < n; k++) {
		bool hole = depth_of(xy, counts, st, n, k) & 1;
		double a = area2(&xy[2 * st[k]], counts[k]);
		bool turn = (a < 0) != hole;
		if (turn)
			reverse(&xy[2 * st[k]], counts[k]);
		if (reversed)
			reversed[k] = turn;
	}
	mem_free(st);
}

/* Signed area of the corner a b c (twice), positive when counter-clockwise. */
static double orient3(const double *a, const double *b, const double *c)
{
	return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

static bool in_triangle(const double *a, const double *b, const double *c, const double *p)
{
	return orient3(a, b, p) >= 0 && orient3(b, c, p) >= 0 && orient3(c, a, p) >= 0;
}

/* Joins hole h (clockwise, vertex indices hv[0..hn)) into the polygon poly (counter-clockwise,
 * indices, *pn of them, room for hn + 2 more) by a bridge from the hole's rightmost vertex. */
static void bridge(const double *xy, uint32_t *poly, uint32_t *pn, const uint32_t *hv, uint32_t hn)
{
	uint32_t m = 0;
	for (uint32_t i = 1; i < hn; i++)
		if (xy[2 * hv[i]] > xy[2 * hv[m]])
			m = i;
	const double *M = &xy[2 * hv[m]];
	/* The nearest edge the ray from M towards +x meets, and its endpoint of larger x. */
	double best = INFINITY;
	uint32_t vis = 0;
	for (uint32_t i = 0; i < *pn; i++) {
		const double *a = &xy[2 * poly[i]], *b = &xy[2 * poly[(i + 1) % *pn]];
		if ((a[1] > M[1]) == (b[1] > M[1]) && a[1] != M[1] && b[1] != M[1])
			continue;
		if (a[1] == b[1]) {
			if (a[1] != M[1])
				continue;
			double x = fmin(a[0], b[0]);
			if (x >= M[0] && x - M[0] < best)
				best = x - M[0], vis = a[0] < b[0] ? i : (i + 1) % *pn;
			continue;
		}
		double x = a[0] + (M[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]);
		if (x >= M[0] && x - M[0] < best)
			best = x - M[0], vis = a[0] > b[0] ? i : (i + 1) % *pn;
	}
	/* A vertex inside the triangle (M, hit, vis) would hide vis: take the one nearest the ray. */
	double I[2] = {M[0] + best, M[1]};
	const double *P = &xy[2 * poly[vis]];
	double best_ang = INFINITY;
	for (uint32_t i = 0; i < *pn && isfinite(best); i++) {
		const double *q = &xy[2 * poly[i]];
		if (i == vis || q[0] < M[0])
			continue;
		bool tri = P[1] > M[1] ? in_triangle(M, I, P, q) : in_triangle(M, P, I, q);
		if (!tri)
			continue;
		double ang = fabs(atan2(q[1] - M[1], q[0] - M[0]));
		if (ang < best_ang)
			best_ang = ang, vis = i;
	}
	/* poly[0..vis], hole from m round to m, poly[vis], poly[vis+1..] */
	uint32_t tail = *pn - vis - 1;
	memmove(&poly[vis + 1 + hn + 2], &poly[vis + 1], tail * sizeof *poly);
	for (uint32_t i = 0; i <= hn; i++)
		poly[vis + 1 + i] = hv[(m + i) % hn];
	poly[vis + 2 + hn] = poly[vis];
	*pn += hn + 2;
}

/* Ear clipping of a simple (bridged) polygon, counter-clockwise. */
static long clip_ears(const double *xy, uint32_t *poly, uint32_t n, uint32_t *out)
{
	long nt = 0;
	uint32_t guard = 0;
	uint32_t i = 0;
	while (n > 3) {
		uint32_t a = poly[(i + n - 1) % n], b = poly[i % n], c = poly[(i + 1) % n];
		const double *A = &xy[2 * a], *B = &xy[2 * b], *C = &xy[2 * c];
		bool ear = orient3(A, B, C) > 0;
		for (uint32_t k = 0; ear && k < n; k++) {
			uint32_t v = poly[k];
			const double *V = &xy[2 * v];
			if (v == a || v == b || v == c || (V[0] == A[0] && V[1] == A[1]) || (V[0] == B[0] && V[1] == B[1]) ||
			    (V[0] == C[0] && V[1] == C[1]))
				continue;
			if (in_triangle(A, B, C, V))
				ear = false;
		}
		/* After a full round without an ear (collinear or tangled input), clip anyway. */
		if (ear || guard > 2 * n) {
			out[3 * nt] = a, out[3 * nt + 1] = b, out[3 * nt + 2] = c;
			nt++;
			uint32_t at = i % n;
			memmove(&poly[at], &poly[at + 1], (n - at - 1) * sizeof *poly);
			n--;
			guard = 0;
			i = at ? at - 1 : 0;
		} else {
			i = (i + 1) % n;
			guard++;
		}
	}
	out[3 * nt] = poly[0], out[3 * nt + 1] = poly[1], out[3 * nt + 2] = poly[2];
	return nt + 1;
}

static bool by_max_x_desc_cmp(const double *xy, const uint32_t *st, const uint32_t *counts, uint32_t a, uint32_t b)
{
	double ma = -INFINITY, mb = -INFINITY;
	for (uint32_t i = 0; i < counts[a]; i++)
		ma = fmax(ma, xy[2 * (st[a] + i)]);
	for (uint32_t i = 0; i < counts[b]; i++)
		mb = fmax(mb, xy[2 * (st[b] + i)]);
	return ma < mb;
}

long poly2d_triangulate(const double *xy, const uint32_t *counts, uint32_t n, uint32_t **tris)
{
	uint32_t total = 0;
	for (uint32_t k = 0; k < n; k++)
		total += counts[k];
	uint32_t *st = starts(counts, n), *dep = mem_alloc(n ? n : 1, sizeof *dep);
	uint32_t *poly = mem_alloc(total + 3 * (size_t)n + 3, sizeof *poly);
	uint32_t *holes = mem_alloc(n ? n : 1, sizeof *holes);
	uint32_t *out = mem_alloc(3 * ((size_t)total + 2 * (size_t)n + 1), sizeof *out);
	long nt = 0;
	if (!st || !dep || !poly || !holes || !out) {
		nt = -1;
		goto done;
	}
	for (uint32_t k = 0; k < n; k++)
		dep[k] = depth_of(xy, counts, st, n, k);
	for (uint32_t k = 0; k < n; k++) {
		if ((dep[k] & 1) || counts[k] < 3)
			continue;
		/* Its holes: contours one level deeper that it holds. */
		uint32_t nh = 0;
		for (uint32_t j = 0; j < n; j++)
			if (dep[j] == dep[k] + 1 && counts[j] >= 3 &&
			    inside(&xy[2 * st[k]], counts[k], xy[2 * st[j]], xy[2 * st[j] + 1]))
				holes[nh++] = j;
		for (uint32_t a = 1; a < nh; a++) /* rightmost hole first (insertion sort) */
			for (uint32_t b = a; b > 0 && by_max_x_desc_cmp(xy, st, counts, holes[b - 1], holes[b]); b--) {
				uint32_t t = holes[b];
				holes[b] = holes[b - 1], holes[b - 1] = t;
			}
		uint32_t pn = counts[k];
		for (uint32_t i = 0; i < pn; i++)
			poly[i] = st[k] + i;
		for (uint32_t h = 0; h < nh; h++) {
			uint32_t j = holes[h];
			uint32_t *hv = mem_alloc(counts[j], sizeof *hv);
			if (!hv) {
				nt = -1;
				goto done;
			}
			for (uint32_t i = 0; i < counts[j]; i++)
				hv[i] = st[j] + i;
			bridge(xy, poly, &pn, hv, counts[j]);
			mem_free(hv);
		}
		nt += clip_ears(xy, poly, pn, out + 3 * nt);
	}
done:
	mem_free(st), mem_free(dep), mem_free(poly), mem_free(holes);
	if (nt < 0) {
		mem_free(out);
		out = NULL;
	}
	*tris = out;
	return nt;
}

/* Whether segments pq and rs cross at a point inside both (touching at an end is not crossing). */
static bool crosses(const double *p, const double *q, const double *r, const double *s)
{
	double d1 = orient3(p, q, r), d2 = orient3(p, q, s), d3 = orient3(r, s, p), d4 = orient3(r, s, q);
	return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

bool poly2d_self_intersects(const double *xy, const uint32_t *counts, uint32_t n, uint32_t *ea, uint32_t *eb)
{
	uint32_t total = 0;
	for (uint32_t k = 0; k < n; k++)
		total += counts[k];
	uint32_t *st = starts(counts, n);
	if (!st)
		return false;
	/* Edge e of contour k runs from vertex e to the next one of the same contour. */
	bool found = false;
	for (uint32_t k = 0, e = 0; k < n && !found; k++)
		for (uint32_t i = 0; i < counts[k] && !found; i++, e++) {
			const double *p = &xy[2 * (st[k] + i)], *q = &xy[2 * (st[k] + (i + 1) % counts[k])];
			double xl = fmin(p[0], q[0]), xh = fmax(p[0], q[0]), yl = fmin(p[1], q[1]), yh = fmax(p[1], q[1]);
			for (uint32_t l = k; l < n && !found; l++) {
				uint32_t j0 = l == k ? i + 1 : 0, f = st[l] + j0;
				for (uint32_t j = j0; j < counts[l]; j++, f++) {
					const double *r = &xy[2 * (st[l] + j)], *s = &xy[2 * (st[l] + (j + 1) % counts[l])];
					if (fmax(r[0], s[0]) < xl || fmin(r[0], s[0]) > xh || fmax(r[1], s[1]) < yl ||
					    fmin(r[1], s[1]) > yh)
						continue;
					if (crosses(p, q, r, s)) {
						*ea = e, *eb = f;
						found = true;
						break;
					}
				}
			}
		}
	(void)total;
	mem_free(st);
	return found;
}
