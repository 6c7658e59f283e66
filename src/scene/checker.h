/* Private: checker materials as geometry for the rasterizer (checker.c). */
#ifndef CG_SCENE_CHECKER_H
#define CG_SCENE_CHECKER_H

#include "cg/mesh.h"

/* The cells of a checker: origin, 1 to 3 unit axes and the cell size. */
typedef struct checker_frame {
    cg_vec3 origin;
    cg_vec3 axis[3];
    int axes;
    double size;
} checker_frame;

/* part (in world space) cut along the cell boundaries of frame, each piece
 * coloured even or odd by its cell.  CG_ERANGE when the cells are so small
 * that one object would be cut into more than 2^22 pieces. */
cg_status scene_checker_split(const cg_mesh *part, const checker_frame *frame, cg_rgbaf even,
                              cg_rgbaf odd, cg_mesh **out);

#endif
