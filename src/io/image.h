/* image.h - float RGBA images in memory, loaded from PNG, JPEG, EXR or Radiance HDR (textures,
 * environment maps, `compare`), and the PNG preview writer. Pixels are linear: 8- and 16-bit files are decoded from
 * sRGB unless the caller asks for raw values (normal maps are data, not colour). */
#ifndef CIRCE_IO_IMAGE_H
#define CIRCE_IO_IMAGE_H

#include "base/diag.h"

#include <stdbool.h>
#include <stddef.h>

typedef struct image {
	int width, height;
	float *rgba; /* width * height * 4, rows top to bottom */
	bool indexed; /* IMAGE_INDEX of a palette PNG: red holds each pixel's palette index (0 to 255) */
	int palette;  /* indexed: the palette's number of entries */
} image;

typedef enum image_encoding {
	IMAGE_SRGB, /* 8/16-bit values are sRGB-encoded colour: decode to linear */
	IMAGE_RAW,  /* 8/16-bit values map linearly to [0, 1] (normal maps, masks) */
	IMAGE_INDEX /* as IMAGE_RAW, but a palette PNG gives its palette indices (image.indexed) */
} image_encoding;

typedef enum image_format { IMAGE_UNKNOWN, IMAGE_PNG, IMAGE_JPEG, IMAGE_EXR, IMAGE_HDR } image_format;
enum { IMAGE_SIGNATURE_BYTES = 8 }; /* enough of a file's start for image_format_of */

/* The format a file's first n bytes announce (PNG and JPEG signatures, EXR magic, Radiance's "#?"). */
image_format image_format_of(const unsigned char *head, size_t n);

/* Loads by content (PNG and JPEG signatures, EXR magic, Radiance HDR's "#?"); missing channels: grey
 * fills RGB, alpha 1. EXR uses R, G, B, A (or Y for luminance); EXR and HDR are linear whatever
 * enc. False with the reason reported to d. */
bool image_load(const char *path, image_encoding enc, image *out, diag *d);
/* image_load refusing, from the size in a PNG, JPEG or EXR header and before anything is decoded,
 * an image whose float RGBA (16 bytes a pixel: all that loading takes for PNG and JPEG; an EXR's
 * planes come on top) exceeds max_bytes (0: no limit). */
bool image_load_limited(const char *path, image_encoding enc, size_t max_bytes, image *out, diag *d);
void image_free(image *img);

/* Bilinear lookup at texture coordinates (u, v), repeating outside [0, 1): u runs left to right,
 * v bottom to top (the OBJ/glTF-after-flip convention: v = 1 is row 0). out receives RGBA. */
void image_bilinear(const image *img, float u, float v, float out[4]);

/* sRGB transfer functions (IEC 61966-2-1). */
float image_srgb_to_linear(float v);
float image_linear_to_srgb(float v);

/* Writes 8-bit sRGB RGB PNG, atomically: each linear value times 2^exposure_stops, clamped to
 * [0, 1], encoded; NaN writes as 0. Pixel (x, y) is rgb[y * row_stride + x * pixel_stride + c]. */
bool png_write(const char *path, int width, int height, const float *rgb, size_t pixel_stride,
	       size_t row_stride, float exposure_stops, diag *d);

#endif
