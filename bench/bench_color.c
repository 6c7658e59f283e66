/* Colour conversions of a 4K image (3840 x 2160, 3 bytes per pixel):
 * cg against OpenCV's cvtColor, both single-threaded, same buffers.
 *
 * Like with like: cg's 8-bit HSV stores the hue as round(256 h / 360) mod 256,
 * which is OpenCV's COLOR_RGB2HSV_FULL (plain COLOR_RGB2HSV stores h / 2 in
 * 0..180 and is shown for reference).  cg's 8-bit Lab is OpenCV's 8-bit
 * scaling (L * 255 / 100, a + 128, b + 128), with sRGB decoding in both.
 * sRGB decode is a table lookup in both (OpenCV: cv::LUT); OpenCV has no sRGB
 * encoder, so its side is the exact piecewise curve in array operations
 * (clamp, pow, compare, copyTo, convertTo).  Each row's note reports how
 * many output bytes differ between the two. */
#include "bench.h"
#include "cg.h"

#include <stdint.h>
#include <string.h>

#define WIDTH 3840
#define HEIGHT 2160
#define PIXELS ((size_t)WIDTH * HEIGHT)
#define DEFAULT_RUNS 9
static int RUNS = DEFAULT_RUNS; /* CG_BENCH_RUNS overrides (1 under callgrind) */

#ifdef CG_BENCH_OPENCV
void peer_init(void);
const char *peer_version(void);
void peer_rgb_to_hsv_full(const uint8_t *in, uint8_t *out, int width, int height);
void peer_hsv_full_to_rgb(const uint8_t *in, uint8_t *out, int width, int height);
void peer_rgb_to_hsv(const uint8_t *in, uint8_t *out, int width, int height);
void peer_rgb_to_lab(const uint8_t *in, uint8_t *out, int width, int height);
void peer_srgb_decode(const uint8_t *in, float *out, const float *table, int width, int height);
void peer_srgb_encode(const float *in, uint8_t *out, int width, int height);
#endif

typedef struct job {
    uint8_t *rgb, *hsv, *out8, *peer8;
    float *linear, *peer_f;
    float table[256];
} job;

static void cg_hsv(void *c)
{
    job *j = c;
    cg_rgb8_to_model8(CG_MODEL_HSV, j->rgb, j->out8, PIXELS, 3);
}
static void cg_hsv_back(void *c)
{
    job *j = c;
    cg_model8_to_rgb8(CG_MODEL_HSV, j->hsv, j->out8, PIXELS, 3);
}
static void cg_lab(void *c)
{
    job *j = c;
    cg_rgb8_to_model8(CG_MODEL_LAB, j->rgb, j->out8, PIXELS, 3);
}
static void cg_decode(void *c)
{
    job *j = c;
    cg_srgb8_decode(j->rgb, j->linear, PIXELS * 3);
}
static void cg_encode(void *c)
{
    job *j = c;
    cg_srgb8_encode(j->linear, j->out8, PIXELS * 3);
}

#ifdef CG_BENCH_OPENCV
/* Times a and b alternately, runs times each, so that a changing load on a
 * shared machine weighs on both alike; the medians go to *ta and *tb. */
static void paired(void (*a)(void *), void (*b)(void *), void *context, int runs, double *ta,
                   double *tb)
{
    double sa[64], sb[64];
    for (int i = 0; i < runs; i++) {
        double t0 = bench_now();
        a(context);
        double t1 = bench_now();
        b(context);
        double t2 = bench_now();
        sa[i] = t1 - t0;
        sb[i] = t2 - t1;
    }
    qsort(sa, (size_t)runs, sizeof sa[0], bench_compare);
    qsort(sb, (size_t)runs, sizeof sb[0], bench_compare);
    *ta = sa[runs / 2];
    *tb = sb[runs / 2];
}

static void cv_hsv(void *c)
{
    job *j = c;
    peer_rgb_to_hsv_full(j->rgb, j->peer8, WIDTH, HEIGHT);
}
static void cv_hsv180(void *c)
{
    job *j = c;
    peer_rgb_to_hsv(j->rgb, j->peer8, WIDTH, HEIGHT);
}
static void cv_hsv_back(void *c)
{
    job *j = c;
    peer_hsv_full_to_rgb(j->hsv, j->peer8, WIDTH, HEIGHT);
}
static void cv_lab(void *c)
{
    job *j = c;
    peer_rgb_to_lab(j->rgb, j->peer8, WIDTH, HEIGHT);
}
static void cv_decode(void *c)
{
    job *j = c;
    peer_srgb_decode(j->rgb, j->peer_f, j->table, WIDTH, HEIGHT);
}
static void cv_encode(void *c)
{
    job *j = c;
    peer_srgb_encode(j->linear, j->peer8, WIDTH, HEIGHT);
}

static void compare_bytes(const uint8_t *a, const uint8_t *b, size_t n, char *note, size_t size)
{
    size_t differ = 0;
    int worst = 0;
    for (size_t i = 0; i < n; i++) {
        int d = abs(a[i] - b[i]);
        differ += d != 0;
        worst = d > worst ? d : worst;
    }
    snprintf(note, size, "4K RGB8; %.3f%% of bytes differ from OpenCV, by at most %d",
             100.0 * (double)differ / (double)n, worst);
}

/* Hue bytes differ by 255 across the wrap: measure circularly for channel 0. */
static void compare_hsv(const uint8_t *a, const uint8_t *b, size_t pixels, char *note, size_t size)
{
    size_t differ = 0;
    int worst = 0;
    for (size_t i = 0; i < 3 * pixels; i++) {
        int d = abs(a[i] - b[i]);
        if (i % 3 == 0 && d > 128)
            d = 256 - d;
        differ += d != 0;
        worst = d > worst ? d : worst;
    }
    snprintf(note, size, "4K RGB8, hue 0..255; %.3f%% of bytes differ from OpenCV, by at most %d",
             100.0 * (double)differ / (double)(3 * pixels), worst);
}
#endif

int main(void)
{
    const char *runs = getenv("CG_BENCH_RUNS");
    if (runs && atoi(runs) >= 1 && atoi(runs) <= 63)
        RUNS = atoi(runs);
    job j;
    j.rgb = malloc(PIXELS * 3);
    j.hsv = malloc(PIXELS * 3);
    j.out8 = malloc(PIXELS * 3);
    j.peer8 = malloc(PIXELS * 3);
    j.linear = malloc(PIXELS * 3 * sizeof(float));
    j.peer_f = malloc(PIXELS * 3 * sizeof(float));
    if (!j.rgb || !j.hsv || !j.out8 || !j.peer8 || !j.linear || !j.peer_f)
        return 1;
    /* A photograph-like test card: smooth colour ramps, a sinusoidal
     * pattern and a little deterministic noise. */
    uint64_t state = 0x9e3779b97f4a7c15ULL;
    for (size_t y = 0; y < HEIGHT; y++)
        for (size_t x = 0; x < WIDTH; x++) {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            int noise = (int)(state % 9) - 4;
            double s = sin((double)x * 0.013) * cos((double)y * 0.021);
            int r = (int)(255.0 * x / WIDTH) + noise;
            int g = (int)(255.0 * y / HEIGHT) - noise;
            int b = (int)(127.5 + 120 * s) + noise;
            uint8_t *p = j.rgb + 3 * (y * WIDTH + x);
            p[0] = (uint8_t)(r < 0 ? 0 : r > 255 ? 255 : r);
            p[1] = (uint8_t)(g < 0 ? 0 : g > 255 ? 255 : g);
            p[2] = (uint8_t)(b < 0 ? 0 : b > 255 ? 255 : b);
        }
    cg_rgb8_to_model8(CG_MODEL_HSV, j.rgb, j.hsv, PIXELS, 3);
    for (int k = 0; k < 256; k++)
        j.table[k] = cg_srgb8_to_linear((uint8_t)k);
    cg_srgb8_decode(j.rgb, j.linear, PIXELS * 3);

#ifdef CG_BENCH_OPENCV
    peer_init();
    char peer[64], note[160];
    snprintf(peer, sizeof peer, "OpenCV %s", peer_version());
    double t_cg, t_cv;

    paired(cg_hsv, cv_hsv, &j, RUNS, &t_cg, &t_cv);
    compare_hsv(j.out8, j.peer8, PIXELS, note, sizeof note);
    bench_row("RGB8 -> HSV8 4K (hue 0..255, RGB2HSV_FULL)", t_cg, peer, t_cv, note);
    paired(cg_hsv, cv_hsv180, &j, RUNS, &t_cg, &t_cv);
    bench_row("RGB8 -> HSV8 4K vs RGB2HSV (hue 0..180)", t_cg, peer, t_cv,
              "OpenCV's default hue scale; cg stores 0..255");

    paired(cg_hsv_back, cv_hsv_back, &j, RUNS, &t_cg, &t_cv);
    compare_bytes(j.out8, j.peer8, PIXELS * 3, note, sizeof note);
    bench_row("HSV8 -> RGB8 4K (HSV2RGB_FULL)", t_cg, peer, t_cv, note);

    paired(cg_lab, cv_lab, &j, RUNS, &t_cg, &t_cv);
    compare_bytes(j.out8, j.peer8, PIXELS * 3, note, sizeof note);
    bench_row("RGB8 -> Lab8 4K (sRGB, D65)", t_cg, peer, t_cv, note);

    paired(cg_decode, cv_decode, &j, RUNS, &t_cg, &t_cv);
    bench_row("sRGB decode 4K RGB8 -> float", t_cg, peer, t_cv,
              memcmp(j.linear, j.peer_f, PIXELS * 3 * sizeof(float)) == 0
                  ? "OpenCV cv::LUT with the same table; identical output"
                  : "OpenCV cv::LUT; OUTPUT DIFFERS");

    paired(cg_encode, cv_encode, &j, RUNS, &t_cg, &t_cv);
    compare_bytes(j.out8, j.peer8, PIXELS * 3, note, sizeof note);
    bench_row("sRGB encode 4K float -> RGB8", t_cg, peer, t_cv, note);
#else
    bench_row("RGB8 -> HSV8 4K", bench_median(cg_hsv, &j, RUNS), "-", 0, "OpenCV not installed");
    bench_row("HSV8 -> RGB8 4K", bench_median(cg_hsv_back, &j, RUNS), "-", 0,
              "OpenCV not installed");
    bench_row("RGB8 -> Lab8 4K", bench_median(cg_lab, &j, RUNS), "-", 0, "OpenCV not installed");
    bench_row("sRGB decode 4K", bench_median(cg_decode, &j, RUNS), "-", 0, "OpenCV not installed");
    bench_row("sRGB encode 4K", bench_median(cg_encode, &j, RUNS), "-", 0, "OpenCV not installed");
#endif
    free(j.rgb);
    free(j.hsv);
    free(j.out8);
    free(j.peer8);
    free(j.linear);
    free(j.peer_f);
    return 0;
}
