/* test_polyfile.c: polyhedra from files in the language (language.md, "Polyhedra
 * from files"): polyhedron, file, scale, pieces, sha256, through the shell.
 *
 * Each bad file gives one error that names the file and the place, and leaves the
 * world as it was (print and list unchanged).  A path is taken from the folder of
 * the script that names it.  A concave file gets one warning.  save writes the
 * file relative to the saved file's folder when it lies under it, else absolute,
 * with its SHA-256; a world read back goes on to the bit, and a file changed since
 * gives the warning.  The readers' own tests are in test_mesh.c.
 */
#include "check.h"

#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "scratch.h"
#include "shell_fixture.h"

static int setup(void **state)
{
    (void)state;
    if (scratch_make("polyfile") != 0) return -1;
    shell_fixture_open();
    return 0;
}

static int teardown(void **state)
{
    (void)state;
    shell_fixture_close();
    return scratch_remove();
}

/* Writes n bytes to the scratch folder's file name; its path in path. */
static void write_file(const char *name, const void *data, size_t n, char *path, size_t len)
{
    snprintf(path, len, "%s/%s", g_dir, name);
    FILE *f = fopen(path, "wb");
    assert_non_null(f);
    assert_int_equal(fwrite(data, 1, n, f), n);
    assert_int_equal(fclose(f), 0);
}

static void write_text(const char *name, const char *text)
{
    char path[256];
    write_file(name, text, strlen(text), path, sizeof path);
}

static const char *CUBE_OBJ = "v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 0.5 -0.5\n"
                              "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 0.5\nv -0.5 0.5 0.5\n"
                              "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";

/* The same L as two groups, each a closed box, and as two open ones (each box
 * without its top). */
static const char *L2_OBJ =
    "g lower\nv 0 0 0\nv 2 0 0\nv 0 1 0\nv 2 1 0\nv 0 0 1\nv 2 0 1\nv 0 1 1\nv 2 1 1\n"
    "f 1 3 4 2\nf 5 6 8 7\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n"
    "g upper\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\nv 0 0 2\nv 1 0 2\nv 0 1 2\nv 1 1 2\n"
    "f 9 11 12 10\nf 13 14 16 15\nf 9 10 14 13\nf 11 15 16 12\nf 9 13 15 11\nf 10 12 16 14\n";
static const char *L2_OPEN_OBJ =
    "g lower\nv 0 0 0\nv 2 0 0\nv 0 1 0\nv 2 1 0\nv 0 0 1\nv 2 0 1\nv 0 1 1\nv 2 1 1\n"
    "f 1 3 4 2\nf 1 2 6 5\nf 3 7 8 4\nf 1 5 7 3\nf 2 4 8 6\n"
    "g upper\nv 0 0 1\nv 1 0 1\nv 0 1 1\nv 1 1 1\nv 0 0 2\nv 1 0 2\nv 0 1 2\nv 1 1 2\n"
    "f 9 11 12 10\nf 9 10 14 13\nf 11 15 16 12\nf 9 13 15 11\nf 10 12 16 14\n";
static const char *ROOM_OBJ =
    "o room\nv -2 -2 -0.1\nv 2 -2 -0.1\nv 2 2 -0.1\nv -2 2 -0.1\n"
    "v -2 -2 3\nv 2 -2 3\nv 2 2 3\nv -2 2 3\n"
    "f 1 2 3 4\nf 5 8 7 6\nf 1 5 6 2\nf 2 6 7 3\nf 3 7 8 4\nf 4 8 5 1\n";

static const char *L_OBJ = "v 0 0 0\nv 2 0 0\nv 2 1 0\nv 0 1 0\nv 0 0 1\nv 2 0 1\nv 2 1 1\nv 0 1 1\n"
                           "v 0 0 2\nv 1 0 2\nv 1 1 2\nv 0 1 2\nv 1 0 1\nv 1 1 1\n"
                           "f 1 4 3 2\nf 1 2 6 13 10 9\nf 4 12 11 14 7 3\nf 2 3 7 6\n"
                           "f 13 6 7 14\nf 10 13 14 11\nf 9 10 11 12\nf 1 9 12 4\n";

/* How many times s occurs in text. */
static int count(const char *text, const char *s)
{
    int n = 0;
    for (const char *p = strstr(text, s); p; p = strstr(p + 1, s)) n++;
    return n;
}

/* Runs text, which must work, and returns what print p and list write. */
static char *state_of(const char *text)
{
    if (text && run(text) != CMD_OK) fail_msg("'%s' failed: %s", text, g_errbuf);
    assert_int_equal(run("print p; list\n"), CMD_OK);
    return strdup(g_out);
}

/* `file = "name"` on p must fail with one error naming the file and want, and
 * leave the world as it was. */
static void bad(const char *name, const char *want)
{
    char text[600];
    char *before = state_of(NULL);
    snprintf(text, sizeof text, "p.file = \"%s/%s\"\n", g_dir, name);
    assert_int_equal(run(text), CMD_ERROR);
    print_message("%s", g_errbuf);
    if (count(g_errbuf, "error:") != 1 || count(g_errbuf, "\n") != 1)
        fail_msg("not one error line: %s", g_errbuf);
    if (!strstr(g_errbuf, name) || !strstr(g_errbuf, want))
        fail_msg("wanted '%s' naming %s in: %s", want, name, g_errbuf);
    char *after = state_of(NULL);
    assert_string_equal(after, before);
    free(before);
    free(after);
}

static void bad_files_leave_the_world_as_it_was(void **state)
{
    (void)state;
    char path[256];
    write_text("cube.obj", CUBE_OBJ);
    char setup_text[400];
    snprintf(setup_text, sizeof setup_text,
             "restart; polyhedron p; file = \"%s/cube.obj\"; translate = (0, 0, 3); sphere s\n", g_dir);
    free(state_of(setup_text));
    /* a binary STL cut short */
    unsigned char stl[84 + 50 * 12] = {0};
    stl[80] = 12;
    write_file("cut.stl", stl, sizeof stl - 7, path, sizeof path);
    bad("cut.stl", "it has 677 bytes, where a binary STL of the 12 triangles its header counts has 684");
    write_text("range.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 9\n");
    bad("range.off", "range.off:7: face 0: vertex index 9 is out of range");
    write_text("huge.off", "OFF\n100000000000 6 0\n0 0 0\n");
    bad("huge.off", "huge.off:2: the header declares 100000000000 vertices");
    write_text("empty.obj", "");
    bad("empty.obj", "the file is empty");
    snprintf(path, sizeof path, "%s/folder.obj", g_dir);
    assert_int_equal(mkdir(path, 0755), 0);
    bad("folder.obj", "cannot read");
    unsigned char noise[200];
    for (int k = 0; k < 200; k++) noise[k] = (unsigned char)(k * 151 + 7);
    write_file("noise.obj", noise, sizeof noise, path, sizeof path);
    bad("noise.obj", "not text, and not a binary STL: it has 200 bytes");
    write_text("nan.obj", "v 0 0 0\nv 1 0 0\nv 0 NaN 0\nv 0 0 1\nf 1 2 3\n");
    bad("nan.obj", "nan.obj:3: v: NaN is not a finite number");
    write_text("count.ply", "ply\nformat ascii 1.0\nelement vertex 100\nproperty float x\n"
                            "property float y\nproperty float z\nend_header\n0 0 0\n");
    bad("count.ply", "count.ply:7: element vertex: 100 instances need at least 600 bytes");
    write_text("flat.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
    bad("flat.obj", "flat.obj: polyhedron: its 4 points make no solid: points are coplanar");
    bad("missing.obj", "cannot read");
    /* not a polyhedron: a warning, nothing else */
    assert_int_equal(run("s.file = \"cube.obj\"\n"), CMD_OK);
    assert_non_null(strstr(g_errbuf, "warning: file does not apply to sphere 's'"));
}

/* A relative path is the script's folder's; the L gets one warning; pieces is read
 * only; scale scales the hull and its mass properties. */
static void paths_warnings_pieces_and_scale(void **state)
{
    (void)state;
    char path[256], text[400];
    write_text("L.obj", L_OBJ);
    write_text("make-l.vroc", "restart\npolyhedron p\nfile = \"L.obj\"\n");
    snprintf(path, sizeof path, "%s/make-l.vroc", g_dir);
    clear_output();
    assert_int_equal(shell_run_file(&g_sh, path), CMD_OK);
    fflush(g_sh.err);
    assert_int_equal(count(g_errbuf, "warning:"), 1);
    assert_non_null(strstr(g_errbuf, "make-l.vroc:3: warning: '"));
    assert_non_null(strstr(g_errbuf, "4 of its 20 triangles are not on its convex hull"));
    assert_non_null(strstr(g_errbuf, "CoACD or V-HACD"));
    assert_int_equal(run("precision = exact\nprint p\n"), CMD_OK);
    assert_non_null(strstr(g_out, "pieces = 1\n"));
    /* the closed mesh's own centre of mass, not its hull's */
    assert_non_null(strstr(g_out, "# centre of mass, in its own axes: (0.83333333333333"));
    assert_non_null(strstr(g_out, "thickness = 0.02\nfile = "));
    assert_int_equal(run("pieces = 1\n"), CMD_OK);
    assert_int_equal(run("pieces = 2\n"), CMD_ERROR);
    assert_non_null(strstr(g_errbuf, "pieces is read only: 'p' collides as 1 convex piece (got 2)"));
    assert_int_equal(run("pieces = 0\n"), CMD_ERROR);
    /* scale: volume times sx sy sz, the centre of mass scaled */
    const body *b = g_sh.w.bodies[0];
    double v0 = b->shape.mass.volume;
    assert_int_equal(run("scale = (2, 0.5, 3)\n"), CMD_OK);
    assert_near(b->shape.mass.volume, 3 * v0, 1e-14);
    assert_vec_near(b->shape.mass.com, v3(2 * 5.0 / 6, 0.25, 3 * 5.0 / 6), 1e-14);
    assert_int_equal(run("scale = 0.001\n"), CMD_OK);
    assert_near(b->shape.mass.volume, 3e-9, 1e-22);
    assert_int_equal(run("scale = 5000\n"), CMD_OK); /* (0, 0, 2) at 10000 m: the limit */
    assert_int_equal(run("scale = 5001\n"), CMD_ERROR);
    assert_non_null(strstr(g_errbuf, "the point (0, 0, 10002) lies beyond 10000 m of its origin"));
    /* beyond the world's lengths: refused, the scale kept */
    write_text("far.obj", "v 0 0 0\nv 3 0 0\nv 0 3 0\nv 0 0 3\n");
    snprintf(text, sizeof text, "file = \"%s/far.obj\"\n", g_dir);
    assert_int_equal(run(text), CMD_ERROR);
    assert_non_null(strstr(g_errbuf, "beyond 10000 m"));
    assert_int_equal(run("scale = 0\n"), CMD_ERROR);
    assert_int_equal(run("scale = (1, -1, 1)\n"), CMD_ERROR);
    assert_near(b->sp.scale.x, 5000, 0);
    assert_int_equal(b->shape.hull->nv, 10); /* still the L */
}

/* Pieces in the shell: groups are pieces (print, the read-only check), open
 * pieces warn of their mass on a moving object and are slabs on a static one,
 * whose thickness is a property; hulls is a view setting. */
static void pieces_rooms_thickness_and_hulls(void **state)
{
    (void)state;
    write_text("l2.obj", L2_OBJ);
    write_text("l2-open.obj", L2_OPEN_OBJ);
    write_text("quad.obj", "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n");
    char text[600];
    snprintf(text, sizeof text, "restart\npolyhedron l\nfile = \"%s/l2.obj\"\nprint l\n", g_dir);
    assert_int_equal(run(text), CMD_OK);
    assert_non_null(strstr(g_out, "pieces = 2\n"));
    assert_int_equal(count(g_errbuf, "warning:"), 0); /* closed: its own mass, convex pieces */
    assert_int_equal(run("pieces = 2\n"), CMD_OK);
    /* distance names the piece: a ball over the upper box's top, and beside the
     * lower box's end */
    assert_int_equal(run("sphere s1\ntranslate = (0.5, 0.5, 2.5)\nradius = 0.25\ndistance l s1\n"), CMD_OK);
    assert_non_null(strstr(g_out, "distance = 0.25\n"));
    assert_non_null(strstr(g_out, "piece_A = 2\n"));
    assert_null(strstr(g_out, "piece_B"));
    assert_int_equal(run("s1.translate = (2.5, 0.5, 0.5)\ndistance s1 l\n"), CMD_OK);
    assert_non_null(strstr(g_out, "distance = 0.25\n"));
    assert_non_null(strstr(g_out, "piece_B = 1\n"));
    assert_int_equal(run("delete s1\npolyhedron l\n"), CMD_OK);
    assert_int_equal(run("pieces = 1\n"), CMD_ERROR);
    assert_non_null(strstr(g_errbuf, "'l' collides as 2 convex pieces (got 1)"));
    /* open groups on a moving object: one warning, overlaps counted twice */
    snprintf(text, sizeof text, "file = \"%s/l2-open.obj\"\n", g_dir);
    assert_int_equal(run(text), CMD_OK);
    assert_int_equal(count(g_errbuf, "warning:"), 1);
    assert_non_null(strstr(g_errbuf, "its mass properties are those of its 2 pieces' hulls together, "
                                     "where overlaps count twice"));
    /* a single face: refused on a moving object (the shape kept), a slab on a
     * static one */
    snprintf(text, sizeof text, "file = \"%s/quad.obj\"\n", g_dir);
    assert_int_equal(run(text), CMD_ERROR);
    assert_non_null(strstr(g_errbuf, "a static object (mass = -1 before file) makes an open piece a slab per face"));
    assert_int_equal(g_sh.w.bodies[0]->shape.pieces, 2);
    snprintf(text, sizeof text, "polyhedron floor\nmass = -1\nfile = \"%s/quad.obj\"\nthickness = 0.25\n", g_dir);
    assert_int_equal(run(text), CMD_OK);
    const body *f = g_sh.w.bodies[1];
    assert_int_equal(f->shape.slabs, 1);
    assert_near(f->shape.box_lo.z, -0.25, 1e-15);
    assert_int_equal(run("print floor.thickness\n"), CMD_OK);
    assert_non_null(strstr(g_out, "floor.thickness = 0.25"));
    /* made moving: its open piece has no solid: refused, static it stays */
    assert_int_equal(run("mass = 2\n"), CMD_ERROR);
    assert_true(body_is_static(f));
    assert_int_equal(run("thickness = 0\n"), CMD_ERROR);
    assert_int_equal(run("sphere s\nthickness = 0.1\n"), CMD_OK);
    assert_non_null(strstr(g_errbuf, "warning: thickness does not apply to sphere 's'"));
    /* hulls: off by default, on shown */
    assert_int_equal(run("show hulls\nhulls = on\nshow hulls\n"), CMD_OK);
    assert_non_null(strstr(g_out, "hulls = off\nhulls = on\n"));
}

/* save and read: the path relative to the saved file's folder (or absolute), the
 * SHA-256 checked, the world going on to the bit. */
static void saved_and_read_back(void **state)
{
    (void)state;
    char path[256], other[256], text[1200];
    write_text("cube.obj", CUBE_OBJ);
    write_text("l2.obj", L2_OBJ);
    write_text("room.obj", ROOM_OBJ);
    /* with bodies of several pieces: a static room of slabs, a thrown L of two */
    const char *world_text =
        "restart; gravity; max_angular = 100; cube floor; mass = -1; size = (2, 2, 0.1)\n"
        "translate = (0, 0, -0.1); polyhedron p; file = \"%s/cube.obj\"; scale = (0.3, 0.2, 0.25); translate = (0, 0, 1)\n"
        "rotate = (1, 2, 3) 0.7; angular_vel = (1, -2, 0.5); linear_vel = (0.3, 0, 0)\n"
        "polyhedron room; mass = -1; thickness = 0.05; file = \"%s/room.obj\"\n"
        "polyhedron l; file = \"%s/l2.obj\"; scale = 0.2; translate = (-1, 0.5, 1.2); elasticity = 0.7\n"
        "rotate = (0.3, 1, 0.2) 0.9; angular_vel = (0, 3, 1); linear_vel = (2.5, -1, 1)\n";
    char made[1000];
    snprintf(made, sizeof made, world_text, g_dir, g_dir, g_dir);
    /* saved at every frame and read back: the same hash 20 frames on */
    char *at[21];
    for (int k = 0; k <= 20; k += 1) {
        snprintf(text, sizeof text, "%s run %d; save \"%s/w%d.vroc\"; run %d; hash\n", made, k, g_dir, k,
                 20 - k);
        assert_int_equal(run(text), CMD_OK);
        at[k] = strdup(g_out);
        snprintf(text, sizeof text, "restart; read \"%s/w%d.vroc\"; run %d; hash\n", g_dir, k, 20 - k);
        assert_int_equal(run(text), CMD_OK);
        assert_string_equal(g_out, at[k]);
        if (k > 0) assert_string_equal(at[k], at[0]);
    }
    for (int k = 0; k <= 20; k++) free(at[k]);
    snprintf(text, sizeof text, "%s run 7; save \"%s/w.vroc\"; run 13; hash\n", made, g_dir);
    assert_int_equal(run(text), CMD_OK);
    char *whole = strdup(g_out);
    snprintf(path, sizeof path, "%s/w.vroc", g_dir);
    FILE *f = fopen(path, "r");
    assert_non_null(f);
    char saved[8192] = "";
    assert_true(fread(saved, 1, sizeof saved - 1, f) > 0);
    fclose(f);
    assert_non_null(strstr(saved, "file = \"cube.obj\"\nsha256 = \""));
    assert_non_null(strstr(saved, "scale = (0.3, 0.2, 0.25)\n"));
    assert_null(strstr(saved, "pieces"));
    snprintf(text, sizeof text, "restart; read \"%s\"; run 13; hash\n", path);
    assert_int_equal(run(text), CMD_OK);
    assert_string_equal(g_out, whole);
    if (!(g_errlen == 0 || g_errbuf[0] == '\0')) fail_msg("read back: %s", g_errbuf);
    free(whole);
    /* saved elsewhere: the path is absolute */
    snprintf(other, sizeof other, "%s/sub", g_dir);
    assert_int_equal(mkdir(other, 0755), 0);
    snprintf(text, sizeof text, "save \"%s/sub/w2.vroc\"\n", g_dir);
    assert_int_equal(run(text), CMD_OK);
    snprintf(path, sizeof path, "%s/sub/w2.vroc", g_dir);
    f = fopen(path, "r");
    assert_non_null(f);
    memset(saved, 0, sizeof saved);
    assert_true(fread(saved, 1, sizeof saved - 1, f) > 0);
    fclose(f);
    char want[300];
    char real[256];
    assert_non_null(realpath(g_dir, real));
    snprintf(want, sizeof want, "file = \"%s/cube.obj\"\n", real);
    assert_non_null(strstr(saved, want));
    /* the file changes: reading the world warns, once, and takes it as it is */
    write_text("cube.obj", "v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0 0.5 -0.5\nv 0 0 0.5\n"
                           "f 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n");
    snprintf(text, sizeof text, "restart; read \"%s/w.vroc\"\n", g_dir);
    assert_int_equal(run(text), CMD_OK);
    assert_int_equal(count(g_errbuf, "warning:"), 1);
    assert_non_null(strstr(g_errbuf, "cube.obj' has changed since it was saved: its SHA-256 is "));
    assert_int_equal(g_sh.w.bodies[1]->shape.hull->nv, 4);
    /* a malformed SHA-256 is refused when the file is parsed */
    assert_int_equal(run("sha256 = \"12ab\"\n"), CMD_ERROR);
    assert_non_null(strstr(g_errbuf, "sha256 must be 64 hexadecimal digits"));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(bad_files_leave_the_world_as_it_was),
        cmocka_unit_test(paths_warnings_pieces_and_scale),
        cmocka_unit_test(pieces_rooms_thickness_and_hulls),
        cmocka_unit_test(saved_and_read_back),
    };
    return cmocka_run_group_tests(tests, setup, teardown);
}
