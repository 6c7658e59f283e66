/* cg render MESH|SCENE.json -o OUT: the rasterizing pipeline (z-buffer or painter's) or
 * the ray tracer on a mesh file. */
#include "cli.h"
#include "command.h"
#include "render_options.h"
#include "render_raytrace.h"
#include "render_scene.h"
#include "cg/color.h"
#include "cg/mesh.h"
#include "cg/render.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define NAME "render"

typedef struct progress_state {
    double start, last;
    int shown;
} progress_state;

/* Shows the percentage done on stderr once a frame takes over a second. */
static void show_progress(void *user, double fraction)
{
    progress_state *p = user;
    double now = cli_now();
    if (now - p->start < 1.0 || (now - p->last < 0.25 && fraction < 1))
        return;
    p->last = now;
    p->shown = 1;
    fprintf(stderr, "\rcg: render: %3.0f%%", fraction * 100);
    if (fraction >= 1)
        fputc('\n', stderr);
    fflush(stderr);
}

static int run(int argc, char **argv)
{
    const char *mesh_path = NULL;
    int have_from = 0, algorithm = 0, output_depth = 0;
    render_cli_options common;
    render_cli_options_default(&common);
    cg_render_options o;
    double crease = 60;
    cg_vec3 from = {0, 0, 1};
    static const char *const algorithms[] = {"zbuffer", "painter", "raytrace", "depth-sort"};
    static const char *const culls[] = {"none", "back"};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i], *v;
        if (!cli_is_option(a)) {
            if (mesh_path)
                return cli_usage_error(NAME, "expected one MESH file, got '%s' as well", a);
            mesh_path = a;
            continue;
        }
        int shared = render_cli_parse_option(NAME, argc, argv, &i, &common);
        if (shared < 0)
            return CLI_USAGE;
        if (shared) {
            if (cli_option_is(a, "--up") && !(cg_vec3_length(common.up) > 0))
                return cli_usage_error(NAME, "--up: the up vector must not be zero");
            continue;
        }
#define VALUE() \
    if (!(v = cli_option_value(NAME, argc, argv, &i))) \
        return CLI_USAGE
        if (cli_option_is(a, "--view-from")) {
            VALUE();
            if (cli_parse_vec3(NAME, "--view-from", v, &from))
                return CLI_USAGE;
            if (!(cg_vec3_length(from) > 0))
                return cli_usage_error(NAME, "--view-from: the direction must not be zero");
            have_from = 1;
        } else if (cli_option_is(a, "--specular") || cli_option_is(a, "--shininess")
                   || cli_option_is(a, "--crease")) {
            int which = cli_option_is(a, "--specular") ? 0 : cli_option_is(a, "--shininess") ? 1 : 2;
            static const char *const names[] = {"--specular", "--shininess", "--crease"};
            double k;
            VALUE();
            if (cli_parse_double(NAME, names[which], v, &k))
                return CLI_USAGE;
            if (!(k >= 0) || (which == 2 && k > 180))
                return cli_usage_error(NAME, "%s: expected a number >= 0%s, got '%s'", names[which],
                                       which == 2 ? " and <= 180" : "", v);
            if (which == 0)
                common.render.specular = k;
            else if (which == 1)
                common.render.shininess = k;
            else
                crease = k;
        } else if (cli_option_is(a, "--cull")) {
            int c;
            VALUE();
            if (render_cli_parse_choice(NAME, "--cull", v, culls, 2, &c))
                return CLI_USAGE;
            common.render.cull = (cg_cull_mode)c;
        } else if (cli_option_is(a, "--algorithm")) {
            VALUE();
            if (render_cli_parse_choice(NAME, "--algorithm", v, algorithms, 4, &algorithm))
                return CLI_USAGE;
        } else if (cli_option_is(a, "--wireframe")) {
            common.render.edges = CG_EDGES_WIREFRAME;
        } else if (cli_option_is(a, "--hidden-line")) {
            common.render.edges = CG_EDGES_HIDDEN_LINE;
        } else if (cli_option_is(a, "--output-depth")) {
            output_depth = 1;
        } else if (cli_option_is(a, "--edges")) {
            common.render.edges = CG_EDGES_OVERLAY;
        } else if (cli_option_is(a, "--edge-color")) {
            cg_rgba8 c;
            VALUE();
            if (cli_parse_color(NAME, "--edge-color", v, &c))
                return CLI_USAGE;
            common.render.edge_color = cg_rgba8_to_linear(c);
        } else {
            return cli_usage_error(NAME, "unknown option '%s'", a);
        }
#undef VALUE
    }
    o = common.render;
    const char *out_path = common.output;
    int width = common.width, height = common.height;
    int have_eye = common.have_eye, have_target = common.have_target;
    int repeat = common.repeat;
    double fov = common.fov_degrees, ortho = common.ortho_height;
    cg_vec3 eye = common.eye, target = common.target, up = common.up;
    if (!mesh_path)
        return cli_usage_error(NAME, "expected a MESH file");
    if (have_eye && have_from)
        return cli_usage_error(NAME, "--eye and --view-from exclude each other");
    if (render_cli_check_output(NAME, out_path) != CLI_OK)
        return CLI_USAGE;
    if (render_scene_is_scene(mesh_path)) {
        /* A scene file: the options given on the command line win over its own. */
        render_scene_overrides so = render_scene_no_overrides();
        if (render_scene_option_given(argc, argv, "--algorithm"))
            so.algorithm = algorithm == 3 ? 1 : algorithm;
        if (render_scene_option_given(argc, argv, "--shading"))
            so.shading = (int)o.shading;
        if (render_scene_option_given(argc, argv, "--size")) {
            so.width = width;
            so.height = height;
        }
        if (render_scene_option_given(argc, argv, "--threads"))
            so.threads = o.threads;
        so.repeat = repeat;
        return render_scene_file(mesh_path, out_path, &so);
    }
    o.crease_angle = cg_radians(crease);

    cg_mesh *mesh;
    cg_error err;
    if (cg_mesh_load(mesh_path, &mesh, &err) != CG_OK)
        return cli_fail("%s", err.message);

    /* The camera: framed to the whole mesh unless --eye places it. */
    double aspect = (double)width / height;
    cg_camera camera = cg_camera_default();
    camera.up = up;
    camera.fovy = cg_radians(fov);
    camera.orthographic = ortho > 0;
    if (ortho > 0)
        camera.ortho_height = ortho;
    cg_vec3 lo, hi;
    int bounded = cg_mesh_bounds(mesh, &lo, &hi) == CG_OK;
    cg_vec3 centre = bounded ? cg_vec3_scale(cg_vec3_add(lo, hi), 0.5) : cg_vec3_make(0, 0, 0);
    if (have_eye) {
        camera.eye = eye;
        camera.target = have_target ? target : centre;
        if (!(cg_vec3_length(cg_vec3_sub(camera.target, camera.eye)) > 0)) {
            cg_mesh_free(mesh);
            return cli_usage_error(NAME, "--eye and --target must differ");
        }
    } else {
        if (have_target)
            camera.target = target;
        camera.eye = cg_vec3_add(camera.target, from);
        if (bounded) {
            cg_camera_frame(&camera, lo, hi, aspect);
            if (have_target) {
                /* Keep the target the user named, at the framed distance. */
                cg_vec3 offset = cg_vec3_sub(camera.eye, camera.target);
                camera.target = target;
                camera.eye = cg_vec3_add(target, offset);
            }
            if (ortho > 0)
                camera.ortho_height = ortho;
        }
    }
    cg_vec3 view_dir = cg_vec3_sub(camera.target, camera.eye);
    if (cg_vec3_length(cg_vec3_cross(view_dir, camera.up)) <= 1e-12 * cg_vec3_length(view_dir)) {
        cg_mesh_free(mesh);
        return cli_usage_error(NAME, "--up must not be parallel to the viewing direction");
    }
    if (render_cli_set_depth(NAME, &common, bounded, lo, hi, &camera) != CLI_OK) {
        cg_mesh_free(mesh);
        return CLI_USAGE;
    }
    o.camera = camera;

    progress_state progress = {0, 0, 0};
    o.progress = show_progress;
    o.progress_user = &progress;

    cg_image *image;
    if (cg_image_create(&image, width, height, CG_PIXEL_RGBA8) != CG_OK) {
        cg_mesh_free(mesh);
        return cli_fail("render: cannot make a %dx%d image", width, height);
    }
    int status = CLI_OK;
    cg_renderer *renderer = NULL;
    render_raytracer *tracer = NULL;
    if (algorithm == 2) {
        status = render_raytrace_create(mesh, &o, &tracer);
    } else {
        o.algorithm = algorithm == 0 ? CG_RENDER_ZBUFFER : algorithm == 1 ? CG_RENDER_PAINTER
                                                                          : CG_RENDER_DEPTH_SORT;
        if (cg_renderer_create(mesh, &o, &renderer, &err) != CG_OK)
            status = cli_fail("%s: %s", mesh_path, err.message);
    }
    cg_mesh_free(mesh);
    int frames = repeat > 0 ? (int)repeat : 1;
    double *times = status == CLI_OK ? malloc(sizeof *times * (size_t)frames) : NULL;
    if (status == CLI_OK && !times)
        status = cli_fail("render: out of memory");
    for (int i = 0; i < frames && status == CLI_OK; i++) {
        progress.start = cli_now();
        progress.last = 0;
        if (tracer) {
            status = render_raytrace_draw(tracer, image);
        } else {
            cg_status s = cg_renderer_draw(renderer, image);
            if (s != CG_OK)
                status = cli_fail("render: %s", cg_status_str(s));
        }
        times[i] = cli_now() - progress.start;
        if (progress.shown && progress.last > 0)
            show_progress(&progress, 1);
        progress.shown = 0;
    }
    if (status == CLI_OK && repeat > 0)
        fprintf(stderr, "frame: %.1f ms\n", cli_median(times, frames) * 1e3);
    if (status == CLI_OK && output_depth) {
        if (!renderer || cg_renderer_depth_image(renderer, image) != CG_OK)
            status = cli_fail("render: --output-depth needs --algorithm zbuffer or painter");
    }
    if (status == CLI_OK)
        status = cli_write_image(image, out_path);
    free(times);
    cg_renderer_free(renderer);
    render_raytrace_free(tracer);
    cg_image_free(image);
    return status;
}

const cg_command cg_command_render = {
    NAME,
    "render a mesh or scene file: z-buffer, painter's or ray tracing",
    "usage: cg render MESH -o OUT [options]\n"
    "       cg render SCENE.json -o OUT [--algorithm A] [--shading S] [--size WxH]\n"
    "                                   [--threads N] [--repeat N]\n\n"
    "Renders MESH (OBJ, PLY, OFF or STL, optionally gzip-compressed) and writes\n"
    "OUT in the format of its extension (.png, .ppm, .pgm).  A SCENE.json file\n"
    "(docs/scene-format.md) brings its own camera, lights, materials and objects;\n"
    "the options listed on its line above override the scene's own settings.\n\n"
    "Camera (default: looking along -z, placed so the whole mesh fills the view):\n"
    "  --size WxH            image size (default 800x600)\n"
    "  --eye X,Y,Z           camera position (then no automatic framing)\n"
    "  --view-from X,Y,Z     direction from the mesh toward a framed camera (default 0,0,1)\n"
    "  --target X,Y,Z        point looked at (default: the centre of the mesh)\n"
    "  --up X,Y,Z            up direction (default 0,1,0)\n"
    "  --fov DEGREES         vertical field of view, perspective (default 45)\n"
    "  --ortho HEIGHT        parallel projection showing HEIGHT world units vertically\n"
    "  --near D, --far D     clip distances along the view (default: the mesh's depth\n"
    "                        range; a parallel view's near may be 0 or negative)\n"
    "Light and material:\n"
    "  --light-dir X,Y,Z     directional light toward which lit surfaces face, strength 1;\n"
    "                        repeatable (default: one light from the camera's upper left)\n"
    "  --ambient K           ambient coefficient (default 0.15)\n"
    "  --specular K          specular coefficient, Blinn-Phong (default 0.25)\n"
    "  --shininess N         specular exponent (default 32)\n"
    "  --color COLOR         diffuse colour where the file has none (default #c4c4c4)\n"
    "  --background COLOR    background (default #1d1f27)\n"
    "  --edge-color COLOR    colour of wireframe and hidden lines\n"
    "Pipeline:\n"
    "  --shading flat|gouraud|phong   (default gouraud)\n"
    "  --crease DEGREES      computed normals are split where faces meet at a\n"
    "                        larger angle (default 60)\n"
    "  --cull back|none      back-face culling; front faces are counter-clockwise as\n"
    "                        seen by the camera (default back)\n"
    "  --algorithm zbuffer|painter|raytrace|depth-sort\n"
    "                        visible-surface algorithm (default zbuffer); depth-sort is\n"
    "                        painter's without its overlap tests, to show their purpose\n"
    "  --wireframe           every edge, no faces\n"
    "  --hidden-line         visible edges only\n"
    "  --edges               shaded faces with their visible edges\n"
    "  --output-depth        write the depth buffer (near light, far dark) instead\n"
    "  --threads N           worker threads, 1 to 64; the picture is the same for any N\n"
    "  --repeat N            render N frames after loading and print the median time\n"
    "                        on stderr as 'frame: 12.3 ms'\n"
    "Frames that take longer than a second show their progress on stderr.\n",
    run,
};
