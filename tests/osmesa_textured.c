/* cg's textured rasterizer against Mesa's software OpenGL (OSMesa): a
 * textured rectangle tilted away from a perspective camera, the same sRGB
 * texture (GL_SRGB8_ALPHA8: decoded to linear light before filtering, as cg
 * does), nearest, bilinear and trilinear (OpenGL's glGenerateMipmap
 * levels), repeat and clamp, drawn unlit (GL_REPLACE)
 * into a float framebuffer and encoded to sRGB here.  The covered-pixel
 * masks must agree on at least 99.5% of the pixels and the mean colour
 * difference over pixels both cover must stay under 2/255. */
#include "cg/color.h"
#include "cg/image.h"
#include "cg/mesh.h"
#include "cg/render.h"
#include "check.h"
#include "gl_camera.h"

#include <GL/osmesa.h>
#include <GL/gl.h>
#include <GL/glext.h>
#include <stdlib.h>
#include <string.h>

#define WIDTH 320
#define HEIGHT 240
#define TEX 64

static unsigned char texels[TEX * TEX * 4]; /* row 0 at the top */

static void compare(cg_texture_filter filter, cg_texture_wrap wrap)
{
    /* The rectangle (-1, -0.5, 0) + s (2, 0, 0) + t (0, 0, -6), texture
     * coordinates (2 s, 3 t) - (0.25, 0.5). */
    cg_vec3 positions[4] = {{-1, -0.5, 0}, {1, -0.5, 0}, {1, -0.5, -6}, {-1, -0.5, -6}};
    cg_vec2 uvs[4] = {{-0.25, -0.5}, {1.75, -0.5}, {1.75, 2.5}, {-0.25, 2.5}};
    uint32_t offsets[2] = {0, 4}, indices[4] = {0, 1, 2, 3}, face_material[1] = {0};
    char path[] = "osmesa_textured.png";
    cg_mesh_material material = cg_mesh_material_default();
    material.base_color_map.image_path = path;
    material.base_color_map.wrap_u = material.base_color_map.wrap_v = wrap;
    cg_mesh mesh = {0};
    mesh.vertex_count = 4;
    mesh.positions = positions;
    mesh.texcoords = uvs;
    mesh.face_count = 1;
    mesh.face_offsets = offsets;
    mesh.face_indices = indices;
    mesh.material_count = 1;
    mesh.materials = &material;
    mesh.face_materials = face_material;
    cg_render_options o;
    cg_render_options_default(&o);
    o.camera = cg_camera_default();
    o.camera.eye = cg_vec3_make(0, 0.4, 1.2);
    o.camera.target = cg_vec3_make(0, -0.3, -2);
    o.camera.near = 0.05;
    o.camera.far = 20;
    o.frame_camera = 0;
    o.cull = CG_CULL_NONE;
    o.shading = CG_SHADING_UNLIT;
    o.texture_filter = filter;
    o.background = (cg_rgbaf){0, 0, 0, 1};
    cg_image *ours;
    cg_error err;
    CHECK(cg_image_create(&ours, WIDTH, HEIGHT, CG_PIXEL_RGBA8) == CG_OK);
    CHECK_MSG(cg_render(&mesh, &o, ours, &err) == CG_OK, "%s", err.message);

    OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    CHECK(context != NULL);
    float *buffer = calloc((size_t)WIDTH * HEIGHT, 4 * sizeof(float));
    CHECK(OSMesaMakeCurrent(context, buffer, GL_FLOAT, WIDTH, HEIGHT));
    GLdouble view[16];
    CHECK(gl_load_camera(&o.camera, WIDTH, HEIGHT, 0, view) == 0);
    /* OpenGL's texture rows start at t = 0, cg's image at v = 1. */
    static unsigned char flipped[TEX * TEX * 4];
    for (int y = 0; y < TEX; y++)
        memcpy(flipped + (size_t)y * TEX * 4, texels + (size_t)(TEX - 1 - y) * TEX * 4, TEX * 4);
    GLuint name;
    glGenTextures(1, &name);
    glBindTexture(GL_TEXTURE_2D, name);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, TEX, TEX, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 flipped);
    GLint gl_filter = filter == CG_TEXTURE_NEAREST ? GL_NEAREST : GL_LINEAR;
    GLint gl_min = filter == CG_TEXTURE_TRILINEAR ? GL_LINEAR_MIPMAP_LINEAR : gl_filter;
    if (filter == CG_TEXTURE_TRILINEAR) {
        /* Mesa builds the levels of an sRGB texture in linear light. */
        PFNGLGENERATEMIPMAPPROC generate = (PFNGLGENERATEMIPMAPPROC)OSMesaGetProcAddress(
            "glGenerateMipmap");
        CHECK(generate != NULL);
        if (generate)
            generate(GL_TEXTURE_2D);
    }
    GLint gl_wrap = wrap == CG_TEXTURE_CLAMP ? GL_CLAMP_TO_EDGE : GL_REPEAT;
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, gl_min);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, gl_filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, gl_wrap);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, gl_wrap);
    glTexEnvi(GL_TEXTURE_ENV, GL_TEXTURE_ENV_MODE, GL_REPLACE);
    glHint(GL_PERSPECTIVE_CORRECTION_HINT, GL_NICEST);
    glEnable(GL_TEXTURE_2D);
    glClearColor(0, 0, 0, 0);
    glClearDepth(1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glBegin(GL_QUADS);
    for (int k = 0; k < 4; k++) {
        glTexCoord2d(uvs[k].x, uvs[k].y);
        glVertex3d(positions[k].x, positions[k].y, positions[k].z);
    }
    glEnd();
    glFinish();
    CHECK(glGetError() == GL_NO_ERROR);

    long mask_agree = 0, both = 0;
    double difference = 0;
    for (int y = 0; y < HEIGHT; y++)
        for (int x = 0; x < WIDTH; x++) {
            const float *g = buffer + ((size_t)(HEIGHT - 1 - y) * WIDTH + x) * 4;
            cg_rgba8 c = cg_image_get_rgba8(ours, x, y);
            int gl_covered = g[3] > 0.5f, cg_covered = (c.r | c.g | c.b) != 0;
            mask_agree += gl_covered == cg_covered;
            if (gl_covered && cg_covered) {
                both++;
                difference += (abs(cg_linear_to_srgb8(g[0]) - c.r)
                               + abs(cg_linear_to_srgb8(g[1]) - c.g)
                               + abs(cg_linear_to_srgb8(g[2]) - c.b))
                              / 3.0;
            }
        }
    double agree = (double)mask_agree / (WIDTH * HEIGHT), mean = both ? difference / both : 255;
    printf("filter %d wrap %d: masks agree on %.3f%% of pixels, mean colour difference %.3f/255 "
           "over %ld pixels\n",
           (int)filter, (int)wrap, agree * 100, mean, both);
    CHECK_MSG(agree >= 0.995, "masks agree on only %.3f%%", agree * 100);
    CHECK_MSG(mean < 2, "mean colour difference %.3f/255", mean);
    CHECK_MSG(both > WIDTH * HEIGHT / 4, "the rectangle covers too little (%ld pixels)", both);
    glDeleteTextures(1, &name);
    OSMesaDestroyContext(context);
    free(buffer);
    cg_image_free(ours);
}

int main(void)
{
    /* A smooth random texture (a few random blobs), codes 16 to 255, so
     * that every covered pixel is told from the black background. */
    check_rng rng = {23};
    double centres[6][5];
    for (int i = 0; i < 6; i++)
        for (int k = 0; k < 5; k++)
            centres[i][k] = check_rng_unit(&rng);
    cg_image *image;
    CHECK(cg_image_create(&image, TEX, TEX, CG_PIXEL_RGBA8) == CG_OK);
    for (int y = 0; y < TEX; y++)
        for (int x = 0; x < TEX; x++) {
            double c[3] = {0.1, 0.1, 0.1};
            for (int i = 0; i < 6; i++) {
                double dx = (x + 0.5) / TEX - centres[i][0], dy = (y + 0.5) / TEX - centres[i][1];
                double w = exp(-(dx * dx + dy * dy) * 40);
                for (int k = 0; k < 3; k++)
                    c[k] += w * centres[i][2 + k];
            }
            unsigned char *t = texels + ((size_t)y * TEX + x) * 4;
            for (int k = 0; k < 3; k++)
                t[k] = (unsigned char)(16 + 239 * (c[k] > 1 ? 1 : c[k]));
            t[3] = 255;
            cg_image_set_rgba8(image, x, y, (cg_rgba8){t[0], t[1], t[2], 255});
        }
    cg_error err;
    CHECK_MSG(cg_image_write(image, "osmesa_textured.png", CG_FILE_UNKNOWN, &err) == CG_OK, "%s",
              err.message);
    cg_image_free(image);
    compare(CG_TEXTURE_NEAREST, CG_TEXTURE_REPEAT);
    compare(CG_TEXTURE_BILINEAR, CG_TEXTURE_REPEAT);
    compare(CG_TEXTURE_BILINEAR, CG_TEXTURE_CLAMP);
    compare(CG_TEXTURE_TRILINEAR, CG_TEXTURE_REPEAT);
    compare(CG_TEXTURE_TRILINEAR, CG_TEXTURE_CLAMP);
    return check_finish();
}
