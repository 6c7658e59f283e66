/* The triangle stage: each triangle of a chunk (a range of the mesh, in
 * mesh order) is rejected when all three corners lie outside one plane of
 * the view volume or one is not finite, culled when it turns its back to the
 * camera, clipped in homogeneous coordinates when it crosses a plane
 * (clip.c), and set up for the rasterizer (setup.c); it is appended to its
 * chunk's list, which the binning then sorts by tile.  A triangle wholly
 * inside the view volume -- nearly all of them -- takes a shorter path from
 * the vertices projected and snapped by the vertex stage.  For the painter's
 * algorithm the stage keeps clipped polygons instead. */
#include "pipeline.h"
#include "cg/color.h"

#include <string.h>

/* Room for one more set-up triangle at the end of the chunk's list (with a
 * whole setup_triangle of slack after it, so that it may be written through
 * that type); NULL when memory runs out.  emit_setup keeps it. */
static setup_triangle *next_setup(render_frame *f, render_chunk *c)
{
    if (c->failed)
        return NULL;
    size_t needed = c->setup_count + 1 + f->setup_slack;
    if (needed <= c->setup_capacity)
        return (setup_triangle *)(c->setups + c->setup_count * f->stride);
    if (core_array_reserve((void **)&c->setups, &c->setup_capacity, needed, f->stride) != CG_OK) {
        c->failed = 1;
        return NULL;
    }
    return (setup_triangle *)(c->setups + c->setup_count * f->stride);
}

static void emit_setup(render_frame *f, render_chunk *c, const setup_triangle *t)
{
    setup_triangle *slot = next_setup(f, c);
    if (!slot)
        return;
    if (slot != t)
        memcpy(slot, t, f->stride);
    c->setup_count++;
}

static void emit_polygon(render_chunk *c, size_t triangle, const screen_vertex *v, int n,
                         const float color[3])
{
    if (c->failed)
        return;
    if (core_array_reserve((void **)&c->polygons, &c->polygon_capacity, c->polygon_count + 1,
                           sizeof *c->polygons)
        != CG_OK) {
        c->failed = 1;
        return;
    }
    painter_polygon *out = &c->polygons[c->polygon_count++];
    out->n = n;
    out->triangle = (uint32_t)triangle;
    memcpy(out->color, color, sizeof out->color);
    memcpy(out->v, v, sizeof *v * (size_t)n);
}

/* Flat colour (or Phong base colour) of triangle i. */
static void triangle_color(const render_frame *f, size_t i, float out[3])
{
    const uint32_t *tri = f->r->triangles[i];
    const prepared_vertex *p0 = &f->r->vertices[tri[0]];
    if (f->fill_background) {
        memcpy(out, f->background, 3 * sizeof(float));
        return;
    }
    if (f->shading != MODE_FLAT) {
        memcpy(out, p0->color, 3 * sizeof(float));
        return;
    }
    float a[3], b[3], c[3];
    world_of(f, f->r->vertices[tri[0]].position, a);
    world_of(f, f->r->vertices[tri[1]].position, b);
    world_of(f, f->r->vertices[tri[2]].position, c);
    double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    double length = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    float normal[3] = {0, 0, 0};
    if (length > 0)
        for (int k = 0; k < 3; k++)
            normal[k] = (float)(n[k] / length);
    float centre[3];
    for (int k = 0; k < 3; k++)
        centre[k] = (a[k] + b[k] + c[k]) / 3;
    render_shade(&f->lighting, centre, normal, p0->color, out);
}

void render_finish_setup(const render_frame *f, setup_triangle *t, const float color[3])
{
    memcpy(t->color, color, sizeof t->color);
    t->material = RENDER_NO_MATERIAL;
    if (f->shading != MODE_FLAT)
        return; /* the encoded colour is for flat shading only */
    t->color8.r = cg_srgb_encode_unit(color[0]);
    t->color8.g = cg_srgb_encode_unit(color[1]);
    t->color8.b = cg_srgb_encode_unit(color[2]);
    t->color8.a = 255;
}

/* A triangle wholly inside the view volume: set up from the vertices the
 * vertex stage projected and snapped; back faces leave before anything
 * else is read. */
static inline void setup_inside(render_frame *f, render_chunk *c, size_t i, const uint32_t *tri,
                                const frame_vertex *const v[3])
{
    const int n = f->attribute_count;
    int64_t area = (int64_t)(v[1]->sx - v[0]->sx) * (v[2]->sy - v[0]->sy)
                   - (int64_t)(v[1]->sy - v[0]->sy) * (v[2]->sx - v[0]->sx);
    if (area > 0 && f->cull) {
        c->culled++;
        return;
    }
    render_corner corner[3];
    for (int k = 0; k < 3; k++) {
        corner[k].x = v[k]->sx;
        corner[k].y = v[k]->sy;
        corner[k].z = v[k]->sz;
        corner[k].iw = v[k]->siw;
        corner[k].a = NULL;
    }
    const render_corner *pc[3] = {&corner[0], &corner[1], &corner[2]};
    /* Set up in place at the end of the chunk's list, attributes after:
     * only triangles that cover a pixel need them. */
    setup_triangle *t = next_setup(f, c);
    if (!t)
        return;
    int result = render_setup_fixed(pc, f->width, f->height, 0, f->setup_flags, t);
    if (result < 0) {
        c->culled++;
        return;
    }
    if (result == 0) {
        c->rejected++;
        return;
    }
    if (n > 0) {
        /* In the setup's order: turned around unless clockwise. */
        static const int turned[3] = {0, 2, 1}, kept[3] = {0, 1, 2};
        const int *order = area > 0 ? kept : turned;
        float local[RENDER_MAX_ATTRIBUTES];
        for (int k = 0; k < 3; k++)
            memcpy(t->a + k * n, vertex_attributes(f, tri[order[k]], local),
                   sizeof(float) * (size_t)n);
    }
    float color[3];
    triangle_color(f, i, color);
    render_finish_setup(f, t, color);
    t->material = render_triangle_material(f->r, i);
    emit_setup(f, c, t);
}

/* The triangle clipped against the planes in `any` (none: as it is) and
 * projected into s; returns the corner count, 0 when nothing usable is
 * left (fewer than three corners, or one not in front of the eye). */
static int clip_and_project(render_frame *f, render_chunk *c, const uint32_t *tri, unsigned any,
                            screen_vertex s[RENDER_MAX_POLYGON])
{
    const int n = f->attribute_count;
    clip_vertex in[3], polygon[RENDER_MAX_POLYGON];
    for (int k = 0; k < 3; k++) {
        render_clip_position(f, tri[k], in[k].c);
        if (n > 0) {
            const float *a = vertex_attributes(f, tri[k], in[k].a);
            if (a != in[k].a)
                memcpy(in[k].a, a, sizeof(float) * (size_t)n);
        }
    }
    int count = 3;
    const clip_vertex *corners = in;
    if (any) {
        c->clipped++;
        count = render_clip_polygon(in, 3, any, n, polygon);
        corners = polygon;
    }
    int usable = count >= 3;
    for (int k = 0; k < count; k++) {
        if (!(corners[k].c[3] > 0))
            usable = 0;
        render_project(&corners[k], f->width, f->height, n, &s[k]);
    }
    return usable ? count : 0;
}

/* The painter's algorithm keeps the clipped polygon whole, culled by the
 * orientation of all its corners. */
static void keep_polygon(render_frame *f, render_chunk *c, size_t i, const screen_vertex *s,
                         int count)
{
    float color[3];
    triangle_color(f, i, color);
    double area = 0;
    for (int k = 0; k < count; k++) {
        const screen_vertex *p = &s[k], *q = &s[(k + 1) % count];
        area += (q->x - p->x) * (q->y + p->y);
    }
    /* area > 0 for polygons the camera sees counter-clockwise (front). */
    if (f->cull && area <= 0) {
        c->culled++;
        return;
    }
    emit_polygon(c, i, s, count, color);
}

/* The z-buffer sets up the clipped polygon as a fan of triangles. */
static void setup_fan(render_frame *f, render_chunk *c, size_t i, const screen_vertex *s, int count)
{
    const int n = f->attribute_count;
    float color[3];
    int colored = 0, culled = 0, emitted = 0;
    for (int k = 1; k + 1 < count; k++) {
        setup_triangle t;
        int result = render_setup(&s[0], &s[k], &s[k + 1], f->width, f->height, n, f->setup_flags,
                                  &t);
        if (result < 0)
            culled = 1;
        if (result != 1)
            continue;
        if (!colored) {
            /* Lit only once the triangle is known to be visible. */
            triangle_color(f, i, color);
            colored = 1;
        }
        render_finish_setup(f, &t, color);
        t.material = render_triangle_material(f->r, i);
        emit_setup(f, c, &t);
        emitted++;
    }
    if (culled && !emitted)
        c->culled++;
    else if (!emitted)
        c->rejected++;
}

void render_triangle_stage(render_frame *f, render_chunk *c, int painter)
{
    for (size_t i = c->begin; i < c->end; i++) {
        const uint32_t *tri = f->r->triangles[i];
        const frame_vertex *v[3] = {&f->vertices[tri[0]], &f->vertices[tri[1]],
                                    &f->vertices[tri[2]]};
        unsigned all = v[0]->outcode & v[1]->outcode & v[2]->outcode;
        unsigned any = v[0]->outcode | v[1]->outcode | v[2]->outcode;
        if ((any & 0x40) || all) {
            c->rejected++;
            continue;
        }
        if (!painter && v[0]->projected && v[1]->projected && v[2]->projected) {
            setup_inside(f, c, i, tri, v);
            continue;
        }
        screen_vertex s[RENDER_MAX_POLYGON];
        int count = clip_and_project(f, c, tri, any, s);
        if (count == 0)
            c->rejected++;
        else if (painter)
            keep_polygon(f, c, i, s, count);
        else
            setup_fan(f, c, i, s, count);
    }
}
