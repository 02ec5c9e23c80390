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

int log_trace_open(world *w, const char *path, char *err, size_t errlen)
{
    FILE *f = open_log(path, "frame,time,name,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,state", err,
                       errlen);
    if (!f) return -1;
    log_trace_close(w);
    w->trace = f;
    snprintf(w->trace_path, sizeof w->trace_path, "%s", path);
    log_trace_frame(w);
    return 0;
}

int log_events_open(world *w, const char *path, char *err, size_t errlen)
{
    FILE *f = open_log(path, "time,a,b,px,py,pz,nx,ny,nz,impulse,speed", err, errlen);
    if (!f) return -1;
    log_events_close(w);
    w->events = f;
    snprintf(w->events_path, sizeof w->events_path, "%s", path);
    return 0;
}

void log_trace_close(world *w)
{
    if (w->trace) fclose(w->trace);
    w->trace = NULL;
    w->trace_path[0] = '\0';
}

void log_events_close(world *w)
{
    if (w->events) fclose(w->events);
    w->events = NULL;
    w->events_path[0] = '\0';
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

void log_trace_frame(world *w)
{
    if (!w->trace) return;
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        fprintf(w->trace,
                "%ld,%.17g,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,"
                "%.17g,%.17g,%.17g,%s\n",
                w->frame, w->time, b->name, b->x.x, b->x.y, b->x.z, b->q.w, b->q.x, b->q.y,
                b->q.z, b->v.x, b->v.y, b->v.z, b->w.x, b->w.y, b->w.z,
                log_state_name(b->state));
    }
    fflush(w->trace);
}

void log_event(world *w, const body *a, const body *b, vec3 p, vec3 n, double j, double s)
{
    if (!w->events) return;
    fprintf(w->events, "%.17g,%s,%s,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
            w->time, a->name, b->name, p.x, p.y, p.z, n.x, n.y, n.z, j, s);
    fflush(w->events);
}
