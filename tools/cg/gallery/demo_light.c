/* Gallery: the illumination model of chapter 6 on a sphere: each term alone,
 * all together (Phong and Blinn-Phong), and one, two and three coloured
 * lights.  The sphere is found per pixel by ray-sphere intersection (an
 * orthographic view along -z); every pixel is shaded by cg_light_shade. */
#include "demo.h"
#include "cg/color.h"
#include "cg/light.h"

#define SIZE 240

enum { TERM_AMBIENT = 1, TERM_DIFFUSE = 2, TERM_SPECULAR = 4, TERM_ALL = 7 };

static int sphere(demo_context *context, const char *file, const char *caption,
                  const cg_material *material, const cg_light *lights, size_t count, int terms)
{
    cg_image *image;
    if (cg_image_create(&image, SIZE, SIZE, CG_PIXEL_RGBAF) != CG_OK)
        return 1;
    cg_vec3 view = cg_vec3_make(0, 0, 1); /* toward the viewer */
    for (int y = 0; y < SIZE; y++) {
        cg_rgbaf *row = cg_image_row_rgbaf(image, y);
        for (int x = 0; x < SIZE; x++) {
            /* Ray from (px, py, +inf) along -z against the unit sphere at the
             * origin: hit at z = sqrt(1 - px^2 - py^2). */
            double px = ((x + 0.5) / SIZE * 2 - 1) * 1.1, py = (1 - (y + 0.5) / SIZE * 2) * 1.1;
            double d2 = px * px + py * py;
            cg_rgbaf background = {0.02f, 0.02f, 0.025f, 1};
            if (d2 >= 1) {
                row[x] = background;
                continue;
            }
            cg_vec3 p = cg_vec3_make(px, py, sqrt(1 - d2));
            cg_shade_terms t = cg_light_shade_terms(p, p, view, material, lights, count, NULL);
            cg_vec3 c = cg_vec3_make(0, 0, 0);
            if (terms & TERM_AMBIENT)
                c = cg_vec3_add(c, t.ambient);
            if (terms & TERM_DIFFUSE)
                c = cg_vec3_add(c, t.diffuse);
            if (terms & TERM_SPECULAR)
                c = cg_vec3_add(c, t.specular);
            cg_rgbaf out = {(float)c.x, (float)c.y, (float)c.z, 1};
            row[x] = out;
        }
    }
    cg_image *encoded;
    int status = 1;
    if (cg_image_tonemap(image, 0, 0, &encoded) == CG_OK) {
        status = demo_add(context, file, encoded, caption, "cg demo --only 'Illumination'");
        cg_image_free(encoded);
    }
    cg_image_free(image);
    return status;
}

static int render(demo_context *context)
{
    cg_material m = cg_material_make(cg_vec3_make(0.8, 0.22, 0.1), 0.2, 0.75, 0.6, 40);
    cg_light key[2] = {cg_light_ambient(cg_vec3_make(0.2, 0.2, 0.2)),
                       cg_light_point(cg_vec3_make(-3, 3, 4), cg_vec3_make(1, 1, 1))};
    int failed = 0;
    failed |= sphere(context, "light-ambient.png",
                     "Ambient term alone: ka Od Ia, the same everywhere (a flat disc)", &m, key, 2,
                     TERM_AMBIENT);
    failed |= sphere(context, "light-diffuse.png",
                     "Lambert diffuse term alone: kd Od Il max(N.L, 0), from a point light at "
                     "upper left",
                     &m, key, 2, TERM_DIFFUSE);
    failed |= sphere(context, "light-specular.png",
                     "Phong specular term alone: ks Os Il max(R.V, 0)^n, n = 40", &m, key, 2,
                     TERM_SPECULAR);
    failed |= sphere(context, "light-phong.png",
                     "Ambient + diffuse + Phong specular, summed in linear light", &m, key, 2,
                     TERM_ALL);
    cg_material blinn = m;
    blinn.specular = CG_SPECULAR_BLINN;
    blinn.shininess = 160; /* about 4x the Phong exponent for a similar highlight */
    failed |= sphere(context, "light-blinn.png",
                     "The same with Blinn-Phong specular max(N.H, 0)^n, n = 160", &blinn, key, 2,
                     TERM_ALL);
    cg_material low = m;
    low.shininess = 5;
    failed |= sphere(context, "light-shininess-5.png",
                     "Phong with a low shininess n = 5: a broad, dull highlight", &low, key, 2,
                     TERM_ALL);

    /* Coloured lights on a white sphere. */
    cg_material white = cg_material_make(cg_vec3_make(0.85, 0.85, 0.85), 0.2, 0.8, 0.5, 60);
    cg_light colored[4] = {
        cg_light_ambient(cg_vec3_make(0.08, 0.08, 0.08)),
        cg_light_point(cg_vec3_make(-5, 2.5, 2), cg_vec3_make(1.0, 0.12, 0.08)),
        cg_light_point(cg_vec3_make(5, 2.5, 2), cg_vec3_make(0.1, 0.9, 0.15)),
        cg_light_point(cg_vec3_make(0, -5, 2), cg_vec3_make(0.12, 0.25, 1.0)),
    };
    failed |= sphere(context, "light-one-colored.png", "One red point light on a white sphere",
                     &white, colored, 2, TERM_ALL);
    failed |= sphere(context, "light-two-colored.png",
                     "Red and green point lights: where both reach, they add to yellow", &white,
                     colored, 3, TERM_ALL);
    failed |= sphere(context, "light-three-colored.png",
                     "Red, green and blue point lights: the sum over lights in linear light",
                     &white, colored, 4, TERM_ALL);

    /* A spot light and attenuation. */
    cg_light spot[2] = {
        cg_light_ambient(cg_vec3_make(0.1, 0.1, 0.1)),
        cg_light_spot(cg_vec3_make(-0.6, 0.6, 3), cg_vec3_make(0.3, -0.2, -1), cg_radians(12), 20,
                      cg_vec3_make(2.4, 2.2, 1.8)),
    };
    cg_light_set_attenuation(&spot[1], 1, 0.1, 0.05);
    failed |= sphere(
        context, "light-spot.png",
        "A spot light (Warn model: cutoff 12 deg, exponent 20) with distance attenuation", &white,
        spot, 2, TERM_ALL);
    return failed;
}

const demo_section demo_section_light = {6, "Illumination models", render};
