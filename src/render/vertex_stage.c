/* The vertex stage, the pipeline's first: every vertex of the mesh is
 * transformed to clip coordinates (the model-view-projection matrix, in
 * double), classified against the six planes of the view volume (its
 * outcode), and, when inside and in front of the eye, projected to the
 * screen and snapped to the 1/256-pixel grid once for all the triangles
 * around it.  Its attributes (the lit colour for Gouraud; normal, world
 * position and colour for Phong) are computed later, only for the vertices
 * of triangles that are drawn (vertex_attributes in pipeline.h). */
#include "pipeline.h"

#include <string.h>

void render_clip_position(const render_frame *f, size_t i, double c[4])
{
    clip_of(f, f->r->vertices[i].position, c);
}

void render_world_position(const render_frame *f, size_t i, float out[3])
{
    world_of(f, f->r->vertices[i].position, out);
}

void render_compute_attributes(const render_frame *f, size_t i, float *out)
{
    const prepared_vertex *p = &f->r->vertices[i];
    const int n = f->attribute_count;
    float nx = p->normal[0], ny = p->normal[1], nz = p->normal[2], normal[3];
    for (int k = 0; k < 3; k++)
        normal[k] = f->normal_matrix[k][0] * nx + f->normal_matrix[k][1] * ny
                    + f->normal_matrix[k][2] * nz;
    float length = sqrtf(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    float inverse = length > 0 ? 1 / length : 0;
    for (int k = 0; k < 3; k++)
        normal[k] *= inverse;
    float world[3];
    if (f->shading == MODE_GOURAUD) {
        /* Only the specular term needs the position. */
        if (f->lighting.ks != 0)
            world_of(f, p->position, world);
        render_shade(&f->lighting, f->lighting.ks != 0 ? world : p->position, normal, p->color,
                     out);
    } else {
        world_of(f, p->position, world);
        memcpy(out, normal, sizeof normal);
        memcpy(out + 3, world, sizeof world);
        if (n > 6)
            memcpy(out + 6, p->color, sizeof p->color);
        if (n > 9)
            memcpy(out + 9, p->uv, sizeof p->uv);
    }
}

void render_vertex_stage(render_frame *f, size_t begin, size_t end)
{
    const cg_renderer *r = f->r;
    for (size_t i = begin; i < end; i++) {
        const prepared_vertex *p = &r->vertices[i];
        frame_vertex *v = &f->vertices[i];
        double c[4];
        clip_of(f, p->position, c);
        v->outcode = (uint8_t)render_outcode(c);
        v->projected = v->outcode == 0 && c[3] > 0;
        if (v->projected) {
            /* Projected and snapped once here for all the triangles that
             * need no clipping (the clipped ones project the same way). */
            clip_vertex cv;
            screen_vertex s;
            memcpy(cv.c, c, sizeof cv.c);
            render_project(&cv, f->width, f->height, 0, &s);
            v->sx = render_snap(s.x, f->width);
            v->sy = render_snap(s.y, f->height);
            v->sz = (float)s.z;
            v->siw = (float)s.iw;
        }
        atomic_store_explicit(&f->states[i], 0, memory_order_relaxed);
    }
}
