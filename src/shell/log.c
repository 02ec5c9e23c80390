/* log.c: trace and event logs as CSV (language.md, "Commands a console tool
 * needs"). */
#include "log.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>

static FILE *open_log(const char *path, const char *header, char *err, size_t errlen)
{
    FILE *f = fopen(path, "w");
    if (!f) {
        snprintf(err, errlen, "cannot write '%s': %s", path, strerror(errno));
        return NULL;
    }
    fprintf(f, "%s\n", header);
    return f;
}

int log_trace_open(shell_logs *l, const world *w, const char *path, char *err, size_t errlen)
{
    FILE *f = open_log(path, "frame,time,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,state", err,
                       errlen);
    if (!f) return -1;
    log_trace_close(l);
    l->trace = f;
    snprintf(l->trace_path, sizeof l->trace_path, "%s", path);
    log_trace_frame(l, w);
    return 0;
}

int log_events_open(shell_logs *l, const char *path, char *err, size_t errlen)
{
    FILE *f = open_log(path, "time,a,b,px,py,pz,nx,ny,nz,impulse,speed", err, errlen);
    if (!f) return -1;
    log_events_close(l);
    l->events = f;
    snprintf(l->events_path, sizeof l->events_path, "%s", path);
    return 0;
}

void log_trace_close(shell_logs *l)
{
    if (l->trace) fclose(l->trace);
    l->trace = NULL;
    l->trace_path[0] = '\0';
}

void log_events_close(shell_logs *l)
{
    if (l->events) fclose(l->events);
    l->events = NULL;
    l->events_path[0] = '\0';
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

void log_trace_frame(shell_logs *l, const world *w)
{
    if (!l->trace) return;
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        fprintf(l->trace,
                "%ld,%.17g,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,"
                "%.17g,%.17g,%.17g,%s\n",
                w->frame, w->time, b->name, b->x.x, b->x.y, b->x.z, b->q.w, b->q.x, b->q.y,
                b->q.z, b->v.x, b->v.y, b->v.z, b->w.x, b->w.y, b->w.z, log_body_state(b));
    }
    fflush(l->trace);
}

void log_events_frame(shell_logs *l, const world *w)
{
    if (!l->events || w->nevents == 0) return;
    for (long k = 0; k < w->nevents; k++) {
        const sim_event *e = &w->events[k];
        vec3 p = e->p, n = e->n;
        fprintf(l->events, "%.17g,%s,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", e->t,
                w->bodies[e->a]->name, w->bodies[e->b]->name, p.x, p.y, p.z, n.x, n.y, n.z, e->j,
                e->speed);
    }
    fflush(l->events);
}
