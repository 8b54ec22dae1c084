/* internals.c - the rest of functions.inc's internal functions (POV-Ray 3.7's
 * source/vm/fnintern.cpp defines each; its definitions were read, the code is ours): the
 * algebraic surfaces as fields (most scaled by their first parameter and clamped to [-10, 10],
 * as POV-Ray clamps them), the "_2d" curves swept or revolved, the helices, spirals, meshes and
 * blobs, and the noise-based fractals (f_ridge, f_ridged_mf, f_hetero_mf, f_noise_generator),
 * which run POV-Ray 3.7's own noise (scene/pattern.h's pattern_noise, base/noise.c's noise_pov);
 * f_pattern (77), POV-Ray's hook of pattern functions,
 * is 0 when a scene calls it directly, as in POV-Ray. func.c's table takes them from
 * lang_fn_internal_more. */
#include "lang/func.h"

#include <math.h>

static const double PI = 3.14159265358979323846;

/* The arguments: x, y, z, then the function's parameters P0, P1, ... (fnintern.cpp's PARAM). */
#define X a[0]
#define Y a[1]
#define Z a[2]
#define P(i) a[3 + (i)]

static double sq(double v) { return v * v; }
/* The usual field: k r within [-10, 10]. */
static double field(double k, double r) { return fmin(10.0, fmax(k * r, -10.0)); }

/* The plane curve of a "_2d" function at (u, v): with sweep = P(s) > 0 the curve is revolved
 * about the y axis at distance P(s+1) from it and tilted by P(s+2) degrees (fnintern.cpp's
 * ROT2D); otherwise it is extruded along z: (u, v) = (x, y). */
static void curve_point(const double *a, int s, double *u, double *v)
{
	*u = X, *v = Y;
	if (P(s) <= 0)
		return;
	double r = sqrt(X * X + Z * Z) - P(s + 1), th = P(s + 2) * PI / 180.0;
	if (th != 0) {
		*u = r * cos(th) - Y * sin(th);
		*v = r * sin(th) + Y * cos(th);
	} else {
		*u = r;
	}
}

/* The round, diamond or rounded-rectangle cross section of helices and spirals: the p-norm of
 * (u, v) with p = 2 / shape (shape 1: a circle, 2: a diamond), the max norm for shape 0. */
static double section(double u, double v, double shape)
{
	if (shape == 1)
		return sqrt(u * u + v * v);
	if (shape == 0)
		return fmax(fabs(u), fabs(v));
	double p = 2.0 / shape;
	return pow(pow(fabs(u), p) + pow(fabs(v), p), 1.0 / p);
}

/* The algebraic cylinders: curves of (u, v) extruded along z, the first clamped to P1. */
static double algbr_cyl(const double *a, int which)
{
	double u, v;
	curve_point(a, 2, &u, &v);
	double u2 = u * u, v2 = v * v, r;
	switch (which) {
	case 1: r = -(u2 * fabs(u) - u2 + v2); return -fmin(P(1), fmax(P(0) * r, -P(1)));
	case 2: r = -(2 * u2 * u2 - 3 * u2 * v + v2 - 2 * v2 * v + v2 * v2); break;
	case 3: r = -(u2 * u2 + u2 * v2 - 2 * u2 * v - u * v2 + v2); break;
	default: r = -(u2 * u2 + v2 * v2 + 2 * u2 * v2 + 3 * u2 * v - v2 * v); break;
	}
	return fmin(P(1), fmax(P(0) * r, -P(1)));
}
static double f_algbr_cyl1(const double *a) { return algbr_cyl(a, 1); }
static double f_algbr_cyl2(const double *a) { return algbr_cyl(a, 2); }
static double f_algbr_cyl3(const double *a) { return algbr_cyl(a, 3); }
static double f_algbr_cyl4(const double *a) { return algbr_cyl(a, 4); }

static double f_bicorn(const double *a)
{
	double s = X * X + Z * Z, b = P(1) * P(1), q = s + 2 * P(1) * Y - b;
	return field(P(0), Y * Y * (b - s) - q * q);
}
static double f_bifolia(const double *a)
{
	double s = X * X + Z * Z, r = s + Y * Y;
	return field(P(0), -(r * r - P(1) * s * Y));
}
/* Two blob components of strength P1 and P3, radii 1/P2 and 1/P4, P0 apart along x. */
static double f_blob(const double *a)
{
	double yz = Y * Y + Z * Z, h = P(0) * 0.5;
	double r1 = fmin(1.0, (sq(X + h) + yz) * P(2) * P(2)), r2 = fmin(1.0, (sq(X - h) + yz) * P(4) * P(4));
	return -(P(1) * sq(1 - r1) + P(3) * sq(1 - r2));
}
static double f_blob2(const double *a)
{
	double yz = Y * Y + Z * Z;
	return P(3) - P(2) * (exp(-(X * X + yz) * P(1)) + exp(-(sq(X - P(0)) + yz) * P(1)));
}
static double f_boy_surface(const double *a)
{
	double x2 = X * X, y2 = Y * Y, z2 = Z * Z, w = 1 - Z, s = x2 + y2, r2 = sqrt(2.0);
	double r = 64 * w * w * w * z2 * Z - 48 * w * w * z2 * (3 * x2 + 3 * y2 + 2 * z2) +
		   12 * w * Z * (27 * s * s - 24 * z2 * s + 36 * r2 * Y * Z * (y2 - 3 * x2) + 4 * z2 * z2) +
		   (9 * x2 + 9 * y2 - 2 * z2) * (-81 * s * s - 72 * z2 * s + 108 * r2 * X * Z * (x2 - 3 * y2) + 4 * z2 * z2);
	return field(P(0), P(1) * r);
}
static double f_comma(const double *a)
{
	double x = X == 0 && Z == 0 ? 0.0001 : X, s = P(0);
	double th = atan2(Z, x), r = sqrt(sq(x + s * 0.25) + Z * Z);
	double t = fmin(Z, cos(th * 0.5) * s * 0.5 - sqrt(sq(r - s * 0.75) + Y * Y));
	double b = s * 0.5 - sqrt(sq(x - s * 0.5) + Z * Z + Y * Y);
	return -fmax(t, b);
}
/* exp(-(k x^2 + k y^2 + z^2) s) and its two permutations: the three crossed ellipsoids. */
static void ellipsoids3(const double *a, double e[3])
{
	double x2 = X * X, y2 = Y * Y, z2 = Z * Z, k = P(0), s = P(1);
	e[0] = exp(-(x2 * k + y2 * k + z2) * s);
	e[1] = exp(-(x2 * k + y2 + z2 * k) * s);
	e[2] = exp(-(x2 + y2 * k + z2 * k) * s);
}
static double f_cross_ellipsoids(const double *a)
{
	double e[3];
	ellipsoids3(a, e);
	return P(3) - fmax(fmax(e[0], e[1]), e[2]) * P(2);
}
static double f_flange_cover(const double *a)
{
	double e[3];
	ellipsoids3(a, e);
	return P(3) - (e[0] + e[1] + e[2]) * P(2);
}
static double f_isect_ellipsoids(const double *a)
{
	double e[3];
	ellipsoids3(a, e);
	return P(3) - fmin(fmin(e[0], e[1]), e[2]) * P(2);
}
static double f_crossed_trough(const double *a) { return field(P(0), X * X * Z * Z - Y); }
static double f_cubic_saddle(const double *a) { return field(P(0), -(X * X * X - Y * Y * Y - Z)); }
/* f_cushion and f_odd are the same quartic (fnintern.cpp writes it twice). */
static double cushion(const double *a)
{
	double x2 = X * X, y2 = Y * Y, z2 = Z * Z;
	return z2 * x2 - z2 * z2 - 2 * Z * x2 + 2 * z2 * Z + x2 - z2 - sq(x2 - Z) - y2 * y2 - 2 * x2 * y2 - y2 * z2 +
	       2 * y2 * Z + y2;
}
static double f_cushion(const double *a) { return field(P(0), cushion(a)); }
static double f_odd(const double *a) { return field(P(0), cushion(a)); }
static double f_devils_curve(const double *a)
{
	double x2 = X * X, y2 = Y * Y, z2 = Z * Z;
	return field(P(0), -(x2 * x2 + 2 * x2 * z2 - 0.36 * x2 - y2 * y2 + 0.25 * y2 + z2 * z2));
}
static double f_devils_curve_2d(const double *a)
{
	double u, v;
	curve_point(a, 3, &u, &v);
	double u2 = u * u, v2 = v * v;
	return field(P(0), -(u2 * (u2 - P(1) * P(1)) - v2 * (v2 - P(2) * P(2))));
}
static double f_dupin_cyclid(const double *a)
{
	double x2 = X * X, y2 = Y * Y, z2 = Z * Z, d2 = P(5) * P(5), b2 = P(2) * P(2), c2 = P(4) * P(4);
	double k1 = b2 - c2 - sq(P(3) + P(1)), k2 = b2 - c2 - sq(P(3) - P(1)), a2 = P(3) * P(3), m2 = P(1) * P(1);
	double s = x2 + y2 + z2;
	double r = k1 * k2 * (x2 * x2 + y2 * y2 + z2 * z2) + 2 * k1 * k2 * (x2 * y2 + x2 * z2 + y2 * z2) +
		   2 * d2 * ((-c2 - a2 + b2 + m2) * (2 * X * P(3) + 2 * Y * P(4) - d2) - 4 * P(4) * b2 * Y) * s +
		   4 * d2 * d2 * (P(3) * X + P(4) * Y) * (-d2 + P(4) * Y + P(3) * X) + 4 * d2 * d2 * m2 * y2 +
		   d2 * d2 * d2 * d2;
	return field(P(0), -r);
}
/* POV-Ray 3.7's Enneper surface, as 3.7 computes it: its constants 2/3, 1/4, 8/9 and 2/9 were
 * integer divisions, so 0 (POV-Ray 3.8 fixed them and deprecates the old f_enneper; the 3.7
 * scenes and functions.inc circe reads have the 3.7 shape). */
static double f_enneper(const double *a)
{
	double x2 = X * X, y2 = Y * Y, z = fabs(Z) < 0.2 ? 0.2 : Z, z2 = Z * Z; /* z2: the z given */
	double p = (y2 - x2) / (2 * z) + 2 * z2 / 9, q = (y2 - x2) / (4 * z);
	return field(P(0), -(p * p * p - 6 * q * q));
}
static double f_folium_surface(const double *a)
{
	return field(P(0), (Y * Y + Z * Z) * (1 + (P(2) - 4 * P(1)) * X) + X * X * (1 + P(2)));
}
static double f_folium_surface_2d(const double *a)
{
	double u, v;
	curve_point(a, 3, &u, &v);
	return field(P(0), -(v * v * (1 + (P(2) - 4 * P(1)) * u) + u * u * (1 + P(2))));
}
static double f_glob(const double *a)
{
	double x2 = X * X;
	return field(P(0), 0.5 * x2 * x2 * X + 0.5 * x2 * x2 - (Y * Y + Z * Z));
}
static double f_helical_torus(const double *a)
{
	double rho = sqrt(X * X + Z * Z), x = X == 0 && Z == 0 ? 0.000001 : X;
	double ph = atan2(x, Z), tilt = atan2(rho - P(0), Y);
	double r = sqrt(sq(rho - P(0)) + Y * Y);
	double th = fmod(ph * P(1) + tilt * P(2), 2 * PI);
	if (th < 0)
		th += 2 * PI;
	double wob = cos(atan2((th - PI) * P(8), r - P(5)) * P(7) + ph * P(9)) * P(3) + P(4);
	double outer = P(4) + P(5) - P(0) - rho;
	th -= PI;
	wob -= fmin(sqrt(sq(r - P(5)) + th * th * P(6)), r + P(5));
	return -fmax(outer, wob);
}
/* P0 helices of frequency P1 about the y axis at radius P3, their section (P5, turned P6
 * degrees) of radius P2 squashed by P4 along the helix. */
static double f_helix1(const double *a)
{
	double rho = sqrt(X * X + Z * Z), x = X == 0 && Z == 0 ? 0.000001 : X;
	double th = fmod(atan2(Z, x) * P(0) + Y * P(1) * P(0), 2 * PI);
	if (th < 0)
		th += 2 * PI;
	double v = (th - PI) / P(4) / (P(1) * P(0)), u = rho - P(3), d;
	if (P(5) == 1) {
		d = sqrt(u * u + v * v);
	} else {
		if (P(6) != 0) {
			double c = cos(P(6) * PI / 180), s = sin(P(6) * PI / 180), t = u * c - v * s;
			v = u * s + v * c, u = t;
		}
		d = P(5) != 0 ? pow(pow(fabs(u), 2.0 / P(5)) + pow(fabs(v), 2.0 / P(5)), P(5) * 0.5) : fmax(fabs(u), fabs(v));
	}
	return -P(2) + fmin(P(3) + rho, d);
}
/* One helix of frequency P1 whose section of radius P2 (shape P5) circles the y axis at P3. */
static double f_helix2(const double *a)
{
	double c = cos(Y * P(1)), s = sin(Y * P(1)), dx = X - P(3) * c, dz = Z - P(3) * s;
	double u = dx * c + dz * s, v = -dx * s + dz * c;
	if (P(5) == 1)
		return sqrt(u * u + v * v) - P(2);
	double d = P(5) != 0 ? pow(pow(fabs(u), 2.0 / P(5)) + pow(fabs(v), 2.0 / P(5)), P(5) * 0.5) : fmax(fabs(u), fabs(v));
	return d - P(2);
}
/* The hexagonal tiling of the x-y plane (cells sqrt 3 by 3): the distance coordinates of the
 * point in its cell, measured along the cell's nearest axis (fnintern.cpp's f_hex_x / f_hex_y). */
static double hex(const double *a, bool want_y)
{
	double w = sqrt(3.0);
	double u = fabs(fmod(fabs(X), w) - w / 2), v = fabs(fmod(fabs(Y), 3) - 1.5);
	double u2 = w / 2 - u, v2 = 1.5 - v;
	if (u * u + v * v > u2 * u2 + v2 * v2)
		u = u2, v = v2;
	if (atan2(v, u) < PI / 6)
		return want_y ? v : u;
	return want_y ? fabs(-sin(PI / 3) * u + cos(PI / 3) * v) : cos(PI / 3) * u + sin(PI / 3) * v;
}
static double f_hex_x(const double *a) { return hex(a, false); }
static double f_hex_y(const double *a) { return hex(a, true); }
static double f_hunt_surface(const double *a)
{
	double x2 = X * X, y2 = Y * Y, z2 = Z * Z, s = x2 + y2 + z2 - 13, t = 3 * x2 + y2 - 4 * z2 - 12;
	return field(P(0), -(4 * s * s * s + 27 * t * t));
}
static double f_hyperbolic_torus(const double *a)
{
	double x2 = X * X, y2 = Y * Y, z2 = Z * Z, R = P(1) * P(1), r = P(2) * P(2);
	return field(P(0), -(x2 * x2 + 2 * x2 * y2 - 2 * x2 * z2 - 2 * (R + r) * x2 + y2 * y2 - 2 * y2 * z2 + 2 * (R - r) * y2 +
			     z2 * z2 + 2 * (R + r) * z2 + sq(R - r)));
}
static double f_kampyle_of_eudoxus(const double *a)
{
	double x2 = X * X, b2 = P(2) * P(2);
	return field(P(0), -((Y * Y + Z * Z) - b2 * x2 * x2 + b2 * P(1) * P(1) * x2));
}
/* As POV-Ray 3.7: its last term is P2^2 P1 P2 x^2 (where the 3-D form has P2^2 P1^2). */
static double f_kampyle_of_eudoxus_2d(const double *a)
{
	double u, v;
	curve_point(a, 3, &u, &v);
	double u2 = u * u, b2 = P(2) * P(2);
	return field(P(0), -(v * v - b2 * u2 * u2 + b2 * P(1) * P(2) * u2));
}
static double f_klein_bottle(const double *a)
{
	double s = X * X + Y * Y + Z * Z, m = s - 2 * Y - 1;
	return field(P(0), -((s + 2 * Y - 1) * (m * m - 8 * Z * Z) + 16 * X * Z * m));
}
static double f_kummer_surface_v1(const double *a)
{
	double x2 = X * X, y2 = Y * Y, z2 = Z * Z;
	return field(P(0), -(x2 * x2 + y2 * y2 + z2 * z2 - x2 - y2 - z2 - x2 * y2 - x2 * z2 - y2 * z2 + 1));
}
static double f_kummer_surface_v2(const double *a)
{
	double x2 = X * X, y2 = Y * Y, z2 = Z * Z;
	return field(P(0), -(x2 * x2 + y2 * y2 + z2 * z2 + P(1) * (x2 + y2 + z2) + P(2) * (x2 * y2 + x2 * z2 + y2 * z2) +
			     P(3) * X * Y * Z - 1));
}
static double f_lemniscate_of_gerono(const double *a)
{
	double x2 = X * X;
	return field(P(0), -(x2 * x2 - x2 + Y * Y + Z * Z));
}
static double f_lemniscate_of_gerono_2d(const double *a)
{
	double u, v;
	curve_point(a, 3, &u, &v);
	double u2 = u * u, b2 = P(2) * P(2);
	return field(P(0), -(v * v - b2 * P(1) * P(1) * u2 + b2 * u2 * u2));
}
/* The distance, scaled by (P2, P4), from (t, y) to a thread waving as y = w cos(phase). */
static double thread(double t, double period, double y, double wave, const double *a)
{
	double r = fmod(t, period * 2);
	if (r < 0)
		r += period * 2;
	r = fabs(r - period) * P(2);
	double h = (y - wave) * P(4);
	return -sqrt(h * h + r * r);
}
/* A woven mesh: threads along z every 2 P0 and along x every 2 P1, waving by P3 (POV-Ray's
 * four threads of f_mesh1). */
static double f_mesh1(const double *a)
{
	double kx = PI / P(0), kz = PI / P(1);
	double t = thread(X, P(0), Y, cos(Z * kz) * P(3), a);
	t = fmax(thread(X - P(0), P(0), Y, -cos(Z * kz) * P(3), a), t);
	t = fmax(thread(Z, P(1), Y, -cos(X * kx) * P(3), a), t);
	return -fmax(thread(Z - P(1), P(1), Y, cos(X * kx) * P(3), a), t);
}
static double f_mitre(const double *a)
{
	double x2 = X * X, y2 = Y * Y, z2 = Z * Z;
	return field(P(0), -(4 * x2 * (x2 + y2 + z2) - y2 * (1 - y2 - z2)));
}
static double f_nodal_cubic(const double *a) { return field(P(0), -(Y * Y * Y + Z * Z * Z - 6 * Y * Z)); }
static double f_ovals_of_cassini(const double *a)
{
	double s = X * X + Y * Y + Z * Z + P(1) * P(1);
	return field(P(0), -(s * s - P(3) * P(1) * P(1) * (X * X + Z * Z) - P(2) * P(2)));
}
static double f_parabolic_torus(const double *a)
{
	double x2 = X * X, y2 = Y * Y, z2 = Z * Z, R = P(1) * P(1), r = P(2) * P(2);
	return field(P(0), -(x2 * x2 + 2 * x2 * y2 - 2 * x2 * Z - (R + r) * x2 + y2 * y2 - 2 * y2 * Z + (R - r) * y2 + z2 +
			     (R + r) * Z + sq(R - r)));
}
static double f_pillow(const double *a)
{
	double x2 = X * X, y2 = Y * Y, z2 = Z * Z;
	return field(P(0), x2 * x2 + y2 * y2 + z2 * z2 - (x2 + y2 + z2));
}
static double f_piriform(const double *a)
{
	double x2 = X * X;
	return -field(P(0), -(x2 * x2 - x2 * X + Y * Y + Z * Z));
}
static double f_piriform_2d(const double *a)
{
	double u, v;
	curve_point(a, 4, &u, &v);
	double u2 = u * u, c2 = P(3) * P(3);
	return field(P(0), -(v * v - P(1) * c2 * u2 * u - P(2) * c2 * u2 * u2));
}
/* A surface of revolution about y whose radius is the quartic P0 + P1 y + ... + P4 y^4 (at least -5). */
static double f_poly4(const double *a)
{
	double y2 = Y * Y, r = fmax(-5.0, P(0) + P(1) * Y + P(2) * y2 + P(3) * y2 * Y + P(4) * y2 * y2);
	return -r + sqrt(X * X + Z * Z);
}
/* P0 tubes around the y axis at the radius the quartic of P1..P5 gives at y: the nearest one's
 * axis distance. */
static double f_polytubes(const double *a)
{
	double y2 = Y * Y, rad = P(1) + P(2) * Y + P(3) * y2 + P(4) * y2 * Y + P(5) * y2 * y2, best = -10000;
	for (int i = 0; i < (int)P(0); i++) {
		double ang = 2 * PI / P(0) * i, dx = X - rad * sin(ang), dz = Z - rad * cos(ang);
		best = fmax(best, -sqrt(dx * dx + dz * dz));
	}
	return -best;
}
/* A hydrogen-like orbital's density, r^2 e^(-r/3) (3 cos^2 theta - 1) at twice the distance. */
static double f_quantum(const double *a)
{
	double x = X == 0 && Z == 0 ? 1e-6 : X, rho = sqrt(x * x + Z * Z);
	double c = cos(atan2(rho, Y)), r = sqrt(rho * rho + Y * Y) * 2.0;
	double t = r * r * exp(-r * 0.33333333) * (3.0 * c * c - 1);
	return (t * t - 12.0) * -0.1;
}
static double f_quartic_paraboloid(const double *a)
{
	double x2 = X * X, z2 = Z * Z;
	return field(P(0), -(x2 * x2 + z2 * z2 - Y));
}
static double f_quartic_saddle(const double *a)
{
	double x2 = X * X, z2 = Z * Z;
	return field(P(0), -(x2 * x2 - z2 * z2 - Y));
}
/* Exponential spikes: a central blob of P4 e^(-P3 r^2) less the three crossed ellipsoids. */
static double f_spikes(const double *a)
{
	double e[3];
	ellipsoids3(a, e);
	double r = exp(-(X * X + Y * Y + Z * Z) * P(3)) * P(4) - e[0] - e[1] - e[2];
	return -r * P(2);
}
static double f_spikes_2d(const double *a)
{
	return -(P(0) * cos(P(1) * X) * cos(P(2) * Z) * exp(-P(3) * (X * X + Z * Z)) - Y);
}
/* A flat spiral about y of pitch P0 and thickness P1 (section P5), within radius P2. */
static double f_spiral(const double *a)
{
	double x = X == 0 && Z == 0 ? 0.000001 : X;
	double rho = sqrt(X * X + Z * Z) + P(0) * atan2(Z, x) / (2 * PI);
	double d = section(fmod(rho, P(0)) - P(0) * 0.5, Y, P(5)), r = sqrt(X * X + Y * Y + Z * Z);
	return -fmin(P(2) - r, P(1) - fmin(d, r));
}
static double f_steiners_roman(const double *a)
{
	double x2 = X * X, y2 = Y * Y, z2 = Z * Z;
	return field(P(0), -(x2 * y2 + x2 * z2 + y2 * z2 + X * Y * Z));
}
static double f_strophoid(const double *a)
{
	double x2 = X * X, c2 = P(3) * P(3);
	return field(P(0), -((P(2) - X) * (Y * Y + Z * Z) - c2 * P(1) * x2 - c2 * x2 * X));
}
static double f_strophoid_2d(const double *a)
{
	double u, v;
	curve_point(a, 4, &u, &v);
	double u2 = u * u, c2 = P(3) * P(3);
	return field(P(0), -((P(2) - u) * v * v - c2 * P(1) * u2 - c2 * u2 * u));
}
static double f_torus_gumdrop(const double *a)
{
	double x2 = X * X, s = Y * Y + Z * Z;
	return field(P(0), -(4 * (x2 * x2 + s * s) + 17 * x2 * s - 20 * (x2 + s) + 17));
}
static double f_umbrella(const double *a) { return field(P(0), -(X * X - Y * Z * Z)); }
static double f_witch_of_agnesi(const double *a) { return field(P(0), -(P(1) * (Y - 1) + (X * X + Z * Z) * Y)); }
static double f_witch_of_agnesi_2d(const double *a)
{
	double u, v;
	curve_point(a, 3, &u, &v);
	return field(P(0), -(P(1) * P(1) * v + u * u * v - P(2)));
}

/* ---- the noise-based fractals: POV-Ray's noise (pattern_noise), centred by 2 N - 1 ---- */

static double snoise(double x, double y, double z) { return pattern_noise(d3(x, y, z)) * 2.0 - 1.0; }

/* Musgrave's heterogeneous multifractal (Texturing and Modeling, 2nd ed., ch. 16), as POV-Ray
 * parameterises it: P0 H, P1 lacunarity, P2 octaves (a fraction too), P3 offset, P4 the power of
 * the signal scaling each increment, P5 the noise generator (circe has one). */
static double f_hetero_mf(const double *a)
{
	double x = X, y = Y, z = Z, signal = snoise(x, y, z) + P(3);
	double w = pow(P(1), -P(0)), e = w;
	x *= P(1), y *= P(1), z *= P(1);
	for (int i = 1; i < P(2); i++) {
		double inc = (snoise(x, y, z) + P(3)) * e;
		for (int k = (int)P(4); k > 0; k--)
			inc *= signal;
		signal += inc;
		x *= P(1), y *= P(1), z *= P(1);
		e *= w;
	}
	double frac = P(2) - (int)P(2);
	if (frac != 0.0)
		signal += frac * (snoise(x, y, z) + P(3)) * e * signal;
	return signal;
}
/* Ridged turbulence: octaves of |noise - P4| (scaled to reach 1) less P3, P0 lambda, P1
 * octaves (a fraction weighting the last), P2 omega, normalised by the weights' sum. */
static double f_ridge(const double *a)
{
	double lambda = P(0), omega = P(2), off = P(3), ridge = P(4);
	int octaves = (int)P(1);
	double rs = 1.0 / fmax(ridge, 1.0 - ridge), s = 1.0 / fmax(off, 1.0 - off), frac = P(1) - octaves;
	double value = fabs(pattern_noise(d3(X, Y, Z)) - ridge) * rs - off, tot = 1.0, l = lambda, o = omega;
	for (int i = 2; i <= octaves; i++) {
		value += o * (fabs(pattern_noise(d3(X * l, Y * l, Z * l)) - ridge) * rs - off);
		tot += o;
		l *= lambda, o *= omega;
	}
	if (frac != 0.0) {
		value += o * (fabs(pattern_noise(d3(X * l, Y * l, Z * l)) - ridge) * rs - off) * frac;
		tot += o * frac;
	}
	return value * s / tot;
}
/* Musgrave's ridged multifractal: P0 H, P1 lacunarity, P2 octaves, P3 offset, P4 gain. */
static double f_ridged_mf(const double *a)
{
	double x = X, y = Y, z = Z, freq = P(1), e = 1.0, w = pow(freq, -P(0));
	double signal = sq(P(3) - fabs(snoise(x, y, z))), result = signal;
	for (int i = 1; i < P(2); i++) {
		x *= freq, y *= freq, z *= freq;
		e *= w; /* pow(freq^i, -H) */
		double weight = fmin(1.0, fmax(0.0, signal * P(4)));
		signal = sq(P(3) - fabs(snoise(x, y, z))) * weight;
		result += signal * e;
	}
	return result;
}
/* POV-Ray's noise of generator P0: circe has one noise, whichever is asked. */
static double f_noise_generator(const double *a) { return pattern_noise(d3(X, Y, Z)); }

/* POV-Ray's f_pattern: the slot its pattern functions run through; called as internal(77) it has
 * no pattern and gives 0 (povray 3.7.0 prints 0 at any point: tests/lang/pov_internals_scene). */
static double f_pattern(const double *a)
{
	(void)a;
	return 0.0;
}

double (*lang_fn_internal_more(int n))(const double *)
{
	static double (*const more[])(const double *) = {
		[0] = f_algbr_cyl1, [1] = f_algbr_cyl2, [2] = f_algbr_cyl3, [3] = f_algbr_cyl4, [4] = f_bicorn,
		[5] = f_bifolia, [6] = f_blob, [7] = f_blob2, [8] = f_boy_surface, [9] = f_comma,
		[10] = f_cross_ellipsoids, [11] = f_crossed_trough, [12] = f_cubic_saddle, [13] = f_cushion,
		[14] = f_devils_curve, [15] = f_devils_curve_2d, [16] = f_dupin_cyclid, [18] = f_enneper,
		[19] = f_flange_cover, [20] = f_folium_surface, [21] = f_folium_surface_2d, [22] = f_glob,
		[24] = f_helical_torus, [25] = f_helix1, [26] = f_helix2, [27] = f_hex_x, [28] = f_hex_y,
		[29] = f_hetero_mf, [30] = f_hunt_surface, [31] = f_hyperbolic_torus, [32] = f_isect_ellipsoids,
		[33] = f_kampyle_of_eudoxus, [34] = f_kampyle_of_eudoxus_2d, [35] = f_klein_bottle,
		[36] = f_kummer_surface_v1, [37] = f_kummer_surface_v2, [38] = f_lemniscate_of_gerono,
		[39] = f_lemniscate_of_gerono_2d, [40] = f_mesh1, [41] = f_mitre, [42] = f_nodal_cubic, [43] = f_odd,
		[44] = f_ovals_of_cassini, [46] = f_parabolic_torus, [48] = f_pillow, [49] = f_piriform,
		[50] = f_piriform_2d, [51] = f_poly4, [52] = f_polytubes, [53] = f_quantum, [54] = f_quartic_paraboloid,
		[55] = f_quartic_saddle, [58] = f_ridge, [59] = f_ridged_mf, [62] = f_spikes, [63] = f_spikes_2d,
		[64] = f_spiral, [65] = f_steiners_roman, [66] = f_strophoid, [67] = f_strophoid_2d,
		[72] = f_torus_gumdrop, [73] = f_umbrella, [74] = f_witch_of_agnesi, [75] = f_witch_of_agnesi_2d,
		[77] = f_pattern, [78] = f_noise_generator,
	};
	return n >= 0 && n < (int)(sizeof more / sizeof *more) ? more[n] : NULL;
}
