// AGG and OpenCV as peers of the fill benchmark.
#include "bench_fill_peers.h"

#include <vector>

#ifdef CG_BENCH_HAVE_AGG
#include <agg_pixfmt_rgba.h>
#include <agg_rasterizer_scanline_aa.h>
#include <agg_renderer_base.h>
#include <agg_renderer_scanline.h>
#include <agg_rendering_buffer.h>
#include <agg_scanline_bin.h>
#include <agg_scanline_u.h>
#include <agg_conv_curve.h>
#include <agg_path_storage.h>
#endif

#ifdef CG_BENCH_HAVE_OPENCV
#include <opencv2/imgproc.hpp>
#endif

extern "C" int peer_agg_fill(unsigned char *pixels, int width, int height, int stride,
                             const bench_shape *shapes, int count, int even_odd, int antialias,
                             const unsigned char rgba[4])
{
#ifdef CG_BENCH_HAVE_AGG
    agg::rendering_buffer buffer(pixels, width, height, stride);
    agg::pixfmt_rgba32 format(buffer);
    agg::renderer_base<agg::pixfmt_rgba32> base(format);
    agg::rasterizer_scanline_aa<> ras;
    ras.filling_rule(even_odd ? agg::fill_even_odd : agg::fill_non_zero);
    agg::rgba8 color(rgba[0], rgba[1], rgba[2], rgba[3]);
    agg::scanline_u8 sl;
    agg::scanline_bin sb;
    for (int s = 0; s < count; s++) {
        ras.reset();
        const double *p = shapes[s].xy;
        for (int c = 0; c < shapes[s].contours; c++) {
            int n = shapes[s].sizes[c];
            ras.move_to_d(p[0], p[1]);
            for (int i = 1; i < n; i++)
                ras.line_to_d(p[2 * i], p[2 * i + 1]);
            ras.close_polygon();
            p += 2 * n;
        }
        if (antialias)
            agg::render_scanlines_aa_solid(ras, sl, base, color);
        else
            agg::render_scanlines_bin_solid(ras, sb, base, color);
    }
    return 1;
#else
    (void)pixels; (void)width; (void)height; (void)stride; (void)shapes; (void)count;
    (void)even_odd; (void)antialias; (void)rgba;
    return 0;
#endif
}

extern "C" int peer_agg_fill_curves(unsigned char *pixels, int width, int height, int stride,
                                    const bench_curve_path *paths, int count,
                                    const unsigned char rgba[4])
{
#ifdef CG_BENCH_HAVE_AGG
    agg::rendering_buffer buffer(pixels, width, height, stride);
    agg::pixfmt_rgba32 format(buffer);
    agg::renderer_base<agg::pixfmt_rgba32> base(format);
    agg::rasterizer_scanline_aa<> ras;
    ras.filling_rule(agg::fill_even_odd);
    agg::rgba8 color(rgba[0], rgba[1], rgba[2], rgba[3]);
    agg::scanline_u8 sl;
    agg::path_storage path;
    for (int s = 0; s < count; s++) {
        path.remove_all();
        const double *p = paths[s].xy;
        for (const char *v = paths[s].verbs; *v; v++) {
            switch (*v) {
            case 'M': path.move_to(p[0], p[1]); p += 2; break;
            case 'L': path.line_to(p[0], p[1]); p += 2; break;
            case 'C': path.curve4(p[0], p[1], p[2], p[3], p[4], p[5]); p += 6; break;
            default: path.close_polygon(); break;
            }
        }
        agg::conv_curve<agg::path_storage> curves(path);
        curves.approximation_scale(5.0); // within 0.5 / 5 = 0.1 pixel, as cg and Cairo here
        ras.reset();
        ras.add_path(curves);
        agg::render_scanlines_aa_solid(ras, sl, base, color);
    }
    return 1;
#else
    (void)pixels; (void)width; (void)height; (void)stride; (void)paths; (void)count; (void)rgba;
    return 0;
#endif
}

extern "C" int peer_opencv_fill(unsigned char *pixels, int width, int height, int stride,
                                const bench_shape *shapes, int count, int antialias,
                                const unsigned char rgba[4])
{
#ifdef CG_BENCH_HAVE_OPENCV
    cv::Mat image(height, width, CV_8UC4, pixels, (size_t)stride);
    cv::Scalar color(rgba[0], rgba[1], rgba[2], rgba[3]);
    const int shift = 8; // sub-pixel coordinates with 8 fractional bits
    std::vector<std::vector<cv::Point>> contours;
    for (int s = 0; s < count; s++) {
        contours.resize((size_t)shapes[s].contours);
        const double *p = shapes[s].xy;
        for (int c = 0; c < shapes[s].contours; c++) {
            int n = shapes[s].sizes[c];
            contours[(size_t)c].resize((size_t)n);
            // OpenCV samples at integer coordinates: shift by half a pixel
            // so both sample at pixel centres.
            for (int i = 0; i < n; i++)
                contours[(size_t)c][(size_t)i] = cv::Point((int)((p[2 * i] - 0.5) * 256),
                                                           (int)((p[2 * i + 1] - 0.5) * 256));
            p += 2 * n;
        }
        cv::fillPoly(image, contours, color, antialias ? cv::LINE_AA : cv::LINE_8, shift);
    }
    return 1;
#else
    (void)pixels; (void)width; (void)height; (void)stride; (void)shapes; (void)count;
    (void)antialias; (void)rgba;
    return 0;
#endif
}

extern "C" int peer_opencv_flood(unsigned char *pixels, int width, int height, int stride, int x,
                                 int y, int connectivity, const unsigned char rgba[4])
{
#ifdef CG_BENCH_HAVE_OPENCV
    cv::Mat image(height, width, CV_8UC3, pixels, (size_t)stride);
    cv::floodFill(image, cv::Point(x, y), cv::Scalar(rgba[0], rgba[1], rgba[2]), nullptr,
                  cv::Scalar(), cv::Scalar(), connectivity);
    return 1;
#else
    (void)pixels; (void)width; (void)height; (void)stride; (void)x; (void)y; (void)connectivity;
    (void)rgba;
    return 0;
#endif
}
