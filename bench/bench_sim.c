/* bench_sim.c: how fast the simulation advances time (thesis chapter 5, design.md
 * "Performance").
 *
 * Loads a scene exactly as the binary does (shell_run_file, or `random` statements
 * through shell_run_text), refuses interpenetrating starts as `run` does, then times
 * sim_frame over N frames with CLOCK_MONOTONIC: simulation only, or each frame
 * followed by view_render of both eyes at 640x512 into memory (--render).  Every run
 * reloads the scene fresh; every figure printed is the median over R runs.  The pair
 * list, the schedule and the copies of the moving objects are made before the timing,
 * by the check `run` makes before time runs (shell_check_start, sim_prepare); the
 * first frame is inside the timing, and its own time is printed as first_frame_ms.
 * The off-screen context is made once, before any timing, and kept across runs.
 *
 *   bench_sim SCENE.vroc [options]
 *   bench_sim --random N [--seed S] [--thick A] [--walls on|off] [options]
 *   bench_sim --gas N [--seed S] [options]
 *
 * options:
 *   --frames N      frames per run (default 100: 10 s of simulated time at 0.1 s)
 *   --runs R        runs, each on a freshly loaded scene (default 5)
 *   --min-time S    after R runs, go on with more runs (up to 101) until the timed
 *                   runs add up to S seconds: steadier medians for fast scenes
 *   --heap on|off   collision_heap (default: as the scene leaves it)
 *   --heap both     runs with the heap on and off in turn (on, off, on, off, ...),
 *                   each on a fresh scene, so that both meet the same state of the
 *                   machine: the heap's ratio compares medians of paired runs.
 *                   --runs, --min-time and --max-time count rounds of two runs:
 *                   R rounds, then more until either side's timed runs add up to
 *                   S seconds; no round starts once both sides' add up to
 *                   --max-time.  Prints two lines, heap=on then heap=off.
 *   --max-time S    no further run once the timed runs add up to S seconds (at
 *                   least one run): bounds the time a slow scene takes
 *   --render        render both eyes into memory after every frame
 *   --budget S      stop a run after S seconds of wall time (reported as
 *                   truncated=1 with the frames it did); default no limit
 *   --name NAME     label printed as scene= (default: file name, or randomN)
 *
 * The random environment (thesis 5.6): N dynamic objects from `random N` (mixed
 * types, elasticity 1, up to 2 m/s and 2 rad/s; frictionless: default_friction and
 * default_rolling_friction 0) with no force, time_step 0.1,
 * max_linear 2, max_angular 2 and collision_dist 0.2 (2 subframes per frame, as in
 * Table 5.6).  `random` scales object sizes with the smallest half-extent of
 * random_box, so that half-extent is held at A (--thick, default 2: objects 0.08 to
 * 0.2 m) and the two others grow as A sqrt(N / 20): random_box = (X, X, A), the
 * same number of objects per cubic metre and the same object sizes for every N
 * (a cube at N = 20).  Six static walls (cubes, mass -1, elasticity 1) 0.2 m thick
 * close the box so the objects keep colliding (--walls off leaves it open); each
 * adds N pairs, and pairs= reports the pairs as the world counts them.
 *
 * The gas (issue 27's scaling table): N objects from `random N` as above, one per
 * cubic metre in a closed cubic room (random_box = (L, L, L), L = N^(1/3) / 2,
 * and six walls): the same sizes and speeds at every N, and a room that grows.
 *
 * --export FILE writes the scene as loaded (before any frame) for a peer program
 * (bench/bullet_gas.cpp) to run the same objects, one per line:
 *   sphere|hull|box mass r|n|hx hy hz [n vertices x y z, body frame] x y z qw qx qy
 *   qz vx vy vz wx wy wz
 * with x the centre of mass, mass < 0 for a static object, and a first line
 * "vroc-scene N time_step frames".
 *
 * cpu_frames_per_s is frames per second of the process's processor time (the
 * median run's): steadier than frames_per_s on a machine that is doing other work.
 * Every line also gives setup_s (the median time to load the scene and make what
 * the frames need: the statements, the check `run` makes and sim_prepare),
 * existing_pairs (the pairs that exist after the last frame: with the heap on, the
 * near ones) and peak_rss_mb (the process's peak resident set so far, from
 * /proc/self/status: run one measurement per process for a figure of its own).
 *
 * Output: one line of name=value fields on stdout (two with --heap both), e.g.
 *   scene=simple objects=4 pairs=6 subframes=6 heap=on render=no frames=100 runs=5
 *   frames_per_s=... subframes_per_s=... pair_checks_per_frame=... ...
 */
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "bench.h"

#include "shell/shell.h"
#include "core/sim.h"
#include "view/view.h"
#include "core/world.h"

#define MAX_RUNS 101

/* options.heap: runs with the heap on and off in turn */
#define HEAP_BOTH 2

typedef struct {
    const char *scene;   /* path, or NULL with random > 0 */
    long random;         /* N random objects */
    bool gas;            /* --gas: in a cubic room, one per cubic metre */
    unsigned long seed;
    double thick;        /* A: smallest half-extent of random_box */
    bool walls;
    long frames;
    int runs;
    int heap;            /* -1 as the scene says, 0 off, 1 on, HEAP_BOTH in turn */
    bool render;
    double budget;       /* s per run, 0 none */
    double min_time;     /* s of timed runs wanted in all, 0 none */
    double max_time;     /* s of timed runs after which no run starts, 0 none */
    char name[128];
    const char *export_path; /* --export FILE */
} options;

typedef struct {
    double fps, sfps, checks, pops, colls, restarts, first_ms, seconds, setup, live, cpu;
    long frames;
    bool truncated;
} run_result;

static double median(double *v, int n)
{
    qsort(v, (size_t)n, sizeof *v, cmp_double);
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/* A rate for the output line: whole above 1e5, else 6 significant digits. */
static void put_rate(const char *name, double v)
{
    if (v >= 1e5)
        printf(" %s=%.0f", name, v);
    else
        printf(" %s=%.6g", name, v);
}

static void usage(void)
{
    fprintf(stderr,
            "usage: bench_sim SCENE.vroc [--frames N] [--runs R] [--min-time S] [--max-time S]\n"
            "                 [--heap on|off|both] [--render] [--budget S] [--name NAME]\n"
            "       bench_sim --random N [--seed S] [--thick A] [--walls on|off] [...]\n"
            "       bench_sim --gas N [--seed S] [--export FILE] [...]\n");
}

/* Half-extents of the random box for n objects: (x, x, a); the gas's (x, x, x). */
static double random_half(const options *o)
{
    if (o->gas) return 0.5 * cbrt((double)o->random);
    double x = o->thick * sqrt((double)o->random / 20.0);
    return x > o->thick ? x : o->thick;
}

/* The smallest half-extent of the random box. */
static double random_thick(const options *o) { return o->gas ? random_half(o) : o->thick; }

/* The statements that build the random environment.  Returns 0, or -1 when the
 * buffer is too small. */
static int random_scene(const options *o, char *buf, size_t len)
{
    double a = random_thick(o), x = random_half(o), t = 0.2;
    /* (frictionless, as the thesis's random environment and Bullet's gas) */
    int k = snprintf(buf, len,
                     "default_friction = 0\n"
                     "default_rolling_friction = 0\n"
                     "time_step = 0.1\n"
                     "max_linear = 2\n"
                     "max_angular = 2\n"
                     "collision_dist = 0.2\n"
                     "seed = %lu\n"
                     "random_box = (%.6g, %.6g, %.6g)\n"
                     "random %ld\n",
                     o->seed, x, x, a, o->random);
    if (k < 0 || (size_t)k >= len) return -1;
    if (o->walls) {
        /* name, half-extents, centre */
        const struct {
            const char *n;
            double sx, sy, sz, cx, cy, cz;
        } wl[6] = {
            {"wall_xm", t, x + 2 * t, a + 2 * t, -(x + t), 0, 0},
            {"wall_xp", t, x + 2 * t, a + 2 * t, x + t, 0, 0},
            {"wall_ym", x, t, a + 2 * t, 0, -(x + t), 0},
            {"wall_yp", x, t, a + 2 * t, 0, x + t, 0},
            {"wall_zm", x, x, t, 0, 0, -(a + t)},
            {"wall_zp", x, x, t, 0, 0, a + t},
        };
        for (int i = 0; i < 6; i++) {
            int m = snprintf(buf + k, len - (size_t)k,
                             "cube %s\nsize = (%.6g, %.6g, %.6g)\n"
                             "translate = (%.6g, %.6g, %.6g)\nmass = -1\nelasticity = 1\n",
                             wl[i].n, wl[i].sx, wl[i].sy, wl[i].sz, wl[i].cx, wl[i].cy, wl[i].cz);
            if (m < 0 || (size_t)m >= len - (size_t)k) return -1;
            k += m;
        }
    }
    /* a head outside the box looking in, for --render */
    int m = snprintf(buf + k, len - (size_t)k,
                     "head = (0, %.6g, %.6g)\nlook_at = (0, 0, 0)\nup = (0, 0, 1)\n",
                     -3.0 * x - 2.0, 0.5 * a);
    if (m < 0 || (size_t)m >= len - (size_t)k) return -1;
    return 0;
}

/* Loads the scene into a fresh shell.  Returns 0 or -1 (message printed). */
static int load(shell *sh, const options *o)
{
    shell_init(sh, stderr, stderr);
    sh->quiet = true;
    sh->stop_on_error = true;
    cmd_status r;
    if (o->random > 0) {
        char text[8192];
        if (random_scene(o, text, sizeof text) != 0) {
            fprintf(stderr, "bench_sim: scene text too long\n");
            return -1;
        }
        r = shell_run_text(sh, text, "bench_sim random");
    } else {
        r = shell_run_file(sh, o->scene);
    }
    if (r == CMD_ERROR) {
        fprintf(stderr, "bench_sim: %s: cannot load the scene\n", o->name);
        return -1;
    }
    if (o->heap >= 0 &&
        shell_run_text(sh, o->heap ? "collision_heap = on" : "collision_heap = off",
                       "bench_sim") != CMD_OK)
        return -1;
    sh->view_set.image_w = 640;
    sh->view_set.image_h = 512;
    /* as `run` does before time runs */
    if (shell_check_start(sh, NULL) != CMD_OK) {
        fprintf(stderr, "bench_sim: %s: objects interpenetrate at the start\n", o->name);
        return -1;
    }
    return 0;
}

/* Writes the world's objects for a peer program (--export).  Returns 0 or -1. */
static int export_scene(const options *o, const world *w)
{
    FILE *f = fopen(o->export_path, "w");
    if (!f) {
        perror(o->export_path);
        return -1;
    }
    fprintf(f, "vroc-scene %d %.17g %ld\n", w->n, w->set.time_step, o->frames);
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        const poly *h = b->shape.hull;
        double m = body_is_static(b) ? -1 : b->mass;
        vec3 c = body_com(b), com = b->shape.mass.com;
        if (b->sp.kind == SHAPE_SPHERE) {
            fprintf(f, "sphere %.17g %.17g", m, b->sp.radius);
        } else if (b->sp.kind == SHAPE_CUBE) {
            fprintf(f, "box %.17g %.17g %.17g %.17g", m, b->sp.size.x, b->sp.size.y, b->sp.size.z);
        } else {
            fprintf(f, "hull %.17g %d", m, h->nv);
            for (int k = 0; k < h->nv; k++)
                fprintf(f, " %.17g %.17g %.17g", h->v[k].x - com.x, h->v[k].y - com.y, h->v[k].z - com.z);
        }
        fprintf(f, " %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n",
                c.x, c.y, c.z, b->q.w, b->q.x, b->q.y, b->q.z, b->v.x, b->v.y, b->v.z, b->w.x,
                b->w.y, b->w.z);
    }
    return fclose(f) == 0 ? 0 : -1;
}

/* One run: a fresh scene, o->frames frames timed.  Returns 0 or -1. */
static int one_run(const options *o, view **v, run_result *res, long *objects, long *pairs,
                   long *subframes, bool *heap_on)
{
    shell sh;
    char err[1024];
    double t_load = now();
    int loaded = load(&sh, o);
    res->setup = now() - t_load;
    if (loaded != 0) {
        shell_free(&sh);
        return -1;
    }
    if (o->export_path && export_scene(o, &sh.w) != 0) {
        shell_free(&sh);
        return -1;
    }
    if (o->render && view_display(v, &sh.view_set, err, sizeof err) != 0) {
        fprintf(stderr, "bench_sim: %s: %s\n", o->name, err);
        shell_free(&sh);
        return -1;
    }
    sim_stats s0 = sh.w.st;
    double t0 = now(), c0 = cpu_now(), first = 0;
    long k;
    res->truncated = false;
    for (k = 0; k < o->frames; k++) {
        if (sim_frame(&sh.w, err, sizeof err) != 0) {
            fprintf(stderr, "bench_sim: %s: frame %ld: %s\n", o->name, k, err);
            shell_free(&sh);
            return -1;
        }
        if (o->render && view_render(v, &sh.w, &sh.view_set, err, sizeof err) != 0) {
            fprintf(stderr, "bench_sim: %s: render: %s\n", o->name, err);
            shell_free(&sh);
            return -1;
        }
        double t = now();
        if (k == 0) first = t - t0;
        if (o->budget > 0 && t - t0 > o->budget && k + 1 < o->frames) {
            res->truncated = true;
            k++;
            break;
        }
    }
    double dt = now() - t0;
    res->cpu = cpu_now() - c0;
    sim_stats *s = &sh.w.st;
    res->frames = k;
    res->seconds = dt;
    res->fps = (double)k / dt;
    res->sfps = (double)(s->subframes - s0.subframes) / dt;
    res->checks = (double)(s->pair_checks - s0.pair_checks) / (double)k;
    res->pops = (double)(s->heap_pops - s0.heap_pops) / (double)k;
    res->colls = (double)(s->collisions - s0.collisions) / (double)k;
    res->restarts = (double)(s->restarts - s0.restarts) / (double)k;
    res->first_ms = 1e3 * first;
    res->live = (double)sh.w.pairs.live;
    *objects = sh.w.n;
    *pairs = world_pairs(&sh.w);
    *subframes = world_subframes(&sh.w);
    *heap_on = sh.w.set.collision_heap;
    shell_free(&sh);
    return 0;
}

static int parse(int argc, char **argv, options *o)
{
    memset(o, 0, sizeof *o);
    o->seed = 1;
    o->thick = 2;
    o->walls = true;
    o->frames = 100;
    o->runs = 5;
    o->heap = -1;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *val = i + 1 < argc ? argv[i + 1] : NULL;
        bool takes = true;
        if (!strcmp(a, "--render")) {
            o->render = true;
            takes = false;
        } else if (a[0] != '-' || !a[1]) {
            if (o->scene) return -1;
            o->scene = a;
            takes = false;
        } else if (!val) {
            return -1;
        } else if (!strcmp(a, "--frames")) {
            o->frames = strtol(val, NULL, 10);
        } else if (!strcmp(a, "--runs")) {
            o->runs = (int)strtol(val, NULL, 10);
        } else if (!strcmp(a, "--random") || !strcmp(a, "--gas")) {
            o->random = strtol(val, NULL, 10);
            o->gas = a[2] == 'g';
            if (o->random < 1) return -1;
        } else if (!strcmp(a, "--seed")) {
            o->seed = strtoul(val, NULL, 10);
        } else if (!strcmp(a, "--thick")) {
            o->thick = strtod(val, NULL);
            if (!(o->thick > 0)) return -1;
        } else if (!strcmp(a, "--max-time")) {
            o->max_time = strtod(val, NULL);
        } else if (!strcmp(a, "--min-time")) {
            o->min_time = strtod(val, NULL);
        } else if (!strcmp(a, "--budget")) {
            o->budget = strtod(val, NULL);
        } else if (!strcmp(a, "--export")) {
            o->export_path = val;
        } else if (!strcmp(a, "--name")) {
            snprintf(o->name, sizeof o->name, "%s", val);
        } else if (!strcmp(a, "--heap") && !strcmp(val, "both")) {
            o->heap = HEAP_BOTH;
        } else if (!strcmp(a, "--heap") || !strcmp(a, "--walls")) {
            int on = !strcmp(val, "on") ? 1 : !strcmp(val, "off") ? 0 : -1;
            if (on < 0) return -1;
            if (a[2] == 'h')
                o->heap = on;
            else
                o->walls = on;
        } else {
            return -1;
        }
        if (takes) i++;
    }
    if ((o->scene != NULL) == (o->random > 0)) return -1;
    if (o->frames < 1 || o->runs < 1 || o->runs > MAX_RUNS) return -1;
    if (!o->name[0]) {
        if (o->random > 0) {
            snprintf(o->name, sizeof o->name, "%s%ld", o->gas ? "gas" : "random", o->random);
        } else {
            const char *b = strrchr(o->scene, '/');
            b = b ? b + 1 : o->scene;
            snprintf(o->name, sizeof o->name, "%s", b);
            char *dot = strrchr(o->name, '.');
            if (dot && !strcmp(dot, ".vroc")) *dot = '\0';
        }
    }
    return 0;
}

/* The runs of one measurement: each figure of each run, for the medians. */
typedef struct {
    double fps[MAX_RUNS], sfps[MAX_RUNS], checks[MAX_RUNS], pops[MAX_RUNS], colls[MAX_RUNS],
        restarts[MAX_RUNS], first[MAX_RUNS], frames[MAX_RUNS], setup[MAX_RUNS], live[MAX_RUNS],
        cpu_fps[MAX_RUNS];
    int runs;
    double spent; /* s of timed runs */
    bool truncated, heap_on;
} series;

static void add_run(series *x, const run_result *res)
{
    int r = x->runs++;
    x->fps[r] = res->fps;
    x->sfps[r] = res->sfps;
    x->checks[r] = res->checks;
    x->pops[r] = res->pops;
    x->colls[r] = res->colls;
    x->restarts[r] = res->restarts;
    x->first[r] = res->first_ms;
    x->frames[r] = (double)res->frames;
    x->setup[r] = res->setup;
    x->cpu_fps[r] = (double)res->frames / res->cpu;
    x->live[r] = res->live;
    x->truncated = x->truncated || res->truncated;
    x->spent += res->seconds;
}

/* Prints the measurement's line (the medians sort the series' arrays). */
static void print_series(const options *o, series *x, long objects, long pairs, long subframes)
{
    int n = x->runs;
    double fps_min = x->fps[0], fps_max = x->fps[0];
    for (int r = 1; r < n; r++) {
        fps_min = fmin(fps_min, x->fps[r]);
        fps_max = fmax(fps_max, x->fps[r]);
    }
    printf("scene=%s objects=%ld pairs=%ld subframes=%ld heap=%s render=%s frames=%.0f runs=%d",
           o->name, objects, pairs, subframes, x->heap_on ? "on" : "off", o->render ? "yes" : "no",
           median(x->frames, n), n);
    put_rate("frames_per_s", median(x->fps, n));
    put_rate("subframes_per_s", median(x->sfps, n));
    put_rate("fps_min", fps_min);
    put_rate("fps_max", fps_max);
    printf(" pair_checks_per_frame=%.1f heap_pops_per_frame=%.1f collisions_per_frame=%.2f"
           " restarts_per_frame=%.2f first_frame_ms=%.3g truncated=%d",
           median(x->checks, n), median(x->pops, n), median(x->colls, n), median(x->restarts, n),
           median(x->first, n), x->truncated ? 1 : 0);
    put_rate("cpu_frames_per_s", median(x->cpu_fps, n));
    printf(" setup_s=%.4g existing_pairs=%.0f peak_rss_mb=%.1f", median(x->setup, n),
           median(x->live, n), peak_rss_mb());
    if (o->heap == HEAP_BOTH) printf(" order=alternate");
    if (o->random > 0) {
        double h = random_half(o);
        printf(" random_box=%.4g,%.4g,%.4g walls=%s", h, h, random_thick(o), o->walls ? "6" : "0");
    }
    printf("\n");
}

int main(int argc, char **argv)
{
    options o;
    if (parse(argc, argv, &o) != 0) {
        usage();
        return 2;
    }
    /* one series, or with --heap both one per side: [0] on, [1] off */
    static series x[2];
    bool both = o.heap == HEAP_BOTH;
    int sides = both ? 2 : 1;
    long objects = 0, pairs = 0, subframes = 0;
    view *v = NULL;
    for (int r = 0; r < o.runs || (fmax(x[0].spent, x[1].spent) < o.min_time && r < MAX_RUNS);
         r++) {
        if (r > 0 && o.max_time > 0 && x[0].spent + x[1].spent >= o.max_time) break;
        for (int k = 0; k < sides; k++) {
            options ok = o;
            if (both) ok.heap = k == 0 ? 1 : 0;
            run_result res;
            if (one_run(&ok, &v, &res, &objects, &pairs, &subframes, &x[k].heap_on) != 0) {
                view_free(v);
                return 1;
            }
            add_run(&x[k], &res);
        }
    }
    view_free(v);
    for (int k = 0; k < sides; k++) print_series(&o, &x[k], objects, pairs, subframes);
    return 0;
}
