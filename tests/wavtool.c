/* wavtool.c: reads 16-bit PCM sound files from outside, for the script tests (a
 * RIFF/WAV parser of its own, not libsndfile, which vroc writes them with; or raw
 * signed 16-bit little-endian stereo at 48 kHz for a name ending in .raw).
 *
 *   wavtool info FILE                  rate=R channels=C bits=B frames=N
 *   wavtool peak FILE [T0 T1]          left=L right=R: largest |sample| in [T0, T1) s
 *   wavtool onset FILE T0 T1 LEVEL     left=T right=T: first time |sample| >= LEVEL
 *                                      in [T0, T1) s (-1: none)
 *   wavtool freq FILE T0 T1            freq=F: the strongest frequency of the left
 *                                      channel in [T0, T1) s (Hann window, 20 Hz to
 *                                      20 kHz, to 0.05 Hz)
 *   wavtool env FILE MS                one line "t left right" per MS milliseconds:
 *                                      the largest |sample| of each channel
 *   wavtool xcorr A B MS               lag=S corr=C: the shift of B's envelope (MS
 *                                      bins, both channels) that best matches A's,
 *                                      and the Pearson correlation there (over at
 *                                      least 80% of B)
 * Times are seconds from the file's first sample.  Exit 2 on a bad file. */
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tone.h"

typedef struct {
    int rate, channels, bits;
    long frames;
    int16_t *x; /* frames * channels */
} pcm;

static unsigned rd16(const unsigned char *p) { return p[0] | (unsigned)p[1] << 8; }
static unsigned long rd32(const unsigned char *p)
{
    return p[0] | (unsigned long)p[1] << 8 | (unsigned long)p[2] << 16 | (unsigned long)p[3] << 24;
}

static void die(const char *what, const char *path)
{
    fprintf(stderr, "wavtool: %s: %s\n", path, what);
    exit(2);
}

static pcm load(const char *path)
{
    FILE *f = fopen(path, "rb");
    if (!f) die("cannot open", path);
    fseek(f, 0, SEEK_END);
    long size = ftell(f);
    rewind(f);
    unsigned char *d = malloc((size_t)size + 1);
    if (!d || fread(d, 1, (size_t)size, f) != (size_t)size) die("cannot read", path);
    fclose(f);
    pcm p = {48000, 2, 16, 0, NULL};
    size_t n = strlen(path);
    if (n > 4 && strcmp(path + n - 4, ".raw") == 0) {
        p.frames = size / 4;
        p.x = (int16_t *)d;
        return p;
    }
    if (size < 12 || memcmp(d, "RIFF", 4) != 0 || memcmp(d + 8, "WAVE", 4) != 0)
        die("not a RIFF WAVE file", path);
    long at = 12;
    int have_fmt = 0;
    while (at + 8 <= size) {
        unsigned long len = rd32(d + at + 4);
        const unsigned char *c = d + at + 8;
        if (memcmp(d + at, "fmt ", 4) == 0 && len >= 16) {
            if (rd16(c) != 1) die("not PCM", path);
            p.channels = (int)rd16(c + 2);
            p.rate = (int)rd32(c + 4);
            p.bits = (int)rd16(c + 14);
            have_fmt = 1;
        } else if (memcmp(d + at, "data", 4) == 0) {
            if (!have_fmt || p.bits != 16) die("no fmt chunk before data, or not 16-bit", path);
            if ((long)len > size - at - 8) len = (unsigned long)(size - at - 8);
            p.frames = (long)len / (2 * p.channels);
            p.x = malloc((size_t)len + 2);
            memcpy(p.x, c, len);
            return p;
        }
        at += 8 + (long)len + (long)(len & 1);
    }
    die("no data chunk", path);
    return p;
}

static long frame_at(const pcm *p, double t)
{
    long k = lround(t * p->rate);
    return k < 0 ? 0 : k > p->frames ? p->frames : k;
}

static int sample(const pcm *p, long k, int ch)
{
    return p->x[k * p->channels + (ch < p->channels ? ch : 0)];
}

/* Largest |sample| of both channels in each bin of ms milliseconds. */
static double *envelope(const pcm *p, double ms, long *nb)
{
    long w = lround(ms * 1e-3 * p->rate);
    if (w < 1) w = 1;
    *nb = p->frames / w;
    double *e = calloc((size_t)*nb + 1, sizeof *e);
    for (long b = 0; b < *nb; b++)
        for (long k = b * w; k < (b + 1) * w; k++)
            for (int c = 0; c < 2; c++) e[b] = fmax(e[b], abs(sample(p, k, c)));
    return e;
}

int main(int argc, char **argv)
{
    if (argc < 3) {
        fprintf(stderr, "usage: wavtool info|peak|onset|freq|env|xcorr FILE ...\n");
        return 2;
    }
    const char *cmd = argv[1];
    pcm p = load(argv[2]);
    if (strcmp(cmd, "info") == 0) {
        printf("rate=%d channels=%d bits=%d frames=%ld\n", p.rate, p.channels, p.bits, p.frames);
    } else if (strcmp(cmd, "peak") == 0) {
        long a = argc > 4 ? frame_at(&p, atof(argv[3])) : 0;
        long z = argc > 4 ? frame_at(&p, atof(argv[4])) : p.frames;
        int m[2] = {0, 0};
        for (long k = a; k < z; k++)
            for (int c = 0; c < 2; c++)
                if (abs(sample(&p, k, c)) > m[c]) m[c] = abs(sample(&p, k, c));
        printf("left=%d right=%d\n", m[0], m[1]);
    } else if (strcmp(cmd, "onset") == 0 && argc > 5) {
        long a = frame_at(&p, atof(argv[3])), z = frame_at(&p, atof(argv[4]));
        int level = atoi(argv[5]);
        double t[2] = {-1, -1};
        for (int c = 0; c < 2; c++)
            for (long k = a; k < z; k++)
                if (abs(sample(&p, k, c)) >= level) {
                    t[c] = (double)k / p.rate;
                    break;
                }
        printf("left=%.6f right=%.6f\n", t[0], t[1]);
    } else if (strcmp(cmd, "freq") == 0 && argc > 4) {
        long a = frame_at(&p, atof(argv[3])), z = frame_at(&p, atof(argv[4])), n = z - a;
        double *x = malloc((size_t)(n > 0 ? n : 1) * sizeof *x);
        for (long k = 0; k < n; k++)
            x[k] = sample(&p, a + k, 0) * (0.5 - 0.5 * cos(2 * M_PI * k / (n - 1 > 0 ? n - 1 : 1)));
        printf("freq=%.2f\n", tone_strongest(x, n, p.rate, 20, fmin(20002, p.rate / 2.0), 2));
    } else if (strcmp(cmd, "env") == 0 && argc > 3) {
        double ms = atof(argv[3]);
        long w = lround(ms * 1e-3 * p.rate);
        for (long b = 0; (b + 1) * w <= p.frames; b++) {
            int m[2] = {0, 0};
            for (long k = b * w; k < (b + 1) * w; k++)
                for (int c = 0; c < 2; c++)
                    if (abs(sample(&p, k, c)) > m[c]) m[c] = abs(sample(&p, k, c));
            printf("%.4f %d %d\n", (double)(b * w) / p.rate, m[0], m[1]);
        }
    } else if (strcmp(cmd, "xcorr") == 0 && argc > 4) {
        pcm q = load(argv[3]);
        double ms = atof(argv[4]);
        long na, nb;
        double *ea = envelope(&p, ms, &na), *eb = envelope(&q, ms, &nb);
        double best = -2;
        long best_lag = 0, need = (long)ceil(0.8 * (double)nb);
        for (long lag = -nb; lag <= na; lag++) {
            long i0 = lag < 0 ? -lag : 0, i1 = nb < na - lag ? nb : na - lag;
            long n = i1 - i0;
            if (n < need || n < 2) continue;
            double sa = 0, sb = 0, saa = 0, sbb = 0, sab = 0;
            for (long i = i0; i < i1; i++) {
                double u = ea[lag + i], v = eb[i];
                sa += u, sb += v, saa += u * u, sbb += v * v, sab += u * v;
            }
            double cov = sab - sa * sb / n, va = saa - sa * sa / n, vb = sbb - sb * sb / n;
            double r = va > 0 && vb > 0 ? cov / sqrt(va * vb) : 0;
            if (r > best) best = r, best_lag = lag;
        }
        printf("lag=%.4f corr=%.4f\n", (double)best_lag * ms * 1e-3, best);
    } else {
        fprintf(stderr, "wavtool: unknown command or missing arguments: %s\n", cmd);
        return 2;
    }
    return 0;
}
