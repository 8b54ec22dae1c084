/* build_csg.c - the scene's CSG solids (scene.h's paths) as trees of nodes over instances, the
 * facts each instance's hits are classified with (render/world_csg.c), and their SSS volumes. */
#include "build/build_impl.h"

#include "base/mem.h"

#include <math.h>
#include <string.h>

/* A hash map from a node's scene id to its index in w->csg_nodes (open addressing; 0 is no id). */
typedef struct idmap {
	uint32_t *ids;
	int32_t *nodes;
	size_t cap;
} idmap;

static size_t slot_of(const idmap *m, uint32_t id)
{
	size_t h = (size_t)(id * 2654435761u) & (m->cap - 1);
	while (m->ids[h] && m->ids[h] != id)
		h = (h + 1) & (m->cap - 1);
	return h;
}

/* One (parent, operand, item) of the trees, in the order first met. */
typedef struct edge {
	int32_t parent, item;
	uint32_t operand, order;
} edge;

static int edge_cmp(const void *a, const void *b)
{
	const edge *x = a, *y = b;
	if (x->parent != y->parent)
		return x->parent < y->parent ? -1 : 1;
	if (x->operand != y->operand)
		return x->operand < y->operand ? -1 : 1;
	return x->order < y->order ? -1 : x->order > y->order;
}

/* How instance in's inside is told: analytically where its mesh is exactly the solid (a plane's
 * half-space, a box), else by the parity of its mesh's crossings. */
static void set_inside_kind(world_inst *in, const scene_geom *g)
{
	in->inside_kind = WORLD_INSIDE_MESH;
	if (g->kind == SHAPE_PLANE) {
		double len = d3_length(g->u.plane.normal);
		if (len > 0.0) {
			in->inside_kind = WORLD_INSIDE_PLANE;
			in->plane_n = d3_scale(g->u.plane.normal, 1.0 / len);
			in->plane_d = g->u.plane.offset;
		}
	} else if (g->kind == SHAPE_CONE && g->u.cone.open) {
		in->inside_kind = WORLD_INSIDE_CONE;
		in->box_lo = g->u.cone.base, in->box_hi = g->u.cone.cap;
		in->cone_r0 = g->u.cone.base_radius, in->cone_r1 = g->u.cone.cap_radius;
	} else if (g->kind == SHAPE_BOX) {
		in->inside_kind = WORLD_INSIDE_BOX;
		dvec3 a = g->u.box.corner1, b = g->u.box.corner2;
		in->box_lo = d3(fmin(a.x, b.x), fmin(a.y, b.y), fmin(a.z, b.z));
		in->box_hi = d3(fmax(a.x, b.x), fmax(a.y, b.y), fmax(a.z, b.z));
	}
}

/* Instance i's place among the pieces of its mesh (scene_object.pieces; insts are the scene's
 * objects in order): all of them meshes, each naming its place, or it is taken whole. */
static void set_pieces(world *w, const scene *sc, size_t i)
{
	world_inst *in = &w->insts[i];
	const scene_object *o = scene_object_at(sc, in->object);
	in->piece0 = 0, in->n_pieces = 0;
	if (o->pieces < 2 || o->piece >= o->pieces || o->piece > i || i - o->piece + o->pieces > w->n_insts)
		return;
	size_t first = i - o->piece;
	for (size_t k = 0; k < o->pieces; k++) {
		const scene_object *ok = scene_object_at(sc, w->insts[first + k].object);
		if (ok->pieces != o->pieces || ok->piece != k || ok->geom->kind != SHAPE_MESH)
			return;
	}
	in->piece0 = (uint32_t)first, in->n_pieces = o->pieces;
}

static bool grow_nodes(world *w, size_t *cap)
{
	if (w->n_csg_nodes < *cap)
		return true;
	size_t nc = *cap ? 2 * *cap : 16;
	world_csg_node *n = mem_realloc(w->csg_nodes, nc, sizeof *n);
	if (!n)
		return false;
	w->csg_nodes = n, *cap = nc;
	return true;
}

static bool grow_edges(edge **e, size_t n, size_t *cap)
{
	if (n < *cap)
		return true;
	size_t nc = *cap ? 2 * *cap : 64;
	edge *ne = mem_realloc(*e, nc, sizeof *ne);
	if (!ne)
		return false;
	*e = ne, *cap = nc;
	return true;
}

static bool make_trees(world *w, const scene *sc, idmap *map, edge **edges, size_t *n_edges)
{
	size_t node_cap = 0, edge_cap = 0, ne = 0;
	uint32_t order = 0;
	for (size_t i = 0; i < w->n_insts; i++) {
		const scene_object *o = scene_object_at(sc, w->insts[i].object);
		int32_t prev = -1;
		for (uint32_t k = 0; k < o->csg_depth; k++) {
			const scene_csg_step *s = &o->csg[k];
			size_t h = slot_of(map, s->id);
			bool fresh = !map->ids[h];
			if (fresh) {
				if (!grow_nodes(w, &node_cap))
					return false;
				map->ids[h] = s->id;
				map->nodes[h] = (int32_t)w->n_csg_nodes;
				w->csg_nodes[w->n_csg_nodes++] = (world_csg_node){s->op, s->inverse, -1, 0, 0, 0};
			}
			int32_t node = map->nodes[h];
			if (k > 0 && fresh) { /* a node's place in its parent, once */
				if (!grow_edges(edges, ne, &edge_cap))
					return false;
				(*edges)[ne++] = (edge){prev, node, o->csg[k - 1].operand, order++};
			}
			prev = node;
		}
		if (o->csg_depth) {
			if (!grow_edges(edges, ne, &edge_cap))
				return false;
			(*edges)[ne++] = (edge){prev, -1 - (int32_t)i, o->csg[o->csg_depth - 1].operand, order++};
		}
	}
	*n_edges = ne;
	return true;
}

/* Puts the item under node `parent`: its parent and slot, for the walk up from a hit. */
static void adopt(world *w, int32_t item, int32_t parent, uint32_t slot)
{
	if (item >= 0) {
		w->csg_nodes[item].parent = parent;
		w->csg_nodes[item].slot = slot;
	} else {
		w->insts[-1 - item].csg_parent = parent;
		w->insts[-1 - item].csg_slot = slot;
	}
}

/* The children of every node from the edges (sorted by parent, operand, order): an operand of
 * several items becomes a union node of them. */
static bool link_trees(world *w, edge *e, size_t ne)
{
	qsort(e, ne, sizeof *e, edge_cmp);
	size_t cap_kids = ne + 1, node_cap = w->n_csg_nodes, made_from = w->n_csg_nodes;
	/* Every edge is a kid once; each union made takes one more. */
	w->csg_kids = mem_alloc(2 * cap_kids, sizeof *w->csg_kids);
	if (!w->csg_kids)
		return false;
	/* First the parents' own kids, contiguous per parent; the unions' kids after them. */
	world_csg_kid *tail = mem_alloc(cap_kids, sizeof *tail);
	size_t n_tail = 0;
	if (!tail)
		return false;
	size_t nk = 0;
	bool ok = true;
	for (size_t a = 0; ok && a < ne;) {
		int32_t parent = e[a].parent;
		w->csg_nodes[parent].first = (uint32_t)nk;
		for (; ok && a < ne && e[a].parent == parent;) {
			size_t b = a;
			while (b < ne && e[b].parent == parent && e[b].operand == e[a].operand)
				b++;
			int32_t item = e[a].item;
			if (b - a > 1) { /* a union of the operand's items */
				ok = grow_nodes(w, &node_cap);
				if (!ok)
					break;
				item = (int32_t)w->n_csg_nodes;
				w->csg_nodes[w->n_csg_nodes++] = (world_csg_node){SCENE_CSG_UNION, false, -1, 0, 0, (uint32_t)(b - a)};
				w->csg_nodes[item].first = (uint32_t)n_tail; /* offset into tail for now */
				for (size_t k = a; k < b; k++) {
					adopt(w, e[k].item, item, (uint32_t)(k - a));
					tail[n_tail++] = (world_csg_kid){e[k].item, 0};
				}
			}
			adopt(w, item, parent, w->csg_nodes[parent].count++);
			w->csg_kids[nk++] = (world_csg_kid){item, e[a].operand};
			a = b;
		}
	}
	if (ok) {
		/* The unions' kids go after the parents': their first moves by nk. */
		memcpy(w->csg_kids + nk, tail, n_tail * sizeof *tail);
		for (size_t n = made_from; n < w->n_csg_nodes; n++)
			w->csg_nodes[n].first += (uint32_t)nk;
		w->n_csg_kids = nk + n_tail;
	}
	mem_free(tail);
	return ok;
}

/* The walk up from every instance: whether any node above it is not a union (its hits are
 * classified), and how many inversions lie above it (its normals reversed when odd). */
static void classify(world *w)
{
	for (size_t i = 0; i < w->n_insts; i++) {
		world_inst *in = &w->insts[i];
		bool filtered = false, flip = in->csg_inverse;
		int32_t node = in->csg_parent;
		uint32_t slot = in->csg_slot;
		while (node >= 0) {
			const world_csg_node *nd = &w->csg_nodes[node];
			filtered |= nd->op != SCENE_CSG_UNION;
			flip ^= nd->inverse;
			if (nd->op == SCENE_CSG_DIFFERENCE && w->csg_kids[nd->first + slot].operand != 0)
				flip ^= true;
			slot = nd->slot;
			node = nd->parent;
		}
		in->csg_filtered = filtered;
		in->csg_flip = flip;
	}
}

/* The SSS volume of a mesh placed in pieces (mesh2's texture_list, world_inst.n_pieces): its SSS
 * pieces of no named group are one volume, the first of them its set, so that circles, probes
 * and the volume walk see the whole closed mesh, not each piece's open part of it. */
static void piece_groups(world *w, const scene *sc)
{
	for (size_t i = 0; i < w->n_insts; i++) {
		const world_inst *in = &w->insts[i];
		const scene_object *o = scene_object_at(sc, in->object);
		if (!in->n_pieces || in->hidden || !is_sss(o->material) || o->material->sss.group)
			continue;
		for (size_t j = in->piece0; j <= i; j++) {
			const world_inst *jn = &w->insts[j];
			const scene_material *mj = scene_object_at(sc, jn->object)->material;
			if (!jn->hidden && is_sss(mj) && !mj->sss.group) {
				w->sss_group[i] = j == i ? -1 : (int)j;
				if (j < i)
					w->sss_group[j] = (int)j;
				break;
			}
		}
	}
}

/* The SSS volume of a CSG solid: its SSS instances (of no named group) are one volume, so that
 * circles and probes find the solid's boundary over all its operands. */
static void csg_groups(world *w, const scene *sc)
{
	for (size_t i = 0; i < w->n_insts; i++) {
		const world_inst *in = &w->insts[i];
		const scene_object *o = scene_object_at(sc, in->object);
		if (in->csg_parent < 0 || in->hidden || !is_sss(o->material) || o->material->sss.group)
			continue;
		for (size_t j = 0; j <= i; j++) {
			const world_inst *jn = &w->insts[j];
			const scene_object *oj = scene_object_at(sc, jn->object);
			if (jn->csg_parent >= 0 && !jn->hidden && is_sss(oj->material) && !oj->material->sss.group &&
			    oj->csg[0].id == o->csg[0].id) {
				w->sss_group[i] = (int)j;
				break;
			}
		}
	}
}

bool build_csg(world *w, const scene *sc, diag *d)
{
	size_t steps = 0;
	for (size_t i = 0; i < w->n_insts; i++) {
		world_inst *in = &w->insts[i];
		const scene_object *o = scene_object_at(sc, in->object);
		in->csg_parent = -1;
		in->csg_inverse = o->inverse;
		in->hidden = o->clip_only;
		set_inside_kind(in, o->geom);
		set_pieces(w, sc, i);
		steps += o->csg_depth;
	}
	piece_groups(w, sc);
	if (!steps)
		return true;
	idmap map = {0};
	map.cap = 16;
	while (map.cap < 2 * steps)
		map.cap *= 2;
	map.ids = mem_calloc(map.cap, sizeof *map.ids);
	map.nodes = mem_calloc(map.cap, sizeof *map.nodes);
	edge *edges = NULL;
	size_t ne = 0;
	bool ok = map.ids && map.nodes && make_trees(w, sc, &map, &edges, &ne) && link_trees(w, edges, ne);
	mem_free(map.ids), mem_free(map.nodes), mem_free(edges);
	if (!ok) {
		diag_error(d, diag_noloc(), "out of memory while building the CSG solids");
		return false;
	}
	classify(w);
	for (size_t i = 0; i < w->n_insts; i++) {
		const scene_object *o = scene_object_at(sc, w->insts[i].object);
		if (w->insts[i].csg_filtered && !w->insts[i].hidden && o->material &&
		    v3_max_comp(o->material->emission) > 0.0f) {
			/* Its light would be sampled on the whole of each operand's surface. */
			diag_error(d, o->loc, "an emissive object in a CSG intersection, difference, merge or clipped_by "
					      "is not supported by circe");
			return false;
		}
	}
	csg_groups(w, sc);
	w->stats.csg_nodes = w->n_csg_nodes;
	for (size_t n = 0; n < w->n_csg_nodes; n++)
		w->stats.csg_solids += w->csg_nodes[n].parent < 0;
	for (size_t i = 0; i < w->n_insts; i++)
		w->stats.csg_clips += w->insts[i].hidden;
	return true;
}
