/* movie.c: frames piped to the ffmpeg program, and the sound muxed in (movie.h). */
#include "movie.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>
#include <sys/stat.h>
#include <unistd.h>

#include "child.h"
#include "shell/infile.h"
#include "shell/outfile.h"

struct movie {
    pid_t pid;              /* the encoding ffmpeg */
    int fd;                 /* the pipe to its standard input (non-blocking) */
    int log;                /* its messages (a file in memory) */
    stereo_mode mode;
    int eye_w, eye_h;       /* one eye's pixels in the movie */
    int w, h;               /* the frame, even */
    double period;
    long frames;
    unsigned char *frame;   /* w x h RGB */
    char path[VIEW_PATH_MAX];
    outfile video;          /* the video being encoded, beside the movie */
    char sound[VIEW_PATH_MAX + 32]; /* where the sound to mux goes */
};

void movie_size(stereo_mode mode, int eye_w, int eye_h, int *w, int *h)
{
    int cw = mode == STEREO_PAIR || mode == STEREO_SBS ? 2 * eye_w : eye_w;
    *w = cw + (cw & 1);
    *h = eye_h + (eye_h & 1);
}

int movie_needs_right(const movie *m) { return m->mode != STEREO_MONO; }
long movie_frames(const movie *m) { return m->frames; }
double movie_period(const movie *m) { return m->period; }
const char *movie_path(const movie *m) { return m->path; }
const char *movie_sound_path(const movie *m) { return m->sound; }

/* The extension of path's last component (after its last dot), or NULL. */
static const char *movie_ext(const char *path)
{
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    const char *dot = strrchr(base, '.');
    return dot && dot != base && dot[1] ? dot + 1 : NULL;
}

static bool ext_is(const char *ext, const char *list)
{
    char one[16];
    for (const char *p = list; *p;) {
        size_t n = strcspn(p, " ");
        snprintf(one, sizeof one, "%.*s", (int)n, p);
        if (strcasecmp(ext, one) == 0) return true;
        p += n;
        while (*p == ' ') p++;
    }
    return false;
}

/* The system's reason that ends a line of ffmpeg's ("av_interleaved_write_frame():
 * File too large": ffmpeg ends a failed call's message with strerror's text), or
 * NULL.  EINVAL is not one: ffmpeg gives it for any input it refuses ("Unable to
 * find a suitable output format", then "...: Invalid argument"), and its own
 * line says more. */
static const char *movie_line_reason(const char *line, size_t k)
{
    for (int e = 1; e < 134; e++) { /* the errno values Linux has */
        if (e == EINVAL) continue;
        const char *why = strerror(e);
        size_t w = strlen(why);
        if (k >= w + 2 && memcmp(line + k - w, why, w) == 0 && line[k - w - 2] == ':' &&
            line[k - w - 1] == ' ')
            return why;
    }
    return NULL;
}

/* What ffmpeg wrote to its log from offset from, for a message: the system's
 * reason when a line ends with one (0 is returned), else its first line, its
 * first complaint (-1; "" when it wrote nothing). */
static int movie_complaint(int fd, off_t from, char *out, size_t len)
{
    char buf[4096];
    out[0] = '\0';
    ssize_t n = pread(fd, buf, sizeof buf - 1, from);
    if (n <= 0) return -1;
    buf[n] = '\0';
    for (const char *line = buf; *line;) {
        size_t k = strcspn(line, "\r\n");
        const char *why = movie_line_reason(line, k);
        if (why) {
            snprintf(out, len, "%s", why);
            return 0;
        }
        line += k;
        line += strspn(line, "\r\n");
    }
    const char *line = buf;
    if (line[0] == '[' && strstr(line, "] ")) line = strstr(line, "] ") + 2; /* "[mp4 @ 0x..] " */
    size_t k = strcspn(line, "\r\n");
    snprintf(out, len, "%.*s", (int)(k < 500 ? k : 500), line);
    return -1;
}

/* The message of a movie ffmpeg could not write, from its log since offset from:
 * "cannot write 'PATH': REASON" when the system said why, else ffmpeg's first
 * complaint, or fallback when it wrote none.  Returns -1. */
static int movie_failed(const movie *m, off_t from, const char *fallback, char *err,
                        size_t errlen)
{
    char why[512];
    if (movie_complaint(m->log, from, why, sizeof why) == 0)
        snprintf(err, errlen, "cannot write '%s': %s", m->path, why);
    else
        snprintf(err, errlen, "ffmpeg could not write '%s': %s", m->path,
                 why[0] ? why : fallback);
    return -1;
}

/* The message of an ffmpeg that stopped working before it finished: -1. */
static int movie_stalled(char *err, size_t errlen)
{
    snprintf(err, errlen, "ffmpeg did no work for %g s before it finished: it is stopped "
             "(VROC_TIMEOUT sets how long vroc waits)", infile_timeout());
    return -1;
}

/* How much ffmpeg has written to its log so far. */
static off_t movie_log_size(const movie *m)
{
    struct stat sb;
    return fstat(m->log, &sb) == 0 ? sb.st_size : 0;
}

/* The frame rate 1 / period as a fraction ffmpeg reads exactly when it is one with
 * a small denominator (10, 30000/1001), else to a millionth of a second. */
static void movie_rate(double period, char *out, size_t len)
{
    double rate = 1.0 / period;
    for (long den = 1; den <= 1001; den++) {
        double num = round(rate * (double)den);
        if (num >= 1 && fabs(num / (double)den - rate) <= 1e-9 * rate) {
            snprintf(out, len, "%.0f/%ld", num, den);
            return;
        }
    }
    snprintf(out, len, "1000000/%lld", llround(period * 1e6));
}

int movie_open(movie **mp, const char *path, const view_settings *vs, double period, char *err,
               size_t errlen)
{
    /* (what the path is, first: it is made beside it, then put in its place) */
    struct stat sb;
    if (stat(path, &sb) == 0 && !S_ISREG(sb.st_mode)) {
        snprintf(err, errlen, "cannot write '%s': not a regular file (a movie is made beside "
                 "it, then put in its place)", path);
        return -1;
    }
    const char *ext = movie_ext(path);
    if (!ext) {
        snprintf(err, errlen, "'%s' has no extension to name its format (such as .mp4)", path);
        return -1;
    }
    if (!(period > 0) || !isfinite(period)) {
        snprintf(err, errlen, "a movie's picture lasts %g s: it must be > 0", period);
        return -1;
    }
    if (strlen(path) >= VIEW_PATH_MAX) {
        snprintf(err, errlen, "the path '%.40s...' is too long", path);
        return -1;
    }
    movie *m = calloc(1, sizeof *m);
    if (m) {
        m->mode = vs->stereo;
        m->eye_w = vs->image_w;
        m->eye_h = vs->image_h;
        movie_size(m->mode, m->eye_w, m->eye_h, &m->w, &m->h);
        m->frame = malloc((size_t)m->w * (size_t)m->h * 3);
    }
    if (!m || !m->frame) {
        if (m) free(m);
        snprintf(err, errlen, "out of memory");
        return -1;
    }
    /* the video is encoded beside the movie (ffmpeg writes it by name), which it
     * replaces only once finished: a path that is a device or a pipe is refused */
    if (outfile_begin(&m->video, path, OUTFILE_REGULAR, err, errlen) != 0) {
        free(m->frame);
        free(m);
        return -1;
    }
    close(m->video.fd);
    m->video.fd = -1;
    m->period = period;
    snprintf(m->path, sizeof m->path, "%s", path);
    child_beside(m->sound, sizeof m->sound, path, ".vroc-part-", ".wav");

    char size[32], rate[48];
    snprintf(size, sizeof size, "%dx%d", m->w, m->h);
    movie_rate(period, rate, sizeof rate);
    const char *argv[40];
    int a = 0;
    const char *head[] = {"ffmpeg", "-nostdin", "-hide_banner", "-loglevel", "error", "-y",
                          "-f", "rawvideo", "-pix_fmt", "rgb24", "-video_size", size,
                          "-framerate", rate, "-i", "pipe:0"};
    for (size_t i = 0; i < sizeof head / sizeof head[0]; i++) argv[a++] = head[i];
    if (ext_is(ext, "mp4 m4v mov mkv")) {
        const char *h264[] = {"-c:v", "libx264", "-preset", "veryfast", "-crf", "18",
                              "-pix_fmt", "yuv420p"};
        for (size_t i = 0; i < sizeof h264 / sizeof h264[0]; i++) argv[a++] = h264[i];
    }
    /* each frame written out as it is encoded, so that a write that fails is
     * known while time runs, not only when the movie closes */
    argv[a++] = "-flush_packets";
    argv[a++] = "1";
    argv[a++] = outfile_now(&m->video);
    argv[a] = NULL;

    if (child_open((char *const *)argv, &m->pid, &m->fd, &m->log, err, errlen) != 0) {
        outfile_abort(&m->video);
        free(m->frame);
        free(m);
        return -1;
    }
    *mp = m;
    return 0;
}

/* Lays the eyes out in m->frame: each movie pixel from the nearest eye pixel (the
 * same one when the sizes agree), the padding repeating the last column and row. */
static void movie_compose(movie *m, const unsigned char *eye[2], int sw, int sh)
{
    int cw = m->mode == STEREO_PAIR || m->mode == STEREO_SBS ? 2 * m->eye_w : m->eye_w;
    for (int y = 0; y < m->h; y++) {
        int yy = y < m->eye_h ? y : m->eye_h - 1;
        size_t sy = (size_t)((long)yy * sh / m->eye_h);
        unsigned char *row = m->frame + (size_t)y * (size_t)m->w * 3;
        for (int x = 0; x < m->w; x++) {
            int xx = x < cw ? x : cw - 1;
            int k = xx >= m->eye_w ? 1 : 0; /* the eye of a side-by-side pixel */
            int ex = xx - k * m->eye_w;
            size_t sx = (size_t)((long)ex * sw / m->eye_w);
            size_t at = (sy * (size_t)sw + sx) * 3;
            unsigned char *o = row + (size_t)x * 3;
            if (m->mode == STEREO_ANAGLYPH) {
                view_anaglyph_pixel(eye[0] + at, eye[1] + at, o);
            } else {
                memcpy(o, eye[k] + at, 3);
            }
        }
    }
}

int movie_add(movie *m, const view *v, long copies, char *err, size_t errlen)
{
    if (copies <= 0) return 0;
    int sw, sh, sw1, sh1;
    const unsigned char *eye[2] = {view_pixels(v, 0, &sw, &sh), NULL};
    eye[1] = movie_needs_right(m) ? view_pixels(v, 1, &sw1, &sh1) : eye[0];
    if (!eye[0] || !eye[1]) {
        snprintf(err, errlen, "no image of the %s eye to add", eye[0] ? "right" : "left");
        return -1;
    }
    movie_compose(m, eye, sw, sh);
    size_t bytes = (size_t)m->w * (size_t)m->h * 3;
    for (long i = 0; i < copies; i++) {
        int rc = child_write(m->fd, m->frame, bytes, m->pid);
        if (rc == ETIMEDOUT) {
            snprintf(err, errlen, "ffmpeg took no frame and did no work for %g s: it is stopped "
                     "(VROC_TIMEOUT sets how long vroc waits)", infile_timeout());
            return -1;
        }
        if (rc != 0) return movie_failed(m, 0, strerror(rc), err, errlen);
        m->frames++;
    }
    /* ffmpeg logs only errors, and goes on after a failed write: the first
     * line it logs ends the movie */
    if (movie_log_size(m) > 0) return movie_failed(m, 0, "", err, errlen);
    return 0;
}

/* Muxes the video and the WAV file wav into a file beside the movie, which then
 * replaces it.  Returns 0, or -1 with a message (nothing is left of the muxed
 * file). */
static int movie_mux(movie *m, const char *wav, char *err, size_t errlen)
{
    outfile muxed;
    if (outfile_begin(&muxed, m->path, OUTFILE_REGULAR, err, errlen) != 0) return -1;
    close(muxed.fd);
    muxed.fd = -1;
    const char *ext = movie_ext(m->path);
    const char *argv[32];
    int a = 0;
    const char *head[] = {"ffmpeg", "-nostdin", "-hide_banner", "-loglevel", "error", "-y",
                          "-i", outfile_now(&m->video), "-i", wav, "-map", "0:v:0", "-map", "1:a:0",
                          "-c:v", "copy"};
    for (size_t i = 0; i < sizeof head / sizeof head[0]; i++) argv[a++] = head[i];
    if (ext && ext_is(ext, "mp4 m4v mov")) {
        const char *aac[] = {"-c:a", "aac", "-b:a", "192k", "-movflags", "+faststart"};
        for (size_t i = 0; i < sizeof aac / sizeof aac[0]; i++) argv[a++] = aac[i];
    }
    argv[a++] = outfile_now(&muxed);
    argv[a] = NULL;
    off_t from = movie_log_size(m);
    pid_t pid;
    int rc = child_spawn((char *const *)argv, -1, m->log, &pid);
    if (rc != 0) {
        outfile_abort(&muxed);
        snprintf(err, errlen, "cannot run ffmpeg: %s", strerror(rc));
        return -1;
    }
    /* (ffmpeg may exit with 0 after a write that failed: what it logged counts) */
    int st = child_wait(pid);
    if (st != 0 || movie_log_size(m) > from) {
        outfile_abort(&muxed);
        if (st == -2) return movie_stalled(err, errlen);
        return movie_failed(m, from, "it failed", err, errlen);
    }
    return outfile_finish(&muxed, err, errlen);
}

int movie_close(movie *m, const char *wav, char *err, size_t errlen)
{
    if (!m) return 0;
    close(m->fd);
    int st = child_wait(m->pid);
    int rc = 0;
    if (m->frames == 0) {
        outfile_abort(&m->video);
    } else if (st != 0 || movie_log_size(m) > 0) { /* (see movie_mux) */
        if (st == -2) movie_stalled(err, errlen);
        else movie_failed(m, 0, "it failed", err, errlen);
        outfile_abort(&m->video);
        rc = -1;
    } else if (wav) { /* the movie is its video and its sound, or nothing */
        rc = movie_mux(m, wav, err, errlen);
        outfile_abort(&m->video);
    } else {
        rc = outfile_finish(&m->video, err, errlen);
    }
    unlink(m->sound); /* (made or not) */
    close(m->log);
    free(m->frame);
    free(m);
    return rc;
}

void movie_abort(movie *m)
{
    if (!m) return;
    close(m->fd);
    child_kill(m->pid);
    outfile_abort(&m->video);
    unlink(m->sound);
    close(m->log);
    free(m->frame);
    free(m);
}
