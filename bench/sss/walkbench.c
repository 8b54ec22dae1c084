/* walkbench: the volume walk's cost and noise, classic against Dwivedi-guided (src/sss/README.md,
 * "Guided sampling"), on circe's three SSS media (skin = skin1, wax = the wax block's artist
 * defaults, marble) in a box of mm: a deep slab (200 mm, semi-infinite for the walk: the light
 * reflected), a 3 mm sheet (the light transmitted, what a back-lit ear shows) and a 30 mm slab
 * (reflected: bench/sss's marble slab), entered at
 * normal incidence in the middle of the top face. Per medium and geometry: walks per
 * second, interactions per walk, the walks that reached the step bound, the mean and standard
 * error of the light leaving (red, green, blue) and the efficiency ratio guided / classic,
 * (var x time) classic over (var x time) guided of the luminance: above 1 the guided walk reaches
 * a given noise that much faster; and the same with interactions (ray casts) for time, which a
 * shared machine's load does not disturb and which dominate a walk in a real mesh. One thread. Usage: bench/sss/walkbench [WALKS] [MAX_STEPS].
 * Not part of make check (bench/sss/README.md). */
#include "accel/bvh.h"
#include "base/rng.h"
#include "geom/prim.h"
#include "sss/medium.h"
#include "sss/walk.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

static double now(void)
{
	struct timespec ts;
	clock_gettime(CLOCK_MONOTONIC, &ts);
	return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

typedef struct run {
	double mean[3], se[3], lum_var, seconds, steps;
	long dropped, n;
} run;

/* exit_z: only walks leaving through that face count (the top: reflection; the bottom of the
 * sheet: transmission, what a back-lit thin object shows) */
static run walk_many(const sss_walk_medium *m, const sss_probe *pr, long n, int max_steps, float exit_z)
{
	run r = {0};
	double s[3] = {0}, s2[3] = {0}, sl = 0, sl2 = 0;
	rng g;
	rng_seed(&g, 5, 9);
	double t0 = now();
	for (long i = 0; i < n; i++) {
		sss_walk_result res = sss_walk(m, pr, v3(0, 0, 0), v3(0, 0, 1), 0.0f, v3(0, 0, -1), &g, max_steps);
		r.steps += res.steps;
		r.dropped += res.status == SSS_WALK_STEP_LIMIT;
		bool counts = res.status == SSS_WALK_EXITED && res.p.z == exit_z;
		double w[3] = {counts ? res.weight.x : 0.0, counts ? res.weight.y : 0.0, counts ? res.weight.z : 0.0};
		for (int c = 0; c < 3; c++)
			s[c] += w[c], s2[c] += w[c] * w[c];
		double l = 0.2126 * w[0] + 0.7152 * w[1] + 0.0722 * w[2];
		sl += l, sl2 += l * l;
	}
	r.seconds = now() - t0;
	r.n = n;
	r.steps /= n;
	for (int c = 0; c < 3; c++) {
		r.mean[c] = s[c] / n;
		r.se[c] = sqrt(fmax(0.0, s2[c] / n - r.mean[c] * r.mean[c]) / n);
	}
	r.lum_var = fmax(0.0, sl2 / n - (sl / n) * (sl / n));
	return r;
}

int main(int argc, char **argv)
{
	long n = argc > 1 ? atol(argv[1]) : 20000;
	int max_steps = argc > 2 ? atoi(argv[2]) : SSS_WALK_MAX_STEPS;
	struct {
		const char *name;
		sss_medium_spec spec;
		double ior;
	} media[] = {
		{"skin", {.preset = "skin1"}, 1.4},
		{"wax", {.albedo = {0.95f, 0.78f, 0.45f}, .radius_mm = {2.0f, 1.2f, 0.6f}, .has = SSS_HAS_ALBEDO | SSS_HAS_RADIUS}, 1.45},
		{"marble", {.preset = "marble"}, 1.5},
	};
	/* the deep slab and the 30 mm one (the bench's marble slab) reflect, the sheet transmits */
	const double depth[] = {200.0, 3.0, 30.0};
	const char *geometry[] = {"slab 200 mm, reflected", "sheet 3 mm, transmitted", "slab 30 mm, reflected"};
	printf("| medium | geometry | walk | walks/s | interactions | dropped | R | G | B | efficiency guided / classic: "
	       "time | interactions |\n");
	printf("|---|---|---|---|---|---|---|---|---|---|---|\n");
	for (int k = 0; k < 3; k++) {
		sss_medium md;
		sss_medium_derive(&media[k].spec, media[k].ior, &md);
		for (int d = 0; d < 3; d++) {
			mesh me;
			if (!prim_box(v3(-400, -400, (float)-depth[d]), v3(400, 400, 0), &me))
				return 1;
			bvh *b = bvh_build(me.positions, me.num_vertices, me.indices, me.num_triangles);
			sss_probe_mesh pm = {b, &me};
			sss_probe pr = sss_probe_of_mesh(&pm);
			run r[2];
			for (int classic = 1; classic >= 0; classic--) {
				sss_walk_medium m;
				if (!sss_walk_medium_from_reduced(&m, md.sigma_s_per_mm, md.sigma_a_per_mm, 0.0, media[k].ior, 1.0))
					return 1;
				m.classic = classic;
				r[classic] = walk_many(&m, &pr, n, max_steps, d == 1 ? (float)-depth[d] : 0.0f);
			}
			for (int classic = 1; classic >= 0; classic--) {
				const run *x = &r[classic];
				char eff[32] = "", eff_steps[32] = "";
				if (!classic) {
					snprintf(eff, sizeof eff, "%.2f", (r[1].lum_var * r[1].seconds) / (r[0].lum_var * r[0].seconds));
					snprintf(eff_steps, sizeof eff_steps, "**%.2f**",
						 (r[1].lum_var * r[1].steps) / (r[0].lum_var * r[0].steps));
				}
				printf("| %s | %s | %s | %.0f | %.1f | %ld | %.4f ± %.4f | %.4f ± %.4f | %.4f ± %.4f | %s | %s |\n",
				       media[k].name, geometry[d], classic ? "classic" : "guided",
				       x->n / x->seconds, x->steps, x->dropped, x->mean[0], x->se[0], x->mean[1], x->se[1],
				       x->mean[2], x->se[2], eff, eff_steps);
			}
			fflush(stdout);
			bvh_free(b);
			mesh_free(&me);
		}
	}
	return 0;
}
