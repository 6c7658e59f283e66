/* The colour of a surface point: the single place where the renderer
 * evaluates illumination (ambient + Lambert diffuse + Blinn-Phong specular
 * for directional lights), and a fast exact sRGB encoder. */
#include "internal.h"
#include "cg/color.h"

void render_shade(const render_lighting *lighting, const float position[3], const float normal[3],
                  const float base[3], float out[3])
{
    float diffuse = lighting->ambient, specular = 0;
    float view[3];
    if (lighting->specular > 0) {
        if (lighting->orthographic) {
            view[0] = lighting->view_dir[0];
            view[1] = lighting->view_dir[1];
            view[2] = lighting->view_dir[2];
        } else {
            view[0] = lighting->eye[0] - position[0];
            view[1] = lighting->eye[1] - position[1];
            view[2] = lighting->eye[2] - position[2];
            float length = sqrtf(view[0] * view[0] + view[1] * view[1] + view[2] * view[2]);
            float inverse = length > 0 ? 1 / length : 0;
            view[0] *= inverse;
            view[1] *= inverse;
            view[2] *= inverse;
        }
    }
    for (int i = 0; i < lighting->count; i++) {
        const float *l = lighting->direction[i];
        float lambert = normal[0] * l[0] + normal[1] * l[1] + normal[2] * l[2];
        if (!(lambert > 0))
            continue;
        diffuse += lighting->intensity[i] * lambert;
        if (lighting->specular > 0) {
            float h[3] = {l[0] + view[0], l[1] + view[1], l[2] + view[2]};
            float length = sqrtf(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
            if (length > 0) {
                float nh = (normal[0] * h[0] + normal[1] * h[1] + normal[2] * h[2]) / length;
                if (nh > 0)
                    specular += lighting->intensity[i] * powf(nh, lighting->shininess);
            }
        }
    }
    specular *= lighting->specular;
    for (int c = 0; c < 3; c++)
        out[c] = base[c] * diffuse + specular;
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
