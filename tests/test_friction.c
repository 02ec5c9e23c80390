/* test_friction.c: Coulomb friction (issue 36), each answer derived here.
 *
 * A spinning ball striking a rough floor leaves rolling at (5 v_t + 2 r w) / 7
 * when mu (1 + e) v_n >= (2/7) |slip|, else with v_t changed by mu (1 + e) v_n and
 * w by 5 mu (1 + e) v_n / (2 r); a rod striking a rough floor on one end matches
 * Mirtich's integration done here in small steps; 10,000 random impacts of
 * balls, boxes and rods (corner, edge and face landings) never raise the kinetic
 * energy; the cone solve keeps Coulomb's law at every point; a box launched
 * along its face's diagonal on a level floor slides along the diagonal and
 * stops where mu g says; a ball rolling on a floor slows at (5/7) c g (to 1e-6,
 * straight on), and comes to rest where it stops. */
#include "check.h"

#include <stdlib.h>
#include <string.h>

#include "core/body.h"
#include "core/friction.h"
#include "core/impulse.h"
#include "core/sim.h"
#include "core/world.h"
#include "worlds.h"

static const double G = 9.8;

/* Two bodies for a single impact: a (mobile) on a static floor b. */
typedef struct {
    world w;
    body *a, *floor;
    body *bs[2];
    bool mobile[2];
} pairw;

static void pair_init(pairw *p, body *a)
{
    p->a = a;
    p->floor = add_static_box(&p->w, "floor", v3(10, 10, 0.1));
    p->floor->x = v3(0, 0, -0.1);
    p->bs[0] = p->a;
    p->bs[1] = p->floor;
    p->mobile[0] = true;
    p->mobile[1] = false;
}

/* ---- a spinning ball ---- */

static void ball_case(double vn, double vt, double w, double e, double mu)
{
    pairw p;
    world_init(&p.w);
    const double r = 0.11, m = 0.7;
    body *ball = add_ball(&p.w, "ball", r);
    body_set_mass(ball, m);
    pair_init(&p, ball);
    ball->x = v3(0, 0, r);
    ball->v = v3(vt, 0, -vn);
    body_set_angular_vel(ball, v3(0, w, 0));
    impulse_row row = {.p = 0, .q = 1, .n = v3(0, 0, 1), .at = v3(0, 0, 0), .e = e, .mu = mu};
    double pn;
    friction_flags f = friction_impact(&row, p.bs, p.mobile, &pn);
    assert_false(f.painleve);
    /* the slip of the contact point: v + w x (-r z) */
    double s = vt - r * w, k = mu * (1 + e) * vn, vt2, w2;
    if (k >= 2.0 / 7.0 * fabs(s)) {
        vt2 = (5 * vt + 2 * r * w) / 7;
        w2 = vt2 / r;
    } else {
        double sg = s > 0 ? 1 : -1;
        vt2 = vt - sg * k;
        w2 = w + sg * 5 * k / (2 * r);
    }
    assert_rel(ball->v.x, vt2, 1e-9);
    assert_rel(ball->w.y, w2, 1e-9);
    assert_rel(ball->v.z, e * vn, 1e-9);
    assert_near(ball->v.y, 0, 1e-12);
    world_free(&p.w);
}

static void spinning_ball_strikes_a_rough_floor(void **state)
{
    (void)state;
    /* topspin (w > v / r), backspin (w < 0), rolling in and sliding through */
    double cases[][5] = {
        {2, 1, 20, 0.5, 0.3},   {2, 1, -20, 0.5, 0.3},  {2, 1, -20, 0.5, 0.05},
        {3, 0.5, 40, 0.8, 0.1}, {1, 2, -30, 0.2, 0.02}, {1.5, -1, 5, 1, 0.6},
        {2, 0, 0, 0.7, 0.4},    {0.5, 3, 0, 0.0, 0.1},  {0.5, 3, 0, 0.0, 1.2},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++)
        ball_case(cases[i][0], cases[i][1], cases[i][2], cases[i][3], cases[i][4]);
}

/* ---- a rod on one end, against Mirtich's integration done here ---- */

/* The rod of half-length a and half-thickness c (a box (a, c, c)) of mass m,
 * tilted by th about y, its lower end at the origin, moving at (vx, 0, vz) and
 * turning at wy: the planar impact integrated in steps of the normal impulse
 * (the slopes are constant between the slip's stop and the phases' ends, which
 * cut the steps).  Gives vx, vz, wy after. */
static void rod_by_steps(double a, double c, double m, double th, double vx, double vz, double wy,
                         double e, double mu, double out[3])
{
    double I = m * (a * a + c * c) / 3; /* about y, through the centre */
    /* the contact point relative to the centre: the lower end, at the middle of
     * its end face's lower edge */
    double rx = -(a * cos(th) - c * sin(th)), rz = -(a * sin(th) + c * cos(th));
    /* u = v + w x r in the plane: ux = vx + wy rz, uz = vz - wy rx */
    const int N = 1000;
    double scale = -(vz - wy * rx) * m, h = 4 * scale / N;
    double W = 0, Wc = 0;
    bool comp = true;
    for (int i = 0; i < 40 * N; i++) {
        double ux = vx + wy * rz, uz = vz - wy * rx;
        if (comp && uz >= 0) {
            comp = false;
            Wc = W;
            if (e == 0) break;
        }
        if (!comp && W >= (1 - e * e) * Wc * (1 + 1e-14) - 1e-300) break;
        /* the tangential impulse per normal impulse: against the slip, or what
         * keeps it stuck when that lies in the cone */
        double ft;
        /* an impulse (Px, Pz) turns it by (rz Px - rx Pz) / I: dux/dPz, dux/dPx,
         * duz/dPz, duz/dPx */
        double kxn = -rz * rx / I, kxx = 1 / m + rz * rz / I;
        double kzn = 1 / m + rx * rx / I, kzx = -rx * rz / I;
        if (fabs(ux) < 1e-12) {
            double stick = -kxn / kxx;
            ft = fabs(stick) <= mu ? stick : (stick > 0 ? mu : -mu);
        } else {
            ft = ux > 0 ? -mu : mu;
        }
        double dux = kxn + kxx * ft, duz = kzn + kzx * ft;
        double hh = h;
        /* the slip stopping within the step */
        if (fabs(ux) >= 1e-12 && ux * (ux + dux * hh) < 0) hh = -ux / dux;
        if (comp && uz + duz * hh > 0) hh = d_min(hh, -uz / duz);
        double target = (1 - e * e) * Wc;
        if (!comp && W + (uz + 0.5 * duz * hh) * hh > target) {
            double r1, r2;
            if (quad_roots(0.5 * duz, uz, W - target, &r1, &r2)) hh = d_min(hh, r1 >= 0 && (r1 < r2 || r2 < 0) ? r1 : r2);
        }
        W += (uz + 0.5 * duz * hh) * hh;
        vx += (ft * hh) / m;
        vz += hh / m;
        wy += (rz * ft * hh - rx * hh) / I;
    }
    out[0] = vx;
    out[1] = vz;
    out[2] = wy;
}

static void rod_case(double th, double vx, double vz, double wy, double e, double mu)
{
    pairw p;
    world_init(&p.w);
    const double a = 0.5, c = 0.02, m = 1.3;
    body *rod = add_box(&p.w, "rod", v3(a, c, c));
    body_set_mass(rod, m);
    pair_init(&p, rod);
    body_set_rotation(rod, v3(0, 1, 0), -th); /* its -x end down */
    double rx = -(a * cos(th) - c * sin(th)), rz = -(a * sin(th) + c * cos(th));
    rod->x = v3(-rx, 0, -rz);
    rod->v = v3(vx, 0, vz);
    body_set_angular_vel(rod, v3(0, wy, 0));
    impulse_row row = {.p = 0, .q = 1, .n = v3(0, 0, 1), .at = v3(0, 0, 0), .e = e, .mu = mu};
    double pn, want[3];
    friction_impact(&row, p.bs, p.mobile, &pn);
    rod_by_steps(a, c, m, th, vx, vz, wy, e, mu, want);
    double scale = fabs(vz) + fabs(vx) + fabs(wy) * a;
    assert_near(rod->v.x, want[0], 1e-5 * scale);
    assert_near(rod->v.z, want[1], 1e-5 * scale);
    assert_near(rod->w.y * a, want[2] * a, 1e-5 * scale);
    world_free(&p.w);
}

static void rod_strikes_a_rough_floor(void **state)
{
    (void)state;
    double th[] = {0.3, 0.7, 1.0, 1.3};
    for (size_t i = 0; i < 4; i++) {
        rod_case(th[i], 1.0, -2.0, 0, 0.5, 0.4);
        rod_case(th[i], -0.5, -1.5, 3, 0.8, 0.9);
        rod_case(th[i], 0.2, -3.0, -2, 0.0, 0.2);
        rod_case(th[i], 2.0, -1.0, 1, 1.0, 1.2);
    }
}

/* ---- energy never rises ---- */

static void ten_thousand_impacts_never_raise_energy(void **state)
{
    (void)state;
    unsigned long long seed = 36;
    world w;
    world_init(&w);
    body *floor = add_static_box(&w, "floor", v3(10, 10, 0.1));
    floor->x = v3(0, 0, -0.1);
    body *shapes[3];
    shapes[0] = add_ball(&w, "ball", 0.1);
    shapes[1] = add_box(&w, "box", v3(0.1, 0.15, 0.2));
    shapes[2] = add_box(&w, "rod", v3(0.6, 0.02, 0.03));
    int cuts = 0;
    for (int i = 0; i < 10000; i++) {
        body *b = shapes[i % 3];
        body *bs[2] = {b, floor};
        bool mobile[2] = {true, false};
        int land = (i / 3) % 3; /* corner, edge, face */
        if (b->sp.kind == SHAPE_SPHERE) land = 0;
        quat q = q_axis_angle(v3_norm(v3(urand(&seed, -1, 1), urand(&seed, -1, 1), urand(&seed, -1, 1))),
                              urand(&seed, 0, 6.3));
        if (land == 1) q = q_axis_angle(v3(1, 0, 0), urand(&seed, -1.5, 1.5));
        if (land == 2) q = q_axis_angle(v3(0, 0, 1), urand(&seed, 0, 6.3));
        b->q = q;
        b->rot_given = false;
        b->x = v3(0, 0, 1);
        b->v = v3(urand(&seed, -3, 3), urand(&seed, -3, 3), urand(&seed, -5, -0.1));
        body_set_angular_vel(b, v3(urand(&seed, -20, 20), urand(&seed, -20, 20), urand(&seed, -20, 20)));
        double e = urand(&seed, 0, 1), mu = urand(&seed, 0, 1.3);
        /* the rows: the lowest corner, or the corners within 1e-9 of it */
        impulse_row rows[8];
        int nr = 0;
        if (b->sp.kind == SHAPE_SPHERE) {
            rows[nr++] = (impulse_row){.p = 0, .q = 1, .n = v3(0, 0, 1), .at = v3(0, 0, 1 - 0.1), .e = e, .mu = mu};
        } else {
            vec3 s = b->sp.size, c[8];
            double low = HUGE_VAL;
            for (int k = 0; k < 8; k++) {
                c[k] = v3_add(b->x, q_rotate(q, v3(k & 1 ? s.x : -s.x, k & 2 ? s.y : -s.y, k & 4 ? s.z : -s.z)));
                low = d_min(low, c[k].z);
            }
            for (int k = 0; k < 8; k++)
                if (c[k].z <= low + 1e-9 * (1 + fabs(low)))
                    rows[nr++] = (impulse_row){.p = 0, .q = 1, .n = v3(0, 0, 1), .at = c[k], .e = e, .mu = mu};
        }
        /* approaching at one point at least */
        bool in = false;
        for (int k = 0; k < nr; k++) in = in || impulse_speed(&rows[k], bs) < 0;
        if (!in) continue;
        double ke0 = body_energy(b), lam[8];
        if (nr == 1) {
            double pn;
            friction_flags f = friction_impact(&rows[0], bs, mobile, &pn);
            cuts += f.energy_cut;
        } else {
            static friction_work fw;
            friction_flags f = {false, false, false};
            double u[8];
            for (int k = 0; k < nr; k++) u[k] = impulse_speed(&rows[k], bs);
            assert_int_equal(friction_compress(rows, nr, bs, mobile, u, lam, &fw, &f), 0);
            friction_restitute(rows, nr, bs, mobile, lam, ke0, &fw, &f);
            cuts += f.energy_cut;
        }
        double ke1 = body_energy(b);
        if (!(ke1 <= ke0 * (1 + 1e-12)))
            fail_msg("impact %d (%s, %d rows, e %g, mu %g): energy %.17g -> %.17g", i, b->name, nr, e, mu,
                     ke0, ke1);
    }
    print_message("10,000 impacts: restitution scaled down in %d\n", cuts);
    world_free(&w);
}

/* ---- the cone solve keeps Coulomb's law ---- */

static void cone_solve_keeps_coulombs_law(void **state)
{
    (void)state;
    unsigned long long seed = 7;
    world w;
    world_init(&w);
    body *floor = add_static_box(&w, "floor", v3(10, 10, 0.1));
    floor->x = v3(0, 0, -0.1);
    body *box = add_box(&w, "box", v3(0.3, 0.2, 0.1));
    box->x = v3(0, 0, 0.1);
    body *bs[2] = {box, floor};
    bool mobile[2] = {true, false};
    static friction_work fw;
    for (int i = 0; i < 200; i++) {
        double mu = urand(&seed, 0, 1.3);
        impulse_row rows[4];
        for (int k = 0; k < 4; k++)
            rows[k] = (impulse_row){.p = 0, .q = 1, .n = v3(0, 0, 1),
                                    .at = v3(k & 1 ? 0.3 : -0.3, k & 2 ? 0.2 : -0.2, 0), .mu = mu};
        box->v = v3(urand(&seed, -2, 2), urand(&seed, -2, 2), urand(&seed, -2, -0.1));
        body_set_angular_vel(box, v3(urand(&seed, -3, 3), urand(&seed, -3, 3), urand(&seed, -3, 3)));
        friction_rows(rows, 4, fw.rows);
        impulse_matrix(fw.rows, 12, bs, mobile, fw.A);
        for (int k = 0; k < 12; k++) fw.q[k] = impulse_speed(&fw.rows[k], bs), fw.z[k] = 0;
        for (int k = 0; k < 4; k++) fw.mu[k] = mu;
        bool jam = false;
        int st = friction_cone_solve(4, fw.A, fw.q, fw.mu, fw.z, fw.w, &jam);
        assert_true(st >= 0);
        double scale = 0;
        for (int k = 0; k < 12; k++) scale = d_max(scale, fabs(fw.q[k]));
        double tol = st == 0 ? 1e-9 * scale : 1e-5 * scale;
        for (int k = 0; k < 4; k++) {
            double zn = fw.z[3 * k], zt = hypot(fw.z[3 * k + 1], fw.z[3 * k + 2]);
            double wn = fw.w[3 * k], wt = hypot(fw.w[3 * k + 1], fw.w[3 * k + 2]);
            assert_true(zn >= 0);
            if (!(wn >= -tol)) fail_msg("case %d st %d point %d: wn %g tol %g", i, st, k, wn, tol);
            assert_true(zn * wn <= tol * (zn + 1e-300) || zn == 0);
            assert_true(zt <= mu * zn * (1 + 1e-9) + 1e-300);
            if (wt > tol) { /* sliding: on the cone's edge, against the slip */
                assert_near(zt, mu * zn, 1e-6 * (mu * zn) + 1e-15);
                if (zt > 0) {
                    double dot = (fw.z[3 * k + 1] * fw.w[3 * k + 1] + fw.z[3 * k + 2] * fw.w[3 * k + 2]) / (zt * wt);
                    assert_near(dot, -1, st == 0 ? 1e-6 : 1e-5);
                }
            }
        }
    }
    world_free(&w);
}

/* ---- the cone solve in blocks (crowds) ---- */

/* Balls of radius 0.05 touching in a grid of nx by ny by nz (along x, y, z, on a
 * floor at z = 0, between walls square to x when walls; without walls, its
 * rows along y apart), each moving at random:
 * their points into rows (room for max), the bodies into bs and mobile.
 * Returns the points. */
static int ball_grid(world *w, int nx, int ny, int nz, bool walls, double mu, unsigned long long *seed,
                     impulse_row *rows, int max, body **bs, bool *mobile)
{
    const double r = 0.05;
    world_init(w);
    body *floor = add_static_box(w, "floor", v3(10, 10, 0.1));
    floor->x = v3(0, 0, -0.1);
    body *east = add_static_box(w, "east", v3(0.1, 10, 10));
    east->x = v3(nx * 2 * r + 0.1, 0, 0);
    body *west = add_static_box(w, "west", v3(0.1, 10, 10));
    west->x = v3(-0.1, 0, 0);
    int nb = 3, m = 0;
    for (int k = 0; k < 3; k++) bs[k] = w->bodies[k], mobile[k] = false;
    for (int i = 0; i < nx; i++)
        for (int j = 0; j < ny; j++)
            for (int k = 0; k < nz; k++) {
                body *b = add_ball(w, "b", r);
                b->x = v3(r + (walls ? 2 : 3) * r * i, r + 2 * r * j, r + 2 * r * k);
                b->v = v3(urand(seed, -1, 1), urand(seed, -1, 1), urand(seed, -1, 0.5));
                body_set_angular_vel(b, v3(urand(seed, -9, 9), urand(seed, -9, 9), urand(seed, -9, 9)));
                bs[nb] = b, mobile[nb] = true;
                nb++;
            }
    /* (ball (i, j, k) is body 3 + (i ny + j) nz + k) */
    for (int i = 0; i < nx; i++)
        for (int j = 0; j < ny; j++)
            for (int k = 0; k < nz; k++) {
                int me = 3 + (i * ny + j) * nz + k;
                vec3 c = bs[me]->x;
                if (k == 0) rows[m++] = (impulse_row){.p = me, .q = 0, .n = v3(0, 0, 1), .at = v3(c.x, c.y, 0), .mu = mu};
                if (walls && i == 0)
                    rows[m++] = (impulse_row){.p = me, .q = 2, .n = v3(1, 0, 0), .at = v3(0, c.y, c.z), .mu = mu};
                if (walls && i == nx - 1)
                    rows[m++] = (impulse_row){.p = me, .q = 1, .n = v3(-1, 0, 0), .at = v3(c.x + r, c.y, c.z), .mu = mu};
                if (walls && i > 0) rows[m++] = (impulse_row){.p = me, .q = me - ny * nz, .n = v3(1, 0, 0), .at = v3(c.x - r, c.y, c.z), .mu = mu};
                if (j > 0) rows[m++] = (impulse_row){.p = me, .q = me - nz, .n = v3(0, 1, 0), .at = v3(c.x, c.y - r, c.z), .mu = mu};
                if (k > 0) rows[m++] = (impulse_row){.p = me, .q = me - 1, .n = v3(0, 0, 1), .at = v3(c.x, c.y, c.z - r), .mu = mu};
                assert_true(m <= max);
            }
    return m;
}

/* Coulomb's law at the m points of z, w (3m each) within tol (the velocities'),
 * and maximal dissipation where a point slides within dot_tol. */
static void check_cones(int m, const double *z, const double *w, const double *mu, double tol,
                        double dot_tol, const char *what)
{
    for (int k = 0; k < m; k++) {
        double zn = z[3 * k], zt = hypot(z[3 * k + 1], z[3 * k + 2]);
        double wn = w[3 * k], wt = hypot(w[3 * k + 1], w[3 * k + 2]);
        if (!(zn >= 0)) fail_msg("%s point %d: zn %g", what, k, zn);
        if (!(wn >= -tol)) fail_msg("%s point %d: wn %g tol %g", what, k, wn, tol);
        if (zn > 0 && !(fabs(wn) <= tol)) fail_msg("%s point %d: zn %g wn %g (tol %g)", what, k, zn, wn, tol);
        if (!(zt <= mu[k] * zn * (1 + 1e-9) + 1e-300)) fail_msg("%s point %d: zt %g > mu zn %g", what, k, zt, mu[k] * zn);
        if (wt > tol && zn > 0) { /* sliding: on the cone's edge, against the slip */
            if (!(fabs(zt - mu[k] * zn) <= 1e-6 * mu[k] * zn))
                fail_msg("%s point %d: slides at %g (tol %g) with zt %g < mu zn %g", what, k, wt, tol, zt, mu[k] * zn);
            double dot = (z[3 * k + 1] * w[3 * k + 1] + z[3 * k + 2] * w[3 * k + 2]) / (zt * wt);
            if (!(fabs(dot + 1) <= dot_tol)) fail_msg("%s point %d: slip against friction %g", what, k, dot);
        }
    }
}

/* The blocks' solve answers as the dense one where both apply: three rows of 8
 * balls on a rough floor, each touching the next, 45 points, moving and
 * turning at random, mu from 0.05 to 0.3 (with mu up to 1, the problem may
 * have more than one answer: in one case of 20 both solves kept Coulomb's law
 * with velocities 0.4% apart).  The velocities w are compared (where the dense solve
 * converged), not the impulses z: where rows are dependent (a ball's spin
 * about the vertical is met at its floor and at its neighbours), many z give
 * the same w. */
static void cone_solve_in_blocks_matches_dense(void **state)
{
    (void)state;
    unsigned long long seed = 11;
    static friction_work fw;
    static impulse_row rows[FRICTION_MAX_POINTS];
    body *bs[64];
    bool mobile[64];
    int unconverged = 0, compared = 0;
    for (int trial = 0; trial < 20; trial++) {
        world w;
        double mu = urand(&seed, 0.05, 0.3);
        int m = ball_grid(&w, 3, 8, 1, false, mu, &seed, rows, FRICTION_MAX_POINTS, bs, mobile);
        assert_int_equal(m, 45);
        friction_crowd *c = &fw.crowd;
        friction_rows(rows, m, fw.rows);
        impulse_matrix(fw.rows, 3 * m, bs, mobile, fw.A);
        assert_int_equal(friction_crowd_matrix(c, rows, m, bs, mobile), 0);
        int n = 3 * m;
        /* the blocks hold the dense matrix's nonzeros, to the bit */
        double *y = malloc(sizeof *y * (size_t)n), *x = malloc(sizeof *x * (size_t)n);
        assert_non_null(y);
        assert_non_null(x);
        for (int j = 0; j < n; j++) {
            for (int i = 0; i < n; i++) x[i] = i == j;
            friction_crowd_mulv(c, m, x, y);
            for (int i = 0; i < n; i++)
                if (y[i] != fw.A[i * n + j]) fail_msg("A[%d][%d] %.17g, blocks %.17g", i, j, fw.A[i * n + j], y[i]);
        }
        for (int i = 0; i < n; i++) c->q[i] = fw.q[i] = impulse_speed(&fw.rows[i], bs), c->z[i] = fw.z[i] = 0;
        for (int k = 0; k < m; k++) c->mu[k] = fw.mu[k] = mu;
        bool jam = false;
        int sd = friction_cone_solve(m, fw.A, fw.q, fw.mu, fw.z, fw.w, &jam);
        int ss = friction_crowd_solve(c, m, FRICTION_CROWD_SWEEPS, 0, &jam);
        assert_true(sd >= 0 && ss >= 0);
        unconverged += ss > 0;
        double scale = 0;
        for (int i = 0; i < n; i++) scale = d_max(scale, fabs(fw.q[i]));
        check_cones(m, c->z, c->w, c->mu, 1e-9 * scale, 1e-6, "rows of 8");
        if (sd == 0) check_cones(m, fw.z, fw.w, fw.mu, 1e-9 * scale, 1e-6, "rows of 8, dense");
        for (int i = 0; i < n && sd == 0; i++) {
            if (!(fabs(c->w[i] - fw.w[i]) <= 1e-8 * scale))
                fail_msg("trial %d row %d: w %.17g dense, %.17g blocks", trial, i, fw.w[i], c->w[i]);
        }
        compared += sd == 0;
        free(x);
        free(y);
        world_free(&w);
    }
    print_message("rows of 8 balls, 20 cases: the blocks' solve unconverged in %d, compared with the dense "
                  "one in %d\n", unconverged, compared);
    assert_true(compared >= 10);
    assert_int_equal(unconverged, 0);
    friction_work_free(&fw);
}

/* Coulomb's law over a crowd: 100 balls in four layers of 25 in a slot between
 * rough walls, on a rough floor (396 points, past FRICTION_MAX_POINTS), moving
 * and turning at random, answered by friction_compress: every point in its
 * cone, apart or pressing, and sliding against its slip; the velocities after
 * are the solve's, and no energy is made.  (Thrown about at random, they do not
 * converge to FRICTION_TOL within FRICTION_CROWD_SWEEPS: the law is checked
 * then to 1e-6 of the speeds.) */
static void cone_solve_in_blocks_keeps_coulombs_law(void **state)
{
    (void)state;
    unsigned long long seed = 5;
    static friction_work fw;
    enum { MAX = 400, BODIES = 103 };
    static impulse_row rows[MAX];
    body *bs[BODIES];
    bool mobile[BODIES];
    for (int trial = 0; trial < 3; trial++) {
        world w;
        double mu = urand(&seed, 0.1, 1);
        int m = ball_grid(&w, 1, 25, 4, true, mu, &seed, rows, MAX, bs, mobile);
        assert_int_equal(m, 396);
        double lam[MAX], u[MAX], ke0 = friction_energy(rows, m, bs, mobile);
        for (int k = 0; k < m; k++) u[k] = impulse_speed(&rows[k], bs);
        friction_flags f = {false, false, false};
        assert_int_equal(friction_compress(rows, m, bs, mobile, u, lam, &fw, &f), 0);
        friction_problem P = friction_problem_of(&fw, m);
        double scale = 0;
        for (int i = 0; i < 3 * m; i++) scale = d_max(scale, fabs(P.q[i]));
        /* the velocities after, read afresh from the bodies, are w */
        for (int i = 0; i < 3 * m; i++) assert_near(impulse_speed(&P.rows[i], bs), P.w[i], 1e-9 * scale);
        check_cones(m, P.z, P.w, P.mu, (f.unconverged ? 1e-6 : 1e-9) * scale, 1e-5, "100 balls");
        assert_true(friction_energy(rows, m, bs, mobile) <= ke0);
        print_message("100 balls, 396 points, mu %.2f: %s\n", mu, f.unconverged ? "unconverged" : "converged");
        world_free(&w);
    }
    friction_work_free(&fw);
}

/* ---- stepped contact ---- */

static void frames(world *w, int n)
{
    char err[256];
    for (int i = 0; i < n; i++) assert_int_equal(sim_frame(w, err, sizeof err), 0);
}

/* w, a world under gravity with fast speed limits and frames of time_step: a
 * level floor (its top at z = 0, half as wide as `half`) of friction mu and
 * rolling resistance c. */
static void rough_floor(world *w, double half, double mu, double c, double time_step)
{
    world_init(w);
    w->set.force = (dir_amount){v3(0, 0, -1), G};
    w->set.max_linear = 50;
    w->set.max_angular = 100;
    w->set.time_step = time_step;
    body *floor = add_static_box(w, "floor", v3(half, half, 0.1));
    floor->x = v3(0, 0, -0.1);
    floor->friction = mu;
    floor->rolling_friction = c;
}

/* A box launched along its face's diagonal slides along it, decelerating at
 * mu g, and stops where u^2 / (2 mu g) says. */
static void box_slides_along_the_diagonal(void **state)
{
    (void)state;
    double yaws[] = {0, 0.4, -1.1};
    for (int y = 0; y < 3; y++) {
        world w;
        rough_floor(&w, 10, 0.4, 0, 0.05);
        body *box = add_box(&w, "box", v3(0.2, 0.2, 0.1));
        box->friction = 0.4;
        box->elasticity = 0;
        body_set_rotation(box, v3(0, 0, 1), yaws[y]);
        box->x = v3(0, 0, 0.1 + 1e-9);
        vec3 d = q_rotate(box->q, v3_norm(v3(1, 1, 0)));
        double u = 1.5, mu = 0.4;
        box->v = v3_scale(d, u);
        frames(&w, 2); /* 0.1 s: still sliding */
        double t = w.time;
        vec3 v = box->v;
        double along = v3_dot(v, d), off = v3_len(v3_mad(v3(v.x, v.y, 0), d, -along));
        /* (to 1e-5: the cone solve stops short of 1e-12 on a face's four
         * corners, and stats counts it) */
        assert_near(off, 0, 1e-5 * u);
        assert_near(along, u - mu * G * t, 2e-3 * u);
        frames(&w, 10);
        vec3 moved = box->x;
        double s = v3_dot(moved, d), soff = v3_len(v3_mad(v3(moved.x, moved.y, 0), d, -s));
        assert_near(soff, 0, 1e-5);
        assert_near(s, u * u / (2 * mu * G), 5e-3 * s);
        assert_int_equal(box->state, STATE_RESTING);
        world_free(&w);
    }
}

/* A solid ball rolling on a level floor slows at (5/7) c g. */
static void ball_rolls_and_slows_at_five_sevenths_c_g(void **state)
{
    (void)state;
    world w;
    rough_floor(&w, 50, 0.5, 0.02, 0.1);
    body *ball = add_ball(&w, "ball", 0.1);
    ball->friction = 0.5;
    ball->rolling_friction = 0.02;
    ball->elasticity = 0;
    ball->x = v3(0, 0, 0.1 + 1e-9);
    ball->v = v3(2, 0, 0);
    body_set_angular_vel(ball, v3(0, 20, 0)); /* rolling: v = w r */
    frames(&w, 2);
    double t1 = w.time, v1 = ball->v.x;
    frames(&w, 10);
    double t2 = w.time, v2 = ball->v.x, c = 0.02;
    double a = (v1 - v2) / (t2 - t1);
    double want = 5.0 / 7.0 * c * G;
    print_message("rolling ball: slows at %.9f (want %.9f)\n", a, want);
    assert_rel(a, want, 1e-6);
    assert_rel(ball->w.y * 0.1, ball->v.x, 1e-9);
    assert_true(fabs(ball->x.y) < 1e-12); /* straight on */
    /* it stops v2^2 / (2 a) further on, and rests there (the frame rule rests
     * it once it is slower than SIM_REST_SPEED: up to that speed's stopping
     * distance short of it) */
    double x2 = ball->x.x, stop = x2 + v2 * v2 / (2 * want);
    frames(&w, 150);
    assert_int_equal(ball->state, STATE_RESTING);
    double short_by = SIM_REST_SPEED * SIM_REST_SPEED / (2 * want);
    print_message("rolling ball: rests at %.9f (stops at %.9f)\n", ball->x.x, stop);
    assert_true(ball->x.x <= stop + 1e-9 && ball->x.x >= stop - short_by - 1e-9);
    world_free(&w);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(spinning_ball_strikes_a_rough_floor),
        cmocka_unit_test(rod_strikes_a_rough_floor),
        cmocka_unit_test(ten_thousand_impacts_never_raise_energy),
        cmocka_unit_test(cone_solve_keeps_coulombs_law),
        cmocka_unit_test(cone_solve_in_blocks_matches_dense),
        cmocka_unit_test(cone_solve_in_blocks_keeps_coulombs_law),
        cmocka_unit_test(box_slides_along_the_diagonal),
        cmocka_unit_test(ball_rolls_and_slows_at_five_sevenths_c_g),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
