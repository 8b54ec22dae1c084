#!/bin/sh
# sse2.sh: the accel tests again on the SSE2 path (CIRCE_SIMD=sse2: 4-wide nodes and kernels),
# which the BVH skips on a CPU with AVX2; both paths must equal brute force bit for bit.
for t in test_bvh test_bvh_head test_bvh_cage test_robust test_circle test_circle_queue test_tlas test_offset; do
	echo "== CIRCE_SIMD=sse2 $t"
	CIRCE_SIMD=sse2 "$top_builddir/tests/accel/$t"
	rc=$?
	[ "$rc" = 0 ] || { echo "FAIL: CIRCE_SIMD=sse2 $t exited $rc" >&2; exit "$rc"; }
done
echo PASS
