/* clip.c: sound files read with libsndfile and resampled with libsamplerate
 * (clip.h). */
#include "clip.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <math.h>
#include <samplerate.h>
#include <sndfile.h>

#include "shell/infile.h"

/* The bytes of a sound file read whole (infile.h), which libsndfile reads through
 * these calls of ours (its virtual I/O): its size was capped, and nothing waits. */
typedef struct {
    const infile *in;
    sf_count_t at;
} clip_mem;

static sf_count_t mem_len(void *u) { return (sf_count_t)((clip_mem *)u)->in->len; }

static sf_count_t mem_seek(sf_count_t off, int whence, void *u)
{
    clip_mem *m = u;
    sf_count_t base = whence == SEEK_SET ? 0 : whence == SEEK_CUR ? m->at : (sf_count_t)m->in->len;
    if (base + off < 0 || base + off > (sf_count_t)m->in->len) return -1;
    m->at = base + off;
    return m->at;
}

static sf_count_t mem_read(void *ptr, sf_count_t n, void *u)
{
    clip_mem *m = u;
    sf_count_t left = (sf_count_t)m->in->len - m->at;
    if (n > left) n = left;
    if (n > 0) memcpy(ptr, m->in->data + m->at, (size_t)n);
    m->at += n;
    return n;
}

static sf_count_t mem_write(const void *ptr, sf_count_t n, void *u)
{
    (void)ptr;
    (void)n;
    (void)u;
    return 0;
}

static sf_count_t mem_tell(void *u) { return ((clip_mem *)u)->at; }

static SF_VIRTUAL_IO clip_vio = {mem_len, mem_seek, mem_read, mem_write, mem_tell};

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
            for (int c = 0; c < ch; c++) {
                /* a float file may hold them; played, they would be full-scale
                 * bursts */
                if (!isfinite(frame[i * ch + c])) {
                    snprintf(err, errlen, "'%s' holds a sample that is not a finite number "
                             "(%g, at frame %ld): a sound file must hold finite samples", path,
                             (double)frame[i * ch + c], got + (long)i);
                    free(mono);
                    free(frame);
                    return NULL;
                }
                s += frame[i * ch + c];
            }
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
    infile in;
    char why[256];
    if (infile_read(&in, path, CLIP_MAX_BYTES, why, sizeof why) != 0) {
        snprintf(err, errlen, "cannot read '%s': %s", path, why);
        return NULL;
    }
    if (in.len == 0) {
        infile_free(&in);
        snprintf(err, errlen, "'%s' is empty", path);
        return NULL;
    }
    SF_INFO info;
    memset(&info, 0, sizeof info);
    clip_mem mem = {&in, 0};
    SNDFILE *f = sf_open_virtual(&clip_vio, SFM_READ, &info, &mem);
    if (!f) {
        infile_free(&in);
        snprintf(err, errlen, "'%s' is not a sound file libsndfile can read (%s)", path,
                 sf_strerror(NULL));
        return NULL;
    }
    if (info.channels < 1 || info.samplerate < 1) {
        sf_close(f);
        infile_free(&in);
        snprintf(err, errlen, "'%s' has no channels or no sample rate", path);
        return NULL;
    }
    long n = 0;
    float *mono = clip_read_mono(f, &info, path, &n, err, errlen);
    sf_close(f);
    infile_free(&in);
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
