/* test_broad.c: the broad phase (issue 27): a pair exists before its objects' earliest
 * possible contact, over many random configurations; its boxes cover their objects
 * along their flights; the heap on (near pairs only) and off (every pair, every
 * internal step) give the same trajectories to the bit; pairs are made and ended
 * as objects come near and move apart, and their number grows with what is near;
 * a body the hand holds (hold.h) is covered by its box too, and its pairs are found
 * afresh whenever the hand sets its motion, within a frame as between frames. */
#include "check.h"

#include <stdlib.h>
#include <string.h>

#include "core/broad.h"
#include "core/flight.h"
#include "core/hold.h"
#include "core/pairs.h"
#include "core/sim.h"
#include "core/step.h"
#include "core/world.h"
#include "worlds.h"

/* A closed room of half-extents (L, L, H) (floor, ceiling and four walls, static),
 * with n random objects of the three kinds in it, spread so that most pairs are
 * far at the start and come near as they fly: random sizes (one large object in
 * some trials), turns, speeds up to max_linear, spins, elasticities, and gravity in
 * odd trials.  The same trial k gives the same world. */
static void random_room(world *w, int k, int n, bool heap)
{
    world_init(w);
    unsigned long long s = 1000 + (unsigned long long)k;
    w->set.collision_heap = heap;
    w->set.max_linear = urand(&s, 1, 12);
    w->set.max_angular = urand(&s, 1, 8);
    w->set.collision_dist = urand(&s, 0.1, 0.5);
    if (k % 2) w->set.force = (dir_amount){v3(urand(&s, -0.3, 0.3), urand(&s, -0.3, 0.3), -1), 9.8};
    double L = urand(&s, 1.5, 3), H = urand(&s, 1, 2), t = 0.2;
    const struct {
        vec3 size, at;
    } walls[6] = {{v3(L, L, t), v3(0, 0, -H - t)}, {v3(L, L, t), v3(0, 0, H + t)},
                  {v3(t, L, H), v3(-L - t, 0, 0)}, {v3(t, L, H), v3(L + t, 0, 0)},
                  {v3(L, t, H), v3(0, -L - t, 0)}, {v3(L, t, H), v3(0, L + t, 0)}};
    for (int j = 0; j < 6; j++) {
        char name[16];
        snprintf(name, sizeof name, "wall%d", j);
        body *b = add_static_box(w, name, walls[j].size);
        b->x = walls[j].at;
    }
    for (int i = 0; i < n; i++) {
        char name[16];
        snprintf(name, sizeof name, "o%d", i);
        body *b = add(w, name, (shape_kind)((i + k) % 3));
        double r = i == 0 && k % 3 == 0 ? urand(&s, 0.4, 0.6) : urand(&s, 0.05, 0.2);
        b->sp.radius = r;
        b->sp.size = v3(r * urand(&s, 0.3, 1), r * urand(&s, 0.3, 1), r * urand(&s, 0.3, 1));
        b->sp.a1 = r;
        b->sp.a2 = r * urand(&s, 0.5, 1);
        b->sp.a3 = r * urand(&s, 0.5, 1);
        b->sp.exp1 = urand(&s, 0.3, 1.8);
        b->sp.exp2 = urand(&s, 0.3, 1.8);
        rebuild(b);
        b->elasticity = urand(&s, 0.3, 1);
        /* a place clear of the others (their spheres) and of the walls */
        for (int tries = 0;; tries++) {
            assert_true(tries < 10000);
            double R = b->shape.r_out;
            vec3 c = v3(urand(&s, -L + R, L - R), urand(&s, -L + R, L - R), urand(&s, -H + R, H - R));
            bool clear = true;
            for (int j = 6; j < w->n - 1 && clear; j++)
                clear = v3_dist(c, body_com(w->bodies[j])) > R + w->bodies[j]->shape.r_out;
            if (clear) {
                b->x = c;
                break;
            }
        }
        body_set_rotation(b, v3(urand(&s, -1, 1), urand(&s, -1, 1), urand(&s, -1, 1)), urand(&s, 0, 3));
        double v = urand(&s, 0, w->set.max_linear);
        b->v = v3_scale(v3_norm(v3(urand(&s, -1, 1), urand(&s, -1, 1), urand(&s, -1, 1))), v);
        body_set_angular_vel(b, v3(urand(&s, -3, 3), urand(&s, -3, 3), urand(&s, -3, 3)));
    }
}

/* Fails unless every object of the two worlds is in the same state to the bit. */
static void same_states(const world *w0, const world *w1, int trial, int frame)
{
    for (int i = 0; i < w0->n; i++) {
        const body *a = w0->bodies[i], *b = w1->bodies[i];
        if (memcmp(&a->x, &b->x, sizeof a->x) != 0 || memcmp(&a->q, &b->q, sizeof a->q) != 0 ||
            memcmp(&a->v, &b->v, sizeof a->v) != 0 || memcmp(&a->L, &b->L, sizeof a->L) != 0 ||
            a->state != b->state)
            fail_msg("trial %d, frame %d: %s differs with the heap on and off: dx %g dv %g", trial,
                     frame, a->name, v3_dist(a->x, b->x), v3_dist(a->v, b->v));
    }
}

/* Fails unless the broad phase holds (broad_check). */
static void broad_checks_out(const world *w, int trial, int frame)
{
    char err[256];
    if (broad_check(w, err, sizeof err) != 0) fail_msg("trial %d, frame %d: %s", trial, frame, err);
}

/* Many random rooms, each run with the heap on (near pairs only) and off (every
 * pair searched at every internal step): the same states to the bit after every
 * frame, no contact ever found of a pair the broad phase did not hold near (it
 * would have been late: late_pairs), and the broad phase's invariants after every
 * frame.  The rooms exercise it: pairs are made and ended on the way, many fewer
 * exist than there are pairs, and the objects collide. */
static void pairs_are_never_late(void **state)
{
    (void)state;
    const int trials = 30, frames = 8;
    long collisions = 0, refits = 0, made = 0, ended = 0;
    double share = 0;
    for (int k = 0; k < trials; k++) {
        world ws[2];
        int n = 20 + k % 17;
        for (int m = 0; m < 2; m++) random_room(&ws[m], k, n, m == 0);
        char err[256];
        for (int f = 0; f < frames; f++) {
            long live = ws[0].pairs.live;
            for (int m = 0; m < 2; m++) {
                if (sim_frame(&ws[m], err, sizeof err) != 0) fail_msg("trial %d: %s", k, err);
                broad_checks_out(&ws[m], k, f);
            }
            same_states(&ws[0], &ws[1], k, f);
            if (f > 0 && ws[0].pairs.live > live) made++;
            if (f > 0 && ws[0].pairs.live < live) ended++;
            share += (double)ws[0].pairs.live / (double)world_pairs(&ws[0]);
        }
        assert_int_equal(ws[0].st.late_pairs, 0);
        assert_int_equal(ws[1].st.late_pairs, 0);
        assert_int_equal(ws[1].pairs.live, world_pairs(&ws[1])); /* heap off: every pair */
        collisions += ws[0].st.collisions;
        refits += ws[0].broad.refits;
        world_free(&ws[0]);
        world_free(&ws[1]);
    }
    share /= trials * frames;
    print_message("never late: %d rooms x %d frames, %ld collisions, %ld boxes made again, "
                  "pairs grew in %ld frames and shrank in %ld; %.1f%% of the pairs existed\n",
                  trials, frames, collisions, refits, made, ended, 100 * share);
    assert_true(collisions > trials * 10);
    assert_true(refits > trials * 20);
    assert_true(made > trials && ended > trials);
    assert_true(share < 0.5);
}

/* The hand of the held-body tests: every HAND_ROW seconds (a tracker's rows), the
 * held body gets a new motion from the seeded sequence: its pivot goes at up to
 * 3 m/s in a new direction, mostly towards the room's middle, and it turns at up to
 * 4 rad/s.  The same seed gives the same hand in both worlds. */
#define HAND_ROW 0.037

typedef struct {
    int held;                /* the body it holds */
    unsigned long long seed;
    double next;             /* its next row */
    long rows;
} test_hand;

static void hand_motion(test_hand *h, world *w)
{
    const body *b = w->bodies[h->held];
    vec3 to = v3_sub(v3(urand(&h->seed, -0.5, 0.5), urand(&h->seed, -0.5, 0.5), 0), body_com(b));
    vec3 v = v3_scale(v3_norm(v3_add(to, v3(urand(&h->seed, -1, 1), urand(&h->seed, -1, 1),
                                             urand(&h->seed, -1, 1)))),
                      urand(&h->seed, 0.5, 3));
    vec3 wv = v3(urand(&h->seed, -2.3, 2.3), urand(&h->seed, -2.3, 2.3), urand(&h->seed, -2.3, 2.3));
    assert_int_equal(hold_set(w, h->held, (hold_motion){b->hold_pivot, v, wv}), 0);
    h->rows++;
}

static double hand_next(void *ctx, const world *w)
{
    (void)w;
    return ((test_hand *)ctx)->next;
}

static void hand_at(void *ctx, world *w)
{
    test_hand *h = ctx;
    hand_motion(h, w);
    h->next += HAND_ROW;
}

/* Random rooms with one body held and carried through the others by a hand that
 * changes its motion within the frames (sim_frame_hooked), heap on and off: the
 * same states to the bit, no contact of a pair the broad phase did not hold near,
 * its invariants after every frame (the held body inside its box: broad_check),
 * and the held body's pairs made as it comes near others. */
static void held_bodies_pairs_never_late(void **state)
{
    (void)state;
    const int trials = 12, frames = 8;
    long rows = 0, met = 0, collisions = 0;
    for (int k = 0; k < trials; k++) {
        world ws[2];
        test_hand hands[2];
        for (int m = 0; m < 2; m++) {
            random_room(&ws[m], k, 24 + k % 7, m == 0);
            /* the first dynamic object (after the six walls), held about a point
             * a little off its centre */
            hands[m] = (test_hand){.held = 6, .seed = 500 + (unsigned long long)k, .next = 0.02};
            body *b = ws[m].bodies[6];
            b->hold_pivot = v3_add(body_com(b), v3(0.05, -0.03, 0.02));
            hand_motion(&hands[m], &ws[m]);
        }
        char err[256];
        for (int f = 0; f < frames; f++) {
            for (int m = 0; m < 2; m++) {
                sim_hook hook = {hand_next, hand_at, &hands[m]};
                if (sim_frame_hooked(&ws[m], &hook, err, sizeof err) != 0) fail_msg("trial %d: %s", k, err);
                broad_checks_out(&ws[m], k, f);
                if (!ws[m].bodies[6]->held) fail_msg("trial %d: the body was let go", k);
            }
            same_states(&ws[0], &ws[1], k, f);
            /* its pairs with other moving objects (not the walls) */
            FOR_PAIRS_OF(&ws[0], 6, link, p) if (link->other >= 6 && p->near) met++;
        }
        assert_int_equal(ws[0].st.late_pairs, 0);
        assert_int_equal(ws[1].st.late_pairs, 0);
        rows += hands[0].rows;
        collisions += ws[0].st.collisions;
        world_free(&ws[0]);
        world_free(&ws[1]);
    }
    print_message("held: %d rooms x %d frames, %ld motions set by the hand, %ld near pairs of the "
                  "held body seen, %ld collisions\n",
                  trials, frames, rows, met, collisions);
    assert_true(rows > trials * frames * 2); /* within frames, not only between */
    assert_true(met > trials);
    assert_true(collisions > trials * 5);
}

/* A moving object's box covers it along its flight to the end of the step: its
 * sphere about the centre of mass, sampled densely, with gravity and spin, and in
 * every other room one body held and turning about a pivot off its centre, after
 * the box was checked or made again (broad_cover). */
static void boxes_cover_their_flights(void **state)
{
    (void)state;
    long samples = 0, made = 0;
    for (int k = 0; k < 24; k++) {
        world w;
        random_room(&w, k, 24, true);
        unsigned long long s = 77 + (unsigned long long)k;
        if (k % 2) { /* one held, turning about a pivot off its centre (FLIGHT_HELD) */
            body *b = w.bodies[6];
            vec3 pivot = v3_add(body_com(b), v3(urand(&s, -0.3, 0.3), urand(&s, -0.3, 0.3), 0.1));
            assert_int_equal(hold_set(&w, 6, (hold_motion){pivot, v3(urand(&s, -2, 2), 1, 0),
                                                          v3(urand(&s, -3, 3), 2, 1)}),
                             0);
        }
        assert_int_equal(sim_prepare(&w), 0);
        for (int round = 0; round < 5; round++) {
            double t = w.time, t_end = t + urand(&s, 0.001, 0.2);
            long before = w.broad.refits;
            for (int i = 0; i < w.n; i++) {
                if (!step_moves(&w, i)) continue;
                step_start(&w, i, t);
                assert_int_equal(broad_cover(&w, i, t, t_end, false), 0);
            }
            made += w.broad.refits - before;
            for (int i = 0; i < w.n; i++) {
                if (!step_moves(&w, i)) continue;
                body b = *w.bodies[i];
                for (int j = 0; j <= 50; j++) {
                    double at = t + (t_end - t) * j / 50.0;
                    step_fly(&w, i, at, &b);
                    vec3 c = body_com(&b);
                    double r = b.shape.r_out;
                    const aabb *x = &w.broad.box[i];
                    if (!(c.x - r >= x->lo.x && c.y - r >= x->lo.y && c.z - r >= x->lo.z &&
                          c.x + r <= x->hi.x && c.y + r <= x->hi.y && c.z + r <= x->hi.z))
                        fail_msg("room %d: %s leaves its box at %.9g s", k, b.name, at);
                    samples++;
                }
            }
            /* on to t_end, where the next round starts */
            for (int i = 0; i < w.n; i++) step_sync(&w, i, t_end);
            w.time = t_end;
            w.sched_dirty = true;
            assert_int_equal(sim_prepare(&w), 0);
        }
        world_free(&w);
    }
    print_message("%ld samples of flights inside their boxes, %ld boxes made again\n", samples, made);
    assert_true(made > 100);
}

/* Objects spread far apart have no pairs; brought together by a command, they do;
 * ended when they part again, unless they touch; and a world of a few objects has
 * every pair. */
static void pairs_come_and_go(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    for (int i = 0; i < 20; i++) {
        char name[8];
        snprintf(name, sizeof name, "b%d", i);
        body *b = add_ball(&w, name, 0.1);
        b->x = v3(3.0 * i, 0, 0);
    }
    assert_int_equal(sim_prepare(&w), 0);
    assert_int_equal(w.pairs.live, 0);
    assert_int_equal(world_pairs(&w), 190);
    w.bodies[1]->x = v3(0.23, 0, 0); /* 3 cm from b0 */
    w.bodies[1]->moved = true;
    w.sched_dirty = true;
    assert_int_equal(sim_prepare(&w), 0);
    assert_int_equal(w.pairs.live, 1);
    assert_true(pair_index(&w, 0, 1) >= 0);
    /* b1 flies away: at some frame its pair ends */
    w.bodies[1]->v = v3(0, 5, 0);
    w.sched_dirty = true;
    char err[256];
    for (int f = 0; f < 20; f++) assert_int_equal(sim_frame(&w, err, sizeof err), 0);
    assert_int_equal(w.pairs.live, 0);
    assert_int_equal(pair_index(&w, 0, 1), -1);
    world_free(&w);
    /* a few objects: every pair, however far */
    world_init(&w);
    for (int i = 0; i < 5; i++) {
        char name[8];
        snprintf(name, sizeof name, "b%d", i);
        add_ball(&w, name, 0.1)->x = v3(100.0 * i, 0, 0);
    }
    assert_int_equal(sim_prepare(&w), 0);
    assert_int_equal(w.pairs.live, 10);
    world_free(&w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(pairs_come_and_go),
        cmocka_unit_test(boxes_cover_their_flights),
        cmocka_unit_test(pairs_are_never_late),
        cmocka_unit_test(held_bodies_pairs_never_late),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
