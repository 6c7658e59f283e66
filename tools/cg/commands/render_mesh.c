/* The rasterizer's path of `cg render` (see render_mesh.h): the camera is
 * framed to the whole mesh unless --eye places it. */
#include "render_mesh.h"

#include "cli.h"
#include "render_progress.h"
#include "cg/mesh.h"
#include "cg/render.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* The camera of the request for a mesh with bounding box [lo, hi] (bounded
 * 0: no finite vertex).  CLI_OK, or CLI_USAGE after printing. */
static int place_camera(const char *command, const render_request *r, int bounded, cg_vec3 lo,
                        cg_vec3 hi, cg_camera *out)
{
    const render_cli_options *c = &r->trace.common;
    double aspect = (double)c->size.width / c->size.height;
    cg_camera camera = cg_camera_default();
    camera.up = c->up;
    camera.fovy = cg_radians(c->fov_degrees);
    camera.orthographic = c->ortho_height > 0;
    if (c->ortho_height > 0)
        camera.ortho_height = c->ortho_height;
    cg_vec3 centre = bounded ? cg_vec3_scale(cg_vec3_add(lo, hi), 0.5) : cg_vec3_make(0, 0, 0);
    if (c->have_eye) {
        camera.eye = c->eye;
        camera.target = c->have_target ? c->target : centre;
        if (!(cg_vec3_length(cg_vec3_sub(camera.target, camera.eye)) > 0))
            return cli_usage_error(command, "--eye and --target must differ");
    } else {
        if (c->have_target)
            camera.target = c->target;
        camera.eye = cg_vec3_add(camera.target, r->trace.view_from);
        if (bounded) {
            cg_camera_frame(&camera, lo, hi, aspect);
            if (c->have_target) {
                /* Keep the target the user named, at the framed distance. */
                cg_vec3 offset = cg_vec3_sub(camera.eye, camera.target);
                camera.target = c->target;
                camera.eye = cg_vec3_add(c->target, offset);
            }
            if (c->ortho_height > 0)
                camera.ortho_height = c->ortho_height;
        }
    }
    cg_vec3 view_dir = cg_vec3_sub(camera.target, camera.eye);
    if (cg_vec3_length(cg_vec3_cross(view_dir, camera.up)) <= 1e-12 * cg_vec3_length(view_dir))
        return cli_usage_error(command, "--up must not be parallel to the viewing direction");
    if (render_cli_set_depth(command, c, bounded, lo, hi, &camera) != CLI_OK)
        return CLI_USAGE;
    *out = camera;
    return CLI_OK;
}

/* A warning when a frame drew no pixel of a face although the mesh has
 * faces, saying why. */
static void warn_if_nothing_drawn(const char *command, const char *path,
                                  const cg_renderer *renderer, const cg_render_options *o)
{
    cg_render_stats st = cg_renderer_stats(renderer);
    if (o->edges == CG_EDGES_WIREFRAME || st.triangles == 0 || st.fragments > 0)
        return;
    if (st.culled == st.triangles)
        fprintf(stderr,
                "cg: %s: warning: %s: every face was culled as a back face, nothing "
                "drawn (faces must be counter-clockwise seen from outside; try "
                "--cull none)\n",
                command, path);
    else if (st.object_culled)
        fprintf(stderr, "cg: %s: warning: %s: the mesh is outside the view, nothing drawn\n",
                command, path);
    else
        fprintf(stderr,
                "cg: %s: warning: %s: no face covers a pixel centre (%zu of %zu culled "
                "as back faces, the others degenerate, too small or outside the view)\n",
                command, path, st.culled, st.triangles);
}

/* Draws the frames and writes the output. */
static int draw_and_write(const char *command, const render_request *r, cg_renderer *renderer,
                          render_progress *progress, cg_image *image)
{
    const render_cli_options *c = &r->trace.common;
    int frames = c->repeat > 0 ? c->repeat : 1;
    double *times = malloc(sizeof *times * (size_t)frames);
    if (!times)
        return cli_fail("%s: out of memory", command);
    int status = CLI_OK;
    for (int i = 0; i < frames && status == CLI_OK; i++) {
        render_progress_start(progress, command);
        cg_status s = cg_renderer_draw(renderer, image);
        if (s != CG_OK)
            status = cli_fail("%s: %s", command, cg_status_str(s));
        times[i] = cli_now() - progress->start;
        render_progress_end(progress);
    }
    if (status == CLI_OK && c->repeat > 0)
        fprintf(stderr, "frame: %.1f ms\n", cli_median(times, frames) * 1e3);
    free(times);
    if (status == CLI_OK)
        warn_if_nothing_drawn(command, r->trace.input, renderer, &c->render);
    if (status == CLI_OK && r->output_depth && cg_renderer_depth_image(renderer, image) != CG_OK)
        status = cli_fail("%s: --output-depth: no depth buffer (the wireframe draws no faces)",
                          command);
    if (status == CLI_OK)
        status = cli_write_image(image, c->output);
    return status;
}

int render_mesh_raster(const char *command, const render_request *r)
{
    const render_cli_options *c = &r->trace.common;
    const char *path = r->trace.input;
    cg_mesh *mesh;
    cg_error err;
    if (cg_mesh_load(path, &mesh, &err) != CG_OK)
        return cli_fail("%s", err.message);
    if (mesh->face_count == 0) {
        size_t n = mesh->vertex_count;
        cg_mesh_free(mesh);
        return cli_fail("%s: %s: nothing to draw: the file has %zu vertices and no faces (a point "
                        "cloud, lines only, or a truncated file)",
                        command, path, n);
    }
    cli_print_notes(mesh->notes);
    cg_render_options o = c->render;
    cg_vec3 lo, hi;
    int bounded = cg_mesh_bounds(mesh, &lo, &hi) == CG_OK;
    int status = place_camera(command, r, bounded, lo, hi, &o.camera);
    if (status != CLI_OK) {
        cg_mesh_free(mesh);
        return status;
    }
    o.algorithm = r->algorithm == RENDER_ZBUFFER   ? CG_RENDER_ZBUFFER
                  : r->algorithm == RENDER_PAINTER ? CG_RENDER_PAINTER
                                                   : CG_RENDER_DEPTH_SORT;
    render_progress progress;
    render_progress_start(&progress, command);
    if (!r->trace.quiet) {
        o.progress = render_progress_show;
        o.progress_user = &progress;
    }
    cg_renderer *renderer = NULL;
    cg_image *image = NULL;
    if (cg_renderer_create(mesh, &o, &renderer, &err) != CG_OK)
        status = cli_fail("%s: %s", path, err.message);
    cg_mesh_free(mesh);
    for (const char *w = status == CLI_OK ? cg_renderer_warnings(renderer) : NULL; w && *w;) {
        const char *end = strchr(w, '\n');
        int n = end ? (int)(end - w) : (int)strlen(w);
        fprintf(stderr, "cg: %s: warning: %.*s\n", command, n, w);
        w += n + (end != NULL);
    }
    if (status == CLI_OK
        && cg_image_create(&image, c->size.width, c->size.height, CG_PIXEL_RGBA8) != CG_OK)
        status = cli_fail("%s: cannot make a %dx%d image", command, c->size.width, c->size.height);
    if (status == CLI_OK)
        status = draw_and_write(command, r, renderer, &progress, image);
    cg_renderer_free(renderer);
    cg_image_free(image);
    return status;
}
