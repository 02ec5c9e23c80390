/* test_schedule.c: the collision heap (issue 6) and the search for first contacts
 * (issue 23): the heap's invariants; bounds that are never later than the true
 * first contact, checked against contacts found by sampling the exact flights
 * densely; the search's contact at the true time; the heap on and off alike. */
#include "check.h"

#include <stdlib.h>
#include <string.h>

#include "core/schedule.h"
#include "core/edit.h"
#include "core/flight.h"
#include "core/rest.h"
#include "core/sim.h"
#include "core/step.h"
#include "core/toi.h"
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
        long i = sched_pair_id(&w.sched, (long)urand(&s, 0, (double)w.pairs.n));
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
    world_free(&w);
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

/* The two bodies of w flown freely (as the flights of the world start them at
 * time 0) to time t, into a and b. */
static void flown(const world *w, double t, body *a, body *b)
{
    step_fly(w, 0, t, a);
    step_fly(w, 1, t, b);
}

/* First time the two bodies of w (flights started) come within `gap` of each
 * other, found by sampling every h seconds and bisecting to 1e-10 s (the end of
 * the last bracket: they are within the gap by then); HUGE_VAL when not within
 * tmax. */
static double first_contact(const world *w, double h, double tmax, double gap)
{
    body a = *w->bodies[0], b = *w->bodies[1];
    for (double t = 0; t < tmax; t += h) {
        flown(w, t + h, &a, &b);
        closest_result r = body_distance(&a, &b, NULL);
        if (r.status != CLOSEST_SEPARATED || r.distance <= gap) {
            double lo = t, hi = t + h;
            while (hi - lo > 1e-10) {
                double mid = 0.5 * (lo + hi);
                flown(w, mid, &a, &b);
                r = body_distance(&a, &b, NULL);
                if (r.status == CLOSEST_SEPARATED && r.distance > gap) lo = mid;
                else hi = mid;
            }
            return hi; /* within the gap by then */
        }
    }
    return HUGE_VAL;
}

/* The motion of body i of w at time 0, as the bounds take it (step.h). */
static sched_move move_of(const world *w, int i)
{
    return step_move(w, i, w->bodies[i]);
}

/* Random pairs, spinning and aimed at each other, some static, some under
 * gravity: the bound from the spheres' gap and the bound along the normal are
 * never later than the first contact found by sampling the exact flights, and
 * the search (conservative advancement) finds that contact, to within the
 * sampling's resolution, never after it. */
static void predictions_are_never_late(void **state)
{
    (void)state;
    unsigned long long s = 11;
    int collided = 0, tight = 0;
    const int trials = 400;
    for (int k = 0; k < trials; k++) {
        world w;
        body *ob[2];
        double d = random_pair(&w, &s, k, ob);
        if (d == 0) continue;
        assert_int_equal(sim_prepare(&w), 0);
        for (int i = 0; i < 2; i++) step_start(&w, i, 0);
        sched_move ma = move_of(&w, 0), mb = move_of(&w, 1);
        closest_result r = body_distance(ob[0], ob[1], NULL);
        double sphere = sched_sphere_time(ob[0], &ma, ob[1], &mb);
        double touch = tol_touch(ob[0], ob[1]);
        double along = sched_ca_time(ob[0], &ma, ob[1], &mb, d, r.normal, r.pa, r.pb, touch);
        double truth = first_contact(&w, urand(&s, 0.0005, 0.003), 2, touch);
        toi_output o = toi_find(&w, &(toi_input){.a = 0, .b = 1, .lo = 0, .hi = 2});
        if (sphere > truth) fail_msg("trial %d: spheres' bound %.12g s, contact at %.12g s", k, sphere, truth);
        if (along > truth) fail_msg("trial %d: normal's bound %.12g s, contact at %.12g s", k, along, truth);
        if (truth < HUGE_VAL) {
            collided++;
            if (o.state != TOI_HIT) fail_msg("trial %d: no contact found, but they touch at %.12g s", k, truth);
            /* found at or before the sampled time (sampling may miss a graze the
             * search sees first), and not long before */
            if (o.t > truth + 1e-9) fail_msg("trial %d: found at %.12g s, contact at %.12g s", k, o.t, truth);
            if (o.t >= truth - 1e-6) tight++;
        } else if (o.state == TOI_HIT) {
            /* a contact the sampling passed over: a graze, within the contact
             * distance at the time found */
            body a = *ob[0], b = *ob[1];
            flown(&w, o.t, &a, &b);
            closest_result rr = body_distance(&a, &b, NULL);
            assert_true(rr.status != CLOSEST_SEPARATED || rr.distance <= touch);
        }
        world_free(&w);
    }
    print_message("never late: %d of %d trials collided, %d found within 1e-6 s of the sampled time\n",
                  collided, trials, tight);
    assert_true(collided > trials / 3); /* the test must exercise real collisions */
    assert_true(tight > collided * 9 / 10);
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
        cmocka_unit_test(heap_on_and_off_agree),
        cmocka_unit_test(prepared_worlds_move_the_same),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
