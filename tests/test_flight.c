/* test_flight.c: free flight against textbook answers.
 *
 * Projectile motion in closed form; a freely spinning asymmetric box checked against
 * the box's closed-form inertia (not vroc's mass code) and against an independent
 * RK4 integration of Euler's equations with tiny steps; a symmetric top, turned in
 * closed form, against the same at any step; the speed limits; the
 * internal-step count of language.md ("Time"); a held body's flight about its
 * moving pivot (hold.h), and a hook acting within a frame (sim.h). */
#include "check.h"

#include <stdlib.h>
#include <string.h>

#include "core/edit.h"
#include "core/flight.h"
#include "core/hold.h"
#include "core/rest.h"
#include "core/sim.h"
#include "core/world.h"
#include "worlds.h"

static void run_frames(world *w, int n)
{
    char err[256];
    for (int i = 0; i < n; i++) assert_int_equal(sim_frame(w, err, sizeof err), 0);
}

static void projectile_is_exact_whatever_the_step(void **state)
{
    (void)state;
    const double steps[] = {0, 0.001, 0.0123, 0.033, 0.1, 0.5};
    for (size_t k = 0; k < sizeof steps / sizeof steps[0]; k++) {
        world w;
        world_init(&w);
        w.set.force = (dir_amount){v3(0, 0, -2), 9.8}; /* direction need not be unit */
        w.set.internal_step = steps[k];
        body *b = add(&w, "ball", SHAPE_SPHERE);
        b->x = v3(0.5, -1, 1);
        b->v = v3(1, 2, 5);
        run_frames(&w, 10);
        double t = 1.0;
        vec3 want = v3(0.5 + 1 * t, -1 + 2 * t, 1 + 5 * t - 0.5 * 9.8 * t * t);
        assert_vec_near(b->x, want, 1e-9);
        assert_vec_near(b->v, v3(1, 2, 5 - 9.8 * t), 1e-9);
        assert_near(w.time, 1.0, 1e-12);
        world_free(&w);
    }
}

/* Closed-form inertia of a solid box of half-extents s and mass m, body axes. */
static vec3 box_inertia(vec3 s, double m)
{
    return v3(m * (s.y * s.y + s.z * s.z) / 3, m * (s.x * s.x + s.z * s.z) / 3,
              m * (s.x * s.x + s.y * s.y) / 3);
}

static vec3 world_L(quat q, vec3 inertia, vec3 w)
{
    vec3 wb = q_unrotate(q, w);
    return q_rotate(q, v3(inertia.x * wb.x, inertia.y * wb.y, inertia.z * wb.z));
}

static void spinning_box_keeps_its_angular_momentum(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    body *b = add(&w, "box", SHAPE_CUBE);
    b->sp.size = v3(0.5, 0.3, 0.1);
    char err[256];
    assert_int_equal(body_build(b, err, sizeof err), 0);
    body_set_mass(b, 2);
    body_set_rotation(b, v3(1, 2, 3), 0.7);
    body_set_angular_vel(b, v3(1, 0.5, 2));
    vec3 inertia = box_inertia(b->sp.size, 2);
    vec3 L0 = world_L(b->q, inertia, b->w);
    double E0 = 0.5 * v3_dot(b->w, L0);
    double max_dL = 0, max_dE = 0;
    for (int f = 0; f < 1000; f++) {
        run_frames(&w, 1);
        vec3 L = world_L(b->q, inertia, b->w);
        max_dL = fmax(max_dL, v3_len(v3_sub(L, L0)) / v3_len(L0));
        max_dE = fmax(max_dE, fabs(0.5 * v3_dot(b->w, L) - E0) / E0);
    }
    print_message("spinning box: max relative change of L %.3g, of energy %.3g over 1000 frames\n",
                  max_dL, max_dE);
    assert_true(max_dL <= 1e-9);
    assert_true(max_dE <= 1e-5);
    assert_near(q_len(b->q), 1, 1e-12);
    world_free(&w);
}

/* Euler's equations in body axes, I dw/dt = (I w) x w, and dq/dt = q (0, w_body)/2,
 * integrated with classical RK4. */
static void rk4_rigid(quat *q, vec3 *wb, vec3 I, double h)
{
    typedef struct {
        quat q;
        vec3 w;
    } st;
    st s0 = {*q, *wb}, k[4];
    for (int i = 0; i < 4; i++) {
        double c = i == 0 ? 0 : i == 3 ? 1 : 0.5;
        st s = s0;
        if (i > 0) {
            s.q = (quat){s0.q.w + c * h * k[i - 1].q.w, s0.q.x + c * h * k[i - 1].q.x,
                         s0.q.y + c * h * k[i - 1].q.y, s0.q.z + c * h * k[i - 1].q.z};
            s.w = v3_mad(s0.w, k[i - 1].w, c * h);
        }
        vec3 Iw = v3(I.x * s.w.x, I.y * s.w.y, I.z * s.w.z);
        vec3 t = v3_cross(Iw, s.w);
        k[i].w = v3(t.x / I.x, t.y / I.y, t.z / I.z);
        quat dq = q_mul(s.q, (quat){0, s.w.x, s.w.y, s.w.z});
        k[i].q = (quat){0.5 * dq.w, 0.5 * dq.x, 0.5 * dq.y, 0.5 * dq.z};
    }
    q->w += h / 6 * (k[0].q.w + 2 * k[1].q.w + 2 * k[2].q.w + k[3].q.w);
    q->x += h / 6 * (k[0].q.x + 2 * k[1].q.x + 2 * k[2].q.x + k[3].q.x);
    q->y += h / 6 * (k[0].q.y + 2 * k[1].q.y + 2 * k[2].q.y + k[3].q.y);
    q->z += h / 6 * (k[0].q.z + 2 * k[1].q.z + 2 * k[2].q.z + k[3].q.z);
    *q = q_normalize(*q);
    for (int i = 0; i < 4; i++) {
        double c = (i == 0 || i == 3) ? 1 : 2;
        *wb = v3_mad(*wb, k[i].w, h / 6 * c);
    }
}

static void spinning_box_follows_eulers_equations(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    w.set.internal_step = 0.0005;
    body *b = add(&w, "box", SHAPE_CUBE);
    b->sp.size = v3(0.4, 0.25, 0.1);
    char err[256];
    assert_int_equal(body_build(b, err, sizeof err), 0);
    body_set_angular_vel(b, v3(0.2, 3, 0.3)); /* near the unstable middle axis: tumbles */
    vec3 inertia = box_inertia(b->sp.size, 1);
    quat q = b->q;
    vec3 wb = q_unrotate(q, b->w);
    run_frames(&w, 20); /* 2 s */
    for (int i = 0; i < 200000; i++) rk4_rigid(&q, &wb, inertia, 1e-5);
    quat d = q_mul(q_conj(q), b->q);
    double angle = 2 * atan2(sqrt(d.x * d.x + d.y * d.y + d.z * d.z), fabs(d.w));
    print_message("tumbling box after 2 s: orientation differs from RK4 by %.3g rad\n", angle);
    assert_true(angle < 1e-4);
    assert_vec_near(b->w, q_rotate(q, wb), 1e-4);
    /* and it really tumbled: the body axes turned far from where they started */
    assert_true(fabs(b->q.w) < 0.99);
    world_free(&w);
}

/* A box with two equal sides is a symmetric top, which vroc turns in closed form:
 * whatever the step, it follows Euler's equations (RK4 with tiny steps) and keeps
 * its energy, and its axis keeps its angle to L while it goes round L. */
static void symmetric_top_is_exact_whatever_the_step(void **state)
{
    (void)state;
    const double steps[] = {0, 0.0123, 0.1};
    for (size_t k = 0; k < sizeof steps / sizeof steps[0]; k++) {
        world w;
        world_init(&w);
        w.set.internal_step = steps[k];
        body *b = add(&w, "top", SHAPE_CUBE);
        b->sp.size = v3(0.2, 0.2, 0.5);
        char err[256];
        assert_int_equal(body_build(b, err, sizeof err), 0);
        body_set_rotation(b, v3(1, -1, 0.5), 0.4);
        body_set_angular_vel(b, v3(1.5, -0.5, 2.5));
        vec3 inertia = box_inertia(b->sp.size, 1);
        quat q = b->q;
        vec3 wb = q_unrotate(q, b->w);
        vec3 L0 = world_L(b->q, inertia, b->w);
        double E0 = 0.5 * v3_dot(b->w, L0);
        vec3 axis0 = q_rotate(b->q, v3(0, 0, 1));
        double tilt0 = v3_dot(axis0, v3_norm(L0));
        run_frames(&w, 20); /* 2 s */
        for (int i = 0; i < 200000; i++) rk4_rigid(&q, &wb, inertia, 1e-5);
        quat d = q_mul(q_conj(q), b->q);
        double angle = 2 * atan2(sqrt(d.x * d.x + d.y * d.y + d.z * d.z), fabs(d.w));
        print_message("symmetric top, internal step %g: %.3g rad from RK4\n", steps[k], angle);
        assert_true(angle < 1e-8);
        vec3 L = world_L(b->q, inertia, b->w);
        assert_vec_near(L, L0, 1e-12);
        assert_near(0.5 * v3_dot(b->w, L), E0, 1e-12);
        assert_near(v3_dot(q_rotate(b->q, v3(0, 0, 1)), v3_norm(L)), tilt0, 1e-12);
        /* and it went a long way round */
        assert_true(v3_dot(q_rotate(b->q, v3(0, 0, 1)), axis0) < 0.9);
        world_free(&w);
    }
}

/* The speed limits apply where a command sets a speed (and a collision), not in
 * free flight: a box set spinning faster than max_angular turns at max_angular;
 * a skew spin, whose |w| varies as L stays, keeps L and its energy exactly. */
static void speed_limits_clamp(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    body *b = add(&w, "fast", SHAPE_SPHERE);
    char err[128];
    assert_int_equal(edit_property(&w, 0, offsetof(body, v), (double[]){20, 0, 0}, err, sizeof err), 0);
    assert_int_equal(edit_property(&w, 0, offsetof(body, w), (double[]){0, 0, 10}, err, sizeof err), 0);
    assert_near(v3_len(b->v), 8, 1e-12);
    assert_near(v3_len(b->w), 4, 1e-12);
    run_frames(&w, 1);
    assert_near(v3_len(b->v), 8, 1e-12);
    assert_true(b->x.x <= 8 * 0.1 + 1e-12);
    body *box = add_box(&w, "box", v3(0.3, 0.2, 0.1));
    box->x = v3(0, 5, 0);
    w.set.max_angular = 3;
    assert_int_equal(edit_property(&w, 1, offsetof(body, w), (double[]){2, 1, 1.5}, err, sizeof err), 0);
    edit_done(&w);
    vec3 L0 = box->L;
    double E0 = body_energy(box), wmin = HUGE_VAL, wmax = 0;
    for (int f = 0; f < 100; f++) {
        run_frames(&w, 1);
        wmin = fmin(wmin, v3_len(box->w));
        wmax = fmax(wmax, v3_len(box->w));
    }
    assert_true(wmax - wmin > 1e-3); /* |w| varies as it turns */
    assert_vec_near(box->L, L0, 1e-12);
    assert_near(body_energy(box), E0, 1e-12 * E0);
    world_free(&w);
}

static void static_objects_never_move(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    w.set.force = (dir_amount){v3(0, 0, -1), 9.8};
    body *b = add(&w, "table", SHAPE_CUBE);
    body_set_mass(b, -1);
    b->v = v3(1, 0, 0);
    run_frames(&w, 10);
    assert_vec_near(b->x, v3(0, 0, 0), 0);
    assert_int_equal(b->state, STATE_STATIC);
    world_free(&w);
}

static void internal_steps_per_frame(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    assert_int_equal(world_subframes(&w), 7); /* ceil(0.1 / (0.25 / 16)) */
    w.set.collision_dist = 0.4;
    assert_int_equal(world_subframes(&w), 4); /* exactly 0.1 / 0.025: no extra step */
    w.set.internal_step = 0.03;
    assert_int_equal(world_subframes(&w), 4);
    w.set.internal_step = 0.05;
    assert_int_equal(world_subframes(&w), 2);
    w.set.time_step = 0;
    assert_int_equal(world_subframes(&w), 0);
    w.set.time_step = 0.1;
    w.set.internal_step = 0;
    w.set.max_linear = 0;
    assert_int_equal(world_subframes(&w), 1);
    w.set.max_linear = 8;
    w.set.time_step = 1e6;
    char err[256];
    assert_int_equal(sim_frame(&w, err, sizeof err), -1);
    assert_non_null(strstr(err, "internal steps per frame"));
    world_free(&w);
}

static void pair_counts(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    for (int i = 0; i < 5; i++) {
        char name[8];
        snprintf(name, sizeof name, "d%d", i);
        add(&w, name, SHAPE_SPHERE);
    }
    for (int i = 0; i < 3; i++) {
        char name[8];
        snprintf(name, sizeof name, "s%d", i);
        body_set_mass(add(&w, name, SHAPE_CUBE), -1);
    }
    assert_int_equal(world_pairs(&w), 5 * 4 / 2 + 5 * 3);
    world_free(&w);
}

/* A held box (hold.h) under gravity: its centre goes round the pivot, which moves
 * at a constant velocity, and it turns rigidly with it, exactly whatever the
 * internal step; gravity does not move it. */
static void held_body_turns_about_its_moving_pivot(void **state)
{
    (void)state;
    const double steps[] = {0, 0.0123, 0.1};
    for (size_t k = 0; k < sizeof steps / sizeof steps[0]; k++) {
        world w;
        world_init(&w);
        w.set.force = (dir_amount){v3(0, 0, -1), 9.8};
        w.set.internal_step = steps[k];
        body *b = add_box(&w, "bat", v3(0.3, 0.05, 0.05));
        b->x = v3(0.5, 0, 1);
        vec3 p0 = v3(0.2, 0, 1), v = v3(0.5, -0.25, 1), wv = v3(0, 0, 2);
        assert_int_equal(hold_set(&w, 0, (hold_motion){p0, v, wv}), 0);
        assert_true(b->held);
        run_frames(&w, 10);
        double t = 1.0, a = 2 * t;
        vec3 r = v3(0.3 * cos(a), 0.3 * sin(a), 0); /* (0.3, 0, 0) turned by 2 rad */
        vec3 want = v3_add(v3_mad(p0, v, t), r);
        assert_vec_near(b->x, want, 1e-12);
        assert_vec_near(b->v, v3_add(v, v3_cross(wv, r)), 1e-12);
        assert_near(fabs(b->q.w), cos(0.5 * a), 1e-12);
        assert_vec_near(b->w, wv, 0);
        assert_vec_near(b->hold_pivot, v3_mad(p0, v, t), 1e-12);
        world_free(&w);
    }
}

/* sim_frame_hooked: the hook acts at its exact instant within an internal step;
 * a held ball released there flies the projectile from that instant. */
typedef struct {
    double at;
    bool done;
} release_hook;

static double release_next(void *ctx, const world *w)
{
    (void)w;
    const release_hook *r = ctx;
    return r->done ? HUGE_VAL : r->at;
}

static void release_at(void *ctx, world *w)
{
    release_hook *r = ctx;
    assert_true(w->time == r->at); /* the step was cut there */
    hold_release(w, 0, v3(1, 0, 3), v3(0, 0, 0));
    r->done = true;
}

static void hook_acts_at_its_instant(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    w.set.force = (dir_amount){v3(0, 0, -1), 9.8};
    w.set.internal_step = 0.1; /* one internal step a frame: the hook cuts it */
    body *b = add(&w, "ball", SHAPE_SPHERE);
    b->x = v3(0, 0, 2);
    assert_int_equal(hold_set(&w, 0, (hold_motion){b->x, v3(0, 0, 0), v3(0, 0, 0)}), 0);
    release_hook r = {0.1234, false};
    sim_hook hook = {release_next, release_at, &r};
    char err[128];
    for (int f = 0; f < 5; f++) assert_int_equal(sim_frame_hooked(&w, &hook, err, sizeof err), 0);
    assert_true(r.done && !b->held);
    double t = 0.5 - 0.1234;
    assert_vec_near(b->x, v3(t, 0, 2 + 3 * t - 0.5 * 9.8 * t * t), 1e-12);
    world_free(&w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(projectile_is_exact_whatever_the_step),
        cmocka_unit_test(spinning_box_keeps_its_angular_momentum),
        cmocka_unit_test(spinning_box_follows_eulers_equations),
        cmocka_unit_test(symmetric_top_is_exact_whatever_the_step),
        cmocka_unit_test(speed_limits_clamp),
        cmocka_unit_test(static_objects_never_move),
        cmocka_unit_test(internal_steps_per_frame),
        cmocka_unit_test(pair_counts),
        cmocka_unit_test(held_body_turns_about_its_moving_pivot),
        cmocka_unit_test(hook_acts_at_its_instant),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
