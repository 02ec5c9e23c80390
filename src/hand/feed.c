/* feed.c: a live tracker feed from a named pipe (feed.h). */
#include "feed.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdio.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

void feed_init(tracker_feed *f)
{
    memset(f, 0, sizeof *f);
    f->fd = -1;
}

bool feed_is_fifo(const char *path)
{
    struct stat sb;
    return stat(path, &sb) == 0 && S_ISFIFO(sb.st_mode);
}

int feed_open(tracker_feed *f, const char *path, char *err, size_t errlen)
{
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        snprintf(err, errlen, "%s: cannot open the pipe: %s", path, strerror(errno));
        return -1;
    }
    feed_close(f);
    f->fd = fd;
    snprintf(f->path, sizeof f->path, "%s", path);
    return 0;
}

void feed_close(tracker_feed *f)
{
    if (f->fd >= 0) close(f->fd);
    feed_init(f);
}

/* One complete line (its newline removed). */
static void take_line(tracker_feed *f, char *line, void (*row)(void *, const tracker_row *),
                      void (*bad)(void *, const char *), void *ctx)
{
    f->line++;
    char msg[FEED_PATH_MAX + 320], why[256];
    if (f->overlong) {
        f->overlong = false;
        snprintf(msg, sizeof msg, "%s:%ld: a line longer than %d characters", f->path, f->line,
                 FEED_LINE_MAX - 1);
        bad(ctx, msg);
        return;
    }
    if (tracker_line_kind(line) != TRACKER_DATA) return;
    tracker_row r;
    if (tracker_parse_row(line, &r, why, sizeof why) != 0 ||
        (f->have_last && tracker_check_spacing(f->last_t, r.t, why, sizeof why) != 0)) {
        snprintf(msg, sizeof msg, "%s:%ld: %s", f->path, f->line, why);
        bad(ctx, msg);
        return;
    }
    f->last_t = r.t;
    f->have_last = true;
    row(ctx, &r);
}

feed_state feed_read(tracker_feed *f, void (*row)(void *ctx, const tracker_row *r),
                     void (*bad)(void *ctx, const char *msg), void *ctx, char *err, size_t errlen)
{
    if (f->fd < 0) return FEED_ENDED;
    for (;;) {
        struct pollfd p = {f->fd, POLLIN, 0};
        if (poll(&p, 1, 0) < 0) {
            if (errno == EINTR) continue;
            snprintf(err, errlen, "%s: %s", f->path, strerror(errno));
            return FEED_FAILED;
        }
        if (!(p.revents & (POLLIN | POLLHUP | POLLERR))) return FEED_WAITING;
        char chunk[512];
        ssize_t n = read(f->fd, chunk, sizeof chunk);
        if (n < 0) {
            if (errno == EINTR) continue;
            if (errno == EAGAIN || errno == EWOULDBLOCK) return FEED_WAITING;
            snprintf(err, errlen, "%s: %s", f->path, strerror(errno));
            return FEED_FAILED;
        }
        if (n == 0) return FEED_ENDED; /* the writer went away */
        for (ssize_t i = 0; i < n; i++) {
            char c = chunk[i];
            if (c == '\n') {
                f->buf[f->len] = '\0';
                take_line(f, f->buf, row, bad, ctx);
                f->len = 0;
            } else if (f->len + 1 < sizeof f->buf) {
                f->buf[f->len++] = c == '\0' ? ' ' : c;
            } else {
                f->overlong = true;
            }
        }
    }
}
