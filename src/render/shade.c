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
    if (lighting->orthographic)
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

#define ENCODER_STEPS 4096

void render_encoder_init(render_encoder *encoder)
{
    for (int i = 0; i <= ENCODER_STEPS; i++)
        encoder->code[i] = cg_linear_to_srgb8((float)i / ENCODER_STEPS);
}

uint8_t render_encode(const render_encoder *encoder, float linear)
{
    if (!(linear > 0))
        return 0;
    if (linear >= 1)
        return 255;
    int i = (int)(linear * ENCODER_STEPS);
    uint8_t code = encoder->code[i];
    /* The code is monotonic: when both ends of the step agree it is exact. */
    if (code == encoder->code[i + 1])
        return code;
    return cg_linear_to_srgb8(linear);
}
