/* draw.c: a mesh file made into the core's polyhedron source (meshfile.h): its
 * points, and a triangle mesh of its own faces with normals to draw.
 *
 * Faces of more than three corners are cut by ear clipping (Eberly, "Triangulation
 * by ear clipping", 2002) in the plane of their Newell normal, so that concave
 * polygons are drawn as they are; one of more than EAR_MAX corners is cut as a fan
 * (ear clipping costs up to the cube of the corners).  A corner's normal is the
 * file's where it gives one; otherwise the area-weighted mean of the normals of the
 * faces at its vertex that turn from its own face by less than CREASE: a
 * tessellated curve is drawn smooth and a box's edges stay sharp.  Each face
 * counts by its angle at the corner (Thurmer and Wuthrich 1998), so that a vertex
 * between large and small faces, as near the poles of a sphere's tessellation,
 * still gets the surface's normal.  (A vertex in
 * more than FAN_MAX faces takes its face's own normal: the search is quadratic in
 * them.)  Corners with the same vertex and normal share one vertex of the mesh.
 * Faces keep the file's winding, which may be either way: polyhedra are drawn
 * two-sided (view.c).
 */
#include "meshfile.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { EAR_MAX = 1024, FAN_MAX = 256 };
/* faces whose normals turn by less than this (40 degrees) are smoothed together */
static const double CREASE_COS = 0.766044443118978;

/* ---- ear clipping ---- */

static double cross2(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* p inside or on triangle abc (counter-clockwise). */
static bool in_triangle(const double *p, const double *a, const double *b, const double *c)
{
    return cross2(a, b, p) >= 0 && cross2(b, c, p) >= 0 && cross2(c, a, p) >= 0;
}

int mesh_ear_clip(const vec3 *p, int n, vec3 nrm, int (*tri)[3])
{
    if (n < 3) return 0;
    if (n == 3 || n > EAR_MAX || !(v3_len(nrm) > 0)) { /* a fan */
        for (int k = 1; k + 1 < n; k++) tri[k - 1][0] = 0, tri[k - 1][1] = k, tri[k - 1][2] = k + 1;
        return n - 2;
    }
    /* the plane: drop the normal's largest axis, and keep the polygon counter-clockwise */
    double ax[3] = {fabs(nrm.x), fabs(nrm.y), fabs(nrm.z)};
    int drop = ax[0] >= ax[1] && ax[0] >= ax[2] ? 0 : ax[1] >= ax[2] ? 1 : 2;
    int u = (drop + 1) % 3, w = (drop + 2) % 3;
    double s = (drop == 0 ? nrm.x : drop == 1 ? nrm.y : nrm.z) < 0 ? -1 : 1;
    double (*q)[2] = malloc((size_t)n * sizeof *q);
    int *next = malloc((size_t)n * sizeof *next), *prev = malloc((size_t)n * sizeof *prev);
    if (!q || !next || !prev) {
        free(q);
        free(next);
        free(prev);
        return -1;
    }
    for (int i = 0; i < n; i++) {
        double c[3] = {p[i].x, p[i].y, p[i].z};
        q[i][0] = c[u];
        q[i][1] = s * c[w];
        next[i] = (i + 1) % n;
        prev[i] = (i + n - 1) % n;
    }
    int left = n, t = 0, i = 0, tried = 0;
    while (left > 3) {
        int a = prev[i], c = next[i];
        bool ear = cross2(q[a], q[i], q[c]) > 0;
        for (int j = next[c]; ear && j != a; j = next[j]) /* no other corner in it */
            if (in_triangle(q[j], q[a], q[i], q[c]) && cross2(q[prev[j]], q[j], q[next[j]]) <= 0)
                ear = false;
        /* after a whole round without an ear (a polygon that crosses itself or
         * doubles back), cut the corner there anyway: n - 2 triangles still */
        if (ear || tried >= left) {
            tri[t][0] = a, tri[t][1] = i, tri[t][2] = c;
            t++;
            next[a] = c;
            prev[c] = a;
            left--;
            tried = 0;
            i = a;
        } else {
            i = c;
            tried++;
        }
    }
    tri[t][0] = prev[i], tri[t][1] = i, tri[t][2] = next[i];
    t++;
    free(q);
    free(next);
    free(prev);
    return t;
}

/* ---- the source ---- */

void mesh_source_release(shape_source *src)
{
    free(((mesh_source *)src)->path);
    free(src->pts);
    free(src->face_first);
    free(src->corner);
    free(src->piece_first);
    free(src->draw.pos);
    free(src->draw.nrm);
    free(src->draw.tri);
    free(src);
}

/* ---- the pieces ---- */

static int root_of(int *parent, int v)
{
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

/* Each face's piece into piece[] (the file's groups when it names more than one,
 * else the connected components of its faces, joined at shared vertices, in the
 * order of their first faces): their number, or -1 when out of memory. */
static int pieces_of(const mesh_file *m, int *piece)
{
    if (m->ng > 1) {
        int n = 0;
        for (int g = 0; g < m->ng; g++) {
            if (m->g[g].count == 0) continue;
            for (int f = m->g[g].first; f < m->g[g].first + m->g[g].count; f++) piece[f] = n;
            n++;
        }
        return n;
    }
    int *parent = malloc((size_t)(m->nv + 1) * sizeof *parent);
    int *label = malloc((size_t)(m->nv + 1) * sizeof *label);
    if (!parent || !label) {
        free(parent);
        free(label);
        return -1;
    }
    for (int v = 0; v < m->nv; v++) parent[v] = v, label[v] = -1;
    for (int f = 0; f < m->nf; f++) {
        int a = root_of(parent, m->corner[m->face_first[f]]);
        for (int c = m->face_first[f] + 1; c < m->face_first[f + 1]; c++) {
            int b = root_of(parent, m->corner[c]);
            if (a != b) parent[b < a ? a : b] = b < a ? b : a, a = b < a ? b : a;
        }
    }
    int n = 0;
    for (int f = 0; f < m->nf; f++) {
        int r = root_of(parent, m->corner[m->face_first[f]]);
        if (label[r] < 0) label[r] = n++;
        piece[f] = label[r];
    }
    free(parent);
    free(label);
    return n;
}

/* src's faces, from m's, in runs by piece (the file's order within each). */
static int faces_by_piece(const mesh_file *m, shape_source *src)
{
    long nc = m->nf > 0 ? m->face_first[m->nf] : 0;
    int *piece = malloc((size_t)(m->nf + 1) * sizeof *piece);
    src->face_first = malloc((size_t)(m->nf + 1) * sizeof *src->face_first);
    src->corner = malloc((size_t)(nc + 1) * sizeof *src->corner);
    int n = piece && src->face_first && src->corner ? pieces_of(m, piece) : -1;
    if (n >= 0) src->piece_first = calloc((size_t)n + 2, sizeof *src->piece_first);
    if (n < 0 || !src->piece_first) {
        free(piece);
        return -1;
    }
    /* counting sort of the faces by piece */
    for (int f = 0; f < m->nf; f++) src->piece_first[piece[f] + 1]++;
    for (int k = 0; k < n; k++) src->piece_first[k + 1] += src->piece_first[k];
    int *at = malloc((size_t)(m->nf + 1) * sizeof *at), *place = malloc((size_t)(n + 1) * sizeof *place);
    if (!at || !place) {
        free(at);
        free(place);
        free(piece);
        return -1;
    }
    memcpy(place, src->piece_first, (size_t)n * sizeof *place);
    for (int f = 0; f < m->nf; f++) at[place[piece[f]]++] = f;
    int c = 0;
    for (int k = 0; k < m->nf; k++) {
        int f = at[k];
        src->face_first[k] = c;
        for (int j = m->face_first[f]; j < m->face_first[f + 1]; j++) src->corner[c++] = m->corner[j];
    }
    src->face_first[m->nf] = c;
    src->nf = m->nf;
    src->npieces = n;
    free(at);
    free(place);
    free(piece);
    return 0;
}

/* Newell's normal of face f: its direction the face's, its length twice its area
 * (for a planar face). */
static vec3 newell(const mesh_file *m, int f)
{
    vec3 n = v3(0, 0, 0);
    int a = m->face_first[f], e = m->face_first[f + 1];
    for (int k = a; k < e; k++) {
        vec3 p = m->v[m->corner[k]], q = m->v[m->corner[k + 1 < e ? k + 1 : a]];
        n.x += (p.y - q.y) * (p.z + q.z);
        n.y += (p.z - q.z) * (p.x + q.x);
        n.z += (p.x - q.x) * (p.y + q.y);
    }
    return n;
}

/* The angle of face f at its corner c, between the nearest corners before and
 * after it at other points (a face may repeat a point: a quad folded into a
 * triangle at a pole); 0 when there are none. */
static double corner_angle(const mesh_file *m, int f, int c)
{
    int a = m->face_first[f], e = m->face_first[f + 1], n = e - a;
    int v = m->corner[c], before = c, after = c;
    for (int k = 1; k < n && m->corner[before] == v; k++) before = a + (c - a - k + n) % n;
    for (int k = 1; k < n && m->corner[after] == v; k++) after = a + (c - a + k) % n;
    vec3 p = m->v[v];
    vec3 u = v3_sub(m->v[m->corner[before]], p), w = v3_sub(m->v[m->corner[after]], p);
    double lu = v3_len(u), lw = v3_len(w);
    if (!(lu > 0 && lw > 0)) return 0;
    return atan2(v3_len(v3_cross(u, w)), v3_dot(u, w));
}

/* The file's normal of corner c, unit, or (0, 0, 0) when it gives none usable. */
static vec3 file_normal(const mesh_file *m, int c)
{
    if (!m->corner_n || m->corner_n[c] < 0) return v3(0, 0, 0);
    vec3 n = m->n[m->corner_n[c]];
    double l = v3_len(n);
    return isfinite(l) && l > 0 ? v3_scale(n, 1 / l) : v3(0, 0, 0);
}

mesh_source *mesh_source_make(const mesh_file *m, const char *path, char *err, size_t errlen)
{
    long nc = m->nf > 0 ? m->face_first[m->nf] : 0, nt = 0;
    for (int f = 0; f < m->nf; f++) nt += m->face_first[f + 1] - m->face_first[f] - 2;
    mesh_source *ms = calloc(1, sizeof *ms);
    shape_source *src = ms ? &ms->src : NULL;
    vec3 *fn = malloc((size_t)(m->nf + 1) * sizeof *fn);       /* face -> unit normal */
    int *first = calloc((size_t)m->nv + 1, sizeof *first);  /* vertex -> its corners */
    int *at = malloc((size_t)(nc + 1) * sizeof *at);
    int *face = malloc((size_t)(nc + 1) * sizeof *face);      /* corner -> face */
    int *dv = malloc((size_t)(nc + 1) * sizeof *dv);          /* corner -> mesh vertex */
    float *ang = malloc((size_t)(nc + 1) * sizeof *ang);      /* corner -> its angle */
    mesh *d = src ? &src->draw : NULL;
    int cap = m->nv + m->nv / 4 + 16, nd = 0;
    if (!src || !(ms->path = strdup(path)) || !fn || !first || !at || !face || !dv || !ang ||
        nt > 2147483647L)
        goto oom;
    src->release = mesh_source_release;
    src->np = m->nv;
    src->pts = malloc((size_t)m->nv * sizeof *src->pts);
    d->pos = malloc((size_t)cap * sizeof *d->pos);
    d->nrm = malloc((size_t)cap * sizeof *d->nrm);
    if (!src->pts || !d->pos || !d->nrm) goto oom;
    memcpy(src->pts, m->v, (size_t)m->nv * sizeof *src->pts);
    if (faces_by_piece(m, src) != 0) goto oom;
    for (int f = 0; f < m->nf; f++) {
        vec3 n = newell(m, f);
        double l = v3_len(n);
        fn[f] = isfinite(l) && l > 0 ? v3_scale(n, 1 / l) : v3(0, 0, 0);
        for (int k = m->face_first[f]; k < m->face_first[f + 1]; k++) {
            face[k] = f;
            ang[k] = (float)corner_angle(m, f, k);
        }
    }
    for (long c = 0; c < nc; c++) first[m->corner[c] + 1]++;
    for (int v = 0; v < m->nv; v++) first[v + 1] += first[v];
    for (long c = nc - 1; c >= 0; c--) at[--first[m->corner[c] + 1]] = (int)c;
    /* first[v + 1] went back to where v's corners start: one place down */
    for (int v = 0; v < m->nv; v++) first[v] = first[v + 1];
    first[m->nv] = (int)nc;
    /* the corners' normals, and the mesh's vertices */
    for (int v = 0; v < m->nv; v++) {
        int lo = first[v], hi = first[v + 1], start = nd;
        for (int k = lo; k < hi; k++) {
            int c = at[k];
            vec3 own = fn[face[c]], n = file_normal(m, c);
            if (v3_len2(n) == 0) {
                if (v3_len2(own) == 0 || hi - lo > FAN_MAX) {
                    n = own;
                } else {
                    for (int j = lo; j < hi; j++) {
                        vec3 g = fn[face[at[j]]];
                        if (v3_dot(g, own) >= CREASE_COS) n = v3_add(n, v3_scale(g, ang[at[j]]));
                    }
                }
                double l = v3_len(n);
                n = isfinite(l) && l > 0 ? v3_scale(n, 1 / l) : own;
                if (v3_len2(n) == 0) n = v3(0, 0, 1);
            }
            int same = -1;
            for (int e = nd - start > FAN_MAX ? nd - FAN_MAX : start; e < nd && same < 0; e++)
                if (d->nrm[e].x == n.x && d->nrm[e].y == n.y && d->nrm[e].z == n.z) same = e;
            if (same < 0) {
                if (nd == cap) {
                    cap = cap > 1073741823 ? 2147483647 : 2 * cap;
                    vec3 *p = realloc(d->pos, (size_t)cap * sizeof *p);
                    if (p) d->pos = p;
                    vec3 *q = p ? realloc(d->nrm, (size_t)cap * sizeof *q) : NULL;
                    if (q) d->nrm = q;
                    if (!p || !q) goto oom;
                }
                d->pos[nd] = m->v[v];
                d->nrm[nd] = n;
                same = nd++;
            }
            dv[c] = same;
        }
    }
    d->nv = nd;
    free(first);
    free(at);
    free(face);
    free(ang);
    first = at = face = NULL;
    ang = NULL;
    vec3 *shrunk = realloc(d->pos, (size_t)(nd + 1) * sizeof *shrunk);
    if (shrunk) d->pos = shrunk;
    shrunk = realloc(d->nrm, (size_t)(nd + 1) * sizeof *shrunk);
    if (shrunk) d->nrm = shrunk;
    /* the triangles */
    d->tri = malloc((size_t)(nt + 1) * sizeof *d->tri);
    if (!d->tri) goto oom;
    int t = 0;
    vec3 *corners = NULL;
    int (*ptri)[3] = NULL, pcap = 0;
    for (int f = 0; f < m->nf; f++) {
        int a = m->face_first[f], k = m->face_first[f + 1] - a;
        if (k == 3) {
            d->tri[t][0] = dv[a], d->tri[t][1] = dv[a + 1], d->tri[t][2] = dv[a + 2];
            t++;
            continue;
        }
        if (k > pcap) {
            vec3 *np = realloc(corners, (size_t)k * sizeof *np);
            if (np) corners = np;
            int (*nt3)[3] = realloc(ptri, (size_t)k * sizeof *nt3);
            if (nt3) ptri = nt3;
            if (!np || !nt3) {
                free(corners);
                free(ptri);
                goto oom;
            }
            pcap = k;
        }
        for (int j = 0; j < k; j++) corners[j] = m->v[m->corner[a + j]];
        int got = mesh_ear_clip(corners, k, fn[f], ptri);
        if (got < 0) {
            free(corners);
            free(ptri);
            goto oom;
        }
        for (int j = 0; j < got; j++, t++)
            for (int e = 0; e < 3; e++) d->tri[t][e] = dv[a + ptri[j][e]];
    }
    free(corners);
    free(ptri);
    d->nt = t;
    free(fn);
    free(dv);
    return ms;
oom:
    snprintf(err, errlen, "out of memory for the mesh of %d faces", m->nf);
    free(fn);
    free(first);
    free(at);
    free(face);
    free(dv);
    free(ang);
    if (src) mesh_source_release(src);
    return NULL;
}
