/* merge.c - tile geometry, consistency checks, coverage, assembly. */
#include "io/merge.h"

#include "base/mem.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

bool merge_tile_rect(int width, int height, int i, int n, exrfile_rect *out)
{
	if (n < 1 || i < 0 || i >= n || width < 1 || height < 1)
		return false;
	/* The factor pair cols x rows = n whose tiles are closest to square. */
	int best_cols = 0;
	double best = INFINITY;
	for (int cols = 1; cols <= n; cols++) {
		if (n % cols)
			continue;
		int rows = n / cols;
		if (cols > width || rows > height)
			continue;
		double aspect = ((double)width / cols) / ((double)height / rows);
		double cost = fabs(log(aspect));
		if (cost < best - 1e-12) {
			best = cost;
			best_cols = cols;
		}
	}
	if (!best_cols)
		return false;
	int cols = best_cols, rows = n / cols;
	int cx = i % cols, cy = i / cols;
	/* The first (size % count) columns/rows are one pixel larger. */
	int bw = width / cols, rw = width % cols, bh = height / rows, rh = height % rows;
	out->x0 = cx * bw + (cx < rw ? cx : rw);
	out->x1 = out->x0 + bw + (cx < rw);
	out->y0 = cy * bh + (cy < rh ? cy : rh);
	out->y1 = out->y0 + bh + (cy < rh);
	return true;
}

static bool attr_equal(const exrfile_attr *a, const exrfile_attr *b)
{
	if (!a || !b)
		return a == b;
	if (a->kind != b->kind)
		return false;
	if (a->kind == EXRFILE_ATTR_STRING || a->kind == EXRFILE_ATTR_OTHER)
		return !strcmp(a->s, b->s);
	if (a->kind == EXRFILE_ATTR_INT)
		return a->i == b->i;
	return a->d == b->d || (isnan(a->d) && isnan(b->d));
}

static void attr_text(const exrfile_attr *a, char *buf, size_t n)
{
	if (!a)
		snprintf(buf, n, "(absent)");
	else if (a->kind == EXRFILE_ATTR_STRING)
		snprintf(buf, n, "\"%s\"", a->s);
	else if (a->kind == EXRFILE_ATTR_INT)
		snprintf(buf, n, "%d", a->i);
	else if (a->kind == EXRFILE_ATTR_OTHER)
		snprintf(buf, n, "(%s)", a->s);
	else
		snprintf(buf, n, "%.17g", a->d);
}

static int cmp(const void *a, const void *b)
{
	int x = *(const int *)a, y = *(const int *)b;
	return (x > y) - (x < y);
}

static bool rects_overlap(exrfile_rect a, exrfile_rect b)
{
	return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

/* Checks tile t against the first tile; reports the first difference. */
static bool same_frame(const exrfile_image *first, const char *first_path, const exrfile_image *t,
		       const char *path, diag *d)
{
	const exrfile_rect a = first->display, b = t->display;
	if (a.x0 != b.x0 || a.y0 != b.y0 || a.x1 != b.x1 || a.y1 != b.y1) {
		diag_file_error(d, path, "frame %dx%d differs from %s's %dx%d", b.x1 - b.x0, b.y1 - b.y0,
				first_path, a.x1 - a.x0, a.y1 - a.y0);
		return false;
	}
	bool same_channels = first->nchannels == t->nchannels;
	for (int c = 0; same_channels && c < t->nchannels; c++)
		same_channels = !strcmp(first->names[c], t->names[c]);
	if (!same_channels) {
		diag_file_error(d, path, "its channels differ from %s's", first_path);
		return false;
	}
	static const char *const keys[] = MERGE_KEYS;
	for (size_t k = 0; k < sizeof keys / sizeof keys[0]; k++) {
		const exrfile_attr *x = exrfile_attr_find(first, keys[k]), *y = exrfile_attr_find(t, keys[k]);
		if (!attr_equal(x, y)) {
			char vx[128], vy[128];
			attr_text(x, vx, sizeof vx);
			attr_text(y, vy, sizeof vy);
			diag_file_error(d, path, "%s is %s but %s has %s: the tiles come from different renders",
					keys[k], vy, first_path, vx);
			return false;
		}
	}
	return true;
}

/* Reports the pixels of the frame no tile covers, as rectangles on the grid of tile edges. */
static bool check_coverage(const exrfile_image *tiles, int n, diag *d)
{
	exrfile_rect f = tiles[0].display;
	/* The cut lines: frame edges and every tile edge, sorted and unique. */
	int *xs = mem_alloc((size_t)n * 2 + 2, sizeof(int)), *ys = mem_alloc((size_t)n * 2 + 2, sizeof(int));
	if (!xs || !ys) {
		mem_free(xs), mem_free(ys);
		diag_file_error(d, "merge", "out of memory");
		return false;
	}
	int nx = 0, ny = 0;
	xs[nx++] = f.x0, xs[nx++] = f.x1, ys[ny++] = f.y0, ys[ny++] = f.y1;
	for (int i = 0; i < n; i++) {
		xs[nx++] = tiles[i].data.x0, xs[nx++] = tiles[i].data.x1;
		ys[ny++] = tiles[i].data.y0, ys[ny++] = tiles[i].data.y1;
	}
	qsort(xs, (size_t)nx, sizeof(int), cmp);
	qsort(ys, (size_t)ny, sizeof(int), cmp);
	int ux = 0, uy = 0;
	for (int i = 0; i < nx; i++)
		if ((!ux || xs[ux - 1] != xs[i]) && xs[i] >= f.x0 && xs[i] <= f.x1)
			xs[ux++] = xs[i];
	for (int i = 0; i < ny; i++)
		if ((!uy || ys[uy - 1] != ys[i]) && ys[i] >= f.y0 && ys[i] <= f.y1)
			ys[uy++] = ys[i];
	int missing = 0;
	/* Each row band: runs of uncovered cells become one rectangle. */
	for (int j = 0; j + 1 < uy; j++) {
		int run_start = -1;
		for (int i = 0; i + 1 <= ux; i++) {
			bool covered = true;
			if (i + 1 < ux) {
				exrfile_rect cell = {xs[i], ys[j], xs[i + 1], ys[j + 1]};
				covered = false;
				for (int t = 0; t < n && !covered; t++)
					covered = rects_overlap(cell, tiles[t].data);
			}
			if (!covered && run_start < 0)
				run_start = i;
			if (covered && run_start >= 0) {
				diag_file_error(d, "merge", "no tile covers pixels x %d..%d, y %d..%d (%dx%d)",
						xs[run_start], xs[i] - 1, ys[j], ys[j + 1] - 1, xs[i] - xs[run_start],
						ys[j + 1] - ys[j]);
				missing++;
				run_start = -1;
			}
		}
	}
	mem_free(xs), mem_free(ys);
	return missing == 0;
}

bool merge_tiles(const char *out_path, const char *const *tile_paths, int ntiles, diag *d)
{
	if (ntiles < 1) {
		diag_file_error(d, out_path, "no tiles to merge");
		return false;
	}
	exrfile_image *tiles = mem_calloc((size_t)ntiles, sizeof *tiles);
	if (!tiles) {
		diag_file_error(d, out_path, "out of memory");
		return false;
	}
	bool ok = true;
	int nread = 0;
	for (int i = 0; i < ntiles && ok; i++, nread++)
		ok = exrfile_read(tile_paths[i], &tiles[i], d);
	for (int i = 1; i < nread && ok; i++)
		ok = same_frame(&tiles[0], tile_paths[0], &tiles[i], tile_paths[i], d);
	for (int i = 0; i < nread && ok; i++) {
		exrfile_rect r = tiles[i].data, f = tiles[i].display;
		if (r.x0 < f.x0 || r.y0 < f.y0 || r.x1 > f.x1 || r.y1 > f.y1) {
			diag_file_error(d, tile_paths[i], "its pixels lie outside its frame");
			ok = false;
		}
		for (int j = 0; j < i && ok; j++)
			if (rects_overlap(r, tiles[j].data)) {
				exrfile_rect o = tiles[j].data;
				diag_file_error(d, tile_paths[i],
						"overlaps %s at pixels x %d..%d, y %d..%d: each pixel must come from one tile",
						tile_paths[j], r.x0 > o.x0 ? r.x0 : o.x0, (r.x1 < o.x1 ? r.x1 : o.x1) - 1,
						r.y0 > o.y0 ? r.y0 : o.y0, (r.y1 < o.y1 ? r.y1 : o.y1) - 1);
				ok = false;
			}
	}
	if (ok)
		ok = check_coverage(tiles, nread, d);
	if (ok) {
		const exrfile_image *t0 = &tiles[0];
		exrfile_rect f = t0->display;
		size_t w = (size_t)(f.x1 - f.x0), h = (size_t)(f.y1 - f.y0);
		int nc = t0->nchannels;
		float *planes = mem_alloc(w * h, (size_t)nc * sizeof(float));
		exrfile_channel *chans = mem_calloc((size_t)nc, sizeof *chans);
		exrfile_attr *attrs = mem_calloc((size_t)t0->nattrs, sizeof *attrs);
		if (!planes || !chans || !attrs) {
			diag_file_error(d, out_path, "out of memory for a %zux%zu image", w, h);
			ok = false;
		}
		for (int i = 0; ok && i < nread; i++) {
			const exrfile_image *t = &tiles[i];
			for (int c = 0; c < nc; c++)
				for (int y = 0; y < t->height; y++)
					memcpy(planes + (size_t)c * w * h + (size_t)(t->data.y0 - f.y0 + y) * w +
						       (size_t)(t->data.x0 - f.x0),
					       t->planes[c] + (size_t)y * (size_t)t->width, (size_t)t->width * sizeof(float));
		}
		int na = 0;
		for (int a = 0; ok && a < t0->nattrs; a++) {
			const exrfile_attr *at = &t0->attrs[a];
			/* The file's own structure and the tile's identity are not carried over. */
			if (at->kind == EXRFILE_ATTR_OTHER || exrfile_attr_is_structural(at->name) ||
			    !strcmp(at->name, "circe.tile"))
				continue;
			attrs[na++] = *at;
		}
		if (ok) {
			for (int c = 0; c < nc; c++)
				chans[c] = (exrfile_channel){t0->names[c], planes + (size_t)c * w * h, 1, w};
			exrfile_write_desc desc = {f, f, nc, chans, na, attrs};
			ok = exrfile_write(out_path, &desc, d);
		}
		mem_free(planes), mem_free(chans), mem_free(attrs);
	}
	for (int i = 0; i < nread; i++)
		exrfile_free(&tiles[i]);
	mem_free(tiles);
	return ok;
}
