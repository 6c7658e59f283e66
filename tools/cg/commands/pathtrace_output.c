/* The path tracer's outputs: PFM, part files, and tone-mapped 8-bit images. */
#include "pathtrace_output.h"

#include "cli.h"
#include "cg/color.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int pathtrace_is_part(const char *path)
{
    size_t n = strlen(path);
    return n >= 5 && strcmp(path + n - 5, ".part") == 0;
}

static int has_extension(const char *path, const char *ext)
{
    size_t n = strlen(path), e = strlen(ext);
    if (n < e)
        return 0;
    for (size_t i = 0; i < e; i++) {
        char c = path[n - e + i];
        if ((c >= 'A' && c <= 'Z' ? c + 32 : c) != ext[i])
            return 0;
    }
    return 1;
}

/* The filmic curve of Narkowicz's ACES fit, x >= 0 to [0, 1]: the
 * pathtrace output's tone map (replaceable by a library one). */
static double pathtrace_tonemap_aces(double x)
{
    double v = (x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14);
    return v < 0 ? 0 : (v > 1 ? 1 : v);
}

/* PFM ("PF", width height, -1 for little-endian, rows bottom to top). */
static int write_pfm(const char *command, const cg_image *im, const char *path)
{
    size_t len = strlen(path);
    char *tmp = malloc(len + 8);
    if (!tmp)
        return cli_fail("%s: out of memory", command);
    memcpy(tmp, path, len);
    memcpy(tmp + len, ".tmpXXX", 8);
    FILE *f = fopen(tmp, "wb");
    int ok = f != NULL;
    if (ok)
        ok = fprintf(f, "PF\n%d %d\n-1.0\n", im->width, im->height) > 0;
    for (int y = im->height - 1; ok && y >= 0; y--)
        for (int x = 0; ok && x < im->width; x++) {
            cg_rgbaf c = cg_image_get(im, x, y);
            float v[3] = {c.r, c.g, c.b};
            unsigned char b[12];
            for (int k = 0; k < 3; k++) {
                uint32_t u;
                memcpy(&u, &v[k], 4);
                for (int i = 0; i < 4; i++)
                    b[4 * k + i] = (unsigned char)(u >> (8 * i));
            }
            ok = fwrite(b, 1, 12, f) == 12;
        }
    if (f)
        ok = fclose(f) == 0 && ok;
    if (!ok || rename(tmp, path) != 0) {
        remove(tmp);
        free(tmp);
        return cli_fail("%s: cannot write '%s'", command, path);
    }
    free(tmp);
    return CLI_OK;
}

int pathtrace_write(const char *command, const cg_path_part *whole, const char *path,
                    double exposure)
{
    cg_error err;
    if (pathtrace_is_part(path)) {
        if (cg_path_part_save(whole, path, &err) != CG_OK)
            return cli_fail("%s: %s", command, err.message);
        return CLI_OK;
    }
    int w = (int)whole->width, h = (int)whole->height;
    cg_image *im = NULL;
    if (cg_image_create(&im, w, h, CG_PIXEL_RGBAF) != CG_OK)
        return cli_fail("%s: out of memory", command);
    cg_path_resolve(whole->sums, w, h, whole->sample_end, im, 0, 0);
    int status;
    if (has_extension(path, ".pfm")) {
        status = write_pfm(command, im, path);
    } else {
        cg_image *out = NULL;
        if (cg_image_create(&out, w, h, CG_PIXEL_RGBA8) != CG_OK) {
            cg_image_free(im);
            return cli_fail("%s: out of memory", command);
        }
        double scale = pow(2.0, exposure);
        for (int y = 0; y < h; y++)
            for (int x = 0; x < w; x++) {
                cg_rgbaf c = cg_image_get(im, x, y);
                cg_rgba8 p = {cg_linear_to_srgb8((float)pathtrace_tonemap_aces(c.r * scale)),
                              cg_linear_to_srgb8((float)pathtrace_tonemap_aces(c.g * scale)),
                              cg_linear_to_srgb8((float)pathtrace_tonemap_aces(c.b * scale)), 255};
                cg_image_set_rgba8(out, x, y, p);
            }
        status = cli_write_image(out, path);
        cg_image_free(out);
    }
    cg_image_free(im);
    return status;
}
