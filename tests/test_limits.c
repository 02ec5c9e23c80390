/* test_limits.c: every numeric property and setting of the command table at its
 * limits and one step beyond, then time run with objects at those limits.
 *
 * The walk reads the command table, so a command added later is walked too, and
 * one whose numbers have no limits fails here.  For each limit, the value at it is
 * accepted and a value one step beyond (the next double, or the next integer) is
 * an error that changes nothing; then two frames are run with an object at that
 * value (a moving sphere aimed at it, under gravity), and every number that
 * print, show, stats, distance and time write must be finite (core/limits.h says
 * why they are).  A few scenes mix the extremes: a heavy speck against a light
 * house-sized box, spinning at the speed limits. */
#include "check.h"

#include <float.h>
#include <stdlib.h>
#include <string.h>

#include "core/limits.h"
#include "shell/fmt.h"
#include "shell/shell.h"
#include "shell_fixture.h"

static int setup(void **state)
{
    (void)state;
    shell_fixture_open();
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    shell_fixture_close();
    return 0;
}

static int g_runs; /* walks whose two frames ran */

static bool is_numeric(const command *c)
{
    switch (c->arg) {
    case ARG_COUNT:
    case VAL_NUMBER:
    case VAL_INTEGER:
    case VAL_VECTOR:
    case VAL_VECTOR_ANGLE:
    case VAL_SIZE2:
    case VAL_RANGE2:
    case VAL_PAIR:
    case VAL_COLOR:
    case VAL_SCALE: return true;
    default: return false;
    }
}

static bool is_integer(const command *c)
{
    return c->arg == ARG_COUNT || c->arg == VAL_INTEGER || c->arg == VAL_SIZE2 ||
           c->arg == VAL_COLOR;
}

/* The value one step beyond the limit x, outwards (dir -1: below, +1: above). */
static double beyond(const command *c, double x, int dir)
{
    if (is_integer(c)) return x + dir;
    return nextafter(x, dir < 0 ? -INFINITY : INFINITY);
}

/* Fails when a number that text shows is not finite. */
static void assert_all_finite(const char *text, const char *what)
{
    char *copy = strdup(text);
    for (char *tok = strtok(copy, " \t\n(),="); tok; tok = strtok(NULL, " \t\n(),=")) {
        char *end;
        double x = strtod(tok, &end);
        if (end != tok && *end == '\0' && !isfinite(x))
            fail_msg("%s printed '%s':\n%s", what, tok, text);
    }
    free(copy);
}

/* The statement that sets c to x: the whole vector at x for a vector, and the
 * number after it in range; with k >= 0 only component k at x (the others at
 * `other`), with k == 3 the number after the vector at x. */
static void statement(const command *c, double x, int k, double other, char *buf, size_t len)
{
    char a[32], b[32], d[32], e[32];
    double v[4] = {other, other, other, 0};
    if (k < 0) v[0] = v[1] = v[2] = x;
    else v[k] = x;
    if (c->arg == VAL_VECTOR_ANGLE && k != 3 && !(c->lo2 <= 0 && 0 <= c->hi2)) v[3] = c->lo2;
    const char *n = c->name;
    switch (c->arg) {
    case ARG_COUNT: snprintf(buf, len, "%s %s", n, fmt_num(a, x)); break;
    case VAL_NUMBER:
    case VAL_INTEGER: snprintf(buf, len, "%s = %s", n, fmt_num(a, x)); break;
    case VAL_SIZE2:
    case VAL_RANGE2:
    case VAL_PAIR:
        snprintf(buf, len, "%s = (%s, %s)", n, fmt_num(a, v[0]), fmt_num(b, v[1]));
        break;
    case VAL_VECTOR_ANGLE:
        snprintf(buf, len, "%s = (%s, %s, %s) %s", n, fmt_num(a, v[0]), fmt_num(b, v[1]),
                 fmt_num(d, v[2]), fmt_num(e, v[3]));
        break;
    default:
        snprintf(buf, len, "%s = (%s, %s, %s)", n, fmt_num(a, v[0]), fmt_num(b, v[1]),
                 fmt_num(d, v[2]));
    }
}

/* The kind of object a property applies to. */
static const char *kind_for(const command *c)
{
    if (c->form != FORM_PROPERTY || (c->classes & C_SPHERE)) return "sphere";
    if (c->classes & C_CUBE) return "cube";
    return (c->classes & C_SQ) ? "superquadric" : "polyhedron";
}

/* What c needs before it: a tracker file playing, for tracker_time and
 * tracker_row (an error without one), and o held, for its hold_pivot and
 * hold_velocity. */
static const char *context_for(const command *c)
{
    if (strcmp(c->name, "tracker_time") == 0 || strcmp(c->name, "tracker_row") == 0)
        return "tracker = scenes/panel-demo.csv; ";
    return strncmp(c->name, "hold_", 5) == 0 ? "grip = o; " : "";
}

/* Runs set (a statement of c) on a fresh world with object o; *accepted gets
 * whether it ran.  Actions (run N, random N) are only parsed: their limits are
 * the parser's, and running a billion frames proves nothing more. */
static cmd_status try_value(const command *c, const char *set)
{
    char text[600];
    if (c->form == FORM_ACTION) {
        char err[512];
        lang_paths paths = {NULL, NULL, NULL};
        program *p = lang_parse(set, strlen(set), NULL, 1, &paths, 0, NULL, 0, err, sizeof err);
        fflush(g_sh.err);
        rewind(g_sh.err);
        memset(g_errbuf, 0, g_errlen);
        fputs(err, g_sh.err);
        fflush(g_sh.err);
        program_free(p);
        return p ? CMD_OK : CMD_ERROR;
    }
    snprintf(text, sizeof text, "restart; %s o; angular_vel = (0.5, 0.2, 0.1); %s%s\n",
             kind_for(c), context_for(c), set);
    return run(text);
}

/* Time run with object o at the value just set: a ball thrown at it under
 * gravity, then everything printed checked. */
static void run_at(const command *c, const char *set)
{
    int i = world_find(&g_sh.w, "o");
    assert_true(i >= 0);
    const body *o = g_sh.w.bodies[i];
    vec3 at = v3_add(body_com(o), v3(o->shape.r_out + 1.5, 0, 0));
    char text[600], a[32], b[32], d[32];
    snprintf(text, sizeof text,
             "gravity; sphere p; radius = 0.5; translate = (%s, %s, %s); linear_vel = (-8, 0, 0)\n"
             "angular_vel = (1, 2, 3)\n",
             fmt_num(a, at.x), fmt_num(b, at.y), fmt_num(d, at.z));
    if (fabs(at.x) > LIM_POSITION_MAX) /* o at the edge of the world: the ball comes from inside */
        snprintf(text, sizeof text,
                 "gravity; sphere p; radius = 0.5; translate = (%s, %s, %s); linear_vel = (8, 0, 0)\n",
                 fmt_num(a, body_com(o).x - o->shape.r_out - 1.5), fmt_num(b, at.y),
                 fmt_num(d, at.z));
    if (run(text) != CMD_OK) fail_msg("after '%s': '%s' failed: %s", set, text, g_errbuf);
    long frame0 = g_sh.w.frame; /* (frame = N sets it) */
    cmd_status r = run("run 2\n");
    /* a frame that needs more internal steps than a frame may take is refused, and
     * so is one that takes the clock past its limit (what save writes must read
     * back) */
    if (r != CMD_OK && !strstr(g_errbuf, "internal steps per frame") &&
        !strstr(g_errbuf, "time cannot run past"))
        fail_msg("after '%s': run 2 failed: %s", set, g_errbuf);
    if (r == CMD_OK) assert_int_equal(g_sh.w.frame, frame0 + 2);
    g_runs += r == CMD_OK;
    assert_int_equal(run("print o; print p; show; stats; distance o p; time; list\n"), CMD_OK);
    char what[700];
    snprintf(what, sizeof what, "'%s' (%s), then run 2", set, c->name);
    assert_all_finite(g_out, what);
}

/* One limit x of c: at it accepted (and run), one step beyond refused. */
static void walk_limit(const command *c, double x, int outwards, bool open)
{
    char set[300];
    double at = open ? nextafter(x, outwards < 0 ? INFINITY : -INFINITY) : x;
    double out = open ? x : beyond(c, x, outwards);
    bool vector = c->arg == VAL_VECTOR || c->arg == VAL_VECTOR_ANGLE || c->arg == VAL_SIZE2 ||
                  c->arg == VAL_RANGE2 || c->arg == VAL_PAIR || c->arg == VAL_COLOR;
    statement(c, at, -1, at, set, sizeof set);
    if (try_value(c, set) != CMD_OK) fail_msg("'%s' (at the limit) was refused: %s", set, g_errbuf);
    if (c->form != FORM_ACTION) run_at(c, set);
    int ncomp = c->arg == VAL_SIZE2 || c->arg == VAL_RANGE2 || c->arg == VAL_PAIR ? 2 : vector ? 3 : 1;
    for (int k = 0; k < ncomp; k++) {
        statement(c, out, vector ? k : -1, at, set, sizeof set);
        if (try_value(c, set) != CMD_ERROR) fail_msg("'%s' (beyond the limit) was accepted", set);
        if (!strstr(g_errbuf, "must be") && !strstr(g_errbuf, "finite number"))
            fail_msg("'%s': the message does not give the limits: %s", set, g_errbuf);
    }
}

static void every_number_has_limits(void **state)
{
    (void)state;
    for (int i = 0; i < command_count; i++) {
        const command *c = &command_table[i];
        if (!is_numeric(c)) continue;
        if (!(c->range & R_RANGE)) fail_msg("%s has no limits (R_RANGE)", c->name);
        if (!(c->lo < c->hi) || !isfinite(c->lo) || !isfinite(c->hi))
            fail_msg("%s: limits %g to %g", c->name, c->lo, c->hi);
        if (c->arg == VAL_VECTOR_ANGLE &&
            (!c->what2 || !(c->lo2 < c->hi2) || !isfinite(c->lo2) || !isfinite(c->hi2)))
            fail_msg("%s: no limits for the number after the vector", c->name);
    }
}

static void every_number_at_its_limits_and_beyond(void **state)
{
    (void)state;
    int walked = 0;
    for (int i = 0; i < command_count; i++) {
        const command *c = &command_table[i];
        /* pieces is read only: any count but the object's is refused
         * (tests/polyhedra.sh) */
        if (!is_numeric(c) || strcmp(c->name, "pieces") == 0) continue;
        if (c->range & R_ABS) { /* both signs */
            walk_limit(c, c->lo, -1, false);
            walk_limit(c, c->hi, +1, false);
            walk_limit(c, -c->lo, +1, false);
            walk_limit(c, -c->hi, -1, false);
        } else {
            walk_limit(c, c->lo, -1, c->range & R_LO_OPEN);
            walk_limit(c, c->hi, +1, c->range & R_HI_OPEN);
        }
        if (c->range & R_ZERO) {
            char set[128];
            statement(c, 0, -1, 0, set, sizeof set);
            if (try_value(c, set) != CMD_OK) fail_msg("'%s' was refused: %s", set, g_errbuf);
        }
        if (c->arg == VAL_VECTOR_ANGLE) { /* the number after the vector */
            char set[300];
            double mid = c->lo > 0 ? c->lo : c->hi < 0 ? c->hi : 1;
            for (int s = 0; s < 2; s++) {
                double x = s ? c->hi2 : c->lo2;
                statement(c, x, 3, mid, set, sizeof set);
                if (try_value(c, set) != CMD_OK) fail_msg("'%s' was refused: %s", set, g_errbuf);
                run_at(c, set);
                statement(c, beyond(c, x, s ? 1 : -1), 3, mid, set, sizeof set);
                if (try_value(c, set) != CMD_ERROR) fail_msg("'%s' was accepted", set);
                if (!strstr(g_errbuf, "must be")) fail_msg("'%s': %s", set, g_errbuf);
            }
        }
        walked++;
    }
    fprintf(stderr, "# walked %d commands, %d runs\n", walked, g_runs);
    assert_true(walked >= 30);
    assert_true(g_runs >= 2 * walked); /* nearly all: a few settings refuse frames */
}

/* The known failures of issue 24, each now a range error or a limited value. */
static void the_extremes_of_issue_24(void **state)
{
    (void)state;
    assert_int_equal(run("restart; sphere a; radius = 1e77\n"), CMD_ERROR);
    assert_non_null(strstr(g_errbuf, "radius must be between 1e-06 and 10000 (got 1e+77)"));
    assert_int_equal(run("restart; sphere a; radius = 5e-324\n"), CMD_ERROR);
    assert_non_null(strstr(g_errbuf, "(got 4.94065645841247e-324)")); /* reads back */
    assert_int_equal(run("restart; sphere a; linear_vel = (1e160, 0, 0); print a\n"), CMD_OK);
    assert_non_null(strstr(g_out, "linear_vel = (8, 0, 0)"));
    assert_int_equal(run("restart; sphere a; angular_vel = (0, -1e300, 0); print a\n"), CMD_OK);
    assert_non_null(strstr(g_out, "angular_vel = (0, -4, 0)"));
    assert_int_equal(run("restart; sphere a; mass = 1e200\n"), CMD_ERROR);
    assert_int_equal(run("restart; sphere a; mass = 1e-300\n"), CMD_ERROR);
    assert_non_null(strstr(g_errbuf, "mass must be between 1e-09 and 1000000000 or between "
                                     "-1000000000 and -1e-09 (got 1e-300)"));
    /* at the mass limits a spin turns the object */
    for (int s = 0; s < 2; s++) {
        assert_int_equal(run(s ? "restart; cube a; mass = 1e9; angular_vel = (0, 0, 1); run 5\n"
                               : "restart; cube a; mass = 1e-9; angular_vel = (0, 0, 1); run 5\n"),
                         CMD_OK);
        const body *b = g_sh.w.bodies[0];
        assert_near(fabs(b->q.w), cos(0.25), 1e-9); /* half of 0.5 rad about z */
    }
    assert_int_equal(run("restart; sphere a; radius = 1e308\n"), CMD_ERROR);
}

/* Several extremes at once, with collisions. */
static void extreme_scenes_stay_finite(void **state)
{
    (void)state;
    static const char *scenes[] = {
        /* a heavy speck thrown hard at a light box the size of a house */
        "max_linear = 10000; max_angular = 10000; collision_dist = 10000\n"
        "cube house; size = (10000, 10000, 10000); mass = 1e-9; angular_vel = (1e9, 0, 0)\n"
        "sphere speck; radius = 1e-6; mass = 1e9; translate = (10001, 0, 0)\n"
        "linear_vel = (-1e9, 0, 1); angular_vel = (0, 1e9, 0)",
        /* the reverse, at the edge of the world, elastic */
        "gravity; force = (1, 1, -1) 10000; max_linear = 10000\n"
        "superquadric s; a1 = 1e-3; a2 = 1e-3; a3 = 1e-3; a1 = 1e-6; a2 = 1e-6; a3 = 1e-6\n"
        "exp1 = 0.001; exp2 = 100; mass = 1e-9\n"
        "translate = (1e6, 1e6, 1e6); linear_vel = (1, 1, 1)\n"
        "cube c; size = (1e-6, 1e-6, 1e-6); mass = -1e9; translate = (999999.99999, 1e6, 1e6)\n"
        "sphere b; radius = 10000; mass = 1e9; translate = (-1e6, -1e6, -1e6); "
        "angular_vel = (1, 1, 1)",
        /* tiny objects, tiny steps, a long frame (b half elastic: with e = 0
         * the two would fly on touching for 3,000 s, which costs 20,000 pair
         * checks a simulated second, the crowd cost issue 35 names; the walk
         * above runs elasticity = 0 for two short frames) */
        "time_step = 1000; collision_dist = 1; internal_step = 0\n"
        "sphere a; radius = 1e-6; linear_vel = (-8, 0, 0); translate = (1, 0, 0)\n"
        "cube b; size = (1e-6, 1e-6, 1e-6); elasticity = 0.5\n"
        "cube floor; mass = -1; size = (10000, 10000, 1e-6); translate = (0, 0, -1)",
    };
    for (size_t k = 0; k < sizeof scenes / sizeof scenes[0]; k++) {
        char text[1200];
        snprintf(text, sizeof text, "restart\n%s\n", scenes[k]);
        if (run(text) != CMD_OK) fail_msg("scene %zu: %s", k, g_errbuf);
        if (run("run 3\n") != CMD_OK && !strstr(g_errbuf, "internal steps per frame"))
            fail_msg("scene %zu: run 3: %s", k, g_errbuf);
        assert_int_equal(run("show; stats; time; list\n"), CMD_OK);
        assert_all_finite(g_out, "an extreme scene");
        for (int i = 0; i < g_sh.w.n; i++) {
            char cmd[400];
            snprintf(cmd, sizeof cmd, "print %s; distance %s %s\n", g_sh.w.bodies[i]->name,
                     g_sh.w.bodies[i]->name, g_sh.w.bodies[(i + 1) % g_sh.w.n]->name);
            assert_int_equal(run(cmd), CMD_OK);
            assert_all_finite(g_out, cmd);
        }
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(every_number_has_limits),
        cmocka_unit_test(every_number_at_its_limits_and_beyond),
        cmocka_unit_test(the_extremes_of_issue_24),
        cmocka_unit_test(extreme_scenes_stay_finite),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
