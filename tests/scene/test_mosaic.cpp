// Bayer mosaicking: the right colour at every site for all four CFA orders,
// against a table written here and against OpenCV's demosaicing (which must
// give back the sampled colour at each site and the image with a sane PSNR
// only when the order names match: rggb = COLOR_BayerBG, etc.).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "model/scene/bayer_mosaic.h"
#include "model/scene/texture.h"
#include "tests/support/data_path.h"

namespace {

struct order_case {
    dsp::cfa_order order;
    const char* cell;  // the 2x2 cell row by row: (0,0) (1,0) (0,1) (1,1)
    int opencv_code;
};

// dsp/bayer_demosaic.h: rggb = R at (0,0), G at (1,0), G at (0,1), B at (1,1);
// OpenCV names a pattern by the second row's 2nd and 3rd pixels.
const order_case orders[] = {
    {dsp::cfa_order::rggb, "RGGB", cv::COLOR_BayerBG2RGB},
    {dsp::cfa_order::bggr, "BGGR", cv::COLOR_BayerRG2RGB},
    {dsp::cfa_order::grbg, "GRBG", cv::COLOR_BayerGB2RGB},
    {dsp::cfa_order::gbrg, "GBRG", cv::COLOR_BayerGR2RGB},
};

uint8_t channel(dsp::rgb8 p, char c) {
    return c == 'R' ? p.r : (c == 'G' ? p.g : p.b);
}

scene::rgb_image random_image(int w, int h, uint64_t seed) {
    scene::random_stream rng(seed);
    scene::rgb_image img(w, h);
    for (dsp::rgb8& p : img.pixels) {
        p = dsp::rgb8{static_cast<uint8_t>(rng.next() & 255),
                      static_cast<uint8_t>(rng.next() & 255),
                      static_cast<uint8_t>(rng.next() & 255)};
    }
    return img;
}

TEST(Mosaic, EverySiteHoldsItsCfaColour) {
    const scene::rgb_image img = random_image(64, 48, 5);
    for (const order_case& oc : orders) {
        const scene::gray_image raw = scene::mosaic(img, oc.order);
        ASSERT_EQ(raw.width, 64);
        ASSERT_EQ(raw.height, 48);
        long wrong = 0;
        for (int y = 0; y < img.height; ++y) {
            for (int x = 0; x < img.width; ++x) {
                const char c = oc.cell[2 * (y & 1) + (x & 1)];
                wrong += raw.at(x, y) != channel(img.at(x, y), c);
            }
        }
        std::printf("%s: %ld wrong sites of %d\n", oc.cell, wrong, 64 * 48);
        EXPECT_EQ(wrong, 0) << oc.cell;
    }
}

TEST(Mosaic, OpenCvDemosaicOfOurMosaicGivesTheImageBack) {
    // Kodak parrots (real RGB ground truth).
    const cv::Mat bgr =
        cv::imread(test_support::data_path("kodak_demosaic_gt/kodim23.png"), cv::IMREAD_COLOR);
    ASSERT_FALSE(bgr.empty());
    cv::Mat rgb;
    cv::cvtColor(bgr, rgb, cv::COLOR_BGR2RGB);
    scene::rgb_image img(rgb.cols, rgb.rows);
    for (int y = 0; y < rgb.rows; ++y) {
        for (int x = 0; x < rgb.cols; ++x) {
            const cv::Vec3b p = rgb.at<cv::Vec3b>(y, x);
            img.at(x, y) = dsp::rgb8{p[0], p[1], p[2]};
        }
    }
    for (const order_case& oc : orders) {
        const scene::gray_image raw = scene::mosaic(img, oc.order);
        const cv::Mat raw_mat(raw.height, raw.width, CV_8UC1,
                              const_cast<uint8_t*>(raw.pixels.data()));
        cv::Mat back;
        cv::demosaicing(raw_mat, back, oc.opencv_code);
        // The sampled colour survives demosaicing at every interior site.
        long wrong = 0;
        for (int y = 2; y < rgb.rows - 2; ++y) {
            for (int x = 2; x < rgb.cols - 2; ++x) {
                const int c =
                    scene::cfa_colour_at(oc.order, x, y) == scene::cfa_colour::red
                        ? 0
                        : (scene::cfa_colour_at(oc.order, x, y) == scene::cfa_colour::green ? 1
                                                                                            : 2);
                wrong += back.at<cv::Vec3b>(y, x)[c] != rgb.at<cv::Vec3b>(y, x)[c];
            }
        }
        const cv::Rect inner(2, 2, rgb.cols - 4, rgb.rows - 4);
        const double psnr = cv::PSNR(back(inner), rgb(inner));
        // The same mosaic read with the wrong (mirrored) order.
        cv::Mat wrong_back;
        const int mirrored =
            oc.opencv_code == cv::COLOR_BayerBG2RGB ? cv::COLOR_BayerRG2RGB : cv::COLOR_BayerBG2RGB;
        cv::demosaicing(raw_mat, wrong_back, mirrored);
        const double psnr_wrong = cv::PSNR(wrong_back(inner), rgb(inner));
        std::printf(
            "%s: %ld interior sites changed by OpenCV demosaic, PSNR %.2f "
            "dB (read as "
            "the wrong order: %.2f dB)\n",
            oc.cell, wrong, psnr, psnr_wrong);
        EXPECT_EQ(wrong, 0) << oc.cell;
        EXPECT_GT(psnr, 28.0) << oc.cell;
        EXPECT_GT(psnr - psnr_wrong, 5.0) << oc.cell;
    }
}

TEST(Mosaic, PlaneVersionWritesIntoAStridedBuffer) {
    const scene::rgb_image img = random_image(16, 8, 9);
    std::vector<uint8_t> buffer(20 * 8, 0xEE);
    const dsp::gray_plane raw{buffer.data(), 16, 8, 20};
    scene::mosaic(img.view(), dsp::cfa_order::gbrg, raw);
    EXPECT_EQ(raw.at(0, 0), img.at(0, 0).g);
    EXPECT_EQ(raw.at(1, 0), img.at(1, 0).b);
    EXPECT_EQ(raw.at(0, 1), img.at(0, 1).r);
    EXPECT_EQ(raw.at(15, 7), img.at(15, 7).g);
    for (int y = 0; y < 8; ++y) {
        for (int x = 16; x < 20; ++x) EXPECT_EQ(buffer[y * 20 + x], 0xEE);  // padding untouched
    }
}

}  // namespace
