// The OpenCV and AGG side of bench_draw_script.c (see its header).
#include "bench_draw_script_peers.h"

#ifdef CG_BENCH_HAVE_OPENCV
#include <opencv2/imgproc.hpp>
#include <vector>
#endif
#ifdef CG_BENCH_HAVE_AGG
#include <agg_pixfmt_rgba.h>
#include <agg_rasterizer_scanline_aa.h>
#include <agg_renderer_base.h>
#include <agg_renderer_scanline.h>
#include <agg_rendering_buffer.h>
#include <agg_scanline_bin.h>
#include <agg_scanline_u.h>
#endif

#ifdef CG_BENCH_HAVE_OPENCV
static cv::Scalar colour(const unsigned char *rgba, int i)
{
    return cv::Scalar(rgba[4 * i], rgba[4 * i + 1], rgba[4 * i + 2], rgba[4 * i + 3]);
}
#endif

extern "C" int peer_opencv_lines(unsigned char *pixels, int width, int height, const int *xy,
                                 int n, const unsigned char *rgba)
{
#ifdef CG_BENCH_HAVE_OPENCV
    cv::Mat image(height, width, CV_8UC4, pixels);
    for (int i = 0; i < n; i++, xy += 4)
        cv::line(image, cv::Point(xy[0], xy[1]), cv::Point(xy[2], xy[3]), colour(rgba, i), 1,
                 cv::LINE_8);
    return 1;
#else
    (void)pixels; (void)width; (void)height; (void)xy; (void)n; (void)rgba;
    return 0;
#endif
}

extern "C" int peer_opencv_circles(unsigned char *pixels, int width, int height, const int *cxr,
                                   int n, const unsigned char *rgba)
{
#ifdef CG_BENCH_HAVE_OPENCV
    cv::Mat image(height, width, CV_8UC4, pixels);
    for (int i = 0; i < n; i++, cxr += 3)
        cv::circle(image, cv::Point(cxr[0], cxr[1]), cxr[2], colour(rgba, i), 1, cv::LINE_8);
    return 1;
#else
    (void)pixels; (void)width; (void)height; (void)cxr; (void)n; (void)rgba;
    return 0;
#endif
}

extern "C" int peer_opencv_polygons(unsigned char *pixels, int width, int height, const double *xy,
                                    const int *first, const int *sizes, int n, int antialias,
                                    const unsigned char *rgba)
{
#ifdef CG_BENCH_HAVE_OPENCV
    cv::Mat image(height, width, CV_8UC4, pixels);
    const int shift = 8; // sub-pixel coordinates with 8 fractional bits
    std::vector<std::vector<cv::Point>> contours(1);
    for (int s = 0; s < n; s++) {
        const double *p = xy + 2 * first[s];
        contours[0].resize((size_t)sizes[s]);
        // OpenCV samples at integer coordinates: shifted by half a pixel,
        // both libraries sample at pixel centres.
        for (int i = 0; i < sizes[s]; i++)
            contours[0][(size_t)i] = cv::Point((int)((p[2 * i] - 0.5) * 256),
                                               (int)((p[2 * i + 1] - 0.5) * 256));
        cv::fillPoly(image, contours, colour(rgba, s), antialias ? cv::LINE_AA : cv::LINE_8, shift);
    }
    return 1;
#else
    (void)pixels; (void)width; (void)height; (void)xy; (void)first; (void)sizes; (void)n;
    (void)antialias; (void)rgba;
    return 0;
#endif
}

extern "C" int peer_agg_polygons(unsigned char *pixels, int width, int height, const double *xy,
                                 const int *first, const int *sizes, int n, int antialias,
                                 const unsigned char *rgba)
{
#ifdef CG_BENCH_HAVE_AGG
    agg::rendering_buffer buffer(pixels, (unsigned)width, (unsigned)height, width * 4);
    agg::pixfmt_rgba32 format(buffer);
    agg::renderer_base<agg::pixfmt_rgba32> base(format);
    agg::rasterizer_scanline_aa<> ras;
    ras.filling_rule(agg::fill_non_zero);
    agg::scanline_u8 sl;
    agg::scanline_bin sb;
    for (int s = 0; s < n; s++) {
        const double *p = xy + 2 * first[s];
        const unsigned char *c = rgba + 4 * s;
        ras.reset();
        ras.move_to_d(p[0], p[1]);
        for (int i = 1; i < sizes[s]; i++)
            ras.line_to_d(p[2 * i], p[2 * i + 1]);
        ras.close_polygon();
        agg::rgba8 color(c[0], c[1], c[2], c[3]);
        if (antialias)
            agg::render_scanlines_aa_solid(ras, sl, base, color);
        else
            agg::render_scanlines_bin_solid(ras, sb, base, color);
    }
    return 1;
#else
    (void)pixels; (void)width; (void)height; (void)xy; (void)first; (void)sizes; (void)n;
    (void)antialias; (void)rgba;
    return 0;
#endif
}
