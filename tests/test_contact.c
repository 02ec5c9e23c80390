/* test_contact.c: how contacts are answered (issue 33), each answer derived here.
 *
 * A pair's tolerances come from its moving object, never from a static one's
 * size: a tilted cube lands on floors from 5 m to 10 km wide, and 4.5 km from the
 * origin, with the textbook's impulse and spin, the same on every floor to 1e-9,
 * and a cube at rest sits the same hair above each.  Seams are flat: a cube and
 * a ball slide across the seams of 2, 5 and 20 coplanar tiles without a
 * collision, at the speed they had to 1e-12. */
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

/* ------------------------------------------------------------ flat seams */

/* n static tiles in a row 4 m long and 1 m wide, 0.2 m thick, along u = (cos yaw,
 * sin yaw, 0) and turned with it, tile k's top at z = lift[k] (NULL: 0); the
 * first is object 0. */
static void add_tiles(world *w, int n, double yaw, const double *lift)
{
    vec3 u = v3(cos(yaw), sin(yaw), 0);
    double half = 2.0 / n;
    for (int k = 0; k < n; k++) {
        char name[16];
        snprintf(name, sizeof name, "tile%d", k);
        body *t = add_static_box(w, name, v3(half, 0.5, 0.1));
        body_set_rotation(t, v3(0, 0, 1), yaw);
        t->x = v3_add(v3_scale(u, -2 + (2 * k + 1) * half), v3(0, 0, -0.1 + (lift ? lift[k] : 0)));
    }
}

/* An object (kind, 0.05 m: a cube's half-size, a ball's radius) set amid the
 * first of n tiles (within the contact distance of its top) and sent along the
 * row at 1 m/s, 0.1 rad off it: it slides across the seams, tile after tile,
 * with no collision and its speed unchanged to 1e-12, and keeps its hover gap
 * above each (where the tiles are lifted too). */
static void slides_across(shape_kind kind, int n, double yaw, const double *lift)
{
    world w;
    contact_world(&w);
    add_tiles(&w, n, yaw, lift);
    body *o = kind == SHAPE_SPHERE ? add_ball(&w, "o", 0.05) : add_box(&w, "o", v3(0.05, 0.05, 0.05));
    vec3 u = v3(cos(yaw), sin(yaw), 0), across = v3(-sin(yaw), cos(yaw), 0);
    if (kind != SHAPE_SPHERE) body_set_rotation(o, v3(0, 0, 1), yaw + 0.3);
    double z = 0.05 + (lift ? lift[0] : 0) + 5e-10;
    o->x = v3_add(v3_add(v3_scale(u, -1.9), v3_scale(across, -0.15)), v3(0, 0, z));
    vec3 dir = v3_add(v3_scale(u, cos(0.1)), v3_scale(across, sin(0.1)));
    o->v = dir;
    vec3 x0 = o->x;
    char err[256];
    for (int f = 0; f < 34; f++) {
        assert_int_equal(sim_frame(&w, err, sizeof err), 0);
        assert_int_equal(w.nevents, 0);
        assert_int_equal(o->mode, MODE_SLIDE);
        assert_near(v3_len(o->v), 1, 1e-12);
    }
    /* where its flight says, on the tile under it there, its hover gap above it */
    assert_int_equal(w.st.collisions, 0);
    vec3 dx = v3_sub(o->x, x0);
    assert_near(v3_dot(dx, dir), w.time, 1e-9);
    int under = (int)floor((v3_dot(o->x, u) + 2) / (4.0 / n));
    assert_true(under > 0.8 * (n - 1));
    assert_int_equal(o->slide_on, under);
    double top = lift ? lift[under] : 0, above = o->x.z - 0.05 - top;
    assert_true(above > 0 && above < 1e-7);
    print_message("%s across %d tiles (yaw %g%s): %g m along in %g s onto tile %d, speed %.17g, "
                  "%.3g m above it\n", kind == SHAPE_SPHERE ? "ball" : "cube", n, yaw,
                  lift ? ", lifted" : "", v3_dot(dx, dir), w.time, under, v3_len(o->v), above);
    world_free(&w);
}

static void seams_of_coplanar_tiles_are_flat(void **state)
{
    (void)state;
    const int counts[] = {2, 5, 20};
    for (int c = 0; c < 3; c++) {
        slides_across(SHAPE_CUBE, counts[c], 0, NULL);
        slides_across(SHAPE_SPHERE, counts[c], 0, NULL);
        slides_across(SHAPE_CUBE, counts[c], 0.7, NULL);
        slides_across(SHAPE_SPHERE, counts[c], -2.1, NULL);
    }
    /* tiles whose tops are up to 4e-10 m apart (coplanar within 1e-9 m) */
    double lift[20];
    unsigned long long seed = 5;
    for (int k = 0; k < 20; k++) lift[k] = urand(&seed, -4e-10, 4e-10);
    slides_across(SHAPE_CUBE, 20, 0.4, lift);
    slides_across(SHAPE_SPHERE, 20, 0.4, lift);
}

/* A block slides down a frictionless ramp of three coplanar tiles (turned by 0.3
 * rad; the third thicker, its top in the same plane): across both seams it goes
 * on at g sin(theta) t, with no collision, as on one face. */
static void block_slides_down_a_ramp_of_tiles(void **state)
{
    (void)state;
    const double theta = 0.3;
    world w;
    contact_world(&w);
    vec3 down = v3(cos(theta), 0, -sin(theta)), n = v3(sin(theta), 0, cos(theta));
    const double along[3] = {0, 1, 2.2}, len[3] = {0.5, 0.5, 0.7}, thick[3] = {0.1, 0.1, 0.3};
    for (int k = 0; k < 3; k++) {
        char name[16];
        snprintf(name, sizeof name, "ramp%d", k);
        body *r = add_static_box(&w, name, v3(len[k], 1, thick[k]));
        body_set_rotation(r, v3(0, 1, 0), theta);
        r->x = v3_add(v3_scale(down, along[k]), v3_scale(n, 0.1 - thick[k]));
    }
    body *b = add_box(&w, "block", v3(0.05, 0.05, 0.05));
    body_set_rotation(b, v3(0, 1, 0), theta);
    b->x = v3_add(v3_scale(down, -0.3), v3_scale(n, 0.15 + 5e-10));
    vec3 x0 = b->x;
    w.set.time_step = 0.05;
    char err[256];
    for (int f = 1; f <= 27; f++) {
        assert_int_equal(sim_frame(&w, err, sizeof err), 0);
        double t = w.time, a = G * sin(theta);
        assert_int_equal(w.nevents, 0);
        assert_int_equal(b->mode, MODE_SLIDE);
        assert_rel(v3_dot(b->v, down), a * t, 1e-9);
        assert_rel(v3_dot(v3_sub(b->x, x0), down), 0.5 * a * t * t, 1e-9);
    }
    assert_int_equal(b->slide_on, 2); /* (2.6 m down: on the third) */
    world_free(&w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(tilted_cube_lands_alike_on_every_floor),
        cmocka_unit_test(resting_cube_sits_alike_on_every_floor),
        cmocka_unit_test(seams_of_coplanar_tiles_are_flat),
        cmocka_unit_test(block_slides_down_a_ramp_of_tiles),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
