/* import.c - mesh files through Assimp's C API: every mesh of the scene graph, flattened through
 * its node transforms into one triangle mesh; and subdivision cages of formats other than OBJ,
 * flattened the same way but with their polygons kept. Nothing Assimp returns is trusted: PLY and
 * GLB files are checked for structure before it reads them, and its meshes (counts, indices,
 * finite coordinates) before they are used. */
#include "geom/cage.h"
#include "geom/mesh.h"
#include "geom/ply.h"

#include "base/mem.h"

#include <assimp/cimport.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <ctype.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

/* ---- checks of the file before Assimp reads it ------------------------------------------------ */

/* GLB, glTF 2.0's binary container (glTF 2.0 specification, "Binary glTF Layout"): a 12-byte header
 * (magic, version, total length) and chunks of (length, type, data), the first one JSON. */
enum { GLB_HEADER = 12, GLB_CHUNK_HEADER = 8, GLB_V1_HEADER = 20 };
#define GLB_MAGIC      0x46546C67u /* "glTF" */
#define GLB_CHUNK_JSON 0x4E4F534Au /* "JSON" */

static uint32_t le32(const unsigned char *b)
{
	return (uint32_t)b[0] | (uint32_t)b[1] << 8 | (uint32_t)b[2] << 16 | (uint32_t)b[3] << 24;
}

static bool glb_check(const unsigned char *d, size_t len, char *why, size_t why_len)
{
	if (len < 4 || le32(d) != GLB_MAGIC)
		return true; /* not a GLB file: not ours to judge */
	if (len < GLB_HEADER) {
		snprintf(why, why_len, "the GLB header is cut short (%zu bytes)", len);
		return false;
	}
	uint32_t version = le32(d + 4), total = le32(d + 8);
	if (total > len || total < GLB_HEADER) {
		snprintf(why, why_len,
			 "the GLB header declares %u bytes but the file has %zu (a truncated file?)", total,
			 len);
		return false;
	}
	if (version == 1) { /* glTF 1.0's binary extension: one JSON content of a declared length */
		if (total < GLB_V1_HEADER || le32(d + 12) > total - GLB_V1_HEADER) {
			snprintf(why, why_len, "the GLB content length runs past the file's %u bytes", total);
			return false;
		}
		return true;
	}
	size_t pos = GLB_HEADER;
	for (int chunk = 0; pos < total; chunk++) {
		if (total - pos < GLB_CHUNK_HEADER) {
			snprintf(why, why_len, "GLB chunk %d is cut short (a truncated file?)", chunk);
			return false;
		}
		uint32_t clen = le32(d + pos), type = le32(d + pos + 4);
		if (clen > total - pos - GLB_CHUNK_HEADER) {
			snprintf(why, why_len, "GLB chunk %d declares %u bytes, but only %zu follow it",
				 chunk, clen, total - pos - GLB_CHUNK_HEADER);
			return false;
		}
		if (chunk == 0 && type != GLB_CHUNK_JSON) {
			snprintf(why, why_len, "the first GLB chunk is not JSON");
			return false;
		}
		pos += GLB_CHUNK_HEADER + (size_t)clen;
	}
	if (pos == GLB_HEADER) {
		snprintf(why, why_len, "the GLB file has no JSON chunk");
		return false;
	}
	return true;
}

/* True when path ends in "." ext (ext lower case; the name in any case). */
static bool has_extension(const char *path, const char *ext)
{
	size_t n = strlen(path), e = strlen(ext);
	if (n <= e || path[n - e - 1] != '.')
		return false;
	for (size_t i = 0; i < e; i++)
		if (tolower((unsigned char)path[n - e + i]) != ext[i])
			return false;
	return true;
}

/* Assimp reads a file as PLY when it is named .ply or begins with "ply" (or "PLY"); ply_check
 * judges a file whose first line is exactly that, so anything else Assimp would take for PLY is
 * refused here (a file beginning "ply1\0..." crashed Assimp's PLY reader). */
static bool ply_first_line(const unsigned char *b, size_t len, const char *path, char *why, size_t why_len)
{
	bool magic = len >= 3 && (!memcmp(b, "ply", 3) || !memcmp(b, "PLY", 3));
	if ((magic || has_extension(path, "ply")) && !(magic && len >= 4 && (b[3] == '\n' || b[3] == '\r'))) {
		snprintf(why, why_len, "a PLY file must begin with the line 'ply'");
		return false;
	}
	return true;
}

/* The structural checks of the whole file (mapped read-only): PLY (ply.h) and GLB, whose broken
 * files hang Assimp, crash it or make it allocate gigabytes. An unreadable file passes (Assimp
 * reports it). *cut is set for an OBJ whose last line has no line end: cut off mid-line. */
static bool precheck(const char *path, char *why, size_t why_len, bool *cut)
{
	*cut = false;
	int fd = open(path, O_RDONLY | O_CLOEXEC);
	if (fd < 0)
		return true;
	struct stat st;
	bool ok = true;
	if (fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && st.st_size > 0) {
		size_t len = (size_t)st.st_size;
		void *map = mmap(NULL, len, PROT_READ, MAP_PRIVATE, fd, 0);
		if (map != MAP_FAILED) {
			const unsigned char *b = map;
			ok = ply_first_line(b, len, path, why, why_len) &&
			     ply_check(map, len, why, why_len) && glb_check(b, len, why, why_len);
			*cut = ok && has_extension(path, "obj") && b[len - 1] != '\n';
			munmap(map, len);
		}
	}
	close(fd);
	return ok;
}

/* ---- Assimp's scene to one triangle mesh -------------------------------------------------------- */

/* Deeper node trees than any exporter writes are refused (the walks below recurse). */
enum { IMPORT_MAX_DEPTH = 256 };

typedef struct count_state {
	size_t nv, nt;
	bool normals, uvs, tangents;
	char *why; /* the reason when the scene is refused */
	size_t why_len;
} count_state;

/* Checks what Assimp's steps and fill_node read of one mesh: arrays present, every face of at
 * least one index (at most max_corners: 3 once triangulated), each index inside the mesh. */
static bool mesh_ok(const struct aiMesh *m, unsigned mi, unsigned max_corners, char *why, size_t why_len)
{
	if ((m->mNumVertices && !m->mVertices) || (m->mNumFaces && !m->mFaces)) {
		snprintf(why, why_len, "mesh %u lacks its vertex or face array", mi);
		return false;
	}
	for (unsigned k = 0; k < m->mNumFaces; k++) {
		const struct aiFace *fc = &m->mFaces[k];
		if (!fc->mNumIndices || fc->mNumIndices > max_corners || !fc->mIndices) {
			snprintf(why, why_len, "mesh %u, face %u has %u corners", mi, k, fc->mNumIndices);
			return false;
		}
		for (unsigned j = 0; j < fc->mNumIndices; j++)
			if (fc->mIndices[j] >= m->mNumVertices) {
				snprintf(why, why_len,
					 "mesh %u, face %u: vertex index %u out of range (the mesh has %u)",
					 mi, k, fc->mIndices[j], m->mNumVertices);
				return false;
			}
	}
	return true;
}

/* The loader's meshes, before any of Assimp's steps reads them: Triangulate and
 * JoinIdenticalVertices index the vertex arrays without checking (a PLY face `3 0 1 7` on three
 * vertices is read out of bounds). */
static bool raw_ok(const struct aiScene *s, char *why, size_t why_len)
{
	if (s->mNumMeshes && !s->mMeshes) {
		snprintf(why, why_len, "the file's mesh list is missing");
		return false;
	}
	for (unsigned i = 0; i < s->mNumMeshes; i++) {
		if (!s->mMeshes[i]) {
			snprintf(why, why_len, "mesh %u is missing", i);
			return false;
		}
		if (!mesh_ok(s->mMeshes[i], i, UINT32_MAX, why, why_len))
			return false;
	}
	return true;
}

/* Counts the triangles and vertices the node tree will produce (meshes may be instanced by
 * several nodes), checking every mesh it uses. */
static bool count_node(const struct aiScene *s, const struct aiNode *nd, int depth, count_state *c)
{
	if (depth > IMPORT_MAX_DEPTH) {
		snprintf(c->why, c->why_len, "the node tree is deeper than %d", IMPORT_MAX_DEPTH);
		return false;
	}
	for (unsigned i = 0; i < nd->mNumMeshes; i++) {
		if (!nd->mMeshes || nd->mMeshes[i] >= s->mNumMeshes || !s->mMeshes[nd->mMeshes[i]]) {
			snprintf(c->why, c->why_len, "a node names mesh %u of %u",
				 nd->mMeshes ? nd->mMeshes[i] : 0, s->mNumMeshes);
			return false;
		}
		const struct aiMesh *m = s->mMeshes[nd->mMeshes[i]];
		if (!(m->mPrimitiveTypes & aiPrimitiveType_TRIANGLE))
			continue;
		if (!mesh_ok(m, nd->mMeshes[i], 3, c->why, c->why_len))
			return false;
		c->nv += m->mNumVertices;
		c->nt += m->mNumFaces;
		c->normals = c->normals && m->mNormals;
		c->uvs = c->uvs && m->mTextureCoords[0];
		c->tangents = c->tangents && m->mTangents && m->mBitangents;
	}
	for (unsigned i = 0; i < nd->mNumChildren; i++)
		if (!nd->mChildren[i] || !count_node(s, nd->mChildren[i], depth + 1, c))
			return false;
	return true;
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
	size_t bad_positions;	     /* not finite, or beyond MESH_MAX_COORD */
	struct aiVector3D first_bad; /* the first such vertex, as the file has it */
	size_t bad_normals;	     /* not finite or zero */
	size_t bad_tangents;	     /* not finite or zero */
	size_t bad_uvs;		     /* not finite: replaced by (0, 0) */
} fill_state;

static bool position_ok(vec3 p)
{
	return fabsf(p.x) <= MESH_MAX_COORD && fabsf(p.y) <= MESH_MAX_COORD && fabsf(p.z) <= MESH_MAX_COORD;
}

/* A unit direction: finite and not zero before normalising. */
static bool direction_ok(vec3 v)
{
	return v3_is_finite(v) && v3_length2(v) > 0.0f;
}

static void fill_vertex(const struct aiMesh *m, unsigned k, const xform *here, fill_state *st)
{
	mesh *o = st->out;
	const struct aiVector3D *p = &m->mVertices[k];
	vec3 pos = d3_to_v3(xform_point(here, d3(p->x, p->y, p->z)));
	o->positions[st->v] = pos;
	if (!position_ok(pos) && !st->bad_positions++)
		st->first_bad = *p;
	if (o->normals) {
		const struct aiVector3D *n = &m->mNormals[k];
		vec3 nw = d3_to_v3(xform_normal(here, d3(n->x, n->y, n->z)));
		st->bad_normals += !direction_ok(nw);
		o->normals[st->v] = v3_normalize(nw);
	}
	if (o->uvs) {
		vec2 uv = v2(m->mTextureCoords[0][k].x, m->mTextureCoords[0][k].y);
		if (!isfinite(uv.x) || !isfinite(uv.y))
			uv = v2(0, 0), st->bad_uvs++;
		o->uvs[st->v] = uv;
	}
	if (o->tangents) {
		const struct aiVector3D *t = &m->mTangents[k], *b = &m->mBitangents[k];
		vec3 tw = d3_to_v3(xform_vector(here, d3(t->x, t->y, t->z)));
		vec3 bw = d3_to_v3(xform_vector(here, d3(b->x, b->y, b->z)));
		st->bad_tangents += !direction_ok(tw) || !v3_is_finite(bw);
		tw = v3_normalize(tw);
		vec3 n = o->normals ? o->normals[st->v] : v3(0, 0, 1);
		o->tangents[st->v] = (mesh_tangent){tw, v3_dot(v3_cross(n, tw), bw) < 0 ? -1.0f : 1.0f};
	}
}

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
		for (unsigned k = 0; k < m->mNumVertices; k++, st->v++)
			fill_vertex(m, k, &here, st);
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

/* The file's attributes that cannot be used: positions refuse the file; normals, tangents and
 * UVs are dropped or zeroed with a warning. */
static bool check_values(const char *path, mesh *out, const fill_state *st, diag *d)
{
	if (st->bad_positions) {
		const struct aiVector3D *p = &st->first_bad;
		diag_file_error(d, path,
				"vertex coordinates must be finite and at most %g in magnitude (after the file's "
				"transforms): %zu of %u vertices are not, the first <%g, %g, %g>",
				(double)MESH_MAX_COORD, st->bad_positions, out->num_vertices, (double)p->x,
				(double)p->y, (double)p->z);
		return false;
	}
	if (st->bad_normals) {
		diag_file_warning(d, path,
				  "%zu normals are zero or not finite: the file's normals are ignored",
				  st->bad_normals);
		mem_free(out->normals), out->normals = NULL;
		mem_free(out->tangents), out->tangents = NULL;
	} else if (st->bad_tangents) {
		diag_file_warning(d, path,
				  "%zu tangents are zero or not finite: the file's tangents are ignored",
				  st->bad_tangents);
		mem_free(out->tangents), out->tangents = NULL;
	}
	if (st->bad_uvs)
		diag_file_warning(d, path, "%zu texture coordinates are not finite: they are set to 0",
				  st->bad_uvs);
	return true;
}

/* Exact duplicate triangles removed, with a warning: duplicated faces are common in exports, and
 * subsurface scattering by circles would see the surface once per copy. */
static bool remove_duplicates(const char *path, mesh *out, diag *d)
{
	uint32_t before = out->num_triangles;
	size_t removed = mesh_remove_duplicate_triangles(out);
	if (removed == SIZE_MAX) {
		diag_file_error(d, path, "out of memory looking for duplicate triangles");
		return false;
	}
	if (removed)
		diag_file_warning(
		    d, path,
		    "%zu of its %u triangles duplicate an earlier one (the same three corners): removed",
		    removed, before);
	return true;
}

bool mesh_import(const char *path, mesh *out, diag *d)
{
	memset(out, 0, sizeof *out);
	char why[256];
	bool cut;
	if (!precheck(path, why, sizeof why, &cut)) {
		diag_file_error(d, path, "cannot import mesh: %s", why);
		return false;
	}
	/* Read with no steps, checked, then triangulated and welded (raw_ok says why in that order). */
	const struct aiScene *s = aiImportFile(path, 0);
	if (!s) {
		diag_file_error(d, path, "cannot import mesh: %s", aiGetErrorString());
		return false;
	}
	if (!raw_ok(s, why, sizeof why)) {
		diag_file_error(d, path, "cannot import mesh: %s", why);
		aiReleaseImport(s);
		return false;
	}
	s = aiApplyPostProcessing(s, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices |
					 aiProcess_SortByPType);
	if (!s) { /* already released */
		diag_file_error(d, path, "cannot import mesh: %s", aiGetErrorString());
		return false;
	}
	if (cut)
		diag_file_warning(d, path,
				  "the file's last line has no line end: a truncated file? (only what is "
				  "there is imported)");
	bool ok = false;
	count_state c = {0, 0, true, true, true, why, sizeof why};
	if (s->mRootNode && !count_node(s, s->mRootNode, 0, &c)) {
		diag_file_error(d, path, "cannot import mesh: %s", why);
	} else if (c.nt == 0) {
		diag_file_error(d, path, "the file holds no triangles");
	} else if (c.nv > UINT32_MAX || c.nt > UINT32_MAX / 3) {
		diag_file_error(d, path, "too many vertices or triangles (%zu, %zu; the limit is %u)", c.nv,
				c.nt, UINT32_MAX / 3);
	} else if (!mesh_alloc(out, c.nv, c.nt, c.normals, c.uvs, c.tangents && c.normals)) {
		diag_file_error(d, path, "out of memory for %zu vertices and %zu triangles", c.nv, c.nt);
	} else {
		fill_state st = {.out = out};
		fill_node(s, s->mRootNode, xform_identity(), &st);
		ok = check_values(path, out, &st, d) && remove_duplicates(path, out, d);
		if (!ok)
			mesh_free(out);
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
	bool cut;
	if (!precheck(path, ply_why, sizeof ply_why, &cut)) {
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
