/* test_bvh_head: rays and circles on the Lee Perry-Smith head equal brute force, exactly. */
#include "check.h"
#include "brute.h"

int main(void)
{
	test_simd_from_env();
	check_mesh_file("scenes/assets/lee_perry_smith_head/LeePerrySmith.obj", test_count(100000),
			test_count(100000));
	return check_done("test_bvh_head");
}
