/* lcp.c: Dantzig's principal pivoting for the contact LCP, as Baraff gives it
 * (Baraff, "Fast contact force computation for nonpenetrating rigid bodies",
 * SIGGRAPH 1994, section 4; Cottle and Dantzig, "Complementary pivot theory of
 * mathematical programming", 1968; den Hertog, Roos and Terlaky, "The linear
 * complementarity problem, sufficient matrices, and the criss-cross method", 1993).
 *
 * The method.  Contacts are taken one at a time, in index order.  The clamped set C
 * has w_i = 0, the free set NC has z_i = 0, and contacts not yet taken may be
 * anything.  A contact d taken with w_d >= 0 joins NC; else it is driven: z_d grows
 * while the forces on C change so that w_C stays 0 (A_CC dz_C = -A_Cd), until w_d
 * reaches 0 (d joins C), a clamped force reaches 0 (it joins NC) or a free w
 * reaches 0 (it joins C): the ratio test.  The drive goes on from the new sets
 * until d is clamped (or freed, below).  The invariants (z_C >= 0, w_NC >= 0, both complementary)
 * hold throughout, so when every contact is taken the answer is found.
 *
 * Why it is safe on singular A.  A_CC stays positive definite: a free contact j
 * joins C only when its w falls, dw_j < 0, and its Schur complement
 * s_j = A_jj - A_jC A_CC^-1 A_Cj is then positive, for s_j = 0 would make
 * u = (-A_CC^-1 A_Cj, 1) a null vector of A (A is PSD), and then
 * dw_j = u.A dz = u_C.dw_C = 0.  d joins C only when w_d rises, at the rate s_d,
 * so only when s_d > 0; and dropping a contact keeps a principal submatrix of a
 * positive definite one.  So every solve is a Cholesky solve, updated as C grows
 * and shrinks.  When s_d = 0 (d's row depends on C's: the fourth corner of a box
 * on a floor) A dz = 0: no w moves, only clamped forces shift, and either one
 * reaches 0 and is dropped, which makes s_d grow, or none does: then dz >= 0,
 * A dz = 0 and q.dz = w_d < 0, which no z can satisfy (dz.(A z + q) would be < 0),
 * so the problem has no solution.
 *
 * Why it ends.  With s_d > 0 a step of positive length raises z_d to where its
 * sets' step ends, so no sets repeat across such steps; steps of length 0 (a force
 * or a w already 0: degenerate contacts) pivot a contact at a time on the drive's
 * direction alone, a principal pivoting on a PSD problem, which the least-index
 * rule keeps from cycling (den Hertog, Roos and Terlaky): ties in the ratio test
 * go to the lowest index, which also makes the answer the same whatever rounding
 * did below the tolerances.  Still, more than 100 + 20 n pivots is a failure.
 *
 * Rounding.  A Schur complement at most PIVOT_TOL of its diagonal is a dependent
 * row.  Forces and rates are compared as if A were scaled to a unit diagonal
 * (z_j sqrt(A_jj)), so that the contacts of light and heavy bodies are judged
 * alike; a rate at most RATE_TOL of the direction's size is rounding.  Two
 * tolerances of w: the pivots take w_j for 0 within LCP_TOL of the size of its own
 * terms (tol_row), so that what they set to 0 is 0 to rounding; the answer
 * allows LCP_TOL of the largest |q| as well (tol_w), so that a contact asked for
 * -1e-15 while others are asked for 10 is not driven, and a drive that cannot
 * raise w_d but has it within that tolerance ends there (w_d taken for 0) instead
 * of failing.  The increments of a drive are thrown away when it ends: z_C is
 * solved afresh from q_C and w computed from it; at the end z_C is solved with two
 * steps of refinement, clamped forces a rounding below 0 become 0, and a free w
 * below the tolerance, or a clamped force far below 0, sends its contact back to
 * be taken again (about one random problem in a thousand).
 */
#include "lcp.h"

#include <assert.h>
#include <math.h>

/* A Schur complement of contact j at most this times A_jj: j's row depends on C's. */
#define PIVOT_TOL 1e-11
/* A rate at most this times the direction's size (both scaled) is rounding. */
#define RATE_TOL 1e-11

enum { UNSEEN, IN_C, IN_NC };

/* The solver's view of the caller's workspace and of the problem. */
typedef struct {
    int n, k;            /* contacts; contacts in C */
    const double *A, *q;
    double *z, *w;
    long pivots;
    /* in the workspace: */
    double *L;           /* Cholesky factor of A_CC (row-major, row stride n), by position in C */
    double *dz, *y, *yj, *tmp; /* by position: direction, L^-1 A_Cd, L^-1 A_Cj, scratch */
    double *dw;          /* by index: rate of w_j */
    double *root;        /* by index: sqrt(A_jj), the scale of contact j (below) */
    double qmax;         /* max |q_i| */
    int *set;            /* by index: UNSEEN, IN_C or IN_NC */
    int *at;             /* by position: the contact */
    int *pos;            /* by index: position in C, or -1 */
    int *skip;           /* by index: a free w whose fall is rounding, this pivot */
} lcp_state;

size_t lcp_work_size(int n)
{
    assert(n >= 0);
    size_t m = (size_t)n;
    return sizeof(double) * (m * m + 6 * m) + sizeof(int) * 4 * m;
}

static void state_init(lcp_state *s, int n, const double *A, const double *q, double *z,
                       double *w, lcp_work *work)
{
    size_t m = (size_t)n;
    double *d = (double *)(void *)work;
    int *i = (int *)(void *)(d + m * m + 6 * m);
    *s = (lcp_state){.n = n, .A = A, .q = q, .z = z, .w = w};
    s->L = d;
    s->dz = d + m * m;
    s->y = s->dz + m;
    s->yj = s->y + m;
    s->tmp = s->yj + m;
    s->dw = s->tmp + m;
    s->root = s->dw + m;
    s->set = i;
    s->at = i + m;
    s->pos = i + 2 * m;
    s->skip = i + 3 * m;
    for (int j = 0; j < n; j++) {
        s->set[j] = UNSEEN;
        s->pos[j] = -1;
        s->skip[j] = 0;
    }
}

static double dot(const double *a, const double *b, int k)
{
    double v = 0;
    for (int i = 0; i < k; i++) v += a[i] * b[i];
    return v;
}

/* w_i = q_i + A_i z, summed in index order: the answer's w. */
static double w_of(const double *Ai, double qi, const double *z, int n)
{
    double v = qi;
    for (int j = 0; j < n; j++) v += Ai[j] * z[j];
    return v;
}

/* The sum over the positions p of row[at[p]] x[p]: a row of A times a vector
 * over C. */
static double dot_at(const lcp_state *s, const double *row, const double *x)
{
    double v = 0;
    for (int p = 0; p < s->k; p++) v += row[s->at[p]] * x[p];
    return v;
}

/* y = L^-1 b over the k positions (y may be b). */
static void solve_lower(const lcp_state *s, const double *b, double *y)
{
    for (int r = 0; r < s->k; r++) {
        const double *Lr = s->L + (size_t)r * s->n;
        y[r] = (b[r] - dot(Lr, y, r)) / Lr[r];
    }
}

/* x = L^-T y over the k positions (x may be y). */
static void solve_upper(const lcp_state *s, const double *y, double *x)
{
    for (int r = s->k - 1; r >= 0; r--) {
        double v = y[r];
        for (int c = r + 1; c < s->k; c++) v -= s->L[(size_t)c * s->n + r] * x[c];
        x[r] = v / s->L[(size_t)r * s->n + r];
    }
}

/* y = L^-1 A_Cj, and returns contact j's Schur complement A_jj - y.y: the part of
 * its row of A independent of the clamped contacts' rows (>= 0, A being PSD). */
static double schur(const lcp_state *s, int j, double *y)
{
    const double *Aj = s->A + (size_t)j * s->n;
    for (int p = 0; p < s->k; p++) y[p] = Aj[s->at[p]];
    solve_lower(s, y, y);
    return Aj[j] - dot(y, y, s->k);
}

/* Contact j joins C, with y = L^-1 A_Cj and its Schur complement sj > 0. */
static void clamp(lcp_state *s, int j, const double *y, double sj)
{
    double *Lk = s->L + (size_t)s->k * s->n;
    for (int p = 0; p < s->k; p++) Lk[p] = y[p];
    Lk[s->k] = sqrt(sj);
    s->at[s->k] = j;
    s->pos[j] = s->k;
    s->set[j] = IN_C;
    s->k++;
}

/* The contact at position p leaves C for NC, its force 0.  Deleting row and column
 * p of A_CC deletes row p of L; the rows below keep their columns before p, and
 * their block after p, T, becomes the factor of T T^T + l l^T (l their column p),
 * a rank-one update by plane rotations (Golub and Van Loan, 6.5.4). */
static void unclamp(lcp_state *s, int p)
{
    int n = s->n, k = s->k, m = k - 1 - p;
    double *L = s->L, *x = s->tmp;
    int j = s->at[p];
    for (int i = 0; i < m; i++) x[i] = L[(size_t)(p + 1 + i) * n + p];
    for (int r = p + 1; r < k; r++) {
        double *dst = L + (size_t)(r - 1) * n, *src = L + (size_t)r * n;
        for (int c = 0; c < p; c++) dst[c] = src[c];
        for (int c = p; c < r; c++) dst[c] = src[c + 1];
        s->at[r - 1] = s->at[r];
        s->pos[s->at[r - 1]] = r - 1;
    }
    for (int i = 0; i < m; i++) {
        double *Li = L + (size_t)(p + i) * n;
        double a = Li[p + i], r = sqrt(a * a + x[i] * x[i]);
        double c = r / a, sn = x[i] / a;
        Li[p + i] = r;
        for (int t = i + 1; t < m; t++) {
            double *Lt = L + (size_t)(p + t) * n;
            Lt[p + i] = (Lt[p + i] + sn * x[t]) / c;
            x[t] = c * x[t] - sn * Lt[p + i];
        }
    }
    s->k--;
    s->pos[j] = -1;
    s->set[j] = IN_NC;
    s->z[j] = 0;
    s->w[j] = 0;
}

/* sum_j sqrt(A_jj) z_j over C, so that sqrt(A_ii) times it bounds |A_i z|. */
static double z_size(const lcp_state *s)
{
    double sum = 0;
    for (int p = 0; p < s->k; p++) sum += s->root[s->at[p]] * s->z[s->at[p]];
    return sum;
}

/* The answer's tolerance of w_i (lcp.h): LCP_TOL times the largest |q| and the
 * size of A_i z, with zs = z_size. */
static double tol_w(const lcp_state *s, int i, double zs)
{
    return LCP_TOL * (s->qmax + s->root[i] * zs);
}

/* The tolerance of w_i in the pivots' bookkeeping, which take a w within it for
 * 0: LCP_TOL times the size of w_i's own terms, so that a light body's contact
 * is not taken for closed while a heavy one's forces are large. */
static double tol_row(const lcp_state *s, int i, double zs)
{
    return LCP_TOL * (fabs(s->q[i]) + s->root[i] * zs);
}

/* Forces compare across contacts as z_j sqrt(A_jj), their values for A scaled to
 * a unit diagonal, so that a light body's small forces are not rounding beside a
 * heavy one's.  The tolerance of z_j sqrt(A_jj): LCP_TOL times the largest. */
static double tol_z(const lcp_state *s)
{
    double m = 0;
    for (int p = 0; p < s->k; p++) m = fmax(m, s->z[s->at[p]] * s->root[s->at[p]]);
    return LCP_TOL * m;
}

/* The size of the direction dz, scaled as the forces are. */
static double dz_size(const lcp_state *s, int d)
{
    double m = s->root[d];
    for (int p = 0; p < s->k; p++) m = fmax(m, fabs(s->dz[p]) * s->root[s->at[p]]);
    return m;
}

/* z_C solved afresh from w_C = 0, A_CC z_C = -q_C, with the given number of steps
 * of iterative refinement; then w = A z + q for every contact (z is 0 outside C). */
static void settle(lcp_state *s, int refine)
{
    int n = s->n, k = s->k;
    double *x = s->yj, *r = s->tmp;
    for (int p = 0; p < k; p++) x[p] = -s->q[s->at[p]];
    solve_lower(s, x, x);
    solve_upper(s, x, x);
    for (int it = 0; it < refine; it++) {
        for (int p = 0; p < k; p++) {
            const double *Ai = s->A + (size_t)s->at[p] * n;
            r[p] = -s->q[s->at[p]] - dot_at(s, Ai, x);
        }
        solve_lower(s, r, r);
        solve_upper(s, r, r);
        for (int p = 0; p < k; p++) x[p] += r[p];
    }
    for (int p = 0; p < k; p++) s->z[s->at[p]] = x[p];
    for (int i = 0; i < n; i++) {
        const double *Ai = s->A + (size_t)i * n;
        s->w[i] = s->set[i] == IN_C ? 0 : s->q[i] + dot_at(s, Ai, x);
    }
}

/* The direction of d's drive: dz over C (by position) with dz_d = 1 keeping w_C
 * fixed, A_CC dz_C = -A_Cd, and y = L^-1 A_Cd; then the rates dw_j of the free
 * contacts and of d.  Returns d's Schur complement s_d, the rate of w_d in exact
 * arithmetic. */
static double direction(lcp_state *s, int d)
{
    int n = s->n, k = s->k;
    double sd = schur(s, d, s->y);
    solve_upper(s, s->y, s->dz);
    for (int p = 0; p < k; p++) s->dz[p] = -s->dz[p];
    for (int j = 0; j < n; j++) {
        if (j != d && s->set[j] != IN_NC) continue;
        const double *Aj = s->A + (size_t)j * n;
        s->dw[j] = Aj[d] + dot_at(s, Aj, s->dz);
    }
    return sd;
}

/* Baraff's ratio test on d's drive: the contact whose bound the step reaches
 * first, the lowest index on ties, and the step in *step; d itself when w_d gets
 * to 0 first, or within the tolerance at the step found (so that d, not another,
 * is clamped when both come together: a clamped d's row is independent); -1 when
 * nothing bounds the step.  A free contact to clamp comes with y_j = L^-1 A_Cj in
 * s->yj and its Schur complement in *sj; one whose row depends on C's falls by
 * rounding only, and is passed over. */
static int ratio_test(lcp_state *s, int d, double sd, bool rises, double *step, double *sj)
{
    int n = s->n;
    const double *z = s->z, *w = s->w;
    double zs = z_size(s), tz = tol_z(s), dzs = dz_size(s, d);
    for (int j = 0; j < n; j++) s->skip[j] = 0;
    for (;;) {
        int best = -1;
        *step = INFINITY;
        for (int j = 0; j < n; j++) {
            double t;
            if (j == d) {
                if (!rises) continue;
                t = w[d] < 0 ? -w[d] / sd : 0;
            } else if (s->set[j] == IN_C) {
                double r = s->dz[s->pos[j]];
                if (!(r * s->root[j] < -RATE_TOL * dzs)) continue;
                t = z[j] * s->root[j] <= tz ? 0 : z[j] / -r;
            } else if (s->set[j] == IN_NC && !s->skip[j]) {
                double r = s->dw[j];
                if (!(r < -RATE_TOL * s->root[j] * dzs)) continue;
                t = w[j] <= tol_row(s, j, zs) ? 0 : w[j] / -r;
            } else {
                continue;
            }
            if (t < *step) {
                best = j;
                *step = t;
            }
        }
        if (best >= 0 && rises && w[d] + *step * sd >= -tol_row(s, d, zs)) return d;
        if (best < 0 || best == d || s->set[best] == IN_C) return best;
        *sj = schur(s, best, s->yj);
        if (*sj > PIVOT_TOL * s->A[(size_t)best * n + best]) return best;
        s->skip[best] = 1;
    }
}

/* z += step dz over C and d, w += step dw over NC and d. */
static void advance(lcp_state *s, int d, double step)
{
    for (int p = 0; p < s->k; p++) s->z[s->at[p]] += step * s->dz[p];
    s->z[d] += step;
    for (int j = 0; j < s->n; j++)
        if (j == d || s->set[j] == IN_NC) s->w[j] += step * s->dw[j];
}

/* d's w is 0 but its row depends on C's (s_d = 0), so it cannot be clamped: its
 * force is handed to C along the drive's direction backwards, a null vector of A
 * that moves no w, until z_d = 0 (d joins NC: 1) or a clamped force reaches 0
 * first (it joins NC, and the drive goes on: 0). */
static int release(lcp_state *s, int d)
{
    double tz = tol_z(s), dzs = dz_size(s, d);
    int best = -1;
    double step = INFINITY;
    for (int j = 0; j < s->n; j++) {
        double t;
        if (j == d) {
            t = s->z[d];
        } else if (s->set[j] == IN_C) {
            double r = s->dz[s->pos[j]];
            if (!(r * s->root[j] > RATE_TOL * dzs)) continue;
            t = s->z[j] * s->root[j] <= tz ? 0 : s->z[j] / r;
        } else {
            continue;
        }
        if (t < step || (t == step && j == d)) {
            best = j;
            step = t;
        }
    }
    advance(s, d, -step);
    if (best == d) {
        s->z[d] = 0;
        s->set[d] = IN_NC;
        return 1;
    }
    unclamp(s, s->pos[best]);
    return 0;
}

/* Drives contact d (w_d < 0, z_d = 0) until it is clamped, or freed at w_d = 0
 * when its row depends on C's (Baraff's drive-to-zero): 0, or -1 when w_d cannot
 * rise (no solution) or after the pivot limit. */
static int drive(lcp_state *s, int d)
{
    int n = s->n;
    for (;;) {
        if (++s->pivots > 100 + 20L * n) return -1;
        double sd = direction(s, d);
        bool rises = sd > PIVOT_TOL * s->A[(size_t)d * n + d];
        double step, sj = 0;
        int best = ratio_test(s, d, sd, rises, &step, &sj);
        if (best < 0) {
            /* w_d cannot rise (dz >= 0, A dz = 0, q.dz = w_d): no solution,
             * unless w_d is within the answer's tolerance: then it is taken
             * for 0, and d is freed or, once its row is independent, clamped */
            if (s->w[d] < -tol_w(s, d, z_size(s))) return -1;
            s->w[d] = 0;
            if (release(s, d)) return 0;
            continue;
        }
        advance(s, d, step);
        if (best == d) {
            clamp(s, d, s->y, sd);
            s->w[d] = 0;
            return 0;
        }
        if (s->set[best] == IN_C) {
            unclamp(s, s->pos[best]);
        } else {
            clamp(s, best, s->yj, sj);
            s->w[best] = 0;
        }
    }
}

/* The end's checks, after every contact was taken: z settled with refinement,
 * clamped forces a rounding below 0 made 0 and w computed in index order.  Returns
 * 0 when the answer holds; 1 when a contact was sent back to be taken again (a
 * clamped force far below 0, or a free w below the tolerance); -1 when a clamped
 * w is beyond the tolerance (refinement could not reach it). */
static int verify(lcp_state *s)
{
    int n = s->n;
    settle(s, 2);
    double tz = tol_z(s);
    int back = 0;
    for (int j = 0; j < n; j++) {
        if (s->set[j] != IN_C || s->z[j] >= 0) continue;
        if (s->z[j] * s->root[j] >= -tz) {
            s->z[j] = 0;
        } else {
            unclamp(s, s->pos[j]);
            s->set[j] = UNSEEN;
            back = 1;
        }
    }
    if (back) {
        s->pivots++;
        settle(s, 0);
        return 1;
    }
    double zs = z_size(s);
    for (int i = 0; i < n; i++) {
        double v = w_of(s->A + (size_t)i * n, s->q[i], s->z, n), tw = tol_w(s, i, zs);
        s->w[i] = v;
        if (s->set[i] == IN_C && (v < -tw || (s->z[i] > 0 && v > tw))) {
            return -1;
        }
        if (s->set[i] == IN_NC && v < -tw) {
            s->set[i] = UNSEEN;
            back = 1;
        }
    }
    if (back) s->pivots++;
    return back;
}

int lcp_solve(int n, const double *A, const double *q, double *z, double *w, lcp_work *work)
{
    assert(n >= 0);
    lcp_state s;
    state_init(&s, n, A, q, z, w, work);
    bool ok = true;
    for (int i = 0; i < n; i++) {
        z[i] = 0;
        w[i] = q[i];
        ok = ok && isfinite(q[i]) && A[(size_t)i * n + i] >= 0;
        for (int j = 0; j < n; j++) ok = ok && isfinite(A[(size_t)i * n + j]);
        s.root[i] = sqrt(fmax(A[(size_t)i * n + i], 0));
        s.qmax = fmax(s.qmax, fabs(q[i]));
    }
    int r = ok ? 1 : -1;
    while (r == 1) {
        int d = 0;
        while (d < n && s.set[d] != UNSEEN) d++;
        if (d == n) {
            r = verify(&s);
        } else if (w[d] >= -tol_w(&s, d, z_size(&s))) {
            s.set[d] = IN_NC;
        } else if (drive(&s, d) < 0) {
            r = -1;
        } else {
            settle(&s, 0);
        }
        if (s.pivots > 100 + 20L * n) r = -1;
    }
    if (r < 0) {
        for (int i = 0; i < n; i++) {
            z[i] = 0;
            w[i] = q[i];
        }
    }
    return r;
}

bool lcp_unique(int n, const double *A, const double *q, const double *z, lcp_work *work)
{
    assert(n >= 0);
    lcp_state s;
    state_init(&s, n, A, q, NULL, NULL, work);
    double zs = 0;
    for (int i = 0; i < n; i++) {
        s.root[i] = sqrt(fmax(A[(size_t)i * n + i], 0));
        s.qmax = fmax(s.qmax, fabs(q[i]));
        zs += s.root[i] * z[i];
    }
    for (int i = 0; i < n; i++) {
        const double *Ai = A + (size_t)i * n;
        if (w_of(Ai, q[i], z, n) > tol_w(&s, i, zs)) continue; /* z_i = 0 in every solution */
        double si = schur(&s, i, s.y);
        if (!(si > PIVOT_TOL * Ai[i])) return false;
        clamp(&s, i, s.y, si);
    }
    return true;
}
