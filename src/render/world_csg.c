/* world_csg.c - the boundary of a CSG solid: whether a point of an operand's surface bounds the
 * solid, by the inside of the other operands at that point (POV-Ray's own classification,
 * source/core/shape/csg.cpp: an intersection keeps a hit inside every other operand, a merge one
 * outside them, a difference A - B... a hit on A outside every B and one on a B inside A and
 * outside the other Bs, a union every hit; inverse turns an inside out). */
#include "render/world.h"

#include <float.h>
#include <math.h>

/* The direction of the rays that count crossings, in object space: off every axis and diagonal,
 * so that a box's or a tessellated shape's edges are not met along it but by chance. */
static const vec3 INSIDE_DIR = {0.5773502f, 0.6172134f, 0.5345225f};

/* No inside test counts more crossings than this (the point is then said to be outside). */
#define WORLD_MAX_CROSSINGS 4096

/* The parity of the crossings of a ray from q (object space) with the mesh: odd inside. Hits at
 * one t (a shared edge or vertex, met by both triangles) count once. */
static bool mesh_inside(const bvh *b, vec3 q)
{
	bvh_ray r = {q, INSIDE_DIR, 0.0f, INFINITY};
	bvh_hit h;
	bool inside = false;
	for (int k = 0; k < WORLD_MAX_CROSSINGS && bvh_intersect(b, &r, &h); k++) {
		inside = !inside;
		r.tmin = nextafterf(h.t, INFINITY);
	}
	return inside;
}

/* p (world) inside instance in's solid, before its own inverse. */
static bool solid_inside(const world_inst *in, vec3 p)
{
	if (in->inside_kind == WORLD_INSIDE_PLANE) { /* a half-space: no bounds */
		dvec3 q = in->identity ? v3_to_d3(p) : xform_inv_point(&in->xf, v3_to_d3(p));
		return d3_dot(in->plane_n, q) < in->plane_d;
	}
	if (p.x < in->lo.x || p.y < in->lo.y || p.z < in->lo.z || p.x > in->hi.x || p.y > in->hi.y || p.z > in->hi.z)
		return false;
	dvec3 q = in->identity ? v3_to_d3(p) : xform_inv_point(&in->xf, v3_to_d3(p));
	if (in->inside_kind == WORLD_INSIDE_CONE) { /* between the caps, within the radius there */
		dvec3 ax = d3_sub(in->box_hi, in->box_lo), rel = d3_sub(q, in->box_lo);
		double len2 = d3_dot(ax, ax), s = len2 > 0.0 ? d3_dot(rel, ax) / len2 : -1.0;
		if (!(s > 0.0 && s < 1.0))
			return false;
		dvec3 off = d3_sub(rel, d3_scale(ax, s));
		double r = in->cone_r0 + s * (in->cone_r1 - in->cone_r0);
		return d3_dot(off, off) < r * r;
	}
	if (in->inside_kind == WORLD_INSIDE_BOX)
		return q.x > in->box_lo.x && q.y > in->box_lo.y && q.z > in->box_lo.z && q.x < in->box_hi.x &&
		       q.y < in->box_hi.y && q.z < in->box_hi.z;
	return in->g->b && mesh_inside(in->g->b, d3_to_v3(q));
}

/* p (world) inside the mesh whose pieces in is one of (world_inst.n_pieces): the parity of the
 * crossings of every piece, each an open surface (no piece's own box bounds the whole's inside). */
static bool pieces_inside(const world *w, const world_inst *in, vec3 p)
{
	bool inside = false, near = false;
	for (uint32_t k = 0; k < in->n_pieces; k++) {
		const world_inst *pk = &w->insts[in->piece0 + k];
		near |= p.x >= pk->lo.x && p.y >= pk->lo.y && p.z >= pk->lo.z && p.x <= pk->hi.x &&
			p.y <= pk->hi.y && p.z <= pk->hi.z;
	}
	for (uint32_t k = 0; near && k < in->n_pieces; k++) {
		const world_inst *pk = &w->insts[in->piece0 + k];
		dvec3 q = pk->identity ? v3_to_d3(p) : xform_inv_point(&pk->xf, v3_to_d3(p));
		inside ^= pk->g->b && mesh_inside(pk->g->b, d3_to_v3(q));
	}
	return inside;
}

bool world_inside(const world *w, uint32_t inst, vec3 p)
{
	const world_inst *in = &w->insts[inst];
	return (in->n_pieces ? pieces_inside(w, in, p) : solid_inside(in, p)) != in->csg_inverse;
}

static bool kid_inside(const world *w, int32_t item, vec3 p);

/* Inside node n: the boolean of its children's insides, then its inverse. */
static bool node_inside(const world *w, int32_t n, vec3 p)
{
	const world_csg_node *nd = &w->csg_nodes[n];
	const world_csg_kid *k = &w->csg_kids[nd->first];
	bool in;
	switch (nd->op) {
	case SCENE_CSG_INTERSECTION:
		in = true;
		for (uint32_t i = 0; in && i < nd->count; i++)
			in = kid_inside(w, k[i].item, p);
		break;
	case SCENE_CSG_DIFFERENCE:
		in = false;
		for (uint32_t i = 0; i < nd->count; i++) /* the base's inside first */
			if (k[i].operand == 0)
				in = kid_inside(w, k[i].item, p);
		for (uint32_t i = 0; in && i < nd->count; i++)
			if (k[i].operand != 0)
				in = !kid_inside(w, k[i].item, p);
		break;
	default: /* union, merge */
		in = false;
		for (uint32_t i = 0; !in && i < nd->count; i++)
			in = kid_inside(w, k[i].item, p);
		break;
	}
	return in != nd->inverse;
}

/* The CSG tree nests at most LANG_MAX_CSG_DEPTH (64) levels, plus the unions of operands: the
 * recursion is bounded by it. */
static bool kid_inside(const world *w, int32_t item, vec3 p)
{
	return item >= 0 ? node_inside(w, item, p) : world_inside(w, (uint32_t)(-1 - item), p);
}

bool world_csg_keep(const world *w, uint32_t inst, vec3 p)
{
	const world_inst *in = &w->insts[inst];
	if (!in->csg_filtered)
		return true;
	int32_t node = in->csg_parent;
	uint32_t slot = in->csg_slot;
	while (node >= 0) {
		const world_csg_node *nd = &w->csg_nodes[node];
		const world_csg_kid *k = &w->csg_kids[nd->first];
		switch (nd->op) {
		case SCENE_CSG_INTERSECTION:
			for (uint32_t i = 0; i < nd->count; i++)
				if (i != slot && !kid_inside(w, k[i].item, p))
					return false;
			break;
		case SCENE_CSG_MERGE:
			for (uint32_t i = 0; i < nd->count; i++)
				if (i != slot && kid_inside(w, k[i].item, p))
					return false;
			break;
		case SCENE_CSG_DIFFERENCE: {
			for (uint32_t i = 0; i < nd->count; i++) {
				if (i == slot)
					continue;
				bool want = k[i].operand == 0; /* inside the base, outside every subtracted one */
				if (kid_inside(w, k[i].item, p) != want)
					return false;
			}
			break;
		}
		default: /* union: every hit */
			break;
		}
		slot = nd->slot;
		node = nd->parent;
	}
	return true;
}

bool world_csg_filter(void *user, uint32_t key, const bvh_ray *ray, const bvh_hit *hit)
{
	(void)ray;
	const world *w = user;
	const world_inst *in = &w->insts[key];
	const mesh *m = &in->g->m;
	const uint32_t *ix = m->indices + 3 * (size_t)hit->prim;
	float b0 = 1.0f - hit->u - hit->v;
	/* The point from the triangle, as fill_hit makes it (world.c). */
	vec3 p = v3_add(v3_add(v3_scale(m->positions[ix[0]], b0), v3_scale(m->positions[ix[1]], hit->u)),
			v3_scale(m->positions[ix[2]], hit->v));
	if (!in->identity)
		p = d3_to_v3(xform_point(&in->xf, v3_to_d3(p)));
	return world_csg_keep(w, key, p);
}

bool world_point_inside(const world *w, vec3 p)
{
	for (size_t i = 0; i < w->n_insts; i++) {
		const world_inst *in = &w->insts[i];
		if (in->csg_parent < 0 && !in->hidden && world_inside(w, (uint32_t)i, p))
			return true;
	}
	for (size_t n = 0; n < w->n_csg_nodes; n++) /* each solid by its root */
		if (w->csg_nodes[n].parent < 0 && node_inside(w, (int32_t)n, p))
			return true;
	return false;
}
