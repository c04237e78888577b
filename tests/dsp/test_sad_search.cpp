// The exhaustive SAD search (dsp/sad_search.h) against a brute-force
// reference written plainly here: every candidate position of the window,
// skipped when the pattern would leave the image, SAD summed pixel by pixel,
// the first strict minimum in raster order kept. Random images, patterns
// and windows (partly or wholly outside the image, patterns larger than the
// image), strides wider than the rows, and value ranges so small that ties
// are everywhere. Position, SAD, validity and position count must be equal.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <vector>

#include "dsp/sad_search.h"

namespace {

// An image stored compactly for the reference, and the same pixels in a
// buffer with a wider stride (padding filled with noise) for the kernel.
struct test_image {
    int width = 0, height = 0, stride = 0;
    std::vector<uint8_t> compact;  // width * height
    std::vector<uint8_t> strided;  // stride * height

    test_image(int w, int h, int pad, int levels, std::mt19937& rng)
        : width(w), height(h), stride(w + pad) {
        compact.resize(static_cast<size_t>(w) * h);
        strided.resize(static_cast<size_t>(stride) * h);
        for (uint8_t& v : strided) v = static_cast<uint8_t>(rng() % 256);
        for (int y = 0; y < h; ++y) {
            for (int x = 0; x < w; ++x) {
                const uint8_t v = static_cast<uint8_t>(rng() % static_cast<unsigned>(levels));
                compact[static_cast<size_t>(y) * w + x] = v;
                strided[static_cast<size_t>(y) * stride + x] = v;
            }
        }
    }
    uint8_t at(int x, int y) const { return compact[static_cast<size_t>(y) * width + x]; }
    dsp::gray_cplane view() const {
        return dsp::gray_cplane{strided.data(), width, height, stride};
    }
};

struct reference_result {
    bool valid = false;
    int x = 0, y = 0;
    uint32_t sad = 0;
    int positions = 0;
    int minima = 0;  // how many positions reach the minimum (ties when > 1)
};

reference_result brute_force_search(const test_image& image, const test_image& pattern, int wx,
                                    int wy, int ww, int wh) {
    reference_result r;
    for (int y = wy; y < wy + wh; ++y) {
        for (int x = wx; x < wx + ww; ++x) {
            if (x < 0 || y < 0 || x + pattern.width > image.width ||
                y + pattern.height > image.height)
                continue;
            uint32_t sad = 0;
            for (int j = 0; j < pattern.height; ++j)
                for (int i = 0; i < pattern.width; ++i)
                    sad +=
                        static_cast<uint32_t>(std::abs(image.at(x + i, y + j) - pattern.at(i, j)));
            ++r.positions;
            if (!r.valid || sad < r.sad) {
                r.valid = true;
                r.x = x;
                r.y = y;
                r.sad = sad;
                r.minima = 1;
            } else if (sad == r.sad) {
                ++r.minima;
            }
        }
    }
    return r;
}

TEST(sad_search, equals_brute_force_on_random_cases) {
    std::mt19937 rng(2024);
    const int levels_choice[] = {2, 3, 16, 256};
    int cases = 0, invalid = 0, tied = 0, clipped = 0, total_positions = 0;
    for (int rep = 0; rep < 5000; ++rep) {
        const int iw = 1 + static_cast<int>(rng() % 48), ih = 1 + static_cast<int>(rng() % 40);
        // Mostly patterns well inside the image, sometimes up to one pixel
        // larger than it (no position fits).
        const bool large = rng() % 8 == 0;
        auto pattern_side = [&](int image_side) {
            const int limit = large ? image_side + 1 : std::max(1, image_side / 2);
            return 1 + static_cast<int>(rng() % static_cast<unsigned>(std::min(20, limit)));
        };
        const int pw = pattern_side(iw), ph = pattern_side(ih);
        const int levels = levels_choice[rng() % 4];
        const test_image image(iw, ih, static_cast<int>(rng() % 9), levels, rng);
        const test_image pattern(pw, ph, static_cast<int>(rng() % 5), levels, rng);
        // Windows centred anywhere from 8 px before the image to 8 px beyond it.
        const int ww = static_cast<int>(rng() % 30), wh = static_cast<int>(rng() % 30);
        const int wx = static_cast<int>(rng() % static_cast<unsigned>(iw + 16)) - 8 - ww / 2;
        const int wy = static_cast<int>(rng() % static_cast<unsigned>(ih + 16)) - 8 - wh / 2;

        const reference_result expected = brute_force_search(image, pattern, wx, wy, ww, wh);
        const dsp::sad_result got =
            dsp::sad_search(image.view(), pattern.view(), dsp::box{wx, wy, ww, wh});
        ASSERT_EQ(got.valid, expected.valid) << "case " << rep;
        ++cases;
        if (!expected.valid) {
            ++invalid;
            continue;
        }
        ASSERT_EQ(got.x, expected.x) << "case " << rep;
        ASSERT_EQ(got.y, expected.y) << "case " << rep;
        ASSERT_EQ(got.sad, expected.sad) << "case " << rep;
        ASSERT_EQ(got.positions, expected.positions) << "case " << rep;
        if (expected.minima > 1) ++tied;
        if (expected.positions < ww * wh) ++clipped;
        total_positions += expected.positions;
    }
    std::printf(
        "sad_search: %d random cases identical to brute force (%d with no position inside the "
        "image, %d windows clipped by the image, %d with tied minima, %d positions)\n",
        cases, invalid, clipped, tied, total_positions);
    // The cases really exercise the rules under test.
    EXPECT_GT(invalid, 100);
    EXPECT_GT(clipped, 500);
    EXPECT_GT(tied, 300);
}

TEST(sad_search, ties_go_to_the_first_position_in_raster_order) {
    std::mt19937 rng(5);
    test_image image(40, 30, 3, 256, rng);
    const test_image pattern(9, 7, 0, 256, rng);
    // Plant the pattern at (25, 4) and (3, 18): (25, 4) comes first in raster order.
    auto plant = [&](int px, int py) {
        for (int j = 0; j < pattern.height; ++j) {
            for (int i = 0; i < pattern.width; ++i) {
                image.compact[static_cast<size_t>(py + j) * image.width + px + i] =
                    pattern.at(i, j);
                image.strided[static_cast<size_t>(py + j) * image.stride + px + i] =
                    pattern.at(i, j);
            }
        }
    };
    plant(3, 18);
    plant(25, 4);
    const dsp::sad_result all = dsp::sad_search(image.view(), pattern.view(), {-5, -5, 60, 60});
    EXPECT_EQ(all.sad, 0u);
    EXPECT_EQ(all.x, 25);
    EXPECT_EQ(all.y, 4);
    // A window that starts below the first copy finds the second.
    const dsp::sad_result lower = dsp::sad_search(image.view(), pattern.view(), {0, 5, 40, 30});
    EXPECT_EQ(lower.sad, 0u);
    EXPECT_EQ(lower.x, 3);
    EXPECT_EQ(lower.y, 18);
    // A constant image: every position ties, the window's first wins.
    const test_image flat(20, 20, 0, 1, rng);
    const test_image flat_pattern(4, 4, 0, 1, rng);
    const dsp::sad_result first =
        dsp::sad_search(flat.view(), flat_pattern.view(), {-3, 2, 10, 10});
    EXPECT_EQ(first.x, 0);
    EXPECT_EQ(first.y, 2);
    EXPECT_EQ(first.positions, 7 * 10);
}

TEST(sad_at, every_width_and_the_extreme_values) {
    // Widths 1..70 cover the 8-pixel steps and every tail length.
    std::mt19937 rng(9);
    for (int w = 1; w <= 70; ++w) {
        const test_image image(w + 3, 6, 5, 256, rng);
        const test_image pattern(w, 4, 2, 256, rng);
        uint32_t expected = 0;
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < w; ++i)
                expected +=
                    static_cast<uint32_t>(std::abs(image.at(2 + i, 1 + j) - pattern.at(i, j)));
        ASSERT_EQ(dsp::sad_at(image.view(), 2, 1, pattern.view()), expected) << "width " << w;
    }
    // 255 against 0 everywhere: the largest SAD of a 96x96 pattern.
    std::vector<uint8_t> white(100 * 100, 255), black(96 * 96, 0);
    const dsp::gray_cplane image{white.data(), 100, 100, 100};
    const dsp::gray_cplane pattern{black.data(), 96, 96, 96};
    EXPECT_EQ(dsp::sad_at(image, 4, 4, pattern), 255u * 96u * 96u);
}

}  // namespace
