/* mixer.c: voices, their sum and the limiter (mixer.h). */
#include "mixer.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

typedef struct {
    sound_buf *b;
    long start[2];
    double gain[2];
} voice;

struct mixer {
    voice v[MIXER_VOICES];
    int nv;
    long pos;      /* next sample to render */
    double g;      /* the limiter's gain at pos - 1 */
    double *sum;   /* scratch: the sum of a render with its look-ahead (2 values a
                    * sample), then each sample's needed gain (1 a sample) */
    long cap;      /* samples the scratch holds */
};

/* Below this gain a voice is not heard in 16 bits (a third of one step). */
#define MIXER_QUIET (1.0 / 98304)
/* No voice gain above this: a sum of 512 of them stays finite in any case. */
#define MIXER_LOUDEST 1e6

mixer *mixer_new(void)
{
    mixer *m = calloc(1, sizeof *m);
    if (m) m->g = 1;
    return m;
}

void mixer_free(mixer *m)
{
    if (!m) return;
    for (int i = 0; i < m->nv; i++) sbuf_unref(m->v[i].b);
    free(m->sum);
    free(m);
}

long mixer_pos(const mixer *m) { return m->pos; }
int mixer_voices(const mixer *m) { return m->nv; }

static double voice_loudness(const voice *v) { return fmax(v->gain[0], v->gain[1]); }

void mixer_add(mixer *m, sound_buf *b, const long start[2], const double gain[2])
{
    voice nv = {b, {start[0], start[1]}, {gain[0], gain[1]}};
    for (int e = 0; e < 2; e++)
        if (!(nv.gain[e] >= 0)) nv.gain[e] = 0; /* NaN too */
        else if (nv.gain[e] > MIXER_LOUDEST) nv.gain[e] = MIXER_LOUDEST;
    double loud = voice_loudness(&nv);
    if (!b || b->n == 0 || loud < MIXER_QUIET) return;
    long first = nv.start[0] < nv.start[1] ? nv.start[0] : nv.start[1];
    if (first < m->pos) {
        nv.start[0] += m->pos - first;
        nv.start[1] += m->pos - first;
    }
    int slot = m->nv;
    if (m->nv == MIXER_VOICES) {
        slot = 0;
        for (int i = 1; i < m->nv; i++)
            if (voice_loudness(&m->v[i]) < voice_loudness(&m->v[slot])) slot = i;
        if (voice_loudness(&m->v[slot]) >= loud) return;
        sbuf_unref(m->v[slot].b);
    } else {
        m->nv++;
    }
    nv.b = sbuf_ref(b);
    m->v[slot] = nv;
}

void mixer_peek(const mixer *m, long from, long n, double *out)
{
    memset(out, 0, 2 * (size_t)n * sizeof *out);
    for (int i = 0; i < m->nv; i++) {
        const voice *v = &m->v[i];
        for (int e = 0; e < 2; e++) {
            long a = from > v->start[e] ? from : v->start[e];
            long z = v->start[e] + v->b->n;
            if (z > from + n) z = from + n;
            const float *x = v->b->x - v->start[e];
            double g = v->gain[e];
            for (long k = a; k < z; k++) out[2 * (k - from) + e] += g * x[k];
        }
    }
}

/* Drops the voices that end before sample pos. */
static void mixer_retire(mixer *m)
{
    for (int i = 0; i < m->nv;) {
        voice *v = &m->v[i];
        if (v->start[0] + v->b->n <= m->pos && v->start[1] + v->b->n <= m->pos) {
            sbuf_unref(v->b);
            *v = m->v[--m->nv];
        } else {
            i++;
        }
    }
}

long mixer_render(mixer *m, long upto, int16_t *out)
{
    long n = upto - m->pos;
    if (n <= 0) return 0;
    const long L = MIXER_LOOKAHEAD;
    long need = n + L;
    if (need > m->cap) {
        double *s = realloc(m->sum, 3 * (size_t)need * sizeof *s);
        if (!s) { /* no room to mix: silence, time still advances */
            memset(out, 0, 2 * (size_t)n * sizeof *out);
            m->pos = upto;
            mixer_retire(m);
            return n;
        }
        m->sum = s;
        m->cap = need;
    }
    double *x = m->sum, *r = m->sum + 2 * need;
    mixer_peek(m, m->pos, need, x);
    for (long k = 0; k < need; k++) {
        double peak = fmax(fabs(x[2 * k]), fabs(x[2 * k + 1]));
        r[k] = peak > MIXER_CEILING ? MIXER_CEILING / peak : 1.0;
    }
    const double recover = 1 - exp(-1.0 / (0.05 * SOUND_RATE));
    double g = m->g;
    for (long k = 0; k < n; k++) {
        double want = 1;
        for (long j = 0; j <= L; j++) {
            double c = r[k + j] + (double)j / (double)L;
            if (c < want) want = c;
        }
        g += (1 - g) * recover;
        if (want < g) g = want;
        for (int e = 0; e < 2; e++) {
            double s = x[2 * k + e] * g * 32767.0;
            long q = lrint(s);
            if (q > 32766) q = 32766; /* never reached: the ceiling is -1 dBFS */
            if (q < -32766) q = -32766;
            out[2 * k + e] = (int16_t)q;
        }
    }
    m->g = g;
    m->pos = upto;
    mixer_retire(m);
    return n;
}

void mixer_reset(mixer *m, long pos)
{
    for (int i = 0; i < m->nv; i++) sbuf_unref(m->v[i].b);
    m->nv = 0;
    m->pos = pos;
    m->g = 1;
}
