/* bvh.c - binned-SAH build of a binary BVH, collapsed into a 4-wide one, and its ray and circle
 * traversals. A 4-wide node holds its children's boxes as struct-of-arrays, so one SSE register
 * (SSE2 is the x86-64 baseline) tests a plane of all four; leaves point into groups of up to four
 * triangles stored pre-transposed, so one SSE register holds a coordinate of four triangles. */
#include "accel/bvh.h"

#include "base/mem.h"

#include <emmintrin.h>
#include <string.h>

/* SAH: the costs of a node visit (two box tests) and of a triangle test. Their ratio sets the
 * leaf size, hence speed against memory (bench/README.md). */
#ifndef SAH_TRAVERSAL_COST
#define SAH_TRAVERSAL_COST 2.0f
#endif
#ifndef SAH_INTERSECTION_COST
#define SAH_INTERSECTION_COST 1.0f
#endif
#define SAH_BINS 16
/* Triangles a leaf test takes at once (a group, bvh_word): SAH prices a leaf by its groups. */
#define BVH_LEAF_BLOCK 4
/* Slack of the slab test's far distance: 1 + 2 gamma(3) of Ize 2013 ("Robust BVH Ray
 * Traversal") covers the rounding of the box distances; we take ten times that, because the
 * triangle test's t carries rounding too and a box must never cull a hit the brute force finds. */
#define BVH_SLAB_SLACK (1.0f + 20.0f * 0x1p-24f * 3.0f)
/* Relative slack of the circle/box test, against float rounding of box and circle data. */
#define BVH_CIRCLE_SLACK 1e-5f
/* The in-plane tests measure distances in the circle's axes (t, n), which is exact for an
 * orthonormal pair; a pair off by eps (|t.t - 1|, |n.n - 1|, |t.n|) changes a distance by about
 * 1.5 eps of itself, well inside the slack for eps up to this. Axes further off skip the tests. */
#define BVH_CIRCLE_ORTHO_TOL 1e-6f

/* The leaves' triangles, pre-transposed in groups (Embree's "triangle4" idea): a group of m
 * triangles (1 to 4) is ten arrays of m words, the coordinates v0x v0y v0z v1x ... v2z and then
 * the ids, so one unaligned load gives one coordinate of all m triangles (lanes past m read the
 * next array and are masked off). A leaf of n triangles from triangle f is groups of four and a
 * last one of the rest; group g starts at word GROUP_WORDS * (f + 4 g). 40 bytes a triangle, and
 * no transposes when a ray visits. */
typedef union bvh_word {
	float f;
	uint32_t u;
} bvh_word;
#define GROUP_WORDS 10
/* Words after the last group: the last coordinate array of a group of one is loaded 16 bytes wide,
 * three words past its end. */
#define LEAF_PAD_WORDS 4

/* A 4-wide node, 112 bytes: b[plane][child] with planes lo x, lo y, lo z, hi x, hi y, hi z. A child
 * is an inner node's index, a leaf (BVH4_LEAF | (count - 1) << BVH4_COUNT_SHIFT | first triangle),
 * or BVH4_EMPTY (then its box is empty, lo = +inf and hi = -inf, and no ray or circle test passes
 * it). */
typedef struct bvh4_node {
	float b[6][4];
	uint32_t child[4];
} bvh4_node;
#define BVH4_LEAF 0x80000000u
#define BVH4_COUNT_SHIFT 27
#define BVH4_FIRST_MASK ((1u << BVH4_COUNT_SHIFT) - 1)
/* Leaves of the binary tree have at most BVH_MAX_LEAF triangles: four bits of count suffice. */
_Static_assert(BVH_MAX_LEAF <= 16, "a leaf's count must fit its four bits");
#define BVH4_EMPTY 0xffffffffu
/* Entries of a traversal stack: a visit pushes at most three. */
#define BVH4_STACK (3 * BVH_MAX_DEPTH + 4)

struct bvh {
	bvh4_node *nodes; /* node 0 is the root */
	uint32_t num_nodes;
	bvh_word *leaf; /* triangle groups in leaf order, then LEAF_PAD_WORDS */
	uint32_t num_tris;
	vec3 lo, hi; /* bounds of all triangles */
};

/* A primitive reference during the build, 32 bytes: its box, and its index in the input in the
 * spare lane 3 of lo (hi's lane 3 is 0). Read lo through ref_lo, which clears that lane: an id
 * read as a float is a denormal for ids below 2^23, and must never enter the arithmetic (nor
 * min/max) of the build. Partitions move refs whole, so the id's bits go along untouched. */
typedef union build_ref {
	struct {
		__m128 lo, hi;
	};
	struct {
		uint32_t lo_bits[3], id;
	};
} build_ref;
_Static_assert(sizeof(build_ref) == 32, "a build ref is two SSE registers");

/* All ones in lanes x, y, z; lane 3 zero. */
static inline __m128 xyz_mask(void) { return _mm_castsi128_ps(_mm_setr_epi32(-1, -1, -1, 0)); }

static inline __m128 ref_lo(const build_ref *r) { return _mm_and_ps(r->lo, xyz_mask()); }

/* The build's inner functions are forced inline: their callers pass constants (the leaf block). */
#define BUILD_INLINE static inline __attribute__((always_inline))

/* A node to build: refs[begin, end), their box and the box of their centroids (doubled: lo + hi),
 * computed by the parent's partition so no pass over the refs is spent on them. */
typedef struct build_task {
	uint32_t node, begin, end, depth;
	__m128 lo, hi, clo, chi;
} build_task;

/* Component max as compare-and-select (maxss): vec.h's fmaxf-based one is a library call at -O2,
 * and build inputs are finite (degenerate triangles are left out). */
static inline vec3 vmax(vec3 a, vec3 b)
{
	return v3(a.x > b.x ? a.x : b.x, a.y > b.y ? a.y : b.y, a.z > b.z ? a.z : b.z);
}
static inline float fmax3(vec3 a)
{
	float m = a.x > a.y ? a.x : a.y;
	return m > a.z ? m : a.z;
}

static float half_area(vec3 lo, vec3 hi)
{
	vec3 e = v3_sub(hi, lo);
	return e.x * e.y + e.y * e.z + e.z * e.x;
}

static inline vec3 m128_to_v3(__m128 a)
{
	float f[4];
	_mm_storeu_ps(f, a);
	return v3(f[0], f[1], f[2]);
}

/* half_area of boxes held in registers (lanes x, y, z), without a trip through memory. */
static inline float half_area4(__m128 lo, __m128 hi)
{
	__m128 e = _mm_sub_ps(hi, lo);
	__m128 p = _mm_mul_ps(e, _mm_shuffle_ps(e, e, _MM_SHUFFLE(3, 0, 2, 1))); /* xy yz zx */
	__m128 s = _mm_add_ss(p, _mm_shuffle_ps(p, p, _MM_SHUFFLE(1, 1, 1, 1)));
	return _mm_cvtss_f32(_mm_add_ss(s, _mm_shuffle_ps(p, p, _MM_SHUFFLE(2, 2, 2, 2))));
}

/* The bins of the three axes for the doubled centroid c: (c - cmin) scale, clamped to the bins in
 * float before truncation (the same bin as truncating then clamping, for finite input). */
static inline __m128i bins_of(__m128 c, __m128 cmin, __m128 scale, __m128 last_bin)
{
	__m128 f = _mm_mul_ps(_mm_sub_ps(c, cmin), scale);
	f = _mm_min_ps(_mm_max_ps(f, _mm_setzero_ps()), last_bin);
	return _mm_cvttps_epi32(f);
}

/* The smallest k with 2^k >= n, for n >= 1. */
static uint32_t ceil_log2(uint32_t n) { return n <= 1 ? 0 : 32 - (uint32_t)__builtin_clz(n - 1); }

static void make_leaf(bvh_node *nd, uint32_t begin, uint32_t count)
{
	nd->first = begin;
	nd->count = count;
}

typedef struct split {
	int axis, bin; /* refs whose bin on axis is below bin go left */
	__m128 cmin, scale; /* of bins_of */
} split;

/* A leaf's cost in units of SAH_INTERSECTION_COST: its count rounded up to whole blocks, the
 * primitives one test takes at once. */
static inline uint32_t blocks(uint32_t block, uint32_t count) { return (count + block - 1) / block; }

/* blocks() of the four lanes of n, as floats, for a power-of-two block. */
static inline __m128 blocks4(uint32_t block, __m128i n)
{
	__m128i b = _mm_srli_epi32(_mm_add_epi32(n, _mm_set1_epi32((int)block - 1)), __builtin_ctz(block));
	return _mm_cvtepi32_ps(b);
}

/* half_area4 of three boxes at once (lane a: box a), the same operations in the same order. */
static inline __m128 half_area3(const __m128 lo[3], const __m128 hi[3])
{
	__m128 e0 = _mm_sub_ps(hi[0], lo[0]), e1 = _mm_sub_ps(hi[1], lo[1]), e2 = _mm_sub_ps(hi[2], lo[2]);
	__m128 t0 = _mm_unpacklo_ps(e0, e1), t1 = _mm_unpacklo_ps(e2, e2); /* x0 x1 y0 y1, x2 x2 y2 y2 */
	__m128 t2 = _mm_unpackhi_ps(e0, e1), t3 = _mm_unpackhi_ps(e2, e2); /* z0 z1 .., z2 z2 .. */
	__m128 x = _mm_movelh_ps(t0, t1), y = _mm_movehl_ps(t1, t0), z = _mm_movelh_ps(t2, t3);
	return _mm_add_ps(_mm_add_ps(_mm_mul_ps(x, y), _mm_mul_ps(y, z)), _mm_mul_ps(z, x));
}

/* a where mask is all ones, b where it is zero. */
static inline __m128i select_si128(__m128i mask, __m128i a, __m128i b)
{
	return _mm_or_si128(_mm_and_si128(mask, a), _mm_andnot_si128(mask, b));
}

/* A ref's box added to a bin's. The bin's count rides in lane 3 of its hi, as the bits of 1.0f plus
 * the count: a positive normal float for any count below 2^27, so max with a ref's 0 keeps it, and
 * no denormal ever appears. */
static inline void bin_add(__m128 *bin_lo, __m128 *bin_hi, __m128 lo, __m128 hi)
{
	*bin_lo = _mm_min_ps(*bin_lo, lo);
	__m128i bits = _mm_castps_si128(_mm_max_ps(*bin_hi, hi));
	*bin_hi = _mm_castsi128_ps(_mm_add_epi32(bits, _mm_setr_epi32(0, 0, 0, 1)));
}
/* The counts of bins bhi[0..2] (lane a: axis a; lane 3 repeats axis 2). */
static inline __m128i bin_counts(const __m128 bhi[3])
{
	__m128 a = _mm_shuffle_ps(bhi[0], bhi[1], _MM_SHUFFLE(3, 3, 3, 3));
	__m128 b = _mm_shuffle_ps(a, bhi[2], _MM_SHUFFLE(3, 3, 2, 0));
	return _mm_sub_epi32(_mm_castps_si128(b), _mm_castps_si128(_mm_set1_ps(1.0f)));
}

/* Chooses the best binned-SAH split of the task's refs. Returns false when no split beats a leaf
 * (or none exists). Nodes of fewer than SAH_BINS refs get one bin a ref: most nodes are
 * small, and clearing and sweeping all bins would cost them more than their refs do (this rather
 * than two bins a ref below 8 refs and 16 above builds 8 % faster on the head, trees as good).
 * Costs are compared multiplied by the node's area, which saves a division per candidate. The
 * sweeps take the three axes at once, one lane each; ties go to the lowest axis, then the lowest
 * bin. block is a power of two. */
BUILD_INLINE bool find_split(const build_ref *refs, const build_task *tk, uint32_t block, split *out)
{
	uint32_t count = tk->end - tk->begin;
	float node_area = half_area4(tk->lo, tk->hi);
	/* The leaf, and the inner node: SAH_TRAVERSAL_COST + SAH_INTERSECTION_COST * sum / node_area
	 * < best exactly when sum < best_sum. */
	float best = count <= BVH_MAX_LEAF ? (float)blocks(block, count) * SAH_INTERSECTION_COST : INFINITY;
	float best_sum = (best - SAH_TRAVERSAL_COST) * node_area / SAH_INTERSECTION_COST;
	int nb = count < SAH_BINS ? (int)count : SAH_BINS;
	__m128 ext = _mm_sub_ps(tk->chi, tk->clo);
	__m128 usable = _mm_cmpgt_ps(ext, _mm_setzero_ps());
	__m128 scale = _mm_and_ps(usable, _mm_div_ps(_mm_set1_ps((float)nb * (1.0f - 1e-6f)), ext));
	__m128 last_bin = _mm_set1_ps((float)(nb - 1));
	/* Bin i of axis a: the box blo[i][a], bhi[i][a], and in bhi's lane 3 its count (bin_counts):
	 * a ref's hi has 0 there, so max keeps the count, and an integer add counts the ref in one
	 * store with the box instead of a separate count's load and store. */
	__m128 blo[SAH_BINS][3], bhi[SAH_BINS][3];
	const __m128 empty_hi = _mm_setr_ps(-INFINITY, -INFINITY, -INFINITY, 1.0f);
	for (int i = 0; i < nb; i++)
		for (int ax = 0; ax < 3; ax++)
			blo[i][ax] = _mm_set1_ps(INFINITY), bhi[i][ax] = empty_hi;
	for (uint32_t i = tk->begin; i < tk->end; i++) {
		__m128 lo = ref_lo(&refs[i]), hi = refs[i].hi;
		__m128i k = bins_of(_mm_add_ps(lo, hi), tk->clo, scale, last_bin);
		/* Bins are below 2^16: the low half of lanes 1 and 2 is the bin. */
		int k0 = _mm_cvtsi128_si32(k), k1 = _mm_extract_epi16(k, 2), k2 = _mm_extract_epi16(k, 4);
		bin_add(&blo[k0][0], &bhi[k0][0], lo, hi), bin_add(&blo[k1][1], &bhi[k1][1], lo, hi);
		bin_add(&blo[k2][2], &bhi[k2][2], lo, hi);
	}
	/* Sweep from the right: the cost of the refs of bins i and up, then from the left. */
	__m128 right_cost[SAH_BINS];
	__m128 lo[3], hi[3];
	__m128i n = _mm_setzero_si128();
	for (int ax = 0; ax < 3; ax++)
		lo[ax] = _mm_set1_ps(INFINITY), hi[ax] = _mm_set1_ps(-INFINITY);
	for (int i = nb - 1; i > 0; i--) {
		for (int ax = 0; ax < 3; ax++)
			lo[ax] = _mm_min_ps(lo[ax], blo[i][ax]), hi[ax] = _mm_max_ps(hi[ax], bhi[i][ax]);
		n = _mm_add_epi32(n, bin_counts(bhi[i]));
		right_cost[i] = _mm_mul_ps(half_area3(lo, hi), blocks4(block, n));
	}
	for (int ax = 0; ax < 3; ax++)
		lo[ax] = _mm_set1_ps(INFINITY), hi[ax] = _mm_set1_ps(-INFINITY);
	n = _mm_setzero_si128();
	/* Lane 3 repeats axis 2 and is not looked at. */
	const __m128i all = _mm_set1_epi32((int)count), zero = _mm_setzero_si128();
	__m128 best4 = _mm_set1_ps(best_sum);
	__m128i best_bin = _mm_setzero_si128();
	for (int i = 0; i < nb - 1; i++) {
		for (int ax = 0; ax < 3; ax++)
			lo[ax] = _mm_min_ps(lo[ax], blo[i][ax]), hi[ax] = _mm_max_ps(hi[ax], bhi[i][ax]);
		n = _mm_add_epi32(n, bin_counts(bhi[i]));
		__m128 sum = _mm_add_ps(_mm_mul_ps(half_area3(lo, hi), blocks4(block, n)), right_cost[i + 1]);
		__m128i empty = _mm_or_si128(_mm_cmpeq_epi32(n, zero), _mm_cmpeq_epi32(n, all));
		__m128i better = _mm_andnot_si128(empty, _mm_castps_si128(_mm_cmplt_ps(sum, best4)));
		__m128i sum_bits = _mm_castps_si128(sum), best_bits = _mm_castps_si128(best4);
		best4 = _mm_castsi128_ps(select_si128(better, sum_bits, best_bits));
		best_bin = select_si128(better, _mm_set1_epi32(i + 1), best_bin);
	}
	float sums[4];
	int bins[4];
	_mm_storeu_ps(sums, best4);
	_mm_storeu_si128((__m128i *)bins, best_bin);
	bool found = false;
	for (int ax = 0; ax < 3; ax++)
		if (bins[ax] != 0 && sums[ax] < best_sum) {
			best_sum = sums[ax], out->axis = ax, out->bin = bins[ax];
			found = true;
		}
	out->cmin = tk->clo, out->scale = scale;
	return found;
}

/* The two children of a task split at mid, their boxes and centroid boxes filled. */
static void child_tasks(const build_ref *refs, const build_task *tk, uint32_t left, uint32_t mid,
			build_task *l, build_task *r)
{
	*l = (build_task){left, tk->begin, mid, tk->depth + 1, _mm_set1_ps(INFINITY),
			  _mm_set1_ps(-INFINITY), _mm_set1_ps(INFINITY), _mm_set1_ps(-INFINITY)};
	*r = (build_task){left + 1, mid, tk->end, tk->depth + 1, l->lo, l->hi, l->clo, l->chi};
	for (uint32_t i = tk->begin; i < tk->end; i++) {
		build_task *t = i < mid ? l : r;
		__m128 lo = ref_lo(&refs[i]), hi = refs[i].hi, c = _mm_add_ps(lo, hi);
		t->lo = _mm_min_ps(t->lo, lo), t->hi = _mm_max_ps(t->hi, hi);
		t->clo = _mm_min_ps(t->clo, c), t->chi = _mm_max_ps(t->chi, c);
	}
}

/* Lane axis (a constant) of a in all four. */
BUILD_INLINE __m128 broadcast_lane(__m128 a, const int axis)
{
	if (axis == 0)
		return _mm_shuffle_ps(a, a, 0x00);
	return axis == 1 ? _mm_shuffle_ps(a, a, 0x55) : _mm_shuffle_ps(a, a, 0xaa);
}

/* Moves the refs of split s's left side to the front of the task's range, returns where the right
 * side starts, and fills the children's boxes as it goes. Branch-free (the side of a ref is a
 * coin toss near the root, and a branch on it mispredicts half the time): Lomuto's scheme, where
 * refs[begin, j) went left and refs[j, i) right, with the swap of refs i and j done for every ref
 * and j advanced for those going left; a box ignores the refs of the other side through NaN lanes,
 * which min and max pass over (_mm_min_ps(a, b) is a < b ? a : b). The axis is a constant in each
 * of the three copies, so the side's mask is a shuffle of the compare, all in SSE registers. */
BUILD_INLINE uint32_t partition_axis(build_ref *refs, const build_task *tk, const split *s, const int axis,
				     uint32_t left, build_task *l, build_task *r)
{
	/* bins_of(c)[axis] < bin exactly when !(f >= bin) for f = (c - cmin) scale on that lane: the
	 * bins truncate after clamping to [0, nb - 1], 1 <= bin <= nb - 1, and a NaN goes to bin 0. */
	__m128 bound = _mm_set1_ps((float)s->bin);
	__m128 llo = _mm_set1_ps(INFINITY), lhi = _mm_set1_ps(-INFINITY), lclo = llo, lchi = lhi;
	__m128 rlo = llo, rhi = lhi, rclo = llo, rchi = lhi;
	const __m128 ones = _mm_castsi128_ps(_mm_set1_epi32(-1));
	uint32_t j = tk->begin;
	for (uint32_t i = tk->begin; i < tk->end; i++) {
		build_ref ref = refs[i];
		__m128 lo = ref_lo(&ref), c = _mm_add_ps(lo, ref.hi);
		__m128 f = _mm_mul_ps(_mm_sub_ps(c, s->cmin), s->scale);
		__m128 to_l = broadcast_lane(_mm_cmpnge_ps(f, bound), axis);
		__m128 to_r = _mm_xor_ps(to_l, ones);
		llo = _mm_min_ps(_mm_or_ps(lo, to_r), llo), lhi = _mm_max_ps(_mm_or_ps(ref.hi, to_r), lhi);
		lclo = _mm_min_ps(_mm_or_ps(c, to_r), lclo), lchi = _mm_max_ps(_mm_or_ps(c, to_r), lchi);
		rlo = _mm_min_ps(_mm_or_ps(lo, to_l), rlo), rhi = _mm_max_ps(_mm_or_ps(ref.hi, to_l), rhi);
		rclo = _mm_min_ps(_mm_or_ps(c, to_l), rclo), rchi = _mm_max_ps(_mm_or_ps(c, to_l), rchi);
		refs[i] = refs[j], refs[j] = ref;
		j += (uint32_t)_mm_movemask_ps(to_l) & 1;
	}
	*l = (build_task){left, tk->begin, j, tk->depth + 1, llo, lhi, lclo, lchi};
	*r = (build_task){left + 1, j, tk->end, tk->depth + 1, rlo, rhi, rclo, rchi};
	return j;
}
static uint32_t partition(build_ref *refs, const build_task *tk, const split *s, uint32_t left, build_task *l,
			  build_task *r)
{
	switch (s->axis) {
	case 0:
		return partition_axis(refs, tk, s, 0, left, l, r);
	case 1:
		return partition_axis(refs, tk, s, 1, left, l, r);
	default:
		return partition_axis(refs, tk, s, 2, left, l, r);
	}
}

/* The root task of refs[0, n), and ref i's box (lo and hi with lane 3 zero) added to it. */
static build_task root_task(uint32_t n)
{
	return (build_task){0, 0, n, 0, _mm_set1_ps(INFINITY), _mm_set1_ps(-INFINITY), _mm_set1_ps(INFINITY),
			    _mm_set1_ps(-INFINITY)};
}
static inline void add_ref(build_task *root, build_ref *ref, __m128 lo, __m128 hi, uint32_t id)
{
	__m128 c = _mm_add_ps(lo, hi);
	ref->lo = _mm_or_ps(lo, _mm_castsi128_ps(_mm_setr_epi32(0, 0, 0, (int)id))), ref->hi = hi;
	root->lo = _mm_min_ps(root->lo, lo), root->hi = _mm_max_ps(root->hi, hi);
	root->clo = _mm_min_ps(root->clo, c), root->chi = _mm_max_ps(root->chi, c);
}

/* Vertex i of positions[0, n) in lanes x, y, z, lane 3 zero: one unaligned load, except for the
 * last vertex, where it would read past the array. */
static inline __m128 load_vertex(const vec3 *positions, uint32_t n, uint32_t i)
{
	if (i + 1 < n)
		return _mm_and_ps(_mm_loadu_ps(&positions[i].x), xyz_mask());
	return _mm_setr_ps(positions[i].x, positions[i].y, positions[i].z, 0.0f);
}

/* tri_is_degenerate (tri.h) of vertices in registers (lane 3 zero): the same operations in the
 * same order, so the same triangles are left out. */
static inline bool tri_is_degenerate4(__m128 v0, __m128 v1, __m128 v2)
{
	__m128 e1 = _mm_sub_ps(v1, v0), e2 = _mm_sub_ps(v2, v0);
	__m128 c = _mm_sub_ps(_mm_mul_ps(_mm_shuffle_ps(e1, e1, _MM_SHUFFLE(3, 0, 2, 1)),
					 _mm_shuffle_ps(e2, e2, _MM_SHUFFLE(3, 1, 0, 2))),
			      _mm_mul_ps(_mm_shuffle_ps(e1, e1, _MM_SHUFFLE(3, 1, 0, 2)),
					 _mm_shuffle_ps(e2, e2, _MM_SHUFFLE(3, 0, 2, 1))));
	/* A lane is not finite when its exponent bits are all ones (lanes x, y, z are looked at). */
	const __m128i exp = _mm_set1_epi32(0x7f800000);
	__m128i bad = _mm_or_si128(
		_mm_or_si128(_mm_cmpeq_epi32(_mm_and_si128(_mm_castps_si128(v0), exp), exp),
			     _mm_cmpeq_epi32(_mm_and_si128(_mm_castps_si128(v1), exp), exp)),
		_mm_or_si128(_mm_cmpeq_epi32(_mm_and_si128(_mm_castps_si128(v2), exp), exp),
			     _mm_cmpeq_epi32(_mm_and_si128(_mm_castps_si128(c), exp), exp)));
	__m128 sq = _mm_mul_ps(c, c);
	__m128 len2 = _mm_add_ss(_mm_add_ss(sq, _mm_shuffle_ps(sq, sq, _MM_SHUFFLE(1, 1, 1, 1))),
				 _mm_shuffle_ps(sq, sq, _MM_SHUFFLE(2, 2, 2, 2)));
	return (_mm_movemask_epi8(bad) & 0x0fff) != 0 || !(_mm_cvtss_f32(len2) > 0.0f);
}

/* Whether count refs may make a leaf that costs no more than SAH_TRAVERSAL_COST: no split can beat
 * it then (find_split returns false), so the binning is skipped. With blocks of four, that is
 * every node of up to eight refs: two fifths of the nodes binned otherwise (head). */
static inline bool leaf_wins(uint32_t block, uint32_t count)
{
	return count <= BVH_MAX_LEAF &&
	       (float)blocks(block, count) * SAH_INTERSECTION_COST <= SAH_TRAVERSAL_COST;
}

/* The binary tree over refs[0, root.end) (root.end > 0), which it reorders into leaf order.
 * Inlined into its two callers, so leaf_block is a constant and blocks() divides by shifts. */
BUILD_INLINE bool build_tree(build_ref *refs, build_task root, uint32_t leaf_block, bvh_node **nodes_out,
		       uint32_t *num_nodes)
{
	uint32_t n = root.end;
	bvh_node *nodes = mem_alloc(2 * (size_t)n - 1, sizeof *nodes);
	if (!nodes)
		return false;
	uint32_t used = 1;
	build_task stack[BVH_MAX_DEPTH + 2];
	int sp = 0;
	stack[sp++] = root;
	while (sp > 0) {
		build_task tk = stack[--sp];
		bvh_node *nd = &nodes[tk.node];
		vec3 blo = m128_to_v3(tk.lo), bhi = m128_to_v3(tk.hi);
		nd->lo[0] = blo.x, nd->lo[1] = blo.y, nd->lo[2] = blo.z;
		nd->hi[0] = bhi.x, nd->hi[1] = bhi.y, nd->hi[2] = bhi.z;
		uint32_t count = tk.end - tk.begin;
		/* A split costs at least SAH_TRAVERSAL_COST; a leaf of one block costs
		 * SAH_INTERSECTION_COST: no need to bin when the leaf is surely cheaper. */
		if (count == 1 || (count <= leaf_block && SAH_TRAVERSAL_COST >= SAH_INTERSECTION_COST)) {
			make_leaf(nd, tk.begin, count);
			continue;
		}
		split s = {0};
		uint32_t left = used;
		build_task l, r;
		if (tk.depth + ceil_log2(count) >= BVH_MAX_DEPTH - 1) {
			/* Near the depth limit (a degenerate distribution): halving takes ceil_log2(count)
			 * more levels to single refs, so the tree stays within the limit and every leaf
			 * within BVH_MAX_LEAF. */
			child_tasks(refs, &tk, left, tk.begin + count / 2, &l, &r);
		} else if (!leaf_wins(leaf_block, count) && find_split(refs, &tk, leaf_block, &s)) {
			partition(refs, &tk, &s, left, &l, &r);
		} else if (count <= BVH_MAX_LEAF) {
			make_leaf(nd, tk.begin, count);
			continue;
		} else {
			/* All centroids coincide (or no split helps): halve by position in the array. */
			child_tasks(refs, &tk, left, tk.begin + count / 2, &l, &r);
		}
		used += 2;
		nd->first = left;
		nd->count = BVH_INNER | (uint32_t)s.axis;
		stack[sp++] = r;
		stack[sp++] = l;
	}
	bvh_node *shrunk = mem_realloc(nodes, used, sizeof *nodes);
	*nodes_out = shrunk ? shrunk : nodes;
	*num_nodes = used;
	return true;
}

bool bvh_build_nodes(const vec3 *lo, const vec3 *hi, uint32_t n, uint32_t leaf_block, bvh_node **nodes_out,
		     uint32_t *num_nodes, uint32_t *perm)
{
	*nodes_out = NULL, *num_nodes = 0;
	if (n == 0)
		return true;
	build_ref *refs = mem_alloc(n, sizeof *refs);
	if (!refs)
		return false;
	build_task root = root_task(n);
	for (uint32_t i = 0; i < n; i++)
		add_ref(&root, &refs[i], _mm_setr_ps(lo[i].x, lo[i].y, lo[i].z, 0.0f),
			_mm_setr_ps(hi[i].x, hi[i].y, hi[i].z, 0.0f), i);
	bool ok = build_tree(refs, root, leaf_block, nodes_out, num_nodes);
	for (uint32_t i = 0; ok && i < n; i++)
		perm[i] = refs[i].id;
	mem_free(refs);
	return ok;
}

/* The collapse of a binary tree into 4-wide nodes: each 4-wide node takes a binary inner node's
 * two children and keeps opening the inner one of largest area until it has four (Wald et al.
 * 2008, "Getting Rid of Packets", section 3). Every 4-wide node consumes at least one binary
 * inner node, so there are at most max(1, inner) of them. Nodes are laid out depth first (a
 * node's children side by side, then the first child's subtree): a ray's next node is more often
 * in a cache line it already fetched than in breadth-first order. */
static bool collapse(const bvh_node *bin, uint32_t num_bin, bvh4_node **out, uint32_t *num_out)
{
	uint32_t cap = num_bin / 2 + 1;
	bvh4_node *nodes = mem_alloc(cap, sizeof *nodes);
	uint32_t *src = mem_alloc(cap, sizeof *src); /* the binary node each 4-wide node stands for */
	if (!nodes || !src) {
		mem_free(nodes), mem_free(src);
		return false;
	}
	uint32_t used = 1;
	src[0] = 0;
	uint32_t todo[BVH4_STACK];
	int sp = 0;
	todo[sp++] = 0;
	while (sp > 0) {
		uint32_t i = todo[--sp];
		const bvh_node *s = &bin[src[i]];
		uint32_t slot[4], n = 0;
		if (s->count & BVH_INNER)
			slot[n++] = s->first, slot[n++] = s->first + 1;
		else
			slot[n++] = src[i]; /* the root is a leaf */
		while (n < 4) {
			int open = -1;
			float best = -1.0f;
			for (uint32_t k = 0; k < n; k++) {
				const bvh_node *c = &bin[slot[k]];
				float a = half_area(bvh_node_lo(c), bvh_node_hi(c));
				if ((c->count & BVH_INNER) && a > best)
					best = a, open = (int)k;
			}
			if (open < 0)
				break;
			uint32_t c0 = bin[slot[open]].first;
			slot[open] = c0, slot[n++] = c0 + 1;
		}
		bvh4_node *nd = &nodes[i];
		int pushed = sp;
		for (uint32_t k = 0; k < 4; k++) {
			if (k >= n) {
				for (int p = 0; p < 3; p++)
					nd->b[p][k] = INFINITY, nd->b[3 + p][k] = -INFINITY;
				nd->child[k] = BVH4_EMPTY;
				continue;
			}
			const bvh_node *c = &bin[slot[k]];
			for (int p = 0; p < 3; p++)
				nd->b[p][k] = c->lo[p], nd->b[3 + p][k] = c->hi[p];
			if (c->count & BVH_INNER) {
				src[used] = slot[k];
				todo[sp++] = used;
				nd->child[k] = used++;
			} else {
				nd->child[k] = BVH4_LEAF | (c->count - 1) << BVH4_COUNT_SHIFT | c->first;
			}
		}
		/* The first child on top. */
		for (int lo = pushed, hi = sp - 1; lo < hi; lo++, hi--) {
			uint32_t tmp = todo[lo];
			todo[lo] = todo[hi], todo[hi] = tmp;
		}
	}
	mem_free(src);
	bvh4_node *shrunk = mem_realloc(nodes, used, sizeof *nodes);
	*out = shrunk ? shrunk : nodes;
	*num_out = used;
	return true;
}

/* The triangles of the leaf ref, as groups (bvh_word): leaf slot i is triangle refs[i].id. */
static void write_leaf(bvh_word *leaf, uint32_t ref, const vec3 *positions, const uint32_t *indices,
		       const build_ref *refs)
{
	uint32_t first = ref & BVH4_FIRST_MASK, count = (ref >> BVH4_COUNT_SHIFT & 15) + 1;
	for (uint32_t g = 0; g < count; g += 4) {
		uint32_t m = count - g < 4 ? count - g : 4;
		bvh_word *w = &leaf[GROUP_WORDS * (size_t)(first + g)];
		for (uint32_t j = 0; j < m; j++) {
			uint32_t f = refs[first + g + j].id;
			for (int k = 0; k < 3; k++) {
				vec3 p = positions[indices[3 * (size_t)f + k]];
				w[(3 * k) * m + j].f = p.x, w[(3 * k + 1) * m + j].f = p.y, w[(3 * k + 2) * m + j].f = p.z;
			}
			w[9 * m + j].u = f;
		}
	}
}

bvh *bvh_build(const vec3 *positions, uint32_t num_vertices, const uint32_t *indices,
	       uint32_t num_triangles)
{
	for (size_t i = 0; i < 3 * (size_t)num_triangles; i++)
		if (indices[i] >= num_vertices)
			return NULL;
	/* A leaf reference holds its first triangle in BVH4_COUNT_SHIFT bits. */
	if (num_triangles > BVH4_FIRST_MASK)
		return NULL;
	bvh *b = mem_calloc(1, sizeof *b);
	build_ref *refs = mem_alloc(num_triangles, sizeof *refs);
	bvh_node *bin = NULL;
	uint32_t num_bin = 0;
	bool ok = b && refs;
	uint32_t n = 0;
	if (ok) {
		/* The refs of the triangles that can be hit, their ids the mesh's. */
		build_task root = root_task(0);
		for (uint32_t f = 0; f < num_triangles; f++) {
			const uint32_t *ix = indices + 3 * f;
			__m128 v0 = load_vertex(positions, num_vertices, ix[0]);
			__m128 v1 = load_vertex(positions, num_vertices, ix[1]);
			__m128 v2 = load_vertex(positions, num_vertices, ix[2]);
			if (tri_is_degenerate4(v0, v1, v2))
				continue;
			__m128 lo = _mm_min_ps(v0, _mm_min_ps(v1, v2));
			add_ref(&root, &refs[n++], lo, _mm_max_ps(v0, _mm_max_ps(v1, v2)), f);
		}
		root.end = n;
		ok = n == 0 || build_tree(refs, root, BVH_LEAF_BLOCK, &bin, &num_bin);
	}
	if (ok && n > 0) {
		b->lo = bvh_node_lo(&bin[0]), b->hi = bvh_node_hi(&bin[0]);
		b->leaf = mem_calloc(GROUP_WORDS * (size_t)n + LEAF_PAD_WORDS, sizeof *b->leaf);
		ok = b->leaf && collapse(bin, num_bin, &b->nodes, &b->num_nodes);
	}
	if (ok && n > 0) {
		for (uint32_t i = 0; i < b->num_nodes; i++)
			for (int k = 0; k < 4; k++) {
				uint32_t ref = b->nodes[i].child[k];
				if ((ref & BVH4_LEAF) && ref != BVH4_EMPTY)
					write_leaf(b->leaf, ref, positions, indices, refs);
			}
		b->num_tris = n;
	}
	mem_free(refs), mem_free(bin);
	if (!ok) {
		bvh_free(b);
		return NULL;
	}
	return b;
}

void bvh_free(bvh *b)
{
	if (!b)
		return;
	mem_free(b->nodes);
	mem_free(b->leaf);
	mem_free(b);
}

bool bvh_bounds(const bvh *b, vec3 *lo, vec3 *hi)
{
	if (b->num_nodes == 0)
		return false;
	*lo = b->lo, *hi = b->hi;
	return true;
}

size_t bvh_bytes(const bvh *b)
{
	return sizeof *b + (size_t)b->num_nodes * sizeof(bvh4_node) +
	       (b->num_tris ? GROUP_WORDS * (size_t)b->num_tris + LEAF_PAD_WORDS : 0) * sizeof(bvh_word);
}

uint32_t bvh_num_nodes(const bvh *b) { return b->num_nodes; }

/* Max and min that ignore a NaN in x (0 * inf, a ray in a slab's plane): the slab then does not
 * constrain, which is conservative. maxss/minss compile from this form. */
static inline float max_nan(float x, float m) { return x > m ? x : m; }
static inline float min_nan(float x, float m) { return x < m ? x : m; }

/* The slab test. The ray's direction signs pick each axis's near and far planes: lo[] sits at
 * word 0 of a node and hi[] at word 4, so the plane is word 4 * sign + axis. */
typedef struct slab_ray {
	float org[3], inv[3];
	int near_off[3], far_off[3];
	float tmin;
} slab_ray;

static inline void slab_prepare(slab_ray *s, const tri_ray *r)
{
	float o[3] = {r->org.x, r->org.y, r->org.z}, d[3] = {r->inv_dir.x, r->inv_dir.y, r->inv_dir.z};
	for (int i = 0; i < 3; i++) {
		s->org[i] = o[i], s->inv[i] = d[i];
		int neg = d[i] < 0.0f;
		s->near_off[i] = 4 * neg + i, s->far_off[i] = 4 * (1 - neg) + i;
	}
	s->tmin = r->tmin;
}

static inline bool node_hit(const bvh_node *nd, const slab_ray *s, float tlimit, float *tnear)
{
	const float *w = (const float *)nd;
	float tn = s->tmin, tf = tlimit;
	for (int i = 0; i < 3; i++) {
		float a = (w[s->near_off[i]] - s->org[i]) * s->inv[i];
		float b = (w[s->far_off[i]] - s->org[i]) * s->inv[i];
		tn = max_nan(a, tn), tf = min_nan(b, tf);
	}
	*tnear = tn;
	return tn <= tf * BVH_SLAB_SLACK;
}

bool bvh_node_hit(const bvh_node *nd, const tri_ray *r, float tlimit, float *tnear)
{
	slab_ray s;
	slab_prepare(&s, r);
	return node_hit(nd, &s, tlimit, tnear);
}

/* The slab test of four boxes at once: the same operations as node_hit, in the same order, so
 * each lane rounds as the scalar test does (_mm_max_ps(a, t) is a > t ? a : t, max_nan). */
typedef struct slab_ray4 {
	__m128 org[3], inv[3], tmin, slack;
	int near_plane[3], far_plane[3];
} slab_ray4;

static inline void slab_prepare4(slab_ray4 *s, const tri_ray *r)
{
	float o[3] = {r->org.x, r->org.y, r->org.z}, d[3] = {r->inv_dir.x, r->inv_dir.y, r->inv_dir.z};
	for (int i = 0; i < 3; i++) {
		s->org[i] = _mm_set1_ps(o[i]), s->inv[i] = _mm_set1_ps(d[i]);
		int neg = d[i] < 0.0f;
		s->near_plane[i] = 3 * neg + i, s->far_plane[i] = 3 * (1 - neg) + i;
	}
	s->tmin = _mm_set1_ps(r->tmin);
	s->slack = _mm_set1_ps(BVH_SLAB_SLACK);
}

/* Bit k of the result is set when child k's box may hold a hit with t in [tmin, tlimit]; tnear
 * receives the entry distances. */
static inline int node4_hit(const bvh4_node *nd, const slab_ray4 *s, float tlimit, float tnear[4])
{
	__m128 tn = s->tmin, tf = _mm_set1_ps(tlimit);
	for (int i = 0; i < 3; i++) {
		__m128 a = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(nd->b[s->near_plane[i]]), s->org[i]), s->inv[i]);
		__m128 b = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(nd->b[s->far_plane[i]]), s->org[i]), s->inv[i]);
		tn = _mm_max_ps(a, tn), tf = _mm_min_ps(b, tf);
	}
	_mm_storeu_ps(tnear, tn);
	return _mm_movemask_ps(_mm_cmple_ps(tn, _mm_mul_ps(tf, s->slack)));
}

/* Index of the lowest set bit of a non-zero mask of four bits. */
static inline int lowest_bit(int mask) { return __builtin_ctz((unsigned)mask); }

typedef struct stack_entry {
	uint32_t ref;
	float tnear;
} stack_entry;

/* The watertight test (tri_intersect) of up to four triangles of a leaf at once: the same
 * operations in the same order in each lane, so every lane rounds as tri_intersect does. Lanes
 * where U, V or W is zero need tri_intersect's double-precision decision and are left to it.
 * Returns the lanes that hit with t in [tmin, tlimit] (bits below n only) in *hit_mask and those
 * left to the scalar test in the result; t, u, v receive the lanes' values. */
typedef struct tri_ray4 {
	__m128 ox, oy, oz, sx, sy, sz, tmin; /* the origin in the ray's axis order kx, ky, kz */
	int kx, ky, kz;
} tri_ray4;

static inline void tri_ray_prepare4(tri_ray4 *q, const tri_ray *r)
{
	q->ox = _mm_set1_ps(v3_get(r->org, r->kx)), q->oy = _mm_set1_ps(v3_get(r->org, r->ky));
	q->oz = _mm_set1_ps(v3_get(r->org, r->kz));
	q->sx = _mm_set1_ps(r->sx), q->sy = _mm_set1_ps(r->sy), q->sz = _mm_set1_ps(r->sz);
	q->tmin = _mm_set1_ps(r->tmin);
	q->kx = r->kx, q->ky = r->ky, q->kz = r->kz;
}

/* Forced inlining: the leaf tests are called from two traversals each, and gcc -O2 would
 * otherwise keep them out of line and pass their results through memory. */
#define BVH_INLINE static inline __attribute__((always_inline))

/* A leaf group (bvh_word): m triangles from word w. */
BVH_INLINE __m128 group_lanes(int m)
{
	return _mm_castsi128_ps(_mm_cmplt_epi32(_mm_setr_epi32(0, 1, 2, 3), _mm_set1_epi32(m)));
}
/* Coordinate array a (0 to 8: v0x v0y v0z v1x ... v2z) of the group, lanes past m zero. */
BVH_INLINE __m128 group_load(const bvh_word *w, int m, int a, __m128 lanes)
{
	return _mm_and_ps(_mm_loadu_ps(&w[a * m].f), lanes);
}
BVH_INLINE vec3 group_vertex(const bvh_word *w, int m, int j, int vertex)
{
	return v3(w[(3 * vertex) * m + j].f, w[(3 * vertex + 1) * m + j].f, w[(3 * vertex + 2) * m + j].f);
}
BVH_INLINE uint32_t group_id(const bvh_word *w, int m, int j) { return w[9 * m + j].u; }

/* The group of m triangles at w; lanes past m are zero and never reported. */
BVH_INLINE int tri4_intersect(const tri_ray4 *q, const bvh_word *w, int m, float tlimit, int *hit_mask,
			      float t[4], float u[4], float v[4])
{
	__m128 in = group_lanes(m);
	/* The coordinate arrays are picked in the ray's axis order as they are loaded, so the
	 * permutation costs no shuffles (and no trip through memory). */
	__m128 Az = _mm_sub_ps(group_load(w, m, q->kz, in), q->oz);
	__m128 Bz = _mm_sub_ps(group_load(w, m, 3 + q->kz, in), q->oz);
	__m128 Cz = _mm_sub_ps(group_load(w, m, 6 + q->kz, in), q->oz);
	__m128 Ax = _mm_sub_ps(_mm_sub_ps(group_load(w, m, q->kx, in), q->ox), _mm_mul_ps(q->sx, Az));
	__m128 Ay = _mm_sub_ps(_mm_sub_ps(group_load(w, m, q->ky, in), q->oy), _mm_mul_ps(q->sy, Az));
	__m128 Bx = _mm_sub_ps(_mm_sub_ps(group_load(w, m, 3 + q->kx, in), q->ox), _mm_mul_ps(q->sx, Bz));
	__m128 By = _mm_sub_ps(_mm_sub_ps(group_load(w, m, 3 + q->ky, in), q->oy), _mm_mul_ps(q->sy, Bz));
	__m128 Cx = _mm_sub_ps(_mm_sub_ps(group_load(w, m, 6 + q->kx, in), q->ox), _mm_mul_ps(q->sx, Cz));
	__m128 Cy = _mm_sub_ps(_mm_sub_ps(group_load(w, m, 6 + q->ky, in), q->oy), _mm_mul_ps(q->sy, Cz));
	__m128 U = _mm_sub_ps(_mm_mul_ps(Cx, By), _mm_mul_ps(Cy, Bx));
	__m128 V = _mm_sub_ps(_mm_mul_ps(Ax, Cy), _mm_mul_ps(Ay, Cx));
	__m128 W = _mm_sub_ps(_mm_mul_ps(Bx, Ay), _mm_mul_ps(By, Ax));
	const __m128 zero = _mm_setzero_ps();
	int lanes = (1 << m) - 1;
	int scalar = _mm_movemask_ps(_mm_or_ps(_mm_or_ps(_mm_cmpeq_ps(U, zero), _mm_cmpeq_ps(V, zero)),
					       _mm_cmpeq_ps(W, zero))) & lanes;
	__m128 neg = _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(U, zero), _mm_cmplt_ps(V, zero)), _mm_cmplt_ps(W, zero));
	__m128 pos = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(U, zero), _mm_cmpgt_ps(V, zero)), _mm_cmpgt_ps(W, zero));
	__m128 det = _mm_add_ps(_mm_add_ps(U, V), W);
	__m128 T = _mm_add_ps(_mm_add_ps(_mm_mul_ps(U, _mm_mul_ps(q->sz, Az)), _mm_mul_ps(V, _mm_mul_ps(q->sz, Bz))),
			      _mm_mul_ps(W, _mm_mul_ps(q->sz, Cz)));
	__m128 tt = _mm_div_ps(T, det);
	__m128 ok = _mm_andnot_ps(_mm_and_ps(neg, pos), _mm_cmpneq_ps(det, zero));
	ok = _mm_and_ps(ok, _mm_and_ps(_mm_cmpge_ps(tt, q->tmin), _mm_cmple_ps(tt, _mm_set1_ps(tlimit))));
	*hit_mask = _mm_movemask_ps(ok) & lanes & ~scalar;
	if (*hit_mask) {
		_mm_storeu_ps(t, tt);
		_mm_storeu_ps(u, _mm_div_ps(V, det));
		_mm_storeu_ps(v, _mm_div_ps(W, det));
	}
	return scalar;
}

/* A leaf reference's triangles: the first, and how many. */
static inline uint32_t leaf_first(uint32_t ref) { return ref & BVH4_FIRST_MASK; }
static inline uint32_t leaf_count(uint32_t ref) { return (ref >> BVH4_COUNT_SHIFT & 15) + 1; }
static inline const bvh_word *leaf_group(const bvh *b, uint32_t ref, uint32_t g)
{
	return &b->leaf[GROUP_WORDS * (size_t)(leaf_first(ref) + g)];
}

bool bvh_intersect_prepared(const bvh *b, const tri_ray *r, float *tlimit, bvh_hit *hit)
{
	if (b->num_nodes == 0)
		return false;
	slab_ray4 sr;
	slab_prepare4(&sr, r);
	tri_ray4 q4;
	tri_ray_prepare4(&q4, r);
	stack_entry stack[BVH4_STACK];
	int sp = 0;
	uint32_t ref = 0;
	bool found = false;
	uint32_t best_id = UINT32_MAX;
	for (;;) {
		if (!(ref & BVH4_LEAF)) {
			const bvh4_node *nd = &b->nodes[ref];
			float tn[4];
			int mask = node4_hit(nd, &sr, *tlimit, tn);
			if (mask != 0) {
				int k0 = lowest_bit(mask);
				mask &= mask - 1;
				if (mask == 0) {
					ref = nd->child[k0];
					continue;
				}
				int k1 = lowest_bit(mask);
				mask &= mask - 1;
				if (mask == 0) {
					/* Two: go to the nearer, keep the other. */
					if (tn[k1] < tn[k0]) {
						int tk = k0;
						k0 = k1, k1 = tk;
					}
					stack[sp++] = (stack_entry){nd->child[k1], tn[k1]};
					ref = nd->child[k0];
					continue;
				}
				/* Three or four: push all sorted, the nearest on top, and take it. */
				int base = sp;
				stack[sp++] = (stack_entry){nd->child[k0], tn[k0]};
				stack[sp++] = (stack_entry){nd->child[k1], tn[k1]};
				do {
					int k = lowest_bit(mask);
					mask &= mask - 1;
					stack[sp++] = (stack_entry){nd->child[k], tn[k]};
				} while (mask != 0);
				for (int i = base + 1; i < sp; i++) {
					stack_entry e = stack[i];
					int j = i;
					for (; j > base && stack[j - 1].tnear < e.tnear; j--)
						stack[j] = stack[j - 1];
					stack[j] = e;
				}
				ref = stack[--sp].ref;
				continue;
			}
		} else {
			/* A group at a time. A hit is taken when closer, or as close with a lower id:
			 * the tie rule of the loop over all triangles, whatever the order of visits. */
			uint32_t count = leaf_count(ref);
			for (uint32_t g = 0; g < count; g += 4) {
				int m = count - g < 4 ? (int)(count - g) : 4;
				const bvh_word *w = leaf_group(b, ref, g);
				float t4[4], u4[4], v4[4];
				int hm, sc = tri4_intersect(&q4, w, m, *tlimit, &hm, t4, u4, v4);
				for (int todo = hm | sc; todo != 0; todo &= todo - 1) {
					int j = lowest_bit(todo);
					float t = t4[j], u = u4[j], v = v4[j];
					bool h = sc >> j & 1 ? tri_intersect(r, group_vertex(w, m, j, 0), group_vertex(w, m, j, 1),
									     group_vertex(w, m, j, 2), *tlimit, &t, &u, &v)
							     : t <= *tlimit;
					uint32_t id = group_id(w, m, j);
					if (h && (t < *tlimit || id < best_id)) {
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
			stack_entry e = stack[--sp];
			if (e.tnear <= *tlimit * BVH_SLAB_SLACK) {
				ref = e.ref;
				break;
			}
		}
	}
}

bool bvh_occluded_prepared(const bvh *b, const tri_ray *r)
{
	if (b->num_nodes == 0)
		return false;
	slab_ray4 sr;
	slab_prepare4(&sr, r);
	tri_ray4 q4;
	tri_ray_prepare4(&q4, r);
	uint32_t stack[BVH4_STACK];
	int sp = 0;
	uint32_t ref = 0;
	for (;;) {
		if (!(ref & BVH4_LEAF)) {
			const bvh4_node *nd = &b->nodes[ref];
			float tn[4];
			int mask = node4_hit(nd, &sr, r->tmax, tn);
			if (mask != 0) {
				ref = nd->child[lowest_bit(mask)];
				for (mask &= mask - 1; mask != 0; mask &= mask - 1)
					stack[sp++] = nd->child[lowest_bit(mask)];
				continue;
			}
		} else {
			uint32_t count = leaf_count(ref);
			for (uint32_t g = 0; g < count; g += 4) {
				int m = count - g < 4 ? (int)(count - g) : 4;
				const bvh_word *w = leaf_group(b, ref, g);
				float t4[4], u4[4], v4[4];
				int hm, sc = tri4_intersect(&q4, w, m, r->tmax, &hm, t4, u4, v4);
				if (hm)
					return true;
				for (; sc != 0; sc &= sc - 1) {
					int j = lowest_bit(sc);
					float t, u, v;
					if (tri_intersect(r, group_vertex(w, m, j, 0), group_vertex(w, m, j, 1),
							  group_vertex(w, m, j, 2), r->tmax, &t, &u, &v))
						return true;
				}
			}
		}
		if (sp == 0)
			return false;
		ref = stack[--sp];
	}
}

bool bvh_intersect(const bvh *b, const bvh_ray *ray, bvh_hit *hit)
{
	tri_ray r;
	if (!tri_ray_prepare(&r, ray->org, ray->dir, ray->tmin, ray->tmax))
		return false;
	float tlimit = ray->tmax;
	hit->inst = 0;
	return bvh_intersect_prepared(b, &r, &tlimit, hit);
}

bool bvh_occluded(const bvh *b, const bvh_ray *ray)
{
	tri_ray r;
	if (!tri_ray_prepare(&r, ray->org, ray->dir, ray->tmin, ray->tmax))
		return false;
	return bvh_occluded_prepared(b, &r);
}

/* A circle prepared for box tests: its plane normal m = t x n and the slack. */
typedef struct circle_prep {
	vec3 lo, hi; /* the circle's own bounds, grown by the slack */
	vec3 c, t, n, m;
	float r, slack, rmax2, rmin2; /* rmin2 < 0: no inner bound */
	bool full, in_plane; /* in_plane: t and n orthonormal enough for the in-plane tests */
} circle_prep;

/* The slack covers rounding of box and circle data of magnitude up to `extent` (the largest
 * coordinate of the boxes that will be tested). */
static bool circle_prepare(const tri_circle *q, float extent, circle_prep *p)
{
	if (!v3_is_finite(q->centre) || !v3_is_finite(q->t) || !v3_is_finite(q->n) || !isfinite(q->radius) ||
	    q->radius < 0.0f)
		return false;
	p->c = q->centre, p->t = q->t, p->n = q->n, p->m = v3_cross(q->t, q->n), p->r = q->radius, p->full = q->full;
	float ortho = fmax3(v3(fabsf(v3_dot(q->t, q->t) - 1.0f), fabsf(v3_dot(q->n, q->n) - 1.0f),
			       fabsf(v3_dot(q->t, q->n))));
	p->in_plane = ortho <= BVH_CIRCLE_ORTHO_TOL;
	p->slack = BVH_CIRCLE_SLACK * (q->radius + fmax3(v3_abs(q->centre)) + extent);
	p->rmax2 = (p->r + p->slack) * (p->r + p->slack);
	float rmin = p->r - p->slack;
	p->rmin2 = rmin > 0.0f ? rmin * rmin : -1.0f;
	/* Bounds of the circle: along axis i, cos(theta) t_i + sin(theta) n_i spans
	 * +-sqrt(t_i^2 + n_i^2); a half circle reaches the positive end only when t_i >= 0 (else its
	 * ends, +-n_i, bound it), the negative end only when t_i <= 0. */
	float tc[3] = {q->t.x, q->t.y, q->t.z}, nc[3] = {q->n.x, q->n.y, q->n.z}, lo[3], hi[3];
	for (int i = 0; i < 3; i++) {
		float a = sqrtf(tc[i] * tc[i] + nc[i] * nc[i]), an = fabsf(nc[i]);
		float up = q->full || tc[i] >= 0.0f ? a : an, down = q->full || tc[i] <= 0.0f ? a : an;
		lo[i] = -down * q->radius - p->slack, hi[i] = up * q->radius + p->slack;
	}
	p->lo = v3_add(q->centre, v3(lo[0], lo[1], lo[2]));
	p->hi = v3_add(q->centre, v3(hi[0], hi[1], hi[2]));
	return true;
}

static bool box_circle(const circle_prep *p, vec3 lo, vec3 hi)
{
	/* All tests evaluated, one branch: cheaper than early exits that mispredict. */
	bool bounds = (lo.x <= p->hi.x) & (lo.y <= p->hi.y) & (lo.z <= p->hi.z) & (hi.x >= p->lo.x) &
		      (hi.y >= p->lo.y) & (hi.z >= p->lo.z);
	vec3 e = v3_scale(v3_sub(hi, lo), 0.5f);
	vec3 rel = v3_sub(v3_scale(v3_add(lo, hi), 0.5f), p->c);
	/* The box meets the plane: its projection on m holds the centre's. */
	bool plane = fabsf(v3_dot(p->m, rel)) <= v3_dot(v3_abs(p->m), e) + p->slack;
	/* For a half circle, the box reaches the side cos theta >= 0. */
	bool side = p->full | (v3_dot(p->t, rel) + v3_dot(v3_abs(p->t), e) >= -p->slack);
	/* The box meets the sphere of radius r: nearest point inside, farthest outside. */
	vec3 a = v3_abs(rel);
	vec3 dn = vmax(v3_sub(a, e), v3s(0.0f)), df = v3_add(a, e);
	bool shell = (v3_length2(dn) <= p->rmax2) & (v3_length2(df) >= p->rmin2);
	/* The same in the plane: the box's part in the plane projects, in the axes t and n, into
	 * the rectangle of its projections, so its distances to the centre lie between the
	 * rectangle's nearest and farthest. Tighter than the sphere for boxes that stick out of
	 * the plane (the sphere counts that part). */
	float pt = fabsf(v3_dot(p->t, rel)), et = v3_dot(v3_abs(p->t), e);
	float pn = fabsf(v3_dot(p->n, rel)), en = v3_dot(v3_abs(p->n), e);
	float nt = pt - et > 0.0f ? pt - et : 0.0f, nn = pn - en > 0.0f ? pn - en : 0.0f;
	float ft = pt + et, fn = pn + en;
	bool ring = (!p->in_plane) | ((nt * nt + nn * nn <= p->rmax2) & (ft * ft + fn * fn >= p->rmin2));
	return bounds & plane & side & shell & ring;
}

static float box_extent(vec3 lo, vec3 hi) { return fmax3(vmax(v3_abs(lo), v3_abs(hi))); }

bool bvh_box_circle(vec3 lo, vec3 hi, const tri_circle *q)
{
	circle_prep p;
	return circle_prepare(q, box_extent(lo, hi), &p) && box_circle(&p, lo, hi);
}

/* box_circle on the four children of a node, lane by lane with the same operations in the same
 * order, so each lane is exactly as conservative as the scalar test. An empty child fails the
 * bounds test (lo = +inf). */
typedef struct circle_prep4 {
	__m128 lo[3], hi[3], c[3], m[3], abs_m[3], t[3], abs_t[3], n[3], abs_n[3];
	__m128 slack, neg_slack, rmax2, rmin2;
	__m128 radius; /* for group_circle */
	bool full, in_plane;
} circle_prep4;

static void circle_prepare4(const circle_prep *p, circle_prep4 *q)
{
	vec3 am = v3_abs(p->m), at = v3_abs(p->t), an = v3_abs(p->n);
	for (int i = 0; i < 3; i++) {
		q->lo[i] = _mm_set1_ps(v3_get(p->lo, i)), q->hi[i] = _mm_set1_ps(v3_get(p->hi, i));
		q->c[i] = _mm_set1_ps(v3_get(p->c, i));
		q->m[i] = _mm_set1_ps(v3_get(p->m, i)), q->abs_m[i] = _mm_set1_ps(v3_get(am, i));
		q->t[i] = _mm_set1_ps(v3_get(p->t, i)), q->abs_t[i] = _mm_set1_ps(v3_get(at, i));
		q->n[i] = _mm_set1_ps(v3_get(p->n, i)), q->abs_n[i] = _mm_set1_ps(v3_get(an, i));
	}
	q->slack = _mm_set1_ps(p->slack), q->neg_slack = _mm_set1_ps(-p->slack);
	q->rmax2 = _mm_set1_ps(p->rmax2), q->rmin2 = _mm_set1_ps(p->rmin2);
	q->radius = _mm_set1_ps(p->r);
	q->full = p->full, q->in_plane = p->in_plane;
}

static inline __m128 abs4(__m128 x) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), x); }
static inline __m128 dot4(const __m128 a[3], const __m128 b[3])
{
	return _mm_add_ps(_mm_add_ps(_mm_mul_ps(a[0], b[0]), _mm_mul_ps(a[1], b[1])), _mm_mul_ps(a[2], b[2]));
}

static inline int node4_circle(const bvh4_node *nd, const circle_prep4 *p)
{
	const __m128 half = _mm_set1_ps(0.5f), zero = _mm_setzero_ps();
	__m128 ok = _mm_castsi128_ps(_mm_set1_epi32(-1));
	__m128 e[3], rel[3], a[3], dn[3], df[3];
	for (int i = 0; i < 3; i++) {
		__m128 lo = _mm_load_ps(nd->b[i]), hi = _mm_load_ps(nd->b[3 + i]);
		ok = _mm_and_ps(ok, _mm_and_ps(_mm_cmple_ps(lo, p->hi[i]), _mm_cmpge_ps(hi, p->lo[i])));
		e[i] = _mm_mul_ps(_mm_sub_ps(hi, lo), half);
		rel[i] = _mm_sub_ps(_mm_mul_ps(_mm_add_ps(lo, hi), half), p->c[i]);
		a[i] = abs4(rel[i]);
		dn[i] = _mm_max_ps(_mm_sub_ps(a[i], e[i]), zero);
		df[i] = _mm_add_ps(a[i], e[i]);
	}
	__m128 plane = _mm_cmple_ps(abs4(dot4(p->m, rel)), _mm_add_ps(dot4(p->abs_m, e), p->slack));
	ok = _mm_and_ps(ok, plane);
	if (!p->full)
		ok = _mm_and_ps(ok, _mm_cmpge_ps(_mm_add_ps(dot4(p->t, rel), dot4(p->abs_t, e)), p->neg_slack));
	ok = _mm_and_ps(ok, _mm_cmple_ps(dot4(dn, dn), p->rmax2));
	ok = _mm_and_ps(ok, _mm_cmpge_ps(dot4(df, df), p->rmin2));
	if (p->in_plane) {
		__m128 pt = abs4(dot4(p->t, rel)), et = dot4(p->abs_t, e);
		__m128 pn = abs4(dot4(p->n, rel)), en = dot4(p->abs_n, e);
		__m128 nt = _mm_max_ps(_mm_sub_ps(pt, et), zero), nn = _mm_max_ps(_mm_sub_ps(pn, en), zero);
		__m128 ft = _mm_add_ps(pt, et), fn = _mm_add_ps(pn, en);
		ok = _mm_and_ps(ok, _mm_cmple_ps(_mm_add_ps(_mm_mul_ps(nt, nt), _mm_mul_ps(nn, nn)), p->rmax2));
		ok = _mm_and_ps(ok, _mm_cmpge_ps(_mm_add_ps(_mm_mul_ps(ft, ft), _mm_mul_ps(fn, fn)), p->rmin2));
	}
	return _mm_movemask_ps(ok);
}

/* Relative size of the margins of group_circle: tri_circle_intersect's float pre-test's. */
#define GROUP_CIRCLE_MARGIN 1e-5f

/* The triangles of a group that may meet the circle (a lane mask): cheap float tests that reject
 * only triangles tri_circle_intersect gives no hit for, so its double-precision work is spent on
 * few. (1) Its plane pre-test, the same operations in the same order: all vertices clearly on one
 * side of the circle's plane. Then, with the margin grown by the radius's rounding: (2) all
 * vertices inside the sphere of radius r about the centre (the triangle, convex, lies inside:
 * its segment cannot reach the circle); (3) the triangle's box entirely outside that sphere; (4)
 * for a half circle, all vertices on the side cos theta < 0; (5) and (6), (2) and (3) in the plane,
 * with the vertices projected on the axes t and n: the segment lies in the projected triangle;
 * (7) the segment itself (segment_misses). */
static inline __m128 select4(__m128 mask, __m128 a, __m128 b)
{
	return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b));
}

/* The lanes of group_circle whose plane segment surely misses the circle. Taken only where all
 * vertices are clearly off the plane (|d| > margin, d's error bound), so the edges that cross it
 * are the exact test's two. An end on edge (i, j) is rel_i + s (rel_j - rel_i) with
 * s = d_i / (d_i - d_j); errors of up to margin in d_i and d_j move s by at most
 * 2 margin / (|d_i| + |d_j| - 2 margin), so the end by that times |rel_j - rel_i| (bounded by its
 * L1 norm). Misses: both ends inside the sphere, the segment's nearest point outside it, or, for a
 * half circle, both ends on the side cos theta < 0, each by the ends' error and the margin sm. */
BVH_INLINE int segment_misses(const circle_prep4 *p, __m128 rel[3][3], const __m128 d[3], __m128 margin,
			      __m128 sm)
{
	const __m128 zero = _mm_setzero_ps(), one = _mm_set1_ps(1.0f);
	__m128 ad[3] = {abs4(d[0]), abs4(d[1]), abs4(d[2])};
	__m128 sure = _mm_and_ps(_mm_and_ps(_mm_cmpgt_ps(ad[0], margin), _mm_cmpgt_ps(ad[1], margin)),
				 _mm_cmpgt_ps(ad[2], margin));
	if (!_mm_movemask_ps(sure))
		return 0;
	__m128 two_margin = _mm_add_ps(margin, margin);
	__m128 x[3][3], err[3], crosses[3];
	for (int e = 0; e < 3; e++) {
		int i = e, j = e == 2 ? 0 : e + 1;
		__m128 s = _mm_div_ps(d[i], _mm_sub_ps(d[i], d[j]));
		__m128 l1 = zero;
		for (int a = 0; a < 3; a++) {
			__m128 dv = _mm_sub_ps(rel[j][a], rel[i][a]);
			x[e][a] = _mm_add_ps(rel[i][a], _mm_mul_ps(s, dv));
			l1 = _mm_add_ps(l1, abs4(dv));
		}
		err[e] = _mm_div_ps(_mm_mul_ps(two_margin, l1), _mm_sub_ps(_mm_add_ps(ad[i], ad[j]), two_margin));
		crosses[e] = _mm_xor_ps(_mm_cmplt_ps(d[i], zero), _mm_cmplt_ps(d[j], zero));
	}
	/* The two crossing edges: (0, 1), (0, 2) or (1, 2). */
	__m128 e1[3], e2[3];
	for (int a = 0; a < 3; a++)
		e1[a] = select4(crosses[0], x[0][a], x[1][a]), e2[a] = select4(crosses[2], x[2][a], x[1][a]);
	__m128 err_max = _mm_max_ps(select4(crosses[0], err[0], err[1]), select4(crosses[2], err[2], err[1]));
	__m128 slack = _mm_add_ps(sm, err_max);
	__m128 rin = _mm_sub_ps(p->radius, slack), rout = _mm_add_ps(p->radius, slack);
	__m128 rin2 = _mm_mul_ps(rin, rin);
	__m128 inside = _mm_and_ps(_mm_and_ps(_mm_cmplt_ps(dot4(e1, e1), rin2), _mm_cmplt_ps(dot4(e2, e2), rin2)),
				   _mm_cmpgt_ps(rin, zero));
	/* The nearest point to the centre (the origin of rel): e1 + clamp(-e1.D / D.D, 0, 1) D; a NaN
	 * from D = 0 clamps to 0 (maxps returns its second operand on NaN). */
	__m128 dd[3];
	for (int a = 0; a < 3; a++)
		dd[a] = _mm_sub_ps(e2[a], e1[a]);
	__m128 f = _mm_div_ps(_mm_sub_ps(zero, dot4(e1, dd)), dot4(dd, dd));
	f = _mm_min_ps(_mm_max_ps(f, zero), one);
	__m128 near[3];
	for (int a = 0; a < 3; a++)
		near[a] = _mm_add_ps(e1[a], _mm_mul_ps(f, dd[a]));
	__m128 miss = _mm_or_ps(inside, _mm_cmpgt_ps(dot4(near, near), _mm_mul_ps(rout, rout)));
	if (!p->full) {
		__m128 neg = _mm_sub_ps(zero, slack);
		miss = _mm_or_ps(miss, _mm_and_ps(_mm_cmplt_ps(dot4(p->t, e1), neg), _mm_cmplt_ps(dot4(p->t, e2), neg)));
	}
	return _mm_movemask_ps(_mm_and_ps(sure, miss));
}

BVH_INLINE int group_circle(const circle_prep4 *p, const bvh_word *w, int m)
{
	const __m128 zero = _mm_setzero_ps();
	__m128 in = group_lanes(m);
	__m128 rel[3][3], mag[3]; /* rel[vertex][axis] = v - c */
	for (int a = 0; a < 3; a++) {
		__m128 v0 = group_load(w, m, a, in), v1 = group_load(w, m, 3 + a, in), v2 = group_load(w, m, 6 + a, in);
		rel[0][a] = _mm_sub_ps(v0, p->c[a]), rel[1][a] = _mm_sub_ps(v1, p->c[a]);
		rel[2][a] = _mm_sub_ps(v2, p->c[a]);
		mag[a] = _mm_add_ps(_mm_add_ps(abs4(v0), abs4(v1)), _mm_add_ps(abs4(v2), abs4(p->c[a])));
	}
	__m128 margin = _mm_mul_ps(_mm_set1_ps(GROUP_CIRCLE_MARGIN), _mm_add_ps(_mm_add_ps(mag[0], mag[1]), mag[2]));
	__m128 neg_margin = _mm_sub_ps(zero, margin);
	__m128 d[3], r2[3], ct[3], st[3];
	for (int v = 0; v < 3; v++) {
		d[v] = dot4(p->m, rel[v]);
		r2[v] = dot4(rel[v], rel[v]);
		ct[v] = dot4(p->t, rel[v]);
		st[v] = dot4(p->n, rel[v]);
	}
	__m128 above = _mm_and_ps(_mm_and_ps(_mm_cmpgt_ps(d[0], margin), _mm_cmpgt_ps(d[1], margin)),
				  _mm_cmpgt_ps(d[2], margin));
	__m128 below = _mm_and_ps(_mm_and_ps(_mm_cmplt_ps(d[0], neg_margin), _mm_cmplt_ps(d[1], neg_margin)),
				  _mm_cmplt_ps(d[2], neg_margin));
	__m128 reject = _mm_or_ps(above, below);
	__m128 sm = _mm_add_ps(margin, _mm_mul_ps(_mm_set1_ps(GROUP_CIRCLE_MARGIN), p->radius));
	__m128 rin = _mm_sub_ps(p->radius, sm), rout = _mm_add_ps(p->radius, sm);
	__m128 rin2 = _mm_mul_ps(rin, rin), rout2 = _mm_mul_ps(rout, rout);
	__m128 inside = _mm_and_ps(_mm_and_ps(_mm_cmplt_ps(r2[0], rin2), _mm_cmplt_ps(r2[1], rin2)),
				   _mm_and_ps(_mm_cmplt_ps(r2[2], rin2), _mm_cmpgt_ps(rin, zero)));
	__m128 near2 = zero;
	for (int a = 0; a < 3; a++) {
		__m128 lo = _mm_min_ps(_mm_min_ps(rel[0][a], rel[1][a]), rel[2][a]);
		__m128 hi = _mm_max_ps(_mm_max_ps(rel[0][a], rel[1][a]), rel[2][a]);
		__m128 dn = _mm_max_ps(_mm_max_ps(lo, _mm_sub_ps(zero, hi)), zero);
		near2 = _mm_add_ps(near2, _mm_mul_ps(dn, dn));
	}
	reject = _mm_or_ps(reject, _mm_or_ps(inside, _mm_cmpgt_ps(near2, rout2)));
	if (p->in_plane) {
		__m128 q2[3];
		for (int v = 0; v < 3; v++)
			q2[v] = _mm_add_ps(_mm_mul_ps(ct[v], ct[v]), _mm_mul_ps(st[v], st[v]));
		__m128 inside2 = _mm_and_ps(_mm_and_ps(_mm_cmplt_ps(q2[0], rin2), _mm_cmplt_ps(q2[1], rin2)),
					    _mm_and_ps(_mm_cmplt_ps(q2[2], rin2), _mm_cmpgt_ps(rin, zero)));
		__m128 tlo = _mm_min_ps(_mm_min_ps(ct[0], ct[1]), ct[2]), thi = _mm_max_ps(_mm_max_ps(ct[0], ct[1]), ct[2]);
		__m128 nlo = _mm_min_ps(_mm_min_ps(st[0], st[1]), st[2]), nhi = _mm_max_ps(_mm_max_ps(st[0], st[1]), st[2]);
		__m128 dt = _mm_max_ps(_mm_max_ps(tlo, _mm_sub_ps(zero, thi)), zero);
		__m128 dn = _mm_max_ps(_mm_max_ps(nlo, _mm_sub_ps(zero, nhi)), zero);
		__m128 near2d = _mm_add_ps(_mm_mul_ps(dt, dt), _mm_mul_ps(dn, dn));
		reject = _mm_or_ps(reject, _mm_or_ps(inside2, _mm_cmpgt_ps(near2d, rout2)));
	}
	if (!p->full) {
		__m128 neg_sm = _mm_sub_ps(zero, sm);
		reject = _mm_or_ps(reject, _mm_and_ps(_mm_and_ps(_mm_cmplt_ps(ct[0], neg_sm), _mm_cmplt_ps(ct[1], neg_sm)),
						      _mm_cmplt_ps(ct[2], neg_sm)));
	}
	int lanes = (1 << m) - 1, left = ~_mm_movemask_ps(reject) & lanes;
	if (left)
		left &= ~segment_misses(p, rel, d, margin, sm);
	return left;
}

uint32_t bvh_circle(const bvh *b, const tri_circle *q, tri_circle_hit *hits, uint32_t max_hits)
{
	circle_prep p;
	if (b->num_nodes == 0)
		return 0;
	if (!circle_prepare(q, box_extent(b->lo, b->hi), &p) || !box_circle(&p, b->lo, b->hi))
		return 0;
	circle_prep4 p4;
	circle_prepare4(&p, &p4);
	uint32_t stack[BVH4_STACK];
	int sp = 0;
	uint32_t ref = 0, total = 0;
	for (;;) {
		if (!(ref & BVH4_LEAF)) {
			const bvh4_node *nd = &b->nodes[ref];
			int mask = node4_circle(nd, &p4);
			if (mask != 0) {
				ref = nd->child[lowest_bit(mask)];
				for (mask &= mask - 1; mask != 0; mask &= mask - 1)
					stack[sp++] = nd->child[lowest_bit(mask)];
				continue;
			}
		} else {
			uint32_t count = leaf_count(ref);
			for (uint32_t g = 0; g < count; g += 4) {
				int m = count - g < 4 ? (int)(count - g) : 4;
				const bvh_word *w = leaf_group(b, ref, g);
				for (int cand = group_circle(&p4, w, m); cand != 0; cand &= cand - 1) {
					int j = lowest_bit(cand);
					tri_circle_hit h[2];
					int nh = tri_circle_intersect(q, group_vertex(w, m, j, 0), group_vertex(w, m, j, 1),
								      group_vertex(w, m, j, 2), h);
					for (int k = 0; k < nh; k++, total++) {
						if (total < max_hits) {
							hits[total] = h[k];
							hits[total].prim = group_id(w, m, j);
						}
					}
				}
			}
		}
		if (sp == 0)
			return total;
		ref = stack[--sp];
	}
}

vec3 bvh_offset_origin(vec3 p, vec3 n)
{
	/* Waechter & Binder 2019, listing 6-1: below 1/32 a fixed float offset, above it an offset of
	 * 256 * n ulps in the integer representation. */
	const float origin = 1.0f / 32.0f, float_scale = 1.0f / 65536.0f, int_scale = 256.0f;
	float pc[3] = {p.x, p.y, p.z}, nc[3] = {n.x, n.y, n.z}, out[3];
	for (int i = 0; i < 3; i++) {
		int32_t of = (int32_t)(int_scale * nc[i]);
		int32_t bits;
		memcpy(&bits, &pc[i], sizeof bits);
		bits += pc[i] < 0.0f ? -of : of;
		float pi;
		memcpy(&pi, &bits, sizeof pi);
		out[i] = fabsf(pc[i]) < origin ? pc[i] + float_scale * nc[i] : pi;
	}
	return v3(out[0], out[1], out[2]);
}
