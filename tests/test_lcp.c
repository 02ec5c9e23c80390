/* test_lcp.c: the contact LCP solver (core/lcp.h) against answers known another way.
 *
 * Random positive semidefinite problems A = B B^T (B n x k, singular when k < n,
 * its rows scaled over decades for light and heavy bodies) built around a chosen
 * solution, whose w the answer must give back (w is unique); small problems
 * against every clamped set tried by brute force; contact matrices from real
 * Jacobians (a box on a floor, a tower of boxes, a ball on two others, a 3-2-1
 * pyramid of balls) whose answers are statics, and a box landing flat; the edge
 * cases; problems infeasible by less and by more than the tolerance; the same bits
 * from any workspace; and the time of a 16- and a 64-contact solve. */
#include "check.h"

#include <stdbool.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/lcp.h"

#define MAXN 64
#define G 9.8

/* ---- checking an answer ---- */

static lcp_work *work_for(int n)
{
    lcp_work *wk = malloc(lcp_work_size(n));
    assert_non_null(wk);
    return wk;
}

/* The size of w_i's terms, s_i of lcp.h. */
static double w_scale(int n, const double *A, const double *q, const double *z, int i)
{
    double qmax = 0, sum = 0;
    for (int j = 0; j < n; j++) {
        qmax = fmax(qmax, fabs(q[j]));
        sum += sqrt(A[j * n + j]) * z[j];
    }
    return qmax + sqrt(A[i * n + i]) * sum;
}

/* The size of the problem's w: max_i s_i. */
static double w_size(int n, const double *A, const double *q, const double *z)
{
    double m = 0;
    for (int i = 0; i < n; i++) m = fmax(m, w_scale(n, A, q, z, i));
    return m;
}

/* Asserts that (z, w) answers the problem as lcp.h promises: z >= 0, w = A z + q
 * summed in index order (to the bit), and complementary within LCP_TOL of each
 * w_i's scale.  Returns the worst violation of w >= 0 and of z_i w_i = 0, relative
 * to that scale. */
static double check_answer(int n, const double *A, const double *q, const double *z,
                           const double *w)
{
    double worst = 0;
    for (int i = 0; i < n; i++) {
        assert_true(z[i] >= 0);
        double v = q[i];
        for (int j = 0; j < n; j++) v += A[i * n + j] * z[j];
        assert_true(v == w[i]);
        double e = fmax(0, -w[i]), s = w_scale(n, A, q, z, i);
        if (z[i] > 0) e = fmax(e, fabs(w[i]));
        worst = fmax(worst, s > 0 ? e / s : e);
    }
    assert_true(worst <= LCP_TOL);
    return worst;
}

/* (A z)_i */
static double Az(int n, const double *A, const double *z, int i)
{
    double v = 0;
    for (int j = 0; j < n; j++) v += A[i * n + j] * z[j];
    return v;
}

/* ---- random problems ---- */

static uint64_t rng_state = 0x9e3779b97f4a7c15u;

static double uniform(void) /* [0, 1), splitmix64 */
{
    uint64_t x = (rng_state += 0x9e3779b97f4a7c15u);
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9u;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebu;
    return (double)((x ^ (x >> 31)) >> 11) * 0x1p-53;
}

static double gaussian(void)
{
    double u = uniform(), v = uniform();
    return sqrt(-2 * log(1 - u)) * cos(2 * M_PI * v);
}

/* A = B B^T for a random Gaussian n x k B: rank min(n, k), exactly symmetric;
 * B's rows scaled by 10^(spread (u - 1/2)), u uniform in [0, 1): contacts of
 * bodies whose masses span 2 spread decades. */
static void random_psd(int n, int k, double spread, double *A)
{
    static double B[MAXN * 2 * MAXN];
    for (int i = 0; i < n; i++) {
        double scale = pow(10, spread * (uniform() - 0.5));
        for (int c = 0; c < k; c++) B[i * k + c] = scale * gaussian();
    }
    for (int i = 0; i < n; i++)
        for (int j = 0; j <= i; j++) {
            double v = 0;
            for (int c = 0; c < k; c++) v += B[i * k + c] * B[j * k + c];
            A[i * n + j] = A[j * n + i] = v;
        }
}

/* q = w0 - A z0 for a random complementary z0, w0 >= 0: a third of the contacts
 * pressed (z0 > 0), a third apart (w0 > 0), a third degenerate (both 0). */
static void around_answer(int n, const double *A, double *z0, double *w0, double *q)
{
    for (int i = 0; i < n; i++) {
        double u = uniform();
        z0[i] = u < 1.0 / 3 ? 0.1 + uniform() : 0;
        w0[i] = u > 2.0 / 3 ? 0.1 + uniform() : 0;
    }
    for (int i = 0; i < n; i++) q[i] = w0[i] - Az(n, A, z0, i);
}

static double max_abs(int n, const double *v)
{
    double m = 0;
    for (int i = 0; i < n; i++) m = fmax(m, fabs(v[i]));
    return m;
}

/* Solves a random problem around a known answer and checks w against it; returns
 * the error of w relative to its scale, and adds the complementarity error to
 * *worst. */
static double solve_around(int n, int k, double spread, lcp_work *wk, double *worst)
{
    static double A[MAXN * MAXN];
    double z0[MAXN], w0[MAXN], q[MAXN], z[MAXN], w[MAXN];
    random_psd(n, k, spread, A);
    around_answer(n, A, z0, w0, q);
    assert_int_equal(lcp_solve(n, A, q, z, w, wk), 0);
    *worst = fmax(*worst, check_answer(n, A, q, z, w));
    double err = 0;
    for (int i = 0; i < n; i++) err = fmax(err, fabs(w[i] - w0[i]) / w_scale(n, A, q, z, i));
    return err;
}

static void random_problems_give_back_their_w(void **state)
{
    (void)state;
    lcp_work *wk = work_for(MAXN);
    double worst = 0, werr[2] = {0, 0};
    for (int t = 0; t < 400; t++) {
        int n = 1 + (int)(uniform() * 40);
        int k = 1 + (int)(uniform() * 2 * n);
        double e = solve_around(n, k, 0, wk, &worst);
        werr[k < n] = fmax(werr[k < n], e);
    }
    print_message("400 random problems: complementarity within %.3g, w within %.3g of the known "
                  "(full rank) and %.3g (singular), relative to w's scale\n",
                  worst, werr[0], werr[1]);
    assert_true(werr[0] < 1e-10 && werr[1] < 1e-10);
    free(wk);
}

/* Rows of A whose diagonals span 8 decades: the forces and rates of light and heavy
 * bodies' contacts are judged alike (lcp.c, "Rounding"). */
static void light_and_heavy_bodies(void **state)
{
    (void)state;
    lcp_work *wk = work_for(MAXN);
    double worst = 0, werr = 0;
    for (int t = 0; t < 300; t++) {
        int n = 1 + (int)(uniform() * 40);
        int k = 1 + (int)(uniform() * 2 * n);
        werr = fmax(werr, solve_around(n, k, 4, wk, &worst));
    }
    print_message("300 random problems, A_ii over 8 decades: complementarity within %.3g, "
                  "w within %.3g of the known\n", worst, werr);
    assert_true(werr < 1e-10);
    free(wk);
}

static void n64_random(void **state)
{
    (void)state;
    lcp_work *wk = work_for(MAXN);
    double worst = 0;
    const int ks[] = {96, 64, 40, 8};
    for (size_t i = 0; i < sizeof ks / sizeof ks[0]; i++) {
        for (int t = 0; t < 10; t++) {
            double e = solve_around(64, ks[i], 0, wk, &worst);
            assert_true(e < 1e-9);
        }
    }
    print_message("n = 64, rank 64, 40, 8: complementarity within %.3g\n", worst);
    free(wk);
}

/* ---- brute force ---- */

/* Cholesky of A_CC (C the bits of mask) in place of L; false when a pivot is below
 * 1e-9 of its diagonal (C's rows dependent or nearly). */
static bool chol_subset(int n, const double *A, const int *C, int k, double *L)
{
    for (int r = 0; r < k; r++)
        for (int c = 0; c <= r; c++) {
            double v = A[C[r] * n + C[c]];
            for (int t = 0; t < c; t++) v -= L[r * n + t] * L[c * n + t];
            if (r == c) {
                if (!(v > 1e-9 * A[C[r] * n + C[r]])) return false;
                L[r * n + r] = sqrt(v);
            } else {
                L[r * n + c] = v / L[c * n + c];
            }
        }
    return true;
}

/* Some answer's w found by trying every clamped set C with independent rows:
 * z_C = -A_CC^-1 q_C >= 0 and w >= 0 elsewhere.  False when no set gives one. */
static bool brute_force(int n, const double *A, const double *q, double *wout)
{
    double L[MAXN * MAXN], z[MAXN], w[MAXN];
    int C[MAXN];
    for (long mask = 0; mask < 1L << n; mask++) {
        int k = 0;
        for (int i = 0; i < n; i++)
            if (mask >> i & 1) C[k++] = i;
        if (!chol_subset(n, A, C, k, L)) continue;
        double y[MAXN];
        for (int r = 0; r < k; r++) {
            double v = -q[C[r]];
            for (int t = 0; t < r; t++) v -= L[r * n + t] * y[t];
            y[r] = v / L[r * n + r];
        }
        for (int r = k - 1; r >= 0; r--) {
            double v = y[r];
            for (int t = r + 1; t < k; t++) v -= L[t * n + r] * y[t];
            y[r] = v / L[r * n + r];
        }
        for (int i = 0; i < n; i++) z[i] = 0;
        for (int r = 0; r < k; r++) z[C[r]] = y[r];
        /* a nearly dependent C can give huge z and w off by more than 1e-9 */
        double qmax = max_abs(n, q), zmax = max_abs(n, z);
        bool ok = true;
        for (int i = 0; i < n && ok; i++) {
            w[i] = q[i] + Az(n, A, z, i);
            ok = z[i] >= -1e-9 * zmax && w[i] >= -1e-9 * qmax;
        }
        if (ok) {
            memcpy(wout, w, sizeof(double) * n);
            return true;
        }
    }
    return false;
}

/* One problem both ways: both find an answer with the same w, or neither does. */
static bool agrees_with_brute_force(int n, const double *A, const double *q, lcp_work *wk)
{
    double z[MAXN], w[MAXN], wb[MAXN];
    int r = lcp_solve(n, A, q, z, w, wk);
    bool found = brute_force(n, A, q, wb);
    assert_int_equal(r, found ? 0 : -1);
    if (r == 0) {
        check_answer(n, A, q, z, w);
        double s = w_size(n, A, q, z);
        for (int i = 0; i < n; i++) assert_near(w[i], wb[i], 1e-9 * s);
    }
    return r == 0;
}

static void small_problems_agree_with_brute_force(void **state)
{
    (void)state;
    lcp_work *wk = work_for(MAXN);
    static double A[MAXN * MAXN];
    double q[MAXN];
    int solved = 0, infeasible = 0;
    for (int t = 0; t < 600; t++) {
        int n = 1 + t % 10;
        int k = 1 + (int)(uniform() * (n + 3));
        random_psd(n, k, 0, A);
        for (int i = 0; i < n; i++) q[i] = gaussian();
        if (agrees_with_brute_force(n, A, q, wk))
            solved++;
        else
            infeasible++;
    }
    print_message("600 problems of n <= 10 (random q): %d solved, %d infeasible, "
                  "as by brute force\n", solved, infeasible);
    assert_true(solved > 100 && infeasible > 10);
    free(wk);
}

/* ---- contact matrices from Jacobians ---- */

typedef struct {
    vec3 x;     /* centre of mass */
    double m;   /* mass */
    vec3 inertia; /* principal moments, about the world axes */
} tbody;

typedef struct {
    int a, b; /* the bodies (-1: the static world); n points from b to a */
    vec3 p, n;
} tcontact;

/* A body's part of contact c's row of J (linear and angular), or false if not in it. */
static bool row_part(const tbody *bs, const tcontact *c, int body, vec3 *lin, vec3 *ang)
{
    double sign = c->a == body ? 1 : c->b == body ? -1 : 0;
    if (sign == 0) return false;
    *lin = v3_scale(c->n, sign);
    *ang = v3_scale(v3_cross(v3_sub(c->p, bs[body].x), c->n), sign);
    return true;
}

/* A = J M^-1 J^T for the contacts, and q the normal accelerations gravity gives. */
static void contact_problem(const tbody *bs, int nb, const tcontact *cs, int n, double *A,
                            double *q)
{
    for (int i = 0; i < n; i++) {
        q[i] = 0;
        if (cs[i].a >= 0) q[i] -= G * cs[i].n.z;
        if (cs[i].b >= 0) q[i] += G * cs[i].n.z;
        for (int j = 0; j < n; j++) {
            double v = 0;
            for (int b = 0; b < nb; b++) {
                vec3 li, ai, lj, aj;
                if (!row_part(bs, &cs[i], b, &li, &ai) || !row_part(bs, &cs[j], b, &lj, &aj))
                    continue;
                vec3 I = bs[b].inertia;
                v += v3_dot(li, lj) / bs[b].m + ai.x * aj.x / I.x + ai.y * aj.y / I.y +
                     ai.z * aj.z / I.z;
            }
            A[i * n + j] = v;
        }
    }
}

/* The net force and torque (about its centre) contact forces z put on body b. */
static void net_push(const tbody *bs, const tcontact *cs, int n, const double *z, int b,
                     vec3 *force, vec3 *torque)
{
    *force = *torque = v3(0, 0, 0);
    for (int i = 0; i < n; i++) {
        vec3 lin, ang;
        if (!row_part(bs, &cs[i], b, &lin, &ang)) continue;
        *force = v3_mad(*force, lin, z[i]);
        *torque = v3_mad(*torque, ang, z[i]);
    }
}

/* Every contact stays still (w = 0) and every body is held: the contact forces
 * balance its weight with no torque. */
static void assert_statics(const tbody *bs, int nb, const tcontact *cs, int n, const double *A,
                           const double *q, const double *z, const double *w)
{
    double s = w_size(n, A, q, z);
    for (int i = 0; i < n; i++) {
        assert_near(w[i], 0, LCP_TOL * s);
        assert_near(Az(n, A, z, i), -q[i], 1e-12 * s);
    }
    for (int b = 0; b < nb; b++) {
        vec3 f, t;
        net_push(bs, cs, n, z, b, &f, &t);
        assert_vec_near(f, v3(0, 0, G * bs[b].m), 1e-11 * s);
        assert_vec_near(t, v3(0, 0, 0), 1e-11 * s);
    }
}

/* A unit cube of mass 1 standing on a floor, its contacts at the four bottom
 * corners (moved by jitter times a fixed pattern). */
static int box_on_floor(tbody *bs, tcontact *cs, double jitter)
{
    bs[0] = (tbody){v3(0, 0, 0.5), 1, v3(1.0 / 6, 1.0 / 6, 1.0 / 6)};
    const double sx[] = {-0.5, 0.5, 0.5, -0.5}, sy[] = {-0.5, -0.5, 0.5, 0.5};
    for (int i = 0; i < 4; i++)
        cs[i] = (tcontact){0, -1, v3(sx[i] + jitter * (i % 3), sy[i] - jitter * (i % 2), 0),
                           v3(0, 0, 1)};
    return 4;
}

static void box_on_floor_is_held(void **state)
{
    (void)state;
    tbody bs[1];
    tcontact cs[4];
    double A[16], q[4], z[4], w[4];
    lcp_work *wk = work_for(4);
    int n = box_on_floor(bs, cs, 0);
    contact_problem(bs, 1, cs, n, A, q);
    assert_near(q[0], -G, 0);
    assert_int_equal(lcp_solve(n, A, q, z, w, wk), 0);
    check_answer(n, A, q, z, w);
    assert_statics(bs, 1, cs, n, A, q, z, w);
    for (int i = 0; i < n; i++) assert_near(Az(n, A, z, i), G, 1e-12 * G);
    assert_near(z[0] + z[1] + z[2] + z[3], G, 1e-12 * G);
    print_message("box on a floor: z = %.17g %.17g %.17g %.17g\n", z[0], z[1], z[2], z[3]);
    assert_false(lcp_unique(n, A, q, z, wk)); /* rank 3: the four forces are not determined */

    /* a tiny change of the corners does not change the answer but by as much */
    double z2[4], w2[4];
    box_on_floor(bs, cs, 1e-12);
    contact_problem(bs, 1, cs, n, A, q);
    assert_int_equal(lcp_solve(n, A, q, z2, w2, wk), 0);
    check_answer(n, A, q, z2, w2);
    for (int i = 0; i < n; i++) {
        assert_near(z2[i], z[i], 1e-9);
        assert_true((z2[i] > 0) == (z[i] > 0));
    }
    free(wk);
}

/* The same box falling flat at 1 m/s onto the floor, restitution 0.5: impulses
 * q = (1 + e) u; it leaves at 0.5 m/s, so w = u' + e u = 0 and the impulses sum to
 * the momentum change 1.5. */
static void box_landing_flat_bounces(void **state)
{
    (void)state;
    tbody bs[1];
    tcontact cs[4];
    double A[16], q[4], z[4], w[4];
    lcp_work *wk = work_for(4);
    int n = box_on_floor(bs, cs, 0);
    contact_problem(bs, 1, cs, n, A, q);
    double e = 0.5, u = -1;
    for (int i = 0; i < n; i++) q[i] = (1 + e) * u;
    assert_int_equal(lcp_solve(n, A, q, z, w, wk), 0);
    check_answer(n, A, q, z, w);
    for (int i = 0; i < n; i++) {
        assert_near(w[i], 0, 1e-14);
        assert_near(Az(n, A, z, i), 1.5, 1e-14);
    }
    assert_near(z[0] + z[1] + z[2] + z[3], 1.5, 1e-14);
    free(wk);
}

/* A tower of m unit boxes, each shifted a little from the one below and with its
 * own mass (0.1, 1 or 10 kg), each on four contacts at the corners of where it
 * overlaps the box below (or the floor): 4m contacts on 3m degrees of freedom
 * that they hold, a long chain of dependent rows. */
static int box_tower(tbody *bs, tcontact *cs, int m)
{
    const double shift[][2] = {{0, 0}, {0.1, 0.05}, {-0.05, 0.15}, {0.12, -0.1}};
    int n = 0;
    for (int b = 0; b < m; b++) {
        double mass = pow(10, b % 3 - 1);
        bs[b] = (tbody){v3(shift[b % 4][0], shift[b % 4][1], 0.5 + b), mass,
                        v3(mass / 6, mass / 6, mass / 6)};
        vec3 lo = v3_sub(bs[b].x, v3(0.5, 0.5, 0)), hi = v3_add(bs[b].x, v3(0.5, 0.5, 0));
        if (b > 0) {
            lo = v3_max(lo, v3_sub(bs[b - 1].x, v3(0.5, 0.5, 0)));
            hi = v3_min(hi, v3_add(bs[b - 1].x, v3(0.5, 0.5, 0)));
        }
        for (int c = 0; c < 4; c++) {
            vec3 p = v3(c == 1 || c == 2 ? hi.x : lo.x, c >= 2 ? hi.y : lo.y, b);
            cs[n++] = (tcontact){b, b - 1, p, v3(0, 0, 1)};
        }
    }
    return n;
}

static void tower_of_boxes_is_held(void **state)
{
    (void)state;
    enum { M = 10 };
    tbody bs[M];
    tcontact cs[4 * M];
    static double A[16 * M * M];
    double q[4 * M], z[4 * M], w[4 * M];
    lcp_work *wk = work_for(4 * M);
    int n = box_tower(bs, cs, M);
    contact_problem(bs, M, cs, n, A, q);
    assert_int_equal(lcp_solve(n, A, q, z, w, wk), 0);
    check_answer(n, A, q, z, w);
    assert_statics(bs, M, cs, n, A, q, z, w);
    assert_false(lcp_unique(n, A, q, z, wk));
    int pressed = 0;
    for (int i = 0; i < n; i++) pressed += z[i] > 0;
    print_message("tower of %d boxes: %d of %d contacts pressed\n", M, pressed, n);
    assert_true(pressed <= 3 * M); /* at most rank(A) */
    free(wk);
}

/* Equal balls of radius 1 and mass 1. */
static tbody ball(double x, double zc)
{
    return (tbody){v3(x, 0, zc), 1, v3(0.4, 0.4, 0.4)};
}

/* The contact where ball b (below or beside) touches ball a. */
static tcontact touch(const tbody *bs, int a, int b)
{
    vec3 n = v3_norm(v3_sub(bs[a].x, bs[b].x));
    return (tcontact){a, b, v3_add(bs[b].x, n), n};
}

/* A ball resting on two others lying on a floor between two walls: seven contacts
 * on the six degrees of freedom they act on, so A is singular; the balls stay put. */
static void ball_on_two_others_is_held(void **state)
{
    (void)state;
    const double r3 = sqrt(3.0);
    tbody bs[3] = {ball(-1, 1), ball(1, 1), ball(0, 1 + r3)};
    tcontact cs[7] = {
        {0, -1, v3(-1, 0, 0), v3(0, 0, 1)}, /* floor */
        {1, -1, v3(1, 0, 0), v3(0, 0, 1)},
        {0, -1, v3(-2, 0, 1), v3(1, 0, 0)}, /* walls */
        {1, -1, v3(2, 0, 1), v3(-1, 0, 0)},
        touch(bs, 1, 0),
        touch(bs, 2, 0),
        touch(bs, 2, 1),
    };
    double A[49], q[7], z[7], w[7];
    lcp_work *wk = work_for(7);
    contact_problem(bs, 3, cs, 7, A, q);
    assert_int_equal(lcp_solve(7, A, q, z, w, wk), 0);
    check_answer(7, A, q, z, w);
    assert_statics(bs, 3, cs, 7, A, q, z, w);
    assert_near(z[5], G / r3, 1e-12 * G); /* the top ball's weight on two slopes of 60 degrees */
    assert_near(z[6], G / r3, 1e-12 * G);
    assert_false(lcp_unique(7, A, q, z, wk)); /* the walls and the middle contact trade */

    /* the top ball alone on the two held fixed: its two forces are determined */
    tcontact two[2] = {touch(bs, 2, 0), touch(bs, 2, 1)};
    two[0].b = two[1].b = -1;
    double A2[4], q2[2];
    contact_problem(bs, 3, two, 2, A2, q2);
    assert_int_equal(lcp_solve(2, A2, q2, z, w, wk), 0);
    assert_near(z[0], G / r3, 1e-14 * G);
    assert_near(z[1], G / r3, 1e-14 * G);
    assert_true(lcp_unique(2, A2, q2, z, wk));
    free(wk);
}

/* A 3-2-1 pyramid of balls on a floor, the bottom row touching; with walls it stays
 * put (14 contacts, 12 degrees of freedom that move); without, its bottom balls
 * are pushed apart on the frictionless floor (checked by brute force). */
static int pyramid(tbody *bs, tcontact *cs, bool walls)
{
    const double h = sqrt(3.0);
    bs[0] = ball(-2, 1), bs[1] = ball(0, 1), bs[2] = ball(2, 1);
    bs[3] = ball(-1, 1 + h), bs[4] = ball(1, 1 + h);
    bs[5] = ball(0, 1 + 2 * h);
    int n = 0;
    for (int i = 0; i < 3; i++) cs[n++] = (tcontact){i, -1, v3(bs[i].x.x, 0, 0), v3(0, 0, 1)};
    cs[n++] = touch(bs, 1, 0);
    cs[n++] = touch(bs, 2, 1);
    cs[n++] = touch(bs, 3, 0);
    cs[n++] = touch(bs, 3, 1);
    cs[n++] = touch(bs, 4, 1);
    cs[n++] = touch(bs, 4, 2);
    cs[n++] = touch(bs, 4, 3);
    cs[n++] = touch(bs, 5, 3);
    cs[n++] = touch(bs, 5, 4);
    if (walls) {
        cs[n++] = (tcontact){0, -1, v3(-3, 0, 1), v3(1, 0, 0)};
        cs[n++] = (tcontact){2, -1, v3(3, 0, 1), v3(-1, 0, 0)};
    }
    return n;
}

static void pyramid_of_balls(void **state)
{
    (void)state;
    tbody bs[6];
    tcontact cs[14];
    double A[14 * 14], q[14], z[14], w[14];
    lcp_work *wk = work_for(14);
    int n = pyramid(bs, cs, true);
    contact_problem(bs, 6, cs, n, A, q);
    assert_int_equal(lcp_solve(n, A, q, z, w, wk), 0);
    check_answer(n, A, q, z, w);
    assert_statics(bs, 6, cs, n, A, q, z, w);
    assert_false(lcp_unique(n, A, q, z, wk));

    n = pyramid(bs, cs, false);
    contact_problem(bs, 6, cs, n, A, q);
    assert_true(agrees_with_brute_force(n, A, q, wk));
    assert_int_equal(lcp_solve(n, A, q, z, w, wk), 0);
    double apart = w[3] + w[4]; /* the bottom row's two contacts open */
    print_message("pyramid without walls: the bottom row's contacts open at %.6g and %.6g m/s^2\n",
                  w[3], w[4]);
    assert_true(apart > 1);
    free(wk);
}

/* ---- crowds: more contacts than a dense solve (sparse, from a guess) ---- */

/* Balls of radius 0.05 in a slot as wide as one (its sides at x = +-0.05, its
 * floor at z = 0), `layers` rows of `per` balls, each row offset half a ball from
 * the one below and resting on it (centres 0.1 apart), their masses over two
 * decades: every ball's contacts with both sides, the bottom row's with the
 * floor, each ball's with its neighbours in its row and the two above it
 * (issue 35's crowd).  Returns the contacts' count. */
static int slot_crowd(int layers, int per, tbody *bs, tcontact *cs)
{
    const double r = 0.05, rise = sqrt(3) / 2 * 2 * r;
    int n = 0;
    for (int k = 0; k < layers; k++)
        for (int j = 0; j < per; j++) {
            int b = k * per + j;
            double m = pow(10, uniform() - 0.5), I = 0.4 * m * r * r;
            bs[b] = (tbody){v3(0, j * 2 * r + (k % 2) * r, r + k * rise), m, v3(I, I, I)};
            vec3 x = bs[b].x;
            cs[n++] = (tcontact){b, -1, v3(r, x.y, x.z), v3(-1, 0, 0)};
            cs[n++] = (tcontact){b, -1, v3(-r, x.y, x.z), v3(1, 0, 0)};
            if (k == 0) cs[n++] = (tcontact){b, -1, v3(0, x.y, 0), v3(0, 0, 1)};
            if (j > 0) {
                vec3 d = v3_sub(x, bs[b - 1].x);
                cs[n++] = (tcontact){b, b - 1, v3_mad(bs[b - 1].x, d, 0.5), v3_scale(d, 1 / v3_len(d))};
            }
            if (k > 0) /* the one or two below, half a ball either way */
                for (int o = -1; o <= 0; o++) {
                    int jb = j + o + (k % 2);
                    if (jb < 0 || jb >= per) continue;
                    const tbody *u = &bs[(k - 1) * per + jb];
                    vec3 d = v3_sub(x, u->x);
                    cs[n++] = (tcontact){b, (k - 1) * per + jb, v3_mad(u->x, d, 0.5), v3_scale(d, 1 / v3_len(d))};
                }
        }
    return n;
}

/* contact_problem's A over the bodies of each pair of contacts alone (the others
 * give nothing): the crowd's hundreds. */
static void crowd_problem(const tbody *bs, const tcontact *cs, int n, double *A, double *q)
{
    for (int i = 0; i < n; i++) {
        q[i] = -G * cs[i].n.z * (cs[i].a >= 0) + G * cs[i].n.z * (cs[i].b >= 0);
        for (int j = 0; j < n; j++) {
            double v = 0;
            const int mine[2] = {cs[i].a, cs[i].b};
            for (int e = 0; e < 2; e++) {
                vec3 li, ai, lj, aj;
                if (mine[e] < 0 || !row_part(bs, &cs[i], mine[e], &li, &ai) ||
                    !row_part(bs, &cs[j], mine[e], &lj, &aj))
                    continue;
                vec3 I = bs[mine[e]].inertia;
                v += v3_dot(li, lj) / bs[mine[e]].m + ai.x * aj.x / I.x + ai.y * aj.y / I.y + ai.z * aj.z / I.z;
            }
            A[i * n + j] = v;
        }
    }
    for (int i = 0; i < n; i++) /* (exactly symmetric) */
        for (int j = 0; j < i; j++) A[i * n + j] = A[j * n + i];
}

/* A crowd of 3 rows of 26 balls and one of 4 rows of 26 in the slot (some 300 and
 * 400 contacts, far past the dense solve's 64; rank deficient, for the sides
 * push each ball both ways along x): answered under gravity, and with q around
 * known answers w comes back (w is unique), from no guess, from the last
 * answer for a q moved a little (the crowd's next Newton step), from a guess of
 * every contact and from a random one: each answer held to lcp.h's promise
 * (check_answer: z >= 0, w = A z + q to the bit, complementary). */
static void crowds_are_solved_sparse_and_warm(void **state)
{
    (void)state;
    for (int layers = 3; layers <= 4; layers++) {
        int per = 26, nb = layers * per;
        tbody *bs = malloc(sizeof *bs * (size_t)nb);
        tcontact *cs = malloc(sizeof *cs * (size_t)nb * 6);
        assert_non_null(bs);
        assert_non_null(cs);
        int n = slot_crowd(layers, per, bs, cs);
        size_t m = (size_t)n;
        double *A = malloc(sizeof *A * m * m), *v = malloc(sizeof *v * m * 6);
        lcp_work *wk = work_for(n);
        assert_non_null(A);
        assert_non_null(v);
        double *q = v, *z = v + m, *w = v + 2 * m, *z0 = v + 3 * m, *w0 = v + 4 * m, *zl = v + 5 * m;
        crowd_problem(bs, cs, n, A, q);
        assert_int_equal(lcp_solve(n, A, q, z, w, wk), 0);
        check_answer(n, A, q, z, w);
        double worst = 0, werr = 0;
        for (int t = 0; t < 4; t++) {
            around_answer(n, A, z0, w0, q);
            for (int g = 0; g < 4; g++) {
                if (g == 1) {
                    /* the answer moved by 1e-3 of itself, and q with it (a q
                     * moved at random may ask the sides for the impossible) */
                    for (int i = 0; i < n; i++) {
                        z0[i] *= 1 + 1e-3 * gaussian();
                        w0[i] *= 1 + 1e-3 * gaussian();
                    }
                    for (int i = 0; i < n; i++) q[i] = w0[i] - Az(n, A, z0, i);
                }
                /* the guess: none; the last answer; every contact; a random half */
                for (int i = 0; i < n; i++)
                    z[i] = g == 1 ? zl[i] : g == 2 ? 1 : g == 3 ? (uniform() < 0.5) * uniform() : 0;
                int r = g == 0 ? lcp_solve(n, A, q, z, w, wk) : lcp_solve_warm(n, A, q, z, w, wk);
                assert_int_equal(r, 0);
                worst = fmax(worst, check_answer(n, A, q, z, w));
                if (g == 0) memcpy(zl, z, sizeof *z * m);
                for (int i = 0; i < n; i++) werr = fmax(werr, fabs(w[i] - w0[i]) / w_scale(n, A, q, z, i));
            }
        }
        print_message("slot of %d rows of %d balls, %d contacts: complementarity within %.3g, w within "
                      "%.3g of the known\n", layers, per, n, worst, werr);
        assert_true(n > 250 && werr < 1e-10);
        free(wk);
        free(A);
        free(v);
        free(bs);
        free(cs);
    }
}

/* ---- edge cases ---- */

static void apart_contacts_need_no_force(void **state)
{
    (void)state;
    lcp_work *wk = work_for(MAXN);
    static double A[MAXN * MAXN];
    double q[MAXN], z[MAXN], w[MAXN];
    for (int n = 1; n <= 20; n++) {
        random_psd(n, 1 + n / 2, 0, A);
        for (int i = 0; i < n; i++) q[i] = i % 3 == 0 ? 0 : uniform();
        assert_int_equal(lcp_solve(n, A, q, z, w, wk), 0);
        for (int i = 0; i < n; i++) {
            assert_true(z[i] == 0);
            assert_true(w[i] == q[i]);
        }
    }
    /* the zero matrix, q >= 0 */
    double Z[9] = {0}, q3[3] = {1, 0, 2};
    assert_int_equal(lcp_solve(3, Z, q3, z, w, wk), 0);
    for (int i = 0; i < 3; i++) assert_true(z[i] == 0 && w[i] == q3[i]);
    /* n = 0 */
    assert_int_equal(lcp_solve(0, Z, q3, z, w, wk), 0);
    free(wk);
}

static void one_contact(void **state)
{
    (void)state;
    lcp_work *wk = work_for(1);
    double z, w;
    double two = 2, zero = 0, q;
    q = -4;
    assert_int_equal(lcp_solve(1, &two, &q, &z, &w, wk), 0);
    assert_true(z == 2 && w == 0);
    assert_true(lcp_unique(1, &two, &q, &z, wk));
    q = 3;
    assert_int_equal(lcp_solve(1, &two, &q, &z, &w, wk), 0);
    assert_true(z == 0 && w == 3);
    q = 0;
    assert_int_equal(lcp_solve(1, &zero, &q, &z, &w, wk), 0);
    assert_true(z == 0 && w == 0);
    assert_false(lcp_unique(1, &zero, &q, &z, wk)); /* any z gives w = 0 */
    q = -1;
    assert_int_equal(lcp_solve(1, &zero, &q, &z, &w, wk), -1);
    assert_true(z == 0 && w == -1);
    free(wk);
}

/* A contact given twice (and thrice): the same row; the force splits any way. */
static void duplicated_contacts(void **state)
{
    (void)state;
    lcp_work *wk = work_for(3);
    double A[9], q[3] = {-3, -3, -3}, z[3], w[3];
    for (int i = 0; i < 9; i++) A[i] = 1.5;
    assert_int_equal(lcp_solve(3, A, q, z, w, wk), 0);
    check_answer(3, A, q, z, w);
    for (int i = 0; i < 3; i++) assert_near(w[i], 0, 1e-15);
    assert_near(z[0] + z[1] + z[2], 2, 1e-15);
    assert_false(lcp_unique(3, A, q, z, wk));
    free(wk);
}

static void infeasible_problems_fail_cleanly(void **state)
{
    (void)state;
    lcp_work *wk = work_for(4);
    double z[4], w[4];
    /* contact 1 touches nothing that moves: its row is zero, and q_1 < 0 */
    double A[9] = {2, 0, 1, 0, 0, 0, 1, 0, 2}, q[3] = {-1, -0.5, -1};
    assert_int_equal(lcp_solve(3, A, q, z, w, wk), -1);
    for (int i = 0; i < 3; i++) assert_true(z[i] == 0 && w[i] == q[i]);
    /* the same with q_1 = 0 is fine */
    q[1] = 0;
    assert_int_equal(lcp_solve(3, A, q, z, w, wk), 0);
    check_answer(3, A, q, z, w);
    /* two contacts pushing a body in opposite directions, both asked to close */
    double B[4] = {1, -1, -1, 1}, qb[2] = {-1, -1};
    assert_int_equal(lcp_solve(2, B, qb, z, w, wk), -1);
    /* not finite, or not PSD on the diagonal */
    double C[4] = {1, 0, 0, NAN}, qc[2] = {-1, -1}, D[4] = {-1, 0, 0, 1};
    assert_int_equal(lcp_solve(2, C, qc, z, w, wk), -1);
    assert_int_equal(lcp_solve(2, D, qc, z, w, wk), -1);
    qc[1] = INFINITY;
    assert_int_equal(lcp_solve(2, B, qc, z, w, wk), -1);
    free(wk);
}

/* Two contacts whose rows of A are opposite multiples (a = (1, -0.1), A = a a^T:
 * pressing one opens the other) can both close only if 0.1 q_0 + q_1 >= 0.  Asked
 * for 1.5e-13 less, within the tolerance, the answer is one within it (the second
 * contact's drive ends with w_1 taken for 0 and its force handed over); asked for
 * 1e-9 less, there is none. */
static void nearly_infeasible_problems(void **state)
{
    (void)state;
    lcp_work *wk = work_for(2);
    double A[4] = {1, -0.1, -0.1, 0.01}, z[2], w[2];
    double q[2] = {1, -0.1 * (1 + 1.5e-12)};
    assert_int_equal(lcp_solve(2, A, q, z, w, wk), 0);
    check_answer(2, A, q, z, w);
    assert_near(0.1 * z[1] - z[0], 1, 1e-11); /* w_1 = q_1 - 0.1 (z_0 - 0.1 z_1) = 0 */
    q[1] = -0.1 * (1 + 1e-9);
    assert_int_equal(lcp_solve(2, A, q, z, w, wk), -1);
    free(wk);
}

/* Same input, same bits, whatever the workspace held before. */
static void same_bits_from_any_workspace(void **state)
{
    (void)state;
    int n = 40;
    size_t size = lcp_work_size(n);
    lcp_work *wk1 = work_for(n), *wk2 = work_for(n);
    static double A[MAXN * MAXN];
    double z0[MAXN], w0[MAXN], q[MAXN], z1[MAXN], w1[MAXN], z2[MAXN], w2[MAXN];
    memset(wk1, 0, size);
    memset(wk2, 0xff, size);
    random_psd(n, 25, 0, A);
    around_answer(n, A, z0, w0, q);
    assert_int_equal(lcp_solve(n, A, q, z1, w1, wk1), 0);
    assert_int_equal(lcp_solve(n, A, q, z2, w2, wk2), 0);
    assert_memory_equal(z1, z2, sizeof(double) * n);
    assert_memory_equal(w1, w2, sizeof(double) * n);
    free(wk1);
    free(wk2);
}

static void full_rank_forces_are_unique(void **state)
{
    (void)state;
    lcp_work *wk = work_for(MAXN);
    static double A[MAXN * MAXN];
    double z0[MAXN], w0[MAXN], q[MAXN], z[MAXN], w[MAXN];
    random_psd(20, 30, 0, A);
    around_answer(20, A, z0, w0, q);
    assert_int_equal(lcp_solve(20, A, q, z, w, wk), 0);
    assert_true(lcp_unique(20, A, q, z, wk));
    for (int i = 0; i < 20; i++) assert_near(z[i], z0[i], 1e-9);
    free(wk);
}

/* ---- the least-norm answer ---- */

/* The least-norm x of the consistent system M x = b (M m x k, row-major), found
 * another way than lcp.c's: an orthonormal basis Q of M's row space by modified
 * Gram-Schmidt, then x = Q c with c from the normal equations of (M Q) c = b.
 * False when M x = b has no solution (residual above tol). */
static bool min_norm_solve(int m, int k, const double *M, const double *b, double tol, double *x)
{
    double Q[MAXN * MAXN], MQ[MAXN * MAXN], N[MAXN * MAXN], c[MAXN];
    int nq = 0;
    for (int i = 0; i < m; i++) {
        double t[MAXN], len = 0;
        for (int j = 0; j < k; j++) len += M[i * k + j] * M[i * k + j];
        for (int j = 0; j < k; j++) t[j] = M[i * k + j];
        for (int pass = 0; pass < 2; pass++)
            for (int a = 0; a < nq; a++) {
                double d = 0;
                for (int j = 0; j < k; j++) d += t[j] * Q[a * k + j];
                for (int j = 0; j < k; j++) t[j] -= d * Q[a * k + j];
            }
        double res = 0;
        for (int j = 0; j < k; j++) res += t[j] * t[j];
        if (!(res > 1e-16 * len) || len == 0) continue;
        for (int j = 0; j < k; j++) Q[nq * k + j] = t[j] / sqrt(res);
        nq++;
    }
    for (int i = 0; i < m; i++)
        for (int a = 0; a < nq; a++) {
            double v = 0;
            for (int j = 0; j < k; j++) v += M[i * k + j] * Q[a * k + j];
            MQ[i * nq + a] = v;
        }
    for (int a = 0; a < nq; a++) {
        c[a] = 0;
        for (int i = 0; i < m; i++) c[a] += MQ[i * nq + a] * b[i];
        for (int e = 0; e < nq; e++) {
            double v = 0;
            for (int i = 0; i < m; i++) v += MQ[i * nq + a] * MQ[i * nq + e];
            N[a * nq + e] = v;
        }
    }
    /* Gaussian elimination with partial pivoting on N c = M Q^T b */
    for (int col = 0; col < nq; col++) {
        int piv = col;
        for (int r = col + 1; r < nq; r++)
            if (fabs(N[r * nq + col]) > fabs(N[piv * nq + col])) piv = r;
        for (int e = 0; e < nq; e++) {
            double t = N[col * nq + e];
            N[col * nq + e] = N[piv * nq + e];
            N[piv * nq + e] = t;
        }
        double t = c[col];
        c[col] = c[piv];
        c[piv] = t;
        for (int r = col + 1; r < nq; r++) {
            double f = N[r * nq + col] / N[col * nq + col];
            for (int e = col; e < nq; e++) N[r * nq + e] -= f * N[col * nq + e];
            c[r] -= f * c[col];
        }
    }
    for (int r = nq - 1; r >= 0; r--) {
        for (int e = r + 1; e < nq; e++) c[r] -= N[r * nq + e] * c[e];
        c[r] /= N[r * nq + r];
    }
    for (int j = 0; j < k; j++) {
        x[j] = 0;
        for (int a = 0; a < nq; a++) x[j] += Q[a * k + j] * c[a];
    }
    for (int i = 0; i < m; i++) {
        double v = -b[i];
        for (int j = 0; j < k; j++) v += M[i * k + j] * x[j];
        if (fabs(v) > tol) return false;
    }
    return true;
}

/* The least-norm answer by brute force, given an answer z (w its w): over the
 * contacts S with w_i = 0, every support F within S whose least-norm x with
 * A_SF x = A_SS z_S is >= 0 is an answer; the shortest of them is the least-norm
 * answer (the optimum's own support gives it).  Its norm, and it in best. */
static double least_norm_by_brute_force(int n, const double *A, const double *z, const double *w,
                                        double tol, double *best)
{
    int S[MAXN], s = 0;
    for (int i = 0; i < n; i++) {
        best[i] = 0;
        if (fabs(w[i]) <= tol) S[s++] = i;
    }
    double b[MAXN], M[MAXN * MAXN], x[MAXN], bn = HUGE_VAL;
    for (int a = 0; a < s; a++) b[a] = Az(n, A, z, S[a]);
    for (long mask = 0; mask < 1L << s; mask++) {
        int F[MAXN], k = 0;
        for (int a = 0; a < s; a++)
            if (mask >> a & 1) F[k++] = S[a];
        for (int a = 0; a < s; a++)
            for (int j = 0; j < k; j++) M[a * k + j] = A[S[a] * n + F[j]];
        if (!min_norm_solve(s, k, M, b, tol, x)) continue;
        double norm = 0;
        bool ok = true;
        for (int j = 0; j < k; j++) {
            ok = ok && x[j] >= -tol;
            norm += x[j] * x[j];
        }
        if (!ok || !(norm < bn)) continue;
        bn = norm;
        for (int i = 0; i < n; i++) best[i] = 0;
        for (int j = 0; j < k; j++) best[F[j]] = fmax(x[j], 0);
    }
    return sqrt(bn);
}

/* Singular problems with many contacts pressed: the least-norm answer keeps w,
 * and is the one brute force finds over every support. */
static void least_norm_answers_agree_with_brute_force(void **state)
{
    (void)state;
    lcp_work *wk = work_for(MAXN);
    static double A[MAXN * MAXN];
    double z0[MAXN], w0[MAXN], q[MAXN], z[MAXN], w[MAXN], zl[MAXN], best[MAXN];
    double worst = 0;
    int moved = 0;
    for (int t = 0; t < 300; t++) {
        int n = 2 + t % 9, k = 1 + (int)(uniform() * (n - 1)); /* rank < n */
        random_psd(n, k, t % 2 ? 2 : 0, A);
        for (int i = 0; i < n; i++) {
            z0[i] = uniform() < 0.75 ? 0.1 + uniform() : 0;
            w0[i] = z0[i] > 0 ? 0 : uniform() < 0.5 ? 0.1 + uniform() : 0;
        }
        for (int i = 0; i < n; i++) q[i] = w0[i] - Az(n, A, z0, i);
        assert_int_equal(lcp_solve(n, A, q, z, w, wk), 0);
        memcpy(zl, z, sizeof(double) * n);
        lcp_least_norm(n, A, q, zl, wk);
        double s = w_size(n, A, q, z), zmax = max_abs(n, z);
        for (int i = 0; i < n; i++) {
            assert_true(zl[i] >= 0);
            assert_near(Az(n, A, zl, i) + q[i], w[i], 1e-11 * s); /* the same w */
        }
        double nz = 0, nl = 0;
        for (int i = 0; i < n; i++) {
            nz += z[i] * z[i];
            nl += zl[i] * zl[i];
        }
        assert_true(sqrt(nl) <= sqrt(nz) * (1 + 1e-12));
        double bn = least_norm_by_brute_force(n, A, z, w, 1e-10 * s, best);
        assert_true(bn < HUGE_VAL);
        assert_near(sqrt(nl), bn, 1e-9 * zmax);
        for (int i = 0; i < n; i++) worst = fmax(worst, fabs(zl[i] - best[i]) / zmax);
        moved += sqrt(nl) < sqrt(nz) * (1 - 1e-9);
    }
    print_message("300 singular problems: the least-norm answer within %.3g of brute force's "
                  "(relative to max z); %d shorter than the pivoting's\n", worst, moved);
    assert_true(worst < 1e-8);
    assert_true(moved > 100);
    free(wk);
}

/* The least-norm answer does not depend on the contacts' order: every problem
 * reversed and rotated gives the same forces, contact for contact. */
static void least_norm_answers_ignore_the_order(void **state)
{
    (void)state;
    lcp_work *wk = work_for(MAXN);
    static double A[MAXN * MAXN], P[MAXN * MAXN];
    double z0[MAXN], w0[MAXN], q[MAXN], z[MAXN], w[MAXN], qp[MAXN], zp[MAXN], wp[MAXN];
    double worst = 0;
    for (int t = 0; t < 200; t++) {
        int n = 2 + t % 30, k = 1 + (int)(uniform() * (n - 1)), shift = t % n;
        random_psd(n, k, 0, A);
        for (int i = 0; i < n; i++) {
            z0[i] = uniform() < 0.6 ? 0.1 + uniform() : 0;
            w0[i] = z0[i] > 0 ? 0 : 0.1 + uniform();
        }
        for (int i = 0; i < n; i++) q[i] = w0[i] - Az(n, A, z0, i);
        /* contact i becomes contact perm(i) = (n - 1 - i + shift) mod n */
        for (int i = 0; i < n; i++) {
            int pi = (n - 1 - i + shift) % n;
            qp[pi] = q[i];
            for (int j = 0; j < n; j++) P[pi * n + (n - 1 - j + shift) % n] = A[i * n + j];
        }
        assert_int_equal(lcp_solve(n, A, q, z, w, wk), 0);
        lcp_least_norm(n, A, q, z, wk);
        assert_int_equal(lcp_solve(n, P, qp, zp, wp, wk), 0);
        lcp_least_norm(n, P, qp, zp, wk);
        double zmax = max_abs(n, z);
        for (int i = 0; i < n; i++) worst = fmax(worst, fabs(zp[(n - 1 - i + shift) % n] - z[i]) / zmax);
    }
    print_message("200 singular problems in two orders: forces within %.3g (relative to max z)\n",
                  worst);
    assert_true(worst < 1e-9);
    free(wk);
}

/* Solves the n-contact problem A, q and makes z its least-norm answer. */
static void solve_least(int n, const double *A, const double *q, double *z, lcp_work *wk)
{
    double w[MAXN];
    assert_int_equal(lcp_solve(n, A, q, z, w, wk), 0);
    lcp_least_norm(n, A, q, z, wk);
}

/* A box on a floor, and the box landing flat: the four corners share the force
 * equally in the least-norm answer; a box off centre on its corners shares it as
 * the lever rule and least norm say. */
static void least_norm_shares_a_face_evenly(void **state)
{
    (void)state;
    tbody bs[1];
    tcontact cs[4];
    double A[16], q[4], z[4];
    lcp_work *wk = work_for(4);
    int n = box_on_floor(bs, cs, 0);
    contact_problem(bs, 1, cs, n, A, q);
    solve_least(n, A, q, z, wk);
    for (int i = 0; i < n; i++) assert_near(z[i], G / 4, 1e-14 * G);
    for (int i = 0; i < n; i++) q[i] = 1.5 * -1;
    solve_least(n, A, q, z, wk);
    for (int i = 0; i < n; i++) assert_near(z[i], 1.5 / 4, 1e-14);
    /* the centre of mass at (0.25, 0.1) over the unit square's corners: the
     * forces f_i = G (1/4 + x_i cx + y_i cy) (x_i, y_i = +-1/2, the corner), the
     * least-norm ones that balance the weight and its moments; all positive */
    bs[0].x = v3(0.25, 0.1, 0.5);
    contact_problem(bs, 1, cs, n, A, q);
    solve_least(n, A, q, z, wk);
    const double sx[] = {-0.5, 0.5, 0.5, -0.5}, sy[] = {-0.5, -0.5, 0.5, 0.5};
    for (int i = 0; i < n; i++) assert_near(z[i], G * (0.25 + sx[i] * 0.25 + sy[i] * 0.1), 1e-13 * G);
    free(wk);
}

/* ---- time ---- */

static double seconds(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return t.tv_sec + 1e-9 * t.tv_nsec;
}

static void time_of_a_solve(int n, int k, int reps)
{
    static double A[MAXN * MAXN];
    double z0[MAXN], w0[MAXN], q[MAXN], z[MAXN], w[MAXN];
    lcp_work *wk = work_for(n);
    random_psd(n, k, 0, A);
    around_answer(n, A, z0, w0, q);
    double t0 = seconds();
    for (int r = 0; r < reps; r++) assert_int_equal(lcp_solve(n, A, q, z, w, wk), 0);
    double t = (seconds() - t0) / reps;
    print_message("n = %d, rank %d: %.1f us a solve\n", n, k < n ? k : n, 1e6 * t);
    free(wk);
}

static void timing(void **state)
{
    (void)state;
    time_of_a_solve(16, 24, 2000);
    time_of_a_solve(16, 10, 2000);
    time_of_a_solve(64, 96, 200);
    time_of_a_solve(64, 40, 200);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(random_problems_give_back_their_w),
        cmocka_unit_test(light_and_heavy_bodies),
        cmocka_unit_test(n64_random),
        cmocka_unit_test(small_problems_agree_with_brute_force),
        cmocka_unit_test(box_on_floor_is_held),
        cmocka_unit_test(box_landing_flat_bounces),
        cmocka_unit_test(tower_of_boxes_is_held),
        cmocka_unit_test(ball_on_two_others_is_held),
        cmocka_unit_test(pyramid_of_balls),
        cmocka_unit_test(apart_contacts_need_no_force),
        cmocka_unit_test(one_contact),
        cmocka_unit_test(duplicated_contacts),
        cmocka_unit_test(infeasible_problems_fail_cleanly),
        cmocka_unit_test(nearly_infeasible_problems),
        cmocka_unit_test(same_bits_from_any_workspace),
        cmocka_unit_test(full_rank_forces_are_unique),
        cmocka_unit_test(least_norm_answers_agree_with_brute_force),
        cmocka_unit_test(least_norm_answers_ignore_the_order),
        cmocka_unit_test(least_norm_shares_a_face_evenly),
        cmocka_unit_test(crowds_are_solved_sparse_and_warm),
        cmocka_unit_test(timing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
