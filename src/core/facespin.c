/* facespin.c: a flat body sliding and spinning on a face (facespin.h).
 *
 * The balance of pressure p = p0 + k . x over a region P is linear in (p0, k)
 * once P is fixed: with the moments of P (region_moments) and the integrals of
 * the unit slip s over it (region_slip: int s = s0, int s x^T = s1),
 *   p0 area + k . m1 = N,   p0 m1 + m2 k = h mu (p0 s0 + s1 k)
 * (int p x = -h F, F = -mu int p s).  Clipped, P is the part of the face where
 * p >= 0 by the last answer, until P no longer changes.
 */
#include "facespin.h"

#include <math.h>

#include "contact.h"
#include "friction.h"
#include "tolerance.h"

/* Rounds of the clipped pressure at most */
#define CLIP_ROUNDS 60

bool face_spin_init(face_spin *fs, const body *b, vec3 n, double mu, double gn, vec3 gt)
{
    fs->nrm = n;
    friction_basis(n, &fs->e1, &fs->e2);
    fs->n = contact_face_outline(b, n, fs->e1, fs->e2, fs->p, FACESPIN_MAX, &fs->h);
    if (fs->n < 3 || !(fs->h > 0)) return false;
    fs->moments = region_moments_of(fs->p, fs->n);
    fs->reach = 0;
    for (int k = 0; k < fs->n; k++) fs->reach = d_max(fs->reach, hypot(fs->p[k].x, fs->p[k].y));
    mat3 I = body_inertia_world(b);
    vec3 In = m3_mulv(I, n);
    fs->in = v3_dot(n, In);
    fs->mu = mu;
    fs->gn = gn;
    fs->mass = b->mass;
    fs->gt[0] = v3_dot(gt, fs->e1);
    fs->gt[1] = v3_dot(gt, fs->e2);
    /* n a principal axis: I n along n (to the rounding of a tessellation's
     * mass properties: the couple a spin w would need to keep it so, w^2 |I n
     * x n|, is then below 1e-5 of I w^2) */
    return fs->in > 0 && v3_len(v3_mad(In, n, -fs->in)) <= 1e-5 * fs->in;
}

/* Solves the 3 x 3 system A z = r: false when singular. */
static bool solve3(double A[3][3], const double r[3], double z[3])
{
    double c0 = A[1][1] * A[2][2] - A[1][2] * A[2][1], c1 = A[1][2] * A[2][0] - A[1][0] * A[2][2],
           c2 = A[1][0] * A[2][1] - A[1][1] * A[2][0];
    double det = A[0][0] * c0 + A[0][1] * c1 + A[0][2] * c2;
    if (!(det != 0) || !isfinite(det)) return false;
    for (int i = 0; i < 3; i++) {
        double M[3][3];
        for (int a = 0; a < 3; a++)
            for (int c = 0; c < 3; c++) M[a][c] = c == i ? r[a] : A[a][c];
        z[i] = (M[0][0] * (M[1][1] * M[2][2] - M[1][2] * M[2][1]) - M[0][1] * (M[1][0] * M[2][2] - M[1][2] * M[2][0]) +
                M[0][2] * (M[1][0] * M[2][1] - M[1][1] * M[2][0])) /
               det;
    }
    return true;
}

/* The balanced pressure over region P (n corners) for slip (v, w): z = (p0, k),
 * and the slip's integrals over P. */
static bool balance(const face_spin *fs, const region_pt *P, int n, const double v[2], double w, double z[3],
                    region_slip *sl)
{
    region_moments m = P == fs->p ? fs->moments : region_moments_of(P, n);
    *sl = region_slip_of(P, n, v, w, fs->reach);
    double hm = fs->h * fs->mu;
    double A[3][3] = {{m.area, m.m1[0], m.m1[1]},
                      {m.m1[0] - hm * sl->s0[0], m.m2[0][0] - hm * sl->s1[0][0], m.m2[0][1] - hm * sl->s1[0][1]},
                      {m.m1[1] - hm * sl->s0[1], m.m2[1][0] - hm * sl->s1[1][0], m.m2[1][1] - hm * sl->s1[1][1]}};
    double r[3] = {fs->mass * fs->gn, 0, 0};
    return m.area > 0 && solve3(A, r, z);
}

bool face_spin_accel(const face_spin *fs, double turn, const double v[2], double w, double a[2], double *dw)
{
    a[0] = a[1] = *dw = 0;
    double c = cos(turn), s = sin(turn);
    double vb[2] = {c * v[0] + s * v[1], -s * v[0] + c * v[1]}; /* in the body's own turn */
    if (vb[0] == 0 && vb[1] == 0 && w == 0) return true;
    region_pt P[FACESPIN_MAX + 1], Q[FACESPIN_MAX + 1];
    const region_pt *cur = fs->p;
    int n = fs->n;
    double z[3];
    region_slip sl;
    double full = fs->moments.area, tol = 1e-13 * fs->reach;
    bool done = false;
    for (int round = 0; round < CLIP_ROUNDS && !done; round++) {
        if (!balance(fs, cur, n, vb, w, z, &sl)) return false;
        int m = region_clip(fs->p, fs->n, z[0], z + 1, Q);
        if (m < 3 || !(region_moments_of(Q, m).area > 1e-9 * full)) return false; /* it tips */
        /* the same region as the last (within rounding): balanced */
        done = m == n;
        for (int k = 0; k < m && done; k++) done = fabs(Q[k].x - cur[k].x) <= tol && fabs(Q[k].y - cur[k].y) <= tol;
        for (int k = 0; k < m; k++) P[k] = Q[k];
        cur = P;
        n = m;
    }
    if (!done) return false;
    /* F = -mu (p0 s0 + s1 k), its couple -mu (p0 u0 + u1 . k) */
    double F[2], tau = -fs->mu * (z[0] * sl.u0 + sl.u1[0] * z[1] + sl.u1[1] * z[2]);
    for (int i = 0; i < 2; i++) F[i] = -fs->mu * (z[0] * sl.s0[i] + sl.s1[i][0] * z[1] + sl.s1[i][1] * z[2]);
    a[0] = (c * F[0] - s * F[1]) / fs->mass;
    a[1] = (s * F[0] + c * F[1]) / fs->mass;
    *dw = tau / fs->in;
    return isfinite(a[0]) && isfinite(a[1]) && isfinite(*dw);
}

/* y' for y = (x, y, turn, vx, vy, w): friction's and gravity's along the face */
static bool deriv(const face_spin *fs, const double y[6], double f[6])
{
    f[0] = y[3], f[1] = y[4], f[2] = y[5];
    if (!face_spin_accel(fs, y[2], y + 3, y[5], f + 3, f + 5)) return false;
    f[3] += fs->gt[0];
    f[4] += fs->gt[1];
    return true;
}

/* Where its integration ends at velocity v, spin w: where static friction
 * holds it (|gt| <= mu g_n), its slip and spin stopped together; else its spin
 * and its drift across the slope gone (it slides on down in closed form) */
static bool spin_done(const face_spin *fs, const double v[2], double w)
{
    double g = hypot(fs->gt[0], fs->gt[1]);
    if (g <= fs->mu * fs->gn) return hypot(v[0], v[1]) + fabs(w) * fs->reach < FACESPIN_STOP;
    double across = fabs(v[0] * fs->gt[1] - v[1] * fs->gt[0]) / g;
    return fabs(w) * fs->reach < FACESPIN_STOP && across < FACESPIN_STOP;
}

/* Dormand and Prince's RK5(4)7M (Hairer, Norsett and Wanner, "Solving Ordinary
 * Differential Equations I", II.5), with its dense output of order 4 */
static const double C2 = 1.0 / 5, C3 = 3.0 / 10, C4 = 4.0 / 5, C5 = 8.0 / 9;
static const double A21 = 1.0 / 5;
static const double A31 = 3.0 / 40, A32 = 9.0 / 40;
static const double A41 = 44.0 / 45, A42 = -56.0 / 15, A43 = 32.0 / 9;
static const double A51 = 19372.0 / 6561, A52 = -25360.0 / 2187, A53 = 64448.0 / 6561, A54 = -212.0 / 729;
static const double A61 = 9017.0 / 3168, A62 = -355.0 / 33, A63 = 46732.0 / 5247, A64 = 49.0 / 176,
                    A65 = -5103.0 / 18656;
static const double A71 = 35.0 / 384, A73 = 500.0 / 1113, A74 = 125.0 / 192, A75 = -2187.0 / 6784, A76 = 11.0 / 84;
static const double E1 = 71.0 / 57600, E3 = -71.0 / 16695, E4 = 71.0 / 1920, E5 = -17253.0 / 339200,
                    E6 = 22.0 / 525, E7 = -1.0 / 40;
static const double D1 = -12715105075.0 / 11282082432, D3 = 87487479700.0 / 32700410799,
                    D4 = -10690763975.0 / 1880347072, D5 = 701980252875.0 / 199316789632,
                    D6 = -1453857185.0 / 822651844, D7 = 69997945.0 / 29380423;

/* One trial step of length h from y0 (k1 = y0'): y1, k7 = y1', the error
 * estimate err; false when some stage found no balance. */
static bool trial(const face_spin *fs, const double y0[6], const double k1[6], double h, double y1[6],
                  double k[7][6], double err[6])
{
    double y[6];
    for (int i = 0; i < 6; i++) k[0][i] = k1[i];
    for (int i = 0; i < 6; i++) y[i] = y0[i] + h * A21 * k[0][i];
    if (!deriv(fs, y, k[1])) return false;
    for (int i = 0; i < 6; i++) y[i] = y0[i] + h * (A31 * k[0][i] + A32 * k[1][i]);
    if (!deriv(fs, y, k[2])) return false;
    for (int i = 0; i < 6; i++) y[i] = y0[i] + h * (A41 * k[0][i] + A42 * k[1][i] + A43 * k[2][i]);
    if (!deriv(fs, y, k[3])) return false;
    for (int i = 0; i < 6; i++) y[i] = y0[i] + h * (A51 * k[0][i] + A52 * k[1][i] + A53 * k[2][i] + A54 * k[3][i]);
    if (!deriv(fs, y, k[4])) return false;
    for (int i = 0; i < 6; i++)
        y[i] = y0[i] + h * (A61 * k[0][i] + A62 * k[1][i] + A63 * k[2][i] + A64 * k[3][i] + A65 * k[4][i]);
    if (!deriv(fs, y, k[5])) return false;
    for (int i = 0; i < 6; i++)
        y1[i] = y0[i] + h * (A71 * k[0][i] + A73 * k[2][i] + A74 * k[3][i] + A75 * k[4][i] + A76 * k[5][i]);
    if (!deriv(fs, y1, k[6])) return false;
    for (int i = 0; i < 6; i++)
        err[i] = h * (E1 * k[0][i] + E3 * k[2][i] + E4 * k[3][i] + E5 * k[4][i] + E6 * k[5][i] + E7 * k[6][i]);
    (void)C2, (void)C3, (void)C4, (void)C5; /* (the field does not depend on time) */
    return true;
}

bool face_spin_step(const face_spin *fs, const double v[2], double w, double hmax, face_step *out)
{
    double R = fs->reach, u0 = hypot(v[0], v[1]) + fabs(w) * R;
    double y0[6] = {0, 0, 0, v[0], v[1], w}, k1[6];
    for (int i = 0; i < 5; i++)
        for (int j = 0; j < 6; j++) out->r[i][j] = i == 0 ? y0[j] : 0;
    out->h = 0;
    out->more = out->tips = false;
    out->slides = hypot(fs->gt[0], fs->gt[1]) > fs->mu * fs->gn;
    if (spin_done(fs, v, w)) return true; /* (stopped, or sliding on) */
    if (!deriv(fs, y0, k1)) return false;
    /* no step goes past the stop: |v| + |w| R falls at mu g_n (1 + m R^2 / I)
     * + |gt| at most, to zero in t_min at the least; the first trial is a
     * sixth of that (about what 1e-9 allows, by the boxes and discs tried) */
    double fall = fs->mu * fs->gn * (1 + fs->mass * R * R / fs->in) + hypot(fs->gt[0], fs->gt[1]);
    double t_min = u0 / fall, least = 1e-9 * t_min;
    double h = t_min / 6;
    if (hmax > 0) h = d_min(h, hmax);
    double k[7][6], y1[6], err[6];
    /* (a step that shrinks to nothing meets the edge of the pressures that
     * balance: it tips there) */
    for (int tries = 0; tries < 60 && h >= least; tries++) {
        if (!trial(fs, y0, k1, h, y1, k, err)) {
            h *= 0.5;
            continue;
        }
        /* 1e-9 relative to the motion's size u0: its speeds, and what they
         * move it in h */
        double sc[6] = {u0 * h, u0 * h, u0 * h / R, u0, u0, u0 / R}, e = 0;
        for (int i = 0; i < 6; i++) e = d_max(e, fabs(err[i]) / (1e-9 * sc[i]));
        if (e <= 1) {
            out->h = h;
            for (int i = 0; i < 6; i++) {
                double dy = y1[i] - y0[i], b = h * k[0][i] - dy;
                out->r[1][i] = dy;
                out->r[2][i] = b;
                out->r[3][i] = dy - h * k[6][i] - b;
                out->r[4][i] = h * (D1 * k[0][i] + D3 * k[2][i] + D4 * k[3][i] + D5 * k[4][i] + D6 * k[5][i] +
                                    D7 * k[6][i]);
            }
            out->more = !spin_done(fs, y1 + 3, y1[5]);
            return true;
        }
        h *= d_max(0.1, 0.8 * pow(e, -0.2));
    }
    return false;
}
