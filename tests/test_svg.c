/* SVG documents (cg/svg.h): each feature drawn and measured against its
 * definition (areas, positions, colours), style precedence, references,
 * and hostile files refused with a message. */
#include "cg/svg.h"
#include "cg/fill.h"
#include "cg/color.h"
#include "check.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define HEAD "<svg xmlns='http://www.w3.org/2000/svg' xmlns:xlink='http://www.w3.org/1999/xlink' "

/* Loads text and draws it at its own size onto a transparent image. */
static cg_image *draw(const char *text, int w, int h, cg_error *err)
{
    cg_svg *svg;
    cg_error local;
    if (!err)
        err = &local;
    if (cg_svg_load_memory(text, strlen(text), "test.svg", &svg, err) != CG_OK) {
        printf("load failed: %s\n", err->message);
        return NULL;
    }
    cg_image *image;
    if (cg_image_create(&image, w, h, CG_PIXEL_RGBA8) != CG_OK) {
        cg_svg_free(svg);
        return NULL;
    }
    if (cg_svg_render(svg, image, cg_mat3_identity(), err) != CG_OK)
        printf("render failed: %s\n", err->message);
    cg_svg_free(svg);
    return image;
}

static cg_rgba8 at(const cg_image *image, int x, int y)
{
    return cg_image_row_rgba8((cg_image *)image, y)[x];
}

/* Total alpha / 255: the covered area in pixels. */
static double area(const cg_image *image)
{
    double sum = 0;
    for (int y = 0; y < image->height; y++)
        for (int x = 0; x < image->width; x++)
            sum += at(image, x, y).a / 255.0;
    return sum;
}

/* The alpha-weighted centroid. */
static cg_vec2 centroid(const cg_image *image)
{
    double sx = 0, sy = 0, s = 0;
    for (int y = 0; y < image->height; y++)
        for (int x = 0; x < image->width; x++) {
            double a = at(image, x, y).a / 255.0;
            sx += a * (x + 0.5);
            sy += a * (y + 0.5);
            s += a;
        }
    return cg_vec2_make(s > 0 ? sx / s : -1, s > 0 ? sy / s : -1);
}

static int same_rgba(cg_rgba8 a, int r, int g, int b, int alpha, int tolerance)
{
    return abs(a.r - r) <= tolerance && abs(a.g - g) <= tolerance && abs(a.b - b) <= tolerance
           && abs(a.a - alpha) <= tolerance;
}

static void shapes(void)
{
    char text[1024];
    /* a pixel-aligned rect: exactly its pixels */
    cg_image *im = draw(HEAD "width='20' height='20'><rect x='3' y='4' width='10' height='5' "
                             "fill='#ff0000'/></svg>",
                        20, 20, NULL);
    CHECK(im && same_rgba(at(im, 3, 4), 255, 0, 0, 255, 0) && at(im, 2, 4).a == 0
          && at(im, 12, 8).a == 255 && at(im, 13, 8).a == 0 && at(im, 12, 9).a == 0);
    CHECK_NEAR(area(im), 50, 1e-9);
    cg_image_free(im);
    /* circles, ellipses and rounded rects of random sizes: their areas */
    check_rng rng = {77};
    for (int n = 0; n < 30; n++) {
        double cx = check_rng_range(&rng, 30, 70), cy = check_rng_range(&rng, 30, 70);
        double rx = check_rng_range(&rng, 3, 25), ry = check_rng_range(&rng, 3, 25);
        snprintf(text, sizeof text,
                 HEAD "width='100' height='100'><ellipse cx='%g' cy='%g' "
                      "rx='%g' ry='%g'/></svg>",
                 cx, cy, rx, ry);
        im = draw(text, 100, 100, NULL);
        CHECK_MSG(fabs(area(im) - CG_PI * rx * ry) < 0.002 * CG_PI * rx * ry + 0.5,
                  "ellipse %g x %g: area %g", rx, ry, area(im));
        cg_vec2 c = centroid(im);
        CHECK(fabs(c.x - cx) < 0.02 && fabs(c.y - cy) < 0.02);
        cg_image_free(im);
        double w = check_rng_range(&rng, 10, 60), h = check_rng_range(&rng, 10, 60);
        double r = check_rng_range(&rng, 0, 8);
        snprintf(text, sizeof text,
                 HEAD "width='100' height='100'><rect x='20.3' y='20.7' "
                      "width='%g' height='%g' rx='%g'/></svg>",
                 w, h, r);
        im = draw(text, 100, 100, NULL);
        double want = w * h - (4 - CG_PI) * r * r; /* ry = rx when only rx is given */
        CHECK_MSG(fabs(area(im) - want) < 0.002 * want, "rounded rect: %g, want %g", area(im),
                  want);
        cg_image_free(im);
    }
    /* polygon and polyline (filled as closed), path with arcs, an odd
     * point count dropping the last number */
    im = draw(HEAD "width='40' height='40'><polygon points='0,0 20,0 20,20 0,20 5'/>"
                   "<path d='M 20 20 h 10 a 10 10 0 0 1 -10 10 z'/></svg>",
              40, 40, NULL);
    CHECK_NEAR(area(im), 400 + CG_PI * 25, 0.5);
    cg_image_free(im);
    /* a line has no fill; a path with an error is drawn up to it */
    im = draw(HEAD "width='20' height='20'><line x1='0' y1='0' x2='20' y2='20' fill='red'/>"
                   "<path d='M 0 10 H 10 V 20 H 0 Z M 10 0 L 20 x'/></svg>",
              20, 20, NULL);
    CHECK_NEAR(area(im), 100, 1e-9);
    cg_image_free(im);
}

static void viewports(void)
{
    /* viewBox 0 0 10 10 into 100 x 50: meet centres a 50 x 50 square */
    cg_image *im = draw(HEAD "width='100' height='50' viewBox='0 0 10 10'><rect width='10' "
                             "height='10'/></svg>",
                        100, 50, NULL);
    CHECK_NEAR(area(im), 2500, 1e-6);
    CHECK(at(im, 24, 25).a == 0 && at(im, 25, 25).a == 255 && at(im, 74, 25).a == 255
          && at(im, 75, 25).a == 0);
    cg_image_free(im);
    im = draw(HEAD "width='100' height='50' viewBox='0 0 10 10' preserveAspectRatio='xMinYMin'>"
                   "<rect width='10' height='10'/></svg>",
              100, 50, NULL);
    CHECK(at(im, 0, 0).a == 255 && at(im, 50, 0).a == 0);
    cg_image_free(im);
    im = draw(HEAD "width='100' height='50' viewBox='0 0 10 10' preserveAspectRatio='none'>"
                   "<rect width='10' height='10'/></svg>",
              100, 50, NULL);
    CHECK_NEAR(area(im), 5000, 1e-6);
    cg_image_free(im);
    im = draw(HEAD "width='100' height='50' viewBox='0 0 10 10' preserveAspectRatio='xMidYMid "
                   "slice'><rect width='10' height='5'/></svg>",
              100, 50, NULL);
    CHECK_NEAR(area(im), 100 * 25, 1e-6); /* scale 10, the top half shifted up by 25 */
    cg_image_free(im);
    /* the document's size: width and height, else the viewBox's */
    cg_svg *svg;
    const char *t = HEAD "viewBox='0 0 30 20'/>";
    CHECK(cg_svg_load_memory(t, strlen(t), "t", &svg, NULL) == CG_OK);
    double w, h;
    cg_svg_size(svg, &w, &h);
    CHECK(w == 30 && h == 20);
    cg_svg_free(svg);
    t = HEAD "width='2in' viewBox='0 0 30 20'/>";
    CHECK(cg_svg_load_memory(t, strlen(t), "t", &svg, NULL) == CG_OK);
    cg_svg_size(svg, &w, &h);
    CHECK(w == 192 && h == 128);
    cg_svg_free(svg);
    /* a nested svg: its own viewport and viewBox */
    im = draw(HEAD "width='40' height='40'><svg x='10' y='10' width='20' height='20' "
                   "viewBox='0 0 2 2'><rect width='1' height='1'/></svg></svg>",
              40, 40, NULL);
    CHECK_NEAR(area(im), 100, 1e-6);
    CHECK(at(im, 10, 10).a == 255 && at(im, 20, 20).a == 0);
    cg_image_free(im);
}

static void transforms(void)
{
    char text[512];
    check_rng rng = {5};
    static const char *const kinds[] = {"translate(%g %g)", "scale(%g,%g)", "rotate(%g 20 20)",
                                        "skewX(%g)", "matrix(%g 0.1 -0.2 %g 3 4)"};
    for (int n = 0; n < 40; n++) {
        int k = (int)check_rng_int(&rng, 0, 4);
        double a = check_rng_range(&rng, 0.5, 1.5), b = check_rng_range(&rng, 0.5, 1.5);
        if (k == 0) {
            a = check_rng_range(&rng, -5, 5);
            b = check_rng_range(&rng, -5, 5);
        } else if (k == 2 || k == 3) {
            a = check_rng_range(&rng, -40, 40);
        }
        char transform[96];
        snprintf(transform, sizeof transform, kinds[k], a, b);
        snprintf(text, sizeof text,
                 HEAD "width='60' height='60'><g transform='translate(10,10)'>"
                      "<rect x='8' y='6' width='6' height='8' transform='%s'/></g></svg>",
                 transform);
        cg_image *im = draw(text, 60, 60, NULL);
        /* the rectangle's centre (11, 10) through the transforms */
        double x = 11, y = 10, area_scale = 1;
        switch (k) {
        case 0:
            x += a;
            y += b;
            break;
        case 1:
            x *= a;
            y *= b;
            area_scale = a * b;
            break;
        case 2: {
            double r = a * CG_PI / 180, dx = x - 20, dy = y - 20;
            x = 20 + dx * cos(r) - dy * sin(r);
            y = 20 + dx * sin(r) + dy * cos(r);
            break;
        }
        case 3: x += tan(a * CG_PI / 180) * y; break;
        default: {
            double nx = a * x - 0.2 * y + 3, ny = 0.1 * x + b * y + 4;
            x = nx;
            y = ny;
            area_scale = a * b + 0.02;
        }
        }
        cg_vec2 c = centroid(im);
        /* the centroid of pixel centres weighted by coverage is within a
         * few hundredths of a pixel of the true one */
        CHECK_MSG(fabs(c.x - (x + 10)) < 0.03 && fabs(c.y - (y + 10)) < 0.03,
                  "%s: centre (%g %g), want (%g %g)", transform, c.x, c.y, x + 10, y + 10);
        CHECK_MSG(fabs(area(im) - 48 * area_scale) < 0.01 * 48 * area_scale, "%s: area %g",
                  transform, area(im));
        cg_image_free(im);
    }
    /* a malformed transform is ignored with a warning; scale(0) hides */
    const char *t = HEAD "width='10' height='10'><rect width='4' height='4' transform='spin(3)'/>"
                         "<rect width='9' height='9' transform='scale(0)'/></svg>";
    cg_svg *svg;
    CHECK(cg_svg_load_memory(t, strlen(t), "t", &svg, NULL) == CG_OK);
    CHECK(cg_svg_warning_count(svg) == 1 && strstr(cg_svg_warning(svg, 0), "spin(3)"));
    cg_svg_free(svg);
    cg_image *im = draw(t, 10, 10, NULL);
    CHECK_NEAR(area(im), 16, 1e-9);
    cg_image_free(im);
}

static void styles(void)
{
    cg_image *im = draw(
        HEAD "width='60' height='10'><style type='text/css'>"
             "rect { fill: #0000ff } .a { fill: #00ff00 } #c { fill: #ff0000 } g rect.d { fill: "
             "#ffff00 }"
             " g > .e { fill: #00ffff } .f { fill: #ff00ff !important } /* comment */"
             " @media print { rect { fill: black } } .g:hover { fill: black }</style>"
             "<rect x='0' width='10' height='10'/>"
             "<rect x='10' width='10' height='10' class='a' fill='black'/>"
             "<rect x='20' width='10' height='10' class='a' id='c'/>"
             "<g><rect x='30' width='10' height='10' class='d a'/></g>"
             "<g><rect x='40' width='10' height='10' class='e' style='fill: #808080'/></g>"
             "<rect x='50' width='10' height='10' class='f' style='fill: #000000'/></svg>",
        60, 10, NULL);
    CHECK(same_rgba(at(im, 5, 5), 0, 0, 255, 255, 0));      /* type selector */
    CHECK(same_rgba(at(im, 15, 5), 0, 255, 0, 255, 0));     /* class beats attribute */
    CHECK(same_rgba(at(im, 25, 5), 255, 0, 0, 255, 0));     /* id beats class */
    CHECK(same_rgba(at(im, 35, 5), 255, 255, 0, 255, 0));   /* descendant, more specific */
    CHECK(same_rgba(at(im, 45, 5), 128, 128, 128, 255, 0)); /* style attribute beats sheet */
    CHECK(same_rgba(at(im, 55, 5), 255, 0, 255, 255, 0));   /* !important beats it */
    cg_image_free(im);
    /* currentColor through inheritance, as icon themes use it */
    im = draw(HEAD
              "width='20' height='10'><style>.ColorScheme-Text { color: #445566 }</style>"
              "<g class='ColorScheme-Text'><rect width='10' height='10' style='fill:currentColor'/>"
              "<rect x='10' width='10' height='10' fill='currentColor' color='rgb(10, 20, 30)'/>"
              "</g></svg>",
              20, 10, NULL);
    CHECK(same_rgba(at(im, 5, 5), 0x44, 0x55, 0x66, 255, 0));
    CHECK(same_rgba(at(im, 15, 5), 10, 20, 30, 255, 0));
    cg_image_free(im);
    /* display: none hides the subtree; visibility can be overridden below */
    im = draw(HEAD "width='30' height='10'><g display='none'><rect width='10' height='10'/></g>"
                   "<g visibility='hidden'><rect x='10' width='10' height='10'/>"
                   "<rect x='20' width='10' height='10' visibility='visible'/></g></svg>",
              30, 10, NULL);
    CHECK_NEAR(area(im), 100, 1e-9);
    CHECK(at(im, 25, 5).a == 255);
    cg_image_free(im);
    /* sRGB compositing: a half-opaque white over black is 128, not 188 */
    im = draw(HEAD "width='10' height='10'><rect width='10' height='10'/><rect width='10' "
                   "height='10' fill='white' fill-opacity='0.5'/></svg>",
              10, 10, NULL);
    CHECK(abs(at(im, 5, 5).r - 128) <= 1);
    cg_image_free(im);
}

static void strokes(void)
{
    /* a horizontal line 20 long, stroke width 2: area 40; under scale(1, 3)
     * the pen is an ellipse and the stroke 6 high */
    cg_image *im = draw(HEAD
                        "width='40' height='40'><line x1='5' y1='10' x2='25' y2='10' "
                        "stroke='black' stroke-width='2'/><g transform='scale(1 3)'>"
                        "<line x1='5' y1='10' x2='25' y2='10' stroke='black' stroke-width='2'/>"
                        "</g></svg>",
                        40, 40, NULL);
    CHECK_NEAR(area(im), 40 + 120, 0.01);
    CHECK(at(im, 15, 27).a == 255 && at(im, 15, 32).a == 255 && at(im, 15, 33).a == 0);
    cg_image_free(im);
    /* dashes: 5 on 5 off over 40 is 4 dashes; square caps add width each */
    im = draw(HEAD "width='50' height='20'><path d='M 0 10 H 40' stroke='black' stroke-width='2' "
                   "stroke-dasharray='5,5'/></svg>",
              50, 20, NULL);
    CHECK_NEAR(area(im), 40, 0.01);
    cg_image_free(im);
    im = draw(HEAD "width='50' height='20'><path d='M 1 10 H 41' stroke='black' stroke-width='2' "
                   "stroke-dasharray='5' stroke-linecap='square'/></svg>",
              50, 20, NULL);
    CHECK_NEAR(area(im), 4 * 7 * 2, 0.01);
    cg_image_free(im);
    /* paint-order stroke: the fill covers the stroke's inner half */
    im = draw(HEAD "width='20' height='20'><rect x='5' y='5' width='10' height='10' fill='red' "
                   "stroke='blue' stroke-width='4' paint-order='stroke'/></svg>",
              20, 20, NULL);
    CHECK(same_rgba(at(im, 5, 5), 255, 0, 0, 255, 0) && same_rgba(at(im, 4, 4), 0, 0, 255, 255, 0));
    cg_image_free(im);
}

static void gradients(void)
{
    /* objectBoundingBox: the ramp spans the shape, whatever its size */
    cg_image *im = draw(HEAD
                        "width='100' height='10'><linearGradient id='g'><stop offset='0' "
                        "stop-color='black'/><stop offset='1' stop-color='white'/></linearGradient>"
                        "<rect x='20' width='50' height='10' fill='url(#g)'/></svg>",
                        100, 10, NULL);
    int bad = 0;
    for (int x = 20; x < 70; x++)
        bad += abs(at(im, x, 5).r - (int)floor((x - 20 + 0.5) / 50 * 255 + 0.5)) > 1;
    CHECK_MSG(bad == 0, "%d pixels of a bounding-box gradient off", bad);
    cg_image_free(im);
    /* href inherits the stops; userSpaceOnUse; gradientTransform; reflect */
    im = draw(HEAD "width='40' height='40'><defs><linearGradient id='a'><stop offset='0' "
                   "stop-color='#000'/><stop offset='100%' stop-color='#fff'/></linearGradient>"
                   "<linearGradient id='b' xlink:href='#a' gradientUnits='userSpaceOnUse' x1='0' "
                   "x2='10' gradientTransform='rotate(90)' spreadMethod='reflect'/></defs>"
                   "<rect width='40' height='40' fill='url(#b)'/></svg>",
              40, 40, NULL);
    bad = 0;
    for (int y = 0; y < 40; y++) {
        double t = (y + 0.5) / 10, m = t - 2 * floor(t / 2), u = m > 1 ? 2 - m : m;
        bad += abs(at(im, 7, y).r - (int)floor(u * 255 + 0.5)) > 1
               || at(im, 3, y).r != at(im, 30, y).r;
    }
    CHECK_MSG(bad == 0, "%d rows of an inherited gradient off", bad);
    cg_image_free(im);
    /* stop-opacity and fill-opacity multiply; one stop is a solid colour;
     * a missing server paints nothing, a fallback colour is used */
    im = draw(HEAD
              "width='30' height='10'><radialGradient id='r'><stop stop-color='#ff0000' "
              "stop-opacity='0.5'/></radialGradient><rect width='10' height='10' fill='url(#r)' "
              "fill-opacity='0.5'/><rect x='10' width='10' height='10' fill='url(#none)'/>"
              "<rect x='20' width='10' height='10' fill='url(#none) #00ff00'/></svg>",
              30, 10, NULL);
    CHECK(same_rgba(at(im, 5, 5), 255, 0, 0, 64, 1));
    CHECK(at(im, 15, 5).a == 0);
    CHECK(same_rgba(at(im, 25, 5), 0, 255, 0, 255, 0));
    cg_image_free(im);
    /* a radial gradient: t is the distance from the centre over r */
    im = draw(HEAD "width='100' height='100'><radialGradient id='r' cx='50' cy='50' r='40' "
                   "gradientUnits='userSpaceOnUse'><stop offset='0' stop-color='white'/>"
                   "<stop offset='1' stop-color='black'/></radialGradient><rect width='100' "
                   "height='100' fill='url(#r)'/></svg>",
              100, 100, NULL);
    bad = 0;
    for (int x = 50; x < 100; x++) {
        double t = fmin(1, (x + 0.5 - 50) / 40);
        bad += abs(at(im, x, 49).r - (int)floor((1 - t) * 255 + 0.5)) > 2;
    }
    CHECK_MSG(bad == 0, "%d pixels of a radial gradient off", bad);
    cg_image_free(im);
}

static void groups(void)
{
    /* group opacity: overlapping rects one flat colour; fill-opacity not */
    cg_image *im = draw(HEAD "width='40' height='20'><g opacity='0.5'><rect width='15' "
                             "height='10'/><rect x='5' width='15' height='10'/></g><rect x='20' "
                             "width='15' height='10' fill-opacity='0.5'/><rect x='25' width='15' "
                             "height='10' fill-opacity='0.5'/></svg>",
                        40, 20, NULL);
    CHECK(abs(at(im, 2, 5).a - 128) <= 1 && at(im, 2, 5).a == at(im, 10, 5).a);
    CHECK(abs(at(im, 30, 5).a - 191) <= 1);
    cg_image_free(im);
    /* a clip path: a circle cuts a square to its area; objectBoundingBox
     * units; clip-rule evenodd makes a hole */
    im = draw(HEAD "width='100' height='100'><clipPath id='c'><circle cx='50' cy='50' r='30'/>"
                   "</clipPath><rect width='100' height='100' clip-path='url(#c)'/></svg>",
              100, 100, NULL);
    CHECK_NEAR(area(im), CG_PI * 900, 2);
    cg_image_free(im);
    im = draw(
        HEAD
        "width='100' height='100'><clipPath id='c' clipPathUnits='objectBoundingBox'>"
        "<path d='M 0 0 H 1 V 1 H 0 Z M 0.25 0.25 H 0.75 V 0.75 H 0.25 Z' clip-rule='evenodd'/>"
        "</clipPath><rect x='10' y='10' width='80' height='80' clip-path='url(#c)'/></svg>",
        100, 100, NULL);
    CHECK_NEAR(area(im), 6400 - 1600, 0.5);
    CHECK(at(im, 50, 50).a == 0 && at(im, 15, 15).a == 255);
    cg_image_free(im);
    /* a mask: luminance times alpha; the default rectangle is the box
     * grown by 10% */
    im = draw(HEAD
              "width='40' height='20'><mask id='m'><rect width='20' height='20' fill='#808080'/>"
              "<rect x='20' width='20' height='20' fill='white' fill-opacity='0.25'/></mask>"
              "<rect width='40' height='20' fill='#ff0000' mask='url(#m)'/></svg>",
              40, 20, NULL);
    CHECK(same_rgba(at(im, 5, 5), 255, 0, 0, 128, 1));
    CHECK(same_rgba(at(im, 30, 5), 255, 0, 0, 64, 1));
    cg_image_free(im);
    /* mix-blend-mode multiply */
    im = draw(
        HEAD "width='10' height='10'><rect width='10' height='10' fill='#808080'/>"
             "<rect width='10' height='10' fill='#808080' style='mix-blend-mode: multiply'/></svg>",
        10, 10, NULL);
    CHECK(abs(at(im, 5, 5).r - 64) <= 1);
    cg_image_free(im);
}

static void references(void)
{
    /* use moves by x, y; symbol maps its viewBox into width x height */
    cg_image *im = draw(HEAD
                        "width='60' height='20'><defs><rect id='r' width='5' height='5'/>"
                        "<symbol id='s' viewBox='0 0 1 1'><rect width='1' height='1'/></symbol>"
                        "</defs><use xlink:href='#r' x='10' y='2'/><use href='#s' x='30' y='0' "
                        "width='20' height='20'/></svg>",
                        60, 20, NULL);
    CHECK_NEAR(area(im), 25 + 400, 1e-6);
    CHECK(at(im, 10, 2).a == 255 && at(im, 9, 2).a == 0 && at(im, 49, 19).a == 255);
    cg_image_free(im);
    /* the used element takes the use's inherited style */
    im = draw(HEAD "width='10' height='10'><defs><rect id='r' width='10' height='10'/></defs>"
                   "<use href='#r' fill='#00ff00'/></svg>",
              10, 10, NULL);
    CHECK(same_rgba(at(im, 5, 5), 0, 255, 0, 255, 0));
    cg_image_free(im);
}

/* A 2 x 2 PNG as a data URI. */
static void images(void)
{
    cg_image *picture;
    CHECK(cg_image_create(&picture, 2, 2, CG_PIXEL_RGBA8) == CG_OK);
    cg_rgba8 colours[4] = {{255, 0, 0, 255},
                           {0, 255, 0, 255},
                           {0, 0, 255, 255},
                           {255, 255, 255, 255}};
    for (int i = 0; i < 4; i++)
        cg_image_row_rgba8(picture, i / 2)[i % 2] = colours[i];
    char path[] = "/tmp/cg_test_svg_XXXXXX";
    int fd = mkstemp(path);
    CHECK(fd >= 0);
    char png_path[64];
    snprintf(png_path, sizeof png_path, "%s.png", path);
    CHECK(cg_image_write(picture, png_path, CG_FILE_PNG, NULL) == CG_OK);
    FILE *f = fopen(png_path, "rb");
    unsigned char bytes[4096];
    size_t n = f ? fread(bytes, 1, sizeof bytes, f) : 0;
    if (f)
        fclose(f);
    remove(png_path);
    remove(path);
    static const char alphabet[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    char base64[8192];
    size_t k = 0;
    for (size_t i = 0; i < n; i += 3) {
        unsigned v = bytes[i] << 16 | (i + 1 < n ? bytes[i + 1] << 8 : 0)
                     | (i + 2 < n ? bytes[i + 2] : 0);
        base64[k++] = alphabet[v >> 18];
        base64[k++] = alphabet[(v >> 12) & 63];
        base64[k++] = i + 1 < n ? alphabet[(v >> 6) & 63] : '=';
        base64[k++] = i + 2 < n ? alphabet[v & 63] : '=';
    }
    base64[k] = 0;
    size_t room = sizeof base64 + 512;
    char *text = malloc(room);
    snprintf(text, room,
             HEAD "width='40' height='40'><image x='0' y='0' width='40' height='40' "
                  "xlink:href='data:image/png;base64,%s'/></svg>",
             base64);
    cg_image *im = draw(text, 40, 40, NULL);
    /* each source pixel fills a 20 x 20 quarter; bilinear filtering (with
     * edges clamped) gives its colour exactly within half a pixel of its
     * centre, at (9.5, 9.5) and (30.5, 30.5) */
    for (int i = 0; i < 4; i++) {
        cg_rgba8 c = colours[i];
        cg_rgba8 got = im ? at(im, i % 2 ? 30 : 9, i / 2 ? 30 : 9) : c;
        CHECK_MSG(im && same_rgba(got, c.r, c.g, c.b, 255, 1), "quarter %d: %d %d %d %d", i, got.r,
                  got.g, got.b, got.a);
    }
    cg_image_free(im);
    free(text);
    cg_image_free(picture);
}

/* The same document onto an RGBAF image (linear light, straight alpha):
 * the RGBA8 drawing decoded, within a code. */
static void float_images(void)
{
    const char *t = HEAD
        "width='24' height='12'><defs><linearGradient id='g'><stop offset='0' "
        "stop-color='#204080'/><stop offset='1' stop-color='#f0c020' stop-opacity='.5'/>"
        "</linearGradient></defs><rect width='24' height='12' fill='#336699'/>"
        "<circle cx='8' cy='6' r='5' fill='url(#g)'/><g opacity='0.5'>"
        "<rect x='12' y='2' width='10' height='8' fill='white' stroke='red'/></g></svg>";
    cg_svg *svg;
    CHECK(cg_svg_load_memory(t, strlen(t), "t", &svg, NULL) == CG_OK);
    cg_image *a, *f;
    CHECK(cg_image_create(&a, 24, 12, CG_PIXEL_RGBA8) == CG_OK);
    CHECK(cg_image_create(&f, 24, 12, CG_PIXEL_RGBAF) == CG_OK);
    CHECK(cg_svg_render(svg, a, cg_mat3_identity(), NULL) == CG_OK);
    CHECK(cg_svg_render(svg, f, cg_mat3_identity(), NULL) == CG_OK);
    int bad = 0;
    for (int y = 0; y < 12; y++)
        for (int x = 0; x < 24; x++) {
            cg_rgba8 p = at(a, x, y);
            cg_rgbaf q = cg_image_row_rgbaf(f, y)[x];
            cg_rgba8 e = cg_linear_to_rgba8(q);
            bad += abs(p.r - e.r) > 1 || abs(p.g - e.g) > 1 || abs(p.b - e.b) > 1
                   || abs(p.a - e.a) > 1;
        }
    CHECK_MSG(bad == 0, "%d float pixels differ from the RGBA8 drawing", bad);
    cg_image_free(a);
    cg_image_free(f);
    cg_svg_free(svg);
}

static cg_status load_status(const char *text, cg_error *err)
{
    cg_svg *svg = NULL;
    cg_status s = cg_svg_load_memory(text, strlen(text), "bad.svg", &svg, err);
    if (s == CG_OK) {
        cg_image *image;
        cg_image_create(&image, 16, 16, CG_PIXEL_RGBA8);
        s = cg_svg_render(svg, image, cg_mat3_identity(), err);
        cg_image_free(image);
        cg_svg_free(svg);
    }
    return s;
}

static void hostile(void)
{
    cg_error err;
    CHECK(load_status("<?xml version='1.0'?><!DOCTYPE svg [<!ENTITY a 'aaaaaaaaaa'>"
                      "<!ENTITY b '&a;&a;&a;&a;&a;&a;&a;&a;&a;&a;'>]><svg>&b;</svg>",
                      &err)
          == CG_EFORMAT);
    CHECK(strstr(err.message, "bad.svg:1: entity declaration 'a' refused") != NULL);
    CHECK(
        load_status("<!DOCTYPE svg [<!ENTITY x SYSTEM 'file:///etc/passwd'>]><svg>&x;</svg>", &err)
        == CG_EFORMAT);
    CHECK(strstr(err.message, "external entities are never read") != NULL);
    /* deep nesting */
    size_t depth = 300;
    char *deep = malloc(depth * 7 + 64);
    strcpy(deep, "<svg>");
    for (size_t i = 0; i < depth; i++)
        strcat(deep, "<g>");
    for (size_t i = 0; i < depth; i++)
        strcat(deep, "</g>");
    strcat(deep, "</svg>");
    CHECK(load_status(deep, &err) == CG_ERANGE && strstr(err.message, "nested deeper than 256"));
    free(deep);
    /* a use cycle, a use of its own ancestor, an exponential use tree */
    CHECK(load_status(HEAD "><use id='a' href='#b'/><use id='b' href='#a'/></svg>", &err)
          == CG_EFORMAT);
    CHECK(strstr(err.message, "cycle") != NULL);
    CHECK(
        load_status(HEAD "><g id='g'><rect width='1' height='1'/><use href='#g'/></g></svg>", &err)
        == CG_EFORMAT);
    char tree[4096] = HEAD "><defs><rect id='l0' width='1' height='1'/>";
    for (int level = 1; level <= 12; level++) {
        char line[300];
        snprintf(line, sizeof line, "<g id='l%d'>", level);
        strcat(tree, line);
        for (int i = 0; i < 10; i++) {
            snprintf(line, sizeof line, "<use href='#l%d'/>", level - 1);
            strcat(tree, line);
        }
        strcat(tree, "</g>");
    }
    strcat(tree, "</defs><use href='#l12'/></svg>");
    CHECK(load_status(tree, &err) == CG_EFORMAT && strstr(err.message, "more than 2000000"));
    /* style sheets whose matching would take minutes: 2000 rules that
     * each search 200 ancestors for every one of 1000 elements */
    size_t room = 2000 * 40 + 1000 * 48 + 200 * 8 + 256;
    char *sheet = malloc(room), *at = sheet;
    at += sprintf(at, "%s", HEAD "><style>");
    for (int i = 0; i < 2000; i++)
        at += sprintf(at, "x g g g g g rect { fill: red }\n");
    at += sprintf(at, "</style>");
    for (int i = 0; i < 200; i++)
        at += sprintf(at, "<g>");
    for (int i = 0; i < 1000; i++)
        at += sprintf(at, "<rect width='1' height='1'/>");
    for (int i = 0; i < 200; i++)
        at += sprintf(at, "</g>");
    sprintf(at, "</svg>");
    CHECK(load_status(sheet, &err) == CG_ERANGE && strstr(err.message, "selector steps"));
    free(sheet);
    /* malformed XML, another root, nothing at all */
    CHECK(load_status("<svg><g></svg>", &err) == CG_EFORMAT
          && strstr(err.message, "bad.svg:1: malformed XML: mismatched tag"));
    CHECK(load_status("<html/>", &err) == CG_EFORMAT && strstr(err.message, "<html>"));
    CHECK(load_status("", &err) == CG_EFORMAT);
    CHECK(load_status("<x:svg xmlns:x='urn:other'/>", &err) == CG_EFORMAT);
    cg_svg *svg;
    CHECK(cg_svg_load("/nonexistent/file.svg", &svg, &err) == CG_EIO
          && strstr(err.message, "/nonexistent/file.svg"));
    /* skipped content: one warning per kind, nothing fetched, metadata of
     * other namespaces ignored silently */
    const char *t = HEAD
        "xmlns:inkscape='http://www.inkscape.org/namespaces/inkscape'>"
        "<inkscape:grid/><filter "
        "id='f'><feGaussianBlur/></filter><text><textPath>a</textPath></text>"
        "<textPath>b</textPath><script>alert(1)</script><rect width='4' height='4' "
        "filter='url(#f)'/><use href='other.svg#x'/><image href='http://x/y.png'/>"
        "</svg>";
    CHECK(cg_svg_load_memory(t, strlen(t), "t", &svg, &err) == CG_OK);
    int n = cg_svg_warning_count(svg);
    const char *expected[] = {"<filter>",       "<feGaussianBlur>", "<textPath>",    "<script>",
                              "filter effects", "other.svg#x",      "http://x/y.png"};
    CHECK_EQ_INT(n, 7);
    for (int i = 0; i < 7; i++) {
        int found = 0;
        for (int k = 0; k < n; k++)
            found |= strstr(cg_svg_warning(svg, k), expected[i]) != NULL;
        CHECK_MSG(found, "no warning names %s", expected[i]);
    }
    cg_svg_free(svg);
    /* huge coordinates and dimensions draw nothing outside, quickly */
    cg_image *im = draw(HEAD "width='16' height='16'><rect x='-1e30' width='1e31' height='8'/>"
                             "<circle cx='1e12' cy='0' r='1e12'/></svg>",
                        16, 16, NULL);
    CHECK(im != NULL);
    cg_image_free(im);
    CHECK(cg_svg_render(NULL, NULL, cg_mat3_identity(), &err) == CG_EINVAL);
}

int main(int argc, char **argv)
{
    check_start(argc, argv);
    CHECK_GROUP(shapes);
    CHECK_GROUP(viewports);
    CHECK_GROUP(transforms);
    CHECK_GROUP(styles);
    CHECK_GROUP(strokes);
    CHECK_GROUP(gradients);
    CHECK_GROUP(groups);
    CHECK_GROUP(references);
    CHECK_GROUP(images);
    CHECK_GROUP(float_images);
    CHECK_GROUP(hostile);
    return check_finish();
}
