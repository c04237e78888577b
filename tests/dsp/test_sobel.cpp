// Sobel magnitude (dsp/sobel.h) against OpenCV: dx and dy from
// cv::Sobel(CV_16S, ksize 3), reference = saturate(|dx| + |dy|), exact on
// interior pixels; the border is 0; the band function equals the whole.
#include <gtest/gtest.h>

#include <cstdio>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "dsp/sobel.h"
#include "tests/support/data_path.h"

namespace {

dsp::gray_plane as_plane(cv::Mat& m) {
    return dsp::gray_plane{m.ptr<uint8_t>(), m.cols, m.rows, static_cast<int>(m.step1())};
}
dsp::gray_cplane as_cplane(const cv::Mat& m) {
    return dsp::gray_cplane{m.ptr<uint8_t>(), m.cols, m.rows, static_cast<int>(m.step1())};
}

cv::Mat opencv_magnitude(const cv::Mat& gray) {
    cv::Mat dx, dy;
    cv::Sobel(gray, dx, CV_16S, 1, 0, 3);
    cv::Sobel(gray, dy, CV_16S, 0, 1, 3);
    const cv::Mat sum16 = cv::abs(dx) + cv::abs(dy);  // |dx| + |dy| <= 2040 fits CV_16S
    cv::Mat out;
    sum16.convertTo(out, CV_8U);  // saturating
    return out;
}

cv::Mat sobel_ours(const cv::Mat& gray, uint8_t fill = 0) {
    cv::Mat out(gray.size(), CV_8UC1, cv::Scalar(fill));
    dsp::sobel_3x3(as_cplane(gray), as_plane(out));
    return out;
}

struct interior_stats {
    long differing = 0;
    long edges = 0;      // interior pixels with a non-zero magnitude
    long saturated = 0;  // interior pixels at 255
};

interior_stats compare_interior(const cv::Mat& ours, const cv::Mat& reference) {
    const cv::Rect inner(1, 1, ours.cols - 2, ours.rows - 2);
    interior_stats s;
    s.differing = cv::countNonZero(ours(inner) != reference(inner));
    s.edges = cv::countNonZero(ours(inner));
    s.saturated = cv::countNonZero(ours(inner) == 255);
    return s;
}

long border_nonzero(const cv::Mat& m) {
    const int w = m.cols, h = m.rows;
    return cv::countNonZero(m.row(0)) + cv::countNonZero(m.row(h - 1)) +
           cv::countNonZero(m.col(0)) + cv::countNonZero(m.col(w - 1));
}

TEST(Sobel, EqualsOpenCvOnRealImages) {
    for (const char* name : {"opencv_vtest/frames_gray/vtest_gray_0000.png",
                             "opencv_stereo_calib_chessboard/left01.jpg"}) {
        const cv::Mat gray = cv::imread(test_support::data_path(name), cv::IMREAD_GRAYSCALE);
        ASSERT_FALSE(gray.empty()) << name;
        const cv::Mat ours = sobel_ours(gray, 99);  // pre-filled: every pixel must be written
        const interior_stats s = compare_interior(ours, opencv_magnitude(gray));
        std::printf(
            "%s %dx%d: %ld interior pixels differ from OpenCV; %ld edge pixels, %ld "
            "saturated; border non-zero %ld\n",
            name, gray.cols, gray.rows, s.differing, s.edges, s.saturated, border_nonzero(ours));
        EXPECT_EQ(s.differing, 0) << name;
        EXPECT_EQ(border_nonzero(ours), 0) << name;
        EXPECT_GT(s.edges, gray.total() / 4) << name;  // a real image has texture everywhere
    }
}

TEST(Sobel, EqualsOpenCvOnRandomNoiseWithSaturation) {
    for (const cv::Size size :
         {cv::Size(3, 3), cv::Size(5, 4), cv::Size(97, 61), cv::Size(640, 480)}) {
        cv::Mat gray(size, CV_8UC1);
        cv::RNG(static_cast<uint64_t>(size.area())).fill(gray, cv::RNG::UNIFORM, 0, 256);
        const cv::Mat ours = sobel_ours(gray, 99);
        const interior_stats s = compare_interior(ours, opencv_magnitude(gray));
        std::printf("noise %dx%d: %ld differ, %ld of %d interior saturated\n", size.width,
                    size.height, s.differing, s.saturated, (size.width - 2) * (size.height - 2));
        EXPECT_EQ(s.differing, 0) << size;
        EXPECT_EQ(border_nonzero(ours), 0) << size;
        if (size.area() > 1000) {
            EXPECT_GT(s.saturated, 0) << size;  // the clamp is exercised
        }
    }
}

// Closed form on a vertical step edge of height 100: |V| = 4 * 100 saturates
// to 255 on the two columns beside the step, H = 0, and flat areas give 0.
TEST(Sobel, ClosedFormStepEdge) {
    cv::Mat gray(8, 10, CV_8UC1, cv::Scalar(20));
    gray.colRange(5, 10).setTo(120);
    const cv::Mat ours = sobel_ours(gray);
    for (int y = 1; y < 7; ++y) {
        for (int x = 1; x < 9; ++x) {
            const int expected = (x == 4 || x == 5) ? 255 : 0;
            EXPECT_EQ(ours.at<uint8_t>(y, x), expected) << x << "," << y;
        }
    }
    // A gentler step of 30: 4 * 30 = 120, below saturation.
    gray.colRange(5, 10).setTo(50);
    EXPECT_EQ(sobel_ours(gray).at<uint8_t>(3, 4), 120);
}

TEST(Sobel, BandEqualsWholeOnItsRowsAndLeavesOtherRowsAlone) {
    const cv::Mat gray =
        cv::imread(test_support::data_path("opencv_vtest/frames_gray/vtest_gray_0001.png"),
                   cv::IMREAD_GRAYSCALE);
    ASSERT_FALSE(gray.empty());
    const cv::Mat whole = sobel_ours(gray);
    struct band {
        int y0, y1;
    };
    // An interior band, bands clipped at the top and bottom, and an empty band.
    for (const band b :
         {band{200, 240}, band{-5, 3}, band{gray.rows - 2, gray.rows + 4}, band{50, 50}}) {
        cv::Mat out(gray.size(), CV_8UC1, cv::Scalar(77));
        dsp::sobel_3x3_rows(as_cplane(gray), b.y0, b.y1, as_plane(out));
        const int lo = std::max(b.y0, 0);
        const int hi = std::min(b.y1, gray.rows);
        long band_diff = 0;
        long outside_touched = 0;
        for (int y = 0; y < gray.rows; ++y) {
            if (y >= lo && y < hi) {
                band_diff += cv::countNonZero(out.row(y) != whole.row(y));
            } else {
                outside_touched += cv::countNonZero(out.row(y) != 77);
            }
        }
        EXPECT_EQ(band_diff, 0) << "band " << b.y0 << ".." << b.y1;
        EXPECT_EQ(outside_touched, 0) << "band " << b.y0 << ".." << b.y1;
    }
}

}  // namespace
