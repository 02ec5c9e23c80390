/* lcp.h: frictionless contact forces and impulses, as a linear complementarity
 * problem (Baraff, "Fast contact force computation for nonpenetrating rigid
 * bodies", SIGGRAPH 1994, section 4; Cottle and Dantzig 1968).
 *
 * For n contacts with the symmetric positive semidefinite n x n matrix
 * A = J M^-1 J^T (J the contact normals' rows, M the bodies' masses) and a vector
 * q, lcp_solve finds z and w with
 *     w = A z + q,   z >= 0,   w >= 0,   z_i w_i = 0 for each i.
 * At a collision q_i = (1 + e_i) u_i, u_i the relative normal velocity before
 * (negative approaching): z are the impulses and w_i = u_i' + e_i u_i, u_i' the
 * velocity after.  For bodies resting or sliding, q are the normal accelerations
 * without contact forces: z are the forces and w the accelerations.
 *
 * What is unique.  w is, and so is A z = w - q, and so are the bodies' motion
 * M^-1 J^T z and the total push J^T z.  z is not when A is singular (a box's four
 * bottom corners on a floor, a contact given twice): lcp_solve then returns one of
 * many answers, with at most rank(A) forces above zero, deterministic but depending
 * on the contacts' order.  So apply J^T z to the bodies and read w; read a single
 * z_i only when lcp_unique says the forces are determined, or after
 * lcp_least_norm has made z the answer of least norm, which is unique: the same
 * whatever the contacts' order, and symmetric when the problem is (a plank on two
 * equal supports gets equal impulses at both).
 */
#ifndef VROC_LCP_H
#define VROC_LCP_H

#include <stdbool.h>
#include <stddef.h>

/* The accuracy of lcp_solve's answer.  With the size of w_i's terms
 *     s_i = max_j |q_j| + sqrt(A_ii) sum_j sqrt(A_jj) z_j
 * (at most max |q| + max A_jj sum z), every w_i >= -LCP_TOL s_i, and
 * |w_i| <= LCP_TOL s_i wherever z_i > 0. */
#define LCP_TOL 1e-12

/* The caller's workspace for lcp_solve, lcp_unique and lcp_least_norm:
 * lcp_work_size(n) bytes from malloc (or any memory aligned for double).  Nothing
 * in it matters between calls, so one workspace of the largest n serves every
 * call. */
typedef struct lcp_work lcp_work;

/* Bytes of workspace for n contacts: 24 n^2 + 64 n. */
size_t lcp_work_size(int n);

/* Solves the problem above for n >= 0 contacts: A is n x n, row-major, symmetric
 * (both triangles given) and positive semidefinite; q, z and w have n entries; z and
 * w may not alias A or q.  Returns 0 with z >= 0 exactly and w = A z + q (summed in
 * index order) within LCP_TOL.  Returns -1, with z = 0 and w = q, when it finds
 * that no z exists (q asks for what no push can give: a contact whose row of A is
 * zero and q_i < 0, two contacts pushing a body opposite ways both asked to
 * close), when A or q is not finite or some A_ii < 0, or after 100 + 20 n pivots
 * (rounding defeating the theory: never seen in the tests).  The same input gives
 * the same bits. */
int lcp_solve(int n, const double *A, const double *q, double *z, double *w, lcp_work *work);

/* lcp_solve from a guess: z on entry is one, as the answer of a problem like
 * this one just solved (the same A, q moved a little).  The contacts with
 * z_i > 0 (finite) are clamped first, z goes from the guess towards
 * -A_CC^-1 q_C, letting go of the forces that would fall below 0 on the way, and
 * the pivoting goes on from there, so that a good guess leaves fewer pivots to
 * make than one or more a contact.
 * The answer is held to the same conditions as lcp_solve's and returned alike;
 * where the answer is not unique (z, not w) it may be another one. */
int lcp_solve_warm(int n, const double *A, const double *q, double *z, double *w, lcp_work *work);

/* Whether z, a solution from lcp_solve, is the problem's only one: true when the
 * contacts that may carry force (w_i within LCP_TOL of 0) have independent rows of A,
 * so their z_i are determined.  False when they do not: z is then one of many,
 * except in degenerate cases where contacts without force pin the others (false is
 * on the safe side). */
bool lcp_unique(int n, const double *A, const double *q, const double *z, lcp_work *work);

/* Makes z, a solution from lcp_solve, the problem's solution of least Euclidean
 * norm: the same w (to rounding), z >= 0 exactly, and among all such z the
 * shortest, which is unique.  Where the contacts that carry force have dependent
 * rows (a box's four bottom corners, a plank's eight on two supports), it spreads
 * the force over them as evenly as their rows allow.  Leaves z as it is when
 * lcp_unique holds. */
void lcp_least_norm(int n, const double *A, const double *q, double *z, lcp_work *work);

#endif
