/* probe.c - the closest-hit probe of a world-space mesh and its BVH, and the every-hit loop of
 * the disk comparator. */
#include "sss/probe.h"

#include "accel/offset.h"

#include <math.h>

static bool probe_mesh_closest(const void *ctx, const bvh_ray *ray, sss_probe_hit *hit)
{
	const sss_probe_mesh *pm = ctx;
	bvh_hit h;
	if (!bvh_intersect(pm->bvh, ray, &h))
		return false;
	const uint32_t *ix = pm->mesh->indices + 3 * (size_t)h.prim;
	vec3 a = pm->mesh->positions[ix[0]], b = pm->mesh->positions[ix[1]], c = pm->mesh->positions[ix[2]];
	vec3 e1 = v3_sub(b, a), e2 = v3_sub(c, a);
	hit->t = h.t;
	/* the barycentric point is exactly on the triangle, which org + t dir is only to rounding */
	hit->p = v3_madd(v3_madd(a, e1, h.u), e2, h.v);
	hit->ng = v3_normalize(v3_cross(e1, e2));
	hit->prim = h.prim;
	hit->u = h.u, hit->v = h.v;
	hit->scale = bvh_triangle_scale(a, b, c);
	return true;
}

static float probe_mesh_nearest(const void *ctx, vec3 p, float cap)
{
	const sss_probe_mesh *pm = ctx;
	return bvh_nearest(pm->bvh, p, cap);
}

sss_probe sss_probe_of_mesh(const sss_probe_mesh *pm)
{
	return (sss_probe){probe_mesh_closest, pm, probe_mesh_nearest};
}

int sss_probe_all(const sss_probe *pr, const bvh_ray *ray, sss_probe_hit *hits, int max_hits, bool *more)
{
	bvh_ray r = *ray;
	float gap = SSS_PROBE_GAP * (ray->tmax - ray->tmin);
	int n = 0;
	if (more)
		*more = false;
	sss_probe_hit h;
	while (r.tmin <= r.tmax && pr->closest(pr->ctx, &r, &h)) {
		if (n == max_hits) {
			if (more)
				*more = true;
			break;
		}
		hits[n++] = h;
		float next = h.t + gap;
		if (!(next > h.t)) /* a gap lost to rounding at large t */
			next = nextafterf(h.t, INFINITY);
		r.tmin = next;
	}
	return n;
}
