/* child.c: the programs the views pipe pictures to, run as children (child.h). */
#define _GNU_SOURCE /* pipe2 (a descriptor the child does not inherit), sigtimedwait */
#include "child.h"

#include <errno.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <stdio.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

extern char **environ;

int child_spawn(char *const argv[], int in, int log, pid_t *pid)
{
    posix_spawn_file_actions_t fa;
    posix_spawnattr_t at;
    posix_spawn_file_actions_init(&fa);
    posix_spawnattr_init(&at);
    if (in >= 0) posix_spawn_file_actions_adddup2(&fa, in, 0);
    else posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&fa, log, 2);
    posix_spawnattr_setflags(&at, POSIX_SPAWN_SETPGROUP);
    posix_spawnattr_setpgroup(&at, 0);
    int rc = posix_spawnp(pid, argv[0], &fa, &at, argv, environ);
    posix_spawn_file_actions_destroy(&fa);
    posix_spawnattr_destroy(&at);
    return rc;
}

int child_open(char *const argv[], const char *path, pid_t *pid, int *in, int *log, char *err,
               size_t errlen)
{
    int pipefd[2] = {-1, -1};
    *log = child_log_file(path);
    int rc = *log < 0 ? errno : pipe2(pipefd, O_CLOEXEC) != 0 ? errno : 0;
    if (rc == 0) rc = child_spawn(argv, pipefd[0], *log, pid);
    if (pipefd[0] >= 0) close(pipefd[0]);
    if (rc == 0) {
        *in = pipefd[1];
        return 0;
    }
    if (rc == ENOENT)
        snprintf(err, errlen, "the %s program is not installed (not found on PATH; make deps "
                 "installs it)", argv[0]);
    else
        snprintf(err, errlen, "cannot run %s: %s", argv[0], strerror(rc));
    if (pipefd[1] >= 0) close(pipefd[1]);
    if (*log >= 0) close(*log);
    *log = -1;
    return -1;
}

int child_wait(pid_t pid)
{
    int st;
    while (waitpid(pid, &st, 0) < 0)
        if (errno != EINTR) return -1;
    return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
}

void child_beside(char *out, size_t len, const char *path, const char *prefix, const char *suffix)
{
    const char *slash = strrchr(path, '/');
    int dirlen = slash ? (int)(slash - path + 1) : 0;
    snprintf(out, len, "%.*s%s%s%s", dirlen, path, prefix, slash ? slash + 1 : path, suffix);
}

int child_log_file(const char *path)
{
    char name[4200];
    child_beside(name, sizeof name, path, ".vroc-part-", ".log");
    int fd = open(name, O_RDWR | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    if (fd >= 0) unlink(name);
    return fd;
}

int child_write(int fd, const void *data, size_t n)
{
    const unsigned char *buf = data;
    sigset_t pipe_set, old;
    sigemptyset(&pipe_set);
    sigaddset(&pipe_set, SIGPIPE);
    sigprocmask(SIG_BLOCK, &pipe_set, &old);
    int rc = 0;
    while (n > 0) {
        ssize_t w = write(fd, buf, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) {
            rc = errno ? errno : EIO;
            break;
        }
        buf += w;
        n -= (size_t)w;
    }
    if (rc == EPIPE) { /* take the SIGPIPE raised, so it is not delivered later */
        struct timespec zero = {0, 0};
        while (sigtimedwait(&pipe_set, NULL, &zero) > 0) {
        }
    }
    sigprocmask(SIG_SETMASK, &old, NULL);
    return rc;
}
