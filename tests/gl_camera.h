/* Loading a cg camera into OpenGL's fixed-function matrices, shared by the
 * OSMesa comparison test and the rendering benchmark. */
#ifndef CG_TEST_GL_CAMERA_H
#define CG_TEST_GL_CAMERA_H

#include "cg/xform.h"

#include <GL/gl.h>

/* A cg matrix (row-major, column vectors) as OpenGL's column-major array. */
static inline void gl_camera_matrix(cg_mat4 m, GLdouble out[16])
{
    for (int r = 0; r < 4; r++)
        for (int c = 0; c < 4; c++)
            out[c * 4 + r] = m.m[r][c];
}

/* Viewport, projection and (unless view_later) the view matrix of camera for
 * a width x height image; with view_later the modelview is left at the
 * identity and *view receives the matrix to load once world-space lights are
 * placed.  0 on success. */
static inline int gl_load_camera(const cg_camera *camera, int width, int height, int view_later,
                                 GLdouble view[16])
{
    cg_mat4 v, p;
    if (cg_camera_view(camera, &v) != CG_OK
        || cg_camera_projection(camera, (double)width / height, &p) != CG_OK)
        return -1;
    GLdouble m[16];
    glViewport(0, 0, width, height);
    glMatrixMode(GL_PROJECTION);
    gl_camera_matrix(p, m);
    glLoadMatrixd(m);
    glMatrixMode(GL_MODELVIEW);
    gl_camera_matrix(v, view);
    if (view_later)
        glLoadIdentity();
    else
        glLoadMatrixd(view);
    return 0;
}

#endif
