/* track.c: the soundtrack as a WAV file (track.h). */
#include "track.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include <sndfile.h>

#include "buf.h"

struct track {
    SNDFILE *f;
    long n;          /* samples written */
    char path[];     /* as named */
};

static SNDFILE *track_create(const char *path, char *err, size_t errlen)
{
    int fd = open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (fd < 0) {
        snprintf(err, errlen, "cannot write '%s': %s", path, strerror(errno));
        return NULL;
    }
    SF_INFO info;
    memset(&info, 0, sizeof info);
    info.samplerate = SOUND_RATE;
    info.channels = 2;
    info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
    SNDFILE *f = sf_open_fd(fd, SFM_WRITE, &info, 1);
    if (!f) {
        snprintf(err, errlen, "cannot write '%s': %s", path, sf_strerror(NULL));
        close(fd);
        return NULL;
    }
    /* the header tells the true length after every write: the file can be read
     * (and muxed into a movie) while it grows */
    sf_command(f, SFC_SET_UPDATE_HEADER_AUTO, NULL, SF_TRUE);
    return f;
}

int track_open(track **t, const char *path, char *err, size_t errlen)
{
    size_t len = strlen(path);
    track *nt = malloc(sizeof *nt + len + 1);
    if (!nt) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    nt->f = track_create(path, err, errlen);
    if (!nt->f) {
        free(nt);
        return -1;
    }
    nt->n = 0;
    memcpy(nt->path, path, len + 1);
    *t = nt;
    return 0;
}

int track_write(track *t, const int16_t *x, long n, char *err, size_t errlen)
{
    if (n <= 0) return 0;
    sf_count_t w = sf_writef_short(t->f, x, n);
    if (w > 0) t->n += (long)w;
    if (w != n) {
        snprintf(err, errlen, "cannot write '%s': %s", t->path, sf_strerror(t->f));
        return -1;
    }
    return 0;
}

long track_length(const track *t) { return t->n; }
const char *track_path(const track *t) { return t->path; }

int track_excerpt(track *t, long from, long n, const char *out, char *err, size_t errlen)
{
    sf_write_sync(t->f);
    SF_INFO in_info;
    memset(&in_info, 0, sizeof in_info);
    SNDFILE *in = sf_open(t->path, SFM_READ, &in_info);
    if (!in) {
        snprintf(err, errlen, "cannot read back '%s': %s", t->path, sf_strerror(NULL));
        return -1;
    }
    SNDFILE *o = track_create(out, err, errlen);
    if (!o) {
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
        if (a < z) {
            if (sf_seek(in, a, SEEK_SET) < 0 ||
                sf_readf_short(in, buf + 2 * (a - k), z - a) != z - a)
                rc = -1;
        }
        if (rc == 0 && sf_writef_short(o, buf, m) != m) rc = -1;
        k += m;
    }
    if (rc != 0) snprintf(err, errlen, "cannot copy the sound of '%s' to '%s'", t->path, out);
    sf_close(in);
    if (sf_close(o) != 0 && rc == 0) {
        snprintf(err, errlen, "cannot write '%s'", out);
        rc = -1;
    }
    return rc;
}

int track_close(track *t, char *err, size_t errlen)
{
    if (!t) return 0;
    int rc = 0;
    sf_write_sync(t->f);
    if (sf_close(t->f) != 0) {
        snprintf(err, errlen, "cannot finish '%s'", t->path);
        rc = -1;
    }
    free(t);
    return rc;
}
