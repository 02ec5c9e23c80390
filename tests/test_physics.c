/* test_physics.c: the textbook setups of issue 23, each answer derived here.
 *
 * A frictionless block slides down a ramp at g sin(theta) and, shoved up it,
 * comes back after 2 u / (g sin(theta)); a resting ball struck by an equal ball
 * leaves at (1 + e) u sin(a) cos(a) / (1 + sin^2 a); an overhanging cube tips off
 * and one held by the cube below rests; a frictionless 3-2-1 pyramid of balls
 * collapses in finite work; a ball sliding off a table edge flies the projectile
 * parabola, or pivots on the edge and leaves it where cos(phi) = (2 + v^2/(g r))/3;
 * energy is kept across two contacts within a millisecond and in a closed box of
 * mixed objects; free rotation keeps energy and angular momentum and follows
 * Euler's equations; a spinning rod touches a thin plate first when root finding
 * says it does; thin plates stop small fast balls whatever collision_dist.
 * The energy and momenta of energy.h are the textbook's.
 * Every test raises max_linear and max_angular above the speeds it reaches. */
#include "check.h"

#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core/body.h"
#include "core/energy.h"
#include "core/sim.h"
#include "core/world.h"
#include "worlds.h"

static const double G = 9.8;
static const double PI = 3.14159265358979323846;
/* An object on a face stays on it within a contact's thickness (SIM_CONTACT_TOL
 * of the pair's size; lasting contacts are kept SIM_HOVER of it apart). */
static const double ON_FACE = 1e-6;

static void frames(world *w, int n)
{
    char err[256];
    for (int i = 0; i < n; i++) assert_int_equal(sim_frame(w, err, sizeof err), 0);
}

/* A world under gravity (g along -z) with speed limits well above what the test
 * reaches. */
static void physics_world(world *w, double max_linear, double max_angular)
{
    world_init(w);
    w->set.force = (dir_amount){v3(0, 0, -1), G};
    w->set.max_linear = max_linear;
    w->set.max_angular = max_angular;
}

static int index_of(const world *w, const body *b)
{
    for (int i = 0; i < w->n; i++)
        if (w->bodies[i] == b) return i;
    fail_msg("body %s not in the world", b->name);
    return -1;
}

/* The first collision of the last frame between a and b, or NULL. */
static const sim_event *event_between(const world *w, const body *a, const body *b)
{
    int ia = index_of(w, a), ib = index_of(w, b);
    for (long k = 0; k < w->nevents; k++) {
        const sim_event *e = &w->events[k];
        if ((e->a == ia && e->b == ib) || (e->a == ib && e->b == ia)) return e;
    }
    return NULL;
}

/* Kinetic energy of every object, and kinetic plus potential (m g z of the centre
 * of mass) under gravity g. */
static double kinetic(const world *w)
{
    double e = 0;
    for (int i = 0; i < w->n; i++) e += body_energy(w->bodies[i]);
    return e;
}

static double total_energy(const world *w, double g)
{
    double e = kinetic(w);
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        if (!body_is_static(b)) e += b->mass * g * body_com(b).z;
    }
    return e;
}

/* Places b turned by q (axis and angle kept as typed), with no spin. */
static void set_orientation(body *b, quat q)
{
    vec3 axis;
    double angle;
    q_to_axis_angle(q, &axis, &angle);
    body_set_rotation(b, axis, angle);
    body_set_angular_vel(b, v3(0, 0, 0));
}

/* ------------------------------------------------------------------ ramps */

/* A frictionless ramp: a still box of half-extents (3, 3, 0.1) turned by theta
 * about the level axis `axis`, and a block of half-extents (0.2, 0.15, 0.05) lying
 * on it, turned by yaw about the ramp's normal, 0.5e-9 m off its face (within
 * the contact distance), its centre s m down the slope from the ramp's centre.
 * Gives the ramp's normal n and the unit vector d down the slope. */
static body *block_on_ramp(world *w, double theta, vec3 axis, double yaw, double s, vec3 *n,
                           vec3 *d)
{
    physics_world(w, 50, 50);
    body *ramp = add_static_box(w, "ramp", v3(3, 3, 0.1));
    body_set_rotation(ramp, axis, theta);
    *n = q_rotate(ramp->q, v3(0, 0, 1));
    /* down the slope: -z less its part along n; |that| = sin(theta) */
    vec3 down = v3_mad(v3(0, 0, -1), *n, n->z);
    assert_near(v3_len(down), sin(theta), 1e-12);
    *d = v3_norm(down);
    body *block = add_box(w, "block", v3(0.2, 0.15, 0.05));
    block->elasticity = 0.5; /* rest would be allowed, were the block held */
    set_orientation(block, q_mul(q_axis_angle(*n, yaw), ramp->q));
    block->x = v3_add(v3_scale(*n, 0.1 + 0.05 + 0.5e-9), v3_scale(*d, s));
    return block;
}

/* Released at rest, the block slides down at g sin(theta): s = g sin(theta) t^2 / 2,
 * neither leaving the face nor turning. */
static void slides_at_g_sin_theta(double theta, vec3 axis, double yaw)
{
    world w;
    vec3 n, d;
    body *block = block_on_ramp(&w, theta, axis, yaw, -2, &n, &d);
    vec3 x0 = block->x;
    quat q0 = block->q;
    const double a = G * sin(theta);
    for (int f = 1; f <= 10; f++) {
        frames(&w, 1);
        double t = w.time, want = 0.5 * a * t * t;
        vec3 dx = v3_sub(block->x, x0);
        if (f == 1 || f == 10)
            print_message("ramp %.0f deg: t %.2f, down the slope %.12f (want %.12f), off the face "
                          "%.3g, state %d\n", theta * 180 / PI, t, v3_dot(dx, d), want,
                          v3_dot(dx, n), block->state);
        assert_int_equal(block->state, STATE_DYNAMIC);
        assert_rel(v3_dot(dx, d), want, 1e-6);
        assert_near(v3_dot(dx, n), 0, ON_FACE);
        assert_rel(v3_dot(block->v, d), a * t, 1e-6);
        assert_near(fabs(q0.w * block->q.w + q0.x * block->q.x + q0.y * block->q.y + q0.z * block->q.z),
                    1, 1e-12);
    }
    world_free(&w);
}

/* Shoved up the slope at u, the block stops at the top of its run (at the end of
 * a frame: the hardest moment for rest) and is back where it started after
 * T = 2 u / (g sin(theta)), at u down the slope: s(t) = -u t + g sin(theta) t^2 / 2. */
static void returns_after_2u_over_g_sin_theta(double theta, vec3 axis, double yaw, double u)
{
    world w;
    vec3 n, d;
    body *block = block_on_ramp(&w, theta, axis, yaw, -0.5, &n, &d);
    const double a = G * sin(theta), T = 2 * u / a;
    block->v = v3_scale(d, -u);
    w.set.time_step = T / 6; /* the top of the run at the end of frame 3 */
    vec3 x0 = block->x;
    for (int f = 1; f <= 6; f++) {
        frames(&w, 1);
        double t = w.time;
        vec3 dx = v3_sub(block->x, x0);
        assert_near(v3_dot(dx, d), -u * t + 0.5 * a * t * t, 1e-8);
        assert_near(v3_dot(dx, n), 0, ON_FACE);
        assert_near(v3_dot(block->v, d), -u + a * t, 1e-8);
        assert_int_equal(block->state, STATE_DYNAMIC);
    }
    assert_near(w.time, T, 1e-12);
    print_message("ramp %.0f deg shoved at %g m/s: back after T = %.6f s %.3g m from the start along "
                  "the slope (%.3g off the face), at %.9f m/s down it\n", theta * 180 / PI, u, T,
                  v3_dot(v3_sub(block->x, x0), d), v3_dot(v3_sub(block->x, x0), n),
                  v3_dot(block->v, d));
    assert_near(v3_dot(v3_sub(block->x, x0), d), 0, 1e-8); /* back where it started */
    assert_rel(v3_dot(block->v, d), u, 1e-8);
    world_free(&w);
}

static void frictionless_block_slides_on_a_ramp(void **state)
{
    (void)state;
    const double deg = PI / 180;
    slides_at_g_sin_theta(20 * deg, v3(0, 1, 0), 0);
    slides_at_g_sin_theta(35 * deg, v3(0, 1, 0), 0);
    slides_at_g_sin_theta(27 * deg, v3(1, 1, 0), 0.3); /* any level axis, any yaw */
    slides_at_g_sin_theta(35 * deg, v3(-1, 0.4, 0), 1.1);
}

static void block_shoved_up_a_ramp_comes_back(void **state)
{
    (void)state;
    const double deg = PI / 180;
    returns_after_2u_over_g_sin_theta(20 * deg, v3(0, 1, 0), 0, 1);
    returns_after_2u_over_g_sin_theta(35 * deg, v3(0, 1, 0), 0, 1.5);
    returns_after_2u_over_g_sin_theta(27 * deg, v3(1, 1, 0), 0.3, 1.2);
}

/* ------------------------------------------------- a resting ball struck */

/* A ball of radius r rests on the floor; an equal ball falls on it at u, the line
 * of centres n at alpha from the vertical (towards azimuth beta).  In the limit of
 * vanishing gaps (instant.h) the lower ball takes the blow along n as a free ball
 * would, the floor answers it along z with its restitution, and the balls again
 * if they close: each contact in turn a textbook impact (balls_on_floor, which
 * derives it).  The floor pushes along z only, so horizontal momentum is kept,
 * and the lower ball goes off along the azimuth, away from the upper one. */
static void struck_resting_ball(double alpha, double beta, double e_low, double e_top, double u)
{
    world w;
    physics_world(&w, 50, 50);
    w.set.time_step = 0.05;
    const double r = 0.1, gap = 0.01, e = d_min(e_low, e_top);
    add_static_box(&w, "floor", v3(3, 3, 0.1)); /* its top at z = 0.1 */
    body *low = add_ball(&w, "low", r);
    low->elasticity = e_low;
    low->x = v3(0.3, -0.2, 0.1 + r + 0.5e-9);
    body *top = add_ball(&w, "top", r);
    top->elasticity = e_top;
    top->x = v3(2, 2, 5); /* out of the way until it is thrown */
    frames(&w, 3);
    int low_state = low->state;
    assert_int_equal(low_state, STATE_RESTING); /* still, on a level floor */
    vec3 rest = low->x;
    assert_near(rest.z, 0.1 + r, ON_FACE);
    /* thrown so that it meets the lower ball at u, gap m of fall later */
    vec3 n = v3(sin(alpha) * cos(beta), sin(alpha) * sin(beta), cos(alpha));
    top->x = v3_add(v3_add(rest, v3_scale(n, 2 * r)), v3(0, 0, gap));
    double v0 = sqrt(u * u - 2 * G * gap);
    top->v = v3(0, 0, -v0);
    w.sched_dirty = true; /* as after a command */
    double t0 = w.time, ti = (u - v0) / G;
    w.set.time_step = ti + 1e-6; /* a frame that ends just after the blow */
    frames(&w, 1);
    const sim_event *ev = event_between(&w, low, top);
    assert_non_null(ev);
    vec3 v_top = v3(0, 0, -u), v_low = v3(0, 0, 0);
    double j12, j2f;
    int waves = balls_on_floor(1, &v_top, 1, &v_low, n, e, d_min(e_low, 1), &j12, &j2f);
    double after = w.time - ev->t;
    vec3 want_low = v_low, want_top = v3_add(v_top, v3(0, 0, -G * after));
    if (want_low.z > 0) want_low.z -= G * after; /* off the floor, it flies */
    double got = -(low->v.x * cos(beta) + low->v.y * sin(beta)); /* away from the top ball */
    double want = -(want_low.x * cos(beta) + want_low.y * sin(beta));
    print_message("struck ball: alpha %.0f deg, e %.2f (state %d before): %d waves, leaves at %.9f m/s, "
                  "want %.9f; v.z %.6f, want %.6f; blow at %.9f s, want %.9f\n", alpha * 180 / PI, e,
                  low_state, waves, got, want, low->v.z, want_low.z, ev->t - t0, ti);
    assert_near(ev->t - t0, ti, 1e-6);
    assert_rel(ev->j, j12, 1e-6);
    assert_true(v3_dist(low->v, want_low) < 1e-6 * u);
    assert_true(v3_dist(top->v, want_top) < 1e-6 * u);
    assert_true(got > 0);
    assert_near(low->v.x * sin(beta) - low->v.y * cos(beta), 0, 1e-9 * u); /* along the azimuth */
    /* the floor pushes along z only: the horizontal momentum (0) is kept */
    assert_near(low->v.x + top->v.x, 0, 1e-9 * u);
    assert_near(low->v.y + top->v.y, 0, 1e-9 * u);
    world_free(&w);
}

static void resting_ball_struck_from_above_leaves_sideways(void **state)
{
    (void)state;
    const double deg = PI / 180;
    const double alphas[] = {45 * deg, 30 * deg, 60 * deg};
    const double es[][2] = {{1, 1}, {0.5, 0.8}}; /* e = min(e_low, e_top) */
    for (size_t i = 0; i < 3; i++)
        for (size_t k = 0; k < 2; k++) struck_resting_ball(alphas[i], 0.7, es[k][0], es[k][1], 2);
}

/* -------------------------------------------------- an overhanging cube */

/* Two cubes of half-side 0.1 on a floor (its top at z = 0.1), frictionless,
 * restitution 0.5, the upper one shifted by dx along x.  Its centre of mass over
 * the lower cube's top face (|dx| < 0.1), it rests there; past its edge, nothing
 * holds it: it tips off, its centre below the lower cube's top (z = 0.3). */
static void overhanging_cube(double dx, bool tips)
{
    world w;
    physics_world(&w, 50, 100);
    add_static_box(&w, "floor", v3(3, 3, 0.1));
    body *low = add_box(&w, "low", v3(0.1, 0.1, 0.1));
    low->elasticity = 0.5;
    low->x = v3(0, 0, 0.2 + 0.5e-9);
    body *top = add_box(&w, "top", v3(0.1, 0.1, 0.1));
    top->elasticity = 0.5;
    top->x = v3(dx, 0, 0.4 + 1e-9);
    vec3 x0 = top->x;
    frames(&w, 30);
    print_message("cube shifted by %.2f m (centre %.2f m %s the edge): after 3 s at (%.4f, %.4f, "
                  "%.4f), states %d %d, %ld collisions\n", dx, fabs(dx - 0.1),
                  dx > 0.1 ? "past" : "inside", top->x.x, top->x.y, top->x.z, low->state,
                  top->state, w.st.collisions);
    if (tips) {
        assert_true(top->x.z < 0.3);
    } else {
        assert_int_equal(top->state, STATE_RESTING);
        assert_int_equal(low->state, STATE_RESTING);
        assert_true(v3_dist(top->x, x0) < 1e-6);
        long checks = w.st.pair_checks;
        frames(&w, 10); /* resting costs nothing */
        assert_int_equal(w.st.pair_checks, checks);
    }
    world_free(&w);
}

static void overhanging_cube_tips_off(void **state)
{
    (void)state;
    overhanging_cube(0.19, true);  /* centre of mass 9 cm past the edge */
    overhanging_cube(0.11, true);  /* 1 cm past */
    overhanging_cube(0.02, false); /* its side 2 cm over the edge, its centre well inside */
    overhanging_cube(0.09, false); /* its centre 1 cm inside the edge */
}

/* ------------------------------------------------------------ a pyramid */

/* A 3-2-1 pyramid of frictionless balls of radius 0.1 on a floor, each 0.5e-9 m
 * off its neighbours, restitution 0.5, of the given masses (bottom row, middle
 * row, top): nothing holds the bottom row together, so it spreads and the
 * pyramid falls, in finitely many collisions (none once the balls have parted). */
static void pyramid(const double mass[6])
{
    world w;
    physics_world(&w, 50, 100);
    const double r = 0.1, gap = 0.5e-9, d = 2 * r + gap, h = d * sqrt(3) / 2;
    add_static_box(&w, "floor", v3(20, 20, 0.1)); /* its top at z = 0.1 */
    const double z0 = 0.1 + r + gap;
    const vec3 at[6] = {{-d, 0, z0},         {0, 0, z0},         {d, 0, z0},
                        {-d / 2, 0, z0 + h}, {d / 2, 0, z0 + h}, {0, 0, z0 + 2 * h}};
    body *ball[6];
    for (int i = 0; i < 6; i++) {
        char name[8];
        snprintf(name, sizeof name, "b%d", i);
        ball[i] = add_ball(&w, name, r);
        ball[i]->elasticity = 0.5;
        body_set_mass(ball[i], mass[i]);
        ball[i]->x = at[i];
    }
    assert_int_equal(sim_penetrations(&w, NULL, NULL), 0);
    frames(&w, 30);
    long hits3 = w.st.collisions;
    frames(&w, 20);
    print_message("pyramid (masses %g %g %g / %g %g / %g): after 5 s, %ld collisions (%ld in the "
                  "last 2 s), %ld pair checks\n", mass[0], mass[1], mass[2], mass[3], mass[4],
                  mass[5], w.st.collisions, w.st.collisions - hits3, w.st.pair_checks);
    for (int i = 0; i < 6; i++)
        print_message("  b%d from (%.3f, %.3f) to (%.4f, %.4f), state %d\n", i, at[i].x, at[i].z,
                      ball[i]->x.x, ball[i]->x.z, ball[i]->state);
    assert_true(ball[5]->x.z < at[5].z - r);
    assert_true(ball[0]->x.x < at[0].x - r);
    assert_true(ball[2]->x.x > at[2].x + r);
    for (int i = 0; i < 6; i++) assert_true(ball[i]->x.z > 0.1); /* all on (or over) the floor */
    assert_true(w.st.collisions < 1000);
    assert_int_equal(w.st.collisions, hits3); /* none once they have parted */
    world_free(&w);
}

static void frictionless_pyramid_collapses(void **state)
{
    (void)state;
    pyramid((const double[6]){1, 1, 1, 1, 1, 1});
    pyramid((const double[6]){1.5, 1, 0.7, 1.2, 0.9, 2}); /* no symmetry to hold it */
}

/* --------------------------------------------------------- off a table */

/* A table with its top at z = 0.05 and its edge at x = 0.5, a floor with its top
 * at z = -1, and a frictionless ball of radius r on the table at x = x0, sliding
 * at v along x with no spin. */
static body *ball_on_table(world *w, double time_step, double r, double x0, double v)
{
    physics_world(w, 50, 50);
    w->set.time_step = time_step;
    add_static_box(w, "table", v3(0.5, 0.5, 0.05));
    add_static_box(w, "floor", v3(5, 5, 0.1))->x = v3(0, 0, -1.1);
    body *ball = add_ball(w, "ball", r);
    ball->elasticity = 0.5;
    ball->x = v3(x0, 0.1, 0.05 + r + 0.5e-9);
    ball->v = v3(v, 0, 0);
    return ball;
}

/* v^2 >= g r: at the edge gravity cannot turn it round the edge (it would need
 * v^2 / r), so it leaves the table as its centre passes the edge, at t_e =
 * (0.5 - x0) / v, and flies the projectile parabola from there: it meets the
 * floor when its centre has fallen 0.05 + r + 1 - r = 1.05 m, after
 * tau = sqrt(2 * 1.05 / g), at x = 0.5 + v tau. */
static double flies_the_parabola(double time_step, double v)
{
    world w;
    const double r = 0.1, x0 = 0.1;
    body *ball = ball_on_table(&w, time_step, r, x0, v);
    body *floor = w.bodies[1];
    const double te = (0.5 - x0) / v, tau = sqrt(2 * 1.05 / G), x_land = 0.5 + v * tau;
    const sim_event *ev = NULL;
    for (int f = 0; f < 400 && !ev; f++) {
        frames(&w, 1);
        ev = event_between(&w, ball, floor);
    }
    assert_non_null(ev);
    print_message("off the table at %.2f m/s, time_step %.3f: lands at x %.7f (want %.7f, %+.3g m), "
                  "t %.7f (want %.7f, %+.3g s)\n", v, time_step, ev->p.x, x_land, ev->p.x - x_land,
                  ev->t, te + tau, ev->t - te - tau);
    assert_near(ev->p.y, 0.1, 1e-9);
    assert_near(ev->p.z, -1, 1e-6);
    double miss = fabs(ev->p.x - x_land);
    world_free(&w);
    return miss;
}

/* v^2 < g r: the ball's centre turns round the edge on a circle of radius r (no
 * spin: the frictionless edge pushes through the centre), until the edge's push
 * is 0: with phi from the vertical, V^2 = v^2 + 2 g r (1 - cos(phi)) and
 * V^2 / r = g cos(phi), so cos(phi) = (2 + v^2 / (g r)) / 3.  It then flies
 * freely, keeping its horizontal speed V cos(phi) = sqrt(g r) cos(phi)^(3/2)
 * (the floor it lands on pushes along z only): cos(phi) = (vx^2 / (g r))^(1/3). */
static void pivots_on_the_edge(double time_step, double v)
{
    world w;
    const double r = 0.1, x0 = 0.3;
    body *ball = ball_on_table(&w, time_step, r, x0, v);
    frames(&w, (int)ceil(2.0 / time_step)); /* 2 s: it has left and landed */
    double want = (2 + v * v / (G * r)) / 3;
    double got = cbrt(ball->v.x * ball->v.x / (G * r));
    print_message("slow ball at %.2f m/s, time_step %.3f: leaves the edge at cos(phi) %.6f (want "
                  "%.6f, %.2f deg), vx %.6f; at (%.3f, %.3f)\n", v, time_step, got, want,
                  acos(want) * 180 / PI, ball->v.x, ball->x.x, ball->x.z);
    assert_true(ball->x.z < 0); /* off the table */
    assert_near(got, want, 1e-3);
    assert_near(ball->v.y, 0, 1e-9);
    world_free(&w);
}

static void ball_off_a_table_flies_the_parabola(void **state)
{
    (void)state;
    const double steps[] = {0.1, 0.05, 0.013}, speeds[] = {1.5, 1.1, 3.0}; /* g r = 0.98 */
    double worst = 0;
    for (size_t k = 0; k < 3; k++)
        for (size_t i = 0; i < 3; i++) worst = fmax(worst, flies_the_parabola(steps[k], speeds[i]));
    assert_near(worst, 0, 1e-4); /* the worst landing point's distance from the closed form */
}

static void slow_ball_pivots_on_the_table_edge(void **state)
{
    (void)state;
    const double steps[] = {0.1, 0.05, 0.013};
    for (size_t k = 0; k < 3; k++) {
        pivots_on_the_edge(steps[k], 0.5);
        pivots_on_the_edge(steps[k], 0.8);
    }
}

/* ---------------------------------------------------------------- energy */

/* Elasticity 1 everywhere, gravity: a cube spinning about the vertical falls
 * flat towards the floor (its top at z = 0) at 2 m/s, its bottom there at
 * t2 = 0.05 s; a ball falls faster onto its top face, off centre, at t1 = t2 -
 * 1 ms (the gap closes at their relative speed, 2 m/s: gravity moves both
 * alike).  Both contacts fall in one internal step.  Energy (kinetic plus
 * potential) is kept to 1e-6 of the kinetic energy through them and the
 * bounces after. */
static void energy_kept_across_two_contacts_within_a_millisecond(void **state)
{
    (void)state;
    world w;
    physics_world(&w, 20, 1000);
    add_static_box(&w, "floor", v3(3, 3, 0.1))->x = v3(0, 0, -0.1);
    const double t2 = 0.05, t1 = t2 - 0.001, vc = 2, vb = 4;
    body *cube = add_box(&w, "cube", v3(0.1, 0.1, 0.1));
    cube->x = v3(0, 0, 0.1 + vc * t2 + 0.5 * G * t2 * t2);
    cube->v = v3(0.2, 0, -vc);
    body_set_angular_vel(cube, v3(0, 0, 6));
    body *ball = add_ball(&w, "ball", 0.05);
    body_set_mass(ball, 0.5);
    /* over the point (0.03, 0.02) of the cube's top at t1 */
    ball->x = v3(0.03 - 0.5 * t1, 0.02, cube->x.z + 0.1 + 0.05 + (vb - vc) * t1);
    ball->v = v3(0.7, 0, -vb);
    double k0 = kinetic(&w), e0 = total_energy(&w, G), worst = 0;
    frames(&w, 1);
    const sim_event *hit = event_between(&w, cube, ball), *land = event_between(&w, cube, w.bodies[0]);
    assert_non_null(hit);
    assert_non_null(land);
    double t_hit = hit->t, t_land = land->t;
    for (int f = 0; f < 10; f++) {
        double e1 = total_energy(&w, G);
        if (fabs(e1 - e0) > worst) worst = fabs(e1 - e0);
        frames(&w, 1);
    }
    print_message("two contacts: ball on cube at %.9f s (want %.9f), cube on floor at %.9f s; "
                  "energy %.9f J then, worst drift %.3g of the kinetic %.6f J in 1 s, %ld collisions\n",
                  t_hit, t1, t_land, e0, worst / k0, k0, w.st.collisions);
    assert_near(t_hit, t1, 1e-9);
    assert_true(t_land > t_hit && t_land < t_hit + 0.002);
    assert_true(worst <= 1e-6 * k0);
    assert_near(total_energy(&w, G), e0, 1e-6 * k0);
    world_free(&w);
}

/* A closed room (six still walls, inner faces at +-1 m) of 30 objects, spheres,
 * cubes and superquadrics, elasticity 1, for `seconds`: the energy (kinetic, plus
 * potential under gravity) drifts by less than 1e-6 of the kinetic energy. */
static void closed_room(double g, double seconds, double *drift, long *hits)
{
    world w;
    world_init(&w);
    w.set.force = (dir_amount){v3(0, 0, -1), g};
    w.set.max_linear = 20;
    w.set.max_angular = 1000;
    const vec3 wall_at[6] = {{1.1, 0, 0}, {-1.1, 0, 0}, {0, 1.1, 0}, {0, -1.1, 0}, {0, 0, 1.1}, {0, 0, -1.1}};
    for (int k = 0; k < 6; k++) {
        char name[16];
        snprintf(name, sizeof name, "wall%d", k);
        vec3 size = v3(k / 2 == 0 ? 0.1 : 1.2, k / 2 == 1 ? 0.1 : 1.2, k / 2 == 2 ? 0.1 : 1.2);
        add_static_box(&w, name, size)->x = wall_at[k];
    }
    unsigned long long seed = 23;
    int made = 0;
    for (int slot = 0; slot < 32 && made < 30; slot++) {
        if (slot == 5 || slot == 26) continue;
        char name[16];
        snprintf(name, sizeof name, "o%d", made);
        shape_kind kind = (shape_kind)(made % 3);
        body *b = add(&w, name, kind);
        b->sp.radius = urand(&seed, 0.08, 0.15);
        b->sp.size = v3(urand(&seed, 0.06, 0.11), urand(&seed, 0.06, 0.11), urand(&seed, 0.06, 0.11));
        b->sp.exp1 = urand(&seed, 0.4, 1.6);
        b->sp.exp2 = urand(&seed, 0.4, 1.6);
        b->sp.a1 = urand(&seed, 0.08, 0.13);
        b->sp.a2 = urand(&seed, 0.08, 0.13);
        b->sp.a3 = urand(&seed, 0.08, 0.13);
        b->sp.ures = b->sp.vres = 12;
        rebuild(b);
        body_set_mass(b, urand(&seed, 0.5, 3));
        b->x = v3(-0.75 + 0.5 * (slot % 4), -0.75 + 0.5 * ((slot / 4) % 4), slot < 16 ? -0.5 : 0.4);
        body_set_rotation(b, v3(urand(&seed, -1, 1), urand(&seed, -1, 1), urand(&seed, -1, 1)),
                          urand(&seed, 0, 3));
        b->v = v3(urand(&seed, -1.5, 1.5), urand(&seed, -1.5, 1.5), urand(&seed, -1.5, 1.5));
        body_set_angular_vel(b, v3(urand(&seed, -3, 3), urand(&seed, -3, 3), urand(&seed, -3, 3)));
        made++;
    }
    assert_int_equal(sim_penetrations(&w, NULL, NULL), 0);
    double k0 = kinetic(&w), e0 = total_energy(&w, g), worst = 0;
    int n = (int)lround(seconds / w.set.time_step);
    for (int f = 0; f < n; f++) {
        frames(&w, 1);
        double e = total_energy(&w, g);
        if (fabs(e - e0) > worst) worst = fabs(e - e0);
    }
    *drift = worst / k0;
    *hits = w.st.collisions;
    for (int i = 6; i < w.n; i++) {
        vec3 c = body_com(w.bodies[i]);
        assert_true(fabs(c.x) < 1 && fabs(c.y) < 1 && fabs(c.z) < 1); /* all inside */
    }
    world_free(&w);
}

static void closed_room_of_thirty_keeps_energy(void **state)
{
    (void)state;
    const double seconds = 60;
    for (int k = 0; k < 2; k++) {
        double g = k ? G : 0, drift;
        long hits;
        struct timespec a, b;
        clock_gettime(CLOCK_MONOTONIC, &a);
        closed_room(g, seconds, &drift, &hits);
        clock_gettime(CLOCK_MONOTONIC, &b);
        print_message("closed room, g %.1f: %ld collisions in %.0f s, energy drift %.3g of the "
                      "kinetic energy (%.2f s of wall time)\n", g, hits, seconds, drift,
                      (double)(b.tv_sec - a.tv_sec) + 1e-9 * (double)(b.tv_nsec - a.tv_nsec));
        assert_true(hits > 100);
        assert_true(drift < 1e-6);
    }
}

/* ------------------------------------------------------- free rotation */

/* q' = q (0, w_b) / 2 with w_b = I^-1 (q* L q), L constant in world axes: the
 * torque-free motion, for the reference below. */
static quat spin_rate(quat q, vec3 L, vec3 inv_i)
{
    vec3 lb = q_unrotate(q, L);
    vec3 wb = v3(lb.x * inv_i.x, lb.y * inv_i.y, lb.z * inv_i.z);
    quat d = q_mul(q, (quat){0, wb.x, wb.y, wb.z});
    return (quat){0.5 * d.w, 0.5 * d.x, 0.5 * d.y, 0.5 * d.z};
}

static quat q_step(quat q, quat d, double h)
{
    return (quat){q.w + h * d.w, q.x + h * d.x, q.y + h * d.y, q.z + h * d.z};
}

/* A box of half-extents (0.3, 0.2, 0.1), mass 2, spinning about a skew axis with
 * no force, for 20 s at the default time_step: energy and angular momentum are
 * kept to 1e-9, and its orientation follows Euler's equations (integrated here
 * by RK4 with a 1e-4 s step, its error far below the tolerance). */
static void free_box_keeps_energy_and_angular_momentum(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    w.set.max_linear = 50;
    w.set.max_angular = 100;
    const double m = 2, a = 0.3, b = 0.2, c = 0.1;
    body *box = add_box(&w, "box", v3(a, b, c));
    body_set_mass(box, m);
    body_set_rotation(box, v3(0.3, -0.5, 0.8), 0.9);
    body_set_angular_vel(box, v3(1.0, -2.0, 3.0));
    box->v = v3(0.1, 0.2, -0.3);
    /* a box's principal moments: m (b^2 + c^2) / 3 and so on (half-extents) */
    const vec3 I = v3(m * (b * b + c * c) / 3, m * (a * a + c * c) / 3, m * (a * a + b * b) / 3);
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            assert_near(box->I_body.m[i][j], i != j ? 0 : v3_comp(I, i), 1e-12);
    const vec3 inv_i = v3(1 / I.x, 1 / I.y, 1 / I.z);
    const vec3 L0 = box->L, x0 = box->x;
    const double e0 = body_energy(box);
    quat q = box->q;
    double worst_e = 0, worst_l = 0;
    for (int f = 1; f <= 200; f++) {
        frames(&w, 1);
        worst_e = fmax(worst_e, fabs(body_energy(box) - e0) / e0);
        worst_l = fmax(worst_l, v3_dist(box->L, L0) / v3_len(L0));
    }
    assert_near(w.time, 20, 1e-12);
    /* the reference */
    const double h = 1e-4;
    for (long k = 0; k < 200000; k++) {
        quat k1 = spin_rate(q, L0, inv_i);
        quat k2 = spin_rate(q_step(q, k1, h / 2), L0, inv_i);
        quat k3 = spin_rate(q_step(q, k2, h / 2), L0, inv_i);
        quat k4 = spin_rate(q_step(q, k3, h), L0, inv_i);
        q = (quat){q.w + h / 6 * (k1.w + 2 * k2.w + 2 * k3.w + k4.w),
                   q.x + h / 6 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x),
                   q.y + h / 6 * (k1.y + 2 * k2.y + 2 * k3.y + k4.y),
                   q.z + h / 6 * (k1.z + 2 * k2.z + 2 * k3.z + k4.z)};
        q = q_normalize(q);
    }
    double worst_axis = 0;
    const vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (int i = 0; i < 3; i++)
        worst_axis = fmax(worst_axis, v3_dist(q_rotate(box->q, axes[i]), q_rotate(q, axes[i])));
    print_message("free box, 20 s: energy drift %.3g, angular momentum drift %.3g, axes %.3g from "
                  "Euler's equations; |w| now %.6f\n", worst_e, worst_l, worst_axis, v3_len(box->w));
    assert_true(worst_e <= 1e-9);
    assert_true(worst_l <= 1e-9);
    assert_true(worst_axis < 1e-7);
    assert_vec_near(box->x, v3_add(x0, v3(2, 4, -6)), 1e-12);
    world_free(&w);
}

/* ------------------------------------------------ spinning and thin objects */

/* The rod's lowest point at time t above the plate's top (its corners, turned
 * about y by theta0 + omega t, its centre falling from z0 at vz under g). */
static double rod_gap(double t, vec3 half, double theta0, double omega, double z0, double vz,
                      double top)
{
    quat q = q_axis_angle(v3(0, 1, 0), theta0 + omega * t);
    double low = HUGE_VAL;
    for (int i = 0; i < 8; i++) {
        vec3 c = v3(i & 1 ? half.x : -half.x, i & 2 ? half.y : -half.y, i & 4 ? half.z : -half.z);
        low = fmin(low, q_rotate(q, c).z);
    }
    return z0 + vz * t - 0.5 * G * t * t + low - top;
}

/* The lowest corner of box b (half-extents half). */
static double lowest_corner(const body *b, vec3 half)
{
    double low = HUGE_VAL;
    for (int i = 0; i < 8; i++) {
        vec3 c = v3(i & 1 ? half.x : -half.x, i & 2 ? half.y : -half.y, i & 4 ? half.z : -half.z);
        low = fmin(low, v3_add(b->x, q_rotate(b->q, c)).z);
    }
    return low;
}

/* A rod 1 m long spinning at 38 rad/s about its major axis (level), falling at
 * 2 m/s towards a still plate 2 mm thick: its ends sweep 19 m/s.  It touches the
 * plate first when its lowest corner first reaches the plate's top: found here
 * by scanning in 1 us steps (the corner cannot dip in and out within one: its
 * acceleration, 720 m/s^2, moves it 1e-10 m in that time) and bisecting. */
static void spinning_rod_touches_a_plate_when_it_should(void **state)
{
    (void)state;
    const vec3 half = v3(0.5, 0.01, 0.015);
    const double theta0 = 0.3, omega = 38, z0 = 0.9, vz = -2, top = 0.001;
    world w;
    physics_world(&w, 10, 100);
    body *plate = add_static_box(&w, "plate", v3(3, 3, 0.001));
    body *rod = add_box(&w, "rod", half);
    body_set_rotation(rod, v3(0, 1, 0), theta0);
    body_set_angular_vel(rod, v3(0, omega, 0));
    rod->x = v3(0.1, 0.2, z0);
    rod->v = v3(0, 0, vz);
    double lo = 0, hi = -1;
    for (double t = 0; t < 1; t += 1e-6) {
        if (rod_gap(t, half, theta0, omega, z0, vz, top) <= 0) {
            hi = t;
            break;
        }
        lo = t;
    }
    assert_true(hi > 0);
    for (int k = 0; k < 100; k++) {
        double mid = 0.5 * (lo + hi);
        if (rod_gap(mid, half, theta0, omega, z0, vz, top) > 0) lo = mid;
        else hi = mid;
    }
    double want = 0.5 * (lo + hi);
    const sim_event *ev = NULL;
    for (int f = 0; f < 20 && !ev; f++) {
        frames(&w, 1);
        ev = event_between(&w, rod, plate);
        assert_true(lowest_corner(rod, half) > top - ON_FACE);
    }
    assert_non_null(ev);
    print_message("spinning rod: first touches the plate at %.9f s (want %.9f, off by %.3g s), at "
                  "(%.4f, %.4f, %.6f)\n", ev->t, want, ev->t - want, ev->p.x, ev->p.y, ev->p.z);
    assert_near(ev->t, want, 1e-4);
    assert_near(ev->p.z, top, 1e-4);
    /* never into the plate afterwards */
    for (int f = 0; f < 20; f++) {
        frames(&w, 1);
        assert_true(lowest_corner(rod, half) > top - ON_FACE);
    }
    world_free(&w);
}

/* True when shot b is under the plate (its top face at z > 0, over |x|, |y| <
 * 20) while over it: it went through. */
static bool through_plate(const body *b)
{
    vec3 c = body_com(b);
    return c.z < 0 && fabs(c.x) < 20 - b->shape.r_out && fabs(c.y) < 20 - b->shape.r_out;
}

/* 60 balls of radius 3 to 10 mm at up to 7.9 m/s, fired at a 1 mm plate from up
 * to 0.5 m above it, a third under gravity: none passes, whatever collision_dist. */
static void small_fast_balls_never_pass_a_thin_plate(void **state)
{
    (void)state;
    const double dists[] = {0.25, 1, 5};
    unsigned long long seed = 2023;
    int through = 0, hits = 0;
    for (size_t k = 0; k < 3; k++) {
        for (int shot = 0; shot < 60; shot++) {
            world w;
            world_init(&w);
            w.set.collision_dist = dists[k];
            w.set.max_linear = 10;
            w.set.max_angular = 100;
            if (shot % 3 == 0) w.set.force = (dir_amount){v3(0, 0, -1), G};
            add_static_box(&w, "plate", v3(20, 20, 0.0005));
            body *b = add_ball(&w, "shot", urand(&seed, 0.003, 0.010));
            b->elasticity = urand(&seed, 0, 1);
            b->x = v3(urand(&seed, -1, 1), urand(&seed, -1, 1),
                      0.0005 + b->sp.radius + urand(&seed, 0.001, 0.5));
            vec3 dir = v3_norm(v3(urand(&seed, -1, 1), urand(&seed, -1, 1), -urand(&seed, 0.2, 1)));
            b->v = v3_scale(dir, 7.9 * urand(&seed, 0.5, 1));
            body_set_angular_vel(b, v3(urand(&seed, -3, 3), urand(&seed, -3, 3), urand(&seed, -3, 3)));
            for (int f = 0; f < 10; f++) {
                frames(&w, 1);
                assert_int_equal(sim_penetrations(&w, NULL, NULL), 0); /* nor stuck in it */
                if (through_plate(b)) {
                    through++;
                    print_message("collision_dist %g, shot %d through: r %.4f\n", dists[k], shot,
                                  b->sp.radius);
                    break;
                }
            }
            hits += w.st.collisions > 0; /* it reached the plate */
            world_free(&w);
        }
    }
    print_message("small fast balls: %d of 180 struck the plate, %d went through\n", hits, through);
    assert_int_equal(hits, 180);
    assert_int_equal(through, 0);
}

/* The 1,000 shots of test_collide.c's nothing_passes_through_a_plate, with the
 * plate's thickness no longer tied to collision_dist: 1 mm to 10 cm, whatever
 * collision_dist (0.25, 1 or 5). */
static void thousand_shots_at_any_collision_dist(void **state)
{
    (void)state;
    const double dists[] = {0.25, 1, 5};
    unsigned long long seed = 77;
    int through = 0, hits = 0;
    for (int shot = 0; shot < 1000; shot++) {
        world w;
        world_init(&w);
        w.set.collision_dist = dists[shot % 3];
        double vmax = urand(&seed, 2, 30);
        w.set.max_linear = vmax + 10; /* above what a fall of 2.3 m adds */
        w.set.max_angular = 100;
        if (shot % 4 == 0) w.set.force = (dir_amount){v3(0, 0, -1), G};
        body *plate = add(&w, "plate", SHAPE_CUBE);
        double half = urand(&seed, 0.0005, 0.05);
        plate->sp.size = v3(20, 20, half);
        rebuild(plate);
        body_set_mass(plate, -1);
        int kind = (shot / 3) % 3;
        body *b = add_random_shot(&w, (shape_kind)kind, &seed);
        b->elasticity = urand(&seed, 0, 1);
        b->x = v3(urand(&seed, -1, 1), urand(&seed, -1, 1), half + b->shape.r_out + urand(&seed, 0.01, 2));
        body_set_rotation(b, v3(urand(&seed, -1, 1), urand(&seed, -1, 1), urand(&seed, -1, 1)),
                          urand(&seed, 0, 3));
        vec3 dir = v3_norm(v3(urand(&seed, -1, 1), urand(&seed, -1, 1), -urand(&seed, 0.2, 1)));
        b->v = v3_scale(dir, vmax * urand(&seed, 0.5, 1));
        body_set_angular_vel(b, v3(urand(&seed, -3, 3), urand(&seed, -3, 3), urand(&seed, -3, 3)));
        for (int f = 0; f < 15; f++) {
            frames(&w, 1);
            if (through_plate(b)) {
                through++;
                print_message("shot %d through: kind %d dist %g half %g\n", shot, kind,
                              w.set.collision_dist, half);
                break;
            }
        }
        hits += w.st.collisions > 0;
        world_free(&w);
    }
    print_message("1,000 shots: %d struck the plate, %d went through\n", hits, through);
    assert_true(hits > 500);
    assert_int_equal(through, 0);
}

/* ------------------------------------------------------------ the runner */

static struct timespec started;

static int clock_start(void **state)
{
    (void)state;
    clock_gettime(CLOCK_MONOTONIC, &started);
    return 0;
}

static int clock_stop(void **state)
{
    (void)state;
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    print_message("  (%.2f s)\n", (double)(now.tv_sec - started.tv_sec) +
                                      1e-9 * (double)(now.tv_nsec - started.tv_nsec));
    return 0;
}

/* ------------------------------------------------------------------ energy */

/* energy.h against the textbook, for boxes and balls of random sizes, masses,
 * places, velocities and spins: kinetic energy m v^2/2 + (I_x wx^2 + I_y wy^2 +
 * I_z wz^2)/2 with a box's I_x = m (b^2 + c^2)/3 for half-extents (a, b, c) in its
 * own axes; potential energy m g z under gravity (and -m a . x under any uniform
 * force); momentum m v; angular momentum about the origin x × m v + I w.  A static
 * body holds none.  The world's figures are the sums, and in free flight the
 * total stays what it was. */
static void energy_is_the_textbooks(void **state)
{
    (void)state;
    unsigned long long seed = 41;
    for (int trial = 0; trial < 20; trial++) {
        world w;
        physics_world(&w, 1e3, 1e3);
        double g = urand(&seed, 1, 20);
        vec3 dir = v3(urand(&seed, -1, 1), urand(&seed, -1, 1), urand(&seed, -1, 1));
        w.set.force = (dir_amount){dir, g};
        vec3 a = v3_scale(v3_norm(dir), g);
        vec3 he = v3(urand(&seed, 0.1, 1), urand(&seed, 0.1, 1), urand(&seed, 0.1, 1));
        body *box = add_box(&w, "box", he);
        double m = urand(&seed, 0.1, 10);
        body_set_mass(box, m);
        box->x = v3(urand(&seed, -5, 5), urand(&seed, -5, 5), urand(&seed, -5, 5));
        box->v = v3(urand(&seed, -3, 3), urand(&seed, -3, 3), urand(&seed, -3, 3));
        vec3 wb = v3(urand(&seed, -2, 2), urand(&seed, -2, 2), urand(&seed, -2, 2)); /* box axes */
        double angle = urand(&seed, 0, 3);
        vec3 axis = v3(urand(&seed, -1, 1), urand(&seed, -1, 1), 1);
        body_set_rotation(box, axis, angle);
        body_set_angular_vel(box, q_rotate(box->q, wb));
        double r = urand(&seed, 0.1, 1);
        body *ball = add_ball(&w, "ball", r);
        double mb = urand(&seed, 0.1, 10);
        body_set_mass(ball, mb);
        ball->x = v3(urand(&seed, 30, 40), 0, urand(&seed, -5, 5)); /* never meets the box */
        ball->v = v3(urand(&seed, -3, 3), urand(&seed, -3, 3), urand(&seed, -3, 3));
        body_set_angular_vel(ball, v3(0, 0, urand(&seed, -2, 2)));
        body *floor = add_static_box(&w, "floor", v3(1, 1, 1));
        floor->x = v3(0, 0, -40);

        double ix = m * (he.y * he.y + he.z * he.z) / 3, iy = m * (he.x * he.x + he.z * he.z) / 3,
               iz = m * (he.x * he.x + he.y * he.y) / 3;
        energy_sum e = energy_of_body(&w, box);
        assert_rel(e.linear, 0.5 * m * v3_len2(box->v), 1e-12);
        assert_rel(e.rotational, 0.5 * (ix * wb.x * wb.x + iy * wb.y * wb.y + iz * wb.z * wb.z), 1e-9);
        assert_near(e.potential, -m * v3_dot(a, box->x), 1e-9 * (1 + fabs(e.potential)));
        vec3 spin = q_rotate(box->q, v3(ix * wb.x, iy * wb.y, iz * wb.z));
        vec3 want_L = v3_add(v3_cross(box->x, v3_scale(box->v, m)), spin);
        assert_true(v3_len(v3_sub(e.angular_momentum, want_L)) < 1e-9 * (1 + v3_len(want_L)));
        assert_true(v3_len(v3_sub(e.momentum, v3_scale(box->v, m))) < 1e-12 * (1 + v3_len(e.momentum)));

        /* a solid ball: I = 2 m r^2 / 5 */
        energy_sum eb = energy_of_body(&w, ball);
        assert_rel(eb.rotational, 0.5 * 0.4 * mb * r * r * v3_len2(ball->w), 1e-9);

        energy_sum ef = energy_of_body(&w, floor);
        assert_true(ef.linear == 0 && ef.rotational == 0 && ef.potential == 0 &&
                    v3_len(ef.momentum) == 0 && v3_len(ef.angular_momentum) == 0);

        energy_sum all = energy_of_world(&w);
        assert_rel(energy_total(all), energy_total(e) + energy_total(eb), 1e-12);
        assert_rel(energy_kinetic(all), body_energy(box) + body_energy(ball), 1e-12);

        /* free flight (the floor far below): the total is kept */
        double e0 = energy_total(all);
        double scale = energy_kinetic(all) + fabs(all.potential);
        frames(&w, 10);
        assert_near(energy_total(energy_of_world(&w)), e0, 1e-9 * scale);
        world_free(&w);
    }
    /* under gravity along -z: m g h, whatever the object */
    world w;
    physics_world(&w, 50, 50);
    body *ball = add_ball(&w, "ball", 0.1);
    body_set_mass(ball, 2);
    ball->x = v3(3, 4, 5);
    assert_near(energy_of_world(&w).potential, 2 * G * 5, 1e-12);
    world_free(&w);
}

#define timed(f) cmocka_unit_test_setup_teardown(f, clock_start, clock_stop)

int main(void)
{
    const struct CMUnitTest tests[] = {
        timed(frictionless_block_slides_on_a_ramp),
        timed(block_shoved_up_a_ramp_comes_back),
        timed(resting_ball_struck_from_above_leaves_sideways),
        timed(overhanging_cube_tips_off),
        timed(frictionless_pyramid_collapses),
        timed(ball_off_a_table_flies_the_parabola),
        timed(slow_ball_pivots_on_the_table_edge),
        timed(energy_kept_across_two_contacts_within_a_millisecond),
        timed(closed_room_of_thirty_keeps_energy),
        timed(free_box_keeps_energy_and_angular_momentum),
        timed(spinning_rod_touches_a_plate_when_it_should),
        timed(small_fast_balls_never_pass_a_thin_plate),
        timed(thousand_shots_at_any_collision_dist),
        timed(energy_is_the_textbooks),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
