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

/* The least distance the pieces i of a and j of b can have: their spheres'
 * (less a rounding's worth). */
static double lower(const body *a, int i, const body *b, int j)
{
    vec3 ca, cb;
    double ra, rb;
    piece_ball(a, i, &ca, &ra);
    piece_ball(b, j, &cb, &rb);
    return v3_dist(ca, cb) - (ra + rb) * (1 + 1e-9);
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
    double others;
    return pieces_distance_others(a, b, pp, use, depth, &others);
}

closest_result pieces_distance_others(const body *a, const body *b, piece_pairs *pp,
                                      pieces_use use, bool depth, double *others)
{
    *others = HUGE_VAL;
    int n = pp && pp->n > 0 ? pp->n : a->shape.pieces * b->shape.pieces;
    bool skip = use == PIECES_SEARCH && pp && pp->n > 0;
    /* the nearest bound first, then every other pair that could be nearer */
    int first = -1, i, j;
    double least = HUGE_VAL;
    for (int t = 0; t < n; t++) {
        if (skip && pp->e[t].held) continue;
        pair_at(b, pp, t, &i, &j);
        double l = lower(a, i, b, j);
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
        double l = lower(a, i, b, j);
        if (!(l < best.distance)) {
            *others = d_min(*others, l);
            continue;
        }
        closest_result r = one_pair(a, i, b, j, cache_of(pp, t, use, &peek), depth);
        if (r.status == CLOSEST_INVALID || r.distance < best.distance) {
            *others = d_min(*others, best.distance);
            best = r;
        } else {
            *others = d_min(*others, r.distance);
        }
    }
    return best;
}

int pieces_touching(const body *a, const body *b, double tol, closest_result *out, int max)
{
    int n = a->shape.pieces * b->shape.pieces, count = 0;
    for (int t = 0; t < n; t++) {
        int i = t / b->shape.pieces, j = t % b->shape.pieces;
        if (!(lower(a, i, b, j) <= tol)) continue;
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
