/* test_bvh_cage: rays and circles on a tessellated subdivision cage (OpenSubdiv's pawn, level 2)
 * equal brute force, exactly. */
#include "check.h"
#include "brute.h"
#include "geom/shapes.h"
#include "geom/subdiv.h"

int main(void)
{
	test_simd_from_env();
	test_cage *t = cage_read(test_path("scenes/assets/opensubdiv_shapes/catmark_pawn.obj"));
	CHECK(t != NULL, "read the pawn");
	if (!t)
		return check_done("test_bvh_cage");
	diag d;
	diag_init(&d, stderr);
	subd_options o = {.level = 2};
	mesh m;
	if (subd_tessellate(&t->c, &o, &m, &d, diag_noloc())) {
		bvh *b = bvh_build(m.positions, m.num_vertices, m.indices, m.num_triangles);
		brute bf = brute_make(&m);
		printf("pawn level 2: %u triangles\n", m.num_triangles);
		check_rays("pawn", &m, &bf, b, test_count(100000), 21);
		check_circles("pawn", &m, &bf, b, test_count(100000), test_count(100000), 22);
		brute_free(&bf);
		bvh_free(b);
		mesh_free(&m);
	} else {
		CHECK(0, "tessellate the pawn");
	}
	diag_free(&d);
	test_cage_free(t);
	return check_done("test_bvh_cage");
}
