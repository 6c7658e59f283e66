/* Gallery: intensity to pixel (6.1.5) - a gradient quantized and dithered
 * to 2, 4 and 8 levels, and halftone cells. */
#include "demo.h"
#include "cg/color.h"

#include <stdio.h>
#include <stdlib.h>

static int add(demo_context *context, const char *file, cg_image *image, const char *caption,
               const char *command)
{
    int status = demo_add(context, file, image, caption, command);
    cg_image_free(image);
    return status;
}

static int dither_gradient(demo_context *context, int levels)
{
    enum { W = 512, BAND = 40, GAP = 4 };
    const cg_dither methods[5] = {CG_DITHER_NONE, CG_DITHER_BAYER2, CG_DITHER_BAYER4,
                                  CG_DITHER_BAYER8, CG_DITHER_FLOYD_STEINBERG};
    const int bands = 6;
    float *plane = malloc(sizeof(float) * W * BAND), *out = malloc(sizeof(float) * W * BAND);
    cg_image *image = NULL;
    int status = 1;
    if (!plane || !out
        || cg_image_create(&image, W, bands * BAND + (bands - 1) * GAP, CG_PIXEL_RGBA8) != CG_OK)
        goto done;
    cg_image_clear_rgba8(image, (cg_rgba8){255, 255, 255, 255});
    for (int y = 0; y < BAND; y++)
        for (int x = 0; x < W; x++)
            plane[y * W + x] = (x + 0.5f) / W;
    for (int b = 0; b < bands; b++) {
        if (b == 0) {
            for (int i = 0; i < W * BAND; i++)
                out[i] = plane[i];
        } else if (cg_dither_plane(plane, out, W, BAND, W, levels, methods[b - 1]) != CG_OK) {
            goto done;
        }
        for (int y = 0; y < BAND; y++)
            for (int x = 0; x < W; x++) {
                uint8_t g = (uint8_t)(out[y * W + x] * 255 + 0.5f);
                cg_image_set_rgba8(image, x, b * (BAND + GAP) + y, (cg_rgba8){g, g, g, 255});
            }
    }
    char file[64], caption[256];
    snprintf(file, sizeof file, "dither-%d-levels.png", levels);
    snprintf(caption, sizeof caption,
             "A gradient at %d levels: the original, then nearest level, Bayer 2x2, 4x4, 8x8 "
             "ordered dithering and Floyd-Steinberg error diffusion (top to bottom)",
             levels);
    status = demo_add(context, file, image, caption, "cg demo --only 'Intensity to pixel'");
done:
    free(plane);
    free(out);
    cg_image_free(image);
    return status;
}

static int halftone(demo_context *context)
{
    enum { W = 56, H = 10, CELL = 3, SCALE = 3 };
    float plane[W * H];
    uint8_t cells[W * CELL * H * CELL];
    for (int y = 0; y < H; y++)
        for (int x = 0; x < W; x++)
            plane[y * W + x] = (float)x / (W - 1);
    if (cg_halftone_plane(plane, W, H, W, CELL, cells) != CG_OK)
        return 1;
    cg_image *image;
    if (cg_image_create(&image, W * CELL * SCALE, H * CELL * SCALE, CG_PIXEL_RGBA8) != CG_OK)
        return 1;
    for (int y = 0; y < H * CELL * SCALE; y++)
        for (int x = 0; x < W * CELL * SCALE; x++) {
            uint8_t g = cells[(y / SCALE) * W * CELL + x / SCALE];
            cg_image_set_rgba8(image, x, y, (cg_rgba8){g, g, g, 255});
        }
    return add(
        context, "halftone-3x3.png", image,
        "Halftoning with 3x3 cells (10 intensity levels from two) on a ramp, each pixel drawn 3x3",
        "cg demo --only 'Intensity to pixel'");
}

static int render_intensity(demo_context *context)
{
    int failed = 0;
    failed |= dither_gradient(context, 2);
    failed |= dither_gradient(context, 4);
    failed |= dither_gradient(context, 8);
    failed |= halftone(context);
    return failed;
}

const demo_section demo_section_dither = {
    6, "Intensity to pixel: quantization, dithering, halftones", render_intensity};
