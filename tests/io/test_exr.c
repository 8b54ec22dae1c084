/* test_exr: EXRs written through the C API read back bit-exactly — RGBA, AOV channels, data and
 * display windows, attributes — and broken or missing files are clear errors. */
#include "base/diag.h"
#include "base/rng.h"
#include "check.h"
#include "io/exr.h"

#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static char dir[] = "/tmp/circe-test-exr-XXXXXX";

static const char *path(const char *name) { return check_path(dir, name); }

int main(void)
{
	if (!mkdtemp(dir))
		return 99;
	diag d;
	diag_init(&d, stderr);
	enum { W = 37, H = 23 };
	/* Values covering the float range: tiny, huge, negative, denormal, signed zero. */
	float *rgba = malloc(sizeof(float) * W * H * 4), *n = malloc(sizeof(float) * W * H * 3);
	float *zz = malloc(sizeof(float) * W * H);
	rng g;
	rng_seed(&g, 3, 4);
	for (int i = 0; i < W * H * 4; i++) {
		uint32_t bits = rng_u32(&g);
		float f;
		memcpy(&f, &bits, 4);
		rgba[i] = isfinite(f) ? f : 1.5f;
	}
	rgba[0] = 1e-45f, rgba[1] = -0.0f, rgba[2] = 3.4e38f;
	for (int i = 0; i < W * H * 3; i++)
		n[i] = rng_float(&g) * 2 - 1;
	for (int i = 0; i < W * H; i++)
		zz[i] = rng_float(&g) * 1e4f;
	size_t row = W * 4;
	exrfile_channel ch[] = {
		{"R", rgba, 4, row},           {"G", rgba + 1, 4, row},       {"B", rgba + 2, 4, row},
		{"A", rgba + 3, 4, row},       {"N.X", n, 3, W * 3},          {"N.Y", n + 1, 3, W * 3},
		{"N.Z", n + 2, 3, W * 3},      {"Z", zz, 1, W},               {"albedo.R", rgba + 2, 4, row},
	};
	exrfile_attr at[] = {
		{.name = "software", .kind = EXRFILE_ATTR_STRING, .s = "circe test"},
		{.name = "circe.spp", .kind = EXRFILE_ATTR_INT, .i = 64},
		{.name = "circe.seed", .kind = EXRFILE_ATTR_INT, .i = -7},
		{.name = "circe.render_time_s", .kind = EXRFILE_ATTR_DOUBLE, .d = 12.5},
		{.name = "circe.sss", .kind = EXRFILE_ATTR_STRING, .s = "circle"},
	};
	/* A tile: full frame 100x80, data window 10..47 x 30..53. */
	exrfile_write_desc desc = {{0, 0, 100, 80}, {10, 30, 10 + W, 30 + H}, 9, ch, 5, at};
	CHECK(exrfile_write(path("a.exr"), &desc, &d), "write a.exr");
	exrfile_image img;
	CHECK(exrfile_read(path("a.exr"), &img, &d), "read a.exr");
	CHECK(img.width == W && img.height == H, "size %dx%d", img.width, img.height);
	CHECK(img.data.x0 == 10 && img.data.y0 == 30 && img.data.x1 == 10 + W && img.data.y1 == 30 + H,
	      "data window %d,%d-%d,%d", img.data.x0, img.data.y0, img.data.x1, img.data.y1);
	CHECK(img.display.x0 == 0 && img.display.x1 == 100 && img.display.y1 == 80, "display window");
	CHECK(img.nchannels == 9, "%d channels", img.nchannels);
	for (int c = 0; c < 9; c++) {
		const float *p = exrfile_find_channel(&img, ch[c].name);
		CHECK(p != NULL, "channel %s present", ch[c].name);
		if (!p)
			continue;
		int mismatches = 0;
		for (int y = 0; y < H; y++)
			for (int x = 0; x < W; x++) {
				float want = ch[c].data[y * ch[c].row_stride + x * ch[c].pixel_stride];
				if (memcmp(&want, &p[y * W + x], 4))
					mismatches++;
			}
		CHECK(mismatches == 0, "channel %s: %d values differ bit-wise", ch[c].name, mismatches);
	}
	const exrfile_attr *a = exrfile_attr_find(&img, "circe.spp");
	CHECK(a && a->kind == EXRFILE_ATTR_INT && a->i == 64, "circe.spp attribute");
	a = exrfile_attr_find(&img, "circe.seed");
	CHECK(a && a->i == -7, "circe.seed attribute");
	a = exrfile_attr_find(&img, "circe.render_time_s");
	CHECK(a && a->kind == EXRFILE_ATTR_DOUBLE && a->d == 12.5, "render time attribute");
	a = exrfile_attr_find(&img, "circe.sss");
	CHECK(a && a->kind == EXRFILE_ATTR_STRING && !strcmp(a->s, "circle"), "sss attribute");
	a = exrfile_attr_find(&img, "compression");
	CHECK(a && a->kind == EXRFILE_ATTR_OTHER, "required attributes are listed too");
	exrfile_free(&img);

	/* Overwriting replaces the file whole. */
	desc.nchannels = 1;
	CHECK(exrfile_write(path("a.exr"), &desc, &d), "rewrite a.exr");
	CHECK(exrfile_read(path("a.exr"), &img, &d) && img.nchannels == 1, "rewritten file has 1 channel");
	exrfile_free(&img);

	/* Errors: a missing file, a file that is not EXR, a truncated EXR, a huge data window, an
	 * unwritable directory. */
	char *buf = NULL;
	size_t len = 0;
	FILE *mem = open_memstream(&buf, &len);
	diag e;
	diag_init(&e, mem);
	CHECK(!exrfile_read(path("missing.exr"), &img, &e), "missing file fails");
	FILE *f = fopen(path("text.exr"), "w");
	fputs("this is not an image\n", f);
	fclose(f);
	CHECK(!exrfile_read(path("text.exr"), &img, &e), "text file fails");
	FILE *src = fopen(path("a.exr"), "rb");
	char chunk[200];
	size_t got = fread(chunk, 1, sizeof chunk, src);
	fclose(src);
	f = fopen(path("trunc.exr"), "wb");
	fwrite(chunk, 1, got / 2, f);
	fclose(f);
	CHECK(!exrfile_read(path("trunc.exr"), &img, &e), "truncated file fails");
	/* A header whose data window asks for 10^10 pixels is refused before anything is allocated
	 * (the attribute is "dataWindow", "box2i", size 16, then xmin ymin xmax ymax; the test
	 * image's starts at 10, 30). */
	static const char dw_attr[] = "dataWindow\0box2i\0";
	char *dwin = memmem(chunk, got, dw_attr, sizeof dw_attr - 1);
	CHECK(dwin != NULL && dwin + sizeof dw_attr - 1 + 20 <= chunk + got, "a.exr's header holds its dataWindow");
	if (dwin) {
		int32_t huge = 99999;
		memcpy(dwin + sizeof dw_attr - 1 + 4 + 8, &huge, 4);
		memcpy(dwin + sizeof dw_attr - 1 + 4 + 12, &huge, 4);
	}
	src = fopen(path("a.exr"), "rb");
	FILE *big = fopen(path("huge.exr"), "wb");
	fwrite(chunk, 1, got, big);
	fseek(src, (long)got, SEEK_SET);
	for (int ch; (ch = fgetc(src)) != EOF;)
		fputc(ch, big);
	fclose(src), fclose(big);
	CHECK(!exrfile_read(path("huge.exr"), &img, &e), "a data window of 10^10 pixels fails");
	CHECK(!exrfile_write("/nonexistent-dir/x.exr", &desc, &e), "unwritable directory fails");
	fclose(mem);
	CHECK(strstr(buf, "missing.exr: error: cannot read EXR") != NULL, "missing file message:\n%s", buf);
	CHECK(strstr(buf, "/nonexistent-dir/x.exr: error: cannot create the output") != NULL,
	      "unwritable message:\n%s", buf);
	CHECK(strstr(buf, "huge.exr: error: cannot read EXR: its data window (99990 x 99970 pixels, 1 "
			  "channel) holds more samples than circe reads (limit 1073741824)") != NULL,
	      "huge data window message:\n%s", buf);
	CHECK(e.errors == 5, "5 errors reported (%d)", e.errors);
	free(buf);
	diag_free(&e);

	/* Nothing but our files is left in the directory: no temporaries. */
	unlink(path("a.exr")), unlink(path("text.exr")), unlink(path("trunc.exr")), unlink(path("huge.exr"));
	CHECK(rmdir(dir) == 0, "directory %s empty at the end", dir);
	diag_free(&d);
	free(rgba), free(n), free(zz);
	return check_done("test_exr");
}
