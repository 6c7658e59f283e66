/* Wireframe and hidden-line drawing with Bresenham's line algorithm
 * (cg_draw_line).  Edges are clipped in homogeneous coordinates like the
 * faces.  For hidden lines the depth buffer of the rendered faces decides,
 * sample by sample along each edge, which parts are visible; each visible
 * run is then drawn as one Bresenham line. */
#include "internal.h"
#include "cg/color.h"
#include "cg/draw.h"

/* Whether a face, through the largest triangle of its triangulation, is
 * turned away from the camera, tested in world space (the first three
 * corners of a concave face may turn the other way). */
static int back_facing(const render_frame *f, uint32_t a, uint32_t b, uint32_t c)
{
    float p[3], q[3], r[3];
    render_world_position(f, a, p);
    render_world_position(f, b, q);
    render_world_position(f, c, r);
    double u[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
    double v[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
    double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    double view[3];
    if (f->lighting.orthographic)
        for (int k = 0; k < 3; k++)
            view[k] = f->lighting.view_dir[k];
    else
        for (int k = 0; k < 3; k++)
            view[k] = f->lighting.eye[k] - p[k];
    return n[0] * view[0] + n[1] * view[1] + n[2] * view[2] <= 0;
}

static int pixel(double v, int size)
{
    double p = floor(v);
    if (p < 0)
        p = 0;
    if (p > size - 1)
        p = size - 1;
    return (int)p;
}

/* Largest depth in the 3 x 3 pixels around (x, y). */
static float depth_around(const render_frame *f, int x, int y)
{
    float m = 0;
    for (int dy = -1; dy <= 1; dy++)
        for (int dx = -1; dx <= 1; dx++) {
            int px = x + dx, py = y + dy;
            if (px < 0 || py < 0 || px >= f->width || py >= f->height)
                return INFINITY;
            float z = f->depth[(size_t)py * f->width + px];
            if (z > m)
                m = z;
        }
    return m;
}

#define LINE_DEPTH_TOLERANCE 2e-5f

static void draw_visible(const render_frame *f, const screen_vertex *a, const screen_vertex *b,
                         cg_rgba8 color)
{
    double dx = b->x - a->x, dy = b->y - a->y;
    int steps = (int)ceil(fmax(fabs(dx), fabs(dy)));
    if (steps < 1)
        steps = 1;
    int run_start = -1, last_x = 0, last_y = 0, start_x = 0, start_y = 0;
    for (int i = 0; i <= steps; i++) {
        double t = (double)i / steps;
        int x = pixel(a->x + t * dx, f->width), y = pixel(a->y + t * dy, f->height);
        float z = (float)(a->z + t * (b->z - a->z));
        int visible = z <= depth_around(f, x, y) + LINE_DEPTH_TOLERANCE;
        if (visible && run_start < 0) {
            run_start = i;
            start_x = x;
            start_y = y;
        }
        if (!visible && run_start >= 0) {
            cg_draw_line(f->image, start_x, start_y, last_x, last_y, color);
            run_start = -1;
        }
        last_x = x;
        last_y = y;
    }
    if (run_start >= 0)
        cg_draw_line(f->image, start_x, start_y, last_x, last_y, color);
}

cg_status render_edges(render_frame *f)
{
    const cg_renderer *r = f->r;
    cg_rgba8 color = cg_linear_to_rgba8(f->o->edge_color);
    int hidden = f->o->edges != CG_EDGES_WIREFRAME;
    for (size_t e = 0; e < r->edge_count; e++) {
        uint32_t face = r->edges[e][2];
        if (f->cull) {
            const uint32_t *t = r->triangles[r->face_triangle[face]];
            if (back_facing(f, t[0], t[1], t[2]))
                continue;
        }
        clip_vertex p, q;
        const frame_vertex *va = &f->vertices[r->edges[e][0]], *vb = &f->vertices[r->edges[e][1]];
        if ((va->outcode | vb->outcode) & 0x40)
            continue;
        render_clip_position(f, r->edges[e][0], p.c);
        render_clip_position(f, r->edges[e][1], q.c);
        if (!render_clip_segment(&p, &q, 0) || !(p.c[3] > 0) || !(q.c[3] > 0))
            continue;
        screen_vertex s, t;
        render_project(&p, f->width, f->height, 0, &s);
        render_project(&q, f->width, f->height, 0, &t);
        if (hidden)
            draw_visible(f, &s, &t, color);
        else
            cg_draw_line(f->image, pixel(s.x, f->width), pixel(s.y, f->height),
                         pixel(t.x, f->width), pixel(t.y, f->height), color);
    }
    return CG_OK;
}
