/* The OpenCV side of bench_draw (draw_opencv.cpp), callable from C. */
#ifndef CG_BENCH_DRAW_OPENCV_H
#define CG_BENCH_DRAW_OPENCV_H

#ifdef __cplusplus
extern "C" {
#endif

/* An 8-bit 4-channel image of the given size, and its pixels. */
void *ocv_create(int width, int height);
void ocv_free(void *image);
void ocv_clear(void *image);
const unsigned char *ocv_pixels(void *image);
/* n lines x0 y0 x1 y1 (pixel indices), 8-connected. */
void ocv_lines(void *image, const int *xy, int n);
/* n anti-aliased lines with endpoints in fixed point (4 fractional bits). */
void ocv_lines_aa(void *image, const int *xy, int n);
/* n circles cx cy r: 8-connected outline, anti-aliased outline, or filled. */
void ocv_circles(void *image, const int *cxr, int n, int mode);

#ifdef __cplusplus
}
#endif
#endif
