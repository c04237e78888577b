// DETECT's frames a stride apart (dsp/stride_history.h): which pairs keep a
// frame, and that its pass is eq. 2-4 on f(t-2s), f(t-s), f(t) with the
// older two at 7 bits (the low bit holds the difference), checked against
// the formula written out per pixel on random frames (the test's own, not
// the firmware's kernels).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <random>
#include <vector>

#include "dsp/stride_history.h"

namespace {

constexpr int frame_w = 64, frame_h = 40;
constexpr uint8_t threshold = 20;

std::vector<uint8_t> random_frame(std::mt19937& rng) {
    std::uniform_int_distribution<int> level(0, 255);
    std::vector<uint8_t> f(frame_w * frame_h);
    for (auto& v : f) v = static_cast<uint8_t>(level(rng));
    return f;
}

dsp::gray_cplane plane(const std::vector<uint8_t>& f) {
    return dsp::gray_cplane{f.data(), frame_w, frame_h, frame_w};
}

// |a - b| > threshold with a kept at 7 bits.
bool differs(uint8_t kept, uint8_t now) {
    return std::abs((kept & 0xFE) - now) > threshold;
}

TEST(StrideHistory, KeepsTheFirstFrameThenOneEveryStride) {
    std::vector<uint8_t> storage(frame_w * frame_h);
    dsp::stride_history h;
    h.init(storage.data(), storage.size());
    std::mt19937 rng(1);
    const auto f = random_frame(rng);
    EXPECT_FALSE(h.has_frame());
    EXPECT_TRUE(h.due());
    h.keep(plane(f), threshold);
    EXPECT_TRUE(h.has_frame());
    EXPECT_FALSE(h.ready());
    for (int pair = 1; pair < dsp::stride_history::stride; ++pair)
        EXPECT_FALSE(h.due()) << "pair " << pair;
    EXPECT_TRUE(h.due());
    h.keep(plane(f), threshold);
    EXPECT_TRUE(h.ready());
    h.reset();
    EXPECT_FALSE(h.has_frame());
    EXPECT_TRUE(h.due());
}

TEST(StrideHistory, ItsPassIsThreeFrameDifferencingAStrideApart) {
    std::mt19937 rng(7);
    const auto f0 = random_frame(rng), f1 = random_frame(rng), f2 = random_frame(rng);
    std::vector<uint8_t> storage(frame_w * frame_h);
    dsp::stride_history h;
    h.init(storage.data(), storage.size());
    h.keep(plane(f0), threshold);
    h.keep(plane(f1), threshold);
    ASSERT_TRUE(h.ready());

    int set = 0;
    std::vector<uint8_t> row(frame_w);
    for (int y = 0; y < frame_h; ++y) {
        h.three_frame_row(f2.data() + y * frame_w, y, threshold, row.data());
        for (int x = 0; x < frame_w; ++x) {
            const size_t i = static_cast<size_t>(y) * frame_w + x;
            const bool object = differs(f0[i], f1[i]) && differs(f1[i], f2[i]);
            ASSERT_EQ(row[x], object ? 255 : 0) << x << "," << y;
            set += object;
            // The kept frame is f1 at 7 bits, whatever the row pass read.
            ASSERT_EQ(h.kept().at(x, y) & 0xFE, f1[i] & 0xFE) << x << "," << y;
        }
    }
    EXPECT_GT(set, 100);  // random frames: about a third of the pixels
    // Keeping f2 makes the next stride's older difference, Dif(f1, f2).
    h.keep(plane(f2), threshold);
    for (int y = 0; y < frame_h; ++y)
        for (int x = 0; x < frame_w; ++x) {
            const size_t i = static_cast<size_t>(y) * frame_w + x;
            ASSERT_EQ(h.kept().at(x, y) & 1, differs(f1[i], f2[i]) ? 1 : 0) << x << "," << y;
        }
}

TEST(StrideHistory, AFrameLargerThanItsBufferIsNotKept) {
    std::vector<uint8_t> storage(frame_w * frame_h / 2);
    dsp::stride_history h;
    h.init(storage.data(), storage.size());
    std::mt19937 rng(3);
    h.keep(plane(random_frame(rng)), threshold);
    EXPECT_FALSE(h.has_frame());
}

}  // namespace
