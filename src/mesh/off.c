/* off.c: the OFF reader (Geomview's Object File Format; meshfile.h).
 *
 * The header is `OFF`, or with the prefixes `ST`, `C` and `N` in that order
 * (`COFF`, `NOFF`, `CNOFF`, ...), then the counts `vertices faces edges` (edges
 * may be left out): on the header's line, on a line of their own, or with the
 * first count glued to the keyword (`OFF8 6 12`, as some collections write it).
 * A file named .off may leave the keyword out.  Then one vertex a line, x y z
 * (then the normal with N, which is kept; colours and texture coordinates are
 * ignored), and one face a line: its corner count, then its 0-based vertex
 * indices (a colour after them is ignored).  `#` starts a comment; blank lines
 * are skipped.  The counts are checked against the file's size before anything is
 * allocated: a vertex line has at least 6 bytes ("0 0 0\n"), a face line at least
 * 8 ("3 0 1 2\n").  The 4-dimensional and binary forms are refused.
 */
#include "reader.h"

#include <string.h>

/* The next line that holds something other than blanks and a comment. */
static bool next_content(text_cursor *c)
{
    while (tc_next_line(c))
        if (!tc_at_eol(c)) return true;
    return false;
}

/* A count at c->p, to *out (>= 0). */
static int off_count(mesh_builder *b, text_cursor *c, const char *what, long long *out)
{
    tc_skip_blanks(c);
    const char *q = c->p;
    if (c->p >= c->eol || *c->p == '#' || parse_long(&c->p, c->eol, out) != 0 || *out < 0)
        return mb_err_line(b, c->line, "expected the number of %s, got '%.*s'", what,
                           (int)word_len(q, c->eol), q);
    return 0;
}

int mesh_read_off(mesh_builder *b, const char *data, size_t len)
{
    b->m->format = MESH_OFF;
    b->m->form = "OFF";
    text_cursor c;
    tc_init(&c, data, len);
    if (!next_content(&c)) return mb_err(b, "it has no OFF header and no counts");
    if (c.eol - c.p >= 3 && memcmp(c.p, "\xEF\xBB\xBF", 3) == 0) c.p += 3; /* a UTF-8 mark */
    bool st = false, col = false, nrm = false;
    const char *p = c.p;
    if (c.eol - p >= 2 && p[0] == 'S' && p[1] == 'T') st = true, p += 2;
    if (p < c.eol && *p == 'C') col = true, p++;
    if (p < c.eol && *p == 'N') nrm = true, p++;
    if (p < c.eol && (*p == '4' || *p == 'n') && word_len(p, c.eol) >= 4 &&
        (memcmp(p + 1, "OFF", 3) == 0 || memcmp(p + 1, "nOFF", 4) == 0))
        return mb_err_line(b, c.line, "'%.*s': OFF of more than 3 dimensions is not read",
                           (int)word_len(c.p, c.eol), c.p);
    if (c.eol - p >= 3 && memcmp(p, "OFF", 3) == 0) { /* the keyword */
        c.p = p + 3;
        tc_skip_blanks(&c);
        if (word_is(c.p, c.eol, "BINARY"))
            return mb_err_line(b, c.line, "binary OFF is not read: write it as text");
        if (tc_at_eol(&c) && !next_content(&c))
            return mb_err(b, "it ends after its header, with no counts");
    } else if (st || col || nrm) {
        return mb_err_line(b, c.line, "expected an OFF header, got '%.*s'",
                           (int)word_len(c.p, c.eol), c.p);
    }
    (void)st; /* (what follows x y z is not read) */
    (void)col;
    long long nv, nf, ne = 0;
    if (off_count(b, &c, "vertices", &nv) != 0 || off_count(b, &c, "faces", &nf) != 0) return -1;
    if (!tc_at_eol(&c) && off_count(b, &c, "edges", &ne) != 0) return -1;
    if (!tc_at_eol(&c))
        return mb_err_line(b, c.line, "unexpected '%.*s' after the counts",
                           (int)word_len(c.p, c.eol), c.p);
    long header_line = c.line;
    size_t left = (size_t)(c.end - c.next);
    if (nv > (long long)(left / 6) || nf > (long long)((left - 6 * (size_t)nv) / 8))
        return mb_err_line(b, header_line,
                           "the header declares %lld vertices and %lld faces, which need at "
                           "least %lld bytes; the file has %zu after it",
                           nv, nf, 6 * nv + 8 * nf, left);
    if (mb_reserve_vertices(b, (long)nv) != 0 || mb_reserve_faces(b, (long)nf, 3 * (long)nf) != 0)
        return mb_oom(b);
    for (long long i = 0; i < nv; i++) {
        if (!next_content(&c))
            return mb_err_line(b, c.line, "the file ends after %lld of the %lld vertices the "
                               "header (line %ld) declares", i, nv, header_line);
        double x[6];
        int want = nrm ? 6 : 3;
        for (int k = 0; k < want; k++) {
            tc_skip_blanks(&c);
            const char *q = c.p;
            int rc = c.p < c.eol && *c.p != '#' ? parse_double(&c.p, c.eol, &x[k]) : -1;
            if (rc == -2)
                return mb_err_line(b, c.line, "vertex %lld: %.*s is not a finite number", i,
                                   (int)word_len(q, c.eol), q);
            if (rc != 0)
                return mb_err_line(b, c.line, "vertex %lld needs %d numbers (x y z%s), got %d", i,
                                   want, nrm ? " and the normal" : "", k);
        }
        if (mb_vertex(b, v3(x[0], x[1], x[2])) < 0) return mb_oom(b);
        if (nrm && mb_normal(b, v3(x[3], x[4], x[5])) < 0) return mb_oom(b);
    }
    for (long long f = 0; f < nf; f++) {
        if (!next_content(&c))
            return mb_err_line(b, c.line, "the file ends after %lld of the %lld faces the header "
                               "(line %ld) declares", f, nf, header_line);
        long long n;
        tc_skip_blanks(&c);
        const char *q = c.p;
        if (parse_long(&c.p, c.eol, &n) != 0)
            return mb_err_line(b, c.line, "face %lld: expected its number of corners, got '%.*s'",
                               f, (int)word_len(q, c.eol), q);
        if (n < 3 || n > (long long)(c.eol - c.p) / 2)
            return mb_err_line(b, c.line, "face %lld: %lld corners: %s", f, n,
                               n < 3 ? "a face needs at least 3"
                                     : "more than the line has room for");
        for (long long k = 0; k < n; k++) {
            long long v;
            tc_skip_blanks(&c);
            q = c.p;
            if (c.p >= c.eol || parse_long(&c.p, c.eol, &v) != 0)
                return mb_err_line(b, c.line, "face %lld: expected %lld vertex indices, got %s",
                                   f, n, c.p >= c.eol ? "fewer" : "something else");
            if (v < 0 || v >= nv)
                return mb_err_line(b, c.line,
                                   "face %lld: vertex index %lld is out of range: the file has "
                                   "%lld vertices (0 to %lld)",
                                   f, v, nv, nv - 1);
            if (mb_corner(b, (int)v, nrm ? (int)v : -1) != 0) return mb_oom(b);
        }
        if (mb_face_end(b) != 0) return mb_oom(b);
    }
    (void)ne;
    return 0;
}
