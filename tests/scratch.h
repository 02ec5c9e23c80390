/* scratch.h: a unit test's scratch folder, /tmp/vroc-NAME-XXXXXX, made before its
 * tests and removed with all it holds after them (in cmocka's setup and teardown).
 * Its path is g_dir. */
#ifndef VROC_TEST_SCRATCH_H
#define VROC_TEST_SCRATCH_H

#include <stdio.h>
#include <stdlib.h>

static char g_dir[64];

/* Makes the folder; 0, or -1 when it cannot be made. */
static inline int scratch_make(const char *name)
{
    snprintf(g_dir, sizeof g_dir, "/tmp/vroc-%s-XXXXXX", name);
    return mkdtemp(g_dir) ? 0 : -1;
}

/* Removes the folder and what it holds; 0, or -1 when that failed. */
static inline int scratch_remove(void)
{
    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf '%s'", g_dir);
    return system(cmd) == 0 ? 0 : -1;
}

#endif
