// subdiv.cpp - the OpenSubdiv shim: the only C++ in circe. Builds a Far::TopologyRefiner from the
// cage, then per face a Bfr::Surface and a Bfr::Tessellation with the rate of each cage edge, and
// shares the points of cage vertices and edges between faces (OpenSubdiv's bfr_tutorial_2_2) so the
// result is watertight. Every entry point catches C++ exceptions and returns a status to C.
extern "C" {
#include "base/diag.h"
#include "base/mem.h"
#include "geom/mesh.h"
}
#include "geom/subdiv.h"

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/bfr/tessellation.h>
#include <opensubdiv/far/error.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <opensubdiv/far/topologyRefinerFactory.h>

#include <algorithm>
#include <cassert>
#include <cstdarg>
#include <cstdio>
#include <cmath>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <new>
#include <stdexcept>
#include <string>
#include <vector>

using namespace OpenSubdiv;

namespace {

// OpenSubdiv reports through global callbacks; the messages of the current thread's call are
// collected here and turned into diagnostics.
thread_local std::string osd_errors;
std::once_flag callbacks_once;

void on_osd_error(Far::ErrorType, const char *message)
{
	if (!osd_errors.empty())
		osd_errors += "; ";
	osd_errors += message;
}

void on_osd_warning(const char *) {}

void install_callbacks()
{
	std::call_once(callbacks_once, [] {
		Far::SetErrorCallback(on_osd_error);
		Far::SetWarningCallback(on_osd_warning);
	});
}

// The reason a tessellation failed, carried to the C side.
struct subd_failure : std::runtime_error {
	explicit subd_failure(const std::string &m) : std::runtime_error(m) {}
};

std::string format(const char *fmt, ...) __attribute__((format(printf, 1, 2)));
std::string format(const char *fmt, ...)
{
	char buf[512];
	va_list ap;
	va_start(ap, fmt);
	vsnprintf(buf, sizeof buf, fmt, ap);
	va_end(ap);
	return buf;
}

float dist3(const vec3 &a, const vec3 &b)
{
	float x = a.x - b.x, y = a.y - b.y, z = a.z - b.z;
	return std::sqrt(x * x + y * y + z * z);
}

// The tessellation rate of the cage edge (a, b): symmetric in a and b, so both faces of an edge
// agree without looking the edge up.
int edge_rate(const subd_options *opt, const vec3 &a, const vec3 &b)
{
	bool adaptive = opt->camera && opt->max_edge_px > 0.0f;
	if (!adaptive)
		return 1 << opt->level;
	const subd_camera *c = opt->camera;
	int max_rate = opt->max_rate > 0 ? opt->max_rate : SUBD_MAX_RATE;
	// Pixels per unit length at distance 1: the focal length in pixels.
	double focal_px = 0.5 * c->image_height / std::tan(0.5 * c->fov_y_deg * M_PI / 180.0);
	vec3 mid = {0.5f * (a.x + b.x), 0.5f * (a.y + b.y), 0.5f * (a.z + b.z)};
	double dist = std::max((double)dist3(mid, c->position), 1e-6);
	double px = dist3(a, b) * focal_px / dist;
	double rate = std::ceil(px / opt->max_edge_px);
	if (!(rate >= 1.0))
		return 1;
	return rate > max_rate ? max_rate : (int)rate;
}

// Checks the cage's arrays and the options; throws subd_failure naming the problem.
void validate(const subd_cage *cage, const subd_options *opt)
{
	bool adaptive = opt->camera && opt->max_edge_px > 0.0f;
	if (!adaptive && (opt->level < 0 || opt->level > SUBD_MAX_LEVEL))
		throw subd_failure(format("subdivision level %d out of range (0 to %d)", opt->level,
					  SUBD_MAX_LEVEL));
	if (adaptive && (opt->camera->image_height == 0 || !(opt->camera->fov_y_deg > 0.0f) ||
			 !(opt->camera->fov_y_deg < 180.0f)))
		throw subd_failure("adaptive tessellation needs a camera with a field of view in (0, 180) "
				   "degrees and an image height");
	if (cage->num_faces == 0)
		throw subd_failure("the cage has no faces");
	size_t k = 0;
	for (uint32_t f = 0; f < cage->num_faces; f++) {
		uint32_t n = cage->face_sizes[f];
		if (n < 3)
			throw subd_failure(format("face %u has %u vertices (at least 3 needed)", f, n));
		if (cage->scheme == SUBD_LOOP && n != 3)
			throw subd_failure(format("face %u has %u vertices: the loop scheme needs triangles", f, n));
		for (uint32_t i = 0; i < n; i++, k++) {
			if (cage->face_indices[k] >= cage->num_vertices)
				throw subd_failure(format("face %u: vertex index %u out of range (there are %u)", f,
							  cage->face_indices[k], cage->num_vertices));
			if (cage->uvs && cage->uv_indices[k] >= cage->num_uvs)
				throw subd_failure(format("face %u: uv index %u out of range (there are %u)", f,
							  cage->uv_indices[k], cage->num_uvs));
		}
		if (k > (size_t)INT32_MAX)
			throw subd_failure("too many face vertices");
	}
	for (uint32_t v = 0; v < cage->num_vertices; v++) {
		const vec3 &p = cage->positions[v];
		if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
			throw subd_failure(format("vertex %u is not finite", v));
	}
	for (uint32_t c = 0; c < cage->num_corners; c++)
		if (cage->corner_vertices[c] >= cage->num_vertices)
			throw subd_failure(format("corner %u: vertex %u out of range", c, cage->corner_vertices[c]));
	for (uint32_t h = 0; h < cage->num_holes; h++)
		if (cage->hole_faces[h] >= cage->num_faces)
			throw subd_failure(format("hole %u: face %u out of range", h, cage->hole_faces[h]));
}

// Keeps one weight per key: a new key is appended to keys (as its parts) and weights, a key seen
// before has its weight replaced (the later entry holds).
template <typename K>
void keep_last(std::map<K, size_t> &slot, const K &key, const Far::Index *parts, int n_parts, float weight,
	       std::vector<Far::Index> &keys, std::vector<float> &weights)
{
	auto it = slot.find(key);
	if (it != slot.end()) {
		weights[it->second] = weight;
		return;
	}
	slot[key] = weights.size();
	keys.insert(keys.end(), parts, parts + n_parts);
	weights.push_back(weight);
}

// The creases and corners with one entry per edge or vertex, the later sharpness holding (so a
// scene's crease or corner overrides a cage file's).
void unique_tags(const subd_cage *cage, std::vector<Far::Index> &pairs, std::vector<float> &crease_w,
		 std::vector<Far::Index> &corners, std::vector<float> &corner_w)
{
	std::map<std::pair<uint32_t, uint32_t>, size_t> edges;
	for (uint32_t c = 0; c < cage->num_creases; c++) {
		uint32_t a = cage->crease_vertices[2 * c], b = cage->crease_vertices[2 * c + 1];
		Far::Index ab[2] = {(Far::Index)a, (Far::Index)b};
		keep_last(edges, std::make_pair(std::min(a, b), std::max(a, b)), ab, 2, cage->crease_sharpness[c], pairs,
			  crease_w);
	}
	std::map<uint32_t, size_t> vertices;
	for (uint32_t c = 0; c < cage->num_corners; c++) {
		Far::Index v = (Far::Index)cage->corner_vertices[c];
		keep_last(vertices, cage->corner_vertices[c], &v, 1, cage->corner_sharpness[c], corners, corner_w);
	}
}

uint64_t estimate_triangles(const subd_cage *cage, const subd_options *opt)
{
	uint64_t tris = 0;
	size_t k = 0;
	for (uint32_t f = 0; f < cage->num_faces; f++) {
		uint32_t n = cage->face_sizes[f];
		uint64_t r = 1;
		for (uint32_t i = 0; i < n; i++) {
			const vec3 &a = cage->positions[cage->face_indices[k + i]];
			const vec3 &b = cage->positions[cage->face_indices[k + (i + 1) % n]];
			r = std::max<uint64_t>(r, (uint64_t)edge_rate(opt, a, b));
		}
		k += n;
		if (n == 3)
			tris += r * r + 3 * r;
		else if (n == 4)
			tris += 2 * r * r + 4 * r;
		else // an n-gon: n sub-quads at half the rate
			tris += n * (2 * (r / 2 + 1) * (r / 2 + 1) + 2 * r);
	}
	return tris;
}

struct shared_edge {
	int first_point = -1; // index in the point table of the first interior edge point
	uint32_t start_vertex = 0; // cage vertex the points run from
};

// Evaluates position and limit normal at uv; where the derivatives are degenerate (some
// extraordinary corners), the normal is taken a little inside the face.
void eval_point(const Bfr::Surface<float> &s, const std::vector<float> &patch, const float uv[2],
		float pos[3], float nrm[3])
{
	float du[3], dv[3];
	s.Evaluate(uv, patch.data(), 3, pos, du, dv);
	for (int attempt = 0; attempt < 3; attempt++) {
		float n[3] = {du[1] * dv[2] - du[2] * dv[1], du[2] * dv[0] - du[0] * dv[2],
			      du[0] * dv[1] - du[1] * dv[0]};
		float l = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
		if (l > 0.0f && std::isfinite(l)) {
			for (int i = 0; i < 3; i++)
				nrm[i] = n[i] / l;
			return;
		}
		float centre[2], p[3], w = attempt == 0 ? 1e-4f : attempt == 1 ? 1e-2f : 0.1f;
		s.GetParameterization().GetCenterCoord(centre);
		float in[2] = {uv[0] + w * (centre[0] - uv[0]), uv[1] + w * (centre[1] - uv[1])};
		s.Evaluate(in, patch.data(), 3, p, du, dv);
	}
	nrm[0] = nrm[1] = 0.0f, nrm[2] = 1.0f;
}

// The estimated size of the result against the memory limit; returns the triangle estimate.
uint64_t check_budget(const subd_cage *cage, const subd_options *opt)
{
	size_t max_bytes = opt->max_bytes ? opt->max_bytes : SUBD_DEFAULT_MAX_BYTES;
	uint64_t est = estimate_triangles(cage, opt);
	if (est > UINT32_MAX / 3 || est * SUBD_BYTES_PER_TRIANGLE > max_bytes)
		throw subd_failure(format("the tessellation would need about %llu triangles and %.1f MiB, over the "
					  "limit of %.1f MiB (lower the level or max_edge, or raise --max-memory)",
					  (unsigned long long)est, est * (double)SUBD_BYTES_PER_TRIANGLE / 1048576.0,
					  max_bytes / 1048576.0));
	return est;
}

// The cage's topology as OpenSubdiv's refiner: faces, creases and corners (one entry each),
// holes, face-varying UVs, the boundary rule and the scheme. Every crease must be a cage edge.
std::unique_ptr<Far::TopologyRefiner> make_refiner(const subd_cage *cage)
{
	std::vector<int> sizes(cage->face_sizes, cage->face_sizes + cage->num_faces);
	size_t nidx = 0;
	for (int s : sizes)
		nidx += (size_t)s;
	std::vector<Far::Index> verts(cage->face_indices, cage->face_indices + nidx);
	std::vector<Far::Index> crease_pairs, corners;
	std::vector<float> crease_weights, corner_weights;
	unique_tags(cage, crease_pairs, crease_weights, corners, corner_weights);
	std::vector<Far::Index> holes(cage->hole_faces, cage->hole_faces + cage->num_holes);
	std::vector<Far::Index> uv_idx;
	Far::TopologyDescriptor desc;
	desc.numVertices = (int)cage->num_vertices;
	desc.numFaces = (int)cage->num_faces;
	desc.numVertsPerFace = sizes.data();
	desc.vertIndicesPerFace = verts.data();
	desc.numCreases = (int)crease_weights.size();
	desc.creaseVertexIndexPairs = crease_pairs.data();
	desc.creaseWeights = crease_weights.data();
	desc.numCorners = (int)corner_weights.size();
	desc.cornerVertexIndices = corners.data();
	desc.cornerWeights = corner_weights.data();
	desc.numHoles = (int)holes.size();
	desc.holeIndices = holes.data();
	Far::TopologyDescriptor::FVarChannel channel;
	if (cage->uvs) {
		uv_idx.assign(cage->uv_indices, cage->uv_indices + nidx);
		channel.numValues = (int)cage->num_uvs;
		channel.valueIndices = uv_idx.data();
		desc.numFVarChannels = 1;
		desc.fvarChannels = &channel;
	}
	Sdc::Options sdc;
	sdc.SetVtxBoundaryInterpolation(cage->boundary == SUBD_BOUNDARY_EDGE_AND_CORNER
						? Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER
						: Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
	sdc.SetFVarLinearInterpolation(Sdc::Options::FVAR_LINEAR_CORNERS_ONLY);
	Sdc::SchemeType scheme = cage->scheme == SUBD_LOOP ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK;
	typedef Far::TopologyRefinerFactory<Far::TopologyDescriptor> Factory;
	osd_errors.clear();
	std::unique_ptr<Far::TopologyRefiner> refiner(Factory::Create(desc, Factory::Options(scheme, sdc)));
	if (!refiner)
		throw subd_failure("invalid cage topology" + (osd_errors.empty() ? std::string() : ": " + osd_errors));
	const Far::TopologyLevel &base = refiner->GetLevel(0);
	for (size_t c = 0; c < crease_weights.size(); c++) {
		Far::Index a = crease_pairs[2 * c], b = crease_pairs[2 * c + 1];
		if (a < 0 || b < 0 || a >= desc.numVertices || b >= desc.numVertices ||
		    base.FindEdge(a, b) == Far::INDEX_INVALID)
			throw subd_failure(format("crease %zu: vertices %d and %d are not an edge of the cage", c, a, b));
	}
	return refiner;
}

// The mesh being made, face after face, and the scratch each face reuses.
struct tessellator {
	const subd_cage *cage;
	const subd_options *opt;
	const Far::TopologyLevel &base;
	bool uvs;
	// Shared points (cage vertices and edge interiors): position and normal. Without UVs they are
	// the output vertices themselves, and interior points are appended to the same table.
	std::vector<float> ppos, pnrm;
	std::vector<float> opos, onrm, ouv; // output vertices (UV mode only)
	std::vector<uint32_t> tris;
	std::vector<int> shared_vertex;		 // point-table index of each cage vertex, -1: none yet
	std::vector<shared_edge> shared_edges; // per cage edge
	Bfr::Surface<float> psurf, uvsurf;
	std::vector<float> patch, uvpatch, coords;
	std::vector<int> facets, point_of; // point_of: point-table index of each coord (boundary)
	std::vector<int> rates;

	tessellator(const subd_cage *c, const subd_options *o, const Far::TopologyLevel &b)
	    : cage(c), opt(o), base(b), uvs(c->uvs != nullptr), shared_vertex(c->num_vertices, -1),
	      shared_edges((size_t)b.GetNumEdges())
	{
	}

	// A point of the current face's surface at uv, appended to the point table; its index.
	int new_point(const float uv[2])
	{
		float p[3], n[3];
		eval_point(psurf, patch, uv, p, n);
		ppos.insert(ppos.end(), p, p + 3);
		pnrm.insert(pnrm.end(), n, n + 3);
		return (int)(ppos.size() / 3 - 1);
	}

	// point_of for the nb boundary coords: for each face vertex its point, then the points of
	// the edge to the next, made by the first face to reach them and reused (reversed when the
	// edge runs the other way) by the second.
	void share_boundary(Far::ConstIndexArray fv, Far::ConstIndexArray fe, int nb, int face)
	{
		int n = fv.size();
		point_of.assign(nb, -1);
		int b = 0;
		for (int i = 0; i < n; i++) {
			Far::Index v = fv[i];
			if (shared_vertex[v] < 0)
				shared_vertex[v] = new_point(&coords[2 * b]);
			point_of[b++] = shared_vertex[v];
			int inner = rates[i] - 1;
			shared_edge &se = shared_edges[fe[i]];
			if (inner > 0 && se.first_point < 0) {
				se.first_point = (int)(ppos.size() / 3);
				se.start_vertex = (uint32_t)v;
				for (int j = 0; j < inner; j++)
					new_point(&coords[2 * (b + j)]);
			}
			for (int j = 0; j < inner; j++, b++)
				point_of[b] = (uint32_t)v == se.start_vertex ? se.first_point + j
									       : se.first_point + inner - 1 - j;
		}
		if (b != nb)
			throw subd_failure(format("face %d: unexpected tessellation boundary", face));
	}

	// point_of extended to all nc coords, each the index of its output vertex: without UVs the
	// interior points join the point table; with UVs every coord gets an output vertex of its own
	// (the boundary ones copied from the shared points) with the UV evaluated there.
	void face_vertices(int nb, int nc)
	{
		std::vector<int> &local = point_of;
		local.resize(nc);
		if (!uvs) {
			for (int c = nb; c < nc; c++)
				local[c] = new_point(&coords[2 * c]);
			return;
		}
		for (int c = 0; c < nc; c++) {
			float p[3], nn[3], t[2];
			if (c < nb) {
				std::memcpy(p, &ppos[3 * (size_t)local[c]], sizeof p);
				std::memcpy(nn, &pnrm[3 * (size_t)local[c]], sizeof nn);
			} else {
				eval_point(psurf, patch, &coords[2 * c], p, nn);
			}
			uvsurf.Evaluate(&coords[2 * c], uvpatch.data(), 2, t);
			local[c] = (int)(opos.size() / 3);
			opos.insert(opos.end(), p, p + 3);
			onrm.insert(onrm.end(), nn, nn + 3);
			ouv.insert(ouv.end(), t, t + 2);
		}
	}

	// One cage face: its surfaces, a tessellation at its edges' rates, its points and triangles.
	void face(const Bfr::RefinerSurfaceFactory<> &factory, const Bfr::Tessellation::Options &topts, int face)
	{
		bool ok = uvs ? factory.InitSurfaces(face, &psurf, &uvsurf) : factory.InitVertexSurface(face, &psurf);
		if (!ok || !psurf.IsValid())
			return; // a hole, or a boundary face without a limit surface
		Far::ConstIndexArray fv = base.GetFaceVertices(face), fe = base.GetFaceEdges(face);
		int n = fv.size();
		rates.resize(n);
		for (int i = 0; i < n; i++)
			rates[i] = edge_rate(opt, cage->positions[fv[i]], cage->positions[fv[(i + 1) % n]]);
		Bfr::Tessellation tess(psurf.GetParameterization(), n, rates.data(), topts);
		if (!tess.IsValid())
			throw subd_failure(format("face %d cannot be tessellated", face));
		int nc = tess.GetNumCoords(), nb = tess.GetNumBoundaryCoords();
		coords.resize(2 * (size_t)nc);
		tess.GetCoords(coords.data());
		patch.resize((size_t)psurf.GetNumPatchPoints() * 3);
		psurf.PreparePatchPoints(&cage->positions[0].x, 3, patch.data(), 3);
		if (uvs) {
			uvpatch.resize((size_t)uvsurf.GetNumPatchPoints() * 2);
			uvsurf.PreparePatchPoints(&cage->uvs[0].x, 2, uvpatch.data(), 2);
		}
		share_boundary(fv, fe, nb, face);
		face_vertices(nb, nc);
		int nf = tess.GetNumFacets();
		facets.resize(3 * (size_t)nf);
		tess.GetFacets(facets.data());
		for (int k = 0; k < 3 * nf; k++) {
			assert(facets[k] >= 0 && facets[k] < nc);
			tris.push_back((uint32_t)point_of[facets[k]]);
		}
	}

	// The finished vertices and triangles copied into out.
	void copy_to(mesh *out) const
	{
		const std::vector<float> &vp = uvs ? opos : ppos, &vn = uvs ? onrm : pnrm;
		size_t nv = vp.size() / 3, nt = tris.size() / 3;
		if (!mesh_alloc(out, nv, nt, true, uvs, false))
			throw std::bad_alloc();
		std::memcpy(out->positions, vp.data(), nv * sizeof(vec3));
		std::memcpy(out->normals, vn.data(), nv * sizeof(vec3));
		if (uvs)
			std::memcpy(out->uvs, ouv.data(), nv * sizeof(vec2));
		std::memcpy(out->indices, tris.data(), tris.size() * sizeof(uint32_t));
	}
};

void tessellate(const subd_cage *cage, const subd_options *opt, mesh *out)
{
	validate(cage, opt);
	uint64_t est = check_budget(cage, opt);
	std::unique_ptr<Far::TopologyRefiner> refiner = make_refiner(cage);
	typedef Bfr::RefinerSurfaceFactory<> SurfaceFactory;
	SurfaceFactory::Options fopts;
	if (cage->uvs)
		fopts.SetDefaultFVarID(0);
	SurfaceFactory factory(*refiner, fopts);
	Bfr::Tessellation::Options topts;
	topts.SetFacetSize(3);
	tessellator t(cage, opt, refiner->GetLevel(0));
	t.tris.reserve((size_t)est * 3);
	for (int face = 0; face < factory.GetNumFaces(); face++)
		t.face(factory, topts, face);
	if (!osd_errors.empty())
		throw subd_failure(osd_errors);
	t.copy_to(out);
}

} // namespace

extern "C" uint64_t subd_estimate(const subd_cage *cage, const subd_options *opt, uint64_t *bytes)
{
	*bytes = 0;
	try {
		validate(cage, opt);
		uint64_t t = estimate_triangles(cage, opt);
		*bytes = t * SUBD_BYTES_PER_TRIANGLE;
		return t;
	} catch (...) {
		return 0;
	}
}

extern "C" bool subd_tessellate(const subd_cage *cage, const subd_options *opt, mesh *out, diag *d,
				diag_loc loc)
{
	std::memset(out, 0, sizeof *out);
	install_callbacks();
	// "subdivision surface" or "subdivision surface of 'cage.obj'": the file is the user's handle.
	char what[320];
	if (cage->source)
		snprintf(what, sizeof what, "subdivision surface of '%s'", cage->source);
	else
		snprintf(what, sizeof what, "subdivision surface");
	try {
		tessellate(cage, opt, out);
		return true;
	} catch (const subd_failure &e) {
		diag_error(d, loc, "%s: %s", what, e.what());
	} catch (const std::bad_alloc &) {
		diag_error(d, loc, "%s: out of memory", what);
	} catch (const std::exception &e) {
		diag_error(d, loc, "%s: %s", what, e.what());
	} catch (...) {
		diag_error(d, loc, "%s: unexpected failure in OpenSubdiv", what);
	}
	mesh_free(out);
	return false;
}
