/* track.c: the soundtrack as a WAV file, RF64 beyond 4 GiB (track.h). */
#include "track.h"

#include <errno.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <sndfile.h>

#include "buf.h"
#include "shell/outfile.h"

struct track {
    outfile o;
    long n;          /* frames written */
    bool failed;     /* a write failed: the file is given up at close */
};

static void put32(unsigned char *p, uint32_t v)
{
    for (int k = 0; k < 4; k++) p[k] = (unsigned char)(v >> (8 * k));
}

static void put64(unsigned char *p, uint64_t v)
{
    for (int k = 0; k < 8; k++) p[k] = (unsigned char)(v >> (8 * k));
}

void track_header(unsigned char h[TRACK_HEADER_BYTES], uint64_t frames, uint64_t riff_max)
{
    uint64_t data = frames * 4, riff = TRACK_HEADER_BYTES - 8 + data;
    bool rf64 = riff > riff_max;
    memset(h, 0, TRACK_HEADER_BYTES);
    memcpy(h, rf64 ? "RF64" : "RIFF", 4);
    put32(h + 4, rf64 ? 0xffffffffu : (uint32_t)riff);
    memcpy(h + 8, "WAVE", 4);
    /* ds64 (RF64), or a JUNK chunk of its size that keeps its place */
    memcpy(h + 12, rf64 ? "ds64" : "JUNK", 4);
    put32(h + 16, 28);
    if (rf64) {
        put64(h + 20, riff);
        put64(h + 28, data);
        put64(h + 36, frames);
        put32(h + 44, 0); /* no table of other chunks' sizes */
    }
    memcpy(h + 48, "fmt ", 4);
    put32(h + 52, 16);
    h[56] = 1; /* PCM */
    h[58] = 2; /* channels */
    put32(h + 60, SOUND_RATE);
    put32(h + 64, SOUND_RATE * 4);
    h[68] = 4;  /* bytes per frame */
    h[70] = 16; /* bits */
    memcpy(h + 72, "data", 4);
    put32(h + 76, rf64 ? 0xffffffffu : (uint32_t)data);
}

/* Writes all n bytes of p at offset off of t's file: 0, or an errno value. */
static int put_at(track *t, const void *p, size_t n, off_t off)
{
    const char *c = p;
    while (n > 0) {
        ssize_t w = pwrite(t->o.fd, c, n, off);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return w < 0 ? errno : EIO;
        c += w;
        n -= (size_t)w;
        off += w;
    }
    return 0;
}

/* The header for what is written so far: 0, or an errno value. */
static int put_header(track *t)
{
    unsigned char h[TRACK_HEADER_BYTES];
    track_header(h, (uint64_t)t->n, TRACK_RIFF_MAX);
    return put_at(t, h, sizeof h, 0);
}

/* The failure of a write: the track failed, the message in err. */
static int write_failed(track *t, int e, char *err, size_t errlen)
{
    t->failed = true;
    return outfile_failed(t->o.path, e, err, errlen);
}

int track_open(track **tp, const char *path, char *err, size_t errlen)
{
    track *t = calloc(1, sizeof *t);
    if (!t) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    /* rewritten as it grows: a device may take it in place (/dev/full says no), a
     * named pipe may not */
    if (outfile_begin(&t->o, path, OUTFILE_SEEK, err, errlen) != 0) {
        free(t);
        return -1;
    }
    int e = put_header(t);
    if (e != 0) {
        outfile_failed(path, e, err, errlen);
        outfile_abort(&t->o);
        free(t);
        return -1;
    }
    *tp = t;
    return 0;
}

int track_write(track *t, const int16_t *x, long n, char *err, size_t errlen)
{
    if (t->failed) return outfile_failed(t->o.path, EIO, err, errlen);
    unsigned char buf[4 * 4096];
    for (long k = 0; k < n;) {
        long m = n - k < 4096 ? n - k : 4096;
        for (long i = 0; i < 2 * m; i++) { /* little-endian, whatever the machine */
            uint16_t s = (uint16_t)x[2 * k + i];
            buf[2 * i] = (unsigned char)(s & 0xff);
            buf[2 * i + 1] = (unsigned char)(s >> 8);
        }
        int e = put_at(t, buf, (size_t)(4 * m), TRACK_HEADER_BYTES + (off_t)t->n * 4);
        if (e != 0) return write_failed(t, e, err, errlen);
        t->n += m;
        k += m;
    }
    /* the header tells the true length after every write: the file can be read
     * (and muxed into a movie) while it grows */
    int e = n > 0 ? put_header(t) : 0;
    return e != 0 ? write_failed(t, e, err, errlen) : 0;
}

long track_length(const track *t) { return t->n; }
const char *track_path(const track *t) { return t->o.path; }

int track_excerpt(track *t, long from, long n, const char *out, char *err, size_t errlen)
{
    SF_INFO in_info;
    memset(&in_info, 0, sizeof in_info);
    SNDFILE *in = sf_open(outfile_now(&t->o), SFM_READ, &in_info);
    if (!in) {
        snprintf(err, errlen, "cannot read back '%s': %s", t->o.path, sf_strerror(NULL));
        return -1;
    }
    track *o;
    if (track_open(&o, out, err, errlen) != 0) {
        sf_close(in);
        return -1;
    }
    enum { CHUNK = 4800 };
    int16_t buf[2 * CHUNK];
    long avail = (long)in_info.frames;
    int rc = 0;
    for (long k = from; k < from + n && rc == 0;) {
        long m = from + n - k < CHUNK ? from + n - k : CHUNK;
        memset(buf, 0, sizeof buf);
        /* the part of [k, k + m) the soundtrack holds */
        long a = k > 0 ? k : 0, z = k + m < avail ? k + m : avail;
        if (a < z && (sf_seek(in, a, SEEK_SET) < 0 ||
                      sf_readf_short(in, buf + 2 * (a - k), z - a) != z - a)) {
            snprintf(err, errlen, "cannot read back '%s': %s", t->o.path, sf_strerror(in));
            o->failed = true;
            rc = -1;
        }
        if (rc == 0) rc = track_write(o, buf, m, err, errlen);
        k += m;
    }
    sf_close(in);
    char why[1024];
    if (track_close(o, why, sizeof why) != 0 && rc == 0) {
        snprintf(err, errlen, "%s", why);
        rc = -1;
    }
    return rc;
}

int track_close(track *t, char *err, size_t errlen)
{
    if (!t) return 0;
    int rc;
    if (t->failed) {
        rc = outfile_failed(t->o.path, EIO, err, errlen);
        outfile_abort(&t->o);
    } else {
        int e = put_header(t);
        if (e != 0) {
            rc = outfile_failed(t->o.path, e, err, errlen);
            outfile_abort(&t->o);
        } else {
            rc = outfile_finish(&t->o, err, errlen);
        }
    }
    free(t);
    return rc;
}
