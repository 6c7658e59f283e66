/* Continuity at the joint of two segments (G0, G1, C1) and builders of
 * C1 and G1 joins (section 2.3.1). */
#include "cg/curve.h"

const char *cg_continuity_name(cg_continuity continuity)
{
    switch (continuity) {
    case CG_CONTINUITY_NONE: return "none";
    case CG_CONTINUITY_G0: return "G0";
    case CG_CONTINUITY_G1: return "G1";
    case CG_CONTINUITY_C1: return "C1";
    }
    return "unknown";
}

static int near2(cg_vec2 a, cg_vec2 b, double tolerance)
{
    return cg_vec2_length(cg_vec2_sub(a, b)) <= tolerance;
}

cg_continuity cg_joint_continuity(cg_vec2 end_a, cg_vec2 tangent_a, cg_vec2 start_b,
                                  cg_vec2 tangent_b, double tolerance)
{
    if (!(tolerance >= 0) || !near2(end_a, start_b, tolerance))
        return CG_CONTINUITY_NONE;
    if (near2(tangent_a, tangent_b, tolerance))
        return CG_CONTINUITY_C1;
    double la = cg_vec2_length(tangent_a), lb = cg_vec2_length(tangent_b);
    if (la <= tolerance || lb <= tolerance)
        return CG_CONTINUITY_G0; /* one side has no direction */
    if (near2(cg_vec2_scale(tangent_a, 1 / la), cg_vec2_scale(tangent_b, 1 / lb), tolerance))
        return CG_CONTINUITY_G1;
    return CG_CONTINUITY_G0;
}

cg_continuity cg_cubic2_continuity(const cg_cubic2 *a, const cg_cubic2 *b, double tolerance)
{
    return cg_joint_continuity(cg_cubic2_point(a, 1), cg_cubic2_tangent(a, 1),
                               cg_cubic2_point(b, 0), cg_cubic2_tangent(b, 0), tolerance);
}

cg_continuity cg_cubic3_continuity(const cg_cubic3 *a, const cg_cubic3 *b, double tolerance)
{
    cg_vec3 pa = cg_cubic3_point(a, 1), pb = cg_cubic3_point(b, 0);
    cg_vec3 ta = cg_cubic3_tangent(a, 1), tb = cg_cubic3_tangent(b, 0);
    if (!(tolerance >= 0) || !(cg_vec3_length(cg_vec3_sub(pa, pb)) <= tolerance))
        return CG_CONTINUITY_NONE;
    if (cg_vec3_length(cg_vec3_sub(ta, tb)) <= tolerance)
        return CG_CONTINUITY_C1;
    double la = cg_vec3_length(ta), lb = cg_vec3_length(tb);
    if (la <= tolerance || lb <= tolerance)
        return CG_CONTINUITY_G0;
    cg_vec3 d = cg_vec3_sub(cg_vec3_scale(ta, 1 / la), cg_vec3_scale(tb, 1 / lb));
    return cg_vec3_length(d) <= tolerance ? CG_CONTINUITY_G1 : CG_CONTINUITY_G0;
}

/* Sets b's start point and start tangent through its Hermite form. */
static cg_status set_start(cg_cubic2 *b, cg_vec2 point, cg_vec2 tangent)
{
    cg_cubic2 h;
    cg_status status = cg_cubic2_convert(b, CG_BASIS_HERMITE, &h);
    if (status != CG_OK)
        return status;
    h.g[0] = point;
    h.g[2] = tangent;
    return cg_cubic2_convert(&h, b->basis, b);
}

cg_status cg_cubic2_join_c1(const cg_cubic2 *a, cg_cubic2 *b)
{
    if (!a || !b)
        return CG_EINVAL;
    return set_start(b, cg_cubic2_point(a, 1), cg_cubic2_tangent(a, 1));
}

cg_status cg_cubic2_join_g1(const cg_cubic2 *a, cg_cubic2 *b)
{
    if (!a || !b)
        return CG_EINVAL;
    cg_vec2 ta = cg_cubic2_tangent(a, 1);
    double la = cg_vec2_length(ta);
    if (!(la > 0) || !isfinite(la))
        return CG_EINVAL;
    double lb = cg_vec2_length(cg_cubic2_tangent(b, 0));
    if (!(lb > 0) || !isfinite(lb))
        lb = la;
    return set_start(b, cg_cubic2_point(a, 1), cg_vec2_scale(ta, lb / la));
}
