/* dl.h: a library loaded with dlopen when first needed (OSMesa for the views,
 * SDL2 for the window), so that a run that needs neither never maps them: the
 * first of its names that loads, and its functions bound by name. */
#ifndef VROC_DL_H
#define VROC_DL_H

#include <stddef.h>

/* A function to bind: its name, and where its pointer goes (a pointer to a
 * function pointer of the function's own type). */
typedef struct {
    const char *name;
    void *slot;
} dl_symbol;

/* Loads the first of names[0 .. n-1] that loads, and binds the nsyms functions
 * of syms from it; what names the library in messages ("OSMesa, which draws the
 * views").  The library stays loaded to the end.  Returns 0, or -1 with why in
 * err (the names tried, the loader's reason, or the function missing). */
int dl_load(const char *const *names, size_t n, const char *what, const dl_symbol *syms,
            size_t nsyms, char *err, size_t errlen);

#endif
