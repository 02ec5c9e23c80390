/* region.h: integrals over a flat contact region, a convex polygon in the plane
 * of a face (2D coordinates): its moments, the polygon cut where a linear
 * pressure turns negative, and the integrals of the slip's direction field of a
 * body that slides and spins on it (facespin.h), exact where the polygon is near
 * the centre of that spin.
 */
#ifndef VROC_REGION_H
#define VROC_REGION_H

typedef struct {
    double x, y;
} region_pt;

/* The integral of the distance from the origin over the triangle (0, a, b),
 * signed as the turn from a to b (exact). */
double region_arm(region_pt a, region_pt b);

/* The moments of polygon p (n corners, counterclockwise): its area, int x dA,
 * int x x^T dA. */
typedef struct {
    double area, m1[2], m2[2][2];
} region_moments;

region_moments region_moments_of(const region_pt *p, int n);

/* The part of polygon p (n corners, convex, counterclockwise) where a + k . x
 * >= 0, into out (room for n + 1): its corner count. */
int region_clip(const region_pt *p, int n, double a, const double k[2], region_pt *out);

/* The integrals over polygon p of the unit slip s(x) = (v + w J x) / |v + w J x|
 * of a plane motion (J the quarter turn, (x, y) -> (-y, x)): s0 = int s dA, s1
 * = int s x^T dA, u0 = int x * s dA, u1 = int (x * s) x dA (x * s the plane's
 * cross product). */
typedef struct {
    double s0[2], s1[2][2], u0, u1[2];
} region_slip;

/* reach: no corner of p is further than that from the origin.  Exact (each
 * triangle from the centre of the spin, in closed form) where that centre is
 * within 4 reach; else (the field smooth over p) by an 8 x 8 Gauss rule on each
 * triangle of a fan, to far below 1e-9 relative. */
region_slip region_slip_of(const region_pt *p, int n, const double v[2], double w, double reach);

#endif
