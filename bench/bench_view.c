/* bench_view.c: how fast the stereo views render and how fast their PNGs are written.
 *
 * A 43-object room like the thesis's Computer Desks and Office scenes (design.md,
 * "Performance"): 4 static boxes (floor, two walls, a table) and 39 virtual objects,
 * spheres and superquadrics at 10x10 and cubes, seen at 640x512 per eye.  Prints
 * stereo frames/s rendering into memory only (view_render) and rendering with the
 * frame's files written (view_refresh, stereo = pair, into a temporary folder), each
 * the median of 3 runs of about 1 s; then the cost of one 640x512 PNG for several
 * zlib levels, strategies and PNG filters (png_write_rgb_opts), the choice behind
 * png_out_default.
 *
 *   build/bench/bench_view [seconds per run]
 */
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include <zlib.h>

#include "view/png_out.h"
#include "view/view.h"
#include "core/world.h"

#define BENCH_RUNS 3
#define BENCH_FILES 8 /* frame numbers cycle through these, so the folder stays small */

static double bench_clock(clockid_t id)
{
    struct timespec t;
    clock_gettime(id, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

static double bench_now(void) { return bench_clock(CLOCK_MONOTONIC); }

/* CPU time of the whole process (every thread: llvmpipe's and the PNG helper). */
static double bench_cpu(void) { return bench_clock(CLOCK_PROCESS_CPUTIME_ID); }

/* A reproducible number in [0, 1). */
static double bench_rand(unsigned long *s)
{
    *s = *s * 6364136223846793005ul + 1442695040888963407ul;
    return (double)(*s >> 11) / 9007199254740992.0;
}

static body *bench_add(world *w, const char *name, shape_kind kind, vec3 x, const int rgb[3])
{
    body *b = malloc(sizeof *b);
    if (!b) return NULL;
    body_init(b, name, kind);
    b->x = x;
    memcpy(b->color, rgb, sizeof b->color);
    return world_add(w, b) >= 0 ? b : NULL;
}

static body *bench_static_box(world *w, const char *name, vec3 x, vec3 half, const int rgb[3])
{
    body *b = bench_add(w, name, SHAPE_CUBE, x, rgb);
    if (!b) return NULL;
    b->sp.size = half;
    body_set_mass(b, -1);
    return b;
}

/* The room: z up, the head at the door looking at the table. Returns 0 or -1. */
static int bench_scene(world *w, view_settings *vs)
{
    static const int grey[3] = {130, 130, 140}, wall[3] = {200, 200, 190},
                     wood[3] = {150, 110, 70};
    static const int palette[6][3] = {{220, 40, 40}, {40, 90, 220}, {40, 190, 70},
                                      {230, 200, 40}, {200, 80, 200}, {240, 240, 240}};
    world_init(w);
    *vs = view_settings_defaults();
    vs->head = v3(0.5, -3.5, 1.7);
    vs->look_at = v3(0, 0, 0.9);
    vs->up = v3(0, 0, 1);
    vs->image_w = 640;
    vs->image_h = 512;
    vs->background[0] = 20;
    vs->background[1] = 20;
    vs->background[2] = 30;
    if (!bench_static_box(w, "floor", v3(0, 0, -0.05), v3(4, 4, 0.05), grey) ||
        !bench_static_box(w, "back_wall", v3(0, 3, 1.5), v3(4, 0.05, 1.5), wall) ||
        !bench_static_box(w, "side_wall", v3(-3, 0, 1.5), v3(0.05, 4, 1.5), wall) ||
        !bench_static_box(w, "table", v3(0, 0, 0.72), v3(1.2, 0.7, 0.03), wood))
        return -1;
    unsigned long seed = 7;
    for (int i = 0; i < 39; i++) {
        char name[32];
        snprintf(name, sizeof name, "obj%d", i);
        vec3 x = v3(-1.5 + 3 * bench_rand(&seed), -1.2 + 3 * bench_rand(&seed),
                    0.9 + 1.2 * bench_rand(&seed));
        body *b = bench_add(w, name, (shape_kind)(i % 3), x, palette[i % 6]);
        if (!b) return -1;
        double s = 0.08 + 0.12 * bench_rand(&seed);
        b->sp.radius = s;
        b->sp.size = v3(s, 0.8 * s, 0.6 * s);
        b->sp.a1 = s;
        b->sp.a2 = 0.8 * s;
        b->sp.a3 = 1.2 * s;
        static const double exps[3] = {0.5, 1, 2};
        b->sp.exp1 = exps[(i / 3) % 3];
        b->sp.exp2 = exps[(i / 9) % 3];
        body_set_rotation(b, v3(bench_rand(&seed), bench_rand(&seed), 1), 6 * bench_rand(&seed));
    }
    char err[256];
    for (int i = 0; i < w->n; i++) {
        if (body_build(w->bodies[i], err, sizeof err) != 0) {
            fprintf(stderr, "bench_view: %s: %s\n", w->bodies[i]->name, err);
            return -1;
        }
    }
    return 0;
}

/* Moves the virtual objects a little so every frame differs. */
static void bench_step(world *w, long frame)
{
    for (int i = 0; i < w->n; i++) {
        body *b = w->bodies[i];
        if (body_is_static(b)) continue;
        b->q = q_normalize(q_mul(q_axis_angle(v3(0, 0, 1), 0.01 * (i % 5 + 1)), b->q));
        b->x.z += 0.002 * ((frame / 50) % 2 ? -1 : 1);
    }
}

static int bench_cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Stereo frames/s, median of BENCH_RUNS runs of about `seconds` each; < 0 on error.
 * *cpu_ms gets the median CPU milliseconds per frame (all threads), which depends
 * less than the rate on what else the machine is running. */
static double bench_rate(view **v, world *w, view_settings *vs, bool write, double seconds,
                         const char *dir, double *cpu_ms)
{
    double rates[BENCH_RUNS], cpu[BENCH_RUNS];
    char err[512];
    view_stats st = {0};
    long frame = 0;
    snprintf(vs->output, sizeof vs->output, "%s", dir);
    vs->stereo = STEREO_PAIR;
    for (int r = 0; r < BENCH_RUNS; r++) {
        long n = 0;
        double t0 = bench_now(), c0 = bench_cpu(), t;
        do {
            bench_step(w, frame);
            int rc = write ? view_refresh(v, w, vs, frame % BENCH_FILES, &st, err, sizeof err)
                           : view_render(v, w, vs, err, sizeof err);
            if (rc != 0) {
                fprintf(stderr, "bench_view: %s\n", err);
                return -1;
            }
            frame++;
            n++;
            t = bench_now();
        } while (t - t0 < seconds);
        rates[r] = (double)n / (t - t0);
        cpu[r] = 1000 * (bench_cpu() - c0) / (double)n;
    }
    qsort(rates, BENCH_RUNS, sizeof rates[0], bench_cmp);
    qsort(cpu, BENCH_RUNS, sizeof cpu[0], bench_cmp);
    *cpu_ms = cpu[BENCH_RUNS / 2];
    return rates[BENCH_RUNS / 2];
}

/* Milliseconds per PNG of the left eye with opts (median of BENCH_RUNS runs), and the
 * file's size in bytes. */
static double bench_png(const unsigned char *rgb, int wd, int ht, png_out_opts opts,
                        double seconds, const char *dir, long *bytes)
{
    char path[1100], err[512];
    snprintf(path, sizeof path, "%s/png-test.png", dir);
    double ms[BENCH_RUNS];
    for (int r = 0; r < BENCH_RUNS; r++) {
        long n = 0;
        double t0 = bench_now(), t;
        do {
            if (png_write_rgb_opts(path, rgb, wd, ht, opts, err, sizeof err) != 0) {
                fprintf(stderr, "bench_view: %s\n", err);
                return -1;
            }
            n++;
            t = bench_now();
        } while (t - t0 < seconds / 3);
        ms[r] = 1000 * (t - t0) / (double)n;
    }
    struct stat sb;
    *bytes = stat(path, &sb) == 0 ? (long)sb.st_size : -1;
    remove(path);
    qsort(ms, BENCH_RUNS, sizeof ms[0], bench_cmp);
    return ms[BENCH_RUNS / 2];
}

static void bench_cleanup(const char *dir)
{
    char path[1100];
    for (int i = 0; i < BENCH_FILES; i++) {
        for (int e = 0; e < 2; e++) {
            snprintf(path, sizeof path, "%s/frame-%06d-%s.png", dir, i, e ? "right" : "left");
            remove(path);
        }
    }
    rmdir(dir);
}

int main(int argc, char **argv)
{
    double seconds = argc > 1 ? atof(argv[1]) : 1.0;
    if (!(seconds > 0)) seconds = 1.0;
    world w;
    view_settings vs;
    if (bench_scene(&w, &vs) != 0) {
        world_free(&w);
        return 1;
    }
    char dir[] = "/tmp/vroc-bench-view-XXXXXX";
    if (!mkdtemp(dir)) {
        perror("bench_view: mkdtemp");
        world_free(&w);
        return 1;
    }
    view *v = NULL;
    int status = 1;
    double cpu_render, cpu_written;
    double render = bench_rate(&v, &w, &vs, false, seconds, dir, &cpu_render);
    if (render < 0) goto done;
    printf("view  render-only  %d objects  %dx%d  %.0f stereo frames/s  (cpu %.1f ms/frame)\n",
           w.n, vs.image_w, vs.image_h, render, cpu_render);
    double written = bench_rate(&v, &w, &vs, true, seconds, dir, &cpu_written);
    if (written < 0) goto done;
    png_out_opts def = png_out_default();
    printf("view  with-png     %d objects  %dx%d  %.0f stereo frames/s  (cpu %.1f ms/frame; "
           "zlib level %d, filter %s)\n",
           w.n, vs.image_w, vs.image_h, written, cpu_written, def.level,
           def.filters == PNG_FILTER_NONE ? "none" : def.filters == PNG_FILTER_SUB ? "sub"
           : def.filters == PNG_FILTER_UP ? "up" : "other");

    int wd, ht;
    const unsigned char *rgb = view_pixels(v, 0, &wd, &ht);
    if (!rgb) goto done;
    static const struct {
        const char *name;
        png_out_opts o;
    } tries[] = {
        {"level 0 (stored), filter none", {0, PNG_FILTER_NONE, Z_DEFAULT_STRATEGY}},
        {"level 1, filter none", {1, PNG_FILTER_NONE, Z_DEFAULT_STRATEGY}},
        {"level 1, filter sub", {1, PNG_FILTER_SUB, Z_DEFAULT_STRATEGY}},
        {"level 1, filter up", {1, PNG_FILTER_UP, Z_DEFAULT_STRATEGY}},
        {"level 1, filter paeth", {1, PNG_FILTER_PAETH, Z_DEFAULT_STRATEGY}},
        {"level 1, filter up, rle", {1, PNG_FILTER_UP, Z_RLE}},
        {"level 1, filter sub, rle", {1, PNG_FILTER_SUB, Z_RLE}},
        {"level 2, filter up", {2, PNG_FILTER_UP, Z_DEFAULT_STRATEGY}},
        {"level 2, filter sub", {2, PNG_FILTER_SUB, Z_DEFAULT_STRATEGY}},
        {"level 6, adaptive (libpng default)", {6, 0, Z_DEFAULT_STRATEGY}},
    };
    for (size_t i = 0; i < sizeof tries / sizeof tries[0]; i++) {
        long bytes;
        double ms = bench_png(rgb, wd, ht, tries[i].o, seconds, dir, &bytes);
        if (ms < 0) goto done;
        printf("png   %-36s %dx%d  %6.2f ms/image  %7ld bytes%s\n", tries[i].name, wd, ht, ms,
               bytes,
               tries[i].o.level == def.level && tries[i].o.filters == def.filters &&
                       tries[i].o.strategy == def.strategy
                   ? "  (chosen)"
                   : "");
    }
    status = 0;
done:
    view_free(v);
    bench_cleanup(dir);
    world_free(&w);
    return status;
}
