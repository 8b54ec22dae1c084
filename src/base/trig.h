/* trig.h - atan2 for the hot paths: trig_atan2 gives libm's atan2 to about 1e-15 radians, in a
 * fraction of its time and without a branch on the quadrant (circle tracing calls it once a hit, at
 * the end of a long chain of dependent operations, where libm's call dominated: bench/README.md). */
#ifndef CIRCE_BASE_TRIG_H
#define CIRCE_BASE_TRIG_H

#include <math.h>

/* atan(k / 16) for k = 0 to 16, as glibc's atan (correctly rounded) gives them. */
static const double trig_atan_table[17] = {
    0.0,
    0.06241880999595735,
    0.12435499454676144,
    0.18534794999569476,
    0.24497866312686414,
    0.30288486837497142,
    0.35877067027057225,
    0.41241044159738732,
    0.46364760900080609,
    0.51238946031073773,
    0.55859931534356244,
    0.60228734613496415,
    0.64350110879328437,
    0.68231655487474807,
    0.71882999962162453,
    0.75315128096219441,
    0.78539816339744828,
};

/* The angle of (x, y) in [-pi, pi], as atan2(y, x), for finite x and y (both zero: +-0 or +-pi by
 * their signs, as atan2). The octant reduction gives t = min(|x|, |y|) / max(|x|, |y|) in [0, 1];
 * with c = k / 16 the nearest sixteenth, atan t = atan c + atan u, u = (t - c) / (1 + t c) and
 * |u| <= 1/32, where atan's series to u^11 leaves under u^13 / 13 < 3e-21. The rounding of the
 * divisions, the table and the three additions keeps the result within 1e-15 of atan2's (and the
 * float it rounds to is atan2's float but within 1e-15 of a rounding boundary); tests/base/test_trig
 * checks it against libm. */
static inline double trig_atan2(double y, double x)
{
	double ax = fabs(x), ay = fabs(y);
	double hi = ax > ay ? ax : ay, lo = ax > ay ? ay : ax;
	double t = hi > 0.0 ? lo / hi : 0.0;
	int k = (int)(t * 16.0 + 0.5);
	double c = k * 0.0625;
	double u = (t - c) / (1.0 + t * c), u2 = u * u;
	double series = u2 * (1.0 / 9.0 + u2 * (-1.0 / 11.0));
	series = u2 * (1.0 / 5.0 + u2 * (-1.0 / 7.0 + series));
	series = u + u * u2 * (-1.0 / 3.0 + series);
	double a = trig_atan_table[k] + series;
	/* The octant by arithmetic on 0/1 flags (the quadrant is a coin toss a branch mispredicts):
	 * s pi/2 + (1 - 2 s) a is pi/2 - a or a, exactly. */
	int swap = ay > ax, back = signbit(x) != 0;
	a = M_PI_2 * swap + (1 - 2 * swap) * a;
	a = M_PI * back + (1 - 2 * back) * a;
	return copysign(a, y);
}

#endif
