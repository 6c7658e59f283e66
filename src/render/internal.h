/* Private pieces shared by the files of the render module. */
#ifndef CG_RENDER_INTERNAL_H
#define CG_RENDER_INTERNAL_H

#include "cg/render.h"
#include "cg/light.h"
#include "cg/color.h"
#include "cg/trace_steps.h"
#include "../color/srgb_tables.h"

#include <math.h>
#include <stdatomic.h>
#include <stddef.h>
#include <stdint.h>

#define RENDER_MAX_ATTRIBUTES 11 /* interpolated floats per vertex */
#define RENDER_MAX_POLYGON 9     /* a triangle clipped by 6 planes */
#define RENDER_TILE 64           /* tile side in pixels */

/* ---- shading: the one place that computes the colour of a point --------- */

/* A directional light's shadow map (shadow.c): world point -> texel u, v
 * and depth along the light's direction by the rows of m. */
typedef struct render_shadow_map {
    int size;
    float m[3][4];
    float texel; /* world units per texel */
    float *depth;
} render_shadow_map;

typedef struct render_lighting {
    int count; /* lights[0] is the ambient light */
    cg_light lights[CG_RENDER_MAX_LIGHTS + 1];
    cg_material material; /* colour replaced per point */
    int orthographic;
    float eye[3];      /* perspective: viewer position */
    float view_dir[3]; /* orthographic: unit direction toward the viewer */
    /* The same in float for render_shade (render_lighting_prepare). */
    int directional;                         /* directional lights */
    float to_light[CG_RENDER_MAX_LIGHTS][3]; /* unit, toward each light */
    float light_color[CG_RENDER_MAX_LIGHTS][3];
    float ambient[3]; /* ka times the ambient lights */
    float kd, ks, shininess;
    float specular_color[3];
    int blinn;
    const render_shadow_map *shadow[CG_RENDER_MAX_LIGHTS]; /* per directional light, or NULL */
} render_lighting;

/* The fraction (0 to 1) of the light of shadow map `map` that reaches the
 * world point `position` whose normal makes cos theta = nl with the light:
 * 3 x 3 percentage-closer filtering, slope-scaled bias (shadow.c). */
float render_shadow_visibility(const render_shadow_map *map, const float position[3], float nl);

/* Fills the float fields of l from its lights (ambient and directional
 * only, which is what the renderer makes) and material. */
void render_lighting_prepare(render_lighting *l);

/* Colour (linear) of a surface point with unit normal n and diffuse colour
 * base, seen from the camera and lit by the lights: the local illumination
 * model of cg/light.h (cg_light_shade), evaluated in float for the ambient
 * and directional lights the renderer uses. */
/* The three terms render_shade sums (ambient, diffuse, specular), apart. */
void render_shade_terms(const render_lighting *l, const float position[3], const float n[3],
                        const float base[3], float ambient[3], float diffuse[3], float specular[3]);
void render_shade(const render_lighting *lighting, const float position[3], const float normal[3],
                  const float base[3], float out[3]);


/* ---- clipping in homogeneous coordinates -------------------------------- */

typedef struct clip_vertex {
    double c[4]; /* clip coordinates x, y, z, w */
    float a[RENDER_MAX_ATTRIBUTES];
} clip_vertex;

/* Outcode bits: one per plane -w<=x, x<=w, -w<=y, y<=w, -w<=z, z<=w that the
 * point violates; 0x40 alone when a coordinate is not finite.  Inline: the
 * vertex stage classifies every vertex of every frame. */
static inline unsigned render_outcode(const double c[4])
{
    /* x - x is 0 for a finite x and NaN otherwise. */
    if (!((c[0] - c[0]) + (c[1] - c[1]) + (c[2] - c[2]) + (c[3] - c[3]) == 0))
        return 0x40;
    double w = c[3];
    return (unsigned)(w + c[0] < 0) | (unsigned)(w - c[0] < 0) << 1 | (unsigned)(w + c[1] < 0) << 2
           | (unsigned)(w - c[1] < 0) << 3 | (unsigned)(w + c[2] < 0) << 4
           | (unsigned)(w - c[2] < 0) << 5;
}
/* Sutherland-Hodgman against the planes in mask, in homogeneous coordinates;
 * in[] (n vertices) is clipped into out (room for RENDER_MAX_POLYGON); returns
 * the new count (0 when nothing is left).  Intersections are computed from
 * the inside endpoint, so an edge shared by two polygons is cut at the same
 * point in both. */
int render_clip_polygon(const clip_vertex *in, int n, unsigned mask, int attribute_count,
                        clip_vertex *out);
/* Clips the segment a-b against all six planes; returns 0 when nothing is
 * left, else 1 with a and b replaced by the ends of the visible part. */
int render_clip_segment(clip_vertex *a, clip_vertex *b, int attribute_count);

/* ---- screen-space vertices and triangle setup --------------------------- */

typedef struct screen_vertex {
    double x, y;                    /* continuous pixel coordinates */
    double z;                       /* window depth in [0, 1] */
    double iw;                      /* 1 / w */
    float a[RENDER_MAX_ATTRIBUTES]; /* attributes (not divided by w) */
} screen_vertex;

/* Maps a clipped vertex to the screen of a width x height image.  Inline
 * (like render_snap) because the vertex stage projects every vertex of
 * every frame. */
static inline void render_project(const clip_vertex *v, int width, int height, int attribute_count,
                                  screen_vertex *out)
{
    double iw = 1.0 / v->c[3];
    out->x = (v->c[0] * iw + 1.0) * 0.5 * width;
    out->y = (1.0 - v->c[1] * iw) * 0.5 * height;
    out->z = v->c[2] * iw * 0.5 + 0.5;
    out->iw = iw;
    for (int i = 0; i < attribute_count; i++)
        out->a[i] = v->a[i];
}

/* A triangle ready to rasterize: fixed-point vertices ordered clockwise as
 * seen on the screen (positive edge functions inside), the
 * pixel box it may cover, and the values to interpolate. */
typedef struct setup_triangle {
    /* 8-aligned, so that SETUP_SIZE (rounded up to 8) never exceeds it */
    _Alignas(8) int32_t x[3], y[3]; /* 1/256 pixel */
    int32_t box[4];                 /* pixels x0, y0, x1, y1 (exclusive) */
    float z[3], iw[3];
    float color[3];     /* flat colour, or the base colour for Phong */
    cg_rgba8 color8;    /* the flat colour encoded */
    float inverse_area; /* 1 / (twice the area in fixed-point units squared) */
    uint32_t material;  /* textured shading: index into the renderer's
                           materials, RENDER_NO_MATERIAL for none */
    /* attributes of vertex k at a[k * attribute_count + j]; only the first
     * 3 * attribute_count floats are stored in the binned copies */
    float a[3 * RENDER_MAX_ATTRIBUTES];
} setup_triangle;

#define SETUP_SIZE(attribute_count) \
    ((offsetof(setup_triangle, a) + 3 * (size_t)(attribute_count) * sizeof(float) + 7) & ~(size_t)7)

/* A corner ready for setup: snapped position, depth, 1 / w, attributes. */
typedef struct render_corner {
    int32_t x, y;
    float z, iw;
    const float *a;
} render_corner;

#define RENDER_SUBPIXEL (1 << CG_RASTER_SUBPIXEL_BITS)
/* Vertices within this many pixels around the image are rasterized exactly;
 * fixed-point values then stay below 2^29 and edge functions within 64 bits. */
#define RENDER_GUARD_BAND (1 << 20)

/* Rounds a pixel coordinate to the 1/256 grid (clamped to the guard band). */
static inline int32_t render_snap(double value, int size)
{
    double s = value * RENDER_SUBPIXEL + 0.5;
    /* Clamped first (NaN to lo), then floored: the bounds are integers, so
     * this equals clamping the floor, and the value fits an int32_t. */
    double lo = -(double)RENDER_GUARD_BAND * RENDER_SUBPIXEL;
    double hi = ((double)size + RENDER_GUARD_BAND) * RENDER_SUBPIXEL;
    s = s > lo ? s : lo;
    s = s < hi ? s : hi;
    int32_t t = (int32_t)s; /* toward zero */
    return t - ((double)t > s);
}
void render_corner_from_screen(const screen_vertex *s, int width, int height, render_corner *out);
/* The flags of render_setup: back faces culled; the box of the pixels whose
 * samples (not only centres) it may cover, for multisampling. */
#define RENDER_SETUP_CULL 1
#define RENDER_SETUP_MULTISAMPLE 2
/* Orients the triangle for the rasterizer; returns 0 when it covers no pixel
 * centre (zero area after snapping, or box empty), -1 when it is back-facing
 * (seen clockwise) and cull (RENDER_SETUP_* flags) culls, 1 when out is
 * ready. */
int render_setup_fixed(const render_corner *const v[3], int width, int height, int attribute_count,
                       int cull, setup_triangle *out);
/* The same from screen vertices (snapped here). */
int render_setup(const screen_vertex *a, const screen_vertex *b, const screen_vertex *c, int width,
                 int height, int attribute_count, int cull, setup_triangle *out);

/* Edge functions of a set-up triangle at the centre of pixel (x, y), with
 * the top-left bias folded in (a pixel is covered when all three are >= 0),
 * and their steps per pixel right and down. */
typedef struct raster_edges {
    int64_t w[3], step_x[3], step_y[3];
} raster_edges;
static inline void render_edge_at(const setup_triangle *t, int i, int j, int64_t px, int64_t py,
                                  int64_t *w, int64_t *step_x, int64_t *step_y)
{
    int64_t dx = (int64_t)t->x[j] - t->x[i], dy = (int64_t)t->y[j] - t->y[i];
    /* With positive area (clockwise on a y-down screen) the interior is
     * where every edge function is positive.  Top edges run in +x with
     * dy == 0, left edges go up (dy < 0); pixel centres on other edges
     * belong to the neighbour: bias -1. */
    int top_left = dy < 0 || (dy == 0 && dx > 0);
    *w = dx * (py - t->y[i]) - dy * (px - t->x[i]) - (top_left ? 0 : 1);
    *step_x = -dy * RENDER_SUBPIXEL;
    *step_y = dx * RENDER_SUBPIXEL;
}

/* The pixel rectangle [x0, x1) x [y0, y1) (a tile's) cut to the triangle's
 * bounding box; 0 when nothing is left. */
static inline int render_clip_to_box(const setup_triangle *t, int *x0, int *y0, int *x1, int *y1)
{
    if (t->box[0] > *x0)
        *x0 = t->box[0];
    if (t->box[1] > *y0)
        *y0 = t->box[1];
    if (t->box[2] < *x1)
        *x1 = t->box[2];
    if (t->box[3] < *y1)
        *y1 = t->box[3];
    return *x0 < *x1 && *y0 < *y1;
}

/* Edge k runs from vertex k + 1 to vertex k + 2 (mod 3).  Inline: every
 * set-up triangle and every tile it touches starts here. */
static inline void render_edges_at(const setup_triangle *t, int x, int y, raster_edges *out)
{
    int64_t px = (int64_t)x * RENDER_SUBPIXEL + RENDER_SUBPIXEL / 2;
    int64_t py = (int64_t)y * RENDER_SUBPIXEL + RENDER_SUBPIXEL / 2;
    render_edge_at(t, 1, 2, px, py, &out->w[0], &out->step_x[0], &out->step_y[0]);
    render_edge_at(t, 2, 0, px, py, &out->w[1], &out->step_x[1], &out->step_y[1]);
    render_edge_at(t, 0, 1, px, py, &out->w[2], &out->step_x[2], &out->step_y[2]);
}

/* The covered run [*begin, *end) of a row whose edge functions are w at
 * pixel offset 0 and change by step per pixel, within [0, width): exact
 * integer bounds of where all three are >= 0.
 *
 *                        top vertex
 *                            /\               (a triangle, clockwise on the
 *                left edge  /  \  right edge   y-down screen: every edge
 *               (step > 0) /    \ (step < 0)   function is positive inside)
 *                         /      \            step: change per pixel right
 *   row:    o    o    o  / #    # \  o    o        o  centre not covered
 *   i:      0    1    2 /  3    4  \ 5    6        #  centre covered
 *                      /   ^begin   \^end (exclusive)
 *                     /______________\      bottom edge: step 0, so a
 *                                                 row is wholly in or out
 *
 *   edge k at the centre of pixel i of the row:   e_k(i) = w[k] + i step[k]
 *   a rising edge (step > 0) is >= 0 from       i = ceil(-w / step)
 *   a falling edge (step < 0) is >= 0 up to     i = floor(w / -step)
 *   begin = the largest of the lower bounds, end = 1 + the smallest of the
 *   upper ones, both kept within [0, width).
 *
 * The top-left rule is already in w: render_edge_at subtracts 1 from an
 * edge that is neither a top nor a left edge, so a centre exactly on the
 * right edge above (e = 0 - 1) is not covered, and one exactly on the left
 * edge (e = 0) is: two triangles sharing an edge never both draw a pixel. */
static inline void render_row_span(const int64_t w[3], const int64_t step[3], int width, int *begin,
                                   int *end)
{
    int64_t lo = 0, hi = width; /* exclusive */
    for (int k = 0; k < 3; k++) {
        if (step[k] > 0) {
            if (w[k] < 0) {
                int64_t first = (-w[k] + step[k] - 1) / step[k];
                if (first > lo)
                    lo = first;
            }
        } else if (step[k] < 0) {
            if (w[k] < 0) {
                hi = 0;
            } else {
                int64_t last = w[k] / -step[k] + 1;
                if (last < hi)
                    hi = last;
            }
        } else if (w[k] < 0) {
            hi = 0;
        }
    }
    if (lo > width)
        lo = width;
    *begin = (int)lo;
    *end = (int)(hi > lo ? hi : lo);
}

/* ---- the renderer ------------------------------------------------------- */

typedef struct prepared_vertex {
    float position[3], normal[3], color[3], uv[2];
} prepared_vertex;

#define RENDER_NO_MATERIAL UINT32_MAX

/* A material as the textured shading uses it (material.c). */
typedef struct render_material {
    cg_texture *base_texture; /* NULL: the base colour alone */
    float alpha;              /* base colour factor's alpha */
    int blend;                /* alpha mode BLEND (OBJ d below 1): blended over
                                 what lies behind, after the opaque faces */
    float alpha_cutoff;       /* alpha mode MASK: fragments below are dropped;
                                 0 for every other mode (drawn opaque) */
    cg_texture_wrap wrap_u, wrap_v;
    /* KHR_texture_transform taken to cg's texture space (v up):
     * uv' = m * (u, v, 1) */
    float transform[2][3];
} render_material;

struct render_chunk;
struct core_worker_pool;

struct cg_renderer {
    cg_render_options options;
    size_t vertex_count;
    prepared_vertex *vertices;
    size_t triangle_count;
    uint32_t (*triangles)[3];
    uint32_t *triangle_face; /* face each triangle comes from */
    uint32_t *face_material; /* per face, index into materials or
                                 RENDER_NO_MATERIAL; NULL when no face has one */
    size_t material_count;
    render_material *materials;
    int textured; /* some material has a texture and the mesh coordinates */
    int blended;  /* some face has a BLEND material */
    char *warnings;
    uint32_t *face_triangle; /* per face, its triangle of largest area, whose
                                 turn is the face's (culling its edges) */
    size_t edge_count;
    uint32_t (*edges)[3]; /* prepared vertex a, b, face */
    size_t face_count;
    int varying_color; /* vertices differ in base colour */
    int has_bounds;
    cg_vec3 lo, hi; /* bounds of the finite positions */
    /* frame state */
    cg_camera camera;
    float *depth;
    size_t depth_capacity; /* floats */
    int depth_valid;
    int depth_width, depth_height;
    cg_render_stats stats;
    /* buffers kept from frame to frame (no allocation, no page faults
     * once they have grown to the mesh and image) */
    struct frame_vertex *frame_vertices;
    float *frame_attributes;
    atomic_uchar *frame_states;
    size_t frame_vertex_capacity, frame_attribute_capacity, frame_state_capacity;
    struct render_chunk *chunks;
    int chunk_count; /* chunks initialized */
    size_t chunk_capacity;
    unsigned char *clean_tiles; /* per tile of the last frame's size: its depth
                                   is all +infinity (nothing drawn there since
                                   it was cleared) */
    size_t clean_tile_capacity;
    render_shadow_map shadow_maps[CG_RENDER_MAX_LIGHTS]; /* kept between frames */
    unsigned char *sample_memory; /* multisampling: one tile's samples per worker */
    size_t sample_memory_capacity;
    struct render_samples *sample_buffers;
    size_t sample_buffer_capacity;
    struct core_worker_pool *pool; /* worker threads kept between frames */
    int pool_threads;              /* the thread count it was started for */
    /* cg_painter_steps: the painter's algorithm reports its steps here
     * during that call (NULL otherwise) */
    cg_step_fn painter_step;
    void *painter_user;
    /* cg_shading_pixel_steps: the fragments at pixel (probe_x, probe_y) */
    cg_step_fn shade_step;
    void *shade_user;
    int probe_x, probe_y, probe_stopped;
    long long probe_count;
};

/* A mesh vertex after the vertex stage: where it lies against the view
 * volume and, when inside, its snapped screen position.  Its clip
 * coordinates and world position are recomputed where needed
 * (render_clip_position, render_world_position); its attributes are in
 * render_frame.attributes. */
typedef struct frame_vertex {
    int32_t sx, sy;    /* snapped screen position, when projected */
    float sz, siw;     /* window depth and 1 / w, when projected */
    uint8_t outcode;   /* render_outcode */
    uint8_t projected; /* outcode 0 and w > 0: sx, sy, sz, siw are set */
} frame_vertex;

/* A clipped polygon in screen space, for the painter's algorithm. */
typedef struct painter_polygon {
    int n;
    uint32_t triangle; /* the mesh triangle it comes from */
    float color[3];
    screen_vertex v[RENDER_MAX_POLYGON];
} painter_polygon;

/* The triangles of one contiguous range of the mesh, processed by whichever
 * thread takes it; the ranges depend on the mesh only and are concatenated
 * in order, so that results do not depend on the number of threads. */
typedef struct render_chunk {
    size_t begin, end;     /* triangle range */
    unsigned char *setups; /* setup triangles, frame->stride bytes each */
    size_t setup_count, setup_capacity;
    size_t setup_stride; /* the frame->stride the capacity counts */
    uint32_t *bin_start; /* tile_count + 1 */
    uint32_t *bin_fill;  /* tile_count */
    size_t bin_start_capacity, bin_fill_capacity;
    uint32_t *bin_list; /* setup indices by tile */
    size_t bin_capacity;
    painter_polygon *polygons; /* painter's only */
    size_t polygon_count, polygon_capacity;
    size_t culled, clipped, rejected, rasterized;
    int failed; /* out of memory */
} render_chunk;

/* Frame context shared by the pipeline stages. */
typedef struct render_frame {
    cg_renderer *r;
    const cg_render_options *o;
    cg_image *image;
    int width, height;
    cg_mat4 mvp, model;
    float normal_matrix[3][3];
    render_lighting lighting;
    int shading, attribute_count, cull;
    int samples;                           /* per pixel: 1, 2, 4, 8 or 16 (multisample.c) */
    int use_samples;                       /* tiles drawn through multisample.c: more than one
                        sample, or blended faces (which need linear colour) */
    int setup_flags;                       /* RENDER_SETUP_* for the z-buffer's triangles */
    struct render_samples *sample_buffers; /* per worker, with use_samples */
    int fill_background;                   /* hidden-line: faces drawn in the background colour */
    float background[4];
    cg_rgba8 background8;
    float *depth;
    frame_vertex *vertices;
    float *attributes;    /* attribute_count per vertex, valid where */
    atomic_uchar *states; /* ... the vertex's state is 2 (see
                                   vertex_attributes in pipeline.h) */
    int thread_count;
    render_chunk *chunks; /* chunk_count triangle ranges, in mesh order */
    int chunk_count;
    size_t stride;
    size_t setup_slack; /* setups of room kept after the last one */
    int tiles_x, tiles_y, tile_count;
    unsigned char *clean_tiles; /* the renderer's */
    size_t splits;
} render_frame;

/* Clip coordinates and world position of mesh vertex i, computed as the
 * vertex stage computes them. */
void render_clip_position(const render_frame *frame, size_t i, double c[4]);
void render_world_position(const render_frame *frame, size_t i, float out[3]);
/* Frees the buffers a renderer keeps between frames. */
void render_buffers_free(cg_renderer *r);
/* With options.shadows, the shadow map of each directional light of the
 * frame into f->lighting (CG_ENOMEM); frees them. */
cg_status render_shadows_build(render_frame *f);
void render_shadows_free(cg_renderer *r);

/* Stores the flat (or Phong base) colour of a set-up triangle, encoded too. */
void render_finish_setup(const render_frame *frame, setup_triangle *t, const float color[3]);
/* Rasterizes t inside [x0, x1) x [y0, y1) with the frame's shading: with
 * depth_test, only nearer fragments are written (and their depth); without,
 * every fragment overwrites colour and depth (painter's).  Returns the
 * number of covered pixels. */
size_t render_raster(const render_frame *frame, const setup_triangle *t, int x0, int y0, int x1,
                     int y1, int depth_test);

/* cg_shading_pixel_steps' report of the fragment of t at the probed pixel
 * (shade_probe.c), after render_raster drew t; depth_before: the buffer's
 * depth there before. */
void render_probe_fragment(const render_frame *frame, const setup_triangle *t, float depth_before);

/* Painter's algorithm and edge drawing, in their own files. */
cg_status render_painter(render_frame *frame);
cg_status render_edges(render_frame *frame);

#endif
