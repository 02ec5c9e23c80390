/* cmd_plot.c: `plot QUANTITY = FILE.png`: the current run's figures (figures.h)
 * drawn by gnuplot (view/plot.h). */
#include <math.h>
#include <stdlib.h>

#include "handlers.h"
#include "outfile.h"
#include "shell.h"
#include "view/plot.h"

/* The table of figures quantity q plots: time first, then its columns. */
static double *plot_table(const figures *f, int q, const figure_series *s, int *ncols)
{
    *ncols = q == PLOT_ENERGY ? 4 : q == PLOT_MOMENTUM ? 7 : 2;
    double *d = malloc((size_t)f->n * (size_t)*ncols * sizeof *d);
    if (!d) return NULL;
    for (int r = 0; r < f->n; r++) {
        const figure_row *row = &f->rows[r];
        double *o = d + (size_t)r * (size_t)*ncols;
        o[0] = row->t;
        if (q == PLOT_ENERGY) {
            o[1] = row->kinetic;
            o[2] = row->potential;
            o[3] = row->kinetic + row->potential;
        } else if (q == PLOT_MOMENTUM) {
            const vec3 p = row->momentum, L = row->angular_momentum;
            double v[6] = {p.x, p.y, p.z, L.x, L.y, L.z};
            for (int k = 0; k < 6; k++) o[1 + k] = v[k];
        } else {
            long k = f->dropped + r - s->first;
            o[1] = k >= 0 && k < s->n ? s->z[k] : NAN;
        }
    }
    return d;
}

cmd_status cmd_plot(shell *sh, const stmt *st)
{
    const figures *f = &sh->figs;
    int q = (int)st->num[0];
    char why[SHELL_PATH_MAX + 256];
    if (outfile_allowed(st->word, why, sizeof why) != 0) {
        sh_error(sh, st, "plot: %s", why);
        return CMD_ERROR;
    }
    if (f->n < 2) {
        sh_error(sh, st, "plot: this run has no frames to plot yet (run or step first; restart "
                 "and read start a new run)");
        return CMD_ERROR;
    }
    const figure_series *s = NULL;
    if (q == PLOT_HEIGHT && !(s = figures_series(f, st->object))) {
        sh_error(sh, st, "plot: no object named '%s' in this run", st->object);
        return CMD_ERROR;
    }
    if (f->dropped > 0)
        sh_warn(sh, st, "plot: the run's first %ld frames were dropped: vroc keeps the last %d "
                "(at most %ld, fewer with many objects)", f->dropped, f->n, FIGURES_MAX_FRAMES);
    if (f->failed)
        sh_warn(sh, st, "plot: out of memory: the figures end at time %g", f->rows[f->n - 1].t);
    plot_spec p = {.npanels = 1, .nrows = f->n};
    char title[BODY_NAME_MAX + 32];
    if (q == PLOT_ENERGY) {
        p.title = "energy";
        p.panel[0] = (plot_panel){"energy (J)", 3, {"kinetic", "potential", "total"}, {1, 2, 3}};
    } else if (q == PLOT_MOMENTUM) {
        p.title = "momentum";
        p.npanels = 2;
        p.panel[0] = (plot_panel){"linear momentum (kg m/s)", 3, {"x", "y", "z"}, {1, 2, 3}};
        p.panel[1] = (plot_panel){"angular momentum about the origin (kg m^2/s)", 3,
                                  {"x", "y", "z"}, {4, 5, 6}};
    } else {
        snprintf(title, sizeof title, "%s.height", st->object);
        p.title = title;
        p.panel[0] = (plot_panel){"height of the origin, z (m)", 1, {st->object}, {1}};
    }
    double *data = plot_table(f, q, s, &p.ncols);
    if (!data) {
        sh_error(sh, st, "plot: out of memory");
        return CMD_ERROR;
    }
    p.data = data;
    char err[SHELL_PATH_MAX + 512];
    int rc = plot_png(st->word, &p, err, sizeof err);
    free(data);
    if (rc != 0) {
        sh_error(sh, st, "plot: %s", err);
        return CMD_ERROR;
    }
    sh_info(sh, "plotted %s over %d frames to %s", p.title, f->n, st->word);
    return CMD_OK;
}
