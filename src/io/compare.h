/* compare.h - error figures of an image A against a reference B (the golden-test contract, as
 * OpenImageIO's idiff): over every channel the two share, per-value RMSE, relMSE, mean and max
 * absolute error, PSNR, and the fraction of pixels whose largest channel error exceeds a
 * threshold. Non-finite values of A are counted and always exceed the threshold. */
#ifndef CIRCE_IO_COMPARE_H
#define CIRCE_IO_COMPARE_H

#include "io/exr.h"

#include <stdbool.h>
#include <stddef.h>

/* relMSE = mean((a - b)^2 / (b^2 + eps)): eps keeps black reference pixels from dominating
 * (the value used by Rousselle et al. 2011 and most denoising papers). */
#define COMPARE_RELMSE_EPS 1e-2
/* PSNR is computed against a peak of 1.0, the white of a display-referred image. */
#define COMPARE_PSNR_PEAK 1.0

typedef struct compare_result {
	int nchannels;         /* channels compared */
	size_t pixels;         /* pixels compared */
	double rmse, relmse, mean_abs, max_abs, psnr;
	double mean_a, mean_b; /* mean values of A and of B (over A's finite values): a signed bias */
	int max_x, max_y;      /* where max_abs was found (image coordinates) */
	const char *max_channel;
	size_t over;           /* pixels with error > threshold (or a non-finite value in A) */
	size_t nan_a, inf_a;   /* non-finite values in A */
} compare_result;

/* Compares a against b. False (reported to d, naming the files) when their data windows differ
 * or they share no channel. When diff is not NULL, it receives |a - b| per shared channel,
 * planar like exrfile_image (caller frees diff->planes[c] and the arrays via exrfile_free). */
bool compare_images(const exrfile_image *a, const char *name_a, const exrfile_image *b,
		    const char *name_b, double threshold, compare_result *r, exrfile_image *diff,
		    diag *d);

#endif
