/* log.c: trace and event logs as CSV (language.md, "Commands a console tool
 * needs").  Every frame's rows are flushed and checked (outfile.h). */
#include "log.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

#include "outfile.h"

/* Starts the log at path, beside it, with its header; the caller writes its
 * first rows and puts it in place (outfile.h), so that a log that cannot start
 * leaves the old file whole. */
static int open_log(outfile *o, const char *path, const char *header, char *err, size_t errlen)
{
    if (outfile_begin(o, path, OUTFILE_STREAM, err, errlen) != 0) return -1;
    fprintf(o->f, "%s\n", header);
    return 0;
}

/* The old log of *slot closed and f put in its place, at path. */
static int replace_log(FILE **slot, char *slot_path, FILE *f, const char *path, char *err,
                       size_t errlen)
{
    int rc = outfile_close(*slot, slot_path, err, errlen);
    *slot = f;
    snprintf(slot_path, LOG_PATH_MAX, "%s", path);
    return rc;
}

int log_trace_open(shell_logs *l, const world *w, const char *path, char *err, size_t errlen)
{
    outfile o;
    if (open_log(&o, path, "frame,time,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,state,ke", err,
                 errlen) != 0)
        return -1;
    shell_logs first = {o.f, "", NULL, ""};
    snprintf(first.trace_path, sizeof first.trace_path, "%s", path);
    if (log_trace_frame(&first, w, err, errlen) != 0 || outfile_place(&o, err, errlen) != 0) {
        outfile_abort(&o);
        return -1;
    }
    return replace_log(&l->trace, l->trace_path, o.f, path, err, errlen);
}

int log_events_open(shell_logs *l, const char *path, char *err, size_t errlen)
{
    outfile o;
    if (open_log(&o, path, "time,a,b,px,py,pz,nx,ny,nz,impulse,speed", err, errlen) != 0)
        return -1;
    if (outfile_place(&o, err, errlen) != 0) return -1;
    return replace_log(&l->events, l->events_path, o.f, path, err, errlen);
}

int log_trace_close(shell_logs *l, char *err, size_t errlen)
{
    int rc = outfile_close(l->trace, l->trace_path, err, errlen);
    l->trace = NULL;
    l->trace_path[0] = '\0';
    return rc;
}

int log_events_close(shell_logs *l, char *err, size_t errlen)
{
    int rc = outfile_close(l->events, l->events_path, err, errlen);
    l->events = NULL;
    l->events_path[0] = '\0';
    return rc;
}

const char *log_state_name(body_state s)
{
    switch (s) {
    case STATE_DYNAMIC: return "dynamic";
    case STATE_STATIC: return "static";
    case STATE_RESTING: return "resting";
    }
    return "?";
}

const char *log_body_state(const body *b)
{
    return b->held ? "held" : log_state_name(b->state);
}

int log_trace_frame(shell_logs *l, const world *w, char *err, size_t errlen)
{
    if (!l->trace) return 0;
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        /* (the reason is the failing write's: a later flush may have none) */
        if (fprintf(l->trace,
                "%ld,%.17g,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,"
                "%.17g,%.17g,%.17g,%s,%.17g\n",
                w->frame, w->time, b->name, b->x.x, b->x.y, b->x.z, b->q.w, b->q.x, b->q.y,
                b->q.z, b->v.x, b->v.y, b->v.z, b->w.x, b->w.y, b->w.z, log_body_state(b),
                body_energy(b)) < 0)
            return outfile_failed(l->trace_path, errno, err, errlen);
    }
    return outfile_flush(l->trace, l->trace_path, err, errlen);
}

int log_events_frame(shell_logs *l, const world *w, char *err, size_t errlen)
{
    if (!l->events || w->nevents == 0) return 0;
    for (long k = 0; k < w->nevents; k++) {
        const sim_event *e = &w->events[k];
        vec3 p = e->p, n = e->n;
        if (fprintf(l->events, "%.17g,%s,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                    e->t, w->bodies[e->a]->name, w->bodies[e->b]->name, p.x, p.y, p.z, n.x, n.y,
                    n.z, e->j, e->speed) < 0)
            return outfile_failed(l->events_path, errno, err, errlen);
    }
    return outfile_flush(l->events, l->events_path, err, errlen);
}
