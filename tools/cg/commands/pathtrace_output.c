/* The path tracer's outputs: part files, float images (PFM, HDR, EXR) and
 * tone-mapped 8-bit images. */
#include "pathtrace_output.h"

#include "cli.h"
#include "cg/image_float.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int pathtrace_is_part(const char *path)
{
    size_t n = strlen(path);
    return n >= 5 && strcmp(path + n - 5, ".part") == 0;
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
    /* Float formats (PFM, HDR, EXR) keep the linear values; the others are
     * tone-mapped (exposure, then the filmic curve) and encoded to sRGB. */
    int status;
    if (cg_file_format_is_float(cg_file_format_from_path(path))) {
        status = cli_write_image(im, path);
    } else {
        cg_image *out = NULL;
        if (cg_image_tonemap_curve(im, exposure, CG_TONEMAP_FILMIC, &out) != CG_OK) {
            cg_image_free(im);
            return cli_fail("%s: out of memory", command);
        }
        status = cli_write_image(out, path);
        cg_image_free(out);
    }
    cg_image_free(im);
    return status;
}
