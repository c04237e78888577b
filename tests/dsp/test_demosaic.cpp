// Bayer bilinear demosaic (dsp/bayer_demosaic.h) against two independent
// references: OpenCV's cv::demosaicing (bilinear) on interior pixels, and a
// brute-force "mean of the same-colour samples in the 3x3 window" written
// plainly here, on every pixel including the reflect-101 border.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "dsp/bayer_demosaic.h"
#include "tests/support/data_path.h"

namespace {

using dsp::cfa_order;

constexpr std::array<cfa_order, 4> all_orders = {cfa_order::rggb, cfa_order::bggr, cfa_order::grbg,
                                                 cfa_order::gbrg};

// Channel (0 = R, 1 = G, 2 = B) sampled at (x, y), straight from the order's name.
int cfa_channel(cfa_order order, int x, int y) {
    const char* cell = dsp::cfa_order_name(order);  // e.g. "rggb": row 0 = "rg", row 1 = "gb"
    const char c = cell[(y % 2) * 2 + (x % 2)];
    return c == 'r' ? 0 : (c == 'g' ? 1 : 2);
}

// OpenCV's code expected for each order (what the header claims).
int opencv_code(cfa_order order) {
    switch (order) {
        case cfa_order::rggb:
            return cv::COLOR_BayerBG2RGB;
        case cfa_order::bggr:
            return cv::COLOR_BayerRG2RGB;
        case cfa_order::grbg:
            return cv::COLOR_BayerGB2RGB;
        case cfa_order::gbrg:
            return cv::COLOR_BayerGR2RGB;
    }
    return -1;
}

cv::Mat mosaic(const cv::Mat& rgb, cfa_order order) {
    cv::Mat raw(rgb.size(), CV_8UC1);
    for (int y = 0; y < rgb.rows; ++y) {
        for (int x = 0; x < rgb.cols; ++x) {
            raw.at<uint8_t>(y, x) = rgb.at<cv::Vec3b>(y, x)[cfa_channel(order, x, y)];
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

cv::Mat random_image(int width, int height, int type, unsigned seed) {
    cv::Mat m(height, width, type);
    cv::RNG rng(seed);
    rng.fill(m, cv::RNG::UNIFORM, 0, 256);
    return m;
}

dsp::gray_cplane as_plane(const cv::Mat& m) {
    return dsp::gray_cplane{m.ptr<uint8_t>(), m.cols, m.rows, static_cast<int>(m.step1())};
}

cv::Mat demosaic_ours(const cv::Mat& raw, cfa_order order) {
    static_assert(sizeof(dsp::rgb8) == 3, "rgb8 must alias an 8UC3 pixel");
    cv::Mat out(raw.size(), CV_8UC3, cv::Scalar::all(0));
    dsp::rgb_plane plane{reinterpret_cast<dsp::rgb8*>(out.data), out.cols, out.rows,
                         static_cast<int>(out.step / 3)};
    dsp::demosaic_bilinear(as_plane(raw), order, plane);
    return out;
}

struct difference {
    int max_abs = 0;
    int differing_values = 0;  // channel values that differ at all
};

// Over the interior only (a border of `margin` pixels excluded).
difference compare(const cv::Mat& a, const cv::Mat& b, int margin) {
    difference d;
    for (int y = margin; y < a.rows - margin; ++y) {
        for (int x = margin; x < a.cols - margin; ++x) {
            for (int c = 0; c < 3; ++c) {
                const int diff = std::abs(a.at<cv::Vec3b>(y, x)[c] - b.at<cv::Vec3b>(y, x)[c]);
                d.max_abs = std::max(d.max_abs, diff);
                d.differing_values += diff != 0;
            }
        }
    }
    return d;
}

// Brute force: a sampled channel is copied; a missing one is the mean, rounded half
// up, of the samples of that channel in the 3x3 window, the window mirrored
// (reflect-101) at the frame edge.
cv::Mat demosaic_brute_force(const cv::Mat& raw, cfa_order order) {
    auto mirror = [](int i, int n) { return i < 0 ? -i : (i >= n ? 2 * n - 2 - i : i); };
    cv::Mat out(raw.size(), CV_8UC3);
    for (int y = 0; y < raw.rows; ++y) {
        for (int x = 0; x < raw.cols; ++x) {
            for (int c = 0; c < 3; ++c) {
                int value = 0;
                if (cfa_channel(order, x, y) == c) {
                    value = raw.at<uint8_t>(y, x);
                } else {
                    int sum = 0;
                    int count = 0;
                    for (int dy = -1; dy <= 1; ++dy) {
                        for (int dx = -1; dx <= 1; ++dx) {
                            const int sx = mirror(x + dx, raw.cols);
                            const int sy = mirror(y + dy, raw.rows);
                            if (cfa_channel(order, sx, sy) != c) continue;
                            sum += raw.at<uint8_t>(sy, sx);
                            ++count;
                        }
                    }
                    value = (sum + count / 2) / count;
                }
                out.at<cv::Vec3b>(y, x)[c] = static_cast<uint8_t>(value);
            }
        }
    }
    return out;
}

// The header's OpenCV names: each order matches its own code and no other.
TEST(Demosaic, OpenCvCodeMappingIsTheDocumentedOne) {
    const cv::Mat rgb = load_rgb("kodak_demosaic_gt/kodim19.png");
    ASSERT_FALSE(rgb.empty());
    const std::array<int, 4> codes = {cv::COLOR_BayerBG2RGB, cv::COLOR_BayerRG2RGB,
                                      cv::COLOR_BayerGB2RGB, cv::COLOR_BayerGR2RGB};
    const char* code_names[] = {"BayerBG", "BayerRG", "BayerGB", "BayerGR"};
    for (cfa_order order : all_orders) {
        const cv::Mat raw = mosaic(rgb, order);
        const cv::Mat ours = demosaic_ours(raw, order);
        std::printf("%s:", dsp::cfa_order_name(order));
        for (size_t i = 0; i < codes.size(); ++i) {
            cv::Mat theirs;
            cv::demosaicing(raw, theirs, codes[i]);
            const difference d = compare(ours, theirs, 1);
            std::printf("  %s max %3d", code_names[i], d.max_abs);
            if (codes[i] == opencv_code(order)) {
                EXPECT_LE(d.max_abs, 1) << dsp::cfa_order_name(order) << " vs " << code_names[i];
            } else {
                EXPECT_GT(d.max_abs, 50) << dsp::cfa_order_name(order) << " vs " << code_names[i];
            }
        }
        std::printf("\n");
    }
}

TEST(Demosaic, MatchesOpenCvBilinearOnKodakInAllOrders) {
    for (const char* name : {"kodak_demosaic_gt/kodim19.png", "kodak_demosaic_gt/kodim23.png"}) {
        const cv::Mat rgb = load_rgb(name);
        ASSERT_FALSE(rgb.empty()) << name;
        for (cfa_order order : all_orders) {
            const cv::Mat raw = mosaic(rgb, order);
            cv::Mat theirs;
            cv::demosaicing(raw, theirs, opencv_code(order));
            const difference d = compare(demosaic_ours(raw, order), theirs, 1);
            std::printf("%s %s: interior max |ours - OpenCV| = %d, %d of %d values differ\n", name,
                        dsp::cfa_order_name(order), d.max_abs, d.differing_values,
                        3 * (raw.cols - 2) * (raw.rows - 2));
            EXPECT_LE(d.max_abs, 1) << name << " " << dsp::cfa_order_name(order);
        }
    }
}

TEST(Demosaic, MatchesOpenCvBilinearOnRandomNoiseInAllOrders) {
    const std::array<cv::Size, 4> sizes = {cv::Size(4, 4), cv::Size(6, 8), cv::Size(64, 48),
                                           cv::Size(322, 242)};
    unsigned seed = 1;
    for (const cv::Size size : sizes) {
        for (cfa_order order : all_orders) {
            const cv::Mat raw = random_image(size.width, size.height, CV_8UC1, seed++);
            cv::Mat theirs;
            cv::demosaicing(raw, theirs, opencv_code(order));
            const difference d = compare(demosaic_ours(raw, order), theirs, 1);
            std::printf("noise %dx%d %s: interior max diff %d, %d values differ\n", size.width,
                        size.height, dsp::cfa_order_name(order), d.max_abs, d.differing_values);
            EXPECT_LE(d.max_abs, 1) << size << " " << dsp::cfa_order_name(order);
        }
    }
}

// Every pixel, border included, against the brute-force definition: exact.
TEST(Demosaic, EqualsBruteForceReflect101EverywhereInAllOrders) {
    const cv::Mat kodak = load_rgb("kodak_demosaic_gt/kodim23.png");
    ASSERT_FALSE(kodak.empty());
    const cv::Mat kodak_crop = kodak(cv::Rect(300, 100, 128, 96)).clone();
    unsigned seed = 100;
    for (cfa_order order : all_orders) {
        for (const cv::Mat& raw :
             {random_image(4, 4, CV_8UC1, seed++), random_image(10, 6, CV_8UC1, seed++),
              random_image(96, 64, CV_8UC1, seed++), mosaic(kodak_crop, order)}) {
            const difference d =
                compare(demosaic_ours(raw, order), demosaic_brute_force(raw, order), 0);
            EXPECT_EQ(d.max_abs, 0) << raw.size() << " " << dsp::cfa_order_name(order);
            EXPECT_EQ(d.differing_values, 0);
        }
    }
}

TEST(Demosaic, RowFunctionEqualsWholeImageExactly) {
    unsigned seed = 200;
    for (cfa_order order : all_orders) {
        // A sub-plane with a stride wider than the width exercises the stride.
        const cv::Mat big = random_image(100, 40, CV_8UC1, seed++);
        const cv::Mat raw = big(cv::Rect(6, 4, 80, 30));
        const cv::Mat whole = demosaic_ours(raw, order);
        std::vector<dsp::rgb8> row(static_cast<size_t>(raw.cols));
        long differing = 0;
        for (int y = 0; y < raw.rows; ++y) {
            dsp::demosaic_bilinear_row(as_plane(raw), order, y, row.data());
            for (int x = 0; x < raw.cols; ++x) {
                const cv::Vec3b w = whole.at<cv::Vec3b>(y, x);
                differing += row[x].r != w[0] || row[x].g != w[1] || row[x].b != w[2];
            }
        }
        EXPECT_EQ(differing, 0) << dsp::cfa_order_name(order);
        // Guards against both paths writing nothing: noise demosaics to mostly non-zero values.
        EXPECT_GT(cv::countNonZero(whole.reshape(1)), static_cast<int>(whole.total()));
    }
}

}  // namespace
