/* cage.c - cage files: circe's OBJ reader (polygons and OpenSubdiv's `t` tags, which Assimp
 * drops), and the welding every format goes through. Why OBJ is read here and not by Assimp: see
 * cage.h. */
#include "geom/cage.h"

#include <assert.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* The largest count of vertices, faces or corners a cage may have: indices are 32-bit. */
#define CAGE_MAX_COUNT (UINT32_MAX - 1u)

/* A reader's context: where errors go and what they name. */
typedef struct cage_ctx {
	const char *path;
	diag *d;
	diag_loc loc;
} cage_ctx;

/* Reports "cage file 'PATH', line N: reason" (line 0: no line) at the scene's place; false. */
static bool cage_fail(const cage_ctx *x, uint32_t line, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
static bool cage_fail(const cage_ctx *x, uint32_t line, const char *fmt, ...)
{
	char why[512];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(why, sizeof why, fmt, ap);
	va_end(ap);
	if (line)
		diag_error(x->d, x->loc, "cage file '%s', line %u: %s", x->path, line, why);
	else
		diag_error(x->d, x->loc, "cage file '%s': %s", x->path, why);
	return false;
}

static bool cage_oom(const cage_ctx *x)
{
	return cage_fail(x, 0, "out of memory");
}

/* ---- tags (OpenSubdiv's shape format: `t NAME nints/nfloats/nstrings ints floats strings`) ---- */

/* The tags of a file, in the file's vertex numbers, applied once the cage is welded. */
typedef struct cage_tags {
	vecbuf creases; /* cage_tag_edge */
	vecbuf corners; /* cage_tag_vertex */
	vecbuf holes;	/* cage_tag_vertex, sharpness unused */
	bool has_boundary;
	subd_boundary boundary;
} cage_tags;

typedef struct cage_tag_edge {
	uint32_t a, b, line;
	float sharpness;
} cage_tag_edge;

typedef struct cage_tag_vertex {
	uint32_t v, line;
	float sharpness;
} cage_tag_vertex;

/* The most arguments one tag line may carry (a crease chain of a large cage fits). */
#define CAGE_MAX_TAG_ARGS 65536

/* Skips blanks; true when something other than the end of the line follows. */
static bool more(const char **p)
{
	while (**p == ' ' || **p == '\t')
		(*p)++;
	return **p && **p != '\n' && **p != '\r';
}

/* A sharpness read from a tag: finite and not negative. */
static bool tag_sharpness(const cage_ctx *x, uint32_t line, const char *what, double s)
{
	if (!(s >= 0.0) || !isfinite(s))
		return cage_fail(x, line, "%s sharpness %g must be a finite number >= 0", what, s);
	return true;
}

/* The argument counts `ints/floats/strings` after a tag's name; *p moves past them. */
static bool tag_counts(const cage_ctx *x, const char **p, uint32_t line, const char *name, long *ni, long *nf)
{
	char *end;
	more(p);
	*ni = strtol(*p, &end, 10);
	if (end == *p || *end != '/')
		return cage_fail(x, line, "tag '%s': expected the argument counts 'ints/floats/strings'",
				 name);
	*p = end + 1;
	*nf = strtol(*p, &end, 10);
	if (end == *p || *end != '/')
		return cage_fail(x, line, "tag '%s': expected the argument counts 'ints/floats/strings'",
				 name);
	*p = end + 1;
	long ns = strtol(*p, &end, 10);
	if (end == *p || *ni < 0 || *nf < 0 || ns < 0 || *ni > CAGE_MAX_TAG_ARGS || *nf > CAGE_MAX_TAG_ARGS)
		return cage_fail(x, line, "tag '%s': bad argument counts", name);
	*p = end;
	return true;
}

/* A known tag's arguments, read, into t. */
static bool apply_tag(const cage_ctx *x, uint32_t line, const char *name, const long *ints, long ni,
		      const double *floats, long nf, cage_tags *t)
{
	bool ok = true;
	if (!strcmp(name, "crease")) {
		if (ni < 2 || ni % 2 || (nf != 1 && nf != ni / 2))
			ok = cage_fail(
			    x, line,
			    "tag 'crease' needs pairs of vertices and one sharpness, or one per pair "
			    "(found %ld/%ld)",
			    ni, nf);
		for (long i = 0; ok && i < ni; i += 2) {
			double s = floats[nf == 1 ? 0 : i / 2];
			cage_tag_edge e = {(uint32_t)ints[i], (uint32_t)ints[i + 1], line, (float)s};
			ok = tag_sharpness(x, line, "crease", s) &&
			     (vecbuf_push(&t->creases, &e) || cage_oom(x));
		}
	} else if (!strcmp(name, "corner")) {
		if (ni < 1 || (nf != 1 && nf != ni))
			ok = cage_fail(x, line,
				       "tag 'corner' needs vertices and one sharpness, or one per vertex "
				       "(found %ld/%ld)",
				       ni, nf);
		for (long i = 0; ok && i < ni; i++) {
			double s = floats[nf == 1 ? 0 : i];
			cage_tag_vertex v = {(uint32_t)ints[i], line, (float)s};
			ok = tag_sharpness(x, line, "corner", s) &&
			     (vecbuf_push(&t->corners, &v) || cage_oom(x));
		}
	} else if (!strcmp(name, "hole")) {
		for (long i = 0; ok && i < ni; i++) {
			cage_tag_vertex h = {(uint32_t)ints[i], line, 0.0f};
			ok = vecbuf_push(&t->holes, &h) || cage_oom(x);
		}
	} else { /* interpolateboundary */
		if (ni != 1 || (ints[0] != 1 && ints[0] != 2))
			ok =
			    cage_fail(x, line,
				      "tag 'interpolateboundary' takes 1 (edge_and_corner) or 2 (edge_only); "
				      "circe has no rule %ld",
				      ni == 1 ? ints[0] : -1L);
		else
			t->has_boundary = true,
			t->boundary = ints[0] == 1 ? SUBD_BOUNDARY_EDGE_AND_CORNER : SUBD_BOUNDARY_EDGE_ONLY;
	}
	return ok;
}

/* `t crease n/m/0 a b [c d ...] s [s ...]`: pairs of vertices (zero-based) with one sharpness
 * for all or one per pair; `t corner n/m/0 v... s...`: vertices; `t hole n/0/0 f...`: faces;
 * `t interpolateboundary 1/0/0 r`: 1 edge_and_corner, 2 edge_only. Others are ignored with a
 * warning. */
static bool parse_tag(const cage_ctx *x, const char *p, uint32_t line, cage_tags *t)
{
	char name[64];
	int n = 0;
	if (!more(&p) || sscanf(p, "%63s%n", name, &n) != 1)
		return cage_fail(x, line, "a 't' line needs a tag name");
	p += n;
	long ni = 0, nf = 0;
	if (!tag_counts(x, &p, line, name, &ni, &nf))
		return false;
	bool known = !strcmp(name, "crease") || !strcmp(name, "corner") || !strcmp(name, "hole") ||
		     !strcmp(name, "interpolateboundary");
	if (!known) {
		diag_warning(x->d, x->loc,
			     "cage file '%s', line %u: tag '%s' is not supported by circe; ignored", x->path,
			     line, name);
		return true;
	}
	long *ints = mem_alloc((size_t)ni + 1, sizeof *ints);
	double *floats = mem_alloc((size_t)nf + 1, sizeof *floats);
	bool ok = ints && floats;
	if (!ok)
		cage_oom(x);
	char *end;
	for (long i = 0; ok && i < ni; i++) {
		more(&p);
		ints[i] = strtol(p, &end, 10);
		if (end == p || ints[i] < 0 || ints[i] > (long)CAGE_MAX_COUNT)
			ok = cage_fail(x, line,
				       "tag '%s': integer argument %ld of %ld missing or out of range", name,
				       i + 1, ni);
		p = end;
	}
	for (long i = 0; ok && i < nf; i++) {
		more(&p);
		floats[i] = strtod(p, &end);
		if (end == p)
			ok = cage_fail(x, line, "tag '%s': number argument %ld of %ld missing", name, i + 1,
				       nf);
		p = end;
	}
	ok = ok && apply_tag(x, line, name, ints, ni, floats, nf, t);
	mem_free(ints), mem_free(floats);
	return ok;
}

/* ---- the OBJ reader ------------------------------------------------------------------------- */

/* The whole file, NUL-terminated; NULL after reporting. */
static char *read_file(const cage_ctx *x, size_t *len)
{
	FILE *f = fopen(x->path, "rb");
	if (!f) {
		cage_fail(x, 0, "cannot open it: %s", strerror(errno));
		return NULL;
	}
	size_t cap = 1 << 16, n = 0;
	char *buf = mem_alloc(cap, 1);
	while (buf) {
		n += fread(buf + n, 1, cap - 1 - n, f);
		if (n < cap - 1)
			break;
		char *nb = cap <= SIZE_MAX / 2 ? mem_realloc(buf, cap * 2, 1) : NULL;
		if (!nb)
			mem_free(buf);
		buf = nb, cap *= 2;
	}
	bool err = ferror(f);
	int e = errno;
	fclose(f);
	if (!buf) {
		cage_oom(x);
		return NULL;
	}
	if (err) {
		mem_free(buf);
		cage_fail(x, 0, "cannot read it: %s", strerror(e));
		return NULL;
	}
	buf[n] = '\0';
	*len = n;
	return buf;
}

/* A number of an OBJ statement; false when none is there. */
static bool obj_number(const char **p, double *v)
{
	char *end;
	if (!more(p))
		return false;
	*v = strtod(*p, &end);
	if (end == *p || (*end && *end != ' ' && *end != '\t' && *end != '\n' && *end != '\r'))
		return false;
	*p = end;
	return true;
}

/* An OBJ index (1-based, or negative: relative to the count so far) made zero-based. */
static bool obj_index(const cage_ctx *x, uint32_t line, const char **p, size_t count, const char *what,
		      uint32_t *out)
{
	char *end;
	long long v = strtoll(*p, &end, 10);
	if (end == *p)
		return cage_fail(x, line, "expected a %s index in 'f'", what);
	*p = end;
	if (v == 0)
		return cage_fail(x, line, "%s index 0 (OBJ indices start at 1)", what);
	if (v < 0) {
		unsigned long long back = 0ULL - (unsigned long long)v; /* -v, defined for LLONG_MIN too */
		if (back > count)
			return cage_fail(x, line, "relative %s index %lld reaches before the first %s", what,
					 v, what);
		*out = (uint32_t)(count - (size_t)back);
	} else {
		if (v > (long long)CAGE_MAX_COUNT)
			return cage_fail(x, line, "%s index %lld out of range", what, v);
		*out = (uint32_t)(v - 1); /* checked against the final count once the file is read */
	}
	return true;
}

/* `f v[/vt[/vn]] ...`: one polygon. */
static bool obj_face(const cage_ctx *x, uint32_t line, const char *p, cage_raw *r)
{
	uint32_t n = 0;
	while (more(&p)) {
		uint32_t v, t;
		if (!obj_index(x, line, &p, r->positions.len, "vertex", &v))
			return false;
		bool has_uv = false;
		if (*p == '/') {
			p++;
			if (*p != '/' && *p != ' ' && *p != '\t' && *p != '\n' && *p != '\r' && *p) {
				if (!obj_index(x, line, &p, r->uvs.len, "uv", &t))
					return false;
				has_uv = true;
			}
			if (*p == '/') { /* the normal: circe takes the limit surface's */
				p++;
				while (*p && *p != ' ' && *p != '\t' && *p != '\n' && *p != '\r')
					p++;
			}
		}
		if (*p && *p != ' ' && *p != '\t' && *p != '\n' && *p != '\r')
			return cage_fail(x, line, "unexpected '%c' in a face corner", *p);
		if (!vecbuf_push(&r->indices, &v))
			return cage_oom(x);
		if (has_uv && !r->uv_missing) {
			if (!vecbuf_push(&r->uv_indices, &t))
				return cage_oom(x);
		} else {
			r->uv_missing = true;
		}
		n++;
	}
	if (!vecbuf_push(&r->face_sizes, &n) || !vecbuf_push(&r->face_lines, &line))
		return cage_oom(x);
	return true;
}

/* Reads the OBJ text (NUL-terminated) into raw polygons and tags. */
static bool obj_parse(const cage_ctx *x, char *text, cage_raw *r, cage_tags *t)
{
	uint32_t line = 0;
	for (char *p = text; *p;) {
		char *eol = strchr(p, '\n');
		if (eol)
			*eol = '\0';
		line++;
		const char *s = p;
		p = eol ? eol + 1 : p + strlen(p);
		more(&s);
		size_t kw = strcspn(s, " \t\r");
		if (kw == 1 && s[0] == 'v') {
			s += 1;
			double c[3];
			for (int i = 0; i < 3; i++)
				if (!obj_number(&s, &c[i]))
					return cage_fail(x, line, "expected three numbers after 'v'");
			vec3 v = v3((float)c[0], (float)c[1], (float)c[2]);
			if (!isfinite(v.x) || !isfinite(v.y) || !isfinite(v.z))
				return cage_fail(x, line, "vertex %zu is not finite", r->positions.len + 1);
			if (!vecbuf_push(&r->positions, &v))
				return cage_oom(x);
		} else if (kw == 2 && s[0] == 'v' && s[1] == 't') {
			s += 2;
			double u, w = 0.0;
			if (!obj_number(&s, &u))
				return cage_fail(x, line, "expected a number after 'vt'");
			if (more(&s) && !obj_number(&s, &w))
				return cage_fail(x, line,
						 "expected a number as the second coordinate of 'vt'");
			vec2 uv = v2((float)u, (float)w);
			if (!isfinite(uv.x) || !isfinite(uv.y))
				return cage_fail(x, line, "uv %zu is not finite", r->uvs.len + 1);
			if (!vecbuf_push(&r->uvs, &uv))
				return cage_oom(x);
		} else if (kw == 1 && s[0] == 'f') {
			if (!obj_face(x, line, s + 1, r))
				return false;
		} else if (kw == 1 && s[0] == 't') {
			if (!parse_tag(x, s + 1, line, t))
				return false;
		}
		/* Anything else (vn, vp, g, o, s, usemtl, mtllib, l, p, comments) has no part in a cage. */
	}
	return true;
}

/* ---- welding ------------------------------------------------------------------------------- */

/* An open-addressing table from exact keys (positions, or a vertex with a UV) to dense ids. */
typedef struct weld_table {
	uint32_t *slot; /* id + 1, 0: empty */
	size_t mask;
} weld_table;

static bool table_init(weld_table *t, size_t n)
{
	size_t cap = 16;
	while (cap < 2 * n && cap < SIZE_MAX / 4)
		cap *= 2;
	t->slot = mem_calloc(cap, sizeof *t->slot);
	t->mask = cap - 1;
	return t->slot != NULL;
}

/* FNV-1a over the key's bytes. */
static uint64_t hash_bytes(const void *key, size_t len)
{
	const unsigned char *b = key;
	uint64_t h = 1469598103934665603ull;
	for (size_t i = 0; i < len; i++)
		h = (h ^ b[i]) * 1099511628211ull;
	return h;
}

/* The id of key among keys[0 .. *n) (each `len` bytes, stored by the caller at keys + id * len),
 * adding it as id *n when new. */
static uint32_t table_id(weld_table *t, const void *key, size_t len, const unsigned char *keys, uint32_t *n)
{
	for (size_t i = hash_bytes(key, len) & t->mask;; i = (i + 1) & t->mask) {
		uint32_t s = t->slot[i];
		if (!s) {
			t->slot[i] = *n + 1;
			return (*n)++;
		}
		if (!memcmp(keys + (size_t)(s - 1) * len, key, len))
			return s - 1;
	}
}

/* Positions equal as numbers are one vertex: -0 and +0 are the same coordinate. */
static vec3 weld_key(vec3 p)
{
	return v3(p.x + 0.0f, p.y + 0.0f, p.z + 0.0f);
}

typedef struct uv_key {
	uint32_t vertex;
	vec2 uv;
} uv_key;

static int cmp_u64(const void *a, const void *b)
{
	uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
	return x < y ? -1 : x > y;
}

static uint64_t edge_key(uint32_t a, uint32_t b)
{
	return a < b ? (uint64_t)a << 32 | b : (uint64_t)b << 32 | a;
}

bool cage_has_edge(const cage_data *c, uint32_t a, uint32_t b)
{
	uint64_t k = edge_key(a, b);
	return a != b && bsearch(&k, c->edges, c->num_edges, sizeof k, cmp_u64) != NULL;
}

/* Every face has at least three corners, each naming a vertex (and a UV) the file has. */
static bool check_faces(const cage_ctx *x, const cage_raw *r)
{
	size_t nv = r->positions.len, nf = r->face_sizes.len;
	const uint32_t *sizes = r->face_sizes.data, *idx = r->indices.data, *lines = r->face_lines.data;
	size_t k = 0;
	for (size_t f = 0; f < nf; k += sizes[f], f++) {
		if (sizes[f] < 3)
			return cage_fail(x, lines[f], "face %zu has %u vertices; a face needs at least 3", f,
					 sizes[f]);
		for (uint32_t i = 0; i < sizes[f]; i++) {
			if (idx[k + i] >= nv)
				return cage_fail(
				    x, lines[f],
				    "face %zu refers to vertex %u, but the file has %zu vertices", f,
				    idx[k + i] + 1, nv);
			if (!r->uv_missing && ((const uint32_t *)r->uv_indices.data)[k + i] >= r->uvs.len)
				return cage_fail(
				    x, lines[f], "face %zu refers to uv %u, but the file has %zu uvs", f,
				    ((const uint32_t *)r->uv_indices.data)[k + i] + 1, r->uvs.len);
		}
	}
	return true;
}

/* c->weld and c->positions: the file's vertices at equal positions become one, numbered by first
 * occurrence. */
static bool weld_positions(const cage_ctx *x, const cage_raw *r, cage_data *c)
{
	size_t nv = r->positions.len;
	const vec3 *pos = r->positions.data;
	weld_table t = {0};
	if (!table_init(&t, nv))
		return cage_oom(x);
	for (size_t v = 0; v < nv; v++) {
		vec3 key = weld_key(pos[v]);
		uint32_t before = c->num_vertices;
		c->weld[v] =
		    table_id(&t, &key, sizeof key, (const unsigned char *)c->positions, &c->num_vertices);
		if (c->num_vertices != before)
			c->positions[c->weld[v]] = key;
	}
	mem_free(t.slot);
	assert(c->num_vertices <= nv);
	return true;
}

/* c->face_indices in welded numbers; a face that uses one welded vertex twice is an error. */
static bool weld_faces(const cage_ctx *x, const cage_raw *r, cage_data *c)
{
	size_t nv = r->positions.len, nf = r->face_sizes.len;
	const uint32_t *sizes = r->face_sizes.data, *idx = r->indices.data, *lines = r->face_lines.data;
	uint32_t *stamp = mem_calloc(nv, sizeof *stamp); /* the last face + 1 that used each vertex */
	if (!stamp)
		return cage_oom(x);
	bool ok = true;
	size_t k = 0;
	for (size_t f = 0; ok && f < nf; k += sizes[f], f++)
		for (uint32_t i = 0; ok && i < sizes[f]; i++) {
			uint32_t w = c->weld[idx[k + i]];
			assert(w < c->num_vertices);
			if (stamp[w] == f + 1)
				ok = cage_fail(x, lines[f],
					       "face %zu uses vertex %u twice (after welding the vertices at "
					       "equal positions)",
					       f, w);
			stamp[w] = (uint32_t)f + 1;
			c->face_indices[k + i] = w;
		}
	mem_free(stamp);
	return ok;
}

/* UVs: one value per (welded vertex, exact UV), so duplicated corners do not make false seams. */
static bool weld_uvs(const cage_ctx *x, const cage_raw *r, cage_data *c)
{
	size_t ni = r->indices.len;
	const vec2 *uv = r->uvs.data;
	const uint32_t *uidx = r->uv_indices.data;
	uv_key *keys = mem_alloc(ni, sizeof *keys);
	c->uvs = mem_alloc(ni, sizeof *c->uvs);
	c->uv_indices = mem_alloc(ni, sizeof *c->uv_indices);
	weld_table t = {0};
	if (!keys || !c->uvs || !c->uv_indices || !table_init(&t, ni)) {
		mem_free(keys);
		return cage_oom(x);
	}
	for (size_t i = 0; i < ni; i++) {
		uv_key key;
		memset(&key, 0, sizeof key); /* no padding bytes in the compared key */
		key.vertex = c->face_indices[i];
		key.uv = v2(uv[uidx[i]].x + 0.0f, uv[uidx[i]].y + 0.0f);
		uint32_t before = c->num_uvs;
		c->uv_indices[i] = table_id(&t, &key, sizeof key, (const unsigned char *)keys, &c->num_uvs);
		if (c->num_uvs != before)
			keys[c->uv_indices[i]] = key, c->uvs[c->uv_indices[i]] = key.uv;
	}
	mem_free(t.slot), mem_free(keys);
	return true;
}

/* c->edges: the cage's edges, sorted and unique, for the crease checks (cage_has_edge). */
static bool collect_edges(const cage_ctx *x, cage_data *c, size_t ni)
{
	c->edges = mem_alloc(ni, sizeof *c->edges);
	if (!c->edges)
		return cage_oom(x);
	const uint32_t *sizes = c->face_sizes;
	size_t k = 0;
	for (size_t f = 0; f < c->num_faces; k += sizes[f], f++)
		for (uint32_t i = 0; i < sizes[f]; i++)
			c->edges[k + i] =
			    edge_key(c->face_indices[k + i], c->face_indices[k + (i + 1) % sizes[f]]);
	assert(k == ni);
	qsort(c->edges, ni, sizeof *c->edges, cmp_u64);
	for (size_t i = 0; i < ni; i++)
		if (c->num_edges == 0 || c->edges[c->num_edges - 1] != c->edges[i])
			c->edges[c->num_edges++] = c->edges[i];
	return true;
}

/* Welds positions, renumbers UVs, checks faces and collects edges. */
static bool cage_build(const cage_ctx *x, const cage_raw *r, cage_data *c)
{
	size_t nv = r->positions.len, nf = r->face_sizes.len, ni = r->indices.len;
	if (nf == 0)
		return cage_fail(x, 0, "the file has no faces");
	if (nv > CAGE_MAX_COUNT || nf > CAGE_MAX_COUNT || ni > CAGE_MAX_COUNT)
		return cage_fail(x, 0, "too many vertices, faces or face corners (the limit is %u)",
				 CAGE_MAX_COUNT);
	if (!check_faces(x, r))
		return false;
	c->num_file_vertices = (uint32_t)nv;
	c->num_faces = (uint32_t)nf;
	c->weld = mem_alloc(nv, sizeof *c->weld);
	c->positions = mem_alloc(nv, sizeof *c->positions);
	c->face_sizes = mem_alloc(nf, sizeof *c->face_sizes);
	c->face_indices = mem_alloc(ni, sizeof *c->face_indices);
	if (!c->weld || !c->positions || !c->face_sizes || !c->face_indices)
		return cage_oom(x);
	memcpy(c->face_sizes, r->face_sizes.data, nf * sizeof *c->face_sizes);
	if (!weld_positions(x, r, c) || !weld_faces(x, r, c))
		return false;
	if (!r->uv_missing && r->uv_indices.len == ni && !weld_uvs(x, r, c))
		return false;
	return collect_edges(x, c, ni);
}

/* The file's tags in welded numbers, each checked against the cage. */
static bool apply_tags(const cage_ctx *x, const cage_tags *t, cage_data *c)
{
	size_t nc = t->creases.len, nk = t->corners.len, nh = t->holes.len;
	c->crease_vertices = mem_alloc(2 * nc, sizeof *c->crease_vertices);
	c->crease_sharpness = mem_alloc(nc, sizeof *c->crease_sharpness);
	c->corner_vertices = mem_alloc(nk, sizeof *c->corner_vertices);
	c->corner_sharpness = mem_alloc(nk, sizeof *c->corner_sharpness);
	c->hole_faces = mem_alloc(nh, sizeof *c->hole_faces);
	if (!c->crease_vertices || !c->crease_sharpness || !c->corner_vertices || !c->corner_sharpness ||
	    !c->hole_faces)
		return cage_oom(x);
	for (size_t i = 0; i < nc; i++) {
		const cage_tag_edge *e = &VECBUF_AT(&t->creases, cage_tag_edge, i);
		if (e->a >= c->num_file_vertices || e->b >= c->num_file_vertices)
			return cage_fail(
			    x, e->line,
			    "crease <%u, %u>: vertex %u is out of range (the file has %u vertices; "
			    "tags count from 0)",
			    e->a, e->b, e->a >= c->num_file_vertices ? e->a : e->b, c->num_file_vertices);
		uint32_t a = c->weld[e->a], b = c->weld[e->b];
		if (!cage_has_edge(c, a, b))
			return cage_fail(x, e->line, "crease <%u, %u> is not an edge of the cage", e->a,
					 e->b);
		c->crease_vertices[2 * i] = a, c->crease_vertices[2 * i + 1] = b;
		c->crease_sharpness[i] = e->sharpness;
	}
	c->num_creases = (uint32_t)nc;
	for (size_t i = 0; i < nk; i++) {
		const cage_tag_vertex *v = &VECBUF_AT(&t->corners, cage_tag_vertex, i);
		if (v->v >= c->num_file_vertices)
			return cage_fail(x, v->line,
					 "corner vertex %u is out of range (the file has %u vertices; tags "
					 "count from 0)",
					 v->v, c->num_file_vertices);
		c->corner_vertices[i] = c->weld[v->v];
		c->corner_sharpness[i] = v->sharpness;
	}
	c->num_corners = (uint32_t)nk;
	for (size_t i = 0; i < nh; i++) {
		const cage_tag_vertex *h = &VECBUF_AT(&t->holes, cage_tag_vertex, i);
		if (h->v >= c->num_faces)
			return cage_fail(x, h->line,
					 "hole face %u is out of range (the file has %u faces; tags count "
					 "from 0)",
					 h->v, c->num_faces);
		c->hole_faces[i] = h->v;
	}
	c->num_holes = (uint32_t)nh;
	c->has_boundary = t->has_boundary;
	c->boundary = t->boundary;
	return true;
}

static bool has_suffix(const char *path, const char *suffix)
{
	size_t n = strlen(path), m = strlen(suffix);
	return n >= m && !strcasecmp(path + n - m, suffix);
}

bool cage_load(const char *path, cage_data *out, diag *d, diag_loc loc)
{
	memset(out, 0, sizeof *out);
	cage_ctx x = {path, d, loc};
	cage_raw r;
	cage_tags t = {0};
	vecbuf_init(&r.positions, sizeof(vec3));
	vecbuf_init(&r.uvs, sizeof(vec2));
	vecbuf_init(&r.face_sizes, sizeof(uint32_t));
	vecbuf_init(&r.face_lines, sizeof(uint32_t));
	vecbuf_init(&r.indices, sizeof(uint32_t));
	vecbuf_init(&r.uv_indices, sizeof(uint32_t));
	r.uv_missing = false;
	vecbuf_init(&t.creases, sizeof(cage_tag_edge));
	vecbuf_init(&t.corners, sizeof(cage_tag_vertex));
	vecbuf_init(&t.holes, sizeof(cage_tag_vertex));
	bool ok;
	if (has_suffix(path, ".obj")) {
		size_t len;
		char *text = read_file(&x, &len);
		ok = text && obj_parse(&x, text, &r, &t);
		mem_free(text);
	} else {
		/* Assimp's own message for a missing file is less plain than errno's. */
		FILE *f = fopen(path, "rb");
		char buf[256];
		const char *why = NULL;
		ok = f != NULL;
		if (!ok)
			cage_fail(&x, 0, "cannot open it: %s", strerror(errno));
		else
			fclose(f);
		ok = ok && cage_import_assimp(path, &r, buf, sizeof buf, &why);
		if (!ok && why)
			cage_fail(&x, 0, "%s", why);
	}
	if (ok && r.uv_missing && r.uv_indices.len)
		diag_warning(
		    d, loc, "cage file '%s': some face corners have no UV; the cage's UVs are dropped", path);
	ok = ok && cage_build(&x, &r, out) && apply_tags(&x, &t, out);
	vecbuf_free(&r.positions), vecbuf_free(&r.uvs), vecbuf_free(&r.face_sizes);
	vecbuf_free(&r.face_lines), vecbuf_free(&r.indices), vecbuf_free(&r.uv_indices);
	vecbuf_free(&t.creases), vecbuf_free(&t.corners), vecbuf_free(&t.holes);
	if (!ok)
		cage_free(out);
	return ok;
}

void cage_free(cage_data *c)
{
	mem_free(c->positions), mem_free(c->weld), mem_free(c->face_sizes), mem_free(c->face_indices);
	mem_free(c->uvs), mem_free(c->uv_indices), mem_free(c->crease_vertices),
	    mem_free(c->crease_sharpness);
	mem_free(c->corner_vertices), mem_free(c->corner_sharpness), mem_free(c->hole_faces),
	    mem_free(c->edges);
	memset(c, 0, sizeof *c);
}

subd_cage cage_view(const cage_data *c)
{
	return (subd_cage){
	    .positions = c->positions,
	    .num_vertices = c->num_vertices,
	    .face_sizes = c->face_sizes,
	    .num_faces = c->num_faces,
	    .face_indices = c->face_indices,
	    .crease_vertices = c->crease_vertices,
	    .crease_sharpness = c->crease_sharpness,
	    .num_creases = c->num_creases,
	    .corner_vertices = c->corner_vertices,
	    .corner_sharpness = c->corner_sharpness,
	    .num_corners = c->num_corners,
	    .hole_faces = c->hole_faces,
	    .num_holes = c->num_holes,
	    .uvs = c->uvs,
	    .num_uvs = c->num_uvs,
	    .uv_indices = c->uvs ? c->uv_indices : NULL,
	};
}
