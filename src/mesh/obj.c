/* obj.c: the Wavefront OBJ reader (meshfile.h).
 *
 * Read: `v x y z` (more numbers, w or a colour, are ignored), `vn x y z`, and
 * `f` with any number of corners (3 or more) in the forms v, v/vt, v//vn and
 * v/vt/vn; a negative index counts back from the last vertex (or normal) so far,
 * a positive one may name a vertex given later in the file.  `o NAME` and
 * `g NAME...` name the faces that follow: each change of either starts a new
 * group.  `#` starts a comment, and a `\` at the end of a line joins the next
 * line to it.  Every other statement (vt, mtllib, usemtl, s, l, p, ...) is
 * ignored.  A line is named by where its statement starts.
 */
#include "reader.h"

#include <stdlib.h>
#include <string.h>

typedef struct {
    mesh_builder *b;
    char o[64], g[64];   /* the current o and g names */
    long forward;        /* the largest positive vertex index beyond the vertices so
                          * far, and its line: checked at the end */
    long forward_line;
} obj_state;

/* One index of a corner at *pp (ends at '/', a blank or eol): into n items so
 * far; 0-based in *out.  A positive index beyond n is left for the end. */
static int obj_index(obj_state *s, const char **pp, const char *eol, int n, const char *what,
                     long line, int *out)
{
    const char *p = *pp;
    long long i = 0;
    bool neg = p < eol && *p == '-';
    if (neg) p++;
    if (p >= eol || *p < '0' || *p > '9')
        return mb_err_line(s->b, line, "expected a %s index in a face, got '%.*s'", what,
                           (int)word_len(*pp, eol), *pp);
    while (p < eol && *p >= '0' && *p <= '9') {
        i = 10 * i + (*p++ - '0');
        if (i > 2147483647LL)
            return mb_err_line(s->b, line, "the %s index %s%lld... is too large", what,
                               neg ? "-" : "", i);
    }
    *pp = p;
    if (i == 0) return mb_err_line(s->b, line, "%s index 0: OBJ counts from 1", what);
    if (neg) {
        if (i > n)
            return mb_err_line(s->b, line,
                               "%s index -%lld counts back past the first: there are %d so far",
                               what, i, n);
        *out = (int)(n - i);
        return 0;
    }
    if (i > n && what[0] == 'n') /* normals come before the faces that use them */
        return mb_err_line(s->b, line, "normal index %lld is out of range: there are %d so far",
                           i, n);
    if (i > n && i > s->forward) {
        s->forward = (long)i;
        s->forward_line = line;
    }
    *out = (int)(i - 1);
    return 0;
}

/* A face's corners: the rest of the line. */
static int obj_face(obj_state *s, const char *p, const char *eol, long line)
{
    mesh_builder *b = s->b;
    int count = 0;
    for (;;) {
        while (p < eol && (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\v' || *p == '\f')) p++;
        if (p >= eol || *p == '#') break;
        int v, n = -1;
        if (obj_index(s, &p, eol, b->m->nv, "vertex", line, &v) != 0) return -1;
        if (p < eol && *p == '/') {
            p++;
            if (p < eol && *p != '/') { /* a texture index: checked for form, not kept */
                int t;
                if (obj_index(s, &p, eol, 2147483647, "texture", line, &t) != 0) return -1;
            }
            if (p < eol && *p == '/') {
                p++;
                if (obj_index(s, &p, eol, b->m->nn, "normal", line, &n) != 0) return -1;
            }
        }
        if (p < eol && !(*p == ' ' || *p == '\t' || *p == '\r' || *p == '\v' || *p == '\f' ||
                         *p == '#'))
            return mb_err_line(b, line, "unexpected '%c' in a face's corner", *p);
        if (mb_corner(b, v, n) != 0) return mb_oom(b);
        count++;
    }
    if (count < 3)
        return mb_err_line(b, line, "a face needs at least 3 corners (got %d)", count);
    return mb_face_end(b) == 0 ? 0 : mb_oom(b);
}

/* Three numbers: the rest of a v or vn line (more are ignored). */
static int obj_xyz(mesh_builder *b, const char *p, const char *eol, long line, const char *what,
                   vec3 *out)
{
    double x[3];
    for (int k = 0; k < 3; k++) {
        while (p < eol && (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\v' || *p == '\f')) p++;
        if (p >= eol || *p == '#')
            return mb_err_line(b, line, "%s needs 3 numbers (x y z), got %d", what, k);
        const char *q = p;
        int rc = parse_double(&p, eol, &x[k]);
        if (rc == -2)
            return mb_err_line(b, line, "%s: %.*s is not a finite number", what,
                               (int)word_len(q, eol), q);
        if (rc != 0)
            return mb_err_line(b, line, "%s: expected a number, got '%.*s'", what,
                               (int)(word_len(q, eol) > 40 ? 40 : word_len(q, eol)), q);
    }
    *out = v3(x[0], x[1], x[2]);
    return 0;
}

/* `o NAME` or `g NAME...`: a new group when the name changes. */
static int obj_name(obj_state *s, char *cur, const char *p, const char *eol)
{
    while (p < eol && (*p == ' ' || *p == '\t')) p++;
    const char *e = p;
    while (e < eol && *e != '#') e++;
    while (e > p && (e[-1] == ' ' || e[-1] == '\t' || e[-1] == '\r')) e--;
    size_t n = (size_t)(e - p);
    if (n > 63) n = 63;
    if (strlen(cur) == n && memcmp(cur, p, n) == 0 && s->b->m->ng > 0) return 0;
    memcpy(cur, p, n);
    cur[n] = '\0';
    return mb_group(s->b, p, n) == 0 ? 0 : mb_oom(s->b);
}

int mesh_read_obj(mesh_builder *b, const char *data, size_t len)
{
    b->m->format = MESH_OBJ;
    b->m->form = "OBJ";
    obj_state s = {.b = b};
    text_cursor c;
    tc_init(&c, data, len);
    char *joined = NULL;
    size_t jcap = 0;
    int rc = 0;
    while (rc == 0 && tc_next_line(&c)) {
        long line = c.line;
        const char *p = c.p, *eol = c.eol;
        if (eol > p && eol[-1] == '\\') { /* continued: join the lines, without the '\'s */
            size_t n = 0;
            for (;;) {
                bool more = eol > c.p && eol[-1] == '\\';
                size_t piece = (size_t)(eol - c.p) - more;
                if (n + piece + 2 > jcap) {
                    size_t cap = 2 * (n + piece + 2);
                    char *nj = realloc(joined, cap);
                    if (!nj) {
                        rc = mb_oom(b);
                        break;
                    }
                    joined = nj;
                    jcap = cap;
                }
                memcpy(joined + n, c.p, piece);
                n += piece;
                joined[n++] = ' ';
                if (!more || !tc_next_line(&c)) break;
                eol = c.eol;
            }
            if (rc != 0) break;
            joined[n] = '\0';
            p = joined;
            eol = joined + n;
        }
        while (p < eol && (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\v' || *p == '\f')) p++;
        if (p >= eol || *p == '#') continue;
        size_t w = word_len(p, eol);
        const char *rest = p + w;
        vec3 x;
        if (w == 1 && *p == 'v') {
            rc = obj_xyz(b, rest, eol, line, "v", &x);
            if (rc == 0 && mb_vertex(b, x) < 0) rc = mb_oom(b);
        } else if (w == 2 && p[0] == 'v' && p[1] == 'n') {
            rc = obj_xyz(b, rest, eol, line, "vn", &x);
            if (rc == 0 && mb_normal(b, x) < 0) rc = mb_oom(b);
        } else if (w == 1 && *p == 'f') {
            rc = obj_face(&s, rest, eol, line);
        } else if (w == 1 && (*p == 'o' || *p == 'g')) {
            rc = obj_name(&s, *p == 'o' ? s.o : s.g, rest, eol);
        }
    }
    free(joined);
    if (rc == 0 && s.forward > b->m->nv)
        rc = mb_err_line(b, s.forward_line, "vertex index %ld is out of range: the file has %d",
                         s.forward, b->m->nv);
    return rc;
}
