/* shapebench: tessellation time and triangle count of each of POV-Ray's shapes (src/geom/povshape.h)
 * at the accuracy the build asks of it (the sphere's rule: 0.1 px of surface error, 1 px edges
 * along curves) for a 640 x 480 view 60 degrees high, the shapes of about 1 unit (the
 * superellipsoid is POV-Ray's, 2 across) at two distances from the eye: 10 units (an object among
 * others) and 2.5 (one filling the view). Each row is
 * the best of ROUNDS (default 20) tessellations. `make bench-shapes` builds and runs it. */
#include "geom/povshape.h"

#include "base/mem.h"

#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void)
{
	struct timespec t;
	clock_gettime(CLOCK_MONOTONIC, &t);
	return t.tv_sec + 1e-9 * t.tv_nsec;
}

/* The accuracy of build_shapes.c for a bounding sphere of radius r at distance dist on the axis. */
static shape_accuracy accuracy(double r, double dist)
{
	double focal_px = 240.0 / tan(30.0 * M_PI / 180.0), ppu = focal_px / sqrt(dist * dist - r * r);
	return (shape_accuracy){.max_error = 0.1 / ppu, .max_edge = 1.0 / ppu, .max_triangles = SHAPE_MAX_TRIANGLES};
}

typedef enum { CYLINDER, CONE, TORUS, DISC, POLYGON, SUPER_ROUND, SUPER_BOXY, HEIGHT_FIELD, ELLIPSOID, N_SHAPES } which;
static const char *const names[N_SHAPES] = {"cylinder r 0.5 h 1", "cone 0.5 to apex", "torus 0.4, 0.1",
					    "disc r 0.5 hole 0.2", "polygon 10 points, a hole", "superellipsoid <1, 1>",
					    "superellipsoid <0.2, 0.2>", "height_field 256 x 256", "quadric ellipsoid"};

static float *field;

static bool make(which k, const shape_accuracy *a, mesh *m, double *err, diag *d)
{
	static const dvec3 holed[10] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0},
					{0.25, 0.25, 0}, {0.75, 0.25, 0}, {0.75, 0.75, 0}, {0.25, 0.75, 0}, {0.25, 0.25, 0}};
	static const double ell[10] = {4, 1, 2, 0.5, 0, 0, 0, 0, 0, -1};
	shape_quadric_kind kind;
	*err = 0.0;
	switch (k) {
	case CYLINDER: return shape_cone(d3(0, 0, 0), 0.5, d3(0, 1, 0), 0.5, false, a, m, err, d, diag_noloc());
	case CONE: return shape_cone(d3(0, 0, 0), 0.5, d3(0, 1, 0), 0.0, false, a, m, err, d, diag_noloc());
	case TORUS: return shape_torus(0.4, 0.1, a, m, err, d, diag_noloc());
	case DISC: return shape_disc(d3(0, 0, 0), d3(0, 1, 0), 0.5, 0.2, a, m, err, d, diag_noloc());
	case POLYGON: return shape_polygon(holed, 10, a, m, d, diag_noloc());
	case SUPER_ROUND: return shape_superellipsoid(1, 1, a, m, err, d, diag_noloc());
	case SUPER_BOXY: return shape_superellipsoid(0.2, 0.2, a, m, err, d, diag_noloc());
	case HEIGHT_FIELD: return shape_height_field(field, 256, 256, true, 0.0, a, m, d, diag_noloc());
	case ELLIPSOID: return shape_quadric(ell, a, m, err, &kind, d, diag_noloc());
	default: return false;
	}
}

int main(int argc, char **argv)
{
	int rounds = argc > 1 ? atoi(argv[1]) : 20;
	diag d;
	diag_init(&d, stderr);
	field = malloc(256 * 256 * sizeof *field);
	for (int z = 0; z < 256; z++)
		for (int x = 0; x < 256; x++)
			field[z * 256 + x] = (float)(0.25 + 0.2 * sin(x * 0.1) * cos(z * 0.07));
	static const double dists[2] = {10.0, 2.5};
	/* The bounding radius build_shapes.c computes for each (the polygon and field are exact). */
	static const double bound[N_SHAPES] = {1.0, 1.0, 0.5, 0.5, 1.0, 1.7320508, 1.7320508, 1.0, 1.0};
	printf("| shape | distance | triangles | error bound (units) | tessellation (ms) |\n|---|---|---|---|---|\n");
	for (int k = 0; k < N_SHAPES; k++)
		for (int di = 0; di < 2; di++) {
			shape_accuracy a = accuracy(bound[k], dists[di]);
			double best = INFINITY, err = 0;
			uint32_t tris = 0;
			for (int r = 0; r < rounds; r++) {
				mesh m;
				double t0 = now();
				if (!make((which)k, &a, &m, &err, &d))
					return 1;
				best = fmin(best, now() - t0);
				tris = m.num_triangles;
				mesh_free(&m);
			}
			printf("| %s | %g | %u | %.2g | %.3f |\n", names[k], dists[di], tris, err, 1e3 * best);
		}
	free(field);
	return 0;
}
