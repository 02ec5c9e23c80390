/* tone.h: the strongest frequency of a signal, for the sound tests: test_sound.c
 * reads the sounds vroc makes, wavtool.c the WAV files it writes.  Goertzel's
 * algorithm gives the power of one frequency; a coarse scan finds the best, and a
 * scan forty times finer about it places it. */
#ifndef VROC_TESTS_TONE_H
#define VROC_TESTS_TONE_H

#include <math.h>

/* The power of frequency f (Hz) in the n samples x at rate (samples/s). */
static inline double tone_power(const double *x, long n, double f, double rate)
{
    double w = 2 * M_PI * f / rate, c = 2 * cos(w), s1 = 0, s2 = 0;
    for (long k = 0; k < n; k++) {
        double s = x[k] + c * s1 - s2;
        s2 = s1;
        s1 = s;
    }
    return s1 * s1 + s2 * s2 - c * s1 * s2;
}

/* The strongest frequency of x from lo up to below hi (Hz): a scan every step
 * Hz, then every step / 40 Hz within step of the best. */
static inline double tone_strongest(const double *x, long n, double rate, double lo, double hi,
                                    double step)
{
    double best = lo, bp = -1;
    for (double f = lo; f < hi; f += step) {
        double p = tone_power(x, n, f, rate);
        if (p > bp) bp = p, best = f;
    }
    for (double f = best - step, c = best; f <= c + step; f += step / 40) {
        double p = tone_power(x, n, f, rate);
        if (p > bp) bp = p, best = f;
    }
    return best;
}

#endif
