/* test_lang.c: the parser against language.md: what it accepts, and the catalogue of
 * broken statements and files, each with its message and its line. */
#include "check.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "shell/commands.h"
#include "shell/help.h"
#include "shell/lang.h"
#include "shell/writer.h"

static char g_err[1024];

static program *parse(const char *text)
{
    lang_paths paths = {NULL, NULL, NULL};
    return lang_parse(text, strlen(text), "t.vroc", 1, &paths, 0, NULL, 0, g_err, sizeof g_err);
}

/* text must fail with a message containing want (and "t.vroc:LINE: error: ") */
static void expect_error(const char *text, int line, const char *want)
{
    g_err[0] = '\0';
    program *p = parse(text);
    if (p) {
        program_free(p);
        fail_msg("parsed without error: %s", text);
    }
    char where[64];
    snprintf(where, sizeof where, "t.vroc:%d: error: ", line);
    if (strncmp(g_err, where, strlen(where)) != 0)
        fail_msg("message '%s' does not start with '%s' (input: %s)", g_err, where, text);
    if (!strstr(g_err, want))
        fail_msg("message '%s' does not contain '%s' (input: %s)", g_err, want, text);
}

static void accepts_the_language(void **state)
{
    (void)state;
    program *p = parse("sphere ball   # a comment\n"
                       "radius = 0.12; translate = ( 0,0 , 1.5 )\n"
                       "\n"
                       "   # only a comment\n"
                       "ball.color = (1,2,3)\n"
                       "rotate = (0, 0, 1) 1.5707963267948966\n"
                       "force = (0,0,-1) 9.8 ;gravity\n"
                       "read \"my file.vroc\"\n"
                       "mass = -1e3\n"
                       "output = \"frames dir\"\n"
                       "stereo = anaglyph\n"
                       "record = on\n"
                       "help radius\n"
                       "help\n"
                       "distance a b\n"
                       "run 10\r\n");
    assert_null(p); /* "my file.vroc" does not exist: read is resolved at parse time */
    assert_non_null(strstr(g_err, "t.vroc:8: error: cannot read 'my file.vroc'"));

    p = parse("sphere ball   # a comment\n"
              "radius = 0.12; translate = ( 0,0 , 1.5 )\n"
              "\n"
              "ball.color = (1,2,3)\n"
              "rotate = (0, 0, 1) 1.5707963267948966\n"
              "force = (0,0,-1) 9.8 ;gravity\n"
              "mass = -1e3\n"
              "output = \"frames dir\"\n"
              "stereo = anaglyph\n"
              "run 10\r\n");
    assert_non_null(p);
    assert_int_equal(p->n, 11);
    assert_string_equal(p->s[0].cmd->name, "sphere");
    assert_string_equal(p->s[0].word, "ball");
    assert_string_equal(p->s[1].cmd->name, "radius");
    assert_near(p->s[1].num[0], 0.12, 0);
    assert_int_equal(p->s[2].line, 2);
    assert_near(p->s[2].num[2], 1.5, 0);
    assert_string_equal(p->s[3].object, "ball");
    assert_string_equal(p->s[3].cmd->name, "color");
    assert_near(p->s[4].num[3], 1.5707963267948966, 0);
    assert_string_equal(p->s[6].cmd->name, "gravity");
    assert_near(p->s[7].num[0], -1000, 0);
    assert_string_equal(p->s[8].word, "frames dir");
    assert_near(p->s[9].num[0], 2, 0); /* anaglyph: the third choice */
    assert_int_equal(p->s[9].line, 9);
    assert_int_equal(p->s[10].line, 10);
    assert_near(p->s[10].num[0], 10, 0);
    program_free(p);
}

static void the_catalogue_of_broken_statements(void **state)
{
    (void)state;
    expect_error("sphere a\nfrobnicate 3\n", 2, "unknown command 'frobnicate'");
    expect_error("radius =\n", 1, "missing value");
    expect_error("radius\n", 1, "missing '= value'");
    expect_error("radius 3\n", 1, "expected '='");
    expect_error("translate = (1, 2)\n", 1, "expected (x, y, z)");
    expect_error("translate = (1, 2, 3\n", 1, "unfinished vector");
    expect_error("translate = 1, 2, 3\n", 1, "expected (x, y, z)");
    expect_error("translate = (1, x, 3)\n", 1, "expected a number, got 'x'");
    expect_error("radius = nan\n", 1, "radius must be a finite number (got nan)");
    expect_error("radius = inf\n", 1, "radius must be a finite number (got inf)");
    expect_error("radius = 1e999\n", 1, "finite number");
    expect_error("translate = (0, -inf, 0)\n", 1, "finite number");
    expect_error("mass = 0\n", 1, "mass must not be 0");
    expect_error("radius = -1\n", 1, "radius must be between 1e-06 and 10000 (got -1)");
    expect_error("size = (1, 1)\n", 1, "(x, y, z)");
    expect_error("a2 = 0\n", 1, "a2 must be between 1e-06 and 10000 (got 0)");
    expect_error("exp1 = -0.5\n", 1, "exp1 must be between 0.001 and 100 (got -0.5)");
    expect_error("ures = 2\n", 1, "ures must be between 3 and 1000 (got 2)");
    expect_error("vres = 3.5\n", 1, "vres must be a whole number (got 3.5)");
    expect_error("elasticity = 1.5\n", 1, "elasticity must be between 0 and 1 (got 1.5)");
    expect_error("color = (256, 0, 0)\n", 1, "whole numbers between 0 and 255 (got 256)");
    expect_error("color = (1.5, 0, 0)\n", 1, "whole numbers between 0 and 255 (got 1.5)");
    expect_error("radius = 2 3\n", 1, "unexpected '3' after the value");
    expect_error("start now\n", 1, "unexpected 'now'");
    expect_error("start = 1\n", 1, "takes no '='");
    expect_error("time_step = -0.1\n", 1, "time_step must be 0 or between 1e-06 and 1000 (got -0.1)");
    expect_error("collision_dist = 0\n", 1, "collision_dist must be between 1e-06 and 10000 (got 0)");
    expect_error("max_linear = -1\n", 1, "max_linear must be between 0 and 10000 (got -1)");
    expect_error("force = (0, 0, 0) 9.8\n", 1, "force: the direction (0, 0, 0)");
    expect_error("rotate = (0, 0, 0) 1\n", 1, "rotate: the direction (0, 0, 0)");
    expect_error("up = (0, 0, 0)\n", 1, "up must not be (0, 0, 0)");
    expect_error("fov = 180\n", 1, "fov must be between 0 and 180, limits excluded (got 180)");
    expect_error("image_size = (8, 8)\n", 1, "image_size components must be between 16 and 8192 (got 8)");
    expect_error("stereo = quad\n", 1, "stereo must be one of pair|sbs|anaglyph|mono (got 'quad')");
    expect_error("record = yes\n", 1, "record must be on or off (got 'yes')");
    expect_error("sphere 3d\n", 1, "'3d' is not a valid object name");
    expect_error("sphere\n", 1, "sphere: missing an object name");
    expect_error("sphere \"a b\"\n", 1, "not quoted");
    expect_error("ball.nosuch = 3\n", 1, "'nosuch' is not an object property");
    expect_error("ball.time_step = 3\n", 1, "'time_step' is not an object property");
    expect_error("read \"unterminated\n", 1, "unterminated string");
    expect_error("run -1\n", 1, "run must be between 0 and 1000000000 (got -1)");
    expect_error("run 1.5\n", 1, "whole number");
    expect_error("(1, 2, 3)\n", 1, "expected a command, got '('");
    expect_error("= 3\n", 1, "expected a command, got '='");
    expect_error("distance a\n", 1, "distance: missing an object name");
    expect_error("seed = -1\n", 1, "seed must be between 0 and 4294967295 (got -1)");
    expect_error("trace = \n", 1, "missing value");
    expect_error("output = \"\"\n", 1, "file name is empty");
    expect_error("sphere a; radius = 1; bogus\n", 1, "unknown command 'bogus'");
    expect_error("plot\n", 1, "plot: missing the quantity: energy, momentum or NAME.height");
    expect_error("plot energie = e.png\n", 1,
                 "plot: the quantity is energy, momentum or NAME.height (got 'energie'): did you mean energy?");
    expect_error("plot ball.radius = e.png\n", 1, "the quantity is energy, momentum or NAME.height");
    expect_error("plot 3d.height = e.png\n", 1, "'3d' is not a valid object name");
    expect_error("plot energy e.png\n", 1, "plot: expected '= FILE.png' after the quantity, got 'e.png'");
    expect_error("plot energy =\n", 1, "plot: missing a file name");
    expect_error("plot energy = e.jpg\n", 1, "plot: the file must be a .png (got 'e.jpg')");
    expect_error("plot energy = e.png now\n", 1, "plot: unexpected 'now' after the value");
    expect_error("energy 3d\n", 1, "'3d' is not a valid object name");
    expect_error("show a b\n", 1, "show: unexpected 'b'");
    expect_error("print a.\n", 1, "'' is not an object property");
    expect_error("print a.radus\n", 1, "'radus' is not an object property: did you mean radius?");
    expect_error("precision = long\n", 1, "precision must be one of short|exact (got 'long')");
}

/* The caret under an error's excerpt: its column in the statement (0 first), or
 * -1 when the message has none. */
static int caret_column(const char *err)
{
    const char *a = strchr(err, '\n');
    const char *b = a ? strchr(a + 1, '\n') : NULL;
    const char *caret = b ? strchr(b + 1, '^') : NULL;
    return caret ? (int)(caret - (b + 1)) - 4 : -1;
}

/* Every number may be an expression (language.md, "The console beyond the
 * thesis"): the grammar's cases, then every error with the column it points at. */
static void expressions(void **state)
{
    (void)state;
    const struct {
        const char *text;
        double want;
        int slot; /* which number of the statement */
    } values[] = {
        {"radius = 1/3", 1.0 / 3, 0},
        {"radius = 0.1", 0.1, 0},             /* a lone literal is strtod's double */
        {"radius = 1e3", 1000, 0},
        {"radius = 0x10", 16, 0},
        {"radius = .5", 0.5, 0},
        {"radius = 1.5e-3", 1.5e-3, 0},
        {"radius =   7   ", 7, 0},
        {"radius = 1+2*3", 7, 0},             /* * before + */
        {"radius = (1+2)*3", 9, 0},
        {"radius = 10-4-3", 3, 0},            /* left to right */
        {"radius = 100/10/5", 2, 0},
        {"radius = 2^3^2", 512, 0},           /* ^ to the right */
        {"radius = 2^-1", 0.5, 0},
        {"radius = -(-3)", 3, 0},
        {"radius = +4", 4, 0},
        {"radius = 2 * 3", 6, 0},
        {"radius = pi", M_PI, 0},
        {"radius = e", M_E, 0},
        {"radius = sqrt(16)", 4, 0},
        {"radius = sin(pi/2)", 1, 0},
        {"radius = cos(0)", 1, 0},
        {"radius = 1 + tan(0)", 1, 0},
        {"radius = asin(1)", M_PI / 2, 0},
        {"radius = 1 + acos(1)", 1, 0},
        {"radius = atan2(1, 1)", M_PI / 4, 0},
        {"radius = exp(0)", 1, 0},
        {"radius = log(e)", 1, 0},
        {"radius = abs(-3)", 3, 0},
        {"radius = min(3, 1, 2)", 1, 0},
        {"radius = max(1, 5)", 5, 0},
        {"radius = min(1, max(2, 3))", 1, 0},
        {"translate = (min(1, 2), -2^2, atan2(0, 1))", -4, 1}, /* commas inside a call */
        {"translate = ((1), (2+3)*2, 3)", 10, 1},
        {"rotate = (0, 0, 1) pi/2", M_PI / 2, 3},
        {"rotate = (0, 0, 1) 30 deg", M_PI / 6, 3},
        {"rotate = (0, 0, 1) 2*30 deg", 2 * (30 * (M_PI / 180)), 3}, /* deg binds tightest */
        {"rotate = (0, 0, 1) -90 deg", -(90 * (M_PI / 180)), 3},
        {"rotate = (0, 0, 1) 2^2 deg", pow(2, 2 * (M_PI / 180)), 3},
        {"angular_vel = (0, 0, 90 deg)", 90 * (M_PI / 180), 2},
        {"max_angular = 180 deg", M_PI, 0},
        {"run 2*50", 100, 0},
        {"ures = 2^4", 16, 0},
        {"color = (255/5, 2*100, 255)", 200, 1},
    };
    for (size_t k = 0; k < sizeof values / sizeof values[0]; k++) {
        char text[128];
        snprintf(text, sizeof text, "sphere a\n%s\n", values[k].text);
        program *p = parse(text);
        if (!p) fail_msg("'%s' refused: %s", values[k].text, g_err);
        double got = p->s[1].num[values[k].slot], want = values[k].want;
        if (!(got == want)) fail_msg("'%s' gave %.17g, not %.17g", values[k].text, got, want);
        program_free(p);
    }
    program *p = parse("translate = (-0, 0, 0)\n");
    if (!p) fail_msg("%s", g_err);
    assert_true(p->s[0].num[0] == 0 && signbit(p->s[0].num[0])); /* as strtod reads it */
    program_free(p);

    const struct {
        const char *text, *msg;
        int col; /* of the caret, in text; -1: none */
    } errors[] = {
        {"radius = 1/0", "radius: division by zero", 10},
        {"radius = 1/(2-2)", "radius: division by zero", 10},
        {"radius = sqrt(-1)", "radius: sqrt of a negative number (-1)", 9},
        {"radius = log(0)", "radius: log of a number that is not > 0 (0)", 9},
        {"radius = asin(2)", "radius: asin of a number outside -1 to 1 (2)", 9},
        {"radius = acos(-1.5)", "radius: acos of a number outside -1 to 1 (-1.5)", 9},
        {"radius = (-8)^(1/3)", "a negative number to a power that is not whole", 13},
        {"radius = 0^-1", "radius: 0 to a negative power is not a number", 10},
        {"radius = 10^400", "radius: the power is not a finite number", 11},
        {"radius = exp(1000)", "radius: exp(...) is not a finite number", 9},
        {"radius = 1e308*10", "radius: the product is not a finite number", 14},
        {"radius = 1e308/1e-308", "radius: the quotient is not a finite number", 14},
        {"radius = 1e308+1e308", "radius: the sum is not a finite number", 14},
        {"radius = -1e308-1e308", "radius: the difference is not a finite number", 15},
        {"radius = 1e999", "radius must be a finite number (got 1e999)", 9},
        {"radius = nan", "radius must be a finite number (got nan)", 9},
        {"radius = -inf", "radius must be a finite number (got inf)", 10},
        {"radius = pj", "radius: expected a number, got 'pj': did you mean pi?", 9},
        {"radius = 2*sqr(4)", "radius: expected a number, got 'sqr': did you mean sqrt?", 11},
        {"radius = x", "radius: expected a number, got 'x'", 9},
        {"radius = 1 +", "radius: expected a number at the end", 12},
        {"radius = *2", "radius: expected a number, got '*'", 9},
        {"radius = )", "radius: expected a number, got ')'", 9},
        {"radius = (1+2", "radius: this '(' is not closed", 9},
        {"radius = (1+2 3)", "radius: expected ')' to close the '(', got '3'", 14},
        {"radius = sqrt 4", "radius: sqrt is a function: write sqrt(x)", 9},
        {"radius = sqrt(1, 2)", "radius: sqrt takes 1 number (got 2)", 9},
        {"radius = atan2(1)", "radius: atan2 takes 2 numbers (got 1)", 9},
        {"radius = min(1)", "radius: min takes 2 numbers or more (got 1)", 9},
        {"radius = max(1, 2", "radius: this '(' is not closed", 12},
        {"radius = atan2(1 2)", "radius: expected ',' or ')' in the function's arguments, got '2'", 17},
        {"radius = 30 deg", "radius is not an angle: deg (degrees to radians) does not apply", 12},
        {"radius = deg", "radius: deg follows the number it converts", 9},
        {"fov = 60 deg", "fov is in degrees already: write the number without deg", 9},
        {"translate = (1, 2 deg, 3)", "translate is not an angle", 18},
        {"rotate = (0, 0, 1 deg) 1", "rotate is not an angle", 18},
        {"force = (0, 0, -1) 9.8 deg", "force is not an angle", 23},
        {"radius = 2 3", "radius: unexpected '3' after the value", 11},
        {"radius = 2 pi", "radius: unexpected 'pi' after the value", 11},
        {"radius = 30 deg deg", "radius is not an angle", 12},
        {"rotate = (0, 0, 1) 30 deg deg", "rotate: unexpected 'deg' after the value", 26},
        {"translate = (1, 2)", "translate: expected (x, y, z) with 3 numbers, got ')'", 17},
        {"translate = (1, 2, 3", "translate: unfinished vector: expected (x, y, z)", 20},
        {"translate = 1, 2, 3", "translate: expected (x, y, z), got '1'", 12},
        {"translate = (1, x, 3)", "translate: expected a number, got 'x'", 16},
        {"radius = \"3\"", "radius: expected a number, got '3'", -1},
    };
    for (size_t k = 0; k < sizeof errors / sizeof errors[0]; k++) {
        char text[128];
        snprintf(text, sizeof text, "%s\n", errors[k].text);
        expect_error(text, 1, errors[k].msg);
        int col = caret_column(g_err);
        if (col != errors[k].col)
            fail_msg("'%s': the caret is at %d, not %d:\n%s", errors[k].text, col, errors[k].col,
                     g_err);
    }
    /* nesting has a limit: a hostile line cannot exhaust the stack */
    char deep[1024];
    snprintf(deep, sizeof deep, "radius = ");
    for (int k = 0; k < 300; k++) strcat(deep, "-");
    strcat(deep, "1\n");
    expect_error(deep, 1, "radius: the expression nests deeper than 200 levels");
    snprintf(deep, sizeof deep, "radius = ");
    for (int k = 0; k < 300; k++) strcat(deep, "(");
    strcat(deep, "1\n");
    expect_error(deep, 1, "radius: the expression nests deeper than 200 levels");
    /* a long line is quoted about the caret, with ... where it is cut */
    char lng[512];
    snprintf(lng, sizeof lng, "radius = 1");
    for (int k = 0; k < 100; k++) strcat(lng, "+1");
    strcat(lng, "+/2\n");
    expect_error(lng, 1, "radius: expected a number, got '/'");
    assert_non_null(strstr(g_err, "\n    ...1+1+1"));
    assert_non_null(strstr(g_err, "+1+/2\n"));
    assert_int_equal(caret_column(g_err), 3 + 52);
}

/* A number may be as long as a word: digits beyond a double's are rounded. */
static void long_numbers(void **state)
{
    (void)state;
    char text[2400];
    for (int zeros = 120; zeros <= 1000; zeros += 440) {
        int n = snprintf(text, sizeof text, "radius = 0.5");
        memset(text + n, '0', (size_t)zeros);
        snprintf(text + n + zeros, sizeof text - (size_t)(n + zeros), "1\nmass = 1.");
        n = (int)strlen(text);
        memset(text + n, '0', (size_t)zeros);
        snprintf(text + n + zeros, sizeof text - (size_t)(n + zeros), "\n");
        program *p = parse(text);
        if (!p) fail_msg("a number of %d digits was refused: %s", zeros + 3, g_err);
        assert_true(p->s[0].num[0] == 0.5);
        assert_true(p->s[1].num[0] == 1);
        program_free(p);
    }
    /* a tiny value keeps its value, and the message prints it so that it reads back */
    expect_error("radius = 5e-324\n", 1, "radius must be between 1e-06 and 10000 (got 4.94065645841247e-324)");
    expect_error("radius = 1e-400\n", 1, "(got 0)");
}

static void binary_garbage_and_huge_lines(void **state)
{
    (void)state;
    expect_error("sphere a\n\x01\x02\x03\n", 2, "control character 0x01");
    const char nul[] = "sphere a\nradius = 1\0garbage\n";
    lang_paths paths = {NULL, NULL, NULL};
    program *p = lang_parse(nul, sizeof nul - 1, "t.vroc", 1, &paths, 0, NULL, 0, g_err,
                            sizeof g_err);
    assert_null(p);
    assert_non_null(strstr(g_err, "t.vroc:2: error: a NUL byte"));

    size_t n = 1 << 20;
    char *big = malloc(n + 16);
    assert_non_null(big);
    memset(big, 'x', n);
    memcpy(big + n, "\n", 2);
    expect_error(big, 1, "(1048576 characters)");
    assert_true(strlen(g_err) < 300); /* the message quotes only the start of the word */
    memcpy(big, "radius = ", 9);
    expect_error(big, 1, "radius: expected a number, got 'xxxx");
    free(big);

    /* every byte value as a statement: errors, never a crash */
    for (int c = 1; c < 256; c++) {
        char text[8] = {(char)c, 'q', '\n', 0};
        program *q = parse(text);
        program_free(q);
    }
}

static char g_dir[64];

static void write_file(const char *name, const char *text)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%s", g_dir, name);
    FILE *f = fopen(path, "w");
    assert_non_null(f);
    fputs(text, f);
    fclose(f);
}

static program *parse_path(const char *name)
{
    char path[256];
    snprintf(path, sizeof path, "%s/%s", g_dir, name);
    lang_paths paths = {NULL, NULL, NULL};
    return lang_parse_file(path, &paths, 1, NULL, 0, NULL, 0, g_err, sizeof g_err);
}

static void files_read_files(void **state)
{
    (void)state;
    snprintf(g_dir, sizeof g_dir, "/tmp/vroc-lang-XXXXXX");
    assert_non_null(mkdtemp(g_dir));
    char sub[128];
    snprintf(sub, sizeof sub, "%s/sub", g_dir);
    assert_int_equal(mkdir(sub, 0755), 0);

    /* relative paths inside a file are taken from that file's folder */
    write_file("sub/inner.vroc", "sphere b\nradius = 2\n");
    write_file("outer.vroc", "sphere a\nread sub/inner.vroc\n");
    write_file("sub/chain.vroc", "read inner.vroc\n");
    write_file("chain-top.vroc", "read sub/chain.vroc\n");
    program *p = parse_path("outer.vroc");
    assert_non_null(p);
    assert_int_equal(p->n, 2);
    assert_non_null(p->s[1].sub);
    assert_int_equal(p->s[1].sub->n, 2);
    program_free(p);
    p = parse_path("chain-top.vroc");
    assert_non_null(p);
    program_free(p);

    /* an error in a file read by another names the inner file and line */
    write_file("bad-inner.vroc", "sphere c\n\nradius = -1\n");
    write_file("bad-outer.vroc", "sphere a\nread bad-inner.vroc\n");
    assert_null(parse_path("bad-outer.vroc"));
    assert_non_null(strstr(g_err, "bad-inner.vroc:3: error: radius must be between 1e-06 and 10000 (got -1)"));

    /* a file that reads itself, directly or in a cycle */
    write_file("self.vroc", "sphere a\nread self.vroc\n");
    assert_null(parse_path("self.vroc"));
    assert_non_null(strstr(g_err, "self.vroc:2: error: 'self.vroc' reads itself"));
    write_file("ping.vroc", "read pong.vroc\n");
    write_file("pong.vroc", "read ping.vroc\n");
    assert_null(parse_path("ping.vroc"));
    assert_non_null(strstr(g_err, "reads itself"));

    /* a missing file */
    write_file("missing.vroc", "sphere a\n\nread nowhere.vroc\n");
    assert_null(parse_path("missing.vroc"));
    assert_non_null(strstr(g_err, "missing.vroc:3: error: cannot read 'nowhere.vroc'"));

    /* nesting deeper than the limit: d0 reads d1 ... reads d20 */
    for (int i = 0; i <= 20; i++) {
        char name[32], text[64];
        snprintf(name, sizeof name, "d%d.vroc", i);
        if (i < 20) snprintf(text, sizeof text, "read d%d.vroc\n", i + 1);
        else snprintf(text, sizeof text, "sphere deep\n");
        write_file(name, text);
    }
    assert_null(parse_path("d0.vroc"));
    assert_non_null(strstr(g_err, "deeper than 16 levels"));
    write_file("d16.vroc", "sphere deep\n"); /* d0 to d16: 17 files */
    assert_null(parse_path("d0.vroc"));
    assert_non_null(strstr(g_err, "d15.vroc:1: error: files read each other deeper than 16 levels"));
    write_file("d15.vroc", "sphere edge\n"); /* d0 to d15: 16 files, the limit */
    p = parse_path("d0.vroc");
    assert_non_null(p);
    program_free(p);
    write_file("d10.vroc", "sphere shallow\n"); /* now 10 deep: fine */
    p = parse_path("d0.vroc");
    assert_non_null(p);
    program_free(p);

    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", g_dir);
    assert_int_equal(system(cmd), 0);
}

static void names(void **state)
{
    (void)state;
    assert_true(lang_valid_name("ball"));
    assert_true(lang_valid_name("_x-1"));
    assert_true(lang_valid_name("A9"));
    assert_false(lang_valid_name("9a"));
    assert_false(lang_valid_name("-a"));
    assert_false(lang_valid_name("a.b"));
    assert_false(lang_valid_name(""));
    char long_name[80];
    memset(long_name, 'a', 79);
    long_name[79] = '\0';
    assert_false(lang_valid_name(long_name));
}

static void numbers_print_to_read_back_exactly(void **state)
{
    (void)state;
    char buf[32];
    assert_string_equal(fmt_num(buf, 0.1), "0.1");
    assert_string_equal(fmt_num(buf, -0.0), "-0"); /* the sign bit too: exact state */
    assert_string_equal(fmt_num(buf, 0.0), "0");
    assert_string_equal(fmt_num(buf, 1e-300), "1e-300");
    unsigned long long s = 42;
    for (int i = 0; i < 100000; i++) {
        s = s * 6364136223846793005ULL + 1442695040888963407ULL;
        double x;
        unsigned long long bits = s;
        memcpy(&x, &bits, sizeof x);
        if (!isfinite(x) || x == 0) continue;
        assert_true(strtod(fmt_num(buf, x), NULL) == x);
    }
}

/* The command table and the reference in commands/ name the same commands, and the
 * reference's group matches each command's form. */
static void table_and_reference_agree(void **state)
{
    (void)state;
    for (int i = 0; i < command_count; i++) {
        const command *c = &command_table[i];
        const help_entry *h = help_find(c->name);
        if (!h) fail_msg("command '%s' has no file in commands/", c->name);
        if (c->form == FORM_PROPERTY && strcmp(h->group, "property") != 0)
            fail_msg("'%s' is a property but commands/%s says group %s", c->name, c->name,
                     h->group);
        if (c->form != FORM_PROPERTY && strcmp(h->group, "property") == 0)
            fail_msg("commands/%s says property but '%s' is not one", c->name, c->name);
        if (strncmp(h->usage, c->name, strlen(c->name)) != 0)
            fail_msg("commands/%s: usage '%s' does not start with the command", c->name,
                     h->usage);
        /* (plot QUANTITY = FILE is an action written with '=') */
        if ((c->form != FORM_ACTION || c->arg == ARG_PLOT) != (strstr(h->usage, " = ") != NULL))
            fail_msg("commands/%s: usage '%s' disagrees with the table about '='", c->name,
                     h->usage);
    }
    for (int i = 0; i < help_count; i++)
        if (!command_find(help_entries[i].name))
            fail_msg("commands/%s describes no command of the table", help_entries[i].name);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(accepts_the_language),
        cmocka_unit_test(the_catalogue_of_broken_statements),
        cmocka_unit_test(binary_garbage_and_huge_lines),
        cmocka_unit_test(long_numbers),
        cmocka_unit_test(expressions),
        cmocka_unit_test(files_read_files),
        cmocka_unit_test(names),
        cmocka_unit_test(numbers_print_to_read_back_exactly),
        cmocka_unit_test(table_and_reference_agree),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
