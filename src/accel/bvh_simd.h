/* bvh_simd.h - the traversals of bvh.c (closest hit, any hit, circles) and their node, triangle and
 * circle tests, written once over a vector of W floats and included by bvh.c once per width: W = 4
 * (SSE2, 4-wide nodes) and W = 8 (AVX2, 8-wide nodes). Before each inclusion bvh.c defines W, vf
 * (the vector type), V(op) (its vector operations: V(add) is f4_add or f8_add) and K(name) (the
 * name of this width's copy). Every lane does the scalar test's operations in the same order, so
 * both widths give the scalar tests' results bit for bit. */

/* A W-wide node: b[plane][child] with planes lo x, lo y, lo z, hi x, hi y, hi z, and the children
 * (bvh.c: BVH_LEAF, BVH_EMPTY). */
typedef struct K(node) {
	float b[6][W];
	uint32_t child[W];
} K(node);
_Static_assert(sizeof(K(node)) == NODE_BYTES(W), "node layout as the collapse writes it");
/* Entries of a traversal stack: a visit pushes at most W - 1 (the any-hit push stores a whole vector of
 * W: the last W entries are room for it). */
#define K_STACK ((W - 1) * BVH_MAX_DEPTH + W)
/* Loops over the three axes or vertices, unrolled so their vector arrays live in registers (gcc -O2
 * would keep them in memory). */
#define K_UNROLL _Pragma("GCC unroll 3")

/* ---- Rays: the slab test ------------------------------------------------------------------- */

/* The slab test of W boxes at once: the same operations as node_hit, in the same order, so each
 * lane rounds as the scalar test does (V(max)(a, t) is a > t ? a : t, max_nan). */
typedef struct K(slab_ray) {
	vf org[3], inv[3], tmin, slack;
	int near_plane[3], far_plane[3];
} K(slab_ray);

static inline void K(slab_prepare)(K(slab_ray) * s, const tri_ray *r)
{
	float o[3] = {r->org.x, r->org.y, r->org.z}, d[3] = {r->inv_dir.x, r->inv_dir.y, r->inv_dir.z};
	K_UNROLL
	for (int i = 0; i < 3; i++) {
		s->org[i] = V(set1)(o[i]), s->inv[i] = V(set1)(d[i]);
		int neg = d[i] < 0.0f;
		s->near_plane[i] = 3 * neg + i, s->far_plane[i] = 3 * (1 - neg) + i;
	}
	s->tmin = V(set1)(r->tmin);
	s->slack = V(set1)(BVH_SLAB_SLACK);
}

/* Bit k of the result is set when child k's box may hold a hit with t in [tmin, tlimit]; tnear
 * receives the entry distances. */
BVH_INLINE int K(node_hit)(const K(node) * nd, const K(slab_ray) * s, float tlimit, float tnear[W])
{
	vf tn = s->tmin, tf = V(set1)(tlimit);
	K_UNROLL
	for (int i = 0; i < 3; i++) {
		vf a = V(mul)(V(sub)(V(load)(nd->b[s->near_plane[i]]), s->org[i]), s->inv[i]);
		vf b = V(mul)(V(sub)(V(load)(nd->b[s->far_plane[i]]), s->org[i]), s->inv[i]);
		tn = V(max)(a, tn), tf = V(min)(b, tf);
	}
	V(storeu)(tnear, tn);
	return V(movemask)(V(le)(tn, V(mul)(tf, s->slack)));
}

/* ---- Rays: the watertight test of a leaf's triangles ----------------------------------------- */

typedef struct K(tri_ray) {
	vf ox, oy, oz, sx, sy, sz, tmin; /* the origin in the ray's axis order kx, ky, kz */
	int kx, ky, kz;
} K(tri_ray);

static inline void K(tri_ray_prepare)(K(tri_ray) * q, const tri_ray *r)
{
	q->ox = V(set1)(v3_get(r->org, r->kx)), q->oy = V(set1)(v3_get(r->org, r->ky));
	q->oz = V(set1)(v3_get(r->org, r->kz));
	q->sx = V(set1)(r->sx), q->sy = V(set1)(r->sy), q->sz = V(set1)(r->sz);
	q->tmin = V(set1)(r->tmin);
	q->kx = r->kx, q->ky = r->ky, q->kz = r->kz;
}

/* Group h of a leaf of m triangles at w (bvh.c: a leaf is groups of W): its first word, and its
 * count in *mg. */
BVH_INLINE const bvh_word *K(group)(const bvh_word *w, int m, int h, int *mg)
{
	*mg = m - W * h < W ? m - W * h : W;
	return w + GROUP_WORDS * W * h;
}
/* Lanes of a group of m triangles. */
BVH_INLINE vf K(group_lanes)(int m) { return V(lanes)(m); }
/* Coordinate array a (0 to 8: v0x v0y v0z v1x ... v2z) of a group, lanes past m zero. */
BVH_INLINE vf K(group_load)(const bvh_word *w, int m, int a, vf lanes)
{
	return V(and)(V(loadu)(&w[a * m].f), lanes);
}

/* The watertight test (tri_intersect) of a group of m triangles at w: the same
 * operations in the same order in each lane, so every lane rounds as tri_intersect does. Lanes
 * where U, V or W is zero need tri_intersect's double-precision decision and are left to it.
 * Returns the lanes that hit with t in [tmin, tlimit] in *hit_mask and those left to the scalar
 * test in the result (lanes of the group only); t, u, v receive the hitting lanes' values. (Returning
 * before t and the divisions when no lane passes the edge tests, as most parts do, was slower:
 * bench/README.md.) */
BVH_INLINE int K(tri_intersect)(const K(tri_ray) * q, const bvh_word *w, int m, float tlimit,
				int *hit_mask, float t[W], float u[W], float v[W])
{
	vf in = K(group_lanes)(m);
	/* The coordinate arrays are picked in the ray's axis order as they are loaded, so the
	 * permutation costs no shuffles (and no trip through memory). */
	vf Az = V(sub)(K(group_load)(w, m, q->kz, in), q->oz);
	vf Bz = V(sub)(K(group_load)(w, m, 3 + q->kz, in), q->oz);
	vf Cz = V(sub)(K(group_load)(w, m, 6 + q->kz, in), q->oz);
	vf Ax = V(sub)(V(sub)(K(group_load)(w, m, q->kx, in), q->ox), V(mul)(q->sx, Az));
	vf Ay = V(sub)(V(sub)(K(group_load)(w, m, q->ky, in), q->oy), V(mul)(q->sy, Az));
	vf Bx = V(sub)(V(sub)(K(group_load)(w, m, 3 + q->kx, in), q->ox), V(mul)(q->sx, Bz));
	vf By = V(sub)(V(sub)(K(group_load)(w, m, 3 + q->ky, in), q->oy), V(mul)(q->sy, Bz));
	vf Cx = V(sub)(V(sub)(K(group_load)(w, m, 6 + q->kx, in), q->ox), V(mul)(q->sx, Cz));
	vf Cy = V(sub)(V(sub)(K(group_load)(w, m, 6 + q->ky, in), q->oy), V(mul)(q->sy, Cz));
	vf U = V(sub)(V(mul)(Cx, By), V(mul)(Cy, Bx));
	vf Vb = V(sub)(V(mul)(Ax, Cy), V(mul)(Ay, Cx));
	vf Wb = V(sub)(V(mul)(Bx, Ay), V(mul)(By, Ax));
	const vf zero = V(zero)();
	int lanes = V(movemask)(in);
	int scalar = V(movemask)(V(or)(V(or)(V(eq)(U, zero), V(eq)(Vb, zero)), V(eq)(Wb, zero))) & lanes;
	vf neg = V(or)(V(or)(V(lt)(U, zero), V(lt)(Vb, zero)), V(lt)(Wb, zero));
	vf pos = V(or)(V(or)(V(gt)(U, zero), V(gt)(Vb, zero)), V(gt)(Wb, zero));
	vf inside = V(andnot)(V(and)(neg, pos), in);
	vf det = V(add)(V(add)(U, Vb), Wb);
	vf T = V(add)(V(add)(V(mul)(U, V(mul)(q->sz, Az)), V(mul)(Vb, V(mul)(q->sz, Bz))),
		      V(mul)(Wb, V(mul)(q->sz, Cz)));
	vf tt = V(div)(T, det);
	vf ok = V(and)(inside, V(neq)(det, zero));
	ok = V(and)(ok, V(and)(V(ge)(tt, q->tmin), V(le)(tt, V(set1)(tlimit))));
	*hit_mask = V(movemask)(ok) & ~scalar;
	if (*hit_mask) {
		V(storeu)(t, tt);
		V(storeu)(u, V(div)(Vb, det));
		V(storeu)(v, V(div)(Wb, det));
	}
	return scalar;
}

/* ---- Rays: the traversals -------------------------------------------------------------------- */

typedef struct K(stack_entry) {
	uint32_t ref;
	float tnear;
} K(stack_entry);

static bool K(intersect)(const bvh *b, const tri_ray *r, float *tlimit, bvh_hit *hit)
{
	const K(node) *nodes = b->nodes;
	K(slab_ray) sr;
	K(slab_prepare)(&sr, r);
	K(tri_ray) q;
	K(tri_ray_prepare)(&q, r);
	K(stack_entry) stack[K_STACK];
	int sp = 0;
	uint32_t ref = 0;
	bool found = false;
	uint32_t best_id = UINT32_MAX;
	for (;;) {
		if (!(ref & BVH_LEAF)) {
			const K(node) *nd = &nodes[ref];
			float tn[W];
			int mask = K(node_hit)(nd, &sr, *tlimit, tn);
			if (mask != 0) {
				const int all = mask;
				int k0 = lowest_bit(mask);
				mask &= mask - 1;
				if (mask == 0) {
					ref = nd->child[k0];
					continue;
				}
				int k1 = lowest_bit(mask);
				mask &= mask - 1;
				if (mask == 0) {
					/* Two: go to the nearer, keep the other; chosen by a mask, not a branch
					 * (which way the nearer lies is a coin toss for incoherent rays). */
					uint32_t c0 = nd->child[k0], c1 = nd->child[k1], t0, t1;
					memcpy(&t0, &tn[k0], sizeof t0), memcpy(&t1, &tn[k1], sizeof t1);
					uint32_t swap = -(uint32_t)(tn[k1] < tn[k0]);
					uint32_t dc = (c0 ^ c1) & swap, dt = (t0 ^ t1) & swap;
					K(stack_entry) *e = &stack[sp++];
					e->ref = c1 ^ dc;
					t1 ^= dt;
					memcpy(&e->tnear, &t1, sizeof t1);
					ref = c0 ^ dc;
					continue;
				}
				/* More: push all sorted, the nearest on top, and take it. Each child's place is
				 * the count of children farther than it (ties: the higher slot counts as
				 * farther), from one compare of all at once: no branch on the order. */
				(void)k0, (void)k1;
				int base = sp;
				vf tv = V(loadu)(tn);
				for (int mm = all; mm != 0; mm &= mm - 1) {
					int k = lowest_bit(mm);
					vf tk = V(set1)(tn[k]);
					int farther = V(movemask)(V(gt)(tv, tk)) | (V(movemask)(V(eq)(tv, tk)) & (int)(0xfffffffeu << k));
					stack[base + V(popcount)(farther & all)] =
					    (K(stack_entry)){nd->child[k], tn[k]};
				}
				sp = base + V(popcount)(all);
				ref = stack[--sp].ref;
				continue;
			}
		} else {
			/* W triangles at a time. A hit is taken when closer, or as close with a lower id:
			 * the tie rule of the loop over all triangles, whatever the order of visits. */
			int m = (int)leaf_count(ref);
			const bvh_word *w = leaf_words(b, ref);
			for (int h = 0; W * h < m; h++) {
				int mg;
				const bvh_word *wg = K(group)(w, m, h, &mg);
				float t4[W], u4[W], v4[W];
				int hm, sc = K(tri_intersect)(&q, wg, mg, *tlimit, &hm, t4, u4, v4);
				for (int todo = hm | sc; todo != 0; todo &= todo - 1) {
					int j = lowest_bit(todo);
					float t = t4[j], u = u4[j], v = v4[j];
					bool hj = sc >> j & 1 ? group_tri_intersect(r, wg, mg, j, *tlimit, &t, &u, &v)
							      : t <= *tlimit;
					uint32_t id = group_id(wg, mg, j);
					if (hj && (t < *tlimit || id < best_id)) {
						*tlimit = t;
						best_id = id;
						hit->t = t, hit->u = u, hit->v = v, hit->prim = id;
						found = true;
					}
				}
			}
		}
		/* Pop the next entry that can still hold a hit no farther than the best. */
		for (;;) {
			if (sp == 0)
				return found;
			K(stack_entry) e = stack[--sp];
			if (e.tnear <= *tlimit * BVH_SLAB_SLACK) {
				ref = e.ref;
				break;
			}
		}
	}
}

static bool K(occluded)(const bvh *b, const tri_ray *r)
{
	const K(node) *nodes = b->nodes;
	K(slab_ray) sr;
	K(slab_prepare)(&sr, r);
	K(tri_ray) q;
	K(tri_ray_prepare)(&q, r);
	uint32_t stack[K_STACK];
	int sp = 0;
	uint32_t ref = 0;
	for (;;) {
		if (!(ref & BVH_LEAF)) {
			const K(node) *nd = &nodes[ref];
			float tn[W];
			int mask = K(node_hit)(nd, &sr, r->tmax, tn);
			if (mask != 0) {
				/* The first passing child next, the others pushed by one left-pack (no loop
				 * whose trip count is the count of children: a branch miss a ray or two, and
				 * nothing reloaded from the stack at once); the pops take them as before,
				 * highest slot first. Any hit 1.01-1.07x (bench/README.md). */
				ref = nd->child[lowest_bit(mask)];
				sp += V(compress)(&stack[sp], nd->child, mask & (mask - 1));
				continue;
			}
		} else {
			int m = (int)leaf_count(ref);
			const bvh_word *w = leaf_words(b, ref);
			for (int h = 0; W * h < m; h++) {
				int mg;
				const bvh_word *wg = K(group)(w, m, h, &mg);
				float t4[W], u4[W], v4[W];
				int hm, sc = K(tri_intersect)(&q, wg, mg, r->tmax, &hm, t4, u4, v4);
				if (hm)
					return true;
				for (; sc != 0; sc &= sc - 1) {
					int j = lowest_bit(sc);
					float t, u, v;
					if (group_tri_intersect(r, wg, mg, j, r->tmax, &t, &u, &v))
						return true;
				}
			}
		}
		if (sp == 0)
			return false;
		ref = stack[--sp];
	}
}

/* ---- Circles --------------------------------------------------------------------------------- */

/* box_circle (bvh.c) on the W children of a node, lane by lane with the same operations in the
 * same order, so each lane is exactly as conservative as the scalar test. An empty child fails the
 * bounds test (lo = +inf). */
typedef struct K(circle_prep) {
	vf lo[3], hi[3], c[3], m[3], neg_m[3], t[3], neg_t[3];
	vf slack, neg_slack, rmax2, rmin2;
	vf radius; /* for group_circle */
	bool full;
} K(circle_prep);

static void K(circle_prepare)(const circle_prep *p, K(circle_prep) * q)
{
	K_UNROLL
	for (int i = 0; i < 3; i++) {
		q->lo[i] = V(set1)(p->lo[i]), q->hi[i] = V(set1)(p->hi[i]);
		q->c[i] = V(set1)(p->c[i]);
		q->m[i] = V(set1)(p->m[i]), q->neg_m[i] = V(set1)(p->neg_m[i]);
		q->t[i] = V(set1)(p->t[i]), q->neg_t[i] = V(set1)(p->neg_t[i]);
	}
	q->slack = V(set1)(p->slack), q->neg_slack = V(set1)(-p->slack);
	q->rmax2 = V(set1)(p->rmax2), q->rmin2 = V(set1)(p->rmin2);
	q->radius = V(set1)(p->r);
	q->full = p->full;
}

BVH_INLINE vf K(dot)(const vf a[3], const vf b[3])
{
	return V(add)(V(add)(V(mul)(a[0], b[0]), V(mul)(a[1], b[1])), V(mul)(a[2], b[2]));
}

BVH_INLINE int K(node_circle)(const K(node) * nd, const K(circle_prep) * p)
{
	const vf zero = V(zero)();
	vf ok = V(lanes)(W);
	vf m_lo = zero, m_hi = zero, t_hi = zero, near2 = zero, far2 = zero;
	K_UNROLL
	for (int i = 0; i < 3; i++) {
		vf lo = V(load)(nd->b[i]), hi = V(load)(nd->b[3 + i]);
		ok = V(and)(ok, V(and)(V(le)(lo, p->hi[i]), V(ge)(hi, p->lo[i])));
		vf a = V(sub)(lo, p->c[i]), b = V(sub)(p->c[i], hi);
		vf ma = V(mul)(p->m[i], a), mb = V(mul)(p->neg_m[i], b);
		vf dn = V(max)(V(max)(a, b), zero), df = V(min)(a, b);
		if (i == 0) {
			m_lo = V(min)(ma, mb), m_hi = V(max)(ma, mb);
			near2 = V(mul)(dn, dn), far2 = V(mul)(df, df);
		} else {
			m_lo = V(add)(m_lo, V(min)(ma, mb)), m_hi = V(add)(m_hi, V(max)(ma, mb));
			near2 = V(add)(near2, V(mul)(dn, dn)), far2 = V(add)(far2, V(mul)(df, df));
		}
		if (!p->full) {
			vf tm = V(max)(V(mul)(p->t[i], a), V(mul)(p->neg_t[i], b));
			t_hi = i == 0 ? tm : V(add)(t_hi, tm);
		}
	}
	ok = V(and)(ok, V(and)(V(le)(m_lo, p->slack), V(ge)(m_hi, p->neg_slack)));
	if (!p->full)
		ok = V(and)(ok, V(ge)(t_hi, p->neg_slack));
	ok = V(and)(ok, V(and)(V(le)(near2, p->rmax2), V(ge)(far2, p->rmin2)));
	return V(movemask)(ok);
}

/* The lanes of group_circle whose plane segment surely misses the circle. Taken only where all
 * vertices are clearly off the plane (|d| > margin, d's error bound), so the edges that cross it
 * are the exact test's two. An end on edge (i, j) is rel_i + s (rel_j - rel_i) with
 * s = d_i / (d_i - d_j); errors of up to margin in d_i and d_j move s by at most
 * 2 margin / (|d_i| + |d_j| - 2 margin), so the end by that times |rel_j - rel_i| (bounded by its
 * L1 norm). Misses: both ends inside the sphere, the segment's nearest point outside it, or, for a
 * half circle, both ends on the side cos theta < 0, each by the ends' error and the margin sm. */
BVH_INLINE int K(segment_misses)(const K(circle_prep) * p, vf rel[3][3], const vf d[3], vf margin, vf sm)
{
	const vf zero = V(zero)(), one = V(set1)(1.0f);
	vf ad[3] = {V(abs)(d[0]), V(abs)(d[1]), V(abs)(d[2])};
	vf sure = V(and)(V(and)(V(gt)(ad[0], margin), V(gt)(ad[1], margin)), V(gt)(ad[2], margin));
	if (!V(movemask)(sure))
		return 0;
	vf two_margin = V(add)(margin, margin);
	vf x[3][3], err[3], crosses[3];
	K_UNROLL
	for (int e = 0; e < 3; e++) {
		int i = e, j = e == 2 ? 0 : e + 1;
		vf s = V(div)(d[i], V(sub)(d[i], d[j]));
		vf l1 = zero;
		K_UNROLL
		for (int a = 0; a < 3; a++) {
			vf dv = V(sub)(rel[j][a], rel[i][a]);
			x[e][a] = V(add)(rel[i][a], V(mul)(s, dv));
			l1 = V(add)(l1, V(abs)(dv));
		}
		err[e] = V(div)(V(mul)(two_margin, l1), V(sub)(V(add)(ad[i], ad[j]), two_margin));
		crosses[e] = V(xor)(V(lt)(d[i], zero), V(lt)(d[j], zero));
	}
	/* The two crossing edges: (0, 1), (0, 2) or (1, 2). */
	vf e1[3], e2[3];
	K_UNROLL
	for (int a = 0; a < 3; a++)
		e1[a] = V(blend)(crosses[0], x[0][a], x[1][a]),
		e2[a] = V(blend)(crosses[2], x[2][a], x[1][a]);
	vf err_max = V(max)(V(blend)(crosses[0], err[0], err[1]), V(blend)(crosses[2], err[2], err[1]));
	vf slack = V(add)(sm, err_max);
	vf rin = V(sub)(p->radius, slack), rout = V(add)(p->radius, slack);
	vf rin2 = V(mul)(rin, rin);
	vf inside =
	    V(and)(V(and)(V(lt)(K(dot)(e1, e1), rin2), V(lt)(K(dot)(e2, e2), rin2)), V(gt)(rin, zero));
	/* The nearest point to the centre (the origin of rel): e1 + clamp(-e1.D / D.D, 0, 1) D; a NaN
	 * from D = 0 clamps to 0 (V(max) returns its second operand on NaN). */
	vf dd[3];
	K_UNROLL
	for (int a = 0; a < 3; a++)
		dd[a] = V(sub)(e2[a], e1[a]);
	vf f = V(div)(V(sub)(zero, K(dot)(e1, dd)), K(dot)(dd, dd));
	f = V(min)(V(max)(f, zero), one);
	vf near[3];
	K_UNROLL
	for (int a = 0; a < 3; a++)
		near[a] = V(add)(e1[a], V(mul)(f, dd[a]));
	vf miss = V(or)(inside, V(gt)(K(dot)(near, near), V(mul)(rout, rout)));
	if (!p->full) {
		vf neg = V(sub)(zero, slack);
		miss = V(or)(miss, V(and)(V(lt)(K(dot)(p->t, e1), neg), V(lt)(K(dot)(p->t, e2), neg)));
	}
	return V(movemask)(V(and)(sure, miss));
}

/* The triangles of a group of m at w that may meet the circle (a lane mask): cheap float tests that
 * reject only triangles tri_circle_intersect gives no hit for, so its double-precision work is
 * spent on few. (1) Its plane pre-test, the same operations in the same order: all vertices
 * clearly on one side of the circle's plane. (2) The segment the plane cuts from the triangle
 * misses the circle (segment_misses), with the margin grown by the radius's rounding. The segment
 * lies in the triangle, so this rejects all that tests of the triangle's vertices or box against
 * the sphere or the circle's half space would, and more. */
BVH_INLINE int K(group_circle)(const K(circle_prep) * p, const bvh_word *w, int m)
{
	const vf zero = V(zero)();
	vf in = K(group_lanes)(m);
	vf rel[3][3], mag[3]; /* rel[vertex][axis] = v - c */
	K_UNROLL
	for (int a = 0; a < 3; a++) {
		vf v0 = K(group_load)(w, m, a, in), v1 = K(group_load)(w, m, 3 + a, in);
		vf v2 = K(group_load)(w, m, 6 + a, in);
		rel[0][a] = V(sub)(v0, p->c[a]), rel[1][a] = V(sub)(v1, p->c[a]);
		rel[2][a] = V(sub)(v2, p->c[a]);
		mag[a] = V(add)(V(add)(V(abs)(v0), V(abs)(v1)), V(add)(V(abs)(v2), V(abs)(p->c[a])));
	}
	vf margin = V(mul)(V(set1)(GROUP_CIRCLE_MARGIN), V(add)(V(add)(mag[0], mag[1]), mag[2]));
	vf neg_margin = V(sub)(zero, margin);
	vf d[3];
	K_UNROLL
	for (int v = 0; v < 3; v++)
		d[v] = K(dot)(p->m, rel[v]);
	vf above = V(and)(V(and)(V(gt)(d[0], margin), V(gt)(d[1], margin)), V(gt)(d[2], margin));
	vf below = V(and)(V(and)(V(lt)(d[0], neg_margin), V(lt)(d[1], neg_margin)), V(lt)(d[2], neg_margin));
	int left = V(movemask)(V(andnot)(V(or)(above, below), in));
	if (left) {
		vf sm = V(add)(margin, V(mul)(V(set1)(GROUP_CIRCLE_MARGIN), p->radius));
		left &= ~K(segment_misses)(p, rel, d, margin, sm);
	}
	return left;
}

/* The leaves among a node's children (their references have the top bit; so has BVH_EMPTY, whose
 * box no test passes): the sign bits of the children read as floats. */
BVH_INLINE int K(leaf_mask)(const K(node) *nd) { return V(movemask)(V(loadu)((const float *)nd->child)); }

/* Leaves a circle traversal collects before it tests them (then it goes on). */
#define K_LEAF_BATCH BVH_CIRCLE_LEAF_BATCH
/* Candidates whose exact tests overlap (K(circle_leaves)). */
#define K_EXACT_CHUNK 4

/* The leaves[0, n) of a circle traversal: first every leaf's pre-test, its candidates left-packed
 * into one list (leaf i, triangle k as i << 8 | k), then the exact test of each. Separate passes,
 * free of each other's branches, overlap better than a leaf test after each node test, and one
 * list needs no branch on which leaves have candidates. Returns the new total (circle_triangle). */
static uint32_t K(circle_leaves)(const bvh *b, const tri_circle_d *q, const K(circle_prep) * p,
				 const uint32_t *leaves, int n, tri_circle_hit *hits, uint32_t max_hits,
				 uint32_t total)
{
	uint32_t cand[(K_LEAF_BATCH + W) * BVH_MAX_LEAF + W];
	int nc = 0;
	/* Fetch every leaf's first group at once, so their misses overlap (1.02x on the head). */
	for (int i = 0; i < n; i++) {
		const char *lw = (const char *)leaf_words(b, leaves[i]);
		const int bytes = GROUP_WORDS * (int)sizeof(bvh_word) * W;
		for (int o = 0; o < bytes; o += 64)
			_mm_prefetch(lw + o, _MM_HINT_T0);
		_mm_prefetch(lw + bytes - 1, _MM_HINT_T0);
	}
	for (int i = 0; i < n; i++) {
		int m = (int)leaf_count(leaves[i]);
		const bvh_word *w = leaf_words(b, leaves[i]);
		for (int h = 0; W * h < m; h++) {
			int mg;
			const bvh_word *wg = K(group)(w, m, h, &mg);
			nc += V(compress_lanes)(&cand[nc], (uint32_t)(i << 8 | W * h), K(group_circle)(p, wg, mg));
		}
	}
	/* The exact tests a few candidates at a time, first halves then second halves: each half is a
	 * chain of dependent divisions and square roots, and the chains of different candidates
	 * overlap. The hits keep the candidates' order. */
	for (int j0 = 0; j0 < nc; j0 += K_EXACT_CHUNK) {
		int nj = nc - j0 < K_EXACT_CHUNK ? nc - j0 : K_EXACT_CHUNK, nr[K_EXACT_CHUNK];
		tri_circle_segment seg[K_EXACT_CHUNK];
		uint32_t id[K_EXACT_CHUNK];
		for (int j = 0; j < nj; j++) {
			uint32_t leaf = leaves[cand[j0 + j] >> 8];
			int k = (int)(cand[j0 + j] & 255), m = (int)leaf_count(leaf), mg;
			const bvh_word *wg = K(group)(leaf_words(b, leaf), m, k / W, &mg);
			nr[j] = circle_segment(q, wg, mg, k % W, &seg[j]);
			id[j] = group_id(wg, mg, k % W);
		}
		for (int j = 0; j < nj; j++)
			if (nr[j])
				total = circle_segment_hits(q, &seg[j], nr[j], id[j], hits, max_hits, total);
	}
	return total;
}

/* The inner nodes a circle traversal queues before it goes depth first (K(circle)). */
#define K_FIFO BVH_CIRCLE_FIFO
/* Its queue: K_FIFO, then room for a depth-first descent (K_STACK) and two nodes' children. */
#define K_QUEUE (K_FIFO + K_STACK + 2 * W)

/* The root is always an inner node (the collapse gives a lone leaf a root of its own). Every
 * node's passing children are appended by one left-pack each: leaves to a batch (K(circle_leaves)),
 * inner nodes to a queue [front, back). The next node comes from the front, so it was queued
 * before the node just tested and does not wait for its test: breadth first, successive node
 * tests overlap (depth first, each waited for the last; 1.13x on the head). Once the queue's back
 * passes K_FIFO, nodes come from the back, depth first, which never takes it past K_QUEUE - W
 * (a descent adds at most W - 1 nodes a level); the front's part of the array is not reused. All
 * hits are returned, in an order that depends on the tree. */
static uint32_t K(circle)(const bvh *b, const tri_circle_d *q, const circle_prep *cp, tri_circle_hit *hits,
			  uint32_t max_hits)
{
	const K(node) *nodes = b->nodes;
	K(circle_prep) p;
	K(circle_prepare)(cp, &p);
	uint32_t queue[K_QUEUE], leaves[K_LEAF_BATCH + W];
	int front = 0, back = 0, nl = 0;
	uint32_t ni = 0, total = 0;
	for (;;) {
		const K(node) *nd = &nodes[ni];
		int mask = K(node_circle)(nd, &p);
		int leaf = mask & K(leaf_mask)(nd);
		/* Room for a whole vector's store in both (once a node, not a lane: no measurable cost). */
		assert(back <= K_QUEUE - W && nl < K_LEAF_BATCH);
		nl += V(compress)(&leaves[nl], nd->child, leaf);
		int inner = mask & ~leaf, was_empty = back == front;
		back += V(compress)(&queue[back], nd->child, inner);
		if (nl >= K_LEAF_BATCH) {
			total = K(circle_leaves)(b, q, &p, leaves, nl, hits, max_hits, total);
			nl = 0;
		}
		if (back == front)
			return K(circle_leaves)(b, q, &p, leaves, nl, hits, max_hits, total);
		if (back > K_FIFO) {
			BVH_QUEUE_STAT(bvh_circle_queue_lifo);
			ni = queue[--back];
		} else if (was_empty) {
			/* The queue's front is the entry this node just wrote: read it from the node, not
			 * back from the vector store at once (a forwarding stall; 1.01-1.05x). */
			ni = nd->child[lowest_bit(inner)];
			front++;
		} else {
			ni = queue[front++];
		}
	}
}

#undef K_FIFO
#undef K_QUEUE
#undef K_LEAF_BATCH
#undef K_EXACT_CHUNK
#undef K_STACK
#undef K_UNROLL
