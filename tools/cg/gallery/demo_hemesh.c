/* Gallery: the half-edge structure of chapter 9 - half-edges drawn as
 * arrows inside their faces, the one-ring of a vertex, and Loop and
 * Catmull-Clark subdivision levels 0 to 3. */
#include "script_pictures.h"
#include "cg/hemesh.h"
#include "cg/xform.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static const cg_rgba8 white = {255, 255, 255, 255}, ink = {40, 44, 52, 255},
                      faint = {205, 208, 214, 255}, boundary_red = {205, 45, 45, 255},
                      orange = {230, 120, 20, 255}, blue = {40, 90, 200, 255};

/* A mesh from a list of points and faces given as (size, corners...). */
static cg_hemesh *make_mesh(const double (*points)[3], size_t n, const uint32_t *faces,
                            size_t face_count)
{
    size_t corners = 0;
    const uint32_t *p = faces;
    for (size_t f = 0; f < face_count; f++) {
        corners += p[0];
        p += p[0] + 1;
    }
    cg_mesh *mesh = NULL;
    if (cg_mesh_create(&mesh, n, face_count, corners, 0) != CG_OK)
        return NULL;
    for (size_t v = 0; v < n; v++)
        mesh->positions[v] = cg_vec3_make(points[v][0], points[v][1], points[v][2]);
    p = faces;
    size_t k = 0;
    for (size_t f = 0; f < face_count; f++) {
        for (uint32_t i = 1; i <= p[0]; i++)
            mesh->face_indices[k++] = p[i];
        mesh->face_offsets[f + 1] = (uint32_t)k;
        p += p[0] + 1;
    }
    cg_hemesh *h = NULL;
    cg_hemesh_build(mesh, 0, &h, NULL, NULL);
    cg_mesh_free(mesh);
    return h;
}

/* Each picture is a draw script written next to it (the meshes are built,
 * subdivided and projected in C), so its caption is `cg draw`. */
static sketch *blank(int width, int height)
{
    sketch *k = calloc(1, sizeof *k);
    if (k)
        sketch_add(k, "size %d %d\nbackground #%02x%02x%02x\n", width, height, white.r, white.g,
                   white.b);
    return k;
}

static void sketch_free(sketch *k)
{
    if (k)
        free(k->text);
    free(k);
}

static void set_color(sketch *k, cg_rgba8 c)
{
    sketch_add(k, "color #%02x%02x%02x\n", c.r, c.g, c.b);
}

/* A line about `width` pixels wide: parallel Bresenham lines. */
static void thick_line(sketch *image, double x0, double y0, double x1, double y1, int width,
                       cg_rgba8 color)
{
    set_color(image, color);
    for (int dx = 0; dx < width; dx++)
        for (int dy = 0; dy < width; dy++)
            sketch_add(image, "line %d %d %d %d\n", (int)lround(x0) + dx - width / 2,
                       (int)lround(y0) + dy - width / 2, (int)lround(x1) + dx - width / 2,
                       (int)lround(y1) + dy - width / 2);
}

/* The pixels within radius of (x, y), row by row. */
static void dot(sketch *image, double x, double y, int radius, cg_rgba8 color)
{
    set_color(image, color);
    for (int dy = -radius; dy <= radius; dy++) {
        int half = 0;
        while ((half + 1) * (half + 1) + dy * dy <= radius * radius)
            half++;
        int cx = (int)lround(x), cy = (int)lround(y) + dy;
        sketch_add(image, "line %d %d %d %d\n", cx - half, cy, cx + half, cy);
    }
}

/* An arrow from p to q with a head of two strokes. */
static void arrow(sketch *image, cg_vec2 p, cg_vec2 q, cg_rgba8 color)
{
    thick_line(image, p.x, p.y, q.x, q.y, 2, color);
    cg_vec2 d = cg_vec2_normalize(cg_vec2_sub(p, q));
    double c = cos(0.45), s = sin(0.45), len = 11;
    cg_vec2 l = {d.x * c - d.y * s, d.x * s + d.y * c}, r = {d.x * c + d.y * s, -d.x * s + d.y * c};
    thick_line(image, q.x, q.y, q.x + len * l.x, q.y + len * l.y, 2, color);
    thick_line(image, q.x, q.y, q.x + len * r.x, q.y + len * r.y, 2, color);
}

/* Writes the script and adds its picture to the gallery; frees it and the
 * mesh. */
static int finish(demo_context *context, const char *name, sketch *image, cg_hemesh *h,
                  const char *caption)
{
    int status = image->failed ? 1 : draw_demo_script(context, name, image->text, caption);
    sketch_free(image);
    cg_hemesh_free(h);
    return status;
}

/* ---- half-edges of a planar mesh --------------------------------------- */

static cg_vec2 to_pixel(cg_vec3 p, double scale, double ox, double oy)
{
    return cg_vec2_make(ox + scale * p.x, oy - scale * p.y);
}

static cg_vec2 face_centre(const cg_hemesh *h, uint32_t f, double scale, double ox, double oy)
{
    cg_vec2 c = {0, 0};
    uint32_t v[16];
    size_t n = cg_hemesh_face_vertices(h, f, v, 16);
    for (size_t i = 0; i < n; i++)
        c = cg_vec2_add(c, to_pixel(h->positions[v[i]], scale, ox, oy));
    return cg_vec2_scale(c, 1.0 / (double)n);
}

static int render_halfedges(demo_context *context)
{
    static const double points[][3] = {{0, 0, 0},   {2, 0, 0}, {4, 0, 0},   {0, 2, 0},
                                       {2, 2.2, 0}, {4, 2, 0}, {1, 3.7, 0}, {3, 3.7, 0}};
    static const uint32_t faces[] = {4, 0, 1, 4, 3, 4, 1, 2, 5, 4, 3,
                                     3, 4, 6, 3, 4, 7, 6, 3, 4, 5, 7};
    cg_hemesh *h = make_mesh(points, 8, faces, 5);
    sketch *image = blank(640, 560);
    if (!h || !image) {
        cg_hemesh_free(h);
        sketch_free(image);
        return 1;
    }
    double scale = 130, ox = 60, oy = 520;
    static const cg_rgba8 face_colour[5] = {{40, 110, 200, 255},
                                            {30, 150, 90, 255},
                                            {150, 80, 190, 255},
                                            {200, 130, 20, 255},
                                            {20, 150, 160, 255}};
    /* the edges, faint */
    for (uint32_t e = 0; e < h->halfedge_count / 2; e++) {
        cg_vec2 a = to_pixel(h->positions[cg_hemesh_origin(h, 2 * e)], scale, ox, oy);
        cg_vec2 b = to_pixel(h->positions[cg_hemesh_dest(h, 2 * e)], scale, ox, oy);
        thick_line(image, a.x, a.y, b.x, b.y, 1, faint);
    }
    /* each half-edge: an arrow pulled towards the centre of its face, or
     * pushed away from its twin's face when on the boundary */
    for (uint32_t x = 0; x < h->halfedge_count; x++) {
        cg_vec2 a = to_pixel(h->positions[cg_hemesh_origin(h, x)], scale, ox, oy);
        cg_vec2 b = to_pixel(h->positions[cg_hemesh_dest(h, x)], scale, ox, oy);
        uint32_t f = cg_hemesh_face(h, x);
        int outside = f == CG_HEMESH_NONE;
        cg_vec2 c = face_centre(h, outside ? cg_hemesh_face(h, x ^ 1u) : f, scale, ox, oy);
        double pull = outside ? -0.13 : 0.16;
        cg_vec2 a1 = cg_vec2_add(a, cg_vec2_scale(cg_vec2_sub(c, a), pull));
        cg_vec2 b1 = cg_vec2_add(b, cg_vec2_scale(cg_vec2_sub(c, b), pull));
        cg_vec2 p = cg_vec2_add(a1, cg_vec2_scale(cg_vec2_sub(b1, a1), 0.14));
        cg_vec2 q = cg_vec2_add(a1, cg_vec2_scale(cg_vec2_sub(b1, a1), 0.86));
        arrow(image, p, q, outside ? boundary_red : face_colour[f % 5]);
    }
    for (uint32_t v = 0; v < h->vertex_count; v++) {
        cg_vec2 p = to_pixel(h->positions[v], scale, ox, oy);
        dot(image, p.x, p.y, 5, ink);
    }
    return finish(context, "hemesh-halfedges", image, h,
                  "Half-edge structure (DCEL): each face's half-edges run counter-clockwise "
                  "inside it (one colour per face); the boundary loop's half-edges (red) "
                  "run clockwise outside, with no face");
}

/* ---- 3D views ---------------------------------------------------------- */

typedef struct view {
    cg_mat4 rotation;
    double scale, ox, oy;
} view;

static cg_vec3 view_point(const view *w, cg_vec3 p)
{
    cg_vec3 r = cg_mat4_transform_point(w->rotation, p);
    return cg_vec3_make(w->ox + w->scale * r.x, w->oy - w->scale * r.y, r.z);
}

static int front_facing(const cg_hemesh *h, const view *w, uint32_t f)
{
    if (f == CG_HEMESH_NONE)
        return 0;
    cg_vec3 n = cg_mat4_transform_vector(w->rotation, cg_hemesh_face_newell(h, f));
    return n.z > 0;
}

/* Edges seen from the front dark, hidden ones faint. */
static void draw_wire(sketch *image, const cg_hemesh *h, const view *w, int width)
{
    for (int pass = 0; pass < 2; pass++)
        for (uint32_t e = 0; e < h->halfedge_count / 2; e++) {
            if (cg_hemesh_edge_is_deleted(h, e))
                continue;
            int front = front_facing(h, w, cg_hemesh_face(h, 2 * e))
                        || front_facing(h, w, cg_hemesh_face(h, 2 * e + 1));
            if (front != pass)
                continue;
            cg_vec3 a = view_point(w, h->positions[cg_hemesh_origin(h, 2 * e)]);
            cg_vec3 b = view_point(w, h->positions[cg_hemesh_dest(h, 2 * e)]);
            thick_line(image, a.x, a.y, b.x, b.y, front ? width : 1, front ? ink : faint);
        }
}

static view make_view(double about_y, double about_x, double scale, double ox, double oy)
{
    view w;
    w.rotation = cg_mat4_mul(cg_xform3_rotate_x(about_x), cg_xform3_rotate_y(about_y));
    w.scale = scale;
    w.ox = ox;
    w.oy = oy;
    return w;
}

static int render_one_ring(demo_context *context)
{
    static const double points[][3] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                       {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
    static const uint32_t faces[] = {3, 0, 2, 4, 3, 2, 1, 4, 3, 1, 3, 4, 3, 3, 0, 4,
                                     3, 2, 0, 5, 3, 1, 2, 5, 3, 3, 1, 5, 3, 0, 3, 5};
    cg_hemesh *h = make_mesh(points, 6, faces, 8);
    for (int level = 0; h && level < 2; level++) {
        cg_hemesh *next = NULL;
        cg_hemesh_subdivide_loop(h, &next);
        cg_hemesh_free(h);
        h = next;
    }
    sketch *image = blank(560, 560);
    if (!h || !image) {
        cg_hemesh_free(h);
        sketch_free(image);
        return 1;
    }
    for (size_t v = 0; v < h->vertex_count; v++)
        h->positions[v] = cg_vec3_normalize(h->positions[v]);
    view w = make_view(cg_radians(25), cg_radians(20), 230, 280, 280);
    draw_wire(image, h, &w, 1);
    /* the vertex nearest the viewer with valence 6 */
    uint32_t best = 0;
    double best_z = -2;
    for (uint32_t v = 0; v < h->vertex_count; v++) {
        double z = view_point(&w, h->positions[v]).z;
        if (cg_hemesh_valence(h, v) == 6 && z > best_z) {
            best_z = z;
            best = v;
        }
    }
    /* the link: for each outgoing half-edge x, the edge next(x) opposite v */
    uint32_t out[32];
    size_t n = cg_hemesh_vertex_outgoing(h, best, 1, out, 32);
    cg_vec3 c = view_point(&w, h->positions[best]);
    for (size_t i = 0; i < n && i < 32; i++) {
        uint32_t x = cg_hemesh_next(h, out[i]);
        cg_vec3 a = view_point(&w, h->positions[cg_hemesh_origin(h, x)]);
        cg_vec3 b = view_point(&w, h->positions[cg_hemesh_dest(h, x)]);
        thick_line(image, a.x, a.y, b.x, b.y, 4, blue);
    }
    for (size_t i = 0; i < n && i < 32; i++) {
        cg_vec3 b = view_point(&w, h->positions[cg_hemesh_dest(h, out[i])]);
        cg_vec2 p = cg_vec2_make(c.x + 0.12 * (b.x - c.x), c.y + 0.12 * (b.y - c.y));
        cg_vec2 q = cg_vec2_make(c.x + 0.85 * (b.x - c.x), c.y + 0.85 * (b.y - c.y));
        arrow(image, p, q, orange);
        dot(image, b.x, b.y, 5, blue);
    }
    dot(image, c.x, c.y, 6, boundary_red);
    return finish(context, "hemesh-one-ring", image, h,
                  "One-ring of a vertex found by rotation (h = twin(prev(h))): its "
                  "outgoing half-edges (orange), neighbours and link (blue), in time "
                  "proportional to the valence");
}

static int render_levels(demo_context *context, cg_hemesh *h, int loop, const char *file,
                         const char *caption)
{
    int panel = 300;
    sketch *image = blank(4 * panel, panel);
    if (!h || !image) {
        cg_hemesh_free(h);
        sketch_free(image);
        return 1;
    }
    for (int level = 0; level <= 3; level++) {
        /* each level fitted to its panel (Loop shrinks a tetrahedron a lot) */
        view w = make_view(cg_radians(loop ? 60 : 30), cg_radians(loop ? 15 : 25), 1, 0, 0);
        double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
        for (uint32_t v = 0; v < h->vertex_count; v++) {
            cg_vec3 p = view_point(&w, h->positions[v]);
            lo_x = fmin(lo_x, p.x), hi_x = fmax(hi_x, p.x);
            lo_y = fmin(lo_y, p.y), hi_y = fmax(hi_y, p.y);
        }
        w.scale = 0.8 * panel / fmax(fmax(hi_x - lo_x, hi_y - lo_y), 1e-9);
        w.ox = panel * level + panel / 2.0 - w.scale * (lo_x + hi_x) / 2;
        w.oy = panel / 2.0 + w.scale * (lo_y + hi_y) / 2;
        draw_wire(image, h, &w, level < 2 ? 2 : 1);
        if (level == 3)
            break;
        cg_hemesh *next = NULL;
        cg_status s = loop ? cg_hemesh_subdivide_loop(h, &next)
                           : cg_hemesh_subdivide_catmull_clark(h, &next);
        cg_hemesh_free(h);
        h = next;
        if (s != CG_OK)
            break;
    }
    return finish(context, file, image, h, caption);
}

static int render(demo_context *context)
{
    if (render_halfedges(context) || render_one_ring(context))
        return 1;
    static const double tetra[][3] = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    static const uint32_t tetra_faces[] = {3, 0, 1, 2, 3, 0, 2, 3, 3, 0, 3, 1, 3, 1, 3, 2};
    if (render_levels(
            context, make_mesh(tetra, 4, tetra_faces, 4), 1, "hemesh-loop",
            "Loop subdivision of a tetrahedron, levels 0 to 3: 4, 16, 64 and 256 "
            "triangles (F' = 4F), each level scaled to fit (the limit surface is much smaller)"))
        return 1;
    static const double box[][3] = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1},
                                    {-1, -1, 1},  {1, -1, 1},  {1, 1, 1},  {-1, 1, 1}};
    static const uint32_t box_faces[] = {4, 0, 3, 2, 1, 4, 4, 5, 6, 7, 4, 0, 1, 5, 4,
                                         4, 3, 7, 6, 2, 4, 0, 4, 7, 3, 4, 1, 2, 6, 5};
    return render_levels(context, make_mesh(box, 8, box_faces, 6), 0, "hemesh-catmull-clark",
                         "Catmull-Clark subdivision of a cube, levels 0 to 3: 6, 24, 96 and 384 "
                         "quads, converging to a rounded shape");
}

const demo_section demo_section_hemesh = {9, "Half-edge meshes (DCEL)", render};
