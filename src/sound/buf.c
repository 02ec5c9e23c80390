/* buf.c: shared mono sounds (buf.h). */
#include "buf.h"

#include <math.h>
#include <stdlib.h>

sound_buf *sbuf_new(long n)
{
    if (n < 0) return NULL;
    sound_buf *b = calloc(1, sizeof *b + (size_t)n * sizeof(float));
    if (!b) return NULL;
    b->refs = 1;
    b->n = n;
    return b;
}

sound_buf *sbuf_ref(sound_buf *b)
{
    b->refs++;
    return b;
}

void sbuf_unref(sound_buf *b)
{
    if (b && --b->refs == 0) free(b);
}

void sbuf_normalize(sound_buf *b)
{
    float peak = 0;
    for (long i = 0; i < b->n; i++)
        if (fabsf(b->x[i]) > peak) peak = fabsf(b->x[i]);
    if (!(peak > 0)) return;
    for (long i = 0; i < b->n; i++) b->x[i] /= peak;
}
