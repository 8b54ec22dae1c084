/* test_image: PNG written then read back within one 8-bit step (sRGB round trip), exposure and
 * clamping, NaN written as black; JPEG and EXR textures load; bad files are clear errors. */
#include "base/diag.h"
#include "check.h"
#include "io/exr.h"
#include "io/image.h"

#include <jpeglib.h>
#include <png.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[] = "/tmp/circe-test-image-XXXXXX";

static const char *path(const char *name) { return check_path(dir, name); }

static void write_jpeg(const char *p, int w, int h)
{
	struct jpeg_compress_struct c;
	struct jpeg_error_mgr err;
	c.err = jpeg_std_error(&err);
	jpeg_create_compress(&c);
	FILE *f = fopen(p, "wb");
	jpeg_stdio_dest(&c, f);
	c.image_width = (JDIMENSION)w, c.image_height = (JDIMENSION)h;
	c.input_components = 3, c.in_color_space = JCS_RGB;
	jpeg_set_defaults(&c);
	jpeg_set_quality(&c, 100, TRUE);
	jpeg_start_compress(&c, TRUE);
	unsigned char *row = malloc((size_t)w * 3);
	for (int y = 0; y < h; y++) {
		for (int x = 0; x < w * 3; x++)
			row[x] = 128;
		jpeg_write_scanlines(&c, &row, 1);
	}
	jpeg_finish_compress(&c);
	jpeg_destroy_compress(&c);
	fclose(f);
	free(row);
}

int main(void)
{
	if (!mkdtemp(dir))
		return 99;
	diag d;
	diag_init(&d, stderr);
	CHECK_NEAR(image_srgb_to_linear(image_linear_to_srgb(0.18f)), 0.18f, 1e-6);
	CHECK_NEAR(image_linear_to_srgb(1.0f), 1.0f, 1e-6);
	CHECK_NEAR(image_srgb_to_linear(0.5f), 0.2140411f, 1e-6);

	enum { W = 64, H = 4 };
	float rgb[W * H * 3];
	for (int y = 0; y < H; y++)
		for (int x = 0; x < W; x++)
			for (int c = 0; c < 3; c++)
				rgb[(y * W + x) * 3 + c] = (float)x / (W - 1) * (c == 0 ? 1.0f : 0.5f);
	rgb[0] = NAN, rgb[1] = 5.0f, rgb[2] = -1.0f;
	CHECK(png_write(path("a.png"), W, H, rgb, 3, W * 3, 0.0f, &d), "png write");
	image img;
	CHECK(image_load(path("a.png"), IMAGE_SRGB, &img, &d), "png read");
	CHECK(img.width == W && img.height == H, "png size %dx%d", img.width, img.height);
	double worst = 0;
	for (int i = 3; i < W * H; i++)
		for (int c = 0; c < 3; c++) {
			float want = rgb[i * 3 + c];
			/* One 8-bit sRGB step is at most 1/255 in the encoded domain. */
			float e = fabsf(image_linear_to_srgb(img.rgba[i * 4 + c]) - image_linear_to_srgb(want));
			if (e > worst)
				worst = e;
		}
	CHECK(worst <= 0.5 / 255 + 1e-6, "png round trip error %g in sRGB units", worst);
	CHECK(img.rgba[0] == 0.0f && img.rgba[1] == 1.0f && img.rgba[2] == 0.0f && img.rgba[3] == 1.0f,
	      "NaN -> 0, 5 -> 1 (clamped), -1 -> 0, alpha 1: %g %g %g %g", img.rgba[0], img.rgba[1],
	      img.rgba[2], img.rgba[3]);
	image_free(&img);
	/* +1 stop doubles the linear value. */
	float grey[3] = {0.2f, 0.2f, 0.2f};
	CHECK(png_write(path("b.png"), 1, 1, grey, 3, 3, 1.0f, &d), "png write with exposure");
	CHECK(image_load(path("b.png"), IMAGE_SRGB, &img, &d), "read");
	CHECK_NEAR(img.rgba[0], 0.4, 0.01);
	image_free(&img);
	CHECK(image_load(path("b.png"), IMAGE_RAW, &img, &d), "read raw");
	CHECK_NEAR(img.rgba[0], image_linear_to_srgb(0.4f), 0.005);
	image_free(&img);

	write_jpeg(path("c.jpg"), 8, 8);
	CHECK(image_load(path("c.jpg"), IMAGE_RAW, &img, &d), "jpeg read");
	CHECK(img.width == 8 && img.height == 8, "jpeg size");
	CHECK_NEAR(img.rgba[0], 128.0 / 255.0, 1.5 / 255.0);
	image_free(&img);

	float lum[6] = {0.5f, 1, 2, 4, 8, 16};
	exrfile_channel ych = {"Y", lum, 1, 3};
	exrfile_write_desc desc = {{0, 0, 3, 2}, {0, 0, 3, 2}, 1, &ych, 0, NULL};
	CHECK(exrfile_write(path("d.exr"), &desc, &d), "exr write");
	CHECK(image_load(path("d.exr"), IMAGE_SRGB, &img, &d), "exr texture read");
	CHECK(img.width == 3 && img.rgba[4 * 5 + 1] == 16.0f, "exr Y channel expands to grey");
	image_free(&img);

	/* Bilinear lookup: texel centres give the texel, midpoints the mean, u and v repeat, v = 1 is
	 * the top row. A 2x2 image: top row 0 and 1, bottom row 2 and 3 (in R). */
	image tex = {2, 2, (float[]){0, 0, 0, 1, 1, 0, 0, 1, 2, 0, 0, 1, 3, 0, 0, 1}, false, 0};
	float px[4];
	image_bilinear(&tex, 0.25f, 0.75f, px);
	CHECK_NEAR(px[0], 0.0, 1e-6);
	image_bilinear(&tex, 0.75f, 0.25f, px);
	CHECK_NEAR(px[0], 3.0, 1e-6);
	image_bilinear(&tex, 0.5f, 0.5f, px);
	CHECK_NEAR(px[0], 1.5, 1e-6);
	image_bilinear(&tex, 1.25f, -0.75f, px);
	CHECK_NEAR(px[0], 2.0, 1e-6);
	CHECK_NEAR(px[3], 1.0, 1e-6);
	/* At u = 0 the left texel's centre is half a texel away: the mean of the two wrapped texels. */
	image_bilinear(&tex, 0.0f, 0.75f, px);
	CHECK_NEAR(px[0], 0.5, 1e-6);

	char *buf = NULL;
	size_t len = 0;
	FILE *mem = open_memstream(&buf, &len);
	diag e;
	diag_init(&e, mem);
	FILE *f = fopen(path("bad.png"), "wb");
	fwrite("\x89PNG\r\n\x1a\n garbage", 1, 17, f);
	fclose(f);
	CHECK(!image_load(path("bad.png"), IMAGE_SRGB, &img, &e), "corrupt png fails");
	f = fopen(path("bad.jpg"), "wb");
	fwrite("\xff\xd8\xff\xe0 garbage", 1, 12, f);
	fclose(f);
	CHECK(!image_load(path("bad.jpg"), IMAGE_SRGB, &img, &e), "corrupt jpeg fails");
	CHECK(!image_load(path("none.png"), IMAGE_SRGB, &img, &e), "missing file fails");
	f = fopen(path("x.txt"), "wb");
	fputs("hello", f);
	fclose(f);
	CHECK(!image_load(path("x.txt"), IMAGE_SRGB, &img, &e), "unknown format fails");
	fclose(mem);
	CHECK(strstr(buf, "bad.png: error: cannot read PNG") && strstr(buf, "bad.jpg: error: cannot read JPEG") &&
		      strstr(buf, "none.png: error: cannot open: No such file or directory") &&
		      strstr(buf, "x.txt: error: not a PNG, JPEG, OpenEXR or Radiance HDR image"),
	      "messages:\n%s", buf);
	free(buf);
	diag_free(&e);
	/* A palette PNG read as IMAGE_INDEX gives its palette indices in red, not its colours (entries
	 * 0 and 2 are the same black, 0 transparent): POV-Ray's material_map picks textures by them. */
	png_image pw;
	memset(&pw, 0, sizeof pw);
	pw.version = PNG_IMAGE_VERSION, pw.width = 4, pw.height = 1, pw.format = PNG_FORMAT_RGBA_COLORMAP;
	pw.colormap_entries = 4;
	const unsigned char cmap[16] = {0, 0, 0, 0, 255, 0, 0, 255, 0, 0, 0, 255, 0, 0, 255, 255}, idx[4] = {2, 1, 3, 0};
	CHECK(png_image_write_to_file(&pw, path("p.png"), 0, idx, 4, cmap), "palette png write: %s", pw.message);
	CHECK(image_load(path("p.png"), IMAGE_INDEX, &img, &d) && img.indexed && img.palette == 4, "palette png read as indices");
	for (int i = 0; i < 4; i++)
		CHECK(img.rgba[4 * i] == (float)idx[i], "palette index %d: %g, want %d", i, img.rgba[4 * i], idx[i]);
	image_free(&img);
	CHECK(image_load(path("p.png"), IMAGE_RAW, &img, &d) && !img.indexed && img.rgba[0] == 0.0f && img.rgba[4] == 1.0f &&
		      img.rgba[11] == 1.0f && img.rgba[15] == 0.0f,
	      "the same png as colours: black, red, blue, clear black");
	image_free(&img);
	CHECK(image_load(path("a.png"), IMAGE_INDEX, &img, &d) && !img.indexed, "an RGB png has no indices");
	image_free(&img);
	/* Radiance HDR (RGBE), written by hand: texel (m + 0.5) 2^(e - 136), 0 for e = 0 (Radiance's
	 * colr_color). new.hdr is 8 x 2 in the run-length form (row 0 all runs, row 1 literals),
	 * old.hdr 3 x 1 flat with the old repeat texel 1, 1, 1, 2; EXPOSURE is ignored (POV-Ray's). */
	f = fopen(path("new.hdr"), "wb");
	fputs("#?RADIANCE\n# a comment\nFORMAT=32-bit_rle_rgbe\nEXPOSURE=2\n\n-Y 2 +X 8\n", f);
	const unsigned char row0[] = {2, 2, 0, 8, 136, 128, 136, 64, 136, 32, 136, 129};
	fwrite(row0, 1, sizeof row0, f);
	unsigned char row1[4 + 4 * 9];
	memcpy(row1, (const unsigned char[]){2, 2, 0, 8}, 4);
	for (int c = 0; c < 4; c++) {
		row1[4 + 9 * c] = 8;
		for (int x = 0; x < 8; x++)
			row1[5 + 9 * c + x] = (unsigned char)(c == 0 ? 16 * x : c == 1 ? 0 : c == 2 ? 255 : x ? 128 + x % 2 : 0);
	}
	fwrite(row1, 1, sizeof row1, f);
	fclose(f);
	CHECK(image_load(path("new.hdr"), IMAGE_SRGB, &img, &d) && img.width == 8 && img.height == 2, "run-length hdr");
	for (int x = 0; x < 8; x++) {
		const float *t = img.rgba + 4 * x, *b = img.rgba + 4 * (8 + x);
		CHECK(t[0] == 128.5f / 128 && t[1] == 64.5f / 128 && t[2] == 32.5f / 128 && t[3] == 1, "hdr row 0, texel %d", x);
		float sc = x ? (x % 2 ? 2.0f : 1.0f) / 256 : 0;
		CHECK(b[0] == (16 * x + 0.5f) * sc && b[1] == 0.5f * sc && b[2] == 255.5f * sc, "hdr row 1, texel %d: %g %g %g",
		      x, b[0], b[1], b[2]);
	}
	image_free(&img);
	f = fopen(path("old.hdr"), "wb");
	fputs("#?RGBE\n\n-Y 1 +X 3\n", f);
	fwrite((const unsigned char[]){10, 20, 30, 137, 1, 1, 1, 2}, 1, 8, f);
	fclose(f);
	CHECK(image_load(path("old.hdr"), IMAGE_RAW, &img, &d) && img.width == 3 && img.height == 1, "flat hdr");
	for (int x = 0; x < 3; x++)
		CHECK(img.rgba[4 * x] == 21.0f && img.rgba[4 * x + 1] == 41.0f && img.rgba[4 * x + 2] == 61.0f,
		      "flat hdr texel %d repeated: %g", x, img.rgba[4 * x]);
	image_free(&img);
	buf = NULL, len = 0;
	mem = open_memstream(&buf, &len);
	diag_init(&e, mem);
	const char *bad[][2] = {{"xyz.hdr", "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 1 +X 1\n\1\1\1\x80"},
				{"flip.hdr", "#?RADIANCE\n\n+Y 1 +X 1\n\1\1\1\x80"},
				{"cut.hdr", "#?RADIANCE\n\n-Y 2 +X 8\n\2\2\0\x08\x88"}};
	for (int i = 0; i < 3; i++) {
		f = fopen(path(bad[i][0]), "wb");
		fputs(bad[i][1], f);
		fclose(f);
		CHECK(!image_load(path(bad[i][0]), IMAGE_SRGB, &img, &e), "%s fails", bad[i][0]);
		unlink(path(bad[i][0]));
	}
	fclose(mem);
	CHECK(strstr(buf, "xyz.hdr: error: Radiance HDR file is not RGBE") && strstr(buf, "flip.hdr: error: Radiance HDR "
		      "resolution line is not '-Y height +X width'") && strstr(buf, "cut.hdr: error: Radiance HDR data is "
		      "corrupt or cut short at row 1 of 2"), "hdr messages:\n%s", buf);
	free(buf);
	diag_free(&e);
	const char *names[] = {"a.png", "b.png", "c.jpg", "d.exr", "bad.png", "bad.jpg", "x.txt", "p.png", "new.hdr", "old.hdr"};
	for (int i = 0; i < 10; i++)
		unlink(path(names[i]));
	CHECK(rmdir(dir) == 0, "no temporaries left in %s", dir);
	diag_free(&d);
	return check_done("test_image");
}
