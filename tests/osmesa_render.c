/* cg's z-buffer pipeline against Mesa's software OpenGL (OSMesa): the same
 * meshes, camera and Gouraud colours, rendered by both.  The covered-pixel
 * masks must agree on at least 99.5% of the pixels and the mean colour
 * difference over pixels both cover must stay under 2/255.
 *
 * Vertex colours are lit once, here, with the library's illumination model
 * (cg_light_shade) on the crease-angle corner normals, and handed to OpenGL
 * sRGB-encoded with lighting off; OpenGL interpolates them and cg
 * interpolates its own (in linear light, then encodes). */
#include "cg/color.h"
#include "cg/light.h"
#include "cg/mesh.h"
#include "cg/render.h"
#include "check.h"
#include "gl_camera.h"

#include <GL/osmesa.h>
#include <GL/gl.h>
#include <stdlib.h>
#include <string.h>

#define WIDTH 480
#define HEIGHT 360

static void compare(const char *path, cg_vec3 view_direction)
{
    cg_mesh *mesh;
    cg_error err;
    char full[1024];
    snprintf(full, sizeof full, "%s/data/meshes/%s", CG_SOURCE_DIR, path);
    if (cg_mesh_load(full, &mesh, &err) != CG_OK) {
        CHECK_MSG(0, "%s", err.message);
        return;
    }
    cg_render_options o;
    cg_render_options_default(&o);
    o.background = (cg_rgbaf){0, 0, 0, 1};
    o.color = (cg_rgbaf){0.5f, 0.45f, 0.3f, 1};
    o.shading = CG_SHADING_GOURAUD;
    o.cull = CG_CULL_BACK;
    o.ambient = 0.2;
    o.specular = 0;
    o.light_count = 1;
    o.lights[0].direction = cg_vec3_make(-0.4, 0.7, 0.6);
    o.lights[0].intensity = 0.9;
    o.camera.eye = cg_vec3_scale(view_direction, -1);
    o.camera.target = cg_vec3_make(0, 0, 0);
    cg_renderer *renderer;
    CHECK(cg_renderer_create(mesh, &o, &renderer, NULL) == CG_OK);
    cg_image *ours;
    cg_image_create(&ours, WIDTH, HEIGHT, CG_PIXEL_RGBA8);
    CHECK(cg_renderer_draw(renderer, ours) == CG_OK);
    cg_camera camera = cg_renderer_camera(renderer);
    cg_renderer_free(renderer);

    /* Corner colours by the illumination model. */
    size_t corners = mesh->face_offsets[mesh->face_count];
    cg_vec3 *normals = malloc(sizeof *normals * corners);
    CHECK(cg_mesh_corner_normals(mesh, o.crease_angle, normals) == CG_OK);
    cg_material material = cg_material_make(cg_vec3_make(o.color.r, o.color.g, o.color.b),
                                            o.ambient, 1, 0, 1);
    cg_light lights[2] = {cg_light_ambient(cg_vec3_make(1, 1, 1)),
                          cg_light_directional(cg_vec3_scale(o.lights[0].direction, -1),
                                               cg_vec3_make(0.9, 0.9, 0.9))};
    /* OpenGL: same camera matrices, smooth shading, back faces culled,
     * counter-clockwise front faces, depth test LESS. */
    OSMesaContext context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, NULL);
    CHECK(context != NULL);
    unsigned char *buffer = calloc((size_t)WIDTH * HEIGHT, 4);
    CHECK(OSMesaMakeCurrent(context, buffer, GL_UNSIGNED_BYTE, WIDTH, HEIGHT));
    GLdouble view[16];
    CHECK(gl_load_camera(&camera, WIDTH, HEIGHT, 0, view) == 0);
    glClearColor(0, 0, 0, 1);
    glClearDepth(1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glEnable(GL_CULL_FACE);
    glFrontFace(GL_CCW);
    glCullFace(GL_BACK);
    glShadeModel(GL_SMOOTH);
    glDisable(GL_LIGHTING);
    glBegin(GL_TRIANGLES);
    for (size_t f = 0; f < mesh->face_count; f++) {
        uint32_t begin = mesh->face_offsets[f], end = mesh->face_offsets[f + 1];
        for (uint32_t k = begin + 1; k + 1 < end; k++) {
            uint32_t corner[3] = {begin, k, k + 1};
            for (int c = 0; c < 3; c++) {
                uint32_t i = corner[c];
                cg_vec3 p = mesh->positions[mesh->face_indices[i]];
                cg_vec3 v = cg_vec3_normalize(cg_vec3_sub(camera.eye, p));
                cg_vec3 shade = cg_light_shade(p, normals[i], v, &material, lights, 2);
                cg_rgba8 e = cg_linear_to_rgba8(
                    (cg_rgbaf){(float)shade.x, (float)shade.y, (float)shade.z, 1});
                glColor3ub(e.r, e.g, e.b);
                glVertex3d(p.x, p.y, p.z);
            }
        }
    }
    glEnd();
    glFinish();

    long mask_agree = 0, both = 0;
    double difference = 0;
    for (int y = 0; y < HEIGHT; y++)
        for (int x = 0; x < WIDTH; x++) {
            const unsigned char *g = buffer + ((size_t)(HEIGHT - 1 - y) * WIDTH + x) * 4;
            cg_rgba8 c = cg_image_get_rgba8(ours, x, y);
            int gl_covered = g[0] | g[1] | g[2], cg_covered = c.r | c.g | c.b;
            mask_agree += !gl_covered == !cg_covered;
            if (gl_covered && cg_covered) {
                both++;
                difference += (abs(g[0] - c.r) + abs(g[1] - c.g) + abs(g[2] - c.b)) / 3.0;
            }
        }
    double agree = (double)mask_agree / (WIDTH * HEIGHT), mean = both ? difference / both : 255;
    printf("%s: masks agree on %.3f%% of pixels, mean colour difference %.3f/255 over %ld pixels\n",
           path, agree * 100, mean, both);
    CHECK_MSG(agree >= 0.995, "%s: masks agree on only %.3f%%", path, agree * 100);
    CHECK_MSG(mean < 2, "%s: mean colour difference %.3f/255", path, mean);
    CHECK_MSG(both > WIDTH * HEIGHT / 10, "%s: the mesh covers too little (%ld pixels)", path,
              both);
    OSMesaDestroyContext(context);
    free(buffer);
    free(normals);
    cg_image_free(ours);
    cg_mesh_free(mesh);
}

int main(void)
{
    compare("bunny.obj", cg_vec3_make(0, 0, -1));
    compare("bunny.obj", cg_vec3_make(0.6, -0.4, -0.7));
    compare("teapot.obj", cg_vec3_make(-0.3, -0.5, -0.8));
    compare("dragon_vrip_res4.ply.gz", cg_vec3_make(0.2, -0.1, -1));
    return check_finish();
}
