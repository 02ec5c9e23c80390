/* check.h: what every cmocka unit test of vroc includes.
 *
 * cmocka needs its headers in this order; the tolerance macros print both values
 * and the tolerance when they fail, so a failing physics test says by how much. */
#ifndef VROC_TEST_CHECK_H
#define VROC_TEST_CHECK_H

#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <math.h>
#include <cmocka.h>

#include "core/vmath.h"

/* |a - b| <= tol */
#define assert_near(a, b, tol)                                                           \
    do {                                                                                 \
        double a_ = (a), b_ = (b), t_ = (tol);                                           \
        if (!(fabs(a_ - b_) <= t_))                                                      \
            fail_msg("%s = %.17g, %s = %.17g, differ by %.3g > %.3g", #a, a_, #b, b_,    \
                     fabs(a_ - b_), t_);                                                 \
    } while (0)

/* |a - b| <= tol * max(|b|, tiny) */
#define assert_rel(a, b, tol)                                                            \
    do {                                                                                 \
        double a_ = (a), b_ = (b), t_ = (tol);                                           \
        double s_ = fabs(b_) > 1e-300 ? fabs(b_) : 1e-300;                               \
        if (!(fabs(a_ - b_) <= t_ * s_))                                                 \
            fail_msg("%s = %.17g, %s = %.17g, relative difference %.3g > %.3g", #a, a_,  \
                     #b, b_, fabs(a_ - b_) / s_, t_);                                    \
    } while (0)

#define assert_vec_near(a, b, tol)                                                       \
    do {                                                                                 \
        vec3 va_ = (a), vb_ = (b);                                                       \
        assert_near(va_.x, vb_.x, tol);                                                  \
        assert_near(va_.y, vb_.y, tol);                                                  \
        assert_near(va_.z, vb_.z, tol);                                                  \
    } while (0)

#endif
