/* `cg trace` for chapters 6-8 from intensity to pixel: quantization,
 * ordered and Floyd-Steinberg dithering (cg_dither_plane_steps), gamma
 * correction (cg_gamma_steps). */
#include "trace_algorithms.h"

#include "cli.h"
#include "cg/color.h"
#include "cg/render.h"
#include "cg/trace_steps.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_VALUES = 64, MAX_DITHER_SIDE = 64 };

/* Intensities argv[from..argc): finite reals (clamped to [0, 1] by the
 * library); the count, or -1 after a message. */
static int read_values(int argc, char **argv, int from, double *values)
{
    if (argc - from > MAX_VALUES) {
        cli_usage_error("trace", "%s: at most %d values", argv[0], MAX_VALUES);
        return -1;
    }
    for (int i = from; i < argc; i++) {
        if (trace_parse_real("I", argv[i], &values[i - from]))
            return -1;
        if (!isfinite(values[i - from])) {
            cli_usage_error("trace", "%s: '%s' is not a finite intensity", argv[0], argv[i]);
            return -1;
        }
    }
    return argc - from;
}

static int read_levels(const char *name, const char *text, long *levels)
{
    if (trace_parse_int("LEVELS", text, 2, 256, levels))
        return cli_usage_error("trace", "%s: LEVELS is a whole number from 2 to 256", name);
    return CLI_OK;
}

/* The plane as a grey picture behind the frames. */
static void plane_background(trace_run *run, const float *plane, int width, int height)
{
    if (cg_image_create(&run->background, width, height, CG_PIXEL_RGBA8) != CG_OK) {
        run->background = NULL;
        return;
    }
    for (int y = 0; y < height; y++)
        for (int x = 0; x < width; x++) {
            uint8_t v = (uint8_t)lround(255 * plane[y * width + x]);
            cg_image_set_rgba8(run->background, x, y, (cg_rgba8){v, v, v, 255});
        }
}

static int run_plane(trace_run *run, const float *plane, int width, int height, int levels,
                     cg_dither method, const trace_outputs *out)
{
    plane_background(run, plane, width, height);
    cg_status status = cg_dither_plane_steps(plane, width, height, levels, method,
                                             cg_step_log_record, run->log);
    return trace_finish(run, status, "bad plane or levels", out);
}

/* quantize LEVELS I [I ...] */
static int run_quantize(int argc, char **argv, const trace_outputs *out)
{
    long levels;
    double values[MAX_VALUES];
    if (argc < 3)
        return cli_usage_error("trace", "quantize: expected 'quantize LEVELS I [I ...]' "
                                        "(intensities, clamped to [0, 1])");
    if (read_levels("quantize", argv[1], &levels) != CLI_OK)
        return CLI_USAGE;
    int n = read_values(argc, argv, 2, values);
    if (n < 0)
        return CLI_USAGE;
    float plane[MAX_VALUES];
    for (int i = 0; i < n; i++)
        plane[i] = (float)values[i];
    trace_run *run = trace_run_create("quantize", argc - 1, argv + 1,
                                      "%d intensities quantized to %ld levels", n, levels);
    if (!run)
        return cli_fail("trace: out of memory");
    trace_note(run, "the levels are 0, 1/(N-1), ..., 1 (N = %ld); I is clamped to [0, 1]", levels);
    trace_note(run, "s = I (N - 1), k = floor(s + 1/2) (ties up), out = k / (N - 1), error = I "
                    "- out");
    return run_plane(run, plane, n, 1, (int)levels, CG_DITHER_NONE, out);
}

/* The input of dither: ramp:WxH (I = (x + 1/2) / W), or an image whose red
 * channel is read as cg_image_dither reads it (code / 255). */
static float *dither_input(const char *text, int *width, int *height)
{
    float *plane;
    if (strncmp(text, "ramp:", 5) == 0) {
        if (cli_parse_size("trace", "ramp", text + 5, width, height))
            return NULL;
    } else {
        cg_image *read, *image;
        cg_error err;
        if (cg_image_read(text, &read, &err) != CG_OK) {
            cli_fail("trace: %s", err.message);
            return NULL;
        }
        cg_status status = cg_image_convert(read, CG_PIXEL_RGBA8, &image);
        cg_image_free(read);
        if (status != CG_OK) {
            cli_fail("trace: %s: %s", text, cg_status_str(status));
            return NULL;
        }
        *width = image->width;
        *height = image->height;
        plane = NULL;
        if (*width <= MAX_DITHER_SIDE && *height <= MAX_DITHER_SIDE) {
            plane = malloc((size_t)*width * (size_t)*height * sizeof *plane);
            if (!plane) {
                cg_image_free(image);
                cli_fail("trace: out of memory");
                return NULL;
            }
        }
        for (int y = 0; plane && y < *height; y++)
            for (int x = 0; x < *width; x++)
                plane[y * *width + x] = cg_image_get_rgba8(image, x, y).r / 255.0f;
        cg_image_free(image);
        if (plane)
            return plane;
    }
    if (*width > MAX_DITHER_SIDE || *height > MAX_DITHER_SIDE) {
        cli_usage_error("trace", "dither: at most %dx%d pixels (%dx%d given)", MAX_DITHER_SIDE,
                        MAX_DITHER_SIDE, *width, *height);
        return NULL;
    }
    plane = malloc((size_t)*width * (size_t)*height * sizeof *plane);
    if (!plane) {
        cli_fail("trace: out of memory");
        return NULL;
    }
    for (int y = 0; y < *height; y++)
        for (int x = 0; x < *width; x++)
            plane[y * *width + x] = (float)((x + 0.5) / *width);
    return plane;
}

static const struct {
    const char *name;
    cg_dither method;
    int side;
} dither_methods[] = {{"bayer2", CG_DITHER_BAYER2, 2},
                      {"bayer4", CG_DITHER_BAYER4, 4},
                      {"bayer8", CG_DITHER_BAYER8, 8},
                      {"floyd-steinberg", CG_DITHER_FLOYD_STEINBERG, 0}};

/* dither METHOD LEVELS INPUT */
static int run_dither(int argc, char **argv, const trace_outputs *out)
{
    long levels;
    if (argc != 4)
        return cli_usage_error("trace", "dither: expected 'dither bayer2|bayer4|bayer8|"
                                        "floyd-steinberg LEVELS ramp:WxH|IMAGE'");
    int m = -1;
    for (int i = 0; i < 4; i++)
        if (strcmp(argv[1], dither_methods[i].name) == 0)
            m = i;
    if (m < 0)
        return cli_usage_error("trace",
                               "dither: unknown method '%s' (bayer2, bayer4, bayer8 or "
                               "floyd-steinberg)",
                               argv[1]);
    if (read_levels("dither", argv[2], &levels) != CLI_OK)
        return CLI_USAGE;
    int width = 0, height = 0;
    float *plane = dither_input(argv[3], &width, &height);
    if (!plane)
        return strncmp(argv[3], "ramp:", 5) == 0 || width > MAX_DITHER_SIDE
                       || height > MAX_DITHER_SIDE
                   ? CLI_USAGE
                   : CLI_FAILED;
    trace_run *run = trace_run_create("dither", argc - 1, argv + 1,
                                      "%s dithering of %s (%dx%d) to %ld levels", argv[1], argv[3],
                                      width, height, levels);
    if (!run) {
        free(plane);
        return cli_fail("trace: out of memory");
    }
    trace_note(run,
               "levels 0, 1/(N-1), ..., 1 (N = %ld); s = I (N - 1); pixels row by row, "
               "left to right",
               levels);
    if (dither_methods[m].side)
        trace_note(run,
                   "ordered: up one level when frac(s) > threshold = (b + 1/2) / %d, b the "
                   "%dx%d Bayer matrix's entry at (x mod %d, y mod %d)",
                   dither_methods[m].side * dither_methods[m].side, dither_methods[m].side,
                   dither_methods[m].side, dither_methods[m].side, dither_methods[m].side);
    else
        trace_note(run, "Floyd-Steinberg: v = I + the errors received, out = the level nearest "
                        "v, error = v - out pushed 7/16 right, 3/16 below left, 5/16 below, "
                        "1/16 below right (weights of missing neighbours shared by the others)");
    int code = run_plane(run, plane, width, height, (int)levels, dither_methods[m].method, out);
    free(plane);
    return code;
}

/* gamma GAMMA I [I ...] */
static int run_gamma(int argc, char **argv, const trace_outputs *out)
{
    double gamma, values[MAX_VALUES];
    if (argc < 3)
        return cli_usage_error("trace", "gamma: expected 'gamma GAMMA I [I ...]' (intensities "
                                        "in [0, 1])");
    if (trace_parse_real("GAMMA", argv[1], &gamma))
        return CLI_USAGE;
    if (!(gamma > 0) || !isfinite(gamma) || gamma > 100)
        return cli_usage_error("trace", "gamma: GAMMA is a number above 0 (2.2 for a CRT), at "
                                        "most 100");
    int n = read_values(argc, argv, 2, values);
    if (n < 0)
        return CLI_USAGE;
    trace_run *run = trace_run_create("gamma", argc - 1, argv + 1,
                                      "Gamma correction of %d intensities for gamma %g", n, gamma);
    if (!run)
        return cli_fail("trace: out of memory");
    trace_note(run, "a CRT shows voltage V as intensity V^gamma; to show I, send the corrected "
                    "V = I^(1/gamma) (section 7.2.1)");
    trace_note(run, "code = round(255 V); shown = V^gamma (I again); uncorrected = I^gamma, what "
                    "sending I itself shows; sRGB: the standard's curve for comparison");
    cg_status status = cg_gamma_steps(values, (size_t)n, gamma, cg_step_log_record, run->log);
    return trace_finish(run, status, "bad gamma", out);
}

/* shading flat|gouraud|phong MESH X Y [WxH] */
static int run_shading(int argc, char **argv, const trace_outputs *out)
{
    static const char *const modes[3] = {"flat", "gouraud", "phong"};
    long x, y;
    int width = 160, height = 120, mode = -1;
    if (argc < 5 || argc > 6)
        return cli_usage_error("trace", "shading: expected 'shading flat|gouraud|phong MESH X Y "
                                        "[WxH]'");
    for (int i = 0; i < 3; i++)
        if (strcmp(argv[1], modes[i]) == 0)
            mode = i;
    if (mode < 0)
        return cli_usage_error("trace", "shading: unknown mode '%s' (flat, gouraud or phong)",
                               argv[1]);
    if ((argc > 5 && cli_parse_size("trace", "WxH", argv[5], &width, &height))
        || trace_parse_int("X", argv[3], 0, width - 1, &x)
        || trace_parse_int("Y", argv[4], 0, height - 1, &y))
        return CLI_USAGE;
    cg_mesh *mesh;
    cg_render_options o;
    cg_render_options_default(&o);
    if (trace_frame_mesh(argv[2], 30, 20, (double)width / height, &mesh, &o.model, &o.camera)
        != CLI_OK)
        return CLI_FAILED;
    o.frame_camera = 0;
    o.shading = (cg_shading)mode;
    cg_renderer *renderer;
    cg_error err = {0};
    cg_image *image = NULL;
    cg_status status = cg_renderer_create(mesh, &o, &renderer, &err);
    cg_mesh_free(mesh);
    if (status != CG_OK)
        return cli_fail("trace: %s: %s", argv[2], err.message[0] ? err.message : "cannot render");
    trace_run *run = trace_run_create("shading", argc - 1, argv + 1,
                                      "%s shading at pixel (%ld, %ld) of a %dx%d frame of %s",
                                      mode == 0   ? "Flat"
                                      : mode == 1 ? "Gouraud"
                                                  : "Phong",
                                      x, y, width, height, argv[2]);
    if (run)
        status = cg_image_create(&image, width, height, CG_PIXEL_RGBAF);
    if (!run || status != CG_OK) {
        trace_run_free(run);
        cg_renderer_free(renderer);
        return cli_fail("trace: out of memory");
    }
    trace_note(run, "the mesh turned 30 degrees about y and 20 about x, framed, back faces culled, "
                    "lit by cg render's key light (ambient 0.15, Blinn-Phong specular 0.25, "
                    "exponent 32)");
    trace_note(run,
               "each triangle covering the centre (%ld.5, %ld.5): its screen barycentric "
               "coordinates l, the perspective-correct weights b_k = l_k (1/w_k) / sum, the "
               "depth test",
               x, y);
    trace_note(run, "flat: one colour per face; Gouraud: the vertex colours (lit at the vertices) "
                    "interpolated by b; Phong: the normals interpolated by b and renormalized, "
                    "then ambient + diffuse + specular at the pixel");
    trace_note(run, "colours are linear RGB; the last written fragment's colour is the pixel's "
                    "(to float rounding)");
    status = cg_shading_pixel_steps(renderer, image, (int)x, (int)y, cg_step_log_record, run->log);
    cg_renderer_free(renderer);
    cg_image_free(image);
    return trace_finish(run, status, "the mesh cannot be drawn", out);
}

const trace_algorithm trace_shading_algorithms[] = {
    {"shading", "flat|gouraud|phong MESH X Y [WxH]", run_shading},
    {"quantize", "LEVELS I [I ...]", run_quantize},
    {"dither", "METHOD LEVELS ramp:WxH|IMAGE", run_dither},
    {"gamma", "GAMMA I [I ...]", run_gamma},
    {NULL, NULL, NULL},
};
