/* glass_shadows: the two ways circe's shadow rays can treat glass (render_settings.
 * opaque_glass_shadows), measured at one floor point in the shadow of a glass ball under a small
 * sphere light: the mean and the standard deviation of one path's luminance for each. With
 * opaque glass shadows the light reaches the point only by paths (the caustic, unbiased, the
 * reference); with POV-Ray's transparent shadows a straight shadow ray stands for it.
 * Usage: bench/glass_shadows [PATHS]. Not part of make check (bench/README.md). */
#include "../tests/render/scenes.h"
#include "render/camera.h"

#include <stdio.h>
#include <stdlib.h>

static void measure(const ts_scene *s, const cam *c, bool opaque, long n, double *mean, double *sd)
{
	render_settings set = {.max_trace_level = 8, .mode = RENDER_MIS, .opaque_glass_shadows = opaque};
	double sum = 0, sum2 = 0;
	for (long k = 0; k < n; k++) {
		render_sampler g = render_sampler_make(RENDER_SAMPLER_SOBOL, 11, 0, 0, (uint32_t)k);
		vec2 pu = render_sampler_2d(&g, RENDER_DIM_PIXEL);
		double l = v3_luminance(render_path(&s->rs, &set, cam_ray(c, 0, 0, pu, v2(0, 0)), &g).radiance);
		sum += l, sum2 += l * l;
	}
	*mean = sum / n;
	*sd = sqrt(fmax(0, sum2 / n - *mean * *mean));
}

int main(int argc, char **argv)
{
	long n = argc > 1 ? atol(argv[1]) : 1000000;
	static ts_scene s;
	ts_init(&s);
	s.rs.shadow_closest = ts_intersect;
	s.pl[s.npl++] = (ts_plane){v3(0, 1, 0), 0.0f, 0};
	s.mat[0] = bsdf_diffuse(v3s(0.8f));
	s.sph[s.nsph++] = (ts_sphere){v3(0, 1, 0), 1.0f, 1};
	s.mat[1] = bsdf_pov_finish(v3s(1), 0, 0, 0.05f);
	s.mat[1].clear = (bsdf_clear){.kind = BSDF_CLEAR_DIELECTRIC, .tint = v3s(0.9f), .reflect = 1, .ior = 1.5f};
	light sl = light_sphere(v3(1, 5, 0), 0.3f, v3s(50));
	light_set_add(&s.lights, &sl);
	light_set_finish(&s.lights, 10.0f);
	cam_params cp = cam_params_default();
	cp.location = d3(-0.25, 0.3, -3);
	cp.look_at = d3(-0.25, 0, -0.5); /* in the ball's shadow, beside its footprint */
	cp.angle_deg = 0.01;
	cam c;
	if (!cam_init(&c, &cp, 1, 1))
		return 1;
	for (int o = 0; o < 2; o++) {
		double m, sd;
		measure(&s, &c, o == 1, n, &m, &sd);
		printf("%-28s mean %.5f  sd per path %.4f  se %.5f  (%ld paths)\n",
		       o ? "opaque glass (caustic paths)" : "transparent shadows", m, sd, sd / sqrt((double)n), n);
	}
	light_set_free(&s.lights);
	return 0;
}
