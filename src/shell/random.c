/* random.c: `random N`, the thesis's random environment (Table 5.6): N dynamic
 * objects of mixed kinds at random non-overlapping places inside random_box, with
 * sizes from random_size, random orientations and velocities, from the shell's own
 * sequence (seed).  Each object is made whole (as a fresh body with its defaults,
 * then its random values) before it is placed.
 *
 * Placing is output-sensitive: a place is tried against the objects near it only,
 * found in a uniform grid of cells as wide as the largest new object (objects
 * larger than that, a wall say, are few and tried one by one), so that N objects
 * are placed in O(N) tries' work rather than N^2.  A place is kept clear of the
 * balls about the new objects (which are turned at random once placed), and of
 * the shapes of the objects already there, so that a furnished room is filled up
 * to its walls and floor.  The objects join the world only once all have found
 * room, so that a refusal adds none. */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>

#include "core/pieces.h"
#include "handlers.h"
#include "shell.h"

/* splitmix64: small, fast, the same everywhere */
static unsigned long long rng_next(unsigned long long *s)
{
    unsigned long long z = (*s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

static double rng_uniform(unsigned long long *s, double lo, double hi)
{
    return lo + (hi - lo) * (double)(rng_next(s) >> 11) * (1.0 / 9007199254740992.0);
}

static vec3 rng_unit(unsigned long long *s)
{
    for (;;) {
        vec3 v = v3(rng_uniform(s, -1, 1), rng_uniform(s, -1, 1), rng_uniform(s, -1, 1));
        double l = v3_len(v);
        if (l > 1e-3 && l <= 1) return v3_scale(v, 1 / l);
    }
}

/* Tries of a place for one object before random gives up. */
#define RANDOM_TRIES 2000

/* ---- the grid of what is placed ---- */

/* A ball to keep clear of: an object's centre of mass and outer radius, and for
 * an object already in the world, the object: a place inside its ball is tried
 * against its shape. */
typedef struct {
    vec3 c;
    double r;
    const body *obj; /* NULL: an object random is placing */
    int next;        /* the next ball in its cell, or -1 */
} ball;

typedef struct {
    long long x, y, z;
    int first; /* its first ball, or -1: an empty place of the table */
} cell;

typedef struct {
    double h;         /* the cells' width: twice the largest radius in them */
    cell *cells;      /* an open-addressing table (ncells, a power of two) */
    long ncells, used;
    ball *balls;
    int nballs, cap;
    int *big, nbig;   /* balls too large for the cells, tried one by one */
} grid;

static long long cell_of(double x, double h) { return (long long)floor(x / h); }

static unsigned long cell_hash(long long x, long long y, long long z)
{
    uint64_t k = (uint64_t)x * 0x9E3779B97F4A7C15ULL ^ (uint64_t)y * 0xC2B2AE3D27D4EB4FULL ^
                 (uint64_t)z * 0x165667B19E3779F9ULL;
    return (unsigned long)(k ^ (k >> 29));
}

/* The cell (x, y, z)'s place in the table: where it is or would go. */
static cell *cell_at(grid *g, long long x, long long y, long long z)
{
    unsigned long m = (unsigned long)g->ncells - 1;
    for (unsigned long at = cell_hash(x, y, z) & m;; at = (at + 1) & m) {
        cell *c = &g->cells[at];
        if (c->first < 0 || (c->x == x && c->y == y && c->z == z)) return c;
    }
}

/* The cells' table made anew with room for twice g->cap balls' cells, every ball
 * of the cells linked into it again: 0, or -1 when out of memory (g as it was). */
static int grid_rehash(grid *g)
{
    long ncells = 16;
    while (ncells < 2L * g->cap) ncells *= 2;
    cell *cells = malloc((size_t)ncells * sizeof *cells);
    if (!cells) return -1;
    for (long k = 0; k < ncells; k++) cells[k].first = -1;
    free(g->cells);
    g->cells = cells;
    g->ncells = ncells;
    g->used = 0;
    for (int k = 0; k < g->nballs; k++) {
        ball *b = &g->balls[k];
        if (2 * b->r > g->h) continue; /* (in big) */
        long long x = cell_of(b->c.x, g->h), y = cell_of(b->c.y, g->h), z = cell_of(b->c.z, g->h);
        cell *at = cell_at(g, x, y, z);
        if (at->first < 0) {
            *at = (cell){x, y, z, -1};
            g->used++;
        }
        b->next = at->first;
        at->first = k;
    }
    return 0;
}

/* Room for n balls (and more as they come: grid_room), cells h wide: 0, or -1
 * when out of memory.  Only what the first balls need is taken at once, so that
 * random 90000000 in a box that holds 600 takes no gigabytes. */
static int grid_init(grid *g, double h, int n)
{
    g->h = h;
    g->cap = n < 4096 ? (n > 0 ? n : 1) : 4096;
    g->nballs = g->nbig = 0;
    g->balls = malloc((size_t)g->cap * sizeof *g->balls);
    g->big = malloc((size_t)g->cap * sizeof *g->big);
    if (!g->balls || !g->big) return -1;
    return grid_rehash(g);
}

/* Room for one more ball: the arrays and the cells' table doubled when full.  0,
 * or -1 when out of memory. */
static int grid_room(grid *g)
{
    if (g->nballs < g->cap) return 0;
    if (g->cap > INT32_MAX / 2) return -1;
    int cap = 2 * g->cap;
    ball *balls = realloc(g->balls, (size_t)cap * sizeof *balls);
    if (balls) g->balls = balls;
    int *big = balls ? realloc(g->big, (size_t)cap * sizeof *big) : NULL;
    if (big) g->big = big;
    if (!balls || !big) return -1;
    g->cap = cap;
    return grid_rehash(g);
}

static void grid_free(grid *g)
{
    free(g->cells);
    free(g->balls);
    free(g->big);
}

/* Adds the ball of radius r at c, of object obj already in the world or NULL
 * (room was made: grid_room). */
static void grid_add(grid *g, vec3 c, double r, const body *obj)
{
    int k = g->nballs++;
    g->balls[k] = (ball){c, r, obj, -1};
    if (2 * r > g->h) {
        g->big[g->nbig++] = k;
        return;
    }
    long long x = cell_of(c.x, g->h), y = cell_of(c.y, g->h), z = cell_of(c.z, g->h);
    cell *at = cell_at(g, x, y, z);
    if (at->first < 0) {
        *at = (cell){x, y, z, -1};
        g->used++;
    }
    g->balls[k].next = at->first;
    at->first = k;
}

/* True when a ball of radius r at c is clear of ball b: of its ball for an
 * object random places (it is turned at random after), of its shape for one that
 * was there (a wall, a floor, a table, a polyhedron: its ball may be far larger). */
static bool clear_of(const ball *b, vec3 c, double r)
{
    if (v3_dist(c, b->c) >= r + b->r) return true;
    if (!b->obj) return false;
    /* (a body of several pieces, a room of one file, piece by piece: the hull of
     * them all would fill the room) */
    if (body_compound(b->obj)) return pieces_ball_gap(b->obj, c, r) > 0;
    closest_proxy place = {NULL, NULL, r, v3(0, 0, 0), c, q_identity()};
    closest_proxy there = shape_proxy(&b->obj->shape, b->obj->x, b->obj->q);
    return closest_distance_apart(&place, &there, NULL).status == CLOSEST_SEPARATED;
}

/* True when a ball of radius r at c is clear of every ball of the grid's (and of
 * the shapes of those of objects that were there): the same test, ball by ball,
 * as trying all of them. */
static bool grid_free_at(grid *g, vec3 c, double r)
{
    for (int k = 0; k < g->nbig; k++)
        if (!clear_of(&g->balls[g->big[k]], c, r)) return false;
    double reach = r + 0.5 * g->h; /* no ball in a cell is larger than h / 2 */
    long long x0 = cell_of(c.x - reach, g->h), x1 = cell_of(c.x + reach, g->h);
    long long y0 = cell_of(c.y - reach, g->h), y1 = cell_of(c.y + reach, g->h);
    long long z0 = cell_of(c.z - reach, g->h), z1 = cell_of(c.z + reach, g->h);
    for (long long x = x0; x <= x1; x++)
        for (long long y = y0; y <= y1; y++)
            for (long long z = z0; z <= z1; z++)
                for (int k = cell_at(g, x, y, z)->first; k >= 0; k = g->balls[k].next)
                    if (!clear_of(&g->balls[k], c, r)) return false;
    return true;
}

/* ---- random ---- */

/* A new object of random kind, size, shape and colour, named by the first free
 * number from *id on; built.  NULL with err when it cannot be. */
static body *random_body(shell *sh, long *id, char *err, size_t errlen)
{
    const world *w = &sh->w;
    body *b = malloc(sizeof *b);
    if (!b) {
        snprintf(err, errlen, "out of memory");
        return NULL;
    }
    char name[BODY_NAME_MAX];
    for (;; (*id)++) {
        snprintf(name, sizeof name, "random%ld", *id);
        if (world_find(w, name) < 0) break;
    }
    (*id)++;
    shape_kind kind = (shape_kind)(rng_next(&sh->rng) % 3);
    body_init(b, name, kind);
    b->friction = w->set.default_friction;
    b->rolling_friction = w->set.default_rolling_friction;
    double s = rng_uniform(&sh->rng, sh->set.random_size[0], sh->set.random_size[1]);
    b->sp.radius = s;
    b->sp.size = v3(s * rng_uniform(&sh->rng, 0.6, 1), s * rng_uniform(&sh->rng, 0.6, 1),
                    s * rng_uniform(&sh->rng, 0.6, 1));
    b->sp.exp1 = rng_uniform(&sh->rng, 0.3, 1.8);
    b->sp.exp2 = rng_uniform(&sh->rng, 0.3, 1.8);
    b->sp.a1 = s;
    b->sp.a2 = s * rng_uniform(&sh->rng, 0.6, 1);
    b->sp.a3 = s * rng_uniform(&sh->rng, 0.6, 1);
    for (int c = 0; c < 3; c++) b->color[c] = 64 + (int)(rng_next(&sh->rng) % 192);
    if (body_build(b, err, errlen) != 0) {
        free(b);
        return NULL;
    }
    return b;
}

cmd_status cmd_random(shell *sh, const stmt *st)
{
    long n = (long)st->num[0];
    world *w = &sh->w;
    vec3 box = sh->set.random_box;
    unsigned long long rng0 = sh->rng; /* a refused statement changes nothing */
    char err[256];
    long made = 0, id = w->n + 1;
    cmd_status rc = CMD_ERROR;
    /* (room for what is made grows as it is made: n may be far more than fits) */
    long made_cap = n < 4096 ? (n > 0 ? n : 1) : 4096;
    body **made_b = malloc((size_t)made_cap * sizeof *made_b);
    grid g = {0};
    /* the cells: as wide as the largest object random_size makes (a box's or a
     * superquadric's corner is at most sqrt(3) times the size drawn out) */
    if (!made_b || n > INT32_MAX - w->n ||
        grid_init(&g, 2 * sqrt(3) * sh->set.random_size[1], (int)(w->n + n)) != 0) {
        sh_error(sh, st, "out of memory");
        goto done;
    }
    for (int i = 0; i < w->n; i++) {
        if (grid_room(&g) != 0) {
            sh_error(sh, st, "out of memory");
            goto done;
        }
        grid_add(&g, body_com(w->bodies[i]), w->bodies[i]->shape.r_out, w->bodies[i]);
    }
    for (; made < n; made++) {
        if (made == made_cap) {
            body **more = realloc(made_b, (size_t)(2 * made_cap) * sizeof *more);
            if (!more) {
                sh_error(sh, st, "random: out of memory after %ld of the %ld objects, so none was added", made, n);
                goto done;
            }
            made_b = more;
            made_cap *= 2;
        }
        if (shell_interrupted) {
            shell_interrupted = 0;
            sh_error(sh, st, "random: interrupted after %ld of the %ld objects, so none was added", made, n);
            goto done;
        }
        body *b = random_body(sh, &id, err, sizeof err);
        if (!b) {
            sh_error(sh, st, "random: %s", err);
            goto done;
        }
        double r = b->shape.r_out;
        bool placed = false;
        for (int tries = 0; tries < RANDOM_TRIES && !placed; tries++) {
            vec3 c = v3(rng_uniform(&sh->rng, -box.x + r, box.x - r),
                        rng_uniform(&sh->rng, -box.y + r, box.y - r),
                        rng_uniform(&sh->rng, -box.z + r, box.z - r));
            if (grid_free_at(&g, c, r)) {
                b->x = c;
                placed = true;
            }
        }
        if (!placed) {
            body_free(b);
            free(b);
            /* with the sequence restored, random k adds the k that fit */
            if (made > 0)
                sh_error(sh, st,
                         "random: only %ld of the %ld objects found room in random_box, so "
                         "none was added; random %ld adds those %ld, and a larger random_box "
                         "or a smaller random_size holds more",
                         made, n, made, made);
            else
                sh_error(sh, st,
                         "random: no room for an object in random_box, so none was added: the "
                         "objects already there fill it (a larger random_box or a smaller "
                         "random_size holds more)");
            goto done;
        }
        if (grid_room(&g) != 0) {
            body_free(b);
            free(b);
            sh_error(sh, st, "random: out of memory after %ld of the %ld objects, so none was added", made, n);
            goto done;
        }
        grid_add(&g, body_com(b), r, NULL);
        body_set_rotation(b, rng_unit(&sh->rng), rng_uniform(&sh->rng, 0, M_PI));
        b->v = v3_scale(rng_unit(&sh->rng), rng_uniform(&sh->rng, 0, fmin(2, w->set.max_linear)));
        body_set_angular_vel(
            b, v3_scale(rng_unit(&sh->rng), rng_uniform(&sh->rng, 0, fmin(2, w->set.max_angular))));
        made_b[made] = b;
    }
    /* all found room: they join the world */
    for (long k = 0; k < n; k++) {
        if (world_add(w, made_b[k]) < 0) { /* (it freed the object) */
            for (long j = k + 1; j < n; j++) {
                body_free(made_b[j]);
                free(made_b[j]);
            }
            made = 0;
            while (k-- > 0) world_delete(w, w->n - 1);
            sh_error(sh, st, "out of memory");
            goto done;
        }
    }
    made = 0;
    rc = CMD_OK;
    if (n > 0) sh->current = w->n - 1; /* the last made, as when an object is created */
done:
    for (long k = 0; k < made; k++) {
        body_free(made_b[k]);
        free(made_b[k]);
    }
    free(made_b);
    grid_free(&g);
    if (rc != CMD_OK) sh->rng = rng0;
    return rc;
}
