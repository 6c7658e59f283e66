/* Framing a box and fitting the depth range: where a camera stands, what
 * it calls up, and where its near and far planes lie for a given box. */
#include "cg/xform.h"

/* The projected box fills 1 / FRAME_MARGIN of the picture's width or height. */
#define FRAME_MARGIN 1.05
/* The least distance from a framing eye to the box, in box diagonals. */
#define FRAME_STANDOFF 0.05
/* A perspective near plane stays at least this fraction of far, so the
 * float depth buffer keeps about 1,600 steps per depth unit at far. */
#define NEAR_FAR_RATIO 1e-4

/* The eight corners of [lo, hi]. */
static void box_corners(cg_vec3 lo, cg_vec3 hi, cg_vec3 corners[8])
{
    for (int i = 0; i < 8; i++)
        corners[i] = cg_vec3_make(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z);
}

static int box_is_valid(cg_vec3 lo, cg_vec3 hi)
{
    return hi.x >= lo.x && hi.y >= lo.y && hi.z >= lo.z && isfinite(lo.x) && isfinite(lo.y)
           && isfinite(lo.z) && isfinite(hi.x) && isfinite(hi.y) && isfinite(hi.z);
}

cg_vec3 cg_camera_up_for(cg_vec3 direction, cg_vec3 up)
{
    double d = cg_vec3_length(direction), u = cg_vec3_length(up);
    if (!(d > 0) || !isfinite(d))
        return up;
    if (u > 0 && cg_vec3_length(cg_vec3_cross(direction, up)) > 1e-9 * d * u)
        return up;
    /* Looking along up: tilt up the way a camera pitching onto that
     * direction would, toward the world axis least aligned with up (z before
     * x before y on ties), so the default up gives -z on top looking down
     * and +z on top looking up, x to the right in both. */
    cg_vec3 reference = u > 0 ? up : cg_vec3_make(0, 1, 0);
    double ax = fabs(reference.x), ay = fabs(reference.y), az = fabs(reference.z);
    cg_vec3 axis = az <= ax && az <= ay ? cg_vec3_make(0, 0, 1)
                   : ax <= ay           ? cg_vec3_make(1, 0, 0)
                                        : cg_vec3_make(0, 1, 0);
    double sign = cg_vec3_dot(direction, reference) >= 0 ? 1 : -1;
    cg_vec3 f = cg_vec3_scale(direction, 1 / d);
    cg_vec3 tilted = cg_vec3_sub(axis, cg_vec3_scale(f, cg_vec3_dot(axis, f)));
    return cg_vec3_scale(cg_vec3_normalize(tilted), sign);
}

cg_status cg_camera_fit_depth(cg_camera *camera, cg_vec3 lo, cg_vec3 hi)
{
    if (!camera || !box_is_valid(lo, hi))
        return CG_EINVAL;
    cg_mat4 view;
    cg_status s = cg_camera_view(camera, &view);
    if (s != CG_OK)
        return s;
    cg_vec3 corners[8];
    box_corners(lo, hi, corners);
    double nearest = INFINITY, farthest = -INFINITY;
    for (int i = 0; i < 8; i++) {
        double depth = -cg_mat4_transform_point(view, corners[i]).z;
        nearest = fmin(nearest, depth);
        farthest = fmax(farthest, depth);
    }
    /* A little room on both sides, so faces lying on the box keep clear of
     * the clip planes after rounding: 0.1% of the range and 1e-5 of the
     * depth (the ray tracer's hit distances carry float rounding). */
    double pad = 1e-3 * (farthest - nearest) + 1e-5 * fmax(fabs(nearest), fabs(farthest));
    if (!(pad > 0))
        pad = 1e-9 * cg_vec3_length(cg_vec3_sub(camera->target, camera->eye));
    double near = nearest - pad, far = farthest + pad;
    if (!camera->orthographic) {
        if (nearest > 0) /* the padding never takes more than 0.1% of nearest */
            near = fmax(near, nearest * (1 - 1e-3));
        if (!(far > 0)) /* the box is behind the eye: an empty, valid range */
            far = cg_vec3_length(cg_vec3_sub(camera->target, camera->eye));
        if (!(near >= far * NEAR_FAR_RATIO))
            near = far * NEAR_FAR_RATIO;
    }
    if (!(far > near) || !isfinite(near) || !isfinite(far))
        return CG_EINVAL;
    camera->near = near;
    camera->far = far;
    return CG_OK;
}

/* The tightest eye position across one image axis: the eye at lateral
 * offset *offset and depth *depth (both along the camera's axes) sees every
 * point (x[i], z[i]) within the half-angle whose tangent is slope. */
static void fit_axis(const double *x, const double *z, double slope, double *offset, double *depth)
{
    double a = -INFINITY, b = INFINITY;
    for (int i = 0; i < 8; i++) {
        a = fmax(a, x[i] - slope * z[i]); /* the eye is right of every left bound */
        b = fmin(b, x[i] + slope * z[i]); /* and left of every right bound */
    }
    *offset = (a + b) / 2;
    *depth = (b - a) / (2 * slope);
}

cg_status cg_camera_frame(cg_camera *camera, cg_vec3 lo, cg_vec3 hi, double aspect)
{
    if (!camera || !box_is_valid(lo, hi) || !(aspect > 0) || !isfinite(aspect))
        return CG_EINVAL;
    double diagonal = cg_vec3_length(cg_vec3_sub(hi, lo));
    if (!isfinite(diagonal))
        return CG_EINVAL;
    if (diagonal == 0) { /* a point: frame the cube of side 2 around it */
        lo = cg_vec3_sub(lo, cg_vec3_make(1, 1, 1));
        hi = cg_vec3_add(hi, cg_vec3_make(1, 1, 1));
        diagonal = cg_vec3_length(cg_vec3_sub(hi, lo));
    }
    cg_vec3 forward = cg_vec3_sub(camera->target, camera->eye);
    if (!(cg_vec3_length(forward) > 0) || !isfinite(cg_vec3_length(forward)))
        forward = cg_vec3_make(0, 0, -1);
    forward = cg_vec3_normalize(forward);
    camera->up = cg_camera_up_for(forward, camera->up);
    cg_vec3 right = cg_vec3_normalize(cg_vec3_cross(forward, camera->up));
    cg_vec3 up = cg_vec3_cross(right, forward);

    /* The box's corners in the camera's axes (origin at the world's). */
    cg_vec3 corners[8];
    double x[8], y[8], z[8];
    box_corners(lo, hi, corners);
    double x_lo = INFINITY, x_hi = -INFINITY, y_lo = INFINITY, y_hi = -INFINITY;
    double z_lo = INFINITY, z_hi = -INFINITY;
    for (int i = 0; i < 8; i++) {
        x[i] = cg_vec3_dot(corners[i], right);
        y[i] = cg_vec3_dot(corners[i], up);
        z[i] = cg_vec3_dot(corners[i], forward);
        x_lo = fmin(x_lo, x[i]), x_hi = fmax(x_hi, x[i]);
        y_lo = fmin(y_lo, y[i]), y_hi = fmax(y_hi, y[i]);
        z_lo = fmin(z_lo, z[i]), z_hi = fmax(z_hi, z[i]);
    }
    double ex, ey, ez;
    if (camera->orthographic) {
        /* Centre the projected box; its taller side (in picture units)
         * sets the height. */
        ex = (x_lo + x_hi) / 2;
        ey = (y_lo + y_hi) / 2;
        ez = z_lo - diagonal;
        double height = fmax(y_hi - y_lo, (x_hi - x_lo) / aspect);
        camera->ortho_height = (height > 0 ? height : diagonal) * FRAME_MARGIN;
    } else {
        /* Every corner inside the four side planes of the frustum, the eye
         * as close as they allow: the projected box touches two opposite
         * sides (less the margin) and is centred across the other axis. */
        double ty = tan(camera->fovy / 2) / FRAME_MARGIN, tx = ty * aspect;
        double dx, dy;
        fit_axis(x, z, tx, &ex, &dx);
        fit_axis(y, z, ty, &ey, &dy);
        ez = fmin(dx, dy);
        /* A corner pointing at the eye of a wide field of view lets the
         * eye come right up to it: keep a twentieth of the box away. */
        ez = fmin(ez, z_lo - FRAME_STANDOFF * diagonal);
    }
    cg_vec3 eye = cg_vec3_add(cg_vec3_add(cg_vec3_scale(right, ex), cg_vec3_scale(up, ey)),
                              cg_vec3_scale(forward, ez));
    double to_centre = (z_lo + z_hi) / 2 - ez;
    camera->eye = eye;
    camera->target = cg_vec3_add(eye, cg_vec3_scale(forward, to_centre));
    return cg_camera_fit_depth(camera, lo, hi);
}
