/* test_pressure.c: objects under pressure (issue 35): piles that rest without
 * overlap, crowds that come to rest, and a closed box whose events run away
 * without anything passing through its floor.
 *
 * The oracle is independent of the simulation's own bookkeeping: after every
 * frame each pair's distance is measured afresh by a closest-feature query with
 * no cache (body_distance), over every pair whose balls meet, and the energy is
 * summed from the objects' states, potential measured from the floor.
 *
 * Issue 35's closed boxes and grooves, and the seeds whose events ran away
 * there, are frictionless: each sets default_friction and
 * default_rolling_friction to 0 after its restart (the grooves are also run
 * with the default friction: rough_grooves_rest).  Its piles have the
 * defaults' friction, as a new user's would, so that they can come to rest
 * (frictionless, an object sliding or spinning about the vertical on a level
 * floor never stops); frictionless piles check that no energy is made. */
#include "check.h"

#include "core/body.h"
#include "core/energy.h"
#include "core/world.h"
#include "shell_fixture.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#if defined(__SANITIZE_ADDRESS__)
#define UNDER_SANITIZERS 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define UNDER_SANITIZERS 1
#endif
#endif

/* The statement that makes the objects of a world frictionless (issue 36). */
#define FRICTIONLESS "default_friction = 0; default_rolling_friction = 0\n"

/* The deepest overlap (m, 0 when none) of any two objects of w, and which;
 * over the pairs with an object that moved (moved[i]; NULL: all). */
static double deepest_moved(const world *w, const bool *moved, int *ia, int *ib)
{
    double d = 0;
    for (int i = 0; i < w->n; i++)
        for (int j = i + 1; j < w->n; j++) {
            const body *a = w->bodies[i], *b = w->bodies[j];
            if (body_is_static(a) && body_is_static(b)) continue;
            if (moved && !moved[i] && !moved[j]) continue;
            double r = a->shape.r_out + b->shape.r_out;
            if (v3_len2(v3_sub(body_com(a), body_com(b))) > r * r) continue;
            closest_result c = body_distance(a, b, NULL);
            if (c.status == CLOSEST_PENETRATING && -c.distance > d) {
                d = -c.distance;
                *ia = i;
                *ib = j;
            }
        }
    return d;
}

static double deepest(const world *w, int *ia, int *ib) { return deepest_moved(w, NULL, ia, ib); }

/* Kinetic energy plus potential measured from height z0 (gravity along -z). */
static double energy_above(const world *w, double z0)
{
    energy_sum e = energy_of_world(w);
    double m = 0;
    for (int i = 0; i < w->n; i++)
        if (!body_is_static(w->bodies[i])) m += w->bodies[i]->mass;
    return e.linear + e.rotational + e.potential - m * -world_accel(w).z * z0;
}

static bool all_rest(const world *w)
{
    for (int i = 0; i < w->n; i++)
        if (!body_is_static(w->bodies[i]) && w->bodies[i]->state != STATE_RESTING) return false;
    return true;
}

/* A pile: 60 random objects of elasticity e (seed), dropped under gravity into a
 * room 4 m wide with a floor whose top is at z = -1.25 (tests/long's worlds);
 * with the defaults' friction (as a new user's pile would have) when rough,
 * else frictionless. */
static void pile(int seed, double e, bool rough)
{
    char text[4096];
    int n = snprintf(text, sizeof text,
                     "restart\n%sgravity\n"
                     "cube floor; mass = -1; size = (2, 2, 0.1); translate = (0, 0, -1.35); elasticity = %g\n"
                     "cube wall-n; mass = -1; size = (2.2, 0.1, 1.4); translate = (0, 2.1, 0)\n"
                     "cube wall-s; mass = -1; size = (2.2, 0.1, 1.4); translate = (0, -2.1, 0)\n"
                     "cube wall-e; mass = -1; size = (0.1, 2, 1.4); translate = (2.1, 0, 0)\n"
                     "cube wall-w; mass = -1; size = (0.1, 2, 1.4); translate = (-2.1, 0, 0)\n"
                     "seed = %d; random_box = (1.95, 1.95, 1.05)\nrandom 60\n",
                     rough ? "" : FRICTIONLESS, e, seed);
    assert_int_equal(run(text), CMD_OK);
    for (int i = 5; i < g_sh.w.n; i++) g_sh.w.bodies[i]->elasticity = e;
    (void)n;
}

/* The largest rise of energy from one frame to the next, relative, of the piles
 * run (printed). */
static double g_rise;

/* Runs a pile frame by frame for up to `frames`, until everything rests: no
 * overlap beyond 1e-6 m at any frame's end, and the energy (kinetic, and
 * potential from the floor's top) never rising from one frame to the next by
 * more than `rise` of it: collisions with e <= 1 and contacts without friction
 * do no work, and friction only takes.  Returns the frame at whose end
 * everything rests (-1: never). */
static int run_pile(int seed, double e, bool rough, int frames, double rise)
{
    pile(seed, e, rough);
    world *w = &g_sh.w;
    double before = energy_above(w, -1.25);
    /* (a pair of objects neither of which moved since the last frame's end was
     * measured there: only pairs with one that moved are measured again) */
    enum { ROOM = 72 };
    assert_true(w->n <= ROOM);
    vec3 x[ROOM];
    quat q[ROOM];
    bool moved[ROOM];
    for (int i = 0; i < w->n; i++) x[i] = w->bodies[i]->x, q[i] = w->bodies[i]->q;
    for (int f = 1; f <= frames; f++) {
        assert_int_equal(run("run 1"), CMD_OK);
        for (int i = 0; i < w->n; i++) {
            const body *o = w->bodies[i];
            moved[i] = f == 1 || memcmp(&o->x, &x[i], sizeof x[i]) != 0 || memcmp(&o->q, &q[i], sizeof q[i]) != 0;
            x[i] = o->x, q[i] = o->q;
        }
        int a = -1, b = -1;
        double d = deepest_moved(w, moved, &a, &b);
        if (d > 1e-6)
            fail_msg("seed %d, e %g, frame %d: '%s' and '%s' overlap by %.3g m", seed, e, f,
                     a >= 0 ? w->bodies[a]->name : "", b >= 0 ? w->bodies[b]->name : "", d);
        double now = energy_above(w, -1.25);
        if (now > before) g_rise = d_max(g_rise, (now - before) / before);
        if (now > before + rise * before)
            fail_msg("seed %d, e %g%s, frame %d: energy rose from %.17g to %.17g J", seed, e,
                     rough ? "" : " (frictionless)", f, before, now);
        before = now;
        if (all_rest(w)) return f;
    }
    return -1;
}

/* Piles of 60 with the default friction, e = 0.5, seeds 1 to 20: every object
 * at rest within 20 s (200 frames of 0.1 s), with no overlap and no energy
 * made (1e-9 of it a frame) on the way.  (The sanitizer build: seeds 1 and 2
 * over 2 s, rest not asked.) */
static void piles_rest_without_overlap(void **state)
{
    (void)state;
#ifdef UNDER_SANITIZERS
    const int last = 2, frames = 20;
#else
    const int last = 20, frames = 200;
#endif
    g_rise = 0;
    int rested = 0, latest = 0;
    for (int seed = 1; seed <= last; seed++) {
        int f = run_pile(seed, 0.5, true, frames, 1e-9);
#ifndef UNDER_SANITIZERS
        if (f < 0) fail_msg("seed %d: not all at rest after %d frames", seed, frames);
#endif
        rested += f > 0;
        latest = f > latest ? f : latest;
    }
    print_message("piles of e = 0.5: %d of %d at rest within %d frames (the last at frame %d); energy rose "
                  "by at most %.3g of itself in a frame\n",
                  rested, last, frames, latest, g_rise);
}

/* Piles of 60, e = 1, seeds 1 to 20, with the default friction over the first
 * 3 s and frictionless over 5 s (the sanitizer build: seeds 1 and 2 over 2 s):
 * no overlap and no energy made (1e-9 of it a frame).  Frictionless with e =
 * 0.5 too, over 10 s, seeds 1 to 10 (1e-7: see issue 35's piles note: a
 * cluster's steps keep its energy only to the order of their length squared,
 * and a frame may end where they hold a little more of it). */
static void elastic_piles_keep_apart(void **state)
{
    (void)state;
#ifdef UNDER_SANITIZERS
    const int last = 2, rough_frames = 20, frames = 20, lossy_last = 1, lossy_frames = 20;
#else
    const int last = 20, rough_frames = 30, frames = 50, lossy_last = 10, lossy_frames = 100;
#endif
    g_rise = 0;
    for (int seed = 1; seed <= last; seed++) run_pile(seed, 1, true, rough_frames, 1e-9);
    print_message("piles of e = 1: energy rose by at most %.3g of itself in a frame\n", g_rise);
    g_rise = 0;
    for (int seed = 1; seed <= last; seed++) run_pile(seed, 1, false, frames, 1e-9);
    print_message("frictionless, e = 1: energy rose by at most %.3g of itself in a frame\n", g_rise);
    g_rise = 0;
    for (int seed = 1; seed <= lossy_last; seed++) run_pile(seed, 0.5, false, lossy_frames, 1e-7);
    print_message("frictionless, e = 0.5: energy rose by at most %.3g of itself in a frame\n", g_rise);
}

/* The closed box of 50 (issue 35): seed, random_box = (1, 1, 1), random 50, six
 * static walls whose inner faces are the box's (the floor's top at z = -1), then
 * gravity; frictionless, or (rough) with the defaults' friction, a user's.
 * False when the seed's 50 do not fit in the box (random refuses). */
static bool closed_box(int seed, bool rough)
{
    char text[1024];
    snprintf(text, sizeof text, "restart\n%sseed = %d; random_box = (1, 1, 1)\nrandom 50\n",
             rough ? "" : FRICTIONLESS, seed);
    if (run(text) != CMD_OK) return false;
    assert_int_equal(run("cube floor; mass = -1; size = (1.2, 1.2, 0.1); translate = (0, 0, -1.1)\n"
                         "cube ceiling; mass = -1; size = (1.2, 1.2, 0.1); translate = (0, 0, 1.1)\n"
                         "cube wall-e; mass = -1; size = (0.1, 1.2, 1.2); translate = (1.1, 0, 0)\n"
                         "cube wall-w; mass = -1; size = (0.1, 1.2, 1.2); translate = (-1.1, 0, 0)\n"
                         "cube wall-n; mass = -1; size = (1.2, 0.1, 1.2); translate = (0, 1.1, 0)\n"
                         "cube wall-s; mass = -1; size = (1.2, 0.1, 1.2); translate = (0, -1.1, 0)\n"
                         "gravity\n"),
                     CMD_OK);
    return true;
}

/* Times "at time = ... ran away" was warned in g_errbuf. */
static int guard_warnings(void)
{
    int n = 0;
    for (const char *p = g_errbuf; (p = strstr(p, "ran away")) != NULL; p++) n++;
    return n;
}

/* Runs the closed box of `seed` frame by frame: after every frame every moving
 * object's centre is above the floor's top and it is in the floor by no more
 * than 1e-6 m (an object that fell through is apart from the floor, below it);
 * returns the guard's warnings over the run. */
static int run_box(int seed, int frames)
{
    world *w = &g_sh.w;
    int floor = world_find(w, "floor"), warned = 0;
    for (int f = 1; f <= frames; f++) {
        assert_int_equal(run("run 1"), CMD_OK);
        warned += guard_warnings();
        const body *fl = w->bodies[floor];
        for (int i = 0; i < w->n; i++) {
            const body *b = w->bodies[i];
            if (body_is_static(b)) continue;
            closest_result c = body_distance(b, fl, NULL);
            double depth = c.status == CLOSEST_PENETRATING ? -c.distance : 0;
            if (body_com(b).z <= -1 || depth > 1e-6)
                fail_msg("box seed %d, frame %d: '%s' at z = %.9g, %.3g m into the floor", seed, f,
                         b->name, body_com(b).z, depth);
        }
    }
    return warned;
}

/* The closed box of 50 under gravity, seeds 1 to 50 over 3 s (the sanitizer
 * build: seeds 1 to 3 over 1 s; VROC_BOX_SEEDS=N runs 1 to N over 6 s, the
 * issue's sweep of 200): nothing falls through the floor, and the event guard
 * warns at most once.  Among seeds 1 to 200, 78, 97 and 178 ran away (a
 * hundred thousand events in a step) before their crowds were answered with no
 * bounce (guard.h); since a cluster's steps stop their closed points none
 * does, and 11 and 12 have crowds. */
static void closed_boxes_keep_their_floor(void **state)
{
    (void)state;
#ifdef UNDER_SANITIZERS
    int last = 3, frames = 10;
#else
    int last = 50, frames = 30;
#endif
    const char *env = getenv("VROC_BOX_SEEDS");
    if (env) {
        last = atoi(env);
        frames = 60;
    }
    int ran = 0;
    long crowds = 0, guards = 0;
    for (int seed = 1; seed <= last; seed++) {
        if (!closed_box(seed, false)) continue;
        ran++;
        int warned = run_box(seed, frames);
        if (warned > 1) fail_msg("box seed %d: %d guard warnings", seed, warned);
        crowds += g_sh.w.st.crowds;
        guards += g_sh.w.st.guards;
    }
    print_message("closed boxes: %d seeds of %d run, %ld crowds, %ld guards\n", ran, last, crowds, guards);
    assert_true(ran >= last * 9 / 10);
}

/* The closed box with the defaults' friction (a user's box), seeds 1 to 5 over
 * 1.5 s, through the fall into the pile (the sanitizer build: seeds 1 and 2
 * over 0.8 s): nothing falls through the floor, the guard warns at most once.
 * Seed 2's box took 16 s CPU for frames 16-18 while the cone solve's polishes
 * did 15 times its sweeps' work (friction.c: POLISH_PROGRESS, POLISH_WORK);
 * 30 frames of seeds 1 to 50 take from 1 s to over 25 s each (issue 35's
 * note), too long for here. */
static void rough_closed_boxes_keep_their_floor(void **state)
{
    (void)state;
#ifdef UNDER_SANITIZERS
    const int last = 2, frames = 8;
#else
    const int last = 5, frames = 15;
#endif
    int ran = 0;
    for (int seed = 1; seed <= last; seed++) {
        if (!closed_box(seed, true)) continue;
        ran++;
        int warned = run_box(seed, frames);
        if (warned > 1) fail_msg("rough box seed %d: %d guard warnings", seed, warned);
        assert_int_equal(g_sh.w.st.unsolved, 0);
    }
    assert_true(ran >= last - 1);
}

/* The guard's last resort, made cheap: seed 11's box, one of whose objects takes
 * part in a thousand events in a step of frame 13, with no crowd rule and a
 * step's events limited to 2000: the objects stop where they are, the warning
 * names them once, stats counts it, and nothing falls through the floor.  (The
 * seed is whichever box crowds early: seed 55's did until the random
 * superquadrics' hulls came from their tessellation, numbered otherwise, and
 * seed 78's, whose events ran away at t = 1.2 s, runs away no more since a
 * cluster's steps stop their closed points: cluster.h.) */
static void last_resort_keeps_the_floor(void **state)
{
    (void)state;
    assert_true(closed_box(11, false));
    g_sh.w.guard.crowd_events = 1L << 40;
    g_sh.w.guard.max_events = 2000;
    int warned = run_box(11, 14);
    assert_true(g_sh.w.st.guards > 0);
    assert_int_equal(warned, 1);
    assert_int_equal(g_sh.w.st.overflows, 0);
    assert_int_equal(run("stats"), CMD_OK);
    assert_non_null(strstr(g_out, "guards = "));
    assert_non_null(strstr(g_out, "crowds = 0"));
}

/* A V-groove along y of two static faces rising from the line x = z = 0 at a and
 * b degrees from the horizontal (towards +x and -x), closed at y = +-1.3 by
 * static ends, with 100 balls of radius 0.05 and elasticity 0.5 dropped into it
 * in four layers (issue 35's crowd); frictionless, or with the default friction
 * when `rough`. */
static void groove(double a, double b, bool rough)
{
    char *text = malloc(65536);
    assert_non_null(text);
    const double pi = 3.14159265358979323846, W = 1, t = 0.05, L = 1.3;
    double ra = a * pi / 180, rb = b * pi / 180;
    int n = snprintf(text, 65536,
                     "restart\n%s"
                     "cube face-a; mass = -1; size = (%.17g, %.17g, %.17g); rotate = (0, 1, 0) %.17g; "
                     "translate = (%.17g, 0, %.17g)\n"
                     "cube face-b; mass = -1; size = (%.17g, %.17g, %.17g); rotate = (0, 1, 0) %.17g; "
                     "translate = (%.17g, 0, %.17g)\n"
                     "cube end-n; mass = -1; size = (1.2, 0.05, 1.2); translate = (0, %.17g, 0.6)\n"
                     "cube end-s; mass = -1; size = (1.2, 0.05, 1.2); translate = (0, %.17g, 0.6)\n",
                     rough ? "" : FRICTIONLESS, W, L + 0.1, t, -ra, W * cos(ra) + t * sin(ra),
                     W * sin(ra) - t * cos(ra), W, L + 0.1, t, rb, -W * cos(rb) - t * sin(rb), W * sin(rb) - t * cos(rb), L + 0.05, -L - 0.05);
    for (int k = 0, i = 0; k < 4; k++)
        for (int j = 0; j < 25; j++, i++)
            n += snprintf(text + n, 65536 - (size_t)n,
                          "sphere b%d; radius = 0.05; elasticity = 0.5; translate = (%g, %.17g, %.17g)\n", i,
                          k % 2 ? 0.03 : -0.03, -1.25 + j * 0.104, 0.35 + k * 0.12);
    snprintf(text + n, 65536 - (size_t)n, "gravity\n");
    assert_int_equal(run(text), CMD_OK);
    free(text);
}

/* Runs the world until everything rests, frame by frame, for at most `frames`
 * frames of 0.1 s, then 2 s more: everything rests within them, no moving
 * object ends below z = 0 (the groove's floor line) or in anything by more than
 * 1e-6 m, and the pair checks per simulated second after rest are under 1% of
 * those before. */
static void comes_to_rest(const char *what, int frames)
{
    world *w = &g_sh.w;
    int rested = -1;
    for (int f = 1; f <= frames && rested < 0; f++) {
        assert_int_equal(run("run 1"), CMD_OK);
        if (all_rest(w)) rested = f;
    }
    if (rested < 0) fail_msg("%s: not at rest after %d frames", what, frames);
    long before = w->st.pair_checks;
    assert_int_equal(run("run 20"), CMD_OK);
    assert_true(all_rest(w));
    double rate_before = before / (rested * 0.1), rate_after = (w->st.pair_checks - before) / 2.0;
    print_message("%s: at rest after %d frames; %.0f pair checks/s before, %.0f after\n", what, rested,
                  rate_before, rate_after);
    assert_true(rate_after < 0.01 * rate_before);
    int a = -1, b = -1;
    double d = deepest(w, &a, &b);
    if (d > 1e-6) fail_msg("%s: '%s' and '%s' overlap by %.3g m", what, w->bodies[a]->name, w->bodies[b]->name, d);
    for (int i = 0; i < w->n; i++)
        if (!body_is_static(w->bodies[i]) && body_com(w->bodies[i]).z < 0)
            fail_msg("%s: '%s' below the groove", what, w->bodies[i]->name);
}

/* 100 balls with e = 0.5 in V-grooves closed at both ends come to rest within
 * 10 s of simulated time, and then cost under 1% of the pair checks: faces at
 * 30 and 60 degrees, at 45 and 45, and at 20 and 70. */
static void grooves_rest(void **state)
{
    (void)state;
    const double faces[][2] = {{30, 60}, {45, 45}, {20, 70}};
    for (size_t k = 0; k < sizeof faces / sizeof faces[0]; k++) {
        char what[64];
        snprintf(what, sizeof what, "groove %g/%g", faces[k][0], faces[k][1]);
        groove(faces[k][0], faces[k][1], false);
        comes_to_rest(what, 100);
    }
}

/* The same grooves with the default friction (a user's: their clusters solved
 * with the friction cones, past 64 points in blocks, friction.h): they
 * rest within 10 s too (after 1 s), and then cost under 1% of the pair checks.
 * Under the sanitizers the 30/60 groove alone. */
static void rough_grooves_rest(void **state)
{
    (void)state;
    const double faces[][2] = {{30, 60}, {45, 45}, {20, 70}};
#ifdef UNDER_SANITIZERS
    size_t count = 1;
#else
    size_t count = sizeof faces / sizeof faces[0];
#endif
    for (size_t k = 0; k < count; k++) {
        char what[64];
        snprintf(what, sizeof what, "groove %g/%g with friction", faces[k][0], faces[k][1]);
        groove(faces[k][0], faces[k][1], true);
        comes_to_rest(what, 100);
    }
}

/* ---- the slot ---- */

/* The radius of the slot's balls (m): the slot is 1e-7 m wider than twice it. */
static double g_slot_r = 0.05;

/* A slot along y on a static floor whose top is at z = 0, between static sides
 * 1e-7 m further apart than the diameter of a ball of radius r, closed at
 * y = +-1.3 by static ends (bench/crowd.awk's slot for r = 0.05), with gravity;
 * then `balls`, statements making balls of radius r in it (issue 35's crowd). */
static void slot_of(double r, const char *balls, bool rough)
{
    g_slot_r = r;
    double half = r + 5e-8;
    char *text = malloc(65536);
    assert_non_null(text);
    snprintf(text, 65536,
             "restart\n%sgravity\n"
             "cube floor; mass = -1; size = (0.5, 1.5, 0.05); translate = (0, 0, -0.05)\n"
             "cube side-e; mass = -1; size = (0.05, 1.5, 1); translate = (%.17g, 0, 1)\n"
             "cube side-w; mass = -1; size = (0.05, 1.5, 1); translate = (%.17g, 0, 1)\n"
             "cube end-n; mass = -1; size = (0.05, 0.05, 1); translate = (0, 1.35, 1)\n"
             "cube end-s; mass = -1; size = (0.05, 0.05, 1); translate = (0, -1.35, 1)\n%s",
             rough ? "" : FRICTIONLESS, half + 0.05, -half - 0.05, balls);
    assert_int_equal(run(text), CMD_OK);
    free(text);
}

static void slot(double r, const char *balls)
{
    slot_of(r, balls, false);
}

/* The rise of the energy from one frame to the next that run_slot allows,
 * relative to it. */
static double g_slot_rise = 1e-9;

/* Runs the slot's world frame by frame for at most `frames`: at every frame's
 * end no pair overlaps by more than 1e-6 m, no ball is out of the slot (its
 * centre within the sides' room, above the floor's top by its radius less
 * 1e-6 m), and the energy (kinetic, and potential from the floor's top) never
 * rises from one frame to the next by more than g_slot_rise of itself: contacts
 * without friction do no work, and collisions with e < 1 only lose energy (to
 * 1e-9 but for the crowd of 100).  Returns the frame at whose end everything
 * rests (-1: never). */
/* When not NULL, run_slot saves the world at every frame's end f into
 * g_slot_save/f.vroc. */
static const char *g_slot_save = NULL;

static int run_slot(const char *what, int frames)
{
    world *w = &g_sh.w;
    double before = energy_above(w, 0), most = 0;
    for (int f = 1; f <= frames; f++) {
        assert_int_equal(run("run 1"), CMD_OK);
        int a = -1, b = -1;
        double d = deepest(w, &a, &b);
        if (d > 1e-6)
            fail_msg("%s, frame %d: '%s' and '%s' overlap by %.3g m", what, f, w->bodies[a]->name,
                     w->bodies[b]->name, d);
        for (int i = 0; i < w->n; i++) {
            const body *o = w->bodies[i];
            vec3 c = body_com(o);
            if (!body_is_static(o) && (fabs(c.x) > 5e-8 + 1e-6 || c.z < g_slot_r - 1e-6))
                fail_msg("%s, frame %d: '%s' out of the slot at (%.17g, %.17g, %.17g)", what, f, o->name,
                         c.x, c.y, c.z);
        }
        double now = energy_above(w, 0);
        most = fmax(most, (now - before) / before);
        if (now > before + g_slot_rise * before)
            fail_msg("%s, frame %d: energy rose from %.17g to %.17g J", what, f, before, now);
        before = now;
        if (g_slot_save) {
            char text[512];
            snprintf(text, sizeof text, "save \"%s/%d.vroc\"\n", g_slot_save, f);
            assert_int_equal(run(text), CMD_OK);
        }
        if (all_rest(w)) {
            print_message("%s: the energy rose by at most %.3g of itself in a frame\n", what, most);
            return f;
        }
    }
    return -1;
}

/* One ball of radius r and elasticity e dropped into the slot from height h
 * (its bottom above the floor's top), thrown across it at vx: it rattles
 * between the sides 1e-7 m apart, whose normals are horizontal, so its fall and
 * bounces are a ball's on a floor alone: it lands after t0 = sqrt(2 h / g), and
 * its bounces, each e times the one before, end at t0 (1 + 2 e / (1 - e)) (it
 * rests then, or sooner, when a bounce's speed falls below the rest speed).  It
 * rests by then and a frame more, answering every contact: no event guard, no
 * problem unsolved, no pair moved apart at a frame's end. */
static void ball_in_slot_rests(void **state)
{
    (void)state;
    const double r[] = {0.05, 0.02, 0.1, 0.05}, e[] = {0.5, 0.3, 0.8, 0.5}, vx[] = {0.5, -1.7, 3.1, -0.2},
                 h[] = {0.35, 0.12, 0.6, 0.05};
    for (size_t k = 0; k < sizeof vx / sizeof vx[0]; k++) {
        char ball[256], what[96];
        snprintf(ball, sizeof ball,
                 "sphere b; radius = %g; elasticity = %g; translate = (0, %g, %.17g); velocity = (%g, 0, 0)\n",
                 r[k], e[k], 0.4 * (double)k - 0.5, r[k] + h[k], vx[k]);
        snprintf(what, sizeof what, "a ball of %g m, e = %g, from %g m at %g m/s across", r[k], e[k], h[k], vx[k]);
        slot(r[k], ball);
        world *w = &g_sh.w;
        double g = -world_accel(w).z, t_end = sqrt(2 * h[k] / g) * (1 + 2 * e[k] / (1 - e[k]));
        int last = (int)ceil(t_end / 0.1) + 1, rested = run_slot(what, last);
        if (rested < 0) fail_msg("%s: not at rest after %d frames (its bounces end at %.3f s)", what, last, t_end);
        assert_int_equal(w->st.guards, 0);
        assert_int_equal(w->st.unsolved, 0);
        assert_int_equal(w->st.separations, 0);
    }
}

static int slot_crowd_rests(const char *what, int frames);

/* The slot's world with a row of 26 balls of e = 0.5 filling it end to end
 * (centres 0.1 m apart), their bottoms 0.1 (1 + i % heights) m above the floor,
 * thrown across it at -0.5, 0 and 0.5 m/s by turns; rough: with the defaults'
 * friction. */
static void row_in_slot(int heights, bool rough)
{
    char *balls = malloc(8192);
    assert_non_null(balls);
    int n = 0;
    for (int i = 0; i < 26; i++)
        n += snprintf(balls + n, 8192 - (size_t)n,
                      "sphere b%d; radius = 0.05; elasticity = 0.5; translate = (0, %.17g, %.17g); "
                      "velocity = (%g, 0, 0)\n",
                      i, -1.25 + i * 0.1, 0.05 + 0.1 * (1 + i % heights) + 0.05, (i % 3 - 1) * 0.5);
    slot_of(0.05, balls, rough);
    free(balls);
}

/* Crowds in the slot, every ball of e = 0.5 and at rest within 10 s: a row of
 * 26 balls filling it end to end (centres 0.1 m apart, touching their
 * neighbours and the ends), dropped from 0.15 to 0.45 m by turns and thrown
 * across it; as they land they press together into one cluster of some 100
 * contact points (both sides', the floor's, their neighbours'), more than the
 * 64 a cluster once held.  Every point is answered: besides run_slot's
 * checks, nothing was moved apart at a frame's end (with points left out the
 * balls sank into each other and hundreds were), no event guard, no problem
 * unsolved, and once at rest the pair checks per simulated second are under
 * 1% of those before (slot_crowd_rests; the hundred of bench/crowd.awk:
 * hundred_in_slot_rest). */
static void crowd_in_slot_rests(void **state)
{
    (void)state;
    row_in_slot(4, false);
    slot_crowd_rests("26 balls in a row", 100);
}

/* The row of 26 with the defaults' friction (mu 0.5, rolling resistance c =
 * 0.01), dropped from up to 0.4 m (heights by fours, slot.sh's) and from up
 * to 0.3 m (by threes).  Rough balls pressed end to end lock: a ball pushed
 * along the row would roll, and its neighbours' contacts, slipping against
 * that, resist it in proportion to the push, so that a few balls' rolling
 * resistance holds a row against any push.  As they land, one ball is
 * squeezed up between two others (26 fill the slot exactly) and its wedge
 * pushes on the rest, which friction holds.  They come to rest within what
 * the physics gives: a drop from h lands after t0 = sqrt(2 h / g) and its
 * bounces of e = 0.5 end by 3 t0; no ball moves faster than the drop and the
 * throw give it, v = sqrt(2 g h + 0.5^2), and one rolling at v stops within
 * v (1 + k) / (c g) (k = 2/5, a ball's) by rolling resistance alone, while
 * collisions only lose energy: within 10 s, the bound, where that is
 * sooner.  (The balance found them unheld: the wedged ball slipped on both its
 * points, and so resisted no turning, and the cone solve from nothing each
 * round of rolling resistance's couples stalled at 5e-6 m/s^2; rest.c.)
 * Under the sanitizers the first alone. */
static void rough_row_in_slot_rests(void **state)
{
    (void)state;
    const int heights[] = {4, 3};
    int cases = 2;
#ifdef UNDER_SANITIZERS
    cases = 1;
#endif
    for (int k = 0; k < cases; k++) {
        row_in_slot(heights[k], true);
        world *w = &g_sh.w;
        const body *b = w->bodies[w->n - 1];
        double g = -world_accel(w).z, h = 0.1 * heights[k], c = b->rolling_friction;
        double v = sqrt(2 * g * h + 0.25), t = 3 * sqrt(2 * h / g) + v * (1 + 0.4) / (c * g);
        int frames = (int)fmin(100, ceil(t / 0.1));
        char what[96];
        snprintf(what, sizeof what, "26 rough balls in a row, from up to %g m", h);
        print_message("%s: at rest within %.1f s by the physics, %d frames here\n", what, t, frames);
        slot_crowd_rests(what, frames);
    }
}

/* The crowd of the slot's world (run_slot's checks at every frame) rests within
 * `frames`, stays at rest 2 s more at under 1% of the pair checks per simulated
 * second before, and every point was answered: nothing moved apart at a frame's
 * end, no event guard, no problem unsolved. */
static int slot_crowd_rests(const char *what, int frames)
{
    world *w = &g_sh.w;
    int rested = run_slot(what, frames);
    if (rested < 0) fail_msg("%s: not at rest after %d frames", what, frames);
    long before = w->st.pair_checks;
    assert_int_equal(run("run 20"), CMD_OK);
    assert_true(all_rest(w));
    double rate_before = before / (rested * 0.1), rate_after = (w->st.pair_checks - before) / 2.0;
    print_message("slot, %s: at rest after %d frames; %.0f pair checks/s before, %.0f after\n", what, rested,
                  rate_before, rate_after);
    assert_true(rate_after < 0.01 * rate_before);
    assert_int_equal(w->st.guards, 0);
    assert_int_equal(w->st.unsolved, 0);
    assert_int_equal(w->st.separations, 0);
    return rested;
}

/* Issue 35's crowd: 100 balls of e = 0.5 in the slot (bench/crowd.awk's), four
 * layers of 25 dropped from 0.1 to 0.55 m, each layer's balls 0.103 m apart
 * and thrown across at -0.5, 0 and 0.5 m/s by turns; they land on each other
 * and press into one cluster of some 400 contact points (both sides', the
 * floor's, their neighbours' in and across the layers), solved at every step
 * of the cluster (lcp.c's crowds; with friction, friction.h's crowds), rough
 * with the defaults' friction, else frictionless. */
static void hundred_in_slot(bool rough)
{
    const int layers = 4;
    char *balls = malloc(16384), what[64];
    assert_non_null(balls);
    int n = 0;
    for (int k = 0, i = 0; k < layers; k++)
        for (int j = 0; j < 25; j++, i++)
            n += snprintf(balls + n, 16384 - (size_t)n,
                          "sphere b%d; radius = 0.05; elasticity = 0.5; translate = (0, %.17g, %.17g); "
                          "velocity = (%g, 0, 0)\n",
                          i, -1.25 + j * 0.103 + (k % 2) * 0.01, 0.1 + k * 0.15, (j % 3 - 1) * 0.5);
    slot_of(0.05, balls, rough);
    free(balls);
    snprintf(what, sizeof what, "%d balls in %d layers%s", 25 * layers, layers, rough ? ", rough" : "");
    /* (a pressed crowd's cluster steps may raise its energy by some 1e-9 of
     * it in a frame while it creeps, and 1.2e-6 once as it settles: the piles'
     * residue, issue 35's item 3, not this test's; a rise of 1e-5 fails.  With
     * friction, 1.9e-5 in the frame it settles, some balls lifted by a third
     * of a millimetre: not understood.  It rose as much without
     * over-relaxation, with up to 1000 sweeps a step, and with frictionless
     * side walls; rough piles of up to 64 points, solved densely and
     * polished, have not been seen to gain energy, so the crowd's inexact
     * sweeps are the suspects.  A rise of 1e-4 fails) */
    g_slot_rise = rough ? 1e-4 : 1e-5;
    char dir[] = "/tmp/vroc-slot-XXXXXX";
    if (rough) assert_non_null(g_slot_save = mkdtemp(dir));
    int rested = slot_crowd_rests(what, 100);
    g_slot_rise = 1e-9;
    if (!rough) return;
    g_slot_save = NULL;
    /* saved at the last frame's end before the rest (the crowd one cluster,
     * rough past 64 points, pressed and moving) and read back, the run goes
     * on to the bit: the same hash at the end */
    char text[512], *whole;
    assert_int_equal(run("hash\n"), CMD_OK);
    assert_non_null(whole = strdup(g_out));
    int k = rested - 1;
    assert_true(k >= 1);
    snprintf(text, sizeof text, "restart; read \"%s/%d.vroc\"; run %d; hash\n", dir, k, rested + 20 - k);
    assert_int_equal(run(text), CMD_OK);
    print_message("%s: saved at frame %d and read back, the same hash %d frames on\n", what, k, rested + 20 - k);
    assert_string_equal(g_out, whole);
    free(whole);
    for (int f = 1; f <= rested; f++) {
        snprintf(text, sizeof text, "%s/%d.vroc", dir, f);
        remove(text);
    }
    rmdir(dir);
}

/* The hundred frictionless (normal build only: some 5 minutes under the
 * sanitizers; their crowd past a dense solve is the row of 26,
 * crowd_in_slot_rests.  Fewer balls do not make a smaller test of this: two
 * layers of 25 leave room along the slot, where frictionless balls slide on
 * for more than 10 s). */
static void hundred_in_slot_rest(void **state)
{
    (void)state;
#ifdef UNDER_SANITIZERS
    skip();
#endif
    hundred_in_slot(false);
}

/* The hundred with the defaults' friction: past 64 points their clusters' cone
 * problems are solved in blocks (friction.h), in the steps, the instants and the
 * balance, so that the spins the collisions gave are braked (along the normals
 * alone, five balls spun in place for good) and a pile that friction holds is
 * found held.  Normal build only, as the frictionless hundred. */
static void rough_hundred_in_slot_rest(void **state)
{
    (void)state;
#ifdef UNDER_SANITIZERS
    skip();
#endif
    hundred_in_slot(true);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(ball_in_slot_rests),
        cmocka_unit_test(crowd_in_slot_rests),
        cmocka_unit_test(rough_row_in_slot_rests),
        cmocka_unit_test(hundred_in_slot_rest),
        cmocka_unit_test(rough_hundred_in_slot_rest),
        cmocka_unit_test(grooves_rest),
        cmocka_unit_test(rough_grooves_rest),
        cmocka_unit_test(closed_boxes_keep_their_floor),
        cmocka_unit_test(rough_closed_boxes_keep_their_floor),
        cmocka_unit_test(last_resort_keeps_the_floor),
        cmocka_unit_test(piles_rest_without_overlap),
        cmocka_unit_test(elastic_piles_keep_apart),
    };
    shell_fixture_open();
    int r = cmocka_run_group_tests(tests, NULL, NULL);
    shell_fixture_close();
    return r;
}
