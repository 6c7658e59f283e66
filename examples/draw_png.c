/* Draws a few lines into an image and saves it as PNG. */
#include <cg.h>
#include <stdio.h>

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "lines.png";
    cg_image *image;
    if (cg_image_create(&image, 200, 200, CG_PIXEL_RGBA8) != CG_OK)
        return 1;
    cg_rgba8 white = {255, 255, 255, 255}, blue = {20, 60, 200, 255};
    cg_image_clear_rgba8(image, white);
    for (int i = 0; i <= 10; i++)
        cg_draw_line(image, 10, 10, 190, 10 + 18 * i, blue);
    cg_error err;
    cg_status status = cg_image_write(image, path, CG_FILE_UNKNOWN, &err);
    cg_image_free(image);
    if (status != CG_OK) {
        fprintf(stderr, "%s\n", err.message);
        return 1;
    }
    return 0;
}
