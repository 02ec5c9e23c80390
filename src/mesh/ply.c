/* ply.c: the PLY reader (Stanford's polygon format; meshfile.h).
 *
 * The header (`ply`, `format ascii|binary_little_endian|binary_big_endian 1.0`,
 * `comment` and `obj_info` lines, `element NAME COUNT`, `property TYPE NAME`,
 * `property list COUNTTYPE ITEMTYPE NAME`, `end_header`) is text; the data after
 * it is text or binary of either byte order.  Types: char, uchar, short, ushort,
 * int, uint, float, double, and their int8 ... float64 names.  The `vertex`
 * element gives x, y, z (and nx, ny, nz, kept when all three are there), of any
 * type; the `face` element gives its corners as a list named `vertex_indices` or
 * `vertex_index`, of any count and index type.  Other elements and properties
 * are read past.  Before anything is allocated, each element's count is checked
 * against the bytes after the header: a binary instance has at least its fixed
 * properties' and its lists' counts' sizes, a text one at least 2 bytes a value.
 * Text data is read as numbers separated by blanks and line ends.
 */
#include "reader.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { PLY_MAX_ELEMENTS = 32, PLY_MAX_PROPS = 64 };

typedef enum { T_NONE, T_I8, T_U8, T_I16, T_U16, T_I32, T_U32, T_F32, T_F64 } ply_type;

static const struct {
    const char *a, *b;
    int size;
} TYPES[] = {{"", "", 0},           {"char", "int8", 1},    {"uchar", "uint8", 1},
             {"short", "int16", 2}, {"ushort", "uint16", 2}, {"int", "int32", 4},
             {"uint", "uint32", 4}, {"float", "float32", 4}, {"double", "float64", 8}};

typedef struct {
    char name[32];
    ply_type type;  /* the value's, or a list's items' */
    ply_type count; /* a list's count, T_NONE for a single value */
} ply_prop;

typedef struct {
    char name[32];
    long long count;
    int np;
    ply_prop p[PLY_MAX_PROPS];
    size_t min_size; /* the least bytes of one instance in binary */
} ply_element;

typedef struct {
    mesh_builder *b;
    int format;      /* 0 ascii, 1 little-endian, 2 big-endian */
    const unsigned char *data, *pos, *end;
    text_cursor c;   /* ascii */
    long long nv;    /* the vertex element's count */
    bool normals;    /* the vertex element has nx, ny and nz: one normal a vertex */
} ply_reader;

static ply_type type_of(const char *p, const char *end)
{
    for (int t = 1; t <= T_F64; t++)
        if (word_is(p, end, TYPES[t].a) || word_is(p, end, TYPES[t].b)) return (ply_type)t;
    return T_NONE;
}

/* The next word of the current header line into out (cut to n - 1 bytes). */
static size_t next_word(text_cursor *c, char *out, size_t n)
{
    tc_skip_blanks(c);
    size_t w = word_len(c->p, c->eol);
    size_t k = w < n - 1 ? w : n - 1;
    memcpy(out, c->p, k);
    out[k] = '\0';
    c->p += w;
    return w;
}

static int read_header(ply_reader *r, ply_element *el, int *nel)
{
    mesh_builder *b = r->b;
    text_cursor *c = &r->c;
    tc_init(c, (const char *)r->data, (size_t)(r->end - r->data));
    while (tc_next_line(c) && tc_at_eol(c)) continue;
    if (c->eol - c->p >= 3 && memcmp(c->p, "\xEF\xBB\xBF", 3) == 0) c->p += 3; /* a UTF-8 mark */
    if (!word_is(c->p, c->eol, "ply")) return mb_err_line(b, c->line, "expected 'ply'");
    r->format = -1;
    *nel = 0;
    char w[64];
    for (;;) {
        if (!tc_next_line(c)) return mb_err_line(b, c->line, "the header has no end_header");
        if (tc_at_eol(c)) continue;
        next_word(c, w, sizeof w);
        if (strcmp(w, "comment") == 0 || strcmp(w, "obj_info") == 0) continue;
        if (strcmp(w, "end_header") == 0) break;
        if (strcmp(w, "format") == 0) {
            next_word(c, w, sizeof w);
            r->format = strcmp(w, "ascii") == 0                  ? 0
                        : strcmp(w, "binary_little_endian") == 0 ? 1
                        : strcmp(w, "binary_big_endian") == 0    ? 2
                                                                 : -2;
            if (r->format == -2)
                return mb_err_line(b, c->line, "unknown format '%s'", w);
            next_word(c, w, sizeof w);
            if (strcmp(w, "1.0") != 0)
                return mb_err_line(b, c->line, "PLY version '%s': only 1.0 is read", w);
        } else if (strcmp(w, "element") == 0) {
            if (*nel == PLY_MAX_ELEMENTS)
                return mb_err_line(b, c->line, "more than %d elements", PLY_MAX_ELEMENTS);
            ply_element *e = &el[(*nel)++];
            memset(e, 0, sizeof *e);
            next_word(c, e->name, sizeof e->name);
            tc_skip_blanks(c);
            if (parse_long(&c->p, c->eol, &e->count) != 0 || e->count < 0)
                return mb_err_line(b, c->line, "element %s: expected its count", e->name);
        } else if (strcmp(w, "property") == 0) {
            if (*nel == 0) return mb_err_line(b, c->line, "a property before any element");
            ply_element *e = &el[*nel - 1];
            if (e->np == PLY_MAX_PROPS)
                return mb_err_line(b, c->line, "more than %d properties", PLY_MAX_PROPS);
            ply_prop *p = &e->p[e->np++];
            tc_skip_blanks(c);
            if (word_is(c->p, c->eol, "list")) {
                next_word(c, w, sizeof w);
                tc_skip_blanks(c);
                p->count = type_of(c->p, c->eol);
                next_word(c, w, sizeof w);
                if (p->count == T_NONE || p->count >= T_F32)
                    return mb_err_line(b, c->line, "a list's count type must be an integer "
                                       "type, not '%s'", w);
                tc_skip_blanks(c);
            }
            p->type = type_of(c->p, c->eol);
            next_word(c, w, sizeof w);
            if (p->type == T_NONE) return mb_err_line(b, c->line, "unknown type '%s'", w);
            if (next_word(c, p->name, sizeof p->name) == 0)
                return mb_err_line(b, c->line, "a property needs a name");
            e->min_size += (size_t)TYPES[p->count ? p->count : p->type].size;
        } else {
            return mb_err_line(b, c->line, "unknown header line '%s'", w);
        }
        if (!tc_at_eol(c))
            return mb_err_line(b, c->line, "unexpected '%.*s'", (int)word_len(c->p, c->eol),
                               c->p);
    }
    if (r->format < 0) return mb_err_line(b, c->line, "the header has no format line");
    r->pos = (const unsigned char *)c->next;
    /* what the counts need, before anything is allocated */
    size_t left = (size_t)(r->end - r->pos);
    for (int i = 0; i < *nel; i++) {
        ply_element *e = &el[i];
        size_t each = r->format == 0 ? 2 * (size_t)e->np : e->min_size;
        if (e->count > 0 && e->np == 0)
            return mb_err(b, "element %s has %lld instances but no property", e->name, e->count);
        if (e->count > 0 && (unsigned long long)e->count > left / each)
            return mb_err_line(b, c->line,
                               "element %s: %lld instances need at least %llu bytes, but only "
                               "%zu are left for them (of the %zu after the header)",
                               e->name, e->count, (unsigned long long)each * (unsigned long long)e->count,
                               left, (size_t)(r->end - r->pos));
        left -= (size_t)e->count * each;
    }
    return 0;
}

/* One value of type t: from binary data (its byte order) or the text's next word.
 * where names it in messages. */
static int read_value(ply_reader *r, ply_type t, const char *what, long long i, double *out)
{
    mesh_builder *b = r->b;
    if (r->format == 0) {
        text_cursor *c = &r->c;
        while (tc_at_eol(c))
            if (!tc_next_line(c))
                return mb_err_line(b, c->line, "the file ends in %s %lld", what, i);
        const char *q = c->p;
        int rc = parse_double(&c->p, c->eol, out);
        if (rc == -2)
            return mb_err_line(b, c->line, "%s %lld: %.*s is not a finite number", what, i,
                               (int)word_len(q, c->eol), q);
        if (rc != 0)
            return mb_err_line(b, c->line, "%s %lld: expected a number, got '%.*s'", what, i,
                               (int)(word_len(q, c->eol) > 40 ? 40 : word_len(q, c->eol)), q);
        if (t < T_F32 && *out != floor(*out))
            return mb_err_line(b, c->line, "%s %lld: %.*s is not a whole number", what, i,
                               (int)word_len(q, c->eol), q);
        return 0;
    }
    int size = TYPES[t].size;
    if (r->end - r->pos < size)
        return mb_err_byte(b, (size_t)(r->pos - r->data), "the file ends in %s %lld", what, i);
    unsigned char v[8];
    for (int k = 0; k < size; k++) v[k] = r->pos[r->format == 1 ? k : size - 1 - k];
    size_t at = (size_t)(r->pos - r->data);
    r->pos += size;
    uint64_t u = 0;
    for (int k = size - 1; k >= 0; k--) u = u << 8 | v[k];
    switch (t) {
    case T_I8: *out = (int8_t)u; break;
    case T_U8: *out = (uint8_t)u; break;
    case T_I16: *out = (int16_t)u; break;
    case T_U16: *out = (uint16_t)u; break;
    case T_I32: *out = (int32_t)u; break;
    case T_U32: *out = (uint32_t)u; break;
    case T_F32: {
        uint32_t w = (uint32_t)u;
        float f;
        memcpy(&f, &w, sizeof f);
        *out = f;
        break;
    }
    default: memcpy(out, &u, sizeof *out); break;
    }
    if (!isfinite(*out))
        return mb_err_byte(b, at, "%s %lld: a value is %s", what, i, isnan(*out) ? "NaN" : "infinite");
    return 0;
}

/* Where the reader is, for messages: the line (text) or the byte (binary). */
static int err_here(ply_reader *r, const char *msg, const char *what, long long i)
{
    if (r->format == 0) return mb_err_line(r->b, r->c.line, "%s %lld: %s", what, i, msg);
    return mb_err_byte(r->b, (size_t)(r->pos - r->data), "%s %lld: %s", what, i, msg);
}

/* The place of e's single value named name (the last such), or -1. */
static int value_index(const ply_element *e, const char *name)
{
    int at = -1;
    for (int k = 0; k < e->np; k++)
        if (!e->p[k].count && strcmp(e->p[k].name, name) == 0) at = k;
    return at;
}

static int read_element(ply_reader *r, const ply_element *e, bool vertex, bool face)
{
    mesh_builder *b = r->b;
    int xyz[3], nxyz[3], list = -1;
    static const char *axes[3] = {"x", "y", "z"}, *naxes[3] = {"nx", "ny", "nz"};
    for (int a = 0; a < 3; a++) {
        xyz[a] = value_index(e, axes[a]);
        nxyz[a] = value_index(e, naxes[a]);
    }
    for (int k = 0; k < e->np; k++)
        if (e->p[k].count && (strcmp(e->p[k].name, "vertex_indices") == 0 ||
                              strcmp(e->p[k].name, "vertex_index") == 0))
            list = k;
    if (vertex && (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0))
        return mb_err(b, "the vertex element has no x, y and z");
    if (face && list < 0)
        return mb_err(b, "the face element has no vertex_indices (or vertex_index) list");
    const char *what = vertex ? "vertex" : face ? "face" : e->name;
    if (vertex && mb_reserve_vertices(b, (long)e->count) != 0) return mb_oom(b);
    if (face && mb_reserve_faces(b, (long)e->count, 3 * (long)e->count) != 0) return mb_oom(b);
    for (long long i = 0; i < e->count; i++) {
        double val[PLY_MAX_PROPS]; /* (a list's place is left unset: never read) */
        for (int k = 0; k < e->np; k++) {
            const ply_prop *p = &e->p[k];
            if (!p->count) {
                if (read_value(r, p->type, what, i, &val[k]) != 0) return -1;
                continue;
            }
            double n;
            if (read_value(r, p->count, what, i, &n) != 0) return -1;
            bool corners = face && k == list;
            size_t left = r->format == 0 ? (size_t)(r->end - (const unsigned char *)r->c.p) / 2
                                         : (size_t)(r->end - r->pos) / (size_t)TYPES[p->type].size;
            if (n < 0 || n > (double)left)
                return err_here(r, "a list's count is negative or more than the file holds", what, i);
            if (corners && n < 3) return err_here(r, "a face needs at least 3 corners", what, i);
            for (long long j = 0; j < (long long)n; j++) {
                double x;
                if (read_value(r, p->type, what, i, &x) != 0) return -1;
                if (!corners) continue;
                if (x < 0 || x >= (double)r->nv || x != floor(x)) {
                    char msg[160];
                    snprintf(msg, sizeof msg, "vertex index %.17g is out of range: the file "
                             "has %lld vertices (0 to %lld)", x, r->nv, r->nv - 1);
                    return err_here(r, msg, what, i);
                }
                if (mb_corner(b, (int)x, r->normals ? (int)x : -1) != 0) return mb_oom(b);
            }
            if (corners && mb_face_end(b) != 0) return mb_oom(b);
        }
        if (vertex && mb_vertex(b, v3(val[xyz[0]], val[xyz[1]], val[xyz[2]])) < 0)
            return mb_oom(b);
        if (vertex && r->normals &&
            mb_normal(b, v3(val[nxyz[0]], val[nxyz[1]], val[nxyz[2]])) < 0)
            return mb_oom(b);
    }
    return 0;
}

static int read_data(ply_reader *r, const ply_element *el, int nel)
{
    mesh_builder *b = r->b;
    static const char *forms[] = {"ASCII PLY", "binary little-endian PLY", "binary big-endian PLY"};
    b->m->form = forms[r->format];
    int iv = -1, iface = -1;
    for (int i = 0; i < nel; i++) {
        if (iv < 0 && strcmp(el[i].name, "vertex") == 0) iv = i;
        if (iface < 0 && strcmp(el[i].name, "face") == 0) iface = i;
    }
    if (iv < 0) return mb_err(b, "it has no vertex element");
    r->nv = el[iv].count;
    r->normals = value_index(&el[iv], "nx") >= 0 && value_index(&el[iv], "ny") >= 0 &&
                 value_index(&el[iv], "nz") >= 0;
    if (r->format == 0) r->c.p = r->c.eol = r->c.next; /* the text goes on after end_header */
    for (int i = 0; i < nel; i++)
        if (read_element(r, &el[i], i == iv, i == iface) != 0) return -1;
    return 0;
}

int mesh_read_ply(mesh_builder *b, const unsigned char *data, size_t len)
{
    b->m->format = MESH_PLY;
    b->m->form = "PLY";
    ply_reader r = {.b = b, .data = data, .end = data + len};
    ply_element *el = malloc(PLY_MAX_ELEMENTS * sizeof *el);
    if (!el) return mb_oom(b);
    int nel = 0, rc = read_header(&r, el, &nel);
    if (rc == 0) rc = read_data(&r, el, nel);
    free(el);
    return rc;
}
