/* mkbigimage: writes DIR/big.png, DIR/big.jpg and DIR/big.exr, whose headers claim W x H pixels
 * (default 30000 x 30000) but whose data stops after a few bytes: a texture too large to load, in
 * a few hundred bytes. The PNG is a valid signature and IHDR chunk (CRC included) and the start of
 * an IDAT; the JPEG is a real 16 x 16 one (progressive with "progressive") with its frame header's
 * size changed, cut 2 bytes into the scan data; the EXR a real 16 x 16 one with its data and
 * display windows changed. Used by tests/io/texture_limit.sh. */
#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <jpeglib.h>

#include "io/exr.h"

/* CRC-32 of PNG chunks (ISO 3309, PNG specification annex D), bit by bit. */
static uint32_t crc32_png(const unsigned char *b, size_t n)
{
	uint32_t c = 0xffffffffu;
	for (size_t i = 0; i < n; i++) {
		c ^= b[i];
		for (int k = 0; k < 8; k++)
			c = c & 1 ? 0xedb88320u ^ (c >> 1) : c >> 1;
	}
	return c ^ 0xffffffffu;
}

static void be32(unsigned char *b, uint32_t v)
{
	b[0] = (unsigned char)(v >> 24), b[1] = (unsigned char)(v >> 16), b[2] = (unsigned char)(v >> 8);
	b[3] = (unsigned char)v;
}

static int write_png(const char *path, uint32_t w, uint32_t h)
{
	unsigned char f[8 + 25 + 12] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
	unsigned char *ihdr = f + 8;
	be32(ihdr, 13);
	memcpy(ihdr + 4, "IHDR", 4);
	be32(ihdr + 8, w), be32(ihdr + 12, h);
	ihdr[16] = 8, ihdr[17] = 6; /* 8-bit RGBA */
	be32(ihdr + 21, crc32_png(ihdr + 4, 17));
	unsigned char *idat = ihdr + 25; /* an IDAT chunk announcing 1000 bytes, then nothing */
	be32(idat, 1000);
	memcpy(idat + 4, "IDAT\x78\x9c\x00\x00", 8);
	FILE *fp = fopen(path, "wb");
	return fp && fwrite(f, 1, sizeof f, fp) == sizeof f && fclose(fp) == 0 ? 0 : 1;
}

static int write_jpeg(const char *path, unsigned w, unsigned h, bool progressive)
{
	struct jpeg_compress_struct c;
	struct jpeg_error_mgr err;
	c.err = jpeg_std_error(&err);
	jpeg_create_compress(&c);
	unsigned char *mem = NULL;
	unsigned long len = 0;
	jpeg_mem_dest(&c, &mem, &len);
	c.image_width = c.image_height = 16;
	c.input_components = 3, c.in_color_space = JCS_RGB;
	jpeg_set_defaults(&c);
	if (progressive)
		jpeg_simple_progression(&c);
	jpeg_start_compress(&c, TRUE);
	unsigned char row[16 * 3];
	memset(row, 100, sizeof row);
	for (int y = 0; y < 16; y++) {
		JSAMPROW r = row;
		jpeg_write_scanlines(&c, &r, 1);
	}
	jpeg_finish_compress(&c);
	jpeg_destroy_compress(&c);
	size_t cut = 0;
	for (size_t i = 0; i + 9 < len; i++) {
		if (mem[i] == 0xff && (mem[i + 1] == 0xc0 || mem[i + 1] == 0xc2)) {
			/* SOF0 or SOF2: length, precision, height, width */
			mem[i + 5] = (unsigned char)(h >> 8), mem[i + 6] = (unsigned char)h;
			mem[i + 7] = (unsigned char)(w >> 8), mem[i + 8] = (unsigned char)w;
		}
		if (mem[i] == 0xff && mem[i + 1] == 0xda) { /* SOS: keep its header and 2 bytes of data */
			cut = i + 2 + ((size_t)mem[i + 2] << 8 | mem[i + 3]) + 2;
			break;
		}
	}
	FILE *fp = fopen(path, "wb");
	int bad = !cut || cut > len || !fp || fwrite(mem, 1, cut, fp) != cut || fclose(fp) != 0;
	free(mem);
	return bad;
}

/* Sets the box2i attribute `name` (both windows) to (0, 0)-(w - 1, h - 1) in the file's bytes. */
static void patch_box(unsigned char *b, size_t len, const char *name, unsigned w, unsigned h)
{
	size_t n = strlen(name) + 1;
	for (size_t i = 0; i + n + 6 + 4 + 16 <= len; i++)
		if (!memcmp(b + i, name, n) && !memcmp(b + i + n, "box2i", 6)) {
			unsigned char *v = b + i + n + 6 + 4;
			int32_t box[4] = {0, 0, (int32_t)w - 1, (int32_t)h - 1};
			for (int k = 0; k < 4; k++)
				for (int j = 0; j < 4; j++)
					v[4 * k + j] =
					    (unsigned char)((uint32_t)box[k] >> (8 * j)); /* little-endian */
			return;
		}
}

static int write_exr(const char *path, unsigned w, unsigned h)
{
	float px[16 * 16] = {0};
	exrfile_channel ch[3] = {{"B", px, 1, 16}, {"G", px, 1, 16}, {"R", px, 1, 16}};
	exrfile_write_desc desc = {{0, 0, 16, 16}, {0, 0, 16, 16}, 3, ch, 0, NULL};
	diag d;
	diag_init(&d, stderr);
	bool ok = exrfile_write(path, &desc, &d);
	diag_free(&d);
	FILE *fp = ok ? fopen(path, "r+b") : NULL;
	unsigned char b[4096];
	size_t len = fp ? fread(b, 1, sizeof b, fp) : 0;
	patch_box(b, len, "dataWindow", w, h);
	patch_box(b, len, "displayWindow", w, h);
	return !fp || fseek(fp, 0, SEEK_SET) != 0 || fwrite(b, 1, len, fp) != len || fclose(fp) != 0;
}

int main(int argc, char **argv)
{
	if (argc < 2 || argc == 3 || argc > 5) {
		fprintf(stderr, "usage: mkbigimage DIR [W H [progressive]]\n");
		return 2;
	}
	unsigned w = argc >= 4 ? (unsigned)atoi(argv[2]) : 30000,
		 h = argc >= 4 ? (unsigned)atoi(argv[3]) : 30000;
	bool progressive = argc == 5 && !strcmp(argv[4], "progressive");
	char png[4096], jpg[4096], exr[4096];
	snprintf(png, sizeof png, "%s/big.png", argv[1]);
	snprintf(jpg, sizeof jpg, "%s/big.jpg", argv[1]);
	snprintf(exr, sizeof exr, "%s/big.exr", argv[1]);
	return write_png(png, w, h) | write_jpeg(jpg, w, h, progressive) | write_exr(exr, w, h);
}
