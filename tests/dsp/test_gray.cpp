// RGB -> gray (dsp/gray_convert.h) against cv::cvtColor(COLOR_RGB2GRAY): every
// one of the 2^24 colours, a real image, and the row function.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "dsp/gray_convert.h"
#include "tests/support/data_path.h"

namespace {

dsp::rgb_cplane as_rgb_plane(const cv::Mat& m) {
    static_assert(sizeof(dsp::rgb8) == 3, "rgb8 must alias an 8UC3 pixel");
    return dsp::rgb_cplane{reinterpret_cast<const dsp::rgb8*>(m.data), m.cols, m.rows,
                           static_cast<int>(m.step / 3)};
}

cv::Mat gray_ours(const cv::Mat& rgb) {
    cv::Mat out(rgb.size(), CV_8UC1, cv::Scalar::all(0));
    dsp::rgb_to_gray(as_rgb_plane(rgb),
                     dsp::gray_plane{out.data, out.cols, out.rows, static_cast<int>(out.step1())});
    return out;
}

struct difference {
    int max_abs = 0;
    long differing = 0;
};

difference compare(const cv::Mat& a, const cv::Mat& b) {
    cv::Mat diff;
    cv::absdiff(a, b, diff);
    double max_abs = 0;
    cv::minMaxLoc(diff, nullptr, &max_abs);
    return difference{static_cast<int>(max_abs), static_cast<long>(cv::countNonZero(diff))};
}

// 4096 x 4096 pixels: pixel i has colour R = i >> 16, G = (i >> 8) & 255, B = i & 255.
cv::Mat all_colours() {
    cv::Mat rgb(4096, 4096, CV_8UC3);
    auto* p = rgb.ptr<uint8_t>();
    for (uint32_t i = 0; i < (1u << 24); ++i) {
        p[3 * i + 0] = static_cast<uint8_t>(i >> 16);
        p[3 * i + 1] = static_cast<uint8_t>(i >> 8);
        p[3 * i + 2] = static_cast<uint8_t>(i);
    }
    return rgb;
}

TEST(Gray, EqualsOpenCvOnAllColours) {
    const cv::Mat rgb = all_colours();
    cv::Mat reference;
    cv::cvtColor(rgb, reference, cv::COLOR_RGB2GRAY);
    const cv::Mat ours = gray_ours(rgb);
    const difference d = compare(ours, reference);
    std::printf("all 2^24 colours: max |ours - cvtColor| = %d, %ld colours differ\n", d.max_abs,
                d.differing);
    EXPECT_LE(d.max_abs, 1);
    EXPECT_EQ(d.differing, 0);  // same Q15 weights and rounding as OpenCV 4.x: exact

    // Against the paper's real-valued formula: the Q14 weights stay within rounding.
    int max_vs_real = 0;
    const auto* p = rgb.ptr<uint8_t>();
    for (uint32_t i = 0; i < (1u << 24); i += 7) {  // a 1-in-7 sample of all colours
        const double y = 0.299 * p[3 * i] + 0.587 * p[3 * i + 1] + 0.114 * p[3 * i + 2];
        max_vs_real =
            std::max(max_vs_real, std::abs(ours.data[i] - static_cast<int>(std::lround(y))));
    }
    std::printf("vs round(0.299 R + 0.587 G + 0.114 B): max diff %d\n", max_vs_real);
    EXPECT_LE(max_vs_real, 1);
}

TEST(Gray, EqualsOpenCvOnRealImage) {
    for (const char* name :
         {"kodak_demosaic_gt/kodim23.png", "opencv_vtest/frames/vtest_0000.png"}) {
        const cv::Mat bgr = cv::imread(test_support::data_path(name), cv::IMREAD_COLOR);
        ASSERT_FALSE(bgr.empty()) << name;
        cv::Mat rgb;
        cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
        cv::Mat reference;
        cv::cvtColor(rgb, reference, cv::COLOR_RGB2GRAY);
        const difference d = compare(gray_ours(rgb), reference);
        std::printf("%s %dx%d: max |ours - cvtColor| = %d, %ld pixels differ\n", name, rgb.cols,
                    rgb.rows, d.max_abs, d.differing);
        EXPECT_LE(d.max_abs, 1) << name;
        EXPECT_EQ(d.differing, 0) << name;
    }
}

TEST(Gray, EqualsOpenCvOnRandomDataWithStride) {
    cv::Mat big(200, 300, CV_8UC3);
    cv::RNG(7).fill(big, cv::RNG::UNIFORM, 0, 256);
    const cv::Mat rgb = big(cv::Rect(13, 9, 257, 170));  // odd width, stride wider than width
    cv::Mat reference;
    cv::cvtColor(rgb, reference, cv::COLOR_RGB2GRAY);
    const difference d = compare(gray_ours(rgb), reference);
    std::printf("random 257x170 (strided): max diff %d, %ld differ\n", d.max_abs, d.differing);
    EXPECT_EQ(d.max_abs, 0);
}

TEST(Gray, RowFunctionAndClosedFormValues) {
    // Closed form: round(255 * w) for each primary, and the extremes.
    EXPECT_EQ(dsp::gray_of({255, 0, 0}), 76);   // 255 * 0.299 = 76.2
    EXPECT_EQ(dsp::gray_of({0, 255, 0}), 150);  // 255 * 0.587 = 149.7
    EXPECT_EQ(dsp::gray_of({0, 0, 255}), 29);   // 255 * 0.114 = 29.1
    EXPECT_EQ(dsp::gray_of({255, 255, 255}), 255);
    EXPECT_EQ(dsp::gray_of({0, 0, 0}), 0);

    cv::Mat rgb(1, 640, CV_8UC3);
    cv::RNG(11).fill(rgb, cv::RNG::UNIFORM, 0, 256);
    cv::Mat reference;
    cv::cvtColor(rgb, reference, cv::COLOR_RGB2GRAY);
    std::vector<uint8_t> row(640, 0);
    dsp::rgb_row_to_gray(reinterpret_cast<const dsp::rgb8*>(rgb.data), 640, row.data());
    const cv::Mat ours(1, 640, CV_8UC1, row.data());
    EXPECT_EQ(compare(ours, reference).max_abs, 0);
}

}  // namespace
