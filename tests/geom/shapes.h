/* shapes.h - for the geometry tests: OpenSubdiv's test shapes read through circe's cage reader,
 * and the crack check of a tessellation (vertices welded by exact position, then every edge
 * shared by exactly two triangles), and a point uniformly on a triangle. */
#ifndef CIRCE_TESTS_GEOM_SHAPES_H
#define CIRCE_TESTS_GEOM_SHAPES_H

#include "geom/cage.h"
#include "base/rng.h"
#include "geom/mesh.h"

#include <stdio.h>

#include <stdlib.h>
#include <string.h>

typedef struct edge_key {
	uint32_t a, b;
} edge_key;

static inline int edge_cmp(const void *x, const void *y)
{
	const edge_key *p = x, *q = y;
	return p->a != q->a ? (p->a < q->a ? -1 : 1) : p->b != q->b ? (p->b < q->b ? -1 : 1) : 0;
}

/* Vertices welded by exact position (the UV mode duplicates boundary vertices per face, with
 * identical positions): the id of each vertex is the first of a run of equal positions. */
static const vec3 *weld_pos;
static inline int pos_cmp(const void *x, const void *y)
{
	uint32_t a = *(const uint32_t *)x, b = *(const uint32_t *)y;
	int c = memcmp(&weld_pos[a], &weld_pos[b], sizeof(vec3));
	return c ? c : (a < b ? -1 : a > b);
}

static inline uint32_t *weld(const mesh *m)
{
	uint32_t n = m->num_vertices, *order = malloc(n * sizeof *order), *id = malloc(n * sizeof *id);
	for (uint32_t i = 0; i < n; i++)
		order[i] = i;
	weld_pos = m->positions;
	qsort(order, n, sizeof *order, pos_cmp);
	for (uint32_t i = 0; i < n; i++)
		id[order[i]] =
		    i > 0 && memcmp(&m->positions[order[i]], &m->positions[order[i - 1]], sizeof(vec3)) == 0
			? id[order[i - 1]]
			: order[i];
	free(order);
	return id;
}

/* Edges not shared by exactly two triangles (0 for a closed, crack-free mesh). */
static inline long open_edges(const mesh *m)
{
	uint32_t *id = weld(m);
	size_t ne = 3 * (size_t)m->num_triangles;
	edge_key *e = malloc(ne * sizeof *e);
	for (uint32_t f = 0; f < m->num_triangles; f++)
		for (int k = 0; k < 3; k++) {
			uint32_t a = id[m->indices[3 * f + k]], b = id[m->indices[3 * f + (k + 1) % 3]];
			e[3 * f + k] = (edge_key){a < b ? a : b, a < b ? b : a};
		}
	qsort(e, ne, sizeof *e, edge_cmp);
	long bad = 0;
	for (size_t i = 0; i < ne;) {
		size_t j = i;
		while (j < ne && edge_cmp(&e[i], &e[j]) == 0)
			j++;
		bad += j - i != 2;
		i = j;
	}
	free(e), free(id);
	return bad;
}

/* A cage file and its subd_cage view (boundary edge_only, as OpenSubdiv's shapes default to). */
typedef struct test_cage {
	cage_data data;
	subd_cage c;
} test_cage;

/* Reads path (errors to stderr); NULL when it fails. Release with test_cage_free. */
static inline test_cage *cage_read(const char *path)
{
	test_cage *t = calloc(1, sizeof *t);
	diag d;
	diag_init(&d, stderr);
	if (t && !cage_load(path, &t->data, &d, diag_noloc())) {
		free(t);
		t = NULL;
	}
	diag_free(&d);
	if (t)
		t->c = cage_view(&t->data);
	return t;
}

static inline void test_cage_free(test_cage *t)
{
	if (t)
		cage_free(&t->data);
	free(t);
}

/* A shape of scenes/assets/opensubdiv_shapes (through $top_srcdir). */
static inline const char *shape_path(const char *name)
{
	static char buf[4096];
	const char *top = getenv("top_srcdir");
	snprintf(buf, sizeof buf, "%s/scenes/assets/opensubdiv_shapes/%s", top ? top : ".", name);
	return buf;
}

/* A point uniformly on triangle t. */
static inline dvec3 sample_tri(const mesh *m, uint32_t t, rng *r)
{
	double u = rng_double(r), v = rng_double(r);
	if (u + v > 1.0)
		u = 1.0 - u, v = 1.0 - v;
	dvec3 a = v3_to_d3(m->positions[m->indices[3 * t]]), b = v3_to_d3(m->positions[m->indices[3 * t + 1]]),
	      c = v3_to_d3(m->positions[m->indices[3 * t + 2]]);
	return d3_add(a, d3_add(d3_scale(d3_sub(b, a), u), d3_scale(d3_sub(c, a), v)));
}

#endif
