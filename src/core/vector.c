/* Vector helpers that are not worth inlining. */
#include "cg/core.h"

cg_vec2 cg_vec2_normalize(cg_vec2 a)
{
    double length = cg_vec2_length(a);
    return length > 0 ? cg_vec2_scale(a, 1.0 / length) : a;
}

cg_vec3 cg_vec3_normalize(cg_vec3 a)
{
    double length = cg_vec3_length(a);
    return length > 0 ? cg_vec3_scale(a, 1.0 / length) : a;
}
