/* build_shape.c - POV-Ray's lathe, sor, prism, sphere_sweep, blob and text (geom/shape.h)
 * tessellated at the accuracy their size on screen asks for: the sphere's rule (build_inst.c's
 * sphere_level) applied to the shape's bounding sphere, for every object that places it, the
 * finest level winning: prim_sphere_level_segments(level) segments around a surface of revolution
 * or a sweep, as around that sphere; and its error bound, WORLD_SPHERE_MAX_ERROR_PX on screen, as
 * the tolerance of every curve (profiles, outlines, glyphs, the blob's grid). */
#include "build/build_impl.h"

#include "base/mem.h"
#include "base/par.h"
#include "geom/shape.h"

#include <math.h>

/* The level of g over the objects that place it (level 0 when none does: a declared shape), and
 * the tolerance: WORLD_SPHERE_MAX_ERROR_PX on screen where the object is nearest, kept between
 * the finest and the coarsest sphere level's relative errors of the bounding radius. */
static uint32_t shape_level(const scene *sc, const scene_geom *g, const subd_camera *view, dvec3 centre, double radius,
			    double *tol)
{
	double rel_err[PRIM_SPHERE_LEVELS];
	for (uint32_t k = 0; k < PRIM_SPHERE_LEVELS; k++)
		rel_err[k] = prim_sphere_rel_error(prim_sphere_level_segments(k));
	uint32_t level = 0;
	*tol = rel_err[0] * radius;
	for (size_t i = 0; i < scene_n_objects(sc); i++) {
		const scene_object *o = scene_object_at(sc, i);
		if (o->geom != g)
			continue;
		double scale = axis_scale(&o->transform), r = radius * scale;
		/* pixels per unit of the shape's own space at its nearest (build_inst.c's rule) */
		double ppu = view_px_per_unit(view, xform_point(&o->transform, centre), r) * scale;
		uint32_t k = sphere_level(rel_err, radius * ppu);
		level = k > level ? k : level;
		double t = fmax(WORLD_SPHERE_MAX_ERROR_PX / ppu, rel_err[PRIM_SPHERE_LEVELS - 1] * radius);
		*tol = fmin(*tol, t);
	}
	return level;
}

/* Appends the record of one tessellated shape to the world's statistics. */
bool note_shape(world *w, const world_shape_stat *st, diag *d)
{
	world_shape_stat *a = mem_realloc((void *)w->stats.shapes, w->stats.n_shapes + 1, sizeof *a);
	if (!a) {
		diag_error(d, st->loc, "out of memory");
		return false;
	}
	a[w->stats.n_shapes++] = *st;
	w->stats.shapes = a;
	return true;
}

/* A blob with component textures: each triangle's part, the strongest component's at its centre
 * (geom/shape.h's shape_blob_part_at), for world.c's fill_hit. */
static bool blob_tri_parts(world_geom *wg, const shape_desc *s, diag *d, diag_loc loc)
{
	bool parted = false;
	for (uint32_t i = 0; s->kind == SHAPE2_BLOB && i < s->n_comps && !parted; i++)
		parted = s->comps[i].part > 0;
	const mesh *m = &wg->m;
	if (!parted || !m->num_triangles)
		return true;
	if (!(wg->tri_part = mem_alloc(m->num_triangles, sizeof *wg->tri_part))) {
		diag_error(d, loc, "out of memory");
		return false;
	}
	for (size_t t = 0; t < m->num_triangles; t++) {
		const uint32_t *ix = m->indices + 3 * t;
		dvec3 c = d3_scale(d3_add(d3_add(v3_to_d3(m->positions[ix[0]]), v3_to_d3(m->positions[ix[1]])),
					  v3_to_d3(m->positions[ix[2]])), 1.0 / 3.0);
		wg->tri_part[t] = (uint8_t)shape_blob_part_at(s, c);
	}
	return true;
}

bool build_pov_shape(world *w, const scene *sc, const scene_geom *g, const world_options *opt, diag *d)
{
	const shape_desc *s = g->u.pov;
	dvec3 lo, hi;
	shape_bounds(s, &lo, &hi);
	dvec3 centre = d3_scale(d3_add(lo, hi), 0.5);
	double radius = fmax(0.5 * d3_length(d3_sub(hi, lo)), 1e-9);
	subd_camera view = scene_view(sc, opt);
	double tol;
	uint32_t level = shape_level(sc, g, &view, centre, radius, &tol);
	shape_accuracy acc = {.tol = tol, .segments = prim_sphere_level_segments(level), .cache = opt->shape_cache,
			      .threads = opt->threads > 0 ? opt->threads : par_default_workers()};
	size_t hits = shape_cache_hits(opt->shape_cache);
	world_geom *wg = &w->geoms[g->id];
	mesh *m = &wg->m;
	/* The same shape at the same accuracy in a trace()'s world: the same mesh, copied. */
	if (opt->reuse && world_tracer_mesh(opt->reuse, s, acc.tol, acc.segments, m, &tol))
		w->stats.reused_shapes++;
	else if (!shape_tessellate(s, &acc, m, &tol, d, g->loc))
		return false;
	else if (shape_cache_hits(opt->shape_cache) > hits)
		w->stats.cached_shapes++;
	wg->shape = s, wg->shape_tol = acc.tol, wg->shape_segments = acc.segments, wg->shape_err = tol;
	if (!blob_tri_parts(wg, s, d, g->loc))
		return false;
	world_shape_stat st = {shape_kind_name(s->kind), g->loc, m->num_triangles, tol, (int)level};
	return note_shape(w, &st, d);
}
