/* stl.c: the STL reader, binary and ASCII (meshfile.h).
 *
 * Binary: an 80-byte header, a little-endian 32-bit count n, and n records of 50
 * bytes (a normal, three corners as 32-bit floats, two attribute bytes): the
 * file has exactly 84 + 50 n bytes, which is how it is told from an ASCII STL
 * even when its header begins with "solid" (mesh_detect).  ASCII: `solid NAME`,
 * then facets (`facet normal x y z`, `outer loop`, three or more `vertex x y z`,
 * `endloop`, `endfacet`), then `endsolid`; a file may hold several solids, each
 * one group.  Keywords are read in any case.  The facets' normals are not used
 * (programs write them carelessly; the drawing makes its own), but must be
 * numbers.  Triangles repeat their corners, so vertices are welded as they come.
 */
#include "reader.h"

#include <math.h>
#include <string.h>
#include <strings.h>

static double le_float(const unsigned char *p)
{
    uint32_t u = le32(p);
    float f;
    memcpy(&f, &u, sizeof f);
    return (double)f;
}

static int stl_binary(mesh_builder *b, const unsigned char *data, size_t len)
{
    b->m->form = "binary STL";
    uint32_t n = le32(data + 80);
    (void)len; /* mesh_stl_binary checked it is 84 + 50 n */
    if (n > 0 && (n > (uint32_t)(2147483647 / 3) || mb_reserve_faces(b, (long)n, 3L * n) != 0))
        return mb_err_byte(b, 80, "no memory for the %lu triangles the header counts",
                           (unsigned long)n);
    for (uint32_t t = 0; t < n; t++) {
        const unsigned char *r = data + 84 + 50 * (size_t)t;
        for (int k = 0; k < 3; k++) {
            double c[3];
            for (int j = 0; j < 3; j++) {
                c[j] = le_float(r + 12 + 12 * k + 4 * j);
                if (!isfinite(c[j]))
                    return mb_err_byte(b, (size_t)(r + 12 + 12 * k + 4 * j - data),
                                       "triangle %lu, corner %d: a coordinate is %s",
                                       (unsigned long)t + 1, k + 1,
                                       isnan(c[j]) ? "NaN" : "infinite");
            }
            int v = mb_vertex_weld(b, v3(c[0], c[1], c[2]));
            if (v < 0 || mb_corner(b, v, -1) != 0) return mb_oom(b);
        }
        if (mb_face_end(b) != 0) return mb_oom(b);
    }
    return 0;
}

/* The keyword at the start of the current line (after blanks), in any case. */
static bool kw(text_cursor *c, const char *w)
{
    size_t n = strlen(w);
    return word_len(c->p, c->eol) == n && strncasecmp(c->p, w, n) == 0;
}

/* Three numbers after the keyword (of n letters) on the current line. */
static int stl_xyz(mesh_builder *b, text_cursor *c, size_t n, const char *what, vec3 *out)
{
    c->p += n;
    double x[3];
    for (int k = 0; k < 3; k++) {
        tc_skip_blanks(c);
        const char *q = c->p;
        int rc = q < c->eol ? parse_double(&c->p, c->eol, &x[k]) : -1;
        if (rc == -2)
            return mb_err_line(b, c->line, "%s: %.*s is not a finite number", what,
                               (int)word_len(q, c->eol), q);
        if (rc != 0)
            return mb_err_line(b, c->line, "%s needs 3 numbers (x y z)", what);
    }
    if (!tc_at_eol(c))
        return mb_err_line(b, c->line, "%s: unexpected '%.*s' after x y z", what,
                           (int)word_len(c->p, c->eol), c->p);
    *out = v3(x[0], x[1], x[2]);
    return 0;
}

/* The next line that is not blank; false at the end of the text. */
static bool next_statement(text_cursor *c)
{
    while (tc_next_line(c)) {
        tc_skip_blanks(c);
        if (c->p < c->eol) return true;
    }
    return false;
}

static int stl_ascii(mesh_builder *b, const char *data, size_t len)
{
    b->m->form = "ASCII STL";
    text_cursor c;
    tc_init(&c, data, len);
    enum { TOP, SOLID, FACET, LOOP, ENDLOOP } at = TOP;
    int corners = 0;
    long facet_line = 0;
    vec3 x;
    while (next_statement(&c)) {
        size_t w = word_len(c.p, c.eol);
        switch (at) {
        case TOP:
            if (!kw(&c, "solid"))
                return mb_err_line(b, c.line, "expected 'solid', got '%.*s'", (int)w, c.p);
            c.p += w;
            tc_skip_blanks(&c);
            if (mb_group(b, c.p, (size_t)(c.eol - c.p)) != 0) return mb_oom(b);
            at = SOLID;
            break;
        case SOLID:
            if (kw(&c, "endsolid")) {
                at = TOP;
            } else if (kw(&c, "facet")) {
                c.p += w;
                tc_skip_blanks(&c);
                if (!kw(&c, "normal"))
                    return mb_err_line(b, c.line, "expected 'facet normal x y z'");
                if (stl_xyz(b, &c, 6, "facet normal", &x) != 0) return -1;
                facet_line = c.line;
                at = FACET;
            } else {
                return mb_err_line(b, c.line, "expected 'facet' or 'endsolid', got '%.*s'", (int)w,
                                   c.p);
            }
            break;
        case FACET:
            if (!kw(&c, "outer"))
                return mb_err_line(b, c.line, "expected 'outer loop', got '%.*s'", (int)w, c.p);
            c.p += w;
            tc_skip_blanks(&c);
            if (!kw(&c, "loop")) return mb_err_line(b, c.line, "expected 'outer loop'");
            corners = 0;
            at = LOOP;
            break;
        case LOOP:
            if (kw(&c, "vertex")) {
                if (stl_xyz(b, &c, 6, "vertex", &x) != 0) return -1;
                int v = mb_vertex_weld(b, x);
                if (v < 0 || mb_corner(b, v, -1) != 0) return mb_oom(b);
                corners++;
            } else if (kw(&c, "endloop")) {
                if (corners < 3)
                    return mb_err_line(b, c.line, "a facet needs at least 3 vertices (got %d)",
                                       corners);
                if (mb_face_end(b) != 0) return mb_oom(b);
                at = ENDLOOP;
            } else {
                return mb_err_line(b, c.line, "expected 'vertex' or 'endloop', got '%.*s'", (int)w,
                                   c.p);
            }
            break;
        case ENDLOOP:
            if (!kw(&c, "endfacet"))
                return mb_err_line(b, c.line, "expected 'endfacet', got '%.*s'", (int)w, c.p);
            at = SOLID;
            break;
        }
    }
    if (at != TOP)
        return mb_err_line(b, at == SOLID ? c.line : facet_line,
                           "the file ends inside a %s: it is cut short",
                           at == SOLID ? "solid (no endsolid)" : "facet");
    return 0;
}

int mesh_read_stl(mesh_builder *b, const unsigned char *data, size_t len)
{
    b->m->format = MESH_STL;
    if (mesh_stl_binary(data, len)) return stl_binary(b, data, len);
    return stl_ascii(b, (const char *)data, len);
}
