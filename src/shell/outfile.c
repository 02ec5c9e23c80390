/* outfile.c: the door every file vroc writes goes through: checks, files written
 * beside and put in place, pipes to programs that may stall (outfile.h). */
#include "outfile.h"

#include <errno.h>
#include <fcntl.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

int outfile_failed(const char *path, int e, char *err, size_t errlen)
{
    snprintf(err, errlen, "cannot write '%s': %s", path, strerror(e ? e : EIO));
    return -1;
}

bool outfile_sandboxed(void)
{
    const char *box = getenv("VROC_SANDBOX");
    return box && *box;
}

/* True when the part of path that exists (path, or its nearest folder that does)
 * resolves to root or below it. */
static bool resolves_below(const char *path, const char *root)
{
    char buf[PATH_MAX], real[PATH_MAX];
    if (strlen(path) >= sizeof buf) return false;
    strcpy(buf, path);
    while (!realpath(buf[0] ? buf : ".", real)) {
        if (errno != ENOENT && errno != ENOTDIR) return false;
        char *slash = strrchr(buf, '/');
        if (!slash) buf[0] = '\0';
        else *slash = '\0';
    }
    size_t n = strlen(root);
    return strncmp(real, root, n) == 0 && (real[n] == '\0' || real[n] == '/' || n == 1);
}

int outfile_allowed(const char *path, char *err, size_t errlen)
{
    if (!outfile_sandboxed()) return 0;
    bool up = false;
    for (const char *p = path; *p;) {
        size_t n = strcspn(p, "/");
        if (n == 2 && p[0] == '.' && p[1] == '.') up = true;
        p += n;
        while (*p == '/') p++;
    }
    char root[PATH_MAX];
    if (path[0] != '/' && !up) {
        if (realpath(".", root) && resolves_below(path, root)) return 0;
        snprintf(err, errlen, "'%s' leads outside the current folder through a link, and "
                 "VROC_SANDBOX allows writing only below it", path);
        return -1;
    }
    snprintf(err, errlen, "'%s' is outside the current folder, and VROC_SANDBOX allows writing "
             "only below it", path);
    return -1;
}

int outfile_flush(FILE *f, const char *path, char *err, size_t errlen)
{
    errno = 0;
    if (fflush(f) != 0 || ferror(f)) return outfile_failed(path, errno, err, errlen);
    return 0;
}

int outfile_close(FILE *f, const char *path, char *err, size_t errlen)
{
    if (!f) return 0;
    int rc = outfile_flush(f, path, err, errlen);
    errno = 0;
    if (fclose(f) != 0 && rc == 0) rc = outfile_failed(path, errno, err, errlen);
    return rc;
}

/* ---- writing beside, then in place ---- */

/* The mode a new file gets: 0666 less the umask. */
static mode_t new_mode(void)
{
    mode_t m = umask(0);
    umask(m);
    return 0666 & ~m;
}

/* Opens a new part file beside o->path, DIR/.vroc-part-XXXXXX-NAME (NAME's last
 * 200 bytes: the extension ffmpeg reads the format from stays).  0 or an errno. */
static int open_part(outfile *o, mode_t mode)
{
    const char *slash = strrchr(o->path, '/');
    const char *base = slash ? slash + 1 : o->path;
    size_t dirlen = slash ? (size_t)(slash - o->path + 1) : 0, blen = strlen(base);
    if (blen > 200) base += blen - 200;
    int n = snprintf(o->part, sizeof o->part, "%.*s.vroc-part-XXXXXX-%s", (int)dirlen, o->path, base);
    if (n < 0 || (size_t)n >= sizeof o->part) return ENAMETOOLONG;
    int fd = mkstemps(o->part, (int)strlen(base) + 1);
    if (fd < 0) {
        int e = errno;
        o->part[0] = '\0';
        return e;
    }
    fcntl(fd, F_SETFD, FD_CLOEXEC); /* (no program vroc runs inherits it) */
    /* (where the system allows no such mode, mkstemp's 0600 stays) */
    fchmod(fd, mode);
    o->fd = fd;
    return 0;
}

int outfile_begin(outfile *o, const char *path, unsigned flags, char *err, size_t errlen)
{
    o->f = NULL;
    o->fd = -1;
    o->part[0] = '\0';
    if (outfile_allowed(path, err, errlen) != 0) return -1;
    if (strlen(path) >= sizeof o->path) {
        snprintf(err, errlen, "cannot write '%.60s...': the path is too long", path);
        return -1;
    }
    strcpy(o->path, path);
    struct stat sb;
    bool exists = lstat(path, &sb) == 0;
    /* a link: the file it names is replaced, and the link stays (not in the
     * sandbox, where nothing is followed) */
    if (exists && S_ISLNK(sb.st_mode) && !outfile_sandboxed()) {
        char real[PATH_MAX];
        if (realpath(path, real) && stat(real, &sb) == 0) strcpy(o->path, real);
        else exists = false; /* a link to nothing: made in its place */
    }
    if (exists && S_ISDIR(sb.st_mode)) {
        snprintf(err, errlen, "cannot write '%s': it is a folder", path);
        return -1;
    }
    bool in_place = exists && !S_ISREG(sb.st_mode) && !S_ISLNK(sb.st_mode);
    if (in_place && (flags & OUTFILE_REGULAR)) {
        snprintf(err, errlen, "cannot write '%s': not a regular file (it is made beside it, then "
                 "put in its place)", path);
        return -1;
    }
    if (in_place && (flags & OUTFILE_SEEK) && (S_ISFIFO(sb.st_mode) || S_ISSOCK(sb.st_mode))) {
        snprintf(err, errlen, "cannot write '%s': a named pipe (the file is rewritten as it grows)",
                 path);
        return -1;
    }
    int e = 0;
    if (in_place) {
        /* without blocking: a named pipe that no program reads is refused (ENXIO) */
        o->fd = open(path, O_WRONLY | O_NONBLOCK | O_CLOEXEC | (outfile_sandboxed() ? O_NOFOLLOW : 0));
        if (o->fd < 0) e = errno;
        else fcntl(o->fd, F_SETFL, fcntl(o->fd, F_GETFL) & ~O_NONBLOCK);
    } else {
        e = open_part(o, exists && S_ISREG(sb.st_mode) ? (sb.st_mode & 07777) : new_mode());
    }
    if (e == ENXIO) {
        snprintf(err, errlen, "cannot write '%s': no program reads the named pipe", path);
        return -1;
    }
    if (e != 0) return outfile_failed(path, e, err, errlen);
    if ((flags & OUTFILE_STREAM) && !(o->f = fdopen(o->fd, "w"))) {
        e = errno;
        outfile_abort(o);
        return outfile_failed(path, e, err, errlen);
    }
    return 0;
}

const char *outfile_now(const outfile *o)
{
    return o->part[0] ? o->part : o->path;
}

void outfile_abort(outfile *o)
{
    if (o->f) fclose(o->f);
    else if (o->fd >= 0) close(o->fd);
    o->f = NULL;
    o->fd = -1;
    if (o->part[0]) unlink(o->part);
    o->part[0] = '\0';
}

/* The part file to its place: 0, or -1 with the message (and the part removed). */
static int put_in_place(outfile *o, char *err, size_t errlen)
{
    if (!o->part[0]) return 0;
    if (rename(o->part, o->path) != 0) {
        int e = errno;
        unlink(o->part);
        o->part[0] = '\0';
        return outfile_failed(o->path, e, err, errlen);
    }
    o->part[0] = '\0';
    return 0;
}

int outfile_place(outfile *o, char *err, size_t errlen)
{
    if (o->f && outfile_flush(o->f, o->path, err, errlen) != 0) {
        outfile_abort(o);
        return -1;
    }
    if (put_in_place(o, err, errlen) != 0) {
        outfile_abort(o);
        return -1;
    }
    return 0;
}

int outfile_finish(outfile *o, char *err, size_t errlen)
{
    int rc;
    if (o->f) {
        rc = outfile_close(o->f, o->path, err, errlen);
    } else {
        errno = 0;
        rc = o->fd >= 0 && close(o->fd) != 0 ? outfile_failed(o->path, errno, err, errlen) : 0;
    }
    o->f = NULL;
    o->fd = -1;
    if (rc != 0) {
        outfile_abort(o);
        return -1;
    }
    return put_in_place(o, err, errlen);
}
