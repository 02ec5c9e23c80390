/* bench_closest.c: how fast closest features are tracked (closest.c, thesis 3.2.1).
 *
 * Two superquadrics (the thesis's defaults: exponents 1, radii 1) at 10x10, 20x20
 * and 40x40 move coherently: A spins, B orbits it at a gap between 0.05 and 0.35
 * while spinning the other way, 0.01 rad a step (a 4000-step loop of poses).  Each
 * pose is queried from the pair's cached features (the simulation's case) and from
 * scratch (no cache: the walk starts from support vertices found by hill climbing,
 * itself sublinear).  For reference, "cold" starts every query from vertex 0 of each
 * (V-Clip's from-scratch start).  Prints queries/s, the median of 3 runs of about
 * `seconds` each, the mean walk lengths and the time ratios; then the same for other
 * pairs of primitives.  Goal (issue 4): cached costs the same at 10x10 and 40x40
 * within 1.5x, and at least 5x less than scratch at 40x40.  Then two polyhedra as
 * files give them (issue 39): the hulls of 100 and of 5,000 points spread over a
 * sphere (a Fibonacci lattice, every point on the hull); goal: cached within 1.5x
 * of each other.
 *
 *   build/bench/bench_closest [seconds per run]
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"

#include "core/closest.h"
#include "core/shape.h"

#define RUNS 3
#define POSES 4000

/* A shape with its closest data (built here when shape_build does not attach it). */
typedef struct {
    shape s;
    bool own;
} bshape;

static int bshape_build(bshape *b, shape_params p)
{
    char err[256];
    if (shape_build(&b->s, &p, err, sizeof err) != 0) {
        fprintf(stderr, "bench_closest: %s\n", err);
        return -1;
    }
    b->own = b->s.hull && !b->s.feat;
    if (b->own) b->s.feat = closest_hull_new(b->s.hull);
    return 0;
}

static void bshape_free(bshape *b)
{
    if (b->own) {
        closest_hull_free(b->s.feat);
        b->s.feat = NULL;
    }
    shape_free(&b->s);
}

typedef struct {
    closest_proxy a[POSES], b[POSES];
} motion;

/* B orbits A with the gap swinging between 0.05 and 0.35 (outer radii apart). */
static void make_motion(motion *m, const shape *sa, const shape *sb)
{
    double ra = sa->r_out, rb = sb->r_out;
    vec3 wa = v3_norm(v3(0.3, 1, 0.2)), wb = v3_norm(v3(-1, 0.4, 0.5));
    vec3 orbit = v3_norm(v3(0.1, 0.2, 1));
    for (int i = 0; i < POSES; i++) {
        double th = 0.01 * i;
        double gap = 0.2 + 0.15 * sin(0.5 * th);
        vec3 dir = q_rotate(q_axis_angle(orbit, 0.3 * th), v3(1, 0, 0));
        m->a[i] = shape_proxy(sa, v3(0, 0, 0), q_axis_angle(wa, th));
        m->b[i] = shape_proxy(sb, v3_scale(dir, ra + rb + gap), q_axis_angle(wb, -0.7 * th));
    }
}

typedef struct {
    double rate;  /* queries per second */
    double steps; /* mean walk length */
    long restarts;
} bench_out;

static volatile double g_sink;

enum { CACHED, SCRATCH, COLD };

/* Queries per second over the motion, median of RUNS. */
static bench_out run(const motion *m, int mode, double seconds)
{
    double rates[RUNS];
    bench_out out = {0, 0, 0};
    for (int r = 0; r < RUNS; r++) {
        closest_cache cache = {0};
        long n = 0, steps = 0;
        double t0 = now(), t = t0;
        int i = 0;
        while (t - t0 < seconds) {
            for (int k = 0; k < 256; k++, n++) {
                if (mode == COLD)
                    cache = (closest_cache){{CLOSEST_VERTEX, 0}, {CLOSEST_VERTEX, 0}, true};
                closest_cache *c = mode == SCRATCH ? NULL : &cache;
                closest_result res = closest_distance(&m->a[i], &m->b[i], c);
                g_sink += res.distance;
                steps += res.steps;
                out.restarts += res.restarted;
                if (++i == POSES) i = 0;
            }
            t = now();
        }
        rates[r] = (double)n / (t - t0);
        out.steps = (double)steps / (double)n;
    }
    qsort(rates, RUNS, sizeof rates[0], cmp_double);
    out.rate = rates[RUNS / 2];
    return out;
}

static int bench_pair(const char *label, shape_params pa, shape_params pb, double seconds,
                      double *cached_rate)
{
    bshape a, b;
    if (bshape_build(&a, pa) != 0) return -1;
    if (bshape_build(&b, pb) != 0) {
        bshape_free(&a);
        return -1;
    }
    motion *m = malloc(sizeof *m);
    if (!m) return -1;
    make_motion(m, &a.s, &b.s);
    bool polys = pa.kind != SHAPE_SPHERE && pb.kind != SHAPE_SPHERE;
    bench_out c = run(m, CACHED, seconds), s = run(m, SCRATCH, seconds);
    bench_out k = polys ? run(m, COLD, seconds) : s;
    printf("closest  %-22s cached %9.0f queries/s  scratch %9.0f queries/s  "
           "(scratch/cached %.1fx; cold %9.0f queries/s, %.1fx; walk steps %.2f / %.2f / %.2f; "
           "restarts %ld)\n",
           label, c.rate, s.rate, c.rate / s.rate, k.rate, c.rate / k.rate, c.steps, s.steps,
           k.steps, c.restarts + s.restarts + k.restarts);
    fflush(stdout);
    if (cached_rate) *cached_rate = c.rate;
    free(m);
    bshape_free(&a);
    bshape_free(&b);
    return 0;
}

/* A polyhedron's source of n points over the unit sphere (Fibonacci lattice), no
 * faces: its hull is drawn. */
static void source_release(shape_source *src)
{
    free(src->pts);
    free(src);
}

static shape_source *sphere_points(int n)
{
    shape_source *src = calloc(1, sizeof *src);
    if (!src || !(src->pts = malloc((size_t)n * sizeof *src->pts))) {
        free(src);
        return NULL;
    }
    src->np = n;
    src->release = source_release;
    const double golden = 3.14159265358979323846 * (3 - sqrt(5));
    for (int i = 0; i < n; i++) {
        double z = 1 - (2 * i + 1.0) / n, r = sqrt(1 - z * z);
        src->pts[i] = v3(r * cos(golden * i), r * sin(golden * i), z);
    }
    return src;
}

int main(int argc, char **argv)
{
    double seconds = argc > 1 ? atof(argv[1]) : 0.5;
    if (!(seconds > 0)) seconds = 0.5;
    int res[3] = {10, 20, 40};
    double rate[3] = {0, 0, 0};
    for (int i = 0; i < 3; i++) {
        shape_params p = shape_defaults(SHAPE_SUPERQUADRIC);
        p.ures = p.vres = res[i];
        char label[64];
        snprintf(label, sizeof label, "superquadric %dx%d", res[i], res[i]);
        if (bench_pair(label, p, p, seconds, &rate[i]) != 0) return 1;
    }
    printf("closest  cached time 40x40 / 10x10: %.2f (goal <= 1.5)\n", rate[0] / rate[2]);

    shape_params sq = shape_defaults(SHAPE_SUPERQUADRIC), box = shape_defaults(SHAPE_CUBE);
    shape_params ball = shape_defaults(SHAPE_SPHERE);
    sq.ures = sq.vres = 40;
    sq.exp1 = 0.5;
    sq.exp2 = 1.5;
    if (bench_pair("sq e.5,1.5 40x40", sq, sq, seconds, NULL) != 0) return 1;
    if (bench_pair("cube cube", box, box, seconds, NULL) != 0) return 1;
    if (bench_pair("sphere superquadric 40", ball, sq, seconds, NULL) != 0) return 1;
    if (bench_pair("sphere cube", ball, box, seconds, NULL) != 0) return 1;
    if (bench_pair("sphere sphere", ball, ball, seconds, NULL) != 0) return 1;

    int np[2] = {100, 5000};
    double prate[2] = {0, 0};
    for (int i = 0; i < 2; i++) {
        shape_source *src = sphere_points(np[i]);
        if (!src) return 1;
        shape_params p = shape_defaults(SHAPE_POLYHEDRON);
        p.src = src;
        char label[64];
        snprintf(label, sizeof label, "polyhedron %d points", np[i]);
        int rc = bench_pair(label, p, p, seconds, &prate[i]);
        shape_source_release(src);
        if (rc != 0) return 1;
    }
    printf("closest  cached time 5000 points / 100 points: %.2f (goal <= 1.5)\n", prate[0] / prate[1]);
    return 0;
}
