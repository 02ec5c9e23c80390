/* test_instant.c: contacts that begin at one instant (issue 34), each answer
 * derived here.
 *
 * Parallel contacts are answered together, symmetric when the set-up is, with
 * every order of object creation: a plank dropped flat on two supports, a ball
 * on two static balls, a ball into grooves of 90 and 120 degrees, for
 * elasticities 0, 0.5 and 1.  Chains pass a blow along in waves: Newton's cradles
 * of 3, 5 and 7 balls with one and two struck, touching or not, a ball thrown
 * onto a touching stack on the floor.  A cube released leaning on an edge lands
 * with its elasticity and rocks back up the same edge to the textbook's angle,
 * for ever with e = 1.  A pinched ball and a lossy stack end their instants with
 * a last inelastic solve, which stats counts. */
#include "check.h"

#include <stdlib.h>
#include <string.h>

#include "core/body.h"
#include "core/edit.h"
#include "core/energy.h"
#include "core/sim.h"
#include "core/world.h"
#include "worlds.h"

static const double G = 9.8, PI = 3.14159265358979323846;

/* A world under gravity (g along -z, or none), with speed limits far above what
 * the tests reach. */
static void instant_world(world *w, double g)
{
    world_init(w);
    w->set.force = (dir_amount){v3(0, 0, -1), g};
    w->set.max_linear = 100;
    w->set.max_angular = 1000;
}

static void frames(world *w, int n)
{
    char err[256];
    for (int i = 0; i < n; i++) assert_int_equal(sim_frame(w, err, sizeof err), 0);
}

/* A static floor whose top is the plane z = 0, 4 m square. */
static void add_floor(world *w)
{
    add_static_box(w, "floor", v3(2, 2, 0.5))->x = v3(0, 0, -0.5);
}

/* Ball number i of a row, radius r, named b0, b1, ... */
static body *numbered_ball(world *w, int i, double r)
{
    char name[16];
    snprintf(name, sizeof name, "b%d", i);
    return add_ball(w, name, r);
}

/* The frame's event between objects named a and b (either order), or NULL. */
static const sim_event *event_of(const world *w, const char *a, const char *b)
{
    int i = world_find(w, a), j = world_find(w, b);
    for (long k = 0; k < w->nevents; k++) {
        const sim_event *e = &w->events[k];
        if ((e->a == i && e->b == j) || (e->a == j && e->b == i)) return &w->events[k];
    }
    return NULL;
}

/* Kinetic energy and momentum of the world's objects. */
static double energy(const world *w)
{
    double e = 0;
    for (int i = 0; i < w->n; i++) e += body_energy(w->bodies[i]);
    return e;
}

static vec3 momentum(const world *w)
{
    vec3 p = v3(0, 0, 0);
    for (int i = 0; i < w->n; i++)
        if (!body_is_static(w->bodies[i])) p = v3_mad(p, w->bodies[i]->v, w->bodies[i]->mass);
    return p;
}

/* ---------------------------------------------------- parallel contacts */

/* The three objects of a symmetric drop, made in the order perm gives (a
 * permutation of 0, 1, 2): object 0 the one that falls (named "drop"), 1 and 2
 * its mirrored supports ("left" at -x, "right" at +x). */
typedef void (*maker)(world *w, int which, double e);

/* What a symmetric drop answers, for comparing orders. */
typedef struct {
    double jl, jr;   /* the impulses at the left and right contacts */
    double vz, vx;   /* the falling object's velocity after */
    double spin;     /* and |w| */
    double xl, xr;   /* where the two impulses act, along x */
} drop_answer;

/* Makes the three objects of `make` in the order perm, drops object 0 from rest
 * (its lowest point h above the supports' contacts) under gravity, and runs one
 * frame that ends 1e-6 s after it lands.  Checks the textbook answer: two
 * contacts, each with the impulse m (1 + e) u / (2 cos alpha) of a symmetric pair
 * whose normals are alpha off the vertical, u the closing speed at the contacts
 * (the speed of the fall along their normals, the event's speed), so that the
 * fall's speed v = u / cos alpha turns into e v upwards, with no spin and no
 * sideways speed; then it flies freely. */
static drop_answer symmetric_drop(maker make, const int perm[3], double e, double h, double alpha)
{
    world w;
    instant_world(&w, G);
    for (int k = 0; k < 3; k++) make(&w, perm[k], e);
    body *d = w.bodies[world_find(&w, "drop")];
    double t_land = sqrt(2 * h / G);
    w.set.time_step = t_land + 1e-6;
    frames(&w, 1);
    assert_int_equal(w.nevents, 2);
    const sim_event *l = event_of(&w, "drop", "left"), *r = event_of(&w, "drop", "right");
    assert_non_null(l);
    assert_non_null(r);
    /* (the contacts' normals as they met: the search stops a hair short) */
    double c = fabs(l->n.z), v = l->speed / c, m = d->mass;
    assert_near(c, cos(alpha), 1e-8);
    assert_rel(v, G * l->t, 1e-7); /* (the fall's speed where the search found it) */
    assert_rel(r->speed, l->speed, 1e-12);
    double j = m * (1 + e) * l->speed / (2 * c * c);
    assert_rel(l->j, j, 1e-9);
    assert_rel(r->j, l->j, 1e-9);
    assert_near(l->t, r->t, 0);
    drop_answer a = {l->j, r->j, d->v.z, d->v.x, v3_len(d->w), l->p.x, r->p.x};
    assert_near(v3_len(d->w), 0, 1e-12);
    assert_near(d->v.x, 0, 1e-12 * v);
    assert_near(d->v.y, 0, 1e-12 * v);
    if (e > 0) /* up at e v, then gravity */
        assert_rel(d->v.z, e * v - G * (w.time - l->t), 1e-9);
    assert_near(l->p.x, -r->p.x, 1e-9);
    world_free(&w);
    return a;
}

/* Every order of creation gives the same answer, mirrored where the set-up is. */
static void every_order(maker make, double e, double h, double alpha, const char *what)
{
    static const int perms[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
    drop_answer ref = symmetric_drop(make, perms[0], e, h, alpha);
    for (int p = 1; p < 6; p++) {
        drop_answer a = symmetric_drop(make, perms[p], e, h, alpha);
        assert_rel(a.jl, ref.jl, 1e-12);
        assert_rel(a.jr, ref.jr, 1e-12);
        assert_near(a.vz, ref.vz, 1e-12 * (1 + fabs(ref.vz)));
        /* (within the gap the search leaves: a point is on one object's surface) */
        assert_near(a.xl, ref.xl, 1e-9);
        assert_near(a.xr, ref.xr, 1e-9);
    }
    print_message("%s, e %g: impulses %.15g and %.15g, v_z %.15g, |w| %.3g, in every order\n", what,
                  e, ref.jl, ref.jr, ref.vz, ref.spin);
}

/* The plank: 1 m x 0.2 m x 0.1 m (mass 1) dropped flat from 0.5 m onto
 * two supports 0.7 m apart, each 0.1 m x 0.4 m on top. */
static void plank_parts(world *w, int which, double e)
{
    if (which == 0) {
        body *p = add_box(w, "drop", v3(0.5, 0.1, 0.05));
        p->elasticity = e;
        p->x = v3(0, 0, 0.05 + 0.5);
        return;
    }
    body *s = add_static_box(w, which == 1 ? "left" : "right", v3(0.05, 0.2, 0.1));
    s->x = v3(which == 1 ? -0.35 : 0.35, 0, -0.1);
}

static void plank_lands_on_two_supports_alike(void **state)
{
    (void)state;
    const double es[] = {0, 0.5, 1};
    for (int k = 0; k < 3; k++) every_order(plank_parts, es[k], 0.5, 0, "plank on two supports");
}

/* A ball of radius 0.1 dropped from 0.3 m onto two static balls of radius 0.1
 * whose centres are 0.24 m apart: it meets them with the lines of centres
 * alpha off the vertical, cos(alpha) = 0.16 / 0.2. */
static void two_balls_parts(world *w, int which, double e)
{
    if (which == 0) {
        body *b = add_ball(w, "drop", 0.1);
        b->elasticity = e;
        b->x = v3(0, 0, 0.16 + 0.3);
        return;
    }
    body *s = add_ball(w, which == 1 ? "left" : "right", 0.1);
    body_set_mass(s, -1);
    s->x = v3(which == 1 ? -0.12 : 0.12, 0, 0);
}

static void ball_lands_on_two_balls_alike(void **state)
{
    (void)state;
    const double es[] = {0, 0.5, 1};
    for (int k = 0; k < 3; k++) every_order(two_balls_parts, es[k], 0.3, acos(0.8), "ball on two balls");
}

/* A groove of two static slabs whose faces meet at the line x = z = 0, each
 * alpha off the horizontal (so beta = pi - 2 alpha between them), and a ball of
 * radius 0.1 dropped from 0.3 m above where it touches both, at its middle. */
static double groove_alpha;

static void groove_parts(world *w, int which, double e)
{
    double a = groove_alpha;
    if (which == 0) {
        body *b = add_ball(w, "drop", 0.1);
        b->elasticity = e;
        b->x = v3(0, 0, 0.1 / cos(a) + 0.3);
        return;
    }
    /* the left slab's top face has normal (sin a, 0, cos a), the right one's
     * (-sin a, 0, cos a); each reaches 0.05 past the bottom line */
    double s = which == 1 ? 1 : -1;
    vec3 n = v3(s * sin(a), 0, cos(a)), along = v3(cos(a), 0, -s * sin(a));
    body *slab = add_static_box(w, which == 1 ? "left" : "right", v3(0.5, 0.5, 0.1));
    body_set_rotation(slab, v3(0, 1, 0), s * a);
    slab->x = v3_sub(v3_scale(along, -s * 0.45), v3_scale(n, 0.1));
}

static void ball_lands_in_grooves_alike(void **state)
{
    (void)state;
    const double es[] = {0, 0.5, 1}, betas[] = {PI / 2, 2 * PI / 3};
    for (int b = 0; b < 2; b++) {
        groove_alpha = 0.5 * (PI - betas[b]);
        for (int k = 0; k < 3; k++)
            every_order(groove_parts, es[k], 0.3, groove_alpha,
                        b == 0 ? "ball in a 90 degree groove" : "ball in a 120 degree groove");
    }
}

/* ------------------------------------------------------------ chains */

/* n equal balls of radius 0.05 in a row along x, `gap` apart (0: touching), no
 * force; the first k sent along the row at 1.5 m/s, e = 1: k leave the far end
 * at 1.5 m/s and the rest stand still, momentum and energy kept.  With gaps each
 * ball strikes the next in turn and they exchange their velocities; touching,
 * the instant's waves do the same (the limit of vanishing gaps), so that the
 * answer does not jump at the contact distance. */
static void cradle(int n, int k, double gap)
{
    world w;
    instant_world(&w, 0);
    const double v = 1.5;
    body *b[7];
    for (int i = 0; i < n; i++) {
        b[i] = numbered_ball(&w, i, 0.05);
        b[i]->x = v3((0.1 + gap) * i, 0, 1);
        if (i < k) b[i]->v = v3(v, 0, 0);
    }
    double e0 = energy(&w);
    w.set.time_step = 0.01;
    frames(&w, 1);
    for (int i = 0; i < n; i++) {
        double want = i >= n - k ? v : 0;
        assert_near(b[i]->v.x, want, 1e-12 * v);
        assert_near(b[i]->v.y, 0, 1e-12 * v);
        assert_near(b[i]->v.z, 0, 1e-12 * v);
    }
    assert_rel(energy(&w), e0, 1e-12);
    assert_rel(momentum(&w).x, k * b[0]->mass * v, 1e-12);
    assert_int_equal(w.st.waves_cut, 0);
    print_message("cradle of %d, %g m apart, %d struck: %ld collisions, out at %.15g\n", n, gap, k,
                  w.st.collisions, b[n - 1]->v.x);
    world_free(&w);
}

static void cradles_send_k_out_for_k_in(void **state)
{
    (void)state;
    const int ns[] = {3, 5, 7};
    const double gaps[] = {0, 2e-9, 1e-4}; /* touching, within the contact distance, apart */
    for (int g = 0; g < 3; g++) {
        for (int i = 0; i < 3; i++) {
            cradle(ns[i], 1, gaps[g]);
            cradle(ns[i], 2, gaps[g]);
        }
    }
}

/* The same on a floor under gravity: five touching balls resting on it, the
 * first sent at the others at 1.5 m/s as time starts, e = 1.  The blow passes
 * along the row as without the floor, which takes none of it (it is
 * horizontal); the last ball slides off at 1.5 m/s along the floor, which holds
 * it without a bounce, and the others stand.  Four collisions in 10 frames,
 * the floor's in none of them. */
static void cradle_on_a_floor_slides_the_last_ball_off(void **state)
{
    (void)state;
    world w;
    instant_world(&w, G);
    add_floor(&w);
    body *b[5];
    for (int i = 0; i < 5; i++) {
        b[i] = numbered_ball(&w, i, 0.05);
        b[i]->x = v3(0.1 * i - 0.2, 0, 0.05);
    }
    const double v = 1.5;
    b[0]->v = v3(v, 0, 0);
    w.set.time_step = 0.05;
    long hops = 0;
    for (int f = 0; f < 10; f++) {
        frames(&w, 1);
        for (long k = 0; k < w.nevents; k++) hops += w.events[k].a == 0 || w.events[k].b == 0;
    }
    print_message("cradle on a floor: %ld collisions (%ld with the floor), the last at (%.15g, %.3g, %.3g), "
                  "mode %d\n", w.st.collisions, hops, b[4]->v.x, b[4]->v.y, b[4]->v.z, b[4]->mode);
    assert_int_equal(w.st.collisions, 4);
    assert_int_equal(hops, 0);
    assert_int_equal(b[4]->mode, MODE_SLIDE);
    assert_near(b[4]->v.x, v, 1e-8 * v);
    assert_near(b[4]->v.z, 0, 1e-12);
    assert_near(b[4]->x.z, 0.05, 1e-6);
    for (int i = 0; i < 4; i++) assert_near(b[i]->v.x, 0, 1e-8 * v);
    world_free(&w);
}

/* A stack of two touching balls (radius 0.1, mass 1) on a floor, and a third
 * thrown down onto it at v, e = 1.  The blow goes down in waves and back up: the
 * thrown ball stops and the top one takes v (m v), the top one stops and the
 * lower takes it (m v), the floor sends the lower back (2 m v), and so up again
 * (m v each): the thrown ball leaves at v and the stack stands still, each
 * contact having taken 2 m v.  With gravity, the stack resting, the same at the
 * instant, the ball dropped from h arriving at sqrt(2 g h). */
static void stack_struck(double g)
{
    world w;
    instant_world(&w, g);
    add_floor(&w);
    body *low = add_ball(&w, "low", 0.1), *top = add_ball(&w, "top", 0.1), *ball = add_ball(&w, "ball", 0.1);
    low->x = v3(0, 0, 0.1);
    top->x = v3(0, 0, 0.3);
    const double h = 0.2;
    ball->x = v3(0, 0, 0.5 + h);
    double v = 2, t_hit = h / v;
    if (g > 0) { /* resting, as a saved world has them */
        char err[256];
        w.bodies[0]->moved = false; /* (the floor, as placed before) */
        assert_int_equal(edit_exact_contact(&w, 0 + 1, MODE_FREE, true, err, sizeof err), 0);
        assert_int_equal(edit_exact_contact(&w, 2, MODE_FREE, true, err, sizeof err), 0);
        assert_int_equal(edit_exact_touching(&w, 1, 0, err, sizeof err), 0);
        assert_int_equal(edit_exact_touching(&w, 2, 1, err, sizeof err), 0);
        v = sqrt(2 * g * h);
        t_hit = sqrt(2 * h / g);
    } else {
        ball->v = v3(0, 0, -v);
    }
    double e0 = energy(&w);
    w.set.time_step = t_hit + 1e-6;
    frames(&w, 1);
    const sim_event *bt = event_of(&w, "ball", "top"), *tl = event_of(&w, "top", "low"),
                    *lf = event_of(&w, "low", "floor");
    assert_non_null(bt);
    assert_non_null(tl);
    assert_non_null(lf);
    double u = bt->speed; /* (v where the search found it) */
    assert_rel(u, v, 1e-7);
    assert_rel(bt->j, 2 * u, 1e-9);
    assert_rel(tl->j, 2 * u, 1e-9);
    assert_rel(lf->j, 2 * u, 1e-9);
    assert_rel(ball->v.z, u - g * (w.time - bt->t), 1e-9);
    if (g == 0) { /* (waves that end by themselves keep the energy) */
        assert_near(v3_len(top->v), 0, 1e-12 * u);
        assert_near(v3_len(low->v), 0, 1e-12 * u);
        assert_rel(energy(&w), e0, 1e-12);
        assert_int_equal(w.st.waves_cut, 0);
    }
    print_message("ball on a stack (g %g): leaves at %.15g of %.15g; impulses %.15g %.15g %.15g\n", g,
                  ball->v.z + g * (w.time - bt->t), u, bt->j, tl->j, lf->j);
    world_free(&w);
}

static void blow_on_a_touching_stack_goes_down_and_back_up(void **state)
{
    (void)state;
    stack_struck(0);
    stack_struck(G);
}

/* ------------------------------------------------------------ landings */

/* A cube of half-size a released from rest leaning on one edge at theta0 on a
 * floor, elasticity e.  Frictionless, its centre of mass falls straight down
 * while the edge slides; it lands flat on the opposite edge with spin w and the
 * centre falling at a w.  The landing is a collision: with the landing edge
 * approaching at 2 a w and the pivot at rest, Newton's law on both edges (an
 * LCP with both pushing) gives w' = -e w and the centre rising at e a w, so the
 * cube rocks back up the same edge with e^2 of its energy:
 *     h(theta1) - a = e^2 (h(theta0) - a),   h(theta) = a (cos theta + sin theta).
 * Follows it through `landings` landings (frames of 1 ms), writing the largest
 * angle it reaches after each into top[]; each landing is one logged collision,
 * it stays on the same edge, turning about that edge's axis only.  With e = 1
 * its energy is kept across them, to the stepping's order (its short steps'
 * kicks keep the pivot closed within the square of their length). */
static void rock(double a, double theta0, double e, int landings, double *top)
{
    world w;
    instant_world(&w, G);
    add_floor(&w);
    body *c = add_box(&w, "cube", v3(a, a, a));
    c->elasticity = e;
    body_set_rotation(c, v3(0, 1, 0), theta0);
    c->x = v3(0, 0, a * (cos(theta0) + sin(theta0)));
    double e0 = energy_total(energy_of_world(&w));
    w.set.time_step = 0.001;
    int landed = 0;
    for (int f = 0; f < 20000 && landed <= landings; f++) {
        frames(&w, 1);
        vec3 up = q_rotate(c->q, v3(0, 0, 1));
        double angle = atan2(up.x, up.z);
        assert_true(angle > -1e-6); /* on the same edge throughout */
        assert_true(fabs(c->w.x) + fabs(c->w.z) < 1e-9 * (1 + fabs(c->w.y)));
        for (long k = 0; k < w.nevents; k++) {
            assert_true(w.events[k].speed > 0.05); /* the landing edge comes down: a collision */
            if (landed < landings) top[landed] = 0;
            landed++;
        }
        if (landed >= 1 && landed <= landings) top[landed - 1] = d_max(top[landed - 1], angle);
        if (e == 1) assert_rel(energy_total(energy_of_world(&w)), e0, 1e-5);
    }
    assert_int_equal(landed, landings + 1);
    world_free(&w);
}

static void leaning_cube_lands_and_rocks_back(void **state)
{
    (void)state;
    const double a = 0.1, thetas[] = {10 * PI / 180, 20 * PI / 180}, es[] = {1, 0.8, 0.5};
    for (int i = 0; i < 2; i++) {
        for (int k = 0; k < 3; k++) {
            double th = thetas[i], e = es[k];
            double h1 = a + e * e * a * (cos(th) + sin(th) - 1);
            /* cos t + sin t = h1 / a: t = asin(h1 / (a sqrt 2)) - pi / 4 */
            double want = asin(h1 / (a * sqrt(2))) - PI / 4, top[10];
            /* with e = 1 it rocks back to where it began for ever: ten times here */
            int n = e == 1 ? 10 : 1;
            rock(a, th, e, n, top);
            for (int l = 0; l < n; l++) assert_near(top[l], want, 1e-3);
            print_message("cube leaning %.0f deg, e %g: rocks back to %.4f deg (want %.4f), %.4f after "
                          "%d landings\n", th * 180 / PI, e, top[0] * 180 / PI, want * 180 / PI,
                          top[n - 1] * 180 / PI, n);
        }
    }
}

/* ------------------------------------------------------------ instants cut short */

/* A ball (radius 0.1) touching two walls 0.2 m apart, sent at one of them, e = 1,
 * no force: it would bounce between them for ever in no time.  After 4 n waves
 * (n = 2 contacts) one last solve with no restitution stops it there. */
static void pinched_ball_ends_its_instant(void **state)
{
    (void)state;
    world w;
    instant_world(&w, 0);
    add_static_box(&w, "left", v3(0.1, 1, 1))->x = v3(-0.2, 0, 0);
    add_static_box(&w, "right", v3(0.1, 1, 1))->x = v3(0.2, 0, 0);
    body *b = add_ball(&w, "ball", 0.1);
    b->v = v3(1, 0, 0);
    frames(&w, 1);
    assert_int_equal(w.st.waves_cut, 1);
    assert_near(v3_len(b->v), 0, 1e-12);
    assert_non_null(event_of(&w, "ball", "left"));
    assert_non_null(event_of(&w, "ball", "right"));
    world_free(&w);
}

/* A heavy ball (10 kg) thrown at 1 m/s onto a touching stack of two light ones
 * (0.1 kg) on a floor, e = 0.5, no force: each light ball takes the blow and
 * passes it on, while the heavy one comes on barely slowed, so that the light
 * ones bounce between it and the floor in ever more waves, which would halve for
 * ever.  After 4 n waves (n = 3 contacts) the last solve ends them with the
 * heavy ball stopped on the stack: counted, no energy made, and no contact left
 * approaching. */
static void lossy_stack_ends_its_instant(void **state)
{
    (void)state;
    world w;
    instant_world(&w, 0);
    add_floor(&w);
    body *b[3];
    for (int i = 0; i < 3; i++) {
        b[i] = numbered_ball(&w, i, 0.1);
        b[i]->elasticity = 0.5;
        body_set_mass(b[i], i < 2 ? 0.1 : 10);
        b[i]->x = v3(0, 0, 0.1 + 0.2 * i);
    }
    b[2]->v = v3(0, 0, -1);
    double e0 = energy(&w);
    w.set.time_step = 0.01;
    frames(&w, 1);
    print_message("lossy stack: %ld collisions, %ld instants cut, energy %.6g of %.6g\n", w.st.collisions,
                  w.st.waves_cut, energy(&w), e0);
    assert_int_equal(w.st.waves_cut, 1);
    assert_true(energy(&w) <= e0 * (1 + 1e-12));
    /* nothing approaches: each ball no faster down than the one below it */
    assert_true(b[0]->v.z >= -1e-12);
    for (int i = 1; i < 3; i++) assert_true(b[i]->v.z >= b[i - 1]->v.z - 1e-12);
    assert_near(b[2]->v.z, 0, 1e-12);
    world_free(&w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(plank_lands_on_two_supports_alike),
        cmocka_unit_test(ball_lands_on_two_balls_alike),
        cmocka_unit_test(ball_lands_in_grooves_alike),
        cmocka_unit_test(cradles_send_k_out_for_k_in),
        cmocka_unit_test(cradle_on_a_floor_slides_the_last_ball_off),
        cmocka_unit_test(blow_on_a_touching_stack_goes_down_and_back_up),
        cmocka_unit_test(leaning_cube_lands_and_rocks_back),
        cmocka_unit_test(pinched_ball_ends_its_instant),
        cmocka_unit_test(lossy_stack_ends_its_instant),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
