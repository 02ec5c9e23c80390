/* elliptic.h: Jacobi's elliptic functions and the elliptic integrals, for real
 * arguments and a parameter m = k^2 in [0, 1], which libm does not have.
 *
 * The Jacobi functions sn, cn, dn (and the amplitude am) come from the descending
 * Landen (Gauss) transformation, the arithmetic-geometric mean's own sequence of
 * moduli (A&S 16.4, 16.12; DLMF 22.7(i), 22.20(ii)); the integrals from Carlson's
 * symmetric forms R_F, R_D, R_J and R_C by duplication (B. C. Carlson, "Numerical
 * computation of real or complex elliptic integrals", Numer. Algorithms 10, 1995;
 * DLMF 19.36(i)), with Legendre's forms written on them (DLMF 19.25(i)).
 *
 * Near m = 1 (the separatrix of a free rigid body) 1 - m in doubles keeps few
 * digits: a caller who knows the complementary parameter mc = 1 - m better than m
 * gives it (ell_param_mc, ell_Kc).  The conventions are A&S's: parameter m, and
 * Pi(n; phi | m) = integral of dtheta / ((1 - n sin^2) sqrt(1 - m sin^2)).
 * Relative errors are a few units of 1e-16 (tests/test_spin.c measures them).
 */
#ifndef VROC_ELLIPTIC_H
#define VROC_ELLIPTIC_H

/* Levels of the Landen sequence: 13 reach k_N < 1e-9 from mc = 5e-324. */
#define ELL_LEVELS 20

/* A parameter with what the Jacobi functions need of it, computed once: the
 * moduli k_1 .. k_N of its descending Landen sequence (k_{j+1} = (1 - k_j') /
 * (1 + k_j'), k_0 = sqrt(m)) down to k_N^2 < 1e-18, where sn is sin, and K(m). */
typedef struct {
    double m, mc;                 /* the parameter and 1 - m */
    double K;                     /* K(m), the quarter period (inf for m = 1) */
    double scale;                 /* pi / (2K) = 1 / prod (1 + k_j) */
    int levels;                   /* N */
    double k[ELL_LEVELS];         /* k_1 .. k_N */
    double k_comp[ELL_LEVELS];    /* 1 - k_1 .. 1 - k_N, without cancellation */
} ell_param;

/* The parameter m in [0, 1]; the parameter 1 - mc, mc in [0, 1].  Outside: m and
 * mc NAN, and every function of it NAN. */
ell_param ell_param_m(double m);
ell_param ell_param_mc(double mc);

/* sn(u|m), cn(u|m) and dn(u|m), any real u.  Each comes with a small relative
 * error, also near a zero of sn or cn (where it is that of u's rounding); m = 1
 * gives tanh u, sech u, sech u. */
void ell_sncndn(const ell_param *p, double u, double *sn, double *cn, double *dn);

/* am(u|m), the amplitude: the angle phi with F(phi|m) = u, continuous in u. */
double ell_am(const ell_param *p, double u);

/* The complete integrals K(m) and E(m), m in [0, 1]; K(1) = inf.  ell_Kc(mc) is
 * K(1 - mc). */
double ell_K(double m);
double ell_Kc(double mc);
double ell_E(double m);

/* The incomplete integral of the first kind F(phi|m), any real phi, m in [0, 1]
 * (inf for m = 1 and |phi| >= pi/2). */
double ell_F(double phi, double m);

/* The incomplete integral of the third kind Pi(n; phi|m), m in [0, 1]: any real
 * phi for n < 1; for n >= 1 only while 1 - n sin^2 phi > 0 (|phi| < pi/2), where
 * the integral is proper.  Otherwise NAN. */
double ell_Pi(double n, double phi, double m);

/* Pi(n; am u | m) for |u| <= K(m) and n < 1, from u and sn, cn, dn of it, as a
 * caller that has them at hand wants it: one R_J, and no cancellation also for
 * n << 0 (where Pi is near F / (1 - n)). */
double ell_Pi_sncndn(double n, double m, double sn, double cn, double dn, double u);

/* Carlson's symmetric integrals (DLMF 19.16(i), 19.2(iv)):
 *   R_F(x,y,z)   = 1/2 int_0^inf dt / sqrt((t+x)(t+y)(t+z)),
 *   R_J(x,y,z,p) = 3/2 int_0^inf dt / ((t+p) sqrt((t+x)(t+y)(t+z))),
 *   R_D(x,y,z)   = R_J(x,y,z,z),   R_C(x,y) = R_F(x,y,y).
 * x, y, z >= 0 with at most one of them 0, p > 0; R_C takes x >= 0, y != 0 (its
 * Cauchy principal value for y < 0).  Otherwise NAN. */
double ell_rf(double x, double y, double z);
double ell_rd(double x, double y, double z);
double ell_rj(double x, double y, double z, double p);
double ell_rc(double x, double y);

#endif
