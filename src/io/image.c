/* image.c - PNG (libpng), JPEG (libjpeg), EXR and Radiance HDR (RGBE) loading to linear float RGBA;
 * PNG writing. */
#include "io/image.h"

#include "base/mem.h"
#include "io/atomic.h"
#include "io/exr.h"

#include <OpenEXR/openexr.h>
#include <assert.h>
#include <errno.h>
#include <jpeglib.h>
#include <jerror.h>
#include <limits.h>
#include <math.h>
#include <png.h>
#include <setjmp.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

/* The largest texture side circe loads: 65536 pixels, beyond any real texture. */
#define IMAGE_MAX_SIDE 65536

float image_srgb_to_linear(float v)
{
	return v <= 0.04045f ? v / 12.92f : powf((v + 0.055f) / 1.055f, 2.4f);
}

float image_linear_to_srgb(float v)
{
	return v <= 0.0031308f ? v * 12.92f : 1.055f * powf(v, 1.0f / 2.4f) - 0.055f;
}

/* u mod 1 in [0, 1), NaN mapped to 0. */
static float wrap01(float u)
{
	float w = u - floorf(u);
	return w >= 0.0f && w < 1.0f ? w : 0.0f;
}

void image_bilinear(const image *img, float u, float v, float out[4])
{
	float x = wrap01(u) * (float)img->width - 0.5f, y = (1.0f - wrap01(v)) * (float)img->height - 0.5f;
	float fx = floorf(x), fy = floorf(y);
	float tx = x - fx, ty = y - fy;
	int x0 = (int)fx, y0 = (int)fy;
	int xs[2] = {x0, x0 + 1}, ys[2] = {y0, y0 + 1};
	assert(img->width > 0 && img->height > 0); /* image_load refuses an empty image */
	for (int k = 0; k < 2; k++) {
		xs[k] = (xs[k] % img->width + img->width) % img->width;
		ys[k] = (ys[k] % img->height + img->height) % img->height;
		assert(xs[k] >= 0 && xs[k] < img->width && ys[k] >= 0 && ys[k] < img->height);
	}
	float w[4] = {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty};
	for (int c = 0; c < 4; c++)
		out[c] = 0.0f;
	for (int k = 0; k < 4; k++) {
		const float *p = img->rgba + ((size_t)ys[k >> 1] * (size_t)img->width + (size_t)xs[k & 1]) * 4;
		for (int c = 0; c < 4; c++)
			out[c] += w[k] * p[c];
	}
}

void image_free(image *img)
{
	mem_free(img->rgba);
	img->rgba = NULL;
	img->width = img->height = 0;
}

/* Bytes of a w x h image as float RGBA: all that loading it takes, since the 8-bit samples are
 * decoded into the tail of the same array (from_integers). */
static double image_bytes(double w, double h)
{
	return w * h * 4.0 * sizeof(float);
}

/* The size the file's header gives, checked before anything is decoded: each side in range, and
 * the float image within max_bytes (0: no limit). */
static bool size_ok(double w, double h, size_t max_bytes, const char *path, diag *d)
{
	if (!(w >= 1 && h >= 1 && w <= IMAGE_MAX_SIDE && h <= IMAGE_MAX_SIDE)) {
		diag_file_error(d, path, "image size %.0fx%.0f is out of range (1 to %d per side)", w, h,
				IMAGE_MAX_SIDE);
		return false;
	}
	if (max_bytes && image_bytes(w, h) > (double)max_bytes) {
		diag_file_error(
		    d, path,
		    "a %.0fx%.0f image takes %.0f MiB as float RGBA, more than the %.0f MiB left under the "
		    "memory limit (--max-memory)",
		    w, h, image_bytes(w, h) / (1 << 20), (double)max_bytes / (1 << 20));
		return false;
	}
	return true;
}

static bool image_alloc(image *img, int w, int h, const char *path, diag *d)
{
	if (!size_ok(w, h, 0, path, d))
		return false;
	img->width = w;
	img->height = h;
	img->indexed = false, img->palette = 0;
	img->rgba = mem_alloc((size_t)w * (size_t)h * 4, sizeof(float));
	if (!img->rgba) {
		diag_file_error(d, path, "out of memory for a %dx%d image", w, h);
		return false;
	}
	return true;
}

/* Where the 8-bit samples of `comps` channels are decoded: the last comps * w * h bytes of the
 * float array, so from_integers can widen them in place. */
static unsigned char *sample_tail(const image *img, int comps)
{
	size_t n = (size_t)img->width * img->height;
	return (unsigned char *)img->rgba + n * 4 * sizeof(float) - n * (size_t)comps;
}

/* Fills the float image from 8-bit samples with `comps` channels (1 grey, 2 grey+alpha, 3 RGB,
 * 4 RGBA) at px, which may be sample_tail(img, comps): pixel i is read whole before its 16 bytes
 * are written, and they end before pixel i + 1's samples begin. */
static void from_integers(image *img, const unsigned char *px, int comps, image_encoding enc)
{
	float lut[256];
	for (int i = 0; i < 256; i++)
		lut[i] = enc == IMAGE_SRGB ? image_srgb_to_linear(i / 255.0f) : i / 255.0f;
	size_t n = (size_t)img->width * img->height;
	bool has_alpha = comps == 2 || comps == 4;
	for (size_t i = 0; i < n; i++) {
		const unsigned char *s = px + i * (size_t)comps;
		float v[3];
		for (int c = 0; c < 3; c++)
			v[c] = lut[s[comps <= 2 ? 0 : c]];
		/* Alpha is linear coverage, never sRGB-encoded. */
		float a = has_alpha ? s[comps - 1] / 255.0f : 1.0f;
		float *o = img->rgba + i * 4;
		o[0] = v[0], o[1] = v[1], o[2] = v[2], o[3] = a;
	}
}

/* A palette PNG's indices (POV-Ray's material_map and image patterns use them): libpng's colormap
 * read keeps a palette image's own order, so each pixel's byte is its index in the file's PLTE. */
static bool load_png_indices(png_image *pi, const char *path, size_t max_bytes, image *out, diag *d)
{
	unsigned char cmap[256 * 4];
	pi->format = PNG_FORMAT_RGBA_COLORMAP;
	if (!size_ok(pi->width, pi->height, max_bytes, path, d) ||
	    !image_alloc(out, (int)pi->width, (int)pi->height, path, d)) {
		png_image_free(pi);
		return false;
	}
	unsigned char *idx = sample_tail(out, 1);
	if (!png_image_finish_read(pi, NULL, idx, (png_int_32)pi->width, cmap)) {
		diag_file_error(d, path, "cannot read PNG: %s", pi->message);
		png_image_free(pi);
		image_free(out);
		return false;
	}
	size_t n = (size_t)out->width * (size_t)out->height;
	for (size_t i = 0; i < n; i++) { /* front to back: each index read before its texel is written */
		float v = idx[i];
		float *o = out->rgba + i * 4;
		o[0] = v, o[1] = o[2] = 0.0f, o[3] = 1.0f;
	}
	out->indexed = true;
	out->palette = (int)pi->colormap_entries;
	return true;
}

static bool load_png(FILE *fp, const char *path, image_encoding enc, size_t max_bytes, image *out, diag *d)
{
	png_image pi;
	memset(&pi, 0, sizeof pi);
	pi.version = PNG_IMAGE_VERSION;
	if (!png_image_begin_read_from_stdio(&pi, fp)) {
		diag_file_error(d, path, "cannot read PNG: %s", pi.message);
		return false;
	}
	if (enc == IMAGE_INDEX && (pi.format & PNG_FORMAT_FLAG_COLORMAP))
		return load_png_indices(&pi, path, max_bytes, out, d);
	/* Let libpng expand palettes and low bit depths to 8-bit RGBA or grey+alpha. */
	int comps = PNG_IMAGE_SAMPLE_CHANNELS(pi.format) >= 3 ? 4 : 2;
	pi.format = comps == 4 ? PNG_FORMAT_RGBA : PNG_FORMAT_GA;
	if (!size_ok(pi.width, pi.height, max_bytes, path, d) ||
	    !image_alloc(out, (int)pi.width, (int)pi.height, path, d)) {
		png_image_free(&pi);
		return false;
	}
	unsigned char *buf = sample_tail(out, comps);
	if (!png_image_finish_read(&pi, NULL, buf, (png_int_32)PNG_IMAGE_ROW_STRIDE(pi), NULL)) {
		diag_file_error(d, path, "cannot read PNG: %s", pi.message);
		png_image_free(&pi);
		image_free(out);
		return false;
	}
	from_integers(out, buf, comps, enc);
	return true;
}

struct jpeg_fail {
	struct jpeg_error_mgr pub;
	jmp_buf jump;
	char msg[JMSG_LENGTH_MAX];
	char warning[JMSG_LENGTH_MAX]; /* the first warning (corrupt or missing data), or "" */
};

static void jpeg_on_error(j_common_ptr cinfo)
{
	struct jpeg_fail *f = (struct jpeg_fail *)cinfo->err;
	(*cinfo->err->format_message)(cinfo, f->msg);
	longjmp(f->jump, 1);
}

/* Trace messages (level >= 0) are dropped; warnings (-1: data corrupt or cut short, which libjpeg
 * fills with grey) are counted and the first kept. */
static void jpeg_on_message(j_common_ptr cinfo, int level)
{
	struct jpeg_fail *f = (struct jpeg_fail *)cinfo->err;
	if (level >= 0)
		return;
	if (!f->pub.num_warnings++)
		(*cinfo->err->format_message)(cinfo, f->warning);
}

/* libjpeg reports errors by longjmp; the image is the only allocation, freed on that path. */
static bool load_jpeg(FILE *fp, const char *path, image_encoding enc, size_t max_bytes, image *out, diag *d)
{
	struct jpeg_decompress_struct cinfo;
	struct jpeg_fail jerr;
	jerr.warning[0] = '\0';
	cinfo.err = jpeg_std_error(&jerr.pub);
	jerr.pub.error_exit = jpeg_on_error;
	jerr.pub.emit_message = jpeg_on_message;
	if (setjmp(jerr.jump)) {
		if (jerr.pub.msg_code == JERR_NO_BACKING_STORE)
			diag_file_error(d, path,
					"a progressive %ux%u JPEG needs its coefficients in memory too, more than "
					"the %.0f MiB left under the memory limit (--max-memory)",
					cinfo.image_width, cinfo.image_height, (double)max_bytes / (1 << 20));
		else
			diag_file_error(d, path, "cannot read JPEG: %s", jerr.msg);
		jpeg_destroy_decompress(&cinfo);
		image_free(out);
		return false;
	}
	jpeg_create_decompress(&cinfo);
	jpeg_stdio_src(&cinfo, fp);
	jpeg_read_header(&cinfo, TRUE);
	/* The header's size, before jpeg_start_decompress allocates anything for it. */
	if (!size_ok(cinfo.image_width, cinfo.image_height, max_bytes, path, d)) {
		jpeg_destroy_decompress(&cinfo);
		return false;
	}
	/* A progressive file is decoded through a whole-image buffer of coefficients (2 bytes a
	 * sample) on top of the image: libjpeg refuses it (JERR_NO_BACKING_STORE) beyond what the
	 * limit leaves. Baseline files need no such buffer. */
	double left = (double)max_bytes - image_bytes(cinfo.image_width, cinfo.image_height);
	if (max_bytes)
		cinfo.mem->max_memory_to_use = left < (double)LONG_MAX ? (long)left : LONG_MAX;
	cinfo.out_color_space = cinfo.num_components == 1 ? JCS_GRAYSCALE : JCS_RGB;
	jpeg_start_decompress(&cinfo);
	int comps = cinfo.output_components;
	if (!image_alloc(out, (int)cinfo.output_width, (int)cinfo.output_height, path, d)) {
		jpeg_destroy_decompress(&cinfo);
		return false;
	}
	unsigned char *buf = sample_tail(out, comps);
	size_t stride = (size_t)cinfo.output_width * comps;
	while (cinfo.output_scanline < cinfo.output_height) {
		JSAMPROW row = buf + cinfo.output_scanline * stride;
		jpeg_read_scanlines(&cinfo, &row, 1);
	}
	jpeg_finish_decompress(&cinfo);
	jpeg_destroy_decompress(&cinfo);
	from_integers(out, buf, comps, enc);
	if (jerr.pub.num_warnings)
		diag_file_warning(
		    d, path,
		    "the JPEG data is corrupt or cut short (%ld warning(s), the first: %s): the "
		    "missing part is grey",
		    jerr.pub.num_warnings, jerr.warning);
	return true;
}

/* The size of an EXR's first part from its header alone (OpenEXR reads nothing else at start);
 * false when the header cannot be read, which exrfile_read then reports. */
static bool exr_header_size(const char *path, double *w, double *h)
{
	exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
	init.flags = EXR_CONTEXT_FLAG_SILENT_HEADER_PARSE;
	init.error_handler_fn = NULL;
	exr_context_t ctx = NULL;
	exr_attr_box2i_t dw;
	bool ok = exr_start_read(&ctx, path, &init) == EXR_ERR_SUCCESS &&
		  exr_get_data_window(ctx, 0, &dw) == EXR_ERR_SUCCESS;
	if (ctx)
		exr_finish(&ctx);
	if (ok)
		*w = (double)dw.max.x - dw.min.x + 1.0, *h = (double)dw.max.y - dw.min.y + 1.0;
	return ok;
}

static bool load_exr(const char *path, size_t max_bytes, image *out, diag *d)
{
	double hw, hh;
	if (max_bytes && exr_header_size(path, &hw, &hh) && !size_ok(hw, hh, max_bytes, path, d))
		return false;
	exrfile_image ex;
	if (!exrfile_read(path, &ex, d))
		return false;
	const float *r = exrfile_find_channel(&ex, "R"), *g = exrfile_find_channel(&ex, "G"),
		    *b = exrfile_find_channel(&ex, "B"), *a = exrfile_find_channel(&ex, "A"),
		    *y = exrfile_find_channel(&ex, "Y");
	if (!(r && g && b) && !y) {
		diag_file_error(d, path, "EXR has neither R, G, B nor Y channels");
		exrfile_free(&ex);
		return false;
	}
	if (!size_ok(ex.width, ex.height, max_bytes, path, d) ||
	    !image_alloc(out, ex.width, ex.height, path, d)) {
		exrfile_free(&ex);
		return false;
	}
	size_t n = (size_t)ex.width * ex.height;
	for (size_t i = 0; i < n; i++) {
		float *o = out->rgba + i * 4;
		if (r && g && b)
			o[0] = r[i], o[1] = g[i], o[2] = b[i];
		else
			o[0] = o[1] = o[2] = y[i];
		o[3] = a ? a[i] : 1.0f;
	}
	exrfile_free(&ex);
	return true;
}

/* ---- Radiance HDR (RGBE) ------------------------------------------------------------------ */

/* One RGBE texel as linear floats: Radiance's colr_color, (m + 0.5) 2^(e - 136), 0 for e = 0. */
static void rgbe_to_float(const unsigned char *c, float *o)
{
	if (!c[3]) {
		o[0] = o[1] = o[2] = 0.0f;
	} else {
		double f = ldexp(1.0, (int)c[3] - 136);
		for (int i = 0; i < 3; i++)
			o[i] = (float)((c[i] + 0.5) * f);
	}
	o[3] = 1.0f;
}

/* A flat scanline (4 bytes a texel) with the old run-length form: a texel 1, 1, 1, n repeats the
 * one before n << shift times, the shift growing by 8 for each such texel in a row. */
static bool hdr_old_line(FILE *fp, unsigned char *line, int width, int start)
{
	int shift = 0;
	for (int x = start; x < width;) {
		unsigned char *t = line + 4 * (size_t)x;
		if (fread(t, 1, 4, fp) != 4)
			return false;
		if (t[0] == 1 && t[1] == 1 && t[2] == 1) {
			if (!x)
				return false; /* nothing to repeat */
			long n = (long)t[3] << shift;
			if (n > width - x)
				return false;
			for (long i = 0; i < n; i++, x++)
				memcpy(line + 4 * (size_t)x, line + 4 * (size_t)(x - 1), 4);
			shift += 8;
			if (shift > 16)
				return false;
		} else {
			x++, shift = 0;
		}
	}
	return true;
}

/* One scanline: the new run-length form (2, 2, width's two bytes, then each of the four channels
 * as runs: a count above 128 repeats the next byte count - 128 times, else that many bytes
 * follow), or the old flat one. */
static bool hdr_line(FILE *fp, unsigned char *line, int width)
{
	if (width < 8 || width > 0x7fff)
		return hdr_old_line(fp, line, width, 0);
	unsigned char h[4];
	if (fread(h, 1, 4, fp) != 4)
		return false;
	if (h[0] != 2 || h[1] != 2 || (h[2] & 128)) { /* a flat line: h is its first texel */
		memcpy(line, h, 4);
		return hdr_old_line(fp, line, width, 1);
	}
	if (((int)h[2] << 8 | h[3]) != width)
		return false;
	for (int c = 0; c < 4; c++)
		for (int x = 0; x < width;) {
			int k = getc(fp);
			if (k == EOF)
				return false;
			if (k > 128) {
				int v = getc(fp);
				k -= 128;
				if (v == EOF || k > width - x)
					return false;
				while (k--)
					line[4 * (size_t)x++ + c] = (unsigned char)v;
			} else {
				if (k == 0 || k > width - x)
					return false;
				while (k--) {
					int v = getc(fp);
					if (v == EOF)
						return false;
					line[4 * (size_t)x++ + c] = (unsigned char)v;
				}
			}
		}
	return true;
}

/* A Radiance picture: "#?" magic, header lines to an empty one (FORMAT must be RGBE, not XYZE;
 * EXPOSURE is ignored, as POV-Ray's hdr.cpp ignores it), the resolution "-Y H +X W" (rows top to
 * bottom, the standard orientation and the only one POV-Ray reads), then the scanlines. */
static bool load_hdr(FILE *fp, const char *path, size_t max_bytes, image *out, diag *d)
{
	char buf[512];
	bool rgbe = true;
	if (!fgets(buf, sizeof buf, fp) || strncmp(buf, "#?", 2) != 0) {
		diag_file_error(d, path, "not a Radiance HDR file (no '#?' line)");
		return false;
	}
	for (;;) {
		if (!fgets(buf, sizeof buf, fp)) {
			diag_file_error(d, path, "Radiance HDR header ends before its resolution line");
			return false;
		}
		if (buf[0] == '\n')
			break;
		if (!strncmp(buf, "FORMAT=", 7) && strncmp(buf + 7, "32-bit_rle_rgbe", 15) != 0)
			rgbe = false;
	}
	if (!rgbe) {
		diag_file_error(d, path, "Radiance HDR file is not RGBE (FORMAT=32-bit_rle_rgbe): XYZE is not supported");
		return false;
	}
	int w = 0, h = 0;
	char tail;
	if (!fgets(buf, sizeof buf, fp) || sscanf(buf, "-Y %d +X %d%c", &h, &w, &tail) != 3 || tail != '\n') {
		diag_file_error(d, path, "Radiance HDR resolution line is not '-Y height +X width' (other orientations "
					 "are not supported)");
		return false;
	}
	if (!size_ok(w, h, max_bytes, path, d) || !image_alloc(out, w, h, path, d))
		return false;
	unsigned char *line = mem_alloc((size_t)w, 4);
	if (!line) {
		image_free(out);
		diag_file_error(d, path, "out of memory for a %dx%d image", w, h);
		return false;
	}
	bool ok = true;
	for (int y = 0; ok && y < h; y++) {
		ok = hdr_line(fp, line, w);
		for (int x = 0; ok && x < w; x++)
			rgbe_to_float(line + 4 * (size_t)x, out->rgba + 4 * ((size_t)y * w + x));
		if (!ok)
			diag_file_error(d, path, "Radiance HDR data is corrupt or cut short at row %d of %d", y + 1, h);
	}
	mem_free(line);
	if (!ok)
		image_free(out);
	return ok;
}

image_format image_format_of(const unsigned char *head, size_t n)
{
	if (n >= 8 && !png_sig_cmp(head, 0, 8))
		return IMAGE_PNG;
	if (n >= 3 && head[0] == 0xFF && head[1] == 0xD8 && head[2] == 0xFF)
		return IMAGE_JPEG;
	if (n >= 4 && head[0] == 0x76 && head[1] == 0x2f && head[2] == 0x31 && head[3] == 0x01)
		return IMAGE_EXR;
	if (n >= 2 && head[0] == '#' && head[1] == '?')
		return IMAGE_HDR;
	return IMAGE_UNKNOWN;
}

bool image_load(const char *path, image_encoding enc, image *out, diag *d)
{
	return image_load_limited(path, enc, 0, out, d);
}

bool image_load_limited(const char *path, image_encoding enc, size_t max_bytes, image *out, diag *d)
{
	out->rgba = NULL;
	out->width = out->height = 0;
	FILE *fp = fopen(path, "rb");
	if (!fp) {
		diag_file_error(d, path, "cannot open: %s", strerror(errno));
		return false;
	}
	unsigned char magic[IMAGE_SIGNATURE_BYTES] = {0};
	size_t got = fread(magic, 1, sizeof magic, fp);
	rewind(fp);
	bool ok;
	image_format fmt = image_format_of(magic, got);
	if (fmt == IMAGE_PNG)
		ok = load_png(fp, path, enc, max_bytes, out, d);
	else if (fmt == IMAGE_JPEG)
		ok = load_jpeg(fp, path, enc, max_bytes, out, d);
	else if (fmt == IMAGE_EXR)
		ok = load_exr(path, max_bytes, out, d);
	else if (fmt == IMAGE_HDR)
		ok = load_hdr(fp, path, max_bytes, out, d);
	else {
		diag_file_error(d, path, "not a PNG, JPEG, OpenEXR or Radiance HDR image");
		ok = false;
	}
	fclose(fp);
	return ok;
}

bool png_write(const char *path, int width, int height, const float *rgb, size_t pixel_stride,
	       size_t row_stride, float exposure_stops, diag *d)
{
	if (width <= 0 || height <= 0) {
		diag_file_error(d, path, "invalid PNG size %dx%d", width, height);
		return false;
	}
	unsigned char *buf = mem_alloc((size_t)width * 3, (size_t)height);
	if (!buf) {
		diag_file_error(d, path, "out of memory");
		return false;
	}
	float gain = exp2f(exposure_stops);
	for (int y = 0; y < height; y++)
		for (int x = 0; x < width; x++)
			for (int c = 0; c < 3; c++) {
				float v = rgb[(size_t)y * row_stride + (size_t)x * pixel_stride + c] * gain;
				v = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; /* also maps NaN to 0 */
				buf[((size_t)y * width + x) * 3 + c] =
					(unsigned char)lrintf(image_linear_to_srgb(v) * 255.0f);
			}
	atomic_file af;
	if (!atomic_open(&af, path, d)) {
		mem_free(buf);
		return false;
	}
	FILE *fp = fdopen(dup(af.fd), "wb");
	png_image pi;
	memset(&pi, 0, sizeof pi);
	pi.version = PNG_IMAGE_VERSION;
	pi.width = (png_uint_32)width;
	pi.height = (png_uint_32)height;
	pi.format = PNG_FORMAT_RGB;
	bool ok = fp && png_image_write_to_stdio(&pi, fp, 0, buf, 0, NULL);
	if (fp && fclose(fp) != 0)
		ok = false;
	mem_free(buf);
	if (!ok) {
		diag_file_error(d, path, "cannot write PNG: %s", fp ? pi.message : strerror(errno));
		atomic_abort(&af);
		return false;
	}
	return atomic_commit(&af, d);
}
