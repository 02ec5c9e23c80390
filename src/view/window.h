/* window.h: a window on the screen that shows an RGB picture, and what the user
 * does in it: keys, the pointer, its buttons and its wheel (SDL2).
 *
 * SDL2 is loaded with dlopen when a window first opens, as OSMesa is (gl_load.h),
 * so that a run that opens none never maps it and starts as fast.  Its signal
 * handlers are turned off (SDL_HINT_NO_SIGNAL_HANDLERS), so Ctrl-C stays the
 * prompt's, and it may not keep the screen saver away.  The picture is copied to
 * the window's own surface unchanged when the window has the picture's size (so a
 * screenshot of the window is the picture, pixel for pixel), else scaled to fit
 * with its proportions kept, centred on black.  The window keeps the last picture
 * and shows it again when the screen asks (exposed, resized) without asking its
 * caller.  One window at a time, from one thread.
 */
#ifndef VROC_WINDOW_H
#define VROC_WINDOW_H

#include <stdbool.h>
#include <stddef.h>

typedef struct window window;

/* What window_poll reports. */
typedef enum {
    WIN_KEY,    /* a key went down (not its repeats) */
    WIN_BUTTON, /* a pointer button went down or up */
    WIN_MOTION, /* the pointer moved */
    WIN_WHEEL,  /* the wheel turned */
    WIN_CLOSE   /* the window's close button */
} win_event_kind;

/* Keys that are not characters (WIN_KEY's key): */
#define WIN_KEY_ESCAPE 27

typedef struct {
    win_event_kind kind;
    int key;         /* WIN_KEY: the character (' ', '.', 'r'...), or WIN_KEY_ESCAPE */
    int button;      /* WIN_BUTTON: 1 left, 2 middle, 3 right */
    bool down;       /* WIN_BUTTON: pressed (else released) */
    double x, y;     /* WIN_BUTTON, WIN_MOTION: the pointer's pixel on the picture,
                      * its centre (+0.5), from the picture's top left corner; off
                      * the picture (outside [0, width) x [0, height)) while a
                      * button held in it is dragged out */
    int wheel;       /* WIN_WHEEL: notches, > 0 turned away from the user */
} win_event;

/* True when there is a display to open a window on: DISPLAY (X11) or
 * WAYLAND_DISPLAY is set. */
bool window_display_named(void);

/* Opens a window titled title, of width x height pixels (the picture it will
 * show).  Returns 0, or -1 with why in err (no display named, SDL2 not
 * installed, the display refused). */
int window_open(window **win, const char *title, int width, int height, char *err, size_t errlen);

/* Shows the picture rgb (8-bit RGB, top row first, width x height), resizing the
 * window to it when its size changed.  Returns 0, or -1 with why in err. */
int window_show(window *win, const unsigned char *rgb, int width, int height, char *err,
                size_t errlen);

/* Sets the window's title. */
void window_title(window *win, const char *title);

/* The next thing the user did, into e: false when nothing is waiting. */
bool window_poll(window *win, win_event *e);

/* Closes the window (NULL is fine). */
void window_close(window *win);

#endif
