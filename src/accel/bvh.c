/* bvh.c - binned-SAH build of a binary BVH, collapsed into a wide one, and its ray and circle
 * traversals. A wide node holds its children's boxes as struct-of-arrays, so one vector register
 * tests a plane of all of them; a leaf's triangles are stored pre-transposed, so one register holds
 * a coordinate of several triangles. The width is chosen at build time by the CPU: 8-wide nodes
 * traversed with AVX2 where the CPU has it, else 4-wide nodes with SSE2 (the x86-64 baseline);
 * bvh_set_simd(BVH_SIMD_SSE2) forces the latter. Both run the same kernels (bvh_simd.h). */
#include "accel/bvh_internal.h"

#include "base/mem.h"

#include <assert.h>
#include <immintrin.h>
#include <stdlib.h>
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
/* Slack of the slab test's far distance: 1 + 2 gamma(3) of Ize 2013 ("Robust BVH Ray
 * Traversal") covers the rounding of the box distances; we take ten times that, because the
 * triangle test's t carries rounding too and a box must never cull a hit the brute force finds. */
#define BVH_SLAB_SLACK (1.0f + 20.0f * 0x1p-24f * 3.0f)
/* Relative slack of the circle/box test, against float rounding of box and circle data. */
#define BVH_CIRCLE_SLACK 1e-5f

/* A leaf's triangles, pre-transposed in groups (Embree's "triangle4" idea): a group of m triangles
 * (1 to W, the node width) is ten arrays of m words, the coordinates v0x v0y v0z v1x ... v2z and
 * then the ids, so one unaligned load gives one coordinate of all m triangles (lanes past m read
 * the next array and are masked off). A leaf of n triangles (up to BVH_MAX_LEAF) from triangle f
 * is groups of W and a last one of the rest; group h starts at word GROUP_WORDS * (f + W h). 40
 * bytes a triangle, and no transposes when a ray visits. */
typedef union bvh_word {
	float f;
	uint32_t u;
} bvh_word;
#define GROUP_WORDS 10
/* Words after the last group: the last coordinate array of a group of one is loaded up to 8 words
 * wide, seven words past its end (its id is one of them). */
#define LEAF_PAD_WORDS 8

/* A node of width W (4 or 8; bvh_simd.h), 28 W bytes: the children's boxes b[plane][child] with
 * planes lo x, lo y, lo z, hi x, hi y, hi z, then the children. A child is an inner node's index,
 * a leaf (BVH_LEAF | (count - 1) << BVH_COUNT_SHIFT | first triangle), or BVH_EMPTY (then its box
 * is empty, lo = +inf and hi = -inf, and no ray or circle test passes it). */
#define NODE_BYTES(W) (28 * (W))
#define NODE_ALIGN 64
#define BVH_LEAF 0x80000000u
#define BVH_COUNT_SHIFT 27
#define BVH_FIRST_MASK ((1u << BVH_COUNT_SHIFT) - 1)
/* Leaves of the binary tree have at most BVH_MAX_LEAF triangles: four bits of count suffice. */
_Static_assert(BVH_MAX_LEAF <= 16, "a leaf's count must fit its four bits");
#define BVH_EMPTY 0xffffffffu
/* The widest node: the collapse's scratch holds this many children. */
#define BVH_MAX_WIDTH 8
/* The AVX2 kernels need gcc's target pragma (clang builds keep to SSE2). */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
#define BVH_HAVE_AVX2 1
#else
#define BVH_HAVE_AVX2 0
#endif

struct bvh {
	void *nodes;    /* node 0 is the root; `width` children a node; in node_mem, aligned */
	void *node_mem; /* the allocation holding the nodes */
	uint32_t num_nodes, width;
	bvh_word *leaf; /* the leaves' triangles in leaf order, then LEAF_PAD_WORDS */
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
	assert(count > 0 && count <= BVH_MAX_LEAF);
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
	assert(n > 0 && root.begin == 0);
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
		/* A binary tree of n leaves has 2n - 1 nodes; the depth bound sizes every traversal
		 * stack (bvh_simd.h's K_STACK, tlas.c's). */
		assert((size_t)used + 2 <= 2 * (size_t)n - 1);
		assert(l.depth < BVH_MAX_DEPTH && r.depth < BVH_MAX_DEPTH);
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

/* The path of the builds that follow (bvh_set_simd). Written before other threads build, then
 * only read. */
static bvh_simd simd_path = BVH_SIMD_AUTO;

void bvh_set_simd(bvh_simd simd)
{
	simd_path = simd;
}

/* Whether to build wide nodes for AVX2: when the CPU has it and bvh_set_simd did not choose SSE2.
 * Asked at each build, so a test can build a tree for each path in one process. */
static uint32_t simd_width(void)
{
	if (simd_path == BVH_SIMD_SSE2)
		return 4;
#if BVH_HAVE_AVX2
	__builtin_cpu_init();
	if (__builtin_cpu_supports("avx2"))
		return 8;
#endif
	return 4;
}

/* Node i's plane p (width floats) and children, in nodes of the given width (NODE_BYTES). */
static float *node_plane(void *nodes, uint32_t width, uint32_t i, int p)
{
	return (float *)((char *)nodes + (size_t)i * NODE_BYTES(width)) + p * width;
}
static uint32_t *node_children(void *nodes, uint32_t width, uint32_t i)
{
	return (uint32_t *)node_plane(nodes, width, i, 6);
}

/* The collapse of a binary tree into nodes of `width` children: each wide node takes a binary inner
 * node's two children and keeps opening the inner one of largest area until it has `width` (Wald
 * et al. 2008, "Getting Rid of Packets", section 3). Every wide node consumes at least one binary
 * inner node, so there are at most max(1, inner) of them. Nodes are laid out depth first (a node's
 * children side by side, then the first child's subtree): a ray's next node is more often in a
 * cache line it already fetched than in breadth-first order. */
static bool collapse(const bvh_node *bin, uint32_t num_bin, uint32_t width, void **mem, void **out,
		     uint32_t *num_out)
{
	uint32_t cap = num_bin / 2 + 1;
	void *nodes = mem_alloc(cap, NODE_BYTES(width));
	uint32_t *src = mem_alloc(cap, sizeof *src); /* the binary node each wide node stands for */
	if (!nodes || !src) {
		mem_free(nodes), mem_free(src);
		return false;
	}
	uint32_t used = 1;
	src[0] = 0;
	uint32_t todo[(BVH_MAX_WIDTH - 1) * BVH_MAX_DEPTH + BVH_MAX_WIDTH];
	int sp = 0;
	todo[sp++] = 0;
	while (sp > 0) {
		uint32_t i = todo[--sp];
		const bvh_node *s = &bin[src[i]];
		uint32_t slot[BVH_MAX_WIDTH], n = 0;
		if (s->count & BVH_INNER)
			slot[n++] = s->first, slot[n++] = s->first + 1;
		else
			slot[n++] = src[i]; /* the root is a leaf */
		while (n < width) {
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
		uint32_t *child = node_children(nodes, width, i);
		int pushed = sp;
		for (uint32_t k = 0; k < width; k++) {
			if (k >= n) {
				for (int p = 0; p < 3; p++) {
					node_plane(nodes, width, i, p)[k] = INFINITY;
					node_plane(nodes, width, i, 3 + p)[k] = -INFINITY;
				}
				child[k] = BVH_EMPTY;
				continue;
			}
			const bvh_node *c = &bin[slot[k]];
			for (int p = 0; p < 3; p++) {
				node_plane(nodes, width, i, p)[k] = c->lo[p];
				node_plane(nodes, width, i, 3 + p)[k] = c->hi[p];
			}
			if (c->count & BVH_INNER) {
				src[used] = slot[k];
				todo[sp++] = used;
				child[k] = used++;
			} else {
				child[k] = BVH_LEAF | (c->count - 1) << BVH_COUNT_SHIFT | c->first;
			}
		}
		/* The first child on top. */
		for (int lo = pushed, hi = sp - 1; lo < hi; lo++, hi--) {
			uint32_t tmp = todo[lo];
			todo[lo] = todo[hi], todo[hi] = tmp;
		}
	}
	mem_free(src);
	/* The nodes at a cache line's start: then no plane of a node straddles two lines. */
	*mem = mem_alloc((size_t)used * NODE_BYTES(width) + NODE_ALIGN - 1, 1);
	if (*mem) {
		*out = (void *)(((uintptr_t)*mem + NODE_ALIGN - 1) & ~(uintptr_t)(NODE_ALIGN - 1));
		memcpy(*out, nodes, (size_t)used * NODE_BYTES(width));
		*num_out = used;
	}
	mem_free(nodes);
	return *mem != NULL;
}

/* A leaf reference's triangles: the first, and how many. */
static inline uint32_t leaf_first(uint32_t ref) { return ref & BVH_FIRST_MASK; }
static inline uint32_t leaf_count(uint32_t ref) { return (ref >> BVH_COUNT_SHIFT & 15) + 1; }

/* The triangles of the leaf ref (bvh_word) in groups of `width`: leaf slot i is triangle
 * refs[i].id. */
static void write_leaf(bvh_word *leaf, uint32_t ref, uint32_t width, const vec3 *positions,
		       const uint32_t *indices, const build_ref *refs)
{
	uint32_t first = leaf_first(ref), count = leaf_count(ref);
	for (uint32_t g = 0; g < count; g += width) {
		uint32_t m = count - g < width ? count - g : width;
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
	/* A leaf reference holds its first triangle in BVH_COUNT_SHIFT bits. */
	if (num_triangles > BVH_FIRST_MASK)
		return NULL;
	bvh *b = mem_calloc(1, sizeof *b);
	build_ref *refs = mem_alloc(num_triangles, sizeof *refs);
	bvh_node *bin = NULL;
	uint32_t num_bin = 0;
	bool ok = b && refs;
	uint32_t n = 0;
	if (ok) {
		b->width = simd_width();
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
		/* A leaf test takes `width` triangles at once: SAH prices a leaf by such blocks (passed
		 * as constants, so the inlined build divides by shifts). */
		ok = n == 0 || (b->width == 8 ? build_tree(refs, root, 8, &bin, &num_bin)
					      : build_tree(refs, root, 4, &bin, &num_bin));
	}
	if (ok && n > 0) {
		b->lo = bvh_node_lo(&bin[0]), b->hi = bvh_node_hi(&bin[0]);
		b->leaf = mem_calloc(GROUP_WORDS * (size_t)n + LEAF_PAD_WORDS, sizeof *b->leaf);
		ok = b->leaf && collapse(bin, num_bin, b->width, &b->node_mem, &b->nodes, &b->num_nodes);
	}
	if (ok && n > 0) {
		for (uint32_t i = 0; i < b->num_nodes; i++) {
			const uint32_t *child = node_children(b->nodes, b->width, i);
			for (uint32_t k = 0; k < b->width; k++)
				if ((child[k] & BVH_LEAF) && child[k] != BVH_EMPTY)
					write_leaf(b->leaf, child[k], b->width, positions, indices, refs);
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
	mem_free(b->node_mem);
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
	size_t nodes = b->num_nodes ? (size_t)b->num_nodes * NODE_BYTES(b->width) + NODE_ALIGN - 1 : 0;
	return sizeof *b + nodes +
	       (b->num_tris ? GROUP_WORDS * (size_t)b->num_tris + LEAF_PAD_WORDS : 0) * sizeof(bvh_word);
}

uint32_t bvh_num_nodes(const bvh *b) { return b->num_nodes; }

uint32_t bvh_width(const bvh *b) { return b->width; }

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

/* A circle prepared for box tests: its plane normal m = t x n, the slack, and the negated axes
 * (box_circle); the vectors as x, y, z and a zero, so that they are made and stored four lanes at
 * once (the set-up was 6-11 % of a circle query). */
typedef struct circle_prep {
	_Alignas(16) float lo[4], hi[4]; /* the circle's own bounds, grown by the slack */
	_Alignas(16) float c[4], t[4], m[4], neg_t[4], neg_m[4];
	float r, slack, rmax2, rmin2; /* rmin2 < 0: no inner bound */
	bool full;
} circle_prep;

/* The slack covers rounding of box and circle data of magnitude up to `extent` (the largest
 * coordinate of the boxes that will be tested). Each lane does the scalar operations of the
 * formulas below, in their order (v3_cross's for m). */
static bool circle_prepare(const tri_circle *q, float extent, circle_prep *p)
{
	__m128 c = _mm_setr_ps(q->centre.x, q->centre.y, q->centre.z, 0.0f);
	__m128 t = _mm_setr_ps(q->t.x, q->t.y, q->t.z, 0.0f), n = _mm_setr_ps(q->n.x, q->n.y, q->n.z, 0.0f);
	__m128 zero = _mm_setzero_ps(), sign = _mm_set1_ps(-0.0f);
	/* Finite: x * 0 is 0 for every finite x, NaN for an infinity or a NaN. */
	__m128 z = _mm_add_ps(_mm_add_ps(_mm_mul_ps(c, zero), _mm_mul_ps(t, zero)), _mm_mul_ps(n, zero));
	if (_mm_movemask_ps(_mm_cmpeq_ps(z, zero)) != 15 || !isfinite(q->radius) || q->radius < 0.0f)
		return false;
	__m128 m = _mm_sub_ps(_mm_mul_ps(_mm_shuffle_ps(t, t, _MM_SHUFFLE(3, 0, 2, 1)),
					 _mm_shuffle_ps(n, n, _MM_SHUFFLE(3, 1, 0, 2))),
			      _mm_mul_ps(_mm_shuffle_ps(t, t, _MM_SHUFFLE(3, 1, 0, 2)),
					 _mm_shuffle_ps(n, n, _MM_SHUFFLE(3, 0, 2, 1))));
	_mm_store_ps(p->c, c), _mm_store_ps(p->t, t), _mm_store_ps(p->m, m);
	_mm_store_ps(p->neg_t, _mm_xor_ps(t, sign)), _mm_store_ps(p->neg_m, _mm_xor_ps(m, sign));
	p->r = q->radius, p->full = q->full;
	p->slack = BVH_CIRCLE_SLACK * (q->radius + fmax3(v3_abs(q->centre)) + extent);
	p->rmax2 = (p->r + p->slack) * (p->r + p->slack);
	float rmin = p->r - p->slack;
	p->rmin2 = rmin > 0.0f ? rmin * rmin : -1.0f;
	/* Bounds of the circle: along axis i, cos(theta) t_i + sin(theta) n_i spans
	 * +-sqrt(t_i^2 + n_i^2); a half circle reaches the positive end only when t_i >= 0 (else its
	 * ends, +-n_i, bound it), the negative end only when t_i <= 0. */
	__m128 a = _mm_sqrt_ps(_mm_add_ps(_mm_mul_ps(t, t), _mm_mul_ps(n, n))), an = _mm_andnot_ps(sign, n);
	__m128 all = q->full ? _mm_castsi128_ps(_mm_set1_epi32(-1)) : zero;
	__m128 use_up = _mm_or_ps(all, _mm_cmpge_ps(t, zero)),
	       use_down = _mm_or_ps(all, _mm_cmple_ps(t, zero));
	__m128 up = _mm_or_ps(_mm_and_ps(use_up, a), _mm_andnot_ps(use_up, an));
	__m128 down = _mm_or_ps(_mm_and_ps(use_down, a), _mm_andnot_ps(use_down, an));
	__m128 r = _mm_set1_ps(q->radius), slack = _mm_set1_ps(p->slack);
	__m128 lo = _mm_sub_ps(_mm_mul_ps(_mm_xor_ps(down, sign), r), slack),
	       hi = _mm_add_ps(_mm_mul_ps(up, r), slack);
	_mm_store_ps(p->lo, _mm_add_ps(c, lo)), _mm_store_ps(p->hi, _mm_add_ps(c, hi));
	return true;
}

/* The box [lo, hi] may meet the circle: it meets the circle's bounds, its plane and the spherical
 * shell of its radius, and for a half circle the half space cos theta >= 0. In the centre's frame
 * the box is [a, -b] with a = lo - c and b = c - hi; a linear form w . x ranges over the box between
 * the sums of min and max of w_i a_i and -w_i b_i (negated axes given: neg_w_i b_i is -w_i b_i
 * exactly); the nearest point is max(a, b, 0) off along each axis and the farthest min(a, b) (its
 * magnitude). All tests are evaluated and one branch taken: cheaper than early exits that
 * mispredict. bvh_simd.h's node_circle is this test lane by lane, the same operations in the same
 * order. */
static bool box_circle(const circle_prep *p, vec3 lo, vec3 hi)
{
	bool bounds = (lo.x <= p->hi[0]) & (lo.y <= p->hi[1]) & (lo.z <= p->hi[2]) & (hi.x >= p->lo[0]) &
		      (hi.y >= p->lo[1]) & (hi.z >= p->lo[2]);
	float m_lo = 0.0f, m_hi = 0.0f, t_hi = 0.0f, near2 = 0.0f, far2 = 0.0f;
	for (int i = 0; i < 3; i++) {
		float a = v3_get(lo, i) - p->c[i], b = p->c[i] - v3_get(hi, i);
		float ma = p->m[i] * a, mb = p->neg_m[i] * b;
		float ta = p->t[i] * a, tb = p->neg_t[i] * b;
		float dn = fmaxf(fmaxf(a, b), 0.0f), df = fminf(a, b);
		m_lo = i ? m_lo + fminf(ma, mb) : fminf(ma, mb);
		m_hi = i ? m_hi + fmaxf(ma, mb) : fmaxf(ma, mb);
		t_hi = i ? t_hi + fmaxf(ta, tb) : fmaxf(ta, tb);
		near2 = i ? near2 + dn * dn : dn * dn;
		far2 = i ? far2 + df * df : df * df;
	}
	bool plane = (m_lo <= p->slack) & (m_hi >= -p->slack);
	bool side = p->full | (t_hi >= -p->slack);
	bool shell = (near2 <= p->rmax2) & (far2 >= p->rmin2);
	return bounds & plane & side & shell;
}

static float box_extent(vec3 lo, vec3 hi) { return fmax3(vmax(v3_abs(lo), v3_abs(hi))); }

bool bvh_box_circle(vec3 lo, vec3 hi, const tri_circle *q)
{
	circle_prep p;
	return circle_prepare(q, box_extent(lo, hi), &p) && box_circle(&p, lo, hi);
}

/* The circle traversal's sizes (bvh_simd.h): inner nodes queued before it goes depth first, and
 * leaves collected before their tests. Test builds (test_circle_queue) make them tiny, and count
 * how often the traversal goes depth first. */
#ifndef BVH_CIRCLE_FIFO
#define BVH_CIRCLE_FIFO 512
#endif
#ifndef BVH_CIRCLE_LEAF_BATCH
#define BVH_CIRCLE_LEAF_BATCH 32
#endif
#ifdef BVH_CIRCLE_QUEUE_STATS
extern long bvh_circle_queue_lifo;
#define BVH_QUEUE_STAT(counter) ((counter)++)
#else
#define BVH_QUEUE_STAT(counter) ((void)0)
#endif

/* ---- The vector kernels -------------------------------------------------------------------- */

/* Forced inlining: the leaf tests are called from two traversals each, and gcc -O2 would
 * otherwise keep them out of line and pass their results through memory. */
#define BVH_INLINE static inline __attribute__((always_inline))

/* Index of the lowest set bit of a non-zero mask. */
static inline int lowest_bit(int mask) { return __builtin_ctz((unsigned)mask); }

/* Triangle k of a leaf of m at w: vertex coordinates and id. */
BVH_INLINE vec3 group_vertex(const bvh_word *w, int m, int k, int vertex)
{
	return v3(w[(3 * vertex) * m + k].f, w[(3 * vertex + 1) * m + k].f, w[(3 * vertex + 2) * m + k].f);
}
BVH_INLINE uint32_t group_id(const bvh_word *w, int m, int k) { return w[9 * m + k].u; }
/* The scalar watertight test (tri_intersect) of triangle k of a group: for the lanes a vector test
 * leaves to it (an edge function exactly zero). */
BVH_INLINE bool group_tri_intersect(const tri_ray *r, const bvh_word *w, int m, int k, float tlimit, float *t,
				    float *u, float *v)
{
	return tri_intersect(r, group_vertex(w, m, k, 0), group_vertex(w, m, k, 1), group_vertex(w, m, k, 2), tlimit,
			     t, u, v);
}
static inline const bvh_word *leaf_words(const bvh *b, uint32_t ref)
{
	return &b->leaf[GROUP_WORDS * (size_t)leaf_first(ref)];
}

/* The exact circle test of triangle k of a leaf that passed the pre-tests, in its two halves: the
 * segment and its roots (returns their number, 0 for no hit), then the hits, which go to
 * hits[total...] (up to max_hits in all; returns the new total). */
BVH_INLINE int circle_segment(const tri_circle_d *q, const bvh_word *w, int m, int k, tri_circle_segment *g)
{
	return tri_circle_segment_solve(q, group_vertex(w, m, k, 0), group_vertex(w, m, k, 1),
					group_vertex(w, m, k, 2), g);
}
static uint32_t circle_segment_hits(const tri_circle_d *q, const tri_circle_segment *g, int nr, uint32_t id,
				    tri_circle_hit *hits, uint32_t max_hits, uint32_t total)
{
	if (total + 2 <= max_hits) {
		/* Room for both: straight into hits. */
		int nh = tri_circle_segment_hits(q, g, nr, &hits[total]);
		for (int i = 0; i < nh; i++)
			hits[total + i].prim = id;
		return total + (uint32_t)nh;
	}
	tri_circle_hit h[2];
	int nh = tri_circle_segment_hits(q, g, nr, h);
	for (int i = 0; i < nh; i++, total++) {
		if (total < max_hits) {
			hits[total] = h[i];
			hits[total].prim = id;
		}
	}
	return total;
}

/* Relative size of the margins of group_circle: tri_circle_intersect's float pre-test's. */
#define GROUP_CIRCLE_MARGIN TRI_CIRCLE_MARGIN

/* The vector operations of bvh_simd.h, one set a width. Compares are the ordered (false on NaN)
 * ones of SSE's cmplt/cmple/cmpgt/cmpge/cmpeq, and neq the unordered one of cmpneq; max and min
 * return their second operand when either is NaN, as maxps and minps do. */
BVH_INLINE __m128 f4_set1(float x) { return _mm_set1_ps(x); }
BVH_INLINE __m128 f4_zero(void) { return _mm_setzero_ps(); }
BVH_INLINE __m128 f4_load(const float *p) { return _mm_load_ps(p); }
BVH_INLINE __m128 f4_loadu(const float *p) { return _mm_loadu_ps(p); }
BVH_INLINE void f4_storeu(float *p, __m128 a) { _mm_storeu_ps(p, a); }
BVH_INLINE __m128 f4_add(__m128 a, __m128 b) { return _mm_add_ps(a, b); }
BVH_INLINE __m128 f4_sub(__m128 a, __m128 b) { return _mm_sub_ps(a, b); }
BVH_INLINE __m128 f4_mul(__m128 a, __m128 b) { return _mm_mul_ps(a, b); }
BVH_INLINE __m128 f4_div(__m128 a, __m128 b) { return _mm_div_ps(a, b); }
BVH_INLINE __m128 f4_min(__m128 a, __m128 b) { return _mm_min_ps(a, b); }
BVH_INLINE __m128 f4_max(__m128 a, __m128 b) { return _mm_max_ps(a, b); }
BVH_INLINE __m128 f4_and(__m128 a, __m128 b) { return _mm_and_ps(a, b); }
BVH_INLINE __m128 f4_or(__m128 a, __m128 b) { return _mm_or_ps(a, b); }
BVH_INLINE __m128 f4_xor(__m128 a, __m128 b) { return _mm_xor_ps(a, b); }
BVH_INLINE __m128 f4_andnot(__m128 a, __m128 b) { return _mm_andnot_ps(a, b); }
BVH_INLINE __m128 f4_abs(__m128 a) { return _mm_andnot_ps(_mm_set1_ps(-0.0f), a); }
BVH_INLINE __m128 f4_lt(__m128 a, __m128 b) { return _mm_cmplt_ps(a, b); }
BVH_INLINE __m128 f4_le(__m128 a, __m128 b) { return _mm_cmple_ps(a, b); }
BVH_INLINE __m128 f4_gt(__m128 a, __m128 b) { return _mm_cmpgt_ps(a, b); }
BVH_INLINE __m128 f4_ge(__m128 a, __m128 b) { return _mm_cmpge_ps(a, b); }
BVH_INLINE __m128 f4_eq(__m128 a, __m128 b) { return _mm_cmpeq_ps(a, b); }
BVH_INLINE __m128 f4_neq(__m128 a, __m128 b) { return _mm_cmpneq_ps(a, b); }
BVH_INLINE int f4_movemask(__m128 a) { return _mm_movemask_ps(a); }
/* All ones in lanes j < n, zero in the others. */
BVH_INLINE __m128 f4_lanes(int n)
{
	return _mm_castsi128_ps(_mm_cmplt_epi32(_mm_setr_epi32(0, 1, 2, 3), _mm_set1_epi32(n)));
}

/* The set bits of a lane mask (SSE2 has no popcnt instruction; gcc would call libgcc). */
BVH_INLINE int f4_popcount(int mask) { return (int)(0x4332322132212110ull >> (4 * (mask & 15)) & 15); }

/* blend: a in the lanes of mask (all ones or all zeros), b in the others. */
BVH_INLINE __m128 f4_blend(__m128 mask, __m128 a, __m128 b) { return _mm_or_ps(_mm_and_ps(mask, a), _mm_andnot_ps(mask, b)); }

/* compress: the words of src[0, W) whose lanes are set in mask, in order, to dst[0, popcount)
 * (dst has room for W; the words past the count are left undefined). Returns the count. */
BVH_INLINE int f4_compress(uint32_t *dst, const uint32_t *src, int mask)
{
	int n = 0;
	for (int i = 0; i < 4; i++) {
		dst[n] = src[i];
		n += (mask >> i) & 1;
	}
	return n;
}

/* compress_lanes: base + i for the lanes i set in mask, in order, to dst[0, popcount) (room for W).
 * Returns the count. */
BVH_INLINE int f4_compress_lanes(uint32_t *dst, uint32_t base, int mask)
{
	const uint32_t lanes[4] = {base, base + 1, base + 2, base + 3};
	return f4_compress(dst, lanes, mask);
}

#define W 4
#define vf __m128
#define V(op) f4_##op
#define K(name) name##_4
#include "accel/bvh_simd.h"
#undef W
#undef vf
#undef V
#undef K

#if BVH_HAVE_AVX2
/* The AVX2 kernels: compiled for AVX2 whatever the compiler's flags, called only when the CPU has
 * it (simd_width). No FMA (target avx2 alone does not enable it; configure adds -ffp-contract=off
 * too), so every lane still rounds as the scalar tests do. */
#pragma GCC push_options
#pragma GCC target("avx2")
BVH_INLINE __m256 f8_set1(float x) { return _mm256_set1_ps(x); }
BVH_INLINE __m256 f8_zero(void) { return _mm256_setzero_ps(); }
BVH_INLINE __m256 f8_load(const float *p) { return _mm256_load_ps(p); }
BVH_INLINE __m256 f8_loadu(const float *p) { return _mm256_loadu_ps(p); }
BVH_INLINE void f8_storeu(float *p, __m256 a) { _mm256_storeu_ps(p, a); }
BVH_INLINE __m256 f8_add(__m256 a, __m256 b) { return _mm256_add_ps(a, b); }
BVH_INLINE __m256 f8_sub(__m256 a, __m256 b) { return _mm256_sub_ps(a, b); }
BVH_INLINE __m256 f8_mul(__m256 a, __m256 b) { return _mm256_mul_ps(a, b); }
BVH_INLINE __m256 f8_div(__m256 a, __m256 b) { return _mm256_div_ps(a, b); }
BVH_INLINE __m256 f8_min(__m256 a, __m256 b) { return _mm256_min_ps(a, b); }
BVH_INLINE __m256 f8_max(__m256 a, __m256 b) { return _mm256_max_ps(a, b); }
BVH_INLINE __m256 f8_and(__m256 a, __m256 b) { return _mm256_and_ps(a, b); }
BVH_INLINE __m256 f8_or(__m256 a, __m256 b) { return _mm256_or_ps(a, b); }
BVH_INLINE __m256 f8_xor(__m256 a, __m256 b) { return _mm256_xor_ps(a, b); }
BVH_INLINE __m256 f8_andnot(__m256 a, __m256 b) { return _mm256_andnot_ps(a, b); }
BVH_INLINE __m256 f8_abs(__m256 a) { return _mm256_andnot_ps(_mm256_set1_ps(-0.0f), a); }
BVH_INLINE __m256 f8_lt(__m256 a, __m256 b) { return _mm256_cmp_ps(a, b, _CMP_LT_OS); }
BVH_INLINE __m256 f8_le(__m256 a, __m256 b) { return _mm256_cmp_ps(a, b, _CMP_LE_OS); }
BVH_INLINE __m256 f8_gt(__m256 a, __m256 b) { return _mm256_cmp_ps(a, b, _CMP_GT_OS); }
BVH_INLINE __m256 f8_ge(__m256 a, __m256 b) { return _mm256_cmp_ps(a, b, _CMP_GE_OS); }
BVH_INLINE __m256 f8_eq(__m256 a, __m256 b) { return _mm256_cmp_ps(a, b, _CMP_EQ_OQ); }
BVH_INLINE __m256 f8_neq(__m256 a, __m256 b) { return _mm256_cmp_ps(a, b, _CMP_NEQ_UQ); }
BVH_INLINE int f8_movemask(__m256 a) { return _mm256_movemask_ps(a); }
BVH_INLINE __m256 f8_lanes(int n)
{
	__m256i lane = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
	return _mm256_castsi256_ps(_mm256_cmpgt_epi32(_mm256_set1_epi32(n), lane));
}

/* The lane permutations of f8_compress: row m lists the set bits of m, lowest first (then zeros),
 * written out by the preprocessor: entry j is the bit i of m that has j set bits below it. */
#define LP_BIT(m, i) (((m) >> (i)) & 1)
#define LP_BELOW(m, i) (((m) & ((1 << (i)) - 1)) == 0 ? 0 : LP_COUNT((m) & ((1 << (i)) - 1)))
#define LP_COUNT(x)                                                                                      \
	(LP_BIT(x, 0) + LP_BIT(x, 1) + LP_BIT(x, 2) + LP_BIT(x, 3) + LP_BIT(x, 4) + LP_BIT(x, 5) +       \
	 LP_BIT(x, 6) + LP_BIT(x, 7))
#define LP_TERM(m, i, j) (LP_BIT(m, i) && LP_BELOW(m, i) == (j) ? (i) : 0)
#define LP_ENTRY(m, j)                                                                                   \
	(LP_TERM(m, 1, j) + LP_TERM(m, 2, j) + LP_TERM(m, 3, j) + LP_TERM(m, 4, j) + LP_TERM(m, 5, j) +  \
	 LP_TERM(m, 6, j) + LP_TERM(m, 7, j))
#define LP_ROW(m)                                                                                        \
	{LP_ENTRY(m, 0), LP_ENTRY(m, 1), LP_ENTRY(m, 2), LP_ENTRY(m, 3),                                  \
	 LP_ENTRY(m, 4), LP_ENTRY(m, 5), LP_ENTRY(m, 6), LP_ENTRY(m, 7)}
#define LP_ROWS4(m) LP_ROW(m), LP_ROW((m) + 1), LP_ROW((m) + 2), LP_ROW((m) + 3)
#define LP_ROWS16(m) LP_ROWS4(m), LP_ROWS4((m) + 4), LP_ROWS4((m) + 8), LP_ROWS4((m) + 12)
#define LP_ROWS64(m) LP_ROWS16(m), LP_ROWS16((m) + 16), LP_ROWS16((m) + 32), LP_ROWS16((m) + 48)
static const int32_t left_pack[256][8] __attribute__((aligned(32))) = {
    LP_ROWS64(0), LP_ROWS64(64), LP_ROWS64(128), LP_ROWS64(192)};

BVH_INLINE int f8_popcount(int mask) { return __builtin_popcount((unsigned)mask); }

BVH_INLINE __m256 f8_blend(__m256 mask, __m256 a, __m256 b) { return _mm256_blendv_ps(b, a, mask); }

BVH_INLINE int f8_compress(uint32_t *dst, const uint32_t *src, int mask)
{
	__m256i perm = _mm256_load_si256((const __m256i *)left_pack[mask]);
	__m256i words = _mm256_loadu_si256((const __m256i *)src);
	_mm256_storeu_si256((__m256i *)dst, _mm256_permutevar8x32_epi32(words, perm));
	return __builtin_popcount((unsigned)mask);
}

BVH_INLINE int f8_compress_lanes(uint32_t *dst, uint32_t base, int mask)
{
	__m256i lanes = _mm256_load_si256((const __m256i *)left_pack[mask]);
	_mm256_storeu_si256((__m256i *)dst, _mm256_add_epi32(lanes, _mm256_set1_epi32((int)base)));
	return __builtin_popcount((unsigned)mask);
}

#define W 8
#define vf __m256
#define V(op) f8_##op
#define K(name) name##_8
#include "accel/bvh_simd.h"
#undef W
#undef vf
#undef V
#undef K
#pragma GCC pop_options
#endif

/* ---- Entry points: the kernels of the bvh's width ---------------------------------------- */

bool bvh_intersect_prepared(const bvh *b, const tri_ray *r, float *tlimit, bvh_hit *hit)
{
	if (b->num_nodes == 0)
		return false;
#if BVH_HAVE_AVX2
	if (b->width == 8)
		return intersect_8(b, r, tlimit, hit);
#endif
	return intersect_4(b, r, tlimit, hit);
}

bool bvh_occluded_prepared(const bvh *b, const tri_ray *r)
{
	if (b->num_nodes == 0)
		return false;
#if BVH_HAVE_AVX2
	if (b->width == 8)
		return occluded_8(b, r);
#endif
	return occluded_4(b, r);
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

/* Every hit of q, in the traversal's order (which depends on the tree). */
static uint32_t circle_traverse(const bvh *b, const tri_circle *q, tri_circle_hit *hits, uint32_t max_hits)
{
	circle_prep p;
	if (b->num_nodes == 0)
		return 0;
	/* No test of the root's own box: the traversal tests its children's. */
	if (!circle_prepare(q, box_extent(b->lo, b->hi), &p))
		return 0;
	tri_circle_d qd;
	tri_circle_d_prepare(q, &qd);
#if BVH_HAVE_AVX2
	if (b->width == 8)
		return circle_8(b, &qd, &p, hits, max_hits);
#endif
	return circle_4(b, &qd, &p, hits, max_hits);
}

uint32_t bvh_circle(const bvh *b, const tri_circle *q, tri_circle_hit *hits, uint32_t max_hits)
{
	uint32_t total = circle_traverse(b, q, hits, max_hits);
	tri_circle_hits_sort(hits, total < max_hits ? total : max_hits);
	return total;
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

/* ---- Nearest surface ----------------------------------------------------------------------- */

/* The squared distance from p to the triangle a, b, c, in double (Ericson 2005, "Real-Time
 * Collision Detection", 5.1.5: the closest point by the Voronoi regions of the vertices, edges and
 * face). The inputs are floats, so their differences are exact in double. */
static double point_triangle_d2(dvec3 p, dvec3 a, dvec3 b, dvec3 c)
{
	dvec3 ab = d3_sub(b, a), ac = d3_sub(c, a), ap = d3_sub(p, a);
	double d1 = d3_dot(ab, ap), d2 = d3_dot(ac, ap);
	if (d1 <= 0.0 && d2 <= 0.0)
		return d3_dot(ap, ap);
	dvec3 bp = d3_sub(p, b);
	double d3 = d3_dot(ab, bp), d4 = d3_dot(ac, bp);
	if (d3 >= 0.0 && d4 <= d3)
		return d3_dot(bp, bp);
	double vc = d1 * d4 - d3 * d2;
	if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
		dvec3 q = d3_sub(ap, d3_scale(ab, d1 / (d1 - d3)));
		return d3_dot(q, q);
	}
	dvec3 cp = d3_sub(p, c);
	double d5 = d3_dot(ab, cp), d6 = d3_dot(ac, cp);
	if (d6 >= 0.0 && d5 <= d6)
		return d3_dot(cp, cp);
	double vb = d5 * d2 - d1 * d6;
	if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
		dvec3 q = d3_sub(ap, d3_scale(ac, d2 / (d2 - d6)));
		return d3_dot(q, q);
	}
	double va = d3 * d6 - d5 * d4;
	if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
		dvec3 q = d3_sub(bp, d3_scale(d3_sub(c, b), (d4 - d3) / ((d4 - d3) + (d5 - d6))));
		return d3_dot(q, q);
	}
	/* inside the face: the distance to the plane */
	dvec3 n = d3_cross(ab, ac);
	double nn = d3_dot(n, n), h = d3_dot(ap, n);
	if (!(nn > 0.0)) /* degenerate in double (the build left out those of zero area in float) */
		return fmin(d3_dot(ap, ap), fmin(d3_dot(bp, bp), d3_dot(cp, cp)));
	return h * h / nn;
}

/* The squared distance from p to the box lo, hi (0 inside; +inf for an empty child's box; no
 * fmax: a libm call at -O2 without -ffinite-math-only). */
static inline double point_box_d2(dvec3 p, float lo_x, float lo_y, float lo_z, float hi_x, float hi_y, float hi_z)
{
	if (!(lo_x <= hi_x))
		return INFINITY;
	double dx = p.x < lo_x ? lo_x - p.x : p.x > hi_x ? p.x - hi_x : 0.0;
	double dy = p.y < lo_y ? lo_y - p.y : p.y > hi_y ? p.y - hi_y : 0.0;
	double dz = p.z < lo_z ? lo_z - p.z : p.z > hi_z ? p.z - hi_z : 0.0;
	return dx * dx + dy * dy + dz * dz;
}

float bvh_nearest(const bvh *b, vec3 p, float cap)
{
	if (!(cap > 0.0f))
		return 0.0f;
	if (b->num_nodes == 0 || !v3_is_finite(p))
		return cap;
	dvec3 pd = v3_to_d3(p);
	double best = (double)cap * (double)cap; /* squared: what is at or beyond it is not looked at */
	uint32_t width = b->width;
	/* Children are pushed farthest first, so the nearest is looked at first and the best
	 * distance falls early; a popped node whose box lies beyond the best is skipped. */
	uint32_t stack[(BVH_MAX_WIDTH - 1) * BVH_MAX_DEPTH + BVH_MAX_WIDTH];
	double stack_d2[(BVH_MAX_WIDTH - 1) * BVH_MAX_DEPTH + BVH_MAX_WIDTH];
	int sp = 0;
	bool found = false;
	stack[sp] = 0, stack_d2[sp++] = 0.0;
	while (sp > 0) {
		--sp;
		if (!(stack_d2[sp] < best))
			continue;
		uint32_t ni = stack[sp];
		const uint32_t *child = node_children(b->nodes, width, ni);
		const float *lx = node_plane(b->nodes, width, ni, 0), *ly = node_plane(b->nodes, width, ni, 1),
			    *lz = node_plane(b->nodes, width, ni, 2), *hx = node_plane(b->nodes, width, ni, 3),
			    *hy = node_plane(b->nodes, width, ni, 4), *hz = node_plane(b->nodes, width, ni, 5);
		uint32_t order[BVH_MAX_WIDTH];
		double dist[BVH_MAX_WIDTH];
		int n = 0;
		for (uint32_t k = 0; k < width; k++) {
			double d2 = point_box_d2(pd, lx[k], ly[k], lz[k], hx[k], hy[k], hz[k]);
			if (!(d2 < best) || child[k] == BVH_EMPTY)
				continue;
			if (child[k] & BVH_LEAF) { /* leaves at once: their triangles lower best for the rest */
				uint32_t ref = child[k], count = leaf_count(ref);
				const bvh_word *w = leaf_words(b, ref);
				for (uint32_t g = 0; g < count; g += width) {
					int m = (int)(count - g < width ? count - g : width);
					const bvh_word *wg = w + GROUP_WORDS * (size_t)g;
					for (int j = 0; j < m; j++) {
						double t2 = point_triangle_d2(pd, v3_to_d3(group_vertex(wg, m, j, 0)),
									      v3_to_d3(group_vertex(wg, m, j, 1)),
									      v3_to_d3(group_vertex(wg, m, j, 2)));
						if (t2 < best)
							best = t2, found = true;
					}
				}
				continue;
			}
			/* insertion by distance, farthest first */
			int i = n++;
			while (i > 0 && dist[i - 1] < d2)
				order[i] = order[i - 1], dist[i] = dist[i - 1], i--;
			order[i] = child[k], dist[i] = d2;
		}
		assert(sp + n <= (int)(sizeof stack / sizeof stack[0]));
		for (int i = 0; i < n; i++)
			stack[sp] = order[i], stack_d2[sp++] = dist[i];
	}
	/* Rounded down, and by a relative 2^-20 more: the double arithmetic's error (relative 1e-15
	 * of the coordinates' differences) and the float result's rounding stay below the truth. */
	if (!found)
		return cap;
	double d = sqrt(best) * (1.0 - 0x1p-20);
	float f = (float)d;
	if ((double)f > d)
		f = nextafterf(f, 0.0f);
	return f < cap ? f : cap;
}
