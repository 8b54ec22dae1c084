/* exr.h - OpenEXR images through the OpenEXR C core (openexr.h): float channels by name (RGBA and
 * any AOVs: `albedo.R`, `N.X`, `Z`, ...), display and data windows (a tile carries the full frame
 * as its display window), and header attributes. Writes are atomic (io/atomic.h). The prefix is
 * exrfile_ because OpenEXR owns exr_. */
#ifndef CIRCE_IO_EXR_H
#define CIRCE_IO_EXR_H

#include "base/diag.h"

#include <stdbool.h>
#include <stddef.h>

typedef enum exrfile_attr_kind {
	EXRFILE_ATTR_STRING,
	EXRFILE_ATTR_INT,
	EXRFILE_ATTR_FLOAT,
	EXRFILE_ATTR_DOUBLE,
	EXRFILE_ATTR_OTHER /* read only: a type circe does not interpret (text holds its type name) */
} exrfile_attr_kind;

typedef struct exrfile_attr {
	const char *name;
	exrfile_attr_kind kind;
	const char *s; /* STRING */
	int i;         /* INT */
	double d;      /* FLOAT and DOUBLE */
} exrfile_attr;

/* A rectangle of pixels, inclusive of x0,y0 and exclusive of x1,y1. */
typedef struct exrfile_rect {
	int x0, y0, x1, y1;
} exrfile_rect;

/* One channel to write: pixel (x, y) of the data window, counted from its corner, is
 * data[y * row_stride + x * pixel_stride] (strides in floats). */
typedef struct exrfile_channel {
	const char *name;
	const float *data;
	size_t pixel_stride, row_stride;
} exrfile_channel;

typedef struct exrfile_write_desc {
	exrfile_rect display; /* the whole frame */
	exrfile_rect data;    /* the pixels present; inside display */
	int nchannels;
	const exrfile_channel *channels;
	int nattrs;
	const exrfile_attr *attrs;
} exrfile_write_desc;

/* Writes the image with ZIP compression; false with the reason reported to d. */
bool exrfile_write(const char *path, const exrfile_write_desc *desc, diag *d);

/* An image read back: every channel converted to float, planar over the data window. */
typedef struct exrfile_image {
	exrfile_rect display, data;
	int width, height; /* of the data window */
	int nchannels;
	char **names;   /* sorted as in the file */
	float **planes; /* planes[c][y * width + x] */
	int nattrs;
	exrfile_attr *attrs; /* names and strings owned by the image */
} exrfile_image;

/* Samples (pixels times channels) exrfile_read accepts: 2^30, 4 GiB of float planes (a 16k x 16k
 * RGBA image). A header asking for more is refused before anything is allocated. */
#define EXRFILE_MAX_SAMPLES ((size_t)1 << 30)
/* Reads the first part of a scanline or tiled file (tiled: the highest-resolution level). */
bool exrfile_read(const char *path, exrfile_image *img, diag *d);
void exrfile_free(exrfile_image *img);
/* The plane of the named channel, or NULL. */
const float *exrfile_find_channel(const exrfile_image *img, const char *name);
/* True for the attributes OpenEXR itself writes from the image's structure (channels,
 * compression, windows, ...): a copy of a header must leave them out. */
bool exrfile_attr_is_structural(const char *name);
/* The named attribute, or NULL. */
const exrfile_attr *exrfile_attr_find(const exrfile_image *img, const char *name);

#endif
