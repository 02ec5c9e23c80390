/* gl_load.c: OSMesa loaded when a view is first made (gl_load.h). */
#include <GL/gl.h>
#include <GL/osmesa.h>

#define GL_LOAD_NO_MACROS
#include "gl_load.h"

#include <dlfcn.h>
#include <stdbool.h>
#include <stdio.h>
#include <string.h>

/* The library's name as Debian's libosmesa6 installs it, then the development
 * link's. */
static const char *const gl_load_names[] = {"libOSMesa.so.8", "libOSMesa.so"};

gl_api gl_load_api;

int gl_load(char *err, size_t errlen)
{
    static bool loaded;
    if (loaded) return 0;
    void *lib = NULL;
    for (size_t k = 0; k < sizeof gl_load_names / sizeof *gl_load_names && !lib; k++)
        lib = dlopen(gl_load_names[k], RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
        snprintf(err, errlen, "cannot load OSMesa, which draws the views (%s): %s",
                 gl_load_names[0], dlerror());
        return -1;
    }
    /* (the library stays loaded to the end: Mesa's threads outlive a context) */
#define GL_LOAD_ONE(name)                                                                    \
    {                                                                                        \
        void *f = dlsym(lib, #name);                                                         \
        if (!f) {                                                                            \
            snprintf(err, errlen, "cannot load OSMesa: %s has no %s", gl_load_names[0], #name); \
            return -1;                                                                       \
        }                                                                                    \
        memcpy(&gl_load_api.p_##name, &f, sizeof f);                                         \
    }
    GL_LOAD_FUNCS(GL_LOAD_ONE)
#undef GL_LOAD_ONE
    loaded = true;
    return 0;
}
