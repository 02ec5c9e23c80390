/* live.c: the live stream to the sound server (live.h). */
#include "live.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <pulse/context.h>
#include <pulse/error.h>
#include <pulse/mainloop.h>
#include <pulse/simple.h>

#include "buf.h"

struct live {
    pa_simple *s;
};

static double live_clock(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Whether a server answers, without autospawn, within LIVE_ASK_SECONDS: 0 with its
 * address in server, or -1 with the reason in err. */
static int live_ask(char *server, size_t len, char *err, size_t errlen)
{
    pa_mainloop *ml = pa_mainloop_new();
    if (!ml) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    pa_context *c = pa_context_new(pa_mainloop_get_api(ml), "vroc");
    int rc = -1;
    if (!c) {
        snprintf(err, errlen, "out of memory");
    } else if (pa_context_connect(c, NULL, PA_CONTEXT_NOAUTOSPAWN, NULL) < 0) {
        snprintf(err, errlen, "%s", pa_strerror(pa_context_errno(c)));
    } else {
        double end = live_clock() + LIVE_ASK_SECONDS;
        for (;;) {
            pa_context_state_t s = pa_context_get_state(c);
            if (s == PA_CONTEXT_READY) {
                const char *name = pa_context_get_server(c);
                snprintf(server, len, "%s", name ? name : "");
                rc = 0;
                break;
            }
            if (!PA_CONTEXT_IS_GOOD(s)) {
                snprintf(err, errlen, "%s", pa_strerror(pa_context_errno(c)));
                break;
            }
            double left = end - live_clock();
            if (left <= 0) {
                snprintf(err, errlen, "no answer within %g s", LIVE_ASK_SECONDS);
                break;
            }
            if (pa_mainloop_prepare(ml, (int)(left * 1e6) + 1) < 0 || pa_mainloop_poll(ml) < 0 ||
                pa_mainloop_dispatch(ml) < 0) {
                snprintf(err, errlen, "the connection failed");
                break;
            }
        }
        pa_context_disconnect(c);
    }
    if (c) pa_context_unref(c);
    pa_mainloop_free(ml);
    return rc;
}

int live_open(live **l, char *err, size_t errlen)
{
    char server[512];
    if (live_ask(server, sizeof server, err, errlen) != 0) return -1;
    pa_sample_spec ss = {PA_SAMPLE_S16LE, SOUND_RATE, 2};
    uint32_t bytes = (uint32_t)(LIVE_BUFFER_SECONDS * SOUND_RATE) * 4;
    pa_buffer_attr attr = {(uint32_t)-1, bytes, (uint32_t)-1, (uint32_t)-1, (uint32_t)-1};
    int e = 0;
    pa_simple *s = pa_simple_new(server[0] ? server : NULL, "vroc", PA_STREAM_PLAYBACK, NULL,
                                 "collisions", &ss, NULL, &attr, &e);
    if (!s) {
        snprintf(err, errlen, "%s", pa_strerror(e));
        return -1;
    }
    live *nl = malloc(sizeof *nl);
    if (!nl) {
        pa_simple_free(s);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    nl->s = s;
    *l = nl;
    return 0;
}

int live_write(live *l, const int16_t *x, long n, char *err, size_t errlen)
{
    int e = 0;
    if (n > 0 && pa_simple_write(l->s, x, (size_t)n * 4, &e) < 0) {
        snprintf(err, errlen, "%s", pa_strerror(e));
        return -1;
    }
    return 0;
}

void live_close(live *l)
{
    if (!l) return;
    int e;
    pa_simple_flush(l->s, &e);
    pa_simple_free(l->s);
    free(l);
}
