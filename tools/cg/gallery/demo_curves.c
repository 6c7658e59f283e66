/* Gallery: parametric cubic curves and Bézier curves (section 2.3). */
#include "script_pictures.h"
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

/* Draw-script lines for the pictures below: the curves are computed in C
 * and written as commands, so each picture's caption is `cg draw`. */
static void set_color(script_text *t, cg_rgba8 c)
{
    script_add(t, "color #%02x%02x%02x\n", c.r, c.g, c.b);
}

static void polyline_aa(script_text *t, const cg_vec2 *p, int n)
{
    for (int i = 0; i + 1 < n; i++)
        script_add(t, "aaline %.17g %.17g %.17g %.17g\n", p[i].x, p[i].y, p[i + 1].x, p[i + 1].y);
}

static void disc(script_text *t, cg_vec2 p, int r)
{
    script_add(t, "disc %d %d %d\n", (int)p.x, (int)p.y, r);
}

static void bezier(script_text *t, const cg_vec2 *p, int n, double tolerance)
{
    script_add(t, "tolerance %.17g\nbezier", tolerance);
    for (int i = 0; i < n; i++)
        script_add(t, " %.17g %.17g", p[i].x, p[i].y);
    script_add(t, "\n");
}

static void start(script_text *t, int width, int height)
{
    script_add(t, "size %d %d\nbackground #%02x%02x%02x\nantialias on\n", width, height, white.r,
               white.g, white.b);
}

/* de Casteljau's construction at t = 0.4 for a quartic. */
static int casteljau(demo_context *context)
{
    script_text s = {.length = 0};
    start(&s, 420, 300);
    cg_vec2 p[5] = {{30, 270}, {70, 40}, {210, 20}, {390, 90}, {330, 280}}, work[5];
    double t = 0.4;
    const cg_rgba8 colours[4] = {polygon, orange, green, blue};
    for (int i = 0; i < 5; i++)
        work[i] = p[i];
    for (int level = 4; level >= 1; level--) {
        set_color(&s, colours[4 - level]);
        polyline_aa(&s, work, level + 1);
        for (int i = 0; i <= level; i++)
            disc(&s, work[i], 3);
        for (int i = 0; i < level; i++)
            work[i] = cg_vec2_add(cg_vec2_scale(work[i], 1 - t), cg_vec2_scale(work[i + 1], t));
    }
    cg_vec2 left[5], right[5];
    cg_bezier_split(p, 5, t, left, right);
    set_color(&s, red);
    bezier(&s, left, 5, 0.2);
    set_color(&s, dark);
    bezier(&s, right, 5, 0.2);
    set_color(&s, red);
    disc(&s, work[0], 5);
    return draw_demo_script(context, "curve-casteljau", s.text,
                            "de Casteljau's algorithm on a quartic Bezier at t = 0.4: each level "
                            "interpolates the one before; the last point is Q(0.4), and the "
                            "intermediate points are the control polygons of the two halves "
                            "(subdivision: red and dark)");
}

typedef struct dots {
    script_text *script;
    cg_vec2 last;
    int count;
} dots;

static cg_status add_dot(void *user, cg_vec2 p)
{
    dots *d = user;
    cg_vec2 segment[2] = {d->last, p};
    set_color(d->script, blue);
    polyline_aa(d->script, segment, 2);
    set_color(d->script, red);
    disc(d->script, p, 2);
    d->last = p;
    d->count++;
    return CG_OK;
}

/* The same cubic flattened within 8, 2 and 0.25 pixels. */
static int flattening(demo_context *context)
{
    static script_text s; /* large: the flattened points of three curves */
    s.length = 0;
    start(&s, 720, 240);
    const double tolerances[3] = {8, 2, 0.25};
    for (int k = 0; k < 3; k++) {
        double ox = 10 + 240 * k;
        cg_vec2 p[4] = {{ox, 220}, {ox + 210, 230}, {ox + 230, 130}, {ox + 120, 10}};
        set_color(&s, polygon);
        bezier(&s, p, 4, 0.05);
        dots d = {&s, p[0], 0};
        set_color(&s, red);
        disc(&s, p[0], 2);
        cg_bezier_flatten(p, 4, tolerances[k], add_dot, &d);
    }
    return draw_demo_script(context, "curve-flatten", s.text,
                            "Adaptive flattening of one cubic Bezier within 8, 2 and 0.25 pixels "
                            "(grey: the exact curve): halves are split only where the control "
                            "points are farther than the tolerance from the chord, so flat parts "
                            "get few points");
}

/* Joins of two Bézier segments: G0 only, G1 and C1, as reported by
 * cg_cubic2_continuity (the colour of the joint says which). */
static int continuity(demo_context *context)
{
    script_text s = {.length = 0};
    start(&s, 720, 220);
    for (int k = 0; k < 3; k++) {
        double ox = 20 + 240 * k;
        cg_cubic2 a = {CG_BASIS_BEZIER, {{ox, 180}, {ox + 20, 60}, {ox + 80, 40}, {ox + 110, 110}}};
        cg_cubic2 b = {CG_BASIS_BEZIER,
                       {{ox + 110, 110}, {ox + 170, 200}, {ox + 190, 40}, {ox + 210, 60}}};
        if (k == 1)
            cg_cubic2_join_g1(&a, &b);
        if (k == 2)
            cg_cubic2_join_c1(&a, &b);
        cg_continuity c = cg_cubic2_continuity(&a, &b, 1e-9);
        for (int segment = 0; segment < 2; segment++) {
            const cg_cubic2 *q = segment ? &b : &a;
            set_color(&s, polygon);
            polyline_aa(&s, q->g, 4);
            for (int i = 0; i < 4; i++)
                disc(&s, q->g[i], 2);
            set_color(&s, segment ? blue : dark);
            bezier(&s, q->g, 4, 0.2);
        }
        set_color(&s, c == CG_CONTINUITY_C1 ? green : c == CG_CONTINUITY_G1 ? orange : red);
        disc(&s, b.g[0], 5);
    }
    return draw_demo_script(
        context, "curve-continuity", s.text,
        "Two Bezier segments joined at a knot: G0 only (left, red), a G1 join "
        "built by cg_cubic2_join_g1 (middle: P3, P4, P5 collinear) and a C1 join "
        "built by cg_cubic2_join_c1 (right: P4 - P3 = P5 - P4), as "
        "cg_cubic2_continuity reports");
}

static int render(demo_context *context)
{
    return draw_demo_script(
               context, "curve-kinds", curves_script,
               "Curves flattened within 0.2 pixels and drawn anti-aliased, with control "
               "polygons: a cubic and a degree-6 Bezier, a Hermite segment with its "
               "tangents, and a uniform B-spline (purple, approximating) and a "
               "Catmull-Rom spline (teal, interpolating) on the same five points")
           || casteljau(context) || flattening(context) || continuity(context);
}

const demo_section demo_section_curves = {2, "Parametric curves", render};
