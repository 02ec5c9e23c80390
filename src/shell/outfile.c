/* outfile.c: the check every file vroc writes goes through (outfile.h). */
#include "outfile.h"

#include <errno.h>
#include <string.h>

/* The message of a failed write; errno as the failing call left it, or EIO when
 * the failure was an earlier write's and nothing says why any more. */
static int failed(const char *path, int e, char *err, size_t errlen)
{
    snprintf(err, errlen, "cannot write '%s': %s", path, strerror(e ? e : EIO));
    return -1;
}

int outfile_flush(FILE *f, const char *path, char *err, size_t errlen)
{
    errno = 0;
    if (fflush(f) != 0 || ferror(f)) return failed(path, errno, err, errlen);
    return 0;
}

int outfile_close(FILE *f, const char *path, char *err, size_t errlen)
{
    if (!f) return 0;
    int rc = outfile_flush(f, path, err, errlen);
    errno = 0;
    if (fclose(f) != 0 && rc == 0) rc = failed(path, errno, err, errlen);
    return rc;
}
