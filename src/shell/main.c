/* main.c: vroc's command line (language.md, "Invocation").
 *
 *   vroc [-b] [-q] [-v] [-o DIR] [-c COMMANDS] [FILE ...]
 *
 * Runs each FILE, then the -c commands, then gives the prompt when standard input
 * is a terminal (readline), or reads statements from standard input otherwise; -b
 * never reads standard input.  With -b, or when input is not a terminal, the first
 * error ends the run with status 1.  Status 2: a bad command line.
 */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "fmt.h"
#include "outfile.h"
#include "shell.h"

static void usage(FILE *f)
{
    fprintf(f,
            "usage: vroc [-b] [-q] [-v] [-o DIR] [-c COMMANDS] [FILE ...]\n"
            "  -b           batch: run the files and -c commands, then exit (no prompt)\n"
            "  -q           quiet: no banner and no informational messages\n"
            "  -v           verbose: show the progress of long runs in batch too\n"
            "  -o DIR       write frames into DIR (the output setting)\n"
            "  -c COMMANDS  run COMMANDS after the files (may be given more than once)\n"
            "  --help       this text\n"
            "  --version    the version\n"
            "At the prompt, help lists the commands; man vroc tells all.\n");
}

/* status, or 1 after a message when what was written to the standard output did
 * not all arrive (a write that fails is never silent: --help > /dev/full). */
static int stdout_checked(int status)
{
    errno = 0;
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "error: cannot write the standard output: %s\n",
                strerror(errno ? errno : EIO));
        return 1;
    }
    return status;
}

static bool is_dir(const char *p)
{
    struct stat sb;
    return stat(p, &sb) == 0 && S_ISDIR(sb.st_mode);
}

/* The scenes folder: $VROC_SCENES, else the installed one, else share/vroc/scenes
 * beside the executable's folder (an installation moved elsewhere, or under
 * DESTDIR), else scenes/ beside the executable (an uninstalled build). */
static const char *scene_dir(char *buf, size_t len)
{
    const char *env = getenv("VROC_SCENES");
    if (env && *env) return env;
    if (is_dir(VROC_SCENEDIR)) return VROC_SCENEDIR;
    char exe[4096];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n > 0) {
        exe[n] = '\0';
        char *slash = strrchr(exe, '/');
        if (slash) {
            *slash = '\0';
            snprintf(buf, len, "%s/../share/vroc/scenes", exe);
            if (is_dir(buf)) return buf;
            snprintf(buf, len, "%s/scenes", exe);
            if (is_dir(buf)) return buf;
        }
    }
    return NULL;
}

int main(int argc, char **argv)
{
    bool batch = false, quiet = false, verbose = false;
    const char *outdir = NULL;
    const char **cmds = calloc((size_t)argc, sizeof *cmds);
    const char **files = calloc((size_t)argc, sizeof *files);
    int ncmds = 0, nfiles = 0;
    if (!cmds || !files) return 1;
    bool options = true;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (options && strcmp(a, "--") == 0) options = false;
        else if (options && (strcmp(a, "--help") == 0 || strcmp(a, "--version") == 0)) {
            if (a[2] == 'h') usage(stdout);
            else printf("vroc %s\n", VROC_VERSION);
            free(cmds);
            free(files);
            return stdout_checked(0);
        } else if (options && a[0] == '-' && a[1] != '\0') {
            for (const char *p = a + 1; *p; p++) {
                if (*p == 'b') batch = true;
                else if (*p == 'q') quiet = true;
                else if (*p == 'v') verbose = true;
                else if (*p == 'o' || *p == 'c') {
                    const char *val = p[1] ? p + 1 : (i + 1 < argc ? argv[++i] : NULL);
                    if (!val) {
                        fprintf(stderr, "vroc: -%c needs a value\n", *p);
                        usage(stderr);
                        free(cmds);
                        free(files);
                        return 2;
                    }
                    if (*p == 'o') outdir = val;
                    else cmds[ncmds++] = val;
                    break;
                } else {
                    char opt[3] = {'-', *p, '\0'};
                    fprintf(stderr, "vroc: unknown option ");
                    fmt_escaped(stderr, opt); /* (a byte of the command line) */
                    fputc('\n', stderr);
                    usage(stderr);
                    free(cmds);
                    free(files);
                    return 2;
                }
            }
        } else {
            files[nfiles++] = a;
        }
    }

    shell sh;
    shell_init(&sh, stdout, stderr);
    char scenes[4200];
    sh.scene_dir = scene_dir(scenes, sizeof scenes);
    sh.quiet = quiet;
    sh.verbose = verbose;
    bool tty = isatty(STDIN_FILENO) && isatty(STDOUT_FILENO);
    sh.interactive = !batch && tty;
    sh.stop_on_error = batch || !isatty(STDIN_FILENO);
    char why[1200];
    /* -o is the output setting: what `output =` would refuse, it refuses (show and
     * save write it back as a statement) */
    if (outdir && (!*outdir || strlen(outdir) >= sizeof sh.view_set.output || strchr(outdir, '\n'))) {
        fprintf(stderr, "vroc: -o: %s\n", !*outdir ? "the folder name is empty"
                                         : strchr(outdir, '\n') ? "a folder name has no newline"
                                                                 : "the folder name is too long");
        free(cmds);
        free(files);
        shell_free(&sh);
        return 2;
    }
    if (outdir && outfile_allowed(outdir, why, sizeof why) != 0) {
        fprintf(stderr, "vroc: -o: ");
        fmt_escaped(stderr, why);
        fputc('\n', stderr);
        free(cmds);
        free(files);
        shell_free(&sh);
        return 2;
    }
    if (outdir) {
        snprintf(sh.view_set.output, sizeof sh.view_set.output, "%s", outdir);
        sh.startup.view = sh.view_set;
    }

    shell_catch_sigint(); /* a long run stops at Ctrl-C, its outputs finished */
    int status = 0;
    bool quit = false;
    for (int i = 0; i < nfiles && !quit; i++) {
        cmd_status r = shell_run_file(&sh, files[i]);
        if (r == CMD_QUIT) quit = true;
        if (r == CMD_ERROR && sh.stop_on_error) {
            status = 1;
            quit = true;
        }
    }
    for (int i = 0; i < ncmds && !quit; i++) {
        cmd_status r = shell_run_text(&sh, cmds[i], NULL);
        if (r == CMD_QUIT) quit = true;
        if (r == CMD_ERROR && sh.stop_on_error) {
            status = 1;
            quit = true;
        }
    }
    if (!quit && !batch) {
        if (sh.interactive && !quiet)
            printf("vroc %s: virtual and real object collisions. Type help for the commands;\n"
                   "quit or Ctrl-D leaves.\n",
                   VROC_VERSION);
        status = shell_loop(&sh);
    }
    /* the logs' last rows and standard output are checked too: a write that
     * failed is never silent */
    if (shell_close_outputs(&sh) != CMD_OK && sh.stop_on_error) status = 1;
    shell_free(&sh);
    free(cmds);
    free(files);
    return stdout_checked(status);
}
