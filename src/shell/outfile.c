/* outfile.c: the check every file vroc writes goes through (outfile.h). */
#include "outfile.h"

#include <errno.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>

int outfile_failed(const char *path, int e, char *err, size_t errlen)
{
    snprintf(err, errlen, "cannot write '%s': %s", path, strerror(e ? e : EIO));
    return -1;
}

int outfile_allowed(const char *path, char *err, size_t errlen)
{
    const char *box = getenv("VROC_SANDBOX");
    if (!box || !*box) return 0;
    bool up = false;
    for (const char *p = path; *p;) {
        size_t n = strcspn(p, "/");
        if (n == 2 && p[0] == '.' && p[1] == '.') up = true;
        p += n;
        while (*p == '/') p++;
    }
    if (path[0] != '/' && !up) return 0;
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
