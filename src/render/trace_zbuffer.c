/* The z-buffer (5.3) at one pixel, step by step (cg/trace_steps.h): every
 * triangle whose screen bounding box holds the pixel's centre, projected as
 * the renderer projects it (W P V M, then the divide by w), tested for
 * covering the centre by its barycentric coordinates, its depth there
 * interpolated (window z is affine in screen x and y), and compared with
 * the buffer's:
 *
 *      depth < buffer: accepted, the buffer takes it (and its colour)
 *      otherwise:      rejected
 *
 * Back faces are culled first when cull is set, as the renderer does. */
#include "cg/render.h"
#include "cg/xform.h"
#include "../core/steps.h"

#include <math.h>
#include <stdlib.h>

typedef struct screen_triangle {
    cg_vec3 v[3]; /* window x, y, depth */
    int behind;   /* a vertex has w <= 0: the renderer clips it */
} screen_triangle;

static screen_triangle project(cg_mat4 whole, const cg_vec3 world[3])
{
    screen_triangle t = {{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, 0};
    for (int k = 0; k < 3; k++) {
        int visible;
        t.v[k] = cg_project_point(whole, world[k], &visible);
        t.behind |= !visible;
    }
    return t;
}

/* Barycentric coordinates of (x, y) in the screen triangle; 0 when it has
 * no area. */
static int barycentric(const screen_triangle *t, double x, double y, double out[3])
{
    const cg_vec3 *a = &t->v[0], *b = &t->v[1], *c = &t->v[2];
    double area = (b->x - a->x) * (c->y - a->y) - (b->y - a->y) * (c->x - a->x);
    if (area == 0)
        return 0;
    out[0] = ((b->x - x) * (c->y - y) - (b->y - y) * (c->x - x)) / area;
    out[1] = ((c->x - x) * (a->y - y) - (c->y - y) * (a->x - x)) / area;
    out[2] = 1 - out[0] - out[1];
    return 1;
}

typedef struct zbuffer_pixel {
    double x, y;   /* the pixel centre */
    double buffer; /* the depth so far (INFINITY: the background) */
    long winner;   /* the triangle that set it, or -1 */
    cg_step_fn fn;
    void *user;
} zbuffer_pixel;

static int emit_fragment(zbuffer_pixel *z, size_t triangle, size_t face, const screen_triangle *t,
                         const double *weights, double depth, const char *decision)
{
    cg_vec2 outline[4];
    for (int k = 0; k < 3; k++)
        outline[k] = cg_vec2_make(t->v[k].x, t->v[k].y);
    outline[3] = outline[0];
    double screen[9];
    for (int k = 0; k < 3; k++) {
        screen[3 * k] = t->v[k].x;
        screen[3 * k + 1] = t->v[k].y;
        screen[3 * k + 2] = t->v[k].z;
    }
    core_step s;
    core_step_begin(&s, "fragments");
    core_step_integer(&s, "triangle", (long long)triangle);
    core_step_integer(&s, "face", (long long)face);
    core_step_reals(&s, "window_xyz", screen, 9);
    if (weights)
        core_step_reals(&s, "barycentric", weights, 3);
    else
        core_step_none(&s, "barycentric");
    if (isfinite(depth))
        core_step_real(&s, "depth", depth);
    else
        core_step_none(&s, "depth");
    core_step_real(&s, "buffer", z->buffer);
    core_step_text(&s, "decision", decision);
    s.step.geometry = outline;
    s.step.geometry_count = 4;
    return core_step_emit(&s, z->fn, z->user);
}

/* One triangle at the pixel: 1 when the callback stopped the trace. */
static int test_triangle(zbuffer_pixel *z, size_t triangle, size_t face, const cg_vec3 world[3],
                         cg_mat4 whole, int cull, const cg_camera *camera)
{
    screen_triangle t = project(whole, world);
    double lo_x = fmin(t.v[0].x, fmin(t.v[1].x, t.v[2].x)),
           hi_x = fmax(t.v[0].x, fmax(t.v[1].x, t.v[2].x));
    double lo_y = fmin(t.v[0].y, fmin(t.v[1].y, t.v[2].y)),
           hi_y = fmax(t.v[0].y, fmax(t.v[1].y, t.v[2].y));
    if (!t.behind && !(z->x >= lo_x && z->x <= hi_x && z->y >= lo_y && z->y <= hi_y))
        return 0; /* nowhere near the pixel: not listed */
    if (t.behind)
        return emit_fragment(z, triangle, face, &t, NULL, INFINITY,
                             "a vertex behind the camera: left to the clipper (not traced)");
    cg_vec3 normal = cg_vec3_cross(cg_vec3_sub(world[1], world[0]),
                                   cg_vec3_sub(world[2], world[0]));
    cg_vec3 to_eye = camera->orthographic ? cg_vec3_sub(camera->eye, camera->target)
                                          : cg_vec3_sub(camera->eye, world[0]);
    if (cull && !(cg_vec3_dot(normal, to_eye) > 0))
        return emit_fragment(z, triangle, face, &t, NULL, INFINITY, "back face: culled");
    double w[3];
    if (!barycentric(&t, z->x, z->y, w) || w[0] < 0 || w[1] < 0 || w[2] < 0)
        return emit_fragment(z, triangle, face, &t, barycentric(&t, z->x, z->y, w) ? w : NULL,
                             INFINITY, "the centre is outside: no fragment");
    double depth = w[0] * t.v[0].z + w[1] * t.v[1].z + w[2] * t.v[2].z;
    int accepted = depth < z->buffer && depth >= 0 && depth <= 1;
    const char *decision = depth < 0 || depth > 1 ? "outside the depth range: clipped"
                           : accepted             ? "accepted: nearer than the buffer"
                                                  : "rejected: not nearer";
    int stopped = emit_fragment(z, triangle, face, &t, w, depth, decision);
    if (accepted) {
        z->buffer = depth;
        z->winner = (long)triangle;
    }
    return stopped;
}

cg_status cg_zbuffer_pixel_steps(const cg_mesh *mesh, cg_mat4 model, const cg_camera *camera,
                                 int width, int height, int x, int y, int cull, cg_step_fn step,
                                 void *user)
{
    if (!mesh || !camera || !step || width <= 0 || height <= 0 || x < 0 || y < 0 || x >= width
        || y >= height)
        return CG_EINVAL;
    cg_status status = cg_mesh_validate(mesh, NULL);
    cg_mat4 view, projection;
    if (status != CG_OK)
        return status;
    if (cg_camera_view(camera, &view) != CG_OK
        || cg_camera_projection(camera, (double)width / height, &projection) != CG_OK)
        return CG_EINVAL;
    cg_mat4 whole = cg_mat4_mul(cg_viewport(width, height), cg_mat4_mul(projection, view));
    size_t count = cg_mesh_triangle_count(mesh);
    uint32_t(*corners)[3] = malloc((count ? count : 1) * sizeof *corners);
    if (!corners)
        return CG_ENOMEM;
    zbuffer_pixel z = {x + 0.5, y + 0.5, INFINITY, -1, step, user};
    int stopped = 0;
    /* corners[] holds corner numbers (positions in face_indices) */
    for (size_t f = 0, t = 0; f < mesh->face_count && !stopped; f++) {
        size_t n = cg_mesh_face_size(mesh, f);
        if (n < 3 || cg_mesh_triangulate_face(mesh, f, corners + t) != CG_OK)
            continue;
        for (size_t k = 0; k + 2 < n && !stopped; k++, t++) {
            cg_vec3 world[3];
            for (int c = 0; c < 3; c++)
                world[c] = cg_mat4_transform_point(
                    model, mesh->positions[mesh->face_indices[corners[t][c]]]);
            stopped = test_triangle(&z, t, f, world, whole, cull, camera);
        }
    }
    free(corners);
    if (stopped)
        return CG_OK;
    core_step s;
    int xy[2] = {x, y};
    core_step_begin(&s, "result");
    core_step_pixel(&s, "pixel", x, y);
    if (z.winner >= 0) {
        core_step_integer(&s, "triangle", z.winner);
        core_step_real(&s, "depth", z.buffer);
        s.step.pixels = xy;
        s.step.pixel_count = 1;
    } else {
        core_step_text(&s, "triangle", "none: the background");
        core_step_none(&s, "depth");
    }
    core_step_emit(&s, step, user);
    return CG_OK;
}
