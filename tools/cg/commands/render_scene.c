/* `cg render SCENE.json`: load, apply the command line (render_scene_apply.c),
 * render with the scene's algorithm (or the command line's), draw the
 * overlays, write. */
#include "render_scene.h"
#include "cli.h"
#include "render_request.h"
#include "draw_script_run.h"
#include "cg/scene.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int render_scene_is_scene(const char *path)
{
    size_t n = strlen(path);
    return n > 5 && strcmp(path + n - 5, ".json") == 0;
}

/* The overlay lines as one script, drawn on the picture. */
static int draw_overlays(const cg_scene *scene, const char *path, cg_image *image)
{
    size_t size = 1;
    for (size_t i = 0; i < scene->overlay_count; i++)
        size += strlen(scene->overlays[i]) + 1;
    char *text = malloc(size), *at = text;
    if (!text)
        return cli_fail("render: out of memory");
    for (size_t i = 0; i < scene->overlay_count; i++) {
        size_t n = strlen(scene->overlays[i]);
        memcpy(at, scene->overlays[i], n);
        at[n] = '\n';
        at += n + 1;
    }
    *at = '\0';
    draw_script script;
    int status = draw_script_parse_array(path, "overlays", text, &script);
    free(text);
    if (status)
        return CLI_FAILED;
    status = draw_script_run_on(&script, image) ? CLI_FAILED : CLI_OK;
    draw_script_free(&script);
    return status;
}

int render_scene_file(const char *command, const render_request *r)
{
    const char *path = r->trace.input, *out_path = r->trace.common.output;
    int repeat = r->trace.common.repeat;
    cg_scene *scene;
    cg_error err;
    if (cg_scene_load(path, &scene, &err) != CG_OK)
        return cli_fail("%s", err.message);
    if (render_scene_apply(command, r, scene) != CLI_OK) {
        cg_scene_free(scene);
        return CLI_USAGE;
    }
    int frames = repeat > 0 ? repeat : 1;
    double *times = malloc(sizeof *times * (size_t)frames);
    cg_image *image = NULL;
    int status = times ? CLI_OK : cli_fail("render: out of memory");
    for (int i = 0; i < frames && status == CLI_OK; i++) {
        cg_image_free(image);
        image = NULL;
        double start = cli_now();
        if (cg_scene_render(scene, &image, &err) != CG_OK)
            status = cli_fail("%s", err.message);
        times[i] = cli_now() - start;
    }
    if (status == CLI_OK && repeat > 0)
        fprintf(stderr, "frame: %.1f ms\n", cli_median(times, frames) * 1e3);
    if (status == CLI_OK && scene->overlay_count)
        status = draw_overlays(scene, path, image);
    if (status == CLI_OK)
        status = cli_write_image(image, out_path);
    free(times);
    cg_image_free(image);
    cg_scene_free(scene);
    return status;
}
