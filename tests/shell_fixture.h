/* shell_fixture.h: a unit test's shell, g_sh, writing into memory: what it prints
 * is in g_out, its messages in g_errbuf.  Quiet, and stopping at the first error,
 * as vroc -b -q does. */
#ifndef VROC_TEST_SHELL_FIXTURE_H
#define VROC_TEST_SHELL_FIXTURE_H

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "shell/shell.h"

static shell g_sh;
static char *g_out, *g_errbuf;
static size_t g_outlen, g_errlen;

static inline void shell_fixture_open(void)
{
    FILE *out = open_memstream(&g_out, &g_outlen);
    FILE *err = open_memstream(&g_errbuf, &g_errlen);
    shell_init(&g_sh, out, err);
    g_sh.quiet = true;
    g_sh.stop_on_error = true;
}

static inline void shell_fixture_close(void)
{
    FILE *out = g_sh.out, *err = g_sh.err;
    shell_free(&g_sh);
    fclose(out);
    fclose(err);
    free(g_out);
    free(g_errbuf);
}

/* Empties g_out and g_errbuf. */
static inline void clear_output(void)
{
    fflush(g_sh.out);
    fflush(g_sh.err);
    rewind(g_sh.out);
    rewind(g_sh.err);
    memset(g_out, 0, g_outlen);
    memset(g_errbuf, 0, g_errlen);
}

/* Runs text as statements, with what they print alone in g_out and g_errbuf. */
static inline cmd_status run(const char *text)
{
    clear_output();
    cmd_status r = shell_run_text(&g_sh, text, NULL);
    fflush(g_sh.out);
    fflush(g_sh.err);
    return r;
}

#endif
