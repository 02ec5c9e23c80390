/* pieces.c: the distance of bodies of several convex pieces over their piece
 * pairs, and a body seen as one of its pieces (pieces.h). */
#include "pieces.h"

#include <math.h>
#include <stdlib.h>

/* The sphere about piece k of b that holds it, in the world: a body of one piece
 * has its outer sphere about its centre of mass. */
static void piece_ball(const body *b, int k, vec3 *c, double *r)
{
    if (b->shape.pieces <= 1) {
        *c = body_com(b);
        *r = b->shape.r_out;
        return;
    }
    const shape_piece *p = &b->shape.piece[k];
    *c = v3_add(b->x, q_rotate(b->q, p->c));
    *r = p->r;
}

static closest_proxy piece_proxy(const body *b, int k)
{
    if (b->shape.pieces <= 1) return shape_proxy(&b->shape, b->x, b->q);
    const shape_piece *p = &b->shape.piece[k];
    return (closest_proxy){p->hull, p->feat, 0, p->c, b->x, b->q};
}

/* The distance of piece i of a and piece j of b, in the canonical order. */
static closest_result one_pair(const body *a, int i, const body *b, int j, closest_cache *cache,
                               bool depth)
{
    closest_proxy pa = piece_proxy(a, i), pb = piece_proxy(b, j);
    closest_result r;
    if (body_before(a, b)) {
        r = depth ? closest_distance(&pa, &pb, cache) : closest_distance_apart(&pa, &pb, cache);
    } else {
        closest_cache c2, *cp = NULL;
        if (cache) {
            c2 = (closest_cache){cache->fb, cache->fa, cache->valid};
            cp = &c2;
        }
        r = depth ? closest_distance(&pb, &pa, cp) : closest_distance_apart(&pb, &pa, cp);
        if (cache && r.status != CLOSEST_INVALID) *cache = (closest_cache){c2.fb, c2.fa, c2.valid};
        if (r.status != CLOSEST_INVALID) closest_mirror(&r);
    }
    r.ka = i;
    r.kb = j;
    return r;
}

/* What bounds the distance of pairs of pieces of a and b from below: the
 * spheres about the pieces, and, for a body of one piece against one of
 * several, its sphere in the other's axes against each piece's box (far
 * tighter for a room's thin slabs). */
typedef struct {
    const body *a, *b;
    bool a_in_b, b_in_a; /* a's (b's) sphere in b's (a's) axes */
    vec3 ca, cb;         /* those centres */
    double ra, rb;       /* and radii */
} bounds;

static bounds bounds_of(const body *a, const body *b)
{
    bounds B = {a, b, false, false, {0, 0, 0}, {0, 0, 0}, 0, 0};
    vec3 c;
    if (a->shape.pieces <= 1 && b->shape.pieces > 1) {
        piece_ball(a, 0, &c, &B.ra);
        B.ca = q_unrotate(b->q, v3_sub(c, b->x));
        B.a_in_b = true;
    }
    if (b->shape.pieces <= 1 && a->shape.pieces > 1) {
        piece_ball(b, 0, &c, &B.rb);
        B.cb = q_unrotate(a->q, v3_sub(c, a->x));
        B.b_in_a = true;
    }
    return B;
}

/* The distance from point c to the box of piece p (its own axes). */
static double box_gap(const shape_piece *p, vec3 c)
{
    double dx = d_max(d_max(p->box_lo.x - c.x, c.x - p->box_hi.x), 0);
    double dy = d_max(d_max(p->box_lo.y - c.y, c.y - p->box_hi.y), 0);
    double dz = d_max(d_max(p->box_lo.z - c.z, c.z - p->box_hi.z), 0);
    return sqrt(dx * dx + dy * dy + dz * dz);
}

/* The least distance the pieces i of a and j of b can have (less a rounding's
 * worth). */
static double lower(const bounds *B, int i, int j)
{
    vec3 ca, cb;
    double ra, rb;
    piece_ball(B->a, i, &ca, &ra);
    piece_ball(B->b, j, &cb, &rb);
    double l = v3_dist(ca, cb) - (ra + rb);
    if (B->a_in_b) l = d_max(l, box_gap(&B->b->shape.piece[j], B->ca) - B->ra);
    if (B->b_in_a) l = d_max(l, box_gap(&B->a->shape.piece[i], B->cb) - B->rb);
    return l - 1e-9 * (ra + rb);
}

/* Piece pair t of the query: from pp, or the t-th of all. */
static void pair_at(const body *b, const piece_pairs *pp, int t, int *i, int *j)
{
    if (pp && pp->n > 0) {
        *i = pp->e[t].i;
        *j = pp->e[t].j;
    } else {
        *i = t / b->shape.pieces;
        *j = t % b->shape.pieces;
    }
}

static closest_cache *cache_of(piece_pairs *pp, int t, pieces_use use, closest_cache *peek)
{
    if (!pp || pp->n == 0) return NULL;
    piece_pair *e = &pp->e[t];
    if (use == PIECES_QUERY) return &e->c;
    if (use == PIECES_SEARCH) return &e->found;
    *peek = e->c;
    return peek;
}

closest_result pieces_distance(const body *a, const body *b, piece_pairs *pp, pieces_use use,
                               bool depth)
{
    return pieces_distance_near(a, b, pp, use, depth, NULL);
}

/* Notes query r (not the nearest) or bound l of a pair of pieces in near. */
static void note(pieces_near *near, const closest_result *r, double l)
{
    if (!near) return;
    if (r && near->n < PIECES_NEAR) near->r[near->n++] = *r;
    else near->others = d_min(near->others, r ? r->distance : l);
}

closest_result pieces_distance_near(const body *a, const body *b, piece_pairs *pp,
                                    pieces_use use, bool depth, pieces_near *near)
{
    if (near) {
        near->n = 0;
        near->others = HUGE_VAL;
    }
    bounds B = bounds_of(a, b);
    int n = pp && pp->n > 0 ? pp->n : a->shape.pieces * b->shape.pieces;
    bool skip = use == PIECES_SEARCH && pp && pp->n > 0;
    /* the nearest bound first, then every other pair that could be nearer */
    int first = -1, i, j;
    double least = HUGE_VAL;
    for (int t = 0; t < n; t++) {
        if (skip && pp->e[t].held) continue;
        pair_at(b, pp, t, &i, &j);
        double l = lower(&B, i, j);
        if (first < 0 || l < least) {
            least = l;
            first = t;
        }
    }
    if (first < 0) { /* every pair left out: apart, as far as the search goes */
        closest_result r = {.status = CLOSEST_SEPARATED, .distance = HUGE_VAL,
                            .normal = v3(0, 0, 1)};
        return r;
    }
    closest_cache peek;
    pair_at(b, pp, first, &i, &j);
    closest_result best = one_pair(a, i, b, j, cache_of(pp, first, use, &peek), depth);
    for (int t = 0; t < n && best.status != CLOSEST_INVALID; t++) {
        if (t == first || (skip && pp->e[t].held)) continue;
        if (!depth && best.status != CLOSEST_SEPARATED) break; /* (apart: no) */
        pair_at(b, pp, t, &i, &j);
        double l = lower(&B, i, j);
        if (!(l < best.distance)) {
            note(near, NULL, l);
            continue;
        }
        closest_result r = one_pair(a, i, b, j, cache_of(pp, t, use, &peek), depth);
        if (r.status == CLOSEST_INVALID || r.distance < best.distance) {
            note(near, &best, 0);
            best = r;
        } else {
            note(near, &r, 0);
        }
    }
    return best;
}

void pieces_hold(const body *a, const body *b, piece_pairs *pp, double tol)
{
    bounds B = bounds_of(a, b);
    for (int t = 0; t < pp->n; t++) {
        piece_pair *e = &pp->e[t];
        e->held = false;
        if (!(lower(&B, e->i, e->j) <= tol)) continue;
        closest_result r = one_pair(a, e->i, b, e->j, &e->found, false);
        e->held = r.status != CLOSEST_SEPARATED || r.distance <= tol;
    }
}

int pieces_touching(const body *a, const body *b, const piece_pairs *pp, double tol,
                    closest_result *out, int max)
{
    int n = pp && pp->n > 0 ? pp->n : a->shape.pieces * b->shape.pieces, count = 0;
    bounds B = bounds_of(a, b);
    for (int t = 0; t < n; t++) {
        int i, j;
        pair_at(b, pp, t, &i, &j);
        if (!(lower(&B, i, j) <= tol)) continue;
        closest_result r = one_pair(a, i, b, j, NULL, true);
        if (r.status == CLOSEST_INVALID || !(r.distance <= tol)) continue;
        /* nearest first (insertion: a contact has few) */
        int at = count < max ? count++ : max;
        while (at > 0 && r.distance < out[at - 1].distance) {
            if (at < max) out[at] = out[at - 1];
            at--;
        }
        if (at < max) out[at] = r;
    }
    return count;
}

double pieces_ball_gap(const body *b, vec3 c, double r)
{
    closest_proxy ball = {NULL, NULL, r, v3(0, 0, 0), c, q_identity()};
    double best = HUGE_VAL;
    for (int k = 0; k < b->shape.pieces; k++) {
        vec3 pc;
        double pr;
        piece_ball(b, k, &pc, &pr);
        if (!(v3_dist(pc, c) - pr - r < best)) continue;
        closest_proxy p = piece_proxy(b, k);
        closest_result res = closest_distance_apart(&ball, &p, NULL);
        if (res.status == CLOSEST_INVALID) return -HUGE_VAL;
        best = d_min(best, res.status == CLOSEST_SEPARATED ? res.distance : 0);
        if (best <= 0) break;
    }
    return best;
}

const body *pieces_view(const body *b, int k, body *tmp)
{
    if (b->shape.pieces <= 1) return b;
    *tmp = *b;
    const shape_piece *p = &b->shape.piece[k];
    tmp->shape.hull = p->hull;
    tmp->shape.feat = p->feat;
    tmp->shape.box_lo = p->box_lo;
    tmp->shape.box_hi = p->box_hi;
    tmp->shape.pieces = 1;
    tmp->shape.piece = NULL;
    tmp->shape.nfaces = p->hull->nf;
    return tmp;
}

/* Room for n piece pairs in pp, emptied: 0 or -1. */
static int room(piece_pairs *pp, long n)
{
    pp->n = 0;
    if (n > 1000000000L) return -1;
    if (n > pp->cap) {
        piece_pair *e = realloc(pp->e, (size_t)n * sizeof *e);
        if (!e) return -1;
        pp->e = e;
        pp->cap = (int)n;
    }
    return 0;
}

int pieces_list(piece_pairs *pp, const body *a, const body *b, const int *bk, int nb)
{
    int na = a->shape.pieces;
    if (!bk) nb = b->shape.pieces;
    if (room(pp, (long)na * nb) != 0) return -1;
    for (int i = 0; i < na; i++)
        for (int t = 0; t < nb; t++)
            pp->e[pp->n++] = (piece_pair){.i = i, .j = bk ? bk[t] : t};
    return 0;
}

bool pieces_listed(const piece_pairs *pp, const body *a, const body *b, bool second, const int *k,
                   int n)
{
    int other = second ? a->shape.pieces : b->shape.pieces;
    if (pp->n != (long)other * n) return false;
    int t = 0;
    for (int x = 0; x < (second ? other : n); x++)
        for (int y = 0; y < (second ? n : other); y++, t++) {
            int i = second ? x : k[x], j = second ? k[y] : y;
            if (pp->e[t].i != i || pp->e[t].j != j) return false;
        }
    return true;
}

int pieces_list_first(piece_pairs *pp, const body *a, const body *b, const int *ak, int na)
{
    int nb = b->shape.pieces;
    if (!ak) na = a->shape.pieces;
    if (room(pp, (long)na * nb) != 0) return -1;
    for (int t = 0; t < na; t++)
        for (int j = 0; j < nb; j++)
            pp->e[pp->n++] = (piece_pair){.i = ak ? ak[t] : t, .j = j};
    return 0;
}

void pieces_hit_from_query(piece_pairs *pp)
{
    for (int t = 0; t < pp->n; t++) pp->e[t].hit = pp->e[t].c;
}

void pieces_hit_from_found(piece_pairs *pp)
{
    for (int t = 0; t < pp->n; t++) pp->e[t].hit = pp->e[t].found;
}

void pieces_forget(piece_pairs *pp)
{
    for (int t = 0; t < pp->n; t++) pp->e[t].c.valid = pp->e[t].hit.valid = pp->e[t].found.valid = false;
}
