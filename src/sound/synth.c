/* synth.c: the built-in collision sounds by modal synthesis (synth.h). */
#include "synth.h"

#include <math.h>
#include <string.h>

typedef struct {
    double f;   /* Hz, at SYNTH_REF_SIZE */
    double tau; /* s, decay time constant */
    double a;   /* amplitude */
} synth_mode;

#define SYNTH_MODES 5

static const struct {
    const char *name;
    synth_mode m[SYNTH_MODES]; /* the first is the lowest; unused ones have f = 0 */
} synth_table[SYNTH_KINDS] = {
    /* a small hard object: bright, a few milliseconds */
    [SYNTH_CLICK] = {"click", {{2900, 0.006, 1.0}, {4750, 0.004, 0.55}, {6800, 0.0025, 0.35},
                               {9100, 0.0018, 0.2}}},
    /* wood: a dull knock, tens of milliseconds */
    [SYNTH_KNOCK] = {"knock", {{340, 0.040, 1.0}, {910, 0.022, 0.55}, {1720, 0.013, 0.35},
                               {2900, 0.008, 0.2}}},
    /* metal: the partials of a church bell (hum, prime, tierce, quint, nominal) over
     * a second or two */
    [SYNTH_BELL] = {"bell", {{440, 1.6, 0.6}, {880, 1.0, 1.0}, {1041, 0.8, 0.7},
                             {1325, 0.5, 0.4}, {1760, 0.6, 0.8}}},
};

int synth_find(const char *name)
{
    for (int k = 0; k < SYNTH_KINDS; k++)
        if (strcmp(name, synth_table[k].name) == 0) return k;
    return -1;
}

double synth_pitch(synth_kind k, double size)
{
    double f0 = synth_table[k].m[0].f;
    double p = size > 0 && isfinite(size) ? SYNTH_REF_SIZE / size : 1.0;
    if (p * f0 > 16000) p = 16000 / f0;
    if (p * f0 < 40) p = 40 / f0;
    return p;
}

sound_buf *synth_make(synth_kind k, double pitch)
{
    const synth_mode *m = synth_table[k].m;
    const double fs = SOUND_RATE, max_len = 4.0 * fs;
    /* long enough for every mode to fall 80 dB below its start */
    double len = 0, sum_a = 0;
    for (int i = 0; i < SYNTH_MODES && m[i].f > 0; i++) {
        if (m[i].f * pitch >= 20000) continue;
        double t = m[i].tau / pitch * log(1e4);
        if (t * fs > len) len = t * fs;
        sum_a += m[i].a;
    }
    long n = (long)fmin(ceil(len), max_len);
    sound_buf *b = sbuf_new(n);
    if (!b || n == 0) return b;
    /* each mode by its two-term recurrence: s[j] = 2 r cos(w) s[j-1] - r^2 s[j-2] */
    for (int i = 0; i < SYNTH_MODES && m[i].f > 0; i++) {
        double f = m[i].f * pitch;
        if (f >= 20000) continue;
        double w = 2 * M_PI * f / fs, r = exp(-pitch / (m[i].tau * fs));
        double c = 2 * r * cos(w), r2 = r * r;
        double s2 = 0, s1 = m[i].a / sum_a * r * sin(w);
        if (n > 1) b->x[1] += (float)s1;
        for (long j = 2; j < n; j++) {
            double s = c * s1 - r2 * s2;
            b->x[j] += (float)s;
            s2 = s1;
            s1 = s;
        }
    }
    sbuf_normalize(b);
    /* a sound cut at max_len fades out over its last 20 ms instead of stopping dead */
    if (n == (long)max_len) {
        long fade = (long)(0.02 * fs);
        for (long j = 0; j < fade; j++) b->x[n - 1 - j] *= (float)j / (float)fade;
    }
    return b;
}
