// The OpenCV side of bench_color: cvtColor and friends on caller-owned
// buffers (wrapped, not copied), single-threaded.
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include <cstdint>

extern "C" {

void peer_init(void)
{
    cv::setNumThreads(1);
}

const char *peer_version(void)
{
    return CV_VERSION;
}

void peer_rgb_to_hsv_full(const uint8_t *in, uint8_t *out, int width, int height)
{
    cv::Mat src(height, width, CV_8UC3, const_cast<uint8_t *>(in)), dst(height, width, CV_8UC3, out);
    cv::cvtColor(src, dst, cv::COLOR_RGB2HSV_FULL);
}

void peer_hsv_full_to_rgb(const uint8_t *in, uint8_t *out, int width, int height)
{
    cv::Mat src(height, width, CV_8UC3, const_cast<uint8_t *>(in)), dst(height, width, CV_8UC3, out);
    cv::cvtColor(src, dst, cv::COLOR_HSV2RGB_FULL);
}

void peer_rgb_to_hsv(const uint8_t *in, uint8_t *out, int width, int height)
{
    cv::Mat src(height, width, CV_8UC3, const_cast<uint8_t *>(in)), dst(height, width, CV_8UC3, out);
    cv::cvtColor(src, dst, cv::COLOR_RGB2HSV);
}

void peer_rgb_to_lab(const uint8_t *in, uint8_t *out, int width, int height)
{
    cv::Mat src(height, width, CV_8UC3, const_cast<uint8_t *>(in)), dst(height, width, CV_8UC3, out);
    cv::cvtColor(src, dst, cv::COLOR_RGB2Lab);
}

// sRGB decode of 8-bit codes to float by a 256-entry table (cv::LUT).
void peer_srgb_decode(const uint8_t *in, float *out, const float *table, int width, int height)
{
    cv::Mat src(height, width, CV_8UC3, const_cast<uint8_t *>(in)), dst(height, width, CV_32FC3, out);
    cv::Mat lut(1, 256, CV_32FC1, const_cast<float *>(table));
    cv::LUT(src, lut, dst);
}

// sRGB encode of float linear light to 8 bits, the exact piecewise curve
// written with OpenCV's array operations.
void peer_srgb_encode(const float *in, uint8_t *out, int width, int height)
{
    cv::Mat src(height, width, CV_32FC3, const_cast<float *>(in)), dst(height, width, CV_8UC3, out);
    cv::Mat clamped, curve, low, mask;
    cv::min(cv::max(src, 0.0), 1.0, clamped);
    cv::pow(clamped, 1.0 / 2.4, curve);
    curve = curve * 1.055 - 0.055;
    low = clamped * 12.92;
    cv::compare(clamped, 0.0031308, mask, cv::CMP_LE);
    low.copyTo(curve, mask);
    curve.convertTo(dst, CV_8U, 255.0);
}
}
