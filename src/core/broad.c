/* broad.c: the broad phase: the objects' boxes, their trees, and the pairs they
 * make and end (broad.h). */
#include "broad.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "grow.h"
#include "pairs.h"
#include "step.h"
#include "tolerance.h"
#include "world.h"

/* A new box reaches this far (s) along the object's flight past the end of the
 * internal step, and is widened on every side by BROAD_MARGIN_REL of the object's
 * outer radius plus BROAD_MARGIN (m): room to go on, and to turn back after a
 * collision, before it must be made again. */
#define BROAD_LOOKAHEAD 0.15
#define BROAD_MARGIN_REL 0.1
#define BROAD_MARGIN 0.01

/* A world of at most this many objects has every pair near (its boxes reach
 * everywhere): there is nothing to leave out, and boxes made again as objects
 * move would cost more than the few pairs they could end. */
#define BROAD_SMALL 12

/* The moving tree is built anew once BROAD_REBUILD times as many boxes as there
 * are objects were made again (its boxes only grow between builds; in the gas a
 * build costs more than the looser tree's extra overlap tests up to about 4). */
#define BROAD_REBUILD 4

/* ---- boxes ---- */

static aabb box_union(aabb a, aabb b) { return (aabb){v3_min(a.lo, b.lo), v3_max(a.hi, b.hi)}; }

static bool box_meets(aabb a, aabb b)
{
    return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y &&
           a.lo.z <= b.hi.z && b.lo.z <= a.hi.z;
}

static bool box_covers(aabb outer, aabb inner)
{
    return outer.lo.x <= inner.lo.x && outer.lo.y <= inner.lo.y && outer.lo.z <= inner.lo.z &&
           outer.hi.x >= inner.hi.x && outer.hi.y >= inner.hi.y && outer.hi.z >= inner.hi.z;
}

/* The surface area (the insertion's cost). */
static double box_area(aabb a)
{
    vec3 d = v3_sub(a.hi, a.lo);
    return 2 * (d.x * d.y + d.y * d.z + d.z * d.x);
}

static aabb box_grow(aabb a, double r) { return (aabb){v3_sub(a.lo, v3(r, r, r)), v3_add(a.hi, v3(r, r, r))}; }

/* How much wider than an object's shape its box must be: the contact distance
 * (each box takes its half of the pair's, tol_touch), and far more than the
 * rounding of positions as large as c and reaches as long as reach. */
static double slack(const body *b, vec3 c, double reach)
{
    double m = fmax(fabs(c.x), fmax(fabs(c.y), fabs(c.z)));
    return SIM_TOUCH + SIM_ROUND_REL * b->shape.r_out + 1e-9 * (b->shape.r_out + m + reach);
}

/* The box from lo to hi in object b's axes, turned and placed as b stands, and
 * widened by its slack. */
static aabb turned_box(const body *b, vec3 lo, vec3 hi)
{
    vec3 mid = v3_scale(v3_add(lo, hi), 0.5), half = v3_scale(v3_sub(hi, lo), 0.5);
    mat3 r = m3_from_quat(b->q);
    vec3 c = v3_add(b->x, m3_mulv(r, mid)), e;
    e.x = fabs(r.m[0][0]) * half.x + fabs(r.m[0][1]) * half.y + fabs(r.m[0][2]) * half.z;
    e.y = fabs(r.m[1][0]) * half.x + fabs(r.m[1][1]) * half.y + fabs(r.m[1][2]) * half.z;
    e.z = fabs(r.m[2][0]) * half.x + fabs(r.m[2][1]) * half.y + fabs(r.m[2][2]) * half.z;
    aabb a = {v3_sub(c, e), v3_add(c, e)};
    return box_grow(a, slack(b, c, 0)); /* (|e| <= the outer radius) */
}

/* The box of object b's shape where it stands (its body-axes box turned). */
static aabb still_box(const body *b) { return turned_box(b, b->shape.box_lo, b->shape.box_hi); }

/* Where a parabola x0 + v s + a s^2 / 2 goes for s in [s0, s1]: its lowest and
 * highest. */
static void sweep1(double x0, double v, double a, double s0, double s1, double *lo, double *hi)
{
    double x_0 = x0 + v * s0 + 0.5 * a * s0 * s0, x_1 = x0 + v * s1 + 0.5 * a * s1 * s1;
    *lo = fmin(x_0, x_1);
    *hi = fmax(x_0, x_1);
    if (a != 0) {
        double s = -v / a;
        if (s > s0 && s < s1) {
            double x = x0 + v * s + 0.5 * a * s * s;
            *lo = fmin(*lo, x);
            *hi = fmax(*hi, x);
        }
    }
}

/* The box that covers moving object i, flying flight f, from time t0 to t1: the
 * sphere about its centre of mass swept, widened by `more`.  A held body's
 * (FLIGHT_HELD) centre turns about the pivot, which goes at a constant velocity:
 * the sphere about the pivot that holds it, swept. */
static aabb swept_box(const body *b, const flight *f, double t0, double t1, double more)
{
    double s0 = d_max(0, t0 - f->t0), s1 = d_max(s0, t1 - f->t0);
    bool held = f->kind == FLIGHT_HELD;
    vec3 c = held ? f->p0 : f->c0, acc = held ? v3(0, 0, 0) : f->a;
    double r = b->shape.r_out + (held ? v3_len(f->r0) : 0);
    aabb a;
    sweep1(c.x, f->v0.x, acc.x, s0, s1, &a.lo.x, &a.hi.x);
    sweep1(c.y, f->v0.y, acc.y, s0, s1, &a.lo.y, &a.hi.y);
    sweep1(c.z, f->v0.z, acc.z, s0, s1, &a.lo.z, &a.hi.z);
    double reach = v3_len(f->v0) * s1 + v3_len(acc) * s1 * s1 + r;
    return box_grow(a, r + slack(b, c, reach) + more);
}

/* The box of piece k of static object b of several pieces, as still_box. */
static aabb piece_box(const body *b, int k)
{
    return turned_box(b, b->shape.piece[k].box_lo, b->shape.piece[k].box_hi);
}

/* The box a moving object's sphere needs where it stands. */
static aabb sphere_box(const body *b)
{
    vec3 c = body_com(b);
    aabb a = {c, c};
    return box_grow(a, b->shape.r_out + slack(b, c, 0));
}

/* The margin a new box gets beyond what it needs. */
static double margin(const body *b) { return BROAD_MARGIN_REL * b->shape.r_out + BROAD_MARGIN; }

/* ---- the trees (Box2D's dynamic_tree.c: insertion by the area cost, with AVL
 * rotations) ---- */

static void tree_init(broad_tree *t)
{
    free(t->node);
    memset(t, 0, sizeof *t);
    t->root = t->free_list = -1;
}

static int node_new(broad_tree *t)
{
    if (t->free_list < 0) {
        int cap = t->cap ? 2 * t->cap : 64;
        broad_node *n = realloc(t->node, (size_t)cap * sizeof *n);
        if (!n) return -1;
        t->node = n;
        for (int k = t->cap; k < cap; k++) {
            n[k].parent = k + 1 < cap ? k + 1 : -1; /* the free list runs through parent */
            n[k].height = -1;
        }
        t->free_list = t->cap;
        t->cap = cap;
    }
    int k = t->free_list;
    t->free_list = t->node[k].parent;
    t->node[k] = (broad_node){.parent = -1, .child = {-1, -1}, .height = 0, .body = -1};
    t->count++;
    return k;
}

static void node_free(broad_tree *t, int k)
{
    t->node[k].parent = t->free_list;
    t->node[k].height = -1;
    t->free_list = k;
    t->count--;
}

static bool is_leaf(const broad_node *n) { return n->child[0] < 0; }

/* Fixes node k's box and height from its children. */
static void node_fit(broad_tree *t, int k)
{
    broad_node *n = &t->node[k];
    const broad_node *c0 = &t->node[n->child[0]], *c1 = &t->node[n->child[1]];
    n->box = box_union(c0->box, c1->box);
    n->height = 1 + (c0->height > c1->height ? c0->height : c1->height);
}

/* Replaces child `old` of node parent (or the root) by `new_`. */
static void replace_child(broad_tree *t, int parent, int old, int new_)
{
    if (parent < 0) t->root = new_;
    else t->node[parent].child[t->node[parent].child[0] == old ? 0 : 1] = new_;
    t->node[new_].parent = parent;
}

/* Rotates the taller grandchild of node a up when a's children differ in height
 * by more than one; returns the node now where a was. */
static int balance(broad_tree *t, int a)
{
    broad_node *A = &t->node[a];
    if (is_leaf(A) || A->height < 2) return a;
    int b = A->child[0], c = A->child[1];
    int diff = t->node[c].height - t->node[b].height;
    if (diff > -2 && diff < 2) return a;
    int up = diff > 0 ? c : b;       /* the taller child, which rises */
    int side = diff > 0 ? 1 : 0;     /* its place in a */
    broad_node *U = &t->node[up];
    int f = U->child[0], g = U->child[1];
    replace_child(t, A->parent, a, up);
    /* up keeps its taller child and takes a; a takes the other */
    int keep = t->node[f].height > t->node[g].height ? f : g, give = keep == f ? g : f;
    U->child[0] = a;
    U->child[1] = keep;
    A->parent = up;
    A->child[side] = give;
    t->node[give].parent = a;
    node_fit(t, a);
    node_fit(t, up);
    return up;
}

/* Refits and balances from node k up to the root. */
static void fix_up(broad_tree *t, int k)
{
    while (k >= 0) {
        k = balance(t, k);
        node_fit(t, k);
        k = t->node[k].parent;
    }
}

/* Inserts a leaf for body with box; its node, or -1 when out of memory. */
static int tree_insert(broad_tree *t, aabb box, int obj)
{
    int leaf = node_new(t);
    if (leaf < 0) return -1;
    t->node[leaf].box = box;
    t->node[leaf].body = obj;
    if (t->root < 0) {
        t->root = leaf;
        return leaf;
    }
    /* the sibling of least cost: the area the union adds, inherited down */
    int k = t->root;
    while (!is_leaf(&t->node[k])) {
        const broad_node *n = &t->node[k];
        double area = box_area(n->box), joined = box_area(box_union(n->box, box));
        double cost = 2 * joined, inherit = 2 * (joined - area), c[2];
        for (int s = 0; s < 2; s++) {
            const broad_node *ch = &t->node[n->child[s]];
            double u = box_area(box_union(ch->box, box));
            c[s] = (is_leaf(ch) ? u : u - box_area(ch->box)) + inherit;
        }
        if (cost < c[0] && cost < c[1]) break;
        k = n->child[c[1] < c[0] ? 1 : 0];
    }
    int parent = node_new(t);
    if (parent < 0) {
        node_free(t, leaf);
        return -1;
    }
    int old = t->node[k].parent;
    replace_child(t, old, k, parent);
    t->node[parent].child[0] = k;
    t->node[parent].child[1] = leaf;
    t->node[k].parent = parent;
    t->node[leaf].parent = parent;
    fix_up(t, parent);
    return leaf;
}

/* The leaf takes box, and its ancestors grow to hold it (Box2D v3's enlarged
 * proxies): no descent and no rotation, at the price of boxes that only grow until
 * the tree is built again. */
static void tree_enlarge(broad_tree *t, int leaf, aabb box)
{
    t->node[leaf].box = box;
    for (int k = t->node[leaf].parent; k >= 0 && !box_covers(t->node[k].box, box); k = t->node[k].parent)
        t->node[k].box = box_union(t->node[k].box, box);
}

static void tree_remove(broad_tree *t, int leaf)
{
    int parent = t->node[leaf].parent;
    node_free(t, leaf);
    if (parent < 0) {
        t->root = -1;
        return;
    }
    const broad_node *P = &t->node[parent];
    int sibling = P->child[0] == leaf ? P->child[1] : P->child[0], grand = P->parent;
    replace_child(t, grand, parent, sibling);
    node_free(t, parent);
    if (grand >= 0) fix_up(t, grand);
}

/* Whether object a comes before b along axis: by their boxes' centres, then by
 * index (a total order: the same tree everywhere). */
static bool before(const aabb *box, int axis, int a, int b)
{
    double ca = v3_comp(box[a].lo, axis) + v3_comp(box[a].hi, axis);
    double cb = v3_comp(box[b].lo, axis) + v3_comp(box[b].hi, axis);
    return ca < cb || (ca == cb && a < b);
}

static void swap_int(int *x, int *y)
{
    int t = *x;
    *x = *y;
    *y = t;
}

/* Reorders obj[0 .. n - 1] so that the k that come first in the order of before()
 * are obj[0 .. k - 1] (quickselect, median-of-three pivots): a split at the
 * median in linear time, where a sort took n log n. */
static void split_at(int *obj, int n, int k, const aabb *box, int axis)
{
    int lo = 0, hi = n - 1;
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (before(box, axis, obj[mid], obj[lo])) swap_int(&obj[mid], &obj[lo]);
        if (before(box, axis, obj[hi], obj[lo])) swap_int(&obj[hi], &obj[lo]);
        if (before(box, axis, obj[hi], obj[mid])) swap_int(&obj[hi], &obj[mid]);
        int pivot = obj[mid], i = lo, j = hi;
        while (i <= j) {
            while (before(box, axis, obj[i], pivot)) i++;
            while (before(box, axis, pivot, obj[j])) j--;
            if (i <= j) swap_int(&obj[i++], &obj[j--]);
        }
        if (k <= j) hi = j;
        else if (k >= i) lo = i;
        else return;
    }
}

/* A subtree over the objects obj[0 .. n - 1] (n >= 1) with boxes box, split at the
 * median of their centres along the longest axis of the centres' spread: its
 * root, or -1 when out of memory.  leaf[] gets each object's node. */
static int tree_build(broad_tree *t, int *obj, int n, const aabb *box, int *leaf)
{
    if (n == 1) {
        int k = node_new(t);
        if (k < 0) return -1;
        t->node[k].box = box[obj[0]];
        t->node[k].body = obj[0];
        leaf[obj[0]] = k;
        return k;
    }
    vec3 lo = v3_add(box[obj[0]].lo, box[obj[0]].hi), hi = lo;
    for (int i = 1; i < n; i++) {
        vec3 c = v3_add(box[obj[i]].lo, box[obj[i]].hi);
        lo = v3_min(lo, c);
        hi = v3_max(hi, c);
    }
    vec3 d = v3_sub(hi, lo);
    int axis = d.x >= d.y && d.x >= d.z ? 0 : d.y >= d.z ? 1 : 2;
    int half = n / 2;
    split_at(obj, n, half, box, axis);
    int k = node_new(t);
    if (k < 0) return -1;
    int a = tree_build(t, obj, half, box, leaf);
    int b = a < 0 ? -1 : tree_build(t, obj + half, n - half, box, leaf);
    if (b < 0) return -1;
    t->node[k].child[0] = a;
    t->node[k].child[1] = b;
    t->node[a].parent = t->node[b].parent = k;
    node_fit(t, k);
    return k;
}

/* The objects of t whose boxes meet box, into bp->found.  Returns 0 or -1. */
static int tree_query(broad_phase *bp, const broad_tree *t, aabb box)
{
    bp->nfound = 0;
    if (t->root < 0) return 0;
    int top = 0;
    if (bp->capstack == 0 && !(bp->stack = malloc(64 * sizeof *bp->stack))) return -1;
    bp->capstack = bp->capstack ? bp->capstack : 64;
    bp->stack[top++] = t->root;
    while (top > 0) {
        const broad_node *n = &t->node[bp->stack[--top]];
        if (!box_meets(n->box, box)) continue;
        if (is_leaf(n)) {
            int *f = grow_for_one(bp->found, bp->nfound, &bp->capfound, sizeof *f, 64);
            if (!f) return -1;
            bp->found = f;
            bp->found[bp->nfound++] = n->body;
            continue;
        }
        if (top + 2 > bp->capstack) {
            int cap = 2 * bp->capstack + 64;
            int *s = realloc(bp->stack, (size_t)cap * sizeof *s);
            if (!s) return -1;
            bp->stack = s;
            bp->capstack = cap;
        }
        bp->stack[top++] = n->child[0];
        bp->stack[top++] = n->child[1];
    }
    return 0;
}

/* ---- the broad phase ---- */

void broad_init(broad_phase *bp)
{
    memset(bp, 0, sizeof *bp);
    tree_init(&bp->moving);
    tree_init(&bp->fixed);
}

void broad_free(broad_phase *bp)
{
    free(bp->moving.node);
    free(bp->fixed.node);
    free(bp->leaf);
    free(bp->box);
    free(bp->until);
    free(bp->stack);
    free(bp->found);
    free(bp->item);
    free(bp->first_item);
    broad_init(bp);
}

static int cmp_int(const void *x, const void *y)
{
    int a = *(const int *)x, b = *(const int *)y;
    return (a > b) - (a < b);
}

/* True when static object j, of several pieces, has an item in the sorted
 * found items f (n of them). */
static bool found_body(const broad_phase *bp, const int *f, int n, int j)
{
    int lo = 0, hi = n;
    while (lo < hi) {
        int mid = lo + (hi - lo) / 2;
        if (bp->item[f[mid]].body < j) lo = mid + 1;
        else hi = mid;
    }
    return lo < n && bp->item[f[lo]].body == j;
}

/* The pieces of static object j (several) whose boxes meet box, into out: their
 * count. */
static int pieces_meeting(const broad_phase *bp, const world *w, int j, aabb box, int *out)
{
    int n = 0;
    for (int k = 0; k < w->bodies[j]->shape.pieces; k++)
        if (box_meets(bp->item[bp->first_item[j] + k].box, box)) out[n++] = k;
    return n;
}

/* Object i's pairs with the objects of tree t whose boxes meet its box (those of
 * the others not static when i is): a static object of several pieces with the
 * pieces whose boxes meet it.  Returns 0 or -1.  (The static tree's items found
 * stay in bp->found, sorted.) */
static int meet(world *w, int i, const broad_tree *t)
{
    broad_phase *bp = &w->broad;
    if (tree_query(bp, t, bp->box[i]) != 0) return -1;
    if (t == &bp->fixed) {
        /* whole objects as the tree gives them; then the pieces, in order: by
         * object, then piece */
        for (int k = 0; k < bp->nfound; k++) {
            const broad_item *it = &bp->item[bp->found[k]];
            if (it->piece < 0 && pair_near(w, i, it->body) != 0) return -1;
        }
        qsort(bp->found, (size_t)bp->nfound, sizeof *bp->found, cmp_int);
        for (int k = 0; k < bp->nfound;) {
            const broad_item *it = &bp->item[bp->found[k]];
            int j = it->body, m = 1;
            if (it->piece < 0) {
                k++;
                continue;
            }
            while (k + m < bp->nfound && bp->item[bp->found[k + m]].body == j) m++;
            /* (the found items' pieces, in place of their items) */
            int *pc = &bp->found[k];
            int *tmp = malloc((size_t)m * sizeof *tmp);
            if (!tmp) return -1;
            for (int q = 0; q < m; q++) tmp[q] = bp->item[pc[q]].piece;
            int rc = pair_near_pieces(w, i, j, tmp, m);
            free(tmp);
            if (rc != 0) return -1;
            k += m;
        }
        return 0;
    }
    bool compound = body_is_static(w->bodies[i]) && body_compound(w->bodies[i]);
    int *pc = NULL;
    if (compound && !(pc = malloc((size_t)w->bodies[i]->shape.pieces * sizeof *pc))) return -1;
    for (int k = 0; k < bp->nfound; k++) {
        int j = bp->found[k], n;
        if (j == i) continue;
        if (!compound) {
            if (pair_near(w, i, j) != 0) return -1;
        } else if ((n = pieces_meeting(bp, w, i, bp->box[j], pc)) > 0 &&
                   pair_near_pieces(w, j, i, pc, n) != 0) {
            free(pc);
            return -1;
        }
    }
    free(pc);
    return 0;
}

static int build(world *w, bool fixed);

/* Both trees anew. */
static int build_trees(world *w) { return build(w, true); }

/* Object i has a new box: it goes into its tree, its pairs with the boxes it now
 * meets are made, and those with the boxes it no longer meets end.  Returns 0 or
 * -1. */
static int refit(world *w, int i, aabb box)
{
    broad_phase *bp = &w->broad;
    bool fixed = body_is_static(w->bodies[i]);
    broad_tree *t = &bp->moving;
    bp->box[i] = box;
    bp->refits++;
    if (fixed && body_compound(w->bodies[i])) {
        /* (a command moved it: the static tree anew, its pieces' boxes too) */
        if (build_trees(w) != 0) return -1;
    } else if (fixed) {
        int it = bp->first_item[i];
        bp->item[it].box = box;
        if (bp->leaf[i] >= 0) tree_remove(&bp->fixed, bp->leaf[i]);
        if ((bp->leaf[i] = tree_insert(&bp->fixed, box, it)) < 0) return -1;
    } else if (bp->leaf[i] >= 0) {
        tree_enlarge(t, bp->leaf[i], box);
    } else if ((bp->leaf[i] = tree_insert(t, box, i)) < 0) {
        return -1;
    }
    /* the boxes of the tree only grow: once as many boxes as there are objects
     * were made again, the tree is built anew */
    if (++bp->since_build > BROAD_REBUILD * w->n && build(w, false) != 0) return -1;
    if (meet(w, i, &bp->moving) != 0 || (!fixed && meet(w, i, &bp->fixed) != 0)) return -1;
    /* (backwards: ending a pair takes it out of the list) */
    const pair_adj *adj = &w->pairs.adj[i];
    for (int k = adj->n - 1; k >= 0; k--) {
        const pair_link *l = &adj->l[k];
        if (k >= adj->n || !w->pairs.p[l->slot].near) continue;
        const body *o = w->bodies[l->other];
        bool apart = !box_meets(box, bp->box[l->other]);
        if (!apart && !fixed && body_is_static(o) && body_compound(o))
            apart = !found_body(bp, bp->found, bp->nfound, l->other);
        if (!apart && fixed && body_compound(w->bodies[i])) {
            int dummy_n = 0;
            for (int q = 0; q < w->bodies[i]->shape.pieces && dummy_n == 0; q++)
                dummy_n = box_meets(bp->item[bp->first_item[i] + q].box, bp->box[l->other]);
            apart = dummy_n == 0;
        }
        if (apart) pair_far(w, l->slot);
    }
    return 0;
}

/* The static tree's items: each static object's box, or its pieces' boxes.
 * Returns 0 or -1. */
static int make_items(world *w)
{
    broad_phase *bp = &w->broad;
    long n = 0;
    for (int i = 0; i < w->n; i++)
        if (body_is_static(w->bodies[i])) n += body_compound(w->bodies[i]) ? w->bodies[i]->shape.pieces : 1;
    if (n > bp->capitem) {
        broad_item *it = realloc(bp->item, (size_t)n * sizeof *it);
        if (!it || n > 1000000000L) return -1;
        bp->item = it;
        bp->capitem = (int)n;
    }
    bp->nitem = 0;
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        if (!body_is_static(b)) continue;
        bp->first_item[i] = bp->nitem;
        if (!body_compound(b)) {
            bp->item[bp->nitem++] = (broad_item){i, -1, bp->box[i]};
            continue;
        }
        for (int k = 0; k < b->shape.pieces; k++) bp->item[bp->nitem++] = (broad_item){i, k, piece_box(b, k)};
    }
    return 0;
}

/* The moving tree anew from the boxes (and the static one too when `fixed`), top
 * down (a better tree than one made by insertions); the refits count starts
 * again.  Returns 0 or -1. */
static int build(world *w, bool fixed)
{
    broad_phase *bp = &w->broad;
    if (fixed && make_items(w) != 0) return -1;
    int big = w->n > bp->nitem ? w->n : bp->nitem;
    int *obj = malloc((size_t)(big ? big : 1) * sizeof *obj);
    aabb *box = malloc((size_t)(bp->nitem ? bp->nitem : 1) * sizeof *box);
    int *leaf = malloc((size_t)(bp->nitem ? bp->nitem : 1) * sizeof *leaf);
    int rc = obj && box && leaf ? 0 : -1;
    if (rc == 0) { /* the moving objects */
        broad_tree *t = &bp->moving;
        tree_init(t);
        int n = 0;
        for (int i = 0; i < w->n; i++) {
            if (!body_is_static(w->bodies[i])) obj[n++] = i;
            else if (fixed) bp->leaf[i] = -1;
        }
        if (n > 0 && (t->root = tree_build(t, obj, n, bp->box, bp->leaf)) < 0) rc = -1;
    }
    if (rc == 0 && fixed) { /* the static items */
        broad_tree *t = &bp->fixed;
        tree_init(t);
        for (int k = 0; k < bp->nitem; k++) {
            obj[k] = k;
            box[k] = bp->item[k].box;
        }
        if (bp->nitem > 0 && (t->root = tree_build(t, obj, bp->nitem, box, leaf)) < 0) rc = -1;
        for (int k = 0; k < bp->nitem && rc == 0; k++)
            if (bp->item[k].piece < 0) bp->leaf[bp->item[k].body] = leaf[k];
    }
    free(obj);
    free(box);
    free(leaf);
    bp->since_build = 0;
    return rc;
}

/* True when every box reaches everywhere (BROAD_SMALL). */
static bool everywhere(const world *w) { return w->n <= BROAD_SMALL; }

int broad_rebuild(world *w)
{
    broad_phase *bp = &w->broad;
    if (w->n > bp->cap) {
        int *leaf = realloc(bp->leaf, (size_t)w->n * sizeof *leaf);
        if (leaf) bp->leaf = leaf;
        aabb *box = realloc(bp->box, (size_t)w->n * sizeof *box);
        if (box) bp->box = box;
        double *until = realloc(bp->until, (size_t)w->n * sizeof *until);
        if (until) bp->until = until;
        int *first = realloc(bp->first_item, (size_t)w->n * sizeof *first);
        if (first) bp->first_item = first;
        if (!leaf || !box || !until || !first) return -1;
        bp->cap = w->n;
    }
    tree_init(&bp->moving);
    tree_init(&bp->fixed);
    if (everywhere(w)) {
        for (int i = 0; i < w->n; i++) {
            bp->box[i] = (aabb){v3(-HUGE_VAL, -HUGE_VAL, -HUGE_VAL), v3(HUGE_VAL, HUGE_VAL, HUGE_VAL)};
            bp->leaf[i] = -1;
            bp->until[i] = HUGE_VAL;
        }
        for (int i = 0; i < w->n; i++)
            for (int j = i + 1; j < w->n; j++)
                if (!(body_is_static(w->bodies[i]) && body_is_static(w->bodies[j])) &&
                    pair_near(w, i, j) != 0)
                    return -1;
        return 0;
    }
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        bool fixed = body_is_static(b);
        bp->box[i] = fixed || b->state != STATE_DYNAMIC ? still_box(b) : box_grow(sphere_box(b), margin(b));
        bp->until[i] = -HUGE_VAL;
    }
    if (build_trees(w) != 0) return -1;
    for (int i = 0; i < w->n; i++) {
        if (body_is_static(w->bodies[i])) continue;
        if (meet(w, i, &bp->moving) != 0 || meet(w, i, &bp->fixed) != 0) return -1;
    }
    return 0;
}

int broad_commands(world *w)
{
    broad_phase *bp = &w->broad;
    if (everywhere(w)) return 0;
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        bool still = body_is_static(b) || b->state != STATE_DYNAMIC;
        aabb need = still ? still_box(b) : sphere_box(b);
        bp->until[i] = -HUGE_VAL; /* (a command may have changed its motion) */
        if (box_covers(bp->box[i], need)) continue;
        if (refit(w, i, still ? need : box_grow(need, margin(b))) != 0) return -1;
    }
    return 0;
}

int broad_cover(world *w, int i, double t, double t_end, bool same)
{
    const body *b = w->bodies[i];
    const flight *f = &w->step.fl[i];
    if (f->kind == FLIGHT_STILL || everywhere(w)) return 0; /* (covered already) */
    broad_phase *bp = &w->broad;
    if (same && t_end <= bp->until[i]) return 0;
    if (box_covers(bp->box[i], swept_box(b, f, t, t_end, 0))) {
        bp->until[i] = t_end;
        return 0;
    }
    double to = d_max(t, t_end) + BROAD_LOOKAHEAD;
    bp->until[i] = to;
    return refit(w, i, swept_box(b, f, t, to, margin(b)));
}

int broad_check(const world *w, char *err, size_t errlen)
{
    const broad_phase *bp = &w->broad;
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        /* (either covers the shape) */
        if (!box_covers(bp->box[i], still_box(b)) && !box_covers(bp->box[i], sphere_box(b))) {
            snprintf(err, errlen, "object %d (%s) is outside its box", i, b->name);
            return -1;
        }
    }
    for (int i = 0; i < w->n; i++)
        for (int j = i + 1; j < w->n; j++) {
            if (body_is_static(w->bodies[i]) && body_is_static(w->bodies[j])) continue;
            long k = pair_index(w, i, j);
            bool meets = box_meets(bp->box[i], bp->box[j]);
            /* a static object of several pieces meets by its pieces' boxes */
            for (int s = 0; s < 2 && meets && !everywhere(w); s++) {
                int st = s ? j : i, mv = s ? i : j;
                const body *o = w->bodies[st];
                if (!body_is_static(o) || !body_compound(o)) continue;
                bool any = false;
                for (int q = 0; q < o->shape.pieces && !any; q++)
                    any = box_meets(piece_box(o, q), bp->box[mv]);
                meets = any;
            }
            bool near = k >= 0 && w->pairs.p[k].near;
            if (meets && !near) {
                snprintf(err, errlen, "objects %d and %d: boxes meet, no near pair", i, j);
                return -1;
            }
            if (near && !meets && !w->pairs.p[k].touching) {
                snprintf(err, errlen, "objects %d and %d: a near pair, boxes apart", i, j);
                return -1;
            }
            if (k >= 0 && !w->pairs.every && !near) {
                snprintf(err, errlen, "objects %d and %d: a far pair with the heap on", i, j);
                return -1;
            }
        }
    return 0;
}
