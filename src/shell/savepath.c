/* savepath.c: the paths a saved world writes (savepath.h). */
#include "savepath.h"

#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

/* The absolute form of path into out (PATH_MAX bytes): its real path when it
 * exists, else the current folder joined to it.  Returns 0, or -1 when it does
 * not fit. */
static int absolute(const char *path, char *out)
{
    if (realpath(path, out)) return 0;
    if (path[0] == '/') return snprintf(out, PATH_MAX, "%s", path) < PATH_MAX ? 0 : -1;
    char cwd[PATH_MAX];
    if (!getcwd(cwd, sizeof cwd)) return -1;
    return snprintf(out, PATH_MAX, "%s/%s", cwd, path) < PATH_MAX ? 0 : -1;
}

const char *savepath(const char *path, const char *save_file, char *out, size_t len)
{
    char file[PATH_MAX], dir[PATH_MAX];
    if (absolute(path, file) != 0) return path;
    /* the saved file's folder: what comes before its last '/' */
    const char *slash = strrchr(save_file, '/');
    if (!slash) snprintf(dir, sizeof dir, ".");
    else if (slash == save_file) snprintf(dir, sizeof dir, "/");
    else snprintf(dir, sizeof dir, "%.*s", (int)(slash - save_file), save_file);
    char folder[PATH_MAX];
    size_t n = 0;
    if (absolute(dir, folder) == 0) {
        n = strlen(folder);
        if (n > 0 && folder[n - 1] == '/') n--; /* (the root) */
    }
    const char *rest = n > 0 && strncmp(file, folder, n) == 0 && file[n] == '/' ? file + n + 1 : file;
    if (!rest[0] || (size_t)snprintf(out, len, "%s", rest) >= len) return path;
    return out;
}
