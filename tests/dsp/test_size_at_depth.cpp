// A tracked box carried to the depth the stereo stages measured
// (dsp/size_at_depth.h), against sizes worked out here from the pinhole
// model: an object's image size is proportional to its disparity (less the
// principal points' offset), so a box of size s at disparity d0 is s d / d0
// at d. The oracle is that ratio in floating point, not the code's rounding.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "dsp/size_at_depth.h"

namespace {

using dsp::box;

double centre(int start, int size) {
    return start + 0.5 * size;
}

TEST(AtDisparity, ResizesAboutTheCentreByTheRatio) {
    const box b{100, 50, 144, 147};
    const int64_t from = 9483, to = 6886;  // a ball 1.38 times as far
    const box r = dsp::at_disparity(b, from, to);
    const double ratio = static_cast<double>(to) / from;
    EXPECT_EQ(r.width, std::lround(144 * ratio));
    EXPECT_EQ(r.height, std::lround(147 * ratio));
    EXPECT_LE(std::fabs(centre(r.x, r.width) - centre(b.x, b.width)), 0.5);
    EXPECT_LE(std::fabs(centre(r.y, r.height) - centre(b.y, b.height)), 0.5);
    const box g = dsp::at_disparity(b, to, from);  // coming nearer: grows
    EXPECT_EQ(g.width, std::lround(144 / ratio));
    EXPECT_LE(std::fabs(centre(g.x, g.width) - centre(b.x, b.width)), 0.5);
}

TEST(AtDisparity, KeepsTheBoxWithinOnePercent) {
    const box b{10, 20, 120, 120};
    const box kept = dsp::at_disparity(b, 10000, 9901);  // 0.99 %
    EXPECT_EQ(kept.x, b.x);
    EXPECT_EQ(kept.width, b.width);
    EXPECT_EQ(dsp::at_disparity(b, 10000, 9900).width, 119);  // 1 %: 118.8
    EXPECT_EQ(dsp::at_disparity(b, 0, 9000).width, 120);      // unknown
}

// A ball going away at 2.5 % of its depth a pair, its box carried pair by
// pair as TRACK does (the last pair's ratio): each pair rounds a size
// already rounded, so the rounding carries on (up to 1.28 px here, where the
// size rules re-measure it each pair in TRACK); within 1 % of the pinhole
// size and half a pixel, where truncating would lose up to a pixel a pair.
TEST(AtDisparity, CarriedPairByPairFollowsTheDepth) {
    const double d0 = 10000.0;
    box b{200, 150, 140, 140};
    double depth = 1.0;
    for (int pair = 1; pair <= 16; ++pair) {
        const int64_t before = std::llround(d0 / depth);
        depth *= 1.025;
        b = dsp::at_disparity(b, before, std::llround(d0 / depth));
        const double expected = 140.0 / depth;
        EXPECT_LE(std::fabs(b.width - expected), 0.01 * expected + 0.5) << "pair " << pair;
    }
}

// The window of a ball going away: each extent read when the object was
// larger is narrowed about its centre to the size the object has now, by
// size (d_then / d_now - 1) rounded; one read when it was smaller, or
// within 1 %, or at no disparity, is left as read.
TEST(ExtentsAtDepth, NarrowsWhatTheObjectWasLargerWhenRead) {
    const dsp::span read[4] = {{300, 110}, {280, 114}, {260, 118}, {240, 122}};
    const int64_t depth_q8[4] = {10000, 10250, 9750, 0};  // as large, 2.5 % larger, smaller, none
    dsp::span now[4];
    dsp::extents_at_depth(read, depth_q8, 4, 80, 10000, now);
    const int larger = static_cast<int>(std::lround(80 * 0.025));  // 2 px
    EXPECT_EQ(now[0].start, 300);
    EXPECT_EQ(now[0].size, 110);
    EXPECT_EQ(now[1].size, 114 - larger);
    EXPECT_LE(std::fabs(centre(now[1].start, now[1].size) - centre(280, 114)), 0.5);
    EXPECT_EQ(now[2].size, 118);  // smaller then: left as read
    EXPECT_EQ(now[3].size, 122);
}

// A key's object read from Dif(key, t): the difference's extent spans the
// ball where the key was, [c - W0/2, c + W0/2), and where it is now,
// [c + s - W/2, c + s + W/2), with W = W0 d_now / d_key. Read less the
// displacement s (dsp::keyed_axis, as TRACK does), then brought to the
// depth, it must be the ball now within a pixel on each end. Built here in
// floating point from the two intervals, not from the formula.
TEST(KeyedSpanAtDepth, IsTheObjectNowOfAGrowingOrShrinkingBall) {
    struct sample {
        double key_size, ratio;
        int shift, shift_read;  // the displacement, and as the key's pattern read it
    };
    // Moved further than a side grew or shrank (an end each), and not (the
    // 150 px ball shrinking 15 px a side, moved 12 or 9; the 80 px growing
    // 10 a side, moved 3; the 60 px 6 a side, not moved). The last: a 60 px
    // ball going away whose pattern read 16 px of the 24 it moved (round
    // 25's ball over aloe: a shrinking texture matched short).
    const sample samples[] = {{45, 1.10, 6, 6},    {45, 1.10, -6, -6}, {150, 0.80, 12, 12},
                              {150, 0.80, -9, -9}, {80, 1.25, 14, 14}, {100, 0.90, 5, 5},
                              {150, 0.80, 20, 20}, {80, 1.25, -3, -3}, {60, 1.20, 0, 0},
                              {60, 0.80, 0, 0},    {58, 0.755, 24, 16}};
    for (const sample& c : samples) {
        const double key_start = 200.0, now_size = c.key_size * c.ratio;
        const double now_start = key_start + 0.5 * c.key_size + c.shift - 0.5 * now_size;
        const double lo = std::min(key_start, now_start);
        const double hi = std::max(key_start + c.key_size, now_start + now_size);
        const dsp::span both{static_cast<int>(std::lround(lo)),
                             static_cast<int>(std::lround(hi - lo))};
        const dsp::span read = dsp::keyed_axis(both, c.shift_read);
        const int64_t key_q8 = 10000, now_q8 = std::llround(10000 * c.ratio);
        const int key_size = static_cast<int>(std::lround(c.key_size));
        const dsp::span now =
            dsp::keyed_span_at_depth(read, c.shift_read, key_size, key_q8, now_q8, nullptr);
        EXPECT_LE(std::fabs(now.start - now_start), 1.0) << c.key_size << " x " << c.ratio;
        EXPECT_LE(std::fabs(now.end() - (now_start + now_size)), 1.0)
            << c.key_size << " x " << c.ratio << " shift " << c.shift;
    }
}

// Within 1 % of the key's disparity, or with none, the reading stands.
TEST(KeyedSpanAtDepth, KeepsTheReadingWithinOnePercent) {
    const dsp::span read{200, 60};
    const dsp::span same = dsp::keyed_span_at_depth(read, 8, 60, 10000, 10090, nullptr);
    EXPECT_EQ(same.size, read.size);
    EXPECT_EQ(dsp::keyed_span_at_depth(read, 8, 60, 0, 10090, nullptr).size, read.size);
}

// A ball that shrank inside the key's box: Dif(key, t)'s extent is the key's
// ball, [200, 200 + W0), and its pattern read no displacement, so the key's
// object at the depth is centred where the key was. The ball now is
// [c + s - W/2, c + s + W/2) with W = W0 d_now / d_key and |s| under half the
// shrink; its silhouette (read 1 px wider or narrower, either side) places
// it within a pixel on each end. Built here in floating point.
TEST(KeyedSpanAtDepth, PlacesABallThatShrankInsideTheKeysBox) {
    struct sample {
        double key_size, ratio, shift;
        int outline_grow_start, outline_grow_end;  // the silhouette's misreading, px
    };
    const sample samples[] = {{58, 0.75, 4.3, 0, 0}, {58, 0.75, -4.3, 1, 0}, {100, 0.8, 6, 0, 1},
                              {100, 0.8, -9, -1, 0}, {40, 0.85, 2, 0, -1},   {150, 0.7, 0, 1, 1},
                              {150, 0.7, 20, 0, 0}};
    for (const sample& c : samples) {
        const int key_size = static_cast<int>(std::lround(c.key_size));
        const dsp::span both{200, key_size};
        const int64_t key_q8 = 10000, now_q8 = std::llround(10000 * c.ratio);
        const double now_size = c.key_size * c.ratio;
        const double now_start = 200.0 + 0.5 * c.key_size + c.shift - 0.5 * now_size;
        const int outline_start = static_cast<int>(std::lround(now_start)) - c.outline_grow_start;
        const int outline_end =
            static_cast<int>(std::lround(now_start + now_size)) + c.outline_grow_end;
        const dsp::span outline{outline_start, outline_end - outline_start};
        const dsp::span now = dsp::keyed_span_at_depth(both, 0, key_size, key_q8, now_q8, &outline);
        EXPECT_LE(std::fabs(now.start - now_start), 1.0) << c.key_size << " shift " << c.shift;
        EXPECT_LE(std::fabs(now.end() - (now_start + now_size)), 1.0)
            << c.key_size << " shift " << c.shift;
    }
}

// Where the silhouette is not the object at the depth, or the object did not
// shrink inside the key's box, the key's reading stands.
TEST(KeyedSpanAtDepth, KeepsTheKeysReadingOtherwise) {
    // Dif(key, t) of a 58 px key's ball: at 0.75 of its disparity the ball
    // moved as read is [207, 251).
    const dsp::span read{200, 58};
    const auto on = [&](int shift, int64_t now_q8, dsp::span outline) {
        const dsp::span with = dsp::keyed_span_at_depth(read, shift, 58, 10000, now_q8, &outline);
        const dsp::span without = dsp::keyed_span_at_depth(read, shift, 58, 10000, now_q8, nullptr);
        return with.start == without.start && with.size == without.size;
    };
    EXPECT_FALSE(on(0, 7500, {211, 44}));  // placed: inside the key's box, its size
    EXPECT_TRUE(on(0, 7500, {211, 30}));   // a part of the outline
    EXPECT_TRUE(on(0, 7500, {220, 44}));   // further than the shrink allows
    EXPECT_TRUE(on(8, 7500, {211, 44}));   // moved more than half the shrink: an end each
    EXPECT_TRUE(on(0, 12500, {211, 44}));  // grew
    EXPECT_TRUE(on(0, 9950, {211, 44}));   // within 1 %
    EXPECT_TRUE(on(0, 0, {211, 44}));      // no disparity
}

TEST(DisparityJumped, OverAnEighthOnly) {
    EXPECT_FALSE(dsp::disparity_jumped(8000, 7000));  // 12.5 %
    EXPECT_TRUE(dsp::disparity_jumped(8000, 6999));
    EXPECT_TRUE(dsp::disparity_jumped(8000, 9001));
    EXPECT_FALSE(dsp::disparity_jumped(0, 9001));  // none yet
}

// A size the track kept stands for the depth it was sized at while the
// object goes away and its silhouette is smaller on both axes; not coming
// nearer, not across a jumped disparity, not without a depth.
TEST(SizeStillStands, GoingAwayWithASmallerSilhouetteOnly) {
    const box kept{250, 208, 34, 33};
    const box smaller{251, 209, 30, 29};
    EXPECT_TRUE(dsp::size_still_stands(kept, smaller, 6000, 5950));
    EXPECT_TRUE(dsp::size_still_stands(kept, smaller, 8000, 7000));   // 12.5 %: not jumped
    EXPECT_FALSE(dsp::size_still_stands(kept, smaller, 8000, 6999));  // jumped
    EXPECT_FALSE(dsp::size_still_stands(kept, smaller, 6000, 6000));  // no change
    EXPECT_FALSE(dsp::size_still_stands(kept, smaller, 5950, 6000));  // coming nearer
    EXPECT_FALSE(dsp::size_still_stands(kept, box{251, 209, 30, 33}, 6000, 5950));
    EXPECT_FALSE(dsp::size_still_stands(kept, box{251, 209, 34, 29}, 6000, 5950));
    EXPECT_FALSE(dsp::size_still_stands(kept, box{248, 207, 36, 35}, 6000, 5950));
    EXPECT_FALSE(dsp::size_still_stands(kept, smaller, 0, 5950));  // none yet
    EXPECT_FALSE(dsp::size_still_stands(kept, smaller, 6000, 0));
}

// The track's loop (controller_track.cpp): each pair the box carried to the
// last pair's disparity, and its size's depth kept where size_still_stands.
// A ball thrown at the wall, its disparity falling 0.9 % a pair (under
// at_disparity's 1 %): the box follows the pinhole size s d / d0 within
// 1.5 px (the 1 % dead band, and each resize rounding the last rounded
// size), where restarted from each pair's depth it stays at its first size
// (5.7 px too large by the 20th pair).
TEST(SizeStillStands, AFallUnderOnePercentAPairAddsUp) {
    const box first{250, 208, 34, 33};
    const int64_t d0 = 6400;
    box kept = first, restarted = first;
    int64_t sized = d0, restarted_sized = d0;
    for (int pair = 1; pair <= 20; ++pair) {
        const int64_t d = std::llround(d0 * std::pow(0.991, pair));
        const box smaller{0, 0, static_cast<int>(std::lround(34.0 * d / d0)) - 1,
                          static_cast<int>(std::lround(33.0 * d / d0)) - 1};
        const box carried = dsp::at_disparity(kept, sized, d);
        const bool same = carried.width == kept.width && carried.height == kept.height;
        sized = same && dsp::size_still_stands(carried, smaller, sized, d) ? sized : d;
        kept = carried;
        restarted = dsp::at_disparity(restarted, restarted_sized, d);
        restarted_sized = d;
        EXPECT_LE(std::fabs(kept.width - 34.0 * d / d0), 1.5) << "pair " << pair;
        EXPECT_LE(std::fabs(kept.height - 33.0 * d / d0), 1.5) << "pair " << pair;
    }
    EXPECT_EQ(restarted.width, first.width);  // never moved a side
    EXPECT_LE(kept.width, 29);                // 34 x 0.991^20 = 28.3
}

}  // namespace
