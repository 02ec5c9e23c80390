/* live.c: the live stream to the sound server, written by a thread of its own
 * (live.h). */
#include "live.h"

#include <pthread.h>
#include <signal.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <pulse/context.h>
#include <pulse/error.h>
#include <pulse/mainloop.h>
#include <pulse/simple.h>

#include "buf.h"

/* Samples handed over and not yet written: half a second; the oldest go first when
 * more come (the server has stalled, and they would be late anyway). */
#define LIVE_RING (SOUND_RATE / 2)
/* What the thread writes at a time: 5 ms. */
#define LIVE_CHUNK (SOUND_RATE / 200)

struct live {
    pa_simple *s;
    pthread_t thread;
    pthread_mutex_t mu;
    pthread_cond_t cv;
    int16_t ring[2 * LIVE_RING];
    long head, n;      /* the oldest sample's place in ring, samples held */
    double head_due;   /* wall-clock time the oldest is due */
    bool stop, failed;
    char err[768];     /* why it failed: "cannot write to the sound server ..." */
    char server[512];  /* the server's address, as it answered */
};

double live_clock(void)
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

/* Drops the n oldest samples of the ring (mu held). */
static void live_drop(live *l, long n)
{
    l->head = (l->head + n) % LIVE_RING;
    l->n -= n;
    l->head_due += (double)n / SOUND_RATE;
}

/* The writing thread: takes a chunk at a time and writes it, waiting on the
 * server as long as it takes; drops what has become late. */
static void *live_run(void *arg)
{
    live *l = arg;
    int16_t chunk[2 * LIVE_CHUNK];
    pthread_mutex_lock(&l->mu);
    for (;;) {
        while (l->n == 0 && !l->stop) pthread_cond_wait(&l->cv, &l->mu);
        if (l->stop) break;
        double late = live_clock() - LIVE_LATE_SECONDS - l->head_due;
        if (late > 0) {
            long drop = (long)(late * SOUND_RATE) + 1;
            live_drop(l, drop < l->n ? drop : l->n);
            continue;
        }
        long k = l->n < LIVE_CHUNK ? l->n : LIVE_CHUNK;
        if (k > LIVE_RING - l->head) k = LIVE_RING - l->head;
        memcpy(chunk, l->ring + 2 * l->head, (size_t)k * 2 * sizeof *chunk);
        live_drop(l, k);
        pthread_mutex_unlock(&l->mu);
        int e = 0;
        int rc = pa_simple_write(l->s, chunk, (size_t)k * 4, &e);
        pthread_mutex_lock(&l->mu);
        if (rc < 0) {
            l->failed = true;
            snprintf(l->err, sizeof l->err, "cannot write to the sound server '%s': %s",
                     l->server[0] ? l->server : "default", pa_strerror(e));
            break;
        }
    }
    pthread_mutex_unlock(&l->mu);
    return NULL;
}

/* live_open's work, with every signal blocked: the threads it starts (ours and
 * libpulse's) inherit that, so that Ctrl-C reaches the prompt's thread. */
static int live_start(live **lp, char *err, size_t errlen)
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
    live *l = calloc(1, sizeof *l);
    if (!l) {
        pa_simple_free(s);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    l->s = s;
    snprintf(l->server, sizeof l->server, "%s", server);
    pthread_mutex_init(&l->mu, NULL);
    pthread_cond_init(&l->cv, NULL);
    if (pthread_create(&l->thread, NULL, live_run, l) != 0) {
        pthread_mutex_destroy(&l->mu);
        pthread_cond_destroy(&l->cv);
        pa_simple_free(s);
        free(l);
        snprintf(err, errlen, "cannot start the thread that writes the sound");
        return -1;
    }
    *lp = l;
    return 0;
}

int live_open(live **lp, char *err, size_t errlen)
{
    sigset_t all, old;
    sigfillset(&all);
    pthread_sigmask(SIG_BLOCK, &all, &old);
    int rc = live_start(lp, err, errlen);
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    return rc;
}

int live_write(live *l, const int16_t *x, long n, double due, char *err, size_t errlen)
{
    pthread_mutex_lock(&l->mu);
    if (l->failed) {
        snprintf(err, errlen, "%s", l->err);
        pthread_mutex_unlock(&l->mu);
        return -1;
    }
    if (l->n == 0) l->head_due = due;
    for (long k = 0; k < n; k++) {
        if (l->n == LIVE_RING) live_drop(l, 1);
        long at = (l->head + l->n) % LIVE_RING;
        l->ring[2 * at] = x[2 * k];
        l->ring[2 * at + 1] = x[2 * k + 1];
        l->n++;
    }
    pthread_cond_signal(&l->cv);
    pthread_mutex_unlock(&l->mu);
    return 0;
}

void live_close(live *l)
{
    if (!l) return;
    pthread_mutex_lock(&l->mu);
    l->stop = true;
    pthread_cond_signal(&l->cv);
    pthread_mutex_unlock(&l->mu);
    pthread_join(l->thread, NULL);
    int e;
    pa_simple_flush(l->s, &e);
    pa_simple_free(l->s);
    pthread_mutex_destroy(&l->mu);
    pthread_cond_destroy(&l->cv);
    free(l);
}
