/* Peer libraries called by bench_draw_script.c (OpenCV and AGG are C++),
 * behind a C interface.  Every shape has its own opaque colour
 * (rgba[4 * i .. 4 * i + 3]); the pixels are an RGBA 8-bit buffer.  Each
 * returns 0 when the peer is not built in. */
#ifndef CG_BENCH_DRAW_SCRIPT_PEERS_H
#define CG_BENCH_DRAW_SCRIPT_PEERS_H

#ifdef __cplusplus
extern "C" {
#endif

/* n lines x0 y0 x1 y1 (pixel indices), 8-connected (cv::line, LINE_8). */
int peer_opencv_lines(unsigned char *pixels, int width, int height, const int *xy, int n,
                      const unsigned char *rgba);
/* n circles cx cy r, one pixel wide outline (cv::circle, LINE_8). */
int peer_opencv_circles(unsigned char *pixels, int width, int height, const int *cxr, int n,
                        const unsigned char *rgba);
/* n polygons, polygon i having sizes[i] points from xy + 2 * first[i]
 * (cv::fillPoly, LINE_8 or LINE_AA). */
int peer_opencv_polygons(unsigned char *pixels, int width, int height, const double *xy,
                         const int *first, const int *sizes, int n, int antialias,
                         const unsigned char *rgba);
/* The same polygons with AGG's scan-line rasterizer (non-zero rule),
 * anti-aliased or aliased (render_scanlines_bin_solid). */
int peer_agg_polygons(unsigned char *pixels, int width, int height, const double *xy,
                      const int *first, const int *sizes, int n, int antialias,
                      const unsigned char *rgba);

#ifdef __cplusplus
}
#endif
#endif
