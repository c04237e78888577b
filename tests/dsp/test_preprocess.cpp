// Brightness compensation and the fused pre-processing (dsp/preprocess.h):
// the gain formula on constructed inputs, the LUT against the plain formula,
// a real global lighting step cancelled, and the fused path equal to the
// separate kernels run one after the other.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "dsp/bayer_demosaic.h"
#include "dsp/gray_convert.h"
#include "dsp/preprocess.h"
#include "tests/support/data_path.h"

namespace {

using dsp::brightness_params;

dsp::gray_plane as_plane(cv::Mat& m) {
    return dsp::gray_plane{m.ptr<uint8_t>(), m.cols, m.rows, static_cast<int>(m.step1())};
}
dsp::gray_cplane as_cplane(const cv::Mat& m) {
    return dsp::gray_cplane{m.ptr<uint8_t>(), m.cols, m.rows, static_cast<int>(m.step1())};
}

// RGGB mosaic of an RGB image.
cv::Mat mosaic_rggb(const cv::Mat& rgb) {
    cv::Mat raw(rgb.size(), CV_8UC1);
    for (int y = 0; y < rgb.rows; ++y) {
        for (int x = 0; x < rgb.cols; ++x) {
            const int channel = (y % 2 == 0) ? (x % 2 == 0 ? 0 : 1) : (x % 2 == 0 ? 1 : 2);
            raw.at<uint8_t>(y, x) = rgb.at<cv::Vec3b>(y, x)[channel];
        }
    }
    return raw;
}

cv::Mat load_rgb(const char* name) {
    cv::Mat bgr = cv::imread(test_support::data_path(name), cv::IMREAD_COLOR);
    cv::Mat rgb;
    if (!bgr.empty()) cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
    return rgb;
}

uint64_t sum_of(const cv::Mat& gray) {
    return static_cast<uint64_t>(cv::sum(gray)[0]);
}

double mean_abs_difference(const cv::Mat& a, const cv::Mat& b) {
    cv::Mat diff;
    cv::absdiff(a, b, diff);
    return cv::mean(diff)[0];
}

// Gain and compensation the way preprocess.h documents them, for a gray frame.
cv::Mat compensate(const cv::Mat& gray, const brightness_params& params, uint16_t* gain = nullptr) {
    cv::Mat out = gray.clone();
    const uint16_t g =
        dsp::brightness_gain_q8(sum_of(gray), static_cast<uint32_t>(gray.total()), params);
    dsp::apply_gain(as_plane(out), g);
    if (gain) *gain = g;
    return out;
}

TEST(Preprocess, GainFormulaOnConstructedInputs) {
    const brightness_params defaults;  // target 110, gain in [64, 1024]
    const uint32_t n = 640 * 480;
    // Uniform frames: the gain is exactly 256 * target / level.
    EXPECT_EQ(dsp::brightness_gain_q8(55ull * n, n, defaults), 512);
    EXPECT_EQ(dsp::brightness_gain_q8(110ull * n, n, defaults), 256);
    EXPECT_EQ(dsp::brightness_gain_q8(220ull * n, n, defaults), 128);
    // Rounding to nearest: 256 * 110 / 200 = 140.8 -> 141.
    EXPECT_EQ(dsp::brightness_gain_q8(200ull * n, n, defaults), 141);
    // 256 * 110 / 96 = 293.33 -> 293; 256 * 110 / 100.5 = 280.199 -> 280.
    EXPECT_EQ(dsp::brightness_gain_q8(96ull * n, n, defaults), 293);
    EXPECT_EQ(dsp::brightness_gain_q8(201ull * n / 2, n, defaults), 280);
    // Clamps: too dark -> 4x, too bright for a low target -> 0.25x, black -> 4x.
    EXPECT_EQ(dsp::brightness_gain_q8(10ull * n, n, defaults), 1024);
    brightness_params dim = defaults;
    dim.target_mean = 10;
    EXPECT_EQ(dsp::brightness_gain_q8(250ull * n, n, dim), 64);
    EXPECT_EQ(dsp::brightness_gain_q8(0, n, defaults), 1024);
    // Disabled or empty: unity.
    brightness_params off = defaults;
    off.enabled = false;
    EXPECT_EQ(dsp::brightness_gain_q8(10ull * n, n, off), 256);
    EXPECT_EQ(dsp::brightness_gain_q8(1000, 0, defaults), 256);

    // Non-uniform sums against round(256 * target / (sum / count)) in long
    // double.
    cv::RNG rng(3);
    brightness_params wide = defaults;
    wide.min_gain_q8 = 1;
    wide.max_gain_q8 = 65535;
    int checked = 0;
    for (int i = 0; i < 20000; ++i) {
        const uint32_t count = 1 + rng.uniform(0, 1920 * 1080);
        wide.target_mean = static_cast<uint8_t>(rng.uniform(1, 256));
        const uint64_t sum = 1 + static_cast<uint64_t>(rng.uniform(0.0, 1.0) * 255.0 * count);
        const long double exact =
            256.0L * wide.target_mean / (static_cast<long double>(sum) / count);
        if (exact > 65535.0L) continue;
        const auto expected = static_cast<long>(std::floor(exact + 0.5L));
        ASSERT_EQ(dsp::brightness_gain_q8(sum, count, wide), expected)
            << "sum " << sum << " count " << count << " target " << int(wide.target_mean);
        ++checked;
    }
    std::printf(
        "gain formula: %d random (sum, count, target) cases equal "
        "round(256 t / mean)\n",
        checked);
    EXPECT_GT(checked, 10000);
}

TEST(Preprocess, ApplyGainMatchesFormulaAndSaturates) {
    cv::Mat ramp(1, 256, CV_8UC1);
    for (int p = 0; p < 256; ++p) ramp.at<uint8_t>(0, p) = static_cast<uint8_t>(p);
    for (int gain : {64, 141, 255, 256, 257, 366, 512, 1024}) {
        cv::Mat image = ramp.clone();
        dsp::apply_gain(as_plane(image), static_cast<uint16_t>(gain));
        int saturated = 0;
        for (int p = 0; p < 256; ++p) {
            const int expected = std::min(255, (p * gain + 128) >> 8);
            ASSERT_EQ(image.at<uint8_t>(0, p), expected) << "p " << p << " gain " << gain;
            saturated += image.at<uint8_t>(0, p) == 255;
        }
        // Outputs reach 255 when p * gain + 128 >= 255 * 256, i.e. p >= ceil(65152
        // / gain).
        const int first_saturated = std::min(256, (65152 + gain - 1) / gain);
        EXPECT_EQ(saturated, 256 - first_saturated) << "gain " << gain;
    }
    // Saturation, not wrap-around: 255 doubled stays 255, 128 doubled is 255 (not
    // 0).
    cv::Mat bright(2, 2, CV_8UC1, cv::Scalar(255));
    bright.at<uint8_t>(1, 1) = 128;
    dsp::apply_gain(as_plane(bright), 512);
    EXPECT_EQ(cv::countNonZero(bright == 255), 4);
}

// A real frame and the same frame under 0.7x the light: after compensation
// the two agree to within rounding; without it they differ by ~30% of the mean.
TEST(Preprocess, GlobalLightingStepIsCompensatedOnRealGrayFrame) {
    const cv::Mat frame =
        cv::imread(test_support::data_path("opencv_vtest/frames_gray/vtest_gray_0000.png"),
                   cv::IMREAD_GRAYSCALE);
    ASSERT_FALSE(frame.empty());
    cv::Mat darker;
    frame.convertTo(darker, CV_8U, 0.7);  // rounds to nearest
    const brightness_params params;
    uint16_t gain_frame = 0;
    uint16_t gain_darker = 0;
    const cv::Mat a = compensate(frame, params, &gain_frame);
    const cv::Mat b = compensate(darker, params, &gain_darker);
    const double before = mean_abs_difference(frame, darker);
    const double after = mean_abs_difference(a, b);
    std::printf(
        "vtest gray 768x576, mean %.1f, x0.7 lighting step: mean "
        "|difference| %.2f grey "
        "levels uncompensated, %.3f compensated (gains %d, %d /256)\n",
        cv::mean(frame)[0], before, after, gain_frame, gain_darker);
    // Bound: input rounding (<= 0.5) amplified by 1/0.7, plus the two outputs'
    // rounding, is at most ~1.7 per pixel and far less on average.
    EXPECT_LT(after, 2.0);
    EXPECT_GT(before, 10.0);
}

// Same step through the whole fused pipeline: a real colour frame mosaicked,
// its raw scaled by 0.7 (the sensor sees less light).
TEST(Preprocess, GlobalLightingStepIsCompensatedThroughFusedPipeline) {
    const cv::Mat rgb = load_rgb("opencv_vtest/frames/vtest_0000.png");
    ASSERT_FALSE(rgb.empty());
    const cv::Mat raw = mosaic_rggb(rgb);
    cv::Mat raw_darker;
    raw.convertTo(raw_darker, CV_8U, 0.7);
    std::vector<dsp::rgb8> line(static_cast<size_t>(raw.cols));

    auto run = [&](const cv::Mat& in, const brightness_params& params, dsp::preprocess_result* r) {
        cv::Mat out(in.size(), CV_8UC1, cv::Scalar(0));
        *r = dsp::preprocess_raw_to_gray(as_cplane(in), dsp::cfa_order::rggb, params, line.data(),
                                         as_plane(out));
        return out;
    };
    brightness_params on;
    brightness_params off;
    off.enabled = false;
    dsp::preprocess_result r1, r2, r3, r4;
    const double after = mean_abs_difference(run(raw, on, &r1), run(raw_darker, on, &r2));
    const double before = mean_abs_difference(run(raw, off, &r3), run(raw_darker, off, &r4));
    std::printf(
        "vtest RGB -> RGGB raw, x0.7 step, fused preprocess: mean |difference| "
        "%.2f "
        "without compensation, %.3f with (means %u -> %u, gains %d, %d)\n",
        before, after, r1.mean_before, r2.mean_before, r1.gain_q8, r2.gain_q8);
    EXPECT_LT(after, 2.0);
    EXPECT_GT(before, 10.0);
    EXPECT_EQ(r3.gain_q8, 256);
    EXPECT_NE(r1.gain_q8, r2.gain_q8);
}

// The fused path against demosaic_bilinear -> rgb_to_gray -> gain ->
// apply_gain.
TEST(Preprocess, FusedEqualsSeparateKernelsExactly) {
    const cv::Mat kodak = load_rgb("kodak_demosaic_gt/kodim19.png");
    ASSERT_FALSE(kodak.empty());
    cv::Mat noise(120, 160, CV_8UC1);
    cv::RNG(5).fill(noise, cv::RNG::UNIFORM, 0, 256);
    cv::Mat dark_noise(64, 80, CV_8UC1);
    cv::RNG(6).fill(dark_noise, cv::RNG::UNIFORM, 0, 40);

    brightness_params defaults;
    brightness_params off;
    off.enabled = false;
    brightness_params bright;  // saturates many pixels
    bright.target_mean = 230;

    int cases = 0;
    for (const cv::Mat& raw : {mosaic_rggb(kodak), noise, dark_noise}) {
        for (dsp::cfa_order order : {dsp::cfa_order::rggb, dsp::cfa_order::gbrg}) {
            for (const brightness_params& params : {defaults, off, bright}) {
                // Separate: full RGB frame, full gray frame, then the gain.
                cv::Mat rgb(raw.size(), CV_8UC3);
                dsp::rgb_plane rgb_plane{reinterpret_cast<dsp::rgb8*>(rgb.data), rgb.cols, rgb.rows,
                                         static_cast<int>(rgb.step / 3)};
                dsp::demosaic_bilinear(as_cplane(raw), order, rgb_plane);
                cv::Mat separate(raw.size(), CV_8UC1);
                dsp::rgb_to_gray(rgb_plane.as_const(), as_plane(separate));
                const uint64_t sum = sum_of(separate);
                const auto count = static_cast<uint32_t>(raw.total());
                const uint16_t gain = dsp::brightness_gain_q8(sum, count, params);
                dsp::apply_gain(as_plane(separate), gain);

                cv::Mat fused(raw.size(), CV_8UC1, cv::Scalar(0));
                std::vector<dsp::rgb8> line(static_cast<size_t>(raw.cols));
                const dsp::preprocess_result r = dsp::preprocess_raw_to_gray(
                    as_cplane(raw), order, params, line.data(), as_plane(fused));

                EXPECT_EQ(cv::countNonZero(fused != separate), 0) << raw.size();
                EXPECT_EQ(r.gain_q8, gain);
                EXPECT_EQ(r.mean_before, (sum + count / 2) / count);
                ++cases;
            }
        }
    }
    EXPECT_EQ(cases, 18);
}

// Sizes outside the documented assumptions: nothing is written, the result is
// the default.
TEST(Preprocess, RejectsSizesOutsideItsAssumptions) {
    std::vector<dsp::rgb8> line(64);
    const brightness_params params;
    for (const cv::Size size : {cv::Size(7, 6), cv::Size(8, 5), cv::Size(2, 2)}) {
        cv::Mat raw(size, CV_8UC1, cv::Scalar(50));
        cv::Mat out(size, CV_8UC1, cv::Scalar(33));
        const dsp::preprocess_result r = dsp::preprocess_raw_to_gray(
            as_cplane(raw), dsp::cfa_order::rggb, params, line.data(), as_plane(out));
        EXPECT_EQ(r.gain_q8, 256) << size;
        EXPECT_EQ(r.mean_before, 0u) << size;
        EXPECT_EQ(cv::countNonZero(out != 33), 0) << size;
    }
    // Output of another size than the raw frame.
    cv::Mat raw(8, 8, CV_8UC1, cv::Scalar(50));
    cv::Mat out(8, 10, CV_8UC1, cv::Scalar(33));
    dsp::preprocess_raw_to_gray(as_cplane(raw), dsp::cfa_order::rggb, params, line.data(),
                                as_plane(out));
    EXPECT_EQ(cv::countNonZero(out != 33), 0);
}

}  // namespace
