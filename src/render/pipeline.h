/* What the stages of the z-buffer pipeline share.  One frame runs them in
 * this order, each stage in its own file:
 *
 *   vertex_stage.c    transform every vertex, classify it against the view
 *                     volume, project and snap the ones inside
 *   triangle_stage.c  per triangle: reject, cull, clip (clip.c), set up
 *                     (setup.c) and append to its chunk's list
 *   binning.c         per chunk: the list of its triangles on each tile
 *   rasterizer.c      per tile: every triangle binned there, in mesh order,
 *                     through the edge functions and the depth test
 *   team.c            the phases above as blocks taken by a team of threads
 *   frame.c           one frame: camera, lights, buffers, then the team
 *
 * The types of a frame (render_frame, render_chunk) are in internal.h, which
 * the painter's algorithm and the edge drawing share too. */
#ifndef CG_RENDER_PIPELINE_H
#define CG_RENDER_PIPELINE_H

#include "internal.h"
#include "../core/array.h"

#include <stdatomic.h>

/* Shading modes (the values of cg_shading, but for the textured one: every
 * frame of a textured mesh, and every unlit frame, of the z-buffer). */
enum { MODE_FLAT, MODE_GOURAUD, MODE_PHONG, MODE_TEXTURED };

/* The attributes of MODE_TEXTURED: normal, world position, base colour,
 * texture coordinates. */
#define TEXTURED_ATTRIBUTES 11
#define TEXTURED_UV 9

/* ---- materials and textured fragments (material.c, textured.c) ------------ */

/* The renderer's materials of mesh (base-colour textures read when the mesh
 * has texture coordinates), its face materials and its warnings.
 * CG_ENOMEM only: a texture that cannot be read is a warning. */
cg_status render_materials_load(cg_renderer *r, const cg_mesh *mesh);
void render_materials_free(cg_renderer *r);

/* The renderer's material index of triangle i, or RENDER_NO_MATERIAL. */
static inline uint32_t render_triangle_material(const cg_renderer *r, size_t i)
{
    return r->face_material ? r->face_material[r->triangle_face[i]] : RENDER_NO_MATERIAL;
}

/* Colour of a textured fragment: v holds the TEXTURED_ATTRIBUTES
 * interpolated (perspective-correct) at the pixel, duv the derivatives of
 * the texture coordinates along x and y (du/dx, dv/dx, du/dy, dv/dy).
 * Returns 0 when the fragment is dropped (alpha mode MASK, alpha below the
 * cutoff): then nothing of it is written, neither colour nor depth.  With
 * alpha non-NULL nothing is dropped: the fragment's alpha (material factor
 * times texel) goes to *alpha and the caller applies the mask. */
int render_textured_fragment(const render_frame *f, uint32_t material, const float *v,
                             const float duv[4], float out[3], float *alpha);

#define VERTEX_BLOCK 4096   /* vertices taken at a time */
#define TRIANGLE_BLOCK 1024 /* triangles per chunk, up to MAX_CHUNKS chunks */
#define MAX_CHUNKS 64

/* ---- vertex stage (vertex_stage.c) ---------------------------------------- */

/* Clip coordinates of a prepared position (double, so that clipping and
 * snapping see the exact product). */
static inline void clip_of(const render_frame *f, const float p[3], double c[4])
{
    double x = p[0], y = p[1], z = p[2];
    for (int k = 0; k < 4; k++)
        c[k] = f->mvp.m[k][0] * x + f->mvp.m[k][1] * y + f->mvp.m[k][2] * z + f->mvp.m[k][3];
}

static inline void world_of(const render_frame *f, const float p[3], float out[3])
{
    double x = p[0], y = p[1], z = p[2];
    for (int k = 0; k < 3; k++)
        out[k] = (float)(f->model.m[k][0] * x + f->model.m[k][1] * y + f->model.m[k][2] * z
                         + f->model.m[k][3]);
}

/* Classifies, projects and snaps vertices [begin, end) and marks their
 * attributes not yet computed. */
void render_vertex_stage(render_frame *f, size_t begin, size_t end);

/* The attributes of vertex i (its lit colour for Gouraud; normal, world
 * position and colour for Phong) into out. */
void render_compute_attributes(const render_frame *f, size_t i, float *out);

/* The attributes of vertex i, computed the first time a triangle that is
 * drawn needs them: most vertices of a large mesh belong only to back faces
 * or to triangles that cover no pixel centre, and are never lit.  The
 * thread that moves the vertex's state from 0 to 1 computes them into the
 * frame's array and publishes them (state 2); a thread that finds them in
 * the making computes its own copy into local (the same bits: the same
 * function of the same inputs), so nobody waits for anybody.  Inline: the
 * triangle stage asks for three per triangle, and most are ready. */
static inline const float *vertex_attributes(const render_frame *f, uint32_t i, float *local)
{
    float *a = f->attributes + (size_t)i * (size_t)f->attribute_count;
    unsigned char state = atomic_load_explicit(&f->states[i], memory_order_acquire);
    if (state == 2)
        return a;
    if (state == 0
        && atomic_compare_exchange_strong_explicit(&f->states[i], &state, 1, memory_order_acquire,
                                                   memory_order_acquire)) {
        render_compute_attributes(f, i, a);
        atomic_store_explicit(&f->states[i], 2, memory_order_release);
        return a;
    }
    if (state == 2)
        return a;
    render_compute_attributes(f, i, local);
    return local;
}

/* ---- triangle stage and binning (triangle_stage.c, binning.c) ------------- */

/* Rejects, culls, clips and sets up the triangles of chunk c, appending
 * them to its list (or, for the painter's algorithm, its polygons). */
void render_triangle_stage(render_frame *f, render_chunk *c, int painter);

/* Tile lists of one chunk (counting sort by tile, mesh order kept), in
 * buffers kept from frame to frame. */
void render_bin_chunk(render_frame *f, render_chunk *c);

/* ---- multisampling (multisample.c) ---------------------------------------- */

/* The samples of one tile, kept by one worker while it draws the tile:
 * depth and colour (linear RGBA) per sample, the colour of pixels whose
 * samples all agree, and a state per pixel. */
typedef struct render_samples {
    int samples;
    int x0, y0; /* the tile's corner */
    float *pixel, *depth, *color;
    unsigned char *state;
} render_samples;

/* The standard sample positions for 1 (the centre), 2, 4, 8 or 16 samples
 * (NULL for another count): x, y in 1/16 pixel from the pixel centre, y down. */
const int8_t (*render_sample_positions(int samples))[2];
/* Bytes of one tile's samples; render_samples_bind lays them out in memory
 * (float-aligned). */
size_t render_samples_bytes(int samples);
void render_samples_bind(render_samples *s, void *memory, int samples);
/* Before the tile [x0, x1) x [y0, y1): every pixel untouched (the image
 * and depth buffer cleared to the background and infinity). */
void render_samples_begin(render_frame *f, render_samples *s, int x0, int y0, int x1, int y1);
/* t drawn into the tile [x0, x1) x [y0, y1) (x0, y0 its corner); returns
 * the number of covered samples. */
size_t render_raster_samples(const render_frame *f, render_samples *s, const setup_triangle *t,
                             int x0, int y0, int x1, int y1);
/* The tile's pixels whose samples differ averaged in linear light into the
 * image, and their nearest sample's depth into the depth buffer (pixels
 * whose samples agree are written as they are drawn). */
void render_samples_resolve(render_frame *f, render_samples *s, int x0, int y0, int x1, int y1);

/* ---- the tiles (clear.c) and the team of threads (team.c) ------------------- */

/* Clears a rectangle to the background colour and (with depth) infinite
 * depth; tiles no triangle touches are streamed past the caches (stream),
 * which saves reading their lines first and keeps the caches for the tiles
 * drawn. */
void render_clear_tile(render_frame *f, int x0, int y0, int x1, int y1, int stream, int depth);

/* One frame's vertex, triangle and tile phases on the renderer's threads
 * (its pool, started or restarted for frame->thread_count); the fragment
 * count of the tiles goes to *fragments. */
void render_run_phases(render_frame *f, int painter, size_t *fragments);

/* Stops the renderer's threads (none: nothing to do). */
void render_team_stop(cg_renderer *r);

#endif
