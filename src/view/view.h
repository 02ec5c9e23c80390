/* view.h: the stereo off-screen views: what a see-through head-mounted display shows.
 *
 * OSMesa renders each eye of the head (view_settings: head, look_at, up, ipd, fov,
 * image_size) into memory with parallel view axes and off-axis frusta that share
 * one window at the focal distance |look_at - head|, the zero-parallax plane
 * (design.md, "Views").  view_refresh writes the frame's PNG files into `output`
 * as `stereo` asks.  Rendering reads the world and never changes it.
 *
 * A view is an OSMesa context with its buffers.  Every function takes the caller's
 * pointer and creates the context on first need, so a shell can hold a NULL view
 * until the first refresh.  Everything is synchronous: the files of a frame are
 * complete when view_refresh returns (a pair is encoded on two threads, joined
 * before it returns).  Use a view from one thread at a time.
 *
 * In AddressSanitizer builds view.c defines LeakSanitizer's
 * __lsan_default_suppressions hook to ignore Mesa's own unfreed allocations; a
 * program linking view.o must not define that hook again.
 */
#ifndef VROC_VIEW_H
#define VROC_VIEW_H

#include <stdbool.h>
#include <stddef.h>

#include "core/world.h"

/* The most pictures a second of simulated time a movie may take (movie_rate). */
#define VIEW_MOVIE_RATE_MAX 1000

/* Longest path of the output folder, with its final NUL. */
#define VIEW_PATH_MAX 1024

typedef enum { STEREO_PAIR, STEREO_SBS, STEREO_ANAGLYPH, STEREO_MONO } stereo_mode;
typedef enum { REAL_SOLID, REAL_WIRE, REAL_HIDDEN } real_mode;

/* The pictures a panel's button shows. */
typedef enum { VIEW_ICON_NONE, VIEW_ICON_STOP, VIEW_ICON_START, VIEW_ICON_STEP, VIEW_ICON_SELECT } view_icon;

/* One control of the tool panel as drawn: a button (a square with its picture and
 * label) or a slider (a line with a knob and its label above), in the panel's
 * plane (metres from its centre, x to the right, y up). */
typedef struct {
    bool slider;
    double x, y, half_w, half_h;
    char label[32];
    view_icon icon;
    double knob;      /* a slider's knob, x */
    bool lit;         /* a button that is on (select mode, time running) */
} view_control;

#define VIEW_CONTROLS 8

/* What the views draw over the world in both eyes, which is no part of it (so
 * `real` does not hide it): the hand's pointer, its tip at hand_p and pointing
 * along hand_q's +x, and the virtual tool panel, a sheet of 2 half_w x 2 half_h
 * in its own x-y plane facing its +z, centred at panel_at and turned by panel_q.
 * Both are hidden by default. */
typedef struct {
    bool hand;
    vec3 hand_p;
    quat hand_q;
    bool panel;
    vec3 panel_at;
    quat panel_q;
    double half_w, half_h;
    view_control controls[VIEW_CONTROLS];
    int ncontrols;
} view_overlay;

/* What the views show and where they go (language.md, "Head, hand and views"). */
typedef struct {
    vec3 head, look_at, up;   /* the head pose the two eyes are placed from */
    double ipd, fov;          /* eye distance (m), vertical field of view (degrees) */
    int image_w, image_h;     /* pixels per eye */
    char output[VIEW_PATH_MAX]; /* the folder frames are written into */
    stereo_mode stereo;
    int background[3];        /* 0..255 */
    real_mode real;           /* how static objects are drawn */
    bool hulls;               /* polyhedra's pieces' hulls drawn as wire frames over them */
    bool record;              /* write the views of every frame while time runs */
    double movie_rate;        /* a movie's pictures per second of simulated time */
    view_overlay overlay;     /* the hand and the panel (the shell keeps it current) */
} view_settings;

/* The start-up values: head at the origin looking along +y with z up, ipd 0.064,
 * fov 60, 640x512, output "frames", pair, black, solid, hulls off, record off, movie_rate 30,
 * no hand or panel drawn. */
view_settings view_settings_defaults(void);

/* What drawing has cost so far. */
typedef struct {
    double render_time;   /* seconds spent drawing and writing frames */
    long frames_written;  /* image files written */
} view_stats;

typedef struct view view; /* opaque: OSMesa context + buffers */

/* Creates the off-screen context for vs's image_size, or re-creates it when the
 * size changed (*v may be NULL on entry; an unchanged size keeps the context).
 * Returns 0, or -1 with a message in err (then *v is NULL). */
int view_display(view **v, const view_settings *vs, char *err, size_t errlen);

/* Renders both eyes of the current state into memory (creating the context on first
 * need).  Returns 0, or -1 with a message in err: a bad head pose (head == look_at,
 * up parallel to the view direction), fov outside (0, 180), a negative ipd, or a
 * context that cannot be made. */
int view_render(view **v, const world *w, const view_settings *vs, char *err, size_t errlen);

/* Where a body is drawn: its origin and orientation. */
typedef struct {
    vec3 x;
    quat q;
} view_pose;

/* view_render with body i of w drawn at poses[i] instead of its own x and q
 * (poses holds w->n of them): a movie's pictures between two frames. */
int view_render_posed(view **v, const world *w, const view_pose *poses, const view_settings *vs,
                      char *err, size_t errlen);

/* Renders and writes frame number `frame` into vs->output, creating the folders as
 * `mkdir -p` does: pair -> frame-NNNNNN-left.png and frame-NNNNNN-right.png; sbs ->
 * frame-NNNNNN-sbs.png (twice as wide, left eye on the left); anaglyph ->
 * frame-NNNNNN-anaglyph.png (view_anaglyph's red-cyan image in colour); mono ->
 * frame-NNNNNN-left.png only (only the left eye
 * is rendered).  NNNNNN is the frame number as %06ld.  Adds the wall time spent to
 * st->render_time and the files written to st->frames_written (st may be NULL).
 * Returns 0, or -1 with a message in err (for a file or folder: naming the path and
 * the system's reason). */
int view_refresh(view **v, const world *w, const view_settings *vs, long frame, view_stats *st,
                 char *err, size_t errlen);

/* The last rendered image of eye 0 (left) or 1 (right): 8-bit RGB, top row first,
 * *width x *height = image_size.  NULL when that eye has not been rendered (no render
 * yet, or the last refresh was mono and eye is 1).  Valid until the next view_* call. */
const unsigned char *view_pixels(const view *v, int eye, int *width, int *height);

/* The last rendering as `stereo` mode lays it out: pair and sbs the two eyes side
 * by side (2 image_w x image_h, left eye on the left), anaglyph view_anaglyph's
 * image, mono the left eye: what the window shows, and the PNG files hold (a pair's
 * two halves).  NULL when an eye it needs has not been rendered.  Valid until the
 * next view_* call. */
const unsigned char *view_picture(view *v, stereo_mode mode, int *width, int *height);

/* The ray through the point (px, py) of eye `eye`'s image (0 left, 1 right, -1 the
 * head's own, midway between them, as if ipd were 0), in pixels from its top left
 * corner (a pixel's centre is at +0.5): its origin (the eye) and unit direction, in
 * world coordinates.  What lies along it is drawn there.  Returns 0, or -1 with a
 * message when the head pose or the optics give no view. */
int view_ray(const view_settings *vs, int eye, double px, double py, vec3 *origin, vec3 *dir,
             char *err, size_t errlen);

/* Destroys the context and the buffers (NULL is fine). */
void view_free(view *v);

/* The colours new objects take in turn (language.md, Table A.1's color): the
 * k-th of VIEW_PALETTE distinguishable colours, bright on the black background,
 * the first the thesis's red (255, 0, 0); k counts on past the last. */
#define VIEW_PALETTE 10
void view_palette(long k, int rgb[3]);

/* The red-cyan anaglyph pixel of a left and a right eye's pixels (8-bit RGB)
 * into out, by Dubois's least-squares projection (E. Dubois, "A projection
 * method to generate anaglyph stereo images", ICASSP 2001), applied in linear
 * light: the colours of the scene are kept as far as red and cyan filters let
 * them, where a luminance anaglyph made everything grey. */
void view_anaglyph_pixel(const unsigned char *left, const unsigned char *right, unsigned char *out);

#endif
