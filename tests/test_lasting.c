/* test_lasting.c: lasting contact with friction in closed form (issue 37), each
 * answer derived here from the textbook's.
 *
 * A block on an incline of angle th with mu: it stays iff tan th <= mu, else
 * slides down at g (sin th - mu cos th); shoved up at u it stops after u / (g
 * (sin th + mu cos th)) at u^2 / (2 g (sin th + mu cos th)), the heat mu m g
 * cos th times the path; it creeps by less than 1e-9 m over 60 s, and so does a
 * stack of three.  A ball sliding on a level floor rolls from t* = 2 v0 / (7
 * mu g) at (5/7) v0, having lost m v0^2 / 7; with backspin -5 v0 / (2 r) it
 * stops dead; rolling with resistance c it stops after 7 v / (5 c g), having
 * gone (7/10) v^2 / (c g).  A ball on an incline rolls at (5/7) g sin th where
 * mu >= (2/7) tan th, and slides otherwise, spinning up at 5 mu g cos th / (2
 * r).  A box at rest on an incline tips iff tan th > b / h; launched on a level
 * floor it stays flat iff mu h < b; sliding flat it goes straight; a cube
 * spinning flat slows at (sqrt 2 + ln(1 + sqrt 2)) mu g / s; one sliding across
 * the seam of two coplanar tiles stops where one face would stop it.  Rolling
 * resistance is 0 unless said; 1e-6 relative unless said. */
#include "check.h"

#include <stdlib.h>
#include <string.h>

#include "core/body.h"
#include "core/friction.h"
#include "core/sim.h"
#include "core/world.h"
#include "worlds.h"

static const double G = 9.8;

static void frame(world *w, double dt)
{
    char err[256];
    w->set.time_step = dt;
    assert_int_equal(sim_frame(w, err, sizeof err), 0);
}

static void frames(world *w, int n, double dt)
{
    for (int i = 0; i < n; i++) frame(w, dt);
}

/* Runs w on to time t (frames of at most dt). */
static void run_to(world *w, double t, double dt)
{
    while (w->time < t - 1e-12) frame(w, d_min(dt, t - w->time));
}

/* A world under gravity with room for fast motion: a static slab (its top face
 * through the origin, half-extents 5 x 2 x 0.1) tilted by th about y, so that
 * its top's normal is n = (-sin th, 0, cos th) and up the slope is d = (cos th,
 * 0, sin th); friction mu on both, rolling resistance c on the slab (0 on the
 * objects: a pair's is then 0 unless the object is given some). */
typedef struct {
    world w;
    body *ramp;
    vec3 n, d;
    double th, mu;
} ramp_world;

static void ramp_init(ramp_world *r, double th, double mu)
{
    world_init(&r->w);
    r->w.set.force = (dir_amount){v3(0, 0, -1), G};
    r->w.set.max_linear = 50;
    r->w.set.max_angular = 1000;
    r->th = th;
    r->mu = mu;
    r->n = v3(-sin(th), 0, cos(th));
    r->d = v3(cos(th), 0, sin(th));
    r->ramp = add_static_box(&r->w, "ramp", v3(5, 2, 0.1));
    body_set_rotation(r->ramp, v3(0, 1, 0), -th);
    r->ramp->x = v3_scale(r->n, -0.1);
    r->ramp->friction = mu;
}

/* A box of half-extents (b, b, hz) resting flat on the ramp at s along d, named
 * name, with friction mu, still. */
static body *ramp_box(ramp_world *r, const char *name, double b, double hz, double s, double lift)
{
    body *x = add_box(&r->w, name, v3(b, b, hz));
    x->friction = r->mu;
    x->rolling_friction = 0;
    x->elasticity = 0;
    body_set_rotation(x, v3(0, 1, 0), -r->th);
    x->x = v3_add(v3_scale(r->d, s), v3_scale(r->n, lift + hz + 1e-9));
    return x;
}

static double along(const ramp_world *r, const body *b) { return v3_dot(body_com(b), r->d); }

/* Kinetic and potential energy. */
static double energy(const body *b)
{
    return body_energy(b) + b->mass * G * body_com(b).z;
}

/* The angle between two orientations (rad): of the turn a^-1 b, from its
 * vector part (acos of its scalar part would lose half the digits). */
static double turn_between(quat a, quat b)
{
    quat d = q_mul(q_conj(a), b);
    return 2 * atan2(sqrt(d.x * d.x + d.y * d.y + d.z * d.z), fabs(d.w));
}

static bool stuck(const body *b) { return b->mode == MODE_STICK && v3_len(b->v) == 0; }

/* ---- a block on an incline ---- */

static const double CASES[][2] = {
    /* th, mu (never tan th = mu) */
    {0.2, 0.5}, {0.35, 0.3}, {0.5, 0.7}, {0.6, 0.5}, {0.8, 0.9}, {1.0, 0.6}, {0.3, 0.0},
};
#define NCASES (int)(sizeof CASES / sizeof CASES[0])

/* Left still on the incline, it stays iff tan th <= mu; else it slides down at
 * g (sin th - mu cos th), and the heat is mu m g cos th times the path. */
static void block_stays_or_slides(void **state)
{
    (void)state;
    for (int k = 0; k < NCASES; k++) {
        double th = CASES[k][0], mu = CASES[k][1];
        ramp_world r;
        ramp_init(&r, th, mu);
        body *box = ramp_box(&r, "box", 0.1, 0.05, 0, 0);
        double s0 = along(&r, box), e0 = energy(box);
        frames(&r.w, 10, 0.1);
        double gone = s0 - along(&r, box);
        if (tan(th) <= mu) {
            print_message("th %.2f mu %.2f: stays (moved %.3g m)\n", th, mu, gone);
            assert_true(fabs(gone) < 1e-9);
            assert_true(stuck(box));
            assert_int_equal(box->state, STATE_RESTING);
        } else {
            double a = G * (sin(th) - mu * cos(th)), t = r.w.time;
            print_message("th %.2f mu %.2f: slides %.12f (want %.12f)\n", th, mu, gone, a * t * t / 2);
            assert_rel(gone, a * t * t / 2, 1e-6);
            assert_rel(v3_len(box->v), a * t, 1e-6);
            assert_int_equal(box->mode, MODE_SLIDE);
            double heat = e0 - energy(box);
            assert_near(heat, mu * box->mass * G * cos(th) * gone, 1e-6 * box->mass * G * gone);
        }
        world_free(&r.w);
    }
}

/* Shoved up the slope at u, it stops after u / (g (sin th + mu cos th)) (found
 * to 1e-7 of it: still sliding just before, stopped just after), at u^2 / (2 g
 * (sin th + mu cos th)); it then sticks, or slides back down.  The heat is mu m
 * g cos th times the path. */
static void block_shoved_up_stops(void **state)
{
    (void)state;
    for (int k = 0; k < NCASES; k++) {
        double th = CASES[k][0], mu = CASES[k][1], u = 1.3;
        ramp_world r;
        ramp_init(&r, th, mu);
        body *box = ramp_box(&r, "box", 0.1, 0.05, -1, 0);
        box->v = v3_scale(r.d, u);
        double s0 = along(&r, box), e0 = energy(box);
        double dec = G * (sin(th) + mu * cos(th)), ts = u / dec, ds = u * u / (2 * dec);
        run_to(&r.w, ts * 0.5, 0.05);
        assert_rel(v3_dot(box->v, r.d), u - dec * r.w.time, 1e-6);
        run_to(&r.w, ts * (1 - 1e-7), 0.05);
        assert_int_equal(box->mode, MODE_SLIDE);
        assert_true(v3_dot(box->v, r.d) > 0);
        run_to(&r.w, ts * (1 + 1e-7), 0.05);
        double up = along(&r, box) - s0;
        print_message("th %.2f mu %.2f: stops at %.12f (want %.12f)\n", th, mu, up, ds);
        assert_rel(up, ds, 1e-6);
        if (tan(th) <= mu) {
            assert_true(stuck(box));
            double heat = e0 - energy(box);
            assert_near(heat, mu * box->mass * G * cos(th) * up, 1e-6 * box->mass * G * up);
        } else {
            assert_true(v3_dot(box->v, r.d) <= 0);
            assert_int_equal(box->mode, MODE_SLIDE);
            /* and down again at g (sin th - mu cos th) */
            run_to(&r.w, ts + 0.4, 0.05);
            double a = G * (sin(th) - mu * cos(th)), t = r.w.time - ts;
            assert_rel(up - (along(&r, box) - s0), a * t * t / 2, 1e-6);
            double path = up + (up - (along(&r, box) - s0));
            double heat = e0 - energy(box);
            assert_near(heat, mu * box->mass * G * cos(th) * path, 1e-6 * box->mass * G * path);
        }
        world_free(&r.w);
    }
}

/* Where it first rests it stays, to 1e-9 m over 60 s: one block, and a stack of
 * three. */
static void no_creep(void **state)
{
    (void)state;
    double ths[] = {0.25, 0.4}, mus[] = {0.5, 0.6};
    for (int k = 0; k < 2; k++) {
        ramp_world r;
        ramp_init(&r, ths[k], mus[k]);
        body *one = ramp_box(&r, "one", 0.1, 0.05, -2, 0);
        body *st[3];
        for (int j = 0; j < 3; j++) {
            char name[8];
            snprintf(name, sizeof name, "s%d", j);
            /* (each 2e-9 above the one below) */
            st[j] = ramp_box(&r, name, 0.15 - 0.02 * j, 0.05, 1, j * (0.1 + 2e-9));
        }
        body *all[4] = {one, st[0], st[1], st[2]};
        vec3 first[4];
        bool rested[4] = {false, false, false, false};
        for (int f = 0; f < 600; f++) {
            frame(&r.w, 0.1);
            for (int j = 0; j < 4; j++) {
                if (!rested[j] && all[j]->state == STATE_RESTING) {
                    rested[j] = true;
                    first[j] = all[j]->x;
                }
            }
        }
        for (int j = 0; j < 4; j++) {
            assert_true(rested[j]);
            double moved = v3_len(v3_sub(all[j]->x, first[j]));
            print_message("th %.2f: %s moved %.3g m after it first rested\n", ths[k], all[j]->name, moved);
            assert_true(moved < 1e-9);
        }
        world_free(&r.w);
    }
}

/* ---- balls ---- */

/* A level floor (its top at z = 0) of friction mu and rolling resistance c, and
 * a ball of radius rad on it, with the same, moving at v0 along x with spin w0
 * about y. */
static body *ball_on_floor(world *w, double mu, double c, double rad, double v0, double w0)
{
    world_init(w);
    w->set.force = (dir_amount){v3(0, 0, -1), G};
    w->set.max_linear = 50;
    w->set.max_angular = 1000;
    body *floor = add_static_box(w, "floor", v3(100, 100, 0.1));
    floor->x = v3(0, 0, -0.1);
    floor->friction = mu;
    floor->rolling_friction = c;
    body *ball = add_ball(w, "ball", rad);
    ball->friction = mu;
    ball->rolling_friction = c;
    ball->elasticity = 0;
    ball->x = v3(0, 0, rad + 1e-9);
    ball->v = v3(v0, 0, 0);
    body_set_angular_vel(ball, v3(0, w0, 0));
    return ball;
}

/* Sliding with no spin, it rolls from t* = 2 v0 / (7 mu g) (to 1e-7 of it) at
 * (5/7) v0, having lost m v0^2 / 7; with backspin -5 v0 / (2 r) it stops dead,
 * after v0 / (mu g), at v0^2 / (2 mu g). */
static void ball_slides_then_rolls(void **state)
{
    (void)state;
    double cases[][3] = {{0.3, 2, 0.1}, {0.6, 0.7, 0.05}, {0.15, 3.5, 0.3}};
    for (int k = 0; k < 3; k++) {
        double mu = cases[k][0], v0 = cases[k][1], rad = cases[k][2];
        world w;
        body *ball = ball_on_floor(&w, mu, 0, rad, v0, 0);
        double e0 = body_energy(ball), ts = 2 * v0 / (7 * mu * G);
        run_to(&w, ts * (1 - 1e-7), 0.05);
        assert_int_equal(ball->mode, MODE_SLIDE);
        assert_rel(ball->v.x, v0 - mu * G * w.time, 1e-6);
        run_to(&w, ts * (1 + 1e-7), 0.05);
        assert_int_equal(ball->mode, MODE_ROLL);
        run_to(&w, ts + 0.3, 0.05);
        print_message("mu %.2f v0 %.2f: rolls at %.12f (want %.12f)\n", mu, v0, ball->v.x, 5 * v0 / 7);
        assert_rel(ball->v.x, 5 * v0 / 7, 1e-6);
        assert_rel(ball->w.y * rad, ball->v.x, 1e-9);
        assert_rel(e0 - body_energy(ball), ball->mass * v0 * v0 / 7, 1e-6);
        world_free(&w);

        ball = ball_on_floor(&w, mu, 0, rad, v0, -5 * v0 / (2 * rad));
        double tstop = v0 / (mu * G), x0 = ball->x.x;
        run_to(&w, tstop * (1 - 1e-7), 0.05);
        assert_true(ball->v.x > 0);
        run_to(&w, tstop * (1 + 1e-7), 0.05);
        assert_true(v3_len(ball->v) == 0 && v3_len(ball->w) == 0);
        run_to(&w, tstop + 1, 0.05);
        print_message("backspin: stops at %.12f (want %.12f)\n", ball->x.x - x0, v0 * v0 / (2 * mu * G));
        assert_rel(ball->x.x - x0, v0 * v0 / (2 * mu * G), 1e-6);
        assert_true(v3_len(ball->v) == 0 && v3_len(ball->w) == 0);
        assert_int_equal(ball->state, STATE_RESTING);
        world_free(&w);
    }
}

/* Rolling at v with rolling resistance c, it stops after 7 v / (5 c g) (to 1e-7
 * of it), having gone (7/10) v^2 / (c g). */
static void ball_rolls_to_a_stop(void **state)
{
    (void)state;
    double cases[][3] = {{0.02, 1, 0.1}, {0.05, 2.5, 0.2}, {0.01, 0.4, 0.05}};
    for (int k = 0; k < 3; k++) {
        double c = cases[k][0], v = cases[k][1], rad = cases[k][2];
        world w;
        body *ball = ball_on_floor(&w, 0.5, c, rad, v, v / rad);
        double ts = 7 * v / (5 * c * G), want = 0.7 * v * v / (c * G), x0 = ball->x.x;
        run_to(&w, ts * (1 - 1e-7), 0.5);
        assert_int_equal(ball->mode, MODE_ROLL);
        assert_true(ball->v.x > 0);
        run_to(&w, ts * (1 + 1e-7), 0.5);
        print_message("c %.2f v %.2f: stops at %.12f (want %.12f)\n", c, v, ball->x.x - x0, want);
        assert_rel(ball->x.x - x0, want, 1e-6);
        assert_true(v3_len(ball->v) == 0);
        assert_true(fabs(ball->x.y) < 1e-12);
        world_free(&w);
    }
}

/* On an incline, from rest: it rolls at (5/7) g sin th where mu >= (2/7) tan
 * th; else it slides at g (sin th - mu cos th), spinning up at 5 mu g cos th /
 * (2 r). */
static void ball_on_incline(void **state)
{
    (void)state;
    double cases[][2] = {{0.3, 0.5}, {0.7, 0.3}, {0.9, 0.2}, {1.1, 0.3}, {0.5, 0.1}};
    for (int k = 0; k < 5; k++) {
        double th = cases[k][0], mu = cases[k][1], rad = 0.1;
        ramp_world r;
        ramp_init(&r, th, mu);
        body *ball = add_ball(&r.w, "ball", rad);
        ball->friction = mu;
        ball->rolling_friction = 0;
        ball->elasticity = 0;
        ball->x = v3_add(v3_scale(r.d, 3), v3_scale(r.n, rad + 1e-9));
        double s0 = along(&r, ball);
        frames(&r.w, 5, 0.1);
        double t = r.w.time, gone = s0 - along(&r, ball);
        vec3 axis = v3_cross(r.n, v3_neg(r.d)); /* rolling down turns about n x (-d) */
        if (mu >= 2.0 / 7.0 * tan(th)) {
            double a = 5.0 / 7.0 * G * sin(th);
            print_message("th %.2f mu %.2f: rolls %.12f (want %.12f)\n", th, mu, gone, a * t * t / 2);
            assert_int_equal(ball->mode, MODE_ROLL);
            assert_rel(gone, a * t * t / 2, 1e-6);
            assert_rel(v3_dot(ball->w, axis) * rad, a * t, 1e-6);
        } else {
            double a = G * (sin(th) - mu * cos(th)), spin = 5 * mu * G * cos(th) / (2 * rad);
            print_message("th %.2f mu %.2f: slides %.12f (want %.12f)\n", th, mu, gone, a * t * t / 2);
            assert_int_equal(ball->mode, MODE_SLIDE);
            assert_rel(gone, a * t * t / 2, 1e-6);
            assert_rel(v3_dot(ball->w, axis), spin * t, 1e-6);
        }
        world_free(&r.w);
    }
}

/* ---- boxes: tipping and going straight ---- */

/* At rest on an incline (tan th <= mu), a box of half-base b and centre of
 * mass height h tips iff tan th > b / h. */
static void box_tips_on_incline_iff(void **state)
{
    (void)state;
    double b = 0.05, h = 0.15; /* b / h = 1/3 */
    double ths[] = {0.25, 0.4}; /* tan: 0.255, 0.423 */
    for (int k = 0; k < 2; k++) {
        ramp_world r;
        ramp_init(&r, ths[k], 0.9);
        body *box = ramp_box(&r, "box", b, h, 0, 0);
        quat q0 = box->q;
        frames(&r.w, 10, 0.1);
        double turned = turn_between(q0, box->q);
        bool tips = tan(ths[k]) > b / h;
        print_message("th %.2f: turned %.3g rad (tips: %d)\n", ths[k], turned, tips);
        if (tips) assert_true(turned > 0.1);
        else {
            assert_true(turned < 1e-9);
            assert_true(stuck(box));
        }
        world_free(&r.w);
    }
}

/* Launched with linear_vel on a level floor, it stays flat iff mu h < b; and
 * sliding flat, in any direction, it goes straight: its orientation changes by
 * less than 1e-9 rad, and its path is a line. */
static void box_launched_on_floor(void **state)
{
    (void)state;
    double b = 0.1, h = 0.2, mus[] = {0.3, 0.7}; /* mu h: 0.06, 0.14 against b 0.1 */
    double yaws[] = {0, 0.3, -1.2, 2.5};
    for (int k = 0; k < 2; k++)
        for (int y = 0; y < 4; y++) {
            world w;
            body *ball = ball_on_floor(&w, mus[k], 0, 0.1, 0, 0);
            ball->x = v3(50, 50, 0.1 + 1e-9); /* (out of the way) */
            body *box = add_box(&w, "box", v3(b, b, h));
            box->friction = mus[k];
            box->rolling_friction = 0;
            box->elasticity = 0;
            body_set_rotation(box, v3(0, 0, 1), yaws[y]);
            box->x = v3(0, 0, h + 1e-9);
            vec3 dir = v3(cos(0.4 + y), sin(0.4 + y), 0);
            box->v = v3_scale(dir, 3);
            quat q0 = box->q;
            frames(&w, 30, 0.05);
            double turned = turn_between(q0, box->q);
            vec3 c = box->x;
            double off = fabs(c.x * dir.y - c.y * dir.x);
            bool flat = mus[k] * h < b;
            if (flat) {
                assert_true(turned < 1e-9);
                assert_true(off < 1e-9);
                assert_near(v3_dot(c, dir), 9 / (2 * mus[k] * G), 1e-6 * 9 / (2 * mus[k] * G));
            } else {
                print_message("mu %.1f yaw %.1f: turned %.3g rad\n", mus[k], yaws[y], turned);
                assert_true(turned > 1e-3);
            }
            world_free(&w);
        }
}

/* Sliding across the seam of two coplanar tiles, a box goes on in closed form
 * as on one face: it stops u^2 / (2 mu g) from where it started, on the second
 * tile, and sticks there. */
static void box_slides_across_a_seam(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    w.set.force = (dir_amount){v3(0, 0, -1), G};
    w.set.max_linear = 50;
    body *t1 = add_static_box(&w, "tile1", v3(0.5, 0.5, 0.05));
    body *t2 = add_static_box(&w, "tile2", v3(0.5, 0.5, 0.05));
    t1->x = v3(0, 0, -0.05);
    t2->x = v3(1, 0, -0.05);
    t1->friction = t2->friction = 0.4;
    body *box = add_box(&w, "box", v3(0.1, 0.1, 0.1));
    box->friction = 0.4;
    box->rolling_friction = 0;
    box->elasticity = 0;
    box->x = v3(-0.3, 0, 0.1 + 1e-9);
    double u = 3, want = u * u / (2 * 0.4 * G); /* 1.148 m: past the seam at 0.5 */
    box->v = v3(u, 0, 0);
    frames(&w, 20, 0.1);
    print_message("across a seam: stops at %.12f (want %.12f)\n", box->x.x + 0.3, want);
    assert_rel(box->x.x + 0.3, want, 1e-6);
    assert_true(stuck(box) && box->slide_on == 1);
    world_free(&w);
}

/* A cube of side s spinning flat about the vertical slows at the angular
 * deceleration of the integral of mu p r over its face, p = m g / s^2 uniform:
 * mu m g s (sqrt 2 + ln(1 + sqrt 2)) / 6 over I = m s^2 / 6, that is (sqrt 2 +
 * ln(1 + sqrt 2)) mu g / s; it stops (to 1e-7 of its stopping time) where it
 * is. */
static void cube_spins_down(void **state)
{
    (void)state;
    double cases[][3] = {{0.2, 0.5, 6}, {0.5, 0.3, 10}, {0.08, 0.8, 25}}; /* s, mu, w0 */
    for (int k = 0; k < 3; k++) {
        double side = cases[k][0], mu = cases[k][1], w0 = cases[k][2];
        world w;
        ball_on_floor(&w, mu, 0, 0.1, 0, 0)->x = v3(50, 50, 0.1 + 1e-9); /* (out of the way) */
        body *cube = add_box(&w, "cube", v3(side / 2, side / 2, side / 2));
        cube->friction = mu;
        cube->rolling_friction = 0;
        cube->elasticity = 0;
        body_set_rotation(cube, v3(0, 0, 1), 0.3 * k);
        cube->x = v3(1, -2, side / 2 + 5e-10); /* (touching: not landing, spinning) */
        body_set_angular_vel(cube, v3(0, 0, w0));
        double dec = (sqrt(2) + log(1 + sqrt(2))) * mu * G / side, ts = w0 / dec;
        run_to(&w, ts / 2, 0.1);
        print_message("s %.2f mu %.1f: spin %.12f (want %.12f)\n", side, mu, cube->w.z, w0 - dec * w.time);
        assert_rel(cube->w.z, w0 - dec * w.time, 1e-6);
        run_to(&w, ts * (1 - 1e-7), 0.1);
        assert_true(cube->w.z > 0);
        run_to(&w, ts * (1 + 1e-7), 0.1);
        assert_true(v3_len(cube->w) == 0);
        assert_true(fabs(cube->x.x - 1) < 1e-12 && fabs(cube->x.y + 2) < 1e-12);
        world_free(&w);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(block_stays_or_slides),
        cmocka_unit_test(block_shoved_up_stops),
        cmocka_unit_test(no_creep),
        cmocka_unit_test(ball_slides_then_rolls),
        cmocka_unit_test(ball_rolls_to_a_stop),
        cmocka_unit_test(ball_on_incline),
        cmocka_unit_test(box_tips_on_incline_iff),
        cmocka_unit_test(box_launched_on_floor),
        cmocka_unit_test(cube_spins_down),
        cmocka_unit_test(box_slides_across_a_seam),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
