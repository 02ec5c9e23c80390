/* test_contact.c: how contacts are answered (issue 33), each answer derived here.
 *
 * A pair's tolerances come from its moving object, never from a static one's
 * size: a tilted cube lands on floors from 5 m to 10 km wide, and 4.5 km from the
 * origin, with the textbook's impulse and spin, the same on every floor to 1e-9,
 * and a cube at rest sits the same hair above each. */
#include "check.h"

#include <stdlib.h>
#include <string.h>

#include "core/body.h"
#include "core/sim.h"
#include "core/world.h"
#include "worlds.h"

static const double G = 9.8;

/* A world under gravity (g along -z) with speed limits far above what the tests
 * reach. */
static void contact_world(world *w)
{
    world_init(w);
    w->set.force = (dir_amount){v3(0, 0, -1), G};
    w->set.max_linear = 100;
    w->set.max_angular = 1000;
}

/* A static floor: a box of half-extents (half, half, 0.5), its top face at z = 0. */
static body *add_floor(world *w, const char *name, double half)
{
    body *f = add_static_box(w, name, v3(half, half, 0.5));
    f->x = v3(0, 0, -0.5);
    return f;
}

/* ------------------------------------------ tolerances from the moving object */

/* The floors' half-widths: 5 m to 10 km wide. */
static const double FLOORS[] = {2.5, 25, 250, 2500, 5000};
#define NFLOORS (int)(sizeof FLOORS / sizeof FLOORS[0])

typedef struct {
    double j, spin, speed; /* the impulse, |w| after it, the closing speed */
} landing;

/* A cube of half-size a (mass 1, e = 0.5), turned by theta about y, dropped with
 * its lowest edge h above the top of a floor of half-width half, over the point
 * (x, y): its first collision, with the state just after it. */
static landing land(double half, double a, double theta, double x, double y, double h)
{
    world w;
    contact_world(&w);
    add_floor(&w, "floor", half);
    body *c = add_box(&w, "cube", v3(a, a, a));
    c->elasticity = 0.5;
    body_set_rotation(c, v3(0, 1, 0), theta);
    double below = a * (sin(theta) + cos(theta)); /* its lowest edge, under its centre */
    c->x = v3(x, y, h + below);
    /* one frame that ends just after it lands: the other edge lands a few
     * milliseconds later */
    w.set.time_step = sqrt(2 * h / G) + 1e-6;
    char err[256];
    assert_int_equal(sim_frame(&w, err, sizeof err), 0);
    assert_int_equal(w.nevents, 1);
    landing l = {w.events[0].j, v3_len(c->w), w.events[0].speed};
    world_free(&w);
    return l;
}

/* It lands on one edge, the textbook's rigid impact there: with the edge at
 * r_x = a (cos theta - sin theta) across from the centre and I = 2/3 m a^2,
 *   j = (1 + e) v / (1/m + r_x^2 / I),   |w| = j r_x / I,
 * v = sqrt(2 g h).  On every floor, and far from the origin, the same to 1e-9. */
static void tilted_cube_lands_alike_on_every_floor(void **state)
{
    (void)state;
    const double sizes[] = {0.05, 0.1, 0.5}, tilts[] = {0.005, 0.02, 0.1}, h = 1.1;
    for (int s = 0; s < 3; s++) {
        for (int k = 0; k < 3; k++) {
            double a = sizes[s], theta = tilts[k];
            landing ref = land(FLOORS[0], a, theta, 0, 0, h);
            double rx = a * (cos(theta) - sin(theta)), I = 2.0 / 3.0 * a * a;
            double v = sqrt(2 * G * h), j = 1.5 * v / (1 + rx * rx / I);
            assert_rel(ref.speed, v, 1e-8);
            assert_rel(ref.j, j, 1e-7);
            assert_rel(ref.spin, j * rx / I, 1e-7);
            for (int f = 1; f <= NFLOORS; f++) {
                /* the last: on the widest floor, 4.5 km from the origin */
                bool far = f == NFLOORS;
                double half = FLOORS[far ? NFLOORS - 1 : f], at = far ? 3200 : 0;
                landing l = land(half, a, theta, at, at, h);
                if (s == 1 && k == 1)
                    print_message("cube %g tilted %g on a %g m floor%s: j %.15g (5 m: %.15g), |w| "
                                  "%.15g (%.15g)\n", a, theta, 2 * half, far ? ", 4.5 km out" : "",
                                  l.j, ref.j, l.spin, ref.spin);
                assert_rel(l.j, ref.j, 1e-9);
                assert_rel(l.spin, ref.spin, 1e-9);
            }
        }
    }
}

/* A cube of half-size a set flat 1 mm above a floor of half-width half at (x, y)
 * (e = 0.5) comes to rest: the height of its centre above the floor's top. */
static double rest_height(double half, double a, double x, double y)
{
    world w;
    contact_world(&w);
    add_floor(&w, "floor", half);
    body *c = add_box(&w, "cube", v3(a, a, a));
    c->elasticity = 0.5;
    c->x = v3(x, y, a + 1e-3);
    char err[256];
    for (int f = 0; f < 100 && c->state != STATE_RESTING; f++)
        assert_int_equal(sim_frame(&w, err, sizeof err), 0);
    assert_int_equal(c->state, STATE_RESTING);
    assert_near(c->x.x, x, 1e-12 * (1 + fabs(x)));
    double z = c->x.z;
    world_free(&w);
    return z;
}

/* At rest a cube sits a hair above the floor (the hover gap, a hundred-millionth
 * of its size plus 1e-8 m), and the same hair above every floor, to 1e-9. */
static void resting_cube_sits_alike_on_every_floor(void **state)
{
    (void)state;
    const double sizes[] = {0.05, 0.3, 2};
    for (int s = 0; s < 3; s++) {
        double a = sizes[s], ref = rest_height(FLOORS[0], a, 0, 0);
        assert_true(ref > a);
        assert_true(ref - a < 1e-8 * (1 + 4 * a));
        for (int f = 1; f <= NFLOORS; f++) {
            bool far = f == NFLOORS;
            double half = FLOORS[far ? NFLOORS - 1 : f], at = far ? 3200 : 0;
            double z = rest_height(half, a, at, at);
            if (s == 1)
                print_message("cube %g at rest on a %g m floor%s: %.3g m above its face (5 m: %.3g)\n",
                              a, 2 * half, far ? ", 4.5 km out" : "", z - a, ref - a);
            assert_rel(z, ref, 1e-9);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(tilted_cube_lands_alike_on_every_floor),
        cmocka_unit_test(resting_cube_sits_alike_on_every_floor),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
