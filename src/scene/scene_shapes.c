/* scene_shapes.c - the names and the dump of POV-Ray's shapes in the IR (cone to poly): kept out of
 * scene.c so that the shapes' records grow in one place. */
#include "scene/scene.h"

const char *scene_shape_name(const scene_geom *g)
{
	static const char *const kinds[] = {"sphere", "box", "plane", "mesh", "mesh_file", "subdivision_surface",
					    "pov_shape", "cone", "torus", "disc", "polygon", "superellipsoid", "height_field",
					    "quadric", "poly"};
	if (g->kind == SHAPE_CONE && g->u.cone.cylinder)
		return "cylinder";
	if (g->kind == SHAPE_POLY)
		return g->u.poly.keyword;
	return (size_t)g->kind < sizeof kinds / sizeof kinds[0] ? kinds[g->kind] : "?";
}

static void dump_v(FILE *o, const char *name, dvec3 v) { fprintf(o, " %s <%g, %g, %g>", name, v.x, v.y, v.z); }

void scene_dump_shape(FILE *o, const scene_geom *g)
{
	switch (g->kind) {
	case SHAPE_CONE: {
		const scene_cone *c = &g->u.cone;
		dump_v(o, "base", c->base);
		fprintf(o, " radius %g", c->base_radius);
		dump_v(o, "cap", c->cap);
		fprintf(o, " radius %g%s\n", c->cap_radius, c->open ? " open" : "");
		break;
	}
	case SHAPE_TORUS:
		fprintf(o, " major %g minor %g\n", g->u.torus.major, g->u.torus.minor);
		break;
	case SHAPE_DISC:
		dump_v(o, "center", g->u.disc.center);
		dump_v(o, "normal", g->u.disc.normal);
		fprintf(o, " radius %g hole %g\n", g->u.disc.radius, g->u.disc.hole);
		break;
	case SHAPE_POLYGON:
		fprintf(o, " points %u\n", g->u.polygon.n);
		for (uint32_t i = 0; i < g->u.polygon.n; i++)
			fprintf(o, "  p %g %g %g\n", g->u.polygon.points[i].x, g->u.polygon.points[i].y,
				g->u.polygon.points[i].z);
		break;
	case SHAPE_SUPERELLIPSOID:
		fprintf(o, " e %g n %g\n", g->u.superellipsoid.e, g->u.superellipsoid.n);
		break;
	case SHAPE_HEIGHT_FIELD:
		if (g->u.height_field.heights) /* a function's: its size and a checksum of its heights */
		{
			double sum = 0;
			for (size_t i = 0; i < (size_t)g->u.height_field.fn_w * g->u.height_field.fn_h; i++)
				sum += g->u.height_field.heights[i];
			fprintf(o, " function %u x %u sum %.6g", g->u.height_field.fn_w, g->u.height_field.fn_h, sum);
		} else {
			fprintf(o, " file \"%s\"", g->u.height_field.path);
		}
		fprintf(o, "%s water_level %g\n", g->u.height_field.smooth ? " smooth" : "", g->u.height_field.water_level);
		break;
	case SHAPE_QUADRIC:
		dump_v(o, "square", g->u.quadric.square);
		dump_v(o, "mixed", g->u.quadric.mixed);
		dump_v(o, "linear", g->u.quadric.linear);
		fprintf(o, " constant %g\n", g->u.quadric.constant);
		break;
	case SHAPE_POLY:
		fprintf(o, " order %d coefficients", g->u.poly.order);
		for (uint32_t i = 0; i < g->u.poly.n; i++)
			fprintf(o, " %g", g->u.poly.coeffs[i]);
		fputc('\n', o);
		break;
	default:
		fputc('\n', o);
		break;
	}
}
