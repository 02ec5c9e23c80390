/* child.c: the programs the views pipe pictures to, run as children (child.h). */
#define _GNU_SOURCE /* pipe2 (a descriptor the child does not inherit), memfd_create, sigtimedwait */
#include "child.h"

#include <errno.h>
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "shell/infile.h"

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

int child_open(char *const argv[], pid_t *pid, int *in, int *log, char *err, size_t errlen)
{
    int pipefd[2] = {-1, -1};
    /* (at -loglevel error ffmpeg writes a line or two, and the movie ends at its
     * first; gnuplot says what it could not draw) */
    *log = memfd_create("vroc-child-log", MFD_CLOEXEC);
    int rc = *log < 0 ? errno : pipe2(pipefd, O_CLOEXEC) != 0 ? errno : 0;
    if (rc == 0) rc = child_spawn(argv, pipefd[0], *log, pid);
    if (pipefd[0] >= 0) close(pipefd[0]);
    if (rc == 0) {
        /* written without blocking: a child that stalls is seen (child_write) */
        fcntl(pipefd[1], F_SETFL, fcntl(pipefd[1], F_GETFL) | O_NONBLOCK);
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

void child_beside(char *out, size_t len, const char *path, const char *prefix, const char *suffix)
{
    const char *slash = strrchr(path, '/');
    int dirlen = slash ? (int)(slash - path + 1) : 0;
    snprintf(out, len, "%.*s%s%s%s", dirlen, path, prefix, slash ? slash + 1 : path, suffix);
}

static double clock_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* The processor time program pid has used (clock ticks), or -1. */
static long cpu_ticks(pid_t pid)
{
    char name[64], buf[1024];
    snprintf(name, sizeof name, "/proc/%ld/stat", (long)pid);
    FILE *f = fopen(name, "r");
    if (!f) return -1;
    size_t n = fread(buf, 1, sizeof buf - 1, f);
    fclose(f);
    buf[n] = '\0';
    const char *p = strrchr(buf, ')'); /* after the name, which may hold anything */
    unsigned long ut, st;
    if (!p || sscanf(p + 1, " %*c %*d %*d %*d %*d %*d %*u %*u %*u %*u %*u %lu %lu", &ut, &st) != 2)
        return -1;
    return (long)(ut + st);
}

/* Whether pid has worked since *ticks was taken (and takes it anew). */
static bool worked(pid_t pid, long *ticks)
{
    long t = cpu_ticks(pid);
    bool w = t != *ticks;
    *ticks = t;
    return w;
}

int child_write(int fd, const void *data, size_t n, pid_t pid)
{
    const unsigned char *buf = data;
    sigset_t pipe_set, old;
    sigemptyset(&pipe_set);
    sigaddset(&pipe_set, SIGPIPE);
    sigprocmask(SIG_BLOCK, &pipe_set, &old);
    double limit = infile_timeout(), since = clock_s();
    long ticks = cpu_ticks(pid);
    int rc = 0;
    while (n > 0) {
        ssize_t w = write(fd, buf, n);
        if (w > 0) {
            buf += w;
            n -= (size_t)w;
            since = clock_s();
            continue;
        }
        if (w < 0 && errno == EINTR) continue;
        if (w < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) { /* full: wait for room */
            struct pollfd pf = {fd, POLLOUT, 0};
            poll(&pf, 1, 100);
            if (clock_s() - since >= limit) {
                if (!worked(pid, &ticks)) {
                    rc = ETIMEDOUT;
                    break;
                }
                since = clock_s();
            }
            continue;
        }
        rc = w < 0 && errno ? errno : EIO;
        break;
    }
    if (rc == EPIPE) { /* take the SIGPIPE raised, so it is not delivered later */
        struct timespec zero = {0, 0};
        while (sigtimedwait(&pipe_set, NULL, &zero) > 0) {
        }
    }
    sigprocmask(SIG_SETMASK, &old, NULL);
    return rc;
}

void child_kill(pid_t pid)
{
    kill(-pid, SIGKILL);
    while (waitpid(pid, NULL, 0) < 0 && errno == EINTR) {
    }
}

int child_wait(pid_t pid)
{
    double limit = infile_timeout(), since = clock_s();
    long ticks = cpu_ticks(pid);
    for (;;) {
        int st;
        pid_t r = waitpid(pid, &st, WNOHANG);
        if (r == pid) return WIFEXITED(st) ? WEXITSTATUS(st) : -1;
        if (r < 0 && errno != EINTR) return -1;
        struct timespec nap = {0, 20 * 1000 * 1000};
        nanosleep(&nap, NULL);
        if (clock_s() - since >= limit) {
            if (!worked(pid, &ticks)) {
                child_kill(pid);
                return -2;
            }
            since = clock_s();
        }
    }
}
