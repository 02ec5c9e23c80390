/* test_spin.c: the elliptic functions and integrals, and the exact free rigid body.
 *
 * Reference values, none from this code:
 *   - Carlson's published test values of R_F, R_C, R_D, R_J (B. C. Carlson,
 *     Numer. Algorithms 10 (1995) 13-26, section 3), to their 14 digits;
 *   - closed forms: K(1/2), the lemniscatic case (A&S 18.14.7),
 *     and K(sin^2 15 deg) = 3^(1/4) Gamma(1/3)^3 / (2^(7/3) pi), a singular value;
 *     sn, cn, dn at K/2 and K (DLMF 22.5(i)); m = 0 and m = 1 (DLMF 22.5(ii));
 *     F and Pi at m = 0 and m = 1 and n = 0 (DLMF 19.6); R_C's elementary forms
 *     (DLMF 19.2(iv));
 *   - identities: sn^2 + cn^2 = 1, dn^2 + m sn^2 = 1, the addition theorems (DLMF
 *     22.8.1-3), the periods (DLMF 22.4), Legendre's relation (DLMF 19.7.1);
 *   - generic values of sn, cn, dn, F and Pi from an independent 30-digit
 *     evaluation (mpmath 1.3), and F, E, Pi by Romberg quadrature of their
 *     integrands written here;
 *   - Euler's equations integrated with classical RK4 at 1e-5 s (written here).
 */
#include "check.h"

#include <stdlib.h>
#include <time.h>

#include "core/elliptic.h"
#include "core/spin.h"

#define EPS 2.220446049250313e-16

/* |a - b| <= tol |b| and a a number */
static void rel_ok(double a, double b, double tol, const char *what)
{
    if (!(fabs(a - b) <= tol * fabs(b)))
        fail_msg("%s: got %.17g, want %.17g, relative difference %.3g > %.3g", what, a, b,
                 fabs(a - b) / fabs(b), tol);
}

static double worst; /* the largest relative error a test saw, for its message */

static void rel_track(double a, double b, double tol, const char *what)
{
    rel_ok(a, b, tol, what);
    if (b != 0) worst = fmax(worst, fabs(a - b) / fabs(b));
}

/* ---- Carlson's integrals ---- */

static void carlson_published_values(void **state)
{
    (void)state;
    worst = 0;
    /* Carlson 1995, section 3: 14 significant digits */
    rel_track(ell_rf(1, 2, 0), 1.3110287771461, 5e-14, "R_F(1,2,0)");
    rel_track(ell_rf(2, 3, 4), 0.58408284167715, 5e-14, "R_F(2,3,4)");
    rel_track(ell_rc(0, 0.25), M_PI, 4 * EPS, "R_C(0,1/4)");
    rel_track(ell_rc(2.25, 2), log(2), 4 * EPS, "R_C(9/4,2)");
    rel_track(ell_rc(0.25, -2), log(2) / 3, 4 * EPS, "R_C(1/4,-2)");
    rel_track(ell_rj(0, 1, 2, 3), 0.77688623778582, 5e-14, "R_J(0,1,2,3)");
    rel_track(ell_rj(2, 3, 4, 5), 0.14297579667157, 5e-14, "R_J(2,3,4,5)");
    rel_track(ell_rd(0, 2, 1), 1.7972103521034, 5e-14, "R_D(0,2,1)");
    rel_track(ell_rd(2, 3, 4), 0.16510527294261, 5e-14, "R_D(2,3,4)");
    /* R_F(0,1,2) = R_F(1,2,0) is the lemniscate constant Gamma(1/4)^2 / (4 sqrt(2 pi)) */
    rel_track(ell_rf(0, 1, 2), pow(tgamma(0.25), 2) / (4 * sqrt(2 * M_PI)), 4 * EPS, "lemniscate");
    print_message("Carlson's test values: largest relative error %.3g\n", worst);
}

static void carlson_closed_forms(void **state)
{
    (void)state;
    worst = 0;
    const double xs[] = {1e-300, 1e-20, 0.3, 1, 7.5, 1e20, 1e300};
    for (size_t i = 0; i < sizeof xs / sizeof xs[0]; i++) {
        double x = xs[i];
        rel_track(ell_rf(x, x, x), 1 / sqrt(x), 2 * EPS, "R_F(x,x,x)");
        rel_track(ell_rc(x, x), 1 / sqrt(x), 2 * EPS, "R_C(x,x)");
        rel_track(ell_rf(0, x, x), M_PI_2 / sqrt(x), 3 * EPS, "R_F(0,x,x)");
        if (x > 1e-200 && x < 1e200) { /* x^-3/2 representable */
            rel_track(ell_rd(x, x, x), 1 / (x * sqrt(x)), 2 * EPS, "R_D(x,x,x)");
            rel_track(ell_rj(x, x, x, x), 1 / (x * sqrt(x)), 2 * EPS, "R_J(x,x,x,x)");
        }
    }
    srand(7);
    for (int i = 0; i < 2000; i++) {
        double x = pow(10, 6.0 * rand() / RAND_MAX - 3), y = pow(10, 6.0 * rand() / RAND_MAX - 3);
        double z = pow(10, 6.0 * rand() / RAND_MAX - 3), p = pow(10, 6.0 * rand() / RAND_MAX - 3);
        /* R_C's elementary forms (DLMF 19.2(iv)) */
        double rc = x < y ? acos(sqrt(x / y)) / sqrt(y - x) : acosh(sqrt(x / y)) / sqrt(x - y);
        if (fabs(x - y) > 0.1 * fmax(x, y)) rel_track(ell_rc(x, y), rc, 8 * EPS, "R_C closed form");
        /* R_D is R_J with p = z; the symmetries; homogeneity of degree -1/2, -3/2 */
        rel_track(ell_rj(x, y, z, z), ell_rd(x, y, z), 10 * EPS, "R_J(x,y,z,z) = R_D");
        rel_track(ell_rf(z, x, y), ell_rf(x, y, z), 4 * EPS, "R_F symmetric");
        rel_track(ell_rj(y, z, x, p), ell_rj(x, y, z, p), 10 * EPS, "R_J symmetric");
        rel_track(ell_rf(4 * x, 4 * y, 4 * z), ell_rf(x, y, z) / 2, 4 * EPS, "R_F homogeneous");
        rel_track(ell_rj(4 * x, 4 * y, 4 * z, 4 * p), ell_rj(x, y, z, p) / 8, 10 * EPS, "R_J homogeneous");
        /* R_F(0, y, 1) is K with 1 - m = y (DLMF 19.25(i)), which ell_Kc takes
         * from the AGM (DLMF 19.8(i)) */
        rel_track(ell_rf(0, y, 1), ell_Kc(y > 1 ? 1 / y : y) / (y > 1 ? sqrt(y) : 1), 6 * EPS,
                  "R_F(0,y,1) = K");
    }
    assert_true(isnan(ell_rf(0, 0, 1)) && isnan(ell_rj(1, 2, 3, 0)) && isnan(ell_rd(0, 0, 1)));
    print_message("Carlson's integrals against closed forms and identities: largest relative error %.3g\n",
                  worst);
}

/* ---- complete and incomplete Legendre integrals ---- */

/* Romberg quadrature of f over [a, b] to a relative 1e-15 (smooth f only). */
static double romberg(double (*f)(double, const double *), const double *prm, double a, double b)
{
    double r[24][24];
    double h = b - a;
    r[0][0] = 0.5 * h * (f(a, prm) + f(b, prm));
    for (int i = 1; i < 24; i++) {
        h *= 0.5;
        double s = 0;
        for (long k = 1; k < (1L << i); k += 2) s += f(a + k * h, prm);
        r[i][0] = 0.5 * r[i - 1][0] + h * s;
        double p4 = 1;
        for (int j = 1; j <= i; j++) {
            p4 *= 4;
            r[i][j] = r[i][j - 1] + (r[i][j - 1] - r[i - 1][j - 1]) / (p4 - 1);
        }
        if (i > 5 && fabs(r[i][i] - r[i - 1][i - 1]) <= 1e-15 * fabs(r[i][i])) return r[i][i];
    }
    return r[23][23];
}

/* the integrands of F, E and Pi: prm = {m, n} */
static double f_first(double t, const double *prm) { return 1 / sqrt(1 - prm[0] * sin(t) * sin(t)); }
static double f_second(double t, const double *prm) { return sqrt(1 - prm[0] * sin(t) * sin(t)); }
static double f_third(double t, const double *prm)
{
    double s2 = sin(t) * sin(t);
    return 1 / ((1 - prm[1] * s2) * sqrt(1 - prm[0] * s2));
}

static void complete_integrals(void **state)
{
    (void)state;
    worst = 0;
    double lemn = pow(tgamma(0.25), 2) / (4 * sqrt(M_PI)); /* A&S 18.14.7 */
    rel_track(ell_K(0.5), lemn, 2 * EPS, "K(1/2)");
    rel_track(ell_K(0.5), 1.8540746773013719184, 2 * EPS, "K(1/2) digits");
    rel_track(ell_E(0.5), 1.3506438810476755025, 2 * EPS, "E(1/2)");
    double s15 = sin(M_PI / 12);
    rel_track(ell_K(s15 * s15), pow(3, 0.25) * pow(tgamma(1.0 / 3), 3) / (pow(2, 7.0 / 3) * M_PI),
              4 * EPS, "K(sin^2 15 deg)");
    rel_track(ell_K(0), M_PI_2, 2 * EPS, "K(0)");
    rel_track(ell_E(0), M_PI_2, 2 * EPS, "E(0)");
    assert_true(isinf(ell_K(1)));
    assert_true(ell_E(1) == 1);
    /* Legendre's relation E K' + E' K - K K' = pi/2 (DLMF 19.7.1), for pairs m,
     * 1 - m both exact in doubles, from m = 2^-40 to the separatrix's 1 - 2^-40 */
    const double ms[] = {0x1p-40, 0x1p-20, 0.0625, 0.25, 0.5, 0.75, 0.9375, 1 - 0x1p-20, 1 - 0x1p-40};
    for (size_t i = 0; i < sizeof ms / sizeof ms[0]; i++) {
        double m = ms[i], k = ell_K(m), e = ell_E(m), kp = ell_K(1 - m), ep = ell_E(1 - m);
        /* its terms are larger than pi/2 where K or K' is: each has an ulp or two */
        rel_track(e * kp + ep * k - k * kp, M_PI_2, 4 * EPS * (e * kp + ep * k + k * kp) / M_PI_2,
                  "Legendre's relation");
        /* K three ways: the AGM, the Landen sequence's, Carlson's R_F (DLMF 19.25(i)) */
        ell_param p = ell_param_m(m);
        rel_track(p.K, k, 2 * EPS, "K of ell_param");
        rel_track(ell_rf(0, 1 - m, 1), k, 4 * EPS, "K = R_F(0, 1 - m, 1)");
        /* the trapezoidal rule is spectrally exact for these periodic integrands */
        if (m < 0.9) {
            double prm[2] = {m, -0.7};
            rel_track(k, romberg(f_first, prm, 0, M_PI_2), 4 * EPS, "K by quadrature");
            rel_track(e, romberg(f_second, prm, 0, M_PI_2), 4 * EPS, "E by quadrature");
            rel_track(ell_Pi(-0.7, M_PI_2, m), romberg(f_third, prm, 0, M_PI_2), 6 * EPS,
                      "Pi(-0.7|m) by quadrature");
        }
    }
    /* K near the separatrix from its complementary parameter: K ~ ln(4 / k')
     * (A&S 17.3.26), the next terms below mc ln(mc) */
    const double mcs[] = {1e-20, 1e-100, 1e-300};
    for (size_t i = 0; i < 3; i++)
        rel_track(ell_Kc(mcs[i]), log(4 / sqrt(mcs[i])), 2 * EPS, "K near m = 1");
    print_message("K, E and Legendre's relation: largest relative error %.3g\n", worst);
}

static void incomplete_integrals(void **state)
{
    (void)state;
    worst = 0;
    /* generic values from a 30-digit evaluation (mpmath 1.3) */
    rel_track(ell_F(0.7, 0.5), 0.72877030571819021448, 2 * EPS, "F(0.7|0.5)");
    rel_track(ell_F(1.5, 0.99), 3.036014097339709753, 8 * EPS, "F(1.5|0.99)");
    rel_track(ell_F(5.0, 0.3), 5.4834619894530847257, 4 * EPS, "F(5|0.3)");
    rel_track(ell_F(-2.0, 0.8), -3.1289632699212865496, 4 * EPS, "F(-2|0.8)");
    rel_track(ell_Pi(0.4, 0.7, 0.5), 0.77850678107579596377, 4 * EPS, "Pi(0.4;0.7|0.5)");
    rel_track(ell_Pi(-2.5, 1.2, 0.8), 0.84872749797191722083, 4 * EPS, "Pi(-2.5;1.2|0.8)");
    rel_track(ell_Pi(-40, 3.0, 0.6), 0.40344098400056528271, 8 * EPS, "Pi(-40;3|0.6)");
    rel_track(ell_Pi(0.9, 1.5, 0.3), 4.8459692690293232652, 8 * EPS, "Pi(0.9;1.5|0.3)");
    rel_track(ell_Pi(-0.3, -1.1, 0.999), -1.28899700334860283, 4 * EPS, "Pi(-0.3;-1.1|0.999)");
    rel_track(ell_Pi(0.5, M_PI_2, 0.5), 2.701287762095351005, 4 * EPS, "Pi(0.5|0.5)");
    rel_track(ell_Pi(-3, M_PI_2, 0.7), 0.94240923363777594648, 4 * EPS, "Pi(-3|0.7)");
    srand(11);
    for (int i = 0; i < 300; i++) {
        double phi = 3.0 * rand() / RAND_MAX - 1.5, m = 0.95 * rand() / RAND_MAX;
        double n = i % 3 == 0 ? 0.9 * rand() / RAND_MAX : -30.0 * rand() / RAND_MAX;
        double prm[2] = {m, n}, s = sin(phi), c = cos(phi);
        rel_track(ell_F(phi, m), romberg(f_first, prm, 0, phi), 8 * EPS, "F by quadrature");
        rel_track(ell_Pi(n, phi, m), romberg(f_third, prm, 0, phi), 16 * EPS, "Pi by quadrature");
        /* m = 0 and n = 0 (DLMF 19.6(ii), 19.6(iv)) */
        rel_track(ell_F(phi, 0), phi, 4 * EPS, "F(phi|0)");
        rel_track(ell_Pi(0, phi, m), ell_F(phi, m), 2 * EPS, "Pi(0;phi|m) = F");
        rel_track(ell_Pi(n, phi, 0), atan2(sqrt(1 - n) * s, c) / sqrt(1 - n), 8 * EPS, "Pi(n;phi|0)");
        /* m = 1 (DLMF 19.6(ii), 19.6(iv), c = csc^2 phi) */
        double cc = 1 / (s * s);
        /* F(phi|1) = atanh(sin phi) has condition number phi / (cos phi F) */
        rel_track(ell_F(phi, 1), atanh(s), 4 * EPS * (1 + fabs(phi / (c * atanh(s)))), "F(phi|1)");
        if (n < 0)
            rel_track(ell_Pi(n, phi, 1), copysign((ell_rc(cc, cc - 1) - n * ell_rc(cc, cc - n)) / (1 - n), phi),
                      16 * EPS, "Pi(n;phi|1)");
        /* the quasi-period: F(phi + j pi) = F(phi) + 2 j K, Pi the same with Pi(n|m) */
        rel_track(ell_F(phi + 3 * M_PI, m), ell_F(phi, m) + 6 * ell_K(m), 4 * EPS, "F quasi-period");
        rel_track(ell_Pi(n, phi - 2 * M_PI, m), ell_Pi(n, phi, m) - 4 * ell_Pi(n, M_PI_2, m), 8 * EPS,
                  "Pi quasi-period");
    }
    /* ell_Pi_sncndn changes its formula at n = -sqrt(m): both sides agree */
    ell_param p = ell_param_m(0.64);
    double sn, cn, dn, u = 1.3;
    ell_sncndn(&p, u, &sn, &cn, &dn);
    rel_ok(ell_Pi_sncndn(nextafter(-0.8, 0), 0.64, sn, cn, dn, u),
           ell_Pi_sncndn(nextafter(-0.8, -1), 0.64, sn, cn, dn, u), 4 * EPS, "Pi at n = -k");
    assert_true(isnan(ell_Pi(2, 1.2, 0.5)) && isnan(ell_Pi(1.5, 4, 0.5)) && isnan(ell_F(1, 1.5)));
    print_message("F and Pi: largest relative error %.3g\n", worst);
}

/* ---- Jacobi's functions ---- */

static void jacobi_reference_values(void **state)
{
    (void)state;
    worst = 0;
    /* 30-digit values (mpmath 1.3); u, m, sn, cn, dn */
    static const double ref[][5] = {
        {0.5, 0.3, 0.47421562271182062559, 0.88040873642646242999, 0.96567896474595120007},
        {1.7, 0.9, 0.95223054210801865053, 0.3053800823181972353, 0.42887211987841085076},
        {2.5, 0.99, 0.98881380842518432827, 0.14915512819773534806, 0.17895468628959132782},
        {10.0, 0.999999999999, 0.99999999587794275428, 0.000090797106090744831401,
         0.000090802612585343644979},
        {-3.3, 0.5, -0.39189350977647487271, -0.92001058526251533198, 0.96083803968074556904},
        {0.2, 1e-10, 0.19866933079493159223, 0.98006657784126790705, 0.99999999999802652485},
    };
    for (size_t i = 0; i < sizeof ref / sizeof ref[0]; i++) {
        ell_param p = ell_param_m(ref[i][1]);
        double sn, cn, dn;
        ell_sncndn(&p, ref[i][0], &sn, &cn, &dn);
        /* cn at u = 10 near m = 1 is sech-like: its relative error is u's times u */
        double tol = 4 * EPS * (1 + fabs(ref[i][0]));
        rel_track(sn, ref[i][2], tol, "sn");
        rel_track(cn, ref[i][3], tol, "cn");
        rel_track(dn, ref[i][4], tol, "dn");
    }
    print_message("sn, cn, dn against 30-digit values: largest relative error %.3g\n", worst);
}

/* The parameters the identities are tried at, from m = 1e-30 to 1 - 1e-300 (the
 * last three from their complementary parameter, m being 1 in doubles). */
static ell_param test_param(int i)
{
    static const double ms[] = {1e-30, 1e-9, 0.1, 0.5, 0.8, 1 - 0x1p-10, 1 - 0x1p-30};
    static const double mcs[] = {1e-20, 1e-100, 1e-300};
    return i < 7 ? ell_param_m(ms[i]) : ell_param_mc(mcs[i - 7]);
}
#define N_PARAMS 10

static void jacobi_special_values(void **state)
{
    (void)state;
    worst = 0;
    for (int i = 0; i < N_PARAMS; i++) {
        ell_param p = test_param(i);
        double kc = sqrt(p.mc), sn, cn, dn, K = p.K;
        /* u = K/2 (DLMF 22.5(i)); relative errors grow as K's argument: tol ~ K eps */
        double tol = 4 * EPS * (1 + K);
        ell_sncndn(&p, K / 2, &sn, &cn, &dn);
        rel_track(sn, 1 / sqrt(1 + kc), tol, "sn(K/2)");
        rel_track(cn, sqrt(kc / (1 + kc)), tol, "cn(K/2)");
        rel_track(dn, sqrt(kc), tol, "dn(K/2)");
        ell_sncndn(&p, K, &sn, &cn, &dn);
        rel_track(sn, 1, EPS, "sn(K)");
        assert_near(cn, 0, 2 * EPS * K * kc); /* cn'(K) = -k', K rounded */
        rel_track(dn, kc, tol, "dn(K)");
        ell_sncndn(&p, -3 * K, &sn, &cn, &dn);
        rel_track(sn, 1, EPS, "sn(-3K)");
        rel_track(dn, kc, tol, "dn(-3K)");
        /* amplitude: am(K) = pi/2, am(2K) = pi, am(-5K) = -5 pi/2 */
        /* amplitude: am(K) = pi/2, am(2K) = pi, am(-5K) = -5 pi/2; am' = dn is 1
         * at 2K, so there am carries the rounding of 2K */
        rel_track(ell_am(&p, K), M_PI_2, 4 * EPS, "am(K)");
        rel_track(ell_am(&p, 2 * K), M_PI, 4 * EPS * (1 + K), "am(2K)");
        rel_track(ell_am(&p, -5 * K), -5 * M_PI_2, 4 * EPS, "am(-5K)");
    }
    /* m = 0: sin, cos, 1; m = 1: tanh, sech, sech (DLMF 22.5(ii)) */
    ell_param p0 = ell_param_m(0), p1 = ell_param_m(1);
    for (double u = -7; u <= 7; u += 0.37) {
        double sn, cn, dn;
        ell_sncndn(&p0, u, &sn, &cn, &dn);
        assert_near(sn, sin(u), 2 * EPS);
        assert_near(cn, cos(u), 2 * EPS);
        assert_true(dn == 1);
        rel_track(ell_am(&p0, u), u, 4 * EPS, "am(u|0)");
        ell_sncndn(&p1, u, &sn, &cn, &dn);
        rel_track(sn, tanh(u), EPS, "sn(u|1)");
        rel_track(cn, 1 / cosh(u), EPS, "cn(u|1)");
        rel_track(dn, 1 / cosh(u), EPS, "dn(u|1)");
    }
    print_message("sn, cn, dn, am special values: largest relative error %.3g\n", worst);
}

static void jacobi_identities(void **state)
{
    (void)state;
    double e_unit = 0, e_add = 0, e_period = 0, e_inverse = 0;
    srand(3);
    for (int i = 0; i < N_PARAMS; i++) {
        ell_param p = test_param(i);
        double K = p.K;
        for (int j = 0; j < 300; j++) {
            double u = (4.0 * rand() / RAND_MAX - 2) * K, v = (4.0 * rand() / RAND_MAX - 2) * K;
            double su, cu, du, sv, cv, dv, sw, cw, dw;
            ell_sncndn(&p, u, &su, &cu, &du);
            ell_sncndn(&p, v, &sv, &cv, &dv);
            ell_sncndn(&p, u + v, &sw, &cw, &dw);
            /* sn^2 + cn^2 = 1, dn^2 + m sn^2 = 1 (as dn^2 = mc + m cn^2) */
            e_unit = fmax(e_unit, fabs(su * su + cu * cu - 1));
            e_unit = fmax(e_unit, fabs(du * du + p.m * su * su - 1));
            /* addition theorems (DLMF 22.8.1-3), their denominator 1 - m sn^2 u
             * sn^2 v written as cn^2 u + sn^2 u dn^2 v; the rounding of u + v
             * shows as (|u| + |v|) eps, and the formulas divide by den */
            double den = cu * cu + su * su * dv * dv, arg = (fabs(u) + fabs(v) + 1) * EPS / den;
            e_add = fmax(e_add, fabs((su * cv * dv + sv * cu * du) / den - sw) / arg);
            e_add = fmax(e_add, fabs((cu * cv - su * du * sv * dv) / den - cw) / arg);
            e_add = fmax(e_add, fabs((du * dv - p.m * su * cu * sv * cv) / den - dw) / arg);
            /* the periods: sn(u + 2K) = -sn u, cn(u + 2K) = -cn u, dn(u + 2K) = dn u */
            double sp, cp, dp;
            ell_sncndn(&p, u + 2 * K, &sp, &cp, &dp);
            double arg2 = (fabs(u) + 2 * K + 1) * EPS;
            e_period = fmax(e_period, fmax(fabs(sp + su), fabs(cp + cu)) / arg2);
            e_period = fmax(e_period, fabs(dp - du) / arg2);
            /* am and F are inverse: F(am u | m) = u, up to am's rounding times
             * F' = 1 / dn */
            if (p.m < 1 && 1 - p.m == p.mc) {
                double a = ell_am(&p, u);
                e_inverse = fmax(e_inverse, fabs(ell_F(a, p.m) - u) * du / ((fabs(u) + 1) * EPS));
            }
        }
    }
    print_message("|sn^2 + cn^2 - 1|, |dn^2 + m sn^2 - 1| <= %.3g; addition theorems within %.3g, "
                  "periods within %.3g, F(am u) = u within %.3g ulps of the arguments\n",
                  e_unit, e_add, e_period, e_inverse);
    assert_true(e_unit <= 4 * EPS);
    assert_true(e_add <= 16);
    assert_true(e_period <= 16);
    assert_true(e_inverse <= 16);
}

/* ---- the free rigid body ---- */

/* L (world) and twice the energy from the principal frame and w. */
static void momentum_energy(vec3 I, quat qp, vec3 w, vec3 *L, double *e2)
{
    vec3 wp = q_unrotate(qp, w), mp = v3(I.x * wp.x, I.y * wp.y, I.z * wp.z);
    *L = q_rotate(qp, mp);
    *e2 = v3_dot(wp, mp);
}

/* The angle of the rotation between two orientations. */
static double q_angle(quat a, quat b)
{
    quat d = q_mul(q_conj(a), b);
    return 2 * atan2(sqrt(d.x * d.x + d.y * d.y + d.z * d.z), fabs(d.w));
}

/* Euler's equations in principal axes, m' = m x Omega, qp' = qp (0, Omega) / 2,
 * Omega = m / I: one classical RK4 step. */
static void rk4_step(quat *q, vec3 *m, vec3 I, double h)
{
    quat kq[4];
    vec3 km[4];
    for (int i = 0; i < 4; i++) {
        double c = i == 0 ? 0 : i == 3 ? h : 0.5 * h;
        quat qs = *q;
        vec3 ms = *m;
        if (i > 0) {
            qs = (quat){q->w + c * kq[i - 1].w, q->x + c * kq[i - 1].x, q->y + c * kq[i - 1].y,
                        q->z + c * kq[i - 1].z};
            ms = v3_mad(*m, km[i - 1], c);
        }
        vec3 om = v3(ms.x / I.x, ms.y / I.y, ms.z / I.z);
        quat d = q_mul(qs, (quat){0, om.x, om.y, om.z});
        kq[i] = (quat){0.5 * d.w, 0.5 * d.x, 0.5 * d.y, 0.5 * d.z};
        km[i] = v3_cross(ms, om);
    }
    q->w += h / 6 * (kq[0].w + 2 * kq[1].w + 2 * kq[2].w + kq[3].w);
    q->x += h / 6 * (kq[0].x + 2 * kq[1].x + 2 * kq[2].x + kq[3].x);
    q->y += h / 6 * (kq[0].y + 2 * kq[1].y + 2 * kq[2].y + kq[3].y);
    q->z += h / 6 * (kq[0].z + 2 * kq[1].z + 2 * kq[2].z + kq[3].z);
    *q = q_normalize(*q);
    *m = v3_add(*m, v3_scale(v3_add(v3_add(km[0], v3_scale(km[1], 2)), v3_add(v3_scale(km[2], 2), km[3])),
                             h / 6));
}

/* A test body: principal moments, principal frame at 0, L in principal axes. */
typedef struct {
    const char *name;
    vec3 I;
    quat q;
    vec3 m;
} body_case;

static quat skew(void) { return q_normalize((quat){0.9, 0.2, -0.3, 0.25}); }

/* Principal moments of a solid box of sides a, b, c and mass 1. */
static vec3 box_moments(double a, double b, double c)
{
    return v3((b * b + c * c) / 12, (a * a + c * c) / 12, (a * a + b * b) / 12);
}

/* Bodies on both sides of the separatrix, near it, on it, tops and a sphere, in
 * scrambled axis orders. */
static const body_case *cases(int *n)
{
    static body_case c[] = {
        {"largest axis", {1, 2, 3}, {0, 0, 0, 0}, {0.3, 0.4, 2.0}},
        {"smallest axis", {1, 2, 3}, {0, 0, 0, 0}, {2.0, 0.4, 0.3}},
        {"largest, axes permuted", {3, 1, 2}, {0, 0, 0, 0}, {2.0, 0.3, -0.4}},
        {"smallest, axes permuted", {2, 3, 1}, {0, 0, 0, 0}, {0.3, -0.4, -2.0}},
        {"near separatrix, mc 1e-8", {1, 2, 3}, {0, 0, 0, 0}, {1e-4, 2.0, 1e-4}},
        {"near separatrix, other side", {1, 2, 3}, {0, 0, 0, 0}, {-1.2e-4, 2.0, 0.9e-4}},
        {"1e-15 off the middle axis", {1, 2, 3}, {0, 0, 0, 0}, {1e-15, 2.0, -1e-15}},
        {"on the separatrix", {1, 1.5, 3}, {1, 0, 0, 0}, {1, 1.3, 1}},
        {"nearly symmetric", {1, 1 + 1e-6, 3}, {0, 0, 0, 0}, {2, 0.001, 0.0001}},
        {"box 2 x 1 x 0.5", {0, 0, 0}, {0, 0, 0, 0}, {0.8, -0.5, 0.3}},
        {"symmetric top", {1, 1, 3}, {0, 0, 0, 0}, {0.3, 0.4, 2.0}},
        {"symmetric top, flat", {2, 1, 2}, {0, 0, 0, 0}, {0.3, -1.4, 0.5}},
        {"sphere", {2, 2, 2}, {0, 0, 0, 0}, {0.3, 0.4, 2.0}},
    };
    *n = sizeof c / sizeof c[0];
    for (int i = 0; i < *n; i++) {
        if (c[i].q.w == 0 && c[i].q.x == 0) c[i].q = skew();
        if (c[i].I.x == 0) c[i].I = box_moments(2, 1, 0.5);
    }
    return c;
}

static void spin_keeps_energy_and_momentum(void **state)
{
    (void)state;
    int n;
    const body_case *c = cases(&n);
    double worst_e = 0, worst_l = 0;
    for (int i = 0; i < n; i++) {
        vec3 L0 = q_rotate(c[i].q, c[i].m), L;
        double e0 = v3_dot(c[i].m, v3(c[i].m.x / c[i].I.x, c[i].m.y / c[i].I.y, c[i].m.z / c[i].I.z)), e;
        free_spin s;
        spin_init(&s, c[i].I, c[i].q, L0);
        const double jumps[] = {1e3, -1e4, 12345.678, 1e6, 1e9};
        for (int k = 0; k <= 200 + 5; k++) {
            double t = k <= 200 ? 0.1 * k : jumps[k - 201];
            quat q;
            vec3 w;
            spin_at(&s, t, &q, &w);
            momentum_energy(c[i].I, q, w, &L, &e);
            double de = fabs(e - e0) / e0, dl = v3_len(v3_sub(L, L0)) / v3_len(L0);
            if (!(de <= 1e-12 && dl <= 1e-12 && fabs(q_len(q) - 1) <= 1e-15))
                fail_msg("%s at t = %g: energy off by %.3g, L by %.3g, |q| - 1 = %.3g", c[i].name, t,
                         de, dl, q_len(q) - 1);
            worst_e = fmax(worst_e, de);
            worst_l = fmax(worst_l, dl);
        }
    }
    print_message("energy and L over 20 s at 0.1 s and jumps to 1e9 s: largest relative change "
                  "%.3g and %.3g\n", worst_e, worst_l);
}

static void spin_follows_eulers_equations(void **state)
{
    (void)state;
    int n;
    const body_case *c = cases(&n);
    for (int i = 0; i < n; i++) {
        free_spin s;
        spin_init(&s, c[i].I, c[i].q, q_rotate(c[i].q, c[i].m));
        quat q = c[i].q;
        vec3 m = c[i].m;
        double h = 1e-5, worst_a = 0, worst_w = 0;
        for (int k = 1; k <= 300000; k++) { /* 3 s */
            rk4_step(&q, &m, c[i].I, h);
            if (k % 20000) continue;
            quat qs;
            vec3 ws;
            spin_at(&s, k * h, &qs, &ws);
            vec3 wr = q_rotate(q, v3(m.x / c[i].I.x, m.y / c[i].I.y, m.z / c[i].I.z));
            worst_a = fmax(worst_a, q_angle(q, qs));
            worst_w = fmax(worst_w, v3_len(v3_sub(ws, wr)) / v3_len(wr));
        }
        print_message("%-28s (kind %d, 1 - m = %.3g): %.3g rad, |dw|/|w| %.3g from RK4 over 3 s\n",
                      c[i].name, s.kind, s.kind == SPIN_TUMBLE ? s.ep.mc : 1, worst_a, worst_w);
        if (c[i].I.y == 1.5) assert_true(s.separatrix); /* on it exactly: no period */
        if (!(worst_a < 1e-9 && worst_w < 1e-9))
            fail_msg("%s: %.3g rad, %.3g in w from RK4", c[i].name, worst_a, worst_w);
        /* and it moved: the principal frame turned far */
        quat q3;
        vec3 w3;
        spin_at(&s, 1.5, &q3, &w3);
        assert_true(q_angle(q3, c[i].q) > 0.3);
    }
}

/* A nearly symmetric body with L almost across its axis: the elliptic argument
 * tau = lambda t + u0 creeps (lambda = 2.6e-5 / s) while the frame turns at
 * 1 rad/s, so psi's mean turn must come from t, not from tau, whose rounding
 * divided by lambda would show (as 6e-11 rad after 50 s); RK4 at 1e-4 s keeps
 * to 2e-12 here. */
static void nearly_symmetric_long_flight(void **state)
{
    (void)state;
    vec3 I = v3(1, 1 + 1e-9, 3), m = v3(1e-5, 1, 1e-5);
    quat q = skew();
    free_spin s;
    spin_init(&s, I, q, q_rotate(q, m));
    assert_int_equal(s.kind, SPIN_TUMBLE);
    double worst_a = 0;
    for (int k = 1; k <= 500000; k++) { /* 50 s */
        rk4_step(&q, &m, I, 1e-4);
        if (k % 10000) continue;
        quat qs;
        vec3 ws;
        spin_at(&s, k * 1e-4, &qs, &ws);
        worst_a = fmax(worst_a, q_angle(q, qs));
    }
    print_message("nearly symmetric body (lambda %.3g / s) over 50 s: %.3g rad from RK4\n", s.lambda,
                  worst_a);
    assert_true(worst_a < 1e-11);
}

/* The symmetric top's closed form: the figure axis e (the unequal moment's)
 * goes round L at |L| / I_1 with a constant tilt, and the frame turns about e
 * at L_e (1/I_3 - 1/I_1). */
static void symmetric_top_closed_form(void **state)
{
    (void)state;
    vec3 I = v3(1.5, 1.5, 0.6), m = v3(0.3, -0.7, 1.1);
    quat q0 = skew();
    vec3 L = q_rotate(q0, m), Lhat = v3_norm(L);
    double l = v3_len(L), prec = l / I.x, own = m.z * (1 / I.z - 1 / I.x);
    free_spin s;
    spin_init(&s, I, q0, L);
    assert_int_equal(s.kind, SPIN_TOP);
    vec3 e0 = q_rotate(q0, v3(0, 0, 1));
    for (double t = -7; t <= 50; t += 0.77) {
        quat q;
        vec3 w;
        spin_at(&s, t, &q, &w);
        quat want = q_mul(q_mul(q_axis_angle(Lhat, prec * t), q0), q_axis_angle(v3(0, 0, 1), own * t));
        assert_true(q_angle(q, want) < 1e-13);
        vec3 e = q_rotate(q, v3(0, 0, 1));
        assert_near(v3_dot(e, Lhat), v3_dot(e0, Lhat), 1e-14);
        /* w = L / I_1 + own e */
        assert_vec_near(w, v3_mad(v3_scale(L, 1 / I.x), e, own), 1e-13);
    }
}

/* From 0 to t1 + t2 at once, or to t1, then again from there: the same. */
static void spin_composes(void **state)
{
    (void)state;
    int n;
    const body_case *c = cases(&n);
    const double t1s[] = {0.37, 2.5, -1.3, 17.1}, t2s[] = {0.5, 3.9, 2.2, -8.4};
    double worst_a = 0, worst_w = 0;
    for (int i = 0; i < n; i++) {
        vec3 L = q_rotate(c[i].q, c[i].m);
        free_spin s, s1;
        spin_init(&s, c[i].I, c[i].q, L);
        for (int k = 0; k < 4; k++) {
            quat q1, qa, qb;
            vec3 w1, wa, wb;
            spin_at(&s, t1s[k], &q1, &w1);
            spin_at(&s, t1s[k] + t2s[k], &qa, &wa);
            spin_init(&s1, c[i].I, q1, L);
            spin_at(&s1, t2s[k], &qb, &wb);
            worst_a = fmax(worst_a, q_angle(qa, qb));
            worst_w = fmax(worst_w, v3_len(v3_sub(wa, wb)) / v3_len(wa));
            if (!(q_angle(qa, qb) < 1e-12 && v3_len(v3_sub(wa, wb)) < 1e-12 * v3_len(wa)))
                fail_msg("%s: t1 %g, t2 %g: %.3g rad, %.3g in w", c[i].name, t1s[k], t2s[k],
                         q_angle(qa, qb), v3_len(v3_sub(wa, wb)));
        }
    }
    print_message("spin_at(t1 + t2) against t1 then t2: %.3g rad, %.3g in w at most\n", worst_a, worst_w);
}

static void spin_rate_bound_holds(void **state)
{
    (void)state;
    int n;
    const body_case *c = cases(&n);
    for (int i = 0; i < n; i++) {
        free_spin s;
        spin_init(&s, c[i].I, c[i].q, q_rotate(c[i].q, c[i].m));
        double bound = spin_rate_bound(&s), most = 0;
        assert_near(bound, v3_len(c[i].m) / fmin(c[i].I.x, fmin(c[i].I.y, c[i].I.z)), 1e-15 * bound);
        for (double t = -10; t <= 10; t += 0.013) {
            quat q;
            vec3 w;
            spin_at(&s, t, &q, &w);
            most = fmax(most, v3_len(w));
        }
        assert_true(most <= bound * (1 + 1e-15));
    }
}

/* A box of sides 2 x 1 x 0.5 turned about a skew axis, stepped as the simulator
 * would: every 0.1 s from where the last step left it, or at once from 0. */
static void box_about_skew_axis(void **state)
{
    (void)state;
    vec3 I = box_moments(2, 1, 0.5);
    quat q0 = q_normalize((quat){0.6, -0.3, 0.5, 0.55});
    vec3 w0 = v3(1.3, -2.1, 0.9); /* world axes, skew to every principal axis */
    vec3 wp = q_unrotate(q0, w0);
    vec3 L0 = q_rotate(q0, v3(I.x * wp.x, I.y * wp.y, I.z * wp.z)), L;
    double e0 = v3_dot(w0, L0), e, worst_e = 0, worst_l = 0;
    free_spin s, once;
    spin_init(&once, I, q0, L0);
    quat q = q0;
    vec3 w = w0;
    for (int k = 1; k <= 200; k++) {
        spin_init(&s, I, q, L0);
        spin_at(&s, 0.1, &q, &w);
        momentum_energy(I, q, w, &L, &e);
        worst_e = fmax(worst_e, fabs(e - e0) / e0);
        worst_l = fmax(worst_l, v3_len(v3_sub(L, L0)) / v3_len(L0));
        quat qo;
        vec3 wo;
        spin_at(&once, 0.1 * k, &qo, &wo);
        assert_true(q_angle(q, qo) < 1e-11);
    }
    print_message("box 2 x 1 x 0.5 about a skew axis, 200 steps of 0.1 s: energy %.3g, L %.3g\n",
                  worst_e, worst_l);
    assert_true(worst_e < 1e-9 && worst_l < 1e-9);
    assert_int_equal(once.kind, SPIN_TUMBLE);
}

/* Still, steady, on and extremely near the separatrix, wide moments: finite and
 * conserving. */
static void spin_degenerate_cases(void **state)
{
    (void)state;
    const body_case c[] = {
        {"at rest", {1, 2, 3}, {1, 0, 0, 0}, {0, 0, 0}},
        {"about the middle axis", {1, 2, 3}, {1, 0, 0, 0}, {0, 2, 0}},
        {"about the largest axis", {1, 2, 3}, {1, 0, 0, 0}, {0, 0, -2}},
        {"top about its axis", {1, 1, 3}, {1, 0, 0, 0}, {0, 0, -2}},
        {"top across its axis", {1, 1, 3}, {1, 0, 0, 0}, {1, 2, 0}},
        {"1e-160 off the middle axis", {1, 2, 3}, {1, 0, 0, 0}, {1e-160, 2, 1e-160}},
        {"1e-100 off the middle axis", {1, 2, 3}, {1, 0, 0, 0}, {1e-100, 2, 1e-100}},
        {"on the separatrix, m1 < 0", {1, 1.5, 3}, {1, 0, 0, 0}, {-1, 1.3, -1}},
        {"underflowing component", {1, 2, 3}, {1, 0, 0, 0}, {1e-170, 0.6, 0.8}},
        {"tiny L", {1, 2, 3}, {0, 0, 0, 0}, {1e-200, 2e-200, 3e-200}},
        {"moments 0.1 .. 10", {0.1, 1, 10}, {0, 0, 0, 0}, {0.1, 1, 3}},
    };
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
        quat q0 = c[i].q.w == 0 && c[i].q.x == 0 ? skew() : c[i].q;
        vec3 L0 = q_rotate(q0, c[i].m), L;
        double scale = fmax(fabs(c[i].m.x), fmax(fabs(c[i].m.y), fabs(c[i].m.z)));
        free_spin s;
        spin_init(&s, c[i].I, q0, L0);
        const double ts[] = {0, 0.1, 3.7, -20, 1e3, 1e5, 1e8};
        double e0 = -1, e;
        for (size_t k = 0; k < sizeof ts / sizeof ts[0]; k++) {
            quat q;
            vec3 w;
            spin_at(&s, ts[k], &q, &w);
            if (!(isfinite(q.w) && isfinite(q.x) && isfinite(q.y) && isfinite(q.z) && v3_finite(w)))
                fail_msg("%s at t = %g: not finite", c[i].name, ts[k]);
            assert_true(v3_len(w) <= spin_rate_bound(&s) * (1 + 1e-15));
            if (scale == 0) {
                assert_true(q_angle(q, q0) == 0 && v3_len(w) == 0);
                continue;
            }
            /* in units of the largest component, so that tiny L's squares are normal */
            momentum_energy(c[i].I, q, v3_scale(w, 1 / scale), &L, &e);
            if (e0 < 0) e0 = e;
            if (!(fabs(e - e0) <= 1e-13 * e0 && v3_len(v3_sub(v3_scale(L, scale), L0)) <= 1e-13 * v3_len(L0)))
                fail_msg("%s at t = %g: energy %.17g, want %.17g; L off by %.3g", c[i].name, ts[k], e, e0,
                         v3_len(v3_sub(v3_scale(L, scale), L0)) / v3_len(L0));
        }
    }
}

/* ns per spin_at: printed, not asserted (the sanitizer build runs it too). */
static void spin_at_speed(void **state)
{
    (void)state;
    const body_case c[] = {
        {"sphere", {2, 2, 2}, {0, 0, 0, 0}, {0.3, 0.4, 2.0}},
        {"symmetric top", {1, 1, 3}, {0, 0, 0, 0}, {0.3, 0.4, 2.0}},
        {"asymmetric", {1, 2, 3}, {0, 0, 0, 0}, {0.3, 0.4, 2.0}},
        {"asymmetric, other side", {1, 2, 3}, {0, 0, 0, 0}, {2.0, 0.4, 0.3}},
        {"near the separatrix", {1, 2, 3}, {0, 0, 0, 0}, {1e-4, 2.0, 1e-4}},
    };
    for (size_t i = 0; i < sizeof c / sizeof c[0]; i++) {
        free_spin s;
        spin_init(&s, c[i].I, skew(), q_rotate(skew(), c[i].m));
        struct timespec a, b;
        double sum = 0;
        const int calls = 200000;
        clock_gettime(CLOCK_MONOTONIC, &a);
        for (int k = 0; k < calls; k++) {
            quat q;
            vec3 w;
            spin_at(&s, 0.0137 * k, &q, &w);
            sum += q.w + w.x;
        }
        clock_gettime(CLOCK_MONOTONIC, &b);
        double ns = ((b.tv_sec - a.tv_sec) * 1e9 + (b.tv_nsec - a.tv_nsec)) / calls;
        print_message("spin_at, %s: %.0f ns a call\n", c[i].name, ns);
        assert_true(isfinite(sum));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(carlson_published_values),
        cmocka_unit_test(carlson_closed_forms),
        cmocka_unit_test(complete_integrals),
        cmocka_unit_test(incomplete_integrals),
        cmocka_unit_test(jacobi_reference_values),
        cmocka_unit_test(jacobi_special_values),
        cmocka_unit_test(jacobi_identities),
        cmocka_unit_test(spin_keeps_energy_and_momentum),
        cmocka_unit_test(spin_follows_eulers_equations),
        cmocka_unit_test(nearly_symmetric_long_flight),
        cmocka_unit_test(symmetric_top_closed_form),
        cmocka_unit_test(spin_composes),
        cmocka_unit_test(spin_rate_bound_holds),
        cmocka_unit_test(box_about_skew_axis),
        cmocka_unit_test(spin_degenerate_cases),
        cmocka_unit_test(spin_at_speed),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
