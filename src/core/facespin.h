/* facespin.h: friction over a face: a flat body sliding and spinning at once on
 * a face of a still support, level or inclined (design.md, "Dynamics"; issue
 * 37).
 *
 * The body presses on the face over its own face, flat on it.  The pressure is
 * linear over the region, p = p0 + k . x (x from under the centre of mass): the
 * distribution that balances the moments, int p = N = m g_n and int p x = -h F
 * (h the centre of mass's height, F friction's force: the face neither lifts
 * nor sinks any corner).  Where it would go negative it is clipped at zero: p =
 * max(0, p0 + k . x), the same balance over the part pressed; where that part
 * shrinks to nothing (at an edge) there is no such pressure, and the body tips
 * (the clusters take it).  Friction's force and couple are the integrals of
 * -mu p s over the region (s the unit slip, region.h), exact.  Slide and spin
 * together have no closed form: they are integrated by Dormand and Prince's
 * RK5(4) with dense output to 1e-9 relative, one step per flight (flight.h's
 * FLIGHT_SPIN), each step's end an event; the last ends where |v| + |w| R <
 * 1e-9 m/s (R its face's reach), where the slip's direction becomes singular:
 * it stops there.  On an incline gravity's part along the face, gt, adds the
 * constant acceleration gt to the slide (at the centre of mass: no moment, so
 * the pressure balances as on the level, pressed at g_n = g cos th).  Where
 * |gt| <= mu g_n static friction then holds it: it stops as on the level, and
 * sticks.  Where |gt| > mu g_n it never stops: its integration ends where its
 * spin and its drift across the slope are below 1e-9 m/s (|w| R, and the speed
 * square to gt), and it slides on down in closed form (friction_face).
 */
#ifndef VROC_FACESPIN_H
#define VROC_FACESPIN_H

#include <stdbool.h>

#include "body.h"
#include "flight.h"
#include "region.h"

/* Corners of a face at most (a superquadric's end of 256 divisions) */
#define FACESPIN_MAX 256

/* The stop: slip and spin below this (m/s, |v| + |w| R) */
#define FACESPIN_STOP 1e-9

typedef struct {
    region_pt p[FACESPIN_MAX]; /* its face, from under its centre of mass, */
    int n;                     /*   in the axes e1, e2, as it was at the start */
    region_moments moments;    /*   and its moments */
    double reach, h;           /* its furthest corner, its centre's height */
    double mu, gn, mass, in;   /* friction, the pressing acceleration, m, I about n */
    double gt[2];              /* gravity's acceleration along the face (e1, e2) */
    vec3 nrm, e1, e2;
} face_spin;

/* Sets fs for body b on a face of normal n (towards b), friction mu, pressed
 * at g_n, pulled along it at gt (square to n; 0 on a level face): false when b has no face flat on it, or n is not one of its
 * principal axes (a spin about n would then need a couple to keep it so). */
bool face_spin_init(face_spin *fs, const body *b, vec3 n, double mu, double gn, vec3 gt);

/* Friction's acceleration a (e1, e2) of the centre of mass and dw of the spin,
 * the body turned by `turn` about n from where fs found it, moving at v (e1,
 * e2) and spinning at w: false when no pressure balances it (it tips). */
bool face_spin_accel(const face_spin *fs, double turn, const double v[2], double w, double a[2], double *dw);

/* One step from velocity v (e1, e2) and spin w, at most hmax long (0: no
 * limit), into out (gt added to friction's acceleration): false when no
 * pressure balances it at the start. */
bool face_spin_step(const face_spin *fs, const double v[2], double w, double hmax, face_step *out);

#endif
