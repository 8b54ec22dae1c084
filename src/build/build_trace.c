/* build_trace.c - POV-Ray's SDL trace(object, start, direction [, normal]) for the language: the
 * object's records alone made a world (copied into a scene of their own, without materials or
 * lights, under the scene's camera as parsed so far, so tessellated by the render's rules), kept
 * for the next trace of the same object, and the ray's nearest hit found by the world's intersect
 * (CSG classified as the render classifies it). The hit lies on the tessellated surface the render
 * draws, its normal the interpolated one (outward, turned on the removed side of a difference). */
#include "build/build_impl.h"

#include "base/mem.h"
#include "geom/shape.h"

#include <math.h>
#include <string.h>

typedef struct tracer_slot {
	const void *key; /* the caller's name for the object (NULL: free) */
	scene *sc;       /* the object's own scene: its geoms are copies of the parent's records */
	world *w;
	size_t triangles;
} tracer_slot;

struct world_tracer {
	world_options opt;
	tracer_slot slot[WORLD_TRACER_SLOTS];
	unsigned next; /* the slot the next new object takes (round robin) */
	size_t builds; /* worlds built, for tests */
	shape_cache *shapes; /* the isosurface grids of its worlds (opt.shape_cache) */
	/* The worlds of object patterns and inside(): kept while the tracer lives (the scene's
	 * patterns call them during the render), one per key. */
	tracer_slot *pinned;
	size_t n_pinned, cap_pinned;
};

world_tracer *world_tracer_new(size_t max_memory)
{
	world_tracer *t = mem_calloc(1, sizeof *t);
	if (!t)
		return NULL;
	t->shapes = shape_cache_new(WORLD_SHAPE_CACHE_BYTES);
	if (!t->shapes) {
		mem_free(t);
		return NULL;
	}
	t->opt = (world_options){.width = WORLD_TRACE_WIDTH, .height = WORLD_TRACE_HEIGHT, .max_memory = max_memory,
				 .shape_cache = t->shapes};
	return t;
}

static void slot_free(tracer_slot *s)
{
	world_free(s->w);
	if (s->sc)
		s->sc->geoms = NULL; /* shallow copies: their arrays are the parent scene's */
	scene_free(s->sc);
	memset(s, 0, sizeof *s);
}

void world_tracer_free(world_tracer *t)
{
	if (!t)
		return;
	for (int i = 0; i < WORLD_TRACER_SLOTS; i++)
		slot_free(&t->slot[i]);
	for (size_t i = 0; i < t->n_pinned; i++)
		slot_free(&t->pinned[i]);
	mem_free(t->pinned);
	shape_cache_free(t->shapes);
	mem_free(t);
}

size_t world_tracer_builds(const world_tracer *t) { return t ? t->builds : 0; }

void world_tracer_set_threads(world_tracer *t, int threads)
{
	if (t)
		t->opt.threads = threads;
}

shape_cache *world_tracer_shapes(const world_tracer *t) { return t ? t->shapes : NULL; }

/* The geom of w that tessellated shape at (tol, segments), or NULL. */
static const world_geom *made_in(const world *w, const void *shape, double tol, uint32_t segments)
{
	for (size_t i = 0; w && i < w->n_geoms; i++) {
		const world_geom *g = &w->geoms[i];
		if (g->shape == shape && g->shape_tol == tol && g->shape_segments == segments)
			return g;
	}
	return NULL;
}

bool world_tracer_mesh(const world_tracer *t, const void *shape, double tol, uint32_t segments, mesh *out,
		       double *err)
{
	const world_geom *g = NULL;
	for (int i = 0; t && !g && i < WORLD_TRACER_SLOTS; i++)
		g = made_in(t->slot[i].w, shape, tol, segments);
	for (size_t i = 0; t && !g && i < t->n_pinned; i++)
		g = made_in(t->pinned[i].w, shape, tol, segments);
	if (!g || !mesh_copy(out, &g->m))
		return false;
	*err = g->shape_err;
	return true;
}

/* The scene of objs[0..n) alone (trace()'s object, a light's projected_through objects): their
 * geometry records copied (shallow, renumbered, linked in a list of their own; a record the
 * objects share stays shared), the objects grey, in no light group, casting shadows, no lights,
 * the parent's camera and settings (so tessellated as the render's objects). NULL when memory
 * runs out. */
scene *build_object_scene(const scene *parent, const scene_object *objs, size_t n)
{
	scene *sc = scene_new();
	if (!sc)
		return NULL;
	sc->global = parent->global;
	sc->has_camera = parent->has_camera;
	sc->camera = parent->camera;
	sc->csg_ids = parent->csg_ids;
	const scene_geom **from = mem_alloc(n ? n : 1, sizeof *from);
	scene_geom **to = mem_alloc(n ? n : 1, sizeof *to);
	bool ok = from && to;
	size_t k = 0;
	for (size_t i = 0; ok && i < n; i++) {
		scene_object o = objs[i];
		size_t j = 0;
		while (j < k && from[j] != o.geom)
			j++;
		if (j == k) {
			scene_geom *g = arena_alloc(&sc->arena, 1, sizeof *g, 16);
			if (!(ok = g != NULL))
				break;
			*g = *o.geom;
			g->id = sc->n_geoms++;
			g->next = sc->geoms;
			sc->geoms = g;
			from[k] = o.geom, to[k] = g, k++;
		}
		o.geom = to[j];
		o.material = NULL;
		o.texture_placed = false;
		o.texture_from_object = xform_identity();
		o.light_group = 0;
		o.no_shadow = false;
		ok = vecbuf_push(&sc->objects, &o) != NULL;
	}
	mem_free(from), mem_free(to);
	if (!ok) {
		sc->geoms = NULL;
		scene_free(sc);
		return NULL;
	}
	return sc;
}

/* Builds s (free) for objs as key's world; false after reporting at loc. */
static bool build_slot(world_tracer *t, tracer_slot *s, const scene *parent, const scene_object *objs, size_t n,
		       const void *key, diag *d, diag_loc loc)
{
	s->sc = build_object_scene(parent, objs, n);
	if (!s->sc) {
		diag_error(d, loc, "out of memory");
		return false;
	}
	/* Quietly: the render builds (and warns about) the same records again. Only a failure is
	 * built again aloud, for its messages. */
	diag quiet;
	diag_init(&quiet, NULL);
	bool valid = scene_validate(s->sc, &quiet) == 0;
	s->w = valid ? world_build(s->sc, &t->opt, &quiet) : NULL;
	diag_free(&quiet);
	if (!s->w) {
		if (valid)
			world_free(world_build(s->sc, &t->opt, d));
		else
			scene_validate(s->sc, d);
		diag_error(d, loc, "the object cannot be made ready to trace or test (above)");
		slot_free(s);
		return false;
	}
	world_stats st;
	world_stats_get(s->w, &st);
	s->triangles = st.instanced_triangles;
	s->key = key;
	t->builds++;
	return true;
}

/* The slot of key, built now when it is not kept; NULL after reporting at loc. */
static tracer_slot *slot_of(world_tracer *t, const scene *parent, const scene_object *objs, size_t n, const void *key,
			    diag *d, diag_loc loc)
{
	for (int i = 0; i < WORLD_TRACER_SLOTS; i++)
		if (t->slot[i].key == key && key)
			return &t->slot[i];
	for (size_t i = 0; i < t->n_pinned; i++)
		if (t->pinned[i].key == key && key)
			return &t->pinned[i];
	tracer_slot *s = &t->slot[t->next];
	t->next = (t->next + 1) % WORLD_TRACER_SLOTS;
	slot_free(s);
	return build_slot(t, s, parent, objs, n, key, d, loc) ? s : NULL;
}

/* The pinned slot of key (kept while t lives), built now or taken from the round robin's. */
static tracer_slot *pinned_of(world_tracer *t, const scene *parent, const scene_object *objs, size_t n, const void *key,
			      diag *d, diag_loc loc)
{
	for (size_t i = 0; i < t->n_pinned; i++)
		if (t->pinned[i].key == key && key)
			return &t->pinned[i];
	if (t->n_pinned == t->cap_pinned) {
		size_t cap = t->cap_pinned ? 2 * t->cap_pinned : 4;
		tracer_slot *g = mem_realloc(t->pinned, cap, sizeof *g);
		if (!g) {
			diag_error(d, loc, "out of memory");
			return NULL;
		}
		t->pinned = g, t->cap_pinned = cap;
	}
	tracer_slot *s = &t->pinned[t->n_pinned];
	memset(s, 0, sizeof *s);
	for (int i = 0; i < WORLD_TRACER_SLOTS; i++)
		if (t->slot[i].key == key && key) { /* traced before: the same world moves */
			*s = t->slot[i];
			memset(&t->slot[i], 0, sizeof t->slot[i]);
			t->n_pinned++;
			return s;
		}
	if (!build_slot(t, s, parent, objs, n, key, d, loc))
		return NULL;
	t->n_pinned++;
	return s;
}

/* scene_fn_eval of an object's inside: 1 inside, 0 outside (thread-safe: the world is read only). */
static bool inside_eval(const void *ctx, const double xyz[3], double *out)
{
	const world *w = ctx;
	*out = world_point_inside(w, v3((float)xyz[0], (float)xyz[1], (float)xyz[2])) ? 1.0 : 0.0;
	return true;
}

bool world_inside_fn(world_tracer *t, const scene *parent, const scene_object *objs, size_t n, const void *key,
		     scene_fn *out, diag *d, diag_loc loc)
{
	tracer_slot *s = pinned_of(t, parent, objs, n, key, d, loc);
	if (!s)
		return false;
	*out = (scene_fn){.eval = inside_eval, .ctx = s->w, .name = "(object)"};
	return true;
}

int world_trace(world_tracer *t, const scene *parent, const scene_object *objs, size_t n, const void *key, dvec3 org,
		dvec3 dir, dvec3 *hit, dvec3 *normal, diag *d, diag_loc loc)
{
	*hit = d3(0, 0, 0), *normal = d3(0, 0, 0);
	double len = d3_length(dir);
	if (!(len > 0) || !isfinite(len) || !isfinite(org.x) || !isfinite(org.y) || !isfinite(org.z)) {
		diag_error(d, loc, "'trace' needs a finite start and a non-zero direction, found <%g, %g, %g> and <%g, %g, %g>",
			   org.x, org.y, org.z, dir.x, dir.y, dir.z);
		return -1;
	}
	tracer_slot *s = slot_of(t, parent, objs, n, key, d, loc);
	if (!s)
		return -1;
	const render_scene *rs = world_scene(s->w);
	dvec3 u = d3_scale(dir, 1 / len);
	render_ray ray = {d3v(org), d3v(u)};
	/* The start may lie on the surface (a vine grown along it): hits within float rounding of it
	 * are the start's own. */
	double big = fmax(fabs(org.x), fmax(fabs(org.y), fabs(org.z)));
	float tmin = (float)(1e-5 * fmax(1.0, big));
	render_hit h;
	memset(&h, 0, sizeof h);
	if (!s->triangles || !rs->intersect(rs->user, &ray, tmin, INFINITY, &h))
		return 0;
	*hit = d3_add(org, d3_scale(u, h.t));
	*normal = v3_to_d3(h.ns);
	return 1;
}
