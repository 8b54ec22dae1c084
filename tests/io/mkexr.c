/* mkexr: writes test EXRs for the shell tests — a deterministic RGBA pattern, optional AOV
 * channels and attributes, and single pixels overridden with --set X,Y,CHANNEL,VALUE (nan and
 * inf accepted). W x H is the frame; --window X0,Y0,X1,Y1 writes only those pixels (a tile: the
 * pattern depends on frame coordinates, so tiles assemble into the whole); --attr K=V and
 * --iattr K=N add string and integer attributes.
 * --studio writes a lat-long studio environment instead (the convention of render/light.h: row 0
 * is +y, column 0.5 is +z): sky gradient, dark ground, one bright soft box up front-left.
 * Usage: mkexr OUT.exr W H [--pattern K | --const V | --studio] [--aov] [--window R] [--attr K=V]...
 *        [--set X,Y,C,V]... */
#include "base/diag.h"
#include "io/exr.h"

#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The studio environment at lat-long (u, v): direction d, then sky, ground and the soft box. */
static void studio_texel(double u, double v, float *p)
{
	const double pi = 3.14159265358979323846;
	double theta = v * pi, phi = 2 * pi * (u - 0.5);
	double d[3] = {sin(theta) * sin(phi), cos(theta), sin(theta) * cos(phi)};
	double c[3];
	if (d[1] >= 0) {
		double t = pow(d[1], 0.5);
		static const double zenith[3] = {0.25, 0.36, 0.62}, horizon[3] = {0.85, 0.86, 0.88};
		for (int k = 0; k < 3; k++)
			c[k] = horizon[k] + (zenith[k] - horizon[k]) * t;
	} else {
		static const double ground[3] = {0.16, 0.14, 0.12};
		for (int k = 0; k < 3; k++)
			c[k] = ground[k];
	}
	/* The soft box: a disc of about 20 degrees around a direction up, at -x and towards +z (where a
	 * camera looking along -z at a subject facing +z has it at its side, above). */
	double box[3] = {-0.55, 0.6, 0.58}, len = sqrt(box[0] * box[0] + box[1] * box[1] + box[2] * box[2]);
	double cosang = (d[0] * box[0] + d[1] * box[1] + d[2] * box[2]) / len;
	if (cosang > cos(20 * pi / 180))
		c[0] = 14.0, c[1] = 13.5, c[2] = 12.5;
	p[0] = (float)c[0], p[1] = (float)c[1], p[2] = (float)c[2], p[3] = 1.0f;
}

int main(int argc, char **argv)
{
	if (argc < 4) {
		fprintf(stderr, "usage: mkexr OUT.exr W H [--pattern K] [--aov] [--set X,Y,C,V]...\n");
		return 2;
	}
	int w = atoi(argv[2]), h = atoi(argv[3]), pattern = 0;
	int aov = 0, constant = 0, studio = 0;
	float cval = 0.0f;
	if (w <= 0 || h <= 0)
		return 2;
	float *rgba = calloc((size_t)w * h * 4, sizeof(float));
	float *z = calloc((size_t)w * h, sizeof(float));
	for (int i = 4; i < argc; i++)
		if (!strcmp(argv[i], "--pattern") && i + 1 < argc)
			pattern = atoi(argv[++i]);
		else if (!strcmp(argv[i], "--aov"))
			aov = 1;
		else if (!strcmp(argv[i], "--studio"))
			studio = 1;
		else if (!strcmp(argv[i], "--const") && i + 1 < argc)
			constant = 1, cval = strtof(argv[++i], NULL);
	for (int y = 0; y < h; y++)
		for (int x = 0; x < w; x++) {
			float *p = rgba + ((size_t)y * w + x) * 4;
			p[0] = (float)(x + pattern) / (float)w;
			p[1] = (float)y / (float)h;
			p[2] = 0.25f + 0.001f * (float)((x * 7 + y * 13 + pattern) % 17);
			p[3] = 1.0f;
			z[(size_t)y * w + x] = 10.0f + (float)x;
			if (constant)
				p[0] = p[1] = p[2] = p[3] = cval;
			if (studio)
				studio_texel((x + 0.5) / w, (y + 0.5) / h, p);
		}
	for (int i = 4; i < argc; i++) {
		if (strcmp(argv[i], "--set") || i + 1 >= argc)
			continue;
		int x, y;
		char ch;
		char val[32];
		if (sscanf(argv[++i], "%d,%d,%c,%31s", &x, &y, &ch, val) != 4 || x < 0 || y < 0 || x >= w ||
		    y >= h || !strchr("RGBA", ch)) {
			fprintf(stderr, "mkexr: bad --set '%s'\n", argv[i]);
			return 2;
		}
		float v = !strcmp(val, "nan") ? NAN : !strcmp(val, "inf") ? INFINITY : strtof(val, NULL);
		rgba[((size_t)y * w + x) * 4 + (strchr("RGBA", ch) - "RGBA")] = v;
	}
	size_t row = (size_t)w * 4;
	exrfile_channel ch[6] = {
		{"R", rgba + 0, 4, row}, {"G", rgba + 1, 4, row}, {"B", rgba + 2, 4, row},
		{"A", rgba + 3, 4, row}, {"Z", z, 1, (size_t)w}, {"albedo.R", rgba + 0, 4, row},
	};
	exrfile_attr attrs[34] = {
		{.name = "software", .kind = EXRFILE_ATTR_STRING, .s = "circe mkexr"},
		{.name = "spp", .kind = EXRFILE_ATTR_INT, .i = 16},
	};
	int nattrs = 2;
	exrfile_rect win = {0, 0, w, h};
	for (int i = 4; i + 1 < argc; i++) {
		bool is_int = !strcmp(argv[i], "--iattr");
		if ((is_int || !strcmp(argv[i], "--attr")) && nattrs < 34) {
			char *eq = strchr(argv[++i], '=');
			if (!eq)
				return 2;
			*eq = '\0';
			attrs[nattrs++] = (exrfile_attr){.name = argv[i], .kind = is_int ? EXRFILE_ATTR_INT : EXRFILE_ATTR_STRING,
							 .s = eq + 1, .i = atoi(eq + 1)};
		} else if (!strcmp(argv[i], "--window")) {
			if (sscanf(argv[++i], "%d,%d,%d,%d", &win.x0, &win.y0, &win.x1, &win.y1) != 4 || win.x0 < 0 ||
			    win.y0 < 0 || win.x1 > w || win.y1 > h)
				return 2;
		}
	}
	/* Channel pointers start at the window's corner of the frame-sized arrays. */
	size_t off = (size_t)win.y0 * w + (size_t)win.x0;
	for (int c = 0; c < 6; c++)
		ch[c].data += off * (ch[c].pixel_stride == 4 ? 4 : 1);
	exrfile_write_desc desc = {{0, 0, w, h}, win, aov ? 6 : 4, ch, nattrs, attrs};
	diag d;
	diag_init(&d, stderr);
	int ok = exrfile_write(argv[1], &desc, &d);
	diag_free(&d);
	free(rgba);
	free(z);
	return ok ? 0 : 1;
}
