/* region.c: integrals over a flat contact region (region.h).
 *
 * The slip field of a plane motion is a turn about its centre c (where v + w J
 * c = 0): s(x) = sgn(w) J e, e = (x - c) / |x - c|.  Over the triangle (c, a,
 * b), in polar coordinates about c with psi measured from the foot of the
 * perpendicular to the line ab (at distance d, unit n towards it, t along it),
 * r runs to d sec psi and e = cos psi n + sin psi t, so that every integral
 * of r^j e^i is d^(j+2) / (j+2) times one of sec^(j+2) psi times cos and sin,
 * each in closed form in t = tan psi, s = sec psi, L = asinh t = ln(s + t):
 * int sec = L, int sec tan = s, int sec^3 = (s t + L) / 2, int sec tan^2 =
 * (s t - L) / 2, int sec^3 tan = s^3 / 3.
 */
#include "region.h"

#include <math.h>

double region_arm(region_pt a, region_pt b)
{
    /* int int r r dr dpsi = d^3 / 3 int sec^3 psi dpsi */
    double ex = b.x - a.x, ey = b.y - a.y, len = hypot(ex, ey), cr = a.x * b.y - a.y * b.x;
    if (!(len > 0) || cr == 0) return 0;
    double d = fabs(cr) / len, tx = ex / len, ty = ey / len;
    double ta = (a.x * tx + a.y * ty) / d, tb = (b.x * tx + b.y * ty) / d; /* tan psi */
    double sa = hypot(1, ta), sb = hypot(1, tb);                           /* sec psi */
    double f = (sb * tb + log(sb + tb)) - (sa * ta + log(sa + ta));
    return copysign(d * d * d / 6 * f, cr);
}

region_moments region_moments_of(const region_pt *p, int n)
{
    region_moments m = {0, {0, 0}, {{0, 0}, {0, 0}}};
    for (int k = 0; k < n; k++) {
        region_pt a = p[k], b = p[(k + 1) % n];
        double A = 0.5 * (a.x * b.y - a.y * b.x);
        double ax[2] = {a.x, a.y}, bx[2] = {b.x, b.y};
        m.area += A;
        for (int i = 0; i < 2; i++) {
            m.m1[i] += A * (ax[i] + bx[i]) / 3;
            for (int j = 0; j < 2; j++)
                m.m2[i][j] += A / 6 * (ax[i] * ax[j] + bx[i] * bx[j]) + A / 12 * (ax[i] * bx[j] + bx[i] * ax[j]);
        }
    }
    return m;
}

int region_clip(const region_pt *p, int n, double a, const double k[2], region_pt *out)
{
    int m = 0;
    for (int i = 0; i < n; i++) {
        region_pt x = p[i], y = p[(i + 1) % n];
        double fx = a + k[0] * x.x + k[1] * x.y, fy = a + k[0] * y.x + k[1] * y.y;
        if (fx >= 0) out[m++] = x;
        if ((fx >= 0) != (fy >= 0)) {
            double s = fx / (fx - fy);
            out[m++] = (region_pt){x.x + s * (y.x - x.x), x.y + s * (y.y - x.y)};
        }
    }
    return m;
}

/* The integrals of e = (x - c) / |x - c| over the triangle (c, c + a, c + b),
 * signed as the turn from a to b, about c: e0 = int e, ee = int r e e^T, r1 =
 * int r, re = int r^2 e (r = |x - c|). */
typedef struct {
    double e0[2], ee[2][2], r1, re[2];
} fan_part;

static fan_part fan_triangle(region_pt a, region_pt b)
{
    fan_part f = {{0, 0}, {{0, 0}, {0, 0}}, 0, {0, 0}};
    double ex = b.x - a.x, ey = b.y - a.y, len = hypot(ex, ey), cr = a.x * b.y - a.y * b.x;
    if (!(len > 0) || cr == 0) return f;
    double t[2] = {ex / len, ey / len}, ta = (a.x * t[0] + a.y * t[1]);
    double d = fabs(cr) / len, nv[2] = {(a.x - ta * t[0]) / d, (a.y - ta * t[1]) / d};
    double tb = (b.x * t[0] + b.y * t[1]) / d;
    ta /= d;
    double sa = sqrt(1 + ta * ta), sb = sqrt(1 + tb * tb), La = asinh(ta), Lb = asinh(tb);
    double sg = cr > 0 ? 1 : -1, d2 = sg * d * d / 2, d3 = sg * d * d * d / 3, d4 = sg * d * d * d * d / 4;
    double cc = Lb - La;                                  /* int sec^3 cos^2 = int sec^2 cos */
    double s1 = sb - sa;                                  /* int sec^2 sin */
    double sc = s1;                                       /* int sec^3 sin cos = int sec tan */
    double ss = 0.5 * ((sb * tb - Lb) - (sa * ta - La));  /* int sec^3 sin^2 */
    double k3 = 0.5 * ((sb * tb + Lb) - (sa * ta + La));  /* int sec^3 = int sec^4 cos */
    double s4 = (sb * sb * sb - sa * sa * sa) / 3;        /* int sec^4 sin */
    for (int i = 0; i < 2; i++) {
        f.e0[i] = d2 * (cc * nv[i] + s1 * t[i]);
        f.re[i] = d4 * (k3 * nv[i] + s4 * t[i]);
        for (int j = 0; j < 2; j++)
            f.ee[i][j] = d3 * (cc * nv[i] * nv[j] + sc * (nv[i] * t[j] + t[i] * nv[j]) + ss * t[i] * t[j]);
    }
    f.r1 = d3 * k3;
    return f;
}

/* Gauss-Legendre's 8 points and weights on [0, 1] */
static const double GX[8] = {0.019855071751231856, 0.10166676129318664, 0.2372337950418355, 0.4082826787521751,
                             0.5917173212478249,   0.7627662049581645,  0.8983332387068134, 0.9801449282487681};
static const double GW[8] = {0.05061426814518813, 0.11119051722668724, 0.15685332293894363, 0.18134189168918100,
                             0.18134189168918100, 0.15685332293894363, 0.11119051722668724, 0.05061426814518813};

region_slip region_slip_of(const region_pt *p, int n, const double v[2], double w, double reach)
{
    region_slip r = {{0, 0}, {{0, 0}, {0, 0}}, 0, {0, 0}};
    double vl = hypot(v[0], v[1]);
    if (fabs(w) * 4 * reach > vl) {
        /* the centre c: v + w J c = 0; s = sgn(w) J e, x * s = sgn(w) x . e */
        double c[2] = {-v[1] / w, v[0] / w}, sg = w > 0 ? 1 : -1;
        double e0[2] = {0, 0}, e1[2][2] = {{0, 0}, {0, 0}}, t0 = 0, t1[2] = {0, 0};
        for (int k = 0; k < n; k++) {
            region_pt a = {p[k].x - c[0], p[k].y - c[1]}, b = {p[(k + 1) % n].x - c[0], p[(k + 1) % n].y - c[1]};
            fan_part f = fan_triangle(a, b);
            /* x = c + r e: int e x^T = e0 c^T + ee; int x . e = c . e0 + r1;
             * int (x . e) x = (c . e0 + r1) c + ee c + re */
            double ce = c[0] * f.e0[0] + c[1] * f.e0[1];
            for (int i = 0; i < 2; i++) {
                e0[i] += f.e0[i];
                for (int j = 0; j < 2; j++) e1[i][j] += f.e0[i] * c[j] + f.ee[i][j];
                t1[i] += (ce + f.r1) * c[i] + f.ee[i][0] * c[0] + f.ee[i][1] * c[1] + f.re[i];
            }
            t0 += ce + f.r1;
        }
        /* J (a, b) = (-b, a) */
        r.s0[0] = -sg * e0[1], r.s0[1] = sg * e0[0];
        for (int j = 0; j < 2; j++) r.s1[0][j] = -sg * e1[1][j], r.s1[1][j] = sg * e1[0][j];
        r.u0 = sg * t0;
        r.u1[0] = sg * t1[0], r.u1[1] = sg * t1[1];
        return r;
    }
    /* the centre far off (or none): a fan from corner 0, each triangle (p0, a,
     * b) mapped from the unit square by x = p0 + xi (a' + eta (b' - a')),
     * dA = xi |a' x b'| */
    if (!(vl > 0)) return r;
    for (int k = 1; k + 1 < n; k++) {
        double ax = p[k].x - p[0].x, ay = p[k].y - p[0].y, bx = p[k + 1].x - p[0].x, by = p[k + 1].y - p[0].y;
        double jac = ax * by - ay * bx;
        for (int i = 0; i < 8; i++)
            for (int j = 0; j < 8; j++) {
                double xi = GX[i], eta = GX[j], wt = GW[i] * GW[j] * xi * jac;
                double x = p[0].x + xi * (ax + eta * (bx - ax)), y = p[0].y + xi * (ay + eta * (by - ay));
                double sx = v[0] - w * y, sy = v[1] + w * x, sl = sqrt(sx * sx + sy * sy);
                sx /= sl, sy /= sl;
                double xs = x * sy - y * sx;
                r.s0[0] += wt * sx, r.s0[1] += wt * sy;
                r.s1[0][0] += wt * sx * x, r.s1[0][1] += wt * sx * y;
                r.s1[1][0] += wt * sy * x, r.s1[1][1] += wt * sy * y;
                r.u0 += wt * xs;
                r.u1[0] += wt * xs * x, r.u1[1] += wt * xs * y;
            }
    }
    return r;
}
