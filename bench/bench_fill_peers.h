/* Peer libraries called by bench_fill.c: AGG and OpenCV (C++), behind a C
 * interface.  Each returns 0 when the peer is not built in. */
#ifndef CG_BENCH_FILL_PEERS_H
#define CG_BENCH_FILL_PEERS_H

#ifdef __cplusplus
extern "C" {
#endif

/* A shape: contours of points (x, y pairs) with the number of points of each. */
typedef struct bench_shape {
    const double *xy;
    const int *sizes;
    int contours;
} bench_shape;

/* A path of verbs 'M' (one point), 'L' (one), 'C' (three: a cubic Bezier)
 * and 'Z'; points as x, y pairs in order. */
typedef struct bench_curve_path {
    const char *verbs;
    const double *xy;
} bench_curve_path;

/* Fills the curved paths (even-odd, anti-aliased) with AGG's own curve
 * flattening (conv_curve). */
int peer_agg_fill_curves(unsigned char *pixels, int width, int height, int stride,
                         const bench_curve_path *paths, int count, const unsigned char rgba[4]);

/* Fills the shapes into an RGBA 8-bit buffer with an opaque colour. */
int peer_agg_fill(unsigned char *pixels, int width, int height, int stride,
                  const bench_shape *shapes, int count, int even_odd, int antialias,
                  const unsigned char rgba[4]);
int peer_opencv_fill(unsigned char *pixels, int width, int height, int stride,
                     const bench_shape *shapes, int count, int antialias,
                     const unsigned char rgba[4]);
/* Flood fill of a 3-channel 8-bit buffer from (x, y) with connectivity 4
 * or 8 (exact colour match); rgba[3] is ignored. */
int peer_opencv_flood(unsigned char *pixels, int width, int height, int stride, int x, int y,
                      int connectivity, const unsigned char rgba[4]);

#ifdef __cplusplus
}
#endif
#endif
