/* Gallery: the rasterizing pipeline (chapter 5) and shading (chapter 8) on
 * the Stanford bunny and a few generated scenes. */
#include "demo.h"
#include "cg/color.h"
#include "cg/mesh.h"
#include "cg/render.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define W 320
#define H 240
#define BUNNY "data/meshes/bunny.obj"

/* The bunny from the project's data folder (or the working directory);
 * NULL when neither has it (an installed tool): its pictures are skipped. */
static cg_mesh *load_bunny(void)
{
    cg_mesh *mesh = NULL;
#ifdef CG_SOURCE_DIR
    if (cg_mesh_load(CG_SOURCE_DIR "/" BUNNY, &mesh, NULL) == CG_OK)
        return mesh;
#endif
    if (cg_mesh_load(BUNNY, &mesh, NULL) == CG_OK)
        return mesh;
    return NULL;
}

static cg_render_options base_options(void)
{
    cg_render_options o;
    cg_render_options_default(&o);
    return o;
}

/* Renders and adds one picture; returns 0 or non-zero. */
static int shot(demo_context *context, const cg_mesh *mesh, const cg_render_options *o,
                const char *file, const char *caption, const char *command)
{
    cg_image *image;
    if (cg_image_create(&image, W, H, CG_PIXEL_RGBA8) != CG_OK)
        return 1;
    cg_error err;
    int status = 0;
    if (cg_render(mesh, o, image, &err) != CG_OK) {
        fprintf(stderr, "cg: demo: %s: %s\n", file, err.message);
        status = 1;
    } else {
        status = demo_add(context, file, image, caption, command);
    }
    cg_image_free(image);
    return status;
}

/* Appends b's vertices and faces to a (colours per face). */
static cg_mesh *join(cg_mesh *a, cg_mesh *b, cg_rgbaf color_a, cg_rgbaf color_b)
{
    size_t corners_a = a->face_offsets[a->face_count], corners_b = b->face_offsets[b->face_count];
    cg_mesh *m;
    if (cg_mesh_create(&m, a->vertex_count + b->vertex_count, a->face_count + b->face_count,
                       corners_a + corners_b, CG_MESH_FACE_COLORS)
        != CG_OK)
        return NULL;
    memcpy(m->positions, a->positions, sizeof *a->positions * a->vertex_count);
    memcpy(m->positions + a->vertex_count, b->positions, sizeof *b->positions * b->vertex_count);
    memcpy(m->face_indices, a->face_indices, sizeof(uint32_t) * corners_a);
    for (size_t k = 0; k < corners_b; k++)
        m->face_indices[corners_a + k] = b->face_indices[k] + (uint32_t)a->vertex_count;
    for (size_t f = 0; f <= a->face_count; f++)
        m->face_offsets[f] = a->face_offsets[f];
    for (size_t f = 1; f <= b->face_count; f++)
        m->face_offsets[a->face_count + f] = b->face_offsets[f] + (uint32_t)corners_a;
    for (size_t f = 0; f < a->face_count; f++)
        m->face_colors[f] = a->face_colors ? a->face_colors[f] : color_a;
    for (size_t f = 0; f < b->face_count; f++)
        m->face_colors[a->face_count + f] = b->face_colors ? b->face_colors[f] : color_b;
    return m;
}

/* Three sticks, each lying over the next: a cyclic overlap no ordering of
 * whole polygons can draw. */
static cg_mesh *sticks(void)
{
    cg_mesh *m;
    if (cg_mesh_create(&m, 12, 3, 12, CG_MESH_FACE_COLORS) != CG_OK)
        return NULL;
    static const cg_rgbaf colors[3] = {{0.8f, 0.12f, 0.08f, 1},
                                       {0.1f, 0.55f, 0.12f, 1},
                                       {0.1f, 0.2f, 0.8f, 1}};
    for (int i = 0; i < 3; i++) {
        double angle = 2 * CG_PI * i / 3;
        double c = cos(angle), s = sin(angle);
        /* Along x from -1.1 to 1.1 at y = -0.45, width 0.35, z falling
         * from 0.5 to -0.5; then rotated by angle about z. */
        const double local[4][3] = {{-1.1, -0.62, 0.5},
                                    {1.1, -0.62, -0.5},
                                    {1.1, -0.28, -0.5},
                                    {-1.1, -0.28, 0.5}};
        for (int k = 0; k < 4; k++) {
            double x = local[k][0], y = local[k][1];
            m->positions[i * 4 + k] = cg_vec3_make(c * x - s * y, s * x + c * y, local[k][2]);
            m->face_indices[i * 4 + k] = (uint32_t)(i * 4 + k);
        }
        m->face_offsets[i + 1] = (uint32_t)(i * 4 + 4);
        m->face_colors[i] = colors[i];
    }
    return m;
}

/* Saves a generated mesh into the gallery folder so its command runs. */
static void save(demo_context *context, const cg_mesh *mesh, const char *name)
{
    char path[4096];
    snprintf(path, sizeof path, "%s/%s", demo_directory(context), name);
    cg_mesh_save(mesh, path, CG_MESH_FORMAT_AUTO, NULL);
}

/* The bunny under each option of the pipeline. */
static int bunny_variants(demo_context *context, const cg_mesh *bunny)
{
    static const struct variant {
        const char *file, *caption, *arguments;
        cg_render_algorithm algorithm;
        cg_edge_mode edges;
        cg_cull_mode cull;
        cg_shading shading;
    } variants[] = {
        {"render-zbuffer.png", "Z-buffer (5.3): nearest fragment per pixel, Gouraud shading", "",
         CG_RENDER_ZBUFFER, CG_EDGES_NONE, CG_CULL_BACK, CG_SHADING_GOURAUD},
        {"render-painter.png",
         "Painter's algorithm (5.2): depth sort with Newell's overlap tests, far to near",
         " --algorithm painter", CG_RENDER_PAINTER, CG_EDGES_NONE, CG_CULL_BACK,
         CG_SHADING_GOURAUD},
        {"render-wireframe.png",
         "Wireframe: every edge, clipped in homogeneous coordinates, Bresenham lines",
         " --wireframe --cull none", CG_RENDER_ZBUFFER, CG_EDGES_WIREFRAME, CG_CULL_NONE,
         CG_SHADING_GOURAUD},
        {"render-wireframe-culled.png",
         "Back-face culling (5.1): only faces the camera sees counter-clockwise", " --wireframe",
         CG_RENDER_ZBUFFER, CG_EDGES_WIREFRAME, CG_CULL_BACK, CG_SHADING_GOURAUD},
        {"render-hidden-line.png",
         "Hidden-line removal: edges tested against the z-buffer of the faces", " --hidden-line",
         CG_RENDER_ZBUFFER, CG_EDGES_HIDDEN_LINE, CG_CULL_BACK, CG_SHADING_GOURAUD},
        {"render-edges.png", "Flat-shaded faces with their visible edges",
         " --edges --edge-color '#1b1b1c' --shading flat", CG_RENDER_ZBUFFER, CG_EDGES_OVERLAY,
         CG_CULL_BACK, CG_SHADING_FLAT},
    };
    int status = 0;
    for (size_t i = 0; i < sizeof variants / sizeof variants[0]; i++) {
        const struct variant *v = &variants[i];
        cg_render_options o = base_options();
        o.algorithm = v->algorithm;
        o.edges = v->edges;
        o.cull = v->cull;
        o.shading = v->shading;
        if (v->edges == CG_EDGES_OVERLAY)
            o.edge_color = cg_rgba8_to_linear((cg_rgba8){0x1b, 0x1b, 0x1c, 255});
        char command[256];
        snprintf(command, sizeof command, "cg render " BUNNY " --size 320x240%s -o %s",
                 v->arguments, v->file);
        status |= shot(context, bunny, &o, v->file, v->caption, command);
    }
    return status;
}

/* A parallel view framed to the bunny. */
static int bunny_orthographic(demo_context *context, const cg_mesh *bunny)
{
    cg_render_options o = base_options();
    o.camera.orthographic = 1;
    o.camera.eye = cg_vec3_make(1, 0.6, 1);
    /* The height framing chose, so that the command repeats the view. */
    cg_renderer *framed;
    cg_image *probe;
    char command[256];
    double height = 0.2;
    if (cg_renderer_create(bunny, &o, &framed, NULL) == CG_OK) {
        if (cg_image_create(&probe, W, H, CG_PIXEL_RGBA8) == CG_OK
            && cg_renderer_draw(framed, probe) == CG_OK)
            height = cg_renderer_camera(framed).ortho_height;
        cg_image_free(probe);
        cg_renderer_free(framed);
    }
    o.frame_camera = 1;
    snprintf(command, sizeof command,
             "cg render " BUNNY
             " --size 320x240 --view-from 1,0.6,1 --ortho %.9g -o render-ortho.png",
             height);
    return shot(context, bunny, &o, "render-ortho.png",
                "Orthographic (parallel) camera from the front right, framed to the mesh", command);
}

/* The depth buffer itself. */
static int bunny_depth(demo_context *context, const cg_mesh *bunny)
{
    cg_render_options o = base_options();
    cg_renderer *r;
    cg_image *image = NULL;
    int status = 0;
    if (cg_renderer_create(bunny, &o, &r, NULL) == CG_OK) {
        if (cg_image_create(&image, W, H, CG_PIXEL_RGBA8) == CG_OK
            && cg_renderer_draw(r, image) == CG_OK && cg_renderer_depth_image(r, image) == CG_OK)
            status |= demo_add(
                context, "render-depth.png", image,
                "The z-buffer after the frame: near is light (window depth, 32-bit float)",
                "cg render " BUNNY " --size 320x240 --output-depth -o render-depth.png");
        cg_image_free(image);
        cg_renderer_free(r);
    }
    return status;
}

/* Painter's: where plain depth sorting fails. */
static int depth_sort_cycle(demo_context *context)
{
    cg_mesh *cycle = sticks();
    if (!cycle)
        return 0;
    save(context, cycle, "sticks.obj");
    cg_render_options o = base_options();
    o.cull = CG_CULL_NONE;
    o.camera.eye = cg_vec3_make(0, 0, 4);
    o.ambient = 0.35;
    static const struct {
        cg_render_algorithm algorithm;
        const char *file, *caption, *arguments;
    } sorts[] = {
        {CG_RENDER_DEPTH_SORT, "render-sort-naive.png",
         "Plain depth sort: each stick lies over the next, so any order of whole polygons is "
         "wrong somewhere",
         " --algorithm depth-sort"},
        {CG_RENDER_PAINTER, "render-sort-painter.png",
         "Painter's with Newell's tests: the cycle is found and broken by splitting a polygon "
         "along another's plane",
         " --algorithm painter"},
        {CG_RENDER_ZBUFFER, "render-sort-zbuffer.png",
         "The z-buffer on the same sticks: per-pixel depth needs no ordering", ""},
    };
    int status = 0;
    for (int i = 0; i < 3; i++) {
        char command[256];
        o.algorithm = sorts[i].algorithm;
        snprintf(command, sizeof command,
                 "cg render sticks.obj --size 320x240 --cull none --ambient 0.35%s -o %s",
                 sorts[i].arguments, sorts[i].file);
        status |= shot(context, cycle, &o, sorts[i].file, sorts[i].caption, command);
    }
    cg_mesh_free(cycle);
    return status;
}

/* Clipping: the camera inside a room, walls crossing w = 0. */
static int camera_inside_room(demo_context *context)
{
    cg_mesh *room = NULL, *ball = NULL, *scene = NULL;
    int status = 0;
    if (cg_mesh_box(cg_vec3_make(-2, -1, -2), cg_vec3_make(2, 1.5, 2), &room) == CG_OK
        && cg_mesh_torus(48, 24, 0.6, 0.25, &ball) == CG_OK) {
        for (size_t i = 0; i < ball->vertex_count; i++)
            ball->positions[i].y -= 0.3;
        scene = join(room, ball, (cg_rgbaf){0.5f, 0.45f, 0.35f, 1},
                     (cg_rgbaf){0.7f, 0.25f, 0.1f, 1});
    }
    if (scene) {
        save(context, scene, "room.obj");
        cg_render_options o = base_options();
        o.frame_camera = 0;
        o.cull = CG_CULL_NONE;
        o.shading = CG_SHADING_PHONG;
        o.camera.eye = cg_vec3_make(1.6, 0.9, 1.7);
        o.camera.target = cg_vec3_make(0, -0.3, 0);
        o.camera.fovy = cg_radians(80);
        o.camera.near = 0.05;
        o.camera.far = 20;
        status |= shot(
            context, scene, &o, "render-inside.png",
            "Camera inside a closed room: walls behind the eye (w <= 0) clipped against "
            "all six planes before the divide",
            "cg render room.obj --size 320x240 --eye 1.6,0.9,1.7 --target 0,-0.3,0 --fov 80 "
            "--cull none --shading phong -o render-inside.png");
    }
    cg_mesh_free(room);
    cg_mesh_free(ball);
    cg_mesh_free(scene);
    return status;
}

static int render_pipeline(demo_context *context)
{
    cg_mesh *bunny = load_bunny();
    int status = 0;
    if (bunny && demo_copy_input(context, BUNNY) != 0) {
        cg_mesh_free(bunny);
        return 1;
    }
    if (bunny) {
        status |= bunny_variants(context, bunny);
        status |= bunny_orthographic(context, bunny);
        status |= bunny_depth(context, bunny);
    }
    status |= depth_sort_cycle(context);
    status |= camera_inside_room(context);
    cg_mesh_free(bunny);
    return status;
}

int demo_render_shading(demo_context *context);
int demo_render_shading(demo_context *context)
{
    int status = 0;
    cg_mesh *sphere = NULL, *bunny = load_bunny();
    if (bunny && demo_copy_input(context, BUNNY) != 0) {
        cg_mesh_free(bunny);
        return 1;
    }
    if (cg_mesh_sphere(14, 8, 1, &sphere) != CG_OK) {
        cg_mesh_free(bunny);
        return 1;
    }
    save(context, sphere, "sphere.obj");
    static const char *const names[3] = {"flat", "gouraud", "phong"};
    static const char *const captions[3][2] = {
        {"Flat shading: one colour per face from its normal", "Flat shading of the bunny"},
        {"Gouraud shading: lit at the vertices, colours interpolated (the highlight breaks up)",
         "Gouraud shading of the bunny"},
        {"Phong shading: normals interpolated and lit at every pixel",
         "Phong shading of the bunny"}};
    for (int s = 0; s < 3; s++) {
        cg_render_options o = base_options();
        o.shading = (cg_shading)s;
        o.specular = 0.5;
        o.shininess = 40;
        o.camera.eye = cg_vec3_make(0, 0.5, 2);
        char file[64], command[256];
        snprintf(file, sizeof file, "shading-sphere-%s.png", names[s]);
        snprintf(
            command, sizeof command,
            "cg render sphere.obj --size 320x240 --view-from 0,0.5,2 --specular 0.5 --shininess 40 "
            "--shading %s -o %s",
            names[s], file);
        status |= shot(context, sphere, &o, file, captions[s][0], command);
        if (!bunny)
            continue;
        o = base_options();
        o.shading = (cg_shading)s;
        snprintf(file, sizeof file, "shading-bunny-%s.png", names[s]);
        snprintf(command, sizeof command, "cg render " BUNNY " --size 320x240 --shading %s -o %s",
                 names[s], file);
        status |= shot(context, bunny, &o, file, captions[s][1], command);
    }
    /* The crease angle of computed vertex normals. */
    cg_mesh *box = NULL;
    if (cg_mesh_box(cg_vec3_make(-1, -1, -1), cg_vec3_make(1, 1, 1), &box) == CG_OK) {
        save(context, box, "box.obj");
        cg_render_options o = base_options();
        o.camera.eye = cg_vec3_make(1.3, 1, 2);
        o.shading = CG_SHADING_PHONG;
        status |= shot(context, box, &o, "shading-crease-60.png",
                       "Vertex normals with a 60 degree crease angle: the cube's edges stay sharp",
                       "cg render box.obj --size 320x240 --view-from 1.3,1,2 --shading phong -o "
                       "shading-crease-60.png");
        o.crease_angle = cg_radians(100);
        status |= shot(
            context, box, &o, "shading-crease-100.png",
            "The same with a 100 degree crease: normals averaged across the edges",
            "cg render box.obj --size 320x240 --view-from 1.3,1,2 --shading phong --crease 100 "
            "-o shading-crease-100.png");
        cg_mesh_free(box);
    }
    cg_mesh_free(sphere);
    cg_mesh_free(bunny);
    return status;
}

const demo_section demo_section_render = {
    5, "Rendering pipeline: culling, clipping, z-buffer, painter's", render_pipeline};
