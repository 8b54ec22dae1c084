/* build.c - world_build: the stages of build_*.c in order, then the per-mesh BVHs; world_free and
 * what main.c may ask of a world. */
#include "build/build_impl.h"

#include "build/assets.h"
#include "base/mem.h"
#include "base/par.h"
#include "geom/prim.h"
#include "geom/shape.h"
#include "geom/subdiv.h"

#include <string.h>

static void world_release(world *w);

/* The BVHs of geoms [begin, end) of w with triangles (each its own: any worker may build any). */
static void build_bvhs(void *ctx, size_t begin, size_t end, int worker)
{
	(void)worker;
	world *w = ctx;
	for (size_t i = begin; i < end; i++) {
		world_geom *g = &w->geoms[i];
		if (g->m.num_triangles)
			g->b = bvh_build(g->m.positions, g->m.num_vertices, g->m.indices, g->m.num_triangles);
	}
}

/* Fills the zeroed w; on failure (reported to d) releases what it made. */
static bool build_world(world *w, const scene *sc, const world_options *opt, diag *d)
{
	if (!assets_open(sc, d)) /* every named file, at its string, before any work */
		return false;
	light_set_init(&w->lights);
	w->working_gamma = sc->global.working_gamma;
	world_options o = *opt;
	if (!o.max_memory)
		o.max_memory = SUBD_DEFAULT_MAX_BYTES;
	/* Room for the scene's geometry, a private mesh per object (used only when flattened, or for a
	 * plane), and the unit spheres. */
	w->unit_spheres = sc->n_geoms + scene_n_objects(sc);
	w->n_geoms = w->unit_spheres + PRIM_SPHERE_LEVELS;
	w->geoms = mem_calloc(w->n_geoms ? w->n_geoms : 1, sizeof *w->geoms);
	w->n_materials = sc->n_materials + 1;
	w->bsdfs = mem_calloc(w->n_materials, sizeof *w->bsdfs);
	w->materials = mem_calloc(w->n_materials, sizeof *w->materials);
	w->sss = mem_calloc(w->n_materials, sizeof *w->sss);
	w->sss_of = mem_calloc(w->n_materials, sizeof *w->sss_of);
	w->media = mem_calloc(w->n_materials, sizeof *w->media);
	w->media_of = mem_calloc(w->n_materials, sizeof *w->media_of);
	if (!w->geoms || !w->bsdfs || !w->materials || !w->sss || !w->sss_of || !w->media || !w->media_of) {
		diag_error(d, diag_noloc(), "out of memory");
		world_release(w);
		return false;
	}
	bool ok = true;
	for (const scene_geom *g = sc->geoms; g && ok; g = g->next)
		ok = build_geom(w, sc, g, &o, d);
	ok = ok && build_instances(w, sc, &o, d) && build_planes(w, sc, &o, d) && check_volumes(w, sc, &o, d);
	for (const scene_material *m = sc->materials; ok && m; m = m->next)
		ok = o.geometry_only || build_material(w, m->id, sc, &o, m, d);
	if (ok)
		w->bsdfs[w->n_materials - 1] = bsdf_diffuse(v3s(WORLD_DEFAULT_GREY));
	ok = ok && (o.geometry_only || build_atmosphere(w, sc, d));
	/* the meshes' BVHs on the threads (world_options.threads), then looked at in order */
	if (ok && !o.geometry_only)
		par_for(o.threads > 0 ? o.threads : par_default_workers(), w->n_geoms, 1, build_bvhs, w);
	for (size_t i = 0; i < w->n_geoms; i++) {
		world_geom *g = &w->geoms[i];
		w->stats.triangles += g->m.num_triangles;
		w->stats.geometry_bytes += mesh_bytes(&g->m);
		if (!ok || o.geometry_only || !g->m.num_triangles)
			continue;
		if (!g->b) {
			diag_error(d, diag_noloc(), "out of memory while building the BVH");
			ok = false;
		} else {
			w->stats.geometry_bytes += bvh_bytes(g->b);
		}
	}
	for (size_t i = 0; i < w->n_insts; i++)
		w->stats.instanced_triangles += w->insts[i].g->m.num_triangles;
	ok = ok && (o.geometry_only || build_top(w, d));
	ok = ok && (o.geometry_only || (build_lights(w, sc, d) && build_reach(w, sc, &o, d) && build_camera(w, sc, &o, d)));
	if (!ok) {
		world_release(w);
		return false;
	}
	world_bind(w);
	if (!o.geometry_only && w->has_sss && !build_pov_probe(w, sc, d)) {
		world_release(w);
		return false;
	}
	return true;
}

/* Frees what w holds and zeroes it. */
static void world_release(world *w)
{
	mem_free((void *)w->stats.shapes);
	w->stats.shapes = NULL;
	for (size_t i = 0; w->insts && i < w->n_insts; i++)
		mem_free(w->insts[i].part_material);
	for (size_t i = 0; w->geoms && i < w->n_geoms; i++) {
		mem_free(w->geoms[i].tri_part);
		mesh_free(&w->geoms[i].m);
		bvh_free(w->geoms[i].b);
	}
	for (size_t i = 0; i < w->n_images; i++) {
		image_free(w->images[i]);
		mem_free(w->images[i]);
		mem_free(w->image_paths[i]);
	}
	for (size_t i = 0; w->materials && i < w->n_materials; i++) {
		mem_free(w->materials[i].layers);
		for (uint32_t j = 0; j < w->materials[i].n_map; j++)
			mem_free(w->materials[i].map[j].layers);
		mem_free(w->materials[i].map);
	}
	light_set_free(&w->lights);
	for (size_t i = 0; i < w->n_reach; i++) {
		world_free(w->reach[i].through);
		if (w->reach[i].through_sc)
			w->reach[i].through_sc->geoms = NULL; /* shallow copies (build_light.c) */
		scene_free(w->reach[i].through_sc);
	}
	mem_free(w->reach), mem_free(w->group_parent), mem_free(w->group_global), mem_free(w->light_sign);
	tlas_free(w->top), tlas_free(w->shadow);
	mem_free(w->top_inst), mem_free(w->inst_top), mem_free(w->sss_group);
	mem_free(w->csg_nodes), mem_free(w->csg_kids);
	mem_free(w->sss), mem_free(w->sss_of);
	mem_free(w->media), mem_free(w->media_of);
	mem_free(w->geoms), mem_free(w->insts), mem_free(w->bsdfs), mem_free(w->materials);
	mem_free(w->images), mem_free(w->image_paths), mem_free(w->env_rgb);
	mem_free((void *)w->stats.shapes);
	pattern_prog_free(&w->patterns);
	memset(w, 0, sizeof *w);
}

world *world_build(const scene *sc, const world_options *opt, diag *d)
{
	world *w = mem_calloc(1, sizeof *w);
	if (!w) {
		diag_error(d, diag_noloc(), "out of memory");
		return NULL;
	}
	world_options o = *opt;
	shape_cache *own = NULL;
	if (!o.shape_cache)
		o.shape_cache = own = shape_cache_new(WORLD_SHAPE_CACHE_BYTES); /* NULL: none, made anew */
	bool ok = build_world(w, sc, &o, d);
	shape_cache_free(own);
	if (!ok) {
		mem_free(w);
		return NULL;
	}
	return w;
}

void world_free(world *w)
{
	if (!w)
		return;
	world_release(w);
	mem_free(w);
}

const render_scene *world_scene(const world *w) { return &w->rs; }

const cam *world_camera(const world *w) { return &w->camera; }

void world_stats_get(const world *w, world_stats *out)
{
	*out = w->stats;
	out->instances = w->n_insts;
	out->instance_bytes = w->n_insts * sizeof *w->insts;
}
