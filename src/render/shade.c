/* The colour of a point, the one place where the renderer evaluates the
 * illumination model of cg/light.h.
 *
 * cg_light_shade evaluates the model for any light in double precision; the
 * renderer lights every vertex of every frame (Gouraud) or every pixel
 * (Phong) with an ambient light and directional lights only, so it evaluates
 * the same terms in float with the lights' constants gathered once per
 * frame.  The difference is a few float roundings (relative 1e-6), far
 * below one code of an 8-bit channel; tests/test_render.c compares the two. */
#include "internal.h"
#include "cg/color.h"

#include <string.h>

void render_lighting_prepare(render_lighting *l)
{
    const cg_material *m = &l->material;
    float ambient[3] = {0, 0, 0};
    l->directional = 0;
    for (int i = 0; i < l->count; i++) {
        const cg_light *light = &l->lights[i];
        if (light->kind == CG_LIGHT_AMBIENT) {
            ambient[0] += (float)light->color.x;
            ambient[1] += (float)light->color.y;
            ambient[2] += (float)light->color.z;
            continue;
        }
        /* Only directional lights besides the ambient one reach here. */
        int k = l->directional++;
        l->to_light[k][0] = (float)-light->direction.x;
        l->to_light[k][1] = (float)-light->direction.y;
        l->to_light[k][2] = (float)-light->direction.z;
        l->light_color[k][0] = (float)light->color.x;
        l->light_color[k][1] = (float)light->color.y;
        l->light_color[k][2] = (float)light->color.z;
    }
    for (int j = 0; j < 3; j++)
        l->ambient[j] = (float)m->ka * ambient[j];
    l->kd = (float)m->kd;
    l->ks = (float)m->ks;
    l->shininess = (float)m->shininess;
    l->specular_color[0] = (float)(m->ks * m->specular_color.x);
    l->specular_color[1] = (float)(m->ks * m->specular_color.y);
    l->specular_color[2] = (float)(m->ks * m->specular_color.z);
    l->blinn = m->specular == CG_SPECULAR_BLINN;
}

void render_shade_terms(const render_lighting *l, const float position[3], const float n[3],
                        const float base[3], float ambient[3], float diffuse_term[3],
                        float specular_term[3])
{
    float view[3] = {n[0], n[1], n[2]}; /* only the specular term looks at it */
    if (l->ks != 0) {
        if (l->orthographic) {
            memcpy(view, l->view_dir, sizeof view);
        } else {
            float d[3] = {l->eye[0] - position[0], l->eye[1] - position[1],
                          l->eye[2] - position[2]};
            float length = sqrtf(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            float inverse = length > 0 ? 1 / length : 0;
            for (int j = 0; j < 3; j++)
                view[j] = d[j] * inverse;
        }
    }
    float diffuse[3] = {0, 0, 0}, specular[3] = {0, 0, 0};
    for (int i = 0; i < l->directional; i++) {
        const float *L = l->to_light[i], *c = l->light_color[i];
        float nl = n[0] * L[0] + n[1] * L[1] + n[2] * L[2];
        if (!(nl > 0))
            continue; /* light behind the surface */
        float lit[3];
        if (l->shadow[i]) {
            float visible = render_shadow_visibility(l->shadow[i], position, nl);
            if (!(visible > 0))
                continue; /* in the shadow */
            for (int j = 0; j < 3; j++)
                lit[j] = c[j] * visible;
            c = lit;
        }
        for (int j = 0; j < 3; j++)
            diffuse[j] += c[j] * nl;
        if (l->ks == 0)
            continue;
        float spec;
        if (l->blinn) {
            float h[3] = {L[0] + view[0], L[1] + view[1], L[2] + view[2]};
            float hl = sqrtf(h[0] * h[0] + h[1] * h[1] + h[2] * h[2]);
            float nh = hl > 0 ? (n[0] * h[0] + n[1] * h[1] + n[2] * h[2]) / hl : 0;
            spec = nh > 0 ? powf(nh, l->shininess) : 0;
        } else {
            float nv = n[0] * view[0] + n[1] * view[1] + n[2] * view[2];
            float lv = L[0] * view[0] + L[1] * view[1] + L[2] * view[2];
            float rv = 2 * nl * nv - lv;
            spec = rv > 0 ? powf(rv > 1 ? 1 : rv, l->shininess) : 0;
        }
        for (int j = 0; j < 3; j++)
            specular[j] += c[j] * spec;
    }
    for (int j = 0; j < 3; j++) {
        ambient[j] = base[j] * l->ambient[j];
        diffuse_term[j] = l->kd * base[j] * diffuse[j];
        specular_term[j] = l->specular_color[j] * specular[j];
    }
}

void render_shade(const render_lighting *l, const float position[3], const float n[3],
                  const float base[3], float out[3])
{
    float ambient[3], diffuse[3], specular[3];
    render_shade_terms(l, position, n, base, ambient, diffuse, specular);
    for (int j = 0; j < 3; j++)
        out[j] = ambient[j] + diffuse[j] + specular[j];
}
