/* gl_load.h: OSMesa and the OpenGL calls the views make, loaded with dlopen when a
 * view is first made, so that a run that draws nothing never maps Mesa (and its
 * LLVM: some 50 MB and most of the start-up time) at all.
 *
 * It brings in <GL/gl.h> and <GL/osmesa.h>: each function the views call is a
 * pointer (gl_api) with the function's own type, and its name a macro that calls
 * through it, so that view.c reads as plain OpenGL.  gl_load must have succeeded
 * before any of them is called.
 */
#ifndef VROC_GL_LOAD_H
#define VROC_GL_LOAD_H

#include <GL/gl.h>
#include <GL/osmesa.h>
#include <stddef.h>

/* Every function the views call: X(name). */
#define GL_LOAD_FUNCS(X)                                                                     \
    X(OSMesaCreateContextExt) X(OSMesaDestroyContext) X(OSMesaGetCurrentContext)             \
    X(OSMesaMakeCurrent) X(OSMesaPixelStore) X(glBegin) X(glClear) X(glClearColor)          \
    X(glColor3ub) X(glColor3ubv) X(glColorMaterial) X(glCullFace) X(glDepthFunc) X(glDisable)              \
    X(glDisableClientState) X(glDrawRangeElements) X(glEnable) X(glEnableClientState)        \
    X(glEnd) X(glFinish) X(glFrontFace) X(glFrustum) X(glGetError) X(glLightModelfv)        \
    X(glLightModeli)                                                                         \
    X(glLightfv) X(glLineWidth) X(glLoadIdentity) X(glLoadMatrixd) X(glMaterialf) X(glMaterialfv)          \
    X(glMatrixMode) X(glMultMatrixd) X(glNormal3d) X(glNormalPointer) X(glPixelStorei) X(glPolygonMode)   \
    X(glPopMatrix) X(glPushMatrix) X(glScissor) X(glShadeModel) X(glVertex3d)              \
    X(glVertexPointer) X(glViewport)

#define GL_LOAD_POINTER(name) __typeof__(name) *p_##name;
typedef struct {
    GL_LOAD_FUNCS(GL_LOAD_POINTER)
} gl_api;
#undef GL_LOAD_POINTER

extern gl_api gl_load_api;

/* Loads OSMesa (once: later calls return at once).  Returns 0, or -1 with why in
 * err. */
int gl_load(char *err, size_t errlen);

#ifndef GL_LOAD_NO_MACROS
#define OSMesaCreateContextExt (*gl_load_api.p_OSMesaCreateContextExt)
#define OSMesaDestroyContext (*gl_load_api.p_OSMesaDestroyContext)
#define OSMesaGetCurrentContext (*gl_load_api.p_OSMesaGetCurrentContext)
#define OSMesaMakeCurrent (*gl_load_api.p_OSMesaMakeCurrent)
#define OSMesaPixelStore (*gl_load_api.p_OSMesaPixelStore)
#define glBegin (*gl_load_api.p_glBegin)
#define glClear (*gl_load_api.p_glClear)
#define glClearColor (*gl_load_api.p_glClearColor)
#define glColor3ub (*gl_load_api.p_glColor3ub)
#define glColor3ubv (*gl_load_api.p_glColor3ubv)
#define glColorMaterial (*gl_load_api.p_glColorMaterial)
#define glCullFace (*gl_load_api.p_glCullFace)
#define glDepthFunc (*gl_load_api.p_glDepthFunc)
#define glDisable (*gl_load_api.p_glDisable)
#define glDisableClientState (*gl_load_api.p_glDisableClientState)
#define glDrawRangeElements (*gl_load_api.p_glDrawRangeElements)
#define glEnable (*gl_load_api.p_glEnable)
#define glEnableClientState (*gl_load_api.p_glEnableClientState)
#define glEnd (*gl_load_api.p_glEnd)
#define glFinish (*gl_load_api.p_glFinish)
#define glFrontFace (*gl_load_api.p_glFrontFace)
#define glFrustum (*gl_load_api.p_glFrustum)
#define glGetError (*gl_load_api.p_glGetError)
#define glLightModelfv (*gl_load_api.p_glLightModelfv)
#define glLightModeli (*gl_load_api.p_glLightModeli)
#define glLightfv (*gl_load_api.p_glLightfv)
#define glLineWidth (*gl_load_api.p_glLineWidth)
#define glLoadIdentity (*gl_load_api.p_glLoadIdentity)
#define glLoadMatrixd (*gl_load_api.p_glLoadMatrixd)
#define glMaterialf (*gl_load_api.p_glMaterialf)
#define glMaterialfv (*gl_load_api.p_glMaterialfv)
#define glMatrixMode (*gl_load_api.p_glMatrixMode)
#define glMultMatrixd (*gl_load_api.p_glMultMatrixd)
#define glNormal3d (*gl_load_api.p_glNormal3d)
#define glNormalPointer (*gl_load_api.p_glNormalPointer)
#define glPixelStorei (*gl_load_api.p_glPixelStorei)
#define glPolygonMode (*gl_load_api.p_glPolygonMode)
#define glPopMatrix (*gl_load_api.p_glPopMatrix)
#define glPushMatrix (*gl_load_api.p_glPushMatrix)
#define glScissor (*gl_load_api.p_glScissor)
#define glShadeModel (*gl_load_api.p_glShadeModel)
#define glVertex3d (*gl_load_api.p_glVertex3d)
#define glVertexPointer (*gl_load_api.p_glVertexPointer)
#define glViewport (*gl_load_api.p_glViewport)
#endif

#endif
