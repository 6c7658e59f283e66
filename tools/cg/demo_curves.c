/* Gallery: parametric cubic curves and Bézier curves (section 2.3). */
#include "draw_demo.h"
#include "cg/curve.h"
#include "cg/draw.h"

#include <stdio.h>

static const cg_rgba8 white = {255, 255, 255, 255}, polygon = {170, 170, 170, 255},
                      dark = {25, 35, 60, 255}, red = {215, 50, 40, 255}, blue = {40, 90, 200, 255},
                      green = {30, 150, 80, 255}, orange = {235, 140, 20, 255};

static const char curves_script[] =
    "# Bezier, Hermite, B-spline and Catmull-Rom curves with their control polygons\n"
    "size 800 260\n"
    "background white\n"
    "tolerance 0.2\n"
    "antialias on\n"
    "# cubic Bezier: control polygon, control points, curve\n"
    "color #b0b0b0\n"
    "aaline 20 230 60 30\naaline 60 30 160 40\naaline 160 40 180 220\n"
    "disc 20 230 3\ndisc 60 30 3\ndisc 160 40 3\ndisc 180 220 3\n"
    "color #1f4e9c\n"
    "bezier 20 230 60 30 160 40 180 220\n"
    "# degree 6 Bezier\n"
    "color #b0b0b0\n"
    "aaline 200 200 210 40\naaline 210 40 260 230\naaline 260 230 300 20\naaline 300 20 330 240\n"
    "aaline 330 240 370 40\naaline 370 40 380 200\n"
    "color #c0392b\n"
    "bezier 200 200 210 40 260 230 300 20 330 240 370 40 380 200\n"
    "# Hermite: endpoints and tangent vectors (drawn at a third of their length)\n"
    "color #e67e22\n"
    "aaline 410 200 490 50\naaline 580 200 630 100\n"
    "disc 410 200 3\ndisc 580 200 3\n"
    "color #27ae60\n"
    "hermite 410 200 580 200 240 -450 150 -300\n"
    "# uniform cubic B-spline and Catmull-Rom spline on the same control points\n"
    "color #b0b0b0\n"
    "aaline 620 230 640 40\naaline 640 40 700 200\naaline 700 200 740 30\naaline 740 30 780 220\n"
    "disc 620 230 3\ndisc 640 40 3\ndisc 700 200 3\ndisc 740 30 3\ndisc 780 220 3\n"
    "color #8e44ad\n"
    "bspline 620 230 640 40 700 200 740 30 780 220\n"
    "color #16a085\n"
    "catmullrom 620 230 640 40 700 200 740 30 780 220\n";

/* de Casteljau's construction at t = 0.4 for a quartic. */
static int casteljau(demo_context *context)
{
    cg_image *image;
    if (cg_image_create(&image, 420, 300, CG_PIXEL_RGBA8) != CG_OK)
        return 1;
    cg_image_clear_rgba8(image, white);
    cg_vec2 p[5] = {{30, 270}, {70, 40}, {210, 20}, {390, 90}, {330, 280}}, work[5];
    double t = 0.4;
    const cg_rgba8 colours[4] = {polygon, orange, green, blue};
    for (int i = 0; i < 5; i++)
        work[i] = p[i];
    for (int level = 4; level >= 1; level--) {
        cg_draw_polyline_aa(image, work, level + 1, colours[4 - level]);
        for (int i = 0; i <= level; i++)
            cg_draw_disc(image, (int)work[i].x, (int)work[i].y, 3, colours[4 - level]);
        for (int i = 0; i < level; i++)
            work[i] = cg_vec2_add(cg_vec2_scale(work[i], 1 - t), cg_vec2_scale(work[i + 1], t));
    }
    cg_vec2 left[5], right[5];
    cg_bezier_split(p, 5, t, left, right);
    cg_draw_bezier(image, left, 5, 0.2, CG_DRAW_ANTIALIASED, red);
    cg_draw_bezier(image, right, 5, 0.2, CG_DRAW_ANTIALIASED, dark);
    cg_draw_disc(image, (int)work[0].x, (int)work[0].y, 5, red);
    int status = demo_add(context, "curve-casteljau.png", image,
                          "de Casteljau's algorithm on a quartic Bezier at t = 0.4: each level "
                          "interpolates the one before; the last point is Q(0.4), and the "
                          "intermediate points are the control polygons of the two halves "
                          "(subdivision: red and dark)",
                          "cg demo --only 'Parametric curves'");
    cg_image_free(image);
    return status;
}

typedef struct dots { cg_image *image; cg_vec2 last; int count; } dots;

static cg_status add_dot(void *user, cg_vec2 p)
{
    dots *d = user;
    cg_draw_line_aa(d->image, d->last.x, d->last.y, p.x, p.y, blue);
    cg_draw_disc(d->image, (int)p.x, (int)p.y, 2, red);
    d->last = p;
    d->count++;
    return CG_OK;
}

/* The same cubic flattened within 8, 2 and 0.25 pixels. */
static int flattening(demo_context *context)
{
    cg_image *image;
    if (cg_image_create(&image, 720, 240, CG_PIXEL_RGBA8) != CG_OK)
        return 1;
    cg_image_clear_rgba8(image, white);
    const double tolerances[3] = {8, 2, 0.25};
    for (int k = 0; k < 3; k++) {
        double ox = 10 + 240 * k;
        cg_vec2 p[4] = {{ox, 220}, {ox + 210, 230}, {ox + 230, 130}, {ox + 120, 10}};
        cg_draw_bezier(image, p, 4, 0.05, CG_DRAW_ANTIALIASED, polygon);
        dots d = {image, p[0], 0};
        cg_draw_disc(image, (int)p[0].x, (int)p[0].y, 2, red);
        cg_bezier_flatten(p, 4, tolerances[k], add_dot, &d);
    }
    int status = demo_add(context, "curve-flatten.png", image,
                          "Adaptive flattening of one cubic Bezier within 8, 2 and 0.25 pixels (grey: "
                          "the exact curve): halves are split only where the control points are "
                          "farther than the tolerance from the chord, so flat parts get few points",
                          "cg demo --only 'Parametric curves'");
    cg_image_free(image);
    return status;
}

/* Joins of two Bézier segments: G0 only, G1 and C1, as reported by
 * cg_cubic2_continuity (the colour of the joint says which). */
static int continuity(demo_context *context)
{
    cg_image *image;
    if (cg_image_create(&image, 720, 220, CG_PIXEL_RGBA8) != CG_OK)
        return 1;
    cg_image_clear_rgba8(image, white);
    for (int k = 0; k < 3; k++) {
        double ox = 20 + 240 * k;
        cg_cubic2 a = {CG_BASIS_BEZIER, {{ox, 180}, {ox + 20, 60}, {ox + 80, 40}, {ox + 110, 110}}};
        cg_cubic2 b = {CG_BASIS_BEZIER, {{ox + 110, 110}, {ox + 170, 200}, {ox + 190, 40}, {ox + 210, 60}}};
        if (k == 1)
            cg_cubic2_join_g1(&a, &b);
        if (k == 2)
            cg_cubic2_join_c1(&a, &b);
        cg_continuity c = cg_cubic2_continuity(&a, &b, 1e-9);
        for (int s = 0; s < 2; s++) {
            const cg_cubic2 *q = s ? &b : &a;
            cg_draw_polyline_aa(image, q->g, 4, polygon);
            for (int i = 0; i < 4; i++)
                cg_draw_disc(image, (int)q->g[i].x, (int)q->g[i].y, 2, polygon);
            cg_draw_bezier(image, q->g, 4, 0.2, CG_DRAW_ANTIALIASED, s ? blue : dark);
        }
        cg_draw_disc(image, (int)b.g[0].x, (int)b.g[0].y, 5,
                     c == CG_CONTINUITY_C1 ? green : c == CG_CONTINUITY_G1 ? orange : red);
    }
    int status = demo_add(context, "curve-continuity.png", image,
                          "Two Bezier segments joined at a knot: G0 only (left, red), a G1 join built "
                          "by cg_cubic2_join_g1 (middle: P3, P4, P5 collinear) and a C1 join built by "
                          "cg_cubic2_join_c1 (right: P4 - P3 = P5 - P4), as cg_cubic2_continuity reports",
                          "cg demo --only 'Parametric curves'");
    cg_image_free(image);
    return status;
}

static int render(demo_context *context)
{
    return draw_demo_script(context, "curve-kinds", curves_script,
                            "Curves flattened within 0.2 pixels and drawn anti-aliased, with control "
                            "polygons: a cubic and a degree-6 Bezier, a Hermite segment with its "
                            "tangents, and a uniform B-spline (purple, approximating) and a "
                            "Catmull-Rom spline (teal, interpolating) on the same five points")
           || casteljau(context) || flattening(context) || continuity(context);
}

const demo_section demo_section_curves = {2, "Parametric curves", render};
