/* Vector helpers that are not worth inlining. */
#include "cg/core.h"

#include <float.h>
#include <math.h>

/* Both normalizations scale by the reciprocal of the length when that is a
 * normal number.  Otherwise the length (or its square) underflowed or
 * overflowed, or 1 / length would: they first divide by the largest
 * component, which makes that one exactly 1 and the length between 1 and
 * sqrt(3).  Zero, NaN and infinite vectors are returned as they are. */

cg_vec2 cg_vec2_normalize(cg_vec2 a)
{
    double length = cg_vec2_length(a);
    if (length >= DBL_MIN && length <= DBL_MAX)
        return cg_vec2_scale(a, 1.0 / length);
    double m = fmax(fabs(a.x), fabs(a.y));
    if (!(m > 0) || isinf(m) || isnan(a.x) || isnan(a.y))
        return a;
    cg_vec2 b = cg_vec2_make(a.x / m, a.y / m);
    return cg_vec2_scale(b, 1.0 / cg_vec2_length(b));
}

cg_vec3 cg_vec3_normalize(cg_vec3 a)
{
    double square = cg_vec3_dot(a, a);
    if (square >= DBL_MIN && square <= DBL_MAX)
        return cg_vec3_scale(a, 1.0 / sqrt(square));
    double m = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
    if (!(m > 0) || isinf(m) || isnan(square))
        return a;
    cg_vec3 b = cg_vec3_make(a.x / m, a.y / m, a.z / m);
    return cg_vec3_scale(b, 1.0 / cg_vec3_length(b));
}
