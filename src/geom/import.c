/* import.c - mesh files through Assimp's C API: every mesh of the scene graph, flattened through
 * its node transforms into one triangle mesh; and subdivision cages of formats other than OBJ,
 * flattened the same way but with their polygons kept. */
#include "geom/cage.h"
#include "geom/mesh.h"
#include "geom/ply.h"

#include "base/mem.h"

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <stdio.h>
#include <string.h>

/* Counts the triangles and vertices the node tree will produce (meshes may be instanced by
 * several nodes). */
static void count_node(const struct aiScene *s, const struct aiNode *nd, size_t *nv, size_t *nt,
		       bool *normals, bool *uvs, bool *tangents)
{
	for (unsigned i = 0; i < nd->mNumMeshes; i++) {
		const struct aiMesh *m = s->mMeshes[nd->mMeshes[i]];
		if (!(m->mPrimitiveTypes & aiPrimitiveType_TRIANGLE))
			continue;
		*nv += m->mNumVertices;
		*nt += m->mNumFaces;
		*normals = *normals && m->mNormals;
		*uvs = *uvs && m->mTextureCoords[0];
		*tangents = *tangents && m->mTangents && m->mBitangents;
	}
	for (unsigned i = 0; i < nd->mNumChildren; i++)
		count_node(s, nd->mChildren[i], nv, nt, normals, uvs, tangents);
}

static xform xform_from_ai(const struct aiMatrix4x4 *a)
{
	double v[12] = {a->a1, a->b1, a->c1, a->a2, a->b2, a->c2, a->a3, a->b3, a->c3, a->a4, a->b4, a->c4};
	xform t;
	if (!xform_from_pov_matrix(v, &t))
		t = xform_identity();
	return t;
}

typedef struct fill_state {
	mesh *out;
	uint32_t v, f;
} fill_state;

static void fill_node(const struct aiScene *s, const struct aiNode *nd, xform parent, fill_state *st)
{
	xform here = xform_then(xform_from_ai(&nd->mTransformation), parent);
	bool mirror = xform_det(&here) < 0.0;
	mesh *o = st->out;
	for (unsigned i = 0; i < nd->mNumMeshes; i++) {
		const struct aiMesh *m = s->mMeshes[nd->mMeshes[i]];
		if (!(m->mPrimitiveTypes & aiPrimitiveType_TRIANGLE))
			continue;
		uint32_t base = st->v;
		for (unsigned k = 0; k < m->mNumVertices; k++, st->v++) {
			const struct aiVector3D *p = &m->mVertices[k];
			o->positions[st->v] = d3_to_v3(xform_point(&here, d3(p->x, p->y, p->z)));
			if (o->normals) {
				const struct aiVector3D *n = &m->mNormals[k];
				o->normals[st->v] = v3_normalize(d3_to_v3(xform_normal(&here, d3(n->x, n->y, n->z))));
			}
			if (o->uvs)
				o->uvs[st->v] = v2(m->mTextureCoords[0][k].x, m->mTextureCoords[0][k].y);
			if (o->tangents) {
				const struct aiVector3D *t = &m->mTangents[k], *b = &m->mBitangents[k];
				vec3 tw = v3_normalize(d3_to_v3(xform_vector(&here, d3(t->x, t->y, t->z))));
				vec3 bw = d3_to_v3(xform_vector(&here, d3(b->x, b->y, b->z)));
				vec3 n = o->normals ? o->normals[st->v] : v3(0, 0, 1);
				o->tangents[st->v] = (mesh_tangent){tw, v3_dot(v3_cross(n, tw), bw) < 0 ? -1.0f : 1.0f};
			}
		}
		for (unsigned k = 0; k < m->mNumFaces; k++) {
			const struct aiFace *fc = &m->mFaces[k];
			uint32_t *ix = o->indices + 3 * (size_t)st->f;
			if (fc->mNumIndices != 3) {
				/* Points and lines mixed into a triangle mesh: a degenerate triangle. */
				ix[0] = ix[1] = ix[2] = base + (fc->mNumIndices ? fc->mIndices[0] : 0);
			} else {
				ix[0] = base + fc->mIndices[0];
				ix[1] = base + fc->mIndices[mirror ? 2 : 1];
				ix[2] = base + fc->mIndices[mirror ? 1 : 2];
			}
			st->f++;
		}
	}
	for (unsigned i = 0; i < nd->mNumChildren; i++)
		fill_node(s, nd->mChildren[i], here, st);
}

bool mesh_import(const char *path, mesh *out, diag *d)
{
	memset(out, 0, sizeof *out);
	char why[256];
	if (!ply_check_file(path, why, sizeof why)) {
		diag_file_error(d, path, "cannot import mesh: %s", why);
		return false;
	}
	const struct aiScene *s = aiImportFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
							     aiProcess_SortByPType);
	if (!s) {
		diag_file_error(d, path, "cannot import mesh: %s", aiGetErrorString());
		return false;
	}
	bool ok = false;
	size_t nv = 0, nt = 0;
	bool normals = true, uvs = true, tangents = true;
	if (s->mRootNode)
		count_node(s, s->mRootNode, &nv, &nt, &normals, &uvs, &tangents);
	if (nt == 0) {
		diag_file_error(d, path, "the file holds no triangles");
	} else if (nv > UINT32_MAX || nt > UINT32_MAX / 3) {
		diag_file_error(d, path, "too many vertices or triangles (%zu, %zu; the limit is %u)", nv, nt,
				UINT32_MAX / 3);
	} else if (!mesh_alloc(out, nv, nt, normals, uvs, tangents && normals)) {
		diag_file_error(d, path, "out of memory for %zu vertices and %zu triangles", nv, nt);
	} else {
		fill_state st = {out, 0, 0};
		fill_node(s, s->mRootNode, xform_identity(), &st);
		ok = true;
	}
	aiReleaseImport(s);
	return ok;
}

/* Appends the polygons of the node tree to raw: positions through the node transforms, one UV
 * per vertex (Assimp's vertices carry their own), polygon order reversed under a mirroring
 * transform. Points and lines are faces of 1 or 2 vertices, which the welding step refuses. */
static bool cage_node(const struct aiScene *s, const struct aiNode *nd, xform parent, cage_raw *r)
{
	xform here = xform_then(xform_from_ai(&nd->mTransformation), parent);
	bool mirror = xform_det(&here) < 0.0;
	for (unsigned i = 0; i < nd->mNumMeshes; i++) {
		const struct aiMesh *m = s->mMeshes[nd->mMeshes[i]];
		size_t base = r->positions.len;
		if (!m->mTextureCoords[0])
			r->uv_missing = true;
		if (!vecbuf_reserve(&r->positions, m->mNumVertices) || !vecbuf_reserve(&r->uvs, m->mNumVertices))
			return false;
		for (unsigned k = 0; k < m->mNumVertices; k++) {
			const struct aiVector3D *p = &m->mVertices[k];
			vec3 v = d3_to_v3(xform_point(&here, d3(p->x, p->y, p->z)));
			vec2 uv = m->mTextureCoords[0] ? v2(m->mTextureCoords[0][k].x, m->mTextureCoords[0][k].y) : v2(0, 0);
			vecbuf_push(&r->positions, &v);
			vecbuf_push(&r->uvs, &uv);
		}
		for (unsigned k = 0; k < m->mNumFaces; k++) {
			const struct aiFace *fc = &m->mFaces[k];
			uint32_t n = fc->mNumIndices, line = 0;
			if (!vecbuf_push(&r->face_sizes, &n) || !vecbuf_push(&r->face_lines, &line))
				return false;
			for (uint32_t j = 0; j < n; j++) {
				uint32_t v = (uint32_t)(base + fc->mIndices[mirror ? (n - j) % n : j]);
				if (!vecbuf_push(&r->indices, &v) || (m->mTextureCoords[0] && !vecbuf_push(&r->uv_indices, &v)))
					return false;
			}
		}
	}
	for (unsigned i = 0; i < nd->mNumChildren; i++)
		if (!cage_node(s, nd->mChildren[i], here, r))
			return false;
	return true;
}

bool cage_import_assimp(const char *path, cage_raw *raw, char *buf, size_t len, const char **why)
{
	/* No aiProcess_Triangulate: a cage keeps its quads and n-gons. No JoinIdenticalVertices
	 * either: cage.c welds by position, whatever the other attributes. */
	char ply_why[200];
	if (!ply_check_file(path, ply_why, sizeof ply_why)) {
		snprintf(buf, len, "cannot import it: %s", ply_why);
		*why = buf;
		return false;
	}
	const struct aiScene *s = aiImportFile(path, aiProcess_ValidateDataStructure);
	if (!s) {
		snprintf(buf, len, "cannot import it: %s", aiGetErrorString());
		*why = buf;
		return false;
	}
	bool ok = !s->mRootNode || cage_node(s, s->mRootNode, xform_identity(), raw);
	aiReleaseImport(s);
	if (!ok)
		*why = "out of memory";
	return ok;
}
