/* shape_desc.c - the names and the IR dump of POV-Ray's shapes (shape.h), apart from their
 * tessellation so the scene IR can print them without linking it. */
#include "geom/shape.h"

const char *shape_kind_name(shape_kind k)
{
	static const char *const names[] = {"lathe", "sor", "prism", "sphere_sweep", "blob", "text", "bicubic_patch",
					      "isosurface", "parametric", "julia_fractal"};
	return names[k];
}

void shape_dump(FILE *o, const shape_desc *s)
{
	static const char *const splines[] = {"linear_spline", "quadratic_spline", "cubic_spline", "bezier_spline",
					      "b_spline"};
	fprintf(o, " %s", shape_kind_name(s->kind));
	switch (s->kind) {
	case SHAPE2_LATHE:
	case SHAPE2_SOR:
	case SHAPE2_PRISM:
		if (s->kind != SHAPE2_SOR)
			fprintf(o, " %s", splines[s->spline]);
		if (s->kind == SHAPE2_PRISM)
			fprintf(o, " %s %g %g", s->conic ? "conic_sweep" : "linear_sweep", s->h1, s->h2);
		fprintf(o, " points %u%s\n", s->n_pts, s->open ? " open" : "");
		for (uint32_t i = 0; i < s->n_pts; i++)
			fprintf(o, "  p %g %g\n", s->pts[2 * i], s->pts[2 * i + 1]);
		break;
	case SHAPE2_SPHERE_SWEEP:
		fprintf(o, " %s spheres %u tolerance %g\n", splines[s->spline], s->n_pts, s->tolerance);
		for (uint32_t i = 0; i < s->n_pts; i++)
			fprintf(o, "  s %g %g %g %g\n", s->pts[4 * i], s->pts[4 * i + 1], s->pts[4 * i + 2], s->pts[4 * i + 3]);
		break;
	case SHAPE2_BLOB:
		fprintf(o, " threshold %g components %u\n", s->threshold, s->n_comps);
		for (uint32_t i = 0; i < s->n_comps; i++) {
			const shape_blob_comp *c = &s->comps[i];
			if (c->cylinder)
				fprintf(o, "  cylinder %g %g %g %g %g %g", c->a.x, c->a.y, c->a.z, c->b.x, c->b.y, c->b.z);
			else
				fprintf(o, "  sphere %g %g %g", c->a.x, c->a.y, c->a.z);
			fprintf(o, " radius %g strength %g%s", c->radius, c->strength, c->has_xf ? " transformed" : "");
			if (c->part) /* only then: older dumps stay as they were */
				fprintf(o, " part %u", c->part);
			fputc('\n', o);
		}
		break;
	case SHAPE2_BICUBIC:
		fprintf(o, " type %d flatness %g u_steps %d v_steps %d uv_vectors %g %g %g %g %g %g %g %g\n", s->patch_type,
			s->flatness, s->u_steps, s->v_steps, s->st[0], s->st[1], s->st[2], s->st[3], s->st[4], s->st[5],
			s->st[6], s->st[7]);
		for (uint32_t i = 0; i < 16; i++)
			fprintf(o, "  p %g %g %g\n", s->pts[3 * i], s->pts[3 * i + 1], s->pts[3 * i + 2]);
		break;
	case SHAPE2_ISOSURFACE:
		fprintf(o, " function %s threshold %g", s->fn_name ? s->fn_name : "function", s->threshold);
		if (s->contained_sphere)
			fprintf(o, " contained_by sphere %g %g %g %g", s->box_lo.x, s->box_lo.y, s->box_lo.z, s->sphere_r);
		else
			fprintf(o, " contained_by box %g %g %g %g %g %g", s->box_lo.x, s->box_lo.y, s->box_lo.z, s->box_hi.x,
				s->box_hi.y, s->box_hi.z);
		fprintf(o, " max_gradient %g accuracy %g max_trace %d%s%s", s->max_gradient, s->iso_accuracy, s->max_trace,
			s->all_intersections ? " all_intersections" : "", s->open ? " open" : "");
		if (s->has_evaluate)
			fprintf(o, " evaluate %g %g %g", s->evaluate[0], s->evaluate[1], s->evaluate[2]);
		fprintf(o, "\n");
		break;
	case SHAPE2_PARAMETRIC:
		fprintf(o, " u %g %g v %g %g", s->uv_lo[0], s->uv_hi[0], s->uv_lo[1], s->uv_hi[1]);
		if (s->contained_sphere)
			fprintf(o, " contained_by sphere %g %g %g %g", s->box_lo.x, s->box_lo.y, s->box_lo.z, s->sphere_r);
		else
			fprintf(o, " contained_by box %g %g %g %g %g %g", s->box_lo.x, s->box_lo.y, s->box_lo.z, s->box_hi.x,
				s->box_hi.y, s->box_hi.z);
		fprintf(o, " max_gradient %g accuracy %g", s->max_gradient, s->iso_accuracy);
		if (s->precompute_depth)
			fprintf(o, " precompute %d%s%s%s", s->precompute_depth, s->precompute_xyz[0] ? " x" : "",
				s->precompute_xyz[1] ? " y" : "", s->precompute_xyz[2] ? " z" : "");
		fprintf(o, "\n");
		break;
	case SHAPE2_JULIA:
		fprintf(o, " <%g, %g, %g, %g> %s %s max_iteration %d precision %g slice <%g, %g, %g, %g> %g\n", s->julia[0],
			s->julia[1], s->julia[2], s->julia[3], s->algebra ? "hypercomplex" : "quaternion", s->jfunc ? "cube" : "sqr",
			s->max_iteration, s->precision, s->slice[0], s->slice[1], s->slice[2], s->slice[3], s->slice_dist);
		break;
	case SHAPE2_TEXT:
		fprintf(o, " ttf \"%s\" \"%s\" depth %g offset %g %g %g\n", s->font, s->text, s->depth, s->offset.x,
			s->offset.y, s->offset.z);
		break;
	}
}
