/* plot.h: figures over time drawn into a PNG file by the gnuplot program
 * (`plot QUANTITY = FILE.png`; language.md, "The console beyond the thesis").
 *
 * As movies pipe frames to ffmpeg (movie.h), plot_png pipes a script and the
 * data, as a datablock, to `gnuplot` found on PATH (child.h), which draws with
 * its pngcairo terminal: one panel, or two stacked with a shared time axis.
 * The picture is made beside the file and put in its place when gnuplot
 * succeeded, so that a failed plot leaves an older file as it was. */
#ifndef VROC_PLOT_H
#define VROC_PLOT_H

#include <stddef.h>

/* Most curves of one panel. */
#define PLOT_CURVES 4

/* One panel: its y axis's label and its curves, each a column of the data. */
typedef struct {
    const char *ylabel;
    int ncurves;
    const char *curve[PLOT_CURVES]; /* each curve's title */
    int column[PLOT_CURVES];        /* its column in the data (0 is time) */
} plot_panel;

typedef struct {
    const char *title;
    int npanels;         /* 1 or 2, stacked */
    plot_panel panel[2];
    long nrows;          /* rows of data, in time order */
    int ncols;           /* columns: time first, then the figures */
    const double *data;  /* nrows x ncols, row after row; NaN: no value there */
} plot_spec;

/* Draws p into the PNG file at path.  Returns 0, or -1 with a message in err:
 * gnuplot is not installed, it failed (its first complaint), or the file cannot
 * be written ("cannot write 'PATH': REASON"). */
int plot_png(const char *path, const plot_spec *p, char *err, size_t errlen);

#endif
