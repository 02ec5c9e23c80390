/* meshfile.c: reading a mesh file's bytes, telling its format from its content,
 * and the builder the readers share: welding, sorting, messages (meshfile.h,
 * reader.h).
 *
 * Welding makes vertices with equal coordinates one (by value: -0 and 0 are
 * equal), so that an STL's triangles share corners; sorting them by x, then y,
 * then z makes the point set canonical: the same points in any order and any
 * format give the core the same array, and so the same hull to the bit.
 */
#include "reader.h"

#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core/grow.h"

/* ---------------------------------------------------------------- reading */

int mesh_read_bytes(const char *path, unsigned char **data, size_t *len, char *err, size_t errlen)
{
    *data = NULL;
    *len = 0;
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(err, errlen, "%s", strerror(errno));
        return -1;
    }
    struct stat sb;
    if (fstat(fileno(f), &sb) != 0 || S_ISDIR(sb.st_mode)) {
        snprintf(err, errlen, "%s", S_ISDIR(sb.st_mode) ? "it is a folder" : strerror(errno));
        fclose(f);
        return -1;
    }
    if (S_ISREG(sb.st_mode) && sb.st_size > MESH_MAX_FILE) {
        snprintf(err, errlen, "it has %lld bytes, more than the %ld a mesh file may have",
                 (long long)sb.st_size, MESH_MAX_FILE);
        fclose(f);
        return -1;
    }
    /* a regular file is read in one go; anything else (a pipe) grows as it comes */
    size_t cap = S_ISREG(sb.st_mode) ? (size_t)sb.st_size + 1 : 65536, n = 0;
    unsigned char *buf = malloc(cap);
    for (;;) {
        if (!buf) {
            snprintf(err, errlen, "out of memory");
            fclose(f);
            return -1;
        }
        if (n + 1 == cap) { /* full: it grew since fstat, or is not a regular file */
            if (cap > (size_t)MESH_MAX_FILE) {
                snprintf(err, errlen, "it has more than the %ld bytes a mesh file may have",
                         MESH_MAX_FILE);
                free(buf);
                fclose(f);
                return -1;
            }
            unsigned char *nb = realloc(buf, cap * 2);
            if (!nb) free(buf);
            buf = nb;
            cap *= 2;
            continue;
        }
        size_t got = fread(buf + n, 1, cap - 1 - n, f);
        n += got;
        if (got == 0) break;
    }
    if (ferror(f)) {
        snprintf(err, errlen, "%s", strerror(errno));
        free(buf);
        fclose(f);
        return -1;
    }
    fclose(f);
    buf[n] = '\0';
    *data = buf;
    *len = n;
    return 0;
}

/* ---------------------------------------------------------------- formats */

bool mesh_stl_binary(const unsigned char *data, size_t len)
{
    return len >= 84 && (len - 84) % 50 == 0 && (len - 84) / 50 == le32(data + 80);
}

size_t mesh_text_length(const unsigned char *data, size_t len)
{
    if (mesh_stl_binary(data, len)) return 0;
    if (len < 3 || memcmp(data, "ply", 3) != 0) return len;
    for (size_t i = 0; i + 10 <= len; i++) /* the line that ends the header */
        if ((i == 0 || data[i - 1] == '\n') && memcmp(data + i, "end_header", 10) == 0) return i;
    return len;
}

/* Text: no NUL and no control character but blanks and line ends (and the ^Z some
 * old programs end text with); bytes from 128 on (UTF-8) are text. */
static bool is_text(const unsigned char *data, size_t len)
{
    for (size_t i = 0; i < len; i++) {
        unsigned char c = data[i];
        if (c < 32 && c != '\t' && c != '\n' && c != '\r' && c != '\v' && c != '\f' && c != 26)
            return false;
        if (c == 127) return false;
    }
    return true;
}

/* Whether the word at p is an OFF header keyword: [ST][C][N]OFF, then the end of
 * the word or a count glued to it. */
static bool is_off_word(const char *p, const char *end)
{
    if (end - p >= 2 && p[0] == 'S' && p[1] == 'T') p += 2;
    if (p < end && *p == 'C') p++;
    if (p < end && *p == 'N') p++;
    if (end - p < 3 || memcmp(p, "OFF", 3) != 0) return false;
    p += 3;
    return p == end || (*p >= '0' && *p <= '9') || *p == ' ' || *p == '\t' || *p == '\r' ||
           *p == '\n';
}

static bool ext_is(const char *name, const char *ext)
{
    const char *dot = name ? strrchr(name, '.') : NULL;
    return dot && strchr(dot, '/') == NULL && strcasecmp(dot + 1, ext) == 0;
}

int mesh_detect(const unsigned char *data, size_t len, const char *name, char *err, size_t errlen)
{
    if (len == 0) {
        snprintf(err, errlen, "%s: the file is empty", name);
        return -1;
    }
    if (mesh_stl_binary(data, len)) return MESH_STL;
    const char *p = (const char *)data, *end = p + len;
    if (len >= 3 && memcmp(p, "\xEF\xBB\xBF", 3) == 0) p += 3; /* a UTF-8 mark */
    while (p < end && (*p == ' ' || *p == '\t' || *p == '\r' || *p == '\n')) p++;
    size_t w = word_len(p, end);
    if (w == 3 && memcmp(p, "ply", 3) == 0) return MESH_PLY; /* its data may be binary */
    if (!is_text(data, len)) {
        if (len < 84)
            snprintf(err, errlen,
                     "%s: not text, and its %zu bytes are too few for a binary STL (84 + 50 n)",
                     name, len);
        else
            snprintf(err, errlen,
                     "%s: not text, and not a binary STL: it has %zu bytes, where a binary STL "
                     "of the %lu triangles its header counts has %llu (84 + 50 n)",
                     name, len, (unsigned long)le32(data + 80),
                     84ULL + 50ULL * le32(data + 80));
        return -1;
    }
    if (w == 5 && memcmp(p, "solid", 5) == 0) return MESH_STL;
    if (is_off_word(p, p + w)) return MESH_OFF;
    return ext_is(name, "off") ? MESH_OFF : MESH_OBJ;
}

int mesh_parse_as(mesh_format format, const unsigned char *data, size_t len, const char *name,
                  mesh_file *m, char *err, size_t errlen)
{
    mesh_builder b;
    mb_init(&b, m, name, err, errlen);
    int rc = -1;
    switch (format) {
    case MESH_OBJ: rc = mesh_read_obj(&b, (const char *)data, len); break;
    case MESH_STL: rc = mesh_read_stl(&b, data, len); break;
    case MESH_OFF: rc = mesh_read_off(&b, (const char *)data, len); break;
    case MESH_PLY: rc = mesh_read_ply(&b, data, len); break;
    }
    if (rc != 0) {
        mb_abandon(&b);
        return -1;
    }
    return mb_finish(&b);
}

int mesh_parse(const unsigned char *data, size_t len, const char *name, mesh_file *m, char *err,
               size_t errlen)
{
    memset(m, 0, sizeof *m);
    int format = mesh_detect(data, len, name, err, errlen);
    return format < 0 ? -1 : mesh_parse_as((mesh_format)format, data, len, name, m, err, errlen);
}

void mesh_file_free(mesh_file *m)
{
    if (!m) return;
    free(m->v);
    free(m->face_first);
    free(m->corner);
    free(m->n);
    free(m->corner_n);
    free(m->g);
    memset(m, 0, sizeof *m);
}

/* ---------------------------------------------------------------- messages */

static int vset(mesh_builder *b, const char *where, const char *fmt, va_list ap)
{
    char msg[400];
    vsnprintf(msg, sizeof msg, fmt, ap);
    snprintf(b->err, b->errlen, "%s%s: %s", b->name, where, msg);
    return -1;
}

int mb_err_line(mesh_builder *b, long line, const char *fmt, ...)
{
    char where[32];
    snprintf(where, sizeof where, ":%ld", line);
    va_list ap;
    va_start(ap, fmt);
    vset(b, where, fmt, ap);
    va_end(ap);
    return -1;
}

int mb_err_byte(mesh_builder *b, size_t offset, const char *fmt, ...)
{
    char where[40];
    snprintf(where, sizeof where, ": byte %zu", offset);
    va_list ap;
    va_start(ap, fmt);
    vset(b, where, fmt, ap);
    va_end(ap);
    return -1;
}

int mb_err(mesh_builder *b, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    vset(b, "", fmt, ap);
    va_end(ap);
    return -1;
}

int mb_oom(mesh_builder *b) { return mb_err(b, "out of memory"); }

/* ---------------------------------------------------------------- the builder */

void mb_init(mesh_builder *b, mesh_file *m, const char *name, char *err, size_t errlen)
{
    memset(b, 0, sizeof *b);
    memset(m, 0, sizeof *m);
    b->m = m;
    b->name = name ? name : "mesh";
    b->err = err;
    b->errlen = errlen;
}

void mb_abandon(mesh_builder *b)
{
    free(b->weld);
    b->weld = NULL;
    mesh_file_free(b->m);
}

/* Makes room for need items in *arr of *cap (ints: the counts stay below INT_MAX). */
static int room(void **arr, int *cap, long need, size_t size)
{
    if (need <= *cap) return 0;
    if (need >= INT_MAX) return -1;
    long c = *cap < 16 ? 16 : *cap;
    while (c < need) c = c > INT_MAX / 2 ? INT_MAX - 1 : 2 * c;
    void *p = realloc(*arr, (size_t)c * size);
    if (!p) return -1;
    *arr = p;
    *cap = (int)c;
    return 0;
}

int mb_reserve_vertices(mesh_builder *b, long n)
{
    return room((void **)&b->m->v, &b->cap_v, b->m->nv + n, sizeof *b->m->v);
}

int mb_reserve_faces(mesh_builder *b, long faces, long corners)
{
    mesh_file *m = b->m;
    if (room((void **)&m->face_first, &b->cap_f, m->nf + faces + 2, sizeof *m->face_first) != 0)
        return -1;
    if (b->nc + corners >= INT_MAX) return -1;
    int cap = (int)b->cap_c;
    if (room((void **)&m->corner, &cap, b->nc + corners, sizeof *m->corner) != 0) return -1;
    if (m->corner_n) {
        int cap_n = (int)b->cap_c;
        if (room((void **)&m->corner_n, &cap_n, b->nc + corners, sizeof *m->corner_n) != 0)
            return -1;
    }
    b->cap_c = cap;
    return 0;
}

int mb_vertex(mesh_builder *b, vec3 p)
{
    mesh_file *m = b->m;
    if (room((void **)&m->v, &b->cap_v, (long)m->nv + 1, sizeof *m->v) != 0) return -1;
    m->v[m->nv] = p;
    return m->nv++;
}

/* The hash of a point's coordinates, -0 taken as 0 (so that equal points hash
 * alike). */
static size_t point_hash(vec3 p)
{
    double c[3] = {p.x + 0.0, p.y + 0.0, p.z + 0.0};
    uint64_t h = 1469598103934665603ULL;
    for (int k = 0; k < 3; k++) {
        uint64_t u;
        memcpy(&u, &c[k], sizeof u);
        h = (h ^ u) * 1099511628211ULL;
        h ^= h >> 29;
    }
    return (size_t)(h ^ (h >> 32));
}

static bool same_point(vec3 a, vec3 b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

/* The welding table at twice the vertices at least (rebuilt when it grows). */
static int weld_grow(mesh_builder *b, size_t want)
{
    if (b->weld && want * 2 <= b->weld_cap) return 0;
    size_t cap = 1024;
    while (cap < want * 4) cap *= 2;
    int *t = calloc(cap, sizeof *t);
    if (!t) return -1;
    for (int i = 0; i < b->m->nv; i++) {
        size_t h = point_hash(b->m->v[i]) & (cap - 1);
        while (t[h]) h = (h + 1) & (cap - 1);
        t[h] = i + 1;
    }
    free(b->weld);
    b->weld = t;
    b->weld_cap = cap;
    return 0;
}

int mb_vertex_weld(mesh_builder *b, vec3 p)
{
    if (weld_grow(b, (size_t)b->m->nv + 1) != 0) return -1;
    size_t mask = b->weld_cap - 1, h = point_hash(p) & mask;
    for (; b->weld[h]; h = (h + 1) & mask)
        if (same_point(b->m->v[b->weld[h] - 1], p)) return b->weld[h] - 1;
    int i = mb_vertex(b, p);
    if (i >= 0) b->weld[h] = i + 1;
    return i;
}

int mb_normal(mesh_builder *b, vec3 n)
{
    mesh_file *m = b->m;
    if (room((void **)&m->n, &b->cap_n, (long)m->nn + 1, sizeof *m->n) != 0) return -1;
    m->n[m->nn] = n;
    return m->nn++;
}

int mb_corner(mesh_builder *b, int v, int n)
{
    mesh_file *m = b->m;
    if (b->nc + 1 > b->cap_c && mb_reserve_faces(b, 0, b->cap_c < 16 ? 16 : b->cap_c) != 0)
        return -1;
    if (n >= 0 && !m->corner_n) { /* the first normal: the corners before have none */
        m->corner_n = malloc((size_t)b->cap_c * sizeof *m->corner_n);
        if (!m->corner_n) return -1;
        for (long k = 0; k < b->nc; k++) m->corner_n[k] = -1;
    }
    m->corner[b->nc] = v;
    if (m->corner_n) m->corner_n[b->nc] = n;
    b->nc++;
    return 0;
}

int mb_face_end(mesh_builder *b)
{
    mesh_file *m = b->m;
    if (room((void **)&m->face_first, &b->cap_f, (long)m->nf + 2, sizeof *m->face_first) != 0)
        return -1;
    if (m->nf == 0) m->face_first[0] = 0;
    m->face_first[++m->nf] = (int)b->nc;
    if (m->ng == 0 && mb_group(b, "", 0) != 0) return -1;
    m->g[m->ng - 1].count++;
    return 0;
}

int mb_group(mesh_builder *b, const char *name, size_t len)
{
    mesh_file *m = b->m;
    if (m->ng > 0 && m->g[m->ng - 1].count == 0) m->ng--; /* the last one is empty */
    if (room((void **)&m->g, &b->cap_g, (long)m->ng + 1, sizeof *m->g) != 0) return -1;
    mesh_group *g = &m->g[m->ng++];
    if (len >= sizeof g->name) len = sizeof g->name - 1;
    memcpy(g->name, name, len);
    g->name[len] = '\0';
    g->first = m->nf;
    g->count = 0;
    return 0;
}

typedef struct {
    vec3 p;
    int i;
} keyed;

static int cmp_point(const void *a, const void *b)
{
    vec3 p = ((const keyed *)a)->p, q = ((const keyed *)b)->p;
    if (p.x != q.x) return p.x < q.x ? -1 : 1;
    if (p.y != q.y) return p.y < q.y ? -1 : 1;
    if (p.z != q.z) return p.z < q.z ? -1 : 1;
    return 0;
}

int mb_finish(mesh_builder *b)
{
    mesh_file *m = b->m;
    if (m->nv == 0) {
        mb_err(b, "it has no vertex");
        mb_abandon(b);
        return -1;
    }
    if (m->ng > 0 && m->g[m->ng - 1].count == 0) m->ng--;
    if (m->nf == 0) { /* no face: an empty face list, and no group */
        free(m->face_first);
        m->face_first = calloc(1, sizeof *m->face_first);
        m->ng = 0;
    }
    /* weld: old index -> distinct index, the distinct points in their first order */
    int *map = malloc((size_t)m->nv * sizeof *map);
    keyed *k = malloc((size_t)m->nv * sizeof *k);
    int nv = m->nv, nd = 0;
    if (!map || !k || !m->face_first || weld_grow(b, (size_t)nv) != 0) goto oom;
    memset(b->weld, 0, b->weld_cap * sizeof *b->weld);
    size_t mask = b->weld_cap - 1;
    for (int i = 0; i < nv; i++) {
        size_t h = point_hash(m->v[i]) & mask;
        while (b->weld[h] && !same_point(k[b->weld[h] - 1].p, m->v[i])) h = (h + 1) & mask;
        if (!b->weld[h]) {
            k[nd] = (keyed){m->v[i], nd};
            b->weld[h] = ++nd;
        }
        map[i] = b->weld[h] - 1;
    }
    free(b->weld);
    b->weld = NULL;
    /* sort the distinct points; rank[j] is where distinct point j went */
    qsort(k, (size_t)nd, sizeof *k, cmp_point);
    int *rank = malloc((size_t)nd * sizeof *rank);
    if (!rank) goto oom;
    for (int j = 0; j < nd; j++) {
        rank[k[j].i] = j;
        vec3 q = k[j].p; /* -0 as 0: the same points, the same bits */
        m->v[j] = v3(q.x + 0.0, q.y + 0.0, q.z + 0.0);
    }
    for (int i = 0; i < nv; i++) map[i] = rank[map[i]];
    free(rank);
    for (long c = 0; c < b->nc; c++) m->corner[c] = map[m->corner[c]];
    free(map);
    free(k);
    m->nv = nd;
    vec3 *v = realloc(m->v, (size_t)nd * sizeof *v); /* give back what welding freed */
    if (v) m->v = v;
    return 0;
oom:
    free(map);
    free(k);
    mb_oom(b);
    mb_abandon(b);
    return -1;
}

/* ---------------------------------------------------------------- text */

void tc_init(text_cursor *c, const char *data, size_t len)
{
    c->p = c->eol = c->next = data;
    c->end = data + len;
    c->line = 0;
}

bool tc_next_line(text_cursor *c)
{
    if (c->next >= c->end) return false;
    c->p = c->next;
    const char *nl = memchr(c->p, '\n', (size_t)(c->end - c->p));
    c->next = nl ? nl + 1 : c->end;
    c->eol = nl ? nl : c->end;
    if (c->eol > c->p && c->eol[-1] == '\r') c->eol--;
    c->line++;
    return true;
}

static bool is_blank(char ch) { return ch == ' ' || ch == '\t' || ch == '\r' || ch == '\v' || ch == '\f'; }

void tc_skip_blanks(text_cursor *c)
{
    while (c->p < c->eol && is_blank(*c->p)) c->p++;
}

bool tc_at_eol(text_cursor *c)
{
    tc_skip_blanks(c);
    return c->p >= c->eol || *c->p == '#';
}

size_t word_len(const char *p, const char *end)
{
    const char *q = p;
    while (q < end && !is_blank(*q) && *q != '\n' && *q != '#') q++;
    return (size_t)(q - p);
}

bool word_is(const char *p, const char *end, const char *w)
{
    size_t n = strlen(w);
    return word_len(p, end) == n && memcmp(p, w, n) == 0;
}

int parse_double(const char **pp, const char *end, double *out)
{
    /* the word ends at a blank, a line's end, '#' or the NUL after the text: none
     * of which strtod reads on into */
    const char *p = *pp;
    size_t n = word_len(p, end);
    if (n == 0) return -1;
    char *e;
    double x = strtod(p, &e);
    if (e != p + n) return -1;
    *pp = p + n;
    *out = x;
    return isfinite(x) ? 0 : -2;
}

int parse_long(const char **pp, const char *end, long long *out)
{
    const char *p = *pp;
    bool neg = false;
    if (p < end && (*p == '-' || *p == '+')) neg = *p++ == '-';
    if (p >= end || *p < '0' || *p > '9') return -1;
    long long x = 0;
    while (p < end && *p >= '0' && *p <= '9') {
        if (x > (1LL << 62) / 10) return -1;
        x = 10 * x + (*p++ - '0');
    }
    if (p < end && !is_blank(*p) && *p != '\n' && *p != '#') return -1;
    *pp = p;
    *out = neg ? -x : x;
    return 0;
}
