/* param.c - POV-Ray's parametric as a mesh: the point (x(u, v), y(u, v), z(u, v)) over the
 * rectangle [u1, u2] x [v1, v2] on a uv grid whose steps keep each triangle within the tolerance
 * of the surface (the chord bound (|P_uu| hu^2 + 2 |P_uv| hu hv + |P_vv| hv^2) / 8, the second
 * derivatives' largest values estimated by differences on a 65 x 65 sampling of the rectangle),
 * clipped by the container (triangles whose centre lies outside are dropped), normals P_u x P_v.
 * The distance reached, each triangle's centre against the surface at its (u, v) (an upper bound
 * of the distance to the surface), is measured and reported. */
#include "geom/shape.h"

#include "base/mem.h"

#include <math.h>

/* The samples each way that estimate the second derivatives. */
#define PARAM_PROBE 64
/* The fewest grid steps each way. */
#define PARAM_MIN_STEPS 8

typedef struct pctx {
	const shape_desc *s;
	bool failed;
	double fu, fv;
} pctx;

static dvec3 at(pctx *c, double u, double v)
{
	double a[3] = {u, v, 0}, r[3];
	for (int k = 0; k < 3; k++) {
		const shape_desc one = {.fn = c->s->fn, .fn_ctx = c->s->fn_ctxs[k]};
		if (!one.fn(one.fn_ctx, a, &r[k]) || !isfinite(r[k])) {
			if (!c->failed)
				c->failed = true, c->fu = u, c->fv = v;
			r[k] = 0;
		}
	}
	return d3(r[0], r[1], r[2]);
}

static bool inside_container(const shape_desc *s, dvec3 p)
{
	if (s->contained_sphere)
		return d3_length(d3_sub(p, s->box_lo)) <= s->sphere_r;
	return p.x >= s->box_lo.x && p.x <= s->box_hi.x && p.y >= s->box_lo.y && p.y <= s->box_hi.y &&
	       p.z >= s->box_lo.z && p.z <= s->box_hi.z;
}

bool shape_parametric(const shape_desc *s, const shape_accuracy *acc, mesh *out, double *tol_out, diag *d, diag_loc loc)
{
	pctx c = {.s = s};
	double su = s->uv_hi[0] - s->uv_lo[0], sv = s->uv_hi[1] - s->uv_lo[1];
	/* the second derivatives' largest lengths over the probe grid */
	double muu = 0, mvv = 0, muv = 0, hu = su / PARAM_PROBE, hv = sv / PARAM_PROBE;
	for (int i = 1; i < PARAM_PROBE; i++)
		for (int j = 1; j < PARAM_PROBE; j++) {
			double u = s->uv_lo[0] + i * hu, v = s->uv_lo[1] + j * hv;
			dvec3 p = at(&c, u, v);
			dvec3 pu0 = at(&c, u - hu, v), pu1 = at(&c, u + hu, v), pv0 = at(&c, u, v - hv), pv1 = at(&c, u, v + hv);
			muu = fmax(muu, d3_length(d3_add(d3_sub(pu1, d3_scale(p, 2)), pu0)) / (hu * hu));
			mvv = fmax(mvv, d3_length(d3_add(d3_sub(pv1, d3_scale(p, 2)), pv0)) / (hv * hv));
			dvec3 x = d3_sub(d3_add(at(&c, u + hu, v + hv), at(&c, u - hu, v - hv)),
					 d3_add(at(&c, u + hu, v - hv), at(&c, u - hu, v + hv)));
			muv = fmax(muv, d3_length(x) / (4 * hu * hv));
		}
	if (c.failed) {
		diag_error(d, loc, "the parametric's functions cannot be evaluated by circe at <u, v> = <%g, %g>", c.fu, c.fv);
		return false;
	}
	/* steps: a third of the tolerance to each term of the chord bound */
	double t3 = acc->tol / 3;
	double nu = muu > 0 ? ceil(su / sqrt(8 * t3 / muu)) : 1, nv = mvv > 0 ? ceil(sv / sqrt(8 * t3 / mvv)) : 1;
	if (muv > 0) { /* 2 muv hu hv / 8 <= t3 */
		double need = 2 * muv * (su / nu) * (sv / nv) / 8 / t3;
		if (need > 1)
			nu = ceil(nu * sqrt(need)), nv = ceil(nv * sqrt(need));
	}
	nu = fmax(nu, PARAM_MIN_STEPS), nv = fmax(nv, PARAM_MIN_STEPS);
	if (!(2 * nu * nv <= SHAPE_MAX_TRIANGLES)) {
		diag_error(d, loc, "the parametric would make %.0f triangles (the limit of one shape is %u)", 2 * nu * nv,
			   SHAPE_MAX_TRIANGLES);
		return false;
	}
	uint32_t Nu = (uint32_t)nu, Nv = (uint32_t)nv;
	shape_builder b;
	sb_init(&b);
	double du = su / Nu, dv = sv / Nv, eu = du * 1e-3, ev = dv * 1e-3;
	for (uint32_t j = 0; j <= Nv && !b.failed; j++)
		for (uint32_t i = 0; i <= Nu; i++) {
			double u = s->uv_lo[0] + i * du, v = s->uv_lo[1] + j * dv;
			dvec3 pu = d3_sub(at(&c, u + eu, v), at(&c, u - eu, v));
			dvec3 pv = d3_sub(at(&c, u, v + ev), at(&c, u, v - ev));
			sb_vertex(&b, at(&c, u, v), d3_cross(pu, pv), (double)i / Nu, (double)j / Nv);
		}
	/* a periodic rectangle's seams: the last column (row) made the first where they meet, to
	 * rounding (cos(2 pi) is not 1 in doubles), so the mesh has no crack there */
	vec3 lo3, hi3;
	lo3 = hi3 = b.nv ? b.pos[0] : v3(0, 0, 0);
	for (uint32_t i = 0; i < b.nv; i++)
		lo3 = v3_min(lo3, b.pos[i]), hi3 = v3_max(hi3, b.pos[i]);
	float eps = 1e-6f * fmaxf(v3_length(v3_sub(hi3, lo3)), 1e-30f);
	bool seam_u = !b.failed, seam_v = !b.failed;
	for (uint32_t j = 0; j <= Nv && seam_u; j++)
		seam_u = v3_length(v3_sub(b.pos[j * (Nu + 1) + Nu], b.pos[j * (Nu + 1)])) <= eps;
	for (uint32_t i = 0; i <= Nu && seam_v; i++)
		seam_v = v3_length(v3_sub(b.pos[Nv * (Nu + 1) + i], b.pos[i])) <= eps;
	for (uint32_t j = 0; j <= Nv && seam_u; j++)
		b.pos[j * (Nu + 1) + Nu] = b.pos[j * (Nu + 1)];
	for (uint32_t i = 0; i <= Nu && seam_v; i++)
		b.pos[Nv * (Nu + 1) + i] = b.pos[i];
	double worst = 0;
	for (uint32_t j = 0; j < Nv && !b.failed; j++)
		for (uint32_t i = 0; i < Nu; i++) {
			uint32_t a = j * (Nu + 1) + i, q[4] = {a, a + 1, a + Nu + 2, a + Nu + 1};
			static const int tri[2][3] = {{0, 1, 2}, {0, 2, 3}};
			for (int t = 0; t < 2; t++) {
				uint32_t v0 = q[tri[t][0]], v1 = q[tri[t][1]], v2 = q[tri[t][2]];
				dvec3 p0 = v3_to_d3(b.pos[v0]), p1 = v3_to_d3(b.pos[v1]), p2 = v3_to_d3(b.pos[v2]);
				dvec3 ctr = d3_scale(d3_add(d3_add(p0, p1), p2), 1.0 / 3);
				if (!inside_container(s, ctr))
					continue;
				/* the centre's (u, v): the mean of its corners' */
				double cu = s->uv_lo[0] + du * (i + (t == 0 ? 2.0 / 3 : 1.0 / 3));
				double cv = s->uv_lo[1] + dv * (j + (t == 0 ? 1.0 / 3 : 2.0 / 3));
				worst = fmax(worst, d3_length(d3_sub(at(&c, cu, cv), ctr)));
				/* wound as u x v: the winding follows P_u x P_v (the normals) */
				dvec3 want = d3_cross(d3_sub(p1, p0), d3_sub(p2, p0));
				sb_tri(&b, v0, v1, v2, want);
			}
		}
	sb_compact(&b);
	*tol_out = fmax(acc->tol, worst);
	return sb_finish(&b, out, true, "parametric", d, loc);
}
