/* test_shading: tangent-space normal mapping — the flat texel keeps the normal, each channel tilts
 * along its axis of the MikkTSpace frame, strength scales the tilt, degenerate input keeps n. */
#include "check.h"
#include "render/shading.h"

static void check_vec(const char *what, vec3 got, vec3 want)
{
	CHECK(v3_length(v3_sub(got, want)) < 1e-5f, "%s: (%g %g %g), want (%g %g %g)", what, got.x, got.y,
	      got.z, want.x, want.y, want.z);
}

int main(void)
{
	vec3 n = v3(0, 1, 0), t = v3(1, 0.3f, 0); /* a tangent with a normal component to remove */
	check_vec("flat texel", render_normal_map(n, t, 1, v3(0.5f, 0.5f, 1), 1), n);
	float s = sqrtf(0.5f);
	/* 45 degrees towards the tangent (+x), then towards the bitangent n x t = (0,0,-1). */
	check_vec("red tilts along the tangent", render_normal_map(n, t, 1, v3(1, 0.5f, 1), 1), v3(s, s, 0));
	check_vec("green tilts along the bitangent", render_normal_map(n, t, 1, v3(0.5f, 1, 1), 1),
		  v3(0, s, -s));
	check_vec("the sign flips the bitangent", render_normal_map(n, t, -1, v3(0.5f, 1, 1), 1),
		  v3(0, s, s));
	check_vec("strength 0", render_normal_map(n, t, 1, v3(1, 0, 0.7f), 0), n);
	vec3 half = render_normal_map(n, t, 1, v3(1, 0.5f, 1), 0.5f);
	check_vec("strength 0.5", half, v3_normalize(v3(0.5f, 1, 0)));
	check_vec("tangent along n", render_normal_map(n, v3(0, 2, 0), 1, v3(1, 0.5f, 1), 1), n);
	/* Only the tangent's direction counts: a scene scaled by 1e-7 hands over a tangent of that
	 * length (an absolute bound of 1e-6 turned every normal map off there). */
	for (float k = 1e-30f; k < 1e31f; k *= 1e5f)
		check_vec("a tangent of any length", render_normal_map(n, v3_scale(t, k), 1, v3(1, 0.5f, 1), 1),
			  v3(s, s, 0));
	check_vec("zero tangent", render_normal_map(n, v3(0, 0, 0), 1, v3(1, 0.5f, 1), 1), n);
	check_vec("texel below the surface", render_normal_map(n, t, 1, v3(0.5f, 0.5f, 0.2f), 1), n);
	return check_done("test_shading");
}
