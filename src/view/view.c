/* view.c: stereo rendering of the world with OSMesa and writing the frames as PNG.
 *
 * Eyes (design.md, "Views"; the parallel-axis asymmetric-frustum method, as in
 * Hodges, "Tutorial: time-multiplexed stereoscopic computer graphics", IEEE CG&A
 * 1992): the head frame is f = |look_at - head|^-1 (look_at - head), r = |f x up|^-1
 * (f x up), u = r x f; the eyes sit at head -+ r ipd/2 and both look along f.  Each
 * eye's frustum is shifted sideways by -+(ipd/2) near/D at the near plane so that both
 * frusta meet the same window at the focal distance D = |look_at - head|: points at
 * D have zero parallax, nearer ones crossed parallax (further right in the left eye).
 *
 * Drawing is legacy fixed-function OpenGL 1.2 on OSMesa (llvmpipe): client-side
 * vertex arrays straight from each body's mesh (vec3 = 3 doubles, triangles = 3
 * ints), one model matrix per body from x and q, two directional lights fixed to the
 * head, z-buffer and back-face culling (the meshes are convex and counter-clockwise
 * seen from outside; a polyhedron's, from a file, is drawn two-sided).  Static (real-world) objects follow `real`: solid like the
 * others, wire (unlit edges of the collision polyhedron, or of the mesh for a
 * sphere) or hidden.  The hand's pointer and the tool panel are drawn over the
 * world in each eye (overlay.c).  Both eyes are drawn side by side into one 2w x h
 * RGBA buffer (one clear and one glFinish a frame, which lets llvmpipe's threads
 * rasterise the whole frame at once); OSMesa copies it there top row first
 * (OSMESA_Y_UP off) and each half is packed to RGB, the form view_pixels and the
 * PNG writer take.
 *
 * OSMesa is loaded when the first view is made (gl_load.h): a run that draws
 * nothing never maps it.
 *
 * Files: PNG encoding costs more than drawing (bench/bench_view.c), so the two files
 * of a pair are encoded at once, one on a helper thread that is joined before
 * view_refresh returns: no state outlives the call.
 */
#include "view.h"

#include <GL/gl.h>
#include <GL/osmesa.h>
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "gl_load.h"
#include "overlay.h"
#include "png_out.h"

#define VIEW_NEAR 0.01     /* m: near clipping plane */
#define VIEW_FAR_MIN 1000. /* m: far plane, unless the scene reaches further */
#define VIEW_MAX_SIZE 8192  /* pixels per eye each way: 2w must fit llvmpipe's 16384 */

struct view {
    OSMesaContext ctx;
    int w, h;              /* pixels per eye the context was made for */
    unsigned char *rgba;   /* OSMesa's colour buffer, 2w x h RGBA, top row first */
    unsigned char *eye[2]; /* last rendered eyes, RGB, top row first */
    bool have[2];          /* eye[i] holds a rendering */
    unsigned char *out;    /* side-by-side or anaglyph image being written */
};

/* One eye: its position and axes (shared by both eyes) and its frustum at near. */
typedef struct {
    vec3 pos, r, u, f;
    double left, right, bottom, top, near, far;
} view_eye;

view_settings view_settings_defaults(void)
{
    view_settings s;
    memset(&s, 0, sizeof s);
    s.head = v3(0, 0, 0);
    s.look_at = v3(0, 1, 0);
    s.up = v3(0, 0, 1);
    s.ipd = 0.064;
    s.fov = 60;
    s.image_w = 640;
    s.image_h = 512;
    snprintf(s.output, sizeof s.output, "frames");
    s.stereo = STEREO_PAIR;
    s.real = REAL_SOLID;
    s.record = false;
    s.hulls = false;
    s.movie_rate = 30;
    return s;
}

static double view_now(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}

/* Far plane: beyond every drawn object seen from head, and at least VIEW_FAR_MIN. */
static double view_far(const world *w, const view_settings *vs)
{
    double far = VIEW_FAR_MIN;
    for (int i = 0; i < w->n; i++) {
        const body *b = w->bodies[i];
        if (!b->built) continue;
        double reach = v3_dist(b->x, vs->head) + v3_len(b->shape.mass.com) + b->shape.r_out;
        if (isfinite(reach) && 1.01 * reach + 1 > far) far = 1.01 * reach + 1;
    }
    return far;
}

/* Both eyes from the head pose (w NULL: the far plane at VIEW_FAR_MIN).  Returns 0,
 * or -1 with a message when the pose or the optics cannot give a view. */
static int view_eyes(const world *w, const view_settings *s, view_eye eye[2], char *err,
                     size_t errlen)
{
    if (!v3_finite(s->head) || !v3_finite(s->look_at) || !v3_finite(s->up)) {
        snprintf(err, errlen, "head, look_at and up must be finite");
        return -1;
    }
    vec3 d = v3_sub(s->look_at, s->head);
    double dist = v3_len(d);
    if (!(dist > 1e-9)) {
        snprintf(err, errlen, "head and look_at are the same point (%g,%g,%g): no view direction",
                 s->head.x, s->head.y, s->head.z);
        return -1;
    }
    vec3 f = v3_scale(d, 1.0 / dist);
    vec3 side = v3_cross(f, s->up);
    if (!(v3_len(side) > 1e-9 * v3_len(s->up))) {
        snprintf(err, errlen, "up (%g,%g,%g) is parallel to the view direction (or zero)",
                 s->up.x, s->up.y, s->up.z);
        return -1;
    }
    if (!(s->fov > 0 && s->fov < 180)) {
        snprintf(err, errlen, "fov must be between 0 and 180 degrees (got %g)", s->fov);
        return -1;
    }
    if (!(s->ipd >= 0) || !isfinite(s->ipd)) {
        snprintf(err, errlen, "ipd must be >= 0 (got %g)", s->ipd);
        return -1;
    }
    vec3 r = v3_norm(side);
    vec3 u = v3_cross(r, f);
    double top = VIEW_NEAR * tan(0.5 * s->fov * M_PI / 180.0);
    double half_w = top * (double)s->image_w / (double)s->image_h;
    double far = w ? view_far(w, s) : VIEW_FAR_MIN;
    for (int i = 0; i < 2; i++) {
        double side_sign = i == 0 ? -1.0 : 1.0; /* left eye at -r */
        double shift = -side_sign * 0.5 * s->ipd * VIEW_NEAR / dist;
        eye[i] = (view_eye){.pos = v3_mad(s->head, r, side_sign * 0.5 * s->ipd),
                            .r = r, .u = u, .f = f,
                            .left = -half_w + shift, .right = half_w + shift,
                            .bottom = -top, .top = top, .near = VIEW_NEAR, .far = far};
    }
    return 0;
}

/* ---- the context ---- */

/* Mesa's OSMesa keeps a few hundred bytes per process and per context that
 * OSMesaDestroyContext never frees (its st manager and each context's last
 * framebuffer).  Under LeakSanitizer that would fail every program that draws, so a
 * sanitizer build tells LSan to ignore allocations made inside libOSMesa (LSan calls
 * this hook at start-up; it exists only in sanitizer builds).  So too libdbus's:
 * SDL2 (the window, window.h) opens D-Bus for the screen saver and input methods,
 * and the SDL of Debian 12 (2.26) cannot be told to shut it down at SDL_Quit. */
#if defined(__SANITIZE_ADDRESS__)
#define VIEW_LSAN_HOOK 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define VIEW_LSAN_HOOK 1
#endif
#endif
#ifdef VIEW_LSAN_HOOK
const char *__lsan_default_suppressions(void);
const char *__lsan_default_suppressions(void) { return "leak:libOSMesa.so\nleak:libdbus-1.so\n"; }
#endif

/* Fixed state: lights, material, depth test, culling, arrays.  The lights are given
 * with an identity model-view, so they stay fixed to the head (both eyes share its
 * axes): a key light from above left of the viewer and a dim fill from the right. */
static void view_gl_init(void)
{
    static const GLfloat key_dir[4] = {-0.35f, 0.6f, 0.7f, 0.0f};
    static const GLfloat key_diffuse[4] = {0.75f, 0.75f, 0.75f, 1.0f};
    static const GLfloat key_specular[4] = {0.35f, 0.35f, 0.35f, 1.0f};
    static const GLfloat fill_dir[4] = {0.6f, -0.1f, 0.4f, 0.0f};
    static const GLfloat fill_diffuse[4] = {0.3f, 0.3f, 0.3f, 1.0f};
    static const GLfloat black[4] = {0, 0, 0, 1};
    static const GLfloat ambient[4] = {0.22f, 0.22f, 0.22f, 1.0f};
    static const GLfloat mat_specular[4] = {0.3f, 0.3f, 0.3f, 1.0f};

    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glLightfv(GL_LIGHT0, GL_POSITION, key_dir);
    glLightfv(GL_LIGHT0, GL_DIFFUSE, key_diffuse);
    glLightfv(GL_LIGHT0, GL_SPECULAR, key_specular);
    glLightfv(GL_LIGHT0, GL_AMBIENT, black);
    glLightfv(GL_LIGHT1, GL_POSITION, fill_dir);
    glLightfv(GL_LIGHT1, GL_DIFFUSE, fill_diffuse);
    glLightfv(GL_LIGHT1, GL_SPECULAR, black);
    glLightfv(GL_LIGHT1, GL_AMBIENT, black);
    glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient);
    glEnable(GL_LIGHT0);
    glEnable(GL_LIGHT1);

    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnable(GL_COLOR_MATERIAL);
    glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, mat_specular);
    glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0f);

    glShadeModel(GL_SMOOTH);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_NORMAL_ARRAY);
}

/* Makes v's context current on its buffer (a no-op when it already is). */
static int view_make_current(view *v, char *err, size_t errlen)
{
    if (OSMesaGetCurrentContext() == v->ctx) return 0;
    if (!OSMesaMakeCurrent(v->ctx, v->rgba, GL_UNSIGNED_BYTE, 2 * v->w, v->h)) {
        snprintf(err, errlen, "cannot make the %dx%d off-screen image current", 2 * v->w, v->h);
        return -1;
    }
    OSMesaPixelStore(OSMESA_Y_UP, 0);
    return 0;
}

/* A context and buffers for w x h pixels per eye, or NULL with a message. */
static view *view_create(int w, int h, char *err, size_t errlen)
{
    if (gl_load(err, errlen) != 0) return NULL;
    view *v = calloc(1, sizeof *v);
    if (!v) {
        snprintf(err, errlen, "out of memory for the views");
        return NULL;
    }
    size_t n = (size_t)w * (size_t)h;
    v->w = w;
    v->h = h;
    v->rgba = malloc(8 * n);
    v->eye[0] = malloc(3 * n);
    v->eye[1] = malloc(3 * n);
    v->out = malloc(6 * n);
    if (!v->rgba || !v->eye[0] || !v->eye[1] || !v->out) {
        snprintf(err, errlen, "out of memory for %dx%d views", w, h);
        view_free(v);
        return NULL;
    }
    v->ctx = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    if (!v->ctx) {
        snprintf(err, errlen, "cannot create the OSMesa off-screen context");
        view_free(v);
        return NULL;
    }
    if (view_make_current(v, err, errlen) != 0) {
        view_free(v);
        return NULL;
    }
    view_gl_init();
    if (glGetError() != GL_NO_ERROR) {
        snprintf(err, errlen, "cannot set up OpenGL on the off-screen context");
        view_free(v);
        return NULL;
    }
    return v;
}

int view_display(view **v, const view_settings *vs, char *err, size_t errlen)
{
    int iw = vs->image_w, ih = vs->image_h;
    if (*v && (*v)->w == iw && (*v)->h == ih) return 0;
    view_free(*v);
    *v = NULL;
    if (iw <= 0 || ih <= 0 || iw > VIEW_MAX_SIZE || ih > VIEW_MAX_SIZE) {
        snprintf(err, errlen, "image_size must be between 1 and %d pixels each way (got %dx%d)",
                 VIEW_MAX_SIZE, iw, ih);
        return -1;
    }
    *v = view_create(iw, ih, err, errlen);
    return *v ? 0 : -1;
}

void view_free(view *v)
{
    if (!v) return;
    if (v->ctx) {
        if (OSMesaGetCurrentContext() == v->ctx) OSMesaMakeCurrent(NULL, NULL, 0, 0, 0);
        OSMesaDestroyContext(v->ctx);
    }
    free(v->rgba);
    free(v->eye[0]);
    free(v->eye[1]);
    free(v->out);
    free(v);
}

/* ---- drawing ---- */

/* The OpenGL matrix of the rigid map body -> world, at pose p (NULL: its own). */
static void view_model_matrix(const body *b, const view_pose *p, GLdouble m[16])
{
    overlay_pose_matrix(p ? p->x : b->x, p ? p->q : b->q, m);
}

/* The OpenGL matrix of world -> eye: rows r, u, -f, origin at the eye. */
static void view_eye_matrix(const view_eye *e, GLdouble m[16])
{
    vec3 rows[3] = {e->r, e->u, v3_neg(e->f)};
    for (int i = 0; i < 3; i++) {
        m[0 * 4 + i] = rows[i].x;
        m[1 * 4 + i] = rows[i].y;
        m[2 * 4 + i] = rows[i].z;
        m[3 * 4 + i] = -v3_dot(rows[i], e->pos);
    }
    m[3] = m[7] = m[11] = 0;
    m[15] = 1;
}

static void view_color(const body *b)
{
    GLubyte c[3];
    for (int k = 0; k < 3; k++)
        c[k] = (GLubyte)(b->color[k] < 0 ? 0 : b->color[k] > 255 ? 255 : b->color[k]);
    glColor3ubv(c);
}

static bool view_mesh_ok(const mesh *m)
{
    return m->nv > 0 && m->nt > 0 && m->pos && m->nrm && m->tri;
}

/* The body's mesh, lit and filled, at pose p (NULL: its own).  A polyhedron's
 * faces run as its file's do, either way round, and need not be convex: both sides
 * of each are drawn and lit. */
static void view_draw_solid(const body *b, const view_pose *p)
{
    const mesh *m = &b->shape.draw;
    bool two_sided = b->sp.kind == SHAPE_POLYHEDRON;
    GLdouble model[16];
    view_model_matrix(b, p, model);
    glPushMatrix();
    glMultMatrixd(model);
    view_color(b);
    if (two_sided) {
        glDisable(GL_CULL_FACE);
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_TRUE);
    }
    glVertexPointer(3, GL_DOUBLE, 0, m->pos);
    glNormalPointer(GL_DOUBLE, 0, m->nrm);
    glDrawRangeElements(GL_TRIANGLES, 0, (GLuint)(m->nv - 1), 3 * m->nt, GL_UNSIGNED_INT,
                        m->tri);
    if (two_sided) {
        glLightModeli(GL_LIGHT_MODEL_TWO_SIDE, GL_FALSE);
        glEnable(GL_CULL_FACE);
    }
    glPopMatrix();
}

/* The edges of polyhedron p, in the body's frame set up by the caller. */
static void view_hull_edges(const poly *p)
{
    glBegin(GL_LINES);
    for (int i = 0; i < p->ne; i++) {
        vec3 a = p->v[p->e[i].v[0]], c = p->v[p->e[i].v[1]];
        glVertex3d(a.x, a.y, a.z);
        glVertex3d(c.x, c.y, c.z);
    }
    glEnd();
}

/* The body's edges, unlit, front and back: those of the collision polyhedron (the
 * real edges of a box, without the triangulation's diagonals), or the mesh's for a
 * sphere and for a polyhedron from a file (its own faces, not its hull), at pose
 * pose (NULL: its own).  Lighting and culling must be off. */
static void view_draw_wire(const body *b, const view_pose *pose)
{
    const poly *p = b->shape.hull;
    GLdouble model[16];
    view_model_matrix(b, pose, model);
    glPushMatrix();
    glMultMatrixd(model);
    view_color(b);
    if (p && p->ne > 0 && b->sp.kind != SHAPE_POLYHEDRON) {
        view_hull_edges(p);
    } else {
        const mesh *m = &b->shape.draw;
        glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
        glVertexPointer(3, GL_DOUBLE, 0, m->pos);
        glDrawRangeElements(GL_TRIANGLES, 0, (GLuint)(m->nv - 1), 3 * m->nt, GL_UNSIGNED_INT,
                            m->tri);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    }
    glPopMatrix();
}

/* A polyhedron's pieces' hulls (`hulls = on`), as wire frames in white over what
 * is drawn of it, at pose pose (NULL: its own).  Lighting and culling must be
 * off. */
static void view_draw_hulls(const body *b, const view_pose *pose)
{
    GLdouble model[16];
    view_model_matrix(b, pose, model);
    glPushMatrix();
    glMultMatrixd(model);
    glColor3ub(255, 255, 255);
    for (int k = 0; k < b->shape.pieces; k++) view_hull_edges(shape_piece_hull(&b->shape, k));
    glPopMatrix();
}

/* How body b is drawn under the `real` setting: 0 not at all, 1 solid, 2 wire. */
static int view_style(const body *b, real_mode real)
{
    if (!b->built || !view_mesh_ok(&b->shape.draw)) return 0;
    if (!body_is_static(b)) return 1;
    return real == REAL_SOLID ? 1 : real == REAL_WIRE ? 2 : 0;
}

/* Packs n RGBA pixels into RGB.  On a little-endian machine four pixels at a time:
 * three 32-bit words out of four, which is several times faster than byte copies and
 * matters, as the main thread shares the cores with llvmpipe's rasterizer threads. */
static void view_pack_row(const unsigned char *src, unsigned char *dst, size_t n)
{
    size_t i = 0;
#if defined(__BYTE_ORDER__) && __BYTE_ORDER__ == __ORDER_LITTLE_ENDIAN__
    for (; i + 4 <= n; i += 4) {
        uint32_t p[4];
        memcpy(p, src + 4 * i, sizeof p);
        uint32_t q0 = (p[0] & 0xffffffu) | p[1] << 24;
        uint32_t q1 = (p[1] >> 8 & 0xffffu) | p[2] << 16;
        uint32_t q2 = (p[2] >> 16 & 0xffu) | p[3] << 8;
        memcpy(dst + 3 * i, &q0, 4); /* one word at a time: no store-forwarding stall */
        memcpy(dst + 3 * i + 4, &q1, 4);
        memcpy(dst + 3 * i + 8, &q2, 4);
    }
#endif
    for (; i < n; i++) {
        dst[3 * i] = src[4 * i];
        dst[3 * i + 1] = src[4 * i + 1];
        dst[3 * i + 2] = src[4 * i + 2];
    }
}

/* Packs eye k's half of OSMesa's RGBA image into v->eye[k] as RGB. */
static void view_pack_eye(view *v, int k)
{
    size_t w = (size_t)v->w;
    for (int y = 0; y < v->h; y++)
        view_pack_row(v->rgba + 4 * ((size_t)y * 2 * w + (size_t)k * w),
                      v->eye[k] + 3 * (size_t)y * w, w);
}

/* Draws the world as eye e sees it into the k-th half of the image, body i at
 * poses[i] (poses NULL: where they are). */
static void view_draw_eye(view *v, const world *w, const view_pose *poses, const view_settings *s,
                          const view_eye *e, int k)
{
    glViewport(k * v->w, 0, v->w, v->h);
    glScissor(k * v->w, 0, v->w, v->h);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glFrustum(e->left, e->right, e->bottom, e->top, e->near, e->far);
    glMatrixMode(GL_MODELVIEW);
    GLdouble m[16];
    view_eye_matrix(e, m);
    glLoadMatrixd(m);

    glEnable(GL_LIGHTING);
    glEnable(GL_CULL_FACE);
    bool any_wire = false;
    for (int i = 0; i < w->n; i++) {
        int style = view_style(w->bodies[i], s->real);
        if (style == 1) view_draw_solid(w->bodies[i], poses ? &poses[i] : NULL);
        any_wire = any_wire || style == 2;
    }
    if (any_wire || s->hulls) {
        glDisable(GL_LIGHTING);
        glDisable(GL_CULL_FACE);
        glDisableClientState(GL_NORMAL_ARRAY);
        for (int i = 0; i < w->n; i++) {
            const body *b = w->bodies[i];
            int style = view_style(b, s->real);
            if (style == 2) view_draw_wire(b, poses ? &poses[i] : NULL);
            if (s->hulls && style != 0 && b->sp.kind == SHAPE_POLYHEDRON && b->shape.hull)
                view_draw_hulls(b, poses ? &poses[i] : NULL);
        }
        glEnableClientState(GL_NORMAL_ARRAY);
        glEnable(GL_LIGHTING);
        glEnable(GL_CULL_FACE);
    }
    /* the hand and the panel, whatever `real` says; a pixel at depth d is
     * (top - bottom) d / (near h) across */
    overlay_draw(&s->overlay, e->pos, e->f, (e->top - e->bottom) / (e->near * v->h));
}

/* Renders eyes 0 .. neyes-1 (1: the left eye only), bodies at poses (NULL: their
 * own). */
static int view_render_eyes(view **v, const world *w, const view_pose *poses,
                            const view_settings *vs, int neyes, char *err, size_t errlen)
{
    view_eye eye[2];
    if (view_display(v, vs, err, errlen) != 0) return -1;
    if (view_eyes(w, vs, eye, err, errlen) != 0) return -1;
    if (view_make_current(*v, err, errlen) != 0) return -1;
    view *vw = *v;
    const int *bg = vs->background;
    glDisable(GL_SCISSOR_TEST);
    glClearColor((GLfloat)bg[0] / 255.0f, (GLfloat)bg[1] / 255.0f, (GLfloat)bg[2] / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_SCISSOR_TEST);
    for (int k = 0; k < neyes; k++) view_draw_eye(vw, w, poses, vs, &eye[k], k);
    glFinish(); /* OSMesa copies the image into vw->rgba */
    for (int k = 0; k < 2; k++) {
        vw->have[k] = k < neyes;
        if (k < neyes) view_pack_eye(vw, k);
    }
    return 0;
}

int view_render(view **v, const world *w, const view_settings *vs, char *err, size_t errlen)
{
    return view_render_eyes(v, w, NULL, vs, 2, err, errlen);
}

int view_render_posed(view **v, const world *w, const view_pose *poses, const view_settings *vs,
                      char *err, size_t errlen)
{
    return view_render_eyes(v, w, poses, vs, 2, err, errlen);
}

int view_ray(const view_settings *vs, int eye, double px, double py, vec3 *origin, vec3 *dir,
             char *err, size_t errlen)
{
    view_settings one = *vs;
    if (eye < 0) one.ipd = 0; /* the head's own eye, midway: both frusta in one */
    view_eye e[2];
    if (view_eyes(NULL, &one, e, err, errlen) != 0) return -1;
    const view_eye *c = &e[eye > 0 ? 1 : 0];
    /* the point on the near plane under the pixel (glViewport maps the frustum's
     * left..right onto 0..image_w, top..bottom onto 0..image_h) */
    double x = c->left + (c->right - c->left) * px / (double)vs->image_w;
    double y = c->top - (c->top - c->bottom) * py / (double)vs->image_h;
    *origin = c->pos;
    *dir = v3_norm(v3_add(v3_scale(c->f, c->near), v3_add(v3_scale(c->r, x), v3_scale(c->u, y))));
    return 0;
}

const unsigned char *view_pixels(const view *v, int eye, int *width, int *height)
{
    if (!v || eye < 0 || eye > 1 || !v->have[eye]) return NULL;
    if (width) *width = v->w;
    if (height) *height = v->h;
    return v->eye[eye];
}

/* ---- frames ---- */

/* mkdir -p path.  Returns 0, or -1 with a message naming path and the reason. */
static int view_mkdirs(const char *path, char *err, size_t errlen)
{
    char buf[VIEW_PATH_MAX];
    if (snprintf(buf, sizeof buf, "%s", path) >= (int)sizeof buf) {
        snprintf(err, errlen, "output folder name too long: '%.64s...'", path);
        return -1;
    }
    size_t len = strlen(buf);
    for (size_t i = 1; i <= len; i++) {
        if (buf[i] != '/' && buf[i] != '\0') continue;
        if (buf[i - 1] == '/') continue; /* "a//b", trailing '/' */
        char c = buf[i];
        buf[i] = '\0';
        struct stat st;
        int e = 0;
        if (stat(buf, &st) == 0) {
            if (!S_ISDIR(st.st_mode)) e = ENOTDIR;
        } else if (mkdir(buf, 0777) != 0 && errno != EEXIST) {
            e = errno;
        }
        if (e) {
            if (strcmp(buf, path) == 0)
                snprintf(err, errlen, "cannot create output folder '%s': %s", path, strerror(e));
            else
                snprintf(err, errlen, "cannot create output folder '%s' (at '%s'): %s", path, buf,
                         strerror(e));
            return -1;
        }
        buf[i] = c;
    }
    return 0;
}

/* The side-by-side image: left eye on the left. */
static void view_compose_sbs(view *v)
{
    size_t row = 3 * (size_t)v->w;
    for (int y = 0; y < v->h; y++) {
        memcpy(v->out + (size_t)y * 2 * row, v->eye[0] + (size_t)y * row, row);
        memcpy(v->out + (size_t)y * 2 * row + row, v->eye[1] + (size_t)y * row, row);
    }
}

/* Dubois's red-cyan matrices (his 2001 paper's, as ffmpeg's stereo3d filter has
 * them): each output primary from the left eye's and the right eye's linear
 * RGB. */
static const float DUBOIS_L[3][3] = {{0.456f, 0.500f, 0.176f},
                                     {-0.040f, -0.038f, -0.016f},
                                     {-0.015f, -0.021f, -0.005f}};
static const float DUBOIS_R[3][3] = {{-0.043f, -0.088f, -0.002f},
                                     {0.378f, 0.734f, -0.018f},
                                     {-0.072f, -0.113f, 1.226f}};

/* sRGB to linear light, by 8-bit value; and back, by linear value in 1/4095ths. */
#define LINEAR_STEPS 4096
static float g_to_linear[256];
static unsigned char g_to_srgb[LINEAR_STEPS];
static pthread_once_t g_tables = PTHREAD_ONCE_INIT;

static void make_tables(void)
{
    for (int i = 0; i < 256; i++) {
        double c = i / 255.0;
        g_to_linear[i] = (float)(c <= 0.04045 ? c / 12.92 : pow((c + 0.055) / 1.055, 2.4));
    }
    for (int i = 0; i < LINEAR_STEPS; i++) {
        double l = i / (double)(LINEAR_STEPS - 1);
        double c = l <= 0.0031308 ? 12.92 * l : 1.055 * pow(l, 1 / 2.4) - 0.055;
        g_to_srgb[i] = (unsigned char)lround(255 * c);
    }
}

void view_anaglyph_pixel(const unsigned char *left, const unsigned char *right, unsigned char *out)
{
    pthread_once(&g_tables, make_tables);
    float l[3], r[3];
    for (int k = 0; k < 3; k++) {
        l[k] = g_to_linear[left[k]];
        r[k] = g_to_linear[right[k]];
    }
    for (int c = 0; c < 3; c++) {
        float x = 0;
        for (int k = 0; k < 3; k++) x += DUBOIS_L[c][k] * l[k] + DUBOIS_R[c][k] * r[k];
        x = x < 0 ? 0 : x > 1 ? 1 : x;
        out[c] = g_to_srgb[(int)(x * (LINEAR_STEPS - 1) + 0.5f)];
    }
}

/* The red-cyan anaglyph of the two eyes (view_anaglyph_pixel). */
static void view_compose_anaglyph(view *v)
{
    size_t n = (size_t)v->w * (size_t)v->h;
    for (size_t i = 0; i < n; i++)
        view_anaglyph_pixel(v->eye[0] + 3 * i, v->eye[1] + 3 * i, v->out + 3 * i);
}

void view_palette(long k, int rgb[3])
{
    static const int palette[VIEW_PALETTE][3] = {
        {255, 0, 0},     /* red, the thesis's */
        {30, 144, 255},  /* blue */
        {50, 205, 50},   /* green */
        {255, 165, 0},   /* orange */
        {186, 85, 211},  /* violet */
        {0, 206, 209},   /* turquoise */
        {255, 215, 0},   /* yellow */
        {255, 105, 180}, /* pink */
        {170, 170, 170}, /* grey */
        {160, 100, 50},  /* brown */
    };
    const int *c = palette[(k % VIEW_PALETTE + VIEW_PALETTE) % VIEW_PALETTE];
    for (int i = 0; i < 3; i++) rgb[i] = c[i];
}

/* One file of a frame: output/frame-NNNNNN-suffix.png and its image. */
typedef struct {
    char path[VIEW_PATH_MAX + 64];
    const unsigned char *rgb;
    int width, height;
    int rc;
    char err[512];
} view_file;

static void view_file_init(view_file *f, const char *dir, long frame, const char *suffix,
                           const unsigned char *rgb, int width, int height)
{
    const char *sep = dir[0] == '\0' ? "" : "/";
    snprintf(f->path, sizeof f->path, "%s%sframe-%06ld-%s.png", dir, sep, frame, suffix);
    f->rgb = rgb;
    f->width = width;
    f->height = height;
    f->rc = -1;
    f->err[0] = '\0';
}

static void *view_file_write(void *arg)
{
    view_file *f = arg;
    f->rc = png_write_rgb(f->path, f->rgb, f->width, f->height, f->err, sizeof f->err);
    return NULL;
}

/* Writes n (1 or 2) files.  Two are encoded at once, the first on a helper thread
 * that is joined before returning (PNG encoding costs more than drawing, and the
 * eyes are independent), or one after the other if no thread can be started.
 * Counts the files written in *files; returns 0, or -1 with the first error. */
static int view_write_files(view_file *f, int n, int *files, char *err, size_t errlen)
{
    pthread_t helper;
    bool threaded = n == 2 && pthread_create(&helper, NULL, view_file_write, &f[0]) == 0;
    for (int i = threaded ? 1 : 0; i < n; i++) view_file_write(&f[i]);
    if (threaded) pthread_join(helper, NULL);
    int rc = 0;
    for (int i = 0; i < n; i++) {
        if (f[i].rc == 0) {
            (*files)++;
        } else if (rc == 0) {
            snprintf(err, errlen, "%s", f[i].err);
            rc = -1;
        }
    }
    return rc;
}

const unsigned char *view_picture(view *v, stereo_mode mode, int *width, int *height)
{
    bool two = mode != STEREO_MONO;
    if (!v || !v->have[0] || (two && !v->have[1])) return NULL;
    *width = mode == STEREO_PAIR || mode == STEREO_SBS ? 2 * v->w : v->w;
    *height = v->h;
    switch (mode) {
    case STEREO_PAIR:
    case STEREO_SBS: view_compose_sbs(v); return v->out;
    case STEREO_ANAGLYPH: view_compose_anaglyph(v); return v->out;
    default: return v->eye[0];
    }
}

/* Renders and writes the frame's files; *files counts those written. */
static int view_frame(view **v, const world *w, const view_settings *s, long frame, int *files,
                      char *err, size_t errlen)
{
    int neyes = s->stereo == STEREO_MONO ? 1 : 2;
    /* the folder first: where no file can be written, nothing is drawn */
    if (s->output[0] && view_mkdirs(s->output, err, errlen) != 0) return -1;
    if (view_render_eyes(v, w, NULL, s, neyes, err, errlen) != 0) return -1;
    view *vw = *v;
    view_file f[2];
    int n = 1;
    switch (s->stereo) {
    case STEREO_PAIR:
        view_file_init(&f[0], s->output, frame, "left", vw->eye[0], vw->w, vw->h);
        view_file_init(&f[1], s->output, frame, "right", vw->eye[1], vw->w, vw->h);
        n = 2;
        break;
    case STEREO_SBS:
    case STEREO_ANAGLYPH: {
        int pw, ph;
        const unsigned char *pic = view_picture(vw, s->stereo, &pw, &ph);
        view_file_init(&f[0], s->output, frame, s->stereo == STEREO_SBS ? "sbs" : "anaglyph", pic, pw, ph);
        break;
    }
    case STEREO_MONO:
        view_file_init(&f[0], s->output, frame, "left", vw->eye[0], vw->w, vw->h);
        break;
    default:
        snprintf(err, errlen, "unknown stereo mode %d", (int)s->stereo);
        return -1;
    }
    return view_write_files(f, n, files, err, errlen);
}

int view_refresh(view **v, const world *w, const view_settings *vs, long frame, view_stats *st,
                 char *err, size_t errlen)
{
    double t0 = view_now();
    int files = 0;
    int rc = view_frame(v, w, vs, frame, &files, err, errlen);
    if (st) {
        st->render_time += view_now() - t0;
        st->frames_written += files;
    }
    return rc;
}
