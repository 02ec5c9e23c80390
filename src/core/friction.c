/* friction.c: Coulomb friction and rolling resistance where objects press
 * (friction.h).
 *
 * The single point's integration (Mirtich 1996, 4.2; Stronge, "Rigid body
 * collisions with friction", 1990) works in the contact's frame (n, t1, t2): u
 * the relative velocity of the point there, K the 3 x 3 matrix of its three rows,
 * so that an impulse P changes u by K P.  With the normal impulse p_n as the
 * parameter, u' = K (1, -mu s) while the point slips along s = u_t / |u_t|, and
 * u' = K (1, t*) while it sticks, t* = -K_tt^-1 K_tn (so that u_t' = 0), which it
 * does while |t*| <= mu.  Where |t*| > mu it slides again, along the direction s
 * in which the slip grows: (K (1, -mu s))_t parallel to s.  The normal work W =
 * int u_n dp_n is W_c when u_n reaches 0 (the end of compression); restitution
 * ends where W = (1 - e^2) W_c.  Within a stretch of constant slope u is linear
 * in p_n and W quadratic, so the stretch's ends (slip stopping, u_n = 0, W at its
 * target) are roots found exactly; a slip that turns (a point off the planes of
 * symmetry) is followed in short stretches, each with its slope taken at its
 * middle.
 */
#include "friction.h"

#include <math.h>
#include <string.h>

#include "contact.h"
#include "facespin.h"
#include "grow.h"
#include "tolerance.h"

/* Stretches of a turning slip in one impact (each at most 1/64 of the impulse's
 * scale), and stretches in all, at most. */
#define IMPACT_STRETCHES 64
#define IMPACT_MAX_STRETCHES 20000

double friction_mu(const body *a, const body *b)
{
    return sqrt(a->friction * b->friction);
}

double friction_rolling(const body *a, const body *b)
{
    return sqrt(a->rolling_friction * b->rolling_friction);
}

bool friction_ball(const body *b)
{
    vec3 com = b->shape.mass.com;
    return b->sp.kind == SHAPE_SPHERE && com.x == 0 && com.y == 0 && com.z == 0;
}

/* A ball's motion on a face (friction_face) while it slips along unit sl, at
 * |slip| (0: it starts to): its centre's acceleration, its spin's about n x sl,
 * and when the slip stops growing smaller; MODE_GENERAL where the force along
 * the face is not along sl, or the slip cannot start along sl. */
static face_motion ball_slides(vec3 gt, double gn, double mu, double k, double r, vec3 n, vec3 sl,
                               double slip, double round)
{
    face_motion m = {.mode = MODE_SLIDE, .a = v3_mad(gt, sl, -mu * gn), .axis = v3_cross(n, sl),
                     .dw = mu * gn / (k * r), .t_stop = HUGE_VAL};
    double ds = v3_dot(gt, sl) - mu * gn * (1 + 1 / k);
    if (v3_len(v3_cross(gt, sl)) > round || (slip == 0 && ds < 0)) m.mode = MODE_GENERAL;
    else if (ds < 0) m.t_stop = slip / -ds;
    return m;
}

/* A box sliding and spinning on a face (facespin.h), pulled along it at gt: its mode, and
 * (hmax >= 0) its step, at most hmax long (0: any; where none can be taken,
 * tips is set and t_stop is 0); the centre of pressure's lean as
 * friction_face's. */
static face_motion face_spins(const body *b, vec3 n, double mu, double gn, vec3 gt, vec3 v, double hmax,
                              vec3 *lean)
{
    face_motion m = {.mode = MODE_GENERAL, .a = v3(0, 0, 0), .axis = n, .t_stop = HUGE_VAL};
    face_spin fs;
    if (!face_spin_init(&fs, b, n, mu, gn, gt)) return m;
    double vp[2] = {v3_dot(v, fs.e1), v3_dot(v, fs.e2)}, w = v3_dot(b->w, n), a[2], dw;
    if (!face_spin_accel(&fs, 0, vp, w, a, &dw)) return m; /* it tips */
    /* the centre of pressure: h lean, lean = -F / N (F friction's alone:
     * gravity acts at the centre of mass) */
    *lean = v3_scale(v3_add(v3_scale(fs.e1, a[0]), v3_scale(fs.e2, a[1])), -1 / gn);
    m.mode = MODE_SLIDE;
    m.spins = true;
    if (hmax < 0) return m;
    /* (a step that cannot be taken ends at once: it tips there) */
    m.step.tips = !face_spin_step(&fs, vp, w, hmax, &m.step);
    m.t_stop = m.step.tips ? 0 : m.step.h;
    m.a = v3(0, 0, 0);
    if (m.step.h > 0) {
        /* (the mean acceleration over the step: the parabola that the
         * schedule bounds its path by) */
        double ax = m.step.r[1][3] / m.step.h, ay = m.step.r[1][4] / m.step.h;
        m.a = v3_add(v3_scale(fs.e1, ax), v3_scale(fs.e2, ay));
    }
    return m;
}

face_motion friction_face(const body *b, const body *s, vec3 g, vec3 n, body_mode want, double hmax, vec3 *lean)
{
    face_motion m = {.mode = MODE_GENERAL, .a = v3(0, 0, 0), .axis = n, .t_stop = HUGE_VAL};
    double mu = friction_mu(b, s), c = friction_rolling(b, s), gn = -v3_dot(g, n);
    *lean = v3(0, 0, 0);
    if (!(mu > 0) || !(gn > 0) || !(b->mass > 0)) return m;
    double size = 1 + b->shape.r_out, round = SIM_ACCEL_ROUND * size;
    vec3 gt = v3_mad(g, n, gn);
    if (v3_len(gt) <= round) gt = v3(0, 0, 0); /* level */
    double gtl = v3_len(gt);
    vec3 v = v3_mad(b->v, n, -v3_dot(b->v, n));
    double vl = v3_len(v);
    if (!friction_ball(b)) {
        double wn = v3_dot(b->w, n);
        if (wn != 0) {
            /* spinning in place on a level face, on a face of its own that is
             * centrally symmetric about its centre of mass's foot: the
             * pressure is uniform, friction's force sums to zero and its
             * couple to mu g_n m arm, against the spin, until it stops */
            double arm = vl == 0 && gtl == 0 ? contact_face_arm(b, n) : -1;
            double in = v3_dot(n, m3_mulv(body_inertia_world(b), n));
            /* else sliding and spinning at once (or spinning on a face not so
             * symmetric, or on a slope): friction over the face */
            if (!(arm > 0)) return face_spins(b, n, mu, gn, gt, v, hmax, lean);
            if (!(arm > 0) || !(in > 0)) return m;
            m.mode = MODE_SLIDE;
            m.dw = -copysign(mu * gn * b->mass * arm / in, wn);
            m.t_stop = fabs(wn / m.dw);
            return m;
        }
        /* a box: its velocity's line, or from rest its pull's */
        if (vl == 0 && gtl <= mu * gn) {
            m.mode = MODE_STICK;
            *lean = v3_scale(gt, 1 / gn);
            return m;
        }
        vec3 dir = vl > 0 ? v3_scale(v, 1 / vl) : v3_scale(gt, 1 / gtl);
        if (v3_len(v3_cross(gt, dir)) > round) return m;
        m.mode = MODE_SLIDE;
        m.a = v3_mad(gt, dir, -mu * gn);
        *lean = v3_scale(dir, mu);
        double along = v3_dot(m.a, dir);
        if (want == MODE_SLIDE && vl == 0 && gtl <= mu * gn) m.t_stop = 0;
        else if (vl > 0 && along < 0) m.t_stop = vl / -along;
        return m;
    }
    double r = b->shape.r_out, k = b->I_princ.x / (b->mass * r * r);
    if (!(k > 0)) return m;
    vec3 slip = v3_sub(v, v3_scale(v3_cross(b->w, n), r));
    double sl = v3_len(slip);
    bool slips = sl > SIM_SPEED_ROUND * size;
    if (slips && want != MODE_ROLL)
        return ball_slides(gt, gn, mu, k, r, n, v3_scale(slip, 1 / sl), sl, round);
    /* not slipping: it rolls along its velocity, or from rest along its pull,
     * where friction holds it so (else it starts to slip, against the force
     * friction would need), and sticks where rolling resistance holds it */
    m.t_stop = 0; /* (the end at once of a mode asked for that does not hold) */
    m.mode = want == MODE_FREE ? MODE_STICK : want;
    if (vl == 0 && gtl <= c * gn && gtl <= mu * gn) return m;
    vec3 dir = vl > 0 ? v3_scale(v, 1 / vl) : v3_scale(gt, 1 / gtl);
    if (v3_len(v3_cross(gt, dir)) > round) {
        m.mode = MODE_GENERAL;
        return m;
    }
    vec3 a = v3_scale(v3_mad(gt, dir, -c * gn), 1 / (1 + k));
    vec3 need = v3_sub(a, gt); /* friction's force over the mass */
    if (v3_len(need) > mu * gn)
        return want == MODE_ROLL ? m : ball_slides(gt, gn, mu, k, r, n, v3_norm(v3_neg(need)), 0, round);
    if (want == MODE_SLIDE) return m;
    m.mode = MODE_ROLL;
    m.a = a;
    m.t_stop = HUGE_VAL;
    double along = v3_dot(a, dir);
    if (vl > 0 && along < 0) m.t_stop = vl / -along;
    return m;
}

bool friction_any(const impulse_row *rows, int n)
{
    for (int k = 0; k < n; k++)
        if (rows[k].mu > 0) return true;
    return false;
}

void friction_basis(vec3 n, vec3 *t1, vec3 *t2)
{
    /* the axis least along n, made square to it */
    vec3 a = fabs(n.x) <= fabs(n.y) && fabs(n.x) <= fabs(n.z) ? v3(1, 0, 0)
             : fabs(n.y) <= fabs(n.z)                         ? v3(0, 1, 0)
                                                              : v3(0, 0, 1);
    *t1 = v3_norm(v3_mad(a, n, -v3_dot(a, n)));
    *t2 = v3_cross(n, *t1);
}

void friction_rows(const impulse_row *rows, int m, impulse_row *out)
{
    for (int k = 0; k < m; k++) {
        vec3 t1, t2;
        friction_basis(rows[k].n, &t1, &t2);
        out[3 * k] = out[3 * k + 1] = out[3 * k + 2] = rows[k];
        out[3 * k + 1].n = t1;
        out[3 * k + 2].n = t2;
    }
}

double friction_energy(const impulse_row *rows, int m, body *const *bs, const bool *mobile)
{
    double ke = 0;
    for (int k = 0; k < m; k++)
        for (int side = 0; side < 2; side++) {
            int x = side == 0 ? rows[k].p : rows[k].q;
            if (!mobile[x] || body_is_static(bs[x])) continue;
            bool seen = false; /* (each body once) */
            for (int j = 0; j <= k && !seen; j++)
                seen = (j < k && (rows[j].p == x || rows[j].q == x)) || (j == k && side == 1 && rows[k].p == x);
            if (!seen) ke += body_energy(bs[x]);
        }
    return ke;
}

/* ---- the cone problem ---- */

/* 2-vectors for the tangent plane */
typedef struct {
    double x, y;
} v2;

static double v2_len(v2 a) { return sqrt(a.x * a.x + a.y * a.y); }

/* The 3 x 3 system B z = r (B symmetric positive definite): false when singular. */
static bool solve3(double B[3][3], const double r[3], double z[3])
{
    double c00 = B[1][1] * B[2][2] - B[1][2] * B[2][1], c01 = B[1][2] * B[2][0] - B[1][0] * B[2][2],
           c02 = B[1][0] * B[2][1] - B[1][1] * B[2][0];
    double det = B[0][0] * c00 + B[0][1] * c01 + B[0][2] * c02;
    double scale = fabs(B[0][0] * B[1][1] * B[2][2]);
    if (!(fabs(det) > 1e-14 * scale) || !isfinite(det)) return false;
    double inv[3][3] = {
        {c00, B[0][2] * B[2][1] - B[0][1] * B[2][2], B[0][1] * B[1][2] - B[0][2] * B[1][1]},
        {c01, B[0][0] * B[2][2] - B[0][2] * B[2][0], B[0][2] * B[1][0] - B[0][0] * B[1][2]},
        {c02, B[0][1] * B[2][0] - B[0][0] * B[2][1], B[0][0] * B[1][1] - B[0][1] * B[1][0]}};
    for (int i = 0; i < 3; i++) z[i] = (inv[i][0] * r[0] + inv[i][1] * r[1] + inv[i][2] * r[2]) / det;
    return true;
}

/* A sliding point of the local problem w = B z + b slides along a unit d with z
 * = zn (1, -mu d): wn = 0 gives zn = -b0 / den, den = B00 - mu B0t.d, and then
 * den wt = den bt - b0 (Bt0 - mu Btt d) must lie along +d.  Its sine with d,
 * times |den wt|, is G(d) = l.d + d.Q d (linear and quadratic in d): a
 * trigonometric polynomial of degree 2 in d's angle, with at most four roots. */
typedef struct {
    double l[2], Q[2][2];
    double b0, B00, g[2], bt[2], Bt0[2], Btt[2][2], mu;
} slide_fn;

static slide_fn slide_fn_of(double B[3][3], const double b[3], double mu)
{
    slide_fn f = {.b0 = b[0], .B00 = B[0][0], .g = {B[0][1], B[0][2]}, .bt = {b[1], b[2]},
                  .Bt0 = {B[1][0], B[2][0]}, .Btt = {{B[1][1], B[1][2]}, {B[2][1], B[2][2]}}, .mu = mu};
    /* den (d x bt) = B00 p.d - mu (g.d)(p.d), p = (bt2, -bt1); -b0 (d x Bt0) =
     * -b0 s.d, s = (Bt0_2, -Bt0_1); b0 mu (d x Btt d) = b0 mu d.R d */
    double p[2] = {b[2], -b[1]}, sv[2] = {B[2][0], -B[1][0]};
    double R[2][2] = {{B[2][1], B[2][2]}, {-B[1][1], -B[1][2]}};
    for (int i = 0; i < 2; i++) {
        f.l[i] = B[0][0] * p[i] - b[0] * sv[i];
        for (int j = 0; j < 2; j++) f.Q[i][j] = -mu * f.g[i] * p[j] + b[0] * mu * R[i][j];
    }
    return f;
}

/* G at d, and its derivative along the angle (d turned a quarter). */
static double slide_g(const slide_fn *f, v2 d, double *dg)
{
    double Qd[2] = {f->Q[0][0] * d.x + f->Q[0][1] * d.y, f->Q[1][0] * d.x + f->Q[1][1] * d.y};
    double Qtd[2] = {f->Q[0][0] * d.x + f->Q[1][0] * d.y, f->Q[0][1] * d.x + f->Q[1][1] * d.y};
    if (dg) {
        double gx = f->l[0] + Qd[0] + Qtd[0], gy = f->l[1] + Qd[1] + Qtd[1];
        *dg = -gx * d.y + gy * d.x;
    }
    return f->l[0] * d.x + f->l[1] * d.y + d.x * Qd[0] + d.y * Qd[1];
}

/* True when sliding along d is an answer's direction: zn > 0 and wt ahead of d
 * (not against it); *zn written. */
static bool slide_ok(const slide_fn *f, v2 d, double *zn)
{
    double den = f->B00 - f->mu * (f->g[0] * d.x + f->g[1] * d.y);
    if (!(den > 0)) return false;
    *zn = -f->b0 / den;
    double wx = f->bt[0] + *zn * (f->Bt0[0] - f->mu * (f->Btt[0][0] * d.x + f->Btt[0][1] * d.y));
    double wy = f->bt[1] + *zn * (f->Bt0[1] - f->mu * (f->Btt[1][0] * d.x + f->Btt[1][1] * d.y));
    return *zn > 0 && wx * d.x + wy * d.y >= 0;
}

/* The root of G between angles lo and hi (G's signs differ there, glo at lo):
 * Newton's steps kept inside the bracket, else bisection. */
static double slide_root(const slide_fn *f, double lo, double hi, double glo)
{
    double t = 0.5 * (lo + hi);
    for (int it = 0; it < 100 && hi - lo > 1e-15 * (1 + fabs(t)); it++) {
        double dg, g = slide_g(f, (v2){cos(t), sin(t)}, &dg);
        if (g == 0) return t;
        if ((g < 0) == (glo < 0)) lo = t, glo = g;
        else hi = t;
        double nt = dg != 0 ? t - g / dg : lo;
        t = nt > lo && nt < hi ? nt : 0.5 * (lo + hi);
    }
    return t;
}

/* A sliding point's direction: the angle of the root of G nearest th0 at which
 * the point slides consistently (slide_ok), found by Newton's method from th0
 * (near the answer once the sweeps settle), else by a scan of the circle for
 * sign changes and a bracketed search.  False when there is none (no
 * consistent sliding answer). */
static bool slide_dir(double B[3][3], const double b[3], double mu, double th0, double *th,
                      double *zn)
{
    slide_fn f = slide_fn_of(B, b, mu);
    double scale = fabs(f.l[0]) + fabs(f.l[1]) + fabs(f.Q[0][0]) + fabs(f.Q[0][1]) +
                   fabs(f.Q[1][0]) + fabs(f.Q[1][1]);
    if (!(scale > 0) || !isfinite(scale)) return false;
    double t = th0;
    for (int it = 0; it < 8; it++) {
        double dg, g = slide_g(&f, (v2){cos(t), sin(t)}, &dg);
        if (fabs(g) <= 1e-15 * scale) {
            if (slide_ok(&f, (v2){cos(t), sin(t)}, zn) && fabs(remainder(t - th0, 2 * M_PI)) < 0.5) {
                *th = t;
                return true;
            }
            break;
        }
        if (!(dg != 0)) break;
        double step = g / dg;
        if (fabs(step) > 0.5) break;
        t -= step;
    }
    /* the scan: 32 directions turned from th0 by a rotation (its rounding is
     * far below what the bracket needs) */
    enum { SCAN = 32 };
    double c = cos(2 * M_PI / SCAN), s = sin(2 * M_PI / SCAN), best = HUGE_VAL;
    v2 d = {cos(th0), sin(th0)};
    double prev = slide_g(&f, d, NULL);
    bool found = false;
    for (int k = 1; k <= SCAN; k++) {
        v2 dk = {c * d.x - s * d.y, s * d.x + c * d.y};
        double l = v2_len(dk);
        dk.x /= l, dk.y /= l;
        double gk = slide_g(&f, dk, NULL);
        if ((prev <= 0) != (gk <= 0)) {
            double lo = th0 + 2 * M_PI * (k - 1) / SCAN, hi = th0 + 2 * M_PI * k / SCAN;
            double tm = slide_root(&f, lo, hi, prev), zm;
            double off = fabs(remainder(tm - th0, 2 * M_PI));
            if (off < best && slide_ok(&f, (v2){cos(tm), sin(tm)}, &zm)) best = off, *th = tm, *zn = zm, found = true;
        }
        d = dk;
        prev = gk;
    }
    return found;
}

/* Point k's own problem: w = B z + b, z in the cone of mu.  z written (on entry:
 * the last answer, whose slip direction starts the search); true when it has a
 * consistent answer.  (Inlined into both sweeps, the dense and the crowd's, as
 * it was into the dense one's alone: called, it cost Bounce's first 100 frames
 * 0.2% more instructions.) */
static inline bool local_solve(double B[3][3], const double b[3], double mu, double z[3])
    __attribute__((always_inline));

static inline bool local_solve(double B[3][3], const double b[3], double mu, double z[3])
{
    double last1 = z[1], last2 = z[2];
    z[0] = z[1] = z[2] = 0;
    if (b[0] >= 0) return true; /* apart (or just touching): no push */
    if (mu == 0 || !(B[1][1] > 0) || !(B[2][2] > 0)) {
        if (B[0][0] > 0) z[0] = -b[0] / B[0][0];
        return B[0][0] > 0;
    }
    double r[3] = {-b[0], -b[1], -b[2]};
    if (solve3(B, r, z) && z[0] > 0 && sqrt(z[1] * z[1] + z[2] * z[2]) <= mu * z[0]) return true; /* sticks */
    /* slides: against the direction it would stick with */
    double th0 = atan2(-z[2], -z[1]), th, zn;
    if (last1 != 0 || last2 != 0) th0 = atan2(-last2, -last1);
    else if (!(z[1] != 0 || z[2] != 0)) th0 = atan2(b[2], b[1]);
    if (slide_dir(B, b, mu, th0, &th, &zn)) {
        z[0] = zn;
        z[1] = -mu * zn * cos(th);
        z[2] = -mu * zn * sin(th);
        return true;
    }
    /* none: frictionless at this point (Painleve) */
    z[1] = z[2] = 0;
    z[0] = B[0][0] > 0 ? -b[0] / B[0][0] : 0;
    return false;
}

static void swap(double *a, double *b)
{
    double t = *a;
    *a = *b, *b = t;
}

/* The square system M x = r (k x k, row-major, overwritten) by Gaussian
 * elimination with full pivoting; an unknown whose pivot is below 1e-13 of the
 * largest is 0 (the system is then singular: points given twice).  Returns the
 * rank found.  Each elimination step also finds the next pivot (the first
 * largest entry, row by row, of what is left), so that the matrix is read once
 * a step. */
static int solve_full(int k, double *M, double *r, double *x)
{
    int perm[3 * FRICTION_MAX_POINTS], rank = k;
    for (int i = 0; i < k; i++) perm[i] = i;
    int pr = 0, pc = 0;
    double best = -1;
    for (int i = 0; i < k; i++)
        for (int j = 0; j < k; j++)
            if (fabs(M[i * k + j]) > best) best = fabs(M[i * k + j]), pr = i, pc = j;
    double big = d_max(best, 0);
    for (int c = 0; c < k; c++) {
        if (!(best > 1e-13 * big)) {
            rank = c;
            break;
        }
        if (pr != c) {
            for (int j = 0; j < k; j++) swap(&M[c * k + j], &M[pr * k + j]);
            swap(&r[c], &r[pr]);
        }
        if (pc != c) {
            for (int i = 0; i < k; i++) swap(&M[i * k + c], &M[i * k + pc]);
            int t = perm[c];
            perm[c] = perm[pc], perm[pc] = t;
        }
        best = -1, pr = pc = c + 1;
        for (int i = c + 1; i < k; i++) {
            double *Mi = &M[i * k];
            double f = Mi[c] / M[c * k + c];
            if (f != 0) {
                Mi[c] -= f * M[c * k + c];
                for (int j = c + 1; j < k; j++) {
                    Mi[j] -= f * M[c * k + j];
                    if (fabs(Mi[j]) > best) best = fabs(Mi[j]), pr = i, pc = j;
                }
                r[i] -= f * r[c];
            } else {
                for (int j = c + 1; j < k; j++)
                    if (fabs(Mi[j]) > best) best = fabs(Mi[j]), pr = i, pc = j;
            }
        }
    }
    double y[3 * FRICTION_MAX_POINTS];
    for (int i = k - 1; i >= 0; i--) {
        if (i >= rank) {
            y[i] = 0;
            continue;
        }
        double s = r[i];
        for (int j = i + 1; j < rank; j++) s -= M[i * k + j] * y[j];
        y[i] = s / M[i * k + i];
    }
    for (int i = 0; i < k; i++) x[perm[i]] = y[i];
    return rank;
}

/* Sweeps crawl when w changes by less than this many times the tolerance in a
 * sweep (points given twice, or nearly: a face's corners, an edge's ends). */
#define FRICTION_STALL 1e3

/* Where a pattern's system is singular, the polish's answer (its basic
 * solution, the inconsistency left in the equations it drops) may leave up to
 * this many times what the sweeps' answer leaves (their own share of it). */
#define POLISH_SLACK 4

/* Rounds of a polish, at most (but its early try: friction_cone_solve). */
#define POLISH_ROUNDS 20

/* After a polish fails (mostly: its rounds spent turning slips, and swapping
 * points between sticking and sliding, that the sweeps have not yet settled),
 * the next is tried only once the sweeps' change is this many times smaller
 * than when it failed.  Each round solves its pattern afresh, cubic in the
 * points; in a closed box of 50 rough objects (issue 35) most polishes failed
 * after all 20 rounds, one every tenth sweep, and the polishes did 15 times
 * the sweeps' work. */
#define POLISH_PROGRESS 0.1

/* The polishes of one solve do at most this many times the work of all its
 * sweeps, counted as a round's nu^3 (its elimination) against a sweep's n^2
 * (three columns of A a point): a round of 60 points all sticking costs some
 * 60 sweeps.  Small problems keep all their rounds (3 points: 33 rounds of 9
 * unknowns), large ones a few. */
#define POLISH_WORK 1

/* Polishes z (the sweeps' answer, nearly right) to the exact answer of its
 * pattern: points apart stay 0, points that stick get w_k = 0, points that slide
 * get wn = 0 with zt along their slip (the slips found again, a few times).
 * True, with z and w written, when within `rounds` rounds the answer holds
 * within tol (or within what the sweeps' answer leaves: where the pattern's
 * system is singular, and for the gaps of points apart when the sweeps are
 * stalled); else nothing changed.  Each round takes its nu^3 from *work, and
 * none is begun that *work cannot pay for. */
static bool polish(int m, const double *A, const double *q, const double *mu, double *z, double *w,
                   double tol, bool stalled, int rounds, double *work)
{
    int n = 3 * m, col[3 * FRICTION_MAX_POINTS], nu = 0;
    enum { APART, STICK, SLIDE } kind[FRICTION_MAX_POINTS];
    double dx[FRICTION_MAX_POINTS], dy[FRICTION_MAX_POINTS];
    for (int k = 0; k < m; k++) {
        double zn = z[3 * k], zt = sqrt(z[3 * k + 1] * z[3 * k + 1] + z[3 * k + 2] * z[3 * k + 2]);
        if (!(zn > 0)) kind[k] = APART;
        else if (mu[k] == 0 || zt < mu[k] * zn * (1 - 1e-6)) kind[k] = STICK;
        else kind[k] = SLIDE, dx[k] = -z[3 * k + 1] / zt, dy[k] = -z[3 * k + 2] / zt;
        if (kind[k] == STICK && mu[k] == 0) kind[k] = SLIDE, dx[k] = 1, dy[k] = 0;
    }
    /* what the sweeps' answer leaves of the pattern's equations (w = 0 where a
     * point sticks, wn = 0 where it slides): where the pattern's system is
     * singular (two points of one object side by side, whose slips along the
     * line between them are one, measured at two places), no answer of the
     * pattern leaves less than its inconsistency, and the polish's answer is
     * kept when it leaves about as little as the sweeps' (POLISH_SLACK) */
    double left = 0;
    for (int k = 0; k < m; k++) {
        if (kind[k] == STICK)
            for (int j = 0; j < 3; j++) left = d_max(left, fabs(w[3 * k + j]));
        else if (kind[k] == SLIDE) left = d_max(left, fabs(w[3 * k]));
        else left = d_max(left, -w[3 * k]);
    }
    /* (and where the sweeps crawl, an answer whose gaps close no faster than
     * the sweeps' do is as good as theirs will be) */
    double tol_gap = stalled ? d_max(tol, left) : tol;
    /* (the one large array: static, since the core runs one frame at a time) */
    static double M[9 * FRICTION_MAX_POINTS * FRICTION_MAX_POINTS];
    double zz[3 * FRICTION_MAX_POINTS], ww[3 * FRICTION_MAX_POINTS], r[3 * FRICTION_MAX_POINTS],
        x[3 * FRICTION_MAX_POINTS];
    double xs[3 * FRICTION_MAX_POINTS];
    for (int i = 0; i < n; i++) xs[i] = z[i];
    for (int round = 0; round < rounds; round++) {
        /* the unknowns: rows of A they stand for (a sliding point's zn stands for
         * its column less mu times its slip's) */
        nu = 0;
        for (int k = 0; k < m; k++) {
            if (kind[k] == STICK) col[nu++] = 3 * k, col[nu++] = 3 * k + 1, col[nu++] = 3 * k + 2;
            else if (kind[k] == SLIDE) col[nu++] = 3 * k;
        }
        if (nu == 0) return false;
        double cost = (double)nu * nu * nu;
        if (cost > *work) return false;
        *work -= cost;
        for (int i = 0; i < nu; i++) {
            int ri = col[i];
            r[i] = -q[ri];
            for (int j = 0; j < nu; j++) {
                int cj = col[j], kj = cj / 3;
                double a = A[ri * n + cj];
                if (kind[kj] == SLIDE)
                    a -= mu[kj] * (dx[kj] * A[ri * n + cj + 1] + dy[kj] * A[ri * n + cj + 2]);
                M[i * nu + j] = a;
            }
        }
        /* (solved for the change from the sweeps' answer, so that where the
         * points are more than the constraints, four corners of a face, the
         * impulses keep the sweeps' share among them, inside the cones, and
         * the change is small) */
        for (int i = 0; i < nu; i++)
            for (int j = 0; j < nu; j++) r[i] -= M[i * nu + j] * xs[col[j]];
        double tol_eq = solve_full(nu, M, r, x) < nu ? d_max(tol, POLISH_SLACK * left) : tol;
        for (int j = 0; j < nu; j++) x[j] += xs[col[j]];
        for (int j = 0; j < nu; j++) xs[col[j]] = x[j];
        for (int i = 0; i < n; i++) zz[i] = 0;
        for (int j = 0; j < nu; j++) {
            int cj = col[j], kj = cj / 3;
            zz[cj] = x[j];
            if (kind[kj] == SLIDE) zz[cj + 1] = -mu[kj] * dx[kj] * x[j], zz[cj + 2] = -mu[kj] * dy[kj] * x[j];
        }
        for (int i = 0; i < n; i++) {
            double s = q[i];
            for (int j = 0; j < n; j++) s += A[i * n + j] * zz[j];
            ww[i] = s;
        }
        /* does it hold?  Where a point's pattern is wrong (an impulse that
         * pulls, a gap that closes, a sticking impulse outside its cone, a slip
         * that reverses), the point takes the pattern the answer shows and the
         * round is solved again (an active set's step); a residual left where
         * the pattern holds fails */
        bool ok = true, turn = false;
        for (int k = 0; k < m && ok; k++) {
            double zn = zz[3 * k], wn = ww[3 * k], wx = ww[3 * k + 1], wy = ww[3 * k + 2];
            double zt = sqrt(zz[3 * k + 1] * zz[3 * k + 1] + zz[3 * k + 2] * zz[3 * k + 2]);
            if (kind[k] != APART && zn < 0) {
                kind[k] = APART, turn = true;
                for (int j = 0; j < 3; j++) xs[3 * k + j] = 0;
            } else if (kind[k] == APART) {
                if (wn < -tol_gap) kind[k] = mu[k] > 0 ? STICK : SLIDE, dx[k] = 1, dy[k] = 0, turn = true;
            } else if (kind[k] == STICK) {
                ok = fabs(wn) <= tol_eq && fabs(wx) <= tol_eq && fabs(wy) <= tol_eq;
                if (ok && zt > mu[k] * zn * (1 + 1e-12))
                    kind[k] = SLIDE, dx[k] = -zz[3 * k + 1] / zt, dy[k] = -zz[3 * k + 2] / zt, turn = true;
            } else if (mu[k] > 0) {
                double along = wx * dx[k] + wy * dy[k], off = fabs(wx * dy[k] - wy * dx[k]);
                ok = fabs(wn) <= tol_eq;
                if (ok && along < -tol) {
                    kind[k] = STICK, turn = true;
                    xs[3 * k + 1] = zz[3 * k + 1], xs[3 * k + 2] = zz[3 * k + 2];
                } else if (ok && off > tol) {
                    double l = sqrt(wx * wx + wy * wy);
                    if (!(l > 0)) ok = false;
                    else dx[k] = wx / l, dy[k] = wy / l, turn = true;
                }
            } else {
                ok = fabs(wn) <= tol_eq;
            }
        }
        if (!ok) return false;
        if (!turn) {
            for (int i = 0; i < n; i++) z[i] = zz[i], w[i] = ww[i];
            return true;
        }
    }
    return false;
}

/* friction_cone_solve, its sweeps stopping once their change is no more than
 * loose (a speed), where that is above FRICTION_TOL's. */
static int cone_solve(int m, const double *A, const double *q, const double *mu, double *z, double *w,
                      double loose, bool *painleve)
{
    int n = 3 * m;
    for (int i = 0; i < n; i++)
        if (!isfinite(q[i]) || !isfinite(z[i])) {
            for (int k = 0; k < n; k++) z[k] = 0, w[k] = q[k];
            return -1;
        }
    for (int i = 0; i < n * n; i++)
        if (!isfinite(A[i])) {
            for (int k = 0; k < n; k++) z[k] = 0, w[k] = q[k];
            return -1;
        }
    /* w from the first guess */
    for (int i = 0; i < n; i++) {
        double s = q[i];
        for (int j = 0; j < n; j++) s += A[i * n + j] * z[j];
        w[i] = s;
    }
    int status = 1;
    bool jam = false;
    /* the change at which a polish last failed: the next is tried only once
     * the sweeps have brought it POLISH_PROGRESS times lower */
    double failed_at = HUGE_VAL;
    /* the polishes' work, at most: POLISH_WORK times the sweeps' at most
     * (a round's elimination costs about the cube of its unknowns, a sweep
     * the square of the rows) */
    double work = POLISH_WORK * FRICTION_SWEEPS * (double)n * n;
    /* the scale of the velocities: q's, and A's diagonal times the impulses */
    double qs = 0, diag = 0, w0[3 * FRICTION_MAX_POINTS];
    for (int i = 0; i < n; i++) qs = d_max(qs, fabs(q[i])), diag = d_max(diag, A[i * n + i]);
    for (int sweep = 0; sweep < FRICTION_SWEEPS; sweep++) {
        double change = 0, size = 0;
        jam = false;
        /* (the velocities w are what converge: the impulses z need not, where
         * points are more than the constraints, a box's four corners) */
        for (int i = 0; i < n; i++) w0[i] = w[i];
        for (int k = 0; k < m; k++) {
            int o = 3 * k;
            double B[3][3], b[3], zk[3] = {z[o], z[o + 1], z[o + 2]};
            for (int i = 0; i < 3; i++) {
                for (int j = 0; j < 3; j++) B[i][j] = A[(o + i) * n + o + j];
                b[i] = w[o + i] - (B[i][0] * z[o] + B[i][1] * z[o + 1] + B[i][2] * z[o + 2]);
            }
            if (!local_solve(B, b, mu[k], zk)) jam = true;
            for (int j = 0; j < 3; j++) {
                double dz = zk[j] - z[o + j];
                if (dz == 0) continue;
                for (int i = 0; i < n; i++) w[i] += A[i * n + o + j] * dz;
                z[o + j] = zk[j];
            }
            size = d_max(size, fabs(zk[0]) + sqrt(zk[1] * zk[1] + zk[2] * zk[2]));
        }
        for (int i = 0; i < n; i++) change = d_max(change, fabs(w[i] - w0[i]));
        double tol = d_max(FRICTION_TOL * (qs + diag * size), loose);
        /* the polish after every tenth sweep, and once early: after the second
         * sweep its first round alone, which holds where the sweeps have found
         * the pattern (mostly so in the clusters' Newton steps, started from
         * the last kicks) and costs little where they have not.  First 100
         * frames, instructions a solve: Computer Desks 42k (69k with the
         * tenth sweeps' only), Bounce 83k (81k); with all its rounds after
         * the second sweep, 39k and 103k. */
        bool early = sweep == 1;
        bool due = early || (sweep % 10 == 9 && change < POLISH_PROGRESS * failed_at);
        if (change > tol && due) {
            bool stalled = change < FRICTION_STALL * tol;
            if (polish(m, A, q, mu, z, w, tol, stalled, early ? 1 : POLISH_ROUNDS, &work))
                change = 0;
            else if (!early)
                failed_at = change;
        }
        if (change <= tol) {
            status = 0;
            break;
        }
    }
    /* w afresh, summed in order */
    for (int i = 0; i < n; i++) {
        double s = q[i];
        for (int j = 0; j < n; j++) s += A[i * n + j] * z[j];
        w[i] = s;
    }
    if (painleve && jam) *painleve = true;
    return status;
}

int friction_cone_solve(int m, const double *A, const double *q, const double *mu, double *z,
                        double *w, bool *painleve)
{
    return cone_solve(m, A, q, mu, z, w, 0, painleve);
}

/* ---- crowds: the cone problem in blocks, past FRICTION_MAX_POINTS ---- */

/* Room in c for m points, and its bodies' lists for bodies below nbody: 0, or -1
 * when out of memory (c keeps what it had, and its room says so). */
static int crowd_room(friction_crowd *c, int m, int nbody)
{
    bool ok = true;
    if (m > c->cap) {
        long n = grow_doubled(m, c->cap);
        c->rows = grow_resized(c->rows, sizeof *c->rows, 3 * n, &ok);
        c->q = grow_resized(c->q, sizeof *c->q, 3 * n, &ok);
        c->z = grow_resized(c->z, sizeof *c->z, 3 * n, &ok);
        c->w = grow_resized(c->w, sizeof *c->w, 3 * n, &ok);
        c->w0 = grow_resized(c->w0, sizeof *c->w0, 3 * n, &ok);
        c->mu = grow_resized(c->mu, sizeof *c->mu, n, &ok);
        c->start = grow_resized(c->start, sizeof *c->start, n + 1, &ok);
        c->mark = grow_resized(c->mark, sizeof *c->mark, n, &ok);
        c->link = grow_resized(c->link, sizeof *c->link, 2 * n, &ok);
        c->resp = grow_resized(c->resp, sizeof *c->resp, 12 * n, &ok);
        if (ok) c->cap = (int)n;
    }
    if (ok && nbody > c->cap_bodies) {
        long n = grow_doubled(nbody, c->cap_bodies);
        c->head = grow_resized(c->head, sizeof *c->head, n, &ok);
        if (ok) c->cap_bodies = (int)n;
    }
    return ok ? 0 : -1;
}

void friction_work_free(friction_work *fw)
{
    friction_crowd *c = &fw->crowd;
    free(c->rows);
    free(c->q);
    free(c->z);
    free(c->w);
    free(c->w0);
    free(c->mu);
    free(c->start);
    free(c->col);
    free(c->B);
    free(c->mark);
    free(c->link);
    free(c->head);
    free(c->resp);
    *c = (friction_crowd){0};
}

friction_problem friction_problem_of(friction_work *fw, int m)
{
    if (m <= FRICTION_MAX_POINTS) return (friction_problem){fw->rows, fw->q, fw->z, fw->w, fw->mu};
    friction_crowd *c = &fw->crowd;
    return (friction_problem){c->rows, c->q, c->z, c->w, c->mu};
}

impulse_row *friction_rows_in(friction_work *fw, const impulse_row *rows, int m)
{
    if (m > FRICTION_MAX_POINTS && crowd_room(&fw->crowd, m, 0) != 0) return NULL;
    impulse_row *out = friction_problem_of(fw, m).rows;
    friction_rows(rows, m, out);
    return out;
}

/* Whether body x of a row takes its impulses. */
static bool moves(int x, body *const *bs, const bool *mobile)
{
    return mobile[x] && !body_is_static(bs[x]);
}

/* Block (k, l) of the crowd, the nb-th, unless k has it already: with fill,
 * its point and entries written.  Returns the blocks then. */
static int crowd_block(friction_crowd *c, int k, int l, int nb, bool fill, body *const *bs,
                       const bool *mobile)
{
    if (c->mark[l] == k) return nb;
    c->mark[l] = k;
    if (!fill) return nb + 1;
    c->col[nb] = l;
    double *B = &c->B[9 * (size_t)nb];
    if (l < k) {
        /* block (l, k), made already, turned over (the matrix is symmetric) */
        for (int b = c->start[l]; b < c->start[l + 1]; b++) {
            if (c->col[b] != k) continue;
            const double *T = &c->B[9 * (size_t)b];
            for (int i = 0; i < 3; i++)
                for (int j = 0; j < 3; j++) B[3 * i + j] = T[3 * j + i];
            return nb + 1;
        }
    }
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++) {
            const impulse_row *ri = &c->rows[3 * k + i], *rj = &c->rows[3 * l + j];
            double a = impulse_effect(ri, rj, &c->resp[4 * (3 * l + j)], bs, mobile);
            /* (made symmetric as impulse_matrix makes it, but on the diagonal) */
            B[3 * i + j] = ri == rj ? a : 0.5 * (a + impulse_effect(rj, ri, &c->resp[4 * (3 * k + i)], bs, mobile));
        }
    return nb + 1;
}

/* The crowd's blocks: point k's, with each point l that shares a mobile body
 * with it (its own first, then those on its p's body and on its q's, each
 * once).  With fill false, only counted (into start); else col and B written. */
static int crowd_blocks(friction_crowd *c, const impulse_row *rows, int m, body *const *bs,
                        const bool *mobile, bool fill)
{
    int nb = 0;
    for (int k = 0; k < m; k++) c->mark[k] = -1;
    for (int k = 0; k < m; k++) {
        c->start[k] = nb;
        nb = crowd_block(c, k, k, nb, fill, bs, mobile);
        for (int s = 0; s < 2; s++) {
            int x = s == 0 ? rows[k].p : rows[k].q;
            if (!moves(x, bs, mobile)) continue;
            for (int e = c->head[x]; e >= 0; e = c->link[e]) nb = crowd_block(c, k, e / 2, nb, fill, bs, mobile);
        }
    }
    c->start[m] = nb;
    return nb;
}

int friction_crowd_matrix(friction_crowd *c, const impulse_row *rows, int m, body *const *bs,
                        const bool *mobile)
{
    int nbody = 0;
    for (int k = 0; k < m; k++) nbody = rows[k].p + 1 > nbody ? rows[k].p + 1 : nbody,
                                nbody = rows[k].q + 1 > nbody ? rows[k].q + 1 : nbody;
    if (crowd_room(c, m, nbody) != 0) return -1;
    friction_rows(rows, m, c->rows);
    for (int i = 0; i < 3 * m; i++) impulse_response(&c->rows[i], bs, mobile, &c->resp[4 * i]);
    /* the points on each body, as lists threaded through link (2k + side) */
    for (int x = 0; x < nbody; x++) c->head[x] = -1;
    for (int k = m - 1; k >= 0; k--)
        for (int s = 1; s >= 0; s--) {
            int x = s == 0 ? rows[k].p : rows[k].q;
            if (!moves(x, bs, mobile)) continue;
            c->link[2 * k + s] = c->head[x];
            c->head[x] = 2 * k + s;
        }
    int nb = crowd_blocks(c, rows, m, bs, mobile, false);
    if (nb > c->cap_blocks) {
        bool ok = true;
        long n = grow_doubled(nb, c->cap_blocks);
        c->col = grow_resized(c->col, sizeof *c->col, n, &ok);
        c->B = grow_resized(c->B, 9 * sizeof *c->B, n, &ok);
        if (!ok) return -1;
        c->cap_blocks = (int)n;
    }
    crowd_blocks(c, rows, m, bs, mobile, true);
    return 0;
}

int friction_matrix(friction_work *fw, const impulse_row *rows, int m, body *const *bs,
                    const bool *mobile)
{
    if (m > FRICTION_MAX_POINTS) return friction_crowd_matrix(&fw->crowd, rows, m, bs, mobile);
    friction_rows(rows, m, fw->rows);
    impulse_matrix(fw->rows, 3 * m, bs, mobile, fw->A);
    return 0;
}

void friction_crowd_mulv(const friction_crowd *c, int m, const double *x, double *y)
{
    for (int k = 0; k < m; k++) {
        double s[3] = {0, 0, 0};
        for (int b = c->start[k]; b < c->start[k + 1]; b++) {
            const double *B = &c->B[9 * (size_t)b], *xl = &x[3 * c->col[b]];
            for (int i = 0; i < 3; i++) s[i] += B[3 * i] * xl[0] + B[3 * i + 1] * xl[1] + B[3 * i + 2] * xl[2];
        }
        for (int i = 0; i < 3; i++) y[3 * k + i] = s[i];
    }
}

int friction_crowd_solve(friction_crowd *c, int m, int sweeps, double loose, bool *painleve)
{
    int n = 3 * m;
    double *z = c->z, *w = c->w;
    bool finite = true;
    for (int i = 0; i < n; i++) finite = finite && isfinite(c->q[i]) && isfinite(z[i]);
    for (long i = 0; i < 9L * c->start[m]; i++) finite = finite && isfinite(c->B[i]);
    if (!finite) {
        for (int k = 0; k < n; k++) z[k] = 0, w[k] = c->q[k];
        return -1;
    }
    friction_crowd_mulv(c, m, z, w);
    double qs = 0, diag = 0;
    for (int i = 0; i < n; i++) w[i] += c->q[i], qs = d_max(qs, fabs(c->q[i]));
    for (int k = 0; k < m; k++)
        for (int i = 0; i < 3; i++) diag = d_max(diag, c->B[9 * (size_t)c->start[k] + 4 * i]);
    int status = 1;
    bool jam = false;
    for (int sweep = 0; sweep < sweeps; sweep++) {
        double change = 0, size = 0;
        jam = false;
        for (int i = 0; i < n; i++) c->w0[i] = w[i];
        for (int k = 0; k < m; k++) {
            int o = 3 * k;
            const double *Bk = &c->B[9 * (size_t)c->start[k]]; /* (its own block) */
            double B[3][3], b[3], zk[3] = {z[o], z[o + 1], z[o + 2]};
            for (int i = 0; i < 3; i++) {
                for (int j = 0; j < 3; j++) B[i][j] = Bk[3 * i + j];
                b[i] = w[o + i] - (B[i][0] * z[o] + B[i][1] * z[o + 1] + B[i][2] * z[o + 2]);
            }
            if (!local_solve(B, b, c->mu[k], zk)) jam = true;
            /* over-relaxed (within the cone) */
            for (int j = 0; j < 3; j++) zk[j] = z[o + j] + FRICTION_CROWD_OMEGA * (zk[j] - z[o + j]);
            double zt = sqrt(zk[1] * zk[1] + zk[2] * zk[2]);
            if (!(zk[0] > 0)) zk[0] = zk[1] = zk[2] = 0;
            else if (zt > c->mu[k] * zk[0]) zk[1] *= c->mu[k] * zk[0] / zt, zk[2] *= c->mu[k] * zk[0] / zt;
            double dz[3] = {zk[0] - z[o], zk[1] - z[o + 1], zk[2] - z[o + 2]};
            if (dz[0] != 0 || dz[1] != 0 || dz[2] != 0) {
                /* w_l += A_lk dz = (A_kl)^T dz, over k's blocks (A symmetric) */
                for (int bl = c->start[k]; bl < c->start[k + 1]; bl++) {
                    const double *A = &c->B[9 * (size_t)bl];
                    double *wl = &w[3 * c->col[bl]];
                    for (int j = 0; j < 3; j++) wl[j] += A[j] * dz[0] + A[3 + j] * dz[1] + A[6 + j] * dz[2];
                }
                for (int j = 0; j < 3; j++) z[o + j] = zk[j];
            }
            size = d_max(size, fabs(zk[0]) + sqrt(zk[1] * zk[1] + zk[2] * zk[2]));
        }
        for (int i = 0; i < n; i++) change = d_max(change, fabs(w[i] - c->w0[i]));
        c->sweeps = sweep + 1;
        if (change <= d_max(FRICTION_TOL * (qs + diag * size), loose)) {
            status = 0;
            break;
        }
    }
    /* w afresh */
    friction_crowd_mulv(c, m, z, w);
    for (int i = 0; i < n; i++) w[i] += c->q[i];
    if (painleve && jam) *painleve = true;
    return status;
}

int friction_solve(friction_work *fw, int m, int sweeps, double loose, bool *painleve)
{
    if (m > FRICTION_MAX_POINTS) return friction_crowd_solve(&fw->crowd, m, sweeps, loose, painleve);
    return cone_solve(m, fw->A, fw->q, fw->mu, fw->z, fw->w, loose, painleve);
}

int friction_compress(const impulse_row *rows, int m, body *const *bs, const bool *mobile,
                      const double *u, double *lambda, friction_work *fw, friction_flags *f)
{
    if (m <= 0 || friction_matrix(fw, rows, m, bs, mobile) != 0) return -1;
    friction_problem P = friction_problem_of(fw, m);
    for (int k = 0; k < m; k++) P.mu[k] = rows[k].mu;
    for (int i = 0; i < 3 * m; i++) P.z[i] = 0;
    return friction_compress_again(m, bs, mobile, u, lambda, fw, f);
}

int friction_compress_again(int m, body *const *bs, const bool *mobile, const double *u, double *lambda,
                            friction_work *fw, friction_flags *f)
{
    int n = 3 * m;
    friction_problem P = friction_problem_of(fw, m);
    for (int i = 0; i < n; i++)
        P.q[i] = u && i % 3 == 0 ? u[i / 3] : impulse_speed(&P.rows[i], bs);
    int st = friction_solve(fw, m, FRICTION_CROWD_SWEEPS, 0, &f->painleve);
    if (st < 0) return -1;
    if (st > 0) f->unconverged = true;
    impulse_apply(P.rows, n, bs, mobile, P.z);
    for (int k = 0; k < m; k++) lambda[k] = P.z[3 * k];
    return 0;
}

/* r A r / 2 over the normals of the m points of friction_compress's matrix
 * (r one a point). */
static double normal_energy(const friction_work *fw, int m, const double *r)
{
    double quad = 0;
    if (m > FRICTION_MAX_POINTS) {
        const friction_crowd *c = &fw->crowd;
        for (int j = 0; j < m; j++) {
            if (r[j] == 0) continue;
            for (int b = c->start[j]; b < c->start[j + 1]; b++) quad += 0.5 * r[j] * c->B[9 * (size_t)b] * r[c->col[b]];
        }
        return quad;
    }
    int n = 3 * m;
    for (int j = 0; j < m; j++) {
        if (r[j] == 0) continue;
        for (int k = 0; k < m; k++) quad += 0.5 * r[j] * fw->A[3 * j * n + 3 * k] * r[k];
    }
    return quad;
}

void friction_restitute(const impulse_row *rows, int m, body *const *bs, const bool *mobile,
                        double *lambda, double ke_before, friction_work *fw, friction_flags *f)
{
    /* (past FRICTION_MAX_POINTS in the crowd's room, which friction_compress
     * made) */
    double rd[FRICTION_MAX_POINTS], *r = m > FRICTION_MAX_POINTS ? fw->crowd.w0 : rd, lin = 0;
    bool any = false;
    for (int k = 0; k < m; k++) {
        r[k] = rows[k].e * lambda[k];
        any = any || r[k] > 0;
    }
    if (!any) return;
    /* the energy with s r applied: ke1 + s lin + s^2 quad */
    double ke1 = friction_energy(rows, m, bs, mobile);
    for (int j = 0; j < m; j++)
        if (r[j] != 0) lin += r[j] * impulse_speed(&rows[j], bs);
    double quad = normal_energy(fw, m, r);
    double s = 1;
    if (ke1 + lin + quad > ke_before && quad > 0) {
        double r1, r2, room = ke_before - ke1;
        s = quad_roots(quad, lin, -d_max(room, 0), &r1, &r2) ? d_max(r1, r2) : 0;
        s = d_min(d_max(s, 0), 1);
        f->energy_cut = true;
    }
    for (int k = 0; k < m; k++) r[k] *= s;
    impulse_apply(rows, m, bs, mobile, r);
    for (int k = 0; k < m; k++) lambda[k] += r[k];
}

bool friction_roll(const impulse_row *rows, int m, body *const *bs, const bool *mobile,
                   const double *z)
{
    bool any = false;
    for (int k = 0; k < m; k++) {
        const impulse_row *r = &rows[k];
        double zn = z[3 * k], zt = hypot(z[3 * k + 1], z[3 * k + 2]);
        if (!(r->roll > 0)) continue;
        any = true;
        if (!(zn > 0) || !(zt < r->mu * zn * (1 - 1e-9))) continue;
        body *P = bs[r->p], *Q = bs[r->q];
        bool mp = mobile[r->p] && !body_is_static(P), mq = mobile[r->q] && !body_is_static(Q);
        const body *arm = mp ? P : Q;
        if (!mp && !mq) continue;
        vec3 rel = v3_sub(P->w, Q->w), nrm = r->n;
        /* rolling (the turning across the normal) and spinning (about it) are
         * resisted apart, each by a couple of up to c r zn */
        vec3 part[2] = {v3_mad(rel, nrm, -v3_dot(rel, nrm)), v3_scale(nrm, v3_dot(rel, nrm))};
        for (int j = 0; j < 2; j++) {
            double wl = v3_len(part[j]);
            if (!(wl > 0)) continue;
            /* no more than stops it: the angular momentum of that turning, on
             * the lighter side (in inertia along it) */
            vec3 dir = v3_scale(part[j], 1 / wl);
            double stop = HUGE_VAL;
            if (mp) stop = d_min(stop, v3_dot(m3_mulv(body_inertia_world(P), part[j]), dir));
            if (mq) stop = d_min(stop, v3_dot(m3_mulv(body_inertia_world(Q), part[j]), dir));
            double J = d_min(r->roll * v3_dist(r->at, body_com(arm)) * zn, d_max(stop, 0));
            if (mp) {
                P->L = v3_mad(P->L, dir, -J);
                body_update_w(P);
            }
            if (mq) {
                Q->L = v3_mad(Q->L, dir, J);
                body_update_w(Q);
            }
        }
    }
    return any;
}

/* ---- one point struck ---- */

/* The slope u' = K (1, zt) in the contact frame. */
static void slope(double K[3][3], double zt1, double zt2, double d[3])
{
    for (int i = 0; i < 3; i++) d[i] = K[i][0] + K[i][1] * zt1 + K[i][2] * zt2;
}

/* The sliding direction of a point whose sticking impulse lies outside the cone:
 * the angle th of s with (K (1, -mu s))_t along s.  False when none. */
static bool unstick_dir(double K[3][3], double mu, double *th)
{
    enum { SCAN = 72 };
    double best = -HUGE_VAL;
    bool found = false;
    double d[3];
    for (int k = 0; k < SCAN; k++) {
        double lo = 2 * M_PI * k / SCAN, hi = 2 * M_PI * (k + 1) / SCAN;
        double flo, fhi;
        slope(K, -mu * cos(lo), -mu * sin(lo), d);
        flo = cos(lo) * d[2] - sin(lo) * d[1];
        slope(K, -mu * cos(hi), -mu * sin(hi), d);
        fhi = cos(hi) * d[2] - sin(hi) * d[1];
        if ((flo <= 0) == (fhi <= 0)) continue;
        for (int i = 0; i < 60; i++) {
            double mid = 0.5 * (lo + hi);
            slope(K, -mu * cos(mid), -mu * sin(mid), d);
            double fm = cos(mid) * d[2] - sin(mid) * d[1];
            if ((fm <= 0) == (flo <= 0)) lo = mid, flo = fm;
            else hi = mid;
        }
        double t = 0.5 * (lo + hi);
        slope(K, -mu * cos(t), -mu * sin(t), d);
        double grow = cos(t) * d[1] + sin(t) * d[2];
        if (grow > best) best = grow, *th = t, found = true;
    }
    return found && best > 0;
}

friction_flags friction_impact(const impulse_row *r, body *const *bs, const bool *mobile, double *pn)
{
    friction_flags f = {false, false, false};
    impulse_row rows[3];
    friction_rows(r, 1, rows);
    double A[9], K[3][3], u[3], P[3] = {0, 0, 0};
    impulse_matrix(rows, 3, bs, mobile, A);
    for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) K[i][j] = A[3 * i + j];
        u[i] = impulse_speed(&rows[i], bs);
    }
    double u0[3] = {u[0], u[1], u[2]}, mu = r->mu, e = r->e;
    *pn = 0;
    if (!(u[0] < 0) || !(K[0][0] > 0)) return f;
    /* the scale of the impulse, and of speeds */
    double scale = -u[0] / K[0][0], vs = fabs(u[0]) + hypot(u[1], u[2]);
    double tiny = 1e-13 * vs, cap = scale / IMPACT_STRETCHES;
    /* sticking: the impulse that keeps the slip 0 */
    double det = K[1][1] * K[2][2] - K[1][2] * K[2][1];
    double ts1 = 0, ts2 = 0;
    bool can_stick = false;
    if (fabs(det) > 1e-14 * K[1][1] * K[2][2]) {
        ts1 = -(K[2][2] * K[1][0] - K[1][2] * K[2][0]) / det;
        ts2 = -(K[1][1] * K[2][0] - K[2][1] * K[1][0]) / det;
        can_stick = hypot(ts1, ts2) <= mu;
    }
    double W = 0, Wc = 0, target = 0, Pc[3] = {0, 0, 0};
    bool compress = true;
    for (int it = 0; it < IMPACT_MAX_STRETCHES; it++) {
        double ut = hypot(u[1], u[2]), d[3], zt1, zt2;
        bool stuck = false, turning = false;
        if (mu == 0) {
            zt1 = zt2 = 0;
        } else if (ut <= tiny) {
            u[1] = u[2] = 0;
            double th;
            if (can_stick) {
                zt1 = ts1, zt2 = ts2, stuck = true;
            } else if (unstick_dir(K, mu, &th)) {
                zt1 = -mu * cos(th), zt2 = -mu * sin(th);
            } else { /* jammed: no consistent answer (Painleve) */
                f.painleve = true;
                zt1 = zt2 = 0, mu = 0;
            }
        } else {
            double s1 = u[1] / ut, s2 = u[2] / ut;
            slope(K, -mu * s1, -mu * s2, d);
            /* a slip that turns: its slope at the middle of a short stretch */
            turning = fabs(s1 * d[2] - s2 * d[1]) > 1e-12 * hypot(d[1], d[2]);
            if (turning) {
                double h = 0.5 * cap, m1 = u[1] + d[1] * h, m2 = u[2] + d[2] * h, ml = hypot(m1, m2);
                if (ml > 0 && m1 * s1 + m2 * s2 > 0) s1 = m1 / ml, s2 = m2 / ml;
            }
            zt1 = -mu * s1, zt2 = -mu * s2;
        }
        slope(K, zt1, zt2, d);
        if (stuck) d[1] = d[2] = 0;
        if (compress && !(d[0] > 0)) {
            /* friction that would jam the contact: frictionless from here */
            f.painleve = true;
            mu = 0;
            continue;
        }
        /* the stretch: to the end of its phase, the slip's stop, or the cap */
        double len = HUGE_VAL, r1, r2;
        bool ends = false, stops = false;
        if (compress) {
            len = -u[0] / d[0];
            ends = true;
        } else if (quad_roots(0.5 * d[0], u[0], W - target, &r1, &r2)) {
            /* W + u0 s + d0 s^2 / 2 = target, the first root ahead */
            double s = HUGE_VAL;
            if (r1 >= 0) s = r1;
            if (r2 >= 0 && r2 < s) s = r2;
            if (s < HUGE_VAL) len = s, ends = true;
        }
        if (!stuck && mu > 0 && ut > tiny) {
            double along = (u[1] * d[1] + u[2] * d[2]) / ut;
            if (along < 0 && ut / -along < len) len = ut / -along, stops = true, ends = false;
            if (turning && cap < len) len = cap, stops = ends = false;
        }
        if (!(len < HUGE_VAL) || !(len >= 0)) break; /* (rounding: nothing left) */
        W += (u[0] + 0.5 * d[0] * len) * len;
        for (int i = 0; i < 3; i++) u[i] += d[i] * len;
        P[0] += len;
        P[1] += zt1 * len;
        P[2] += zt2 * len;
        if (stuck) u[1] = u[2] = 0;
        if (stops) u[1] = u[2] = 0;
        if (ends && compress) {
            compress = false;
            u[0] = 0;
            Wc = W;
            target = (1 - e * e) * Wc;
            memcpy(Pc, P, sizeof P);
            if (e == 0) break;
        } else if (ends) {
            break;
        }
    }
    /* no energy made (Stronge's law keeps it; rounding may not): the change is
     * u0 . P + P K P / 2, and restitution is scaled down until it is <= 0 */
    double dke = 0;
    for (int i = 0; i < 3; i++) {
        dke += u0[i] * P[i];
        for (int j = 0; j < 3; j++) dke += 0.5 * P[i] * K[i][j] * P[j];
    }
    if (dke > 0) {
        /* P = Pc + s R: the energy change is a + b s + c s^2 */
        double R[3], a = 0, b = 0, c = 0, r1, r2;
        for (int i = 0; i < 3; i++) R[i] = P[i] - Pc[i];
        for (int i = 0; i < 3; i++) {
            a += u0[i] * Pc[i];
            b += u0[i] * R[i];
            for (int j = 0; j < 3; j++) {
                a += 0.5 * Pc[i] * K[i][j] * Pc[j];
                b += Pc[i] * K[i][j] * R[j];
                c += 0.5 * R[i] * K[i][j] * R[j];
            }
        }
        double s = c > 0 && quad_roots(c, b, a, &r1, &r2) ? d_max(d_min(d_max(r1, r2), 1), 0) : 0;
        if (a > 0) s = 0;
        for (int i = 0; i < 3; i++) P[i] = Pc[i] + s * R[i];
        f.energy_cut = true;
    }
    impulse_apply(rows, 3, bs, mobile, P);
    *pn = P[0];
    return f;
}
