/* random.c: `random N`, the thesis's random environment (Table 5.6): N dynamic
 * objects of mixed kinds at random non-overlapping places inside random_box, with
 * random sizes, orientations and velocities, from the shell's own sequence (seed).
 * Each object is made whole (as a fresh body with its defaults, then its random
 * values) before it joins the world. */
#include <math.h>
#include <stdlib.h>

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

/* True when a ball of radius r at c is clear of every object's circumscribed
 * sphere. */
static bool place_is_free(const world *w, vec3 c, double r)
{
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        if (v3_dist(c, body_com(b)) < r + b->shape.r_out) return false;
    }
    return true;
}

cmd_status cmd_random(shell *sh, const stmt *st)
{
    long n = (long)st->num[0];
    world *w = &sh->w;
    vec3 box = sh->set.random_box;
    double scale = fmin(box.x, fmin(box.y, box.z));
    int first = w->n;
    unsigned long long rng0 = sh->rng; /* a refused statement changes nothing */
    char err[256];
    for (long k = 0; k < n; k++) {
        body *b = malloc(sizeof *b);
        if (!b) goto oom;
        char name[BODY_NAME_MAX];
        for (long id = w->n + 1;; id++) {
            snprintf(name, sizeof name, "random%ld", id);
            if (world_find(w, name) < 0) break;
        }
        shape_kind kind = (shape_kind)(rng_next(&sh->rng) % 3);
        body_init(b, name, kind);
        double s = scale * rng_uniform(&sh->rng, 0.04, 0.1);
        b->sp.radius = s;
        b->sp.size = v3(s * rng_uniform(&sh->rng, 0.6, 1), s * rng_uniform(&sh->rng, 0.6, 1),
                        s * rng_uniform(&sh->rng, 0.6, 1));
        b->sp.exp1 = rng_uniform(&sh->rng, 0.3, 1.8);
        b->sp.exp2 = rng_uniform(&sh->rng, 0.3, 1.8);
        b->sp.a1 = s;
        b->sp.a2 = s * rng_uniform(&sh->rng, 0.6, 1);
        b->sp.a3 = s * rng_uniform(&sh->rng, 0.6, 1);
        for (int c = 0; c < 3; c++) b->color[c] = 64 + (int)(rng_next(&sh->rng) % 192);
        if (body_build(b, err, sizeof err) != 0) {
            free(b);
            sh_error(sh, st, "random: %s", err);
            goto undo;
        }
        double r = b->shape.r_out;
        bool placed = false;
        for (int tries = 0; tries < 2000 && !placed; tries++) {
            vec3 c = v3(rng_uniform(&sh->rng, -box.x + r, box.x - r),
                        rng_uniform(&sh->rng, -box.y + r, box.y - r),
                        rng_uniform(&sh->rng, -box.z + r, box.z - r));
            if (place_is_free(w, c, r)) {
                b->x = c;
                placed = true;
            }
        }
        if (!placed) {
            body_free(b);
            free(b);
            /* the objects' sizes scale with the box, so a larger box holds no more
             * of them; with the sequence restored, random k adds the k that fit */
            if (k > 0)
                sh_error(sh, st,
                         "random: only %ld of the %ld objects found room in random_box, so "
                         "none was added; random %ld adds those %ld (a larger random_box holds "
                         "no more: the objects grow with it)",
                         k, n, k, k);
            else
                sh_error(sh, st,
                         "random: no room for an object in random_box, so none was added: the "
                         "objects already there fill it (a larger random_box holds no more: the "
                         "objects grow with it)");
            goto undo;
        }
        body_set_rotation(b, rng_unit(&sh->rng), rng_uniform(&sh->rng, 0, M_PI));
        b->v = v3_scale(rng_unit(&sh->rng), rng_uniform(&sh->rng, 0, fmin(2, w->set.max_linear)));
        body_set_angular_vel(
            b, v3_scale(rng_unit(&sh->rng), rng_uniform(&sh->rng, 0, fmin(2, w->set.max_angular))));
        if (world_add(w, b) < 0) goto oom;
    }
    return CMD_OK;
oom:
    sh_error(sh, st, "out of memory");
undo:
    while (w->n > first) world_delete(w, w->n - 1);
    sh->rng = rng0;
    return CMD_ERROR;
}
