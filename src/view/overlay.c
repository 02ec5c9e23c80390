/* overlay.c: the hand's pointer and the virtual tool panel, drawn in both eyes
 * (thesis Appendix A.1.2; language.md, "The hand and the tool panel").
 *
 * The pointer is a slim four-sided pyramid, its tip at the hand's point and its
 * base 8 cm behind along the hand's -x, 2.4 cm across; where that would be fewer
 * than OVERLAY_POINTER_MIN_PX pixels (the hand far from the eye) the whole
 * pointer is drawn larger about its tip, so that it is never lost.  The panel is a dark sheet with light
 * buttons (a lit one green), each with its picture (the tape player's stop,
 * play and step, and a pointer for select) and its label, and the sliders as a
 * track with a knob at the value and a label above.  Buttons stand 2 mm in front
 * of the sheet and pictures and labels 4 mm, so the depth test keeps them in
 * order; all of it is drawn two-sided, and hidden by objects in front of it.
 * Labels are 13 mm tall: 9 to 10 pixels in a 640x512 view at 60 degrees from
 * 0.6 m, drawn with 2-pixel strokes (font.h).
 */
#include "overlay.h"

#include <math.h>

#include "font.h"
#include "gl_load.h"

#define POINTER_LENGTH 0.08
#define POINTER_HALF 0.012
#define BUTTON_Z 0.002  /* in front of the sheet */
#define MARK_Z 0.004    /* pictures, labels, knobs */
#define LABEL_H 0.013

void overlay_pose_matrix(vec3 x, quat q, GLdouble m[16])
{
    mat3 r = q_len(q) > 0 ? m3_from_quat(q_normalize(q)) : m3_identity();
    for (int col = 0; col < 3; col++) {
        for (int row = 0; row < 3; row++) m[col * 4 + row] = r.m[row][col];
        m[col * 4 + 3] = 0;
    }
    m[12] = x.x;
    m[13] = x.y;
    m[14] = x.z;
    m[15] = 1;
}

/* A rectangle in the plane z, facing +z. */
static void rect(double x0, double y0, double x1, double y1, double z)
{
    glNormal3d(0, 0, 1);
    glBegin(GL_QUADS);
    glVertex3d(x0, y0, z);
    glVertex3d(x1, y0, z);
    glVertex3d(x1, y1, z);
    glVertex3d(x0, y1, z);
    glEnd();
}

static void triangle(double ax, double ay, double bx, double by, double cx, double cy, double z)
{
    glBegin(GL_TRIANGLES);
    glVertex3d(ax, ay, z);
    glVertex3d(bx, by, z);
    glVertex3d(cx, cy, z);
    glEnd();
}

/* Pushes the model-view and moves it to the pose (x, q). */
static void push_pose(vec3 x, quat q)
{
    GLdouble m[16];
    overlay_pose_matrix(x, q, m);
    glPushMatrix();
    glMultMatrixd(m);
}

/* The pointer, scale times its size about its tip. */
static void draw_pointer(const view_overlay *o, double scale)
{
    push_pose(o->hand_p, o->hand_q);
    glColor3ub(255, 220, 110);
    const double L = scale * POINTER_LENGTH, h = scale * POINTER_HALF;
    const double base[4][2] = {{h, h}, {-h, h}, {-h, -h}, {h, -h}};
    glBegin(GL_TRIANGLES);
    for (int k = 0; k < 4; k++) {
        const double *a = base[k], *b = base[(k + 1) % 4];
        vec3 n = v3_norm(v3_cross(v3(-L, a[0], a[1]), v3(-L, b[0], b[1])));
        glNormal3d(n.x, n.y, n.z);
        glVertex3d(0, 0, 0);
        glVertex3d(-L, a[0], a[1]);
        glVertex3d(-L, b[0], b[1]);
    }
    glEnd();
    glNormal3d(-1, 0, 0);
    glBegin(GL_QUADS);
    for (int k = 0; k < 4; k++) glVertex3d(-L, base[k][0], base[k][1]);
    glEnd();
    glPopMatrix();
}

/* A button's picture, about (x, y), s across. */
static void icon(view_icon k, double x, double y, double s)
{
    double h = 0.5 * s;
    switch (k) {
    case VIEW_ICON_STOP: rect(x - 0.8 * h, y - 0.8 * h, x + 0.8 * h, y + 0.8 * h, MARK_Z); break;
    case VIEW_ICON_START: triangle(x - 0.7 * h, y - h, x + h, y, x - 0.7 * h, y + h, MARK_Z); break;
    case VIEW_ICON_STEP:
        rect(x - h, y - h, x - 0.55 * h, y + h, MARK_Z);
        triangle(x - 0.3 * h, y - h, x + h, y, x - 0.3 * h, y + h, MARK_Z);
        break;
    case VIEW_ICON_SELECT: /* a pointer aimed up and to the left */
        triangle(x - h, y + h, x + 0.2 * h, y - 0.1 * h, x - 0.1 * h, y + 0.2 * h, MARK_Z);
        triangle(x - h, y + h, x - 0.1 * h, y + 0.2 * h, x - 0.75 * h, y - 0.4 * h, MARK_Z);
        triangle(x - 0.35 * h, y + 0.05 * h, x - 0.15 * h, y + 0.25 * h, x + h, y - 0.9 * h, MARK_Z); /* the stem */
        triangle(x - 0.35 * h, y + 0.05 * h, x + h, y - 0.9 * h, x + 0.8 * h, y - h, MARK_Z);
        break;
    default: break;
    }
}

static void draw_panel(const view_overlay *o)
{
    push_pose(o->panel_at, o->panel_q);
    glColor3ub(52, 58, 70);
    rect(-o->half_w, -o->half_h, o->half_w, o->half_h, 0);
    for (int i = 0; i < o->ncontrols; i++) { /* buttons and the sliders' tracks */
        const view_control *c = &o->controls[i];
        if (c->slider) {
            glColor3ub(150, 150, 160);
            rect(c->x - c->half_w, c->y - 0.002, c->x + c->half_w, c->y + 0.002, BUTTON_Z);
            glColor3ub(245, 180, 40);
            rect(c->knob - 0.009, c->y - 0.009, c->knob + 0.009, c->y + 0.009, MARK_Z);
        } else {
            if (c->lit) glColor3ub(95, 195, 95);
            else glColor3ub(205, 205, 212);
            rect(c->x - c->half_w, c->y - c->half_h, c->x + c->half_w, c->y + c->half_h, BUTTON_Z);
        }
    }
    glDisable(GL_LIGHTING);
    glLineWidth(2.0f);
    for (int i = 0; i < o->ncontrols; i++) { /* pictures and labels */
        const view_control *c = &o->controls[i];
        if (c->slider) {
            glColor3ub(235, 235, 240);
            font_draw(c->label, c->x - c->half_w, c->y + 0.0115, MARK_Z, LABEL_H);
        } else {
            glColor3ub(20, 22, 28);
            icon(c->icon, c->x, c->y + 0.012, 0.03);
            font_draw(c->label, c->x - 0.5 * font_width(c->label, LABEL_H), c->y - 0.034, MARK_Z, LABEL_H);
        }
    }
    glLineWidth(1.0f);
    glEnable(GL_LIGHTING);
    glPopMatrix();
}

void overlay_draw(const view_overlay *o, vec3 eye, vec3 ahead, double pixel)
{
    if (!o->hand && !o->panel) return;
    glDisable(GL_CULL_FACE);
    if (o->panel) draw_panel(o);
    if (o->hand) {
        double d = v3_dot(v3_sub(o->hand_p, eye), ahead); /* the tip's depth */
        double want = 0.5 * OVERLAY_POINTER_MIN_PX * pixel * d;
        draw_pointer(o, d > 0 && want > POINTER_HALF ? want / POINTER_HALF : 1);
    }
    glEnable(GL_CULL_FACE);
}
