/* mesh.c - allocation, mesh/mesh2 arrays to vertices, tangents and transforms of triangle meshes. */
#include "geom/mesh.h"

#include "base/mem.h"

#include <assert.h>
#include <string.h>

bool mesh_alloc(mesh *m, size_t nv, size_t nt, bool normals, bool uvs, bool tangents)
{
	memset(m, 0, sizeof *m);
	size_t ni;
	if (nv > UINT32_MAX || nt > UINT32_MAX / 3 || !mem_mul_ok(nt, 3, &ni))
		return false;
	m->num_vertices = (uint32_t)nv;
	m->num_triangles = (uint32_t)nt;
	m->positions = mem_alloc(nv, sizeof(vec3));
	m->indices = mem_alloc(ni, sizeof(uint32_t));
	m->normals = normals ? mem_alloc(nv, sizeof(vec3)) : NULL;
	m->uvs = uvs ? mem_alloc(nv, sizeof(vec2)) : NULL;
	m->tangents = tangents ? mem_alloc(nv, sizeof(mesh_tangent)) : NULL;
	if (!m->positions || !m->indices || (normals && !m->normals) || (uvs && !m->uvs) ||
	    (tangents && !m->tangents)) {
		mesh_free(m);
		return false;
	}
	return true;
}

bool mesh_copy(mesh *dst, const mesh *src)
{
	if (!mesh_alloc(dst, src->num_vertices, src->num_triangles, src->normals, src->uvs, src->tangents))
		return false;
	size_t nv = src->num_vertices;
	memcpy(dst->positions, src->positions, nv * sizeof(vec3));
	memcpy(dst->indices, src->indices, (size_t)src->num_triangles * 3 * sizeof(uint32_t));
	if (src->normals)
		memcpy(dst->normals, src->normals, nv * sizeof(vec3));
	if (src->uvs)
		memcpy(dst->uvs, src->uvs, nv * sizeof(vec2));
	if (src->tangents)
		memcpy(dst->tangents, src->tangents, nv * sizeof(mesh_tangent));
	return true;
}

void mesh_free(mesh *m)
{
	mem_free(m->positions);
	mem_free(m->normals);
	mem_free(m->uvs);
	mem_free(m->tangents);
	mem_free(m->indices);
	memset(m, 0, sizeof *m);
}

size_t mesh_bytes(const mesh *m)
{
	size_t per_vertex = sizeof(vec3) + (m->normals ? sizeof(vec3) : 0) + (m->uvs ? sizeof(vec2) : 0) +
			    (m->tangents ? sizeof(mesh_tangent) : 0);
	return (size_t)m->num_vertices * per_vertex + (size_t)m->num_triangles * 3 * sizeof(uint32_t);
}

/* One corner of mesh2 data: which position, normal and uv it combines. */
typedef struct corner_key {
	uint32_t p, n, t;
} corner_key;

static uint64_t corner_hash(corner_key k)
{
	uint64_t h = (uint64_t)k.p * 0x9e3779b97f4a7c15ULL ^ (uint64_t)k.n * 0xc2b2ae3d27d4eb4fULL ^
		     (uint64_t)k.t * 0x165667b19e3779f9ULL;
	return h ^ (h >> 29);
}

static bool index_ok(const uint32_t *idx, size_t f, size_t limit, const char *what, diag *d,
		     diag_loc loc)
{
	for (int c = 0; c < 3; c++)
		if (idx[3 * f + c] >= limit) {
			diag_error(d, loc, "face %zu: %s index %u out of range (there are %zu)", f, what,
				   idx[3 * f + c], limit);
			return false;
		}
	return true;
}

bool mesh_from_arrays(const mesh_arrays *a, mesh *out, diag *d, diag_loc loc)
{
	memset(out, 0, sizeof *out);
	const uint32_t *ni = a->normals ? (a->normal_indices ? a->normal_indices : a->face_indices) : NULL;
	const uint32_t *ti = a->uvs ? (a->uv_indices ? a->uv_indices : a->face_indices) : NULL;
	for (size_t f = 0; f < a->num_faces; f++) {
		if (!index_ok(a->face_indices, f, a->num_positions, "vertex", d, loc) ||
		    (ni && !index_ok(ni, f, a->num_normals, "normal", d, loc)) ||
		    (ti && !index_ok(ti, f, a->num_uvs, "uv", d, loc)))
			return false;
	}
	size_t corners;
	if (!mem_mul_ok(a->num_faces, 3, &corners) || corners > UINT32_MAX) {
		diag_error(d, loc, "too many faces (%zu; the limit is %u)", a->num_faces, UINT32_MAX / 3);
		return false;
	}
	/* Hash table of distinct corners, power-of-two size at least twice the corner count. */
	size_t cap = 16;
	while (cap < 2 * corners)
		cap *= 2;
	corner_key *keys = mem_alloc(cap, sizeof *keys);
	uint32_t *slot = mem_alloc(cap, sizeof *slot);
	uint32_t *remap = mem_alloc(corners, sizeof *remap);
	corner_key *uniq = mem_alloc(corners, sizeof *uniq);
	bool ok = keys && slot && remap && uniq;
	uint32_t nv = 0;
	if (ok) {
		memset(slot, 0xff, cap * sizeof *slot);
		for (size_t c = 0; c < corners; c++) {
			corner_key k = {a->face_indices[c], ni ? ni[c] : 0, ti ? ti[c] : 0};
			size_t h = corner_hash(k) & (cap - 1);
			while (slot[h] != UINT32_MAX &&
			       (keys[h].p != k.p || keys[h].n != k.n || keys[h].t != k.t))
				h = (h + 1) & (cap - 1);
			if (slot[h] == UINT32_MAX) {
				keys[h] = k;
				slot[h] = nv;
				uniq[nv++] = k;
			}
			remap[c] = slot[h];
		}
		ok = mesh_alloc(out, nv, a->num_faces, ni != NULL, ti != NULL, false);
	}
	if (ok) {
		for (uint32_t v = 0; v < nv; v++) {
			out->positions[v] = a->positions[uniq[v].p];
			if (ni)
				out->normals[v] = v3_normalize(a->normals[uniq[v].n]);
			if (ti)
				out->uvs[v] = a->uvs[uniq[v].t];
		}
		memcpy(out->indices, remap, corners * sizeof *remap);
	} else {
		diag_error(d, loc, "out of memory building a mesh of %zu faces", a->num_faces);
	}
	mem_free(keys);
	mem_free(slot);
	mem_free(remap);
	mem_free(uniq);
	return ok;
}

/* The bits of a coordinate, with -0 made +0 so that equal floats have equal keys. */
static uint32_t coord_bits(float f)
{
	uint32_t u;
	f = f == 0.0f ? 0.0f : f;
	memcpy(&u, &f, sizeof u);
	return u;
}

/* A triangle's corners as a key independent of their order: the three positions' bits, sorted. */
typedef struct tri_key {
	uint32_t c[9];
} tri_key;

static tri_key triangle_key(const mesh *m, uint32_t f)
{
	uint32_t p[3][3];
	for (int k = 0; k < 3; k++) {
		vec3 v = m->positions[m->indices[3 * (size_t)f + k]];
		p[k][0] = coord_bits(v.x), p[k][1] = coord_bits(v.y), p[k][2] = coord_bits(v.z);
	}
	/* Three corners: a sorting network of three compare-exchanges. */
	static const int pairs[3][2] = {{0, 1}, {1, 2}, {0, 1}};
	for (int s = 0; s < 3; s++) {
		uint32_t *a = p[pairs[s][0]], *b = p[pairs[s][1]];
		if (memcmp(a, b, sizeof p[0]) > 0) {
			uint32_t t[3];
			memcpy(t, a, sizeof t), memcpy(a, b, sizeof t), memcpy(b, t, sizeof t);
		}
	}
	tri_key k;
	memcpy(k.c, p, sizeof k.c);
	return k;
}

static uint64_t tri_key_hash(const tri_key *k)
{
	uint64_t h = 0xcbf29ce484222325ULL; /* FNV-1a over the words, then a final mix */
	for (int i = 0; i < 9; i++)
		h = (h ^ k->c[i]) * 0x100000001b3ULL;
	return h ^ (h >> 31);
}

size_t mesh_remove_duplicate_triangles(mesh *m)
{
	size_t nt = m->num_triangles, cap = 16;
	while (cap < 2 * nt)
		cap *= 2;
	uint32_t *slot = mem_alloc(cap, sizeof *slot); /* a kept triangle's new number, or UINT32_MAX */
	if (!slot)
		return SIZE_MAX;
	memset(slot, 0xff, cap * sizeof *slot);
	uint32_t kept = 0;
	for (uint32_t f = 0; f < nt; f++) {
		tri_key k = triangle_key(m, f);
		size_t h = tri_key_hash(&k) & (cap - 1);
		bool dup = false;
		for (; slot[h] != UINT32_MAX; h = (h + 1) & (cap - 1)) {
			tri_key o = triangle_key(m, slot[h]);
			if (!memcmp(&o, &k, sizeof k)) {
				dup = true;
				break;
			}
		}
		if (dup)
			continue;
		/* Kept triangles move down in order: slot[] names them by their new number, whose corners
		 * are already in place. */
		memmove(m->indices + 3 * (size_t)kept, m->indices + 3 * (size_t)f, 3 * sizeof *m->indices);
		slot[h] = kept++;
	}
	mem_free(slot);
	size_t removed = nt - kept;
	m->num_triangles = kept;
	return removed;
}

bool mesh_indices_valid(const mesh *m)
{
	for (size_t i = 0; i < 3 * (size_t)m->num_triangles; i++)
		if (m->indices[i] >= m->num_vertices)
			return false;
	return true;
}

bool mesh_generate_tangents(mesh *m)
{
	assert(mesh_indices_valid(m));
	if (!m->normals || !m->uvs)
		return false;
	vec3 *acc = mem_calloc(m->num_vertices, 2 * sizeof(vec3));
	if (!acc)
		return false;
	if (!m->tangents && !(m->tangents = mem_alloc(m->num_vertices, sizeof(mesh_tangent)))) {
		mem_free(acc);
		return false;
	}
	/* Lengyel 2001: per triangle, solve (e1, e2) = (t, b) [du1 du2; dv1 dv2] for t and b. */
	for (uint32_t f = 0; f < m->num_triangles; f++) {
		const uint32_t *ix = m->indices + 3 * f;
		vec3 p0 = m->positions[ix[0]], e1 = v3_sub(m->positions[ix[1]], p0),
		     e2 = v3_sub(m->positions[ix[2]], p0);
		vec2 t0 = m->uvs[ix[0]], t1 = m->uvs[ix[1]], t2 = m->uvs[ix[2]];
		float du1 = t1.x - t0.x, dv1 = t1.y - t0.y, du2 = t2.x - t0.x, dv2 = t2.y - t0.y;
		float det = du1 * dv2 - du2 * dv1;
		if (det == 0.0f || !isfinite(1.0f / det))
			continue;
		float r = 1.0f / det;
		vec3 t = v3_scale(v3_sub(v3_scale(e1, dv2), v3_scale(e2, dv1)), r);
		vec3 b = v3_scale(v3_sub(v3_scale(e2, du1), v3_scale(e1, du2)), r);
		for (int c = 0; c < 3; c++) {
			acc[2 * ix[c]] = v3_add(acc[2 * ix[c]], t);
			acc[2 * ix[c] + 1] = v3_add(acc[2 * ix[c] + 1], b);
		}
	}
	for (uint32_t v = 0; v < m->num_vertices; v++) {
		vec3 n = m->normals[v], t = acc[2 * v], b = acc[2 * v + 1];
		t = v3_normalize(v3_sub(t, v3_scale(n, v3_dot(n, t))));
		if (!(v3_length2(t) > 0.5f)) {
			vec3 b2;
			v3_basis(n, &t, &b2);
		}
		m->tangents[v].t = t;
		m->tangents[v].sign = v3_dot(v3_cross(n, t), b) < 0.0f ? -1.0f : 1.0f;
	}
	mem_free(acc);
	return true;
}

void mesh_transform(mesh *m, const xform *t)
{
	for (uint32_t v = 0; v < m->num_vertices; v++) {
		m->positions[v] = d3_to_v3(xform_point(t, v3_to_d3(m->positions[v])));
		if (m->normals)
			m->normals[v] = v3_normalize(d3_to_v3(xform_normal(t, v3_to_d3(m->normals[v]))));
		if (m->tangents)
			m->tangents[v].t =
				v3_normalize(d3_to_v3(xform_vector(t, v3_to_d3(m->tangents[v].t))));
	}
	if (xform_det(t) < 0.0) {
		for (uint32_t f = 0; f < m->num_triangles; f++) {
			uint32_t tmp = m->indices[3 * f + 1];
			m->indices[3 * f + 1] = m->indices[3 * f + 2];
			m->indices[3 * f + 2] = tmp;
		}
		if (m->tangents)
			for (uint32_t v = 0; v < m->num_vertices; v++)
				m->tangents[v].sign = -m->tangents[v].sign;
	}
}

bool mesh_bounds(const mesh *m, vec3 *lo, vec3 *hi)
{
	if (m->num_vertices == 0)
		return false;
	*lo = *hi = m->positions[0];
	for (uint32_t v = 1; v < m->num_vertices; v++) {
		*lo = v3_min(*lo, m->positions[v]);
		*hi = v3_max(*hi, m->positions[v]);
	}
	return true;
}
