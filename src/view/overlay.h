/* overlay.h: drawing the hand's pointer and the tool panel over the world, in the
 * eye being drawn (view.c calls it; view.h's view_overlay says what to draw). */
#ifndef VROC_OVERLAY_H
#define VROC_OVERLAY_H

#include <GL/gl.h>

#include "view.h"

/* The OpenGL (column-major) matrix of the rigid map x + q p (q renormalised, so
 * that a drifting quaternion cannot scale the normals and the lighting). */
void overlay_pose_matrix(vec3 x, quat q, GLdouble m[16]);

/* The hand's pointer is never narrower than this many pixels across, however far
 * the hand is: it is drawn larger where it would be smaller. */
#define OVERLAY_POINTER_MIN_PX 12

/* Draws o with the eye's matrices loaded, lighting and culling on (it leaves them
 * on), over what is drawn already (the depth test on).  The eye is at eye,
 * looking along the unit vector ahead; pixel is the width of a pixel one metre
 * ahead of it (d times that at depth d), by which the pointer keeps
 * OVERLAY_POINTER_MIN_PX. */
void overlay_draw(const view_overlay *o, vec3 eye, vec3 ahead, double pixel);

#endif
