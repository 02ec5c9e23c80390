/* test_view.c: the stereo views: files, sizes, parallax, modes, `real`, errors.
 *
 * Each test builds a small world in code (z up, the head at the origin looking along
 * +y unless it says otherwise), renders it small (160x128 per eye) into a fresh
 * folder under /tmp, reads the PNGs back and looks at the pixels: what is not the
 * background colour is an object.  Geometry of the parallax tests: with parallel eyes
 * at -+ipd/2 and frusta sharing the window at distance D, a point on the axis at
 * distance d projects ipd/2 (1/d - 1/D) right of the window's centre in the left eye
 * and as much left in the right eye: crossed (left image further right) when d < D,
 * uncrossed when d > D, zero at D, and larger the nearer the point.
 */
#include "check.h"

#include <dirent.h>
#include <errno.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "view/png_out.h"
#include "view/view.h"
#include "core/world.h"
#include "mesh/meshfile.h"

#define TW 160
#define TH 128

static const int BG[3] = {10, 20, 40};

typedef struct {
    char dir[64];
    world w;
    view_settings vs;
    view *v;
    view_stats st;
    char err[512];
} fixture;

/* rm -r path (files and folders the tests made). */
static void rm_tree(const char *path)
{
    struct stat sb;
    if (lstat(path, &sb) != 0) return;
    if (S_ISDIR(sb.st_mode)) {
        DIR *d = opendir(path);
        if (d) {
            struct dirent *e;
            while ((e = readdir(d)) != NULL) {
                if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0) continue;
                char sub[1024];
                snprintf(sub, sizeof sub, "%s/%s", path, e->d_name);
                rm_tree(sub);
            }
            closedir(d);
        }
        rmdir(path);
    } else {
        unlink(path);
    }
}

static int setup(void **state)
{
    fixture *f = calloc(1, sizeof *f);
    if (!f) return -1;
    snprintf(f->dir, sizeof f->dir, "/tmp/vroc-test-view-XXXXXX");
    if (!mkdtemp(f->dir)) {
        free(f);
        return -1;
    }
    world_init(&f->w);
    f->vs = view_settings_defaults();
    view_settings *s = &f->vs;
    s->head = v3(0, 0, 0);
    s->look_at = v3(0, 1, 0);
    s->up = v3(0, 0, 1);
    s->ipd = 0.064;
    s->fov = 60;
    s->image_w = TW;
    s->image_h = TH;
    memcpy(s->background, BG, sizeof BG);
    snprintf(s->output, sizeof s->output, "%s/frames", f->dir);
    *state = f;
    return 0;
}

static int teardown(void **state)
{
    fixture *f = *state;
    view_free(f->v);
    world_free(&f->w);
    rm_tree(f->dir);
    free(f);
    return 0;
}

/* Adds a built object; returns it. */
static body *add(fixture *f, const char *name, shape_kind kind, vec3 x, int r, int g, int b)
{
    body *o = malloc(sizeof *o);
    assert_non_null(o);
    body_init(o, name, kind);
    o->x = x;
    o->color[0] = r;
    o->color[1] = g;
    o->color[2] = b;
    assert_true(world_add(&f->w, o) >= 0);
    return o;
}

static void build(body *b)
{
    char err[256];
    if (body_build(b, err, sizeof err) != 0) fail_msg("%s: %s", b->name, err);
}

static body *add_sphere(fixture *f, vec3 x, double radius, int r, int g, int b)
{
    body *o = add(f, "ball", SHAPE_SPHERE, x, r, g, b);
    o->sp.radius = radius;
    o->sp.ures = o->sp.vres = 24;
    build(o);
    return o;
}

static bool is_bg(const unsigned char *p)
{
    return p[0] == BG[0] && p[1] == BG[1] && p[2] == BG[2];
}

/* Number of non-background pixels and the mean x of them. */
static long coverage(const unsigned char *rgb, int w, int h, double *mean_x)
{
    long n = 0;
    double sx = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            if (!is_bg(rgb + 3 * ((size_t)y * w + x))) {
                n++;
                sx += x;
            }
    if (mean_x) *mean_x = n ? sx / (double)n : -1;
    return n;
}

/* Mean y of the non-background pixels (rows counted from the top). */
static double mean_y(const unsigned char *rgb, int w, int h)
{
    long n = 0;
    double sy = 0;
    for (int y = 0; y < h; y++)
        for (int x = 0; x < w; x++)
            if (!is_bg(rgb + 3 * ((size_t)y * w + x))) {
                n++;
                sy += y;
            }
    return n ? sy / (double)n : -1;
}

static const unsigned char *px(const unsigned char *rgb, int w, int x, int y)
{
    return rgb + 3 * ((size_t)y * w + x);
}

static char *frame_path(const fixture *f, long frame, const char *suffix)
{
    static char path[1200];
    snprintf(path, sizeof path, "%s/frame-%06ld-%s.png", f->vs.output, frame, suffix);
    return path;
}

static bool exists(const char *path)
{
    struct stat sb;
    return stat(path, &sb) == 0;
}

/* Reads a frame file; fails the test if it is missing or not width x height. */
static unsigned char *read_frame(const fixture *f, long frame, const char *suffix, int width,
                                 int height)
{
    unsigned char *rgb;
    int w, h;
    const char *path = frame_path(f, frame, suffix);
    if (png_read_rgb(path, &rgb, &w, &h) != 0) fail_msg("cannot read %s", path);
    assert_int_equal(w, width);
    assert_int_equal(h, height);
    return rgb;
}

static void refresh_ok(fixture *f, long frame)
{
    if (view_refresh(&f->v, &f->w, &f->vs, frame, &f->st, f->err, sizeof f->err) != 0)
        fail_msg("view_refresh: %s", f->err);
}

/* Horizontal disparity (left centroid x - right centroid x) of the only object. */
static double disparity(fixture *f)
{
    if (view_render(&f->v, &f->w, &f->vs, f->err, sizeof f->err) != 0) fail_msg("view_render: %s", f->err);
    int w, h;
    double xl, xr;
    const unsigned char *l = view_pixels(f->v, 0, &w, &h);
    const unsigned char *r = view_pixels(f->v, 1, &w, &h);
    assert_non_null(l);
    assert_non_null(r);
    assert_true(coverage(l, w, h, &xl) > 0);
    assert_true(coverage(r, w, h, &xr) > 0);
    return xl - xr;
}

/* (1) pair: two PNGs of image_size; a red sphere ahead is red at the centre, the
 * corners are background, in both eyes; the stats count the files and the time. */
static void test_pair_files(void **state)
{
    fixture *f = *state;
    add_sphere(f, v3(0, 1, 0), 0.2, 255, 0, 0);
    refresh_ok(f, 7);
    assert_int_equal(f->st.frames_written, 2);
    assert_true(f->st.render_time > 0);
    const char *eyes[2] = {"left", "right"};
    for (int e = 0; e < 2; e++) {
        unsigned char *rgb = read_frame(f, 7, eyes[e], TW, TH);
        const unsigned char *c = px(rgb, TW, TW / 2, TH / 2);
        assert_true(c[0] > 100);
        assert_true(c[0] > 3 * c[1] && c[0] > 3 * c[2]);
        int corners[4][2] = {{0, 0}, {TW - 1, 0}, {0, TH - 1}, {TW - 1, TH - 1}};
        for (int k = 0; k < 4; k++) assert_true(is_bg(px(rgb, TW, corners[k][0], corners[k][1])));
        long n = coverage(rgb, TW, TH, NULL);
        assert_true(n > 100 && n < TW * TH / 2);
        /* the file is what view_pixels holds */
        int w, h;
        const unsigned char *mem = view_pixels(f->v, e, &w, &h);
        assert_non_null(mem);
        assert_int_equal(w, TW);
        assert_int_equal(h, TH);
        assert_memory_equal(mem, rgb, (size_t)TW * TH * 3);
        free(rgb);
    }
    assert_false(exists(frame_path(f, 8, "left")));
}

/* The image is upright and not mirrored: up is up, the head's right is right. */
static void test_orientation(void **state)
{
    fixture *f = *state;
    body *b = add_sphere(f, v3(0, 2, 0.5), 0.15, 255, 255, 0);
    refresh_ok(f, 0);
    unsigned char *rgb = read_frame(f, 0, "left", TW, TH);
    assert_true(mean_y(rgb, TW, TH) < TH / 2.0 - 10);
    free(rgb);
    b->x = v3(0.6, 2, 0); /* +x is the head's right: f x up = (0,1,0) x (0,0,1) */
    refresh_ok(f, 1);
    rgb = read_frame(f, 1, "right", TW, TH);
    double mx;
    assert_true(coverage(rgb, TW, TH, &mx) > 0);
    assert_true(mx > TW / 2.0 + 10);
    free(rgb);
}

/* (2) parallax: the eyes differ; nearer than the focal distance is crossed (left eye's
 * centroid further right), beyond it uncrossed, at it zero; nearer means more. */
static void test_parallax(void **state)
{
    fixture *f = *state;
    f->vs.ipd = 0.1;
    f->vs.look_at = v3(0, 2, 0); /* D = 2 */
    body *b = add_sphere(f, v3(0, 0.8, 0), 0.1, 255, 255, 255);

    refresh_ok(f, 0);
    unsigned char *l = read_frame(f, 0, "left", TW, TH);
    unsigned char *r = read_frame(f, 0, "right", TW, TH);
    assert_memory_not_equal(l, r, (size_t)TW * TH * 3);
    double xl, xr;
    coverage(l, TW, TH, &xl);
    coverage(r, TW, TH, &xr);
    assert_true(xl > xr);
    free(l);
    free(r);

    /* expected: ipd/2 (1/d - 1/D) in window units, times (TH/2)/tan(fov/2) pixels */
    double scale = (TH / 2.0) / tan(30 * M_PI / 180);
    double d08 = disparity(f);
    assert_near(d08, 2 * 0.05 * (1 / 0.8 - 1 / 2.0) * scale, 1.0);
    b->x = v3(0, 1.4, 0);
    double d14 = disparity(f);
    assert_true(d14 > 0 && d14 < d08 - 2);
    b->x = v3(0, 2, 0);
    assert_near(disparity(f), 0, 0.5);
    b->x = v3(0, 5, 0);
    b->sp.radius = 0.3;
    build(b);
    double d5 = disparity(f);
    assert_true(d5 < -1);
    assert_near(d5, 2 * 0.05 * (1 / 5.0 - 1 / 2.0) * scale, 1.0);
}

/* ipd 0 gives the same image to both eyes. */
static void test_zero_ipd(void **state)
{
    fixture *f = *state;
    f->vs.ipd = 0;
    add_sphere(f, v3(0.1, 0.5, 0), 0.1, 0, 0, 255);
    assert_int_equal(view_render(&f->v, &f->w, &f->vs, f->err, sizeof f->err), 0);
    int w, h;
    const unsigned char *l = view_pixels(f->v, 0, &w, &h);
    const unsigned char *r = view_pixels(f->v, 1, &w, &h);
    assert_memory_equal(l, r, (size_t)w * h * 3);
}

/* (3a) sbs: one file twice as wide, the left eye on the left. */
static void test_sbs(void **state)
{
    fixture *f = *state;
    f->vs.stereo = STEREO_SBS;
    f->vs.ipd = 0.2;
    add_sphere(f, v3(0, 0.6, 0), 0.1, 0, 200, 255);
    refresh_ok(f, 3);
    assert_int_equal(f->st.frames_written, 1);
    assert_false(exists(frame_path(f, 3, "left")));
    assert_false(exists(frame_path(f, 3, "right")));
    unsigned char *rgb = read_frame(f, 3, "sbs", 2 * TW, TH);
    int w, h;
    for (int e = 0; e < 2; e++) {
        const unsigned char *eye = view_pixels(f->v, e, &w, &h);
        assert_non_null(eye);
        for (int y = 0; y < TH; y++)
            assert_memory_equal(rgb + 3 * ((size_t)y * 2 * TW + (size_t)e * TW),
                                eye + 3 * (size_t)y * TW, 3 * TW);
    }
    free(rgb);
}

/* Dubois's red-cyan anaglyph of one pixel, computed here in doubles from his
 * paper's matrices, in linear light (the sRGB curve both ways). */
static void dubois(const unsigned char *l, const unsigned char *r, double out[3])
{
    static const double L[3][3] = {{0.456, 0.500, 0.176}, {-0.040, -0.038, -0.016}, {-0.015, -0.021, -0.005}};
    static const double R[3][3] = {{-0.043, -0.088, -0.002}, {0.378, 0.734, -0.018}, {-0.072, -0.113, 1.226}};
    double ll[3], rl[3];
    for (int k = 0; k < 3; k++) {
        double a = l[k] / 255.0, b = r[k] / 255.0;
        ll[k] = a <= 0.04045 ? a / 12.92 : pow((a + 0.055) / 1.055, 2.4);
        rl[k] = b <= 0.04045 ? b / 12.92 : pow((b + 0.055) / 1.055, 2.4);
    }
    for (int c = 0; c < 3; c++) {
        double x = 0;
        for (int k = 0; k < 3; k++) x += L[c][k] * ll[k] + R[c][k] * rl[k];
        x = x < 0 ? 0 : x > 1 ? 1 : x;
        out[c] = 255 * (x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1 / 2.4) - 0.055);
    }
}

/* (3b) anaglyph: every pixel is Dubois's projection of the two eyes' pixels; a
 * white object at strong parallax leaves red-only and cyan-only fringes; and
 * colours are kept: a green and a blue object where the eyes agree (at the
 * focal distance) stay green and blue, where a luminance anaglyph made them
 * grey. */
static void test_anaglyph(void **state)
{
    fixture *f = *state;
    f->vs.stereo = STEREO_ANAGLYPH;
    f->vs.ipd = 0.3;
    add_sphere(f, v3(0, 0.5, 0), 0.08, 255, 255, 255);
    refresh_ok(f, 4);
    assert_int_equal(f->st.frames_written, 1);
    unsigned char *rgb = read_frame(f, 4, "anaglyph", TW, TH);
    int w, h;
    const unsigned char *l = view_pixels(f->v, 0, &w, &h);
    const unsigned char *r = view_pixels(f->v, 1, &w, &h);
    long red_only = 0, cyan_only = 0;
    for (size_t i = 0; i < (size_t)TW * TH; i++) {
        const unsigned char *a = rgb + 3 * i;
        double want[3];
        dubois(l + 3 * i, r + 3 * i, want);
        for (int c = 0; c < 3; c++)
            if (fabs(a[c] - want[c]) > 1.5)
                fail_msg("pixel %zu channel %d: %d, Dubois gives %.2f", i, c, a[c], want[c]);
        if (a[0] > 100 && a[1] < 40) red_only++;
        if (a[1] > 100 && a[0] < 40) cyan_only++;
    }
    assert_true(red_only > 20);
    assert_true(cyan_only > 20);
    free(rgb);

    f->vs.ipd = 0.064;
    for (int k = 0; k < 2; k++) {
        world_free(&f->w);
        world_init(&f->w);
        add_sphere(f, v3(0, 1, 0), 0.2, 0, k == 0 ? 200 : 0, k == 0 ? 0 : 200);
        refresh_ok(f, 5 + k);
        rgb = read_frame(f, 5 + k, "anaglyph", TW, TH);
        const unsigned char *c = rgb + 3 * ((size_t)(TH / 2) * TW + TW / 2);
        if (k == 0) assert_true(c[1] > c[0] + 30 && c[1] > c[2] + 30); /* green */
        else assert_true(c[2] > c[0] + 30 && c[2] > c[1] + 30);        /* blue */
        free(rgb);
    }
}

/* (3c) mono: only the left file, only the left eye rendered. */
static void test_mono(void **state)
{
    fixture *f = *state;
    f->vs.stereo = STEREO_MONO;
    add_sphere(f, v3(0, 1, 0), 0.2, 255, 0, 0);
    refresh_ok(f, 5);
    assert_int_equal(f->st.frames_written, 1);
    unsigned char *rgb = read_frame(f, 5, "left", TW, TH);
    assert_true(coverage(rgb, TW, TH, NULL) > 100);
    free(rgb);
    assert_false(exists(frame_path(f, 5, "right")));
    assert_non_null(view_pixels(f->v, 0, NULL, NULL));
    assert_null(view_pixels(f->v, 1, NULL, NULL));
}

/* (4) real: a static green cube alone in view is drawn solid, as fewer pixels in
 * wire, not at all when hidden; a dynamic object is drawn whatever `real` says. */
static void test_real(void **state)
{
    fixture *f = *state;
    body *c = add(f, "table", SHAPE_CUBE, v3(0, 2, 0), 0, 255, 0);
    c->sp.size = v3(0.4, 0.3, 0.2);
    body_set_mass(c, -1);
    build(c);
    body_set_rotation(c, v3(1, 1, 1), 0.7);
    long n[3];
    real_mode modes[3] = {REAL_SOLID, REAL_WIRE, REAL_HIDDEN};
    for (int m = 0; m < 3; m++) {
        f->vs.real = modes[m];
        refresh_ok(f, m);
        for (int e = 0; e < 2; e++) {
            unsigned char *rgb = read_frame(f, m, e ? "right" : "left", TW, TH);
            long k = coverage(rgb, TW, TH, NULL);
            if (e == 0) n[m] = k;
            if (modes[m] == REAL_WIRE) { /* unlit lines in the object's colour */
                for (size_t i = 0; i < (size_t)TW * TH; i++)
                    if (!is_bg(rgb + 3 * i)) assert_int_equal(rgb[3 * i + 1], 255);
            }
            free(rgb);
        }
    }
    assert_true(n[0] > 1000);
    assert_true(n[1] > 50 && n[1] < n[0] / 2);
    assert_int_equal(n[2], 0);

    body *ball = add_sphere(f, v3(0, 1, 0), 0.1, 255, 0, 0);
    (void)ball;
    f->vs.real = REAL_HIDDEN;
    refresh_ok(f, 9);
    unsigned char *rgb = read_frame(f, 9, "left", TW, TH);
    assert_true(coverage(rgb, TW, TH, NULL) > 100);
    free(rgb);
}

/* hulls = on: a polyhedron of two pieces (two boxes side by side, read from an
 * OBJ of two groups) gets white wire frames over its green faces; off, none;
 * and the other objects are drawn as before. */
static void test_hulls(void **state)
{
    fixture *f = *state;
    static const char *TWO =
        "g a\nv -0.3 -0.1 -0.1\nv 0 -0.1 -0.1\nv -0.3 0.1 -0.1\nv 0 0.1 -0.1\n"
        "v -0.3 -0.1 0.1\nv 0 -0.1 0.1\nv -0.3 0.1 0.1\nv 0 0.1 0.1\n"
        "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n"
        "g b\nv 0.05 -0.1 -0.1\nv 0.3 -0.1 -0.1\nv 0.05 0.1 -0.1\nv 0.3 0.1 -0.1\n"
        "v 0.05 -0.1 0.1\nv 0.3 -0.1 0.1\nv 0.05 0.1 0.1\nv 0.3 0.1 0.1\n"
        "f 9 11 12 10\nf 13 14 16 15\nf 9 10 14 13\nf 11 15 16 12\nf 9 13 15 11\nf 10 12 16 14\n";
    mesh_file m;
    char err[256];
    assert_int_equal(mesh_parse((const unsigned char *)TWO, strlen(TWO), "two.obj", &m, err, sizeof err), 0);
    mesh_source *src = mesh_source_make(&m, "two.obj", err, sizeof err);
    mesh_file_free(&m);
    assert_non_null(src);
    body *p = add(f, "two", SHAPE_POLYHEDRON, v3(0, 1.5, 0), 0, 200, 0);
    p->sp.src = &src->src;
    build(p);
    body_set_rotation(p, v3(1, 0.5, 0.3), 0.6);
    assert_int_equal(p->shape.pieces, 2);
    long white[2];
    for (int on = 0; on < 2; on++) {
        f->vs.hulls = on;
        refresh_ok(f, 20 + on);
        unsigned char *rgb = read_frame(f, 20 + on, "left", TW, TH);
        white[on] = 0;
        for (size_t i = 0; i < (size_t)TW * TH; i++)
            white[on] += rgb[3 * i] == 255 && rgb[3 * i + 1] == 255 && rgb[3 * i + 2] == 255;
        assert_true(coverage(rgb, TW, TH, NULL) > 500);
        free(rgb);
    }
    print_message("white pixels: %ld with hulls off, %ld on\n", white[0], white[1]);
    assert_int_equal(white[0], 0);
    assert_true(white[1] > 50);
}

/* An object whose shape is not built is skipped. */
static void test_unbuilt_skipped(void **state)
{
    fixture *f = *state;
    add(f, "raw", SHAPE_SPHERE, v3(0, 1, 0), 255, 255, 255);
    assert_int_equal(view_render(&f->v, &f->w, &f->vs, f->err, sizeof f->err), 0);
    int w, h;
    const unsigned char *l = view_pixels(f->v, 0, &w, &h);
    assert_int_equal(coverage(l, w, h, NULL), 0);
}

/* (5) an output folder that cannot be created is an error naming it. */
static void test_output_unwritable(void **state)
{
    fixture *f = *state;
    add_sphere(f, v3(0, 1, 0), 0.2, 255, 0, 0);
    char plain[128];
    snprintf(plain, sizeof plain, "%s/plain", f->dir);
    FILE *fp = fopen(plain, "w");
    assert_non_null(fp);
    fclose(fp);
    snprintf(f->vs.output, sizeof f->vs.output, "%s/sub/frames", plain);
    f->err[0] = '\0';
    assert_int_equal(view_refresh(&f->v, &f->w, &f->vs, 0, &f->st, f->err, sizeof f->err), -1);
    assert_non_null(strstr(f->err, f->vs.output));
    assert_non_null(strstr(f->err, strerror(ENOTDIR)));
    assert_int_equal(f->st.frames_written, 0);
    /* the output path itself a regular file */
    snprintf(f->vs.output, sizeof f->vs.output, "%s", plain);
    assert_int_equal(view_refresh(&f->v, &f->w, &f->vs, 0, &f->st, f->err, sizeof f->err), -1);
    assert_non_null(strstr(f->err, plain));
}

/* (6) no view direction, or up along it: -1 and a message, no crash. */
static void test_bad_head(void **state)
{
    fixture *f = *state;
    add_sphere(f, v3(0, 1, 0), 0.2, 255, 0, 0);
    f->vs.look_at = f->vs.head = v3(1, 2, 3);
    f->err[0] = '\0';
    assert_int_equal(view_render(&f->v, &f->w, &f->vs, f->err, sizeof f->err), -1);
    assert_non_null(strstr(f->err, "look_at"));
    assert_int_equal(view_refresh(&f->v, &f->w, &f->vs, 0, &f->st, f->err, sizeof f->err), -1);
    assert_false(exists(frame_path(f, 0, "left")));

    f->vs.look_at = v3(1, 2, 5);
    f->vs.up = v3(0, 0, 2);
    f->err[0] = '\0';
    assert_int_equal(view_render(&f->v, &f->w, &f->vs, f->err, sizeof f->err), -1);
    assert_non_null(strstr(f->err, "parallel"));

    f->vs.up = v3(0, 1, 0);
    f->vs.fov = 180;
    assert_int_equal(view_render(&f->v, &f->w, &f->vs, f->err, sizeof f->err), -1);
    assert_non_null(strstr(f->err, "fov"));
    f->vs.fov = 60;
    assert_int_equal(view_render(&f->v, &f->w, &f->vs, f->err, sizeof f->err), 0);
}

/* (7) nested output folders are created; frames go on into an existing one. */
static void test_nested_output(void **state)
{
    fixture *f = *state;
    add_sphere(f, v3(0, 1, 0), 0.2, 255, 0, 0);
    snprintf(f->vs.output, sizeof f->vs.output, "%s/a/b//c/", f->dir);
    refresh_ok(f, 1);
    refresh_ok(f, 2);
    char path[256];
    for (long fr = 1; fr <= 2; fr++) {
        snprintf(path, sizeof path, "%s/a/b/c/frame-%06ld-left.png", f->dir, fr);
        assert_true(exists(path));
        snprintf(path, sizeof path, "%s/a/b/c/frame-%06ld-right.png", f->dir, fr);
        assert_true(exists(path));
    }
    assert_int_equal(f->st.frames_written, 4);
}

/* A new image_size re-creates the context; a bad one is an error. */
static void test_resize(void **state)
{
    fixture *f = *state;
    add_sphere(f, v3(0, 1, 0), 0.2, 255, 0, 0);
    assert_int_equal(view_display(&f->v, &f->vs, f->err, sizeof f->err), 0);
    assert_non_null(f->v);
    assert_null(view_pixels(f->v, 0, NULL, NULL));
    assert_int_equal(view_render(&f->v, &f->w, &f->vs, f->err, sizeof f->err), 0);
    f->vs.image_w = 64;
    f->vs.image_h = 48;
    assert_int_equal(view_render(&f->v, &f->w, &f->vs, f->err, sizeof f->err), 0);
    int w, h;
    const unsigned char *rgb = view_pixels(f->v, 1, &w, &h);
    assert_non_null(rgb);
    assert_int_equal(w, 64);
    assert_int_equal(h, 48);
    const unsigned char *c = px(rgb, 64, 32, 24);
    assert_true(c[0] > 100 && c[1] < 50);
    f->vs.image_w = 0;
    assert_int_equal(view_display(&f->v, &f->vs, f->err, sizeof f->err), -1);
    assert_null(f->v);
    assert_non_null(strstr(f->err, "image_size"));
}

/* Two views at once each keep their own context. */
static void test_two_views(void **state)
{
    fixture *f = *state;
    add_sphere(f, v3(0, 1, 0), 0.2, 255, 0, 0);
    view *other = NULL;
    world w2;
    world_init(&w2);
    view_settings vs2 = f->vs;
    vs2.image_w = 32;
    vs2.image_h = 32;
    assert_int_equal(view_render(&f->v, &f->w, &f->vs, f->err, sizeof f->err), 0);
    assert_int_equal(view_render(&other, &w2, &vs2, f->err, sizeof f->err), 0);
    assert_int_equal(view_render(&f->v, &f->w, &f->vs, f->err, sizeof f->err), 0);
    int w, h;
    const unsigned char *rgb = view_pixels(f->v, 0, &w, &h);
    assert_int_equal(w, TW);
    assert_true(px(rgb, TW, TW / 2, TH / 2)[0] > 100);
    const unsigned char *empty = view_pixels(other, 0, &w, &h);
    assert_int_equal(w, 32);
    assert_int_equal(coverage(empty, w, h, NULL), 0);
    view_free(other);
    world_free(&w2);
}

/* png_out round trip. */
static void test_png_roundtrip(void **state)
{
    fixture *f = *state;
    enum { W = 37, H = 11 };
    unsigned char img[W * H * 3];
    for (int i = 0; i < W * H * 3; i++) img[i] = (unsigned char)(i * 7 + i / 13);
    char path[128], err[256];
    snprintf(path, sizeof path, "%s/rt.png", f->dir);
    assert_int_equal(png_write_rgb(path, img, W, H, err, sizeof err), 0);
    unsigned char *back;
    int w, h;
    assert_int_equal(png_read_rgb(path, &back, &w, &h), 0);
    assert_int_equal(w, W);
    assert_int_equal(h, H);
    assert_memory_equal(back, img, sizeof img);
    free(back);
    snprintf(path, sizeof path, "%s/missing/rt.png", f->dir);
    assert_int_equal(png_write_rgb(path, img, W, H, err, sizeof err), -1);
    assert_non_null(strstr(err, path));
    assert_int_equal(png_read_rgb(path, &back, &w, &h), -1);
    assert_null(back);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test_setup_teardown(test_pair_files, setup, teardown),
        cmocka_unit_test_setup_teardown(test_orientation, setup, teardown),
        cmocka_unit_test_setup_teardown(test_parallax, setup, teardown),
        cmocka_unit_test_setup_teardown(test_zero_ipd, setup, teardown),
        cmocka_unit_test_setup_teardown(test_sbs, setup, teardown),
        cmocka_unit_test_setup_teardown(test_anaglyph, setup, teardown),
        cmocka_unit_test_setup_teardown(test_mono, setup, teardown),
        cmocka_unit_test_setup_teardown(test_hulls, setup, teardown),
        cmocka_unit_test_setup_teardown(test_real, setup, teardown),
        cmocka_unit_test_setup_teardown(test_unbuilt_skipped, setup, teardown),
        cmocka_unit_test_setup_teardown(test_output_unwritable, setup, teardown),
        cmocka_unit_test_setup_teardown(test_bad_head, setup, teardown),
        cmocka_unit_test_setup_teardown(test_nested_output, setup, teardown),
        cmocka_unit_test_setup_teardown(test_resize, setup, teardown),
        cmocka_unit_test_setup_teardown(test_two_views, setup, teardown),
        cmocka_unit_test_setup_teardown(test_png_roundtrip, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
