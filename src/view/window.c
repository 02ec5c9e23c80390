/* window.c: the window on the screen, with SDL2 loaded when first opened (window.h).
 *
 * Each SDL function used is a pointer of the function's own type, bound by dl.h
 * as gl_load.c binds OSMesa's.  The picture
 * goes through the window's surface (SDL_GetWindowSurface), not a renderer: a
 * software blit with no filtering, so that at the window's own size the screen
 * holds the picture's very pixels, and no OpenGL of the display's beside the
 * views' OSMesa.
 */
#include "window.h"

#include "dl.h"

#include <SDL.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Every SDL function the window calls: X(name). */
#define SDL_FUNCS(X)                                                                           \
    X(SDL_SetHint) X(SDL_Init) X(SDL_Quit) X(SDL_GetError) X(SDL_CreateWindow)                  \
    X(SDL_DestroyWindow) X(SDL_GetWindowSurface) X(SDL_UpdateWindowSurface)                    \
    X(SDL_CreateRGBSurfaceWithFormatFrom) X(SDL_FreeSurface) X(SDL_UpperBlit)                  \
    X(SDL_UpperBlitScaled) X(SDL_FillRect) X(SDL_PollEvent) X(SDL_SetWindowTitle)              \
    X(SDL_SetWindowSize) X(SDL_GetWindowSize) X(SDL_GetWindowID) X(SDL_PumpEvents)

#define SDL_POINTER(name) __typeof__(name) *name;
static struct {
    SDL_FUNCS(SDL_POINTER)
} sdl;
#undef SDL_POINTER

/* The library's name as Debian's libsdl2-2.0-0 installs it, then the
 * development link's. */
static const char *const sdl_names[] = {"libSDL2-2.0.so.0", "libSDL2.so"};

/* Loads SDL2 (once).  Returns 0, or -1 with why in err. */
static int sdl_load(char *err, size_t errlen)
{
    static bool loaded;
    if (loaded) return 0;
#define SDL_ONE(name) {#name, &sdl.name},
    static const dl_symbol syms[] = {SDL_FUNCS(SDL_ONE)};
#undef SDL_ONE
    if (dl_load(sdl_names, sizeof sdl_names / sizeof *sdl_names,
                "SDL2, which draws the window", syms, sizeof syms / sizeof *syms, err,
                errlen) != 0)
        return -1;
    loaded = true;
    return 0;
}

struct window {
    SDL_Window *w;
    unsigned char *pic; /* the picture shown, kept to show again */
    int pw, ph;
    SDL_Rect dst;       /* where it is on the window */
};

/* The value of the environment variable name, or NULL where it is unset or empty. */
static const char *env_named(const char *name)
{
    const char *v = getenv(name);
    return v && *v ? v : NULL;
}

bool window_display_named(void)
{
    return env_named("DISPLAY") || env_named("WAYLAND_DISPLAY");
}

int window_open(window **win, const char *title, int width, int height, char *err, size_t errlen)
{
    *win = NULL;
    const char *x = env_named("DISPLAY"), *wl = env_named("WAYLAND_DISPLAY");
    if (!x && !wl) {
        snprintf(err, errlen, "no display to open a window on (neither DISPLAY nor WAYLAND_DISPLAY is set)");
        return -1;
    }
    if (sdl_load(err, errlen) != 0) return -1;
    sdl.SDL_SetHint(SDL_HINT_NO_SIGNAL_HANDLERS, "1");
    sdl.SDL_SetHint(SDL_HINT_VIDEO_ALLOW_SCREENSAVER, "1");
    sdl.SDL_SetHint(SDL_HINT_MOUSE_FOCUS_CLICKTHROUGH, "1");
    /* the window's surface drawn by the display's own means (X11's shared
     * memory images), not through an OpenGL renderer: the system's GL (Mesa's
     * GLX) and the OSMesa the views draw with clash in one process */
    sdl.SDL_SetHint(SDL_HINT_FRAMEBUFFER_ACCELERATION, "0");
    /* Only a display that shows the window will do: left to itself, SDL falls
     * back to its invisible "offscreen" driver when no X11 or Wayland server
     * answers, and the window would open nowhere without a word.  So SDL tries
     * the servers the environment names, and no other.  A driver the user names
     * in SDL_VIDEODRIVER is still theirs. */
    const char *named = env_named("SDL_VIDEODRIVER");
    if (!named) sdl.SDL_SetHint(SDL_HINT_VIDEODRIVER, x && wl ? "x11,wayland" : x ? "x11" : "wayland");
    if (sdl.SDL_Init(SDL_INIT_VIDEO) != 0) {
        if (!named && x)
            snprintf(err, errlen, "cannot open a window: no %s server answers on DISPLAY=%s%s",
                     wl ? "X11 or Wayland" : "X11", x, wl ? " or WAYLAND_DISPLAY" : "");
        else if (!named)
            snprintf(err, errlen, "cannot open a window: no Wayland server answers on WAYLAND_DISPLAY=%s",
                     wl);
        else
            snprintf(err, errlen, "cannot open a window on the display: %s", sdl.SDL_GetError());
        sdl.SDL_Quit();
        return -1;
    }
    window *v = calloc(1, sizeof *v);
    if (v) v->w = sdl.SDL_CreateWindow(title, SDL_WINDOWPOS_UNDEFINED, SDL_WINDOWPOS_UNDEFINED, width,
                                       height, SDL_WINDOW_SHOWN | SDL_WINDOW_RESIZABLE);
    if (!v || !v->w) {
        snprintf(err, errlen, "cannot open a window: %s", v ? sdl.SDL_GetError() : "out of memory");
        free(v);
        sdl.SDL_Quit();
        return -1;
    }
    *win = v;
    return 0;
}

void window_close(window *win)
{
    if (!win) return;
    sdl.SDL_DestroyWindow(win->w);
    sdl.SDL_Quit();
    free(win->pic);
    free(win);
}

void window_title(window *win, const char *title)
{
    sdl.SDL_SetWindowTitle(win->w, title);
}

/* Puts the kept picture on the window: at its own size where the window has it,
 * else scaled to fit, centred on black. */
static int present(window *win, char *err, size_t errlen)
{
    SDL_Surface *dst = sdl.SDL_GetWindowSurface(win->w);
    if (!dst) {
        snprintf(err, errlen, "the window has no surface to draw on: %s", sdl.SDL_GetError());
        return -1;
    }
    if (!win->pic) return 0;
    SDL_Surface *src = sdl.SDL_CreateRGBSurfaceWithFormatFrom(win->pic, win->pw, win->ph, 24, 3 * win->pw,
                                                               SDL_PIXELFORMAT_RGB24);
    if (!src) {
        snprintf(err, errlen, "cannot show the picture: %s", sdl.SDL_GetError());
        return -1;
    }
    int rc;
    if (dst->w == win->pw && dst->h == win->ph) {
        win->dst = (SDL_Rect){0, 0, win->pw, win->ph};
        rc = sdl.SDL_UpperBlit(src, NULL, dst, &win->dst);
    } else { /* the largest rectangle of the picture's proportions that fits */
        int w = dst->w, h = (int)((long)dst->w * win->ph / win->pw);
        if (h > dst->h) {
            h = dst->h;
            w = (int)((long)dst->h * win->pw / win->ph);
        }
        win->dst = (SDL_Rect){(dst->w - w) / 2, (dst->h - h) / 2, w > 0 ? w : 1, h > 0 ? h : 1};
        sdl.SDL_FillRect(dst, NULL, 0);
        SDL_Rect r = win->dst; /* (the blit clips its copy) */
        rc = sdl.SDL_UpperBlitScaled(src, NULL, dst, &r);
    }
    sdl.SDL_FreeSurface(src);
    if (rc != 0 || sdl.SDL_UpdateWindowSurface(win->w) != 0) {
        snprintf(err, errlen, "cannot show the picture: %s", sdl.SDL_GetError());
        return -1;
    }
    return 0;
}

int window_show(window *win, const unsigned char *rgb, int width, int height, char *err,
                size_t errlen)
{
    size_t n = 3 * (size_t)width * (size_t)height;
    if (width != win->pw || height != win->ph) {
        unsigned char *p = realloc(win->pic, n);
        if (!p) {
            snprintf(err, errlen, "out of memory for a %dx%d picture", width, height);
            return -1;
        }
        win->pic = p;
        win->pw = width;
        win->ph = height;
        int ww, wh;
        sdl.SDL_GetWindowSize(win->w, &ww, &wh);
        if (ww != width || wh != height) {
            sdl.SDL_SetWindowSize(win->w, width, height);
            sdl.SDL_PumpEvents(); /* (the new size's surface) */
        }
    }
    memcpy(win->pic, rgb, n);
    return present(win, err, errlen);
}

/* The window's point (x, y) as the picture's pixel centre. */
static void to_picture(const window *win, int x, int y, double *px, double *py)
{
    const SDL_Rect *d = &win->dst;
    double sx = d->w > 0 ? (double)win->pw / d->w : 1, sy = d->h > 0 ? (double)win->ph / d->h : 1;
    *px = ((double)(x - d->x) + 0.5) * sx;
    *py = ((double)(y - d->y) + 0.5) * sy;
}

bool window_poll(window *win, win_event *e)
{
    SDL_Event ev;
    while (sdl.SDL_PollEvent(&ev)) {
        memset(e, 0, sizeof *e);
        switch (ev.type) {
        case SDL_QUIT: e->kind = WIN_CLOSE; return true;
        case SDL_WINDOWEVENT:
            if (ev.window.windowID != sdl.SDL_GetWindowID(win->w)) break;
            if (ev.window.event == SDL_WINDOWEVENT_CLOSE) {
                e->kind = WIN_CLOSE;
                return true;
            }
            if (ev.window.event == SDL_WINDOWEVENT_EXPOSED || ev.window.event == SDL_WINDOWEVENT_SIZE_CHANGED) {
                char ignored[256]; /* (a picture that cannot be shown again is shown at the next) */
                present(win, ignored, sizeof ignored);
            }
            break;
        case SDL_KEYDOWN: {
            SDL_Keycode k = ev.key.keysym.sym;
            if (ev.key.repeat) break;
            e->kind = WIN_KEY;
            e->key = k == SDLK_ESCAPE ? WIN_KEY_ESCAPE : k == SDLK_KP_PERIOD ? '.' : k >= 32 && k < 127 ? (int)k : 0;
            if (e->key) return true;
            break;
        }
        case SDL_MOUSEBUTTONDOWN:
        case SDL_MOUSEBUTTONUP:
            e->kind = WIN_BUTTON;
            e->button = ev.button.button == SDL_BUTTON_LEFT ? 1 : ev.button.button == SDL_BUTTON_RIGHT ? 3 : 2;
            e->down = ev.type == SDL_MOUSEBUTTONDOWN;
            to_picture(win, ev.button.x, ev.button.y, &e->x, &e->y);
            return true;
        case SDL_MOUSEMOTION:
            e->kind = WIN_MOTION;
            to_picture(win, ev.motion.x, ev.motion.y, &e->x, &e->y);
            return true;
        case SDL_MOUSEWHEEL:
            e->kind = WIN_WHEEL;
            e->wheel = ev.wheel.direction == SDL_MOUSEWHEEL_FLIPPED ? -ev.wheel.y : ev.wheel.y;
            if (e->wheel) return true;
            break;
        default: break;
        }
    }
    return false;
}
