/* clip.c: sound files read with libsndfile and resampled with libsamplerate
 * (clip.h). */
#include "clip.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include <samplerate.h>
#include <sndfile.h>

/* The file's frames averaged to mono; *n gets their count.  NULL with err set. */
static float *clip_read_mono(SNDFILE *f, const SF_INFO *info, const char *path, long *n,
                             char *err, size_t errlen)
{
    long cap = info->frames > 0 && info->frames != SF_COUNT_MAX ? (long)info->frames : 48000;
    int ch = info->channels;
    float *mono = malloc((size_t)cap * sizeof *mono);
    float *frame = malloc(4096 * (size_t)ch * sizeof *frame);
    long got = 0;
    if (!mono || !frame) goto oom;
    for (;;) {
        sf_count_t k = sf_readf_float(f, frame, 4096);
        if (k <= 0) break;
        if (got + k > (long)CLIP_MAX_SECONDS * info->samplerate) {
            snprintf(err, errlen, "'%s' is too long: a collision sound lasts at most %d s",
                     path, CLIP_MAX_SECONDS);
            free(mono);
            free(frame);
            return NULL;
        }
        if (got + k > cap) {
            while (got + k > cap) cap *= 2;
            float *m = realloc(mono, (size_t)cap * sizeof *mono);
            if (!m) goto oom;
            mono = m;
        }
        for (sf_count_t i = 0; i < k; i++) {
            double s = 0;
            for (int c = 0; c < ch; c++) s += frame[i * ch + c];
            mono[got + i] = (float)(s / ch);
        }
        got += (long)k;
    }
    free(frame);
    *n = got;
    return mono;
oom:
    free(mono);
    free(frame);
    snprintf(err, errlen, "out of memory reading '%s'", path);
    return NULL;
}

sound_buf *clip_load(const char *path, char *err, size_t errlen)
{
    FILE *probe = fopen(path, "rb");
    if (!probe) {
        snprintf(err, errlen, "cannot read '%s': %s", path, strerror(errno));
        return NULL;
    }
    struct stat sb;
    int st = fstat(fileno(probe), &sb);
    fclose(probe);
    if (st == 0 && S_ISDIR(sb.st_mode)) {
        snprintf(err, errlen, "'%s' is a folder, not a file", path);
        return NULL;
    }
    if (st == 0 && sb.st_size == 0) {
        snprintf(err, errlen, "'%s' is empty", path);
        return NULL;
    }
    SF_INFO info;
    memset(&info, 0, sizeof info);
    SNDFILE *f = sf_open(path, SFM_READ, &info);
    if (!f) {
        snprintf(err, errlen, "'%s' is not a sound file libsndfile can read (%s)", path,
                 sf_strerror(NULL));
        return NULL;
    }
    if (info.channels < 1 || info.samplerate < 1) {
        sf_close(f);
        snprintf(err, errlen, "'%s' has no channels or no sample rate", path);
        return NULL;
    }
    long n = 0;
    float *mono = clip_read_mono(f, &info, path, &n, err, errlen);
    sf_close(f);
    if (!mono) return NULL;
    if (n == 0) {
        free(mono);
        snprintf(err, errlen, "'%s' holds no sound (0 frames)", path);
        return NULL;
    }
    double ratio = (double)SOUND_RATE / info.samplerate;
    long out_n = info.samplerate == SOUND_RATE ? n : (long)((double)n * ratio) + 1;
    sound_buf *b = sbuf_new(out_n);
    if (!b) {
        free(mono);
        snprintf(err, errlen, "out of memory reading '%s'", path);
        return NULL;
    }
    if (info.samplerate == SOUND_RATE) {
        memcpy(b->x, mono, (size_t)n * sizeof *mono);
    } else {
        SRC_DATA d;
        memset(&d, 0, sizeof d);
        d.data_in = mono;
        d.input_frames = n;
        d.data_out = b->x;
        d.output_frames = out_n;
        d.src_ratio = ratio;
        d.end_of_input = 1;
        int e = src_simple(&d, SRC_SINC_MEDIUM_QUALITY, 1);
        if (e != 0) {
            free(mono);
            sbuf_unref(b);
            snprintf(err, errlen, "cannot resample '%s' to %d Hz: %s", path, SOUND_RATE,
                     src_strerror(e));
            return NULL;
        }
        b->n = d.output_frames_gen;
    }
    free(mono);
    sbuf_normalize(b);
    return b;
}
