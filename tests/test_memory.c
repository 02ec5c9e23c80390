/* test_memory.c: memory linear in the objects (issue 27).  Ten thousand random
 * objects in a closed room (random 10000 in random_box = (12, 12, 12), as the
 * language promises) run a few frames within 300 MB of resident memory at its peak
 * (VmHWM of /proc/self/status), with pairs that grow with what is near.  Skipped
 * in the sanitizer build, whose shadow memory and quarantine are no measure. */
#include "check.h"

#include <stdlib.h>
#include <string.h>

#include "core/world.h"
#include "shell/shell.h"

#if defined(__SANITIZE_ADDRESS__)
#define MEMORY_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MEMORY_SANITIZED 1
#endif
#endif

/* The limit of the issue (MB). */
#define MEMORY_LIMIT_MB 300.0

/* The process's peak resident set (MB), or -1 when /proc does not say. */
static double peak_mb(void)
{
    FILE *f = fopen("/proc/self/status", "r");
    if (!f) return -1;
    char line[256];
    double kb = -1;
    while (fgets(line, sizeof line, f))
        if (sscanf(line, "VmHWM: %lf kB", &kb) == 1) break;
    fclose(f);
    return kb < 0 ? -1 : kb / 1024;
}

static void ten_thousand_objects_fit_in_memory(void **state)
{
    (void)state;
#ifdef MEMORY_SANITIZED
    skip();
#endif
    shell sh;
    FILE *out = tmpfile(), *err = tmpfile();
    assert_non_null(out);
    assert_non_null(err);
    shell_init(&sh, out, err);
    sh.quiet = true;
    sh.stop_on_error = true;
    /* the room: six static walls about the box */
    const char *scene =
        "random_box = (12, 12, 12)\n"
        "random 10000\n"
        "cube floor; mass = -1; size = (12.4, 12.4, 0.2); translate = (0, 0, -12.2)\n"
        "cube ceiling; mass = -1; size = (12.4, 12.4, 0.2); translate = (0, 0, 12.2)\n"
        "cube west; mass = -1; size = (0.2, 12.4, 12); translate = (-12.2, 0, 0)\n"
        "cube east; mass = -1; size = (0.2, 12.4, 12); translate = (12.2, 0, 0)\n"
        "cube south; mass = -1; size = (12, 0.2, 12); translate = (0, -12.2, 0)\n"
        "cube north; mass = -1; size = (12, 0.2, 12); translate = (0, 12.2, 0)\n"
        "run 5\n";
    assert_int_equal(shell_run_text(&sh, scene, "test_memory"), CMD_OK);
    assert_int_equal(sh.w.n, 10006);
    assert_int_equal(sh.w.frame, 5);
    double mb = peak_mb();
    long live = sh.w.pairs.live, all = world_pairs(&sh.w);
    print_message("10,006 objects, 5 frames: peak resident set %.1f MB (limit %.0f), %ld pairs "
                  "exist of %ld, %ld collisions\n",
                  mb, MEMORY_LIMIT_MB, live, all, sh.w.st.collisions);
    assert_true(mb > 0);
    assert_true(mb < MEMORY_LIMIT_MB);
    assert_true(live > 0 && live < 10 * sh.w.n); /* with what is near, not n^2 */
    assert_true(sh.w.st.collisions > 0);
    shell_free(&sh);
    fclose(out);
    fclose(err);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(ten_thousand_objects_fit_in_memory),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
