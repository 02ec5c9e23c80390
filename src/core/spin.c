/* spin.c: the torque-free rigid body in closed form (spin.h gives the sources).
 *
 * Three different moments.  The principal axes are relabelled 1, 2, 3 by a
 * proper rotation (a permutation with signs) so that axis 3 is the one the body
 * turns about: the largest moment when |L|^2 >= 2E I_middle, else the smallest;
 * axis 2 is the middle one, and x = L / |L| in these axes has x1 >= 0 and x3 > 0
 * (x3 never changes sign).  With J the moments and d_ij = J_i - J_j, Euler's
 * equations are solved by (Landau and Lifshitz, Mechanics, section 37)
 *     x = (a1 cn tau, a2 sn tau, a3 dn tau),   tau = lambda t + u0,
 *     a1^2 = J1 A / d31,   a2^2 = J2 A / d32,   a3^2 = J3 B / d31,
 *     parameter m = d21 A / (d32 B),   1 - m = d31 D / (d32 B),
 *     lambda = sign(d31) sqrt(B d32 / (J1 J2 J3)) |L|,
 * A = (2E J3 - |L|^2) / |L|^2, B = (|L|^2 - 2E J1) / |L|^2 and D = (|L|^2 -
 * 2E J2) / |L|^2 being written as sums of x_i^2 times moment differences, which
 * for A and B are terms of one sign: nothing cancels but in D, which vanishes on
 * the separatrix, as the problem's own conditioning there has it.  u0 = F(phi0|m),
 * phi0 the angle of (x1 / a1, x2 / a2).
 *
 * The orientation: with A(x) the least rotation taking x to z (its axis in the
 * xy plane; defined since x3 > 0), qp(t) = Q0 Rz(psi) A(x(t)) for a constant Q0
 * that turns z to L.  qp' = qp [Omega] gives psi' = |L| / J3 + (2E - |L|^2 / J3)
 * / (|L| (1 + x3)), and as 1 / (1 + x3) = (1 - x3) / (x1^2 + x2^2), x1^2 + x2^2 =
 * a1^2 (1 - n sn^2) with n = -J3 d21 / (J1 d32) < 0,
 *     psi = |L| t / J3 + [c_pi Pi(n; am tau | m) - c_g G(tau)] from u0 to tau,
 *     c_pi = beta |L| / lambda,  c_g = beta a3 |L| / lambda,  beta = d31 / (J1 J3),
 *     G(tau) = atan(sqrt(1 - n) tan am tau) / sqrt(1 - n),
 * G the integral of dn / (1 - n sn^2) and Pi the incomplete integral of the third
 * kind (van Zon and Schofield split the same turn into Euler angles).  tau is
 * reduced to |r| <= K: each half period 2K changes the signs of sn and cn and
 * adds 2 Pi(n|m) to Pi and pi / sqrt(1 - n) to G.  psi's mean rate, from these,
 * multiplies t itself; Pi and G less their mean growth give the periodic rest,
 * from r: tau's rounding, divided by lambda, would otherwise show in psi, and
 * lambda is small for nearly symmetric bodies.  Pi(n; am r) - r is n/3 sn^3
 * R_J(cn^2, dn^2, 1, 1 - n sn^2) (DLMF 19.25(i)).  Exactly on the separatrix
 * (m = 1, no period) sn = tanh, cn = dn = sech and Pi is elementary.
 * Q0 = qp(0) A(x(0))^-1 makes psi(0) = 0.
 *
 * Each call forms x from sn, cn, dn, normalised (|x| = 1 to rounding), and turns
 * it to world axes by a rotation, so L and the energy are kept to rounding
 * whatever t: only psi, an angle about L, carries the errors of the elliptic
 * functions and integrals.
 */
#include "spin.h"

#include <assert.h>

/* Components of L / |L| off a principal axis below this: the spin is steady
 * about it (their squares would underflow; such a perturbation of an unstable
 * spin takes some 350 / lambda seconds, ln 1e150, to grow to 1). */
#define SPIN_ON_AXIS 1e-150

/* The least rotation taking the unit vector x to z: (1 + x3, x2, -x1, 0) normed. */
static quat to_z(vec3 x)
{
    double c = 1 + x.z, h = 1 / sqrt(2 * c);
    return (quat){c * h, x.y * h, -x.x * h, 0};
}

/* Pi(n; am r | m) on the separatrix: the integral of 1 / (1 - n tanh^2). */
static double pi_separatrix(double n, double r)
{
    double s = sqrt(-n);
    return (r + s * atan(s * tanh(r))) / (1 - n);
}

/* G(r), the integral of dn / (1 - n sn^2) from 0 to r, |r| <= K. */
static double g_of(const free_spin *s, double sn, double cn)
{
    return atan2(s->sq1n * sn, cn) / s->sq1n;
}

/* Pi(n; am r | m) less its mean growth Pi(n|m) r / K, |r| <= K: for |n| <= 1 as
 * n/3 (sn^3 R_J - r R_J(0, 1 - m, 1, 1 - n) / K), which stays small with n, else
 * Pi itself (then near r / (1 - n), small with 1 / n). */
static double pi_wave(const free_spin *s, double r, double sn, double cn, double dn)
{
    if (s->n >= -1)
        return s->n / 3 * (sn * sn * sn * ell_rj(cn * cn, dn * dn, 1, 1 - s->n * sn * sn) - r * s->pi_slope);
    return ell_Pi_sncndn(s->n, s->m, sn, cn, dn, r) - r * s->pi_slope;
}

/* The part of psi that is periodic in r (with the separatrix's all of it). */
static double psi_wave(const free_spin *s, double r, double sn, double cn, double dn)
{
    if (s->separatrix) return s->c_pi * pi_separatrix(s->n, r) - s->c_g * g_of(s, sn, cn);
    return s->c_pi * pi_wave(s, r, sn, cn, dn) - s->c_g * (g_of(s, sn, cn) - r * s->g_slope);
}

/* The working axes 1, 2, 3 for x = L / |L| in principal axes, in the principal
 * moments: writes to s the rotation back to principal axes, and returns x in
 * working axes and their moments J. */
static vec3 working_axes(free_spin *s, const double in[3], vec3 x, vec3 *J)
{
    int ax[3] = {0, 1, 2}; /* sorted by moment: smallest, middle, largest */
    for (int i = 0; i < 3; i++)
        for (int j = 2; j > i; j--)
            if (in[ax[j]] < in[ax[j - 1]]) {
                int t = ax[j];
                ax[j] = ax[j - 1];
                ax[j - 1] = t;
            }
    /* D's sign: turning about the largest moment's axis, or the smallest's */
    double lo = v3_comp(x, ax[0]), hi = v3_comp(x, ax[2]);
    double d = lo * lo * (in[ax[0]] - in[ax[1]]) / in[ax[0]] + hi * hi * (in[ax[2]] - in[ax[1]]) / in[ax[2]];
    if (d < 0) {
        int t = ax[0];
        ax[0] = ax[2];
        ax[2] = t;
    }
    /* signs: x1 >= 0, x3 >= 0, and a determinant of +1 */
    bool cyclic = (ax[1] - ax[0] + 3) % 3 == 1;
    double s1 = v3_comp(x, ax[0]) < 0 ? -1 : 1, s3 = v3_comp(x, ax[2]) < 0 ? -1 : 1;
    double s2 = cyclic ? s1 * s3 : -s1 * s3;
    mat3 g = m3_zero(); /* column j: working axis j in principal axes */
    g.m[ax[0]][0] = s1;
    g.m[ax[1]][1] = s2;
    g.m[ax[2]][2] = s3;
    s->to_working = q_conj(q_from_m3(g));
    *J = v3(in[ax[0]], in[ax[1]], in[ax[2]]);
    return v3(s1 * v3_comp(x, ax[0]), s2 * v3_comp(x, ax[1]), s3 * v3_comp(x, ax[2]));
}

/* Three different moments: the constants of the file comment's equations. */
static void tumble_init(free_spin *s, vec3 I, quat qp, vec3 m, double l)
{
    /* the moments in units of a power of 2 near the largest, exactly (so that
     * the separatrix's D = 0 stays 0), and rates in |L| over that unit: no
     * product of three moments under- or overflows */
    int e;
    frexp(fmax(I.x, fmax(I.y, I.z)), &e);
    double unit = ldexp(1, -e), rate = l * unit;
    const double in[3] = {I.x * unit, I.y * unit, I.z * unit};
    vec3 J, x = working_axes(s, in, v3(m.x / l, m.y / l, m.z / l), &J);
    quat qw = q_mul(qp, q_conj(s->to_working)); /* working axes -> world */
    double d21 = J.y - J.x, d31 = J.z - J.x, d32 = J.z - J.y;
    double x1 = x.x * x.x, x2 = x.y * x.y, x3 = x.z * x.z;
    double A = x1 * d31 / J.x + x2 * d32 / J.y;
    double B = x2 * d21 / J.y + x3 * d31 / J.z;
    double D = x3 * d32 / J.z - x1 * d21 / J.x;
    s->amp = v3(sqrt(fmax(J.x * A / d31, 0)), sqrt(fmax(J.y * A / d32, 0)),
                sqrt(fmax(J.z * B / d31, 0)));
    s->w_scale = v3(rate / J.x, rate / J.y, rate / J.z);
    double mc = fmin(fmax(d31 * D / (d32 * B), 0), 1);
    s->m = fmin(fmax(d21 * A / (d32 * B), 0), 1);
    s->separatrix = mc == 0;
    s->ep = mc < 0.5 ? ell_param_mc(mc) : ell_param_m(s->m);
    s->two_k = 2 * s->ep.K;
    s->lambda = copysign(rate * sqrt(B * d32 / (J.x * J.y * J.z)), d31);
    s->n = -J.z * d21 / (J.x * d32);
    s->sq1n = sqrt(1 - s->n);
    double beta = d31 / (J.x * J.z);
    s->psi_rate = rate / J.z;
    s->c_pi = beta * rate / s->lambda;
    s->c_g = beta * s->amp.z * rate / s->lambda;

    /* phi0 = am u0: the angle of (x1 / a1, x2 / a2) = (x1, x2 / rho) / a1 */
    double rho = sqrt(J.y * d31 / (J.x * d32));
    double cn = x.x, sn = x.y / rho, h = hypot(cn, sn);
    if (h > 0) {
        cn /= h;
        sn /= h;
    } else {
        cn = 1;
        sn = 0;
    }
    double dn = sqrt(cn * cn + mc * sn * sn);
    s->u0 = sn * ell_rf(cn * cn, dn * dn, 1);
    s->psi_mean = s->psi_rate;
    if (!s->separatrix) {
        /* the mean growths of Pi and G over a half period 2K: 2 Pi(n|m) and
         * pi / sqrt(1 - n) */
        double K = s->ep.K, kc = sqrt(mc);
        double rj = s->n >= -1 ? ell_rj(0, mc, 1, 1 - s->n) : 0; /* (once: it is the cost) */
        s->pi_slope = s->n >= -1 ? rj / K : ell_Pi_sncndn(s->n, s->m, 1, 0, kc, K) / K;
        double pi_c = s->n >= -1 ? K + s->n / 3 * rj : s->pi_slope * K;
        s->g_slope = M_PI_2 / (K * s->sq1n);
        s->psi_mean += s->lambda * (s->c_pi * pi_c / K - s->c_g * s->g_slope);
    }
    s->psi0 = psi_wave(s, s->u0, sn, cn, dn);
    s->q0 = q_mul(qw, q_conj(to_z(x)));
}

void spin_init(free_spin *s, vec3 I, quat qp, vec3 L)
{
    assert(I.x > 0 && I.y > 0 && I.z > 0);
    *s = (free_spin){.kind = SPIN_STILL, .q0 = q_normalize(qp)};
    double big = fmax(fabs(L.x), fmax(fabs(L.y), fabs(L.z)));
    if (big == 0) return;
    double l = big * v3_len(v3(L.x / big, L.y / big, L.z / big)); /* no square overflows */
    s->rate_bound = l / fmin(I.x, fmin(I.y, I.z));
    s->axis = v3(L.x / l, L.y / l, L.z / l);
    vec3 m = q_unrotate(s->q0, L); /* L in principal axes */
    vec3 u = v3(m.x / l, m.y / l, m.z / l);
    int on_axis = fabs(u.y) < SPIN_ON_AXIS && fabs(u.z) < SPIN_ON_AXIS ? 0
                : fabs(u.x) < SPIN_ON_AXIS && fabs(u.z) < SPIN_ON_AXIS ? 1
                : fabs(u.x) < SPIN_ON_AXIS && fabs(u.y) < SPIN_ON_AXIS ? 2 : -1;
    if (I.x == I.y && I.y == I.z) on_axis = 0;
    if (on_axis >= 0) {
        s->kind = SPIN_STEADY;
        s->rate = l / v3_comp(I, on_axis);
        return;
    }
    int k = I.x == I.y ? 2 : I.y == I.z ? 0 : I.x == I.z ? 1 : -1;
    if (k >= 0) {
        /* the frame turns about L at |L| / I_p and about its own axis k at
         * L_k (1/I_k - 1/I_p), I_p the two equal moments */
        double ip = v3_comp(I, (k + 1) % 3);
        s->kind = SPIN_TOP;
        s->rate = l / ip;
        s->sym = k;
        s->sym_rate = v3_comp(m, k) * (1 / v3_comp(I, k) - 1 / ip);
        return;
    }
    s->kind = SPIN_TUMBLE;
    tumble_init(s, I, s->q0, m, l);
}

/* Rotation about principal axis k by angle. */
static quat about_axis(int k, double angle)
{
    double h = 0.5 * angle, c = cos(h), sn = sin(h);
    return (quat){c, k == 0 ? sn : 0, k == 1 ? sn : 0, k == 2 ? sn : 0};
}

static void tumble_at(const free_spin *s, double t, quat *qp, vec3 *w)
{
    double tau = s->lambda * t + s->u0, j = 0, r = tau;
    if (!s->separatrix) {
        j = nearbyint(tau / s->two_k);
        r = fma(-j, s->two_k, tau);
    }
    double sn, cn, dn;
    ell_sncndn(&s->ep, r, &sn, &cn, &dn);
    /* the mean turn from t itself, not from tau: tau's rounding would count
     * 1/lambda times, and lambda is small for a nearly symmetric body */
    double psi = s->psi_mean * t + (psi_wave(s, r, sn, cn, dn) - s->psi0);
    double half = 0.5 * j;
    if (half != floor(half)) { /* an odd number of half periods */
        sn = -sn;
        cn = -cn;
    }
    vec3 x = v3_norm(v3(s->amp.x * cn, s->amp.y * sn, s->amp.z * dn));
    quat qw = q_mul(q_mul(s->q0, about_axis(2, psi)), to_z(x)); /* working -> world */
    *qp = q_mul(qw, s->to_working);
    *w = q_rotate(qw, v3(s->w_scale.x * x.x, s->w_scale.y * x.y, s->w_scale.z * x.z));
}

void spin_at(const free_spin *s, double t, quat *qp, vec3 *w)
{
    switch (s->kind) {
    case SPIN_STILL:
        *qp = s->q0;
        *w = v3(0, 0, 0);
        break;
    case SPIN_STEADY:
        *qp = q_mul(q_axis_angle(s->axis, s->rate * t), s->q0);
        *w = v3_scale(s->axis, s->rate);
        break;
    case SPIN_TOP: {
        quat q = q_mul(q_mul(q_axis_angle(s->axis, s->rate * t), s->q0),
                       about_axis(s->sym, s->sym_rate * t));
        *qp = q;
        /* w = L / I_p + sym_rate e_k, e_k the body's axis k in world axes */
        vec3 ek = q_rotate(q, v3(s->sym == 0, s->sym == 1, s->sym == 2));
        *w = v3_mad(v3_scale(s->axis, s->rate), ek, s->sym_rate);
        break;
    }
    case SPIN_TUMBLE:
        tumble_at(s, t, qp, w);
        break;
    }
}

double spin_rate_bound(const free_spin *s) { return s->rate_bound; }
