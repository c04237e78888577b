// The part of an object's box the SAD stereo match reads (dsp/object_core.h):
// its shape by size, the ellipse's rows against pixel centres tested one by
// one in floating point, and a round core matched on a disc whose box is too
// wide (a synthetic pair, the disc's disparity known by construction).
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "dsp/object_core.h"
#include "dsp/stereo_sad.h"
#include "tests/support/layer_texture.h"

namespace {

using dsp::box;

// Whether pixel (x, y)'s centre lies in the ellipse inscribed in b.
bool centre_in_ellipse(box b, int x, int y) {
    const double cx = b.x + 0.5 * b.width, cy = b.y + 0.5 * b.height;
    const double u = (x + 0.5 - cx) / (0.5 * b.width), v = (y + 0.5 - cy) / (0.5 * b.height);
    return u * u + v * v <= 1.0;
}

TEST(EllipseRow, HoldsThePixelsWhoseCentresLieInTheInscribedEllipse) {
    for (const box b : {box{0, 0, 1, 1}, box{3, 5, 10, 10}, box{7, 2, 31, 17}, box{100, 40, 36, 37},
                        box{11, 9, 64, 80}}) {
        for (int y = b.y - 1; y <= b.bottom(); ++y) {
            const dsp::row_span row = dsp::ellipse_row(b, y);
            for (int x = b.x - 1; x <= b.right(); ++x) {
                const bool in_row = x >= row.begin && x < row.end;
                EXPECT_EQ(in_row, centre_in_ellipse(b, x, y))
                    << "box " << b.x << "," << b.y << " " << b.width << "x" << b.height << " pixel "
                    << x << "," << y;
            }
        }
    }
}

TEST(ObjectCore, SquareUnderAndOverTheRoundSizes) {
    const dsp::object_depth_params surface;  // tiled from 80 px
    dsp::row_span spans[dsp::max_round_core_rows];
    const dsp::object_core_pattern small = dsp::object_core(box{10, 10, 23, 35}, surface, spans);
    EXPECT_FALSE(small.round);
    EXPECT_EQ(small.core.width, 23 - 2 * 4);   // a fifth a side from 16 to 23 px
    EXPECT_EQ(small.core.height, 35 - 2 * 5);  // a seventh from 24 px
    EXPECT_EQ(small.pixels, small.core.width * small.core.height);
    const dsp::object_core_pattern sixteen = dsp::object_core(box{10, 10, 16, 16}, surface, spans);
    EXPECT_EQ(sixteen.core.width, 16 - 2 * 3);
    const dsp::object_core_pattern tiny = dsp::object_core(box{10, 10, 15, 12}, surface, spans);
    EXPECT_EQ(tiny.core.width, 11);  // 2 px a side under 16 px
    EXPECT_EQ(tiny.core.height, 8);
    const dsp::object_core_pattern large = dsp::object_core(box{10, 10, 90, 70}, surface, spans);
    EXPECT_FALSE(large.round);
    EXPECT_EQ(large.core.width, 90 - 2 * 12);
    EXPECT_EQ(large.core.height, 70 - 2 * 10);
}

TEST(ObjectCore, RoundFromTwentyFourToFiftyNinePixels) {
    const dsp::object_depth_params surface;
    dsp::row_span spans[dsp::max_round_core_rows];
    const box object{20, 30, 48, 46};
    const dsp::object_core_pattern p = dsp::object_core(object, surface, spans);
    ASSERT_TRUE(p.round);
    EXPECT_EQ(p.core.x, 24);  // a tenth a side
    EXPECT_EQ(p.core.y, 34);
    EXPECT_EQ(p.core.width, 40);
    EXPECT_EQ(p.core.height, 38);
    int pixels = 0;
    for (int y = 0; y < p.core.height; ++y) {
        for (int x = 0; x < p.core.width; ++x) {
            const bool in = x >= spans[y].begin && x < spans[y].end;
            EXPECT_EQ(in, centre_in_ellipse(p.core, p.core.x + x, p.core.y + y));
            pixels += in;
        }
    }
    EXPECT_EQ(p.pixels, pixels);
    EXPECT_TRUE(dsp::object_core(box{20, 30, 59, 24}, surface, spans).round);
    EXPECT_FALSE(dsp::object_core(box{20, 30, 60, 24}, surface, spans).round);
    EXPECT_FALSE(dsp::object_core(box{20, 30, 40, 60}, surface, spans).round);
}

// A 45 px textured disc at disparity 30 over a textured background at 10;
// its box 48 px wide, 3 px past the disc's left side (as a tracked box was
// at a pair where a 43 px ball's depth went 1.07 % far). The round core
// reads the disc alone: its disparity is the disc's.
TEST(ObjectCore, ARoundCoreOfABoxTooWideReadsTheDiscAlone) {
    constexpr int width = 200, height = 100, disc_d = 30, back_d = 10;
    const double cx = 100.5, cy = 50.5, radius = 22.5;  // pixels [78, 123) x [28, 73)
    auto on_disc = [&](int x, int y) {
        const double u = x + 0.5 - cx, v = y + 0.5 - cy;
        return u * u + v * v <= radius * radius;
    };
    std::vector<uint8_t> right(width * height), left(width * height);
    for (int y = 0; y < height; ++y) {
        for (int x = 0; x < width; ++x) {
            right[y * width + x] = on_disc(x, y) ? test_support::layer_texture(1, x, y)
                                                 : test_support::layer_texture(0, x, y);
            left[y * width + x] = on_disc(x - disc_d, y)
                                      ? test_support::layer_texture(1, x - disc_d, y)
                                      : test_support::layer_texture(0, x - back_d, y);
        }
    }
    const dsp::gray_cplane r{right.data(), width, height, width},
        l{left.data(), width, height, width};
    dsp::row_span spans[dsp::max_round_core_rows];
    const dsp::object_core_pattern p =
        dsp::object_core(box{75, 28, 48, 45}, dsp::object_depth_params{}, spans);
    ASSERT_TRUE(p.round);
    dsp::stereo_params search;
    search.min_disparity = 0;
    search.max_disparity = 60;
    const dsp::stereo_result m = dsp::stereo_match_sad_masked(r, l, p.core, spans, search);
    ASSERT_TRUE(m.valid);
    EXPECT_EQ(m.disparity, disc_d);
    EXPECT_EQ(m.sad, 0u);  // no pixel of the background in it
    // The square core of the same box (a seventh a side) takes the
    // background in at its corners.
    const dsp::stereo_result square = dsp::stereo_match_sad(r, l, box{81, 34, 36, 33}, search);
    EXPECT_GT(square.sad, 0u);
}

}  // namespace
