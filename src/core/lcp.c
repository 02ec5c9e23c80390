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
 *
 * Crowds.  Beyond DENSE_MAX contacts (a crowd's cluster: a hundred balls in a
 * slot make 400) A is sparse, for a contact's row touches only the contacts of
 * its two bodies, and so, mostly, is the factor of A_CC: a row of L is 0 before
 * the first clamped contact it is coupled to (through shared bodies, directly or
 * by the rows between).  The sums over C then run over A's nonzeros alone
 * (row_dot), each row of L from its first nonzero (first), the rank-one update
 * of unclamp over the rows that change, and L^-T by rows; the answer is held to
 * the same checks.  Up to DENSE_MAX every sum is the dense one, to the bit.  A
 * crowd's Newton steps solve problems that differ little from the last:
 * lcp_solve_warm starts from the last answer's clamped set (warm); on the slot
 * that takes some half the pivots of a cold start.
 */
#include "lcp.h"

#include <assert.h>
#include <math.h>

/* A Schur complement of contact j at most this times A_jj: j's row depends on C's. */
#define PIVOT_TOL 1e-11
/* A rate at most this times the direction's size (both scaled) is rounding. */
#define RATE_TOL 1e-11

/* Problems of more contacts than this are solved sparsely (below); those of up to
 * it exactly as before, to the bit. */
#define DENSE_MAX 64

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
    /* sparse (n > DENSE_MAX), in the workspace's room the least-norm answer
     * uses otherwise: */
    bool sparse;
    double *inv;         /* by position: 1 / L's diagonal */
    int *first;          /* by position: L's row holds 0 before this column */
    int *nzs, *nzc;      /* A's nonzeros: row i's columns nzc[nzs[i] .. nzs[i+1]) */
    int *pair;           /* scratch of 2 n: (position, index) of one row's terms */
} lcp_state;

/* Doubles of the workspace: the pivoting's m^2 + 6 m, and lcp_least_norm's
 * 3 m^2 + 6 m (its ints fit in the pivoting's 4 m). */
static size_t work_doubles(size_t m)
{
    return 3 * m * m + 6 * m;
}

size_t lcp_work_size(int n)
{
    assert(n >= 0);
    size_t m = (size_t)n;
    return sizeof(double) * work_doubles(m) + sizeof(int) * 4 * m;
}

static void state_init(lcp_state *s, int n, const double *A, const double *q, double *z,
                       double *w, lcp_work *work)
{
    size_t m = (size_t)n;
    double *d = (double *)(void *)work;
    int *i = (int *)(void *)(d + work_doubles(m));
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
    s->sparse = n > DENSE_MAX;
    if (s->sparse) {
        /* m doubles and m^2 + 4 m + 1 ints in the 2 m^2 doubles after the
         * pivoting's */
        s->inv = d + m * m + 6 * m;
        int *f = (int *)(void *)(s->inv + m);
        s->first = f;
        s->nzs = f + m;
        s->pair = s->nzs + m + 1;
        s->nzc = s->pair + 2 * m;
    }
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

/* Row j of A times x over C (x by position): the sum over the positions p of
 * A_j,at[p] x[p], in the order of p.  Sparse, over row j's nonzeros alone, put in
 * the order of their positions: the same sum but for the zeros' terms. */
static double row_dot(const lcp_state *s, int j, const double *x)
{
    const double *Aj = s->A + (size_t)j * s->n;
    if (!s->sparse) return dot_at(s, Aj, x);
    int m = 0, *pr = s->pair;
    for (int e = s->nzs[j]; e < s->nzs[j + 1]; e++) {
        int c = s->nzc[e], p = s->pos[c];
        if (p < 0) continue;
        /* (insertion by position: a row's nonzeros are its contacts' bodies' few) */
        int t = m++;
        for (; t > 0 && pr[2 * (t - 1)] > p; t--) {
            pr[2 * t] = pr[2 * (t - 1)];
            pr[2 * t + 1] = pr[2 * (t - 1) + 1];
        }
        pr[2 * t] = p;
        pr[2 * t + 1] = c;
    }
    double v = 0;
    for (int t = 0; t < m; t++) v += Aj[pr[2 * t + 1]] * x[pr[2 * t]];
    return v;
}

/* y = L^-1 b over the k positions (y may be b).  Sparse, each row's sum starts at
 * its first nonzero, or at b's (y is 0 before it), and the diagonal's division is
 * a product (the rows are short: it was a third of their time). */
static void solve_lower(const lcp_state *s, const double *b, double *y)
{
    int b0 = 0;
    if (s->sparse)
        while (b0 < s->k && b[b0] == 0) b0++;
    for (int r = 0; r < s->k; r++) {
        const double *Lr = s->L + (size_t)r * s->n;
        int lo = s->sparse ? (s->first[r] > b0 ? s->first[r] : b0) : 0;
        double v = b[r] - (lo < r ? dot(Lr + lo, y + lo, r - lo) : 0);
        y[r] = s->sparse ? v * s->inv[r] : v / Lr[r];
    }
}

/* x = L^-T y over the k positions (x may be y).  Sparse, by rows of L from the
 * last, each over its nonzeros (the same answer, summed in another order; the
 * division a product, as in solve_lower). */
static void solve_upper(const lcp_state *s, const double *y, double *x)
{
    if (s->sparse) {
        for (int r = 0; r < s->k; r++) x[r] = y[r];
        for (int r = s->k - 1; r >= 0; r--) {
            const double *Lr = s->L + (size_t)r * s->n;
            double xr = x[r] *= s->inv[r];
            for (int c = s->first[r]; c < r; c++) x[c] -= Lr[c] * xr;
        }
        return;
    }
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
    if (s->sparse) {
        int f = 0;
        while (f < s->k && y[f] == 0) f++;
        s->first[s->k] = f;
        s->inv[s->k] = 1 / Lk[s->k];
    }
    s->at[s->k] = j;
    s->pos[j] = s->k;
    s->set[j] = IN_C;
    s->k++;
}

/* The plane rotation of unclamp's step at the diagonal *a with x_i: *a becomes
 * their length; c and sn as Golub and Van Loan's update uses them. */
static void rotation(double *a, double xi, double *c, double *sn)
{
    double r = sqrt(*a * *a + xi * xi);
    *c = r / *a;
    *sn = xi / *a;
    *a = r;
}

/* unclamp's rank-one update of the m rows from position p on, sparse: at step i
 * only the rows that hold column p + i or an x_t not 0 change (the others' 0
 * stays 0), and a row does from the step at its first column on (x_t is 0
 * before: it starts as the row's column p, and only a column held makes it
 * more), so the rows join a list of those changing as the steps reach their
 * first columns, and leave it at their own diagonals.  The same numbers as the
 * dense update's. */
static void rotate_sparse(lcp_state *s, int p, int m, double *x)
{
    int n = s->n, *head = s->pair, *next = s->pair + n, live = -1;
    for (int i = 0; i < m; i++) head[i] = -1;
    for (int t = m - 1; t >= 0; t--) {
        int at = s->first[p + t] - p;
        if (at < 0) at = 0;
        next[t] = head[at];
        head[at] = t;
    }
    for (int i = 0; i < m; i++) {
        double c, sn, *diag = s->L + (size_t)(p + i) * n + p + i;
        rotation(diag, x[i], &c, &sn);
        s->inv[p + i] = 1 / *diag;
        for (int t = head[i], after; t >= 0; t = after) {
            after = next[t];
            next[t] = live;
            live = t;
        }
        for (int t = live, prev = -1, after; t >= 0; t = after) {
            after = next[t];
            if (t <= i) {
                if (prev < 0) live = after;
                else next[prev] = after;
                continue;
            }
            double *Lt = s->L + (size_t)(p + t) * n;
            Lt[p + i] = (Lt[p + i] + sn * x[t]) / c;
            x[t] = c * x[t] - sn * Lt[p + i];
            prev = t;
        }
    }
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
    /* (sparse, a row's columns before its first are not read, nor moved: the
     * update fills no column before a row's first, for it mixes a row's columns
     * from p on, with x_t nonzero only where row t holds column p or, later,
     * one of those mixed) */
    for (int i = 0; i < m; i++)
        x[i] = !s->sparse || s->first[p + 1 + i] <= p ? L[(size_t)(p + 1 + i) * n + p] : 0;
    for (int r = p + 1; r < k; r++) {
        double *dst = L + (size_t)(r - 1) * n, *src = L + (size_t)r * n;
        int f = 0;
        if (s->sparse) {
            f = s->first[r] > p ? s->first[r] - 1 : s->first[r];
            s->first[r - 1] = f;
            s->inv[r - 1] = s->inv[r];
        }
        for (int c = f; c < p; c++) dst[c] = src[c];
        for (int c = f > p ? f : p; c < r; c++) dst[c] = src[c + 1];
        s->at[r - 1] = s->at[r];
        s->pos[s->at[r - 1]] = r - 1;
    }
    if (s->sparse) {
        rotate_sparse(s, p, m, x);
    } else {
        for (int i = 0; i < m; i++) {
            double *Li = L + (size_t)(p + i) * n;
            double c, sn;
            rotation(Li + p + i, x[i], &c, &sn);
            for (int t = i + 1; t < m; t++) {
                double *Lt = L + (size_t)(p + t) * n;
                Lt[p + i] = (Lt[p + i] + sn * x[t]) / c;
                x[t] = c * x[t] - sn * Lt[p + i];
            }
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
            r[p] = -s->q[s->at[p]] - row_dot(s, s->at[p], x);
        }
        solve_lower(s, r, r);
        solve_upper(s, r, r);
        for (int p = 0; p < k; p++) x[p] += r[p];
    }
    for (int p = 0; p < k; p++) s->z[s->at[p]] = x[p];
    for (int i = 0; i < n; i++) s->w[i] = s->set[i] == IN_C ? 0 : s->q[i] + row_dot(s, i, x);
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
        s->dw[j] = s->A[(size_t)j * n + d] + row_dot(s, j, s->dz);
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
        double v = s->q[i], tw = tol_w(s, i, zs);
        if (s->sparse) {
            /* (w_of's sum but for the zeros' terms) */
            for (int e = s->nzs[i]; e < s->nzs[i + 1]; e++)
                v += s->A[(size_t)i * n + s->nzc[e]] * s->z[s->nzc[e]];
        } else {
            v = w_of(s->A + (size_t)i * n, s->q[i], s->z, n);
        }
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

/* A's nonzeros, row by row, into nzs/nzc (row i's columns in index order);
 * whether all of A is finite. */
static bool nonzeros(lcp_state *s)
{
    int n = s->n, e = 0;
    bool ok = true;
    for (int i = 0; i < n; i++) {
        s->nzs[i] = e;
        const double *Ai = s->A + (size_t)i * n;
        for (int j = 0; j < n; j++) {
            ok = ok && isfinite(Ai[j]);
            if (Ai[j] != 0) s->nzc[e++] = j;
        }
    }
    s->nzs[n] = e;
    return ok;
}

/* The warm start from the guess z0 >= 0 (by index, z0_i > 0 guessed clamped):
 * the guessed contacts clamped in index order, but for those whose rows depend
 * on the ones clamped before; then from z0 on C towards z_C = -A_CC^-1 q_C (an
 * active set's step, as Lawson and Hanson's for least squares with z >= 0): where
 * a force would fall below 0 on the way, the step stops where the first does,
 * those at 0 there let go (to be taken again), and on from there.  The
 * invariants hold at the end (z_C >= 0, w_C = 0, NC empty): it is as if these
 * contacts had been taken first and clamped. */
static void warm(lcp_state *s, double *z0)
{
    int n = s->n;
    double *x = s->yj;
    for (int i = 0; i < n; i++) {
        if (!(z0[i] > 0)) continue;
        double si = schur(s, i, s->y);
        if (si > PIVOT_TOL * s->A[(size_t)i * n + i]) clamp(s, i, s->y, si);
    }
    for (;;) {
        for (int p = 0; p < s->k; p++) x[p] = -s->q[s->at[p]];
        solve_lower(s, x, x);
        solve_upper(s, x, x);
        double t = 1;
        for (int p = 0; p < s->k; p++) {
            double a = z0[s->at[p]];
            if (x[p] < 0 && a / (a - x[p]) < t) t = a / (a - x[p]);
        }
        if (t == 1) break;
        for (int p = 0; p < s->k; p++) {
            int j = s->at[p];
            z0[j] = x[p] < 0 && z0[j] / (z0[j] - x[p]) == t ? 0 : z0[j] + t * (x[p] - z0[j]);
        }
        for (int j = 0; j < n; j++) {
            if (s->set[j] != IN_C || z0[j] != 0) continue;
            unclamp(s, s->pos[j]);
            s->set[j] = UNSEEN;
            s->pivots++;
        }
    }
    settle(s, 0);
}

static int pivot(lcp_state *s);

/* lcp_solve and lcp_solve_warm: from the guess z > 0 when warm. */
static int solve(int n, const double *A, const double *q, double *z, double *w, lcp_work *work,
                 bool warmed)
{
    assert(n >= 0);
    lcp_state s;
    state_init(&s, n, A, q, z, w, work);
    bool ok = true;
    for (int i = 0; i < n; i++) {
        ok = ok && isfinite(q[i]) && A[(size_t)i * n + i] >= 0;
        if (!s.sparse)
            for (int j = 0; j < n; j++) ok = ok && isfinite(A[(size_t)i * n + j]);
        /* (the guess, in dw till the pivots' first use) */
        s.dw[i] = warmed && isfinite(z[i]) && z[i] > 0 ? z[i] : 0;
        z[i] = 0;
        w[i] = q[i];
        s.root[i] = sqrt(fmax(A[(size_t)i * n + i], 0));
        s.qmax = fmax(s.qmax, fabs(q[i]));
    }
    if (s.sparse) ok = nonzeros(&s) && ok;
    if (ok && warmed) warm(&s, s.dw);
    int r = ok ? pivot(&s) : -1;
    if (r < 0) {
        for (int i = 0; i < n; i++) {
            z[i] = 0;
            w[i] = q[i];
        }
    }
    return r;
}

/* The contacts taken in index order until the answer holds: 0, or -1. */
static int pivot(lcp_state *s)
{
    int n = s->n, r = 1, d = 0;
    double *w = s->w, zs = z_size(s);
    while (r == 1) {
        /* (the contacts before the last taken are seen: but after verify) */
        while (d < n && s->set[d] != UNSEEN) d++;
        if (d == n) {
            r = verify(s);
            d = 0;
            zs = z_size(s);
        } else if (w[d] >= -tol_w(s, d, zs)) {
            s->set[d] = IN_NC;
        } else if (drive(s, d) < 0) {
            r = -1;
        } else {
            settle(s, 0);
            zs = z_size(s);
        }
        if (s->pivots > 100 + 20L * n) r = -1;
    }
    return r;
}

int lcp_solve(int n, const double *A, const double *q, double *z, double *w, lcp_work *work)
{
    return solve(n, A, q, z, w, work, false);
}

int lcp_solve_warm(int n, const double *A, const double *q, double *z, double *w, lcp_work *work)
{
    return solve(n, A, q, z, w, work, true);
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

/* ------------------------------------------------------ the least-norm answer
 *
 * The answers of one problem share w (lcp.h): they are the z >= 0 with A z = A z*
 * (z* the one found) and z_i = 0 wherever w_i > 0.  Over the set S of the other
 * contacts, A_SS z_S = A_SS z*_S says only that z_S lies in z*_S plus the null
 * space of A_SS: with A_SS = D U L U^T D (D its diagonal's square roots, U the
 * eigenvectors of the scaled matrix, L their r eigenvalues above zero), it is
 * V^T z_S = V^T z*_S for V = D U, r independent equations.  The least-norm answer
 * is the convex quadratic program
 *     minimise |x|^2 / 2  subject to  V^T x = V^T z*_S,  x >= 0,
 * solved by the primal active-set method (Nocedal and Wright, "Numerical
 * Optimization", 16.5) from x = z*_S, which is feasible: the free set F keeps r
 * independent rows of V; each step projects x_F onto the range of V_F (the
 * least-norm x with the bounds outside F held at 0), and goes as far towards it
 * as x >= 0 allows, a bound that stops it joining those held; at the projection,
 * a held bound whose multiplier -V_i mu is negative is let go.  The answer is
 * unique (the objective is strictly convex), so it does not depend on the order of
 * the contacts, and it is symmetric when the problem is.  The eigenvectors come
 * from Jacobi's cyclic method (Golub and Van Loan, "Matrix Computations", 8.5),
 * robust at the rank-deficient matrices met here. */

/* An eigenvalue of A_SS scaled to a unit diagonal at most this times the largest
 * is zero (Jacobi's are exact to about 1e-16 of it): those contacts' rows depend
 * on the others'. */
#define RANK_TOL 1e-12
/* Sweeps of Jacobi's method, at most (it converges quadratically: about 6). */
#define JACOBI_SWEEPS 60

/* The eigen-decomposition of the symmetric s x s matrix M (row-major; its diagonal
 * becomes the eigenvalues, the rest is destroyed), the eigenvectors in the columns
 * of U. */
static void jacobi(int s, double *M, double *U)
{
    for (int i = 0; i < s; i++)
        for (int j = 0; j < s; j++) U[i * s + j] = i == j;
    for (int sweep = 0; sweep < JACOBI_SWEEPS; sweep++) {
        double off = 0, diag = 0;
        for (int i = 0; i < s; i++) {
            diag += M[i * s + i] * M[i * s + i];
            for (int j = i + 1; j < s; j++) off += M[i * s + j] * M[i * s + j];
        }
        if (off <= 1e-32 * diag) return;
        for (int p = 0; p < s; p++) {
            for (int q = p + 1; q < s; q++) {
                double apq = M[p * s + q];
                if (apq == 0) continue;
                /* the rotation of rows and columns p, q that zeroes M_pq */
                double theta = (M[q * s + q] - M[p * s + p]) / (2 * apq);
                double t = (theta >= 0 ? 1 : -1) / (fabs(theta) + sqrt(theta * theta + 1));
                double c = 1 / sqrt(t * t + 1), sn = t * c;
                for (int k = 0; k < s; k++) {
                    double a = M[k * s + p], b = M[k * s + q];
                    M[k * s + p] = c * a - sn * b;
                    M[k * s + q] = sn * a + c * b;
                }
                for (int k = 0; k < s; k++) {
                    double a = M[p * s + k], b = M[q * s + k];
                    M[p * s + k] = c * a - sn * b;
                    M[q * s + k] = sn * a + c * b;
                }
                for (int k = 0; k < s; k++) {
                    double a = U[k * s + p], b = U[k * s + q];
                    U[k * s + p] = c * a - sn * b;
                    U[k * s + q] = sn * a + c * b;
                }
            }
        }
    }
}

/* The QR factors of V_F, the rows F of V (s x r, rank r): the |F| x r matrix Q
 * with orthonormal columns, by modified Gram-Schmidt twice over (Q row a of V_F
 * at Q's row a; rows outside F left 0), and the upper triangular r x r R with
 * V_F = Q R.  False when a column falls to rounding (rank below r). */
static bool qr_free(int s, int r, const double *V, const int *F, double *Q, double *R)
{
    for (int j = 0; j < r; j++) {
        double len = 0;
        for (int a = 0; a < s; a++) {
            Q[a * r + j] = F[a] ? V[a * r + j] : 0;
            len += Q[a * r + j] * Q[a * r + j];
        }
        for (int i = 0; i < r; i++) R[i * r + j] = 0;
        for (int pass = 0; pass < 2; pass++) {
            for (int i = 0; i < j; i++) {
                double d = 0;
                for (int a = 0; a < s; a++) d += Q[a * r + i] * Q[a * r + j];
                for (int a = 0; a < s; a++) Q[a * r + j] -= d * Q[a * r + i];
                R[i * r + j] += d;
            }
        }
        double res = 0;
        for (int a = 0; a < s; a++) res += Q[a * r + j] * Q[a * r + j];
        if (!(res > 1e-24 * len)) return false;
        res = sqrt(res);
        R[j * r + j] = res;
        for (int a = 0; a < s; a++) Q[a * r + j] /= res;
    }
    return true;
}

/* The rows of V (s x r) in F, with rows added from outside F in index order
 * until they span R^r (Gram-Schmidt, B the r x r basis found): false when even
 * all s rows do not. */
static bool span_free(int s, int r, const double *V, int *F, double *B, double *t)
{
    int k = 0;
    for (int pass = 0; pass < 2 && k < r; pass++) {
        for (int a = 0; a < s && k < r; a++) {
            if ((F[a] != 0) != (pass == 0)) continue;
            double len = 0;
            for (int j = 0; j < r; j++) {
                t[j] = V[a * r + j];
                len += t[j] * t[j];
            }
            for (int b = 0; b < k; b++) {
                double d = 0;
                for (int j = 0; j < r; j++) d += t[j] * B[b * r + j];
                for (int j = 0; j < r; j++) t[j] -= d * B[b * r + j];
            }
            double res = 0;
            for (int j = 0; j < r; j++) res += t[j] * t[j];
            if (!(res > 1e-18 * len)) continue;
            res = sqrt(res);
            for (int j = 0; j < r; j++) B[k * r + j] = t[j] / res;
            k++;
            F[a] = 1;
        }
    }
    return k == r;
}

void lcp_least_norm(int n, const double *A, const double *q, double *z, lcp_work *work)
{
    assert(n >= 0);
    if (n < 2 || lcp_unique(n, A, q, z, work)) return;
    size_t m = (size_t)n;
    double *M = (double *)(void *)work, *U = M + m * m, *V = U + m * m;
    double *d = V + m * m, *x = d + m, *p = x + m, *mu = p + m, *g = mu + m, *lam = g + m;
    int *S = (int *)(void *)(M + work_doubles(m)), *F = S + m; /* F: x_a free */
    /* S: the contacts that may carry force (w_i = 0); the others carry none in
     * any answer, nor do those whose row is zero */
    double qmax = 0, zs = 0;
    for (int i = 0; i < n; i++) {
        qmax = fmax(qmax, fabs(q[i]));
        zs += sqrt(fmax(A[i * n + i], 0)) * z[i];
    }
    int s = 0;
    for (int i = 0; i < n; i++) {
        double root = sqrt(fmax(A[i * n + i], 0));
        double wi = w_of(A + (size_t)i * n, q[i], z, n);
        if (root > 0 && wi <= LCP_TOL * (qmax + root * zs)) S[s++] = i;
        else z[i] = 0;
    }
    if (s < 2) return;
    for (int a = 0; a < s; a++) {
        d[a] = sqrt(A[S[a] * n + S[a]]);
        x[a] = z[S[a]];
    }
    for (int a = 0; a < s; a++)
        for (int b = 0; b < s; b++) M[a * s + b] = A[S[a] * n + S[b]] / (d[a] * d[b]);
    jacobi(s, M, U);
    double top = 0;
    for (int a = 0; a < s; a++) {
        lam[a] = M[a * s + a];
        top = fmax(top, lam[a]);
    }
    /* V = D U over the eigenvalues above zero */
    int r = 0;
    for (int k = 0; k < s; k++) {
        if (!(lam[k] > RANK_TOL * top)) continue;
        for (int a = 0; a < s; a++) V[a * s + r] = d[a] * U[a * s + k];
        r++;
    }
    if (r == s || r == 0) return;
    for (int a = 0; a < s; a++)
        for (int j = 0; j < r; j++) V[a * r + j] = V[a * s + j]; /* (packed s x r) */
    for (int a = 0; a < s; a++) F[a] = x[a] > 0;
    if (!span_free(s, r, V, F, M, g)) return;
    for (int it = 0; it < 4 * s + 20; it++) {
        /* the projection of x_F onto the range of V_F = Q R: Q Q^T x_F, which is
         * V_F mu for mu = R^-1 Q^T x_F */
        if (!qr_free(s, r, V, F, M, U)) break; /* (rounding: x stands, an answer) */
        for (int j = 0; j < r; j++) {
            g[j] = 0;
            for (int a = 0; a < s; a++) g[j] += M[a * r + j] * x[a];
        }
        for (int i = r - 1; i >= 0; i--) {
            double v = g[i];
            for (int j = i + 1; j < r; j++) v -= U[i * r + j] * mu[j];
            mu[i] = v / U[i * r + i];
        }
        double pmax = 0, xmax = 0;
        for (int a = 0; a < s; a++) {
            double v = 0;
            if (F[a])
                for (int j = 0; j < r; j++) v += M[a * r + j] * g[j];
            else
                for (int j = 0; j < r; j++) v += V[a * r + j] * mu[j];
            p[a] = F[a] ? v - x[a] : -v; /* held: its multiplier */
            if (F[a]) pmax = fmax(pmax, fabs(p[a]));
            xmax = fmax(xmax, fabs(x[a]));
        }
        if (pmax <= 1e-11 * xmax) {
            /* at the projection: let go of the held bound whose multiplier is the
             * most negative, or stop */
            int worst = -1;
            for (int a = 0; a < s; a++)
                if (!F[a] && p[a] < -1e-12 * xmax && (worst < 0 || p[a] < p[worst])) worst = a;
            if (worst < 0) break;
            F[worst] = 1;
            continue;
        }
        /* towards it, as far as x >= 0 allows */
        double step = 1;
        int stop = -1;
        for (int a = 0; a < s; a++) {
            if (!F[a] || !(p[a] < 0) || !(x[a] + p[a] < 0)) continue;
            double t = x[a] / -p[a];
            if (t < step) {
                step = t;
                stop = a;
            }
        }
        for (int a = 0; a < s; a++)
            if (F[a]) x[a] += step * p[a];
        if (stop >= 0) {
            x[stop] = 0;
            F[stop] = 0;
        }
    }
    for (int a = 0; a < s; a++) z[S[a]] = fmax(x[a], 0);
}
