/* test_schedule.c: the collision heap (issue 6): its invariants, and predicted
 * collision times that are never later than the true first contact. */
#include "check.h"

#include <stdlib.h>
#include <string.h>

#include "core/schedule.h"
#include "core/edit.h"
#include "core/flight.h"
#include "core/rest.h"
#include "core/sim.h"
#include "core/world.h"
#include "worlds.h"

static void heap_keeps_its_order(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    for (int i = 0; i < 40; i++) {
        char name[8];
        snprintf(name, sizeof name, "o%d", i);
        add(&w, name, SHAPE_SPHERE);
    }
    assert_int_equal(pairs_update(&w), 0);
    assert_int_equal(sched_build(&w, 0), 0);
    assert_int_equal(w.pairs.n, 40 * 39 / 2);
    unsigned long long s = 5;
    for (int k = 0; k < 20000; k++) {
        long i = (long)urand(&s, 0, (double)w.pairs.n);
        sched_set(&w, i, urand(&s, 0, 100));
        if (k % 1000 == 0) assert_int_equal(sched_check(&w), 0);
    }
    assert_int_equal(sched_check(&w), 0);
    /* taking the top and pushing it far away yields the times in order */
    double last = -1, next;
    for (long k = 0; k < w.pairs.n; k++) {
        long i = sched_top(&w, &next);
        assert_true(next >= last);
        last = next;
        sched_set(&w, i, HUGE_VAL);
    }
    assert_int_equal(sched_check(&w), 0);
    /* every pair of object 3 made due, and only those */
    sched_object_due(&w, 3, 1.0);
    long due = 0;
    for (long i = 0; i < w.pairs.n; i++)
        if (w.pairs.p[i].next == 1.0) {
            assert_true(w.pairs.p[i].a == 3 || w.pairs.p[i].b == 3);
            due++;
        }
    assert_int_equal(due, 39);
    assert_int_equal(sched_check(&w), 0);
    /* a slide of object 5 that ends makes due its near pairs, and the far ones
     * whose times counted that slide; not the far ones found at the whole force */
    for (long i = 0; i < w.pairs.n; i++) {
        pair *p = &w.pairs.p[i];
        sched_set(&w, i, 10.0);
        p->far = i % 3 != 0;
        p->far_slide_a = p->far_slide_b = false;
        if (i % 3 == 1) *(p->a == 5 ? &p->far_slide_a : &p->far_slide_b) = true;
    }
    sched_slide_ends(&w, 5, 2.0);
    due = 0;
    for (long i = 0; i < w.pairs.n; i++) {
        const pair *p = &w.pairs.p[i];
        bool mine = p->a == 5 || p->b == 5;
        assert_true(w.pairs.p[i].next == (mine && i % 3 != 2 ? 2.0 : 10.0));
        due += w.pairs.p[i].next == 2.0;
    }
    assert_true(due > 10 && due < 39);
    assert_int_equal(sched_check(&w), 0);
    world_free(&w);
}

/* Body b flown h seconds in one flight, under the force as it feels it (less the
 * part its support takes while it slides), when it moves. */
static void fly_felt(const world *w, body *b, double h)
{
    if (b->state == STATE_DYNAMIC)
        flight_fly(b, h, world_body_accel(w, b), w->set.max_linear, w->set.max_angular);
}

/* First time the two bodies touch when flown with vroc's integrator in steps of
 * h, found to 1e-9 s; HUGE_VAL when not within tmax. */
static double first_contact(const world *w, const body *a0, const body *b0, double h, double tmax)
{
    body a = *a0, b = *b0;
    double t = 0;
    while (t < tmax) {
        body na = a, nb = b;
        fly_felt(w, &na, h);
        fly_felt(w, &nb, h);
        closest_result r = body_distance(&na, &nb, NULL);
        if (r.status != CLOSEST_SEPARATED) {
            /* contact within this step: bisect its length */
            double lo = 0, hi = h;
            while (hi - lo > 1e-9) {
                double mid = 0.5 * (lo + hi);
                na = a;
                nb = b;
                fly_felt(w, &na, mid);
                fly_felt(w, &nb, mid);
                if (body_distance(&na, &nb, NULL).status == CLOSEST_SEPARATED) lo = mid;
                else hi = mid;
            }
            return t + lo;
        }
        a = na;
        b = nb;
        t += h;
    }
    return HUGE_VAL;
}

/* Trial k of a random pair: two objects of the kinds k picks (one of them static
 * in some trials), turned, spinning and aimed at each other, in world w (made
 * here), with random limits and, in odd trials, gravity.  Returns their distance,
 * or 0 when they are not apart (w is freed then). */
static double random_pair(world *w, unsigned long long *s, int k, body *ob[2])
{
    world_init(w);
    w->set.max_linear = urand(s, 1, 12);
    w->set.max_angular = urand(s, 1, 8);
    if (k % 2) w->set.force = (dir_amount){v3(urand(s, -1, 1), urand(s, -1, 1), -1), 9.8};
    for (int j = 0; j < 2; j++) {
        char name[4] = {(char)('a' + j), 0};
        ob[j] = add(w, name, (shape_kind)((k + j) % 3));
        body *b = ob[j];
        b->sp.radius = urand(s, 0.1, 0.5);
        b->sp.size = v3(urand(s, 0.05, 0.5), urand(s, 0.05, 0.5), urand(s, 0.05, 0.5));
        b->sp.a1 = urand(s, 0.1, 0.5);
        b->sp.a2 = urand(s, 0.1, 0.5);
        b->sp.a3 = urand(s, 0.05, 0.5);
        b->sp.exp1 = urand(s, 0.2, 2);
        b->sp.exp2 = urand(s, 0.2, 2);
        char err[256];
        assert_int_equal(body_build(b, err, sizeof err), 0);
        body_set_rotation(b, v3(urand(s, -1, 1), urand(s, -1, 1), urand(s, -1, 1)), urand(s, 0, 3));
        body_set_angular_vel(b, v3(urand(s, -6, 6), urand(s, -6, 6), urand(s, -6, 6)));
    }
    if (k % 5 == 0) body_set_mass(ob[1], -1); /* a static partner, */
    if (k % 5 == 1) body_set_mass(ob[0], -1); /* first or second */
    ob[0]->x = v3(0, 0, 0);
    ob[1]->x = v3(urand(s, 1.2, 3), urand(s, -0.5, 0.5), urand(s, -0.5, 0.5));
    /* aimed at each other, with some scatter */
    vec3 dir = v3_norm(v3_sub(ob[1]->x, ob[0]->x));
    ob[0]->v = v3_add(v3_scale(dir, urand(s, 0, 8)), v3(urand(s, -1, 1), urand(s, -1, 1), urand(s, -1, 1)));
    if (!body_is_static(ob[1]))
        ob[1]->v = v3_add(v3_scale(dir, -urand(s, 0, 4)), v3(urand(s, -1, 1), urand(s, -1, 1), urand(s, -1, 1)));
    closest_result r = body_distance(ob[0], ob[1], NULL);
    if (r.status != CLOSEST_SEPARATED) {
        world_free(w);
        return 0;
    }
    assert_int_equal(pairs_update(w), 0);
    return r.distance;
}

static void predictions_are_never_late(void **state)
{
    (void)state;
    unsigned long long s = 11;
    int collided = 0, tight = 0, far_useful = 0, ball_gaps = 0;
    const int trials = 600;
    for (int k = 0; k < trials; k++) {
        world w;
        body *ob[2];
        double d = random_pair(&w, &s, k, ob);
        if (d == 0) continue;
        double predicted = sched_predict(&w, &w.pairs.p[0], d);
        /* the bound that allows any spin and a few jumps is earlier still */
        double far = sched_predict_far(&w, ob[0], ob[1], d, true, true);
        if (far > predicted) fail_msg("trial %d: far bound %.9g s after %.9g s", k, far, predicted);
        if (far >= 0.5 * predicted) far_useful++;
        /* from the gap of the spheres about the centres of mass that hold them,
         * which no turn changes: no turn counted */
        double balls = v3_len(v3_sub(body_com(ob[0]), body_com(ob[1]))) - ob[0]->shape.r_out -
                       ob[1]->shape.r_out;
        double unturned = balls > 0 ? sched_predict_far(&w, ob[0], ob[1], balls, false, false) : 0;
        double truth = first_contact(&w, ob[0], ob[1], urand(&s, 0.001, 0.02), 3);
        if (truth < HUGE_VAL) collided++;
        if (predicted > truth)
            fail_msg("trial %d: predicted %.9g s but they touch at %.9g s", k, predicted, truth);
        if (unturned > truth)
            fail_msg("trial %d: far bound from the spheres' gap %.9g s, but they touch at %.9g s", k,
                     unturned, truth);
        if (balls > 0) ball_gaps++;
        if (truth < HUGE_VAL && predicted > 0.3 * truth) tight++;
        world_free(&w);
    }
    print_message("never late: %d of %d trials collided; %d predictions within 70%% of the truth; "
                  "%d far bounds at least half the prediction; %d from the spheres' gap\n",
                  collided, trials, tight, far_useful, ball_gaps);
    assert_true(collided > trials / 3); /* the test must exercise real collisions */
    assert_true(tight > collided / 4);  /* and the bound must be of use */
    assert_true(far_useful > trials / 2); /* the far one too */
    assert_true(ball_gaps > trials / 4);  /* and the spheres' gap was tried */
}

/* A far pair's time holds when a slide of one of its objects ends, unless it
 * counted that slide's lesser acceleration: only a steady slide (on a face of a
 * still support, turning about its normal only) is counted so, and a slide that
 * ends makes due the pairs that did (sched_slide_ends).  Objects slide on random
 * supports, then fly under the whole force from a random instant on: no far time
 * found while they slid is later than their first contact. */
static void far_times_hold_when_a_slide_ends(void **state)
{
    (void)state;
    unsigned long long s = 29;
    int collided = 0, steadier = 0, tried = 0;
    const int trials = 600;
    for (int k = 0; k < trials; k++) {
        world w;
        body *ob[2];
        double d = random_pair(&w, &s, 2 * k + 1, ob); /* with gravity */
        if (d == 0) continue;
        int i = body_is_static(ob[0]) ? 1 : 0;
        body *m = ob[i], *o = ob[1 - i];
        /* slow, the force mostly towards the other, which the slide holds back */
        vec3 to = v3_norm(v3_sub(o->x, m->x));
        w.set.force = (dir_amount){v3_add(to, v3(urand(&s, -0.5, 0.5), urand(&s, -0.5, 0.5), 0)), 9.8};
        for (int j = 0; j < 2; j++)
            if (!body_is_static(ob[j])) ob[j]->v = v3(urand(&s, -1, 1), urand(&s, -1, 1), urand(&s, -1, 1));
        /* pressed onto a support on the far side from the other, tilted up to 60 degrees */
        vec3 g = world_accel(&w);
        vec3 up = v3_neg(v3_norm(g));
        vec3 n = v3_norm(v3_add(up, v3(urand(&s, -1, 1), urand(&s, -1, 1), urand(&s, -1, 1))));
        if (v3_dot(n, up) < 0.5) {
            world_free(&w);
            continue;
        }
        m->slide = 1 - i;
        m->slide_n = n;
        m->slide_steady = false;
        double far = sched_predict_far(&w, ob[0], ob[1], d, true, true);
        m->slide_steady = true;
        double steady = sched_predict_far(&w, ob[0], ob[1], d, true, true);
        if (steady > far) steadier++;
        if (steady < far) fail_msg("trial %d: a steady slide's far time %.9g s before %.9g s", k, steady, far);
        /* it slides until tau, and falls under the whole force from there */
        double tau = urand(&s, 0, 1) * fmin(far, 1), h = urand(&s, 0.001, 0.02);
        double truth = first_contact(&w, ob[0], ob[1], h, tau);
        if (truth == HUGE_VAL) {
            body a = *ob[0], b = *ob[1];
            fly_felt(&w, &a, tau);
            fly_felt(&w, &b, tau);
            (i == 0 ? &a : &b)->slide = -1;
            truth = tau + first_contact(&w, &a, &b, h, 5);
        }
        tried++;
        if (truth < HUGE_VAL) collided++;
        if (far > truth)
            fail_msg("trial %d: far time %.9g s while sliding, but they touch at %.9g s (the slide "
                     "ended at %.9g s)",
                     k, far, truth, tau);
        world_free(&w);
    }
    print_message("slides that end: %d trials, %d collided; %d steady slides' far times later\n", tried,
                  collided, steadier);
    assert_true(tried > trials / 3);
    assert_true(collided > tried / 8); /* the test must exercise real collisions */
    assert_true(steadier > tried / 2);
}

/* Body b flown h seconds in one flight, when it moves. */
static void fly(const world *w, body *b, double h)
{
    if (!body_is_static(b)) flight_fly(b, h, world_accel(w), w->set.max_linear, w->set.max_angular);
}

/* Whether b flies h seconds within the speed limits (sim.c, unlimited). */
static bool unlimited(const world *w, const body *b, double h)
{
    return body_is_static(b) || (v3_len(b->v) + v3_len(world_accel(w)) * h < w->set.max_linear &&
                                 v3_len(b->w) < w->set.max_angular);
}

/* A near pair's time made again after a collision changed one of its objects'
 * motion before that time (sim.c, repredict): from what the bound kept at the
 * check leaves of the distance, or, for a check at the end of the step after the
 * change, from its distance there less what the old flights could have closed
 * since the change; the other object known only where its flight starts.  Never
 * later than the true first contact of the new motions. */
static void kept_bounds_are_never_late(void **state)
{
    (void)state;
    unsigned long long s = 17;
    int left_some = 0, collided = 0, tight = 0;
    const int trials = 600;
    for (int k = 0; k < trials; k++) {
        world w;
        body *ob[2];
        double d = random_pair(&w, &s, k, ob);
        if (d == 0) continue;
        sched_bound kept;
        double until = fmin(sched_predict_kept(&w, ob[0], ob[1], d, 0, 0, &kept), 1);
        /* in a third of the trials the check comes after the change, at the end of
         * the step: it found the pair at distance d_end at t_end, with the flights
         * from before the change */
        bool later = k % 3 == 2;
        double t_end = urand(&s, 0.05, 0.5), d_end = 0;
        if (later) { /* parting until then: the distance at t_end is more than at t */
            ob[0]->v = v3_neg(ob[0]->v);
            ob[1]->v = v3_neg(ob[1]->v);
        }
        double t = urand(&s, 0, 1) * (later ? t_end : until);
        /* both fly to t, each in one flight from the start, as the simulation flies */
        body a = *ob[0], b = *ob[1], ae = *ob[0], be = *ob[1];
        vec3 g = world_accel(&w);
        fly(&w, &a, t);
        fly(&w, &b, t);
        int i = body_is_static(ob[0]) ? 1 : body_is_static(ob[1]) ? 0 : (k / 2) % 2;
        if (later) {
            fly(&w, &ae, t_end);
            fly(&w, &be, t_end);
            closest_result r = body_distance(&ae, &be, NULL);
            const body *pre = i == 0 ? &a : &b, *o = ob[1 - i];
            if (r.status != CLOSEST_SEPARATED || !unlimited(&w, pre, t_end - t) ||
                !unlimited(&w, o, t_end)) {
                world_free(&w);
                continue;
            }
            d_end = r.distance;
        }
        const body *o = ob[1 - i];
        double slack = body_is_static(o) ? 0 : v3_len(g) * t;
        double left = later ? d_end - (i == 0 ? sched_closing(&w, &a, o, 0, slack, t_end - t)
                                              : sched_closing(&w, o, &b, slack, 0, t_end - t))
                            : sched_left(&kept, t);
        /* where a collision sends one of them off anew */
        body *m = i == 0 ? &a : &b;
        vec3 at = v3_norm(v3_sub(ob[1 - i]->x, m->x)); /* mostly at the other */
        m->v = v3_add(v3_scale(at, urand(&s, 0, 8)), v3(urand(&s, -2, 2), urand(&s, -2, 2), urand(&s, -2, 2)));
        body_set_angular_vel(m, v3(urand(&s, -6, 6), urand(&s, -6, 6), urand(&s, -6, 6)));
        if (left <= 0) { /* due at once: nothing to predict */
            world_free(&w);
            continue;
        }
        left_some++;
        sched_bound again;
        double next = i == 0 ? sched_predict_kept(&w, m, o, left, 0, slack, &again)
                             : sched_predict_kept(&w, o, m, left, slack, 0, &again);
        double truth = first_contact(&w, &a, &b, urand(&s, 0.001, 0.02), 3);
        if (truth < HUGE_VAL) collided++;
        if (next > truth)
            fail_msg("trial %d: made again %.9g s after the change, but they touch %.9g s after it", k,
                     next, truth);
        if (truth < HUGE_VAL && next > 0.2 * truth) tight++;
        world_free(&w);
    }
    print_message("kept bounds: %d of %d trials left some distance, %d of those collided, %d made "
                  "within 80%% of the truth\n",
                  left_some, trials, collided, tight);
    assert_true(left_some > trials / 3);
    assert_true(collided > left_some / 4);
    assert_true(tight > collided / 4);
}

/* The time along the normal (sched_predict_along) is never later than the true
 * first contact either, with the objects sent every way: at each other, anywhere,
 * or across the line between them; and it is later than the bound from speeds
 * alone where they do not come on straight. */
static void along_predictions_are_never_late(void **state)
{
    (void)state;
    unsigned long long s = 23;
    int collided = 0, later = 0, much_later = 0;
    const int trials = 900;
    for (int k = 0; k < trials; k++) {
        world w;
        body *ob[2];
        if (random_pair(&w, &s, k, ob) == 0) continue;
        vec3 dir = v3_norm(v3_sub(ob[1]->x, ob[0]->x));
        for (int j = 0; j < 2 && k % 3 != 0; j++) {
            if (body_is_static(ob[j])) continue;
            vec3 v = v3(urand(&s, -4, 4), urand(&s, -4, 4), urand(&s, -4, 4));
            if (k % 3 == 2) v = v3_mad(v, dir, -v3_dot(v, dir)); /* across */
            ob[j]->v = v;
        }
        if (k % 4 == 3) body_set_angular_vel(ob[0], v3(0, 0, 0)); /* one not turning */
        for (int j = 0; j < 2 && k % 5 == 4; j++) /* at 90% to 100% of the speed limit */
            if (v3_len(ob[j]->v) > 0)
                ob[j]->v = v3_scale(v3_norm(ob[j]->v), urand(&s, 0.9, 1) * w.set.max_linear);
        closest_result r = body_distance(ob[0], ob[1], NULL);
        if (r.status != CLOSEST_SEPARATED) {
            world_free(&w);
            continue;
        }
        double speeds = sched_predict_bodies(&w, ob[0], ob[1], r.distance);
        double along = sched_predict_along(&w, ob[0], ob[1], r.distance, v3_neg(r.normal), r.pa, r.pb);
        double truth = first_contact(&w, ob[0], ob[1], urand(&s, 0.001, 0.02), 3);
        if (truth < HUGE_VAL) collided++;
        /* exact for objects that do not turn: allowed the 1e-9 s to which
         * first_contact finds the contact (its last time apart) */
        if (along > truth + 1e-9)
            fail_msg("trial %d: along the normal %.12g s, but they touch at %.12g s", k, along, truth);
        if (along > speeds) later++;
        if (along > 2 * speeds) much_later++;
        world_free(&w);
    }
    print_message("along the normal: %d of %d trials collided; %d later than the bound from speeds, "
                  "%d twice as late\n",
                  collided, trials, later, much_later);
    assert_true(collided > trials / 6);
    assert_true(later > trials / 4);
    assert_true(much_later > trials / 8);
}

/* A ball going away from a wall and fast across it, under a force mostly across:
 * the speed limit soon holds it back, it turns its velocity along the force and
 * comes back long before the parabola would.  The time along the normal must stop
 * where the limit may start to act. */
static void along_stops_at_the_speed_limit(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    w.set.max_linear = 5;
    w.set.force = (dir_amount){v3(-2, 20, 0), v3_len(v3(-2, 20, 0))}; /* 2 m/s^2 back */
    body *wall = add_static_box(&w, "wall", v3(0.1, 100, 100));
    body *ball = add_ball(&w, "ball", 0.1);
    ball->x = v3(0.5, 0, 0);
    ball->v = v3(2, 4.5, 0); /* away at 2 m/s: 4.92 m/s in all */
    closest_result r = body_distance(wall, ball, NULL);
    assert_int_equal(r.status, CLOSEST_SEPARATED);
    double along = sched_predict_along(&w, wall, ball, r.distance, v3_neg(r.normal), r.pa, r.pb);
    double truth = first_contact(&w, wall, ball, 0.001, 5);
    double parabola = 1 + sqrt(1 + r.distance); /* 2 t - t^2 = -d */
    print_message("going off a wall at the speed limit: back at %.4f s (the parabola: %.4f s); "
                  "along the normal %.4f s\n",
                  truth, parabola, along);
    assert_true(truth < parabola - 0.1); /* the limit acts */
    assert_true(along <= truth);
    world_free(&w);
}

/* Thirty objects of the three kinds, thrown at random over a floor. */
static void pile(world *w, bool heap)
{
    world_init(w);
    w->set.collision_heap = heap;
    w->set.force = (dir_amount){v3(0, 0, -1), 9.8};
    unsigned long long s = 3;
    body *floor_ = add(w, "floor", SHAPE_CUBE);
    floor_->sp.size = v3(3, 3, 0.1);
    char err[256];
    assert_int_equal(body_build(floor_, err, sizeof err), 0);
    body_set_mass(floor_, -1);
    for (int i = 0; i < 30; i++) {
        char name[8];
        snprintf(name, sizeof name, "o%d", i);
        body *b = add(w, name, (shape_kind)(i % 3));
        b->sp.radius = 0.15;
        b->sp.size = v3(0.15, 0.1, 0.12);
        b->sp.a1 = b->sp.a2 = b->sp.a3 = 0.14;
        b->sp.exp1 = 0.6;
        assert_int_equal(body_build(b, err, sizeof err), 0);
        b->x = v3((i % 6) * 0.5 - 1.25, (i / 6) * 0.5 - 1, 0.6 + urand(&s, 0, 1.5));
        b->v = v3(urand(&s, -1, 1), urand(&s, -1, 1), urand(&s, -1, 1));
        body_set_angular_vel(b, v3(urand(&s, -2, 2), urand(&s, -2, 2), urand(&s, -2, 2)));
        b->elasticity = 0.7;
    }
}

/* Fails unless every object of the two worlds is in the same state to the bit. */
static void same_states(const world *w0, const world *w1, int frame, const char *what)
{
    for (int i = 0; i < w0->n; i++) {
        const body *a = w0->bodies[i], *b = w1->bodies[i];
        if (memcmp(&a->x, &b->x, sizeof a->x) != 0 || memcmp(&a->q, &b->q, sizeof a->q) != 0 ||
            memcmp(&a->v, &b->v, sizeof a->v) != 0 || a->state != b->state)
            fail_msg("frame %d: %s differs %s: dx %g dv %g states %d %d", frame, a->name, what,
                     v3_dist(a->x, b->x), v3_dist(a->v, b->v), a->state, b->state);
    }
}

/* The heap and checking every pair give the same trajectories. */
static void heap_on_and_off_agree(void **state)
{
    (void)state;
    world ws[2];
    for (int m = 0; m < 2; m++) pile(&ws[m], m == 0);
    char err[256];
    for (int f = 0; f < 25; f++) {
        for (int m = 1; m >= 0; m--) assert_int_equal(sim_frame(&ws[m], err, sizeof err), 0);
        same_states(&ws[0], &ws[1], f, "with the heap on and off");
    }
    print_message("heap on: %ld pair checks, off: %ld; %ld collisions\n", ws[0].st.pair_checks,
                  ws[1].st.pair_checks, ws[0].st.collisions);
    assert_true(ws[0].st.collisions > 30);
    assert_true(ws[0].st.pair_checks < ws[1].st.pair_checks);
    world_free(&ws[0]);
    world_free(&ws[1]);
}

/* Runs w (heap on) for n frames, and fails unless after every one each moving
 * object's bounding sphere lies within its box (sched_box) and every parked pair
 * waits at +inf with boxes that do not meet: so no parked pair can touch.
 * Returns the parked pairs seen, frame by frame. */
static long frames_in_boxes(world *w, int n)
{
    char err[256];
    long parked = 0;
    for (int f = 0; f < n; f++) {
        assert_int_equal(sim_frame(w, err, sizeof err), 0);
        assert_int_equal(sched_check(w), 0);
        for (int k = 0; k < w->n; k++) {
            const body *b = w->bodies[k];
            const sched_box *x = &w->sched.box[k];
            if (b->state != STATE_DYNAMIC) continue;
            vec3 c = body_com(b), r = v3(b->shape.r_out, b->shape.r_out, b->shape.r_out);
            vec3 lo = v3_sub(c, r), hi = v3_add(c, r);
            if (lo.x < x->lo.x || lo.y < x->lo.y || lo.z < x->lo.z || hi.x > x->hi.x ||
                hi.y > x->hi.y || hi.z > x->hi.z)
                fail_msg("frame %ld: %s is out of its box", w->frame, b->name);
        }
        for (long i = 0; i < w->pairs.n; i++) {
            const pair *p = &w->pairs.p[i];
            if (!w->sched.parked[i]) continue;
            parked++;
            assert_true(p->next == HUGE_VAL);
            assert_true(sched_boxes_apart(w, p->a, p->b));
        }
    }
    return parked;
}

/* The broad phase in a pile of thrown objects: boxes made again when they end,
 * and after collisions beyond them. */
static void boxes_hold_a_pile(void **state)
{
    (void)state;
    world w;
    pile(&w, true);
    w.set.time_step = 0.02; /* a look after every internal step or two */
    long parked = frames_in_boxes(&w, 200);
    print_message("%ld parked pairs seen in 200 frames; %ld collisions\n", parked, w.st.collisions);
    assert_true(w.st.collisions > 50);
    assert_true(parked > 200 * w.pairs.n / 4); /* a quarter of the pairs, or more */
    world_free(&w);
}

/* The broad phase when motion leaves a box's bound without a collision beyond
 * it: a box that slides slowly on a high table (its box counts the slide's lesser
 * acceleration) goes over the edge and falls; a ball slides along the floor into
 * a box at rest there (its box holds it where it is) and sets it moving. */
static void boxes_end_when_a_slide_ends_or_a_rest(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    w.set.collision_heap = true;
    w.set.force = (dir_amount){v3(0, 0, -1), 9.8};
    w.set.time_step = 0.02;
    add_static_box(&w, "floor", v3(4, 4, 0.1))->x = v3(0, 0, -0.1);
    add_static_box(&w, "table", v3(0.5, 0.5, 0.05))->x = v3(-1, 0, 2);
    body *slider = add_box(&w, "slider", v3(0.1, 0.1, 0.1));
    slider->x = v3(-1.3, 0, 2.151);
    slider->v = v3(0.2, 0, 0);
    body *still = add_box(&w, "still", v3(0.1, 0.1, 0.1));
    still->x = v3(1, 0, 0.101);
    body *ball = add_ball(&w, "ball", 0.1);
    ball->x = v3(-0.3, 0, 0.101);
    ball->v = v3(1, 0, 0);
    slider->elasticity = still->elasticity = ball->elasticity = 0;
    bool rested = false;
    long parked = 0;
    for (int f = 0; f < 300; f++) {
        parked += frames_in_boxes(&w, 1);
        rested = rested || still->state == STATE_RESTING;
    }
    print_message("slider at z %.3f, still box at x %.3f (rested first: %s); %ld parked pairs\n",
                  slider->x.z, still->x.x, rested ? "yes" : "no", parked);
    assert_true(slider->x.z < 0.5); /* fell off */
    assert_true(rested && still->x.x > 1.05); /* rested, then struck */
    assert_true(parked > 0);
    world_free(&w);
}

/* sim_prepare (what `start` does before time runs) leaves the schedule built and
 * the scratch of the steps in place, and changes no trajectory. */
static void prepared_worlds_move_the_same(void **state)
{
    (void)state;
    world ws[2];
    for (int m = 0; m < 2; m++) pile(&ws[m], true);
    assert_int_equal(sim_prepare(&ws[0]), 0);
    assert_false(ws[0].sched_dirty);
    assert_int_equal(sched_check(&ws[0]), 0);
    assert_true(ws[0].step.capdue >= ws[0].pairs.n);
    assert_true(ws[0].step.cap >= ws[0].n);
    for (long i = 0; i < ws[0].pairs.n; i++) assert_true(ws[0].pairs.p[i].next == ws[0].time);
    assert_int_equal(sim_prepare(&ws[0]), 0); /* again: nothing to do */
    char err[256];
    for (int f = 0; f < 10; f++) {
        for (int m = 0; m < 2; m++) assert_int_equal(sim_frame(&ws[m], err, sizeof err), 0);
        same_states(&ws[0], &ws[1], f, "prepared and not");
    }
    assert_true(ws[0].st.collisions > 0);
    world_free(&ws[0]);
    world_free(&ws[1]);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(heap_keeps_its_order),
        cmocka_unit_test(predictions_are_never_late),
        cmocka_unit_test(far_times_hold_when_a_slide_ends),
        cmocka_unit_test(kept_bounds_are_never_late),
        cmocka_unit_test(along_predictions_are_never_late),
        cmocka_unit_test(along_stops_at_the_speed_limit),
        cmocka_unit_test(heap_on_and_off_agree),
        cmocka_unit_test(boxes_hold_a_pile),
        cmocka_unit_test(boxes_end_when_a_slide_ends_or_a_rest),
        cmocka_unit_test(prepared_worlds_move_the_same),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
