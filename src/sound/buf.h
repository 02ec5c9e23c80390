/* buf.h: a mono sound at the mixer's rate (48 kHz), shared by the voices that play it.
 *
 * A collision's sound is made once (synth.h, or a file read by clip.h) and played by
 * any number of voices at once (mixer.h); each holds a reference, so a sound chosen
 * away while its voices still ring is freed only when the last one ends. */
#ifndef VROC_SOUND_BUF_H
#define VROC_SOUND_BUF_H

/* The sample rate of every sound vroc makes, of the mixer, the soundtrack and the
 * live stream. */
#define SOUND_RATE 48000

typedef struct sound_buf {
    int refs;
    long n;       /* samples */
    float x[];    /* n samples, the loudest of magnitude 1 (or all 0) */
} sound_buf;

/* A buffer of n zero samples with one reference, or NULL when out of memory. */
sound_buf *sbuf_new(long n);

/* Another reference to b (returns b). */
sound_buf *sbuf_ref(sound_buf *b);

/* Drops one reference; frees b with the last (NULL is fine). */
void sbuf_unref(sound_buf *b);

/* Scales b so that its loudest sample has magnitude 1 (an all-zero b stays so). */
void sbuf_normalize(sound_buf *b);

#endif
