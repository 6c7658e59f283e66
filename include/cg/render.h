/* cg/render.h - the rasterizing pipeline (chapters 5, 8 and 11.3 of the notes):
 * model / view / projection, back-face culling, clipping in homogeneous
 * coordinates, triangle rasterization by edge functions, the z-buffer and the
 * painter's algorithm, flat / Gouraud / Phong shading, wireframe and
 * hidden-line drawing, multithreaded by screen tiles.
 *
 * Conventions (see docs/render.md for the full story):
 *  - Front faces are counter-clockwise as the camera sees them (OpenGL's
 *    default, glFrontFace(GL_CCW)); cg_mesh faces are counter-clockwise seen
 *    from outside, so back-face culling removes the faces turned away.
 *  - Vertices are snapped to 1/256 pixel (CG_RASTER_SUBPIXEL_BITS); a pixel is
 *    covered when its centre (x + 0.5, y + 0.5) is inside the triangle, or on
 *    a top or left edge (the top-left rule), so triangles that share an edge
 *    cover every pixel along it exactly once.
 *  - Depth is the window depth of OpenGL: 0 at the near plane, 1 at the far
 *    plane, stored as 32-bit float (24-bit mantissa); nearer wins, and among
 *    equal depths the triangle drawn first (lower face index) wins.
 *  - Colours are linear light; the image format decides the encoding.
 *  - Output is byte-identical for any number of threads.
 */
#ifndef CG_RENDER_H
#define CG_RENDER_H

#include "cg/core.h"
#include "cg/image.h"
#include "cg/light.h"
#include "cg/mesh.h"
#include "cg/texture.h"
#include "cg/xform.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- the rasterizer on its own ------------------------------------------ */

#define CG_RASTER_SUBPIXEL_BITS 8
/* Largest image side the rasterizer accepts (fixed-point edge functions stay
 * within 64 bits): 2^20 pixels. */
#define CG_RASTER_MAX_SIDE (1 << 20)

/* Receives the covered pixels x_begin <= x < x_end of row y. */
typedef void (*cg_span_fn)(void *user, int y, int x_begin, int x_end);

/* Rasterizes the triangle with vertices v (continuous pixel coordinates, y
 * down) into a width x height grid: the vertices are snapped to the 1/256
 * pixel grid, and the covered pixels (centre inside, or on a top or left
 * edge) are reported row by row, top to bottom, through span.  Either
 * orientation; a triangle of zero area after snapping covers nothing.
 * CG_EINVAL for a non-finite vertex or a NULL argument, CG_ERANGE when a
 * side exceeds CG_RASTER_MAX_SIDE.  Vertices outside the grid are fine:
 * within 2^20 pixels of it they are used exactly; beyond, the triangle is
 * first clipped to that band in double precision (an error of about
 * |coordinate| * 2^-52 pixels in the clipped edges). */
cg_status cg_raster_triangle(const cg_vec2 v[3], int width, int height, cg_span_fn span,
                             void *user);

/* ---- the pipeline -------------------------------------------------------- */

typedef enum cg_render_algorithm {
    CG_RENDER_ZBUFFER = 0,   /* z-buffer (5.3), tiled and multithreaded */
    CG_RENDER_PAINTER = 1,   /* depth sort with Newell's overlap tests (5.2) */
    CG_RENDER_DEPTH_SORT = 2 /* plain depth sort, no overlap tests: shows what the
                                tests are for (wrong where polygons overlap in depth) */
} cg_render_algorithm;

typedef enum cg_shading {
    CG_SHADING_FLAT = 0,    /* one colour per face from its geometric normal */
    CG_SHADING_GOURAUD = 1, /* colours lit at the vertices, interpolated */
    CG_SHADING_PHONG = 2,   /* normals interpolated, lit at every pixel */
    CG_SHADING_UNLIT = 3    /* the base colour (material factor times texture
                               times vertex colour) as it is, no lighting */
} cg_shading;

typedef enum cg_cull_mode {
    CG_CULL_NONE = 0,
    CG_CULL_BACK = 1 /* drop faces the camera sees clockwise */
} cg_cull_mode;

typedef enum cg_edge_mode {
    CG_EDGES_NONE = 0,        /* shaded faces only */
    CG_EDGES_WIREFRAME = 1,   /* every edge (of the faces culling keeps), no faces */
    CG_EDGES_HIDDEN_LINE = 2, /* the visible edges only, on the background */
    CG_EDGES_OVERLAY = 3      /* shaded faces with their visible edges on top */
} cg_edge_mode;

#define CG_RENDER_MAX_LIGHTS 8

/* A directional light: direction points from the surface toward the light
 * (world space, any length but not zero). */
typedef struct cg_render_light {
    cg_vec3 direction;
    double intensity; /* 1 for full strength */
} cg_render_light;

typedef struct cg_render_options {
    cg_camera camera;
    int frame_camera; /* non-zero: cg_camera_frame places the camera to show the
                            whole mesh, keeping its viewing direction (default 1) */
    cg_mat4 model;    /* model matrix, world = model * position (default identity) */
    cg_render_algorithm algorithm;
    cg_shading shading;
    cg_cull_mode cull;
    cg_edge_mode edges;
    int threads;         /* worker threads, 1 .. 64 (default 1) */
    cg_rgbaf background; /* linear light */
    cg_rgbaf color;      /* diffuse colour where the mesh has none (linear) */
    cg_rgbaf edge_color; /* colour of wireframe and hidden lines (linear) */
    double ambient;      /* ambient coefficient, times the diffuse colour */
    double specular;     /* specular coefficient (Blinn-Phong) */
    double shininess;    /* specular exponent */
    int light_count;     /* 0: one light from the camera's upper left */
    cg_render_light lights[CG_RENDER_MAX_LIGHTS];
    /* How base-colour textures are filtered (default CG_TEXTURE_TRILINEAR,
     * the level of detail from the screen-space derivatives of the texture
     * coordinates at each pixel). */
    cg_texture_filter texture_filter;
    /* Samples per pixel of the z-buffer: 1 (default; 0 means 1 too), 2, 4, 8
     * or 16, at the standard sample positions of Direct3D and Vulkan.  Each
     * sample has its own coverage (top-left rule) and depth; a triangle is
     * shaded once per pixel, at its centre; the samples are averaged in
     * linear light.  CG_EINVAL for another count, or for more than one with
     * the painter's algorithms. */
    int msaa;
    /* Non-zero: shadow maps for the directional lights (2048 x 2048 texels
     * over the mesh's world box, percentage-closer filtered, slope-scaled
     * bias), in every algorithm and shading of the rasterizer (default 0). */
    int shadows;
    double crease_angle; /* radians: when the mesh has no normals, faces meeting at a
                            larger angle keep separate vertex normals (default 60 deg) */
    /* Called now and then from the calling thread with the fraction done
     * (0 to 1) during long renders; may be NULL. */
    void (*progress)(void *user, double fraction);
    void *progress_user;
} cg_render_options;

/* Defaults: z-buffer, Gouraud, back-face culling, framed perspective camera
 * looking along -z, white-ish surface on a dark background, ambient 0.15,
 * specular 0.25 with exponent 32, one thread. */
void cg_render_options_default(cg_render_options *options);

/* Counts from the last frame. */
typedef struct cg_render_stats {
    size_t triangles;  /* triangles in the mesh (fan triangulation) */
    size_t culled;     /* removed by back-face culling */
    size_t clipped;    /* that needed clipping against the frustum */
    size_t rejected;   /* outside the frustum, degenerate or not finite */
    size_t rasterized; /* screen triangles rasterized (after clipping) */
    size_t fragments;  /* covered pixels generated (before the depth test) */
    size_t splits;     /* painter's: polygons split to break cyclic overlaps */
    int object_culled; /* the whole mesh was outside the view (bounding box test) */
} cg_render_stats;

typedef struct cg_renderer cg_renderer;

/* Prepares a mesh for rendering: validates it, triangulates its faces by
 * fans, computes angle-weighted vertex normals with the crease angle when the
 * mesh has none, and takes the per-vertex or per-face colours.  Faces with
 * a material take its base colour (times the vertex colours); when the mesh
 * has texture coordinates, each material's base-colour texture is read
 * (cg_texture_load, or the bytes the file embeds) and the z-buffer draws
 * those faces lit per pixel (any shading but unlit) with the texel the
 * perspective-correct coordinates map to, times the base colour.  A texture
 * that cannot be read leaves its material its colour, and
 * cg_renderer_warnings says so.  The renderer
 * keeps its own copy; the mesh may be freed afterwards.  The options are
 * copied too (cg_renderer_set_options changes them later; changing the crease
 * angle or the colour needs a new renderer).  CG_EFORMAT (with err) for an
 * invalid mesh, CG_EINVAL for bad options, CG_ENOMEM. */
cg_status cg_renderer_create(const cg_mesh *mesh, const cg_render_options *options,
                             cg_renderer **out, cg_error *err);
void cg_renderer_free(cg_renderer *renderer);
/* Replaces the options for the next frames (camera, lights, modes...). */
cg_status cg_renderer_set_options(cg_renderer *renderer, const cg_render_options *options);

/* Renders one frame into image (RGBA8 or RGBAF), every pixel written.
 * A mesh with no faces gives the background.  CG_EINVAL for a NULL or empty
 * image or an unusable camera, CG_ERANGE for an image side over
 * CG_RASTER_MAX_SIDE, CG_ENOMEM. */
cg_status cg_renderer_draw(cg_renderer *renderer, cg_image *image);

/* The depth buffer of the last frame: width * height floats, row by row,
 * window depth in [0, 1], +infinity where nothing was drawn (painter's: the
 * depth of the polygon painted last at each pixel).  NULL before the first
 * frame, after a failed one, and after a wireframe frame (no faces drawn). */
const float *cg_renderer_depth(const cg_renderer *renderer);
/* Shows the last frame's depth buffer in image (RGBA8 or RGBAF, the size of
 * the frame): grey levels from light (nearest drawn depth) to dark (farthest),
 * black where nothing was drawn.  CG_EINVAL without a depth buffer or for a
 * different size. */
cg_status cg_renderer_depth_image(const cg_renderer *renderer, cg_image *image);
/* What preparing the mesh could not do, one line each ("texture of
 * material 'NAME': why; drawn with the material's colour"), or NULL when nothing went
 * wrong.  Owned by the renderer. */
const char *cg_renderer_warnings(const cg_renderer *renderer);
/* The counts of the last frame. */
cg_render_stats cg_renderer_stats(const cg_renderer *renderer);
/* The camera the last frame used (after framing). */
cg_camera cg_renderer_camera(const cg_renderer *renderer);

/* The light the renderer uses when the options name none: a directional key
 * light of strength 0.85 from the upper left of the camera whose view matrix
 * is given (view-space direction (-1, 1, 1.5)).  The ray tracer's commands
 * and scenes without lights use it too, so every renderer lights alike. */
cg_light cg_render_key_light(cg_mat4 view);

/* One-shot: create, draw, free. */
cg_status cg_render(const cg_mesh *mesh, const cg_render_options *options, cg_image *image,
                    cg_error *err);


/* cg_mesh_corner_normals and the generated meshes (cg_mesh_sphere,
 * cg_mesh_torus, cg_mesh_box) are declared in cg/mesh.h, included above. */

#ifdef __cplusplus
}
#endif
#endif
