/* gl_load.c: OSMesa loaded when a view is first made (gl_load.h). */
#include <GL/gl.h>
#include <GL/osmesa.h>

#define GL_LOAD_NO_MACROS
#include "gl_load.h"

#include <stdbool.h>

#include "dl.h"

/* The library's name as Debian's libosmesa6 installs it, then the development
 * link's. */
static const char *const gl_load_names[] = {"libOSMesa.so.8", "libOSMesa.so"};

gl_api gl_load_api;

int gl_load(char *err, size_t errlen)
{
    static bool loaded;
    if (loaded) return 0;
#define GL_LOAD_ONE(name) {#name, &gl_load_api.p_##name},
    static const dl_symbol syms[] = {GL_LOAD_FUNCS(GL_LOAD_ONE)};
#undef GL_LOAD_ONE
    /* (the library stays loaded to the end: Mesa's threads outlive a context) */
    if (dl_load(gl_load_names, sizeof gl_load_names / sizeof *gl_load_names, "OSMesa, which draws the views",
                syms, sizeof syms / sizeof *syms, err, errlen) != 0)
        return -1;
    loaded = true;
    return 0;
}
