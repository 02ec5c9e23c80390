/* dl.c: libraries loaded when first needed (dl.h). */
#include "dl.h"

#include <dlfcn.h>
#include <stdio.h>
#include <string.h>

int dl_load(const char *const *names, size_t n, const char *what, const dl_symbol *syms,
            size_t nsyms, char *err, size_t errlen)
{
    void *lib = NULL;
    for (size_t k = 0; k < n && !lib; k++) lib = dlopen(names[k], RTLD_NOW | RTLD_LOCAL);
    if (!lib) {
        snprintf(err, errlen, "cannot load %s (%s): %s", what, names[0], dlerror());
        return -1;
    }
    for (size_t k = 0; k < nsyms; k++) {
        void *f = dlsym(lib, syms[k].name);
        if (!f) {
            snprintf(err, errlen, "cannot load %s: %s has no %s", what, names[0], syms[k].name);
            return -1;
        }
        memcpy(syms[k].slot, &f, sizeof f); /* (a function pointer from dlsym's void *) */
    }
    return 0;
}
