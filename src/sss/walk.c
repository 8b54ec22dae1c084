/* walk.c - the volumetric random walk (README.md, "The volume random walk") and the closed-mesh
 * check. */
#include "sss/walk.h"

#include "accel/offset.h"
#include "base/mem.h"
#include "sss/profile.h"

#include <assert.h>
#include <math.h>
#include <stdlib.h>

#define WALK_PI 3.14159265358979323846

/* Below this |g| the phase function is sampled as isotropic: the inverse CDF's 1/g loses all
 * digits as g -> 0. */
#define WALK_G_ISOTROPIC 1e-4

/* No collision happens within WALK_SKIN times the hit's scale (the larger of its largest
 * coordinate and its triangle's: the hit's t carries the error of the triangle's vertices; about
 * 8 float ulps), measured along the normal: a collision point rounded onto or across the surface
 * would start the next ray outside (on a 400 mm box the point's own scale let walks land 5e-6
 * outside its face, lost). The skin only transmits (weight e^{-sigma_t d_skin}, sampled consistently): a bias of
 * the order sigma_t * 1e-6 * |coordinates|, negligible. */
#define WALK_SKIN 1e-6


bool sss_walk_medium_from_reduced(sss_walk_medium *m, const double sigma_s_prime_per_mm[3],
				  const double sigma_a_per_mm[3], double g, double eta, double mm_per_unit)
{
	if (!(fabs(g) < 1.0) || !(eta > 0.0) || !isfinite(eta) || !(mm_per_unit > 0.0) || !isfinite(mm_per_unit))
		return false;
	for (int c = 0; c < 3; c++)
		if (!(sigma_s_prime_per_mm[c] >= 0.0) || !isfinite(sigma_s_prime_per_mm[c]) ||
		    !(sigma_a_per_mm[c] >= 0.0) || !isfinite(sigma_a_per_mm[c]))
			return false;
	for (int c = 0; c < 3; c++) {
		m->sigma_s[c] = sigma_s_prime_per_mm[c] / (1.0 - g) * mm_per_unit;
		m->sigma_a[c] = sigma_a_per_mm[c] * mm_per_unit;
	}
	m->g = g;
	m->eta = eta;
	return true;
}

vec3 sss_walk_sample_hg(vec3 w, double g, double u1, double u2)
{
	double mu;
	if (fabs(g) < WALK_G_ISOTROPIC) {
		mu = 1.0 - 2.0 * u1;
	} else {
		double s = (1.0 - g * g) / (1.0 - g + 2.0 * g * u1);
		mu = (1.0 + g * g - s * s) / (2.0 * g);
	}
	mu = fmax(-1.0, fmin(1.0, mu));
	double sin_t = sqrt(fmax(0.0, 1.0 - mu * mu)), phi = 2.0 * WALK_PI * u2;
	vec3 b1, b2;
	v3_basis(w, &b1, &b2);
	vec3 d = v3_add(v3_scale(w, (float)mu),
			v3_add(v3_scale(b1, (float)(sin_t * cos(phi))), v3_scale(b2, (float)(sin_t * sin(phi)))));
	return v3_normalize(d);
}

/* The channel probabilities of the next free path: proportional to throughput times
 * single-scattering albedo (the channels that will carry energy), else to the throughput alone
 * (a pure absorber: the boundary is all that matters). False when the throughput is zero. */
static bool walk_channel_probs(const sss_walk_medium *m, const double beta[3], double q[3])
{
	double s = 0.0;
	for (int c = 0; c < 3; c++) {
		double st = m->sigma_s[c] + m->sigma_a[c];
		q[c] = st > 0.0 ? beta[c] * m->sigma_s[c] / st : 0.0;
		s += q[c];
	}
	if (!(s > 0.0)) {
		s = 0.0;
		for (int c = 0; c < 3; c++)
			s += q[c] = beta[c];
	}
	if (!(s > 0.0) || !isfinite(s))
		return false;
	for (int c = 0; c < 3; c++)
		q[c] /= s;
	return true;
}

/* The normal of the side of the surface that direction w goes to. */
static vec3 walk_side(vec3 ng, vec3 w)
{
	return v3_dot(ng, w) >= 0.0f ? ng : v3_neg(ng);
}

/* The k-th try in a row to start inside again from the boundary point p (n_in pointing into the
 * medium; scale the triangle's, accel/offset.h): the ray offset, doubled k - 1 times. */
static vec3 walk_step_in(vec3 p, vec3 n_in, float scale, int k)
{
	vec3 o = bvh_offset_scaled(p, n_in, scale);
	return k <= 1 ? o : v3_madd(p, v3_sub(o, p), ldexpf(1.0f, k - 1 < 30 ? k - 1 : 30));
}

/* One of the few functions over 100 lines left whole (issue 16): the walk is one loop whose
 * steps (the boundary hit, the free flight with its channel pdfs, the exit test, the reentry
 * after a step that lands outside, the scattering) read and write the same eight variables of
 * its state (origin, direction, beta, sigma_t, outward, stuck, steps, the result); split, each
 * step would take them all by pointer and the loop would read worse, not better. */
sss_walk_result sss_walk(const sss_walk_medium *m, const sss_probe *pr, vec3 x, vec3 ng, float x_scale, vec3 w,
			 rng *g, int max_steps)
{
	sss_walk_result res = {0};
	res.weight = v3s(0.0f);
	if (!v3_is_finite(x) || !v3_is_finite(ng) || !v3_is_finite(w) || v3_length2(w) == 0.0f || max_steps < 1) {
		res.status = SSS_WALK_BAD_INPUT;
		return res;
	}
	double sigma_t[3], beta[3] = {1.0, 1.0, 1.0};
	for (int c = 0; c < 3; c++)
		sigma_t[c] = m->sigma_s[c] + m->sigma_a[c];
	w = v3_normalize(w);
	vec3 org = bvh_offset_scaled(x, walk_side(ng, w), x_scale);
	/* the mesh's orientation, from the entry: +1 when ng points out of the medium */
	float outward = v3_dot(w, ng) <= 0.0f ? 1.0f : -1.0f;
	int stuck = 0; /* reentries in a row */
	for (res.steps = 0; res.steps < max_steps;) {
		bvh_ray ray = {org, w, 0.0f, INFINITY};
		sss_probe_hit h;
		if (!pr->closest(pr->ctx, &ray, &h)) {
			res.status = SSS_WALK_LOST;
			return res;
		}
		double q[3];
		if (!walk_channel_probs(m, beta, q)) {
			res.status = SSS_WALK_ABSORBED;
			return res;
		}
		/* one-sample MIS over channels: pick a channel, sample its exponential free path, and
		 * weigh by the mixture density sum_k q_k sigma_t,k e^{-sigma_t,k t} (balance heuristic) */
		double uc = rng_double(g), ut = rng_double(g);
		int c = uc < q[0] ? 0 : uc < q[0] + q[1] ? 1 : 2;
		if (q[c] == 0.0) /* uc fell on a channel of probability 0 only by rounding */
			c = q[0] > 0.0 ? 0 : q[1] > 0.0 ? 1 : 2;
		assert(q[c] > 0.0); /* walk_channel_probs: the q sum to s > 0 */
		double t = sigma_t[c] > 0.0 ? -log1p(-ut) / sigma_t[c] : INFINITY;
		double scale = fmax(h.scale, fmax(fabs(h.p.x), fmax(fabs(h.p.y), fabs(h.p.z))));
		double cos_n = fmax(1e-6, fabs((double)v3_dot(w, h.ng)));
		double d = fmax(0.0, h.t - WALK_SKIN * scale / cos_n); /* w is unit */
		res.steps++;
		if (t < d) {
			double pdf = 0.0, tr[3];
			for (int k = 0; k < 3; k++) {
				tr[k] = exp(-sigma_t[k] * t);
				pdf += q[k] * sigma_t[k] * tr[k];
			}
			for (int k = 0; k < 3; k++)
				beta[k] *= m->sigma_s[k] * tr[k] / pdf;
			org = v3_madd(org, w, (float)t);
			w = sss_walk_sample_hg(w, m->g, rng_double(g), rng_double(g));
		} else {
			double prob = 0.0, tr[3];
			for (int k = 0; k < 3; k++) {
				tr[k] = exp(-sigma_t[k] * d);
				prob += q[k] * tr[k];
			}
			for (int k = 0; k < 3; k++)
				beta[k] *= tr[k] / prob;
			vec3 n_out = walk_side(h.ng, w); /* points out of the medium along w */
			if (outward * v3_dot(w, h.ng) < 0.0f) {
				/* the surface seen from outside: a collision point rounded across the
				 * boundary (closer to it than a float resolves), or a ray leaving a large
				 * triangle from behind that the triangle test still reports at t ~ 0 (its
				 * error grows with the triangle's size, not with |p|). Step back in, each
				 * time in a row twice as far. */
				org = walk_step_in(h.p, n_out, h.scale, ++stuck);
				res.reentries++;
				continue;
			}
			stuck = 0;
			double cos_i = fmin(1.0, (double)v3_dot(w, n_out));
			double eta = 1.0 / m->eta; /* from the medium (eta) to outside (1) */
			if (rng_double(g) < sss_fresnel_dielectric(cos_i, eta)) {
				w = v3_normalize(v3_madd(w, n_out, (float)(-2.0 * cos_i)));
				org = bvh_offset_scaled(h.p, v3_neg(n_out), h.scale);
				res.reflections++;
			} else {
				/* Snell: the tangential part scales by n_i/n_t = m->eta */
				double sin2_t = m->eta * m->eta * (1.0 - cos_i * cos_i);
				double cos_t = sqrt(fmax(0.0, 1.0 - sin2_t));
				vec3 wt = v3_madd(v3_scale(w, (float)m->eta), n_out, (float)(cos_t - m->eta * cos_i));
				res.status = SSS_WALK_EXITED;
				res.p = h.p, res.ng = h.ng, res.dir = v3_normalize(wt);
				res.prim = h.prim, res.u = h.u, res.v = h.v;
				res.weight = v3((float)beta[0], (float)beta[1], (float)beta[2]);
				if (!v3_is_finite(res.weight) || !v3_is_finite(res.dir)) {
					res.weight = v3s(0.0f);
					res.status = SSS_WALK_LOST;
				}
				return res;
			}
		}
		if (res.steps >= SSS_WALK_RR_START) {
			double survive = fmin(1.0, fmax(beta[0], fmax(beta[1], beta[2])));
			if (!(rng_double(g) < survive)) {
				res.status = SSS_WALK_ABSORBED;
				return res;
			}
			for (int k = 0; k < 3; k++)
				beta[k] /= survive;
		}
	}
	res.status = SSS_WALK_STEP_LIMIT;
	return res;
}

/* ---- closed meshes ---------------------------------------------------------------------------- */

/* A vertex under welding: its position and index, sorted by position (no context for qsort). */
typedef struct weld_vertex {
	vec3 p;
	uint32_t index;
} weld_vertex;

static int weld_cmp(const void *a, const void *b)
{
	vec3 p = ((const weld_vertex *)a)->p, q = ((const weld_vertex *)b)->p;
	if (p.x != q.x)
		return p.x < q.x ? -1 : 1;
	if (p.y != q.y)
		return p.y < q.y ? -1 : 1;
	if (p.z != q.z)
		return p.z < q.z ? -1 : 1;
	return 0;
}

static int edge_cmp(const void *a, const void *b)
{
	uint64_t x = *(const uint64_t *)a, y = *(const uint64_t *)b;
	return x < y ? -1 : x > y;
}

sss_mesh_closure sss_walk_mesh_closure(const mesh *m, uint64_t *open_edges)
{
	if (open_edges)
		*open_edges = 0;
	if (m->num_triangles == 0)
		return SSS_MESH_OPEN;
	uint32_t nv = m->num_vertices;
	weld_vertex *order = mem_alloc(nv, sizeof *order);
	uint32_t *canon = mem_alloc(nv, sizeof *canon);
	uint64_t *edges = mem_alloc(m->num_triangles, 3 * sizeof *edges);
	if (!order || !canon || !edges) {
		mem_free(order), mem_free(canon), mem_free(edges);
		return SSS_MESH_NO_MEMORY;
	}
	for (uint32_t i = 0; i < nv; i++)
		order[i] = (weld_vertex){m->positions[i], i};
	qsort(order, nv, sizeof *order, weld_cmp);
	for (uint32_t i = 0; i < nv; i++)
		canon[order[i].index] = i > 0 && weld_cmp(&order[i - 1], &order[i]) == 0 ? canon[order[i - 1].index]
										    : order[i].index;
	size_t ne = 0;
	for (uint32_t t = 0; t < m->num_triangles; t++) {
		uint32_t v[3];
		for (int k = 0; k < 3; k++)
			v[k] = canon[m->indices[3 * (size_t)t + k]];
		if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0])
			continue; /* collapsed by welding: no area, no edges */
		for (int k = 0; k < 3; k++) {
			uint32_t a = v[k], b = v[(k + 1) % 3];
			edges[ne++] = a < b ? (uint64_t)a << 32 | b : (uint64_t)b << 32 | a;
		}
	}
	qsort(edges, ne, sizeof *edges, edge_cmp);
	uint64_t open = 0;
	for (size_t i = 0; i < ne;) {
		size_t j = i;
		while (j < ne && edges[j] == edges[i])
			j++;
		open += j - i != 2;
		i = j;
	}
	mem_free(order), mem_free(canon), mem_free(edges);
	if (open_edges)
		*open_edges = open;
	return open == 0 && ne > 0 ? SSS_MESH_CLOSED : SSS_MESH_OPEN;
}
