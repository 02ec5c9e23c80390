/* test_collide.c: collisions in time against textbook answers (issue 5).
 *
 * Head-on collisions of unequal masses, bounce heights e^2 h, conservation of
 * momentum, angular momentum and energy in a closed system, an off-centre hit,
 * nothing through a plate, a box landing flat, a drum's contact region, a box
 * turning onto an edge, a block rocking from corner to corner, sliders leaving a
 * table and outlasting objects added and deleted elsewhere, Newton's cradle, rest; settling, a rocking pillow and a stack, without
 * storms of micro-collisions; far pairs that keep their times while a box settles. */
#include "check.h"

#include <stdlib.h>
#include <string.h>

#include "core/closest.h"
#include "core/contact.h"
#include "core/schedule.h"
#include "core/edit.h"
#include "core/flight.h"
#include "core/impulse.h"
#include "core/lcp.h"
#include "core/rest.h"
#include "core/sim.h"
#include "core/world.h"
#include "worlds.h"

static void frames(world *w, int n)
{
    char err[256];
    for (int i = 0; i < n; i++) assert_int_equal(sim_frame(w, err, sizeof err), 0);
}

static void head_on(double e, double want1, double want2)
{
    world w;
    world_init(&w);
    body *a = add(&w, "a", SHAPE_SPHERE), *b = add(&w, "b", SHAPE_SPHERE);
    a->sp.radius = b->sp.radius = 0.5;
    rebuild(a);
    rebuild(b);
    body_set_mass(a, 1);
    body_set_mass(b, 3);
    a->elasticity = b->elasticity = e;
    a->x = v3(-2, 0, 0);
    b->x = v3(0.5, 0, 0);
    a->v = v3(2, 0, 0);
    frames(&w, 20);
    assert_int_equal(w.st.collisions, 1);
    assert_near(a->v.x, want1, 1e-6);
    assert_near(b->v.x, want2, 1e-6);
    assert_near(a->v.y, 0, 1e-12);
    world_free(&w);
}

static void head_on_unequal_masses(void **state)
{
    (void)state;
    head_on(1, -1, 1);
    head_on(0, 0.5, 0.5);
    head_on(0.5, -0.25, 0.75); /* v1 = (m1 - e m2) u / (m1 + m2), v2 = (1 + e) m1 u / (m1 + m2) */
}

/* Height of the apex of the flight the ball is in now, above the floor's top. */
static double apex(const body *b, double g, double floor_top)
{
    return b->x.z - b->sp.radius - floor_top + b->v.z * b->v.z / (2 * g);
}

static void bounce_height(double e, double h, double time_step, double internal_step)
{
    world w;
    world_init(&w);
    w.set.force = (dir_amount){v3(0, 0, -1), 9.8};
    w.set.time_step = time_step;
    w.set.internal_step = internal_step;
    w.set.max_linear = 50;
    add_static_box(&w, "floor", v3(5, 5, 0.5));
    body *ball = add_ball(&w, "ball", 0.2);
    ball->elasticity = e;
    ball->x = v3(0.3, -0.2, 0.5 + 0.2 + h);
    char err[256];
    while (w.st.collisions == 0) assert_int_equal(sim_frame(&w, err, sizeof err), 0);
    double a = apex(ball, 9.8, 0.5);
    assert_rel(a, e * e * h, 1e-4);
    world_free(&w);
}

static void bounce_apex_is_e_squared_h(void **state)
{
    (void)state;
    const double steps[][2] = {{0.1, 0}, {0.02, 0}, {0.1, 0.001}, {0.05, 0.013}, {0.5, 0}};
    for (size_t k = 0; k < sizeof steps / sizeof steps[0]; k++) {
        bounce_height(0.8, 1.0, steps[k][0], steps[k][1]);
        bounce_height(0.5, 2.5, steps[k][0], steps[k][1]);
        bounce_height(1.0, 0.7, steps[k][0], steps[k][1]);
    }
}

static vec3 momentum(const world *w)
{
    vec3 p = v3(0, 0, 0);
    for (int i = 0; i < w->n; i++) p = v3_mad(p, w->bodies[i]->v, w->bodies[i]->mass);
    return p;
}

/* Angular momentum about the origin: orbital plus spin. */
static vec3 angular_momentum(const world *w)
{
    vec3 l = v3(0, 0, 0);
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        l = v3_add(l, v3_add(v3_cross(body_com(b), v3_scale(b->v, b->mass)), b->L));
    }
    return l;
}

static double energy(const world *w)
{
    double e = 0;
    for (int i = 0; i < w->n; i++) e += body_energy(w->bodies[i]);
    return e;
}

static void closed_system_conserves(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    w.set.max_linear = 100;
    w.set.max_angular = 100;
    unsigned long long seed = 7;
    /* 20 objects on a 3x3x3 grid (less 7), moving inwards: many collisions */
    int k = 0;
    for (int i = 0; i < 27 && k < 20; i++) {
        if (i % 4 == 3) continue;
        char name[16];
        snprintf(name, sizeof name, "o%d", k);
        body *b = add(&w, name, k % 2 ? SHAPE_SUPERQUADRIC : SHAPE_SPHERE);
        b->sp.radius = urand(&seed, 0.2, 0.35);
        b->sp.exp1 = urand(&seed, 0.4, 1.6);
        b->sp.exp2 = urand(&seed, 0.4, 1.6);
        b->sp.a1 = urand(&seed, 0.2, 0.35);
        b->sp.a2 = urand(&seed, 0.2, 0.35);
        b->sp.a3 = urand(&seed, 0.2, 0.35);
        b->sp.ures = b->sp.vres = 12;
        rebuild(b);
        body_set_mass(b, urand(&seed, 0.5, 3));
        vec3 c = v3(i % 3 - 1, (i / 3) % 3 - 1, i / 9 - 1);
        b->x = v3_scale(c, 1.0);
        body_set_rotation(b, v3(urand(&seed, -1, 1), urand(&seed, -1, 1), 1), urand(&seed, 0, 3));
        b->v = v3_add(v3_scale(c, -0.5), v3(urand(&seed, -.3, .3), urand(&seed, -.3, .3), urand(&seed, -.3, .3)));
        body_set_angular_vel(b, v3(urand(&seed, -1, 1), urand(&seed, -1, 1), urand(&seed, -1, 1)));
        k++;
    }
    vec3 p0 = momentum(&w), l0 = angular_momentum(&w);
    double e0 = energy(&w);
    assert_int_equal(sim_penetrations(&w, NULL, NULL), 0);
    frames(&w, 100); /* 10 s */
    print_message("closed system: %ld collisions in 10 s\n", w.st.collisions);
    assert_true(w.st.collisions >= 20);
    vec3 p1 = momentum(&w), l1 = angular_momentum(&w);
    double scale_p = 0, scale_l = 0;
    for (int i = 0; i < w.n; i++) {
        scale_p += w.bodies[i]->mass * v3_len(w.bodies[i]->v);
        scale_l += v3_len(w.bodies[i]->L) + w.bodies[i]->mass * v3_len(body_com(w.bodies[i])) * v3_len(w.bodies[i]->v);
    }
    assert_true(v3_len(v3_sub(p1, p0)) <= 1e-9 * scale_p);
    assert_true(v3_len(v3_sub(l1, l0)) <= 1e-9 * scale_l);
    assert_rel(energy(&w), e0, 1e-6);
    world_free(&w);
}

static void off_centre_hit_conserves_momentum_about_a_point(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    body *box = add_box(&w, "box", v3(0.5, 0.2, 0.3));
    body_set_mass(box, 4);
    box->elasticity = 0.6;
    body *ball = add_ball(&w, "ball", 0.1);
    body_set_mass(ball, 1);
    ball->x = v3(0.35, -1, 0.1); /* off centre in x and z */
    ball->v = v3(0, 3, 0);
    vec3 p0 = momentum(&w), l0 = angular_momentum(&w);
    frames(&w, 10);
    assert_int_equal(w.st.collisions, 1);
    assert_vec_near(momentum(&w), p0, 1e-12);
    assert_vec_near(angular_momentum(&w), l0, 1e-12);
    assert_true(v3_len(box->w) > 0.5); /* it spins */
    assert_true(energy(&w) < 0.5 * 9); /* e < 1 loses energy */
    world_free(&w);
}

static void nothing_passes_through_a_plate(void **state)
{
    (void)state;
    unsigned long long seed = 99;
    int through = 0;
    for (int shot = 0; shot < 1000; shot++) {
        world w;
        world_init(&w);
        w.set.collision_dist = urand(&seed, 0.05, 0.3);
        w.set.max_linear = urand(&seed, 2, 30);
        if (shot % 3 == 0) w.set.force = (dir_amount){v3(0, 0, -1), 9.8};
        body *plate = add(&w, "plate", SHAPE_CUBE);
        double half = 0.5 * w.set.collision_dist * urand(&seed, 1.05, 2);
        plate->sp.size = v3(20, 20, half);
        rebuild(plate);
        body_set_mass(plate, -1);
        int kind = shot % 3;
        body *b = add_random_shot(&w, (shape_kind)kind, &seed);
        b->elasticity = urand(&seed, 0, 1);
        b->x = v3(urand(&seed, -1, 1), urand(&seed, -1, 1), half + b->shape.r_out + urand(&seed, 0.01, 2));
        body_set_rotation(b, v3(urand(&seed, -1, 1), urand(&seed, -1, 1), urand(&seed, -1, 1)), urand(&seed, 0, 3));
        vec3 dir = v3_norm(v3(urand(&seed, -1, 1), urand(&seed, -1, 1), -urand(&seed, 0.2, 1)));
        b->v = v3_scale(dir, w.set.max_linear * urand(&seed, 0.5, 1));
        body_set_angular_vel(b, v3(urand(&seed, -3, 3), urand(&seed, -3, 3), urand(&seed, -3, 3)));
        for (int f = 0; f < 15; f++) {
            frames(&w, 1);
            vec3 c = body_com(b);
            /* below the plate while over it (it may slide off its edge and fall) */
            if (c.z < 0 && fabs(c.x) < 20 - b->shape.r_out && fabs(c.y) < 20 - b->shape.r_out) {
                through++;
                print_message("shot %d through: kind %d dist %g vmax %g\n", shot, kind,
                              w.set.collision_dist, w.set.max_linear);
                break;
            }
        }
        world_free(&w);
    }
    assert_int_equal(through, 0);
}

/* A world under gravity with a still box, the table (body 0, half-sizes table,
 * its top at z = table.z), and over it a box (body 1, half-sizes size) of
 * restitution e, turned by angle about axis, its centre at x. */
static body *box_over_table(world *w, vec3 table, vec3 size, double e, vec3 axis, double angle,
                            vec3 x)
{
    world_init(w);
    w->set.force = (dir_amount){v3(0, 0, -1), 9.8};
    add_static_box(w, "table", table);
    body *box = add_box(w, "box", size);
    box->elasticity = e;
    body_set_rotation(box, axis, angle);
    box->x = x;
    return box;
}

static void box_dropped_flat_rests_flat(void **state)
{
    (void)state;
    world w;
    /* turned about the vertical: still flat */
    body *box = box_over_table(&w, v3(2, 2, 0.1), v3(0.3, 0.2, 0.1), 0.5, v3(0, 0, 1), 0.4,
                               v3(0.2, -0.3, 1.5));
    quat q0 = box->q;
    int f = 0;
    while (box->state != STATE_RESTING && f < 100) {
        frames(&w, 1);
        f++;
    }
    print_message("box dropped flat: resting after %d frames, %ld collisions\n", f, w.st.collisions);
    assert_int_equal(box->state, STATE_RESTING);
    assert_true(f < 60);
    assert_near(q0.w, box->q.w, 1e-6);
    assert_near(q0.x, box->q.x, 1e-6);
    assert_near(q0.y, box->q.y, 1e-6);
    assert_near(q0.z, box->q.z, 1e-6);
    assert_near(box->x.z, 0.1 + 0.1, 1e-4);
    assert_near(box->x.x, 0.2, 1e-9);
    world_free(&w);
}

static void box_dropped_on_its_corner_settles(void **state)
{
    (void)state;
    world w;
    /* a corner down, off balance */
    body *box = box_over_table(&w, v3(3, 3, 0.1), v3(0.2, 0.2, 0.2), 0.4, v3(1, 0.4, 0.1), 0.8,
                               v3(0, 0, 1.5));
    frames(&w, 150);
    assert_int_equal(box->state, STATE_RESTING);
    /* it rests on a face: its lowest point is on the table, its centre a half side up */
    assert_near(box->x.z, 0.1 + 0.2, 2e-3);
    world_free(&w);
}

/* A frictionless contact pushes along the vertical only: it changes neither the
 * horizontal momentum nor the angular momentum about the vertical.  A box that
 * lands slightly tilted, sliding and spinning, rocks and settles on its face
 * (thesis 3.3.3, rest.c "rest_settle") keeping both, in a few collisions. */
static void tilted_box_settles_keeping_what_contact_keeps(void **state)
{
    (void)state;
    world w;
    body *box = box_over_table(&w, v3(3, 3, 0.1), v3(0.15, 0.1, 0.1), 0.5, v3(1, 0.3, 0), 0.12,
                               v3(0, 0, 0.1 + 0.125));
    box->v = v3(0.3, -0.1, 0);
    body_set_angular_vel(box, v3(0, 0, 1));
    w.set.max_angular = 100; /* the clamp would scale L down as the box rocks */
    double lz = box->L.z;
    frames(&w, 15);
    print_message("tilted box: %ld collisions, state %d, mode %d\n", w.st.collisions, box->state, box->mode);
    assert_true(w.st.collisions > 0);
    assert_true(w.st.collisions < 40);
    assert_int_equal(box->state, STATE_DYNAMIC);
    assert_int_equal(box->mode, MODE_SLIDE); /* on the table */
    assert_int_equal(box->slide_on, 0);
    vec3 up = q_rotate(box->q, v3(0, 0, 1));
    assert_true(fabs(up.z) > 1 - 1e-9); /* flat on a face */
    assert_near(box->x.z, 0.1 + 0.1, 1e-4);
    assert_near(box->v.x, 0.3, 1e-9);
    assert_near(box->v.y, -0.1, 1e-9);
    assert_near(box->v.z, 0, 1e-9);
    assert_near(box->L.z, lz, 1e-9 * fabs(lz));
    /* sliding flat and turning about the vertical, it collides no more */
    long hits = w.st.collisions;
    frames(&w, 10);
    assert_int_equal(w.st.collisions, hits);
    assert_near(box->L.z, lz, 1e-9 * fabs(lz));
    world_free(&w);
}

/* A pillow (a superquadric with a rounded underside) dropped tilted and spinning
 * rocks to a stop instead of colliding thousands of times a second. */
static void pillow_rocks_to_a_stop(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    w.set.force = (dir_amount){v3(0, 0, -1), 9.8};
    add_static_box(&w, "floor", v3(5, 5, 0.1));
    body *pillow = add(&w, "pillow", SHAPE_SUPERQUADRIC);
    pillow->sp.exp1 = 0.4;
    pillow->sp.exp2 = 1;
    pillow->sp.a1 = 0.3;
    pillow->sp.a2 = 0.2;
    pillow->sp.a3 = 0.08;
    pillow->sp.ures = pillow->sp.vres = 16;
    rebuild(pillow);
    pillow->elasticity = 0.5;
    body_set_rotation(pillow, v3(1, 1, 0), 0.4);
    pillow->x = v3(0, 0, 0.6);
    body_set_angular_vel(pillow, v3(1, -2, 0.5));
    frames(&w, 30);
    long hits = w.st.collisions;
    print_message("pillow: %ld collisions in 3 s, state %d\n", hits, pillow->state);
    assert_true(hits > 0);
    assert_true(hits < 300);
    frames(&w, 10);
    assert_int_equal(w.st.collisions, hits);
    /* lying on the floor: no lower than its half thickness, not much higher */
    assert_true(pillow->x.z > 0.1 + 0.07 && pillow->x.z < 0.1 + 0.09);
    world_free(&w);
}

/* The contact region of a superquadric drum (its hull walked, not read in turn)
 * of ures x vres divisions, its hull more than min_nv vertices.  Upright (when
 * asked), standing on its flat end on a box, anywhere and turned any way about
 * its axis: the end is a regular polygon, so the contact point is on the drum's
 * axis, and the drum stands.  Tilted onto its rim it touches at a vertex or an
 * edge, at the rim's lowest point (found here by reading every vertex), and does
 * not. */
static void drum_region(int ures, int vres, int min_nv, bool upright)
{
    world w;
    world_init(&w);
    body *table = add_static_box(&w, "table", v3(1, 1, 0.1));
    body *drum = add(&w, "drum", SHAPE_SUPERQUADRIC);
    drum->sp.exp1 = 0.1;
    drum->sp.exp2 = 1;
    drum->sp.a1 = drum->sp.a2 = 0.1;
    drum->sp.a3 = 0.15;
    drum->sp.ures = ures;
    drum->sp.vres = vres;
    rebuild(drum);
    const poly *h = drum->shape.hull;
    assert_true(h->nv > min_nv);
    double bottom = HUGE_VAL; /* the end's height below the centre */
    for (int i = 0; i < h->nv; i++) bottom = fmin(bottom, h->v[i].z);
    unsigned long long s = 41;
    for (int k = 0; k < 40; k++) {
        bool tilted = k % 2 || !upright;
        vec3 axis = tilted ? v3(urand(&s, -1, 1), urand(&s, -1, 1), 0) : v3(0, 0, 1);
        double angle = tilted ? urand(&s, 0.2, 0.6) : urand(&s, 0, 6.3);
        body_set_rotation(drum, axis, angle);
        drum->x = v3(urand(&s, -0.5, 0.5), urand(&s, -0.5, 0.5), 0);
        /* the lowest vertex, read from all of them; the drum put 1e-8 m above the table */
        vec3 low = v3(0, 0, HUGE_VAL);
        for (int i = 0; i < h->nv; i++) {
            vec3 p = v3_add(drum->x, q_rotate(drum->q, h->v[i]));
            if (p.z < low.z) low = p;
        }
        drum->x.z += 0.1 + 1e-8 - low.z;
        low.z = 0.1 + 1e-8;
        closest_result r = body_distance(drum, table, NULL);
        assert_int_equal(r.status, CLOSEST_SEPARATED);
        vec3 c = contact_point(drum, table, &r, 1e-6);
        int face;
        bool stands = contact_holds(drum, table, &r, 1e-6, &face);
        if (!tilted) {
            assert_true(fabs(drum->x.z + bottom - 0.1) < 1e-7);
            if (fabs(c.x - drum->x.x) > 1e-9 || fabs(c.y - drum->x.y) > 1e-9)
                fail_msg("trial %d: contact at (%g, %g), the axis at (%g, %g)", k, c.x, c.y, drum->x.x,
                         drum->x.y);
            assert_true(stands);
        } else {
            /* a rim vertex, or the middle of a rim edge (0.1 * 2 pi / ures long) */
            if (hypot(c.x - low.x, c.y - low.y) > 0.5 * 0.1 * 2 * M_PI / ures + 1e-9)
                fail_msg("trial %d: contact at (%g, %g), the lowest vertex at (%g, %g)", k, c.x, c.y,
                         low.x, low.y);
            assert_false(stands);
        }
    }
    world_free(&w);
}

/* More vertices than contact.c reads in turn (32), and more than the walk marks
 * on the stack (4,096).  The fine drum is tried tilted only: the hull's flat
 * regions (poly.c, POLY_FLAT_ANGLE) group the nearly flat facets of its end
 * unevenly, so that its end is no longer a regular polygon. */
static void drum_contact_region(void **state)
{
    (void)state;
    drum_region(24, 12, 32, true);
    drum_region(100, 60, 4096, false);
}

/* The closing speed along +z of box's material point p onto a still support. */
static double closing_onto(const body *box, vec3 p)
{
    vec3 v = v3_add(box->v, v3_cross(box->w, v3_sub(p, box->x)));
    return -v.z;
}

/* A box whose lowest edge lies on a table while it turns about a level axis across
 * that edge: the edge's middle moves apart, one end comes down.  The impulse goes
 * where the region closes: at that end, found here from the box's corners; it
 * leaves that end moving apart at e times its closing speed (Newton's law of
 * restitution at the point struck) and takes energy away.  Nothing closes: the
 * centre stays the point. */
static void box_turning_onto_its_edge_strikes_with_the_lower_end(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    body *table = add_static_box(&w, "table", v3(1, 1, 0.1));
    body *box = add_box(&w, "box", v3(0.2, 0.1, 0.1));
    unsigned long long s = 43;
    for (int k = 0; k < 20; k++) {
        /* an edge along x lowest; turned about z a little, and shifted */
        body_set_rotation(box, v3(1, 0, 0), M_PI / 4);
        double yaw = urand(&s, -0.5, 0.5);
        box->q = q_mul(q_axis_angle(v3(0, 0, 1), yaw), box->q);
        box->x = v3(urand(&s, -0.3, 0.3), urand(&s, -0.3, 0.3), 0);
        /* the two lowest corners, from the eight */
        vec3 low[2] = {v3(0, 0, HUGE_VAL), v3(0, 0, HUGE_VAL)};
        for (int i = 0; i < 8; i++) {
            vec3 c = v3(i & 1 ? 0.2 : -0.2, i & 2 ? 0.1 : -0.1, i & 4 ? 0.1 : -0.1);
            vec3 p = v3_add(box->x, q_rotate(box->q, c));
            if (p.z < low[0].z) {
                low[1] = low[0];
                low[0] = p;
            } else if (p.z < low[1].z) {
                low[1] = p;
            }
        }
        double lift = 0.1 + 1e-8 - 0.5 * (low[0].z + low[1].z);
        box->x.z += lift;
        low[0].z += lift;
        low[1].z += lift;
        /* turning about the level axis across the edge, rising a little */
        double omega = urand(&s, 0.5, 3) * (k % 2 ? 1 : -1);
        vec3 across = q_rotate(q_axis_angle(v3(0, 0, 1), yaw), v3(0, 1, 0));
        body_set_angular_vel(box, v3_scale(across, omega));
        box->v = v3(0, 0, 0.01);
        closest_result r = body_distance(box, table, NULL);
        assert_int_equal(r.status, CLOSEST_SEPARATED);
        vec3 mid = contact_point(box, table, &r, 1e-6);
        assert_true(contact_closing_speed(box, table, mid, r.normal) < 0);
        int down = closing_onto(box, low[0]) > closing_onto(box, low[1]) ? 0 : 1;
        assert_true(closing_onto(box, low[down]) > 0);
        vec3 p = contact_closing_corner(box, table, &r, 1e-6, mid);
        if (v3_len(v3_sub(p, low[down])) > 1e-7)
            fail_msg("trial %d: struck at (%g, %g, %g), the lower end at (%g, %g, %g)", k, p.x, p.y,
                     p.z, low[down].x, low[down].y, low[down].z);
        double before = closing_onto(box, low[down]);
        double energy = 0.5 * v3_dot(box->v, box->v) / box->inv_mass + 0.5 * v3_dot(box->w, box->L);
        impulse_row row = {.p = 0, .q = 1, .e = 0.5, .n = r.normal, .at = p};
        body *bs[2] = {box, table};
        bool mobile[2] = {true, false};
        double u = impulse_speed(&row, bs), lambda;
        lcp_work *work = malloc(lcp_work_size(1));
        assert_non_null(work);
        assert_int_equal(impulse_solve(&row, 1, bs, mobile, &u, &lambda, work), 0);
        free(work);
        assert_true(lambda > 0);
        assert_near(closing_onto(box, low[down]), -0.5 * before, 1e-9);
        assert_true(0.5 * v3_dot(box->v, box->v) / box->inv_mass + 0.5 * v3_dot(box->w, box->L) <
                    energy);
        /* rising and not turning, nothing closes: the centre it is */
        body_set_angular_vel(box, v3(0, 0, 0));
        vec3 q = contact_closing_corner(box, table, &r, 1e-6, mid);
        assert_true(q.x == mid.x && q.y == mid.y && q.z == mid.z);
    }
    world_free(&w);
}

/* A block dropped on a corner, turning, rocks from corner to corner before it
 * rests.  Its bounces are collisions; once a bounce is too slow to see, it rocks
 * on a lasting contact (cluster.h), whose corners coming down are found by the
 * cluster's steps, not by searches.  No corner ever goes into the table, and it
 * comes to rest. */
static void rocking_block_finds_its_next_corner(void **state)
{
    (void)state;
    long collisions = 0, checks = 0;
    for (int k = 0; k < 4; k++) {
        world w;
        body *box = box_over_table(&w, v3(1, 1, 0.1), v3(0.08, 0.06, 0.05), 0.5,
                                   v3(1, 0.4 + 0.1 * k, 0.1), 0.8, v3(0, 0, 0.5));
        body_set_angular_vel(box, v3(1, 2, 0.5));
        for (int f = 0; f < 30; f++) {
            frames(&w, 1);
            for (int i = 0; i < 8; i++) {
                vec3 c = v3(i & 1 ? 0.08 : -0.08, i & 2 ? 0.06 : -0.06, i & 4 ? 0.05 : -0.05);
                assert_true(v3_add(box->x, q_rotate(box->q, c)).z > 0.1 - 1e-9);
            }
        }
        assert_int_equal(box->state, STATE_RESTING);
        collisions += w.st.collisions;
        checks += w.st.pair_checks;
        world_free(&w);
    }
    print_message("rocking block: %ld collisions, %ld pair checks\n", collisions, checks);
    assert_true(collisions > 4);
    /* rocking on a corner is a lasting contact: few queries (its landings on the
     * next corners are collisions since issue 34, and it rocks on with them) */
    assert_true(checks < 2000 * 4);
}

/* A box dropped onto a box resting on the floor: both come to rest, the top one on
 * the bottom one, without a storm of collisions within the stack. */
static void stack_comes_to_rest(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    w.set.force = (dir_amount){v3(0, 0, -1), 9.8};
    add_static_box(&w, "floor", v3(3, 3, 0.1));
    body *low = add_box(&w, "low", v3(0.2, 0.2, 0.1));
    low->elasticity = 0.3;
    low->x = v3(0, 0, 0.2 + 1e-3);
    body *top = add_box(&w, "top", v3(0.1, 0.1, 0.1));
    top->elasticity = 0.3;
    top->mass = 2;
    body_set_mass(top, 2);
    top->x = v3(0.05, 0.02, 0.4 + 0.05);
    frames(&w, 30);
    print_message("stack: %ld collisions, states %d %d\n", w.st.collisions, low->state, top->state);
    assert_int_equal(low->state, STATE_RESTING);
    assert_int_equal(top->state, STATE_RESTING);
    assert_true(w.st.collisions < 100);
    assert_near(low->x.z, 0.2, 1e-4);
    assert_near(top->x.z, 0.4, 1e-4);
    assert_near(top->x.x, 0.05, 1e-9); /* pushed along the vertical only */
    long checks = w.st.pair_checks;
    frames(&w, 20);
    assert_int_equal(w.st.pair_checks, checks);
    world_free(&w);
}

/* A box (2 kg) thrown down onto a box (1 kg) resting on the floor, restitution
 * 0.3 between them and at the floor (the lesser of each pair's), both centred:
 * in the limit of vanishing gaps (instant.h) the blow goes down to the floor and
 * back up in waves, each a textbook impact of two bodies, ever smaller (from 3 m/s
 * the eighth still closes at 0.08 m/s).  After 4 n waves of n = 2 contacts the
 * last solve, with no restitution, stops both: the floor takes the upper box's
 * momentum m v through the lower one, each contact's impulse m v, and the upper
 * box does not bounce.  Both rest then where they lie. */
static void blow_on_a_stack_passes_to_the_floor(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    const double g = 9.8, e = 0.3, v0 = 3, gap = 0.01, step = 0.05, m = 2;
    w.set.force = (dir_amount){v3(0, 0, -1), g};
    w.set.time_step = step;
    add_static_box(&w, "floor", v3(3, 3, 0.1));
    body *low = add_box(&w, "low", v3(0.2, 0.2, 0.1));
    low->elasticity = e; /* the pair's restitution: the lesser of the two */
    low->x = v3(0, 0, 0.2 + 1e-3);
    frames(&w, 10);
    assert_int_equal(low->state, STATE_RESTING);
    vec3 rest = low->x;
    body *top = add_box(&w, "top", v3(0.1, 0.1, 0.1));
    top->elasticity = 0.5;
    body_set_mass(top, m);
    top->x = v3(0, 0, rest.z + 0.2 + gap);
    top->v = v3(0, 0, -v0);
    long before = w.st.collisions;
    frames(&w, 1);
    /* v0 t + g t^2 / 2 = gap: the speed of impact */
    double ti = 2 * gap / (v0 + sqrt(v0 * v0 + 2 * g * gap)), vi = v0 + g * ti;
    /* the waves, each impact in turn: they do not end by themselves */
    double v1 = -vi, v2 = 0;
    for (int wave = 0; wave < 8; wave++) {
        if (wave % 2 == 0) { /* the boxes: e * closing is above the threshold */
            double c = v2 - v1, j = (1 + e) * c / (1 / m + 1);
            assert_true(e * c > SIM_BOUNCE_SPEED);
            v1 += j / m;
            v2 -= j;
        } else { /* the lower one off the floor */
            assert_true(-v2 * e > SIM_BOUNCE_SPEED);
            v2 = -e * v2;
        }
    }
    assert_true(v1 < v2); /* still closing after the eighth */
    const sim_event *tl = NULL, *lf = NULL;
    for (long k = 0; k < w.nevents; k++) {
        const sim_event *ev = &w.events[k];
        if (ev->a == 1 || ev->b == 1) tl = ev->a == 2 || ev->b == 2 ? ev : tl;
        if ((ev->a == 0 && ev->b == 1) || (ev->a == 1 && ev->b == 0)) lf = ev;
    }
    print_message("blow: %ld collisions, %ld instants cut, impulses %.9f and %.9f (want %.9f); the "
                  "lower box %.3g m from where it rested\n", w.st.collisions - before, w.st.waves_cut,
                  tl ? tl->j : 0, lf ? lf->j : 0, m * vi, v3_len(v3_sub(low->x, rest)));
    assert_int_equal(w.st.collisions - before, 2);
    assert_int_equal(w.st.waves_cut, 1);
    assert_non_null(tl);
    assert_non_null(lf);
    assert_rel(tl->j, m * vi, 1e-6);
    assert_rel(lf->j, m * vi, 1e-6);
    assert_int_equal(low->state, STATE_RESTING);
    assert_int_equal(top->state, STATE_RESTING);
    assert_true(v3_len(v3_sub(low->x, rest)) < 1e-12);
    assert_near(top->x.z, rest.z + 0.2, 1e-6);
    world_free(&w);
}

/* A ball falls on a ball that slides on the floor, off centre.  In the limit of
 * vanishing gaps (instant.h) the sliding ball takes the blow along the line of
 * centres n as a free ball would, then the floor answers it along z with its
 * restitution, and the balls again if they close: each a textbook impact,
 * answered in turn (balls_on_floor).  The floor does not act horizontally, so
 * horizontal momentum is kept. */
static void blow_on_a_slider_moves_it_along_the_floor(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    const double g = 9.8, e = 0.5, m1 = 2, m2 = 1, r = 0.1, step = 0.05;
    w.set.force = (dir_amount){v3(0, 0, -1), g};
    w.set.time_step = step;
    add_static_box(&w, "floor", v3(3, 3, 0.1)); /* its top at z = 0.1 */
    body *low = add_ball(&w, "low", r);
    low->elasticity = e;
    body_set_mass(low, m2);
    low->x = v3(0, 0, 0.2 + 1e-6);
    low->v = v3(0.5, 0, 0);
    body *top = add_ball(&w, "top", r); /* out of the way until it is thrown */
    top->elasticity = 0.8;
    body_set_mass(top, m1);
    top->x = v3(2, 2, 5);
    frames(&w, 2);
    assert_int_equal(low->mode, MODE_SLIDE);
    assert_true(low->v.z == 0);
    vec3 c2 = low->x, v2 = low->v, v1 = v3(0, 0, -2);
    vec3 c1 = v3_add(c2, v3(0.1, 0, sqrt(3) * 0.1 + 0.01));
    top->x = c1;
    top->v = v1;
    w.sched_dirty = true; /* as after a command */
    /* the instant of contact: |c1(t) - c2(t)| = 2 r, by bisection */
    double lo = 0, hi = step;
    for (int k = 0; k < 200; k++) {
        double t = 0.5 * (lo + hi);
        vec3 d = v3_sub(v3_add(c1, v3(0, 0, v1.z * t - 0.5 * g * t * t)), v3_mad(c2, v2, t));
        if (v3_len(d) > 2 * r) lo = t;
        else hi = t;
    }
    double ti = lo;
    long before = w.st.collisions;
    w.set.time_step = ti + 1e-6; /* a frame that ends just after it */
    frames(&w, 1);
    assert_int_equal(w.st.collisions - before, 2); /* the balls, the floor */
    vec3 d = v3_sub(v3_add(c1, v3(0, 0, v1.z * ti - 0.5 * g * ti * ti)), v3_mad(c2, v2, ti));
    vec3 n = v3_scale(d, 1 / v3_len(d)), u1 = v3(0, 0, v1.z - g * ti), u2 = v2;
    double j12, j2f;
    int waves = balls_on_floor(m1, &u1, m2, &u2, n, e, e, &j12, &j2f);
    assert_true(u2.z > 0); /* the lower ball leaves the floor: both fly on */
    const sim_event *ev = NULL; /* the balls' */
    for (long k = 0; k < w.nevents; k++)
        if (w.events[k].a >= 1 && w.events[k].b >= 1) ev = &w.events[k];
    assert_non_null(ev);
    double after = w.time - ev->t;
    vec3 want1 = v3_add(u1, v3(0, 0, -g * after)), want2 = v3_add(u2, v3(0, 0, -g * after));
    print_message("slider: %d waves; top v (%.6f %.6f %.6f) want (%.6f %.6f %.6f); low v (%.6f %.6f %.6f) "
                  "want (%.6f %.6f %.6f)\n", waves, top->v.x, top->v.y, top->v.z, want1.x, want1.y,
                  want1.z, low->v.x, low->v.y, low->v.z, want2.x, want2.y, want2.z);
    assert_near(ev->j, j12, 1e-6 * j12);
    assert_true(v3_len(v3_sub(top->v, want1)) < 1e-6);
    assert_true(v3_len(v3_sub(low->v, want2)) < 1e-6);
    assert_near(m1 * top->v.x + m2 * low->v.x, m2 * v2.x, 1e-9);
    world_free(&w);
}

/* A world under gravity, frames of time_step, and a table (body 0) with its top
 * at z = 0.05 and its edge at x = 0.5. */
static void slider_world(world *w, double time_step)
{
    world_init(w);
    w->set.force = (dir_amount){v3(0, 0, -1), 9.8};
    w->set.time_step = time_step;
    add_static_box(w, "table", v3(0.5, 0.5, 0.05));
}

/* Frames until slider b (on body 0, the table) is past x_until: it slides on at
 * height z (within tol), and no pair is checked. */
static void slides_without_queries(world *w, const body *b, double x_until, double z, double tol)
{
    long checks = w->st.pair_checks;
    while (b->x.x < x_until) {
        frames(w, 1);
        assert_int_equal(b->mode, MODE_SLIDE);
        assert_int_equal(b->slide_on, 0);
        assert_true(fabs(b->x.z - z) <= tol);
        assert_int_equal(w->st.pair_checks, checks);
    }
}

/* A ball slides along a table at 1 m/s: flat while it is over the table (its
 * contact needs no check there), and off the edge it falls. */
static void slider_leaves_the_table_at_its_edge(void **state)
{
    (void)state;
    world w;
    slider_world(&w, 0.05);
    body *ball = add_ball(&w, "ball", 0.1);
    ball->elasticity = 0;
    ball->x = v3(-0.45, 0, 0.15 + 1e-6);
    ball->v = v3(1, 0, 0);
    frames(&w, 2);
    assert_int_equal(ball->mode, MODE_SLIDE);
    double z = ball->x.z;
    assert_near(z, 0.15, 1e-6);
    /* its centre over the table, where the face is nearest */
    slides_without_queries(&w, ball, 0.45, z, 0);
    frames(&w, 10); /* half a second later it has left the table */
    print_message("slider: at x %.3f z %.3f after the edge, mode %d\n", ball->x.x, ball->x.z, ball->mode);
    assert_int_equal(ball->mode, MODE_FREE);
    assert_true(ball->x.z < 0);
    assert_true(ball->x.x > 0.5);
    world_free(&w);
}

/* A box of half-edge 0.1 m, restitution 0, just over a table top at z = 0.05:
 * at x = -0.3, sliding at 1 m/s along x and turning at 2 rad/s about the vertical. */
static body *add_turning_slider(world *w)
{
    body *box = add_box(w, "box", v3(0.1, 0.1, 0.1));
    box->elasticity = 0;
    box->x = v3(-0.3, 0, 0.15 + 1e-6);
    box->v = v3(1, 0, 0);
    body_set_angular_vel(box, v3(0, 0, 2));
    return box;
}

/* A box sliding flat, turning about the vertical, needs no query while what it
 * stands on (its bottom face, within 0.1414 m of its centre however it turns)
 * is over the table, though its bounding sphere (0.1732 m) passes the edge first;
 * past the edge it tips and leaves. */
static void box_slides_to_the_edge_without_queries(void **state)
{
    (void)state;
    world w;
    slider_world(&w, 0.01);
    body *box = add_turning_slider(&w);
    frames(&w, 2);
    assert_int_equal(box->mode, MODE_SLIDE);
    slides_without_queries(&w, box, 0.345, 0.15, 1e-6); /* to x = 0.35: its footprint to 0.4914 */
    frames(&w, 60);
    assert_int_not_equal(box->mode, MODE_SLIDE);
    assert_true(box->x.z < 0);
    world_free(&w);
}

/* Objects added and deleted elsewhere leave a slide as it was: a box sliding and
 * turning on a table goes on sliding, with no collision, at the same height, its
 * support's index moved down when an object before it is deleted. */
static void slides_outlast_other_objects_coming_and_going(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    w.set.force = (dir_amount){v3(0, 0, -1), 9.8};
    w.set.time_step = 0.01;
    body *post = add_static_box(&w, "post", v3(0.1, 0.1, 1));
    post->x = v3(0, 5, 0);
    add_static_box(&w, "table", v3(0.5, 0.5, 0.05));
    body *box = add_turning_slider(&w);
    frames(&w, 2);
    assert_int_equal(box->mode, MODE_SLIDE);
    assert_int_equal(box->slide_on, 1);
    long hits = w.st.collisions;
    body *ball = add_ball(&w, "ball", 0.1); /* falling, far away */
    ball->x = v3(0, -5, 1);
    for (int k = 0; k < 5; k++) {
        frames(&w, 1);
        assert_int_equal(box->slide_on, 1);
        assert_near(box->x.z, 0.15, 1e-6);
    }
    world_delete(&w, 0); /* the post: the table is object 0 now */
    for (int k = 0; k < 5; k++) {
        frames(&w, 1);
        assert_int_equal(box->slide_on, 0);
        assert_near(box->x.z, 0.15, 1e-6);
    }
    assert_int_equal(w.st.collisions, hits);
    assert_true(box->x.x > -0.3 + 0.11);
    world_free(&w);
}

/* The sandwich's world, with no force: a wall with its face at x = 0.1
 * (restitution 0), a 1 kg box 1 cm from it arriving at 1 m/s (there at 10 ms),
 * and a 5 kg ball for the caller to aim. */
static void sandwich(world *w, body **box, body **ball)
{
    world_init(w);
    w->set.force = (dir_amount){v3(0, 0, -1), 0};
    w->set.time_step = 0.05;
    body *wall = add_static_box(w, "wall", v3(0.1, 1, 1));
    wall->elasticity = 0;
    *box = add_box(w, "box", v3(0.1, 0.1, 0.1));
    (*box)->elasticity = 0.5;
    (*box)->x = v3(0.2 + 0.01, 0, 0);
    (*box)->v = v3(-1, 0, 0);
    *ball = add_ball(w, "ball", 0.1);
    (*ball)->elasticity = 0.5;
    body_set_mass(*ball, 5);
}

/* The box strikes the wall and stops there; 5 ms later the heavy ball strikes
 * the box.  In the limit of vanishing gaps (instant.h) each blow on the box
 * (restitution 0.5) sends it into the wall, which stops it (0), and the ball,
 * five times heavier, comes on at 3/4 of its speed after each such pair of
 * waves: 2, 1.5, 1.125 m/s ... ever faster, ever smaller, never apart.  After 4 n
 * waves of n = 2 contacts the last solve with no restitution stops the ball
 * against the box against the wall: three collisions in all, the wall and the
 * box each taking the ball's momentum, 10 N s. */
static void sandwich_against_a_wall_passes_the_blow_on(void **state)
{
    (void)state;
    world w;
    body *box, *ball;
    sandwich(&w, &box, &ball);
    ball->x = v3(0.4 + 0.03, 0, 0); /* 3 cm from the box's far side, at 2 m/s: 15 ms */
    ball->v = v3(-2, 0, 0);
    frames(&w, 1);
    print_message("sandwich: %ld collisions, %ld instants cut, box v %.9f, ball v %.9f\n",
                  w.st.collisions, w.st.waves_cut, box->v.x, ball->v.x);
    assert_int_equal(w.st.collisions, 3);
    assert_int_equal(w.st.waves_cut, 1);
    assert_true(fabs(box->v.x) < 1e-12);
    assert_true(fabs(ball->v.x) < 1e-12);
    for (long k = 0; k < w.nevents; k++)
        if (w.events[k].t > 0.012) assert_near(w.events[k].j, 5 * 2, 1e-9);
    assert_near(box->x.x, 0.2, 1e-6);
    world_free(&w);
}

/* The same with the ball's blow 30 degrees off the wall's normal, on the box's
 * edge.  The wall pushes along its normal (x) only, and the box pushes the ball
 * along n only, so the momentum across the wall's normal is kept and the ball
 * moves along n throughout.  As head-on, the ball chases the box into the wall
 * wave after wave, and the last solve (no restitution) ends it: the box held by
 * the wall, the ball moving with it along n.  So the ball at b n and the box at
 * (0, B) with 5 b n_y + B = 5 (-2) n_y (momentum across) and b = B n_y (together
 * along n): B = -20/9, b = -10/9 m/s.  No energy is made. */
static void oblique_sandwich_passes_the_blow_on(void **state)
{
    (void)state;
    world w;
    body *box, *ball;
    sandwich(&w, &box, &ball);
    /* towards the box's edge at (0.3, 0.1), along n, 30 degrees off the wall's
     * normal: there 3 cm later, at 15 ms */
    const double pi = 3.14159265358979323846;
    vec3 n = v3(cos(pi / 6), sin(pi / 6), 0);
    ball->x = v3_add(v3(0.3, 0.1, 0), v3_scale(n, 0.1 + 0.03));
    ball->v = v3_scale(n, -2);
    frames(&w, 1);
    vec3 p = v3_add(v3_scale(box->v, box->mass), v3_scale(ball->v, ball->mass));
    double e1 = body_energy(box) + body_energy(ball), e0 = 0.5 * 5 * 4;
    print_message("oblique sandwich: %ld collisions, %ld instants cut, box v (%.3g, %.6f), ball v "
                  "(%.6f, %.6f), box w %.3g, momentum across %.9f, energy %.6f of %.6f\n",
                  w.st.collisions, w.st.waves_cut, box->v.x, box->v.y, ball->v.x, ball->v.y,
                  v3_len(box->w), p.y, e1, e0);
    assert_int_equal(w.st.waves_cut, 1);
    /* (to 1e-6: the box stands 1e-7 m off the wall after its own collision,
     * which turns the normal by 1e-6) */
    assert_true(fabs(box->v.x) < 1e-6);
    assert_near(box->v.y, -20.0 / 9, 1e-6);
    assert_vec_near(ball->v, v3_scale(n, -10.0 / 9), 1e-6);
    assert_near(p.y, 5 * -2 * n.y, 1e-9); /* momentum across the normal */
    assert_true(e1 <= e0 * (1 + 1e-12));
    world_free(&w);
}

static void ball_comes_to_rest_in_finite_time(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    w.set.force = (dir_amount){v3(0, 0, -1), 9.8};
    add_static_box(&w, "table", v3(1, 1, 0.05));
    body *ball = add_ball(&w, "ball", 0.1);
    ball->elasticity = 0.8;
    ball->x = v3(0, 0, 1.05);
    int f = 0;
    while (ball->state != STATE_RESTING && f < 200) {
        frames(&w, 1);
        f++;
    }
    /* bounces last 2 v0 / (g (1 - e)) = 4.04 s after a 0.45 s fall */
    print_message("ball e=0.8: resting after %d frames, %ld collisions, %ld pair checks\n", f,
                  w.st.collisions, w.st.pair_checks);
    assert_int_equal(ball->state, STATE_RESTING);
    assert_true(f <= 50);
    assert_true(w.st.pair_checks < 100000); /* no storm of micro-collisions */
    assert_near(ball->x.z, 0.05 + 0.1, 1e-4);
    long checks = w.st.pair_checks;
    frames(&w, 100); /* resting: no more work */
    assert_int_equal(w.st.pair_checks, checks);
    /* something hits it: it wakes */
    body *hit = add_ball(&w, "hit", 0.1);
    hit->x = v3(-1, 0, 0.15);
    hit->v = v3(3, 0, 0);
    frames(&w, 5);
    assert_true(ball->v.x > 1);
    world_free(&w);
}

static void newtons_cradle(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    body *ball[5];
    for (int i = 0; i < 5; i++) {
        char name[8];
        snprintf(name, sizeof name, "b%d", i);
        ball[i] = add(&w, name, SHAPE_SPHERE);
        ball[i]->sp.radius = 0.1;
        rebuild(ball[i]);
        ball[i]->x = v3(i * 0.201, 0, 1);
    }
    ball[0]->x.x = -0.5;
    ball[0]->v = v3(2, 0, 0);
    frames(&w, 10);
    for (int i = 0; i < 4; i++) assert_near(ball[i]->v.x, 0, 1e-6);
    assert_near(ball[4]->v.x, 2, 1e-6);
    assert_int_equal(w.st.collisions, 4);
    world_free(&w);
}

static void penetration_is_reported(void **state)
{
    (void)state;
    world w;
    world_init(&w);
    body *a = add(&w, "a", SHAPE_SPHERE), *b = add(&w, "b", SHAPE_CUBE);
    (void)a;
    b->x = v3(1.5, 0, 0);
    assert_int_equal(sim_penetrations(&w, NULL, NULL), 1);
    b->x = v3(2.5, 0, 0);
    assert_int_equal(sim_penetrations(&w, NULL, NULL), 0);
    world_free(&w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(head_on_unequal_masses),
        cmocka_unit_test(bounce_apex_is_e_squared_h),
        cmocka_unit_test(closed_system_conserves),
        cmocka_unit_test(off_centre_hit_conserves_momentum_about_a_point),
        cmocka_unit_test(nothing_passes_through_a_plate),
        cmocka_unit_test(box_dropped_flat_rests_flat),
        cmocka_unit_test(box_dropped_on_its_corner_settles),
        cmocka_unit_test(tilted_box_settles_keeping_what_contact_keeps),
        cmocka_unit_test(pillow_rocks_to_a_stop),
        cmocka_unit_test(drum_contact_region),
        cmocka_unit_test(box_turning_onto_its_edge_strikes_with_the_lower_end),
        cmocka_unit_test(rocking_block_finds_its_next_corner),
        cmocka_unit_test(stack_comes_to_rest),
        cmocka_unit_test(blow_on_a_stack_passes_to_the_floor),
        cmocka_unit_test(blow_on_a_slider_moves_it_along_the_floor),
        cmocka_unit_test(slider_leaves_the_table_at_its_edge),
        cmocka_unit_test(box_slides_to_the_edge_without_queries),
        cmocka_unit_test(slides_outlast_other_objects_coming_and_going),
        cmocka_unit_test(sandwich_against_a_wall_passes_the_blow_on),
        cmocka_unit_test(oblique_sandwich_passes_the_blow_on),
        cmocka_unit_test(ball_comes_to_rest_in_finite_time),
        cmocka_unit_test(newtons_cradle),
        cmocka_unit_test(penetration_is_reported),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
