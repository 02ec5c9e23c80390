/* support.c: a Dobkin-Kirkpatrick hierarchy for furthest-vertex queries on large
 * hulls (support.h). */
#include "support.h"

#include <stdlib.h>
#include <string.h>

/* A level of at most this many vertices is the top: the query looks at them all. */
#define TOP_VERTICES 24

/* Removed vertices have at most this many edges (Dobkin and Kirkpatrick bound it
 * near 8 for their proof; a higher bound lets a level remove more, and a query
 * never reads a removed vertex's edges). */
#define REMOVE_DEGREE 10

/* A level that would remove fewer than this fraction of its vertices ends the
 * hierarchy (a hull where few low-degree vertices are independent). */
#define REMOVE_LEAST 0.0625

/* How the furthest vertex of a level is found from the one above: where the level
 * above kept as a vertex every vertex it did not remove (exact), from vertex j
 * above, its own vertex node[j].u or one of the candidates cand[node[j].first ..
 * + n - 1], the removed neighbours of u, with their coordinates: a step reads two
 * or three cache lines (the large levels do not fit in a cache); else node is NULL
 * and the step climbs from up[j].  */
typedef struct {
    int u, first, n;
} down_node;

typedef struct {
    vec3 p;
    int v;
} down_cand;

typedef struct {
    down_node *node;
    down_cand *cand;
} step_down;

struct support_tree {
    int nlev;       /* levels; level 0 is the hull itself */
    poly **lev;     /* lev[k], k >= 1, owned */
    int **up;       /* up[k][j]: the level k - 1 vertex that level k's vertex j is */
    step_down *dn;  /* dn[k], k < nlev - 1: from level k + 1 down to level k */
};

void support_tree_free(support_tree *t)
{
    if (!t) return;
    for (int k = 1; k < t->nlev; k++) {
        poly_free(t->lev[k]);
        free(t->up[k]);
        free(t->dn[k - 1].node);
        free(t->dn[k - 1].cand);
    }
    free(t->lev);
    free(t->up);
    free(t->dn);
    free(t);
}

static int degree(const poly *p, int v) { return p->vert_first[v + 1] - p->vert_first[v]; }

static int neighbour(const poly *p, int v, int k)
{
    const poly_edge *e = &p->e[p->vert_edge[k]];
    return e->v[0] == v ? e->v[1] : e->v[0];
}

/* Marks in removed[] an independent set of p's vertices of degree REMOVE_DEGREE or
 * less, lowest degrees first (ties in index order).  Returns its size, -1 when out
 * of memory. */
static int independent_set(const poly *p, unsigned char *removed)
{
    int *count = calloc(REMOVE_DEGREE + 2, sizeof *count), *order = malloc((size_t)p->nv * sizeof *order);
    unsigned char *blocked = calloc((size_t)p->nv, 1);
    if (!count || !order || !blocked) {
        free(count);
        free(order);
        free(blocked);
        return -1;
    }
    /* a counting sort by degree, of the vertices that may go */
    for (int v = 0; v < p->nv; v++)
        if (degree(p, v) <= REMOVE_DEGREE) count[degree(p, v) + 1]++;
    for (int g = 1; g <= REMOVE_DEGREE + 1; g++) count[g] += count[g - 1];
    int n = count[REMOVE_DEGREE + 1];
    for (int v = 0; v < p->nv; v++)
        if (degree(p, v) <= REMOVE_DEGREE) order[count[degree(p, v)]++] = v;
    int m = 0;
    memset(removed, 0, (size_t)p->nv);
    for (int i = 0; i < n; i++) {
        int v = order[i];
        if (blocked[v]) continue;
        removed[v] = 1;
        m++;
        for (int k = p->vert_first[v]; k < p->vert_first[v + 1]; k++) blocked[neighbour(p, v, k)] = 1;
    }
    free(count);
    free(order);
    free(blocked);
    return m;
}

/* A kept vertex, sorted by its coordinates to find a level's vertices below. */
typedef struct {
    vec3 p;
    int v;
} keyed;

static int cmp_vec(const vec3 *a, const vec3 *b)
{
    if (a->x != b->x) return a->x < b->x ? -1 : 1;
    if (a->y != b->y) return a->y < b->y ? -1 : 1;
    if (a->z != b->z) return a->z < b->z ? -1 : 1;
    return 0;
}

static int cmp_keyed(const void *x, const void *y)
{
    return cmp_vec(&((const keyed *)x)->p, &((const keyed *)y)->p);
}

/* The step down to p from the level above (its vertex j is p's up[j], nq of
 * them), where removed[] marks what p lost.  Returns 0, -1 when out of memory. */
static int step_lists(const poly *p, const unsigned char *removed, const int *up, int nq,
                      step_down *dn)
{
    int n = 0;
    for (int j = 0; j < nq; j++)
        for (int k = p->vert_first[up[j]]; k < p->vert_first[up[j] + 1]; k++)
            n += removed[neighbour(p, up[j], k)];
    dn->node = malloc((size_t)nq * sizeof *dn->node);
    dn->cand = malloc((size_t)(n > 0 ? n : 1) * sizeof *dn->cand);
    if (!dn->node || !dn->cand) return -1;
    n = 0;
    for (int j = 0; j < nq; j++) {
        int u = up[j];
        dn->node[j] = (down_node){u, n, 0};
        for (int k = p->vert_first[u]; k < p->vert_first[u + 1]; k++) {
            int o = neighbour(p, u, k);
            if (removed[o]) dn->cand[n++] = (down_cand){p->v[o], o};
        }
        dn->node[j].n = n - dn->node[j].first;
    }
    return 0;
}

/* The level above p: the hull of p's vertices less an independent set, in *up_out
 * which of p's vertices each of its vertices is, and in *dn how to step down from
 * it.  NULL when it would not be smaller by REMOVE_LEAST, or qhull or memory
 * failed (the hierarchy ends at p). */
static poly *level_above(const poly *p, int **up_out, step_down *dn)
{
    *dn = (step_down){NULL, NULL};
    unsigned char *removed = malloc((size_t)p->nv);
    keyed *kept = malloc((size_t)p->nv * sizeof *kept);
    vec3 *pts = malloc((size_t)p->nv * sizeof *pts);
    poly *q = NULL;
    int *up = NULL;
    int m = removed && kept && pts ? independent_set(p, removed) : -1;
    if (m < REMOVE_LEAST * p->nv || p->nv - m < 4) goto done;
    int nk = 0;
    for (int v = 0; v < p->nv; v++)
        if (!removed[v]) {
            pts[nk] = p->v[v];
            kept[nk++] = (keyed){p->v[v], v};
        }
    char err[256];
    q = poly_hull_merge(pts, nk, 0, err, sizeof err);
    if (!q) goto done;
    /* qhull gives each vertex's coordinates as they came: find them among p's */
    up = malloc((size_t)q->nv * sizeof *up);
    if (!up) goto fail;
    qsort(kept, (size_t)nk, sizeof *kept, cmp_keyed);
    for (int j = 0; j < q->nv; j++) {
        int lo = 0, hi = nk - 1, at = -1;
        while (lo <= hi) {
            int mid = lo + (hi - lo) / 2, c = cmp_vec(&q->v[j], &kept[mid].p);
            if (c == 0) {
                at = kept[mid].v;
                break;
            }
            if (c < 0) hi = mid - 1;
            else lo = mid + 1;
        }
        if (at < 0) goto fail; /* (a vertex moved: merging beyond roundoff) */
        up[j] = at;
    }
    /* qhull leaves out a kept vertex only when it is not a corner of their hull
     * (coplanar): the lemma then does not hold, and the step down climbs */
    if (q->nv == nk && step_lists(p, removed, up, q->nv, dn) != 0) goto fail;
    goto done;
fail:
    poly_free(q);
    free(up);
    free(dn->node);
    free(dn->cand);
    *dn = (step_down){NULL, NULL};
    q = NULL;
    up = NULL;
done:
    free(removed);
    free(kept);
    free(pts);
    *up_out = up;
    return q;
}

support_tree *support_tree_new(const poly *p)
{
    if (!p || p->nv <= SUPPORT_MIN_VERTICES) return NULL;
    support_tree *t = calloc(1, sizeof *t);
    if (!t) return NULL;
    int cap = 0;
    const poly *cur = p;
    t->nlev = 1;
    while (cur->nv > TOP_VERTICES) {
        if (t->nlev + 1 > cap) {
            cap = cap ? 2 * cap : 16;
            poly **lev = realloc(t->lev, (size_t)cap * sizeof *lev);
            if (lev) t->lev = lev;
            int **up = realloc(t->up, (size_t)cap * sizeof *up);
            if (up) t->up = up;
            step_down *dn = realloc(t->dn, (size_t)cap * sizeof *dn);
            if (dn) t->dn = dn;
            if (!lev || !up || !dn) {
                support_tree_free(t);
                return NULL;
            }
            t->lev[0] = (poly *)p; /* (not freed: level 0 is the caller's) */
            t->up[0] = NULL;
        }
        int *up;
        poly *q = level_above(cur, &up, &t->dn[t->nlev - 1]);
        if (!q) break;
        t->lev[t->nlev] = q;
        t->up[t->nlev] = up;
        t->nlev++;
        cur = q;
    }
    if (t->nlev == 1) { /* no level above the hull: a climb alone */
        support_tree_free(t);
        return NULL;
    }
    return t;
}

int support_vertex(const support_tree *t, const poly *p, vec3 d)
{
    if (!t) return poly_climb(p, d, 0);
    const poly *top = t->lev[t->nlev - 1];
    /* a top of more than TOP_VERTICES (the hierarchy stopped early) is climbed */
    int j = poly_climb(top, d, poly_support(top, d));
    double best = v3_dot(top->v[j], d);
    for (int k = t->nlev - 1; k >= 1; k--) {
        const step_down *dn = &t->dn[k - 1];
        if (!dn->node) {
            const poly *lo = t->lev[k - 1];
            j = poly_climb(lo, d, t->up[k][j]);
            best = v3_dot(lo->v[j], d);
            continue;
        }
        /* the furthest of the level below is j or a removed neighbour of it */
        const down_node *nd = &dn->node[j];
        int bj = nd->u;
        for (int i = nd->first; i < nd->first + nd->n; i++) {
            double x = v3_dot(dn->cand[i].p, d);
            if (x > best) {
                best = x;
                bj = dn->cand[i].v;
            }
        }
        j = bj;
    }
    return j;
}
