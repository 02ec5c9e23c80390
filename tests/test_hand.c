/* test_hand.c: the hand's parts alone, and what the views show of it.
 *
 * The tracker path (linear position, slerp orientation, exact rates), the row
 * parser's limits, the panel's hit testing in any pose, a live feed through a real
 * FIFO (rows as they come; a writer that goes away ends it; none yet is not an
 * end), bad tracker files that change nothing, and images: the panel and the hand
 * drawn in both eyes where the eyes' projection puts them, with the parallax of
 * their depth, a label legible at 640x512 from 0.6 m, and the hand drawn whatever
 * `real` says; a live source (the window's mouse) whose hand_log, replayed as a
 * tracker file, gives the same world to the bit; and the ray through a pixel
 * (view_ray) against an independent projection.  The physics of holding and
 * throwing is tested through vroc -b (tests/hand.sh), which does not depend on
 * the core's insides.
 *
 * Projection (view.c): the head at the origin looking along +y with z up, eyes at
 * -+ipd/2 along x, frusta sharing the window at D = |look_at - head|.  A point
 * (x, d, z) lands in the left eye at column W/2 (1 + ((x + ipd/2)/d - ipd/(2D)) /
 * (t W/H)) and row H/2 (1 - z / (d t)), t = tan(fov/2); in the right eye with
 * -ipd.  So its parallax, left column less right, is (H/2) ipd (1/d - 1/D) / t.
 */
#include "check.h"
#include "scratch.h"

#include <fcntl.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "hand/feed.h"
#include "hand/panel.h"
#include "hand/tracker.h"
#include "shell/shell.h"
#include "shell/writer.h"
#include "view/view.h"

static int setup_dir(void **state)
{
    (void)state;
    return scratch_make("hand");
}

static int teardown_dir(void **state)
{
    (void)state;
    return scratch_remove();
}

static const char *in_dir(const char *name)
{
    static char path[2][256];
    static int k;
    k = 1 - k;
    snprintf(path[k], sizeof path[k], "%s/%s", g_dir, name);
    return path[k];
}

static void write_text(const char *path, const char *text)
{
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

/* ---- the path ---- */

static void path_is_linear_and_slerp_with_exact_rates(void **state)
{
    (void)state;
    /* a turn of 1.2 rad about (1, 2, 2)/3 from 0.5 to 1.3 s, and a move */
    quat q0 = q_axis_angle(v3(0, 0, 1), 0.3);
    quat q1 = q_mul(q_axis_angle(v3(1, 2, 2), 1.2), q0);
    char text[512];
    snprintf(text, sizeof text,
             "# a comment\n time , x,y,z,qw,qx,qy,qz,trigger,button \n"
             "0.5,1,2,3,%.17g,%.17g,%.17g,%.17g,0,0\n\n1.3,1.8,1.6,3.4,%.17g,%.17g,%.17g,%.17g,1,0\n",
             q0.w, q0.x, q0.y, q0.z, q1.w, q1.x, q1.y, q1.z);
    write_text(in_dir("p.csv"), text);
    tracker_path tp;
    char err[512];
    if (tracker_load(in_dir("p.csv"), &tp, err, sizeof err) != 0) fail_msg("%s", err);
    assert_int_equal(tp.n, 2);
    assert_true(tp.rows[1].trigger && !tp.rows[0].trigger);
    vec3 p, v, w;
    quat q;
    for (double s = 0; s <= 1; s += 0.125) {
        tracker_pose(&tp, 0.5 + 0.8 * s, &p, &q);
        assert_vec_near(p, v3(1 + 0.8 * s, 2 - 0.4 * s, 3 + 0.4 * s), 1e-14);
        quat want = q_mul(q_axis_angle(v3(1, 2, 2), 1.2 * s), q0);
        assert_near(fabs(q.w * want.w + q.x * want.x + q.y * want.y + q.z * want.z), 1, 1e-14);
    }
    tracker_segment_rates(&tp, 0, &v, &w);
    assert_vec_near(v, v3(1, -0.5, 0.5), 1e-14);
    assert_vec_near(w, v3_scale(v3(1, 2, 2), 1.2 / 3 / 0.8), 1e-14);
    /* before the first row, the first; after the last, the last; no rates there */
    tracker_pose(&tp, 0.1, &p, &q);
    assert_vec_near(p, v3(1, 2, 3), 0);
    tracker_pose(&tp, 9, &p, &q);
    assert_vec_near(p, v3(1.8, 1.6, 3.4), 0);
    tracker_segment_rates(&tp, 1, &v, &w);
    assert_vec_near(v, v3(0, 0, 0), 0);
    tracker_free(&tp);
}

/* The row is refused with a message that says want. */
static void bad_row(const char *line, const char *want)
{
    tracker_row r;
    char err[256];
    assert_int_equal(tracker_parse_row(line, &r, err, sizeof err), -1);
    if (!strstr(err, want)) fail_msg("'%s': '%s' lacks '%s'", line, err, want);
}

static void rows_are_checked(void **state)
{
    (void)state;
    tracker_row r;
    char err[256];
    assert_int_equal(tracker_parse_row("0,1,2,3,1.0000009,0,0,0,1,1", &r, err, sizeof err), 0);
    assert_near(q_len(r.q), 1, 1e-15); /* normalised within 1e-6 */
    assert_true(r.trigger && r.button);
    bad_row("0,1,2,3,1.0000011,0,0,0,1,1", "not a unit one");
    bad_row("0,1,2,3,1,0,0,0,1", "9 columns");
    bad_row("0,1,2,3,1,0,0,0,1,0,7", "more than 10 columns");
    bad_row("-1,1,2,3,1,0,0,0,1,0", "time must be between 0 and 1e+12 (got -1)");
    /* the limits every statement has (core/limits.h): just inside and just outside */
    assert_int_equal(tracker_parse_row("1e12,-1e6,1e6,0,1,0,0,0,0,0", &r, err, sizeof err), 0);
    bad_row("1.0000001e12,1,2,3,1,0,0,0,1,0", "time must be between 0 and 1e+12");
    bad_row("0,1e308,2,3,1,0,0,0,1,0", "x must be between -1e+06 and 1e+06 (got 1e+308)");
    bad_row("0,1,-1000000.1,3,1,0,0,0,1,0", "y must be between -1e+06 and 1e+06");
    bad_row("0,1,2,1.0000001e6,1,0,0,0,1,0", "z must be between");
    /* rows at one time (a jump), or 1e-6 s apart at least */
    assert_int_equal(tracker_check_spacing(1, 1, err, sizeof err), 0);
    assert_int_equal(tracker_check_spacing(1, 1 + 1.0001e-6, err, sizeof err), 0);
    assert_int_equal(tracker_check_spacing(1, 0.5, err, sizeof err), 0); /* (the order is checked apart) */
    assert_int_equal(tracker_check_spacing(1, 1 + 0.9999e-6, err, sizeof err), -1);
    assert_non_null(strstr(err, "at least 1e-06 s apart"));
    assert_int_equal(tracker_check_spacing(0, 1e-300, err, sizeof err), -1);
    bad_row("0,inf,2,3,1,0,0,0,1,0", "x must be finite");
    bad_row("0,1,2,3,1,0,0,0,0.5,0", "trigger must be 0 or 1");
    bad_row("0,1,2,3x,1,0,0,0,0,0", "z is not a number");
    assert_int_equal(tracker_line_kind("   # x"), TRACKER_SKIP);
    assert_int_equal(tracker_line_kind(TRACKER_HEADER), TRACKER_HEADER_LINE);
    /* a row written reads back to the bit */
    tracker_row a = {0.1, v3(1.0 / 3, -2e-7, 999999.12345678912), q_axis_angle(v3(1, 1, 0), 0.7), true, false}, b;
    FILE *f = fopen(in_dir("row.csv"), "w");
    assert_non_null(f);
    tracker_write_row(f, &a);
    fclose(f);
    f = fopen(in_dir("row.csv"), "r");
    char line[256];
    assert_non_null(fgets(line, sizeof line, f));
    fclose(f);
    line[strcspn(line, "\n")] = '\0';
    assert_int_equal(tracker_parse_row(line, &b, err, sizeof err), 0);
    assert_true(memcmp(&a.p, &b.p, sizeof a.p) == 0 && a.t == b.t && a.trigger == b.trigger);
}

/* ---- the panel ---- */

static void the_panel_finds_every_control_in_any_pose(void **state)
{
    (void)state;
    const quat poses[] = {q_axis_angle(v3(1, 0, 0), M_PI / 2), q_axis_angle(v3(0.3, -1, 2), 2.1),
                          q_identity()};
    const vec3 at = v3(0.4, -1, 2);
    for (size_t k = 0; k < sizeof poses / sizeof poses[0]; k++) {
        quat q = poses[k];
        /* the sheet's point (x, y) at height h over it, in the world */
#define AT(x, y, h) v3_add(at, q_rotate(q, v3((x), (y), (h))))
        for (int c = 0; c < PANEL_CONTROLS; c++) {
            const panel_control *pc = panel_control_of((panel_part)c);
            assert_int_equal(panel_hit(at, q, AT(pc->x, pc->y, 0.019)), c);
            assert_int_equal(panel_hit(at, q, AT(pc->x + 0.99 * pc->half_w, pc->y - 0.99 * pc->half_h, -0.019)), c);
            assert_int_equal(panel_hit(at, q, AT(pc->x, pc->y, 0.021)), PANEL_OFF);
        }
        assert_int_equal(panel_hit(at, q, AT(-0.16 + 0.041, 0.0625, 0)), PANEL_SHEET);
        assert_int_equal(panel_hit(at, q, AT(0.2, 0.11, 0)), PANEL_SHEET);
        assert_int_equal(panel_hit(at, q, AT(0.226, 0, 0)), PANEL_OFF);
        assert_int_equal(panel_hit(at, q, AT(0, -0.126, 0)), PANEL_OFF);
        /* slider values: 2 (x + 0.18) / 0.36, clamped */
        assert_near(panel_slider_value(at, q, AT(-0.18, -0.03, 0), 0), 0, 1e-12);
        assert_near(panel_slider_value(at, q, AT(0.09, -0.03, 0), 0), 1.5, 1e-12);
        assert_near(panel_slider_value(at, q, AT(0.2, -0.03, 0), 0), 2, 0);
        assert_near(panel_slider_value(at, q, AT(-0.2, -0.09, 0), 0.001), 0.001, 0);
        assert_near(panel_slider_x(1.5), 0.09, 1e-15);
#undef AT
    }
}

/* ---- a live feed ---- */

typedef struct {
    tracker_row rows[8];
    int n, bad;
    char last[512]; /* the last bad line's message */
} got;

static void got_row(void *ctx, const tracker_row *r)
{
    got *g = ctx;
    if (g->n < 8) g->rows[g->n++] = *r;
}

static void got_bad(void *ctx, const char *msg)
{
    got *g = ctx;
    g->bad++;
    snprintf(g->last, sizeof g->last, "%s", msg);
}

static void a_fifo_feeds_rows_as_they_come(void **state)
{
    (void)state;
    const char *path = in_dir("hand.fifo");
    assert_int_equal(mkfifo(path, 0600), 0);
    assert_true(feed_is_fifo(path));
    tracker_feed f;
    feed_init(&f);
    char err[256];
    assert_int_equal(feed_open(&f, path, err, sizeof err), 0);
    got g = {.n = 0};
    /* no writer yet: waiting, not ended */
    assert_int_equal(feed_read(&f, got_row, got_bad, &g, err, sizeof err), FEED_WAITING);
    int wfd = open(path, O_WRONLY | O_NONBLOCK);
    assert_true(wfd >= 0);
    const char *part = TRACKER_HEADER "\n0.5,1,2,3,1,0,0,0,1,0\nnot a row\n0.6,1,2";
    assert_int_equal(write(wfd, part, strlen(part)), (ssize_t)strlen(part));
    assert_int_equal(feed_read(&f, got_row, got_bad, &g, err, sizeof err), FEED_WAITING);
    assert_int_equal(g.n, 1); /* the unfinished line waits for its end */
    assert_int_equal(g.bad, 1);
    assert_non_null(strstr(g.last, ":3: "));
    assert_near(g.rows[0].p.y, 2, 0);
    const char *rest = ",4,1,0,0,0,0,1\n";
    assert_int_equal(write(wfd, rest, strlen(rest)), (ssize_t)strlen(rest));
    assert_int_equal(feed_read(&f, got_row, got_bad, &g, err, sizeof err), FEED_WAITING);
    assert_int_equal(g.n, 2);
    assert_true(!g.rows[1].trigger && g.rows[1].button && g.rows[1].p.z == 4);
    /* the limits a file has: a row 1e-7 s after the last, one 2e6 m away, left out */
    const char *more = "0.6000001,1,2,4,1,0,0,0,0,0\n0.7,2e6,2,4,1,0,0,0,0,0\n0.6000011,1,2,5,1,0,0,0,0,0\n";
    assert_int_equal(write(wfd, more, strlen(more)), (ssize_t)strlen(more));
    assert_int_equal(feed_read(&f, got_row, got_bad, &g, err, sizeof err), FEED_WAITING);
    assert_int_equal(g.bad, 3);
    assert_non_null(strstr(g.last, "hand.fifo:6: x must be between -1e+06 and 1e+06 (got 2e+06)"));
    assert_int_equal(g.n, 3); /* 1e-6 s after the last row taken: taken */
    assert_near(g.rows[2].p.z, 5, 0);
    close(wfd); /* the writer goes away */
    assert_int_equal(feed_read(&f, got_row, got_bad, &g, err, sizeof err), FEED_ENDED);
    feed_close(&f);
    assert_int_equal(f.fd, -1);
}

/* ---- through the shell ---- */

typedef struct {
    shell sh;
    char *out, *errs;
    size_t outlen, errlen;
} shell_fix;

static void shell_open(shell_fix *s)
{
    memset(s, 0, sizeof *s);
    FILE *out = open_memstream(&s->out, &s->outlen);
    FILE *err = open_memstream(&s->errs, &s->errlen);
    shell_init(&s->sh, out, err);
    s->sh.quiet = true;
    s->sh.stop_on_error = true;
}

static void shell_close(shell_fix *s)
{
    FILE *out = s->sh.out, *err = s->sh.err;
    shell_free(&s->sh);
    fclose(out);
    fclose(err);
    free(s->out);
    free(s->errs);
}

static void must(shell_fix *s, const char *text)
{
    if (shell_run_text(&s->sh, text, NULL) != CMD_OK) {
        fflush(s->sh.err);
        fail_msg("'%s' failed: %s", text, s->errs);
    }
}

static char *snapshot(shell *sh)
{
    char *text;
    size_t len;
    FILE *f = open_memstream(&text, &len);
    int shown = sh->set.precision; /* every setting to the bit, and then put back */
    sh->set.precision = FMT_EXACT;
    settings_write(f, sh, 0);
    sh->set.precision = shown;
    fprintf(f, "precision %d\n", shown);
    for (int i = 0; i < sh->w.n; i++) body_write(f, sh->w.bodies[i], (write_style){FMT_EXACT, false, NULL});
    fclose(f);
    return text;
}

static void a_bad_tracker_file_changes_nothing(void **state)
{
    (void)state;
    static const char *const bad[] = {
        "time,x,y,z,qw,qx,qy,qz,trigger,button\n0,0,0,0,1,0,0,0,0,0\n0,0,0,nan,1,0,0,0,0,0\n",
        "time,x,y,z,qw,qx,qy,qz,trigger,button\n0.2,0,0,0,1,0,0,0,0,0\n0.1,0,0,0,1,0,0,0,0,0\n",
        "time,x,y,z,qw,qx,qy,qz,trigger,button\n0,0,0,0,0.9,0,0,0,1,0\n",
        "time,x,y,z,qw,qx,qy,qz,trigger\n0,0,0,0,1,0,0,0,1\n",
        "\x7f" "ELF binary\n",
    };
    write_text(in_dir("good.csv"), "time,x,y,z,qw,qx,qy,qz,trigger,button\n0,0.5,0,0,1,0,0,0,1,0\n"
                                   "1,0.5,1,0,1,0,0,0,0,0\n");
    for (size_t k = 0; k < sizeof bad / sizeof bad[0]; k++) {
        shell_fix s;
        shell_open(&s);
        char text[600];
        snprintf(text, sizeof text, "sphere ball; radius = 0.1; translate = (0.5, 0, 0); select on\n"
                                    "tracker = \"%s\"; run 3; hand_rotate = (0, 0, 1) 0.5\n",
                 in_dir("good.csv"));
        must(&s, text);
        char *before = snapshot(&s.sh);
        assert_non_null(strstr(before, "grip = ball"));
        write_text(in_dir("bad.csv"), bad[k]);
        snprintf(text, sizeof text, "tracker = \"%s\"\n", in_dir("bad.csv"));
        assert_int_equal(shell_run_text(&s.sh, text, NULL), CMD_ERROR);
        fflush(s.sh.err);
        if (!strstr(s.errs, "bad.csv:")) fail_msg("no file:line in '%s'", s.errs);
        char *after = snapshot(&s.sh);
        assert_string_equal(before, after);
        /* the old tracker plays on: the ball is let go at 1 s */
        must(&s, "run 10");
        assert_false(s.sh.w.bodies[0]->held);
        free(before);
        free(after);
        shell_close(&s);
    }
}

/* ---- images ---- */

#define W 640
#define HT 512
static const int BG[3] = {10, 20, 40};

static bool is_bg(const unsigned char *p)
{
    return p[0] == BG[0] && p[1] == BG[1] && p[2] == BG[2];
}

/* The box [x0, x1) x [y0, y1) of the pixels that pass keep, within the box
 * given; false when none. */
static bool bbox(const unsigned char *rgb, bool (*keep)(const unsigned char *), int bx0, int by0, int bx1,
                 int by1, int *x0, int *y0, int *x1, int *y1)
{
    *x0 = *y0 = 1 << 30;
    *x1 = *y1 = -1;
    for (int y = by0; y < by1; y++)
        for (int x = bx0; x < bx1; x++)
            if (keep(rgb + 3 * ((size_t)y * W + x))) {
                if (x < *x0) *x0 = x;
                if (y < *y0) *y0 = y;
                if (x + 1 > *x1) *x1 = x + 1;
                if (y + 1 > *y1) *y1 = y + 1;
            }
    return *x1 > 0;
}

static bool not_bg(const unsigned char *p) { return !is_bg(p); }

/* Where the eyes project world point (x, d, z), d ahead of the eyes: column (eye
 * 0 left, 1 right) and row, as the header says (fov 60, ipd 0.064, the focal
 * distance D). */
static double column_at(int eye, double x, double d, double D)
{
    double t = tan(M_PI / 6), ipd = eye == 0 ? 0.064 : -0.064;
    return W / 2.0 * (1 + ((x + ipd / 2) / d - ipd / (2 * D)) / (t * W / HT));
}

/* The same with the default look_at, D = 1. */
static double column(int eye, double x, double d)
{
    return column_at(eye, x, d, 1);
}

static double row(double z, double d)
{
    return HT / 2.0 * (1 - z / (d * tan(M_PI / 6)));
}

static const unsigned char *eye_pixels(shell *sh, int eye)
{
    int w, h;
    const unsigned char *rgb = view_pixels(sh->view, eye, &w, &h);
    assert_non_null(rgb);
    assert_int_equal(w, W);
    assert_int_equal(h, HT);
    return rgb;
}

static void render(shell_fix *s, const char *text)
{
    char all[800];
    snprintf(all, sizeof all, "restart; background = (10, 20, 40); output = \"%s\"\n%s\nrefresh\n",
             in_dir("frames"), text);
    must(s, all);
}

static void the_panel_and_hand_appear_where_the_eyes_project_them(void **state)
{
    (void)state;
    shell_fix s;
    shell_open(&s);
    /* the panel facing the head, 0.6 m away (nearer than D: crossed parallax) */
    render(&s, "panel = on; panel_at = (0.05, 0.6, 0.02); panel_rotate = (1, 0, 0) 1.5707963267948966");
    double want_disp = HT / 2.0 * 0.064 * (1 / 0.6 - 1) / tan(M_PI / 6), c[2];
    for (int eye = 0; eye < 2; eye++) {
        int x0, y0, x1, y1;
        assert_true(bbox(eye_pixels(&s.sh, eye), not_bg, 0, 0, W, HT, &x0, &y0, &x1, &y1));
        /* the sheet's corners, 0.225 and 0.125 from its centre */
        assert_near(x0, column(eye, 0.05 - 0.225, 0.6), 1.5);
        assert_near(x1, column(eye, 0.05 + 0.225, 0.6), 1.5);
        assert_near(y0, row(0.02 + 0.125, 0.6), 1.5);
        assert_near(y1, row(0.02 - 0.125, 0.6), 1.5);
        c[eye] = 0.5 * (x0 + x1);
    }
    assert_near(c[0] - c[1], want_disp, 1.0);
    assert_true(c[0] - c[1] > 15); /* crossed: further right in the left eye */

    /* the hand alone, 0.8 m away (nearer than D), pointing along +x: its tip is
     * the right end of what is drawn, its body 8 cm long and 2.4 cm wide (16
     * pixels at that distance, more than the least, 12) */
    render(&s, "hand = (-0.3, 0.8, -0.2)");
    want_disp = HT / 2.0 * 0.064 * (1 / 0.8 - 1) / tan(M_PI / 6);
    for (int eye = 0; eye < 2; eye++) {
        int x0, y0, x1, y1;
        assert_true(bbox(eye_pixels(&s.sh, eye), not_bg, 0, 0, W, HT, &x0, &y0, &x1, &y1));
        /* (the tip is a point: its last pixels are too thin to be drawn) */
        assert_true(x1 <= column(eye, -0.3, 0.8) + 1.5 && x1 >= column(eye, -0.3, 0.8) - 4);
        /* (the base is a square along the line of sight: its near edge, 1.2 cm
         * nearer, reaches furthest left and down, its far edge up, below the eyes) */
        assert_near(x0, column(eye, -0.38, 0.788), 1.5);
        assert_near(y0, row(-0.2 + 0.012, 0.812), 1.5);
        assert_near(y1, row(-0.2 - 0.012, 0.788), 1.5);
        c[eye] = x0;
    }
    assert_near(c[0] - c[1], want_disp, 1.0);
    assert_true(c[0] - c[1] > 5);
    /* far away, 1.5 m (beyond D: uncrossed) and 6 m, the pointer is drawn larger
     * about its tip, so that it stays 12 pixels across (2.4 cm would be 7 and 2) */
    for (int k = 0; k < 2; k++) {
        double d = k == 0 ? 1.5 : 6;
        char text[96];
        snprintf(text, sizeof text, "hand = (-0.3, %g, -0.2)", d);
        render(&s, text);
        double px_per_m = HT / (2 * d * tan(M_PI / 6)), scale = 12 / (0.024 * px_per_m);
        for (int eye = 0; eye < 2; eye++) {
            int x0, y0, x1, y1;
            assert_true(bbox(eye_pixels(&s.sh, eye), not_bg, 0, 0, W, HT, &x0, &y0, &x1, &y1));
            double h = 0.012 * scale, near = d - h, far = d + h; /* the base's edges */
            assert_true(y1 - y0 >= 12);
            assert_near(y0, row(-0.2 + h, far), 1.5);
            assert_near(y1, row(-0.2 - h, near), 1.5);
            assert_near(x0, column(eye, -0.3 - 0.08 * scale, near), 1.5);
            c[eye] = x0;
        }
        if (k == 0) assert_true(c[0] - c[1] < -5);
    }

    /* real = hidden hides the room, not the hand (nor the panel) */
    render(&s, "cube wall; mass = -1; size = (2, 0.1, 2); translate = (0, 3, 0); real = hidden\n"
               "hand = (0, 1.5, 0); panel = on; panel_at = (0, 1, -0.3)");
    for (int eye = 0; eye < 2; eye++) {
        int x0, y0, x1, y1;
        assert_true(bbox(eye_pixels(&s.sh, eye), not_bg, W / 2 - 20, HT / 2 - 20, W / 2 + 20, HT / 2 + 20, &x0,
                         &y0, &x1, &y1));
    }
    /* and nothing of the hand or the panel is drawn before they are used */
    render(&s, "sphere ball; mass = -1; radius = 0.01; translate = (0, 5, 0); real = hidden");
    for (int eye = 0; eye < 2; eye++) {
        int x0, y0, x1, y1;
        assert_false(bbox(eye_pixels(&s.sh, eye), not_bg, 0, 0, W, HT, &x0, &y0, &x1, &y1));
    }
    shell_close(&s);
}

/* The labels' ink (20, 22, 28), darker than the lit sheet around the button. */
static bool dark(const unsigned char *p) { return p[0] < 45 && p[1] < 45 && p[2] < 45 && !is_bg(p); }

static void a_label_is_legible_at_640x512_from_0_6_m(void **state)
{
    (void)state;
    shell_fix s;
    shell_open(&s);
    render(&s, "head = (0, 0.4, 0); look_at = (0, 1, 0); panel = on; panel_at = (0, 1, 0)\n"
               "panel_rotate = (1, 0, 0) 1.5707963267948966");
    /* SELECT's label: baseline 0.034 below the button's centre (0.16, 0.0625), 13
     * mm tall, 5.5 / 6 of that per letter less a gap: 68 mm wide */
    double d = 0.6, top = row(0.0625 - 0.034 + 0.013, d), bottom = row(0.0625 - 0.034, d);
    double left = column_at(0, 0.16 - 0.034125, d, d), right = column_at(0, 0.16 + 0.034125, d, d);
    int x0, y0, x1, y1;
    assert_true(bbox(eye_pixels(&s.sh, 0), dark, (int)left - 3, (int)top - 3, (int)right + 3, (int)bottom + 3, &x0,
                     &y0, &x1, &y1));
    assert_true(y1 - y0 >= 9); /* letters at least 9 pixels tall */
    assert_near(y1 - y0, bottom - top + 2, 2);
    assert_near(x1 - x0, right - left + 2, 3);
    /* six letters with gaps: runs of columns with strokes, separated */
    const unsigned char *rgb = eye_pixels(&s.sh, 0);
    int runs = 0;
    bool in = false;
    for (int x = x0; x < x1; x++) {
        bool any = false;
        for (int y = y0; y < y1 && !any; y++) any = dark(rgb + 3 * ((size_t)y * W + x));
        if (any && !in) runs++;
        in = any;
    }
    assert_true(runs >= 6);
    shell_close(&s);
}

/* ---- a live source (the window's mouse) ---- */

/* A small generator of the test's own (xorshift64*), in [0, 1). */
static double uniform(unsigned long long *st)
{
    *st ^= *st >> 12;
    *st ^= *st << 25;
    *st ^= *st >> 27;
    return (double)((*st * 2685821657736338717ULL) >> 11) / 9007199254740992.0;
}

/* The world of the live source's test: a ball at the hand's first place, another
 * moving, a floor (no gravity: a ball let go stays in reach). */
static const char *const live_world =
    "cube floor; size = (4, 4, 0.2); translate = (0, 1, -0.8); mass = -1\n"
    "sphere ball; radius = 0.1; translate = (0, 1, 0); sphere other; radius = 0.15\n"
    "translate = (0.6, 1.2, -0.3); linear_vel = (-0.2, 0, -0.3); select on\n";

/* A session of the live source: the hand moves on the wall clock while time
 * stands still (as at the prompt), then hand_log opens, and for `frames` frames of
 * time_step h (h2 from frame 12 on) the source grabs the ball at frame 4 (the
 * trigger down for one sample only: a click shorter than a frame), lets it drop,
 * grabs it again, wanders with it, throws it at 20, and presses re-select at 25.  Then the log, replayed as a
 * tracker file from a fresh start with the same frames, must give the same world
 * to the bit: every object's state and the same hash. */
static void live_session(double h, double h2, unsigned long long seed)
{
    unsigned long long st = seed;
    shell_fix a, b;
    shell_open(&a);
    shell_open(&b);
    must(&a, live_world);
    must(&b, live_world);
    char text[600];
    snprintf(text, sizeof text, "time_step = %.17g", h);
    must(&a, text);
    must(&b, text);
    hand *ha = &a.sh.hand;
    /* stood still, on the wall clock: the hand jumps with the source */
    tracker_row r = {0, v3(0.3, 1, 0.2), q_identity(), false, false};
    for (int k = 0; k < 5; k++) {
        hand_wall(ha, &a.sh.w, 0.013 + 0.01 * uniform(&st));
        r.p.x -= 0.06;
        r.p.z -= 0.04;
        hand_live(ha, &a.sh.w, &r);
        hand_live_act(ha, &a.sh.w);
    }
    assert_true(ha->clock > 0);
    snprintf(text, sizeof text, "hand_log = \"%s\"", in_dir("live.csv"));
    must(&a, text);
    int frames = 40, held = 0;
    for (int k = 0; k < frames; k++) {
        if (k == 12) {
            snprintf(text, sizeof text, "time_step = %.17g", h2);
            must(&a, text);
        }
        if (k >= 7) /* (at the ball's centre until it is held again) */
            r.p = v3_add(r.p, v3(0.05 * (uniform(&st) - 0.3), 0.02 * (uniform(&st) - 0.5), 0.05 * (uniform(&st) - 0.3)));
        r.trigger = k == 4 || (k >= 6 && k < 20);
        r.button = k == 25;
        hand_live(ha, &a.sh.w, &r);
        if (shell_advance(&a.sh, NULL, 1) != CMD_OK) {
            fflush(a.sh.err);
            fail_msg("frame %d: %s", k, a.errs);
        }
        held += a.sh.w.bodies[1]->held;
    }
    hand_live(ha, &a.sh.w, NULL);
    assert_true(held >= 8); /* it was held, */
    assert_true(v3_len(a.sh.w.bodies[1]->v) > 0.1); /* and thrown */
    must(&a, "hand_log = off");

    snprintf(text, sizeof text, "tracker = \"%s\"", in_dir("live.csv"));
    must(&b, text);
    for (int k = 0; k < frames; k++) {
        if (k == 12) {
            snprintf(text, sizeof text, "time_step = %.17g", h2);
            must(&b, text);
        }
        assert_int_equal(shell_advance(&b.sh, NULL, 1), CMD_OK);
    }
    char *sa = snapshot(&a.sh), *sb = snapshot(&b.sh);
    /* (the settings of the hand differ: one was told by a tracker file) */
    const char *oa = strstr(sa, "sphere ball"), *ob = strstr(sb, "sphere ball");
    assert_non_null(oa);
    assert_non_null(ob);
    assert_string_equal(oa, ob);
    assert_true(world_hash(&a.sh.w) == world_hash(&b.sh.w));
    free(sa);
    free(sb);
    shell_close(&a);
    shell_close(&b);
}

static void a_live_source_replays_from_its_log_to_the_bit(void **state)
{
    (void)state;
    live_session(0.1, 0.1, 1);
    live_session(0.1, 0.05, 2);
    live_session(1.0 / 3, 1.0 / 7, 3);
    live_session(0.125, 0.03, 4);
}

/* What view_ray gives meets the point that an independent projection puts at its
 * pixel: for an eye at e = s ipd/2 along r (s = -1 left, +1 right, 0 the head's
 * own) and the window shared at D = |look_at - head|, a point at (x, y, z) in
 * the head's axes (r, u, f) is at X = e + (x - e) D / z, Y = y D / z on that
 * window, which spans D tan(fov/2) (W/H) by D tan(fov/2) from its centre. */
static void a_ray_through_a_pixel_meets_what_projects_there(void **state)
{
    (void)state;
    unsigned long long st = 7;
    for (int n = 0; n < 200; n++) {
        view_settings vs = view_settings_defaults();
        vs.head = v3(4 * uniform(&st) - 2, 4 * uniform(&st) - 2, 4 * uniform(&st) - 2);
        vs.look_at = v3_add(vs.head, v3(3 * uniform(&st) - 1.5, 3 * uniform(&st) - 1.5, 3 * uniform(&st) - 1.5));
        vs.up = v3(uniform(&st) - 0.5, uniform(&st) - 0.5, 1);
        vs.ipd = 0.1 * uniform(&st);
        vs.fov = 20 + 120 * uniform(&st);
        vs.image_w = 16 + (int)(700 * uniform(&st));
        vs.image_h = 16 + (int)(700 * uniform(&st));
        vec3 f = v3_norm(v3_sub(vs.look_at, vs.head)), r = v3_norm(v3_cross(f, vs.up)), u = v3_cross(r, f);
        double D = v3_dist(vs.look_at, vs.head), hh = D * tan(vs.fov * M_PI / 360), hw = hh * vs.image_w / vs.image_h;
        double x = 2 * uniform(&st) - 1, y = 2 * uniform(&st) - 1, z = 0.1 + 5 * uniform(&st);
        vec3 p = v3_add(vs.head, v3_add(v3_scale(r, x), v3_add(v3_scale(u, y), v3_scale(f, z))));
        for (int eye = -1; eye <= 1; eye++) {
            double e = (eye < 0 ? 0 : eye == 0 ? -1 : 1) * vs.ipd / 2;
            double X = e + (x - e) * D / z, Y = y * D / z;
            double px = (X / hw + 1) / 2 * vs.image_w, py = (1 - Y / hh) / 2 * vs.image_h;
            vec3 o, d;
            char err[256];
            assert_int_equal(view_ray(&vs, eye, px, py, &o, &d, err, sizeof err), 0);
            assert_near(v3_len(d), 1, 1e-12);
            assert_near(v3_dist(o, v3_mad(vs.head, r, e)), 0, 1e-12);
            vec3 op = v3_sub(p, o);
            double off = v3_len(v3_sub(op, v3_scale(d, v3_dot(op, d))));
            assert_true(v3_dot(op, d) > 0);
            assert_near(off, 0, 1e-9 * (1 + v3_len(op)));
        }
    }
    view_settings bad = view_settings_defaults();
    bad.look_at = bad.head;
    vec3 o, d;
    char err[256];
    assert_int_equal(view_ray(&bad, 0, 1, 1, &o, &d, err, sizeof err), -1);
    assert_non_null(strstr(err, "same point"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(path_is_linear_and_slerp_with_exact_rates),
        cmocka_unit_test(rows_are_checked),
        cmocka_unit_test(the_panel_finds_every_control_in_any_pose),
        cmocka_unit_test(a_fifo_feeds_rows_as_they_come),
        cmocka_unit_test(a_bad_tracker_file_changes_nothing),
        cmocka_unit_test(the_panel_and_hand_appear_where_the_eyes_project_them),
        cmocka_unit_test(a_label_is_legible_at_640x512_from_0_6_m),
        cmocka_unit_test(a_live_source_replays_from_its_log_to_the_bit),
        cmocka_unit_test(a_ray_through_a_pixel_meets_what_projects_there),
    };
    return cmocka_run_group_tests(tests, setup_dir, teardown_dir);
}
