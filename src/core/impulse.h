/* impulse.h: contacts answered together: the impulses of a collision, and the
 * kicks that keep bodies pressed together apart (thesis 3.2.2, extended to many
 * contacts at once; design.md, "Dynamics").
 *
 * Each row is a point where two objects press: p gets the impulse +lambda n, q
 * gets -lambda n, n the unit normal from q to p, at the world point `at`.  The
 * impulses can only push (lambda >= 0), and each row obeys Newton's law of
 * restitution with its own e: the relative normal velocity after it is at least
 * -e times the one before, and exactly that where it pushes (a linear
 * complementarity problem, lcp.h, over the matrix J M^-1 J^T of the rows).  With e
 * = 1 on every row no energy is lost; what rows that only rest (no approach)
 * cannot absorb moves the objects.  Bodies not marked mobile have infinite mass.
 */
#ifndef VROC_IMPULSE_H
#define VROC_IMPULSE_H

#include <stdbool.h>

#include "body.h"
#include "lcp.h"

/* Rows one problem may hold. */
#define IMPULSE_MAX_ROWS 64

typedef struct {
    int p, q;    /* body indices */
    vec3 n, at;  /* unit normal from q to p; where the impulse acts (world) */
    double e;    /* restitution of this row */
    double mu;   /* Coulomb's coefficient at it (friction.h), */
    double roll; /*   and its rolling resistance */
} impulse_row;

/* The relative normal velocity of row r (> 0 separating) with the bodies in bs
 * (indexed as the rows are). */
double impulse_speed(const impulse_row *r, body *const *bs);

/* The matrix A (n x n, row-major) of the rows: A[j][k] is row j's change of
 * relative normal velocity for a unit impulse at row k. */
void impulse_matrix(const impulse_row *rows, int n, body *const *bs, const bool *mobile,
                    double *A);

/* Row k's unit impulse's effect on its bodies (as impulse_matrix finds it): on
 * its p, the change of linear and of angular velocity (resp[0], resp[1]), on its
 * q (resp[2], resp[3]); zero for a body that does not move. */
void impulse_response(const impulse_row *rk, body *const *bs, const bool *mobile, vec3 resp[4]);

/* Row k's effect on row j, from row k's response: impulse_matrix's A[j][k]
 * before it is made symmetric (the mean of this and row j's effect on row k),
 * to the bit, for a matrix built in parts (friction.h's crowds). */
double impulse_effect(const impulse_row *rj, const impulse_row *rk, const vec3 resp[4], body *const *bs,
                      const bool *mobile);

/* Applies impulses lambda at the rows to the mobile bodies of bs (their v, L, w).
 * (A row along a tangent, friction.h, may have lambda < 0.) */
void impulse_apply(const impulse_row *rows, int n, body *const *bs, const bool *mobile,
                   const double *lambda);

/* Solves the rows' impulses (Newton's law with each row's e; u_before the rows'
 * relative normal velocities before, from impulse_speed) and applies them.
 * lambda gets the impulses: of the many that give the same velocities where rows
 * are dependent, those of least norm (lcp_least_norm), so that they do not
 * depend on the rows' order and are symmetric where the contacts are.  Returns 0, or -1 when the problem has too many rows or
 * cannot be solved (nothing is applied then).  work: lcp_work_size(IMPULSE_MAX_ROWS)
 * bytes. */
int impulse_solve(const impulse_row *rows, int n, body *const *bs, const bool *mobile,
                  const double *u_before, double *lambda, lcp_work *work);

/* impulse_solve for any n, in the caller's room: A (n x n), q and w (n each),
 * work lcp_work_size(n) bytes (a cluster's rows, rows.h).  Beyond
 * IMPULSE_MAX_ROWS rows lambda is one answer of many where rows are dependent
 * (not least-norm): the same motion, for callers that read only that. */
int impulse_solve_in(const impulse_row *rows, int n, body *const *bs, const bool *mobile,
                     const double *u_before, double *lambda, lcp_work *work, double *A, double *q,
                     double *w);

/* Whether impulse_solve's frictionless problem has an answer (0) or not (-1),
 * nothing applied: a held object that pushes what cannot give way leaves none
 * (squeeze.h), and a cone solve, which always returns its best, cannot tell. */
int impulse_solvable(const impulse_row *rows, int n, body *const *bs, const bool *mobile,
                     const double *u_before, lcp_work *work);

#endif
