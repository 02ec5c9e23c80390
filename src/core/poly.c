/* poly.c: convex polyhedra with full adjacency, built from point clouds by qhull,
 * and their exact mass properties.
 *
 * A hull is built in up to three runs of libqhull_r (reentrant qhull; Barber,
 * Dobkin and Huhdanpaa 1996, "The Quickhull algorithm for convex hulls"):
 *
 *  1. the exact hull of the points, with qhull's default premerge ('C-0'), which
 *     merges facets coplanar to roundoff (a box's two triangles per side);
 *  2. if some neighbouring faces are nearly coplanar (normals within the flatness
 *     angle: the sides of a superquadric with small exponents are close to flat but
 *     not flat), the faces are grouped into flat regions; each region's plane has
 *     the area-weighted normal and is moved out to support the hull, and the
 *     vertices of the intersection of those half-spaces are the facets of the dual
 *     hull (points n / h, h the plane's distance from an interior point);
 *  3. the hull of those vertices, again merged to roundoff only.
 *
 * So every face is planar to roundoff, every input point lies inside every face
 * plane, and merging only grows the hull, by about the flatness angle times a
 * region's width.  Faces are walked from qhull's ridges; vertices met by only two
 * faces (the middle of a straight edge) are dropped; every incidence of poly.h is
 * derived from the oriented face cycles alone.  qhull writes its messages to a
 * memory stream, never to the console; the first line becomes the error message.
 *
 * Mass properties sum signed tetrahedra from a reference point over a fan of each
 * face, with the closed-form second moment of a tetrahedron (as in Tonon 2004,
 * "Explicit exact formulas for the 3-D tetrahedron inertia tensor"; Blow and
 * Binstock 2004, "How to find the inertia tensor (or other mass properties) of a
 * 3D solid body represented by a triangle mesh").
 */
#include "poly.h"

#include <float.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <libqhull_r/libqhull_r.h>

#include "errmsg.h"

/* Largest distance of a vertex from its face's plane accepted in a result: this
 * fraction of the cloud's size plus this many units of roundoff of its largest
 * coordinate (qhull's roundoff-level merging stays well below both). */
#define PLANAR_REL 1e-10
#define PLANAR_ULPS 1000

/* poly_hull_surface: the most vertex-face checks it makes before it leaves the
 * hull to qhull (they grow with the square of the points), and the least fold at
 * an edge, relative to the cloud's size, it accepts (far above roundoff, so that
 * qhull would merge none of its faces) */
#define POLY_SURFACE_CHECKS 2000000
#define POLY_SURFACE_FOLD 1e-9

/* ---- allocation ---- */

int poly_climb(const poly *p, vec3 d, int j)
{
    for (;;) {
        double best = v3_dot(p->v[j], d);
        int bj = -1;
        for (int k = p->vert_first[j]; k < p->vert_first[j + 1]; k++) {
            const poly_edge *e = &p->e[p->vert_edge[k]];
            int o = e->v[0] == j ? e->v[1] : e->v[0];
            double x = v3_dot(p->v[o], d);
            if (x > best) {
                best = x;
                bj = o;
            }
        }
        if (bj < 0) return j;
        j = bj;
    }
}

void poly_free(poly *p)
{
    if (!p) return;
    free(p->v);
    free(p->e);
    free(p->f);
    free(p->face_vert);
    free(p->face_edge);
    free(p->vert_first);
    free(p->vert_edge);
    free(p);
}

/* A poly with room for nv vertices, ne edges, nf faces and nfv face corners. */
static poly *poly_alloc(int nv, int ne, int nf, int nfv)
{
    poly *p = calloc(1, sizeof *p);
    if (!p) return NULL;
    p->nv = nv;
    p->ne = ne;
    p->nf = nf;
    p->v = malloc((size_t)nv * sizeof *p->v);
    p->e = malloc((size_t)ne * sizeof *p->e);
    p->f = malloc((size_t)nf * sizeof *p->f);
    p->face_vert = malloc((size_t)nfv * sizeof *p->face_vert);
    p->face_edge = malloc((size_t)nfv * sizeof *p->face_edge);
    p->vert_first = malloc((size_t)(nv + 1) * sizeof *p->vert_first);
    p->vert_edge = malloc((size_t)(2 * ne) * sizeof *p->vert_edge);
    if (!p->v || !p->e || !p->f || !p->face_vert || !p->face_edge || !p->vert_first ||
        !p->vert_edge) {
        poly_free(p);
        return NULL;
    }
    return p;
}

static int face_corners(const poly *p)
{
    return p->nf ? p->f[p->nf - 1].first + p->f[p->nf - 1].count : 0;
}

poly *poly_copy(const poly *p)
{
    int nfv = face_corners(p);
    poly *q = poly_alloc(p->nv, p->ne, p->nf, nfv);
    if (!q) return NULL;
    memcpy(q->v, p->v, (size_t)p->nv * sizeof *p->v);
    memcpy(q->e, p->e, (size_t)p->ne * sizeof *p->e);
    memcpy(q->f, p->f, (size_t)p->nf * sizeof *p->f);
    memcpy(q->face_vert, p->face_vert, (size_t)nfv * sizeof *p->face_vert);
    memcpy(q->face_edge, p->face_edge, (size_t)nfv * sizeof *p->face_edge);
    memcpy(q->vert_first, p->vert_first, (size_t)(p->nv + 1) * sizeof *p->vert_first);
    memcpy(q->vert_edge, p->vert_edge, (size_t)(2 * p->ne) * sizeof *p->vert_edge);
    return q;
}

/* ---- assembling a poly from face cycles ---- */

/* Area vector of the polygon pos[vert[0..count-1]] (Newell's method about the
 * centroid c): its direction is the normal of the ccw side, its length twice the
 * area. */
static vec3 polygon_area2(const vec3 *pos, const int *vert, int count, vec3 *centroid)
{
    vec3 c = v3(0, 0, 0);
    for (int k = 0; k < count; k++) c = v3_add(c, pos[vert[k]]);
    c = v3_scale(c, 1.0 / count);
    vec3 a = v3(0, 0, 0);
    for (int k = 0; k < count; k++) {
        vec3 p = v3_sub(pos[vert[k]], c), q = v3_sub(pos[vert[(k + 1) % count]], c);
        a = v3_add(a, v3_cross(p, q));
    }
    if (centroid) *centroid = c;
    return a;
}

static void reverse_ints(int *a, int n)
{
    for (int i = 0, j = n - 1; i < j; i++, j--) {
        int t = a[i];
        a[i] = a[j];
        a[j] = t;
    }
}

/* Orients each face cycle ccw about its hint normal and fits its plane (Newell
 * normal, mean offset). */
static int assemble_faces(poly *p, const int *count, const vec3 *hint, char *err,
                          size_t errlen)
{
    int first = 0;
    for (int f = 0; f < p->nf; f++) {
        poly_face *F = &p->f[f];
        F->first = first;
        F->count = count[f];
        first += count[f];
        int *vert = p->face_vert + F->first;
        if (F->count < 3) {
            errmsg_set(err, errlen, "hull face %d has only %d vertices", f, F->count);
            return -1;
        }
        vec3 a = polygon_area2(p->v, vert, F->count, NULL);
        if (v3_dot(a, hint[f]) < 0) {
            reverse_ints(vert, F->count);
            a = v3_neg(a);
        }
        if (!(v3_len(a) > 0)) {
            errmsg_set(err, errlen, "hull face %d has no area", f);
            return -1;
        }
        F->n = v3_norm(a);
        double d = 0;
        for (int k = 0; k < F->count; k++) d += v3_dot(F->n, p->v[vert[k]]);
        F->d = d / F->count;
    }
    return 0;
}

/* Pairs every directed boundary step a -> b of a face with the step b -> a of its
 * neighbour, making the edges, face_edge and the vertex -> edge lists. */
static int assemble_edges(poly *p, char *err, size_t errlen)
{
    int nfv = face_corners(p), rc = -1;
    int *out_first = calloc((size_t)p->nv + 1, sizeof *out_first);
    int *out = malloc((size_t)nfv * sizeof *out); /* corner indices, by tail vertex */
    int *fill = calloc((size_t)p->nv, sizeof *fill);
    int *face_of = malloc((size_t)nfv * sizeof *face_of);
    if (!out_first || !out || !fill || !face_of) {
        errmsg_set(err, errlen, "out of memory");
        goto done;
    }
    for (int f = 0; f < p->nf; f++)
        for (int k = 0; k < p->f[f].count; k++) {
            face_of[p->f[f].first + k] = f;
            out_first[p->face_vert[p->f[f].first + k] + 1]++;
        }
    for (int v = 0; v < p->nv; v++) out_first[v + 1] += out_first[v];
    for (int i = 0; i < nfv; i++) {
        int a = p->face_vert[i];
        out[out_first[a] + fill[a]++] = i;
    }
    int ne = 0;
    for (int i = 0; i < nfv; i++) {
        const poly_face *F = &p->f[face_of[i]];
        int k = i - F->first;
        int a = p->face_vert[i], b = p->face_vert[F->first + (k + 1) % F->count];
        if (a == b) {
            errmsg_set(err, errlen, "hull face %d repeats vertex %d", face_of[i], a);
            goto done;
        }
        if (a > b) continue;
        int twin = -1, found = 0;
        for (int j = out_first[b]; j < out_first[b + 1]; j++) {
            int c = out[j];
            const poly_face *G = &p->f[face_of[c]];
            if (p->face_vert[G->first + (c - G->first + 1) % G->count] == a) {
                twin = c;
                found++;
            }
        }
        if (found != 1 || ne >= p->ne) {
            errmsg_set(err, errlen, "hull edge %d-%d is not shared by exactly two faces", a, b);
            goto done;
        }
        p->e[ne] = (poly_edge){{a, b}, {face_of[i], face_of[twin]}};
        p->face_edge[i] = p->face_edge[twin] = ne++;
    }
    if (ne != p->ne) {
        errmsg_set(err, errlen, "hull has %d edges, expected %d", ne, p->ne);
        goto done;
    }
    memset(p->vert_first, 0, (size_t)(p->nv + 1) * sizeof *p->vert_first);
    for (int e = 0; e < ne; e++) {
        p->vert_first[p->e[e].v[0] + 1]++;
        p->vert_first[p->e[e].v[1] + 1]++;
    }
    for (int v = 0; v < p->nv; v++) p->vert_first[v + 1] += p->vert_first[v];
    memset(fill, 0, (size_t)p->nv * sizeof *fill);
    for (int e = 0; e < ne; e++)
        for (int s = 0; s < 2; s++) {
            int v = p->e[e].v[s];
            p->vert_edge[p->vert_first[v] + fill[v]++] = e;
        }
    rc = 0;
done:
    free(out_first);
    free(out);
    free(fill);
    free(face_of);
    return rc;
}

/* A poly from nv positions and nf face cycles (fvert, count[f] vertices each, any
 * orientation), hint[f] pointing out of face f.  NULL with err on failure. */
static poly *poly_assemble(int nv, const vec3 *pos, int nf, const int *count,
                           const int *fvert, const vec3 *hint, char *err, size_t errlen)
{
    int nfv = 0;
    for (int f = 0; f < nf; f++) nfv += count[f];
    if (nfv % 2 != 0) {
        errmsg_set(err, errlen, "hull faces do not close up (%d corners)", nfv);
        return NULL;
    }
    poly *p = poly_alloc(nv, nfv / 2, nf, nfv);
    if (!p) {
        errmsg_set(err, errlen, "out of memory");
        return NULL;
    }
    memcpy(p->v, pos, (size_t)nv * sizeof *pos);
    memcpy(p->face_vert, fvert, (size_t)nfv * sizeof *fvert);
    if (assemble_faces(p, count, hint, err, errlen) < 0 || assemble_edges(p, err, errlen) < 0) {
        poly_free(p);
        return NULL;
    }
    if (p->nv - p->ne + p->nf != 2) {
        errmsg_set(err, errlen, "hull is not a closed surface (V - E + F = %d)",
                p->nv - p->ne + p->nf);
        poly_free(p);
        return NULL;
    }
    return p;
}

poly *poly_box(vec3 h, char *err, size_t errlen)
{
    /* qhull's vertex order for the corners (k & 1: +x, k & 2: +y, k & 4: +z), and
     * its facets' cycles as it gives them: poly_assemble turns faces 0, 3, 4 and 5
     * to face out (which makes their normals' zeros -0, as with qhull's) */
    static const int corner[8] = {1, 6, 4, 2, 7, 0, 3, 5};
    static const int cycle[6][4] = {{6, 3, 5, 0}, {7, 2, 5, 0}, {7, 0, 6, 4},
                                    {1, 2, 5, 3}, {1, 3, 6, 4}, {1, 4, 7, 2}};
    vec3 pos[8], hint[6];
    int count[6], fvert[24];
    for (int i = 0; i < 8; i++) {
        int k = corner[i];
        pos[i] = v3(k & 1 ? h.x : -h.x, k & 2 ? h.y : -h.y, k & 4 ? h.z : -h.z);
    }
    for (int f = 0; f < 6; f++) {
        vec3 c = v3(0, 0, 0);
        for (int k = 0; k < 4; k++) {
            fvert[4 * f + k] = cycle[f][k];
            c = v3_add(c, pos[cycle[f][k]]);
        }
        count[f] = 4;
        hint[f] = c; /* (the face's centre points out of a box about the origin) */
    }
    return poly_assemble(8, pos, 6, count, fvert, hint, err, errlen);
}

/* ---- running qhull ---- */

/* One qhull session: its state, a private error stream (so that qhull never writes
 * to the console) and the coordinates it points into. */
typedef struct {
    qhT qh;
    FILE *log;
    char *logbuf;
    size_t loglen;
    coordT *coords;
    int exitcode;
    bool started; /* qh_new_qhull was called: qhull memory to free */
} qrun;

static void qrun_end(qrun *r)
{
    int curlong, totlong;
    if (r->started) {
        qh_freeqhull(&r->qh, !qh_ALL);
        qh_memfreeshort(&r->qh, &curlong, &totlong);
    }
    if (r->log) fclose(r->log);
    free(r->logbuf);
    free(r->coords);
}

/* qhull's failure in plain words: its own message (its first line) speaks of its
 * options and roundoff, which a user of vroc never set; it stays in the log. */
static void qrun_message(qrun *r, const char *what, char *err, size_t errlen)
{
    if (r->exitcode == qh_ERRsingular)
        errmsg_set(err, errlen, "%s: points are coplanar or collinear (no volume)", what);
    else if (r->exitcode == qh_ERRmem)
        errmsg_set(err, errlen, "%s: out of memory", what);
    else
        errmsg_set(err, errlen,
                "%s: the points are too close together for their size to make a solid",
                what);
}

/* Runs qhull on n points, with its default merging of facets coplanar to roundoff
 * ('C-0').  Returns 0, or -1 with err (call qrun_end either way). */
static int qrun_start(qrun *r, const vec3 *pts, int n, char *err, size_t errlen)
{
    memset(r, 0, sizeof *r);
    r->coords = malloc((size_t)n * 3 * sizeof *r->coords);
    r->log = open_memstream(&r->logbuf, &r->loglen); /* qhull writes its messages here */
    if (!r->coords || !r->log) {
        errmsg_set(err, errlen, "out of memory");
        r->exitcode = -1;
        return -1;
    }
    for (int i = 0; i < n; i++) {
        r->coords[3 * i] = pts[i].x;
        r->coords[3 * i + 1] = pts[i].y;
        r->coords[3 * i + 2] = pts[i].z;
    }
    char cmd[] = "qhull ";
    qh_zero(&r->qh, r->log);
    r->started = true;
    r->exitcode = qh_new_qhull(&r->qh, 3, n, r->coords, False, cmd, NULL, r->log);
    return r->exitcode ? -1 : 0;
}

/* The cycle of facet's vertices, walked from its ridges (or its three vertices when
 * simplicial), as indices vmap[vertex->id], appended to cyc.  Returns the count. */
static int facet_cycle(qhT *qh, facetT *facet, const int *vmap, int *cyc, int *nbr,
                       int *stamp, int mark)
{
    vertexT *vertex, **vertexp;
    ridgeT *ridge, **ridgep;
    int k = 0;
    (void)qh;
    if (facet->simplicial) {
        FOREACHvertex_(facet->vertices) cyc[k++] = vmap[vertex->id];
        return k;
    }
    /* nbr[2v], nbr[2v+1]: v's two neighbours along the facet's boundary */
    int start = -1, nridge = 0;
    FOREACHridge_(facet->ridges)
    {
        int ab[2] = {vmap[((vertexT *)SETfirst_(ridge->vertices))->id],
                     vmap[((vertexT *)SETsecond_(ridge->vertices))->id]};
        for (int s = 0; s < 2; s++) {
            int v = ab[s];
            if (stamp[v] != mark) {
                stamp[v] = mark;
                nbr[2 * v] = ab[1 - s];
                nbr[2 * v + 1] = -1;
            } else if (nbr[2 * v + 1] < 0) {
                nbr[2 * v + 1] = ab[1 - s];
            } else {
                return -1;
            }
        }
        start = ab[0];
        nridge++;
    }
    int prev = -1, v = start;
    for (; k < nridge; k++) {
        if (nbr[2 * v + 1] < 0) return -1;
        cyc[k] = v;
        int next = nbr[2 * v] != prev ? nbr[2 * v] : nbr[2 * v + 1];
        prev = v;
        v = next;
        if (v == start && k + 1 < nridge) return -1;
    }
    return v == start ? k : -1;
}

/* Keeps only vertices met by three or more faces (the others are the middle of a
 * straight edge), renumbering them compactly; rewrites cyc and count in place. */
static int drop_edge_vertices(int nvq, vec3 *pos, int nf, int *count, int *cyc)
{
    int *uses = calloc((size_t)nvq, sizeof *uses), nfv = 0;
    if (!uses) return -1;
    for (int f = 0; f < nf; f++) nfv += count[f];
    for (int i = 0; i < nfv; i++) uses[cyc[i]]++;
    int nv = 0;
    for (int v = 0; v < nvq; v++) {
        if (uses[v] >= 3) {
            pos[nv] = pos[v];
            uses[v] = nv++;
        } else {
            uses[v] = -1;
        }
    }
    int in = 0, out = 0;
    for (int f = 0; f < nf; f++) {
        int kept = 0;
        for (int k = 0; k < count[f]; k++, in++)
            if (uses[cyc[in]] >= 0) cyc[out + kept++] = uses[cyc[in]];
        count[f] = kept;
        out += kept;
    }
    free(uses);
    return nv;
}

/* The poly of a finished qhull run. */
static poly *qrun_extract(qrun *r, char *err, size_t errlen)
{
    qhT *qh = &r->qh;
    facetT *facet;
    vertexT *vertex;
    int nvq = qh->num_vertices, nf = qh->num_facets, nfv = 0;
    FORALLfacets nfv += qh_setsize(qh, facet->vertices);
    int *vmap = malloc((size_t)qh->vertex_id * sizeof *vmap);
    vec3 *pos = malloc((size_t)nvq * sizeof *pos);
    int *nbr = malloc((size_t)nvq * 2 * sizeof *nbr);
    int *stamp = malloc((size_t)nvq * sizeof *stamp);
    int *count = malloc((size_t)nf * sizeof *count);
    int *cyc = malloc((size_t)nfv * sizeof *cyc);
    vec3 *hint = malloc((size_t)nf * sizeof *hint);
    poly *p = NULL;
    if (!vmap || !pos || !nbr || !stamp || !count || !cyc || !hint) {
        errmsg_set(err, errlen, "out of memory");
        goto done;
    }
    int nv = 0;
    FORALLvertices
    {
        vmap[vertex->id] = nv;
        stamp[nv] = -1;
        pos[nv++] = v3(vertex->point[0], vertex->point[1], vertex->point[2]);
    }
    int f = 0, at = 0;
    FORALLfacets
    {
        count[f] = facet_cycle(qh, facet, vmap, cyc + at, nbr, stamp, f);
        if (count[f] < 3 || count[f] != qh_setsize(qh, facet->vertices)) {
            errmsg_set(err, errlen, "qhull facet f%u has no simple boundary", facet->id);
            goto done;
        }
        hint[f] = v3(facet->normal[0], facet->normal[1], facet->normal[2]);
        at += count[f++];
    }
    nv = drop_edge_vertices(nv, pos, nf, count, cyc);
    if (nv < 0) {
        errmsg_set(err, errlen, "out of memory");
        goto done;
    }
    p = poly_assemble(nv, pos, nf, count, cyc, hint, err, errlen);
done:
    free(vmap);
    free(pos);
    free(nbr);
    free(stamp);
    free(count);
    free(cyc);
    free(hint);
    return p;
}

/* The hull of pts by one qhull run. */
static poly *hull_once(const vec3 *pts, int n, char *err, size_t errlen)
{
    qrun r;
    poly *p = NULL;
    if (qrun_start(&r, pts, n, err, errlen) == 0)
        p = qrun_extract(&r, err, errlen);
    else if (r.exitcode > 0)
        qrun_message(&r, "convex hull", err, errlen);
    qrun_end(&r);
    return p;
}

/* ---- merging nearly flat regions ---- */

/* Largest distance of a face's vertex from the face's plane. */
static double poly_planarity(const poly *p)
{
    double dev = 0;
    for (int f = 0; f < p->nf; f++)
        for (int k = 0; k < p->f[f].count; k++) {
            vec3 v = p->v[p->face_vert[p->f[f].first + k]];
            dev = fmax(dev, fabs(v3_dot(p->f[f].n, v) - p->f[f].d));
        }
    return dev;
}

static vec3 vertex_mean(const poly *p)
{
    vec3 c = v3(0, 0, 0);
    for (int v = 0; v < p->nv; v++) c = v3_add(c, p->v[v]);
    return v3_scale(c, 1.0 / p->nv);
}

/* ---- faces as their geometry gives them, whatever their numbering ----
 *
 * Merging must make the same solid of the same hull however its vertices and
 * faces are numbered (qhull's order, or a tessellation's: poly_hull_surface), to
 * the bit: so each face's area vector is summed from its least vertex
 * (lexicographically) on, regions are seeded in an order of the faces that their
 * areas and coordinates alone decide, and sums over faces and vertices run in
 * such orders. */

static int cmp_vec3(const vec3 *a, const vec3 *b)
{
    if (a->x != b->x) return a->x < b->x ? -1 : 1;
    if (a->y != b->y) return a->y < b->y ? -1 : 1;
    if (a->z != b->z) return a->z < b->z ? -1 : 1;
    return 0;
}

static int cmp_vec3_any(const void *a, const void *b) { return cmp_vec3(a, b); }

/* Where face f's cycle starts when read from its least vertex. */
static int face_start(const poly *p, int f)
{
    const int *fv = p->face_vert + p->f[f].first;
    int k0 = 0;
    for (int k = 1; k < p->f[f].count; k++)
        if (cmp_vec3(&p->v[fv[k]], &p->v[fv[k0]]) < 0) k0 = k;
    return k0;
}

/* Face f's area vector (polygon_area2) read from its least vertex on. */
static vec3 face_area2(const poly *p, int f)
{
    const int *fv = p->face_vert + p->f[f].first;
    int n = p->f[f].count, k0 = face_start(p, f);
    vec3 c = v3(0, 0, 0);
    for (int k = 0; k < n; k++) c = v3_add(c, p->v[fv[(k0 + k) % n]]);
    c = v3_scale(c, 1.0 / n);
    vec3 a = v3(0, 0, 0);
    for (int k = 0; k < n; k++) {
        vec3 u = v3_sub(p->v[fv[(k0 + k) % n]], c), w = v3_sub(p->v[fv[(k0 + k + 1) % n]], c);
        a = v3_add(a, v3_cross(u, w));
    }
    return a;
}

typedef struct {
    const poly *p;
    double area;
    int face, start;
} face_key;

/* Largest area first; ties by the faces' corners from their least vertex on
 * (then fewer corners first), so that the order is the geometry's. */
static int by_area_desc(const void *a, const void *b)
{
    const face_key *x = a, *y = b;
    if (x->area != y->area) return x->area < y->area ? 1 : -1;
    const poly *p = x->p;
    int nx = p->f[x->face].count, ny = p->f[y->face].count;
    const int *fx = p->face_vert + p->f[x->face].first, *fy = p->face_vert + p->f[y->face].first;
    for (int k = 0; k < nx && k < ny; k++) {
        int c = cmp_vec3(&p->v[fx[(x->start + k) % nx]], &p->v[fy[(y->start + k) % ny]]);
        if (c != 0) return c;
    }
    return (nx > ny) - (nx < ny);
}

/* The faces in that order (into order[]), their area vectors into a2[]; 0, or -1
 * when out of memory. */
static int faces_in_order(const poly *p, vec3 *a2, int *order)
{
    face_key *key = malloc((size_t)p->nf * sizeof *key);
    if (!key) return -1;
    for (int f = 0; f < p->nf; f++) {
        a2[f] = face_area2(p, f);
        key[f] = (face_key){p, v3_len(a2[f]), f, face_start(p, f)};
    }
    qsort(key, (size_t)p->nf, sizeof *key, by_area_desc);
    for (int i = 0; i < p->nf; i++) order[i] = key[i].face;
    free(key);
    return 0;
}

/* The mean of p's vertices, summed in the order of their coordinates. */
static vec3 vertex_mean_sorted(const poly *p)
{
    vec3 *v = malloc((size_t)p->nv * sizeof *v);
    if (!v) return vertex_mean(p);
    memcpy(v, p->v, (size_t)p->nv * sizeof *v);
    qsort(v, (size_t)p->nv, sizeof *v, cmp_vec3_any);
    vec3 c = v3(0, 0, 0);
    for (int i = 0; i < p->nv; i++) c = v3_add(c, v[i]);
    free(v);
    return v3_scale(c, 1.0 / p->nv);
}

/* Groups p's faces into regions: from each face not yet grouped, in order, the
 * faces connected to it whose normals (a2, unit) lie within half_angle of its
 * normal.  Writes region[f] and returns the number of regions, or -1 when out of
 * memory. */
static int flat_regions(const poly *p, const vec3 *a2, const int *order, double half_angle, int *region)
{
    int *stack = malloc((size_t)p->nf * sizeof *stack);
    vec3 *n = malloc((size_t)p->nf * sizeof *n);
    int nreg = -1;
    if (!stack || !n) goto done;
    for (int f = 0; f < p->nf; f++) {
        n[f] = v3_norm(a2[f]);
        region[f] = -1;
    }
    double cos_max = cos(half_angle);
    nreg = 0;
    for (int i = 0; i < p->nf; i++) {
        int s = order[i], top = 0;
        if (region[s] >= 0) continue;
        region[s] = nreg;
        stack[top++] = s;
        while (top > 0) {
            int f = stack[--top];
            const poly_face *F = &p->f[f];
            for (int k = 0; k < F->count; k++) {
                const poly_edge *e = &p->e[p->face_edge[F->first + k]];
                int g = e->f[0] == f ? e->f[1] : e->f[0];
                if (region[g] < 0 && v3_dot(n[g], n[s]) >= cos_max) {
                    region[g] = nreg;
                    stack[top++] = g;
                }
            }
        }
        nreg++;
    }
done:
    free(stack);
    free(n);
    return nreg;
}

/* The plane of each region: the area-weighted normal (summed in the faces'
 * order), moved out to touch p (so that it supports every point p contains).  A
 * region of one face keeps that face's normal. */
static void region_planes(const poly *p, const vec3 *a2, const int *order, const int *region, int nreg,
                          vec3 *n, double *d)
{
    for (int r = 0; r < nreg; r++) n[r] = v3(0, 0, 0);
    for (int i = 0; i < p->nf; i++) n[region[order[i]]] = v3_add(n[region[order[i]]], a2[order[i]]);
    for (int r = 0; r < nreg; r++) {
        n[r] = v3_norm(n[r]);
        d[r] = -INFINITY;
        for (int v = 0; v < p->nv; v++) d[r] = fmax(d[r], v3_dot(n[r], p->v[v]));
    }
}

/* The vertices of the intersection of the half-spaces n[k] . x <= d[k], found as
 * the facets of the dual hull (points n[k] / (d[k] - n[k] . c)) about the interior
 * point c.  Returns the count (malloc'ed in *out) or -1 with err. */
static int halfspace_vertices(const vec3 *n, const double *d, int m, vec3 c, vec3 **out,
                              char *err, size_t errlen)
{
    vec3 *dual = malloc((size_t)m * sizeof *dual);
    *out = NULL;
    if (!dual) {
        errmsg_set(err, errlen, "out of memory");
        return -1;
    }
    for (int k = 0; k < m; k++) {
        double h = d[k] - v3_dot(n[k], c);
        if (!(h > 0)) {
            free(dual);
            errmsg_set(err, errlen, "convex hull: flat face merging lost the interior");
            return -1;
        }
        dual[k] = v3_scale(n[k], 1.0 / h);
    }
    qrun r;
    int nv = -1;
    if (qrun_start(&r, dual, m, err, errlen) == 0) {
        qhT *qh = &r.qh;
        facetT *facet;
        *out = malloc((size_t)qh->num_facets * sizeof **out);
        nv = *out ? 0 : -1;
        FORALLfacets
        {
            if (nv < 0 || !(facet->offset < 0)) {
                nv = -1;
                break;
            }
            vec3 a = v3(facet->normal[0], facet->normal[1], facet->normal[2]);
            (*out)[nv++] = v3_add(c, v3_scale(a, -1.0 / facet->offset));
        }
        if (nv < 0) errmsg_set(err, errlen, "convex hull: flat face merging failed");
    } else if (r.exitcode > 0) {
        qrun_message(&r, "convex hull (merging flat faces)", err, errlen);
    }
    qrun_end(&r);
    free(dual);
    if (nv < 0) {
        free(*out);
        *out = NULL;
    }
    return nv;
}

/* p with each nearly flat region made one planar face (see poly_hull_merge), or
 * NULL with err.  p itself is left alone. */
static poly *merge_flat(const poly *p, double angle, char *err, size_t errlen)
{
    int *region = malloc((size_t)p->nf * sizeof *region), *order = malloc((size_t)p->nf * sizeof *order);
    vec3 *a2 = malloc((size_t)p->nf * sizeof *a2);
    int nreg = region && order && a2 && faces_in_order(p, a2, order) == 0
                   ? flat_regions(p, a2, order, 0.5 * angle, region)
                   : -1;
    vec3 *n = nreg > 0 ? malloc((size_t)nreg * sizeof *n) : NULL;
    double *d = nreg > 0 ? malloc((size_t)nreg * sizeof *d) : NULL;
    vec3 *verts = NULL;
    poly *q = NULL;
    if (!n || !d) {
        errmsg_set(err, errlen, "out of memory");
    } else {
        region_planes(p, a2, order, region, nreg, n, d);
        int nv = halfspace_vertices(n, d, nreg, vertex_mean_sorted(p), &verts, err, errlen);
        if (nv >= 4) q = hull_once(verts, nv, err, errlen);
        else if (nv >= 0) errmsg_set(err, errlen, "convex hull: merging left %d vertices", nv);
    }
    free(region);
    free(order);
    free(a2);
    free(n);
    free(d);
    free(verts);
    return q;
}

/* Whether some faces of p would merge at this angle (their normals as
 * flat_regions finds them). */
static bool has_flat_region(const poly *p, double angle)
{
    double cos_max = cos(0.5 * angle);
    vec3 *n = malloc((size_t)p->nf * sizeof *n);
    for (int f = 0; n && f < p->nf; f++) n[f] = v3_norm(face_area2(p, f));
    bool flat = false;
    for (int e = 0; e < p->ne && !flat; e++) {
        int f = p->e[e].f[0], g = p->e[e].f[1];
        vec3 a = n ? n[f] : v3_norm(face_area2(p, f)), b = n ? n[g] : v3_norm(face_area2(p, g));
        flat = v3_dot(a, b) >= cos_max;
    }
    free(n);
    return flat;
}

/* ---- public construction ---- */

/* Largest extent of the points' bounding box (0 when they coincide, NaN when one is
 * not finite); *coord gets the largest coordinate magnitude. */
static double cloud_size(const vec3 *pts, int n, double *coord)
{
    vec3 lo = pts[0], hi = pts[0];
    for (int i = 0; i < n; i++) {
        if (!v3_finite(pts[i])) return NAN;
        lo = v3_min(lo, pts[i]);
        hi = v3_max(hi, pts[i]);
    }
    vec3 d = v3_sub(hi, lo), m = v3_max(v3_neg(lo), hi);
    *coord = fmax(m.x, fmax(m.y, m.z));
    return fmax(d.x, fmax(d.y, d.z));
}

/* poly_mass(p).volume, the same sum to the bit, without the moments. */
static double poly_volume(const poly *p)
{
    vec3 r = vertex_mean(p);
    double vol = 0;
    for (int f = 0; f < p->nf; f++) {
        const int *fv = p->face_vert + p->f[f].first;
        vec3 a = v3_sub(p->v[fv[0]], r);
        for (int k = 1; k + 1 < p->f[f].count; k++) {
            vec3 b = v3_sub(p->v[fv[k]], r), c = v3_sub(p->v[fv[k + 1]], r);
            vol += v3_dot(a, v3_cross(b, c)) / 6.0;
        }
    }
    return vol;
}

/* The checks and merging every hull p of points of this size (largest extent) and
 * largest coordinate gets once built: solid, planar faces, nearly flat regions
 * merged at angle.  Takes p; NULL with err. */
static poly *hull_finish(poly *p, double size, double coord, double angle, char *err, size_t errlen)
{
    if (!(poly_volume(p) > 1e-12 * size * size * size)) {
        errmsg_set(err, errlen, "convex hull: the solid is too thin: its volume is under 1e-12 "
                "of the cube around it");
        poly_free(p);
        return NULL;
    }
    /* planar to roundoff: relative to the size, and to the coordinates' magnitude */
    double tol = PLANAR_REL * size + PLANAR_ULPS * DBL_EPSILON * coord;
    bool planar = poly_planarity(p) <= tol;
    if (!planar || (angle > 0 && has_flat_region(p, angle))) {
        /* merging also flattens faces qhull merged beyond roundoff; if the merged
         * hull came out worse, the exact one is kept */
        poly *q = merge_flat(p, angle, err, errlen);
        if (q && poly_planarity(q) <= tol) {
            poly_free(p);
            p = q;
            planar = true;
        } else {
            poly_free(q);
        }
    }
    if (!planar) {
        errmsg_set(err, errlen, "convex hull: a face is not planar (off by %.3g)",
                poly_planarity(p));
        poly_free(p);
        return NULL;
    }
    return p;
}

/* The points' size (cloud_size), or -1 with err when they cannot make a hull. */
static double hull_size(const vec3 *pts, int n, double *coord, char *err, size_t errlen)
{
    if (n < 4) {
        errmsg_set(err, errlen, "convex hull needs at least 4 points (got %d)", n);
        return -1;
    }
    double size = cloud_size(pts, n, coord);
    if (isnan(size)) {
        errmsg_set(err, errlen, "convex hull: a point is not finite");
        return -1;
    }
    if (!(size > 0)) {
        errmsg_set(err, errlen, "convex hull: all %d points coincide", n);
        return -1;
    }
    return size;
}

poly *poly_hull_merge(const vec3 *pts, int n, double angle, char *err, size_t errlen)
{
    double coord, size = hull_size(pts, n, &coord, err, errlen);
    if (size < 0) return NULL;
    poly *p = hull_once(pts, n, err, errlen);
    return p ? hull_finish(p, size, coord, angle, err, errlen) : NULL;
}

/* Whether p is the convex hull of its vertices with every edge a fold of more than
 * margin (each neighbour's other vertices that far below a face's plane), so that
 * no two faces would merge to roundoff: every vertex on or below every face's
 * plane (within tol). */
static bool surface_is_hull(const poly *p, double tol, double margin)
{
    for (int e = 0; e < p->ne; e++)
        for (int s = 0; s < 2; s++) {
            const poly_face *F = &p->f[p->e[e].f[s]], *G = &p->f[p->e[e].f[1 - s]];
            for (int k = 0; k < G->count; k++) {
                int v = p->face_vert[G->first + k];
                if (v == p->e[e].v[0] || v == p->e[e].v[1]) continue;
                if (!(v3_dot(F->n, p->v[v]) - F->d < -margin)) return false;
            }
        }
    for (int f = 0; f < p->nf; f++) {
        const poly_face *F = &p->f[f];
        for (int k = 0; k < F->count; k++)
            if (!(fabs(v3_dot(F->n, p->v[p->face_vert[F->first + k]]) - F->d) <= tol)) return false;
        for (int v = 0; v < p->nv; v++)
            if (!(v3_dot(F->n, p->v[v]) - F->d <= tol)) return false;
    }
    return true;
}

poly *poly_hull_surface(const vec3 *pts, int n, int nf, const int *count, const int *fvert,
                        double angle, char *err, size_t errlen)
{
    double coord, size = hull_size(pts, n, &coord, err, errlen);
    if (size < 0) return NULL;
    int nfv = 0;
    for (int f = 0; f < nf; f++) nfv += count[f];
    vec3 *hint = malloc((size_t)(nf > 0 ? nf : 1) * sizeof *hint);
    char why[200];
    poly *p = NULL;
    if (hint && (long long)n * nf <= POLY_SURFACE_CHECKS) {
        /* each face's own ccw normal is its hint: assembling keeps its turn */
        for (int f = 0, at = 0; f < nf; at += count[f++])
            hint[f] = polygon_area2(pts, fvert + at, count[f], NULL);
        p = poly_assemble(n, pts, nf, count, fvert, hint, why, sizeof why);
    }
    free(hint);
    double tol = PLANAR_REL * size + PLANAR_ULPS * DBL_EPSILON * coord;
    if (!p || p->ne * 2 != nfv || !surface_is_hull(p, tol, POLY_SURFACE_FOLD * size)) {
        poly_free(p);
        return poly_hull_merge(pts, n, angle, err, errlen);
    }
    return hull_finish(p, size, coord, angle, err, errlen);
}

poly *poly_hull(const vec3 *pts, int n, char *err, size_t errlen)
{
    return poly_hull_merge(pts, n, POLY_FLAT_ANGLE, err, errlen);
}

/* ---- queries ---- */

double poly_outer_radius(const poly *p, vec3 c)
{
    double r2 = 0;
    for (int v = 0; v < p->nv; v++) r2 = fmax(r2, v3_len2(v3_sub(p->v[v], c)));
    return sqrt(r2);
}

double poly_inner_radius(const poly *p, vec3 c)
{
    double r = INFINITY;
    for (int f = 0; f < p->nf; f++) r = fmin(r, p->f[f].d - v3_dot(p->f[f].n, c));
    return r;
}

int poly_support(const poly *p, vec3 d)
{
    int best = 0;
    double bd = v3_dot(p->v[0], d);
    for (int v = 1; v < p->nv; v++) {
        double x = v3_dot(p->v[v], d);
        if (x > bd) {
            bd = x;
            best = v;
        }
    }
    return best;
}

/* ---- mass properties ---- */

mass_props poly_mass(const poly *p)
{
    /* tetrahedra (r, a, b, c), r a reference point near the centre: volume
     * V = a.(b x c)/6, first moment V (a+b+c)/4, second moment
     * V/20 (aa' + bb' + cc' + (a+b+c)(a+b+c)'), all relative to r */
    vec3 r = vertex_mean(p);
    double vol = 0;
    vec3 m1 = v3(0, 0, 0);
    mat3 m2 = m3_zero();
    for (int f = 0; f < p->nf; f++) {
        const int *fv = p->face_vert + p->f[f].first;
        vec3 a = v3_sub(p->v[fv[0]], r);
        for (int k = 1; k + 1 < p->f[f].count; k++) {
            vec3 b = v3_sub(p->v[fv[k]], r), c = v3_sub(p->v[fv[k + 1]], r);
            double v = v3_dot(a, v3_cross(b, c)) / 6.0;
            vec3 s = v3_add(a, v3_add(b, c));
            mat3 cov = m3_add(m3_add(m3_outer(a, a), m3_outer(b, b)),
                              m3_add(m3_outer(c, c), m3_outer(s, s)));
            vol += v;
            m1 = v3_mad(m1, s, v / 4.0);
            m2 = m3_add(m2, m3_scale(cov, v / 20.0));
        }
    }
    mass_props mp;
    mp.volume = vol;
    vec3 g = vol > 0 ? v3_scale(m1, 1.0 / vol) : v3(0, 0, 0);
    mp.com = v3_add(r, g);
    mat3 cc = m3_add(m2, m3_scale(m3_outer(g, g), -vol)); /* second moment about com */
    double tr = cc.m[0][0] + cc.m[1][1] + cc.m[2][2];
    mp.inertia = m3_add(m3_scale(m3_identity(), tr), m3_scale(cc, -1.0));
    return mp;
}

/* ---- invariants ---- */

/* Edge e's tail and head in the order face f walks it, or -1 if f is not on e. */
static int edge_walked_by(const poly_edge *e, int f, int *tail, int *head)
{
    if (e->f[0] == f) {
        *tail = e->v[0];
        *head = e->v[1];
        return 0;
    }
    if (e->f[1] == f) {
        *tail = e->v[1];
        *head = e->v[0];
        return 0;
    }
    return -1;
}

static int check_counts(const poly *p, char *err, size_t errlen)
{
    if (p->nv < 4 || p->ne < 6 || p->nf < 4) {
        errmsg_set(err, errlen, "too few features (%d v, %d e, %d f)", p->nv, p->ne, p->nf);
        return -1;
    }
    if (p->nv - p->ne + p->nf != 2) {
        errmsg_set(err, errlen, "euler: V - E + F = %d, not 2", p->nv - p->ne + p->nf);
        return -1;
    }
    if (face_corners(p) != 2 * p->ne) {
        errmsg_set(err, errlen, "face corners %d != 2 E = %d", face_corners(p), 2 * p->ne);
        return -1;
    }
    return 0;
}

/* Face f: unit normal, vertices on its plane, ccw and convex about n, its edges. */
static int check_face(const poly *p, int f, double tol, char *err, size_t errlen)
{
    const poly_face *F = &p->f[f];
    const int *fv = p->face_vert + F->first;
    if (F->count < 3 || (f > 0 && F->first != p->f[f - 1].first + p->f[f - 1].count) ||
        (f == 0 && F->first != 0)) {
        errmsg_set(err, errlen, "face %d: bad layout (first %d, count %d)", f, F->first, F->count);
        return -1;
    }
    if (fabs(v3_len(F->n) - 1) > 1e-12) {
        errmsg_set(err, errlen, "face %d: normal not unit (|n| = %.17g)", f, v3_len(F->n));
        return -1;
    }
    for (int k = 0; k < F->count; k++) {
        int a = fv[k], b = fv[(k + 1) % F->count], c = fv[(k + 2) % F->count];
        if (a < 0 || a >= p->nv) {
            errmsg_set(err, errlen, "face %d: vertex index %d out of range", f, a);
            return -1;
        }
        double dist = v3_dot(F->n, p->v[a]) - F->d;
        if (fabs(dist) > tol) {
            errmsg_set(err, errlen, "face %d: vertex %d is %.3g off the plane", f, a, dist);
            return -1;
        }
        vec3 turn = v3_cross(v3_sub(p->v[b], p->v[a]), v3_sub(p->v[c], p->v[b]));
        if (v3_dot(turn, F->n) < -tol * v3_dist(p->v[c], p->v[a])) {
            errmsg_set(err, errlen, "face %d: corner at vertex %d is not convex ccw", f, b);
            return -1;
        }
        int e = p->face_edge[F->first + k], t, h;
        if (e < 0 || e >= p->ne || edge_walked_by(&p->e[e], f, &t, &h) < 0 || t != a ||
            h != b) {
            errmsg_set(err, errlen, "face %d: edge %d does not run %d -> %d with the face on "
                    "its left", f, e, a, b);
            return -1;
        }
    }
    vec3 area = polygon_area2(p->v, fv, F->count, NULL);
    if (!(v3_dot(area, F->n) > 0)) {
        errmsg_set(err, errlen, "face %d: vertices are clockwise seen from outside", f);
        return -1;
    }
    return 0;
}

/* Edge e appears in both its faces' boundaries, once each. */
static int check_edge(const poly *p, int e, char *err, size_t errlen)
{
    const poly_edge *E = &p->e[e];
    if (E->v[0] < 0 || E->v[0] >= p->nv || E->v[1] < 0 || E->v[1] >= p->nv ||
        E->v[0] == E->v[1] || E->f[0] < 0 || E->f[0] >= p->nf || E->f[1] < 0 ||
        E->f[1] >= p->nf || E->f[0] == E->f[1]) {
        errmsg_set(err, errlen, "edge %d: bad indices", e);
        return -1;
    }
    for (int s = 0; s < 2; s++) {
        const poly_face *F = &p->f[E->f[s]];
        int seen = 0;
        for (int k = 0; k < F->count; k++) seen += p->face_edge[F->first + k] == e;
        if (seen != 1) {
            errmsg_set(err, errlen, "edge %d: listed %d times by face %d", e, seen, E->f[s]);
            return -1;
        }
    }
    return 0;
}

/* The vertex -> edge lists: well formed, each edge at both its ends, degree >= 3. */
static int check_vertices(const poly *p, char *err, size_t errlen)
{
    if (p->vert_first[0] != 0 || p->vert_first[p->nv] != 2 * p->ne) {
        errmsg_set(err, errlen, "vert_first does not span 2 E entries");
        return -1;
    }
    for (int v = 0; v < p->nv; v++) {
        int deg = p->vert_first[v + 1] - p->vert_first[v];
        if (deg < 3) {
            errmsg_set(err, errlen, "vertex %d: only %d edges", v, deg);
            return -1;
        }
        for (int j = p->vert_first[v]; j < p->vert_first[v + 1]; j++) {
            int e = p->vert_edge[j];
            if (e < 0 || e >= p->ne || (p->e[e].v[0] != v && p->e[e].v[1] != v)) {
                errmsg_set(err, errlen, "vertex %d: lists edge %d not at it", v, e);
                return -1;
            }
        }
    }
    return 0;
}

/* Every vertex on or inside every face plane (O(V F)). */
static int check_convex(const poly *p, double tol, char *err, size_t errlen)
{
    for (int f = 0; f < p->nf; f++)
        for (int v = 0; v < p->nv; v++) {
            double dist = v3_dot(p->f[f].n, p->v[v]) - p->f[f].d;
            if (dist > tol) {
                errmsg_set(err, errlen, "vertex %d is %.3g outside face %d", v, dist, f);
                return -1;
            }
        }
    return 0;
}

int poly_check(const poly *p, double tol, char *err, size_t errlen)
{
    if (check_counts(p, err, errlen) < 0) return -1;
    for (int f = 0; f < p->nf; f++)
        if (check_face(p, f, tol, err, errlen) < 0) return -1;
    for (int e = 0; e < p->ne; e++)
        if (check_edge(p, e, err, errlen) < 0) return -1;
    if (check_vertices(p, err, errlen) < 0) return -1;
    return check_convex(p, tol, err, errlen);
}
