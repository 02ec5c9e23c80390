/* figures.c: the figures of each frame of the current run, for plot
 * (figures.h). */
#include "figures.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core/energy.h"
#include "core/grow.h"

void figures_init(figures *f, long max_frames, long max_heights)
{
    memset(f, 0, sizeof *f);
    f->max_frames = max_frames;
    f->max_heights = max_heights;
}

void figures_clear(figures *f)
{
    for (int i = 0; i < f->nseries; i++) free(f->series[i].z);
    f->nseries = 0;
    f->n = 0;
    f->dropped = 0;
    f->heights = 0;
    f->failed = false;
}

void figures_free(figures *f)
{
    figures_clear(f);
    free(f->rows);
    free(f->series);
    free(f->of_body);
    memset(f, 0, sizeof *f);
}

/* Drops the oldest quarter of the rows (one at least), and the heights that
 * belong to them. */
static void drop_oldest(figures *f)
{
    int d = f->n / 4 > 0 ? f->n / 4 : 1;
    if (d > f->n) d = f->n;
    memmove(f->rows, f->rows + d, (size_t)(f->n - d) * sizeof *f->rows);
    f->n -= d;
    f->dropped += d;
    for (int i = 0; i < f->nseries; i++) {
        figure_series *s = &f->series[i];
        long cut = f->dropped - s->first; /* its values before the new first row */
        if (cut <= 0) continue;
        if (cut > s->n) cut = s->n;
        memmove(s->z, s->z + cut, (size_t)(s->n - cut) * sizeof *s->z);
        s->n -= cut;
        s->first += cut;
        f->heights -= cut;
    }
}

static figure_series *find_series(figures *f, const char *name)
{
    for (int i = 0; i < f->nseries; i++)
        if (strcmp(f->series[i].name, name) == 0) return &f->series[i];
    return NULL;
}

const figure_series *figures_series(const figures *f, const char *name)
{
    return find_series((figures *)f, name);
}

/* The series of body i named name (made when new), or NULL when out of memory. */
static figure_series *series_of(figures *f, int i, const char *name)
{
    int k = f->of_body[i];
    if (k >= 0 && k < f->nseries && strcmp(f->series[k].name, name) == 0) return &f->series[k];
    figure_series *s = find_series(f, name);
    if (!s) {
        figure_series *ns = grow_for_one(f->series, f->nseries, &f->capseries, sizeof *ns, 16);
        if (!ns) return NULL;
        f->series = ns;
        s = &f->series[f->nseries++];
        memset(s, 0, sizeof *s);
        strcpy(s->name, name);
    }
    f->of_body[i] = (int)(s - f->series);
    return s;
}

/* Appends z as row `row` of s, NaN over a gap since its last value. */
static bool append(figures *f, figure_series *s, long row, double z)
{
    if (s->n == 0) s->first = row;
    long need = row - s->first + 1;
    if (need > s->cap) {
        long cap = s->cap ? 2 * s->cap : 64;
        while (cap < need) cap *= 2;
        double *nz = realloc(s->z, (size_t)cap * sizeof *nz);
        if (!nz) return false;
        s->z = nz;
        s->cap = cap;
    }
    long before = s->n;
    while (s->first + s->n < row) s->z[s->n++] = NAN;
    s->z[s->n++] = z;
    f->heights += s->n - before;
    return true;
}

void figures_record(figures *f, const world *w)
{
    if (f->failed) return;
    while (f->n > 0 && (f->n >= f->max_frames || f->heights + w->n > f->max_heights)) drop_oldest(f);
    figure_row *nr = grow_for_one(f->rows, f->n, &f->cap, sizeof *nr, 256);
    int capbody = f->capbody;
    int *nb = w->n > capbody ? realloc(f->of_body, (size_t)w->n * sizeof *nb) : f->of_body;
    if (!nr || (w->n > 0 && !nb)) {
        if (nr) f->rows = nr;
        f->failed = true;
        return;
    }
    f->rows = nr;
    if (w->n > capbody) {
        for (int i = capbody; i < w->n; i++) nb[i] = -1;
        f->of_body = nb;
        f->capbody = w->n;
    }
    energy_sum e = energy_of_world(w);
    long row = f->dropped + f->n;
    f->rows[f->n++] = (figure_row){w->frame, w->time, energy_kinetic(e), e.potential, e.momentum,
                                   e.angular_momentum};
    for (int i = 0; i < w->n; i++) {
        figure_series *s = series_of(f, i, w->bodies[i]->name);
        if (!s || !append(f, s, row, w->bodies[i]->x.z)) {
            f->failed = true;
            return;
        }
    }
}
