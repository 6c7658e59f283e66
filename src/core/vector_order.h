/* A total order on points, for sorting them and for putting the two ends of
 * a segment in a fixed order (so that the same segment, met from either
 * side, gives the same computed points). */
#ifndef CG_CORE_VECTOR_ORDER_H
#define CG_CORE_VECTOR_ORDER_H

#include "cg/core.h"

/* Whether a comes before b in lexicographic order: by x, then y, then z.
 * (src/clip/mesh_clip.c's pos_less is the same order, to be replaced.) */
static inline int core_vec3_less(cg_vec3 a, cg_vec3 b)
{
    if (a.x != b.x)
        return a.x < b.x;
    if (a.y != b.y)
        return a.y < b.y;
    return a.z < b.z;
}

#endif
