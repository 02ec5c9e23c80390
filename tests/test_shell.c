/* test_shell.c: statements run against a world: the bad-input catalogue (each entry
 * gives its message and changes nothing), objects and properties, save and read
 * round trips, what stats counts and what the speed limits say. */
#include "check.h"
#include "scratch.h"
#include "shell_fixture.h"

#include <math.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include "shell/shell.h"
#include "shell/writer.h"

static int setup(void **state)
{
    (void)state;
    shell_fixture_open();
    return scratch_make("shell");
}

static int teardown(void **state)
{
    (void)state;
    shell_fixture_close();
    return scratch_remove();
}

/* Everything the user could observe of the world, as text. */
static char *snapshot(void)
{
    char *text;
    size_t len;
    FILE *f = open_memstream(&text, &len);
    int shown = g_sh.set.precision; /* every setting to the bit, and then put back */
    g_sh.set.precision = FMT_EXACT;
    settings_write(f, &g_sh, 0);
    g_sh.set.precision = shown;
    fprintf(f, "precision %d\n", shown);
    for (int i = 0; i < g_sh.w.n; i++) body_write(f, g_sh.w.bodies[i], (write_style){FMT_EXACT, false, NULL});
    fprintf(f, "current %d time %.17g frame %ld\n", g_sh.current, g_sh.w.time, g_sh.w.frame);
    fclose(f);
    return text;
}


static void path_in_dir(char *out, size_t len, const char *name)
{
    snprintf(out, len, "%s/%s", g_dir, name);
}

/* The statements fmt makes of the path of name in the test's folder (fmt's one
 * %s), in text (returned). */
static const char *about(char *text, size_t len, const char *fmt, const char *name)
{
    char path[256];
    path_in_dir(path, sizeof path, name);
    snprintf(text, len, fmt, path);
    return text;
}

static void write_file(const char *name, const char *text, size_t n)
{
    char path[256];
    path_in_dir(path, sizeof path, name);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    fwrite(text, 1, n, f);
    fclose(f);
}

/* A world to break: a few objects with non-default state. */
static void build_world(void)
{
    assert_int_equal(run("restart; gravity; time_step = 0.05\n"
                         "sphere ball; radius = 0.25; translate = (1, 2, 3); linear_vel = (1, 0, 0)\n"
                         "cube box; size = (1, 0.5, 0.25); rotate = (1, 1, 0) 0.5; mass = 3\n"
                         "superquadric pillow; exp1 = 0.3; exp2 = 1.5; a1 = 0.5; ures = 12\n"
                         "translate = (4, 0, 0)\n"
                         "cube table; mass = -1; size = (2, 1, 0.1); translate = (0, 0, -3)\n"
                         "sphere ball\n"),
                     CMD_OK);
}

static void bad(const char *text, const char *want)
{
    build_world();
    char *before = snapshot();
    cmd_status r = run(text);
    char *after = snapshot();
    if (r != CMD_ERROR) fail_msg("'%s' did not fail", text);
    if (!strstr(g_errbuf, want)) fail_msg("'%s': message '%s' lacks '%s'", text, g_errbuf, want);
    if (strcmp(before, after) != 0)
        fail_msg("'%s' changed the world:\n--- before\n%s\n--- after\n%s", text, before, after);
    free(before);
    free(after);
}

static void the_bad_input_catalogue(void **state)
{
    (void)state;
    char path[256], text[600];
    bad("frobnicate\n", "error: unknown command 'frobnicate'");
    bad("radius =\n", "error: radius: missing value");
    bad("translate = (1, 2\n", "unfinished vector");
    bad("translate = (1, 2, x)\n", "expected a number, got 'x'");
    bad("radius = nan\n", "radius must be a finite number (got nan)");
    bad("translate = (inf, 0, 0)\n", "translate must be a finite number (got inf)");
    bad("mass = 0\n", "mass must not be 0");
    bad("radius = -1\n", "radius must be between 1e-06 and 10000 (got -1)");
    bad("radius = 1 2\n", "unexpected '2'");
    /* the first statements of a bad line do not run either: parsed whole first */
    bad("radius = 0.5; translate = (0, 0, 0); bogus\n", "unknown command 'bogus'");
    bad("nosuch.radius = 2\n", "no object named 'nosuch'");
    bad("cube ball\n", "'ball' is already a sphere; it cannot also be a cube");
    bad("delete ghost\n", "no object named 'ghost'");
    bad("print ghost\n", "no object named 'ghost'");
    bad("distance ball ghost\n", "no object named 'ghost'");
    bad("read /nonexistent/scene.vroc\n", "cannot read '/nonexistent/scene.vroc'");
    path_in_dir(path, sizeof path, "self.vroc");
    snprintf(text, sizeof text, "sphere other\nread \"%s\"\n", path);
    write_file("self.vroc", text, strlen(text));
    snprintf(text, sizeof text, "read \"%s\"\n", path);
    bad(text, "reads itself");
    write_file("garbage.vroc", "sphere z\n\x7f\x45\x4c\x46\x02\x01\x01\0\0\0", 18);
    path_in_dir(path, sizeof path, "garbage.vroc");
    snprintf(text, sizeof text, "read \"%s\"\n", path);
    bad(text, "garbage.vroc:2: error: a NUL byte");
    /* a line of LANG_MAX_LINE bytes: its long word is quoted in part; one more
     * byte, and the line is refused whole */
    size_t n = LANG_MAX_LINE - 10;
    char *big = malloc(n + 32);
    memcpy(big, "sphere z\nradius = ", 18);
    memset(big + 18, '7', n);
    memcpy(big + 18 + n, "x\n", 3);
    write_file("long.vroc", big, strlen(big));
    path_in_dir(path, sizeof path, "long.vroc");
    snprintf(text, sizeof text, "read \"%s\"\n", path);
    bad(text, "long.vroc:2: error: radius must be a finite number (got '7777");
    memcpy(big + 18 + n, "7x\n", 4);
    write_file("long.vroc", big, strlen(big));
    bad(text, "long.vroc:2: error: a line longer than 1048576 bytes");
    free(big);
    path_in_dir(path, sizeof path, "late-typo.vroc");
    write_file("late-typo.vroc", "sphere early\nradius = 9\n\n\n\nradius = 9\nradiuss = 1\n", 46);
    snprintf(text, sizeof text, "read \"%s\"\n", path);
    bad(text, "late-typo.vroc:7: error: unknown command 'radiuss'");
    bad("save /nonexistent/dir/world.vroc\n", "cannot write '/nonexistent/dir/world.vroc'");
    bad("trace = /nonexistent/dir/t.csv\n", "cannot write '/nonexistent/dir/t.csv'");
    bad("collision_sound = /nonexistent.wav\n", "cannot read '/nonexistent.wav'");
    /* sound and movies: the sound in use and the outputs stay as they were */
    write_file("empty.wav", "", 0);
    write_file("words.wav", "not a sound at all\n", 19);
    bad(about(text, sizeof text, "collision_sound = \"%s\"\n", "empty.wav"), "is empty");
    bad(about(text, sizeof text, "collision_sound = \"%s\"\n", "words.wav"),
        "is not a sound file libsndfile can read");
    snprintf(text, sizeof text, "collision_sound = \"%s\"\n", g_dir);
    bad(text, "': it is a folder");
    about(text, sizeof text, "collision_sound = bell; collision_sound = \"%s\"\n", "words.wav");
    assert_int_equal(run(text), CMD_ERROR);
    assert_string_equal(g_sh.sound_set.collision_sound, "bell");
    bad("collision_vol = -0.5\n", "collision_vol must be between 0 and 1000 (got -0.5)");
    bad("volume = -1\n", "volume must be between 0 and 1000 (got -1)");
    bad("soundtrack = /nonexistent/dir/t.wav\n", "soundtrack: cannot write '/nonexistent/dir/t.wav'");
    bad("movie = /nonexistent/dir/m.mp4\n", "movie: cannot write '/nonexistent/dir/m.mp4'");
    bad(about(text, sizeof text, "movie = \"%s\"\n", "movie"), "has no extension");
    path_in_dir(path, sizeof path, "m.mp4");
    snprintf(text, sizeof text, "movie_rate = 0; movie = \"%s\"\n", path);
    bad(text, "movie_rate must be between 0 and 1000, limits excluded (got 0)");
    assert_int_equal(access(path, F_OK), -1); /* no file left behind */
    bad("tracker = /nonexistent.trk\n", "cannot read '/nonexistent.trk'");
    bad("run 1; run 1; run 1e9999\n", "run must be a finite number");
    bad("reselect\n", "reselect: no object has been held yet");
    bad("ball.size = (1, 1, 1); box.radius = 2; bogus\n", "unknown command 'bogus'");
}

static void no_current_object(void **state)
{
    (void)state;
    assert_int_equal(run("restart\n"), CMD_OK);
    char *before = snapshot();
    assert_int_equal(run("radius = 2\n"), CMD_ERROR);
    assert_non_null(strstr(g_errbuf, "no current object: create one with sphere NAME"));
    char *after = snapshot();
    assert_string_equal(before, after);
    free(before);
    free(after);
}

static void properties_of_other_classes_are_ignored(void **state)
{
    (void)state;
    build_world();
    char *before = snapshot();
    assert_int_equal(run("box.radius = 2\n"), CMD_OK);
    assert_non_null(strstr(g_errbuf, "warning: radius does not apply to cube 'box'"));
    char *after = snapshot();
    assert_string_equal(before, after);
    free(before);
    free(after);
}

static void names_select_objects(void **state)
{
    (void)state;
    build_world();
    /* NAME.property does not change the current object */
    assert_int_equal(run("box.mass = 5; radius = 0.5\n"), CMD_OK);
    assert_near(g_sh.w.bodies[world_find(&g_sh.w, "box")]->mass, 5, 0);
    assert_near(g_sh.w.bodies[world_find(&g_sh.w, "ball")]->sp.radius, 0.5, 0);
    /* reusing a name of the same type reselects it */
    assert_int_equal(run("cube box; size = (2, 2, 2)\n"), CMD_OK);
    assert_int_equal(g_sh.w.n, 4);
    assert_near(g_sh.w.bodies[world_find(&g_sh.w, "box")]->sp.size.x, 2, 0);
    assert_int_equal(run("delete box; list\n"), CMD_OK);
    assert_int_equal(g_sh.w.n, 3);
    assert_null(strstr(g_out, "box"));
    assert_non_null(strstr(g_out, "table"));
    assert_non_null(strstr(g_out, "static"));
    assert_int_equal(g_sh.current, -1);
    assert_int_equal(run("radius = 1\n"), CMD_ERROR);
}

static void save_restart_read_round_trips_exactly(void **state)
{
    (void)state;
    build_world();
    assert_int_equal(run("box.angular_vel = (0.3, -1.1, 2.2); pillow.angular_vel = (1, 1, 1)\n"
                         "pillow.translate = (4.1, 0.2, 0.3); ball.color = (1, 2, 3)\n"
                         "force = (0.1, 0.2, -1) 3.3; stereo = sbs; record = off; ipd = 0.07\n"
                         "image_size = (320, 200); background = (9, 8, 7); real = wire\n"
                         "hand_rotate = (0, 1, 0) 0.25; select on; seed = 77\n"
                         "run 7\n"),
                     CMD_OK);
    char *before = snapshot();
    char path[256], text[400];
    path_in_dir(path, sizeof path, "saved.vroc");
    snprintf(text, sizeof text, "save \"%s\"\n", path);
    assert_int_equal(run(text), CMD_OK);
    snprintf(text, sizeof text, "restart; read \"%s\"\n", path);
    assert_int_equal(run(text), CMD_OK);
    char *after = snapshot();
    /* time and frame restart at 0: compare all but the last line */
    *strstr(before, "current ") = '\0';
    *strstr(after, "current ") = '\0';
    assert_string_equal(before, after);
    assert_int_equal(g_sh.current, world_find(&g_sh.w, "ball"));
    free(before);
    free(after);
}

static void restart_returns_every_setting(void **state)
{
    (void)state;
    build_world();
    assert_int_equal(run("stereo = mono; trace = off; restart\n"), CMD_OK);
    char *text;
    size_t len;
    FILE *f = open_memstream(&text, &len);
    settings_write(f, &g_sh, 0);
    fclose(f);
    shell fresh;
    shell_init(&fresh, stdout, stderr);
    char *want;
    f = open_memstream(&want, &len);
    settings_write(f, &fresh, 0);
    fclose(f);
    assert_string_equal(text, want);
    assert_int_equal(g_sh.w.n, 0);
    shell_free(&fresh);
    free(text);
    free(want);
}

static void show_lists_every_setting(void **state)
{
    (void)state;
    assert_int_equal(run("show\n"), CMD_OK);
    for (int i = 0; i < command_count; i++) {
        const command *c = &command_table[i];
        if (c->form != FORM_SETTING) continue;
        char line[64];
        snprintf(line, sizeof line, "\n%s = ", c->name);
        if (!strstr(g_out, line) && strncmp(g_out, line + 1, strlen(line) - 1) != 0)
            fail_msg("show does not write %s", c->name);
    }
    /* and show's text reads back */
    char *text = strdup(g_out);
    assert_int_equal(run(text), CMD_OK);
    free(text);
}

static void time_cannot_run_through_objects(void **state)
{
    (void)state;
    assert_int_equal(run("restart; sphere a; sphere b; translate = (1.5, 0, 0); cube c\n"
                         "translate = (0, 3, 0); mass = -1\n"),
                     CMD_OK);
    char *before = snapshot();
    assert_int_equal(run("run 1\n"), CMD_ERROR);
    assert_non_null(strstr(g_errbuf, "error: 'a' and 'b' interpenetrate by 0.5 m"));
    assert_non_null(strstr(g_errbuf, "time cannot run while objects interpenetrate"));
    assert_int_equal(run("step\n"), CMD_ERROR);
    assert_int_equal(run("start\n"), CMD_ERROR);
    assert_false(g_sh.running);
    char *after = snapshot();
    assert_string_equal(before, after);
    free(before);
    free(after);
    assert_int_equal(run("b.translate = (2.5, 0, 0); run 1\n"), CMD_OK);
}

/* The frames start advances in real time (shell_advance without a statement, as
 * the prompt's loop calls it) are not checked for overlap one by one: the one
 * check start made holds until a statement runs.  Ten ticks query exactly the
 * pairs that run 10 queries, and reach the same states.  A statement between
 * ticks is checked again: one that moves an object into another stops time. */
static void real_time_checks_overlap_once(void **state)
{
    (void)state;
    const char *scene = "restart; seed = 7; random 30; gravity\n";
    assert_int_equal(run(scene), CMD_OK);
    assert_int_equal(run("start\n"), CMD_OK);
    assert_true(g_sh.running);
    long pairs = g_sh.w.pairs.live; /* the near ones */
    assert_true(pairs > 0 && pairs <= 30 * 29 / 2);
    for (int k = 0; k < 10; k++) assert_int_equal(shell_advance(&g_sh, NULL, 1), CMD_OK);
    long ticks = g_sh.w.st.pair_checks;
    char *by_ticks = snapshot();
    assert_int_equal(run(scene), CMD_OK);
    assert_int_equal(run("run 10\n"), CMD_OK);
    assert_int_equal(g_sh.w.st.pair_checks, ticks);
    assert_true(ticks >= pairs); /* the one check, at least */
    char *by_run = snapshot();
    assert_string_equal(by_ticks, by_run);
    free(by_ticks);
    free(by_run);
    /* an object put into another between ticks */
    const body *r1 = g_sh.w.bodies[world_find(&g_sh.w, "random1")];
    char move[160];
    snprintf(move, sizeof move, "start; random2.translate = (%.17g, %.17g, %.17g)\n", r1->x.x,
             r1->x.y, r1->x.z);
    assert_int_equal(run(move), CMD_OK);
    assert_int_equal(shell_advance(&g_sh, NULL, 1), CMD_ERROR);
    assert_non_null(strstr(g_errbuf, "'random1' and 'random2' interpenetrate"));
}

static void time_and_stats(void **state)
{
    (void)state;
    assert_int_equal(run("restart; time_step = 1000; collision_dist = 0.001; run 1\n"), CMD_ERROR);
    assert_non_null(strstr(g_errbuf, "internal steps per frame (limit 1000000)"));
    assert_int_equal(g_sh.w.frame, 0);
    assert_int_equal(run("restart; sphere a; cube t; mass = -1; translate = (0, 0, -5)\n"
                         "run 3; time; stats\n"),
                     CMD_OK);
    assert_non_null(strstr(g_out, "time = 0.3"));
    assert_non_null(strstr(g_out, "objects = 2\npairs = 1\nsubframes = 7\nframes = 3\n"));
    assert_int_equal(run("quit; sphere never\n"), CMD_QUIT);
    assert_int_equal(world_find(&g_sh.w, "never"), -1);
}

/* stats gives the thesis's pair count (every dynamic pair, Table 5.1) and the
 * pairs that exist: with the heap on only the near ones (the broad phase), with
 * it off every one. */
static void stats_counts_the_pairs_that_exist(void **state)
{
    (void)state;
    char text[2400];
    int k = snprintf(text, sizeof text, "restart\n");
    /* twenty spheres 3 m apart in a row, and b1 3 cm from b0 */
    for (int i = 0; i < 20; i++)
        k += snprintf(text + k, sizeof text - (size_t)k,
                      "sphere b%d; radius = 0.1; translate = (%g, 0, 0)\n", i, i == 1 ? 0.23 : 3.0 * i);
    snprintf(text + k, sizeof text - (size_t)k, "run 1; stats\n");
    assert_int_equal(run(text), CMD_OK);
    assert_non_null(strstr(g_out, "objects = 20\npairs = 190\n"));
    assert_non_null(strstr(g_out, "existing_pairs = 1\n"));
    assert_int_equal(run("collision_heap = off; run 1; stats\n"), CMD_OK);
    assert_non_null(strstr(g_out, "pairs = 190\n"));
    assert_non_null(strstr(g_out, "existing_pairs = 190\n"));
}

/* A frame that cannot be written turns record off; a batch run (stop_on_error)
 * stops there with an error, the prompt goes on. */
static void failed_record_stops_a_batch_run(void **state)
{
    (void)state;
    char out[256], text[400];
    write_file("plain", "x", 1); /* a file, so no folder can be made under it */
    path_in_dir(out, sizeof out, "plain/frames/f");
    snprintf(text, sizeof text, "restart; sphere a; output = \"%s\"; record = on\n", out);
    assert_int_equal(run(text), CMD_OK);
    assert_int_equal(run("run 5\n"), CMD_ERROR);
    assert_non_null(strstr(g_errbuf, "record: "));
    assert_non_null(strstr(g_errbuf, "time stopped"));
    assert_false(g_sh.view_set.record);
    assert_int_equal(g_sh.w.frame, 1);
    g_sh.stop_on_error = false; /* at the prompt */
    assert_int_equal(run("record = on; run 5\n"), CMD_OK);
    assert_non_null(strstr(g_errbuf, "; record is now off\n")); /* and time goes on */
    assert_false(g_sh.view_set.record);
    assert_int_equal(g_sh.w.frame, 6);
    g_sh.stop_on_error = true;
}

/* A log that fails in the middle of a run (here: it outgrows the file size limit,
 * SIGXFSZ ignored) is closed with an error that names it and says why; at the
 * prompt time goes on without it, a batch run stops at that frame. */
static void failed_logs_are_turned_off(void **state)
{
    (void)state;
    char path[256], text[400];
    struct rlimit old, lim;
    assert_int_equal(getrlimit(RLIMIT_FSIZE, &old), 0);
    void (*old_xfsz)(int) = signal(SIGXFSZ, SIG_IGN);
    lim = old;
    lim.rlim_cur = 4096;
    path_in_dir(path, sizeof path, "small.csv");
    for (int batch = 0; batch < 2; batch++) {
        g_sh.stop_on_error = batch;
        snprintf(text, sizeof text, "restart; sphere a; linear_vel = (1, 0, 0); trace = \"%s\"\n",
                 path);
        assert_int_equal(run(text), CMD_OK);
        assert_int_equal(setrlimit(RLIMIT_FSIZE, &lim), 0);
        cmd_status r = run("run 200\n");
        assert_int_equal(setrlimit(RLIMIT_FSIZE, &old), 0);
        if (!strstr(g_errbuf, "error: trace: cannot write '") ||
            !strstr(g_errbuf, "small.csv': File too large; trace is now off"))
            fail_msg("run 200 said: '%s'", g_errbuf);
        assert_null(g_sh.logs.trace);
        assert_string_equal(g_sh.logs.trace_path, "");
        if (batch) {
            assert_int_equal(r, CMD_ERROR);
            assert_non_null(strstr(g_errbuf, "small.csv': File too large; trace is now off, time stopped\n"));
            assert_true(g_sh.w.frame < 200);
        } else {
            assert_int_equal(r, CMD_OK);
            assert_non_null(strstr(g_errbuf, "small.csv': File too large; trace is now off\n"));
            assert_int_equal(g_sh.w.frame, 200);
        }
    }
    signal(SIGXFSZ, old_xfsz);
    g_sh.stop_on_error = true;
}

/* random's refusal is true: it says how many objects fit, adds none and leaves
 * its sequence as it was, so that random with that many adds them.  The objects'
 * sizes come from random_size, not from the box: a larger box, or smaller
 * objects, hold more. */
/* The two tests below run hundreds of random objects for hundreds of frames:
 * seconds here, minutes under valgrind, which tests/valgrind.sh runs this
 * program in.  There (VROC_TEST_LIGHT set) they skip: the code they reach,
 * random and run, is under valgrind in the lighter tests, and the sanitizer
 * build runs them whole. */
static void skip_when_light(void)
{
    const char *light = getenv("VROC_TEST_LIGHT");
    if (light && *light) skip();
}

static void random_says_how_many_fit(void **state)
{
    (void)state;
    skip_when_light();
    long fit;
    assert_int_equal(run("restart\n"), CMD_OK);
    unsigned long long rng = g_sh.rng;
    assert_int_equal(run("random 2000\n"), CMD_ERROR);
    const char *m = strstr(g_errbuf, "random: only ");
    assert_non_null(m);
    assert_int_equal(sscanf(m, "random: only %ld of the 2000 objects found room", &fit), 1);
    assert_non_null(strstr(m, "so none was added"));
    assert_int_equal(g_sh.w.n, 0);
    assert_true(g_sh.rng == rng);
    char text[64];
    snprintf(text, sizeof text, "random %ld\n", fit);
    assert_int_equal(run(text), CMD_OK);
    assert_int_equal(g_sh.w.n, fit);
    assert_true(fit > 100 && fit < 2000);
    /* a box filled by a static block: the second message */
    assert_int_equal(run("cube block; mass = -1; size = (2.5, 2.5, 2.5); random 1\n"), CMD_ERROR);
    assert_non_null(strstr(g_errbuf, "random: no room for an object in random_box"));
    /* twice the box, or objects half the size: 2000 fit */
    assert_int_equal(run("restart; random_box = (4, 4, 4); random 2000\n"), CMD_OK);
    assert_int_equal(g_sh.w.n, 2000);
    double largest = 0;
    for (int i = 0; i < g_sh.w.n; i++) largest = fmax(largest, g_sh.w.bodies[i]->shape.r_out);
    assert_true(largest <= 0.2 * sqrt(3) && largest > 0.15); /* sizes 0.08 to 0.2 */
    assert_int_equal(run("restart; random_size = (0.04, 0.1); random 2000\n"), CMD_OK);
    assert_int_equal(g_sh.w.n, 2000);
    for (int i = 0; i < g_sh.w.n; i++) assert_true(g_sh.w.bodies[i]->shape.r_out <= 0.1 * sqrt(3));
    /* no two of them overlap (their spheres, as random keeps them apart) */
    for (int i = 0; i < g_sh.w.n; i++)
        for (int j = i + 1; j < g_sh.w.n; j++) {
            const body *a = g_sh.w.bodies[i], *b = g_sh.w.bodies[j];
            assert_true(v3_dist(body_com(a), body_com(b)) >= a->shape.r_out + b->shape.r_out);
        }
}

/* random in a furnished room (issue 31): a place is tried against the shapes of
 * what is there (a floor 10 cm below the box, a wall across it, a static
 * superquadric inside it), not against their circumscribed spheres, which cover
 * the box.  The room fills, every new object is apart from every shape (the
 * oracle: the closest-feature distance of each pair), time runs without an
 * overlap, and the last new object is current. */
static void random_fills_a_furnished_room(void **state)
{
    (void)state;
    static const char *const rooms[] = {
        "cube floor; mass = -1; size = (3, 3, 0.05); translate = (0, 0, -2.15); random 30\n",
        "cube floor; mass = -1; size = (3, 3, 0.05); translate = (0, 0, -2.15)\n"
        "cube wall; mass = -1; size = (0.05, 3, 3); translate = (1.9, 0, 0); random 40\n",
        "cube floor; mass = -1; size = (3, 3, 0.05); translate = (0, 0, -2.05)\n"
        "superquadric rock; mass = -1; a1 = 1.5; a2 = 1.2; a3 = 0.8; exp1 = 0.5; exp2 = 0.5\n"
        "rotate = (1, 1, 0) 0.4; random 60\n",
    };
    static const int made[] = {30, 40, 60};
    for (int r = 0; r < 3; r++) {
        char text[512];
        snprintf(text, sizeof text, "restart; seed = %d; random_box = (2, 2, 2)\n%s", 3 + r, rooms[r]);
        if (run(text) != CMD_OK) fail_msg("room %d: %s", r, g_errbuf);
        int nstatic = 0;
        for (int i = 0; i < g_sh.w.n; i++) nstatic += body_is_static(g_sh.w.bodies[i]);
        assert_int_equal(g_sh.w.n - nstatic, made[r]);
        for (int i = 0; i < g_sh.w.n; i++)
            for (int j = 0; j < nstatic; j++) {
                const body *a = g_sh.w.bodies[i], *b = g_sh.w.bodies[j];
                if (body_is_static(a)) continue;
                closest_result d = body_distance(a, b, NULL);
                if (!(d.status == CLOSEST_SEPARATED && d.distance > 0))
                    fail_msg("room %d: %s meets %s (%g)", r, a->name, b->name, d.distance);
            }
        assert_int_equal(g_sh.current, g_sh.w.n - 1);
        assert_int_equal(run("gravity; run 1\n"), CMD_OK);
    }
}

static void trace_writes_a_row_per_object_per_frame(void **state)
{
    (void)state;
    char path[256], text[400];
    path_in_dir(path, sizeof path, "trace.csv");
    snprintf(text, sizeof text,
             "restart; gravity; sphere a; linear_vel = (1, 0, 4); sphere b; translate = (5, 0, 0)\n"
             "trace = \"%s\"; run 10; trace = off; run 5\n",
             path);
    assert_int_equal(run(text), CMD_OK);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    char line[1024];
    int rows = 0;
    double z = 0, t = 0;
    assert_non_null(fgets(line, sizeof line, f));
    assert_string_equal(line, "frame,time,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,state,ke\n");
    while (fgets(line, sizeof line, f)) {
        rows++;
        int commas = 0;
        for (char *p = line; *p; p++) commas += *p == ',';
        assert_int_equal(commas, 17);
        long frame;
        char name[16];
        double x, y;
        assert_int_equal(sscanf(line, "%ld,%lf,%15[^,],%lf,%lf,%lf", &frame, &t, name, &x, &y, &z), 6);
        if (strcmp(name, "a") == 0 && frame == 10) {
            assert_near(x, 1.0, 1e-9);
            assert_near(z, 4.0 - 4.9, 1e-9);
            assert_near(t, 1.0, 1e-12);
        }
        char *st = strstr(line, ",dynamic,");
        assert_non_null(st);
        /* ke, the last column: m |v|^2 / 2 with v = (1, 0, 4 - g t) for a, (0, 0, -g t) for b */
        double ke = strtod(st + strlen(",dynamic,"), NULL);
        double vz = (strcmp(name, "a") == 0 ? 4 : 0) - 9.8 * t, vx = strcmp(name, "a") == 0;
        assert_near(ke, 0.5 * (vx * vx + vz * vz), 1e-9);
    }
    fclose(f);
    assert_int_equal(rows, 2 * 11); /* two objects, at the start and after 10 frames */
}

/* plot's figures (figures.h): each frame's row, each object's series aligned with
 * the rows (a new object starts late, a deleted one ends, one back after a gap
 * goes on with NaN between), the oldest dropped past the frame and height
 * limits, and plot saying so; the figures are the world's (energy.h). */
static void figures_of_the_run(void **state)
{
    (void)state;
    assert_int_equal(run("restart; gravity; sphere a; translate = (0, 0, 5); run 3\n"
                         "sphere b; translate = (3, 0, 5); run 2; delete b; run 2\n"
                         "sphere b; translate = (3, 0, 9); run 1\n"),
                     CMD_OK);
    const figures *f = &g_sh.figs;
    assert_int_equal(f->n, 9); /* the start and 8 frames */
    assert_int_equal(f->dropped, 0);
    for (int r = 0; r < f->n; r++) {
        assert_int_equal(f->rows[r].frame, r);
        assert_near(f->rows[r].t, 0.1 * r, 1e-12);
    }
    const figure_series *a = figures_series(f, "a"), *b = figures_series(f, "b");
    assert_non_null(a);
    assert_non_null(b);
    assert_int_equal(a->first, 0);
    assert_int_equal(a->n, 9);
    for (int r = 0; r < 9; r++) { /* free fall: 5 - g t^2 / 2 */
        double t = 0.1 * r;
        assert_near(a->z[r], 5 - 4.9 * t * t, 1e-9);
    }
    /* b: rows 4 and 5 (made after frame 3), gone for 6 and 7, back at 8 */
    assert_int_equal(b->first, 4);
    assert_int_equal(b->n, 5);
    assert_true(isnan(b->z[2]) && isnan(b->z[3]));
    assert_near(b->z[4], 9 - 4.9 * 0.01, 1e-9);
    /* the last row is the world's energy: a and b each m g z + m v^2 / 2 */
    double ta = 0.8, tb = 0.1;
    double want = 9.8 * (5 - 4.9 * ta * ta) + 0.5 * (9.8 * ta) * (9.8 * ta) +
                  9.8 * (9 - 4.9 * tb * tb) + 0.5 * (9.8 * tb) * (9.8 * tb);
    assert_near(f->rows[8].kinetic + f->rows[8].potential, want, 1e-9);

    /* restart starts a new run; the limits drop the oldest quarter */
    assert_int_equal(run("restart; sphere a; sphere b; translate = (3, 0, 0); sphere c\n"
                         "translate = (6, 0, 0)\n"),
                     CMD_OK);
    assert_int_equal(f->n, 0);
    g_sh.figs.max_frames = 10;
    assert_int_equal(run("run 30\n"), CMD_OK);
    assert_true(f->n <= 10 && f->n >= 7);
    assert_int_equal(f->dropped + f->n, 31);
    assert_int_equal(f->rows[f->n - 1].frame, 30);
    assert_int_equal(f->rows[0].frame, f->dropped);
    a = figures_series(f, "a");
    assert_int_equal(a->first, f->dropped);
    assert_int_equal(a->n, f->n);
    if (system("command -v gnuplot > /dev/null 2>&1") == 0) {
        char text[400], path[300];
        path_in_dir(path, sizeof path, "e.png");
        snprintf(text, sizeof text, "plot energy = \"%s\"\n", path);
        assert_int_equal(run(text), CMD_OK);
        char want_msg[128];
        snprintf(want_msg, sizeof want_msg, "plot: the run's first %ld frames were dropped",
                 f->dropped);
        if (!strstr(g_errbuf, want_msg)) fail_msg("'%s' lacks '%s'", g_errbuf, want_msg);
    }
    g_sh.figs.max_frames = FIGURES_MAX_FRAMES;
    g_sh.figs.max_heights = 12; /* three objects: at most 4 frames */
    assert_int_equal(run("restart; sphere a; sphere b; translate = (3, 0, 0); sphere c\n"
                         "translate = (6, 0, 0); run 20\n"),
                     CMD_OK);
    assert_true(f->n <= 4 && f->heights <= 12);
    assert_int_equal(f->dropped + f->n, 21);
    g_sh.figs.max_heights = FIGURES_MAX_HEIGHTS;
    assert_int_equal(run("restart\n"), CMD_OK);
}

/* ------------------------------------------------------- the speed limits */

/* The kinetic energy of every object (J). */
static double kinetic_energy(void)
{
    double e = 0;
    for (int i = 0; i < g_sh.w.n; i++) e += body_energy(g_sh.w.bodies[i]);
    return e;
}

/* The number after "name = " in g_out, or -1. */
static long stat_of(const char *name)
{
    char key[64];
    snprintf(key, sizeof key, "\n%s = ", name);
    const char *at = strstr(g_out, key);
    return at ? strtol(at + strlen(key), NULL, 10) : -1;
}

/* How many times needle occurs in hay. */
static int occurrences(const char *hay, const char *needle)
{
    int n = 0;
    for (const char *p = strstr(hay, needle); p; p = strstr(p + 1, needle)) n++;
    return n;
}

/* The room of issue 33: 200 objects of `random` (elasticity 1, up to 2 m/s and
 * 2 rad/s) in a closed room of six static walls, no force. */
static void the_room_of_200(void)
{
    char text[2048];
    const double x = 2 * sqrt(10.0), a = 2, t = 0.2;
    snprintf(text, sizeof text,
             "default_friction = 0; default_rolling_friction = 0; seed = 1; random_box = (%.17g, %.17g, %g); random 200\n"
             "cube wxm; size = (%g, %.17g, %g); translate = (%.17g, 0, 0); mass = -1\n"
             "cube wxp; size = (%g, %.17g, %g); translate = (%.17g, 0, 0); mass = -1\n"
             "cube wym; size = (%.17g, %g, %g); translate = (0, %.17g, 0); mass = -1\n"
             "cube wyp; size = (%.17g, %g, %g); translate = (0, %.17g, 0); mass = -1\n"
             "cube wzm; size = (%.17g, %.17g, %g); translate = (0, 0, %g); mass = -1\n"
             "cube wzp; size = (%.17g, %.17g, %g); translate = (0, 0, %g); mass = -1\n",
             x, x, a, t, x + 2 * t, a + 2 * t, -(x + t), t, x + 2 * t, a + 2 * t, x + t, x, t,
             a + 2 * t, -(x + t), x, t, a + 2 * t, x + t, x, x, t, -(a + t), x, x, t, a + t);
    assert_int_equal(run(text), CMD_OK);
}

/* At the default limits (max_angular 4) collisions spin objects faster, and each
 * one the limit cuts loses energy: stats counts them, and the first warns, once,
 * naming the object and the limit to raise.  With the limits raised nothing is
 * cut, and elasticity 1 keeps the energy to 1e-9 over 60 s. */
static void speed_limits_count_what_they_cut(void **state)
{
    (void)state;
    skip_when_light();
    assert_int_equal(run("restart"), CMD_OK);
    the_room_of_200();
    double e0 = kinetic_energy();
    assert_int_equal(run("run 600; stats"), CMD_OK);
    long cuts = stat_of("speed_cuts"), hits = stat_of("collisions");
    double e1 = kinetic_energy();
    print_message("room of 200 at the default limits: %ld collisions, %ld cut, kinetic energy %.6g J "
                  "then %.6g J; %s", hits, cuts, e0, e1, g_errbuf);
    assert_true(cuts > 0 && cuts <= hits);
    assert_true(e1 < 0.9 * e0);
    assert_int_equal(occurrences(g_errbuf, "warning:"), 1);
    assert_true(strstr(g_errbuf, "raise max_angular to keep it") || strstr(g_errbuf, "raise max_linear to keep it"));
    const char *q = strchr(g_errbuf, '\'');
    assert_non_null(q);
    char name[64] = "";
    sscanf(q + 1, "%63[^']", name);
    assert_true(world_find(&g_sh.w, name) >= 0);
    assert_int_equal(run("run 20"), CMD_OK); /* once */
    assert_null(strstr(g_errbuf, "warning:"));

    assert_int_equal(run("restart; max_linear = 100; max_angular = 1000"), CMD_OK);
    the_room_of_200();
    e0 = kinetic_energy();
    for (int k = 0; k < 6; k++) {
        assert_int_equal(run("run 100"), CMD_OK);
        assert_near(kinetic_energy(), e0, 1e-9 * e0);
    }
    assert_int_equal(run("stats"), CMD_OK);
    print_message("room of 200, limits raised: %ld collisions in 60 s, none cut, energy %.15g J for "
                  "%.15g J\n", stat_of("collisions"), kinetic_energy(), e0);
    assert_true(stat_of("collisions") > 1000);
    assert_int_equal(stat_of("speed_cuts"), 0);
    assert_null(strstr(g_errbuf, "warning:"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(the_bad_input_catalogue),
        cmocka_unit_test(no_current_object),
        cmocka_unit_test(properties_of_other_classes_are_ignored),
        cmocka_unit_test(names_select_objects),
        cmocka_unit_test(save_restart_read_round_trips_exactly),
        cmocka_unit_test(restart_returns_every_setting),
        cmocka_unit_test(show_lists_every_setting),
        cmocka_unit_test(time_cannot_run_through_objects),
        cmocka_unit_test(real_time_checks_overlap_once),
        cmocka_unit_test(time_and_stats),
        cmocka_unit_test(stats_counts_the_pairs_that_exist),
        cmocka_unit_test(failed_record_stops_a_batch_run),
        cmocka_unit_test(trace_writes_a_row_per_object_per_frame),
        cmocka_unit_test(failed_logs_are_turned_off),
        cmocka_unit_test(random_says_how_many_fit),
        cmocka_unit_test(random_fills_a_furnished_room),
        cmocka_unit_test(figures_of_the_run),
        cmocka_unit_test(speed_limits_count_what_they_cut),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
