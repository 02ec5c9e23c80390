/* plot.c: figures over time drawn by the gnuplot program (plot.h). */
#include "plot.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdarg.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "child.h"

/* Pixels of the picture: one panel, and each more. */
#define PLOT_W 900
#define PLOT_H 520
#define PLOT_H_MORE 380

/* What goes down the pipe, gathered in a buffer and written in large pieces. */
typedef struct {
    int fd;
    pid_t pid; /* gnuplot, which reads it */
    int rc; /* the first write's errno, or 0 */
    size_t n;
    char buf[1 << 16];
} pipe_out;

static void out_flush(pipe_out *o)
{
    if (o->rc == 0 && o->n > 0) o->rc = child_write(o->fd, o->buf, o->n, o->pid);
    o->n = 0;
}

static void out_printf(pipe_out *o, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
static void out_printf(pipe_out *o, const char *fmt, ...)
{
    if (sizeof o->buf - o->n < 512) out_flush(o);
    va_list ap;
    va_start(ap, fmt);
    int k = vsnprintf(o->buf + o->n, sizeof o->buf - o->n, fmt, ap);
    va_end(ap);
    if (k > 0 && (size_t)k < sizeof o->buf - o->n) o->n += (size_t)k;
}

/* s as a gnuplot string in double quotes: backslashes and quotes escaped. */
static void out_string(pipe_out *o, const char *s)
{
    out_printf(o, "\"");
    for (; *s; s++) {
        if (*s == '"' || *s == '\\') out_printf(o, "\\%c", *s);
        else out_printf(o, "%c", *s);
    }
    out_printf(o, "\"");
}

/* The script and its data. */
static void write_script(pipe_out *o, const char *part, const plot_spec *p)
{
    int h = PLOT_H + (p->npanels - 1) * PLOT_H_MORE;
    out_printf(o, "set terminal pngcairo size %d,%d font \"sans,10\"\nset output ", PLOT_W, h);
    out_string(o, part);
    out_printf(o, "\nset datafile missing \"NaN\"\n$d << EOD\n");
    for (long r = 0; r < p->nrows; r++) {
        const double *row = p->data + r * p->ncols;
        for (int c = 0; c < p->ncols; c++)
            out_printf(o, isfinite(row[c]) ? "%s%.17g" : "%sNaN", c ? " " : "", row[c]);
        out_printf(o, "\n");
    }
    out_printf(o, "EOD\nset grid\nset key top right\n");
    if (p->npanels > 1) {
        out_printf(o, "set multiplot layout %d,1 title ", p->npanels);
        out_string(o, p->title);
        out_printf(o, "\n");
    } else {
        out_printf(o, "set title ");
        out_string(o, p->title);
        out_printf(o, "\n");
    }
    for (int k = 0; k < p->npanels; k++) {
        const plot_panel *pn = &p->panel[k];
        out_printf(o, "set xlabel \"time (s)\"\nset ylabel ");
        out_string(o, pn->ylabel);
        out_printf(o, "\nplot ");
        for (int c = 0; c < pn->ncurves; c++) {
            out_printf(o, "%s$d using 1:%d with lines linewidth 2 title ", c ? ", " : "",
                       pn->column[c] + 1);
            out_string(o, pn->curve[c]);
        }
        out_printf(o, "\n");
    }
    if (p->npanels > 1) out_printf(o, "unset multiplot\n");
    out_printf(o, "set output\nexit\n");
    out_flush(o);
}

/* gnuplot's complaint, from its log: the last line it wrote (gnuplot quotes the
 * line it read and a caret, then says what is wrong), in out. */
static void complaint(int log, char *out, size_t len)
{
    char buf[4096];
    out[0] = '\0';
    ssize_t n = pread(log, buf, sizeof buf - 1, 0);
    if (n <= 0) return;
    buf[n] = '\0';
    while (n > 0 && (buf[n - 1] == '\n' || buf[n - 1] == ' ')) buf[--n] = '\0';
    const char *last = strrchr(buf, '\n');
    last = last ? last + 1 : buf;
    while (*last == ' ' || *last == '\t') last++;
    snprintf(out, len, "%.300s", last);
}

int plot_png(const char *path, const plot_spec *p, char *err, size_t errlen)
{
    char part[4200];
    child_beside(part, sizeof part, path, ".vroc-part-", ".png");
    pid_t pid;
    int in, log;
    char *const argv[] = {"gnuplot", NULL};
    if (child_open(argv, &pid, &in, &log, err, errlen) != 0) return -1;
    pipe_out *o = malloc(sizeof *o);
    if (o) {
        o->fd = in;
        o->pid = pid;
        o->rc = 0;
        o->n = 0;
        write_script(o, part, p);
    }
    close(in);
    int status = child_wait(pid);
    struct stat sb;
    char why[600];
    if (!o || status != 0 || stat(part, &sb) != 0 || sb.st_size == 0) {
        complaint(log, why, sizeof why);
        if (!o) snprintf(err, errlen, "out of memory");
        else if (why[0]) snprintf(err, errlen, "gnuplot could not draw '%s': %s", path, why);
        else snprintf(err, errlen, "gnuplot could not draw '%s' (%s)", path,
                      status == -2 || o->rc == ETIMEDOUT ? "it stalled, and was stopped"
                      : o->rc ? strerror(o->rc) : "it wrote no picture");
        unlink(part);
        free(o);
        close(log);
        return -1;
    }
    free(o);
    close(log);
    if (rename(part, path) != 0) {
        snprintf(err, errlen, "cannot write '%s': %s", path, strerror(errno));
        unlink(part);
        return -1;
    }
    return 0;
}
