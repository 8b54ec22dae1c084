/* compare.c - pixel statistics of A against B over their shared channels. */
#include "io/compare.h"

#include "base/mem.h"

#include <math.h>
#include <string.h>

/* Sets up `diff` with the same windows as a and one plane per shared channel. */
static bool diff_init(exrfile_image *diff, const exrfile_image *a, int nshared)
{
	memset(diff, 0, sizeof *diff);
	diff->display = a->display;
	diff->data = a->data;
	diff->width = a->width;
	diff->height = a->height;
	diff->names = mem_calloc((size_t)nshared, sizeof(char *));
	diff->planes = mem_calloc((size_t)nshared, sizeof(float *));
	return diff->names && diff->planes;
}

bool compare_images(const exrfile_image *a, const char *name_a, const exrfile_image *b,
		    const char *name_b, double threshold, compare_result *r, exrfile_image *diff,
		    diag *d)
{
	memset(r, 0, sizeof *r);
	if (a->data.x0 != b->data.x0 || a->data.y0 != b->data.y0 || a->data.x1 != b->data.x1 ||
	    a->data.y1 != b->data.y1) {
		diag_file_error(d, name_a, "size %dx%d (data window %d,%d-%d,%d) differs from %s: %dx%d (%d,%d-%d,%d)",
				a->width, a->height, a->data.x0, a->data.y0, a->data.x1, a->data.y1,
				name_b, b->width, b->height, b->data.x0, b->data.y0, b->data.x1, b->data.y1);
		return false;
	}
	const float *pa[64], *pb[64];
	const char *names[64];
	int n = 0;
	for (int c = 0; c < b->nchannels && n < 64; c++) {
		const float *p = exrfile_find_channel(a, b->names[c]);
		if (p) {
			pa[n] = p;
			pb[n] = b->planes[c];
			names[n++] = b->names[c];
		}
	}
	if (n == 0) {
		diag_file_error(d, name_a, "shares no channel with %s", name_b);
		return false;
	}
	if (diff) {
		if (!diff_init(diff, a, n)) {
			exrfile_free(diff);
			diag_file_error(d, name_a, "out of memory");
			return false;
		}
		for (int c = 0; c < n; c++) {
			diff->nchannels++;
			diff->names[c] = mem_strdup(names[c]);
			diff->planes[c] = mem_calloc((size_t)a->width * a->height, sizeof(float));
			if (!diff->names[c] || !diff->planes[c]) {
				exrfile_free(diff);
				diag_file_error(d, name_a, "out of memory");
				return false;
			}
		}
	}
	size_t npix = (size_t)a->width * a->height;
	double se = 0, rel = 0, abs_sum = 0, sum_a = 0, sum_b = 0;
	size_t finite_values = 0;
	r->max_abs = -1;
	for (size_t i = 0; i < npix; i++) {
		double worst = 0;
		bool bad = false;
		for (int c = 0; c < n; c++) {
			double va = pa[c][i], vb = pb[c][i];
			if (isnan(va) || isinf(va)) {
				if (isnan(va))
					r->nan_a++;
				else
					r->inf_a++;
				bad = true;
				if (diff)
					diff->planes[c][i] = (float)INFINITY;
				continue;
			}
			double e = fabs(va - vb);
			se += e * e;
			rel += e * e / (vb * vb + COMPARE_RELMSE_EPS);
			abs_sum += e;
			sum_a += va;
			sum_b += vb;
			finite_values++;
			if (e > worst)
				worst = e;
			if (e > r->max_abs) {
				r->max_abs = e;
				r->max_x = a->data.x0 + (int)(i % (size_t)a->width);
				r->max_y = a->data.y0 + (int)(i / (size_t)a->width);
				r->max_channel = names[c];
			}
			if (diff)
				diff->planes[c][i] = (float)e;
		}
		if (bad || worst > threshold)
			r->over++;
	}
	r->nchannels = n;
	r->pixels = npix;
	if (r->max_abs < 0) { /* every value of A non-finite */
		r->max_abs = INFINITY;
		r->max_channel = names[0];
	}
	double mse = finite_values ? se / (double)finite_values : INFINITY;
	r->rmse = sqrt(mse);
	r->relmse = finite_values ? rel / (double)finite_values : INFINITY;
	r->mean_abs = finite_values ? abs_sum / (double)finite_values : INFINITY;
	r->mean_a = finite_values ? sum_a / (double)finite_values : NAN;
	r->mean_b = finite_values ? sum_b / (double)finite_values : NAN;
	r->psnr = mse > 0 ? 10.0 * log10(COMPARE_PSNR_PEAK * COMPARE_PSNR_PEAK / mse) : INFINITY;
	return true;
}
