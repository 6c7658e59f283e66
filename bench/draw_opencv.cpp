// OpenCV peer of bench_draw: cv::line and cv::circle on a CV_8UC4 image.
#include "draw_opencv.h"

#include <opencv2/imgproc.hpp>

extern "C" {

void *ocv_create(int width, int height)
{
    return new cv::Mat(height, width, CV_8UC4, cv::Scalar(0, 0, 0, 255));
}

void ocv_free(void *image)
{
    delete static_cast<cv::Mat *>(image);
}

void ocv_clear(void *image)
{
    static_cast<cv::Mat *>(image)->setTo(cv::Scalar(0, 0, 0, 255));
}

const unsigned char *ocv_pixels(void *image)
{
    return static_cast<cv::Mat *>(image)->data;
}

void ocv_lines(void *image, const int *xy, int n)
{
    cv::Mat &m = *static_cast<cv::Mat *>(image);
    const cv::Scalar color(40, 180, 250, 255);
    for (int i = 0; i < n; i++, xy += 4)
        cv::line(m, cv::Point(xy[0], xy[1]), cv::Point(xy[2], xy[3]), color, 1, cv::LINE_8);
}

void ocv_lines_aa(void *image, const int *xy, int n)
{
    cv::Mat &m = *static_cast<cv::Mat *>(image);
    const cv::Scalar color(40, 180, 250, 255);
    for (int i = 0; i < n; i++, xy += 4)
        cv::line(m, cv::Point(xy[0], xy[1]), cv::Point(xy[2], xy[3]), color, 1, cv::LINE_AA, 4);
}

void ocv_circles(void *image, const int *cxr, int n, int mode)
{
    cv::Mat &m = *static_cast<cv::Mat *>(image);
    const cv::Scalar color(40, 180, 250, 255);
    for (int i = 0; i < n; i++, cxr += 3)
        cv::circle(m, cv::Point(cxr[0], cxr[1]), cxr[2], color, mode == 2 ? cv::FILLED : 1,
                   mode == 1 ? cv::LINE_AA : cv::LINE_8);
}

}
