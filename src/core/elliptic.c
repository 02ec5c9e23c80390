/* elliptic.c: Jacobi's elliptic functions by the descending Landen transformation,
 * and the elliptic integrals by Carlson's duplication (elliptic.h gives the
 * sources).
 *
 * sn, cn, dn.  The descending Landen transformation (DLMF 22.7(i)) writes the
 * functions of modulus k through those of the smaller k1 = (1 - k') / (1 + k') at
 * u / (1 + k1); repeated, the moduli fall quadratically (the AGM's c_n / a_n) to
 * k_N ~ 0, where sn = sin and dn = 1.  Climbing back, the usual recurrence of the
 * amplitude (A&S 16.4.3) takes an arcsine that loses half the digits when m is
 * near 1; here each level instead carries cs = cn/sn (or its inverse sc) and dn:
 *     cs(u, k) = cs(w, k1) dn(w, k1) / (1 + k1),
 *     dn(u, k) = ((1 - k1) + cs^2) / ((1 + k1) + cs^2),   w = u / (1 + k1),
 * products and quotients of positive numbers (1 - k1 = 2k' / (1 + k') is kept
 * without cancellation), so each level adds an ulp or two of relative error
 * whatever m, as in Bulirsch's algorithm (Numer. Math. 7, 1965).  sin and cos of
 * w_N = u pi / (2K) give the quadrant, so no reduction by the period is needed.
 *
 * Carlson's integrals: each duplication step moves the arguments to (x + lambda)
 * / 4 ..., lambda = sqrt(x y) + sqrt(x z) + sqrt(y z), which keeps the value and
 * shrinks the arguments' spread about their mean A by 4; once the spread is below
 * a tolerance the value is the fifth-order Taylor series about A (Carlson 1995,
 * section 2; DLMF 19.36(i)).  R_J adds at each step a term
 * 4^-m R_C(1, 1 + e_m) / d_m whose e_m falls by 64 a step: after the first one or
 * two, R_C is the series atan(sqrt e) / sqrt e = 1 - e/3 + e^2/5 - ..., no call;
 * 1 + e_m, near 0 when p is far below x, y, z, is taken as 2 sqrt(p)(p + lambda)
 * / d_m, which has no cancellation.
 */
#include "elliptic.h"

#include <math.h>
#include <stdbool.h>

#define PI_LO 1.2246467991473532e-16 /* pi - M_PI */

/* k_N below this: k_N^2 < 9e-19, sn(u, k_N) = sin u and dn = 1 within it. */
#define LANDEN_SMALL 9.5e-10

/* The duplication stops when the arguments' spread about their mean is below
 * TOL times it; the series left out are then below 1e-16 relatively:
 * (3r)^(1/6) with r = 1e-16 for R_F (fifth order), (3r)^(1/8) for R_C (seventh),
 * (r/4)^(1/6) for R_D and R_J (Carlson 1995, section 2). */
#define RF_TOL 0.0026
#define RC_TOL 0.012
#define RJ_TOL 0.0017

/* ---- the Landen sequence and the Jacobi functions ---- */

/* The arithmetic-geometric mean of 1 and sqrt(mc), mc > 0: K(1 - mc) = pi / (2M)
 * (A&S 17.6).  Once a and b agree to 1e-9 the next mean is exact. */
static double agm(double mc)
{
    double a = 1, b = sqrt(mc);
    while (a - b > 1e-9 * a) {
        double an = 0.5 * (a + b);
        b = sqrt(a * b);
        a = an;
    }
    return 0.5 * (a + b);
}

static ell_param param(double m, double mc)
{
    ell_param p = {.m = m, .mc = mc, .K = NAN, .scale = NAN};
    if (!(m >= 0 && m <= 1 && mc >= 0 && mc <= 1)) {
        p.m = p.mc = NAN;
        return p;
    }
    if (mc == 0) {
        p.K = INFINITY;
        p.scale = 0;
        return p;
    }
    /* k_{j+1} = k_j^2 / (1 + k_j')^2, k_{j+1}' = 2 sqrt(k_j') / (1 + k_j').  K is
     * (pi/2) prod (1 + k_j) too, but that product gathers an ulp a factor where
     * the AGM's mean keeps to one or two: K sets the period, and so the error of
     * sn(u) at large u. */
    double kk = m, kc = sqrt(mc);
    int n = 0;
    while (kk > LANDEN_SMALL * LANDEN_SMALL && n < ELL_LEVELS) {
        double k1 = kk / ((1 + kc) * (1 + kc));
        p.k[n] = k1;
        p.k_comp[n] = 2 * kc / (1 + kc);
        kc = 2 * sqrt(kc) / (1 + kc);
        kk = k1 * k1;
        n++;
    }
    p.levels = n;
    p.scale = agm(mc);
    p.K = M_PI_2 / p.scale;
    return p;
}

ell_param ell_param_m(double m) { return param(m, 1 - m); }
ell_param ell_param_mc(double mc) { return param(1 - mc, mc); }

void ell_sncndn(const ell_param *p, double u, double *sn, double *cn, double *dn)
{
    if (p->mc == 0) {
        *sn = tanh(u);
        *cn = *dn = 1 / cosh(u);
        return;
    }
    double w = u * p->scale, s = sin(w), c = cos(w);
    /* x is cn/sn (ratio) or, while |sn| < |cn|, sn/cn (tangent): neither
     * overflows nor loses digits near a zero of sn or cn */
    bool tangent = fabs(s) < fabs(c);
    double x = tangent ? s / c : c / s, d = 1;
    for (int j = p->levels - 1; j >= 0; j--) {
        double k = p->k[j], kc = p->k_comp[j], x2 = x * x;
        if (tangent) {
            double d_up = (1 + kc * x2) / (1 + (1 + k) * x2);
            x *= (1 + k) / d;
            d = d_up;
            if (fabs(x) > 1) {
                x = 1 / x;
                tangent = false;
            }
        } else {
            double d_up = (kc + x2) / ((1 + k) + x2);
            x *= d / (1 + k);
            d = d_up;
        }
    }
    /* the Landen steps keep the signs of sn and cn: those of sin w and cos w */
    double h = 1 / sqrt(1 + x * x);
    *sn = copysign(tangent ? fabs(x) * h : h, s);
    *cn = copysign(tangent ? h : fabs(x) * h, c);
    *dn = d;
}

double ell_am(const ell_param *p, double u)
{
    if (p->mc == 0) return atan(sinh(u)); /* the Gudermannian */
    if (isnan(p->mc)) return NAN;
    double sn, cn, dn;
    ell_sncndn(p, u, &sn, &cn, &dn);
    /* u = 2K j + r, |r| <= K: am(u) = j pi + am(r), cn(r) = (-1)^j cn(u) >= 0 */
    double j = nearbyint(u * p->scale / M_PI);
    if (fmod(j, 2) != 0) {
        sn = -sn;
        cn = -cn;
    }
    return fma(j, M_PI, j * PI_LO + atan2(sn, cn));
}

/* ---- Carlson's integrals ---- */

double ell_rf(double x, double y, double z)
{
    if (!(x >= 0 && y >= 0 && z >= 0) || (x == 0) + (y == 0) + (z == 0) > 1) return NAN;
    double a0 = (x + y + z) / 3, a = a0;
    double dx = a0 - x, dy = a0 - y, dz = a0 - z;
    double q = fmax(fabs(dx), fmax(fabs(dy), fabs(dz))) / RF_TOL, f = 1;
    while (q * f >= a) {
        double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
        double lam = sx * (sy + sz) + sy * sz;
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        z = 0.25 * (z + lam);
        a = 0.25 * (a + lam);
        f *= 0.25;
    }
    /* X = (A0 - x0) / (4^m A_m): the differences shrink by exactly 4 a step */
    double X = dx * f / a, Y = dy * f / a, Z = -(X + Y);
    double e2 = X * Y - Z * Z, e3 = X * Y * Z;
    return (1 - e2 / 10 + e3 / 14 + e2 * e2 / 24 - 3 * e2 * e3 / 44) / sqrt(a);
}

double ell_rc(double x, double y)
{
    if (!(x >= 0) || y == 0 || isnan(y)) return NAN;
    if (y < 0) return sqrt(x / (x - y)) * ell_rc(x - y, -y); /* DLMF 19.2(iv) */
    double a0 = (x + 2 * y) / 3, a = a0, dy = y - a0;
    double q = fabs(a0 - x) / RC_TOL, f = 1;
    while (q * f >= a) {
        double lam = 2 * sqrt(x) * sqrt(y) + y;
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        a = 0.25 * (a + lam);
        f *= 0.25;
    }
    double s = dy * f / a;
    return (1 + s * s * (3.0 / 10 + s * (1.0 / 7 + s * (3.0 / 8 + s * (9.0 / 22 +
            s * (159.0 / 208 + s * (9.0 / 8))))))) / sqrt(a);
}

/* R_C(1, y) for y = 1 + e in (0, 2), as R_J needs it: the series of
 * atan(sqrt e) / sqrt e for small e, else its closed form; below 1 as
 * acosh(1 / sqrt y) / sqrt(-e), with e and y each known without cancellation. */
static double rc_one(double e, double y)
{
    if (fabs(e) < 0.01) /* sum (-e)^i / (2i + 1), the rest below 6e-18 */
        return 1 - e * (1.0 / 3 - e * (1.0 / 5 - e * (1.0 / 7 - e * (1.0 / 9 -
               e * (1.0 / 11 - e * (1.0 / 13 - e * (1.0 / 15)))))));
    double s = sqrt(fabs(e));
    return e > 0 ? atan(s) / s : log((1 + s) / sqrt(y)) / s;
}

/* The fifth-order series of R_J and R_D about their mean, in its differences
 * (Carlson 1995, section 2); e2 .. e5 the elementary symmetric functions. */
static double rj_series(double e2, double e3, double e4, double e5)
{
    return 1 - 3 * e2 / 14 + e3 / 6 + 9 * e2 * e2 / 88 - 3 * e4 / 22 - 9 * e2 * e3 / 52 +
           3 * e5 / 26;
}

double ell_rj(double x, double y, double z, double p)
{
    if (!(x >= 0 && y >= 0 && z >= 0 && p > 0) || (x == 0) + (y == 0) + (z == 0) > 1)
        return NAN;
    double a0 = (x + y + z + 2 * p) / 5, a = a0;
    double dx = a0 - x, dy = a0 - y, dz = a0 - z, dp = a0 - p;
    double delta = (p - x) * (p - y) * (p - z);
    double q = fmax(fmax(fabs(dx), fabs(dy)), fmax(fabs(dz), fabs(dp))) / RJ_TOL;
    double f = 1, f3 = 1, sum = 0;
    while (q * f >= a) {
        double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z), sp = sqrt(p);
        double lam = sx * (sy + sz) + sy * sz;
        /* d_m, and 1 + e_m = 1 + 4^-3m delta / d_m^2 = 2 sqrt(p) (p + lam) / d_m */
        double id = 1 / ((sp + sx) * (sp + sy) * (sp + sz));
        sum += f * id * rc_one(f3 * delta * id * id, 2 * sp * (p + lam) * id);
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        z = 0.25 * (z + lam);
        p = 0.25 * (p + lam);
        a = 0.25 * (a + lam);
        f *= 0.25;
        f3 *= 1.0 / 64;
    }
    double X = dx * f / a, Y = dy * f / a, Z = dz * f / a, P = -0.5 * (X + Y + Z);
    double xyz = X * Y * Z, p2 = P * P;
    double e2 = X * Y + X * Z + Y * Z - 3 * p2;
    double e3 = xyz + 2 * e2 * P + 4 * p2 * P;
    double e4 = (2 * xyz + e2 * P + 3 * p2 * P) * P;
    double e5 = xyz * p2;
    return f / (a * sqrt(a)) * rj_series(e2, e3, e4, e5) + 6 * sum;
}

double ell_rd(double x, double y, double z)
{
    if (!(x >= 0 && y >= 0 && z > 0) || (x == 0 && y == 0)) return NAN;
    double a0 = (x + y + 3 * z) / 5, a = a0;
    double dx = a0 - x, dy = a0 - y, dz = a0 - z;
    double q = fmax(fabs(dx), fmax(fabs(dy), fabs(dz))) / RJ_TOL, f = 1, sum = 0;
    while (q * f >= a) {
        double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
        double lam = sx * (sy + sz) + sy * sz;
        sum += f / (sz * (z + lam));
        x = 0.25 * (x + lam);
        y = 0.25 * (y + lam);
        z = 0.25 * (z + lam);
        a = 0.25 * (a + lam);
        f *= 0.25;
    }
    double X = dx * f / a, Y = dy * f / a, Z = -(X + Y) / 3;
    double xy = X * Y, z2 = Z * Z;
    double e2 = xy - 6 * z2, e3 = (3 * xy - 8 * z2) * Z, e4 = 3 * (xy - z2) * z2, e5 = xy * z2 * Z;
    return f / (a * sqrt(a)) * rj_series(e2, e3, e4, e5) + 3 * sum;
}

/* ---- Legendre's integrals ---- */

double ell_Kc(double mc)
{
    if (!(mc >= 0 && mc <= 1)) return NAN;
    return mc == 0 ? INFINITY : M_PI_2 / agm(mc);
}

double ell_K(double m) { return m >= 0 && m <= 1 ? ell_Kc(1 - m) : NAN; }

double ell_E(double m)
{
    if (!(m >= 0 && m <= 1)) return NAN;
    if (m == 1) return 1;
    /* DLMF 19.25(i)'s second form of E: two positive terms (the first, R_F - m/3 R_D,
     * loses digits as K grows near m = 1) */
    double mc = 1 - m;
    return mc / 3 * (ell_rd(0, mc, 1) + ell_rd(0, 1, mc));
}

/* phi = j pi + r, |r| <= pi/2. */
static double reduce_pi(double phi, double *r)
{
    double j = nearbyint(phi / M_PI);
    *r = fma(-j, M_PI, phi) - j * PI_LO;
    return j;
}

double ell_F(double phi, double m)
{
    if (!(m >= 0 && m <= 1)) return NAN;
    double r, j = reduce_pi(phi, &r);
    double s = sin(r), c = cos(r);
    /* DLMF 19.25(i); 1 - m s^2 as c^2 + (1 - m) s^2, without cancellation */
    double f = s * ell_rf(c * c, c * c + (1 - m) * s * s, 1);
    return j == 0 ? f : f + 2 * j * ell_K(m);
}

double ell_Pi_sncndn(double n, double m, double sn, double cn, double dn, double u)
{
    if (sn == 0) return u;
    double s3 = sn * sn * sn;
    if (n >= -sqrt(m)) /* DLMF 19.25(i): F + n/3 s^3 R_J, F = u */
        return u + n / 3 * s3 * ell_rj(cn * cn, dn * dn, 1, 1 - n * sn * sn);
    /* n < -k: F + n/3 s^3 R_J cancels (Pi ~ F / (1 - n)); with N = m/n (DLMF
     * 19.7(iii)) Pi(n) = F - Pi(N) + s R_C(c^2 dn^2, (1 - n s^2)(1 - N s^2)), the two
     * arguments of R_C differing by s^2 w^2: two positive terms */
    double N = m / n, w = sqrt(1 + m - n - N);
    return atan2(w * sn, cn * dn) / w - N / 3 * s3 * ell_rj(cn * cn, dn * dn, 1, 1 - N * sn * sn);
}

double ell_Pi(double n, double phi, double m)
{
    if (!(m >= 0 && m <= 1) || isnan(n)) return NAN;
    double r, j = reduce_pi(phi, &r);
    if (j != 0 && !(n < 1)) return NAN;
    if (j != 0 && m == 1) return copysign(INFINITY, j);
    double s = sin(r), c = cos(r), mc = 1 - m;
    if (!(1 - n * s * s > 0)) return NAN;
    /* sn, cn, dn of u = F(r|m) */
    double d = sqrt(c * c + mc * s * s);
    double v = ell_Pi_sncndn(n, m, s, c, d, s * ell_rf(c * c, d * d, 1));
    if (j != 0) v += 2 * j * ell_Pi_sncndn(n, m, 1, 0, sqrt(mc), ell_K(m));
    return v;
}
