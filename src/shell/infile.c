/* infile.c: files read whole within a size cap and a time limit, and walked line
 * by line within a line cap (infile.h). */
#include "infile.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <stdbool.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

/* (defined here, with the doors that watch it, so that they depend on no other
 * file of the shell's) */
volatile sig_atomic_t shell_interrupted;

double infile_timeout(void)
{
    const char *e = getenv("VROC_TIMEOUT");
    if (e && *e) {
        char *end;
        double t = strtod(e, &end);
        if (*end == '\0' && t > 0 && t <= 1e6) return t;
    }
    return INFILE_TIMEOUT_DEFAULT;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

void infile_free(infile *in)
{
    free(in->data);
    in->data = NULL;
    in->len = 0;
}

/* The failure of infile_read: fd closed, in emptied, why kept. */
static int read_fails(infile *in, int fd)
{
    close(fd);
    infile_free(in);
    return -1;
}

int infile_read(infile *in, const char *path, size_t max_bytes, char *why, size_t whylen)
{
    in->data = NULL;
    in->len = 0;
    /* without blocking: a named pipe with no writer does not hold the open */
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        snprintf(why, whylen, "%s", strerror(errno));
        return -1;
    }
    struct stat sb;
    if (fstat(fd, &sb) != 0) {
        snprintf(why, whylen, "%s", strerror(errno));
        return read_fails(in, fd);
    }
    if (S_ISDIR(sb.st_mode)) {
        snprintf(why, whylen, "it is a folder");
        return read_fails(in, fd);
    }
    bool regular = S_ISREG(sb.st_mode);
    if (regular && (unsigned long long)sb.st_size > max_bytes) {
        snprintf(why, whylen, "it is larger than %zu bytes", max_bytes);
        return read_fails(in, fd);
    }
    /* room for what is there and one more byte, which tells whether it grew */
    size_t cap = regular ? (size_t)sb.st_size + 1 : 65536;
    if (cap > max_bytes + 1) cap = max_bytes + 1;
    in->data = malloc(cap + 1);
    if (!in->data) {
        snprintf(why, whylen, "out of memory");
        return read_fails(in, fd);
    }
    double limit = infile_timeout(), quiet_since = now_s();
    for (;;) {
        if (shell_interrupted) {
            shell_interrupted = 0;
            snprintf(why, whylen, "interrupted");
            return read_fails(in, fd);
        }
        if (in->len == cap) {
            if (cap > max_bytes) {
                snprintf(why, whylen, "it is larger than %zu bytes", max_bytes);
                return read_fails(in, fd);
            }
            size_t nc = cap * 2 < max_bytes + 1 ? cap * 2 : max_bytes + 1;
            char *nd = realloc(in->data, nc + 1);
            if (!nd) {
                snprintf(why, whylen, "out of memory");
                return read_fails(in, fd);
            }
            in->data = nd;
            cap = nc;
        }
        if (!regular) { /* wait for bytes, a tenth of a second at a time (Ctrl-C) */
            struct pollfd p = {fd, POLLIN, 0};
            int n = poll(&p, 1, 100);
            if (n < 0 && errno != EINTR) {
                snprintf(why, whylen, "%s", strerror(errno));
                return read_fails(in, fd);
            }
            if (n <= 0) {
                if (now_s() - quiet_since >= limit) {
                    snprintf(why, whylen, "nothing came through it for %g s (a pipe no program "
                             "writes to?)", limit);
                    return read_fails(in, fd);
                }
                continue;
            }
        }
        ssize_t got = read(fd, in->data + in->len, cap - in->len);
        if (got < 0 && (errno == EINTR || errno == EAGAIN || errno == EWOULDBLOCK)) continue;
        if (got < 0) {
            snprintf(why, whylen, "%s", strerror(errno));
            return read_fails(in, fd);
        }
        if (got == 0) break;
        in->len += (size_t)got;
        quiet_since = now_s();
    }
    close(fd);
    in->data[in->len] = '\0';
    return 0;
}

void infile_lines_init(infile_lines *it, const char *data, size_t len, size_t max_line)
{
    it->p = data;
    it->end = data + len;
    it->max_line = max_line;
    it->number = 0;
}

int infile_next_line(infile_lines *it, infile_line *ln, char *why, size_t whylen)
{
    if (it->p >= it->end) return 0;
    const char *nl = memchr(it->p, '\n', (size_t)(it->end - it->p));
    const char *e = nl ? nl : it->end;
    ln->s = it->p;
    ln->len = (size_t)(e - it->p);
    ln->number = ++it->number;
    it->p = nl ? nl + 1 : it->end;
    if (ln->len > it->max_line) {
        snprintf(why, whylen, "a line longer than %zu bytes", it->max_line);
        return -1;
    }
    if (memchr(ln->s, '\0', ln->len)) {
        snprintf(why, whylen, "a NUL byte (binary file?)");
        return -1;
    }
    return 1;
}
