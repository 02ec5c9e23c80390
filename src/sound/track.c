/* track.c: the soundtrack as a WAV file (track.h). */
#include "track.h"

#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include <sndfile.h>

#include "buf.h"

/* A file libsndfile writes through these calls of ours (its virtual I/O), so
 * that a write that fails keeps the system's reason: libsndfile's own message
 * for it does not give one we can pass on (outfile.h's rule wants "cannot write
 * 'PATH': REASON"). */
typedef struct {
    int fd;
    int err;     /* errno of the first call that failed, 0 while none has */
} track_io;

struct track {
    SNDFILE *f;
    track_io io;
    long n;          /* samples written */
    char path[];     /* as named */
};

static sf_count_t io_len(void *u)
{
    track_io *io = u;
    struct stat sb;
    if (fstat(io->fd, &sb) == 0) return (sf_count_t)sb.st_size;
    if (!io->err) io->err = errno;
    return -1;
}

static sf_count_t io_seek(sf_count_t off, int whence, void *u)
{
    track_io *io = u;
    off_t r = lseek(io->fd, (off_t)off, whence);
    if (r < 0 && !io->err) io->err = errno;
    return (sf_count_t)r;
}

static sf_count_t io_tell(void *u) { return io_seek(0, SEEK_CUR, u); }

static sf_count_t io_read(void *ptr, sf_count_t n, void *u)
{
    track_io *io = u;
    sf_count_t done = 0;
    while (done < n) {
        ssize_t r = read(io->fd, (char *)ptr + done, (size_t)(n - done));
        if (r < 0 && errno == EINTR) continue;
        if (r < 0 && !io->err) io->err = errno;
        if (r <= 0) break;
        done += r;
    }
    return done;
}

static sf_count_t io_write(const void *ptr, sf_count_t n, void *u)
{
    track_io *io = u;
    sf_count_t done = 0;
    while (done < n) {
        ssize_t w = write(io->fd, (const char *)ptr + done, (size_t)(n - done));
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) {
            if (!io->err) io->err = w < 0 ? errno : EIO;
            break;
        }
        done += w;
    }
    return done;
}

static SF_VIRTUAL_IO track_vio = {io_len, io_seek, io_read, io_write, io_tell};

/* "cannot write 'path': REASON", the system's reason when one is known. */
static int track_failed(const track_io *io, const char *path, const char *sf_why, char *err,
                        size_t errlen)
{
    if (io->err || !sf_why) snprintf(err, errlen, "cannot write '%s': %s", path,
                                     strerror(io->err ? io->err : EIO));
    else snprintf(err, errlen, "cannot write '%s': %s", path, sf_why);
    return -1;
}

/* Creates (or empties) path and starts a WAV file there through io; NULL with a
 * message in err. */
static SNDFILE *track_create(track_io *io, const char *path, char *err, size_t errlen)
{
    io->err = 0;
    io->fd = open(path, O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
    if (io->fd < 0) {
        snprintf(err, errlen, "cannot write '%s': %s", path, strerror(errno));
        return NULL;
    }
    SF_INFO info;
    memset(&info, 0, sizeof info);
    info.samplerate = SOUND_RATE;
    info.channels = 2;
    info.format = SF_FORMAT_WAV | SF_FORMAT_PCM_16;
    SNDFILE *f = sf_open_virtual(&track_vio, SFM_WRITE, &info, io);
    if (!f || io->err) { /* (libsndfile may not notice that its header failed) */
        track_failed(io, path, sf_strerror(NULL), err, errlen);
        if (f) sf_close(f);
        close(io->fd);
        return NULL;
    }
    /* the header tells the true length after every write: the file can be read
     * (and muxed into a movie) while it grows */
    sf_command(f, SFC_SET_UPDATE_HEADER_AUTO, NULL, SF_TRUE);
    return f;
}

/* Finishes f (libsndfile writes the last header) and closes io's file.  0, or
 * -1 with the message. */
static int track_finish(SNDFILE *f, track_io *io, const char *path, char *err, size_t errlen)
{
    int rc = sf_close(f) != 0 || io->err ? track_failed(io, path, NULL, err, errlen) : 0;
    if (close(io->fd) != 0 && rc == 0) {
        io->err = errno;
        rc = track_failed(io, path, NULL, err, errlen);
    }
    return rc;
}

int track_open(track **t, const char *path, char *err, size_t errlen)
{
    size_t len = strlen(path);
    track *nt = malloc(sizeof *nt + len + 1);
    if (!nt) {
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    nt->f = track_create(&nt->io, path, err, errlen);
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
    if (w != n || t->io.err) return track_failed(&t->io, t->path, sf_strerror(t->f), err, errlen);
    return 0;
}

long track_length(const track *t) { return t->n; }
const char *track_path(const track *t) { return t->path; }

int track_excerpt(track *t, long from, long n, const char *out, char *err, size_t errlen)
{
    SF_INFO in_info;
    memset(&in_info, 0, sizeof in_info);
    SNDFILE *in = sf_open(t->path, SFM_READ, &in_info);
    if (!in) {
        snprintf(err, errlen, "cannot read back '%s': %s", t->path, sf_strerror(NULL));
        return -1;
    }
    track_io io;
    SNDFILE *o = track_create(&io, out, err, errlen);
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
        if (a < z && (sf_seek(in, a, SEEK_SET) < 0 ||
                      sf_readf_short(in, buf + 2 * (a - k), z - a) != z - a)) {
            snprintf(err, errlen, "cannot read back '%s': %s", t->path, sf_strerror(in));
            rc = -1;
        }
        if (rc == 0 && sf_writef_short(o, buf, m) != m)
            rc = track_failed(&io, out, sf_strerror(o), err, errlen);
        k += m;
    }
    sf_close(in);
    char why[512];
    if (track_finish(o, &io, out, why, sizeof why) != 0 && rc == 0) {
        snprintf(err, errlen, "%s", why);
        rc = -1;
    }
    return rc;
}

int track_close(track *t, char *err, size_t errlen)
{
    if (!t) return 0;
    int rc = track_finish(t->f, &t->io, t->path, err, errlen);
    free(t);
    return rc;
}
