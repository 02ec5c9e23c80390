/* progress.c: a status line while a long run works (progress.h). */
#include "progress.h"

#include <unistd.h>

void progress_begin(progress *p, FILE *out, long n, double now)
{
    p->out = out;
    p->tty = isatty(fileno(out));
    p->n = n;
    p->start = now;
    p->next = now + PROGRESS_AFTER;
    p->shown = false;
}

/* Seconds as a person reads a time left: "42 s", "3 min 5 s", "2 h 10 min". */
static void say_left(char *buf, size_t len, double s)
{
    if (s < 10) snprintf(buf, len, "%.1f s", s);
    else if (s < 60) snprintf(buf, len, "%.0f s", s);
    else if (s < 3600) snprintf(buf, len, "%d min %d s", (int)(s / 60), (int)s % 60);
    else snprintf(buf, len, "%d h %d min", (int)(s / 3600), ((int)s % 3600) / 60);
}

void progress_tick(progress *p, long k, double t, double now)
{
    if (now < p->next) return;
    double rate = (double)k / (now - p->start);
    char left[48];
    say_left(left, sizeof left, rate > 0 ? (double)(p->n - k) / rate : 0);
    fprintf(p->out, "%srun: frame %ld of %ld, time = %.6g, %.0f frames/s, %s left%s",
            p->tty ? "\r\033[K" : "", k, p->n, t, rate, left, p->tty ? "" : "\n");
    fflush(p->out);
    p->shown = p->tty;
    p->next = now + (p->tty ? PROGRESS_EVERY : PROGRESS_LOG);
}

void progress_hide(progress *p)
{
    if (!p->shown) return;
    fputs("\r\033[K", p->out);
    fflush(p->out);
    p->shown = false;
}
