/* The colour of a surface point, the one place where the renderer calls the
 * illumination model (cg/light.h), and a fast exact sRGB encoder. */
#include "internal.h"
#include "cg/color.h"

void render_shade(const render_lighting *lighting, const float position[3], const float normal[3],
                  const float base[3], float out[3])
{
    cg_vec3 p = {position[0], position[1], position[2]};
    cg_vec3 n = {normal[0], normal[1], normal[2]};
    cg_vec3 view;
    if (lighting->material.ks == 0)
        view = n; /* only the specular term looks at the viewer */
    else if (lighting->orthographic)
        view = cg_vec3_make(lighting->view_dir[0], lighting->view_dir[1], lighting->view_dir[2]);
    else
        view = cg_vec3_normalize(cg_vec3_make(lighting->eye[0] - p.x, lighting->eye[1] - p.y,
                                              lighting->eye[2] - p.z));
    cg_material material = lighting->material;
    material.color = cg_vec3_make(base[0], base[1], base[2]);
    cg_vec3 c = cg_light_shade(p, n, view, &material, lighting->lights, (size_t)lighting->count);
    out[0] = (float)c.x;
    out[1] = (float)c.y;
    out[2] = (float)c.z;
}


void render_encoder_init(render_encoder *encoder)
{
    for (int i = 0; i <= RENDER_ENCODER_STEPS; i++)
        encoder->code[i] = cg_linear_to_srgb8((float)i / RENDER_ENCODER_STEPS);
    encoder->code[RENDER_ENCODER_STEPS + 1] = 255;
}
