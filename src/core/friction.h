/* friction.h: Coulomb friction and rolling resistance where objects press
 * (beyond the thesis, which is frictionless; language.md, "Friction"; design.md,
 * "Dynamics").
 *
 * A pair's coefficients are sqrt(mu_a mu_b) and sqrt(c_a c_b).  Two laws live
 * here, and every contact problem with friction uses one of them:
 *  - friction_impact: one point struck (a collision with a single row and no
 *    lasting contact), by Mirtich's collision integration ("Impulse-based dynamic
 *    simulation of rigid body systems", 1996, 4.2): the contact velocity changes
 *    along the normal impulse p_n; a slipping point is opposed by mu dp_n against
 *    its current slip, which may turn and stop; at zero slip it sticks if the
 *    impulse that keeps it stuck lies inside the cone, and slides on otherwise.
 *    Restitution ends it by Stronge's energetic coefficient: the work of the
 *    normal impulse while it restitutes is e^2 times what it did while it
 *    compressed, so no impact creates energy, even where the slip reverses.
 *  - friction_compress: points answered together (a collision with lasting
 *    contacts, a cluster's kicks, the balance of objects at rest): Coulomb's
 *    isotropic cones, not pyramids, with the maximal dissipation of a sliding
 *    point (friction_cone_solve); then friction_restitute adds e times each
 *    point's normal compression impulse, scaled down where it would raise the
 *    kinetic energy.
 * Each row of a point becomes three rows (impulse.h): its normal and two tangents
 * t1, t2 (friction_basis), so that the matrix of impulse_matrix is the problem's
 * (3m x 3m, the point k's rows at 3k, 3k + 1, 3k + 2).
 */
#ifndef VROC_FRICTION_H
#define VROC_FRICTION_H

#include <stdbool.h>

#include "body.h"
#include "flight.h"
#include "impulse.h"

/* Points (3 rows each) up to which a problem with friction is solved densely
 * (friction_cone_solve, with its polish); past them, in blocks (friction_crowd). */
#define FRICTION_MAX_POINTS 64

/* The cone solve stops when no impulse changes by more than this, relative to the
 * largest, in a sweep. */
#define FRICTION_TOL 1e-12

/* Sweeps of the cone solve, at most. */
#define FRICTION_SWEEPS 300

/* What a problem with friction met, for the world's counters (sim_stats). */
typedef struct {
    bool energy_cut;   /* restitution scaled down: it would have raised the energy */
    bool unconverged;  /* the cone solve stopped short of FRICTION_TOL */
    bool painleve;     /* no consistent answer (Painleve): friction that jams the
                        * contact; the answer falls back to a sliding point's */
} friction_flags;

/* Sweeps of the cone solve past FRICTION_MAX_POINTS, at most, where it must be
 * exact (friction_compress: the balance of objects at rest, a collision's
 * compression; friction_crowd_solve: there is no polish there, so the sweeps
 * alone must converge). */
#define FRICTION_CROWD_SWEEPS 1000

/* The over-relaxation of those sweeps: each point's change from its exact local
 * answer is taken this many times over (and brought back into its cone).  A
 * crowd's points form long chains (a slot's rows of 25 balls), along which plain
 * Gauss-Seidel carries a change a point a sweep: a row of 25 balls on a rough
 * floor took 961 sweeps to converge, 73 at 1.6; the slot of 100 rests with 1.5. */
#define FRICTION_CROWD_OMEGA 1.5

/* A problem of more points than FRICTION_MAX_POINTS (a crowd's cluster: a hundred
 * balls in a slot press at some 450) in blocks: its matrix (impulse_matrix's over
 * friction_rows, to the bit) kept as its nonzero 3 x 3 blocks alone, for block
 * (k, l) is nonzero only where points k and l share a mobile body, a few a
 * point.  Its arrays are grown to the largest problem met and kept. */
typedef struct {
    int cap, cap_blocks, cap_bodies;  /* room: points, blocks, bodies */
    impulse_row *rows;                /* 3 a point (friction_rows) */
    double *q, *z, *w, *w0, *mu;      /* 3 a point (mu: 1) */
    int *start;                       /* point k's blocks: start[k] .. start[k + 1] - 1, */
    int *col;                         /*   each block's other point (its own first), */
    double *B;                        /*   and its 9 entries: rows of k, columns of col */
    int *mark, *link, *head;          /* the blocks' search: points seen, points by body */
    vec3 *resp;                       /* each row's impulse_response (4 a row) */
    int sweeps;                       /* the last solve's sweeps (for the tests) */
} friction_crowd;

/* The scratch of the problems with friction (in answer_scratch: too large for a
 * stack). */
typedef struct {
    impulse_row rows[3 * FRICTION_MAX_POINTS];
    double A[9 * FRICTION_MAX_POINTS * FRICTION_MAX_POINTS];
    double q[3 * FRICTION_MAX_POINTS], z[3 * FRICTION_MAX_POINTS], w[3 * FRICTION_MAX_POINTS];
    double mu[FRICTION_MAX_POINTS];
    friction_crowd crowd; /* past FRICTION_MAX_POINTS (zeroed at first) */
} friction_work;

/* The arrays of a problem of m points in fw: the dense ones up to
 * FRICTION_MAX_POINTS, the crowd's past it. */
typedef struct {
    impulse_row *rows;
    double *q, *z, *w, *mu;
} friction_problem;

friction_problem friction_problem_of(friction_work *fw, int m);

/* The 3m rows of the m rows into the problem's arrays (friction_problem_of),
 * with the matrix: dense (fw->A) up to FRICTION_MAX_POINTS, in blocks past it.
 * Returns 0, or -1 when out of memory (past FRICTION_MAX_POINTS). */
int friction_matrix(friction_work *fw, const impulse_row *rows, int m, body *const *bs,
                    const bool *mobile);

/* The 3m rows alone, as friction_matrix puts them: NULL when out of memory. */
impulse_row *friction_rows_in(friction_work *fw, const impulse_row *rows, int m);

/* The crowd's problem of m points (any m: friction_matrix's past
 * FRICTION_MAX_POINTS): its 3m rows (c->rows) and its blocks.  0, or -1 when out
 * of memory. */
int friction_crowd_matrix(friction_crowd *c, const impulse_row *rows, int m, body *const *bs,
                          const bool *mobile);

/* y = A x over the crowd's blocks (3m each; friction_matrix's past
 * FRICTION_MAX_POINTS), each entry summed in its blocks' order. */
void friction_crowd_mulv(const friction_crowd *c, int m, const double *x, double *y);

/* The cone problem of friction_cone_solve over the crowd's blocks (c->q, c->mu;
 * z from c->z as given, w into c->w): block Gauss-Seidel with each point's 3 x 3
 * problem solved exactly, as friction_cone_solve's sweeps, over-relaxed
 * (FRICTION_CROWD_OMEGA), each sweep over the nonzero blocks alone, with no
 * polish, for `sweeps` at most, stopping once a sweep's change is no more
 * than loose (a speed: 0 for FRICTION_TOL alone).  Returns as
 * friction_cone_solve. */
int friction_crowd_solve(friction_crowd *c, int m, int sweeps, double loose, bool *painleve);

/* The cone solve of the problem friction_matrix set up, its q, mu and z (the
 * guess) in friction_problem_of's arrays: friction_cone_solve, or
 * friction_crowd_solve for `sweeps` at most; the sweeps stop once their change
 * is no more than loose (a speed), where that is above FRICTION_TOL's (0:
 * FRICTION_TOL alone), as in the early steps of an inexact Newton's method. */
int friction_solve(friction_work *fw, int m, int sweeps, double loose, bool *painleve);

/* Frees the crowd's arrays of fw (fw itself is the caller's). */
void friction_work_free(friction_work *fw);

/* A pair's coefficients. */
double friction_mu(const body *a, const body *b);
double friction_rolling(const body *a, const body *b);

/* True when some row of rows (n) has friction. */
bool friction_any(const impulse_row *rows, int n);

/* Two unit tangents with (n, t1, t2) right-handed, a function of n alone. */
void friction_basis(vec3 n, vec3 *t1, vec3 *t2);

/* The 3m rows of the m rows (normal, t1, t2 each), into out. */
void friction_rows(const impulse_row *rows, int m, impulse_row *out);

/* The cone problem of m points: A (3m x 3m, symmetric, from impulse_matrix over
 * friction_rows), q (3m), mu (m).  Finds z with w = A z + q such that at each
 * point k (z_k = (zn, zt), w_k = (wn, wt)), starting from z as given (0, or a
 * guess in the cones): zn >= 0, wn >= 0, zn wn = 0; |zt| <=
 * mu_k zn; and where wt != 0, zt = -mu_k zn wt / |wt| (Coulomb, maximal
 * dissipation).  By block Gauss-Seidel with each point's 3 x 3 problem solved
 * exactly.  Returns 0 when it converged to FRICTION_TOL, 1 when it stopped after
 * FRICTION_SWEEPS (z the last sweep's, usable), -1 when A or q is not finite (z =
 * 0).  *painleve is set when some point's problem had no consistent answer. */
int friction_cone_solve(int m, const double *A, const double *q, const double *mu, double *z,
                        double *w, bool *painleve);

/* One point struck: row r (its restitution e = r->e, its mu = r->mu) between the
 * bodies bs (mobile as marked), by Mirtich's integration (above).  Applies the
 * impulse; writes its normal part to *pn.  Returns what it met. */
friction_flags friction_impact(const impulse_row *r, body *const *bs, const bool *mobile,
                               double *pn);

/* The compression of m points answered together (e = 0, cones): u their normal
 * speeds before (NULL: impulse_speed's), the tangential ones found here.  Applies the
 * impulses; writes each point's normal impulse to lambda (all three in
 * friction_problem_of(fw, m).z).  Returns 0, or -1 when out of memory or not
 * finite (nothing applied); *f gets what it met. */
int friction_compress(const impulse_row *rows, int m, body *const *bs, const bool *mobile,
                      const double *u, double *lambda, friction_work *fw, friction_flags *f);

/* friction_compress's problem of m points once more, on bodies bs posed as
 * then (so that its matrix holds) but moving otherwise: from its last
 * impulses, which a small change of the speeds leaves near the answer (the
 * rounds of a balance, rest.c).  Returns as friction_compress. */
int friction_compress_again(int m, body *const *bs, const bool *mobile, const double *u, double *lambda,
                            friction_work *fw, friction_flags *f);

/* The restitution after friction_compress: e_k lambda_k along each point's
 * normal, scaled down (all alike) so far as the kinetic energy of the mobile
 * bodies would rise above ke_before.  Adds what it applied to lambda.  The
 * matrix of the normals is fw's from friction_compress. */
void friction_restitute(const impulse_row *rows, int m, body *const *bs, const bool *mobile,
                        double *lambda, double ke_before, friction_work *fw, friction_flags *f);

/* Closed-form lasting contact (design.md, "Dynamics"): how body b moves on a
 * level or inclined face of a still support s (normal n, towards b) with
 * friction, pressed onto it by the force's acceleration g, from its state (its
 * velocity along the face; a ball's spin, about an axis along the face square
 * to its velocity: what a caller makes of it first).  With mu and c the pair's
 * coefficients, g_n = -g.n, g_t g's part along the face:
 *  - a box (any body but a ball), flat on the face and not turning: at rest,
 *    it sticks where |g_t| <= mu g_n, else it slides down along g_t; moving at
 *    v, it slides at g_t - mu g_n v/|v| until v is zero (t_stop).  *lean is the
 *    friction force over the normal force, -F_t / N: the centre of pressure is
 *    h *lean from under the centre of mass (h its height over the face), which
 *    must lie inside the region they touch on, or the box tips.  Spinning in
 *    place about n on a level face, on a face of its own centrally symmetric
 *    about its centre of mass's foot (contact_face_arm: the pressure is then
 *    uniform), its spin slows at mu g_n m arm / I_n until it stops; sliding
 *    and spinning at once on a level face (or spinning on a face not so
 *    symmetric), it moves by friction over its face (facespin.h: spins set;
 *    where hmax >= 0 the first step of its motion, at most hmax long (0:
 *    any), t_stop its length, or where no step can be taken t_stop 0 and
 *    step.tips; where no pressure balances it now, it tips: general);
 *  - a ball (I = k m r^2), slipping at s = v - r w x n: it slides at g_t - mu
 *    g_n s/|s|, its spin growing by mu g_n / (k r) about n x s/|s|, until its
 *    slip is zero (t_stop: ds/dt = g_t - mu g_n (1 + 1/k) s/|s|); not
 *    slipping, it rolls at (g_t - c g_n v/|v|) / (1 + k) until its speed is
 *    zero, where friction can hold that (|m a - m g_t| <= mu m g_n), and
 *    slides otherwise; at rest it sticks where |g_t| <= c g_n and mu g_n;
 * along a line: where g_t is not along the motion (beyond rounding), or the
 * pair has no friction, there is no closed form (MODE_GENERAL).  want is the
 * mode asked for (MODE_SLIDE or MODE_ROLL: that mode's motion, t_stop 0 where
 * it ends at once), or MODE_FREE: the mode the state gives. */
face_motion friction_face(const body *b, const body *s, vec3 g, vec3 n, body_mode want, double hmax, vec3 *lean);

/* True when b is a ball to friction_face: a sphere with its centre of mass at
 * its centre. */
bool friction_ball(const body *b);

/* Rolling resistance at the m points with the impulses z (3m, as
 * friction_cone_solve's): at each point that does not slip (zt strictly inside
 * its cone) and has roll c > 0, two couples of angular impulse up to c r zn
 * each: one against the relative rolling of its objects (their turning across
 * the normal), one against their spinning about the normal,
 * r the distance from the centre of mass of the row's p (its q's when p does
 * not move) to the point; no more than stops that turning.  Applied to the
 * mobile bodies of bs; true when some point has rolling resistance. */
bool friction_roll(const impulse_row *rows, int m, body *const *bs, const bool *mobile,
                   const double *z);

/* The kinetic energy of the mobile bodies of bs among the rows' (each once). */
double friction_energy(const impulse_row *rows, int m, body *const *bs, const bool *mobile);

#endif
