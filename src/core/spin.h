/* spin.h: the exact torque-free rotation of a rigid body, at any time from a start.
 *
 * A free body keeps its angular momentum L (world axes) and its energy; its
 * principal frame turns in closed form: about L at a constant rate for a sphere
 * or a spin about a principal axis, a precession and a spin for a symmetric top,
 * and Jacobi's elliptic functions with an integral of the third kind for three
 * different moments (spin.c says how; van Zon and Schofield, J. Comput. Phys. 225,
 * 2007; Celledoni, Fasso, Safstrom and Zanna, SIAM J. Sci. Comput. 30, 2008).
 * spin_init does all that depends on the start only, so that spin_at, called many
 * times per flight, costs one sn/cn/dn and one elliptic integral.
 *
 * Conventions: the principal frame qp maps principal axes to world axes; a body
 * (body.h) has qp = q * q_principal, so its orientation at t is
 * q = qp(t) * conj(q_principal); its principal moments are I_princ.
 */
#ifndef VROC_SPIN_H
#define VROC_SPIN_H

#include <stdbool.h>

#include "elliptic.h"
#include "vmath.h"

typedef enum {
    SPIN_STILL,  /* L = 0: no motion */
    SPIN_STEADY, /* a turn about L at a constant rate: three equal moments, or L
                  * along a principal axis */
    SPIN_TOP,    /* two equal moments: precession about L, spin about the axis */
    SPIN_TUMBLE  /* three different moments: elliptic functions */
} spin_kind;

/* What spin_at needs, computed once by spin_init. */
typedef struct {
    spin_kind kind;
    double rate_bound; /* |L| / min I */
    quat q0;           /* STILL, STEADY, TOP: the principal frame at 0; TUMBLE:
                        * Q0, from the frame with L along z to world axes */
    vec3 axis;         /* STEADY, TOP: L / |L| */
    double rate;       /* STEADY, TOP: the turn about L, rad/s */
    int sym;           /* TOP: the principal axis of the unequal moment */
    double sym_rate;   /* TOP: the turn about it, L_sym (1/I_sym - 1/I_other) */
    /* TUMBLE (spin.c names them after its equations) */
    quat to_working;   /* principal axes -> the working axes 1, 2, 3 */
    vec3 amp;          /* L in working axes = |L| (amp.x cn, amp.y sn, amp.z dn) */
    vec3 w_scale;      /* |L| / J_i: the angular velocity is w_scale * L / |L| */
    double lambda, u0; /* the elliptic functions' argument lambda t + u0 */
    double two_k;      /* their half period 2K (inf on the separatrix) */
    double n, m;       /* the third kind's characteristic, the parameter */
    double sq1n;       /* sqrt(1 - n) */
    double psi_rate, c_pi, c_g; /* psi = psi_rate t + c_pi Pi - c_g G */
    double psi_mean;   /* psi's mean rate */
    double pi_slope;   /* Pi's mean growth per unit of tau, Pi(n|m) / K; for
                        * |n| <= 1 (Pi - F)'s over n/3, R_J(0, 1 - m, 1, 1 - n) / K */
    double g_slope;    /* G's: pi / (2K sqrt(1 - n)) */
    double psi0;       /* psi's periodic part at u0 */
    bool separatrix;   /* exactly on it: m = 1, no period */
    ell_param ep;
} free_spin;

/* The torque-free motion of a body with principal moments I (I.x, I.y, I.z > 0,
 * in any order, any two or three may be equal) whose principal frame is turned by
 * qp (principal -> world) at time 0, with angular momentum L (world axes,
 * constant).  A spin within 1e-150 of a principal axis is taken as steady. */
void spin_init(free_spin *s, vec3 I, quat qp, vec3 L);

/* The principal frame's orientation (principal -> world) t seconds later (t may
 * be any real, also negative or large), and the angular velocity in world axes
 * then.  Computed directly from time 0 (no accumulation), exact to rounding. */
void spin_at(const free_spin *s, double t, quat *qp, vec3 *w);

/* |w| never exceeds this: |L| / min(I) (for the collision schedule's bounds). */
double spin_rate_bound(const free_spin *s);

#endif
