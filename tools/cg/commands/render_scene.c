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

/* The file of frame `frame` for the output path: a %d or %0Nd in out takes
 * the number, else -NNNN goes before the extension.  0, or -1 after a
 * message when out holds another conversion or the name is too long. */
static int frame_path(const char *out, int frame, char *path, size_t size)
{
    const char *percent = strchr(out, '%');
    int n;
    if (percent) {
        const char *p = percent + 1;
        if (*p == '0' && p[1] >= '1' && p[1] <= '9')
            p += 2;
        if (*p != 'd' || strchr(p, '%')) {
            cli_usage_error("render",
                            "--frames: %s: the only %% in OUT may be %%d or %%0Nd (N from 1 to "
                            "9), for the frame number",
                            out);
            return -1;
        }
        /* one integer conversion checked above */
        n = snprintf(path, size, "%.*s%0*d%s", (int)(percent - out), out,
                     p == percent + 3 ? percent[2] - '0' : 1, frame, p + 1);
    } else {
        const char *slash = strrchr(out, '/'), *dot = strrchr(out, '.');
        size_t stem = dot && (!slash || dot > slash) && dot != (slash ? slash + 1 : out)
                          ? (size_t)(dot - out)
                          : strlen(out);
        n = snprintf(path, size, "%.*s-%04d%s", (int)stem, out, frame, out + stem);
    }
    if (n < 0 || (size_t)n >= size) {
        cli_usage_error("render", "--frames: output name too long: %s", out);
        return -1;
    }
    return 0;
}

/* One picture: rendered (repeat times, the median reported), the overlays
 * drawn, written to out_path. */
static int render_one(const cg_scene *scene, const char *path, const char *out_path, int repeat)
{
    int frames = repeat > 0 ? repeat : 1;
    double *times = malloc(sizeof *times * (size_t)frames);
    cg_image *image = NULL;
    cg_error err;
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
    return status;
}

/* --frames A..B: every frame of the range posed and written. */
static int render_frames(const render_request *r, cg_scene *scene)
{
    const char *path = r->trace.input, *out_path = r->trace.common.output;
    if (!scene->animation)
        return cli_fail("%s: --frames: the scene has no \"animation\" key to pose", path);
    if (r->frame_last >= scene->frame_count)
        return cli_fail("%s: --frames %d..%d: the animation has frames 0 to %d", path,
                        r->frame_first, r->frame_last, scene->frame_count - 1);
    int status = CLI_OK;
    for (int f = r->frame_first; f <= r->frame_last && status == CLI_OK; f++) {
        char frame_out[4096];
        if (frame_path(out_path, f, frame_out, sizeof frame_out) != 0)
            return CLI_USAGE;
        cg_scene_set_frame(scene, f);
        status = render_one(scene, path, frame_out, r->trace.common.repeat);
    }
    return status;
}

int render_scene_file(const char *command, const render_request *r)
{
    const char *path = r->trace.input;
    cg_scene *scene;
    cg_error err;
    if (cg_scene_load(path, &scene, &err) != CG_OK)
        return cli_fail("%s", err.message);
    if (render_scene_apply(command, r, scene) != CLI_OK) {
        cg_scene_free(scene);
        return CLI_USAGE;
    }
    int status = render_request_has(r, OPT_FRAMES)
                     ? render_frames(r, scene)
                     : render_one(scene, path, r->trace.common.output, r->trace.common.repeat);
    cg_scene_free(scene);
    return status;
}
