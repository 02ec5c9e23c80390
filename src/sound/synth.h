/* synth.h: the built-in collision sounds, made by modal synthesis.
 *
 * After van den Doel and Pai ("The sounds of physical shapes", Presence 7(4), 1998):
 * a struck object rings in a few modes, each an exponentially damped sinusoid
 *
 *     y(t) = sum_i a_i exp(-t / tau_i) sin(2 pi f_i t),
 *
 * and objects of the same shape and material but k times the size ring k times lower
 * and, their damping following the frequency, longer.  `click` is a small hard
 * object, `knock` wood, `bell` metal; their modes are given for objects of
 * SYNTH_REF_SIZE and scaled by size.  The result is normalised to a peak of 1: the
 * loudness is the mixer's business (sound.h). */
#ifndef VROC_SOUND_SYNTH_H
#define VROC_SOUND_SYNTH_H

#include "buf.h"

typedef enum { SYNTH_CLICK, SYNTH_KNOCK, SYNTH_BELL, SYNTH_KINDS } synth_kind;

/* The size (m) the modes of each sound are given for. */
#define SYNTH_REF_SIZE 0.1

/* The built-in sound named name ("click", "knock", "bell"), or -1. */
int synth_find(const char *name);

/* The frequency factor for objects of the given size (m): SYNTH_REF_SIZE / size,
 * held so that the sound's lowest mode stays within 40 Hz to 16 kHz. */
double synth_pitch(synth_kind k, double size);

/* The sound of kind k with its modes' frequencies times pitch (synth_pitch) and
 * their decay times divided by it: mono, 48 kHz, peak 1, as long as it rings above
 * -80 dB (at most 4 s).  Modes at or above 20 kHz are left out.  NULL when out of
 * memory. */
sound_buf *synth_make(synth_kind k, double pitch);

#endif
