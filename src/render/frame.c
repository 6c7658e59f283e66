/* One frame of the z-buffer pipeline (or of the painter's algorithm, which
 * shares its vertex and triangle stages): the camera, matrices and lights of
 * the frame, the buffers the renderer keeps from frame to frame, the whole
 * object culled at once when its box lies outside the view volume, then the
 * stages on the team of threads (team.c) and the edges drawn over. */
#include "pipeline.h"
#include "cg/color.h"

#include <stdlib.h>
#include <string.h>

static cg_status frame_camera(cg_renderer *r, double aspect, cg_camera *camera)
{
    *camera = r->options.camera;
    if (!r->options.frame_camera || !r->has_bounds)
        return CG_OK;
    /* World bounds of the model-space box. */
    cg_vec3 lo = {INFINITY, INFINITY, INFINITY}, hi = {-INFINITY, -INFINITY, -INFINITY};
    for (int i = 0; i < 8; i++) {
        cg_vec3 p = {(i & 1) ? r->hi.x : r->lo.x, (i & 2) ? r->hi.y : r->lo.y,
                     (i & 4) ? r->hi.z : r->lo.z};
        p = cg_mat4_transform_point(r->options.model, p);
        lo = cg_vec3_make(fmin(lo.x, p.x), fmin(lo.y, p.y), fmin(lo.z, p.z));
        hi = cg_vec3_make(fmax(hi.x, p.x), fmax(hi.y, p.y), fmax(hi.z, p.z));
    }
    return cg_camera_frame(camera, lo, hi, aspect);
}

cg_light cg_render_key_light(cg_mat4 view)
{
    /* From the camera's upper left, a little in front (view space). */
    cg_vec3 d = cg_vec3_normalize(cg_vec3_make(-1, 1, 1.5));
    /* View-space direction to world: the view's rotation is orthonormal,
     * so its inverse is its transpose. */
    cg_vec3 world = {view.m[0][0] * d.x + view.m[1][0] * d.y + view.m[2][0] * d.z,
                     view.m[0][1] * d.x + view.m[1][1] * d.y + view.m[2][1] * d.z,
                     view.m[0][2] * d.x + view.m[1][2] * d.y + view.m[2][2] * d.z};
    return cg_light_directional(cg_vec3_scale(world, -1), cg_vec3_make(0.85, 0.85, 0.85));
}

static void setup_lighting(render_frame *f, const cg_camera *camera, const cg_mat4 *view)
{
    const cg_render_options *o = f->o;
    render_lighting *l = &f->lighting;
    /* White lights; ka, kd = 1 and ks of the options; Blinn-Phong. */
    l->material = cg_material_make(cg_vec3_make(1, 1, 1), o->ambient, 1, o->specular, o->shininess);
    l->material.specular = CG_SPECULAR_BLINN;
    if (o->specular == 0)
        l->material.shininess = 1; /* the term is zero anyway: spare its power */
    l->orthographic = camera->orthographic;
    l->eye[0] = (float)camera->eye.x;
    l->eye[1] = (float)camera->eye.y;
    l->eye[2] = (float)camera->eye.z;
    cg_vec3 back = cg_vec3_normalize(cg_vec3_sub(camera->eye, camera->target));
    l->view_dir[0] = (float)back.x;
    l->view_dir[1] = (float)back.y;
    l->view_dir[2] = (float)back.z;
    l->lights[0] = cg_light_ambient(cg_vec3_make(1, 1, 1));
    if (o->light_count == 0) {
        l->lights[1] = cg_render_key_light(*view);
        l->count = 2;
    } else {
        /* The options name the direction toward each light; cg_light the
         * way its light travels. */
        for (int i = 0; i < o->light_count; i++) {
            double k = o->lights[i].intensity;
            l->lights[i + 1] = cg_light_directional(cg_vec3_scale(o->lights[i].direction, -1),
                                                    cg_vec3_make(k, k, k));
        }
        l->count = o->light_count + 1;
    }
    render_lighting_prepare(l);
}

void render_buffers_free(cg_renderer *r)
{
    render_team_stop(r);
    for (int i = 0; i < r->chunk_count; i++) {
        free(r->chunks[i].setups);
        free(r->chunks[i].bin_start);
        free(r->chunks[i].bin_fill);
        free(r->chunks[i].bin_list);
        free(r->chunks[i].polygons);
    }
    free(r->chunks);
    r->chunks = NULL;
    r->chunk_count = 0;
    r->chunk_capacity = 0;
    free(r->frame_vertices);
    free(r->frame_attributes);
    free(r->frame_states);
    free(r->clean_tiles);
    r->clean_tiles = NULL;
    render_shadows_free(r);
    free(r->sample_memory);
    free(r->sample_buffers);
    r->sample_memory = NULL;
    r->sample_buffers = NULL;
    r->sample_memory_capacity = r->sample_buffer_capacity = 0;
    r->clean_tile_capacity = 0;
    r->frame_vertices = NULL;
    r->frame_attributes = NULL;
    r->frame_states = NULL;
    r->frame_vertex_capacity = r->frame_attribute_capacity = r->frame_state_capacity = 0;
}

/* The frame's vertex buffers, kept by the renderer. */
static cg_status frame_vertex_buffers(render_frame *f)
{
    cg_renderer *r = f->r;
    size_t count = r->vertex_count ? r->vertex_count : 1;
    size_t floats = count * (size_t)(f->attribute_count ? f->attribute_count : 1);
    /* The vertex count is the mesh's: these grow at the first frame only
     * (and the attributes when the shading needs more of them). */
    if (core_array_reserve((void **)&r->frame_vertices, &r->frame_vertex_capacity, count,
                           sizeof *r->frame_vertices)
            != CG_OK
        || core_array_reserve((void **)&r->frame_attributes, &r->frame_attribute_capacity, floats,
                              sizeof *r->frame_attributes)
               != CG_OK
        || core_array_reserve((void **)&r->frame_states, &r->frame_state_capacity, count,
                              sizeof *r->frame_states)
               != CG_OK)
        return CG_ENOMEM;
    f->vertices = r->frame_vertices;
    f->attributes = r->frame_attributes;
    f->states = r->frame_states;
    return CG_OK;
}

/* The triangle ranges of the triangle stage, their buffers kept by the
 * renderer and emptied: one per TRIANGLE_BLOCK triangles, at most
 * MAX_CHUNKS, a number that depends on the mesh only. */
static cg_status frame_chunks(render_frame *f)
{
    cg_renderer *r = f->r;
    size_t wanted = (r->triangle_count + TRIANGLE_BLOCK - 1) / TRIANGLE_BLOCK;
    f->chunk_count = wanted < 1 ? 1 : wanted > MAX_CHUNKS ? MAX_CHUNKS : (int)wanted;
    if (r->chunk_count < f->chunk_count) {
        if (core_array_reserve((void **)&r->chunks, &r->chunk_capacity, (size_t)f->chunk_count,
                               sizeof *r->chunks)
            != CG_OK)
            return CG_ENOMEM;
        memset(r->chunks + r->chunk_count, 0,
               (size_t)(f->chunk_count - r->chunk_count) * sizeof *r->chunks);
        r->chunk_count = f->chunk_count;
    }
    for (int i = 0; i < f->chunk_count; i++) {
        render_chunk *c = &r->chunks[i];
        c->begin = r->triangle_count * (size_t)i / (size_t)f->chunk_count;
        c->end = r->triangle_count * (size_t)(i + 1) / (size_t)f->chunk_count;
        /* The capacity counts set-ups of the last frame's size. */
        if (c->setup_stride != f->stride) {
            c->setup_capacity = c->setup_stride ? c->setup_capacity * c->setup_stride / f->stride
                                                : 0;
            c->setup_stride = f->stride;
        }
        c->setup_count = c->polygon_count = 0;
        c->culled = c->clipped = c->rejected = c->rasterized = 0;
        c->failed = 0;
    }
    f->chunks = r->chunks;
    return CG_OK;
}

/* The frame's camera, matrices, lights and modes for drawing into image. */
static cg_status frame_begin(cg_renderer *r, cg_image *image, render_frame *f)
{
    const cg_render_options *o = &r->options;
    memset(f, 0, sizeof *f);
    f->r = r;
    f->o = o;
    f->image = image;
    f->width = image->width;
    f->height = image->height;
    double aspect = (double)f->width / f->height;
    cg_camera camera;
    cg_mat4 view, projection;
    if (frame_camera(r, aspect, &camera) != CG_OK || cg_camera_view(&camera, &view) != CG_OK
        || cg_camera_projection(&camera, aspect, &projection) != CG_OK)
        return CG_EINVAL;
    r->camera = camera;
    f->model = o->model;
    f->mvp = cg_mat4_mul(projection, cg_mat4_mul(view, o->model));
    cg_mat4 inverse;
    if (cg_mat4_inverse(o->model, &inverse) != CG_OK)
        return CG_EINVAL;
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 3; j++)
            f->normal_matrix[i][j] = (float)inverse.m[j][i];
    setup_lighting(f, &camera, &view);
    f->fill_background = o->edges == CG_EDGES_HIDDEN_LINE;
    f->shading = f->fill_background ? MODE_FLAT : (int)o->shading;
    if (!f->fill_background && (r->textured || r->blended || o->shading == CG_SHADING_UNLIT))
        f->shading = MODE_TEXTURED; /* per pixel, textures sampled, alpha (textured.c) */
    f->attribute_count = f->shading == MODE_FLAT       ? 0
                         : f->shading == MODE_GOURAUD  ? 3
                         : f->shading == MODE_TEXTURED ? TEXTURED_ATTRIBUTES
                         : r->varying_color            ? 9
                                                       : 6;
    f->cull = o->cull == CG_CULL_BACK;
    f->samples = o->msaa > 1 && o->algorithm == CG_RENDER_ZBUFFER ? o->msaa : 1;
    f->use_samples = o->algorithm == CG_RENDER_ZBUFFER
                     && (f->samples > 1 || (r->blended && !f->fill_background));
    f->setup_flags = (f->cull ? RENDER_SETUP_CULL : 0)
                     | (f->samples > 1 ? RENDER_SETUP_MULTISAMPLE : 0);
    f->background[0] = o->background.r;
    f->background[1] = o->background.g;
    f->background[2] = o->background.b;
    f->background[3] = o->background.a;
    f->background8 = cg_linear_to_rgba8(o->background);
    f->stride = SETUP_SIZE(f->attribute_count);
    f->setup_slack = (sizeof(setup_triangle) + f->stride - 1) / f->stride;
    f->tiles_x = (f->width + RENDER_TILE - 1) / RENDER_TILE;
    f->tiles_y = (f->height + RENDER_TILE - 1) / RENDER_TILE;
    f->tile_count = f->tiles_x * f->tiles_y;
    return CG_OK;
}

/* Multisampling: one tile's samples for each worker, kept by the renderer. */
static cg_status frame_sample_buffers(render_frame *f)
{
    cg_renderer *r = f->r;
    size_t bytes = render_samples_bytes(f->samples), workers = (size_t)f->thread_count;
    if (core_array_reserve((void **)&r->sample_memory, &r->sample_memory_capacity, bytes * workers,
                           1)
            != CG_OK
        || core_array_reserve((void **)&r->sample_buffers, &r->sample_buffer_capacity, workers,
                              sizeof *r->sample_buffers)
               != CG_OK)
        return CG_ENOMEM;
    for (size_t i = 0; i < workers; i++)
        render_samples_bind(&r->sample_buffers[i], r->sample_memory + i * bytes, f->samples);
    f->sample_buffers = r->sample_buffers;
    return CG_OK;
}

/* The depth buffer and the tiles known to hold infinite depth, kept by the
 * renderer from frame to frame. */
static cg_status frame_depth_buffers(render_frame *f)
{
    cg_renderer *r = f->r;
    size_t pixels = (size_t)f->width * (size_t)f->height;
    if (core_array_reserve((void **)&r->depth, &r->depth_capacity, pixels, sizeof *r->depth)
        != CG_OK)
        return CG_ENOMEM;
    f->depth = r->depth;
    /* Which tiles hold infinite depth from an earlier frame of this size. */
    int same_layout = r->depth_width == f->width && r->depth_height == f->height;
    if (r->clean_tile_capacity < (size_t)f->tile_count) {
        if (core_array_reserve((void **)&r->clean_tiles, &r->clean_tile_capacity,
                               (size_t)f->tile_count, 1)
            != CG_OK)
            return CG_ENOMEM;
        same_layout = 0;
    }
    if (!same_layout)
        memset(r->clean_tiles, 0, (size_t)f->tile_count);
    f->clean_tiles = r->clean_tiles;
    r->depth_width = f->width;
    r->depth_height = f->height;
    return CG_OK;
}

/* Whole-object culling: the planes of the view volume that the mesh's
 * bounding box lies wholly outside of (0x3f when it has no bounds). */
static unsigned object_outside(const render_frame *f)
{
    const cg_renderer *r = f->r;
    unsigned all = 0x3f;
    if (r->has_bounds) {
        for (int i = 0; i < 8; i++) {
            cg_vec3 p = {(i & 1) ? r->hi.x : r->lo.x, (i & 2) ? r->hi.y : r->lo.y,
                         (i & 4) ? r->hi.z : r->lo.z};
            cg_vec4 c = cg_mat4_mul_vec4(f->mvp, cg_vec4_from_point(p));
            double cc[4] = {c.x, c.y, c.z, c.w};
            all &= render_outcode(cc);
        }
    }
    return all;
}

/* A frame without faces to draw (the object culled, no triangles, or a
 * wireframe): the background, and the wireframe's edges. */
static cg_status draw_without_faces(render_frame *f, unsigned outside)
{
    cg_renderer *r = f->r;
    r->stats.object_culled = outside != 0 && r->has_bounds;
    render_clear_tile(f, 0, 0, f->width, f->height, 0, 1);
    memset(f->clean_tiles, 1, (size_t)f->tile_count);
    r->depth_valid = 1;
    if (f->o->edges == CG_EDGES_WIREFRAME && !outside && r->triangle_count) {
        if (frame_vertex_buffers(f) != CG_OK)
            return CG_ENOMEM;
        render_vertex_stage(f, 0, r->vertex_count);
        r->depth_valid = 0;
        return render_edges(f);
    }
    return CG_OK;
}

/* The faces through the stages on the team of threads (and the painter's
 * algorithm after them), then the edges drawn over. */
static cg_status draw_faces(render_frame *f)
{
    cg_renderer *r = f->r;
    const cg_render_options *o = f->o;
    f->thread_count = o->threads;
    if ((size_t)f->thread_count > r->triangle_count)
        f->thread_count = (int)r->triangle_count;
    int painter = o->algorithm != CG_RENDER_ZBUFFER;
    if (frame_vertex_buffers(f) != CG_OK || frame_chunks(f) != CG_OK
        || (f->use_samples && frame_sample_buffers(f) != CG_OK))
        return CG_ENOMEM;
    size_t fragments;
    render_run_phases(f, painter, &fragments);
    cg_status status = CG_OK;
    for (int i = 0; i < f->chunk_count && status == CG_OK; i++) {
        render_chunk *c = &f->chunks[i];
        if (c->failed)
            status = CG_ENOMEM;
        r->stats.culled += c->culled;
        r->stats.clipped += c->clipped;
        r->stats.rejected += c->rejected;
        r->stats.rasterized += c->setup_count;
    }
    r->stats.fragments += fragments;
    if (status == CG_OK && painter) {
        memset(f->clean_tiles, 0, (size_t)f->tile_count); /* painted over everywhere */
        status = render_painter(f);
    }
    if (status == CG_OK) {
        r->depth_valid = 1;
        r->stats.splits = f->splits;
        if (o->edges == CG_EDGES_HIDDEN_LINE || o->edges == CG_EDGES_OVERLAY)
            status = render_edges(f);
    }
    return status;
}

cg_status cg_renderer_draw(cg_renderer *r, cg_image *image)
{
    if (!r || !image || !image->data || image->width <= 0 || image->height <= 0
        || (image->format != CG_PIXEL_RGBA8 && image->format != CG_PIXEL_RGBAF))
        return CG_EINVAL;
    if (image->width > CG_RASTER_MAX_SIDE || image->height > CG_RASTER_MAX_SIDE)
        return CG_ERANGE;
    memset(&r->stats, 0, sizeof r->stats);
    r->stats.triangles = r->triangle_count;
    r->depth_valid = 0;
    render_frame f;
    cg_status status = frame_begin(r, image, &f);
    if (status == CG_OK)
        status = frame_depth_buffers(&f);
    if (status == CG_OK)
        status = render_shadows_build(&f);
    if (status != CG_OK)
        return status;
    unsigned outside = object_outside(&f);
    if (outside || r->triangle_count == 0 || r->options.edges == CG_EDGES_WIREFRAME)
        return draw_without_faces(&f, outside);
    return draw_faces(&f);
}
