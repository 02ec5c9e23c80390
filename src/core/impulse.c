/* impulse.c: contacts answered together (impulse.h).
 *
 * Row k's effect on row j: for each mobile body X in both, with sign s (+1 when X
 * is the row's p, -1 when its q) and arm r from X's centre of mass to the point,
 *   A[j][k] += s_j s_k (n_j . n_k / m_X + (r_j x n_j) . I_X^-1 (r_k x n_k)).
 * The problem: find lambda >= 0 with A lambda + (1 + e) u >= 0, complementary.
 */
#include "impulse.h"

#include <assert.h>
#include <math.h>

#include "lcp.h"

/* Velocity of body b's material point at world point x (zero for a still body:
 * the caller's states say so). */
static vec3 point_velocity(const body *b, vec3 x)
{
    return v3_add(b->v, v3_cross(b->w, v3_sub(x, body_com(b))));
}

double impulse_speed(const impulse_row *r, body *const *bs)
{
    vec3 rel = v3_sub(point_velocity(bs[r->p], r->at), point_velocity(bs[r->q], r->at));
    return v3_dot(rel, r->n);
}

/* Row k's unit-impulse response of body X (sign s): linear velocity per unit
 * impulse, and angular velocity change. */
static void response(const body *x, double s, vec3 n, vec3 at, vec3 *dv, vec3 *dw)
{
    vec3 arm = v3_sub(at, body_com(x));
    *dv = v3_scale(n, s * x->inv_mass);
    *dw = body_inertia_inv_mulv(x, v3_scale(v3_cross(arm, n), s));
}

void impulse_matrix(const impulse_row *rows, int n, body *const *bs, const bool *mobile,
                    double *A)
{
    for (int j = 0; j < n * n; j++) A[j] = 0;
    for (int k = 0; k < n; k++) {
        const impulse_row *rk = &rows[k];
        for (int side = 0; side < 2; side++) {
            int x = side == 0 ? rk->p : rk->q;
            if (!mobile[x] || body_is_static(bs[x])) continue;
            vec3 dv, dw;
            response(bs[x], side == 0 ? 1 : -1, rk->n, rk->at, &dv, &dw);
            /* its effect on every row touching x */
            for (int j = 0; j < n; j++) {
                const impulse_row *rj = &rows[j];
                double sj = rj->p == x ? 1 : rj->q == x ? -1 : 0;
                if (sj == 0) continue;
                vec3 arm = v3_sub(rj->at, body_com(bs[x]));
                double du = v3_dot(dv, rj->n) + v3_dot(dw, v3_cross(arm, rj->n));
                A[j * n + k] += sj * du;
            }
        }
    }
    /* the matrix is symmetric; make it so to the bit */
    for (int j = 0; j < n; j++)
        for (int k = j + 1; k < n; k++) {
            double m = 0.5 * (A[j * n + k] + A[k * n + j]);
            A[j * n + k] = A[k * n + j] = m;
        }
}

void impulse_response(const impulse_row *rk, body *const *bs, const bool *mobile, vec3 resp[4])
{
    for (int side = 0; side < 2; side++) {
        int x = side == 0 ? rk->p : rk->q;
        resp[2 * side] = resp[2 * side + 1] = v3(0, 0, 0);
        if (mobile[x] && !body_is_static(bs[x]))
            response(bs[x], side == 0 ? 1 : -1, rk->n, rk->at, &resp[2 * side], &resp[2 * side + 1]);
    }
}

double impulse_effect(const impulse_row *rj, const impulse_row *rk, const vec3 resp[4], body *const *bs,
                      const bool *mobile)
{
    double a = 0; /* (impulse_matrix's sum, in its order) */
    for (int side = 0; side < 2; side++) {
        int x = side == 0 ? rk->p : rk->q;
        double sj = rj->p == x ? 1 : rj->q == x ? -1 : 0;
        if (!mobile[x] || body_is_static(bs[x]) || sj == 0) continue;
        vec3 arm = v3_sub(rj->at, body_com(bs[x]));
        a += sj * (v3_dot(resp[2 * side], rj->n) + v3_dot(resp[2 * side + 1], v3_cross(arm, rj->n)));
    }
    return a;
}

void impulse_apply(const impulse_row *rows, int n, body *const *bs, const bool *mobile,
                   const double *lambda)
{
    for (int k = 0; k < n; k++) {
        if (lambda[k] == 0 || !isfinite(lambda[k])) continue;
        const impulse_row *r = &rows[k];
        vec3 J = v3_scale(r->n, lambda[k]);
        for (int side = 0; side < 2; side++) {
            int x = side == 0 ? r->p : r->q;
            body *b = bs[x];
            if (!mobile[x] || body_is_static(b)) continue;
            vec3 Js = side == 0 ? J : v3_neg(J);
            b->v = v3_mad(b->v, Js, b->inv_mass);
            b->L = v3_add(b->L, v3_cross(v3_sub(r->at, body_com(b)), Js));
            body_update_w(b);
        }
    }
}

/* The frictionless problem of impulse_solve set up and solved into lambda (not
 * least-norm, not applied): 0, or -1.  A (n x n), q and w are the caller's room;
 * A is left in A. */
static int normal_lcp(const impulse_row *rows, int n, body *const *bs, const bool *mobile,
                      const double *u_before, double *lambda, lcp_work *work, double *A, double *q,
                      double *w)
{
    if (n <= 0) return -1;
    impulse_matrix(rows, n, bs, mobile, A);
    for (int k = 0; k < n; k++) q[k] = (1 + rows[k].e) * u_before[k];
    return lcp_solve(n, A, q, lambda, w, work) != 0 ? -1 : 0;
}

int impulse_solve_in(const impulse_row *rows, int n, body *const *bs, const bool *mobile,
                     const double *u_before, double *lambda, lcp_work *work, double *A, double *q,
                     double *w)
{
    if (normal_lcp(rows, n, bs, mobile, u_before, lambda, work, A, q, w) != 0) return -1;
    /* (beyond IMPULSE_MAX_ROWS, a crowd's hundreds of rows, the least-norm
     * sweeps would cost more than all the rest of its step; the motion is the
     * same without them, lcp.h, only the split among dependent rows is not) */
    if (n <= IMPULSE_MAX_ROWS) lcp_least_norm(n, A, q, lambda, work);
    impulse_apply(rows, n, bs, mobile, lambda);
    return 0;
}

int impulse_solve(const impulse_row *rows, int n, body *const *bs, const bool *mobile,
                  const double *u_before, double *lambda, lcp_work *work)
{
    double A[IMPULSE_MAX_ROWS * IMPULSE_MAX_ROWS], q[IMPULSE_MAX_ROWS], w[IMPULSE_MAX_ROWS];
    if (n > IMPULSE_MAX_ROWS) return -1;
    return impulse_solve_in(rows, n, bs, mobile, u_before, lambda, work, A, q, w);
}

int impulse_solvable(const impulse_row *rows, int n, body *const *bs, const bool *mobile,
                     const double *u_before, lcp_work *work)
{
    double A[IMPULSE_MAX_ROWS * IMPULSE_MAX_ROWS], q[IMPULSE_MAX_ROWS], lambda[IMPULSE_MAX_ROWS],
        w[IMPULSE_MAX_ROWS];
    if (n > IMPULSE_MAX_ROWS) return -1;
    return normal_lcp(rows, n, bs, mobile, u_before, lambda, work, A, q, w);
}
